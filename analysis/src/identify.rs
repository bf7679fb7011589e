//! `zerocal identify LOG.csv`: stage 2 on a recorded log.

use clap::Args;
use serde::Serialize;
use std::path::PathBuf;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt};
use zerocal_core::real::deg_to_rad;
use zerocal_core::report::{write_report, Verdict};
use zerocal_core::stage2::{fit, FitConfig, FitResult, SigmaSource, Stage2Model};
use zerocal_core::FitError;
use zerocal_inputs::args::{RealIn, CONDITION, TILT_PAIR};
use zerocal_inputs::error::CliError;
use zerocal_inputs::log_file::{read_log, Log};

/// Arguments of `zerocal identify`.
#[derive(Args, Debug, Clone)]
pub struct IdentifyArgs {
    /// The log: `j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg`, one pose a row, `#` comments.
    pub log: PathBuf,
    /// How the sensor's angles derive from gravity (docs/method.md): rpy (the paper's
    /// sensor) or axis (the pendant's SCL3300). Required: the two differ by 0.15° at
    /// 10° of tilt, and a log does not say which it holds.
    #[arg(long, value_parser = zerocal_inputs::args::convention())]
    pub convention: Convention,
    /// Base tilt α,β in degrees, as stage 1 measured it. It is composed with joints 1
    /// and 2 as the log records them (its `j1_deg`, `j2_deg` columns, required with this
    /// flag) and `--delta-theta2-deg`. Range: each [-10, 10] deg.
    #[arg(long, value_name = "X,Y", value_parser = TILT_PAIR, allow_hyphen_values = true)]
    pub base_tilt_deg: Option<(f64, f64)>,
    /// Δθ2 in degrees, as stage 1 measured it (joint 2's true angle is the log's j2 plus
    /// this). Range: [-10, 10] deg.
    #[arg(long, value_name = "D", value_parser = RealIn::closed(-10.0, 10.0, "deg"), allow_hyphen_values = true)]
    pub delta_theta2_deg: Option<f64>,
    /// Sensor bias x,y in degrees, as measured by stage 0 (and stage 1 for y).
    /// Range: each [-10, 10] deg.
    #[arg(long, value_name = "X,Y", value_parser = TILT_PAIR, allow_hyphen_values = true)]
    pub bias_deg: Option<(f64, f64)>,
    /// The sensor's noise as the half-width of uniform noise ±A (deg): used for 1σ
    /// when a log has too few poses to estimate it, and to judge the residual.
    /// Range: (0, 1] deg.
    #[arg(long, default_value_t = 0.002, value_name = "A", value_parser = RealIn::above(0.0, 1.0, "deg"))]
    pub noise_deg: f64,
    /// Readings beyond ±this (deg) are refused as saturated or mis-recorded.
    /// Range: (0, 90] deg.
    #[arg(long, default_value_t = 30.0, value_parser = RealIn::above(0.0, 90.0, "deg"))]
    pub range_deg: f64,
    /// Refuse pose sets whose Jacobian condition number exceeds this. Range: (1, 100000].
    #[arg(long, default_value_t = 1000.0, value_parser = CONDITION)]
    pub max_condition: f64,
    /// Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file.
    #[arg(long, value_name = "NAME", default_value = "paper-wrist")]
    pub robot: String,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
}

/// The `--json` output.
#[derive(Serialize, Debug)]
pub struct IdentifyJson {
    /// Δθ3..Δθ6 (deg).
    pub offsets_deg: [f64; 4],
    /// 1σ of each (deg).
    pub sigma_deg: [f64; 4],
    /// RMS of the residuals (deg).
    pub residual_rms_deg: f64,
    /// Iterations of the fit.
    pub iterations: u32,
    /// Condition number of the Jacobian.
    pub condition_number: f64,
    /// Poses fitted.
    pub poses: usize,
    /// Convention used.
    pub convention: &'static str,
    /// `residuals` or `sensor_noise`.
    pub sigma_source: &'static str,
    /// Empty when the verdict is pass.
    pub warnings: Vec<String>,
    /// What was assumed (as the text report's `note:` lines).
    pub notes: Vec<String>,
}

