//! Driver for the Murata SCL3300 inclinometer: the pendant's only sensor.
//!
//! Ours rather than the `scl3300` crate (0.5), whose gaps matter here: it panics
//! (`unreachable!`) on a valid "self-test running" frame, converts angles as unsigned
//! (−0.13° reads 359.87°), never checks that a response answers the register asked
//! for, and has no recovery from the error status.
//!
//! - [`protocol`]: frames, CRC, registers, return status and status flags; pure.
//! - [`spec`]: the datasheet's figures the rest of zerocal uses (noise per output,
//!   range, offset limits), each with its source; pure.
//! - [`angle_rad`], [`temperature_celsius`]: register values to physical units; pure.
//! - `Scl3300` (feature `driver`, on by default): the one driver, async, over an
//!   `embedded-hal-async` 1.0 `SpiDevice` (mode 0, 2-4 MHz) and `DelayNs`. The pendant's
//!   sensor task awaits it; the simulators, host tests and fuzz targets run the same code
//!   through `blocking` (feature `blocking`).
//!
//! # Mounting and the `axis` convention
//!
//! The chip reports per-axis elevations, `ANG_X = atan2(a_X, hypot(a_Y, a_Z))` and
//! likewise `ANG_Y`, where `a` is the acceleration it measures: at rest `+1 g` on an
//! axis pointing up, so `a` is the up vector `u` in chip coordinates.
//!
//! The pendant's frame (the `x`, `y`, `z` of docs/method.md) is the chip's frame turned by
//! +90° about its Z axis, chip mounted component side up (chip Z up when the pendant
//! lies level):
//!
//! | pendant axis | chip axis |
//! | --- | --- |
//! | x | −Y |
//! | y | +X |
//! | z | +Z |
//!
//! Then docs/method.md's `axis` convention, `x = atan2(u_y, hypot(u_x, u_z))` and
//! `y = atan2(−u_x, hypot(u_y, u_z))`, is exactly `x = ANG_X`, `y = ANG_Y`: no sign
//! flips in the firmware. In words: x grows when the pendant rolls about its own
//! x axis (its y side rising); y grows when it pitches about its y axis (its x side
//! dropping). A board that mounts the chip otherwise must restate this table; check it
//! on a new board by tilting the pendant's y side up (x must read positive).
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
#![warn(missing_docs)]

#[cfg(feature = "blocking")]
pub mod blocking;
#[cfg(feature = "driver")]
mod driver;
mod error;
pub mod protocol;
pub mod spec;

#[cfg(feature = "driver")]
pub use driver::{RawSample, Scl3300, CS_HIGH_US};
pub use error::Error;
pub use protocol::{Command, Mode, Register, ReturnStatus, StatusFlags};

/// One count of an angle register (rad): 90° / 2¹⁴, i.e. 0.0055°.
pub const ANGLE_LSB_RAD: f32 = core::f32::consts::FRAC_PI_2 / 16384.0;

/// One count of an angle register (degrees).
pub const ANGLE_LSB_DEG: f32 = 90.0 / 16384.0;

/// An angle register value (ANG_X/Y/Z, two's complement) in radians: `raw / 2¹⁴ · 90°`.
/// The range is ±180°; negative tilts are negative values.
pub fn angle_rad(raw: u16) -> f32 {
    f32::from(raw as i16) * ANGLE_LSB_RAD
}

/// The temperature register value in degrees Celsius: `−273 + raw / 18.9`.
pub fn temperature_celsius(raw: u16) -> f32 {
    -273.0 + f32::from(raw) / 18.9
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f32, b: f32, tolerance: f32) -> bool {
        (a - b).abs() <= tolerance
    }

    #[test]
    fn angles_convert_with_sign() {
        let deg = |raw: u16| angle_rad(raw).to_degrees();
        assert!(close(deg(0), 0.0, 1e-9));
        assert!(close(deg(16384), 90.0, 1e-4));
        assert!(close(deg(1), 90.0 / 16384.0, 1e-7));
        // −0.13°: the case the `scl3300` crate reads as 359.87°.
        let raw = (-0.13_f32 / ANGLE_LSB_DEG).round() as i16 as u16;
        assert!(close(deg(raw), -0.13, ANGLE_LSB_DEG / 2.0), "{}", deg(raw));
        assert!(close(deg(0xFFFF), -ANGLE_LSB_DEG, 1e-7));
        assert!(close(deg(0xC000), -90.0, 1e-4));
        assert!(close(deg(0x8000), -180.0, 1e-3));
    }

    #[test]
    fn lsb_is_0_0055_degrees() {
        assert!(close(ANGLE_LSB_DEG, 0.0055, 0.0001));
        assert!(close(ANGLE_LSB_RAD.to_degrees(), ANGLE_LSB_DEG, 1e-9));
    }

    #[test]
    fn temperature_converts() {
        // 25 °C ≈ 298 · 18.9 = 5632.2 counts.
        assert!(close(temperature_celsius(5632), 25.0, 0.1));
        assert!(close(temperature_celsius(0), -273.0, 1e-3));
    }
}
