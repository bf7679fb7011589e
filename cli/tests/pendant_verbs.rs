//! `zerocal pendant`'s guided verbs against the pendant's own tasks on the desktop
//! (`zerocal_pendant_desktop::port`: its link server, procedure, store and screens on
//! the simulated clock, an operator script doing what its screens ask): a bracket
//! calibrated step by step to its kept result, a check followed to its export, the
//! live view refreshed and stopped with the pendant answering again; and every link
//! command has a verb.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::io::{Read, Write};
use std::path::PathBuf;
use std::time::Duration;

use zerocal_core::plan::{SESSION_POSES, SESSION_REVISITS};
use zerocal_inputs::error::CliError;
use zerocal_link::{Console, Link, PendantAction, Timeouts};
use zerocal_pendant_desktop::bracket::{
    calibration_world, leave_calibration, operate_calibration, BRACKET_TURN_DEG,
};
use zerocal_pendant_desktop::port::{first_screen, DesktopPort};
use zerocal_pendant_desktop::session::{drive_check_program, operate_check};
use zerocal_pendant_desktop::world::{Place, WorldConfig};
use zerocal_procedure::bracket_cal::BRACKET_CAPTURES;
use zerocal_procedure::link::Command;

/// The desktop pendant as the verbs' port: its clock is the link's.
struct Harness(DesktopPort);

impl Read for Harness {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.0.read(buf)
    }
}

impl Write for Harness {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush()
    }
}

impl Link for Harness {
    fn now(&self) -> Duration {
        self.0.clock()
    }
    fn pause(&mut self, d: Duration) -> std::io::Result<()> {
        self.0.pause(d)
    }
}

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-pendant-verbs-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn world(seed: u64) -> WorldConfig {
    WorldConfig {
        seed,
        ..WorldConfig::default()
    }
}

/// `action` on `port`; its progress lines and what it returned.
fn act(
    port: &mut Harness,
    action: &PendantAction,
    in_place: bool,
    stop: &dyn Fn() -> bool,
) -> (String, Result<String, CliError>) {
    let mut progress = Vec::new();
    let out = zerocal_link::act(
        port,
        action,
        Timeouts::LINK,
        Console {
            out: &mut progress,
            in_place,
            stop,
        },
    );
    (String::from_utf8(progress).unwrap(), out)
}

/// The flange bracket calibrated from the desktop: each of the twelve steps said once,
/// in order, as the pendant reached it; the result's screen; the calibration kept
/// (the `brackets` TOML, written to --out) with the bracket's turn measured within
/// 0.01° of the world's.
#[test]
fn a_bracket_calibration_is_followed_step_by_step_to_its_kept_result() {
    let port = DesktopPort::new(world(21), |rig, _| async move {
        first_screen(rig).await?;
        operate_calibration(rig).await
    })
    .unwrap();
    calibration_world(port.rig());
    let mut port = Harness(port);
    let out = dir().join("brackets.toml");
    let action = PendantAction::BracketCalibrate {
        mount: "flange".into(),
        id: "F-017".into(),
        out: Some(out.clone()),
        date: Some("2026-03-02".into()),
    };
    let (progress, said) = act(&mut port, &action, false, &|| false);
    let said = said.unwrap_or_else(|e| panic!("{e}\n{progress}"));
    assert_eq!(port.0.script(), Some(Ok(())), "{progress}");
    assert!(said.contains("wrote"), "{said}");
    // Every step said once, in order, then the result.
    let mut at = 0;
    for k in 1..=BRACKET_CAPTURES {
        let step = format!("step {k} of {BRACKET_CAPTURES}: ");
        assert_eq!(progress.matches(&step).count(), 1, "{step}\n{progress}");
        let here = progress.find(&step).unwrap();
        assert!(here > at, "{step} out of order\n{progress}");
        at = here;
    }
    let result = progress
        .find("the result is on the pendant's screen")
        .unwrap();
    let kept = progress
        .find("kept on the pendant: bracket flange id F-017")
        .unwrap();
    assert!(at < result && result < kept, "{progress}");
    assert!(progress.contains("capturing: hands off"), "{progress}");
    // The TOML the profile takes, with the turn the world has.
    let toml = std::fs::read_to_string(&out).unwrap();
    let brackets =
        zerocal_inputs::bracket_file::read(&out).unwrap_or_else(|e| panic!("{e}\n{toml}"));
    let flange = brackets.flange.expect("the flange's calibration");
    assert_eq!(flange.id.as_str(), "F-017");
    let (x, y) = (
        flange.rotation_rad.x_rad.to_degrees(),
        flange.rotation_rad.y_rad.to_degrees(),
    );
    assert!(
        (x - BRACKET_TURN_DEG.0).abs() < 0.01 && (y - BRACKET_TURN_DEG.1).abs() < 0.01,
        "{x} {y} against {BRACKET_TURN_DEG:?}\n{toml}"
    );
}

