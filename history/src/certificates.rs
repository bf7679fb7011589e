//! The certificates issued: each one's number (unique across every machine that issues
//! one: the CLI makes it from a random UUID), the session it certifies (as found), the
//! check after the entry (as left, if any), its issue date, and who issued it with which
//! equipment (the issuer's configuration, as JSON). The same session, check and issuer
//! give the same certificate again: its number and date are kept.

use crate::db::Value;
use crate::{invalid, sha256_hex, History, HistoryError, RecordKind};
use serde::{Deserialize, Serialize};

/// The most characters a certificate number may have.
pub const MAX_NUMBER_CHARS: usize = 64;

/// A certificate to record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NewCertificate {
    /// Its number.
    pub number: String,
    /// The session certified (as found).
    pub session_id: i64,
    /// The check after the session's offsets were entered (as left).
    pub as_left_id: Option<i64>,
    /// The issue date, `YYYY-MM-DD`.
    pub issued_on: String,
    /// The issuer: laboratory, customer, site and equipment (JSON text).
    pub issuer_json: String,
}

/// A recorded certificate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct IssuedCertificate {
    /// When it was stored, UTC RFC 3339.
    pub recorded_at: String,
    /// SHA-256 of its issuer JSON.
    pub issuer_sha256: String,
    /// What was recorded.
    pub new: NewCertificate,
}

const COLUMNS: &str =
    "number, session_id, as_left_id, issued_on, issuer_json, issuer_sha256, recorded_at";

fn from_row(row: &[Value]) -> Result<IssuedCertificate, HistoryError> {
    let [number, session_id, as_left_id, issued_on, issuer_json, issuer_sha256, recorded_at] = row
    else {
        return Err(HistoryError::Corrupt(format!(
            "a certificates row has {} columns",
            row.len()
        )));
    };
    Ok(IssuedCertificate {
        recorded_at: recorded_at.string("certificates.recorded_at")?,
        issuer_sha256: issuer_sha256.string("certificates.issuer_sha256")?,
        new: NewCertificate {
            number: number.string("certificates.number")?,
            session_id: session_id.i64("certificates.session_id")?,
            as_left_id: as_left_id.opt_i64("certificates.as_left_id")?,
            issued_on: issued_on.string("certificates.issued_on")?,
            issuer_json: issuer_json.string("certificates.issuer_json")?,
        },
    })
}

fn kind_of(c: &mut crate::db::Conn, id: i64) -> Result<(String, Option<i64>), HistoryError> {
    let rows = c.query(
        "SELECT kind, reference_id FROM records WHERE id = $1",
        &[Value::Int(Some(id))],
    )?;
    match rows.first().map(Vec::as_slice) {
        Some([kind, reference]) => Ok((
            kind.string("records.kind")?,
            reference.opt_i64("records.reference_id")?,
        )),
        Some(_) => Err(HistoryError::Corrupt("a records row".into())),
        None => Err(invalid(format!("record {id} does not exist"))),
    }
}

/// Who asks for a certificate: a signed-in user of the web application.
#[derive(Clone, Copy, Debug)]
pub struct CertificateRequest<'a> {
    /// Their user name (the audit's actor).
    pub name: &'a str,
    /// Whether their role issues certificates (a first one gets a number).
    pub may_issue: bool,
}

impl History {
    /// Records `c`, or gives the certificate already issued for the same session,
    /// as-left check and issuer (its number and date kept, `false`).
    ///
    /// # Errors
    /// [`HistoryError::InvalidRecord`]: an empty or over-long number, an issue date that
    /// is not a calendar date, a session that is not a session record, an as-left record
    /// that is not a check of that session, issuer text that is not JSON, a number
    /// already given to another certificate.
    pub fn issue_certificate(
        &mut self,
        c: &NewCertificate,
    ) -> Result<(IssuedCertificate, bool), HistoryError> {
        self.issue_certificate_by(c, None)
    }

