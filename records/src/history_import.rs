//! `zerocal history SERIAL --import FILE`: the pendant's kept results (`zerocal pendant
//! results`, or the `.results` file beside `zerocal pendant export --out`) into the
//! history, each once: a result is its own lines (unit and ID among them), so importing
//! the same file twice stores nothing new.
//!
//! A kept result holds the pendant's offsets and their 1σ, not the readings: its
//! record's U(k = 2) is twice the fit's 1σ (the pendant keeps no budget), and the
//! record says so; it cannot be certified or checked against (those solve the export
//! again). Record the export itself for that (`zerocal session EXPORT --record`).

use serde_json::json;
use zerocal_analysis::db::RecordMeta;
use zerocal_analysis::record_builder::{build, kept_brackets, Origin, RecordParts, RecordRobot};
use zerocal_analysis::stored_session::KEPT_RESULT_NOTE;
use zerocal_core::session::COVERAGE_FACTOR;
use zerocal_history::{History, Inserted, JointRow, NewRecord, Verdict};
use zerocal_inputs::error::CliError;
use zerocal_procedure::kept::VERDICT_WORDS;
use zerocal_procedure::log::{read_kept_results, write_kept_result, Line, KEPT_RESULT_LINES};
use zerocal_procedure::KeptResult;

/// The kept result's own lines, as the pendant writes them: the record's bytes.
fn lines_of(k: &KeptResult) -> Result<String, CliError> {
    let mut text = String::new();
    for part in 0..KEPT_RESULT_LINES {
        let mut line = Line::new();
        write_kept_result(&mut line, k, part)
            .map_err(|_| CliError::Input(format!("kept result {}: a line too long", k.id)))?;
        text.push_str(line.as_str());
        text.push('\n');
    }
    Ok(text)
}

fn record_of(k: &KeptResult, serial: &str, meta: &RecordMeta) -> Result<NewRecord, CliError> {
    let (profile, profile_toml) = zerocal_inputs::robot::load_with_text(k.robot.as_str())?;
    let offsets = k.offsets_deg.map(f64::from);
    let sigma = k.sigma_deg.map(f64::from);
    let mut delta = [0.0; zerocal_core::model::JOINTS];
    for (d, o) in delta[1..].iter_mut().zip(&offsets) {
        *d = o.to_radians();
    }
    let shown = profile.controller.offsets_deg(&delta);
    let joints = (0..offsets.len())
        .map(|i| JointRow {
            joint: (i + 2) as u8,
            name: profile.joints[i + 1].name.clone(),
            offset_deg: offsets[i],
            expanded_k2_deg: COVERAGE_FACTOR * sigma[i],
            controller_offset_deg: shown[i + 1],
            pass: None,
        })
        .collect();
    let warnings: Vec<String> = VERDICT_WORDS
        .iter()
        .enumerate()
        .filter(|(bit, _)| k.warnings & (1 << bit) != 0)
        .map(|(_, w)| (*w).to_owned())
        .collect();
    let unit = k.unit.map(|u| u.to_string());
    let brackets = kept_brackets([k.brackets[0].as_deref(), k.brackets[1].as_deref()]);
    let [stage0, stage1, closing] = k.temperatures_c.map(|t| t.map(f64::from));
    build(
        RecordParts {
            origin: Origin::KeptResult(k.id),
            serial: serial.to_owned(),
            robot: RecordRobot::of_profile(&profile, &profile_toml),
            export: lines_of(k)?.into_bytes(),
            pendant_unit: unit.clone(),
            verdict: Verdict::warn_if_any(warnings),
            brackets,
            conditions: json!({
                "stage0_temperature_c": stage0,
                "stage1_temperature_c": stage1,
                "closing_temperature_c": closing,
                "residual_rms_deg": f64::from(k.residual_rms_deg),
            }),
            result_json: json!({
                "kept_result_id": k.id,
                "pendant_unit": unit,
                "offsets_deg": offsets,
                "sigma_deg": sigma,
                "note": KEPT_RESULT_NOTE,
            })
            .to_string(),
            joints,
            harmonics: Vec::new(),
        },
        meta,
    )
}

/// Imports every kept result of `text` under `serial`: each once.
///
/// # Errors
/// A malformed kept-result line (named), a robot profile not built in, the history.
pub fn import(
    history: &mut History,
    text: &str,
    serial: &str,
    meta: &RecordMeta,
) -> Result<Vec<(u32, Inserted)>, CliError> {
    let kept =
        read_kept_results(text).map_err(|e| CliError::Input(format!("kept results: {e}")))?;
    if kept.is_empty() {
        return Err(CliError::Input(
            "no kept results in the file (their lines start '# kept_result'): read them with \
             zerocal pendant results"
                .into(),
        ));
    }
    kept.iter()
        .map(|k| {
            let record = record_of(k, serial, meta)?;
            let inserted = history
                .insert(&record)
                .map_err(zerocal_analysis::db::history_failed)?;
            Ok((k.id, inserted))
        })
        .collect()
}
