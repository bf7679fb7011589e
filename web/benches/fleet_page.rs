//! The fleet page at a plant's scale: 1,000 robots of 12 models, 20,000 records (a
//! quarter checks), in a fresh SQLite file, the records sized as real ones
//! (history/benches/fleet.rs's sizes), each session with ten fitted harmonics (joints
//! 2-6, orders 1 and 2; joint 6's order 2 measured by every other session only, so that
//! the reducers' column looks back past a session that held it at its prior); then the time of `GET /fleet` through the whole
//! application (session lookup, `History::fleet`, the rows, the template), one request
//! after another, and the pages per second that gives. `cargo bench -p zerocal-web
//! --bench fleet_page`; `FLEET_ROBOTS`, `FLEET_RECORDS` and `FLEET_REQUESTS` change the
//! scale. A benchmark, not a test: it prints what it measured and asserts nothing.

// A failed set-up stops the benchmark with its reason, as a test's would.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use axum::body::Body;
use axum::http::{header, Request, StatusCode};
use http_body_util::BodyExt;
use std::time::Instant;
use tower::ServiceExt;
use zerocal_history::{
    DbLocation, Harmonic, History, JointRow, NewRecord, Record, RecordKind, Role,
};

/// `len` bytes that depend on `seed` only (xorshift64): an export that does not
/// compress away, as the history's tests make them.
fn export_bytes(seed: u64, len: usize) -> Vec<u8> {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    (0..len)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 24) as u8
        })
        .collect()
}

/// The fleet page needs no solver, certificate or plot.
struct NoProduct;

impl zerocal_web::Product for NoProduct {
    fn solve_export(&self, _: &[u8], _: &str, _: &str) -> Result<NewRecord, String> {
        Err("not in this benchmark".into())
    }
    fn certificate_html(
        &self,
        _: &mut History,
        _: &Record,
        _: zerocal_history::CertificateRequest<'_>,
    ) -> Result<String, String> {
        Err("not in this benchmark".into())
    }
    fn robot_plots_svg(&self, _: &str, _: &[Record]) -> Result<Vec<String>, String> {
        Ok(Vec::new())
    }
    fn reducer_notes(&self, _: &[Record]) -> Vec<String> {
        Vec::new()
    }
}

