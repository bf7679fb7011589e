//! The calibration result as the pendant shows it and the CLI prints it: degrees,
//! 1σ beside every number, and a verdict that says what to distrust.

use crate::decimal::Fixed;
use crate::model::WRIST_JOINTS;
use crate::real::{rad_to_deg, Real};
use crate::stage1::Stage1Result;
use crate::stage2::{FitConfig, FitResult, SigmaSource};
use core::fmt::{self, Write};

/// A residual RMS this many times the sensor's noise means the data do not fit the
/// model: the robot moved, a pose was entered wrong, or the convention is wrong.
pub const RESIDUAL_WARN_FACTOR: f64 = 3.0;

/// With a residual ceiling (a real sensor on a real robot, whose repeatability leaves
/// part of itself in the residuals) the verdict warns when the residuals come within
/// this fraction of the refusal.
pub const RESIDUAL_WARN_OF_CEILING: f64 = 0.8;

/// The residual rule a verdict applies under a fit configuration: one place, so that a
/// certificate states the rule that was applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ResidualRule {
    /// Warn above [`RESIDUAL_WARN_OF_CEILING`] of the refusal ceiling (rad): the
    /// session is refused above the ceiling itself.
    OfCeiling {
        /// The refusal ceiling (rad).
        ceiling_rad: f64,
    },
    /// Warn above [`RESIDUAL_WARN_FACTOR`] times the sensor's noise (rad).
    OfNoise {
        /// The sensor's noise, 1σ (rad).
        noise_rad: f64,
    },
}

impl ResidualRule {
    /// The rule `config` sets.
    pub fn of<T: Real>(config: &FitConfig<T>) -> Self {
        let ceiling = config.max_residual_rms_rad.to_f64();
        if ceiling > 0.0 {
            ResidualRule::OfCeiling {
                ceiling_rad: ceiling,
            }
        } else {
            ResidualRule::OfNoise {
                noise_rad: config.sensor_noise_rad.to_f64(),
            }
        }
    }

    /// The residual RMS above which the verdict warns (rad).
    pub fn warn_above_rad(&self) -> f64 {
        match *self {
            ResidualRule::OfCeiling { ceiling_rad } => RESIDUAL_WARN_OF_CEILING * ceiling_rad,
            ResidualRule::OfNoise { noise_rad } => RESIDUAL_WARN_FACTOR * noise_rad,
        }
    }
}

/// Something the operator should know before trusting the numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Warning {
    /// Residual RMS far above the sensor's noise.
    ResidualHigh {
        /// Residual RMS (deg).
        residual_rms_deg: f64,
        /// Sensor noise 1σ (deg).
        sensor_noise_deg: f64,
    },
    /// No stage-0 bias: Δθ2 includes the sensor's x bias.
    BiasXUnknown,
    /// Too few poses to estimate σ: the 1σ are from the sensor's noise figure.
    SigmaFromSensorFigure,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Warning::ResidualHigh {
                residual_rms_deg,
                sensor_noise_deg,
            } => write!(
                f,
                "residual RMS {} deg is {}x the sensor noise ({} deg): robot moved, wrong pose or wrong convention?",
                Fixed::new(residual_rms_deg, 5),
                Fixed::new(residual_rms_deg / sensor_noise_deg, 1),
                Fixed::new(sensor_noise_deg, 5)
            ),
            Warning::BiasXUnknown => f.write_str(
                "no stage-0 reversal: the sensor's x bias is unknown; it is in the j2 offset and biases j3-j6 (run stage 0)",
            ),
            Warning::SigmaFromSensorFigure => {
                f.write_str("few poses: 1-sigma taken from the sensor's noise figure")
            }
        }
    }
}

/// At most this many warnings apply at once.
pub const MAX_WARNINGS: usize = 3;

/// Pass, or the warnings that apply.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Verdict {
    /// What to distrust; empty means pass.
    pub warnings: heapless::Vec<Warning, MAX_WARNINGS>,
}

impl Verdict {
    /// No warnings.
    pub fn is_pass(&self) -> bool {
        self.warnings.is_empty()
    }

    /// Judges a stage-2 result (and the stage-1 result, when there is one).
    pub fn judge<T: Real>(
        fit: &FitResult<T>,
        config: &FitConfig<T>,
        stage1: Option<&Stage1Result<T>>,
    ) -> Self {
        let mut v = Verdict::default();
        let rms = fit.residual_rms_rad.to_f64();
        let noise = config.sensor_noise_rad.to_f64();
        let warn_above = ResidualRule::of(config).warn_above_rad();
        // Capacity is MAX_WARNINGS and each variant is pushed at most once.
        if rms > warn_above {
            let _ = v.warnings.push(Warning::ResidualHigh {
                residual_rms_deg: rms.to_degrees(),
                sensor_noise_deg: noise.to_degrees(),
            });
        }
        if stage1.is_some_and(|s| !s.bias_x_known) {
            let _ = v.warnings.push(Warning::BiasXUnknown);
        }
        if fit.sigma_source == SigmaSource::SensorNoise {
            let _ = v.warnings.push(Warning::SigmaFromSensorFigure);
        }
        v
    }
}

/// Writes the report: Δθ2 (if stage 1 ran) and Δθ3..Δθ6 with 1σ, fit statistics and
/// the verdict. Plain ASCII, one item a line, so it reads the same on a terminal, in a
/// log and over the pendant's serial link.
///
/// # Errors
/// Only those of the writer.
pub fn write_report<T: Real, W: Write>(
    w: &mut W,
    stage1: Option<&Stage1Result<T>>,
    fit: &FitResult<T>,
    verdict: &Verdict,
) -> fmt::Result {
    writeln!(w, "joint  offset_deg    1sigma_deg")?;
    if let Some(s1) = stage1 {
        // Stage 1 uses the same sensor: its readings carry the σ the fit found.
        writeln!(
            w,
            "j2     {}    {}  (stage 1)",
            Fixed::signed(deg(s1.delta_theta2_rad), 5),
            Fixed::new(deg(s1.delta_theta2_sigma_rad(fit.noise_sigma_rad)), 5)
        )?;
    }
    for k in 0..WRIST_JOINTS {
        writeln!(
            w,
            "j{}     {}    {}",
            k + 3,
            Fixed::signed(deg(fit.offsets_rad[k]), 5),
            Fixed::new(deg(fit.sigma_rad[k]), 5)
        )?;
    }
    if let Some(s1) = stage1 {
        writeln!(
            w,
            "base tilt alpha {} deg, beta {} deg",
            Fixed::signed(deg(s1.base_tilt.alpha_rad), 5),
            Fixed::signed(deg(s1.base_tilt.beta_rad), 5)
        )?;
    }
    writeln!(
        w,
        "poses {}, residual RMS {} deg, iterations {}, condition number {}",
        fit.poses,
        Fixed::new(deg(fit.residual_rms_rad), 5),
        fit.iterations,
        Fixed::new(fit.condition_number.to_f64(), 1)
    )?;
    writeln!(
        w,
        "offset = true - commanded: the controller's reading of each joint must rise by it (docs/controllers/ says where)"
    )?;
    if verdict.is_pass() {
        writeln!(w, "verdict: PASS")
    } else {
        for warning in &verdict.warnings {
            writeln!(w, "verdict: WARN {warning}")?;
        }
        Ok(())
    }
}

fn deg<T: Real>(rad: T) -> f64 {
    rad_to_deg(rad).to_f64()
}
