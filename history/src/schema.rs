//! The versioned schema: the migration steps, how a database says it is zerocal's and
//! at which version, and the checks made before anything is written to it.
//!
//! SQLite marks the file itself (`PRAGMA application_id` = [`SQLITE_APPLICATION_ID`],
//! `PRAGMA user_version` = the schema version), so a file is recognised from its
//! header before any table is read. PostgreSQL has no such header: there the
//! `zerocal_meta` table is the mark. Both backends keep `zerocal_meta` (one row:
//! application name and schema version) so the schema is the same text for both; on
//! SQLite the header is what opening checks, and both are set in the same transaction.

use crate::db::{Conn, Value};
use crate::HistoryError;
use std::path::Path;
use std::time::Duration;

/// SQLite `application_id` of a zerocal history: "ZCAL" in ASCII.
pub const SQLITE_APPLICATION_ID: i64 = 0x5A43_414C;

/// The application name in `zerocal_meta`.
pub const APPLICATION: &str = "zerocal";

/// How long a writer waits for another process's write to finish before giving up.
/// A whole insert takes milliseconds; ten seconds covers a slow disk and a queue of
/// several writers.
pub const BUSY_TIMEOUT: Duration = Duration::from_secs(10);

/// One step of the schema: applied in its own transaction, after which the database
/// is at `version`.
pub struct Migration {
    /// The schema version this step makes.
    pub version: i64,
    /// What it changes, for the docs and messages.
    pub what: &'static str,
    /// The statements, written once for both dialects (see `db::Dialect::sql`).
    pub sql: &'static str,
    /// A rewrite of stored values that SQL alone would write twice (once per dialect's
    /// JSON functions), run after `sql` in the same transaction.
    pub(crate) rewrite: Option<Rewrite>,
}

/// A migration's rewrite of stored values, inside the step's transaction.
pub(crate) type Rewrite = fn(&mut Conn) -> Result<(), HistoryError>;

