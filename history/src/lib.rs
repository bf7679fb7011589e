//! zerocal's calibration history: every session and check, per robot serial, stored
//! with what produced it (the pendant export's bytes, the profile's text, the zerocal
//! version) so that a robot's zeros can be listed and plotted over time.
//!
//! One schema ([`schema::MIGRATIONS`]) and one query layer serve both backends: a local
//! SQLite file (the default, see [`DbLocation::from_arg`]) and a plant-wide PostgreSQL
//! server. See `docs/history.md` for the guarantees and how they are tested.

mod brackets;
mod certificates;
mod conventions;
mod corrections;
mod db;
mod error;
mod fleet;
mod pgpass;
mod pgtls;
mod record_harmonics;
pub mod reducers;
mod review;
pub mod schema;
mod uploads;
mod verdict;

pub use brackets::{RecordBracket, RecordBracketCalibration, RecordBracketYaw, RecordBrackets};
pub use certificates::{CertificateRequest, IssuedCertificate, NewCertificate, MAX_NUMBER_CHARS};
pub use conventions::{Convention, NewConvention};
pub use corrections::Correction;
pub use error::HistoryError;
pub use fleet::{Drift, RecordSummary, RobotSummary};
pub use pgtls::SslMode;
pub use reducers::Harmonic;
pub use review::{
    check_user_name, AuditEntry, LoginGate, Role, SignStep, Signature, User, WebSession,
    MAX_USER_CHARS,
};
pub use verdict::{Verdict, PASS};

use db::{Conn, Value};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// What a record is: a calibration session or a later check of its zeros.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RecordKind {
    /// A calibration session: the zeros found.
    Session,
    /// A check of the zeros against a reference record.
    Check,
}

impl RecordKind {
    /// As stored: `session` or `check`.
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Session => "session",
            Self::Check => "check",
        }
    }

    fn parse(s: &str) -> Result<Self, HistoryError> {
        match s {
            "session" => Ok(Self::Session),
            "check" => Ok(Self::Check),
            other => Err(HistoryError::Corrupt(format!(
                "records.kind {other:?} is neither session nor check"
            ))),
        }
    }
}

/// The joints a record may hold: 2..=6 (joint 1's zero is not identified by tilt).
pub const JOINTS: std::ops::RangeInclusive<u8> = 2..=6;

/// The most characters a serial may have.
pub const MAX_SERIAL_CHARS: usize = 64;

/// One joint's result in a record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct JointRow {
    /// The joint, 2..=6 ([`JOINTS`]).
    pub joint: u8,
    /// Its name on the controller, e.g. `A3`.
    pub name: String,
    /// The identified zero offset (deg).
    pub offset_deg: f64,
    /// Its expanded uncertainty, k = 2 (deg).
    pub expanded_k2_deg: f64,
    /// The offset in the controller's own terms (deg).
    pub controller_offset_deg: f64,
    /// A check's verdict on this joint; `None` for a session.
    pub pass: Option<bool>,
}

/// A record to store.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NewRecord {
    /// Session or check.
    pub kind: RecordKind,
    /// The robot's serial (required, 1..=64 printable characters).
    pub serial: String,
    /// The profile's name, e.g. `kuka-kr6-r900-sixx`.
    pub robot: String,
    /// The profile's title.
    pub robot_title: String,
    /// The controller family: kuka, abb, fanuc, ...
    pub controller_family: String,
    /// The profile's text as used.
    pub profile_toml: String,
    /// The pendant export's bytes, exactly.
    pub export: Vec<u8>,
    /// The day measured, `YYYY-MM-DD`.
    pub measured_on: String,
    /// Who measured.
    pub operator: Option<String>,
    /// The pendant's unit identifier.
    pub pendant_unit: Option<String>,
    /// The pendant's own result ID when imported from it.
    pub pendant_result_id: Option<u32>,
    /// A check's reference record (same serial).
    pub reference_id: Option<i64>,
    /// The zerocal version that computed the result.
    pub zerocal_version: String,
    /// `PASS`, `WARN ...`, `FAIL ...`: [`Verdict::text`].
    pub verdict: String,
    /// The brackets' IDs and calibrations (stored as JSON text, `records.brackets_json`).
    pub brackets: RecordBrackets,
    /// Temperatures, base tilt (JSON text).
    pub conditions_json: String,
    /// The whole result (`zerocal session --json` object) as JSON text.
    pub result_json: String,
    /// Per joint results.
    pub joints: Vec<JointRow>,
    /// A session's fitted harmonics (`record_harmonics`; none for a check).
    #[serde(default)]
    pub harmonics: Vec<Harmonic>,
}

