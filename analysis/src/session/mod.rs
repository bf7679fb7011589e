//! `zerocal session EXPORT`: a whole pendant export (stages 0, 1 and 2 with all six
//! joints and the `#` metadata) through core's session solver, reported with the
//! covariance of Δθ2..Δθ6, each stage's share of each variance, and the offsets in the
//! robot controller's own terms.
//!
//! Everything comes from the file: the robot, the convention, stage 0's bias and
//! stage 1's readings with the joints they were taken at. Nothing is retyped, so the
//! hand-over cannot be got wrong (stage 1's tilt composes with joint 2's recorded
//! angle).
//!
//! Nothing in the file is ignored or guessed at: an unknown column or metadata key, a
//! key given twice, rows whose joint 2 is not stage 1's, a pose captured from one side
//! only, another robot's `--robot` and bytes that are not UTF-8 are refused, naming the
//! line (and key, column or byte). A session without a stage-0 reversal is solved, with
//! the sensor's unknown x offset in its budget and a note saying so.

pub mod entry;
mod record;
pub mod reducer_trend;
pub mod reducers;
mod render;
mod session_json;
pub use record::{session_record, verdict_of};
pub use render::render;
pub use session_json::{to_json, BudgetJson, JointJson, SessionJson};

use clap::Args;
use std::path::PathBuf;
use zerocal_core::bracket::{
    BracketMount, Brackets, BRACKET_YAW_TOLERANCE_DEG, SEAT_REPEATABILITY_DEG,
};
use zerocal_core::capture::CaptureIndex;
use zerocal_core::model::Convention;
use zerocal_core::report::Verdict;
use zerocal_core::session::{
    budget, half_turn_half_width, one_sided_pose, sensor_drift_spec_rad_per_k,
    sensor_offset_x_spec_deg, solve, stage1_joint1_mismatch, unknown_offset_half_width,
    unmeasured_drift_half_width, BiasSource, Budget, BudgetInputs, BudgetTerm, SessionError,
    SessionReadings, SessionSolution, StageTemperatures, DEFAULT_HALF_TURN_TOLERANCE_DEG,
    DEFAULT_LOST_MOTION_DEG, DEFAULT_REPEATABILITY_DEG, SESSION_JOINTS,
    STAGE1_JOINT1_TOLERANCE_DEG,
};
use zerocal_core::stage0::BenchTurnsAt;
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::{FitConfig, PoseReading};
use zerocal_core::Tilt;
use zerocal_inputs::args::RealIn;
use zerocal_inputs::error::CliError;
use zerocal_inputs::log_file::parse_number;
use zerocal_procedure::log::{
    parse_meta, strip_bom, text_of, ExportMode, LogLine, LogReader, MetaItem, MetaKeys,
};
use zerocal_procedure::Approach;
use zerocal_profile::Profile;

