//! The brackets that hold the pendant on the robot, as calibrated parts.
//!
//! A bracket that seats the pendant turned by ε about joint 2's axis (upper arm) or
//! joint 6's axis (flange) moves that joint's zero by ε, and no reading on the robot can
//! tell: the brackets define the zeros. So each bracket is a part with an ID and a
//! calibration, measured off the robot on a reference (docs/bracket-calibration.md):
//!
//! 1. the pendant alone on a surface plate, read, turned half a turn on the spot, read
//!    (stage 0's reversal: the chip's offset in its box);
//! 2. the pendant in the bracket, the bracket on its reference (a block that holds the
//!    bracket's seating faces as the robot's surfaces do, the pendant then level), read,
//!    the reference turned half a turn on the plate, read.
//!
//! Each reversal's half-sum cancels the plate's tilt; their difference is the turn of the
//! pendant in the bracket about the pendant's x and y ([`calibrate`]). The session
//! applies it to the profile's mounting ([`Brackets::apply`]), so what the fit sees is
//! the bracket as it is, and the budget carries what is left: the calibration's
//! uncertainty and the bracket's seat repeatability on the robot
//! ([`SEAT_REPEATABILITY_DEG`]), or, for a bracket never calibrated,
//! [`UNCALIBRATED_BRACKET_DEG`].
//!
//! A turn about the pendant's z (the bracket's yaw) does not change what gravity reads
//! on a level reference: the same two reversals on a sine plate against a fence
//! measure it ([`calibrate_yaw`]), and [`BracketCalibration::turn`] applies it with the
//! tilt. Where it was not measured the budget carries the design's tolerance
//! ([`BRACKET_YAW_TOLERANCE_DEG`]).

use crate::error::StageError;
use crate::model::{rot_x, rot_y, rot_z, Arm, Convention, Gain, Tilt};
use crate::real::{deg_to_rad, Real};
use crate::stage0::BenchTurns;
use nalgebra::{Rotation3, Vector3};

/// The seat repeatability the bracket designs require: a bracket taken off and clipped
/// on again seats within ±this about each axis (uniform). A design requirement of
/// the brackets in `cad/` (ground seating faces, the bracket turned against its pressed
/// dowel; docs/mounting.md, T1), not a measured figure, allocated from the budget: at
/// ±0.002° the FANUC M-20iA's Δθ3 was within 0.005° in 94.5 % of 200 simulated
/// sessions (host-tests `brackets_acceptance`), at ±0.0015° it is above 95 %. A
/// bracket that does not meet it is reworked, or `zerocal session
/// --seat-repeatability-deg` states what it achieved.
pub const SEAT_REPEATABILITY_DEG: f64 = 0.0015;

/// What a bracket never calibrated may be off by, about each axis (± half width,
/// uniform): the largest seat error the design's tolerances allow for a bracket made
/// but not measured (docs/mounting.md). The budget carries it whole, and the report
/// names the bracket.
pub const UNCALIBRATED_BRACKET_DEG: f64 = 0.5;

/// A bracket's yaw, the turn of the pendant about its own z in the bracket (± half
/// width, uniform): gravity does not see it on a level reference, so it is not
/// calibrated. The design's requirement (docs/mounting.md): the pocket locates the box
/// by two pins 60 mm apart whose holes are placed within ±0.025 mm, so the box turns by
/// at most 0.05 mm / 60 mm = 0.048°. It enters Δθ3 as the two yaws' difference times
/// the base's tilt (the budget's bracket-yaw term).
pub const BRACKET_YAW_TOLERANCE_DEG: f64 = 0.05;

/// How far the reference's half turn may be from 180° when turned by hand against no
/// stop (± half width, uniform): it moves a reversal's half-sum by half the turn's
/// error times the plate's tilt (the readings' half difference).
pub const REFERENCE_TURN_TOLERANCE_DEG: f64 = 1.0;

/// The plate a bracket is calibrated on must be level within this (deg, the
/// magnitude of the pendant's reversal half difference): a half turn by hand is off
/// 180° by up to [`REFERENCE_TURN_TOLERANCE_DEG`], which moves a reversal's half-sum by
/// half that times the tilt; at 0.1° that is at most 0.0009°. A surface plate is
/// levelled with its stand's screws and the pendant's own reading.
pub const PLATE_LEVEL_MAX_DEG: f64 = 0.1;

