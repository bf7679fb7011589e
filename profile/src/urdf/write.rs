//! The imported profile's TOML: every value from the URDF cites it ([[source]] `U1`,
//! the file's name and SHA-256, with the URDF joint or link each came from in a
//! comment), the stage-1 pose and the flange bracket's axes derived from the
//! kinematics, and each thing a URDF cannot give listed in `missing` with its cost.

use super::chain::{ArmChain, ArmJoint};
use super::read::Description;
use super::{ImportOptions, UrdfError};
use crate::Family;
use nalgebra::Vector3;
use std::fmt::Write;
use zerocal_core::model::{Arm, Joint, JointAxis, JOINTS};

/// Stage 1 wants joint 1 where its half turn ends as far from its limits as it starts:
/// −90°, the built-in profiles' choice, when the limits allow it.
const STAGE1_J1_DEG: f64 = -90.0;

/// A family's convention between the URDF's joint angles and what its controller
/// shows, as its ROS-Industrial driver applies it: the coupling and the source.
struct Convention {
    coupling: &'static str,
    cite: &'static str,
    check: &'static str,
}

/// The convention of `family`'s ROS-Industrial driver (the same sources the built-in
/// profiles cite), `None` for `generic`.
fn convention(family: Family) -> Option<Convention> {
    Some(match family {
        Family::Kuka => Convention {
            coupling: "none",
            cite: "ros-industrial/kuka_experimental, kuka_rsi_hw_interface/src/kuka_hardware_interface.cpp, commit 0c4927c960b0b1ccff4b774be960d02f2f0b7fa8: joint_position_[i] = DEG2RAD * rsi_state_.positions[i] (KRC axis angles passed through, no sign or offset)",
            check: "right for a description written for that driver (ros-industrial's kuka_*_support packages)",
        },
        Family::Abb => Convention {
            coupling: "none",
            cite: "ros-industrial/abb_driver, launch/robot_interface.launch and src/abb_robot_state_node.cpp, commit f3068b92d9f5550992143f775d110b946ef04551: joint angles passed through; J23_coupled defaults to false (no J2/J3 linkage correction)",
            check: "right for a description written for that driver whose support package leaves J23_coupled false (its launch file says); a parallel-linkage arm (J23_coupled = true) shows J3 otherwise, which format 1 cannot state for ABB",
        },
        Family::Fanuc => Convention {
            coupling: "j3-minus-j2",
            cite: "ros-industrial/fanuc, fanuc_driver/src/fanuc_utils.cpp, commit 93b75377f3ea7012e173e6015e048e48318d52fd: linkage_transform, points_out->at(2) += J23_factor * points_out->at(1); +J23_factor on state, -J23_factor on motion: the pendant's J3 = URDF J3 - J2 with J23_factor = 1",
            check: "right for a description written for that driver with J23_factor = 1 (its support package's launch file says; 0 means coupling = \"none\")",
        },
        Family::Yaskawa => Convention {
            coupling: "none",
            cite: "ros-industrial/motoman, motoman_driver/MotoPlus/CtrlGroup.c, commit 07fd8c3787f113fbc65829ddaf503c8f9056e9e5: rosPos[i] = motopulsePos[i] / PtoR[i] (no offset)",
            check: "right for a description written for that driver (ros-industrial's motoman_*_support packages: their U limits are relative to the L arm)",
        },
        Family::Staubli => Convention {
            coupling: "none",
            cite: "ros-industrial/staubli_val3_driver, staubli_val3_driver/val3/ros_server/pushMotion.pgx, commit 021155cf: '// ROS joint position values are in rad, but VAL3 uses degrees'",
            check: "right for a description written for that driver (ros-industrial's staubli_*_support packages)",
        },
        Family::Ur => Convention {
            coupling: "none",
            cite: "ros-industrial/universal_robot, ur_description/config/ur5e/default_kinematics.yaml, commit 6485dfa6444f769f854d8135c123d4baf6796f44, with Universal Robots' 'DH Parameters for calculations of kinematics and dynamics': the ROS description reproduces the controller's DH zero",
            check: "right for a description generated from Universal Robots' DH parameters (ur_description)",
        },
        Family::Generic => return None,
    })
}

