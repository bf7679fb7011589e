//! Signing in and out, the fleet, a robot's page and plots, and the upload of a
//! pendant export.

use crate::auth::{self, action_session, now_unix, page_session, random_hex};
use crate::fleet_view::{rows, FleetQuery};
use crate::templates::render;
use crate::{with_history, Shared, WebError};
use axum::extract::{Multipart, Path, Query, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Redirect, Response};
use axum::Form;
use minijinja::context;
use std::collections::HashMap;
use zerocal_history::HistoryError;
use zerocal_history::{sha256_hex, LoginGate, RecordKind, Role};

/// `/`: the fleet.
pub async fn home() -> Redirect {
    Redirect::to("/fleet")
}

fn result(r: Result<Response, WebError>) -> Response {
    r.unwrap_or_else(IntoResponse::into_response)
}

/// The answer to a sign-in refused for its name or password: the same whichever was
/// wrong, so that it does not tell which names exist.
const WRONG_SIGN_IN: &str = "the name or the password is wrong, or the account is disabled";

/// `GET /login`.
pub async fn login_form(State(app): State<Shared>) -> Response {
    result(render(&app.templates, "login.html", context! {}).map(IntoResponse::into_response))
}

/// `POST /login` (name, password): a session cookie and to the fleet; refused after
/// [`auth::MAX_FAILED_LOGINS`] failures of the name within
/// [`auth::LOGIN_WINDOW_SECONDS`], without trying the password.
pub async fn login(
    State(app): State<Shared>,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let name = form.get("name").cloned().unwrap_or_default();
    let password = form.get("password").cloned().unwrap_or_default();
    let page = |status: StatusCode, message: String| {
        result(
            render(&app.templates, "login.html", context! { message })
                .map(|html| (status, html).into_response()),
        )
    };
    let outcome = with_history(&app, move |h| {
        // A name no account can have is refused as a wrong one, and not recorded: a
        // flood of made-up names must not fill the attempts table.
        if zerocal_history::check_user_name(&name).is_err() {
            return Ok(Err((
                StatusCode::UNAUTHORIZED,
                WRONG_SIGN_IN.to_owned(),
            )));
        }
        let now = now_unix();
        // The count and this attempt's row in one locked transaction, the attempt
        // recorded failed before its password is tried: parallel guesses cannot all
        // pass the same count.
        let attempt = match h.begin_login_attempt(
            &name,
            now,
            now - auth::LOGIN_WINDOW_SECONDS,
            auth::MAX_FAILED_LOGINS,
        )? {
            LoginGate::Attempt(id) => id,
            LoginGate::Refused { failures } => {
                return Ok(Err((
                    StatusCode::TOO_MANY_REQUESTS,
                    format!(
                        "{failures} failed sign-ins for this name in the last {} minutes: refused until they are older",
                        auth::LOGIN_WINDOW_SECONDS / 60
                    ),
                )));
            }
        };
        // An unknown name costs one Argon2 verification too, so that the time taken
        // does not tell which names exist.
        let ok = match h.user(&name)? {
            Some(u) => auth::verify_password(&password, &u.password_phc) && u.active,
            None => {
                auth::verify_password(&password, auth::unknown_user_phc());
                false
            }
        };
        if !ok {
            return Ok(Err((
                StatusCode::UNAUTHORIZED,
                WRONG_SIGN_IN.to_owned(),
            )));
        }
        h.mark_login_succeeded(attempt)?;
        let id = random_hex(32)?;
        let csrf = random_hex(32)?;
        h.start_web_session(&sha256_hex(id.as_bytes()), &name, &csrf, now + auth::SESSION_SECONDS)?;
        Ok(Ok(id))
    })
    .await;
    match outcome {
        Ok(Ok(id)) => (
            StatusCode::SEE_OTHER,
            [
                (header::LOCATION, "/fleet".to_owned()),
                (
                    header::SET_COOKIE,
                    auth::cookie(&app, &id, auth::SESSION_SECONDS),
                ),
            ],
        )
            .into_response(),
        Ok(Err((status, message))) => page(status, message),
        Err(e) => e.into_response(),
    }
}