/// Every step, oldest first. Never edit a step that has shipped: add one.
pub const MIGRATIONS: &[Migration] = &[
    Migration {
        version: 1,
        what: "records, joints and zerocal_meta; one record per serial, kind and export",
        sql: "
CREATE TABLE zerocal_meta (
    application TEXT NOT NULL,
    schema_version BIGINT NOT NULL
);
CREATE TABLE records (
    id {id},
    recorded_at TEXT NOT NULL,
    kind TEXT NOT NULL CHECK (kind IN ('session', 'check')),
    serial TEXT NOT NULL,
    robot TEXT NOT NULL,
    robot_title TEXT NOT NULL,
    controller_family TEXT NOT NULL,
    profile_toml TEXT NOT NULL,
    profile_sha256 TEXT NOT NULL,
    export {bytes} NOT NULL,
    export_sha256 TEXT NOT NULL,
    measured_on TEXT NOT NULL,
    operator TEXT,
    pendant_unit TEXT,
    pendant_result_id BIGINT,
    reference_id BIGINT REFERENCES records (id),
    zerocal_version TEXT NOT NULL,
    verdict TEXT NOT NULL,
    brackets_json TEXT NOT NULL,
    conditions_json TEXT NOT NULL,
    result_json TEXT NOT NULL
);
CREATE UNIQUE INDEX records_once ON records (serial, kind, export_sha256);
CREATE TABLE joints (
    record_id BIGINT NOT NULL REFERENCES records (id),
    joint BIGINT NOT NULL CHECK (joint BETWEEN 2 AND 6),
    name TEXT NOT NULL,
    offset_deg DOUBLE PRECISION NOT NULL,
    expanded_k2_deg DOUBLE PRECISION NOT NULL,
    controller_offset_deg DOUBLE PRECISION NOT NULL,
    pass BIGINT CHECK (pass IN (0, 1)),
    PRIMARY KEY (record_id, joint)
);
",
        rewrite: None,
    },
    Migration {
        version: 2,
        what: "index of records by serial and ID (`zerocal history SERIAL` lists in ID order)",
        sql: "CREATE INDEX records_by_serial ON records (serial, id);",
        rewrite: None,
    },
    Migration {
        version: 3,
        what: "conventions: how each robot's controller takes a typed offset, per joint, with \
               the check that measured it; certificates: each issued certificate's number, \
               its session (as found), its check after the entry (as left), its issue date, \
               its issuer and equipment",
        sql: "
CREATE TABLE conventions (
    id {id},
    recorded_at TEXT NOT NULL,
    serial TEXT NOT NULL,
    joint BIGINT NOT NULL CHECK (joint BETWEEN 2 AND 6),
    factor DOUBLE PRECISION NOT NULL,
    check_id BIGINT NOT NULL REFERENCES records (id),
    verified BIGINT NOT NULL CHECK (verified IN (0, 1)),
    UNIQUE (check_id, joint)
);
CREATE INDEX conventions_by_serial ON conventions (serial, id);
CREATE TABLE certificates (
    number TEXT PRIMARY KEY,
    session_id BIGINT NOT NULL REFERENCES records (id),
    as_left_id BIGINT REFERENCES records (id),
    issued_on TEXT NOT NULL,
    issuer_json TEXT NOT NULL,
    issuer_sha256 TEXT NOT NULL,
    recorded_at TEXT NOT NULL
);
CREATE INDEX certificates_by_session ON certificates (session_id);
",
        rewrite: None,
    },
    Migration {
        version: 4,
        what: "texts: a profile's text stored once by its SHA-256 and referenced by every \
               record of it (records.profile_sha256), where each record held a copy",
        sql: "
CREATE TABLE texts (
    sha256 TEXT PRIMARY KEY,
    text TEXT NOT NULL
);
INSERT INTO texts (sha256, text) SELECT DISTINCT profile_sha256, profile_toml FROM records;
ALTER TABLE records DROP COLUMN profile_toml;
",
        rewrite: None,
    },
    Migration {
        version: 5,
        what: "the web application's state, kept in the database so that several servers \
               share it: users (name, role, Argon2 PHC hash), web sessions (the SHA-256 of \
               their random ID, the user, the expiry, the CSRF token), login attempts (the \
               flood limit), signatures (a record checked, then authorized, each by whom and \
               when), corrections (a new record naming the one it replaces, why and by \
               whom), the append-only audit log, and an index holding every column the \
               fleet view reads (a record's columns after its export are read through the \
               export's overflow pages otherwise) (who, when, what, before and after)",
        sql: "
CREATE TABLE users (
    name TEXT PRIMARY KEY,
    role TEXT NOT NULL CHECK (role IN ('technician', 'reviewer', 'authorizer', 'admin')),
    password_phc TEXT NOT NULL,
    active BIGINT NOT NULL CHECK (active IN (0, 1)),
    created_at TEXT NOT NULL
);
CREATE TABLE web_sessions (
    id_sha256 TEXT PRIMARY KEY,
    user_name TEXT NOT NULL REFERENCES users (name),
    csrf_token TEXT NOT NULL,
    expires_unix BIGINT NOT NULL
);
CREATE TABLE login_attempts (
    id {id},
    user_name TEXT NOT NULL,
    at_unix BIGINT NOT NULL,
    succeeded BIGINT NOT NULL CHECK (succeeded IN (0, 1))
);
CREATE INDEX login_attempts_by_user ON login_attempts (user_name, at_unix);
CREATE TABLE signatures (
    record_id BIGINT NOT NULL REFERENCES records (id),
    step TEXT NOT NULL CHECK (step IN ('checked', 'authorized')),
    user_name TEXT NOT NULL REFERENCES users (name),
    signed_at TEXT NOT NULL,
    PRIMARY KEY (record_id, step)
);
CREATE INDEX records_fleet ON records (serial, measured_on, id, kind, robot, robot_title, verdict);
CREATE TABLE corrections (
    record_id BIGINT PRIMARY KEY REFERENCES records (id),
    replaces_id BIGINT NOT NULL UNIQUE REFERENCES records (id),
    reason TEXT NOT NULL,
    user_name TEXT NOT NULL,
    recorded_at TEXT NOT NULL
);
CREATE TABLE audit (
    id {id},
    at TEXT NOT NULL,
    actor TEXT NOT NULL,
    action TEXT NOT NULL,
    subject TEXT NOT NULL,
    before_json TEXT,
    after_json TEXT NOT NULL
);
",
        rewrite: None,
    },
    Migration {
        version: 6,
        what: "records.brackets_json in one typed shape (`RecordBrackets`: each mount's \
               bracket ID and, where known, its calibration), rewritten from the two shapes \
               older builds wrote (a session's array of mounts, an import's IDs by mount)",
        sql: "",
        rewrite: Some(brackets_in_one_shape),
    },
    Migration {
        version: 7,
        what: "record_harmonics: each session's fitted harmonics of its joints' transmission \
               error (joint, order, amplitude, phase, amplitude's U(k=2), measured or held at \
               its prior) in typed rows, filled from the `reducers` of the results stored \
               before, so that the fleet view reads the reducers' health without parsing \
               any result",
        sql: "
CREATE TABLE record_harmonics (
    record_id BIGINT NOT NULL REFERENCES records (id),
    joint BIGINT NOT NULL CHECK (joint BETWEEN 2 AND 6),
    harmonic_order BIGINT NOT NULL,
    amplitude_deg DOUBLE PRECISION NOT NULL,
    phase_deg DOUBLE PRECISION NOT NULL,
    amplitude_k2_deg DOUBLE PRECISION NOT NULL,
    measured BIGINT NOT NULL CHECK (measured IN (0, 1)),
    PRIMARY KEY (record_id, joint, harmonic_order)
);
",
        rewrite: Some(crate::record_harmonics::backfill),
    },
];

