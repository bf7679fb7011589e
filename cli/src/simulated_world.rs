//! `zerocal simulate` in the real world (the default): a production SCL3300 unit and a
//! robot that sags, has backlash and repeats only so well, every source switchable,
//! the session planned and solved exactly as the pendant does (two captures per pose,
//! the closing reversal), its k = 2 budget printed beside the hidden truth. And
//! `zerocal error-table`: the same sessions by the hundred, one error source at a time,
//! with and without the compensation (the README's table).

use crate::args::{CountIn, RealIn, SEED};
use crate::error::CliError;
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use zerocal_core::report::Verdict;
use zerocal_core::session::{budget, solve, Budget, BudgetTerm, SessionSolution, SESSION_JOINTS};
use zerocal_profile::Profile;
use zerocal_sim::montecarlo::{self, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::sensor::SensorSources;
use zerocal_sim::world::{BracketKnowledge, RealSession, WorldConfig};

/// An error source of the simulated world.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Source {
    /// Per-axis sensitivity error (±0.7 %).
    Sensitivity,
    /// Cross-axis sensitivity (±1 % each pair).
    CrossAxis,
    /// Offset (±20 mg, Y −25/+20 mg).
    Offset,
    /// Offset drift with temperature (±0.009 °/K).
    Drift,
    /// The box warming 3 K over the session.
    Warming,
    /// Non-linearity (±1 mg over ±1 g, cubic).
    Nonlinearity,
    /// Output noise behind the 10 Hz filter (0.08/0.06 mg).
    Noise,
    /// Angle and temperature quantisation.
    Quantisation,
    /// Gravity sag of joints 2-3 (0.01-0.02° at full lever).
    Sag,
    /// Gear backlash (lost motion up to 1 arc min).
    Backlash,
    /// Repeatability (0.0015° per joint, 1σ).
    Repeatability,
    /// Joint axes off the drawing's (0.01-0.05° per perpendicular pair, 0.01-0.5° per
    /// parallel pair).
    Misalignment,
    /// Transmission error (0.005-0.03° peak to peak per joint, and once per turn
    /// 0.005-0.025° on joints 4 and 6).
    Transmission,
    /// Joints 4-6 giving under the wrist's load (0.01-0.03° at full lever).
    WristCompliance,
}

impl Source {
    /// Every source, in table order.
    pub const ALL: [Source; 14] = [
        Source::Noise,
        Source::Quantisation,
        Source::Sensitivity,
        Source::CrossAxis,
        Source::Offset,
        Source::Nonlinearity,
        Source::Drift,
        Source::Warming,
        Source::Sag,
        Source::Backlash,
        Source::Repeatability,
        Source::Misalignment,
        Source::Transmission,
        Source::WristCompliance,
    ];

    /// What the table calls it.
    pub fn label(self) -> &'static str {
        match self {
            Source::Sensitivity => "sensitivity error per axis, +/-0.7 %",
            Source::CrossAxis => "cross-axis sensitivity, +/-1 % each pair",
            Source::Offset => "offset, +/-20 mg (1.15 deg)",
            Source::Drift => "offset drift +/-0.009 deg/K (box at constant temperature)",
            Source::Warming => "drift with the box warming 3 K over the session",
            Source::Nonlinearity => "non-linearity, +/-1 mg over +/-1 g",
            Source::Noise => "noise 0.08/0.06 mg behind the 10 Hz filter",
            Source::Quantisation => "angle output quantised at 0.0055 deg/LSB",
            Source::Sag => "gravity sag of joints 2-3, 0.01-0.02 deg at full lever",
            Source::Backlash => "backlash, lost motion up to 1 arc min",
            Source::Repeatability => "robot repeatability 0.0015 deg per joint",
            Source::Misalignment => "axis misalignment 0.01-0.05 (parallel 0.5) deg",
            Source::Transmission => "transmission error 0.005-0.03 deg p-p",
            Source::WristCompliance => "wrist compliance 0.01-0.03 deg at full lever",
        }
    }
}

