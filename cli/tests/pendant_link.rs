//! `zerocal pendant` against the pendant's own link task, run on the desktop
//! (`zerocal_pendant_desktop::conversation::converse`), and against ports that say anything
//! else: the desktop believes nothing it cannot check. Every wrong reply is refused
//! with exit 3 naming what is wrong, no answer is exit 2, and a flood or a trickle is
//! cut off within the reply's bounds.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::VecDeque;
use std::io::{Read, Write};
use std::time::{Duration, Instant};

use zerocal_core::plan::{SESSION_POSES, SESSION_REVISITS};
use zerocal_inputs::error::CliError;
use zerocal_link::{Expect, PendantAction, Timeouts};
use zerocal_pendant::screen::Screen;
use zerocal_pendant_desktop::conversation::converse;
use zerocal_pendant_desktop::session::{session, SessionReport};
use zerocal_pendant_desktop::world::WorldConfig;
use zerocal_procedure::link::{parse_status, Stage2Status};
use zerocal_procedure::profile::{ProfileStep, ProfileUpload};

/// Short enough for a test, long against a scripted port that answers at once.
const FAST: Timeouts = Timeouts {
    quiet: Duration::from_millis(50),
    reply: Duration::from_millis(1000),
};

/// What a scripted port says after each write.
enum Script {
    /// These bytes, then nothing.
    Bytes(Vec<u8>),
    /// These bytes over and over, forever.
    Forever(Vec<u8>),
    /// One byte of these every few milliseconds, forever.
    Trickle(Vec<u8>),
}

/// A port that answers each request with the next scripted reply and times out, as a
/// serial port does, when it has nothing to say.
struct Scripted {
    replies: VecDeque<Script>,
    now: Option<Script>,
    at: usize,
    written: Vec<u8>,
    /// Bytes it gave.
    given: usize,
    /// When it was made: its clock.
    opened: Instant,
}

impl Scripted {
    fn new(replies: impl IntoIterator<Item = Script>) -> Self {
        Scripted {
            replies: replies.into_iter().collect(),
            now: None,
            at: 0,
            written: Vec::new(),
            given: 0,
            opened: Instant::now(),
        }
    }

    fn bytes(replies: impl IntoIterator<Item = Vec<u8>>) -> Self {
        Self::new(replies.into_iter().map(Script::Bytes))
    }
}

/// A scripted port answers in real time.
impl zerocal_link::Link for Scripted {
    fn now(&self) -> Duration {
        self.opened.elapsed()
    }
    fn pause(&mut self, d: Duration) -> std::io::Result<()> {
        std::thread::sleep(d);
        Ok(())
    }
}

impl Write for Scripted {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.written.extend_from_slice(buf);
        self.now = self.replies.pop_front();
        self.at = 0;
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl Read for Scripted {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let quiet = || {
            std::thread::sleep(Duration::from_millis(1));
            Err(std::io::ErrorKind::TimedOut.into())
        };
        let n = match &self.now {
            None => return quiet(),
            Some(Script::Bytes(b)) => {
                let n = buf.len().min(b.len() - self.at);
                if n == 0 {
                    return quiet();
                }
                buf[..n].copy_from_slice(&b[self.at..self.at + n]);
                self.at += n;
                n
            }
            Some(Script::Forever(b)) => {
                for (k, out) in buf.iter_mut().enumerate() {
                    *out = b[(self.at + k) % b.len()];
                }
                self.at += buf.len();
                buf.len()
            }
            Some(Script::Trickle(b)) => {
                // 50 bytes a second: within the reply's deadline (1 s in FAST) fewer
                // bytes than one line may hold, so only the deadline can end it.
                std::thread::sleep(Duration::from_millis(20));
                buf[0] = b[self.at % b.len()];
                self.at += 1;
                1
            }
        };
        self.given += n;
        Ok(n)
    }
}

fn load(robot: &str) -> PendantAction {
    PendantAction::LoadProfile {
        robot: robot.into(),
        plan: None,
        brackets: None,
    }
}

