//! The plant's view of the history: every robot with its last session, the session
//! before it, and its last check (a record a correction replaced left out), without the records' exports, results and profiles
//! (listing those for every record of a plant takes seconds: `benches/fleet.rs`), and
//! what the wear rule ([`crate::reducers`]) needs of its reducers: its last session's
//! harmonics, each with the robot's previous session that measured it
//! (`record_harmonics`, typed rows: no result is parsed).

use crate::reducers::{changes, ReducerChange, SessionHarmonics};
use crate::{joint_from_row, History, HistoryError, JointRow, RecordKind, JOINT_COLUMNS};
use serde::Serialize;
use std::collections::BTreeMap;

/// A record as the fleet view needs it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecordSummary {
    /// Its ID.
    pub id: i64,
    /// The day measured, `YYYY-MM-DD`.
    pub measured_on: String,
    /// `PASS`, `WARN ...`, `FAIL ...`.
    pub verdict: String,
    /// Per joint results.
    pub joints: Vec<JointRow>,
}

/// One robot (serial) of the plant.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobotSummary {
    /// The robot's serial.
    pub serial: String,
    /// The profile's name of its last record.
    pub robot: String,
    /// The profile's title of its last record.
    pub robot_title: String,
    /// Its sessions.
    pub sessions: usize,
    /// Its checks.
    pub checks: usize,
    /// The last session measured (by day, then by ID).
    pub last_session: Option<RecordSummary>,
    /// The session measured before it.
    pub previous_session: Option<RecordSummary>,
    /// The last check measured.
    pub last_check: Option<RecordSummary>,
    /// The last session's harmonics (first; empty where it fitted none or there is no
    /// session), then each earlier session of the robot that last measured one of
    /// them, with those harmonics only: what [`RobotSummary::reducer_changes`] compares.
    /// Not serialized: the pages show the changes, not the rows they come from.
    #[serde(skip)]
    pub reducer_sessions: Vec<SessionHarmonics>,
}

/// A joint's change between two sessions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Drift {
    /// The joint, 2..=6.
    pub joint: u8,
    /// Last session's offset minus the previous one's (deg).
    pub change_deg: f64,
    /// The two sessions' U(k = 2) combined, √(U₁² + U₂²) (deg): a change beyond it is
    /// more than the two measurements' own uncertainty.
    pub combined_k2_deg: f64,
}

impl RobotSummary {
    /// Whether the last session fitted any harmonic of its reducers.
    #[must_use]
    pub fn reducers_fitted(&self) -> bool {
        self.reducer_sessions
            .first()
            .is_some_and(|s| !s.reducers.is_empty())
    }

    /// How many of the last session's measured harmonics have an earlier measurement to
    /// be compared with.
    #[must_use]
    pub fn reducers_compared(&self) -> usize {
        let Some((last, before)) = self.reducer_sessions.split_first() else {
            return 0;
        };
        last.reducers
            .iter()
            .filter(|h| {
                h.measured
                    && before.iter().any(|s| {
                        s.reducers
                            .iter()
                            .any(|p| p.joint == h.joint && p.order == h.order)
                    })
            })
            .count()
    }

    /// The last session's harmonics grown beyond the wear rule ([`crate::reducers::changes`])
    /// since the robot's previous session that measured each.
    #[must_use]
    pub fn reducer_changes(&self) -> Vec<ReducerChange> {
        let Some(last) = self.reducer_sessions.first() else {
            return Vec::new();
        };
        let mut out = changes(&self.reducer_sessions);
        out.retain(|c| c.record_id == last.record_id);
        out
    }

