//! `zerocal program`: a robot program that drives the whole session, in the
//! controller's own language, as the session's procedure has it: a stop to clip the
//! pendant to the upper arm; the stage-1 pose captured twice, then joint 1 turned by
//! 180° (an OK on the pendant arms the first reading) and that pose captured twice; a
//! stop to move the pendant to the flange; every stage-2 pose of the plan captured
//! twice, in the plan's order (the pendant's); then the robot parks and stops for the
//! closing reversal on the bench. Every pose's first capture is reached with every
//! joint moving in its positive direction, its second with every joint moving
//! negative: the session averages the two, the middle of each gear's backlash.
//!
//! The session is built once, as a list of [`Step`]s in the controller's joint
//! degrees ([`Session`]), and written by one module per family (`krl`, `rapid`, `tp`,
//! `inform`, `val3`, `urscript`, syntax cited in `docs/controllers/`); [`read`] holds
//! a small reader per family that takes the joint targets, waits and stops back out of
//! a written program, for the tests.
//!
//! Physics the program respects (`crate::timing`): joint moves at a reduced speed
//! with exact stops; both sides of the backlash at every pose, each capture's last
//! move moving every joint (by the approach distance up, or the overshoot down); a
//! dwell at every capture long enough for the arm to settle and the pendant's still
//! window to complete; a stop with a message wherever the pendant needs an OK (after
//! the half turn, after a move too small to arm the next capture); room for both sides
//! of every capture pose, and every point, inside the profile's joint limits before
//! anything is written; a header saying what the program does, at what speed, and that
//! the cell must be checked for collisions with the pendant and its bracket.

pub mod inform;
pub mod krl;
pub mod rapid;
pub mod read;

pub use read::ReadMove;
pub mod tp;
pub mod urscript;
pub mod val3;

use crate::error::CliError;
use crate::plan::PlanArgs;
use crate::timing::{self, Pendant, SessionPoses, Timing, TimingArgs};
use clap::{Args, Parser};
use std::fmt;
use std::path::{Path, PathBuf};
use zerocal_core::model::JOINTS;
use zerocal_core::stage2::MEMS_RANGE_DEG;
use zerocal_procedure::robot_time::Mounting;
use zerocal_procedure::robot_time::SessionTime;
use zerocal_profile::{Family, OffsetUnit, Profile};

/// A controller family's program format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// KUKA KRL (`.src`).
    Krl,
    /// ABB RAPID (`.mod`).
    Rapid,
    /// FANUC TP in its LS text form (`.ls`).
    Tp,
    /// Yaskawa INFORM job (`.jbi`).
    Inform,
    /// Stäubli VAL3 project (a folder).
    Val3,
    /// Universal Robots URScript (`.script`).
    Urscript,
}

impl Format {
    /// Every format.
    pub const ALL: [Format; 6] = [
        Format::Krl,
        Format::Rapid,
        Format::Tp,
        Format::Inform,
        Format::Val3,
        Format::Urscript,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Krl => "krl",
            Format::Rapid => "rapid",
            Format::Tp => "tp",
            Format::Inform => "inform",
            Format::Val3 => "val3",
            Format::Urscript => "urscript",
        }
    }

    /// The controller family that runs it.
    pub fn family(self) -> Family {
        match self {
            Format::Krl => Family::Kuka,
            Format::Rapid => Family::Abb,
            Format::Tp => Family::Fanuc,
            Format::Inform => Family::Yaskawa,
            Format::Val3 => Family::Staubli,
            Format::Urscript => Family::Ur,
        }
    }

    /// The format a family's controller runs, if zerocal writes one.
    pub fn of(family: Family) -> Option<Format> {
        Format::ALL.into_iter().find(|f| f.family() == family)
    }

    /// The formats a profile can be written in: its family's; every one for a
    /// generic profile (no controller named: angles as the model's, in degrees).
    pub fn for_profile(profile: &Profile) -> Vec<Format> {
        match Format::of(profile.family) {
            Some(f) => vec![f],
            None => Format::ALL.to_vec(),
        }
    }

    /// The longest program name the format takes here (characters).
    fn max_name(self) -> usize {
        match self {
            // NX100 job names: up to 8 characters (docs/controllers/yaskawa.md [Y4]).
            Format::Inform => 8,
            // RoboDK's FANUC post allows 10 (docs/controllers/fanuc.md [F13]); 8 here.
            Format::Tp => 8,
            _ => 24,
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Arguments of `zerocal program`.
#[derive(Args, Debug, Clone)]
pub struct ProgramArgs {
    /// Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file.
    #[arg(long, value_name = "NAME")]
    pub robot: String,
    /// The plan: `zerocal plan --csv` (j1_deg..j6_deg, model degrees) or `--json`
    /// output, for the same robot. Default: `zerocal plan --robot R` with its defaults
    /// and the timing options below.
    #[arg(long, value_name = "FILE")]
    pub plan: Option<PathBuf>,
    /// The controller's program format: krl (KUKA), rapid (ABB), tp (FANUC, LS text),
    /// inform (Yaskawa JBI), val3 (Stäubli project folder), urscript (UR).
    #[arg(long, value_enum)]
    pub format: Format,
    /// Where to write it: a file (a folder for val3). Its name gives the program's.
    #[arg(long, value_name = "PATH")]
    pub out: PathBuf,
    /// The session's timing.
    #[command(flatten)]
    pub timing: TimingArgs,
}

/// What a capture pose is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capture {
    /// Stage 1, joint 1 at its mark.
    Stage1,
    /// Stage 1, joint 1 turned by 180°.
    Stage1Turned,
    /// Stage-2 pose `i` (0-based) of the plan.
    Pose(usize),
}

/// Which side of the backlash a capture is taken from: every joint's last move before
/// it is positive (`Below`) or negative (`Above`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The pose's first capture: every joint arrives moving in its positive direction.
    Below,
    /// The pose's second capture: every joint arrives moving negative.
    Above,
}

