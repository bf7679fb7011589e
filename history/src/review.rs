//! What the web application keeps in the history (schema 5), so that several servers
//! over one database share it and none holds state of its own: the users and their
//! roles, the signed-in sessions with their CSRF tokens, the login attempts the flood
//! limit counts, the signatures that move a record from measured to checked to
//! authorized, and the append-only audit log.
//!
//! Every change here is written in one transaction with its audit entry (who, when,
//! what, before and after as JSON): a change is never stored without its entry, nor an
//! entry without its change. Nothing here updates or deletes a record or an audit
//! entry; the API has no statement that would.

use crate::db::{Conn, Value};
use crate::{insert_in, validate, History, HistoryError, Inserted, NewRecord};
use serde::Serialize;
use serde_json::json;

/// What a user may do. Each role is one step of the work; an administrator manages
/// the accounts (and signs nothing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Role {
    /// Records sessions (uploads exports).
    Technician,
    /// Checks a measured record.
    Reviewer,
    /// Authorizes a checked record.
    Authorizer,
    /// Manages the users.
    Admin,
}

impl Role {
    /// Every role, in the order of the work.
    pub const ALL: [Role; 4] = [
        Role::Technician,
        Role::Reviewer,
        Role::Authorizer,
        Role::Admin,
    ];

    /// As stored and typed: `technician`, `reviewer`, `authorizer`, `admin`.
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Technician => "technician",
            Self::Reviewer => "reviewer",
            Self::Authorizer => "authorizer",
            Self::Admin => "admin",
        }
    }

    /// The role named `s`.
    ///
    /// # Errors
    /// A name that is none of [`Role::ALL`]'s, named in the message.
    pub fn parse(s: &str) -> Result<Role, String> {
        Self::ALL
            .into_iter()
            .find(|r| r.as_str() == s)
            .ok_or_else(|| format!("role {s:?} is none of technician, reviewer, authorizer, admin"))
    }
}

/// A user account.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct User {
    /// The sign-in name.
    pub name: String,
    /// What the user may do.
    pub role: Role,
    /// The password's Argon2 hash, a PHC string (never the password).
    #[serde(skip)]
    pub password_phc: String,
    /// Whether the account may sign in.
    pub active: bool,
    /// When it was made, UTC RFC 3339.
    pub created_at: String,
}

/// A step of a record's review after it was measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SignStep {
    /// Checked by a reviewer.
    Checked,
    /// Authorized by an authorizer, after it was checked.
    Authorized,
}

impl SignStep {
    /// As stored: `checked`, `authorized`.
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Checked => "checked",
            Self::Authorized => "authorized",
        }
    }

    /// What the step's signer does: `checks`, `authorizes`.
    #[must_use]
    pub fn verb(self) -> &'static str {
        match self {
            Self::Checked => "checks",
            Self::Authorized => "authorizes",
        }
    }

    /// The role that signs this step.
    #[must_use]
    pub fn role(self) -> Role {
        match self {
            Self::Checked => Role::Reviewer,
            Self::Authorized => Role::Authorizer,
        }
    }

    /// The step named `s`.
    ///
    /// # Errors
    /// Neither `checked` nor `authorized`.
    pub fn parse(s: &str) -> Result<SignStep, String> {
        match s {
            "checked" => Ok(Self::Checked),
            "authorized" => Ok(Self::Authorized),
            other => Err(format!("step {other:?} is neither checked nor authorized")),
        }
    }
}

/// A signature on a record.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Signature {
    /// The step signed.
    pub step: SignStep,
    /// Who signed.
    pub user_name: String,
    /// When, UTC RFC 3339.
    pub signed_at: String,
}

/// One entry of the audit log.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct AuditEntry {
    /// Its number, in the order written.
    pub id: i64,
    /// When, UTC RFC 3339.
    pub at: String,
    /// Who (a user's name).
    pub actor: String,
    /// What, e.g. `record.insert`, `user.add`, `record.sign`.
    pub action: String,
    /// What it was done to, e.g. `record 12`, `user ana`.
    pub subject: String,
    /// The state before (JSON), `None` for something new.
    pub before_json: Option<String>,
    /// The state after (JSON).
    pub after_json: String,
}