/// Arguments of `zerocal session`.
#[derive(Args, Debug, Clone)]
pub struct SessionArgs {
    /// The pendant's export (its `export` command's output, saved to a file).
    pub export: PathBuf,
    /// Robot profile, if not the one the export names: a built-in name or a TOML file.
    #[arg(long, value_name = "NAME")]
    pub robot: Option<String>,
    /// A calibrated bracket's seat repeatability on the robot, ± deg about joint 2
    /// (upper arm) and joint 6 (flange): enters Δθ2, Δθ3 and Δθ6 one to one with the
    /// calibration's uncertainty (default: the bracket design's requirement,
    /// docs/mounting.md). An uncalibrated bracket carries ±0.5 deg instead. Range:
    /// [0, 1] deg.
    #[arg(long, default_value_t = SEAT_REPEATABILITY_DEG, value_name = "DEG", value_parser = RealIn::closed(0.0, 1.0, "deg"))]
    pub seat_repeatability_deg: f64,
    /// The brackets' yaw tolerance, ± deg about the pendant's z: not calibrated, it
    /// enters Δθ3 times the base's tilt (default: the bracket design's,
    /// docs/mounting.md). Range: [0, 2] deg.
    #[arg(long, default_value_t = BRACKET_YAW_TOLERANCE_DEG, value_name = "DEG", value_parser = RealIn::closed(0.0, 2.0, "deg"))]
    pub bracket_yaw_deg: f64,
    /// How far stage 0's half turn may be off 180° (default: 1 deg, a turn by hand without
    /// a jig, a stated figure). On a tilted bench it moves the bias by this times the
    /// tilt, over 2. Range: [0, 10] deg.
    #[arg(long, default_value_t = DEFAULT_HALF_TURN_TOLERANCE_DEG, value_name = "DEG", value_parser = RealIn::closed(0.0, 10.0, "deg"))]
    pub half_turn_tolerance_deg: f64,
    /// The robot's repeatability per joint, 1σ. Range: [0, 0.1] deg.
    #[arg(long, default_value_t = DEFAULT_REPEATABILITY_DEG, value_name = "DEG", value_parser = RealIn::closed(0.0, 0.1, "deg"))]
    pub repeatability_deg: f64,
    /// The gears' lost motion (joint 3 may sit on gravity's side of it; default: the
    /// 1 arc min of an RV gear). Range: [0, 0.5] deg.
    #[arg(long, default_value_t = DEFAULT_LOST_MOTION_DEG, value_name = "DEG", value_parser = RealIn::closed(0.0, 0.5, "deg"))]
    pub lost_motion_deg: f64,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
    /// Store the session in the history (`zerocal history`), with `--serial`; then name
    /// each reducer harmonic grown since the robot's previous session beyond three
    /// combined standard uncertainties (a gearbox wearing; docs/history.md).
    #[arg(long, requires = "serial")]
    pub record: bool,
    /// The robot's serial number, as on its rating plate (with `--record`).
    #[arg(long, value_name = "SN")]
    pub serial: Option<String>,
    #[command(flatten)]
    pub meta: crate::db::RecordMeta,
    #[command(flatten)]
    pub db: crate::db::DbArg,
}

impl SessionArgs {
    /// `zerocal session EXPORT` with every option at its default.
    pub fn for_export(export: PathBuf) -> SessionArgs {
        SessionArgs {
            export,
            robot: None,
            seat_repeatability_deg: SEAT_REPEATABILITY_DEG,
            bracket_yaw_deg: BRACKET_YAW_TOLERANCE_DEG,
            half_turn_tolerance_deg: DEFAULT_HALF_TURN_TOLERANCE_DEG,
            repeatability_deg: DEFAULT_REPEATABILITY_DEG,
            lost_motion_deg: DEFAULT_LOST_MOTION_DEG,
            json: false,
            record: false,
            serial: None,
            meta: crate::db::RecordMeta::default(),
            db: crate::db::DbArg::default(),
        }
    }
}

/// What the export holds.
#[derive(Clone, Debug)]
pub struct ExportContents {
    /// `# robot` (the name) and the convention.
    pub robot: Option<(String, Convention)>,
    /// `# stage0_bias_deg`: `Some(None)` for "none".
    pub bias: Option<Option<Tilt<f64>>>,
    /// `# stage1_readings_deg`.
    pub stage1: Option<Option<AxisOneTurn<f64>>>,
    /// `# stage0_reversal_deg`: stage 0's readings and temperature.
    pub stage0: Option<BenchTurnsAt<f64>>,
    /// `# stage1_temp_c`.
    pub stage1_temperature_c: Option<f64>,
    /// `# closing_reversal_deg`.
    pub closing: Option<BenchTurnsAt<f64>>,
    /// `# bracket_upper_arm`, `# bracket_flange`: the calibrations the pendant applied
    /// (none where the export has none).
    pub brackets: Brackets<f64>,
    /// `# fit_extras`: the pendant's model.
    pub extras: Option<zerocal_core::stage2::Extras>,
    /// The line of `# stage1_readings_deg` (0: none).
    pub stage1_line: usize,
    /// The stage-2 rows.
    pub poses: Vec<PoseReading<f64>>,
    /// Their lines.
    pub lines: Vec<usize>,
    /// Each row's `approach`, where the export has the column (exports written before
    /// it have not).
    pub approaches: Option<Vec<Approach>>,
    /// Each row's capture index (its `pose` and `approach`), where the export has the
    /// `pose` column (exports written before it have not): a pose's two captures are
    /// paired by it.
    pub captures: Option<Vec<CaptureIndex>>,
    /// The export ended with its end trailer, which matched (`zerocal_procedure::export_trailer`):
    /// nothing lost or changed since the pendant wrote it. Without one (a file edited by
    /// hand, or not from a pendant) it is read unchecked, with a note.
    pub trailer_checked: bool,
    /// `# pendant unit HEX firmware VERSION`: the pendant unit's ID (24 hex digits),
    /// where the export names it.
    pub pendant_unit: Option<String>,
    /// `# mode`: a session's export or a check's (no line: a session).
    pub mode: ExportMode,
}

