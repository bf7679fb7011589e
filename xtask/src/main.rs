//! `cargo xtask`: the project's build tasks, in Rust rather than shell scripts.
//!
//! The firmware and the no_std check build for `thumbv7em-none-eabihf` with whichever
//! toolchain this machine has, each tool named by its absolute path: rustup's with the
//! target installed (and its own rust-lld), or Debian's rustc with `-Zbuild-std=core`
//! linked by Debian's ld.lld, installed with apt-get when missing. [`toolchain`] is the
//! one owner of that knowledge; `cargo xtask setup` runs it alone.

mod browser_test;
mod cad;
mod certificate;
mod dfu;
mod dist;
mod figures;
mod fleet_bench;
mod fuzz;
mod history_demo;
mod measured;
mod pendant_sim;
mod postgres;
mod size;
mod target_test;
mod toolchain;

use std::path::{Path, PathBuf};

use anyhow::Result;
use clap::{Parser, Subcommand};

use toolchain::ToolchainChoice;

/// zerocal's build tasks.
#[derive(Parser)]
#[command(name = "cargo xtask", about)]
struct Cli {
    /// The thumb toolchain: `auto` takes rustup's when its thumb target is installed,
    /// else Debian's (installed with apt-get when missing, as root).
    #[arg(long, value_enum, global = true, default_value_t = ToolchainChoice::Auto)]
    toolchain: ToolchainChoice,
    #[command(subcommand)]
    command: Command,
}

