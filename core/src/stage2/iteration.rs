//! The Levenberg-Marquardt iteration of stage 2's fit: each pass linearises the model
//! at the current estimate, folding every reading's two rows, the held offsets'
//! pseudo-readings and the priors of the geometric and reducer terms into the fit's
//! triangular factor ([`super::information`]), and takes the damped step.

use super::{
    check_conditioning, geometry, transmission, Estimate, FitConfig, Information, Layout,
    PoseReading, Stage2Model, MAX_PARAMS,
};
use crate::error::FitError;
use crate::model::{Tilt, WRIST_JOINTS};
use crate::real::Real;

/// Steps smaller than this (rad, ≈ 0.006°) are taken without the cost test of
/// Levenberg-Marquardt: see [`super::fit`].
const LOCAL_STEP_RAD: f64 = 1e-4;

/// J over all poses, with the residuals when `with_residuals`; the sum of squared
/// residuals and the largest one (and its pose).
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
pub(super) fn linearise<T: Real>(
    info: &mut Information<T>,
    model: &Stage2Model<T>,
    layout: &Layout,
    poses: &[PoseReading<T>],
    x: &[T; MAX_PARAMS],
    with_residuals: bool,
    held: &Held<T>,
) -> (T, (T, usize)) {
    let estimate = Estimate::from_slots(layout, x);
    let pass = model.pass(&estimate, layout);
    info.reset(layout.len());
    let mut ssr = T::zero();
    let mut worst = (T::zero(), 0);
    let mut rows = [[T::zero(); MAX_PARAMS]; 2];
    for (i, pose) in poses.iter().enumerate() {
        let (reading, _) = model.predict_into(&pass, layout, &estimate, pose, false, &mut rows);
        let r = if with_residuals {
            let r = pose.reading.minus(&reading);
            Tilt::new(r.x_rad, r.y_rad * model.y_weight)
        } else {
            Tilt::default()
        };
        let size = r.x_rad.abs().max(r.y_rad.abs());
        if size > worst.0 {
            worst = (size, i);
        }
        ssr += r.x_rad * r.x_rad + r.y_rad * r.y_rad;
        info.add_row(&rows[0], r.x_rad);
        info.add_row(&rows[1], r.y_rad);
    }
    // A held offset: a pseudo-reading that it equals its starting value, weighted ten
    // readings' worth. The data say nothing on it (it is another joint's twin), so the
    // solution puts it there and its twin takes the sum.
    for (k, &h) in held.offsets.iter().enumerate() {
        if h {
            let mut row = [T::zero(); MAX_PARAMS];
            row[k] = T::lit(HELD_WEIGHT);
            info.add_row(&row, T::lit(HELD_WEIGHT) * (held.at_rad[k] - x[k]));
        }
    }
    // A geometric term: a pseudo-reading that it is 0 within its stated worst case (a
    // prior, in units of one reading's noise). Where the poses determine it, it moves
    // it by (noise / worst case)², a few parts per million; where two terms are nearly
    // one (a tilt of joint 2 and of joint 3 about nearly the same direction), it keeps
    // their difference from wandering off to tens of degrees.
    for (slot, w) in held.prior_weight.iter().enumerate().take(layout.len()) {
        if *w > T::zero() {
            let mut row = [T::zero(); MAX_PARAMS];
            row[slot] = *w;
            info.add_row(&row, -*w * x[slot]);
            ssr += *w * *w * x[slot] * x[slot];
        }
    }
    (ssr, worst)
}

/// The weight of a held offset's pseudo-reading, in readings.
pub(super) const HELD_WEIGHT: f64 = 10.0;

/// Offsets held at a value, and the priors on the geometric terms (by slot; 0: none).
pub(super) struct Held<T> {
    pub(super) offsets: [bool; WRIST_JOINTS],
    pub(super) at_rad: [T; WRIST_JOINTS],
    pub(super) prior_weight: [T; MAX_PARAMS],
}

/// The prior weights of `layout`'s geometric terms and reducer terms: the reading
/// noise over each one's stated worst case (geometry) or stated standard deviation
/// (transmission error, lost motion: [`transmission::prior_sd_rad`]).
pub(super) fn prior_weights<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    poses: &[PoseReading<T>],
    noise_rad: T,
) -> [T; MAX_PARAMS] {
    let mut w = [T::zero(); MAX_PARAMS];
    for (slot, p) in layout.params().iter().enumerate() {
        let worst = transmission::prior_sd_rad(*p)
            .unwrap_or_else(|| geometry::worst_case(model, *p, poses.iter().map(|p| p.joints_rad)));
        if worst > T::zero() {
            w[slot] = noise_rad / worst;
        }
    }
    w
}

