//! Provisioning: the one place that knows which tools the thumb build, the QEMU check and
//! the certificate's rendering need, where they live, and how to install them (`cargo
//! xtask setup`).
//!
//! Every xtask command that builds for the pendant's CPU or runs QEMU calls
//! [`provision`] first; `.ci/run` calls `cargo xtask setup` and repeats no package list
//! or path. Each tool is named by its absolute path, never looked up on `PATH`, so a
//! tool some other installer left on this machine cannot make a build pass here and
//! fail on a fresh one.
//!
//! Two thumb toolchains, chosen by `--toolchain` ([`ToolchainChoice`]):
//!
//! - **rustup with the thumb target** (what the README tells users to install): its own
//!   `cargo`/`rustc` and the `rust-lld` shipped inside the toolchain's sysroot. Its
//!   precompiled `core` keeps panic messages and locations in the image.
//! - **Debian's toolchain**: `rustc-web` and `cargo-web`, `rust-web-src` (the library
//!   sources for `-Zbuild-std=core`) and the `lld-N` of the LLVM that Debian's rustc is
//!   built on (`rustc -vV`: Debian 12's rustc-web 1.96 is on LLVM 22, so `lld-22` and
//!   `ld.lld-22`; its 1.85 was on LLVM 19). Rebuilding `core` lets panics abort at once. Installed without
//!   recommends: `rustc-web` merely recommends `rust-web-llvm`, the package with a
//!   `/usr/bin/rust-lld` symlink, so a build that relied on rustc finding `rust-lld` by
//!   itself passed where apt had installed recommends and failed where it had not.
//!
//! `auto` (the default) takes rustup's when its thumb target is installed, else
//! Debian's; `cargo xtask setup` first tries `rustup target add` (which fails offline).
//! Installing is `apt-get install -y --no-install-recommends` as root (anyone else is
//! told the command); QEMU (`qemu-system-arm`) for `cargo xtask target-test` comes the
//! same way, and so do the certificate's renderer and its check (`chromium`,
//! `poppler-utils`, and `fonts-dejavu-core` so that the printed page's font is the same
//! on every machine) for `cargo xtask certificate-render`.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

/// The pendant's target: Cortex-M4F with hardware floating point.
pub const THUMB_TARGET: &str = "thumbv7em-none-eabihf";

/// The cargo variable that names the thumb target's linker.
const LINKER_VARIABLE: &str = "CARGO_TARGET_THUMBV7EM_NONE_EABIHF_LINKER";

/// A Debian package and the file that shows it is installed.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Package {
    name: String,
    provides: PathBuf,
}

impl Package {
    fn new(name: &str, provides: &str) -> Package {
        Package {
            name: name.to_owned(),
            provides: PathBuf::from(provides),
        }
    }
}

/// Debian's thumb toolchain less its linker: rustc with the standard library sources,
/// used with `RUSTC_BOOTSTRAP=1 -Zbuild-std=core` because Debian ships no thumb std.
/// The linker is [`debian_lld`], whose version follows the rustc installed.
fn debian_rust() -> [Package; 3] {
    [
        Package::new("rustc-web", DEBIAN_RUSTC),
        Package::new("cargo-web", DEBIAN_CARGO),
        Package::new(
            "rust-web-src",
            "/usr/lib/rustlib/src/rust/library/core/Cargo.toml",
        ),
    ]
}

/// `lld-N` for the LLVM major version `llvm_major` (Debian's versioned packages install
/// `/usr/bin/ld.lld-N`).
fn debian_lld(llvm_major: u32) -> Package {
    Package {
        name: format!("lld-{llvm_major}"),
        provides: PathBuf::from(format!("/usr/bin/ld.lld-{llvm_major}")),
    }
}

const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";

/// The first rustc whose `-Cpanic=immediate-abort` replaces the older
/// `-Zbuild-std-features=panic_immediate_abort` (which it then refuses).
const PANIC_STRATEGY_SINCE_MINOR: u32 = 92;

/// QEMU with the `netduinoplus2` (STM32F405, Cortex-M4F) machine.
fn qemu_package() -> Package {
    Package::new("qemu-system-arm", "/usr/bin/qemu-system-arm")
}

/// What renders a certificate's HTML to PDF and checks it: headless Chromium, poppler's
/// `pdftotext`, `pdftoppm` and `pdfinfo`, and the font the page names first.
fn render_packages() -> [Package; 3] {
    [
        Package::new("chromium", CHROMIUM),
        Package::new("poppler-utils", PDFTOTEXT),
        Package::new(
            "fonts-dejavu-core",
            "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
        ),
    ]
}

