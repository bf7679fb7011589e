//! The room a session needs inside the profile's joint limits: every point inside
//! them, every capture pose with room for the approach from below and the overshoot
//! above, and the planner's limits shrunk by that room.

use super::poses::SessionPoses;
use super::{joint_label, APPROACH_DEG, OVERSHOOT_DEG};
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// Refuses a point (controller degrees) outside the profile's joint limits, naming
/// the joint, its value and the limits (exit status 3).
///
/// # Errors
/// The first joint outside its limits.
pub fn check_limits(
    profile: &Profile,
    point_deg: &[f64; JOINTS],
    what: &str,
) -> Result<(), CliError> {
    let model = profile.model_rad(point_deg);
    if let Some((joint, value, lo, hi)) = profile.outside_limits(&model) {
        return Err(CliError::Refused(format!(
            "{what}: {} at {value:.3} deg (model angle) is outside its limits {lo}..{hi} deg of profile {}; nothing was written",
            joint_label(profile, joint - 1),
            profile.name
        )));
    }
    Ok(())
}

/// Refuses a capture pose without room on both sides of the backlash: the point
/// [`APPROACH_DEG`] below it and the point [`OVERSHOOT_DEG`] above it on every joint
/// must be inside the limits, or that pose cannot be captured from both sides.
///
/// # Errors
/// The first such pose, naming the side, the joint, its value and the limits.
pub fn check_room(profile: &Profile, poses: &SessionPoses) -> Result<(), CliError> {
    for (what, q) in poses.capture_poses() {
        check_capture_room(profile, &q, &what)?;
    }
    Ok(())
}

/// [`check_room`] for one capture pose (controller degrees): the pose, the point
/// [`APPROACH_DEG`] below it and the point [`OVERSHOOT_DEG`] above it on every joint.
///
/// # Errors
/// The first point outside the limits, named as in [`check_room`].
pub fn check_capture_room(
    profile: &Profile,
    pose_deg: &[f64; JOINTS],
    what: &str,
) -> Result<(), CliError> {
    check_limits(profile, pose_deg, what)?;
    for (side, d) in [("below", -APPROACH_DEG), ("above", OVERSHOOT_DEG)] {
        let p = pose_deg.map(|v| v + d);
        check_limits(
            profile,
            &p,
            &format!(
                "{what} cannot be captured from {side} (every pose is captured from both sides of the backlash, reached from {} deg {side} on every joint)",
                d.abs()
            ),
        )?;
    }
    Ok(())
}

/// The limits (model degrees) of joint `joint` (0-based) the planner keeps its poses
/// inside: `limits_deg` less the room the two captures of a pose need, the model angles
/// the approach from [`APPROACH_DEG`] below and the overshoot to [`OVERSHOOT_DEG`]
/// above (controller degrees, on every joint) reach through the profile's signs and
/// coupling. So every planned pose passes [`check_room`] on the joints the plan moves
/// (joint 1 stands at the stage-1 pose, which the planner does not choose).
pub fn planner_limit(profile: &Profile, joint: usize, limits_deg: (f64, f64)) -> (f64, f64) {
    let origin = profile.model_rad(&[0.0; JOINTS]);
    let (mut below, mut above) = (0.0f64, 0.0f64);
    for d in [-APPROACH_DEG, OVERSHOOT_DEG] {
        let m = profile.model_rad(&[d; JOINTS]);
        let change = (m[joint] - origin[joint]).to_degrees();
        above = above.max(change);
        below = below.max(-change);
    }
    (limits_deg.0 + below, limits_deg.1 - above)
}

