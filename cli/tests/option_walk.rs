//! Every numeric option of every subcommand, walked through the values that break
//! careless parsers: 0, a negative, 1e308, NaN and ±inf; the negatives both as
//! `--flag=-1` and as two arguments `--flag -1`.
//!
//! The valid range of each option is read back from its `--help` (`Range: [a, b]`, as
//! `zerocal_inputs::args` states it), so the help, the parser and this test cannot drift
//! apart. Outside the range the binary must exit 2 with a message naming the option and
//! the range; inside it, 0 (numbers) or 3 (refused, with a message). Never a panic
//! (exit 101), a signal or a hang.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The values each option is walked through.
const WALK: [&str; 6] = ["0", "-1", "1e308", "NaN", "inf", "-inf"];

/// No run of the CLI on these small inputs takes more than a few seconds; a run past
/// this is a hang.
const HANG: Duration = Duration::from_secs(120);

struct Run {
    code: Option<i32>,
    stderr: String,
}

fn zerocal(args: &[String]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start zerocal");
    let mut stderr_pipe = child.stderr.take().expect("piped stderr");
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stderr_pipe.read_to_string(&mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for zerocal") {
            break status;
        }
        if start.elapsed() > HANG {
            let _ = child.kill();
            panic!("zerocal {args:?} hung (killed after {} s)", HANG.as_secs());
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Run {
        code: status.code(),
        stderr: reader.join().unwrap_or_default(),
    }
}

/// A stated range: `[lo, hi]`, `(lo, hi]` and so on.
#[derive(Debug)]
struct Stated {
    lo: f64,
    lo_open: bool,
    hi: f64,
    hi_open: bool,
    integer: bool,
    pair: bool,
    text: String,
}

impl Stated {
    fn accepts(&self, v: &str) -> bool {
        let Ok(x) = v.parse::<f64>() else {
            return false;
        };
        if self.integer && (x.fract() != 0.0 || v.contains('e') || v.contains('.')) {
            return false;
        }
        let lo_ok = if self.lo_open {
            x > self.lo
        } else {
            x >= self.lo
        };
        let hi_ok = if self.hi_open {
            x < self.hi
        } else {
            x <= self.hi
        };
        lo_ok && hi_ok
    }
}

/// Parses `Range: [a, b] unit` (or `Range: each [a, b] unit` for `X,Y` pairs).
fn parse_range(text: &str) -> Option<Stated> {
    let rest = text.split("Range: ").nth(1)?;
    let (pair, rest) = match rest.strip_prefix("each ") {
        Some(r) => (true, r),
        None => (false, rest),
    };
    let open = rest.chars().next()?;
    let close_at = rest.find([']', ')'])?;
    let inner = &rest[1..close_at];
    let close = rest[close_at..].chars().next()?;
    let (lo, hi) = inner.split_once(',')?;
    let (lo, hi) = (lo.trim(), hi.trim());
    Some(Stated {
        lo: lo.parse().ok()?,
        lo_open: open == '(',
        hi: hi.parse().ok()?,
        hi_open: close == ')',
        integer: !lo.contains('.') && !hi.contains('.') && !rest[close_at..].contains("deg"),
        pair,
        text: format!("{open}{lo}, {hi}{close}"),
    })
}

/// Value names of options that take text, not a number.
const TEXT_VALUES: [&str; 14] = [
    "<SN>",
    "<DAY>",
    "<J=DEG>",
    "<MODEL=DAYS>",
    "<DEG,DEG,DEG,DEG,DEG>",
    "<FILE>",
    "<PORT>",
    "<DIR>",
    "<PATH>",
    "<NAME>",
    "<NAMES>",
    "<SOURCES>",
    "<PATH|URL>",
    "<ADDR:PORT>",
];

/// `(flag line, its help text)` for every option of a subcommand, from its `--help`.
fn options(subcommand: &str) -> Vec<(String, String)> {
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args([subcommand, "--help"])
        .output()
        .expect("zerocal --help");
    assert_eq!(out.status.code(), Some(0), "{subcommand} --help");
    let help = String::from_utf8_lossy(&out.stdout).into_owned();
    let mut found: Vec<(String, String)> = Vec::new();
    for line in help.lines() {
        let t = line.trim_start();
        let starts_option = t.starts_with("--") || (t.starts_with('-') && t.contains(", --"));
        if starts_option {
            // Short help sits on the flag's own line; long help follows it.
            found.push((t.to_owned(), t.to_owned()));
        } else if let Some((_, text)) = found.last_mut() {
            text.push(' ');
            text.push_str(t);
        }
    }
    found
}

/// The subcommands `zerocal --help` lists.
fn subcommands() -> Vec<String> {
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .arg("--help")
        .output()
        .expect("zerocal --help");
    let help = String::from_utf8_lossy(&out.stdout).into_owned();
    help.split("Commands:")
        .nth(1)
        .expect("a Commands: section")
        .split("Options:")
        .next()
        .unwrap_or("")
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|w| *w != "help")
        .map(str::to_owned)
        .collect()
}

