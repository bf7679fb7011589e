//! Where the figures come from, each run once per `cargo xtask figures` and kept for
//! every block that quotes it: the `zerocal` binary (built once, release), a test's
//! printed output (`cargo test` of one test by its exact name, single-threaded, its
//! libtest framing taken off), and the firmware's saved measurements
//! ([`crate::measured`]). Every run is seeded by its own arguments, so the same source
//! gives the same text on every run and `--check` is deterministic.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Context, Result};

use crate::measured::Measured;
use crate::toolchain::ToolchainKind;

/// The figures' sources, with what has been run so far.
pub struct Sources {
    root: PathBuf,
    zerocal: Option<PathBuf>,
    runs: HashMap<String, String>,
}

/// A `zerocal` run's result: its exit status and both outputs.
#[derive(Clone, Debug)]
pub struct Run {
    /// The exit status (`None`: killed).
    pub status: Option<i32>,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

/// The cargo that runs xtask (its `CARGO`), else the one on PATH.
fn cargo() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned())
}

/// The target directory cargo builds into.
fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from)
}

/// The test's own output in `cargo test -q … --nocapture --test-threads 1` of one
/// test: after `running 1 test`, before `test result:`, less the `.` libtest prints
/// when it passes.
pub fn test_output(stdout: &str, name: &str) -> Result<String> {
    let Some((_, after)) = stdout.split_once("running 1 test\n") else {
        bail!("the test run did not run exactly one test named '{name}':\n{stdout}");
    };
    let Some((body, result)) = after.rsplit_once("\ntest result: ") else {
        bail!("no 'test result:' after the test '{name}':\n{stdout}");
    };
    if !result.starts_with("ok.") {
        bail!("the test '{name}' failed:\n{stdout}");
    }
    let body = body.trim_end();
    let body = body.strip_suffix('.').unwrap_or(body).trim_end();
    Ok(format!("{body}\n"))
}

impl Sources {
    /// No runs yet, in the repository at `root`.
    pub fn new(root: &Path) -> Sources {
        Sources {
            root: root.to_path_buf(),
            zerocal: None,
            runs: HashMap::new(),
        }
    }

    /// The `zerocal` binary, built in release the first time.
    fn zerocal_binary(&mut self) -> Result<PathBuf> {
        if let Some(b) = &self.zerocal {
            return Ok(b.clone());
        }
        eprintln!("figures: building zerocal (release)");
        let status = Command::new(cargo())
            .current_dir(&self.root)
            .args([
                "build",
                "-q",
                "--release",
                "-p",
                "zerocal-cli",
                "--bin",
                "zerocal",
            ])
            .status()
            .context("running cargo build -p zerocal-cli")?;
        if !status.success() {
            bail!("cargo build --release -p zerocal-cli failed");
        }
        let binary = target_dir(&self.root).join("release").join("zerocal");
        self.zerocal = Some(binary.clone());
        Ok(binary)
    }

    /// `zerocal ARGS`, run in the repository's root, whatever its exit status.
    ///
    /// # Errors
    /// It could not be built or started.
    pub fn zerocal_run(&mut self, args: &[&str]) -> Result<Run> {
        let key = format!("zerocal {}", args.join(" "));
        let binary = self.zerocal_binary()?;
        let started = Instant::now();
        let out = Command::new(&binary)
            .current_dir(&self.root)
            .args(args)
            .output()
            .with_context(|| format!("running {key}"))?;
        eprintln!("figures: {key} ({:.1} s)", started.elapsed().as_secs_f64());
        Ok(Run {
            status: out.status.code(),
            stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
            stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        })
    }

    /// The standard output of `zerocal ARGS`, which must succeed; run once.
    ///
    /// # Errors
    /// It could not run, or it failed.
    pub fn zerocal(&mut self, args: &[&str]) -> Result<String> {
        let key = format!("zerocal {}", args.join(" "));
        if let Some(out) = self.runs.get(&key) {
            return Ok(out.clone());
        }
        let run = self.zerocal_run(args)?;
        if run.status != Some(0) {
            bail!("{key} failed ({:?}): {}", run.status, run.stderr);
        }
        self.runs.insert(key, run.stdout.clone());
        Ok(run.stdout)
    }

    /// What the test `name` of `package`'s test target `test` prints; run once.
    ///
    /// # Errors
    /// It could not run, did not run exactly that test, or failed.
    pub fn test(&mut self, package: &str, test: &str, name: &str) -> Result<String> {
        let key = format!("test {package} {test} {name}");
        if let Some(out) = self.runs.get(&key) {
            return Ok(out.clone());
        }
        let started = Instant::now();
        let out = Command::new(cargo())
            .current_dir(&self.root)
            .args(["test", "-q", "-p", package, "--test", test, "--"])
            .args(["--exact", name, "--nocapture", "--test-threads", "1"])
            .output()
            .with_context(|| format!("running cargo test -p {package} --test {test}"))?;
        eprintln!(
            "figures: cargo test -p {package} --test {test} -- --exact {name} ({:.1} s)",
            started.elapsed().as_secs_f64()
        );
        let stdout = String::from_utf8_lossy(&out.stdout);
        if !out.status.success() {
            bail!(
                "cargo test -p {package} --test {test} -- --exact {name} failed:\n{stdout}\n{}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        let text = test_output(&stdout, name)?;
        self.runs.insert(key, text.clone());
        Ok(text)
    }

    /// Makes `target/figures`, where runs write their files (named relative to the
    /// repository's root, as `zerocal` runs there).
    ///
    /// # Errors
    /// It cannot be made.
    pub fn scratch(&self) -> Result<()> {
        let dir = self.root.join("target").join("figures");
        std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))
    }

    /// The saved measurement of `command` with the toolchain `kind`.
    ///
    /// # Errors
    /// None saved, or a malformed file.
    pub fn measured(&self, command: &str, kind: ToolchainKind) -> Result<Measured> {
        Measured::read(&self.root, command, kind)
    }

    /// The saved host measurement `name`, made by `command`.
    ///
    /// # Errors
    /// None saved, or a malformed file.
    pub fn measured_host(&self, name: &str, command: &str) -> Result<Measured> {
        Measured::read_host(&self.root, name, command)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_test_output_is_what_the_test_printed() {
        let stdout = "\nrunning 1 test\nrobot  within\nkr6    100.0\n.\ntest result: ok. 1 passed; 0 failed; finished in 5.79s\n\n";
        assert_eq!(
            test_output(stdout, "t").unwrap(),
            "robot  within\nkr6    100.0\n"
        );
        assert!(test_output("\nrunning 0 tests\n\ntest result: ok.", "t").is_err());
        let failed = "\nrunning 1 test\nx\nF\ntest result: FAILED. 0 passed; 1 failed";
        assert!(test_output(failed, "t").is_err());
    }
}
