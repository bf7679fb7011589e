//! The pendant's settings: the procedure's configuration for the SCL3300 in mode 4, and
//! the timings of the screens.

use zerocal_core::procedure::ProcedureConfig;
use zerocal_core::real::deg_to_rad;

/// Mode 4 is specified for inclinations within ±10° (deg): a reading beyond is flagged
/// and not captured.
pub const SENSOR_RANGE_DEG: f32 = 10.0;

/// Armed and not still for this long: the screen says the robot does not come to rest.
/// Longer than the longest move of a plan (180° on a joint at 30°/s peak is 9 s) plus
/// clipping the pendant on (3 s) and settling.
pub const STILL_MOVING_MS: u64 = 30_000;

/// The display is redrawn at most this often (ms): a 1 KiB frame takes ~25 ms of I2C
/// at 400 kHz, and a person reads nothing faster.
pub const REDRAW_PERIOD_MS: u64 = 100;

/// The procedure's configuration on the pendant: core's for a MEMS sensor
/// ([`ProcedureConfig::for_mems`]) with mode 4's range.
pub fn procedure_config() -> ProcedureConfig<f32> {
    let mut config = ProcedureConfig::for_mems();
    config.fit.sensor_range_rad = deg_to_rad(SENSOR_RANGE_DEG);
    config
}