/// Why the robot goes to a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Where the pendant is clipped on (`crate::timing::mount_poses`).
    Mount(Mounting),
    /// Where the robot parks for the closing reversal (the flange's mounting pose).
    Park,
    /// Joint 1 turned by 180° (short of the turned pose by the approach distance).
    Turn,
    /// The point a capture's last move starts from: the approach distance below the
    /// pose on every joint (`Below`), or the overshoot above it (`Above`).
    Approach(Side),
    /// A pose the pendant captures at, from one side.
    Capture(Capture, Side),
}

/// One statement of the session.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// A comment line.
    Comment(String),
    /// A joint move with an exact stop, to controller degrees.
    Move {
        /// The target (controller degrees).
        target_deg: [f64; JOINTS],
        /// Why.
        role: Role,
        /// The move's time in the time model (s): RAPID's `\T`. `None` for the
        /// first move, which starts from a pose the program does not know.
        time_s: Option<f64>,
    },
    /// Stand still (s).
    Dwell(f64),
    /// Show the message lines and stop until the operator continues.
    Stop(Vec<String>),
}

/// A whole session, ready for a family's writer.
#[derive(Clone, Debug)]
pub struct Session {
    /// The program's name.
    pub name: String,
    /// The robot.
    pub profile: Profile,
    /// The header's lines (what, speed, collision warning).
    pub header: Vec<String>,
    /// The statements in order.
    pub steps: Vec<Step>,
    /// The time model.
    pub timing: Timing,
    /// The predicted robot time.
    pub time: SessionTime<f64>,
    /// The session's poses in the controller's degrees, stage 2's in order.
    pub poses: SessionPoses,
}

impl Session {
    /// Each move's target with the dwell and the stop that follow it, if any: what a
    /// reader gives back (a stop's message lines joined by spaces).
    pub fn moves(&self) -> Vec<ReadMove> {
        let mut out: Vec<ReadMove> = Vec::new();
        for s in &self.steps {
            match s {
                Step::Move { target_deg, .. } => out.push(ReadMove {
                    joints_deg: *target_deg,
                    dwell_s: None,
                    stop: None,
                }),
                Step::Dwell(t) => {
                    if let Some(last) = out.last_mut() {
                        last.dwell_s = Some(*t);
                    }
                }
                Step::Stop(lines) => {
                    if let Some(last) = out.last_mut() {
                        last.stop = Some(lines.join(" "));
                    }
                }
                Step::Comment(_) => {}
            }
        }
        out
    }

    /// The joint speed (rad/s) and acceleration (rad/s²) of URScript's `movej`: the
    /// reduced speed of the slowest joint, so no joint exceeds its own.
    pub fn ur_speed(&self) -> (f64, f64) {
        let v = self
            .timing
            .model
            .speed_deg_s
            .iter()
            .fold(f64::INFINITY, |m, v| m.min(*v));
        let a = self
            .timing
            .model
            .accel_deg_s2
            .iter()
            .fold(f64::INFINITY, |m, v| m.min(*v));
        (v.to_radians(), a.to_radians())
    }

