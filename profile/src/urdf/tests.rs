//! The import on the public fixtures of `data/urdf/` (fixtures.toml lists them): every
//! built-in profile with a URDF source comes back with the same forward kinematics,
//! every fixture's profile has the URDF's own forward kinematics, and bad files are
//! refused by name.

use super::*;
use nalgebra::{Rotation3, Unit, Vector3};
use serde::Deserialize;
use zerocal_core::model::{Placement, JOINTS};

#[derive(Deserialize)]
struct Manifest {
    fixture: Vec<Fixture>,
}

#[derive(Deserialize)]
#[allow(dead_code)]
struct Fixture {
    name: String,
    builtin: bool,
    family: String,
}

fn manifest() -> Vec<Fixture> {
    let text = include_str!("../../../data/urdf/fixtures.toml");
    toml::from_str::<Manifest>(text).unwrap().fixture
}

fn fixture_bytes(name: &str) -> Vec<u8> {
    let path = format!("{}/../data/urdf/{name}.urdf", env!("CARGO_MANIFEST_DIR"));
    std::fs::read(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn family(name: &str) -> Family {
    Family::parse(name).unwrap_or_else(|| panic!("family {name}"))
}

fn options(name: &str, fam: Family) -> ImportOptions {
    ImportOptions {
        file_name: format!("{name}.urdf"),
        ends: Ends::default(),
        family: fam,
        name: Some(name.to_owned()),
    }
}

fn imported(f: &Fixture) -> Imported {
    import(
        &fixture_bytes(&f.name),
        &options(&f.name, family(&f.family)),
    )
    .unwrap_or_else(|e| panic!("{}: {e}", f.name))
}

/// A reproducible stream of numbers in [0, 1) (SplitMix64).
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A pose inside the profile's limits (rad).
    fn pose(&mut self, p: &Profile) -> [f64; JOINTS] {
        core::array::from_fn(|k| {
            let j = &p.joints[k];
            (j.min_deg + (j.max_deg - j.min_deg) * self.next()).to_radians()
        })
    }
}

/// The angle between two rotations (rad), accurate near zero (`Rotation3::angle`'s
/// arccosine of the trace loses half the digits there: 1e-8 rad of rounding).
fn angle_between(a: &Rotation3<f64>, b: &Rotation3<f64>) -> f64 {
    let m = (a.inverse() * b).into_inner();
    let sin = Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    )
    .norm()
        / 2.0;
    let cos = (m.trace() - 1.0) / 2.0;
    sin.atan2(cos)
}

/// Forward kinematics straight from the URDF's text, independent of the import: the
/// joints from base to tip, each origin then a turn about its raw axis.
fn urdf_fk(d: &read::Description, base: &str, tip: &str, q: &[f64; JOINTS]) -> Placement<f64> {
    let mut path = Vec::new();
    let mut at = tip.to_owned();
    while at != base {
        let j = d.joints.iter().find(|j| j.child == at).unwrap();
        path.push(j);
        at = j.parent.clone();
    }
    path.reverse();
    let mut pose = Placement::identity();
    let mut k = 0;
    for j in path {
        pose = crate::compose(&pose, &chain::placement(j.origin.xyz_m, j.origin.rpy_rad));
        if j.kind != read::JointKind::Fixed {
            let axis = Unit::new_normalize(Vector3::from(j.axis));
            pose.rotation *= Rotation3::from_axis_angle(&axis, q[k]);
            k += 1;
        }
    }
    pose
}