/// A small, valid stage-2 log (the paper's wrist, rpy, no offsets): enough for
/// `identify` to run to numbers or a refusal, whatever the option walked.
fn sample_log() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("zerocal-option-walk-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("log.csv");
    let mut text = String::from("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n");
    let poses: [[f64; 4]; 8] = [
        [0.0, 0.0, 0.0, 0.0],
        [90.0, 3.0, -90.0, 2.0],
        [-90.0, -4.0, 90.0, 1.0],
        [180.0, 2.0, 180.0, -3.0],
        [45.0, 60.0, -45.0, -62.0],
        [-30.0, -120.0, 30.0, 118.0],
        [10.0, 170.0, 5.0, -175.0],
        [120.0, -5.0, -125.0, 4.0],
    ];
    for q in poses {
        let [a, b, c, d] = q.map(f64::to_radians);
        let r = nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::x_axis(), a)
            * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), b)
            * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::x_axis(), c)
            * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), d);
        let u = r.transpose() * nalgebra::Vector3::z();
        let x = u.y.atan2(u.z).to_degrees();
        let y = (-u.x).atan2((u.y * u.y + u.z * u.z).sqrt()).to_degrees();
        text.push_str(&format!(
            "0,0,{},{},{},{},{x:.9},{y:.9}\n",
            q[0], q[1], q[2], q[3]
        ));
    }
    std::fs::write(&path, text).expect("write log");
    path
}

/// A pendant export of a real-world simulated session on the KR 6.
fn sample_export() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("zerocal-option-walk-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("export.csv");
    let profile = zerocal_profile::builtin("kuka-kr6-r900-sixx").expect("built in");
    let world = zerocal_sim::world::WorldConfig::real();
    let session =
        zerocal_sim::world::RealSession::simulate_default_plan(&profile, &world, 5).expect("plan");
    std::fs::write(&path, session.export_text(&profile.name)).expect("write export");
    path
}

/// A history beside the walk's log holding the sample session as record 1.
fn walk_history(log: &std::path::Path) -> String {
    let db = log
        .with_file_name("walk-records.sqlite")
        .display()
        .to_string();
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args([
            "session",
            &sample_export().display().to_string(),
            "--record",
            "--serial",
            "WALK",
            "--db",
            &db,
        ])
        .output()
        .expect("zerocal session --record");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    db
}

/// The arguments that make each subcommand run at all; a new subcommand must be added
/// here, or the walk fails.
fn base_args(subcommand: &str, log: &std::path::Path) -> Vec<String> {
    match subcommand {
        "simulate" => vec!["simulate".into(), "--accuracy-points=20".into()],
        "identify" => vec![
            "identify".into(),
            "--convention=rpy".into(),
            log.display().to_string(),
        ],
        "plan" => vec!["plan".into()],
        "robots" => vec!["robots".into()],
        "session" => vec!["session".into(), sample_export().display().to_string()],
        "error-table" => vec![
            "error-table".into(),
            "--sessions=1".into(),
            "--robot=paper-wrist".into(),
        ],
        // Writes next to the walk's log; a refused value writes nothing.
        "program" => vec![
            "program".into(),
            "--robot".into(),
            "kuka-kr16".into(),
            "--format".into(),
            "krl".into(),
            "--out".into(),
            log.with_file_name("walk.src").display().to_string(),
        ],
        // No pendant on the walk's machine: the port does not open (exit 2); the walk
        // only checks its options' help.
        "pendant" => vec![
            "pendant".into(),
            "--port".into(),
            "/nonexistent/zerocal-walk".into(),
            "status".into(),
        ],
        "bracket" => vec!["bracket".into(), "--robot".into(), "ur5e".into()],
        // No numeric option of its own: only its help is walked.
        "profile" => vec!["profile".into(), "check".into(), "kuka-kr16".into()],
        // A history of its own next to the walk's log, never the user's default one.
        "history" => vec![
            "history".into(),
            "--db".into(),
            log.with_file_name("walk-history.sqlite")
                .display()
                .to_string(),
        ],
        // An address this machine does not have (TEST-NET-1, RFC 5737): the server
        // cannot listen and exits (3), so an accepted value ends the run too.
        "serve" => vec![
            "serve".into(),
            "--listen=192.0.2.1:9".into(),
            "--behind-tls-proxy".into(),
            "--db".into(),
            log.with_file_name("walk-serve.sqlite")
                .display()
                .to_string(),
        ],
        // On a history holding the sample session as record 1, checked against itself.
        "check" | "restore" | "certificate" => {
            let db = walk_history(log);
            match subcommand {
                "check" => vec![
                    "check".into(),
                    sample_export().display().to_string(),
                    "--against=1".into(),
                    "--restored".into(),
                    "--no-record".into(),
                    "--db".into(),
                    db,
                ],
                "restore" => vec![
                    "restore".into(),
                    sample_export().display().to_string(),
                    "--reference=1".into(),
                    "--db".into(),
                    db,
                ],
                _ => vec![
                    "certificate".into(),
                    "1".into(),
                    "--out".into(),
                    log.with_file_name("walk-certificate.html")
                        .display()
                        .to_string(),
                    "--config".into(),
                    concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/issuer.toml").into(),
                    "--db".into(),
                    db,
                ],
            }
        }
        other => panic!("option walk: no base invocation for the subcommand '{other}'"),
    }
}

