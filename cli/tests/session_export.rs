//! `zerocal session` on exports that used to give wrong numbers with exit 0: each is now
//! refused with the line and key or column named, or (a session without a stage-0
//! reversal) solved with the sensor's unknown offset in its budget. The exports are the
//! simulator's (`RealSession::export_text`, truth known) and the pendant's own (its
//! tasks run on the desktop, the link's `export` with the `approach` and `pose` columns),
//! edited as a user or a damaged file would.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use zerocal_pendant_desktop::session::session as pendant_session;
use zerocal_profile::Profile;
use zerocal_sim::world::{ApproachScheme, RealSession, WorldConfig};

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-session-export-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn kr6() -> Profile {
    zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap()
}

/// A simulated KR 6 session with every error source on.
fn simulated(world: &WorldConfig, seed: u64) -> RealSession {
    RealSession::simulate_default_plan(&kr6(), world, seed).unwrap()
}

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir().join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

fn session(path: &Path, extra: &[&str]) -> Output {
    let mut args = vec!["session", path.to_str().unwrap(), "--json"];
    args.extend_from_slice(extra);
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(&args)
        .output()
        .unwrap()
}

/// `text` with its end trailer made anew over its lines (any old one dropped): the
/// edited export as a writer that made it so would have sealed it, so that the
/// reader's own checks, not the trailer, must catch what the edit did.
fn resealed(text: &str) -> String {
    let mut out: String = text
        .lines()
        .filter(|l| !zerocal_procedure::export_trailer::is_trailer(l))
        .flat_map(|l| [l, "\n"])
        .collect();
    let trailer = zerocal_procedure::export_trailer::trailer_of(&out);
    out.push_str(&format!("{trailer}\n"));
    out
}

