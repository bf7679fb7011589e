//! The web application refuses what it must and changes nothing when it does: a
//! request without a session, another role's action, a form without its CSRF token,
//! markup and SQL in fields, an oversized, malformed or another robot's export, and a
//! flood of sign-ins; and every change it accepts is in the audit log with who, when,
//! what, before and after. On SQLite, and on PostgreSQL when `ZEROCAL_TEST_POSTGRES`
//! is set.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use axum::http::{header, StatusCode};
use common::*;
use zerocal_web::{LOGIN_WINDOW_SECONDS, MAX_FAILED_LOGINS};

const EXPORT: &[u8] = b"robot kuka-kr6-r900-sixx\nrow 1\n";

#[tokio::test]
async fn without_a_session_pages_send_to_sign_in_and_actions_are_refused_unchanged() {
    for site in sites("no_session") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &csrf, "R1", EXPORT).await.status,
            StatusCode::SEE_OTHER
        );
        let before = state(&site.at);
        for page in [
            "/fleet",
            "/robot/R1",
            "/record/1",
            "/upload",
            "/audit",
            "/admin/users",
            "/record/1/certificate",
        ] {
            let reply = get(r, page, "").await;
            assert_eq!(reply.status, StatusCode::SEE_OTHER, "{} {page}", site.name);
            assert_eq!(reply.headers.get(header::LOCATION).unwrap(), "/login");
        }
        // A made-up session ID is no session.
        let forged = format!("zerocal_session={}", "0".repeat(64));
        assert_eq!(
            get(r, "/fleet", &forged).await.status,
            StatusCode::SEE_OTHER
        );
        for (path, fields) in [
            (
                "/record/1/sign",
                vec![("csrf", csrf.as_str()), ("step", "checked")],
            ),
            (
                "/admin/users",
                vec![
                    ("csrf", csrf.as_str()),
                    ("name", "eve"),
                    ("role", "admin"),
                    ("password", "x"),
                ],
            ),
            (
                "/admin/users/tec",
                vec![("csrf", csrf.as_str()), ("role", "admin"), ("active", "1")],
            ),
            ("/record/1/certificate", vec![("csrf", csrf.as_str())]),
            ("/logout", vec![("csrf", csrf.as_str())]),
        ] {
            for cookie in ["", forged.as_str()] {
                let reply = post(r, path, cookie, &fields).await;
                assert_eq!(
                    reply.status,
                    StatusCode::UNAUTHORIZED,
                    "{} {path}",
                    site.name
                );
            }
        }
        assert_eq!(
            upload(r, "", &csrf, "R2", EXPORT).await.status,
            StatusCode::UNAUTHORIZED
        );
        assert_eq!(state(&site.at), before, "{}", site.name);
    }
}

#[tokio::test]
async fn another_roles_action_is_forbidden_and_changes_nothing() {
    for site in sites("wrong_role") {
        let r = &site.router;
        let (tec, tec_csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &tec_csrf, "R1", EXPORT).await.status,
            StatusCode::SEE_OTHER
        );
        let before = state(&site.at);
        let (rev, rev_csrf) = sign_in(r, "rev").await;
        let (aut, aut_csrf) = sign_in(r, "aut").await;
        let (adm, adm_csrf) = sign_in(r, "adm").await;
        // Technician: records, signs nothing, manages nobody.
        for step in ["checked", "authorized"] {
            let reply = post(
                r,
                "/record/1/sign",
                &tec,
                &[("csrf", &tec_csrf), ("step", step)],
            )
            .await;
            assert_eq!(
                reply.status,
                StatusCode::FORBIDDEN,
                "{} tec {step}",
                site.name
            );
        }
        for (cookie, csrf) in [(&tec, &tec_csrf), (&rev, &rev_csrf), (&aut, &aut_csrf)] {
            let reply = post(
                r,
                "/admin/users",
                cookie,
                &[
                    ("csrf", csrf),
                    ("name", "eve"),
                    ("role", "admin"),
                    ("password", "pw"),
                ],
            )
            .await;
            assert_eq!(reply.status, StatusCode::FORBIDDEN, "{}", site.name);
            let reply = post(
                r,
                "/admin/users/tec",
                cookie,
                &[("csrf", csrf), ("role", "admin"), ("active", "1")],
            )
            .await;
            assert_eq!(reply.status, StatusCode::FORBIDDEN, "{}", site.name);
            assert_eq!(
                get(r, "/admin/users", cookie).await.status,
                StatusCode::FORBIDDEN
            );
        }
        // Reviewer does not authorize; authorizer does not check; admin signs nothing;
        // only a technician records.
        assert_eq!(
            post(
                r,
                "/record/1/sign",
                &rev,
                &[("csrf", &rev_csrf), ("step", "authorized")]
            )
            .await
            .status,
            StatusCode::FORBIDDEN
        );
        assert_eq!(
            post(
                r,
                "/record/1/sign",
                &aut,
                &[("csrf", &aut_csrf), ("step", "checked")]
            )
            .await
            .status,
            StatusCode::FORBIDDEN
        );
        assert_eq!(
            post(
                r,
                "/record/1/sign",
                &adm,
                &[("csrf", &adm_csrf), ("step", "checked")]
            )
            .await
            .status,
            StatusCode::FORBIDDEN
        );
        for (cookie, csrf) in [(&rev, &rev_csrf), (&aut, &aut_csrf), (&adm, &adm_csrf)] {
            assert_eq!(
                upload(r, cookie, csrf, "R9", EXPORT).await.status,
                StatusCode::FORBIDDEN
            );
        }
        assert_eq!(state(&site.at), before, "{}", site.name);
    }
}

