//! `zerocal pendant` against the pendant's own link task, run on the desktop
//! (`zerocal_pendant::host::runner::converse`): the requests the CLI sends, the
//! pendant's answers, what it keeps across a power cycle.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_cli::pendant::{self, PendantAction};
use zerocal_core::procedure::profile::{ProfileStep, ProfileUpload};
use zerocal_pendant::host::runner::converse;
use zerocal_pendant::screen::Screen;

fn load(robot: &str) -> PendantAction {
    PendantAction::LoadProfile {
        robot: robot.into(),
        plan: None,
    }
}

#[test]
fn a_loaded_profile_and_plan_survive_a_reboot_and_name_the_robot() {
    let action = load("kuka-kr6-r900-sixx");
    let requests: Vec<Vec<u8>> = pendant::requests(&action)
        .unwrap()
        .into_iter()
        .map(|r| r.bytes)
        .collect();
    let c = converse(&requests, &[b"profile\r\n".to_vec(), b"plan\r\n".to_vec()]).unwrap();
    let out = pendant::check(&action, &c.answers).unwrap();
    assert!(
        out.contains("ok: profile kuka-kr6-r900-sixx stored"),
        "{out}"
    );
    assert!(out.contains("ok: plan set, 24 poses"), "{out}");
    // The boot screen names it.
    match &c.boot_after_reboot {
        Some(Screen::Starting(Some(name))) => assert_eq!(name.as_str(), "kuka-kr6-r900-sixx"),
        other => panic!("{other:?}"),
    }
    // The stored profile reads back as the one sent.
    let profile = zerocal_cli::robot::load("kuka-kr6-r900-sixx").unwrap();
    let sent = pendant::pendant_profile(&profile).unwrap();
    let mut up = ProfileUpload::<f64>::default();
    let mut back = None;
    for line in c.answers_after_reboot[0].lines() {
        if let ProfileStep::Done(p) = up.feed(line).unwrap() {
            back = Some(p);
        }
    }
    let back = back.expect("the profile's lines, to 'end'");
    assert_eq!(back.robot, sent.robot);
    assert_eq!(back.display.names, sent.display.names);
    assert_eq!(back.display.sign, sent.display.sign);
    for (a, b) in back.arm.joints.iter().zip(&sent.arm.joints) {
        assert_eq!(a.axis, b.axis);
        // The pendant keeps f32: 1e-6 of a unit rotation, 1e-6 m.
        assert!((a.origin.rotation.matrix() - b.origin.rotation.matrix()).norm() < 1e-6);
        assert!((a.origin.translation_m - b.origin.translation_m).norm() < 1e-6);
    }
    // The plan is the one `zerocal program --robot kuka-kr6-r900` drives, to 0.001°
    // (the listing's decimals).
    let rows: Vec<&str> = c.answers_after_reboot[1]
        .lines()
        .filter(|l| {
            l.chars()
                .next()
                .is_some_and(|ch| ch.is_ascii_digit() || ch == '-')
        })
        .collect();
    assert_eq!(rows.len(), 24);
    let expected = requests[1].clone();
    let expected = String::from_utf8(expected).unwrap();
    for (row, sent_row) in rows.iter().zip(expected.lines().skip(1)) {
        let got: Vec<f64> = row.split(',').map(|v| v.parse().unwrap()).collect();
        let want: Vec<f64> = sent_row.split(',').map(|v| v.parse().unwrap()).collect();
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() <= 0.0005 + 1e-9, "{row} vs {sent_row}");
        }
    }
}

#[test]
fn erase_status_export_and_refusals() {
    let bytes = |a: &PendantAction| -> Vec<Vec<u8>> {
        pendant::requests(a)
            .unwrap()
            .into_iter()
            .map(|r| r.bytes)
            .collect()
    };
    let requests: Vec<Vec<u8>> = [
        bytes(&load("abb-irb140")),
        bytes(&PendantAction::Erase),
        bytes(&PendantAction::Status),
        bytes(&PendantAction::Export { out: None }),
        vec![b"profile set\r\nname x convention axis\r\nend\r\n".to_vec()],
    ]
    .concat();
    let c = converse(&requests, &[b"profile\r\n".to_vec()]).unwrap();
    pendant::check(&load("abb-irb140"), &c.answers[..2]).unwrap();
    let erased = pendant::check(&PendantAction::Erase, &c.answers[2..3]).unwrap();
    assert!(erased.contains("ok: store erased"), "{erased}");
    let status = pendant::check(&PendantAction::Status, &c.answers[3..4]).unwrap();
    assert!(status.contains("phase stage 0"), "{status}");
    let export = pendant::check(&PendantAction::Export { out: None }, &c.answers[4..5]).unwrap();
    assert!(
        export.contains("# robot paper-wrist convention axis"),
        "{export}"
    );
    // A broken upload: the pendant's words, exit 3.
    let refused = pendant::check(&load("x"), &c.answers[5..6]).unwrap_err();
    assert_eq!(refused.exit_code(), 3);
    assert!(
        refused.to_string().contains("profile incomplete"),
        "{refused}"
    );
    // Erased: the built-in profile after the reboot too.
    assert!(
        c.answers_after_reboot[0].starts_with("name paper-wrist"),
        "{:?}",
        c.answers_after_reboot
    );
    // No answer at all is named, exit 2.
    let silent = pendant::check(&PendantAction::Status, &[String::new()]).unwrap_err();
    assert_eq!(silent.exit_code(), 2);
}
