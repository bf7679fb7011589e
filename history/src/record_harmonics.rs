//! The `record_harmonics` table: each session's fitted harmonics
//! ([`crate::Harmonic`]) in typed rows, one per joint and order, written with the record
//! in its insert's transaction, read back into `NewRecord::harmonics`, and read by
//! [`crate::History::fleet`] without parsing any record's `result_json`.
//!
//! A table rather than typed columns on `records`: a session fits a varying number of
//! harmonics (per joint, as the profile models them), and the fleet's question (the
//! latest earlier session of the same robot that measured the same joint and order) is
//! a lookup by (record, joint, order), which the table's primary key answers.
//! The record's `result_json` keeps its `reducers` too, as the whole result it is;
//! schema 7 filled this table from it for the records stored before.

use crate::db::{Conn, Value};
use crate::reducers::{Harmonic, SessionHarmonics};
use crate::{HistoryError, RecordKind, RecordSummary, JOINTS};
use std::collections::BTreeMap;

/// The columns read, in [`from_row`]'s order.
const COLUMNS: &str =
    "record_id, joint, harmonic_order, amplitude_deg, phase_deg, amplitude_k2_deg, measured";

/// Why `harmonics` cannot be stored, or `None`.
pub(crate) fn invalid(harmonics: &[Harmonic]) -> Option<String> {
    let mut seen = std::collections::BTreeSet::new();
    for h in harmonics {
        if !JOINTS.contains(&h.joint) {
            return Some(format!(
                "harmonic j{} n={}: joint {} is outside {}..={}",
                h.joint,
                h.order,
                h.joint,
                JOINTS.start(),
                JOINTS.end()
            ));
        }
        if !seen.insert((h.joint, h.order)) {
            return Some(format!(
                "harmonic j{} n={} is given twice",
                h.joint, h.order
            ));
        }
        for (field, v) in [
            ("amplitude_deg", h.amplitude_deg),
            ("phase_deg", h.phase_deg),
            ("amplitude_k2_deg", h.amplitude_k2_deg),
        ] {
            if !v.is_finite() {
                return Some(format!(
                    "harmonic j{} n={}: {field} is {v}",
                    h.joint, h.order
                ));
            }
        }
        if h.amplitude_k2_deg < 0.0 {
            return Some(format!(
                "harmonic j{} n={}: amplitude_k2_deg {} is negative",
                h.joint, h.order, h.amplitude_k2_deg
            ));
        }
    }
    None
}

/// Stores the harmonics of record `id` inside the insert's transaction `c`.
pub(crate) fn insert(c: &mut Conn, id: i64, harmonics: &[Harmonic]) -> Result<(), HistoryError> {
    for h in harmonics {
        c.execute(
            "INSERT INTO record_harmonics (record_id, joint, harmonic_order, amplitude_deg, \
             phase_deg, amplitude_k2_deg, measured) VALUES ($1, $2, $3, $4, $5, $6, $7)",
            &[
                Value::Int(Some(id)),
                Value::Int(Some(i64::from(h.joint))),
                Value::Int(Some(i64::from(h.order))),
                Value::Real(Some(h.amplitude_deg)),
                Value::Real(Some(h.phase_deg)),
                Value::Real(Some(h.amplitude_k2_deg)),
                Value::Int(Some(i64::from(h.measured))),
            ],
        )?;
    }
    Ok(())
}

fn from_row(row: &[Value]) -> Result<(i64, Harmonic), HistoryError> {
    let [record_id, joint, order, amplitude, phase, k2, measured] = row else {
        return Err(HistoryError::Corrupt(format!(
            "a record_harmonics row has {} columns",
            row.len()
        )));
    };
    let record_id = record_id.i64("record_harmonics.record_id")?;
    let small = |v: &Value, what: &str| -> Result<u8, HistoryError> {
        let n = v.i64(what)?;
        u8::try_from(n)
            .map_err(|_| HistoryError::Corrupt(format!("record {record_id}: {what} {n}")))
    };
    let measured = match measured.i64("record_harmonics.measured")? {
        0 => false,
        1 => true,
        v => {
            return Err(HistoryError::Corrupt(format!(
                "record {record_id}: record_harmonics.measured {v}"
            )))
        }
    };
    Ok((
        record_id,
        Harmonic {
            joint: small(joint, "record_harmonics.joint")?,
            order: small(order, "record_harmonics.harmonic_order")?,
            amplitude_deg: amplitude.f64("record_harmonics.amplitude_deg")?,
            phase_deg: phase.f64("record_harmonics.phase_deg")?,
            amplitude_k2_deg: k2.f64("record_harmonics.amplitude_k2_deg")?,
            measured,
        },
    ))
}

/// The harmonics of the records `filter` (an SQL condition on `record_id`, with
/// `params`) selects, by record, each record's in joint and order.
pub(crate) fn by_record(
    c: &mut Conn,
    filter: &str,
    params: &[Value],
) -> Result<BTreeMap<i64, Vec<Harmonic>>, HistoryError> {
    let mut out: BTreeMap<i64, Vec<Harmonic>> = BTreeMap::new();
    for row in c.query(
        &format!(
            "SELECT {COLUMNS} FROM record_harmonics WHERE {filter} \
             ORDER BY record_id, joint, harmonic_order"
        ),
        params,
    )? {
        let (id, h) = from_row(&row)?;
        out.entry(id).or_default().push(h);
    }
    Ok(out)
}

