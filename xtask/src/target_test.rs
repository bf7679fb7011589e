//! `cargo xtask target-test`: zerocal-core on the real CPU, in QEMU.
//!
//! 1. Simulates seeded sessions on the host (host-tests' simulators) and writes their
//!    readings, rounded to `f32`, as the Rust source of static arrays (never committed).
//! 2. Builds `target-test/` (cortex-m-rt, no embassy) in release for thumbv7em with the
//!    firmware's toolchain choice, the vectors included.
//! 3. Runs it under `qemu-system-arm -machine netduinoplus2` (a Cortex-M4F) with a time
//!    limit, reading its semihosting output (format: `target-test/src/main.rs`).
//! 4. Solves the same `f32` data in `f64` on the host with the same pipeline
//!    (`target-test/src/pipeline.rs`) and compares: every number within
//!    [`TOLERANCE_DEG`], every refusal the same variant naming the same joints.
//! 5. Checks the instruction count and peak stack of one 30-pose fit, and the release
//!    firmware's flash and static RAM, against [`BUDGETS`].

use std::collections::BTreeMap;
use std::fmt;
use std::fmt::Write as _;
use std::fs;
use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context, Result};
use rand_chacha::rand_core::SeedableRng;
use rand_chacha::ChaCha8Rng;
use zerocal_core::fit::PoseReading;
use zerocal_core::model::{Convention, Tilt};
use zerocal_core::real::{deg_to_rad, rad_to_deg};
use zerocal_core::stage0::Reversal;
use zerocal_core::stage1::AxisOneTurn;
use zerocal_host_tests::sim::session::SessionConfig;
use zerocal_host_tests::sim::{PoseSampler, SimInclinometer, SimRobot, SimSession, Table4};

use crate::pipeline::{self, FitErrorWords, Session, StageErrorWords};
use crate::toolchain::THUMB_TARGET;

/// Largest difference allowed between the target's `f32` and the host's `f64` result,
/// on every angle (deg): a tenth of the Table 4 noise-limited accuracy.
pub const TOLERANCE_DEG: f64 = 2e-5;

/// What the pendant's CPU may spend. Exceeding any of them fails the check.
pub const BUDGETS: Figures = Figures {
    solve_instructions: 600_000,
    solve_stack_bytes: 8 * 1024,
    flash_bytes: 128 * 1024,
    static_ram_bytes: 32 * 1024,
};

/// The session whose fit is timed and stack-measured: the paper's Table 4 setup.
const MEASURED_CASE: &str = "table4";

/// The refusal the degenerate set must give: θ4 and θ6 held at 0 make joints 3 and 5
/// coaxial, one parameter.
const DEGENERATE_CASE: &str = "degenerate";
const DEGENERATE_ERROR: &str = "RankDeficient j3+j5";

/// The QEMU run is killed (and the check fails) after this long. It takes about a
/// second; the margin is for a loaded 2-core CI machine.
const QEMU_TIME_LIMIT: Duration = Duration::from_secs(120);

/// The environment variable through which `target-test/build.rs` finds the vectors.
const VECTORS_VAR: &str = "ZEROCAL_TARGET_TEST_VECTORS";

/// The four figures the check measures (and the budgets, in the same shape).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Figures {
    /// Instructions of one 30-pose `f32` fit.
    pub solve_instructions: u64,
    /// Peak stack of that fit (bytes).
    pub solve_stack_bytes: u64,
    /// Release firmware's flash (bytes).
    pub flash_bytes: u64,
    /// Release firmware's static RAM (bytes).
    pub static_ram_bytes: u64,
}

