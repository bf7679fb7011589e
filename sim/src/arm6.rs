//! A full 6-axis arm for the positioning-accuracy side of the method: the paper's
//! 200-point laser-tracker test (TCP position error along X, Y, Z before and after
//! entering the identified zeros), reproduced in simulation, ISO 9283 style.
//!
//! The kinematics is a product of exponentials: each joint k turns right-handed about
//! the unit axis `ω_k` through the point `q_k`, both given at the home pose (all joints
//! 0) in the base frame, so `p(θ) = e^{ξ1θ1}·…·e^{ξ6θ6}·p_home`. Any serial 6R arm is
//! described by editing the data file (`data/arm6_kr6.json` is the KUKA KR 6 R900 sixx,
//! dimensions cited in the file), no code change.
//!
//! **Mapping onto the stage-2 wrist chain.** At the home pose every link frame is
//! aligned with the base frame, so with joints 1 and 2 at their zeros the flange
//! orientation is `E3(θ3)·E4(θ4)·E5(θ5)·E6(θ6)` with `Ek` the rotation about `ω_k`, and
//! no fixed rotations: [`Arm6::wrist_chain`] is that [`WristChain`], and the paper's
//! chain (x, y, x, y) is exactly the KR 6's (joint 3 ∥ joint 2 ∥ x; joint 4 along the
//! forearm, +y; joint 5 ∥ x; joint 6 along the flange axis, +y). The inclinometer is
//! clipped to the flange level at the home pose (sensor axes = base axes); on the upper
//! arm for stage 1 its x axis is ∥ joint 2, and `s2` is the sign of `ω_2` along x.
//! The joint angles of this file are 0 at the home pose: a controller whose zeros sit
//! elsewhere (KUKA: A2 = −90°, A3 = +90° there) maps onto them by a constant and a sign
//! per joint, which leaves the zero *offsets* unchanged up to that sign.
//!
//! **Error model.** The true joint angle is the commanded one plus the zero offset
//! Δθ (axis 1: none, gravity cannot see it and it stays at the mark). Before
//! compensation the TCP is at `p(θ + Δθ)` instead of `p(θ)`; after entering the
//! identified Δθ̂ (the controller commands `θ − Δθ̂`) it is at `p(θ + Δθ − Δθ̂)`.

use nalgebra::{Rotation3, Unit, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::fmt;
use zerocal_core::model::{JointAxis, WristChain, WRIST_JOINTS};

/// The KR 6 R900 sixx data file, built in.
pub const KR6_R900_JSON: &str = include_str!("../../data/arm6_kr6.json");

/// Joints of the arm.
pub const ARM_JOINTS: usize = 6;

/// One revolute joint at the home pose.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct JointSpec {
    /// Unit axis in the base frame at home (right-handed positive rotation).
    pub axis: [f64; 3],
    /// Any point on the axis at home (mm).
    pub point_mm: [f64; 3],
    /// Lower joint limit (deg).
    pub min_deg: f64,
    /// Upper joint limit (deg).
    pub max_deg: f64,
}

/// Where test poses may put the TCP.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Workspace {
    /// TCP at least this high above the base plane (mm).
    pub min_z_mm: f64,
    /// TCP at least this far from the joint-1 axis (mm).
    pub min_radius_mm: f64,
}

/// A 6-axis arm as the data file describes it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Arm6 {
    /// Model name.
    pub name: String,
    /// Where the dimensions come from.
    pub source: String,
    /// How the frame and the joint angles are defined.
    #[serde(default)]
    pub frame: String,
    /// Joints 1-6.
    pub joints: [JointSpec; ARM_JOINTS],
    /// Flange centre at home (mm).
    pub flange_mm: [f64; 3],
    /// TCP in flange coordinates (= base axes at home) (mm).
    pub tool_mm: [f64; 3],
    /// Where the test poses may go.
    pub workspace: Workspace,
}

/// What is wrong with an arm description.
#[derive(Debug)]
pub enum ArmError {
    /// Not valid JSON for an [`Arm6`] (serde's message has the line and column).
    Json(serde_json::Error),
    /// A joint axis is not a unit vector.
    AxisNotUnit {
        /// Joint number (1-6).
        joint: usize,
    },
    /// A joint's limits are not finite with min ≤ max.
    BadLimits {
        /// Joint number (1-6).
        joint: usize,
    },
    /// A number is not finite.
    NonFinite {
        /// Which field.
        field: &'static str,
    },
    /// Joints 3-6 must turn about base x, y or z at home for the stage-2 wrist chain;
    /// joint 1 about z and joint 2 about ±x for stage 1.
    NotAWristChain {
        /// Joint number (1-6).
        joint: usize,
    },
    /// No reachable pose in the workspace after many draws.
    WorkspaceUnreachable {
        /// Draws tried.
        tries: u64,
    },
}