/// `POST /logout` (csrf): the session ends here and in the database.
pub async fn logout(
    State(app): State<Shared>,
    headers: HeaderMap,
    Form(form): Form<HashMap<String, String>>,
) -> Response {
    let r = async {
        action_session(
            &app,
            &headers,
            form.get("csrf").map(String::as_str),
            &Role::ALL,
        )
        .await?;
        let hash = auth::session_hash(&headers).unwrap_or_default();
        with_history(&app, move |h| Ok(h.end_web_session(&hash, now_unix())?)).await?;
        Ok((
            StatusCode::SEE_OTHER,
            [
                (header::LOCATION, "/login".to_owned()),
                (header::SET_COOKIE, auth::cookie(&app, "", 0)),
            ],
        )
            .into_response())
    };
    result(r.await)
}

/// `GET /fleet?sort=&q=&only=`.
pub async fn fleet(
    State(app): State<Shared>,
    headers: HeaderMap,
    Query(query): Query<FleetQuery>,
) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    let r = async {
        let fleet = with_history(&app, |h| Ok(h.fleet()?)).await?;
        let today = zerocal_civil::Timestamp::clock().date();
        let intervals = &app.config.intervals;
        // A model given its own interval that no robot of the fleet is of: a misspelt
        // name, shown rather than silently unused.
        let unused: Vec<String> = intervals
            .by_model
            .keys()
            .filter(|m| !fleet.iter().any(|r| &r.robot == *m))
            .cloned()
            .collect();
        let rows = rows(fleet, intervals, today, &query)
            .map_err(|e| WebError(StatusCode::BAD_REQUEST, e))?;
        render(
            &app.templates,
            "fleet.html",
            context! {
                user => s.user, csrf => s.csrf_token, rows, query, intervals, unused,
                wear_sigmas => zerocal_history::reducers::WEAR_SIGMAS,
            },
        )
        .map(IntoResponse::into_response)
    };
    result(r.await)
}

/// `GET /robot/SERIAL`: its records with their review state, reducers, conventions,
/// and its plots.
pub async fn robot(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path(serial): Path<String>,
) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    let r = async {
        let app2 = app.clone();
        let serial2 = serial.clone();
        let (records, conventions, reducer_notes, plots, plot_error) =
            with_history(&app, move |h| {
                let records = h.list(Some(&serial2))?;
                if records.is_empty() {
                    return Err(WebError(
                        StatusCode::NOT_FOUND,
                        format!("the history holds no record of serial {serial2:?}"),
                    ));
                }
                let corrections = h.corrections(&serial2)?;
                let mut rows = Vec::new();
                for r in &records {
                    let signed = h.signatures(r.id)?;
                    let review = match (r.new.kind, signed.last()) {
                        (RecordKind::Check, _) => "-".to_owned(),
                        (_, None) => "measured".to_owned(),
                        (_, Some(s)) => format!("{} by {}", s.step.as_str(), s.user_name),
                    };
                    rows.push(context! {
                        id => r.id, kind => r.new.kind.as_str(), reference_id => r.new.reference_id,
                        measured_on => r.new.measured_on, operator => r.new.operator,
                        verdict => r.new.verdict, review,
                        replaced_by => corrections.iter().find(|c| c.replaces_id == r.id),
                        replaces => corrections.iter().find(|c| c.record_id == r.id),
                    });
                }
                let conventions = h.conventions(&serial2)?;

                let notes = app2.product.reducer_notes(&records);
                let (plots, plot_error) = match app2.product.robot_plots_svg(&serial2, &records) {
                    Ok(p) => ((0..p.len()).collect::<Vec<_>>(), None),
                    Err(e) => (Vec::new(), Some(e)),
                };
                Ok((rows, conventions, notes, plots, plot_error))
            })
            .await?;
        render(
            &app.templates,
            "robot.html",
            context! { user => s.user, csrf => s.csrf_token, serial, records, conventions, reducer_notes, plots, plot_error, pdf => app.config.chromium.is_some() },
        )
        .map(IntoResponse::into_response)
    };
    result(r.await)
}

/// `GET /robot/SERIAL/plot/N`: its Nth plot, an SVG image (shown through `<img>`, so
/// nothing in it runs).
pub async fn robot_plot(
    State(app): State<Shared>,
    headers: HeaderMap,
    Path((serial, index)): Path<(String, usize)>,
) -> Response {
    if let Err(r) = page_session(&app, &headers).await {
        return r;
    }
    let app2 = app.clone();
    let r = with_history(&app, move |h| {
        let records = h.list(Some(&serial))?;
        let plots = app2
            .product
            .robot_plots_svg(&serial, &records)
            .map_err(|e| WebError(StatusCode::INTERNAL_SERVER_ERROR, e))?;
        plots
            .into_iter()
            .nth(index)
            .ok_or_else(|| WebError(StatusCode::NOT_FOUND, format!("no plot {index}")))
    })
    .await
    .map(|svg| ([(header::CONTENT_TYPE, "image/svg+xml")], svg).into_response());
    result(r)
}

