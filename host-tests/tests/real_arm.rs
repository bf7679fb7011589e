//! What real arms have beyond their zeros, in the simulated robot: joint-axis
//! misalignment, transmission error, wrist compliance and stage 1's loading. Each
//! source, switched on alone, moves the arm by an amount within its stated range; and a
//! measurement table (printed, not asserted) of what each does to whole sessions.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use zerocal_core::model::JOINTS;
use zerocal_profile::Profile;
use zerocal_sim::montecarlo::{run, setup, Method, DEFAULT_POSES};
use zerocal_sim::robot::{misalign, peak_to_peak_rad, RobotErrors, RobotSources, RobotSpec};
use zerocal_sim::sensor::SensorSources;
use zerocal_sim::world::{RealSession, WorldConfig};

fn limits_rad(profile: &Profile) -> [(f64, f64); JOINTS] {
    core::array::from_fn(|k| {
        profile.joints.get(k).map_or((-3.0, 3.0), |j| {
            (j.min_deg.to_radians(), j.max_deg.to_radians())
        })
    })
}

fn only(sources: RobotSources) -> WorldConfig {
    WorldConfig {
        robot: sources,
        ..WorldConfig::real()
    }
}

/// The real-arm sources are off in today's world: its figures stay what they were.
#[test]
fn real_arm_sources_are_off_by_default() {
    let r = WorldConfig::real().robot;
    assert!(!r.misalignment && !r.transmission && !r.wrist_compliance);
    let all = RobotSources::REAL_ARM;
    assert!(all.misalignment && all.transmission && all.wrist_compliance);
}

/// Misalignment moves the flange by at most the drawn angles' sum (each tilt turns the
/// rest of the chain by its angle) and, over poses, by at least a quarter of the
/// largest drawn angle (a loose floor: tilts of different joints may partly cancel).
#[test]
fn misalignment_moves_the_flange_within_the_drawn_angles() {
    for robot in ["kuka-kr6-r900-sixx", "ur5e", "fanuc-m20ia"] {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let (arm, angles) = misalign(&profile.arm, &RobotSpec::DEFAULT, &mut rng);
        let sum: f64 = angles.iter().sum();
        let largest = angles.iter().copied().fold(0.0, f64::max);
        let tilt = zerocal_core::model::BaseTilt::from_deg(0.0, 0.0);
        let mut worst = 0.0f64;
        for i in 0..50 {
            let q: [f64; JOINTS] =
                core::array::from_fn(|k| 0.37 * (i * (k + 1)) as f64 % 2.0 - 1.0);
            let ideal = profile.arm.flange_sensor(&tilt, &q);
            let real = arm.flange_sensor(&tilt, &q);
            let d = (ideal.inverse() * real).angle();
            assert!(
                d <= sum * 1.000_001,
                "{robot}: {d} rad beyond the sum {sum}"
            );
            worst = worst.max(d);
        }
        assert!(
            worst >= 0.25 * largest,
            "{robot}: {worst} rad, largest tilt {largest}"
        );
        // Parallel pairs draw from their own range (up to 0.5°), perpendicular up to 0.05°.
        for a in &angles[1..] {
            assert!(a.to_degrees() >= 0.01 - 1e-12 && a.to_degrees() <= 0.5 + 1e-12);
        }
    }
}