#[tokio::test]
async fn a_form_without_its_sessions_csrf_token_is_forbidden() {
    for site in sites("csrf") {
        let r = &site.router;
        let (tec, tec_csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &tec_csrf, "R1", EXPORT).await.status,
            StatusCode::SEE_OTHER
        );
        let before = state(&site.at);
        let (rev, rev_csrf) = sign_in(r, "rev").await;
        let wrong = "f".repeat(64);
        // Missing, wrong, and another session's own (valid) token.
        for fields in [
            vec![("step", "checked")],
            vec![("csrf", wrong.as_str()), ("step", "checked")],
            vec![("csrf", tec_csrf.as_str()), ("step", "checked")],
        ] {
            let reply = post(r, "/record/1/sign", &rev, &fields).await;
            assert_eq!(
                reply.status,
                StatusCode::FORBIDDEN,
                "{} {fields:?}",
                site.name
            );
            assert!(reply.body.contains("CSRF"), "{}", reply.body);
        }
        for csrf in ["", wrong.as_str(), rev_csrf.as_str()] {
            assert_eq!(
                upload(r, &tec, csrf, "R2", EXPORT).await.status,
                StatusCode::FORBIDDEN
            );
        }
        assert_eq!(
            post(r, "/logout", &rev, &[("csrf", &tec_csrf)])
                .await
                .status,
            StatusCode::FORBIDDEN
        );
        assert_eq!(state(&site.at), before, "{}", site.name);
    }
}

/// A serial holding `/`, `?`, `#` or a space links to its own robot page (each link's
/// segment percent-encoded whole; minijinja's urlencode keeps `/`, which made such a
/// link a path no route has).
#[tokio::test]
async fn a_serial_with_a_slash_links_to_its_own_page() {
    for site in sites("serial_slash") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        let serial = "KR 6/2 ?#1";
        let reply = upload(r, &tec, &csrf, serial, EXPORT).await;
        assert_eq!(
            reply.status,
            StatusCode::SEE_OTHER,
            "{}: {}",
            site.name,
            reply.body
        );
        let link = "/robot/KR%206%2F2%20%3F%231";
        for page in ["/fleet", "/record/1"] {
            let body = get(r, page, &tec).await.body;
            assert!(
                body.contains(&format!("href=\"{link}\"")),
                "{} {page}: {body}",
                site.name
            );
        }
        let robot = get(r, link, &tec).await;
        assert_eq!(
            robot.status,
            StatusCode::OK,
            "{}: {}",
            site.name,
            robot.body
        );
        // minijinja escapes `/` in HTML text as `&#x2f;`.
        assert!(
            robot.body.contains("KR 6&#x2f;2 ?#1"),
            "{}: {}",
            site.name,
            robot.body
        );
    }
}

