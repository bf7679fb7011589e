//! `zerocal pendant --port PORT ACTION`: the desktop end of the pendant's USB serial
//! link (docs/pendant-link.md), one verb for each of the link's commands ([`verb`]),
//! so that no procedure needs a serial terminal.
//!
//! - `status`: the pendant's `status` lines.
//! - `load-profile ROBOT [--plan FILE] [--brackets FILE]`: the robot profile (`profile
//!   set`, the lines of `zerocal_procedure::profile`: its kinematics, display, masses
//!   and the brackets' calibrations from the `--brackets` file, [`zerocal_inputs::bracket_file`]),
//!   then the plan `zerocal program --robot ROBOT` drives (or FILE, `zerocal plan
//!   --csv` output), so the pendant's screens, the robot program and the export all
//!   name the same robot and poses, and the pendant's fit is `zerocal session`'s.
//! - `profile [--out FILE]`, `plan [--out FILE]`: what the pendant holds (`profile`,
//!   `plan`), the plan as `--plan` takes it back.
//! - `export [--out FILE] [--results FILE]`: the session as `zerocal session` reads it;
//!   with a file, the results the pendant keeps (`results`, the lines
//!   `zerocal_procedure::log::read_kept_results` reads) into their own file beside it.
//! - `results [--out FILE]`: the results the pendant keeps (its last eight, each with
//!   its ID and the pendant unit's).
//! - `clear`: the session in progress cleared (`clear`); `erase`: `erase all`.
//! - `brackets [--out FILE] [--date YYYY-MM-DD]`: the brackets' calibrations made on the
//!   pendant (`brackets`), as the `[[bracket]]` TOML `load-profile --brackets` reads,
//!   dated today (the pendant has no calendar) or `--date`.
//! - `bracket-calibrate MOUNT ID [--out FILE]`: a bracket's calibration started on the
//!   pendant (`bracket calibrate`) and followed step by step (`bracket status`) until
//!   it is kept, then its TOML ([`bracket_calibrate`]).
//! - `check --out FILE`: a check of entered offsets started (`check`), followed phase by
//!   phase (`status`) to its end, its export saved ([`check_follow`]).
//! - `live [--seconds S]`: the live reading in a view that refreshes, until Enter
//!   ([`live`]).
//!
//! Each request has the grammar its reply must have ([`Expect`]). Nothing the port
//! sends is believed unchecked: a reply is printable ASCII lines within the link's
//! bounds ([`read_reply`]: line length, lines and bytes of the reply, time on the
//! link's clock), then exactly the lines its request has ([`check_reply`]): `status`
//! parsed field by field and printed from the fields, the export whole by its end
//! trailer, the changes by their confirmation lines. The I/O is any [`Link`] (a serial
//! port opened raw; in the tests a scripted port, and the pendant's own tasks on the
//! desktop, `zerocal_pendant_desktop::port`, whose clock the verbs' pauses move).

mod bracket_calibrate;
mod check_follow;
mod exchange;
mod live;
mod port;
mod reply;

use std::io::Write;
use std::path::PathBuf;
use std::time::Duration;

use clap::{Args, Subcommand};
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_core::model::JOINTS;
use zerocal_procedure::link::{parse_status, Command, MAX_COMMAND_BYTES, UPLOAD_END};
use zerocal_procedure::profile::{JointName, PendantProfile};
use zerocal_procedure::replies::Reply as PendantReply;
use zerocal_procedure::{RobotName, MAX_PLAN_POSES};
use zerocal_profile::Profile;

pub use bracket_calibrate::step_instruction;
pub use exchange::{exchange, exchange_lines, Lines};
pub use live::{LiveView, Reading};
pub use port::{Link, SerialLink};
pub use reply::{check_reply, read_reply, render_status, Expect, Reply, ReplyError, Timeouts};

use zerocal_inputs::args::RealIn;
use zerocal_inputs::error::CliError;

