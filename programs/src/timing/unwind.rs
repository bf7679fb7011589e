//! Turns that cost nothing: a joint whose limits span more than a turn reaches a pose's
//! angle θ also at θ ± 360°, the same physical pose (the flange, the pendant and every
//! link in the same place), so a session can take whichever of them is nearer the
//! pose before it.
//!
//! Nothing the fit sees changes: the kinematics and the reducers' harmonics are
//! functions of whole output turns, so every reading's prediction and the design's σ
//! are the same (tested to 1e-9 relative in `plan::session_plan`). What changes is the
//! travel: the planner spreads each joint over its turn so that the reducers'
//! harmonics separate from the zero, and on an arm whose wrist turns ±360° (the UR5e,
//! the FANUC and Yaskawa wrists) a pose at −170° after one at +170° is a 20° move
//! instead of 340°.
//!
//! Only the wrist's joints are turned: a shoulder or elbow taken the other way round
//! could sweep the arm through the floor (the limits check poses, not the way between
//! them).
//!
//! What it does not claim: a real reducer whose ratio is not a whole number repeats its
//! motor-side error only over several output turns, and the cables inside a wrist are
//! wound one turn further. Neither is in the fit; both are within the transmission
//! error's higher-order share that the budget carries (docs/real-arm.md).

use super::joint_limits::check_capture_room;
use std::f64::consts::TAU;
use zerocal_core::model::JOINTS;
use zerocal_core::plan::{with_revisits, PoseList};
use zerocal_profile::Profile;

/// The first joint (0-based) turned by whole turns: the wrist's (joints 4-6). The arm's
/// joints 2 and 3 are not: the limits check the poses, not the way between them, and a
/// shoulder or elbow taken the other way round can sweep the arm through the floor or
/// the stand (a UR5e's shoulder through straight down), where a wrist turning the other
/// way sweeps only the pendant and the flange about their own axes.
const FIRST_TURNED: usize = 3;

/// The whole turns tried either way: ±2 covers any limits within ±900°.
const TURNS: [i32; 5] = [0, -1, 1, -2, 2];

/// The distinct poses of a plan (model rad, in session order) with each wrist joint
/// (joints 4-6, [`FIRST_TURNED`]) turned by whole turns where its limits allow (with
/// room for both captures, [`check_capture_room`]), to the angles that make the least
/// travel from `start` (model rad, the pose the robot comes from) through every visit:
/// the poses in order with `revisits` of them visited again (core's [`with_revisits`],
/// which must copy a pose exactly: the refusal rule finds a revisit by its equal
/// joints). A pose that would leave its room with two joints turned together keeps its
/// planned angles.
pub fn unwound(
    profile: &Profile,
    start: &[f64; JOINTS],
    poses: &[[f64; JOINTS]],
    revisits: usize,
) -> Vec<[f64; JOINTS]> {
    let options = turn_options(profile, poses);
    let visits = visit_order(poses.len(), revisits);
    let mut out: Vec<[f64; JOINTS]> = poses.to_vec();
    for joint in FIRST_TURNED..JOINTS {
        let allowed: Vec<Vec<i32>> = options.iter().map(|o| o[joint].clone()).collect();
        let angles: Vec<f64> = poses.iter().map(|q| q[joint]).collect();
        let turns = least_travel(start[joint], &angles, &allowed, &visits);
        for (q, k) in out.iter_mut().zip(turns) {
            q[joint] += f64::from(k) * TAU;
        }
    }
    // Joints turned one at a time each had room; together (a coupled controller's
    // joint 3 sums joints 2 and 3) they may not: such a pose keeps its plan.
    for (q, planned) in out.iter_mut().zip(poses) {
        if !has_room(profile, q) {
            *q = *planned;
        }
    }
    out
}

/// Whether a pose (model rad) has the room both captures need.
fn has_room(profile: &Profile, q: &[f64; JOINTS]) -> bool {
    check_capture_room(profile, &profile.shown_deg(q), "an unwound pose").is_ok()
}

/// The whole turns (of `TURNS`) each joint of each pose (model rad) may take, one
/// joint at a time, keeping the room both captures need: `[pose][joint]`, each holding
/// 0; joints before [`FIRST_TURNED`] only 0.
pub fn turn_options(profile: &Profile, poses: &[[f64; JOINTS]]) -> Vec<[Vec<i32>; JOINTS]> {
    poses
        .iter()
        .map(|q| {
            core::array::from_fn(|joint| {
                TURNS
                    .iter()
                    .copied()
                    .filter(|&k| {
                        let mut t = *q;
                        t[joint] += f64::from(k) * TAU;
                        k == 0 || (joint >= FIRST_TURNED && has_room(profile, &t))
                    })
                    .collect()
            })
        })
        .collect()
}