/// Reads a pendant export, strictly ([`LogReader::for_export`], [`MetaKeys`]): an
/// unknown column or metadata key, or a key given twice, is refused by name and line.
/// A leading byte-order mark is dropped.
///
/// # Errors
/// A malformed row or metadata line (naming the line).
pub fn read_export(text: &str) -> Result<ExportContents, String> {
    let text = strip_bom(text);
    let mut reader = LogReader::for_export();
    let mut keys = MetaKeys::default();
    let mut approaches = Vec::new();
    let mut captures = Vec::new();
    let mut export = ExportContents {
        robot: None,
        bias: None,
        stage1: None,
        stage0: None,
        stage1_temperature_c: None,
        closing: None,
        extras: None,
        brackets: Brackets::default(),
        stage1_line: 0,
        poses: Vec::new(),
        lines: Vec::new(),
        approaches: None,
        captures: None,
        trailer_checked: false,
        pendant_unit: None,
        mode: ExportMode::Session,
    };
    for line in text.lines() {
        match reader.feed(line, parse_number).map_err(|e| e.to_string())? {
            LogLine::Pose(p) => {
                export.poses.push(p);
                export.lines.push(reader.line());
                approaches.extend(reader.approach());
                captures.extend(reader.capture_index());
            }
            LogLine::Comment(c) => {
                let item =
                    parse_meta::<f64>(c, reader.line(), parse_number).map_err(|e| e.to_string())?;
                if let Some(item) = &item {
                    keys.note(item, reader.line()).map_err(|e| e.to_string())?;
                }
                match item {
                    Some(MetaItem::Robot(name, conv)) => {
                        export.robot = Some((name.as_str().to_owned(), conv));
                    }
                    Some(MetaItem::Bias(b)) => export.bias = Some(b),
                    Some(MetaItem::Stage1(s)) => {
                        export.stage1 = Some(s);
                        export.stage1_line = reader.line();
                    }
                    Some(MetaItem::Stage0Bench(r)) => export.stage0 = Some(r),
                    Some(MetaItem::Stage1Temperature(t)) => export.stage1_temperature_c = Some(t),
                    Some(MetaItem::Closing(r)) => export.closing = Some(r),
                    Some(MetaItem::FitExtras(e)) => export.extras = Some(e),
                    Some(MetaItem::Bracket(BracketMount::UpperArm, c)) => {
                        export.brackets.upper_arm = c;
                    }
                    Some(MetaItem::Bracket(BracketMount::Flange, c)) => {
                        export.brackets.flange = c;
                    }
                    Some(MetaItem::Pendant(unit, _)) => {
                        export.pendant_unit = Some(unit.to_string())
                    }
                    Some(MetaItem::Mode(m)) => export.mode = m,
                    None => {}
                }
            }
            LogLine::Blank | LogLine::Header => {}
        }
    }
    reader.finish().map_err(|e| e.to_string())?;
    // The reader has the column for every row or for none.
    if reader.has_column("approach") {
        export.approaches = Some(approaches);
    }
    if reader.has_column("pose") {
        export.captures = Some(captures);
    }
    export.trailer_checked = reader.trailer().is_some();
    Ok(export)
}

/// Refuses an export whose rows contradict its metadata or that the solver would get
/// silently wrong: rows at another joint 1 than stage 1's, a pose captured from one
/// side only.
fn check_rows(export: &ExportContents, stage1: &AxisOneTurn<f64>) -> Result<(), String> {
    if let Some(i) = stage1_joint1_mismatch(stage1, &export.poses) {
        return Err(format!(
            "line {}: joint 1 at {} deg, but stage 1's j1_deg (line {}) says {} deg: stage 2 runs \
             with joint 1 back where stage 1 had it (tolerance {STAGE1_JOINT1_TOLERANCE_DEG} deg), \
             and stage 1's base tilt is read at its recorded joint 1, so a wrong record would \
             move Δθ3 unseen; correct the export",
            export.lines.get(i).copied().unwrap_or(0),
            export.poses[i].joints_rad[0].to_degrees(),
            export.stage1_line,
            stage1.j1_rad.to_degrees()
        ));
    }
    if let Some(i) = one_sided_pose(
        &export.poses,
        export.captures.as_deref(),
        export.approaches.as_deref(),
    ) {
        let how = match &export.approaches {
            Some(a) => format!(
                "captured only from {}",
                a.get(i)
                    .map_or("one side", |s| zerocal_procedure::log::approach_name(*s))
            ),
            None => "captured once (an export without the approach column: every pose must be \
             captured twice, from below and from above)"
                .to_owned(),
        };
        return Err(format!(
            "line {}: the pose there is {how}: its reading sits on one side of every gear's \
             backlash, up to half the lost motion off its zero, which no budget term covers; \
             capture it from both sides or leave it out",
            export.lines.get(i).copied().unwrap_or(0)
        ));
    }
    Ok(())
}

