//! What the pendant keeps in flash so that a reset or power cut at any moment loses
//! nothing: each change of the session is one small record under a fixed key, written
//! before the change is shown. Sequential-storage's map keeps the newest value per key,
//! so "undo" overwrites a count rather than deleting (the STM32F4 flash cannot delete).
//!
//! Encoding: a format byte, then little-endian fields; every angle as an `f64` of
//! radians (exact for the pendant's `f32`). Format 3 (the two-sided procedure) keeps every
//! capture of stages 0 and 1 and of the closing reversal with its temperature, and two
//! stage-2 captures per plan pose (each under the index of its approach); format 4 adds
//! the profile's link masses and bracket calibrations (and the head's flag saying
//! whether masses are stored). Formats 1-3 are refused as `WrongFormat` and the pendant
//! starts afresh.

use super::profile::{MAX_MASS_KG, MAX_POSITION_M};
use super::{Capture, Phase, ReadingSlot, READING_SLOTS};
use crate::log::{MAX_READING_DEG, TEMPERATURE_RANGE_C};
use zerocal_core::bracket::{
    bracket_id, BracketCalibration, BracketMount, BracketYaw, BRACKET_ID_LEN,
};
use zerocal_core::capture::{CaptureIndex, MAX_CAPTURES};
use zerocal_core::model::{Convention, JointAxis, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::MAX_POSES;
use zerocal_core::real::Real;
use zerocal_core::stage2::PoseReading;

/// Largest encoded record (bytes): the last result (format, ten angles); a capture
/// (format, slot, index, six joints, two readings, a flag and a temperature) is 76.
pub const MAX_RECORD_LEN: usize = 1 + 8 * 10;

/// The record format this build writes and reads (the first byte of every value). A
/// store holding another format is reset by the pendant, never misread.
pub const FORMAT: u8 = 4;

/// One stored fact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Record<T> {
    /// The sensor bias from the last stage-0 reversal (kept across sessions).
    Bias(Tilt<T>),
    /// Where the session stands.
    Progress {
        /// Phase.
        phase: Phase,
        /// Stage 1: the approach of the next capture (0 from below, 1 from above);
        /// stage 2: the index of the next capture in the plan's list (two a pose).
        cursor: u8,
        /// Valid stage-2 captures (slots 0..captures).
        captures: u8,
        /// Whether stage 0 was skipped this session.
        stage0_skipped: bool,
        /// Whether the closing reversal was skipped this session.
        closing_skipped: bool,
    },
    /// A capture of stage 0, stage 1 or the closing reversal.
    Reading {
        /// Which one.
        slot: ReadingSlot,
        /// The window's mean reading and temperature.
        capture: Capture<T>,
    },
    /// A stage-2 capture.
    Capture {
        /// Slot (capture order).
        slot: u8,
        /// Which capture: stored as its place in capture order
        /// ([`CaptureIndex::sequence`]).
        index: CaptureIndex,
        /// The commanded joints, the averaged reading and the temperature.
        pose: PoseReading<T>,
    },
    /// Number of poses in the plan.
    PlanLen(u8),
    /// One plan pose.
    PlanPose {
        /// Index in the plan.
        index: u8,
        /// Joint targets θ1..θ6 (rad).
        joints_rad: [T; JOINTS],
    },
    /// The robot profile's head, written last of its parts: the parts are the profile
    /// only when all carry its `generation`.
    ProfileHead {
        /// Which `profile set` wrote it.
        generation: u8,
        /// The profile's name, UTF-8, `name_len` bytes.
        name: [u8; 32],
        /// Bytes of `name` used.
        name_len: u8,
        /// The sensor convention.
        convention: Convention,
        /// Joints 1 and 2 at stage 1 (rad).
        stage1_rad: [T; 2],
        /// The controller's J3 is θ3 − θ2.
        j3_minus_j2: bool,
        /// The profile has link masses (its [`Record::ProfileMass`] parts); else the
        /// fit has no sag term.
        masses: bool,
    },
    /// A joint's frame (parts 0-5) or the flange's (part 6).
    ProfilePlacement {
        /// As the head's.
        generation: u8,
        /// Which.
        part: u8,
        /// The joint's axis (`JointAxis` code; 0 for the flange).
        axis: u8,
        /// Orientation, a unit quaternion `w,x,y,z`.
        rotation: [T; 4],
        /// Origin (m).
        translation_m: [T; 3],
    },
    /// A bracket's orientation: the upper arm's or the flange's.
    ProfileMount {
        /// As the head's.
        generation: u8,
        /// The flange bracket (else the upper arm's).
        flange: bool,
        /// A unit quaternion `w,x,y,z`.
        rotation: [T; 4],
    },
    /// A link's mass (parts 0-5: the link after joint part+1) or the pendant's on the
    /// flange (part 6), stored only when the head says the profile has masses.
    ProfileMass {
        /// As the head's.
        generation: u8,
        /// Which.
        part: u8,
        /// The mass (kg, or the profile's common unit), at least 0.
        kg: T,
        /// Its centre of mass in that joint's frame (the flange's for the pendant, m).
        com_m: [T; 3],
    },
    /// A bracket's calibration: the upper arm's or the flange's, or that it has none.
    ProfileBracket {
        /// As the head's.
        generation: u8,
        /// The flange bracket (else the upper arm's).
        flange: bool,
        /// Its calibration, if it has one.
        calibration: Option<StoredBracket<T>>,
    },
    /// How the controller shows the joints.
    ProfileDisplay {
        /// As the head's.
        generation: u8,
        /// Names, UTF-8, zero-padded.
        names: [[u8; 3]; JOINTS],
        /// +1 or −1 each.
        sign: [i8; JOINTS],
        /// Shown at the model's zero (deg).
        zero_deg: [T; JOINTS],
    },
    /// A bracket's calibration made on the pendant (`crate::bracket_cal`), the last
    /// kept for its mount. No date: the pendant has no calendar; the desktop stamps
    /// the day it reads the calibration out.
    BracketCalibration {
        /// Which bracket.
        mount: BracketMount,
        /// Its ID, ASCII, `id_len` bytes.
        id: [u8; BRACKET_ID_LEN],
        /// Bytes of `id` used.
        id_len: u8,
        /// The pendant's turn in the bracket about its x and y (rad).
        rotation_rad: Tilt<T>,
        /// The calibration's standard uncertainty (rad).
        uncertainty_rad: T,
        /// The bracket's yaw, the sine plate's (rad).
        yaw_rad: T,
        /// Its standard uncertainty (rad).
        yaw_uncertainty_rad: T,
        /// The mean temperature of the readings (°C), if the sensor gave one.
        temperature_c: Option<T>,
    },
    /// The last completed result.
    LastResult {
        /// Δθ3..Δθ6 (rad).
        offsets_rad: [T; WRIST_JOINTS],
        /// Their 1σ (rad).
        sigma_rad: [T; WRIST_JOINTS],
        /// Δθ2 (rad), if stage 1 ran.
        delta_theta2_rad: T,
        /// Residual RMS (rad).
        residual_rms_rad: T,
    },
}