/// A signed-in session as stored.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WebSession {
    /// Its user (active).
    pub user: User,
    /// The CSRF token every form of this session carries.
    pub csrf_token: String,
}

const USER_COLUMNS: &str = "name, role, password_phc, active, created_at";

fn user_from_row(row: &[Value]) -> Result<User, HistoryError> {
    let [name, role, phc, active, created_at] = row else {
        return Err(HistoryError::Corrupt(format!(
            "a users row has {} columns",
            row.len()
        )));
    };
    Ok(User {
        name: name.string("users.name")?,
        role: Role::parse(&role.string("users.role")?).map_err(HistoryError::Corrupt)?,
        password_phc: phc.string("users.password_phc")?,
        active: active.i64("users.active")? == 1,
        created_at: created_at.string("users.created_at")?,
    })
}

fn user_in(c: &mut Conn, name: &str) -> Result<Option<User>, HistoryError> {
    c.query(
        &format!("SELECT {USER_COLUMNS} FROM users WHERE name = $1"),
        &[Value::text(name)],
    )?
    .first()
    .map(|r| user_from_row(r))
    .transpose()
}

fn user_json(u: &User) -> serde_json::Value {
    json!({ "name": u.name, "role": u.role.as_str(), "active": u.active })
}

/// Writes an audit entry inside the transaction `c`.
pub(crate) fn audit_in(
    c: &mut Conn,
    actor: &str,
    action: &str,
    subject: &str,
    before: Option<&serde_json::Value>,
    after: &serde_json::Value,
) -> Result<(), HistoryError> {
    c.execute(
        "INSERT INTO audit (at, actor, action, subject, before_json, after_json) \
         VALUES ($1, $2, $3, $4, $5, $6)",
        &[
            Value::text(&zerocal_civil::Timestamp::clock().to_string()),
            Value::text(actor),
            Value::text(action),
            Value::text(subject),
            Value::Text(before.map(ToString::to_string)),
            Value::text(&after.to_string()),
        ],
    )?;
    Ok(())
}

/// The most characters a user name may have.
pub const MAX_USER_CHARS: usize = 64;

/// A user name as accounts take it: 1 to [`MAX_USER_CHARS`] characters, no control
/// characters, no white space at either end.
///
/// # Errors
/// The name, and what a name must be.
pub fn check_user_name(name: &str) -> Result<(), HistoryError> {
    let n = name.chars().count();
    if n == 0 || n > MAX_USER_CHARS || name.trim() != name || name.chars().any(char::is_control) {
        return Err(HistoryError::Refused(format!(
            "user name {name:?}: 1 to {MAX_USER_CHARS} characters, no control characters, \
             no white space at either end"
        )));
    }
    Ok(())
}

impl History {
    /// Stores `r` as [`History::insert`] does, with an audit entry naming `actor`, in
    /// one transaction (a record already stored is not audited again).
    ///
    /// # Errors
    /// As [`History::insert`].
    pub fn insert_audited(&mut self, actor: &str, r: &NewRecord) -> Result<Inserted, HistoryError> {
        validate(r)?;
        self.conn.write(|c| insert_audited_in(c, actor, r))
    }

    /// Makes the account `name` with `role` and the Argon2 PHC string `password_phc`,
    /// audited as `actor`'s.
    ///
    /// # Errors
    /// [`HistoryError::Refused`] for a name that exists or is malformed.
    pub fn add_user(
        &mut self,
        actor: &str,
        name: &str,
        role: Role,
        password_phc: &str,
    ) -> Result<User, HistoryError> {
        check_user_name(name)?;
        self.conn.write(|c| {
            if user_in(c, name)?.is_some() {
                return Err(HistoryError::Refused(format!("user {name:?} exists")));
            }
            let user = User {
                name: name.to_owned(),
                role,
                password_phc: password_phc.to_owned(),
                active: true,
                created_at: zerocal_civil::Timestamp::clock().to_string(),
            };
            c.execute(
                "INSERT INTO users (name, role, password_phc, active, created_at) \
                 VALUES ($1, $2, $3, 1, $4)",
                &[
                    Value::text(name),
                    Value::text(role.as_str()),
                    Value::text(password_phc),
                    Value::text(&user.created_at),
                ],
            )?;
            let subject = format!("user {name}");
            audit_in(c, actor, "user.add", &subject, None, &user_json(&user))?;
            Ok(user)
        })
    }

