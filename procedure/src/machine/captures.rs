//! The stage-2 captures of a session, in the order taken ([`Captures`]): which capture
//! each is and its pose reading, kept side by side so that the session solver takes
//! both as slices. Kept as pairs they had to be copied apart for every solve: with the
//! 96 captures a plan of 48 poses takes, 4 KiB of stack at the solve, the pendant's
//! deepest moment.

use crate::log::CaptureRows;
use zerocal_core::capture::{CaptureIndex, MAX_CAPTURES};
use zerocal_core::stage2::PoseReading;

/// The stage-2 captures, in the order taken.
#[derive(Clone, Debug, PartialEq)]
pub struct Captures<T> {
    index: heapless::Vec<CaptureIndex, MAX_CAPTURES>,
    poses: heapless::Vec<PoseReading<T>, MAX_CAPTURES>,
}

impl<T> Default for Captures<T> {
    fn default() -> Self {
        Captures {
            index: heapless::Vec::new(),
            poses: heapless::Vec::new(),
        }
    }
}

impl<T: Copy> Captures<T> {
    /// How many.
    pub fn len(&self) -> usize {
        self.poses.len()
    }

    /// None yet.
    pub fn is_empty(&self) -> bool {
        self.poses.is_empty()
    }

    /// Which capture each is (its pose in the plan and its approach), in the order
    /// taken.
    pub fn indices(&self) -> &[CaptureIndex] {
        &self.index
    }

    /// The pose readings, in the order taken.
    pub fn poses(&self) -> &[PoseReading<T>] {
        &self.poses
    }

    /// Capture `i` (in the order taken) with its index.
    pub fn get(&self, i: usize) -> Option<(CaptureIndex, PoseReading<T>)> {
        Some((*self.index.get(i)?, *self.poses.get(i)?))
    }

    /// The last capture taken.
    pub fn last(&self) -> Option<(CaptureIndex, PoseReading<T>)> {
        self.get(self.len().checked_sub(1)?)
    }

    /// Every capture with its index, in the order taken.
    pub fn iter(&self) -> impl Iterator<Item = (CaptureIndex, PoseReading<T>)> + '_ {
        self.index.iter().copied().zip(self.poses.iter().copied())
    }

    /// Adds a capture; `Err` when [`MAX_CAPTURES`] are taken.
    pub(super) fn push(&mut self, index: CaptureIndex, pose: PoseReading<T>) -> Result<(), ()> {
        if self.poses.is_full() {
            return Err(());
        }
        // Both hold MAX_CAPTURES and grow together.
        self.index.push(index).map_err(|_| ())?;
        self.poses.push(pose).map_err(|_| ())
    }

    /// Takes the last capture back.
    pub(super) fn pop(&mut self) -> Option<(CaptureIndex, PoseReading<T>)> {
        Some((self.index.pop()?, self.poses.pop()?))
    }

    /// Forgets every capture.
    pub(super) fn clear(&mut self) {
        self.index.clear();
        self.poses.clear();
    }
}

impl<T: Copy> CaptureRows<T> for &Captures<T> {
    fn count(&self) -> usize {
        self.len()
    }
    fn capture(&self, i: usize) -> Option<(CaptureIndex, PoseReading<T>)> {
        self.get(i)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::model::Tilt;

    fn pose(k: usize) -> PoseReading<f64> {
        PoseReading {
            joints_rad: [0.0, 0.0, 0.1 * k as f64, 0.2, 0.3, 0.4],
            reading: Tilt::new(0.01 * k as f64, 0.02),
            temperature_c: Some(23.0),
        }
    }

    #[test]
    fn captures_keep_index_and_pose_together_up_to_the_capacity() {
        let mut c = Captures::<f64>::default();
        for k in 0..MAX_CAPTURES {
            let index = CaptureIndex::from_sequence(k).unwrap();
            assert_eq!(c.push(index, pose(k)), Ok(()));
        }
        let full = CaptureIndex::from_sequence(0).unwrap();
        assert_eq!(c.push(full, pose(0)), Err(()));
        assert_eq!((c.len(), c.indices().len()), (MAX_CAPTURES, MAX_CAPTURES));
        for (k, (index, p)) in c.iter().enumerate() {
            assert_eq!((index.sequence(), p), (k, pose(k)));
        }
        let last = c.pop().unwrap();
        assert_eq!(last.0.sequence(), MAX_CAPTURES - 1);
        assert_eq!(c.last().map(|(i, _)| i.sequence()), Some(MAX_CAPTURES - 2));
        assert_eq!(
            (c.len(), c.indices().len()),
            (MAX_CAPTURES - 1, MAX_CAPTURES - 1)
        );
        c.clear();
        assert!(c.is_empty() && c.indices().is_empty() && c.last().is_none());
    }
}
