//! The brackets that hold the pendant on the robot, as calibrated parts.
//!
//! A bracket that seats the pendant turned by ε about joint 2's axis (upper arm) or
//! joint 6's axis (flange) moves that joint's zero by ε, and no reading on the robot can
//! tell: the brackets define the zeros. So each bracket is a part with an ID and a
//! calibration, measured off the robot on a reference (docs/mounting.md, "Calibrating
//! a bracket"):
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
//! on a level reference and is not calibrated here; the budget carries it
//! ([`BRACKET_YAW_TOLERANCE_DEG`]).

use crate::error::StageError;
use crate::model::{rot_x, rot_y, Arm, Convention, Gain, Tilt};
use crate::real::{deg_to_rad, Real};
use crate::stage0::Reversal;
use nalgebra::Vector3;

/// The seat repeatability the bracket designs require: a bracket taken off and clipped
/// on again seats within ±this about each axis (uniform). A design requirement of
/// the brackets in `cad/` (two pins in a press fit, ground seating faces;
/// docs/mounting.md), not a measured figure: a bracket that does not meet it must be
/// reworked, and `zerocal session --seat-repeatability-deg` states another.
pub const SEAT_REPEATABILITY_DEG: f64 = 0.002;

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
    /// When it was calibrated, `YYYYMMDD`.
    pub date: u32,
    /// The sensor's temperature during the calibration (°C).
    pub temperature_c: T,
}

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
        date: u32,
        temperature_c: T,
    ) -> Result<Self, BracketError> {
        check_date(date)?;
        let limit = deg_to_rad(T::lit(MAX_BRACKET_TURN_DEG));
        let plausible = rotation_rad.is_finite()
            && rotation_rad.x_rad.abs() <= limit
            && rotation_rad.y_rad.abs() <= limit
            && uncertainty_rad.is_finite()
            && uncertainty_rad >= T::zero()
            && temperature_c.is_finite();
        if !plausible {
            return Err(BracketError::Implausible);
        }
        Ok(Self {
            id,
            rotation_rad,
            uncertainty_rad,
            date,
            temperature_c,
        })
    }
}

/// A reversal's half difference: the plate's tilt as the first reading saw it (rad).
fn plate_tilt<T: Real>(r: &Reversal<T>) -> T {
    let half = T::lit(0.5);
    let (tx, ty) = (
        (r.first.x_rad - r.second.x_rad) * half,
        (r.first.y_rad - r.second.y_rad) * half,
    );
    (tx * tx + ty * ty).sqrt()
}

/// The pendant's turn in a bracket from the two reversals on the plate (the pendant
/// alone, then in the bracket on its reference), and the standard uncertainty of its
/// x part: the readings' noise (`capture_noise_rad`, one capture's 1σ; the difference
/// of two half-sums has one capture's variance) and each reversal's turn, within
/// ±[`REFERENCE_TURN_TOLERANCE_DEG`] of 180°, times its plate tilt (uniform).
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
    pendant: &Reversal<T>,
    in_bracket: &Reversal<T>,
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
    let half_turn_u = |r: &Reversal<T>| plate_tilt(r) * turn * T::lit(0.5) / T::lit(3.0).sqrt();
    let (u0, u1) = (half_turn_u(pendant), half_turn_u(in_bracket));
    let u = (capture_noise_rad * capture_noise_rad + u0 * u0 + u1 * u1).sqrt();
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

    /// The arm with each calibrated bracket's turn in its mounting: the pendant's frame
    /// is the profile's mounting turned by R_x(a)·R_y(b).
    pub fn apply(&self, arm: &Arm<T>) -> Arm<T> {
        let turn = |c: Option<&BracketCalibration<T>>| {
            c.map(|c| rot_x(c.rotation_rad.x_rad) * rot_y(c.rotation_rad.y_rad))
        };
        let mut out = *arm;
        if let Some(r) = turn(self.upper_arm.as_ref()) {
            out.upper_arm_mount = arm.upper_arm_mount * r;
        }
        if let Some(r) = turn(self.flange.as_ref()) {
            out.flange_mount = arm.flange_mount * r;
        }
        out
    }

    /// [`Brackets::apply`] with each calibration read back through the sensor's gain
    /// and cross-axis terms `gain` (as the session's fit estimated them): the
    /// calibration's reversals read the bracket's turn as `(I + E)·Rᵀẑ`'s horizontal
    /// part, so a 0.5° turn read with 1 % cross-axis error is 0.005° off; this undoes
    /// it to first order (the calibration made with this pendant's chip).
    pub fn apply_with_gain(&self, arm: &Arm<T>, gain: &Gain<T>) -> Arm<T> {
        let corrected = |c: &BracketCalibration<T>| {
            let (a, b) = (c.rotation_rad.x_rad, c.rotation_rad.y_rad);
            // The horizontal part of Rᵀẑ as read, for R = R_x(a)·R_y(b).
            let read = Vector3::new(-(b.sin() * a.cos()), a.sin(), T::zero());
            let e = gain.apply_linear(&read) - read;
            let (ux, uy) = (read.x - e.x, read.y - e.y);
            let a = uy.clamp(-T::one(), T::one()).asin();
            let b = (-ux / a.cos()).clamp(-T::one(), T::one()).asin();
            BracketCalibration {
                rotation_rad: Tilt::new(a, b),
                ..c.clone()
            }
        };
        Brackets {
            upper_arm: self.upper_arm.as_ref().map(corrected),
            flange: self.flange.as_ref().map(corrected),
        }
        .apply(arm)
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
        let pendant = Reversal {
            first: read(&plate, &bias),
            second: read(&(plate * half), &bias),
        };
        for yaw_deg in [0.0, 0.3] {
            let c = deg_to_rad(yaw_deg);
            let bracket = rot_x(a) * rot_y(b) * crate::model::rot_z(c);
            let seated = Reversal {
                first: read(&(plate * bracket), &bias),
                second: read(&(plate * half * bracket), &bias),
            };
            let (rot, u) = calibrate(&pendant, &seated, Convention::Axis, 0.2, 1e-5).unwrap();
            let bound = 1e-6 + 1.05 * (c * b).abs();
            assert!(
                (rot.x_rad - a).abs() < bound
                    && (rot.y_rad - b).abs() < bound + 1.05 * (c * a).abs(),
                "yaw {yaw_deg}: {rot:?}"
            );
            // The plate's 0.07° of tilt and a turn within ±1°: 0.07°·1°/2/√3 in rad each,
            // with the 1e-5 rad of noise.
            assert!(u > 1e-5 && u < 2e-5, "{u}");
        }
    }

    /// A plate tilted 0.2° is refused by name.
    #[test]
    fn a_tilted_plate_is_refused() {
        let bias = Tilt::from_deg(0.5, -0.3);
        let plate = rot_x(deg_to_rad(0.2));
        let half = crate::model::rot_z(core::f64::consts::PI);
        let r = Reversal {
            first: read(&plate, &bias),
            second: read(&(plate * half), &bias),
        };
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
            20261127,
            21.0,
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
