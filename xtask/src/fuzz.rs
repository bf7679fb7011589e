//! `cargo xtask fuzz`: the coverage-guided fuzz targets of `fuzz/` (cargo-fuzz,
//! libFuzzer), one per parser of outside bytes.
//!
//! - `--smoke`: builds every target and runs each for [`SMOKE_SECONDS`] from the
//!   committed corpus, seeds and regressions; fails on any crash, hang (an input that
//!   takes over [`TIMEOUT_SECONDS`]) or allocation over [`MALLOC_LIMIT_MB`]. New inputs
//!   go to `target/fuzz/`, so the committed corpus stays as it is.
//! - `TARGET… --time SECS` (or `--runs N`): a campaign; new inputs go into
//!   `fuzz/corpus/TARGET`. `--minimize` then merges that corpus down
//!   (`-set_cover_merge=1 -use_counters=0`: every edge kept) before it is committed.
//!
//! libFuzzer needs nightly flags (`-Zsanitizer=address`, coverage instrumentation):
//! the build runs on the stable toolchain with `RUSTC_BOOTSTRAP=1`. cargo-fuzz is
//! installed at [`CARGO_FUZZ_VERSION`] when missing ([`crate::toolchain`]).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Context, Result};

use crate::toolchain;

/// Every target, in `fuzz/fuzz_targets/`.
pub const TARGETS: [&str; 13] = [
    "decimal",
    "link_lines",
    "link_serve",
    "log_reader",
    "export_lines",
    "record",
    "profile",
    "urdf",
    "limits",
    "scl3300",
    "store_restore",
    "store_model",
    "kept_results",
];

/// Seconds each target runs in `--smoke`: thirteen targets in about four minutes after
/// the build, on one core.
pub const SMOKE_SECONDS: u32 = 20;

/// An input that runs longer than this is a hang.
pub const TIMEOUT_SECONDS: u32 = 10;

/// A single allocation larger than this is a failure (an input-sized buffer gone wild).
pub const MALLOC_LIMIT_MB: u32 = 256;

/// Resident memory limit of a fuzzing process.
const RSS_LIMIT_MB: u32 = 2048;

/// The pinned cargo-fuzz.
pub const CARGO_FUZZ_VERSION: &str = "0.13.2";

/// The libFuzzer target triple cargo-fuzz builds for.
const HOST_TRIPLE: &str = "x86_64-unknown-linux-gnu";

/// What to run.
pub struct Options {
    /// Every target for [`SMOKE_SECONDS`].
    pub smoke: bool,
    /// The targets (all when empty).
    pub targets: Vec<String>,
    /// Seconds per target.
    pub time: Option<u32>,
    /// Executions per target.
    pub runs: Option<u64>,
    /// Merge each target's corpus down instead of fuzzing.
    pub minimize: bool,
}

/// One target's run.
struct Outcome {
    target: String,
    executions: u64,
    coverage: String,
    seconds: f64,
    failure: Option<String>,
}

