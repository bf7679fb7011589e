//! `zerocal check EXPORT --against ID`: after the offsets were entered, did the
//! controller take them, with the right sign and unit? The check's export (stage 0
//! and a handful of the plan's poses, `zerocal program --check`) against the session
//! whose offsets were entered ([`crate::compare::check`]); recorded in the history.

use crate::compare::check::{judge, CheckResult, Expected, JointCheck};
use crate::compare::{CompareOptions, DifferenceBudget};
use crate::db::DbArg;
use crate::db::RecordMeta;
use crate::error::CliError;
use crate::restore::{against, render_budget, Against};
use clap::Args;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;
use zerocal_core::model::JOINTS;
use zerocal_history::{JointRow, NewRecord, RecordKind};

/// Arguments of `zerocal check`.
#[derive(Args, Debug, Clone)]
pub struct CheckArgs {
    /// The pendant's check export (stage 0 and the check's poses).
    pub export: PathBuf,
    /// The session whose offsets were entered: its record in the history. Range: [1,
    /// 9223372036854775807].
    #[arg(long, value_name = "ID", value_parser = crate::args::RECORD_ID)]
    pub against: i64,
    /// A restore to that session's zero was entered (`zerocal restore`), not its
    /// offsets: nothing should have moved since it.
    #[arg(long)]
    pub restored: bool,
    /// The tolerance per joint (deg; default: three of the check's own standard
    /// uncertainties, from the reference's budget). Range: (0, 1] deg.
    #[arg(long, value_name = "DEG", value_parser = crate::args::RealIn::above(0.0, 1.0, "deg"))]
    pub tolerance_deg: Option<f64>,
    /// How far each stage-0 half turn may be off 180° (deg), as for `zerocal session`.
    /// Range: [0, 10] deg.
    #[arg(long, default_value_t = zerocal_core::session::DEFAULT_HALF_TURN_TOLERANCE_DEG, value_name = "DEG", value_parser = crate::args::RealIn::closed(0.0, 10.0, "deg"))]
    pub half_turn_tolerance_deg: f64,
    /// Do not store the check in the history.
    #[arg(long)]
    pub no_record: bool,
    #[command(flatten)]
    pub meta: RecordMeta,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub db: DbArg,
}

/// One joint in `--json`: the check and what is left in the controller's terms.
#[derive(Serialize, Debug, Clone)]
pub struct CheckJoint {
    /// The check.
    #[serde(flatten)]
    pub check: JointCheck,
    /// What is left as the controller shows the joint (deg).
    pub controller_remaining_deg: f64,
}

/// `zerocal check --json`.
#[derive(Serialize, Debug, Clone)]
pub struct CheckJson {
    /// The reference record.
    pub reference_id: i64,
    /// This check's record, when stored.
    pub record_id: Option<i64>,
    /// The robot's serial.
    pub serial: String,
    /// Every checked joint within its tolerance.
    pub pass: bool,
    /// The rule.
    pub rule: String,
    /// Poses compared.
    pub poses: usize,
    /// Joints 2-6.
    pub joints: Vec<CheckJoint>,
    /// The check's budget.
    pub budget: DifferenceBudget,
    /// What was assumed.
    pub notes: Vec<String>,
}

fn to_json(a: &Against, r: &CheckResult) -> CheckJson {
    let mut delta = [0.0; JOINTS];
    for (k, j) in r.joints.iter().enumerate() {
        delta[k + 1] = j.remaining_deg.to_radians();
    }
    let shown = a.reference.profile.controller.offsets_deg(&delta);
    CheckJson {
        reference_id: a.record.id,
        record_id: None,
        serial: a.record.new.serial.clone(),
        pass: r.pass,
        rule: r.rule.clone(),
        poses: a.comparison.poses,
        joints: r
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| CheckJoint {
                check: j.clone(),
                controller_remaining_deg: shown[k + 1],
            })
            .collect(),
        budget: a.comparison.budget.clone(),
        notes: a.comparison.notes.clone(),
    }
}