/// Pose `to` (model rad) with each joint at the one of its allowed whole turns
/// (`options`, from [`turn_options`]) nearest `from`'s angle: the pose as the robot
/// reaches it from `from` the short way round.
pub fn nearest(
    from: &[f64; JOINTS],
    to: &[f64; JOINTS],
    options: &[Vec<i32>; JOINTS],
) -> [f64; JOINTS] {
    core::array::from_fn(|joint| {
        let base = to[joint];
        options[joint]
            .iter()
            .map(|&k| base + f64::from(k) * TAU)
            .fold(base, |best, a| {
                if (a - from[joint]).abs() < (best - from[joint]).abs() {
                    a
                } else {
                    best
                }
            })
    })
}

/// The order the robot visits `n` distinct poses in with `revisits` of them visited
/// again: indices into the distinct poses, as core's [`with_revisits`] places them
/// (applied to poses that carry their own index, so the rule lives in one place).
pub fn visit_order(n: usize, revisits: usize) -> Vec<usize> {
    let mut tagged: PoseList<f64> = PoseList::new();
    for i in 0..n {
        // n ≤ MAX_POSES, so every index is exact in an f64.
        let _ = tagged.push([i as f64; JOINTS]);
    }
    with_revisits(&mut tagged, n, revisits);
    tagged.iter().map(|q| q[0] as usize).collect()
}

