//! What the firmware's commands measure, saved where `cargo xtask figures` reads it:
//! `docs/measured/COMMAND-TOOLCHAIN.txt`, one file per command and thumb toolchain
//! (`firmware` for the release image's flash and static RAM, which every command that
//! builds it writes; `target-test` for the fit's instructions and stack under QEMU;
//! `dfu` for the image's size). Each file says which command and toolchain measured it;
//! the docs' firmware figures are written from these files only, so a figure there is
//! always one that command measured. A file is written whole each time: its keys are
//! the command's. Host measurements (`fleet-bench`'s web page times) are
//! `docs/measured/NAME.txt`, their `toolchain` line naming the compiler and the CPUs.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context, Result};

use crate::toolchain::ToolchainKind;

/// Where the files live, from the repository's root.
pub const DIR: &str = "docs/measured";

/// The toolchain's name in file names and commands.
pub fn kind_name(kind: ToolchainKind) -> &'static str {
    match kind {
        ToolchainKind::Rustup => "rustup",
        ToolchainKind::Debian => "debian",
    }
}

/// The file of `command` measured with `kind`.
pub fn path(root: &Path, command: &str, kind: ToolchainKind) -> PathBuf {
    root.join(DIR)
        .join(format!("{command}-{}.txt", kind_name(kind)))
}

/// Saves what `command` measured with the toolchain `kind` (`toolchain`: its
/// description, rustc's version among it).
///
/// # Errors
/// The file cannot be written.
pub fn save(
    root: &Path,
    command: &str,
    kind: ToolchainKind,
    toolchain: &str,
    values: &[(&str, String)],
) -> Result<()> {
    let file = path(root, command, kind);
    if let Some(dir) = file.parent() {
        fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    let mut text = format!(
        "# measured by `cargo xtask --toolchain {} {command}`; read by `cargo xtask figures`\n\
         toolchain {toolchain}\n",
        kind_name(kind)
    );
    for (key, value) in values {
        text.push_str(&format!("{key} {value}\n"));
    }
    fs::write(&file, text).with_context(|| format!("writing {}", file.display()))?;
    println!("saved the measurement in {}", file.display());
    Ok(())
}

/// The file of a host measurement `name` (not of a thumb toolchain's build).
pub fn host_path(root: &Path, name: &str) -> PathBuf {
    root.join(DIR).join(format!("{name}.txt"))
}

/// Saves what `command` measured on this host (`machine`: the compiler and the CPUs it
/// ran on) as `docs/measured/NAME.txt`.
///
/// # Errors
/// The file cannot be written.
pub fn save_host(
    root: &Path,
    name: &str,
    command: &str,
    machine: &str,
    values: &[(&str, String)],
) -> Result<()> {
    let file = host_path(root, name);
    if let Some(dir) = file.parent() {
        fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    let mut text =
        format!("# measured by `{command}`; read by `cargo xtask figures`\ntoolchain {machine}\n");
    for (key, value) in values {
        text.push_str(&format!("{key} {value}\n"));
    }
    fs::write(&file, text).with_context(|| format!("writing {}", file.display()))?;
    println!("saved the measurement in {}", file.display());
    Ok(())
}

/// The measurement of `command` with `kind` as the checked-out commit holds it
/// (`git show HEAD:docs/measured/…`), whatever a build since wrote over the file.
///
/// # Errors
/// Not a git checkout, or the file not committed.
pub fn committed(root: &Path, command: &str, kind: ToolchainKind) -> Result<Measured> {
    let file = path(root, command, kind);
    let relative = format!("{DIR}/{command}-{}.txt", kind_name(kind));
    let output = std::process::Command::new("git")
        .arg("-C")
        .arg(root)
        .args(["show", &format!("HEAD:{relative}")])
        .output()
        .context("running git show")?;
    if !output.status.success() {
        anyhow::bail!("{relative} is not committed at HEAD");
    }
    Measured::parse(&String::from_utf8_lossy(&output.stdout), file)
}

/// A saved measurement.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Measured {
    /// The file.
    pub file: PathBuf,
    /// The toolchain that built what was measured.
    pub toolchain: String,
    values: BTreeMap<String, String>,
}

impl Measured {
    /// Reads `command`'s file for `kind`.
    ///
    /// # Errors
    /// A missing or malformed file.
    pub fn read(root: &Path, command: &str, kind: ToolchainKind) -> Result<Measured> {
        let file = path(root, command, kind);
        let text = fs::read_to_string(&file).with_context(|| {
            format!(
                "reading {} (run `cargo xtask --toolchain {} {command}`)",
                file.display(),
                kind_name(kind)
            )
        })?;
        Self::parse(&text, file)
    }

    /// Reads the host measurement `name` (`save_host`'s), naming `command` to make it
    /// when it is missing.
    ///
    /// # Errors
    /// A missing or malformed file.
    pub fn read_host(root: &Path, name: &str, command: &str) -> Result<Measured> {
        let file = host_path(root, name);
        let text = fs::read_to_string(&file)
            .with_context(|| format!("reading {} (run `{command}`)", file.display()))?;
        Self::parse(&text, file)
    }

    fn parse(text: &str, file: PathBuf) -> Result<Measured> {
        let mut toolchain = None;
        let mut values = BTreeMap::new();
        for line in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.is_empty())
        {
            let (key, value) = line
                .split_once(' ')
                .ok_or_else(|| anyhow!("{}: '{line}' is not 'key value'", file.display()))?;
            if key == "toolchain" {
                toolchain = Some(value.to_owned());
            } else {
                values.insert(key.to_owned(), value.to_owned());
            }
        }
        Ok(Measured {
            toolchain: toolchain.ok_or_else(|| anyhow!("{}: no toolchain line", file.display()))?,
            values,
            file,
        })
    }

    /// The value of `key`.
    ///
    /// # Errors
    /// Not in the file.
    pub fn get(&self, key: &str) -> Result<&str> {
        self.values
            .get(key)
            .map(String::as_str)
            .ok_or_else(|| anyhow!("{}: no '{key}'", self.file.display()))
    }

    /// Every `key value` whose key starts with `prefix`, the prefix taken off, in key
    /// order.
    pub fn with_prefix<'a>(&'a self, prefix: &'a str) -> impl Iterator<Item = (&'a str, &'a str)> {
        self.values
            .iter()
            .filter_map(move |(k, v)| Some((k.strip_prefix(prefix)?, v.as_str())))
    }

    /// The value of `key` as a count.
    ///
    /// # Errors
    /// Not in the file, or not a count.
    pub fn count(&self, key: &str) -> Result<u64> {
        let v = self.get(key)?;
        v.parse()
            .with_context(|| format!("{}: '{key}' is not a count: {v}", self.file.display()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_measurement_reads_back() {
        let dir = std::env::temp_dir().join(format!("xtask-measured-{}", std::process::id()));
        save(
            &dir,
            "firmware",
            ToolchainKind::Debian,
            "Debian toolchain (rustc 1.96.0)",
            &[("flash_bytes", "198860".into())],
        )
        .unwrap();
        let m = Measured::read(&dir, "firmware", ToolchainKind::Debian).unwrap();
        assert_eq!(m.toolchain, "Debian toolchain (rustc 1.96.0)");
        assert_eq!(m.count("flash_bytes").unwrap(), 198_860);
        assert!(m.count("static_ram_bytes").is_err());
        assert!(Measured::read(&dir, "firmware", ToolchainKind::Rustup).is_err());
        let _ = fs::remove_dir_all(&dir);
    }
}
