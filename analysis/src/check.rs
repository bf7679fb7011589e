//! `zerocal check EXPORT --against ID`: after the offsets were entered, did the
//! controller take them, with the right sign and unit? The check's export (stage 0
//! and a handful of the plan's poses, `zerocal program --check`) against the session
//! whose offsets were entered ([`crate::compare::entry_check`]); recorded in the history.

use crate::compare::entry_check::{judge, CheckResult, Expected, JointCheck};
use crate::compare::mistake::{classify, EntryJoint, Mistake};
use crate::compare::{CompareOptions, Consistency, DifferenceBudget};
use crate::db::DbArg;
use crate::db::RecordMeta;
use crate::record_builder::{build, record_brackets, Origin, RecordParts, RecordRobot};
use crate::restore::{against, render_budget, Against};
use clap::Args;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;
use zerocal_core::model::JOINTS;
use zerocal_history::{JointRow, NewConvention, NewRecord, Verdict};
use zerocal_inputs::error::CliError;

/// Arguments of `zerocal check`.
#[derive(Args, Debug, Clone)]
pub struct CheckArgs {
    /// The pendant's check export (stage 0 and the check's poses).
    pub export: PathBuf,
    /// The session whose offsets were entered: its record in the history. Range: [1,
    /// 9223372036854775807].
    #[arg(long, value_name = "ID", value_parser = zerocal_inputs::args::RECORD_ID)]
    pub against: i64,
    /// A restore to that session's zero was entered (`zerocal restore`), not its
    /// offsets: nothing should have moved since it.
    #[arg(long)]
    pub restored: bool,
    /// With `--restored`: the export the restore was computed from (the one given to
    /// `zerocal restore`): the restore is solved again and its own uncertainty joins the
    /// tolerance (what is left after a restore is its error as well as the check's).
    /// Without it the restore's is taken as the check's own.
    #[arg(long, value_name = "FILE", requires = "restored")]
    pub restore_export: Option<PathBuf>,
    /// The tolerance per joint (deg; default: three of the check's own standard
    /// uncertainties, from the reference's budget). Range: (0, 1] deg.
    #[arg(long, value_name = "DEG", value_parser = zerocal_inputs::args::RealIn::above(0.0, 1.0, "deg"))]
    pub tolerance_deg: Option<f64>,
    /// How far each stage-0 half turn may be off 180° (deg), as for `zerocal session`.
    /// Range: [0, 10] deg.
    #[arg(long, default_value_t = zerocal_core::session::DEFAULT_HALF_TURN_TOLERANCE_DEG, value_name = "DEG", value_parser = zerocal_inputs::args::RealIn::closed(0.0, 10.0, "deg"))]
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
    /// After an entry: what the controller was to take (the session's Δq, deg).
    pub to_take_deg: Option<f64>,
    /// What is left over what was to be taken, where the offset stands out of the
    /// tolerance: 0 taken, 1 not taken, 2 the sign reversed, `1 − f` a factor `f`.
    pub left_ratio: Option<f64>,
    /// What went wrong with the entry (after an entry, for a joint the check sees).
    pub mistake: Option<Mistake>,
}

/// What the check found of how the controller takes a typed value, per joint.
#[derive(Serialize, Debug, Clone)]
pub struct ConventionFinding {
    /// The controller's name for the joint.
    pub name: String,
    /// The joint, 2-6.
    pub joint: u8,
    /// What the session's numbers assumed the controller takes of a typed value.
    pub assumed_factor: f64,
    /// What it took (the assumed factor times what the check measured).
    pub measured_factor: f64,
    /// The entry was taken as typed: the assumed convention is verified.
    pub verified: bool,
    /// Stored in the history for this robot (a family whose sign or unit is unknown).
    pub recorded: bool,
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
    /// What was expected: the session's offsets entered, or a restore.
    pub expected: Expected,
    /// The test that the export is of the reference's robot, passed.
    pub consistency: Consistency,
    /// How this robot's controller took the entry, per joint (after an entry).
    pub conventions: Vec<ConventionFinding>,
    /// What was assumed.
    pub notes: Vec<String>,
}

/// The linear map from the model's offsets to the controller's (deg per deg), its rows
/// the controller's joints 1-6: what an error of one model offset does to each shown one.
fn controller_map(a: &Against) -> [[f64; JOINTS]; JOINTS] {
    let c = &a.reference.profile.controller;
    let mut m = [[0.0; JOINTS]; JOINTS];
    for i in 0..JOINTS {
        let mut unit = [0.0; JOINTS];
        unit[i] = 1f64.to_radians();
        let column = c.offsets_deg(&unit);
        for (k, row) in m.iter_mut().enumerate() {
            row[i] = column[k];
        }
    }
    m
}

