//! Golden files: one robot per controller family, written by the `zerocal` binary
//! with a fixed date (`SOURCE_DATE_EPOCH`), compared byte for byte with
//! `tests/golden/`. A change to a writer shows up here as a diff to review; after
//! reviewing it, `ZEROCAL_BLESS=1 cargo test -p zerocal-cli --test program_golden`
//! rewrites the files.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
// Joint loops read best with the joint index, as the formulas write them.
#![allow(clippy::needless_range_loop)]

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use zerocal_programs::program::{read, Format};
use zerocal_programs::robot_time::CAPTURES_PER_POSE;

/// 2023-11-14 22:13:20 UTC: the date the TP and INFORM headers carry.
const EPOCH: &str = "1700000000";

fn golden() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden")
}

/// The UR5e's plan: the planner refuses the UR5e (joints 2-4 parallel), so its
/// program is written for the seeded window poses of `common::window_poses`, kept as
/// a plan file (model degrees, as `zerocal plan --csv` writes).
fn ur5e_plan(bless: bool) -> PathBuf {
    let path = golden().join("ur5e-plan.csv");
    if bless {
        let profile = zerocal_profile::builtin("ur5e").unwrap();
        let mut text = String::from("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg\n");
        for q in common::window_poses(&profile, 8, 7) {
            let row: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
            text.push_str(&row.join(","));
            text.push('\n');
        }
        std::fs::write(&path, text).unwrap();
    }
    path
}

#[test]
fn one_program_per_family_matches_its_golden_file() {
    let bless = std::env::var("ZEROCAL_BLESS").is_ok_and(|v| v == "1");
    let gp7 = golden().join("yaskawa-gp7-pulses.toml");
    let ur_plan = ur5e_plan(bless);
    let cases: [(&str, &str, Format, Option<&Path>); 6] = [
        ("kuka-kr16", "zc_kr16.src", Format::Krl, None),
        ("abb-irb140", "zc_irb140.mod", Format::Rapid, None),
        ("fanuc-m20ia", "zc_m20ia.ls", Format::Tp, None),
        (gp7.to_str().unwrap(), "zc_gp7.jbi", Format::Inform, None),
        ("staubli-tx2-60", "zc_tx260", Format::Val3, None),
        ("ur5e", "zc_ur5e.script", Format::Urscript, Some(&ur_plan)),
    ];
    compare_with_goldens(&cases, &[], bless);
}

/// The check's programs (`--check`), one per family, on the same robots and plans.
#[test]
fn one_check_program_per_family_matches_its_golden_file() {
    let bless = std::env::var("ZEROCAL_BLESS").is_ok_and(|v| v == "1");
    let gp7 = golden().join("yaskawa-gp7-pulses.toml");
    let ur_plan = ur5e_plan(false);
    let cases: [(&str, &str, Format, Option<&Path>); 6] = [
        ("kuka-kr16", "zc_chk16.src", Format::Krl, None),
        ("abb-irb140", "zc_chk140.mod", Format::Rapid, None),
        ("fanuc-m20ia", "zc_chk20.ls", Format::Tp, None),
        (gp7.to_str().unwrap(), "zc_chkgp7.jbi", Format::Inform, None),
        ("staubli-tx2-60", "zc_chktx", Format::Val3, None),
        (
            "ur5e",
            "zc_chkur5e.script",
            Format::Urscript,
            Some(&ur_plan),
        ),
    ];
    compare_with_goldens(&cases, &["--check"], bless);
}

