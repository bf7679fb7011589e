//! `zerocal certificate ID --out FILE.html`: a calibration certificate for one session of
//! the history, in the manner of ISO/IEC 17025 §7.8 (the certificate's content) and
//! §7.8.6 (a statement of conformity with its decision rule). One self-contained HTML
//! page set for A4 (inline CSS and SVG; no external file, font or script), printed to
//! PDF by headless Chromium (`cargo xtask certificate-render`).
//!
//! Everything on it comes from the history record ([`CertificateSubject`]: what was
//! measured, when, by whom, with which pendant, and the SHA-256 of the profile and the
//! export) and from the session solved again from its stored export
//! ([`zerocal_analysis::session::analyse`]): the numbers are those `zerocal session` gives for that
//! export, so the certificate can be checked by re-solving the export.
//!
//! Every number goes through one formatter that refuses a non-finite value, naming it,
//! and lists the number as printed ([`Certificate::printed_numbers`]), so the PDF can be
//! checked to hold every one; every text is escaped for HTML. docs/certificate.md says
//! what each section is for.

pub mod as_left;
mod gum;
pub mod issuer;
mod page;
mod printed;
mod residual_plot;
mod sections;
mod trace;

pub use as_left::{AsLeft, AsLeftJoint};
pub use issuer::{Equipment, EquipmentKind, Issuer, Used};
pub use printed::esc as escape_html;
pub use sections::without_paths;

use clap::Args;
use std::fmt;
use std::path::{Path, PathBuf};
use zerocal_analysis::session::Analysis;
use zerocal_core::stage2::MEMS_RANGE_DEG;
use zerocal_inputs::args::RealIn;
use zerocal_inputs::error::CliError;

/// What the history record adds to the session: the robot's identity, when and by
/// whom it was measured, what the numbers were computed from, who issues the
/// certificate with which equipment, and the robot as left.
#[derive(Clone, Debug, PartialEq)]
pub struct CertificateSubject {
    /// The certificate's number (unique across machines: [`issuer::new_number`]).
    pub number: String,
    /// The session's history record.
    pub record_id: i64,
    /// The robot's serial number.
    pub serial: String,
    /// When the session was measured, `YYYY-MM-DD`.
    pub measured_on: String,
    /// When the record was stored (as the history keeps it).
    pub recorded_at: String,
    /// Who measured, if recorded.
    pub operator: Option<String>,
    /// The pendant's identification, if recorded.
    pub pendant_unit: Option<String>,
    /// SHA-256 of the robot profile the session was solved with (64 hex digits).
    pub profile_sha256: String,
    /// SHA-256 of the pendant's export (64 hex digits).
    pub export_sha256: String,
    /// The zerocal version that solved the session.
    pub zerocal_version: String,
    /// The decision's tolerance per joint (deg), if one is stated: a joint conforms when
    /// its U (k = 2) is at most this.
    pub tolerance_deg: Option<f64>,
    /// The issuing laboratory, the customer, the site and the equipment register.
    pub issuer: Issuer,
    /// The equipment the session used, found in the register.
    pub equipment: Vec<Used>,
    /// The check after the entry, if one was recorded.
    pub as_left: Option<AsLeft>,
}

/// A certificate: its HTML and every number it prints.
#[derive(Clone, Debug, PartialEq)]
pub struct Certificate {
    /// The certificate, a self-contained HTML document for A4.
    pub html: String,
    /// Every number printed in its text (as printed; the figure's axis scale is not
    /// among them), for the check that the PDF holds them all.
    pub printed_numbers: Vec<String>,
}

/// Why no certificate could be written.
#[derive(Clone, Debug, PartialEq)]
pub enum CertificateError {
    /// A quantity to be printed is not a finite number: the session's numbers cannot
    /// be certified.
    NotFinite {
        /// Which quantity.
        what: String,
        /// Its value.
        value: f64,
    },
    /// A field of the record is not what a certificate can state.
    Subject {
        /// The field.
        field: &'static str,
        /// What is wrong with it.
        why: String,
    },
    /// The residual figure could not be drawn.
    Figure(String),
    /// Equipment the session rests on was past its due date, or the number could not be
    /// drawn.
    Equipment(String),
}

