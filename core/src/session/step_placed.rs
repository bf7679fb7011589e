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

use super::judge::{evidence_with_steps, StepTable};
use super::Handover;
use crate::error::FitError;
use crate::plan::MAX_POSES;

// The candidates are bits of a u64.
const _: () = assert!(MAX_POSES <= 64);
use crate::real::Real;
use crate::stage2::{fit, FitConfig, FitResult, PoseReading};

/// Places whose fall is within this fraction of the largest are fitted again.
const NEAR_LARGEST: f64 = 0.5;

/// Refits per place: the step's size is taken again against each refit (the first
/// fit, holding the knock, sees about half of it).
const REFITS: usize = 3;

/// The residual RMS of the session fitted with the readings from `m` on taken back by
/// the step found there (refitted [`REFITS`] times) and that step's size (rad), `None`
/// where a fit fails. `steps` is scratch for the step test's table.
fn stepped_rms<T: Real>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    m: usize,
    config: &FitConfig<T>,
    first: &FitResult<T>,
    steps: &mut StepTable<T>,
) -> Option<(T, T)> {
    let mut shift = [T::zero(); 2];
    let mut current = *first;
    let mut taken: heapless::Vec<PoseReading<T>, MAX_POSES> = heapless::Vec::new();
    for p in poses {
        taken.push(*p).ok()?;
    }
    for _ in 0..REFITS {
        evidence_with_steps(&h.model, &current, &taken, None, Some(steps));
        let (s, _) = steps.get(m)?;
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
/// leaves the smallest residuals and the step's size there (rad), among the places
/// whose fall against `first` (the fit that holds the step) is near the largest, run
/// as the session's stage 2 was (`config` with the hand-over `h` and its noise per
/// reading); `None` where no place could be refitted.
#[inline(never)]
pub fn step_placed<T: Real>(
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    first: &FitResult<T>,
    config: &FitConfig<T>,
    handover_noise_rad: T,
) -> Option<(usize, T)> {
    let config = FitConfig {
        model_covariance: h.covariance,
        handover_noise_rad,
        max_residual_rms_rad: T::zero(),
        ..*config
    };
    let mut steps: StepTable<T> = [([T::zero(); 2], T::zero()); MAX_POSES];
    evidence_with_steps(&h.model, first, poses, None, Some(&mut steps));
    // Places the step test does not look at keep a fall of 0.
    let largest = steps.iter().fold(T::zero(), |a, &(_, d)| a.max(d));
    // The candidates, one bit a place (MAX_POSES ≤ 64): the table is scratch for the
    // refits that follow.
    let mut candidates = 0u64;
    for (m, &(_, fall)) in steps.iter().enumerate() {
        if fall > T::zero() && fall >= largest * T::lit(NEAR_LARGEST) {
            candidates |= 1 << m;
        }
    }
    let mut best: Option<(T, usize, T)> = None;
    for m in (0..MAX_POSES).filter(|m| candidates & (1 << m) != 0) {
        let Some((rms, size)) = stepped_rms(h, poses, m, &config, first, &mut steps) else {
            continue;
        };
        if best.is_none_or(|(b, _, _)| rms < b) {
            best = Some((rms, m, size));
        }
    }
    best.map(|(_, m, size)| (m, size))
}

/// `fault`, with a knock's place and size taken again by [`step_placed`] against the fit
/// `first` (the session's, holding the knock) where the fault is the pendant moving.
pub fn placed<T: Real>(
    fault: FitError,
    h: &Handover<T>,
    poses: &[PoseReading<T>],
    first: &FitResult<T>,
    config: &FitConfig<T>,
    handover_noise_rad: T,
) -> FitError {
    let FitError::PendantMoved { .. } = fault else {
        return fault;
    };
    match step_placed(h, poses, first, config, handover_noise_rad) {
        Some((from_pose, size_rad)) => FitError::PendantMoved {
            from_pose,
            step_deg: crate::real::rad_to_deg(size_rad).to_f64() as f32,
        },
        None => fault,
    }
}