/// The largest turn a calibration accepts about either axis (deg): twice what an
/// uncalibrated bracket of the design may be off, so that a bracket at the edge of
/// its tolerance is still measured, and a reading of something else is refused.
pub const MAX_BRACKET_TURN_DEG: f64 = 2.0 * UNCALIBRATED_BRACKET_DEG;

/// Captures averaged into each of a calibration's four readings: the bracket's turn
/// goes into the zero one to one, so its noise is averaged down by 2 (0.0004° from a
/// capture's 0.0008°); the pendant is on a bench, where the time costs nothing.
pub const CAPTURES_PER_READING: usize = 4;

/// The longest bracket ID (bytes of ASCII).
pub const BRACKET_ID_LEN: usize = 12;

/// A bracket's ID, as engraved on it: 1-12 ASCII letters, digits, `-` or `_`.
pub type BracketId = heapless::String<BRACKET_ID_LEN>;

/// Which bracket.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BracketMount {
    /// On link 2, for stage 1.
    UpperArm,
    /// On the flange, for stage 2.
    Flange,
}

impl BracketMount {
    /// Both, in the order of the session.
    pub const ALL: [BracketMount; 2] = [BracketMount::UpperArm, BracketMount::Flange];

    /// Its name in files and on the screen.
    pub fn name(self) -> &'static str {
        match self {
            BracketMount::UpperArm => "upper-arm",
            BracketMount::Flange => "flange",
        }
    }

    /// The inverse of [`BracketMount::name`].
    pub fn parse(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }
}

/// Checks a bracket ID's spelling and makes it one.
///
/// # Errors
/// [`BracketError::BadId`] for an empty, too long or non-ASCII-word ID.
pub fn bracket_id(s: &str) -> Result<BracketId, BracketError> {
    let ok = !s.is_empty()
        && s.len() <= BRACKET_ID_LEN
        && s.bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_');
    let mut id = BracketId::new();
    if !ok || id.push_str(s).is_err() {
        return Err(BracketError::BadId);
    }
    Ok(id)
}

/// One bracket's calibration.
// No `defmt::Format`: its ID is a heapless `String`, which implements only defmt 0.3's.
#[derive(Clone, Debug, PartialEq)]
pub struct BracketCalibration<T> {
    /// The bracket's ID.
    pub id: BracketId,
    /// The pendant's turn in the bracket: about the pendant's x (the joint's axis: this
    /// is the angle that would go into the zero) and about its y (rad).
    pub rotation_rad: Tilt<T>,
    /// The calibration's standard uncertainty about x (rad).
    pub uncertainty_rad: T,
    /// When it was calibrated, `YYYYMMDD`; `None` for a calibration made on the
    /// pendant, which has no calendar (the desktop stamps the day it reads it out).
    pub date: Option<u32>,
    /// The sensor's temperature during the calibration (°C), if it gave one.
    pub temperature_c: Option<T>,
    /// The bracket's yaw, where measured on the sine plate ([`calibrate_yaw`]).
    pub yaw: Option<BracketYaw<T>>,
}

/// A bracket's yaw: the pendant's turn about its own z in the bracket, measured on a
/// sine plate ([`calibrate_yaw`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BracketYaw<T> {
    /// The turn (rad).
    pub yaw_rad: T,
    /// Its standard uncertainty (rad).
    pub uncertainty_rad: T,
}

/// The sine plate's tilt for the yaw step: at least this (deg), so that the readings'
/// noise is a small angle of it, and at most [`SINE_PLATE_MAX_DEG`] so that the readings
/// stay inside mode 4's ±10°.
pub const SINE_PLATE_MIN_DEG: f64 = 2.0;

/// See [`SINE_PLATE_MIN_DEG`].
pub const SINE_PLATE_MAX_DEG: f64 = 8.0;

/// How far a face laid against the sine plate's fence may turn the pendant or the
/// reference about the vertical (± deg, uniform): the box's long sides and the
/// reference's fence face are held parallel within 0.05 mm over 60 mm (docs/mounting.md,
/// T9), 0.048°.
pub const FENCE_CONTACT_TOLERANCE_DEG: f64 = 0.05;

/// The two brackets of a session, each calibrated or not.
// No `defmt::Format`, as [`BracketCalibration`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Brackets<T> {
    /// The upper-arm bracket's calibration, if it has one.
    pub upper_arm: Option<BracketCalibration<T>>,
    /// The flange bracket's calibration, if it has one.
    pub flange: Option<BracketCalibration<T>>,
}

