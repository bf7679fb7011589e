//! The covariance (Cramér-Rao) bound of a pose set: what any unbiased estimator can
//! reach on it, for planning poses before the robot moves.

use super::{
    check_conditioning, information, Extras, PoseReading, Stage2Model, MAX_PARAMS, MIN_POSES,
    RANK_DEFICIENT_CONDITION, ZEROS,
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
    /// The same for the zeros ([`super::ZEROS`]: the correction of stage 1's Δθ2, then
    /// Δθ3..Δθ6).
    pub zeros_sigma_rad: [T; ZEROS],
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
    let mut info = information(model, extras, joints_rad, offsets_rad, noise_sigma_rad);
    let condition_number = check_conditioning(&info, &layout, T::lit(RANK_DEFICIENT_CONDITION))?;
    let unit = info.unit_sigma().ok_or(FitError::NonFiniteResult)?;
    let all_sigma = unit.map(|u| u * noise_sigma_rad);
    let inv = info.invert_in_place().ok_or(FitError::NonFiniteResult)?;
    let l = super::zeros_map(model, &layout);
    let n = layout.len();
    let zeros_sigma_rad = l.map(|row| {
        let mut acc = T::zero();
        for i in 0..n {
            for j in 0..n {
                acc += row[i] * inv.m[i][j] * row[j];
            }
        }
        acc.max(T::zero()).sqrt() * noise_sigma_rad
    });
    Ok(CovarianceBound {
        sigma_rad: core::array::from_fn(|k| all_sigma[k]),
        all_sigma,
        zeros_sigma_rad,
        condition_number,
    })
}

/// How much the robot's repeatability moves the offsets: the covariance of Δθ3..Δθ6
/// (rad²) when every capture's joints 2-6 land off their commanded angles by
/// independent errors of variance `joint_variance_rad2 / captures_per_row` (a row
/// averaging that many captures). A joint error at one pose looks like an offset at
/// that pose, so the fit takes most of it for one and the residuals barely show it:
/// σ from the residuals alone would miss it.
///
/// `S = (JᵀJ)⁻¹Jᵀ` maps reading errors to the parameters; the joints' errors reach the
/// readings through `J_q` (the offsets' own columns for joints 3-6, the hand-over's Δθ2
/// column for joint 2), so the covariance is `σ_q²·S·J_q·J_qᵀ·Sᵀ`.
///
/// # Errors
/// As [`covariance_bound`].
pub fn repeatability_covariance<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    poses: &[PoseReading<T>],
    offsets_rad: &[T; WRIST_JOINTS],
    joint_variance_rad2: T,
    captures_per_row: T,
    noise_rad: T,
) -> Result<Propagated<[[T; ZEROS]; ZEROS], T>, FitError> {
    let v = joint_variance_rad2 / captures_per_row;
    joint_error_covariance(
        model,
        extras,
        poses,
        offsets_rad,
        &[v; WRIST_JOINTS + 1],
        noise_rad,
    )
}

