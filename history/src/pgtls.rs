//! TLS to a PostgreSQL history server, through rustls (no OpenSSL), as libpq's `sslmode`
//! and `sslrootcert` in the `--db` URL ask (PostgreSQL documentation, "SSL Support",
//! "Protection Provided in Different Modes"):
//!
//! - `disable`: no TLS.
//! - `prefer` (the default): TLS when the server offers it, else plain.
//! - `require`: TLS, or no connection.
//! - `verify-ca`: TLS, the server's certificate chaining to a trusted root.
//! - `verify-full`: as `verify-ca`, and the certificate names the host connected to.
//!
//! The trusted roots are those of `sslrootcert=FILE` (PEM), else libpq's default file
//! `~/.postgresql/root.crt`; `sslrootcert=system` is the operating system's store (read by
//! rustls-native-certs) and, as for libpq, makes `verify-full` the default and refuses a
//! weaker mode. As libpq, `prefer` and `require` check the certificate's chain (as
//! `verify-ca`) when a root file is given or the default one exists, and otherwise only
//! encrypt: they then protect against a listener, not against an impostor.
//!
//! tokio-postgres (under the `postgres` client) parses `sslmode` itself but knows only
//! `disable`, `prefer` and `require`: the two are taken out of the URL here, the client
//! is told the transport (`verify-*` is its `require`) and the verification is the
//! rustls configuration's. `allow` (plain first, TLS on refusal) has no counterpart in
//! the client and is refused by name rather than taken as another mode.

use crate::HistoryError;
use rustls::client::danger::{HandshakeSignatureValid, ServerCertVerified, ServerCertVerifier};
use rustls::client::WebPkiServerVerifier;
use rustls::crypto::CryptoProvider;
use rustls::pki_types::pem::PemObject;
use rustls::pki_types::{CertificateDer, ServerName, UnixTime};
use rustls::{CertificateError, DigitallySignedStruct, RootCertStore, SignatureScheme};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// libpq's `sslmode`, all five that zerocal honours.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SslMode {
    /// No TLS.
    Disable,
    /// TLS when the server offers it, else plain.
    Prefer,
    /// TLS or nothing.
    Require,
    /// TLS, the certificate chaining to a trusted root.
    VerifyCa,
    /// TLS, the certificate chaining to a trusted root and naming the host.
    VerifyFull,
}

impl SslMode {
    fn parse(value: &str) -> Result<SslMode, HistoryError> {
        Ok(match value {
            "disable" => Self::Disable,
            "prefer" => Self::Prefer,
            "require" => Self::Require,
            "verify-ca" => Self::VerifyCa,
            "verify-full" => Self::VerifyFull,
            "allow" => {
                return Err(HistoryError::BadLocation(
                    "sslmode=allow (plain first, TLS only if the server refuses plain) is not supported: use prefer (TLS when offered), require, verify-ca or verify-full (docs/history.md)".into(),
                ))
            }
            other => {
                return Err(HistoryError::BadLocation(format!(
                    "sslmode={other} is not one of disable, prefer, require, verify-ca, verify-full"
                )))
            }
        })
    }

    /// The URL's spelling.
    #[must_use]
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Disable => "disable",
            Self::Prefer => "prefer",
            Self::Require => "require",
            Self::VerifyCa => "verify-ca",
            Self::VerifyFull => "verify-full",
        }
    }

    /// What the client's handshake is told: whether TLS may be skipped.
    fn transport(self) -> postgres::config::SslMode {
        match self {
            Self::Disable => postgres::config::SslMode::Disable,
            Self::Prefer => postgres::config::SslMode::Prefer,
            Self::Require | Self::VerifyCa | Self::VerifyFull => postgres::config::SslMode::Require,
        }
    }
}

/// Where the trusted roots come from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Roots {
    /// A PEM file (`sslrootcert=FILE`, or libpq's default file when it exists).
    File(PathBuf),
    /// The operating system's store (`sslrootcert=system`).
    System,
    /// None given and no default file.
    None,
}

