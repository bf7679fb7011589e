//! The stage-1 pose with no gravity torque on joints 2 and 3.
//!
//! Stage 1 reads the pendant on the upper arm before and after a half turn of joint 1;
//! joint 2 must stand at the same angle in both captures. A profile states a geometric
//! pose (the "candle": upper arm and the line to the wrist centre vertical), but where
//! the forearm's centre of mass is not on that line (a J3-J4 offset) gravity still
//! loads joints 3 and 2, and joint 2 rests on gravity's side of its play. Here the
//! stated pose is turned into the nearest one where gravity's torque about both joints
//! vanishes, so that neither is pulled to one side.
//!
//! - **Joint 3** turns until the torque about it vanishes: links 3-6 and the pendant
//!   turn about its axis as one body (joints 4-6 held), so the torque is a sinusoid of
//!   its angle with two zeros half a turn apart (centre of mass straight above or
//!   below the axis). The one above, nearest the stated angle within the limits, is
//!   found by bisection on the torque's sign; the one below (the forearm hanging) is
//!   torque-free too but is no candle, and is never taken.
//! - **Joint 2**: with joints 2 and 3 parallel, the torque about joint 2 is link 2's
//!   own plus the weight of everything beyond joint 3 acting at joint 3's axis plus
//!   the torque about joint 3 (which then vanishes): it does not depend on joint 3's
//!   angle. With the upper arm vertical and link 2's centre of mass on the line from
//!   joint 2 to joint 3 (as the uniform mass model has it), both parts vanish at the
//!   stated angle and joint 2 is kept; otherwise it turns to the nearest angle where
//!   they cancel with the weight above joint 2, again by bisection.
//! - **Joints 1, 4, 5, 6** stay as stated: joint 1's half turn does not change the
//!   torques about the horizontal joints 2-3, and joint 3 alone balances links 3-6
//!   whatever the wrist's angles. The wrist joints carry only the wrist and the pendant
//!   and stay on the side they were driven to (stage 1 reads only the upper arm).
//!
//! A J2 gravity balancer (spring or gas cylinder) adds a torque no public source gives;
//! it is not modelled here.

use crate::model::{Arm, JOINTS};
use crate::real::{deg_to_rad, Real};
use crate::stage2::MassModel;
use core::fmt;

/// How far the scan for a sign change of a torque steps (deg). The torque is a
/// sinusoid of the joint's angle whose zeros are 180° apart, so a step well under that
/// brackets the nearest zero on each side.
const SCAN_STEP_DEG: f64 = 5.0;

/// Scan steps on each side at most: 5° steps over more than the widest joint range a
/// profile may state (±720°).
const MAX_SCAN_STEPS: usize = 600;

/// Halvings of a bracket at most: 5° reaches below `f64`'s resolution in about 60.
const MAX_BISECTIONS: usize = 200;

/// A torque at most this fraction of the full-load torque is taken as zero at the
/// stated angle (the joint is then kept as stated): rounding in the torque sum.
const BALANCED_FRACTION: f64 = 1e-12;

/// The masses a profile gives are within ± this share of the real arm's: a stated bound
/// (CAD-derived link masses in robot descriptions carry no stated tolerance; the
/// simulator draws the true masses within it).
pub const MASS_UNCERTAINTY: f64 = 0.3;

/// Whether joint 2 at stage-1 pose `q_rad` rests where the approach left it: its
/// gravity torque, with every link's mass off by [`MASS_UNCERTAINTY`] the way that adds
/// up, stays below [`crate::stage2::transmission::UNLOADED_SHARE`] of the most it could
/// carry. Then the two approaches straddle its play and their mean is its middle; where
/// not, gravity may hold it on one flank in both.
pub fn joint2_unloaded<T: Real>(arm: &Arm<T>, masses: &MassModel<T>, q_rad: &[T; JOINTS]) -> bool {
    let torque = masses.gravity_torques_nm(arm, q_rad)[1].abs();
    let spread = masses.moment_magnitudes_nm(arm, q_rad)[1];
    let most = masses.stretched_torques_nm(arm)[1];
    let worst = torque + T::lit(MASS_UNCERTAINTY) * spread;
    most > T::zero()
        && worst.is_finite()
        && worst < T::lit(crate::stage2::transmission::UNLOADED_SHARE) * most
}