/// Why a bracket calibration or ID is refused.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BracketError {
    /// An ID that is empty, longer than [`BRACKET_ID_LEN`] or not ASCII letters, digits,
    /// `-` and `_`.
    BadId,
    /// A date that is not a calendar day `YYYYMMDD` (years 2000-2999).
    BadDate,
    /// A calibrated turn beyond [`MAX_BRACKET_TURN_DEG`] (either axis), or a
    /// non-finite or negative uncertainty: not a bracket of the design, or a reading of
    /// something else.
    Implausible,
    /// The plate is tilted more than [`PLATE_LEVEL_MAX_DEG`] (deg, as read).
    PlateNotLevel {
        /// The plate's tilt the reversal read (deg).
        tilt_deg: f32,
    },
    /// The yaw step's reversal read a tilt outside the sine plate's
    /// [`SINE_PLATE_MIN_DEG`]..[`SINE_PLATE_MAX_DEG`] (deg, as read).
    NotOnSinePlate {
        /// The tilt the reversal read (deg).
        tilt_deg: f32,
    },
    /// A reversal the sensor could not have read.
    Reading(StageError),
}

impl core::fmt::Display for BracketError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            BracketError::BadId => write!(
                f,
                "a bracket ID is 1-{BRACKET_ID_LEN} ASCII letters, digits, '-' or '_'"
            ),
            BracketError::BadDate => f.write_str("a calibration date is YYYYMMDD, a real day"),
            BracketError::Implausible => write!(
                f,
                "the bracket turns the pendant by more than {MAX_BRACKET_TURN_DEG} deg, or \
                 its uncertainty is not a number >= 0: check the bracket seats on its \
                 reference and the pendant in the bracket"
            ),
            BracketError::PlateNotLevel { tilt_deg } => write!(
                f,
                "the plate is tilted {tilt_deg:.3} deg, more than {PLATE_LEVEL_MAX_DEG}: level \
                 it (the half turns by hand are not exact) and repeat"
            ),
            BracketError::NotOnSinePlate { tilt_deg } => write!(
                f,
                "the yaw step read a tilt of {tilt_deg:.2} deg: set the sine plate between \
                 {SINE_PLATE_MIN_DEG} and {SINE_PLATE_MAX_DEG} deg and repeat"
            ),
            BracketError::Reading(e) => write!(f, "a reading of the calibration: {e}"),
        }
    }
}

/// Checks a `YYYYMMDD` date.
///
/// # Errors
/// [`BracketError::BadDate`].
pub fn check_date(date: u32) -> Result<u32, BracketError> {
    let (y, m, d) = (date / 10_000, (date / 100) % 100, date % 100);
    let leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    let days = match m {
        2 if leap => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        1..=12 => 31,
        _ => 0,
    };
    if (2000..3000).contains(&y) && (1..=days).contains(&d) {
        Ok(date)
    } else {
        Err(BracketError::BadDate)
    }
}

impl<T: Real> BracketCalibration<T> {
    /// A calibration from its stored values, checked.
    ///
    /// # Errors
    /// A bad date, or a turn or uncertainty no bracket of the design has.
    pub fn new(
        id: BracketId,
        rotation_rad: Tilt<T>,
        uncertainty_rad: T,
        date: Option<u32>,
        temperature_c: Option<T>,
    ) -> Result<Self, BracketError> {
        if let Some(date) = date {
            check_date(date)?;
        }
        let limit = deg_to_rad(T::lit(MAX_BRACKET_TURN_DEG));
        let plausible = rotation_rad.is_finite()
            && rotation_rad.x_rad.abs() <= limit
            && rotation_rad.y_rad.abs() <= limit
            && uncertainty_rad.is_finite()
            && uncertainty_rad >= T::zero()
            && temperature_c.is_none_or(|t| t.is_finite());
        if !plausible {
            return Err(BracketError::Implausible);
        }
        Ok(Self {
            id,
            rotation_rad,
            uncertainty_rad,
            date,
            temperature_c,
            yaw: None,
        })
    }

    /// With the yaw the sine plate measured.
    ///
    /// # Errors
    /// [`BracketError::Implausible`] for a yaw beyond [`MAX_BRACKET_TURN_DEG`] or a
    /// non-finite or negative uncertainty.
    pub fn with_yaw(self, yaw: BracketYaw<T>) -> Result<Self, BracketError> {
        let limit = deg_to_rad(T::lit(MAX_BRACKET_TURN_DEG));
        if !(yaw.yaw_rad.is_finite()
            && yaw.yaw_rad.abs() <= limit
            && yaw.uncertainty_rad.is_finite()
            && yaw.uncertainty_rad >= T::zero())
        {
            return Err(BracketError::Implausible);
        }
        Ok(Self {
            yaw: Some(yaw),
            ..self
        })
    }

