//! Joint 2 between two measurements of one robot: the upper arm's readings (stage 1 of
//! a session, or a check's upper-arm capture) at the same commanded pose, each solved
//! as a session solves its stage 1 (the λ/2 turn of joint 1 separates the base's tilt),
//! on the same arm, bracket and gain. The difference of the two Δθ2 is how far joint
//! 2's zero moved: the base's tilt, the upper-arm bracket's calibration and joint 2's
//! transmission error at that angle are the same in both and cancel.
//!
//! Gravity at the flange sees joints 2 and 3 only together (their axes are parallel):
//! with joint 2's move known, joint 3's is the flange's less joint 2's share
//! ([`joint3_per_joint2`]).

use super::budget::{bench_solution, half_turn_u_rad};
use super::DifferenceTerm;
use crate::session::{Analysis, ExportContents};
use zerocal_core::bracket::{BracketMount, SEAT_REPEATABILITY_DEG};
use zerocal_core::model::{Arm, Convention, Gain};
use zerocal_core::session::{BudgetTerm, SESSION_JOINTS};
use zerocal_core::stage0::BiasOverTemperature;
use zerocal_core::stage1::{AxisOneTurn, Stage1Result};
use zerocal_core::stage2::{MEMS_CAPTURE_NOISE_DEG, MEMS_RANGE_DEG};

/// Two stage-1 poses are the same when joints 1 and 2 agree within this (rad), as the
/// flange's poses ([`super::SAME_POSE_RAD`]).
const SAME_STAGE1_RAD: f64 = 1e-9;

/// How a move of joint 2's zero shows in joint 3's line when the flange alone is
/// compared: joints 2 and 3 turn about parallel axes, so the flange turns by
/// `θ2 + r·θ3` about joint 2's axis, with `r` the dot product of joint 3's axis (in
/// link 2, at its zero) with joint 2's: +1 where both turn the same way (KUKA, ABB,
/// Stäubli, UR, PUMA), −1 where joint 3 turns the other way (the FANUC and Yaskawa
/// models: J3 / U about −y, J2 / L about +y). A move m2 of joint 2 alone reads as
/// joint 3 moving by `r·m2`.
pub fn joint3_per_joint2(arm: &Arm<f64>) -> f64 {
    let a2 = arm.joints[1].axis.unit::<f64>();
    let a3 = arm.joints[2].origin.rotation * arm.joints[2].axis.unit::<f64>();
    a2.dot(&a3)
}

/// Joint 2's move from the upper arm's readings, with its budget.
#[derive(Clone, Debug)]
pub(super) struct Joint2Move {
    /// Δθ2 now less Δθ2 at the reference (rad).
    pub moved_rad: f64,
    /// The terms of its uncertainty (deg, joint 2's column; the others zero).
    pub terms: Vec<DifferenceTerm>,
}

/// Why joint 2 was not compared (a note), or the comparison's refusal.
pub(super) enum NoJoint2 {
    /// Nothing to compare: the measurement has no upper-arm readings.
    NotMeasured,
    /// Not comparable, with the reason for the note.
    Skipped(String),
}

/// Stage 1 of one export solved as its session would solve it: its own stage-0 bias
/// (moved to stage 1's temperature by its own closing reversal), on `arm`.
fn solved(
    export: &ExportContents,
    turn: &AxisOneTurn<f64>,
    arm: &Arm<f64>,
    gain: Gain<f64>,
    captures_per_reading: f64,
) -> Result<Stage1Result<f64>, String> {
    let range = MEMS_RANGE_DEG.to_radians();
    let bias = match (export.stage0, export.bias.flatten()) {
        (Some(r), _) => BiasOverTemperature::measure(
            &r,
            export.closing.as_ref(),
            Convention::Axis,
            gain,
            range,
            0.0,
        )
        .map_err(|(step, e)| match step {
            zerocal_core::stage0::BenchStep::Stage0 => format!("stage 0: {e}"),
            zerocal_core::stage0::BenchStep::Closing => format!("closing bench readings: {e}"),
        })?,
        (None, Some(b)) => BiasOverTemperature::constant(b, None),
        (None, None) => return Err("no stage-0 bias".into()),
    };
    let t1 = export.stage1_temperature_c;
    let at = bias.at(t1);
    let variance = bias.variance_factor(t1) * captures_per_reading;
    turn.solve_with_gain(arm, Convention::Axis, gain, Some((&at, variance)), range)
        .map_err(|e| format!("stage 1: {e}"))
}

fn column(u_rad: f64) -> [f64; SESSION_JOINTS] {
    let mut v = [0.0; SESSION_JOINTS];
    v[0] = u_rad.to_degrees();
    v
}