#[test]
fn every_numeric_option_refuses_what_is_outside_its_stated_range() {
    let log = sample_log();
    let mut walked = 0;
    for sub in subcommands() {
        let base = base_args(&sub, &log);
        for (line, help) in options(&sub) {
            let flag = line
                .split_whitespace()
                .find(|w| w.starts_with("--"))
                .map(|w| w.trim_end_matches(',').to_owned())
                .unwrap_or_default();
            let Some(range) = parse_range(&help) else {
                // Only switches, files and named choices may go without a range.
                let flag_part = line.split("  ").next().unwrap_or("");
                let takes_value = flag_part.contains('<');
                let textual = TEXT_VALUES.iter().any(|v| flag_part.contains(v))
                    || help.contains("[possible values:")
                    || help.contains("Possible values:");
                assert!(
                    !takes_value || textual,
                    "zerocal {sub} {flag}: takes a value but states no `Range:` (help: {help})"
                );
                continue;
            };
            // A negative value is walked as `--flag=-1` and as two arguments
            // `--flag -1`: both must reach the range check, not clap's unknown flag.
            let forms = WALK.iter().flat_map(|v| {
                [(*v, false)]
                    .into_iter()
                    .chain(v.starts_with('-').then_some((*v, true)))
            });
            for (v, separate) in forms {
                let value = if range.pair {
                    format!("{v},{v}")
                } else {
                    v.to_owned()
                };
                let mut args = base.clone();
                args.retain(|a| !a.starts_with(&format!("{flag}=")));
                if separate {
                    args.push(flag.clone());
                    args.push(value);
                } else {
                    args.push(format!("{flag}={value}"));
                }
                let run = zerocal(&args);
                walked += 1;
                let code = run.code;
                assert!(
                    matches!(code, Some(0 | 2 | 3)),
                    "zerocal {args:?}: exit {code:?} (panic or signal); stderr:\n{}",
                    run.stderr
                );
                if range.accepts(v) {
                    assert_ne!(
                        code,
                        Some(2),
                        "zerocal {args:?}: {v} is inside the stated range {} but was refused:\n{}",
                        range.text,
                        run.stderr
                    );
                } else {
                    assert_eq!(
                        code,
                        Some(2),
                        "zerocal {args:?}: {v} is outside the stated range {}; stderr:\n{}",
                        range.text,
                        run.stderr
                    );
                    assert!(
                        run.stderr.contains(&flag) && run.stderr.contains(&range.text),
                        "zerocal {args:?}: the message must name {flag} and {}:\n{}",
                        range.text,
                        run.stderr
                    );
                }
                if code == Some(3) {
                    assert!(
                        run.stderr.contains("refused"),
                        "zerocal {args:?}: exit 3 without a message:\n{}",
                        run.stderr
                    );
                }
            }
        }
    }
    // simulate 6, identify 5, plan 10, program 3 numeric options at the time of
    // writing.
    assert!(
        walked >= 24 * (WALK.len() + 2),
        "only {walked} runs: options lost?"
    );
}

#[test]
fn ranges_are_read_from_help() {
    let r = parse_range("Stage-2 poses. Range: [4, 10000].").expect("integer");
    assert!(r.integer && r.accepts("4") && !r.accepts("3") && !r.accepts("4.5"));
    let r = parse_range("noise. Range: (0, 1] deg.").expect("real");
    assert!(!r.integer && !r.accepts("0") && r.accepts("1") && !r.accepts("NaN"));
    let r = parse_range("tilt. Range: each [-10, 10] deg.").expect("pair");
    assert!(r.pair && r.accepts("-1") && !r.accepts("inf"));
}
