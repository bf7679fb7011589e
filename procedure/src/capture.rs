//! What one capture of stages 0 and 1 or of the closing bench readings holds: the still
//! window's mean reading and temperature. Here, apart from the procedure that takes it,
//! so the export's writer can carry it without reading the procedure's state.

use zerocal_core::model::Tilt;

/// A capture of stages 0 and 1 or of the closing bench readings: the stillness window's mean
/// reading and temperature.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Capture<T> {
    /// The mean reading (raw, bias included).
    pub reading: Tilt<T>,
    /// The mean temperature (°C), if the sensor reports one.
    pub temperature_c: Option<T>,
}
