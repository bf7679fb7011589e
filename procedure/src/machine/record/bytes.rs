//! The records' byte encoding: little-endian fields after the format byte, every angle
//! an `f64`.

use super::RecordError;
use zerocal_core::model::{Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::real::Real;

pub(super) struct Writer<'a> {
    pub(super) buf: &'a mut [u8],
    pub(super) len: usize,
}

impl Writer<'_> {
    // Out of line: inlined, each of its forty callers had a copy (flash).
    #[inline(never)]
    pub(super) fn put(&mut self, bytes: &[u8]) -> Result<(), RecordError> {
        let end = self.len + bytes.len();
        let dst = self
            .buf
            .get_mut(self.len..end)
            .ok_or(RecordError::BufferTooSmall)?;
        dst.copy_from_slice(bytes);
        self.len = end;
        Ok(())
    }
    pub(super) fn f<T: Real>(&mut self, v: T) -> Result<(), RecordError> {
        self.put(&v.to_f64().to_le_bytes())
    }
    /// An `f32` as its own four bytes (a kept result's numbers: the pendant's `f32`s).
    pub(super) fn f32(&mut self, v: f32) -> Result<(), RecordError> {
        self.put(&v.to_le_bytes())
    }
    pub(super) fn temperature<T: Real>(&mut self, c: Option<T>) -> Result<(), RecordError> {
        match c {
            Some(c) => {
                self.put(&[1])?;
                self.f(c)
            }
            None => self.put(&[0]),
        }
    }
}

pub(super) struct Reader<'a> {
    pub(super) buf: &'a [u8],
    pub(super) at: usize,
}

impl Reader<'_> {
    pub(super) fn take<const N: usize>(&mut self) -> Result<[u8; N], RecordError> {
        let s = self
            .buf
            .get(self.at..self.at + N)
            .ok_or(RecordError::Truncated)?;
        self.at += N;
        let mut out = [0u8; N];
        out.copy_from_slice(s);
        Ok(out)
    }
    pub(super) fn u8(&mut self) -> Result<u8, RecordError> {
        Ok(self.take::<1>()?[0])
    }
    pub(super) fn f<T: Real>(&mut self) -> Result<T, RecordError> {
        let v = f64::from_le_bytes(self.take::<8>()?);
        // Finite in the reader's float too: 1e300 is an f32 infinity.
        let t = T::lit(v);
        if v.is_finite() && t.to_f64().is_finite() {
            Ok(t)
        } else {
            Err(RecordError::BadField)
        }
    }
    /// A finite `f32` written by [`Writer::f32`].
    pub(super) fn f32(&mut self) -> Result<f32, RecordError> {
        let v = f32::from_le_bytes(self.take::<4>()?);
        if v.is_finite() {
            Ok(v)
        } else {
            Err(RecordError::BadField)
        }
    }
    pub(super) fn temperature<T: Real>(&mut self) -> Result<Option<T>, RecordError> {
        match self.u8()? {
            0 => Ok(None),
            1 => Ok(Some(self.f()?)),
            _ => Err(RecordError::BadField),
        }
    }
    pub(super) fn flag(&mut self) -> Result<bool, RecordError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(RecordError::BadField),
        }
    }
    pub(super) fn tilt<T: Real>(&mut self) -> Result<Tilt<T>, RecordError> {
        let [x, y] = self.array()?;
        Ok(Tilt::new(x, y))
    }
    pub(super) fn four<T: Real>(&mut self) -> Result<[T; WRIST_JOINTS], RecordError> {
        self.array()
    }
    pub(super) fn joints<T: Real>(&mut self) -> Result<[T; JOINTS], RecordError> {
        self.array()
    }
    /// `N` numbers in order: one read in a loop, not `N` copies of it (flash).
    pub(super) fn array<T: Real, const N: usize>(&mut self) -> Result<[T; N], RecordError> {
        let mut out = [T::zero(); N];
        for v in &mut out {
            *v = self.f()?;
        }
        Ok(out)
    }
}