/// The world with `on` switched on and everything else off (`None`: all on).
pub fn world_with(on: Option<&[Source]>) -> WorldConfig {
    let has = |s: Source| on.is_none_or(|list| list.contains(&s));
    let mut w = WorldConfig::real();
    w.sensor = SensorSources {
        sensitivity: has(Source::Sensitivity),
        cross_axis: has(Source::CrossAxis),
        offset: has(Source::Offset),
        drift: has(Source::Drift) || has(Source::Warming),
        nonlinearity: has(Source::Nonlinearity),
        noise: has(Source::Noise),
        quantisation: has(Source::Quantisation),
    };
    w.robot = RobotSources {
        sag: has(Source::Sag),
        backlash: has(Source::Backlash),
        repeatability: has(Source::Repeatability),
        misalignment: has(Source::Misalignment),
        transmission: has(Source::Transmission),
        wrist_compliance: has(Source::WristCompliance),
    };
    if !has(Source::Warming) {
        w.warming_k = 0.0;
    }
    w
}

/// Arguments shared by the real-world runs.
#[derive(Args, Debug, Clone)]
pub struct WorldArgs {
    /// Switch these error sources off (comma-separated); all are on by default.
    #[arg(long, value_delimiter = ',', value_name = "SOURCES")]
    pub without: Vec<Source>,
    /// A loose flange bracket: it seats anew within ± this at every capture (0: tight).
    /// Range: [0, 1] deg.
    #[arg(long, default_value_t = 0.0, value_name = "DEG", value_parser = RealIn::closed(0.0, 1.0, "deg"))]
    pub loose_bracket_deg: f64,
    /// How far the box warms over the session (the stated figure: 3). Range: [0, 60] K.
    #[arg(long, default_value_t = 3.0, value_name = "K", value_parser = RealIn::closed(0.0, 60.0, "K"))]
    pub warming_k: f64,
    /// Each bracket as made turns the pendant within ± this about its x and y (0:
    /// exact). Range: [0, 1] deg.
    #[arg(long, default_value_t = 0.0, value_name = "DEG", value_parser = RealIn::closed(0.0, 1.0, "deg"))]
    pub mount_tolerance_deg: f64,
    /// Each bracket's yaw (about the pendant's z, not calibrated) within ± this.
    /// Range: [0, 1] deg.
    #[arg(long, default_value_t = 0.0, value_name = "DEG", value_parser = RealIn::closed(0.0, 1.0, "deg"))]
    pub bracket_yaw_deg: f64,
    /// Each clip-on seats the bracket anew within ± this about each axis. Range:
    /// [0, 0.1] deg.
    #[arg(long, default_value_t = 0.0, value_name = "DEG", value_parser = RealIn::closed(0.0, 0.1, "deg"))]
    pub seat_repeatability_deg: f64,
    /// What the session knows of its brackets: `exact` (their turns, exactly),
    /// `calibrated` (each calibrated on its reference as docs/mounting.md says) or
    /// `uncalibrated`.
    #[arg(long, value_enum, default_value_t = BracketsArg::Exact)]
    pub brackets: BracketsArg,
    /// Skip the closing reversal (the bias' drift is then unmeasured).
    #[arg(long)]
    pub no_closing_reversal: bool,
    /// Also write the simulated session as the pendant exports it, for `zerocal session`
    /// to read (a rehearsal before a real robot).
    #[arg(long, value_name = "FILE")]
    pub export: Option<std::path::PathBuf>,
    /// Another session of the robot `--seed` draws, with the same pendant and brackets
    /// (their calibrations kept): its noise, seats and bench drawn from this seed. For
    /// rehearsing a history, a restore and a check. Range: [0, 18446744073709551615].
    #[arg(long, value_name = "SEED", value_parser = crate::args::SEED)]
    pub again: Option<u64>,
    /// With `--again`: joint J's reading reads DEG more at the same arm position than at
    /// the first session, as after a motor swap (J 2-6; repeat for more).
    #[arg(long = "zero-moved", value_name = "J=DEG", value_parser = parse_zero_moved, requires = "again")]
    pub zero_moved: Vec<(usize, f64)>,
    /// With `--again`: the offsets entered into the controller since the first session,
    /// in the model's terms: Δθ2..Δθ6 in deg, the `offset_deg` (j2-j6) `zerocal session`
    /// printed, not the controller's dq (a correct entry of dq moves each model zero by
    /// Δθ, FANUC's J2/J3 coupling included).
    #[arg(long, value_name = "DEG,DEG,DEG,DEG,DEG", value_parser = parse_entered, allow_hyphen_values = true, requires = "again")]
    pub entered: Option<[f64; 5]>,
}

