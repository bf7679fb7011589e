//! What can go wrong, named so that an operator can act on it.

use crate::decimal::Fixed;
use crate::model::TiltAxis;
use core::fmt;

/// The names of stage 2's parameters, by index (`stage2::Param`'s order).
/// `tiltJ` is joint J's axis misalignment (`tiltJb` its second direction, where J's
/// axis is parallel to the one before), `sagJ` joint J's compliance under its load
/// (`sag` joint 3's, `sag2` joint 2's where stage 2 moves joint 2), `lashJ` half of
/// joint J's lost motion on the side gravity loads it, `teJcN`/`teJsN` the cosine and
/// sine coefficients of joint J's transmission error N times per turn.
pub const PARAM_NAMES: [&str; 61] = [
    "j3", "j4", "j5", "j6", "gain_x", "gain_y", "cross_xy", "cross_yx", "cross_xz", "cross_yz",
    "cross_zx", "cross_zy", "gain_z", "sag", "bias_x", "bias_y", "drift_x", "drift_y", "tilt2",
    "tilt2b", "tilt3", "tilt3b", "tilt4", "tilt4b", "tilt5", "tilt5b", "tilt6", "tilt6b", "sag4",
    "sag5", "sag6", "psag4", "psag5", "psag6", "sag2", "lash2", "lash3", "te2c1", "te2s1", "te2c2",
    "te2s2", "te3c1", "te3s1", "te3c2", "te3s2", "te4c1", "te4s1", "te4c2", "te4s2", "te5c1",
    "te5s1", "te5c2", "te5s2", "te6c1", "te6s1", "te6c2", "te6s2", "te2c3", "te2s3", "te2c4",
    "te2s4",
];

/// A set of stage-2 parameters by index (bit k = parameter k; 0..=3 are Δθ3..Δθ6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ParamSet(pub u64);

impl ParamSet {
    /// How many parameters a set can name.
    pub const CAPACITY: usize = 64;

    /// Adds parameter `k` (0 = Δθ3). An index past [`CAPACITY`](Self::CAPACITY) names
    /// no parameter and leaves the set as it is.
    pub fn with(self, k: usize) -> Self {
        match u32::try_from(k).ok().and_then(|k| 1u64.checked_shl(k)) {
            Some(bit) => ParamSet(self.0 | bit),
            None => self,
        }
    }

    /// Whether parameter `k` (0 = Δθ3) is in the set.
    pub fn contains(self, k: usize) -> bool {
        u32::try_from(k)
            .ok()
            .and_then(|k| 1u64.checked_shl(k))
            .is_some_and(|bit| self.0 & bit != 0)
    }

    /// Robot joint numbers (3..=6) in the set.
    pub fn joints(self) -> impl Iterator<Item = u8> {
        (0..4u8)
            .filter(move |&k| self.contains(usize::from(k)))
            .map(|k| k + 3)
    }
}

impl fmt::Display for ParamSet {
    /// `j4+j6`, `j3+sag`: short enough for the pendant's display.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for k in (0..Self::CAPACITY).filter(|&k| self.contains(k)) {
            if !first {
                f.write_str("+")?;
            }
            match PARAM_NAMES.get(k) {
                Some(name) => f.write_str(name)?,
                None => write!(f, "p{k}")?,
            }
            first = false;
        }
        Ok(())
    }
}