/// The URL's TLS settings.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Tls {
    pub mode: SslMode,
    pub roots: Roots,
}

/// libpq's default root file, under the home directory.
const DEFAULT_ROOT_FILE: [&str; 2] = [".postgresql", "root.crt"];

/// libpq's environment defaults for TLS (`PGSSLMODE`, `PGSSLROOTCERT`): each applies
/// where the URL does not name its option, as libpq takes them.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(crate) struct TlsEnvironment {
    pub sslmode: Option<String>,
    pub sslrootcert: Option<String>,
}

impl TlsEnvironment {
    /// The process's `PGSSLMODE` and `PGSSLROOTCERT` (an empty one is unset).
    pub(crate) fn from_process() -> Self {
        let var = |name| std::env::var(name).ok().filter(|v| !v.is_empty());
        Self {
            sslmode: var("PGSSLMODE"),
            sslrootcert: var("PGSSLROOTCERT"),
        }
    }
}

/// `url` without its `sslmode` and `sslrootcert`, and the TLS they ask for (`home`: the
/// home directory, where libpq's default root file is; `env`: `PGSSLMODE` and
/// `PGSSLROOTCERT`, for the options the URL does not name). A connection string that
/// is not a URL is left to the client, which knows `sslmode` up to `require`: there
/// the environment's TLS options are refused, not silently dropped.
///
/// # Errors
/// An `sslmode` that is not libpq's or is `allow`; a mode below `verify-full` with
/// `sslrootcert=system`; `verify-ca` or `verify-full` without any root certificate;
/// `PGSSLMODE` or `PGSSLROOTCERT` beside a connection string that is not a URL.
pub(crate) fn split_url(
    url: &str,
    home: Option<&Path>,
    env: &TlsEnvironment,
) -> Result<(String, Tls), HistoryError> {
    let default_file = home
        .map(|h| {
            DEFAULT_ROOT_FILE
                .iter()
                .fold(h.to_path_buf(), |p, c| p.join(c))
        })
        .filter(|f| f.exists());
    let is_url = url.starts_with("postgres://") || url.starts_with("postgresql://");
    let (base, query) = match url.split_once('?') {
        Some((b, q)) if is_url => (b, q),
        None if is_url => (url, ""),
        _ if !is_url && (env.sslmode.is_some() || env.sslrootcert.is_some()) => {
            return Err(HistoryError::BadLocation(
                "PGSSLMODE or PGSSLROOTCERT is set, and --db is not a postgres:// URL: give sslmode and sslrootcert in a URL (docs/history.md)".into(),
            ))
        }
        _ => {
            let mode = match url.parse::<postgres::Config>()?.get_ssl_mode() {
                postgres::config::SslMode::Disable => SslMode::Disable,
                postgres::config::SslMode::Require => SslMode::Require,
                _ => SslMode::Prefer,
            };
            let roots = default_file.map_or(Roots::None, Roots::File);
            return Ok((url.to_owned(), Tls { mode, roots }));
        }
    };
    let mut mode = None;
    let mut root = None;
    let mut kept = Vec::new();
    for pair in query.split('&').filter(|p| !p.is_empty()) {
        let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
        match percent_decoded(key).as_str() {
            "sslmode" => mode = Some(SslMode::parse(&percent_decoded(value))?),
            "sslrootcert" => root = Some(percent_decoded(value)),
            key @ ("sslcert" | "sslkey" | "sslpassword" | "sslcrl" | "sslcrldir") => {
                return Err(HistoryError::BadLocation(format!(
                    "{key} is not supported: zerocal presents no client certificate and reads no revocation list (docs/history.md)"
                )))
            }
            _ => kept.push(pair),
        }
    }
    // The URL's own options win; the environment's fill in what it does not name.
    if mode.is_none() {
        if let Some(m) = &env.sslmode {
            mode = Some(SslMode::parse(m)?);
        }
    }
    let root = root.or_else(|| env.sslrootcert.clone());
    let roots =
        match root.as_deref() {
            Some("system") => Roots::System,
            Some("") => return Err(HistoryError::BadLocation(
                "sslrootcert is empty: give a PEM file of the trusted root certificates, or system"
                    .into(),
            )),
            Some(file) => Roots::File(PathBuf::from(file)),
            None => default_file.map_or(Roots::None, Roots::File),
        };
    let mode = match (mode, &roots) {
        (None, Roots::System) => SslMode::VerifyFull,
        (None, _) => SslMode::Prefer,
        (Some(m), Roots::System) if m != SslMode::VerifyFull => {
            return Err(HistoryError::BadLocation(format!(
                "sslmode={} with sslrootcert=system: the system's roots trust any public server's certificate, so only verify-full (which checks the host's name) is allowed, as for libpq",
                m.as_str()
            )))
        }
        (Some(m), _) => m,
    };
    if matches!(mode, SslMode::VerifyCa | SslMode::VerifyFull) && roots == Roots::None {
        return Err(HistoryError::BadLocation(format!(
            "sslmode={} needs the trusted root certificates: give sslrootcert=FILE (PEM) or sslrootcert=system, or put them in ~/.postgresql/root.crt",
            mode.as_str()
        )));
    }
    let url = if kept.is_empty() {
        base.to_owned()
    } else {
        format!("{base}?{}", kept.join("&"))
    };
    Ok((url, Tls { mode, roots }))
}

