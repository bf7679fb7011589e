//! The link's `bracket status` line: where a bracket calibration on the pendant stands,
//! so that `zerocal pendant bracket-calibrate` follows it step by step and knows its
//! end. One line, written by [`progress_line`] and read back by [`parse_progress_line`]:
//!
//! - `calibrating none`: no calibration in progress (none started, or it was kept, or
//!   left with BACK; `brackets` tells which);
//! - `calibrating MOUNT ID step K of 12 waiting|armed`: at capture step K (1-based,
//!   [`BracketStep::CAPTURES`]), waiting for OK, or armed and capturing once still;
//! - `calibrating MOUNT ID result`: the result is shown, OK on the pendant keeps it;
//! - `calibrating MOUNT ID refused WORD`: refused ([`BracketRefusal`]), OK starts
//!   again from the first step.
//!
//! No numbers: the pendant's screen shows them, and the kept result reaches the
//! desktop through `brackets` (and this keeps float formatting out of the firmware).

use core::fmt::{self, Write};

use super::{BracketCalState, BracketStep, BRACKET_CAPTURES};
use crate::link::Line;
use zerocal_core::bracket::{bracket_id, BracketError, BracketId, BracketMount};
use zerocal_core::real::Real;

/// The first word of a [`progress_line`].
const TAG: &str = "calibrating";

/// Why a calibration was refused, as one word on the link (the pendant's screen gives
/// the numbers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BracketRefusal {
    /// [`BracketError::PlateNotLevel`].
    PlateNotLevel,
    /// [`BracketError::NotOnSinePlate`].
    NotOnSinePlate,
    /// [`BracketError::Implausible`].
    Implausible,
    /// [`BracketError::Reading`].
    Reading,
    /// [`BracketError::BadId`] or [`BracketError::BadDate`] (not from a calibration's
    /// readings; listed so every refusal has a word).
    BadRecord,
}

impl BracketRefusal {
    /// Every refusal.
    pub const ALL: [BracketRefusal; 5] = [
        BracketRefusal::PlateNotLevel,
        BracketRefusal::NotOnSinePlate,
        BracketRefusal::Implausible,
        BracketRefusal::Reading,
        BracketRefusal::BadRecord,
    ];

    /// The refusal of `e`.
    pub fn of(e: &BracketError) -> Self {
        match e {
            BracketError::PlateNotLevel { .. } => BracketRefusal::PlateNotLevel,
            BracketError::NotOnSinePlate { .. } => BracketRefusal::NotOnSinePlate,
            BracketError::Implausible => BracketRefusal::Implausible,
            BracketError::Reading(_) => BracketRefusal::Reading,
            BracketError::BadId | BracketError::BadDate => BracketRefusal::BadRecord,
        }
    }

    /// Its word on the link.
    pub const fn word(self) -> &'static str {
        match self {
            BracketRefusal::PlateNotLevel => "plate-not-level",
            BracketRefusal::NotOnSinePlate => "not-on-sine-plate",
            BracketRefusal::Implausible => "implausible",
            BracketRefusal::Reading => "reading",
            BracketRefusal::BadRecord => "bad-record",
        }
    }

    /// The refusal named by `word`.
    pub fn parse(word: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.word() == word)
    }
}

/// A [`progress_line`] read back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BracketProgress {
    /// No calibration in progress.
    Idle,
    /// A calibration of bracket `id` on `mount`.
    Calibrating {
        /// Which bracket.
        mount: BracketMount,
        /// Its ID.
        id: BracketId,
        /// Where it stands.
        stage: CalibrationStage,
    },
}

/// Where a calibration in progress stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CalibrationStage {
    /// At this capture step, waiting for OK (`armed` false) or capturing once still.
    Step {
        /// The step.
        step: BracketStep,
        /// Whether OK was pressed and the capture waits for stillness.
        armed: bool,
    },
    /// The result is shown; OK keeps it.
    Result,
    /// Refused; OK starts again.
    Refused(BracketRefusal),
}

/// The step's number (1-based) among [`BracketStep::CAPTURES`].
fn step_number(step: BracketStep) -> Option<usize> {
    BracketStep::CAPTURES
        .iter()
        .position(|s| *s == step)
        .map(|i| i + 1)
}

/// The `bracket status` line for the calibration in progress, if any.
///
/// # Errors
/// Only a full line buffer.
pub fn progress_line<T: Real>(state: Option<&BracketCalState<T>>) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    let Some(s) = state else {
        write!(w, "{TAG} none")?;
        return Ok(w);
    };
    write!(w, "{TAG} {} {} ", s.mount().name(), s.id())?;
    match (s.outcome(), step_number(s.step())) {
        (Some(Ok(_)), _) => w.write_str("result")?,
        (Some(Err(e)), _) => write!(w, "refused {}", BracketRefusal::of(e).word())?,
        (None, Some(k)) => write!(
            w,
            "step {k} of {BRACKET_CAPTURES} {}",
            if s.armed() { "armed" } else { "waiting" }
        )?,
        // Every capture in and no outcome: the result is being computed.
        (None, None) => w.write_str("result")?,
    }
    Ok(w)
}

/// What is wrong with a line that should be a [`progress_line`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProgressLineError {
    /// Not `calibrating …`.
    NotAProgressLine,
    /// A field missing, out of place or out of its range.
    BadField(&'static str),
}

