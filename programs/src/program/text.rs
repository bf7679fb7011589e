//! Text every writer shares: the program's name from the output path, the header
//! saying what the program does, the UTC stamp some headers carry, and message text
//! cut to a controller's line length.

use super::Format;
use crate::robot_time::SessionTime;
use crate::timing::Timing;
use std::path::Path;
use zerocal_civil::Timestamp;
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// A program's name from the output path: letters, digits and `_`, upper case,
/// starting with a letter, at most `max` characters; `ZEROCAL` if nothing is left.
pub fn program_name(out: &Path, max: usize) -> String {
    let stem = out
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut name: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .skip_while(|c| !c.is_ascii_alphabetic())
        .take(max)
        .collect();
    while name.ends_with('_') {
        name.pop();
    }
    if name.is_empty() {
        name = "ZEROCAL".chars().take(max).collect();
    }
    name
}

/// Now, for the headers that carry a date and time (TP, INFORM): `SOURCE_DATE_EPOCH`
/// (seconds since 1970, the reproducible-builds convention) if set, else the clock.
///
/// # Errors
/// `SOURCE_DATE_EPOCH` set to anything but seconds since 1970 (status 2): a
/// reproducible program asked for is not written with the clock's time instead.
pub fn stamp() -> Result<Timestamp, CliError> {
    Timestamp::now().map_err(|e| CliError::Input(e.to_string()))
}

/// Splits `text` into pieces of at most `max` characters at spaces where it can.
///
/// Linear in the text: each character is looked at a fixed number of times (a word
/// longer than `max` is cut as it is read, never re-counted).
pub fn pieces(text: &str, max: usize) -> Vec<String> {
    let max = max.max(1);
    let mut out = Vec::new();
    let mut line = String::new();
    let mut line_chars = 0;
    for word in text.split_whitespace() {
        let word_chars = word.chars().count();
        if word_chars > max {
            if !line.is_empty() {
                out.push(std::mem::take(&mut line));
            }
            let mut head = String::new();
            let mut head_chars = 0;
            for c in word.chars() {
                if head_chars == max {
                    out.push(std::mem::take(&mut head));
                    head_chars = 0;
                }
                head.push(c);
                head_chars += 1;
            }
            // The word's tail starts the next line.
            line = head;
            line_chars = head_chars;
        } else if line.is_empty() {
            line.push_str(word);
            line_chars = word_chars;
        } else if line_chars + 1 + word_chars <= max {
            line.push(' ');
            line.push_str(word);
            line_chars += 1 + word_chars;
        } else {
            out.push(std::mem::replace(&mut line, word.to_owned()));
            line_chars = word_chars;
        }
    }
    if !line.is_empty() {
        out.push(line);
    }
    out
}

/// The header's lines: what the program does, its speed and dwells, the predicted
/// robot time and the collision warning. `poses` is the number of stage-2 poses, `j1`
/// joint 1's name.
pub fn header_lines(
    profile: &Profile,
    format: Format,
    timing: &Timing,
    time: &SessionTime<f64>,
    poses: usize,
    j1: &str,
) -> Vec<String> {
    let (t, tm, n) = (timing, &timing.model, poses);
    let dwell = tm.dwell_s();

    let unit = match format {
        Format::Urscript => "radians".to_owned(),
        Format::Inform => "pulses (joint degrees x the profile's pulses per degree)".to_owned(),
        _ => "degrees".to_owned(),
    };
    vec![
        "zerocal robot program: a joint-zero calibration session.".to_owned(),
        format!(
            "Robot {} (profile {}); {n} stage-2 poses. Written by zerocal {}; targets in the controller's joint {unit}.",
            profile.title,
            profile.name,
            env!("CARGO_PKG_VERSION")
        ),
        format!(
            "Every pose is captured twice: first with every joint arriving moving positive (from {} deg below), then, after every joint has gone {} deg past it, moving negative (from above). The pendant averages the two: the middle of every gear's backlash.",
            tm.approach_deg, tm.overshoot_deg
        ),
        format!(
            "Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its range, so it cannot capture early). Stage 1: the stage-1 pose twice, then {j1} turned by 180 deg twice (an OK on the pendant arms the first). Stop: move the pendant to the flange (tilted again). Stage 2: the plan's poses in its order, twice each; load the same plan into the pendant (plan set)."
        ),
        format!(
            "Closing bench readings: the robot parks where the pendant went on the flange and stops; take the pendant off and continue: the program ends there and the robot is free. Then read the pendant on the bench as in stage 0 ({} headings, turned by hand about a quarter turn on the same spot between them).",
            zerocal_procedure::BENCH_HEADINGS
        ),
        format!(
            "Speed: joint moves at {} % of each joint's maximum speed, exact stops.",
            t.speed_percent
        ),
        format!(
            "Dwell {dwell:.1} s at each capture: settling {} s (stated default) + the pendant's {} s still window + 2 sensor periods of {} s.",
            tm.settle_s, tm.window_s, tm.sample_period_s
        ),
        format!(
            "Predicted robot time {:.1} min, until the pendant is off the flange: motion {:.0} s, dwell {:.0} s ({} captures), {} mountings {:.0} s, operator OKs {:.0} s; then the closing bench readings, {:.0} s, the robot free.",
            time.total_s / 60.0,
            time.motion_s,
            time.dwell_s,
            time.captures,
            time.mountings,
            time.remount_s,
            time.operator_s,
            time.closing_s
        ),
        "WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check the cell, then step through the program once at reduced speed (T1) before running it.".to_owned(),
    ]
}

