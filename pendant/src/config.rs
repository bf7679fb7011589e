//! The pendant's settings: the procedure's configuration for the SCL3300 in mode 4, and
//! the timings of the screens.

use zerocal_procedure::ProcedureConfig;

/// The display is redrawn at most this often (ms): a 1 KiB frame takes ~25 ms of I2C
/// at 400 kHz, and a person reads nothing faster.
pub const REDRAW_PERIOD_MS: u64 = 100;

/// The procedure's configuration on the pendant: the procedure's for a MEMS sensor
/// ([`ProcedureConfig::for_mems`]: mode 4's noise and range, from the chip crate's
/// datasheet figures).
pub fn procedure_config() -> ProcedureConfig<f32> {
    ProcedureConfig::for_mems()
}