/// One task per variant. Each builds what it needs itself.
#[derive(Subcommand)]
enum Command {
    /// Install and check what the thumb build and the QEMU check need (rustup's thumb
    /// target with its own rust-lld, `rustup target add` tried when missing; else
    /// Debian's rustc-web, cargo-web, rust-web-src and the lld-N of its LLVM;
    /// qemu-system-arm; chromium, poppler-utils and fonts-dejavu-core for the
    /// certificate; Debian's postgresql for the history's tests), and print which tools
    /// are used.
    Setup,
    /// Build the release firmware (firmware/, thumbv7em-none-eabihf) and print its
    /// flash and static RAM use; saved in docs/measured/firmware-TOOLCHAIN.txt (every
    /// command that builds the firmware saves it), which `figures` writes the docs from.
    Firmware,
    /// Build the release firmware and print where its flash and static RAM go: one row
    /// per crate (per module for zerocal's own), from the ELF's symbols, against the
    /// plan's ceilings (docs/flash-plan.md); saved in docs/measured/size-TOOLCHAIN.txt
    /// (every firmware build saves it).
    Size,
    /// Build the release firmware and write target/dfu/zerocal.dfu, a DfuSe image for
    /// the STM32's ROM bootloader (`dfu-util -a 0 -D zerocal.dfu`): the vector table and
    /// the program as two elements, the calibration store left alone. Reads the file
    /// back and checks it against the ELF.
    Dfu,
    /// A release bundle in target/dist/zerocal-VERSION/ (and .tar.gz): the firmware ELF
    /// and DFU image, the `zerocal` release binary, README.md, docs/ and SHA256SUMS.
    Dist,
    /// Build each no_std crate (zerocal-core, zerocal-procedure, zerocal-scl3300) alone
    /// for thumbv7em-none-eabihf, without features and with its optional derives: proves
    /// each is no_std (a host build cannot, std being always there).
    CoreThumb,
    /// Run zerocal-core on the pendant's CPU in QEMU (target-test/, netduinoplus2):
    /// stages 0-2 in f32 on seeded simulated sessions, compared with the host's f64
    /// solution within 2e-5 deg; then the instructions and peak stack of one 30-pose
    /// fit and the release firmware's flash and static RAM, against their budgets.
    TargetTest,
    /// Run the pendant's application on the desktop: a whole calibration on a
    /// simulated robot (SCL3300 at the SPI-frame level, SSD1306 as a frame buffer, USB
    /// as a byte stream, the F411's flash sectors), then the fault scenarios. Writes
    /// DIR/export, DIR/status, DIR/result-screen, DIR/screens/NN-name.png and
    /// DIR/truth.json; prints the identified offsets beside the truth.
    PendantSim {
        /// Where to write the export, the screens and the truth.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// Seed of the simulated world (truth and noise).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Also cut the power at every flash write and erase of a session in turn,
        /// reboot and finish; report what was lost or duplicated.
        #[arg(long)]
        power_cuts: bool,
        /// At most this many cut points, spread over the session (default: all).
        #[arg(long, value_name = "N")]
        cut_limit: Option<usize>,
        /// Fail if the gallery in DIR (and docs/pendant.md's table) differs from what the
        /// code draws.
        #[arg(long, value_name = "DIR")]
        check_gallery: Option<PathBuf>,
        /// Write the gallery into DIR and docs/pendant.md's table.
        #[arg(long, value_name = "DIR")]
        write_gallery: Option<PathBuf>,
    },
    /// Compares one pendant-sim session's numbers three ways, to the printed digit:
    /// DIR/result-screen (the result screen as drawn), DIR/status (the link's `status`)
    /// and DIR/session.txt (`zerocal session DIR/export`). Fails naming each joint whose
    /// Δθ or 1σ differs.
    PendantAgree {
        /// The pendant-sim output directory, with session.txt beside its export.
        dir: PathBuf,
    },
    /// Print a calibration certificate (`zerocal certificate`'s FILE.html) to
    /// OUTDIR/certificate.pdf with headless Chromium and its first page to
    /// OUTDIR/certificate.png; then fail naming each number of NUMBERS (FILE.numbers, one
    /// a line) that the PDF's text does not hold, or a PDF of more than two A4 pages.
    /// Installs chromium and poppler-utils when missing (as root).
    /// One simulated robot's history through `zerocal`: five sessions recorded, a
    /// motor swap restored and checked, the history plotted, the first session's
    /// certificate printed and checked (headless Chromium). `--write-docs DIR` copies
    /// the A3 plot and the certificate's first page there.
    HistoryDemo {
        /// Where everything goes.
        #[arg(long, default_value = "target/history-demo")]
        out: PathBuf,
        /// Copy the README's figures into this directory (docs).
        #[arg(long)]
        write_docs: Option<PathBuf>,
    },
    CertificateRender {
        /// The certificate's HTML.
        html: PathBuf,
        /// Every number it prints, one a line.
        numbers: PathBuf,
        /// Where the PDF and the PNG go (created).
        outdir: PathBuf,
    },
    /// Render the bracket designs of cad/ to docs/cad/*.png with OpenSCAD (under
    /// xvfb-run when there is no display). Not run by CI: run it after changing a
    /// design and commit the pictures.
    Cad,
    /// The web application (`zerocal serve`) in headless Chromium, as its people use it:
    /// on a fresh SQLite history (and PostgreSQL when ZEROCAL_TEST_POSTGRES is set;
    /// under CI=true it must be), a technician signs in, uploads two simulated exports
    /// and finds the robot on the fleet page, a reviewer checks and an authorizer signs
    /// its certificate, each seeing the review's state; the audit log and the users page
    /// show them. Fails naming the step and what the page showed.
    BrowserTest {
        /// Where the histories, exports, server logs and a failure's screenshot go.
        #[arg(long, default_value = "target/browser-test")]
        out: PathBuf,
        /// Write a screenshot of each page into this directory (docs/web).
        #[arg(long, value_name = "DIR")]
        screenshots: Option<PathBuf>,
    },
    /// A throwaway PostgreSQL cluster in target/postgres for the history's tests:
    /// `start` (fresh cluster on a free local port, database zerocal_test; prints its
    /// URL, for ZEROCAL_TEST_POSTGRES) or `stop`.
    Postgres {
        #[arg(value_enum)]
        action: PostgresAction,
    },
    /// The web application's fleet page at a plant's scale: runs `cargo bench -p
    /// zerocal-web --bench fleet_page` (1,000 robots, 20,000 records, SQLite) and saves
    /// its time per page and pages per second in docs/measured/fleet-page.txt, which
    /// `figures` writes docs/web.md from.
    FleetBench,
    /// Write every figure the README and docs/ quote from a simulation, a budget, an
    /// example's output or the firmware's size into its marked block
    /// (`<!-- figures:NAME -->` … `<!-- /figures:NAME -->`), each made by the command
    /// `--list` names: `zerocal` runs (release build), the tests that print figures, and
    /// the firmware's saved measurements (docs/measured/). `--check` writes nothing and
    /// fails naming each block whose text is not what its command makes now.
    Figures {
        /// Fail on a stale block instead of writing it.
        #[arg(long)]
        check: bool,
        /// Only these figures (default: every one the documents use).
        #[arg(long, value_name = "NAME")]
        only: Vec<String>,
        /// List every figure, its command and where it is used; run nothing.
        #[arg(long)]
        list: bool,
    },
    /// Fuzz the parsers of outside bytes (fuzz/, cargo-fuzz and libFuzzer on the stable
    /// toolchain with RUSTC_BOOTSTRAP=1; installs cargo-fuzz if missing). `--smoke`
    /// runs every target for 20 s from the committed corpus and fails on any crash,
    /// hang or runaway allocation; `TARGET... --time SECS` is a campaign that adds to
    /// fuzz/corpus; `--minimize` merges the corpus down before it is committed.
    Fuzz {
        /// The targets (default: all).
        #[arg(value_name = "TARGET")]
        targets: Vec<String>,
        /// Every target for a short fixed time (CI).
        #[arg(long, conflicts_with_all = ["time", "runs", "minimize"])]
        smoke: bool,
        /// Seconds per target.
        #[arg(long, value_name = "SECS")]
        time: Option<u32>,
        /// Executions per target.
        #[arg(long, value_name = "N")]
        runs: Option<u64>,
        /// Merge each target's corpus (fuzz/corpus/TARGET) down to what adds coverage.
        #[arg(long)]
        minimize: bool,
    },
}

