//! A bracket's calibration as the flash holds it: the one stored form of
//! [`BracketCalibration`], held by both the bench's kept calibration
//! ([`super::Record::BracketCalibration`]) and the profile's bracket line
//! ([`super::Record::ProfileBracket`]), written and read by one encoding.

use super::bytes::{Reader, Writer};
use super::RecordError;
use crate::log::{MAX_READING_DEG, TEMPERATURE_RANGE_C};
use zerocal_core::bracket::{
    bracket_id, BracketCalibration, BracketId, BracketYaw, BRACKET_ID_LEN,
};
use zerocal_core::model::Tilt;
use zerocal_core::real::Real;

/// A bracket calibration as a record holds it: [`BracketCalibration`]'s fields, the ID
/// as bytes (a record is `Copy`). The date is absent for a calibration made on the
/// pendant (it has no calendar), the temperature where the sensor gave none, the yaw
/// where no sine plate measured it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StoredBracket<T> {
    /// The ID's bytes, `id_len` of them used.
    pub id: [u8; BRACKET_ID_LEN],
    /// Bytes of `id` used.
    pub id_len: u8,
    /// The pendant's turn in the bracket about its x and y (rad).
    pub rotation_rad: Tilt<T>,
    /// The calibration's standard uncertainty (rad).
    pub uncertainty_rad: T,
    /// `YYYYMMDD`, if known.
    pub date: Option<u32>,
    /// The sensor's temperature during the calibration (°C), if it gave one.
    pub temperature_c: Option<T>,
    /// The yaw and its standard uncertainty, where the sine plate measured it.
    pub yaw: Option<BracketYaw<T>>,
}

impl<T: Real> StoredBracket<T> {
    /// A calibration's fields.
    pub fn of(c: &BracketCalibration<T>) -> Self {
        let (id, id_len) = id_bytes(&c.id);
        StoredBracket {
            id,
            id_len,
            rotation_rad: c.rotation_rad,
            uncertainty_rad: c.uncertainty_rad,
            date: c.date,
            temperature_c: c.temperature_c,
            yaw: c.yaw,
        }
    }

    /// The bracket's ID, if the bytes spell one.
    pub fn id(&self) -> Option<BracketId> {
        id_of(&self.id, self.id_len)
    }

    /// The calibration, checked as core checks one ([`bracket_id`],
    /// [`BracketCalibration::new`]) and as a profile line takes one (an uncertainty
    /// within [`MAX_READING_DEG`], a temperature within [`TEMPERATURE_RANGE_C`]);
    /// `None` for fields no calibration has.
    pub fn calibration(&self) -> Option<BracketCalibration<T>> {
        let u_deg = self.uncertainty_rad.to_f64().to_degrees();
        let t_ok = self
            .temperature_c
            .is_none_or(|t| (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(&t.to_f64()));
        if !(u_deg <= MAX_READING_DEG && t_ok) {
            return None;
        }
        let c = BracketCalibration::new(
            self.id()?,
            self.rotation_rad,
            self.uncertainty_rad,
            self.date,
            self.temperature_c,
        )
        .ok()?;
        match self.yaw {
            Some(yaw) => c.with_yaw(yaw).ok(),
            None => Some(c),
        }
    }

    /// Writes it: the ID's length and bytes, the turn, its uncertainty, then the date,
    /// the temperature and the yaw, each after a byte saying whether it is there.
    ///
    /// # Errors
    /// [`RecordError::BadField`] for what [`Self::read`] would refuse: a record that
    /// does not read back is never written.
    pub(super) fn put(&self, w: &mut Writer<'_>) -> Result<(), RecordError> {
        self.checked()?;
        self.put_unchecked(w)
    }

    /// [`Self::put`] without the check (the tests write what must be refused).
    pub(super) fn put_unchecked(&self, w: &mut Writer<'_>) -> Result<(), RecordError> {
        w.put(&[self.id_len])?;
        w.put(&self.id)?;
        w.f(self.rotation_rad.x_rad)?;
        w.f(self.rotation_rad.y_rad)?;
        w.f(self.uncertainty_rad)?;
        match self.date {
            None => w.put(&[0])?,
            Some(d) => {
                w.put(&[1])?;
                w.put(&d.to_le_bytes())?;
            }
        }
        w.temperature(self.temperature_c)?;
        match self.yaw {
            None => w.put(&[0]),
            Some(y) => {
                w.put(&[1])?;
                w.f(y.yaw_rad)?;
                w.f(y.uncertainty_rad)
            }
        }
    }

    /// Reads what [`Self::put`] wrote, refusing what no calibration has
    /// ([`Self::checked`]).
    pub(super) fn read(r: &mut Reader<'_>) -> Result<Self, RecordError> {
        let id_len = r.u8()?;
        let id = r.take::<BRACKET_ID_LEN>()?;
        let rotation_rad = r.tilt()?;
        let uncertainty_rad = r.f()?;
        let date = if r.flag()? {
            Some(u32::from_le_bytes(r.take::<4>()?))
        } else {
            None
        };
        let temperature_c = r.temperature()?;
        let yaw = if r.flag()? {
            Some(BracketYaw {
                yaw_rad: r.f()?,
                uncertainty_rad: r.f()?,
            })
        } else {
            None
        };
        StoredBracket {
            id,
            id_len,
            rotation_rad,
            uncertainty_rad,
            date,
            temperature_c,
            yaw,
        }
        .checked()
    }

    /// Itself if its ID's bytes past the ID are zero and core would accept the
    /// calibration ([`Self::calibration`]).
    pub(super) fn checked(self) -> Result<Self, RecordError> {
        let padded = self
            .id
            .get(usize::from(self.id_len)..)
            .is_some_and(|pad| pad.iter().all(|b| *b == 0));
        if padded && self.calibration().is_some() {
            Ok(self)
        } else {
            Err(RecordError::BadField)
        }
    }
}

/// A bracket ID as a record holds it: its bytes, zero-padded, and how many are used.
pub fn id_bytes(id: &BracketId) -> ([u8; BRACKET_ID_LEN], u8) {
    let mut bytes = [0_u8; BRACKET_ID_LEN];
    // A `BracketId` holds at most BRACKET_ID_LEN bytes.
    for (to, from) in bytes.iter_mut().zip(id.as_bytes()) {
        *to = *from;
    }
    (bytes, id.len() as u8)
}

/// The ID the first `id_len` bytes of a record's `id` spell, if they spell one
/// ([`bracket_id`]: it goes into link lines and files as one word).
pub fn id_of(id: &[u8; BRACKET_ID_LEN], id_len: u8) -> Option<BracketId> {
    let text = core::str::from_utf8(id.get(..usize::from(id_len))?).ok()?;
    bracket_id(text).ok()
}