    /// Pulses per degree of each joint, for INFORM.
    pub fn pulses_per_deg(&self) -> Option<[f64; JOINTS]> {
        match self.profile.controller.unit {
            OffsetUnit::Counts(Some(c)) => Some(c),
            _ => None,
        }
    }
}

/// A program's name from the output path: letters, digits and `_`, upper case,
/// starting with a letter, at most `max` characters; `ZEROCAL` if nothing is left.
pub fn program_name(out: &Path, max: usize) -> String {
    let stem = out
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut name: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .skip_while(|c| !c.is_ascii_alphabetic())
        .take(max)
        .collect();
    while name.ends_with('_') {
        name.pop();
    }
    if name.is_empty() {
        name = "ZEROCAL".chars().take(max).collect();
    }
    name
}

/// A UTC date and time for the headers that carry one (TP, INFORM).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stamp {
    /// Year.
    pub year: i64,
    /// Month 1-12.
    pub month: u32,
    /// Day 1-31.
    pub day: u32,
    /// Hour 0-23.
    pub hour: u32,
    /// Minute.
    pub minute: u32,
    /// Second.
    pub second: u32,
}

impl Stamp {
    /// `SOURCE_DATE_EPOCH` (seconds since 1970, the reproducible-builds convention) if
    /// set and valid, else the clock.
    pub fn now() -> Self {
        let secs = std::env::var("SOURCE_DATE_EPOCH")
            .ok()
            .and_then(|v| v.trim().parse::<i64>().ok())
            .unwrap_or_else(|| {
                std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(0))
            });
        Self::from_unix(secs)
    }

    /// The civil UTC date of `secs` since 1970-01-01 (H. Hinnant's days-to-civil).
    pub fn from_unix(secs: i64) -> Self {
        let days = secs.div_euclid(86_400);
        let rem = secs.rem_euclid(86_400);
        let z = days + 719_468;
        let era = z.div_euclid(146_097);
        let doe = z - era * 146_097;
        let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
        let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
        let mp = (5 * doy + 2) / 153;
        let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
        let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
        let year = yoe + era * 400 + i64::from(month <= 2);
        Stamp {
            year,
            month,
            day,
            hour: (rem / 3600) as u32,
            minute: (rem % 3600 / 60) as u32,
            second: (rem % 60) as u32,
        }
    }
}

/// Splits `text` into pieces of at most `max` characters at spaces where it can.
///
/// Linear in the text: each character is looked at a fixed number of times (a word
/// longer than `max` is cut as it is read, never re-counted).
pub fn pieces(text: &str, max: usize) -> Vec<String> {
    let max = max.max(1);
    let mut out = Vec::new();
    let mut line = String::new();
    let mut line_chars = 0;
    for word in text.split_whitespace() {
        let word_chars = word.chars().count();
        if word_chars > max {
            if !line.is_empty() {
                out.push(std::mem::take(&mut line));
            }
            let mut head = String::new();
            let mut head_chars = 0;
            for c in word.chars() {
                if head_chars == max {
                    out.push(std::mem::take(&mut head));
                    head_chars = 0;
                }
                head.push(c);
                head_chars += 1;
            }
            // The word's tail starts the next line.
            line = head;
            line_chars = head_chars;
        } else if line.is_empty() {
            line.push_str(word);
            line_chars = word_chars;
        } else if line_chars + 1 + word_chars <= max {
            line.push(' ');
            line.push_str(word);
            line_chars += 1 + word_chars;
        } else {
            out.push(std::mem::replace(&mut line, word.to_owned()));
            line_chars = word_chars;
        }
    }
    if !line.is_empty() {
        out.push(line);
    }
    out
}

/// Reads a plan file: `zerocal plan --csv` rows (model degrees) or its `--json`.
///
/// # Errors
/// An unreadable file, a malformed row (naming the line), another robot's plan.
pub fn read_plan(path: &Path, profile: &Profile) -> Result<Vec<[f64; JOINTS]>, CliError> {
    let text = crate::input::read_capped(path, crate::input::MAX_PLAN_BYTES, "plan")?;
    parse_plan(&text, path, profile)
}