/// A bracket calibration as a record holds it: [`BracketCalibration`]'s fields, the ID
/// as bytes (a record is `Copy`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StoredBracket<T> {
    /// The ID's bytes, `id_len` of them used.
    pub id: [u8; BRACKET_ID_LEN],
    /// Bytes of `id` used.
    pub id_len: u8,
    /// The pendant's turn in the bracket about its x and y (rad).
    pub rotation_rad: [T; 2],
    /// The calibration's standard uncertainty (rad).
    pub uncertainty_rad: T,
    /// `YYYYMMDD`.
    pub date: u32,
    /// The sensor's temperature during the calibration (°C).
    pub temperature_c: T,
    /// The yaw and its standard uncertainty (rad), where the sine plate measured it.
    pub yaw_rad: Option<[T; 2]>,
}

impl<T: Real> StoredBracket<T> {
    /// A calibration's fields.
    pub fn of(c: &BracketCalibration<T>) -> Self {
        let mut id = [0_u8; BRACKET_ID_LEN];
        let bytes = c.id.as_bytes();
        // A BracketId holds at most BRACKET_ID_LEN bytes.
        id[..bytes.len()].copy_from_slice(bytes);
        StoredBracket {
            id,
            id_len: bytes.len() as u8,
            rotation_rad: [c.rotation_rad.x_rad, c.rotation_rad.y_rad],
            uncertainty_rad: c.uncertainty_rad,
            date: c.date,
            temperature_c: c.temperature_c,
            yaw_rad: c.yaw.map(|y| [y.yaw_rad, y.uncertainty_rad]),
        }
    }

    /// The calibration, checked as core checks one ([`bracket_id`],
    /// [`BracketCalibration::new`]) and as a profile line takes one (an uncertainty
    /// within [`MAX_READING_DEG`], a temperature within [`TEMPERATURE_RANGE_C`]);
    /// `None` for fields no calibration has.
    pub fn calibration(&self) -> Option<BracketCalibration<T>> {
        let u_deg = self.uncertainty_rad.to_f64().to_degrees();
        let t = self.temperature_c.to_f64();
        if !(u_deg <= MAX_READING_DEG
            && (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(&t))
        {
            return None;
        }
        let id = self.id.get(..usize::from(self.id_len))?;
        let id = bracket_id(core::str::from_utf8(id).ok()?).ok()?;
        let c = BracketCalibration::new(
            id,
            Tilt::new(self.rotation_rad[0], self.rotation_rad[1]),
            self.uncertainty_rad,
            self.date,
            self.temperature_c,
        )
        .ok()?;
        match self.yaw_rad {
            Some([yaw_rad, uncertainty_rad]) => c
                .with_yaw(BracketYaw {
                    yaw_rad,
                    uncertainty_rad,
                })
                .ok(),
            None => Some(c),
        }
    }
}

/// Why a stored record could not be read back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RecordError {
    /// The key is not one of ours.
    UnknownKey(u16),
    /// Written by another format version.
    WrongFormat(u8),
    /// Shorter than its kind needs.
    Truncated,
    /// A field is out of its range (phase code, index, an angle not finite in the
    /// reader's float).
    BadField,
    /// The buffer given to `encode` is too small.
    BufferTooSmall,
}

