//! The covariance (Cramér-Rao) bound of a pose set: what any unbiased estimator can
//! reach on it, for planning poses before the robot moves.

use super::{
    check_conditioning, information, Extras, Stage2Model, MAX_PARAMS, MIN_POSES,
    RANK_DEFICIENT_CONDITION,
};
use crate::error::FitError;
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::real::Real;

/// The predicted 1σ of a pose set (the Cramér-Rao bound for Gaussian noise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CovarianceBound<T> {
    /// σ·sqrt(diag((JᵀJ)⁻¹)) per offset (rad), the extra terms estimated alongside.
    pub sigma_rad: [T; WRIST_JOINTS],
    /// The same for every estimated parameter, by slot of `Extras::layout`.
    pub all_sigma: [T; MAX_PARAMS],
    /// Condition number of J.
    pub condition_number: T,
}

/// The covariance bound σ²(JᵀJ)⁻¹ of a pose set for the parameters `extras` adds to
/// the offsets: the 1σ any unbiased estimator can reach with per-reading noise
/// `noise_sigma_rad` (Cramér-Rao for Gaussian noise), evaluated at `offsets_rad` (zero
/// when planning).
///
/// # Errors
/// Too few poses, non-finite joints, a rank-deficient set (naming the parameters).
/// An ill-conditioned set still gets its (large) bound: that is the information a
/// planner needs.
pub fn covariance_bound<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: &[[T; JOINTS]],
    offsets_rad: &[T; WRIST_JOINTS],
    noise_sigma_rad: T,
) -> Result<CovarianceBound<T>, FitError> {
    for (i, j) in joints_rad.iter().enumerate() {
        if j.iter().any(|q| !q.is_finite()) {
            return Err(FitError::NonFiniteJoint { pose: i });
        }
    }
    if joints_rad.len() < MIN_POSES {
        return Err(FitError::TooFewPoses {
            got: joints_rad.len(),
            min: MIN_POSES,
        });
    }
    let layout = extras.layout();
    let info = information(model, extras, joints_rad, offsets_rad);
    let condition_number = check_conditioning(&info, &layout, T::lit(RANK_DEFICIENT_CONDITION))?;
    let unit = info.unit_sigma().ok_or(FitError::NonFiniteResult)?;
    let all_sigma = unit.map(|u| u * noise_sigma_rad);
    Ok(CovarianceBound {
        sigma_rad: core::array::from_fn(|k| all_sigma[k]),
        all_sigma,
        condition_number,
    })
}
