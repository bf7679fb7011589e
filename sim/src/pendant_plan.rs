//! The plan and fit settings the pendant uses, for the simulated sessions: the planner
//! run as the pendant runs it on a profile, with or without the real-sensor
//! compensation.

use zerocal_core::model::{Convention, SensorModel, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{plan, Candidate, Plan, PlanConfig, PlanError};
use zerocal_core::stage2::{FitConfig, Stage2Model};
use zerocal_profile::Profile;

/// The stage-2 plan for a profile as the pendant makes it: its stage-1 joints 1-2,
/// the profile's wrist limits, the `axis` convention at zero offsets.
///
/// # Errors
/// The planner's refusal.
pub fn plan_for(profile: &Profile, config: &PlanConfig<f64>) -> Result<Plan<f64>, PlanError> {
    let model = Stage2Model {
        arm: profile.arm,
        sensor: SensorModel::new(Convention::Axis, Tilt::default()),
        masses: profile.mass_model(),
        y_weight: zerocal_core::stage2::MEMS_Y_WEIGHT,
        stage1_j2_rad: profile.stage1_joints_rad[1],
        ..Stage2Model::default()
    };
    let mut config = *config;
    config.fixed_joints_rad = [profile.stage1_joints_rad[0], profile.stage1_joints_rad[1]];
    for k in 0..WRIST_JOINTS {
        let j = &profile.joints[k + 2];
        config.limits_rad[k] = (j.min_deg.to_radians(), j.max_deg.to_radians());
    }
    // Joint 2 swings in stage 2 where the fit models its transmission error.
    if config.extras.transmission != 0 {
        let j2 = &profile.joints[1];
        config.joint2_range_rad = zerocal_core::plan::joint2_range(
            profile.stage1_joints_rad[1],
            (j2.min_deg.to_radians(), j2.max_deg.to_radians()),
            zerocal_core::plan::JOINT2_SWING_DEG.to_radians(),
        );
        config.min_flange_height_m = Some(zerocal_core::plan::shoulder_height_m(&profile.arm));
        config.revisits = zerocal_core::plan::SESSION_REVISITS;
    }
    let mut pool = vec![Candidate::default(); config.candidates];
    plan(&model, &config, &mut pool)
}

/// How a session is run and solved: before the compensation of the real sensor and robot (the paper's model
/// with a MEMS sensor: offsets only, one approach direction, no closing reversal) or
/// with it (the real-sensor model, both approach directions, the closing reversal).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Offsets only.
    Uncompensated,
    /// The real-sensor model ([`FitConfig::for_mems`]).
    Compensated,
}

/// Stage-2 poses a session plans by default (distinct; the revisits come on top).
pub const DEFAULT_POSES: usize = zerocal_core::plan::SESSION_POSES;

/// The pendant's plan and fit settings for `profile` under `method`, with `poses`
/// stage-2 poses.
///
/// # Errors
/// The planner's refusal.
pub fn setup(
    profile: &Profile,
    method: Method,
    poses: usize,
) -> Result<(Vec<[f64; JOINTS]>, FitConfig<f64>), PlanError> {
    let sag = profile.mass_model().is_some();
    let fit = match method {
        Method::Compensated => FitConfig::for_mems(&profile.arm, sag),
        Method::Uncompensated => FitConfig {
            sensor_range_rad: FitConfig::<f64>::for_mems(&profile.arm, sag).sensor_range_rad,
            sensor_noise_rad: FitConfig::<f64>::for_mems(&profile.arm, sag).sensor_noise_rad,
            // The paper's offsets only, but a parallel twin held as every fit holds it.
            extras: zerocal_core::stage2::Extras {
                held: profile.arm.parallel_twins(),
                ..zerocal_core::stage2::Extras::NONE
            },
            ..FitConfig::default()
        },
    };
    let config = PlanConfig {
        poses,
        candidates: zerocal_core::plan::SESSION_POOL,
        extras: fit.extras,
        noise_sigma_rad: fit.sensor_noise_rad,
        window_rad: PLAN_WINDOW_DEG.to_radians(),
        margin_rad: 0.0,
        ..PlanConfig::default()
    };
    let plan = plan_for(profile, &config)?;
    Ok((plan.poses_rad.iter().copied().collect(), fit))
}

/// The planning window (deg): mode 4's range less the pendant's margin for the sensor's
/// offset, the base tilt and the offsets not yet known (the procedure's figures).
pub const PLAN_WINDOW_DEG: f64 =
    zerocal_core::stage2::MEMS_RANGE_DEG - zerocal_procedure::PENDANT_PLAN_MARGIN_DEG;
