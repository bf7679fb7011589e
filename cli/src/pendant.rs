//! `zerocal pendant --port PORT ACTION`: the desktop end of the pendant's USB serial
//! link (README, "The USB link").
//!
//! - `status`: the pendant's `status` lines.
//! - `load-profile ROBOT [--plan FILE]`: the robot profile (`profile set`, the lines of
//!   `zerocal_core::procedure::profile`), then the plan `zerocal program --robot ROBOT`
//!   drives (or FILE, `zerocal plan --csv` output), so the pendant's screens, the
//!   robot program and the export all name the same robot and poses.
//! - `export [--out FILE]`: the session as `zerocal session` reads it.
//! - `erase`: `erase all` (session, bias, last result, profile, plan).
//!
//! Each action is a list of requests (bytes) and a check of the answers; the I/O is
//! a serial port opened raw. The requests and checks are tested against the pendant's
//! own link task on the desktop (`zerocal_pendant::host::runner::converse`).

use std::io::{Read, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::{Args, Subcommand};
use zerocal_core::model::JOINTS;
use zerocal_core::procedure::profile::{ControllerDisplay, JointName, PendantProfile};
use zerocal_core::procedure::{RobotName, MAX_PLAN_POSES};
use zerocal_profile::{Coupling, Profile};

use crate::error::CliError;

/// `zerocal pendant`.
#[derive(Args, Debug)]
pub struct PendantArgs {
    /// The pendant's serial port (`/dev/ttyACM0`, `COM5`).
    #[arg(long, value_name = "PORT")]
    pub port: String,
    /// What to do.
    #[command(subcommand)]
    pub action: PendantAction,
}

/// What `zerocal pendant` does.
#[derive(Subcommand, Debug, Clone)]
pub enum PendantAction {
    /// Print the pendant's status.
    Status,
    /// Store a robot profile on the pendant and its plan (clears the session).
    LoadProfile {
        /// Built-in profile name (`zerocal robots`) or a TOML file.
        robot: String,
        /// The plan (`zerocal plan --csv`); default: the one `zerocal program` drives.
        #[arg(long, value_name = "FILE")]
        plan: Option<PathBuf>,
    },
    /// Save the session (`zerocal session` reads it).
    Export {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Erase the pendant's store: session, bias, last result, profile and plan.
    Erase,
}

/// The profile as the pendant keeps it.
///
/// # Errors
/// A name or a joint name too long for the pendant.
pub fn pendant_profile(profile: &Profile) -> Result<PendantProfile<f64>, CliError> {
    let mut robot = RobotName::new();
    robot.push_str(&profile.name).map_err(|()| {
        CliError::Input(format!(
            "robot profile name '{}' is longer than the pendant's 32 bytes",
            profile.name
        ))
    })?;
    let mut names: [JointName; JOINTS] = Default::default();
    for (n, j) in names.iter_mut().zip(&profile.joints) {
        n.push_str(&j.name).map_err(|()| {
            CliError::Input(format!(
                "joint name '{}' is longer than the pendant's 3 bytes",
                j.name
            ))
        })?;
    }
    let c = &profile.controller;
    Ok(PendantProfile {
        robot,
        // The pendant's SCL3300 reads in the `axis` convention.
        convention: zerocal_core::model::Convention::Axis,
        arm: profile.arm,
        stage1_rad: [profile.stage1_joints_rad[0], profile.stage1_joints_rad[1]],
        display: ControllerDisplay {
            names,
            sign: c.sign,
            zero_deg: c.zero_deg,
            j3_minus_j2: c.coupling == Coupling::J3MinusJ2,
        },
    })
}

/// The bytes of `profile set` … `end`.
///
/// # Errors
/// A line the pendant's buffer cannot hold (never, for the built-in profiles).
pub fn profile_request(p: &PendantProfile<f64>) -> Result<Vec<u8>, CliError> {
    let mut out = b"profile set\r\n".to_vec();
    for i in 0.. {
        match p.line(i) {
            None => break,
            Some(Ok(line)) => {
                out.extend_from_slice(line.as_bytes());
                out.extend_from_slice(b"\r\n");
            }
            Some(Err(_)) => {
                return Err(CliError::Input(format!(
                    "profile line {} does not fit the pendant's line",
                    i + 1
                )))
            }
        }
    }
    Ok(out)
}

/// The bytes of `plan set` … `end`: every joint in model degrees.
///
/// # Errors
/// More poses than the pendant holds.
pub fn plan_request(poses_rad: &[[f64; JOINTS]]) -> Result<Vec<u8>, CliError> {
    if poses_rad.len() > MAX_PLAN_POSES {
        return Err(CliError::Input(format!(
            "{} poses: the pendant holds at most {MAX_PLAN_POSES} (each is captured twice)",
            poses_rad.len()
        )));
    }
    let mut out = b"plan set\r\n".to_vec();
    for q in poses_rad {
        let row: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
        out.extend_from_slice(row.join(",").as_bytes());
        out.extend_from_slice(b"\r\n");
    }
    out.extend_from_slice(b"end\r\n");
    Ok(out)
}

/// The requests of an action, in order.
///
/// # Errors
/// An unknown robot, a plan that does not read or does not fit.
pub fn requests(action: &PendantAction) -> Result<Vec<Vec<u8>>, CliError> {
    Ok(match action {
        PendantAction::Status => vec![b"status\r\n".to_vec()],
        PendantAction::Export { .. } => vec![b"export\r\n".to_vec()],
        PendantAction::Erase => vec![b"erase all\r\n".to_vec()],
        PendantAction::LoadProfile { robot, plan } => {
            let profile = crate::robot::load(robot)?;
            let poses = match plan {
                Some(path) => crate::program::read_plan(path, &profile)?,
                None => crate::program::default_plan(robot, &default_timing()?)?,
            };
            vec![
                profile_request(&pendant_profile(&profile)?)?,
                plan_request(&poses)?,
            ]
        }
    })
}

fn default_timing() -> Result<crate::timing::TimingArgs, CliError> {
    use clap::Parser;
    #[derive(Parser)]
    struct Defaults {
        #[command(flatten)]
        timing: crate::timing::TimingArgs,
    }
    Defaults::try_parse_from(["timing"])
        .map(|d| d.timing)
        .map_err(|e| CliError::Input(e.to_string()))
}

/// The pendant's `error:` line in an answer, if any.
fn pendant_error(answer: &str) -> Option<&str> {
    answer
        .lines()
        .find_map(|l| l.trim().strip_prefix("error:"))
        .map(str::trim)
}

/// Checks the answers of an action and returns what to print.
///
/// # Errors
/// No answer (exit 2: the port is not a pendant, or it is not ready); an `error:` from
/// the pendant (exit 3, with its words).
pub fn check(action: &PendantAction, answers: &[String]) -> Result<String, CliError> {
    if answers.iter().any(|a| a.trim().is_empty()) {
        return Err(CliError::Input(
            "the pendant did not answer: is this its port, and is it on a capture or result screen?"
                .into(),
        ));
    }
    if let Some(e) = answers.iter().find_map(|a| pendant_error(a)) {
        return Err(CliError::Refused(format!("the pendant refused: {e}")));
    }
    let text = answers.concat().replace("\r\n", "\n");
    Ok(match action {
        PendantAction::LoadProfile { .. } => {
            let oks: Vec<&str> = text
                .lines()
                .filter(|l| l.starts_with("ok: profile") || l.starts_with("ok: plan set"))
                .collect();
            if oks.len() != 2 {
                return Err(CliError::Refused(format!(
                    "the pendant did not confirm the profile and the plan:\n{text}"
                )));
            }
            format!("{}\n", oks.join("\n"))
        }
        PendantAction::Export { .. } => {
            if !text.starts_with("# zerocal pendant export") {
                return Err(CliError::Refused(format!(
                    "not a pendant export:\n{}",
                    text.lines().next().unwrap_or("")
                )));
            }
            text
        }
        PendantAction::Status | PendantAction::Erase => text,
    })
}

/// Sends `request` and collects the answer until the pendant has been silent for
/// `silence` (or `limit` has passed).
///
/// # Errors
/// The port's own errors.
pub fn exchange(
    port: &mut (impl Read + Write),
    request: &[u8],
    silence: Duration,
    limit: Duration,
) -> std::io::Result<Vec<u8>> {
    port.write_all(request)?;
    port.flush()?;
    let start = Instant::now();
    let mut last = Instant::now();
    let mut answer = Vec::new();
    let mut buf = [0_u8; 512];
    while start.elapsed() < limit {
        match port.read(&mut buf) {
            Ok(0) => {}
            Ok(n) => {
                answer.extend_from_slice(&buf[..n]);
                last = Instant::now();
                continue;
            }
            Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {}
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
        if !answer.is_empty() && last.elapsed() >= silence {
            break;
        }
        if answer.is_empty() && start.elapsed() >= silence * 6 {
            break;
        }
    }
    Ok(answer)
}

/// Runs `zerocal pendant`.
///
/// # Errors
/// A port that does not open, no answer, the pendant's refusal.
pub fn run(args: &PendantArgs) -> Result<String, CliError> {
    let requests = requests(&args.action)?;
    // A USB CDC port ignores the baud rate; opened raw (no echo, no line editing).
    let mut port = serialport::new(&args.port, 115_200)
        .timeout(Duration::from_millis(50))
        .open()
        .map_err(|e| CliError::Input(format!("{}: {e}", args.port)))?;
    let mut answers = Vec::new();
    for r in &requests {
        let bytes = exchange(
            &mut port,
            r,
            Duration::from_millis(500),
            Duration::from_secs(60),
        )
        .map_err(|e| CliError::Input(format!("{}: {e}", args.port)))?;
        answers.push(String::from_utf8_lossy(&bytes).into_owned());
    }
    let out = check(&args.action, &answers)?;
    if let PendantAction::Export { out: Some(path) } = &args.action {
        std::fs::write(path, &out)
            .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
        return Ok(format!(
            "wrote {} (read it with `zerocal session {}`)\n",
            path.display(),
            path.display()
        ));
    }
    Ok(out)
}