/// Joint 2's move between `reference` and `now` from their upper-arm readings.
///
/// `half_turn_tolerance_deg` is stage 0's, as for the flange's comparison.
pub(super) fn joint2_move(
    reference: &Analysis,
    now: &ExportContents,
    half_turn_tolerance_deg: f64,
) -> Result<Joint2Move, NoJoint2> {
    let Some(turn_now) = now.stage1.flatten() else {
        return Err(NoJoint2::NotMeasured);
    };
    let Some(turn_ref) = reference.export.stage1.flatten() else {
        return Err(NoJoint2::Skipped(
            "the reference has no stage-1 readings".into(),
        ));
    };
    if (turn_now.j1_rad - turn_ref.j1_rad).abs() > SAME_STAGE1_RAD
        || (turn_now.j2_rad - turn_ref.j2_rad).abs() > SAME_STAGE1_RAD
    {
        return Err(NoJoint2::Skipped(format!(
            "the upper-arm readings were taken at joint 1 {:.3} deg, joint 2 {:.3} deg, the \
             reference's at {:.3} deg, {:.3} deg: not the same pose",
            turn_now.j1_rad.to_degrees(),
            turn_now.j2_rad.to_degrees(),
            turn_ref.j1_rad.to_degrees(),
            turn_ref.j2_rad.to_degrees()
        )));
    }
    // The same arm and bracket for both: a calibration error of the bracket is then
    // common and cancels; another bracket's or calibration's does not (a term below).
    // The same pendant: both solved with the sensor gain the reference's fit estimated,
    // as the session solves its stages 0-1 again with it (a nominal gain moves each
    // bench's circle centre by ~1 % of that bench's tilt, another error on each).
    let gain = reference.solution.fit.gain();
    let arm = reference
        .export
        .brackets
        .apply_with_gain(&reference.profile.arm, &gain);
    // A stage-1 reading is the mean of its two captures (from below and above).
    let per_reading = 2.0;
    let r = solved(&reference.export, &turn_ref, &arm, gain, per_reading)
        .map_err(|e| NoJoint2::Skipped(format!("the reference's {e}")))?;
    let n = solved(now, &turn_now, &arm, gain, per_reading)
        .map_err(|e| NoJoint2::Skipped(format!("this measurement's {e}")))?;
    let moved_rad = n.delta_theta2_rad - r.delta_theta2_rad;
    if !moved_rad.is_finite() {
        return Err(NoJoint2::Skipped("joint 2's move is not a number".into()));
    }
    // The readings' noise and both biases' (each solve's covariance is in units of one
    // reading's noise variance: a capture's over the captures a reading averages).
    let sigma = MEMS_CAPTURE_NOISE_DEG.to_radians() / per_reading.sqrt();
    let noise = sigma * (r.covariance[2][2].max(0.0) + n.covariance[2][2].max(0.0)).sqrt();
    let reference_terms = &reference.budget.terms_rad;
    let both = |t: BudgetTerm| reference_terms[t.index()][0] * 2f64.sqrt();
    let seat = SEAT_REPEATABILITY_DEG.to_radians() / 3f64.sqrt() * 2f64.sqrt();
    // The half turn of each stage 0 on its bench where two headings assume one (three
    // or more solve their turns): Δθ2 takes the x bias whole.
    let half_turn = |export: &ExportContents| {
        bench_solution(export, &gain).map_or(0.0, |b| half_turn_u_rad(&b, half_turn_tolerance_deg))
    };
    let half_turns = half_turn(&reference.export).hypot(half_turn(now));
    let mut terms = vec![
        DifferenceTerm {
            term: "joint 2: upper-arm readings and stage-0 biases of both (noise)".into(),
            standard_uncertainty_deg: column(noise),
        },
        DifferenceTerm {
            term: "joint 2: both stage-0 half turns on a tilted bench".into(),
            standard_uncertainty_deg: column(half_turns),
        },
        DifferenceTerm {
            term: "joint 2: robot repeatability at the upper-arm pose, both".into(),
            standard_uncertainty_deg: column(both(BudgetTerm::Repeatability)),
        },
        DifferenceTerm {
            term: "joint 2: backlash side at the upper-arm pose, both".into(),
            standard_uncertainty_deg: column(both(BudgetTerm::Stage1Backlash)),
        },
        DifferenceTerm {
            term: "joint 2: upper-arm bracket seated twice".into(),
            standard_uncertainty_deg: column(seat),
        },
    ];
    let reference_bracket = reference.export.brackets.get(BracketMount::UpperArm);
    let now_bracket = now.brackets.get(BracketMount::UpperArm);
    if reference_bracket != now_bracket {
        let u = |c: Option<&zerocal_core::bracket::BracketCalibration<f64>>| {
            c.map_or(
                zerocal_core::bracket::UNCALIBRATED_BRACKET_DEG.to_radians() / 3f64.sqrt(),
                |c| c.uncertainty_rad,
            )
        };
        terms.push(DifferenceTerm {
            term: "joint 2: upper-arm bracket: another bracket or calibration than the \
                   reference's"
                .into(),
            standard_uncertainty_deg: column(u(reference_bracket).hypot(u(now_bracket))),
        });
    }
    Ok(Joint2Move { moved_rad, terms })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn joint_3_turns_against_joint_2_on_the_fanuc_and_yaskawa_models() {
        // From the profiles' URDF axes: J2 / L about +y, J3 / U about -y on the FANUC
        // and Yaskawa models; the same direction on every other built-in.
        let against = [
            "fanuc-lrmate200id",
            "fanuc-m20ia",
            "yaskawa-gp7",
            "yaskawa-mh5lf",
        ];
        for name in zerocal_profile::builtin_names() {
            let p = zerocal_profile::builtin(name).unwrap();
            let r = if against.contains(&name) { -1.0 } else { 1.0 };
            assert!((joint3_per_joint2(&p.arm) - r).abs() < 1e-12, "{name}");
        }
    }
}
