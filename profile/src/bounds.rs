//! The stated range of every number and the longest of every text a profile holds.
//!
//! These are plausibility bounds, not facts about any robot: a value outside one is a
//! unit or typing mistake (millimetres for metres, grams for kilograms, a radian
//! figure in degrees) or a hostile file, and is refused at load naming the key, before
//! it can reach a planner, a simulator or a report as an absurd or non-finite number.

use crate::ProfileError;

/// Largest profile file (bytes): a profile is six joints, their sources and notes; the
/// largest built-in is under 7 KB (`every_builtin_fits_the_bounds`); 64 KiB leaves
/// room for longer notes and citations.
pub const MAX_PROFILE_BYTES: usize = 64 << 10;

/// Longest `name` (bytes): what the pendant stores of it (core's
/// `procedure::RobotName`, 32 bytes), so a profile that loads can be sent to it.
pub const MAX_NAME_BYTES: usize = 32;

/// Longest `title` (characters): one line of a report.
pub const MAX_TITLE_CHARS: usize = 120;

/// Longest joint name (characters): a controller's axis name (`A1`, `J1`, `S`) with
/// room to spare; it heads a column of every table.
pub const MAX_JOINT_NAME_CHARS: usize = 16;

/// Longest free text (characters): a citation, a `missing` entry, `offset_where`, a
/// source id; the longest built-in is under 400.
pub const MAX_TEXT_CHARS: usize = 1000;

/// Most `[[source]]` tables and most `missing` entries each: the built-ins have at
/// most ten.
pub const MAX_LIST_ITEMS: usize = 64;

/// Joint limits, zeros and stage-1 angles within ± this (deg): two turns either way,
/// as core's log takes joint commands (`zerocal_procedure::log::MAX_JOINT_DEG`).
pub const MAX_JOINT_DEG: f64 = zerocal_procedure::log::MAX_JOINT_DEG;

/// Joint speeds (deg/s): below 0.1 a joint barely moves in a session; above 10,000 a
/// radian-per-second figure was probably taken for degrees twice over.
pub const SPEED_DEG_S: (f64, f64) = (0.1, 10_000.0);

/// Link masses (kg): above 10 t a gram figure was probably taken for kilograms; the
/// pendant's profile line takes no more.
pub const MAX_MASS_KG: f64 = zerocal_procedure::profile::MAX_MASS_KG;

/// Lengths and positions (m): a link origin, DH `a`/`d`, a flange offset or a centre of
/// mass beyond 10 m is a millimetre figure taken for metres.
pub const MAX_LENGTH_M: f64 = 10.0;

/// Rotations (deg): roll-pitch-yaw angles and DH `alpha`/`theta` within one turn.
pub const MAX_ROTATION_DEG: f64 = 360.0;

/// Gear ratios (motor turns per joint turn): at most 10,000, so a 720° offset is at
/// most 1.3e5 motor radians in a report.
pub const GEAR_RATIO: (f64, f64) = (1e-3, 1e4);

/// Encoder counts per joint degree: at most 1e9, so a 720° offset is at most 7.2e11
/// counts, a 12-digit figure in a report.
pub const COUNTS_PER_DEG: (f64, f64) = (1e-3, 1e9);

/// `v` finite and within `[lo, hi]`, else an error naming `key`, the value and range.
pub(crate) fn number(key: &str, v: f64, lo: f64, hi: f64, unit: &str) -> Result<(), ProfileError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(ProfileError::new(
            key,
            format!(
                "{} is outside the plausible range [{lo}, {hi}] {unit}",
                short(v)
            ),
        ))
    }
}

/// A number as a message shows it: plain between 1e-4 and 1e6, else in exponent form
/// (`1e308`, not 309 digits).
pub(crate) fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-4..1e6).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Every entry of `v` by [`number`].
pub(crate) fn numbers(
    key: &str,
    v: &[f64],
    lo: f64,
    hi: f64,
    unit: &str,
) -> Result<(), ProfileError> {
    v.iter().try_for_each(|x| number(key, *x, lo, hi, unit))
}

/// `v` within ± `max`.
pub(crate) fn symmetric(key: &str, v: &[f64], max: f64, unit: &str) -> Result<(), ProfileError> {
    numbers(key, v, -max, max, unit)
}

/// `text` at most `max` characters; a longer one is not shown back in the message.
pub(crate) fn text(key: &str, text: &str, max: usize) -> Result<(), ProfileError> {
    // Counting stops past the limit: a megabyte of text costs no more than `max` steps.
    if text.chars().nth(max).is_some() {
        Err(ProfileError::new(
            key,
            format!("longer than {max} characters"),
        ))
    } else {
        Ok(())
    }
}

/// At most [`MAX_LIST_ITEMS`] entries.
pub(crate) fn list(key: &str, len: usize) -> Result<(), ProfileError> {
    if len > MAX_LIST_ITEMS {
        Err(ProfileError::new(
            key,
            format!("{len} entries; a profile has at most {MAX_LIST_ITEMS}"),
        ))
    } else {
        Ok(())
    }
}