/// Debian's headless-capable Chromium.
const CHROMIUM: &str = "/usr/bin/chromium";
/// poppler-utils' tools, one package.
const PDFTOTEXT: &str = "/usr/bin/pdftotext";
const PDFTOPPM: &str = "/usr/bin/pdftoppm";
const PDFINFO: &str = "/usr/bin/pdfinfo";
/// Debian's PostgreSQL server (the `postgresql` package pulls in the server of
/// Debian's current major version, its binaries under `/usr/lib/postgresql/N/bin`), for
/// the history's PostgreSQL tests (`cargo xtask postgres start`). The metapackage's own
/// file is its copyright notice, which Debian's slim images keep.
fn postgres_package() -> Package {
    Package::new("postgresql", "/usr/share/doc/postgresql/copyright")
}

/// Installs Debian's PostgreSQL server when missing (see [`postgres_package`]).
///
/// # Errors
/// Missing and not installable (the message names the command).
pub fn provision_postgres() -> Result<()> {
    let package = postgres_package();
    if !installed(&package) {
        install(std::slice::from_ref(&package))?;
    }
    require(std::slice::from_ref(&package))
}

/// Variables that cargo, rustc's wrappers and rustup set for the process running
/// xtask. Left in place they would make the child build use the host toolchain, the
/// host's target directory, its flags or its manifest.
const LEAKED_VARIABLES: [&str; 15] = [
    "RUSTUP_TOOLCHAIN",
    "RUST_RECURSION_COUNT",
    "CARGO",
    "RUSTC",
    "RUSTDOC",
    "RUSTC_WRAPPER",
    "RUSTC_WORKSPACE_WRAPPER",
    "RUSTFLAGS",
    "RUSTDOCFLAGS",
    "CARGO_ENCODED_RUSTFLAGS",
    "CARGO_TARGET_DIR",
    "CARGO_BUILD_TARGET",
    "CARGO_BUILD_TARGET_DIR",
    "CARGO_MANIFEST_DIR",
    LINKER_VARIABLE,
];

/// What a command needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Needs {
    /// A toolchain and linker for [`THUMB_TARGET`].
    pub thumb: bool,
    /// `qemu-system-arm`.
    pub qemu: bool,
    /// Chromium and poppler-utils ([`RenderTools`]).
    pub render: bool,
}

impl Needs {
    /// Everything (`cargo xtask setup`).
    pub const ALL: Needs = Needs {
        thumb: true,
        qemu: true,
        render: true,
    };
    /// The thumb build and QEMU (the target test).
    pub const TARGET_TEST: Needs = Needs {
        thumb: true,
        qemu: true,
        render: false,
    };
    /// The thumb build only.
    pub const THUMB: Needs = Needs {
        thumb: true,
        qemu: false,
        render: false,
    };
    /// The certificate's renderer only.
    pub const RENDER: Needs = Needs {
        thumb: false,
        qemu: false,
        render: true,
    };
}

/// What prints a certificate and reads it back, each by absolute path.
#[derive(Clone, Debug)]
pub struct RenderTools {
    /// Headless Chromium.
    pub chromium: PathBuf,
    /// The PDF's text, laid out (`pdftotext -layout`).
    pub pdftotext: PathBuf,
    /// A PDF page as PNG.
    pub pdftoppm: PathBuf,
    /// The PDF's page count.
    pub pdfinfo: PathBuf,
}

/// The tools found, each by absolute path.
#[derive(Clone, Debug)]
pub struct Tools {
    /// The thumb toolchain, if asked for.
    pub thumb: Option<ThumbToolchain>,
    /// `qemu-system-arm`, if asked for.
    pub qemu: Option<PathBuf>,
    /// The certificate's renderer, if asked for.
    pub render: Option<RenderTools>,
}

impl Tools {
    /// The thumb toolchain.
    ///
    /// # Errors
    /// When [`provision`] was not asked for it.
    pub fn thumb(&self) -> Result<&ThumbToolchain> {
        self.thumb
            .as_ref()
            .context("internal: the thumb toolchain was not provisioned")
    }

    /// `qemu-system-arm`.
    ///
    /// # Errors
    /// When [`provision`] was not asked for it.
    pub fn qemu(&self) -> Result<&Path> {
        self.qemu
            .as_deref()
            .context("internal: QEMU was not provisioned")
    }

