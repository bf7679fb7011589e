//! Stage 0 (optional): the sensor's zero error by reversal.
//!
//! The pendant is read on any stable surface, turned 180° about the vertical on the same
//! spot and read again. Turning the sensor half a turn about its own z axis negates both
//! bias-free angles in either convention (u_x, u_y change sign, u_z does not), so the
//! half-sum of the two readings is the bias, exactly, whatever the surface's tilt.

use crate::error::StageError;
use crate::model::{SensorBias, Tilt};
use crate::real::Real;
use crate::stage1::check_reading;

/// The two readings of a reversal.
#[derive(Clone, Copy, Debug, PartialEq)]
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
