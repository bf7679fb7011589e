//! What the pendant keeps in flash so that a reset or power cut at any moment loses
//! nothing: each change of the session is one small record under a fixed key, written
//! before the change is shown. Sequential-storage's map keeps the newest value per key,
//! so "undo" overwrites a count rather than deleting (the STM32F4 flash cannot delete).
//!
//! Encoding: a format byte, then little-endian fields; every angle as an `f64` of
//! radians (exact for the pendant's `f32`). Format 3 (the two-sided procedure) keeps every
//! capture of stages 0 and 1 and of the closing readings with its temperature, and two
//! stage-2 captures per plan pose (each under the index of its approach); format 4 adds
//! the profile's link masses and bracket calibrations (and the head's flag saying
//! whether masses are stored); format 5 reads the bench at four headings (stage 0's and
//! the closing readings' slots, [`ReadingSlot`], and the phases' codes changed with
//! them) and holds 96 stage-2 captures. Formats 1-4 are refused as `WrongFormat` and
//! the pendant starts afresh: a format-4 store's slot 1 was a half turn's second
//! reading, which format 5 would take for a heading.
//!
//! The two bracket records ([`Record::BracketCalibration`], [`Record::ProfileBracket`])
//! hold one stored form, [`StoredBracket`], written by one encoding under their own
//! format byte, [`BRACKET_FORMAT`]: bumping [`FORMAT`] would reset every store. A
//! bracket record of format 5 (the layouts before: the bench's with a yaw and no date,
//! the profile's with a date and a temperature) still reads, into the same stored
//! form, so a pendant's kept calibrations survive the update.

