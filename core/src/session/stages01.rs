//! Stages 0 and 1 and what they hand to stage 2: the sensor's bias from the bench
//! readings (at the stages' temperatures, drifting as the closing readings measured),
//! stage 1's half turn of axis 1 solved on it, the temperatures the bias model can
//! follow, and the stage-2 model built from both ([`Handover`]).

use super::{BiasSource, SessionError, StageTemperatures};
use crate::model::{Arm, Convention, Gain, SensorBias, SensorModel, Tilt};
use crate::real::Real;
use crate::stage0::{BenchStep, BenchTurnsAt, BiasOverTemperature};
use crate::stage1::{AxisOneTurn, Stage1Result};
use crate::stage2::{MassModel, PoseReading, Stage2Model};

/// Without a closing reversal the drift is unknown: stage 2's temperatures may differ
/// from stage 0's by at most this (K). At the SCL3300's up to ~0.009 °/K
/// ([`SENSOR_DRIFT_SPEC_G_PER_K`]) 0.5 K is 0.0045°, just inside the 0.005° aimed at.
pub const MAX_UNMEASURED_DRIFT_K: f64 = 0.5;

/// The SCL3300's offset drift with temperature, ± (g/K) on x and y: the chip crate's
/// [`zerocal_scl3300::spec::OFFSET_DRIFT_G_PER_K`] (0.009 °/K). Where no closing bench
/// readings measured the drift, it is what the bias may have done between captures at
/// different temperatures: the refusal rule does not call a drift of the readings that
/// this explains a creeping bracket, and the budget carries it
/// ([`super::unmeasured_drift_half_width`]).
pub const SENSOR_DRIFT_SPEC_G_PER_K: f64 = zerocal_scl3300::spec::OFFSET_DRIFT_G_PER_K;

/// [`SENSOR_DRIFT_SPEC_G_PER_K`] as an angle at level (rad/K).
pub fn sensor_drift_spec_rad_per_k<T: Real>() -> T {
    T::lit(libm::asin(SENSOR_DRIFT_SPEC_G_PER_K))
}

/// Whether the bias' drift with temperature was measured: stage 0's bench readings and
/// the closing ones after stage 2, both with their temperatures.
pub fn drift_measured<T: Real>(bias: &Option<BiasOverTemperature<T>>) -> bool {
    // `closing_c` is set only where the two bench solves' temperatures gave a slope.
    bias.as_ref().is_some_and(|b| b.closing_c.is_some())
}

/// With a closing reversal the drift is linear between the two reversals' temperatures:
/// a capture may lie outside them by at most this (K).
pub const MAX_DRIFT_EXTRAPOLATION_K: f64 = 1.0;

/// The two reversals may differ by at most this (K): the offset's temperature curve is
/// not a line over tens of kelvin (the SCA3300 data sheet's Figure 2, the SCL3300 notes'
/// §2.9), and a box that warms this much is not settled.
pub const MAX_DRIFT_SPAN_K: f64 = 10.0;

/// What stages 0-1 hand to stage 2: the model of the arm, the tilt, Δθ2 and the sensor,
/// and how well they are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handover<T: Real> {
    /// The stage-2 model.
    pub model: Stage2Model<T>,
    /// Covariance of (α, β, Δθ2, bias x, bias y) in units of one reading's noise
    /// variance (stage 1's, with stage 0's propagated).
    pub covariance: [[T; 5]; 5],
    /// The part of `covariance` that stage 0's bias brings.
    pub covariance_from_stage0: [[T; 5]; 5],
}

