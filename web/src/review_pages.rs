//! A record's page with its review (measured → checked → authorized), its certificate
//! with the signatures on it, the users (administrators only) and the audit log.

use crate::auth::{action_session, page_session};
use crate::templates::render;
use crate::{with_history, Shared, WebError};
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{Html, IntoResponse, Redirect, Response};
use axum::Form;
use minijinja::context;
use std::collections::HashMap;
use zerocal_history::{CertificateRequest, RecordKind, Role, SignStep, WebSession};

fn result(r: Result<Response, WebError>) -> Response {
    r.unwrap_or_else(IntoResponse::into_response)
}

/// The step a session's record waits for, given its signatures.
fn next_step(signed: &[zerocal_history::Signature]) -> Option<SignStep> {
    if signed.iter().any(|s| s.step == SignStep::Authorized) {
        None
    } else if signed.iter().any(|s| s.step == SignStep::Checked) {
        Some(SignStep::Authorized)
    } else {
        Some(SignStep::Checked)
    }
}

/// `GET /record/ID`: the record, its zeros, its review and the form to sign its next
/// step (shown to the role that signs it).
pub async fn record(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(id): Path<i64>,
) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    let r = async {
        let (r, signatures, issued) = with_history(&app, move |h| {
            Ok((
                h.get(id)?,
                h.signatures(id)?,
                !h.certificates_of(id)?.is_empty(),
            ))
        })
        .await?;
        let next = next_step(&signatures);
        render(
            &app.templates,
            "record.html",
            context! {
                user => s.user, csrf => s.csrf_token, r, signatures,
                next_step => next.map(SignStep::as_str),
                next_role => next.map(|n| n.role().as_str()),
                pdf => app.config.chromium.is_some(), issued,
                may_issue => CERTIFICATE_ISSUERS.contains(&s.user.role),
            },
        )
        .map(IntoResponse::into_response)
    };
    result(r.await)
}

/// The signatures as a block of the certificate, escaped (names are the users').
fn signature_block(
    record_id: i64,
    operator: Option<&str>,
    signed: &[zerocal_history::Signature],
) -> String {
    let esc = |t: &str| minijinja::HtmlEscape(t).to_string();
    let mut out = format!(
        "<section id=\"zerocal-review\" style=\"border-top: 1px solid #888; margin-top: 2em\">\
         <h2>Review of record {record_id}</h2><ul><li>measured by {}</li>",
        esc(operator.unwrap_or("-"))
    );
    for s in signed {
        out.push_str(&format!(
            "<li>{} by {} at {}</li>",
            s.step.as_str(),
            esc(&s.user_name),
            esc(&s.signed_at)
        ));
    }
    if next_step(signed).is_some() {
        out.push_str("<li>not authorized</li>");
    }
    out.push_str("</ul></section>");
    out
}

/// How a certificate is asked for: shown (`GET`: only one already issued for the
/// session's current as-left check and issuer) or issued (`POST`: a first issue gives
/// it a number and writes the audit).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Ask {
    Show,
    Issue,
}

/// Why a certificate is not shown: none issued yet (404), or none for the session's
/// current as-left check and issuer (422, the product's refusal); the page offers the
/// issuing button to those who may issue.
struct NotIssued(StatusCode, String);

