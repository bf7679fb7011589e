//! The files the pendant writes and the desktop reads, written and parsed here, once,
//! so the firmware and the CLI cannot drift apart.
//!
//! **The stage-2 log** (`zerocal identify` reads it): `#` comment lines, a header
//! naming the columns (any order, extra columns ignored), then one pose a row, the
//! commanded joints and the raw readings in degrees:
//!
//! ```text
//! # comment lines start with '#'
//! j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg
//! 12.5,-40.0,3.25,90.0,1.234567,-0.456789
//! ```
//!
//! **The pendant's export** is such a log with the session in `#` metadata lines,
//! `# key value…`, before the header: `robot NAME convention rpy|axis`,
//! `stage0_bias_deg x,y` or `stage0_bench_deg x,y x,y x,y x,y temp_c t` (stage 0's
//! readings at each heading, [`write_bench`]), `stage1_readings_deg before x,y after x,y
//! j1_deg a j2_deg c`, `stage1_temp_c t`, stage 1's results, `closing_bench_deg x,y …
//! temp_c t` (the bench readings after stage 2 that measure the bias' drift), `pendant
//! unit HEX firmware VERSION` (the pendant unit that wrote it), and after the rows the
//! result line. The older two-reading lines (`stage0_reversal_deg first x,y second x,y
//! temp_c t`, `closing_reversal_deg …`) are still read.
//! A check's export (`mode check`) has a `mode check` line instead of stage 1's lines
//! and no result line, its rows' `pose` the plan's pose index. `zerocal session` reads all of it. [`Export`] writes it a line at a time; [`LogReader`] reads both, and
//! [`MetaItem`] the metadata the session solver needs.
//!
//! The export is read strictly, because a line it ignores can make a session silently
//! wrong ([`LogReader::for_export`], [`MetaKeys`]): its header [`EXPORT_HEADER`] adds the
//! `approach` column (`below` or `above`: the side every joint arrived from) and the
//! `pose` column (the pose's index in the plan; a pose has one capture a side) and no
//! other column may appear; a comment whose first word has the form of a key (lowercase
//! letters, digits and `_`, with at least one digit or `_`, see [`metadata_key`]) is a
//! metadata line, and must be a key of [`METADATA_KEYS`], given once; any other comment
//! (the export's first line, [`CLOSING_NOT_MADE`], a user's note) is free text.
//!
//! Numbers are written with [`EXPORT_DECIMALS`] decimals of a degree: below the
//! resolution of any `f32` the pendant holds, so the desktop reads back its numbers.
//!
//! The parts: `write.rs` the
//! export's writer and a log row's; `read.rs` the reader of both, a line at a time;
//! `meta.rs` the metadata lines' keys and grammar; `error.rs` what a reader refuses.
//! This file holds what they share: the columns, the headers and the bounds.

mod error;
mod kept_lines;
mod meta;
mod read;
mod write;

pub use crate::text::{Line, LINE_BYTES, MAX_JOINT_DEG};
pub use error::{LogError, ShortText};
#[cfg(any(test, feature = "std"))]
pub use kept_lines::read_kept_results;
pub use kept_lines::{write_kept_result, KeptResultReader, KEPT_RESULT_KEY, KEPT_RESULT_LINES};
pub use meta::{
    bracket_key, metadata_key, parse_bracket_fields, parse_meta, write_bench, write_bracket,
    write_bracket_fields, write_fit_extras, write_pendant, ExportMode, MetaItem, MetaKeys,
    CLOSING_BENCH_KEY, STAGE0_BENCH_KEY,
};
pub use read::{strip_bom, text_of, LogLine, LogReader};
pub(crate) use write::result_line;
pub use write::{
    export, write_export_row, write_row, CaptureRows, Export, ExportSession, CLOSING_NOT_MADE,
    EXPORT_MAX_LINES,
};

use core::fmt::{self, Write};
use zerocal_core::capture::Approach;
use zerocal_core::decimal::Fixed;
use zerocal_core::model::Tilt;
use zerocal_core::real::{rad_to_deg, Real};

