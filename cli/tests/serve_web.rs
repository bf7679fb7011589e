//! `zerocal serve` with the CLI's own product: an export uploaded by a signed-in
//! technician is solved as `zerocal session --record` solves it and recorded with them
//! as its operator, on every built-in profile (each controller family); another
//! robot's export under a serial is refused and nothing recorded; the certificate, issued
//! by a technician's form (never by a GET), is `zerocal certificate`'s with the review
//! under it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use axum::body::Body;
use axum::http::{header, Request, StatusCode};
use http_body_util::BodyExt;
use tower::ServiceExt;
use zerocal_cli::serve::CliProduct;
use zerocal_history::{DbLocation, History, Role};

const PASSWORD: &str = "a test password";

/// The status, the cookie set (else the redirect's target) and the body.
async fn send(router: &axum::Router, req: Request<Body>) -> (StatusCode, Option<String>, String) {
    let res = router.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let location = res
        .headers()
        .get(header::LOCATION)
        .map(|v| v.to_str().unwrap().to_owned());
    let cookie = res
        .headers()
        .get(header::SET_COOKIE)
        .map(|v| v.to_str().unwrap().split(';').next().unwrap().to_owned());
    let body = res.into_body().collect().await.unwrap().to_bytes();
    (
        status,
        cookie.or(location),
        String::from_utf8_lossy(&body).into_owned(),
    )
}

fn export_of(robot: &str, seed: u64) -> String {
    let profile = zerocal_profile::builtin(robot).unwrap();
    let world = zerocal_sim::world::WorldConfig::real();
    zerocal_sim::world::RealSession::simulate_default_plan(&profile, &world, seed)
        .unwrap()
        .export_text(&profile.name)
}

async fn upload(
    router: &axum::Router,
    cookie: &str,
    csrf: &str,
    serial: &str,
    export: &str,
) -> (StatusCode, Option<String>, String) {
    const B: &str = "serveWebTestBoundary";
    let body = format!(
        "--{B}\r\nContent-Disposition: form-data; name=\"csrf\"\r\n\r\n{csrf}\r\n\
         --{B}\r\nContent-Disposition: form-data; name=\"serial\"\r\n\r\n{serial}\r\n\
         --{B}\r\nContent-Disposition: form-data; name=\"export\"; filename=\"e.txt\"\r\n\r\n{export}\r\n--{B}--\r\n"
    );
    let req = Request::post("/upload")
        .header(
            header::CONTENT_TYPE,
            format!("multipart/form-data; boundary={B}"),
        )
        .header(header::COOKIE, cookie)
        .body(Body::from(body))
        .unwrap();
    send(router, req).await
}