/// A stored record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// Its ID, assigned by the database in insertion order.
    pub id: i64,
    /// When it was stored, UTC RFC 3339.
    pub recorded_at: String,
    /// SHA-256 of `new.export`, lowercase hex.
    pub export_sha256: String,
    /// SHA-256 of `new.profile_toml`, lowercase hex.
    pub profile_sha256: String,
    /// What was stored.
    pub new: NewRecord,
}

/// The outcome of [`History::insert`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Inserted {
    /// The record's ID.
    pub id: i64,
    /// `false` when the same export of the same kind for the same serial was already
    /// stored: `id` is then that record's.
    pub new: bool,
}

/// Where the history lives.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DbLocation {
    /// An SQLite file.
    Sqlite(PathBuf),
    /// A PostgreSQL URL, `postgres://user@host:port/database`; the password comes from
    /// `PGPASSWORD` or the password file when the URL has none (`pgpass.rs`).
    Postgres(String),
}

/// The file under the data directory.
const DEFAULT_FILE: [&str; 2] = ["zerocal", "history.sqlite"];

impl DbLocation {
    /// The location `--db` names: `postgres://...` or `postgresql://...` is a server
    /// (refused if it holds a password: that belongs in `PGPASSWORD` or the password
    /// file), anything else a file. Without `--db`: `$XDG_DATA_HOME/zerocal/history.sqlite`,
    /// else `$HOME/.local/share/zerocal/history.sqlite` (the XDG Base Directory
    /// specification, which also says a relative `XDG_DATA_HOME` is ignored).
    ///
    /// # Errors
    /// An empty `--db`; a URL with a password; no `--db` and neither variable set.
    pub fn from_arg(arg: Option<&str>) -> Result<DbLocation, HistoryError> {
        Self::from_arg_in(
            arg,
            std::env::var_os("XDG_DATA_HOME"),
            std::env::var_os("HOME"),
        )
    }

    fn from_arg_in(
        arg: Option<&str>,
        xdg_data_home: Option<std::ffi::OsString>,
        home: Option<std::ffi::OsString>,
    ) -> Result<DbLocation, HistoryError> {
        match arg {
            Some("") => Err(HistoryError::BadLocation(
                "--db is empty: give a file or a postgres:// URL".into(),
            )),
            Some(url) if url.starts_with("postgres://") || url.starts_with("postgresql://") => {
                if pgpass::url_has_password(url) {
                    return Err(HistoryError::BadLocation(
                        "--db holds a password, which every user of this machine can read in the process list: give the URL without it and put the password in PGPASSWORD or a password file (~/.pgpass, or the file PGPASSFILE names; docs/history.md)".into(),
                    ));
                }
                Ok(Self::Postgres(url.to_owned()))
            }
            Some(path) => Ok(Self::Sqlite(PathBuf::from(path))),
            None => {
                let xdg = xdg_data_home.map(PathBuf::from).filter(|p| p.is_absolute());
                let data = match xdg {
                    Some(d) => d,
                    None => home
                        .filter(|h| !h.is_empty())
                        .map(|h| PathBuf::from(h).join(".local").join("share"))
                        .ok_or(HistoryError::NoDataDir)?,
                };
                Ok(Self::Sqlite(
                    DEFAULT_FILE.iter().fold(data, |p, c| p.join(c)),
                ))
            }
        }
    }
}

impl std::fmt::Display for DbLocation {
    /// The path, or the URL with its password replaced by `***`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Sqlite(p) => write!(f, "{}", p.display()),
            Self::Postgres(url) => f.write_str(&redacted(url)),
        }
    }
}