/// Stage 2's model from stages 0-1: the measured base tilt and Δθ2 (joint 2's true
/// angle is its recorded one plus Δθ2, wherever stage 2 has it), the stage-0 bias, or
/// without stage 0 an x bias of 0 (the report warns) and stage 1's y bias.
///
/// Why stage 0's y bias where there is one: stage 1's half-sum of the y readings is the
/// y bias plus whatever turns with joint 1, and a joint-2 axis tilted off the drawing
/// (out of the plane normal to joint 1's axis, 0.005-0.05° on real arms) turns with
/// joint 1 exactly as the sensor's bias does. Taken as the bias, that tilt went into the
/// flange's readings as a bias error no stage-2 pose separates (up to the whole tilt in
/// Δθ6 on the paper's wrist); with the bench's bias, stage 2 fits the tilt itself
/// (`Param::Tilt(0)`).
pub fn handover<T: Real>(
    stage1: &Stage1Result<T>,
    arm: Arm<T>,
    convention: Convention,
    bias: Option<&SensorBias<T>>,
    masses: Option<MassModel<T>>,
) -> Handover<T> {
    let bias = bias.map(|b| BiasOverTemperature::constant(*b, None));
    handover_at(stage1, arm, convention, bias.as_ref(), None, masses)
}

/// As [`handover`], with the bias following the temperature: the model's bias is
/// stage 1's (x from the reversals at stage 1's temperature, y from the half turn),
/// and it drifts from there as the reversals measured.
pub fn handover_at<T: Real>(
    stage1: &Stage1Result<T>,
    arm: Arm<T>,
    convention: Convention,
    bias: Option<&BiasOverTemperature<T>>,
    stage1_c: Option<T>,
    masses: Option<MassModel<T>>,
) -> Handover<T> {
    Handover {
        model: Stage2Model {
            arm,
            base_tilt: stage1.base_tilt,
            delta_theta2_rad: stage1.delta_theta2_rad,
            stage1_j2_rad: stage1.j2_rad,
            sensor: SensorModel::new(
                convention,
                bias.map_or(Tilt::new(T::zero(), stage1.bias_y_rad), |b| b.at(stage1_c)),
            ),
            reference_temperature_c: stage1_c
                .or(bias.and_then(|b| b.reference_c))
                .unwrap_or(T::zero()),
            drift_per_k: bias.map_or(Tilt::default(), |b| b.drift_per_k),
            masses,
            y_weight: match convention {
                Convention::Axis => T::lit(crate::stage2::MEMS_Y_WEIGHT),
                Convention::Rpy => T::one(),
            },
        },
        covariance: bias.map_or(stage1.covariance, |_| bench_y(&stage1.covariance)),
        covariance_from_stage0: bias.map_or(stage1.covariance_from_stage0, |_| {
            bench_y(&stage1.covariance_from_stage0)
        }),
    }
}

/// Stage 1's covariance with the y bias taken from stage 0 instead of stage 1's
/// half-sum: the bench's y bias is known as well as its x bias (one variance factor for
/// the circle's centre), and independently of stage 1's readings and of the bench's x
/// (the headings' centre: its x and y from orthogonal components), so its row holds its
/// variance alone. α, β and Δθ2 do not depend on the y bias (stage 1 solves them with
/// it unknown).
fn bench_y<T: Real>(c: &[[T; 5]; 5]) -> [[T; 5]; 5] {
    const BIAS_X: usize = 3;
    const BIAS_Y: usize = 4;
    let mut out = *c;
    for k in 0..5 {
        out[BIAS_Y][k] = T::zero();
        out[k][BIAS_Y] = T::zero();
    }
    out[BIAS_Y][BIAS_Y] = c[BIAS_X][BIAS_X];
    out
}

/// Stage 1 on the bias of stage 0: the part of the chain the pendant runs as soon as
/// stage 1's second reading is in, to ask for it again if it is refused.
///
/// # Errors
/// Stage 0's or stage 1's refusal.
pub fn solve_stages01<T: Real>(
    bias: &BiasSource<T>,
    stage1: &AxisOneTurn<T>,
    arm: &Arm<T>,
    convention: Convention,
    range_rad: T,
) -> Result<(Option<SensorBias<T>>, Stage1Result<T>), SessionError> {
    let bias = bias_over_temperature(
        bias,
        &StageTemperatures::default(),
        None,
        &BenchSettings {
            convention,
            gain: Gain::default(),
            range_rad,
            noise_rad: T::zero(),
        },
    )?;
    let s1 = solve_stage1(
        &bias,
        None,
        &Stage1Setup {
            turn: stage1,
            arm,
            convention,
            range_rad,
        },
        Gain::default(),
        T::one(),
    )?;
    Ok((bias.map(|b| b.bias), s1))
}

