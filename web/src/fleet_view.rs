//! The fleet page's rows: every robot with its last session and check, its next due
//! day, each joint's drift since the session before against the two sessions' combined
//! U(k = 2), its reducers' harmonics grown beyond the wear rule since the robot's
//! previous session that measured each (`RobotSummary::reducer_changes`, the one rule of
//! `zerocal_history::reducers`), sorted and filtered as the query asks
//! (`History::fleet`, which reads no export, result or profile: the page stays quick at
//! a plant's size).

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use zerocal_civil::Date;
use zerocal_history::RobotSummary;

/// The fleet page's query:
/// `?sort=serial|due|drift|wear|verdict&q=TEXT&only=due|failed|drifted|wearing`.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
pub struct FleetQuery {
    /// The column to sort by: `serial` (default), `due` (soonest first), `drift`
    /// (largest first), `wear` (the harmonic grown by the most standard uncertainties
    /// first), `verdict` (failed checks first).
    pub sort: Option<String>,
    /// Keep the robots whose serial, profile or title holds this text.
    pub q: Option<String>,
    /// Keep only the robots `due` (overdue), `failed` (last check not PASS),
    /// `drifted` (a joint beyond its combined U) or `wearing` (a reducer's harmonic
    /// grown beyond the wear rule).
    pub only: Option<String>,
}

/// The calibration intervals: a robot is due this many days after its last session,
/// its model's own interval (by the robot profile's name) where one is set, else the
/// plant's.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Intervals {
    /// The plant's interval, for every model without its own; `None`: those robots
    /// show no due date.
    pub days: Option<u32>,
    /// Each model's own interval, by robot profile name.
    pub by_model: BTreeMap<String, u32>,
}

impl Intervals {
    /// The interval of a robot of profile `model` and whether it is the model's own
    /// (`false`: the plant's); `None` where neither is set.
    #[must_use]
    pub fn of(&self, model: &str) -> Option<(u32, bool)> {
        match self.by_model.get(model) {
            Some(days) => Some((*days, true)),
            None => self.days.map(|d| (d, false)),
        }
    }
}

/// One robot's row.
#[derive(Debug, Clone, Serialize)]
pub struct FleetRow {
    /// What the history holds of it.
    pub robot: RobotSummary,
    /// Each joint's change since the previous session: (joint, change deg, combined U deg, beyond).
    pub drift: Vec<(u8, f64, f64, bool)>,
    /// The largest |change| / combined U of its joints (0 without two sessions).
    pub worst_drift_ratio: f64,
    /// The last session's day plus the interval, if one is set and there is a session.
    pub due_on: Option<String>,
    /// The interval that applied (days), if one is set.
    pub interval_days: Option<u32>,
    /// Whether it is the robot model's own interval (else the plant's).
    pub interval_of_model: bool,
    /// Whether `due_on` is before today.
    pub overdue: bool,
    /// Whether the last check did not pass.
    pub check_failed: bool,
    /// The reducers' column: nothing fitted, nothing to compare with, no growth beyond
    /// the rule, or the harmonics grown beyond it.
    pub reducers: Reducers,
    /// The largest growth among `reducers`, in standard uncertainties (0 without one).
    pub worst_wear_sigmas: f64,
}

/// A robot's reducers as its last session left them, by the wear rule.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "state", content = "grown", rename_all = "snake_case")]
pub enum Reducers {
    /// The last session fitted no harmonic (or there is no session).
    NotFitted,
    /// The last session held every harmonic at its prior: it measured none.
    NotMeasured,
    /// None of its measured harmonics was measured by an earlier session.
    NotCompared,
    /// No measured harmonic grew beyond the rule.
    Ok,
    /// These grew beyond it: (joint, order, increase deg, increase in standard
    /// uncertainties), in joint and order.
    Wearing(Vec<(u8, u8, f64, f64)>),
}

impl Reducers {
    /// The column of `robot`.
    #[must_use]
    pub fn of(robot: &RobotSummary) -> Reducers {
        if !robot.reducers_fitted() {
            return Reducers::NotFitted;
        }
        let measured_any = robot
            .reducer_sessions
            .first()
            .is_some_and(|last| last.reducers.iter().any(|h| h.measured));
        if !measured_any {
            return Reducers::NotMeasured;
        }
        let grown: Vec<(u8, u8, f64, f64)> = robot
            .reducer_changes()
            .iter()
            .map(|c| (c.joint, c.order, c.increase_deg, c.sigmas()))
            .collect();
        if !grown.is_empty() {
            Reducers::Wearing(grown)
        } else if robot.reducers_compared() == 0 {
            Reducers::NotCompared
        } else {
            Reducers::Ok
        }
    }
}