/// `url` without the password of its `user:password@` part or its query's `password`.
fn redacted(url: &str) -> String {
    let Some((scheme, rest)) = url.split_once("://") else {
        return url.to_owned();
    };
    let authority_end = rest.find(['/', '?']).unwrap_or(rest.len());
    let (authority, tail) = rest.split_at(authority_end);
    let authority = match authority.rsplit_once('@') {
        Some((userinfo, host)) => match userinfo.split_once(':') {
            Some((user, _)) => format!("{user}:***@{host}"),
            None => authority.to_owned(),
        },
        None => authority.to_owned(),
    };
    let tail = match tail.split_once('?') {
        Some((path, query)) => {
            let pairs: Vec<String> = query
                .split('&')
                .map(|pair| match pair.split_once('=') {
                    Some((key, _)) if pgtls::percent_decoded(key) == "password" => {
                        format!("{key}=***")
                    }
                    _ => pair.to_owned(),
                })
                .collect();
            format!("{path}?{}", pairs.join("&"))
        }
        None => tail.to_owned(),
    };
    format!("{scheme}://{authority}{tail}")
}

/// The client configuration of a PostgreSQL URL, its password (when the URL has none)
/// from `PGPASSWORD` or the password file, as libpq takes it (`pgpass.rs`), and its
/// `sslmode` as the client's transport (`verify-ca` and `verify-full` are its
/// `require`; the verification is [`postgres_connect`]'s, `pgtls.rs`).
///
/// # Errors
/// A URL the client cannot parse; an `sslmode` or `sslrootcert` that cannot be
/// honoured; a password file others can read, or unreadable.
pub fn postgres_config(url: &str) -> Result<postgres::Config, HistoryError> {
    let (config, tls) = postgres_settings(url)?;
    // A client connecting with its own transport would not verify: a mode that asks
    // for verification is only honoured by `postgres_connect`.
    if matches!(tls.mode, SslMode::VerifyCa | SslMode::VerifyFull) {
        return Err(HistoryError::BadLocation(format!(
            "sslmode={}: connect through zerocal_history::postgres_connect, which verifies the server's certificate",
            tls.mode.as_str()
        )));
    }
    Ok(config)
}

fn postgres_settings(url: &str) -> Result<(postgres::Config, pgtls::Tls), HistoryError> {
    let home = std::env::var_os("HOME")
        .filter(|h| !h.is_empty())
        .map(PathBuf::from);
    let (url, tls) =
        pgtls::split_url(url, home.as_deref(), &pgtls::TlsEnvironment::from_process())?;
    let mut config: postgres::Config = url.parse()?;
    tls.apply(&mut config);
    pgpass::fill(
        &mut config,
        std::env::var("PGPASSWORD").ok(),
        pgpass::file_path().as_deref(),
    )?;
    Ok((config, tls))
}

/// A connection to the PostgreSQL server of `url` ([`postgres_config`]), over TLS as its
/// `sslmode` asks (`prefer` by default: TLS when the server offers it; `pgtls.rs`).
/// Every connection to a history server is made here.
///
/// # Errors
/// As [`postgres_config`]; the root certificates unreadable; the server's certificate
/// not trusted, or no TLS offered where the mode asks for it ([`HistoryError::Tls`]);
/// the client's or the server's refusal.
pub fn postgres_connect(url: &str) -> Result<postgres::Client, HistoryError> {
    let (config, tls) = postgres_settings(url)?;
    let connected = if tls.mode == SslMode::Disable {
        config.connect(postgres::NoTls)
    } else {
        let connector = tokio_postgres_rustls::MakeRustlsConnect::new(tls.client_config()?);
        config.connect(connector)
    };
    connected.map_err(|e| tls.error(e))
}

/// Lowercase hex SHA-256 of `bytes`.
#[must_use]
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// An open history database.
pub struct History {
    conn: Conn,
    location: String,
}