impl Figures {
    /// One line per figure with its budget; `Err` lists the figures over budget.
    ///
    /// # Errors
    /// When any figure exceeds its budget (the message names them).
    pub fn against(&self, budgets: &Figures) -> Result<String, String> {
        let rows = [
            (
                "30-pose f32 fit (table4)",
                self.solve_instructions,
                budgets.solve_instructions,
                "instructions",
            ),
            (
                "30-pose f32 fit peak stack",
                self.solve_stack_bytes,
                budgets.solve_stack_bytes,
                "bytes",
            ),
            (
                "firmware flash",
                self.flash_bytes,
                budgets.flash_bytes,
                "bytes",
            ),
            (
                "firmware static RAM",
                self.static_ram_bytes,
                budgets.static_ram_bytes,
                "bytes",
            ),
        ];
        let mut text = String::new();
        let mut over = Vec::new();
        for (what, value, budget, unit) in rows {
            let verdict = if value <= budget { "ok" } else { "OVER BUDGET" };
            // Writing to a String cannot fail.
            let _ = writeln!(
                text,
                "{what}: {value} {unit} (budget {budget} {unit}, {:.0} %) {verdict}",
                value as f64 * 100.0 / budget.max(1) as f64
            );
            if value > budget {
                over.push(format!("{what} {value} > {budget} {unit}"));
            }
        }
        if over.is_empty() {
            Ok(text)
        } else {
            Err(format!("{text}over budget: {}", over.join("; ")))
        }
    }
}

/// One session's data in the precision the pendant stores it, and what it must give.
#[derive(Clone, Debug)]
struct Case {
    name: &'static str,
    convention: Convention,
    stage0: Option<Reversal<f32>>,
    stage1: AxisOneTurn<f32>,
    poses: Vec<PoseReading<f32>>,
    /// The fit's refusal this case is built to provoke, if any.
    expected_error: Option<&'static str>,
}