/// The model and config the flags describe.
pub fn model_and_config(
    args: &IdentifyArgs,
) -> Result<(Stage2Model<f64>, FitConfig<f64>), CliError> {
    let profile = zerocal_inputs::robot::load(&args.robot)?;
    let (a, b) = args.base_tilt_deg.unwrap_or((0.0, 0.0));
    let (bx, by) = args.bias_deg.unwrap_or((0.0, 0.0));
    let model = Stage2Model {
        arm: profile.arm,
        base_tilt: BaseTilt::from_deg(a, b),
        delta_theta2_rad: deg_to_rad(args.delta_theta2_deg.unwrap_or(0.0)),
        sensor: SensorModel::new(args.convention, Tilt::from_deg(bx, by)),
        ..Stage2Model::default()
    };
    let config = FitConfig {
        sensor_range_rad: deg_to_rad(args.range_deg),
        sensor_noise_rad: deg_to_rad(args.noise_deg / 3f64.sqrt()),
        max_condition_number: args.max_condition,
        ..FitConfig::default()
    };
    Ok((model, config))
}

/// Names the log line of a pose-indexed error.
fn refusal(e: FitError, log: &Log) -> CliError {
    let line = |pose: usize| log.lines.get(pose).copied().unwrap_or(0);
    let msg = match e {
        FitError::NonFiniteJoint { pose }
        | FitError::NonFiniteReading { pose }
        | FitError::ReadingOutOfRange { pose, .. } => format!("line {}: {e}", line(pose)),
        _ => e.to_string(),
    };
    CliError::Refused(msg)
}

/// Runs the identification and returns what to print.
pub fn run(args: &IdentifyArgs) -> Result<String, CliError> {
    let text = zerocal_inputs::input::read_capped(
        &args.log,
        zerocal_inputs::input::MAX_LOG_BYTES,
        "stage-2 log",
    )?;
    let log = read_log(text.as_bytes())
        .map_err(|e| CliError::Input(format!("{}: {e}", args.log.display())))?;
    if (args.base_tilt_deg.is_some() || args.delta_theta2_deg.is_some()) && !log.has_j1_j2 {
        // Stage 1's tilt and Δθ2 compose with joint 2's recorded angle: without it the
        // tilt of the frame joint 3 turns in would be wrong by joint 2's angle, a silent
        // error of degrees in Δθ3.
        return Err(CliError::Input(format!(
            "{}: the log has no j1_deg and j2_deg columns, which --base-tilt-deg and --delta-theta2-deg compose with; add them, or run `zerocal session` on the pendant's whole export",
            args.log.display()
        )));
    }
    let (model, config) = model_and_config(args)?;
    let result = fit(&model, &log.poses, &config).map_err(|e| refusal(e, &log))?;
    let verdict = Verdict::judge(&result, &config, None);
    let mut notes = Vec::new();
    if args.bias_deg.is_none() {
        notes.push("no --bias-deg given: sensor bias taken as zero".to_owned());
    }
    if args.base_tilt_deg.is_none() {
        notes.push("no --base-tilt-deg given: base taken as level".to_owned());
    }
    notes.push(
        "1-sigma covers the stage-2 readings only, the base tilt and bias taken as exact, and the sensor as ideal; `zerocal session` on the pendant's export adds stages 0-1 and the real sensor's terms".to_owned(),
    );
    if args.json {
        let json = to_json(&result, args.convention, &verdict, notes);
        serde_json::to_string_pretty(&json).map_err(|e| CliError::Input(e.to_string()))
    } else {
        let mut out = format!(
            "zerocal identify: {} poses from {} ({} convention)\n",
            log.poses.len(),
            args.log.display(),
            args.convention.name()
        );
        for n in &notes {
            out.push_str(&format!("note: {n}\n"));
        }
        write_report(&mut out, None, &result, &verdict)
            .map_err(|e| CliError::Input(e.to_string()))?;
        Ok(out)
    }
}

/// The JSON object of a result.
pub fn to_json(
    r: &FitResult<f64>,
    convention: Convention,
    verdict: &Verdict,
    notes: Vec<String>,
) -> IdentifyJson {
    IdentifyJson {
        offsets_deg: r.offsets_rad.map(f64::to_degrees),
        sigma_deg: r.sigma_rad.map(f64::to_degrees),
        residual_rms_deg: r.residual_rms_rad.to_degrees(),
        iterations: r.iterations,
        condition_number: r.condition_number,
        poses: r.poses,
        convention: convention.name(),
        sigma_source: match r.sigma_source {
            SigmaSource::Residuals => "residuals",
            SigmaSource::SensorNoise => "sensor_noise",
        },
        warnings: verdict.warnings.iter().map(|w| w.to_string()).collect(),
        notes,
    }
}