/// How far this `f64` re-solve of a pendant's export may lie from the pendant's own
/// `f32` result for the two to be the same session (deg): the `f32` solve agrees with the
/// `f64` one within 2.8e-6° (docs/figures.md; 1.23e-6° on the target) and the export's readings are
/// written to 1e-12°, so a larger difference means another model or other readings.
pub const PENDANT_AGREEMENT_DEG: f64 = 1e-5;

/// The same for 1σ, relative.
pub const PENDANT_SIGMA_AGREEMENT: f64 = 0.01;

/// Where the export carries the pendant's own result and this re-solve agrees with it
/// (within [`PENDANT_AGREEMENT_DEG`] and [`PENDANT_SIGMA_AGREEMENT`]), the report gives
/// the pendant's Δθ and 1σ (its covariance scaled to them, correlations kept): the
/// numbers its screen showed and a technician typed in, so the screen and the report
/// never differ in a printed digit. Returns the note that says which numbers are shown.
fn adopt_pendant_result(solution: &mut SessionSolution<f64>, text: &str) -> Option<String> {
    let pendant = zerocal_procedure::log::read_pendant_result(text)?;
    let sigma = solution.sigma_rad();
    let mut worst_offset_deg: f64 = 0.0;
    let mut worst_sigma: f64 = 0.0;
    for (k, own_sigma_rad) in sigma.iter().enumerate() {
        let own_deg = solution.offsets_rad[k].to_degrees();
        let d = (own_deg - pendant.offsets_deg[k]).abs();
        // `f64::max` would drop a NaN: carry it.
        worst_offset_deg = if d.is_nan() {
            d
        } else {
            worst_offset_deg.max(d)
        };
        let own = own_sigma_rad.to_degrees();
        let r = if own > 0.0 {
            (pendant.sigma_deg[k] / own - 1.0).abs()
        } else if pendant.sigma_deg[k] == 0.0 {
            0.0
        } else {
            // A zero 1σ here against a non-zero one there: not the same session.
            f64::INFINITY
        };
        worst_sigma = if r.is_nan() { r } else { worst_sigma.max(r) };
    }
    // Written so that a NaN difference refuses the adoption too.
    let agrees =
        worst_offset_deg <= PENDANT_AGREEMENT_DEG && worst_sigma <= PENDANT_SIGMA_AGREEMENT;
    if !agrees {
        return Some(format!(
            "the pendant's own result differs from this re-solve by up to {worst_offset_deg:.6} \
             deg in an offset and {:.1} % in a 1-sigma (agreement is within {PENDANT_AGREEMENT_DEG} \
             deg and {:.0} %): the numbers below are this computer's, not the pendant's screen's; \
             check that --robot names the profile the pendant holds",
            worst_sigma * 100.0,
            PENDANT_SIGMA_AGREEMENT * 100.0
        ));
    }
    let scale: [f64; SESSION_JOINTS] = core::array::from_fn(|k| {
        if sigma[k] > 0.0 {
            pendant.sigma_deg[k].to_radians() / sigma[k]
        } else {
            1.0
        }
    });
    for i in 0..SESSION_JOINTS {
        solution.offsets_rad[i] = pendant.offsets_deg[i].to_radians();
        for j in 0..SESSION_JOINTS {
            solution.covariance_rad2[i][j] *= scale[i] * scale[j];
        }
        for share in &mut solution.variance_shares_rad2[i] {
            *share *= scale[i] * scale[i];
        }
        solution.prior_variance_rad2[i] *= scale[i] * scale[i];
    }
    Some(format!(
        "offsets and 1-sigma are the pendant's own, as its screen showed them; this f64 \
         re-solve of the export agrees within {worst_offset_deg:.7} deg and {:.2} % of a 1-sigma",
        worst_sigma * 100.0
    ))
}

