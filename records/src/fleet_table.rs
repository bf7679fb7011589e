//! `zerocal history --fleet`: the plant's robots at a glance, one line each: the last
//! session and check with their verdicts, when the next session is due (with
//! `--due-days`), and each joint's drift since the session before, marked where it is
//! beyond the two sessions' combined U(k = 2) (`zerocal_history::History::fleet`, which
//! reads no export, result or profile).

use serde::Serialize;
use std::fmt::Write as _;
use zerocal_civil::Date;
use zerocal_history::{Drift, RecordSummary, RobotSummary};
use zerocal_inputs::error::CliError;

/// `--due-days`: a day to ten years.
pub const DUE_DAYS: zerocal_inputs::args::CountIn<u32> =
    zerocal_inputs::args::CountIn::new(1, 3653);

/// One robot in `--fleet --json`.
#[derive(Serialize, Debug)]
pub struct FleetRow<'a> {
    /// What the history holds of it.
    #[serde(flatten)]
    pub robot: &'a RobotSummary,
    /// Each joint's change since the session before.
    pub drift: Vec<Drift>,
    /// The joints whose change is beyond the combined U(k = 2).
    pub drifted: Vec<u8>,
    /// The last session's day plus `--due-days`, if given and there is a session.
    pub due_on: Option<String>,
    /// Whether `due_on` is before `today`.
    pub overdue: bool,
}

/// The rows of `fleet`, `due_days` after each last session, overdue against `today`.
///
/// # Errors
/// A stored session day that is not a date.
pub fn rows<'a>(
    fleet: &'a [RobotSummary],
    due_days: Option<u32>,
    today: Date,
) -> Result<Vec<FleetRow<'a>>, CliError> {
    fleet
        .iter()
        .map(|robot| {
            let drift = robot.drift();
            let drifted = drift
                .iter()
                .filter(|d| d.change_deg.abs() > d.combined_k2_deg)
                .map(|d| d.joint)
                .collect();
            let due = match (due_days, &robot.last_session) {
                (Some(days), Some(s)) => {
                    let day = Date::parse(&s.measured_on).map_err(|e| {
                        CliError::Input(format!(
                            "record {}: measured_on {:?} is not a date: {e}",
                            s.id, s.measured_on
                        ))
                    })?;
                    Some(Date::from_days(day.days() + i64::from(days)))
                }
                _ => None,
            };
            Ok(FleetRow {
                robot,
                drift,
                drifted,
                overdue: due.is_some_and(|d| d.days() < today.days()),
                due_on: due.map(|d| d.to_string()),
            })
        })
        .collect()
}

fn record_cell(r: Option<&RecordSummary>) -> String {
    r.map_or_else(
        || "-".to_owned(),
        |r| format!("{} #{} {}", r.measured_on, r.id, r.verdict),
    )
}

/// The table: a line per robot.
#[must_use]
pub fn table(rows: &[FleetRow<'_>]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<16} {:<20} {:<30} {:<30} {:<12} drift since the session before (deg; * beyond both sessions' U(k=2))",
        "serial", "robot", "last session", "last check", "due"
    );
    for r in rows {
        let due = match (&r.due_on, r.overdue) {
            (Some(d), true) => format!("{d} OVERDUE"),
            (Some(d), false) => d.clone(),
            (None, _) => "-".to_owned(),
        };
        let drift = if r.drift.is_empty() {
            "-".to_owned()
        } else {
            r.drift
                .iter()
                .map(|d| {
                    let mark = if r.drifted.contains(&d.joint) {
                        "*"
                    } else {
                        ""
                    };
                    format!("j{} {:+.4}{mark}", d.joint, d.change_deg)
                })
                .collect::<Vec<_>>()
                .join(" ")
        };
        let _ = writeln!(
            out,
            "{:<16} {:<20} {:<30} {:<30} {:<12} {drift}",
            r.robot.serial,
            r.robot.robot,
            record_cell(r.robot.last_session.as_ref()),
            record_cell(r.robot.last_check.as_ref()),
            due,
        );
    }
    out
}
