//! The order of the stage-2 poses that makes the session short, and the robot time of
//! a session in a given order.

use super::capture_rule::Pendant;
use super::poses::SessionPoses;
use crate::robot_time::{shortest_tour_visiting, CheckPath, Mounting, SessionTime, TimeModel};
use zerocal_core::model::JOINTS;

/// Penalty (s) in the tour's costs for a move that could be captured early: high
/// enough that the tour avoids it whenever an order exists that does.
const EARLY_PENALTY_S: f64 = 1e6;

/// The order of the stage-2 poses that makes the session short (core's
/// [`shortest_tour_visiting`] on the robot times from one pose's second capture to the next
/// pose's first, an operator's OK where that does not arm the next capture, and moves
/// that could be captured early avoided): indices into `poses.poses`. `reach(i, j)` is
/// pose `j` (controller degrees) as the robot reaches it from pose `i` (the same pose,
/// or the same turned by whole turns of a joint whose limits allow it,
/// [`super::unwind`]). The tour is costed with `revisits` of its poses visited again
/// where core's `with_revisits` will place them, so it puts the revisited poses where
/// going back costs least.
pub fn time_order(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
    revisits: usize,
    reach: impl Fn(usize, usize) -> [f64; JOINTS],
) -> Vec<usize> {
    let n = poses.poses.len();
    let leg = |a: &[f64; JOINTS], b: &[f64; JOINTS]| {
        let path = time.first_capture_path(a, b);
        let check = pendant.leg(time, Mounting::Flange, &path);
        let mut c = time.path_s(&path);
        if !check.armed {
            c += time.operator_ok_s;
        }
        if check.early_still {
            c += EARLY_PENALTY_S;
        }
        c
    };
    // The robot comes from stage 1's turned pose (through the flange's mounting pose,
    // a turn of one joint away from the first pose, about the same for any).
    let start: Vec<f64> = poses
        .poses
        .iter()
        .map(|q| time.path_s(&time.first_capture_path(&poses.turned, q)))
        .collect();
    let cost: Vec<Vec<f64>> = poses
        .poses
        .iter()
        .enumerate()
        .map(|(i, a)| (0..n).map(|j| leg(a, &reach(i, j))).collect())
        .collect();
    shortest_tour_visiting(
        n,
        &super::unwind::visit_order(n, revisits),
        |i| start.get(i).copied().unwrap_or(0.0),
        |i, j| cost.get(i).and_then(|r| r.get(j)).copied().unwrap_or(0.0),
    )
    .iter()
    .map(|&i| usize::from(i))
    .collect()
}

/// The robot time of a session in the given order.
pub fn session_time(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
) -> SessionTime<f64> {
    time.session_time(&poses.path(), |m, p| !pendant.leg(time, m, p).armed)
}

/// The robot time of a check on `poses` (its `poses` the check's, in order): from the
/// flange's mounting pose on, no stage 1.
pub fn check_time(
    pendant: &Pendant<'_>,
    time: &TimeModel<f64>,
    poses: &SessionPoses,
) -> SessionTime<f64> {
    let path = CheckPath {
        mount: poses.mount2,
        poses: &poses.poses,
        park: poses.park,
    };
    time.check_time(&path, |m, p| !pendant.leg(time, m, p).armed)
}
