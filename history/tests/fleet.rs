//! The plant's view (`History::fleet`): each robot's last session by the day measured,
//! the one before it, its last check, and each joint's drift between the two sessions
//! against their combined U; on SQLite and PostgreSQL.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, record};
use zerocal_history::{History, RecordKind};

#[test]
fn each_robot_shows_its_last_sessions_by_day_and_its_last_check() {
    for b in backends("fleet_view") {
        let mut h = History::open(&b.at).unwrap();
        // KR6-0001: three sessions stored out of their days' order, then a check.
        let mut days = Vec::new();
        for (i, day) in [(1, "2026-03-01"), (2, "2026-09-01"), (3, "2026-06-01")] {
            let mut r = record(RecordKind::Session, "KR6-0001", i, 256);
            r.measured_on = day.into();
            for j in &mut r.joints {
                j.offset_deg = f64::from(i) * 0.01 * f64::from(j.joint);
                j.expanded_k2_deg = 0.003;
            }
            days.push((h.insert(&r).unwrap().id, day));
        }
        let mut check = record(RecordKind::Check, "KR6-0001", 4, 256);
        check.measured_on = "2026-09-02".into();
        check.verdict = "FAIL A4".into();
        let check_id = h.insert(&check).unwrap().id;
        // KR6-0002: one session only.
        let only = h
            .insert(&record(RecordKind::Session, "KR6-0002", 1, 256))
            .unwrap()
            .id;

        let fleet = h.fleet().unwrap();
        assert_eq!(fleet.len(), 2, "{}", b.name);
        let a = &fleet[0];
        assert_eq!(
            (a.serial.as_str(), a.sessions, a.checks),
            ("KR6-0001", 3, 1),
            "{}",
            b.name
        );
        // The last by day is record 2 (September), the one before it record 3 (June).
        assert_eq!(
            a.last_session.as_ref().map(|s| s.id),
            Some(days[1].0),
            "{}",
            b.name
        );
        assert_eq!(
            a.previous_session.as_ref().map(|s| s.id),
            Some(days[2].0),
            "{}",
            b.name
        );
        let c = a.last_check.as_ref().unwrap();
        assert_eq!(
            (c.id, c.verdict.as_str()),
            (check_id, "FAIL A4"),
            "{}",
            b.name
        );
        // Drift: (2 - 3) * 0.01 * joint, against √2 · 0.003.
        let drift = a.drift();
        assert_eq!(drift.len(), 5, "{}", b.name);
        for d in drift {
            assert!(
                (d.change_deg + 0.01 * f64::from(d.joint)).abs() < 1e-12,
                "{d:?}"
            );
            assert!(
                (d.combined_k2_deg - 0.003 * 2f64.sqrt()).abs() < 1e-12,
                "{d:?}"
            );
        }
        let one = &fleet[1];
        assert_eq!(
            one.last_session.as_ref().map(|s| s.id),
            Some(only),
            "{}",
            b.name
        );
        assert!(
            one.previous_session.is_none() && one.drift().is_empty(),
            "{}",
            b.name
        );
        assert!(one.last_check.is_none(), "{}", b.name);
    }
}
