//! `cargo xtask dist`: the release bundle a technician or a user downloads.
//!
//! `target/dist/zerocal-VERSION/` holds
//! - `firmware/`: the release firmware ELF (for a probe: `probe-rs download`), its DfuSe
//!   image (for `dfu-util`) and each image element alone (to compare a read-back with),
//!   as `cargo xtask dfu` wrote and verified them;
//! - `bin/zerocal`: the desktop program, a release build for this machine;
//! - `README.md` and `docs/`;
//! - `BUILD.txt`: which thumb toolchain built the firmware and its sizes;
//! - `SHA256SUMS`: every other file's SHA-256 (`sha256sum -c SHA256SUMS` checks them);
//!
//! and `target/dist/zerocal-VERSION.tar.gz` packs the directory.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

use crate::toolchain::ToolchainChoice;

/// The workspace version (xtask shares it).
const VERSION: &str = env!("CARGO_PKG_VERSION");

/// coreutils' `sha256sum` and GNU tar: both in every Debian installation (essential
/// packages), so the bundle needs no hashing or archive crate.
const SHA256SUM: &str = "/usr/bin/sha256sum";
const TAR: &str = "/usr/bin/tar";

/// Builds everything and writes the bundle and its archive.
///
/// # Errors
/// A failed build or DFU check, a file that cannot be copied, or `sha256sum`/`tar`
/// failing.
pub fn run(root: &Path, choice: ToolchainChoice) -> Result<()> {
    let image = crate::dfu::run(root, choice)?;
    let zerocal = build_zerocal(root)?;

    let dist = root.join("target").join("dist");
    let name = format!("zerocal-{VERSION}");
    let bundle = dist.join(&name);
    if bundle.exists() {
        fs::remove_dir_all(&bundle).with_context(|| format!("removing {}", bundle.display()))?;
    }
    let firmware = bundle.join("firmware");
    fs::create_dir_all(&firmware).with_context(|| format!("creating {}", firmware.display()))?;
    copy(&image.elf, &firmware.join("zerocal-firmware.elf"))?;
    copy(&image.dfu, &firmware.join("zerocal.dfu"))?;
    for element in &image.element_files {
        let file_name = element
            .file_name()
            .with_context(|| format!("{} has no file name", element.display()))?;
        copy(element, &firmware.join(file_name))?;
    }
    let bin = bundle.join("bin");
    fs::create_dir_all(&bin).with_context(|| format!("creating {}", bin.display()))?;
    copy(&zerocal, &bin.join("zerocal"))?;
    copy(&root.join("README.md"), &bundle.join("README.md"))?;
    copy_dir(&root.join("docs"), &bundle.join("docs"))?;

    let usage = crate::size::MemoryUsage::of_elf(&image.elf)?;
    let capacity = crate::size::MemoryCapacity::from_memory_x(&root.join("memory.x"))?;
    let build = format!(
        "zerocal {VERSION}\nfirmware toolchain: {}\n{}\n",
        image.toolchain.describe(),
        usage.report(&capacity)
    );
    fs::write(bundle.join("BUILD.txt"), build).context("writing BUILD.txt")?;

    let mut files = Vec::new();
    list_files(&bundle, &bundle, &mut files)?;
    files.sort();
    let sums = output(Command::new(SHA256SUM).current_dir(&bundle).args(&files))?;
    fs::write(bundle.join("SHA256SUMS"), &sums).context("writing SHA256SUMS")?;

    let archive = dist.join(format!("{name}.tar.gz"));
    output(
        Command::new(TAR)
            .arg("-czf")
            .arg(&archive)
            .arg("-C")
            .arg(&dist)
            .arg(&name),
    )?;
    println!(
        "{}: {} files and SHA256SUMS; archive {}",
        bundle.display(),
        files.len(),
        archive.display()
    );
    Ok(())
}

/// `cargo build --release -p zerocal-cli` with the cargo that runs xtask; the binary.
fn build_zerocal(root: &Path) -> Result<PathBuf> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.current_dir(root).args([
        "build",
        "--release",
        "--package",
        "zerocal-cli",
        "--bin",
        "zerocal",
    ]);
    eprintln!("xtask: {command:?}");
    let status = command.status().context("cannot run cargo")?;
    if !status.success() {
        bail!("the release build of zerocal failed ({status})");
    }
    let binary = root.join("target").join("release").join("zerocal");
    if !binary.is_file() {
        bail!("cargo built no {}", binary.display());
    }
    Ok(binary)
}

fn copy(from: &Path, to: &Path) -> Result<()> {
    fs::copy(from, to)
        .map(|_| ())
        .with_context(|| format!("copying {} to {}", from.display(), to.display()))
}

fn copy_dir(from: &Path, to: &Path) -> Result<()> {
    fs::create_dir_all(to).with_context(|| format!("creating {}", to.display()))?;
    for entry in fs::read_dir(from).with_context(|| format!("reading {}", from.display()))? {
        let entry = entry.with_context(|| format!("reading {}", from.display()))?;
        let path = entry.path();
        let target = to.join(entry.file_name());
        if path.is_dir() {
            copy_dir(&path, &target)?;
        } else {
            copy(&path, &target)?;
        }
    }
    Ok(())
}

/// The files under `dir`, as paths relative to `base`.
fn list_files(base: &Path, dir: &Path, files: &mut Vec<PathBuf>) -> Result<()> {
    for entry in fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))? {
        let path = entry
            .with_context(|| format!("reading {}", dir.display()))?
            .path();
        if path.is_dir() {
            list_files(base, &path, files)?;
        } else {
            files.push(path.strip_prefix(base)?.to_path_buf());
        }
    }
    Ok(())
}

/// Runs a command that must succeed; its standard output.
fn output(command: &mut Command) -> Result<Vec<u8>> {
    let out = command
        .output()
        .with_context(|| format!("cannot run {command:?}"))?;
    if !out.status.success() {
        bail!(
            "{command:?} failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
    }
    Ok(out.stdout)
}
