//! Provisioning: the one place that knows which tools the thumb build and the QEMU check
//! need, where they live, and how to install them (`cargo xtask setup`).
//!
//! Every xtask command that builds for the pendant's CPU or runs QEMU calls
//! [`provision`] first; `.ci/run` calls `cargo xtask setup` and repeats no package list
//! or path. Each tool is named by its absolute path, never looked up on `PATH`, so a
//! tool some other installer left on this machine cannot make a build pass here and
//! fail on a fresh one.
//!
//! - **rustup with the thumb target** (what the README tells users to install): its own
//!   `cargo`/`rustc` and the `rust-lld` shipped inside the toolchain's sysroot.
//! - **Debian's toolchain** otherwise (rustup cannot download targets offline):
//!   `rustc-web` and `cargo-web` (rustc 1.96), `rust-web-src` (the library sources for
//!   `-Zbuild-std=core`) and `lld-22`, whose `ld.lld-22` links. Installed without
//!   recommends: `rustc-web` merely recommends `rust-web-llvm`, the package with a
//!   `/usr/bin/rust-lld` symlink, so a build that relied on rustc finding `rust-lld` by
//!   itself passed where apt had installed recommends and failed where it had not.
//! - **QEMU** (`qemu-system-arm`) for `cargo xtask target-test`.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

/// The pendant's target: Cortex-M4F with hardware floating point.
pub const THUMB_TARGET: &str = "thumbv7em-none-eabihf";

/// The cargo variable that names the thumb target's linker.
const LINKER_VARIABLE: &str = "CARGO_TARGET_THUMBV7EM_NONE_EABIHF_LINKER";

/// A Debian package and the file that shows it is installed.
struct Package {
    name: &'static str,
    provides: &'static str,
}

/// Debian's thumb toolchain: rustc with the standard library sources, used with
/// `RUSTC_BOOTSTRAP=1 -Zbuild-std=core` because Debian ships no thumb std; lld links.
const DEBIAN_TOOLCHAIN: [Package; 4] = [
    Package {
        name: "rustc-web",
        provides: "/usr/bin/rustc",
    },
    Package {
        name: "cargo-web",
        provides: "/usr/bin/cargo",
    },
    Package {
        name: "rust-web-src",
        provides: "/usr/lib/rustlib/src/rust/library/core/Cargo.toml",
    },
    Package {
        name: "lld-22",
        provides: "/usr/bin/ld.lld-22",
    },
];

const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";
const DEBIAN_LINKER: &str = "/usr/bin/ld.lld-22";

/// QEMU with the `netduinoplus2` (STM32F405, Cortex-M4F) machine.
const QEMU: Package = Package {
    name: "qemu-system-arm",
    provides: "/usr/bin/qemu-system-arm",
};

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
}

impl Needs {
    /// Everything (`cargo xtask setup`, the target test).
    pub const ALL: Needs = Needs {
        thumb: true,
        qemu: true,
    };
    /// The thumb build only.
    pub const THUMB: Needs = Needs {
        thumb: true,
        qemu: false,
    };
}

/// The tools found, each by absolute path.
#[derive(Clone, Debug)]
pub struct Tools {
    /// The thumb toolchain, if asked for.
    pub thumb: Option<ThumbToolchain>,
    /// `qemu-system-arm`, if asked for.
    pub qemu: Option<PathBuf>,
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
}

/// Which toolchain builds for the thumb target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolchainKind {
    /// rustup's, with the target's std installed.
    Rustup,
    /// Debian's, building `core` from source.
    Debian,
}

/// A toolchain that can build for [`THUMB_TARGET`], with its linker.
#[derive(Clone, Debug)]
pub struct ThumbToolchain {
    /// Which one.
    pub kind: ToolchainKind,
    /// The `cargo` to run.
    pub cargo: PathBuf,
    /// The `rustc` it must use (Debian's), or `None` for the rustup proxy's choice.
    pub rustc: Option<PathBuf>,
    /// The linker, named to cargo explicitly.
    pub linker: PathBuf,
}

/// Finds what `needs` asks for, installing what is missing with apt-get, and checks
/// that every file is there afterwards.
///
/// # Errors
/// A tool that is missing and cannot be installed (the message names it, its package
/// and the command that installs it).
pub fn provision(needs: Needs) -> Result<Tools> {
    let mut missing: Vec<&Package> = Vec::new();
    let rustup = if needs.thumb {
        rustup_thumb_toolchain()?
    } else {
        None
    };
    if needs.thumb && rustup.is_none() {
        missing.extend(DEBIAN_TOOLCHAIN.iter().filter(|p| !installed(p)));
    }
    if needs.qemu && !installed(&QEMU) {
        missing.push(&QEMU);
    }
    if !missing.is_empty() {
        install(&missing)?;
    }
    let thumb = match (needs.thumb, rustup) {
        (false, _) => None,
        (true, Some(t)) => Some(t),
        (true, None) => {
            require(&DEBIAN_TOOLCHAIN)?;
            Some(ThumbToolchain {
                kind: ToolchainKind::Debian,
                cargo: DEBIAN_CARGO.into(),
                rustc: Some(DEBIAN_RUSTC.into()),
                linker: DEBIAN_LINKER.into(),
            })
        }
    };
    let qemu = if needs.qemu {
        require(std::slice::from_ref(&QEMU))?;
        Some(PathBuf::from(QEMU.provides))
    } else {
        None
    };
    Ok(Tools { thumb, qemu })
}

