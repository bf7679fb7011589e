//! Two measurements of one robot at the same poses: how far each joint's zero moved
//! between them. The reference is a whole session, solved; the other (a check, or a
//! session after a motor swap) needs only stage 0's bench reversal and some of the
//! reference's stage-2 poses, commanded at the same joint angles.
//!
//! The reference's fitted model (its base tilt, its sensor gain and cross-axis, its
//! sag, the misalignments it estimated) predicts the reading at each pose; its residual
//! there (what the model does not hold: the reducers' transmission error at that
//! angle, the geometry no pose separates, the bracket's calibration error) is the same
//! at the same commanded angles on the same robot with the same bracket, so it is
//! carried over whole, and only the offsets and the bias move. The bias' component
//! that the poses cannot tell from Δθ6 comes from the two sessions' stage-0
//! reversals; the other is estimated with the offsets, as the session estimates it.
//!
//! Gravity sees joints 2 and 3 only together at the flange (their axes are parallel):
//! where the measurement has the upper arm's readings at the reference's stage-1 pose,
//! joint 2's move comes from them ([`joint2`]) and joint 3's is the flange's less joint
//! 2's share; without them joint 2's zero is taken as unchanged and the combination's
//! move is joint 3's. [`Comparison::notes`] says which.
//!
//! Before any number is given, the two measurements must be of one robot
//! ([`consistency`]): what the comparison leaves at the common poses is held against
//! what two measurements of one robot leave (the sensor's noise, the robot's
//! repeatability and backlash, the transmission error over the zeros' moves), not
//! against its own residuals.

mod budget;
pub mod consistency;
pub mod entry_check;
mod joint2;
pub mod mistake;

pub use budget::{DifferenceBudget, DifferenceTerm};
pub use consistency::Consistency;
pub use joint2::joint3_per_joint2;

use crate::session::{Analysis, ExportContents};
use nalgebra::{DMatrix, DVector};
use zerocal_core::model::{Convention, Gain, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::session::SESSION_JOINTS;
use zerocal_core::stage0::BenchSolution;
use zerocal_core::stage2::{
    moved_reading, Param, PoseReading, MEMS_CAPTURE_NOISE_DEG, MEMS_RANGE_DEG,
};

/// Two commanded poses are the same when every joint agrees within this (rad): the
/// export writes joints to 1e-12°, so anything larger is another pose.
pub(crate) const SAME_POSE_RAD: f64 = 1e-9;

/// Fewest poses the comparison solves on: four offsets and a bias component from two
/// readings a pose need three poses; four leave room for σ.
pub const MIN_COMPARED_POSES: usize = 4;

/// Gauss-Newton steps at most; the model is smooth and a move of a degree converges in
/// three.
const MAX_STEPS: usize = 12;

/// The turn of the flange bracket (rad) the offsets' response to a seat's turn is
/// differentiated over: far above the readings' rounding (1e-16 of a radian), far
/// below where the model bends.
const MOUNT_STEP_RAD: f64 = 1e-6;

/// The readings' sandwich covariance is taken where the poses number at least this many
/// times the unknowns: a cluster-robust estimate is only as good as its clusters are
/// many (a restore from a whole session: 40 poses for 5 unknowns).
const SANDWICH_POSES_PER_UNKNOWN: usize = 4;

/// A step below this (rad) has converged.
const CONVERGED_RAD: f64 = 1e-12;

/// Why two measurements cannot be compared.
#[derive(Clone, Debug, PartialEq)]
pub enum CompareError {
    /// The measurement has no stage-0 reversal: its bias is unknown.
    NoStage0,
    /// Its stage-0 readings are refused (out of range).
    Stage0(String),
    /// Too few of its poses are the reference's.
    TooFewCommonPoses {
        /// Poses of the measurement.
        poses: usize,
        /// Of which at the reference's commanded joints.
        common: usize,
    },
    /// The reference session was solved with another sensor convention.
    Convention,
    /// The solve did not converge or gave a non-finite number.
    NoSolution(String),
    /// What the comparison leaves is far more than two measurements of one robot
    /// leave: the measurement is of another robot (or this one was moved).
    OtherRobot(Consistency),
}

impl core::fmt::Display for CompareError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            CompareError::NoStage0 => write!(
                f,
                "no stage-0 reversal in the export: the bias it was measured with is unknown \
                 (make the bench reversal before mounting the pendant)"
            ),
            CompareError::Stage0(e) => write!(f, "stage 0: {e}"),
            CompareError::TooFewCommonPoses { poses, common } => write!(
                f,
                "only {common} of the export's {poses} poses are at the reference session's \
                 commanded joints (at least {MIN_COMPARED_POSES} are needed): run the check \
                 program written for this robot's plan (zerocal program --check)"
            ),
            CompareError::Convention => write!(
                f,
                "the reference session is the paper's rpy sensor: a comparison needs the \
                 SCL3300's axis convention"
            ),
            CompareError::NoSolution(e) => write!(f, "the comparison did not solve: {e}"),
            CompareError::OtherRobot(c) => write!(
                f,
                "not the reference's robot: at the poses both measured, the comparison leaves \
                 {:.5} deg RMS where two measurements of one robot leave {:.5} deg (the \
                 sensor's noise, the robot's repeatability and backlash, the transmission \
                 error over the zeros' moves): {:.1} times, above the limit of {}. The export \
                 is of another robot, or this robot's base was moved since the reference",
                c.residual_rms_deg,
                c.expected_rms_deg,
                c.ratio,
                consistency::CONSISTENCY_LIMIT
            ),
        }
    }
}

