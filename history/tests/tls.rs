//! TLS to the history's PostgreSQL server, as the `--db` URL's `sslmode` asks, against a
//! real server (`ZEROCAL_TEST_POSTGRES`, the one `cargo xtask postgres start` runs with
//! TLS on; skipped without it, except under `CI=true`). Whether a connection is
//! encrypted is the server's word: `pg_stat_ssl` for the connection's own backend.
//!
//! The server's certificate authority is `target/postgres/ca.pem` (xtask's), or the
//! file `ZEROCAL_TEST_POSTGRES_CA` names.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[allow(dead_code)]
mod common;

use common::POSTGRES_ENV;
use std::path::PathBuf;
use zerocal_history::{postgres_connect, HistoryError};

/// The server's URL, or `None` (with a note) when no server is given.
fn server(test: &str) -> Option<String> {
    match std::env::var(POSTGRES_ENV) {
        Ok(url) if !url.is_empty() => Some(url),
        _ => {
            assert!(
                std::env::var("CI").as_deref() != Ok("true"),
                "CI=true but {POSTGRES_ENV} is unset: {test} would be skipped"
            );
            eprintln!("{test}: {POSTGRES_ENV} unset, PostgreSQL not tested");
            None
        }
    }
}

/// The test server's certificate authority (PEM).
fn ca_file() -> PathBuf {
    let file = std::env::var_os("ZEROCAL_TEST_POSTGRES_CA")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/postgres/ca.pem")
        });
    assert!(
        file.exists(),
        "{} is missing: `cargo xtask postgres start` writes it (or set ZEROCAL_TEST_POSTGRES_CA)",
        file.display()
    );
    file
}

/// A URL query value, percent-encoded.
fn encoded(value: &str) -> String {
    value
        .bytes()
        .map(|b| {
            if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
                (b as char).to_string()
            } else {
                format!("%{b:02X}")
            }
        })
        .collect()
}

/// `url` with `options` added to its query.
fn with(url: &str, options: &[(&str, &str)]) -> String {
    let query: Vec<String> = options
        .iter()
        .map(|(k, v)| format!("{k}={}", encoded(v)))
        .collect();
    let sep = if url.contains('?') { '&' } else { '?' };
    format!("{url}{sep}{}", query.join("&"))
}

/// Whether the server sees this connection encrypted.
fn encrypted(url: &str) -> Result<bool, HistoryError> {
    let mut c = postgres_connect(url)?;
    let row = c
        .query_one(
            "SELECT ssl FROM pg_stat_ssl WHERE pid = pg_backend_pid()",
            &[],
        )
        .unwrap();
    Ok(row.get(0))
}

#[test]
fn require_and_the_default_prefer_connect_over_tls_and_disable_is_plain() {
    let Some(url) = server("tls_modes") else {
        return;
    };
    assert!(!url.contains("sslmode"), "the test server's URL: {url}");
    assert!(encrypted(&url).unwrap(), "prefer (the default): {url}");
    for (mode, tls) in [("require", true), ("prefer", true), ("disable", false)] {
        let url = with(&url, &[("sslmode", mode)]);
        assert_eq!(encrypted(&url).unwrap(), tls, "{url}");
    }
}

#[test]
fn verify_full_and_verify_ca_connect_with_the_servers_authority() {
    let Some(url) = server("tls_verify") else {
        return;
    };
    let ca = ca_file();
    for mode in ["verify-full", "verify-ca", "require"] {
        let url = with(
            &url,
            &[("sslmode", mode), ("sslrootcert", ca.to_str().unwrap())],
        );
        assert!(encrypted(&url).unwrap(), "{url}");
    }
}

#[test]
fn another_authority_is_refused_by_name() {
    let Some(url) = server("tls_wrong_ca") else {
        return;
    };
    // An authority of its own, which never signed the server's certificate.
    let key = rcgen::KeyPair::generate().unwrap();
    let mut params = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
    params.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, "another CA");
    let other = params.self_signed(&key).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("other-ca.pem");
    std::fs::write(&file, other.pem()).unwrap();
    // require with a root file checks the chain too (libpq's rule).
    for mode in ["verify-full", "verify-ca", "require"] {
        let url = with(
            &url,
            &[("sslmode", mode), ("sslrootcert", file.to_str().unwrap())],
        );
        match postgres_connect(&url) {
            Err(HistoryError::Tls(m)) => assert!(
                m.contains("not trusted")
                    && m.contains("unknown certificate authority")
                    && m.contains("other-ca.pem")
                    && m.contains(mode),
                "{mode}: {m}"
            ),
            Err(e) => panic!("{mode}: refused, but not as a TLS trust problem: {e}"),
            Ok(_) => panic!("{mode}: connected with an authority that signed nothing"),
        }
    }
}

/// PostgreSQL never offers TLS over a Unix socket: `require` there is refused, naming
/// why, and `prefer` connects plain.
#[test]
fn require_without_tls_offered_is_refused_by_name() {
    let Some(url) = server("tls_not_offered") else {
        return;
    };
    let config: postgres::Config = url.parse().unwrap();
    let port = config
        .get_ports()
        .first()
        .copied()
        .unwrap_or(5432)
        .to_string();
    let socket = ca_file().parent().unwrap().join("socket");
    let local = with(
        "postgresql://postgres@/zerocal_test",
        &[("host", socket.to_str().unwrap()), ("port", &port)],
    );
    assert!(!encrypted(&local).unwrap(), "{local}");
    let required = with(&local, &[("sslmode", "require")]);
    match postgres_connect(&required) {
        Err(HistoryError::Tls(m)) => assert!(
            m.contains("does not offer TLS") && m.contains("sslmode=require"),
            "{m}"
        ),
        Err(e) => panic!("refused, but not for the missing TLS: {e}"),
        Ok(_) => panic!("require connected over a Unix socket"),
    }
}
