//! The kept results' lines ([`KeptResult`]): the pendant's link writes them, the
//! desktop reads them back, both through this file.
//!
//! A result takes [`KEPT_RESULT_LINES`] lines, in this order, each starting with its ID:
//!
//! ```text
//! # kept_result id 7 robot kuka-kr6-r900-sixx unit 36002f001347333130373539 brackets UA-0042,none
//! # kept_result id 7 verdict bias_x_unknown temps_c 21.530000686645508,none,22.06999969482422
//! # kept_result id 7 offsets_deg -0.123456701636314,0.5,-0.00124999997206,3,0.000000100000001
//! # kept_result id 7 sigma_deg 0.001234499970451,0.002000000094995,0.003000000026077,0.00400000018999,0.004999999888241 residual_rms_deg 0.000812000012957
//! ```
//!
//! (the unit is one word of 24 hex digits, `none` where unknown). Offsets are Δθ2..Δθ6;
//! the verdict is `pass` or its warnings ([`VERDICT_WORDS`]) joined by `,`; the
//! temperatures are stage 0's, stage 1's and the closing reversal's
//! ([`TEMPERATURE_STAGES`](crate::kept::TEMPERATURE_STAGES)); the brackets the upper arm's then the flange's. Numbers have
//! [`KEPT_DECIMALS`] decimals (trailing zeros dropped), which read back to the
//! pendant's `f32`s bit for bit, so the desktop gets exactly what the pendant holds.
//! One line would pass the link's [`Line`] length.

use core::fmt::{self, Write};

use super::{Line, LogError, MAX_READING_DEG, TEMPERATURE_RANGE_C};
use crate::kept::{KeptResult, UnitId, VERDICT_BITS, VERDICT_PASS, VERDICT_WORDS};
use crate::text::RobotName;
use zerocal_core::bracket::bracket_id;
use zerocal_core::decimal::Fixed;
use zerocal_core::session::SESSION_JOINTS;

/// The first word of a kept result's lines (after `#`).
pub const KEPT_RESULT_KEY: &str = "kept_result";

/// Lines a kept result takes.
pub const KEPT_RESULT_LINES: usize = 4;

/// The word after the ID on each of a result's lines, in their order.
const PARTS: [&str; KEPT_RESULT_LINES] = ["robot", "verdict", "offsets_deg", "sigma_deg"];

/// The word for an absent value (a temperature, a bracket, the unit).
const NONE: &str = "none";

/// Decimals of a kept result's numbers: 1e-15 is below half an `f32`'s step for every
/// magnitude down to 1e-8 (an `f32` carries 24 bits: a relative step of 6e-8), so the
/// reader's nearest `f32` is the pendant's own, bit for bit; smaller numbers (no angle
/// or 1σ the pendant computes) come back within 1e-15.
pub const KEPT_DECIMALS: u8 = 15;

/// Largest magnitude a kept result's number may have: the reader takes angles within
/// ±180° and temperatures within the log's range; beyond, the writer refuses.
const MAX_KEPT_NUMBER: f64 = 1.0e4;

/// Writes `v` with [`KEPT_DECIMALS`] decimals, trailing zeros dropped (`0.5`, `3`):
/// core's integer writer, not `{}` on a float, whose formatting machinery would take
/// ~20 KiB of the firmware's flash.
fn number_text(w: &mut Line, v: f32) -> fmt::Result {
    let v = f64::from(v);
    if !v.is_finite() || v.abs() >= MAX_KEPT_NUMBER {
        return Err(fmt::Error);
    }
    let mut text = heapless::String::<32>::new();
    write!(text, "{}", Fixed::new(v, KEPT_DECIMALS))?;
    let digits = text.trim_end_matches('0').trim_end_matches('.');
    w.write_str(digits)
}

fn list(w: &mut Line, values: &[f32]) -> fmt::Result {
    for (i, v) in values.iter().enumerate() {
        if i > 0 {
            w.write_char(',')?;
        }
        number_text(w, *v)?;
    }
    Ok(())
}

