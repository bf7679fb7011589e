//! `zerocal serve [--db PATH|URL] [--listen ADDR:PORT]`: the plant's web application
//! over the history (`zerocal_web`), with the CLI's own code solving uploaded exports,
//! rendering certificates and plotting robots ([`CliProduct`]); and
//! `zerocal serve --add-user NAME --role ROLE`, which makes an account (its password
//! from `ZEROCAL_NEW_PASSWORD` or the first line of standard input, never the
//! command line, where every user of the machine reads it). docs/web.md.

use clap::{Args, ValueEnum};
use std::io::BufRead;
use std::net::SocketAddr;
use std::path::PathBuf;
use zerocal_history::{History, NewRecord, Record, Role};
use zerocal_inputs::error::CliError;

/// The environment variable `--add-user` reads the new password from, if set.
pub const PASSWORD_ENV: &str = "ZEROCAL_NEW_PASSWORD";

/// `--interval-days`: a day to ten years.
const INTERVAL_DAYS: zerocal_inputs::args::CountIn<u32> =
    zerocal_inputs::args::CountIn::new(1, 3653);

/// `--interval-days-for MODEL=DAYS`: a robot profile's name and its interval, in the
/// range of `--interval-days`.
///
/// # Errors
/// Not `MODEL=DAYS`, an empty or blank-holding model name, days not a whole number in
/// the range: the message names the value.
fn model_interval(text: &str) -> Result<(String, u32), String> {
    let Some((model, days)) = text.split_once('=') else {
        return Err(format!(
            "'{text}' is not MODEL=DAYS (a robot profile's name, e.g. kuka-kr6-r900-sixx=180)"
        ));
    };
    let model = model.trim();
    if model.is_empty() || model.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err(format!(
            "'{text}': the model {model:?} is not a robot profile's name (no blanks, not empty)"
        ));
    }
    let days = INTERVAL_DAYS
        .check(days)
        .map_err(|e| format!("'{text}': {e}"))?;
    let days = u32::try_from(days).map_err(|_| format!("'{text}': too many days"))?;
    Ok((model.to_owned(), days))
}

/// The plant's interval and each model's, one interval a model.
///
/// # Errors
/// A model given twice.
fn intervals(args: &ServeArgs) -> Result<zerocal_web::Intervals, CliError> {
    let mut by_model = std::collections::BTreeMap::new();
    for (model, days) in &args.interval_days_for {
        if by_model.insert(model.clone(), *days).is_some() {
            return Err(CliError::Input(format!(
                "serve: --interval-days-for names {model} twice: one interval a model"
            )));
        }
    }
    Ok(zerocal_web::Intervals {
        days: args.interval_days,
        by_model,
    })
}

/// A user's role (docs/web.md).
#[derive(ValueEnum, Debug, Clone, Copy)]
pub enum RoleArg {
    /// Records sessions (uploads exports).
    Technician,
    /// Checks a measured session.
    Reviewer,
    /// Authorizes a checked session.
    Authorizer,
    /// Manages the users.
    Admin,
}

impl RoleArg {
    fn role(self) -> Role {
        match self {
            Self::Technician => Role::Technician,
            Self::Reviewer => Role::Reviewer,
            Self::Authorizer => Role::Authorizer,
            Self::Admin => Role::Admin,
        }
    }
}

/// Arguments of `zerocal serve`.
#[derive(Args, Debug, Clone)]
pub struct ServeArgs {
    /// The address and port to listen on, ADDR:PORT. Another address than the
    /// loopback's is refused without --behind-tls-proxy: the passwords would cross the
    /// network in clear.
    #[arg(long, value_name = "ADDR:PORT", default_value = "127.0.0.1:8080")]
    pub listen: SocketAddr,
    /// A TLS reverse proxy serves this server (docs/web.md): cookies are marked
    /// Secure, and a non-loopback --listen is allowed (for the proxy to reach).
    #[arg(long)]
    pub behind_tls_proxy: bool,
    /// The days between calibrations: a robot is due this many days after its last
    /// session (without it the fleet page shows no due dates). Range: [1, 3653] days.
    #[arg(long, value_name = "DAYS", value_parser = INTERVAL_DAYS)]
    pub interval_days: Option<u32>,
    /// A robot model's own interval, MODEL=DAYS (MODEL a robot profile's name, as the
    /// records name it): its robots are due DAYS after their last session, whatever
    /// --interval-days says; repeatable, one a model. DAYS: [1, 3653].
    #[arg(long, value_name = "MODEL=DAYS", value_parser = model_interval)]
    pub interval_days_for: Vec<(String, u32)>,
    /// The issuer's configuration for the certificates (as `zerocal certificate
    /// --config`). Default: $XDG_CONFIG_HOME/zerocal/certificate.toml, else
    /// ~/.config/zerocal/certificate.toml.
    #[arg(long, value_name = "FILE")]
    pub certificate_config: Option<PathBuf>,
    /// The Chromium that prints certificates to PDF (headless, `--print-to-pdf`).
    /// Default: `chromium` on PATH; without one, the pages offer no PDF.
    #[arg(long, value_name = "FILE")]
    pub chromium: Option<PathBuf>,
    /// Make this account instead of serving (with --role); its password from
    /// ZEROCAL_NEW_PASSWORD, else the first line of standard input.
    #[arg(long, value_name = "NAME", requires = "role")]
    pub add_user: Option<String>,
    /// The new account's role.
    #[arg(long, value_enum, requires = "add_user")]
    pub role: Option<RoleArg>,
    #[command(flatten)]
    pub db: zerocal_analysis::db::DbArg,
}