/// Runs `zerocal session`.
///
/// # Errors
/// An unreadable or malformed export, an unknown robot (status 2); a session the solver
/// refuses (status 3).
pub fn run(args: &SessionArgs) -> Result<String, CliError> {
    let bytes = zerocal_inputs::input::read_capped_bytes(
        &args.export,
        zerocal_inputs::input::MAX_EXPORT_BYTES,
        "pendant export",
    )?;
    let mut analysis = analyse(args, &bytes)?;
    if let Some(serial) = &args.serial {
        // The numbers to type on this robot, through what its checks measured.
        let recorded = args.db.open()?.conventions(serial);
        let recorded = recorded.map_err(crate::db::history_failed)?;
        entry::apply(
            &mut analysis.json,
            serial,
            &recorded,
            analysis.profile.family,
        );
    }
    let recorded = match (&args.serial, args.record) {
        (Some(serial), true) => {
            let record = session_record(&analysis, &bytes, serial, &args.meta)?;
            let mut history = args.db.open()?;
            let inserted = history.insert(&record).map_err(crate::db::history_failed)?;
            // The reducers' amplitudes against the robot's previous sessions.
            let mut changes = crate::session::reducer_trend::changes_in(
                &history
                    .list(Some(serial))
                    .map_err(crate::db::history_failed)?,
            );
            changes.retain(|c| c.record_id == inserted.id);
            Some((inserted, history.location().to_owned(), changes))
        }
        _ => None,
    };
    if args.json {
        let mut value =
            serde_json::to_value(&analysis.json).map_err(|e| CliError::Input(e.to_string()))?;
        if let (Some((inserted, _, changes)), Some(object)) = (&recorded, value.as_object_mut()) {
            object.insert("record_id".into(), inserted.id.into());
            object.insert(
                "reducer_changes".into(),
                serde_json::to_value(changes).map_err(|e| CliError::Input(e.to_string()))?,
            );
        }
        return serde_json::to_string_pretty(&value).map_err(|e| CliError::Input(e.to_string()));
    }
    let mut out = render(&analysis.json);
    if let Some((inserted, at, changes)) = recorded {
        out.push_str(&if inserted.new {
            format!("recorded: record {} in {at}\n", inserted.id)
        } else {
            format!(
                "already recorded: record {} in {at} (the same export)\n",
                inserted.id
            )
        });
        for c in &changes {
            out.push_str(&c.line());
            out.push('\n');
        }
    }
    Ok(out)
}

/// A session solved: its report and what it was solved from.
#[derive(Clone, Debug)]
pub struct Analysis {
    /// The report (`--json`'s object).
    pub json: SessionJson,
    /// The export as read.
    pub export: ExportContents,
    /// The robot profile it was solved with.
    pub profile: Profile,
    /// Its TOML text.
    pub profile_toml: String,
    /// The solution (the pendant's numbers where it agrees: see the notes).
    pub solution: SessionSolution<f64>,
    /// Its budget.
    pub budget: Budget<f64>,
    /// The fit as configured.
    pub config: FitConfig<f64>,
}

/// Solves the export `bytes` (the file `args.export`, named in errors) as `zerocal
/// session` does.
///
/// # Errors
/// As [`run`].
pub fn analyse(args: &SessionArgs, bytes: &[u8]) -> Result<Analysis, CliError> {
    analyse_with(args, bytes, None)
}

