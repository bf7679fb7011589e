//! zerocal's web application over the calibration history (`zerocal serve`): the
//! fleet at a glance, each robot's records and plots, the upload of a pendant export,
//! the review and signature of a session (measured → checked → authorized), the
//! accounts and the audit log.
//!
//! All of its state (accounts, signed-in sessions, CSRF tokens, login attempts,
//! signatures, audit) is in the history database (`zerocal_history`, schema 5), none
//! only in memory: several servers over one database serve the same users. The
//! history's API is synchronous; each request opens the history in
//! `tokio::task::spawn_blocking`.
//!
//! What only the CLI knows (solving an export as `zerocal session --record` does,
//! a record's certificate, a robot's plots) comes in through [`Product`], so that this
//! crate does not depend on the CLI (which depends on it for `zerocal serve`).
//! See `docs/web.md`.

mod auth;
mod fleet_view;
mod pages;
mod pdf;
mod review_pages;
mod templates;

pub use auth::{hash_password, LOGIN_WINDOW_SECONDS, MAX_FAILED_LOGINS, SESSION_SECONDS};
pub use fleet_view::{FleetQuery, FleetRow, Intervals};

use axum::extract::DefaultBodyLimit;
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::Router;
use std::sync::Arc;
use zerocal_history::{DbLocation, History, HistoryError, NewRecord, Record};

/// What the CLI supplies: the code that solves and renders as `zerocal` does.
pub trait Product: Send + Sync + 'static {
    /// Solves the pendant export `export` as `zerocal session --record --serial SERIAL
    /// --operator OPERATOR` does and gives the record it would store.
    ///
    /// # Errors
    /// The export is malformed, of a check, or the solver refuses it: the message says
    /// why, as the CLI's does.
    fn solve_export(
        &self,
        export: &[u8],
        serial: &str,
        operator: &str,
    ) -> Result<NewRecord, String>;

    /// The certificate (HTML document) of the session `record`, issued in `history`
    /// as `zerocal certificate` issues it (the same number again once issued), a first
    /// issue audited as `by`'s in the same transaction and refused where `by` may not
    /// issue one.
    ///
    /// # Errors
    /// A record no certificate can be made of, no issuer configured, a first issue
    /// `by` may not make.
    fn certificate_html(
        &self,
        history: &mut History,
        record: &Record,
        by: zerocal_history::CertificateRequest<'_>,
    ) -> Result<String, String>;

    /// The robot's plots over time (each joint's zero and U, its reducers), each an SVG
    /// document, from its records in ID order.
    ///
    /// # Errors
    /// A plot that cannot be drawn.
    fn robot_plots_svg(&self, serial: &str, records: &[Record]) -> Result<Vec<String>, String>;

    /// What the robot's records say of its reducers (the fitted transmission error's
    /// harmonics grown beyond their uncertainty), one line each; empty when nothing
    /// grew or the records carry no fitted transmission error.
    fn reducer_notes(&self, records: &[Record]) -> Vec<String>;
}

/// Room in an upload's body for what is not the export (the multipart boundaries and
/// headers, the serial, the CSRF token): the body limit is the export's limit plus this.
pub const MULTIPART_OVERHEAD_BYTES: usize = 16 * 1024;

/// How the server runs.
#[derive(Debug, Clone)]
pub struct Config {
    /// The history.
    pub db: DbLocation,
    /// Whether cookies are marked `Secure` (served over TLS, by a reverse proxy).
    pub secure_cookies: bool,
    /// The most bytes a request body may have (an upload's).
    pub max_upload_bytes: usize,
    /// The days between calibrations, the plant's and each robot model's: a robot is
    /// due this many days after its last session. None set: no due date is shown (the
    /// plant sets its intervals).
    pub intervals: Intervals,
    /// The Chromium that prints certificates to PDF; `None`: no PDF download (the
    /// page says so).
    pub chromium: Option<std::path::PathBuf>,
}

pub(crate) struct App {
    pub config: Config,
    pub product: Box<dyn Product>,
    pub templates: minijinja::Environment<'static>,
}

pub(crate) type Shared = Arc<App>;

/// A refusal or failure as the response says it: plain text, so nothing in it is
/// read as markup.
#[derive(Debug)]
pub(crate) struct WebError(pub StatusCode, pub String);

impl IntoResponse for WebError {
    fn into_response(self) -> Response {
        (
            self.0,
            [(header::CONTENT_TYPE, "text/plain; charset=utf-8")],
            self.1,
        )
            .into_response()
    }
}

impl From<HistoryError> for WebError {
    fn from(e: HistoryError) -> Self {
        let status = match e {
            HistoryError::NoSuchRecord(_) => StatusCode::NOT_FOUND,
            HistoryError::Refused(_)
            | HistoryError::InvalidRecord(_)
            | HistoryError::AnotherRobot { .. } => StatusCode::UNPROCESSABLE_ENTITY,
            _ => StatusCode::INTERNAL_SERVER_ERROR,
        };
        WebError(status, format!("history: {e}"))
    }
}