/// The controller's joint names for `family` (the pendant shows three bytes).
fn joint_names(family: Family) -> [&'static str; JOINTS] {
    match family {
        Family::Kuka => ["A1", "A2", "A3", "A4", "A5", "A6"],
        Family::Yaskawa => ["S", "L", "U", "R", "B", "T"],
        _ => ["J1", "J2", "J3", "J4", "J5", "J6"],
    }
}

/// A TOML basic string (quoted and escaped).
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_owned()).to_string()
}

/// A name from the file, safe inside a TOML comment: one line, at most 60 characters.
fn comment_safe(s: &str) -> String {
    s.chars()
        .take(60)
        .map(|c| if c.is_control() { '?' } else { c })
        .collect()
}

/// A number as TOML reads it back to the same f64.
fn num(v: f64) -> String {
    // `{:?}` is the shortest text that reads back exactly, with a `.0` or an exponent;
    // −0 is written 0.
    let v = if v == 0.0 { 0.0 } else { v };
    format!("{v:?}")
}

fn nums(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| num(*x)).collect();
    format!("[{}]", parts.join(", "))
}

/// The profile's name: `--name`, or the robot's, lowercased with `-` for anything else.
fn profile_name(d: &Description, options: &ImportOptions) -> String {
    if let Some(n) = &options.name {
        return n.clone();
    }
    let mut out = String::new();
    for c in d.name.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    let mut out: String = out.chars().take(crate::bounds::MAX_NAME_BYTES).collect();
    while out.ends_with('-') {
        out.pop();
    }
    if out.is_empty() {
        String::from("imported-arm")
    } else {
        out
    }
}

/// The core arm of the chain, pendant mounts not yet placed.
fn core_arm(chain: &ArmChain) -> Arm<f64> {
    let mut joints = [Joint {
        origin: zerocal_core::model::Placement::identity(),
        axis: JointAxis::Z,
    }; JOINTS];
    for (j, a) in joints.iter_mut().zip(&chain.joints) {
        *j = Joint {
            origin: a.origin,
            axis: a.axis,
        };
    }
    Arm {
        joints,
        flange: chain.flange,
        upper_arm_mount: nalgebra::Rotation3::identity(),
        flange_mount: nalgebra::Rotation3::identity(),
    }
}

/// The angle (rad) about `axis` that turns `v` so that its part across the axis points
/// where `target`'s does; `None` when either has no such part.
fn turn_onto(v: &Vector3<f64>, target: &Vector3<f64>, axis: &Vector3<f64>) -> Option<f64> {
    let across = |u: &Vector3<f64>| u - axis * axis.dot(u);
    let (a, b) = (across(v), across(target));
    if a.norm() < 1e-9 || b.norm() < 1e-9 {
        return None;
    }
    Some(axis.dot(&a.cross(&b)).atan2(a.dot(&b)))
}

/// `angle` or a whole turn from it inside `[lo, hi]` (rad), the one nearest zero.
fn inside(angle: f64, lo: f64, hi: f64) -> Option<f64> {
    let turn = std::f64::consts::TAU;
    [angle - turn, angle, angle + turn]
        .into_iter()
        .filter(|a| (lo..=hi).contains(a))
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
}