/// What is left in the controller's terms, and each shown joint's tolerance. Joint 2's
/// line is its own; the others' take joint 2 as entered where joint 3's line holds the
/// two together (joint 2 passed, or was not seen).
fn in_controller_terms(a: &Against, r: &CheckResult) -> ([f64; JOINTS], [f64; JOINTS]) {
    let controller = &a.reference.profile.controller;
    let together = r.joints.get(1).is_some_and(|j| j.with_joint2);
    let model = |with_joint2: bool| {
        let mut delta = [0.0; JOINTS];
        for (k, j) in r.joints.iter().enumerate() {
            delta[k + 1] = j.remaining_deg.to_radians();
        }
        if with_joint2 {
            delta[1] = 0.0;
        }
        controller.offsets_deg(&delta)
    };
    let own = model(false);
    let mut shown = model(together);
    shown[1] = own[1];
    let map = controller_map(a);
    let tolerance = core::array::from_fn(|k| {
        r.joints
            .iter()
            .enumerate()
            .filter(|(i, j)| j.pass.is_some() && !(*i == 0 && together && k != 1))
            .map(|(i, j)| (map[k][i + 1] * j.tolerance_deg).powi(2))
            .sum::<f64>()
            .sqrt()
    });
    (shown, tolerance)
}

fn to_json(a: &Against, r: &CheckResult, expected: Expected) -> CheckJson {
    let (shown, tolerance_q) = in_controller_terms(a, r);
    let entries: Vec<EntryJoint> = r
        .joints
        .iter()
        .enumerate()
        .map(|(k, j)| EntryJoint {
            name: j.name.clone(),
            to_take_deg: a.reference.json.joints[k].controller_offset_deg,
            left_deg: shown[k + 1],
            tolerance_deg: tolerance_q[k + 1],
            seen: j.pass.is_some(),
        })
        .collect();
    let entered = expected == Expected::Entered;
    let mistakes = if entered {
        classify(&entries)
    } else {
        vec![None; entries.len()]
    };
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
            .zip(entries)
            .zip(mistakes)
            .enumerate()
            .map(|(k, ((j, e), mistake))| CheckJoint {
                check: j.clone(),
                controller_remaining_deg: shown[k + 1],
                to_take_deg: entered.then_some(e.to_take_deg),
                left_ratio: (entered && e.seen && e.to_take_deg.abs() > e.tolerance_deg)
                    .then(|| e.left_deg / e.to_take_deg),
                mistake,
            })
            .collect(),
        budget: a.comparison.budget.clone(),
        expected,
        consistency: a.comparison.consistency,
        conventions: Vec::new(),
        notes: a.comparison.notes.clone(),
    }
}