/// Runs `cargo xtask fuzz`.
///
/// # Errors
/// No cargo-fuzz and no way to install it, a failed build, or a target that crashed,
/// hung or allocated too much (the message names the reproducer).
pub fn run(root: &Path, options: &Options) -> Result<()> {
    let targets: Vec<String> = if options.targets.is_empty() {
        TARGETS.iter().map(|t| (*t).to_owned()).collect()
    } else {
        options.targets.clone()
    };
    for t in &targets {
        if !TARGETS.contains(&t.as_str()) {
            bail!(
                "unknown fuzz target '{t}'; the targets: {}",
                TARGETS.join(", ")
            );
        }
    }
    let cargo_fuzz = toolchain::cargo_fuzz(CARGO_FUZZ_VERSION)?;
    let fuzz_dir = root.join("fuzz");
    build(&cargo_fuzz, &fuzz_dir)?;
    let work = root.join("target").join("fuzz");
    if options.minimize {
        for t in &targets {
            minimize(&fuzz_dir, &work, t)?;
        }
        return Ok(());
    }
    let (seconds, runs) = match (options.smoke, options.time, options.runs) {
        (true, _, _) => (Some(SMOKE_SECONDS), None),
        (false, None, None) => bail!("say --smoke, --time SECS or --runs N"),
        (false, time, runs) => (time, runs),
    };
    let mut outcomes = Vec::new();
    for t in &targets {
        let outcome = fuzz(&fuzz_dir, &work, t, options.smoke, seconds, runs)?;
        outcomes.push(outcome);
    }
    println!(
        "\n{:<14} {:>12} {:>8}  coverage",
        "target", "executions", "seconds"
    );
    for o in &outcomes {
        println!(
            "{:<14} {:>12} {:>8.0}  {}",
            o.target, o.executions, o.seconds, o.coverage
        );
    }
    let failures: Vec<&String> = outcomes.iter().filter_map(|o| o.failure.as_ref()).collect();
    if !failures.is_empty() {
        for f in &failures {
            eprintln!("{f}");
        }
        bail!("{} fuzz target(s) failed", failures.len());
    }
    println!("fuzz: every target ran without a crash, hang or runaway allocation");
    Ok(())
}

/// `cargo fuzz build` of every target (release, debug assertions, AddressSanitizer).
fn build(cargo_fuzz: &Path, fuzz_dir: &Path) -> Result<()> {
    let mut command = Command::new(cargo_fuzz);
    command
        .current_dir(fuzz_dir)
        .args(["fuzz", "build", "--debug-assertions"])
        .env("RUSTC_BOOTSTRAP", "1");
    toolchain::remove_leaked_variables(&mut command);
    eprintln!(
        "xtask: in {}: cargo fuzz build --debug-assertions (RUSTC_BOOTSTRAP=1)",
        fuzz_dir.display()
    );
    let status = command
        .status()
        .with_context(|| format!("cannot run {}", cargo_fuzz.display()))?;
    if !status.success() {
        bail!("the fuzz targets do not build ({status})");
    }
    Ok(())
}

fn binary(fuzz_dir: &Path, target: &str) -> PathBuf {
    fuzz_dir
        .join("target")
        .join(HOST_TRIPLE)
        .join("release")
        .join(target)
}

/// The input directories of a target: its corpus first (where a campaign adds), then
/// its regressions and the seeds it shares with others.
fn inputs(fuzz_dir: &Path, target: &str) -> Vec<PathBuf> {
    let mut dirs = vec![
        fuzz_dir.join("corpus").join(target),
        fuzz_dir.join("regressions").join(target),
    ];
    let seeds = match target {
        "link_lines" | "link_serve" => Some("link"),
        "log_reader" => Some("log"),
        "profile" => Some("profile"),
        "urdf" => Some("urdf"),
        "limits" => Some("limits"),
        _ => None,
    };
    if let Some(s) = seeds {
        dirs.push(fuzz_dir.join("seeds").join(s));
    }
    dirs.into_iter().filter(|d| d.is_dir()).collect()
}