/// Runs the whole check from the repository root.
///
/// # Errors
/// Simulation, build, QEMU, a missing or different result, or a budget exceeded.
pub fn run(root: &Path) -> Result<()> {
    let cases = simulated_cases()?;
    let expected = host_results(&cases)?;

    let vectors_path = root.join("target").join("target-test").join("vectors.rs");
    if let Some(dir) = vectors_path.parent() {
        fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    fs::write(&vectors_path, render_vectors(&cases)?)
        .with_context(|| format!("writing {}", vectors_path.display()))?;
    eprintln!(
        "xtask: {} test vectors in {}",
        cases.len(),
        vectors_path.display()
    );

    let program_dir = root.join("target-test");
    let tools = crate::toolchain::provision(crate::toolchain::Needs::ALL)?;
    let toolchain = tools.thumb()?;
    // The child cargo (and its build script) inherit xtask's environment; xtask is
    // single-threaded here.
    std::env::set_var(VECTORS_VAR, &vectors_path);
    toolchain.cargo_build(&program_dir, &["--release"])?;
    let elf = program_dir
        .join("target")
        .join(THUMB_TARGET)
        .join("release")
        .join("zerocal-target-test");

    let output = run_qemu(tools.qemu()?, &elf, QEMU_TIME_LIMIT)?;
    let report = TargetReport::parse(&output);
    if report.done != Some(cases.len()) {
        bail!(
            "the target program did not finish all {} cases (done line: {:?}); its output:\n{output}",
            cases.len(),
            report.done
        );
    }

    let mismatches = compare(&expected, &report.results, TOLERANCE_DEG);
    for m in &mismatches {
        eprintln!("mismatch: {m}");
    }
    if !mismatches.is_empty() {
        bail!(
            "{} result(s) differ between the target (f32) and the host (f64); target output:\n{output}",
            mismatches.len()
        );
    }
    println!(
        "target (f32 on Cortex-M4F, QEMU) agrees with host (f64) on {} cases, {} results, within {TOLERANCE_DEG:e} deg (worst {:.2e} deg)",
        cases.len(),
        expected.len(),
        worst_difference(&expected, &report.results)
    );

    let (calibration_instructions, calibration_ticks) = report
        .calibration
        .ok_or_else(|| anyhow!("no `calibrate` line in the target output"))?;
    let &(solve_ticks, solve_stack_bytes) = report
        .measures
        .get(MEASURED_CASE)
        .ok_or_else(|| anyhow!("no `measure {MEASURED_CASE}` line in the target output"))?;
    let solve_instructions =
        ticks_to_instructions(solve_ticks, calibration_instructions, calibration_ticks)?;
    println!(
        "SysTick: {calibration_ticks} ticks for {calibration_instructions} instructions \
         ({:.1} MHz at 1 instruction/ns under -icount shift=0)",
        calibration_ticks as f64 * 1000.0 / calibration_instructions as f64
    );

    let (usage, _) = crate::build_firmware(root)?;
    let figures = Figures {
        solve_instructions,
        solve_stack_bytes,
        flash_bytes: usage.flash_bytes,
        static_ram_bytes: usage.ram_bytes,
    };
    match figures.against(&BUDGETS) {
        Ok(text) => {
            print!("{text}");
            Ok(())
        }
        Err(text) => bail!("{text}"),
    }
}

/// Instructions from SysTick ticks, by the calibration loop's known instruction count.
///
/// Under `-icount shift=0` QEMU's virtual clock advances 1 ns per instruction and
/// SysTick ticks at the CPU clock, so ticks are proportional to instructions; the loop
/// gives the ratio (168 MHz: 5.95 instructions a tick) and the rounding is ±6
/// instructions.
///
/// # Errors
/// A calibration of zero ticks.
fn ticks_to_instructions(
    ticks: u64,
    calibration_instructions: u64,
    calibration_ticks: u64,
) -> Result<u64> {
    if calibration_ticks == 0 {
        bail!("SysTick did not advance during the calibration loop (is -icount on?)");
    }
    let scaled = u128::from(ticks) * u128::from(calibration_instructions);
    let rounded = (scaled + u128::from(calibration_ticks) / 2) / u128::from(calibration_ticks);
    u64::try_from(rounded).context("instruction count overflows u64")
}

// --- the vectors -------------------------------------------------------------------

/// The sessions: the paper's Table 4 setup (timed), 5° offsets, the `axis` convention
/// with base tilt, two random seeded sessions (one without stage 0) and a degenerate set.
fn simulated_cases() -> Result<Vec<Case>> {
    let table4 = SimRobot::paper(Table4::OFFSETS_DEG, (0.0, 0.0));
    let mut offsets5 = SimRobot::paper([5.0, -5.0, 5.0, -5.0], (0.3, -0.5));
    offsets5.delta_theta2_rad = deg_to_rad(5.0);
    let mut axis_tilt = SimRobot::paper(Table4::OFFSETS_DEG, (0.3, -0.5));
    axis_tilt.delta_theta2_rad = deg_to_rad(-0.08);
    axis_tilt.j2_direction = -1;

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
    let joints = sampler
        .sample(&session.robot, &sensor, config.poses)
        .map_err(|e| anyhow!("sampling the {DEGENERATE_CASE} poses: {e:?}"))?;
    session.poses = joints
        .iter()
        .map(|q| PoseReading {
            joints_rad: *q,
            reading: sensor.read(&session.robot.flange_orientation(q)),
        })
        .collect();
    Ok(to_case(DEGENERATE_CASE, &session, Some(DEGENERATE_ERROR)))
}

/// The session's readings rounded to `f32`, as the pendant holds them.
fn to_case(name: &'static str, s: &SimSession, expected_error: Option<&'static str>) -> Case {
    let tilt = |t: &Tilt<f64>| Tilt::new(t.x_rad as f32, t.y_rad as f32);
    Case {
        name,
        convention: s.sensor.model.convention,
        stage0: s.stage0.map(|r| Reversal {
            first: tilt(&r.first),
            second: tilt(&r.second),
        }),
        stage1: AxisOneTurn {
            before: tilt(&s.stage1.before),
            after: tilt(&s.stage1.after),
            commanded_j2_rad: s.stage1.commanded_j2_rad as f32,
            j2_direction: s.stage1.j2_direction,
        },
        poses: s
            .poses
            .iter()
            .map(|p| PoseReading {
                joints_rad: p.joints_rad.map(|q| q as f32),
                reading: tilt(&p.reading),
            })
            .collect(),
        expected_error,
    }
}

/// The Rust source of the vectors: one static pose array per case, then `SESSIONS`.
///
/// # Errors
/// A non-finite value (it would have no literal).
fn render_vectors(cases: &[Case]) -> Result<String> {
    let mut out = String::from(
        "// Generated by `cargo xtask target-test` from seeded simulations: do not edit,\n\
         // do not commit. Readings and joint angles in rad, rounded to f32.\n\n",
    );
    let _ = writeln!(
        out,
        "/// The session whose fit is timed.\npub const MEASURED: &str = {MEASURED_CASE:?};\n"
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
                "    PoseReading {{ joints_rad: [{}], reading: {} }},",
                joints.join(", "),
                tilt_literal(&p.reading)?
            );
        }
        out.push_str("];\n\n");
    }
    let _ = writeln!(
        out,
        "/// The sessions, solved in this order.\npub static SESSIONS: [Session<'static, f32>; {}] = [",
        cases.len()
    );
    for (i, case) in cases.iter().enumerate() {
        let stage0 = match &case.stage0 {
            Some(r) => format!(
                "Some(Reversal {{ first: {}, second: {} }})",
                tilt_literal(&r.first)?,
                tilt_literal(&r.second)?
            ),
            None => "None".to_owned(),
        };
        let convention = match case.convention {
            Convention::Rpy => "Convention::Rpy",
            Convention::Axis => "Convention::Axis",
        };
        let _ = writeln!(
            out,
            "    Session {{\n        name: {:?},\n        convention: {convention},\n        stage0: {stage0},\n        \
             stage1: AxisOneTurn {{ before: {}, after: {}, commanded_j2_rad: {}, j2_direction: {} }},\n        \
             poses: &POSES_{i},\n    }},",
            case.name,
            tilt_literal(&case.stage1.before)?,
            tilt_literal(&case.stage1.after)?,
            literal(case.stage1.commanded_j2_rad)?,
            case.stage1.j2_direction,
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

// --- the host's solution -----------------------------------------------------------

/// What one stage of one case gave: numbers (deg) or a named refusal.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// The stage's numbers, in output order (deg).
    Numbers(Vec<f64>),
    /// `Variant [params]`, as the output line names it.
    Error(String),
}

/// Results keyed by (case, stage), stage being `stage0`, `stage1` or `fit`.
pub type Results = BTreeMap<(String, String), Value>;

/// The `f64` solution of each case's `f32` data, with the same pipeline as the target.
///
/// # Errors
/// When a case does not give what it was built for (numbers, or its named refusal):
/// then the vectors, not the target, are wrong.
fn host_results(cases: &[Case]) -> Result<Results> {
    let mut results = Results::new();
    for case in cases {
        let tilt = |t: &Tilt<f32>| Tilt::new(f64::from(t.x_rad), f64::from(t.y_rad));
        let poses: Vec<PoseReading<f64>> = case
            .poses
            .iter()
            .map(|p| PoseReading {
                joints_rad: p.joints_rad.map(f64::from),
                reading: tilt(&p.reading),
            })
            .collect();
        let session = Session {
            name: case.name,
            convention: case.convention,
            stage0: case.stage0.map(|r| Reversal {
                first: tilt(&r.first),
                second: tilt(&r.second),
            }),
            stage1: AxisOneTurn {
                before: tilt(&case.stage1.before),
                after: tilt(&case.stage1.after),
                commanded_j2_rad: f64::from(case.stage1.commanded_j2_rad),
                j2_direction: case.stage1.j2_direction,
            },
            poses: &poses,
        };
        let fit = solve_host(&session, &mut results);
        let name = case.name;
        match (case.expected_error, fit) {
            (None, Some(Value::Numbers(_))) => {}
            (Some(want), Some(Value::Error(got))) if want == got => {}
            (want, got) => bail!(
                "case {name}: the host's f64 fit gave {got:?}, the case is built to give {}",
                want.map_or_else(|| "numbers".to_owned(), |w| format!("error {w}"))
            ),
        }
    }
    Ok(results)
}

/// Solves one session in `f64`, recording each stage's value; returns the fit's.
fn solve_host(session: &Session<'_, f64>, results: &mut Results) -> Option<Value> {
    let mut record = |stage: &str, value: Value| {
        results.insert((session.name.to_owned(), stage.to_owned()), value.clone());
        value
    };
    let bias = match pipeline::stage0(session) {
        Ok(bias) => bias,
        Err(e) => {
            record("stage0", Value::Error(StageErrorWords(&e).to_string()));
            return None;
        }
    };
    if let Some(b) = &bias {
        record(
            "stage0",
            Value::Numbers(vec![rad_to_deg(b.x_rad), rad_to_deg(b.y_rad)]),
        );
    }
    let stage1 = match pipeline::stage1(session, bias.as_ref()) {
        Ok(s) => s,
        Err(e) => {
            record("stage1", Value::Error(StageErrorWords(&e).to_string()));
            return None;
        }
    };
    record(
        "stage1",
        Value::Numbers(
            [
                stage1.base_tilt.alpha_rad,
                stage1.base_tilt.beta_rad,
                stage1.bias_y_rad,
                stage1.delta_theta2_rad,
            ]
            .map(rad_to_deg)
            .to_vec(),
        ),
    );
    let (model, config) = pipeline::stage2_setup(session, bias.as_ref(), &stage1);
    let value = match zerocal_core::fit(&model, session.poses, &config) {
        Ok(r) => Value::Numbers(r.offsets_rad.map(rad_to_deg).to_vec()),
        Err(e) => Value::Error(FitErrorWords(&e).to_string()),
    };
    Some(record("fit", value))
}

// --- the target's output -----------------------------------------------------------

/// What the target program printed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TargetReport {
    /// `case` lines.
    pub results: Results,
    /// `calibrate <instructions> <ticks>`.
    pub calibration: Option<(u64, u64)>,
    /// `measure <case> ticks <n> stack <bytes>`: (ticks, bytes) per case.
    pub measures: BTreeMap<String, (u64, u64)>,
    /// `done <cases>`.
    pub done: Option<usize>,
}