/// The transmission error of each joint spans the drawn peak to peak: harmonics 1-4 of
/// the output turn within the spec's 0.005-0.03° (sampled every 0.5°: 1e-6° of slack for
/// the sampling), harmonics 3 and 4 each at most the spec's share of the larger of 1 and
/// 2; a ripple of 20-60 cycles a turn up to the spec's 0.001°; on joints 4 and 6 a
/// once-per-turn term of 0.005-0.025° peak to peak, on no other joint.
#[test]
fn transmission_error_within_its_range() {
    let profile = zerocal_profile::builtin("fanuc-m20ia").unwrap();
    let spec = RobotSpec::DEFAULT;
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let sources = RobotSources {
        transmission: true,
        ..RobotSources::NONE
    };
    let e = RobotErrors::draw(
        &profile.arm,
        profile.mass_model(),
        &limits_rad(&profile),
        &spec,
        sources,
        &mut rng,
    );
    let (lo, hi) = spec.transmission_pp_deg;
    let (once_lo, once_hi) = spec.once_per_turn_pp_deg;
    for k in 0..JOINTS {
        let terms = &e.transmission[k];
        let gear = peak_to_peak_rad(&terms[..4]).to_degrees();
        assert!(
            (lo - 1e-6..=hi + 1e-6).contains(&gear),
            "j{}: {gear}°",
            k + 1
        );
        let orders: Vec<f64> = terms[..4].iter().map(|h| h.order).collect();
        assert_eq!(orders, [1.0, 2.0, 3.0, 4.0], "j{}", k + 1);
        let top = terms[0].amplitude_rad.max(terms[1].amplitude_rad);
        for h in &terms[2..4] {
            assert!(
                h.amplitude_rad <= spec.higher_harmonic_share * top + 1e-15,
                "j{}: order {} at {} of {top} rad",
                k + 1,
                h.order,
                h.amplitude_rad
            );
        }
        let ripple = &terms[4];
        assert!(
            (20.0..=60.0).contains(&ripple.order)
                && ripple.amplitude_rad.to_degrees() <= spec.ripple_deg + 1e-12,
            "j{}: ripple {ripple:?}",
            k + 1
        );
        let once = 2.0 * terms[5].amplitude_rad.to_degrees();
        if k == 3 || k == 5 {
            assert!(
                terms[5].order == 1.0 && (once_lo..=once_hi).contains(&once),
                "j{}: once per turn {once}°",
                k + 1
            );
        } else {
            assert_eq!(once, 0.0, "j{}", k + 1);
        }
        let total = peak_to_peak_rad(terms).to_degrees();
        assert!(
            total <= hi + once_hi + 2.0 * spec.ripple_deg + 1e-6,
            "j{}: {total}°",
            k + 1
        );
    }
    // Off, the joint goes where it is commanded.
    let none = RobotErrors::draw(
        &profile.arm,
        profile.mass_model(),
        &limits_rad(&profile),
        &spec,
        RobotSources::NONE,
        &mut rng,
    );
    assert_eq!(none.transmission_error_rad(3, 1.0), 0.0);
}

/// Wrist compliance: joints 4-6 deflect 0.01-0.03° at their largest gravity torque,
/// and no more than 0.03° (+1 %: the torque grid is 12 steps) anywhere.
#[test]
fn wrist_compliance_within_its_range() {
    for robot in ["kuka-kr6-r900-sixx", "fanuc-m20ia"] {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let sources = RobotSources {
            wrist_compliance: true,
            ..RobotSources::NONE
        };
        let limits = limits_rad(&profile);
        let e = RobotErrors::draw(
            &profile.arm,
            profile.mass_model(),
            &limits,
            &RobotSpec::DEFAULT,
            sources,
            &mut rng,
        );
        for k in 3..JOINTS {
            let at_full = (e.compliance_rad_per_nm[k] * e.full_torque_nm[k]).to_degrees();
            assert!(
                e.full_torque_nm[k] == 0.0 || (0.01 - 1e-12..=0.03 + 1e-12).contains(&at_full),
                "{robot} j{}: {at_full}°",
                k + 1
            );
        }
        let mut moved = 0.0f64;
        for i in 0..40 {
            let q: [f64; JOINTS] = core::array::from_fn(|k| {
                let (lo, hi) = limits[k];
                lo + (hi - lo) * ((0.61 * (i * (k + 3)) as f64) % 1.0)
            });
            let d = e.deflect(&profile.arm, &q, &[1; JOINTS], &mut rng);
            for k in 3..JOINTS {
                let deg = (d[k] - q[k]).to_degrees().abs();
                assert!(deg <= 0.03 * 1.01, "{robot} j{}: {deg}°", k + 1);
                moved = moved.max(deg);
            }
            assert_eq!(d[..3], q[..3], "{robot}: only the wrist moves");
        }
        assert!(moved > 0.0, "{robot}: the wrist never deflected");
    }
}