/// Keys: fixed ones, then a range for the readings of stages 0-1 and the closing
/// reversal, one for capture slots and one for plan poses.
pub mod key {
    /// [`super::Record::Bias`].
    pub const BIAS: u16 = 1;
    /// [`super::Record::Progress`].
    pub const PROGRESS: u16 = 2;
    /// [`super::Record::LastResult`].
    pub const LAST_RESULT: u16 = 6;
    /// [`super::Record::PlanLen`].
    pub const PLAN_LEN: u16 = 7;
    /// [`super::Record::Reading`] of slot s is `READING + s`.
    pub const READING: u16 = 0x10;
    /// [`super::Record::Capture`] of slot s is `CAPTURE + s`.
    pub const CAPTURE: u16 = 0x100;
    /// [`super::Record::PlanPose`] of index i is `PLAN_POSE + i`.
    pub const PLAN_POSE: u16 = 0x200;
    /// [`super::Record::ProfileHead`].
    pub const PROFILE_HEAD: u16 = 0x20;
    /// [`super::Record::ProfilePlacement`] of part p is `PROFILE_PLACEMENT + p`.
    pub const PROFILE_PLACEMENT: u16 = 0x21;
    /// [`super::Record::ProfileMount`]: the upper arm's, then the flange's.
    pub const PROFILE_MOUNT: u16 = 0x28;
    /// [`super::Record::ProfileDisplay`].
    pub const PROFILE_DISPLAY: u16 = 0x2A;
    /// [`super::Record::ProfileMass`] of part p is `PROFILE_MASS + p`.
    pub const PROFILE_MASS: u16 = 0x2B;
    /// [`super::Record::ProfileBracket`]: the upper arm's, then the flange's.
    pub const PROFILE_BRACKET: u16 = 0x32;
    /// [`super::Record::BracketCalibration`] of the upper arm's bracket; the flange's
    /// is the next.
    pub const BRACKET_CALIBRATION: u16 = 0x40;
}

/// The stored bracket calibrations: one a mount.
const BRACKET_KEYS: usize = BracketMount::ALL.len();

/// The storage code of a bracket's mount (its place in [`BracketMount::ALL`]).
fn mount_code(m: BracketMount) -> u8 {
    match m {
        BracketMount::UpperArm => 0,
        BracketMount::Flange => 1,
    }
}

/// Placements of a profile: six joints and the flange.
pub const PROFILE_PLACEMENTS: usize = 7;

/// Masses of a profile: six links and the pendant.
pub const PROFILE_MASSES: usize = 7;

/// The profile's keys (from [`key::PROFILE_HEAD`] on): head, placements, two mounts,
/// display, masses, two brackets.
pub const PROFILE_KEYS: usize = 1 + PROFILE_PLACEMENTS + 2 + 1 + PROFILE_MASSES + 2;

/// The fixed keys, in the order a restore reads them.
const FIXED_KEYS: [u16; 4] = [key::BIAS, key::PROGRESS, key::LAST_RESULT, key::PLAN_LEN];

fn profile_key(k: u16) -> Option<usize> {
    (key::PROFILE_HEAD..key::PROFILE_HEAD + PROFILE_KEYS as u16)
        .contains(&k)
        .then(|| usize::from(k - key::PROFILE_HEAD))
}

/// How many keys the procedure uses: the fixed ones, the readings, a capture slot per
/// capture, a plan pose per plan pose and the robot profile's parts.
pub const STORED_KEYS: usize =
    FIXED_KEYS.len() + READING_SLOTS + MAX_CAPTURES + MAX_POSES + PROFILE_KEYS + BRACKET_KEYS;

/// Every key a restore may need, in the order to read them.
pub fn all_keys() -> impl Iterator<Item = u16> {
    FIXED_KEYS
        .into_iter()
        .chain((0..READING_SLOTS as u16).map(|s| key::READING + s))
        .chain((0..MAX_CAPTURES as u16).map(|s| key::CAPTURE + s))
        .chain((0..MAX_POSES as u16).map(|i| key::PLAN_POSE + i))
        .chain((0..PROFILE_KEYS as u16).map(|i| key::PROFILE_HEAD + i))
        .chain((0..BRACKET_KEYS as u16).map(|i| key::BRACKET_CALIBRATION + i))
}

/// The place of `key` in [`all_keys`] (`0..STORED_KEYS`), if it is one of the
/// procedure's (the profile's parts included): a restore keeps one record per place.
pub fn key_index(k: u16) -> Option<usize> {
    let (captures, poses) = (MAX_CAPTURES as u16, MAX_POSES as u16);
    let fixed = FIXED_KEYS.len();
    if let Some(i) = FIXED_KEYS.iter().position(|f| *f == k) {
        return Some(i);
    }
    if (key::READING..key::READING + READING_SLOTS as u16).contains(&k) {
        return Some(fixed + usize::from(k - key::READING));
    }
    if (key::CAPTURE..key::CAPTURE + captures).contains(&k) {
        return Some(fixed + READING_SLOTS + usize::from(k - key::CAPTURE));
    }
    if (key::PLAN_POSE..key::PLAN_POSE + poses).contains(&k) {
        return Some(fixed + READING_SLOTS + MAX_CAPTURES + usize::from(k - key::PLAN_POSE));
    }
    let profiles = fixed + READING_SLOTS + MAX_CAPTURES + MAX_POSES;
    if let Some(i) = profile_key(k) {
        return Some(profiles + i);
    }
    (key::BRACKET_CALIBRATION..key::BRACKET_CALIBRATION + BRACKET_KEYS as u16)
        .contains(&k)
        .then(|| profiles + PROFILE_KEYS + usize::from(k - key::BRACKET_CALIBRATION))
}

/// The storage code of a joint axis (1-6).
pub fn axis_code(a: JointAxis) -> u8 {
    match a {
        JointAxis::X => 1,
        JointAxis::Y => 2,
        JointAxis::Z => 3,
        JointAxis::NegX => 4,
        JointAxis::NegY => 5,
        JointAxis::NegZ => 6,
    }
}