/// Writes each case's program with the `zerocal` binary (`extra` arguments added) and
/// compares it byte for byte with its golden file (or writes it, blessing).
fn compare_with_goldens(
    cases: &[(&str, &str, Format, Option<&Path>)],
    extra: &[&str],
    bless: bool,
) {
    let tmp = std::env::temp_dir().join(format!(
        "zerocal-golden-{}{}",
        std::process::id(),
        extra.concat()
    ));
    std::fs::create_dir_all(&tmp).unwrap();
    for &(robot, out, format, plan) in cases {
        let target = tmp.join(out);
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_zerocal"));
        cmd.env("SOURCE_DATE_EPOCH", EPOCH).args([
            "program",
            "--robot",
            robot,
            "--format",
            format.name(),
            "--out",
            target.to_str().unwrap(),
        ]);
        if let Some(p) = plan {
            cmd.args(["--plan", p.to_str().unwrap()]);
        }
        cmd.args(extra);
        let run = cmd.output().unwrap();
        assert_eq!(
            run.status.code(),
            Some(0),
            "{robot} {format}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        let files: Vec<(String, PathBuf)> = if format == Format::Val3 {
            let mut v: Vec<(String, PathBuf)> = std::fs::read_dir(&target)
                .unwrap()
                .map(|e| {
                    let p = e.unwrap().path();
                    (
                        format!("{out}/{}", p.file_name().unwrap().to_string_lossy()),
                        p,
                    )
                })
                .collect();
            v.sort();
            v
        } else {
            vec![(out.to_owned(), target.clone())]
        };
        for (name, written) in files {
            let text = std::fs::read(&written).unwrap();
            let want = golden().join(&name);
            if bless {
                std::fs::create_dir_all(want.parent().unwrap()).unwrap();
                std::fs::write(&want, &text).unwrap();
                continue;
            }
            let expected = std::fs::read(&want).unwrap_or_else(|e| {
                panic!(
                    "{}: {e} (run with ZEROCAL_BLESS=1 to create it)",
                    want.display()
                )
            });
            if text != expected {
                let (a, b) = (
                    String::from_utf8_lossy(&text),
                    String::from_utf8_lossy(&expected),
                );
                let first = a
                    .lines()
                    .zip(b.lines())
                    .position(|(x, y)| x != y)
                    .unwrap_or(a.lines().count().min(b.lines().count()));
                panic!(
                    "{name} differs from its golden file at line {}:\n  now:    {:?}\n  golden: {:?}",
                    first + 1,
                    a.lines().nth(first),
                    b.lines().nth(first)
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

/// The golden files themselves read back through the readers: every pose (stage 1's
/// two and the plan's) captured twice, four operator stops (clip on, the OK after the
/// half turn, to the flange, the closing bench readings), the last one the closing
/// bench readings', after the last move.
#[test]
fn golden_files_read_back() {
    let g = golden();
    let text = |n: &str| std::fs::read_to_string(g.join(n)).unwrap();
    let gp7 = common::gp7_with_pulses();
    let pulses = match gp7.controller.unit {
        zerocal_profile::OffsetUnit::Counts(Some(c)) => c,
        _ => panic!("test profile without pulses"),
    };
    let all = [
        read::krl(&text("zc_kr16.src")),
        read::rapid(&text("zc_irb140.mod")),
        read::tp(&text("zc_m20ia.ls")),
        read::inform(&text("zc_gp7.jbi"), &pulses),
        read::val3(&text("zc_tx260/ZC_TX260.dtx"), &text("zc_tx260/start.pgx")),
        read::urscript(&text("zc_ur5e.script")),
    ];
    // Stage 1's two captures and the plan's poses: the default plan's for five (its
    // distinct poses and its revisits), the UR5e's 8-pose plan file for the last.
    for (i, moves) in all.into_iter().enumerate() {
        let moves = moves.unwrap_or_else(|e| panic!("{e}"));
        let poses = if i == 5 {
            8
        } else {
            zerocal_core::plan::SESSION_POSES + zerocal_core::plan::SESSION_REVISITS
        };
        assert_eq!(
            moves.iter().filter(|m| m.dwell_s.is_some()).count(),
            CAPTURES_PER_POSE * (2 + poses)
        );
        assert_eq!(moves.iter().filter(|m| m.stop.is_some()).count(), 4);
        let last = moves.last().unwrap_or_else(|| panic!("file {i}: no moves"));
        let closing = last.stop.clone().unwrap_or_default().to_lowercase();
        assert!(
            last.dwell_s.is_none() && closing.contains("closing bench readings"),
            "file {i}: {closing}"
        );
    }
    // INFORM's line ends are CRLF (docs/controllers/yaskawa.md [Y3]).
    let jbi = text("zc_gp7.jbi");
    assert!(jbi.ends_with("\r\n"));
    assert!(jbi
        .split('\n')
        .filter(|l| !l.is_empty())
        .all(|l| l.ends_with('\r')));
}

/// The check's golden files read back through the readers: the check's poses only
/// (no stage 1), each captured twice; the first stop clips the pendant to the flange,
/// the last is the closing bench readings', after the last move.
#[test]
fn check_golden_files_read_back() {
    let g = golden();
    let text = |n: &str| std::fs::read_to_string(g.join(n)).unwrap();
    let gp7 = common::gp7_with_pulses();
    let pulses = match gp7.controller.unit {
        zerocal_profile::OffsetUnit::Counts(Some(c)) => c,
        _ => panic!("test profile without pulses"),
    };
    let all = [
        read::krl(&text("zc_chk16.src")),
        read::rapid(&text("zc_chk140.mod")),
        read::tp(&text("zc_chk20.ls")),
        read::inform(&text("zc_chkgp7.jbi"), &pulses),
        read::val3(&text("zc_chktx/ZC_CHKTX.dtx"), &text("zc_chktx/start.pgx")),
        read::urscript(&text("zc_chkur5e.script")),
    ];
    for (i, moves) in all.into_iter().enumerate() {
        let moves = moves.unwrap_or_else(|e| panic!("file {i}: {e}"));
        assert_eq!(
            moves.iter().filter(|m| m.dwell_s.is_some()).count(),
            CAPTURES_PER_POSE * zerocal_core::plan::CHECK_POSES,
            "file {i}"
        );
        let stops: Vec<String> = moves
            .iter()
            .filter_map(|m| m.stop.clone())
            .map(|s| s.to_lowercase())
            .collect();
        assert!(
            stops.first().is_some_and(|s| s.contains("flange")),
            "file {i}: {stops:?}"
        );
        assert!(
            !stops.iter().any(|s| s.contains("upper arm")),
            "file {i}: {stops:?}"
        );
        let last = moves.last().unwrap();
        let closing = last.stop.clone().unwrap_or_default().to_lowercase();
        assert!(
            last.dwell_s.is_none() && closing.contains("closing bench readings"),
            "file {i}: {closing}"
        );
    }
}
