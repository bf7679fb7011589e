//! The TCP test against the best zero-only correction: how far a tool point is from
//! where the nominal model puts it, over random reachable poses, with no correction
//! entered, with the offsets a session found entered, and with the zero offsets that
//! would do best on this very robot.
//!
//! A real arm is more than its zeros (misaligned axes, transmission error, sag): no
//! zero correction brings its TCP error to 0. The best one says how much of the error
//! zeros can remove at all, so `after / best` says how close a session's offsets come
//! to that, whatever the rest of the arm does.

use crate::positioning::{random_poses, ArmError, ARM_JOINTS};
use crate::SimRobot;
use nalgebra::{DMatrix, DVector, Vector3};
use serde::Serialize;
use zerocal_core::model::Arm;
use zerocal_profile::Profile;

/// Offsets the pendant calibrates: Δθ2..Δθ6.
pub const CALIBRATED_JOINTS: usize = ARM_JOINTS - 1;

/// Step of the numerical Jacobian's central differences (rad).
pub const JACOBIAN_STEP_RAD: f64 = 1e-7;

/// The search for the best correction stops when no offset moves more than this (rad).
pub const CONVERGED_STEP_RAD: f64 = 1e-10;

/// Iterations the search may take (each one a Jacobian or a damped retry) before it
/// reports that it did not converge. The problem is nearly linear (offsets of a
/// fraction of a degree): Gauss-Newton takes a handful.
pub const MAX_ITERATIONS: usize = 100;

/// A joint whose offset moves the TCP less than this fraction of the most telling
/// joint's does is one the TCP cannot see (joint 6 with the tool point on its axis):
/// the best keeps it as entered. A numerical choice: on the KR 6 and IRB 140 with the
/// tool on the flange normal (the twenty robots of host-tests/tests/tcp.rs), joint 6's
/// column is 0 and the smallest other one 0.16 of the largest; central differences of
/// 1e-7 rad on millimetre positions leave about 1e-9 of a column in rounding.
pub const UNSEEN_FRACTION: f64 = 1e-6;

/// Two mean TCP errors below this (mm) are numerically the same: a correction that is
/// perfect by construction then reads a ratio of 1, not 0/0 (a numerical floor, 1 nm,
/// not a measurement's resolution).
pub const TCP_FLOOR_MM: f64 = 1e-6;

/// The TCP test's figures.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TcpCheck {
    /// Mean TCP distance error with no correction entered (mm).
    pub mean_before_mm: f64,
    /// With the given offsets entered (mm).
    pub mean_after_mm: f64,
    /// With the best zero-only correction entered (mm).
    pub mean_best_mm: f64,
    /// RMS TCP distance error with no correction (mm).
    pub rms_before_mm: f64,
    /// RMS with the given offsets entered (mm).
    pub rms_after_mm: f64,
    /// RMS with the best correction (mm): the least any zero-only correction reaches
    /// over these poses, the quantity the best minimises.
    pub rms_best_mm: f64,
    /// The best correction Δθ1..Δθ6 (rad): Δθ1 is 0 (the pendant does not calibrate
    /// joint 1), and a joint in [`Self::held`] keeps its entered value.
    pub best_offsets_rad: [f64; ARM_JOINTS],
    /// Joints the best did not move from the entered value: joint 1, and any whose
    /// offset does not move the TCP ([`UNSEEN_FRACTION`]).
    pub held: [bool; ARM_JOINTS],
    /// `mean_after_mm / mean_best_mm`, both floored at [`TCP_FLOOR_MM`]: 1 when the
    /// entered offsets do as well as any zero correction can. It may fall a little
    /// below 1: the best minimises the mean SQUARED distance, not the mean distance
    /// (the RMS ratio `rms_after_mm / rms_best_mm` is never below 1).
    pub ratio_to_best: f64,
    /// Test poses.
    pub poses: usize,
}

/// The TCP's position (mm): the point `tool_m` along the flange frame's z, at joint
/// angles `q_rad` of `arm`. The flange frame is the profile's (`[flange]`, the
/// controller's tool0/flange frame), whose z is the flange normal pointing out of the
/// flange, i.e. along joint 6's axis: [`Arm::frames`] returns it in the base frame.
pub fn tcp_position_mm(arm: &Arm<f64>, q_rad: &[f64; ARM_JOINTS], tool_m: f64) -> Vector3<f64> {
    let (_, flange) = arm.frames(q_rad);
    (flange.translation_m + flange.rotation * Vector3::new(0.0, 0.0, tool_m)) * 1000.0
}

