//! What the history tests share: the backends each test runs on and records made
//! from a seed, so a reader (another process) can tell every byte they should hold.

use std::path::PathBuf;
use zerocal_history::{DbLocation, JointRow, NewRecord, RecordBracket, RecordBrackets, RecordKind};

/// The environment variable naming the PostgreSQL server of the tests.
pub const POSTGRES_ENV: &str = "ZEROCAL_TEST_POSTGRES";

/// A backend a test runs on; the temporary directory lives as long as it.
pub struct Backend {
    pub name: &'static str,
    pub at: DbLocation,
    _dir: Option<tempfile::TempDir>,
}

/// `url` with its database replaced by `database`.
pub fn with_database(url: &str, database: &str) -> String {
    let (base, query) = match url.split_once('?') {
        Some((b, q)) => (b, format!("?{q}")),
        None => (url, String::new()),
    };
    let (scheme, rest) = base.split_once("://").unwrap();
    let authority = rest.split('/').next().unwrap();
    format!("{scheme}://{authority}/{database}{query}")
}

/// A fresh SQLite file in a temporary directory, and a fresh PostgreSQL database
/// (named after the test) on the server `ZEROCAL_TEST_POSTGRES` names. Without that
/// variable the PostgreSQL half is skipped with a note, except under `CI=true`, where
/// it fails: CI must not pass by skipping it.
pub fn backends(test: &str) -> Vec<Backend> {
    let dir = tempfile::tempdir().unwrap();
    let mut out = vec![Backend {
        name: "SQLite",
        at: DbLocation::Sqlite(dir.path().join("history.sqlite")),
        _dir: Some(dir),
    }];
    match std::env::var(POSTGRES_ENV) {
        Ok(url) if !url.is_empty() => out.push(Backend {
            name: "PostgreSQL",
            at: DbLocation::Postgres(fresh_postgres_database(&url, test)),
            _dir: None,
        }),
        _ => {
            assert!(
                std::env::var("CI").as_deref() != Ok("true"),
                "CI=true but {POSTGRES_ENV} is unset: the PostgreSQL half of {test} would be \
                 skipped (CI runs `cargo xtask postgres start` and exports it)"
            );
            eprintln!("{test}: {POSTGRES_ENV} unset, PostgreSQL not tested");
        }
    }
    out
}

/// Drops and creates database `zc_TEST` on the server and returns its URL.
pub fn fresh_postgres_database(url: &str, test: &str) -> String {
    let name = format!("zc_{test}");
    let mut admin = zerocal_history::postgres_connect(url).unwrap();
    admin
        .batch_execute(&format!("DROP DATABASE IF EXISTS {name} WITH (FORCE)"))
        .unwrap();
    admin
        .batch_execute(&format!("CREATE DATABASE {name}"))
        .unwrap();
    with_database(url, &name)
}

/// A temporary file path of its own directory.
pub fn temp_file(name: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    (dir, path)
}

/// `len` bytes that depend on `seed` only (xorshift64).
pub fn export_bytes(seed: u64, len: usize) -> Vec<u8> {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    (0..len)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u8
        })
        .collect()
}

/// The seed of record `i` of `serial`.
pub fn seed(serial: &str, i: u32) -> u64 {
    serial.bytes().fold(u64::from(i) + 1, |h, b| {
        h.wrapping_mul(31).wrapping_add(u64::from(b))
    })
}

