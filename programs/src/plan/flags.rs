//! The flags of `zerocal plan` and what they make: the profile (its limits narrowed by
//! `--limits`), the stage-2 model the plan is made for, the fit the session will run
//! and the planner's settings.
//!
//! `--noise-deg A` is the half-width of uniform reading noise ±A, as for `simulate`
//! (the paper's Table 4: 0.002): the predicted 1σ uses σ = A/√3 per reading.

use super::limits::{narrow_limits, LimitsDeg};
use crate::robot_time::CAPTURES_PER_POSE;
use crate::timing::{self, TimingArgs};
use clap::Args;
use std::path::PathBuf;
use zerocal_core::model::{BaseTilt, Convention, SensorModel, Tilt};
use zerocal_core::plan::{Criterion, PlanConfig};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage2::{FitConfig, Stage2Model};
use zerocal_inputs::args::{CountIn, RealIn, SEED, TILT_PAIR};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// `--margin-deg`'s help, its default written from the constant the pendant plans
/// with (`zerocal_procedure::PENDANT_PLAN_MARGIN_DEG`), so the two cannot disagree.
pub fn margin_help() -> String {
    let margin = zerocal_procedure::PENDANT_PLAN_MARGIN_DEG;
    format!(
        "Planned readings stay within ±(W − margin) at zero offsets (±{:.1}° by default), \
         leaving room for the offsets not yet known, the sensor's offset (up to 1.45° on an \
         SCL3300), the base tilt, a bracket's seat and the chip's turn in its box: {margin}° \
         by default, the pendant's own margin, chosen by Monte-Carlo (docs/error-budget.md) \
         (deg); it must also be smaller than W. Range: [0, 90] deg.",
        zerocal_core::stage2::MEMS_RANGE_DEG - margin
    )
}

/// The widest swing of joint 2 `--joint2-swing-deg` takes (deg): a plan file whose
/// joint 2 lies further from the profile's stage-1 angle is no plan of this robot's
/// stage-1 pose.
pub const MAX_JOINT2_SWING_DEG: f64 = 120.0;

/// Arguments of `zerocal plan`.
#[derive(Args, Debug, Clone)]
pub struct PlanArgs {
    /// Distinct poses to plan (the revisits come on top; `zerocal_core::plan::MAX_POSES`
    /// in all at most; the SCL3300's model with the reducers' terms needs 40 for its
    /// 45-51 parameters: docs/error-budget.md). Range: [4, 45].
    #[arg(long, default_value_t = zerocal_core::plan::SESSION_POSES, value_parser = CountIn::<usize>::new(4, 45))]
    pub poses: usize,
    /// How far stage 2 swings joint 2 either side of its stage-1 angle, within its
    /// limits (deg): its transmission error is then told from its zero; 0 holds joint 2
    /// where stage 1 had it (its error there is then budgeted whole). Range: [0, 120] deg.
    #[arg(long, default_value_t = zerocal_core::plan::JOINT2_SWING_DEG, value_parser = RealIn::closed(0.0, MAX_JOINT2_SWING_DEG, "deg"))]
    pub joint2_swing_deg: f64,
    /// Poses visited again later in the session, so that a bracket creeping on the
    /// flange shows. Range: [0, 3].
    #[arg(long, default_value_t = zerocal_core::plan::SESSION_REVISITS, value_parser = CountIn::<usize>::new(0, 3))]
    pub revisits: usize,
    /// Sensor window: readings must stay within ±W degrees (the SCL3300's mode 4 by
    /// default). Range: (0, 90] deg.
    #[arg(long, default_value_t = zerocal_core::stage2::MEMS_RANGE_DEG, value_name = "W", value_parser = RealIn::above(0.0, 90.0, "deg"))]
    pub window_deg: f64,
    #[arg(long, help = margin_help(), default_value_t = zerocal_procedure::PENDANT_PLAN_MARGIN_DEG, value_parser = RealIn::closed(0.0, 90.0, "deg"))]
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
    #[arg(long, default_value_t = zerocal_core::plan::SESSION_POOL, value_parser = CountIn::<usize>::new(4, 65_535))]
    pub candidates: usize,
    /// Optimality criterion: a (A-optimal, least sum of the four predicted variances)
    /// or d (D-optimal, greatest log det JᵀJ).
    #[arg(long, default_value = "a", value_parser = zerocal_inputs::args::criterion())]
    pub criterion: Criterion,
    /// Sensor convention: axis (the pendant's SCL3300: the plan then separates its gain,
    /// cross-axis and the sag too, and each pose is captured from both sides of the
    /// backlash) or rpy (the paper's ideal sensor).
    #[arg(long, default_value = "axis", value_parser = zerocal_inputs::args::convention())]
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

/// `zerocal plan`'s flags as a command of their own, for [`PlanArgs::from_flags`].
#[derive(clap::Parser)]
struct PlanCommand {
    #[command(flatten)]
    args: PlanArgs,
}

impl PlanArgs {
    /// `zerocal plan`'s flags parsed from `flags` (without the command's name) as the
    /// command line parses them: for another tool that plans, and the tests.
    ///
    /// # Errors
    /// clap's: a flag unknown or out of its range (exit status 2).
    pub fn from_flags(flags: &[&str]) -> Result<PlanArgs, clap::Error> {
        use clap::Parser;
        PlanCommand::try_parse_from(std::iter::once("plan").chain(flags.iter().copied()))
            .map(|c| c.args)
    }

    /// The robot profile `--robot` names, its limits narrowed by `--limits`.
    ///
    /// # Errors
    /// A profile or a limits file that does not read; limits wider than the profile's.
    pub fn profile(&self) -> Result<Profile, CliError> {
        let profile = zerocal_inputs::robot::load(&self.robot)?;
        match &self.limits {
            None => Ok(profile),
            Some(path) => {
                let text = zerocal_inputs::input::read_capped(
                    path,
                    zerocal_inputs::input::MAX_LIMITS_BYTES,
                    "limits file",
                )?;
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
        let mut fit = zerocal_inputs::robot::fit_config(self.convention, profile);
        if let Some(a) = self.noise_deg {
            fit.sensor_noise_rad = deg_to_rad(a / 3f64.sqrt());
        }
        fit
    }

    /// Captures per pose: two (one from each side of the backlash) with the SCL3300,
    /// one for the paper's sensor.
    pub fn captures_per_pose(&self) -> usize {
        match self.convention {
            Convention::Axis => CAPTURES_PER_POSE,
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
        let j2 = timing::planner_limit(
            profile,
            1,
            (profile.joints[1].min_deg, profile.joints[1].max_deg),
        );
        let swings = self.convention == Convention::Axis;
        let joint2_range_rad = zerocal_core::plan::joint2_range(
            q1[1],
            (deg_to_rad(j2.0), deg_to_rad(j2.1)),
            if swings {
                deg_to_rad(self.joint2_swing_deg)
            } else {
                0.0
            },
        );
        Ok(PlanConfig {
            joint2_range_rad,
            min_flange_height_m: joint2_range_rad
                .map(|_| zerocal_core::plan::shoulder_height_m(&profile.arm)),
            revisits: if swings { self.revisits } else { 0 },
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

/// `zerocal plan`'s flags parsed from `flags` (without the command's name), for the
/// tests of the plan's modules.
#[cfg(test)]
pub(crate) fn test_args(flags: &[&str]) -> PlanArgs {
    PlanArgs::from_flags(flags).unwrap_or_else(|e| panic!("{e}"))
}
