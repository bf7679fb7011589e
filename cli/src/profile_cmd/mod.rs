//! `zerocal profile`: a robot profile from the arm's description, and what a profile
//! lets zerocal do.
//!
//! - `zerocal profile import FILE.urdf --out PROFILE.toml [--base LINK] [--tip LINK]
//!   [--family F] [--name NAME]`: the arm's chain read out of its URDF
//!   (`zerocal_profile::urdf`), written as a profile citing the file ([`urdf_import`]).
//! - `zerocal profile check PROFILE.toml|NAME [--json]`: what the profile lets the
//!   product do (plan, simulate, session, program, check, restore, the pendant, the
//!   bracket), tried on the profile itself, and what is missing with what each item
//!   costs; the exit status says how bad it is ([`profile_check`]).

pub mod profile_check;
pub mod urdf_import;

use clap::{Args, Subcommand};
use std::io::Write;
use std::process::ExitCode;
use zerocal_inputs::error::CliError;

/// Arguments of `zerocal profile`.
#[derive(Args, Debug, Clone)]
pub struct ProfileArgs {
    /// What to do.
    #[command(subcommand)]
    pub action: ProfileAction,
}

/// `zerocal profile` subcommands.
#[derive(Subcommand, Debug, Clone)]
pub enum ProfileAction {
    /// Write a profile from a robot's URDF (expanded, not a xacro): the chain from the
    /// base to the flange frame, its fixed joints folded, each value citing the file.
    Import(urdf_import::ImportArgs),
    /// Say what a profile lets zerocal do and what it is missing, with what each missing
    /// item costs. Exit status: 0 nothing missing, 1 usable with what is listed missing,
    /// 2 the profile does not read, 3 it reads but no session can be planned with it.
    Check(profile_check::CheckArgs),
}

/// Runs `zerocal profile`, printing its report, and gives the exit status: the
/// check's by severity ([`profile_check::Severity`]), else 0, or the error's.
pub fn main(args: &ProfileArgs) -> ExitCode {
    let outcome = match &args.action {
        ProfileAction::Import(a) => urdf_import::run(a).map(|out| (out, 0)),
        ProfileAction::Check(a) => {
            profile_check::run(a).map(|(out, severity)| (out, severity.exit_code()))
        }
    };
    match outcome {
        Ok((out, code)) => {
            let mut stdout = std::io::stdout().lock();
            match writeln!(stdout, "{}", out.trim_end()).and_then(|()| stdout.flush()) {
                Ok(()) => ExitCode::from(code),
                // `| head` closing the pipe early is not an error of ours.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(code),
                Err(e) => {
                    eprintln!("zerocal: cannot write the output: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Err(e) => {
            eprintln!("zerocal: {e}");
            ExitCode::from(exit_status(&e))
        }
    }
}

fn exit_status(e: &CliError) -> u8 {
    u8::try_from(e.exit_code()).unwrap_or(2)
}
