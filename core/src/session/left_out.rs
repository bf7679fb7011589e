//! One pose judged against the fit without it: the refusal rule's second look at the
//! pose most unlike the others ([`super::judge::Evidence::outlier`]) when a session is
//! already about to be refused (its residuals past their limit, or stages 0-1 refusing
//! the gain its stage 2 measured).
//!
//! The outlier test of [`super::judge::evidence`] weighs a pose against the fit that
//! holds it. With the reducers' terms in the model (tens of parameters over forty-odd
//! poses) a pose the robot did not reach pulls that fit towards itself: its residuals
//! spread over the others, its F falls under the limit and the session is refused as
//! "residuals too large" without saying where. Fitted without the pose, the rest is a
//! robot again and the pose stands out by its full error: F is the same test
//! (`F = (ΔSSR/2) / (SSR₋ₚ/(dof₋ₚ))`, with `ΔSSR = eᵀ(I + H)⁻¹e` for the pose's
//! prediction error e and its leverage H under the fit without it), with the same
//! limits. It costs one more fit, so it runs only on the way to a refusal.

use super::judge::RefusalRule;
use super::Handover;
use crate::error::FitError;
use crate::plan::MAX_POSES;
use crate::real::{deg_to_rad, rad_to_deg, Real};
use crate::stage2::{
    add_held, fit, FitConfig, FitResult, Information, PoseReading, Stage2Model, MAX_PARAMS,
};

/// A pose against the fit of the others.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LeftOut<T> {
    /// The pose (0-based, fitted order).
    pub pose: usize,
    /// Its readings' difference from the others' fit (rad, the larger of x and y).
    pub size_rad: T,
    /// Its F against the others' scatter.
    pub f: T,
    /// The others' residual RMS (rad, per reading, y weighted as the fit weighs it).
    pub others_rms_rad: T,
}

/// `poses[pose]` against the fit of the others, run as the session's stage 2 was
/// (`config` with the hand-over `h` and its noise per reading). `None` where the
/// others cannot be fitted or too few are left to judge by.
// A frame of its own: the poses' copy and the fit's settings leave the stack when it
// returns (the session's solve is stack-measured on target, and this never runs there).
#[inline(never)]
pub fn left_out<T: Real>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    pose: usize,
    config: &FitConfig<T>,
    handover_noise_rad: T,
) -> Option<LeftOut<T>> {
    let left = poses.get(pose)?;
    let model = &h.model;
    let config = FitConfig {
        model_covariance: h.covariance,
        handover_noise_rad,
        max_residual_rms_rad: T::zero(),
        ..*config
    };
    let mut others: heapless::Vec<PoseReading<T>, MAX_POSES> = heapless::Vec::new();
    for (i, p) in poses.iter().enumerate() {
        if i != pose {
            others.push(*p).ok()?;
        }
    }
    let refit = fit(model, &others, &config).ok()?;
    against(model, &refit, &others, left, pose)
}