/// A calibration left with BACK on the pendant (at its first step): followed until
/// then, and ended with exit 3 naming the bracket and what the pendant keeps.
#[test]
fn a_bracket_calibration_left_with_back_is_refused_by_name() {
    let port = DesktopPort::new(world(22), |rig, _| async move {
        first_screen(rig).await?;
        leave_calibration(rig).await
    })
    .unwrap();
    let mut port = Harness(port);
    let action = PendantAction::BracketCalibrate {
        mount: "upper-arm".into(),
        id: "U-017".into(),
        out: None,
        date: Some("2026-03-02".into()),
    };
    let (progress, said) = act(&mut port, &action, false, &|| false);
    let e = said.unwrap_err();
    assert_eq!(e.exit_code(), 3, "{e}");
    assert!(
        e.to_string().contains(
            "upper-arm bracket U-017's calibration was left on the pendant without keeping it"
        ),
        "{e}"
    );
    assert!(
        progress.contains("step 1 of 12: the pendant alone on the levelled plate"),
        "{progress}"
    );
}

/// A check started and followed from the desktop: each phase said as the pendant
/// reached it (stage 0's headings on the bench, the flange's poses with their captures
/// counting up, the closing bench readings, done), and its export saved whole: a check
/// export (`# mode check`) with two captures of each check pose.
#[test]
fn a_check_is_followed_to_its_end_and_its_export_saved() {
    let port = DesktopPort::new(world(23), |rig, shared| async move {
        first_screen(rig).await?;
        operate_check(rig, shared).await
    })
    .unwrap();
    let poses = drive_check_program(port.rig()).unwrap();
    let mut port = Harness(port);
    let out = dir().join("check.export");
    let action = PendantAction::Check { out: out.clone() };
    let (progress, said) = act(&mut port, &action, false, &|| false);
    let said = said.unwrap_or_else(|e| panic!("{e}\n{progress}"));
    assert_eq!(port.0.script(), Some(Ok(())), "{progress}");
    assert!(said.contains("zerocal check"), "{said}");
    let order = [
        "stage 0 (bench, turned by hand)",
        "stage 2 (flange poses): 0 captured",
        "stage 2 (flange poses): 1 captured",
        &format!("stage 2 (flange poses): {} captured", 2 * poses.len() - 1),
        "closing bench readings",
        "done: captured",
    ];
    let mut at = 0;
    for phase in order {
        let here = progress[at..]
            .find(phase)
            .unwrap_or_else(|| panic!("'{phase}' not after {at}:\n{progress}"));
        at += here;
    }
    let text = std::fs::read_to_string(&out).unwrap();
    let export = zerocal_analysis::session::read_export(&text).unwrap();
    assert!(export.trailer_checked);
    assert!(text.lines().any(|l| l == "# mode check"), "{text}");
    assert_eq!(export.poses.len(), 2 * poses.len());
}