impl TargetReport {
    /// Reads the lines it knows; anything else (QEMU's own messages) is ignored, and a
    /// malformed known line is recorded as an error value so the comparison shows it.
    pub fn parse(output: &str) -> TargetReport {
        let mut report = TargetReport::default();
        for line in output.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            match words.as_slice() {
                ["case", name, stage, rest @ ..] => {
                    let value = match rest {
                        ["error", words @ ..] => Value::Error(words.join(" ")),
                        numbers => numbers
                            .iter()
                            .map(|w| w.parse::<f64>())
                            .collect::<Result<Vec<_>, _>>()
                            .map_or_else(
                                |_| Value::Error(format!("unparsable line `{line}`")),
                                Value::Numbers,
                            ),
                    };
                    report
                        .results
                        .insert(((*name).to_owned(), (*stage).to_owned()), value);
                }
                ["calibrate", instructions, ticks] => {
                    if let (Ok(i), Ok(t)) = (instructions.parse(), ticks.parse()) {
                        report.calibration = Some((i, t));
                    }
                }
                ["measure", name, "ticks", ticks, "stack", bytes] => {
                    if let (Ok(t), Ok(b)) = (ticks.parse(), bytes.parse()) {
                        report.measures.insert((*name).to_owned(), (t, b));
                    }
                }
                ["done", cases] => report.done = cases.parse().ok(),
                _ => {}
            }
        }
        report
    }
}

