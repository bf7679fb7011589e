//! A plan's joints turned by whole turns (`zerocal_programs::timing::unwound`, what `zerocal
//! plan` does to shorten the session) are the same physical poses: on every built-in
//! profile, the simulated real arm (every error source on) read at the unwound poses
//! gives the same readings and the same solved offsets as at the planned ones.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_core::model::JOINTS;
use zerocal_core::plan::{with_revisits, without_revisits, PoseList, SESSION_REVISITS};
use zerocal_core::session::solve;
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::world::{RealSession, WorldConfig};

/// The solved offsets agree to this (deg): far below the printed 0.0001°, and far above
/// the rounding of sines of angles one turn larger (~1e-15 rad).
const SAME_DEG: f64 = 1e-9;

/// `plan` (with its revisits) unwound as `zerocal plan` unwinds it.
fn unwound(profile: &zerocal_profile::Profile, plan: &[[f64; JOINTS]]) -> Vec<[f64; JOINTS]> {
    let distinct = without_revisits(plan, SESSION_REVISITS);
    let mut start = profile.stage1_joints_rad;
    start[0] += std::f64::consts::PI;
    let mut poses: PoseList<f64> = PoseList::new();
    for q in zerocal_programs::timing::unwound(profile, &start, &distinct, SESSION_REVISITS) {
        poses.push(q).unwrap();
    }
    let n = poses.len();
    with_revisits(&mut poses, n, SESSION_REVISITS);
    poses.to_vec()
}

#[test]
fn unwound_poses_read_and_solve_as_the_planned_ones_on_every_profile() {
    let world = WorldConfig::real();
    let mut turned_joints = 0usize;
    for name in zerocal_profile::builtin_names() {
        let profile = zerocal_profile::builtin(name).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let turned = unwound(&profile, &plan);
        assert_eq!(turned.len(), plan.len(), "{name}");
        turned_joints += plan
            .iter()
            .zip(&turned)
            .map(|(a, b)| a.iter().zip(b).filter(|(x, y)| x != y).count())
            .sum::<usize>();
        let seed = 5;
        let a = RealSession::simulate(&profile, &plan, &world, seed);
        let b = RealSession::simulate(&profile, &turned, &world, seed);
        let (ra, rb) = (a.readings(&profile, &world), b.readings(&profile, &world));
        let (sa, sb) = (solve(&ra, &fit), solve(&rb, &fit));
        match (sa.result, sb.result) {
            (Ok(x), Ok(y)) => {
                for (k, (p, q)) in x.offsets_rad.iter().zip(&y.offsets_rad).enumerate() {
                    let d = (p - q).to_degrees().abs();
                    assert!(d < SAME_DEG, "{name} j{}: {d:e} deg apart", k + 2);
                }
            }
            (Err(x), Err(y)) => assert_eq!(format!("{x:?}"), format!("{y:?}"), "{name}"),
            (x, y) => panic!("{name}: planned {:?}, unwound {:?}", x.is_ok(), y.is_ok()),
        }
    }
    // Not a vacuous pass: some joints of some profiles were turned.
    assert!(turned_joints > 0, "no joint was turned on any profile");
    println!("{turned_joints} joint angles turned by whole turns over the built-in profiles");
}
