//! What can go wrong opening or using a history database, each case naming its cause.

use std::fmt;

/// An error of the history database. Its `Display` names what is wrong and where.
#[derive(Debug)]
pub enum HistoryError {
    /// The file or server database exists but is not a zerocal history (another
    /// application's database, random bytes, a text file). It was left untouched.
    NotZerocal {
        /// The path or URL, and what was found there.
        what: String,
    },
    /// The database was written by a newer zerocal (schema `found`); this build reads up
    /// to `supported`. It was left untouched.
    NewerSchema {
        /// The schema version stored in the database.
        found: i64,
        /// The newest schema version this build knows.
        supported: i64,
    },
    /// No record has this ID.
    NoSuchRecord(i64),
    /// A record given to [`crate::History::insert`] that cannot be stored as it is.
    InvalidRecord(String),
    /// A change the history refuses as asked (a signature out of order or by the wrong
    /// role, an account that exists): nothing was written.
    Refused(String),
    /// An export of robot profile `export` under `serial`, whose record `record_id` is of
    /// profile `stored`: another robot's export, not recorded.
    AnotherRobot {
        /// The serial typed with the export.
        serial: String,
        /// The profile of the serial's record in the history.
        stored: String,
        /// That record's ID.
        record_id: i64,
        /// The export's profile.
        export: String,
    },
    /// A stored value that does not read as what the schema says it is.
    Corrupt(String),
    /// No `--db` given and neither `XDG_DATA_HOME` nor `HOME` is set.
    NoDataDir,
    /// A `--db` that names no location (empty).
    BadLocation(String),
    /// SQLite refused an operation.
    Sqlite(rusqlite::Error),
    /// TLS to the PostgreSQL server cannot be had as `sslmode` asks: the server's
    /// certificate not trusted, no TLS offered, the root certificates unreadable.
    Tls(String),
    /// The PostgreSQL server or its client refused an operation.
    Postgres(postgres::Error),
    /// A file or directory could not be read or made.
    Io(std::io::Error),
}

impl fmt::Display for HistoryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotZerocal { what } => write!(
                f,
                "{what} is not a zerocal history database (left untouched)"
            ),
            Self::NewerSchema { found, supported } => write!(
                f,
                "the history database has schema version {found}, written by a newer zerocal; \
                 this build reads versions up to {supported} (left untouched: use a newer zerocal)"
            ),
            Self::NoSuchRecord(id) => write!(f, "no history record has ID {id}"),
            Self::InvalidRecord(why) => write!(f, "record not stored: {why}"),
            Self::Refused(why) => write!(f, "refused: {why}"),
            Self::AnotherRobot {
                serial,
                stored,
                record_id,
                export,
            } => write!(
                f,
                "serial {serial:?} is a {stored} in the history (record {record_id}); this export is of a {export}: another robot's export, not recorded"
            ),
            Self::Corrupt(why) => write!(
                f,
                "the history database holds a value that does not read: {why}"
            ),
            Self::NoDataDir => write!(
                f,
                "no history database location: give --db, or set XDG_DATA_HOME or HOME"
            ),
            Self::BadLocation(why) => write!(f, "{why}"),
            Self::Sqlite(e) => write!(f, "SQLite: {e}"),
            Self::Tls(why) => write!(f, "PostgreSQL over TLS: {why}"),
            // The client's own text is only the kind ("db error", "error connecting to
            // server"); the cause says what the server or the socket said.
            Self::Postgres(e) => match std::error::Error::source(e) {
                Some(cause) => write!(f, "PostgreSQL: {e}: {cause}"),
                None => write!(f, "PostgreSQL: {e}"),
            },
            Self::Io(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for HistoryError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Sqlite(e) => Some(e),
            Self::Postgres(e) => Some(e),
            Self::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<rusqlite::Error> for HistoryError {
    fn from(e: rusqlite::Error) -> Self {
        Self::Sqlite(e)
    }
}

impl From<postgres::Error> for HistoryError {
    fn from(e: postgres::Error) -> Self {
        Self::Postgres(e)
    }
}

impl From<std::io::Error> for HistoryError {
    fn from(e: std::io::Error) -> Self {
        Self::Io(e)
    }
}
