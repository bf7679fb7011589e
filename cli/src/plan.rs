//! `zerocal plan`: the stage-2 poses to send the robot to, planned before it moves
//! (`zerocal_core::plan`), with what they promise: the predicted 1σ and k = 2
//! uncertainty per joint, the worst correlation between the parameters (naming the
//! poorly separated ones), and the session's robot time (`crate::timing`).
//!
//! The poses come in the order that makes the session short (a joint-space tour,
//! `crate::timing::time_order`): the order the pendant's plan and the robot program
//! (`zerocal program`) must both follow. They lie inside the joint limits less the room
//! the two captures of a pose need (`crate::timing::planner_limits`: every pose is
//! captured from below and from above on every joint). `--target-k2-deg U` asks for the
//! fewest poses whose predicted k = 2 uncertainty is at most U on every joint, through
//! one function, [`predicted_k2_deg`] (core's `predict_budget`).
//!
//! Output: a table (default), `--csv` (header `j1_deg,...,j6_deg`, model degrees, one
//! row per pose, nothing else on stdout) or `--json` (one object: `poses_deg`,
//! `predicted_sigma_deg`, `predicted_k2_deg`, `correlation`, `robot_time`, settings).
//!
//! `--limits FILE` narrows the profile's joint limits: CSV, one joint per line, by
//! number (1-6) or by the profile's name for it (`A5`), model degrees:
//!
//! ```text
//! # joint,min_deg,max_deg     (a header line and '#' comments are allowed)
//! joint,min_deg,max_deg
//! 3,-170,170
//! A5,-100,100
//! ```
//! Joints not listed keep the profile's limits; a listed joint's limits must lie
//! within the profile's (a wider range is the profile's to state: `zerocal program`
//! checks every point against it). A bad line is named by its number and field.
//!
//! `--noise-deg A` is the half-width of uniform reading noise ±A, as for `simulate`
//! (the paper's Table 4: 0.002): the predicted 1σ uses σ = A/√3 per reading.

use crate::args::{CountIn, RealIn, SEED, TILT_PAIR};
use crate::error::CliError;
use crate::timing::{self, Pendant, SessionPoses, SpeedSource, Timing, TimingArgs};
use clap::Args;
use serde::Serialize;
use std::fmt::Write;
use std::path::PathBuf;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{plan, Candidate, Criterion, Plan, PlanConfig, PlanError, MAX_POSES};
use zerocal_core::real::{deg_to_rad, rad_to_deg};
use zerocal_core::session::{
    predict_budget, BudgetInputs, PlannedRobot, DEFAULT_LOST_MOTION_DEG, DEFAULT_REPEATABILITY_DEG,
};
use zerocal_core::stage2::{information, Extras, FitConfig, Stage2Model, MIN_POSES};
use zerocal_procedure::robot_time::{SessionTime, CAPTURES_PER_POSE};
use zerocal_profile::Profile;

/// A parameter pair whose |correlation| exceeds this is named as poorly separated:
/// at 0.9 the pair's difference is known √(1/(1−0.9)) ≈ 3× worse than if they were
/// independent (a stated example figure).
pub const POORLY_SEPARATED: f64 = 0.9;

/// Arguments of `zerocal plan`.
#[derive(Args, Debug, Clone)]
pub struct PlanArgs {
    /// Poses to plan (`zerocal_core::plan::MAX_POSES` at most; the SCL3300's model
    /// needs 24 for its 13-17 parameters: docs/error-budget.md). Range: [4, 48].
    #[arg(long, default_value_t = zerocal_sim::montecarlo::DEFAULT_POSES, value_parser = CountIn::<usize>::new(4, 48))]
    pub poses: usize,
    /// Sensor window: readings must stay within ±W degrees. Range: (0, 90] deg.
    #[arg(long, default_value_t = 10.0, value_name = "W", value_parser = RealIn::above(0.0, 90.0, "deg"))]
    pub window_deg: f64,
    /// Planned readings stay within ±(W − margin) at zero offsets, leaving room for
    /// the offsets not yet known and the sensor's offset (up to 1.45° on an SCL3300):
    /// 3° by default, chosen by Monte-Carlo (docs/error-budget.md) (deg); it must also
    /// be smaller than W. Range: [0, 90] deg.
    #[arg(long, default_value_t = 10.0 - zerocal_sim::montecarlo::PLAN_WINDOW_DEG, value_parser = RealIn::closed(0.0, 90.0, "deg"))]
    pub margin_deg: f64,
    /// Narrower joint limits than the profile's: CSV lines `joint,min_deg,max_deg`,
    /// the joint by number (1-6) or name (`A5`), model degrees; joints not listed keep
    /// the profile's.
    #[arg(long, value_name = "FILE")]
    pub limits: Option<PathBuf>,
    /// Reading noise: uniform in ±A degrees (σ = A/√3). Default: for `axis`, one
    /// SCL3300 capture's noise (σ 0.0008°); for `rpy`, the paper's ±0.002°.
    /// Range: (0, 1] deg.
    #[arg(long, value_name = "A", value_parser = RealIn::above(0.0, 1.0, "deg"))]
    pub noise_deg: Option<f64>,
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
    /// Sensor convention: axis (the pendant's SCL3300: the plan then separates its gain,
    /// cross-axis and the sag too, and each pose is captured from both sides of the
    /// backlash) or rpy (the paper's ideal sensor).
    #[arg(long, default_value = "axis", value_parser = crate::args::convention())]
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
    /// Print CSV rows j1_deg..j6_deg (model degrees, in the session's order).
    #[arg(long)]
    pub csv: bool,
    /// Plan the fewest poses whose predicted k = 2 uncertainty is at most U on every
    /// joint (j2 from stage 1, j3-j6 from the plan); --poses is then searched from 4
    /// up. Range: (0, 1] deg.
    #[arg(long, value_name = "U", conflicts_with = "poses", value_parser = RealIn::above(0.0, 1.0, "deg"))]
    pub target_k2_deg: Option<f64>,
    /// The session's robot time.
    #[command(flatten)]
    pub timing: TimingArgs,
}

