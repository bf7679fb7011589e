//! `zerocal program --check`: the check's robot time on every built-in profile, and its
//! programs read back: the flange's stop, the check's poses (the session plan's, at its
//! commanded angles) each captured twice, the closing bench readings; no stage 1.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use zerocal_core::model::JOINTS;
use zerocal_core::plan::CHECK_POSES;
use zerocal_profile::Profile;
use zerocal_programs::program::{build_check, check_indices, default_plan, Format};
use zerocal_programs::robot_time::CAPTURES_PER_POSE;
use zerocal_programs::timing::{
    check_time, Pendant, SessionPoses, Timing, TimingArgs, CHECK_RUN_LIMIT_S,
};

/// The session plan a program is written for: `zerocal plan`'s default, or for a
/// profile the planner refuses (the UR5e) the seeded window poses the session's
/// golden program uses.
fn session_plan(name: &str, profile: &Profile) -> Vec<[f64; JOINTS]> {
    default_plan(name).unwrap_or_else(|_| common::window_poses(profile, 8, 7))
}

/// Every built-in profile's check, at the default speed, runs its program (moves,
/// dwells, OKs) within [`CHECK_RUN_LIMIT_S`]; the two mountings come on top.
#[test]
fn every_builtin_check_runs_within_three_minutes() {
    for name in zerocal_profile::builtin_names() {
        let profile = zerocal_profile::builtin(name).unwrap();
        let plan = session_plan(name, &profile);
        let index = check_indices(&profile, &plan).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(index.len(), CHECK_POSES.min(plan.len()), "{name}");
        let chosen: Vec<[f64; JOINTS]> = index.iter().map(|&i| plan[i]).collect();
        let poses = SessionPoses::new(&profile, &chosen)
            .with_mounts(&profile)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let t = Timing::new(&profile, &TimingArgs::default()).unwrap();
        let time = check_time(&Pendant::new(&profile), &t.model, &poses);
        let run_s = time.total_s - time.remount_s;
        println!("{name:<20} check run {run_s:.0} s (limit {CHECK_RUN_LIMIT_S:.0} s)");
        assert!(run_s <= CHECK_RUN_LIMIT_S, "{name}: {run_s:.0} s");
        // No stage 1: the pendant clipped to the flange and taken off it, two captures
        // a pose on the robot; the closing bench readings follow with the robot free.
        assert_eq!(time.mountings, 2, "{name}");
        assert_eq!(
            usize::from(time.captures),
            CAPTURES_PER_POSE * index.len(),
            "{name}"
        );
        assert!(time.closing_s > 0.0, "{name}");
    }
}

/// The check's program on the KR 16 holds the session plan's commanded angles at the
/// check's poses, each captured twice (both approaches), three stops (the flange, an
/// OK where needed excepted, the closing bench readings) and no stage-1 pose.
#[test]
fn the_check_program_drives_the_plans_own_angles_without_stage_1() {
    let profile = zerocal_profile::builtin("kuka-kr16").unwrap();
    let plan = session_plan("kuka-kr16", &profile);
    let check = build_check(
        profile.clone(),
        &plan,
        Format::Krl,
        "ZC_CHECK".into(),
        &TimingArgs::default(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let index = check_indices(&profile, &plan).unwrap();
    let moves = check.moves();
    let captured: Vec<[f64; JOINTS]> = moves
        .iter()
        .filter(|m| m.dwell_s.is_some())
        .map(|m| m.joints_deg)
        .collect();
    assert_eq!(captured.len(), CAPTURES_PER_POSE * index.len());
    for (k, &i) in index.iter().enumerate() {
        let want = profile.shown_deg(&plan[i]);
        for c in &captured[CAPTURES_PER_POSE * k..CAPTURES_PER_POSE * (k + 1)] {
            for j in 0..JOINTS {
                // The same number the session's program writes: no rounding between.
                assert_eq!(c[j], want[j], "pose {i} joint {}", j + 1);
            }
        }
    }
    let stage1 = profile.shown_deg(&profile.stage1_joints_rad);
    assert!(captured.iter().all(|q| *q != stage1));
    let stops: Vec<&str> = moves.iter().filter_map(|m| m.stop.as_deref()).collect();
    assert!(stops.first().unwrap().contains("flange"), "{stops:?}");
    assert!(
        stops.last().unwrap().contains("closing bench readings"),
        "{stops:?}"
    );
    assert!(!stops.iter().any(|s| s.contains("upper arm")), "{stops:?}");
}
