//! Stage 0 (optional): the sensor's zero error by reversal.
//!
//! The pendant is read on any stable surface, turned 180° about the vertical on the same
//! spot and read again. Turning the sensor half a turn about its own z axis negates both
//! bias-free angles in either convention (u_x, u_y change sign, u_z does not), so the
//! half-sum of the two readings is the bias, exactly, whatever the surface's tilt.

use crate::error::StageError;
use crate::model::{SensorBias, Tilt};
use crate::real::{rad_to_deg, Real};

/// Checks that a reading is finite and inside the sensor's range (stages 0 and 1).
pub(crate) fn check_reading<T: Real>(t: &Tilt<T>, range_rad: T) -> Result<(), StageError> {
    if !t.is_finite() {
        return Err(StageError::NonFiniteReading);
    }
    match t.axis_beyond(range_rad) {
        Some(axis) => Err(StageError::ReadingOutOfRange {
            axis,
            value_deg: rad_to_deg(t.get(axis)).to_f64() as f32,
            range_deg: rad_to_deg(range_rad).to_f64() as f32,
        }),
        None => Ok(()),
    }
}

/// The two readings of a reversal.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Reversal<T> {
    /// Reading before the half turn.
    pub first: Tilt<T>,
    /// Reading after the half turn.
    pub second: Tilt<T>,
}

impl<T: Real> Reversal<T> {
    /// The sensor bias `(r + r')/2`.
    ///
    /// # Errors
    /// A non-finite reading, or one outside `±range_rad`.
    pub fn bias(&self, range_rad: T) -> Result<SensorBias<T>, StageError> {
        check_reading(&self.first, range_rad)?;
        check_reading(&self.second, range_rad)?;
        let half = T::lit(0.5);
        Ok(Tilt::new(
            (self.first.x_rad + self.second.x_rad) * half,
            (self.first.y_rad + self.second.y_rad) * half,
        ))
    }
}