/// Why stage 2 gave no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
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
    /// One pose's residual stands far out of the others': the robot did not reach that
    /// pose (a stop, a wrong point, a program line skipped) or the pendant was touched
    /// there.
    PoseNotReached {
        /// The pose (0-based, in the order fitted).
        pose: usize,
        /// Its residual (deg, the larger of x and y).
        residual_deg: f32,
        /// The others' RMS (deg).
        others_rms_deg: f32,
    },
    /// The readings jump between two parts of the session as a turn of the pendant on
    /// the flange would: it was knocked (or the bracket slipped) before this pose.
    PendantMoved {
        /// The first pose after the move (0-based, in the order fitted).
        from_pose: usize,
        /// The size of the jump (deg).
        step_deg: f32,
    },
    /// A pose the plan visits again reads differently the second time: the pendant
    /// moved on the flange between the two visits (knocked, or the bracket creeping).
    RevisitDisagrees {
        /// The pose's first visit (0-based, in the order fitted).
        pose: usize,
        /// Its later visit (0-based, in the order fitted).
        revisit: usize,
        /// How far apart the two read (deg).
        difference_deg: f32,
        /// The most a tight bracket on a real arm shows (deg).
        limit_deg: f32,
    },
    /// The readings drift steadily over stage 2 as a pendant turning slowly on the flange
    /// would: the bracket creeps (a clamp not quite tight).
    PendantCreeping {
        /// How far the readings drifted from the first pose to the last (deg).
        drift_deg: f32,
    },
    /// The two captures of a pose (approached from either side) disagree by more than
    /// the gears' lost motion and the sensor's noise explain: the flange bracket moves.
    CapturesDisagree {
        /// RMS of the differences (deg).
        rms_deg: f32,
        /// The most a tight bracket on a real arm shows (deg).
        limit_deg: f32,
        /// The pose whose captures differ most (0-based, in the order fitted).
        worst_pose: usize,
    },
    /// A fitted term is far beyond what a real arm has (a joint axis tenths of a
    /// degree off where the drawing has it): the profile does not describe this robot.
    ImplausibleGeometry {
        /// The term.
        params: ParamSet,
        /// Its fitted value (deg).
        value_deg: f32,
        /// The most a real arm has (deg).
        limit_deg: f32,
    },
    /// The residuals are far above what a still robot, a tight bracket and the right
    /// model leave.
    ResidualTooLarge {
        /// Residual RMS (deg).
        rms_deg: f32,
        /// The limit (deg).
        limit_deg: f32,
        /// The pose with the largest residual (0-based).
        worst_pose: usize,
    },
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
                "rank-deficient pose set: the zeros of {params} cannot be separated by these \
                 poses; vary those joints, or, if the poses were planned for this robot, check \
                 its profile"
            ),
            FitError::IllConditioned {
                condition_number,
                limit,
                params,
            } => write!(
                f,
                "ill-conditioned pose set (condition number {} > {}): {params} barely separable; vary those joints more, or, if the poses were planned for this robot, check its profile",
                Fixed::new(f64::from(condition_number), 0),
                Fixed::new(f64::from(limit), 0)
            ),
            FitError::NoConvergence { iterations } => write!(
                f,
                "no convergence after {iterations} iterations: the readings do not fit this \
                 robot's model; check the profile (model, joint directions) and the convention"
            ),
            FitError::NonFiniteResult => f.write_str("the fit produced a non-finite number"),
            FitError::PoseNotReached {
                pose,
                residual_deg,
                others_rms_deg,
            } => write!(
                f,
                "pose {}: its reading is {} deg off the model while the others are {} deg RMS: \
                 the robot did not reach this pose (stopped, skipped or wrong point) or the \
                 pendant was touched there; check the program and repeat the session",
                pose + 1,
                Fixed::new(f64::from(residual_deg), 4),
                Fixed::new(f64::from(others_rms_deg), 4)
            ),
            FitError::PendantMoved { from_pose, step_deg } => write!(
                f,
                "the pendant moved on the flange before pose {}: the readings after it jump \
                 by {} deg; tighten the flange bracket and repeat stage 2",
                from_pose + 1,
                Fixed::new(f64::from(step_deg), 4)
            ),
            FitError::RevisitDisagrees {
                pose,
                revisit,
                difference_deg,
                limit_deg,
            } => write!(
                f,
                "the pendant moved on the flange between pose {} and its revisit (pose {}): \
                 the same pose reads {} deg apart (limit {} deg); tighten the flange \
                 bracket's clamp and repeat stage 2",
                pose + 1,
                revisit + 1,
                Fixed::new(f64::from(difference_deg), 4),
                Fixed::new(f64::from(limit_deg), 4)
            ),
            FitError::PendantCreeping { drift_deg } => write!(
                f,
                "the pendant crept on the flange: the readings drift steadily by {} deg from \
                 the first pose to the last (a revisited pose no longer reads as it did); \
                 tighten the flange bracket's clamp and repeat stage 2",
                Fixed::new(f64::from(drift_deg), 4)
            ),
            FitError::CapturesDisagree {
                rms_deg,
                limit_deg,
                worst_pose,
            } => write!(
                f,
                "loose flange bracket: the two captures of a pose differ by {} deg RMS, more \
                 than the {} deg a tight bracket on a real arm shows (worst at pose {}); \
                 tighten it and repeat stage 2",
                Fixed::new(f64::from(rms_deg), 4),
                Fixed::new(f64::from(limit_deg), 4),
                worst_pose + 1
            ),
            FitError::ImplausibleGeometry {
                params,
                value_deg,
                limit_deg,
            } => write!(
                f,
                "wrong robot profile: fitting the readings needs {params} = {} deg, beyond the \
                 {} deg any real arm of this model has; check the profile and the robot's \
                 joint directions",
                Fixed::new(f64::from(value_deg), 3),
                Fixed::new(f64::from(limit_deg), 3)
            ),
            FitError::ResidualTooLarge {
                rms_deg,
                limit_deg,
                worst_pose,
            } => write!(
                f,
                "residuals of {} deg RMS exceed the {} deg a still robot, a tight bracket and \
                 the right robot model leave (worst at pose {}): check the flange bracket is \
                 tight, the robot stood still, and the profile and convention are the robot's",
                Fixed::new(f64::from(rms_deg), 4),
                Fixed::new(f64::from(limit_deg), 4),
                worst_pose + 1
            ),
        }
    }
}