    /// The pendant's turn in the bracket, `R_x(a)·R_y(b)·R_z(c)`, with the sensor's
    /// gain and cross-axis terms `gain` undone from the readings (where known) and
    /// the yaw c applied: the level reversals read `Rᵀẑ`'s horizontal part
    /// `R_z(−c)·(−sin b·cos a, sin a)` through `(I + E)`, so both are undone before a and
    /// b are taken from it (without the yaw, a 0.5° yaw and 0.5° tilt leave 0.0044°).
    pub fn turn(&self, gain: Option<&Gain<T>>) -> Rotation3<T> {
        let (a, b) = (self.rotation_rad.x_rad, self.rotation_rad.y_rad);
        let read = Vector3::new(-(b.sin() * a.cos()), a.sin(), T::zero());
        let undone = match gain {
            Some(g) => read - (g.apply_linear(&read) - read),
            None => read,
        };
        let c = self.yaw.map_or(T::zero(), |y| y.yaw_rad);
        let (s, co) = (c.sin(), c.cos());
        let (ux, uy) = (undone.x * co - undone.y * s, undone.x * s + undone.y * co);
        let a = uy.clamp(-T::one(), T::one()).asin();
        let b = (-ux / a.cos()).clamp(-T::one(), T::one()).asin();
        rot_x(a) * rot_y(b) * rot_z(c)
    }
}

/// The up vector a reading saw, with the chip's offset `bias` (stage 0's, in
/// `convention`'s terms) taken out: in the `axis` convention the reading is the
/// direction n of `a = u + o` (`o = (−b_y, b_x, 0)`), and `|u| = 1` fixes the length.
fn up_vector<T: Real>(
    reading: &Tilt<T>,
    bias: &Tilt<T>,
    convention: Convention,
) -> Option<Vector3<T>> {
    match convention {
        Convention::Rpy => convention.up_from_reading(&reading.minus(bias)),
        Convention::Axis => {
            let n = convention.up_from_reading(reading)?;
            let o = Vector3::new(-bias.y_rad, bias.x_rad, T::zero());
            let no = n.dot(&o);
            let disc = no * no - o.dot(&o) + T::one();
            (disc >= T::zero()).then(|| n * (no + disc.sqrt()) - o)
        }
    }
}

/// A reversal's half difference as an up-vector difference in the pendant's frame.
fn half_difference<T: Real>(
    r: &BenchTurns<T>,
    bias: &Tilt<T>,
    convention: Convention,
) -> Option<Vector3<T>> {
    let (a, b) = (
        up_vector(&r.readings[0], bias, convention)?,
        up_vector(&r.readings[1], bias, convention)?,
    );
    Some((a - b) * T::lit(0.5))
}

