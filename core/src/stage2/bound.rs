//! The covariance (Cramér-Rao) bound of a pose set: what any unbiased estimator can
//! reach on it, for planning poses before the robot moves.

use super::{check_conditioning, Stage2Model, MIN_POSES, RANK_DEFICIENT_CONDITION};
use crate::error::FitError;
use crate::model::WRIST_JOINTS;
use crate::real::Real;

/// The predicted 1σ of a pose set (the Cramér-Rao bound for Gaussian noise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CovarianceBound<T> {
    /// σ·sqrt(diag((JᵀJ)⁻¹)) per offset (rad).
    pub sigma_rad: [T; WRIST_JOINTS],
    /// Condition number of J.
    pub condition_number: T,
}

/// The covariance bound σ²(JᵀJ)⁻¹ of a pose set: the 1σ per offset any unbiased
/// estimator can reach with per-reading noise `noise_sigma_rad` (Cramér-Rao for
/// Gaussian noise), evaluated at `offsets_rad`.
///
/// # Errors
/// Too few poses, non-finite joints, a rank-deficient set (naming the parameters).
/// An ill-conditioned set still gets its (large) bound: that is the information a
/// planner needs.
pub fn covariance_bound<'p, T: Real + 'p>(
    model: &Stage2Model<T>,
    joints_rad: impl Iterator<Item = &'p [T; WRIST_JOINTS]> + Clone,
    offsets_rad: &[T; WRIST_JOINTS],
    noise_sigma_rad: T,
) -> Result<CovarianceBound<T>, FitError> {
    let mut n = 0;
    for (i, j) in joints_rad.clone().enumerate() {
        if j.iter().any(|q| !q.is_finite()) {
            return Err(FitError::NonFiniteJoint { pose: i });
        }
        n += 1;
    }
    if n < MIN_POSES {
        return Err(FitError::TooFewPoses {
            got: n,
            min: MIN_POSES,
        });
    }
    let info = model.information(joints_rad, offsets_rad);
    let condition_number = check_conditioning(&info, T::lit(RANK_DEFICIENT_CONDITION))?;
    let unit = info.unit_sigma().ok_or(FitError::NonFiniteResult)?;
    let mut sigma_rad = [T::zero(); WRIST_JOINTS];
    for (s, u) in sigma_rad.iter_mut().zip(unit) {
        *s = u * noise_sigma_rad;
    }
    Ok(CovarianceBound {
        sigma_rad,
        condition_number,
    })
}
