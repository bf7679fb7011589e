//! Schema 3 on both backends: the entry conventions a check measured, read back per
//! serial in recording order, each check's once, refused when they do not name a check
//! of that serial; the certificates issued, the same session, as-left check and issuer
//! giving the same number and date again, a number never given twice, an as-left that
//! is not a check of the session refused; and a schema-2 database migrated with its
//! records kept.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with store.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use common::{backends, record};
use zerocal_history::schema::SCHEMA_VERSION;
use zerocal_history::{
    CertificateRequest, History, HistoryError, NewCertificate, NewConvention, RecordKind,
};

#[test]
fn conventions_are_kept_per_serial_once_per_check_and_only_from_a_check() {
    for b in backends("conventions") {
        let mut h = History::open(&b.at).unwrap();
        let mut session = record(RecordKind::Session, "UR-1", 1, 256);
        session.robot = "ur5e".into();
        let s = h.insert(&session).unwrap().id;
        let mut c = record(RecordKind::Check, "UR-1", 2, 256);
        c.reference_id = Some(s);
        let check = h.insert(&c).unwrap().id;
        let found: Vec<NewConvention> = (2..=6)
            .map(|joint| NewConvention {
                serial: "UR-1".into(),
                joint,
                factor: -1.0,
                check_id: check,
                verified: false,
            })
            .collect();
        assert_eq!(h.record_conventions(&found).unwrap(), 5, "{}", b.name);
        assert_eq!(h.record_conventions(&found).unwrap(), 0, "{}: once", b.name);
        let back = h.conventions("UR-1").unwrap();
        assert_eq!(
            back.iter().map(|c| c.new.clone()).collect::<Vec<_>>(),
            found,
            "{}",
            b.name
        );
        assert!(h.conventions("UR-2").unwrap().is_empty(), "{}", b.name);
        // Not a check, or another serial's, or a factor that is no scale: refused.
        for bad in [
            NewConvention {
                check_id: s,
                ..found[0].clone()
            },
            NewConvention {
                serial: "UR-2".into(),
                ..found[0].clone()
            },
            NewConvention {
                factor: 0.0,
                ..found[0].clone()
            },
            NewConvention {
                factor: f64::NAN,
                ..found[0].clone()
            },
            NewConvention {
                joint: 1,
                ..found[0].clone()
            },
        ] {
            assert!(
                matches!(
                    h.record_conventions(std::slice::from_ref(&bad)),
                    Err(HistoryError::InvalidRecord(_))
                ),
                "{}: {bad:?}",
                b.name
            );
        }
        assert_eq!(h.conventions("UR-1").unwrap().len(), 5, "{}", b.name);
    }
}

#[test]
fn a_certificate_keeps_its_number_and_a_number_is_given_once() {
    for b in backends("certificates") {
        let mut h = History::open(&b.at).unwrap();
        let s = h
            .insert(&record(RecordKind::Session, "KR6-1", 1, 256))
            .unwrap()
            .id;
        let mut c = record(RecordKind::Check, "KR6-1", 2, 256);
        c.reference_id = Some(s);
        let left = h.insert(&c).unwrap().id;
        let new = NewCertificate {
            number: "ZC-0d4f6a57-8d53-4a3e-9f1b-2b8c9e0a7d11".into(),
            session_id: s,
            as_left_id: Some(left),
            issued_on: "2026-11-27".into(),
            issuer_json: "{\"laboratory\":\"Line 4\"}".into(),
        };
        let (issued, fresh) = h.issue_certificate(&new).unwrap();
        assert!(fresh, "{}", b.name);
        assert_eq!(issued.new, new, "{}", b.name);
        // The same again, on another day with another number drawn: the first kept.
        let again = NewCertificate {
            number: "ZC-another".into(),
            issued_on: "2026-12-01".into(),
            ..new.clone()
        };
        let (kept, fresh) = h.issue_certificate(&again).unwrap();
        assert!(!fresh, "{}", b.name);
        assert_eq!(kept.new, new, "{}", b.name);
        // Another issuer is another certificate; the number already given is refused.
        let other_issuer = NewCertificate {
            issuer_json: "{\"laboratory\":\"Line 5\"}".into(),
            ..new.clone()
        };
        assert!(
            matches!(
                h.issue_certificate(&other_issuer),
                Err(HistoryError::InvalidRecord(_))
            ),
            "{}",
            b.name
        );
        for bad in [
            NewCertificate {
                issued_on: "2026-02-31".into(),
                number: "ZC-x".into(),
                ..other_issuer.clone()
            },
            NewCertificate {
                as_left_id: Some(s),
                number: "ZC-y".into(),
                ..other_issuer.clone()
            },
            NewCertificate {
                session_id: left,
                as_left_id: None,
                number: "ZC-z".into(),
                ..other_issuer.clone()
            },
            NewCertificate {
                number: String::new(),
                ..other_issuer.clone()
            },
        ] {
            assert!(
                matches!(
                    h.issue_certificate(&bad),
                    Err(HistoryError::InvalidRecord(_))
                ),
                "{}: {bad:?}",
                b.name
            );
        }
        assert_eq!(h.certificates_of(s).unwrap().len(), 1, "{}", b.name);
        let checks = h.checks_against(s).unwrap();
        assert_eq!(checks.iter().map(|r| r.id).collect::<Vec<_>>(), vec![left]);
    }
}

