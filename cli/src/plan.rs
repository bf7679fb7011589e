//! `zerocal plan`: the stage-2 poses to send the robot to, planned before it moves
//! (`zerocal_core::plan`), with the 1σ per axis they promise.
//!
//! Output: a table (default), `--csv` (header `j3_deg,j4_deg,j5_deg,j6_deg`, one row
//! per pose, nothing else on stdout) or `--json` (one object: `poses_deg`,
//! `predicted_sigma_deg`, `condition_number`, `max_reading_deg`, settings).
//!
//! `--limits FILE` gives the joint limits as CSV, one joint per line, degrees:
//!
//! ```text
//! # joint,min_deg,max_deg     (a header line and '#' comments are allowed)
//! joint,min_deg,max_deg
//! 3,-170,170
//! 4,-185,185
//! 5,-120,120
//! 6,-350,350
//! ```
//! Joints not listed keep ±180°. A bad line is named by its number and field.
//!
//! `--noise-deg A` is the half-width of uniform reading noise ±A, as for `simulate`
//! (the paper's Table 4: 0.002): the predicted 1σ uses σ = A/√3 per reading.

use crate::args::{CountIn, RealIn, SEED, TILT_PAIR};
use crate::error::CliError;
use clap::Args;
use serde::Serialize;
use std::fmt::Write;
use std::path::PathBuf;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{plan, Candidate, Criterion, Plan, PlanConfig, PlanError};
use zerocal_core::real::{deg_to_rad, rad_to_deg};
use zerocal_core::stage2::Stage2Model;
use zerocal_profile::Profile;

/// Arguments of `zerocal plan`.
#[derive(Args, Debug, Clone)]
pub struct PlanArgs {
    /// Poses to plan (`zerocal_core::plan::MAX_POSES` at most). Range: [4, 48].
    #[arg(long, default_value_t = 8, value_parser = CountIn::<usize>::new(4, 48))]
    pub poses: usize,
    /// Sensor window: readings must stay within ±W degrees. Range: (0, 90] deg.
    #[arg(long, default_value_t = 10.0, value_name = "W", value_parser = RealIn::above(0.0, 90.0, "deg"))]
    pub window_deg: f64,
    /// Planned readings stay within ±(W − margin) at zero offsets, leaving room for
    /// the offsets not yet known (deg); it must also be smaller than W.
    /// Range: [0, 90] deg.
    #[arg(long, default_value_t = 1.0, value_parser = RealIn::closed(0.0, 90.0, "deg"))]
    pub margin_deg: f64,
    /// Joint limits of joints 3-6: CSV lines `joint,min_deg,max_deg` (default: the
    /// robot profile's).
    #[arg(long, value_name = "FILE")]
    pub limits: Option<PathBuf>,
    /// Reading noise: uniform in ±A degrees, as for `simulate` (σ = A/√3).
    /// Range: (0, 1] deg.
    #[arg(long, default_value_t = 0.002, value_name = "A", value_parser = RealIn::above(0.0, 1.0, "deg"))]
    pub noise_deg: f64,
    /// Seed of the candidate draw: the same seed gives the same plan.
    /// Range: [0, 18446744073709551615].
    #[arg(long, default_value_t = 1, value_parser = SEED)]
    pub seed: u64,
    /// Feasible candidate poses to choose from (at least --poses). Range: [4, 65535].
    #[arg(long, default_value_t = 256, value_parser = CountIn::<usize>::new(4, 65_535))]
    pub candidates: usize,
    /// Optimality criterion: a (A-optimal, least sum of the four predicted variances)
    /// or d (D-optimal, greatest log det JᵀJ).
    #[arg(long, default_value = "a", value_parser = crate::args::criterion())]
    pub criterion: Criterion,
    /// Sensor convention (rpy or axis).
    #[arg(long, default_value = "rpy", value_parser = crate::args::convention())]
    pub convention: Convention,
    /// Base tilt α,β from stage 1 (deg), so the plan's readings are those the robot
    /// will show. Range: each [-10, 10] deg.
    #[arg(long, value_name = "A,B", value_parser = TILT_PAIR, allow_hyphen_values = true)]
    pub base_tilt_deg: Option<(f64, f64)>,
    /// Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file.
    /// Its joint limits apply unless `--limits` overrides them; joints 1 and 2 stay at
    /// its stage-1 pose.
    #[arg(long, value_name = "NAME", default_value = "paper-wrist")]
    pub robot: String,
    /// Print one JSON object.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV rows j3_deg,j4_deg,j5_deg,j6_deg.
    #[arg(long)]
    pub csv: bool,
}

