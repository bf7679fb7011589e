//! An upload's record is stored only if every record of its serial is of its robot
//! profile, checked in the insert's transaction: another robot's export is refused by
//! name with nothing stored, and two uploads of two robots racing under one new serial
//! store one robot's only. On SQLite and PostgreSQL.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, record};
use zerocal_history::{History, HistoryError, NewRecord, RecordKind};

/// `record`'s session `i` of `serial`, of the robot profile `robot`.
fn of_robot(serial: &str, i: u32, robot: &str) -> NewRecord {
    let mut r = record(RecordKind::Session, serial, i, 64);
    r.robot = robot.into();
    r
}

const KR6: &str = "kuka-kr6-r900-sixx";
const UR5E: &str = "ur5e";

#[test]
fn another_robots_export_under_a_serial_is_refused_by_name_and_nothing_stored() {
    for b in backends("upload_another_robot") {
        let mut h = History::open(&b.at).unwrap();
        let first = h
            .insert_of_one_robot("tec", &of_robot("R1", 1, KR6), None)
            .unwrap();
        assert!(first.new);
        // The same robot again, and a correction of it: stored.
        let second = h
            .insert_of_one_robot("tec", &of_robot("R1", 2, KR6), None)
            .unwrap();
        h.insert_of_one_robot("tec", &of_robot("R1", 3, KR6), Some((second.id, "typo")))
            .unwrap();
        let before = (h.list(None).unwrap().len(), h.audit_log(i64::MAX).unwrap());
        for correction in [None, Some((second.id, "typo"))] {
            let refused = h.insert_of_one_robot("tec", &of_robot("R1", 4, UR5E), correction);
            match &refused {
                Err(
                    e @ HistoryError::AnotherRobot {
                        serial,
                        stored,
                        record_id,
                        export,
                    },
                ) => {
                    assert_eq!(
                        (
                            serial.as_str(),
                            stored.as_str(),
                            *record_id,
                            export.as_str()
                        ),
                        ("R1", KR6, first.id, UR5E),
                        "{}",
                        b.name
                    );
                    assert!(e.to_string().contains("another robot's export"), "{e}");
                }
                other => panic!("{}: {other:?}", b.name),
            }
        }
        assert_eq!(
            (h.list(None).unwrap().len(), h.audit_log(i64::MAX).unwrap()),
            before,
            "{}",
            b.name
        );
        // Another serial is another robot.
        h.insert_of_one_robot("tec", &of_robot("R2", 1, UR5E), None)
            .unwrap();
    }
}

#[test]
fn two_robots_uploads_racing_under_one_new_serial_store_one_robots_only() {
    for b in backends("upload_race") {
        for round in 0..8_u32 {
            let serial = format!("RACE{round}");
            let barrier = std::sync::Barrier::new(2);
            let outcomes: Vec<_> = std::thread::scope(|s| {
                let runs: Vec<_> = [KR6, UR5E]
                    .into_iter()
                    .map(|robot| {
                        let (at, serial, barrier) = (&b.at, &serial, &barrier);
                        s.spawn(move || {
                            let mut h = History::open(at).unwrap();
                            barrier.wait();
                            h.insert_of_one_robot("tec", &of_robot(serial, round, robot), None)
                        })
                    })
                    .collect();
                runs.into_iter().map(|r| r.join().unwrap()).collect()
            });
            let stored = outcomes.iter().filter(|o| o.is_ok()).count();
            let refused = outcomes
                .iter()
                .filter(|o| matches!(o, Err(HistoryError::AnotherRobot { .. })))
                .count();
            assert_eq!((stored, refused), (1, 1), "{} {outcomes:?}", b.name);
            let mut h = History::open(&b.at).unwrap();
            let robots: std::collections::BTreeSet<_> = h
                .list(Some(&serial))
                .unwrap()
                .into_iter()
                .map(|r| r.new.robot)
                .collect();
            assert_eq!(robots.len(), 1, "{} {robots:?}", b.name);
        }
    }
}