/// Where Levenberg-Marquardt left a fit (its information in the caller's buffer).
pub(super) struct Solved<T: Real> {
    pub(super) x: [T; MAX_PARAMS],
    pub(super) cost: T,
    pub(super) worst: (T, usize),
    pub(super) iterations: u32,
}

/// Levenberg-Marquardt on `layout` from `x`; the information at the solution is left
/// in `info`.
// A frame of its own: its one square matrix (the trial's) leaves the stack when it
// returns (the pendant's fit is stack-measured on target).
#[inline(never)]
pub(super) fn levenberg_marquardt<T: Real>(
    info: &mut Information<T>,
    model: &Stage2Model<T>,
    layout: &Layout,
    poses: &[PoseReading<T>],
    mut x: [T; MAX_PARAMS],
    held: &Held<T>,
    config: &FitConfig<T>,
) -> Result<Solved<T>, FitError> {
    let n = layout.len();
    let (mut cost, mut worst) = linearise(info, model, layout, poses, &x, true, held);
    check_conditioning(info, layout, config.max_condition_number)?;
    // The damped factor and then the candidate's information: one buffer for both.
    let mut trial = Information::new(0);

    let mut lambda = T::zero();
    let mut iterations = 0;
    let mut converged = false;
    // Accept equal cost within rounding, so a step at the precision floor is not
    // mistaken for a worse one.
    let slack = T::one() + T::lit(8.0) * T::EPSILON;
    while iterations < config.max_iterations {
        iterations += 1;
        let mut step = info
            .step(lambda, &mut trial)
            .ok_or(FitError::NonFiniteResult)?;
        if !step.iter().take(n).all(|s| s.is_finite()) {
            return Err(FitError::NonFiniteResult);
        }
        // A trust region on the geometric terms: no step moves one by more than its
        // stated worst case. A turn of tens of degrees about a direction the poses see
        // only to first order is a valley of the cost the Gauss-Newton step can leap
        // into (found at 40° where the minimum was at 0.3°). The reducer terms are
        // errors of a joint's angle, as the offsets are: no such valley, and a bound at
        // their prior's size crawled the fit of a pose not reached (a harmonic fifty
        // priors out) a fiftieth of the way a step, into no convergence.
        let mut scale = T::one();
        for ((st, w), p) in step
            .iter()
            .zip(&held.prior_weight)
            .zip(layout.params())
            .take(n)
        {
            if *w > T::zero() && transmission::prior_sd_rad::<T>(*p).is_none() {
                let bound = config.sensor_noise_rad / *w;
                if st.abs() * scale > bound {
                    scale = bound / st.abs();
                }
            }
        }
        if scale < T::one() {
            for st in step.iter_mut().take(n) {
                *st *= scale;
            }
        }
        // Convergence is judged on the angles (the offsets); the other terms are
        // dimensionless or per metre, and follow them.
        let size = step[..WRIST_JOINTS]
            .iter()
            .fold(T::zero(), |m, s| m.max(s.abs()));
        let small = size < T::STEP_TOLERANCE_RAD;
        let mut candidate = x;
        for (c, s) in candidate.iter_mut().zip(&step).take(n) {
            *c += *s;
        }
        let (cand_cost, cand_worst) =
            linearise(&mut trial, model, layout, poses, &candidate, true, held);
        // Below LOCAL_STEP_RAD the linearisation error (∝ δ²) is far under the noise, so
        // the Gauss-Newton step is trusted as it is: there the cost's own rounding noise
        // (~1e-3 relative in f32) would otherwise reject genuine steps and stall the
        // fit short of the minimum.
        let local = size < T::lit(LOCAL_STEP_RAD);
        if cand_cost.is_finite() && (local || cand_cost <= cost * slack) {
            x = candidate;
            core::mem::swap(info, &mut trial);
            cost = cand_cost;
            worst = cand_worst;
            lambda /= T::lit(10.0);
            if lambda < T::EPSILON {
                lambda = T::zero();
            }
        } else {
            // Gauss-Newton overshot: damp towards gradient descent. The scale is that of
            // JᵀJ's diagonal (trace/n = ‖R‖²/n).
            lambda = if lambda == T::zero() {
                T::lit(1e-3) * info.norm_squared() / T::lit(n as f64)
            } else {
                lambda * T::lit(10.0)
            };
        }
        if small {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(FitError::NoConvergence { iterations });
    }
    Ok(Solved {
        x,
        cost,
        worst,
        iterations,
    })
}