#[tokio::test]
async fn markup_and_sql_in_fields_are_shown_as_text_and_bound_as_values() {
    for site in sites("injection") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        let serial = "<script>alert(1)</script>'; DROP TABLE records; --";
        let reply = upload(r, &tec, &csrf, serial, EXPORT).await;
        assert_eq!(
            reply.status,
            StatusCode::SEE_OTHER,
            "{}: {}",
            site.name,
            reply.body
        );
        let records = with_history(&site.at, |h| h.list(None).unwrap());
        assert_eq!(records.len(), 1, "{}", site.name);
        assert_eq!(
            records[0].new.serial, serial,
            "stored as given, the table intact"
        );
        for page in ["/fleet", "/record/1", "/audit"] {
            let body = get(r, page, &tec).await.body;
            assert!(!body.contains("<script>"), "{} {page}: {body}", site.name);
            assert!(body.contains("&lt;script&gt;"), "{} {page}", site.name);
        }
        // A sign-in name of SQL signs nobody in, and a search of it finds nothing.
        assert_eq!(
            login_as(r, "' OR '1'='1", "' OR '1'='1").await.status,
            StatusCode::UNAUTHORIZED
        );
        let found = get(r, "/fleet?q=%27%20OR%20%271%27%3D%271", &tec).await;
        assert!(found.body.contains("Fleet: 0 robots"), "{}", found.body);
        // An admin's new user with markup in its name is shown as text.
        let (adm, adm_csrf) = sign_in(r, "adm").await;
        let reply = post(
            r,
            "/admin/users",
            &adm,
            &[
                ("csrf", &adm_csrf),
                ("name", "<b>x</b>"),
                ("role", "technician"),
                ("password", "pw"),
            ],
        )
        .await;
        assert_eq!(reply.status, StatusCode::SEE_OTHER, "{}", reply.body);
        let users = get(r, "/admin/users", &adm).await.body;
        assert!(
            users.contains("&lt;b&gt;x&lt;") && !users.contains("<b>x</b>"),
            "{users}"
        );
        // An unknown sort is refused by name, not run.
        let bad = get(r, "/fleet?sort=serial;DROP", &tec).await;
        assert_eq!(bad.status, StatusCode::BAD_REQUEST);
        assert!(bad
            .headers
            .get(header::CONTENT_TYPE)
            .unwrap()
            .to_str()
            .unwrap()
            .starts_with("text/plain"));
    }
}

#[tokio::test]
async fn an_oversized_malformed_or_other_robots_export_is_refused_and_nothing_recorded() {
    for site in sites("bad_exports") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &csrf, "R1", EXPORT).await.status,
            StatusCode::SEE_OTHER
        );
        let before = state(&site.at);
        let mut big = EXPORT.to_vec();
        big.resize(TEST_UPLOAD_LIMIT + 1, b'x');
        let reply = upload(r, &tec, &csrf, "R2", &big).await;
        assert_eq!(
            reply.status,
            StatusCode::PAYLOAD_TOO_LARGE,
            "{}: {}",
            site.name,
            reply.body
        );
        let reply = upload(
            r,
            &tec,
            &csrf,
            "R2",
            b"robot kuka-kr6-r900-sixx\nmalformed\n",
        )
        .await;
        assert_eq!(reply.status, StatusCode::UNPROCESSABLE_ENTITY);
        assert!(reply.body.contains("unknown column"), "{}", reply.body);
        let reply = upload(r, &tec, &csrf, "R2", b"no robot line").await;
        assert_eq!(reply.status, StatusCode::UNPROCESSABLE_ENTITY);
        assert!(
            reply.body.contains("not a pendant export"),
            "{}",
            reply.body
        );
        // R1 is a KR6 in the history: a FANUC's export under its serial is another robot's.
        let reply = upload(r, &tec, &csrf, "R1", b"robot fanuc-m-10id-12\nrow 1\n").await;
        assert_eq!(reply.status, StatusCode::UNPROCESSABLE_ENTITY);
        assert!(
            reply.body.contains("another robot")
                && reply.body.contains("kuka-kr6-r900-sixx")
                && !reply.body.contains("history: serial"),
            "{}",
            reply.body
        );
        assert_eq!(
            upload(r, &tec, &csrf, "R2", b"").await.status,
            StatusCode::UNPROCESSABLE_ENTITY
        );
        assert_eq!(state(&site.at), before, "{}", site.name);
    }
}