/// Parses a plan file's text (`path` names it in errors): as [`read_plan`].
///
/// # Errors
/// A malformed row (naming the line), another robot's plan.
pub fn parse_plan(
    text: &str,
    path: &Path,
    profile: &Profile,
) -> Result<Vec<[f64; JOINTS]>, CliError> {
    let bad = |m: String| CliError::Input(format!("{}: {m}", path.display()));
    let poses_deg: Vec<[f64; JOINTS]> = if text.trim_start().starts_with('{') {
        let v: serde_json::Value =
            serde_json::from_str(text).map_err(|e| bad(format!("not JSON: {e}")))?;
        if let Some(robot) = v.get("robot").and_then(|r| r.as_str()) {
            if robot != profile.name {
                return Err(bad(format!(
                    "the plan is for robot '{robot}', not '{}'",
                    profile.name
                )));
            }
        }
        let rows = v
            .get("poses_deg")
            .and_then(|p| p.as_array())
            .ok_or_else(|| {
                bad("no \"poses_deg\" array (write it with zerocal plan --json)".into())
            })?;
        rows.iter()
            .enumerate()
            .map(|(i, r)| {
                let a = r
                    .as_array()
                    .filter(|a| a.len() == JOINTS)
                    .ok_or_else(|| bad(format!("poses_deg[{i}]: not {JOINTS} numbers")))?;
                let mut q = [0.0; JOINTS];
                for (k, x) in a.iter().enumerate() {
                    q[k] = x
                        .as_f64()
                        .filter(|x| x.is_finite())
                        .ok_or_else(|| bad(format!("poses_deg[{i}][{k}]: not a finite number")))?;
                }
                Ok(q)
            })
            .collect::<Result<_, CliError>>()?
    } else {
        let mut rows = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = raw.split('#').next().unwrap_or("").trim();
            if line.is_empty() || line.starts_with("j1_deg") {
                continue;
            }
            let f: Vec<&str> = line.split(',').map(str::trim).collect();
            if f.len() != JOINTS {
                return Err(bad(format!(
                    "line {}: {} fields, expected j1_deg..j6_deg",
                    i + 1,
                    f.len()
                )));
            }
            let mut q = [0.0; JOINTS];
            for (k, x) in f.iter().enumerate() {
                q[k] = x
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        bad(format!(
                            "line {}: field j{}_deg: '{x}' is not a finite number",
                            i + 1,
                            k + 1
                        ))
                    })?;
            }
            rows.push(q);
        }
        rows
    };
    if poses_deg.len() < zerocal_core::stage2::MIN_POSES
        || poses_deg.len() > zerocal_core::plan::MAX_POSES
    {
        return Err(bad(format!(
            "{} poses; a plan has {}-{}",
            poses_deg.len(),
            zerocal_core::stage2::MIN_POSES,
            zerocal_core::plan::MAX_POSES
        )));
    }
    let q1 = profile.stage1_joints_rad.map(f64::to_degrees);
    for (i, q) in poses_deg.iter().enumerate() {
        // The plan prints 6 decimals: 1e-5 deg covers its rounding.
        if (q[0] - q1[0]).abs() > 1e-5 || (q[1] - q1[1]).abs() > 1e-5 {
            return Err(bad(format!(
                "pose {}: joints 1-2 at ({}, {}) deg are not the profile's stage-1 values ({:.6}, {:.6}) (model degrees): a plan for another robot or stage-1 pose",
                i + 1,
                q[0],
                q[1],
                q1[0],
                q1[1]
            )));
        }
    }
    Ok(poses_deg)
}

/// The plan `zerocal plan --robot R` would make with its defaults and these timing
/// options, in the session's order (model radians).
pub fn default_plan(robot: &str, timing: &TimingArgs) -> Result<Vec<[f64; JOINTS]>, CliError> {
    #[derive(Parser)]
    struct Defaults {
        #[command(flatten)]
        plan: PlanArgs,
    }
    let mut args = Defaults::try_parse_from(["plan", "--robot", robot])
        .map_err(|e| CliError::Input(e.to_string()))?
        .plan;
    args.timing = timing.clone();
    let sp = crate::plan::make_plan(&args)?;
    Ok(sp.plan.poses_rad.iter().copied().collect())
}

/// The lines of a stop asking for an OK on the pendant after `what`.
fn ok_stop(what: &str) -> Step {
    Step::Stop(vec![
        "zerocal: press OK on the pendant".into(),
        format!("({what} is too small to arm it), then continue."),
    ])
}