/// The session's certificate as `zerocal certificate` makes it, with its review under
/// it: shown if issued (`Ask::Show` writes nothing), or issued (in the history the
/// first time, audited then: `Ask::Issue`, for [`CERTIFICATE_ISSUERS`] only).
async fn certificate_of(
    app: &Shared,
    actor: &WebSession,
    id: i64,
    ask: Ask,
) -> Result<Result<String, NotIssued>, WebError> {
    let app2 = app.clone();
    let (name, role) = (actor.user.name.clone(), actor.user.role);
    with_history(app, move |h| {
        let record = h.get(id)?;
        if record.new.kind != RecordKind::Session {
            return Err(WebError(
                StatusCode::UNPROCESSABLE_ENTITY,
                format!("record {id} is a check: a certificate is of a session"),
            ));
        }
        let may_issue = ask == Ask::Issue && CERTIFICATE_ISSUERS.contains(&role);
        if ask == Ask::Show && h.certificates_of(id)?.is_empty() {
            return Ok(Err(NotIssued(
                StatusCode::NOT_FOUND,
                format!("record {id} has no certificate issued yet"),
            )));
        }
        // A first issue gives it a number, which those who work the records do, not
        // the users' admin (refused before, and in the issuing transaction where a new
        // as-left check or issuer would make another); showing one never issues.
        let html = match app2.product.certificate_html(
            h,
            &record,
            CertificateRequest {
                name: &name,
                may_issue,
            },
        ) {
            Ok(html) => html,
            Err(e) if ask == Ask::Show => {
                return Ok(Err(NotIssued(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    format!("record {id}'s certificate: {e}"),
                )))
            }
            Err(e) => {
                return Err(WebError(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    format!("certificate: {e}"),
                ))
            }
        };
        let block = signature_block(id, record.new.operator.as_deref(), &h.signatures(id)?);
        Ok(Ok(match html.rfind("</body>") {
            Some(at) => format!("{}{block}{}", &html[..at], &html[at..]),
            None => format!("{html}{block}"),
        }))
    })
    .await
}

/// The roles that may issue a record's first certificate.
const CERTIFICATE_ISSUERS: [Role; 3] = [Role::Technician, Role::Reviewer, Role::Authorizer];

/// The page saying a certificate is not issued, with the issuing button for those who
/// may issue.
fn not_issued(app: &Shared, s: &WebSession, id: i64, n: NotIssued) -> Result<Response, WebError> {
    let page = render(
        &app.templates,
        "certificate_none.html",
        context! {
            user => s.user, csrf => s.csrf_token, id, message => n.1,
            may_issue => CERTIFICATE_ISSUERS.contains(&s.user.role),
        },
    )?;
    Ok((n.0, page).into_response())
}

/// `GET /record/ID/certificate`: the certificate issued, HTML; where none is issued
/// (for the current as-left check and issuer), a page that says so. Issues nothing.
pub async fn certificate(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(id): Path<i64>,
) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    result(match certificate_of(&app, &s, id, Ask::Show).await {
        Ok(Ok(html)) => Ok(Html(html).into_response()),
        Ok(Err(n)) => not_issued(&app, &s, id, n),
        Err(e) => Err(e),
    })
}

/// `POST /record/ID/certificate` (csrf): issues the session's certificate (a
/// technician, reviewer or authorizer; the same number again where one is issued for
/// the same as-left check and issuer) and shows it.
pub async fn issue_certificate(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(id): Path<i64>,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let r = async {
        let s = action_session(
            &app,
            &headers,
            form.get("csrf").map(String::as_str),
            &CERTIFICATE_ISSUERS,
        )
        .await?;
        match certificate_of(&app, &s, id, Ask::Issue).await? {
            Ok(_) => Ok(Redirect::to(&format!("/record/{id}/certificate")).into_response()),
            Err(n) => not_issued(&app, &s, id, n),
        }
    };
    result(r.await)
}

/// `GET /record/ID/certificate.pdf`: the certificate printed by headless Chromium.
pub async fn certificate_pdf(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(id): Path<i64>,
) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    let r = async {
        let chromium = app.config.chromium.clone().ok_or_else(|| {
            WebError(
                StatusCode::NOT_FOUND,
                "no PDF: this server has no Chromium to print with (zerocal serve --chromium)"
                    .into(),
            )
        })?;
        let html = match certificate_of(&app, &s, id, Ask::Show).await? {
            Ok(html) => html,
            Err(n) => return not_issued(&app, &s, id, n),
        };
        let pdf = tokio::task::spawn_blocking(move || crate::pdf::print(&chromium, &html))
            .await
            .map_err(|e| WebError(StatusCode::INTERNAL_SERVER_ERROR, format!("worker: {e}")))?
            .map_err(|e| WebError(StatusCode::INTERNAL_SERVER_ERROR, format!("PDF: {e}")))?;
        Ok((
            [
                (header::CONTENT_TYPE, "application/pdf".to_owned()),
                (
                    header::CONTENT_DISPOSITION,
                    format!("attachment; filename=\"zerocal-certificate-{id}.pdf\""),
                ),
            ],
            pdf,
        )
            .into_response())
    };
    result(r.await)
}

