//! Finding (or installing) a toolchain that builds for the Cortex-M4F, and running
//! cargo with it in a clean environment.

use std::path::Path;
use std::process::Command;

use anyhow::{bail, Context, Result};

/// The pendant's target: Cortex-M4F with hardware floating point.
pub const THUMB_TARGET: &str = "thumbv7em-none-eabihf";

/// Debian's toolchain: rustc with the standard library sources, used with
/// `RUSTC_BOOTSTRAP=1 -Zbuild-std=core` because Debian ships no thumb std.
const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";
const DEBIAN_RUST_SRC: &str = "/usr/lib/rustlib/src/rust/library/core";
const DEBIAN_PACKAGES: [&str; 4] = ["rustc-web", "cargo-web", "rust-web-src", "lld-22"];

/// Variables that cargo, rustc's wrappers and rustup set for the process running
/// xtask. Left in place they would make the child build use the host toolchain, the
/// host's target directory, its flags or its manifest.
const LEAKED_VARIABLES: [&str; 14] = [
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
];

/// A toolchain that can build for [`THUMB_TARGET`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThumbToolchain {
    /// rustup's, with the target's std installed.
    Rustup,
    /// Debian's, building `core` from source.
    Debian,
}

impl ThumbToolchain {
    /// rustup's if it has the target, else Debian's, installing it if needed.
    ///
    /// # Errors
    /// When neither is present and apt-get fails.
    pub fn find_or_install() -> Result<ThumbToolchain> {
        if rustup_has_thumb_target() {
            return Ok(ThumbToolchain::Rustup);
        }
        if !debian_toolchain_present() {
            eprintln!(
                "xtask: no toolchain for {THUMB_TARGET}; installing Debian's ({})",
                DEBIAN_PACKAGES.join(" ")
            );
            install_debian_toolchain()?;
        }
        Ok(ThumbToolchain::Debian)
    }

    /// `cargo build` in `dir` with `args`, for the thumb target.
    ///
    /// # Errors
    /// When cargo cannot start or the build fails.
    pub fn cargo_build(self, dir: &Path, args: &[&str]) -> Result<()> {
        let mut command = match self {
            ThumbToolchain::Rustup => Command::new("cargo"),
            ThumbToolchain::Debian => Command::new(DEBIAN_CARGO),
        };
        command.current_dir(dir).arg("build").args(args);
        for variable in LEAKED_VARIABLES {
            command.env_remove(variable);
        }
        // Cargo also sets CARGO_PKG_*, CARGO_BIN_* and CARGO_CRATE_NAME for xtask's own
        // run: the child cargo sets its own, but none should be inherited.
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
        // Panic locations embed source paths; cut the machine-specific prefixes, so the
        // image neither depends on where it was built nor spends ~3 KiB of flash on
        // `/root/.cargo/registry/src/index.crates.io-…/` 47 times.
        // Encoded (0x1f-separated) so that a path with spaces stays one argument.
        command.env("CARGO_ENCODED_RUSTFLAGS", remap_flags(dir));
        if self == ThumbToolchain::Debian {
            command
                .env("RUSTC", DEBIAN_RUSTC)
                .env("RUSTC_BOOTSTRAP", "1")
                .arg("-Zbuild-std=core");
        }
        let shown_args: Vec<_> = command
            .get_args()
            .map(|arg| arg.to_string_lossy())
            .collect();
        eprintln!(
            "xtask: in {}: {} {} ({self:?} toolchain)",
            dir.display(),
            command.get_program().to_string_lossy(),
            shown_args.join(" ")
        );
        let status = command
            .status()
            .with_context(|| format!("cannot run {:?}", command.get_program()))?;
        if !status.success() {
            bail!("build failed ({status}) in {}", dir.display());
        }
        Ok(())
    }
}

/// rustup is here and lists the thumb target as installed.
fn rustup_has_thumb_target() -> bool {
    let Ok(output) = Command::new("rustup")
        .args(["target", "list", "--installed"])
        .env_remove("RUSTUP_TOOLCHAIN")
        .output()
    else {
        return false;
    };
    output.status.success()
        && String::from_utf8_lossy(&output.stdout)
            .lines()
            .any(|line| line.trim() == THUMB_TARGET)
}

/// Debian's rustc, cargo and the core sources are installed.
fn debian_toolchain_present() -> bool {
    [DEBIAN_RUSTC, DEBIAN_CARGO, DEBIAN_RUST_SRC]
        .iter()
        .all(|path| Path::new(path).exists())
}

/// `apt-get update`, then installs [`DEBIAN_PACKAGES`].
fn install_debian_toolchain() -> Result<()> {
    run(Command::new("apt-get").arg("update"))?;
    run(Command::new("apt-get")
        .args(["install", "-y", "--no-install-recommends"])
        .args(DEBIAN_PACKAGES)
        .env("DEBIAN_FRONTEND", "noninteractive"))?;
    if !debian_toolchain_present() {
        bail!("apt-get installed {DEBIAN_PACKAGES:?}, but {DEBIAN_RUSTC}, {DEBIAN_CARGO} or {DEBIAN_RUST_SRC} is still missing");
    }
    Ok(())
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

/// `--remap-path-prefix` flags for the registry sources and the repository, in
/// `CARGO_ENCODED_RUSTFLAGS` form.
fn remap_flags(dir: &Path) -> String {
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(std::path::PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")));
    let mut flags = Vec::new();
    if let Some(home) = cargo_home {
        flags.push(format!(
            "--remap-path-prefix={}=/deps",
            home.join("registry").join("src").display()
        ));
    }
    if let Some(repo) = dir.parent() {
        flags.push(format!("--remap-path-prefix={}=/zerocal", repo.display()));
    }
    flags.join("\u{1f}")
}