/// The stage-1 pose (model angles, rad): joint 1 where its half turn fits, the upper
/// arm (joint 2 to joint 3) and the forearm (joint 3 to joint 5, the wrist centre)
/// standing up, the wrist at zero. The profile's reader then turns joints 2 and 3 to
/// the nearest pose free of gravity torque.
fn stage1_pose(arm: &Arm<f64>, chain: &ArmChain) -> Result<[f64; JOINTS], UrdfError> {
    let lim = |k: usize| (chain.joints[k].lower_rad, chain.joints[k].upper_rad);
    let derive = |reason: String| UrdfError::Derive {
        key: "stage1.pose_deg",
        reason,
    };
    let (lo1, hi1) = lim(0);
    let half = std::f64::consts::PI;
    if lo1 > hi1 - half {
        return Err(derive(format!(
            "joint 1 turns {:.1}..{:.1} deg, less than the half turn stage 1 needs",
            lo1.to_degrees(),
            hi1.to_degrees()
        )));
    }
    let mut q = [0.0; JOINTS];
    q[0] = STAGE1_J1_DEG.to_radians().clamp(lo1, hi1 - half);
    for (k, v) in q.iter_mut().enumerate().skip(3) {
        let (lo, hi) = lim(k);
        *v = 0.0f64.clamp(lo, hi);
    }
    let up = Vector3::z();
    // Joint 2 stands the upper arm up, then joint 3 the forearm.
    for (k, from, to) in [(1usize, 1usize, 2usize), (2, 2, 4)] {
        let (frames, _) = arm.frames(&q);
        let axis = frames[k].rotation * arm.joints[k].axis.unit::<f64>();
        let v = frames[to].translation_m - frames[from].translation_m;
        let turn = turn_onto(&v, &up, &axis).ok_or_else(|| {
            derive(format!(
                "joint {} and joint {} lie on joint {}'s axis: no arm to stand up",
                from + 1,
                to + 1,
                k + 1
            ))
        })?;
        let (lo, hi) = lim(k);
        q[k] = inside(q[k] + turn, lo, hi).ok_or_else(|| {
            derive(format!(
                "joint {} would stand at {:.2} deg to put its arm upright, outside its limits {:.1}..{:.1} deg",
                k + 1,
                (q[k] + turn).to_degrees(),
                lo.to_degrees(),
                hi.to_degrees()
            ))
        })?;
    }
    Ok(q)
}

/// The flange bracket's axes in the flange frame: x along joint 6's axis out of the
/// flange, z across it (`stage2.mount_x`, `mount_z`).
fn flange_mount(arm: &Arm<f64>) -> Result<(&'static str, &'static str), UrdfError> {
    let derive = |reason: String| UrdfError::Derive {
        key: "stage2.mount_x",
        reason,
    };
    let axis6 = arm.joints[5].axis.unit::<f64>();
    // Joint 5's frame origin (the wrist) seen from link 6 at joint 6's zero.
    let o6 = &arm.joints[5].origin;
    let wrist = -(o6.rotation.inverse() * o6.translation_m);
    let out = (arm.flange.translation_m - wrist).dot(&axis6);
    if out.abs() < 1e-6 {
        return Err(derive(String::from(
            "the flange frame's origin is level with joint 5 along joint 6's axis: which way is out of the flange is not known",
        )));
    }
    let out_flange = arm.flange.rotation.inverse() * (axis6 * out.signum());
    let names = [
        (Vector3::x(), "x"),
        (-Vector3::x(), "-x"),
        (Vector3::y(), "y"),
        (-Vector3::y(), "-y"),
        (Vector3::z(), "z"),
        (-Vector3::z(), "-z"),
    ];
    // Within a microradian: descriptions write π to seven digits (3.1415926).
    let Some((_, mount_x)) = names.iter().find(|(v, _)| (v - out_flange).norm() < 1e-6) else {
        return Err(derive(format!(
            "joint 6's axis is ({:.4}, {:.4}, {:.4}) in the tip frame, not one of its axes: give --tip a frame with an axis along joint 6 (ROS-Industrial's tool0)",
            out_flange.x, out_flange.y, out_flange.z
        )));
    };
    let mount_z = if mount_x.ends_with('x') { "y" } else { "x" };
    Ok((mount_x, mount_z))
}

