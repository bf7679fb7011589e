//! What a joint's angle-dependent error does to the zero a session reports.
//!
//! A reducer's transmission error (and the arm's deflection that varies with the angle)
//! makes a joint's true angle differ from the commanded one by a function of the angle,
//! not by one number. The zero a controller takes is one number per joint, so the zero
//! a session finds is that error averaged over the angles its poses cover, weighted as
//! the fit weighs them: against the zero of the drawing it is off by that weighted
//! mean. For a harmonic `a·sin(n·q + φ)` of unknown phase the weighted mean
//! `Σᵢ gᵢ·a·sin(n·qᵢ + φ)` has variance `a²/2·|Σᵢ gᵢ·e^{i·n·qᵢ}|²`: small where the poses
//! spread the joint over whole periods, up to `a²/2` where they sit at one angle.

use super::{add_held, RANK_DEFICIENT_CONDITION};
use super::{check_conditioning, Extras, PoseReading, Stage2Model, MAX_PARAMS};
use crate::error::FitError;
use crate::model::WRIST_JOINTS;
use crate::real::Real;

/// The largest peak-to-peak transmission error of one joint the budget assumes (deg),
/// harmonics 2-4 of the joint's turn: reducer catalogues state about 1 arc min of
/// transmission accuracy (Harmonic Drive CSF, Nabtesco RV), and a joint adds its
/// bearings and its motor's encoder; 0.03° is the top of the range the simulator draws.
/// A session whose residuals show more gets its own figure ([`amplitude_from_residuals`]).
pub const TRANSMISSION_PP_MAX_DEG: f64 = 0.03;

/// The largest once-per-turn error of joints 4 and 6 the budget assumes (deg, peak to
/// peak): a laser tracker on a FANUC R-2000iC/165F found 0.023-0.027° (public data of
/// Boby and Klimchik), the wrist twisting under gravity.
pub const ONCE_PER_TURN_PP_MAX_DEG: f64 = 0.025;

/// Orders of the harmonics the budget considers: once per turn (joints 4 and 6 only),
/// then 2-4.
const ORDERS: [u8; 4] = [1, 2, 3, 4];

/// The variance of Δθ3..Δθ6 (rad²) from each joint's angle-dependent error of amplitude
/// `amplitude_rad[j]` (joints 3-6, half its peak to peak, in whichever one of orders 2-4
/// moves the offsets most) and `once_per_turn_rad[j]`, of unknown phase and independent
/// from joint to joint, through the fit of `extras` on `poses`. Joint 2 is held where
/// stage 1 had it, so its error there is part of Δθ2 and not of these.
///
/// # Errors
/// A pose set the fit could not have solved.
pub fn transmission_variance<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    poses: &[PoseReading<T>],
    offsets_rad: &[T; WRIST_JOINTS],
    amplitude_rad: &[T; WRIST_JOINTS],
    once_per_turn_rad: &[T; WRIST_JOINTS],
) -> Result<[T; WRIST_JOINTS], FitError> {
    let layout = extras.layout();
    let n = layout.len();
    let estimate = super::Estimate {
        offsets_rad: *offsets_rad,
        ..super::Estimate::default()
    };
    let pass = model.pass(&estimate, &layout);
    let mut info = super::information::Information::new(n);
    // z[o][j]: Σᵢ J_iᵀ·(∂reading/∂θⱼ)·e^{i·n·qᵢⱼ}, real and imaginary parts.
    let mut z = [[([T::zero(); MAX_PARAMS], [T::zero(); MAX_PARAMS]); WRIST_JOINTS]; 4];
    for pose in poses {
        let p = model.predict_rows(&pass, &layout, &estimate, pose, false);
        info.add_row(&p.rows[0], T::zero());
        info.add_row(&p.rows[1], T::zero());
        for j in 0..WRIST_JOINTS {
            let q = pose.joints_rad[j + 2];
            for (o, order) in ORDERS.iter().enumerate() {
                let (s, c) = (q * T::lit(f64::from(*order))).fast_sin_cos();
                let (re, im) = &mut z[o][j];
                for i in 0..n {
                    let b = p.rows[0][i] * p.rows[0][j] + p.rows[1][i] * p.rows[1][j];
                    re[i] += b * c;
                    im[i] += b * s;
                }
            }
        }
    }
    add_held(&mut info, &extras);
    check_conditioning(&info, &layout, T::lit(RANK_DEFICIENT_CONDITION))?;
    let inv = info.inverse_gram().ok_or(FitError::NonFiniteResult)?;
    let mut variance = [T::zero(); WRIST_JOINTS];
    for (k, v) in variance.iter_mut().enumerate() {
        for j in 0..WRIST_JOINTS {
            let power = |o: usize| {
                let (re, im) = &z[o][j];
                let (mut a, mut b) = (T::zero(), T::zero());
                for i in 0..n {
                    a += inv.m[k][i] * re[i];
                    b += inv.m[k][i] * im[i];
                }
                a * a + b * b
            };
            let worst_order = (1..ORDERS.len()).fold(T::zero(), |w, o| w.max(power(o)));
            let half = T::lit(0.5);
            *v += half * amplitude_rad[j] * amplitude_rad[j] * worst_order;
            *v += half * once_per_turn_rad[j] * once_per_turn_rad[j] * power(0);
        }
    }
    Ok(variance)
}

/// The amplitude of an angle-dependent joint error the residuals show: the part of the
/// residuals' variance beyond the sensor's noise and the robot's repeatability
/// (`expected_rad2`, per reading), taken as every joint's error of amplitude `a` in a
/// harmonic of unknown phase (variance a²/2 per joint), through the mean power of the
/// joints' partials (`joint_power`, [`super::joint_sensitivity_power`]). Zero when the
/// residuals show no more than expected.
pub fn amplitude_from_residuals<T: Real>(residual_rad2: T, expected_rad2: T, joint_power: T) -> T {
    let excess = residual_rad2 - expected_rad2;
    if excess > T::zero() && joint_power > T::zero() {
        (T::lit(2.0) * excess / joint_power).sqrt()
    } else {
        T::zero()
    }
}