/// Per-joint (min, max) limits of joints 3-6 (deg).
pub type LimitsDeg = [(f64, f64); WRIST_JOINTS];

/// The limits a limits file lists (format in the module doc), per joint 1-6 (model
/// degrees); `names` are the profile's joint names. Errors name the line and field.
pub fn parse_limits(
    text: &str,
    names: &[String; JOINTS],
) -> Result<[Option<(f64, f64)>; JOINTS], String> {
    let mut limits = [None; JOINTS];
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
        let k = fields[0]
            .parse::<usize>()
            .ok()
            .filter(|j| (1..=JOINTS).contains(j))
            .map(|j| j - 1)
            .or_else(|| names.iter().position(|n| n.eq_ignore_ascii_case(fields[0])))
            .ok_or_else(|| {
                format!(
                    "limits line {line_no}: field joint: '{}' is not a joint 1-6 or one of the profile's {}",
                    fields[0].chars().take(16).collect::<String>(),
                    names.join(", ")
                )
            })?;
        let num = |f: usize, name: &str| -> Result<f64, String> {
            fields[f]
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "limits line {line_no}: field {name}: '{}' is not a finite number",
                        fields[f].chars().take(32).collect::<String>()
                    )
                })
        };
        let (lo, hi) = (num(1, "min_deg")?, num(2, "max_deg")?);
        if lo > hi {
            return Err(format!(
                "limits line {line_no}: min_deg {lo} is above max_deg {hi}"
            ));
        }
        if limits[k].is_some() {
            return Err(format!(
                "limits line {line_no}: joint {} is listed twice",
                k + 1
            ));
        }
        limits[k] = Some((lo, hi));
    }
    Ok(limits)
}

/// `profile` with the limits a limits file lists (`name` names the file in
/// messages); the joints it does not list keep the profile's.
///
/// # Errors
/// A malformed line; a listed range wider than the profile's (naming the joint).
pub fn narrow_limits(mut profile: Profile, text: &str, name: &str) -> Result<Profile, CliError> {
    let names: [String; JOINTS] = core::array::from_fn(|k| {
        profile
            .joints
            .get(k)
            .map_or_else(|| format!("J{}", k + 1), |j| j.name.clone())
    });
    let labels: [String; JOINTS] = core::array::from_fn(|k| timing::joint_label(&profile, k));
    let listed = parse_limits(text, &names).map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    let robot = profile.name.clone();
    for ((j, l), label) in profile.joints.iter_mut().zip(listed).zip(labels) {
        let Some((lo, hi)) = l else { continue };
        if lo < j.min_deg || hi > j.max_deg {
            return Err(CliError::Input(format!(
                "{name}: {label}: {lo}..{hi} deg reaches outside profile {robot}'s limits {}..{} deg; --limits only narrows them (a wider range belongs in the profile, which zerocal program checks every point against)",
                j.min_deg, j.max_deg
            )));
        }
        (j.min_deg, j.max_deg) = (lo, hi);
    }
    Ok(profile)
}