    /// The certificate's renderer.
    ///
    /// # Errors
    /// When [`provision`] was not asked for it.
    pub fn render(&self) -> Result<&RenderTools> {
        self.render
            .as_ref()
            .context("internal: the certificate's renderer was not provisioned")
    }
}

/// Which toolchain builds for the thumb target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolchainKind {
    /// rustup's, with the target's std installed.
    Rustup,
    /// Debian's, building `core` from source.
    Debian,
}

/// The toolchain asked for on the command line (`--toolchain`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ToolchainChoice {
    /// rustup's if its thumb target is installed, else Debian's.
    #[default]
    Auto,
    /// rustup's; fails if its thumb target is not installed.
    Rustup,
    /// Debian's, installed with apt-get when missing.
    Debian,
}

/// How a build-std toolchain makes panics abort at once.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImmediateAbort {
    /// `-Zunstable-options -Cpanic=immediate-abort` (rustc 1.92 on).
    PanicStrategy,
    /// `-Zbuild-std-features=panic_immediate_abort` (before 1.92).
    StdFeature,
}

/// A toolchain that can build for [`THUMB_TARGET`], with its linker.
#[derive(Clone, Debug)]
pub struct ThumbToolchain {
    /// Which one.
    pub kind: ToolchainKind,
    /// The `cargo` to run.
    pub cargo: PathBuf,
    /// The `rustc` it must use, named to cargo (`RUSTC`): cargo would otherwise run the
    /// first `rustc` on PATH, which in CI is Debian's even for rustup's cargo.
    pub rustc: PathBuf,
    /// `rustc -V` of the compiler used.
    pub rustc_version: String,
    /// The linker, named to cargo explicitly.
    pub linker: PathBuf,
    /// How panics can abort at once, if the toolchain rebuilds `core`.
    pub immediate_abort: Option<ImmediateAbort>,
}

/// Finds what `needs` asks for with the toolchain `choice`, installing what is missing
/// with apt-get, and checks that every file is there afterwards.
///
/// # Errors
/// A tool that is missing and cannot be installed (the message names it, its package
/// and the command that installs it), or rustup asked for without its thumb target.
pub fn provision(needs: Needs, choice: ToolchainChoice) -> Result<Tools> {
    let rustup = if needs.thumb && choice != ToolchainChoice::Debian {
        rustup_thumb_toolchain()?
    } else {
        None
    };
    if needs.thumb && choice == ToolchainChoice::Rustup && rustup.is_none() {
        bail!(
            "xtask: --toolchain rustup, but rustup has no {THUMB_TARGET} target here; \
             install it with `rustup target add {THUMB_TARGET}` (needs the internet) or use \
             --toolchain debian"
        );
    }
    let debian = needs.thumb && rustup.is_none();
    let mut missing: Vec<Package> = Vec::new();
    if debian {
        missing.extend(debian_rust().into_iter().filter(|p| !installed(p)));
    }
    if needs.qemu && !installed(&qemu_package()) {
        missing.push(qemu_package());
    }
    if needs.render {
        missing.extend(render_packages().into_iter().filter(|p| !installed(p)));
    }
    if !missing.is_empty() {
        install(&missing)?;
    }
    let thumb = match (needs.thumb, rustup) {
        (false, _) => None,
        (true, Some(t)) => Some(t),
        (true, None) => Some(debian_thumb_toolchain()?),
    };
    let qemu = if needs.qemu {
        let package = qemu_package();
        require(std::slice::from_ref(&package))?;
        Some(package.provides)
    } else {
        None
    };
    let render = if needs.render {
        require(&render_packages())?;
        Some(RenderTools {
            chromium: CHROMIUM.into(),
            pdftotext: PDFTOTEXT.into(),
            pdftoppm: PDFTOPPM.into(),
            pdfinfo: PDFINFO.into(),
        })
    } else {
        None
    };
    Ok(Tools {
        thumb,
        qemu,
        render,
    })
}