/// [`analyse`] with the robot profile given (a record's own), not loaded by name.
///
/// # Errors
/// As [`run`].
pub fn analyse_with(
    args: &SessionArgs,
    bytes: &[u8],
    given: Option<(Profile, String)>,
) -> Result<Analysis, CliError> {
    let name = |what: &str| format!("{}: {what}", args.export.display());
    let text = text_of(bytes).map_err(|e| CliError::Input(name(&e.to_string())))?;
    let export = read_export(text).map_err(|e| CliError::Input(name(&e)))?;
    if export.mode == ExportMode::Check {
        return Err(CliError::Input(name(
            "a check export (`# mode check`): it holds no stage 1 and solves nothing; use zerocal check",
        )));
    }
    let (robot_name, convention) = export.robot.clone().ok_or_else(|| {
        CliError::Input(name(
            "no `# robot … convention …` line: not a pendant export",
        ))
    })?;
    let (profile, profile_toml) = match given {
        Some(p) => p,
        None => {
            zerocal_inputs::robot::load_with_text(args.robot.as_deref().unwrap_or(&robot_name))?
        }
    };
    // Another robot's profile fits another arm: the solver would fail to converge or,
    // worse, converge on wrong numbers. A profile file of the same robot is welcome.
    if profile.name != robot_name {
        return Err(CliError::Input(name(&format!(
            "export is for robot {robot_name}, --robot says {}",
            profile.name
        ))));
    }
    let stage1 = export.stage1.flatten().ok_or_else(|| {
        CliError::Refused(name("stage 1 was not completed (no stage-1 readings)"))
    })?;
    check_rows(&export, &stage1).map_err(|e| CliError::Input(name(&e)))?;
    // Stage 1's joint 2 is where the pendant's profile stands it: a record that says
    // otherwise would move Δθ2 by its error and Δθ3 back (joints 2 and 3 parallel),
    // unseen by the fit, now that stage 2's own joint 2 swings.
    let stated = profile.stage1_joints_rad[1];
    if (stage1.j2_rad - stated).abs().to_degrees() > STAGE1_JOINT1_TOLERANCE_DEG
        || !stage1.j2_rad.is_finite()
    {
        return Err(CliError::Input(name(&format!(
            "line {}: stage 1's j2_deg says {} deg, but the profile's stage-1 pose stands \
             joint 2 at {} deg (tolerance {STAGE1_JOINT1_TOLERANCE_DEG} deg): a wrong record \
             would move Δθ2 and Δθ3 by its error unseen; correct the export or give the \
             profile it was made with (--robot)",
            export.stage1_line,
            stage1.j2_rad.to_degrees(),
            stated.to_degrees()
        ))));
    }
    // The reversal's own readings where the export has them (the drift model needs
    // their temperature), else the bias it computed.
    let bias = match (export.stage0, export.bias.flatten()) {
        (Some(r), _) => BiasSource::Bench(r.turns),
        (None, Some(b)) => BiasSource::Stored(b),
        (None, None) => BiasSource::Unknown,
    };
    let masses = profile.mass_model();
    let readings = SessionReadings {
        convention,
        arm: profile.arm,
        masses,
        brackets: &export.brackets,
        bias,
        stage1,
        poses: &export.poses,
        capture_index: export.captures.as_deref(),
        temperatures: StageTemperatures {
            stage0_c: export.stage0.and_then(|r| r.temperature_c),
            stage1_c: export.stage1_temperature_c,
        },
        closing: export.closing,
    };
    // The pendant's own model where the export states it, so both compute the same.
    let mut config = zerocal_inputs::robot::fit_config(convention, &profile);
    if let Some(e) = export.extras {
        config.extras = zerocal_core::stage2::Extras {
            held: config.extras.held,
            tilt: config.extras.tilt,
            wrist_sag: config.extras.wrist_sag,
            sag2: config.extras.sag2,
            lash: config.extras.lash,
            transmission: config.extras.transmission,
            ..e
        };
    }
    let outcome = solve(&readings, &config);
    let mut solution = match outcome.result {
        Ok(s) => s,
        Err(e) => {
            return Err(refused_with_diagnosis(
                e, &export, &readings, &config, &profile,
            ))
        }
    };
    let pendant_note = adopt_pendant_result(&mut solution, text);
    let verdict = Verdict::judge(&solution.fit, &config, outcome.stage1.as_ref());
    let unknown_offset = unknown_offset_half_width(&readings, &config).map_err(|e| {
        CliError::Refused(name(&format!(
            "no stage-0 reversal, and with the sensor's x offset at either end of its \
                 specification (+/-{:.3} deg) the session is refused ({e}), so how far the \
                 offsets move with it is not known: run stage 0 (the bench reversal)",
            sensor_offset_x_spec_deg()
        )))
    })?;
    let mut budget = budget(
        &solution,
        &export.poses,
        &BudgetInputs {
            extras: config.extras,
            sensor_noise_rad: config.sensor_noise_rad,
            bracket_u_rad: BracketMount::ALL.map(|m| {
                export
                    .brackets
                    .standard_uncertainty_rad(m, args.seat_repeatability_deg.to_radians())
            }),
            bracket_yaw_u_rad: BracketMount::ALL.map(|m| {
                export
                    .brackets
                    .yaw_uncertainty_rad(m, args.bracket_yaw_deg.to_radians())
            }),
            repeatability_rad: args.repeatability_deg.to_radians(),
            lost_motion_rad: args.lost_motion_deg.to_radians(),
            // The profile's stage-1 pose, where the export's stage 1 stood at it: whether
            // joint 2 rests unloaded there follows from the profile's masses.
            stage1_joints_rad: export
                .stage1
                .flatten()
                .filter(|s| {
                    let q = profile.stage1_joints_rad;
                    (s.j1_rad - q[0]).abs().max((s.j2_rad - q[1]).abs())
                        < zerocal_core::session::STAGE1_JOINT1_TOLERANCE_DEG.to_radians()
                })
                .map(|_| profile.stage1_joints_rad),
        },
    );
    let half_turn = half_turn_half_width(
        &readings,
        &config,
        args.half_turn_tolerance_deg.to_radians(),
    )
    .map_err(|e| {
        // The refusal names its own step: it is what the session, solved again with the
        // half turn at the edge of its tolerance, shows (a knock, say), not the bench.
        CliError::Refused(name(&format!(
            "{e} (found solving the session again with stage 0's half turn off 180 deg by \
             +/-{} deg, as its budget term does; stage 0 read at four headings assumes no \
             half turn)",
            args.half_turn_tolerance_deg
        )))
    })?;
    if let Some(w) = half_turn {
        budget.add_half_turn(&w);
    }
    let unmeasured_drift = unmeasured_drift_half_width(&readings, &config).map_err(|e| {
        // As for the half turn: the refusal is what the session shows solved again with
        // the sensor's bias drifting at either end of its stated rate.
        CliError::Refused(name(&format!(
            "{e} (found solving the session again with the sensor's bias drifting by \
             +/-{:.4} deg/K, its stated drift, as its budget term does; the closing bench \
             readings measure the drift)",
            sensor_drift_spec_rad_per_k::<f64>().to_degrees()
        )))
    })?;
    if let Some(w) = unmeasured_drift {
        budget.add_unmeasured_drift(&w);
    }
    let mut notes = vec![format!(
        "robot profile {} ({}), convention {}",
        profile.name,
        profile.title,
        convention.name()
    )];
    if let Some(w) = unknown_offset {
        budget.add_unknown_sensor_offset(&w);
        let names: Vec<String> = w
            .iter()
            .enumerate()
            .filter(|(_, v)| v.to_degrees() >= 0.0005)
            .map(|(k, v)| format!("j{} +/-{:.3} deg", k + 2, v.to_degrees()))
            .collect();
        notes.push(format!(
            "no stage-0 reversal: the sensor's x offset is unknown, within +/-{:.2} deg (the \
             SCL3300's offset specification), and the offsets were solved taking it as 0; across \
             that range they move by {}, which the budget carries as the term '{}' (uniform). \
             Run stage 0 (the bench reversal) to measure it",
            sensor_offset_x_spec_deg(),
            if names.is_empty() {
                "less than 0.0005 deg".to_owned()
            } else {
                names.join(", ")
            },
            BudgetTerm::UnknownSensorOffset.name()
        ));
    }
    notes.push(crate::report_notes::offsets_meaning(&solution.fit));
    notes.extend(pendant_note);
    notes.extend(profile.missing.iter().map(|m| format!("profile: {m}")));
    if !export.trailer_checked {
        notes.push(
            "the export has no end trailer ('# end lines N crc32 X'): edited by hand or not \
             from a pendant, so whether lines were lost or changed is not checked"
                .into(),
        );
    }
    notes.extend(crate::report_notes::bracket_notes(
        &export.brackets,
        args.seat_repeatability_deg,
    ));
    if export.closing.is_none() && convention == Convention::Axis {
        notes.push(
            "no closing reversal: the sensor's bias drift was not measured; the session is \
             refused if the pendant's temperature moved more than 0.5 K"
                .to_owned(),
        );
    }
    if let Some(w) = unmeasured_drift {
        notes.push(format!(
            "the sensor's bias drift with temperature was not measured: at its stated \
             +/-{:.4} deg/K over the captures' temperatures the offsets move by up to {:.4} \
             deg, which the budget carries as the term '{}' (uniform)",
            sensor_drift_spec_rad_per_k::<f64>().to_degrees(),
            w.iter().fold(0.0f64, |m, v| m.max(v.to_degrees())),
            BudgetTerm::UnmeasuredDrift.name()
        ));
    }
    let held = config.extras.held;
    for (k, h) in held.iter().enumerate() {
        if *h {
            let this = &profile.joints[k + 2].name;
            // The first earlier wrist joint not itself held carries the sum.
            let carrier = (0..k).rev().find(|&i| !held[i]).unwrap_or(0);
            let twin = &profile.joints[carrier + 2].name;
            notes.push(format!(
                "{this} (joint {}) turns about an axis parallel to {twin}'s (joint {}) in every pose: gravity sees only the sum of their offsets, which {twin}'s line carries; {this}'s own zero needs another method (the controller's mastering marks or a fixture), and its line is not a zero",
                k + 3,
                carrier + 3
            ));
        }
    }
    let json = to_json(&profile, &solution, &verdict, &budget, held, notes);
    Ok(Analysis {
        json,
        export,
        profile,
        profile_toml,
        solution,
        budget,
        config,
    })
}