impl fmt::Display for CertificateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CertificateError::NotFinite { what, value } => write!(
                f,
                "certificate: {what} is {value}, not a number that can be certified"
            ),
            CertificateError::Subject { field, why } => {
                write!(f, "certificate: the record's {field}: {why}")
            }
            CertificateError::Figure(e) => {
                write!(f, "certificate: the residual figure cannot be drawn: {e}")
            }
            CertificateError::Equipment(e) => write!(f, "certificate: {e}"),
        }
    }
}

impl std::error::Error for CertificateError {}

impl From<CertificateError> for CliError {
    fn from(e: CertificateError) -> Self {
        match e {
            CertificateError::Subject { .. } => CliError::Input(e.to_string()),
            CertificateError::NotFinite { .. }
            | CertificateError::Figure(_)
            | CertificateError::Equipment(_) => CliError::Refused(e.to_string()),
        }
    }
}

/// A tolerance per joint wider than the sensor's specified range (mode 4's ±10°, within
/// which every reading of a session lies) would accept any session: none is meant.
const TOLERANCE: RealIn = RealIn::above(0.0, MEMS_RANGE_DEG, "deg");

/// Arguments of `zerocal certificate` (the history database's option is the history's).
#[derive(Args, Debug, Clone)]
pub struct CertificateArgs {
    /// The history record's number.
    pub id: i64,
    /// Where the certificate goes (FILE.html); every number it prints goes beside it
    /// (FILE.numbers, one a line) for `cargo xtask certificate-render`'s check.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// The tolerance per joint (deg): each joint conforms when its U (k = 2) is at most
    /// this (simple acceptance). Without it the certificate states the session's own
    /// acceptance only. Range: (0, 10] deg.
    #[arg(long, value_name = "DEG", value_parser = TOLERANCE)]
    pub tolerance_deg: Option<f64>,
    /// The issuer's configuration: the laboratory, the customer, the site and the
    /// equipment register (TOML, docs/certificate.md). Default:
    /// $XDG_CONFIG_HOME/zerocal/certificate.toml, else ~/.config/zerocal/certificate.toml.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// The check after the entry to state as the robot as left (default: the latest
    /// check recorded against this session after an entry). Range: [1,
    /// 9223372036854775807].
    #[arg(long, value_name = "ID", value_parser = zerocal_inputs::args::RECORD_ID)]
    pub as_left: Option<i64>,
    #[command(flatten)]
    pub db: zerocal_analysis::db::DbArg,
}

/// The issuer's configuration file `--config` names, or the default one.
fn config_path(args: &CertificateArgs) -> Result<PathBuf, CliError> {
    issuer_config_path(args.config.as_deref())
}

/// The issuer's configuration file `given`, or the default one
/// ($XDG_CONFIG_HOME/zerocal/certificate.toml, else ~/.config/zerocal/certificate.toml).
///
/// # Errors
/// None given and neither variable set.
pub fn issuer_config_path(given: Option<&Path>) -> Result<PathBuf, CliError> {
    if let Some(p) = given {
        return Ok(p.to_path_buf());
    }
    let base = std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| {
            std::env::var_os("HOME")
                .filter(|h| !h.is_empty())
                .map(|h| PathBuf::from(h).join(".config"))
        })
        .ok_or_else(|| {
            CliError::Input(
                "certificate: no --config and no XDG_CONFIG_HOME or HOME: give the issuer's \
                 configuration file (docs/certificate.md)"
                    .into(),
            )
        })?;
    Ok(base.join("zerocal").join("certificate.toml"))
}

/// Runs `zerocal certificate ID --out FILE.html`: the record's session solved again
/// from its stored export and profile, certified by the issuer of `--config`, with the
/// robot as left by the check after the entry; the certificate's number and issue date
/// kept in the history, so the same certificate comes out again.
///
/// # Errors
/// No such record, a check's record, a record the certificate cannot state, an issuer
/// file that does not read, equipment past its due date.
pub fn run(args: &CertificateArgs) -> Result<String, CliError> {
    let mut history = args.db.open()?;
    let record = history
        .get(args.id)
        .map_err(zerocal_analysis::db::history_failed)?;
    let path = config_path(args)?;
    // The command line's user is no account of the web application: not audited.
    let (subject, analysis, issued_on) = issue(
        &mut history,
        &record,
        &path,
        (args.tolerance_deg, args.as_left),
        None,
    )?;
    let written = write_issued_on(&subject, &analysis, &args.out, &issued_on)?;
    Ok(
        std::iter::once(format!("certificate no. {}", subject.number))
            .chain(written.iter().map(|p| format!("wrote {}", p.display())))
            .collect::<Vec<_>>()
            .join("\n"),
    )
}