fn fuzz(
    fuzz_dir: &Path,
    work: &Path,
    target: &str,
    smoke: bool,
    seconds: Option<u32>,
    runs: Option<u64>,
) -> Result<Outcome> {
    let artifacts = work.join("artifacts").join(target);
    fs::create_dir_all(&artifacts)?;
    let mut command = Command::new(binary(fuzz_dir, target));
    // The smoke run adds to a scratch corpus; a campaign to the committed one.
    let first = if smoke {
        let scratch = work.join("smoke").join(target);
        if scratch.exists() {
            fs::remove_dir_all(&scratch)?;
        }
        fs::create_dir_all(&scratch)?;
        scratch
    } else {
        let corpus = fuzz_dir.join("corpus").join(target);
        fs::create_dir_all(&corpus)?;
        corpus
    };
    command.arg(&first);
    for dir in inputs(fuzz_dir, target) {
        if dir != first {
            command.arg(dir);
        }
    }
    command.args([
        format!("-artifact_prefix={}/", artifacts.display()),
        format!("-timeout={TIMEOUT_SECONDS}"),
        format!("-malloc_limit_mb={MALLOC_LIMIT_MB}"),
        format!("-rss_limit_mb={RSS_LIMIT_MB}"),
        // One process, one thread (libFuzzer's default): no -jobs, which would fork a
        // worker logging to ./fuzz-N.log.
        "-print_final_stats=1".to_owned(),
    ]);
    if let Some(s) = seconds {
        command.arg(format!("-max_total_time={s}"));
    }
    if let Some(n) = runs {
        command.arg(format!("-runs={n}"));
    }
    let log_path = work.join(format!("{target}.log"));
    let log = fs::File::create(&log_path)?;
    command
        .current_dir(work)
        .stdout(log.try_clone()?)
        .stderr(log);
    eprintln!(
        "xtask: fuzzing {target} ({}), log {}",
        match (seconds, runs) {
            (Some(s), _) => format!("{s} s"),
            (None, Some(n)) => format!("{n} runs"),
            (None, None) => "until stopped".to_owned(),
        },
        log_path.display()
    );
    let start = Instant::now();
    let status = command
        .status()
        .with_context(|| format!("cannot run the {target} fuzzer; was it built?"))?;
    let seconds = start.elapsed().as_secs_f64();
    let text = fs::read_to_string(&log_path).unwrap_or_default();
    let executions = text
        .lines()
        .find_map(|l| l.strip_prefix("stat::number_of_executed_units:"))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0);
    let coverage = text
        .lines()
        .rev()
        .find_map(|l| {
            let at = l.find("cov: ")?;
            let rest = &l[at..];
            let end = rest.find(" corp:").unwrap_or(rest.len());
            Some(rest[..end].to_owned())
        })
        .unwrap_or_default();
    let failure = (!status.success()).then(|| {
        let artifact = text
            .lines()
            .rev()
            .find_map(|l| l.split("Test unit written to ").nth(1))
            .unwrap_or("(no artifact)")
            .trim()
            .to_owned();
        let summary = text
            .lines()
            .rev()
            .find(|l| l.starts_with("SUMMARY:") || l.contains("panicked at"))
            .unwrap_or("")
            .to_owned();
        format!(
            "fuzz target {target} failed ({status}): {summary}\n  reproducer: {artifact}\n  \
             rerun it: {} {artifact}\n  log: {}",
            binary(fuzz_dir, target).display(),
            log_path.display()
        )
    });
    Ok(Outcome {
        target: target.to_owned(),
        executions,
        coverage,
        seconds,
        failure,
    })
}

/// Merges `fuzz/corpus/TARGET` down to a set of inputs that covers the same edges.
fn minimize(fuzz_dir: &Path, work: &Path, target: &str) -> Result<()> {
    let corpus = fuzz_dir.join("corpus").join(target);
    if !corpus.is_dir() {
        return Ok(());
    }
    let merged = work.join("merged").join(target);
    if merged.exists() {
        fs::remove_dir_all(&merged)?;
    }
    fs::create_dir_all(&merged)?;
    // The smallest set of inputs that covers every edge the corpus covers (hit counts
    // aside): the committed corpus stays small (~1.5 MB for all targets) and a run
    // regains the counts within seconds.
    let status = Command::new(binary(fuzz_dir, target))
        .args(["-set_cover_merge=1", "-use_counters=0"])
        .arg(format!("-timeout={TIMEOUT_SECONDS}"))
        .arg(&merged)
        .arg(&corpus)
        .output()
        .with_context(|| format!("cannot run the {target} fuzzer"))?
        .status;
    if !status.success() {
        bail!("merging the {target} corpus failed ({status})");
    }
    let before = fs::read_dir(&corpus)?.count();
    fs::remove_dir_all(&corpus)?;
    fs::create_dir_all(&corpus)?;
    for entry in fs::read_dir(&merged)? {
        let entry = entry?;
        fs::copy(entry.path(), corpus.join(entry.file_name()))?;
    }
    let after = fs::read_dir(&corpus)?.count();
    println!("{target}: corpus {before} -> {after} inputs");
    Ok(())
}