    /// [`Self::issue_certificate`] asked for by a signed-in user (`by`, where given): a
    /// first issue written to the audit log as theirs in the same transaction (no
    /// certificate without its entry), and refused where they may not issue one.
    ///
    /// # Errors
    /// As [`Self::issue_certificate`]; [`HistoryError::Refused`] where `by` may not
    /// issue and no certificate of the same session, as-left check and issuer exists.
    pub fn issue_certificate_by(
        &mut self,
        c: &NewCertificate,
        by: Option<CertificateRequest<'_>>,
    ) -> Result<(IssuedCertificate, bool), HistoryError> {
        let chars = c.number.chars().count();
        if chars == 0 || chars > MAX_NUMBER_CHARS || c.number.chars().any(char::is_control) {
            return Err(invalid(format!(
                "certificate number {:?}: 1 to {MAX_NUMBER_CHARS} printable characters",
                c.number
            )));
        }
        if let Err(e) = zerocal_civil::Date::parse(&c.issued_on) {
            return Err(invalid(format!(
                "issued_on {:?} is not a calendar date YYYY-MM-DD: {e}",
                c.issued_on
            )));
        }
        serde_json::from_str::<serde_json::Value>(&c.issuer_json)
            .map_err(|e| invalid(format!("issuer_json is not JSON: {e}")))?;
        let issuer_sha256 = sha256_hex(c.issuer_json.as_bytes());
        let recorded_at = zerocal_civil::Timestamp::clock().to_string();
        self.conn.write(|conn| {
            let (kind, _) = kind_of(conn, c.session_id)?;
            if kind != RecordKind::Session.as_str() {
                return Err(invalid(format!(
                    "record {} is a {kind}: a certificate is for a session",
                    c.session_id
                )));
            }
            if let Some(left) = c.as_left_id {
                let (kind, reference) = kind_of(conn, left)?;
                if kind != RecordKind::Check.as_str() || reference != Some(c.session_id) {
                    return Err(invalid(format!(
                        "record {left} is not a check against session {}: it cannot be its \
                         as-left",
                        c.session_id
                    )));
                }
            }
            let key = [
                Value::Int(Some(c.session_id)),
                Value::Int(Some(c.as_left_id.unwrap_or(0))),
                Value::text(&issuer_sha256),
            ];
            let existing = conn.query(
                &format!(
                    "SELECT {COLUMNS} FROM certificates WHERE session_id = $1 \
                     AND COALESCE(as_left_id, 0) = $2 AND issuer_sha256 = $3"
                ),
                &key,
            )?;
            if let Some(row) = existing.first() {
                return Ok((from_row(row)?, false));
            }
            if let Some(by) = by.filter(|b| !b.may_issue) {
                return Err(HistoryError::Refused(format!(
                    "record {} has no certificate for this as-left check and issuer yet, and {} may not issue one",
                    c.session_id, by.name
                )));
            }
            let taken = conn.query(
                "SELECT number FROM certificates WHERE number = $1",
                &[Value::text(&c.number)],
            )?;
            if !taken.is_empty() {
                return Err(invalid(format!(
                    "certificate number {:?} is already given",
                    c.number
                )));
            }
            conn.execute(
                "INSERT INTO certificates (number, session_id, as_left_id, issued_on, \
                 issuer_json, issuer_sha256, recorded_at) VALUES ($1, $2, $3, $4, $5, $6, $7)",
                &[
                    Value::text(&c.number),
                    Value::Int(Some(c.session_id)),
                    Value::Int(c.as_left_id),
                    Value::text(&c.issued_on),
                    Value::text(&c.issuer_json),
                    Value::text(&issuer_sha256),
                    Value::text(&recorded_at),
                ],
            )?;
            if let Some(by) = by {
                crate::review::audit_in(
                    conn,
                    by.name,
                    "certificate.issue",
                    &format!("record {}", c.session_id),
                    None,
                    &serde_json::json!({
                        "number": c.number, "session_id": c.session_id, "issued_on": c.issued_on,
                    }),
                )?;
            }
            Ok((
                IssuedCertificate {
                    recorded_at: recorded_at.clone(),
                    issuer_sha256: issuer_sha256.clone(),
                    new: c.clone(),
                },
                true,
            ))
        })
    }

    /// Every certificate issued for session `session_id`, in number order.
    ///
    /// # Errors
    /// The backend's.
    pub fn certificates_of(
        &mut self,
        session_id: i64,
    ) -> Result<Vec<IssuedCertificate>, HistoryError> {
        self.conn
            .query(
                &format!(
                    "SELECT {COLUMNS} FROM certificates WHERE session_id = $1 ORDER BY recorded_at, number"
                ),
                &[Value::Int(Some(session_id))],
            )?
            .iter()
            .map(|r| from_row(r))
            .collect()
    }

    /// The checks against `session_id` (its as-left candidates), in ID order.
    ///
    /// # Errors
    /// The backend's.
    pub fn checks_against(&mut self, session_id: i64) -> Result<Vec<crate::Record>, HistoryError> {
        let serial = self.get(session_id)?.new.serial;
        Ok(self
            .list(Some(&serial))?
            .into_iter()
            .filter(|r| r.new.kind == RecordKind::Check && r.new.reference_id == Some(session_id))
            .collect())
    }
}