/// Five offsets, comma-separated, each within ±10°.
fn parse_entered(text: &str) -> Result<[f64; 5], String> {
    let values = text
        .split(',')
        .map(|v| RealIn::closed(-10.0, 10.0, "deg").check(v.trim()))
        .collect::<Result<Vec<f64>, String>>()?;
    <[f64; 5]>::try_from(values)
        .map_err(|v| format!("'{text}': five offsets (joints 2-6), not {}", v.len()))
}

/// `J=DEG`: a joint 2-6 and a move within ±10°.
fn parse_zero_moved(text: &str) -> Result<(usize, f64), String> {
    let (j, d) = text
        .split_once('=')
        .ok_or_else(|| format!("'{text}': give J=DEG, e.g. 3=1.0"))?;
    let joint: usize = j
        .trim()
        .parse()
        .ok()
        .filter(|j| (2..=6).contains(j))
        .ok_or_else(|| format!("'{text}': the joint is 2-6"))?;
    let deg = RealIn::closed(-10.0, 10.0, "deg").check(d.trim())?;
    Ok((joint, deg))
}

impl WorldArgs {
    /// The change between the first session and `--again`'s, on the simulated robot:
    /// a moved zero makes the reading larger at the same position (Δθ = true − reading
    /// falls), an entered offset moves the reading by itself (Δθ falls by it).
    pub fn change(&self) -> impl Fn(&mut zerocal_sim::robot::SimRobot) + '_ {
        move |r| {
            for (joint, deg) in &self.zero_moved {
                if let Some(o) = r.offsets_rad.get_mut(joint - 1) {
                    *o -= deg.to_radians();
                }
            }
            for (o, e) in r.offsets_rad[1..]
                .iter_mut()
                .zip(self.entered.iter().flatten())
            {
                *o -= e.to_radians();
            }
        }
    }
}

/// `--brackets`: what the simulated session knows of its brackets.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum BracketsArg {
    /// Their turns, exactly.
    Exact,
    /// Calibrated on their references.
    Calibrated,
    /// Never calibrated.
    Uncalibrated,
}

impl WorldArgs {
    /// The world these flags describe.
    pub fn world(&self) -> WorldConfig {
        let on: Vec<Source> = Source::ALL
            .into_iter()
            .filter(|s| !self.without.contains(s))
            .collect();
        let mut w = world_with(Some(&on));
        if on.contains(&Source::Warming) {
            w.warming_k = self.warming_k;
        }
        w.loose_bracket_deg = self.loose_bracket_deg;
        w.mount_tolerance_deg = self.mount_tolerance_deg;
        w.bracket_yaw_deg = self.bracket_yaw_deg;
        w.seat_repeatability_deg = self.seat_repeatability_deg;
        w.brackets = match self.brackets {
            BracketsArg::Exact => BracketKnowledge::Exact,
            BracketsArg::Calibrated => BracketKnowledge::Calibrated,
            BracketsArg::Uncalibrated => BracketKnowledge::Uncalibrated,
        };
        w.closing_reversal = !self.no_closing_reversal;
        w
    }
}

/// One real-world session, solved as the pendant does.
pub struct RealRun {
    /// The profile.
    pub profile: Profile,
    /// The session and its truth.
    pub session: RealSession,
    /// The solution.
    pub solution: SessionSolution<f64>,
    /// Its budget.
    pub budget: Budget<f64>,
    /// The verdict.
    pub verdict: Verdict,
}