/// Per-joint (min, max) limits of joints 3-6 (deg).
pub type LimitsDeg = [(f64, f64); WRIST_JOINTS];

/// Parses a limits file (format in the module doc). Errors name the line and field.
pub fn parse_limits(text: &str) -> Result<LimitsDeg, String> {
    let mut limits = [(-180.0, 180.0); WRIST_JOINTS];
    let mut seen = [false; WRIST_JOINTS];
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields
            .first()
            .is_some_and(|f| f.eq_ignore_ascii_case("joint"))
        {
            continue; // header
        }
        if fields.len() != 3 {
            return Err(format!(
                "limits line {line_no}: expected 3 fields joint,min_deg,max_deg, got {}",
                fields.len()
            ));
        }
        let joint: usize = fields[0]
            .parse()
            .ok()
            .filter(|j| (3..=6).contains(j))
            .ok_or_else(|| {
                format!(
                    "limits line {line_no}: field joint: '{}' is not a joint 3-6",
                    fields[0]
                )
            })?;
        let num = |k: usize, name: &str| -> Result<f64, String> {
            fields[k]
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "limits line {line_no}: field {name}: '{}' is not a finite number",
                        fields[k]
                    )
                })
        };
        let (lo, hi) = (num(1, "min_deg")?, num(2, "max_deg")?);
        if lo > hi {
            return Err(format!(
                "limits line {line_no}: min_deg {lo} is above max_deg {hi}"
            ));
        }
        let k = joint - 3;
        if seen[k] {
            return Err(format!(
                "limits line {line_no}: joint {joint} is listed twice"
            ));
        }
        seen[k] = true;
        limits[k] = (lo, hi);
    }
    Ok(limits)
}

/// The `--json` output.
#[derive(Serialize, Debug)]
pub struct PlanJson {
    /// Robot profile.
    pub robot: String,
    /// θ1..θ6 per pose in the model's angles (deg): what the pendant's `plan set` takes.
    pub poses_deg: Vec<[f64; JOINTS]>,
    /// The same poses as the robot's controller shows them (deg).
    pub poses_controller_deg: Vec<[f64; JOINTS]>,
    /// Predicted 1σ of Δθ3..Δθ6 (deg).
    pub predicted_sigma_deg: [f64; WRIST_JOINTS],
    /// Condition number of the plan's Jacobian.
    pub condition_number: f64,
    /// Largest |reading| at zero offsets (deg).
    pub max_reading_deg: f64,
    /// Window (± deg).
    pub window_deg: f64,
    /// Margin (deg).
    pub margin_deg: f64,
    /// Limits used (deg).
    pub limits_deg: LimitsDeg,
    /// Uniform noise half-width (deg).
    pub noise_deg: f64,
    /// Criterion ("a" or "d").
    pub criterion: &'static str,
    /// Seed.
    pub seed: u64,
}

