//! `zerocal simulate` in the real world (the default): a production SCL3300 unit and a
//! robot that sags, has backlash and repeats only so well, every source switchable,
//! the session planned and solved exactly as the pendant does (two captures per pose,
//! the closing reversal), its k = 2 budget printed beside the hidden truth. And
//! `zerocal error-table`: the same sessions by the hundred, one error source at a time,
//! with and without the compensation (the README's table).
//!
//! The simulation and its report are zerocal-sim's (`error_sources`, `real_run` with
//! `RealRun::report`, `error_table` with its `render`); here are the flags that choose
//! it and the errors in the CLI's terms.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use clap::Args;
use std::fmt::Write as _;
use zerocal_inputs::args::{CountIn, RealIn, SEED};
use zerocal_inputs::error::CliError;
use zerocal_sim::error_sources::{world_with, ErrorSource};
use zerocal_sim::error_table::error_table as table_rows;
use zerocal_sim::montecarlo::DEFAULT_POSES;
use zerocal_sim::real_run::{Again, RealRun};
use zerocal_sim::world::{BracketKnowledge, WorldConfig};

/// `--without`'s values: each error source by its name, with its summary.
fn error_source() -> impl TypedValueParser<Value = ErrorSource> {
    PossibleValuesParser::new(
        ErrorSource::LISTED.map(|s| PossibleValue::new(s.name()).help(s.summary())),
    )
    .try_map(|name| {
        ErrorSource::named(&name).ok_or_else(|| format!("'{name}': no such error source"))
    })
}

/// Arguments shared by the real-world runs.
#[derive(Args, Debug, Clone)]
pub struct WorldArgs {
    /// Switch these error sources off (comma-separated); all are on by default.
    #[arg(long, value_delimiter = ',', value_name = "SOURCES", value_parser = error_source())]
    pub without: Vec<ErrorSource>,
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
    #[arg(long, value_name = "SEED", value_parser = zerocal_inputs::args::SEED)]
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
        let on: Vec<ErrorSource> = ErrorSource::ALL
            .into_iter()
            .filter(|s| !self.without.contains(s))
            .collect();
        let mut w = world_with(Some(&on));
        if on.contains(&ErrorSource::Warming) {
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

    /// `--again`'s session: its seed, and the change made to the robot since the first
    /// (`--zero-moved`, `--entered`).
    pub fn again_session(&self) -> Option<Again> {
        self.again.map(|seed| Again {
            seed,
            zero_moved_deg: self.zero_moved.clone(),
            entered_deg: self.entered,
        })
    }
}

/// Simulates and solves one session (`again`: `--again`'s, if given).
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
    let profile = zerocal_inputs::robot::load(robot)?;
    let again = again.and_then(WorldArgs::again_session);
    RealRun::simulate(profile, world, poses, seed, again.as_ref())
        .map_err(|e| CliError::Refused(e.to_string()))
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
        let profile = zerocal_inputs::robot::load(name)?;
        let _ = writeln!(out, "\n{} ({})", profile.name, profile.title);
        let rows = table_rows(&profile, args.sessions, args.poses, args.seed)
            .map_err(|e| CliError::Refused(format!("{name}: plan: {e}")))?;
        zerocal_sim::error_table::render(&mut out, &rows);
    }
    Ok(out)
}

/// The ISO 9283-style test on the robot ([`RealRun::accuracy`]).
///
/// # Errors
/// A profile without lengths (no positions to test).
pub fn accuracy(
    run: &RealRun,
    points: usize,
    seed: u64,
) -> Result<zerocal_sim::positioning::AccuracyReport, CliError> {
    run.accuracy(points, seed)
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
    let res = zerocal_analysis::plots::residuals(
        &run.solution.model,
        poses,
        &run.solution.fit.offsets_rad,
    );
    zerocal_analysis::plots::write_plots(dir, report, &res)
        .map_err(|e| CliError::Input(format!("{}: {e}", dir.display())))
}