/// The columns a stage-2 log has, in the order the pendant writes them. The first six
/// are required; `j1_deg` and `j2_deg` default to 0 (joints 1 and 2 where stage 1 had
/// them, for a log of the paper's wrist), `temp_c` to unrecorded, `approach` (the
/// export's: `below` or `above`) and `pose` (the export's: the pose's index in the plan)
/// to unrecorded.
pub const LOG_COLUMNS: [&str; 11] = [
    "j3_deg", "j4_deg", "j5_deg", "j6_deg", "x_deg", "y_deg", "j1_deg", "j2_deg", "temp_c",
    "approach", "pose",
];

/// Index of `temp_c` in [`LOG_COLUMNS`].
const TEMPERATURE_COLUMN: usize = 8;

/// Index of `approach` in [`LOG_COLUMNS`].
const APPROACH_COLUMN: usize = 9;

/// Index of `pose` in [`LOG_COLUMNS`].
const POSE_COLUMN: usize = 10;

/// How many of [`LOG_COLUMNS`] a log must have.
const REQUIRED_COLUMNS: usize = 6;

/// The header of a stage-2 log.
pub const LOG_HEADER: &str = "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg,temp_c";

/// The header of the pendant's export: a stage-2 log's, the side each capture was
/// approached from (`below` or `above`), so the desktop can tell a pose captured from
/// one side only, and the pose's index in the plan, so the desktop pairs a pose's two
/// captures by it (not by its joints, which a hand edit or a rounding may set apart).
pub const EXPORT_HEADER: &str =
    "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg,temp_c,approach,pose";

/// The `approach` column's word for each side.
pub fn approach_name(a: Approach) -> &'static str {
    a.word()
}

/// Temperatures a log may hold (°C): the SCL3300's operating range is −40..+125 °C.
pub const TEMPERATURE_RANGE_C: (f64, f64) = (-60.0, 150.0);

/// Largest reading a log may hold (deg): an inclinometer reads ±180° at most.
pub const MAX_READING_DEG: f64 = 180.0;

/// Most columns a log row may have (extra ones are ignored, but counted).
pub const MAX_COLUMNS: usize = 32;

/// Decimals of a temperature (°C) in the log and the export: 0.01 K, a fifth of the
/// sensor's 0.053 K register step (its 40-sample mean is finer). The pendant keeps each
/// capture's temperature at this resolution ([`quantise_temperature`]), so the desktop
/// solves from the very temperatures the pendant used: the bias' drift is interpolated
/// between the two bench steps' temperatures, and with the pendant's own unrounded a
/// session's result moved by up to 6e-6° and its 1σ by 0.2 % between the two, a digit
/// apart on the screen.
pub const TEMPERATURE_DECIMALS: u8 = 2;

/// A capture's temperature at the export's resolution ([`TEMPERATURE_DECIMALS`]): what
/// the pendant keeps, solves with and writes.
pub fn quantise_temperature<T: Real>(celsius: T) -> T {
    let scale = libm::pow(10.0, f64::from(TEMPERATURE_DECIMALS));
    T::lit(libm::round(celsius.to_f64() * scale) / scale)
}

/// Decimals of a degree in the export: 1e-12° is 2e-14 rad, below the resolution of
/// any `f32` the pendant holds (1.5e-8 rad at 0.17 rad), so the desktop reads back the
/// pendant's numbers, and an `f64` session's offsets move by ~1e-12° at most.
pub const EXPORT_DECIMALS: u8 = 12;

/// Every metadata key an export may hold (the first word of a `# key value…` line).
pub const METADATA_KEYS: [&str; 16] = [
    "robot",
    "stage0_bias_deg",
    "stage0_bench_deg",
    "stage0_reversal_deg",
    "stage1_readings_deg",
    "stage1_temp_c",
    "stage1_captures_deg",
    "stage1",
    "closing_bench_deg",
    "closing_reversal_deg",
    "fit_extras",
    "stage2",
    "bracket_upper_arm",
    "bracket_flange",
    "pendant",
    "mode",
];

/// [`METADATA_KEYS`], comma-separated, for messages.
struct KnownKeys;

impl fmt::Display for KnownKeys {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, k) in METADATA_KEYS.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            f.write_str(k)?;
        }
        Ok(())
    }
}