// The profile's text is stored once in `texts`, by its hash (schema 4).
const RECORD_COLUMNS: &str = "id, recorded_at, export_sha256, profile_sha256, kind, serial, \
    robot, robot_title, controller_family, \
    (SELECT text FROM texts WHERE texts.sha256 = records.profile_sha256) AS profile_toml, \
    export, measured_on, operator, \
    pendant_unit, pendant_result_id, reference_id, zerocal_version, verdict, brackets_json, \
    conditions_json, result_json";

const JOINT_COLUMNS: &str =
    "record_id, joint, name, offset_deg, expanded_k2_deg, controller_offset_deg, pass";

fn invalid(why: impl Into<String>) -> HistoryError {
    HistoryError::InvalidRecord(why.into())
}

fn check_json(field: &str, text: &str) -> Result<(), HistoryError> {
    serde_json::from_str::<serde_json::Value>(text)
        .map(|_| ())
        .map_err(|e| invalid(format!("{field} is not JSON: {e}")))
}

/// Everything about `r` that can be checked without the database.
fn validate(r: &NewRecord) -> Result<(), HistoryError> {
    let chars = r.serial.chars().count();
    if chars == 0 || chars > MAX_SERIAL_CHARS {
        return Err(invalid(format!(
            "serial {:?} has {chars} characters; 1 to {MAX_SERIAL_CHARS} are allowed",
            r.serial
        )));
    }
    if r.serial.chars().any(char::is_control) {
        return Err(invalid(format!(
            "serial {:?} holds a control character",
            r.serial
        )));
    }
    // "R1 " and "R1" would be two robots in the history and one on the nameplate.
    if r.serial.trim() != r.serial {
        return Err(invalid(format!(
            "serial {:?} starts or ends with white space",
            r.serial
        )));
    }
    for (field, value) in [
        ("robot", &r.robot),
        ("controller_family", &r.controller_family),
        ("zerocal_version", &r.zerocal_version),
        ("verdict", &r.verdict),
    ] {
        if value.trim().is_empty() {
            return Err(invalid(format!("{field} is empty")));
        }
    }
    // The export is what makes a record once (serial, kind and export hash): an empty
    // one would make every later record of the serial "the same".
    if r.export.is_empty() {
        return Err(invalid("the export is empty"));
    }
    if let Err(e) = zerocal_civil::Date::parse(&r.measured_on) {
        return Err(invalid(format!(
            "measured_on {:?} is not a date YYYY-MM-DD: {e}",
            r.measured_on
        )));
    }
    r.brackets
        .check()
        .map_err(|e| invalid(format!("brackets: {e}")))?;
    check_json("conditions_json", &r.conditions_json)?;
    check_json("result_json", &r.result_json)?;
    if let Some(why) = record_harmonics::invalid(&r.harmonics) {
        return Err(invalid(why));
    }
    let mut seen = [false; 7];
    for j in &r.joints {
        if !JOINTS.contains(&j.joint) {
            return Err(invalid(format!(
                "joint {} is outside {}..={}",
                j.joint,
                JOINTS.start(),
                JOINTS.end()
            )));
        }
        let slot = &mut seen[usize::from(j.joint)];
        if *slot {
            return Err(invalid(format!("joint {} is given twice", j.joint)));
        }
        *slot = true;
        for (field, v) in [
            ("offset_deg", j.offset_deg),
            ("expanded_k2_deg", j.expanded_k2_deg),
            ("controller_offset_deg", j.controller_offset_deg),
        ] {
            if !v.is_finite() {
                return Err(invalid(format!("joint {}: {field} is {v}", j.joint)));
            }
        }
        if j.expanded_k2_deg < 0.0 {
            return Err(invalid(format!(
                "joint {}: expanded_k2_deg {} is negative",
                j.joint, j.expanded_k2_deg
            )));
        }
    }
    Ok(())
}

