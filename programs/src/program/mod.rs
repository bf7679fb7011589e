//! `zerocal program`: a robot program that drives the whole session, in the
//! controller's own language, as the session's procedure has it: a stop to clip the
//! pendant to the upper arm; the stage-1 pose captured twice, then joint 1 turned by
//! 180° (an OK on the pendant arms the first reading) and that pose captured twice; a
//! stop to move the pendant to the flange; every stage-2 pose of the plan captured
//! twice, in the plan's order (the pendant's); then the robot parks and stops for the
//! closing bench readings. Every pose's first capture is reached with every
//! joint moving in its positive direction, its second with every joint moving
//! negative: the session averages the two, the middle of each gear's backlash.
//!
//! `--check` writes the check instead (after the offsets were entered): a stop to clip
//! the pendant to the flange, the check's poses of the plan (core's `check_poses`, the
//! pendant's choice on the same plan) each captured twice at the session's commanded
//! angles, the park for the closing bench readings; no stage 1.
//!
//! The session is built once ([`build`](fn@build)), as a list of [`Step`]s in the
//! controller's joint degrees ([`Session`], [`steps`]), after the safety checks
//! ([`checks`]), and written by one module per family (`krl`, `rapid`, `tp`, `inform`,
//! `val3`, `urscript`, syntax cited in `docs/controllers/`) with the text they share
//! ([`text`]) into its files ([`files`]); [`read`] holds a small reader per family that
//! takes the joint targets, waits and stops back out of a written program, for the
//! tests. The plan comes from a file `zerocal plan` wrote or from its defaults
//! ([`plan_file`]).
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

pub mod build;
pub mod checks;
pub mod files;
pub mod format;
pub mod inform;
pub mod krl;
pub mod plan_file;
pub mod rapid;
pub mod read;
pub mod steps;
pub mod text;
pub mod tp;
pub mod urscript;
pub mod val3;

pub use build::{build, build_check, check_indices};
pub use files::{destinations, output_folder, render, Files};
pub use format::Format;
pub use plan_file::{default_plan, parse_plan, plan_with, read_plan};
pub use read::ReadMove;
pub use steps::{Capture, Role, Session, Side, Step};
pub use text::{pieces, program_name, stamp};

use crate::timing::TimingArgs;
use clap::Args;
use std::path::PathBuf;
use zerocal_core::model::JOINTS;
use zerocal_inputs::error::CliError;

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
    /// Write the check instead of the session: after the offsets were entered, the
    /// pendant on the flange only, a handful of the plan's poses (the same commanded
    /// angles as the session's, both approaches), then the closing bench readings; no stage
    /// 1. The plan must be the reference session's.
    #[arg(long)]
    pub check: bool,
    /// The session's timing.
    #[command(flatten)]
    pub timing: TimingArgs,
}

/// Runs `zerocal program`: writes the program and says what it wrote.
///
/// # Errors
/// As [`build()`]; an unreadable plan; a file that cannot be written.
pub fn run(args: &ProgramArgs) -> Result<String, CliError> {
    output_folder(&args.out)?;
    let profile = zerocal_inputs::robot::load(&args.robot)?;
    let poses_rad: Vec<[f64; JOINTS]> = match &args.plan {
        Some(path) => read_plan(path, &profile)?
            .iter()
            .map(|q| q.map(f64::to_radians))
            .collect(),
        None => default_plan(&args.robot)?,
    };
    let name = program_name(&args.out, args.format.max_name());
    if args.check {
        let check = build_check(profile, &poses_rad, args.format, name, &args.timing)?;
        let written = write_files(&check, args)?;
        let t = &check.time;
        let run_s = t.total_s - t.remount_s;
        return Ok(format!(
            "wrote {written}: {} check program {} for {} ({} of the plan's {} poses, each captured twice; {} moves) at {} % speed.\nPredicted robot time {:.1} min: the program's run {:.1} min (moves, dwells, OKs; a check keeps it within {:.0} min) and {} mountings of the pendant {:.1} min (stated default each); the closing bench readings follow, the robot free.\nRun it after stage 0 of the pendant's check mode. Check the cell for collisions with the pendant and its bracket, then step through it once at reduced speed (T1).",
            args.format,
            check.name,
            check.profile.name,
            check.poses.poses.len(),
            poses_rad.len(),
            t.moves,
            check.timing.speed_percent,
            t.total_s / 60.0,
            run_s / 60.0,
            crate::timing::CHECK_RUN_LIMIT_S / 60.0,
            t.mountings,
            t.remount_s / 60.0,
        ));
    }
    let session = build(profile, &poses_rad, args.format, name, &args.timing)?;
    let written = write_files(&session, args)?;
    let t = &session.time;
    Ok(format!(
        "wrote {written}: {} program {} for {} ({} stage-2 poses, each captured twice; {} moves), predicted robot time {:.1} min at {} % speed, until the pendant is off the flange (the closing bench readings follow, the robot free).\nCheck the cell for collisions with the pendant and its bracket, then step through it once at reduced speed (T1).",
        args.format,
        session.name,
        session.profile.name,
        session.poses.poses.len(),
        t.moves,
        t.total_s / 60.0,
        session.timing.speed_percent
    ))
}

/// Writes `session`'s files where `args` says; gives their paths, comma-separated.
///
/// # Errors
/// A file that cannot be written.
fn write_files(session: &Session, args: &ProgramArgs) -> Result<String, CliError> {
    let files = render(session, args.format)?;
    let mut written = Vec::new();
    for (path, text) in destinations(&args.out, args.format, &files)? {
        std::fs::write(&path, text)
            .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
        written.push(path.display().to_string());
    }
    Ok(written.join(", "))
}
