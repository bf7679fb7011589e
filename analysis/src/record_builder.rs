//! The one builder of a history record ([`zerocal_history::NewRecord`]): a session
//! (`zerocal session --record`), a pendant's kept result (`zerocal history --import`)
//! and a check (`zerocal check --record`) each give what is theirs ([`Origin`], the
//! verdict, the result) and this fills in the rest the same way for all three: the
//! robot's identity, who measured and when, the zerocal version, the verdict's text
//! ([`Verdict::text`]) and the brackets ([`record_brackets`]).

use crate::db::RecordMeta;
use zerocal_core::bracket::{BracketCalibration, Brackets};
use zerocal_history::{
    Harmonic, JointRow, NewRecord, RecordBracket, RecordBracketCalibration, RecordBracketYaw,
    RecordBrackets, RecordKind, Verdict,
};
use zerocal_inputs::error::CliError;

/// What made the record: its kind and the reference it carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// A session solved from its export.
    Session,
    /// A session the pendant solved and kept, with its result ID.
    KeptResult(u32),
    /// A check of the zeros against the record with this ID.
    Check(i64),
}

/// The robot a record is of: its profile's name, title, controller family and text.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordRobot {
    /// The profile's name.
    pub name: String,
    /// Its title.
    pub title: String,
    /// The controller family's name.
    pub family: String,
    /// The profile's text as used.
    pub profile_toml: String,
}

impl RecordRobot {
    /// The robot of `profile` (its text `toml`).
    #[must_use]
    pub fn of_profile(profile: &zerocal_profile::Profile, toml: &str) -> RecordRobot {
        RecordRobot {
            name: profile.name.clone(),
            title: profile.title.clone(),
            family: profile.family.name().to_owned(),
            profile_toml: toml.to_owned(),
        }
    }

    /// The robot of a stored record (a check is of its reference's robot).
    #[must_use]
    pub fn of_record(r: &NewRecord) -> RecordRobot {
        RecordRobot {
            name: r.robot.clone(),
            title: r.robot_title.clone(),
            family: r.controller_family.clone(),
            profile_toml: r.profile_toml.clone(),
        }
    }
}

/// Everything a record holds that its maker decides.
#[derive(Debug, Clone)]
pub struct RecordParts {
    /// Session, kept result or check.
    pub origin: Origin,
    /// The robot's serial.
    pub serial: String,
    /// Its robot.
    pub robot: RecordRobot,
    /// The bytes it was read from (export or kept result's lines).
    pub export: Vec<u8>,
    /// The pendant unit that measured.
    pub pendant_unit: Option<String>,
    /// Its verdict.
    pub verdict: Verdict,
    /// The brackets it was measured through.
    pub brackets: RecordBrackets,
    /// Temperatures, base tilt and the like.
    pub conditions: serde_json::Value,
    /// The whole result as JSON text.
    pub result_json: String,
    /// Per joint results.
    pub joints: Vec<JointRow>,
    /// A session's fitted harmonics of its reducers (none for a check or a kept result).
    pub harmonics: Vec<Harmonic>,
}

/// The record of `parts`, measured as `meta` says.
///
/// # Errors
/// `--measured-on` that is no day.
pub fn build(parts: RecordParts, meta: &RecordMeta) -> Result<NewRecord, CliError> {
    let (kind, pendant_result_id, reference_id) = match parts.origin {
        Origin::Session => (RecordKind::Session, None, None),
        Origin::KeptResult(id) => (RecordKind::Session, Some(id), None),
        Origin::Check(reference) => (RecordKind::Check, None, Some(reference)),
    };
    Ok(NewRecord {
        kind,
        serial: parts.serial,
        robot: parts.robot.name,
        robot_title: parts.robot.title,
        controller_family: parts.robot.family,
        profile_toml: parts.robot.profile_toml,
        export: parts.export,
        measured_on: meta.day()?,
        operator: meta.operator.clone(),
        pendant_unit: parts.pendant_unit,
        pendant_result_id,
        reference_id,
        zerocal_version: env!("CARGO_PKG_VERSION").to_owned(),
        verdict: parts.verdict.text(),
        brackets: parts.brackets,
        conditions_json: parts.conditions.to_string(),
        result_json: parts.result_json,
        joints: parts.joints,
        harmonics: parts.harmonics,
    })
}