/// `POST /record/ID/sign` (csrf, step): the step signed by the signed-in user, whose
/// role must be the step's; the history checks the order and the four eyes again in
/// the same transaction.
pub async fn sign(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(id): Path<i64>,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let r = async {
        let step = SignStep::parse(form.get("step").map_or("", String::as_str))
            .map_err(|e| WebError(StatusCode::BAD_REQUEST, e))?;
        let s = action_session(
            &app,
            &headers,
            form.get("csrf").map(String::as_str),
            &[step.role()],
        )
        .await?;
        let name = s.user.name.clone();
        with_history(&app, move |h| Ok(h.sign(&name, id, step)?)).await?;
        Ok(Redirect::to(&format!("/record/{id}")).into_response())
    };
    result(r.await)
}

/// `GET /admin/users` (administrators).
pub async fn users(State(app): State<Shared>, headers: HeaderMap) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    if s.user.role != Role::Admin {
        return WebError(
            StatusCode::FORBIDDEN,
            "the users are managed by an admin".into(),
        )
        .into_response();
    }
    let r = async {
        let users = with_history(&app, |h| Ok(h.users()?)).await?;
        let roles: Vec<&str> = Role::ALL.iter().map(|r| r.as_str()).collect();
        render(
            &app.templates,
            "users.html",
            context! { user => s.user, csrf => s.csrf_token, users, roles },
        )
        .map(IntoResponse::into_response)
    };
    result(r.await)
}

fn role_of(form: &HashMap<String, String>) -> Result<Role, WebError> {
    Role::parse(form.get("role").map_or("", String::as_str))
        .map_err(|e| WebError(StatusCode::BAD_REQUEST, e))
}

/// `POST /admin/users` (csrf, name, role, password): a new account (administrators).
pub async fn add_user(
    State(app): State<Shared>,
    headers: HeaderMap,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let r = async {
        let s = action_session(
            &app,
            &headers,
            form.get("csrf").map(String::as_str),
            &[Role::Admin],
        )
        .await?;
        let role = role_of(&form)?;
        let name = form.get("name").cloned().unwrap_or_default();
        let password = form.get("password").cloned().unwrap_or_default();
        let actor = s.user.name.clone();
        with_history(&app, move |h| {
            let phc = crate::hash_password(&password)
                .map_err(|e| WebError(StatusCode::BAD_REQUEST, e))?;
            Ok(h.add_user(&actor, &name, role, &phc)?)
        })
        .await?;
        Ok(Redirect::to("/admin/users").into_response())
    };
    result(r.await)
}

/// `POST /admin/users/NAME` (csrf, role, active): the account's role and whether it
/// may sign in (administrators); its sessions end.
pub async fn set_user(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(name): Path<String>,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let r = async {
        let s = action_session(
            &app,
            &headers,
            form.get("csrf").map(String::as_str),
            &[Role::Admin],
        )
        .await?;
        let role = role_of(&form)?;
        let active = match form.get("active").map(String::as_str) {
            Some("1") => true,
            Some("0") => false,
            other => {
                return Err(WebError(
                    StatusCode::BAD_REQUEST,
                    format!("active {other:?} is neither 1 nor 0"),
                ))
            }
        };
        let actor = s.user.name.clone();
        with_history(&app, move |h| Ok(h.set_user(&actor, &name, role, active)?)).await?;
        Ok(Redirect::to("/admin/users").into_response())
    };
    result(r.await)
}

/// How many audit entries the page shows, newest first.
pub const AUDIT_PAGE_ENTRIES: i64 = 500;

/// `GET /audit`: the newest entries of the audit log (anyone signed in).
pub async fn audit(State(app): State<Shared>, headers: HeaderMap) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    let r = async {
        let entries = with_history(&app, |h| Ok(h.audit_log(AUDIT_PAGE_ENTRIES)?)).await?;
        render(
            &app.templates,
            "audit.html",
            context! { user => s.user, csrf => s.csrf_token, entries },
        )
        .map(IntoResponse::into_response)
    };
    result(r.await)
}
