//! `zerocal bracket`: the flange bracket's OpenSCAD parameters for a profile, compared
//! byte for byte with `tests/golden/*-bracket.scad`. After reviewing a change,
//! `ZEROCAL_BLESS=1 cargo test -p zerocal-cli --test bracket_golden` rewrites them.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn golden() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden")
}

fn zerocal(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .unwrap()
}

/// The UR5e (the one built-in whose flange a source gives, without its dowel) and a
/// fixture profile with a made-up flange and dowel: each written with `--out`, the
/// same text as printed, and equal to its golden file.
#[test]
fn bracket_parameters_match_their_golden_files() {
    let bless = std::env::var("ZEROCAL_BLESS").is_ok_and(|v| v == "1");
    let fixture = golden().join("bracket-fixture.toml");
    let cases = [
        ("ur5e".to_owned(), "ur5e-bracket.scad"),
        (fixture.to_str().unwrap().to_owned(), "fixture-bracket.scad"),
    ];
    let tmp = std::env::temp_dir().join(format!("zerocal-bracket-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    for (robot, file) in &cases {
        let target = tmp.join(file);
        let run = zerocal(&[
            "bracket",
            "--robot",
            robot,
            "--out",
            target.to_str().unwrap(),
        ]);
        assert_eq!(
            run.status.code(),
            Some(0),
            "{robot}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        let written = std::fs::read_to_string(&target).unwrap();
        let printed = zerocal(&["bracket", "--robot", robot]);
        assert_eq!(
            String::from_utf8_lossy(&printed.stdout).trim_end(),
            written.trim_end(),
            "{robot}: printed and written differ"
        );
        let path = golden().join(file);
        if bless {
            std::fs::write(&path, &written).unwrap();
        }
        let expected = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (bless it first)", path.display()));
        assert_eq!(
            written,
            expected,
            "{robot}: differs from {}",
            path.display()
        );
        assert!(
            written.contains("include <flange_bracket.scad>"),
            "{robot}: the design is included"
        );
    }
    std::fs::remove_dir_all(&tmp).unwrap();
}

/// A profile without `[flange] iso9409` is refused (exit 3), naming the key and
/// quoting the profile's own `missing` line; nothing is written.
#[test]
fn a_profile_without_a_flange_interface_is_refused() {
    let target =
        std::env::temp_dir().join(format!("zerocal-bracket-kr16-{}.scad", std::process::id()));
    let run = zerocal(&[
        "bracket",
        "--robot",
        "kuka-kr16",
        "--out",
        target.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(3));
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("iso9409"), "{err}");
    assert!(
        err.contains("not found in a public source reached"),
        "{err}"
    );
    assert!(!target.exists(), "nothing written");
}

/// docs/mounting.md's per-robot table agrees with the profiles: every built-in is named
/// in exactly one row, and that row gives its ISO 9409-1 designation where the profile
/// has one, and begins "none" where it has not.
#[test]
fn the_mounting_pages_table_agrees_with_the_profiles() {
    let page =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/mounting.md"))
            .unwrap();
    let section = page
        .split("### Per robot")
        .nth(1)
        .and_then(|s| s.split("### The designs").next())
        .expect("docs/mounting.md has its 'Per robot' table");
    let rows: Vec<Vec<&str>> = section
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l.split('|').map(str::trim).collect())
        .collect();
    for name in zerocal_profile::builtin_names() {
        let tick = format!("`{name}`");
        let hits: Vec<&Vec<&str>> = rows.iter().filter(|r| r[1].contains(&tick)).collect();
        assert_eq!(hits.len(), 1, "{name}: in {} rows", hits.len());
        let cell = hits[0][2];
        let profile = zerocal_profile::builtin(name).unwrap();
        match &profile.flange_interface {
            Some(f) => assert!(cell.contains(&f.iso9409.designation()), "{name}: {cell}"),
            None => assert!(cell.starts_with("none"), "{name}: {cell}"),
        }
    }
}