/// The CLI's code, as the web application calls it.
pub struct CliProduct {
    /// The issuer's configuration file for certificates.
    pub certificate_config: Option<PathBuf>,
}

fn message(e: CliError) -> String {
    e.to_string()
}

impl zerocal_web::Product for CliProduct {
    fn solve_export(
        &self,
        export: &[u8],
        serial: &str,
        operator: &str,
    ) -> Result<NewRecord, String> {
        if export.len() > zerocal_inputs::input::MAX_EXPORT_BYTES {
            return Err(format!(
                "the export has {} bytes; a pendant's export has at most {}",
                export.len(),
                zerocal_inputs::input::MAX_EXPORT_BYTES
            ));
        }
        let args =
            zerocal_analysis::session::SessionArgs::for_export(PathBuf::from("uploaded export"));
        let analysis = zerocal_analysis::session::analyse(&args, export).map_err(message)?;
        let meta = zerocal_analysis::db::RecordMeta {
            operator: Some(operator.to_owned()),
            measured_on: None,
        };
        zerocal_analysis::session::session_record(&analysis, export, serial, &meta).map_err(message)
    }

    fn certificate_html(
        &self,
        history: &mut History,
        record: &Record,
        by: zerocal_history::CertificateRequest<'_>,
    ) -> Result<String, String> {
        let path =
            zerocal_records::certificate::issuer_config_path(self.certificate_config.as_deref())
                .map_err(message)?;
        let (subject, analysis, issued_on) =
            zerocal_records::certificate::issue(history, record, &path, (None, None), Some(by))
                .map_err(message)?;
        zerocal_records::certificate::certificate_issued_on(&subject, &analysis, &issued_on)
            .map(|c| c.html)
            .map_err(|e| e.to_string())
    }

    fn robot_plots_svg(&self, serial: &str, records: &[Record]) -> Result<Vec<String>, String> {
        // The history's plots are written as files; a directory of this call's own.
        let mut tag = [0_u8; 8];
        getrandom::fill(&mut tag).map_err(|e| format!("no random source: {e}"))?;
        let tag: String = tag.iter().map(|b| format!("{b:02x}")).collect();
        let dir = std::env::temp_dir().join(format!("zerocal-serve-plots-{tag}"));
        let written = zerocal_records::history::plots(&dir, serial, records);
        let read = written.map_err(message).and_then(|files| {
            files
                .iter()
                .map(|f| std::fs::read_to_string(f).map_err(|e| format!("{}: {e}", f.display())))
                .collect()
        });
        // Nothing of it is kept; a failed removal leaves a temporary directory only.
        let _ = std::fs::remove_dir_all(&dir);
        read
    }

    fn reducer_notes(&self, records: &[Record]) -> Vec<String> {
        zerocal_analysis::session::reducer_trend::changes_in(records)
            .iter()
            .map(zerocal_analysis::session::reducer_trend::ReducerChange::line)
            .collect()
    }
}

/// The new account's password: `ZEROCAL_NEW_PASSWORD`, else standard input's first line.
fn new_password() -> Result<String, CliError> {
    if let Ok(p) = std::env::var(PASSWORD_ENV) {
        return Ok(p);
    }
    let mut line = String::new();
    std::io::stdin()
        .lock()
        .read_line(&mut line)
        .map_err(|e| CliError::Input(format!("serve --add-user: standard input: {e}")))?;
    Ok(line.trim_end_matches(['\r', '\n']).to_owned())
}

