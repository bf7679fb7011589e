//! `zerocal restore EXPORT --reference ID`: after a motor or gearbox change, the
//! offsets that bring each joint back to the zero it had at a reference session taken
//! while the robot was healthy, so that taught programs do not shift. EXPORT is a
//! check's export (stage 0 and the check's poses) or a whole session's; the
//! comparison is [`crate::compare`], its budget that of a difference.
//!
//! Also the shared part of `zerocal check`: the reference record solved again and the
//! export read.

use crate::compare::{compare, CompareError, CompareOptions, Comparison, DifferenceBudget};
use crate::db::DbArg;
use crate::session::{read_export, Analysis, ExportContents};
use clap::Args;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use zerocal_core::model::JOINTS;
use zerocal_core::session::SESSION_JOINTS;
use zerocal_history::Record;
use zerocal_inputs::error::CliError;

/// Arguments of `zerocal restore`.
#[derive(Args, Debug, Clone)]
pub struct RestoreArgs {
    /// The pendant's export after the change (its check, or a whole session).
    pub export: PathBuf,
    /// The reference: the history's record of a session taken while the robot was
    /// healthy (`zerocal history SN` lists them). Range: [1, 9223372036854775807].
    #[arg(long, value_name = "ID", value_parser = zerocal_inputs::args::RECORD_ID)]
    pub reference: i64,
    /// A joint whose gearbox (reducer) was changed, 3-6 (repeat for more): its
    /// transmission error is then not the reference's, and the budget says so. Range:
    /// [3, 6].
    #[arg(long = "gearbox-replaced", value_name = "JOINT", value_parser = zerocal_inputs::args::CountIn::<u8>::new(3, 6))]
    pub gearbox_replaced: Vec<u8>,
    /// How far each stage-0 half turn may be off 180° (deg), as for `zerocal session`
    /// (default: by hand, 1). Range: [0, 10] deg.
    #[arg(long, default_value_t = zerocal_core::session::DEFAULT_HALF_TURN_TOLERANCE_DEG, value_name = "DEG", value_parser = zerocal_inputs::args::RealIn::closed(0.0, 10.0, "deg"))]
    pub half_turn_tolerance_deg: f64,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub db: DbArg,
}

/// A measurement against a stored reference.
pub struct Against {
    /// The reference's record.
    pub record: Record,
    /// The reference solved again.
    pub reference: Analysis,
    /// The measurement's bytes.
    pub bytes: Vec<u8>,
    /// The measurement as read.
    pub export: ExportContents,
    /// What moved.
    pub comparison: Comparison,
}

/// Reads `export`, solves the reference record `id` again and compares.
///
/// # Errors
/// An unreadable export or record, another robot's export, a comparison refused.
pub fn against(
    db: &DbArg,
    id: i64,
    export: &Path,
    options: &CompareOptions,
) -> Result<Against, CliError> {
    let mut history = db.open()?;
    let record = history.get(id).map_err(crate::db::history_failed)?;
    let reference = crate::stored_session::solve_record(&record)?;
    let bytes = zerocal_inputs::input::read_capped_bytes(
        export,
        zerocal_inputs::input::MAX_EXPORT_BYTES,
        "pendant export",
    )?;
    let name = |what: &str| format!("{}: {what}", export.display());
    let text = zerocal_procedure::log::text_of(&bytes)
        .map_err(|e| CliError::Input(name(&e.to_string())))?;
    let contents = read_export(text).map_err(|e| CliError::Input(name(&e)))?;
    match &contents.robot {
        Some((robot, _)) if *robot == reference.profile.name => {}
        Some((robot, _)) => {
            return Err(CliError::Input(name(&format!(
                "the export is for robot {robot}, record {id} for {}",
                reference.profile.name
            ))))
        }
        None => {
            return Err(CliError::Input(name(
                "no `# robot` line: not a pendant export",
            )))
        }
    }
    let comparison = compare(&reference, &contents, options).map_err(|e| match e {
        CompareError::OtherRobot(_) => CliError::Refused(name(&format!(
            "record {id} is robot {}'s ({}), and this export is {e}; give the ID of this \
             robot's own session (zerocal history SERIAL lists them)",
            record.new.serial, reference.profile.name
        ))),
        e => CliError::Refused(name(&e.to_string())),
    })?;
    Ok(Against {
        record,
        reference,
        bytes,
        export: contents,
        comparison,
    })
}

/// One joint of the restore.
#[derive(Serialize, Debug, Clone)]
pub struct RestoreJoint {
    /// The controller's name.
    pub name: String,
    /// Measured (joint 2 only from the upper arm's readings; a held twin never).
    pub measured: bool,
    /// How far its zero moved since the reference (deg, model terms).
    pub moved_deg: f64,
    /// Expanded uncertainty of the move, k = 2 (deg).
    pub expanded_k2_deg: f64,
    /// The restore in the controller's terms: its reading must move by this (deg).
    pub controller_dq_deg: f64,
    /// The same in the controller's offset unit, where known.
    pub controller_in_unit: Option<f64>,
    /// The unit.
    pub controller_unit: String,
    /// Why there is no value in the unit.
    pub controller_unit_missing: Option<String>,
}

/// `zerocal restore --json`.
#[derive(Serialize, Debug, Clone)]
pub struct RestoreJson {
    /// The reference record.
    pub reference_id: i64,
    /// The robot's serial.
    pub serial: String,
    /// Its controller family.
    pub family: String,
    /// Where the controller keeps its zeros.
    pub controller_offset_where: String,
    /// Poses compared.
    pub poses: usize,
    /// The comparison's residual RMS (deg).
    pub residual_rms_deg: f64,
    /// Joints 2-6.
    pub joints: Vec<RestoreJoint>,
    /// The budget of the difference.
    pub budget: DifferenceBudget,
    /// What was assumed.
    pub notes: Vec<String>,
}