/// `cargo xtask setup`: provisions everything and says what is used.
///
/// # Errors
/// As [`provision`].
pub fn setup() -> Result<()> {
    let tools = provision(Needs::ALL)?;
    let thumb = tools.thumb()?;
    println!("thumb toolchain: {:?}", thumb.kind);
    println!("  cargo:  {}", thumb.cargo.display());
    if let Some(rustc) = &thumb.rustc {
        println!("  rustc:  {}", rustc.display());
    }
    println!("  linker: {}", thumb.linker.display());
    println!("qemu:     {}", tools.qemu()?.display());
    Ok(())
}

fn installed(package: &Package) -> bool {
    Path::new(package.provides).exists()
}

/// Fails, naming each package whose file is still missing.
fn require(packages: &[Package]) -> Result<()> {
    let missing: Vec<String> = packages
        .iter()
        .filter(|p| !installed(p))
        .map(|p| format!("{} (package {})", p.provides, p.name))
        .collect();
    if !missing.is_empty() {
        bail!(
            "xtask: still missing after installation: {}; run `cargo xtask setup` as root",
            missing.join(", ")
        );
    }
    Ok(())
}

/// rustup's toolchain, if rustup is here and has the thumb target: its `cargo`, and the
/// `rust-lld` in the toolchain's own sysroot.
fn rustup_thumb_toolchain() -> Result<Option<ThumbToolchain>> {
    let Some(targets) = output_of(
        Command::new("rustup")
            .args(["target", "list", "--installed"])
            .env_remove("RUSTUP_TOOLCHAIN"),
    ) else {
        return Ok(None);
    };
    if !targets.lines().any(|line| line.trim() == THUMB_TARGET) {
        return Ok(None);
    }
    let sysroot = output_of(
        Command::new("rustc")
            .args(["--print", "sysroot"])
            .env_remove("RUSTUP_TOOLCHAIN")
            .env_remove("RUSTC"),
    )
    .context("rustup lists the thumb target but `rustc --print sysroot` fails")?;
    let version = output_of(
        Command::new("rustc")
            .arg("-vV")
            .env_remove("RUSTUP_TOOLCHAIN")
            .env_remove("RUSTC"),
    )
    .context("`rustc -vV` fails")?;
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
        rustc: None,
        linker,
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
fn install(packages: &[&Package]) -> Result<()> {
    let names: Vec<&str> = packages.iter().map(|p| p.name).collect();
    let command = format!("apt-get update && apt-get install -y {}", names.join(" "));
    if !is_root() {
        bail!(
            "xtask: missing {} (needed: {}); install them as root: `{command}`",
            names.join(", "),
            packages
                .iter()
                .map(|p| p.provides)
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

fn is_root() -> bool {
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
    /// `cargo build` in `dir` with `args`, for the thumb target, with the linker named.
    ///
    /// # Errors
    /// When cargo cannot start or the build fails.
    pub fn cargo_build(&self, dir: &Path, args: &[&str]) -> Result<()> {
        self.cargo_build_with(dir, args, Panics::Handler)
    }

    /// As [`cargo_build`](Self::cargo_build); with [`Panics::ImmediateAbort`] and the
    /// build-std toolchain, panics abort at once (`-Cpanic=immediate-abort`): no panic
    /// messages or locations in the image. The stable rustup toolchain cannot rebuild
    /// `core` that way and keeps its panic handler.
    ///
    /// # Errors
    /// As [`cargo_build`](Self::cargo_build).
    pub fn cargo_build_with(&self, dir: &Path, args: &[&str], panics: Panics) -> Result<()> {
        let mut command = Command::new(&self.cargo);
        command.current_dir(dir).arg("build").args(args);
        remove_leaked_variables(&mut command);
        command.env(LINKER_VARIABLE, &self.linker);
        // Panic locations embed source paths; cut the machine-specific prefixes, so the
        // image neither depends on where it was built nor spends ~3 KiB of flash on
        // `/root/.cargo/registry/src/index.crates.io-…/` 47 times.
        // Encoded (0x1f-separated) so that a path with spaces stays one argument.
        let mut flags = remap_flags(dir);
        if panics == Panics::ImmediateAbort && self.rustc.is_some() {
            flags.push_str("\u{1f}-Zunstable-options\u{1f}-Cpanic=immediate-abort");
        }
        command.env("CARGO_ENCODED_RUSTFLAGS", flags);
        if let Some(rustc) = &self.rustc {
            command
                .env("RUSTC", rustc)
                .env("RUSTC_BOOTSTRAP", "1")
                .arg("-Zbuild-std=core");
        }
        let shown_args: Vec<_> = command
            .get_args()
            .map(|arg| arg.to_string_lossy())
            .collect();
        eprintln!(
            "xtask: in {}: {} {} ({:?} toolchain, linker {})",
            dir.display(),
            command.get_program().to_string_lossy(),
            shown_args.join(" "),
            self.kind,
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
