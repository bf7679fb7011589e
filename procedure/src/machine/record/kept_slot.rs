//! A kept result's flash bytes ([`KeptResult`]), and the pendant's next result ID.
//!
//! Kept results are not [`Record`](super::Record)s: a restore does not read them into
//! RAM (eight of them would double the restore's table); the store reads one at a time
//! when the link asks. Result `id` lives under [`kept_key`]`(id)`, so the ninth result
//! replaces the first: sequential-storage's map writes an item whole or not at all, so
//! a power cut leaves either the old result or the new one under the key.
//!
//! The next ID has its own key and a layout of its own ([`encode_next_id`]) that no
//! change of the record [`FORMAT`](super::FORMAT) touches, so the store can carry it
//! over an erase and an ID never names two results on one pendant.

use super::bytes::{Reader, Writer};
use super::{id_bytes, id_of, RecordError};
use crate::kept::{KeptResult, UnitId, KEPT_RESULTS, UNIT_ID_BYTES, VERDICT_BITS};
use crate::log::TEMPERATURE_RANGE_C;
use crate::text::RobotName;
use zerocal_core::bracket::BRACKET_ID_LEN;
use zerocal_core::session::SESSION_JOINTS;

/// The first byte of a kept result's value: its layout's version, apart from the
/// records' [`FORMAT`](super::FORMAT).
pub const KEPT_FORMAT: u8 = 1;

/// Bytes of a robot name in a kept result (zero-padded): a [`RobotName`]'s capacity.
const NAME_BYTES: usize = 32;

/// A kept result's value: format, ID, the name's length and bytes, Δθ2..Δθ6 and their
/// 1σ and the residual RMS (`f32` each), the warnings, three temperatures (a flag and
/// an `f32`), two bracket IDs (a length and the bytes) and the unit (a flag and its
/// bytes).
pub const KEPT_RESULT_LEN: usize = 1
    + 4
    + 1
    + NAME_BYTES
    + 4 * (2 * SESSION_JOINTS + 1)
    + 1
    + 3 * 5
    + 2 * (1 + BRACKET_ID_LEN)
    + 1
    + UNIT_ID_BYTES;

/// The next-ID value: a tag and the ID (`u32`, little-endian).
pub const NEXT_ID_LEN: usize = 6;

/// The next-ID value's tag.
const NEXT_ID_TAG: [u8; 2] = *b"nx";

/// The key of result `id`: one of [`KEPT_RESULTS`] slots, taken in turn.
pub fn kept_key(id: u32) -> u16 {
    super::key::KEPT_RESULT + (id % KEPT_RESULTS as u32) as u16
}

/// Whether `k` is a kept result's key.
pub fn is_kept_key(k: u16) -> bool {
    (super::key::KEPT_RESULT..super::key::KEPT_RESULT + KEPT_RESULTS as u16).contains(&k)
}

/// The next-ID value for `next`.
pub fn encode_next_id(next: u32) -> [u8; NEXT_ID_LEN] {
    let n = next.to_le_bytes();
    [NEXT_ID_TAG[0], NEXT_ID_TAG[1], n[0], n[1], n[2], n[3]]
}

/// The ID a next-ID value holds, if it is one.
pub fn decode_next_id(value: &[u8]) -> Option<u32> {
    match value {
        [a, b, n0, n1, n2, n3] if [*a, *b] == NEXT_ID_TAG => {
            Some(u32::from_le_bytes([*n0, *n1, *n2, *n3]))
        }
        _ => None,
    }
}

impl KeptResult {
    /// Writes the value into `buf`; returns its length.
    ///
    /// # Errors
    /// [`RecordError::BufferTooSmall`].
    // Out of line (as decode): inlined into the store's async write and power-up read
    // the record's every arm cost flash in each (-1,216 B rustup for the four).
    #[inline(never)]
    pub fn encode(&self, buf: &mut [u8]) -> Result<usize, RecordError> {
        let mut w = Writer { buf, len: 0 };
        w.put(&[KEPT_FORMAT])?;
        w.put(&self.id.to_le_bytes())?;
        let mut name = [0_u8; NAME_BYTES];
        for (to, from) in name.iter_mut().zip(self.robot.as_bytes()) {
            *to = *from;
        }
        w.put(&[self.robot.len() as u8])?;
        w.put(&name)?;
        for v in self.offsets_deg.iter().chain(&self.sigma_deg) {
            w.f32(*v)?;
        }
        w.f32(self.residual_rms_deg)?;
        w.put(&[self.warnings])?;
        for t in self.temperatures_c {
            match t {
                Some(c) => {
                    w.put(&[1])?;
                    w.f32(c)?;
                }
                None => w.put(&[0, 0, 0, 0, 0])?,
            }
        }
        for b in &self.brackets {
            let (bytes, len) = b.as_ref().map_or(([0; BRACKET_ID_LEN], 0), id_bytes);
            w.put(&[len])?;
            w.put(&bytes)?;
        }
        match self.unit {
            Some(u) => {
                w.put(&[1])?;
                w.put(&u.0)?;
            }
            None => {
                w.put(&[0])?;
                w.put(&[0; UNIT_ID_BYTES])?;
            }
        }
        Ok(w.len)
    }