/// What moved between the reference and the measurement.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// How far each zero moved, Δθ2..Δθ6 now less at the reference (rad, the model's
    /// terms: true − commanded). Joint 2's is 0 by assumption (see the notes).
    pub moved_rad: [f64; SESSION_JOINTS],
    /// Its budget.
    pub budget: DifferenceBudget,
    /// Poses compared.
    pub poses: usize,
    /// The comparison's residual RMS (rad).
    pub residual_rms_rad: f64,
    /// Joints whose move was measured: joint 2 only from the upper arm's readings; a
    /// held twin never (their sum is the earlier joint's). Joint 3's move
    /// (`moved_rad[1]`) is always the flange's: joints 2 and 3 together, as joint 3's
    /// (joint 2 held); [`Comparison::joint3_own`] takes joint 2's share out.
    pub identifiable: [bool; SESSION_JOINTS],
    /// How a move of joint 2 alone shows in joint 3's line at the flange
    /// ([`joint3_per_joint2`]): without joint 2 measured, joint 3's move is joint 3's
    /// plus this times joint 2's.
    pub joint3_per_joint2: f64,
    /// The test that both measurements are of one robot, passed.
    pub consistency: Consistency,
    /// What was assumed.
    pub notes: Vec<String>,
}

/// One pose of both: the mean of each one's captures there.
struct Pair {
    joints_rad: [f64; JOINTS],
    reference: Tilt<f64>,
    reference_captures: usize,
    now: Tilt<f64>,
    now_captures: usize,
    now_temperature_c: Option<f64>,
    reference_temperature_c: Option<f64>,
}

/// Whole turns apart count as the same: a wrist joint at θ + 360° is the same physical
/// pose, and `zerocal plan` turns wrist joints so (`zerocal_programs::timing::unwind`), so a check
/// planned by one version matches a session planned by another.
fn same_pose(a: &[f64; JOINTS], b: &[f64; JOINTS]) -> bool {
    use std::f64::consts::{PI, TAU};
    a.iter()
        .zip(b)
        .all(|(x, y)| ((x - y + PI).rem_euclid(TAU) - PI).abs() <= SAME_POSE_RAD)
}

