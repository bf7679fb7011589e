//! A record's brackets in one typed shape (schema 6): records stored by a schema-5
//! build in either old shape (a session's array of mounts, an import's IDs by mount)
//! read back as `RecordBrackets` after the migration, on every backend; a row in no
//! shape zerocal wrote stops the migration, naming the record; a record whose brackets
//! do not hold is refused on insert, naming the field.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, insert_at_schema_5, record};
use zerocal_history::schema::SCHEMA_VERSION;
use zerocal_history::{
    History, HistoryError, RecordBracket, RecordBracketCalibration, RecordBracketYaw,
    RecordBrackets, RecordKind,
};

/// A session's brackets as schema-5 builds stored them: the upper arm's calibrated
/// without a yaw, the flange's with one.
const OLD_SESSION: &str = r#"[{"mount":"upper_arm","id":"U-3","calibrated_on":20261120,"rotation_deg":[0.125,-0.5],"standard_uncertainty_deg":0.002,"temperature_c":21.5,"yaw_deg":null,"yaw_standard_uncertainty_deg":null},{"mount":"flange","id":"F-017","calibrated_on":20261121,"rotation_deg":[-0.25,0.75],"standard_uncertainty_deg":0.003,"temperature_c":22.0,"yaw_deg":1.5,"yaw_standard_uncertainty_deg":0.01}]"#;

/// What [`OLD_SESSION`] holds, typed.
fn session_brackets() -> RecordBrackets {
    RecordBrackets {
        upper_arm: Some(RecordBracket {
            id: "U-3".into(),
            calibration: Some(RecordBracketCalibration {
                calibrated_on: Some(20_261_120),
                rotation_deg: [0.125, -0.5],
                standard_uncertainty_deg: 0.002,
                temperature_c: Some(21.5),
                yaw: None,
            }),
        }),
        flange: Some(RecordBracket {
            id: "F-017".into(),
            calibration: Some(RecordBracketCalibration {
                calibrated_on: Some(20_261_121),
                rotation_deg: [-0.25, 0.75],
                standard_uncertainty_deg: 0.003,
                temperature_c: Some(22.0),
                yaw: Some(RecordBracketYaw {
                    yaw_deg: 1.5,
                    standard_uncertainty_deg: 0.01,
                }),
            }),
        }),
    }
}

fn id_only(id: &str) -> Option<RecordBracket> {
    Some(RecordBracket {
        id: id.into(),
        calibration: None,
    })
}

#[test]
fn schema_5_brackets_of_either_shape_are_rewritten_into_the_typed_one() {
    for b in backends("brackets_v5") {
        drop(History::open_at_schema(&b.at, 5).unwrap());
        // Each old shape, with what it must read as after the migration.
        let cases = [
            (OLD_SESSION, session_brackets()),
            (
                r#"[{"mount":"upper_arm","calibrated":false},{"mount":"flange","calibrated":false}]"#,
                RecordBrackets::default(),
            ),
            ("[]", RecordBrackets::default()),
            (
                r#"{"upper_arm":"U-3","flange":"B-12"}"#,
                RecordBrackets {
                    upper_arm: id_only("U-3"),
                    flange: id_only("B-12"),
                },
            ),
            (
                r#"{"upper_arm":null,"flange":"B-12"}"#,
                RecordBrackets {
                    upper_arm: None,
                    flange: id_only("B-12"),
                },
            ),
            ("{}", RecordBrackets::default()),
        ];
        let stored: Vec<_> = cases
            .iter()
            .enumerate()
            .map(|(i, (old, want))| {
                let mut r = record(RecordKind::Session, "KR6-0006", i as u32, 256);
                r.brackets = want.clone();
                (insert_at_schema_5(&b.at, &r, old), r)
            })
            .collect();

        let mut h = History::open(&b.at).unwrap();
        assert_eq!(h.schema_version().unwrap(), SCHEMA_VERSION, "{}", b.name);
        for ((id, r), (old, _)) in stored.iter().zip(&cases) {
            assert_eq!(&h.get(*id).unwrap().new, r, "{}: {old}", b.name);
        }
        // Stored in the new shape: a record of it inserted now reads the same.
        let mut again = record(RecordKind::Session, "KR6-0006", 99, 256);
        again.brackets = session_brackets();
        let id = h.insert(&again).unwrap().id;
        assert_eq!(h.get(id).unwrap().new, again, "{}", b.name);
    }
}

#[test]
fn a_row_in_no_shape_stops_the_migration_naming_it_and_the_database_stays_at_5() {
    for b in backends("brackets_bad_row") {
        drop(History::open_at_schema(&b.at, 5).unwrap());
        let good = insert_at_schema_5(
            &b.at,
            &record(RecordKind::Session, "KR6-0007", 1, 256),
            "{}",
        );
        let bad = insert_at_schema_5(
            &b.at,
            &record(RecordKind::Session, "KR6-0007", 2, 256),
            r#"{"wrist":"W-1"}"#,
        );
        match History::open(&b.at) {
            Err(HistoryError::Corrupt(why)) => {
                assert!(why.contains(&format!("record {bad}")), "{}: {why}", b.name);
                assert!(why.contains("\"wrist\""), "{}: {why}", b.name);
            }
            Err(e) => panic!("{}: {e}", b.name),
            Ok(_) => panic!("{}: a bracket mount \"wrist\" was migrated", b.name),
        }
        let mut h = History::open_at_schema(&b.at, 5).unwrap();
        assert_eq!(h.schema_version().unwrap(), 5, "{}", b.name);
        assert!(good < bad, "{}", b.name);
    }
}

#[test]
fn brackets_that_do_not_hold_are_refused_on_insert_naming_the_field() {
    for b in backends("brackets_refused") {
        let mut h = History::open(&b.at).unwrap();
        let mut r = record(RecordKind::Session, "KR6-0008", 1, 256);
        r.brackets = session_brackets();
        type Spoil = fn(&mut RecordBracketCalibration);
        let spoils: [(Spoil, &str); 3] = [
            (
                |c| c.temperature_c = Some(f64::INFINITY),
                "flange: temperature_c is inf",
            ),
            (
                |c| c.standard_uncertainty_deg = -0.001,
                "flange: standard_uncertainty_deg -0.001 is negative",
            ),
            (
                |c| c.calibrated_on = Some(20_261_131),
                "flange: calibrated_on 20261131",
            ),
        ];
        for (spoil, says) in spoils {
            let mut bad = r.clone();
            if let Some(c) = bad
                .brackets
                .flange
                .as_mut()
                .and_then(|f| f.calibration.as_mut())
            {
                spoil(c);
            }
            match h.insert(&bad) {
                Err(HistoryError::InvalidRecord(why)) => {
                    assert!(why.contains(says), "{}: {why}", b.name);
                }
                other => panic!("{}: {says}: {other:?}", b.name),
            }
        }
        let mut no_id = r.clone();
        no_id.brackets.upper_arm = id_only("");
        assert!(
            matches!(h.insert(&no_id), Err(HistoryError::InvalidRecord(why)) if why.contains("upper_arm: bracket ID")),
            "{}",
            b.name
        );
        assert!(h.list(Some("KR6-0008")).unwrap().is_empty(), "{}", b.name);
        let id = h.insert(&r).unwrap().id;
        assert_eq!(
            h.get(id).unwrap().new.brackets,
            session_brackets(),
            "{}",
            b.name
        );
    }
}