/// Why stage 0 or stage 1 gave no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
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
    /// The two readings cannot separate the tilt, the arm's angle and the bias: the
    /// bracket is not along joint 2, or the turn was not a half turn.
    Unresolvable,
    /// A commanded joint angle is NaN or infinite.
    NonFiniteCommand,
    /// Fewer than two bench readings.
    TooFewHeadings {
        /// Readings taken.
        got: u8,
    },
    /// The readings do not show their headings well enough to find the circle's centre
    /// (turned too little, or a bench so level that the circle is lost in the noise):
    /// the bias would be known far worse than from headings a quarter turn apart.
    HeadingsTooClose {
        /// The bias's variance in units of one reading's noise variance.
        variance_factor: f32,
        /// The largest accepted ([`crate::stage0::HEADINGS_VARIANCE_LIMIT`]).
        limit: f32,
    },
    /// The bench readings do not lie on one circle: the pendant was moved between
    /// headings, not turned on the spot (or knocked, or the bench is not flat).
    NotTurnedOnTheSpot {
        /// The solve's residual RMS per degree of freedom (deg): the figure judged.
        rms_deg: f32,
        /// The limit ([`crate::stage0::BENCH_RESIDUAL_LIMIT`] readings' noise, deg).
        limit_deg: f32,
    },
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
            StageError::Unresolvable => f.write_str(
                "the two readings cannot separate base tilt, joint 2 and bias: is the pendant's x along joint 2, and was the turn 180 deg?",
            ),
            StageError::NonFiniteCommand => {
                f.write_str("a commanded joint angle is not a finite number")
            }
            StageError::TooFewHeadings { got } => write!(
                f,
                "{got} bench reading(s): at least two headings are needed (four by hand)"
            ),
            StageError::HeadingsTooClose {
                variance_factor,
                limit,
            } => write!(
                f,
                "the bench readings do not show their headings (bias variance {} readings' noise, limit {}): turn a quarter turn between readings; tilt a level bench 0.1 deg",
                Fixed::new(f64::from(variance_factor), 1),
                Fixed::new(f64::from(limit), 1)
            ),
            StageError::NotTurnedOnTheSpot { rms_deg, limit_deg } => write!(
                f,
                "the bench readings do not lie on one circle ({} deg RMS, limit {} deg): turn the pendant on the same spot of a flat, steady bench without lifting it, and read it again",
                Fixed::new(f64::from(rms_deg), 4),
                Fixed::new(f64::from(limit_deg), 4)
            ),
        }
    }
}