/// A centre of mass farther from its joint than this many times the link's reach (the
/// next joint's origin, the flange for link 6; at least 0.1 m) is not that link's: a
/// CAD export in another frame. TX2-60's link 5 (0.23 m on a 0.07 m link) is one.
const COM_REACH_FACTOR: f64 = 1.5;

/// Why the URDF's masses are not copied, if they are not: every link given one and
/// the same mass (placeholders), or a centre of mass off its link.
fn implausible_masses(chain: &ArmChain) -> Option<String> {
    let masses: Vec<&super::chain::LinkMass> = chain
        .joints
        .iter()
        .filter_map(|j| j.mass.as_ref())
        .collect();
    if masses.len() == JOINTS && masses.iter().all(|m| m.kg == masses[0].kg) {
        return Some(format!(
            "every link's mass is {} kg: placeholders",
            masses[0].kg
        ));
    }
    for (k, j) in chain.joints.iter().enumerate() {
        let Some(m) = &j.mass else { continue };
        let next = chain
            .joints
            .get(k + 1)
            .map_or(chain.flange.translation_m, |n| n.origin.translation_m);
        let reach = next.norm().max(0.1);
        if m.com_m.norm() > COM_REACH_FACTOR * reach {
            return Some(format!(
                "link {}'s centre of mass lies {:.3} m from joint {}, on a link reaching {:.3} m: not in this link's frame",
                k + 1,
                m.com_m.norm(),
                k + 1,
                next.norm()
            ));
        }
    }
    None
}

/// What a URDF leaves out, each with its cost.
fn missing(chain: &ArmChain, family: Family, conv: Option<&Convention>) -> Vec<String> {
    let mut out = Vec::new();
    match conv {
        None => out.push(String::from(
            "[controller]: a URDF does not say how the controller shows each joint or takes a zero offset; without one the offsets are in model terms only (the URDF's joint angles, degrees), and every pose shown and every program written is in the URDF's angles: right only where the controller shows those (stand the robot at the URDF's zero: every axis should read 0); give --family, or write the [controller] table (docs/profiles.md)",
        )),
        Some(c) => out.push(format!(
            "[controller]: not in a URDF; sign +1, zero 0 and coupling \"{}\" are the ROS-Industrial {} driver's convention (C1), {}; elsewhere every pose shown and every program written is off by the difference: stand the robot at the URDF's zero and check every axis reads 0",
            c.coupling,
            family.name(),
            c.check
        )),
    }
    out.push(format!(
        "controller.offset_unit, offset_where: not in a URDF; offsets are given in {} joint degrees, and where the controller takes them is not stated (docs/controllers/)",
        if conv.is_some() { "the controller's" } else { "the model's" }
    ));
    out.push(String::from(
        "flange interface (ISO 9409-1 bolt circle, dowel): not in a URDF; `zerocal bracket` makes no flange bracket design for this profile until one is cited ([flange] iso9409, interface_source)",
    ));
    out.push(String::from(
        "stage1.registers_on, stage2.registers_on: not in a URDF; the report names no machined reference for either bracket, which seat on the upper arm's casting and the flange face and are squared by their own calibration (docs/mounting.md)",
    ));
    let massless: Vec<String> = chain.joints[2..]
        .iter()
        .zip(3..)
        .filter(|(j, _)| j.mass.is_none())
        .map(|(_, k)| format!("link {k}"))
        .collect();
    if let Some(why) = implausible_masses(chain) {
        out.push(format!(
            "mass_kg, com_m: the URDF's <inertial> are not copied ({why}); the sag model and the stage-1 search for no gravity torque use links of uniform mass per metre (the stated default), so the sag correction and its budget term are that model's, not this arm's"
        ));
    } else if !massless.is_empty() {
        out.push(format!(
            "mass_kg, com_m ({}): no <inertial> in the URDF; the sag model and the stage-1 search for no gravity torque use links of uniform mass per metre (the stated default), so the sag correction and its budget term are that model's, not this arm's",
            massless.join(", ")
        ));
    }
    let slow: Vec<&str> = chain
        .joints
        .iter()
        .filter(|j| j.velocity_rad_s.is_none())
        .map(|j| j.urdf_name.as_str())
        .collect();
    if !slow.is_empty() {
        out.push(format!(
            "max_speed_deg_s ({}): the URDF gives no <limit velocity> above 0; the robot-time prediction uses the timing model's default speed for those joints",
            slow.iter().map(|s| comment_safe(s)).collect::<Vec<_>>().join(", ")
        ));
    }
    out
}