impl fmt::Display for ArmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ArmError::Json(e) => write!(f, "arm file: {e}"),
            ArmError::AxisNotUnit { joint } => {
                write!(f, "arm file: joint {joint}: axis must be a unit vector")
            }
            ArmError::BadLimits { joint } => write!(
                f,
                "arm file: joint {joint}: min_deg and max_deg must be finite with min_deg <= max_deg"
            ),
            ArmError::NonFinite { field } => write!(f, "arm file: {field} is not a finite number"),
            ArmError::NotAWristChain { joint } => write!(
                f,
                "arm file: joint {joint}: the calibration needs joint 1 about z, joint 2 about x and joints 3-6 about a base axis (x, y or z) at home"
            ),
            ArmError::WorkspaceUnreachable { tries } => write!(
                f,
                "no joint configuration within the limits puts the TCP in the workspace after {tries} draws"
            ),
        }
    }
}

impl std::error::Error for ArmError {}

/// One test point: where the TCP should be and how far off it is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PointError {
    /// Commanded joints 1-6 (deg).
    pub joints_deg: [f64; ARM_JOINTS],
    /// Nominal TCP position (mm).
    pub nominal_mm: [f64; 3],
    /// Actual − nominal before compensation, X Y Z (mm).
    pub before_mm: [f64; 3],
    /// Actual − nominal after compensation, X Y Z (mm).
    pub after_mm: [f64; 3],
}

/// Summary of position errors over the test points.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Default)]
pub struct ErrorStats {
    /// Mean |error| along X, Y, Z (mm).
    pub mean_abs_mm: [f64; 3],
    /// Largest |error| along X, Y, Z (mm).
    pub max_abs_mm: [f64; 3],
    /// Mean distance error (mm).
    pub mean_distance_mm: f64,
    /// Largest distance error (mm).
    pub max_distance_mm: f64,
    /// RMS distance error (mm).
    pub rms_distance_mm: f64,
}

impl ErrorStats {
    /// Statistics of a set of error vectors.
    pub fn of(errors_mm: impl Iterator<Item = [f64; 3]>) -> Self {
        let mut s = ErrorStats::default();
        let mut n = 0usize;
        let mut sum_sq = 0.0;
        for e in errors_mm {
            n += 1;
            for ((mean, max), x) in s.mean_abs_mm.iter_mut().zip(&mut s.max_abs_mm).zip(e) {
                *mean += x.abs();
                *max = max.max(x.abs());
            }
            let d = Vector3::from(e).norm();
            s.mean_distance_mm += d;
            s.max_distance_mm = s.max_distance_mm.max(d);
            sum_sq += d * d;
        }
        if n > 0 {
            let nf = n as f64;
            s.mean_abs_mm = s.mean_abs_mm.map(|x| x / nf);
            s.mean_distance_mm /= nf;
            s.rms_distance_mm = (sum_sq / nf).sqrt();
        }
        s
    }
}

/// The before/after positioning test.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AccuracyReport {
    /// Arm model name.
    pub arm: String,
    /// True Δθ1..Δθ6 (deg).
    pub true_offsets_deg: [f64; ARM_JOINTS],
    /// Identified Δθ1..Δθ6 (deg).
    pub identified_offsets_deg: [f64; ARM_JOINTS],
    /// Every test point, for plotting.
    pub points: Vec<PointError>,
    /// Before compensation.
    pub before: ErrorStats,
    /// After compensation.
    pub after: ErrorStats,
}

impl AccuracyReport {
    /// mean distance before / after.
    pub fn improvement_factor(&self) -> f64 {
        self.before.mean_distance_mm / self.after.mean_distance_mm
    }
}

fn finite3(v: &[f64; 3], field: &'static str) -> Result<(), ArmError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { field })
    }
}

