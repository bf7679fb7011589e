//! The web application's state in the history (schema 5): accounts, signatures in
//! order and by role, sessions, the login attempts the flood limit counts, and the
//! audit entry written with every change; on SQLite and PostgreSQL.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, record};
use zerocal_history::{History, HistoryError, LoginGate, RecordKind, Role, SignStep};

#[test]
fn a_session_is_checked_then_authorized_by_two_people_each_with_the_role() {
    for b in backends("review_steps") {
        let mut h = History::open(&b.at).unwrap();
        for (name, role) in [
            ("tec", Role::Technician),
            ("rev", Role::Reviewer),
            ("rev2", Role::Reviewer),
            ("aut", Role::Authorizer),
        ] {
            h.add_user("setup", name, role, "$argon2id$fake").unwrap();
        }
        let id = h
            .insert_audited("tec", &record(RecordKind::Session, "R1", 1, 64))
            .unwrap()
            .id;
        let check = h
            .insert(&record(RecordKind::Check, "R1", 2, 64))
            .unwrap()
            .id;
        let refused = |r: Result<_, HistoryError>| matches!(r, Err(HistoryError::Refused(_)));
        // Authorizing first, signing with another role's step, or a check: refused.
        assert!(
            refused(h.sign("aut", id, SignStep::Authorized)),
            "{}",
            b.name
        );
        assert!(refused(h.sign("tec", id, SignStep::Checked)), "{}", b.name);
        assert!(refused(h.sign("aut", id, SignStep::Checked)), "{}", b.name);
        assert!(
            refused(h.sign("rev", check, SignStep::Checked)),
            "{}",
            b.name
        );
        assert!(
            refused(h.sign("nobody", id, SignStep::Checked)),
            "{}",
            b.name
        );
        assert!(h.signatures(id).unwrap().is_empty());
        h.sign("rev", id, SignStep::Checked).unwrap();
        assert!(refused(h.sign("rev2", id, SignStep::Checked)), "once only");
        h.sign("aut", id, SignStep::Authorized).unwrap();
        let s = h.signatures(id).unwrap();
        assert_eq!(
            s.iter()
                .map(|s| (s.step, s.user_name.as_str()))
                .collect::<Vec<_>>(),
            [(SignStep::Checked, "rev"), (SignStep::Authorized, "aut")],
            "{}",
            b.name
        );
        // Every accepted change has its entry: four users, one record, two signatures
        // (the check inserted without an actor is not audited, as `insert` is the CLI's).
        let log = h.audit_log(100).unwrap();
        let actions: Vec<(&str, &str, &str)> = log
            .iter()
            .rev()
            .map(|e| (e.actor.as_str(), e.action.as_str(), e.subject.as_str()))
            .collect();
        let subject = format!("record {id}");
        assert_eq!(
            actions,
            [
                ("setup", "user.add", "user tec"),
                ("setup", "user.add", "user rev"),
                ("setup", "user.add", "user rev2"),
                ("setup", "user.add", "user aut"),
                ("tec", "record.insert", subject.as_str()),
                ("rev", "record.sign", subject.as_str()),
                ("aut", "record.sign", subject.as_str()),
            ],
            "{}",
            b.name
        );
        let last = &log[0];
        assert!(last.before_json.as_deref().unwrap().contains("\"checked\""));
        assert!(last.after_json.contains("\"authorized\""));
    }
}

#[test]
fn one_person_does_not_check_and_authorize() {
    for b in backends("review_four_eyes") {
        let mut h = History::open(&b.at).unwrap();
        h.add_user("setup", "both", Role::Reviewer, "x").unwrap();
        let id = h
            .insert(&record(RecordKind::Session, "R1", 1, 64))
            .unwrap()
            .id;
        h.sign("both", id, SignStep::Checked).unwrap();
        h.set_user("setup", "both", Role::Authorizer, true).unwrap();
        let r = h.sign("both", id, SignStep::Authorized);
        assert!(
            matches!(&r, Err(HistoryError::Refused(m)) if m.contains("another person")),
            "{r:?}"
        );
    }
}

