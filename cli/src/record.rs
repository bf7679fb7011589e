//! What the history keeps of a session or a check: the export's bytes, the profile's
//! text, the pendant unit and the brackets' calibrations, the conditions, the result
//! in the model's and the controller's terms, and the verdict ([`zerocal_history`]).
//! And the way back: a stored session solved again exactly as it was.

use crate::error::CliError;
use crate::session::{analyse_with, Analysis, SessionArgs};
use clap::Args;
use serde_json::json;
use std::path::PathBuf;
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_history::{JointRow, NewRecord, Record, RecordKind};

pub use crate::history::DbArg;

/// A history error as the CLI's.
pub fn history_error(e: zerocal_history::HistoryError) -> CliError {
    CliError::Input(format!("history: {e}"))
}

/// Who recorded, when: the options every recording command shares.
#[derive(Args, Debug, Clone, Default)]
pub struct RecordMeta {
    /// Who measured (stored with the record, printed on its certificate).
    #[arg(long, value_name = "NAME")]
    pub operator: Option<String>,
    /// The day measured, YYYY-MM-DD (default: today, UTC).
    #[arg(long, value_name = "DAY")]
    pub measured_on: Option<String>,
}

impl RecordMeta {
    /// The day measured.
    ///
    /// # Errors
    /// `--measured-on` that is not a day.
    pub fn day(&self) -> Result<String, CliError> {
        match &self.measured_on {
            Some(d) => crate::brackets::calibration_date(d)
                .map_err(|_| CliError::Input(format!("--measured-on '{d}': not a day YYYY-MM-DD"))),
            None => Ok(crate::brackets::today_utc()),
        }
    }
}

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

/// A stored session solved again, as it was: its export with its own profile.
///
/// # Errors
/// A record of a check, or one the solver now refuses (a record of another version).
pub fn solve_record(record: &Record) -> Result<Analysis, CliError> {
    if record.new.kind != RecordKind::Session {
        return Err(CliError::Input(format!(
            "record {} is a {}, not a session: give a session's ID",
            record.id,
            record.new.kind.as_str()
        )));
    }
    if record.new.pendant_result_id.is_some()
        && !record.new.export.starts_with(b"# zerocal pendant export")
    {
        return Err(CliError::Input(format!(
            "record {}: {}",
            record.id,
            crate::import::KEPT_RESULT_NOTE
        )));
    }
    let profile = zerocal_profile::parse(&record.new.profile_toml).map_err(|e| {
        CliError::Input(format!(
            "record {}: its robot profile does not read: {e}",
            record.id
        ))
    })?;
    let args = SessionArgs::for_export(PathBuf::from(format!("record {}", record.id)));
    analyse_with(
        &args,
        &record.new.export,
        Some((profile, record.new.profile_toml.clone())),
    )
}
