//! The flange's mechanical interface (ISO 9409-1 designation, locating dowel) and what
//! each bracket registers on: what a flange bracket is drilled to (`zerocal bracket`,
//! `cad/flange_bracket.scad`) and what the operator seats it against
//! (`docs/mounting.md`).
//!
//! ISO 9409-1 names a flange `ISO 9409-1-<d1>-<n>-M<t>`: the pitch circle diameter d1
//! (mm) of its `n` threaded holes of thread M<t>; some makers write `A<d1>` for form A.
//! The parser takes that text and refuses anything else with the key named.

use crate::bounds;
use crate::ProfileError;

/// The key a designation is read from, named in every refusal.
pub const ISO9409_KEY: &str = "flange.iso9409";

/// The key of the dowel hole's diameter.
pub const DOWEL_KEY: &str = "flange.dowel_hole_mm";

/// Pitch circle diameters within these (mm): plausibility bounds, not the standard's
/// series. Below 10 mm no M3 screw fits four to a circle; above 1000 mm is a figure in
/// the wrong unit.
pub const PITCH_CIRCLE_MM: (f64, f64) = (10.0, 1000.0);

/// Threaded holes per flange: at least three (fewer cannot clamp a plate flat), at most
/// 32 (a plausibility bound).
pub const HOLES: (u32, u32) = (3, 32);

/// Metric thread nominal diameters within these (mm): M2 to M48, plausibility bounds.
pub const THREAD_MM: (f64, f64) = (2.0, 48.0);

/// Dowel (locating pin) hole diameters within these (mm): plausibility bounds.
pub const DOWEL_MM: (f64, f64) = (1.0, 50.0);

/// An ISO 9409-1 flange designation, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Iso9409 {
    /// The pitch circle diameter of the threaded holes (mm).
    pub pitch_circle_mm: f64,
    /// How many threaded holes on it.
    pub holes: u32,
    /// The metric thread's nominal diameter (mm): 6 for M6.
    pub thread_mm: f64,
}

impl Iso9409 {
    /// The designation as ISO 9409-1 writes it (`ISO 9409-1-50-4-M6`).
    pub fn designation(&self) -> String {
        format!(
            "ISO 9409-1-{}-{}-M{}",
            self.pitch_circle_mm, self.holes, self.thread_mm
        )
    }
}

/// The flange's mechanical interface as a profile gives it.
#[derive(Clone, Debug, PartialEq)]
pub struct FlangeInterface {
    /// The bolt circle.
    pub iso9409: Iso9409,
    /// The locating dowel's hole diameter (mm), where a source gives it.
    pub dowel_hole_mm: Option<f64>,
    /// The id of the `[[source]]` that gives them.
    pub source: String,
}

/// Reads `ISO 9409-1-50-4-M6` (also `ISO 9409-1-A50-4-M6`, `DIN ISO 9409-1-...`).
///
/// # Errors
/// Text that is not such a designation, or a number outside [`PITCH_CIRCLE_MM`],
/// [`HOLES`], [`THREAD_MM`], or holes that would overlap on their circle: each a
/// [`ProfileError`] naming [`ISO9409_KEY`] and what is wrong.
pub fn parse_iso9409(text: &str) -> Result<Iso9409, ProfileError> {
    let bad = |why: String| ProfileError::new(ISO9409_KEY, why);
    let form =
        "the form is 'ISO 9409-1-<pitch circle mm>-<holes>-M<thread>', e.g. 'ISO 9409-1-50-4-M6'";
    let trimmed = text.trim();
    let rest = trimmed
        .strip_prefix("DIN ")
        .unwrap_or(trimmed)
        .strip_prefix("ISO 9409-1-")
        .ok_or_else(|| {
            bad(format!(
                "'{trimmed}' does not start with 'ISO 9409-1-': {form}"
            ))
        })?;
    let parts: Vec<&str> = rest.split('-').collect();
    let [pcd, holes, thread] = parts.as_slice() else {
        return Err(bad(format!(
            "'{trimmed}' has {} fields after 'ISO 9409-1-', not 3: {form}",
            parts.len()
        )));
    };
    let pcd_text = pcd.strip_prefix('A').unwrap_or(pcd);
    let number = |s: &str, what: &str| {
        // Digits and one decimal point only: no signs, exponents, `inf` or `NaN`.
        let plain = !s.is_empty()
            && s.chars().all(|c| c.is_ascii_digit() || c == '.')
            && s.chars().filter(|c| *c == '.').count() <= 1;
        plain
            .then(|| s.parse::<f64>().ok())
            .flatten()
            .ok_or_else(|| {
                bad(format!(
                    "{what} '{s}' in '{trimmed}' is not a number: {form}"
                ))
            })
    };
    let pitch_circle_mm = number(pcd_text, "the pitch circle diameter")?;
    let holes_text = *holes;
    let holes: u32 = holes_text
        .parse()
        .ok()
        .filter(|_| holes_text.chars().all(|c| c.is_ascii_digit()))
        .ok_or_else(|| {
            bad(format!(
                "the hole count '{holes_text}' in '{trimmed}' is not a whole number: {form}"
            ))
        })?;
    let thread_text = thread.strip_prefix('M').ok_or_else(|| {
        bad(format!(
            "the thread '{thread}' in '{trimmed}' is not M<diameter>: {form}"
        ))
    })?;
    let thread_mm = number(thread_text, "the thread diameter")?;
    let (lo, hi) = PITCH_CIRCLE_MM;
    bounds::number(ISO9409_KEY, pitch_circle_mm, lo, hi, "mm pitch circle")?;
    let (lo, hi) = HOLES;
    if !(lo..=hi).contains(&holes) {
        return Err(bad(format!(
            "{holes} holes is outside the plausible range [{lo}, {hi}]"
        )));
    }
    let (lo, hi) = THREAD_MM;
    bounds::number(ISO9409_KEY, thread_mm, lo, hi, "mm thread")?;
    // Neighbouring holes on the circle are a chord 2r·sin(π/n) apart: the threads must
    // not meet.
    let chord_mm = pitch_circle_mm * (std::f64::consts::PI / f64::from(holes)).sin();
    if thread_mm >= chord_mm {
        return Err(bad(format!(
            "{holes} M{thread_mm} holes on a {pitch_circle_mm} mm circle are {chord_mm:.2} mm apart: they would overlap"
        )));
    }
    Ok(Iso9409 {
        pitch_circle_mm,
        holes,
        thread_mm,
    })
}

/// Checks a dowel hole against the bolt circle it sits on.
///
/// # Errors
/// A diameter outside [`DOWEL_MM`] or not smaller than the pitch circle's radius.
pub fn check_dowel(dowel_hole_mm: f64, iso: &Iso9409) -> Result<(), ProfileError> {
    let (lo, hi) = DOWEL_MM;
    bounds::number(DOWEL_KEY, dowel_hole_mm, lo, hi, "mm")?;
    if dowel_hole_mm >= iso.pitch_circle_mm / 2.0 {
        return Err(ProfileError::new(
            DOWEL_KEY,
            format!(
                "a {dowel_hole_mm} mm dowel hole does not fit inside a {} mm bolt circle",
                iso.pitch_circle_mm
            ),
        ));
    }
    Ok(())
}