impl Arm6 {
    /// Parses and checks an arm description.
    ///
    /// # Errors
    /// Bad JSON (with line and column), a non-unit axis, bad limits, a non-finite number.
    pub fn from_json(text: &str) -> Result<Self, ArmError> {
        let arm: Arm6 = serde_json::from_str(text).map_err(ArmError::Json)?;
        arm.validate()?;
        Ok(arm)
    }

    /// The built-in KUKA KR 6 R900 sixx.
    ///
    /// # Errors
    /// Only if the built-in file were broken (a test checks it is not).
    pub fn kr6_r900() -> Result<Self, ArmError> {
        Self::from_json(KR6_R900_JSON)
    }

    fn validate(&self) -> Result<(), ArmError> {
        for (i, j) in self.joints.iter().enumerate() {
            finite3(&j.axis, "a joint axis")?;
            finite3(&j.point_mm, "a joint point_mm")?;
            if (Vector3::from(j.axis).norm() - 1.0).abs() > 1e-9 {
                return Err(ArmError::AxisNotUnit { joint: i + 1 });
            }
            if !(j.min_deg.is_finite() && j.max_deg.is_finite() && j.min_deg <= j.max_deg) {
                return Err(ArmError::BadLimits { joint: i + 1 });
            }
        }
        finite3(&self.flange_mm, "flange_mm")?;
        finite3(&self.tool_mm, "tool_mm")?;
        if !(self.workspace.min_z_mm.is_finite() && self.workspace.min_radius_mm.is_finite()) {
            return Err(ArmError::NonFinite { field: "workspace" });
        }
        Ok(())
    }

    /// TCP position (mm) at true joint angles `joints_rad`.
    pub fn tcp_mm(&self, joints_rad: &[f64; ARM_JOINTS]) -> Vector3<f64> {
        let mut p = Vector3::from(self.flange_mm) + Vector3::from(self.tool_mm);
        // e^{ξ1θ1}·…·e^{ξ6θ6}·p: apply joint 6 first.
        for (j, &q) in self.joints.iter().zip(joints_rad).rev() {
            let axis = Unit::new_normalize(Vector3::from(j.axis));
            let c = Vector3::from(j.point_mm);
            p = Rotation3::from_axis_angle(&axis, q) * (p - c) + c;
        }
        p
    }

    /// Flange orientation at true joint angles `joints_rad`.
    pub fn flange_orientation(&self, joints_rad: &[f64; ARM_JOINTS]) -> Rotation3<f64> {
        let mut r = Rotation3::identity();
        for (j, &q) in self.joints.iter().zip(joints_rad) {
            r *= Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(j.axis)), q);
        }
        r
    }

    /// Joints 3-6 as the stage-2 [`WristChain`] (see the module doc for the mapping).
    ///
    /// # Errors
    /// Joint 1 not about z, joint 2 not about ±x, or joints 3-6 not about a base axis.
    pub fn wrist_chain(&self) -> Result<WristChain<f64>, ArmError> {
        let as_axis = |k: usize| -> Option<JointAxis> {
            let a = self.joints[k].axis;
            let names = [
                ([1.0, 0.0, 0.0], JointAxis::X),
                ([0.0, 1.0, 0.0], JointAxis::Y),
                ([0.0, 0.0, 1.0], JointAxis::Z),
            ];
            names.iter().find_map(|(v, ax)| {
                let dot: f64 = v.iter().zip(a).map(|(x, y)| x * y).sum();
                if (dot - 1.0).abs() < 1e-12 {
                    Some(*ax)
                } else if (dot + 1.0).abs() < 1e-12 {
                    Some(ax.negated())
                } else {
                    None
                }
            })
        };
        if as_axis(0) != Some(JointAxis::Z) {
            return Err(ArmError::NotAWristChain { joint: 1 });
        }
        if !matches!(as_axis(1), Some(JointAxis::X | JointAxis::NegX)) {
            return Err(ArmError::NotAWristChain { joint: 2 });
        }
        let mut chain = WristChain::paper();
        for k in 0..WRIST_JOINTS {
            chain.axes[k] = as_axis(k + 2).ok_or(ArmError::NotAWristChain { joint: k + 3 })?;
        }
        Ok(chain)
    }

    /// +1 if positive joint-2 motion increases the upper-arm sensor's x reading
    /// (joint 2 about +x), −1 if about −x.
    pub fn j2_direction(&self) -> i8 {
        if self.joints[1].axis[0] < 0.0 {
            -1
        } else {
            1
        }
    }

    /// `n` seeded random joint configurations within the limits whose TCP lies in the
    /// workspace (above `min_z_mm`, beyond `min_radius_mm` from the joint-1 axis).
    ///
    /// # Errors
    /// The workspace is unreachable within the limits.
    pub fn random_poses(&self, n: usize, seed: u64) -> Result<Vec<[f64; ARM_JOINTS]>, ArmError> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let max_tries = 1000 * n as u64 + 10_000;
        let mut out = Vec::with_capacity(n);
        let mut tries = 0;
        while out.len() < n {
            if tries >= max_tries {
                return Err(ArmError::WorkspaceUnreachable { tries });
            }
            tries += 1;
            let mut q = [0.0; ARM_JOINTS];
            for (qk, j) in q.iter_mut().zip(&self.joints) {
                *qk = if j.max_deg > j.min_deg {
                    rng.gen_range(j.min_deg..j.max_deg).to_radians()
                } else {
                    j.min_deg.to_radians()
                };
            }
            let p = self.tcp_mm(&q);
            if p.z >= self.workspace.min_z_mm && p.x.hypot(p.y) >= self.workspace.min_radius_mm {
                out.push(q);
            }
        }
        Ok(out)
    }
}