fn request_bytes(action: &PendantAction) -> Vec<Vec<u8>> {
    zerocal_link::requests(action)
        .unwrap()
        .into_iter()
        .map(|r| r.bytes)
        .collect()
}

/// `action` against a port that answers with `answers`.
fn replay(action: &PendantAction, answers: &[String]) -> Result<String, CliError> {
    let mut port = Scripted::bytes(answers.iter().map(|a| a.as_bytes().to_vec()));
    zerocal_link::perform(&mut port, action, FAST)
}

/// The refusal of `action` against `port`: its exit status and words.
fn refusal(port: &mut Scripted, action: &PendantAction) -> (i32, String) {
    let e = zerocal_link::perform(port, action, FAST).unwrap_err();
    (e.exit_code(), e.to_string())
}

/// The reply a port sending `bytes` gives for `expect`.
fn reply_of(
    bytes: &[u8],
    expect: &Expect,
) -> Result<zerocal_link::Reply, zerocal_link::ReplyError> {
    let mut port = Scripted::bytes([bytes.to_vec()]);
    port.write_all(b"request").unwrap();
    zerocal_link::read_reply(&mut port, expect, FAST)
}

fn crlf(lines: &[&str]) -> Vec<u8> {
    lines
        .iter()
        .flat_map(|l| format!("{l}\r\n").into_bytes())
        .collect()
}

/// A whole session of the pendant's own tasks on the desktop (stages 0-2, every plan
/// pose captured twice), with its export and status replies as the link sent them.
fn whole_session() -> SessionReport {
    let world = WorldConfig {
        seed: 11,
        ..WorldConfig::default()
    };
    session(world, false).expect("a whole session").0
}

/// The export's lines, without their line ends.
fn export_lines(report: &SessionReport) -> Vec<String> {
    report.export_text().lines().map(str::to_owned).collect()
}

#[test]
fn a_loaded_profile_and_plan_survive_a_reboot_and_name_the_robot() {
    let action = load("kuka-kr6-r900-sixx");
    let requests = request_bytes(&action);
    let c = converse(&requests, &[b"profile\r\n".to_vec(), b"plan\r\n".to_vec()]).unwrap();
    let out = replay(&action, &c.answers).unwrap();
    assert!(
        out.contains("ok: profile kuka-kr6-r900-sixx stored"),
        "{out}"
    );
    // The desktop planner's default: its distinct poses and the revisits that show a
    // creeping bracket.
    let poses = SESSION_POSES + SESSION_REVISITS;
    assert!(
        out.contains(&format!("ok: plan set, {poses} poses")),
        "{out}"
    );
    // The boot screen names it.
    match &c.boot_after_reboot {
        Some(Screen::Starting(Some(name))) => assert_eq!(name.as_str(), "kuka-kr6-r900-sixx"),
        other => panic!("{other:?}"),
    }
    // The stored profile reads back as the one sent.
    let profile = zerocal_inputs::robot::load("kuka-kr6-r900-sixx").unwrap();
    let sent = zerocal_link::pendant_profile(&profile, Default::default()).unwrap();
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
    // (the listing's decimals), the pendant keeping f32 (3e-5° at 360°: an angle a
    // hair under a rounding midpoint may print rounded up).
    let rows: Vec<&str> = c.answers_after_reboot[1]
        .lines()
        .filter(|l| {
            l.chars()
                .next()
                .is_some_and(|ch| ch.is_ascii_digit() || ch == '-')
        })
        .collect();
    assert_eq!(rows.len(), poses);
    let expected = String::from_utf8(requests[1].clone()).unwrap();
    for (row, sent_row) in rows.iter().zip(expected.lines().skip(1)) {
        let got: Vec<f64> = row.split(',').map(|v| v.parse().unwrap()).collect();
        let want: Vec<f64> = sent_row.split(',').map(|v| v.parse().unwrap()).collect();
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() <= 0.0005 + 3e-5, "{row} vs {sent_row}");
        }
    }
}

