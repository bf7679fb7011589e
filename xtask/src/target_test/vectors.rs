//! The test vectors: seeded simulated sessions rounded to `f32` as the pendant holds
//! them, and the Rust source the target program includes.

use std::fmt::Write as _;

use anyhow::{anyhow, bail, Result};
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use zerocal_core::model::{Convention, Tilt};
use zerocal_core::real::deg_to_rad;
use zerocal_core::session::BiasSource;
use zerocal_core::stage0::BenchTurns;
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::PoseReading;
use zerocal_sim::session::SessionConfig;
use zerocal_sim::{PoseSampler, SimInclinometer, SimRobot, SimSession, Table4};

use super::{DEGENERATE_CASE, DEGENERATE_ERROR, KNOCKED_CASE, KNOCK_POSE};

/// One session's data in the precision the pendant stores it, and what it must give.
#[derive(Clone, Debug)]
pub(super) struct Case {
    pub(super) name: &'static str,
    pub(super) convention: Convention,
    pub(super) bias: BiasSource<f32>,
    pub(super) stage1: AxisOneTurn<f32>,
    /// The paper robot's joint-2 direction (its arm is `Arm::paper_with_j2_direction`).
    pub(super) j2_direction: i8,
    pub(super) poses: Vec<PoseReading<f32>>,
    /// The fit's refusal this case is built to provoke, if any.
    pub(super) expected_error: Option<String>,
}

/// The sessions: the paper's Table 4 setup (timed), 5° offsets, the `axis` convention
/// with base tilt, two random seeded sessions (one without stage 0), a degenerate set
/// and a session whose pendant was knocked (the refusal's own refits, the deepest path).
pub(super) fn simulated_cases() -> Result<Vec<Case>> {
    let table4 = SimRobot::paper(Table4::OFFSETS_DEG, (0.0, 0.0));
    let mut offsets5 = SimRobot::paper([5.0, -5.0, 5.0, -5.0], (0.3, -0.5));
    offsets5.offsets_rad[1] = deg_to_rad(5.0);
    let mut axis_tilt = SimRobot::paper(Table4::OFFSETS_DEG, (0.3, -0.5)).with_j2_direction(-1);
    axis_tilt.offsets_rad[1] = deg_to_rad(-0.08);

    let rpy = SessionConfig::default();
    let axis = SessionConfig {
        convention: Convention::Axis,
        ..SessionConfig::default()
    };
    let mut cases = vec![
        from_robot("table4", table4, (0.01, -0.02), &rpy, 41)?,
        from_robot("offsets5", offsets5, (0.02, 0.01), &rpy, 42)?,
        from_robot("axis_tilt", axis_tilt, (0.03, -0.02), &axis, 43)?,
        from_config(
            "random_rpy",
            &SessionConfig {
                seed: 44,
                ..SessionConfig::default()
            },
        )?,
        from_config(
            "random_axis_no_stage0",
            &SessionConfig {
                seed: 45,
                convention: Convention::Axis,
                joint_range_deg: 90.0,
                with_stage0: false,
                ..SessionConfig::default()
            },
        )?,
    ];
    cases.push(degenerate_case(table4, &rpy, 46)?);
    cases.push(knocked_case(&SessionConfig {
        seed: 47,
        ..SessionConfig::default()
    })?);
    Ok(cases)
}

/// A session on a given robot, with a sensor of the given bias (deg).
fn from_robot(
    name: &'static str,
    robot: SimRobot,
    bias_deg: (f64, f64),
    config: &SessionConfig,
    seed: u64,
) -> Result<Case> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut sensor = SimInclinometer::new(
        config.convention,
        Tilt::from_deg(bias_deg.0, bias_deg.1),
        config.noise,
        seed.wrapping_add(1000),
    );
    let session = SimSession::from_parts(robot, &mut sensor, config, &mut rng)
        .map_err(|e| anyhow!("simulating case {name}: {e:?}"))?;
    Ok(to_case(name, &session, None))
}

/// A session whose truth is drawn from `config.seed`.
fn from_config(name: &'static str, config: &SessionConfig) -> Result<Case> {
    let session =
        SimSession::simulate(config).map_err(|e| anyhow!("simulating case {name}: {e:?}"))?;
    Ok(to_case(name, &session, None))
}

/// 30 poses with θ4 and θ6 held at 0 (stages 0 and 1 as usual).
fn degenerate_case(robot: SimRobot, config: &SessionConfig, seed: u64) -> Result<Case> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut sensor = SimInclinometer::new(
        config.convention,
        Tilt::from_deg(0.01, -0.02),
        config.noise,
        seed.wrapping_add(1000),
    );
    let mut session = SimSession::from_parts(robot, &mut sensor, config, &mut rng)
        .map_err(|e| anyhow!("simulating case {DEGENERATE_CASE}: {e:?}"))?;
    let mut sampler = PoseSampler::symmetric(config.joint_range_deg, config.window_deg, seed);
    sampler.limits_rad[1] = (0.0, 0.0);
    sampler.limits_rad[3] = (0.0, 0.0);
    sampler.fixed_joints_rad = [session.stage1.j1_rad, session.stage1.j2_rad];
    let joints = sampler
        .sample(&session.robot, &sensor, config.poses)
        .map_err(|e| anyhow!("sampling the {DEGENERATE_CASE} poses: {e:?}"))?;
    session.poses = joints
        .iter()
        .map(|q| PoseReading {
            joints_rad: *q,
            reading: sensor.read(&session.robot.flange_orientation(q)),
            temperature_c: None,
        })
        .collect();
    Ok(to_case(
        DEGENERATE_CASE,
        &session,
        Some(DEGENERATE_ERROR.to_owned()),
    ))
}

