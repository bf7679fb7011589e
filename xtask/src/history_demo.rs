//! `cargo xtask history-demo --out DIR [--write-docs docs]`: one simulated robot's
//! history through the `zerocal` binary, as a technician would make it: the first
//! session recorded, its offsets entered and checked (the robot as left), four more
//! sessions over a year recorded, a motor swap on A3 restored to the second session's
//! zero and checked, each joint's zero over time plotted with its U(k = 2) band, and the
//! first session's certificate (as found and as left, issued by
//! `cli/tests/golden/issuer.toml`) printed by headless Chromium with every number
//! checked in the PDF. `--write-docs` copies the A3 plot and the certificate's first
//! page to the docs (docs/history.md and docs/certificate.md show them). Every command it
//! runs is printed first.

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

/// The issuer of the demo's certificate: the tests' (illustrative IDs and dates).
const ISSUER: &str = "cli/tests/golden/issuer.toml";

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
    let simulate = |export: &Path, extra: &[String]| -> Result<()> {
        let mut args = strings(&["simulate"]);
        args.extend(strings(&ROBOT));
        args.extend(extra.iter().cloned());
        args.extend(["--export".to_owned(), path(export)]);
        zerocal(&args).map(|_| ())
    };
    let record = |export: &Path, day: &str| -> Result<serde_json::Value> {
        let mut args = strings(&["session"]);
        args.push(path(export));
        args.extend(strings(&[
            "--record",
            "--serial",
            SERIAL,
            "--operator",
            "A. Tech",
            "--json",
        ]));
        args.extend(["--measured-on".to_owned(), day.to_owned()]);
        args.extend(strings(&FENCE));
        args.extend(db_args.clone());
        Ok(serde_json::from_str(&zerocal(&args)?)?)
    };
    // The first session, recorded; its offsets (the model's, as `--entered` takes them)
    // entered and checked the same day: the robot as left.
    let first = out.join("session-1.export");
    simulate(&first, &[])?;
    let s1 = record(&first, DAYS[0])?;
    let entered: Vec<f64> = (0..5)
        .map(|k| {
            s1["joints"][k]["offset_deg"]
                .as_f64()
                .context("the session's offsets")
        })
        .collect::<Result<_>>()?;
    let entered_arg = |extra: [f64; 5]| {
        entered
            .iter()
            .zip(extra)
            .map(|(e, x)| format!("{:e}", e + x))
            .collect::<Vec<_>>()
            .join(",")
    };
    let as_left = out.join("as-left.export");
    simulate(
        &as_left,
        &[
            "--again".into(),
            "11".into(),
            "--entered".into(),
            entered_arg([0.0; 5]),
        ],
    )?;
    let mut args = strings(&["check"]);
    args.push(path(&as_left));
    args.extend(strings(&["--against", "1", "--measured-on", DAYS[0]]));
    args.extend(strings(&FENCE));
    args.extend(db_args.clone());
    print!("{}", zerocal(&args)?);
    // Four more sessions of the robot over the year, its zeros as the entry left them.
    for (n, day) in DAYS.iter().enumerate().skip(1) {
        let export = out.join(format!("session-{}.export", n + 1));
        simulate(
            &export,
            &[
                "--again".into(),
                n.to_string(),
                "--entered".into(),
                entered_arg([0.0; 5]),
            ],
        )?;
        record(&export, day)?;
    }
    // A motor swap on A3 after the last session: restored to the second session's zero
    // (the first after the entry).
    let swap = out.join("swap.export");
    simulate(
        &swap,
        &[
            "--again".into(),
            "9".into(),
            "--zero-moved".into(),
            "3=1.0".into(),
            "--entered".into(),
            entered_arg([0.0; 5]),
        ],
    )?;
    let mut args = strings(&["restore"]);
    args.push(path(&swap));
    args.extend(strings(&["--reference", "3", "--json"]));
    args.extend(strings(&FENCE));
    args.extend(db_args.clone());
    let restore: serde_json::Value = serde_json::from_str(&zerocal(&args)?)?;
    let a3 = restore["joints"][1]["controller_dq_deg"]
        .as_f64()
        .context("the restore printed no A3")?;
    println!("restore: A3's reading must move by {a3:+.5} deg");
    // The restore entered (KUKA: the controller's A3 is the model's), then checked
    // against the second session's zero.
    let checked = out.join("check.export");
    simulate(
        &checked,
        &[
            "--again".into(),
            "10".into(),
            "--zero-moved".into(),
            "3=1.0".into(),
            "--entered".into(),
            entered_arg([0.0, a3, 0.0, 0.0, 0.0]),
        ],
    )?;
    let mut args = strings(&["check"]);
    args.push(path(&checked));
    args.extend(strings(&[
        "--against",
        "3",
        "--restored",
        "--measured-on",
        "2026-10-05",
        "--restore-export",
    ]));
    args.push(path(&swap));
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
    args.extend(strings(&["--config", ISSUER]));
    args.extend(db_args);
    print!("{}", zerocal(&args)?);
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