    /// Changes `name`'s role and whether it may sign in, audited as `actor`'s; its
    /// signed-in sessions end.
    ///
    /// # Errors
    /// [`HistoryError::Refused`] for no such user.
    pub fn set_user(
        &mut self,
        actor: &str,
        name: &str,
        role: Role,
        active: bool,
    ) -> Result<User, HistoryError> {
        self.conn.write(|c| {
            c.lock_table("users")?;
            let before = user_in(c, name)?
                .ok_or_else(|| HistoryError::Refused(format!("no user {name:?}")))?;
            c.execute(
                "UPDATE users SET role = $1, active = $2 WHERE name = $3",
                &[
                    Value::text(role.as_str()),
                    Value::Int(Some(i64::from(active))),
                    Value::text(name),
                ],
            )?;
            // Someone must be able to manage the users: the last active admin stays one.
            let admins = c.query(
                "SELECT count(*) FROM users WHERE role = $1 AND active = 1",
                &[Value::text(Role::Admin.as_str())],
            )?;
            let admins = admins
                .first()
                .and_then(|r| r.first())
                .ok_or_else(|| HistoryError::Corrupt("count(*) returned nothing".into()))?
                .i64("count")?;
            let was_admin = before.role == Role::Admin && before.active;
            if was_admin && admins == 0 {
                return Err(HistoryError::Refused(format!(
                    "{name} is the last active admin: make another admin first"
                )));
            }
            c.execute(
                "DELETE FROM web_sessions WHERE user_name = $1",
                &[Value::text(name)],
            )?;
            let after = User {
                role,
                active,
                ..before.clone()
            };
            let subject = format!("user {name}");
            audit_in(
                c,
                actor,
                "user.set",
                &subject,
                Some(&user_json(&before)),
                &user_json(&after),
            )?;
            Ok(after)
        })
    }

    /// The account `name`.
    ///
    /// # Errors
    /// The backend's.
    pub fn user(&mut self, name: &str) -> Result<Option<User>, HistoryError> {
        user_in(&mut self.conn, name)
    }

    /// Every account, by name.
    ///
    /// # Errors
    /// The backend's.
    pub fn users(&mut self) -> Result<Vec<User>, HistoryError> {
        self.conn
            .query(
                &format!("SELECT {USER_COLUMNS} FROM users ORDER BY name"),
                &[],
            )?
            .iter()
            .map(|r| user_from_row(r))
            .collect()
    }

    /// Records a finished sign-in attempt for `name` at `at_unix` (seconds).
    ///
    /// # Errors
    /// The backend's.
    pub fn record_login_attempt(
        &mut self,
        name: &str,
        at_unix: i64,
        succeeded: bool,
    ) -> Result<(), HistoryError> {
        insert_attempt(&mut self.conn, name, at_unix, succeeded).map(|_| ())
    }

    /// Starts a sign-in attempt for `name` at `at_unix` (seconds), in one transaction:
    /// refused ([`LoginGate::Refused`]) where `max_failures` failed since `since_unix`
    /// (after the last success), else recorded as failed until
    /// [`Self::mark_login_succeeded`] says otherwise. Recorded before the password is
    /// checked, and counted under a lock, so that parallel guesses (on any server
    /// sharing the database) cannot all pass the same count.
    ///
    /// # Errors
    /// The backend's.
    pub fn begin_login_attempt(
        &mut self,
        name: &str,
        at_unix: i64,
        since_unix: i64,
        max_failures: i64,
    ) -> Result<LoginGate, HistoryError> {
        self.conn.write(|c| {
            c.lock_table("login_attempts")?;
            let failures = failures_since(c, name, since_unix)?;
            if failures >= max_failures {
                return Ok(LoginGate::Refused { failures });
            }
            insert_attempt(c, name, at_unix, false).map(LoginGate::Attempt)
        })
    }

