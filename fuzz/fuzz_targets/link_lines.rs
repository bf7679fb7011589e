//! The pendant's command lines, `plan set` rows and `profile set` lines (core's `link`
//! and `procedure::profile`), as the firmware parses them; the `plan` reply read back
//! by `plan set` gives the same poses, and the `profile` reply read back by `profile
//! set` the same profile. The desktop's readers of the pendant's replies
//! (`zerocal pendant`'s reply reader and checks, core's `parse_status`, the export's
//! end trailer) take any bytes without a panic, and what they accept is printable
//! text with finite numbers.
#![no_main]
use libfuzzer_sys::fuzz_target;
use zerocal_core::plan::PoseList;
use zerocal_procedure::link::{parse_command, plan_line, PlanUpload, UploadStep};
use zerocal_procedure::profile::{PendantProfile, ProfileStep, ProfileUpload};

/// The `profile` reply of an uploaded profile reads back as the same profile (names,
/// display, axes, whether it has masses, the brackets' IDs and days exactly; frames to
/// the lines' decimals), every line within the link's 128 bytes.
fn profile_round_trip(p: &PendantProfile<f32>) {
    let mut back = ProfileUpload::<f32>::default();
    let mut done = None;
    for i in 0.. {
        let Some(line) = p.line(i) else { break };
        let line = line.expect("a profile line fits a link line");
        assert!(line.len() + 2 <= 128, "{line}");
        match back.feed(&line) {
            Ok(ProfileStep::More) => {}
            Ok(ProfileStep::Done(q)) => done = Some(q),
            Err(e) => panic!("line {i} {line:?}: {e}"),
        }
    }
    let q = done.expect("the reply ends with 'end'");
    assert_eq!((&q.robot, q.convention), (&p.robot, p.convention));
    assert_eq!(
        (&q.display.names, q.display.sign),
        (&p.display.names, p.display.sign)
    );
    for (a, b) in q.arm.joints.iter().zip(&p.arm.joints) {
        assert_eq!(a.axis, b.axis);
        assert!((a.origin.rotation.matrix() - b.origin.rotation.matrix()).norm() < 1e-5);
        assert!((a.origin.translation_m - b.origin.translation_m).norm() < 1e-5);
    }
    assert_eq!(q.masses.is_some(), p.masses.is_some());
    let ids = |b: &zerocal_core::bracket::Brackets<f32>| {
        [&b.upper_arm, &b.flange].map(|c| c.as_ref().map(|c| (c.id.clone(), c.date)))
    };
    assert_eq!(ids(&q.brackets), ids(&p.brackets));
}

/// A port that answers once with the fuzzer's bytes, then stays quiet; its clock moves
/// a millisecond a read (the link's time, not the machine's: the same run every time).
struct Port<'a> {
    bytes: &'a [u8],
    reads: u32,
}

impl zerocal_link::Link for Port<'_> {
    fn now(&self) -> std::time::Duration {
        std::time::Duration::from_millis(u64::from(self.reads))
    }
    fn pause(&mut self, d: std::time::Duration) -> std::io::Result<()> {
        let ms = u32::try_from(d.as_millis()).unwrap_or(u32::MAX);
        self.reads = self.reads.saturating_add(ms);
        Ok(())
    }
}

impl std::io::Write for Port<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl std::io::Read for Port<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.reads = self.reads.saturating_add(1);
        if self.bytes.is_empty() {
            return Err(std::io::ErrorKind::TimedOut.into());
        }
        let n = buf.len().min(self.bytes.len());
        buf[..n].copy_from_slice(&self.bytes[..n]);
        self.bytes = &self.bytes[n..];
        Ok(n)
    }
}

/// Any bytes as the reply to each request of `zerocal pendant`: refused or accepted,
/// never a panic; accepted output is printable ASCII lines.
fn desktop_reader(data: &[u8]) {
    use zerocal_link::{check_reply, read_reply, Expect, Timeouts};
    // No quiet wait: the bytes are all there at once.
    let timeouts = Timeouts {
        quiet: std::time::Duration::ZERO,
        reply: std::time::Duration::from_secs(10),
    };
    for expect in [
        Expect::Status,
        Expect::Export,
        Expect::Erased,
        Expect::ProfileStored("abb-irb140".into()),
        Expect::PlanStored(24),
        Expect::Plan(24),
        Expect::Profile,
        Expect::BracketProgress,
        Expect::Line {
            name: "clear",
            line: "ok: session cleared (bias and plan kept)".into(),
        },
    ] {
        let mut port = Port {
            bytes: data,
            reads: 0,
        };
        let Ok(reply) = read_reply(&mut port, &expect, timeouts) else {
            continue;
        };
        assert!(reply.lines.len() <= expect.max_lines());
        if let Ok(out) = check_reply(&expect, &reply) {
            assert!(
                out.bytes()
                    .all(|b| b == b'\n' || (0x20..=0x7e).contains(&b)),
                "{out:?}"
            );
        }
    }
}

