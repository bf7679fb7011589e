//! What `zerocal plan` and `zerocal program --check` promise before the robot moves,
//! and the worked examples of a session (`zerocal simulate --export`, then `zerocal
//! session` on it).

use anyhow::{anyhow, bail, Result};

use super::{fenced, line_starting, word_after, Figure};
use crate::figures::sources::Sources;

/// The KR 6 R900 sixx: the worked example and the README's robot.
const KR6: &str = "kuka-kr6-r900-sixx";

/// `zerocal plan --robot R`'s output.
fn plan(s: &mut Sources, robot: &str) -> Result<String> {
    s.zerocal(&["plan", "--robot", robot])
}

/// The built-in profiles, as `zerocal robots` lists them.
fn robots(s: &mut Sources) -> Result<Vec<String>> {
    let list = s.zerocal(&["robots"])?;
    Ok(list
        .lines()
        .filter(|l| !l.starts_with("your own"))
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_owned)
        .collect())
}

/// The planned readings' window, `±6.00°`.
pub const PLAN_WINDOW: Figure = Figure {
    name: "plan-window",
    command: "zerocal plan --robot kuka-kr6-r900-sixx (its first line)",
    make: |s| {
        let out = plan(s, KR6)?;
        let first = out.lines().next().unwrap_or_default();
        Ok(format!("±{}°", word_after(first, "within +/-")?))
    },
};

/// `--margin-deg`'s default, `4°`.
pub const PLAN_MARGIN: Figure = Figure {
    name: "plan-margin",
    command: "zerocal plan --help (--margin-deg's default)",
    make: |s| {
        let help = s.zerocal(&["plan", "--help"])?;
        let margin = help
            .split("--margin-deg")
            .nth(1)
            .ok_or_else(|| anyhow!("no --margin-deg in plan --help"))?;
        Ok(format!(
            "{}°",
            word_after(margin, "[default: ")?.trim_end_matches(']')
        ))
    },
};

/// The KR 6's promise: predicted k = 2, correlations, robot time.
pub const PLAN_KR6_SUMMARY: Figure = Figure {
    name: "plan-kr6-summary",
    command: "zerocal plan --robot kuka-kr6-r900-sixx",
    make: |s| {
        let out = plan(s, KR6)?;
        let lines = [
            line_starting(&out, "predicted k=2")?,
            line_starting(&out, "worst correlation")?,
            line_starting(&out, "robot time")?,
        ];
        Ok(fenced(
            &format!("zerocal plan --robot {KR6}"),
            &format!("...\n{}", lines.join("\n")),
        ))
    },
};

/// The KR 16-2's plan, its poses left out.
pub const PLAN_KR16: Figure = Figure {
    name: "plan-kr16",
    command: "zerocal plan --robot kuka-kr16",
    make: |s| {
        let out = plan(s, "kuka-kr16")?;
        let head: Vec<&str> = out.lines().take(2).collect();
        let from = out
            .find("stage 2 alone")
            .ok_or_else(|| anyhow!("no 'stage 2 alone' line"))?;
        Ok(fenced(
            "zerocal plan --robot kuka-kr16",
            &format!("{}\n...\n{}", head.join("\n"), &out[from..]),
        ))
    },
};

/// Every built-in profile's default plan: poses, predicted k = 2, robot time.
pub const PLAN_PER_PROFILE: Figure = Figure {
    name: "plan-per-profile",
    command: "zerocal plan --robot R, for each R of zerocal robots",
    make: |s| {
        let mut table = String::from(
            "| robot | poses | predicted k = 2, j2 j3 j4 j5 j6 (°) | condition number | robot time |\n\
             | --- | --- | --- | --- | --- |\n",
        );
        for robot in robots(s)? {
            let run = s.zerocal_run(&["plan", "--robot", &robot])?;
            if run.status != Some(0) {
                let why = run.stderr.trim().trim_start_matches("zerocal: ");
                table.push_str(&format!("| `{robot}` | refused: {why} | | | |\n"));
                continue;
            }
            let out = run.stdout;
            let first = out.lines().next().unwrap_or_default();
            let poses = first.split_whitespace().next().unwrap_or_default();
            let k2: Vec<&str> = line_starting(&out, "predicted k=2")?
                .split_whitespace()
                .filter(|w| w.starts_with("0.") || *w == "-")
                .collect();
            let condition = word_after(line_starting(&out, "condition number")?, "number ")?;
            let time = line_starting(&out, "robot time")?;
            let minutes = word_after(time, "robot time ")?;
            table.push_str(&format!(
                "| `{robot}` | {poses} | {} | {condition} | {minutes} min |\n",
                k2.join(" ")
            ));
        }
        Ok(table)
    },
};

