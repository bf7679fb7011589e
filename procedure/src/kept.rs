//! The results the pendant keeps: the last [`KEPT_RESULTS`] completed sessions, each
//! under an ID no other result of the same pendant ever had, with what the desktop
//! needs to file it (the robot, the numbers, the verdict, the temperatures, the
//! brackets and the pendant unit that made it).
//!
//! A technician may master several robots before exporting; a new session or a power
//! cut must not lose an earlier result. The pendant keeps them in flash, one record a
//! result (`machine::record::kept_slot`), read back one at a time; `log::kept_lines` writes and reads
//! their lines for the desktop; `machine::kept_result` makes one from a finished session.
//!
//! Numbers are kept as the pendant showed them, `f32` degrees: the lines carry
//! decimals that read back to the same `f32`, so the desktop files exactly what the
//! pendant holds. The pendant computes no uncertainty budget (the expanded
//! U(k=2) is the desktop's, from the profile's error budget): a kept result has the
//! fit's 1σ only.

use core::fmt;

use crate::text::RobotName;
use zerocal_core::bracket::BracketId;
use zerocal_core::report::{Verdict, Warning};
use zerocal_core::session::SESSION_JOINTS;

/// How many completed results the pendant keeps; the oldest goes first when full.
pub const KEPT_RESULTS: usize = 8;

/// Bytes of the pendant unit's ID: the STM32F411's 96-bit unique device ID.
pub const UNIT_ID_BYTES: usize = 12;

/// The pendant unit's ID, as the board reads it (on the STM32F411 its unique device
/// ID, 96 bits at 0x1FFF7A10, RM0383 "Unique device ID register"). Written as 24
/// lowercase hex digits, byte 0 first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct UnitId(pub [u8; UNIT_ID_BYTES]);

impl UnitId {
    /// Hex digits of [`fmt::Display`].
    pub const HEX_LEN: usize = 2 * UNIT_ID_BYTES;

    /// Reads the 24 hex digits [`fmt::Display`] writes (either case).
    pub fn parse(hex: &str) -> Option<Self> {
        if hex.len() != Self::HEX_LEN || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
            return None;
        }
        let mut bytes = [0_u8; UNIT_ID_BYTES];
        for (i, b) in bytes.iter_mut().enumerate() {
            *b = u8::from_str_radix(hex.get(2 * i..2 * i + 2)?, 16).ok()?;
        }
        Some(UnitId(bytes))
    }
}

impl fmt::Display for UnitId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for b in self.0 {
            write!(f, "{b:02x}")?;
        }
        Ok(())
    }
}

/// The pendant that runs the procedure: its unit ID and its firmware's version, as
/// the board hands them to the application (none on the desktop's own solvers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PendantUnit {
    /// The chip's unique ID.
    pub id: UnitId,
    /// The firmware's version (one word).
    pub firmware: &'static str,
}

/// The verdict's warnings, by name, in the order of their bit in a kept result.
pub const VERDICT_WORDS: [&str; 3] = [
    "residual_high",
    "bias_x_unknown",
    "sigma_from_sensor_figure",
];

/// The verdict of a pass (no warning).
pub const VERDICT_PASS: &str = "pass";

/// The bit of `w` in [`KeptResult::warnings`] (its place in [`VERDICT_WORDS`]).
pub fn warning_bit(w: &Warning) -> u8 {
    match w {
        Warning::ResidualHigh { .. } => 1 << 0,
        Warning::BiasXUnknown => 1 << 1,
        Warning::SigmaFromSensorFigure => 1 << 2,
    }
}

/// Every bit [`VERDICT_WORDS`] names.
pub const VERDICT_BITS: u8 = (1 << VERDICT_WORDS.len()) - 1;

/// Which sensor temperature of a session a kept result holds, by its place in
/// [`KeptResult::temperatures_c`].
pub const TEMPERATURE_STAGES: [&str; 3] = ["stage0", "stage1", "closing"];

/// A completed result as the pendant keeps it.
#[derive(Clone, Debug, PartialEq)]
pub struct KeptResult {
    /// Its ID on this pendant: 1 for the first result the pendant ever kept, then
    /// counting up, never reused (the count survives an erase of the store).
    pub id: u32,
    /// The robot profile's name.
    pub robot: RobotName,
    /// Δθ2..Δθ6 (deg).
    pub offsets_deg: [f32; SESSION_JOINTS],
    /// Their 1σ (deg), from the session's covariance.
    pub sigma_deg: [f32; SESSION_JOINTS],
    /// The fit's residual RMS (deg).
    pub residual_rms_deg: f32,
    /// The verdict's warnings, a bit each ([`VERDICT_WORDS`]); 0 is a pass.
    pub warnings: u8,
    /// The sensor's temperature (°C) during stage 0's bench readings, stage 1's half
    /// turn and the closing bench readings ([`TEMPERATURE_STAGES`]), where recorded.
    pub temperatures_c: [Option<f32>; 3],
    /// The brackets' IDs, the upper arm's then the flange's, where the session applied a
    /// calibration ([`zerocal_core::bracket::BracketMount::ALL`]).
    pub brackets: [Option<BracketId>; 2],
    /// The pendant unit that made it, where known.
    pub unit: Option<UnitId>,
}

/// A verdict's warnings as [`KeptResult::warnings`] holds them.
pub fn verdict_bits(v: &Verdict) -> u8 {
    v.warnings.iter().fold(0, |bits, w| bits | warning_bit(w))
}

/// A kept result of every kind of field, for tests.
#[cfg(test)]
pub(crate) fn example_kept_result(id: u32) -> KeptResult {
    let mut robot = RobotName::new();
    let _ = robot.push_str("kuka-kr6-r900-sixx");
    let bracket = zerocal_core::bracket::bracket_id("UA-0042").ok();
    KeptResult {
        id,
        robot,
        offsets_deg: [-0.123_456_7, 0.5, -1.25e-3, 3.0, 1.0e-7],
        sigma_deg: [0.001_234_5, 0.002, 0.003, 0.004, 0.005],
        residual_rms_deg: 0.000_812,
        warnings: 0b010,
        temperatures_c: [Some(21.53), None, Some(22.07)],
        brackets: [bracket, None],
        unit: Some(UnitId([
            0x36, 0, 0x2f, 0, 0x13, 0x47, 0x33, 0x31, 0x30, 0x37, 0x35, 0x39,
        ])),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_unit_id_reads_back_from_its_hex_and_junk_does_not() {
        let id = UnitId([0x00, 0x1f, 0xa0, 0xff, 1, 2, 3, 4, 5, 6, 7, 0x80]);
        let hex = std::format!("{id}");
        assert_eq!(hex, "001fa0ff0102030405060780");
        assert_eq!(UnitId::parse(&hex), Some(id));
        assert_eq!(UnitId::parse(&hex.to_uppercase()), Some(id));
        for bad in [
            "",
            "001fa0ff01020304050607",
            "001fa0ff01020304050607801",
            "001fa0ff0102030405060g80",
            "+01fa0ff0102030405060780",
        ] {
            assert_eq!(UnitId::parse(bad), None, "{bad}");
        }
    }

    #[test]
    fn each_warning_has_its_own_bit_and_word() {
        let all = [
            Warning::ResidualHigh {
                residual_rms_deg: 1.0,
                sensor_noise_deg: 0.1,
            },
            Warning::BiasXUnknown,
            Warning::SigmaFromSensorFigure,
        ];
        let bits: u8 = all.iter().fold(0, |b, w| {
            assert_eq!(b & warning_bit(w), 0);
            b | warning_bit(w)
        });
        assert_eq!(bits, VERDICT_BITS);
    }
}
