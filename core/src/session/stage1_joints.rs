//! Stage 2's rows against stage 1's record of joint 1: stage 2 runs with joint 1 where
//! stage 1 had it, and a row that says otherwise contradicts the stage-1 line in a way
//! the fit cannot see, so the session refuses it by name (`zerocal session`'s row
//! checks). Joint 2 may move: stage 2 swings it to tell its transmission error from
//! its zero (`crate::stage2::Param::Harmonic`), its angle at every row the row's own.

use crate::real::Real;
use crate::stage1::AxisOneTurn;
use crate::stage2::PoseReading;

/// How far a stage-2 capture's joint 1 may lie from stage 1's (deg): the tolerance the
/// pendant also holds a plan's joint 1 to against stage 1's (the link's 3 decimals, and
/// an `f32` of a few hundred degrees); 5× below the 0.005° aimed at, so a difference
/// within it moves no offset by anything that matters.
pub const STAGE1_JOINT1_TOLERANCE_DEG: f64 = 1e-3;

/// The first stage-2 capture whose joint `joint` (0-based: 0 or 1) differs from stage
/// 1's record of it by more than `tolerance_deg`; a non-finite joint differs too.
fn stage1_joint_mismatch<T: Real>(
    recorded_rad: T,
    joint: usize,
    tolerance_deg: f64,
    poses: &[PoseReading<T>],
) -> Option<usize> {
    let tolerance = crate::real::deg_to_rad(T::lit(tolerance_deg));
    poses.iter().position(|p| {
        p.joints_rad.get(joint).is_none_or(|q| {
            let off = (*q - recorded_rad).abs();
            !off.is_finite() || off > tolerance
        })
    })
}

/// The first stage-2 capture whose joint 1 differs from stage 1's by more than
/// [`STAGE1_JOINT1_TOLERANCE_DEG`]. Stage 2 runs with joint 1 back at stage 1's
/// angle (the programs and the pendant's plan keep it there). Stage 1's base tilt
/// and the sensor terms stage 2 hands back to it are read in the frame of stage 1's
/// recorded joint 1: an export whose stage-1 line and rows disagree on joint 1 (one
/// of them wrong, and nothing in the readings says which) gives a wrong Δθ3 with
/// nothing in the fit to show it, so it is refused rather than solved.
pub fn stage1_joint1_mismatch<T: Real>(
    stage1: &AxisOneTurn<T>,
    poses: &[PoseReading<T>],
) -> Option<usize> {
    stage1_joint_mismatch(stage1.j1_rad, 0, STAGE1_JOINT1_TOLERANCE_DEG, poses)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Tilt;

    fn at(joints_deg: [f64; 6]) -> PoseReading<f64> {
        PoseReading {
            joints_rad: joints_deg.map(f64::to_radians),
            reading: Tilt::new(0.0, 0.0),
            temperature_c: None,
        }
    }

    #[test]
    fn joint_1_must_stay_where_stage_1_had_it() {
        let turn = AxisOneTurn {
            before: Tilt::new(0.0, 0.0),
            after: Tilt::new(0.0, 0.0),
            j1_rad: 0.0,
            j2_rad: (-90.0f64).to_radians(),
        };
        let near = 0.5 * STAGE1_JOINT1_TOLERANCE_DEG;
        let beyond = 2.0 * STAGE1_JOINT1_TOLERANCE_DEG;
        let poses = [
            at([near, -90.0, 10.0, 0.0, 0.0, 0.0]),
            at([-near, -90.0, 20.0, 0.0, 0.0, 0.0]),
            // The export: stage 1 at joint 1 = 0, its rows at -90.
            at([-90.0, -90.0, 10.0, 0.0, 0.0, 0.0]),
        ];
        assert_eq!(stage1_joint1_mismatch(&turn, &poses[..2]), None);
        assert_eq!(stage1_joint1_mismatch(&turn, &poses), Some(2));
        // Just past the tolerance either way, and a joint that is no number.
        assert_eq!(
            stage1_joint1_mismatch(&turn, &[at([beyond, -90.0, 0.0, 0.0, 0.0, 0.0])]),
            Some(0)
        );
        assert_eq!(
            stage1_joint1_mismatch(&turn, &[at([-beyond, -90.0, 0.0, 0.0, 0.0, 0.0])]),
            Some(0)
        );
        assert_eq!(
            stage1_joint1_mismatch(&turn, &[at([f64::NAN, -90.0, 0.0, 0.0, 0.0, 0.0])]),
            Some(0)
        );
        // Joint 2 moves in stage 2: not joint 1's business.
        let j2_off = [at([0.0, -80.0, 0.0, 0.0, 0.0, 0.0])];
        assert_eq!(stage1_joint1_mismatch(&turn, &j2_off), None);
    }
}
