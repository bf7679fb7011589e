//! Where the operator is ([`Phase`]) and which capture of stages 0 and 1 and of the
//! closing bench readings is which ([`ReadingSlot`]): the one numbering the state
//! machine, its flash records and its restore share.
//!
//! The bench (stage 0, and again after stage 2) is read at [`BENCH_HEADINGS`] headings,
//! the pendant turned by hand about a quarter turn on the same spot between them; core
//! solves the headings and the sensor's bias as the centre of the circle the readings
//! draw ([`zerocal_core::stage0::BenchTurns`]), so no turn needs to be exact.

use zerocal_core::stage0::BENCH_HEADINGS;

/// Where the operator is. In the bench phases the procedure's cursor is the heading
/// (0-based), in stage 1 the approach, in stage 2 the capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Phase {
    /// Stage 0: the pendant on a stable bench, read at each of [`BENCH_HEADINGS`]
    /// headings, turned by hand about a quarter turn on the same spot between them.
    Stage0,
    /// Stage 1: on the upper arm, axis 1 at its mark (from below, then from above).
    Stage1Before,
    /// Stage 1: axis 1 turned by 180° (from below, then from above).
    Stage1After,
    /// Stage 2: on the flange, the plan's poses, each from below, then from above.
    Stage2,
    /// The closing bench readings: the pendant back on stage 0's bench, read at the
    /// headings again, so the bias' drift over the session is measured.
    Closing,
    /// The result (or why there is none).
    Done,
}

impl Phase {
    /// Every phase, by [`code`](Self::code).
    pub const ALL: [Phase; 6] = [
        Phase::Stage0,
        Phase::Stage1Before,
        Phase::Stage1After,
        Phase::Stage2,
        Phase::Closing,
        Phase::Done,
    ];

    /// Stable code for storage: its place in [`ALL`](Self::ALL).
    pub fn code(self) -> u8 {
        match self {
            Phase::Stage0 => 0,
            Phase::Stage1Before => 1,
            Phase::Stage1After => 2,
            Phase::Stage2 => 3,
            Phase::Closing => 4,
            Phase::Done => 5,
        }
    }

    /// Inverse of [`code`](Self::code).
    pub fn from_code(c: u8) -> Option<Self> {
        Self::ALL.get(usize::from(c)).copied()
    }

    /// Whether this phase captures readings.
    pub fn captures(self) -> bool {
        self != Phase::Done
    }

    /// Whether the pendant sits on the bench (stage 0 and the closing readings).
    pub fn on_bench(self) -> bool {
        matches!(self, Phase::Stage0 | Phase::Closing)
    }
}

/// How many [`ReadingSlot`]s there are: stage 0's headings, stage 1's four captures,
/// the closing headings.
pub const READING_SLOTS: usize = 2 * BENCH_HEADINGS + STAGE1_SLOTS;

/// Stage 1's captures: at the mark and turned, each from below and from above.
const STAGE1_SLOTS: usize = 4;

/// Which capture of stages 0 and 1 or of the closing bench readings: its place in
/// capture order (also its storage code), `0..`[`READING_SLOTS`]. Stage 0's headings
/// first, then stage 1's four captures, then the closing headings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ReadingSlot(u8);

/// The first closing slot's index.
const CLOSING_START: usize = BENCH_HEADINGS + STAGE1_SLOTS;

impl ReadingSlot {
    /// Stage 0's first heading.
    pub const STAGE0_FIRST: ReadingSlot = ReadingSlot(0);
    /// Stage 0's last heading.
    pub const STAGE0_LAST: ReadingSlot = ReadingSlot(BENCH_HEADINGS as u8 - 1);
    /// Stage 1 at the mark, from below.
    pub const STAGE1_BEFORE_BELOW: ReadingSlot = ReadingSlot(BENCH_HEADINGS as u8);
    /// Stage 1 at the mark, from above.
    pub const STAGE1_BEFORE_ABOVE: ReadingSlot = ReadingSlot(BENCH_HEADINGS as u8 + 1);
    /// Stage 1 turned, from below.
    pub const STAGE1_AFTER_BELOW: ReadingSlot = ReadingSlot(BENCH_HEADINGS as u8 + 2);
    /// Stage 1 turned, from above.
    pub const STAGE1_AFTER_ABOVE: ReadingSlot = ReadingSlot(BENCH_HEADINGS as u8 + 3);
    /// The closing readings' first heading.
    pub const CLOSING_FIRST: ReadingSlot = ReadingSlot(CLOSING_START as u8);
    /// The closing readings' last heading.
    pub const CLOSING_LAST: ReadingSlot = ReadingSlot(READING_SLOTS as u8 - 1);

