//! `cargo xtask`: the project's build tasks, in Rust rather than shell scripts.
//!
//! The firmware and the no_std check build for `thumbv7em-none-eabihf` with whichever
//! toolchain this machine has (see [`toolchain`]): rustup's with the target installed,
//! or Debian's rustc with `-Zbuild-std=core`, installed with apt-get when missing.

mod size;
mod toolchain;

use std::path::{Path, PathBuf};

use anyhow::Result;
use clap::{Parser, Subcommand};

/// zerocal's build tasks.
#[derive(Parser)]
#[command(name = "cargo xtask", about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// One task per variant. Each builds what it needs itself.
#[derive(Subcommand)]
enum Command {
    /// Build the release firmware (firmware/, thumbv7em-none-eabihf) and print its
    /// flash and static RAM use.
    Firmware,
    /// Build zerocal-core alone for thumbv7em-none-eabihf with its default features:
    /// proves it is no_std (a host build cannot, std being always there).
    CoreThumb,
}

fn main() -> Result<()> {
    match Cli::parse().command {
        Command::Firmware => firmware(),
        Command::CoreThumb => core_thumb(),
    }
}

/// The repository root: xtask lives one level below it.
fn repo_root() -> PathBuf {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest_dir
        .parent()
        .map_or_else(|| manifest_dir.to_path_buf(), Path::to_path_buf)
}

fn firmware() -> Result<()> {
    let root = repo_root();
    let firmware_dir = root.join("firmware");
    let toolchain = toolchain::ThumbToolchain::find_or_install()?;
    // The firmware's own .cargo/config.toml selects the target; its own [workspace]
    // keeps host features out.
    toolchain.cargo_build(&firmware_dir, &["--release"])?;
    let elf = firmware_dir
        .join("target")
        .join(toolchain::THUMB_TARGET)
        .join("release")
        .join("zerocal-firmware");
    let capacity = size::MemoryCapacity::from_memory_x(&root.join("memory.x"))?;
    let usage = size::MemoryUsage::of_elf(&elf)?;
    println!("{}", usage.report(&capacity));
    Ok(())
}

fn core_thumb() -> Result<()> {
    let root = repo_root();
    let toolchain = toolchain::ThumbToolchain::find_or_install()?;
    // Only zerocal-core is selected, so no other member's features (std) unify into
    // it; its own target dir keeps the host build's cache intact.
    let manifest = root.join("core").join("Cargo.toml");
    let target_dir = root.join("target").join("thumb");
    toolchain.cargo_build(
        &root,
        &[
            "--manifest-path",
            path_str(&manifest)?,
            "--target",
            toolchain::THUMB_TARGET,
            "--target-dir",
            path_str(&target_dir)?,
        ],
    )?;
    println!(
        "zerocal-core builds for {} (no_std)",
        toolchain::THUMB_TARGET
    );
    Ok(())
}

fn path_str(path: &Path) -> Result<&str> {
    path.to_str()
        .ok_or_else(|| anyhow::anyhow!("path is not UTF-8: {}", path.display()))
}