/// Debian's toolchain, its rustc installed: the `lld-N` of rustc's LLVM (installed if
/// missing), and how this rustc aborts at once.
fn debian_thumb_toolchain() -> Result<ThumbToolchain> {
    require(&debian_rust())?;
    let verbose = output_of(Command::new(DEBIAN_RUSTC).arg("-vV"))
        .with_context(|| format!("`{DEBIAN_RUSTC} -vV` fails"))?;
    let (minor, llvm_major) = parse_rustc_verbose_version(&verbose)
        .with_context(|| format!("`{DEBIAN_RUSTC} -vV` printed:\n{verbose}"))?;
    let lld = debian_lld(llvm_major);
    if !installed(&lld) {
        install(std::slice::from_ref(&lld))?;
    }
    require(std::slice::from_ref(&lld))?;
    Ok(ThumbToolchain {
        kind: ToolchainKind::Debian,
        cargo: DEBIAN_CARGO.into(),
        rustc: DEBIAN_RUSTC.into(),
        rustc_version: verbose.lines().next().unwrap_or_default().to_owned(),
        linker: lld.provides,
        immediate_abort: Some(immediate_abort_for(minor)),
    })
}

/// How a build-std rustc 1.`minor` makes panics abort at once.
fn immediate_abort_for(minor: u32) -> ImmediateAbort {
    if minor >= PANIC_STRATEGY_SINCE_MINOR {
        ImmediateAbort::PanicStrategy
    } else {
        ImmediateAbort::StdFeature
    }
}

/// `(minor, LLVM major)` from `rustc -vV`: `rustc 1.85.0 (…)` and `LLVM version: 19.1.7`.
fn parse_rustc_verbose_version(verbose: &str) -> Result<(u32, u32)> {
    let release = verbose
        .lines()
        .find_map(|l| l.strip_prefix("release: "))
        .context("no `release:` line")?;
    let mut parts = release.trim().split('.');
    let major = parts.next().context("empty release")?;
    if major != "1" {
        bail!("rustc release {release} is not 1.x");
    }
    let minor = parts
        .next()
        .context("release without a minor version")?
        .parse()
        .with_context(|| format!("minor version of release {release}"))?;
    let llvm = verbose
        .lines()
        .find_map(|l| l.strip_prefix("LLVM version: "))
        .context("no `LLVM version:` line")?;
    let llvm_major = llvm
        .trim()
        .split('.')
        .next()
        .unwrap_or_default()
        .parse()
        .with_context(|| format!("LLVM version {llvm}"))?;
    Ok((minor, llvm_major))
}

/// `cargo xtask setup`: tries to add rustup's thumb target (unless Debian's toolchain
/// is asked for), provisions everything and says what is used (`cargo xtask setup` then
/// provisions PostgreSQL too: `postgres::setup`).
///
/// # Errors
/// As [`provision`].
pub fn setup(choice: ToolchainChoice) -> Result<()> {
    if choice != ToolchainChoice::Debian {
        try_rustup_target_add();
    }
    let tools = provision(Needs::ALL, choice)?;
    let thumb = tools.thumb()?;
    println!("thumb toolchain: {}", thumb.describe());
    println!("  cargo:  {}", thumb.cargo.display());
    println!("  rustc:  {}", thumb.rustc.display());
    println!("  linker: {}", thumb.linker.display());
    println!("qemu:     {}", tools.qemu()?.display());
    let render = tools.render()?;
    println!("chromium: {}", render.chromium.display());
    println!("pdftotext: {}", render.pdftotext.display());
    Ok(())
}

/// `rustup target add` for the thumb target when rustup is here without it. It needs
/// the internet: offline it fails, and the Debian toolchain is used instead.
fn try_rustup_target_add() {
    let Some(targets) = rustup_installed_targets() else {
        return;
    };
    if targets.lines().any(|line| line.trim() == THUMB_TARGET) {
        return;
    }
    eprintln!(
        "xtask: rustup has no {THUMB_TARGET} target; trying `rustup target add {THUMB_TARGET}`"
    );
    let status = Command::new("rustup")
        .args(["target", "add", THUMB_TARGET])
        .env_remove("RUSTUP_TOOLCHAIN")
        .status();
    match status {
        Ok(s) if s.success() => {}
        Ok(s) => {
            eprintln!("xtask: `rustup target add` failed ({s}); Debian's toolchain will build")
        }
        Err(e) => eprintln!("xtask: cannot run rustup ({e}); Debian's toolchain will build"),
    }
}

fn installed(package: &Package) -> bool {
    package.provides.exists()
}