/// Runs `work` on the history in a blocking thread (the history is synchronous),
/// opening it for this request.
pub(crate) async fn with_history<T: Send + 'static>(
    app: &Shared,
    work: impl FnOnce(&mut History) -> Result<T, WebError> + Send + 'static,
) -> Result<T, WebError> {
    let at = app.config.db.clone();
    tokio::task::spawn_blocking(move || {
        let mut history = History::open(&at)?;
        work(&mut history)
    })
    .await
    .map_err(|e| WebError(StatusCode::INTERNAL_SERVER_ERROR, format!("worker: {e}")))?
}

/// Headers every response carries: no framing, no sniffing, and a content policy
/// that runs no script at all (the pages have none) and loads only this server's
/// images and styles.
async fn security_headers(req: axum::extract::Request, next: axum::middleware::Next) -> Response {
    let mut res = next.run(req).await;
    let h = res.headers_mut();
    h.insert(
        header::CONTENT_SECURITY_POLICY,
        HeaderValue::from_static(
            "default-src 'none'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; \
             form-action 'self'; frame-ancestors 'none'; base-uri 'none'",
        ),
    );
    h.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    h.insert(
        header::REFERRER_POLICY,
        HeaderValue::from_static("no-referrer"),
    );
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

/// Refuses a form sent from another site (403, nothing done): the browser says where a
/// request comes from in `Sec-Fetch-Site` (every current browser) and `Origin`. The
/// session cookie is `SameSite=Strict`, so another site's form carries no session; this
/// also stops one that signs the victim in as the attacker (login CSRF), which needs no
/// session. Without `Sec-Fetch-Site` (an older browser) `Origin` must name this host
/// (a proxy must pass `Host` on: docs/web.md); a request with neither (a script)
/// passes to the CSRF token and the session like any other.
async fn same_site_forms(req: axum::extract::Request, next: axum::middleware::Next) -> Response {
    if req.method() == axum::http::Method::POST {
        let headers = req.headers();
        let fetch_site = headers.get("sec-fetch-site").and_then(|v| v.to_str().ok());
        // HTTP/2 carries the host as the request's authority, not a `Host` header.
        let authority = req.uri().authority().map(|a| a.as_str().to_owned());
        let host = headers
            .get(header::HOST)
            .and_then(|v| v.to_str().ok())
            .map(str::to_owned)
            .or(authority);
        let origin_host = headers
            .get(header::ORIGIN)
            .and_then(|v| v.to_str().ok())
            .map(|o| o.split_once("://").map_or(o, |(_, rest)| rest));
        // The browser's own word first: a proxy may rewrite `Host`, never it.
        let cross_site = match (fetch_site, origin_host, host) {
            (Some(site), _, _) => site != "same-origin" && site != "none",
            (None, Some("null"), _) => true,
            (None, Some(o), Some(h)) => !o.eq_ignore_ascii_case(&h),
            // An origin but no host to compare it with: not this site's own form.
            (None, Some(_), None) => true,
            (None, None, _) => false,
        };
        if cross_site {
            return WebError(
                StatusCode::FORBIDDEN,
                "a form sent from another site: open this server's own page and send it from there"
                    .into(),
            )
            .into_response();
        }
    }
    next.run(req).await
}

/// The application's routes over `config`'s history, with `product` solving and
/// rendering as the CLI does.
///
/// # Errors
/// A template that does not compile (a build error, caught by every test).
pub fn router(config: Config, product: Box<dyn Product>) -> Result<Router, String> {
    let limit = config.max_upload_bytes;
    let app: Shared = Arc::new(App {
        config,
        product,
        templates: templates::environment()?,
    });
    Ok(Router::new()
        .route("/", get(pages::home))
        .route("/login", get(pages::login_form).post(pages::login))
        .route("/logout", post(pages::logout))
        .route("/fleet", get(pages::fleet))
        .route("/robot/{serial}", get(pages::robot))
        .route("/robot/{serial}/plot/{index}", get(pages::robot_plot))
        .route("/upload", get(pages::upload_form).post(pages::upload))
        .route("/record/{id}", get(review_pages::record))
        .route(
            "/record/{id}/certificate",
            get(review_pages::certificate).post(review_pages::issue_certificate),
        )
        .route(
            "/record/{id}/certificate.pdf",
            get(review_pages::certificate_pdf),
        )
        .route("/record/{id}/sign", post(review_pages::sign))
        .route(
            "/admin/users",
            get(review_pages::users).post(review_pages::add_user),
        )
        .route("/admin/users/{name}", post(review_pages::set_user))
        .route("/audit", get(review_pages::audit))
        .layer(DefaultBodyLimit::max(limit))
        .layer(axum::middleware::from_fn(same_site_forms))
        .layer(axum::middleware::from_fn(security_headers))
        .with_state(app))
}

/// Serves [`router`] on `listen` until the process ends (each request's history work
/// in its own blocking thread; a killed server leaves the last committed state, as
/// the history guarantees).
///
/// # Errors
/// The address cannot be bound; a template does not compile; the server fails.
pub fn serve(
    listen: std::net::SocketAddr,
    config: Config,
    product: Box<dyn Product>,
) -> Result<(), String> {
    let app = router(config, product)?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| format!("the server's runtime: {e}"))?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(listen)
            .await
            .map_err(|e| format!("cannot listen on {listen}: {e}"))?;
        axum::serve(listener, app)
            .await
            .map_err(|e| format!("the server stopped: {e}"))
    })
}