/// Simulates and solves one session.
///
/// # Errors
/// An unknown robot (status 2), a plan or a session refused (status 3).
pub fn run_session(
    robot: &str,
    world: &WorldConfig,
    poses: usize,
    seed: u64,
    again: Option<&WorldArgs>,
) -> Result<RealRun, CliError> {
    let profile = crate::robot::load(robot)?;
    let (plan, fit) = montecarlo::setup(&profile, Method::Compensated, poses)
        .map_err(|e| CliError::Refused(format!("plan: {e}")))?;
    let first = RealSession::simulate(&profile, &plan, world, seed);
    let session = match again {
        Some(args) => match args.again {
            Some(n) => first.again(&profile, &plan, world, n, args.change()),
            None => first,
        },
        None => first,
    };
    let readings = session.readings(&profile, world);
    if session.outside_range > 0 {
        return Err(CliError::Refused(format!(
            "{} capture(s) left the SCL3300's mode-4 range of +/-10 deg: the pendant refuses them",
            session.outside_range
        )));
    }
    let outcome = solve(&readings, &fit);
    let solution = outcome
        .result
        .map_err(|e| CliError::Refused(e.to_string()))?;
    let verdict = Verdict::judge(&solution.fit, &fit, outcome.stage1.as_ref());
    let budget = budget(
        &solution,
        &session.poses,
        &world.budget_inputs(&profile, &fit, &session.brackets),
    );
    Ok(RealRun {
        profile,
        session,
        solution,
        budget,
        verdict,
    })
}

/// The report of one real-world session beside its truth.
pub fn render(run: &RealRun, world: &WorldConfig, seed: u64) -> String {
    let mut out = String::new();
    let s = &run.solution;
    let truth = run.session.truth_rad();
    let off: Vec<&str> = Source::ALL
        .iter()
        .filter(|src| !source_on(world, **src))
        .map(|src| src.label())
        .collect();
    let _ = writeln!(
        out,
        "zerocal simulate: {} ({}), seed {seed}, real world: {}",
        run.profile.name,
        run.profile.title,
        if off.is_empty() {
            "every error source on".to_owned()
        } else {
            format!("without {}", off.join("; "))
        }
    );
    let _ = writeln!(
        out,
        "{} captures ({} poses, each from both sides of the backlash), residual RMS {:.5} deg, condition number {:.1}",
        run.session.poses.len(),
        s.fit.poses,
        s.fit.residual_rms_rad.to_degrees(),
        s.fit.condition_number
    );
    let _ = writeln!(
        out,
        "\njoint  found_deg   truth_deg   error_deg   1sigma_deg  U(k=2)_deg  |error|/U"
    );
    for (k, t) in truth.iter().enumerate().take(SESSION_JOINTS) {
        let f = s.offsets_rad[k].to_degrees();
        let t = t.to_degrees();
        let u = run.budget.expanded_rad[k].to_degrees();
        let _ = writeln!(
            out,
            "j{}     {f:+.5}    {t:+.5}    {:+.5}    {:.5}     {u:.5}     {:.2}",
            k + 2,
            f - t,
            s.sigma_rad()[k].to_degrees(),
            (f - t).abs() / u
        );
    }
    let _ = writeln!(out, "\nbudget (standard uncertainties, deg):");
    for (term, u) in BudgetTerm::ALL.iter().zip(&run.budget.terms_rad) {
        let cols: Vec<String> = u.iter().map(|v| format!("{:.5}", v.to_degrees())).collect();
        let _ = writeln!(out, "  {:<42} {}", term.name(), cols.join("  "));
    }
    if run.verdict.is_pass() {
        let _ = writeln!(out, "verdict: PASS");
    }
    for w in &run.verdict.warnings {
        let _ = writeln!(out, "verdict: WARN {w}");
    }
    out
}

