//! The refusal rule names each fault far outside its range (core's `session::judge`):
//! a pose the robot did not reach, a loose flange bracket, a pendant knocked
//! mid-session, the wrong profile; on six profiles, every error source of a real arm
//! on beside the fault. A fault nearer its limit (a bracket loose by 0.02-0.075°, one
//! creeping) is named where it would carry the numbers outside their U(k = 2).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use zerocal_core::error::FitError;
use zerocal_core::session::{solve, SessionError};
use zerocal_core::stage2::FitConfig;
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::world::{RealSession, SessionFault, WorldConfig};

use common::FAMILY_PROFILES as PROFILES;

/// Sessions per profile and fault.
const SESSIONS: u64 = 10;

fn real_arm() -> WorldConfig {
    WorldConfig {
        robot: RobotSources::REAL_ARM,
        ..WorldConfig::real()
    }
}

/// Every session of `world` on every profile, solved with the profile `solve_as` gives
/// (its own where `None`), is refused, and `named` accepts the refusal.
fn refused_as(
    world: &WorldConfig,
    solve_as: impl Fn(&str) -> Option<&'static str>,
    named: impl Fn(&FitError) -> bool,
) {
    for robot in PROFILES {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let assumed = zerocal_profile::builtin(solve_as(robot).unwrap_or(robot)).unwrap();
        let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        for seed in 0..SESSIONS {
            let session = RealSession::simulate(&profile, &plan, world, 500 + seed);
            let mut readings = session.readings(&assumed, world);
            readings.arm = assumed.arm;
            readings.masses = assumed.mass_model();
            match solve(&readings, &fit).result {
                Err(SessionError::Stage2(e)) if named(&e) => {}
                other => panic!("{robot} seed {seed}: {:?}", other.map(|s| s.offsets_rad)),
            }
        }
    }
}

/// Joint 3 stopped 0.5° short of pose 10: that pose is named.
#[test]
fn a_pose_not_reached_is_named() {
    let world = WorldConfig {
        fault: SessionFault::UnreachedPose {
            pose: 9,
            joint: 3,
            short_deg: 0.5,
        },
        ..real_arm()
    };
    refused_as(
        &world,
        |_| None,
        |e| matches!(e, FitError::PoseNotReached { pose: 9, .. }),
    );
}

/// A flange bracket that seats anew within ±0.1° at every capture.
#[test]
fn a_loose_bracket_is_named() {
    let world = WorldConfig {
        loose_bracket_deg: 0.1,
        ..real_arm()
    };
    refused_as(
        &world,
        |_| None,
        |e| matches!(e, FitError::CapturesDisagree { .. }),
    );
}

/// The pendant turned 0.1° about its x and its y on the flange before pose 13: the move
/// is named, within a pose of where it happened, with its size (a shift of every
/// reading by 0.1° on x and on y, √2 × 0.1° in all) within 15 %: the step is measured
/// against the robot's own scatter, not the fit that bent towards it.
#[test]
fn a_knocked_pendant_is_named() {
    let world = WorldConfig {
        fault: SessionFault::Knocked { pose: 12, deg: 0.1 },
        ..real_arm()
    };
    let size_deg = 0.1 * core::f64::consts::SQRT_2;
    refused_as(
        &world,
        |_| None,
        |e| {
            matches!(e, FitError::PendantMoved { from_pose, step_deg }
                if from_pose.abs_diff(12) <= 1
                    && (f64::from(*step_deg) - size_deg).abs() <= 0.15 * size_deg)
        },
    );
}

/// A session solved with another robot's profile is refused with a message that names
/// the profile.
#[test]
fn the_wrong_profile_is_named() {
    refused_as(
        &real_arm(),
        |r| {
            Some(if r == "abb-irb140" {
                "kuka-kr6-r900-sixx"
            } else {
                "abb-irb140"
            })
        },
        |e| e.to_string().contains("profile"),
    );
}

/// A flange bracket that creeps (a clamp not quite tight: the pendant turning a little
/// further at each capture, 0.0005-0.01° a capture): in at least 95 % of the
/// sessions whose result it would carry outside its U(k = 2) on some joint, the session
/// is refused naming the bracket's move (a revisited pose that reads otherwise, or the
/// readings' drift over stage 2); no creeping session is refused under another name.
#[test]
fn a_creeping_bracket_is_named_where_it_matters() {
    use zerocal_core::session::{budget, solve};
    use zerocal_core::stage2::refusal::RefusalRule;
    let creeping = |e: &FitError| {
        matches!(
            e,
            FitError::RevisitDisagrees { .. }
                | FitError::PendantCreeping { .. }
                | FitError::PendantMoved { .. }
        )
    };
    for deg_per_capture in [0.0005, 0.002, 0.01] {
        let world = WorldConfig {
            fault: SessionFault::Creeping { deg_per_capture },
            ..real_arm()
        };
        let (mut beyond_u, mut named) = (0, 0);
        for robot in PROFILES {
            let profile = zerocal_profile::builtin(robot).unwrap();
            let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
            for seed in 0..SESSIONS {
                let session = RealSession::simulate(&profile, &plan, &world, 900 + seed);
                let readings = session.readings(&profile, &world);
                let refused = match solve(&readings, &fit).result {
                    Ok(_) => None,
                    Err(SessionError::Stage2(e)) if creeping(&e) => Some(true),
                    Err(e) => panic!("{robot} {deg_per_capture} seed {seed}: refused as {e}"),
                };
                // What the session would have given without the rule: outside its U?
                let off = FitConfig {
                    refusal: RefusalRule::OFF,
                    ..fit
                };
                let outside = solve(&readings, &off).result.ok().is_none_or(|s| {
                    let b = budget(
                        &s,
                        &session.poses,
                        &world.budget_inputs(&profile, &fit, &session.brackets),
                    );
                    let truth = session.truth_rad();
                    (0..5).any(|k| (s.offsets_rad[k] - truth[k]).abs() > b.expanded_rad[k])
                });
                if outside {
                    beyond_u += 1;
                    named += usize::from(refused.is_some());
                }
            }
        }
        println!("creeping {deg_per_capture} deg a capture: {named} of {beyond_u} sessions outside U named");
        assert!(
            named as f64 >= 0.95 * beyond_u as f64,
            "{deg_per_capture}: {named} of {beyond_u}"
        );
    }
}