/// Inverse of [`axis_code`].
pub fn axis_of(code: u8) -> Option<JointAxis> {
    Some(match code {
        1 => JointAxis::X,
        2 => JointAxis::Y,
        3 => JointAxis::Z,
        4 => JointAxis::NegX,
        5 => JointAxis::NegY,
        6 => JointAxis::NegZ,
        _ => return None,
    })
}

struct Writer<'a> {
    buf: &'a mut [u8],
    len: usize,
}

impl Writer<'_> {
    fn put(&mut self, bytes: &[u8]) -> Result<(), RecordError> {
        let end = self.len + bytes.len();
        let dst = self
            .buf
            .get_mut(self.len..end)
            .ok_or(RecordError::BufferTooSmall)?;
        dst.copy_from_slice(bytes);
        self.len = end;
        Ok(())
    }
    fn f<T: Real>(&mut self, v: T) -> Result<(), RecordError> {
        self.put(&v.to_f64().to_le_bytes())
    }
    fn temperature<T: Real>(&mut self, c: Option<T>) -> Result<(), RecordError> {
        match c {
            Some(c) => {
                self.put(&[1])?;
                self.f(c)
            }
            None => self.put(&[0]),
        }
    }
}

struct Reader<'a> {
    buf: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], RecordError> {
        let s = self
            .buf
            .get(self.at..self.at + N)
            .ok_or(RecordError::Truncated)?;
        self.at += N;
        let mut out = [0u8; N];
        out.copy_from_slice(s);
        Ok(out)
    }
    fn u8(&mut self) -> Result<u8, RecordError> {
        Ok(self.take::<1>()?[0])
    }
    fn f<T: Real>(&mut self) -> Result<T, RecordError> {
        let v = f64::from_le_bytes(self.take::<8>()?);
        // Finite in the reader's float too: 1e300 is an f32 infinity.
        let t = T::lit(v);
        if v.is_finite() && t.to_f64().is_finite() {
            Ok(t)
        } else {
            Err(RecordError::BadField)
        }
    }
    fn temperature<T: Real>(&mut self) -> Result<Option<T>, RecordError> {
        match self.u8()? {
            0 => Ok(None),
            1 => Ok(Some(self.f()?)),
            _ => Err(RecordError::BadField),
        }
    }
    fn flag(&mut self) -> Result<bool, RecordError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(RecordError::BadField),
        }
    }
    fn tilt<T: Real>(&mut self) -> Result<Tilt<T>, RecordError> {
        Ok(Tilt::new(self.f()?, self.f()?))
    }
    fn four<T: Real>(&mut self) -> Result<[T; WRIST_JOINTS], RecordError> {
        Ok([self.f()?, self.f()?, self.f()?, self.f()?])
    }
    fn joints<T: Real>(&mut self) -> Result<[T; JOINTS], RecordError> {
        Ok([
            self.f()?,
            self.f()?,
            self.f()?,
            self.f()?,
            self.f()?,
            self.f()?,
        ])
    }
}

impl<T: Real> Record<T> {
    /// The record's key.
    pub fn key(&self) -> u16 {
        match self {
            Record::Bias(_) => key::BIAS,
            Record::Progress { .. } => key::PROGRESS,
            Record::Reading { slot, .. } => key::READING + slot.index() as u16,
            Record::LastResult { .. } => key::LAST_RESULT,
            Record::PlanLen(_) => key::PLAN_LEN,
            Record::Capture { slot, .. } => key::CAPTURE + u16::from(*slot),
            Record::PlanPose { index, .. } => key::PLAN_POSE + u16::from(*index),
            Record::ProfileHead { .. } => key::PROFILE_HEAD,
            Record::ProfilePlacement { part, .. } => key::PROFILE_PLACEMENT + u16::from(*part),
            Record::ProfileMount { flange, .. } => key::PROFILE_MOUNT + u16::from(*flange),
            Record::ProfileDisplay { .. } => key::PROFILE_DISPLAY,
            Record::BracketCalibration { mount, .. } => {
                key::BRACKET_CALIBRATION + u16::from(mount_code(*mount))
            }
            Record::ProfileMass { part, .. } => key::PROFILE_MASS + u16::from(*part),
            Record::ProfileBracket { flange, .. } => key::PROFILE_BRACKET + u16::from(*flange),
        }
    }

