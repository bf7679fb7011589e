//! `cargo xtask history-demo --out DIR [--write-docs docs]`: one simulated robot's
//! history through the `zerocal` binary, as a technician would make it: five sessions
//! over a year recorded, a motor swap on A3 restored to the first session's zero and
//! checked, each joint's zero over time plotted with its U(k = 2) band, and the first
//! session's certificate printed by headless Chromium with every number checked in the
//! PDF. `--write-docs` copies the A3 plot and the certificate's first page to the docs
//! (the README shows them). Every command it runs is printed first.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

/// The robot's serial in the demo.
const SERIAL: &str = "KR6-0001";

/// The simulated robot (its seed) and pendant: calibrated brackets as made within
/// ±0.3°, seated within the design's repeatability.
const ROBOT: [&str; 8] = [
    "--seed",
    "5",
    "--brackets",
    "calibrated",
    "--mount-tolerance-deg",
    "0.3",
    "--seat-repeatability-deg",
    "0.0015",
];

/// Stage 0 turned end for end against the fence (docs/mounting.md, T9).
const FENCE: [&str; 2] = ["--half-turn-tolerance-deg", "0.05"];

/// The sessions' days.
const DAYS: [&str; 5] = [
    "2026-01-12",
    "2026-03-09",
    "2026-05-11",
    "2026-07-06",
    "2026-09-14",
];

fn zerocal(args: &[String]) -> Result<String> {
    println!("zerocal {}", args.join(" "));
    let out = Command::new("cargo")
        .args(["run", "-q", "--release", "-p", "zerocal-cli", "--"])
        .args(args)
        .output()
        .context("running cargo run -p zerocal-cli")?;
    if !out.status.success() {
        bail!(
            "zerocal {} failed: {}",
            args.join(" "),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

fn strings(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| (*s).to_owned()).collect()
}

fn path(p: &Path) -> String {
    p.display().to_string()
}

/// Runs the demo into `out`; with `docs`, copies its figures there.
///
/// # Errors
/// A command failing, the certificate's check failing.
pub fn run(out: &Path, docs: Option<&Path>) -> Result<()> {
    fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let db = out.join("history.sqlite");
    for f in ["history.sqlite", "history.sqlite-wal", "history.sqlite-shm"] {
        let _ = fs::remove_file(out.join(f));
    }
    let db_args = ["--db".to_owned(), path(&db)];
    // Five sessions of one robot over the year, recorded.
    for (n, day) in DAYS.iter().enumerate() {
        let export = out.join(format!("session-{}.export", n + 1));
        let mut args = strings(&["simulate"]);
        args.extend(strings(&ROBOT));
        if n > 0 {
            args.extend(["--again".to_owned(), n.to_string()]);
        }
        args.extend(["--export".to_owned(), path(&export)]);
        zerocal(&args)?;
        let mut args = strings(&["session"]);
        args.push(path(&export));
        args.extend(strings(&[
            "--record",
            "--serial",
            SERIAL,
            "--operator",
            "A. Tech",
        ]));
        args.extend(["--measured-on".to_owned(), (*day).to_owned()]);
        args.extend(strings(&FENCE));
        args.extend(db_args.clone());
        zerocal(&args)?;
    }
    // A motor swap on A3 after the last session: restored to the first session's zero.
    let swap = out.join("swap.export");
    let mut args = strings(&["simulate"]);
    args.extend(strings(&ROBOT));
    args.extend(strings(&[
        "--again",
        "9",
        "--zero-moved",
        "3=1.0",
        "--export",
    ]));
    args.push(path(&swap));
    zerocal(&args)?;
    let mut args = strings(&["restore"]);
    args.push(path(&swap));
    args.extend(strings(&["--reference", "1", "--json"]));
    args.extend(strings(&FENCE));
    args.extend(db_args.clone());
    let restore: serde_json::Value = serde_json::from_str(&zerocal(&args)?)?;
    let a3 = restore["joints"][1]["controller_dq_deg"]
        .as_f64()
        .context("the restore printed no A3")?;
    println!("restore: A3's reading must move by {a3:+.5} deg");
    // The restore entered, then checked against the first session's zero.
    let checked = out.join("check.export");
    let mut args = strings(&["simulate"]);
    args.extend(strings(&ROBOT));
    args.extend(strings(&[
        "--again",
        "10",
        "--zero-moved",
        "3=1.0",
        "--entered",
    ]));
    args.push(format!("0,{a3},0,0,0"));
    args.extend(["--export".to_owned(), path(&checked)]);
    zerocal(&args)?;
    let mut args = strings(&["check"]);
    args.push(path(&checked));
    args.extend(strings(&[
        "--against",
        "1",
        "--restored",
        "--measured-on",
        "2026-10-05",
    ]));
    args.extend(strings(&FENCE));
    args.extend(db_args.clone());
    print!("{}", zerocal(&args)?);
    // The history, its plots and the first session's certificate.
    let plots = out.join("plots");
    let mut args = strings(&["history", SERIAL, "--plot"]);
    args.push(path(&plots));
    args.extend(db_args.clone());
    print!("{}", zerocal(&args)?);
    let html = out.join("certificate.html");
    let mut args = strings(&["certificate", "1", "--out"]);
    args.push(path(&html));
    args.extend(db_args);
    zerocal(&args)?;
    let rendered = out.join("certificate");
    crate::certificate::run(&html, &html.with_extension("numbers"), &rendered)?;
    if let Some(docs) = docs {
        let plot = plots.join(format!("{SERIAL}-j3.svg"));
        let figures: [(PathBuf, PathBuf); 2] = [
            (plot, docs.join("history-j3.svg")),
            (
                rendered.join("certificate.png"),
                docs.join("certificate-page1.png"),
            ),
        ];
        for (from, to) in figures {
            fs::copy(&from, &to)
                .with_context(|| format!("copying {} to {}", from.display(), to.display()))?;
            println!("wrote {}", to.display());
        }
    }
    Ok(())
}