/// Record `i` of `serial`: its export (`export_len` bytes) and its offsets follow from
/// the serial and `i`, and `pendant_result_id` is `i`.
pub fn record(kind: RecordKind, serial: &str, i: u32, export_len: usize) -> NewRecord {
    let joints = (2..=6u8)
        .map(|joint| JointRow {
            joint,
            name: format!("A{joint}"),
            offset_deg: 0.001 * f64::from(joint) + 1e-5 * f64::from(i),
            expanded_k2_deg: 0.004 + 0.0005 * f64::from(joint),
            controller_offset_deg: -0.001 * f64::from(joint),
            pass: match kind {
                RecordKind::Session => None,
                RecordKind::Check => Some(joint != 4),
            },
        })
        .collect();
    NewRecord {
        kind,
        serial: serial.into(),
        robot: "kuka-kr6-r900-sixx".into(),
        robot_title: "KUKA KR 6 R900 sixx".into(),
        controller_family: "kuka".into(),
        profile_toml: "name = \"kuka-kr6-r900-sixx\"\n".into(),
        export: export_bytes(seed(serial, i), export_len),
        measured_on: "2026-11-27".into(),
        operator: Some("A. Technician".into()),
        pendant_unit: Some("ZC-0007".into()),
        pendant_result_id: Some(i),
        reference_id: None,
        zerocal_version: "0.1.0".into(),
        verdict: "PASS".into(),
        // An ID only: the shape an import's old `{"flange": "B-12"}` migrates to.
        brackets: RecordBrackets {
            upper_arm: None,
            flange: Some(RecordBracket {
                id: "B-12".into(),
                calibration: None,
            }),
        },
        conditions_json: r#"{"temperature_c":21.5}"#.into(),
        result_json: r#"{"verdict":"PASS"}"#.into(),
        harmonics: Vec::new(),
        joints,
    }
}

/// Stores `r` as a build of schema 1-3 did (the profile's text in the record itself,
/// the brackets' IDs in an import's old shape, [`old_import_brackets`]), straight through
/// the backend's own client: the record a migration must carry over. Returns its ID.
pub fn insert_before_schema_4(at: &DbLocation, r: &NewRecord) -> i64 {
    insert_old(at, r, OldSchema::ProfileInRecord, &old_import_brackets(r))
}

/// Stores `r` as a build of schema 4-5 did (the profile's text in `texts`), with
/// `brackets_json` as given: one of the shapes schema 6 rewrites. Returns its ID.
pub fn insert_at_schema_5(at: &DbLocation, r: &NewRecord, brackets_json: &str) -> i64 {
    insert_old(at, r, OldSchema::ProfileInTexts, brackets_json)
}

/// The brackets of `r` as an import wrote them before schema 6: `{"upper_arm": ID or
/// null, "flange": ID or null}` (calibrations, which that shape cannot hold, dropped).
pub fn old_import_brackets(r: &NewRecord) -> String {
    let id = |b: &Option<zerocal_history::RecordBracket>| b.as_ref().map(|b| b.id.clone());
    serde_json::json!({ "upper_arm": id(&r.brackets.upper_arm), "flange": id(&r.brackets.flange) })
        .to_string()
}

/// Where an old build kept a record's profile text.
#[derive(Clone, Copy, PartialEq)]
enum OldSchema {
    /// Schema 1-3: `records.profile_toml`.
    ProfileInRecord,
    /// Schema 4-5: `texts`, by hash.
    ProfileInTexts,
}