impl PlanArgs {
    /// The limits of joints 3-6: the file's, else the profile's.
    pub fn limits_deg(&self, profile: &Profile) -> Result<LimitsDeg, CliError> {
        match &self.limits {
            None => Ok(core::array::from_fn(|k| {
                let j = &profile.joints[k + 2];
                (j.min_deg, j.max_deg)
            })),
            Some(path) => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| CliError::Input(format!("cannot read {}: {e}", path.display())))?;
                parse_limits(&text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
            }
        }
    }

    fn model(&self, profile: &Profile) -> Stage2Model<f64> {
        let (a, b) = self.base_tilt_deg.unwrap_or((0.0, 0.0));
        Stage2Model {
            arm: profile.arm,
            base_tilt: BaseTilt::from_deg(a, b),
            sensor: SensorModel::new(self.convention, Tilt::default()),
            ..Stage2Model::default()
        }
    }

    /// The planner settings the flags give.
    pub fn config(&self, profile: &Profile) -> Result<PlanConfig<f64>, CliError> {
        let limits = self.limits_deg(profile)?;
        let q1 = profile.stage1_joints_rad;
        Ok(PlanConfig {
            poses: self.poses,
            window_rad: deg_to_rad(self.window_deg),
            margin_rad: deg_to_rad(self.margin_deg),
            limits_rad: limits.map(|(lo, hi)| (deg_to_rad(lo), deg_to_rad(hi))),
            fixed_joints_rad: [q1[0], q1[1]],
            seed: self.seed,
            candidates: self.candidates,
            noise_sigma_rad: deg_to_rad(self.noise_deg / 3f64.sqrt()),
            criterion: self.criterion,
            ..PlanConfig::default()
        })
    }
}

/// Maps a planner error to the CLI's: bad settings are input errors (status 2), an
/// unobservable or unreachable plan is refused (status 3).
fn cli_error(e: PlanError) -> CliError {
    match e {
        PlanError::InvalidSetting(_)
        | PlanError::TooFewPoses { .. }
        | PlanError::TooManyPoses { .. }
        | PlanError::PoolTooSmall { .. } => CliError::Input(e.to_string()),
        PlanError::WindowUnreachable { .. } | PlanError::Unobservable(_) => {
            CliError::Refused(e.to_string())
        }
    }
}

/// Plans the poses the flags ask for.
///
/// # Errors
/// Bad flags or limits file (status 2); a plan that cannot separate the parameters or
/// reach the window inside the limits (status 3).
pub fn make_plan(args: &PlanArgs) -> Result<(Profile, PlanConfig<f64>, Plan<f64>), CliError> {
    let profile = crate::robot::load(&args.robot)?;
    let config = args.config(&profile)?;
    let model = args.model(&profile);
    let mut pool = vec![Candidate::default(); args.candidates.max(1)];
    let p = plan(&model, &config, &mut pool).map_err(cli_error)?;
    Ok((profile, config, p))
}