/// How a reported result differs from the expected one.
#[derive(Clone, Debug, PartialEq)]
pub enum Mismatch {
    /// Expected, not reported.
    Missing {
        /// (case, stage).
        key: (String, String),
    },
    /// Reported, not expected.
    Unexpected {
        /// (case, stage).
        key: (String, String),
    },
    /// Numbers against a refusal, or a different count of numbers.
    Shape {
        /// (case, stage).
        key: (String, String),
        /// Host's.
        expected: Value,
        /// Target's.
        reported: Value,
    },
    /// A number beyond the tolerance.
    Number {
        /// (case, stage).
        key: (String, String),
        /// Position in the line.
        index: usize,
        /// Host's (deg).
        expected: f64,
        /// Target's (deg).
        reported: f64,
    },
    /// A different refusal.
    Error {
        /// (case, stage).
        key: (String, String),
        /// Host's.
        expected: String,
        /// Target's.
        reported: String,
    },
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Mismatch::Missing { key } => write!(f, "case {} {}: no result", key.0, key.1),
            Mismatch::Unexpected { key } => {
                write!(f, "case {} {}: result not expected", key.0, key.1)
            }
            Mismatch::Shape {
                key,
                expected,
                reported,
            } => write!(
                f,
                "case {} {}: host {expected:?}, target {reported:?}",
                key.0, key.1
            ),
            Mismatch::Number {
                key,
                index,
                expected,
                reported,
            } => write!(
                f,
                "case {} {} value {index}: host {expected:.9} deg, target {reported:.9} deg, difference {:.2e} deg",
                key.0,
                key.1,
                (reported - expected).abs()
            ),
            Mismatch::Error {
                key,
                expected,
                reported,
            } => write!(
                f,
                "case {} {}: host refuses with {expected}, target with {reported}",
                key.0, key.1
            ),
        }
    }
}

