//! Every built-in profile reads and places its brackets right; broken ones are refused
//! with the key named.

use super::*;
use zerocal_core::model::{up_in_sensor, BaseTilt};

#[test]
fn every_builtin_reads_and_levels_the_pendant_at_stage_1() {
    let names: Vec<&str> = builtin_names().collect();
    assert!(names.len() >= 12, "{names:?}");
    for name in names {
        let p = builtin(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(p.name, name, "file stem and name agree");
        let q = p.stage1_joints_rad;
        let level = BaseTilt::level();
        for j1 in [q[0], q[0] + std::f64::consts::PI] {
            let r = p.arm.upper_arm_sensor(&level, j1, q[1]);
            // The bracket puts z up and x along joint 2: on a level base the pendant
            // reads zero before and after the half turn (rounding only).
            let u = up_in_sensor(&r);
            assert!((u - Vector3::z()).norm() < 1e-12, "{name}: up {u:?}");
            let axis2 =
                (p.arm.link2(&level, j1, q[1]) * p.arm.joints[1].axis.unit::<f64>()).normalize();
            let x = r * Vector3::x();
            assert!((x.dot(&axis2).abs() - 1.0).abs() < 1e-12, "{name}: x {x:?}");
        }
        // Shown and model angles round-trip.
        let shown = p.shown_deg(&q);
        let back = p.model_rad(&shown);
        for k in 0..JOINTS {
            assert!((back[k] - q[k]).abs() < 1e-12, "{name} joint {}", k + 1);
        }
        assert!(p.outside_limits(&q).is_none(), "{name}");
    }
}

#[test]
fn kuka_candle_stands_both_arms_up() {
    let p = builtin("kuka-kr6-r900-sixx").unwrap_or_else(|e| panic!("{e}"));
    let (frames, _) = p.arm.frames(&p.stage1_joints_rad);
    let upper = frames[2].translation_m - frames[1].translation_m;
    // A2 = −90: the 0.455 m upper arm straight up (KUKA's cannon/candle convention).
    assert!(
        (upper.normalize() - Vector3::z()).norm() < 1e-12,
        "{upper:?}"
    );
    assert!((upper.norm() - 0.455).abs() < 1e-12);
    let wrist = frames[4].translation_m - frames[2].translation_m;
    // A3 = 4.76 puts the line to the wrist centre vertical (to the profile's 0.01°).
    let lean = (wrist.xy().norm() / wrist.norm()).asin().to_degrees();
    assert!(lean < 0.01, "{lean}");
}

#[test]
fn fanuc_shows_j3_against_the_horizontal() {
    let p = builtin("fanuc-lrmate200id").unwrap_or_else(|e| panic!("{e}"));
    let model = p.model_rad(&[0.0, 30.0, 10.0, 0.0, 0.0, 0.0]);
    assert!((model[2].to_degrees() - 40.0).abs() < 1e-12);
}

fn minimal() -> String {
    builtin_names().next().map_or_else(String::new, |_| {
        include_str!("../../data/robots/paper-wrist.toml").to_owned()
    })
}

#[test]
fn broken_profiles_name_the_key() {
    let base = minimal();
    let cases: [(&str, String, &str); 8] = [
        ("format", base.replace("format = 1", "format = 7"), "format"),
        (
            "name",
            base.replace("name = \"paper-wrist\"", "name = \"Paper Wrist\""),
            "name",
        ),
        (
            "axis",
            base.replacen("axis = [0, 1, 0]", "axis = [0, 0.7, 0.7]", 1),
            "joint 4: axis",
        ),
        (
            "limits",
            base.replacen("min_deg = -180.0", "min_deg = 200.0", 1),
            "joint 1: min_deg",
        ),
        (
            "source",
            base.replace("source = \"P\"", "source = \"S9\""),
            "source",
        ),
        (
            "mount",
            base.replace("mount_x = \"x\"", "mount_x = \"z\""),
            "stage2.mount_x",
        ),
        (
            "unknown key",
            base.replace("[stage2]", "[stage2]\nsensor_mode = 4"),
            "toml",
        ),
        (
            "joint count",
            base.replacen("[[joint]]\nname = \"J6\"", "[unused]\nname = \"J6\"", 1),
            "",
        ),
    ];
    for (what, text, key) in cases {
        let e = parse(&text)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        assert!(e.to_string().contains(key), "{what}: {e}");
    }
}