/// A bracket's yaw from two reversals on a sine plate against its fence (the pendant
/// alone, its long side against the fence, turned end for end; then the bracket's
/// reference against the fence, turned end for end): each half difference is the
/// plate's tilt in the pendant's frame, so the second is the first turned by the
/// bracket, `(R_x(a)·R_y(b)·R_z(c))ᵀ`; with a and b from the level step (`tilt_rad`) and
/// the chip's offset `bias` (stage 0's) taken out, c is the angle left. The chip's own
/// turn in its box is in both. Its uncertainty: the readings' noise over the tilt, and
/// the two faces against the fence within ±[`FENCE_CONTACT_TOLERANCE_DEG`].
///
/// # Errors
/// [`BracketError::NotOnSinePlate`] when either reversal's tilt is outside
/// [`SINE_PLATE_MIN_DEG`]..[`SINE_PLATE_MAX_DEG`]; [`BracketError::Implausible`] for a
/// yaw beyond [`MAX_BRACKET_TURN_DEG`] or readings no orientation gives.
pub fn calibrate_yaw<T: Real>(
    pendant: &BenchTurns<T>,
    in_bracket: &BenchTurns<T>,
    tilt_rad: &Tilt<T>,
    bias: &Tilt<T>,
    convention: Convention,
    capture_noise_rad: T,
) -> Result<BracketYaw<T>, BracketError> {
    let (Some(va), Some(vb)) = (
        half_difference(pendant, bias, convention),
        half_difference(in_bracket, bias, convention),
    ) else {
        return Err(BracketError::Implausible);
    };
    let norm = |v: &Vector3<T>| (v.x * v.x + v.y * v.y).sqrt();
    let (na, nb) = (norm(&va), norm(&vb));
    let (lo, hi) = (
        deg_to_rad(T::lit(SINE_PLATE_MIN_DEG)).sin(),
        deg_to_rad(T::lit(SINE_PLATE_MAX_DEG)).sin(),
    );
    for n in [na, nb] {
        if !n.is_finite() || n < lo || n > hi {
            return Err(BracketError::NotOnSinePlate {
                tilt_deg: crate::real::rad_to_deg(n.clamp(-T::one(), T::one()).asin()).to_f64()
                    as f32,
            });
        }
    }
    // The alone pendant's tilt as the bracket's tilted (not yet yawed) frame sees it.
    let w = (rot_x(tilt_rad.x_rad) * rot_y(tilt_rad.y_rad)).inverse() * va;
    let yaw_rad = -(w.x * vb.y - w.y * vb.x).atan2(w.x * vb.x + w.y * vb.y);
    let noise2 = capture_noise_rad * capture_noise_rad / T::lit(CAPTURES_PER_READING as f64);
    // Each half difference's noise across it is σ/√2, its angle's σ/(√2·|t|).
    let fence = deg_to_rad(T::lit(FENCE_CONTACT_TOLERANCE_DEG)) / T::lit(3.0).sqrt();
    let u2 = noise2 / (T::lit(2.0) * na * na)
        + noise2 / (T::lit(2.0) * nb * nb)
        + T::lit(2.0) * fence * fence;
    let yaw = BracketYaw {
        yaw_rad,
        uncertainty_rad: u2.sqrt(),
    };
    if !yaw_rad.is_finite() || yaw_rad.abs() > deg_to_rad(T::lit(MAX_BRACKET_TURN_DEG)) {
        return Err(BracketError::Implausible);
    }
    Ok(yaw)
}

/// The plate's tilt the bench readings show (rad): a reversal's half difference, the
/// circle's radius for headings turned by hand.
fn plate_tilt<T: Real>(r: &BenchTurns<T>) -> T {
    let t = r.tilt_seen_first();
    (t.x_rad * t.x_rad + t.y_rad * t.y_rad).sqrt()
}

/// The pendant's turn in a bracket from the two reversals on the plate (the pendant
/// alone, then in the bracket on its reference), and the standard uncertainty of its
/// x part: the readings' noise (`capture_noise_rad`, one capture's 1σ; each reading
/// averages [`CAPTURES_PER_READING`] captures, and the difference of two half-sums has
/// one reading's variance) and each reversal's turn, within
/// ±[`REFERENCE_TURN_TOLERANCE_DEG`] of 180°, times its plate tilt (uniform), and the
/// bracket's seat on its reference when it was read, within ±[`SEAT_REPEATABILITY_DEG`]
/// (uniform): the calibration holds that seat as part of the bracket's turn, and the
/// session's own seat on the robot comes on top
/// ([`Brackets::standard_uncertainty_rad`]).
///
/// In the `axis` convention each half-sum is the acceleration offset `o = (−b_y, b_x)`
/// the reversal saw; the bracket's turn R adds `Rᵀ·ẑ`'s horizontal part to it, so with
/// R = R_x(a)·R_y(b) the difference is `(sin a, cos a·sin b)` in `(b_x, b_y)`. In the
/// `rpy` convention the difference is the two angles.
///
/// # Errors
/// A reading out of range or not a number ([`BracketError::Reading`]), or a turn no
/// bracket of the design has ([`BracketError::Implausible`]).
pub fn calibrate<T: Real>(
    pendant: &BenchTurns<T>,
    in_bracket: &BenchTurns<T>,
    convention: Convention,
    range_rad: T,
    capture_noise_rad: T,
) -> Result<(Tilt<T>, T), BracketError> {
    let alone = pendant
        .bias(convention, range_rad)
        .map_err(BracketError::Reading)?;
    let seated = in_bracket
        .bias(convention, range_rad)
        .map_err(BracketError::Reading)?;
    let level = deg_to_rad(T::lit(PLATE_LEVEL_MAX_DEG));
    for r in [pendant, in_bracket] {
        let tilt = plate_tilt(r);
        // A tilt that is not a number is refused too.
        if !tilt.is_finite() || tilt > level {
            return Err(BracketError::PlateNotLevel {
                tilt_deg: crate::real::rad_to_deg(tilt).to_f64() as f32,
            });
        }
    }
    let d = seated.minus(&alone);
    let rotation = match convention {
        Convention::Rpy => d,
        Convention::Axis => {
            let a = d.x_rad.clamp(-T::one(), T::one()).asin();
            let b = (d.y_rad / a.cos()).clamp(-T::one(), T::one()).asin();
            Tilt::new(a, b)
        }
    };
    let turn = deg_to_rad(T::lit(REFERENCE_TURN_TOLERANCE_DEG));
    // A half turn by hand moves a reversal's half-sum by half its error times the tilt;
    // headings turned by hand solve their own turns.
    let half_turn_u = |r: &BenchTurns<T>| {
        if r.count == 2 {
            plate_tilt(r) * turn * T::lit(0.5) / T::lit(3.0).sqrt()
        } else {
            T::zero()
        }
    };
    let (u0, u1) = (half_turn_u(pendant), half_turn_u(in_bracket));
    let noise2 = capture_noise_rad * capture_noise_rad / T::lit(CAPTURES_PER_READING as f64);
    // The bracket sat on its reference within its seat repeatability when it was read:
    // the calibration keeps that seat, which no clip-on on the robot repeats.
    let seat = deg_to_rad(T::lit(SEAT_REPEATABILITY_DEG)) / T::lit(3.0).sqrt();
    let u = (noise2 + u0 * u0 + u1 * u1 + seat * seat).sqrt();
    let limit = deg_to_rad(T::lit(MAX_BRACKET_TURN_DEG));
    if !(rotation.is_finite() && rotation.x_rad.abs() <= limit && rotation.y_rad.abs() <= limit) {
        return Err(BracketError::Implausible);
    }
    Ok((rotation, u))
}