    /// Reads a kept result back from its key and value.
    ///
    /// # Errors
    /// Another layout, a short value, a field out of its range, or a value under
    /// another result's key.
    #[inline(never)]
    pub fn decode(key: u16, value: &[u8]) -> Result<Self, RecordError> {
        let mut r = Reader { buf: value, at: 0 };
        let format = r.u8()?;
        if format != KEPT_FORMAT {
            return Err(RecordError::WrongFormat(format));
        }
        let id = u32::from_le_bytes(r.take::<4>()?);
        if id == 0 || !is_kept_key(key) || kept_key(id) != key {
            return Err(RecordError::BadField);
        }
        let name_len = usize::from(r.u8()?);
        let name = r.take::<NAME_BYTES>()?;
        let mut robot = RobotName::new();
        let text = name
            .get(..name_len)
            .filter(|n| !n.is_empty() && n.iter().all(u8::is_ascii_graphic))
            .and_then(|n| core::str::from_utf8(n).ok())
            .ok_or(RecordError::BadField)?;
        robot.push_str(text).map_err(|()| RecordError::BadField)?;
        let mut five = || -> Result<[f32; SESSION_JOINTS], RecordError> {
            let mut out = [0.0; SESSION_JOINTS];
            for v in &mut out {
                *v = r.f32()?;
            }
            Ok(out)
        };
        let offsets_deg = five()?;
        let sigma_deg = five()?;
        let residual_rms_deg = r.f32()?;
        let warnings = r.u8()?;
        if sigma_deg.iter().any(|s| *s < 0.0) || residual_rms_deg < 0.0 {
            return Err(RecordError::BadField);
        }
        if warnings & !VERDICT_BITS != 0 {
            return Err(RecordError::BadField);
        }
        let mut temperatures_c = [None; 3];
        for t in &mut temperatures_c {
            let present = r.flag()?;
            let bits = r.take::<4>()?;
            if present {
                let c = f32::from_le_bytes(bits);
                let (low, high) = TEMPERATURE_RANGE_C;
                if !(low..=high).contains(&f64::from(c)) {
                    return Err(RecordError::BadField);
                }
                *t = Some(c);
            }
        }
        let mut brackets = [None, None];
        for b in &mut brackets {
            let len = r.u8()?;
            let bytes = r.take::<BRACKET_ID_LEN>()?;
            if len > 0 {
                *b = Some(id_of(&bytes, len).ok_or(RecordError::BadField)?);
            }
        }
        let unit = r.flag()?;
        let unit_bytes = r.take::<UNIT_ID_BYTES>()?;
        Ok(KeptResult {
            id,
            robot,
            offsets_deg,
            sigma_deg,
            residual_rms_deg,
            warnings,
            temperatures_c,
            brackets,
            unit: unit.then_some(UnitId(unit_bytes)),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kept::example_kept_result as example;

    #[test]
    fn a_kept_result_reads_back_exactly_under_its_key() {
        for k in [
            example(1),
            example(8),
            example(9),
            KeptResult {
                unit: None,
                brackets: [None, None],
                ..example(u32::MAX)
            },
        ] {
            let mut buf = [0_u8; KEPT_RESULT_LEN];
            let len = k.encode(&mut buf).unwrap();
            assert_eq!(len, KEPT_RESULT_LEN, "every value has the same length");
            assert_eq!(KeptResult::decode(kept_key(k.id), &buf), Ok(k.clone()));
            // Under another slot's key: refused, never filed under the wrong ID.
            let other = kept_key(k.id.wrapping_add(1));
            assert_eq!(KeptResult::decode(other, &buf), Err(RecordError::BadField));
            // Cut short anywhere: refused.
            for cut in 0..len {
                assert!(
                    KeptResult::decode(kept_key(k.id), &buf[..cut]).is_err(),
                    "cut at {cut}"
                );
            }
        }
    }

    #[test]
    fn the_ninth_result_takes_the_first_ones_key() {
        assert_eq!(kept_key(9), kept_key(1));
        let keys: std::vec::Vec<u16> = (1..=KEPT_RESULTS as u32).map(kept_key).collect();
        for (i, k) in keys.iter().enumerate() {
            assert!(is_kept_key(*k));
            assert!(!keys[..i].contains(k), "eight results, eight keys");
        }
    }

    #[test]
    fn bad_fields_are_refused() {
        let mut buf = [0_u8; KEPT_RESULT_LEN];
        let k = example(3);
        k.encode(&mut buf).unwrap();
        let key = kept_key(3);
        let bad = |at: usize, byte: u8| {
            let mut b = buf;
            b[at] = byte;
            KeptResult::decode(key, &b)
        };
        // Another layout; ID 0; an empty or non-ASCII name; an unknown warning bit.
        assert_eq!(bad(0, 2), Err(RecordError::WrongFormat(2)));
        let mut zero = buf;
        zero[1..5].copy_from_slice(&0_u32.to_le_bytes());
        assert_eq!(
            KeptResult::decode(kept_key(0), &zero),
            Err(RecordError::BadField)
        );
        assert_eq!(bad(5, 0), Err(RecordError::BadField));
        assert_eq!(bad(6, b' '), Err(RecordError::BadField));
        let warnings_at = 1 + 4 + 1 + NAME_BYTES + 4 * 11;
        assert_eq!(bad(warnings_at, 0b1000), Err(RecordError::BadField));
        // A NaN offset.
        let mut nan = buf;
        nan[38..42].copy_from_slice(&f32::NAN.to_le_bytes());
        assert_eq!(KeptResult::decode(key, &nan), Err(RecordError::BadField));
    }

    #[test]
    fn the_next_id_reads_back_and_nothing_else_does() {
        for n in [1, 9, u32::MAX] {
            assert_eq!(decode_next_id(&encode_next_id(n)), Some(n));
        }
        assert_eq!(decode_next_id(b"nx\x01\x00\x00"), None);
        assert_eq!(decode_next_id(b"xx\x01\x00\x00\x00"), None);
    }
}