/// Runs `zerocal plan`: the text to print on stdout.
///
/// # Errors
/// As [`make_plan`].
pub fn run(args: &PlanArgs) -> Result<String, CliError> {
    let (profile, config, p) = make_plan(args)?;
    let poses_deg: Vec<[f64; JOINTS]> = p.poses_rad.iter().map(|q| q.map(rad_to_deg)).collect();
    let shown: Vec<[f64; JOINTS]> = p.poses_rad.iter().map(|q| profile.shown_deg(q)).collect();
    let sigma_deg = p.predicted_sigma_deg();
    if args.csv {
        // Model degrees, six joints: what the pendant's `plan set` takes.
        let mut out = String::from("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg\n");
        for q in &poses_deg {
            let row: Vec<String> = q.iter().map(|v| format!("{v:.4}")).collect();
            let _ = writeln!(out, "{}", row.join(","));
        }
        return Ok(out);
    }
    if args.json {
        let j = PlanJson {
            robot: profile.name.clone(),
            poses_deg,
            poses_controller_deg: shown,
            predicted_sigma_deg: sigma_deg,
            condition_number: p.condition_number,
            max_reading_deg: rad_to_deg(p.max_reading_rad),
            window_deg: args.window_deg,
            margin_deg: args.margin_deg,
            limits_deg: config
                .limits_rad
                .map(|(lo, hi)| (rad_to_deg(lo), rad_to_deg(hi))),
            noise_deg: args.noise_deg,
            criterion: args.criterion.name(),
            seed: args.seed,
        };
        return serde_json::to_string_pretty(&j)
            .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{} planned poses (readings within +/-{:.2} deg at zero offsets, window +/-{} deg; {} candidates from {} draws, {} exchanges)",
        p.poses_rad.len(),
        rad_to_deg(config.window_rad - config.margin_rad),
        args.window_deg,
        p.candidates,
        p.draws,
        p.exchanges
    );
    let _ = writeln!(
        out,
        "robot {} ({}); joints as its controller shows them (deg):",
        profile.name, profile.title
    );
    let names: Vec<String> = profile
        .joints
        .iter()
        .map(|j| format!("{:>9}", j.name))
        .collect();
    let _ = writeln!(out, "pose {}", names.join("  "));
    for (i, q) in shown.iter().enumerate() {
        let row: Vec<String> = q.iter().map(|v| format!("{v:>9.4}")).collect();
        let _ = writeln!(out, "{:>4} {}", i + 1, row.join("  "));
    }
    let _ = writeln!(
        out,
        "predicted 1-sigma (deg), noise uniform +/-{} deg: j3 {:.6}  j4 {:.6}  j5 {:.6}  j6 {:.6}",
        args.noise_deg, sigma_deg[0], sigma_deg[1], sigma_deg[2], sigma_deg[3]
    );
    let _ = writeln!(
        out,
        "condition number {:.2}, largest reading {:.3} deg",
        p.condition_number,
        rad_to_deg(p.max_reading_rad)
    );
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Wrap {
        #[command(flatten)]
        args: PlanArgs,
    }

    fn args(flags: &[&str]) -> PlanArgs {
        let mut v = vec!["plan"];
        v.extend_from_slice(flags);
        match Wrap::try_parse_from(v) {
            Ok(w) => w.args,
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn limits_file_parses_and_names_bad_lines() {
        let ok = parse_limits("# KR 6\njoint,min_deg,max_deg\n3,-170,170\n4, -30 , 30\n");
        assert_eq!(
            ok,
            Ok([
                (-170.0, 170.0),
                (-30.0, 30.0),
                (-180.0, 180.0),
                (-180.0, 180.0)
            ])
        );
        let e = parse_limits("3,-170,170\n5,-10,abc\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("max_deg"), "{e}");
        let e = parse_limits("7,0,1\n").unwrap_err();
        assert!(e.contains("line 1") && e.contains("joint"), "{e}");
        let e = parse_limits("3,1,0\n").unwrap_err();
        assert!(e.contains("above"), "{e}");
        let e = parse_limits("3,0,1\n3,0,1\n").unwrap_err();
        assert!(e.contains("twice"), "{e}");
        let e = parse_limits("3,0\n").unwrap_err();
        assert!(e.contains("3 fields"), "{e}");
    }

    #[test]
    fn csv_and_json_outputs() {
        let csv = run(&args(&["--poses", "6", "--csv"])).unwrap_or_else(|e| panic!("{e}"));
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg");
        assert_eq!(lines.len(), 7);
        let json = run(&args(&["--poses", "6", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["poses_deg"].as_array().map(Vec::len), Some(6));
        assert_eq!(v["predicted_sigma_deg"].as_array().map(Vec::len), Some(4));
        let text = run(&args(&[])).unwrap_or_else(|e| panic!("{e}"));
        println!("{text}");
        assert!(text.contains("predicted 1-sigma"), "{text}");
    }

    #[test]
    fn exit_statuses() {
        // Bad input is refused when the flags are parsed: status 2, naming the range.
        for (flag, value, range) in [
            ("--poses", "2", "[4, 48]"),
            ("--noise-deg", "0", "(0, 1] deg"),
        ] {
            let e = Wrap::try_parse_from(["plan", flag, value])
                .err()
                .unwrap_or_else(|| panic!("{flag} {value} accepted"));
            assert_eq!(e.exit_code(), 2, "{e}");
            assert!(e.to_string().contains(range), "{e}");
        }
        // A margin within its own range but not below the window: status 2 as well.
        let e = run(&args(&["--window-deg", "5", "--margin-deg", "6"])).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        // θ4 pinned: j3 and j5 inseparable, refused with status 3 naming them.
        let dir = std::env::temp_dir().join(format!("zerocal-plan-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let f = dir.join("limits.csv");
        let _ = std::fs::write(&f, "4,0,0\n");
        let path = f.to_string_lossy().into_owned();
        let e = run(&args(&["--limits", &path])).unwrap_err();
        assert_eq!(e.exit_code(), 3, "{e}");
        assert!(e.to_string().contains("j3+j5"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