/// For every built-in profile whose source is a URDF or xacro, its expanded URDF kept
/// in data/urdf/ imports to the same arm: on 1,000 random poses within the limits the
/// flange frame's position agrees to 1e-9 m and its orientation to 1e-9 rad, every
/// joint's frame turns alike and its axis is the same line (1e-9 m, 1e-9 rad); the
/// limits and speeds agree to 1e-6 deg (the built-ins write some converted from
/// radians to nine decimals), the sources' masses to 1e-9.
#[test]
fn every_builtin_with_a_urdf_source_imports_to_the_same_arm() {
    let fixtures = manifest();
    let with_urdf: Vec<&str> = crate::builtin_names()
        .filter(|n| {
            let p = crate::builtin(n).unwrap();
            p.sources
                .iter()
                .any(|s| s.cite.contains("xacro") || s.cite.contains(".urdf"))
                && crate::builtin_text(n).is_some_and(|t| t.contains("form = \"urdf\""))
                && *n != "paper-wrist"
        })
        .collect();
    let mut with_urdf = with_urdf;
    with_urdf.sort_unstable();
    let mut covered: Vec<&str> = fixtures
        .iter()
        .filter(|f| f.builtin)
        .map(|f| f.name.as_str())
        .collect();
    covered.sort_unstable();
    assert_eq!(
        with_urdf, covered,
        "a built-in with a URDF source and no fixture, or the reverse"
    );
    let mut draw = Draw(32);
    for f in fixtures.iter().filter(|f| f.builtin) {
        let builtin = crate::builtin(&f.name).unwrap();
        let ours = imported(f).profile;
        let (mut worst_m, mut worst_rad) = (0.0f64, 0.0f64);
        for _ in 0..1000 {
            let q = draw.pose(&builtin);
            let (bf, bflange) = builtin.arm.frames(&q);
            let (of, oflange) = ours.arm.frames(&q);
            worst_m = worst_m.max((bflange.translation_m - oflange.translation_m).norm());
            worst_rad = worst_rad.max(angle_between(&bflange.rotation, &oflange.rotation));
            for k in 0..JOINTS {
                worst_rad = worst_rad.max(angle_between(&bf[k].rotation, &of[k].rotation));
                // The same axis line: parallel, and one origin on the other's line.
                let axis = bf[k].rotation * builtin.arm.joints[k].axis.unit::<f64>();
                let other = of[k].rotation * ours.arm.joints[k].axis.unit::<f64>();
                worst_rad = worst_rad.max(axis.cross(&other).norm());
                let d = of[k].translation_m - bf[k].translation_m;
                worst_m = worst_m.max((d - axis * axis.dot(&d)).norm());
            }
        }
        assert!(
            worst_m <= 1e-9 && worst_rad <= 1e-9,
            "{}: {worst_m:e} m, {worst_rad:e} rad",
            f.name
        );
        for (k, (b, o)) in builtin.joints.iter().zip(&ours.joints).enumerate() {
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-6;
            assert!(
                close(b.min_deg, o.min_deg) && close(b.max_deg, o.max_deg),
                "{} joint {}: limits {}..{} vs {}..{}",
                f.name,
                k + 1,
                b.min_deg,
                b.max_deg,
                o.min_deg,
                o.max_deg
            );
            match (b.max_speed_deg_s, o.max_speed_deg_s) {
                (Some(x), Some(y)) => {
                    assert!(close(x, y), "{} joint {}: {x} vs {y}", f.name, k + 1)
                }
                (x, y) => assert_eq!(x, y, "{} joint {}", f.name, k + 1),
            }
        }
        match (builtin.masses, ours.masses) {
            (Some(b), Some(o)) => {
                for k in 0..JOINTS {
                    assert!(
                        (b.link_kg[k] - o.link_kg[k]).abs() <= 1e-9,
                        "{} link {k}",
                        f.name
                    );
                    assert!(
                        (b.com_m[k] - o.com_m[k]).norm() <= 1e-9,
                        "{} com {k}",
                        f.name
                    );
                }
            }
            (b, o) => assert_eq!(b.is_some(), o.is_some(), "{}: masses", f.name),
        }
        assert_eq!(
            builtin.controller.coupling, ours.controller.coupling,
            "{}",
            f.name
        );
        // The derived stage-1 pose comes out where the built-in's stated one does.
        for k in 0..JOINTS {
            let (b, o) = (builtin.stage1_joints_rad[k], ours.stage1_joints_rad[k]);
            assert!(
                (b - o).abs() <= 1e-9,
                "{} stage 1 joint {}: {b} vs {o}",
                f.name,
                k + 1
            );
        }
        assert!(angle_between(&builtin.arm.upper_arm_mount, &ours.arm.upper_arm_mount) <= 1e-9);
        assert!(angle_between(&builtin.arm.flange_mount, &ours.arm.flange_mount) <= 1e-9);
        println!(
            "{:<20} worst over 1,000 poses {worst_m:.1e} m, {worst_rad:.1e} rad",
            f.name
        );
    }
}

