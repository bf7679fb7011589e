//! The bracket records as format 5 wrote them, read into today's stored form
//! ([`StoredBracket`]) so that calibrations kept before the one encoding
//! ([`super::BRACKET_FORMAT`]) are not lost: the bench's (mount, ID, turn, uncertainty,
//! yaw and its uncertainty, temperature if any; no date) and the profile's (ID, turn,
//! uncertainty, date, temperature, yaw if any). Each is accepted exactly as format 5's
//! reader accepted it, so no store that read before reads as unreadable now.

use super::bytes::Reader;
use super::{bracket_mount, key, Record, RecordError, StoredBracket};
use zerocal_core::bracket::{BracketYaw, BRACKET_ID_LEN};
use zerocal_core::real::Real;

/// A bracket record of format 5 under `key`, after its format byte.
pub(super) fn decode_bracket<T: Real>(
    key: u16,
    r: &mut Reader<'_>,
) -> Result<Record<T>, RecordError> {
    if let Some(flange) = key.checked_sub(key::PROFILE_BRACKET).filter(|f| *f < 2) {
        let generation = r.u8()?;
        if u16::from(r.u8()?) != flange {
            return Err(RecordError::BadField);
        }
        let calibration = if r.flag()? {
            let id_len = r.u8()?;
            let id = r.take::<BRACKET_ID_LEN>()?;
            let rotation_rad = r.tilt()?;
            let uncertainty_rad = r.f()?;
            let date = Some(u32::from_le_bytes(r.take::<4>()?));
            let temperature_c = Some(r.f()?);
            let yaw = if r.flag()? {
                Some(BracketYaw {
                    yaw_rad: r.f()?,
                    uncertainty_rad: r.f()?,
                })
            } else {
                None
            };
            Some(
                StoredBracket {
                    id,
                    id_len,
                    rotation_rad,
                    uncertainty_rad,
                    date,
                    temperature_c,
                    yaw,
                }
                .checked()?,
            )
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
    let id_len = r.u8()?;
    let id = r.take::<BRACKET_ID_LEN>()?;
    let rotation_rad = r.tilt()?;
    let uncertainty_rad: T = r.f()?;
    let yaw = BracketYaw {
        yaw_rad: r.f()?,
        uncertainty_rad: r.f()?,
    };
    let calibration = StoredBracket {
        id,
        id_len,
        rotation_rad,
        uncertainty_rad,
        date: None,
        temperature_c: r.temperature()?,
        yaw: Some(yaw),
    };
    // Format 5's checks of the bench's record: an ID, uncertainties at least 0.
    if calibration.id().is_none() || uncertainty_rad < T::zero() || yaw.uncertainty_rad < T::zero()
    {
        return Err(RecordError::BadField);
    }
    Ok(Record::BracketCalibration { mount, calibration })
}