/// The export `text` edited (and [`resealed`]), refused with exit status 2 and every
/// one of `words` in the message.
fn refused(name: &str, text: &str, words: &[&str]) {
    let out = session(&write(name, resealed(text).as_bytes()), &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{name}: {err}");
    for w in words {
        assert!(err.contains(w), "{name}: no '{w}' in: {err}");
    }
}

/// The line of `text` starting with `prefix` (1-based) and the line itself.
fn line_of(text: &str, prefix: &str) -> (usize, String) {
    text.lines()
        .enumerate()
        .find(|(_, l)| l.starts_with(prefix))
        .map(|(i, l)| (i + 1, l.to_owned()))
        .unwrap_or_else(|| panic!("no line '{prefix}'"))
}

/// Without stage 0 the sensor's x offset (±1.15° by specification) goes into Δθ2 and,
/// through the hand-over, into Δθ3 and Δθ6: tenths of a degree the noise-only σ
/// (thousandths) did not show. The budget now carries it: every offset's error is
/// within its own U (k = 2), Δθ2's U exceeds 0.1° (the offset is known only to its
/// specification, so U is of its order: no session can do better without stage 0),
/// and the report says why.
#[test]
fn a_session_without_stage_0_carries_the_sensor_offset_in_its_budget() {
    let s = simulated(&WorldConfig::real(), 31);
    let text = s.export_text("kuka-kr6-r900-sixx");
    let (_, stage0) = line_of(&text, "# stage0_bench_deg");
    let truth = s.truth_rad().map(f64::to_degrees);
    for (name, edited) in [
        ("none.csv", text.replace(&stage0, "# stage0_bias_deg none")),
        ("removed.csv", text.replace(&format!("{stage0}\n"), "")),
    ] {
        let out = session(&write(name, resealed(&edited).as_bytes()), &[]);
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        for k in 0..5 {
            let j = &v["joints"][k];
            let f = j["offset_deg"].as_f64().unwrap();
            let u = j["expanded_k2_deg"].as_f64().unwrap();
            assert!(
                (f - truth[k]).abs() <= u,
                "{name} j{}: {f} vs truth {} (U {u})",
                k + 2,
                truth[k]
            );
            let term = j["budget_deg"]
                .as_array()
                .unwrap()
                .iter()
                .find(|t| t["term"] == "sensor offset, no stage 0 (specification)")
                .expect("the term");
            assert!(term["standard_uncertainty_deg"].as_f64().unwrap() >= 0.0);
        }
        assert!(v["joints"][0]["expanded_k2_deg"].as_f64().unwrap() > 0.1);
        let notes = v["notes"].to_string();
        assert!(
            notes.contains("no stage-0 reversal") && notes.contains("offset specification"),
            "{notes}"
        );
    }
    // With stage 0, the term is zero: the reversal measured the offset.
    let out = session(&write("with.csv", text.as_bytes()), &[]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let term = v["joints"][0]["budget_deg"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["term"] == "sensor offset, no stage 0 (specification)")
        .map(|t| t["standard_uncertainty_deg"].as_f64().unwrap());
    assert_eq!(term, Some(0.0));
}

/// A misspelt key is an unknown key, not a free comment: its value would be lost.
#[test]
fn an_unknown_metadata_key_is_refused_by_name_and_line() {
    let text = simulated(&WorldConfig::real(), 32).export_text("kuka-kr6-r900-sixx");
    let (n, _) = line_of(&text, "# stage0_bench_deg");
    refused(
        "misspelt.csv",
        &text.replacen("# stage0_bench_deg", "# stage0_reversal_dge", 1),
        &[
            &format!("line {n}"),
            "unknown metadata key 'stage0_reversal_dge'",
        ],
    );
    // Free comments (no '_' or digit in the first word) stay allowed.
    let commented = text.replacen(
        "# robot",
        "# measured on cell 4 by the night shift\n# robot",
        1,
    );
    let out = session(
        &write("commented.csv", resealed(&commented).as_bytes()),
        &[],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Two stage-1 lines: which one the solver used would be a guess.
#[test]
fn a_metadata_key_given_twice_is_refused_with_both_lines() {
    let text = simulated(&WorldConfig::real(), 33).export_text("kuka-kr6-r900-sixx");
    let (n, stage1) = line_of(&text, "# stage1_readings_deg");
    // The same line with another "before" reading.
    let mut words: Vec<&str> = stage1.split(' ').collect();
    let at = words.iter().position(|w| *w == "before").unwrap() + 1;
    words[at] = "0.5,0.5";
    let other = words.join(" ");
    let edited = text.replace(&stage1, &format!("{stage1}\n{other}"));
    refused(
        "twice.csv",
        &edited,
        &[
            &format!("line {}", n + 1),
            "'stage1_readings_deg' given again",
            &format!("first on line {n}"),
        ],
    );
}

/// Stage 1's j2_deg against the profile's stage-1 pose (−90°): a record 10° or 0.5° off
/// would move Δθ2 and Δθ3 by as much, unseen by the fit (stage 2's rows swing joint 2).
#[test]
fn stage_1_joint_2_disagreeing_with_the_profile_is_refused() {
    let s = simulated(&WorldConfig::real(), 34);
    let text = s.export_text("kuka-kr6-r900-sixx");
    let (_, stage1) = line_of(&text, "# stage1_readings_deg");
    let j2 = s.stage1.j2_rad.to_degrees();
    let (first_row, _) = line_of(&text, "j1_deg,");
    for off in [10.0, 0.5] {
        let written = format!(" j2_deg {j2:.12}");
        assert!(stage1.ends_with(&written), "{stage1}");
        let edited = text.replace(
            &stage1,
            &stage1.replace(&written, &format!(" j2_deg {:.12}", j2 + off)),
        );
        let (stage1_line, _) = line_of(&text, "# stage1_readings_deg");
        let _ = first_row;
        refused(
            "j2.csv",
            &edited,
            &[&format!("line {stage1_line}"), "stage 1's j2_deg"],
        );
    }
}

/// Stage 1's j1_deg against the rows' joint 1: the export (its stage-1 line at
/// joint 1 = 0, its rows at -90, or the other way round) gave a wrong Δθ3 with exit 0;
/// a single row's joint 1 just past the tolerance is refused the same way, by its line.
#[test]
fn stage_1_joint_1_disagreeing_with_the_rows_is_refused() {
    let s = simulated(&WorldConfig::real(), 39);
    let text = s.export_text("kuka-kr6-r900-sixx");
    let (_, stage1) = line_of(&text, "# stage1_readings_deg");
    let j1 = s.stage1.j1_rad.to_degrees();
    let (header, _) = line_of(&text, "j1_deg,");
    let written = format!(" j1_deg {j1:.12} ");
    assert!(stage1.contains(&written), "{stage1}");
    for off in [-90.0, 0.5] {
        let edited = text.replace(
            &stage1,
            &stage1.replace(&written, &format!(" j1_deg {:.12} ", j1 + off)),
        );
        refused(
            "j1.csv",
            &edited,
            &[
                &format!("line {}", header + 1),
                "stage 1's j1_deg",
                "joint 1 at",
            ],
        );
    }
    // The fifth row's joint 1, twice the tolerance off.
    let rows: Vec<&str> = text.lines().skip(header).take(5).collect();
    let (first, rest) = rows[4].split_once(',').unwrap();
    let moved: f64 =
        first.parse::<f64>().unwrap() + 2.0 * zerocal_core::session::STAGE1_JOINT1_TOLERANCE_DEG;
    refused(
        "row-j1.csv",
        &text.replace(rows[4], &format!("{moved:.12},{rest}")),
        &[&format!("line {}", header + 5), "stage 1's j1_deg"],
    );
    // Every row's joint 1 within the tolerance (both captures of a pose alike, as
    // they pair by equal joints): solved.
    let near = 0.5 * zerocal_core::session::STAGE1_JOINT1_TOLERANCE_DEG;
    let edited: String = text
        .lines()
        .enumerate()
        .map(|(i, l)| match l.split_once(',') {
            Some((q1, rest)) if i >= header && !l.starts_with('#') => {
                format!("{:.12},{rest}\n", q1.parse::<f64>().unwrap() + near)
            }
            _ => format!("{l}\n"),
        })
        .collect();
    let edited = resealed(&edited);
    let out = session(&write("near-j1.csv", edited.as_bytes()), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `zerocal simulate --export` seals its export with the pendant's end trailer: read
/// whole without the "no end trailer" note; cut short, a line altered, or the trailer
/// itself altered, it is refused naming the trailer; without the trailer it is read
/// with the note.
#[test]
fn a_simulated_export_is_sealed_and_a_cut_or_altered_one_is_refused() {
    let path = dir().join("simulated.export");
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["simulate", "--seed", "41", "--export"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let last = text.lines().last().unwrap();
    assert!(
        zerocal_procedure::export_trailer::is_trailer(last),
        "{last}"
    );
    let whole = session(&path, &[]);
    assert!(
        whole.status.success(),
        "{}",
        String::from_utf8_lossy(&whole.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&whole.stdout).unwrap();
    assert!(!v["notes"].to_string().contains("no end trailer"), "{v}");
    let lines: Vec<&str> = text.lines().collect();
    let n = lines.len();
    let joined = |ls: &[&str]| ls.iter().flat_map(|l| [*l, "\n"]).collect::<String>();
    // The last row lost, the trailer kept.
    let mut cut = lines.clone();
    cut.remove(n - 2);
    // A digit of a row changed.
    let row = lines[n - 2];
    let digit = row.rfind(|c: char| c.is_ascii_digit() && c != '9').unwrap();
    let mut altered_row = row.to_owned();
    altered_row.replace_range(digit..=digit, "9");
    let mut altered = lines.clone();
    altered[n - 2] = &altered_row;
    // The trailer's CRC changed.
    let crc_at = last.rfind(' ').unwrap() + 1;
    let flipped = if &last[crc_at..crc_at + 1] == "0" {
        "1"
    } else {
        "0"
    };
    let bad_trailer = format!("{}{flipped}{}", &last[..crc_at], &last[crc_at + 1..]);
    let mut retrailed = lines.clone();
    retrailed[n - 1] = &bad_trailer;
    for (name, edited, words) in [
        ("cut.export", joined(&cut), "lines lost or added"),
        ("altered.export", joined(&altered), "a line changed"),
        ("trailer.export", joined(&retrailed), "a line changed"),
    ] {
        let out = session(&write(name, edited.as_bytes()), &[]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains("end trailer") && err.contains(words),
            "{name}: {err}"
        );
    }
    let unsealed = session(
        &write("unsealed.export", joined(&lines[..n - 1]).as_bytes()),
        &[],
    );
    assert!(unsealed.status.success());
    let v: serde_json::Value = serde_json::from_slice(&unsealed.stdout).unwrap();
    assert!(v["notes"].to_string().contains("no end trailer"), "{v}");
}

/// Every pose captured from one side only (the simulator's consistent approach): an
/// export without the approach column must have each pose twice.
#[test]
fn poses_captured_from_one_side_are_refused() {
    let world = WorldConfig {
        approach: ApproachScheme::Consistent,
        ..WorldConfig::real()
    };
    let text = simulated(&world, 35).export_text("kuka-kr6-r900-sixx");
    let (header, _) = line_of(&text, "j1_deg,");
    refused(
        "one-sided.csv",
        &text,
        &[&format!("line {}", header + 1), "captured once"],
    );
}

/// The pendant's own export records each capture's side: a pose whose "above" row is
/// lost is refused, naming the row of the lone "below" capture.
#[test]
fn the_pendant_export_records_the_side_and_a_lone_side_is_refused() {
    let pendant_world = zerocal_pendant_desktop::world::WorldConfig {
        seed: 14,
        ..zerocal_pendant_desktop::world::WorldConfig::default()
    };
    let (report, _) = pendant_session(pendant_world, false).expect("a whole session");
    // Saved as `zerocal pendant export` saves it: the lines as sent, LF line ends.
    let text: String = report
        .export_text()
        .lines()
        .map(|l| format!("{l}\n"))
        .collect();
    // Every plan pose captured from below, then from above.
    assert_eq!(
        report.state.captures().len(),
        zerocal_core::capture::CaptureIndex::captures_of(report.poses)
    );
    let (header, h) = line_of(&text, "j1_deg,");
    assert_eq!(h, zerocal_procedure::log::EXPORT_HEADER);
    let rows: Vec<&str> = text
        .lines()
        .skip(header)
        .take(zerocal_core::capture::CaptureIndex::captures_of(
            report.poses,
        ))
        .collect();
    for (i, r) in rows.iter().enumerate() {
        let side = if i % 2 == 0 { ",below" } else { ",above" };
        // The side, then the pose's index in the plan: two captures a pose.
        assert!(r.ends_with(&format!("{side},{}", i / 2)), "row {i}: {r}");
    }
    let out = session(&write("pendant.csv", text.as_bytes()), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The third pose's "above" row dropped, and the end trailer with it (which would
    // refuse the edit first: lines lost): the rule for one side is what is shown.
    let edited: String = text
        .replace(&format!("{}\n", rows[5]), "")
        .lines()
        .filter(|l| !l.starts_with(zerocal_procedure::export_trailer::TRAILER_PREFIX))
        .map(|l| format!("{l}\n"))
        .collect();
    refused(
        "lone.csv",
        &edited,
        &[&format!("line {}", header + 5), "captured only from below"],
    );
}

/// The pendant's whole session (its own tasks on the desktop) exported, its end trailer dropped (so an edit
/// is read, not refused as damage), and the line of its header.
fn pendant_export_text() -> (String, usize) {
    let pendant_world = zerocal_pendant_desktop::world::WorldConfig {
        seed: 14,
        ..zerocal_pendant_desktop::world::WorldConfig::default()
    };
    let (report, _) = pendant_session(pendant_world, false).expect("a whole session");
    let mut text = String::new();
    for line in report.export_text().lines() {
        if !line.starts_with(zerocal_procedure::export_trailer::TRAILER_PREFIX) {
            text.push_str(line);
            text.push('\n');
        }
    }
    let (header, _) = line_of(&text, "j1_deg,");
    (text, header)
}

/// Each joint's offset (deg) `zerocal session --json` finds in `text`.
fn offsets_deg(name: &str, text: &str) -> Vec<f64> {
    let out = session(&write(name, text.as_bytes()), &[]);
    assert!(
        out.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    (0..5)
        .map(|k| v["joints"][k]["offset_deg"].as_f64().unwrap())
        .collect()
}

/// `row` with its joint 3 (the third field) changed in its last written digit.
fn last_digit_changed(row: &str) -> String {
    let mut fields: Vec<String> = row.split(',').map(str::to_owned).collect();
    let j3 = &mut fields[2];
    let last = j3.pop().unwrap().to_digit(10).unwrap();
    j3.push(char::from_digit((last + 1) % 10, 10).unwrap());
    fields.join(",")
}

#[test]
fn a_pose_s_captures_pair_by_index_though_their_joints_differ_in_the_last_digit() {
    let (text, header) = pendant_export_text();
    let rows: Vec<&str> = text.lines().skip(header).take(24).collect();
    let exact = offsets_deg("exact.csv", &text);
    // The third pose's "above" capture with its joint 3 a digit (1e-12 deg) off.
    let nudged_row = last_digit_changed(rows[5]);
    assert_ne!(nudged_row, rows[5]);
    let nudged = text.replace(rows[5], &nudged_row);
    // 1e-12 deg on one joint of one capture moves no offset by more than 1e-9 deg
    // (the fit's sensitivity to a joint is of order one); a pose split in two by the
    // nudge would move them by its backlash, far more, or be refused as one-sided.
    for (k, (a, b)) in exact
        .iter()
        .zip(offsets_deg("nudged.csv", &nudged))
        .enumerate()
    {
        assert!((a - b).abs() <= 1e-9, "j{}: {a} vs {b}", k + 2);
    }
    // Without the pose column the rows pair by joints, as a plain log's do: the
    // nudged capture is a pose of its own, and so is its partner, captured only from
    // below (the first of the two refused).
    let without_pose: String = nudged
        .lines()
        .map(|l| {
            let l = if l == zerocal_procedure::log::EXPORT_HEADER {
                l.trim_end_matches(",pose")
            } else if !l.starts_with('#') && (l.contains(",below,") || l.contains(",above,")) {
                l.rsplit_once(',').map_or(l, |(head, _)| head)
            } else {
                l
            };
            format!("{l}\n")
        })
        .collect();
    refused(
        "by_joints.csv",
        &without_pose,
        &[&format!("line {}", header + 5), "captured only from below"],
    );
}

#[test]
fn a_pose_index_out_of_the_plan_or_a_side_given_twice_is_refused_by_name() {
    let (text, header) = pendant_export_text();
    let rows: Vec<&str> = text.lines().skip(header).take(24).collect();
    // The third pose's "above" row given the fourth pose's index, which has its own.
    let twice = rows[5].rsplit_once(',').unwrap().0.to_owned() + ",3";
    refused(
        "twice.csv",
        &text.replace(rows[5], &twice),
        &[
            &format!("line {}", header + 8),
            "pose 3 captured from above again",
            &format!("first on line {}", header + 6),
        ],
    );
    let beyond = rows[5].rsplit_once(',').unwrap().0.to_owned() + ",200";
    refused(
        "beyond.csv",
        &text.replace(rows[5], &beyond),
        &[&format!("line {}: pose is not a pose index", header + 6)],
    );
}

/// A column the export does not have (`j7_deg`) is refused by name, not ignored.
#[test]
fn an_unknown_column_is_refused_by_name() {
    let text = simulated(&WorldConfig::real(), 36).export_text("kuka-kr6-r900-sixx");
    let (header, h) = line_of(&text, "j1_deg,");
    let mut edited = String::new();
    for (i, l) in text.lines().enumerate() {
        edited.push_str(l);
        if i + 1 == header {
            edited.push_str(",j7_deg");
        } else if i + 1 > header {
            edited.push_str(",0");
        }
        edited.push('\n');
    }
    assert!(edited.contains(&format!("{h},j7_deg")));
    refused(
        "j7.csv",
        &edited,
        &[&format!("line {header}"), "unknown column 'j7_deg'"],
    );
}

/// A byte-order mark (some editors write one) is dropped: the same offsets as without.
/// A Latin-1 byte is named by line and byte.
#[test]
fn a_byte_order_mark_is_dropped_and_non_utf8_is_named() {
    let text = simulated(&WorldConfig::real(), 37).export_text("kuka-kr6-r900-sixx");
    let plain = session(&write("plain.csv", text.as_bytes()), &[]);
    let mut bom = b"\xEF\xBB\xBF".to_vec();
    bom.extend_from_slice(text.as_bytes());
    let with_bom = session(&write("bom.csv", &bom), &[]);
    assert!(
        with_bom.status.success(),
        "{}",
        String::from_utf8_lossy(&with_bom.stderr)
    );
    assert_eq!(plain.stdout, with_bom.stdout);
    // "# Messung Ü" in Latin-1 (0xDC) on a new line 2, after the 10 bytes "# Messung ".
    let mut latin1 = b"# zerocal export\n# Messung \xDC\n".to_vec();
    latin1.extend_from_slice(text.as_bytes());
    let out = session(&write("latin1.csv", &latin1), &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("line 2, byte 11") && err.contains("not UTF-8"),
        "{err}"
    );
}

/// Another robot's profile is refused by name before solving.
#[test]
fn another_robots_profile_is_refused_by_name() {
    let text = simulated(&WorldConfig::real(), 38).export_text("kuka-kr6-r900-sixx");
    let out = session(
        &write("robot.csv", text.as_bytes()),
        &["--robot", "abb-irb140"],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("export is for robot kuka-kr6-r900-sixx, --robot says abb-irb140"),
        "{err}"
    );
}

/// The report gives the pendant's own Δθ and 1σ (its screen's) only where this re-solve
/// agrees with them: a result line that no longer fits its readings is not believed,
/// and the report says by how much it differs.
#[test]
fn the_pendant_s_own_numbers_are_reported_only_where_the_re_solve_agrees() {
    let (text, _) = pendant_export_text();
    let notes = |name: &str, text: &str| -> (Vec<f64>, String) {
        let out = session(&write(name, text.as_bytes()), &[]);
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let offsets = (0..5)
            .map(|k| v["joints"][k]["offset_deg"].as_f64().unwrap())
            .collect();
        (offsets, v["notes"].to_string())
    };
    let pendant = zerocal_procedure::log::read_pendant_result(&text).expect("a result line");
    let (offsets, said) = notes("own.csv", &text);
    assert!(said.contains("are the pendant's own"), "{said}");
    // Its own, through radians and back: equal to the last bits of an f64.
    for (got, want) in offsets.iter().zip(pendant.offsets_deg) {
        assert!(
            (got - want).abs() < 1e-12,
            "{offsets:?} against {:?}",
            pendant.offsets_deg
        );
    }
    // Δθ4 on the result line moved by 0.001°: the readings do not give it.
    let line = text
        .lines()
        .find(|l| l.starts_with("# stage2 offsets_deg "))
        .unwrap();
    let list = line.split_whitespace().nth(3).unwrap();
    let mut values: Vec<f64> = list.split(',').map(|v| v.parse().unwrap()).collect();
    values[1] += 0.001;
    let moved: Vec<String> = values.iter().map(|v| format!("{v:.12}")).collect();
    let edited = text.replace(list, &moved.join(","));
    let (offsets, said) = notes("moved.csv", &edited);
    assert!(said.contains("differs from this re-solve"), "{said}");
    assert!(
        (offsets[2] - pendant.offsets_deg[2]).abs() < 1e-5,
        "{offsets:?}"
    );
    // Δθ5's 1σ on the result line 2 % larger: beyond the 1 % agreement.
    let sigmas = line.split_whitespace().nth(5).unwrap();
    let mut values: Vec<f64> = sigmas.split(',').map(|v| v.parse().unwrap()).collect();
    values[2] *= 1.02;
    let grown: Vec<String> = values.iter().map(|v| format!("{v:.12}")).collect();
    let (_, said) = notes("sigma.csv", &text.replace(sigmas, &grown.join(",")));
    assert!(said.contains("differs from this re-solve"), "{said}");
}