/// The refusal of a target no plan reaches.
pub const PLAN_TARGET_REFUSED: Figure = Figure {
    name: "plan-target-refused",
    command: "zerocal plan --robot kuka-kr16 --target-k2-deg 0.005",
    make: |s| {
        let args = ["plan", "--robot", "kuka-kr16", "--target-k2-deg", "0.005"];
        let run = s.zerocal_run(&args)?;
        if run.status == Some(0) {
            bail!("zerocal {} was not refused", args.join(" "));
        }
        Ok(fenced(
            &format!("zerocal {}", args.join(" ")),
            &format!("{}(exit status {})", run.stderr, run.status.unwrap_or(-1)),
        ))
    },
};

/// The robot time of `robot`'s default plan, `8.3 min`.
fn robot_time(s: &mut Sources, robot: &str) -> Result<String> {
    let out = plan(s, robot)?;
    Ok(format!(
        "{} min",
        word_after(line_starting(&out, "robot time")?, "robot time ")?
    ))
}

/// The KR 6's robot time.
pub const ROBOT_TIME_KR6: Figure = Figure {
    name: "robot-time-kr6",
    command: "zerocal plan --robot kuka-kr6-r900-sixx (robot time)",
    make: |s| robot_time(s, KR6),
};

/// The KR 16-2's robot time.
pub const ROBOT_TIME_KR16: Figure = Figure {
    name: "robot-time-kr16",
    command: "zerocal plan --robot kuka-kr16 (robot time)",
    make: |s| robot_time(s, "kuka-kr16"),
};

/// The robot time a default session aims at (min, at 10 % speed): core's.
const ROBOT_TIME_AIM_MIN: f64 = zerocal_core::plan::ROBOT_TIME_AIM_S / 60.0;

