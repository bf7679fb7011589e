//! What the pendant keeps in flash so that a reset or power cut at any moment loses
//! nothing: each change of the session is one small record under a fixed key, written
//! before the change is shown. Sequential-storage's map keeps the newest value per key,
//! so "undo" overwrites a count rather than deleting (the STM32F4 flash cannot delete).
//!
//! Encoding: a format byte, then little-endian fields; every angle as an `f64` of
//! radians (exact for the pendant's `f32`). Format 2 holds all six joints and the
//! temperature of each capture; format 1 (the wrist's four joints) is refused as
//! `WrongFormat` and the pendant starts afresh.

use super::Phase;
use crate::model::{Tilt, JOINTS, WRIST_JOINTS};
use crate::plan::MAX_POSES;
use crate::real::Real;
use crate::stage2::PoseReading;

/// Largest encoded record (bytes): the last result (format, ten angles); a capture
/// (format, slot, index, six joints, two readings, a flag and a temperature) is 76.
pub const MAX_RECORD_LEN: usize = 1 + 8 * 10;

/// The record format this build writes and reads (the first byte of every value). A
/// store holding another format is reset by the pendant, never misread.
pub const FORMAT: u8 = 2;

/// One stored fact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Record<T> {
    /// The sensor bias from the last stage-0 reversal (kept across sessions).
    Bias(Tilt<T>),
    /// Where the session stands.
    Progress {
        /// Phase.
        phase: Phase,
        /// Plan index of the next stage-2 pose.
        next_pose: u8,
        /// Valid stage-2 captures (slots 0..captures).
        captures: u8,
        /// Whether stage 0 was skipped this session.
        stage0_skipped: bool,
    },
    /// First reversal reading of stage 0.
    Stage0First(Tilt<T>),
    /// Stage-1 reading before the half turn.
    Stage1Before(Tilt<T>),
    /// Stage-1 reading after the half turn.
    Stage1After(Tilt<T>),
    /// A stage-2 capture.
    Capture {
        /// Slot (capture order).
        slot: u8,
        /// The plan pose it answers.
        plan_index: u8,
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

/// Keys: fixed ones, then a range for capture slots and one for plan poses.
pub mod key {
    /// [`super::Record::Bias`].
    pub const BIAS: u16 = 1;
    /// [`super::Record::Progress`].
    pub const PROGRESS: u16 = 2;
    /// [`super::Record::Stage0First`].
    pub const STAGE0_FIRST: u16 = 3;
    /// [`super::Record::Stage1Before`].
    pub const STAGE1_BEFORE: u16 = 4;
    /// [`super::Record::Stage1After`].
    pub const STAGE1_AFTER: u16 = 5;
    /// [`super::Record::LastResult`].
    pub const LAST_RESULT: u16 = 6;
    /// [`super::Record::PlanLen`].
    pub const PLAN_LEN: u16 = 7;
    /// [`super::Record::Capture`] of slot s is `CAPTURE + s`.
    pub const CAPTURE: u16 = 0x100;
    /// [`super::Record::PlanPose`] of index i is `PLAN_POSE + i`.
    pub const PLAN_POSE: u16 = 0x200;
}

/// Every key a restore may need, in the order to read them.
pub fn all_keys() -> impl Iterator<Item = u16> {
    [
        key::BIAS,
        key::PROGRESS,
        key::STAGE0_FIRST,
        key::STAGE1_BEFORE,
        key::STAGE1_AFTER,
        key::LAST_RESULT,
        key::PLAN_LEN,
    ]
    .into_iter()
    .chain((0..MAX_POSES as u16).map(|s| key::CAPTURE + s))
    .chain((0..MAX_POSES as u16).map(|i| key::PLAN_POSE + i))
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
            Record::Stage0First(_) => key::STAGE0_FIRST,
            Record::Stage1Before(_) => key::STAGE1_BEFORE,
            Record::Stage1After(_) => key::STAGE1_AFTER,
            Record::LastResult { .. } => key::LAST_RESULT,
            Record::PlanLen(_) => key::PLAN_LEN,
            Record::Capture { slot, .. } => key::CAPTURE + u16::from(*slot),
            Record::PlanPose { index, .. } => key::PLAN_POSE + u16::from(*index),
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
            Record::Bias(t)
            | Record::Stage0First(t)
            | Record::Stage1Before(t)
            | Record::Stage1After(t) => {
                w.f(t.x_rad)?;
                w.f(t.y_rad)?;
            }
            Record::Progress {
                phase,
                next_pose,
                captures,
                stage0_skipped,
            } => w.put(&[phase.code(), next_pose, captures, u8::from(stage0_skipped)])?,
            Record::Capture {
                slot,
                plan_index,
                pose,
            } => {
                w.put(&[slot, plan_index])?;
                for q in pose.joints_rad {
                    w.f(q)?;
                }
                w.f(pose.reading.x_rad)?;
                w.f(pose.reading.y_rad)?;
                match pose.temperature_c {
                    Some(c) => {
                        w.put(&[1])?;
                        w.f(c)?;
                    }
                    None => w.put(&[0])?,
                }
            }
            Record::PlanLen(n) => w.put(&[n])?,
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
        let slot_range = key::CAPTURE..key::CAPTURE + MAX_POSES as u16;
        let plan_range = key::PLAN_POSE..key::PLAN_POSE + MAX_POSES as u16;
        Ok(match key {
            key::BIAS => Record::Bias(r.tilt()?),
            key::STAGE0_FIRST => Record::Stage0First(r.tilt()?),
            key::STAGE1_BEFORE => Record::Stage1Before(r.tilt()?),
            key::STAGE1_AFTER => Record::Stage1After(r.tilt()?),
            key::PROGRESS => {
                let phase = Phase::from_code(r.u8()?).ok_or(RecordError::BadField)?;
                let next_pose = r.u8()?;
                let captures = r.u8()?;
                let stage0_skipped = r.u8()? != 0;
                if usize::from(next_pose) > MAX_POSES || usize::from(captures) > MAX_POSES {
                    return Err(RecordError::BadField);
                }
                Record::Progress {
                    phase,
                    next_pose,
                    captures,
                    stage0_skipped,
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
                let plan_index = r.u8()?;
                if u16::from(slot) != k - key::CAPTURE || usize::from(plan_index) >= MAX_POSES {
                    return Err(RecordError::BadField);
                }
                let joints_rad = r.joints()?;
                let reading = r.tilt()?;
                let temperature_c = match r.u8()? {
                    0 => None,
                    1 => Some(r.f()?),
                    _ => return Err(RecordError::BadField),
                };
                Record::Capture {
                    slot,
                    plan_index,
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
        round_trip(Record::Stage0First(t));
        round_trip(Record::Stage1Before(t));
        round_trip(Record::Stage1After(t));
        round_trip(Record::Progress {
            phase: Phase::Stage2,
            next_pose: 7,
            captures: 6,
            stage0_skipped: true,
        });
        round_trip(Record::Capture {
            slot: 5,
            plan_index: 9,
            pose: PoseReading {
                joints_rad: [0.0, -1.5, 0.1, -3.1, 2.0, 1e-9],
                reading: t,
                temperature_c: Some(24.5),
            },
        });
        round_trip(Record::Capture {
            slot: 6,
            plan_index: 10,
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
            plan_index: 1,
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
