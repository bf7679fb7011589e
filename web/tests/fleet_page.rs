//! The fleet page's due dates: each robot due its model's own interval after its last
//! session where one is set (`zerocal serve --interval-days-for`), else the plant's,
//! the page saying which applied; a model given an interval that no robot of the
//! fleet is of is named. Its reducers' column: a harmonic grown beyond the wear rule
//! since the robot's previous session that measured it is shown and kept by
//! `only=wearing`; a healthy robot's is not.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared with security.rs, which uses the rest of it.
#[allow(dead_code)]
mod common;

use axum::http::StatusCode;
use common::*;
use zerocal_history::reducers::WEAR_SIGMAS;
use zerocal_history::{Harmonic, NewRecord};

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

/// A session of `serial` measured on `day` with these harmonics: (joint, order,
/// amplitude deg, U(k=2) deg, measured).
fn session_with(serial: &str, day: &str, harmonics: &[(u8, u8, f64, f64, bool)]) -> NewRecord {
    use zerocal_web::Product;
    let export = format!("robot kuka-kr6-r900-sixx\n{serial} {day}\n");
    let mut r = FakeProduct
        .solve_export(export.as_bytes(), serial, "tec")
        .unwrap();
    r.measured_on = day.into();
    r.harmonics = harmonics
        .iter()
        .map(
            |&(joint, order, amplitude_deg, amplitude_k2_deg, measured)| Harmonic {
                joint,
                order,
                amplitude_deg,
                phase_deg: 10.0,
                amplitude_k2_deg,
                measured,
            },
        )
        .collect();
    r
}

#[tokio::test]
async fn a_reducer_grown_beyond_the_wear_rule_shows_as_wearing_and_a_healthy_one_does_not() {
    for site in sites("fleet_reducers") {
        let r = &site.router;
        let u = 0.002;
        // WEAR: joint 4's order 2 grows by 0.012 deg (the U of each session 0.002 deg);
        // joint 5's order 1, held at its prior both times, "grows" more and is no
        // measurement. Its middle session held j4 h2 at its prior too: the comparison
        // goes back to the first.
        // HEALTHY: the same harmonic up by 0.0005 deg, within its U.
        // SKIPPED: the previous session that measured it is the first, then a fall.
        // HELD: its last session measured nothing (held at its prior).
        // NONE: a session that fitted nothing.
        let sessions = [
            session_with(
                "WEAR",
                "2026-01-10",
                &[(4, 2, 0.010, u, true), (5, 1, 0.001, u, false)],
            ),
            session_with("WEAR", "2026-03-10", &[(4, 2, 0.030, u, false)]),
            session_with(
                "WEAR",
                "2026-06-10",
                &[(4, 2, 0.022, u, true), (5, 1, 0.050, u, false)],
            ),
            session_with("HEALTHY", "2026-01-10", &[(4, 2, 0.010, u, true)]),
            session_with("HEALTHY", "2026-06-10", &[(4, 2, 0.0105, u, true)]),
            session_with("FALL", "2026-01-10", &[(3, 1, 0.020, u, true)]),
            session_with("FALL", "2026-06-10", &[(3, 1, 0.005, u, true)]),
            session_with("FIRST", "2026-06-10", &[(3, 1, 0.020, u, true)]),
            session_with("HELD", "2026-01-10", &[(4, 2, 0.010, u, true)]),
            session_with("HELD", "2026-06-10", &[(4, 2, 0.030, u, false)]),
            session_with("NONE", "2026-06-10", &[]),
        ];
        with_history(&site.at, |h| {
            for s in &sessions {
                h.insert(s).unwrap();
            }
        });
        let (tec, _) = sign_in(r, "tec").await;
        let page = get(r, "/fleet", &tec).await;
        assert_eq!(page.status, StatusCode::OK, "{}: {}", site.name, page.body);
        let row = |body: &str, serial: &str| {
            body.split("<tr>")
                .find(|row| row.contains(&format!(">{serial}</a>")))
                .map(str::to_owned)
        };
        let increase: f64 = 0.022 - 0.010;
        let sigmas = increase / (u.hypot(u) / 2.0);
        assert!(sigmas > WEAR_SIGMAS, "the test's growth is beyond the rule");
        let wear = format!("J4 h2 {increase:+.4}° ({sigmas:.1}σ)");
        let wearing = row(&page.body, "WEAR").unwrap();
        assert!(wearing.contains(&wear), "{}: {wearing}", site.name);
        assert!(!wearing.contains("J5"), "{}: {wearing}", site.name);
        for (serial, shown) in [
            ("HEALTHY", ">ok<"),
            ("FALL", ">ok<"),
            ("FIRST", "first measured"),
            ("HELD", "held at prior"),
            ("NONE", "—"),
        ] {
            let got = row(&page.body, serial).unwrap();
            assert!(
                got.contains(shown) && !got.contains('σ'),
                "{}: {serial}: {got}",
                site.name
            );
        }
        assert!(
            page.body.contains(&format!(
                "grew by more than {WEAR_SIGMAS:.1} standard uncertainties"
            )),
            "the legend names the rule: {}",
            page.body
        );

        let only = get(r, "/fleet?only=wearing&sort=wear", &tec).await;
        assert_eq!(only.status, StatusCode::OK, "{}: {}", site.name, only.body);
        assert!(
            row(&only.body, "WEAR").is_some(),
            "{}: {}",
            site.name,
            only.body
        );
        for serial in ["HEALTHY", "FALL", "FIRST", "HELD", "NONE"] {
            assert!(
                row(&only.body, serial).is_none(),
                "{}: {serial} kept by only=wearing",
                site.name
            );
        }
        let sorted = get(r, "/fleet?sort=wear", &tec).await;
        let first = sorted.body.find(">WEAR</a>").unwrap();
        let healthy = sorted.body.find(">HEALTHY</a>").unwrap();
        assert!(
            first < healthy,
            "{}: sort=wear puts the wearing robot first",
            site.name
        );
    }
}