#[tokio::test]
async fn an_uploaded_export_is_solved_and_recorded_as_zerocal_session_does_on_every_profile() {
    let dir = tempfile::tempdir().unwrap();
    let at = DbLocation::Sqlite(dir.path().join("history.sqlite"));
    let mut h = History::open(&at).unwrap();
    let phc = zerocal_web::hash_password(PASSWORD).unwrap();
    h.add_user("setup", "tec", Role::Technician, &phc).unwrap();
    h.add_user("setup", "rev", Role::Reviewer, &phc).unwrap();
    let router = zerocal_web::router(
        zerocal_web::Config {
            db: at.clone(),
            secure_cookies: true,
            max_upload_bytes: zerocal_inputs::input::MAX_EXPORT_BYTES
                + zerocal_web::MULTIPART_OVERHEAD_BYTES,
            intervals: zerocal_web::Intervals {
                days: Some(365),
                by_model: Default::default(),
            },
            chromium: None,
        },
        Box::new(CliProduct {
            certificate_config: Some(
                concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/issuer.toml").into(),
            ),
        }),
    )
    .unwrap();
    let login = Request::post("/login")
        .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
        .body(Body::from(format!(
            "name=tec&password={}",
            PASSWORD.replace(' ', "+")
        )))
        .unwrap();
    let (status, cookie, _) = send(&router, login).await;
    assert_eq!(status, StatusCode::SEE_OTHER);
    let cookie = cookie.unwrap();
    let (_, _, page) = send(
        &router,
        Request::get("/upload")
            .header(header::COOKIE, &cookie)
            .body(Body::empty())
            .unwrap(),
    )
    .await;
    let csrf = page
        .split("name=\"csrf\" value=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .to_owned();

    let mut families = std::collections::BTreeSet::new();
    for robot in zerocal_profile::builtin_names() {
        let export = export_of(robot, 41);
        let serial = format!("SN-{robot}");
        let (status, location, body) = upload(&router, &cookie, &csrf, &serial, &export).await;
        assert_eq!(status, StatusCode::SEE_OTHER, "{robot}: {body}");
        let id: i64 = location
            .unwrap()
            .trim_start_matches("/record/")
            .parse()
            .unwrap();
        let stored = h.get(id).unwrap();
        // What `zerocal session --record` stores for the same bytes.
        let args = zerocal_analysis::session::SessionArgs::for_export("uploaded export".into());
        let analysis = zerocal_analysis::session::analyse(&args, export.as_bytes()).unwrap();
        assert_eq!(stored.new.robot, analysis.profile.name, "{robot}");
        assert_eq!(stored.new.operator.as_deref(), Some("tec"));
        assert_eq!(stored.new.export, export.as_bytes());
        assert_eq!(
            stored.new.joints.len(),
            analysis.json.joints.len(),
            "{robot}"
        );
        for (j, a) in stored.new.joints.iter().zip(&analysis.json.joints) {
            assert_eq!(
                (j.offset_deg, j.expanded_k2_deg),
                (a.offset_deg, a.expanded_k2_deg),
                "{robot}"
            );
        }
        families.insert(stored.new.controller_family.clone());
        // Another robot's export under this serial: refused, nothing recorded.
        let other = if robot == "ur5e" { "kuka-kr16" } else { "ur5e" };
        let before = h.list(None).unwrap().len();
        let (status, _, body) =
            upload(&router, &cookie, &csrf, &serial, &export_of(other, 41)).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{robot}");
        assert!(body.contains("another robot"), "{robot}: {body}");
        assert_eq!(h.list(None).unwrap().len(), before, "{robot}");
    }
    assert!(families.len() >= 6, "every controller family: {families:?}");

    // No certificate shown before one is issued, and the GET issues none.
    let (status, _, _) = send(
        &router,
        Request::get("/record/1/certificate")
            .header(header::COOKIE, &cookie)
            .body(Body::empty())
            .unwrap(),
    )
    .await;
    assert_eq!(status, StatusCode::NOT_FOUND);
    assert!(h.certificates_of(1).unwrap().is_empty());
    // Issued by the technician's form.
    let (status, location, body) = send(
        &router,
        Request::post("/record/1/certificate")
            .header(header::COOKIE, &cookie)
            .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
            .body(Body::from(format!("csrf={csrf}")))
            .unwrap(),
    )
    .await;
    assert_eq!(status, StatusCode::SEE_OTHER, "{body}");
    assert_eq!(location.as_deref(), Some("/record/1/certificate"));
    // The certificate of the first session: zerocal certificate's, with its review.
    let (status, _, html) = send(
        &router,
        Request::get("/record/1/certificate")
            .header(header::COOKIE, &cookie)
            .body(Body::empty())
            .unwrap(),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{html}");
    assert!(
        html.contains("Calibration certificate no.") && html.contains("measured by tec"),
        "{html}"
    );
    // Its first issue is in the audit log, by whom, once: showing it again issues
    // nothing new.
    let issued = |h: &mut History| {
        h.audit_log(500)
            .unwrap()
            .into_iter()
            .filter(|e| e.action == "certificate.issue" && e.subject == "record 1")
            .map(|e| e.actor)
            .collect::<Vec<_>>()
    };
    assert_eq!(issued(&mut h), ["tec"]);
    let (status, _, _) = send(
        &router,
        Request::get("/record/1/certificate")
            .header(header::COOKIE, &cookie)
            .body(Body::empty())
            .unwrap(),
    )
    .await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(issued(&mut h), ["tec"]);
}