#[tokio::test]
async fn a_flood_of_sign_ins_is_refused_across_servers_sharing_the_database() {
    for site in sites("login_flood") {
        let r = &site.router;
        for i in 0..MAX_FAILED_LOGINS {
            let reply = login_as(r, "rev", "wrong").await;
            assert_eq!(
                reply.status,
                StatusCode::UNAUTHORIZED,
                "{} attempt {i}",
                site.name
            );
        }
        // The right password now: refused, untried, here and on another server.
        let reply = login_as(r, "rev", PASSWORD).await;
        assert_eq!(reply.status, StatusCode::TOO_MANY_REQUESTS, "{}", site.name);
        assert!(reply.headers.get(header::SET_COOKIE).is_none());
        assert!(
            reply
                .body
                .contains(&format!("{} minutes", LOGIN_WINDOW_SECONDS / 60)),
            "{}",
            reply.body
        );
        let other = server(&site.at);
        assert_eq!(
            login_as(&other, "rev", PASSWORD).await.status,
            StatusCode::TOO_MANY_REQUESTS
        );
        // Another name is not locked by it.
        sign_in(&other, "tec").await;
    }
}

/// A form sent from another site is refused before anything is tried or written, the
/// sign-in form included (login CSRF): by the browser's `Sec-Fetch-Site`, or by an
/// `Origin` that is not this host where a browser sends no `Sec-Fetch-Site`; the same
/// form from this server's own page signs in.
#[tokio::test]
async fn a_form_from_another_site_is_refused_even_the_sign_in() {
    for site in sites("cross_site_forms") {
        let login = |headers: &[(&'static str, &'static str)]| {
            let mut b = axum::http::Request::post("/login")
                .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
                .header(header::HOST, "zerocal.plant.example");
            for (k, v) in headers {
                b = b.header(*k, *v);
            }
            b.body(axum::body::Body::from(form_body(&[
                ("name", "tec"),
                ("password", PASSWORD),
            ])))
            .unwrap()
        };
        for headers in [
            &[("sec-fetch-site", "cross-site")][..],
            &[("sec-fetch-site", "same-site")],
            &[("origin", "https://evil.example")],
            &[("origin", "null")],
        ] {
            let reply = send(&site.router, login(headers)).await;
            assert_eq!(
                reply.status,
                StatusCode::FORBIDDEN,
                "{} {headers:?}",
                site.name
            );
            assert!(reply.headers.get(header::SET_COOKIE).is_none());
        }
        let tried = with_history(&site.at, |h| h.login_failures_since("tec", 0).unwrap());
        assert_eq!(tried, 0, "{}: a refused form was counted", site.name);
        for headers in [
            &[
                ("sec-fetch-site", "same-origin"),
                ("origin", "https://zerocal.plant.example"),
            ][..],
            // Behind a proxy that rewrites Host, the browser's own word decides.
            &[
                ("sec-fetch-site", "same-origin"),
                ("origin", "https://elsewhere.example"),
            ],
            &[("origin", "https://zerocal.plant.example")],
            &[],
        ] {
            let reply = send(&site.router, login(headers)).await;
            assert_eq!(
                reply.status,
                StatusCode::SEE_OTHER,
                "{} {headers:?}",
                site.name
            );
        }
    }
}