/// Schema 6's rewrite: every record's brackets read in either old shape
/// ([`crate::brackets::from_old_json`]) and written in the typed one. A record whose
/// brackets fit neither stops the migration, naming it: the database stays at schema 5,
/// nothing rewritten, rather than a record's brackets being dropped.
fn brackets_in_one_shape(c: &mut Conn) -> Result<(), HistoryError> {
    for row in c.query("SELECT id, brackets_json FROM records ORDER BY id", &[])? {
        let [id, text] = row.as_slice() else {
            return Err(HistoryError::Corrupt(format!(
                "SELECT id, brackets_json returned {} columns",
                row.len()
            )));
        };
        let id = id.i64("records.id")?;
        let text = text.string("records.brackets_json")?;
        let brackets = crate::brackets::from_old_json(&text).map_err(|e| {
            HistoryError::Corrupt(format!(
                "record {id}: brackets_json {text:?} fits no shape zerocal wrote ({e}); \
                 the database is left at schema 5"
            ))
        })?;
        let new = brackets.to_json();
        if new != text {
            c.execute(
                "UPDATE records SET brackets_json = $1 WHERE id = $2",
                &[Value::Text(Some(new)), Value::Int(Some(id))],
            )?;
        }
    }
    Ok(())
}

/// The newest schema version this build reads and writes.
pub const SCHEMA_VERSION: i64 = MIGRATIONS[MIGRATIONS.len() - 1].version;

/// What a database holds, as far as opening is concerned.
#[derive(Debug, PartialEq)]
enum Mark {
    /// No tables and no mark: a new database, made here.
    Empty,
    /// Zerocal's, at this schema version.
    Ours(i64),
    /// Someone else's: what was found.
    Foreign(String),
}

fn check(mark: Mark, what: &str) -> Result<i64, HistoryError> {
    match mark {
        Mark::Empty => Ok(0),
        Mark::Foreign(found) => Err(HistoryError::NotZerocal {
            what: format!("{what} ({found})"),
        }),
        Mark::Ours(found) if found > SCHEMA_VERSION => Err(HistoryError::NewerSchema {
            found,
            supported: SCHEMA_VERSION,
        }),
        Mark::Ours(v) => Ok(v),
    }
}

fn sqlite_mark(c: &mut Conn) -> Result<Mark, HistoryError> {
    // One statement, so one snapshot: read one at a time, another process's first
    // migration could commit between them (application_id 0 read before it, its
    // user_version and tables after), and a zerocal database be called foreign.
    const MARK: &str = "SELECT (SELECT application_id FROM pragma_application_id()), \
                        (SELECT user_version FROM pragma_user_version()), \
                        (SELECT count(*) FROM sqlite_master)";
    let rows = c.query(MARK, &[])?;
    let [application_id, version, tables] = match rows.first().map(Vec::as_slice) {
        Some([a, v, t]) => [
            a.i64("application_id")?,
            v.i64("user_version")?,
            t.i64("count")?,
        ],
        _ => return Err(HistoryError::Corrupt(format!("{MARK} returned nothing"))),
    };
    Ok(if application_id == SQLITE_APPLICATION_ID {
        Mark::Ours(version)
    } else if application_id == 0 && version == 0 && tables == 0 {
        Mark::Empty
    } else {
        Mark::Foreign(format!(
            "an SQLite database with application_id {application_id:#x}, \
             user_version {version} and {tables} schema objects"
        ))
    })
}