/// The check as the history keeps it. Each joint's offset is the one a session would
/// measure now (what is left after an entry; the reference's offset plus the move after
/// a restore), so the history's plot of a joint's zero puts a check beside the sessions.
fn record_of(
    a: &Against,
    j: &CheckJson,
    expected: Expected,
    meta: &RecordMeta,
) -> Result<NewRecord, CliError> {
    let base = |k: usize| match expected {
        Expected::Entered => 0.0,
        Expected::Restored => a.reference.json.joints[k].offset_deg,
    };
    let mut now = [0.0; JOINTS];
    for (k, x) in j.joints.iter().enumerate() {
        now[k + 1] = (base(k) + x.check.remaining_deg).to_radians();
    }
    let shown = a.reference.profile.controller.offsets_deg(&now);
    let reference = &a.record.new;
    let failed: Vec<&str> = j
        .joints
        .iter()
        .filter(|x| x.check.pass == Some(false))
        .map(|x| x.check.name.as_str())
        .collect();
    Ok(NewRecord {
        kind: RecordKind::Check,
        serial: reference.serial.clone(),
        robot: reference.robot.clone(),
        robot_title: reference.robot_title.clone(),
        controller_family: reference.controller_family.clone(),
        profile_toml: reference.profile_toml.clone(),
        export: a.bytes.clone(),
        measured_on: meta.day()?,
        operator: meta.operator.clone(),
        pendant_unit: a.export.pendant_unit.clone(),
        pendant_result_id: None,
        reference_id: Some(a.record.id),
        zerocal_version: env!("CARGO_PKG_VERSION").to_owned(),
        verdict: if j.pass {
            "PASS".to_owned()
        } else {
            format!("FAIL {}", failed.join(" "))
        },
        brackets_json: crate::session::brackets_json(&a.export.brackets).to_string(),
        conditions_json: serde_json::json!({
            "stage0_temperature_c": a.export.stage0.and_then(|s| s.temperature_c),
            "poses": j.poses,
            "residual_rms_deg": a.comparison.residual_rms_rad.to_degrees(),
        })
        .to_string(),
        result_json: serde_json::to_string(j).map_err(|e| CliError::Input(e.to_string()))?,
        joints: j
            .joints
            .iter()
            .enumerate()
            .filter(|(_, x)| x.check.pass.is_some())
            .map(|(k, x)| JointRow {
                joint: (k + 2) as u8,
                name: x.check.name.clone(),
                offset_deg: base(k) + x.check.remaining_deg,
                expanded_k2_deg: x.check.expanded_k2_deg,
                controller_offset_deg: shown[k + 1],
                pass: x.check.pass,
            })
            .collect(),
    })
}

/// The report as text.
pub fn render(j: &CheckJson) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "zerocal check: robot {} against record {}: {} poses compared",
        j.serial, j.reference_id, j.poses
    );
    let _ = writeln!(
        out,
        "joint  left_deg    controller_deg  U(k=2)_deg  tolerance_deg  result"
    );
    for (k, joint) in j.joints.iter().enumerate() {
        let c = &joint.check;
        let Some(pass) = c.pass else {
            let _ = writeln!(out, "{:<6} not seen by the check (see the note)", c.name);
            continue;
        };
        let sum = if k == 1 {
            " (with joint 2: their sum)"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "{:<6} {:+.5}    {:+.5}        {:.5}     {:.5}        {}{sum}",
            c.name,
            c.remaining_deg,
            joint.controller_remaining_deg,
            c.expanded_k2_deg,
            c.tolerance_deg,
            if pass { "pass" } else { "FAIL" }
        );
    }
    let _ = writeln!(out, "rule: {}", j.rule);
    render_budget(&mut out, &j.budget);
    for n in &j.notes {
        let _ = writeln!(out, "note: {n}");
    }
    if let Some(id) = j.record_id {
        let _ = writeln!(out, "recorded: record {id}");
    }
    let failed: Vec<&str> = j
        .joints
        .iter()
        .filter(|x| x.check.pass == Some(false))
        .map(|x| x.check.name.as_str())
        .collect();
    if j.pass {
        let _ = writeln!(out, "check: PASS");
    } else {
        let _ = writeln!(
            out,
            "check: FAIL {}: the controller did not take these offsets as given (a sign, a unit, a joint mixed up, a value not activated): compare what was typed with the session's report",
            failed.join(" ")
        );
    }
    out
}

/// Runs `zerocal check`: the report, or [`CliError::Failed`] with it (exit status 4).
///
/// # Errors
/// As [`against`]; a failed check.
pub fn run(args: &CheckArgs) -> Result<String, CliError> {
    let options = CompareOptions {
        half_turn_tolerance_deg: args.half_turn_tolerance_deg,
        ..CompareOptions::default()
    };
    let a = against(&args.db, args.against, &args.export, &options)?;
    let expected = if args.restored {
        Expected::Restored
    } else {
        Expected::Entered
    };
    let result = judge(&a.reference, &a.comparison, expected, args.tolerance_deg);
    let mut json = to_json(&a, &result);
    if !args.no_record {
        let record = record_of(&a, &json, expected, &args.meta)?;
        let mut history = args.db.open()?;
        let inserted = history.insert(&record).map_err(crate::db::history_failed)?;
        json.record_id = Some(inserted.id);
    }
    let out = if args.json {
        serde_json::to_string_pretty(&json).map_err(|e| CliError::Input(e.to_string()))?
    } else {
        render(&json)
    };
    if json.pass {
        Ok(out)
    } else {
        Err(CliError::Failed(out))
    }
}