/// The captures at one commanded pose, averaged: (mean reading, count, mean temperature).
fn mean_at(
    poses: &[PoseReading<f64>],
    at: &[f64; JOINTS],
) -> Option<(Tilt<f64>, usize, Option<f64>)> {
    let here: Vec<&PoseReading<f64>> = poses
        .iter()
        .filter(|p| same_pose(&p.joints_rad, at))
        .collect();
    if here.is_empty() {
        return None;
    }
    let n = here.len() as f64;
    let x = here.iter().map(|p| p.reading.x_rad).sum::<f64>() / n;
    let y = here.iter().map(|p| p.reading.y_rad).sum::<f64>() / n;
    let temps: Vec<f64> = here.iter().filter_map(|p| p.temperature_c).collect();
    let t = (temps.len() == here.len()).then(|| temps.iter().sum::<f64>() / n);
    Some((Tilt::new(x, y), here.len(), t))
}

fn pairs(reference: &[PoseReading<f64>], now: &[PoseReading<f64>]) -> (Vec<Pair>, usize) {
    let mut distinct: Vec<[f64; JOINTS]> = Vec::new();
    for p in now {
        if !distinct.iter().any(|d| same_pose(d, &p.joints_rad)) {
            distinct.push(p.joints_rad);
        }
    }
    let total = distinct.len();
    let pairs = distinct
        .iter()
        .filter_map(|q| {
            let (r, rn, rt) = mean_at(reference, q)?;
            let (n, nn, nt) = mean_at(now, q)?;
            Some(Pair {
                joints_rad: *q,
                reference: r,
                reference_captures: rn,
                now: n,
                now_captures: nn,
                now_temperature_c: nt,
                reference_temperature_c: rt,
            })
        })
        .collect();
    (pairs, total)
}

/// The measurement's stage-0 bench solve (its bias) and its temperature, solved
/// with the reference fit's sensor gain as the reference's own bias was
/// ([`budget::bench_solution`]).
fn stage0_bias(
    now: &ExportContents,
    gain: &Gain<f64>,
) -> Result<(BenchSolution<f64>, Option<f64>), CompareError> {
    let s0 = now.stage0.ok_or(CompareError::NoStage0)?;
    let solution = s0
        .turns
        .solve(Convention::Axis, *gain, MEMS_RANGE_DEG.to_radians(), 0.0)
        .map_err(|e| CompareError::Stage0(e.to_string()))?;
    Ok((solution, s0.temperature_c))
}

/// What a comparison assumes besides the two measurements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompareOptions {
    /// `gearbox_replaced[k]`: joint k+2's reducer was changed between them (its
    /// transmission error is then not the reference's).
    pub gearbox_replaced: [bool; SESSION_JOINTS],
    /// How far each stage-0 half turn may be off 180° (deg), as `zerocal session`'s
    /// option of that name.
    pub half_turn_tolerance_deg: f64,
}

impl Default for CompareOptions {
    fn default() -> Self {
        CompareOptions {
            gearbox_replaced: [false; SESSION_JOINTS],
            half_turn_tolerance_deg: zerocal_core::session::DEFAULT_HALF_TURN_TOLERANCE_DEG,
        }
    }
}