fn postgres_mark(c: &mut Conn) -> Result<Mark, HistoryError> {
    let tables: Vec<String> = c
        .query(
            "SELECT table_name::text FROM information_schema.tables \
             WHERE table_schema = current_schema() \
             AND table_name IN ('zerocal_meta', 'records', 'joints')",
            &[],
        )?
        .iter()
        .filter_map(|r| {
            r.first()
                .and_then(|v| v.opt_text("table_name").ok().flatten())
        })
        .collect();
    if tables.is_empty() {
        return Ok(Mark::Empty);
    }
    if !tables.iter().any(|t| t == "zerocal_meta") {
        return Ok(Mark::Foreign(format!(
            "tables {} not made by zerocal, and no zerocal_meta",
            tables.join(", ")
        )));
    }
    let rows = c.query("SELECT application, schema_version FROM zerocal_meta", &[])?;
    match rows.as_slice() {
        [row] if row.len() == 2 => {
            let application = row[0].string("zerocal_meta.application")?;
            let version = row[1].i64("zerocal_meta.schema_version")?;
            if application == APPLICATION {
                Ok(Mark::Ours(version))
            } else {
                Ok(Mark::Foreign(format!(
                    "zerocal_meta names the application {application:?}"
                )))
            }
        }
        _ => Ok(Mark::Foreign(format!(
            "zerocal_meta holds {} rows, not one",
            rows.len()
        ))),
    }
}

fn mark(c: &mut Conn) -> Result<Mark, HistoryError> {
    match c {
        Conn::Sqlite(_) => sqlite_mark(c),
        Conn::Postgres(_) => postgres_mark(c),
    }
}

fn set_version(c: &mut Conn, version: i64) -> Result<(), HistoryError> {
    let v = [Value::Int(Some(version))];
    if c.execute("UPDATE zerocal_meta SET schema_version = $1", &v)? == 0 {
        c.execute(
            "INSERT INTO zerocal_meta (application, schema_version) VALUES ($1, $2)",
            &[Value::text(APPLICATION), Value::Int(Some(version))],
        )?;
    }
    if let Conn::Sqlite(_) = c {
        // Pragmas take no parameters; both numbers are ours.
        c.batch(&format!(
            "PRAGMA application_id = {SQLITE_APPLICATION_ID}; PRAGMA user_version = {version};"
        ))?;
    }
    Ok(())
}

/// Brings the database up to `target` (at most [`SCHEMA_VERSION`]), one transaction a
/// step, each re-reading the mark under the write lock so that a process that opened
/// it at the same time and migrated first is not repeated.
fn migrate(c: &mut Conn, what: &str, target: i64) -> Result<(), HistoryError> {
    if check(mark(c)?, what)? >= target {
        return Ok(());
    }
    for step in MIGRATIONS.iter().filter(|m| m.version <= target) {
        let lock = c.dialect().lock_schema;
        c.write(|c| {
            if let Some(lock) = lock {
                c.execute(lock, &[])?;
            }
            let at = check(mark(c)?, what)?;
            if at >= step.version {
                return Ok(());
            }
            if !step.sql.is_empty() {
                c.batch(step.sql)?;
            }
            if let Some(rewrite) = step.rewrite {
                rewrite(c)?;
            }
            set_version(c, step.version)
        })?;
    }
    Ok(())
}

/// The schema version of an open database.
pub(crate) fn version(c: &mut Conn, what: &str) -> Result<i64, HistoryError> {
    check(mark(c)?, what)
}

fn not_a_database(e: &rusqlite::Error) -> bool {
    matches!(
        e,
        rusqlite::Error::SqliteFailure(f, _) if f.code == rusqlite::ErrorCode::NotADatabase
    )
}