/// Fails, naming each package whose file is still missing.
fn require(packages: &[Package]) -> Result<()> {
    let missing: Vec<String> = packages
        .iter()
        .filter(|p| !installed(p))
        .map(|p| format!("{} (package {})", p.provides.display(), p.name))
        .collect();
    if !missing.is_empty() {
        bail!(
            "xtask: still missing after installation: {}; run `cargo xtask setup` as root",
            missing.join(", ")
        );
    }
    Ok(())
}

/// `rustup target list --installed`, if rustup is here.
fn rustup_installed_targets() -> Option<String> {
    output_of(
        Command::new("rustup")
            .args(["target", "list", "--installed"])
            .env_remove("RUSTUP_TOOLCHAIN"),
    )
}

/// rustup's toolchain, if rustup is here and has the thumb target: its `cargo`, and the
/// `rust-lld` in the toolchain's own sysroot.
fn rustup_thumb_toolchain() -> Result<Option<ThumbToolchain>> {
    let Some(targets) = rustup_installed_targets() else {
        return Ok(None);
    };
    if !targets.lines().any(|line| line.trim() == THUMB_TARGET) {
        return Ok(None);
    }
    // rustup's own rustc by absolute path: `rustc` on PATH may be Debian's
    // (/usr/bin comes first in CI's PATH), whose sysroot has no rust-lld.
    let rustc = output_of(
        Command::new("rustup")
            .args(["which", "rustc"])
            .env_remove("RUSTUP_TOOLCHAIN"),
    )
    .context("rustup lists the thumb target but `rustup which rustc` fails")?;
    let rustc = PathBuf::from(rustc.trim());
    let sysroot = output_of(
        Command::new(&rustc)
            .args(["--print", "sysroot"])
            .env_remove("RUSTUP_TOOLCHAIN"),
    )
    .with_context(|| format!("`{} --print sysroot` fails", rustc.display()))?;
    let version = output_of(
        Command::new(&rustc)
            .arg("-vV")
            .env_remove("RUSTUP_TOOLCHAIN"),
    )
    .with_context(|| format!("`{} -vV` fails", rustc.display()))?;
    let host = version
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .context("`rustc -vV` names no host triple")?;
    let linker = Path::new(sysroot.trim())
        .join("lib/rustlib")
        .join(host.trim())
        .join("bin/rust-lld");
    if !linker.exists() {
        bail!(
            "rustup has the {THUMB_TARGET} target but its toolchain has no linker at {}; \
             reinstall the toolchain (`rustup toolchain install stable`)",
            linker.display()
        );
    }
    let cargo = output_of(
        Command::new("rustup")
            .args(["which", "cargo"])
            .env_remove("RUSTUP_TOOLCHAIN"),
    )
    .context("`rustup which cargo` fails")?;
    Ok(Some(ThumbToolchain {
        kind: ToolchainKind::Rustup,
        cargo: PathBuf::from(cargo.trim()),
        rustc,
        rustc_version: version.lines().next().unwrap_or_default().to_owned(),
        linker,
        immediate_abort: None,
    }))
}

/// The standard output of a command that ran and succeeded.
fn output_of(command: &mut Command) -> Option<String> {
    let output = command.output().ok()?;
    output
        .status
        .success()
        .then(|| String::from_utf8_lossy(&output.stdout).into_owned())
}

/// Removes from `command` the variables cargo and rustup set for xtask's own run, so
/// that a child cargo builds with its own toolchain, flags and target directory. Cargo
/// also sets CARGO_PKG_*, CARGO_BIN_* and CARGO_CRATE_NAME for xtask's own run: the
/// child cargo sets its own, but none should be inherited.
pub fn remove_leaked_variables(command: &mut Command) {
    for variable in LEAKED_VARIABLES {
        command.env_remove(variable);
    }
    for (variable, _) in std::env::vars_os() {
        let name = variable.to_string_lossy();
        if name.starts_with("CARGO_PKG_")
            || name.starts_with("CARGO_BIN_")
            || name == "CARGO_CRATE_NAME"
            || name == "CARGO_PRIMARY_PACKAGE"
        {
            command.env_remove(&variable);
        }
    }
}