impl<T: Real> Brackets<T> {
    /// The calibration of `mount`'s bracket, if any.
    pub fn get(&self, mount: BracketMount) -> Option<&BracketCalibration<T>> {
        match mount {
            BracketMount::UpperArm => self.upper_arm.as_ref(),
            BracketMount::Flange => self.flange.as_ref(),
        }
    }

    /// The arm with each calibrated bracket's turn in its mounting
    /// ([`BracketCalibration::turn`], without the sensor's gain).
    pub fn apply(&self, arm: &Arm<T>) -> Arm<T> {
        self.apply_turns(arm, None)
    }

    /// [`Brackets::apply`] with each calibration read back through the sensor's gain
    /// and cross-axis terms `gain` (as the session's fit estimated them): a 0.5° turn
    /// read with 1 % cross-axis error is 0.005° off; this undoes it to first order (the
    /// calibration made with this pendant's chip).
    pub fn apply_with_gain(&self, arm: &Arm<T>, gain: &Gain<T>) -> Arm<T> {
        self.apply_turns(arm, Some(gain))
    }

    fn apply_turns(&self, arm: &Arm<T>, gain: Option<&Gain<T>>) -> Arm<T> {
        let mut out = *arm;
        if let Some(c) = &self.upper_arm {
            out.upper_arm_mount = arm.upper_arm_mount * c.turn(gain);
        }
        if let Some(c) = &self.flange {
            out.flange_mount = arm.flange_mount * c.turn(gain);
        }
        out
    }

    /// The standard uncertainty of `mount`'s bracket's yaw (rad): the sine plate's
    /// where measured, else the stated tolerance `yaw_tolerance_rad` (± half width,
    /// uniform).
    pub fn yaw_uncertainty_rad(&self, mount: BracketMount, yaw_tolerance_rad: T) -> T {
        match self.get(mount).and_then(|c| c.yaw) {
            Some(y) => y.uncertainty_rad,
            None => yaw_tolerance_rad.abs() / T::lit(3.0).sqrt(),
        }
    }

    /// What `mount`'s bracket leaves in the zero it defines, one standard uncertainty
    /// (rad): a calibrated bracket its calibration's uncertainty and the seat's
    /// repeatability (uniform within ±`seat_repeatability_rad`); an uncalibrated one
    /// [`UNCALIBRATED_BRACKET_DEG`] (uniform). Never 0.
    pub fn standard_uncertainty_rad(&self, mount: BracketMount, seat_repeatability_rad: T) -> T {
        let sqrt3 = T::lit(3.0).sqrt();
        match self.get(mount) {
            Some(c) => {
                let seat = seat_repeatability_rad.abs() / sqrt3;
                (c.uncertainty_rad * c.uncertainty_rad + seat * seat).sqrt()
            }
            None => deg_to_rad(T::lit(UNCALIBRATED_BRACKET_DEG)) / sqrt3,
        }
    }