/// `cargo xtask postgres ACTION`.
#[derive(Clone, Copy, clap::ValueEnum)]
enum PostgresAction {
    /// Make and start a fresh cluster, print the test database's URL.
    Start,
    /// Stop it.
    Stop,
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    match cli.command {
        Command::Setup => toolchain::setup(cli.toolchain).and_then(|()| postgres::setup()),
        Command::Firmware => firmware(cli.toolchain),
        Command::Size => size_table(cli.toolchain),
        Command::Dfu => dfu::run(&repo_root(), cli.toolchain).map(|_| ()),
        Command::Dist => dist::run(&repo_root(), cli.toolchain),
        Command::CoreThumb => core_thumb(cli.toolchain),
        Command::TargetTest => target_test::run(&repo_root(), cli.toolchain),
        Command::PendantAgree { dir } => pendant_sim::agree(&dir),
        Command::Cad => cad::run(&repo_root()),
        Command::HistoryDemo { out, write_docs } => history_demo::run(&out, write_docs.as_deref()),
        Command::CertificateRender {
            html,
            numbers,
            outdir,
        } => certificate::run(&html, &numbers, &outdir),
        Command::FleetBench => fleet_bench::run(&repo_root()),
        Command::BrowserTest { out, screenshots } => {
            browser_test::run(&repo_root(), &browser_test::Options { out, screenshots })
        }
        Command::Postgres {
            action: PostgresAction::Start,
        } => postgres::start(&repo_root()),
        Command::Postgres {
            action: PostgresAction::Stop,
        } => postgres::stop(&repo_root()),
        Command::PendantSim {
            out,
            seed,
            power_cuts,
            cut_limit,
            check_gallery,
            write_gallery,
        } => pendant_sim::run(
            &repo_root(),
            &pendant_sim::Options {
                out,
                seed,
                power_cuts,
                cut_limit,
                check_gallery,
                write_gallery,
            },
        ),
        Command::Figures { check, only, list } => {
            figures::run(&repo_root(), &figures::Options { check, only, list })
        }
        Command::Fuzz {
            targets,
            smoke,
            time,
            runs,
            minimize,
        } => fuzz::run(
            &repo_root(),
            &fuzz::Options {
                smoke,
                targets,
                time,
                runs,
                minimize,
            },
        ),
    }
}

/// The repository root: xtask lives one level below it.
fn repo_root() -> PathBuf {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest_dir
        .parent()
        .map_or_else(|| manifest_dir.to_path_buf(), Path::to_path_buf)
}

fn firmware(choice: ToolchainChoice) -> Result<()> {
    let built = build_firmware(&repo_root(), choice)?;
    println!("firmware toolchain: {}", built.toolchain.describe());
    println!("{}", built.usage.report(&built.capacity));
    Ok(())
}

fn size_table(choice: ToolchainChoice) -> Result<()> {
    let built = build_firmware(&repo_root(), choice)?;
    println!("firmware toolchain: {}", built.toolchain.describe());
    println!("{}", built.usage.report(&built.capacity));
    println!("{:<44} {:>9} {:>9}", "crate or module", "flash B", "RAM B");
    for (name, flash, ram) in built.sizes.by_flash() {
        println!("{name:<44} {flash:>9} {ram:>9}");
    }
    let (flash, ram) = built.sizes.totals();
    println!("{:<44} {flash:>9} {ram:>9}", "total");
    Ok(())
}

/// A release firmware build and what it takes.
struct FirmwareBuild {
    /// The toolchain that built it.
    toolchain: toolchain::ThumbToolchain,
    /// The ELF.
    elf: PathBuf,
    /// Its flash and static RAM.
    usage: size::MemoryUsage,
    /// The same, by crate and module.
    sizes: size::ModuleSizes,
    /// The capacities of `memory.x`.
    capacity: size::MemoryCapacity,
}