/// Compares the target's results with the host's: every expected result present,
/// nothing else, numbers within `tolerance_deg` (a NaN never is), refusals identical.
pub fn compare(expected: &Results, reported: &Results, tolerance_deg: f64) -> Vec<Mismatch> {
    let mut mismatches = Vec::new();
    for (key, want) in expected {
        let Some(got) = reported.get(key) else {
            mismatches.push(Mismatch::Missing { key: key.clone() });
            continue;
        };
        match (want, got) {
            (Value::Numbers(w), Value::Numbers(g)) if w.len() == g.len() => {
                for (index, (&e, &r)) in w.iter().zip(g).enumerate() {
                    // A NaN compares false, so it is never within.
                    let within = (r - e).abs() <= tolerance_deg;
                    if !within {
                        mismatches.push(Mismatch::Number {
                            key: key.clone(),
                            index,
                            expected: e,
                            reported: r,
                        });
                    }
                }
            }
            (Value::Error(w), Value::Error(g)) => {
                if w != g {
                    mismatches.push(Mismatch::Error {
                        key: key.clone(),
                        expected: w.clone(),
                        reported: g.clone(),
                    });
                }
            }
            _ => mismatches.push(Mismatch::Shape {
                key: key.clone(),
                expected: want.clone(),
                reported: got.clone(),
            }),
        }
    }
    for key in reported.keys() {
        if !expected.contains_key(key) {
            mismatches.push(Mismatch::Unexpected { key: key.clone() });
        }
    }
    mismatches
}

/// The largest difference between matching numbers (deg), for the log.
fn worst_difference(expected: &Results, reported: &Results) -> f64 {
    let mut worst = 0.0_f64;
    for (key, want) in expected {
        if let (Value::Numbers(w), Some(Value::Numbers(g))) = (want, reported.get(key)) {
            for (e, r) in w.iter().zip(g) {
                worst = worst.max((r - e).abs());
            }
        }
    }
    worst
}

// --- QEMU --------------------------------------------------------------------------