    /// Each joint's change from the previous session to the last, where both have it.
    #[must_use]
    pub fn drift(&self) -> Vec<Drift> {
        let (Some(last), Some(before)) = (&self.last_session, &self.previous_session) else {
            return Vec::new();
        };
        last.joints
            .iter()
            .filter_map(|j| {
                let b = before.joints.iter().find(|b| b.joint == j.joint)?;
                Some(Drift {
                    joint: j.joint,
                    change_deg: j.offset_deg - b.offset_deg,
                    combined_k2_deg: j.expanded_k2_deg.hypot(b.expanded_k2_deg),
                })
            })
            .collect()
    }
}

impl History {
    /// Every robot of the history, by serial, with its last and previous session and
    /// its last check (no exports, results or profiles read).
    ///
    /// # Errors
    /// The backend's; a stored value that does not read as the schema says.
    pub fn fleet(&mut self) -> Result<Vec<RobotSummary>, HistoryError> {
        let records = self.conn.query(
            "SELECT id, serial, robot, robot_title, kind, measured_on, verdict FROM records \
             WHERE id NOT IN (SELECT replaces_id FROM corrections) \
             ORDER BY serial, measured_on, id",
            &[],
        )?;
        let mut fleet: Vec<RobotSummary> = Vec::new();
        for row in &records {
            let [id, serial, robot, robot_title, kind, measured_on, verdict] = row.as_slice()
            else {
                return Err(HistoryError::Corrupt(format!(
                    "a records row has {} columns",
                    row.len()
                )));
            };
            let id = id.i64("records.id")?;
            let serial = serial.string("records.serial")?;
            let kind = RecordKind::parse(&kind.string("records.kind")?)?;
            let summary = RecordSummary {
                id,
                measured_on: measured_on.string("records.measured_on")?,
                verdict: verdict.string("records.verdict")?,
                // Read below, for the records the view shows only.
                joints: Vec::new(),
            };
            if fleet.last().is_none_or(|r| r.serial != serial) {
                fleet.push(RobotSummary {
                    serial: serial.clone(),
                    robot: String::new(),
                    robot_title: String::new(),
                    sessions: 0,
                    checks: 0,
                    last_session: None,
                    previous_session: None,
                    last_check: None,
                    reducer_sessions: Vec::new(),
                });
            }
            let Some(robot_now) = fleet.last_mut() else {
                continue;
            };
            robot_now.robot = robot.string("records.robot")?;
            robot_now.robot_title = robot_title.string("records.robot_title")?;
            match kind {
                RecordKind::Session => {
                    robot_now.sessions += 1;
                    robot_now.previous_session = robot_now.last_session.replace(summary);
                }
                RecordKind::Check => {
                    robot_now.checks += 1;
                    robot_now.last_check = Some(summary);
                }
            }
        }
        self.fill_joints(&mut fleet)?;
        crate::record_harmonics::fill_fleet(&mut self.conn, &mut fleet)?;
        Ok(fleet)
    }

    /// Reads the joints of the records `fleet` shows (at most three a robot), not of
    /// every record: a plant's history holds far more.
    fn fill_joints(&mut self, fleet: &mut [RobotSummary]) -> Result<(), HistoryError> {
        let ids: Vec<i64> = fleet
            .iter()
            .flat_map(|r| [&r.last_session, &r.previous_session, &r.last_check])
            .filter_map(|s| s.as_ref().map(|s| s.id))
            .collect();
        let mut joints: BTreeMap<i64, Vec<JointRow>> = BTreeMap::new();
        for list in crate::db::id_lists(&ids) {
            for row in &self.conn.query(
                &format!(
                    "SELECT {JOINT_COLUMNS} FROM joints WHERE record_id IN ({list}) \
                     ORDER BY record_id, joint"
                ),
                &[],
            )? {
                let (id, j) = joint_from_row(row)?;
                joints.entry(id).or_default().push(j);
            }
        }
        for robot in fleet {
            for s in [
                &mut robot.last_session,
                &mut robot.previous_session,
                &mut robot.last_check,
            ]
            .into_iter()
            .flatten()
            {
                s.joints = joints.remove(&s.id).unwrap_or_default();
            }
        }
        Ok(())
    }
}