    /// The brackets without a calibration, in the session's order.
    pub fn uncalibrated(&self) -> impl Iterator<Item = BracketMount> + '_ {
        BracketMount::ALL
            .into_iter()
            .filter(|m| self.get(*m).is_none())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{up_in_sensor, Convention, SensorModel};
    use nalgebra::Rotation3;

    fn read(r: &Rotation3<f64>, bias: &Tilt<f64>) -> Tilt<f64> {
        SensorModel::new(Convention::Axis, *bias)
            .read_up(&up_in_sensor(r), bias)
            .reading
    }

    /// A bracket turned by known angles, calibrated on a plate tilted 0.07° with a chip
    /// offset of 0.58°: without yaw the reversals give the turn back to 1e-6 rad (an
    /// exact half turn, no noise: the method, not the sensor); a yaw c, which gravity
    /// cannot see, moves the x part by about c·b, the second order the budget's
    /// bracket-yaw term carries.
    #[test]
    fn calibration_returns_the_brackets_turn() {
        let bias = Tilt::from_deg(0.5, -0.3);
        let plate = rot_x(deg_to_rad(0.06)) * rot_y(deg_to_rad(-0.04)) * crate::model::rot_z(0.7);
        let half = crate::model::rot_z(core::f64::consts::PI);
        let (a, b) = (deg_to_rad(0.41), deg_to_rad(-0.27));
        let pendant = BenchTurns::half_turn(read(&plate, &bias), read(&(plate * half), &bias));
        for yaw_deg in [0.0, 0.3] {
            let c = deg_to_rad(yaw_deg);
            let bracket = rot_x(a) * rot_y(b) * crate::model::rot_z(c);
            let seated = BenchTurns::half_turn(
                read(&(plate * bracket), &bias),
                read(&(plate * half * bracket), &bias),
            );
            let (rot, u) = calibrate(&pendant, &seated, Convention::Axis, 0.2, 1e-5).unwrap();
            let bound = 1e-6 + 1.05 * (c * b).abs();
            assert!(
                (rot.x_rad - a).abs() < bound
                    && (rot.y_rad - b).abs() < bound + 1.05 * (c * a).abs(),
                "yaw {yaw_deg}: {rot:?}"
            );
            // The bracket's seat on its reference, ±SEAT_REPEATABILITY_DEG uniform
            // (1.51e-5 rad), and the rest: the plate's 0.07° of tilt and a turn within
            // ±1°, 0.07°·1°/2/√3 in rad each, with the 1e-5 rad of a capture's noise
            // halved by four captures a reading.
            let seat = deg_to_rad(SEAT_REPEATABILITY_DEG) / 3f64.sqrt();
            assert!((seat - 1.512e-5).abs() < 1e-8, "{seat}");
            let rest = (u * u - seat * seat).sqrt();
            assert!(rest > 5e-6 && rest < 1.5e-5, "{u} {rest}");
        }
    }

    /// A bracket turned R_x(a)·R_y(b)·R_z(c): the level reversals and the sine plate's
    /// (5°, against its fence) give back its whole turn, yaw included, to 2e-6 rad in
    /// every entry of the rotation (an exact turn, no noise: the method).
    #[test]
    fn the_sine_plate_gives_the_yaw_and_the_whole_turn() {
        let bias = Tilt::from_deg(0.5, -0.3);
        let half = crate::model::rot_z(core::f64::consts::PI);
        let level = rot_x(deg_to_rad(0.05)) * crate::model::rot_z(0.3);
        let sine = rot_x(deg_to_rad(5.0)) * crate::model::rot_z(0.0);
        let bracket = rot_x(deg_to_rad(0.45))
            * rot_y(deg_to_rad(-0.4))
            * crate::model::rot_z(deg_to_rad(0.5));
        let reversals = |plate: &Rotation3<f64>| {
            (
                BenchTurns::half_turn(read(plate, &bias), read(&(plate * half), &bias)),
                BenchTurns::half_turn(
                    read(&(plate * bracket), &bias),
                    read(&(plate * half * bracket), &bias),
                ),
            )
        };
        let (alone, seated) = reversals(&level);
        let (rot, u) = calibrate(&alone, &seated, Convention::Axis, 0.2, 1e-5).unwrap();
        let (alone, seated) = reversals(&sine);
        let yaw = calibrate_yaw(&alone, &seated, &rot, &bias, Convention::Axis, 1e-5).unwrap();
        assert!((yaw.yaw_rad - deg_to_rad(0.5)).abs() < 2e-6, "{yaw:?}");
        // The fence's two contacts dominate: 0.05°·√(2/3) = 0.041°.
        assert!(
            (yaw.uncertainty_rad.to_degrees() - 0.0408).abs() < 0.001,
            "{yaw:?}"
        );
        let cal = BracketCalibration::new(
            bracket_id("F-2").unwrap(),
            rot,
            u,
            Some(20261127),
            Some(21.0),
        )
        .unwrap()
        .with_yaw(yaw)
        .unwrap();
        let turn = cal.turn(None);
        let worst = (turn.matrix() - bracket.matrix()).abs().max();
        assert!(worst < 2e-6, "{worst}");
        // Without the yaw the turn about x is off by about c·b.
        let without = BracketCalibration { yaw: None, ..cal };
        let off = (without.turn(None).matrix() - bracket.matrix()).abs().max();
        assert!(off > 5e-3, "{off}");
    }

