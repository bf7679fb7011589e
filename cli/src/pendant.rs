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
use zerocal_core::procedure::profile::{JointName, PendantProfile};
use zerocal_core::procedure::{RobotName, MAX_PLAN_POSES};
use zerocal_profile::Profile;

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
    Ok(PendantProfile {
        robot,
        // The pendant's SCL3300 reads in the `axis` convention.
        convention: zerocal_core::model::Convention::Axis,
        arm: profile.arm,
        stage1_rad: [profile.stage1_joints_rad[0], profile.stage1_joints_rad[1]],
        display: profile.controller.display(names),
    })
}

/// The longest line the pendant's link takes (bytes): `zerocal_pendant::link::MAX_LINE`.
const LINK_LINE_BYTES: usize = 128;

/// The bytes of `profile set` … `end`.
///
/// # Errors
/// A line the pendant's buffer cannot hold (never, for the built-in profiles).
pub fn profile_request(p: &PendantProfile<f64>) -> Result<Vec<u8>, CliError> {
    let mut out = b"profile set\r\n".to_vec();
    for i in 0.. {
        match p.line(i) {
            None => break,
            // The pendant's line editor holds 128 bytes, the line ending included.
            Some(Ok(line)) if line.len() + 2 <= LINK_LINE_BYTES => {
                out.extend_from_slice(line.as_bytes());
                out.extend_from_slice(b"\r\n");
            }
            Some(_) => {
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

/// One request: its bytes, and the line that ends its answer (`None`: the answer ends
/// when the pendant falls silent).
#[derive(Clone, Debug)]
pub struct Request {
    /// What is sent.
    pub bytes: Vec<u8>,
    /// The start of the answer's last line on success (an `error:` line ends it too).
    pub done: Option<&'static str>,
}

/// The requests of an action, in order. A request is sent only once the one before it
/// was answered without an error (a plan must not follow a refused profile).
///
/// # Errors
/// An unknown robot, a plan that does not read or does not fit.
pub fn requests(action: &PendantAction) -> Result<Vec<Request>, CliError> {
    let silent = |bytes: &[u8]| Request {
        bytes: bytes.to_vec(),
        done: None,
    };
    Ok(match action {
        PendantAction::Status => vec![silent(b"status\r\n")],
        PendantAction::Export { .. } => vec![silent(b"export\r\n")],
        PendantAction::Erase => vec![Request {
            bytes: b"erase all\r\n".to_vec(),
            done: Some("ok: store erased"),
        }],
        PendantAction::LoadProfile { robot, plan } => {
            let profile = crate::robot::load(robot)?;
            let poses = match plan {
                Some(path) => crate::program::read_plan(path, &profile)?,
                None => crate::program::default_plan(robot, &default_timing()?)?,
            };
            vec![
                Request {
                    bytes: profile_request(&pendant_profile(&profile)?)?,
                    done: Some("ok: profile "),
                },
                Request {
                    bytes: plan_request(&poses)?,
                    done: Some("ok: plan set"),
                },
            ]
        }
    })
}

/// Whether `answer` is complete for `request`: its success line or an `error:` line.
pub fn answered(request: &Request, answer: &str) -> bool {
    answer.lines().any(|l| {
        let l = l.trim();
        l.starts_with("error:") || request.done.is_some_and(|d| l.starts_with(d))
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

/// Sends `request` and collects the answer until it is [`answered`] or, for a request
/// without a success line, the pendant has been silent for `silence`; at most `limit`
/// (a flash erase may hold a reply for half a second).
///
/// # Errors
/// The port's own errors.
pub fn exchange(
    port: &mut (impl Read + Write),
    request: &Request,
    silence: Duration,
    limit: Duration,
) -> std::io::Result<Vec<u8>> {
    port.write_all(&request.bytes)?;
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
                if request.done.is_some() && answered(request, &String::from_utf8_lossy(&answer)) {
                    break;
                }
                continue;
            }
            Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {}
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
        if request.done.is_none() && !answer.is_empty() && last.elapsed() >= silence {
            break;
        }
        if answer.is_empty() && start.elapsed() >= silence * 6 {
            break;
        }
    }
    Ok(answer)
}

/// Sends the requests in turn and returns each answer, stopping after the first that
/// failed (an `error:` line, or no success line): a plan must not follow a refused
/// profile.
///
/// # Errors
/// The port's own errors.
pub fn talk(
    port: &mut (impl Read + Write),
    requests: &[Request],
    silence: Duration,
) -> std::io::Result<Vec<String>> {
    let mut answers = Vec::new();
    for r in requests {
        let bytes = exchange(port, r, silence, Duration::from_secs(60))?;
        let answer = String::from_utf8_lossy(&bytes).into_owned();
        let failed = pendant_error(&answer).is_some() || !answered(r, &answer);
        answers.push(answer);
        if failed {
            break;
        }
    }
    Ok(answers)
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
    let answers = talk(&mut port, &requests, Duration::from_millis(500))
        .map_err(|e| CliError::Input(format!("{}: {e}", args.port)))?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::VecDeque;

    /// A port that answers each request with the next scripted reply, and times out
    /// when it has nothing to say.
    struct Scripted {
        replies: VecDeque<&'static [u8]>,
        pending: VecDeque<u8>,
        written: Vec<u8>,
    }

    impl Write for Scripted {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.written.extend_from_slice(buf);
            if let Some(r) = self.replies.pop_front() {
                self.pending.extend(r.iter().copied());
            }
            Ok(buf.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl Read for Scripted {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            if self.pending.is_empty() {
                std::thread::sleep(Duration::from_millis(2));
                return Err(std::io::ErrorKind::TimedOut.into());
            }
            let n = buf.len().min(self.pending.len());
            for b in buf.iter_mut().take(n) {
                *b = self.pending.pop_front().unwrap_or(0);
            }
            Ok(n)
        }
    }

    #[test]
    fn a_refused_profile_stops_before_the_plan() {
        let requests = requests(&PendantAction::LoadProfile {
            robot: "abb-irb140".into(),
            plan: None,
        })
        .unwrap();
        assert_eq!(requests.len(), 2);
        let mut port = Scripted {
            replies: VecDeque::from([
                &b"ok: send the profile's lines, then 'end'\r\nerror: a session is in progress; 'clear' first (profile unchanged)\r\n"[..],
                &b"ok: plan set, 24 poses\r\n"[..],
            ]),
            pending: VecDeque::new(),
            written: Vec::new(),
        };
        let answers = talk(&mut port, &requests, Duration::from_millis(20)).unwrap();
        assert_eq!(answers.len(), 1, "the plan was not sent");
        assert!(!String::from_utf8_lossy(&port.written).contains("plan set"));
        let e = check(
            &PendantAction::LoadProfile {
                robot: "abb-irb140".into(),
                plan: None,
            },
            &answers,
        )
        .unwrap_err();
        assert_eq!(e.exit_code(), 3);
        assert!(e.to_string().contains("session is in progress"), "{e}");
    }

    #[test]
    fn an_upload_waits_for_its_line_past_a_silence() {
        // The first 'ok:' of 'profile set' is not the answer's end: the exchange goes on
        // through a pause (a flash erase) to 'ok: profile'.
        let request = Request {
            bytes: b"profile set\r\n".to_vec(),
            done: Some("ok: profile "),
        };
        assert!(!answered(
            &request,
            "ok: send the profile's lines, then 'end'\r\n"
        ));
        assert!(answered(
            &request,
            "ok: send ...\r\nok: profile x stored\r\n"
        ));
        assert!(answered(
            &request,
            "error: profile line 2: bad 'joint' values\r\n"
        ));
    }
}