/// The executable `name` in a directory of PATH.
fn on_path(name: &str) -> Option<PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|d| d.join(name))
        .find(|p| p.is_file())
}

/// Runs `zerocal serve`.
///
/// # Errors
/// The history does not open; an account that exists or a password that is empty; a
/// non-loopback address without --behind-tls-proxy; an address that cannot be bound.
pub fn run(args: &ServeArgs) -> Result<String, CliError> {
    let intervals = intervals(args)?;
    let at = args.db.location()?;
    let mut history = args.db.open()?;
    if let (Some(name), Some(role)) = (&args.add_user, args.role) {
        let phc = zerocal_web::hash_password(&new_password()?)
            .map_err(|e| CliError::Input(format!("serve --add-user: {e}")))?;
        let actor = match std::env::var("USER") {
            Ok(u) if !u.is_empty() => format!("zerocal serve --add-user (OS user {u})"),
            _ => "zerocal serve --add-user".to_owned(),
        };
        let user = history
            .add_user(&actor, name, role.role(), &phc)
            .map_err(zerocal_analysis::db::history_failed)?;
        return Ok(format!(
            "user {} ({}) added to {}",
            user.name,
            user.role.as_str(),
            history.location()
        ));
    }
    if !args.listen.ip().is_loopback() && !args.behind_tls_proxy {
        return Err(CliError::Input(format!(
            "serve: --listen {} is not a loopback address: passwords and sessions would cross the network in clear; serve it behind a TLS reverse proxy and say so with --behind-tls-proxy (docs/web.md)",
            args.listen
        )));
    }
    drop(history);
    eprintln!("zerocal serve: {} on http://{}", at, args.listen);
    zerocal_web::serve(
        args.listen,
        zerocal_web::Config {
            db: at,
            secure_cookies: args.behind_tls_proxy,
            max_upload_bytes: zerocal_inputs::input::MAX_EXPORT_BYTES
                + zerocal_web::MULTIPART_OVERHEAD_BYTES,
            intervals,
            chromium: args.chromium.clone().or_else(|| on_path("chromium")),
        },
        Box::new(CliProduct {
            certificate_config: args.certificate_config.clone(),
        }),
    )
    .map_err(|e| CliError::Refused(format!("serve: {e}")))?;
    Ok(String::new())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_models_interval_is_model_equals_days_in_the_range_and_else_refused_naming_it() {
        assert_eq!(
            model_interval("kuka-kr6-r900-sixx=180"),
            Ok(("kuka-kr6-r900-sixx".to_owned(), 180))
        );
        assert_eq!(model_interval("ur5e=3653"), Ok(("ur5e".to_owned(), 3653)));
        for (bad, says) in [
            ("kuka-kr6-r900-sixx", "is not MODEL=DAYS"),
            ("kuka-kr6-r900-sixx:180", "is not MODEL=DAYS"),
            ("=180", "is not a robot profile's name"),
            ("kuka kr6=180", "is not a robot profile's name"),
            ("ur5e=0", "outside the range"),
            ("ur5e=3654", "outside the range"),
            ("ur5e=half", "is not a whole number"),
            ("ur5e=-5", "is not a whole number"),
        ] {
            let e = model_interval(bad).unwrap_err();
            assert!(e.contains(bad) && e.contains(says), "{bad}: {e}");
        }
    }

    #[test]
    fn a_model_given_two_intervals_is_refused() {
        use clap::Parser;
        #[derive(Parser)]
        struct Cli {
            #[command(flatten)]
            serve: ServeArgs,
        }
        let parse = |extra: &[&str]| {
            let mut argv = vec!["zerocal", "--interval-days", "365"];
            argv.extend_from_slice(extra);
            Cli::try_parse_from(argv).unwrap().serve
        };
        let args = parse(&[
            "--interval-days-for",
            "kuka-kr6-r900-sixx=180",
            "--interval-days-for",
            "ur5e=730",
        ]);
        let i = intervals(&args).unwrap();
        assert_eq!(i.days, Some(365));
        assert_eq!(i.of("kuka-kr6-r900-sixx"), Some((180, true)));
        assert_eq!(i.of("ur5e"), Some((730, true)));
        assert_eq!(i.of("fanuc-m10ia"), Some((365, false)));
        let twice = parse(&[
            "--interval-days-for",
            "ur5e=180",
            "--interval-days-for",
            "ur5e=730",
        ]);
        let e = intervals(&twice).unwrap_err().to_string();
        assert!(e.contains("ur5e twice"), "{e}");
    }
}