/// Builds the release firmware and measures it against the capacities of `memory.x`.
///
/// # Errors
/// No toolchain, a failed build, an unreadable ELF or `memory.x`.
fn build_firmware(root: &Path, choice: ToolchainChoice) -> Result<FirmwareBuild> {
    let firmware_dir = root.join("firmware");
    let tools = toolchain::provision(toolchain::Needs::THUMB, choice)?;
    let toolchain = tools.thumb()?;
    // The firmware's own .cargo/config.toml selects the target; its own [workspace]
    // keeps host features out.
    toolchain.cargo_build_with(
        &firmware_dir,
        &["--release"],
        toolchain::Panics::ImmediateAbort,
    )?;
    let elf = toolchain
        .target_dir(&firmware_dir)
        .join(toolchain::THUMB_TARGET)
        .join("release")
        .join("zerocal-firmware");
    let capacity = size::MemoryCapacity::from_memory_x(&root.join("memory.x"))?;
    let usage = size::MemoryUsage::of_elf(&elf)?;
    let sizes = size::ModuleSizes::of_elf(&elf)?;
    if sizes.totals() != (usage.flash_bytes, usage.ram_bytes) {
        anyhow::bail!(
            "{}: the symbols' rows add up to {:?} bytes (flash, RAM), the sections to {:?}",
            elf.display(),
            sizes.totals(),
            (usage.flash_bytes, usage.ram_bytes)
        );
    }
    // The difference from the committed measurement: what this change costs.
    for (key, now) in [
        ("flash_bytes", usage.flash_bytes),
        ("static_ram_bytes", usage.ram_bytes),
    ] {
        match measured::committed(root, "firmware", toolchain.kind).and_then(|m| m.count(key)) {
            Ok(before) => println!(
                "firmware {key}: {now} here, {before} committed ({:+} B)",
                i128::from(now) - i128::from(before)
            ),
            Err(e) => println!("firmware {key}: {now} here, no committed figure ({e:#})"),
        }
    }
    measured::save(
        root,
        "size",
        toolchain.kind,
        &toolchain.describe(),
        &size::measured_rows(&sizes)
            .iter()
            .map(|(k, v)| (k.as_str(), v.clone()))
            .collect::<Vec<_>>(),
    )?;
    measured::save(
        root,
        "firmware",
        toolchain.kind,
        &toolchain.describe(),
        &[
            ("flash_bytes", usage.flash_bytes.to_string()),
            ("static_ram_bytes", usage.ram_bytes.to_string()),
            ("flash_capacity_bytes", capacity.flash_bytes.to_string()),
            ("ram_capacity_bytes", capacity.ram_bytes.to_string()),
        ],
    )?;
    Ok(FirmwareBuild {
        toolchain: toolchain.clone(),
        elf,
        usage,
        sizes,
        capacity,
    })
}

/// The no_std crates and the feature sets each is proved with: as the firmware takes it,
/// and with every optional derive.
const NO_STD_CRATES: [(&str, &str, [Option<&str>; 2]); 3] = [
    ("zerocal-core", "core", [None, Some("defmt,serde")]),
    (
        "zerocal-procedure",
        "procedure",
        [None, Some("defmt,serde")],
    ),
    (
        "zerocal-scl3300",
        "scl3300",
        [Some("driver"), Some("defmt")],
    ),
];

fn core_thumb(choice: ToolchainChoice) -> Result<()> {
    let root = repo_root();
    let tools = toolchain::provision(toolchain::Needs::THUMB, choice)?;
    let toolchain = tools.thumb()?;
    // One crate selected at a time, so no other member's features (std) unify into it;
    // its own target dir keeps the host build's cache intact.
    let target_dir = root.join("target").join("thumb");
    for (name, dir, feature_sets) in NO_STD_CRATES {
        let manifest = root.join(dir).join("Cargo.toml");
        for features in feature_sets {
            let mut args = vec![
                "--manifest-path",
                path_str(&manifest)?,
                "--target",
                toolchain::THUMB_TARGET,
                "--target-dir",
                path_str(&target_dir)?,
            ];
            if let Some(f) = features {
                args.extend(["--features", f]);
            }
            toolchain.cargo_build(&root, &args)?;
            println!(
                "{name} builds for {} (no_std), features: {}",
                toolchain::THUMB_TARGET,
                features.unwrap_or("none")
            );
        }
    }
    Ok(())
}

fn path_str(path: &Path) -> Result<&str> {
    path.to_str()
        .ok_or_else(|| anyhow::anyhow!("path is not UTF-8: {}", path.display()))
}
