//! The way back from the history: a stored session solved again exactly as it was, from
//! its own export and profile (what `zerocal certificate`, `check` and `restore` start
//! from). A session's record is made by `crate::session::session_record`.

use crate::session::{analyse_with, Analysis, SessionArgs};
use std::path::PathBuf;
use zerocal_history::{Record, RecordKind};
use zerocal_inputs::error::CliError;

/// What a record imported from a kept result says of its uncertainty
/// (`zerocal history --import`, zerocal-records).
pub const KEPT_RESULT_NOTE: &str = "imported from the pendant's kept results: U(k = 2) is twice \
     the fit's 1-sigma (the pendant keeps no budget); record the export itself (zerocal session \
     EXPORT --record) for the whole budget, a certificate or a check";

/// A stored session solved again, as it was: its export with its own profile.
///
/// # Errors
/// A record of a check, or one the solver now refuses (a record of another version).
pub fn solve_record(record: &Record) -> Result<Analysis, CliError> {
    if record.new.kind != RecordKind::Session {
        return Err(CliError::Input(format!(
            "record {} is a {}, not a session: give a session's ID",
            record.id,
            record.new.kind.as_str()
        )));
    }
    if record.new.pendant_result_id.is_some()
        && !record.new.export.starts_with(b"# zerocal pendant export")
    {
        return Err(CliError::Input(format!(
            "record {}: {}",
            record.id, KEPT_RESULT_NOTE
        )));
    }
    let profile = zerocal_profile::parse(&record.new.profile_toml).map_err(|e| {
        CliError::Input(format!(
            "record {}: its robot profile does not read: {e}",
            record.id
        ))
    })?;
    let args = SessionArgs::for_export(PathBuf::from(format!("record {}", record.id)));
    analyse_with(
        &args,
        &record.new.export,
        Some((profile, record.new.profile_toml.clone())),
    )
}