/// The brackets of a session as the record keeps them: each calibrated bracket's ID
/// and calibration in degrees; a mount without a calibration is `None` (the export
/// gives a bracket's ID only with its calibration).
#[must_use]
pub fn record_brackets(brackets: &Brackets<f64>) -> RecordBrackets {
    let one = |c: &BracketCalibration<f64>| RecordBracket {
        id: c.id.as_str().to_owned(),
        calibration: Some(RecordBracketCalibration {
            calibrated_on: c.date,
            rotation_deg: [
                c.rotation_rad.x_rad.to_degrees(),
                c.rotation_rad.y_rad.to_degrees(),
            ],
            standard_uncertainty_deg: c.uncertainty_rad.to_degrees(),
            temperature_c: c.temperature_c,
            yaw: c.yaw.map(|y| RecordBracketYaw {
                yaw_deg: y.yaw_rad.to_degrees(),
                standard_uncertainty_deg: y.uncertainty_rad.to_degrees(),
            }),
        }),
    };
    RecordBrackets {
        upper_arm: brackets.upper_arm.as_ref().map(one),
        flange: brackets.flange.as_ref().map(one),
    }
}

/// The brackets of a kept result: the IDs the pendant kept, without calibrations.
#[must_use]
pub fn kept_brackets(ids: [Option<&str>; 2]) -> RecordBrackets {
    let one = |id: Option<&str>| {
        id.map(|id| RecordBracket {
            id: id.to_owned(),
            calibration: None,
        })
    };
    RecordBrackets {
        upper_arm: one(ids[0]),
        flange: one(ids[1]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parts(origin: Origin, verdict: Verdict) -> RecordParts {
        RecordParts {
            origin,
            serial: "KR6-0001".into(),
            robot: RecordRobot {
                name: "kuka-kr6-r900-sixx".into(),
                title: "KUKA KR 6 R900 sixx".into(),
                family: "kuka".into(),
                profile_toml: "name = \"kuka-kr6-r900-sixx\"\n".into(),
            },
            export: b"export".to_vec(),
            pendant_unit: None,
            verdict,
            brackets: kept_brackets([None, Some("F-017")]),
            conditions: serde_json::json!({}),
            result_json: "{}".into(),
            joints: Vec::new(),
            harmonics: Vec::new(),
        }
    }

    #[test]
    fn each_origin_gives_its_kind_and_reference_and_the_verdict_its_one_text() {
        let meta = RecordMeta {
            operator: Some("A. Technician".into()),
            measured_on: Some("2026-11-27".into()),
        };
        let session = build(parts(Origin::Session, Verdict::Pass), &meta).unwrap();
        assert_eq!(
            (
                session.kind,
                session.pendant_result_id,
                session.reference_id
            ),
            (RecordKind::Session, None, None)
        );
        assert_eq!(
            (session.verdict.as_str(), session.measured_on.as_str()),
            ("PASS", "2026-11-27")
        );
        let kept = build(
            parts(
                Origin::KeptResult(7),
                Verdict::warn_if_any(vec!["hot".into()]),
            ),
            &meta,
        )
        .unwrap();
        assert_eq!(
            (kept.kind, kept.pendant_result_id, kept.verdict.as_str()),
            (RecordKind::Session, Some(7), "WARN hot")
        );
        assert_eq!(kept.brackets.upper_arm, None);
        assert_eq!(
            kept.brackets.flange,
            Some(RecordBracket {
                id: "F-017".into(),
                calibration: None
            })
        );
        let check = build(
            parts(
                Origin::Check(3),
                Verdict::Fail(vec!["A3".into(), "A5".into()]),
            ),
            &meta,
        )
        .unwrap();
        assert_eq!(
            (check.kind, check.reference_id, check.verdict.as_str()),
            (RecordKind::Check, Some(3), "FAIL A3; A5")
        );
    }
}
