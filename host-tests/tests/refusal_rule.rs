//! The refusal rule names each fault far outside its range (core's `session::judge`):
//! a pose the robot did not reach, a loose flange bracket, a pendant knocked
//! mid-session, the wrong profile; on six profiles, every error source of a real arm
//! on beside the fault.

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