/// The header of a check's program: what it does (the flange, the check's poses of the
/// plan, the closing bench readings; no stage 1), the speed, the dwell, the predicted robot
/// time and the collision warning. `plan_index` are the check's poses in the session
/// plan of `plan_len` poses.
pub fn check_header_lines(
    profile: &Profile,
    format: Format,
    timing: &Timing,
    time: &SessionTime<f64>,
    plan_index: &[usize],
    plan_len: usize,
) -> Vec<String> {
    let session = header_lines(profile, format, timing, time, plan_index.len(), "");
    let shown: Vec<String> = plan_index.iter().map(|i| (i + 1).to_string()).collect();
    let mut lines = vec![
        "zerocal robot program: a check of the offsets entered after a calibration session.".to_owned(),
        format!(
            "Robot {} (profile {}); {} of the session plan's {plan_len} poses ({}), at the session's commanded angles. Written by zerocal {}.",
            profile.title,
            profile.name,
            plan_index.len(),
            shown.join(", "),
            env!("CARGO_PKG_VERSION")
        ),
    ];
    // The capture scheme's line as the session's header words it.
    lines.extend(session.get(2).cloned());
    lines.push(
        "Before it: stage 0 on the bench (the pendant's check mode starts there). Stop: clip the pendant to the flange (the robot stands with the pendant tilted past its range, so it cannot capture early). Then the check's poses in the plan's order, twice each; the pendant must hold the same plan as the session (plan set). No stage 1.".to_owned(),
    );
    lines.extend(session.into_iter().skip(4));
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_pieces() {
        assert_eq!(program_name(Path::new("out/zc-kr16.src"), 24), "ZC_KR16");
        assert_eq!(program_name(Path::new("9lives.jbi"), 8), "LIVES");
        assert_eq!(
            program_name(Path::new("calibration_session.ls"), 8),
            "CALIBRAT"
        );
        assert_eq!(program_name(Path::new("___.ls"), 8), "ZEROCAL");
        assert_eq!(
            pieces("press OK on the pendant, then continue", 10),
            ["press OK", "on the", "pendant,", "then", "continue"]
        );
        assert_eq!(pieces("abcdefghijkl", 5), ["abcde", "fghij", "kl"]);
        for p in pieces(&"word ".repeat(40), 20) {
            assert!(p.chars().count() <= 20);
        }
        assert_eq!(pieces("ab abcdefgh x", 3), ["ab", "abc", "def", "gh", "x"]);
        // Ten million characters in one word (a long name): linear, so well under a
        // second where the quadratic cut took minutes; nothing lost.
        let long = "k".repeat(10_000_000);
        let start = std::time::Instant::now();
        let cut = pieces(&long, 60);
        assert!(start.elapsed().as_secs_f64() < 5.0, "{:?}", start.elapsed());
        assert_eq!(cut.concat(), long);
        assert!(cut.iter().all(|p| p.chars().count() <= 60));
    }
}