/// Δθ1..Δθ6 of the arm from stage 1's Δθ2 and stage 2's Δθ3..Δθ6 (rad); Δθ1 = 0
/// (axis 1 stays at its mark).
pub fn arm_offsets(
    delta_theta2_rad: f64,
    wrist_offsets_rad: &[f64; WRIST_JOINTS],
) -> [f64; ARM_JOINTS] {
    let mut out = [0.0; ARM_JOINTS];
    out[1] = delta_theta2_rad;
    out[2..].copy_from_slice(wrist_offsets_rad);
    out
}

fn add6(a: &[f64; ARM_JOINTS], b: &[f64; ARM_JOINTS], sign: f64) -> [f64; ARM_JOINTS] {
    let mut out = *a;
    for (o, x) in out.iter_mut().zip(b) {
        *o += sign * x;
    }
    out
}

/// The ISO 9283-style test: `n_poses` seeded random reachable poses, TCP position
/// error before compensation (true offsets only) and after entering the identified
/// offsets (residual `true − identified`), per point and summarised.
///
/// Offsets are Δθ1..Δθ6 = true − commanded (rad); Δθ1 is normally 0.
///
/// # Errors
/// The workspace is unreachable within the limits.
pub fn accuracy_test(
    arm: &Arm6,
    true_offsets_rad: &[f64; ARM_JOINTS],
    identified_offsets_rad: &[f64; ARM_JOINTS],
    n_poses: usize,
    seed: u64,
) -> Result<AccuracyReport, ArmError> {
    let residual = add6(true_offsets_rad, identified_offsets_rad, -1.0);
    let points: Vec<PointError> = arm
        .random_poses(n_poses, seed)?
        .iter()
        .map(|q| {
            let nominal = arm.tcp_mm(q);
            let before = arm.tcp_mm(&add6(q, true_offsets_rad, 1.0)) - nominal;
            let after = arm.tcp_mm(&add6(q, &residual, 1.0)) - nominal;
            PointError {
                joints_deg: q.map(f64::to_degrees),
                nominal_mm: nominal.into(),
                before_mm: before.into(),
                after_mm: after.into(),
            }
        })
        .collect();
    Ok(AccuracyReport {
        arm: arm.name.clone(),
        true_offsets_deg: true_offsets_rad.map(f64::to_degrees),
        identified_offsets_deg: identified_offsets_rad.map(f64::to_degrees),
        before: ErrorStats::of(points.iter().map(|p| p.before_mm)),
        after: ErrorStats::of(points.iter().map(|p| p.after_mm)),
        points,
    })
}