fn joint_from_row(row: &[Value]) -> Result<(i64, JointRow), HistoryError> {
    let [record_id, joint, name, offset, expanded, controller, pass] = row else {
        return Err(HistoryError::Corrupt(format!(
            "a joints row has {} columns",
            row.len()
        )));
    };
    let record_id = record_id.i64("joints.record_id")?;
    let joint_no = joint.i64("joints.joint")?;
    let joint = u8::try_from(joint_no)
        .ok()
        .filter(|j| JOINTS.contains(j))
        .ok_or_else(|| HistoryError::Corrupt(format!("record {record_id}: joint {joint_no}")))?;
    let pass = match pass.opt_i64("joints.pass")? {
        None => None,
        Some(0) => Some(false),
        Some(1) => Some(true),
        Some(v) => {
            return Err(HistoryError::Corrupt(format!(
                "record {record_id} joint {joint}: pass {v}"
            )))
        }
    };
    Ok((
        record_id,
        JointRow {
            joint,
            name: name.string("joints.name")?,
            offset_deg: offset.f64("joints.offset_deg")?,
            expanded_k2_deg: expanded.f64("joints.expanded_k2_deg")?,
            controller_offset_deg: controller.f64("joints.controller_offset_deg")?,
            pass,
        },
    ))
}

fn record_from_row(row: &[Value], joints: Vec<JointRow>) -> Result<Record, HistoryError> {
    let [id, recorded_at, export_sha256, profile_sha256, kind, serial, robot, robot_title, controller_family, profile_toml, export, measured_on, operator, pendant_unit, pendant_result_id, reference_id, zerocal_version, verdict, brackets_json, conditions_json, result_json] =
        row
    else {
        return Err(HistoryError::Corrupt(format!(
            "a records row has {} columns",
            row.len()
        )));
    };
    let id = id.i64("records.id")?;
    let pendant_result_id =
        match pendant_result_id.opt_i64("records.pendant_result_id")? {
            None => None,
            Some(v) => Some(u32::try_from(v).map_err(|_| {
                HistoryError::Corrupt(format!("record {id}: pendant_result_id {v}"))
            })?),
        };
    Ok(Record {
        id,
        recorded_at: recorded_at.string("records.recorded_at")?,
        export_sha256: export_sha256.string("records.export_sha256")?,
        profile_sha256: profile_sha256.string("records.profile_sha256")?,
        new: NewRecord {
            kind: RecordKind::parse(&kind.string("records.kind")?)?,
            serial: serial.string("records.serial")?,
            robot: robot.string("records.robot")?,
            robot_title: robot_title.string("records.robot_title")?,
            controller_family: controller_family.string("records.controller_family")?,
            // NULL when `texts` has no row for the record's profile_sha256.
            profile_toml: profile_toml
                .string("the profile text (texts, by records.profile_sha256)")?,
            export: export.bytes("records.export")?,
            measured_on: measured_on.string("records.measured_on")?,
            operator: operator.opt_text("records.operator")?,
            pendant_unit: pendant_unit.opt_text("records.pendant_unit")?,
            pendant_result_id,
            reference_id: reference_id.opt_i64("records.reference_id")?,
            zerocal_version: zerocal_version.string("records.zerocal_version")?,
            verdict: verdict.string("records.verdict")?,
            brackets: RecordBrackets::from_json(&brackets_json.string("records.brackets_json")?)
                .map_err(|e| HistoryError::Corrupt(format!("record {id}: brackets_json: {e}")))?,
            conditions_json: conditions_json.string("records.conditions_json")?,
            result_json: result_json.string("records.result_json")?,
            joints,
            // Read by the caller, from `record_harmonics`.
            harmonics: Vec::new(),
        },
    })
}

fn opt_text(v: Option<&String>) -> Value {
    Value::Text(v.cloned())
}