fn insert_old(at: &DbLocation, r: &NewRecord, schema: OldSchema, brackets_json: &str) -> i64 {
    use zerocal_history::sha256_hex;
    let (profile_sha, export_sha) = (sha256_hex(r.profile_toml.as_bytes()), sha256_hex(&r.export));
    let pass = |p: Option<bool>| p.map(i64::from);
    // The profile's text: a column of the record, or a row of `texts` (NULL here, the
    // row inserted first).
    let (profile_column, texts) = match schema {
        OldSchema::ProfileInRecord => ("profile_toml, ", None),
        OldSchema::ProfileInTexts => ("", Some(r.profile_toml.clone())),
    };
    let sql = |p: char| {
        let n = if texts.is_some() { 18 } else { 19 };
        let params: Vec<String> = (1..=n).map(|i| format!("{p}{i}")).collect();
        format!(
            "INSERT INTO records (recorded_at, kind, serial, robot, robot_title, \
             controller_family, {profile_column}profile_sha256, export, export_sha256, \
             measured_on, operator, pendant_unit, pendant_result_id, reference_id, \
             zerocal_version, verdict, brackets_json, conditions_json, result_json) \
             VALUES ('2026-11-27T10:00:00Z', {}) RETURNING id",
            params.join(", ")
        )
    };
    match at {
        DbLocation::Sqlite(p) => {
            let c = rusqlite::Connection::open(p).unwrap();
            let mut params: Vec<Box<dyn rusqlite::ToSql>> = vec![
                Box::new(r.kind.as_str()),
                Box::new(r.serial.clone()),
                Box::new(r.robot.clone()),
                Box::new(r.robot_title.clone()),
                Box::new(r.controller_family.clone()),
            ];
            match &texts {
                None => params.push(Box::new(r.profile_toml.clone())),
                Some(text) => {
                    c.execute(
                        "INSERT INTO texts (sha256, text) VALUES (?1, ?2) \
                         ON CONFLICT (sha256) DO NOTHING",
                        rusqlite::params![profile_sha, text],
                    )
                    .unwrap();
                }
            }
            params.extend::<[Box<dyn rusqlite::ToSql>; 13]>([
                Box::new(profile_sha.clone()),
                Box::new(r.export.clone()),
                Box::new(export_sha.clone()),
                Box::new(r.measured_on.clone()),
                Box::new(r.operator.clone()),
                Box::new(r.pendant_unit.clone()),
                Box::new(r.pendant_result_id),
                Box::new(r.reference_id),
                Box::new(r.zerocal_version.clone()),
                Box::new(r.verdict.clone()),
                Box::new(brackets_json.to_owned()),
                Box::new(r.conditions_json.clone()),
                Box::new(r.result_json.clone()),
            ]);
            let id: i64 = c
                .query_row(
                    &sql('?'),
                    rusqlite::params_from_iter(params.iter()),
                    |row| row.get(0),
                )
                .unwrap();
            for j in &r.joints {
                c.execute(
                    "INSERT INTO joints VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)",
                    rusqlite::params![
                        id,
                        j.joint,
                        j.name,
                        j.offset_deg,
                        j.expanded_k2_deg,
                        j.controller_offset_deg,
                        pass(j.pass)
                    ],
                )
                .unwrap();
            }
            id
        }
        DbLocation::Postgres(url) => {
            let mut c = zerocal_history::postgres_connect(url).unwrap();
            let result_id = r.pendant_result_id.map(i64::from);
            let kind = r.kind.as_str();
            let brackets_json = brackets_json.to_owned();
            let mut params: Vec<&(dyn postgres::types::ToSql + Sync)> = vec![
                &kind,
                &r.serial,
                &r.robot,
                &r.robot_title,
                &r.controller_family,
            ];
            match &texts {
                None => params.push(&r.profile_toml),
                Some(text) => {
                    c.execute(
                        "INSERT INTO texts (sha256, text) VALUES ($1, $2) \
                         ON CONFLICT (sha256) DO NOTHING",
                        &[&profile_sha, text],
                    )
                    .unwrap();
                }
            }
            params.extend::<[&(dyn postgres::types::ToSql + Sync); 13]>([
                &profile_sha,
                &r.export,
                &export_sha,
                &r.measured_on,
                &r.operator,
                &r.pendant_unit,
                &result_id,
                &r.reference_id,
                &r.zerocal_version,
                &r.verdict,
                &brackets_json,
                &r.conditions_json,
                &r.result_json,
            ]);
            let id: i64 = c.query_one(&sql('$'), &params).unwrap().get(0);
            for j in &r.joints {
                c.execute(
                    "INSERT INTO joints VALUES ($1, $2, $3, $4, $5, $6, $7)",
                    &[
                        &id,
                        &i64::from(j.joint),
                        &j.name,
                        &j.offset_deg,
                        &j.expanded_k2_deg,
                        &j.controller_offset_deg,
                        &pass(j.pass),
                    ],
                )
                .unwrap();
            }
            id
        }
    }
}