/// Compares the measurement `now` with the solved `reference`.
///
/// # Errors
/// [`CompareError`]: no stage 0, too few common poses, no convergence.
pub fn compare(
    reference: &Analysis,
    now: &ExportContents,
    options: &CompareOptions,
) -> Result<Comparison, CompareError> {
    if reference.export.robot.as_ref().map(|r| r.1) != Some(Convention::Axis) {
        return Err(CompareError::Convention);
    }
    let model = &reference.solution.model;
    let fit = &reference.solution.fit;
    // The same pendant: its gain and cross-axis terms are the reference fit's, and the
    // measurement's bench is solved with them as the reference's was (a nominal gain
    // draws a tilted bench's circle as an ellipse and moves its centre by ~1 % of the
    // tilt, a different error on each bench).
    let gain = fit.gain();
    let (bench_now, t0_now) = stage0_bias(now, &gain)?;
    let b0_now = bench_now.bias;
    let both_biases_u_rad = budget::stage0_bias_u_rad(
        budget::bench_solution(&reference.export, &gain).as_ref(),
        options.half_turn_tolerance_deg,
    )
    .hypot(budget::stage0_bias_u_rad(
        Some(&bench_now),
        options.half_turn_tolerance_deg,
    ));
    let (pairs, total) = pairs(&reference.export.poses, &now.poses);
    if pairs.len() < MIN_COMPARED_POSES {
        return Err(CompareError::TooFewCommonPoses {
            poses: total,
            common: pairs.len(),
        });
    }
    // The bias the reference's model holds (its stages' plus what its fit estimated),
    // at its reference temperature; the measurement's is its own stage 0's, moved to
    // that temperature by the reference's drift.
    let fitted = |p: Param| fit.values[p.index()];
    let reference_bias = Tilt::new(
        model.sensor.bias.x_rad + fitted(Param::BiasX),
        model.sensor.bias.y_rad + fitted(Param::BiasY),
    );
    let dt = t0_now.map_or(0.0, |t| t - model.reference_temperature_c);
    let now_bias = Tilt::new(
        b0_now.x_rad - model.drift_per_k.x_rad * dt,
        b0_now.y_rad - model.drift_per_k.y_rad * dt,
    );
    let shift = Tilt::new(
        now_bias.x_rad - reference_bias.x_rad,
        now_bias.y_rad - reference_bias.y_rad,
    );
    // The component stage 2 estimates is estimated here too; the other is stage 0's.
    let free_bias = [fit.extras.bias_x, fit.extras.bias_y];
    let held = fit.extras.held;
    let wrist: Vec<usize> = (0..WRIST_JOINTS).filter(|&k| !held[k]).collect();
    let free: Vec<usize> = (0..2).filter(|&c| free_bias[c]).collect();
    let n_params = wrist.len() + free.len();
    let w_y = model.y_weight;
    // The reference's residual at each pose, carried over.
    let pose_at = |p: &Pair, reading: Tilt<f64>, t: Option<f64>| PoseReading {
        joints_rad: p.joints_rad,
        reading,
        temperature_c: t,
    };
    let carried: Vec<Tilt<f64>> = pairs
        .iter()
        .map(|p| {
            let at = pose_at(p, p.reference, p.reference_temperature_c);
            let f = moved_reading(model, fit, &at, &[0.0; WRIST_JOINTS], &Tilt::default());
            Tilt::new(
                p.reference.x_rad - f.reading.x_rad,
                p.reference.y_rad - f.reading.y_rad,
            )
        })
        .collect();
    let mut offsets = [0.0; WRIST_JOINTS];
    let mut bias_free = [0.0; 2];
    let mut jacobian = DMatrix::<f64>::zeros(2 * pairs.len(), n_params);
    let mut residual = DVector::<f64>::zeros(2 * pairs.len());
    let mut converged = false;
    for _ in 0..MAX_STEPS {
        let bias = Tilt::new(shift.x_rad + bias_free[0], shift.y_rad + bias_free[1]);
        for (i, (p, r)) in pairs.iter().zip(&carried).enumerate() {
            let at = pose_at(p, p.now, p.now_temperature_c);
            let m = moved_reading(model, fit, &at, &offsets, &bias);
            let e = [
                p.now.x_rad - r.x_rad - m.reading.x_rad,
                p.now.y_rad - r.y_rad - m.reading.y_rad,
            ];
            for (axis, e_axis) in e.iter().enumerate() {
                let w = if axis == 0 { 1.0 } else { w_y };
                let row = 2 * i + axis;
                residual[row] = e_axis * w;
                for (c, &k) in wrist.iter().enumerate() {
                    jacobian[(row, c)] = m.d_offsets[axis][k] * w;
                }
                for (c, &b) in free.iter().enumerate() {
                    jacobian[(row, wrist.len() + c)] = m.d_bias[axis][b] * w;
                }
            }
        }
        let step = jacobian
            .clone()
            .svd(true, true)
            .solve(&residual, 1e-12)
            .map_err(|e| CompareError::NoSolution(e.to_owned()))?;
        for (c, &k) in wrist.iter().enumerate() {
            offsets[k] += step[c];
        }
        for (c, &b) in free.iter().enumerate() {
            bias_free[b] += step[wrist.len() + c];
        }
        if step.iter().all(|s| s.abs() < CONVERGED_RAD) {
            converged = true;
            break;
        }
    }
    if !converged || offsets.iter().any(|o| !o.is_finite()) {
        return Err(CompareError::NoSolution(format!(
            "no convergence in {MAX_STEPS} steps"
        )));
    }
    // Residuals at the solution (the last pass computed them before its step), each
    // with what it is sensitive to, for the test that both are one robot's.
    let fixed: Vec<usize> = (0..2).filter(|&c| !free_bias[c]).collect();
    let rows: Vec<consistency::Row> = {
        let bias = Tilt::new(shift.x_rad + bias_free[0], shift.y_rad + bias_free[1]);
        pairs
            .iter()
            .zip(&carried)
            .flat_map(|(p, r)| {
                let at = pose_at(p, p.now, p.now_temperature_c);
                let m = moved_reading(model, fit, &at, &offsets, &bias);
                let noise_factor =
                    (1.0 / p.now_captures as f64) + (1.0 / p.reference_captures as f64);
                let e = [
                    p.now.x_rad - r.x_rad - m.reading.x_rad,
                    p.now.y_rad - r.y_rad - m.reading.y_rad,
                ];
                let fixed = &fixed;
                (0..2).map(move |axis| {
                    let w = if axis == 0 { 1.0 } else { w_y };
                    consistency::Row {
                        residual_rad: e[axis] * w,
                        d_offsets: m.d_offsets[axis].map(|d| d * w),
                        d_fixed_bias: fixed.iter().map(|&b| m.d_bias[axis][b]).sum::<f64>() * w,
                        noise_factor,
                        weight: w,
                    }
                })
            })
            .collect()
    };
    let ssr: f64 = rows.iter().map(|r| r.residual_rad * r.residual_rad).sum();
    let consistency = consistency::consistency(
        &rows,
        &consistency::Figures {
            moved_rad: offsets,
            gearbox_replaced: core::array::from_fn(|k| options.gearbox_replaced[k + 1]),
            bias_u_rad: both_biases_u_rad,
        },
    );
    if !consistency.one_robot() {
        return Err(CompareError::OtherRobot(consistency));
    }
    let readings = 2 * pairs.len();
    let residual_rms_rad = (ssr / readings as f64).sqrt();
    let dof = readings.saturating_sub(n_params);
    // σ of one compared reading: what the residuals show, at least the sensor's noise
    // figure through both sessions' means.
    let per_pose_captures =
        |p: &Pair| (1.0 / p.now_captures as f64) + (1.0 / p.reference_captures as f64);
    let mean_factor = pairs.iter().map(per_pose_captures).sum::<f64>() / pairs.len() as f64;
    let stated = MEMS_CAPTURE_NOISE_DEG.to_radians() * mean_factor.sqrt();
    let from_residuals = if dof > 0 {
        (ssr / dof as f64).sqrt()
    } else {
        0.0
    };
    let sigma_rad = from_residuals.max(stated);
    let jtj = jacobian.transpose() * &jacobian;
    let inverse = jtj
        .try_inverse()
        .ok_or_else(|| CompareError::NoSolution("the poses do not separate the offsets".into()))?;
    // The readings' share, two ways, the larger kept: σ²·(JᵀJ)⁻¹ with σ from the
    // residuals (each reading's error alike and independent), and the sandwich
    // (JᵀJ)⁻¹·(Σ gᵢgᵢᵀ)·(JᵀJ)⁻¹ over poses, gᵢ = Jᵢᵀrᵢ the pose's two rows, scaled by
    // readings/dof (GUM's Type A from the data, without that assumption). A pose's x and
    // y share its joints' repeatability, and the rows' weights follow the sensor's
    // noise, not the robot's: the first alone covered 34 of 40 KR 6 restores on joint 5
    // (error/u RMS 1.43). The sandwich's own scatter falls only with the number of poses
    // against the unknowns ([`SANDWICH_POSES_PER_UNKNOWN`]): a check's five poses for
    // five unknowns leave it as uncertain as what it estimates, so there the first
    // stands alone.
    let sandwich_usable = pairs.len() >= SANDWICH_POSES_PER_UNKNOWN * n_params;
    let sandwich = if !sandwich_usable {
        DMatrix::<f64>::zeros(n_params, n_params)
    } else {
        let mut meat = DMatrix::<f64>::zeros(n_params, n_params);
        for (i, pose_rows) in rows.chunks(2).enumerate() {
            let mut g = DVector::<f64>::zeros(n_params);
            for (axis, row) in pose_rows.iter().enumerate() {
                for c in 0..n_params {
                    g[c] += jacobian[(2 * i + axis, c)] * row.residual_rad;
                }
            }
            meat += &g * g.transpose();
        }
        let scale = if dof > 0 {
            readings as f64 / dof as f64
        } else {
            0.0
        };
        &inverse * meat * &inverse * scale
    };
    let mut type_a = [0.0; SESSION_JOINTS];
    for (c, &k) in wrist.iter().enumerate() {
        type_a[k + 1] = (inverse[(c, c)].max(0.0) * sigma_rad * sigma_rad)
            .max(sandwich[(c, c)])
            .sqrt();
    }
    // How the offsets follow the bias component stage 0 fixes: one unit of it, solved.
    let mut bias_sensitivity = [0.0; SESSION_JOINTS];
    if !fixed.is_empty() {
        let mut column = DVector::<f64>::zeros(readings);
        let bias = Tilt::new(shift.x_rad + bias_free[0], shift.y_rad + bias_free[1]);
        for (i, p) in pairs.iter().enumerate() {
            let at = pose_at(p, p.now, p.now_temperature_c);
            let m = moved_reading(model, fit, &at, &offsets, &bias);
            for axis in 0..2 {
                let w = if axis == 0 { 1.0 } else { w_y };
                column[2 * i + axis] = fixed.iter().map(|&b| m.d_bias[axis][b]).sum::<f64>() * w;
            }
        }
        let response = &inverse * (jacobian.transpose() * column);
        for (c, &k) in wrist.iter().enumerate() {
            bias_sensitivity[k + 1] = response[c].abs();
        }
    }
    // How the offsets follow a turn of the flange bracket on its seat about each of
    // the pendant's axes (one radian of it, solved as the comparison solves): a seat's
    // turn is a rotation of the pendant, not a bias, and over the poses' tilts it
    // reads partly as the wrist's offsets (joint 5's too), not only through the bias
    // component stage 0 fixes. The model's reading differentiated numerically.
    let mount_response: [[f64; SESSION_JOINTS]; 3] = {
        let bias = Tilt::new(shift.x_rad + bias_free[0], shift.y_rad + bias_free[1]);
        let turned = |axis: usize, angle: f64| {
            let mut m = *model;
            let mut v = nalgebra::Vector3::zeros();
            v[axis] = angle;
            m.arm.flange_mount *= nalgebra::Rotation3::new(v);
            m
        };
        core::array::from_fn(|axis| {
            let (plus, minus) = (turned(axis, MOUNT_STEP_RAD), turned(axis, -MOUNT_STEP_RAD));
            let mut column = DVector::<f64>::zeros(readings);
            for (i, p) in pairs.iter().enumerate() {
                let at = pose_at(p, p.now, p.now_temperature_c);
                let a = moved_reading(&plus, fit, &at, &offsets, &bias).reading;
                let b = moved_reading(&minus, fit, &at, &offsets, &bias).reading;
                column[2 * i] = (a.x_rad - b.x_rad) / (2.0 * MOUNT_STEP_RAD);
                column[2 * i + 1] = (a.y_rad - b.y_rad) / (2.0 * MOUNT_STEP_RAD) * w_y;
            }
            let response = &inverse * (jacobian.transpose() * column);
            let mut out = [0.0; SESSION_JOINTS];
            for (c, &k) in wrist.iter().enumerate() {
                out[k + 1] = response[c].abs();
            }
            out
        })
    };
    let mut moved_rad = [0.0; SESSION_JOINTS];
    moved_rad[1..].copy_from_slice(&offsets);
    let mut identifiable = [false; SESSION_JOINTS];
    for k in 0..WRIST_JOINTS {
        identifiable[k + 1] = !held[k];
    }
    let mut budget = budget::difference_budget(&budget::Inputs {
        reference,
        now,
        moved_rad: &moved_rad,
        type_a_rad: &type_a,
        bias_sensitivity: &bias_sensitivity,
        mount_response: &mount_response,
        both_biases_u_rad,
        options,
    });
    let j3_per_j2 = joint3_per_joint2(&reference.profile.arm);
    let mut notes = Vec::new();
    match joint2::joint2_move(reference, now, options.half_turn_tolerance_deg) {
        Ok(j2) => {
            moved_rad[0] = j2.moved_rad;
            identifiable[0] = true;
            budget.add_joint2(j2.terms);
            notes.push(format!(
                "joint 2 compared on the upper arm (stage 1's readings at the reference's \
                 stage-1 pose, each solved with its own stage 0). Joint 3's line holds what \
                 the flange sees, joints 2 and 3 together (θ2 {} θ3 about joint 2's axis), \
                 far better known than either alone; joint 3's own move is that less joint \
                 2's share",
                if j3_per_j2 < 0.0 { "−" } else { "+" }
            ));
        }
        Err(why) => {
            let because = match why {
                joint2::NoJoint2::NotMeasured => {
                    "the export has no upper-arm readings (stage 1)".to_owned()
                }
                joint2::NoJoint2::Skipped(e) => e,
            };
            notes.push(format!(
                "joint 2 not compared ({because}): its zero is taken as unchanged. Gravity at \
                 the flange sees joints 2 and 3 only together (θ2 {} θ3 about joint 2's axis), \
                 so joint 3's line holds their combination's move. Capture the upper arm in \
                 the check to compare joint 2 (docs/check.md); after a motor or gearbox \
                 change on joint 2, master it absolutely (zerocal session)",
                if j3_per_j2 < 0.0 { "−" } else { "+" }
            ));
        }
    }
    if held.iter().any(|h| *h) {
        notes.push(
            "a joint parallel to the one before it in every pose is not compared (its zero \
             needs another method); the earlier joint's move holds their sum"
                .into(),
        );
    }
    if pairs.len() < total {
        notes.push(format!(
            "{} of the export's {total} poses are not the reference's and were not compared",
            total - pairs.len()
        ));
    }
    Ok(Comparison {
        moved_rad,
        budget,
        poses: pairs.len(),
        residual_rms_rad,
        identifiable,
        joint3_per_joint2: j3_per_j2,
        consistency,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pose and the same pose with a wrist joint one turn round are one pose (a plan
    /// of another version may have turned it); a millionth of a radian apart is another.
    #[test]
    fn poses_whole_turns_apart_are_the_same_pose() {
        let a = [0.1, -0.5, 0.7, -3.0, 1.2, 3.1];
        let mut turned = a;
        turned[5] -= std::f64::consts::TAU;
        turned[3] += 2.0 * std::f64::consts::TAU;
        assert!(same_pose(&a, &turned));
        let mut other = a;
        other[4] += 1e-6;
        assert!(!same_pose(&a, &other));
        let mut half = a;
        half[5] += std::f64::consts::PI;
        assert!(!same_pose(&a, &half));
    }
}
