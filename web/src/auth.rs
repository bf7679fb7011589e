//! Who is signed in: passwords (Argon2id, memory-hard), the session cookie (a random
//! ID whose SHA-256 alone is stored), the CSRF token each form carries, the roles each
//! action needs, and the limit on failed sign-ins. All of it in the database.

use crate::{with_history, Shared, WebError};
use argon2::password_hash::{PasswordHash, PasswordHasher, PasswordVerifier, SaltString};
use argon2::Argon2;
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Redirect, Response};
use zerocal_history::{sha256_hex, Role, WebSession};

/// The cookie that carries the session's ID.
pub const COOKIE: &str = "zerocal_session";

/// How long a sign-in lasts: one shift (8 h), after which the user signs in again.
pub const SESSION_SECONDS: i64 = 8 * 3600;

/// Failed sign-ins of one user name within [`LOGIN_WINDOW_SECONDS`] after which its
/// sign-in is refused (its password not even tried) until the window has passed: five,
/// OWASP's Authentication Cheat Sheet's order of a lockout threshold.
pub const MAX_FAILED_LOGINS: i64 = 5;

/// The window [`MAX_FAILED_LOGINS`] counts in: 15 minutes.
pub const LOGIN_WINDOW_SECONDS: i64 = 15 * 60;

/// Now, in unix seconds.
pub(crate) fn now_unix() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// `n` random bytes from the operating system, as lowercase hex.
pub(crate) fn random_hex(n: usize) -> Result<String, WebError> {
    let mut bytes = vec![0_u8; n];
    getrandom::fill(&mut bytes).map_err(|e| {
        WebError(
            StatusCode::INTERNAL_SERVER_ERROR,
            format!("no random source: {e}"),
        )
    })?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// The Argon2id PHC string of `password` with a fresh random salt (the crate's
/// default parameters: 19 MiB, 2 passes, OWASP's Password Storage Cheat Sheet's).
///
/// # Errors
/// An empty password; no random source.
pub fn hash_password(password: &str) -> Result<String, String> {
    if password.is_empty() {
        return Err("the password is empty".into());
    }
    let mut salt = [0_u8; 16];
    getrandom::fill(&mut salt).map_err(|e| format!("no random source: {e}"))?;
    let salt = SaltString::encode_b64(&salt).map_err(|e| e.to_string())?;
    Argon2::default()
        .hash_password(password.as_bytes(), &salt)
        .map(|h| h.to_string())
        .map_err(|e| e.to_string())
}

/// A hash no password is checked against but to spend an unknown user name's time
/// (made once, of random bytes nobody knows).
pub(crate) fn unknown_user_phc() -> &'static str {
    static PHC: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    PHC.get_or_init(|| {
        random_hex(32)
            .ok()
            .and_then(|p| hash_password(&p).ok())
            .unwrap_or_default()
    })
}

/// Whether `password` is the one `phc` was made from.
pub(crate) fn verify_password(password: &str, phc: &str) -> bool {
    PasswordHash::new(phc)
        .map(|h| {
            Argon2::default()
                .verify_password(password.as_bytes(), &h)
                .is_ok()
        })
        .unwrap_or(false)
}

/// The session ID in the request's cookie.
fn session_id(headers: &HeaderMap) -> Option<String> {
    headers
        .get_all(header::COOKIE)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(';'))
        .filter_map(|kv| kv.trim().split_once('='))
        .find(|(k, _)| *k == COOKIE)
        .map(|(_, v)| v.to_owned())
        .filter(|v| v.len() == 64 && v.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// The signed-in session of the request, if any.
pub(crate) async fn current(
    app: &Shared,
    headers: &HeaderMap,
) -> Result<Option<WebSession>, WebError> {
    let Some(id) = session_id(headers) else {
        return Ok(None);
    };
    let hash = sha256_hex(id.as_bytes());
    with_history(app, move |h| Ok(h.web_session(&hash, now_unix())?)).await
}

/// The session cookie's `Set-Cookie` value: HttpOnly (no script reads it),
/// SameSite=Strict (no other site's page sends it), Secure where served over TLS.
pub(crate) fn cookie(app: &Shared, id: &str, max_age: i64) -> String {
    let secure = if app.config.secure_cookies {
        "; Secure"
    } else {
        ""
    };
    format!("{COOKIE}={id}; Path=/; HttpOnly; SameSite=Strict; Max-Age={max_age}{secure}")
}

/// The session of the request's ID, hashed as stored, for signing out.
pub(crate) fn session_hash(headers: &HeaderMap) -> Option<String> {
    session_id(headers).map(|id| sha256_hex(id.as_bytes()))
}

/// A page for those signed in: without a session, to the sign-in page.
pub(crate) async fn page_session(
    app: &Shared,
    headers: &HeaderMap,
) -> Result<WebSession, Response> {
    match current(app, headers).await {
        Ok(Some(s)) => Ok(s),
        Ok(None) => Err(Redirect::to("/login").into_response()),
        Err(e) => Err(e.into_response()),
    }
}

/// An action: a session (401 without), the form's CSRF token equal to the session's
/// (403 without or wrong), and one of `roles` (403 otherwise). Nothing is done before
/// all three hold.
pub(crate) async fn action_session(
    app: &Shared,
    headers: &HeaderMap,
    csrf: Option<&str>,
    roles: &[Role],
) -> Result<WebSession, WebError> {
    let s = current(app, headers).await?.ok_or_else(|| {
        WebError(
            StatusCode::UNAUTHORIZED,
            "not signed in: sign in at /login".into(),
        )
    })?;
    let given = csrf.unwrap_or_default();
    if !constant_time_eq(given.as_bytes(), s.csrf_token.as_bytes()) {
        return Err(WebError(
            StatusCode::FORBIDDEN,
            "the form's CSRF token is missing or wrong: reload the page and try again".into(),
        ));
    }
    if !roles.contains(&s.user.role) {
        return Err(WebError(
            StatusCode::FORBIDDEN,
            format!(
                "{} is a {}: this needs a {}",
                s.user.name,
                s.user.role.as_str(),
                roles
                    .iter()
                    .map(|r| r.as_str())
                    .collect::<Vec<_>>()
                    .join(" or ")
            ),
        ));
    }
    Ok(s)
}

/// `a == b` in a time that does not depend on where they differ.
fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0_u8, |d, (x, y)| d | (x ^ y)) == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_password_verifies_against_its_hash_only() {
        let phc = hash_password("correct horse").unwrap();
        assert!(phc.starts_with("$argon2id$"), "{phc}");
        assert!(verify_password("correct horse", &phc));
        assert!(!verify_password("correct hors", &phc));
        assert!(!verify_password("correct horse", "not a hash"));
        assert!(hash_password("").is_err());
        // A fresh salt each time.
        assert_ne!(phc, hash_password("correct horse").unwrap());
    }

    #[test]
    fn the_session_id_is_read_from_its_cookie_only() {
        let id = "ab".repeat(32);
        let mut h = HeaderMap::new();
        h.insert(
            header::COOKIE,
            format!("other=1; {COOKIE}={id}").parse().unwrap(),
        );
        assert_eq!(session_id(&h).as_deref(), Some(id.as_str()));
        h.insert(
            header::COOKIE,
            format!("{COOKIE}=' OR 1=1 --").parse().unwrap(),
        );
        assert_eq!(session_id(&h), None);
        assert!(constant_time_eq(b"abc", b"abc"));
        assert!(!constant_time_eq(b"abc", b"abd"));
        assert!(!constant_time_eq(b"abc", b"ab"));
    }
}
