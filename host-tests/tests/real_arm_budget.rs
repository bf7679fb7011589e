//! A real arm gets numbers, and honest ones: with every error source of the simulated
//! world on (the sensor's, today's robot's, and the real arm's misaligned axes,
//! transmission error and wrist compliance at their stated ranges), over 200 sessions
//! on each of seven profiles, no session is refused, the k = 2 budget covers each joint's
//! error in at least 95 % of sessions, and entering the offsets positions a 0.1 m tool
//! within 10 % of the best zero-only correction (mean distance over 200 reachable
//! poses). The share of sessions with every joint within 0.005° is printed
//! (`--nocapture`): on a real arm it is limited by the transmission error, which no
//! zero removes (docs/error-budget.md).
//!
//! About 1 min on two cores in the test profile (optimised).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use zerocal_sim::montecarlo::{run_with_tcp, setup, summarise, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::world::WorldConfig;

/// Sessions per profile.
const SESSIONS: usize = 200;

/// The budget's coverage aimed at: k = 2 is about 95 % (GUM 6.3.3).
const COVERAGE: f64 = 0.95;

/// Entering the offsets leaves the TCP within this factor of the best zero-only
/// correction's mean error.
const TCP_FACTOR: f64 = 1.10;

/// `tcp_factor`: the TCP bound asserted (`None`: printed only). An arm with parallel
/// twins (the UR5e's joints 3 and 4 after joint 2) is not held to it: gravity cannot
/// split their zeros, the session reports the sum on the first and the second "not
/// identifiable", and the TCP needs the split (docs/error-budget.md).
fn acceptance(world: &WorldConfig, what: &str, seed: u64, tcp_factor: Option<f64>) {
    println!("{what}: robot, refused/{SESSIONS}, coverage j2..j6, mean U(k=2) j2..j6 (deg), within 0.005 deg, TCP after/best (mean, worst)");
    // One profile per controller family, and the PUMA 560.
    for robot in common::FAMILY_PROFILES.iter().chain(&["puma560"]) {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let out = run_with_tcp(&profile, &plan, world, &fit, SESSIONS, seed, true);
        let s = summarise(&out, 0.005);
        let ratios: Vec<f64> = out
            .iter()
            .filter_map(|o| o.tcp.map(|t| t.mean_after_mm / t.mean_best_mm))
            .collect();
        let mean_ratio = ratios.iter().sum::<f64>() / ratios.len().max(1) as f64;
        let worst_ratio = ratios.iter().copied().fold(0.0f64, f64::max);
        println!(
            "  {robot:<19} {:>3}  {}  {}  {:>5.1} %  {mean_ratio:.3} {worst_ratio:.3}",
            s.refused,
            s.covered.map(|c| format!("{:.3}", c)).join(" "),
            s.mean_k2_deg.map(|u| format!("{u:.4}")).join(" "),
            100.0 * s.all_within
        );
        let reasons: Vec<String> = out
            .iter()
            .filter_map(|o| {
                o.result
                    .as_ref()
                    .err()
                    .map(|e| format!("seed {}: {e}", o.seed))
            })
            .collect();
        assert!(reasons.is_empty(), "{what}, {robot}: refused {reasons:?}");
        for (k, c) in s.covered.iter().enumerate() {
            assert!(*c >= COVERAGE, "{what}, {robot} j{}: k=2 covers {c}", k + 2);
        }
        assert_eq!(ratios.len(), SESSIONS, "{what}, {robot}: TCP test missing");
        let twins = profile.arm.parallel_twins().iter().any(|t| *t);
        if let (Some(factor), false) = (tcp_factor, twins) {
            assert!(
                mean_ratio <= factor,
                "{what}, {robot}: TCP after/best {mean_ratio}"
            );
        }
    }
}

/// Every source on at its stated range.
#[test]
fn a_real_arm_at_the_stated_ranges_gets_covered_numbers() {
    let world = WorldConfig {
        robot: RobotSources::REAL_ARM,
        ..WorldConfig::real()
    };
    acceptance(&world, "every source on", 71, Some(TCP_FACTOR));
}

/// The FANUC R-2000iC/165F as a laser tracker measured it (transmission error to 0.06°
/// peak to peak, beyond the stated range): numbers still, with a larger budget; its
/// TCP after/best (1.08-1.12 on the six) is printed, not held to 10 %: that much
/// transmission error is beyond what the stated ranges promise.
#[test]
fn the_fanuc_as_measured_gets_covered_numbers() {
    acceptance(
        &WorldConfig::fanuc_as_measured(),
        "FANUC as measured",
        72,
        None,
    );
}