/// The move in the controller's terms: its reading must move by the model's move
/// (true − commanded) to read again what it read at the reference.
pub fn to_json(a: &Against) -> RestoreJson {
    let c = &a.comparison;
    let profile = &a.reference.profile;
    let mut delta = [0.0; JOINTS];
    let mut cov = [[0.0; JOINTS]; JOINTS];
    for k in 0..SESSION_JOINTS {
        delta[k + 1] = c.moved_rad[k];
        cov[k + 1][k + 1] = c.budget.combined_deg[k].to_radians().powi(2);
    }
    // Joint 3's own move: the flange's less joint 2's share, where joint 2 was compared.
    let (j3_moved_deg, j3_u_deg) = c.joint3_own();
    delta[2] = j3_moved_deg.to_radians();
    cov[2][2] = j3_u_deg.to_radians().powi(2);
    let controller = profile.controller.offsets(&delta, &cov);
    let expanded = |k: usize| {
        if k == 1 {
            j3_u_deg * zerocal_core::session::COVERAGE_FACTOR
        } else {
            c.budget.expanded_deg[k]
        }
    };
    let joints = (0..SESSION_JOINTS)
        .map(|k| RestoreJoint {
            name: profile.joints[k + 1].name.clone(),
            measured: c.identifiable[k],
            moved_deg: delta[k + 1].to_degrees(),
            expanded_k2_deg: expanded(k),
            controller_dq_deg: controller[k + 1].shown_deg,
            controller_in_unit: controller[k + 1].in_unit,
            controller_unit: profile.controller.unit.name().to_owned(),
            controller_unit_missing: controller[k + 1].no_unit_because.map(str::to_owned),
        })
        .collect();
    RestoreJson {
        reference_id: a.record.id,
        serial: a.record.new.serial.clone(),
        family: a.reference.json.family.clone(),
        controller_offset_where: a.reference.json.controller_offset_where.clone(),
        poses: c.poses,
        residual_rms_deg: c.residual_rms_rad.to_degrees(),
        joints,
        budget: c.budget.clone(),
        notes: c.notes.clone(),
    }
}

/// The budget of a difference as text: the terms that stay, then those that cancel.
pub fn render_budget(out: &mut String, b: &DifferenceBudget) {
    let _ = writeln!(
        out,
        "\nuncertainty of the difference (standard uncertainties, deg; GUM, k = 2):"
    );
    // Joint 2's column where the upper arm was compared.
    let from = if b.expanded_deg[0] > 0.0 { 0 } else { 1 };
    let row = |out: &mut String, name: &str, v: &[f64; SESSION_JOINTS]| {
        let _ = write!(out, "{name:<70}");
        for u in &v[from..] {
            let _ = write!(out, "  {u:.5}");
        }
        let _ = writeln!(out);
    };
    let _ = write!(out, "{:<70}", "term");
    for k in from..SESSION_JOINTS {
        let _ = write!(out, "  j{:<6}", k + 2);
    }
    let _ = writeln!(out);
    for t in &b.terms {
        row(out, &t.term, &t.standard_uncertainty_deg);
    }
    row(out, "expanded, k = 2", &b.expanded_deg);
    let _ = writeln!(
        out,
        "cancelled: common to the reference and this measurement (the reference's values):"
    );
    for t in &b.cancelled {
        row(out, &t.term, &t.standard_uncertainty_deg);
    }
}

/// The report as text.
pub fn render(j: &RestoreJson) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "zerocal restore: robot {} against record {}: {} poses compared, residual RMS {:.5} deg",
        j.serial, j.reference_id, j.poses, j.residual_rms_deg
    );
    let _ = writeln!(
        out,
        "joint  moved_deg   U(k=2)_deg   restore: the reading must move by ({}; {})",
        j.family, j.controller_offset_where
    );
    for joint in &j.joints {
        if !joint.measured {
            let _ = writeln!(
                out,
                "{:<6} not measured: taken as unchanged (see the note)",
                joint.name
            );
            continue;
        }
        let unit = match (joint.controller_in_unit, &joint.controller_unit_missing) {
            (Some(v), _) => format!("{v:+.6} {}", joint.controller_unit),
            (None, Some(why)) => format!("({why})"),
            (None, None) => String::new(),
        };
        let _ = writeln!(
            out,
            "{:<6} {:+.5}    {:.5}      {:+.5} deg   {unit}",
            joint.name, joint.moved_deg, joint.expanded_k2_deg, joint.controller_dq_deg
        );
    }
    let _ = writeln!(
        out,
        "enter each as a session's offset is entered: docs/controllers/{}.md says where and with which sign; then check it (zerocal check EXPORT --against {} --restored)",
        j.family, j.reference_id
    );
    render_budget(&mut out, &j.budget);
    for n in &j.notes {
        let _ = writeln!(out, "note: {n}");
    }
    out
}

/// Runs `zerocal restore`.
///
/// # Errors
/// As [`against`].
pub fn run(args: &RestoreArgs) -> Result<String, CliError> {
    let mut options = CompareOptions {
        half_turn_tolerance_deg: args.half_turn_tolerance_deg,
        ..CompareOptions::default()
    };
    for j in &args.gearbox_replaced {
        if let Some(g) = options.gearbox_replaced.get_mut(usize::from(*j) - 2) {
            *g = true;
        }
    }
    let a = against(&args.db, args.reference, &args.export, &options)?;
    let json = to_json(&a);
    if args.json {
        return serde_json::to_string_pretty(&json).map_err(|e| CliError::Input(e.to_string()));
    }
    Ok(render(&json))
}
