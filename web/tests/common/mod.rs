//! What the web tests share: a server over a fresh history (SQLite always, PostgreSQL
//! when `ZEROCAL_TEST_POSTGRES` names a server), driven without a socket
//! (`tower::ServiceExt::oneshot`), a fake product that solves a tiny stand-in export,
//! and the steps a browser takes (sign in, read a form's CSRF token, post a form).

use axum::body::Body;
use axum::http::{header, HeaderMap, Request, StatusCode};
use axum::Router;
use http_body_util::BodyExt;
use tower::ServiceExt;
use zerocal_history::{DbLocation, History, JointRow, NewRecord, Record, RecordKind, Role};
use zerocal_web::{Config, Product};

/// The fake product's export: `robot NAME` on its first line, anything after it (the
/// bytes make the record's identity). `malformed` anywhere is refused, as the CLI
/// refuses a malformed export.
pub struct FakeProduct;

impl Product for FakeProduct {
    fn solve_export(
        &self,
        export: &[u8],
        serial: &str,
        operator: &str,
    ) -> Result<NewRecord, String> {
        let text = std::str::from_utf8(export).map_err(|e| format!("export: {e}"))?;
        if text.contains("malformed") {
            return Err("export line 3: an unknown column \"malformed\"".into());
        }
        let robot = text
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("robot "))
            .ok_or("export: no `robot` line: not a pendant export")?;
        Ok(NewRecord {
            kind: RecordKind::Session,
            serial: serial.to_owned(),
            robot: robot.to_owned(),
            robot_title: format!("Title of {robot}"),
            controller_family: "kuka".into(),
            profile_toml: format!("name = \"{robot}\""),
            export: export.to_vec(),
            measured_on: "2026-05-04".into(),
            operator: Some(operator.to_owned()),
            pendant_unit: None,
            pendant_result_id: None,
            reference_id: None,
            zerocal_version: "test".into(),
            verdict: "PASS".into(),
            brackets: zerocal_history::RecordBrackets::default(),
            conditions_json: "{}".into(),
            result_json: "{}".into(),
            harmonics: Vec::new(),
            joints: (2..=6)
                .map(|j| JointRow {
                    joint: j,
                    name: format!("A{j}"),
                    offset_deg: 0.01 * f64::from(j),
                    expanded_k2_deg: 0.002,
                    controller_offset_deg: 0.01 * f64::from(j),
                    pass: None,
                })
                .collect(),
        })
    }

    /// Issues (or finds) the record's certificate in the history as the CLI's does,
    /// numbered after the record.
    fn certificate_html(
        &self,
        history: &mut History,
        record: &Record,
        by: zerocal_history::CertificateRequest<'_>,
    ) -> Result<String, String> {
        history
            .issue_certificate_by(
                &zerocal_history::NewCertificate {
                    number: format!("TEST-{}", record.id),
                    session_id: record.id,
                    as_left_id: None,
                    issued_on: "2026-05-05".into(),
                    issuer_json: "{}".into(),
                },
                Some(by),
            )
            .map_err(|e| e.to_string())?;
        Ok(format!(
            "<html><body><h1>Certificate of record {}</h1></body></html>",
            record.id
        ))
    }

    fn robot_plots_svg(&self, _: &str, records: &[Record]) -> Result<Vec<String>, String> {
        Ok(vec![format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\"><!-- {} --></svg>",
            records.len()
        )])
    }

    fn reducer_notes(&self, _: &[Record]) -> Vec<String> {
        Vec::new()
    }
}

/// The most bytes an upload may have in these tests.
pub const TEST_UPLOAD_LIMIT: usize = 4096;

/// One server over a fresh history.
pub struct Site {
    pub name: &'static str,
    pub at: DbLocation,
    pub router: Router,
    _dir: Option<tempfile::TempDir>,
}

/// The password every test user has.
pub const PASSWORD: &str = "a long test password";

/// The users every site starts with, one per role.
pub const USERS: [(&str, Role); 5] = [
    ("tec", Role::Technician),
    ("rev", Role::Reviewer),
    ("aut", Role::Authorizer),
    ("adm", Role::Admin),
    ("aut2", Role::Authorizer),
];

