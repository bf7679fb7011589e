//! A real arm gets numbers, and honest ones (the design's acceptance): with every error
//! source of the simulated world on (the sensor's, the robot's, the real arm's misaligned
//! axes, transmission error 0.005-0.03° peak to peak with more harmonics than the fit
//! estimates, wrist compliance, brackets calibrated by their own procedure, stage 0 read
//! at four headings turned by hand), over 200 sessions on each of the six family
//! profiles (the UR5e reported, its parallel wrist excepted):
//!
//! - no session is refused;
//! - every joint is within 0.005° of its constant zero in at least 80 % of sessions
//!   (98 % without transmission error);
//! - the k = 2 budget covers each joint's error in 95-99.5 % of sessions, neither short
//!   nor a stack of worst cases, and its median is at most 0.010° on every joint;
//! - entering the offsets leaves the TCP within 1.03 of the best zero-only correction
//!   (mean over 200 reachable poses, a 0.1 m tool).
//!
//! About 3 min on two cores in the test profile (optimised).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use common::rates;

use zerocal_core::bracket::SEAT_REPEATABILITY_DEG;
use zerocal_sim::montecarlo::{run_with_tcp, setup, summarise, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::world::{BracketKnowledge, WorldConfig};

/// Sessions per profile.
const SESSIONS: usize = 200;

/// The shares of sessions a k = 2 budget covers (GUM 6.3.3: about 95 %), per mille;
/// above the upper one it is a stack of worst cases, no longer an uncertainty. A count
/// of sessions refutes them only where it is improbable under them (`common::rates`),
/// per arm and over the arms pooled.
const COVERAGE_PER_MILLE: (usize, usize) = (950, 995);

/// The median expanded uncertainty every joint must reach (deg).
const MEDIAN_U_DEG: f64 = 0.010;

/// Sessions with every joint within 0.005° of its constant zero, at least.
const WITHIN_SHARE: f64 = 0.80;

/// The same without transmission error.
const WITHIN_SHARE_WITHOUT_TE: f64 = 0.98;

/// Entering the offsets leaves the TCP within this factor of the best zero-only
/// correction's mean error.
const TCP_FACTOR: f64 = 1.03;

/// What a world's acceptance holds it to.
struct Bounds {
    within: f64,
    coverage_per_mille: Option<(usize, usize)>,
    median_u_deg: Option<f64>,
    tcp_factor: Option<f64>,
}

/// Runs the six family profiles in `world`; holds each but the UR5e (reported: gravity
/// cannot split its parallel J3/J4, docs/real-arm.md) to `bounds`.
fn acceptance(world: &WorldConfig, what: &str, seed: u64, bounds: &Bounds) {
    println!(
        "{what}: robot, refused/{SESSIONS}, coverage j2..j6, median U(k=2) j2..j6 (deg), within 0.005 deg, TCP after/best (mean, worst)"
    );
    let mut failures = Vec::new();
    let mut held = Vec::new();
    for robot in common::FAMILY_PROFILES {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let out = run_with_tcp(&profile, &plan, world, &fit, SESSIONS, seed, true);
        let s = summarise(&out, 0.005);
        let median: [f64; 5] = core::array::from_fn(|k| {
            let mut u: Vec<f64> = out
                .iter()
                .filter_map(|o| o.budget.as_ref().map(|b| b.expanded_rad[k].to_degrees()))
                .collect();
            u.sort_by(f64::total_cmp);
            u.get(u.len() / 2).copied().unwrap_or(f64::INFINITY)
        });
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
            median.map(|u| format!("{u:.4}")).join(" "),
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
        if !reasons.is_empty() {
            failures.push(format!("{robot}: refused {reasons:?}"));
        }
        if profile.arm.parallel_twins().iter().any(|t| *t) {
            continue;
        }
        if !rates::all_within_at_least(&s, bounds.within) {
            failures.push(format!("{robot}: within 0.005 deg {}", s.all_within));
        }
        let solved = s.sessions - s.refused;
        for (k, (&c, &u)) in s.covered_sessions.iter().zip(&median).enumerate() {
            if !coverage_holds(c, solved, bounds) {
                failures.push(format!("{robot} j{}: k=2 covers {c}/{solved}", k + 2));
            }
            if let Some(limit) = bounds.median_u_deg {
                if u > limit {
                    failures.push(format!("{robot} j{}: median U {u}", k + 2));
                }
            }
        }
        if let Some(factor) = bounds.tcp_factor {
            if mean_ratio > factor {
                failures.push(format!("{robot}: TCP after/best {mean_ratio}"));
            }
        }
        held.push(s);
    }
    // The same claims on the arms held to them, pooled: a budget a little short on
    // every arm, or a stack of worst cases, shows here though no one arm's 200
    // sessions can tell it (`common::rates`).
    let (within, sessions) = rates::pooled_all_within(&held);
    println!("  pooled over the arms held: within 0.005 deg {within}/{sessions}");
    if !rates::consistent_with_at_least(within, sessions, bounds.within) {
        failures.push(format!("pooled: within 0.005 deg {within}/{sessions}"));
    }
    for (k, (covered, solved)) in rates::pooled_coverage(&held).into_iter().enumerate() {
        println!("  pooled j{}: k=2 covers {covered}/{solved}", k + 2);
        if !coverage_holds(covered, solved, bounds) {
            failures.push(format!("pooled j{}: k=2 covers {covered}/{solved}", k + 2));
        }
    }
    assert!(failures.is_empty(), "{what}: {failures:#?}");
}

/// Whether `covered` of `solved` sessions is consistent with the coverage `bounds`
/// state (none stated: any).
fn coverage_holds(covered: usize, solved: usize, bounds: &Bounds) -> bool {
    bounds.coverage_per_mille.is_none_or(|(lo, hi)| {
        rates::consistent_with_at_least(covered, solved, lo as f64 / 1000.0)
            && rates::consistent_with_at_most(covered, solved, hi as f64 / 1000.0)
    })
}

/// Every source on at its stated range, transmission error 0.005-0.03° peak to peak,
/// the brackets calibrated and seated within their stated repeatability (the budget
/// carries both: a world without them tests a budget term against nothing).
#[test]
fn a_real_arm_at_the_stated_ranges_gets_covered_numbers() {
    let world = WorldConfig {
        robot: RobotSources::REAL_ARM,
        seat_repeatability_deg: SEAT_REPEATABILITY_DEG,
        brackets: BracketKnowledge::Calibrated,
        ..WorldConfig::real()
    };
    acceptance(
        &world,
        "every source on",
        71,
        &Bounds {
            within: WITHIN_SHARE,
            coverage_per_mille: Some(COVERAGE_PER_MILLE),
            median_u_deg: Some(MEDIAN_U_DEG),
            tcp_factor: Some(TCP_FACTOR),
        },
    );
}

/// The same arm without transmission error: every other source on.
#[test]
fn without_transmission_error_every_joint_is_within_0_005_deg() {
    let world = WorldConfig {
        robot: RobotSources {
            transmission: false,
            ..RobotSources::REAL_ARM
        },
        ..WorldConfig::real()
    };
    acceptance(
        &world,
        "without transmission error",
        73,
        &Bounds {
            within: WITHIN_SHARE_WITHOUT_TE,
            coverage_per_mille: Some((COVERAGE_PER_MILLE.0, 1000)),
            median_u_deg: Some(MEDIAN_U_DEG),
            tcp_factor: Some(TCP_FACTOR),
        },
    );
}

/// The FANUC R-2000iC/165F as a laser tracker measured it (transmission error to 0.06°
/// peak to peak, beyond the stated range): numbers still, reported, held to nothing but
/// no refusal.
#[test]
fn the_fanuc_as_measured_gets_numbers() {
    acceptance(
        &WorldConfig::fanuc_as_measured(),
        "FANUC as measured",
        72,
        &Bounds {
            within: 0.0,
            coverage_per_mille: None,
            median_u_deg: None,
            tcp_factor: None,
        },
    );
}