/// The exit statuses, for `--help`.
fn exit_statuses() -> String {
    format!(
        "Exit status: 0 the pendant answered as it must (a calibration kept, a check to \
         its end); 2 usage, a port that does not open, or no answer within {} s; 3 the \
         pendant refused, or answered something else than the request's reply (not \
         printable text, too long, not over within {} s, cut short, a field that does not \
         parse, an export whose end trailer is missing or does not match, no \
         confirmation), or a bracket calibration left on the pendant without keeping it. \
         docs/pendant-link.md has the replies.",
        Timeouts::LINK.quiet.as_secs_f64(),
        Timeouts::LINK.reply.as_secs_f64()
    )
}

/// `zerocal pendant`.
#[derive(Args, Debug)]
#[command(after_help = exit_statuses())]
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
        /// The brackets' calibrations (TOML, `[[bracket]]` tables: mount, id,
        /// rotation_deg, uncertainty_deg, date, temperature_c); default: both
        /// uncalibrated.
        #[arg(long, value_name = "FILE")]
        brackets: Option<PathBuf>,
    },
    /// Print the robot profile the pendant holds, as the lines `load-profile` sent.
    Profile {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Print the pose list the pendant holds (`zerocal plan --csv`'s form, which
    /// `load-profile --plan` takes back).
    Plan {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Save the session (`zerocal session` reads it), and with --out the results the
    /// pendant keeps beside it.
    Export {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
        /// Write the kept results here; default with --out: FILE.results (a file of
        /// their own: `zerocal session` reads the export alone).
        #[arg(long, value_name = "FILE")]
        results: Option<PathBuf>,
    },
    /// Read the results the pendant keeps (its last eight, oldest first).
    Results {
        /// Write them here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Clear the session in progress (its bias and plan are kept).
    Clear,
    /// Erase the pendant's store: session, bias, last result, profile, plan and brackets.
    Erase,
    /// Read the brackets' calibrations made on the pendant (`bracket-calibrate`), as
    /// the `[[bracket]]` TOML `load-profile --brackets` takes.
    Brackets {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
        /// The calibrations' date (the pendant has no calendar); default: today (UTC).
        #[arg(long, value_name = "YYYY-MM-DD")]
        date: Option<String>,
    },
    /// Calibrate a bracket on the pendant (docs/bracket-calibration.md): start it, then
    /// follow it step by step, saying what each step wants, until OK on the pendant
    /// keeps the result; then print the brackets' calibrations as --brackets takes
    /// them. Ctrl-C stops following (the pendant carries on; `brackets` reads the
    /// result later).
    BracketCalibrate {
        /// Which bracket.
        #[arg(value_parser = clap::builder::PossibleValuesParser::new(BracketMount::ALL.map(BracketMount::name)))]
        mount: String,
        /// Its engraved ID: 1-12 letters, digits, '-' or '_'.
        id: String,
        /// Write the calibrations (TOML) here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
        /// The calibration's date (the pendant has no calendar); default: today (UTC).
        #[arg(long, value_name = "YYYY-MM-DD")]
        date: Option<String>,
    },
    /// Start a check of entered offsets on the pendant (docs/check.md: stage 0, the
    /// flange's check poses that `zerocal program --check` drives, the closing
    /// reversal), follow it phase by phase to its end, and save its export for
    /// `zerocal check`. Ctrl-C stops following (the pendant carries on; `export`
    /// saves it later).
    Check {
        /// Where the check's export goes.
        #[arg(long, short, value_name = "FILE")]
        out: PathBuf,
    },
    /// Show the live reading (x, y in degrees, ten times a second) in a view that
    /// refreshes in place, with its spread over the pendant's still window, until
    /// Enter (or --seconds).
    Live {
        /// Stop after this many seconds instead of at Enter. Range: (0, 86400] s.
        #[arg(long, value_name = "S", value_parser = RealIn::above(0.0, 86_400.0, "s"))]
        seconds: Option<f64>,
    },
}

/// The verb of `zerocal pendant` that sends each of the link's commands: every command
/// has one (`help`'s is this tool's own `--help`).
pub fn verb(command: Command) -> &'static str {
    match command {
        Command::Help => "--help",
        Command::Status => "status",
        Command::Live => "live",
        Command::Plan => "plan",
        Command::PlanSet | Command::ProfileSet => "load-profile",
        Command::Export => "export",
        Command::Clear => "clear",
        Command::Profile => "profile",
        Command::Erase => "erase",
        Command::Brackets => "brackets",
        Command::Results => "results",
        Command::Check => "check",
        Command::BracketStatus => "bracket-calibrate",
    }
}

/// The profile as the pendant keeps it, with the brackets' calibrations: the masses
/// are the profile's (`Profile::mass_model`), as `zerocal session` takes them.
///
/// # Errors
/// A name or a joint name too long for the pendant, a mass beyond what its line takes.
pub fn pendant_profile(
    profile: &Profile,
    brackets: Brackets<f64>,
) -> Result<PendantProfile<f64>, CliError> {
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
        masses: profile.mass_model(),
        brackets,
    })
}

