//! The stage-2 plan the pendant uses when none was uploaded ([`pendant_default`]): core's
//! planner on the pendant's own configuration, computed by the firmware's build.

use super::ProcedureConfig;
use zerocal_core::model::{BaseTilt, SensorModel, Tilt};
use zerocal_core::plan::{plan, Candidate, PlanConfig, PlanError, PoseList, SESSION_REVISITS};
use zerocal_core::real::{deg_to_rad, Real};
use zerocal_core::stage2::Stage2Model;

/// Distinct poses in the pendant's default plan: 24, each captured twice, then
/// [`SESSION_REVISITS`] of them visited again (27 in all). The default plan holds joint
/// 2 where stage 1 had it (the built-in paper arm has no joint limits to swing it
/// within), so the fit has no joint-2 harmonics, sag or lost motion to separate, and
/// 24 poses keep it conditioned far inside the fit's own limit (the planner refuses a
/// design past it); a plan that swings joint 2 takes core's `SESSION_POSES`
/// (`zerocal plan`, which prints the 1σ a design predicts).
pub const PENDANT_PLAN_POSES: usize = 24;

/// The planning window (deg) inside the sensor's ±10° mode-4 range: 4° are left for the
/// sensor's offset (up to 1.45°), the base tilt, the offsets not yet known, a bracket's
/// seat (±0.5°) and the chip's turn in its box (±1°). At 3° about one session in 200
/// with every one of those at the top of its range had a capture past ±10°; at 4° none
/// of 6,000 (host-tests `margins_hold`, docs/error-budget.md).
pub const PENDANT_PLAN_MARGIN_DEG: f64 = 4.0;

/// The plan the pendant uses when none was uploaded: this planner on the pendant's arm
/// and convention with the fit's own terms, a level base and no bias (the real ones are
/// not known before stages 0-1; [`PENDANT_PLAN_MARGIN_DEG`] inside the sensor's range
/// absorbs them), and the fit's own conditioning limit; [`PENDANT_PLAN_POSES`] poses
/// with joint 1 at stage 1's mark and joint 2 held at stage 1's angle, then
/// [`SESSION_REVISITS`] of them visited again so that a creeping bracket shows.
///
/// Seeded, so the same every time: the firmware computes it when it is built.
///
/// # Errors
/// As [`plan`].
pub fn pendant_default<T: Real>(
    config: &ProcedureConfig<T>,
    pool: &mut [Candidate<T>],
) -> Result<PoseList<T>, PlanError> {
    let model = Stage2Model {
        arm: config.arm,
        base_tilt: BaseTilt::level(),
        sensor: SensorModel::new(config.convention, Tilt::default()),
        masses: config.masses,
        stage1_j2_rad: config.stage1_joints_rad[1],
        ..Stage2Model::default()
    };
    let plan_config = PlanConfig {
        poses: PENDANT_PLAN_POSES,
        max_condition_number: config.fit.max_condition_number,
        fixed_joints_rad: [config.stage1_joints_rad[0], config.stage1_joints_rad[1]],
        joint2_range_rad: None,
        revisits: SESSION_REVISITS,
        extras: config.fit.extras,
        noise_sigma_rad: config.fit.sensor_noise_rad,
        window_rad: config.fit.sensor_range_rad,
        margin_rad: deg_to_rad(T::lit(PENDANT_PLAN_MARGIN_DEG)),
        ..PlanConfig::default()
    };
    Ok(plan(&model, &plan_config, pool)?.poses_rad)
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::plan::DEFAULT_POOL;

    /// The firmware's default plan: the distinct poses with joint 1 at its mark and
    /// joint 2 held at stage 1's angle, then the revisits, each an earlier pose again
    /// (core's `with_revisits`: the first halfway through, the first and the middle at
    /// the end); within what the pendant holds.
    #[test]
    fn the_default_plan_holds_joint_2_and_revisits_earlier_poses() {
        let config = ProcedureConfig::<f64>::for_mems();
        let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
        let plan = pendant_default(&config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(plan.len(), PENDANT_PLAN_POSES + SESSION_REVISITS);
        assert!(plan.len() <= crate::MAX_PLAN_POSES);
        for q in &plan {
            assert_eq!(q[..2], config.stage1_joints_rad[..2], "{q:?}");
        }
        let distinct = |q: &[f64; 6]| plan.iter().filter(|p| *p == q).count();
        let repeated: std::vec::Vec<_> = plan.iter().filter(|q| distinct(q) > 1).collect();
        // The first pose three times (its own, halfway, the end), the middle twice.
        assert_eq!(distinct(&plan[0]), 3);
        assert_eq!(repeated.len(), 3 + 2);
    }
}
