//! `zerocal profile check PROFILE`: what a profile lets the product do, each job tried
//! on the profile itself (the default plan made, every program format the family runs
//! built, the pendant's `profile set` and `plan set` lines made), and what is missing
//! with what each item costs: the profile's own `missing` lines, and what the checks
//! find (offsets in model terms only, no offset unit, no sag masses, no bracket design,
//! a program or the pendant refusing it).
//!
//! The exit status says how bad it is ([`Severity`]): 0 nothing missing, 1 usable with
//! what is listed, 3 no session can be planned with it (2, as everywhere, a profile
//! that does not read).

use clap::Args;
use serde::Serialize;
use std::fmt::Write;
use zerocal_inputs::error::CliError;
use zerocal_profile::{OffsetUnit, Profile};
use zerocal_programs::plan::{make_plan, PlanArgs, SessionPlan};
use zerocal_programs::program::Format;

/// Arguments of `zerocal profile check`.
#[derive(Args, Debug, Clone)]
pub struct CheckArgs {
    /// The profile: a TOML file or a built-in name.
    #[arg(value_name = "PROFILE")]
    pub profile: String,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
}

/// How much a profile lets zerocal do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Severity {
    /// Every job runs, in the controller's terms, nothing missing that costs one.
    Complete,
    /// The session runs; something is missing, each item listed with its cost.
    Limited,
    /// No session can be planned with it.
    NoSession,
}

impl Severity {
    /// The process exit status.
    pub fn exit_code(self) -> u8 {
        match self {
            Severity::Complete => 0,
            Severity::Limited => 1,
            Severity::NoSession => 3,
        }
    }
}

/// Whether a job runs with the profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Runs, nothing missing.
    Yes,
    /// Runs, with less than a complete profile gives (the detail says what).
    Limited,
    /// Does not run (the detail says why).
    No,
}

/// One job and what the profile lets it do.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Capability {
    /// The job (`plan`, `session`, `program`, ...).
    pub job: &'static str,
    /// Whether it runs.
    pub status: Status,
    /// What it gives, or what stops it, and what that costs.
    pub detail: String,
}

/// `zerocal profile check --json`.
#[derive(Clone, Debug, Serialize)]
pub struct CheckReport {
    /// The profile's name.
    pub profile: String,
    /// Its title.
    pub title: String,
    /// Its family.
    pub family: &'static str,
    /// How bad it is.
    pub severity: Severity,
    /// The exit status.
    pub exit_status: u8,
    /// Each job.
    pub capabilities: Vec<Capability>,
    /// The profile's own `missing` lines (what no source gave, with its cost).
    pub missing: Vec<String>,
}

fn cap(job: &'static str, status: Status, detail: impl Into<String>) -> Capability {
    Capability {
        job,
        status,
        detail: detail.into(),
    }
}

/// The default plan of the profile at `path` (what `zerocal plan --robot PATH` makes).
fn default_plan(path: &str) -> Result<SessionPlan, CliError> {
    let args =
        PlanArgs::from_flags(&["--robot", path]).map_err(|e| CliError::Input(e.to_string()))?;
    make_plan(&args)
}

/// In what terms a session gives its offsets, and whether that is the controller's own.
fn session_terms(p: &Profile) -> (Status, String) {
    if !p.controller_stated {
        return (
            Status::Limited,
            String::from("offsets in model terms only (no [controller] table): the model's joint angle changes in degrees, to be turned into the controller's sign, zero, coupling and unit by hand"),
        );
    }
    if !p.offset_entry_stated {
        return (
            Status::Limited,
            String::from("offsets in the controller's joint degrees; in what unit and where the controller takes them is not stated (no offset_unit, offset_where)"),
        );
    }
    match p.controller.unit {
        OffsetUnit::MotorRadians(None) | OffsetUnit::Counts(None) => (
            Status::Limited,
            format!(
                "offsets in the controller's joint degrees, not in its {} (no gear_ratio or counts_per_deg): multiply by the controller's own ratio; entered at {}",
                p.controller.unit.name(),
                p.controller.offset_where
            ),
        ),
        _ => (
            Status::Yes,
            format!(
                "offsets in the controller's terms ({}), entered at {}",
                p.controller.unit.name(),
                p.controller.offset_where
            ),
        ),
    }
}

/// Every job tried on the profile.
fn capabilities(path: &str, p: &Profile) -> (Vec<Capability>, bool) {
    let mut out = Vec::new();
    let sp = match default_plan(path) {
        Ok(sp) => sp,
        Err(e) => {
            let why = format!("the default plan is refused: {e}");
            out.push(cap("plan", Status::No, why.clone()));
            for job in [
                "simulate", "session", "program", "check", "restore", "pendant",
            ] {
                out.push(cap(job, Status::No, "no plan: see plan"));
            }
            return (out, false);
        }
    };
    let worst = sp.k2_deg.iter().fold(0.0f64, |m, v| m.max(*v));
    out.push(cap(
        "plan",
        Status::Yes,
        format!(
            "{} poses, predicted U(k=2) at most {worst:.4} deg, robot time {:.1} min",
            sp.plan.poses_rad.len(),
            sp.time.total_s / 60.0
        ),
    ));
    let lengths = p.mass_model().is_some();
    out.push(if lengths {
        cap(
            "simulate",
            Status::Yes,
            "a whole session on the simulated arm, and the positioning test",
        )
    } else {
        cap(
            "simulate",
            Status::Limited,
            "a whole session; no positioning test (the arm has no lengths)",
        )
    });
    let (status, terms) = session_terms(p);
    out.push(cap("session", status, terms.clone()));
    out.push(match p.masses {
        Some(_) => cap("sag model", Status::Yes, "the sources' link masses and centres of mass"),
        None if lengths => cap(
            "sag model",
            Status::Limited,
            "no link masses: links of uniform mass per metre (the stated default), so the sag correction, its budget term and the stage-1 pose free of gravity torque are that model's, not this arm's",
        ),
        None => cap("sag model", Status::Limited, "no lengths: no sag model"),
    });
    out.push(program_capability(p, &sp));
    for job in ["check", "restore"] {
        out.push(cap(job, status, format!("as the session: {terms}")));
    }
    out.push(pendant_capability(p, &sp));
    out.push(match &p.flange_interface {
        Some(f) => cap(
            "bracket",
            Status::Yes,
            format!("the flange bracket drilled to {}", f.iso9409.designation()),
        ),
        None => cap(
            "bracket",
            Status::No,
            "no [flange] iso9409 with its source: `zerocal bracket` makes no flange bracket design; its holes and key come from the robot's own flange",
        ),
    });
    (out, true)
}