/// The rows of `fleet`, each due its model's interval of `intervals` after its last
/// session (overdue against `today`), filtered and sorted by `query`.
///
/// # Errors
/// A query naming a sort or filter that does not exist.
pub fn rows(
    fleet: Vec<RobotSummary>,
    intervals: &Intervals,
    today: Date,
    query: &FleetQuery,
) -> Result<Vec<FleetRow>, String> {
    let needle = query.q.as_deref().unwrap_or("").to_lowercase();
    let only = query.only.as_deref().filter(|o| !o.is_empty());
    if let Some(o) = only {
        if !["due", "failed", "drifted", "wearing"].contains(&o) {
            return Err(format!(
                "only={o:?} is none of due, failed, drifted, wearing"
            ));
        }
    }
    let mut rows: Vec<FleetRow> = fleet
        .into_iter()
        .filter(|r| {
            needle.is_empty()
                || [&r.serial, &r.robot, &r.robot_title]
                    .iter()
                    .any(|f| f.to_lowercase().contains(&needle))
        })
        .map(|robot| {
            let drift: Vec<(u8, f64, f64, bool)> = robot
                .drift()
                .iter()
                .map(|d| {
                    (
                        d.joint,
                        d.change_deg,
                        d.combined_k2_deg,
                        d.change_deg.abs() > d.combined_k2_deg,
                    )
                })
                .collect();
            let worst_drift_ratio = drift
                .iter()
                .map(|(_, c, u, _)| if *u > 0.0 { c.abs() / u } else { 0.0 })
                .fold(0.0, f64::max);
            // A stored day that is not a date has no due day (the history validates
            // every day it stores; this is a corrupt row, shown without one).
            let interval = intervals.of(&robot.robot);
            let due = match (interval, &robot.last_session) {
                (Some((days, _)), Some(s)) => Date::parse(&s.measured_on)
                    .ok()
                    .map(|d| Date::from_days(d.days() + i64::from(days))),
                _ => None,
            };
            let check_failed = robot
                .last_check
                .as_ref()
                .is_some_and(|c| c.verdict != zerocal_history::PASS);
            let reducers = Reducers::of(&robot);
            let worst_wear_sigmas = match &reducers {
                Reducers::Wearing(grown) => grown.iter().map(|g| g.3).fold(0.0, f64::max),
                _ => 0.0,
            };
            FleetRow {
                reducers,
                worst_wear_sigmas,
                drift,
                worst_drift_ratio,
                overdue: due.is_some_and(|d| d.days() < today.days()),
                due_on: due.map(|d| d.to_string()),
                interval_days: interval.map(|(d, _)| d),
                interval_of_model: interval.is_some_and(|(_, own)| own),
                check_failed,
                robot,
            }
        })
        .filter(|r| match only {
            Some("due") => r.overdue,
            Some("failed") => r.check_failed,
            Some("drifted") => r.drift.iter().any(|d| d.3),
            Some("wearing") => matches!(r.reducers, Reducers::Wearing(_)),
            _ => true,
        })
        .collect();
    match query.sort.as_deref().unwrap_or("serial") {
        "serial" | "" => {}
        // Fleet order is by serial already; the others keep it among equals.
        "due" => rows.sort_by(|a, b| {
            a.due_on
                .is_none()
                .cmp(&b.due_on.is_none())
                .then(a.due_on.cmp(&b.due_on))
        }),
        "drift" => rows.sort_by(|a, b| b.worst_drift_ratio.total_cmp(&a.worst_drift_ratio)),
        "wear" => rows.sort_by(|a, b| b.worst_wear_sigmas.total_cmp(&a.worst_wear_sigmas)),
        "verdict" => rows.sort_by_key(|r| !r.check_failed),
        other => {
            return Err(format!(
                "sort={other:?} is none of serial, due, drift, wear, verdict"
            ))
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_history::RecordSummary;

    fn robot(serial: &str, model: &str, last_session: &str) -> RobotSummary {
        RobotSummary {
            serial: serial.into(),
            robot: model.into(),
            robot_title: model.into(),
            sessions: 1,
            checks: 0,
            last_session: Some(RecordSummary {
                id: 1,
                measured_on: last_session.into(),
                verdict: "PASS".into(),
                joints: Vec::new(),
            }),
            previous_session: None,
            last_check: None,
            reducer_sessions: Vec::new(),
        }
    }

    fn due(rows: &[FleetRow]) -> Vec<(&str, Option<&str>, Option<u32>, bool)> {
        rows.iter()
            .map(|r| {
                (
                    r.robot.serial.as_str(),
                    r.due_on.as_deref(),
                    r.interval_days,
                    r.interval_of_model,
                )
            })
            .collect()
    }

    #[test]
    fn a_model_with_its_own_interval_is_due_by_it_and_the_others_by_the_plants() {
        let fleet = || {
            vec![
                robot("R1", "kuka-kr6-r900-sixx", "2026-05-04"),
                robot("R2", "ur5e", "2026-05-04"),
            ]
        };
        let today = Date::parse("2026-11-29").unwrap();
        let query = FleetQuery::default();
        let mut intervals = Intervals {
            days: Some(365),
            by_model: BTreeMap::from([("kuka-kr6-r900-sixx".to_owned(), 180)]),
        };
        let got = rows(fleet(), &intervals, today, &query).unwrap();
        assert_eq!(
            due(&got),
            [
                ("R1", Some("2026-10-31"), Some(180), true),
                ("R2", Some("2027-05-04"), Some(365), false),
            ]
        );
        assert!(got[0].overdue && !got[1].overdue);
        // Without the plant's interval only the model with its own is due.
        intervals.days = None;
        let got = rows(fleet(), &intervals, today, &query).unwrap();
        assert_eq!(
            due(&got),
            [
                ("R1", Some("2026-10-31"), Some(180), true),
                ("R2", None, None, false),
            ]
        );
    }
}
