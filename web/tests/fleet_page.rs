//! The fleet page's due dates: each robot due its model's own interval after its last
//! session where one is set (`zerocal serve --interval-days-for`), else the plant's,
//! the page saying which applied; a model given an interval that no robot of the
//! fleet is of is named.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with security.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use axum::http::StatusCode;
use common::*;

#[tokio::test]
async fn each_robot_is_due_by_its_models_interval_else_the_plants_and_the_page_says_which() {
    for site in sites("fleet_intervals") {
        let router = zerocal_web::router(
            zerocal_web::Config {
                db: site.at.clone(),
                secure_cookies: false,
                max_upload_bytes: TEST_UPLOAD_LIMIT,
                intervals: zerocal_web::Intervals {
                    days: Some(365),
                    by_model: [
                        ("kuka-kr6-r900-sixx".to_owned(), 180),
                        ("abb-irb120".to_owned(), 90),
                    ]
                    .into(),
                },
                chromium: None,
            },
            Box::new(FakeProduct),
        )
        .unwrap();
        let r = &router;
        let (tec, csrf) = sign_in(r, "tec").await;
        // The fake product's sessions are measured on 2026-05-04.
        for (serial, export) in [
            ("R1", "robot kuka-kr6-r900-sixx\n1\n"),
            ("R2", "robot ur5e\n2\n"),
        ] {
            let reply = upload(r, &tec, &csrf, serial, export.as_bytes()).await;
            assert_eq!(reply.status, StatusCode::SEE_OTHER, "{}", reply.body);
        }
        let page = get(r, "/fleet", &tec).await;
        assert_eq!(page.status, StatusCode::OK, "{}", site.name);
        let row = |serial: &str| {
            page.body
                .split("<tr>")
                .find(|row| row.contains(&format!(">{serial}</a>")))
                .unwrap()
                .to_owned()
        };
        let (kr6, ur5e) = (row("R1"), row("R2"));
        assert!(
            kr6.contains("2026-10-31") && kr6.contains("180 days, the model's"),
            "{kr6}"
        );
        assert!(
            ur5e.contains("2027-05-04") && ur5e.contains("365 days, the plant's"),
            "{ur5e}"
        );
        assert!(
            page.body.contains("kuka-kr6-r900-sixx: 180 days")
                && page.body.contains("No robot of the fleet is a abb-irb120"),
            "{}",
            page.body
        );
        assert!(
            !page
                .body
                .contains("No robot of the fleet is a kuka-kr6-r900-sixx"),
            "{}",
            page.body
        );
    }
}
