//! The reducers' health over time, from the history's records: each session's fitted
//! harmonics (the record's typed `harmonics`, [`zerocal_history::Harmonic`]) put to
//! the wear rule ([`zerocal_history::reducers`]: an amplitude up by more than
//! [`WEAR_SIGMAS`] combined standard uncertainties since the robot's previous session
//! that measured it, [`ReducerChange`]). `zerocal session --record` prints the new
//! record's changes, `zerocal history` every record's, and `zerocal history --plot`
//! draws the amplitudes; the web application's fleet page applies the same rule.

pub use zerocal_history::reducers::{changes, ReducerChange, SessionHarmonics, WEAR_SIGMAS};
use zerocal_history::{Record, RecordKind};

/// A session's harmonics from its record: `None` for a check, and for a session that
/// holds none (recorded before they were kept, or a kept result of the pendant's).
#[must_use]
pub fn of_record(record: &Record) -> Option<SessionHarmonics> {
    if record.new.kind != RecordKind::Session || record.new.harmonics.is_empty() {
        return None;
    }
    Some(SessionHarmonics {
        record_id: record.id,
        serial: record.new.serial.clone(),
        measured_on: record.new.measured_on.clone(),
        reducers: record.new.harmonics.clone(),
    })
}

/// [`changes`] over the sessions among `records`.
#[must_use]
pub fn changes_in(records: &[Record]) -> Vec<ReducerChange> {
    changes(&records.iter().filter_map(of_record).collect::<Vec<_>>())
}