impl fmt::Display for ProgressLineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProgressLineError::NotAProgressLine => write!(f, "not a '{TAG} ...' line"),
            ProgressLineError::BadField(name) => write!(f, "its '{name}' is missing or bad"),
        }
    }
}

/// Reads a [`progress_line`] back.
///
/// # Errors
/// [`ProgressLineError`], naming the field.
pub fn parse_progress_line(line: &str) -> Result<BracketProgress, ProgressLineError> {
    let mut words = line.split_whitespace();
    if words.next() != Some(TAG) {
        return Err(ProgressLineError::NotAProgressLine);
    }
    let bad = ProgressLineError::BadField;
    let first = words.next().ok_or(bad("mount"))?;
    if first == "none" {
        return match words.next() {
            None => Ok(BracketProgress::Idle),
            Some(_) => Err(bad("end of line")),
        };
    }
    let mount = BracketMount::parse(first).ok_or(bad("mount"))?;
    let id = words
        .next()
        .and_then(|w| bracket_id(w).ok())
        .ok_or(bad("id"))?;
    let stage = match words.next() {
        Some("result") => CalibrationStage::Result,
        Some("refused") => CalibrationStage::Refused(
            words
                .next()
                .and_then(BracketRefusal::parse)
                .ok_or(bad("refused"))?,
        ),
        Some("step") => {
            let k: usize = words
                .next()
                .filter(|k| k.len() <= 2 && k.bytes().all(|b| b.is_ascii_digit()))
                .and_then(|k| k.parse().ok())
                .ok_or(bad("step"))?;
            let step = k
                .checked_sub(1)
                .and_then(|i| BracketStep::CAPTURES.get(i))
                .copied()
                .ok_or(bad("step"))?;
            let total = (words.next(), words.next());
            let of = BRACKET_CAPTURES;
            if total.0 != Some("of") || total.1.and_then(|n| n.parse::<usize>().ok()) != Some(of) {
                return Err(bad("of"));
            }
            let armed = match words.next() {
                Some("armed") => true,
                Some("waiting") => false,
                _ => return Err(bad("armed")),
            };
            CalibrationStage::Step { step, armed }
        }
        _ => return Err(bad("stage")),
    };
    if words.next().is_some() {
        return Err(bad("end of line"));
    }
    Ok(BracketProgress::Calibrating { mount, id, stage })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::Event;
    use crate::stillness::StillnessFilter;

    #[test]
    fn every_stage_reads_back_as_written() {
        assert_eq!(
            parse_progress_line(&progress_line::<f64>(None).unwrap()),
            Ok(BracketProgress::Idle)
        );
        let config = crate::machine::ProcedureConfig::<f64>::default();
        let id = bracket_id("F-017").unwrap();
        let mut s = BracketCalState::<f64>::new(BracketMount::Flange, id.clone());
        let line = progress_line(Some(&s)).unwrap();
        assert_eq!(
            line.as_str(),
            "calibrating flange F-017 step 1 of 12 waiting"
        );
        let mut window = StillnessFilter::new();
        let _ = super::super::bracket_step(&config, &mut s, &mut window, Event::Ok);
        let line = progress_line(Some(&s)).unwrap();
        assert_eq!(
            parse_progress_line(&line),
            Ok(BracketProgress::Calibrating {
                mount: BracketMount::Flange,
                id,
                stage: CalibrationStage::Step {
                    step: BracketStep::Alone { heading: 0 },
                    armed: true
                }
            })
        );
        for r in BracketRefusal::ALL {
            let line = std::format!("calibrating upper-arm U-1 refused {}", r.word());
            assert!(
                matches!(
                    parse_progress_line(&line),
                    Ok(BracketProgress::Calibrating {
                        stage: CalibrationStage::Refused(back),
                        ..
                    }) if back == r
                ),
                "{line}"
            );
        }
    }

    #[test]
    fn junk_is_named() {
        for (line, err) in [
            ("brackets flange none", ProgressLineError::NotAProgressLine),
            ("calibrating", ProgressLineError::BadField("mount")),
            (
                "calibrating none x",
                ProgressLineError::BadField("end of line"),
            ),
            (
                "calibrating wrist F-1 result",
                ProgressLineError::BadField("mount"),
            ),
            (
                "calibrating flange F 1 result",
                ProgressLineError::BadField("stage"),
            ),
            (
                "calibrating flange F-1 step 0 of 12 armed",
                ProgressLineError::BadField("step"),
            ),
            (
                "calibrating flange F-1 step 13 of 12 armed",
                ProgressLineError::BadField("step"),
            ),
            (
                "calibrating flange F-1 step 2 of 7 armed",
                ProgressLineError::BadField("of"),
            ),
            (
                "calibrating flange F-1 step 2 of 12 ready",
                ProgressLineError::BadField("armed"),
            ),
            (
                "calibrating flange F-1 refused tilted",
                ProgressLineError::BadField("refused"),
            ),
            (
                "calibrating flange F-1 result now",
                ProgressLineError::BadField("end of line"),
            ),
        ] {
            assert_eq!(parse_progress_line(line), Err(err), "{line}");
        }
    }
}
