//! A session as the history keeps it: the export's bytes, the profile's text, the
//! pendant unit and the brackets' calibrations, the conditions, the result in the
//! model's and the controller's terms, and the verdict ([`zerocal_history`]).

use super::Analysis;
use crate::db::RecordMeta;
use crate::record_builder::{build, record_brackets, Origin, RecordParts, RecordRobot};
use serde_json::json;
use zerocal_history::{JointRow, NewRecord, Verdict};
use zerocal_inputs::error::CliError;

/// The conditions: the stages' temperatures and the base's tilt.
fn conditions_json(a: &Analysis) -> serde_json::Value {
    let temps: Vec<f64> = a
        .export
        .poses
        .iter()
        .filter_map(|p| p.temperature_c)
        .collect();
    let lo = temps.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = temps.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    json!({
        "stage0_temperature_c": a.export.stage0.and_then(|s| s.temperature_c),
        "stage1_temperature_c": a.export.stage1_temperature_c,
        "closing_temperature_c": a.export.closing.and_then(|s| s.temperature_c),
        "stage2_temperature_c": if temps.is_empty() { json!(null) } else { json!([lo, hi]) },
        "base_tilt_deg": a.json.base_tilt_deg,
        "poses": a.json.poses,
        "residual_rms_deg": a.json.residual_rms_deg,
    })
}

/// The session's verdict: its warnings, if any.
pub fn verdict_of(a: &Analysis) -> Verdict {
    if a.json.pass {
        Verdict::Pass
    } else {
        Verdict::Warn(a.json.warnings.clone())
    }
}

/// A session's record.
///
/// # Errors
/// The result does not serialise (never for a finite result).
pub fn session_record(
    a: &Analysis,
    export: &[u8],
    serial: &str,
    meta: &RecordMeta,
) -> Result<NewRecord, CliError> {
    let joints = a
        .json
        .joints
        .iter()
        .enumerate()
        .map(|(k, j)| JointRow {
            joint: (k + 2) as u8,
            name: j.name.clone(),
            offset_deg: j.offset_deg,
            expanded_k2_deg: j.expanded_k2_deg,
            controller_offset_deg: j.controller_offset_deg,
            pass: None,
        })
        .collect();
    build(
        RecordParts {
            origin: Origin::Session,
            serial: serial.to_owned(),
            robot: RecordRobot {
                family: a.json.family.clone(),
                ..RecordRobot::of_profile(&a.profile, &a.profile_toml)
            },
            export: export.to_vec(),
            pendant_unit: a.export.pendant_unit.clone(),
            verdict: verdict_of(a),
            brackets: record_brackets(&a.export.brackets),
            conditions: conditions_json(a),
            result_json: serde_json::to_string(&a.json)
                .map_err(|e| CliError::Input(e.to_string()))?,
            joints,
            harmonics: a.json.reducers.clone(),
        },
        meta,
    )
}