/// Runs the program in QEMU and returns its output (stdout, then stderr).
///
/// # Errors
/// QEMU cannot start, the program exits with failure, or it runs past `limit` (then it
/// is killed).
fn run_qemu(qemu: &Path, elf: &Path, limit: Duration) -> Result<String> {
    let mut command = Command::new(qemu);
    command
        .args([
            "-machine",
            "netduinoplus2",
            "-cpu",
            "cortex-m4",
            "-nographic",
        ])
        .args(["-semihosting-config", "enable=on,target=native"])
        // Virtual time = executed instructions (1 ns each): SysTick counts them.
        .args(["-icount", "shift=0"])
        .arg("-kernel")
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    eprintln!("xtask: {command:?}");
    let mut child = command.spawn().context("cannot start qemu-system-arm")?;
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut pipe) = pipe {
                // A read error leaves what was read so far: the output is diagnostics.
                let _ = pipe.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let stdout = drain(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let stderr = drain(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );

    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().context("waiting for qemu-system-arm")? {
            break Some(status);
        }
        if start.elapsed() > limit {
            // Kill this child (by its handle), then reap it.
            child.kill().context("killing qemu-system-arm")?;
            child.wait().context("reaping qemu-system-arm")?;
            break None;
        }
        thread::sleep(Duration::from_millis(20));
    };
    let join = |h: thread::JoinHandle<String>| h.join().unwrap_or_default();
    let output = format!("{}{}", join(stdout), join(stderr));
    match status {
        None => bail!(
            "the target program hung: killed after {} s; its output:\n{output}",
            limit.as_secs()
        ),
        Some(status) if !status.success() => {
            bail!("the target program failed ({status}); its output:\n{output}")
        }
        Some(_) => Ok(output),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(case: &str, stage: &str) -> (String, String) {
        (case.to_owned(), stage.to_owned())
    }

    fn expected() -> Results {
        let mut r = Results::new();
        r.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06, -0.04, 0.07]),
        );
        r.insert(
            key("degenerate", "fit"),
            Value::Error("RankDeficient j3+j5".to_owned()),
        );
        r
    }

    #[test]
    fn a_change_within_the_tolerance_passes_and_beyond_it_fails() {
        let host = expected();
        let mut target = host.clone();
        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05 + 1.9e-5, 0.06, -0.04 - 1.9e-5, 0.07]),
        );
        assert_eq!(compare(&host, &target, TOLERANCE_DEG), vec![]);

        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06 + 2.1e-5, -0.04, 0.07]),
        );
        let m = compare(&host, &target, TOLERANCE_DEG);
        assert!(
            matches!(m.as_slice(), [Mismatch::Number { index: 1, .. }]),
            "{m:?}"
        );

        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06, f64::NAN, 0.07]),
        );
        assert_eq!(compare(&host, &target, TOLERANCE_DEG).len(), 1);
    }

    #[test]
    fn a_different_or_missing_refusal_fails() {
        let host = expected();
        let mut target = host.clone();
        target.insert(
            key("degenerate", "fit"),
            Value::Error("RankDeficient j4+j6".to_owned()),
        );
        assert!(matches!(
            compare(&host, &target, TOLERANCE_DEG).as_slice(),
            [Mismatch::Error { .. }]
        ));
        target.insert(
            key("degenerate", "fit"),
            Value::Numbers(vec![0.0, 0.0, 0.0, 0.0]),
        );
        assert!(matches!(
            compare(&host, &target, TOLERANCE_DEG).as_slice(),
            [Mismatch::Shape { .. }]
        ));
        target.remove(&key("degenerate", "fit"));
        target.insert(key("extra", "stage0"), Value::Numbers(vec![0.0, 0.0]));
        let m = compare(&host, &target, TOLERANCE_DEG);
        assert!(
            matches!(
                m.as_slice(),
                [Mismatch::Missing { .. }, Mismatch::Unexpected { .. }]
            ),
            "{m:?}"
        );
    }

    #[test]
    fn parses_the_target_output() {
        let output = "calibrate 1000000 168000\n\
                      case table4 stage0 0.01 -0.02\n\
                      case table4 fit 0.05000001 0.06 -0.04 0.07\n\
                      measure table4 ticks 50000 stack 2048\n\
                      case degenerate fit error RankDeficient j3+j5\n\
                      case broken fit 0.1 zero\n\
                      QEMU noise\n\
                      done 2\n";
        let r = TargetReport::parse(output);
        assert_eq!(r.calibration, Some((1_000_000, 168_000)));
        assert_eq!(r.measures.get("table4"), Some(&(50_000, 2048)));
        assert_eq!(r.done, Some(2));
        assert_eq!(
            r.results.get(&key("degenerate", "fit")),
            Some(&Value::Error("RankDeficient j3+j5".to_owned()))
        );
        assert_eq!(
            r.results.get(&key("table4", "stage0")),
            Some(&Value::Numbers(vec![0.01, -0.02]))
        );
        assert!(matches!(
            r.results.get(&key("broken", "fit")),
            Some(Value::Error(_))
        ));
    }

    #[test]
    fn converts_ticks_with_the_calibration() {
        assert_eq!(
            ticks_to_instructions(168, 1_000_000, 168_000).ok(),
            Some(1000)
        );
        assert!(ticks_to_instructions(1, 1, 0).is_err());
    }

    #[test]
    fn budgets_fail_when_exceeded() {
        assert!(BUDGETS.against(&BUDGETS).is_ok());
        let over = Figures {
            solve_instructions: BUDGETS.solve_instructions + 1,
            ..BUDGETS
        };
        assert!(over.against(&BUDGETS).is_err());
    }

    #[test]
    fn vectors_render_exact_literals() {
        let x = 0.1_f32 + f32::EPSILON;
        let text = literal(x).unwrap_or_default();
        let parsed: f32 = text.trim_end_matches("_f32").parse().unwrap_or(f32::NAN);
        assert_eq!(parsed.to_bits(), x.to_bits());
        assert!(literal(f32::NAN).is_err());
    }
}