/// Why no stage-1 pose without gravity torque on joints 2 and 3 could be found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage1PoseError {
    /// A stated angle, a limit, a mass or a centre of mass is not finite.
    NotFinite,
    /// The stated angle of this joint (1-based) is outside its limits.
    OutsideLimits {
        /// The joint, 1-6.
        joint: usize,
    },
    /// Joints 2 and 3 are not parallel: the torque about joint 2 then depends on
    /// joint 3's angle and this method does not apply.
    AxesNotParallel,
    /// No angle of this joint (2 or 3) within its limits has the weight it carries
    /// balanced straight above it.
    NoBalanceWithinLimits {
        /// The joint, 2 or 3.
        joint: usize,
    },
}

impl fmt::Display for Stage1PoseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stage1PoseError::NotFinite => {
                write!(f, "a stage-1 angle, a limit or a mass is not finite")
            }
            Stage1PoseError::OutsideLimits { joint } => {
                write!(f, "joint {joint} of the stage-1 pose is outside its limits")
            }
            Stage1PoseError::AxesNotParallel => write!(
                f,
                "joints 2 and 3 are not parallel: no stage-1 pose free of gravity torque is derived for such an arm"
            ),
            Stage1PoseError::NoBalanceWithinLimits { joint } => write!(
                f,
                "no angle of joint {joint} within its limits balances the arm's weight above it (no gravity torque on joints 2 and 3)"
            ),
        }
    }
}

/// The stage-1 pose nearest `stated_rad` (model angles) with no gravity torque about
/// joints 2 and 3: joint 3 turned (and joint 2 only where link 2's own weight loads it
/// at the stated angle), joints 1, 4, 5, 6 as stated, every joint within
/// `limits_rad` (lowest, highest; model angles). See the module's documentation for
/// why joint 2's torque vanishes with joint 3's.
///
/// # Errors
/// A stated pose outside its limits or not finite, joints 2 and 3 not parallel, or
/// no balancing angle within the limits ([`Stage1PoseError`]).
pub fn unloaded_stage1_pose<T: Real>(
    arm: &Arm<T>,
    masses: &MassModel<T>,
    stated_rad: &[T; JOINTS],
    limits_rad: &[(T, T); JOINTS],
) -> Result<[T; JOINTS], Stage1PoseError> {
    let finite = |x: T| x.to_f64().is_finite();
    let masses_finite = masses.link_kg.iter().all(|m| finite(*m))
        && masses
            .com_m
            .iter()
            .flat_map(|c| c.iter())
            .all(|x| finite(*x))
        && finite(masses.pendant_kg)
        && masses.pendant_com_m.iter().all(|x| finite(*x));
    if !(stated_rad.iter().all(|q| finite(*q))
        && limits_rad.iter().all(|(lo, hi)| finite(*lo) && finite(*hi))
        && masses_finite)
    {
        return Err(Stage1PoseError::NotFinite);
    }
    for (k, (q, (lo, hi))) in stated_rad.iter().zip(limits_rad).enumerate() {
        if !(*lo <= *q && *q <= *hi) {
            return Err(Stage1PoseError::OutsideLimits { joint: k + 1 });
        }
    }
    let (frames, _) = arm.frames(stated_rad);
    let axis2 = frames[1].rotation * arm.joints[1].axis.unit::<T>();
    let axis3 = frames[2].rotation * arm.joints[2].axis.unit::<T>();
    if axis2.cross(&axis3).norm() > T::lit(1e-9) {
        return Err(Stage1PoseError::AxesNotParallel);
    }
    // ±1: joint 3's torque counted about joint 2's axis.
    let along = axis2.dot(&axis3);

    let mut pose = *stated_rad;
    let full = masses.full_load_torques_nm(arm, stated_rad);
    let tolerance = |k: usize| full[k] * T::lit(BALANCED_FRACTION);
    // Link 2 and the weight beyond joint 3 acting at its axis: joint 3's angle drops out.
    let shoulder = |q2: T| {
        let mut q = *stated_rad;
        q[1] = q2;
        let tau = masses.gravity_torques_nm(arm, &q);
        tau[1] - along * tau[2]
    };
    pose[1] = nearest_zero(shoulder, stated_rad[1], limits_rad[1], tolerance(1))
        .ok_or(Stage1PoseError::NoBalanceWithinLimits { joint: 2 })?;
    let q2 = pose[1];
    let elbow = |q3: T| {
        let mut q = *stated_rad;
        q[1] = q2;
        q[2] = q3;
        masses.gravity_torques_nm(arm, &q)[2]
    };
    pose[2] = nearest_zero(elbow, stated_rad[2], limits_rad[2], tolerance(2))
        .ok_or(Stage1PoseError::NoBalanceWithinLimits { joint: 3 })?;
    Ok(pose)
}