/// A refusal; when the readings do not fit the model at all, with the model change
/// that makes them fit ([`crate::diagnose`]).
fn refused_with_diagnosis(
    e: SessionError,
    export: &ExportContents,
    readings: &SessionReadings<'_, f64>,
    config: &FitConfig<f64>,
    profile: &Profile,
) -> CliError {
    use zerocal_core::FitError;
    let wrong_model = matches!(
        e,
        SessionError::Stage2(
            FitError::ResidualTooLarge { .. }
                | FitError::NoConvergence { .. }
                | FitError::IllConditioned { .. }
                | FitError::NonFiniteResult
        ) | SessionError::Stage1(zerocal_core::StageError::InconsistentReading)
    );
    let base = refused(e, export);
    if !wrong_model {
        return base;
    }
    // Without a ceiling of its own (the paper's sensor), five times the noise figure.
    let level = if config.max_residual_rms_rad > 0.0 {
        config.max_residual_rms_rad.to_degrees()
    } else {
        5.0 * config.sensor_noise_rad.to_degrees()
    };
    let names: Vec<String> = profile.joints.iter().map(|j| j.name.clone()).collect();
    let found = crate::diagnose::diagnose(readings, config, &names, level);
    let CliError::Refused(msg) = base else {
        return base;
    };
    CliError::Refused(match found.first() {
        Some(d) => format!(
            "{msg}\ndiagnosis: the readings fit at the noise level ({:.4} deg RMS) with {}; correct that and run `zerocal session` again",
            d.residual_rms_deg, d.change
        ),
        // An ill-conditioned set can be just that: the message stands alone.
        None if matches!(e, SessionError::Stage2(FitError::IllConditioned { .. })) => msg,
        None => format!(
            "{msg}\ndiagnosis: no joint direction, bracket orientation or convention change makes the readings fit: check that the robot stood still at every capture, that the export is this robot's, and the bracket is tight"
        ),
    })
}