/// The program in every format the profile's family runs, built as `zerocal program`
/// builds it (its safety checks included).
fn program_capability(p: &Profile, sp: &SessionPlan) -> Capability {
    let timing = zerocal_programs::timing::TimingArgs::default();
    let (mut written, mut refused) = (Vec::new(), Vec::new());
    for format in Format::for_profile(p) {
        match zerocal_programs::program::build(
            p.clone(),
            &sp.plan.poses_rad,
            format,
            String::from("ZCCHECK"),
            &timing,
        ) {
            Ok(_) => written.push(format.to_string()),
            Err(e) => refused.push(format!("{format}: {e}")),
        }
    }
    let terms = if p.controller_stated {
        ""
    } else {
        " in the model's angles (no [controller]: right only where the controller shows those)"
    };
    match (written.is_empty(), refused.is_empty()) {
        (false, true) if p.controller_stated => cap(
            "program",
            Status::Yes,
            format!("--format {}", written.join(", ")),
        ),
        (false, _) => cap(
            "program",
            Status::Limited,
            format!(
                "--format {}{terms}{}",
                written.join(", "),
                if refused.is_empty() {
                    String::new()
                } else {
                    format!("; refused: {}", refused.join("; "))
                }
            ),
        ),
        (true, _) => cap(
            "program",
            Status::No,
            format!(
                "no robot program (the poses must be taught by hand): {}",
                refused.join("; ")
            ),
        ),
    }
}

/// The pendant's `load-profile`: its profile and plan lines made as they would be sent.
fn pendant_capability(p: &Profile, sp: &SessionPlan) -> Capability {
    let made = zerocal_link::pendant_profile(p, zerocal_core::bracket::Brackets::default())
        .and_then(|pp| zerocal_link::profile_request(&pp))
        .and_then(|_| zerocal_link::plan_request(&sp.plan.poses_rad));
    match made {
        Ok(_) => cap(
            "pendant",
            Status::Yes,
            "load-profile: the profile and its plan fit the pendant",
        ),
        Err(e) => cap(
            "pendant",
            Status::No,
            format!("load-profile refuses it: {e}; the pendant cannot guide this session"),
        ),
    }
}

/// Checks the profile: the report (text or JSON) and its severity.
///
/// # Errors
/// A profile that does not read (status 2, naming the key).
pub fn run(args: &CheckArgs) -> Result<(String, Severity), CliError> {
    let p = zerocal_inputs::robot::load(&args.profile)?;
    let (capabilities, plans) = capabilities(&args.profile, &p);
    let severity = if !plans {
        Severity::NoSession
    } else if capabilities.iter().all(|c| c.status == Status::Yes) {
        Severity::Complete
    } else {
        Severity::Limited
    };
    let report = CheckReport {
        profile: p.name.clone(),
        title: p.title.clone(),
        family: p.family.name(),
        severity,
        exit_status: severity.exit_code(),
        capabilities,
        missing: p.missing.clone(),
    };
    let out = if args.json {
        serde_json::to_string_pretty(&report)
            .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")))?
    } else {
        render(&report)
    };
    Ok((out, severity))
}

/// The report as text.
pub fn render(r: &CheckReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "profile {} ({}), family {}",
        r.profile, r.title, r.family
    );
    let _ = writeln!(out, "\nwhat it lets zerocal do:");
    let width = r
        .capabilities
        .iter()
        .map(|c| c.job.len())
        .max()
        .unwrap_or(0);
    for c in &r.capabilities {
        let status = match c.status {
            Status::Yes => "yes",
            Status::Limited => "limited",
            Status::No => "no",
        };
        let _ = writeln!(out, "  {:<width$}  {status:<7}  {}", c.job, c.detail);
    }
    let _ = writeln!(
        out,
        "\nmissing ({}), as the profile says, with what it costs:",
        r.missing.len()
    );
    for m in &r.missing {
        let _ = writeln!(out, "  - {m}");
    }
    let verdict = match r.severity {
        Severity::Complete => "complete: every job, in the controller's terms",
        Severity::Limited => "usable: the session runs; what is limited or missing is listed above",
        Severity::NoSession => "no session can be planned with this profile (see plan)",
    };
    let _ = writeln!(out, "\n{verdict} (exit status {})", r.exit_status);
    out
}