/// A command's line, as the pendant's parser takes it.
fn command_line(command: Command) -> Vec<u8> {
    format!("{}\r\n", command.word()).into_bytes()
}

/// The bytes of `profile set` … `end`.
///
/// # Errors
/// A line the pendant's buffer cannot hold (never, for the built-in profiles).
pub fn profile_request(p: &PendantProfile<f64>) -> Result<Vec<u8>, CliError> {
    let mut out = command_line(Command::ProfileSet);
    for i in 0.. {
        match p.line(i) {
            None => break,
            // The pendant's line editor holds MAX_COMMAND_BYTES, the line end included.
            Some(Ok(line)) if line.len() + 2 <= MAX_COMMAND_BYTES => {
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
    let mut out = command_line(Command::PlanSet);
    for q in poses_rad {
        let row: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
        out.extend_from_slice(row.join(",").as_bytes());
        out.extend_from_slice(b"\r\n");
    }
    out.extend_from_slice(UPLOAD_END.as_bytes());
    out.extend_from_slice(b"\r\n");
    Ok(out)
}

/// One request: its bytes, and what its reply must be.
#[derive(Clone, Debug)]
pub struct Request {
    /// What is sent.
    pub bytes: Vec<u8>,
    /// What must come back.
    pub expect: Expect,
}

/// A command's request, with what its reply must be.
fn request(command: Command, expect: Expect) -> Request {
    Request {
        bytes: command_line(command),
        expect,
    }
}

/// A calibration date given, or today's.
fn date_or_today(date: Option<&String>) -> Result<String, CliError> {
    match date {
        Some(d) => zerocal_inputs::bracket_file::calibration_date(d),
        None => Ok(zerocal_inputs::bracket_file::today_utc()),
    }
}

/// The requests of an action that is a fixed list of them, in order (`plan`, which
/// first asks `status` how many poses to expect, and the guided verbs have more than
/// a list: [`act`]). A request is sent only once the one before it was answered as it
/// must be (a plan must not follow a refused profile). Every action's words are
/// checked here, before the port is opened.
///
/// # Errors
/// An unknown robot, a plan that does not read or does not fit, a bad date, mount or
/// bracket ID (exit 2).
pub fn requests(action: &PendantAction) -> Result<Vec<Request>, CliError> {
    Ok(match action {
        PendantAction::Status | PendantAction::Plan { .. } => {
            vec![request(Command::Status, Expect::Status)]
        }
        PendantAction::Export { .. } => vec![request(Command::Export, Expect::Export)],
        PendantAction::Results { .. } => vec![request(Command::Results, Expect::KeptResults)],
        PendantAction::Erase => vec![request(Command::Erase, Expect::Erased)],
        PendantAction::Profile { .. } => vec![request(Command::Profile, Expect::Profile)],
        PendantAction::Clear => vec![request(
            Command::Clear,
            Expect::Line {
                name: Command::Clear.word(),
                line: PendantReply::Cleared.to_string(),
            },
        )],
        PendantAction::Brackets { date, .. } => {
            let date = date_or_today(date.as_ref())?;
            vec![request(Command::Brackets, Expect::Brackets(date))]
        }
        PendantAction::BracketCalibrate {
            mount, id, date, ..
        } => {
            date_or_today(date.as_ref())?;
            vec![bracket_calibrate::start_request(mount, id)?]
        }
        PendantAction::Check { .. } => vec![check_follow::start_request()],
        // A stream, not a reply: `live::show` reads it.
        PendantAction::Live { .. } => Vec::new(),
        PendantAction::LoadProfile {
            robot,
            plan,
            brackets,
        } => {
            let profile = zerocal_inputs::robot::load(robot)?;
            let brackets = match brackets {
                Some(path) => zerocal_inputs::bracket_file::read(path)?,
                None => Brackets::default(),
            };
            // Model radians, as the pendant's plan holds them (the file is in degrees).
            let poses: Vec<[f64; JOINTS]> = match plan {
                Some(path) => zerocal_programs::program::read_plan(path, &profile)?
                    .iter()
                    .map(|q| q.map(f64::to_radians))
                    .collect(),
                None => zerocal_programs::program::default_plan(robot)?,
            };
            let pendant = pendant_profile(&profile, brackets)?;
            vec![
                Request {
                    bytes: profile_request(&pendant)?,
                    expect: Expect::ProfileStored(pendant.robot.as_str().to_owned()),
                },
                Request {
                    bytes: plan_request(&poses)?,
                    expect: Expect::PlanStored(poses.len()),
                },
            ]
        }
    })
}

/// Sends an action's requests in turn, each only after the one before it was answered
/// as it must be, and returns what to print: the actions that are a list of requests
/// and `plan` (the guided verbs: [`act`]).
///
/// # Errors
/// No answer, or a port error (exit 2); a reply that is not its request's (exit 3).
pub fn perform(
    port: &mut impl Link,
    action: &PendantAction,
    timeouts: Timeouts,
) -> Result<String, CliError> {
    let mut out = String::new();
    let mut last = Vec::new();
    for request in requests(action)? {
        let (lines, text) = exchange_lines(port, &request.bytes, &request.expect, timeouts)?;
        out.push_str(&text);
        last = lines;
    }
    if let PendantAction::Plan { .. } = action {
        // `status` said how many poses: the reply's length.
        let lines: Vec<&str> = last.iter().map(String::as_str).collect();
        let poses = parse_status(&lines)
            .map_err(|e| CliError::Refused(format!("status: {e}")))?
            .plan_poses;
        return exchange(
            port,
            &command_line(Command::Plan),
            &Expect::Plan(poses),
            timeouts,
        );
    }
    Ok(out)
}

/// Writes `text` to `path`.
fn write_file(path: &PathBuf, text: &str) -> Result<(), CliError> {
    std::fs::write(path, text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
}

/// Where the guided verbs (`bracket-calibrate`, `check`, `live`) show their progress
/// as it happens, and how they learn to stop.
pub struct Console<'a> {
    /// Their lines.
    pub out: &'a mut dyn Write,
    /// `out` is a terminal: `live` redraws its view in place.
    pub in_place: bool,
    /// Whether the user asked to stop (Enter, for `live` without --seconds).
    pub stop: &'a dyn Fn() -> bool,
}

/// Does an action on `port`, writing its files, and returns what to print last; the
/// guided verbs show their progress on `console` as it happens.
///
/// # Errors
/// No answer, or a port or file error (exit 2); a reply that is not its request's, or
/// a calibration left without keeping it (exit 3).
pub fn act(
    port: &mut impl Link,
    action: &PendantAction,
    timeouts: Timeouts,
    console: Console<'_>,
) -> Result<String, CliError> {
    let progress = console.out;
    match action {
        PendantAction::BracketCalibrate {
            mount,
            id,
            out,
            date,
        } => {
            let date = date_or_today(date.as_ref())?;
            let toml = bracket_calibrate::calibrate(port, mount, id, &date, timeouts, progress)?;
            match out {
                Some(path) => {
                    write_file(path, &toml)?;
                    Ok(format!(
                        "wrote {} (give it to `zerocal pendant load-profile ROBOT --brackets {}`)\n",
                        path.display(),
                        path.display()
                    ))
                }
                None => Ok(toml),
            }
        }
        PendantAction::Check { out } => {
            let export = check_follow::follow(port, timeouts, progress)?;
            write_file(out, &export)?;
            Ok(format!(
                "wrote {} (the check's export: `zerocal check {} --against ID`, ID the \
                 session's record)\n",
                out.display(),
                out.display()
            ))
        }
        PendantAction::Live { seconds } => live::show(
            port,
            seconds.map(Duration::from_secs_f64),
            timeouts,
            progress,
            console.in_place,
            console.stop,
        ),
        PendantAction::Export { out, results } => {
            let text = perform(port, action, timeouts)?;
            let results = results
                .clone()
                .or_else(|| out.as_ref().map(|p| results_path(p)));
            let mut said = String::new();
            if let Some(path) = out {
                write_file(path, &text)?;
                said = format!(
                    "wrote {} (read it with `zerocal session {}`)\n",
                    path.display(),
                    path.display()
                );
            }
            let Some(path) = results else {
                return Ok(text);
            };
            let kept = perform(port, &PendantAction::Results { out: None }, timeouts)?;
            write_file(&path, &kept)?;
            if out.is_none() {
                // The export still goes to standard output, alone.
                return Ok(text);
            }
            said.push_str(&format!(
                "wrote {} (the results the pendant keeps)\n",
                path.display()
            ));
            Ok(said)
        }
        PendantAction::Results { out: Some(path) } => {
            write_file(path, &perform(port, action, timeouts)?)?;
            Ok(format!(
                "wrote {} (the results the pendant keeps)\n",
                path.display()
            ))
        }
        PendantAction::Brackets {
            out: Some(path), ..
        } => {
            write_file(path, &perform(port, action, timeouts)?)?;
            Ok(format!(
                "wrote {} (give it to `zerocal pendant load-profile ROBOT --brackets {}`)\n",
                path.display(),
                path.display()
            ))
        }
        PendantAction::Plan { out: Some(path) } => {
            write_file(path, &perform(port, action, timeouts)?)?;
            Ok(format!(
                "wrote {} (give it back with `zerocal pendant load-profile ROBOT --plan {}`)\n",
                path.display(),
                path.display()
            ))
        }
        PendantAction::Profile { out: Some(path) } => {
            write_file(path, &perform(port, action, timeouts)?)?;
            Ok(format!(
                "wrote {} (the pendant's profile)\n",
                path.display()
            ))
        }
        _ => perform(port, action, timeouts),
    }
}

/// Runs `zerocal pendant`.
///
/// # Errors
/// A port that does not open, no answer (exit 2); a reply that is not what the
/// request's must be, a calibration left without keeping it (exit 3).
pub fn run(args: &PendantArgs) -> Result<String, CliError> {
    // Before the port: a bad robot, plan, date or ID is named without a pendant.
    requests(&args.action)?;
    // A USB CDC port ignores the baud rate; opened raw (no echo, no line editing).
    let port = serialport::new(&args.port, 115_200)
        .timeout(Duration::from_millis(50))
        .open()
        .map_err(|e| CliError::Input(format!("{}: {e}", args.port)))?;
    let mut port = SerialLink::new(port);
    // `live` without --seconds stops at Enter: a line on standard input.
    let entered = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    if let PendantAction::Live { seconds: None } = args.action {
        let flag = entered.clone();
        std::thread::spawn(move || {
            let mut line = String::new();
            // End of input counts as Enter too.
            let _ = std::io::stdin().read_line(&mut line);
            flag.store(true, std::sync::atomic::Ordering::Relaxed);
        });
    }
    let stop = || entered.load(std::sync::atomic::Ordering::Relaxed);
    let mut stdout = std::io::stdout();
    let console = Console {
        in_place: std::io::IsTerminal::is_terminal(&stdout),
        out: &mut stdout,
        stop: &stop,
    };
    act(&mut port, &args.action, Timeouts::LINK, console).map_err(|e| match e {
        CliError::Input(m) => CliError::Input(format!("{}: {m}", args.port)),
        refused => refused,
    })
}

/// Where `export --out FILE` puts the kept results: `FILE.results`.
pub fn results_path(export: &std::path::Path) -> PathBuf {
    let mut name = export.as_os_str().to_owned();
    name.push(".results");
    PathBuf::from(name)
}