/// `live` for 10 s of the pendant's time from its power-up, the pendant picked up and
/// turned on the bench after 3 s: the view redrawn in place (cursor up two lines each
/// frame), ten readings a second once past the 1.5 s boot screen, "moving" while it
/// was carried and "still" at the end, the reading changed; then stopped, and the
/// pendant answered `status` again.
#[test]
fn the_live_view_refreshes_and_stops_with_the_pendant_answering() {
    let port = DesktopPort::moved(
        world(24),
        Duration::from_secs(3),
        Place::Bench {
            heading_rad: core::f64::consts::PI,
        },
    )
    .unwrap();
    let mut port = Harness(port);
    let action = PendantAction::Live {
        seconds: Some(10.0),
    };
    let (progress, said) = act(&mut port, &action, true, &|| false);
    let said = said.unwrap_or_else(|e| panic!("{e}\n{progress}"));
    assert!(
        said.contains("stopped: the pendant answered status"),
        "{said}"
    );
    let count: usize = said
        .split(" readings over")
        .next()
        .and_then(|s| s.rsplit(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!((80..=86).contains(&count), "{count}: {said}");
    // Frames drawn over each other.
    let frames = progress.matches("\x1b[2A").count();
    assert!(frames >= 40, "{frames} redraws");
    let frame_lines: Vec<&str> = progress
        .split("\r\x1b[K")
        .filter(|l| l.starts_with("live  x "))
        .collect();
    let x_of = |l: &str| -> f64 { l[8..].split_whitespace().next().unwrap().parse().unwrap() };
    let (first, last) = (
        x_of(frame_lines[5]),
        x_of(frame_lines[frame_lines.len() - 1]),
    );
    assert!((first - last).abs() > 0.01, "{first} {last}");
    let spreads: Vec<&str> = progress
        .split("\r\x1b[K")
        .filter(|l| l.contains("peak to peak"))
        .collect();
    assert!(spreads.iter().any(|l| l.contains(": moving")), "{progress}");
    assert!(spreads[spreads.len() - 1].contains(": still"), "{progress}");
}

/// Without --seconds, `live` runs until the user's Enter (here, after the view has
/// been asked 20 times), and stops at once.
#[test]
fn live_without_seconds_stops_at_enter() {
    let mut port = Harness(DesktopPort::idle(world(25)).unwrap());
    let asked = std::cell::Cell::new(0);
    let stop = || {
        asked.set(asked.get() + 1);
        asked.get() > 20
    };
    let (progress, said) = act(
        &mut port,
        &PendantAction::Live { seconds: None },
        false,
        &stop,
    );
    let said = said.unwrap_or_else(|e| panic!("{e}\n{progress}"));
    assert!(progress.starts_with("live reading from the pendant (Enter stops)"));
    assert!(
        said.contains("stopped: the pendant answered status"),
        "{said}"
    );
}

/// `plan`, `profile` and `clear` against the pendant: after `load-profile` of the KR 6,
/// once `clear` has cleared the session the pendant began on the bench meanwhile: the
/// plan `plan` saves is the one `zerocal program` drives, and `load-profile --plan`
/// takes it back; the profile's lines to `end`.
#[test]
fn plan_profile_and_clear_against_the_pendant() {
    let mut port = Harness(DesktopPort::idle(world(26)).unwrap());
    // Past the boot screen.
    port.pause(Duration::from_secs(3)).unwrap();
    let robot = "kuka-kr6-r900-sixx";
    // The desktop planner's default plan: its distinct poses and the revisits.
    let poses = SESSION_POSES + SESSION_REVISITS;
    let plan_set = format!("ok: plan set, {poses} poses");
    let load = |plan: Option<PathBuf>| PendantAction::LoadProfile {
        robot: robot.into(),
        plan,
        brackets: None,
    };
    // The pendant, still on the bench, has taken stage 0 by now: a session in
    // progress, which a profile may not replace until it is cleared.
    let (_, said) = act(&mut port, &load(None), false, &|| false);
    assert_eq!(said.unwrap_err().exit_code(), 3);
    let (_, said) = act(&mut port, &PendantAction::Clear, false, &|| false);
    assert_eq!(
        said.unwrap().trim(),
        "ok: session cleared (bias and plan kept)"
    );
    let (_, said) = act(&mut port, &load(None), false, &|| false);
    assert!(said.unwrap().contains(&plan_set));
    let plan_file = dir().join("plan.csv");
    let (_, said) = act(
        &mut port,
        &PendantAction::Plan {
            out: Some(plan_file.clone()),
        },
        false,
        &|| false,
    );
    assert!(said.unwrap().contains("load-profile ROBOT --plan"));
    let plan = std::fs::read_to_string(&plan_file).unwrap();
    assert_eq!(
        plan.lines().next(),
        Some(zerocal_procedure::link::PLAN_CSV_HEADER)
    );
    let profile = zerocal_inputs::robot::load(robot).unwrap();
    let read = zerocal_programs::program::read_plan(&plan_file, &profile).unwrap();
    assert_eq!(read.len(), poses);
    let (_, said) = act(
        &mut port,
        &PendantAction::Profile { out: None },
        false,
        &|| false,
    );
    let text = said.unwrap();
    assert!(text.starts_with(&format!("name {robot} ")), "{text}");
    assert_eq!(text.lines().last(), Some("end"));
    act(&mut port, &PendantAction::Clear, false, &|| false)
        .1
        .unwrap();
    let (_, said) = act(&mut port, &load(Some(plan_file)), false, &|| false);
    assert!(said.unwrap().contains(&plan_set));
    // The same poses, to the link's thousandth of a degree.
    let (_, again) = act(
        &mut port,
        &PendantAction::Plan { out: None },
        false,
        &|| false,
    );
    assert_eq!(again.unwrap(), plan);
}

/// Every command of the link has its verb, and `zerocal pendant --help` lists it: no
/// procedure needs a serial terminal.
#[test]
fn every_link_command_has_a_verb_in_the_help() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["pendant", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    let listed: Vec<&str> = help
        .split("Commands:")
        .nth(1)
        .unwrap()
        .split("Options:")
        .next()
        .unwrap()
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for command in Command::ALL {
        let verb = zerocal_link::verb(command);
        assert!(
            verb == "--help" || listed.contains(&verb),
            "`{}` has no verb: {verb} not in {listed:?}",
            command.word()
        );
    }
}
