//! What a step hands the firmware: the records to write to flash, in order, before the
//! new view is shown. A record that does not fit is never dropped unseen: the output
//! remembers the loss and [`Output::records`] refuses to hand over the rest, so the
//! firmware writes nothing of the step and says the write failed.
//!
//! The capacity suffices for every step (`capacity_tests` drives the largest): the most
//! a step writes is [`Event::SetPlan`](super::Event::SetPlan) of a whole plan in stage
//! 2 before its first capture, the plan's length before and after its
//! [`MAX_PLAN_POSES`] poses and the progress ([`MOST_STEP_RECORDS`]); any other step
//! writes at most three (a capture, the result it completes, the progress).

use super::{Record, MAX_PLAN_POSES};

/// How many records an [`Output`] holds: a whole plan's poses and four more.
pub const OUTPUT_RECORDS: usize = MAX_PLAN_POSES + 4;

/// The most records one step writes: a whole plan's poses, its length twice (0 first,
/// so a cut mid-plan leaves no plan; the new length last) and the progress.
const MOST_STEP_RECORDS: usize = MAX_PLAN_POSES + 3;

const _: () = assert!(MOST_STEP_RECORDS <= OUTPUT_RECORDS);

/// Why a step's records cannot be written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputError {
    /// A record came when the output was full and was not kept: the others, written
    /// alone, would store a state the pendant does not hold.
    RecordLost,
}

/// What the firmware must do after a step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Output<T> {
    persist: heapless::Vec<Record<T>, OUTPUT_RECORDS>,
    /// A record was pushed when `persist` was full.
    lost: bool,
}

impl<T> Output<T> {
    /// Adds a record to write; one beyond the capacity is remembered as lost.
    // Out of line: inlined, each of its dozen and more callers had a copy (flash).
    #[inline(never)]
    pub fn push(&mut self, r: Record<T>) {
        if self.persist.push(r).is_err() {
            self.lost = true;
        }
    }

    /// Adds `other`'s records after these; a record `other` lost stays lost.
    pub fn append(&mut self, other: Output<T>) {
        self.lost |= other.lost;
        for r in other.persist {
            self.push(r);
        }
    }

    /// The records to write to flash, in order, before showing the new view.
    ///
    /// # Errors
    /// [`OutputError::RecordLost`] if a record did not fit: none is to be written.
    pub fn records(&self) -> Result<&[Record<T>], OutputError> {
        if self.lost {
            return Err(OutputError::RecordLost);
        }
        Ok(&self.persist)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_past_the_capacity_is_reported_lost_not_dropped() {
        let mut out = Output::<f64>::default();
        for k in 0..OUTPUT_RECORDS {
            out.push(Record::PlanLen(k as u8));
        }
        assert_eq!(out.records().map(<[_]>::len), Ok(OUTPUT_RECORDS));
        out.push(Record::PlanLen(0));
        assert_eq!(out.records(), Err(OutputError::RecordLost));
    }

    #[test]
    fn appending_keeps_the_order_and_a_loss() {
        let mut first = Output::<f64>::default();
        first.push(Record::PlanLen(1));
        let mut second = Output::default();
        second.push(Record::PlanLen(2));
        first.append(second.clone());
        assert_eq!(
            first.records(),
            Ok(&[Record::PlanLen(1), Record::PlanLen(2)][..])
        );
        for _ in 0..OUTPUT_RECORDS {
            second.push(Record::PlanLen(3));
        }
        // Full, with one lost: appended to an empty output it fits, but the loss stays.
        let mut empty = Output::default();
        empty.append(second);
        assert_eq!(empty.records(), Err(OutputError::RecordLost));
        // Appending past the capacity loses records too.
        let mut full = Output::<f64>::default();
        for _ in 0..OUTPUT_RECORDS {
            full.push(Record::PlanLen(4));
        }
        let mut one = Output::default();
        one.push(Record::PlanLen(5));
        full.append(one);
        assert_eq!(full.records(), Err(OutputError::RecordLost));
    }
}