    /// Writes the value (not the key) into `buf`; returns its length.
    ///
    /// # Errors
    /// [`RecordError::BufferTooSmall`] if `buf` is shorter than [`MAX_RECORD_LEN`] needs.
    pub fn encode(&self, buf: &mut [u8]) -> Result<usize, RecordError> {
        let mut w = Writer { buf, len: 0 };
        w.put(&[FORMAT])?;
        match *self {
            Record::Bias(t) => {
                w.f(t.x_rad)?;
                w.f(t.y_rad)?;
            }
            Record::Progress {
                phase,
                cursor,
                captures,
                stage0_skipped,
                closing_skipped,
            } => w.put(&[
                phase.code(),
                cursor,
                captures,
                u8::from(stage0_skipped) | u8::from(closing_skipped) << 1,
            ])?,
            Record::Reading { slot, capture } => {
                w.put(&[slot.index() as u8])?;
                w.f(capture.reading.x_rad)?;
                w.f(capture.reading.y_rad)?;
                w.temperature(capture.temperature_c)?;
            }
            Record::Capture { slot, index, pose } => {
                // At most MAX_CAPTURES − 1 (checked when decoded): fits a byte.
                w.put(&[slot, index.sequence() as u8])?;
                for q in pose.joints_rad {
                    w.f(q)?;
                }
                w.f(pose.reading.x_rad)?;
                w.f(pose.reading.y_rad)?;
                w.temperature(pose.temperature_c)?;
            }
            Record::PlanLen(n) => w.put(&[n])?,
            Record::ProfileHead {
                generation,
                name,
                name_len,
                convention,
                stage1_rad,
                j3_minus_j2,
                masses,
            } => {
                w.put(&[generation, name_len])?;
                w.put(&name)?;
                w.put(&[
                    u8::from(convention == Convention::Rpy),
                    u8::from(j3_minus_j2),
                    u8::from(masses),
                ])?;
                for v in stage1_rad {
                    w.f(v)?;
                }
            }
            Record::ProfilePlacement {
                generation,
                part,
                axis,
                rotation,
                translation_m,
            } => {
                w.put(&[generation, part, axis])?;
                for v in rotation.iter().chain(&translation_m) {
                    w.f(*v)?;
                }
            }
            Record::ProfileMount {
                generation,
                flange,
                rotation,
            } => {
                w.put(&[generation, u8::from(flange)])?;
                for v in rotation {
                    w.f(v)?;
                }
            }
            Record::ProfileMass {
                generation,
                part,
                kg,
                com_m,
            } => {
                w.put(&[generation, part])?;
                w.f(kg)?;
                for v in com_m {
                    w.f(v)?;
                }
            }
            Record::ProfileBracket {
                generation,
                flange,
                calibration,
            } => {
                w.put(&[generation, u8::from(flange)])?;
                match calibration {
                    None => w.put(&[0])?,
                    Some(c) => {
                        w.put(&[1, c.id_len])?;
                        w.put(&c.id)?;
                        for v in c.rotation_rad {
                            w.f(v)?;
                        }
                        w.f(c.uncertainty_rad)?;
                        w.put(&c.date.to_le_bytes())?;
                        w.f(c.temperature_c)?;
                        match c.yaw_rad {
                            None => w.put(&[0])?,
                            Some([yaw, u]) => {
                                w.put(&[1])?;
                                w.f(yaw)?;
                                w.f(u)?;
                            }
                        }
                    }
                }
            }
            Record::ProfileDisplay {
                generation,
                names,
                sign,
                zero_deg,
            } => {
                w.put(&[generation])?;
                for n in names {
                    w.put(&n)?;
                }
                w.put(&sign.map(|s| s as u8))?;
                for v in zero_deg {
                    w.f(v)?;
                }
            }
            Record::BracketCalibration {
                mount,
                id,
                id_len,
                rotation_rad,
                uncertainty_rad,
                yaw_rad,
                yaw_uncertainty_rad,
                temperature_c,
            } => {
                w.put(&[mount_code(mount), id_len])?;
                w.put(&id)?;
                w.f(rotation_rad.x_rad)?;
                w.f(rotation_rad.y_rad)?;
                w.f(uncertainty_rad)?;
                w.f(yaw_rad)?;
                w.f(yaw_uncertainty_rad)?;
                w.temperature(temperature_c)?;
            }
            Record::PlanPose { index, joints_rad } => {
                w.put(&[index])?;
                for q in joints_rad {
                    w.f(q)?;
                }
            }
            Record::LastResult {
                offsets_rad,
                sigma_rad,
                delta_theta2_rad,
                residual_rms_rad,
            } => {
                for v in offsets_rad.iter().chain(&sigma_rad) {
                    w.f(*v)?;
                }
                w.f(delta_theta2_rad)?;
                w.f(residual_rms_rad)?;
            }
        }
        Ok(w.len)
    }

