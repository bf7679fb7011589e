//! Bounded resources for every input, through the binary: endless or huge files are
//! refused at their cap, implausible profile numbers and texts at load, and the
//! widest plausible profile runs to finite numbers of a sane width.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;
use std::process::{Command, Output};
use std::time::{Duration, Instant};
use zerocal_inputs::input::{MAX_EXPORT_BYTES, MAX_LIMITS_BYTES, MAX_LOG_BYTES, MAX_PLAN_BYTES};
use zerocal_profile::bounds::MAX_PROFILE_BYTES;
use zerocal_programs::program::Format;

/// A refusal at a cap reads `cap + 1` bytes at most: far under this on any machine
/// (the 200 MB export that prompted the caps took 501 s).
const QUICK: Duration = Duration::from_secs(10);

fn zerocal(args: &[&str]) -> (Output, Duration) {
    let start = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .expect("run zerocal");
    (out, start.elapsed())
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("zerocal-bounds-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// The KR 6's profile with one replacement made (which must apply).
fn kr6_with(from: &str, to: &str) -> String {
    let text = include_str!("../../data/robots/kuka-kr6-r900-sixx.toml");
    assert!(text.contains(from), "{from}");
    text.replacen(from, to, 1)
}

/// `/dev/zero` as every file the CLI reads: refused quickly (status 2), naming the
/// file, what it is and the cap.
#[test]
fn endless_files_are_refused_at_their_cap() {
    if !std::path::Path::new("/dev/zero").exists() {
        return;
    }
    let out = temp_dir("zero").join("p.src");
    let out = out.to_str().expect("utf-8 path");
    let cases: [(Vec<&str>, &str, usize); 4] = [
        (
            vec!["identify", "--convention", "rpy", "/dev/zero"],
            "stage-2 log",
            MAX_LOG_BYTES,
        ),
        (
            vec!["plan", "--limits", "/dev/zero"],
            "limits file",
            MAX_LIMITS_BYTES,
        ),
        (
            vec![
                "program",
                "--robot",
                "kuka-kr16",
                "--format",
                "krl",
                "--out",
                out,
                "--plan",
                "/dev/zero",
            ],
            "plan",
            MAX_PLAN_BYTES,
        ),
        (
            vec!["plan", "--robot", "/dev/zero"],
            "robot profile",
            MAX_PROFILE_BYTES,
        ),
    ];
    for (args, what, cap) in cases {
        let (o, took) = zerocal(&args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert!(
            e.contains(&format!("/dev/zero ({what})")) && e.contains(&format!("{cap} bytes")),
            "{args:?}: {e}"
        );
        assert!(took < QUICK, "{args:?}: {took:?}");
    }
}

/// A pendant export of the most captures fills a quarter of the export cap at most
/// (the rest is room for comments added by hand).
#[test]
fn the_largest_export_fits_a_quarter_of_its_cap() {
    let profile = zerocal_profile::builtin("kuka-kr6-r900-sixx").expect("built in");
    // Twice each of the default plan's poses and revisits: 86 rows, within the
    // pendant's most (MAX_CAPTURES).
    let world = zerocal_sim::world::WorldConfig::real();
    let session =
        zerocal_sim::world::RealSession::simulate_default_plan(&profile, &world, 5).expect("plan");
    let text = session.export_text(&profile.name);
    let rows = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("j1_deg"))
        .count();
    println!("export of {rows} rows: {} bytes", text.len());
    assert_eq!(
        rows,
        2 * (zerocal_core::plan::SESSION_POSES + zerocal_core::plan::SESSION_REVISITS)
    );
    assert!(rows <= zerocal_core::capture::MAX_CAPTURES);
    assert!(text.len() * 4 <= MAX_EXPORT_BYTES, "{}", text.len());
}

/// A ten-megabyte profile name (the quadratic case of `program`): refused quickly at
/// the profile's size cap; a name past the pendant's 32 bytes in a small file is
/// refused naming the key.
#[test]
fn long_names_are_refused_at_load() {
    let dir = temp_dir("names");
    let huge = dir.join("huge.toml");
    let name = "k".repeat(10 << 20);
    std::fs::write(
        &huge,
        kr6_with(
            "name = \"kuka-kr6-r900-sixx\"",
            &format!("name = \"{name}\""),
        ),
    )
    .expect("write");
    let long = dir.join("long.toml");
    std::fs::write(
        &long,
        kr6_with(
            "name = \"kuka-kr6-r900-sixx\"",
            &format!("name = \"{}\"", "k".repeat(40)),
        ),
    )
    .expect("write");
    let out = dir.join("p.src");
    for (file, expected) in [
        (&huge, format!("longer than {MAX_PROFILE_BYTES} bytes")),
        (&long, "name: longer than 32 bytes".to_owned()),
    ] {
        let (o, took) = zerocal(&[
            "program",
            "--robot",
            file.to_str().expect("utf-8"),
            "--format",
            "krl",
            "--out",
            out.to_str().expect("utf-8"),
        ]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{e}");
        assert!(e.contains(&expected) && e.len() < 400, "{e}");
        assert!(took < QUICK, "{took:?}");
    }
    assert!(!out.exists());
}

/// Limits of ±1e308 (which made `simulate` panic in its random draw), counts per degree
/// of 1e308 (a 300-digit offset with PASS) and a joint speed of 1e-6 deg/s (gigabytes
/// in `plan`): each refused at load, status 2, naming the key and its range.
#[test]
fn implausible_profile_numbers_are_refused_at_load() {
    let dir = temp_dir("numbers");
    let cases = [
        (
            "simulate",
            kr6_with(
                "min_deg = -120.0\nmax_deg = 120.0",
                "min_deg = -1e308\nmax_deg = 1e308",
            ),
            "joint 5: min_deg: -1e308 is outside the plausible range [-720, 720] deg",
        ),
        (
            "simulate",
            kr6_with(
                "offset_unit = \"deg\"",
                "offset_unit = \"counts\"\ncounts_per_deg = [1e308, 1e308, 1e308, 1e308, 1e308, 1e308]",
            ),
            "controller.counts_per_deg: 1e308 is outside the plausible range [0.001, 1000000000] counts/deg",
        ),
        (
            "plan",
            kr6_with("max_speed_deg_s = 388.0", "max_speed_deg_s = 1e-6"),
            "joint 5: max_speed_deg_s: 1e-6 is outside the plausible range [0.1, 10000] deg/s",
        ),
        (
            "program",
            kr6_with("max_speed_deg_s = 388.0", "max_speed_deg_s = 1e-6"),
            "joint 5: max_speed_deg_s",
        ),
    ];
    for (i, (sub, text, expected)) in cases.into_iter().enumerate() {
        let file = dir.join(format!("p{i}.toml"));
        std::fs::write(&file, text).expect("write");
        let file = file.to_str().expect("utf-8");
        let out = dir.join("p.src");
        let out = out.to_str().expect("utf-8");
        let args: Vec<&str> = match sub {
            "program" => vec![sub, "--robot", file, "--format", "krl", "--out", out],
            _ => vec![sub, "--robot", file],
        };
        let (o, took) = zerocal(&args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert!(e.contains(expected), "{args:?}: {e}");
        assert!(took < QUICK, "{args:?}: {took:?}");
    }
}

/// The widest limits (±720° on every joint) and the fastest joints with the most
/// counts per degree the ranges allow: `simulate` and `plan` run to numbers, none
/// of them infinite or NaN, and an offset in counts is at most a 13-character figure.
#[test]
fn the_widest_plausible_profile_gives_finite_numbers() {
    let dir = temp_dir("wide");
    let text = include_str!("../../data/robots/kuka-kr6-r900-sixx.toml");
    let mut wide = String::new();
    for line in text.lines() {
        let line = if line.starts_with("min_deg") {
            "min_deg = -720.0"
        } else if line.starts_with("max_deg") {
            "max_deg = 720.0"
        } else if line.starts_with("max_speed_deg_s") {
            "max_speed_deg_s = 10000.0"
        } else {
            line
        };
        wide.push_str(line);
        wide.push('\n');
    }
    let wide = wide.replacen(
        "offset_unit = \"deg\"",
        "offset_unit = \"counts\"\ncounts_per_deg = [1e9, 1e9, 1e9, 1e9, 1e9, 1e9]",
        1,
    );
    let file = dir.join("wide.toml");
    std::fs::write(&file, wide).expect("write");
    let file = file.to_str().expect("utf-8");
    let export = dir.join("export.csv");
    let export = export.to_str().expect("utf-8");
    let mut offsets_in_counts = 0;
    for args in [
        vec![
            "simulate",
            "--robot",
            file,
            "--accuracy-points",
            "20",
            "--export",
            export,
        ],
        vec![
            "simulate",
            "--robot",
            file,
            "--world",
            "ideal",
            "--accuracy-points",
            "20",
        ],
        vec!["plan", "--robot", file],
        vec!["session", export, "--robot", file],
    ] {
        let (o, _) = zerocal(&args);
        let text = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let lower = text.to_lowercase();
        for bad in ["inf", "nan"] {
            assert!(
                !lower
                    .split(|c: char| !c.is_ascii_alphanumeric())
                    .any(|w| w == bad || w == "-inf"),
                "{args:?}: '{bad}' in\n{text}"
            );
        }
        for line in text.lines().filter(|l| l.ends_with(" counts")) {
            let figure = line.split_whitespace().rev().nth(1).unwrap_or("");
            let whole = figure.split('.').next().unwrap_or("");
            assert!(whole.len() <= 13, "{args:?}: {line}");
            offsets_in_counts += 1;
        }
    }
    // The session's report gives j2-j6 in counts.
    assert!(offsets_in_counts >= 5, "{offsets_in_counts}");
}

/// Every format refuses an output path in a missing folder the same way, status 2 and
/// nothing made (VAL3, a project folder, made the folder before).
#[test]
fn every_format_refuses_a_missing_folder() {
    let dir = temp_dir("folders");
    let pulses = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/golden/yaskawa-gp7-pulses.toml"
    );
    for format in Format::ALL {
        let robot = match format {
            Format::Krl => "kuka-kr16",
            Format::Rapid => "abb-irb140",
            Format::Tp => "fanuc-lrmate200id",
            Format::Inform => pulses,
            Format::Val3 => "staubli-tx2-60",
            Format::Urscript => "ur5e",
        };
        let missing = dir.join("missing");
        let out = missing.join("zc");
        let (o, _) = zerocal(&[
            "program",
            "--robot",
            robot,
            "--format",
            format.name(),
            "--out",
            out.to_str().expect("utf-8"),
        ]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{format}: {e}");
        assert!(
            e.contains(&format!("the folder {} does not exist", missing.display())),
            "{format}: {e}"
        );
        assert!(!missing.exists(), "{format}: made {}", missing.display());
    }
}

/// `simulate --world ideal --noise-deg 0` is refused naming the range (zero noise
/// made the report divide rounding by rounding: "factor inf"); the smallest noise
/// in range prints no infinity.
#[test]
fn zero_noise_is_refused_and_the_least_noise_prints_finite_ratios() {
    let (o, _) = zerocal(&["simulate", "--world", "ideal", "--noise-deg", "0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("[0.000001, 1] deg"), "{}", stderr(&o));
    let (o, _) = zerocal(&[
        "simulate",
        "--world",
        "ideal",
        "--noise-deg",
        "0.000001",
        "--accuracy-points",
        "20",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(!text.contains("inf") && !text.contains("NaN"), "{text}");
}
