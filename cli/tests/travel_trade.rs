//! `zerocal plan` gives a little information for travel only where a session would run
//! over its robot-time aim (`zerocal_programs::plan::travel_trade`), and never more than its
//! tolerance: on every built-in profile, a plan within the aim keeps the planner's poses;
//! a traded plan is shorter than the planner's, swapped no more poses than it says,
//! predicts every joint's k = 2 within the tolerance of the planner's, and leaves every
//! capture room inside the joint limits (`zerocal program` takes it).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{plan, Candidate, ROBOT_TIME_AIM_S};
use zerocal_core::stage2::covariance_bound;
use zerocal_programs::plan::{make_plan, PlanArgs};
use zerocal_programs::timing::{session_time, Pendant};

/// The most a joint's predicted k = 2 may grow for travel (docs/planning.md): 2 %, a
/// fifth of the capture noise on the largest k = 2. Stated here, not read back from
/// the output, so that a looser tolerance fails this test.
const TOLERANCE: f64 = 0.02;

/// `zerocal plan`'s flags, parsed as the command line parses them.
fn plan_args(flags: &[&str]) -> PlanArgs {
    PlanArgs::from_flags(flags).unwrap_or_else(|e| panic!("{e}"))
}

/// `a` and `b` (model rad) are the same pose up to whole turns of a joint.
fn same_pose(a: &[f64; JOINTS], b: &[f64; JOINTS]) -> bool {
    a.iter().zip(b).all(|(x, y)| {
        let d = (x - y) / std::f64::consts::TAU;
        (d - d.round()).abs() < 1e-9
    })
}

#[test]
fn only_a_plan_over_the_aim_gives_information_and_never_beyond_its_tolerance() {
    let mut traded = Vec::new();
    for name in zerocal_profile::builtin_names() {
        let args = plan_args(&["--robot", name]);
        let profile = args.profile().unwrap();
        let sp = make_plan(&args).unwrap();
        // The planner's own poses, as `zerocal plan` starts from them.
        let mut pool = vec![Candidate::default(); args.candidates];
        let planned = plan(
            &args.model(&profile),
            &args.config(&profile).unwrap(),
            &mut pool,
        )
        .unwrap()
        .distinct_poses();
        let session = sp.plan.distinct_poses();
        assert_eq!(session.len(), planned.len(), "{name}");
        let swapped = session
            .iter()
            .filter(|q| !planned.iter().any(|p| same_pose(p, q)))
            .count();
        assert!(
            sp.program_refused.is_none(),
            "{name}: {:?}",
            sp.program_refused
        );
        // What is printed is of the poses printed: their bound, conditioning, largest
        // reading and robot time, computed afresh.
        let model = args.model(&profile);
        let bound = covariance_bound(
            &model,
            sp.plan.extras,
            &session,
            &[0.0; WRIST_JOINTS],
            args.config(&profile).unwrap().noise_sigma_rad,
        )
        .unwrap();
        let same = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs());
        assert!(
            same(bound.condition_number, sp.plan.condition_number),
            "{name}"
        );
        for (a, b) in bound.sigma_rad.iter().zip(&sp.plan.predicted_sigma_rad) {
            assert!(same(*a, *b), "{name}: sigma {a} printed {b}");
        }
        let largest = session.iter().fold(0.0f64, |m, q| {
            let t = model.predict(q, &[0.0; WRIST_JOINTS]);
            m.max(t.x_rad.abs()).max(t.y_rad.abs())
        });
        assert!(
            same(largest, sp.plan.max_reading_rad),
            "{name}: largest reading"
        );
        let time = session_time(&Pendant::new(&profile), &sp.timing.model, &sp.poses);
        assert!(same(time.total_s, sp.time.total_s), "{name}: robot time");
        match sp.trade {
            None => assert_eq!(swapped, 0, "{name}: poses changed without a trade"),
            Some(t) => {
                traded.push(name);
                assert!(
                    t.before_s > ROBOT_TIME_AIM_S,
                    "{name}: traded within the aim"
                );
                assert!(sp.time.total_s < t.before_s, "{name}: no shorter");
                assert_eq!(t.tolerance, TOLERANCE, "{name}");
                assert!(
                    (1..=t.swaps).contains(&swapped),
                    "{name}: {swapped} poses differ, {} swaps said",
                    t.swaps
                );
                for (k, (now, before)) in sp.k2_deg.iter().zip(&t.k2_before_deg).enumerate() {
                    assert!(
                        *now <= before * (1.0 + TOLERANCE) * (1.0 + 1e-12),
                        "{name} j{}: k=2 {now} deg against {before} before",
                        k + 2
                    );
                }
            }
        }
    }
    // The UR5e is over the aim as planned (docs/planning.md): a test that traded
    // nothing anywhere would test nothing.
    assert!(traded.contains(&"ur5e"), "traded: {traded:?}");
}
