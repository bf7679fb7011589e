//! Corrections: no record is edited or deleted in place; a correction is a new record
//! (of the same serial and kind) that names the one it replaces, with the reason and
//! who made it, written with its audit entry in one transaction. A record is replaced
//! at most once; the replaced one stays, readable, and the fleet view leaves it out.

use crate::db::{Conn, Value};
use crate::review::audit_in;
use crate::{insert_in, validate, History, HistoryError, Inserted, NewRecord};
use serde::Serialize;
use serde_json::json;

/// A correction as stored.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Correction {
    /// The new record.
    pub record_id: i64,
    /// The record it replaces.
    pub replaces_id: i64,
    /// Why.
    pub reason: String,
    /// Who made it.
    pub user_name: String,
    /// When, UTC RFC 3339.
    pub recorded_at: String,
}

impl History {
    /// Stores `r` as the correction of record `replaces`, for `reason`, by `actor`.
    ///
    /// # Errors
    /// [`HistoryError::Refused`]: no such record, another serial's or kind's, already
    /// replaced, an empty reason, or `r`'s export already stored (then it is no new
    /// record); [`HistoryError::InvalidRecord`] as for [`History::insert`].
    pub fn insert_correction(
        &mut self,
        actor: &str,
        r: &NewRecord,
        replaces: i64,
        reason: &str,
    ) -> Result<Inserted, HistoryError> {
        validate(r)?;
        let reason = correction_reason(reason)?;
        self.conn
            .write(|c| correction_in(c, actor, r, replaces, reason))
    }

    /// The corrections among `serial`'s records, oldest first.
    ///
    /// # Errors
    /// The backend's.
    pub fn corrections(&mut self, serial: &str) -> Result<Vec<Correction>, HistoryError> {
        self.conn
            .query(
                "SELECT record_id, replaces_id, reason, user_name, recorded_at FROM corrections \
                 WHERE record_id IN (SELECT id FROM records WHERE serial = $1) ORDER BY record_id",
                &[Value::text(serial)],
            )?
            .iter()
            .map(|row| {
                let [id, replaces, reason, user, at] = row.as_slice() else {
                    return Err(HistoryError::Corrupt("a corrections row".into()));
                };
                Ok(Correction {
                    record_id: id.i64("corrections.record_id")?,
                    replaces_id: replaces.i64("corrections.replaces_id")?,
                    reason: reason.string("corrections.reason")?,
                    user_name: user.string("corrections.user_name")?,
                    recorded_at: at.string("corrections.recorded_at")?,
                })
            })
            .collect()
    }
}

/// [`History::insert_correction`]'s work in the caller's writing transaction (`reason`
/// trimmed and not empty).
pub(crate) fn correction_in(
    c: &mut Conn,
    actor: &str,
    r: &NewRecord,
    replaces: i64,
    reason: &str,
) -> Result<Inserted, HistoryError> {
    let rows = c.query(
        "SELECT serial, kind, (SELECT record_id FROM corrections WHERE replaces_id = $1) \
                 FROM records WHERE id = $1",
        &[Value::Int(Some(replaces))],
    )?;
    let Some([serial, kind, replaced_by]) = rows.first().map(Vec::as_slice) else {
        return Err(HistoryError::Refused(format!(
            "record {replaces} does not exist"
        )));
    };
    let (serial, kind) = (
        serial.string("records.serial")?,
        kind.string("records.kind")?,
    );
    if serial != r.serial || kind != r.kind.as_str() {
        return Err(HistoryError::Refused(format!(
            "record {replaces} is a {kind} of serial {serial:?}: a correction is a {} of \
                     serial {:?}",
            r.kind.as_str(),
            r.serial
        )));
    }
    if let Some(by) = replaced_by.opt_i64("corrections.record_id")? {
        return Err(HistoryError::Refused(format!(
            "record {replaces} is already replaced by record {by}"
        )));
    }
    let inserted = insert_in(c, r)?;
    if !inserted.new {
        return Err(HistoryError::Refused(format!(
            "this export is already record {}: a correction is a new record",
            inserted.id
        )));
    }
    let at = zerocal_civil::Timestamp::clock().to_string();
    c.execute(
        "INSERT INTO corrections (record_id, replaces_id, reason, user_name, recorded_at) \
                 VALUES ($1, $2, $3, $4, $5)",
        &[
            Value::Int(Some(inserted.id)),
            Value::Int(Some(replaces)),
            Value::text(reason),
            Value::text(actor),
            Value::text(&at),
        ],
    )?;
    let before = json!({ "id": replaces, "replaced_by": null });
    let after = json!({
        "id": replaces, "replaced_by": inserted.id, "reason": reason,
        "new_record": { "id": inserted.id, "serial": r.serial, "kind": r.kind.as_str(),
            "measured_on": r.measured_on, "operator": r.operator, "verdict": r.verdict,
            "export_sha256": crate::sha256_hex(&r.export) },
    });
    let subject = format!("record {replaces}");
    audit_in(c, actor, "record.correct", &subject, Some(&before), &after)?;
    Ok(inserted)
}

/// A correction's reason, trimmed.
///
/// # Errors
/// [`HistoryError::Refused`]: an empty reason.
pub(crate) fn correction_reason(reason: &str) -> Result<&str, HistoryError> {
    let reason = reason.trim();
    if reason.is_empty() {
        return Err(HistoryError::Refused(
            "a correction states its reason".into(),
        ));
    }
    Ok(reason)
}