use super::profile::{MAX_MASS_KG, MAX_POSITION_M};
use super::{Capture, Phase, ReadingSlot, READING_SLOTS};
use zerocal_core::bracket::BracketMount;
use zerocal_core::capture::{CaptureIndex, MAX_CAPTURES};
use zerocal_core::model::{Convention, JointAxis, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::MAX_POSES;
use zerocal_core::real::Real;
use zerocal_core::stage2::PoseReading;

mod bytes;
pub mod kept_slot;
mod legacy;
mod stored_bracket;
#[cfg(test)]
mod tests;

use bytes::{Reader, Writer};
pub use stored_bracket::{id_bytes, id_of, StoredBracket};

/// Largest encoded record (bytes): the last result (format, ten angles); a capture
/// (format, slot, index, six joints, two readings, a flag and a temperature) is 76.
pub const MAX_RECORD_LEN: usize = 1 + 8 * 10;

/// The record format this build writes and reads (the first byte of every value). A
/// store holding another format is reset by the pendant, never misread.
pub const FORMAT: u8 = 5;

/// The format byte of the bracket records ([`StoredBracket`]'s one encoding); those of
/// [`FORMAT`] are read in the layouts that format wrote ([`legacy`]).
pub const BRACKET_FORMAT: u8 = 6;

/// One stored fact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Record<T> {
    /// The sensor bias from the last stage 0 (kept across sessions).
    Bias(Tilt<T>),
    /// Where the session stands.
    Progress {
        /// Phase.
        phase: Phase,
        /// On the bench: the heading of the next capture; stage 1: its approach (0
        /// from below, 1 from above); stage 2: the index of the next capture in the
        /// plan's list (two a pose).
        cursor: u8,
        /// Valid stage-2 captures (slots 0..captures).
        captures: u8,
        /// Whether stage 0 was skipped this session.
        stage0_skipped: bool,
        /// Whether the closing bench readings were skipped this session.
        closing_skipped: bool,
        /// Whether this is a check, not a session.
        check: bool,
    },
    /// A capture of stage 0, stage 1 or the closing bench readings.
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
        /// Its calibration.
        calibration: StoredBracket<T>,
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
/// bench readings, one for capture slots and one for plan poses.
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
    /// The next kept result's ID ([`super::kept`]; not a [`super::Record`]).
    pub const KEPT_NEXT_ID: u16 = 0x70;

    // Each range ends before the next begins.
    const _: () = assert!(READING + super::READING_SLOTS as u16 <= PROFILE_HEAD);
    const _: () = assert!(CAPTURE + super::MAX_CAPTURES as u16 <= PLAN_POSE);
    /// The kept results' slots ([`super::kept_slot::kept_key`]; not [`super::Record`]s):
    /// `KEPT_RESULT + id % KEPT_RESULTS`.
    pub const KEPT_RESULT: u16 = 0x71;
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
    // Out of line (as decode): inlined into the store's async write and power-up read
    // the record's every arm cost flash in each (-1,216 B rustup for the four).
    #[inline(never)]
    pub fn encode(&self, buf: &mut [u8]) -> Result<usize, RecordError> {
        let mut w = Writer { buf, len: 0 };
        let format = match self {
            Record::BracketCalibration { .. } | Record::ProfileBracket { .. } => BRACKET_FORMAT,
            _ => FORMAT,
        };
        w.put(&[format])?;
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
                check,
            } => w.put(&[
                phase.code(),
                cursor,
                captures,
                u8::from(stage0_skipped) | u8::from(closing_skipped) << 1 | u8::from(check) << 2,
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
                        w.put(&[1])?;
                        c.put(&mut w)?;
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
            Record::BracketCalibration { mount, calibration } => {
                w.put(&[mount_code(mount)])?;
                calibration.put(&mut w)?;
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
    #[inline(never)]
    pub fn decode(key: u16, value: &[u8]) -> Result<Self, RecordError> {
        let mut r = Reader { buf: value, at: 0 };
        let format = r.u8()?;
        let bracket_keys = [key::PROFILE_BRACKET, key::BRACKET_CALIBRATION];
        if bracket_keys.iter().any(|k| (*k..*k + 2).contains(&key)) {
            return match format {
                BRACKET_FORMAT => Self::decode_bracket(key, &mut r),
                FORMAT => legacy::decode_bracket(key, &mut r),
                other => Err(RecordError::WrongFormat(other)),
            };
        }
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
                    || flags > 7
                {
                    return Err(RecordError::BadField);
                }
                Record::Progress {
                    phase,
                    cursor,
                    captures,
                    stage0_skipped: flags & 1 != 0,
                    closing_skipped: flags & 2 != 0,
                    check: flags & 4 != 0,
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
                    stage1_rad: r.array()?,
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
                let com_m: [T; 3] = r.array()?;
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
                    rotation: r.array()?,
                    translation_m: r.array()?,
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
                    rotation: r.array()?,
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
            k => return Err(RecordError::UnknownKey(k)),
        })
    }

    /// A bracket record of [`BRACKET_FORMAT`], after its format byte.
    fn decode_bracket(key: u16, r: &mut Reader<'_>) -> Result<Self, RecordError> {
        if let Some(flange) = key.checked_sub(key::PROFILE_BRACKET).filter(|f| *f < 2) {
            let generation = r.u8()?;
            if u16::from(r.u8()?) != flange {
                return Err(RecordError::BadField);
            }
            let calibration = if r.flag()? {
                Some(StoredBracket::read(r)?)
            } else {
                None
            };
            return Ok(Record::ProfileBracket {
                generation,
                flange: flange == 1,
                calibration,
            });
        }
        let mount = bracket_mount(key, r.u8()?)?;
        Ok(Record::BracketCalibration {
            mount,
            calibration: StoredBracket::read(r)?,
        })
    }
}

/// The mount of a bench calibration's record under `key` whose mount byte is `code`.
fn bracket_mount(key: u16, code: u8) -> Result<BracketMount, RecordError> {
    BracketMount::ALL
        .get(usize::from(code))
        .copied()
        .filter(|m| u16::from(mount_code(*m)) == key.wrapping_sub(key::BRACKET_CALIBRATION))
        .ok_or(RecordError::BadField)
}