/// Every fixture's profile moves as its URDF does: the flange frame from the import
/// against forward kinematics computed straight from the file, 1,000 poses each.
#[test]
fn every_fixture_imports_with_the_urdf_own_forward_kinematics() {
    let mut draw = Draw(7);
    for f in manifest() {
        let i = imported(&f);
        let d = read::read(&fixture_bytes(&f.name)).unwrap();
        for _ in 0..1000 {
            let q = draw.pose(&i.profile);
            let (_, flange) = i.profile.arm.frames(&q);
            let want = urdf_fk(&d, &i.chain.base, &i.chain.tip, &q);
            assert!(
                (flange.translation_m - want.translation_m).norm() <= 1e-9,
                "{} {q:?} {flange:?} {want:?}",
                f.name
            );
            let a = angle_between(&flange.rotation, &want.rotation);
            assert!(a <= 1e-9, "{} {a:e} {q:?}", f.name);
        }
    }
}

fn kr6_text() -> String {
    String::from_utf8(fixture_bytes("kuka-kr6-r900-sixx")).unwrap()
}

/// `text` with `from` replaced once (it must be there).
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "no '{from}'");
    text.replacen(from, to, 1)
}

fn import_text(text: &str, ends: Ends) -> Result<Imported, UrdfError> {
    import(
        text.as_bytes(),
        &ImportOptions {
            ends,
            ..options("test-arm", Family::Kuka)
        },
    )
}

/// Every way a URDF cannot give a six-axis profile is refused by name: the error's
/// kind, and its message naming the joint, link or line and what to do.
#[test]
fn bad_urdfs_are_refused_by_name() {
    let kr6 = kr6_text();
    let a3 = "<joint name=\"joint_a3\" type=\"revolute\">";
    let a6 = "<joint name=\"joint_a6\" type=\"revolute\">";
    let a2_limit = "<limit effort=\"0\" lower=\"-3.3161255787892263\" upper=\"0.7853981633974483\" velocity=\"5.235987755982989\"/>";
    let branch = "<link name=\"camera\"/>\n  <joint name=\"camera_pan\" type=\"revolute\">\n    <parent link=\"link_3\"/>\n    <child link=\"camera\"/>\n    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"-1\" upper=\"1\" velocity=\"1\"/>\n  </joint>\n</robot>";
    let seventh = "<link name=\"link_7\"/>\n  <joint name=\"joint_a7\" type=\"revolute\">\n    <parent link=\"link_6\"/>\n    <child link=\"link_7\"/>\n    <axis xyz=\"0 0 1\"/>\n    <limit lower=\"-1\" upper=\"1\" velocity=\"1\"/>\n  </joint>\n</robot>";
    let cases: Vec<(&str, String, Ends, &[&str])> = vec![
        ("prismatic", edited(&kr6, a3, "<joint name=\"joint_a3\" type=\"prismatic\">"), Ends::default(), &["joint_a3", "prismatic", "line 118"]),
        ("continuous", edited(&kr6, a6, "<joint name=\"joint_a6\" type=\"continuous\">"), Ends::default(), &["joint_a6", "continuous", "limits"]),
        ("mimic", edited(&kr6, a3, &format!("{a3}\n    <mimic joint=\"joint_a2\"/>")), Ends::default(), &["joint_a3", "mimics joint_a2"]),
        ("branch", edited(&kr6, "</robot>", branch), Ends::default(), &["camera_pan", "branch"]),
        ("five joints", edited(&kr6, a6, "<joint name=\"joint_a6\" type=\"fixed\">"), Ends::default(), &["5 revolute joints", "joint_a1"]),
        ("seven joints", edited(&edited(&kr6, "</robot>", seventh), "<parent link=\"link_6\"/>\n    <child link=\"tool0\"/>", "<parent link=\"link_7\"/>\n    <child link=\"tool0\"/>"), Ends::default(), &["7 revolute joints", "joint_a7"]),
        ("millimetres", edited(&kr6, "xyz=\"0.455 0 0\"", "xyz=\"455 0 0\""), Ends::default(), &["joint_a3 <origin xyz>[0]", "455", "millimetres"]),
        ("degrees", edited(&kr6, a2_limit, "<limit effort=\"0\" lower=\"-190\" upper=\"45\" velocity=\"5.2\"/>"), Ends::default(), &["joint_a2 <limit lower>", "-190", "degrees"]),
        ("deg/s", edited(&kr6, "velocity=\"5.235987755982989\"", "velocity=\"300\""), Ends::default(), &["joint_a2 <limit velocity>", "300", "rad/s"]),
        ("no limit", edited(&kr6, a2_limit, ""), Ends::default(), &["joint_a2", "no <limit>"]),
        ("limits swapped", edited(&kr6, a2_limit, "<limit lower=\"1\" upper=\"-1\" velocity=\"1\"/>"), Ends::default(), &["joint_a2", "above upper"]),
        ("unknown type", edited(&kr6, a3, "<joint name=\"joint_a3\" type=\"hinge\">"), Ends::default(), &["joint_a3", "\"hinge\""]),
        ("no axis length", edited(&kr6, "<axis xyz=\"0 0 -1\"/>", "<axis xyz=\"0 0 0\"/>"), Ends::default(), &["joint_a1", "no direction"]),
        ("not a number", edited(&kr6, "xyz=\"0.455 0 0\"", "xyz=\"0.455 nan 0\""), Ends::default(), &["joint_a3 <origin>", "xyz=\"0.455 nan 0\"", "three finite numbers"]),
        ("two parents", edited(&kr6, "</robot>", "<joint name=\"loop\" type=\"fixed\"><parent link=\"link_1\"/><child link=\"link_3\"/></joint></robot>"), Ends::default(), &["link_3", "two joints", "joint_a3", "loop"]),
        ("duplicate link", edited(&kr6, "<link name=\"tool0\"/>", "<link name=\"tool0\"/><link name=\"tool0\"/>"), Ends::default(), &["second link named tool0"]),
        ("unknown link", edited(&kr6, "<child link=\"tool0\"/>", "<child link=\"tool9\"/>"), Ends::default(), &["joint_a6-tool0", "tool9"]),
        ("no tip", kr6.replace("tool0", "tcp"), Ends::default(), &["no tool0 or flange", "--tip", "tcp"]),
        ("tip not below base", kr6.clone(), Ends { base: Some("link_3".into()), tip: Some("link_1".into()) }, &["link link_1 is not below link link_3"]),
        ("no such base", kr6.clone(), Ends { base: Some("world".into()), tip: None }, &["--base world", "no such link"]),
        ("not a robot", String::from("<?xml version=\"1.0\"?>\n<sdf version=\"1.6\"/>"), Ends::default(), &["<sdf>", "not a URDF"]),
        ("not XML", kr6[..kr6.len() / 2].to_owned(), Ends::default(), &["not well-formed XML"]),
        ("a DTD", format!("<!DOCTYPE robot [<!ENTITY a \"aaaa\">]>\n{}", kr6.replacen("<?xml version=\"1.0\"?>", "", 1)), Ends::default(), &["not well-formed XML"]),
        ("a xacro expression", edited(&kr6, "xyz=\"0.455 0 0\"", "xyz=\"${a3} 0 0\""), Ends::default(), &["${...}", "xacro", "pip install xacro"]),
    ];
    for (what, text, ends, words) in cases {
        let e = import_text(&text, ends)
            .err()
            .unwrap_or_else(|| panic!("{what}: accepted"));
        let m = e.to_string();
        for w in words {
            assert!(m.contains(w), "{what}: no '{w}' in: {m}");
        }
    }
}

