//! The brackets, the box and stage 0 as a technician would meet them, over 200 sessions
//! per robot on the six family profiles, every source of the error table on:
//!
//! - the design's world: brackets made within ±0.5° (tilt) and calibrated on a level
//!   plate and a sine plate (docs/bracket-calibration.md), seated within the design's
//!   ±0.0015°, their yaws within the design's ±0.05° (two pins), the chip within ±1° in
//!   its box, the bench tilted 0.5° and stage 0's half turn made against the fence
//!   (±0.05°): every joint within 0.005° in at least 95 % of sessions, the budget's
//!   k = 2 covering at least 95 % per joint, no refusal, no capture past mode 4's ±10°;
//! - the same with the yaws within ±0.5°: the same holds (the sine plate measures them);
//! - the same brackets never calibrated: the budget (±0.5° for each) covers at least 95 %
//!   (that the report names each: cli/tests/bracket_report.rs);
//! - stage 0 turned by hand (±1°) instead of at the fence: the budget still covers, no
//!   refusal; the 0.005° aim holds in 94-96.5 % (printed with `--nocapture`; see
//!   docs/method.md, stage 0).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use common::rates;

use zerocal_core::bracket::{BRACKET_YAW_TOLERANCE_DEG, SEAT_REPEATABILITY_DEG};
use zerocal_core::session::JIG_HALF_TURN_TOLERANCE_DEG;
use zerocal_sim::montecarlo::{run, setup, summarise, Method, Summary, DEFAULT_POSES};
use zerocal_sim::world::{BracketKnowledge, WorldConfig};

/// Sessions per robot.
const SESSIONS: usize = 200;

/// The design's world (the module doc).
fn design_world() -> WorldConfig {
    WorldConfig {
        mount_tolerance_deg: 0.5,
        bracket_yaw_deg: BRACKET_YAW_TOLERANCE_DEG,
        seat_repeatability_deg: SEAT_REPEATABILITY_DEG,
        brackets: BracketKnowledge::Calibrated,
        chip_rotation_deg: 1.0,
        bench_tilt_deg: 0.5,
        half_turn_error_deg: JIG_HALF_TURN_TOLERANCE_DEG,
        ..WorldConfig::real()
    }
}

/// Runs `world` on every family profile and checks `accept` on each summary and on the
/// captures' range, and each joint's coverage pooled over the six arms against at least
/// 95 %; prints the table. A share is judged as a binomial count (`common::rates`).
fn run_all(world: &WorldConfig, seed: u64, accept: impl Fn(&str, &Summary)) -> Vec<Summary> {
    let mut summaries = Vec::new();
    println!("robot               refused  worst j2..j6 (deg)                      within 0.005  k=2 covers (least joint)");
    for robot in common::FAMILY_PROFILES {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let out = run(&profile, &plan, world, &fit, SESSIONS, seed);
        let s = summarise(&out, 0.005);
        for o in out.iter().filter_map(|o| o.result.as_ref().err()).take(3) {
            eprintln!("REASON {o}");
        }
        println!(
            "{robot:<19} {:>3}/{SESSIONS}  {}   {:>5.1} %     {:>5.1} %",
            s.refused,
            s.max_deg.map(|x| format!("{x:.4}")).join(" "),
            100.0 * s.all_within,
            100.0 * s.covered.iter().copied().fold(1.0f64, f64::min)
        );
        let past = out.iter().filter(|o| o.outside_range > 0).count();
        assert_eq!(
            past, 0,
            "{robot}: {past} sessions with a capture past 10 deg"
        );
        accept(robot, &s);
        summaries.push(s);
    }
    for (k, (covered, solved)) in rates::pooled_coverage(&summaries).into_iter().enumerate() {
        println!("pooled j{}: k=2 covers {covered}/{solved}", k + 2);
        assert!(
            rates::consistent_with_at_least(covered, solved, 0.95),
            "j{}: pooled k=2 covers {covered}/{solved}",
            k + 2
        );
    }
    summaries
}

/// Every joint within 0.005° in at least 95 % of the sessions of the six arms pooled.
fn pooled_all_within_95(summaries: &[Summary]) {
    let (within, sessions) = rates::pooled_all_within(summaries);
    println!("pooled: every joint within 0.005 deg in {within}/{sessions}");
    assert!(
        rates::consistent_with_at_least(within, sessions, 0.95),
        "pooled within 0.005 deg {within}/{sessions}"
    );
}

#[test]
fn calibrated_brackets_of_the_design_give_every_joint_within_0_005_deg() {
    let summaries = run_all(&design_world(), 2200, |robot, s| {
        assert_eq!(s.refused, 0, "{robot}: refused");
        assert!(rates::all_within_at_least(s, 0.95), "{robot}: {:?}", s);
        assert!(rates::short_joints(s, 0.95).is_empty(), "{robot}: {:?}", s);
    });
    pooled_all_within_95(&summaries);
}

#[test]
fn uncalibrated_brackets_are_covered_by_the_budget() {
    let world = WorldConfig {
        brackets: BracketKnowledge::Uncalibrated,
        ..design_world()
    };
    run_all(&world, 2300, |robot, s| {
        assert_eq!(s.refused, 0, "{robot}: refused");
        assert!(rates::short_joints(s, 0.95).is_empty(), "{robot}: {:?}", s);
    });
}

#[test]
fn at_the_widest_ranges_with_the_fence_every_joint_is_within_0_005_deg() {
    let world = WorldConfig {
        bracket_yaw_deg: 0.5,
        ..design_world()
    };
    let summaries = run_all(&world, 2400, |robot, s| {
        assert_eq!(s.refused, 0, "{robot}: refused");
        assert!(rates::all_within_at_least(s, 0.95), "{robot}: {:?}", s);
        assert!(rates::short_joints(s, 0.95).is_empty(), "{robot}: {:?}", s);
    });
    pooled_all_within_95(&summaries);
}

#[test]
fn with_stage_0_turned_by_hand_the_budget_still_covers() {
    let world = WorldConfig {
        bracket_yaw_deg: 0.5,
        half_turn_error_deg: 1.0,
        ..design_world()
    };
    run_all(&world, 2500, |robot, s| {
        assert_eq!(s.refused, 0, "{robot}: refused");
        assert!(rates::short_joints(s, 0.95).is_empty(), "{robot}: {:?}", s);
    });
}

/// A bench levelled as well as it can be (tilt 0): the readings' circle is lost in
/// their noise and the box's warming between headings, and its centre (the bias) with
/// it. A session is solved and covered, or refused naming the bench and saying to tilt
/// it: 11 of 200 KR 6 sessions were refused with only the advice to turn the pendant,
/// which had been turned.
#[test]
fn a_level_bench_is_solved_or_named() {
    let world = WorldConfig {
        bench_tilt_deg: 0.0,
        ..design_world()
    };
    for robot in common::FAMILY_PROFILES {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let out = run(&profile, &plan, &world, &fit, SESSIONS, 2600);
        for o in &out {
            if let Err(e) = &o.result {
                let text = e.to_string();
                assert!(
                    text.contains("do not show their headings")
                        && text.contains("tilt a level bench"),
                    "{robot} seed {}: {text}",
                    o.seed
                );
            }
        }
        let s = summarise(&out, 0.005);
        println!("{robot:<19} refused (named) {:>3}/{SESSIONS}", s.refused);
        assert!(rates::short_joints(&s, 0.95).is_empty(), "{robot}: {:?}", s);
    }
}