/// Whoever measured a session (its operator) neither checks nor authorizes it, and a
/// refused signature leaves none behind.
#[test]
fn the_operator_does_not_check_or_authorize_the_measurement() {
    for b in backends("review_operator") {
        let mut h = History::open(&b.at).unwrap();
        let mut r = record(RecordKind::Session, "R1", 1, 64);
        r.operator = Some("ops".into());
        let id = h.insert(&r).unwrap().id;
        h.add_user("setup", "ops", Role::Reviewer, "x").unwrap();
        h.add_user("setup", "rev", Role::Reviewer, "x").unwrap();
        let refused = h.sign("ops", id, SignStep::Checked);
        assert!(
            matches!(&refused, Err(HistoryError::Refused(m)) if m.contains("ops measured")),
            "{refused:?}"
        );
        assert!(h.signatures(id).unwrap().is_empty());
        h.sign("rev", id, SignStep::Checked).unwrap();
        h.set_user("setup", "ops", Role::Authorizer, true).unwrap();
        let refused = h.sign("ops", id, SignStep::Authorized);
        assert!(
            matches!(&refused, Err(HistoryError::Refused(m)) if m.contains("another person authorizes")),
            "{refused:?}"
        );
    }
}

/// The last active admin can neither be disabled nor lose the role (nobody could manage
/// the users after); with a second admin, either can.
#[test]
fn the_last_active_admin_stays_one() {
    for b in backends("review_last_admin") {
        let mut h = History::open(&b.at).unwrap();
        h.add_user("setup", "adm", Role::Admin, "x").unwrap();
        for (role, active) in [(Role::Admin, false), (Role::Reviewer, true)] {
            let r = h.set_user("adm", "adm", role, active);
            assert!(
                matches!(&r, Err(HistoryError::Refused(m)) if m.contains("last active admin")),
                "{r:?}"
            );
        }
        assert!(h
            .user("adm")
            .unwrap()
            .is_some_and(|u| u.active && u.role == Role::Admin));
        h.add_user("adm", "adm2", Role::Admin, "x").unwrap();
        h.set_user("adm2", "adm", Role::Reviewer, true).unwrap();
    }
}

/// Failed sign-ins started in parallel each count: the gate refuses once the limit is
/// reached, and a marked success resets the count.
#[test]
fn a_login_attempt_is_counted_before_its_password_is_checked() {
    for b in backends("review_login_gate") {
        let mut h = History::open(&b.at).unwrap();
        for t in 0..3 {
            assert!(matches!(
                h.begin_login_attempt("ana", t, 0, 3).unwrap(),
                LoginGate::Attempt(_)
            ));
        }
        assert_eq!(
            h.begin_login_attempt("ana", 4, 0, 3).unwrap(),
            LoginGate::Refused { failures: 3 }
        );
        let LoginGate::Attempt(id) = h.begin_login_attempt("ana", 5, 0, 4).unwrap() else {
            panic!("refused under a limit of 4");
        };
        h.mark_login_succeeded(id).unwrap();
        assert_eq!(h.login_failures_since("ana", 0).unwrap(), 0);
    }
}

#[test]
fn a_session_expires_and_ends_and_a_disabled_user_has_none() {
    for b in backends("review_sessions") {
        let mut h = History::open(&b.at).unwrap();
        h.add_user("setup", "ana", Role::Technician, "x").unwrap();
        h.start_web_session("hash1", "ana", "csrf1", 1000).unwrap();
        let s = h.web_session("hash1", 999).unwrap().unwrap();
        assert_eq!(
            (s.user.name.as_str(), s.csrf_token.as_str()),
            ("ana", "csrf1")
        );
        assert!(h.web_session("hash1", 1000).unwrap().is_none(), "expired");
        assert!(h.web_session("other", 999).unwrap().is_none());
        h.end_web_session("hash1", 0).unwrap();
        assert!(h.web_session("hash1", 999).unwrap().is_none(), "ended");
        h.start_web_session("hash2", "ana", "csrf2", 1000).unwrap();
        h.set_user("setup", "ana", Role::Technician, false).unwrap();
        assert!(h.web_session("hash2", 999).unwrap().is_none(), "disabled");
        assert!(matches!(
            h.add_user("setup", "ana", Role::Admin, "x"),
            Err(HistoryError::Refused(_))
        ));
        assert!(matches!(
            h.add_user("setup", " ana", Role::Admin, "x"),
            Err(HistoryError::Refused(_))
        ));
    }
}