/// Writes line `part` (0..[`KEPT_RESULT_LINES`]) of `k`, without a line end.
///
/// # Errors
/// A line too long for [`Line`] (numbers far outside their ranges), or `part` past
/// the last.
pub fn write_kept_result(w: &mut Line, k: &KeptResult, part: usize) -> fmt::Result {
    let word = PARTS.get(part).ok_or(fmt::Error)?;
    write!(w, "# {KEPT_RESULT_KEY} id {} {word} ", k.id)?;
    match part {
        0 => {
            write!(w, "{} unit ", k.robot)?;
            match k.unit {
                Some(u) => write!(w, "{u}")?,
                None => w.write_str(NONE)?,
            }
            w.write_str(" brackets ")?;
            for (i, b) in k.brackets.iter().enumerate() {
                if i > 0 {
                    w.write_char(',')?;
                }
                w.write_str(b.as_ref().map_or(NONE, |b| b.as_str()))?;
            }
        }
        1 => {
            if k.warnings == 0 {
                w.write_str(VERDICT_PASS)?;
            }
            let mut first = true;
            for (bit, name) in VERDICT_WORDS.iter().enumerate() {
                if k.warnings & (1 << bit) != 0 {
                    if !first {
                        w.write_char(',')?;
                    }
                    w.write_str(name)?;
                    first = false;
                }
            }
            w.write_str(" temps_c ")?;
            for (i, t) in k.temperatures_c.iter().enumerate() {
                if i > 0 {
                    w.write_char(',')?;
                }
                match t {
                    Some(c) => number_text(w, *c)?,
                    None => w.write_str(NONE)?,
                }
            }
        }
        2 => list(w, &k.offsets_deg)?,
        _ => {
            list(w, &k.sigma_deg)?;
            w.write_str(" residual_rms_deg ")?;
            list(w, &[k.residual_rms_deg])?;
        }
    }
    Ok(())
}

/// Reads kept results a line at a time: [`Self::feed`] each line, then
/// [`Self::finish`].
#[derive(Clone, Debug, Default)]
pub struct KeptResultReader {
    /// The result being read, its lines so far, and its first line's number.
    partial: Option<(KeptResult, usize, usize)>,
}

/// A finite `f32` within `range`.
fn number(word: &str, range: (f64, f64)) -> Option<f32> {
    let v = word.parse::<f32>().ok()?;
    (v.is_finite() && (range.0..=range.1).contains(&f64::from(v))).then_some(v)
}

/// Five numbers within `range`, `,`-separated.
fn five(word: Option<&str>, range: (f64, f64)) -> Option<[f32; SESSION_JOINTS]> {
    let mut out = [0.0; SESSION_JOINTS];
    let mut parts = word?.split(',');
    for v in &mut out {
        *v = number(parts.next()?, range)?;
    }
    parts.next().is_none().then_some(out)
}