/// The built-in profiles whose default plan takes longer than [`ROBOT_TIME_AIM_MIN`],
/// with their times: "`ur5e` (12.8 min) and `puma560` (16.2 min)", or "none".
pub const ROBOT_TIME_OVER: Figure = Figure {
    name: "robot-time-over",
    command: "zerocal plan --robot R (robot time), for each R of zerocal robots",
    make: |s| {
        let mut over = Vec::new();
        for robot in robots(s)? {
            let time = robot_time(s, &robot)?;
            let minutes: f64 = time
                .trim_end_matches(" min")
                .parse()
                .map_err(|e| anyhow!("{robot}: robot time {time:?}: {e}"))?;
            if minutes > ROBOT_TIME_AIM_MIN {
                over.push(format!("`{robot}` ({time})"));
            }
        }
        Ok(match over.as_slice() {
            [] => "none".to_owned(),
            [one] => one.clone(),
            [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
        })
    },
};

/// The check program's format of each family, and a profile for the one whose program
/// needs what no built-in profile has (INFORM's pulses per degree).
fn check_program(robot: &str) -> (&'static str, Option<&'static str>) {
    match robot.split('-').next().unwrap_or_default() {
        "abb" => ("rapid", None),
        "fanuc" => ("tp", None),
        "yaskawa" if robot == "yaskawa-gp7" => {
            ("inform", Some("cli/tests/golden/yaskawa-gp7-pulses.toml"))
        }
        "yaskawa" => ("inform", None),
        "staubli" => ("val3", None),
        "ur5e" => ("urscript", None),
        _ => ("krl", None),
    }
}

/// Every profile's check: the program's run and the whole with the two mountings.
pub const CHECK_TIME_PER_PROFILE: Figure = Figure {
    name: "check-time-per-profile",
    command: "zerocal program --check --robot R --format F --out target/figures/check-R, for each R of zerocal robots",
    make: |s| {
        let mut table = String::from(
            "| profile | program's run | with the two mountings |\n| --- | --- | --- |\n",
        );
        s.scratch()?;
        for robot in robots(s)? {
            let (format, profile) = check_program(&robot);
            let out = format!("target/figures/check-{robot}");
            let name = profile.unwrap_or(&robot);
            let run = s.zerocal_run(&[
                "program", "--check", "--robot", name, "--format", format, "--out", &out,
            ])?;
            let shown = match profile {
                Some(p) => format!("{robot} (`{p}`: its pulses per degree)"),
                None => robot.clone(),
            };
            if run.status != Some(0) {
                let why = run.stderr.trim().trim_start_matches("zerocal: ");
                let why = why.split(" (").next().unwrap_or(why);
                table.push_str(&format!("| {shown} | {why} | |\n"));
                continue;
            }
            let line = line_starting(&run.stdout, "Predicted robot time")?;
            let whole = word_after(line, "robot time ")?;
            let program = word_after(line, "the program's run ")?;
            table.push_str(&format!("| {shown} | {program} min | {whole} min |\n"));
        }
        Ok(table)
    },
};

/// A simulated session's export, written under target/figures, and `zerocal session`
/// on it.
fn session_of(s: &mut Sources, robot: &str, seed: &str) -> Result<(String, String)> {
    s.scratch()?;
    let export = format!("target/figures/{robot}-{seed}.export");
    s.zerocal(&[
        "simulate", "--robot", robot, "--seed", seed, "--export", &export,
    ])?;
    let report = s.zerocal(&["session", &export])?;
    Ok((export, report))
}

/// The KR 6's worked example: the report's offsets, the controller's terms and the
/// verdict.
pub const SESSION_KR6_EXAMPLE: Figure = Figure {
    name: "session-kr6-example",
    command: "zerocal simulate --robot kuka-kr6-r900-sixx --seed 3 --export kr6.export; zerocal session kr6.export",
    make: |s| {
        let (_, report) = session_of(s, KR6, "3")?;
        let lines: Vec<&str> = report.lines().collect();
        // The summary line, the columns' line and j2..j6.
        let head: Vec<&str> = lines.iter().take(7).copied().collect();
        let terms = lines
            .iter()
            .position(|l| l.starts_with("in the controller's terms"))
            .ok_or_else(|| anyhow!("no controller's terms in the report"))?;
        let verdict = lines
            .iter()
            .position(|l| l.starts_with("verdict:"))
            .ok_or_else(|| anyhow!("no verdict in the report"))?;
        Ok(format!(
            "```text\n$ zerocal simulate --robot {KR6} --seed 3 --export kr6.export\n\
             $ zerocal session kr6.export\n{}\n...\n{}\n...\n```\n",
            head.join("\n"),
            lines[terms..=verdict].join("\n")
        ))
    },
};

/// The IRB 140's joint 2, in the session's table and the controller's terms.
pub const SESSION_IRB140_EXAMPLE: Figure = Figure {
    name: "session-irb140-example",
    command: "zerocal simulate --robot abb-irb140 --seed 4 --export irb.export; zerocal session irb.export",
    make: |s| {
        let (_, report) = session_of(s, "abb-irb140", "4")?;
        Ok(format!(
            "```text\n$ zerocal simulate --robot abb-irb140 --seed 4 --export irb.export\n\
             $ zerocal session irb.export\n...\n{}\n...\n{}\n...\n```\n",
            line_starting(&report, "j2 ")?,
            line_starting(&report, "J2 ")?
        ))
    },
};

/// `zerocal robots`' first two lines.
pub const ROBOTS_EXAMPLE: Figure = Figure {
    name: "robots-example",
    command: "zerocal robots",
    make: |s| {
        let out = s.zerocal(&["robots"])?;
        let head: Vec<&str> = out.lines().take(2).collect();
        Ok(fenced(
            "zerocal robots",
            &format!("{}\n...", head.join("\n")),
        ))
    },
};

/// What the KR 6's worked example enters in `$MAMES` for A2 and A3.
pub const SESSION_KR6_MAMES: Figure = Figure {
    name: "session-kr6-mames",
    command: "zerocal session kr6.export (the worked example's dq of A2 and A3)",
    make: |s| {
        let (_, report) = session_of(s, KR6, "3")?;
        let unit = |joint: &str| -> Result<String> {
            let line = line_starting(&report, &format!("{joint} "))?;
            line.split_whitespace()
                .nth(1)
                .map(str::to_owned)
                .ok_or_else(|| anyhow!("no value in its unit: {line}"))
        };
        let (a2, a3) = (unit("A2")?, unit("A3")?);
        let plain = |v: &str| v.trim_start_matches('+').to_owned();
        Ok(format!(
            "`$MAMES[2]` += {}, `$MAMES[3]` += {}",
            plain(&a2),
            plain(&a3)
        ))
    },
};

/// The README's main job on its own robot: `zerocal simulate`'s U(k = 2) per joint,
/// `j2 0.0087°, j3 …` (the "before" beside it, from before the reducers were fitted, is quoted, not made).
pub const SIMULATE_U_KR6: Figure = Figure {
    name: "simulate-u-kr6",
    command: "zerocal simulate (the U(k=2) column)",
    make: |s| {
        let out = s.zerocal(&["simulate"])?;
        let mut parts = Vec::new();
        for joint in ["j2", "j3", "j4", "j5", "j6"] {
            let row = super::rows(&out, &[joint]);
            let fields = row
                .first()
                .ok_or_else(|| anyhow!("zerocal simulate printed no {joint} row"))?;
            // joint found truth error 1sigma U(k=2) |error|/U
            let u = fields
                .get(5)
                .ok_or_else(|| anyhow!("zerocal simulate's {joint} row has no U(k=2)"))?;
            let u = super::number(u)?;
            parts.push(format!("{joint} {u:.4}"));
        }
        Ok(format!("{}°", parts.join(", ")))
    },
};
