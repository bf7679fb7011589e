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

/// The most stage-2 captures [`unmeasured_drift_half_width`] shifts: four times the
/// pendant's [`crate::capture::MAX_CAPTURES`] (a plain log may hold more than a pendant
/// session).
const DRIFT_SHIFT_CAPTURES: usize = 4 * crate::capture::MAX_CAPTURES;

/// Where no closing bench readings measured the bias' drift with temperature: how far
/// each of Δθ2..Δθ6 moves with the sensor's bias drifting at its stated rate
/// ([`super::sensor_drift_spec_rad_per_k`], 0.009 °/K) on x or on y, as half the
/// difference between the session solved with every reading moved by
/// `±drift·(t − t_ref)` (rad, the two axes' half swings in quadrature: each axis' drift
/// is its own, uniform within ±the rate). `t_ref` is the temperature the bias was
/// measured at (stage 0's; without stage 0, stage 1's, where stage 1 measures the y
/// bias; else the first capture's). Without it the refusal rule lets such a drift of
/// the readings pass as the sensor's own (it is not a creeping bracket), and the
/// offsets carry it unseen. `None` where the drift was measured, or no capture
/// recorded its temperature.
///
/// # Errors
/// The solver's refusal at either end (the refusal rule off: the session was judged
/// as read); [`SessionError::Warmed`] (limit 0 K) for a
/// session of more than four times the pendant's captures whose drift was not measured.
pub fn unmeasured_drift_half_width<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
) -> Result<Option<[T; SESSION_JOINTS]>, SessionError> {
    use super::stages01::{bias_over_temperature, drift_measured, BenchSettings};
    use crate::model::Gain;
    use crate::stage2::PoseReading;
    let bench = BenchSettings {
        convention: readings.convention,
        gain: Gain::default(),
        range_rad: config.sensor_range_rad,
        noise_rad: T::zero(),
    };
    let temps = &readings.temperatures;
    let bias = bias_over_temperature(&readings.bias, temps, readings.closing.as_ref(), &bench)?;
    if drift_measured(&bias) {
        return Ok(None);
    }
    let stage0_c = match readings.bias {
        BiasSource::Bench(_) => temps.stage0_c,
        _ => None,
    };
    let first_c = readings.poses.iter().find_map(|p| p.temperature_c);
    let Some(reference_c) = stage0_c.or(temps.stage1_c).or(first_c) else {
        return Ok(None);
    };
    let Some(last_c) = readings.poses.iter().rev().find_map(|p| p.temperature_c) else {
        return Ok(None);
    };
    if readings.poses.len() > DRIFT_SHIFT_CAPTURES {
        return Err(SessionError::Warmed {
            kelvin: (last_c - reference_c).abs().to_f64() as f32,
            limit_k: 0.0,
            drift_measured: false,
        });
    }
    let rate = super::sensor_drift_spec_rad_per_k::<T>();
    // The session moved by the drift is a sensitivity, not a session: it was judged as
    // it was read, and the drift added on top of the one it already has is no creep.
    let sensitivity = FitConfig {
        refusal: crate::stage2::refusal::RefusalRule::OFF,
        ..*config
    };
    let moved = |t: Option<T>, axis: Tilt<T>| {
        let dt = t.map_or(T::zero(), |t| t - reference_c);
        Tilt::new(axis.x_rad * rate * dt, axis.y_rad * rate * dt)
    };
    let at = |axis: Tilt<T>| {
        let mut poses: heapless::Vec<PoseReading<T>, DRIFT_SHIFT_CAPTURES> = heapless::Vec::new();
        for p in readings.poses {
            let d = moved(p.temperature_c, axis);
            // Room was checked above.
            let _ = poses.push(PoseReading {
                reading: Tilt::new(p.reading.x_rad + d.x_rad, p.reading.y_rad + d.y_rad),
                ..*p
            });
        }
        let d1 = moved(temps.stage1_c, axis);
        let shift = |r: Tilt<T>| Tilt::new(r.x_rad + d1.x_rad, r.y_rad + d1.y_rad);
        let r = SessionReadings {
            poses: &poses,
            stage1: crate::stage1::AxisOneTurn {
                before: shift(readings.stage1.before),
                after: shift(readings.stage1.after),
                ..readings.stage1
            },
            ..*readings
        };
        solve(&r, &sensitivity).result.map(|s| s.offsets_rad)
    };
    let mut squared = [T::zero(); SESSION_JOINTS];
    for axis in [
        Tilt::new(T::one(), T::zero()),
        Tilt::new(T::zero(), T::one()),
    ] {
        let neg = Tilt::new(-axis.x_rad, -axis.y_rad);
        let (plus, minus) = (at(axis)?, at(neg)?);
        for (s, (p, m)) in squared.iter_mut().zip(plus.iter().zip(&minus)) {
            let w = (*p - *m) * T::lit(0.5);
            *s += w * w;
        }
    }
    Ok(Some(squared.map(|s| s.sqrt())))
}
