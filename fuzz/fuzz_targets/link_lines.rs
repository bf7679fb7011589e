//! The pendant's command lines and `plan set` rows (core's `link`), as the firmware
//! parses them; the `plan` reply read back by `plan set` gives the same poses.
#![no_main]
use libfuzzer_sys::fuzz_target;
use zerocal_core::link::{parse_command, plan_line, PlanUpload, UploadStep};
use zerocal_core::plan::PoseList;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    let mut upload = PlanUpload::<f32>::new([0.25, -0.5]);
    for line in text.split(['\n', '\r']) {
        let _ = parse_command(line);
        match upload.feed(line) {
            Ok(UploadStep::More) => {}
            Ok(UploadStep::Done(plan)) => {
                check_plan(&plan);
                round_trip(&plan);
                upload = PlanUpload::new([0.25, -0.5]);
            }
            Err(error) => {
                // Every error prints within a link line.
                let mut line = zerocal_core::link::Line::new();
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
                v.is_finite() && v.abs() <= 360f32.to_radians() * 1.000_001,
                "{q:?}"
            );
        }
    }
}

/// `plan` prints j3..j6 with 3 decimals; `plan set` takes them back (joints 1 and 2
/// from stage 1).
fn round_trip(plan: &PoseList<f32>) {
    let mut upload = PlanUpload::<f32>::new([0.25, -0.5]);
    for i in 0.. {
        let Some(line) = plan_line(plan, i) else {
            break;
        };
        let Ok(line) = line else {
            panic!("plan line {i} does not fit a link line");
        };
        // The reply's first column is the pose number: the upload takes j3..j6.
        let row = if i == 0 {
            "j3_deg,j4_deg,j5_deg,j6_deg"
        } else {
            line.split_once(',').map_or("", |(_, rest)| rest)
        };
        match upload.feed(row) {
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
        assert_eq!(&b[..2], &[0.25, -0.5]);
        for k in 2..6 {
            // 3 decimals of a degree, then f32.
            let error_deg = (a[k] - b[k]).abs().to_degrees();
            assert!(error_deg <= 0.0005 + 1e-4, "{a:?} -> {b:?}");
        }
    }
}