    /// Marks the attempt `id` ([`LoginGate::Attempt`]) as succeeded.
    ///
    /// # Errors
    /// The backend's.
    pub fn mark_login_succeeded(&mut self, id: i64) -> Result<(), HistoryError> {
        self.conn.execute(
            "UPDATE login_attempts SET succeeded = 1 WHERE id = $1",
            &[Value::Int(Some(id))],
        )?;
        Ok(())
    }

    /// The failed sign-in attempts for `name` since `since_unix` (seconds), after its
    /// last successful one.
    ///
    /// # Errors
    /// The backend's.
    pub fn login_failures_since(
        &mut self,
        name: &str,
        since_unix: i64,
    ) -> Result<i64, HistoryError> {
        failures_since(&mut self.conn, name, since_unix)
    }

    /// Stores a signed-in session: the SHA-256 of its random ID (the ID itself is only
    /// in the browser's cookie), its user, its CSRF token and expiry (unix seconds).
    ///
    /// # Errors
    /// The backend's.
    pub fn start_web_session(
        &mut self,
        id_sha256: &str,
        user_name: &str,
        csrf_token: &str,
        expires_unix: i64,
    ) -> Result<(), HistoryError> {
        self.conn.execute(
            "INSERT INTO web_sessions (id_sha256, user_name, csrf_token, expires_unix) \
             VALUES ($1, $2, $3, $4)",
            &[
                Value::text(id_sha256),
                Value::text(user_name),
                Value::text(csrf_token),
                Value::Int(Some(expires_unix)),
            ],
        )?;
        Ok(())
    }

    /// The session whose ID hashes to `id_sha256`, if it has not expired at `now_unix`
    /// and its user may sign in.
    ///
    /// # Errors
    /// The backend's.
    pub fn web_session(
        &mut self,
        id_sha256: &str,
        now_unix: i64,
    ) -> Result<Option<WebSession>, HistoryError> {
        let rows = self.conn.query(
            "SELECT user_name, csrf_token FROM web_sessions \
             WHERE id_sha256 = $1 AND expires_unix > $2",
            &[Value::text(id_sha256), Value::Int(Some(now_unix))],
        )?;
        let Some([user_name, csrf]) = rows.first().map(Vec::as_slice) else {
            return Ok(None);
        };
        let csrf_token = csrf.string("web_sessions.csrf_token")?;
        Ok(
            user_in(&mut self.conn, &user_name.string("web_sessions.user_name")?)?
                .filter(|u| u.active)
                .map(|user| WebSession { user, csrf_token }),
        )
    }

    /// Ends the session whose ID hashes to `id_sha256`, and every expired one.
    ///
    /// # Errors
    /// The backend's.
    pub fn end_web_session(&mut self, id_sha256: &str, now_unix: i64) -> Result<(), HistoryError> {
        self.conn.execute(
            "DELETE FROM web_sessions WHERE id_sha256 = $1 OR expires_unix <= $2",
            &[Value::text(id_sha256), Value::Int(Some(now_unix))],
        )?;
        Ok(())
    }