/// Writes `rad` in degrees with [`EXPORT_DECIMALS`] decimals: the one number format
/// of the export's rows and metadata.
fn deg<T: Real>(w: &mut Line, rad: T) -> fmt::Result {
    // In f64, whatever T is: the f32 value converts exactly.
    write!(
        w,
        "{}",
        Fixed::new(rad_to_deg(rad.to_f64()), EXPORT_DECIMALS)
    )
}

/// Writes `x,y` in degrees.
fn pair<T: Real>(w: &mut Line, t: &Tilt<T>) -> fmt::Result {
    deg(w, t.x_rad)?;
    w.write_char(',')?;
    deg(w, t.y_rad)
}

/// The pendant's own result, as its export's result line records it: Δθ2..Δθ6 and their
/// 1σ (deg), the numbers its result screen showed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PendantResult {
    /// Δθ2..Δθ6 (deg).
    pub offsets_deg: [f64; zerocal_core::session::SESSION_JOINTS],
    /// Their 1σ (deg).
    pub sigma_deg: [f64; zerocal_core::session::SESSION_JOINTS],
}

/// The pendant's result from an export's text: Δθ2 and its 1σ from the line `# stage1
/// delta_theta2_deg x alpha_deg a beta_deg b bias_y_deg y j2_sigma_deg s`, Δθ3..Δθ6 and
/// theirs from `# stage2 offsets_deg a,b,c,d sigma_deg a,b,c,d residual_rms_deg r`;
/// `None` when the export has no result (a refused or unfinished session, an older
/// export) or a line does not read.
pub fn read_pendant_result(text: &str) -> Option<PendantResult> {
    let words = |prefix: &str| -> Option<heapless::Vec<&str, 12>> {
        let line = text.lines().find(|l| l.starts_with(prefix))?;
        Some(line.split_whitespace().take(12).collect())
    };
    let number = |word: &str| word.parse::<f64>().ok().filter(|x| x.is_finite());
    let four = |list: &str| -> Option<[f64; 4]> {
        let mut out = [0.0; 4];
        let mut parts = list.split(',');
        for v in &mut out {
            *v = number(parts.next()?)?;
        }
        parts.next().is_none().then_some(out)
    };
    let stage1 = words("# stage1 delta_theta2_deg ")?;
    let [_, _, _, j2, "alpha_deg", _, "beta_deg", _, "bias_y_deg", _, "j2_sigma_deg", j2_sigma] =
        stage1.as_slice()
    else {
        return None;
    };
    let stage2 = words("# stage2 offsets_deg ")?;
    let [_, _, _, offsets, "sigma_deg", sigma, "residual_rms_deg", _] = stage2.as_slice() else {
        return None;
    };
    let (o, s) = (four(offsets)?, four(sigma)?);
    Some(PendantResult {
        offsets_deg: [number(j2)?, o[0], o[1], o[2], o[3]],
        sigma_deg: [number(j2_sigma)?, s[0], s[1], s[2], s[3]],
    })
}

#[cfg(test)]
mod pendant_result_tests {
    use super::*;

    #[test]
    fn the_result_line_reads_back_and_junk_does_not() {
        let stage1 = "# stage1 delta_theta2_deg -7 alpha_deg 0.1 beta_deg 0.2 bias_y_deg 0.3 j2_sigma_deg 0.7";
        let stage2 = "# stage2 offsets_deg 1,2,3,4 sigma_deg 0.1,0.2,0.3,0.4 residual_rms_deg 0.5";
        let text = format!("# x\n{stage1}\n{stage2}\n");
        let r = read_pendant_result(&text).unwrap();
        assert_eq!(r.offsets_deg, [-7.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(r.sigma_deg, [0.7, 0.1, 0.2, 0.3, 0.4]);
        // No Δθ2 σ (an export of a refused session), a NaN, a fifth value: no result.
        for bad in [
            format!("# stage1 delta_theta2_deg -7 alpha_deg 0.1 beta_deg 0.2 bias_y_deg 0.3\n{stage2}"),
            format!("{stage1}\n# stage2 offsets_deg 1,2,NaN,4 sigma_deg 0.1,0.2,0.3,0.4 residual_rms_deg 0.5"),
            format!("{stage1}\n# stage2 offsets_deg 1,2,3,4,5 sigma_deg 0.1,0.2,0.3,0.4 residual_rms_deg 0.5"),
        ] {
            assert_eq!(read_pendant_result(&bad), None, "{bad}");
        }
    }
}