/// Another server over the same history (as a second instance of a plant's would be).
pub fn server(at: &DbLocation) -> Router {
    zerocal_web::router(
        Config {
            db: at.clone(),
            secure_cookies: false,
            max_upload_bytes: TEST_UPLOAD_LIMIT,
            intervals: zerocal_web::Intervals {
                days: Some(365),
                by_model: Default::default(),
            },
            chromium: None,
        },
        Box::new(FakeProduct),
    )
    .unwrap()
}

/// A fresh SQLite history, and a fresh PostgreSQL database (named after the test)
/// when `ZEROCAL_TEST_POSTGRES` is set, each with [`USERS`].
pub fn sites(test: &str) -> Vec<Site> {
    std::thread::scope(|s| s.spawn(|| sites_off_runtime(test)).join().unwrap())
}

fn sites_off_runtime(test: &str) -> Vec<Site> {
    let dir = tempfile::tempdir().unwrap();
    let mut out = vec![(
        "SQLite",
        DbLocation::Sqlite(dir.path().join("history.sqlite")),
        Some(dir),
    )];
    match std::env::var("ZEROCAL_TEST_POSTGRES") {
        Ok(url) if !url.is_empty() => out.push((
            "PostgreSQL",
            DbLocation::Postgres(fresh_postgres_database(&url, test)),
            None,
        )),
        _ => {
            // CI must not pass by skipping PostgreSQL (as the history's tests require).
            assert!(
                std::env::var("CI").as_deref() != Ok("true"),
                "CI=true but ZEROCAL_TEST_POSTGRES is unset: the PostgreSQL half of {test} would be skipped"
            );
            eprintln!("{test}: ZEROCAL_TEST_POSTGRES unset, PostgreSQL not tested");
        }
    }
    out.into_iter()
        .map(|(name, at, dir)| {
            with_history(&at, |h| {
                let phc = zerocal_web::hash_password(PASSWORD).unwrap();
                for (user, role) in USERS {
                    h.add_user("setup", user, role, &phc).unwrap();
                }
            });
            Site {
                name,
                router: server(&at),
                at,
                _dir: dir,
            }
        })
        .collect()
}

/// Drops and creates database `zcw_TEST` on the server and returns its URL.
fn fresh_postgres_database(url: &str, test: &str) -> String {
    let name = format!("zcw_{test}");
    let mut admin = zerocal_history::postgres_config(url)
        .unwrap()
        .connect(postgres::NoTls)
        .unwrap();
    admin
        .batch_execute(&format!("DROP DATABASE IF EXISTS {name} WITH (FORCE)"))
        .unwrap();
    admin
        .batch_execute(&format!("CREATE DATABASE {name}"))
        .unwrap();
    let (base, query) = url
        .split_once('?')
        .map_or((url, String::new()), |(b, q)| (b, format!("?{q}")));
    let (scheme, rest) = base.split_once("://").unwrap();
    let authority = rest.split('/').next().unwrap();
    format!("{scheme}://{authority}/{name}{query}")
}

/// A response as a test reads it.
pub struct Reply {
    pub status: StatusCode,
    pub headers: HeaderMap,
    pub body: String,
}

/// Sends `req` to `router`.
pub async fn send(router: &Router, req: Request<Body>) -> Reply {
    let res = router.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let headers = res.headers().clone();
    let bytes = res.into_body().collect().await.unwrap().to_bytes();
    Reply {
        status,
        headers,
        body: String::from_utf8_lossy(&bytes).into_owned(),
    }
}

/// `GET path` with `cookie` (none when empty).
pub async fn get(router: &Router, path: &str, cookie: &str) -> Reply {
    let mut b = Request::get(path);
    if !cookie.is_empty() {
        b = b.header(header::COOKIE, cookie);
    }
    send(router, b.body(Body::empty()).unwrap()).await
}

/// `application/x-www-form-urlencoded` of `fields`.
pub fn form_body(fields: &[(&str, &str)]) -> String {
    fields
        .iter()
        .map(|(k, v)| format!("{}={}", enc(k), enc(v)))
        .collect::<Vec<_>>()
        .join("&")
}

fn enc(s: &str) -> String {
    s.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' => (b as char).to_string(),
            _ => format!("%{b:02X}"),
        })
        .collect()
}