fn source_on(world: &WorldConfig, s: Source) -> bool {
    match s {
        Source::Sensitivity => world.sensor.sensitivity,
        Source::CrossAxis => world.sensor.cross_axis,
        Source::Offset => world.sensor.offset,
        Source::Drift => world.sensor.drift,
        Source::Warming => world.warming_k > 0.0,
        Source::Nonlinearity => world.sensor.nonlinearity,
        Source::Noise => world.sensor.noise,
        Source::Quantisation => world.sensor.quantisation,
        Source::Sag => world.robot.sag,
        Source::Backlash => world.robot.backlash,
        Source::Repeatability => world.robot.repeatability,
        Source::Misalignment => world.robot.misalignment,
        Source::Transmission => world.robot.transmission,
        Source::WristCompliance => world.robot.wrist_compliance,
    }
}

/// Arguments of `zerocal error-table`.
#[derive(Args, Debug, Clone)]
pub struct ErrorTableArgs {
    /// Robot profiles (comma-separated).
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "NAMES",
        default_value = "paper-wrist"
    )]
    pub robot: Vec<String>,
    /// Sessions per row. Range: [1, 100000].
    #[arg(long, default_value_t = 30, value_parser = CountIn::<usize>::new(1, 100_000))]
    pub sessions: usize,
    /// Stage-2 poses per session. Range: [8, 48].
    #[arg(long, default_value_t = DEFAULT_POSES, value_parser = CountIn::<usize>::new(8, 48))]
    pub poses: usize,
    /// Seed of the first session. Range: [0, 18446744073709551615].
    #[arg(long, default_value_t = 1, value_parser = SEED)]
    pub seed: u64,
}

/// Runs `zerocal error-table`.
///
/// # Errors
/// An unknown robot, a plan refused.
pub fn error_table(args: &ErrorTableArgs) -> Result<String, CliError> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "worst error over j2-j6 and {} sessions per row (deg); `after`: 95th percentile of each session's worst joint, its worst, and sessions with every joint within 0.005 deg; `k=2 cov`: the least share over j2-j6 of sessions whose error the k = 2 budget covers; `TCP/best`: mean TCP error (200 poses, 0.1 m tool) after entering the offsets over the best zero-only correction's (a joint gravity cannot tell from its parallel twin is judged by their sum)",
        args.sessions
    );
    for name in &args.robot {
        let profile = crate::robot::load(name)?;
        let _ = writeln!(out, "\n{} ({})", profile.name, profile.title);
        let _ = writeln!(
            out,
            "{:<58} {:>10} {:>10} {:>10} {:>8} {:>8} {:>7} {:>9}",
            "error source switched on",
            "before",
            "after p95",
            "after max",
            "<=0.005",
            "refused",
            "k=2 cov",
            "TCP/best"
        );
        let mut rows: Vec<(String, WorldConfig, bool)> = vec![(
            "none (noise and quantisation only)".to_owned(),
            world_with(Some(&[Source::Noise, Source::Quantisation])),
            false,
        )];
        for s in Source::ALL.iter().skip(2) {
            let mut world = world_with(Some(&[Source::Noise, Source::Quantisation, *s]));
            if *s == Source::Drift {
                world.warming_k = 0.0;
            }
            rows.push((s.label().to_owned(), world, false));
        }
        rows.push(("all together".to_owned(), world_with(None), true));
        rows.push((
            "all together, the FANUC R-2000iC as a tracker measured it".to_owned(),
            WorldConfig::fanuc_as_measured(),
            true,
        ));
        for (label, world, with_tcp) in rows {
            let mut cells = Vec::new();
            let mut refusals: Vec<String> = Vec::new();
            let mut compensated = Vec::new();
            for method in [Method::Uncompensated, Method::Compensated] {
                let (plan, fit) = montecarlo::setup(&profile, method, args.poses)
                    .map_err(|e| CliError::Refused(format!("{name}: plan: {e}")))?;
                let w = montecarlo::world_for(method, world);
                let tcp = with_tcp && method == Method::Compensated;
                let outcomes = montecarlo::run_with_tcp(
                    &profile,
                    &plan,
                    &w,
                    &fit,
                    args.sessions,
                    args.seed,
                    tcp,
                );
                if method == Method::Compensated {
                    refusals = outcomes
                        .iter()
                        .filter_map(|o| {
                            o.result
                                .as_ref()
                                .err()
                                .map(|e| format!("seed {}: {e}", o.seed))
                        })
                        .collect();
                }
                let worst: Vec<f64> = outcomes
                    .iter()
                    .map(|o| {
                        o.errors_deg().map_or(f64::INFINITY, |e| {
                            e.iter().fold(0.0f64, |m, v| m.max(v.abs()))
                        })
                    })
                    .collect();
                cells.push(worst);
                if method == Method::Compensated {
                    compensated = outcomes;
                }
            }
            let summary = montecarlo::summarise(&compensated, 0.005);
            let coverage = summary.covered.iter().copied().fold(1.0f64, f64::min);
            let ratios: Vec<f64> = compensated
                .iter()
                .filter_map(|o| o.tcp.map(|t| t.mean_after_mm / t.mean_best_mm))
                .collect();
            let tcp_cell = if ratios.is_empty() {
                "-".to_owned()
            } else {
                format!("{:.3}", ratios.iter().sum::<f64>() / ratios.len() as f64)
            };
            // Refused sessions (NaN) give no error: they are counted on their own.
            let max = |v: &[f64]| {
                v.iter()
                    .cloned()
                    .filter(|x| x.is_finite())
                    .fold(0.0f64, f64::max)
            };
            let mut after: Vec<f64> = cells[1].iter().cloned().filter(|x| x.is_finite()).collect();
            after.sort_by(f64::total_cmp);
            let p95 = after
                .get(((after.len() as f64 * 0.95).ceil() as usize).saturating_sub(1))
                .copied()
                .unwrap_or(f64::NAN);
            let ok = cells[1].iter().filter(|w| **w <= 0.005).count() as f64
                / cells[1].len().max(1) as f64;
            let fmt = |v: f64| {
                if v.is_finite() {
                    format!("{v:.4}")
                } else {
                    "refused".to_owned()
                }
            };
            let _ = writeln!(
                out,
                "{:<58} {:>10} {:>10} {:>10} {:>7.1}% {:>8} {:>6.1}% {:>9}",
                label,
                fmt(max(&cells[0])),
                fmt(p95),
                fmt(max(&cells[1])),
                ok * 100.0,
                refusals.len(),
                coverage * 100.0,
                tcp_cell
            );
            for r in &refusals {
                let _ = writeln!(out, "    refused, {r}");
            }
        }
    }
    Ok(out)
}