/// Reads the file's mark through a read-only connection: nothing is written to a file
/// that turns out not to be ours or to be newer. An absent or empty file passes (it
/// is made here).
fn inspect_sqlite(path: &Path, what: &str) -> Result<(), HistoryError> {
    let meta = match std::fs::metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => {
            return Err(HistoryError::Io(std::io::Error::new(
                e.kind(),
                format!("{what}: {e}"),
            )))
        }
    };
    if meta.is_dir() {
        return Err(HistoryError::NotZerocal {
            what: format!("{what} (a directory)"),
        });
    }
    if meta.len() == 0 {
        return Ok(());
    }
    let foreign = |e: &rusqlite::Error| HistoryError::NotZerocal {
        what: format!("{what} ({e})"),
    };
    let ro = rusqlite::Connection::open_with_flags(
        path,
        rusqlite::OpenFlags::SQLITE_OPEN_READ_ONLY | rusqlite::OpenFlags::SQLITE_OPEN_NO_MUTEX,
    )?;
    ro.busy_timeout(BUSY_TIMEOUT)?;
    let mut ro = Conn::Sqlite(ro);
    match mark(&mut ro) {
        Ok(m) => check(m, what).map(|_| ()),
        Err(HistoryError::Sqlite(e)) if not_a_database(&e) => Err(foreign(&e)),
        Err(e) => Err(e),
    }
}

/// Opens (making it if absent or empty) the SQLite history at `path`, migrated up to
/// `target`: WAL journal, the busy timeout, foreign keys on.
///
/// SQLite answers `SQLITE_BUSY` at once, without its busy handler, where waiting inside
/// the call could deadlock: switching a database another process is making to WAL, or
/// reading a WAL index another opener is still building. Opening is then tried again,
/// from the start, until [`BUSY_TIMEOUT`]: processes that open one new database at once
/// (`history/tests/store.rs`, three writers) all get it, none fails.
pub(crate) fn open_sqlite(path: &Path, target: i64) -> Result<Conn, HistoryError> {
    let start = std::time::Instant::now();
    let mut pause = Duration::from_millis(2);
    loop {
        match open_sqlite_once(path, target) {
            Err(HistoryError::Sqlite(e)) if busy(&e) && start.elapsed() < BUSY_TIMEOUT => {
                std::thread::sleep(pause);
                pause = (pause * 2).min(Duration::from_millis(100));
            }
            other => return other,
        }
    }
}

/// Whether SQLite refused for another connection's lock (the open may be tried again).
fn busy(e: &rusqlite::Error) -> bool {
    matches!(
        e.sqlite_error_code(),
        Some(rusqlite::ErrorCode::DatabaseBusy | rusqlite::ErrorCode::DatabaseLocked)
    )
}

fn open_sqlite_once(path: &Path, target: i64) -> Result<Conn, HistoryError> {
    let what = path.display().to_string();
    inspect_sqlite(path, &what)?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| {
            HistoryError::Io(std::io::Error::new(
                e.kind(),
                format!("{}: {e}", dir.display()),
            ))
        })?;
    }
    let c = rusqlite::Connection::open(path)?;
    c.busy_timeout(BUSY_TIMEOUT)?;
    // WAL: readers never block the writer and a commit is one append to the log, so a
    // process killed mid-write leaves the last committed state. `synchronous = FULL`
    // (SQLite's default, set so that no build option changes it): a commit is on disk
    // when insert returns, power cut included.
    let mode: String = c.query_row("PRAGMA journal_mode = WAL", [], |r| r.get(0))?;
    if !mode.eq_ignore_ascii_case("wal") {
        return Err(HistoryError::Corrupt(format!(
            "{what}: SQLite kept journal mode {mode}, not WAL"
        )));
    }
    c.execute_batch("PRAGMA synchronous = FULL; PRAGMA foreign_keys = ON")?;
    let mut c = Conn::Sqlite(c);
    migrate(&mut c, &what, target)?;
    Ok(c)
}

/// Opens the PostgreSQL history at `url` (`what` is the URL without its password),
/// making the tables in an empty database, migrated up to `target`.
///
/// A URL without a password takes it from `PGPASSWORD` or the password file, as libpq
/// does (`pgpass.rs`).
pub(crate) fn open_postgres(url: &str, what: &str, target: i64) -> Result<Conn, HistoryError> {
    let client = crate::postgres_connect(url)?;
    let mut c = Conn::Postgres(Box::new(client));
    // The first look writes nothing: a foreign or newer database is refused as it is.
    check(mark(&mut c)?, what)?;
    migrate(&mut c, what, target)?;
    Ok(c)
}
