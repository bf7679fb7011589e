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

/// |τ| about joints 2 and 3 over their full-load torque at a pose.
fn torque_fractions(p: &Profile, q: &[f64; JOINTS]) -> Option<[f64; 2]> {
    let m = p.mass_model()?;
    let tau = m.gravity_torques_nm(&p.arm, q);
    let full = m.full_load_torques_nm(&p.arm, q);
    Some([tau[1].abs() / full[1], tau[2].abs() / full[2]])
}

#[test]
fn every_builtin_stage1_pose_has_no_gravity_torque_on_joints_2_and_3() {
    for name in builtin_names() {
        let p = builtin(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (q, stated) = (p.stage1_joints_rad, p.stage1_stated_rad);
        let Some(fractions) = torque_fractions(&p, &q) else {
            // No lengths (the paper's arm): nothing for gravity to load, kept as stated.
            assert_eq!(q, stated, "{name}");
            continue;
        };
        // The search's promise: 1e-9 of the full load (it reaches rounding, ~1e-16).
        for (j, f) in [2, 3].into_iter().zip(fractions) {
            assert!(f < 1e-9, "{name}: joint {j} at {f:e} of its full load");
        }
        // Joints 1, 4, 5, 6 as stated; joint 2 too where the uniform mass model puts
        // link 2's centre on the vertical upper arm (every profile without source
        // masses states the upper arm vertical).
        for k in [0, 3, 4, 5] {
            assert_eq!(q[k], stated[k], "{name}: joint {}", k + 1);
        }
        if p.masses.is_none() {
            assert_eq!(q[1], stated[1], "{name}: joint 2");
        }
        println!(
            "{name:20} stated {:?} -> {:?} (controller deg)",
            p.shown_deg(&stated).map(|d| (d * 1e4).round() / 1e4),
            p.shown_deg(&q).map(|d| (d * 1e4).round() / 1e4)
        );
    }
}

#[test]
fn fanuc_m20ia_leans_the_forearm_14_6_deg_off_the_geometric_candle() {
    let p = builtin("fanuc-m20ia").unwrap_or_else(|e| panic!("{e}"));
    assert!(
        p.masses.is_none(),
        "no source gives its masses: the uniform model"
    );
    // The profile states pendant J3 = 73.33, the line from J3 to the wrist centre
    // vertical (0.835 m forward, 0.250 m up in J3's frame: atan(0.835 / 0.250)).
    let stated = p.shown_deg(&p.stage1_stated_rad);
    assert!((stated[2] - 73.33).abs() < 1e-9, "{stated:?}");
    // Uniform mass per metre: link 3 (0.25) centred 0.125 up, link 4 (0.835) 0.4175
    // forward and 0.25 up, link 5 (0.1) 0.885 forward and 0.25 up, link 6 none. Their
    // centre stands above J3 where pendant J3 (the forearm's elevation, J2 = 0) is
    // atan(x̄ / z̄).
    let x = 0.835 * 0.4175 + 0.1 * 0.885;
    let z = 0.25 * 0.125 + 0.835 * 0.25 + 0.1 * 0.25;
    let balanced_deg = f64::atan2(x, z).to_degrees();
    let shown = p.shown_deg(&p.stage1_joints_rad);
    // Bisection to f64's resolution; 1e-9 deg is far above it.
    assert!(
        (shown[2] - balanced_deg).abs() < 1e-9,
        "{} vs {balanced_deg}",
        shown[2]
    );
    // 14.56 deg lower than the geometric candle: the 0.25 m offset puts the
    // forearm's weight well behind the line to the wrist centre.
    let change = shown[2] - stated[2];
    assert!((change - (-14.556)).abs() < 1e-3, "{change}");
    // The upper arm stays as stated (vertical), and the pose shown is the adjusted
    // one converted back to the controller's terms.
    assert_eq!(shown[1], stated[1]);
    let back = p.model_rad(&shown);
    for (b, q) in back.iter().zip(&p.stage1_joints_rad) {
        assert!((b - q).abs() < 1e-12);
    }
}

#[test]
fn a_stage1_pose_that_cannot_be_balanced_is_refused() {
    // J3 kept at 70 deg or more: the balance at 58.77 is out of reach, and the one
    // half a turn on (238.77, the forearm hanging) is no stage-1 pose.
    let m20ia = include_str!("../../data/robots/fanuc-m20ia.toml");
    let narrowed = m20ia.replacen("min_deg = -184.999993343", "min_deg = 70.0", 1);
    assert_ne!(narrowed, m20ia);
    let e = parse(&narrowed).err().unwrap_or_else(|| panic!("accepted"));
    assert_eq!(e.key, "stage1.pose_deg", "{e}");
    assert!(e.reason.contains("joint 3"), "{e}");
}

#[test]
fn kuka_stage1_stands_the_upper_arm_up() {
    let p = builtin("kuka-kr6-r900-sixx").unwrap_or_else(|e| panic!("{e}"));
    let (frames, _) = p.arm.frames(&p.stage1_joints_rad);
    let upper = frames[2].translation_m - frames[1].translation_m;
    // A2 = −90: the 0.455 m upper arm straight up (KUKA's cannon/candle convention).
    assert!(
        (upper.normalize() - Vector3::z()).norm() < 1e-12,
        "{upper:?}"
    );
    assert!((upper.norm() - 0.455).abs() < 1e-12);
    // The stated A3 = 4.76 stands the line to the wrist centre vertical (to the
    // profile's 0.01°); the forearm's weight is not on that line, so A3 turns off it.
    let (stated_frames, _) = p.arm.frames(&p.stage1_stated_rad);
    let wrist = stated_frames[4].translation_m - stated_frames[2].translation_m;
    let lean = (wrist.xy().norm() / wrist.norm()).asin().to_degrees();
    assert!(lean < 0.01, "{lean}");
    let turned = (p.stage1_joints_rad[2] - p.stage1_stated_rad[2])
        .to_degrees()
        .abs();
    assert!(turned > 1.0, "{turned}");
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

/// Every built-in is well inside the bounds: its file under a quarter of the size cap,
/// its name within what the pendant stores.
#[test]
fn every_builtin_fits_the_bounds() {
    for (name, text) in BUILTIN {
        assert!(
            text.len() * 4 <= bounds::MAX_PROFILE_BYTES,
            "{name}: {} bytes",
            text.len()
        );
    }
    let robot = zerocal_procedure::RobotName::new();
    assert_eq!(robot.capacity(), bounds::MAX_NAME_BYTES);
}

/// A number outside its plausible range or a text past its length is refused at load,
/// naming the key and the range; never a panic, an infinity or a silently odd number
/// later on.
#[test]
fn out_of_range_numbers_and_long_texts_name_the_key() {
    let kr6 = include_str!("../../data/robots/kuka-kr6-r900-sixx.toml");
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "limits of ±1e308",
            kr6.replacen("min_deg = -170.0\nmax_deg = 170.0", "min_deg = -1e308\nmax_deg = 1e308", 1),
            "joint 1: min_deg: -1e308 is outside the plausible range [-720, 720] deg",
        ),
        (
            "a slow joint",
            kr6.replacen("max_speed_deg_s = 360.0", "max_speed_deg_s = 1e-6", 1),
            "joint 1: max_speed_deg_s: 1e-6 is outside the plausible range [0.1, 10000] deg/s",
        ),
        (
            "a length in millimetres",
            kr6.replacen("xyz_m = [0.0, 0.0, 0.400]", "xyz_m = [0.0, 0.0, 400.0]", 1),
            "joint 1: xyz_m: 400 is outside the plausible range [-10, 10] m",
        ),
        (
            "a rotation past a turn",
            kr6.replacen("rpy_deg = [0.0, 90.0, 0.0]", "rpy_deg = [0.0, 900.0, 0.0]", 1),
            "flange.rpy_deg: 900",
        ),
        (
            "a zero past two turns",
            kr6.replacen("zero_deg = [0.0,", "zero_deg = [1e300,", 1),
            "controller.zero_deg",
        ),
        (
            "a stage-1 angle past two turns",
            kr6.replacen("pose_deg = [-90.0,", "pose_deg = [-9000.0,", 1),
            "stage1.pose_deg",
        ),
        (
            "counts per degree of 1e308",
            kr6.replacen(
                "offset_unit = \"deg\"",
                "offset_unit = \"counts\"\ncounts_per_deg = [1e308, 1, 1, 1, 1, 1]",
                1,
            ),
            "controller.counts_per_deg: 1e308 is outside the plausible range [0.001, 1000000000] counts/deg",
        ),
        (
            "a gear ratio of 0",
            kr6.replacen(
                "offset_unit = \"deg\"",
                "offset_unit = \"motor_rad\"\ngear_ratio = [0, 1, 1, 1, 1, 1]",
                1,
            ),
            "controller.gear_ratio: 0 is outside",
        ),
        (
            "a ten-megabyte name",
            kr6.replacen(
                "name = \"kuka-kr6-r900-sixx\"",
                &format!("name = \"{}\"", "k".repeat(10 << 20)),
                1,
            ),
            "name: longer than 32 bytes",
        ),
        (
            "a long title",
            kr6.replacen("title = \"", &format!("title = \"{}", "T".repeat(200)), 1),
            "title: longer than 120 characters",
        ),
        (
            "a long joint name",
            kr6.replacen("name = \"A5\"", &format!("name = \"{}\"", "A".repeat(17)), 1),
            "joint 5: name: longer than 16 characters",
        ),
        (
            "a heavy link",
            kr6.replacen(
                "max_speed_deg_s = 388.0",
                "max_speed_deg_s = 388.0\nmass_kg = 2e4\ncom_m = [0, 0, 0]",
                1,
            ),
            "joint 5: mass_kg: 20000",
        ),
    ];
    for (what, text, expected) in cases {
        assert!(parse(kr6).is_ok(), "the KR 6 itself reads");
        let e = parse(&text)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        let e = e.to_string();
        assert!(e.contains(expected), "{what}: {e}");
        assert!(
            e.len() < 300,
            "{what}: the message repeats the input: {} bytes",
            e.len()
        );
    }
}