/// The poses and the two arms: the nominal TCP at each pose, and the real one for a
/// given entered correction.
struct Bench<'a> {
    robot: &'a SimRobot,
    poses: Vec<[f64; ARM_JOINTS]>,
    nominal_mm: Vec<Vector3<f64>>,
    tool_m: f64,
}

impl Bench<'_> {
    /// The real TCP − nominal TCP at every pose (mm), with `entered_rad` (Δθ1..Δθ6)
    /// typed into the controller: the true joint is then
    /// `q + (true offset − entered)` plus the robot's deterministic errors.
    fn errors_mm(
        &self,
        entered_rad: &[f64; ARM_JOINTS],
    ) -> impl Iterator<Item = Vector3<f64>> + '_ {
        let residual: [f64; ARM_JOINTS] =
            core::array::from_fn(|k| self.robot.offsets_rad[k] - entered_rad[k]);
        self.poses
            .iter()
            .zip(&self.nominal_mm)
            .map(move |(q, nominal)| {
                let joints = self
                    .robot
                    .errors
                    .true_joints_rad(&self.robot.arm, q, &residual);
                tcp_position_mm(&self.robot.arm, &joints, self.tool_m) - nominal
            })
    }

    /// Mean and RMS distance (mm).
    fn mean_rms_mm(&self, entered_rad: &[f64; ARM_JOINTS]) -> (f64, f64) {
        let n = self.poses.len() as f64;
        let (sum, sum_sq) = self
            .errors_mm(entered_rad)
            .fold((0.0, 0.0), |(s, q), e| (s + e.norm(), q + e.norm_squared()));
        (sum / n, (sum_sq / n).sqrt())
    }

    /// The stacked error vector (3 per pose, mm).
    fn residual_mm(&self, entered_rad: &[f64; ARM_JOINTS]) -> DVector<f64> {
        DVector::from_iterator(
            3 * self.poses.len(),
            self.errors_mm(entered_rad).flat_map(|e| [e.x, e.y, e.z]),
        )
    }

    /// Central-difference Jacobian of [`Self::residual_mm`] in the `free` joints.
    fn jacobian(&self, at: &[f64; ARM_JOINTS], free: &[usize]) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(3 * self.poses.len(), free.len());
        for (c, &k) in free.iter().enumerate() {
            let (mut plus, mut minus) = (*at, *at);
            plus[k] += JACOBIAN_STEP_RAD;
            minus[k] -= JACOBIAN_STEP_RAD;
            let d =
                (self.residual_mm(&plus) - self.residual_mm(&minus)) / (2.0 * JACOBIAN_STEP_RAD);
            j.set_column(c, &d);
        }
        j
    }

    /// The zero correction (joints 2-6) minimising the mean squared TCP distance,
    /// from `start`: Levenberg-Marquardt on the numerical Jacobian. Joints the TCP
    /// does not see stay at `start`. Returns the correction and which joints were held.
    fn best(
        &self,
        start: &[f64; ARM_JOINTS],
    ) -> Result<([f64; ARM_JOINTS], [bool; ARM_JOINTS]), ArmError> {
        let mut held = [true; ARM_JOINTS];
        let all: Vec<usize> = (1..ARM_JOINTS).collect();
        let j0 = self.jacobian(start, &all);
        let norms: Vec<f64> = j0.column_iter().map(|c| c.norm()).collect();
        let largest = norms.iter().copied().fold(0.0, f64::max);
        let free: Vec<usize> = all
            .iter()
            .zip(&norms)
            .filter(|(_, n)| **n > UNSEEN_FRACTION * largest)
            .map(|(k, _)| *k)
            .collect();
        for &k in &free {
            held[k] = false;
        }
        let mut x = *start;
        if free.is_empty() {
            return Ok((x, held));
        }
        let mut r = self.residual_mm(&x);
        let mut cost = r.norm_squared();
        let mut jac = self.jacobian(&x, &free);
        // Marquardt's damping, scaled to each parameter's curvature; small at first
        // (the problem is nearly linear), raised only when a step makes things worse.
        let mut lambda = 1e-6;
        for _ in 0..MAX_ITERATIONS {
            let jtj = jac.transpose() * &jac;
            let g = jac.transpose() * &r;
            let mut a = jtj.clone();
            for i in 0..free.len() {
                a[(i, i)] += lambda * jtj[(i, i)];
            }
            let Some(chol) = a.cholesky() else {
                lambda *= 10.0;
                continue;
            };
            let step = chol.solve(&(-g));
            let mut trial = x;
            for (&k, s) in free.iter().zip(step.iter()) {
                trial[k] += s;
            }
            let r_trial = self.residual_mm(&trial);
            let cost_trial = r_trial.norm_squared();
            let small = step.amax() < CONVERGED_STEP_RAD;
            if cost_trial <= cost {
                x = trial;
                r = r_trial;
                cost = cost_trial;
                if small {
                    return Ok((x, held));
                }
                lambda = (lambda * 0.1).max(1e-12);
                jac = self.jacobian(&x, &free);
            } else if small {
                // At the floor of the arithmetic: no step that small lowers the sum.
                return Ok((x, held));
            } else {
                lambda *= 10.0;
            }
        }
        Err(ArmError::BestNotConverged {
            iterations: MAX_ITERATIONS,
        })
    }
}