/// Stores `r` (validated) and its joints inside the transaction `c`.
fn insert_in(c: &mut Conn, r: &NewRecord) -> Result<Inserted, HistoryError> {
    let export_sha256 = sha256_hex(&r.export);
    let profile_sha256 = sha256_hex(r.profile_toml.as_bytes());
    let recorded_at = zerocal_civil::Timestamp::clock().to_string();
    let key = [
        Value::text(&r.serial),
        Value::text(r.kind.as_str()),
        Value::text(&export_sha256),
    ];
    {
        if let Some(reference) = r.reference_id {
            let rows = c.query(
                "SELECT serial FROM records WHERE id = $1",
                &[Value::Int(Some(reference))],
            )?;
            let Some(serial) = rows.first().and_then(|row| row.first()) else {
                return Err(invalid(format!(
                    "reference record {reference} does not exist"
                )));
            };
            let serial = serial.string("records.serial")?;
            if serial != r.serial {
                return Err(invalid(format!(
                    "reference record {reference} is of serial {serial:?}, not {:?}",
                    r.serial
                )));
            }
        }
        // The profile's text once, by its hash: every record of it refers to it.
        c.execute(
            "INSERT INTO texts (sha256, text) VALUES ($1, $2) \
                 ON CONFLICT (sha256) DO NOTHING",
            &[Value::text(&profile_sha256), Value::text(&r.profile_toml)],
        )?;
        let inserted = c.query(
            "INSERT INTO records (recorded_at, kind, serial, robot, robot_title, \
                 controller_family, profile_sha256, export, export_sha256, \
                 measured_on, operator, pendant_unit, pendant_result_id, reference_id, \
                 zerocal_version, verdict, brackets_json, conditions_json, result_json) \
                 VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, \
                 $16, $17, $18, $19) \
                 ON CONFLICT (serial, kind, export_sha256) DO NOTHING RETURNING id",
            &[
                Value::text(&recorded_at),
                Value::text(r.kind.as_str()),
                Value::text(&r.serial),
                Value::text(&r.robot),
                Value::text(&r.robot_title),
                Value::text(&r.controller_family),
                Value::text(&profile_sha256),
                Value::Bytes(Some(r.export.clone())),
                Value::text(&export_sha256),
                Value::text(&r.measured_on),
                opt_text(r.operator.as_ref()),
                opt_text(r.pendant_unit.as_ref()),
                Value::Int(r.pendant_result_id.map(i64::from)),
                Value::Int(r.reference_id),
                Value::text(&r.zerocal_version),
                Value::text(&r.verdict),
                Value::text(&r.brackets.to_json()),
                Value::text(&r.conditions_json),
                Value::text(&r.result_json),
            ],
        )?;
        let Some(row) = inserted.first() else {
            // Already stored (by us earlier or by another process just now).
            let existing = c.query(
                "SELECT id FROM records WHERE serial = $1 AND kind = $2 AND export_sha256 = $3",
                &key,
            )?;
            let id = existing
                .first()
                .and_then(|row| row.first())
                .ok_or_else(|| {
                    HistoryError::Corrupt(
                        "an insert conflicted with a record that is not there".into(),
                    )
                })?
                .i64("records.id")?;
            return Ok(Inserted { id, new: false });
        };
        let id = row
            .first()
            .ok_or_else(|| HistoryError::Corrupt("INSERT returned no ID".into()))?
            .i64("records.id")?;
        for j in &r.joints {
            c.execute(
                "INSERT INTO joints (record_id, joint, name, offset_deg, expanded_k2_deg, \
                     controller_offset_deg, pass) VALUES ($1, $2, $3, $4, $5, $6, $7)",
                &[
                    Value::Int(Some(id)),
                    Value::Int(Some(i64::from(j.joint))),
                    Value::text(&j.name),
                    Value::Real(Some(j.offset_deg)),
                    Value::Real(Some(j.expanded_k2_deg)),
                    Value::Real(Some(j.controller_offset_deg)),
                    Value::Int(j.pass.map(i64::from)),
                ],
            )?;
        }
        record_harmonics::insert(c, id, &r.harmonics)?;
        Ok(Inserted { id, new: true })
    }
}

impl History {
    /// Opens the history at `at`, making the database (and for a file, its directory)
    /// when absent or empty, and migrating an older schema.
    ///
    /// # Errors
    /// [`HistoryError::NotZerocal`] for another application's database or a file that
    /// is no database, [`HistoryError::NewerSchema`] for one written by a newer
    /// zerocal (both left untouched); the backend's error otherwise.
    pub fn open(at: &DbLocation) -> Result<History, HistoryError> {
        Self::open_at_schema(at, schema::SCHEMA_VERSION)
    }