impl KeptResultReader {
    /// Reads `line` (its number `line_no`, 1-based). `Ok(None)`: not a kept result's
    /// line, or not its last; `Ok(Some)`: a whole result.
    ///
    /// # Errors
    /// [`LogError::BadMetadata`] naming the line: a kept result's line that does not
    /// parse, or comes out of its order (another result's before this one's last).
    pub fn feed(&mut self, line: &str, line_no: usize) -> Result<Option<KeptResult>, LogError> {
        let bad = LogError::BadMetadata {
            line: line_no,
            key: KEPT_RESULT_KEY,
        };
        let Some(comment) = line.trim_end().strip_prefix('#') else {
            return Ok(None);
        };
        let mut words = comment.split_whitespace();
        if words.next() != Some(KEPT_RESULT_KEY) {
            return Ok(None);
        }
        if words.next() != Some("id") {
            return Err(bad);
        }
        let id = words
            .next()
            .and_then(|w| w.parse::<u32>().ok())
            .filter(|id| *id > 0)
            .ok_or(bad)?;
        let word = words.next().ok_or(bad)?;
        let part = PARTS.iter().position(|p| *p == word).ok_or(bad)?;
        let expected = self.partial.as_ref().map_or(0, |(_, parts, _)| *parts);
        let same_id = self.partial.as_ref().is_none_or(|(k, _, _)| k.id == id);
        if part != expected || !same_id {
            return Err(bad);
        }
        let (mut k, _, first_line) = self.partial.take().unwrap_or((
            KeptResult {
                id,
                robot: RobotName::new(),
                offsets_deg: [0.0; SESSION_JOINTS],
                sigma_deg: [0.0; SESSION_JOINTS],
                residual_rms_deg: 0.0,
                warnings: 0,
                temperatures_c: [None; 3],
                brackets: [None, None],
                unit: None,
            },
            0,
            line_no,
        ));
        let angle = (-MAX_READING_DEG, MAX_READING_DEG);
        let spread = (0.0, MAX_READING_DEG);
        match part {
            0 => {
                let name = words
                    .next()
                    .filter(|n| n.bytes().all(|b| b.is_ascii_graphic()))
                    .ok_or(bad)?;
                k.robot.push_str(name).map_err(|()| bad)?;
                if words.next() != Some("unit") {
                    return Err(bad);
                }
                k.unit = match words.next().ok_or(bad)? {
                    NONE => None,
                    hex => Some(UnitId::parse(hex).ok_or(bad)?),
                };
                if words.next() != Some("brackets") {
                    return Err(bad);
                }
                let mut ids = words.next().ok_or(bad)?.split(',');
                for b in &mut k.brackets {
                    *b = match ids.next().ok_or(bad)? {
                        NONE => None,
                        id => Some(bracket_id(id).map_err(|_| bad)?),
                    };
                }
                if ids.next().is_some() {
                    return Err(bad);
                }
            }
            1 => {
                let verdict = words.next().ok_or(bad)?;
                if verdict != VERDICT_PASS {
                    for name in verdict.split(',') {
                        let bit = VERDICT_WORDS.iter().position(|w| *w == name).ok_or(bad)?;
                        if k.warnings & (1 << bit) != 0 {
                            return Err(bad);
                        }
                        k.warnings |= 1 << bit;
                    }
                }
                if k.warnings & !VERDICT_BITS != 0 || words.next() != Some("temps_c") {
                    return Err(bad);
                }
                let mut temps = words.next().ok_or(bad)?.split(',');
                for t in &mut k.temperatures_c {
                    *t = match temps.next().ok_or(bad)? {
                        NONE => None,
                        c => Some(number(c, TEMPERATURE_RANGE_C).ok_or(bad)?),
                    };
                }
                if temps.next().is_some() {
                    return Err(bad);
                }
            }
            2 => k.offsets_deg = five(words.next(), angle).ok_or(bad)?,
            _ => {
                k.sigma_deg = five(words.next(), spread).ok_or(bad)?;
                if words.next() != Some("residual_rms_deg") {
                    return Err(bad);
                }
                k.residual_rms_deg = words.next().and_then(|r| number(r, spread)).ok_or(bad)?;
            }
        }
        if words.next().is_some() {
            return Err(bad);
        }
        if part + 1 == KEPT_RESULT_LINES {
            return Ok(Some(k));
        }
        self.partial = Some((k, part + 1, first_line));
        Ok(None)
    }

    /// After the last line.
    ///
    /// # Errors
    /// [`LogError::BadMetadata`] naming the first line of a result whose lines stop
    /// short.
    pub fn finish(&self) -> Result<(), LogError> {
        match &self.partial {
            Some((_, _, first_line)) => Err(LogError::BadMetadata {
                line: *first_line,
                key: KEPT_RESULT_KEY,
            }),
            None => Ok(()),
        }
    }
}