/// Builds the session a program drives: the steps, checked against the joint limits
/// and the pendant's capture rule.
///
/// # Errors
/// A capture pose without room on both sides of the backlash inside the joint limits,
/// or any other point outside them (naming the joint and the limit); a capture pose
/// the pendant would read past mode 4's ±10°; a move the pendant could capture before
/// the robot arrives; an INFORM job without pulses per degree; a format of another
/// family.
pub fn build(
    profile: Profile,
    poses_rad: &[[f64; JOINTS]],
    format: Format,
    name: String,
    timing_args: &TimingArgs,
) -> Result<Session, CliError> {
    if let Some(f) = Format::of(profile.family) {
        if f != format {
            return Err(CliError::Input(format!(
                "--format {format}: profile {} is a {} robot; its controller runs --format {f}",
                profile.name,
                profile.family.name()
            )));
        }
    }
    if format == Format::Inform && !matches!(profile.controller.unit, OffsetUnit::Counts(Some(_))) {
        return Err(CliError::Refused(format!(
            "--format inform: an INFORM job holds pulses, and profile {} has no pulses per degree (controller.counts_per_deg; not public for the built-in Yaskawa profiles). Read them from your controller (MotoPlus GP_getPulseToRad, or its parameter file) into your own profile (docs/profiles.md, docs/controllers/yaskawa.md); nothing was written",
            profile.name
        )));
    }
    let poses = SessionPoses::new(&profile, poses_rad).with_mounts(&profile)?;
    timing::check_room(&profile, &poses)?;
    let t = Timing::new(&profile, timing_args)?;
    let tm = t.model;
    let pendant = Pendant::new(&profile);
    // Every capture pose read inside mode 4's range.
    for (i, (what, q)) in poses.capture_poses().into_iter().enumerate() {
        let mounting = if i < 2 {
            Mounting::UpperArm
        } else {
            Mounting::Flange
        };
        let r = pendant.reading_on(mounting, &q);
        let worst = r.x_rad.to_degrees().abs().max(r.y_rad.to_degrees().abs());
        if worst > MEMS_RANGE_DEG {
            return Err(CliError::Refused(format!(
                "{what}: the pendant would read {worst:.1} deg there, past its {MEMS_RANGE_DEG:.0} deg range (the SCL3300's mode 4): it cannot capture that pose (plan with zerocal plan); nothing was written"
            )));
        }
    }
    let time = timing::session_time(&pendant, &tm, &poses);
    let dwell = tm.dwell_s();
    let j1 = timing::joint_label(&profile, 0);

    let mut steps = Vec::new();
    // Drives `path` (its first point is where the robot stands), the moves' roles in
    // turn, after checking that the pendant cannot capture before the robot arrives;
    // says whether the path arms the next capture.
    let drive = |steps: &mut Vec<Step>,
                 path: &[[f64; JOINTS]],
                 roles: &[Role],
                 mounting: Mounting,
                 what: &str|
     -> Result<bool, CliError> {
        let check = pendant.leg(&tm, mounting, path);
        if check.early_still {
            return Err(CliError::Refused(format!(
                "the moves to {what} keep the pendant's reading still for {} s before the robot arrives: the pendant could capture early. Plan again (another --seed) or change the order; nothing was written",
                tm.window_s
            )));
        }
        for (w, role) in path.windows(2).zip(roles) {
            steps.push(Step::Move {
                target_deg: w[1],
                role: *role,
                time_s: Some(tm.move_s(&w[0], &w[1])),
            });
        }
        Ok(check.armed)
    };
    let below = Role::Approach(Side::Below);
    let above = Role::Approach(Side::Above);
    let upper = Mounting::UpperArm;
    let flange = Mounting::Flange;

    // Stage 1.
    steps.push(Step::Comment(
        "zerocal stage 1: the pendant goes on the upper arm here, tilted past its range so that it cannot capture yet".into(),
    ));
    steps.push(Step::Move {
        target_deg: poses.mount1,
        role: Role::Mount(upper),
        time_s: None,
    });
    steps.push(Step::Stop(vec![
        "zerocal: clip the pendant to the upper arm".into(),
        "(its screen at STAGE 1), then continue.".into(),
    ]));
    steps.push(Step::Comment(
        "zerocal stage 1: the stage-1 pose, captured from below, then from above".into(),
    ));
    let what = describe(Capture::Stage1);
    drive(
        &mut steps,
        &tm.first_capture_path(&poses.mount1, &poses.stage1),
        &[below, Role::Capture(Capture::Stage1, Side::Below)],
        upper,
        &what,
    )?;
    steps.push(Step::Dwell(dwell));
    if !drive(
        &mut steps,
        &tm.second_capture_path(&poses.stage1),
        &[above, Role::Capture(Capture::Stage1, Side::Above)],
        upper,
        &what,
    )? {
        steps.push(ok_stop("the overshoot"));
    }
    steps.push(Step::Dwell(dwell));
    steps.push(Step::Comment(format!(
        "zerocal stage 1: {j1} turned by 180 deg, captured from below, then from above"
    )));
    let what = describe(Capture::Stage1Turned);
    drive(
        &mut steps,
        &tm.turn_path(&poses.stage1, &poses.turned),
        &[
            Role::Turn,
            below,
            Role::Capture(Capture::Stage1Turned, Side::Below),
        ],
        upper,
        &what,
    )?;
    steps.push(Step::Stop(vec![
        "zerocal: press OK on the pendant (after the".into(),
        "half turn only OK arms it), then continue.".into(),
    ]));
    steps.push(Step::Dwell(dwell));
    if !drive(
        &mut steps,
        &tm.second_capture_path(&poses.turned),
        &[above, Role::Capture(Capture::Stage1Turned, Side::Above)],
        upper,
        &what,
    )? {
        steps.push(ok_stop("the overshoot"));
    }
    steps.push(Step::Dwell(dwell));

    // The pendant to the flange.
    steps.push(Step::Comment(format!(
        "zerocal: {j1} back; the pendant goes from the upper arm to the flange here, both tilted past its range"
    )));
    drive(
        &mut steps,
        &[poses.turned, poses.mount2],
        &[Role::Mount(flange)],
        upper,
        "the mounting pose for the flange",
    )?;
    steps.push(Step::Stop(vec![
        "zerocal: move the pendant from the upper arm".into(),
        "to the flange (its screen at POSE 1), then continue.".into(),
    ]));

    // Stage 2.
    let n = poses.poses.len();
    let mut last = poses.mount2;
    for (i, q) in poses.poses.iter().enumerate() {
        steps.push(Step::Comment(format!(
            "zerocal stage 2: pose {} of {n}, captured from below, then from above",
            i + 1
        )));
        let what = describe(Capture::Pose(i));
        let armed = drive(
            &mut steps,
            &tm.first_capture_path(&last, q),
            &[below, Role::Capture(Capture::Pose(i), Side::Below)],
            flange,
            &what,
        )?;
        if i > 0 && !armed {
            steps.push(ok_stop("this move"));
        }
        steps.push(Step::Dwell(dwell));
        if !drive(
            &mut steps,
            &tm.second_capture_path(q),
            &[above, Role::Capture(Capture::Pose(i), Side::Above)],
            flange,
            &what,
        )? {
            steps.push(ok_stop("the overshoot"));
        }
        steps.push(Step::Dwell(dwell));
        last = *q;
    }

    // The closing reversal.
    steps.push(Step::Comment(
        "zerocal: stage 2 done; the robot parks where the pendant went on the flange (tilted past its range) for the closing reversal".into(),
    ));
    drive(
        &mut steps,
        &[last, poses.park],
        &[Role::Park],
        flange,
        "the park",
    )?;
    steps.push(Step::Stop(vec![
        "zerocal: closing reversal: take the pendant off".into(),
        "the flange to the bench of stage 0, let it".into(),
        "capture, turn it 180 deg on the same spot,".into(),
        "press OK, let it capture. Then continue.".into(),
    ]));
    steps.push(Step::Comment(
        "zerocal: session done; the pendant shows the result".into(),
    ));

    // Every point the robot is sent to, inside the limits.
    for (n, s) in steps.iter().enumerate() {
        if let Step::Move {
            target_deg, role, ..
        } = s
        {
            let next_capture = steps[n + 1..].iter().find_map(|s| match s {
                Step::Move {
                    role: Role::Capture(c, _),
                    ..
                } => Some(*c),
                _ => None,
            });
            let next = next_capture.map_or_else(|| "a pose".to_owned(), describe);
            let what = match role {
                Role::Mount(Mounting::UpperArm) => "the mounting pose for the upper arm".to_owned(),
                Role::Mount(Mounting::Flange) => "the mounting pose for the flange".to_owned(),
                Role::Park => "the park for the closing reversal".to_owned(),
                Role::Turn => format!("{j1}'s half turn"),
                Role::Approach(Side::Below) => {
                    format!("the point {} deg below {next}", tm.approach_deg)
                }
                Role::Approach(Side::Above) => {
                    format!("the point {} deg above {next}", tm.overshoot_deg)
                }
                Role::Capture(c, _) => describe(*c),
            };
            timing::check_limits(&profile, target_deg, &what)?;
        }
    }

    let unit = match format {
        Format::Urscript => "radians".to_owned(),
        Format::Inform => "pulses (joint degrees x the profile's pulses per degree)".to_owned(),
        _ => "degrees".to_owned(),
    };
    let header = vec![
        "zerocal robot program: a joint-zero calibration session.".to_owned(),
        format!(
            "Robot {} (profile {}); {n} stage-2 poses. Written by zerocal {}; targets in the controller's joint {unit}.",
            profile.title,
            profile.name,
            env!("CARGO_PKG_VERSION")
        ),
        format!(
            "Every pose is captured twice: first with every joint arriving moving positive (from {} deg below), then, after every joint has gone {} deg past it, moving negative (from above). The pendant averages the two: the middle of every gear's backlash.",
            tm.approach_deg, tm.overshoot_deg
        ),
        format!(
            "Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its range, so it cannot capture early). Stage 1: the stage-1 pose twice, then {j1} turned by 180 deg twice (an OK on the pendant arms the first). Stop: move the pendant to the flange (tilted again). Stage 2: the plan's poses in its order, twice each; load the same plan into the pendant (plan set)."
        ),
        "Closing reversal: the robot parks where the pendant went on the flange and stops; take the pendant off and reverse it on the bench as in stage 0 (two readings, turned 180 deg on the same spot between them). The program ends there.".to_owned(),
        format!(
            "Speed: joint moves at {} % of each joint's maximum speed, exact stops.",
            t.speed_percent
        ),
        format!(
            "Dwell {dwell:.1} s at each capture: settling {} s (stated default) + the pendant's {} s still window + 2 sensor periods of {} s.",
            tm.settle_s, tm.window_s, tm.sample_period_s
        ),
        format!(
            "Predicted robot time {:.1} min, the closing reversal included: motion {:.0} s, dwell {:.0} s ({} captures), {} mountings {:.0} s, operator OKs {:.0} s.",
            time.total_s / 60.0,
            time.motion_s,
            time.dwell_s,
            time.captures,
            time.mountings,
            time.remount_s,
            time.operator_s
        ),
        "WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check the cell, then step through the program once at reduced speed (T1) before running it.".to_owned(),
    ];
    Ok(Session {
        name,
        profile,
        header,
        steps,
        timing: t,
        time,
        poses,
    })
}

