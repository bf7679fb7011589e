//! An upload of the web application: a pendant export recorded under the serial the
//! technician typed, refused where that serial's records are of another robot profile
//! (another robot's export under its serial). The check and the insert are one
//! transaction, the records table locked against another such insert on PostgreSQL
//! (SQLite's writing transaction already excludes every other writer), so that two
//! uploads racing under one new serial cannot both pass it.

use crate::corrections::{correction_in, correction_reason};
use crate::db::{Conn, Value};
use crate::review::insert_audited_in;
use crate::{validate, History, HistoryError, Inserted, NewRecord};

/// The first of `r.serial`'s records whose robot profile is not `r.robot`: its ID and
/// profile name.
fn another_robot_in(c: &mut Conn, r: &NewRecord) -> Result<Option<(i64, String)>, HistoryError> {
    let rows = c.query(
        "SELECT id, robot FROM records WHERE serial = $1 AND robot <> $2 ORDER BY id LIMIT 1",
        &[Value::text(&r.serial), Value::text(&r.robot)],
    )?;
    match rows.first().map(Vec::as_slice) {
        None => Ok(None),
        Some([id, robot]) => Ok(Some((
            id.i64("records.id")?,
            robot.string("records.robot")?,
        ))),
        Some(_) => Err(HistoryError::Corrupt("a records row".into())),
    }
}

impl History {
    /// Stores `r` as [`History::insert_audited`] does (or, with `correction` = the
    /// record it replaces and why, as [`History::insert_correction`] does), only if
    /// every record of its serial is of its robot profile: checked in the insert's
    /// transaction.
    ///
    /// # Errors
    /// [`HistoryError::AnotherRobot`]: a record of the serial is of another robot
    /// profile (nothing stored); otherwise as [`History::insert_audited`] and
    /// [`History::insert_correction`].
    pub fn insert_of_one_robot(
        &mut self,
        actor: &str,
        r: &NewRecord,
        correction: Option<(i64, &str)>,
    ) -> Result<Inserted, HistoryError> {
        validate(r)?;
        let correction = match correction {
            Some((replaces, reason)) => Some((replaces, correction_reason(reason)?)),
            None => None,
        };
        self.conn.write(|c| {
            c.lock_table("records")?;
            if let Some((record_id, stored)) = another_robot_in(c, r)? {
                return Err(HistoryError::AnotherRobot {
                    serial: r.serial.clone(),
                    stored,
                    record_id,
                    export: r.robot.clone(),
                });
            }
            match correction {
                Some((replaces, reason)) => correction_in(c, actor, r, replaces, reason),
                None => insert_audited_in(c, actor, r),
            }
        })
    }
}