/// `load-profile --brackets FILE` of a profile with masses: the pendant's own link
/// task stores the masses and both calibrations, and after a reboot its `profile`
/// reply reads back (through the pendant's parser) as what was sent, within the
/// `f32` the pendant keeps them in.
#[test]
fn masses_and_bracket_calibrations_survive_a_reboot() {
    let dir = std::env::temp_dir().join(format!("zerocal-brackets-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("brackets.toml");
    std::fs::write(
        &file,
        r#"
[[bracket]]
mount = "upper-arm"
id = "U-017"
rotation_deg = [0.213, -0.0417]
uncertainty_deg = 0.0012
date = "2026-11-27"
temperature_c = 21.5

[[bracket]]
mount = "flange"
id = "F_2"
rotation_deg = [-0.4999, 0.125]
uncertainty_deg = 0.0009
date = "2026-11-26"
temperature_c = 22.25
"#,
    )
    .unwrap();
    let robot = "kuka-kr6-r900-sixx";
    let action = PendantAction::LoadProfile {
        robot: robot.into(),
        plan: None,
        brackets: Some(file.clone()),
    };
    let requests = request_bytes(&action);
    let c = converse(&requests, &[b"profile\r\n".to_vec()]).unwrap();
    let out = replay(&action, &c.answers).unwrap();
    assert!(
        out.contains("ok: profile kuka-kr6-r900-sixx stored"),
        "{out}"
    );
    let profile = zerocal_inputs::robot::load(robot).unwrap();
    let brackets = zerocal_inputs::bracket_file::read(&file).unwrap();
    let sent = zerocal_link::pendant_profile(&profile, brackets).unwrap();
    let mut up = ProfileUpload::<f64>::default();
    let mut back = None;
    for line in c.answers_after_reboot[0].lines() {
        if let ProfileStep::Done(p) = up.feed(line).unwrap() {
            back = Some(p);
        }
    }
    let back = back.expect("the profile's lines, to 'end'");
    // The masses are the profile's, the ones `zerocal session` fits with.
    let (want, got) = (sent.masses.unwrap(), back.masses.unwrap());
    assert_eq!(Some(want), profile.mass_model());
    // f32's relative resolution (6e-8) on each mass and centre of mass.
    for k in 0..6 {
        assert!((want.link_kg[k] - got.link_kg[k]).abs() <= 1e-7 * want.link_kg[k].max(1.0));
        assert!((want.com_m[k] - got.com_m[k]).amax() <= 1e-7);
    }
    assert!((want.pendant_kg - got.pendant_kg).abs() <= 1e-7);
    for (mount, id) in [
        (zerocal_core::bracket::BracketMount::UpperArm, "U-017"),
        (zerocal_core::bracket::BracketMount::Flange, "F_2"),
    ] {
        let (a, b) = (
            sent.brackets.get(mount).unwrap(),
            back.brackets.get(mount).unwrap(),
        );
        assert_eq!((a.id.as_str(), b.id.as_str(), a.date), (id, id, b.date));
        // f32 radians: 1e-9 rad on a turn below 0.01 rad.
        assert!((a.rotation_rad.x_rad - b.rotation_rad.x_rad).abs() < 1e-9);
        assert!((a.rotation_rad.y_rad - b.rotation_rad.y_rad).abs() < 1e-9);
        assert!((a.uncertainty_rad - b.uncertainty_rad).abs() < 1e-11);
        assert!((a.temperature_c.unwrap() - b.temperature_c.unwrap()).abs() < 1e-5);
    }
    // A brackets file that does not check is refused before anything is sent.
    std::fs::write(&file, "[[bracket]]\nmount = \"elbow\"\n").unwrap();
    let e = zerocal_link::requests(&action).unwrap_err();
    assert_eq!(e.exit_code(), 2, "{e}");
    assert!(e.to_string().contains("brackets.toml"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn erase_status_export_and_refusals_against_the_pendant() {
    let requests: Vec<Vec<u8>> = [
        request_bytes(&load("abb-irb140")),
        request_bytes(&PendantAction::Erase),
        request_bytes(&PendantAction::Status),
        request_bytes(&PendantAction::Export {
            out: None,
            results: None,
        }),
        vec![b"profile set\r\nname x convention axis\r\nend\r\n".to_vec()],
    ]
    .concat();
    let c = converse(&requests, &[b"profile\r\n".to_vec()]).unwrap();
    replay(&load("abb-irb140"), &c.answers[..2]).unwrap();
    let erased = replay(&PendantAction::Erase, &c.answers[2..3]).unwrap();
    assert!(erased.contains("ok: store erased"), "{erased}");
    // Printed from the parsed fields.
    let status = replay(&PendantAction::Status, &c.answers[3..4]).unwrap();
    assert!(status.starts_with("phase: stage 0"), "{status}");
    assert!(status.contains("bias: none"), "{status}");
    // The export of an erased pendant: no captures, whole by its trailer.
    let export = replay(
        &PendantAction::Export {
            out: None,
            results: None,
        },
        &c.answers[4..5],
    )
    .unwrap();
    assert!(
        export.contains("# robot paper-wrist convention axis"),
        "{export}"
    );
    assert!(export.lines().last().unwrap().starts_with("# end lines "));
    // A broken upload: the pendant's words, exit 3.
    let expect = Expect::ProfileStored("x".into());
    let reply = reply_of(c.answers[5].as_bytes(), &expect).unwrap();
    let refused = zerocal_link::check_reply(&expect, &reply).unwrap_err();
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
}

#[test]
fn a_refused_profile_stops_before_the_plan() {
    let mut port = Scripted::bytes([
        crlf(&[
            zerocal_procedure::link::PROFILE_PROMPT,
            "error: a session is in progress; 'clear' first (profile unchanged)",
        ]),
        crlf(&["ok: plan set, 24 poses"]),
    ]);
    let (code, words) = refusal(&mut port, &load("abb-irb140"));
    assert_eq!(code, 3);
    assert!(words.contains("session is in progress"), "{words}");
    assert!(!String::from_utf8_lossy(&port.written).contains("plan set"));
}

#[test]
fn status_of_a_whole_session_reads_back_to_its_decimals() {
    let report = whole_session();
    let lines = report.status_lines();
    let refs: Vec<&str> = lines.iter().map(String::as_str).collect();
    let s = parse_status(&refs).unwrap();
    let fit = report.state.outcome().unwrap().result.unwrap().fit;
    let Stage2Status::Done {
        offsets_deg,
        sigma_deg,
        ..
    } = s.stage2
    else {
        panic!("{:?}", s.stage2);
    };
    // The stage-2 line has the export's 12 decimals for offsets and 6 for 1σ; the f32
    // to f64 conversion is exact.
    for k in 0..4 {
        let want = f64::from(fit.offsets_rad[k]).to_degrees();
        assert!((offsets_deg[k] - want).abs() <= 5e-12 + 1e-15, "{k}");
        let want = f64::from(fit.sigma_rad[k]).to_degrees();
        assert!((sigma_deg[k] - want).abs() <= 5e-7 + 1e-12, "{k}");
    }
    // The session solver's stage 1 (the one the result screen shows), 5 decimals on the
    // stage-1 line.
    let stage1 = report.state.outcome().unwrap().stage1.unwrap();
    let want = f64::from(stage1.delta_theta2_rad).to_degrees();
    assert!((s.stage1.unwrap().j2_offset_deg - want).abs() <= 5e-6 + 1e-12);
    assert_eq!(s.captured, report.state.captures().len());
    // Printed from those fields, every line.
    let out = replay(
        &PendantAction::Status,
        &[format!("{}\r\n", lines.join("\r\n"))],
    )
    .unwrap();
    assert_eq!(out.lines().count(), 7, "{out}");
    assert!(out.contains("stage 2: j3..j6 offsets "), "{out}");
    let faults = format!("display faults {}", s.display_faults);
    assert!(out.contains(&faults), "{out} lacks {faults}");
}

#[test]
fn status_that_is_not_status_is_refused_naming_it() {
    let good = whole_session().status_lines();
    let with = |i: usize, text: &str| {
        let mut v = good.clone();
        v[i] = text.to_owned();
        v.iter()
            .flat_map(|l| format!("{l}\r\n").into_bytes())
            .collect::<Vec<u8>>()
    };
    for (bytes, words) in [
        (
            b"\x00\xff\xfeA\x01garbage\r\n".to_vec(),
            "non-printable byte 0x00 at 0",
        ),
        (
            b"phase \x1b[31mdone\x1b[0m; plan 0 poses; 0 captured\r\n".to_vec(),
            "non-printable byte 0x1b at 6",
        ),
        (
            b"result j2 NaN\r\n".to_vec(),
            "status: line 1 is not the phase line",
        ),
        (
            with(1, "bias x NaN deg, y 0.00000 deg"),
            "status: line 2: field 'bias x' is not a number: NaN",
        ),
        (
            with(5, "pendant: sensor frames dropped -1, display faults 0"),
            "field 'frames dropped' is not a number: -1",
        ),
        (
            // A lone CR: a terminal's overwrite, not the pendant's line end.
            with(0, "phase done\rphase done"),
            "non-printable byte 0x0d",
        ),
        (
            crlf(&["phase done; plan 3 poses; 0 captured"]),
            "status: reply ends after 1 lines, 6 expected",
        ),
    ] {
        let (code, e) = refusal(&mut Scripted::bytes([bytes]), &PendantAction::Status);
        assert_eq!(code, 3, "{e}");
        assert!(e.contains(words), "{e} lacks {words}");
    }
}

#[test]
fn an_export_is_saved_only_whole_by_its_trailer() {
    let lines = export_lines(&whole_session());
    let refs: Vec<&str> = lines.iter().map(String::as_str).collect();
    assert!(refs.len() > 29, "{}", refs.len());
    let export = PendantAction::Export {
        out: None,
        results: None,
    };
    let whole = zerocal_link::perform(&mut Scripted::bytes([crlf(&refs)]), &export, FAST).unwrap();
    assert_eq!(
        whole,
        format!("{}\n", refs.join("\n")),
        "saved as sent, LF line ends"
    );

    for (bytes, words) in [
        // Cut: the pendant stopped (cable, reset) after 29 lines.
        (
            crlf(&refs[..29]),
            "export: cut after 29 lines (trailer missing)",
        ),
        // Cut half-way through a line.
        (
            crlf(&refs[..29])
                .into_iter()
                .chain(b"12.5,-3".iter().copied())
                .collect(),
            "export: cut after 29 lines (trailer missing), then 7 bytes of a line cut off",
        ),
        // The first line, then garbage: not even a trailer.
        (
            crlf(&[refs[0], "garbage", "more garbage"]),
            "export: cut after 3 lines (trailer missing)",
        ),
        // The first line, a line that is not the pendant's and a made-up trailer.
        (
            crlf(&[refs[0], "# garbage", "# end lines 2 crc32 00000000"]),
            "export: line 3: end trailer has crc32 00000000 but the lines before it give",
        ),
        // A row changed on the way.
        (
            crlf(
                &refs
                    .iter()
                    .enumerate()
                    .map(|(k, l)| {
                        if k == 23 {
                            "1,2,3,4,5,6,0.1,0.2,20,above,4"
                        } else {
                            l
                        }
                    })
                    .collect::<Vec<_>>(),
            ),
            "end trailer has crc32",
        ),
        // A row lost on the way.
        (
            crlf(
                &refs
                    .iter()
                    .enumerate()
                    .filter(|(k, _)| *k != 23)
                    .map(|(_, l)| *l)
                    .collect::<Vec<_>>(),
            ),
            "lines lost or added",
        ),
        // The pendant's own complaint in the middle.
        (
            crlf(&[refs[0], "error: line too long", refs[refs.len() - 1]]),
            "export: line 2: the pendant says: error: line too long",
        ),
    ] {
        let (code, e) = refusal(&mut Scripted::bytes([bytes]), &export);
        assert_eq!(code, 3, "{e}");
        assert!(e.contains(words), "{e} lacks {words}");
    }
}

#[test]
fn a_flood_is_refused_within_the_reply_s_bounds() {
    let export = PendantAction::Export {
        out: None,
        results: None,
    };
    let max = Expect::Export.max_bytes();
    // Valid-looking rows without end: refused at the most lines an export has.
    let mut port = Scripted::new([Script::Forever(b"1,2,3,4,5,6,0.1,0.2,20\r\n".to_vec())]);
    let start = Instant::now();
    let (code, e) = refusal(&mut port, &export);
    assert_eq!(code, 3);
    let lines = zerocal_procedure::log::EXPORT_MAX_LINES;
    assert!(
        e.contains(&format!("export: reply longer than {lines} lines")),
        "{e}"
    );
    // The reader stops within one read (512 bytes) of the cap, at once.
    assert!(port.given <= max + 512, "{} bytes read", port.given);
    assert!(
        start.elapsed() < Duration::from_millis(500),
        "{:?}",
        start.elapsed()
    );
    // One endless line: refused after one line's bytes.
    let mut port = Scripted::new([Script::Forever(b"A".to_vec())]);
    let (code, e) = refusal(&mut port, &PendantAction::Status);
    assert_eq!(code, 3);
    let line_max = zerocal_procedure::link::REPLY_LINE_BYTES;
    assert!(
        e.contains(&format!("a line longer than {line_max} bytes")),
        "{e}"
    );
    assert!(port.given <= line_max + 512, "{} bytes read", port.given);
    // A trickle that never ends: refused at the reply's deadline.
    let mut port = Scripted::new([Script::Trickle(b"x".to_vec())]);
    let start = Instant::now();
    let (code, e) = refusal(&mut port, &PendantAction::Erase);
    assert_eq!(code, 3);
    assert!(e.contains("erase: reply not over within 1.0 s"), "{e}");
    assert!(start.elapsed() < FAST.reply + Duration::from_millis(300));
}

#[test]
fn a_silent_port_is_no_answer_within_its_timeout() {
    for action in [
        PendantAction::Status,
        PendantAction::Erase,
        PendantAction::Export {
            out: None,
            results: None,
        },
    ] {
        let start = Instant::now();
        let (code, e) = refusal(&mut Scripted::bytes([]), &action);
        let took = start.elapsed();
        assert_eq!(code, 2, "{e}");
        assert!(e.contains("the pendant did not answer within"), "{e}");
        // The quiet time, and a little for the scheduler.
        assert!(
            took >= FAST.quiet && took < FAST.quiet + Duration::from_millis(300),
            "{took:?}"
        );
    }
}

#[test]
fn an_erase_is_done_only_when_the_pendant_says_so() {
    let erase = PendantAction::Erase;
    let ok = zerocal_link::perform(
        &mut Scripted::bytes([crlf(&[zerocal_procedure::link::ERASED])]),
        &erase,
        FAST,
    )
    .unwrap();
    assert_eq!(ok.trim(), zerocal_procedure::link::ERASED);
    for (bytes, words) in [
        (
            crlf(&["ok"]),
            "erase: the pendant did not confirm the erase: 'ok'",
        ),
        (
            crlf(&["error: press OK on the pendant first"]),
            "erase: the pendant refused: press OK on the pendant first",
        ),
        (
            b"ok: store era".to_vec(),
            "erase: no confirmation line, then 13 bytes of a line cut off",
        ),
    ] {
        let (code, e) = refusal(&mut Scripted::bytes([bytes]), &erase);
        assert_eq!(code, 3, "{e}");
        assert!(e.contains(words), "{e} lacks {words}");
    }
    // Nothing at all: no answer.
    let (code, _) = refusal(&mut Scripted::bytes([]), &erase);
    assert_eq!(code, 2);
}

#[test]
fn the_exit_statuses_are_in_the_help() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["pendant", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    for words in [
        "Exit status: 0",
        "2 usage",
        "3 the pendant refused",
        "docs/pendant-link.md",
    ] {
        assert!(help.contains(words), "{words}: {help}");
    }
}

/// `zerocal pendant brackets` on what the simulated pendant answered after a bracket's
/// calibration and a power cycle: the flange's `[[bracket]]` table dated as asked, the
/// upper arm's a comment. An answer cut to one line is refused (exit 3), and a date
/// that is no day is refused before any port (exit 2).
#[test]
fn brackets_read_out_as_the_uploads_toml() {
    let report = zerocal_pendant_desktop::bracket::calibrated().unwrap();
    let lines: Vec<&str> = report
        .link_text
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("bracket "))
        .collect();
    // The last `brackets` answer: upper arm, then flange.
    let answer = &lines[lines.len() - 2..];
    let action = PendantAction::Brackets {
        out: None,
        date: Some("2026-11-27".into()),
    };
    let toml = replay(&action, &[String::from_utf8(crlf(answer)).unwrap()]).unwrap();
    assert!(toml.contains("# upper-arm: none calibrated"), "{toml}");
    assert!(
        toml.contains("[[bracket]]\nmount = \"flange\"\nid = \"F-017\"\nrotation_deg = ["),
        "{toml}"
    );
    assert!(toml.contains("date = \"2026-11-27\""), "{toml}");
    let (code, words) = refusal(&mut Scripted::bytes([crlf(&answer[1..])]), &action);
    assert_eq!(code, 3, "{words}");
    let bad = PendantAction::Brackets {
        out: None,
        date: Some("2026-02-30".into()),
    };
    assert_eq!(zerocal_link::requests(&bad).unwrap_err().exit_code(), 2);
}

/// `zerocal pendant results` against the pendant: a fresh one keeps none (its reply is
/// the head and the end line); a reply with results reads back through the desktop's
/// `read_kept_results`, and a malformed result line is refused, exit 3, by its line.
#[test]
fn results_are_read_whole_and_a_malformed_line_is_refused_by_number() {
    use zerocal_procedure::link::{KEPT_RESULTS_END, KEPT_RESULTS_HEAD};
    let action = PendantAction::Results { out: None };
    let c = converse(&request_bytes(&action), &[]).unwrap();
    let none = replay(&action, &c.answers[..1]).unwrap();
    assert_eq!(none, format!("{KEPT_RESULTS_HEAD}\n{KEPT_RESULTS_END}\n"));
    assert_eq!(
        zerocal_procedure::log::read_kept_results(&none).unwrap(),
        []
    );
    let one = [
        KEPT_RESULTS_HEAD,
        "# kept_result id 7 robot abb-irb140 unit 36002f001347333130373539 brackets U-017,none",
        "# kept_result id 7 verdict pass temps_c 21.53,none,22.07",
        "# kept_result id 7 offsets_deg -0.1234567,0.5,-0.00125,3,0.0000001",
        "# kept_result id 7 sigma_deg 0.0012345,0.002,0.003,0.004,0.005 residual_rms_deg 0.000812",
        KEPT_RESULTS_END,
    ];
    let text = replay(&action, &[String::from_utf8(crlf(&one)).unwrap()]).unwrap();
    let kept = zerocal_procedure::log::read_kept_results(&text).unwrap();
    assert_eq!(kept.len(), 1);
    assert_eq!(kept[0].id, 7);
    assert_eq!(kept[0].offsets_deg[0], -0.123_456_7_f32);
    let mut bad = one;
    bad[3] = "# kept_result id 7 offsets_deg -0.1234567,0.5,-0.00125,3";
    let mut port = Scripted::bytes([crlf(&bad)]);
    let (code, words) = refusal(&mut port, &action);
    assert_eq!(code, 3, "{words}");
    assert!(
        words.contains("line 4") && words.contains("kept_result"),
        "{words}"
    );
    // Cut before its end line: refused, not taken for fewer results.
    let mut port = Scripted::bytes([crlf(&one[..5])]);
    let (code, words) = refusal(&mut port, &action);
    assert_eq!(code, 3, "{words}");
}

#[test]
fn export_out_puts_the_kept_results_beside_it() {
    let path = std::path::Path::new("/tmp/x/session.csv");
    assert_eq!(
        zerocal_link::results_path(path),
        std::path::Path::new("/tmp/x/session.csv.results")
    );
}