/// The TCP test: `n_poses` seeded random reachable poses of the NOMINAL arm within the
/// profile's joint limits ([`random_poses`]), a tool point `tool_m` along the flange
/// normal ([`tcp_position_mm`]), and the mean distance between the real TCP (the true
/// arm at its true joints, [`crate::robot::RobotErrors::true_joints_rad`]) and the
/// nominal one (the profile's arm at the commanded joints):
///
/// - before: nothing entered;
/// - after: `entered_rad` (Δθ2..Δθ6) entered;
/// - best: the Δθ2..Δθ6 minimising the mean squared distance over the same poses.
///
/// Joint 1 is never corrected: the pendant does not calibrate it (it turns about the
/// vertical, which no inclinometer sees). The base tilt is no part of the TCP error:
/// both TCPs are in the robot's base frame, as a tracker test registers it. Typical:
/// 200 poses, a 0.1 m tool.
///
/// # Errors
/// The profile has no lengths or missing joints, no poses reach the workspace, zero
/// poses were asked for, the tool length or an entered offset is not finite, or the
/// search for the best correction did not converge.
pub fn tcp_check(
    nominal: &Profile,
    robot: &SimRobot,
    entered_rad: &[f64; CALIBRATED_JOINTS],
    n_poses: usize,
    tool_m: f64,
    seed: u64,
) -> Result<TcpCheck, ArmError> {
    if n_poses == 0 {
        return Err(ArmError::NoPoses);
    }
    if !tool_m.is_finite() {
        return Err(ArmError::NotFinite {
            what: "the tool length".to_owned(),
        });
    }
    if let Some(k) = entered_rad.iter().position(|e| !e.is_finite()) {
        return Err(ArmError::NotFinite {
            what: format!("the entered offset of joint {}", k + 2),
        });
    }
    let mut limits_deg = [(0.0, 0.0); ARM_JOINTS];
    for (k, limit) in limits_deg.iter_mut().enumerate() {
        let j = nominal
            .joints
            .get(k)
            .ok_or(ArmError::MissingJoint { joint: k + 1 })?;
        *limit = (j.min_deg, j.max_deg);
    }
    let poses = random_poses(&nominal.arm, &limits_deg, n_poses, seed)?;
    let nominal_mm = poses
        .iter()
        .map(|q| tcp_position_mm(&nominal.arm, q, tool_m))
        .collect();
    let bench = Bench {
        robot,
        poses,
        nominal_mm,
        tool_m,
    };
    let mut entered = [0.0; ARM_JOINTS];
    entered[1..].copy_from_slice(entered_rad);
    let (mean_before_mm, rms_before_mm) = bench.mean_rms_mm(&[0.0; ARM_JOINTS]);
    let (mean_after_mm, rms_after_mm) = bench.mean_rms_mm(&entered);
    let (best_offsets_rad, held) = bench.best(&entered)?;
    let (mean_best_mm, rms_best_mm) = bench.mean_rms_mm(&best_offsets_rad);
    Ok(TcpCheck {
        mean_before_mm,
        mean_after_mm,
        mean_best_mm,
        rms_before_mm,
        rms_after_mm,
        rms_best_mm,
        best_offsets_rad,
        held,
        ratio_to_best: mean_after_mm.max(TCP_FLOOR_MM) / mean_best_mm.max(TCP_FLOOR_MM),
        poses: bench.poses.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The KR 6's flange frame (tool0, KUKA's $FLANGE) has its z out of the flange: at
    /// all-zero the arm points along +x, so a 0.1 m tool sits 100 mm beyond the flange's
    /// (980, 0, 435) mm along +x (rounding only).
    #[test]
    fn the_tool_point_lies_along_the_flange_normal() {
        let p = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap_or_else(|e| panic!("{e}"));
        let tcp = tcp_position_mm(&p.arm, &[0.0; ARM_JOINTS], 0.1);
        assert!(
            (tcp - Vector3::new(1080.0, 0.0, 435.0)).norm() < 1e-9,
            "{tcp}"
        );
    }
}
