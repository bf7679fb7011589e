//! The capture scheme, defined once: every stage-2 pose (and every stage-1 reading) is
//! captured twice, first with every joint arriving from below, then from above after an
//! overshoot, so the two captures sit on the two sides of each gear's backlash and their
//! mean in its middle. The pendant's procedure, its records and export, the robot
//! programs, the robot-time model and the session solver all take the scheme from here.

/// Captures per pose: one from below, one from above.
pub const CAPTURES_PER_POSE: usize = 2;

/// How many stage-2 captures the pendant holds (its flash records and its RAM): a
/// plan's [`crate::plan::MAX_POSES`] poses, each twice.
pub const MAX_CAPTURES: usize = 96;

/// How many poses a plan sent to the pendant may have: every pose takes
/// [`CAPTURES_PER_POSE`] of the [`MAX_CAPTURES`].
pub const MAX_PLAN_POSES: usize = MAX_CAPTURES / CAPTURES_PER_POSE;

/// How far below a pose every joint starts the last move to the pose's first capture
/// (deg): a stated default, 50× the order of gear backlash named in the controller
/// leads (0.01-0.02°, calibration-practice leads, not verified against a source).
pub const APPROACH_DEG: f64 = 1.0;

/// How far above a pose every joint goes before coming back to it for the pose's
/// second capture (deg). The excursion must also re-arm the pendant (its reading must
/// leave the last capture by twice the re-arm threshold): 4° does at every pose of every
/// built-in profile's default plan and at stage 1; the smallest change is 0.49° (a
/// FANUC M-20iA pose, whose J2/J3 coupling moves the forearm little when J2 and J3 turn
/// together), against 0.36° at 3° and 0.23° at 2° (the CLI's
/// `overshoot_rearms_every_builtin_plan` test). Where a plan of the user's is not
/// re-armed, the program stops for an OK instead.
pub const OVERSHOOT_DEG: f64 = 4.0;

/// The side every joint arrives from before a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Approach {
    /// Every joint arriving moving positive.
    FromBelow,
    /// Every joint arriving moving negative (after going past the pose).
    FromAbove,
}

impl Approach {
    /// The approaches in capture order.
    pub const ORDER: [Approach; CAPTURES_PER_POSE] = [Approach::FromBelow, Approach::FromAbove];

    /// The approach of capture `index` of a pose or stage-1 reading, counted in capture
    /// order.
    pub fn of(index: usize) -> Self {
        Self::ORDER[index % CAPTURES_PER_POSE]
    }

    /// Position in [`Self::ORDER`].
    pub fn ordinal(self) -> usize {
        match self {
            Approach::FromBelow => 0,
            Approach::FromAbove => 1,
        }
    }

    /// The export's word for it.
    pub fn word(self) -> &'static str {
        match self {
            Approach::FromBelow => "below",
            Approach::FromAbove => "above",
        }
    }

    /// Reads the export's word.
    pub fn from_word(word: &str) -> Option<Self> {
        Self::ORDER.into_iter().find(|a| a.word() == word)
    }
}

/// Which capture of a session: the pose (its index in the plan) and the side it was
/// approached from. The one way captures are numbered, so no code does cursor arithmetic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CaptureIndex {
    /// The pose's index in the plan.
    pub pose: u8,
    /// The side of this capture.
    pub approach: Approach,
}

impl CaptureIndex {
    /// The capture at `sequence` in capture order (pose 0 below, pose 0 above, pose 1
    /// below, ...); `None` past [`MAX_CAPTURES`].
    pub fn from_sequence(sequence: usize) -> Option<Self> {
        if sequence >= MAX_CAPTURES {
            return None;
        }
        Some(CaptureIndex {
            pose: u8::try_from(sequence / CAPTURES_PER_POSE).ok()?,
            approach: Approach::of(sequence),
        })
    }

    /// Position in capture order: the inverse of [`Self::from_sequence`].
    pub fn sequence(self) -> usize {
        usize::from(self.pose) * CAPTURES_PER_POSE + self.approach.ordinal()
    }

    /// The sequence number of pose `pose`'s first capture (from below).
    pub fn first_of(pose: usize) -> usize {
        pose * CAPTURES_PER_POSE
    }

    /// Captures a plan of `poses` poses takes.
    pub fn captures_of(poses: usize) -> usize {
        poses * CAPTURES_PER_POSE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sequence_round_trips_over_the_whole_capacity() {
        for sequence in 0..MAX_CAPTURES {
            let index = CaptureIndex::from_sequence(sequence).unwrap();
            assert_eq!(index.sequence(), sequence);
            assert!(usize::from(index.pose) < MAX_PLAN_POSES);
        }
        assert_eq!(CaptureIndex::from_sequence(MAX_CAPTURES), None);
    }

    #[test]
    fn below_comes_first() {
        assert_eq!(Approach::of(0), Approach::FromBelow);
        assert_eq!(Approach::of(1), Approach::FromAbove);
        for a in Approach::ORDER {
            assert_eq!(Approach::from_word(a.word()), Some(a));
        }
    }
}