/// The zero of `torque` nearest `start` within `(lo, hi)` with the weight above the
/// joint: `start` itself where the torque is within `tolerance` there (a stated pose
/// already free of torque is kept, whichever balance it is), else the nearest
/// place where it rises through zero (τ = −dV/dθ rises where the potential energy
/// peaks: the weight straight above), bracketed by 5° steps outward and bisected to the
/// type's resolution. `None`: no such place in the range.
fn nearest_zero<T: Real>(
    torque: impl Fn(T) -> T,
    start: T,
    (lo, hi): (T, T),
    tolerance: T,
) -> Option<T> {
    let at_start = torque(start);
    if at_start.abs() <= tolerance {
        return Some(start);
    }
    let step = deg_to_rad(T::lit(SCAN_STEP_DEG));
    // Each side's last scanned angle and its torque.
    let (mut up, mut down) = ((start, at_start), (start, at_start));
    for _ in 0..MAX_SCAN_STEPS {
        let (up_open, down_open) = (up.0 < hi, down.0 > lo);
        if !(up_open || down_open) {
            return None;
        }
        let mut found: Option<T> = None;
        if up_open {
            let next = (up.0 + step).min(hi);
            let f = torque(next);
            if rises(up.1, f) {
                found = Some(bisect(&torque, up, (next, f)));
            }
            up = (next, f);
        }
        if down_open {
            let next = (down.0 - step).max(lo);
            let f = torque(next);
            if rises(f, down.1) {
                let zero = bisect(&torque, (next, f), down);
                found = Some(match found {
                    Some(z) if (z - start).abs() <= (zero - start).abs() => z,
                    _ => zero,
                });
            }
            down = (next, f);
        }
        if found.is_some() {
            return found;
        }
    }
    None
}

/// Whether a continuous function with these values at the lower and the upper end of
/// an interval rises through zero in it.
fn rises<T: Real>(lower: T, upper: T) -> bool {
    lower <= T::zero() && upper >= T::zero()
}

/// Whether a continuous function with these end values has a zero between them.
fn changes_sign<T: Real>(a: T, b: T) -> bool {
    a == T::zero() || b == T::zero() || (a < T::zero()) != (b < T::zero())
}

