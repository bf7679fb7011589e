//! A session as the history keeps it: the export's bytes, the profile's text, the
//! pendant unit and the brackets' calibrations, the conditions, the result in the
//! model's and the controller's terms, and the verdict ([`zerocal_history`]).

use super::Analysis;
use crate::db::RecordMeta;
use crate::error::CliError;
use serde_json::json;
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_history::{JointRow, NewRecord, RecordKind};

/// The brackets as the record keeps them.
pub fn brackets_json(brackets: &Brackets<f64>) -> serde_json::Value {
    let one = |m: BracketMount| match brackets.get(m) {
        Some(c) => json!({
            "mount": m.name(),
            "id": c.id.as_str(),
            "calibrated_on": c.date,
            "rotation_deg": [c.rotation_rad.x_rad.to_degrees(), c.rotation_rad.y_rad.to_degrees()],
            "standard_uncertainty_deg": c.uncertainty_rad.to_degrees(),
            "temperature_c": c.temperature_c,
            "yaw_deg": c.yaw.map(|y| y.yaw_rad.to_degrees()),
            "yaw_standard_uncertainty_deg": c.yaw.map(|y| y.uncertainty_rad.to_degrees()),
        }),
        None => json!({ "mount": m.name(), "calibrated": false }),
    };
    json!(BracketMount::ALL.map(one))
}

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

/// The verdict as stored: `PASS` or `WARN` and the warnings.
pub fn verdict_of(a: &Analysis) -> String {
    if a.json.pass {
        "PASS".to_owned()
    } else {
        format!("WARN {}", a.json.warnings.join("; "))
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
    Ok(NewRecord {
        kind: RecordKind::Session,
        serial: serial.to_owned(),
        robot: a.profile.name.clone(),
        robot_title: a.profile.title.clone(),
        controller_family: a.json.family.clone(),
        profile_toml: a.profile_toml.clone(),
        export: export.to_vec(),
        measured_on: meta.day()?,
        operator: meta.operator.clone(),
        pendant_unit: a.export.pendant_unit.clone(),
        pendant_result_id: None,
        reference_id: None,
        zerocal_version: env!("CARGO_PKG_VERSION").to_owned(),
        verdict: verdict_of(a),
        brackets_json: brackets_json(&a.export.brackets).to_string(),
        conditions_json: conditions_json(a).to_string(),
        result_json: serde_json::to_string(&a.json).map_err(|e| CliError::Input(e.to_string()))?,
        joints,
    })
}