/// The options taken out of the URL here, not the client's.
const TLS_OPTIONS: [&str; 7] = [
    "sslmode",
    "sslrootcert",
    "sslcert",
    "sslkey",
    "sslpassword",
    "sslcrl",
    "sslcrldir",
];

/// `url` without the TLS options read here, whatever their values: what the client
/// parses to see the rest (a password in the URL is looked for there).
pub(crate) fn without_tls_options(url: &str) -> String {
    match url.split_once('?') {
        Some((base, query)) => {
            let kept: Vec<&str> = query
                .split('&')
                .filter(|pair| {
                    let key = pair.split_once('=').map_or(*pair, |(k, _)| k);
                    !TLS_OPTIONS.contains(&percent_decoded(key).as_str())
                })
                .collect();
            if kept.is_empty() {
                base.to_owned()
            } else {
                format!("{base}?{}", kept.join("&"))
            }
        }
        None => url.to_owned(),
    }
}

/// `s` with its `%XX` escapes decoded (as the client decodes a URL's query).
pub(crate) fn percent_decoded(s: &str) -> String {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = bytes
            .get(i + 1..i + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[i], hex) {
            (b'%', Some(b)) => {
                out.push(b);
                i += 3;
            }
            (b, _) => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

impl Tls {
    /// Sets the client's transport mode on `config`.
    pub(crate) fn apply(&self, config: &mut postgres::Config) {
        config.ssl_mode(self.mode.transport());
    }

    /// Where the roots come from, as an error names them.
    fn roots_named(&self) -> String {
        match &self.roots {
            Roots::File(f) => format!("the root certificates in {}", f.display()),
            Roots::System => "the system's trusted root certificates".into(),
            Roots::None => "no root certificate".into(),
        }
    }

    /// The rustls configuration: verifying as the mode and roots ask.
    ///
    /// # Errors
    /// The root file unreadable or holding no certificate; the system's store empty.
    pub(crate) fn client_config(&self) -> Result<rustls::ClientConfig, HistoryError> {
        let provider = Arc::new(rustls::crypto::ring::default_provider());
        let builder = rustls::ClientConfig::builder_with_provider(provider.clone())
            .with_safe_default_protocol_versions()
            .map_err(|e| HistoryError::Tls(format!("rustls: {e}")))?;
        Ok(builder
            .dangerous()
            .with_custom_certificate_verifier(self.verifier(provider)?)
            .with_no_client_auth())
    }

    /// What checks the server's certificate: the chain and the name (`verify-full`),
    /// the chain alone (`verify-ca`, and `prefer` or `require` with roots), nothing but
    /// the handshake's signatures (`prefer` or `require` without roots).
    fn verifier(
        &self,
        provider: Arc<CryptoProvider>,
    ) -> Result<Arc<dyn ServerCertVerifier>, HistoryError> {
        Ok(match (&self.roots, self.mode) {
            // Verification asked for with nothing to verify against: never encryption
            // alone in its place (split_url refuses this first; this holds it here too).
            (Roots::None, SslMode::VerifyCa | SslMode::VerifyFull) => {
                return Err(HistoryError::Tls(format!(
                    "sslmode={} needs the trusted root certificates, and none are given",
                    self.mode.as_str()
                )))
            }
            (Roots::None, _) => Arc::new(EncryptOnly(provider)),
            (roots, mode) => {
                let store = Arc::new(root_store(roots)?);
                let webpki = WebPkiServerVerifier::builder_with_provider(store, provider)
                    .build()
                    .map_err(|e| HistoryError::Tls(format!("{}: {e}", self.roots_named())))?;
                if mode == SslMode::VerifyFull {
                    webpki
                } else {
                    Arc::new(ChainOnly(webpki))
                }
            }
        })
    }

    /// The client's error, said as a TLS problem where it is one: a certificate not
    /// trusted, the server offering no TLS under a mode that asks for it.
    pub(crate) fn error(&self, e: postgres::Error) -> HistoryError {
        if let Some(rustls::Error::InvalidCertificate(c)) = rustls_cause(&e) {
            let why = match c {
                CertificateError::UnknownIssuer => {
                    "it is not signed by any of them (an unknown certificate authority)".to_owned()
                }
                CertificateError::NotValidForName
                | CertificateError::NotValidForNameContext { .. } => {
                    "it does not name the host connected to (verify-ca checks the chain alone)"
                        .to_owned()
                }
                CertificateError::Expired | CertificateError::ExpiredContext { .. } => {
                    "it has expired".to_owned()
                }
                other => format!("{other:?}"),
            };
            return HistoryError::Tls(format!(
                "the server's certificate is not trusted under sslmode={} with {}: {why}",
                self.mode.as_str(),
                self.roots_named()
            ));
        }
        let text = std::error::Error::source(&e).map(ToString::to_string);
        if text.as_deref() == Some("server does not support TLS") {
            return HistoryError::Tls(format!(
                "the server does not offer TLS and sslmode={} asks for it (over a Unix socket PostgreSQL never offers it)",
                self.mode.as_str()
            ));
        }
        HistoryError::Postgres(e)
    }
}

/// The rustls error somewhere in `e`'s causes (tokio-rustls wraps it in an I/O error).
fn rustls_cause(e: &postgres::Error) -> Option<&rustls::Error> {
    let mut cause: Option<&(dyn std::error::Error + 'static)> = std::error::Error::source(e);
    while let Some(c) = cause {
        if let Some(r) = c.downcast_ref::<rustls::Error>() {
            return Some(r);
        }
        if let Some(r) = c
            .downcast_ref::<std::io::Error>()
            .and_then(|io| io.get_ref())
            .and_then(|inner| inner.downcast_ref::<rustls::Error>())
        {
            return Some(r);
        }
        cause = c.source();
    }
    None
}

/// The trusted roots of `roots`.
fn root_store(roots: &Roots) -> Result<RootCertStore, HistoryError> {
    let mut store = RootCertStore::empty();
    match roots {
        Roots::File(file) => {
            let named = |why: String| {
                HistoryError::Tls(format!(
                    "the root certificate file {}: {why}",
                    file.display()
                ))
            };
            let certs = CertificateDer::pem_file_iter(file)
                .map_err(|e| named(e.to_string()))?
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| named(e.to_string()))?;
            if certs.is_empty() {
                return Err(named("holds no PEM certificate".into()));
            }
            for cert in certs {
                store
                    .add(cert)
                    .map_err(|e| named(format!("a certificate that does not read: {e}")))?;
            }
        }
        Roots::System => {
            let found = rustls_native_certs::load_native_certs();
            let (added, _ignored) = store.add_parsable_certificates(found.certs);
            if added == 0 {
                let errors: Vec<String> = found.errors.iter().map(ToString::to_string).collect();
                return Err(HistoryError::Tls(format!(
                    "sslrootcert=system: the system holds no trusted root certificate that reads ({})",
                    errors.join("; ")
                )));
            }
        }
        Roots::None => {}
    }
    Ok(store)
}

/// `verify-ca`: the chain must reach a trusted root; the name is not checked.
#[derive(Debug)]
struct ChainOnly(Arc<WebPkiServerVerifier>);

impl ServerCertVerifier for ChainOnly {
    fn verify_server_cert(
        &self,
        end_entity: &CertificateDer<'_>,
        intermediates: &[CertificateDer<'_>],
        server_name: &ServerName<'_>,
        ocsp_response: &[u8],
        now: UnixTime,
    ) -> Result<ServerCertVerified, rustls::Error> {
        // webpki checks the chain first and the name last: a wrong name is the only
        // error left once the chain has been accepted.
        match self
            .0
            .verify_server_cert(end_entity, intermediates, server_name, ocsp_response, now)
        {
            Err(rustls::Error::InvalidCertificate(
                CertificateError::NotValidForName | CertificateError::NotValidForNameContext { .. },
            )) => Ok(ServerCertVerified::assertion()),
            other => other,
        }
    }

    fn verify_tls12_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        self.0.verify_tls12_signature(message, cert, dss)
    }

    fn verify_tls13_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        self.0.verify_tls13_signature(message, cert, dss)
    }

    fn supported_verify_schemes(&self) -> Vec<SignatureScheme> {
        self.0.supported_verify_schemes()
    }
}

/// `prefer` and `require` without a root certificate (libpq's): any certificate is
/// taken, the handshake's signatures are still checked (the key is the certificate's).
#[derive(Debug)]
struct EncryptOnly(Arc<CryptoProvider>);

impl ServerCertVerifier for EncryptOnly {
    fn verify_server_cert(
        &self,
        _end_entity: &CertificateDer<'_>,
        _intermediates: &[CertificateDer<'_>],
        _server_name: &ServerName<'_>,
        _ocsp_response: &[u8],
        _now: UnixTime,
    ) -> Result<ServerCertVerified, rustls::Error> {
        Ok(ServerCertVerified::assertion())
    }

    fn verify_tls12_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        rustls::crypto::verify_tls12_signature(
            message,
            cert,
            dss,
            &self.0.signature_verification_algorithms,
        )
    }

    fn verify_tls13_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        rustls::crypto::verify_tls13_signature(
            message,
            cert,
            dss,
            &self.0.signature_verification_algorithms,
        )
    }

    fn supported_verify_schemes(&self) -> Vec<SignatureScheme> {
        self.0.signature_verification_algorithms.supported_schemes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn split(url: &str) -> Result<(String, Tls), HistoryError> {
        split_url(url, None, &TlsEnvironment::default())
    }

    #[test]
    fn the_environment_fills_in_what_the_url_does_not_name() {
        let env = TlsEnvironment {
            sslmode: Some("verify-full".into()),
            sslrootcert: Some("/etc/plant/ca.pem".into()),
        };
        let (_, tls) = split_url("postgres://zc@db/z", None, &env).unwrap();
        assert_eq!(tls.mode, SslMode::VerifyFull);
        assert_eq!(tls.roots, Roots::File(PathBuf::from("/etc/plant/ca.pem")));
        // The URL's own option wins over the environment's.
        let (_, tls) = split_url("postgres://zc@db/z?sslmode=require", None, &env).unwrap();
        assert_eq!(tls.mode, SslMode::Require);
        // A mode the environment asks for that needs roots it does not give is refused.
        let bare = TlsEnvironment {
            sslmode: Some("verify-ca".into()),
            sslrootcert: None,
        };
        assert!(split_url("postgres://zc@db/z", None, &bare).is_err());
        // Beside a key=value string the client would drop them: refused by name.
        let e = split_url("host=db user=zc", None, &env).unwrap_err();
        assert!(e.to_string().contains("PGSSLMODE"), "{e}");
    }

    #[test]
    fn sslmode_and_sslrootcert_leave_the_url_and_other_options_stay() {
        let (url, tls) = split(
            "postgresql://zc@db.plant/zerocal?connect_timeout=10&sslmode=verify-full&sslrootcert=%2Fetc%2Fplant-ca.pem",
        )
        .unwrap();
        assert_eq!(url, "postgresql://zc@db.plant/zerocal?connect_timeout=10");
        assert_eq!(
            tls,
            Tls {
                mode: SslMode::VerifyFull,
                roots: Roots::File("/etc/plant-ca.pem".into())
            }
        );
        let (url, tls) = split("postgres://zc@db/zerocal?sslmode=require").unwrap();
        assert_eq!(
            (url.as_str(), tls.mode, tls.roots),
            ("postgres://zc@db/zerocal", SslMode::Require, Roots::None)
        );
        // The client's own check of what is left still applies.
        assert!(url.parse::<postgres::Config>().is_ok());
    }

    /// libpq's defaults: prefer; verify-full with the system's roots.
    #[test]
    fn the_default_mode_is_prefer_and_verify_full_with_system_roots() {
        assert_eq!(
            split("postgres://zc@db/zerocal").unwrap().1.mode,
            SslMode::Prefer
        );
        assert_eq!(
            split("postgres://zc@db/zerocal?sslrootcert=system")
                .unwrap()
                .1,
            Tls {
                mode: SslMode::VerifyFull,
                roots: Roots::System
            }
        );
    }

    #[test]
    fn what_cannot_be_honoured_is_refused_by_name() {
        for (url, named) in [
            ("postgres://zc@db/z?sslmode=allow", "sslmode=allow"),
            ("postgres://zc@db/z?sslmode=verify", "sslmode=verify"),
            (
                "postgres://zc@db/z?sslmode=require&sslrootcert=system",
                "only verify-full",
            ),
            ("postgres://zc@db/z?sslmode=verify-ca", "sslrootcert=FILE"),
            ("postgres://zc@db/z?sslmode=verify-full", "sslrootcert=FILE"),
            ("postgres://zc@db/z?sslrootcert=", "sslrootcert is empty"),
            (
                "postgres://zc@db/z?sslcert=me.crt",
                "sslcert is not supported",
            ),
        ] {
            let e = split(url).map(|(_, t)| t);
            assert!(
                matches!(&e, Err(HistoryError::BadLocation(m)) if m.contains(named)),
                "{url}: {e:?}"
            );
        }
    }

    /// libpq reads `~/.postgresql/root.crt` when no `sslrootcert` is given.
    #[test]
    fn the_default_root_file_is_used_when_it_exists() {
        let home = tempfile::tempdir().unwrap();
        let url = "postgres://zc@db/zerocal?sslmode=verify-ca";
        assert!(split_url(url, Some(home.path()), &TlsEnvironment::default()).is_err());
        std::fs::create_dir(home.path().join(".postgresql")).unwrap();
        let file = home.path().join(".postgresql").join("root.crt");
        std::fs::write(&file, "").unwrap();
        assert_eq!(
            split_url(url, Some(home.path()), &TlsEnvironment::default())
                .unwrap()
                .1
                .roots,
            Roots::File(file)
        );
    }

    #[test]
    fn a_root_file_without_a_certificate_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("ca.pem");
        std::fs::write(&file, "not a certificate\n").unwrap();
        let e = root_store(&Roots::File(file.clone()))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("holds no PEM certificate") && e.contains("ca.pem"),
            "{e}"
        );
        let e = root_store(&Roots::File(dir.path().join("absent.pem")))
            .unwrap_err()
            .to_string();
        assert!(e.contains("absent.pem"), "{e}");
    }

    /// A certificate authority's PEM file in `dir` and a certificate it signed for
    /// `127.0.0.1`.
    fn authority(dir: &Path, name: &str) -> (PathBuf, CertificateDer<'static>) {
        let ca_key = rcgen::KeyPair::generate().unwrap();
        let mut ca = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
        ca.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
        ca.distinguished_name.push(rcgen::DnType::CommonName, name);
        let ca_cert = ca.self_signed(&ca_key).unwrap();
        let issuer = rcgen::Issuer::new(ca, ca_key);
        let key = rcgen::KeyPair::generate().unwrap();
        let server = rcgen::CertificateParams::new(vec!["127.0.0.1".to_owned()])
            .unwrap()
            .signed_by(&key, &issuer)
            .unwrap();
        let file = dir.join(format!("{name}.pem"));
        std::fs::write(&file, ca_cert.pem()).unwrap();
        (file, server.der().clone())
    }

    /// What each mode accepts of a certificate for `127.0.0.1`, reached as
    /// `127.0.0.1` and as `localhost`, signed by the trusted authority or another.
    #[test]
    fn verify_full_checks_the_name_verify_ca_the_chain_alone() {
        let dir = tempfile::tempdir().unwrap();
        let (trusted, ours) = authority(dir.path(), "trusted");
        let (_, theirs) = authority(dir.path(), "other");
        let provider = Arc::new(rustls::crypto::ring::default_provider());
        let accepts = |mode, cert: &CertificateDer<'_>, host: &str| {
            let tls = Tls {
                mode,
                roots: Roots::File(trusted.clone()),
            };
            let name = ServerName::try_from(host.to_owned()).unwrap();
            tls.verifier(provider.clone())
                .unwrap()
                .verify_server_cert(cert, &[], &name, &[], UnixTime::now())
                .map(|_| ())
        };
        let not_for_name = |r: Result<(), rustls::Error>| {
            matches!(
                r,
                Err(rustls::Error::InvalidCertificate(
                    CertificateError::NotValidForName
                        | CertificateError::NotValidForNameContext { .. }
                ))
            )
        };
        let unknown = |r: Result<(), rustls::Error>| {
            r == Err(rustls::Error::InvalidCertificate(
                CertificateError::UnknownIssuer,
            ))
        };
        assert_eq!(accepts(SslMode::VerifyFull, &ours, "127.0.0.1"), Ok(()));
        assert!(not_for_name(accepts(
            SslMode::VerifyFull,
            &ours,
            "localhost"
        )));
        for mode in [SslMode::VerifyCa, SslMode::Require, SslMode::Prefer] {
            assert_eq!(accepts(mode, &ours, "localhost"), Ok(()), "{mode:?}");
        }
        for mode in [SslMode::VerifyFull, SslMode::VerifyCa, SslMode::Require] {
            assert!(unknown(accepts(mode, &theirs, "127.0.0.1")), "{mode:?}");
        }
        // Without roots (libpq's prefer and require): encryption only.
        let bare = Tls {
            mode: SslMode::Require,
            roots: Roots::None,
        };
        let name = ServerName::try_from("localhost").unwrap();
        assert!(bare
            .verifier(provider.clone())
            .unwrap()
            .verify_server_cert(&theirs, &[], &name, &[], UnixTime::now())
            .is_ok());
    }

    #[test]
    fn percent_escapes_are_decoded_and_a_stray_percent_kept() {
        assert_eq!(percent_decoded("%2Fa%2fb%"), "/a/b%");
        assert_eq!(percent_decoded("ssl%6Dode"), "sslmode");
    }
}