/// Schema 7's rewrite: every session's `reducers` read from its `result_json` into
/// `record_harmonics`. A result without `reducers` (recorded before they were kept, or a
/// kept result of the pendant's) gives none; so does one whose `reducers` do not read
/// as [`Harmonic`]s or do not hold (a hand-edited database, a NaN written as `null`):
/// its result keeps them as written, nothing is lost, and the wear rule sees no
/// harmonics of that session, as it did not before. Refusing the migration instead
/// would leave every tool unable to open the history, with no correction that could
/// help (records are never edited).
pub(crate) fn backfill(c: &mut Conn) -> Result<(), HistoryError> {
    let rows = c.query(
        "SELECT id, result_json FROM records WHERE kind = $1 ORDER BY id",
        &[Value::text(RecordKind::Session.as_str())],
    )?;
    for row in rows {
        let [id, text] = row.as_slice() else {
            return Err(HistoryError::Corrupt(format!(
                "SELECT id, result_json returned {} columns",
                row.len()
            )));
        };
        let id = id.i64("records.id")?;
        let text = text.string("records.result_json")?;
        let Ok(result) = serde_json::from_str::<serde_json::Value>(&text) else {
            continue;
        };
        let Some(reducers) = result.get("reducers") else {
            continue;
        };
        let Ok(harmonics) = serde_json::from_value::<Vec<Harmonic>>(reducers.clone()) else {
            continue;
        };
        if invalid(&harmonics).is_some() {
            continue;
        }
        insert(c, id, &harmonics)?;
    }
    Ok(())
}

/// What the wear rule needs for each robot of `fleet`: its last session's harmonics and,
/// for each one that session measured, the latest session of the robot measured before
/// it that measured the same joint and order (a record a correction replaced left out),
/// in [`crate::RobotSummary::reducer_sessions`]. One query a chunk of 500 robots.
pub(crate) fn fill_fleet(
    c: &mut Conn,
    fleet: &mut [crate::RobotSummary],
) -> Result<(), HistoryError> {
    let ids: Vec<i64> = fleet
        .iter()
        .filter_map(|r| r.last_session.as_ref().map(|s| s.id))
        .collect();
    // Per harmonic of a last session: it, then the previous measurement's record, day
    // and harmonic (NULL where there is none). The previous is found through the
    // records' (serial, measured_on, id) index and the harmonics' primary key.
    let mut last: BTreeMap<i64, Vec<Harmonic>> = BTreeMap::new();
    let mut before: BTreeMap<i64, BTreeMap<i64, SessionHarmonics>> = BTreeMap::new();
    for list in crate::db::id_lists(&ids) {
        let rows = c.query(
            &format!(
                "SELECT h.record_id, h.joint, h.harmonic_order, h.amplitude_deg, h.phase_deg, \
                 h.amplitude_k2_deg, h.measured, \
                 p.record_id, pr.serial, pr.measured_on, p.joint, p.harmonic_order, \
                 p.amplitude_deg, p.phase_deg, p.amplitude_k2_deg, p.measured \
                 FROM record_harmonics h JOIN records r ON r.id = h.record_id \
                 LEFT JOIN record_harmonics p ON h.measured = 1 \
                 AND p.joint = h.joint AND p.harmonic_order = h.harmonic_order \
                 AND p.record_id = (SELECT r2.id FROM records r2 \
                   JOIN record_harmonics m ON m.record_id = r2.id \
                   AND m.joint = h.joint AND m.harmonic_order = h.harmonic_order \
                   AND m.measured = 1 \
                   WHERE r2.serial = r.serial AND r2.kind = '{session}' \
                   AND (r2.measured_on < r.measured_on \
                        OR (r2.measured_on = r.measured_on AND r2.id < r.id)) \
                   AND r2.id NOT IN (SELECT replaces_id FROM corrections) \
                   ORDER BY r2.measured_on DESC, r2.id DESC LIMIT 1) \
                 LEFT JOIN records pr ON pr.id = p.record_id \
                 WHERE h.record_id IN ({list}) \
                 ORDER BY h.record_id, h.joint, h.harmonic_order",
                session = RecordKind::Session.as_str()
            ),
            &[],
        )?;
        for row in rows {
            let (now, rest) = row.split_at(7.min(row.len()));
            let (id, h) = from_row(now)?;
            last.entry(id).or_default().push(h);
            let [prev_id, serial, measured_on, p @ ..] = rest else {
                return Err(HistoryError::Corrupt(format!(
                    "the fleet's harmonics row has {} columns",
                    row.len()
                )));
            };
            let Some(prev_id) = prev_id.opt_i64("record_harmonics.record_id")? else {
                continue;
            };
            let mut p_row = vec![Value::Int(Some(prev_id))];
            p_row.extend_from_slice(p);
            let (_, previous) = from_row(&p_row)?;
            let (serial, measured_on) = (
                serial.string("records.serial")?,
                measured_on.string("records.measured_on")?,
            );
            before
                .entry(id)
                .or_default()
                .entry(prev_id)
                .or_insert_with(|| SessionHarmonics {
                    record_id: prev_id,
                    serial,
                    measured_on,
                    reducers: Vec::new(),
                })
                .reducers
                .push(previous);
        }
    }
    for robot in fleet {
        let Some(RecordSummary {
            id, measured_on, ..
        }) = robot.last_session.as_ref()
        else {
            continue;
        };
        let Some(harmonics) = last.remove(id) else {
            continue;
        };
        let mut sessions = vec![SessionHarmonics {
            record_id: *id,
            serial: robot.serial.clone(),
            measured_on: measured_on.clone(),
            reducers: harmonics,
        }];
        sessions.extend(before.remove(id).unwrap_or_default().into_values());
        robot.reducer_sessions = sessions;
    }
    Ok(())
}