    /// The yaw step refuses a plate that is not tilted as a sine plate is.
    #[test]
    fn the_yaw_step_needs_the_sine_plate() {
        let bias = Tilt::from_deg(0.5, -0.3);
        let half = crate::model::rot_z(core::f64::consts::PI);
        let flat = rot_x(deg_to_rad(0.5));
        let r = BenchTurns::half_turn(read(&flat, &bias), read(&(flat * half), &bias));
        let e = calibrate_yaw(&r, &r, &Tilt::default(), &bias, Convention::Axis, 1e-5).unwrap_err();
        assert!(
            matches!(e, BracketError::NotOnSinePlate { tilt_deg } if (tilt_deg - 0.5).abs() < 0.01),
            "{e:?}"
        );
    }

    /// A plate tilted 0.2° is refused by name.
    #[test]
    fn a_tilted_plate_is_refused() {
        let bias = Tilt::from_deg(0.5, -0.3);
        let plate = rot_x(deg_to_rad(0.2));
        let half = crate::model::rot_z(core::f64::consts::PI);
        let r = BenchTurns::half_turn(read(&plate, &bias), read(&(plate * half), &bias));
        let e = calibrate(&r, &r, Convention::Axis, 0.2, 1e-5).unwrap_err();
        assert!(
            matches!(e, BracketError::PlateNotLevel { tilt_deg } if (tilt_deg - 0.2).abs() < 0.01),
            "{e:?}"
        );
    }

    #[test]
    fn ids_and_dates_are_checked() {
        assert!(bracket_id("U-017").is_ok());
        assert_eq!(bracket_id(""), Err(BracketError::BadId));
        assert_eq!(bracket_id("A B"), Err(BracketError::BadId));
        assert_eq!(bracket_id("ABCDEFGHIJKLM"), Err(BracketError::BadId));
        assert_eq!(check_date(20261127), Ok(20261127));
        assert_eq!(check_date(20240229), Ok(20240229));
        assert_eq!(check_date(20250229), Err(BracketError::BadDate));
        assert_eq!(check_date(20261301), Err(BracketError::BadDate));
        assert_eq!(check_date(19991231), Err(BracketError::BadDate));
    }

    /// Never 0: a calibrated bracket carries its seat, an uncalibrated one the design's
    /// ±0.5° (0.289° at 1σ).
    #[test]
    fn the_bracket_term_is_never_zero() {
        let none: Brackets<f64> = Brackets::default();
        let u = none.standard_uncertainty_rad(BracketMount::Flange, 0.0);
        assert!((u.to_degrees() - 0.5 / 3f64.sqrt()).abs() < 1e-12);
        let cal = BracketCalibration::new(
            bracket_id("F-1").unwrap(),
            Tilt::from_deg(0.1, 0.0),
            0.0,
            Some(20261127),
            Some(21.0),
        )
        .unwrap();
        let some = Brackets {
            upper_arm: None,
            flange: Some(cal),
        };
        let seat = deg_to_rad(SEAT_REPEATABILITY_DEG);
        let u = some.standard_uncertainty_rad(BracketMount::Flange, seat);
        assert!((u - seat / 3f64.sqrt()).abs() < 1e-15 && u > 0.0);
        assert_eq!(
            some.uncalibrated().collect::<Vec<_>>(),
            vec![BracketMount::UpperArm]
        );
    }
}
