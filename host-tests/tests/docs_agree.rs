//! The docs against what they describe, where a test can hold it: the
//! example profile stands the pendant as docs/mounting.md says it must,
//! the technician's guide loads the profile with the brackets' calibrations, and no
//! procedure asks the reader to type a link command into a serial terminal (every
//! command has a `zerocal pendant` verb).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::fs;
use std::path::{Path, PathBuf};

use zerocal_procedure::link::{Command, BRACKET_CALIBRATE};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn read(page: &str) -> String {
    fs::read_to_string(repo_root().join(page)).unwrap()
}

/// README.md and every Markdown file under docs/, with their text.
fn pages() -> Vec<(PathBuf, String)> {
    let root = repo_root();
    let mut out = vec![root.join("README.md")];
    let mut stack = vec![root.join("docs")];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    out.sort();
    out.into_iter()
        .map(|p| {
            let text = fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect()
}

/// The example profile's flange bracket stands the pendant across joint 6 (its z not
/// along the flange frame's z): along it, Δθ6 and the chip's cross-axis rotation are one
/// parameter (docs/mounting.md), as on no built-in profile but the paper's wrist.
#[test]
fn the_example_profile_mounts_the_pendant_across_joint_6() {
    let profiles = read("docs/profiles.md");
    let stage2 = profiles
        .split("[stage2]")
        .nth(1)
        .expect("the example's [stage2] table");
    let mount_z = stage2
        .lines()
        .find_map(|l| l.trim().strip_prefix("mount_z"))
        .expect("its mount_z");
    let axis = mount_z
        .trim_start_matches([' ', '='])
        .split('"')
        .nth(1)
        .expect("a quoted axis");
    assert!(
        !matches!(axis, "z" | "-z" | "+z"),
        "docs/profiles.md's example mounts the pendant along joint 6 ({axis}), which \
         docs/mounting.md says makes Δθ6 the chip's cross-axis twin"
    );
    assert!(read("docs/mounting.md").contains("*across* joint 6"));
}

/// Every `load-profile` the technician's guide runs loads the brackets' calibrations:
/// without them both brackets are budgeted at ±0.5°.
#[test]
fn the_guide_loads_the_profile_with_its_brackets() {
    let guide = read("docs/real-robot.md");
    let loads: Vec<&str> = guide
        .lines()
        .filter(|l| l.contains("load-profile") && l.contains("zerocal pendant"))
        .collect();
    assert!(!loads.is_empty());
    for line in loads {
        assert!(line.contains("--brackets"), "docs/real-robot.md: {line}");
    }
}

/// No page tells the reader to type one of the link's commands (or to send it "on the
/// link"): each has a `zerocal pendant` verb, which the procedures use.
#[test]
fn no_procedure_types_a_link_command() {
    let mut words: Vec<&str> = Command::ALL
        .iter()
        .map(|c| c.word())
        .filter(|w| *w != "help")
        .collect();
    words.push(BRACKET_CALIBRATE);
    let mut found = Vec::new();
    for (path, text) in pages() {
        for (n, line) in text.lines().enumerate() {
            let lower = line.to_lowercase();
            let asks = [
                "type `",
                "on the link: ",
                "over the usb link, type",
                "serial terminal",
            ];
            for cue in asks {
                let Some(at) = lower.find(cue) else { continue };
                let after = &line[at + cue.len()..];
                if cue == "serial terminal" {
                    if !lower.contains("no procedure") && !lower.contains("needs that") {
                        found.push(format!("{}:{}: {line}", path.display(), n + 1));
                    }
                    continue;
                }
                if words.iter().any(|w| after.starts_with(w)) {
                    found.push(format!("{}:{}: {line}", path.display(), n + 1));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "use the `zerocal pendant` verb:\n{}",
        found.join("\n")
    );
}