/// The kept results in `text` (the pendant's `results` reply, or a file of it), in
/// their order. Blank lines and free comments are skipped; any other line is refused.
///
/// # Errors
/// A [`LogError`] naming the line: a kept result's line that does not parse or is out
/// of order, a result whose lines stop short, an ID given twice
/// ([`LogError::DuplicateKey`]), a line that is not a comment.
#[cfg(any(test, feature = "std"))]
pub fn read_kept_results(text: &str) -> Result<std::vec::Vec<KeptResult>, LogError> {
    let mut reader = KeptResultReader::default();
    let mut out: std::vec::Vec<(KeptResult, usize)> = std::vec::Vec::new();
    for (i, line) in super::strip_bom(text).lines().enumerate() {
        let line_no = i + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        if !trimmed.starts_with('#') {
            return Err(LogError::BadMetadata {
                line: line_no,
                key: KEPT_RESULT_KEY,
            });
        }
        if let Some(k) = reader.feed(trimmed, line_no)? {
            if let Some((_, first_line)) = out.iter().find(|(o, _)| o.id == k.id) {
                return Err(LogError::DuplicateKey {
                    line: line_no,
                    key: KEPT_RESULT_KEY,
                    first_line: *first_line,
                });
            }
            out.push((k, line_no));
        }
    }
    reader.finish()?;
    Ok(out.into_iter().map(|(k, _)| k).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kept::example_kept_result as example;
    use std::string::{String, ToString};

    fn lines(results: &[KeptResult]) -> String {
        let mut text = String::from("# zerocal pendant kept results\n");
        for k in results {
            for part in 0..KEPT_RESULT_LINES {
                let mut w = Line::new();
                write_kept_result(&mut w, k, part).unwrap();
                text.push_str(&w);
                text.push_str("\r\n");
            }
        }
        text
    }

    #[test]
    fn the_lines_read_back_exactly_what_was_written() {
        let all_warnings = KeptResult {
            warnings: VERDICT_BITS,
            temperatures_c: [None; 3],
            unit: None,
            brackets: [None, None],
            ..example(12)
        };
        let results = [example(3), all_warnings, example(u32::MAX)];
        let back = read_kept_results(&lines(&results)).unwrap();
        // Bit for bit: the desktop files the very numbers the pendant holds.
        assert_eq!(back, results);
        for (a, b) in back.iter().zip(&results) {
            for (x, y) in a.offsets_deg.iter().zip(&b.offsets_deg) {
                assert_eq!(x.to_bits(), y.to_bits());
            }
        }
        assert_eq!(read_kept_results("").unwrap(), std::vec![]);
    }

    #[test]
    fn the_widest_result_fits_a_line() {
        // The longest name, both brackets of the longest ID, every warning, and
        // numbers with every decimal used.
        let mut robot = RobotName::new();
        robot.push_str(&"r".repeat(32)).unwrap();
        let long = bracket_id("ABCDEFGHIJKL").unwrap();
        let k = KeptResult {
            id: u32::MAX,
            robot,
            offsets_deg: [
                -179.99998,
                -0.000_123_456_79,
                -1.234_567_9e-7,
                -99.999_99,
                -0.999_999_9,
            ],
            sigma_deg: [1.234_567_9e-7; SESSION_JOINTS],
            residual_rms_deg: 1.234_567_9e-7,
            warnings: VERDICT_BITS,
            temperatures_c: [Some(-40.123_45), Some(124.987_65), Some(-0.000_012_3)],
            brackets: [Some(long.clone()), Some(long)],
            ..example(1)
        };
        assert_eq!(
            read_kept_results(&lines(std::slice::from_ref(&k))).unwrap(),
            [k]
        );
    }

    #[test]
    fn the_example_reads_as_written_and_below_1e_8_comes_back_within_1e_15() {
        let text = lines(&[example(7)]);
        std::println!("{text}");
        assert!(
            text.contains("# kept_result id 7 offsets_deg -0.123456701636314,0.5,"),
            "{text}"
        );
        assert!(
            text.contains(" temps_c 21.530000686645508,none,22.06999969482422"),
            "{text}"
        );
        let tiny = KeptResult {
            offsets_deg: [1.0e-12, -3.0e-9, 0.0, 7.5e-9, 1.0e-8],
            ..example(7)
        };
        let back = read_kept_results(&lines(std::slice::from_ref(&tiny))).unwrap();
        for (a, b) in back[0].offsets_deg.iter().zip(&tiny.offsets_deg) {
            assert!((f64::from(*a) - f64::from(*b)).abs() <= 1e-15, "{a} {b}");
        }
        assert_eq!(back[0].offsets_deg[4].to_bits(), 1.0e-8_f32.to_bits());
        // Beyond what the reader takes: the writer refuses rather than write "huge".
        let huge = KeptResult {
            residual_rms_deg: 1.0e5,
            ..example(7)
        };
        assert!(write_kept_result(&mut Line::new(), &huge, 3).is_err());
    }

    /// `text` with line `n` (1-based) replaced.
    fn with_line(text: &str, n: usize, line: &str) -> String {
        text.lines()
            .enumerate()
            .map(|(i, l)| {
                if i + 1 == n {
                    line.to_string()
                } else {
                    l.to_string()
                }
            })
            .collect::<std::vec::Vec<_>>()
            .join("\n")
    }

    #[test]
    fn malformed_lines_are_refused_by_line() {
        let good = lines(&[example(3), example(4)]);
        let bad = |line| LogError::BadMetadata {
            line,
            key: KEPT_RESULT_KEY,
        };
        let cases: [(usize, &str); 16] = [
            (2, "# kept_result id 0 robot r unit none brackets none,none"),
            (2, "# kept_result id x robot r unit none brackets none,none"),
            (2, "# kept_result 3 robot r unit none brackets none,none"),
            (2, "# kept_result id 3 robot r unit 0011 brackets none,none"),
            (2, "# kept_result id 3 robot r unit none brackets none"),
            (2, "# kept_result id 3 robot r unit none brackets a b,none"),
            (
                2,
                "# kept_result id 3 robot r unit none brackets none,none extra",
            ),
            (3, "# kept_result id 3 verdict fine temps_c none,none,none"),
            (
                3,
                "# kept_result id 3 verdict bias_x_unknown,bias_x_unknown temps_c none,none,none",
            ),
            (3, "# kept_result id 3 verdict pass temps_c 20,none"),
            (3, "# kept_result id 3 verdict pass temps_c 200,none,none"),
            (4, "# kept_result id 3 offsets_deg 1,2,3,4"),
            (4, "# kept_result id 3 offsets_deg 1,2,NaN,4,5"),
            (4, "# kept_result id 3 offsets_deg 1,2,3,4,181"),
            (
                5,
                "# kept_result id 3 sigma_deg 1,2,3,4,-5 residual_rms_deg 1",
            ),
            // Another result's line before this one's last.
            (
                5,
                "# kept_result id 4 sigma_deg 1,2,3,4,5 residual_rms_deg 1",
            ),
        ];
        for (n, line) in cases {
            assert_eq!(
                read_kept_results(&with_line(&good, n, line)),
                Err(bad(n)),
                "{line}"
            );
        }
        // Out of order; a row that is not a comment.
        assert_eq!(
            read_kept_results(&with_line(
                &good,
                2,
                "# kept_result id 3 verdict pass temps_c none,none,none"
            )),
            Err(bad(2))
        );
        assert_eq!(
            read_kept_results(&with_line(&good, 6, "1,2,3")),
            Err(bad(6))
        );
        // Stopping short: the result's first line is named.
        let short: String = good
            .lines()
            .take(8)
            .collect::<std::vec::Vec<_>>()
            .join("\n");
        assert_eq!(read_kept_results(&short), Err(bad(6)));
        // The same ID twice.
        let twice = lines(&[example(3), example(3)]);
        assert_eq!(
            read_kept_results(&twice),
            Err(LogError::DuplicateKey {
                line: 9,
                key: KEPT_RESULT_KEY,
                first_line: 5
            })
        );
    }
}