/// What the entry says of this robot's conventions: for each joint whose mistake is one
/// of sign or scale (or none), what the controller takes of a typed value, from the
/// factor the session's numbers assumed (its stored record's) times what the check
/// measured; `recorded` where the family leaves that aspect unknown.
fn conventions(a: &Against, j: &CheckJson) -> Vec<ConventionFinding> {
    // The numbers the technician typed: the session's as it printed them (its record).
    let printed: Option<crate::session::SessionJson> =
        serde_json::from_str(&a.record.new.result_json).ok();
    let entry = a.reference.profile.family.entry();
    j.joints
        .iter()
        .enumerate()
        .filter_map(|(k, x)| {
            let f = x.mistake.as_ref()?.factor()?;
            let assumed = printed
                .as_ref()
                .and_then(|p| p.joints.get(k))
                .map_or(1.0, crate::session::JointJson::entry_factor);
            let verified = f == 1.0;
            Some(ConventionFinding {
                name: x.check.name.clone(),
                joint: (k + 2) as u8,
                assumed_factor: assumed,
                measured_factor: assumed * f,
                verified,
                recorded: entry.any_unknown() && entry.learns(f),
            })
        })
        .collect()
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
    let failed: Vec<String> = j
        .joints
        .iter()
        .filter(|x| x.check.pass == Some(false))
        .map(|x| x.check.name.clone())
        .collect();
    build(
        RecordParts {
            origin: Origin::Check(a.record.id),
            serial: reference.serial.clone(),
            robot: RecordRobot::of_record(reference),
            export: a.bytes.clone(),
            pendant_unit: a.export.pendant_unit.clone(),
            verdict: if j.pass {
                Verdict::Pass
            } else {
                Verdict::Fail(failed)
            },
            brackets: record_brackets(&a.export.brackets),
            conditions: serde_json::json!({
                "stage0_temperature_c": a.export.stage0.and_then(|s| s.temperature_c),
                "poses": j.poses,
                "residual_rms_deg": a.comparison.residual_rms_rad.to_degrees(),
                "expected": expected,
                "upper_arm_compared": a.comparison.identifiable[0],
            }),
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
            // A check fits no harmonics.
            harmonics: Vec::new(),
        },
        meta,
    )
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
        "the same robot: the comparison leaves {:.5} deg RMS where two measurements of one \
         robot leave {:.5} deg ({:.1} times; another robot's export is refused above {})",
        j.consistency.residual_rms_deg,
        j.consistency.expected_rms_deg,
        j.consistency.ratio,
        crate::compare::consistency::CONSISTENCY_LIMIT
    );
    let entered = j.expected == Expected::Entered;
    let _ = writeln!(
        out,
        "joint  left_deg    controller_deg  U(k=2)_deg  tolerance_deg  result{}",
        if entered {
            "  left/to enter: what went wrong"
        } else {
            ""
        }
    );
    for joint in &j.joints {
        let c = &joint.check;
        let Some(pass) = c.pass else {
            let _ = writeln!(out, "{:<6} not seen by the check (see the note)", c.name);
            continue;
        };
        let sum = if c.with_joint2 {
            " (with joint 2's: their combination at the flange)"
        } else {
            ""
        };
        let what = match (&joint.mistake, joint.left_ratio) {
            (Some(m), Some(ratio)) if !pass => format!("  {ratio:.3}: {}", m.words()),
            (Some(m), None) if !pass => format!("  {}", m.words()),
            _ => String::new(),
        };
        let _ = writeln!(
            out,
            "{:<6} {:+.5}    {:+.5}        {:.5}     {:.5}        {}{sum}{what}",
            c.name,
            c.remaining_deg,
            joint.controller_remaining_deg,
            c.expanded_k2_deg,
            c.tolerance_deg,
            if pass { "pass" } else { "FAIL" }
        );
    }
    let _ = writeln!(out, "rule: {}", j.rule);
    // A check fits no transmission error (analysis/src/compare: its poses are compared with
    // the reference's model, nothing more is solved).
    let _ = writeln!(
        out,
        "reducers: not measured by a check (its {} poses are compared with the reference's \
         model; no transmission error is fitted); the sessions': zerocal history {} --plot DIR",
        j.poses, j.serial
    );
    render_budget(&mut out, &j.budget);
    for n in &j.notes {
        let _ = writeln!(out, "note: {n}");
    }
    for c in &j.conventions {
        let f = c.measured_factor;
        let how = match (f < 0.0, (f.abs() - 1.0).abs() > 1e-9) {
            (false, false) => "as typed (the controller page's convention)".to_owned(),
            (true, false) => "with its sign reversed".to_owned(),
            (false, true) => format!("times {f:.4} (its unit or gear ratio)"),
            (true, true) => format!(
                "with its sign reversed, times {:.4} (its unit or gear ratio)",
                f.abs()
            ),
        };
        let recorded = match (c.recorded, j.record_id) {
            (true, Some(id)) if c.verified => {
                format!(": verified on this robot, check {id} recorded as its evidence")
            }
            (true, Some(id)) => format!(
                ": recorded for this robot, check {id} its evidence; the next session of it \
                 prints the numbers to type with it"
            ),
            (true, None) => ": not recorded (--no-record)".to_owned(),
            (false, _) => String::new(),
        };
        let _ = writeln!(
            out,
            "convention: {} takes a typed value {how} (factor {f:+.4}){recorded}",
            c.name
        );
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
    } else if entered {
        let _ = writeln!(
            out,
            "check: FAIL {}: the controller did not take these offsets as given (what went \
             wrong is on each joint's line); correct the entry and check again",
            failed.join(" ")
        );
    } else {
        let _ = writeln!(
            out,
            "check: FAIL {}: the restore was not taken as given: compare what was typed with \
             the restore's report",
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
    let restore_combined_deg = match &args.restore_export {
        Some(export) => Some(
            against(&args.db, args.against, export, &options)?
                .comparison
                .budget
                .combined_deg,
        ),
        None => None,
    };
    let result = judge(
        &a.reference,
        &a.comparison,
        expected,
        args.tolerance_deg,
        restore_combined_deg.as_ref(),
    );
    let mut json = to_json(&a, &result, expected);
    json.conventions = conventions(&a, &json);
    if args.no_record {
        for c in &mut json.conventions {
            c.recorded = false;
        }
    } else {
        let record = record_of(&a, &json, expected, &args.meta)?;
        let mut history = args.db.open()?;
        let inserted = history.insert(&record).map_err(crate::db::history_failed)?;
        json.record_id = Some(inserted.id);
        let found: Vec<NewConvention> = json
            .conventions
            .iter()
            .filter(|c| c.recorded)
            .map(|c| NewConvention {
                serial: json.serial.clone(),
                joint: c.joint,
                factor: c.measured_factor,
                check_id: inserted.id,
                verified: c.verified,
            })
            .collect();
        if !found.is_empty() {
            history
                .record_conventions(&found)
                .map_err(crate::db::history_failed)?;
        }
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
