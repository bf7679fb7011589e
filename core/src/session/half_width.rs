//! How far the zeros swing with what a session cannot measure: the session solved
//! again with the unknown at either end of its stated range (the sensor's x offset
//! without a bench, stage 0's half turn off 180° when two headings were read), half
//! the difference taken as the swing.

use super::SESSION_JOINTS;
use super::{sensor_offset_x_spec_deg, solve, BiasSource, SessionError, SessionReadings};
use crate::model::Tilt;
use crate::real::Real;
use crate::stage0::{BenchTurns, BenchTurnsAt};
use crate::stage2::FitConfig;

/// For a session without a stage-0 reversal: how far each of Δθ2..Δθ6 moves with the
/// sensor's unknown x offset, as half the difference between the session solved with
/// the offset at +[`sensor_offset_x_spec_deg`] and at −it (rad). The solver then takes
/// the offset as 0, and stage 1 cannot tell it from Δθ2 (the upper arm's tilt about
/// joint 2 and the sensor's x offset read alike), so without this the offsets carry an
/// error of up to a degree their noise-only σ does not show. `None` when the session
/// has a bias (a reversal, or a stored one).
///
/// # Errors
/// The solver's refusal at either end of the range.
pub fn unknown_offset_half_width<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
) -> Result<Option<[T; SESSION_JOINTS]>, SessionError> {
    if readings.bias != BiasSource::Unknown {
        return Ok(None);
    }
    let limit_rad = crate::real::deg_to_rad(T::lit(sensor_offset_x_spec_deg()));
    let at = |x_rad: T| {
        let r = SessionReadings {
            bias: BiasSource::Stored(Tilt::new(x_rad, T::zero())),
            ..*readings
        };
        solve(&r, config).result.map(|s| s.offsets_rad)
    };
    let (plus, minus) = (at(limit_rad)?, at(-limit_rad)?);
    Ok(Some(core::array::from_fn(|k| {
        ((plus[k] - minus[k]) * T::lit(0.5)).abs()
    })))
}

/// The half turn of stage 0's reversal made by hand is off 180° by up to this (deg) when
/// nothing else is stated: a stated figure (no jig, a turn judged by eye against the
/// box's edges); no public source gives one.
pub const DEFAULT_HALF_TURN_TOLERANCE_DEG: f64 = 1.0;

/// Stage 0's half turn made against a straight edge (the jig: the pendant's long side
/// against a fence on the bench, turned end for end against the same fence) is off 180°
/// by no more than the box's two long sides are out of parallel: the box's drawing
/// requires 0.05 mm over its 60 mm, 0.048° (docs/method.md, stage 0). A design
/// requirement, stated with `zerocal session --half-turn-tolerance-deg 0.05`.
pub const JIG_HALF_TURN_TOLERANCE_DEG: f64 = 0.05;

/// How far each of Δθ2..Δθ6 moves with stage 0's half turn off 180° by up to
/// `tolerance_rad` (rad, half the swing). A turn of π + ε on a bench tilted by t leaves
/// the reversal's half-sum off by ε·|t|/2, perpendicular to the tilt (the two readings'
/// horizontal parts no longer cancel); the reversal measures t itself (their half
/// difference). The session is solved with the bias moved that far either way. `None`
/// without a stage-0 reversal.
///
/// # Errors
/// The solver's refusal at either end.
pub fn half_turn_half_width<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
    tolerance_rad: T,
) -> Result<Option<[T; SESSION_JOINTS]>, SessionError> {
    let BiasSource::Bench(opening) = readings.bias else {
        return Ok(None);
    };
    // Three or more headings solve their own turns: no half turn is assumed.
    if opening.count != 2 {
        return Ok(None);
    }
    let half = T::lit(0.5);
    // The reversal moved as a turn of π ± tolerance would move it: ε·|t|/2 along the
    // tilt t (the readings' half difference) turned a quarter turn, (−t_y, t_x)·ε/2.
    let moved = |r: &BenchTurns<T>, sign: T| {
        if r.count != 2 {
            return *r;
        }
        let t = r.tilt_seen_first();
        r.shifted(&Tilt::new(
            -t.y_rad * tolerance_rad * half * sign,
            t.x_rad * tolerance_rad * half * sign,
        ))
    };
    // Both reversals (the closing one too, where made) off the same way: the worst case.
    let at = |sign: T| {
        let moved_readings = SessionReadings {
            bias: BiasSource::Bench(moved(&opening, sign)),
            closing: readings.closing.map(|c| BenchTurnsAt {
                turns: moved(&c.turns, sign),
                ..c
            }),
            ..*readings
        };
        solve(&moved_readings, config).result.map(|s| s.offsets_rad)
    };
    let (plus, minus) = (at(T::one())?, at(-T::one())?);
    Ok(Some(core::array::from_fn(|k| {
        ((plus[k] - minus[k]) * half).abs()
    })))
}