/// cargo-fuzz at `version`, in cargo's bin directory: installed there with
/// `cargo install --locked` (from crates.io) when missing or another version.
///
/// # Errors
/// No cargo home, or the installation fails.
pub fn cargo_fuzz(version: &str) -> Result<PathBuf> {
    let home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")))
        .context("neither CARGO_HOME nor HOME is set: where is cargo's bin directory?")?;
    let path = home.join("bin").join("cargo-fuzz");
    let installed = output_of(Command::new(&path).args(["fuzz", "--version"]));
    if installed.is_some_and(|v| v.trim() == format!("cargo-fuzz {version}")) {
        return Ok(path);
    }
    eprintln!("xtask: installing cargo-fuzz {version} (cargo install --locked)");
    let mut command = Command::new("cargo");
    command.args([
        "install",
        "cargo-fuzz",
        "--locked",
        "--force",
        "--version",
        version,
    ]);
    remove_leaked_variables(&mut command);
    run(&mut command)?;
    if !path.exists() {
        bail!("cargo install put no cargo-fuzz at {}", path.display());
    }
    Ok(path)
}

/// `apt-get update`, then installs `packages`. Root only: anyone else gets the command
/// to run.
fn install(packages: &[Package]) -> Result<()> {
    let names: Vec<&str> = packages.iter().map(|p| p.name.as_str()).collect();
    let command = format!("apt-get update && apt-get install -y {}", names.join(" "));
    if !is_root() {
        bail!(
            "xtask: missing {} (needed: {}); install them as root: `{command}`",
            names.join(", "),
            packages
                .iter()
                .map(|p| p.provides.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    eprintln!("xtask: installing {}", names.join(" "));
    run(Command::new("apt-get")
        .args(["update", "-qq"])
        .env("DEBIAN_FRONTEND", "noninteractive"))?;
    run(Command::new("apt-get")
        .args(["install", "-y", "-qq", "--no-install-recommends"])
        .args(&names)
        .env("DEBIAN_FRONTEND", "noninteractive"))
}

pub(crate) fn is_root() -> bool {
    output_of(Command::new("id").arg("-u")).is_some_and(|uid| uid.trim() == "0")
}

fn run(command: &mut Command) -> Result<()> {
    let status = command
        .status()
        .with_context(|| format!("cannot run {command:?}"))?;
    if !status.success() {
        bail!("{command:?} failed ({status})");
    }
    Ok(())
}

impl ThumbToolchain {
    /// `rustup toolchain (rustc 1.95.0 …)`: which toolchain, for the logs and reports.
    pub fn describe(&self) -> String {
        let kind = match self.kind {
            ToolchainKind::Rustup => "rustup",
            ToolchainKind::Debian => "Debian",
        };
        format!("{kind} toolchain ({})", self.rustc_version)
    }

    /// Where a build of the crate in `dir` goes: cargo's default `dir/target` for
    /// rustup's toolchain (where `cargo build` in `dir` puts it too), `dir/target/debian`
    /// for Debian's, so that building with one does not throw away the other's cache.
    /// An explicit `--target-dir` in the build's arguments wins.
    pub fn target_dir(&self, dir: &Path) -> PathBuf {
        match self.kind {
            ToolchainKind::Rustup => dir.join("target"),
            ToolchainKind::Debian => dir.join("target").join("debian"),
        }
    }

    /// `cargo build` in `dir` with `args`, for the thumb target, with the linker named.
    ///
    /// # Errors
    /// When cargo cannot start or the build fails.
    pub fn cargo_build(&self, dir: &Path, args: &[&str]) -> Result<()> {
        self.cargo_build_with(dir, args, Panics::Handler)
    }

    /// As [`cargo_build`](Self::cargo_build); with [`Panics::ImmediateAbort`] and the
    /// build-std toolchain, panics abort at once ([`ImmediateAbort`]): no panic
    /// messages or locations in the image. The stable rustup toolchain cannot rebuild
    /// `core` that way (an immediate-abort crate cannot link its precompiled `core`) and
    /// keeps its panic handler.
    ///
    /// # Errors
    /// As [`cargo_build`](Self::cargo_build).
    pub fn cargo_build_with(&self, dir: &Path, args: &[&str], panics: Panics) -> Result<()> {
        let mut command = Command::new(&self.cargo);
        command.current_dir(dir).arg("build").args(args);
        remove_leaked_variables(&mut command);
        command.env(LINKER_VARIABLE, &self.linker);
        command.env("CARGO_TARGET_DIR", self.target_dir(dir));
        // Panic locations embed source paths; cut the machine-specific prefixes, so the
        // image neither depends on where it was built nor spends ~3 KiB of flash on
        // `/root/.cargo/registry/src/index.crates.io-…/` 47 times.
        // Encoded (0x1f-separated) so that a path with spaces stays one argument.
        let mut flags = remap_flags(dir);
        let immediate_abort = match panics {
            Panics::ImmediateAbort => self.immediate_abort,
            Panics::Handler => None,
        };
        if immediate_abort == Some(ImmediateAbort::PanicStrategy) {
            flags.push_str("\u{1f}-Zunstable-options\u{1f}-Cpanic=immediate-abort");
        }
        command.env("CARGO_ENCODED_RUSTFLAGS", flags);
        command.env("RUSTC", &self.rustc);
        if self.kind == ToolchainKind::Debian {
            // No thumb std in Debian: `core` from rust-web-src's sources.
            command.env("RUSTC_BOOTSTRAP", "1").arg("-Zbuild-std=core");
        }
        if immediate_abort == Some(ImmediateAbort::StdFeature) {
            command.arg("-Zbuild-std-features=panic_immediate_abort");
        }
        let shown_args: Vec<_> = command
            .get_args()
            .map(|arg| arg.to_string_lossy())
            .collect();
        eprintln!(
            "xtask: in {}: {} {} ({}, linker {})",
            dir.display(),
            command.get_program().to_string_lossy(),
            shown_args.join(" "),
            self.describe(),
            self.linker.display()
        );
        let status = command
            .status()
            .with_context(|| format!("cannot run {}", self.cargo.display()))?;
        if !status.success() {
            bail!("build failed ({status}) in {}", dir.display());
        }
        Ok(())
    }
}

/// What a thumb build does on panic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panics {
    /// The panic handler runs (the target's `panic = "abort"` after it).
    Handler,
    /// Abort at once where the toolchain can rebuild `core` for it (the firmware: its
    /// HardFault handler keeps the address).
    ImmediateAbort,
}

/// `--remap-path-prefix` flags for the registry sources and the repository, in
/// `CARGO_ENCODED_RUSTFLAGS` form.
fn remap_flags(dir: &Path) -> String {
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")));
    let mut flags = Vec::new();
    if let Some(home) = cargo_home {
        // Each registry's own directory to nothing: a panic location then reads
        // `embassy-usb-0.6.0/src/lib.rs`, and the ~40 bytes of prefix on each of the
        // firmware's ~60 locations stay out of its 128 KiB.
        // (rustc applies the last matching prefix: the general one goes first.)
        let src = home.join("registry").join("src");
        flags.push(format!("--remap-path-prefix={}=/deps", src.display()));
        if let Ok(entries) = std::fs::read_dir(&src) {
            for e in entries.flatten() {
                flags.push(format!("--remap-path-prefix={}/=", e.path().display()));
            }
        }
    }
    if let Some(repo) = dir.parent() {
        flags.push(format!("--remap-path-prefix={}=/zerocal", repo.display()));
    }
    flags.join("\u{1f}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_minor_version_and_llvm_major_of_rustc() {
        // Debian 12's rustc-web, `rustc -vV`, before and after its update.
        let old = "rustc 1.85.0 (4d91de4e4 2025-02-17) (built from a source tarball)\n\
                   binary: rustc\nhost: x86_64-unknown-linux-gnu\nrelease: 1.85.0\n\
                   LLVM version: 19.1.7\n";
        let new = "rustc 1.96.0 (ac68faa20 2026-05-25) (built from a source tarball)\n\
                   binary: rustc\ncommit-hash: ac68faa20c58cbccd01ee7208bf3b6e93a7d7f96\n\
                   commit-date: 2026-05-25\nhost: x86_64-unknown-linux-gnu\n\
                   release: 1.96.0\nLLVM version: 22.1.8\n";
        assert_eq!(parse_rustc_verbose_version(old).ok(), Some((85, 19)));
        assert_eq!(parse_rustc_verbose_version(new).ok(), Some((96, 22)));
        // 1.85 takes the std feature, 1.96 the panic strategy.
        assert_eq!(immediate_abort_for(85), ImmediateAbort::StdFeature);
        assert_eq!(immediate_abort_for(96), ImmediateAbort::PanicStrategy);
        assert_eq!(debian_lld(22).name, "lld-22");
        assert_eq!(debian_lld(22).provides, Path::new("/usr/bin/ld.lld-22"));
        assert!(parse_rustc_verbose_version("rustc 1.85.0\nrelease: 1.85.0\n").is_err());
        assert!(parse_rustc_verbose_version("release: 2.0.0\nLLVM version: 19\n").is_err());
    }
}