    /// [`History::open`], migrating no further than `version`: the migration tests
    /// make the databases an older zerocal made with it.
    #[doc(hidden)]
    pub fn open_at_schema(at: &DbLocation, version: i64) -> Result<History, HistoryError> {
        let location = at.to_string();
        let conn = match at {
            DbLocation::Sqlite(path) => schema::open_sqlite(path, version)?,
            DbLocation::Postgres(url) => schema::open_postgres(url, &location, version)?,
        };
        Ok(History { conn, location })
    }

    /// The database's schema version.
    ///
    /// # Errors
    /// The backend's.
    pub fn schema_version(&mut self) -> Result<i64, HistoryError> {
        schema::version(&mut self.conn, &self.location)
    }

    /// Where this history is (a URL without its password).
    #[must_use]
    pub fn location(&self) -> &str {
        &self.location
    }

    /// Stores `r` and its joints in one transaction. The same export bytes of the same
    /// kind for the same serial are stored once: again, the existing record's ID is
    /// returned with `new: false`.
    ///
    /// # Errors
    /// [`HistoryError::InvalidRecord`] naming the field; the backend's error.
    pub fn insert(&mut self, r: &NewRecord) -> Result<Inserted, HistoryError> {
        validate(r)?;
        self.conn.write(|c| insert_in(c, r))
    }

    /// The record `id` with its joints.
    ///
    /// # Errors
    /// [`HistoryError::NoSuchRecord`]; the backend's error.
    pub fn get(&mut self, id: i64) -> Result<Record, HistoryError> {
        let key = [Value::Int(Some(id))];
        let rows = self.conn.query(
            &format!("SELECT {RECORD_COLUMNS} FROM records WHERE id = $1"),
            &key,
        )?;
        let row = rows.first().ok_or(HistoryError::NoSuchRecord(id))?;
        let joints = self
            .conn
            .query(
                &format!("SELECT {JOINT_COLUMNS} FROM joints WHERE record_id = $1 ORDER BY joint"),
                &key,
            )?
            .iter()
            .map(|r| joint_from_row(r).map(|(_, j)| j))
            .collect::<Result<Vec<_>, _>>()?;
        let mut record = record_from_row(row, joints)?;
        record.new.harmonics = record_harmonics::by_record(&mut self.conn, "record_id = $1", &key)?
            .remove(&id)
            .unwrap_or_default();
        Ok(record)
    }

    /// Every record, or those of `serial`, in ID order (the order they were stored).
    ///
    /// # Errors
    /// The backend's.
    pub fn list(&mut self, serial: Option<&str>) -> Result<Vec<Record>, HistoryError> {
        // Records first, then joints: a record committed between the two queries is
        // not listed, and every listed record's joints were committed with it.
        let (records, joints) = match serial {
            Some(s) => {
                let key = [Value::text(s)];
                (
                    self.conn.query(
                        &format!(
                            "SELECT {RECORD_COLUMNS} FROM records WHERE serial = $1 ORDER BY id"
                        ),
                        &key,
                    )?,
                    self.conn.query(
                        &format!(
                            "SELECT {JOINT_COLUMNS} FROM joints WHERE record_id IN \
                             (SELECT id FROM records WHERE serial = $1) ORDER BY record_id, joint"
                        ),
                        &key,
                    )?,
                )
            }
            None => (
                self.conn.query(
                    &format!("SELECT {RECORD_COLUMNS} FROM records ORDER BY id"),
                    &[],
                )?,
                self.conn.query(
                    &format!("SELECT {JOINT_COLUMNS} FROM joints ORDER BY record_id, joint"),
                    &[],
                )?,
            ),
        };
        let mut harmonics = match serial {
            Some(s) => record_harmonics::by_record(
                &mut self.conn,
                "record_id IN (SELECT id FROM records WHERE serial = $1)",
                &[Value::text(s)],
            )?,
            None => record_harmonics::by_record(&mut self.conn, "1 = 1", &[])?,
        };
        let mut by_record: BTreeMap<i64, Vec<JointRow>> = BTreeMap::new();
        for row in &joints {
            let (record_id, joint) = joint_from_row(row)?;
            by_record.entry(record_id).or_default().push(joint);
        }
        records
            .iter()
            .map(|row| {
                let id = row
                    .first()
                    .ok_or_else(|| HistoryError::Corrupt("a records row is empty".into()))?
                    .i64("records.id")?;
                let mut record = record_from_row(row, by_record.remove(&id).unwrap_or_default())?;
                record.new.harmonics = harmonics.remove(&id).unwrap_or_default();
                Ok(record)
            })
            .collect()
    }

