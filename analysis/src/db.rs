//! `--db PATH|URL`: where the calibration history is, the one option every command
//! that reads or writes it shares ([`zerocal_history::DbLocation`]).

use clap::Args;
use zerocal_history::{DbLocation, History};
use zerocal_inputs::error::CliError;

/// `--db PATH|URL`: where the history is.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct DbArg {
    /// The history database: an SQLite file, or a PostgreSQL server
    /// `postgres://USER@HOST:PORT/DATABASE` (the password from PGPASSWORD or
    /// ~/.pgpass, never here; TLS as ?sslmode= asks, prefer by default:
    /// docs/history.md). Default:
    /// $XDG_DATA_HOME/zerocal/history.sqlite, else ~/.local/share/zerocal/history.sqlite.
    #[arg(long, value_name = "PATH|URL")]
    pub db: Option<String>,
}

/// The history's error as the CLI's, naming the database unless the error does.
pub fn history_error(at: &DbLocation) -> impl Fn(zerocal_history::HistoryError) -> CliError + '_ {
    move |e| match e {
        zerocal_history::HistoryError::NotZerocal { .. } => {
            CliError::Input(format!("history: {e}"))
        }
        _ => CliError::Input(format!("history {at}: {e}")),
    }
}

impl DbArg {
    /// The location `--db` names, or the default.
    ///
    /// # Errors
    /// An empty `--db`; no `--db` and no data directory.
    pub fn location(&self) -> Result<DbLocation, CliError> {
        DbLocation::from_arg(self.db.as_deref())
            .map_err(|e| CliError::Input(format!("history: {e}")))
    }

    /// Opens (making or migrating) the history `--db` names.
    ///
    /// # Errors
    /// As [`History::open`], with the location named.
    pub fn open(&self) -> Result<History, CliError> {
        let at = self.location()?;
        History::open(&at).map_err(history_error(&at))
    }
}

/// A history error as the CLI's.
pub fn history_failed(e: zerocal_history::HistoryError) -> CliError {
    match e {
        // A well-formed ID the history does not hold: nothing to give numbers from.
        zerocal_history::HistoryError::NoSuchRecord(_) => {
            CliError::Refused(format!("history: {e}"))
        }
        _ => CliError::Input(format!("history: {e}")),
    }
}

/// Who recorded, when: the options every recording command shares.
#[derive(Args, Debug, Clone, Default)]
pub struct RecordMeta {
    /// Who measured (stored with the record, printed on its certificate).
    #[arg(long, value_name = "NAME")]
    pub operator: Option<String>,
    /// The day measured, YYYY-MM-DD (default: today, UTC).
    #[arg(long, value_name = "DAY")]
    pub measured_on: Option<String>,
}

impl RecordMeta {
    /// The day measured.
    ///
    /// # Errors
    /// `--measured-on` that is not a day of 2000-2999 (without it: today, by the clock).
    pub fn day(&self) -> Result<String, CliError> {
        match &self.measured_on {
            Some(d) => zerocal_inputs::bracket_file::calibration_day(d)
                .map(|day| day.to_string())
                .map_err(|e| {
                    CliError::Input(format!("--measured-on '{d}': not a day YYYY-MM-DD: {e}"))
                }),
            None => Ok(zerocal_inputs::bracket_file::today_utc()),
        }
    }
}