fn describe(c: Capture) -> String {
    match c {
        Capture::Stage1 => "the stage-1 pose".to_owned(),
        Capture::Stage1Turned => "the stage-1 pose with joint 1 turned by 180 deg".to_owned(),
        Capture::Pose(i) => format!("stage-2 pose {}", i + 1),
    }
}

/// The files of a program: (name relative to `--out`'s folder, contents).
pub type Files = Vec<(String, String)>;

/// Writes `session` in `format`: the file names and contents.
pub fn render(session: &Session, format: Format) -> Result<Files, CliError> {
    Ok(match format {
        Format::Krl => vec![(
            format!("{}.src", session.name.to_ascii_lowercase()),
            krl::write(session),
        )],
        Format::Rapid => vec![(format!("{}.mod", session.name), rapid::write(session))],
        Format::Tp => vec![(format!("{}.ls", session.name), tp::write(session))],
        Format::Inform => vec![(format!("{}.JBI", session.name), inform::write(session)?)],
        Format::Val3 => val3::write(session),
        Format::Urscript => vec![(
            format!("{}.script", session.name.to_ascii_lowercase()),
            urscript::write(session),
        )],
    })
}

/// Refuses an output path whose folder does not exist, for every format alike:
/// zerocal makes no folders but a VAL3 project's own, so a mistyped path is refused,
/// not created. Checked before anything is planned.
///
/// # Errors
/// The folder `out` lies in does not exist.
pub fn output_folder(out: &Path) -> Result<(), CliError> {
    let folder = out
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if folder.is_dir() {
        Ok(())
    } else {
        Err(CliError::Input(format!(
            "cannot write {}: the folder {} does not exist (zerocal makes none); nothing was written",
            out.display(),
            folder.display()
        )))
    }
}