/// A refusal in a few words for machine-read output (the on-target check): the
/// variant's name, then what it names (`RankDeficient j3+j5`, `ReadingOutOfRange 4 y`).
pub struct Terse<'a, E>(pub &'a E);

impl fmt::Display for Terse<'_, FitError> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            FitError::TooFewPoses { got, min } => write!(f, "TooFewPoses {got} {min}"),
            FitError::NonFiniteJoint { pose } => write!(f, "NonFiniteJoint {pose}"),
            FitError::NonFiniteReading { pose } => write!(f, "NonFiniteReading {pose}"),
            FitError::ReadingOutOfRange { pose, axis, .. } => {
                write!(f, "ReadingOutOfRange {pose} {axis}")
            }
            FitError::RankDeficient { params } => write!(f, "RankDeficient {params}"),
            FitError::IllConditioned { params, .. } => write!(f, "IllConditioned {params}"),
            FitError::NoConvergence { .. } => f.write_str("NoConvergence"),
            FitError::NonFiniteResult => f.write_str("NonFiniteResult"),
            FitError::ResidualTooLarge { worst_pose, .. } => {
                write!(f, "ResidualTooLarge {worst_pose}")
            }
            FitError::PoseNotReached { pose, .. } => write!(f, "PoseNotReached {pose}"),
            FitError::PendantMoved { from_pose, .. } => write!(f, "PendantMoved {from_pose}"),
            FitError::PendantCreeping { .. } => f.write_str("PendantCreeping"),
            FitError::RevisitDisagrees { pose, revisit, .. } => {
                write!(f, "RevisitDisagrees {pose} {revisit}")
            }
            FitError::CapturesDisagree { worst_pose, .. } => {
                write!(f, "CapturesDisagree {worst_pose}")
            }
            FitError::ImplausibleGeometry { params, .. } => {
                write!(f, "ImplausibleGeometry {params}")
            }
        }
    }
}

impl fmt::Display for Terse<'_, StageError> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            StageError::NonFiniteReading => f.write_str("NonFiniteReading"),
            StageError::ReadingOutOfRange { axis, .. } => write!(f, "ReadingOutOfRange {axis}"),
            StageError::InconsistentReading => f.write_str("InconsistentReading"),
            StageError::Unresolvable => f.write_str("Unresolvable"),
            StageError::NonFiniteCommand => f.write_str("NonFiniteCommand"),
            StageError::TooFewHeadings { got } => write!(f, "TooFewHeadings {got}"),
            StageError::HeadingsTooClose { .. } => f.write_str("HeadingsTooClose"),
            StageError::NotTurnedOnTheSpot { .. } => f.write_str("NotTurnedOnTheSpot"),
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

    #[test]
    fn param_set_holds_every_index_up_to_its_capacity() {
        // A u8 shifted by 8 or more lost the bit (or overflowed): every index counts.
        for k in 0..ParamSet::CAPACITY {
            let s = ParamSet::default().with(k);
            assert!(s.contains(k), "{k}");
            assert_eq!(s.0.count_ones(), 1, "{k}");
        }
        let full = ParamSet::default()
            .with(ParamSet::CAPACITY)
            .with(usize::MAX);
        assert_eq!(full, ParamSet::default());
        assert!(!full.contains(ParamSet::CAPACITY));
    }
}