    /// Signs `step` of the session record `record_id` as `actor`, audited, after
    /// checking in the same transaction that the actor is active and has the step's
    /// role, that the record is a session, that `checked` comes before `authorized`,
    /// and that one person does not sign both steps.
    ///
    /// # Errors
    /// [`HistoryError::Refused`] saying which of these failed; nothing is written.
    pub fn sign(
        &mut self,
        actor: &str,
        record_id: i64,
        step: SignStep,
    ) -> Result<Signature, HistoryError> {
        self.conn.write(|c| {
            let user = user_in(c, actor)?
                .filter(|u| u.active)
                .ok_or_else(|| HistoryError::Refused(format!("no active user {actor:?}")))?;
            if user.role != step.role() {
                return Err(HistoryError::Refused(format!(
                    "{actor} is a {}; {} is signed by a {}",
                    user.role.as_str(),
                    step.as_str(),
                    step.role().as_str()
                )));
            }
            let row = c.query(
                "SELECT kind, operator FROM records WHERE id = $1",
                &[Value::Int(Some(record_id))],
            )?;
            let [kind, operator] = row.first().map(Vec::as_slice).unwrap_or_default() else {
                return Err(HistoryError::NoSuchRecord(record_id));
            };
            if kind.string("records.kind")? != "session" {
                return Err(HistoryError::Refused(format!(
                    "record {record_id} is a check: only a session is signed"
                )));
            }
            // Four eyes: whoever measured does not check or authorize the measurement.
            // A record made on the command line names its operator as typed: the
            // comparison ignores case and surrounding spaces. It binds operators that
            // are account names; another spelling of a person is not caught.
            let measured_by = operator.opt_text("records.operator")?;
            if measured_by.is_some_and(|o| o.trim().eq_ignore_ascii_case(actor.trim())) {
                return Err(HistoryError::Refused(format!(
                    "{actor} measured record {record_id}: another person {} it",
                    step.verb()
                )));
            }
            let before = signatures_in(c, record_id)?;
            if before.iter().any(|s| s.step == step) {
                return Err(HistoryError::Refused(format!(
                    "record {record_id} is already {}",
                    step.as_str()
                )));
            }
            if step == SignStep::Authorized {
                match before.iter().find(|s| s.step == SignStep::Checked) {
                    None => {
                        return Err(HistoryError::Refused(format!(
                            "record {record_id} is not checked yet: it is authorized after a reviewer checked it"
                        )))
                    }
                    Some(s) if s.user_name == actor => {
                        return Err(HistoryError::Refused(format!(
                            "{actor} checked record {record_id}: another person authorizes it"
                        )))
                    }
                    Some(_) => {}
                }
            }
            let signature = Signature {
                step,
                user_name: actor.to_owned(),
                signed_at: zerocal_civil::Timestamp::clock().to_string(),
            };
            c.execute(
                "INSERT INTO signatures (record_id, step, user_name, signed_at) VALUES ($1, $2, $3, $4)",
                &[
                    Value::Int(Some(record_id)),
                    Value::text(step.as_str()),
                    Value::text(actor),
                    Value::text(&signature.signed_at),
                ],
            )?;
            let mut after = before.clone();
            after.push(signature.clone());
            let to_json = |s: &[Signature]| serde_json::to_value(s).unwrap_or_default();
            let subject = format!("record {record_id}");
            audit_in(c, actor, "record.sign", &subject, Some(&to_json(&before)), &to_json(&after))?;
            Ok(signature)
        })
    }

    /// The signatures of `record_id`, checked first.
    ///
    /// # Errors
    /// The backend's.
    pub fn signatures(&mut self, record_id: i64) -> Result<Vec<Signature>, HistoryError> {
        signatures_in(&mut self.conn, record_id)
    }

    /// Writes an audit entry for a change made by another call (a certificate issued
    /// by the CLI's code, which writes it in its own transaction).
    ///
    /// # Errors
    /// The backend's.
    pub fn audit_note(
        &mut self,
        actor: &str,
        action: &str,
        subject: &str,
        after: &serde_json::Value,
    ) -> Result<(), HistoryError> {
        self.conn
            .write(|c| audit_in(c, actor, action, subject, None, after))
    }