/// A seeded session whose pendant turned [`KNOCK_DEG`] about both its axes before pose
/// [`KNOCK_POSE`] (0-based): every later reading steps by that much. The refusal rule
/// names it only after refitting the session once per candidate place, so this case
/// takes the solve's deepest stack.
fn knocked_case(config: &SessionConfig) -> Result<Case> {
    let mut session = SimSession::simulate(config)
        .map_err(|e| anyhow!("simulating case {KNOCKED_CASE}: {e:?}"))?;
    let step = deg_to_rad(KNOCK_DEG);
    for p in session.poses.iter_mut().skip(KNOCK_POSE) {
        p.reading.x_rad += step;
        p.reading.y_rad += step;
    }
    Ok(to_case(
        KNOCKED_CASE,
        &session,
        Some(format!("PendantMoved {KNOCK_POSE}")),
    ))
}

/// The knock's turn about each of the pendant's axes (deg): the refusal rule's test
/// size (host-tests/tests/refusal_rule.rs).
const KNOCK_DEG: f64 = 0.1;

/// The session's readings rounded to `f32`, as the pendant holds them.
fn to_case(name: &'static str, s: &SimSession, expected_error: Option<String>) -> Case {
    let tilt = |t: &Tilt<f64>| Tilt::new(t.x_rad as f32, t.y_rad as f32);
    Case {
        name,
        convention: s.sensor.model.convention,
        bias: s.stage0.map_or(BiasSource::Unknown, |r| {
            BiasSource::Bench(BenchTurns {
                readings: r.readings.map(|t| tilt(&t)),
                count: r.count,
            })
        }),
        stage1: AxisOneTurn {
            before: tilt(&s.stage1.before),
            after: tilt(&s.stage1.after),
            j1_rad: s.stage1.j1_rad as f32,
            j2_rad: s.stage1.j2_rad as f32,
        },
        j2_direction: if s.robot.arm.joints[1].axis == zerocal_core::model::JointAxis::NegX {
            -1
        } else {
            1
        },
        poses: s
            .poses
            .iter()
            .map(|p| PoseReading {
                joints_rad: p.joints_rad.map(|q| q as f32),
                reading: tilt(&p.reading),
                temperature_c: None,
            })
            .collect(),
        expected_error,
    }
}

/// The Rust source of the vectors: one static pose array per case, then `SESSIONS`.
///
/// # Errors
/// A non-finite value (it would have no literal).
pub(super) fn render_vectors(cases: &[Case]) -> Result<String> {
    let mut out = String::from(
        "// Generated by `cargo xtask target-test` from seeded simulations: do not edit,\n\
         // do not commit. Readings and joint angles in rad, rounded to f32.\n\n",
    );
    for (i, case) in cases.iter().enumerate() {
        let _ = writeln!(
            out,
            "static POSES_{i}: [PoseReading<f32>; {}] = [",
            case.poses.len()
        );
        for p in &case.poses {
            let joints = p
                .joints_rad
                .iter()
                .map(|q| literal(*q))
                .collect::<Result<Vec<_>>>()?;
            let _ = writeln!(
                out,
                "    PoseReading {{ joints_rad: [{}], reading: {}, temperature_c: None }},",
                joints.join(", "),
                tilt_literal(&p.reading)?
            );
        }
        out.push_str("];\n\n");
    }
    let _ = writeln!(
        out,
        "/// The sessions, solved in this order.\npub static SESSIONS: [Case; {}] = [",
        cases.len()
    );
    for (i, case) in cases.iter().enumerate() {
        let bias = match &case.bias {
            BiasSource::Bench(r) => format!(
                "BiasSource::Bench(BenchTurns {{ readings: [{}], count: {} }})",
                r.readings
                    .iter()
                    .map(tilt_literal)
                    .collect::<Result<Vec<_>>>()?
                    .join(", "),
                r.count
            ),
            BiasSource::Stored(b) => format!("BiasSource::Stored({})", tilt_literal(b)?),
            BiasSource::Unknown => "BiasSource::Unknown".to_owned(),
        };
        let convention = match case.convention {
            Convention::Rpy => "Convention::Rpy",
            Convention::Axis => "Convention::Axis",
        };
        let _ = writeln!(
            out,
            "    Case {{\n        name: {:?},\n        convention: {convention},\n        bias: {bias},\n        \
             stage1: AxisOneTurn {{ before: {}, after: {}, j1_rad: {}, j2_rad: {} }},\n        \
             j2_direction: {},\n        poses: &POSES_{i},\n    }},",
            case.name,
            tilt_literal(&case.stage1.before)?,
            tilt_literal(&case.stage1.after)?,
            literal(case.stage1.j1_rad)?,
            literal(case.stage1.j2_rad)?,
            case.j2_direction,
        );
    }
    out.push_str("];\n");
    Ok(out)
}

/// A `Tilt` literal.
fn tilt_literal(t: &Tilt<f32>) -> Result<String> {
    Ok(format!(
        "Tilt {{ x_rad: {}, y_rad: {} }}",
        literal(t.x_rad)?,
        literal(t.y_rad)?
    ))
}

/// An `f32` literal that reads back to the same bits (`{:?}` is round-trip exact).
fn literal(x: f32) -> Result<String> {
    if !x.is_finite() {
        bail!("non-finite value {x} in the test vectors");
    }
    Ok(format!("{x:?}_f32"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_render_exact_literals() {
        let x = 0.1_f32 + f32::EPSILON;
        let text = literal(x).unwrap_or_default();
        let parsed: f32 = text.trim_end_matches("_f32").parse().unwrap_or(f32::NAN);
        assert_eq!(parsed.to_bits(), x.to_bits());
        assert!(literal(f32::NAN).is_err());
    }
}