/// A flange bracket loose by less than the 0.1° [`a_loose_bracket_is_named`] injects
/// (raised to it when 0.05° was no longer refused by its captures' difference): seated
/// anew within ±0.02, ±0.05 and ±0.075° about each axis at every capture of stage 2
/// (`loose_bracket_deg`, `sim/src/world.rs`), 40 sessions per profile and size. Each
/// session is either refused by a name that sends the technician to the bracket (the
/// two captures of a pose disagree, a revisited pose reads otherwise, the pendant moved
/// or crept on the flange, residuals no tight bracket leaves) or solved with numbers
/// its U(k = 2) covers: per joint, the sessions named or covered are consistent with
/// the budget's 95 % (`common::rates`), the six profiles pooled at each size (240
/// sessions) and each profile alone (40: a gross failure only); no session is refused
/// under another name. Measured: the standard rule names every session at 0.05 and
/// 0.075°, and 194 of 240 at 0.02° (a revisit, or the move's step); with its limits for
/// a moving bracket raised to 1° the UR5e's j2 is covered in 29 of 40 at 0.05°, and
/// some sessions are refused as a bench not turned on the spot. The sessions with
/// every joint covered at once are printed, not judged: the budget's claim is per joint
/// (on a tight bracket 219 of 240 sessions had every joint covered).
#[test]
fn a_slightly_loose_bracket_is_named_or_covered() {
    use common::rates;
    use zerocal_sim::montecarlo::run;
    /// Sessions per profile and size.
    const LOOSE_SESSIONS: usize = 40;
    let names_the_bracket = |e: &FitError| {
        matches!(
            e,
            FitError::CapturesDisagree { .. }
                | FitError::RevisitDisagrees { .. }
                | FitError::PendantMoved { .. }
                | FitError::PendantCreeping { .. }
                | FitError::ResidualTooLarge { .. }
        )
    };
    println!("loose (deg)  robot               named  solved  covered j2..j6  every joint");
    for loose_bracket_deg in [0.02, 0.05, 0.075] {
        let world = WorldConfig {
            loose_bracket_deg,
            ..real_arm()
        };
        // Per joint: the sessions named or covered, and the sessions, pooled.
        let mut pooled = [0usize; 5];
        let mut sessions = 0;
        // Each profile its own seeds, so that the pooled sessions are independent draws.
        for (seed, robot) in (2700..).zip(PROFILES) {
            let profile = zerocal_profile::builtin(robot).unwrap();
            let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
            let out = run(&profile, &plan, &world, &fit, LOOSE_SESSIONS, seed);
            let (mut named, mut every, mut covered) = (0, 0, [0usize; 5]);
            for o in &out {
                match (&o.result, o.errors_deg(), &o.budget) {
                    (Ok(_), Some(e), Some(b)) => {
                        let c: [bool; 5] =
                            core::array::from_fn(|k| e[k].abs() <= b.expanded_rad[k].to_degrees());
                        for (n, c) in covered.iter_mut().zip(c) {
                            *n += usize::from(c);
                        }
                        every += usize::from(c.iter().all(|&c| c));
                    }
                    (Err(SessionError::Stage2(e)), _, _) if names_the_bracket(e) => named += 1,
                    (Err(e), _, _) => panic!(
                        "{robot} loose {loose_bracket_deg} deg seed {}: refused as {e}",
                        o.seed
                    ),
                    (Ok(_), _, _) => panic!("{robot} seed {}: solved without a budget", o.seed),
                }
            }
            let solved = LOOSE_SESSIONS - named;
            println!(
                "{loose_bracket_deg:<12} {robot:<19} {named:>2}/{LOOSE_SESSIONS}  {solved:>2}      {}   {every:>2}",
                covered.map(|c| format!("{c:>2}")).join(" ")
            );
            for (k, c) in covered.iter().enumerate() {
                assert!(
                    rates::consistent_with_at_least(named + c, LOOSE_SESSIONS, 0.95),
                    "{robot} loose {loose_bracket_deg} deg j{}: {named} named and {c} covered of {LOOSE_SESSIONS}",
                    k + 2
                );
                pooled[k] += named + c;
            }
            sessions += LOOSE_SESSIONS;
        }
        println!(
            "{loose_bracket_deg:<12} pooled: named or covered j2..j6 {} of {sessions}",
            pooled.map(|c| c.to_string()).join(" ")
        );
        for (k, c) in pooled.iter().enumerate() {
            assert!(
                rates::consistent_with_at_least(*c, sessions, 0.95),
                "loose {loose_bracket_deg} deg j{}: pooled named or covered {c} of {sessions}",
                k + 2
            );
        }
    }
}
