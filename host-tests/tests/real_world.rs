//! Whole sessions in the real world: a production SCL3300 unit drawn from
//! the datasheet's ranges and a robot that sags, has backlash and repeats only to
//! 0.0015° per joint, the box warming 3 K; 200 sessions per robot on the paper's wrist
//! and three published arms, each planned and solved as the pendant does. And the
//! sessions that must be refused: a box that warmed far beyond the stated 3 K, a loose
//! bracket, poses outside the sensor's mode.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use common::rates;
use zerocal_core::session::{solve, SessionError, SessionReadings};
use zerocal_core::FitError;
use zerocal_profile::Profile;
use zerocal_sim::montecarlo::{run, setup, summarise, Method, DEFAULT_POSES};
use zerocal_sim::world::{RealSession, WorldConfig};

/// The target per joint (deg): the accuracy goal of docs/error-budget.md.
const TARGET_DEG: f64 = 0.005;

/// The session as the pendant recorded it, with or without the closing reversal.
fn readings<'a>(profile: &Profile, s: &'a RealSession, closing: bool) -> SessionReadings<'a, f64> {
    let world = WorldConfig {
        closing_reversal: closing,
        ..WorldConfig::real()
    };
    s.readings(profile, &world)
}

#[test]
fn every_error_source_on_200_sessions_per_robot() {
    let sessions = 200;
    println!("robot                 within {TARGET_DEG} deg (j2..j6, % of sessions)          k=2 covers the error (%)               mean U(k=2) deg");
    for robot in ["paper-wrist", "kuka-kr6-r900-sixx", "abb-irb140", "puma560"] {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let world = WorldConfig::real();
        let out = run(&profile, &plan, &world, &fit, sessions, 15);
        let outside: usize = out.iter().map(|o| o.outside_range).sum();
        let worst_residual = out
            .iter()
            .filter_map(|o| o.result.as_ref().ok())
            .map(|r| r.fit.residual_rms_rad.to_degrees())
            .fold(0.0f64, f64::max);
        let s = summarise(&out, TARGET_DEG);
        let pct = |v: [f64; 5]| v.map(|x| format!("{:5.1}", x * 100.0)).join(" ");
        let deg = |v: [f64; 5]| v.map(|x| format!("{x:.4}")).join(" ");
        println!(
            "{robot:<21} {}   {}   {}   (worst {}; residual RMS at most {worst_residual:.4})",
            pct(s.within),
            pct(s.covered),
            deg(s.mean_k2_deg),
            deg(s.max_deg)
        );
        // The plan keeps every capture inside mode 4's ±10°, whatever the unit's offset.
        assert_eq!(outside, 0, "{robot}: captures outside the sensor's range");
        assert_eq!(s.refused, 0, "{robot}: sessions refused");
        // The goal: each joint within 0.005° in at least 95 % of sessions, and the k = 2
        // budget covering the actual error in at least 95 %, each judged as a binomial
        // count of 200 sessions (`common::rates`; the figures measured are 99.5-100 %).
        for k in 0..5 {
            let within = rates::count_of(s.within[k], s.sessions);
            assert!(
                rates::consistent_with_at_least(within, s.sessions, 0.95),
                "{robot} j{}: {:?}",
                k + 2,
                s.within
            );
        }
        assert!(
            rates::short_joints(&s, 0.95).is_empty(),
            "{robot}: {:?}",
            s.covered
        );
    }
}

/// A box that warms far beyond the stated 3 K: refused with a named reason, with the
/// closing reversal (beyond the linear drift's 10 K) and without it (beyond 0.5 K).
#[test]
fn a_warm_box_is_refused() {
    let profile = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    let world = WorldConfig {
        warming_k: 25.0,
        ..WorldConfig::real()
    };
    let s = RealSession::simulate(&profile, &plan, &world, 3);
    for closing in [true, false] {
        let e = solve(&readings(&profile, &s, closing), &fit)
            .result
            .unwrap_err();
        match e {
            SessionError::Warmed { drift_measured, .. } => assert_eq!(drift_measured, closing),
            other => panic!("{other}"),
        }
        let msg = e.to_string();
        assert!(msg.starts_with("warm box:"), "{msg}");
    }
    // The stated 3 K with the closing reversal is solved.
    let s = RealSession::simulate(&profile, &plan, &WorldConfig::real(), 3);
    assert!(solve(&readings(&profile, &s, true), &fit).result.is_ok());
}

/// A flange bracket that seats anew within ±0.1° at every capture: the two captures
/// of a pose give it away (0.097° RMS apart, against at most 0.032° on a tight bracket
/// of the FANUC as measured).
#[test]
fn a_loose_bracket_is_refused() {
    let profile = zerocal_profile::builtin("abb-irb140").unwrap();
    let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    let world = WorldConfig {
        loose_bracket_deg: 0.1,
        ..WorldConfig::real()
    };
    for seed in 1..=5 {
        let s = RealSession::simulate(&profile, &plan, &world, seed);
        match solve(&readings(&profile, &s, true), &fit).result {
            Err(SessionError::Stage2(FitError::CapturesDisagree {
                rms_deg, limit_deg, ..
            })) => {
                assert!(rms_deg > limit_deg, "{rms_deg}");
            }
            other => panic!("seed {seed}: {:?}", other.map(|s| s.offsets_rad)),
        }
    }
}

/// Poses planned for a ±14° window put captures outside mode 4's ±10°: the session
/// names the pose, the axis and the range instead of giving numbers.
#[test]
fn a_sensor_out_of_its_mode_range_is_refused() {
    let profile = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (_, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    let config = zerocal_core::plan::PlanConfig {
        poses: DEFAULT_POSES,
        extras: fit.extras,
        noise_sigma_rad: fit.sensor_noise_rad,
        window_rad: 14f64.to_radians(),
        margin_rad: 0.0,
        ..zerocal_core::plan::PlanConfig::default()
    };
    let wide = zerocal_sim::montecarlo::plan_for(&profile, &config).unwrap();
    let plan: Vec<_> = wide.poses_rad.iter().copied().collect();
    let s = RealSession::simulate(&profile, &plan, &WorldConfig::real(), 4);
    assert!(s.outside_range > 0, "the wide plan stayed inside ±10°");
    match solve(&readings(&profile, &s, true), &fit).result {
        Err(SessionError::Stage2(FitError::ReadingOutOfRange { range_deg, .. })) => {
            assert!((range_deg - 10.0).abs() < 1e-6, "{range_deg}");
        }
        other => panic!("{other:?}"),
    }
}