/// What the bench readings are solved with: the convention, the sensor's gain (stage
/// 2's, once known), the range, and one reading's noise to judge their residuals by.
pub(super) struct BenchSettings<T> {
    pub(super) convention: Convention,
    pub(super) gain: Gain<T>,
    pub(super) range_rad: T,
    pub(super) noise_rad: T,
}

pub(super) fn bias_over_temperature<T: Real>(
    bias: &BiasSource<T>,
    temperatures: &StageTemperatures<T>,
    closing: Option<&BenchTurnsAt<T>>,
    settings: &BenchSettings<T>,
) -> Result<Option<BiasOverTemperature<T>>, SessionError> {
    Ok(match bias {
        BiasSource::Bench(r) => Some(
            BiasOverTemperature::measure(
                &BenchTurnsAt {
                    turns: *r,
                    temperature_c: temperatures.stage0_c,
                },
                closing,
                settings.convention,
                settings.gain,
                settings.range_rad,
                settings.noise_rad,
            )
            .map_err(|(step, e)| match step {
                BenchStep::Stage0 => SessionError::Stage0(e),
                BenchStep::Closing => SessionError::Closing(e),
            })?,
        ),
        BiasSource::Stored(b) => Some(BiasOverTemperature::constant(*b, None)),
        BiasSource::Unknown => None,
    })
}

/// Stage 1 with the bias at its temperature (a reversal's half-sum has half a reading's
/// variance, a stored bias too: it was such a half-sum).
pub(super) fn solve_stage1<T: Real>(
    bias: &Option<BiasOverTemperature<T>>,
    stage1_c: Option<T>,
    setup: &Stage1Setup<'_, T>,
    gain: Gain<T>,
    captures_per_reading: T,
) -> Result<Stage1Result<T>, SessionError> {
    // Variances are in units of one reading of stages 1-2; a reversal's readings are
    // single captures, `captures_per_reading` times noisier than a reading that
    // averages that many.
    let at = bias.as_ref().map(|b| {
        (
            b.at(stage1_c),
            b.variance_factor(stage1_c) * captures_per_reading,
        )
    });
    setup
        .turn
        .solve_with_gain(
            setup.arm,
            setup.convention,
            gain,
            at.as_ref().map(|(b, v)| (b, *v)),
            setup.range_rad,
        )
        .map_err(SessionError::Stage1)
}

/// What stage 1 is solved on, besides the bias.
pub(super) struct Stage1Setup<'a, T: Real> {
    pub(super) turn: &'a AxisOneTurn<T>,
    pub(super) arm: &'a Arm<T>,
    pub(super) convention: Convention,
    pub(super) range_rad: T,
}

/// Refuses a session whose temperatures the bias model cannot follow.
pub(super) fn check_temperatures<T: Real>(
    bias: &Option<BiasOverTemperature<T>>,
    poses: &[PoseReading<T>],
) -> Result<(), SessionError> {
    let Some(b) = bias else { return Ok(()) };
    let Some(t0) = b.reference_c else {
        return Ok(());
    };
    if let Some(t1) = b.closing_c {
        let span = (t1 - t0).abs();
        if span > T::lit(MAX_DRIFT_SPAN_K) {
            return Err(SessionError::Warmed {
                kelvin: span.to_f64() as f32,
                limit_k: MAX_DRIFT_SPAN_K as f32,
                drift_measured: true,
            });
        }
    }
    let (lo, hi, limit, measured) = match b.closing_c {
        Some(t1) => (
            t0.min(t1),
            t0.max(t1),
            T::lit(MAX_DRIFT_EXTRAPOLATION_K),
            true,
        ),
        None => (t0, t0, T::lit(MAX_UNMEASURED_DRIFT_K), false),
    };
    let worst = poses
        .iter()
        .filter_map(|p| p.temperature_c)
        .map(|t| (lo - t).max(t - hi).max(T::zero()))
        .fold(T::zero(), |m, d| m.max(d));
    if worst > limit {
        return Err(SessionError::Warmed {
            kelvin: worst.to_f64() as f32,
            limit_k: limit.to_f64() as f32,
            drift_measured: measured,
        });
    }
    Ok(())
}