#[test]
fn failed_logins_are_counted_since_the_last_success() {
    for b in backends("review_logins") {
        let mut h = History::open(&b.at).unwrap();
        for t in [10, 11, 12] {
            h.record_login_attempt("ana", t, false).unwrap();
        }
        assert_eq!(h.login_failures_since("ana", 0).unwrap(), 3);
        assert_eq!(h.login_failures_since("ana", 11).unwrap(), 2);
        assert_eq!(h.login_failures_since("bob", 0).unwrap(), 0);
        h.record_login_attempt("ana", 13, true).unwrap();
        h.record_login_attempt("ana", 14, false).unwrap();
        assert_eq!(h.login_failures_since("ana", 0).unwrap(), 1);
    }
}

#[test]
fn a_correction_is_a_new_record_naming_the_one_it_replaces_and_the_fleet_leaves_that_out() {
    for b in backends("review_corrections") {
        let mut h = History::open(&b.at).unwrap();
        let mut first = record(RecordKind::Session, "R1", 1, 64);
        first.measured_on = "2026-01-01".into();
        let wrong = h.insert_audited("tec", &first).unwrap().id;
        let other = h
            .insert(&record(RecordKind::Session, "R2", 1, 64))
            .unwrap()
            .id;
        let mut fixed = record(RecordKind::Session, "R1", 2, 64);
        fixed.measured_on = "2026-01-01".into();
        let refused = |r: Result<_, HistoryError>| matches!(r, Err(HistoryError::Refused(_)));
        // No reason; another serial's record; a record that does not exist; the same
        // export again (no new record): refused, nothing written.
        assert!(
            refused(h.insert_correction("tec", &fixed, wrong, "  ")),
            "{}",
            b.name
        );
        assert!(
            refused(h.insert_correction("tec", &fixed, other, "typo")),
            "{}",
            b.name
        );
        assert!(
            refused(h.insert_correction("tec", &fixed, 999, "typo")),
            "{}",
            b.name
        );
        assert!(
            refused(h.insert_correction("tec", &first, wrong, "typo")),
            "{}",
            b.name
        );
        assert_eq!(h.list(Some("R1")).unwrap().len(), 1, "{}", b.name);
        let id = h
            .insert_correction("tec", &fixed, wrong, "wrong serial typed on the pendant")
            .unwrap()
            .id;
        // Once only; the replaced record is still there, unchanged.
        let mut again = record(RecordKind::Session, "R1", 3, 64);
        again.measured_on = "2026-01-01".into();
        assert!(refused(h.insert_correction("tec", &again, wrong, "again")));
        assert_eq!(h.get(wrong).unwrap().new, first);
        let c = h.corrections("R1").unwrap();
        assert_eq!(
            c.iter()
                .map(|c| (c.record_id, c.replaces_id, c.user_name.as_str()))
                .collect::<Vec<_>>(),
            [(id, wrong, "tec")]
        );
        let fleet = h.fleet().unwrap();
        let r1 = fleet.iter().find(|r| r.serial == "R1").unwrap();
        assert_eq!(
            (r1.sessions, r1.last_session.as_ref().unwrap().id),
            (1, id),
            "{}",
            b.name
        );
        let log = h.audit_log(1).unwrap();
        assert_eq!(
            (log[0].action.as_str(), log[0].subject.clone()),
            ("record.correct", format!("record {wrong}"))
        );
        assert!(log[0].after_json.contains("wrong serial typed"));
    }
}
