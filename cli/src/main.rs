//! `zerocal`: the desktop side of the zerocal pendant.
//!
//! - `zerocal simulate`: a whole calibration on a simulated robot, report beside truth.
//! - `zerocal identify LOG.csv`: stage 2 on a recorded log.
//! - `zerocal plan --poses N`: the stage-2 poses that minimise the predicted 1σ.
//! - `zerocal session EXPORT`: stages 0-2 on a pendant export, in the controller's terms.
//! - `zerocal program --robot R --format F --out FILE`: a robot program that drives the
//!   whole session.
//! - `zerocal pendant --port P ACTION`: the pendant's link, a verb for each of its
//!   commands (status, load-profile, export, results, brackets, bracket-calibrate,
//!   check, live, plan, profile, clear, erase).
//! - `zerocal bracket --robot R [--out FILE]`: the flange bracket's OpenSCAD parameters
//!   from the profile's flange interface.
//! - `zerocal certificate ID --out FILE.html`: a session's calibration certificate.
//! - `zerocal check EXPORT --against ID`: after the offsets were entered, what is left.
//! - `zerocal restore EXPORT --reference ID`: after a motor swap, back to a reference's zero.
//! - `zerocal history [SERIAL] [--db PATH|URL] [--json] [--plot DIR]`: the calibration
//!   history per robot serial.
//! - `zerocal serve [--db PATH|URL] [--listen ADDR:PORT]`: the plant's web application
//!   over the history (fleet, robots, uploads, review and signature, audit).
//! - `zerocal profile import FILE.urdf --out P.toml` / `profile check P.toml`: a profile
//!   from a robot's URDF, and what a profile lets zerocal do.

use clap::{Parser, Subcommand};
use std::io::Write;
use std::process::ExitCode;
use zerocal_analysis::identify::{self, IdentifyArgs};
use zerocal_analysis::session::{self, SessionArgs};
use zerocal_cli::simulate::{self, SimulateArgs};
use zerocal_cli::world_args;
use zerocal_inputs::error::CliError;
use zerocal_programs::plan::{self, PlanArgs};
use zerocal_programs::program::{self, ProgramArgs};

/// Find the joint zeros of a six-axis robot with the zerocal pendant: `plan` the poses,
/// `program` the robot, load and read the `pendant`, solve its export into the
/// offsets to enter in the controller's terms (`session`), then `check` the entry.
///
/// Around it: `simulate` rehearses the whole job on a simulated robot, `restore` brings
/// a joint back to a reference's zero after a motor swap, `history` and `certificate`
/// keep the record, and `serve` shows it to the plant on the web; `profile` imports an arm from its URDF and says what a profile
/// lets the product do; `bracket`, `robots`, `identify` and `error-table` are the tools
/// behind them. docs/cli.md has every command.
#[derive(Parser, Debug)]
#[command(name = "zerocal", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run stages 0-2 on a simulated robot and print the report beside the truth.
    Simulate(SimulateArgs),
    /// Identify the zero offsets of joints 3-6 from a recorded log (stage 2).
    Identify(IdentifyArgs),
    /// Plan the stage-2 poses and print the 1-sigma they promise.
    Plan(PlanArgs),
    /// List the built-in robot profiles, one a line.
    Robots(zerocal_inputs::robot::RobotsArgs),
    /// The error sources one at a time, over many simulated sessions, with and without
    /// the compensation.
    ErrorTable(world_args::ErrorTableArgs),
    /// Solve a whole pendant session export (stages 0-2) and print the offsets in the
    /// controller's own terms.
    Session(SessionArgs),
    /// Write a robot program (KRL, RAPID, TP, INFORM, VAL3, URScript) that drives the
    /// whole session: stage 1, the remount stop, every planned pose.
    Program(ProgramArgs),
    /// Talk to a pendant over its USB serial port, a verb for each of its commands:
    /// status, load a robot profile and its plan, export, calibrate a bracket and start
    /// a check (each followed to its end), the live reading, erase the store.
    Pendant(zerocal_link::PendantArgs),
    /// After the offsets were entered: what a check's export says is left of each
    /// joint's offset against the session's record (recorded in the history).
    Check(zerocal_analysis::check::CheckArgs),
    /// A calibration certificate (HTML for A4) of a session in the history.
    Certificate(zerocal_records::certificate::CertificateArgs),
    /// After a motor or gearbox change: the offsets that bring each joint back to a
    /// reference session's zero.
    Restore(zerocal_analysis::restore::RestoreArgs),
    /// Write the flange bracket's OpenSCAD parameters (`include <flange_bracket.scad>`
    /// and the profile's ISO 9409-1 bolt circle and dowel) for the robot.
    Bracket(zerocal_programs::bracket_design::BracketArgs),
    /// List the calibration history (every session and check, per robot serial) as a
    /// table or JSON, or plot each joint's zero over time with its U(k=2) band.
    History(zerocal_records::history::HistoryArgs),
    /// A robot profile from the robot's URDF (`import`), and what a profile lets zerocal
    /// do and is missing (`check`, its exit status by severity).
    Profile(zerocal_cli::profile_cmd::ProfileArgs),
    /// Serve the plant's web application over the history: the fleet, each robot,
    /// uploads of pendant exports, review and signature, accounts and the audit log
    /// (or make an account with --add-user).
    Serve(zerocal_cli::serve::ServeArgs),
}