    /// Reads a record back from its key and value.
    ///
    /// # Errors
    /// An unknown key, another format, a short value or a field out of range.
    pub fn decode(key: u16, value: &[u8]) -> Result<Self, RecordError> {
        let mut r = Reader { buf: value, at: 0 };
        let format = r.u8()?;
        if format != FORMAT {
            return Err(RecordError::WrongFormat(format));
        }
        let reading_range = key::READING..key::READING + READING_SLOTS as u16;
        let slot_range = key::CAPTURE..key::CAPTURE + MAX_CAPTURES as u16;
        let plan_range = key::PLAN_POSE..key::PLAN_POSE + MAX_POSES as u16;
        Ok(match key {
            key::BIAS => Record::Bias(r.tilt()?),
            key::PROGRESS => {
                let phase = Phase::from_code(r.u8()?).ok_or(RecordError::BadField)?;
                let cursor = r.u8()?;
                let captures = r.u8()?;
                let flags = r.u8()?;
                if usize::from(cursor) > MAX_CAPTURES
                    || usize::from(captures) > MAX_CAPTURES
                    || flags > 3
                {
                    return Err(RecordError::BadField);
                }
                Record::Progress {
                    phase,
                    cursor,
                    captures,
                    stage0_skipped: flags & 1 != 0,
                    closing_skipped: flags & 2 != 0,
                }
            }
            k if reading_range.contains(&k) => {
                let slot = ReadingSlot::from_index(usize::from(r.u8()?))
                    .filter(|s| s.index() == usize::from(k - key::READING))
                    .ok_or(RecordError::BadField)?;
                let reading = r.tilt()?;
                Record::Reading {
                    slot,
                    capture: Capture {
                        reading,
                        temperature_c: r.temperature()?,
                    },
                }
            }
            key::PLAN_LEN => {
                let n = r.u8()?;
                if usize::from(n) > MAX_POSES {
                    return Err(RecordError::BadField);
                }
                Record::PlanLen(n)
            }
            key::LAST_RESULT => {
                let offsets_rad = r.four()?;
                let sigma_rad = r.four()?;
                Record::LastResult {
                    offsets_rad,
                    sigma_rad,
                    delta_theta2_rad: r.f()?,
                    residual_rms_rad: r.f()?,
                }
            }
            k if slot_range.contains(&k) => {
                let slot = r.u8()?;
                let index = CaptureIndex::from_sequence(usize::from(r.u8()?));
                let Some(index) = index.filter(|_| u16::from(slot) == k - key::CAPTURE) else {
                    return Err(RecordError::BadField);
                };
                let joints_rad = r.joints()?;
                let reading = r.tilt()?;
                let temperature_c = r.temperature()?;
                Record::Capture {
                    slot,
                    index,
                    pose: PoseReading {
                        joints_rad,
                        reading,
                        temperature_c,
                    },
                }
            }
            k if plan_range.contains(&k) => {
                let index = r.u8()?;
                if u16::from(index) != k - key::PLAN_POSE {
                    return Err(RecordError::BadField);
                }
                Record::PlanPose {
                    index,
                    joints_rad: r.joints()?,
                }
            }
            key::PROFILE_HEAD => {
                let generation = r.u8()?;
                let name_len = r.u8()?;
                let name = r.take::<32>()?;
                let convention = match r.u8()? {
                    0 => Convention::Axis,
                    1 => Convention::Rpy,
                    _ => return Err(RecordError::BadField),
                };
                let j3_minus_j2 = r.flag()?;
                let masses = r.flag()?;
                // A name goes into export and link lines as one word: printable ASCII.
                let ok_name = name
                    .get(..usize::from(name_len))
                    .is_some_and(|n| !n.is_empty() && n.iter().all(u8::is_ascii_graphic));
                if !ok_name {
                    return Err(RecordError::BadField);
                }
                Record::ProfileHead {
                    generation,
                    name,
                    name_len,
                    convention,
                    stage1_rad: [r.f()?, r.f()?],
                    j3_minus_j2,
                    masses,
                }
            }
            k if (key::PROFILE_MASS..key::PROFILE_MASS + PROFILE_MASSES as u16).contains(&k) => {
                let generation = r.u8()?;
                let part = r.u8()?;
                if u16::from(part) != k - key::PROFILE_MASS {
                    return Err(RecordError::BadField);
                }
                // What a profile line takes: a mass from 0 to MAX_MASS_KG, a centre
                // of mass within MAX_POSITION_M.
                let kg: T = r.f()?;
                let com_m: [T; 3] = [r.f()?, r.f()?, r.f()?];
                if !(T::zero()..=T::lit(MAX_MASS_KG)).contains(&kg)
                    || com_m.iter().any(|c| c.abs() > T::lit(MAX_POSITION_M))
                {
                    return Err(RecordError::BadField);
                }
                Record::ProfileMass {
                    generation,
                    part,
                    kg,
                    com_m,
                }
            }
            k if k == key::PROFILE_BRACKET || k == key::PROFILE_BRACKET + 1 => {
                let generation = r.u8()?;
                let flange = r.u8()?;
                if u16::from(flange) != k - key::PROFILE_BRACKET {
                    return Err(RecordError::BadField);
                }
                let calibration = if r.flag()? {
                    let id_len = r.u8()?;
                    let id = r.take::<BRACKET_ID_LEN>()?;
                    let stored = StoredBracket {
                        id,
                        id_len,
                        rotation_rad: [r.f()?, r.f()?],
                        uncertainty_rad: r.f()?,
                        date: u32::from_le_bytes(r.take::<4>()?),
                        temperature_c: r.f()?,
                        yaw_rad: if r.flag()? {
                            Some([r.f()?, r.f()?])
                        } else {
                            None
                        },
                    };
                    // Bytes past the ID zero, and a calibration core would accept.
                    let padded = id
                        .get(usize::from(id_len)..)
                        .is_some_and(|pad| pad.iter().all(|b| *b == 0));
                    if !padded || stored.calibration().is_none() {
                        return Err(RecordError::BadField);
                    }
                    Some(stored)
                } else {
                    None
                };
                Record::ProfileBracket {
                    generation,
                    flange: flange == 1,
                    calibration,
                }
            }
            k if (key::PROFILE_PLACEMENT..key::PROFILE_MOUNT).contains(&k) => {
                let generation = r.u8()?;
                let part = r.u8()?;
                let axis = r.u8()?;
                if u16::from(part) != k - key::PROFILE_PLACEMENT
                    || (usize::from(part) < JOINTS && axis_of(axis).is_none())
                {
                    return Err(RecordError::BadField);
                }
                Record::ProfilePlacement {
                    generation,
                    part,
                    axis,
                    rotation: [r.f()?, r.f()?, r.f()?, r.f()?],
                    translation_m: [r.f()?, r.f()?, r.f()?],
                }
            }
            k if k == key::PROFILE_MOUNT || k == key::PROFILE_MOUNT + 1 => {
                let generation = r.u8()?;
                let flange = r.u8()?;
                if u16::from(flange) != k - key::PROFILE_MOUNT {
                    return Err(RecordError::BadField);
                }
                Record::ProfileMount {
                    generation,
                    flange: flange == 1,
                    rotation: [r.f()?, r.f()?, r.f()?, r.f()?],
                }
            }
            key::PROFILE_DISPLAY => {
                let generation = r.u8()?;
                let mut names = [[0_u8; 3]; JOINTS];
                for n in &mut names {
                    *n = r.take::<3>()?;
                    // Printable ASCII, zero-padded at the end.
                    let len = n.iter().position(|c| *c == 0).unwrap_or(3);
                    let (name, pad) = n.split_at(len);
                    if name.is_empty()
                        || !name.iter().all(u8::is_ascii_graphic)
                        || pad.iter().any(|c| *c != 0)
                    {
                        return Err(RecordError::BadField);
                    }
                }
                let sign = r.take::<JOINTS>()?.map(|b| b as i8);
                if sign.iter().any(|s| !matches!(s, 1 | -1)) {
                    return Err(RecordError::BadField);
                }
                Record::ProfileDisplay {
                    generation,
                    names,
                    sign,
                    zero_deg: r.joints()?,
                }
            }
            k if (key::BRACKET_CALIBRATION..key::BRACKET_CALIBRATION + BRACKET_KEYS as u16)
                .contains(&k) =>
            {
                let mount = BracketMount::ALL
                    .get(usize::from(r.u8()?))
                    .copied()
                    .filter(|m| u16::from(mount_code(*m)) == k - key::BRACKET_CALIBRATION)
                    .ok_or(RecordError::BadField)?;
                let id_len = r.u8()?;
                let id = r.take::<BRACKET_ID_LEN>()?;
                // Spelled as an ID: it goes into link lines and files as one word.
                let spelled = id
                    .get(..usize::from(id_len))
                    .and_then(|b| core::str::from_utf8(b).ok())
                    .is_some_and(|s| bracket_id(s).is_ok());
                if !spelled {
                    return Err(RecordError::BadField);
                }
                let rotation_rad = r.tilt()?;
                let uncertainty_rad: T = r.f()?;
                let yaw_rad: T = r.f()?;
                let yaw_uncertainty_rad: T = r.f()?;
                if uncertainty_rad < T::zero() || yaw_uncertainty_rad < T::zero() {
                    return Err(RecordError::BadField);
                }
                Record::BracketCalibration {
                    mount,
                    id,
                    id_len,
                    rotation_rad,
                    uncertainty_rad,
                    yaw_rad,
                    yaw_uncertainty_rad,
                    temperature_c: r.temperature()?,
                }
            }
            k => return Err(RecordError::UnknownKey(k)),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip(r: Record<f32>) {
        let mut buf = [0u8; MAX_RECORD_LEN];
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
        // Every strict prefix is refused, never misread.
        for cut in 0..n {
            assert!(
                Record::<f32>::decode(r.key(), &buf[..cut]).is_err(),
                "{r:?} cut {cut}"
            );
        }
    }

    #[test]
    fn every_kind_round_trips_bit_exactly() {
        let t = Tilt::new(0.123_456_79_f32, -1.0e-7);
        round_trip(Record::Bias(t));
        for slot in ReadingSlot::ALL {
            round_trip(Record::Reading {
                slot,
                capture: Capture {
                    reading: t,
                    temperature_c: Some(23.25),
                },
            });
        }
        round_trip(Record::Reading {
            slot: ReadingSlot::ClosingSecond,
            capture: Capture {
                reading: t,
                temperature_c: None,
            },
        });
        for (stage0_skipped, closing_skipped) in [(true, false), (false, true), (true, true)] {
            round_trip(Record::Progress {
                phase: Phase::ClosingSecond,
                cursor: 7,
                captures: 6,
                stage0_skipped,
                closing_skipped,
            });
        }
        round_trip(Record::Capture {
            slot: 5,
            index: CaptureIndex::from_sequence(9).unwrap(),
            pose: PoseReading {
                joints_rad: [0.0, -1.5, 0.1, -3.1, 2.0, 1e-9],
                reading: t,
                temperature_c: Some(24.5),
            },
        });
        round_trip(Record::Capture {
            slot: 6,
            index: CaptureIndex::from_sequence(10).unwrap(),
            pose: PoseReading {
                joints_rad: [0.0; 6],
                reading: t,
                temperature_c: None,
            },
        });
        round_trip(Record::PlanLen(12));
        round_trip(Record::PlanPose {
            index: MAX_POSES as u8 - 1,
            joints_rad: [0.0, -1.5, 1.0, 2.0, 3.0, -3.0],
        });
        for (mount, temperature_c) in [
            (BracketMount::UpperArm, Some(21.5)),
            (BracketMount::Flange, None),
        ] {
            let mut id = [0; BRACKET_ID_LEN];
            id[..5].copy_from_slice(b"F-017");
            round_trip(Record::BracketCalibration {
                mount,
                id,
                id_len: 5,
                rotation_rad: t,
                uncertainty_rad: 1.4e-5,
                yaw_rad: -3e-3,
                yaw_uncertainty_rad: 7e-4,
                temperature_c,
            });
        }
        round_trip(Record::LastResult {
            offsets_rad: [1e-3, -2e-3, 3e-3, 4e-3],
            sigma_rad: [1e-6; 4],
            delta_theta2_rad: 5e-4,
            residual_rms_rad: 2e-5,
        });
    }

    #[test]
    fn corrupt_values_are_named() {
        let mut buf = [0u8; MAX_RECORD_LEN];
        let r = Record::Capture {
            slot: 2,
            index: CaptureIndex::from_sequence(1).unwrap(),
            pose: PoseReading::<f32>::default(),
        };
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(key::CAPTURE + 3, &buf[..n]),
            Err(RecordError::BadField)
        );
        assert_eq!(
            Record::<f32>::decode(999, &buf[..n]),
            Err(RecordError::UnknownKey(999))
        );
        buf[0] = 9;
        assert_eq!(
            Record::<f32>::decode(r.key(), &buf[..n]),
            Err(RecordError::WrongFormat(9))
        );
        // A reading stored under another slot's key.
        let r = Record::Reading {
            slot: ReadingSlot::Stage1AfterBelow,
            capture: Capture::<f32>::default(),
        };
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(key::READING, &buf[..n]),
            Err(RecordError::BadField)
        );
        // A bracket's calibration under the other mount's key, or with an ID that is
        // not one (a space in it).
        let mut id = [0; BRACKET_ID_LEN];
        id[..3].copy_from_slice(b"F 1");
        let r = Record::BracketCalibration {
            mount: BracketMount::Flange,
            id,
            id_len: 3,
            rotation_rad: Tilt::new(0.0f32, 0.0),
            uncertainty_rad: 1e-5,
            yaw_rad: 0.0,
            yaw_uncertainty_rad: 7e-4,
            temperature_c: None,
        };
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(key::BRACKET_CALIBRATION, &buf[..n]),
            Err(RecordError::BadField)
        );
        assert_eq!(
            Record::<f32>::decode(r.key(), &buf[..n]),
            Err(RecordError::BadField)
        );
        let nan = Record::Bias(Tilt::new(f32::NAN, 0.0));
        let n = nan.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(key::BIAS, &buf[..n]),
            Err(RecordError::BadField)
        );
        assert_eq!(
            Record::Bias(Tilt::new(0.0f32, 0.0)).encode(&mut [0u8; 4]),
            Err(RecordError::BufferTooSmall)
        );
    }

    fn stored_bracket() -> StoredBracket<f32> {
        let c = BracketCalibration::new(
            bracket_id("U-017").unwrap(),
            Tilt::new(0.0037_f32, -0.0007),
            2.1e-5,
            20261127,
            21.5,
        )
        .unwrap();
        StoredBracket::of(&c)
    }

    #[test]
    fn profile_masses_and_brackets_round_trip_bit_exactly() {
        for part in 0..PROFILE_MASSES as u8 {
            round_trip(Record::ProfileMass {
                generation: 9,
                part,
                kg: 0.123_456_79,
                com_m: [0.01, -0.2, 1.5e-7],
            });
        }
        for flange in [false, true] {
            round_trip(Record::ProfileBracket {
                generation: 9,
                flange,
                calibration: Some(stored_bracket()),
            });
            round_trip(Record::ProfileBracket {
                generation: 9,
                flange,
                calibration: None,
            });
        }
    }

    /// A stored mass or calibration that no profile line could have given is refused,
    /// never used: a negative mass or one beyond 10 t, a centre of mass 101 m away, a
    /// bracket ID with a foreign byte or bytes after its length, a day that is not one,
    /// a turn beyond the design's, an uncertainty beyond 180° (4 rad), a temperature
    /// beyond the sensor's range.
    #[test]
    fn impossible_masses_and_calibrations_are_refused() {
        let refused = |r: Record<f32>| {
            let mut buf = [0u8; MAX_RECORD_LEN];
            let n = r.encode(&mut buf).unwrap();
            assert_eq!(
                Record::<f32>::decode(r.key(), &buf[..n]),
                Err(RecordError::BadField),
                "{r:?}"
            );
        };
        for (kg, com_m) in [(-1.0, [0.0; 3]), (2e4, [0.0; 3]), (1.0, [0.0, 0.0, 101.0])] {
            refused(Record::ProfileMass {
                generation: 1,
                part: 2,
                kg,
                com_m,
            });
        }
        let bracket = |edit: fn(&mut StoredBracket<f32>)| {
            let mut c = stored_bracket();
            edit(&mut c);
            Record::ProfileBracket {
                generation: 1,
                flange: true,
                calibration: Some(c),
            }
        };
        refused(bracket(|c| c.id[1] = b'/'));
        refused(bracket(|c| c.id[7] = b'x'));
        refused(bracket(|c| c.id_len = 13));
        refused(bracket(|c| c.date = 20260230));
        refused(bracket(|c| c.rotation_rad[1] = 0.01));
        refused(bracket(|c| c.uncertainty_rad = 4.0));
        refused(bracket(|c| c.temperature_c = 200.0));
        // A mass stored under another part's key.
        let mut buf = [0u8; MAX_RECORD_LEN];
        let r = Record::ProfileMass {
            generation: 1,
            part: 2,
            kg: 1.0_f32,
            com_m: [0.0; 3],
        };
        let n = r.encode(&mut buf).unwrap();
        assert_eq!(
            Record::<f32>::decode(key::PROFILE_MASS + 3, &buf[..n]),
            Err(RecordError::BadField)
        );
    }

    /// Found by the `record` fuzz target: a finite `f64` beyond `f32`'s range (a
    /// stored 1e300) decoded into the pendant's `f32` as an infinity, which the export
    /// then printed as "huge".
    #[test]
    fn a_value_beyond_the_readers_float_is_refused() {
        let mut value = [FORMAT; 17];
        value[1..9].copy_from_slice(&1e-3_f64.to_le_bytes());
        value[9..17].copy_from_slice(&(-1e300_f64).to_le_bytes());
        assert_eq!(
            Record::<f32>::decode(key::BIAS, &value),
            Err(RecordError::BadField)
        );
        // The same value is fine in f64.
        assert!(Record::<f64>::decode(key::BIAS, &value).is_ok());
    }
}
