//! What can go wrong, named so that an operator can act on it.

use crate::decimal::Fixed;
use crate::model::TiltAxis;
use core::fmt;

/// A set of the stage-2 parameters Δθ3..Δθ6 (bit k = joint k+3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct ParamSet(pub u8);

impl ParamSet {
    /// Adds joint index `k` (0 = joint 3).
    pub fn with(self, k: usize) -> Self {
        ParamSet(self.0 | (1 << k))
    }

    /// Whether joint index `k` (0 = joint 3) is in the set.
    pub fn contains(self, k: usize) -> bool {
        self.0 & (1 << k) != 0
    }

    /// Robot joint numbers (3..=6) in the set.
    pub fn joints(self) -> impl Iterator<Item = u8> {
        (0..4u8)
            .filter(move |&k| self.contains(k as usize))
            .map(|k| k + 3)
    }
}

impl fmt::Display for ParamSet {
    /// `j4+j6`: short enough for the pendant's display.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for j in self.joints() {
            if !first {
                f.write_str("+")?;
            }
            write!(f, "j{j}")?;
            first = false;
        }
        Ok(())
    }
}

/// Why stage 2 gave no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FitError {
    /// Fewer poses than the fit needs.
    TooFewPoses {
        /// Poses given.
        got: usize,
        /// Poses needed.
        min: usize,
    },
    /// A commanded joint angle is NaN or infinite.
    NonFiniteJoint {
        /// Pose index (0-based).
        pose: usize,
    },
    /// A reading is NaN or infinite.
    NonFiniteReading {
        /// Pose index (0-based).
        pose: usize,
    },
    /// A reading lies outside the sensor's range.
    ReadingOutOfRange {
        /// Pose index (0-based).
        pose: usize,
        /// Which reading.
        axis: TiltAxis,
        /// The reading (deg).
        value_deg: f32,
        /// The sensor's range (± deg).
        range_deg: f32,
    },
    /// The pose set cannot separate these parameters at all.
    RankDeficient {
        /// The parameters that move together.
        params: ParamSet,
    },
    /// The pose set separates these parameters too weakly to trust the numbers.
    IllConditioned {
        /// Condition number of the Jacobian.
        condition_number: f32,
        /// Largest allowed.
        limit: f32,
        /// The parameters that are nearly inseparable.
        params: ParamSet,
    },
    /// The iteration did not settle.
    NoConvergence {
        /// Iterations spent.
        iterations: u32,
    },
    /// The arithmetic produced a non-finite number (a model far from the data).
    NonFiniteResult,
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            FitError::TooFewPoses { got, min } => {
                write!(f, "too few poses: {got} given, at least {min} needed")
            }
            FitError::NonFiniteJoint { pose } => {
                write!(f, "pose {}: a joint angle is not a finite number", pose + 1)
            }
            FitError::NonFiniteReading { pose } => {
                write!(f, "pose {}: a reading is not a finite number", pose + 1)
            }
            FitError::ReadingOutOfRange {
                pose,
                axis,
                value_deg,
                range_deg,
            } => write!(
                f,
                "pose {}: reading {axis} = {} deg is outside the sensor range of +/-{} deg",
                pose + 1,
                Fixed::new(f64::from(value_deg), 3),
                Fixed::new(f64::from(range_deg), 1)
            ),
            FitError::RankDeficient { params } => write!(
                f,
                "rank-deficient pose set: the zeros of {params} cannot be separated; vary those joints"
            ),
            FitError::IllConditioned {
                condition_number,
                limit,
                params,
            } => write!(
                f,
                "ill-conditioned pose set (condition number {} > {}): {params} barely separable; vary those joints more",
                Fixed::new(f64::from(condition_number), 0),
                Fixed::new(f64::from(limit), 0)
            ),
            FitError::NoConvergence { iterations } => {
                write!(f, "no convergence after {iterations} iterations")
            }
            FitError::NonFiniteResult => f.write_str("the fit produced a non-finite number"),
        }
    }
}

/// Why stage 0 or stage 1 gave no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StageError {
    /// A reading is NaN or infinite.
    NonFiniteReading,
    /// A reading lies outside the sensor's range.
    ReadingOutOfRange {
        /// Which reading.
        axis: TiltAxis,
        /// The reading (deg).
        value_deg: f32,
        /// The sensor's range (± deg).
        range_deg: f32,
    },
    /// The readings cannot come from one orientation (`axis` convention only).
    InconsistentReading,
    /// `s2` must be +1 or −1.
    BadDirectionSign,
    /// The commanded joint-2 angle is NaN or infinite.
    NonFiniteCommand,
}

impl fmt::Display for StageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            StageError::NonFiniteReading => f.write_str("a reading is not a finite number"),
            StageError::ReadingOutOfRange {
                axis,
                value_deg,
                range_deg,
            } => write!(
                f,
                "reading {axis} = {} deg is outside the sensor range of +/-{} deg",
                Fixed::new(f64::from(value_deg), 3),
                Fixed::new(f64::from(range_deg), 1)
            ),
            StageError::InconsistentReading => {
                f.write_str("the x and y readings cannot come from one orientation")
            }
            StageError::BadDirectionSign => {
                f.write_str("the joint-2 direction sign must be +1 or -1")
            }
            StageError::NonFiniteCommand => {
                f.write_str("the commanded joint-2 angle is not a finite number")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for FitError {}
#[cfg(feature = "std")]
impl std::error::Error for StageError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn param_set_names_robot_joints() {
        let s = ParamSet::default().with(1).with(3);
        assert_eq!(format!("{s}"), "j4+j6");
        assert!(s.contains(1) && !s.contains(0));
    }
}
