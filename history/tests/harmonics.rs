//! A session's fitted harmonics in typed rows (schema 7, `record_harmonics`): stored
//! with the record and read back with it, refused on insert when they do not hold; the
//! records a schema-6 build stored get theirs from their result's `reducers` when the
//! database is migrated (none for a result without them), and a result whose
//! `reducers` do not read stops the migration naming the record. On every backend.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, insert_at_schema_5, old_import_brackets, record};
use zerocal_history::schema::SCHEMA_VERSION;
use zerocal_history::{Harmonic, History, HistoryError, RecordKind};

fn harmonics() -> Vec<Harmonic> {
    vec![
        Harmonic {
            joint: 3,
            order: 1,
            amplitude_deg: 0.0042,
            phase_deg: -35.5,
            amplitude_k2_deg: 0.0011,
            measured: true,
        },
        Harmonic {
            joint: 4,
            order: 2,
            amplitude_deg: 0.0005,
            phase_deg: 12.25,
            amplitude_k2_deg: 0.003,
            measured: false,
        },
    ]
}

#[test]
fn a_sessions_harmonics_are_stored_with_it_and_read_back() {
    for b in backends("harmonics_stored") {
        let mut h = History::open(&b.at).unwrap();
        let mut r = record(RecordKind::Session, "KR6-0101", 1, 128);
        r.harmonics = harmonics();
        let id = h.insert(&r).unwrap().id;
        assert_eq!(h.get(id).unwrap().new.harmonics, harmonics(), "{}", b.name);
        let listed = h.list(Some("KR6-0101")).unwrap();
        assert_eq!(listed[0].new.harmonics, harmonics(), "{}", b.name);
    }
}

#[test]
fn harmonics_that_do_not_hold_are_refused_on_insert_naming_them() {
    for b in backends("harmonics_refused") {
        let mut h = History::open(&b.at).unwrap();
        type Spoil = fn(&mut Vec<Harmonic>);
        let spoils: [(Spoil, &str); 3] = [
            (|v| v[0].joint = 7, "joint 7 is outside"),
            (|v| v[1] = v[0].clone(), "j3 n=1 is given twice"),
            (
                |v| v[0].amplitude_k2_deg = -0.001,
                "amplitude_k2_deg -0.001 is negative",
            ),
        ];
        for (i, (spoil, why)) in spoils.into_iter().enumerate() {
            let mut r = record(RecordKind::Session, "KR6-0102", 1 + i as u32, 128);
            r.harmonics = harmonics();
            spoil(&mut r.harmonics);
            match h.insert(&r) {
                Err(HistoryError::InvalidRecord(m)) => assert!(m.contains(why), "{}: {m}", b.name),
                other => panic!("{}: {why}: {other:?}", b.name),
            }
        }
        assert!(h.list(Some("KR6-0102")).unwrap().is_empty(), "{}", b.name);
    }
}

#[test]
fn schema_6_records_get_their_harmonics_from_their_results_reducers() {
    for b in backends("harmonics_v6") {
        drop(History::open_at_schema(&b.at, 5).unwrap());
        let mut with = record(RecordKind::Session, "KR6-0103", 1, 128);
        with.result_json =
            serde_json::json!({ "verdict": "PASS", "reducers": harmonics() }).to_string();
        let with_id = insert_at_schema_5(&b.at, &with, &old_import_brackets(&with));
        // Recorded before the reducers were kept: none.
        let without = record(RecordKind::Session, "KR6-0103", 2, 128);
        let without_id = insert_at_schema_5(&b.at, &without, &old_import_brackets(&without));

        let mut h = History::open(&b.at).unwrap();
        assert_eq!(h.schema_version().unwrap(), SCHEMA_VERSION, "{}", b.name);
        assert_eq!(
            h.get(with_id).unwrap().new.harmonics,
            harmonics(),
            "{}",
            b.name
        );
        assert!(
            h.get(without_id).unwrap().new.harmonics.is_empty(),
            "{}",
            b.name
        );
    }
}

/// A session whose `reducers` do not read (a hand-edited database, a NaN written as
/// `null`) migrates with no harmonics, its result as it was: the history stays open to
/// every tool, and the session beside it gets its harmonics.
#[test]
fn reducers_that_do_not_read_migrate_as_none_and_keep_the_history_open() {
    for b in backends("harmonics_unreadable") {
        drop(History::open_at_schema(&b.at, 6).unwrap());
        let mut bad = record(RecordKind::Session, "KR6-0104", 1, 128);
        bad.result_json = r#"{"verdict":"PASS","reducers":[{"joint":3,"order":"two"}]}"#.into();
        let bad_id = insert_at_schema_5(&b.at, &bad, &bad.brackets.to_json());
        let mut good = record(RecordKind::Session, "KR6-0104", 2, 128);
        good.result_json =
            serde_json::json!({ "verdict": "PASS", "reducers": harmonics() }).to_string();
        let good_id = insert_at_schema_5(&b.at, &good, &good.brackets.to_json());
        let mut h = History::open(&b.at).unwrap_or_else(|e| panic!("{}: {e}", b.name));
        assert_eq!(h.schema_version().unwrap(), SCHEMA_VERSION, "{}", b.name);
        let kept = h.get(bad_id).unwrap();
        assert!(kept.new.harmonics.is_empty(), "{}", b.name);
        assert_eq!(kept.new.result_json, bad.result_json, "{}", b.name);
        assert_eq!(
            h.get(good_id).unwrap().new.harmonics,
            harmonics(),
            "{}",
            b.name
        );
    }
}