/// The ISO 9283-style test on the robot: flange position error at seeded random poses
/// within its limits, with the hidden offsets and after entering the found ones.
///
/// # Errors
/// A profile without lengths (no positions to test).
pub fn accuracy(
    run: &RealRun,
    points: usize,
    seed: u64,
) -> Result<zerocal_sim::positioning::AccuracyReport, CliError> {
    let p = &run.profile;
    let limits = core::array::from_fn(|k| (p.joints[k].min_deg, p.joints[k].max_deg));
    let mut found = [0.0; 6];
    found[1..].copy_from_slice(&run.solution.offsets_rad);
    zerocal_sim::positioning::accuracy_test(
        &p.title,
        &p.arm,
        &limits,
        &run.session.robot.offsets_rad,
        &found,
        points,
        seed,
    )
    .map_err(|e| CliError::Refused(format!("accuracy test: {e}")))
}

/// Writes the plots of `--plot DIR`: the positioning errors and the fit's residuals.
///
/// # Errors
/// The directory cannot be written.
pub fn plots(
    dir: &std::path::Path,
    run: &RealRun,
    report: &zerocal_sim::positioning::AccuracyReport,
) -> Result<Vec<std::path::PathBuf>, CliError> {
    let merged = zerocal_core::session::merge_repeats(&run.session.poses);
    let poses = merged
        .as_ref()
        .map_or(&run.session.poses[..], |m| m.as_slice());
    let res = crate::plots::residuals(&run.solution.model, poses, &run.solution.fit.offsets_rad);
    crate::plots::write_plots(dir, report, &res)
        .map_err(|e| CliError::Input(format!("{}: {e}", dir.display())))
}