    /// Every slot, in capture order.
    pub fn all() -> impl Iterator<Item = ReadingSlot> {
        (0..READING_SLOTS as u8).map(ReadingSlot)
    }

    /// Stage 0's heading `heading` (0-based), if there is one.
    pub fn stage0(heading: usize) -> Option<Self> {
        (heading < BENCH_HEADINGS).then_some(ReadingSlot(heading as u8))
    }

    /// The closing readings' heading `heading` (0-based), if there is one.
    pub fn closing(heading: usize) -> Option<Self> {
        (heading < BENCH_HEADINGS).then_some(ReadingSlot((CLOSING_START + heading) as u8))
    }

    /// Its place in capture order (also its storage code).
    pub fn index(self) -> usize {
        usize::from(self.0)
    }

    /// Inverse of [`index`](Self::index).
    pub fn from_index(i: usize) -> Option<Self> {
        (i < READING_SLOTS).then_some(ReadingSlot(i as u8))
    }

    /// Whether the slot is one of stage 0's headings.
    pub fn is_stage0(self) -> bool {
        self <= Self::STAGE0_LAST
    }

    /// Whether the slot is one of stage 1's (a check has none).
    pub fn is_stage1(self) -> bool {
        (Self::STAGE1_BEFORE_BELOW..=Self::STAGE1_AFTER_ABOVE).contains(&self)
    }

    /// Whether the slot is one of the closing headings.
    pub fn is_closing(self) -> bool {
        self >= Self::CLOSING_FIRST
    }

    /// The slot captured in `phase` at `cursor` (stage 1: 0 from below, 1 from above;
    /// on the bench: the heading).
    pub fn at(phase: Phase, cursor: usize) -> Option<Self> {
        let side = cursor.min(1) as u8;
        match phase {
            Phase::Stage0 => Self::stage0(cursor),
            Phase::Stage1Before => Some(ReadingSlot(Self::STAGE1_BEFORE_BELOW.0 + side)),
            Phase::Stage1After => Some(ReadingSlot(Self::STAGE1_AFTER_BELOW.0 + side)),
            Phase::Closing => Self::closing(cursor),
            Phase::Stage2 | Phase::Done => None,
        }
    }

    /// Where the procedure stands when this slot is the next to take.
    pub fn phase_cursor(self) -> (Phase, usize) {
        let i = self.index();
        if self.is_stage0() {
            (Phase::Stage0, i)
        } else if self.is_closing() {
            (Phase::Closing, i - CLOSING_START)
        } else if self < Self::STAGE1_AFTER_BELOW {
            (Phase::Stage1Before, i - Self::STAGE1_BEFORE_BELOW.index())
        } else {
            (Phase::Stage1After, i - Self::STAGE1_AFTER_BELOW.index())
        }
    }

    /// The next slot in capture order, if any.
    pub fn next(self) -> Option<Self> {
        Self::from_index(self.index() + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_slot_is_where_its_phase_and_cursor_say() {
        let mut seen = 0;
        for slot in ReadingSlot::all() {
            let (phase, cursor) = slot.phase_cursor();
            assert_eq!(ReadingSlot::at(phase, cursor), Some(slot), "{slot:?}");
            assert_eq!(ReadingSlot::from_index(slot.index()), Some(slot));
            // Each slot is exactly one of the three stages'.
            let kinds = [slot.is_stage0(), slot.is_stage1(), slot.is_closing()];
            assert_eq!(kinds.iter().filter(|k| **k).count(), 1, "{slot:?}");
            seen += 1;
        }
        assert_eq!(seen, READING_SLOTS);
        assert_eq!(ReadingSlot::from_index(READING_SLOTS), None);
        assert_eq!(ReadingSlot::stage0(BENCH_HEADINGS), None);
        assert_eq!(ReadingSlot::closing(BENCH_HEADINGS), None);
        assert_eq!(ReadingSlot::at(Phase::Stage0, BENCH_HEADINGS), None);
        // The headings of each bench step, in order, are that step's slots.
        for h in 0..BENCH_HEADINGS {
            assert_eq!(
                ReadingSlot::stage0(h).map(ReadingSlot::phase_cursor),
                Some((Phase::Stage0, h))
            );
            assert_eq!(
                ReadingSlot::closing(h).map(ReadingSlot::phase_cursor),
                Some((Phase::Closing, h))
            );
        }
    }

    #[test]
    fn phase_codes_are_dense_and_round_trip() {
        for (i, p) in Phase::ALL.into_iter().enumerate() {
            assert_eq!(usize::from(p.code()), i);
            assert_eq!(Phase::from_code(p.code()), Some(p));
        }
        assert_eq!(Phase::from_code(Phase::ALL.len() as u8), None);
    }
}