/// A user who may not issue gets an issued certificate back but never a new one, even
/// where a new as-left check would make another; a first issue by one who may is in the
/// audit log once, as theirs.
#[test]
fn only_a_user_who_may_issue_gets_a_new_certificate_and_it_is_audited() {
    for b in backends("certificate_requests") {
        let mut h = History::open(&b.at).unwrap();
        let s = h
            .insert(&record(RecordKind::Session, "KR6-1", 1, 256))
            .unwrap()
            .id;
        let new = NewCertificate {
            number: "ZC-1".into(),
            session_id: s,
            as_left_id: None,
            issued_on: "2026-11-27".into(),
            issuer_json: "{\"laboratory\":\"Line 4\"}".into(),
        };
        let admin = CertificateRequest {
            name: "adm",
            may_issue: false,
        };
        let refused = h.issue_certificate_by(&new, Some(admin));
        assert!(
            matches!(&refused, Err(HistoryError::Refused(m)) if m.contains("adm may not issue")),
            "{}: {refused:?}",
            b.name
        );
        let tec = CertificateRequest {
            name: "tec",
            may_issue: true,
        };
        let (_, fresh) = h.issue_certificate_by(&new, Some(tec)).unwrap();
        assert!(fresh, "{}", b.name);
        let (kept, fresh) = h.issue_certificate_by(&new, Some(admin)).unwrap();
        assert!(!fresh && kept.new == new, "{}", b.name);
        // A check recorded since would be a new as-left: not the admin's to issue.
        let mut c = record(RecordKind::Check, "KR6-1", 2, 256);
        c.reference_id = Some(s);
        let left = h.insert(&c).unwrap().id;
        let with_left = NewCertificate {
            number: "ZC-2".into(),
            as_left_id: Some(left),
            ..new.clone()
        };
        assert!(
            matches!(
                h.issue_certificate_by(&with_left, Some(admin)),
                Err(HistoryError::Refused(_))
            ),
            "{}",
            b.name
        );
        let issued: Vec<String> = h
            .audit_log(100)
            .unwrap()
            .into_iter()
            .filter(|e| e.action == "certificate.issue")
            .map(|e| e.actor)
            .collect();
        assert_eq!(issued, ["tec"], "{}", b.name);
    }
}

#[test]
fn a_schema_2_database_is_migrated_keeping_its_records() {
    for b in backends("migrate_v2") {
        drop(History::open_at_schema(&b.at, 2).unwrap());
        let r = record(RecordKind::Session, "KR6-0002", 1, 512);
        let id = common::insert_before_schema_4(&b.at, &r);
        let mut h = History::open(&b.at).unwrap();
        assert_eq!(h.schema_version().unwrap(), SCHEMA_VERSION, "{}", b.name);
        assert_eq!(h.get(id).unwrap().new, r, "{}", b.name);
        assert!(h.conventions("KR6-0002").unwrap().is_empty(), "{}", b.name);
        assert!(h.certificates_of(id).unwrap().is_empty(), "{}", b.name);
    }
}
