//! A correction from the web: a new record naming the one it replaces and why, by the
//! signed-in technician, audited; the replaced record stays and says so; a correction
//! without a reason, of another serial's record or of one already replaced is refused
//! and nothing is recorded. On SQLite, and on PostgreSQL when `ZEROCAL_TEST_POSTGRES`
//! is set.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use axum::http::{header, StatusCode};
use common::*;

#[tokio::test]
async fn a_correction_is_a_new_record_naming_the_one_it_replaces() {
    for site in sites("web_corrections") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &csrf, "R1", b"robot kuka-kr16\nfirst\n")
                .await
                .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            upload(r, &tec, &csrf, "R2", b"robot kuka-kr16\nother\n")
                .await
                .status,
            StatusCode::SEE_OTHER
        );
        let before = state(&site.at);
        let fixed = b"robot kuka-kr16\nsecond\n";
        for (replaces, reason, why) in [
            ("1", "", "reason"),
            ("2", "typo", "serial"),
            ("x1", "typo", "record number"),
            ("99", "typo", "does not exist"),
        ] {
            let fields = [
                ("csrf", csrf.as_str()),
                ("serial", "R1"),
                ("replaces", replaces),
                ("reason", reason),
            ];
            let reply = upload_with(r, &tec, &fields, fixed).await;
            assert_eq!(
                reply.status,
                StatusCode::UNPROCESSABLE_ENTITY,
                "{} {why}: {}",
                site.name,
                reply.body
            );
            assert!(reply.body.contains(why), "{why}: {}", reply.body);
        }
        assert_eq!(state(&site.at), before, "{}", site.name);
        let fields = [
            ("csrf", csrf.as_str()),
            ("serial", "R1"),
            ("replaces", "1"),
            ("reason", "the <b>wrong</b> bracket"),
        ];
        let reply = upload_with(r, &tec, &fields, fixed).await;
        assert_eq!(reply.status, StatusCode::SEE_OTHER, "{}", reply.body);
        assert_eq!(reply.headers.get(header::LOCATION).unwrap(), "/record/3");
        // Once only.
        let fields = [
            ("csrf", csrf.as_str()),
            ("serial", "R1"),
            ("replaces", "1"),
            ("reason", "again"),
        ];
        let reply = upload_with(r, &tec, &fields, b"robot kuka-kr16\nthird\n").await;
        assert!(
            reply.body.contains("already replaced by record 3"),
            "{}",
            reply.body
        );
        let page = get(r, "/robot/R1", &tec).await.body;
        assert!(
            page.contains("replaced by record 3: the &lt;b&gt;wrong&lt;"),
            "{page}"
        );
        assert!(page.contains("replaces record 1"), "{page}");
        let log = with_history(&site.at, |h| h.audit_log(1).unwrap());
        assert_eq!(
            (
                log[0].actor.as_str(),
                log[0].action.as_str(),
                log[0].subject.as_str()
            ),
            ("tec", "record.correct", "record 1")
        );
        assert_eq!(
            log[0].before_json.as_deref(),
            Some(r#"{"id":1,"replaced_by":null}"#)
        );
        // The fleet shows the correction, not the record it replaced.
        let fleet = with_history(&site.at, |h| h.fleet().unwrap());
        assert_eq!(
            fleet[0].last_session.as_ref().map(|s| s.id),
            Some(3),
            "{}",
            site.name
        );
        assert_eq!(fleet[0].sessions, 1);
    }
}
