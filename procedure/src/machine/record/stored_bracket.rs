//! A bracket's calibration as a profile record holds it.

use crate::log::{MAX_READING_DEG, TEMPERATURE_RANGE_C};
use zerocal_core::bracket::{
    bracket_id, BracketCalibration, BracketId, BracketYaw, BRACKET_ID_LEN,
};
use zerocal_core::model::Tilt;
use zerocal_core::real::Real;

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
        let (id, id_len) = id_bytes(&c.id);
        StoredBracket {
            id,
            id_len,
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
        let id = id_of(&self.id, self.id_len)?;
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
