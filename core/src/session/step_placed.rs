//! Where a pendant knocked on the flange moved: the refusal rule's second look at the
//! step it found ([`super::judge::Evidence::step`]) once the session is refused for it.
//!
//! The step test of [`super::judge::evidence`] weighs each place against the fit that
//! holds the knock. With the reducers' terms in the model, their priors weighed against
//! the residuals' scatter (which the knock inflates), that fit bends its harmonics
//! towards the step and leaves a fall of the squared residuals that hardly changes over
//! a dozen places: on the UR5e (refusal_rule's session 500) a 0.1° knock before pose 12
//! left a fall of 7.46e-6 rad² before pose 9, 7.43e-6 before 11 and 6.82e-6 before 12,
//! and pose 9 was named in all ten sessions. Fitted again with the readings from the
//! place on taken back by the step, the rest is a robot again: the scatter falls to the
//! robot's, the priors tighten, and only the right place leaves the residuals of one
//! (the same session: 0.0025° RMS before pose 12, 0.0095° before 13, 0.015-0.032°
//! elsewhere). It costs a few fits per place, so it runs only on the way to
//! that refusal, over the places whose fall is near the largest.

use super::judge::step_at;
use super::Handover;
use crate::plan::MAX_POSES;
use crate::real::Real;
use crate::stage2::{fit, FitConfig, FitResult, PoseReading};

/// Places whose fall is within this fraction of the largest are fitted again.
const NEAR_LARGEST: f64 = 0.5;

/// Refits per place: the step's size is taken again against each refit (the first
/// fit, holding the knock, sees about half of it).
const REFITS: usize = 3;

/// The residual RMS of the session fitted with the readings from `m` on taken back by
/// the step found there (refitted [`REFITS`] times) and that step's size (rad), `None`
/// where a fit fails.
fn stepped_rms<T: Real>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    m: usize,
    config: &FitConfig<T>,
    first: &FitResult<T>,
) -> Option<(T, T)> {
    let mut shift = [T::zero(); 2];
    let mut current = *first;
    let mut taken: heapless::Vec<PoseReading<T>, MAX_POSES> = heapless::Vec::new();
    taken.extend_from_slice(poses).ok()?;
    for _ in 0..REFITS {
        let (s, _) = step_at(&h.model, &current, &taken, m)?;
        shift[0] += s[0];
        shift[1] += s[1];
        for (q, p) in taken.iter_mut().zip(poses).skip(m) {
            q.reading.x_rad = p.reading.x_rad - shift[0];
            q.reading.y_rad = p.reading.y_rad - shift[1];
        }
        current = fit(&h.model, &taken, config).ok()?;
    }
    Some((
        current.residual_rms_rad,
        (shift[0] * shift[0] + shift[1] * shift[1]).sqrt(),
    ))
}

/// The place of the step (the first pose after it, 0-based, fitted order) whose refit
/// leaves the smallest residuals and the step's size there (rad), among the places at
/// least `edge` poses from either end whose fall against `first` (the fit that holds
/// the step) is near the largest, run as the session's stage 2 was (`config` with the
/// hand-over `h` and its noise per reading); `None` where no place could be refitted.
#[inline(never)]
pub fn step_placed<T: Real>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    first: &FitResult<T>,
    config: &FitConfig<T>,
    handover_noise_rad: T,
    edge: usize,
) -> Option<(usize, T)> {
    let config = FitConfig {
        model_covariance: h.covariance,
        handover_noise_rad,
        max_residual_rms_rad: T::zero(),
        ..*config
    };
    let falls: heapless::Vec<(usize, T), MAX_POSES> = (edge..=poses.len().saturating_sub(edge))
        .filter_map(|m| Some((m, step_at(&h.model, first, poses, m)?.1)))
        .collect();
    let largest = falls.iter().fold(T::zero(), |a, &(_, d)| a.max(d));
    let mut best: Option<(T, usize, T)> = None;
    for &(m, fall) in &falls {
        if fall < largest * T::lit(NEAR_LARGEST) {
            continue;
        }
        let Some((rms, size)) = stepped_rms(h, poses, m, &config, first) else {
            continue;
        };
        if best.is_none_or(|(b, _, _)| rms < b) {
            best = Some((rms, m, size));
        }
    }
    best.map(|(_, m, size)| (m, size))
}