/// `GET /upload`.
pub async fn upload_form(State(app): State<Shared>, headers: HeaderMap) -> Response {
    let s = match page_session(&app, &headers).await {
        Ok(s) => s,
        Err(r) => return r,
    };
    result(
        render(
            &app.templates,
            "upload.html",
            context! { user => s.user, csrf => s.csrf_token, max_bytes => app.config.max_upload_bytes },
        )
        .map(IntoResponse::into_response),
    )
}

/// The upload's fields: the CSRF token, the serial and the export's bytes.
async fn upload_fields(mut form: Multipart) -> Result<HashMap<String, Vec<u8>>, WebError> {
    let mut fields = HashMap::new();
    loop {
        let field = form
            .next_field()
            .await
            .map_err(|e| WebError(e.status(), format!("upload: {}", e.body_text())))?;
        let Some(field) = field else { break };
        let name = field.name().unwrap_or_default().to_owned();
        let bytes = field
            .bytes()
            .await
            .map_err(|e| WebError(e.status(), format!("upload: {}", e.body_text())))?;
        fields.insert(name, bytes.to_vec());
    }
    Ok(fields)
}

/// `POST /upload` (multipart: csrf, serial, export, and for a correction replaces
/// and reason): solved by the CLI's code and
/// recorded with the signed-in technician as its operator; a malformed export, another
/// robot's (the serial's records are of another profile) or one too large is refused
/// and nothing is recorded.
pub async fn upload(State(app): State<Shared>, headers: HeaderMap, form: Multipart) -> Response {
    let r = async {
        // Not signed in: refused before the body is read.
        if auth::current(&app, &headers).await?.is_none() {
            return Err(WebError(
                StatusCode::UNAUTHORIZED,
                "not signed in: sign in at /login".into(),
            ));
        }
        let fields = upload_fields(form).await?;
        let text = |k: &str| {
            fields
                .get(k)
                .map(|v| String::from_utf8_lossy(v).into_owned())
        };
        let s =
            action_session(&app, &headers, text("csrf").as_deref(), &[Role::Technician]).await?;
        let serial = text("serial").unwrap_or_default();
        let export = fields.get("export").cloned().unwrap_or_default();
        if export.is_empty() {
            return Err(WebError(
                StatusCode::UNPROCESSABLE_ENTITY,
                "upload: no export file".into(),
            ));
        }
        // A correction names the record it replaces and why.
        let replaces = match text("replaces").as_deref().map(str::trim) {
            None | Some("") => None,
            Some(t) => Some(t.parse::<i64>().ok().filter(|id| *id > 0).ok_or_else(|| {
                WebError(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    format!("upload: replaces {t:?} is not a record number"),
                )
            })?),
        };
        let reason = text("reason").unwrap_or_default();
        let app2 = app.clone();
        let user = s.user.name.clone();
        let id = with_history(&app, move |h| {
            let record = app2
                .product
                .solve_export(&export, &serial, &user)
                .map_err(|e| WebError(StatusCode::UNPROCESSABLE_ENTITY, e))?;
            // The serial's records all of this export's robot, checked in the insert's
            // transaction: two uploads racing cannot both pass.
            let correction = replaces.map(|old| (old, reason.as_str()));
            // Another robot's export is the uploader's mistake, said in its own words
            // (not as a history failure).
            match h.insert_of_one_robot(&user, &record, correction) {
                Ok(stored) => Ok(stored.id),
                Err(e @ HistoryError::AnotherRobot { .. }) => {
                    Err(WebError(StatusCode::UNPROCESSABLE_ENTITY, e.to_string()))
                }
                Err(e) => Err(e.into()),
            }
        })
        .await;
        match id {
            Ok(id) => Ok(Redirect::to(&format!("/record/{id}")).into_response()),
            Err(WebError(status, message)) => render(
                &app.templates,
                "upload.html",
                context! { user => s.user, csrf => s.csrf_token, max_bytes => app.config.max_upload_bytes, message },
            )
            .map(|html| (status, html).into_response()),
        }
    };
    result(r.await)
}