/// [`planner_limit`] for joints 3-6.
pub fn planner_limits(
    profile: &Profile,
    limits_deg: &[(f64, f64); WRIST_JOINTS],
) -> [(f64, f64); WRIST_JOINTS] {
    let origin = profile.model_rad(&[0.0; JOINTS]);
    let mut below = [0.0f64; WRIST_JOINTS];
    let mut above = [0.0f64; WRIST_JOINTS];
    for d in [-APPROACH_DEG, OVERSHOOT_DEG] {
        let m = profile.model_rad(&[d; JOINTS]);
        for k in 0..WRIST_JOINTS {
            let change = (m[k + 2] - origin[k + 2]).to_degrees();
            above[k] = above[k].max(change);
            below[k] = below[k].max(-change);
        }
    }
    core::array::from_fn(|k| (limits_deg[k].0 + below[k], limits_deg[k].1 - above[k]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The planner's limits leave the approach's and the overshoot's room, through the
    /// controller's signs and coupling: a pose at a shrunk limit has its two points at
    /// the profile's limit at most.
    #[test]
    fn planner_limits_leave_room_for_both_sides() {
        for name in ["kuka-kr16", "fanuc-m20ia", "abb-irb140"] {
            let profile = zerocal_profile::builtin(name).unwrap_or_else(|e| panic!("{e}"));
            let full: [(f64, f64); WRIST_JOINTS] = core::array::from_fn(|k| {
                (profile.joints[k + 2].min_deg, profile.joints[k + 2].max_deg)
            });
            let shrunk = planner_limits(&profile, &full);
            for k in 0..WRIST_JOINTS {
                // At least the approach and the overshoot, at most twice (J2/J3 coupled).
                let (lo, hi) = (shrunk[k].0 - full[k].0, full[k].1 - shrunk[k].1);
                assert!(
                    (APPROACH_DEG - 1e-9..=2.0 * OVERSHOOT_DEG + 1e-9).contains(&lo)
                        && (APPROACH_DEG - 1e-9..=2.0 * OVERSHOOT_DEG + 1e-9).contains(&hi),
                    "{name} j{}: {lo} {hi}",
                    k + 3
                );
            }
            // Every corner of the shrunk box, at the stage-1 joints 1-2, has room.
            for corner in 0..16u32 {
                let mut q = profile.stage1_joints_rad;
                for k in 0..WRIST_JOINTS {
                    let (lo, hi) = shrunk[k];
                    q[k + 2] = if corner >> k & 1 == 1 { hi } else { lo }.to_radians();
                }
                let shown = profile.shown_deg(&q);
                for d in [-APPROACH_DEG, OVERSHOOT_DEG] {
                    let m = profile.model_rad(&shown.map(|v| v + d));
                    for (k, (q, j)) in m.iter().zip(&profile.joints).enumerate().skip(2) {
                        let v = q.to_degrees();
                        assert!(
                            v >= j.min_deg - 1e-9 && v <= j.max_deg + 1e-9,
                            "{name} corner {corner} j{}: {v}",
                            k + 1
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn a_pose_without_room_on_one_side_is_refused() {
        let profile = zerocal_profile::builtin("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        let mut poses = SessionPoses::new(&profile, &[profile.stage1_joints_rad]);
        assert!(check_room(&profile, &poses).is_ok());
        // A5 at -129.5: 1 deg below it is past the -130 limit.
        poses.poses[0][4] = -129.5;
        let e = check_room(&profile, &poses).unwrap_err();
        assert_eq!(e.exit_code(), 3);
        let m = e.to_string();
        assert!(
            m.contains("stage-2 pose 1")
                && m.contains("from below")
                && m.contains("A5 (joint 5)")
                && m.contains("-130..130"),
            "{m}"
        );
        // At 127 the overshoot reaches 131.
        poses.poses[0][4] = 127.0;
        let m = check_room(&profile, &poses).unwrap_err().to_string();
        assert!(m.contains("from above") && m.contains("131.000"), "{m}");
        // Outside the limits itself: named with its own value.
        poses.poses[0][4] = 131.5;
        let m = check_room(&profile, &poses).unwrap_err().to_string();
        assert!(
            m.starts_with("refused: stage-2 pose 1: A5") && m.contains("131.500"),
            "{m}"
        );
    }
}