/// The zero of `torque` in `[a, b]` (values at the ends of opposite signs, or zero),
/// halved until the midpoint is an end (the type's resolution): the end with the
/// smaller torque.
fn bisect<T: Real>(
    torque: &impl Fn(T) -> T,
    (mut a, mut fa): (T, T),
    (mut b, mut fb): (T, T),
) -> T {
    for _ in 0..MAX_BISECTIONS {
        if fa == T::zero() {
            return a;
        }
        if fb == T::zero() {
            return b;
        }
        let mid = (a + b) * T::lit(0.5);
        if mid == a || mid == b {
            break;
        }
        let fm = torque(mid);
        if changes_sign(fa, fm) {
            (b, fb) = (mid, fm);
        } else {
            (a, fa) = (mid, fm);
        }
    }
    if fa.abs() <= fb.abs() {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{JointAxis, Placement};
    use nalgebra::Vector3;

    /// A planar arm shaped like a large six-axis robot with a J3-J4 offset: joint 2
    /// and 3 about x, the upper arm 0.79 m up, link 3 a 0.25 m offset up, the forearm
    /// 0.835 m along y to the wrist, 0.1 m to joint 6. Upper arm vertical at zero.
    fn offset_arm() -> Arm<f64> {
        let mut arm = Arm::paper();
        let at = |x: f64, y: f64, z: f64, axis| crate::model::Joint {
            origin: Placement {
                translation_m: Vector3::new(x, y, z),
                ..Placement::identity()
            },
            axis,
        };
        arm.joints = [
            at(0.0, 0.0, 0.525, JointAxis::Z),
            at(0.0, 0.15, 0.0, JointAxis::X),
            at(0.0, 0.0, 0.79, JointAxis::X),
            at(0.0, 0.0, 0.25, JointAxis::Y),
            at(0.0, 0.835, 0.0, JointAxis::X),
            at(0.0, 0.1, 0.0, JointAxis::Y),
        ];
        arm
    }

    fn limits_deg(j2: (f64, f64), j3: (f64, f64)) -> [(f64, f64); JOINTS] {
        let mut l = [(-180.0f64, 180.0f64); JOINTS];
        l[1] = j2;
        l[2] = j3;
        l.map(|(a, b)| (a.to_radians(), b.to_radians()))
    }

    /// |τ| about joints 2 and 3 over their full-load torque.
    fn torque_fractions(arm: &Arm<f64>, m: &MassModel<f64>, q: &[f64; JOINTS]) -> [f64; 2] {
        let tau = m.gravity_torques_nm(arm, q);
        let full = m.full_load_torques_nm(arm, q);
        [tau[1].abs() / full[1], tau[2].abs() / full[2]]
    }

    #[test]
    fn gravity_torque_is_minus_the_slope_of_the_potential_energy() {
        // τₖ = −∂V/∂qₖ with V = g·Σ mᵢ·zᵢ: the torques this pose search zeroes are
        // gravity's, whatever the frames' conventions.
        let arm = offset_arm();
        let mut m = MassModel::uniform(&arm);
        m.pendant_kg = 0.25;
        m.pendant_com_m = Vector3::new(0.02, 0.0, 0.05);
        let q = [0.4, -0.3, 0.9, 0.5, -0.7, 1.1];
        let energy = |q: &[f64; JOINTS]| {
            let (frames, flange) = arm.frames(q);
            let mut z = m.pendant_kg * (flange.translation_m + flange.rotation * m.pendant_com_m).z;
            for i in 0..JOINTS {
                z += m.link_kg[i] * (frames[i].translation_m + frames[i].rotation * m.com_m[i]).z;
            }
            9.81 * z
        };
        let tau = m.gravity_torques_nm(&arm, &q);
        let full = m.full_load_torques_nm(&arm, &q);
        let h = 1e-5;
        for k in 0..JOINTS {
            let (mut up, mut down) = (q, q);
            up[k] += h;
            down[k] -= h;
            let slope = (energy(&up) - energy(&down)) / (2.0 * h);
            // Central difference: error ~h²/6 times the third derivative (≤ the full
            // load, ~30 N·m: 5e-10) and V's rounding (~40 J × 1e-16) over 2h (2e-10):
            // 1e-8 N·m covers both.
            assert!(
                (tau[k] + slope).abs() <= 1e-8,
                "joint {}: {} vs {}",
                k + 1,
                tau[k],
                -slope
            );
            assert!(tau[k].abs() <= full[k] + 1e-12, "joint {}", k + 1);
        }
        // Joint 1 is vertical: gravity has no torque about it.
        assert!(tau[0].abs() < 1e-12);
    }

    #[test]
    fn joint_3_turns_the_forearms_centre_of_mass_above_its_axis() {
        let arm = offset_arm();
        let m = MassModel::uniform(&arm);
        let stated = [-1.0, 0.0, 0.0, 0.3, 0.0, 0.0];
        let q = unloaded_stage1_pose(&arm, &m, &stated, &limits_deg((-90.0, 90.0), (-90.0, 90.0)))
            .unwrap_or_else(|e| panic!("{e}"));
        // Uniform masses: link 3 0.25 at (0, 0, 0.125), link 4 0.835 at
        // (0, 0.4175, 0.25), link 5 0.1 at (0, 0.885, 0.25) in joint 3's frame (joint
        // 4's roll keeps link 4's centre on its axis; link 5's turns about y, the
        // forearm, so it stays in the y-z plane). A turn θ about x puts their centre
        // (ȳ, z̄) above the axis where tan θ = ȳ / z̄.
        let y: f64 = 0.835 * 0.4175 + 0.1 * 0.885;
        let z = 0.25 * 0.125 + 0.835 * 0.25 + 0.1 * 0.25;
        let expected = y.atan2(z);
        // Bisection to f64's resolution: 1e-12 rad is a thousand times its error.
        assert!((q[2] - expected).abs() < 1e-12, "{} vs {expected}", q[2]);
        // Joints 1, 2 (upper arm vertical, link 2's centre on it), 4, 5, 6 as stated.
        for k in [0, 1, 3, 4, 5] {
            assert_eq!(q[k], stated[k], "joint {}", k + 1);
        }
        // The stated pose is loaded; the result is not (the 1e-9 of the full load the
        // pose promises).
        assert!(torque_fractions(&arm, &m, &stated)[1] > 0.1);
        for f in torque_fractions(&arm, &m, &q) {
            assert!(f < 1e-9, "{f}");
        }
    }

    #[test]
    fn joint_2_turns_where_link_2s_own_weight_loads_it() {
        let arm = offset_arm();
        let mut m = MassModel::uniform(&arm);
        // Link 2's centre 0.1 m off the line from joint 2 to joint 3.
        m.com_m[1] = Vector3::new(0.0, 0.1, 0.395);
        let stated = [0.0; JOINTS];
        let q = unloaded_stage1_pose(&arm, &m, &stated, &limits_deg((-90.0, 90.0), (-90.0, 90.0)))
            .unwrap_or_else(|e| panic!("{e}"));
        // About x, a turn θ moves y to y·cosθ − z·sinθ: link 2 (mass m₂ at y 0.1,
        // z 0.395) and the rest (mass M at joint 3, z 0.79) balance where
        // tan θ = m₂·0.1 / (m₂·0.395 + M·0.79).
        let m2 = m.link_kg[1];
        let rest: f64 = m.link_kg[2..].iter().sum();
        let expected = (m2 * 0.1).atan2(m2 * 0.395 + rest * 0.79);
        assert!((q[1] - expected).abs() < 1e-12, "{} vs {expected}", q[1]);
        for f in torque_fractions(&arm, &m, &q) {
            assert!(f < 1e-9, "{f}");
        }
    }

    #[test]
    fn a_balanced_pose_is_kept() {
        // The forearm's centre straight above joint 3 already: nothing to turn.
        let arm = offset_arm();
        let m = MassModel::uniform(&arm);
        let limits = limits_deg((-90.0, 90.0), (-90.0, 90.0));
        let once = unloaded_stage1_pose(&arm, &m, &[0.0; JOINTS], &limits)
            .unwrap_or_else(|e| panic!("{e}"));
        let twice =
            unloaded_stage1_pose(&arm, &m, &once, &limits).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(once, twice);
    }

    #[test]
    fn limits_that_exclude_the_balance_are_refused() {
        let arm = offset_arm();
        let m = MassModel::uniform(&arm);
        // The balance is at 58.77° (the test above): joint 3 kept within ±30° cannot
        // reach it.
        let got = unloaded_stage1_pose(
            &arm,
            &m,
            &[0.0; JOINTS],
            &limits_deg((-90.0, 90.0), (-30.0, 30.0)),
        );
        assert_eq!(
            got,
            Err(Stage1PoseError::NoBalanceWithinLimits { joint: 3 })
        );
        // Half a turn away, at −121.23°, the forearm hangs below joint 3: torque-free
        // too, inside these limits, and no stage-1 pose.
        let got = unloaded_stage1_pose(
            &arm,
            &m,
            &[0.0; JOINTS],
            &limits_deg((-90.0, 90.0), (-180.0, 30.0)),
        );
        assert_eq!(
            got,
            Err(Stage1PoseError::NoBalanceWithinLimits { joint: 3 })
        );
        let mut off = m;
        off.com_m[1] = Vector3::new(0.0, 0.1, 0.395);
        let got = unloaded_stage1_pose(
            &arm,
            &off,
            &[0.0; JOINTS],
            &limits_deg((-1.0, 1.0), (-90.0, 90.0)),
        );
        assert_eq!(
            got,
            Err(Stage1PoseError::NoBalanceWithinLimits { joint: 2 })
        );
    }

    #[test]
    fn bad_input_is_refused_by_name() {
        let arm = offset_arm();
        let m = MassModel::uniform(&arm);
        let limits = limits_deg((-90.0, 90.0), (-90.0, 90.0));
        let mut nan = [0.0; JOINTS];
        nan[2] = f64::NAN;
        assert_eq!(
            unloaded_stage1_pose(&arm, &m, &nan, &limits),
            Err(Stage1PoseError::NotFinite)
        );
        let mut outside = [0.0; JOINTS];
        outside[1] = 2.0;
        assert_eq!(
            unloaded_stage1_pose(&arm, &m, &outside, &limits),
            Err(Stage1PoseError::OutsideLimits { joint: 2 })
        );
        let mut skew = arm;
        skew.joints[2].axis = JointAxis::Y;
        assert_eq!(
            unloaded_stage1_pose(&skew, &m, &[0.0; JOINTS], &limits),
            Err(Stage1PoseError::AxesNotParallel)
        );
    }
}