/// The whole turns of one joint at each distinct pose (each in `allowed[pose]`, which
/// holds 0) that make the least travel of that joint from `start_rad` through `visits`
/// (indices into `angles_rad`, a pose visited more than once at the same angle every
/// time): a shortest path over the few candidates of each visit, tried for every
/// choice of the revisited poses' turns.
fn least_travel(
    start_rad: f64,
    angles_rad: &[f64],
    allowed: &[Vec<i32>],
    visits: &[usize],
) -> Vec<i32> {
    let n = angles_rad.len();
    let mut repeated: Vec<usize> = Vec::new();
    for (i, &v) in visits.iter().enumerate() {
        if visits[..i].contains(&v) && !repeated.contains(&v) {
            repeated.push(v);
        }
    }
    let options = |p: usize| allowed.get(p).cloned().unwrap_or_else(|| vec![0]);
    // Every choice of the revisited poses' turns (at most MAX_REVISITS poses, a few
    // candidates each).
    let mut fixings: Vec<Vec<(usize, i32)>> = vec![Vec::new()];
    for &p in &repeated {
        fixings = fixings
            .iter()
            .flat_map(|f| {
                options(p).into_iter().map(move |k| {
                    let mut g = f.clone();
                    g.push((p, k));
                    g
                })
            })
            .collect();
    }
    let mut best: (f64, Vec<i32>) = (f64::INFINITY, vec![0; n]);
    for fixing in &fixings {
        let states = |p: usize| match fixing.iter().find(|(q, _)| *q == p) {
            Some(&(_, k)) => vec![k],
            None => options(p),
        };
        // cost[c], path[c]: the least travel to the current visit at its candidate c,
        // and each distinct pose's turns on that way.
        let mut cost: Vec<f64> = Vec::new();
        let mut paths: Vec<Vec<i32>> = Vec::new();
        let mut prev_angles: Vec<f64> = vec![start_rad];
        let mut prev_cost: Vec<f64> = vec![0.0];
        let mut prev_paths: Vec<Vec<i32>> = vec![vec![0; n]];
        for &v in visits {
            let base = angles_rad.get(v).copied().unwrap_or(0.0);
            cost.clear();
            paths.clear();
            let here = states(v);
            let mut here_angles = Vec::with_capacity(here.len());
            for &k in &here {
                let angle = base + f64::from(k) * TAU;
                let (mut c_best, mut from) = (f64::INFINITY, 0usize);
                for (p, (&a, &c)) in prev_angles.iter().zip(&prev_cost).enumerate() {
                    let c = c + (angle - a).abs();
                    if c < c_best {
                        (c_best, from) = (c, p);
                    }
                }
                let mut path = prev_paths.get(from).cloned().unwrap_or_else(|| vec![0; n]);
                if let Some(t) = path.get_mut(v) {
                    *t = k;
                }
                cost.push(c_best);
                paths.push(path);
                here_angles.push(angle);
            }
            prev_angles = here_angles;
            prev_cost = cost.clone();
            prev_paths = paths.clone();
        }
        for (c, path) in prev_cost.iter().zip(prev_paths) {
            if *c < best.0 {
                best = (*c, path);
            }
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(a: &[f64]) -> Vec<f64> {
        a.iter().map(|v| v.to_radians()).collect()
    }

    /// A joint allowed a turn each way goes from +170° to −170° by 20°, not 340°.
    #[test]
    fn a_free_joint_takes_the_near_way_round() {
        let angles = deg(&[170.0, -170.0, 160.0]);
        let allowed = vec![vec![0, -1, 1]; 3];
        let turns = least_travel(170f64.to_radians(), &angles, &allowed, &[0, 1, 2]);
        assert_eq!(turns, vec![0, 1, 0]);
    }

    /// Where no turn is allowed the plan's angles stand.
    #[test]
    fn a_joint_without_room_keeps_its_angles() {
        let angles = deg(&[170.0, -170.0, 160.0]);
        let allowed = vec![vec![0]; 3];
        let turns = least_travel(0.0, &angles, &allowed, &[0, 1, 2]);
        assert_eq!(turns, vec![0, 0, 0]);
    }

    /// A pose visited twice is at one angle both times, chosen for both visits: here
    /// pose 0 at −170° is visited again after pose 1 at +170°, so it is taken at +190°.
    #[test]
    fn a_revisited_pose_takes_one_angle_for_all_its_visits() {
        let angles = deg(&[-170.0, 170.0]);
        let allowed = vec![vec![0, 1], vec![0]];
        let turns = least_travel(170f64.to_radians(), &angles, &allowed, &[0, 1, 0]);
        assert_eq!(turns, vec![1, 0]);
    }

    /// The visit order is core's: the first pose again halfway, the first and the
    /// middle at the end.
    #[test]
    fn visits_follow_cores_revisits() {
        assert_eq!(visit_order(4, 0), vec![0, 1, 2, 3]);
        assert_eq!(visit_order(4, 3), vec![0, 1, 0, 2, 3, 0, 2]);
    }

    /// The UR5e's shoulder could take a whole turn within its ±360° limits, but is
    /// never turned (it could sweep the arm through the floor); its wrist is.
    #[test]
    fn the_shoulder_is_never_turned_the_wrist_is() {
        let Ok(ur) = zerocal_profile::builtin("ur5e") else {
            panic!("ur5e is built in");
        };
        let q0 = ur.stage1_joints_rad;
        let poses: Vec<[f64; JOINTS]> = [170.0, -170.0, 160.0]
            .iter()
            .map(|&a: &f64| {
                let mut q = q0;
                q[1] = a.to_radians();
                q[3] = a.to_radians();
                q
            })
            .collect();
        let out = unwound(&ur, &q0, &poses, 0);
        for (u, p) in out.iter().zip(&poses) {
            assert_eq!(u[..3], p[..3], "joints 1-3");
        }
        assert!(out.iter().zip(&poses).any(|(u, p)| u[3] != p[3]), "{out:?}");
    }

    /// Every built-in profile: the unwound poses are the same physical poses (each
    /// joint moved by whole turns) and each has the room both captures need.
    #[test]
    fn unwound_poses_are_the_plan_by_whole_turns_with_room() {
        for name in zerocal_profile::builtin_names() {
            let Ok(profile) = zerocal_profile::builtin(name) else {
                continue;
            };
            let q0 = profile.stage1_joints_rad;
            let poses: Vec<[f64; JOINTS]> = [-150.0, 150.0, -120.0, 170.0]
                .iter()
                .map(|&a: &f64| {
                    let mut q = q0;
                    q[5] = a.to_radians();
                    q
                })
                .collect();
            let out = unwound(&profile, &q0, &poses, 3);
            for (u, p) in out.iter().zip(&poses) {
                for k in 0..JOINTS {
                    let turns = (u[k] - p[k]) / std::f64::consts::TAU;
                    assert!(
                        (turns - turns.round()).abs() < 1e-12,
                        "{name}: joint {}",
                        k + 1
                    );
                }
                if u != p {
                    assert!(check_capture_room(&profile, &profile.shown_deg(u), "t").is_ok());
                }
            }
        }
    }
}