/// `status` lines read back: every accepted number finite.
fn status_reader(text: &str) {
    let lines: Vec<&str> = text.split("\r\n").collect();
    if let Ok(s) = zerocal_procedure::link::parse_status(&lines) {
        let mut numbers = Vec::new();
        numbers.extend(s.bias_deg.into_iter().flatten());
        if let Some(r) = s.stage1 {
            numbers.extend([r.j2_offset_deg, r.alpha_deg, r.beta_deg]);
        }
        if let zerocal_procedure::link::Stage2Status::Done {
            offsets_deg,
            sigma_deg,
            residual_rms_deg,
        } = s.stage2
        {
            numbers.extend(
                offsets_deg
                    .into_iter()
                    .chain(sigma_deg)
                    .chain([residual_rms_deg]),
            );
        }
        if let Some(r) = s.last_result {
            numbers.extend(r.offsets_deg.into_iter().chain(r.sigma_deg));
        }
        assert!(numbers.iter().all(|v| v.is_finite()), "{s:?}");
    }
    // A trailer that reads writes back as itself.
    for line in text.split(['\n', '\r']) {
        if let Ok(t) = zerocal_procedure::export_trailer::parse(line) {
            assert_eq!(
                zerocal_procedure::export_trailer::parse(&t.to_string()),
                Ok(t)
            );
        }
    }
}

fuzz_target!(|data: &[u8]| {
    desktop_reader(data);
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    status_reader(text);
    let mut upload = PlanUpload::<f32>::new([0.25, -0.5]);
    let mut profile = ProfileUpload::<f32>::default();
    for line in text.split(['\n', '\r']) {
        let _ = parse_command(line);
        match profile.feed(line) {
            Ok(ProfileStep::More) => {}
            Ok(ProfileStep::Done(p)) => {
                profile_round_trip(&p);
                profile = ProfileUpload::default();
            }
            Err(error) => {
                let mut line = zerocal_procedure::link::Line::new();
                assert!(
                    core::fmt::Write::write_fmt(&mut line, format_args!("error: {error}")).is_ok()
                );
                profile = ProfileUpload::default();
            }
        }
        match upload.feed(line) {
            Ok(UploadStep::More) => {}
            Ok(UploadStep::Done(plan)) => {
                check_plan(&plan);
                round_trip(&plan);
                upload = PlanUpload::new([0.25, -0.5]);
            }
            Err(error) => {
                // Every error prints within a link line.
                let mut line = zerocal_procedure::link::Line::new();
                assert!(
                    core::fmt::Write::write_fmt(&mut line, format_args!("error: {error}")).is_ok()
                );
                upload = PlanUpload::new([0.25, -0.5]);
            }
        }
    }
});

fn check_plan(plan: &PoseList<f32>) {
    assert!(plan.len() >= zerocal_core::stage2::MIN_POSES);
    for q in plan {
        for v in q {
            assert!(
                v.is_finite()
                    && v.abs()
                        <= (zerocal_procedure::log::MAX_JOINT_DEG as f32).to_radians() * 1.000_001,
                "{q:?}"
            );
        }
    }
}

/// `plan` prints j1..j6 with 3 decimals under `zerocal plan --csv`'s header; `plan set`
/// takes the lines back as they are.
fn round_trip(plan: &PoseList<f32>) {
    let mut upload = PlanUpload::<f32>::new([0.25, -0.5]);
    for i in 0.. {
        let Some(line) = plan_line(plan, i) else {
            break;
        };
        let Ok(line) = line else {
            panic!("plan line {i} does not fit a link line");
        };
        match upload.feed(&line) {
            Ok(UploadStep::More) => {}
            other => panic!("plan line {i} {line:?}: {other:?}"),
        }
    }
    let back = match upload.feed("end") {
        Ok(UploadStep::Done(p)) => p,
        other => panic!("end: {other:?}"),
    };
    assert_eq!(back.len(), plan.len());
    for (a, b) in plan.iter().zip(&back) {
        for k in 0..6 {
            // 3 decimals of a degree, then f32.
            let error_deg = (a[k] - b[k]).abs().to_degrees();
            assert!(error_deg <= 0.0005 + 1e-4, "{a:?} -> {b:?}");
        }
    }
}