/// Where each of a program's files goes, the same way for every format: `--out`
/// itself for a one-file format, files inside the project folder `--out` for VAL3
/// (made if missing, in a folder [`output_folder`] checked).
///
/// # Errors
/// A VAL3 project folder that cannot be made.
pub fn destinations<'a>(
    out: &Path,
    format: Format,
    files: &'a Files,
) -> Result<Vec<(PathBuf, &'a str)>, CliError> {
    if format != Format::Val3 {
        return Ok(files
            .first()
            .map(|(_, text)| (out.to_path_buf(), text.as_str()))
            .into_iter()
            .collect());
    }
    if !out.is_dir() {
        std::fs::create_dir(out)
            .map_err(|e| CliError::Input(format!("cannot create {}: {e}", out.display())))?;
    }
    Ok(files
        .iter()
        .map(|(file, text)| (out.join(file), text.as_str()))
        .collect())
}

/// Runs `zerocal program`: writes the program and says what it wrote.
///
/// # Errors
/// As [`build`]; an unreadable plan; a file that cannot be written.
pub fn run(args: &ProgramArgs) -> Result<String, CliError> {
    output_folder(&args.out)?;
    let profile = crate::robot::load(&args.robot)?;
    let poses_rad: Vec<[f64; JOINTS]> = match &args.plan {
        Some(path) => read_plan(path, &profile)?
            .iter()
            .map(|q| q.map(f64::to_radians))
            .collect(),
        None => default_plan(&args.robot, &args.timing)?,
    };
    let name = program_name(&args.out, args.format.max_name());
    let session = build(profile, &poses_rad, args.format, name, &args.timing)?;
    let files = render(&session, args.format)?;
    let mut written = Vec::new();
    for (path, text) in destinations(&args.out, args.format, &files)? {
        std::fs::write(&path, text)
            .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
        written.push(path.display().to_string());
    }
    let t = &session.time;
    Ok(format!(
        "wrote {}: {} program {} for {} ({} stage-2 poses, each captured twice; {} moves), predicted robot time {:.1} min at {} % speed, the closing reversal included.\nCheck the cell for collisions with the pendant and its bracket, then step through it once at reduced speed (T1).",
        written.join(", "),
        args.format,
        session.name,
        session.profile.name,
        session.poses.poses.len(),
        t.moves,
        t.total_s / 60.0,
        session.timing.speed_percent
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn civil_dates() {
        // 0 is 1970-01-01; 951782400 is 2000-02-29 (a leap day); 1700000000 is
        // 2023-11-14 22:13:20 UTC.
        assert_eq!(
            Stamp::from_unix(0),
            Stamp {
                year: 1970,
                month: 1,
                day: 1,
                hour: 0,
                minute: 0,
                second: 0
            }
        );
        let leap = Stamp::from_unix(951_782_400);
        assert_eq!((leap.year, leap.month, leap.day), (2000, 2, 29));
        assert_eq!(
            Stamp::from_unix(1_700_000_000),
            Stamp {
                year: 2023,
                month: 11,
                day: 14,
                hour: 22,
                minute: 13,
                second: 20
            }
        );
    }

    #[test]
    fn names_and_pieces() {
        assert_eq!(program_name(Path::new("out/zc-kr16.src"), 24), "ZC_KR16");
        assert_eq!(program_name(Path::new("9lives.jbi"), 8), "LIVES");
        assert_eq!(
            program_name(Path::new("calibration_session.ls"), 8),
            "CALIBRAT"
        );
        assert_eq!(program_name(Path::new("___.ls"), 8), "ZEROCAL");
        assert_eq!(
            pieces("press OK on the pendant, then continue", 10),
            ["press OK", "on the", "pendant,", "then", "continue"]
        );
        assert_eq!(pieces("abcdefghijkl", 5), ["abcde", "fghij", "kl"]);
        for p in pieces(&"word ".repeat(40), 20) {
            assert!(p.chars().count() <= 20);
        }
        assert_eq!(pieces("ab abcdefgh x", 3), ["ab", "abc", "def", "gh", "x"]);
        // Ten million characters in one word (a long name): linear, so well under a
        // second where the quadratic cut took minutes; nothing lost.
        let long = "k".repeat(10_000_000);
        let start = std::time::Instant::now();
        let cut = pieces(&long, 60);
        assert!(start.elapsed().as_secs_f64() < 5.0, "{:?}", start.elapsed());
        assert_eq!(cut.concat(), long);
        assert!(cut.iter().all(|p| p.chars().count() <= 60));
    }
}
