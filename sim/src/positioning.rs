//! The paper's laser-tracker test in simulation: TCP (flange) position error of a whole
//! arm at random reachable poses, before and after entering the zero offsets a session
//! identified. The arm is a robot profile's kinematics (`zerocal_profile`), lengths
//! included.

use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use zerocal_core::model::{Arm, JOINTS};

/// Joints of the arm.
pub const ARM_JOINTS: usize = JOINTS;

/// Test points must have the flange this far above the base frame's origin (m) and
/// this far from joint 1's axis: a robot's usable workspace, not its own base.
pub const MIN_Z_M: f64 = 0.1;
/// See [`MIN_Z_M`] (m).
pub const MIN_RADIUS_M: f64 = 0.2;

/// Why no test could be run.
#[derive(Clone, Debug, PartialEq)]
pub enum ArmError {
    /// Too few random poses in the limits reach the workspace.
    WorkspaceUnreachable {
        /// Draws tried.
        tries: u64,
    },
    /// The arm has no lengths (the paper's wrist): no positions to test.
    NoLengths,
    /// Zero test poses were asked for: no mean to take.
    NoPoses,
    /// An input is NaN or infinite.
    NotFinite {
        /// Which (`the tool length`).
        what: String,
    },
    /// The profile lists fewer than six joints.
    MissingJoint {
        /// The joint (1-6).
        joint: usize,
    },
    /// The search for the best zero correction ([`crate::tcp`]) did not settle.
    BestNotConverged {
        /// Iterations taken.
        iterations: usize,
    },
}

impl std::fmt::Display for ArmError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ArmError::WorkspaceUnreachable { tries } => write!(
                f,
                "no reachable test poses within the joint limits after {tries} draws"
            ),
            ArmError::NoLengths => {
                f.write_str("the robot's profile has no link lengths: no positioning test on it")
            }
            ArmError::NoPoses => f.write_str("zero test poses asked for: at least one is needed"),
            ArmError::NotFinite { what } => write!(f, "{what} is not a finite number"),
            ArmError::MissingJoint { joint } => {
                write!(
                    f,
                    "the robot's profile has no joint {joint}: six are needed"
                )
            }
            ArmError::BestNotConverged { iterations } => write!(
                f,
                "the best zero correction did not converge in {iterations} iterations"
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

/// The flange's position (mm) at joint angles `q_rad` (true angles).
pub fn tcp_mm(arm: &Arm<f64>, q_rad: &[f64; ARM_JOINTS]) -> Vector3<f64> {
    arm.frames(q_rad).1.translation_m * 1000.0
}

/// `n` seeded random joint configurations within `limits_deg` whose flange lies in the
/// workspace ([`MIN_Z_M`], [`MIN_RADIUS_M`]).
///
/// # Errors
/// The workspace is unreachable within the limits, or the arm has no lengths.
pub fn random_poses(
    arm: &Arm<f64>,
    limits_deg: &[(f64, f64); ARM_JOINTS],
    n: usize,
    seed: u64,
) -> Result<Vec<[f64; ARM_JOINTS]>, ArmError> {
    if tcp_mm(arm, &[0.0; ARM_JOINTS]).norm() == 0.0 {
        return Err(ArmError::NoLengths);
    }
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
        for (qk, &(lo, hi)) in q.iter_mut().zip(limits_deg) {
            *qk = if hi > lo {
                rng.gen_range(lo..hi).to_radians()
            } else {
                lo.to_radians()
            };
        }
        let p = tcp_mm(arm, &q) / 1000.0;
        if p.z >= MIN_Z_M && p.x.hypot(p.y) >= MIN_RADIUS_M {
            out.push(q);
        }
    }
    Ok(out)
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
/// The workspace is unreachable within the limits, or the arm has no lengths.
pub fn accuracy_test(
    name: &str,
    arm: &Arm<f64>,
    limits_deg: &[(f64, f64); ARM_JOINTS],
    true_offsets_rad: &[f64; ARM_JOINTS],
    identified_offsets_rad: &[f64; ARM_JOINTS],
    n_poses: usize,
    seed: u64,
) -> Result<AccuracyReport, ArmError> {
    let residual = add6(true_offsets_rad, identified_offsets_rad, -1.0);
    let points: Vec<PointError> = random_poses(arm, limits_deg, n_poses, seed)?
        .iter()
        .map(|q| {
            let nominal = tcp_mm(arm, q);
            let before = tcp_mm(arm, &add6(q, true_offsets_rad, 1.0)) - nominal;
            let after = tcp_mm(arm, &add6(q, &residual, 1.0)) - nominal;
            PointError {
                joints_deg: q.map(f64::to_degrees),
                nominal_mm: nominal.into(),
                before_mm: before.into(),
                after_mm: after.into(),
            }
        })
        .collect();
    Ok(AccuracyReport {
        arm: name.to_owned(),
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

    fn kr6() -> (Arm<f64>, [(f64, f64); ARM_JOINTS]) {
        let p = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap_or_else(|e| panic!("{e}"));
        let limits = core::array::from_fn(|k| (p.joints[k].min_deg, p.joints[k].max_deg));
        (p.arm, limits)
    }

    #[test]
    fn the_flange_sits_where_the_urdf_puts_it() {
        let (arm, _) = kr6();
        // All zero: 0.025 + 0.455 + 0.420 + 0.080 m forward, 0.400 + 0.035 m up (the
        // profile's joint origins, S1); rounding only.
        let p = tcp_mm(&arm, &[0.0; ARM_JOINTS]);
        assert!((p - Vector3::new(980.0, 0.0, 435.0)).norm() < 1e-9, "{p}");
        // Joint 1 turns about the vertical: the height stays.
        let q1 = tcp_mm(&arm, &[1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert!((q1.z - p.z).abs() < 1e-9 && (q1.xy().norm() - p.xy().norm()).abs() < 1e-9);
    }

    #[test]
    fn zero_residual_means_zero_error_after() {
        let (arm, limits) = kr6();
        let off = [0.0, 0.01, -0.005, 0.003, 0.002, -0.004];
        let r = accuracy_test("kr6", &arm, &limits, &off, &off, 50, 3)
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(r.after.max_distance_mm < 1e-9);
        assert!(r.before.mean_distance_mm > 1.0);
        assert_eq!(r.points.len(), 50);
    }

    #[test]
    fn the_papers_wrist_has_no_positions() {
        let arm = Arm::<f64>::paper();
        let limits = [(-180.0, 180.0); ARM_JOINTS];
        assert_eq!(random_poses(&arm, &limits, 3, 1), Err(ArmError::NoLengths));
    }
}