/// `left` against `refit` (the fit of `others`).
// A frame of its own: its square matrix leaves the stack when it returns.
#[inline(never)]
fn against<T: Real>(
    model: &Stage2Model<T>,
    refit: &FitResult<T>,
    others: &[PoseReading<T>],
    left: &PoseReading<T>,
    pose: usize,
) -> Option<LeftOut<T>> {
    let layout = refit.extras.layout();
    let n = layout.len();
    let estimate = refit.estimate(&layout);
    let pass = model.pass(&estimate, &layout);
    let w = model.y_weight;
    let mut rows = [[T::zero(); MAX_PARAMS]; 2];
    let mut info = Information::new(n);
    let mut ssr = T::zero();
    for p in others {
        let (reading, _) = model.predict_into(&pass, &layout, &estimate, p, false, &mut rows);
        let r = p.reading.minus(&reading);
        ssr += r.x_rad * r.x_rad + r.y_rad * w * r.y_rad * w;
        info.add_row(&rows[0], T::zero());
        info.add_row(&rows[1], T::zero());
    }
    add_held(&mut info, &refit.extras, refit.prior_noise_rad);
    let readings = 2 * others.len();
    let dof = readings.checked_sub(n).filter(|d| *d > 0)?;
    let (reading, _) = model.predict_into(&pass, &layout, &estimate, left, false, &mut rows);
    let d = left.reading.minus(&reading);
    let e = [d.x_rad, d.y_rad * w];
    let inv = info.invert_in_place()?;
    let quad = |u: &[T; MAX_PARAMS], v: &[T; MAX_PARAMS]| {
        let mut acc = T::zero();
        for i in 0..n {
            for k in 0..n {
                acc += u[i] * inv.m[i][k] * v[k];
            }
        }
        acc
    };
    // (I + H), H = A(JᵀJ)⁻¹Aᵀ for the pose's two rows A.
    let h01 = quad(&rows[0], &rows[1]);
    let m = [
        [T::one() + quad(&rows[0], &rows[0]), h01],
        [h01, T::one() + quad(&rows[1], &rows[1])],
    ];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if !det.is_finite() || det <= T::EPSILON || ssr <= T::zero() {
        return None;
    }
    let delta =
        (m[1][1] * e[0] * e[0] - T::lit(2.0) * m[0][1] * e[0] * e[1] + m[0][0] * e[1] * e[1]) / det;
    let f = (delta / T::lit(2.0)) / (ssr / T::lit(dof as f64));
    Some(LeftOut {
        pose,
        size_rad: d.x_rad.abs().max(d.y_rad.abs()),
        f,
        others_rms_rad: (ssr / T::lit(readings.max(1) as f64)).sqrt(),
    })
}

/// The fault `left` shows by the rule's outlier limits ([`RefusalRule::outlier_limit`],
/// [`RefusalRule::outlier_floor_deg`]), where the others alone are a robot (their
/// residual RMS within `max_residual_rms_rad`, where that is set): the pose named.
pub fn judge_left_out<T: Real>(
    left: &LeftOut<T>,
    rule: &RefusalRule,
    max_residual_rms_rad: T,
) -> Option<FitError> {
    let quiet = max_residual_rms_rad <= T::zero() || left.others_rms_rad <= max_residual_rms_rad;
    let stands_out = rule.outlier_floor_deg.is_finite()
        && left.size_rad > deg_to_rad(T::lit(rule.outlier_floor_deg))
        && rule.outlier_limit.is_finite()
        && left.f > T::lit(rule.outlier_limit);
    (quiet && stands_out).then(|| FitError::PoseNotReached {
        pose: left.pose,
        residual_deg: rad_to_deg(left.size_rad).to_f64() as f32,
        others_rms_deg: rad_to_deg(left.others_rms_rad).to_f64() as f32,
    })
}

/// The suspects (`poses` indices; a repeat is judged once), each against the fit of
/// the others ([`left_out`]; `config` the session's, its rule and residual limit the
/// refusal's): the one that stands out most by [`judge_left_out`], named. One fit per
/// suspect, so only on the way to a refusal.
#[inline(never)]
pub fn suspect_named<T: Real, const K: usize>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    suspects: [usize; K],
    config: &FitConfig<T>,
    handover_noise_rad: T,
) -> Option<FitError> {
    let mut best: Option<(T, FitError)> = None;
    for (i, &pose) in suspects.iter().enumerate() {
        if suspects[..i].contains(&pose) {
            continue;
        }
        let Some(l) = left_out(h, poses, pose, config, handover_noise_rad) else {
            continue;
        };
        if let Some(fault) = judge_left_out(&l, &config.refusal, config.max_residual_rms_rad) {
            if best.as_ref().is_none_or(|(f, _)| l.f > *f) {
                best = Some((l.f, fault));
            }
        }
    }
    best.map(|(_, fault)| fault)
}