/// Stage 1 is loaded: with sag alone (ideal sensor, no warming), the stage-1 reading
/// differs from the rigid robot's by joint 2's sag there, at most its 0.02° at full lever.
#[test]
fn stage1_reading_carries_joint2_sag() {
    let profile = zerocal_profile::builtin("fanuc-m20ia").unwrap();
    let plan = [[0.0; JOINTS]];
    let world = |sag: bool| WorldConfig {
        sensor: SensorSources::NONE,
        robot: RobotSources {
            sag,
            ..RobotSources::NONE
        },
        warming_k: 0.0,
        ..WorldConfig::real()
    };
    let sagging = RealSession::simulate(&profile, &plan, &world(true), 11);
    let rigid = RealSession::simulate(&profile, &plan, &world(false), 11);
    let d = |a: f64, b: f64| (a - b).to_degrees().abs();
    let moved = d(sagging.stage1.before.x_rad, rigid.stage1.before.x_rad)
        .max(d(sagging.stage1.before.y_rad, rigid.stage1.before.y_rad));
    assert!(
        moved > 1e-6 && moved <= 0.02 + 1e-9,
        "stage 1 moved {moved}°"
    );
}

/// The measurement table: 20 sessions per robot and effect, solved as the pendant
/// does. Printed (`--nocapture`), not asserted: it is what the method meets on real
/// arms. About 5 s.
#[test]
fn real_arm_measurement_table() {
    let effects: [(&str, WorldConfig); 6] = [
        ("today", WorldConfig::real()),
        (
            "misalignment",
            only(RobotSources {
                misalignment: true,
                ..RobotSources::ALL
            }),
        ),
        (
            "transmission",
            only(RobotSources {
                transmission: true,
                ..RobotSources::ALL
            }),
        ),
        (
            "wrist",
            only(RobotSources {
                wrist_compliance: true,
                ..RobotSources::ALL
            }),
        ),
        ("all", only(RobotSources::REAL_ARM)),
        ("fanuc-as-measured", WorldConfig::fanuc_as_measured()),
    ];
    println!("robot               effect             refused  worst |error| j2..j6 (deg)              worst residual RMS (deg)");
    for robot in common::FAMILY_PROFILES {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, fit) = match setup(&profile, Method::Compensated, DEFAULT_POSES) {
            Ok(p) => p,
            Err(e) => {
                println!("{robot:<19} plan refused: {e}");
                continue;
            }
        };
        for (name, world) in &effects {
            let out = run(&profile, &plan, world, &fit, 20, 21);
            let mut worst = [0.0f64; 5];
            let mut residual = 0.0f64;
            let mut reasons = Vec::new();
            for o in &out {
                match &o.result {
                    Ok(s) => residual = residual.max(s.fit.residual_rms_rad.to_degrees()),
                    Err(e) => reasons.push(e.to_string()),
                }
                if let Some(e) = o.errors_deg() {
                    for (w, x) in worst.iter_mut().zip(e) {
                        *w = w.max(x.abs());
                    }
                }
            }
            reasons.sort();
            reasons.dedup();
            println!(
                "{robot:<19} {name:<18} {:>2}/20    {}   {residual:.4}{}",
                out.iter().filter(|o| o.result.is_err()).count(),
                worst.map(|x| format!("{x:.4}")).join(" "),
                if reasons.is_empty() {
                    String::new()
                } else {
                    format!("  refused: {}", reasons.join(" | "))
                }
            );
        }
    }
}