/// A record's first certificate is numbered by those who work the records, on a form
/// they send: a GET shows only an issued one (none yet: 404, nothing issued); a POST
/// without the form's CSRF token, or by the users' admin, is refused and issues
/// nothing; a technician's issues it, audited once, and the same POST again gives the
/// same certificate.
#[tokio::test]
async fn a_certificate_is_issued_by_a_form_of_those_who_work_the_records_never_by_a_get() {
    for site in sites("certificate_issuer") {
        let r = &site.router;
        let (tec, csrf) = sign_in(r, "tec").await;
        assert_eq!(
            upload(r, &tec, &csrf, "R1", EXPORT).await.status,
            StatusCode::SEE_OTHER
        );
        let certificates = || with_history(&site.at, |h| h.certificates_of(1).unwrap().len());
        let issues = || {
            with_history(&site.at, |h| {
                h.audit_log(i64::MAX)
                    .unwrap()
                    .into_iter()
                    .filter(|e| e.action == "certificate.issue")
                    .map(|e| e.actor)
                    .collect::<Vec<_>>()
            })
        };
        let before = state(&site.at);
        let (adm, adm_csrf) = sign_in(r, "adm").await;
        // The record page offers the button to a technician, not to the admin.
        let issue_form = "action=\"/record/1/certificate\"";
        assert!(get(r, "/record/1", &tec).await.body.contains(issue_form));
        assert!(!get(r, "/record/1", &adm).await.body.contains(issue_form));
        for cookie in [&tec, &adm] {
            let shown = get(r, "/record/1/certificate", cookie).await;
            assert_eq!(shown.status, StatusCode::NOT_FOUND, "{}", site.name);
            assert!(
                shown.body.contains("no certificate issued yet"),
                "{}",
                shown.body
            );
        }
        assert!(get(r, "/record/1/certificate", &tec)
            .await
            .body
            .contains(issue_form));
        for fields in [vec![], vec![("csrf", "0".repeat(64))]] {
            let fields: Vec<(&str, &str)> = fields.iter().map(|(k, v)| (*k, v.as_str())).collect();
            let refused = post(r, "/record/1/certificate", &tec, &fields).await;
            assert_eq!(refused.status, StatusCode::FORBIDDEN, "{}", site.name);
            assert!(refused.body.contains("CSRF"), "{}", refused.body);
        }
        let refused = post(r, "/record/1/certificate", &adm, &[("csrf", &adm_csrf)]).await;
        assert_eq!(refused.status, StatusCode::FORBIDDEN, "{}", site.name);
        assert!(refused.body.contains("adm is a admin"), "{}", refused.body);
        assert_eq!(state(&site.at), before, "{}", site.name);
        assert_eq!((certificates(), issues().len()), (0, 0), "{}", site.name);

        let issued = post(r, "/record/1/certificate", &tec, &[("csrf", &csrf)]).await;
        assert_eq!(issued.status, StatusCode::SEE_OTHER, "{}", issued.body);
        assert_eq!(
            issued.headers.get(header::LOCATION).unwrap(),
            "/record/1/certificate"
        );
        assert_eq!((certificates(), issues()), (1, vec!["tec".to_owned()]));
        // Shown to anyone signed in now, the admin too; issued again: the same one.
        for cookie in [&tec, &adm] {
            let shown = get(r, "/record/1/certificate", cookie).await;
            assert_eq!(shown.status, StatusCode::OK, "{}", site.name);
            assert!(
                shown.body.contains("Certificate of record 1"),
                "{}",
                shown.body
            );
        }
        assert_eq!(
            post(r, "/record/1/certificate", &tec, &[("csrf", &csrf)])
                .await
                .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!((certificates(), issues()), (1, vec!["tec".to_owned()]));
        let page = get(r, "/record/1", &tec).await.body;
        assert!(page.contains("href=\"/record/1/certificate\"") && !page.contains(issue_form));
    }
}

/// Parallel guesses are counted against each other: of twelve wrong sign-ins sent at
/// once, to two servers sharing the database, at most [`MAX_FAILED_LOGINS`] have their
/// password tried and the rest are refused untried (counted and recorded in one locked
/// transaction, before the password is checked; before that, all twelve could pass a
/// count of none).
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn parallel_sign_ins_cannot_pass_the_same_count() {
    for site in sites("login_parallel") {
        let other = server(&site.at);
        let mut tries = tokio::task::JoinSet::new();
        for i in 0..12 {
            let r = if i % 2 == 0 {
                site.router.clone()
            } else {
                other.clone()
            };
            tries.spawn(async move { login_as(&r, "rev", "wrong").await.status });
        }
        let mut tried = 0;
        while let Some(status) = tries.join_next().await {
            match status.unwrap() {
                StatusCode::UNAUTHORIZED => tried += 1,
                StatusCode::TOO_MANY_REQUESTS => {}
                s => panic!("{}: {s}", site.name),
            }
        }
        assert_eq!(tried, MAX_FAILED_LOGINS, "{}: passwords tried", site.name);
        // The right password now is refused untried as well.
        assert_eq!(
            login_as(&site.router, "rev", PASSWORD).await.status,
            StatusCode::TOO_MANY_REQUESTS,
            "{}",
            site.name
        );
    }
}

/// A name no account can have is refused as a wrong one and not recorded: a flood of
/// made-up names cannot fill the attempts table. A NUL in the name (which PostgreSQL's
/// text cannot hold: before, a 500) is refused the same way.
#[tokio::test]
async fn a_sign_in_with_a_name_no_account_can_have_records_nothing() {
    for site in sites("login_bad_name") {
        let long = "x".repeat(1_000);
        let reply = login_as(&site.router, &long, "whatever").await;
        assert_eq!(reply.status, StatusCode::UNAUTHORIZED, "{}", site.name);
        let recorded = with_history(&site.at, |h| h.login_failures_since(&long, 0).unwrap());
        assert_eq!(recorded, 0, "{}", site.name);
        let reply = login_as(&site.router, "a\u{0}b", "whatever").await;
        assert_eq!(reply.status, StatusCode::UNAUTHORIZED, "{}", site.name);
    }
}

#[tokio::test]
async fn a_session_started_on_one_server_is_valid_on_another_and_ends_on_both() {
    for site in sites("shared_sessions") {
        let (cookie, csrf) = sign_in(&site.router, "tec").await;
        let other = server(&site.at);
        assert_eq!(get(&other, "/fleet", &cookie).await.status, StatusCode::OK);
        assert_eq!(
            post(&other, "/logout", &cookie, &[("csrf", &csrf)])
                .await
                .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            get(&site.router, "/fleet", &cookie).await.status,
            StatusCode::SEE_OTHER
        );
    }
}

#[tokio::test]
async fn every_accepted_change_is_in_the_audit_log_with_who_what_before_and_after() {
    for site in sites("audit_trail") {
        let r = &site.router;
        let (tec, tec_csrf) = sign_in(r, "tec").await;
        let (rev, rev_csrf) = sign_in(r, "rev").await;
        let (aut, aut_csrf) = sign_in(r, "aut").await;
        let (adm, adm_csrf) = sign_in(r, "adm").await;
        let reply = upload(r, &tec, &tec_csrf, "R1", EXPORT).await;
        assert_eq!(
            reply.headers.get(header::LOCATION).unwrap(),
            "/record/1",
            "{}",
            site.name
        );
        // Authorizing before the check is refused; then checked, then authorized.
        let early = post(
            r,
            "/record/1/sign",
            &aut,
            &[("csrf", &aut_csrf), ("step", "authorized")],
        )
        .await;
        assert_eq!(
            early.status,
            StatusCode::UNPROCESSABLE_ENTITY,
            "{}",
            early.body
        );
        assert_eq!(
            post(
                r,
                "/record/1/sign",
                &rev,
                &[("csrf", &rev_csrf), ("step", "checked")]
            )
            .await
            .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            post(
                r,
                "/record/1/sign",
                &aut,
                &[("csrf", &aut_csrf), ("step", "authorized")]
            )
            .await
            .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            post(
                r,
                "/admin/users",
                &adm,
                &[
                    ("csrf", &adm_csrf),
                    ("name", "ana"),
                    ("role", "reviewer"),
                    ("password", "pw")
                ]
            )
            .await
            .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            post(
                r,
                "/admin/users/ana",
                &adm,
                &[("csrf", &adm_csrf), ("role", "authorizer"), ("active", "0")]
            )
            .await
            .status,
            StatusCode::SEE_OTHER
        );
        assert_eq!(
            post(r, "/record/1/certificate", &rev, &[("csrf", &rev_csrf)])
                .await
                .status,
            StatusCode::SEE_OTHER
        );
        let cert = get(r, "/record/1/certificate", &rev).await;
        assert!(
            cert.body.contains("checked by rev") && cert.body.contains("authorized by aut"),
            "{}",
            cert.body
        );

        let (log, operator) = with_history(&site.at, |h| {
            (h.audit_log(100).unwrap(), h.get(1).unwrap().new.operator)
        });
        let log: Vec<_> = log
            .into_iter()
            .rev()
            .filter(|e| e.actor != "setup")
            .collect();
        let seen: Vec<(&str, &str, &str)> = log
            .iter()
            .map(|e| (e.actor.as_str(), e.action.as_str(), e.subject.as_str()))
            .collect();
        assert_eq!(
            seen,
            [
                ("tec", "record.insert", "record 1"),
                ("rev", "record.sign", "record 1"),
                ("aut", "record.sign", "record 1"),
                ("adm", "user.add", "user ana"),
                ("adm", "user.set", "user ana"),
                ("rev", "certificate.issue", "record 1"),
            ],
            "{}",
            site.name
        );
        for e in &log {
            assert!(
                zerocal_civil::Timestamp::clock().to_string() >= e.at,
                "{e:?}"
            );
        }
        assert!(log[0].before_json.is_none() && log[0].after_json.contains("\"operator\":\"tec\""));
        assert_eq!(
            log[4].before_json.as_deref(),
            Some(r#"{"active":true,"name":"ana","role":"reviewer"}"#)
        );
        assert_eq!(
            log[4].after_json,
            r#"{"active":false,"name":"ana","role":"authorizer"}"#
        );
        // The record's operator is the signed-in user, whatever the form said.
        assert_eq!(operator.as_deref(), Some("tec"));
        // The audit page shows it to anyone signed in; a disabled user cannot sign in.
        assert!(get(r, "/audit", &tec).await.body.contains("user.set"));
        assert_eq!(
            login_as(r, "ana", "pw").await.status,
            StatusCode::UNAUTHORIZED
        );
    }
}

#[tokio::test]
async fn the_certificate_is_printed_to_pdf_by_headless_chromium_where_there_is_one() {
    let chromium = std::path::Path::new("/usr/bin/chromium");
    if !chromium.is_file() {
        eprintln!("no /usr/bin/chromium: the PDF is not tested");
        return;
    }
    let site = sites("pdf").remove(0);
    let router = zerocal_web::router(
        zerocal_web::Config {
            db: site.at.clone(),
            secure_cookies: false,
            max_upload_bytes: TEST_UPLOAD_LIMIT,
            intervals: zerocal_web::Intervals::default(),
            chromium: Some(chromium.into()),
        },
        Box::new(FakeProduct),
    )
    .unwrap();
    let (tec, csrf) = sign_in(&router, "tec").await;
    assert_eq!(
        upload(&router, &tec, &csrf, "R1", EXPORT).await.status,
        StatusCode::SEE_OTHER
    );
    assert_eq!(
        post(&router, "/record/1/certificate", &tec, &[("csrf", &csrf)])
            .await
            .status,
        StatusCode::SEE_OTHER
    );
    assert!(get(&router, "/record/1", &tec)
        .await
        .body
        .contains("certificate.pdf"));
    let reply = get(&router, "/record/1/certificate.pdf", &tec).await;
    assert_eq!(reply.status, StatusCode::OK, "{}", reply.body);
    assert_eq!(
        reply.headers.get(header::CONTENT_TYPE).unwrap(),
        "application/pdf"
    );
    assert!(reply.body.starts_with("%PDF"));
    // Without Chromium configured, the download says so.
    let reply = get(&site.router, "/record/1/certificate.pdf", &tec).await;
    assert_eq!(reply.status, StatusCode::NOT_FOUND);
    assert!(reply.body.contains("Chromium"), "{}", reply.body);
}

#[tokio::test]
async fn every_page_forbids_scripts_and_framing_and_the_cookie_is_http_only_and_strict() {
    let site = sites("headers").remove(0);
    let r = &site.router;
    for page in ["/login", "/fleet"] {
        let reply = get(r, page, "").await;
        let csp = reply
            .headers
            .get(header::CONTENT_SECURITY_POLICY)
            .unwrap()
            .to_str()
            .unwrap();
        assert!(
            csp.contains("default-src 'none'") && !csp.contains("script-src"),
            "{csp}"
        );
        assert!(csp.contains("frame-ancestors 'none'"), "{csp}");
        assert_eq!(
            reply.headers.get(header::X_CONTENT_TYPE_OPTIONS).unwrap(),
            "nosniff"
        );
    }
    let reply = login_as(r, "tec", PASSWORD).await;
    let cookie = reply
        .headers
        .get(header::SET_COOKIE)
        .unwrap()
        .to_str()
        .unwrap();
    assert!(
        cookie.contains("HttpOnly") && cookie.contains("SameSite=Strict"),
        "{cookie}"
    );
    assert!(
        !cookie.contains("Secure"),
        "plain HTTP on the loopback: {cookie}"
    );
    // Behind a TLS proxy the cookie is Secure.
    let behind = zerocal_web::router(
        zerocal_web::Config {
            db: site.at.clone(),
            secure_cookies: true,
            max_upload_bytes: TEST_UPLOAD_LIMIT,
            intervals: zerocal_web::Intervals::default(),
            chromium: None,
        },
        Box::new(FakeProduct),
    )
    .unwrap();
    let reply = login_as(&behind, "tec", PASSWORD).await;
    let cookie = reply
        .headers
        .get(header::SET_COOKIE)
        .unwrap()
        .to_str()
        .unwrap();
    assert!(cookie.contains("; Secure"), "{cookie}");
}