/// The worst correlation between two parameters of the plan.
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct Correlation {
    /// The two parameters (`j3`..`j6`).
    pub params: [&'static str; 2],
    /// Their correlation coefficient.
    pub value: f64,
}

/// The correlations of the plan's parameters (the stage-2 offsets).
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct Correlations {
    /// The parameters, in the matrix's order.
    pub params: Vec<&'static str>,
    /// Correlation coefficients of (JᵀJ)⁻¹.
    pub matrix: Vec<Vec<f64>>,
    /// The largest |coefficient| off the diagonal.
    pub worst: Correlation,
    /// Every pair with |coefficient| above [`POORLY_SEPARATED`].
    pub poorly_separated: Vec<Correlation>,
    /// The threshold.
    pub threshold: f64,
}

/// The session's robot time in `--json`.
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct RobotTimeJson {
    /// All of it (s).
    pub total_s: f64,
    /// Moving (s).
    pub motion_s: f64,
    /// Standing for settling and the pendant's still window (s).
    pub dwell_s: f64,
    /// The pendant's remount (s).
    pub remount_s: f64,
    /// Operator OKs at the pendant (s).
    pub operator_s: f64,
    /// Moves.
    pub moves: u16,
    /// Captures: two per pose (stage 1's two and every stage-2 pose), the closing
    /// reversal's two.
    pub captures: u16,
    /// Mountings of the pendant (upper arm, flange, the bench for the closing
    /// reversal).
    pub mountings: u16,
    /// Stops for an operator's OK.
    pub ok_stops: u16,
    /// Joint speed, % of each joint's maximum.
    pub speed_percent: u8,
    /// Each joint's maximum speed (deg/s).
    pub max_speed_deg_s: [f64; JOINTS],
    /// Where each comes from.
    pub max_speed_source: [SpeedSource; JOINTS],
    /// Each joint's acceleration (deg/s², stated default).
    pub accel_deg_s2: [f64; JOINTS],
    /// Settling per pose (s).
    pub settle_s: f64,
    /// The wait at each capture (s): settling, still window, two sensor periods.
    pub dwell_per_capture_s: f64,
    /// Captures of every pose: first with every joint arriving from below, then from
    /// above.
    pub captures_per_pose: usize,
    /// How far below a pose every joint starts the last move to its first capture
    /// (controller degrees).
    pub approach_deg: f64,
    /// How far above a pose every joint goes before coming back for its second capture
    /// (controller degrees).
    pub overshoot_deg: f64,
    /// Why `zerocal program` would refuse this session (a capture pose without room
    /// on both sides inside the joint limits, say), if it would.
    pub program_refused: Option<String>,
}

/// The `--json` output.
#[derive(Serialize, Debug)]
pub struct PlanJson {
    /// Robot profile.
    pub robot: String,
    /// θ1..θ6 per pose in the model's angles (deg), in the session's order: what the
    /// pendant's `plan set` takes.
    pub poses_deg: Vec<[f64; JOINTS]>,
    /// The same poses as the robot's controller shows them (deg).
    pub poses_controller_deg: Vec<[f64; JOINTS]>,
    /// Predicted 1σ of Δθ3..Δθ6 (deg).
    pub predicted_sigma_deg: [f64; WRIST_JOINTS],
    /// Predicted k = 2 uncertainty of Δθ2..Δθ6 (deg): [`predicted_k2_deg`].
    pub predicted_k2_deg: [f64; WRIST_JOINTS + 1],
    /// What the prediction includes.
    pub predicted_from: &'static str,
    /// The target asked for (deg), if any.
    pub target_k2_deg: Option<f64>,
    /// Correlations of the plan's parameters.
    pub correlation: Correlations,
    /// The session's robot time.
    pub robot_time: RobotTimeJson,
    /// Condition number of the plan's Jacobian.
    pub condition_number: f64,
    /// Largest |reading| at zero offsets (deg).
    pub max_reading_deg: f64,
    /// Window (± deg).
    pub window_deg: f64,
    /// Margin (deg).
    pub margin_deg: f64,
    /// Limits the poses were planned inside (model degrees): the profile's or
    /// `--limits`', less the room the approach from below and the overshoot above need.
    pub limits_deg: LimitsDeg,
    /// The capture noise assumed, 1σ (deg).
    pub noise_sigma_deg: f64,
    /// What the plan separates besides the offsets.
    pub fitted: Vec<&'static str>,
    /// Captures per pose the prediction assumes.
    pub captures_per_pose: usize,
    /// Criterion ("a" or "d").
    pub criterion: &'static str,
    /// Seed.
    pub seed: u64,
}

impl PlanArgs {
    /// The robot profile `--robot` names, its limits narrowed by `--limits`.
    ///
    /// # Errors
    /// A profile or a limits file that does not read; limits wider than the profile's.
    pub fn profile(&self) -> Result<Profile, CliError> {
        let profile = crate::robot::load(&self.robot)?;
        match &self.limits {
            None => Ok(profile),
            Some(path) => {
                let text =
                    crate::input::read_capped(path, crate::input::MAX_LIMITS_BYTES, "limits file")?;
                narrow_limits(profile, &text, &path.display().to_string())
            }
        }
    }

    /// The limits of joints 3-6: the profile's (narrowed by `--limits` in
    /// [`profile`](Self::profile)).
    pub fn limits_deg(profile: &Profile) -> LimitsDeg {
        // A profile has six joints (checked when it is read).
        core::array::from_fn(|k| (profile.joints[k + 2].min_deg, profile.joints[k + 2].max_deg))
    }

    /// The stage-2 model the plan is made for: the profile's arm, the given base tilt,
    /// the convention, no bias.
    pub fn model(&self, profile: &Profile) -> Stage2Model<f64> {
        let (a, b) = self.base_tilt_deg.unwrap_or((0.0, 0.0));
        Stage2Model {
            arm: profile.arm,
            base_tilt: BaseTilt::from_deg(a, b),
            sensor: SensorModel::new(self.convention, Tilt::default()),
            masses: profile.mass_model(),
            y_weight: match self.convention {
                Convention::Axis => zerocal_core::stage2::MEMS_Y_WEIGHT,
                Convention::Rpy => 1.0,
            },
            ..Stage2Model::default()
        }
    }

    /// The fit the session will run: `zerocal session`'s for this convention, with
    /// `--noise-deg` if given.
    pub fn fit_config(&self, profile: &Profile) -> FitConfig<f64> {
        let mut fit = crate::session::fit_config(self.convention, profile);
        if let Some(a) = self.noise_deg {
            fit.sensor_noise_rad = deg_to_rad(a / 3f64.sqrt());
        }
        fit
    }

    /// Captures per pose: two (one from each side of the backlash) with the SCL3300,
    /// one for the paper's sensor.
    pub fn captures_per_pose(&self) -> usize {
        match self.convention {
            Convention::Axis => 2,
            Convention::Rpy => 1,
        }
    }

    /// The planner settings the flags give: the limits less the room the two captures
    /// of a pose need on either side (`crate::timing::planner_limits`).
    pub fn config(&self, profile: &Profile) -> Result<PlanConfig<f64>, CliError> {
        let full = Self::limits_deg(profile);
        let limits = timing::planner_limits(profile, &full);
        for (k, ((lo, hi), (flo, fhi))) in limits.iter().zip(&full).enumerate() {
            if lo > hi {
                return Err(CliError::Input(format!(
                    "limits of joint {}: {flo}..{fhi} deg leave no room for the two captures of a pose (every joint reached from {} deg below it and from {} deg above it: {:.3} deg below and {:.3} deg above in model angles)",
                    k + 3,
                    timing::APPROACH_DEG,
                    timing::OVERSHOOT_DEG,
                    lo - flo,
                    fhi - hi
                )));
            }
        }
        let q1 = profile.stage1_joints_rad;
        Ok(PlanConfig {
            poses: self.poses,
            window_rad: deg_to_rad(self.window_deg),
            margin_rad: deg_to_rad(self.margin_deg),
            limits_rad: limits.map(|(lo, hi)| (deg_to_rad(lo), deg_to_rad(hi))),
            fixed_joints_rad: [q1[0], q1[1]],
            seed: self.seed,
            candidates: self.candidates,
            noise_sigma_rad: self.fit_config(profile).sensor_noise_rad,
            extras: self.fit_config(profile).extras,
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

/// What [`predicted_k2_deg`] includes (printed beside the figures).
pub const PREDICTED_FROM: &str = "the session's budget predicted before the robot moves (core's predict_budget): stages 0-1 handed over, the plan's readings with the sensor's noise, the cost of estimating the sensor's gain and cross-axis, the sag and the flange bracket's tilt, and the robot's repeatability (0.0015 deg per joint); not the brackets' seats";

/// The predicted k = 2 uncertainty of Δθ2..Δθ6 (deg) of a session on `profile` with
/// the stage-2 poses `poses_rad` (model angles), per-reading noise 1σ
/// `noise_sigma_rad`: j2 from stage 1's two readings at the profile's stage-1 pose
/// (with a stage-0 bias), j3-j6 from core's covariance bound of the poses.
///
/// The one function the target search calls: a fuller uncertainty budget (stage 0-1's
/// hand-over, the sensor's and the robot's error terms) replaces its body.
///
/// # Errors
/// A pose set the bound refuses (too few poses, rank deficient: naming the
/// parameters), or a stage-1 pose the two readings cannot resolve.
pub fn predicted_k2_deg(
    profile: &Profile,
    model: &Stage2Model<f64>,
    poses_rad: &[[f64; JOINTS]],
    fit: &FitConfig<f64>,
    captures_per_pose: usize,
) -> Result<[f64; WRIST_JOINTS + 1], CliError> {
    let robot = PlannedRobot {
        arm: profile.arm,
        masses: model.masses,
        convention: model.sensor.convention,
        stage1_joints_rad: profile.stage1_joints_rad,
    };
    let b = predict_budget(
        &robot,
        poses_rad,
        captures_per_pose,
        fit,
        &BudgetInputs {
            extras: fit.extras,
            mount_tolerance_rad: 0.0,
            repeatability_rad: DEFAULT_REPEATABILITY_DEG.to_radians(),
            lost_motion_rad: DEFAULT_LOST_MOTION_DEG.to_radians(),
        },
    )
    .map_err(|e| CliError::Refused(format!("plan refused: {e}")))?;
    Ok(b.expanded_rad.map(rad_to_deg))
}

/// The correlations of Δθ3..Δθ6 on a pose set, from (JᵀJ)⁻¹.
///
/// # Errors
/// A singular information matrix.
pub fn correlations(
    model: &Stage2Model<f64>,
    extras: Extras,
    poses_rad: &[[f64; JOINTS]],
) -> Result<Correlations, CliError> {
    let gram = information(model, extras, poses_rad, &[0.0; WRIST_JOINTS]).gram();
    let singular = || CliError::Refused("plan refused: its information matrix is singular".into());
    let l = gram.cholesky().ok_or_else(singular)?;
    let ui = l.transpose().upper_inverse().ok_or_else(singular)?;
    let cov = ui.mul(&ui.transpose());
    let layout = extras.layout();
    let n = layout.len();
    let params: Vec<&'static str> = layout.params().iter().map(|p| p.name()).collect();
    let mut matrix = vec![vec![0.0; n]; n];
    let mut worst = Correlation {
        params: [params[0], params[1]],
        value: 0.0,
    };
    let mut poorly_separated = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let r = cov.m[i][j] / (cov.m[i][i] * cov.m[j][j]).sqrt();
            matrix[i][j] = r;
            if j > i {
                let c = Correlation {
                    params: [params[i], params[j]],
                    value: r,
                };
                if r.abs() > worst.value.abs() {
                    worst = c.clone();
                }
                if r.abs() > POORLY_SEPARATED {
                    poorly_separated.push(c);
                }
            }
        }
    }
    Ok(Correlations {
        params,
        matrix,
        worst,
        poorly_separated,
        threshold: POORLY_SEPARATED,
    })
}

/// A plan with everything `zerocal plan` reports of it.
#[derive(Clone, Debug)]
pub struct SessionPlan {
    /// The robot.
    pub profile: Profile,
    /// The planner's settings.
    pub config: PlanConfig<f64>,
    /// The plan, its poses in the session's order.
    pub plan: Plan<f64>,
    /// The poses in the controller's terms.
    pub poses: SessionPoses,
    /// The time model.
    pub timing: Timing,
    /// The robot time in this order.
    pub time: SessionTime<f64>,
    /// The same poses' robot time in the planner's own order.
    pub time_unordered: SessionTime<f64>,
    /// Why `zerocal program` would refuse the session, if it would
    /// (`crate::timing::check_room`).
    pub program_refused: Option<String>,
    /// [`predicted_k2_deg`].
    pub k2_deg: [f64; WRIST_JOINTS + 1],
    /// The correlations.
    pub correlation: Correlations,
}

/// Plans `poses` poses with the flags' other settings, unordered.
fn plan_n(
    args: &PlanArgs,
    profile: &Profile,
    poses: usize,
) -> Result<(PlanConfig<f64>, Plan<f64>), CliError> {
    let mut config = args.config(profile)?;
    config.poses = poses;
    let model = args.model(profile);
    let mut pool = vec![Candidate::default(); args.candidates.max(1)];
    let p = plan(&model, &config, &mut pool).map_err(cli_error)?;
    Ok((config, p))
}

/// Puts a plan's poses in the session's order and works out what it promises.
///
/// # Errors
/// A pose whose approach leaves the joint limits; a plan the bound refuses.
pub fn session_plan(
    args: &PlanArgs,
    profile: Profile,
    config: PlanConfig<f64>,
    mut p: Plan<f64>,
) -> Result<SessionPlan, CliError> {
    let model = args.model(&profile);
    let unordered = SessionPoses::new(&profile, &p.poses_rad).with_mounts(&profile)?;
    let t = Timing::new(&profile, &args.timing)?;
    let pendant = Pendant::new(&profile);
    let time_unordered = timing::session_time(&pendant, &t.model, &unordered);
    let toured = timing::time_order(&pendant, &t.model, &unordered);
    let candidate = unordered.reordered(&profile, &toured)?;
    // The tour leaves out the legs that depend on the first and last pose (the
    // flange's mounting, the park): keep the planner's order if it is shorter in all.
    let (order, poses) =
        if timing::session_time(&pendant, &t.model, &candidate).total_s <= time_unordered.total_s {
            (toured, candidate)
        } else {
            ((0..unordered.poses.len()).collect(), unordered)
        };
    let program_refused = timing::check_room(&profile, &poses).err().map(|e| match e {
        CliError::Input(m) | CliError::Refused(m) => m,
    });
    let original = p.poses_rad.clone();
    p.poses_rad.clear();
    for &i in &order {
        if let Some(q) = original.get(i) {
            // As many as there were: cannot overflow.
            let _ = p.poses_rad.push(*q);
        }
    }
    let time = timing::session_time(&pendant, &t.model, &poses);
    let fit = args.fit_config(&profile);
    let k2_deg = predicted_k2_deg(
        &profile,
        &model,
        &p.poses_rad,
        &fit,
        args.captures_per_pose(),
    )?;
    let correlation = correlations(&model, fit.extras, &p.poses_rad)?;
    Ok(SessionPlan {
        profile,
        config,
        plan: p,
        poses,
        timing: t,
        time,
        time_unordered,
        program_refused,
        k2_deg,
        correlation,
    })
}

/// Residual degrees of freedom a plan leaves at least: the session takes σ from its
/// residuals, and with fewer than 20 (two readings a pose, less the parameters) that σ
/// is itself uncertain by more than 16 % (1/√(2·20)).
pub const MIN_RESIDUAL_DOF: usize = 20;

/// The fewest poses whose two readings each leave [`MIN_RESIDUAL_DOF`] beyond the
/// parameters `fit` estimates.
pub fn fewest_poses(fit: &FitConfig<f64>) -> usize {
    let params = fit.extras.layout().len();
    MIN_POSES.max((params + MIN_RESIDUAL_DOF).div_ceil(2))
}

/// Plans the poses the flags ask for, in the session's order, with what they
/// promise; with `--target-k2-deg`, the fewest poses that reach it.
///
/// # Errors
/// Bad flags or limits file (status 2); a plan that cannot separate the parameters or
/// reach the window inside the limits, or a target no plan reaches (status 3).
pub fn make_plan(args: &PlanArgs) -> Result<SessionPlan, CliError> {
    let profile = args.profile()?;
    let Some(target) = args.target_k2_deg else {
        let (config, p) = plan_n(args, &profile, args.poses)?;
        return session_plan(args, profile, config, p);
    };
    let model = args.model(&profile);
    let mut best: Option<(usize, [f64; WRIST_JOINTS + 1])> = None;
    let mut refusal = None;
    for n in fewest_poses(&args.fit_config(&profile))..=MAX_POSES {
        let (config, p) = match plan_n(args, &profile, n) {
            Ok(v) => v,
            // A plan this small may not separate the parameters: try more poses.
            Err(CliError::Refused(m)) => {
                refusal = Some(m);
                continue;
            }
            Err(e) => return Err(e),
        };
        let fit = args.fit_config(&profile);
        let k2 = predicted_k2_deg(
            &profile,
            &model,
            &p.poses_rad,
            &fit,
            args.captures_per_pose(),
        )?;
        if k2.iter().all(|u| *u <= target) {
            return session_plan(args, profile, config, p);
        }
        let worst = |k: &[f64; WRIST_JOINTS + 1]| k.iter().fold(0.0f64, |m, u| m.max(*u));
        if best.is_none_or(|(_, b)| worst(&k2) < worst(&b)) {
            best = Some((n, k2));
        }
    }
    let detail = match best {
        Some((n, k2)) => {
            let names = ["j2", "j3", "j4", "j5", "j6"];
            let over: Vec<String> = names
                .iter()
                .zip(k2)
                .filter(|(_, u)| *u > target)
                .map(|(name, u)| format!("{name} {u:.5}"))
                .collect();
            format!(
                "the best, {n} poses, predicts k=2 {} deg (j2 and j3 are set by stage 1's readings: more poses do not improve them)",
                over.join(", ")
            )
        }
        None => format!(
            "no plan of {MIN_POSES}-{MAX_POSES} poses separates the parameters ({})",
            refusal.unwrap_or_default()
        ),
    };
    Err(CliError::Refused(format!(
        "no plan of at most {MAX_POSES} poses reaches k=2 <= {target} deg on every joint: {detail}"
    )))
}

fn minutes(s: f64) -> String {
    format!("{:.1} min ({s:.0} s)", s / 60.0)
}

/// Runs `zerocal plan`: the text to print on stdout.
///
/// # Errors
/// As [`make_plan`].
pub fn run(args: &PlanArgs) -> Result<String, CliError> {
    let sp = make_plan(args)?;
    let (profile, config, p) = (&sp.profile, &sp.config, &sp.plan);
    let poses_deg: Vec<[f64; JOINTS]> = p.poses_rad.iter().map(|q| q.map(rad_to_deg)).collect();
    let shown = sp.poses.poses.clone();
    let sigma_deg = p.predicted_sigma_deg();
    if args.csv {
        // Model degrees, six joints: what the pendant's `plan set` takes.
        let mut out = String::from("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg\n");
        for q in &poses_deg {
            let row: Vec<String> = q.iter().map(|v| format!("{v:.6}")).collect();
            let _ = writeln!(out, "{}", row.join(","));
        }
        return Ok(out);
    }
    let t = &sp.time;
    let tm = &sp.timing;
    let robot_time = RobotTimeJson {
        total_s: t.total_s,
        motion_s: t.motion_s,
        dwell_s: t.dwell_s,
        remount_s: t.remount_s,
        operator_s: t.operator_s,
        moves: t.moves,
        captures: t.captures,
        mountings: t.mountings,
        ok_stops: t.ok_stops,
        speed_percent: tm.speed_percent,
        max_speed_deg_s: tm.max_speed_deg_s,
        max_speed_source: tm.speed_source,
        accel_deg_s2: tm.model.accel_deg_s2,
        settle_s: tm.model.settle_s,
        dwell_per_capture_s: tm.model.dwell_s(),
        captures_per_pose: CAPTURES_PER_POSE,
        approach_deg: tm.model.approach_deg,
        overshoot_deg: tm.model.overshoot_deg,
        program_refused: sp.program_refused.clone(),
    };
    if args.json {
        let j = PlanJson {
            robot: profile.name.clone(),
            poses_deg,
            poses_controller_deg: shown,
            predicted_sigma_deg: sigma_deg,
            predicted_k2_deg: sp.k2_deg,
            predicted_from: PREDICTED_FROM,
            target_k2_deg: args.target_k2_deg,
            correlation: sp.correlation.clone(),
            robot_time,
            condition_number: p.condition_number,
            max_reading_deg: rad_to_deg(p.max_reading_rad),
            window_deg: args.window_deg,
            margin_deg: args.margin_deg,
            limits_deg: config
                .limits_rad
                .map(|(lo, hi)| (rad_to_deg(lo), rad_to_deg(hi))),
            noise_sigma_deg: rad_to_deg(config.noise_sigma_rad),
            fitted: config.extras.layout().params()[WRIST_JOINTS..]
                .iter()
                .map(|p| p.name())
                .collect(),
            captures_per_pose: args.captures_per_pose(),
            criterion: args.criterion.name(),
            seed: args.seed,
        };
        return serde_json::to_string_pretty(&j)
            .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")));
    }
    let mut out = String::new();
    if let Some(target) = args.target_k2_deg {
        let _ = writeln!(
            out,
            "fewest poses with predicted k=2 <= {target} deg on j2-j6: {}",
            p.poses_rad.len()
        );
    }
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
        "robot {} ({}); joints as its controller shows them (deg), in the session's order:",
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
        "stage 2 alone, predicted 1-sigma (deg), {} capture(s) per pose of sigma {:.5} deg: j3 {:.6}  j4 {:.6}  j5 {:.6}  j6 {:.6}",
        args.captures_per_pose(),
        rad_to_deg(config.noise_sigma_rad),
        sigma_deg[0],
        sigma_deg[1],
        sigma_deg[2],
        sigma_deg[3]
    );
    let k2 = sp.k2_deg;
    let _ = writeln!(
        out,
        "predicted k=2 (deg): j2 {:.5}  j3 {:.5}  j4 {:.5}  j5 {:.5}  j6 {:.5}\n  ({PREDICTED_FROM})",
        k2[0], k2[1], k2[2], k2[3], k2[4]
    );
    let c = &sp.correlation;
    let _ = writeln!(
        out,
        "worst correlation {}-{} {:+.3}; poorly separated (|r| > {}): {}",
        c.worst.params[0],
        c.worst.params[1],
        c.worst.value,
        c.threshold,
        if c.poorly_separated.is_empty() {
            "none".to_owned()
        } else {
            c.poorly_separated
                .iter()
                .map(|p| format!("{}-{} {:+.3}", p.params[0], p.params[1], p.value))
                .collect::<Vec<_>>()
                .join(", ")
        }
    );
    let _ = writeln!(
        out,
        "condition number {:.2}, largest reading {:.3} deg",
        p.condition_number,
        rad_to_deg(p.max_reading_rad)
    );
    let defaults: Vec<String> = (0..JOINTS)
        .filter(|&k| tm.speed_source[k] == SpeedSource::StatedDefault)
        .map(|k| timing::joint_label(profile, k))
        .collect();
    let _ = writeln!(
        out,
        "robot time {}: motion {:.0} s, dwell {:.0} s ({} captures x {:.1} s), pendant mountings {:.0} s ({}), operator OKs {:.0} s ({} stops); planner's order {}",
        minutes(t.total_s),
        t.motion_s,
        t.dwell_s,
        t.captures,
        tm.model.dwell_s(),
        t.remount_s,
        t.mountings,
        t.operator_s,
        t.ok_stops,
        minutes(sp.time_unordered.total_s),
    );
    let _ = writeln!(
        out,
        "  every pose captured twice (stage 1's two and the {} of the plan): every joint arriving from {} deg below, then from {} deg above; then the closing reversal on the bench (a mounting, 2 captures, 1 OK)",
        p.poses_rad.len(),
        tm.model.approach_deg,
        tm.model.overshoot_deg,
    );
    let _ = writeln!(
        out,
        "  joints at {} % of their maximum speed ({}), acceleration {:.1} deg/s^2 (stated default), settling {} s, each mounting {} s, OK {} s (stated defaults)",
        tm.speed_percent,
        if defaults.is_empty() {
            "the profile's".to_owned()
        } else {
            format!(
                "{} deg/s stated default for {} (not given by the profile)",
                timing::DEFAULT_JOINT_SPEED_DEG_S,
                defaults.join(", ")
            )
        },
        tm.model.accel_deg_s2[0],
        tm.model.settle_s,
        tm.model.remount_s,
        tm.model.operator_ok_s,
    );
    if let Some(why) = &sp.program_refused {
        let _ = writeln!(out, "zerocal program would refuse this session: {why}");
    }
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
        let names: [String; JOINTS] = core::array::from_fn(|k| format!("A{}", k + 1));
        let ok = parse_limits(
            "# KR 6\njoint,min_deg,max_deg\n3,-170,170\na4, -30 , 30\n",
            &names,
        );
        assert_eq!(
            ok,
            Ok([
                None,
                None,
                Some((-170.0, 170.0)),
                Some((-30.0, 30.0)),
                None,
                None
            ])
        );
        let e = parse_limits("3,-170,170\n5,-10,abc\n", &names).unwrap_err();
        assert!(e.contains("line 2") && e.contains("max_deg"), "{e}");
        let e = parse_limits("7,0,1\n", &names).unwrap_err();
        assert!(e.contains("line 1") && e.contains("joint"), "{e}");
        let e = parse_limits("3,1,0\n", &names).unwrap_err();
        assert!(e.contains("above"), "{e}");
        let e = parse_limits("3,0,1\nA3,0,1\n", &names).unwrap_err();
        assert!(e.contains("twice"), "{e}");
        let e = parse_limits("3,0\n", &names).unwrap_err();
        assert!(e.contains("3 fields"), "{e}");
    }

    /// A limits file listing only A1 leaves the KR 6's A5 at its own ±120° (not ±180°),
    /// and `zerocal program` takes the plan made with it; a range wider than the
    /// profile's is refused naming the joint.
    #[test]
    fn a_partial_limits_file_keeps_the_profiles_other_limits() {
        let dir = std::env::temp_dir().join(format!("zerocal-plan-a1-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let f = dir.join("limits.csv");
        let _ = std::fs::write(&f, "joint,min_deg,max_deg\nA1,-160,160\n");
        let path = f.to_string_lossy().into_owned();
        let a = args(&["--robot", "kuka-kr6-r900-sixx", "--limits", &path]);
        let sp = make_plan(&a).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            (sp.profile.joints[0].min_deg, sp.profile.joints[0].max_deg),
            (-160.0, 160.0)
        );
        for q in &sp.plan.poses_rad {
            let a5 = q[4].to_degrees();
            // The planner keeps the approach's 1° and the overshoot's 4° inside ±120°.
            assert!((-119.0..=116.0).contains(&a5), "A5 at {a5} deg");
        }
        assert!(sp.program_refused.is_none(), "{:?}", sp.program_refused);
        let csv = dir.join("plan.csv");
        let rows: String = sp
            .plan
            .poses_rad
            .iter()
            .map(|q| {
                let r: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
                r.join(",") + "\n"
            })
            .collect();
        let _ = std::fs::write(
            &csv,
            format!("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg\n{rows}"),
        );
        let program = crate::program::ProgramArgs {
            robot: "kuka-kr6-r900-sixx".into(),
            plan: Some(csv),
            format: crate::program::Format::Krl,
            out: dir.join("zc.src"),
            timing: TimingArgs::default(),
        };
        let wrote = crate::program::run(&program).unwrap_or_else(|e| panic!("{e}"));
        assert!(wrote.starts_with("wrote"), "{wrote}");
        let _ = std::fs::write(&f, "A5,-150,150\n");
        let e = make_plan(&a).unwrap_err().to_string();
        assert!(
            e.contains("A5 (joint 5)") && e.contains("-120..120") && e.contains("only narrows"),
            "{e}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// `zerocal plan --json` of the most poses, its largest output, uses a quarter of
    /// the plan file's cap at most: the rest is room for hand edits.
    #[test]
    fn plan_files_of_the_most_poses_fit_their_cap() {
        let json = run(&args(&["--poses", "48", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        println!("zerocal plan --poses 48 --json: {} bytes", json.len());
        assert!(
            json.len() * 4 <= crate::input::MAX_PLAN_BYTES,
            "{}",
            json.len()
        );
    }

    #[test]
    fn csv_and_json_outputs() {
        let csv = run(&args(&["--poses", "24", "--csv"])).unwrap_or_else(|e| panic!("{e}"));
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg");
        assert_eq!(lines.len(), 25);
        let json = run(&args(&["--poses", "24", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["poses_deg"].as_array().map(Vec::len), Some(24));
        assert_eq!(v["predicted_sigma_deg"].as_array().map(Vec::len), Some(4));
        let text = run(&args(&[])).unwrap_or_else(|e| panic!("{e}"));
        println!("{text}");
        assert!(text.contains("predicted 1-sigma"), "{text}");
        // The paper's wrist (the default robot) turns joint 1 from -90° to +90°: the
        // program it would write has room for every capture.
        assert!(!text.contains("zerocal program would refuse"), "{text}");
    }

    /// The session's order moves the poses, never the prediction: the same poses'
    /// information in another order (a sum over poses: rounding only), and the tour is
    /// no longer than the planner's order.
    #[test]
    fn session_order_keeps_the_prediction_and_shortens_the_session() {
        for robot in ["paper-wrist", "kuka-kr16", "fanuc-m20ia"] {
            let a = args(&["--robot", robot, "--poses", "24"]);
            let profile = crate::robot::load(robot).unwrap_or_else(|e| panic!("{e}"));
            let (config, p) = plan_n(&a, &profile, 24).unwrap_or_else(|e| panic!("{e}"));
            let model = a.model(&profile);
            let before = predicted_k2_deg(
                &profile,
                &model,
                &p.poses_rad,
                &a.fit_config(&profile),
                a.captures_per_pose(),
            )
            .unwrap_or_else(|e| panic!("{e}"));
            let original = p.poses_rad.clone();
            let sp = session_plan(&a, profile, config, p).unwrap_or_else(|e| panic!("{e}"));
            for (k, (x, y)) in sp.k2_deg.iter().zip(before).enumerate() {
                // Relative rounding of a sum of 12 terms in another order.
                assert!((x - y).abs() <= 1e-9 * y, "{robot} j{}: {x} vs {y}", k + 2);
            }
            assert!(
                sp.time.total_s <= sp.time_unordered.total_s + 1e-9,
                "{robot}"
            );
            let mut a: Vec<String> = original.iter().map(|q| format!("{q:?}")).collect();
            let mut b: Vec<String> = sp.plan.poses_rad.iter().map(|q| format!("{q:?}")).collect();
            a.sort();
            b.sort();
            assert_eq!(a, b, "{robot}: the same poses");
            println!(
                "{robot}: 12 poses, robot time {:.0} s toured, {:.0} s in the planner's order",
                sp.time.total_s, sp.time_unordered.total_s
            );
        }
    }

    #[test]
    fn json_carries_the_prediction_correlations_and_robot_time() {
        let json =
            run(&args(&["--robot", "kuka-kr16", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["predicted_k2_deg"].as_array().map(Vec::len), Some(5));
        let t = &v["robot_time"];
        let parts: f64 = ["motion_s", "dwell_s", "remount_s", "operator_s"]
            .iter()
            .map(|k| t[*k].as_f64().unwrap_or(f64::NAN))
            .sum();
        let total = t["total_s"].as_f64().unwrap_or(f64::NAN);
        assert!((parts - total).abs() < 1e-9, "{parts} vs {total}");
        // Two captures of stage 1's two poses and of every planned pose, the closing
        // reversal's two; three mountings; each capture's dwell 3.1 s.
        let poses = v["poses_deg"].as_array().map_or(0, Vec::len) as u64;
        let captures = t["captures"].as_u64().unwrap_or(0);
        assert_eq!(captures, 2 * (poses + 2) + 2);
        assert_eq!(t["mountings"].as_u64(), Some(3));
        let dwell = t["dwell_per_capture_s"].as_f64().unwrap_or(f64::NAN);
        assert!((dwell - 3.1).abs() < 1e-12, "{dwell}");
        assert!((t["dwell_s"].as_f64().unwrap_or(f64::NAN) - captures as f64 * dwell).abs() < 1e-9);
        assert!(t["program_refused"].is_null(), "{}", t["program_refused"]);
        let m = &v["correlation"]["matrix"];
        for i in 0..4 {
            assert!((m[i][i].as_f64().unwrap_or(0.0) - 1.0).abs() < 1e-12);
            for j in 0..4 {
                let (a, b) = (
                    m[i][j].as_f64().unwrap_or(2.0),
                    m[j][i].as_f64().unwrap_or(3.0),
                );
                assert!((a - b).abs() < 1e-12 && a.abs() <= 1.0 + 1e-12);
            }
        }
        let worst = v["correlation"]["worst"]["value"].as_f64().unwrap_or(2.0);
        assert!(worst.abs() < POORLY_SEPARATED, "{worst}");
        assert_eq!(v["robot_time"]["max_speed_source"][0], "profile");
    }

    /// The target search returns the fewest poses that reach the target, never fewer
    /// than leave the session 20 residual degrees of freedom; a target below what stage 1
    /// allows j2 and j3 is refused naming them.
    #[test]
    fn target_search_finds_the_fewest_poses() {
        let profile = crate::robot::load("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        let a = args(&["--robot", "kuka-kr16", "--target-k2-deg", "0.0058"]);
        let floor = fewest_poses(&a.fit_config(&profile));
        assert!(floor > MIN_POSES, "{floor}");
        let sp = make_plan(&a).unwrap_or_else(|e| panic!("{e}"));
        let n = sp.plan.poses_rad.len();
        assert!(sp.k2_deg.iter().all(|u| *u <= 0.0058), "{:?}", sp.k2_deg);
        assert!(n >= floor, "{n} < {floor}");
        for fewer in floor..n {
            if let Ok((_, p)) = plan_n(&a, &profile, fewer) {
                let k2 = predicted_k2_deg(
                    &profile,
                    &a.model(&profile),
                    &p.poses_rad,
                    &a.fit_config(&profile),
                    a.captures_per_pose(),
                )
                .unwrap_or_else(|e| panic!("{e}"));
                assert!(
                    k2.iter().any(|u| *u > 0.0058),
                    "{fewer} poses reach it: {k2:?}"
                );
            }
        }
        let e =
            make_plan(&args(&["--robot", "kuka-kr16", "--target-k2-deg", "0.001"])).unwrap_err();
        assert_eq!(e.exit_code(), 3);
        assert!(
            e.to_string().contains("j2") && e.to_string().contains("stage 1"),
            "{e}"
        );
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
        // θ4 pinned: no room for the two captures of a pose, status 2 naming joint 4.
        let dir = std::env::temp_dir().join(format!("zerocal-plan-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let f = dir.join("limits.csv");
        let _ = std::fs::write(&f, "4,0,0\n");
        let path = f.to_string_lossy().into_owned();
        let e = run(&args(&["--limits", &path])).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        assert!(
            e.to_string().contains("joint 4") && e.to_string().contains("no room"),
            "{e}"
        );
        // θ4 within -1..4: the room of the approach (1°) and the overshoot (4°) pins it
        // at 0 (the paper's wrist: no signs, no coupling): j3 and j5 inseparable,
        // refused with status 3 naming them.
        let _ = std::fs::write(&f, "4,-1,4\n");
        let e = run(&args(&["--limits", &path])).unwrap_err();
        assert_eq!(e.exit_code(), 3, "{e}");
        assert!(e.to_string().contains("j3+j5"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