/// `POST path` of a form with `cookie` (none when empty).
pub async fn post(router: &Router, path: &str, cookie: &str, fields: &[(&str, &str)]) -> Reply {
    let mut b =
        Request::post(path).header(header::CONTENT_TYPE, "application/x-www-form-urlencoded");
    if !cookie.is_empty() {
        b = b.header(header::COOKIE, cookie);
    }
    send(router, b.body(Body::from(form_body(fields))).unwrap()).await
}

/// `POST /upload` as a browser's file form sends it.
pub async fn upload(
    router: &Router,
    cookie: &str,
    csrf: &str,
    serial: &str,
    export: &[u8],
) -> Reply {
    upload_with(
        router,
        cookie,
        &[("csrf", csrf), ("serial", serial)],
        export,
    )
    .await
}

/// `POST /upload` with the text `fields` and the export file.
pub async fn upload_with(
    router: &Router,
    cookie: &str,
    fields: &[(&str, &str)],
    export: &[u8],
) -> Reply {
    const B: &str = "zerocalTestBoundary7MA4YWxk";
    let mut body = Vec::new();
    for (name, value) in fields {
        body.extend_from_slice(
            format!("--{B}\r\nContent-Disposition: form-data; name=\"{name}\"\r\n\r\n").as_bytes(),
        );
        body.extend_from_slice(value.as_bytes());
        body.extend_from_slice(b"\r\n");
    }
    body.extend_from_slice(
        format!("--{B}\r\nContent-Disposition: form-data; name=\"export\"; filename=\"export.txt\"\r\nContent-Type: text/plain\r\n\r\n").as_bytes(),
    );
    body.extend_from_slice(export);
    body.extend_from_slice(format!("\r\n--{B}--\r\n").as_bytes());
    let mut b = Request::post("/upload").header(
        header::CONTENT_TYPE,
        format!("multipart/form-data; boundary={B}"),
    );
    if !cookie.is_empty() {
        b = b.header(header::COOKIE, cookie);
    }
    send(router, b.body(Body::from(body)).unwrap()).await
}

/// Signs `name` in with `password`: the reply.
pub async fn login_as(router: &Router, name: &str, password: &str) -> Reply {
    post(
        router,
        "/login",
        "",
        &[("name", name), ("password", password)],
    )
    .await
}

/// Signs `name` in with [`PASSWORD`]: its cookie (`zerocal_session=…`) and the CSRF
/// token its forms carry.
pub async fn sign_in(router: &Router, name: &str) -> (String, String) {
    let r = login_as(router, name, PASSWORD).await;
    assert_eq!(r.status, StatusCode::SEE_OTHER, "{name}: {}", r.body);
    let set = r.headers.get(header::SET_COOKIE).unwrap().to_str().unwrap();
    assert!(
        set.contains("HttpOnly") && set.contains("SameSite=Strict"),
        "{set}"
    );
    let cookie = set.split(';').next().unwrap().to_owned();
    let page = get(router, "/upload", &cookie).await;
    let csrf = page
        .body
        .split("name=\"csrf\" value=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .unwrap()
        .to_owned();
    (cookie, csrf)
}

/// `work` on the history at `at`, off the test's async runtime (the PostgreSQL client
/// is synchronous and starts a runtime of its own, as the server's spawn_blocking
/// lets it).
pub fn with_history<T: Send>(at: &DbLocation, work: impl FnOnce(&mut History) -> T + Send) -> T {
    std::thread::scope(|s| {
        s.spawn(|| work(&mut History::open(at).unwrap()))
            .join()
            .unwrap()
    })
}

/// What a refusal must leave as it was: every record, signature, certificate, user and
/// audit entry.
pub fn state(at: &DbLocation) -> String {
    with_history(at, state_of)
}

fn state_of(h: &mut History) -> String {
    let records = h.list(None).unwrap();
    let signatures: Vec<_> = records
        .iter()
        .map(|r| h.signatures(r.id).unwrap())
        .collect();
    let certificates: Vec<_> = records
        .iter()
        .map(|r| h.certificates_of(r.id).unwrap())
        .collect();
    format!(
        "{:?}\n{:?}\n{:?}\n{:?}\n{:?}",
        records
            .iter()
            .map(|r| (r.id, &r.new.serial, &r.new.robot))
            .collect::<Vec<_>>(),
        signatures,
        certificates,
        h.users().unwrap(),
        h.audit_log(i64::MAX).unwrap()
    )
}