/// Issues the certificate of the session `record` in `history` (its number and issue
/// date kept there, so the same certificate comes out again) by the issuer of the file
/// `path`, with the robot as left by the check `as_left_id` (default: the latest check
/// after the entry): what `zerocal certificate` and `zerocal serve` render. A first
/// issue asked for by a signed-in user (`by`, `zerocal serve`) is audited in the same
/// transaction, and refused where their role issues none.
///
/// # Errors
/// As [`run`].
pub fn issue(
    history: &mut zerocal_history::History,
    record: &zerocal_history::Record,
    path: &Path,
    (tolerance_deg, as_left_id): (Option<f64>, Option<i64>),
    by: Option<zerocal_history::CertificateRequest<'_>>,
) -> Result<(CertificateSubject, Analysis, String), CliError> {
    let analysis = zerocal_analysis::stored_session::solve_record(record)?;
    let text =
        zerocal_inputs::input::read_capped(path, issuer::MAX_ISSUER_BYTES, "issuer configuration")
            .map_err(|e| match e {
                CliError::Input(m) => CliError::Input(format!(
                    "{m}: a certificate names its laboratory, customer and site from this file \
                 (docs/certificate.md gives its format)"
                )),
                e => e,
            })?;
    let issuer =
        issuer::parse(&text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let left = match as_left_id {
        Some(id) => Some(
            history
                .get(id)
                .map_err(zerocal_analysis::db::history_failed)?,
        ),
        None => history
            .checks_against(record.id)
            .map_err(zerocal_analysis::db::history_failed)?
            .into_iter()
            .rfind(|c| as_left::is_after_entry(c, record.id)),
    };
    let as_left = left
        .map(|c| as_left::as_left(&c, record.id))
        .transpose()
        .map_err(CliError::Input)?;
    let equipment = issuer::equipment_used(
        &issuer,
        record.new.pendant_unit.as_deref(),
        &analysis.export.brackets,
        &record.new.measured_on,
    )?;
    let issuer_json = serde_json::json!({ "issuer": &issuer, "equipment": &equipment }).to_string();
    let (issued, _) = history
        .issue_certificate_by(
            &zerocal_history::NewCertificate {
                number: issuer::new_number(&issuer)?,
                session_id: record.id,
                as_left_id: as_left.as_ref().map(|a| a.record_id),
                issued_on: zerocal_inputs::bracket_file::today_utc(),
                issuer_json,
            },
            by,
        )
        .map_err(zerocal_analysis::db::history_failed)?;
    let subject = CertificateSubject {
        number: issued.new.number.clone(),
        record_id: record.id,
        serial: record.new.serial.clone(),
        measured_on: record.new.measured_on.clone(),
        recorded_at: record.recorded_at.clone(),
        operator: record.new.operator.clone(),
        pendant_unit: record.new.pendant_unit.clone(),
        profile_sha256: record.profile_sha256.clone(),
        export_sha256: record.export_sha256.clone(),
        zerocal_version: record.new.zerocal_version.clone(),
        tolerance_deg,
        issuer,
        equipment,
        as_left,
    };
    Ok((subject, analysis, issued.new.issued_on))
}

/// The certificate of `analysis` (the session solved from the record's export) for the
/// record `subject`, issued today (UTC).
///
/// # Errors
/// A record field a certificate cannot state (a malformed date or hash, an empty
/// serial, a tolerance that is not a positive number), a non-finite number in the
/// session, the figure failing. Issued today, by the clock (UTC).
pub fn certificate(
    subject: &CertificateSubject,
    analysis: &Analysis,
) -> Result<Certificate, CertificateError> {
    certificate_issued_on(
        subject,
        analysis,
        &zerocal_inputs::bracket_file::today_utc(),
    )
}

/// [`certificate`] with its issue date given (`YYYY-MM-DD`).
///
/// # Errors
/// As [`certificate`], and an `issued_on` that is not a date.
pub fn certificate_issued_on(
    subject: &CertificateSubject,
    analysis: &Analysis,
    issued_on: &str,
) -> Result<Certificate, CertificateError> {
    check_subject(subject)?;
    check_date("issue date", issued_on)?;
    let (html, printed) = page::page(&sections::Context {
        subject,
        analysis,
        issued_on,
    })?;
    Ok(Certificate {
        html,
        printed_numbers: printed.into_numbers(),
    })
}

/// Writes the certificate, issued today, to `out` (its HTML) and `out` with the
/// extension `numbers` (every number it prints, one a line). Returns the two paths.
///
/// # Errors
/// As [`certificate`]; `out` named `.numbers`; a file that cannot be written.
pub fn write(
    subject: &CertificateSubject,
    analysis: &Analysis,
    out: &Path,
) -> Result<Vec<PathBuf>, CliError> {
    write_issued_on(
        subject,
        analysis,
        out,
        &zerocal_inputs::bracket_file::today_utc(),
    )
}

/// [`write`] with its issue date given (`YYYY-MM-DD`).
///
/// # Errors
/// As [`write`].
pub fn write_issued_on(
    subject: &CertificateSubject,
    analysis: &Analysis,
    out: &Path,
    issued_on: &str,
) -> Result<Vec<PathBuf>, CliError> {
    let numbers = out.with_extension("numbers");
    if numbers == out {
        return Err(CliError::Input(format!(
            "{}: the certificate's numbers go to FILE.numbers beside it; name the \
             certificate FILE.html",
            out.display()
        )));
    }
    let c = certificate_issued_on(subject, analysis, issued_on)?;
    let mut list = c.printed_numbers.join("\n");
    list.push('\n');
    for (path, bytes) in [(out, c.html.as_bytes()), (&numbers, list.as_bytes())] {
        std::fs::write(path, bytes)
            .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    }
    Ok(vec![out.to_path_buf(), numbers])
}

/// Refuses a record a certificate cannot state as it is.
fn check_subject(s: &CertificateSubject) -> Result<(), CertificateError> {
    if s.number.trim().is_empty() {
        return Err(CertificateError::Subject {
            field: "number",
            why: "empty: every certificate has its own number".into(),
        });
    }
    if s.serial.trim().is_empty() {
        return Err(CertificateError::Subject {
            field: "serial",
            why: "empty: a certificate names the robot it is for".into(),
        });
    }
    check_date("measured_on", &s.measured_on)?;
    for (field, hash) in [
        ("profile_sha256", &s.profile_sha256),
        ("export_sha256", &s.export_sha256),
    ] {
        if hash.len() != 64 || !hash.chars().all(|c| c.is_ascii_hexdigit()) {
            return Err(CertificateError::Subject {
                field,
                why: format!("'{hash}' is not a SHA-256 (64 hexadecimal digits)"),
            });
        }
    }
    if let Some(t) = s.tolerance_deg {
        if !TOLERANCE.contains(t) {
            return Err(CertificateError::Subject {
                field: "tolerance_deg",
                why: format!("{t} deg is outside (0, {MEMS_RANGE_DEG}] deg"),
            });
        }
    }
    Ok(())
}

/// Refuses anything but a calendar date `YYYY-MM-DD` (zerocal_civil's calendar, the
/// history's: 2026-02-31 is no date), saying what is wrong.
fn check_date(field: &'static str, date: &str) -> Result<(), CertificateError> {
    zerocal_civil::Date::parse(date)
        .map(|_| ())
        .map_err(|e| CertificateError::Subject {
            field,
            why: format!("'{date}' is not a calendar date YYYY-MM-DD: {e}"),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_calendar_date_passes() {
        for good in ["2026-11-27", "1999-01-31", "2024-02-29"] {
            assert!(check_date("d", good).is_ok(), "{good}");
        }
        for bad in [
            "2026-13-01",
            "2026-02-31",
            "2026-04-31",
            "2023-02-29",
            "2026-1-01",
            "26-11-27",
            "2026-11-27x",
            "2026/11/27",
            "",
        ] {
            assert!(check_date("d", bad).is_err(), "{bad}");
        }
    }
}