/// The sources as written (xacro) are refused with how to expand them; bytes that are
/// not text and a file past the cap too, before any parsing.
#[test]
fn xacros_other_bytes_and_huge_files_are_refused_before_parsing() {
    let xacro = std::fs::read(format!(
        "{}/../data/urdf/sources/kuka-kr6-r900-sixx/kuka_kr6_support/urdf/kr6r900sixx_macro.xacro",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let m = import(&xacro, &options("x", Family::Kuka))
        .unwrap_err()
        .to_string();
    assert!(
        m.contains("line 3: a <xacro:...> element") && m.contains("xacro FILE.xacro > FILE.urdf"),
        "{m}"
    );
    let undeclared = String::from_utf8(xacro)
        .unwrap()
        .replace(" xmlns:xacro=\"http://www.ros.org/wiki/xacro\"", "");
    let m = import(undeclared.as_bytes(), &options("x", Family::Kuka))
        .unwrap_err()
        .to_string();
    assert!(m.contains("line 3: a <xacro:...> element"), "{m}");
    let mut bytes = fixture_bytes("kuka-kr6-r900-sixx");
    bytes.insert(50, 0xff);
    assert!(matches!(
        import(&bytes, &options("x", Family::Kuka)),
        Err(UrdfError::NotUtf8 { at_byte: 50 })
    ));
    let mut huge = fixture_bytes("kuka-kr6-r900-sixx");
    huge.extend(std::iter::repeat_n(b' ', MAX_URDF_BYTES));
    let e = import(&huge, &options("x", Family::Kuka)).unwrap_err();
    assert!(matches!(e, UrdfError::TooLarge { .. }), "{e}");
}

/// Fixed joints between revolute ones fold into the next joint's origin, a slanted
/// axis turns its joint's frame, a root above the base link (`world`) is the default
/// base: the profile still moves as the URDF does, and its comments say what was folded.
#[test]
fn fixed_joints_fold_and_slanted_axes_turn_without_changing_the_arm() {
    let kr6 = kr6_text();
    let folded = edited(
        &kr6,
        "<parent link=\"link_2\"/>\n    <child link=\"link_3\"/>",
        "<parent link=\"link_2b\"/>\n    <child link=\"link_3\"/>",
    );
    let folded = edited(
        &folded,
        "</robot>",
        "<link name=\"link_2b\"/>\n  <joint name=\"elbow_block\" type=\"fixed\">\n    <origin xyz=\"0.01 -0.02 0.03\" rpy=\"0 0.3 0\"/>\n    <parent link=\"link_2\"/>\n    <child link=\"link_2b\"/>\n  </joint>\n  <link name=\"world\"/>\n  <joint name=\"world-base\" type=\"fixed\">\n    <origin xyz=\"1 2 0\" rpy=\"0 0 0.5\"/>\n    <parent link=\"world\"/>\n    <child link=\"base_link\"/>\n  </joint>\n</robot>",
    );
    let slanted = edited(
        &folded,
        "<axis xyz=\"-1 0 0\"/>",
        "<axis xyz=\"-0.6 0.8 0\"/>",
    );
    let slanted = edited(&slanted, "<axis xyz=\"0 1 0\"/>\n    <limit effort=\"0\" lower=\"-2.0943951023931953\" upper=\"2.0943951023931953\"", "<axis xyz=\"0 2 2\"/>\n    <limit effort=\"0\" lower=\"-2.0943951023931953\" upper=\"2.0943951023931953\"");
    let mut draw = Draw(5);
    for (what, text) in [("folded", folded), ("slanted", slanted)] {
        let i = import_text(&text, Ends::default()).unwrap_or_else(|e| panic!("{what}: {e}"));
        assert_eq!(i.chain.base, "world", "{what}");
        assert!(i.toml.contains("fixed world-base folded in"), "{what}");
        assert!(i.toml.contains("fixed elbow_block folded in"), "{what}");
        if what == "slanted" {
            assert!(i.toml.contains("slanted axis on z"), "{what}");
        }
        let d = read::read(text.as_bytes()).unwrap();
        for _ in 0..1000 {
            let q = draw.pose(&i.profile);
            let (_, flange) = i.profile.arm.frames(&q);
            let want = urdf_fk(&d, "world", "tool0", &q);
            assert!(
                (flange.translation_m - want.translation_m).norm() <= 1e-9,
                "{what}"
            );
            assert!(
                angle_between(&flange.rotation, &want.rotation) <= 1e-9,
                "{what}"
            );
        }
    }
}

/// A link's mass is its own `<inertial>` with those of the links fixed to it, the
/// centre of mass mass-weighted in the joint's frame (turned with a slanted axis).
#[test]
fn links_fixed_to_a_link_add_their_mass() {
    let kr6 = kr6_text();
    let mut text = kr6.clone();
    for (k, m) in (1..=6).zip([20.0, 18.0, 9.0, 4.0, 3.0, 0.5]) {
        text = edited(
            &text,
            &format!("<link name=\"link_{k}\">"),
            &format!("<link name=\"link_{k}\">\n    <inertial><mass value=\"{m}\"/><origin xyz=\"0.1 0 0.02\"/></inertial>"),
        );
    }
    // A 1 kg tool plate on the flange, fixed to link 6 through tool0 (turned 90° about y).
    let text = edited(&text, "<link name=\"tool0\"/>", "<link name=\"tool0\"><inertial><mass value=\"1.5\"/><origin xyz=\"0 0 0.04\"/></inertial></link>");
    let i = import_text(&text, Ends::default()).unwrap();
    let m = i.profile.masses.unwrap();
    assert_eq!(m.link_kg, [20.0, 18.0, 9.0, 4.0, 3.0, 2.0]);
    // tool0's z is link 6's +x: its 0.04 m is 0.04 along x; (0.5·0.1 + 1.5·0.04) / 2.
    let want = Vector3::new((0.5 * 0.1 + 1.5 * 0.04) / 2.0, 0.0, 0.5 * 0.02 / 2.0);
    assert!((m.com_m[5] - want).norm() < 1e-15, "{:?}", m.com_m[5]);
    assert!(
        i.toml.contains("<inertial> of link_6 + tool0"),
        "{}",
        i.toml
    );
    // The same mass everywhere is a placeholder: not copied, and said so.
    let mut same = kr6;
    for k in 1..=6 {
        same = edited(&same, &format!("<link name=\"link_{k}\">"), &format!("<link name=\"link_{k}\">\n    <inertial><mass value=\"2\"/><origin xyz=\"0.1 0 0\"/></inertial>"));
    }
    let i = import_text(&same, Ends::default()).unwrap();
    assert!(i.profile.masses.is_none());
    assert!(
        i.profile
            .missing
            .iter()
            .any(|m| m.contains("every link's mass is 2 kg: placeholders")),
        "{:?}",
        i.profile.missing
    );
}

/// What the profile says of itself: the file's SHA-256 in its source, the convention
/// of the family, a name from the robot's, and what it misses with what that costs.
#[test]
fn the_profile_cites_the_file_and_says_what_it_misses() {
    let bytes = fixture_bytes("fanuc-m10ia");
    let i = import(
        &bytes,
        &ImportOptions {
            name: None,
            ..options("fanuc-m10ia", Family::Fanuc)
        },
    )
    .unwrap();
    let p = &i.profile;
    assert_eq!(i.sha256.len(), 64);
    assert!(
        p.sources[0].cite.contains(&i.sha256) && p.sources[0].cite.contains("fanuc-m10ia.urdf")
    );
    assert_eq!(p.name, "fanuc-m10ia");
    assert_eq!(p.controller.coupling, crate::Coupling::J3MinusJ2);
    assert!(p.controller_stated && !p.offset_entry_stated);
    for key in [
        "[controller]",
        "offset_unit",
        "flange interface",
        "registers_on",
        "mass_kg",
    ] {
        assert!(
            p.missing.iter().any(|m| m.contains(key)),
            "{key}: {:?}",
            p.missing
        );
    }
    assert!(p.flange_interface.is_none() && p.upper_arm_registers_on.is_none());
    // Without --family: generic, no [controller], offsets in model terms.
    let g = import(&bytes, &options("m10ia-model", Family::Generic)).unwrap();
    assert!(!g.profile.controller_stated);
    assert!(!g.toml.contains("\n[controller]"));
    // The pendant's joint names by family.
    let names: Vec<&str> = p.joints.iter().map(|j| j.name.as_str()).collect();
    assert_eq!(names, ["J1", "J2", "J3", "J4", "J5", "J6"]);
}

/// The URDFs ROS 1's xacro wrote into the repositories themselves (`data/urdf/upstream/`,
/// README.md): they keep `xmlns:xacro` on `<robot>`, which is no sign of a xacro left,
/// and import to the built-in profile's arm (limits to the six decimals they are
/// written with: 1e-4 deg).
#[test]
fn urdfs_expanded_by_ros_1_import_to_the_built_in_arm() {
    let mut draw = Draw(3);
    for name in ["kuka-kr16", "fanuc-m20ia"] {
        let path = format!(
            "{}/../data/urdf/upstream/{name}.urdf",
            env!("CARGO_MANIFEST_DIR")
        );
        let bytes = std::fs::read(&path).unwrap();
        assert!(
            String::from_utf8_lossy(&bytes).contains("xmlns:xacro"),
            "{name}"
        );
        let fam = crate::builtin(name).unwrap().family;
        let ours = import(&bytes, &options(name, fam))
            .unwrap_or_else(|e| panic!("{name}: {e}"))
            .profile;
        let builtin = crate::builtin(name).unwrap();
        for _ in 0..1000 {
            let q = draw.pose(&builtin);
            let (_, b) = builtin.arm.frames(&q);
            let (_, o) = ours.arm.frames(&q);
            assert!((b.translation_m - o.translation_m).norm() <= 1e-9, "{name}");
            assert!(angle_between(&b.rotation, &o.rotation) <= 1e-9, "{name}");
        }
        for (b, o) in builtin.joints.iter().zip(&ours.joints) {
            assert!(
                (b.min_deg - o.min_deg).abs() < 1e-4 && (b.max_deg - o.max_deg).abs() < 1e-4,
                "{name}"
            );
        }
    }
}
