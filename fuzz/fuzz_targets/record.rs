//! Records read back from flash (core's `Record::decode`, the pendant's `f32`): a
//! decoded record re-encodes to one that decodes the same (round trip), under the same
//! key; a session rebuilt from any decoded records (`ProcedureState::restore`, what the
//! pendant does at power-up) answers `status` and `export` within link lines, and the
//! desktop (`zerocal session`'s reader) reads its export, whenever the values are
//! within the log's bounds (beyond them the pendant may answer `error: line too long`
//! for a line, and the desktop refuse a value; never a panic).
#![no_main]
use arbitrary::{Arbitrary, Unstructured};
use libfuzzer_sys::fuzz_target;
use zerocal_core::stage2::PoseReading;
use zerocal_pendant::config::procedure_config;
use zerocal_procedure::link::status;
use zerocal_procedure::log::{MAX_JOINT_DEG, MAX_READING_DEG, TEMPERATURE_RANGE_C};
use zerocal_procedure::record::{key, Record, MAX_RECORD_LEN, PROFILE_KEYS};
use zerocal_procedure::{PendantProfile, ProcedureState};

#[derive(Arbitrary, Debug)]
struct Stored {
    /// Mostly one of core's keys.
    key_choice: u8,
    key: u16,
    value: Vec<u8>,
}

fn key_of(s: &Stored) -> u16 {
    match s.key_choice % 6 {
        0 => 1 + s.key % 7,
        1 => 0x100 + s.key % 64,
        2 => 0x200 + s.key % 64,
        // Stage 0-1 and closing readings; the robot profile's parts.
        3 => 0x10 + s.key % 8,
        4 => key::PROFILE_HEAD + s.key % PROFILE_KEYS as u16,
        _ => s.key,
    }
}

fn in_bounds(r: &Record<f32>) -> bool {
    let reading = |x: f32, y: f32| {
        x.to_degrees().abs() <= MAX_READING_DEG as f32
            && y.to_degrees().abs() <= MAX_READING_DEG as f32
    };
    match r {
        Record::Bias(t) => reading(t.x_rad, t.y_rad),
        Record::Reading { capture, .. } => {
            reading(capture.reading.x_rad, capture.reading.y_rad)
                && capture.temperature_c.is_none_or(|t| {
                    (TEMPERATURE_RANGE_C.0 as f32..=TEMPERATURE_RANGE_C.1 as f32).contains(&t)
                })
        }
        Record::ProfileHead { stage1_rad, .. } => stage1_rad
            .iter()
            .all(|q| q.to_degrees().abs() <= MAX_JOINT_DEG as f32),
        Record::ProfileDisplay { zero_deg, .. } => {
            zero_deg.iter().all(|z| z.abs() <= MAX_JOINT_DEG as f32)
        }
        Record::Capture { pose, .. } => pose_in_bounds(pose),
        Record::PlanPose { joints_rad, .. } => joints_rad
            .iter()
            .all(|q| q.to_degrees().abs() <= MAX_JOINT_DEG as f32),
        Record::LastResult {
            offsets_rad,
            sigma_rad,
            delta_theta2_rad,
            residual_rms_rad,
        } => offsets_rad
            .iter()
            .chain(sigma_rad)
            .chain([delta_theta2_rad, residual_rms_rad])
            .all(|v| v.to_degrees().abs() <= MAX_JOINT_DEG as f32),
        _ => true,
    }
}

fn pose_in_bounds(p: &PoseReading<f32>) -> bool {
    p.joints_rad
        .iter()
        .all(|q| q.to_degrees().abs() <= MAX_JOINT_DEG as f32)
        && p.reading.x_rad.to_degrees().abs() <= MAX_READING_DEG as f32
        && p.reading.y_rad.to_degrees().abs() <= MAX_READING_DEG as f32
        && p.temperature_c.is_none_or(|t| {
            (TEMPERATURE_RANGE_C.0 as f32..=TEMPERATURE_RANGE_C.1 as f32).contains(&t)
        })
}

fuzz_target!(|data: &[u8]| {
    let Ok(stored) = Vec::<Stored>::arbitrary(&mut Unstructured::new(data)) else {
        return;
    };
    let mut records = Vec::new();
    for s in &stored {
        let key = key_of(s);
        let Ok(record) = Record::<f32>::decode(key, &s.value) else {
            continue;
        };
        assert_eq!(record.key(), key, "{record:?}");
        let mut buf = [0_u8; MAX_RECORD_LEN];
        let n = record.encode(&mut buf).expect("a decoded record encodes");
        assert_eq!(
            Record::<f32>::decode(key, &buf[..n]),
            Ok(record),
            "{key:#x} {:?}",
            s.value
        );
        records.push(record);
    }
    let all_in_bounds = records.iter().all(in_bounds);
    let mut config = procedure_config();
    // The pendant's power-up: the stored profile first (whole, or none).
    if let Some((profile, _)) = PendantProfile::from_records(records.iter().copied()) {
        config.apply(&profile);
    }
    let session = ProcedureState::restore(&config, records.iter().copied());
    // Out of bounds (a stored result of 1e14 deg), a line may outgrow the link's
    // 192 bytes: the pendant then answers `error: line too long` for it
    // (fuzz/regressions/record/crash-43b7...).
    let mut status_lines = Vec::new();
    for i in 0.. {
        match status(&session, i) {
            None => break,
            Some(Ok(line)) => status_lines.push(line.as_str().to_owned()),
            Some(Err(_)) => assert!(!all_in_bounds, "status line {i} overflows"),
        }
    }
    // The desktop reads the status of any stored session back (`zerocal pendant status`);
    // it refuses a negative 1-sigma, which no fit gives.
    let sigmas_valid = records.iter().all(|r| match r {
        Record::LastResult { sigma_rad, .. } => sigma_rad.iter().all(|s| *s >= 0.0),
        _ => true,
    });
    if all_in_bounds && sigmas_valid {
        status_lines.push(
            zerocal_procedure::link::pendant_status(0, 0)
                .expect("fits")
                .as_str()
                .to_owned(),
        );
        let lines: Vec<&str> = status_lines.iter().map(String::as_str).collect();
        if let Err(e) = zerocal_procedure::link::parse_status(&lines) {
            panic!("the desktop refuses the status: {e}\n{lines:#?}");
        }
    }
    let mut text = String::new();
    for (i, line) in session.export(&config).enumerate() {
        match line {
            Ok(line) => text.push_str(&line),
            Err(_) => assert!(!all_in_bounds, "export line {i} overflows"),
        }
        text.push('\n');
    }
    if all_in_bounds {
        if let Err(e) = zerocal_analysis::session::read_export(&text) {
            assert!(
                e.contains("no poses") && session.captures().is_empty(),
                "the desktop refuses the export: {e}\n{text}"
            );
        }
    }
});