/// As [`repeatability_covariance`], with each of joints 2-6 off by its own variance
/// per row (rad², index 0 = joint 2): for an error that differs by joint, such as the
/// backlash of a loaded joint.
///
/// # Errors
/// As [`covariance_bound`].
pub fn joint_error_covariance<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    poses: &[PoseReading<T>],
    offsets_rad: &[T; WRIST_JOINTS],
    joint_variance_rad2: &[T; WRIST_JOINTS + 1],
    noise_rad: T,
) -> Result<Propagated<[[T; ZEROS]; ZEROS], T>, FitError> {
    let layout = extras.layout();
    let n = layout.len();
    let estimate = super::Estimate {
        offsets_rad: *offsets_rad,
        ..super::Estimate::default()
    };
    let pass = model.pass(&estimate, &layout);
    let mut info = super::information::Information::new(n);
    // Σ over poses of (Jᵀ J_q)(Jᵀ J_q)ᵀ, pose by pose: B_i = J_iᵀ·J_q,i (n × 5).
    let mut outer = crate::linalg::Square::<T, MAX_PARAMS>::zeros(n);
    // Σ over readings of the error's variance in them: E[rᵀr] before the fit.
    let mut reading_power = T::zero();
    for pose in poses {
        let p = model.predict_rows(&pass, &layout, &estimate, pose, true);
        info.add_row(&p.rows[0], T::zero());
        info.add_row(&p.rows[1], T::zero());
        // J_q for this pose: columns Δθ2 (hand-over slot 2) and the offsets.
        let jq = |axis: usize, joint: usize| -> T {
            if joint == 0 {
                p.handover_rows[axis][2]
            } else {
                p.rows[axis][joint - 1]
            }
        };
        for axis in 0..2 {
            for (j, v) in joint_variance_rad2.iter().enumerate() {
                reading_power += jq(axis, j) * jq(axis, j) * *v;
            }
        }
        let mut b = [[T::zero(); WRIST_JOINTS + 1]; MAX_PARAMS];
        for (i, bi) in b.iter_mut().enumerate().take(n) {
            for (j, bij) in bi.iter_mut().enumerate() {
                *bij = p.rows[0][i] * jq(0, j) + p.rows[1][i] * jq(1, j);
            }
        }
        for i in 0..n {
            for k in 0..n {
                let s = b[i]
                    .iter()
                    .zip(&b[k])
                    .zip(joint_variance_rad2)
                    .fold(T::zero(), |s, ((x, y), v)| s + *x * *y * *v);
                outer.m[i][k] += s;
            }
        }
    }
    super::add_held(&mut info, &extras, noise_rad);
    check_conditioning(&info, &layout, T::lit(RANK_DEFICIENT_CONDITION))?;
    let inv = info.invert_in_place().ok_or(FitError::NonFiniteResult)?;
    // The zeros' rows of (JᵀJ)⁻¹ first: L·(JᵀJ)⁻¹ (ZEROS × n), then L·inv·O·invᵀ·Lᵀ.
    let l = super::zeros_map(model, &layout);
    let mut li = [[T::zero(); MAX_PARAMS]; ZEROS];
    for (lia, la) in li.iter_mut().zip(&l) {
        for (j, v) in lia.iter_mut().enumerate().take(n) {
            *v = (0..n).fold(T::zero(), |acc, i| acc + la[i] * inv.m[i][j]);
        }
    }
    let mut cov = [[T::zero(); ZEROS]; ZEROS];
    for (a, row) in cov.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            let mut acc = T::zero();
            for i in 0..n {
                for k in 0..n {
                    acc += li[a][i] * outer.m[i][k] * li[c][k];
                }
            }
            *v = acc;
        }
    }
    // What the fit takes of it: tr(P·M) = tr((JᵀJ)⁻¹·Σᵢ Bᵢ·V·Bᵢᵀ).
    let taken = (0..n).fold(T::zero(), |acc, i| {
        (0..n).fold(acc, |acc, k| acc + inv.m[i][k] * outer.m[k][i])
    });
    Ok(Propagated {
        zeros: cov,
        residual_rad2: residual_per_dof(reading_power - taken, poses.len(), n, &extras),
    })
}

/// What an error the fit does not estimate does to a session: to its zeros (`zeros`),
/// and to its residuals: `residual_rad2`, its expected share of σ² as the fit takes σ
/// from the residuals (E[rᵀr] over the residual degrees of freedom, rad²). A budget
/// that carries the error as its own term takes this out of the σ that scales the
/// terms evaluated from the residuals, or the error would be counted twice (GUM
/// 4.2, 5.1: each effect once).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Propagated<Z, T> {
    /// The effect on the zeros (their covariance or variance, rad²).
    pub zeros: Z,
    /// Its expected share of the residuals' σ² (rad²).
    pub residual_rad2: T,
}

/// E[rᵀr] (`left_rad2`, what a fit of `n` parameters leaves of an error's variance in
/// `poses`' readings) per residual degree of freedom, as the fit's σ counts them (2N
/// readings less the parameters not held); 0 where none are left.
pub(super) fn residual_per_dof<T: Real>(
    left_rad2: T,
    poses: usize,
    n: usize,
    extras: &Extras,
) -> T {
    let held = extras.held.iter().filter(|h| **h).count();
    let dof = (2 * poses).saturating_sub(n - held.min(n));
    if dof == 0 {
        T::zero()
    } else {
        left_rad2.max(T::zero()) / T::lit(dof as f64)
    }
}

/// The mean over readings of Σₖ (∂reading/∂θₖ)² for joints 2-6: how strongly a joint
/// error of unit variance, independent at each pose, moves a reading. With the robot's
/// repeatability it gives the part of the residuals a session should expect beyond
/// the sensor's noise, taken as isotropic ([`super::Propagated::residual_rad2`] has it
/// exactly).
pub fn joint_sensitivity_power<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: &[[T; JOINTS]],
    offsets_rad: &[T; WRIST_JOINTS],
) -> T {
    let layout = extras.layout();
    let estimate = super::Estimate {
        offsets_rad: *offsets_rad,
        ..super::Estimate::default()
    };
    let pass = model.pass(&estimate, &layout);
    let mut sum = T::zero();
    let mut readings = 0u32;
    for q in joints_rad {
        let pose = PoseReading {
            joints_rad: *q,
            reading: crate::model::Tilt::default(),
            temperature_c: None,
        };
        let p = model.predict_rows(&pass, &layout, &estimate, &pose, true);
        for axis in 0..2 {
            let mut s = p.handover_rows[axis][2] * p.handover_rows[axis][2];
            for k in 0..WRIST_JOINTS {
                s += p.rows[axis][k] * p.rows[axis][k];
            }
            sum += s;
            readings += 1;
        }
    }
    if readings == 0 {
        T::zero()
    } else {
        sum / T::lit(f64::from(readings))
    }
}
