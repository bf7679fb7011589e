//! The pages' templates (`web/templates/`), compiled into the binary. Auto-escaping is
//! on for every one of them (minijinja escapes HTML in templates named `*.html`): a
//! serial, an operator or an error message with markup is shown as text.

use crate::WebError;
use axum::http::StatusCode;
use axum::response::Html;

const TEMPLATES: [(&str, &str); 9] = [
    ("base.html", include_str!("../templates/base.html")),
    ("login.html", include_str!("../templates/login.html")),
    ("fleet.html", include_str!("../templates/fleet.html")),
    ("robot.html", include_str!("../templates/robot.html")),
    ("upload.html", include_str!("../templates/upload.html")),
    ("record.html", include_str!("../templates/record.html")),
    (
        "certificate_none.html",
        include_str!("../templates/certificate_none.html"),
    ),
    ("users.html", include_str!("../templates/users.html")),
    ("audit.html", include_str!("../templates/audit.html")),
];

/// Every template, compiled.
pub(crate) fn environment() -> Result<minijinja::Environment<'static>, String> {
    let mut env = minijinja::Environment::new();
    env.set_auto_escape_callback(|_| minijinja::AutoEscape::Html);
    env.add_filter("segment", segment);
    for (name, text) in TEMPLATES {
        env.add_template(name, text)
            .map_err(|e| format!("template {name}: {e}"))?;
    }
    Ok(env)
}

/// `text` as one path segment of a link: every byte but letters, digits and `-_~`
/// percent-encoded, so that a serial or user name holding `/`, `?` or `#` links to its
/// own page (minijinja's `urlencode` keeps `/`, meant for whole paths). The route's
/// extractor decodes it back.
fn segment(text: &str) -> String {
    // `.` too: a serial of `.` or `..` left as is would be a path step the browser
    // resolves away.
    const SEGMENT: &percent_encoding::AsciiSet = &percent_encoding::NON_ALPHANUMERIC
        .remove(b'-')
        .remove(b'_')
        .remove(b'~');
    percent_encoding::utf8_percent_encode(text, SEGMENT).to_string()
}

/// The page `name` rendered with `context`.
pub(crate) fn render(
    env: &minijinja::Environment<'static>,
    name: &str,
    context: minijinja::Value,
) -> Result<Html<String>, WebError> {
    env.get_template(name)
        .and_then(|t| t.render(context))
        .map(Html)
        .map_err(|e| {
            WebError(
                StatusCode::INTERNAL_SERVER_ERROR,
                format!("page {name}: {e}"),
            )
        })
}