/// Where one joint's origin came from, for its comment.
fn origin_note(j: &ArmJoint) -> String {
    let mut note = format!("U1: joint {} (line {})", comment_safe(&j.urdf_name), j.line);
    if !j.folded.is_empty() {
        let folded: Vec<String> = j.folded.iter().map(|s| comment_safe(s)).collect();
        let _ = write!(note, ", fixed {} folded in", folded.join(", "));
    }
    if j.turned {
        note.push_str(", its frame turned to put the slanted axis on z");
    }
    note
}

/// The whole profile.
pub(super) fn profile_toml(
    d: &Description,
    chain: &ArmChain,
    options: &ImportOptions,
    sha256: &str,
) -> Result<String, UrdfError> {
    let family = options.family;
    let conv = convention(family);
    let name = profile_name(d, options);
    let file: String = options.file_name.chars().take(200).collect();
    let robot = if d.name.is_empty() {
        String::from("(unnamed robot)")
    } else {
        d.name.chars().take(60).collect()
    };
    let title: String = format!("{robot} (imported from {file})")
        .chars()
        .take(crate::bounds::MAX_TITLE_CHARS)
        .collect();
    let arm = core_arm(chain);
    let stage1 = stage1_pose(&arm, chain)?;
    let (mount_x, mount_z) = flange_mount(&arm)?;
    let coupling = conv.as_ref().map_or("none", |c| c.coupling);
    // The pose in the controller's values: FANUC's J3 is the model's θ3 − θ2.
    let mut shown: [f64; JOINTS] = stage1.map(f64::to_degrees);
    if coupling == "j3-minus-j2" {
        shown[2] -= shown[1];
    }
    let names = joint_names(family);
    let copy_masses = implausible_masses(chain).is_none();

    let mut t = String::new();
    let w = &mut t;
    let _ = writeln!(
        w,
        "# Imported by `zerocal profile import` from the URDF {}\n# (SHA-256 {sha256}), the chain {} -> {}.\n# Every number of the arm is the file's (source U1); the stage-1 pose and the flange\n# bracket's axes are derived from it; `missing` says what a URDF cannot give and what\n# its absence costs (`zerocal profile check` lists it).",
        comment_safe(&file),
        comment_safe(&chain.base),
        comment_safe(&chain.tip)
    );
    let _ = writeln!(w, "format = {}", crate::FORMAT);
    let _ = writeln!(w, "name = {}", quoted(&name));
    let _ = writeln!(w, "title = {}", quoted(&title));
    let _ = writeln!(w, "family = {}", quoted(family.name()));
    let _ = writeln!(w, "missing = [");
    for m in missing(chain, family, conv.as_ref()) {
        let _ = writeln!(w, "  {},", quoted(&m));
    }
    let _ = writeln!(w, "]\n");
    let _ = writeln!(w, "[[source]]\nid = \"U1\"");
    let _ = writeln!(
        w,
        "cite = {}",
        quoted(&format!(
            "URDF file {file}, SHA-256 {sha256}: <robot name=\"{robot}\">, chain {} to {}",
            chain.base, chain.tip
        ))
    );
    if let Some(c) = &conv {
        let _ = writeln!(w, "\n[[source]]\nid = \"C1\"\ncite = {}", quoted(c.cite));
    }
    let _ = writeln!(
        w,
        "\n[kinematics]\nform = \"urdf\"\nsource = \"U1\"\n\n# Origins, axes and limits are U1's (radians converted to degrees; rpy_deg is the\n# URDF's fixed-axis roll, pitch, yaw). Masses: each joint's child link with the links\n# fixed to it, centre of mass in the joint's frame."
    );
    for (j, jn) in chain.joints.iter().zip(names) {
        let _ = writeln!(w, "\n[[joint]]");
        let _ = writeln!(w, "name = \"{jn}\"            # {}", origin_note(j));
        let _ = writeln!(w, "xyz_m = {}", nums(&j.xyz_m));
        let _ = writeln!(w, "rpy_deg = {}", nums(&j.rpy_rad.map(f64::to_degrees)));
        let a = j.axis.unit::<f64>();
        let _ = writeln!(w, "axis = {}", nums(&[a.x, a.y, a.z]));
        let _ = writeln!(w, "min_deg = {}", num(j.lower_rad.to_degrees()));
        let _ = writeln!(w, "max_deg = {}", num(j.upper_rad.to_degrees()));
        if let Some(v) = j.velocity_rad_s {
            let _ = writeln!(w, "max_speed_deg_s = {}", num(v.to_degrees()));
        }
        let _ = writeln!(w, "limits_source = \"U1\"");
        if let Some(m) = j.mass.as_ref().filter(|_| copy_masses) {
            let links: Vec<String> = m.links.iter().map(|s| comment_safe(s)).collect();
            let _ = writeln!(
                w,
                "mass_kg = {}            # U1: <inertial> of {}",
                num(m.kg),
                links.join(" + ")
            );
            let _ = writeln!(w, "com_m = {}", nums(&[m.com_m.x, m.com_m.y, m.com_m.z]));
        }
    }
    let (flange_xyz, flange_rpy) = chain.flange_xyz_rpy;
    let folded: Vec<String> = chain
        .flange_folded
        .iter()
        .map(|s| comment_safe(s))
        .collect();
    let _ = writeln!(
        w,
        "\n[flange]\n# U1: link 6 to {} ({}); the controller's flange frame where the tip is\n# ROS-Industrial's tool0.\nxyz_m = {}\nrpy_deg = {}",
        comment_safe(&chain.tip),
        if folded.is_empty() {
            String::from("the same frame")
        } else {
            format!("fixed {}", folded.join(", "))
        },
        nums(&flange_xyz),
        nums(&flange_rpy.map(f64::to_degrees))
    );
    if let Some(c) = &conv {
        let _ = writeln!(
            w,
            "\n[controller]\n# Not in a URDF: the ROS-Industrial {} driver's convention (C1; see missing).\n# offset_unit, offset_where, offset_source: not given (offsets in joint degrees).\nsign = [1, 1, 1, 1, 1, 1]\nzero_deg = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\ncoupling = {}\nsource = \"C1\"",
            family.name(),
            quoted(c.coupling)
        );
    } else {
        let _ = writeln!(
            w,
            "\n# No [controller] table: a URDF does not give one (see missing); offsets and\n# poses are in the model's (the URDF's) angles."
        );
    }
    let _ = writeln!(
        w,
        "\n[stage1]\n# Derived from U1 (zerocal's choice, not a source's): joint 1 where its half turn\n# fits, the upper arm (joint 2 to 3) and the forearm (joint 3 to the wrist centre)\n# upright, the wrist at zero; in the controller's values. The reader turns joints 2\n# and 3 to the nearest pose free of gravity torque, and mounts the upper-arm bracket\n# there: the pendant's x along joint 2's axis, its z up.\npose_deg = {}",
        nums(&shown)
    );
    let _ = writeln!(
        w,
        "\n[stage2]\n# Derived from U1: the pendant's x along joint 6's axis, out of the flange, its z\n# across it.\nmount_z = \"{mount_z}\"\nmount_x = \"{mount_x}\""
    );
    Ok(t)
}