/// ISO 9409-1 designations read into their three numbers; the `A` of form A and a
/// `DIN` prefix are accepted as makers write them, and the designation prints back as
/// ISO writes it.
#[test]
fn iso9409_designations_read_into_bolt_circle_holes_and_thread() {
    let cases = [
        ("ISO 9409-1-50-4-M6", 50.0, 4, 6.0),
        ("ISO 9409-1-31.5-4-M5", 31.5, 4, 5.0),
        ("DIN ISO 9409-1-A50-4-M6", 50.0, 4, 6.0),
        ("  ISO 9409-1-80-6-M8 ", 80.0, 6, 8.0),
    ];
    for (text, pcd, holes, thread) in cases {
        let iso = flange::parse_iso9409(text).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(
            (iso.pitch_circle_mm, iso.holes, iso.thread_mm),
            (pcd, holes, thread),
            "{text}"
        );
        let again = flange::parse_iso9409(&iso.designation()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(again, iso, "{text} prints back as {}", iso.designation());
    }
}

/// Text that is not a designation is refused naming `flange.iso9409`, never a panic
/// nor a NaN or infinite bolt circle.
#[test]
fn malformed_iso9409_designations_name_the_key() {
    let cases = [
        "",
        "ISO 9409-50-4-M6",
        "ISO 9409-1-50-4-6",
        "ISO 9409-1-50-four-M6",
        "ISO 9409-1-50-4",
        "ISO 9409-1-50-4-M6-7",
        "ISO 9409-1--4-M6",
        "ISO 9409-1-NaN-4-M6",
        "ISO 9409-1-inf-4-M6",
        "ISO 9409-1-1e2-4-M6",
        "ISO 9409-1-5.0.0-4-M6",
        "ISO 9409-1-50-+4-M6",
        "ISO 9409-1-50-4-M",
        "ISO 9409-1-50-99999999999-M6",
        "ISO 9409-1-50-4-M6\u{2011}",
    ];
    for text in cases {
        let e = flange::parse_iso9409(text)
            .err()
            .unwrap_or_else(|| panic!("'{text}': accepted"));
        assert_eq!(e.key, "flange.iso9409", "'{text}': {e}");
    }
}

/// Numbers beyond the stated plausibility bounds (`flange::PITCH_CIRCLE_MM`, `HOLES`,
/// `THREAD_MM`) and holes that would overlap on their circle are refused with the
/// reason.
#[test]
fn out_of_range_iso9409_designations_say_why() {
    let cases = [
        ("ISO 9409-1-5-4-M2", "plausible range"),
        ("ISO 9409-1-5000-4-M6", "plausible range"),
        ("ISO 9409-1-50-2-M6", "plausible range"),
        ("ISO 9409-1-500-64-M6", "plausible range"),
        ("ISO 9409-1-50-4-M1", "plausible range"),
        ("ISO 9409-1-500-4-M64", "plausible range"),
        // 12 holes on a 20 mm circle are 5.18 mm apart: M6 cannot fit.
        ("ISO 9409-1-20-12-M6", "overlap"),
    ];
    for (text, why) in cases {
        let e = flange::parse_iso9409(text)
            .err()
            .unwrap_or_else(|| panic!("'{text}': accepted"));
        assert_eq!(e.key, "flange.iso9409", "'{text}': {e}");
        assert!(e.reason.contains(why), "'{text}': {e}");
    }
}

/// The `[flange]` interface keys in a profile: the UR5e's is read; a designation
/// without its source, an undefined source, a dowel without a designation or one that
/// cannot fit, and a bad designation are each refused naming the key.
#[test]
fn flange_interface_keys_are_read_and_checked() {
    let ur5e = builtin("ur5e").unwrap_or_else(|e| panic!("{e}"));
    let iface = ur5e
        .flange_interface
        .unwrap_or_else(|| panic!("ur5e has its flange"));
    assert_eq!(iface.iso9409.designation(), "ISO 9409-1-50-4-M6");
    assert_eq!(iface.source, "S6");
    assert_eq!(iface.dowel_hole_mm, None, "no source reached gives it");

    let text = include_str!("../../data/robots/ur5e.toml");
    let iso = "iso9409 = \"ISO 9409-1-50-4-M6\"";
    let with_dowel = |d: &str| text.replacen(iso, &format!("{iso}\ndowel_hole_mm = {d}"), 1);
    let p = parse(&with_dowel("6.0")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.flange_interface.and_then(|f| f.dowel_hole_mm), Some(6.0));
    let cases: [(&str, String, &str); 6] = [
        (
            "no source",
            text.replacen("interface_source = \"S6\"", "", 1),
            "flange.interface_source",
        ),
        (
            "undefined source",
            text.replacen("interface_source = \"S6\"", "interface_source = \"S99\"", 1),
            "flange.interface_source",
        ),
        (
            "dowel alone",
            text.replacen(iso, "dowel_hole_mm = 6.0", 1).replacen(
                "interface_source = \"S6\"",
                "",
                1,
            ),
            "flange.dowel_hole_mm",
        ),
        ("dowel too big", with_dowel("30.0"), "flange.dowel_hole_mm"),
        ("dowel NaN", with_dowel("nan"), "flange.dowel_hole_mm"),
        (
            "bad designation",
            text.replacen(iso, "iso9409 = \"ISO 9409-1-50-4\"", 1),
            "flange.iso9409",
        ),
    ];
    for (what, text, key) in cases {
        let e = parse(&text)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        assert_eq!(e.key, key, "{what}: {e}");
    }
}

/// Every built-in says what each bracket registers on, and either gives the flange's
/// interface with its source or says in `missing` that none was found.
#[test]
fn every_builtin_says_where_its_brackets_register() {
    for name in builtin_names() {
        let p = builtin(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        for (what, text) in [
            ("stage1", &p.upper_arm_registers_on),
            ("stage2", &p.flange_registers_on),
        ] {
            assert!(
                text.as_ref().is_some_and(|t| !t.trim().is_empty()),
                "{name}: {what}.registers_on"
            );
        }
        let said_missing = p.missing.iter().any(|m| m.starts_with("flange"));
        match &p.flange_interface {
            Some(f) => assert!(p.sources.iter().any(|s| s.id == f.source), "{name}"),
            None => assert!(
                said_missing,
                "{name}: no flange interface and no missing line"
            ),
        }
    }
}

/// Without a `[controller]` table a profile reads in model terms (a URDF import without
/// `--family`); the offset's unit and place go together, all three or none, and a scale
/// without a unit is refused by name.
#[test]
fn a_controller_table_may_be_left_out_or_leave_the_offset_entry_out() {
    let base = include_str!("../../data/robots/kuka-kr6-r900-sixx.toml");
    let start = base.find("\n[controller]\n").unwrap_or(0);
    let end = base.find("\n[stage1]\n").unwrap_or(0);
    let without = format!("{}{}", &base[..start], &base[end..]);
    let p = parse(&without).unwrap_or_else(|e| panic!("{e}"));
    assert!(!p.controller_stated && !p.offset_entry_stated);
    assert_eq!(p.controller, Controller::model_terms());
    assert!(p.controller.offset_where.starts_with("model terms only"));
    let full = parse(base).unwrap_or_else(|e| panic!("{e}"));
    assert!(full.controller_stated && full.offset_entry_stated);
    // The stage-1 pose is the same: KUKA's controller shows the model's angles.
    assert_eq!(p.stage1_joints_rad, full.stage1_joints_rad);

    let no_entry = base
        .replace("offset_unit = \"deg\"\n", "")
        .replace("offset_source = \"S5\"\n", "");
    let cut = no_entry.find("offset_where").unwrap_or(0);
    let line_end = cut + no_entry[cut..].find('\n').unwrap_or(0) + 1;
    let no_entry = format!("{}{}", &no_entry[..cut], &no_entry[line_end..]);
    let p = parse(&no_entry).unwrap_or_else(|e| panic!("{e}"));
    assert!(p.controller_stated && !p.offset_entry_stated);
    assert_eq!(p.controller.unit, OffsetUnit::Degrees);
    for (what, text, key) in [
        (
            "unit alone",
            no_entry.replace("source = \"S4\"", "source = \"S4\"\noffset_unit = \"deg\""),
            "go together",
        ),
        (
            "a ratio without a unit",
            no_entry.replace(
                "source = \"S4\"",
                "source = \"S4\"\ngear_ratio = [1.0, 1.0, 1.0, 1.0, 1.0, 1.0]",
            ),
            "controller.gear_ratio",
        ),
    ] {
        let e = parse(&text)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        assert!(e.to_string().contains(key), "{what}: {e}");
    }
}