fn refused(e: SessionError, export: &ExportContents) -> CliError {
    // The solver fits a pose's captures merged, paired as the export pairs them (by
    // index where it has the `pose` column): its pose index is into the merged list,
    // whose order is that of each pose's first capture.
    let firsts = zerocal_core::session::first_captures(&export.poses, export.captures.as_deref());
    let line = |pose: usize| {
        // More poses than a plan holds are fitted unmerged: the index is the row's.
        firsts
            .as_ref()
            .map_or(Some(pose), |f| f.get(pose).copied())
            .and_then(|i| export.lines.get(i).copied())
            .unwrap_or(0)
    };
    let msg = match e {
        SessionError::Stage2(
            f @ (zerocal_core::FitError::NonFiniteJoint { pose }
            | zerocal_core::FitError::NonFiniteReading { pose }
            | zerocal_core::FitError::ReadingOutOfRange { pose, .. }),
        ) => format!("line {}: stage 2: {f}", line(pose)),
        SessionError::Stage2(f @ zerocal_core::FitError::ResidualTooLarge { worst_pose, .. }) => {
            format!(
                "stage 2: {f} (the worst pose's first capture is on line {})",
                line(worst_pose)
            )
        }
        other => other.to_string(),
    };
    CliError::Refused(msg)
}
