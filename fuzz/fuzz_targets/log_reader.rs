//! The stage-2 log and the pendant export as read by the desktop (`zerocal_cli`'s
//! `read_log` and `read_export`, std's correctly rounded numbers) against the same
//! reader with core's no_std number parser (`decimal::parse`, what the pendant would
//! use): wherever the two number parsers agree on every field, the readers agree on
//! every line, error and value.
#![no_main]
use std::cell::Cell;

use libfuzzer_sys::fuzz_target;
use zerocal_core::session::{stage1_joint1_mismatch, STAGE1_JOINT1_TOLERANCE_DEG};
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::PoseReading;
use zerocal_fuzz::{close, same_number};
use zerocal_inputs::log_file::parse_number;
use zerocal_procedure::log::{
    parse_meta, strip_bom, LogError, LogLine, LogReader, MetaItem, MetaKeys,
};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    let disagree = Cell::new(false);
    let parse = |s: &str| {
        let ours = zerocal_core::decimal::parse(s);
        if !same_number(ours, parse_number(s), 1e-14) {
            disagree.set(true);
        }
        ours
    };
    let core_export = read_with(text, &parse, true);
    let core_log = read_with(text, &parse, false);
    let host_export = zerocal_analysis::session::read_export(text);
    let host_log = zerocal_inputs::log_file::read_log(text.as_bytes());
    if disagree.get() {
        return;
    }
    match (&core_export, &host_export) {
        (Ok((poses, metas)), Ok(export)) => {
            same_poses(poses, &export.poses);
            if let Some(Some(stage1)) = &export.stage1 {
                stage1_joints_checked(stage1, &export.poses);
            }
            assert_eq!(
                metas,
                &(
                    export.robot.is_some(),
                    export.bias.is_some(),
                    export.stage1.is_some(),
                    export.extras.is_some()
                )
            );
        }
        (Err(a), Err(b)) => assert_eq!(&a.to_string(), b),
        (a, b) => panic!("core {a:?}, host {:?}", b.as_ref().map(|e| e.poses.len())),
    }
    match (&core_log, &host_log) {
        (Ok((poses, _)), Ok(log)) => same_poses(poses, &log.poses),
        (Err(a), Err(b)) => assert_eq!(&a.to_string(), b),
        (a, b) => panic!("core {a:?}, host {:?}", b.as_ref().map(|l| l.poses.len())),
    }
});

/// `zerocal session`'s refusal of rows at another joint 1 than stage 1's, on
/// whatever the reader took (non-finite joints and stage-1 angles among them): it names
/// the first row past the tolerance, and none when every row is within it.
fn stage1_joints_checked(stage1: &AxisOneTurn<f64>, poses: &[PoseReading<f64>]) {
    let tolerance = zerocal_core::real::deg_to_rad(STAGE1_JOINT1_TOLERANCE_DEG);
    let recorded = [stage1.j1_rad];
    let found = [stage1_joint1_mismatch(stage1, poses)];
    for (joint, found) in found.into_iter().enumerate() {
        let within = |p: &PoseReading<f64>| {
            let off = (p.joints_rad[joint] - recorded[joint]).abs();
            off.is_finite() && off <= tolerance
        };
        match found {
            Some(i) => {
                assert!(!within(&poses[i]), "joint {}: row {i}", joint + 1);
                assert!(
                    poses[..i].iter().all(within),
                    "joint {}: row {i}",
                    joint + 1
                );
            }
            None => assert!(poses.iter().all(within), "joint {}", joint + 1),
        }
    }
}

type Read = (Vec<PoseReading<f64>>, (bool, bool, bool, bool));

/// `read_export` (or `read_log` without metadata), line by line with `parse`.
fn read_with(
    text: &str,
    parse: &impl Fn(&str) -> Option<f64>,
    metadata: bool,
) -> Result<Read, LogError> {
    // An export is read strictly: unknown columns, unknown or repeated keys refused.
    let mut reader = if metadata {
        LogReader::for_export()
    } else {
        LogReader::new()
    };
    let mut keys = MetaKeys::default();
    let mut poses = Vec::new();
    let mut seen = (false, false, false, false);
    for line in strip_bom(text).lines() {
        match reader.feed::<f64>(line, parse)? {
            LogLine::Pose(p) => poses.push(p),
            LogLine::Comment(c) if metadata => {
                let item = parse_meta::<f64>(c, reader.line(), parse)?;
                if let Some(item) = &item {
                    keys.note(item, reader.line())?;
                }
                match item {
                    Some(MetaItem::Robot(..)) => seen.0 = true,
                    Some(MetaItem::Bias(_)) => seen.1 = true,
                    Some(MetaItem::Stage1(_)) => seen.2 = true,
                    Some(MetaItem::FitExtras(_)) => seen.3 = true,
                    _ => {}
                }
            }
            _ => {}
        }
    }
    reader.finish()?;
    Ok((poses, seen))
}

fn same_poses(a: &[PoseReading<f64>], b: &[PoseReading<f64>]) {
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        let values = |p: &PoseReading<f64>| {
            let mut v = p.joints_rad.to_vec();
            v.extend([
                p.reading.x_rad,
                p.reading.y_rad,
                p.temperature_c.unwrap_or(f64::NAN),
            ]);
            v
        };
        for (x, y) in values(p).into_iter().zip(values(q)) {
            assert!(
                (x.is_nan() && y.is_nan()) || close(x, y, 1e-13),
                "{p:?} vs {q:?}"
            );
        }
    }
}