fn run(cli: &Cli) -> Result<String, CliError> {
    match &cli.command {
        Command::Simulate(args) if args.world == simulate::World::Real => {
            let world = args.real.world();
            let run = world_args::run_session(
                &args.robot,
                &world,
                args.poses.unwrap_or(zerocal_sim::montecarlo::DEFAULT_POSES),
                args.seed,
                Some(&args.real),
            )?;
            let mut out = run.report(&world, args.seed);
            if let Some(path) = &args.real.export {
                std::fs::write(path, run.session.export_text(&run.profile.name))
                    .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
                out.push_str(&format!(
                    "wrote {} (read it with `zerocal session {}`)\n",
                    path.display(),
                    path.display()
                ));
            }
            match world_args::accuracy(&run, args.accuracy_points, args.seed) {
                Ok(report) => {
                    out.push_str(&format!(
                        "\n-- positioning accuracy, ISO 9283-style, {} --\n",
                        run.profile.title
                    ));
                    out.push_str(&report.to_string());
                    if let Some(dir) = &args.plot {
                        for f in world_args::plots(dir, &run, &report)? {
                            out.push_str(&format!("wrote {}\n", f.display()));
                        }
                    }
                }
                Err(e) => out.push_str(&format!("\nno positioning test: {e}\n")),
            }
            Ok(out)
        }
        Command::ErrorTable(args) => world_args::error_table(args),
        Command::Robots(args) => zerocal_inputs::robot::list(args),
        Command::Simulate(args) => {
            let (profile, session, result) = simulate::simulate(args)?;
            let mut out = simulate::render(args, &session, &result)?;
            let report = match simulate::accuracy(args, &profile, &session, &result) {
                Ok(report) => report,
                // The paper's wrist has no lengths: no positions to test.
                Err(e) => {
                    out.push_str(&format!("\nno positioning test: {e}\n"));
                    return Ok(out);
                }
            };
            out.push_str(&format!(
                "\n-- positioning accuracy, ISO 9283-style, {} --\n",
                profile.title
            ));
            out.push_str(&report.to_string());
            if let Some(dir) = &args.plot {
                for f in simulate::plots(dir, &session, &result, &report)? {
                    out.push_str(&format!("wrote {}\n", f.display()));
                }
            }
            Ok(out)
        }
        Command::Identify(args) => identify::run(args),
        Command::Plan(args) => plan::run(args),
        Command::Session(args) => session::run(args),
        Command::Program(args) => program::run(args),
        Command::Pendant(args) => zerocal_link::run(args),
        Command::Bracket(args) => zerocal_programs::bracket_design::run(args),
        Command::Check(args) => zerocal_analysis::check::run(args),
        Command::Certificate(args) => zerocal_records::certificate::run(args),
        Command::Restore(args) => zerocal_analysis::restore::run(args),
        Command::History(args) => zerocal_records::history::run(args),
        Command::Serve(args) => zerocal_cli::serve::run(args),
        // Prints and exits by itself (`main`): its check's status is by severity.
        Command::Profile(_) => Err(CliError::Input(String::from("profile: not run here"))),
    }
}

fn main() -> ExitCode {
    let cli: Cli = zerocal_inputs::args::parse();
    if let Command::Profile(args) = &cli.command {
        return zerocal_cli::profile_cmd::main(args);
    }
    match run(&cli) {
        Ok(out) => {
            let mut stdout = std::io::stdout().lock();
            match writeln!(stdout, "{}", out.trim_end()).and_then(|()| stdout.flush()) {
                // `zerocal ... | head` closes the pipe early: not an error of ours.
                Ok(()) => ExitCode::SUCCESS,
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("zerocal: cannot write the output: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Err(e) => {
            eprintln!("zerocal: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
    }
}
