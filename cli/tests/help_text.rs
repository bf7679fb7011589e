//! What `--help` says against what the code does: the introduction names only commands
//! that exist (and the technician's path among them), and a default the help states in
//! words is the default clap applies, both written from the constant they come from.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The commands `zerocal --help` lists.
fn commands(text: &str) -> Vec<String> {
    let list = text.split("Commands:").nth(1).unwrap();
    let list = list.split("Options:").next().unwrap();
    list.lines()
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_introduction_names_the_technicians_path_and_only_commands_that_exist() {
    let text = help(&["--help"]);
    let intro = text.split("Usage:").next().unwrap();
    let listed = commands(&text);
    let named: Vec<&str> = intro.split('`').skip(1).step_by(2).collect();
    for word in &named {
        assert!(
            listed.iter().any(|c| c == word),
            "the introduction names `{word}`, which is not a command: {listed:?}"
        );
    }
    // The job in order, as a technician does it.
    let path = ["plan", "program", "pendant", "session", "check"];
    let at: Vec<usize> = path
        .iter()
        .map(|c| {
            intro
                .find(&format!("`{c}`"))
                .unwrap_or_else(|| panic!("{c}: {intro}"))
        })
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{intro}");
    // Every command is named somewhere in it, but `help`.
    for c in listed.iter().filter(|c| *c != "help") {
        assert!(named.contains(&c.as_str()), "`{c}` not introduced: {intro}");
    }
}

/// The number a help text gives before `what`, and clap's `[default: X]` after it.
fn stated_and_default(text: &str, what: &str) -> (f64, f64) {
    let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let at = flat
        .find(what)
        .unwrap_or_else(|| panic!("'{what}': {flat}"));
    let number = flat[..at]
        .rsplit(|c: char| !(c.is_ascii_digit() || c == '.'))
        .find(|w| !w.is_empty())
        .unwrap()
        .parse()
        .unwrap();
    let default = flat[at..]
        .split("[default: ")
        .nth(1)
        .and_then(|d| d.split(']').next())
        .unwrap()
        .parse()
        .unwrap();
    (number, default)
}

#[test]
fn plan_help_states_the_margin_and_window_the_code_defaults_to() {
    let text = help(&["plan", "--help"]);
    let margin = zerocal_procedure::PENDANT_PLAN_MARGIN_DEG;
    let window = zerocal_core::stage2::MEMS_RANGE_DEG;
    let (said, default) = stated_and_default(&text, "° by default, the pendant's own margin");
    assert_eq!((said, default), (margin, margin), "{text}");
    let (within, _) = stated_and_default(&text, "° by default), leaving room");
    assert_eq!(within, window - margin, "{text}");
    let window_help = text.split("--window-deg").nth(1).unwrap();
    let default: f64 = window_help
        .split("[default: ")
        .nth(1)
        .and_then(|d| d.split(']').next())
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(default, window);
    // The plan the command makes by default keeps to it (its first line says so).
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["plan", "--robot", "kuka-kr6-r900-sixx"])
        .output()
        .unwrap();
    let plan = String::from_utf8(out.stdout).unwrap();
    let first = plan.lines().next().unwrap();
    assert!(
        first.contains(&format!(
            "readings within +/-{:.2} deg at zero offsets, window +/-{window} deg",
            window - margin
        )),
        "{first}"
    );
}