    /// SQLite's `PRAGMA integrity_check` of the file: `Some("ok")`, or what it found.
    /// `None` on PostgreSQL, which has no such check of a database (the server keeps its
    /// own pages consistent; its `amcheck` extension is the administrator's tool).
    ///
    /// # Errors
    /// The backend's.
    pub fn integrity_check(&mut self) -> Result<Option<String>, HistoryError> {
        match self.conn {
            Conn::Sqlite(_) => {
                let rows = self.conn.query("PRAGMA integrity_check", &[])?;
                let lines: Vec<String> = rows
                    .iter()
                    .filter_map(|r| {
                        r.first()
                            .and_then(|v| v.opt_text("integrity_check").ok().flatten())
                    })
                    .collect();
                Ok(Some(lines.join("\n")))
            }
            Conn::Postgres(_) => Ok(None),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsString;

    #[test]
    fn location_follows_the_xdg_base_directory_spec() {
        let home = Some(OsString::from("/home/tech"));
        assert_eq!(
            DbLocation::from_arg_in(None, Some("/data".into()), home.clone()).ok(),
            Some(DbLocation::Sqlite("/data/zerocal/history.sqlite".into()))
        );
        // Unset or relative XDG_DATA_HOME: the spec's default under HOME.
        for xdg in [
            None,
            Some(OsString::from("relative/dir")),
            Some(OsString::new()),
        ] {
            assert_eq!(
                DbLocation::from_arg_in(None, xdg, home.clone()).ok(),
                Some(DbLocation::Sqlite(
                    "/home/tech/.local/share/zerocal/history.sqlite".into()
                ))
            );
        }
        assert!(matches!(
            DbLocation::from_arg_in(None, None, None),
            Err(HistoryError::NoDataDir)
        ));
    }

    #[test]
    fn a_db_argument_is_a_server_url_or_a_file() {
        for url in [
            "postgres://u@h/db",
            "postgresql://u@h:5433/db?sslmode=disable",
        ] {
            assert_eq!(
                DbLocation::from_arg(Some(url)).ok(),
                Some(DbLocation::Postgres(url.into()))
            );
        }
        // A password on the command line is readable by every user of the machine.
        let refused = DbLocation::from_arg(Some("postgresql://u:p@h:5433/db"));
        assert!(
            matches!(&refused, Err(HistoryError::BadLocation(m)) if m.contains("PGPASSWORD")),
            "{refused:?}"
        );
        assert_eq!(
            DbLocation::from_arg(Some("plant/history.sqlite")).ok(),
            Some(DbLocation::Sqlite("plant/history.sqlite".into()))
        );
        assert!(matches!(
            DbLocation::from_arg(Some("")),
            Err(HistoryError::BadLocation(_))
        ));
    }

    #[test]
    fn a_url_is_shown_without_its_password() {
        let at = DbLocation::Postgres("postgresql://zc:s3cret@db.plant:5432/zerocal".into());
        assert_eq!(at.to_string(), "postgresql://zc:***@db.plant:5432/zerocal");
        let no_password = DbLocation::Postgres("postgres://zc@db/zerocal".into());
        assert_eq!(no_password.to_string(), "postgres://zc@db/zerocal");
        // In the query too, percent-encoded key or not, the other options kept.
        let query = DbLocation::Postgres(
            "postgres://zc@db/z?gssencmode=disable&pass%77ord=s3cret&sslmode=require".into(),
        );
        assert_eq!(
            query.to_string(),
            "postgres://zc@db/z?gssencmode=disable&pass%77ord=***&sslmode=require"
        );
    }

    #[test]
    fn sha256_matches_the_standard_test_vector() {
        // FIPS 180-2 appendix B.1: SHA-256("abc").
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }
}