fn env_count(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Record `i`'s harmonics: amplitudes that change from one session to the next (a few
/// beyond the wear rule), every one measured but joint 6's order 2 on every other round.
fn harmonics(i: usize, robots: usize) -> Vec<Harmonic> {
    let round = i / robots;
    (2..=6u8)
        .flat_map(|joint| (1..=2u8).map(move |order| (joint, order)))
        .map(|(joint, order)| Harmonic {
            joint,
            order,
            amplitude_deg: 0.001 * f64::from(order)
                + 0.0004 * ((i + usize::from(joint)) % 5) as f64,
            phase_deg: 10.0 * f64::from(joint),
            amplitude_k2_deg: 0.0003,
            measured: !(joint == 6 && order == 2 && round % 2 == 1),
        })
        .collect()
}

fn fill(h: &mut History, robots: usize, records: usize) {
    let models = 12;
    let profiles: Vec<String> = (0..models)
        .map(|m| format!("name = \"model-{m}\"\n# {}\n", "x".repeat(6_160)))
        .collect();
    let result_json = format!("{{\"pad\":\"{}\"}}", "r".repeat(15_000));
    for i in 0..records {
        let robot = i % robots;
        let model = robot % models;
        let kind = if i % 4 == 3 {
            RecordKind::Check
        } else {
            RecordKind::Session
        };
        // Each robot's records a month apart, from 2020 on.
        let day = zerocal_civil::Date::from_days(
            zerocal_civil::Date::new(2020, 1, 1).unwrap().days() + 30 * (i / robots) as i64,
        );
        let r = NewRecord {
            kind,
            serial: format!("SN-{robot:04}"),
            robot: format!("model-{model}"),
            robot_title: format!("Model {model}"),
            controller_family: "kuka".into(),
            profile_toml: profiles[model].clone(),
            export: export_bytes(i as u64, 13_000),
            measured_on: day.to_string(),
            operator: Some("A. Technician".into()),
            pendant_unit: Some("ZC-0007".into()),
            pendant_result_id: None,
            reference_id: None,
            zerocal_version: "0.1.0".into(),
            verdict: if i % 40 == 3 {
                "FAIL A4".into()
            } else {
                "PASS".into()
            },
            brackets: zerocal_history::RecordBrackets::default(),
            conditions_json: "{}".into(),
            result_json: result_json.clone(),
            harmonics: if kind == RecordKind::Session {
                harmonics(i, robots)
            } else {
                Vec::new()
            },
            joints: (2..=6u8)
                .map(|joint| JointRow {
                    joint,
                    name: format!("A{joint}"),
                    offset_deg: 0.001 * f64::from(joint) * (1 + i % 7) as f64,
                    expanded_k2_deg: 0.005,
                    controller_offset_deg: 0.001,
                    pass: (kind == RecordKind::Check).then_some(true),
                })
                .collect(),
        };
        h.insert(&r).unwrap();
    }
}

fn main() {
    let robots = env_count("FLEET_ROBOTS", 1_000).max(1);
    let records = env_count("FLEET_RECORDS", 20_000).max(1);
    let requests = env_count("FLEET_REQUESTS", 20).max(1);
    let dir = tempfile::tempdir().unwrap();
    let at = DbLocation::Sqlite(dir.path().join("history.sqlite"));
    let mut h = History::open(&at).unwrap();
    let start = Instant::now();
    fill(&mut h, robots, records);
    println!(
        "fleet_page: {robots} robots, {records} records stored in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    let start = Instant::now();
    let fleet = h.fleet().unwrap();
    println!(
        "fleet_page: History::fleet alone: {} robots in {:.1} ms",
        fleet.len(),
        start.elapsed().as_secs_f64() * 1e3
    );
    let phc = zerocal_web::hash_password("bench password").unwrap();
    h.add_user("bench", "viewer", Role::Reviewer, &phc).unwrap();
    drop(h);
    let router = zerocal_web::router(
        zerocal_web::Config {
            db: at,
            secure_cookies: false,
            max_upload_bytes: 1 << 20,
            intervals: zerocal_web::Intervals {
                days: Some(365),
                by_model: Default::default(),
            },
            chromium: None,
        },
        Box::new(NoProduct),
    )
    .unwrap();
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .unwrap();
    runtime.block_on(async {
        let login = Request::post("/login")
            .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
            .body(Body::from("name=viewer&password=bench+password"))
            .unwrap();
        let res = router.clone().oneshot(login).await.unwrap();
        let cookie = res.headers()[header::SET_COOKIE]
            .to_str()
            .unwrap()
            .split(';')
            .next()
            .unwrap()
            .to_owned();
        let mut times_ms = Vec::new();
        let mut page_bytes = 0;
        for _ in 0..requests {
            let req = Request::get("/fleet?sort=drift")
                .header(header::COOKIE, &cookie)
                .body(Body::empty())
                .unwrap();
            let start = Instant::now();
            let res = router.clone().oneshot(req).await.unwrap();
            assert_eq!(res.status(), StatusCode::OK);
            page_bytes = res.into_body().collect().await.unwrap().to_bytes().len();
            times_ms.push(start.elapsed().as_secs_f64() * 1e3);
        }
        times_ms.sort_by(f64::total_cmp);
        let mean = times_ms.iter().sum::<f64>() / times_ms.len() as f64;
        println!(
            "fleet_page: GET /fleet?sort=drift, {requests} requests one after another: \
             median {:.1} ms, max {:.1} ms, mean {mean:.1} ms ({:.1} pages/s), page {page_bytes} B",
            times_ms[times_ms.len() / 2],
            times_ms[times_ms.len() - 1],
            1e3 / mean
        );
    });
}