impl std::fmt::Display for AccuracyReport {
    /// The table as `zerocal simulate` prints it: offsets (true, identified) per joint,
    /// then the TCP position error before and after compensation per axis and as a
    /// distance (mm).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "positioning test: {}, {} random reachable poses",
            self.arm,
            self.points.len()
        )?;
        writeln!(f, "joint   true_deg   identified_deg   error_deg")?;
        for k in 0..ARM_JOINTS {
            let (t, found) = (self.true_offsets_deg[k], self.identified_offsets_deg[k]);
            writeln!(
                f,
                "j{}    {t:+9.5}   {found:+9.5}        {:+.6}",
                k + 1,
                found - t
            )?;
        }
        writeln!(
            f,
            "TCP error (mm)  mean|X|   mean|Y|   mean|Z|    max|X|    max|Y|    max|Z|  mean_dist  max_dist"
        )?;
        for (name, s) in [("before", &self.before), ("after", &self.after)] {
            writeln!(
                f,
                "{name:<7} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>10.4} {:>9.4}",
                s.mean_abs_mm[0],
                s.mean_abs_mm[1],
                s.mean_abs_mm[2],
                s.max_abs_mm[0],
                s.max_abs_mm[1],
                s.max_abs_mm[2],
                s.mean_distance_mm,
                s.max_distance_mm
            )?;
        }
        writeln!(
            f,
            "mean distance error {:.4} mm -> {:.4} mm (factor {:.0})",
            self.before.mean_distance_mm,
            self.after.mean_distance_mm,
            self.improvement_factor()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::model::BaseTilt;

    fn arm() -> Arm6 {
        Arm6::kr6_r900().unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn home_pose_and_reach_match_the_datasheet() {
        let a = arm();
        let p = a.tcp_mm(&[0.0; 6]);
        assert!((p - Vector3::new(0.0, 625.0, 940.0)).norm() < 1e-9, "{p}");
        // Reach of the wrist centre from the joint-2 axis: forearm straight up along
        // the upper arm (θ3 = +90°): 455 + 420 = 875 mm above joint 2, 35 mm aside.
        let wc = |q: &[f64; 6]| {
            let mut a2 = a.clone();
            a2.tool_mm = [0.0; 3];
            a2.flange_mm = a.joints[4].point_mm;
            a2.tcp_mm(q)
        };
        let up = wc(&[0.0, 0.0, 90f64.to_radians(), 0.0, 0.0, 0.0]);
        assert!(
            (up - Vector3::new(0.0, -10.0, 1275.0)).norm() < 1e-9,
            "{up}"
        );
    }

    #[test]
    fn wrist_orientation_is_the_papers_chain() {
        // With joints 1, 2 at zero the flange orientation equals the stage-2 chain's.
        let a = arm();
        let chain = a.wrist_chain().unwrap_or_else(|e| panic!("{e}"));
        let q = [0.3, -1.2, 2.0, 0.7];
        let r = a.flange_orientation(&[0.0, 0.0, q[0], q[1], q[2], q[3]]);
        let w = chain.orientation(&BaseTilt::level(), &q);
        assert!((r.matrix() - w.matrix()).norm() < 1e-14);
        assert_eq!(a.j2_direction(), 1);
    }

    #[test]
    fn positions_follow_the_joint_axes() {
        // Turning joint 6 about the flange axis moves a TCP 50 mm off that axis on a
        // circle of radius 50 mm; turning joint 1 keeps the height.
        let a = arm();
        let p0 = a.tcp_mm(&[0.0; 6]);
        let p6 = a.tcp_mm(&[0.0, 0.0, 0.0, 0.0, 0.0, std::f64::consts::PI]);
        assert!(((p6 - p0).norm() - 100.0).abs() < 1e-9);
        let p1 = a.tcp_mm(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert!((p1.z - p0.z).abs() < 1e-9 && (p1.xy().norm() - p0.xy().norm()).abs() < 1e-9);
    }

    #[test]
    fn bad_files_are_named() {
        let mut a = arm();
        a.joints[3].axis = [0.0, 2.0, 0.0];
        let text = serde_json::to_string(&a).unwrap_or_default();
        assert!(matches!(
            Arm6::from_json(&text),
            Err(ArmError::AxisNotUnit { joint: 4 })
        ));
        let e = Arm6::from_json("{\"name\": 3}");
        assert!(matches!(e, Err(ArmError::Json(_))));
        let msg = e
            .map(|_| ())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(msg.contains("line 1"), "{msg}");
    }

    #[test]
    fn zero_residual_means_zero_error_after() {
        let a = arm();
        let off = [0.0, 0.01, -0.005, 0.003, 0.002, -0.004];
        let r = accuracy_test(&a, &off, &off, 50, 3).unwrap_or_else(|e| panic!("{e}"));
        assert!(r.after.max_distance_mm < 1e-9);
        assert!(r.before.mean_distance_mm > 1.0);
        assert_eq!(r.points.len(), 50);
    }
}