    /// The audit log, newest first, at most `limit` entries.
    ///
    /// # Errors
    /// The backend's.
    pub fn audit_log(&mut self, limit: i64) -> Result<Vec<AuditEntry>, HistoryError> {
        self.conn
            .query(
                "SELECT id, at, actor, action, subject, before_json, after_json FROM audit \
                 ORDER BY id DESC LIMIT $1",
                &[Value::Int(Some(limit))],
            )?
            .iter()
            .map(|row| {
                let [id, at, actor, action, subject, before, after] = row.as_slice() else {
                    return Err(HistoryError::Corrupt("an audit row".into()));
                };
                Ok(AuditEntry {
                    id: id.i64("audit.id")?,
                    at: at.string("audit.at")?,
                    actor: actor.string("audit.actor")?,
                    action: action.string("audit.action")?,
                    subject: subject.string("audit.subject")?,
                    before_json: before.opt_text("audit.before_json")?,
                    after_json: after.string("audit.after_json")?,
                })
            })
            .collect()
    }
}

fn signatures_in(c: &mut Conn, record_id: i64) -> Result<Vec<Signature>, HistoryError> {
    let mut out = c
        .query(
            "SELECT step, user_name, signed_at FROM signatures WHERE record_id = $1",
            &[Value::Int(Some(record_id))],
        )?
        .iter()
        .map(|row| {
            let [step, user, at] = row.as_slice() else {
                return Err(HistoryError::Corrupt("a signatures row".into()));
            };
            Ok(Signature {
                step: SignStep::parse(&step.string("signatures.step")?)
                    .map_err(HistoryError::Corrupt)?,
                user_name: user.string("signatures.user_name")?,
                signed_at: at.string("signatures.signed_at")?,
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    out.sort_by_key(|s| s.step == SignStep::Authorized);
    Ok(out)
}

/// What [`History::begin_login_attempt`] decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoginGate {
    /// Too many failures: refused, the password not tried, nothing recorded.
    Refused {
        /// The failures counted.
        failures: i64,
    },
    /// Recorded (as failed so far): the attempt's ID.
    Attempt(i64),
}

/// Inserts an attempt; its ID.
fn insert_attempt(
    c: &mut Conn,
    name: &str,
    at_unix: i64,
    succeeded: bool,
) -> Result<i64, HistoryError> {
    let rows = c.query(
        "INSERT INTO login_attempts (user_name, at_unix, succeeded) VALUES ($1, $2, $3) \
         RETURNING id",
        &[
            Value::text(name),
            Value::Int(Some(at_unix)),
            Value::Int(Some(i64::from(succeeded))),
        ],
    )?;
    rows.first()
        .and_then(|r| r.first())
        .ok_or_else(|| HistoryError::Corrupt("an insert returned no id".into()))?
        .i64("login_attempts.id")
}

/// `name`'s failed attempts since `since_unix`, after its last successful one.
fn failures_since(c: &mut Conn, name: &str, since_unix: i64) -> Result<i64, HistoryError> {
    let rows = c.query(
        "SELECT count(*) FROM login_attempts WHERE user_name = $1 AND succeeded = 0 \
         AND at_unix >= $2 AND id > COALESCE((SELECT max(id) FROM login_attempts \
         WHERE user_name = $1 AND succeeded = 1), 0)",
        &[Value::text(name), Value::Int(Some(since_unix))],
    )?;
    rows.first()
        .and_then(|r| r.first())
        .ok_or_else(|| HistoryError::Corrupt("count(*) returned nothing".into()))?
        .i64("count")
}

/// [`History::insert_audited`]'s work in the caller's writing transaction.
pub(crate) fn insert_audited_in(
    c: &mut Conn,
    actor: &str,
    r: &NewRecord,
) -> Result<Inserted, HistoryError> {
    let inserted = insert_in(c, r)?;
    if inserted.new {
        let after = json!({
            "id": inserted.id,
            "kind": r.kind.as_str(),
            "serial": r.serial,
            "robot": r.robot,
            "measured_on": r.measured_on,
            "operator": r.operator,
            "verdict": r.verdict,
            "export_sha256": crate::sha256_hex(&r.export),
        });
        let subject = format!("record {}", inserted.id);
        audit_in(c, actor, "record.insert", &subject, None, &after)?;
    }
    Ok(inserted)
}
