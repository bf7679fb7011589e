//! How one robot's controller takes a typed zero offset, as checks measured it: per
//! joint, the factor the controller applied to the value typed (−1: the sign the
//! controller's page could not settle is reversed on this robot; another factor: its
//! unit or gear ratio), each row with the check that measured or verified it as its
//! evidence. The latest row of a serial's joint is the convention in force; a session of
//! that serial prints the numbers to type with it.

use crate::db::Value;
use crate::{invalid, History, HistoryError, RecordKind, JOINTS};
use serde::{Deserialize, Serialize};

/// A convention to record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NewConvention {
    /// The robot's serial.
    pub serial: String,
    /// The joint, 2..=6.
    pub joint: u8,
    /// What the controller took over what was typed (finite, not 0).
    pub factor: f64,
    /// The check that measured it: a check record of the same serial.
    pub check_id: i64,
    /// The check found the entry taken with this factor already in force (a
    /// verification), rather than measuring a new one.
    pub verified: bool,
}

/// A recorded convention.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Convention {
    /// Its ID, in recording order.
    pub id: i64,
    /// When it was stored, UTC RFC 3339.
    pub recorded_at: String,
    /// What was recorded.
    pub new: NewConvention,
}

const COLUMNS: &str = "id, recorded_at, serial, joint, factor, check_id, verified";

fn from_row(row: &[Value]) -> Result<Convention, HistoryError> {
    let [id, recorded_at, serial, joint, factor, check_id, verified] = row else {
        return Err(HistoryError::Corrupt(format!(
            "a conventions row has {} columns",
            row.len()
        )));
    };
    let id = id.i64("conventions.id")?;
    let joint_no = joint.i64("conventions.joint")?;
    let joint = u8::try_from(joint_no)
        .ok()
        .filter(|j| JOINTS.contains(j))
        .ok_or_else(|| HistoryError::Corrupt(format!("convention {id}: joint {joint_no}")))?;
    let verified = match verified.i64("conventions.verified")? {
        0 => false,
        1 => true,
        v => {
            return Err(HistoryError::Corrupt(format!(
                "convention {id}: verified {v}"
            )))
        }
    };
    Ok(Convention {
        id,
        recorded_at: recorded_at.string("conventions.recorded_at")?,
        new: NewConvention {
            serial: serial.string("conventions.serial")?,
            joint,
            factor: factor.f64("conventions.factor")?,
            check_id: check_id.i64("conventions.check_id")?,
            verified,
        },
    })
}

impl History {
    /// Records the conventions one check measured, all or none; a check's conventions
    /// are recorded once (again: nothing changes). Returns how many were new.
    ///
    /// # Errors
    /// [`HistoryError::InvalidRecord`]: a joint outside 2..=6, a factor that is not a
    /// finite non-zero number, a check that is not a check record of that serial.
    pub fn record_conventions(
        &mut self,
        conventions: &[NewConvention],
    ) -> Result<usize, HistoryError> {
        for c in conventions {
            if !JOINTS.contains(&c.joint) {
                return Err(invalid(format!(
                    "convention: joint {} is outside 2..=6",
                    c.joint
                )));
            }
            if !c.factor.is_finite() || c.factor == 0.0 {
                return Err(invalid(format!(
                    "convention of joint {}: factor {} is not a finite non-zero number",
                    c.joint, c.factor
                )));
            }
        }
        let recorded_at = zerocal_civil::Timestamp::clock().to_string();
        self.conn.write(|c| {
            let mut new = 0;
            for conv in conventions {
                let rows = c.query(
                    "SELECT serial, kind FROM records WHERE id = $1",
                    &[Value::Int(Some(conv.check_id))],
                )?;
                let Some(row) = rows.first() else {
                    return Err(invalid(format!(
                        "convention: check record {} does not exist",
                        conv.check_id
                    )));
                };
                let (serial, kind) = match row.as_slice() {
                    [s, k] => (s.string("records.serial")?, k.string("records.kind")?),
                    _ => return Err(HistoryError::Corrupt("a records row".into())),
                };
                if kind != RecordKind::Check.as_str() || serial != conv.serial {
                    return Err(invalid(format!(
                        "convention: record {} is a {kind} of serial {serial:?}, not a check of {:?}",
                        conv.check_id, conv.serial
                    )));
                }
                let inserted = c.query(
                    "INSERT INTO conventions (recorded_at, serial, joint, factor, check_id, \
                     verified) VALUES ($1, $2, $3, $4, $5, $6) \
                     ON CONFLICT (check_id, joint) DO NOTHING RETURNING id",
                    &[
                        Value::text(&recorded_at),
                        Value::text(&conv.serial),
                        Value::Int(Some(i64::from(conv.joint))),
                        Value::Real(Some(conv.factor)),
                        Value::Int(Some(conv.check_id)),
                        Value::Int(Some(i64::from(conv.verified))),
                    ],
                )?;
                new += inserted.len();
            }
            Ok(new)
        })
    }

    /// Every convention recorded for `serial`, in recording order: the last of a joint is
    /// the one in force.
    ///
    /// # Errors
    /// The backend's.
    pub fn conventions(&mut self, serial: &str) -> Result<Vec<Convention>, HistoryError> {
        self.conn
            .query(
                &format!("SELECT {COLUMNS} FROM conventions WHERE serial = $1 ORDER BY id"),
                &[Value::text(serial)],
            )?
            .iter()
            .map(|r| from_row(r))
            .collect()
    }
}
