//! The arm in a URDF: the chain of joints from the base link to the tip link, checked
//! to be six revolute joints and nothing else that moves, with the fixed joints folded
//! into their neighbours: a fixed joint before a revolute one into that joint's origin,
//! the fixed joints after joint 6 into the flange, and links hung on a link by fixed
//! joints into its mass.
//!
//! A joint whose axis is not a coordinate axis of its frame (format 1 takes `±x`, `±y`,
//! `±z`) has its frame turned to put the axis on `z`; the next origin and the link's
//! centre of mass are turned back, so every pose of the arm is the URDF's.

use super::read::{Description, Inertial, Joint, JointKind};
use super::UrdfError;
use crate::bounds;
use crate::compose;
use nalgebra::{Rotation3, Vector3};
use std::collections::BTreeMap;
use zerocal_core::model::{rot_x, rot_y, rot_z, JointAxis, Placement, JOINTS};

/// One of the arm's six joints, as the profile writes it.
#[derive(Clone, Debug, PartialEq)]
pub struct ArmJoint {
    /// The URDF joint's name.
    pub urdf_name: String,
    /// Its line in the file.
    pub line: u32,
    /// Its frame on the previous joint's (the base link's for joint 1), the fixed
    /// joints before it folded in.
    pub origin: Placement<f64>,
    /// `origin` as written: the URDF's own `xyz` (m) and `rpy` (rad) where nothing was
    /// folded into it, else worked out from the composed placement.
    pub xyz_m: [f64; 3],
    /// See `xyz_m`.
    pub rpy_rad: [f64; 3],
    /// The axis in its frame.
    pub axis: JointAxis,
    /// The fixed joints folded into `origin`, base side first.
    pub folded: Vec<String>,
    /// Whether its frame was turned to put a slanted axis on `z`.
    pub turned: bool,
    /// `<limit lower>` (rad).
    pub lower_rad: f64,
    /// `<limit upper>` (rad).
    pub upper_rad: f64,
    /// `<limit velocity>` (rad/s), when given and above zero.
    pub velocity_rad_s: Option<f64>,
    /// The moving link's mass: the joint's child link with every link hung on it by
    /// fixed joints, where any of them has an `<inertial>`.
    pub mass: Option<LinkMass>,
}

/// The mass after a joint.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkMass {
    /// Total (kg).
    pub kg: f64,
    /// Centre of mass in the joint's frame (m).
    pub com_m: Vector3<f64>,
    /// The links whose `<inertial>` it sums.
    pub links: Vec<String>,
}

/// The arm read out of a URDF.
#[derive(Clone, Debug, PartialEq)]
pub struct ArmChain {
    /// The base link.
    pub base: String,
    /// The tip link: the flange frame.
    pub tip: String,
    /// Joints 1-6.
    pub joints: Vec<ArmJoint>,
    /// The tip's frame on link 6.
    pub flange: Placement<f64>,
    /// The fixed joints from link 6 to the tip.
    pub flange_folded: Vec<String>,
    /// `flange` as written: the one fixed joint's own `xyz` (m) and `rpy` (rad) where
    /// it is that joint's origin alone, else worked out from the placement.
    pub flange_xyz_rpy: ([f64; 3], [f64; 3]),
}

/// The default tip links, in order of preference: ROS-Industrial's `tool0` (the
/// controller's flange frame, z out of the flange), then its `flange`.
pub const DEFAULT_TIPS: [&str; 2] = ["tool0", "flange"];

/// A URDF origin as a placement: translation, then `Rz(yaw)·Ry(pitch)·Rx(roll)`.
pub fn placement(xyz_m: [f64; 3], rpy_rad: [f64; 3]) -> Placement<f64> {
    Placement {
        rotation: rot_z(rpy_rad[2]) * rot_y(rpy_rad[1]) * rot_x(rpy_rad[0]),
        translation_m: Vector3::from(xyz_m),
    }
}

/// Roll, pitch, yaw (rad) of a rotation, the URDF's convention: `R = Rz(y)·Ry(p)·Rx(r)`,
/// pitch within ±90°. Accurate near ±90° too (a description's π/2 written to six
/// decimals is 3e-7 rad from it): roll and yaw come from the columns scaled by
/// cos(pitch), merged only where it is zero to rounding.
pub fn rpy_of(r: &Rotation3<f64>) -> [f64; 3] {
    let m = r.matrix();
    let cp = m[(0, 0)].hypot(m[(1, 0)]);
    let pitch = (-m[(2, 0)]).atan2(cp);
    if cp > 1e-12 {
        [
            m[(2, 1)].atan2(m[(2, 2)]),
            pitch,
            m[(1, 0)].atan2(m[(0, 0)]),
        ]
    } else {
        // Gimbal lock: roll and yaw turn about one axis; put it all in yaw.
        [0.0, pitch, (-m[(0, 1)]).atan2(m[(1, 1)])]
    }
}

/// Where the chain starts and ends.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Ends {
    /// The base link (default: the root, or `base_link` when there are several).
    pub base: Option<String>,
    /// The tip link (default: `tool0`, else `flange`).
    pub tip: Option<String>,
}

/// The arm from `ends.base` to `ends.tip`.
///
/// # Errors
/// A link named twice or not at all, a link with two parents, no base or tip, a tip not
/// below the base, a joint in the chain that is not revolute (prismatic, continuous,
/// floating, planar) or mimics another, a revolute joint without limits, not six
/// revolute joints, a joint that moves off the chain before link 6 (a branch), a value
/// out of its range.
pub fn arm_chain(d: &Description, ends: &Ends) -> Result<ArmChain, UrdfError> {
    let mut links: BTreeMap<&str, usize> = BTreeMap::new();
    for (i, l) in d.links.iter().enumerate() {
        if links.insert(l.name.as_str(), i).is_some() {
            return Err(UrdfError::Duplicate {
                what: "link",
                name: l.name.clone(),
                line: l.line,
            });
        }
    }
    let mut parent_joint: BTreeMap<&str, usize> = BTreeMap::new();
    let mut joint_names: BTreeMap<&str, usize> = BTreeMap::new();
    for (i, j) in d.joints.iter().enumerate() {
        if joint_names.insert(j.name.as_str(), i).is_some() {
            return Err(UrdfError::Duplicate {
                what: "joint",
                name: j.name.clone(),
                line: j.line,
            });
        }
        for l in [&j.parent, &j.child] {
            if !links.contains_key(l.as_str()) {
                return Err(UrdfError::UnknownLink {
                    joint: j.name.clone(),
                    line: j.line,
                    link: l.clone(),
                });
            }
        }
        if let Some(first) = parent_joint.insert(j.child.as_str(), i) {
            return Err(UrdfError::TwoParents {
                link: j.child.clone(),
                joints: [d.joints[first].name.clone(), j.name.clone()],
            });
        }
    }
    let base = base_link(d, &parent_joint, ends)?;
    let tip = tip_link(d, &links, &parent_joint, ends)?;
    let chain = walk(d, &parent_joint, &base, &tip)?;
    for &i in &chain {
        refuse_kind(&d.joints[i])?;
    }
    let revolute: Vec<usize> = chain
        .iter()
        .copied()
        .filter(|&i| d.joints[i].kind != JointKind::Fixed)
        .collect();
    if revolute.len() != JOINTS {
        return Err(UrdfError::JointCount {
            base: base.clone(),
            tip: tip.clone(),
            names: revolute.iter().map(|&i| d.joints[i].name.clone()).collect(),
        });
    }
    refuse_branches(d, &chain, &revolute)?;
    fold(d, &chain, base, tip)
}

fn base_link(
    d: &Description,
    parent_joint: &BTreeMap<&str, usize>,
    ends: &Ends,
) -> Result<String, UrdfError> {
    if let Some(b) = &ends.base {
        if !d.links.iter().any(|l| &l.name == b) {
            return Err(UrdfError::NoSuchLink {
                option: "--base",
                link: b.clone(),
            });
        }
        return Ok(b.clone());
    }
    let roots: Vec<&str> = d
        .links
        .iter()
        .map(|l| l.name.as_str())
        .filter(|n| !parent_joint.contains_key(n))
        .collect();
    match roots.as_slice() {
        [one] => Ok((*one).to_owned()),
        _ if d.links.iter().any(|l| l.name == "base_link") => Ok("base_link".to_owned()),
        _ => Err(UrdfError::NoBase {
            roots: roots.iter().map(|r| (*r).to_owned()).collect(),
        }),
    }
}

fn tip_link(
    d: &Description,
    links: &BTreeMap<&str, usize>,
    parent_joint: &BTreeMap<&str, usize>,
    ends: &Ends,
) -> Result<String, UrdfError> {
    if let Some(t) = &ends.tip {
        if !links.contains_key(t.as_str()) {
            return Err(UrdfError::NoSuchLink {
                option: "--tip",
                link: t.clone(),
            });
        }
        return Ok(t.clone());
    }
    if let Some(t) = DEFAULT_TIPS.iter().find(|t| links.contains_key(**t)) {
        return Ok((*t).to_owned());
    }
    // No default: name the leaves, one of which is the arm's end.
    let leaves = d
        .links
        .iter()
        .map(|l| l.name.clone())
        .filter(|n| {
            parent_joint.contains_key(n.as_str()) && !d.joints.iter().any(|j| &j.parent == n)
        })
        .collect();
    Err(UrdfError::NoTip { leaves })
}

/// The joints from `base` down to `tip`, base first.
fn walk(
    d: &Description,
    parent_joint: &BTreeMap<&str, usize>,
    base: &str,
    tip: &str,
) -> Result<Vec<usize>, UrdfError> {
    let mut chain = Vec::new();
    let mut at = tip;
    while at != base {
        let Some(&i) = parent_joint.get(at) else {
            return Err(UrdfError::NotBelow {
                tip: tip.to_owned(),
                base: base.to_owned(),
            });
        };
        chain.push(i);
        // Every link has one parent joint: a walk longer than the joints is a loop.
        if chain.len() > d.joints.len() {
            return Err(UrdfError::Loop {
                link: at.to_owned(),
            });
        }
        at = &d.joints[i].parent;
    }
    chain.reverse();
    Ok(chain)
}

/// A joint in the chain that is not revolute, or follows another.
fn refuse_kind(j: &Joint) -> Result<(), UrdfError> {
    match j.kind {
        JointKind::Revolute | JointKind::Fixed => {}
        JointKind::Continuous => {
            return Err(UrdfError::Continuous {
                joint: j.name.clone(),
                line: j.line,
            })
        }
        kind => {
            return Err(UrdfError::NotRevolute {
                joint: j.name.clone(),
                line: j.line,
                kind: kind.name(),
            })
        }
    }
    if let Some(of) = &j.mimic {
        return Err(UrdfError::Mimic {
            joint: j.name.clone(),
            line: j.line,
            of: of.clone(),
        });
    }
    Ok(())
}

/// A joint that moves and hangs off the chain before link 6 (directly or below fixed
/// joints): a second arm, an external axis, a parallel linkage modelled as a branch.
/// What hangs on link 6 and after it (a gripper) is the tool's, not the arm's.
fn refuse_branches(d: &Description, chain: &[usize], revolute: &[usize]) -> Result<(), UrdfError> {
    let Some(&sixth) = revolute.last() else {
        return Ok(());
    };
    let end = chain.iter().position(|&i| i == sixth).unwrap_or(0);
    let mut before_six: Vec<&str> = vec![d.joints[chain[0]].parent.as_str()];
    before_six.extend(chain[..end].iter().map(|&i| d.joints[i].child.as_str()));
    let mut stack: Vec<usize> = d
        .joints
        .iter()
        .enumerate()
        .filter(|(i, j)| !chain.contains(i) && before_six.contains(&j.parent.as_str()))
        .map(|(i, _)| i)
        .collect();
    let mut seen = 0usize;
    while let Some(i) = stack.pop() {
        seen += 1;
        if seen > d.joints.len() {
            break;
        }
        let j = &d.joints[i];
        if j.kind != JointKind::Fixed {
            return Err(UrdfError::Branch {
                joint: j.name.clone(),
                line: j.line,
                kind: j.kind.name(),
            });
        }
        stack.extend(
            d.joints
                .iter()
                .enumerate()
                .filter(|(_, c)| c.parent == j.child)
                .map(|(k, _)| k),
        );
    }
    Ok(())
}

/// A value within ± `max`, else refused naming where and the likely unit mistake.
fn within(
    element: String,
    line: u32,
    value: f64,
    max: f64,
    unit: &'static str,
    hint: &'static str,
) -> Result<(), UrdfError> {
    if value.abs() <= max {
        Ok(())
    } else {
        Err(UrdfError::OutOfRange {
            element,
            line,
            value,
            range: format!("±{max} {unit}"),
            hint,
        })
    }
}

const METRES: &str = "a URDF is in metres: millimetres?";
const RADIANS: &str = "a URDF is in radians: degrees?";

/// The joints folded, each origin checked.
fn fold(
    d: &Description,
    chain: &[usize],
    base: String,
    tip: String,
) -> Result<ArmChain, UrdfError> {
    let mut joints = Vec::with_capacity(JOINTS);
    // Fixed joints since the last revolute one, and the turn of a slanted axis.
    let mut pending = Placement::identity();
    let mut pending_names: Vec<String> = Vec::new();
    let mut turned_before = false;
    for &i in chain {
        let j = &d.joints[i];
        check_origin(j)?;
        let own = placement(j.origin.xyz_m, j.origin.rpy_rad);
        let composed = compose(&pending, &own);
        if j.kind == JointKind::Fixed {
            pending = composed;
            pending_names.push(j.name.clone());
            continue;
        }
        let limit = j.limit.ok_or_else(|| UrdfError::NoLimit {
            joint: j.name.clone(),
            line: j.line,
        })?;
        check_limit(j, &limit)?;
        let (axis, turn) = axis_of(j)?;
        let exact = pending_names.is_empty() && !turned_before && turn.is_none();
        let origin = Placement {
            rotation: composed.rotation * turn.unwrap_or_else(Rotation3::identity),
            translation_m: composed.translation_m,
        };
        let (xyz_m, rpy_rad) = if exact {
            (j.origin.xyz_m, j.origin.rpy_rad)
        } else {
            (origin.translation_m.into(), rpy_of(&origin.rotation))
        };
        let back = turn.map_or_else(Rotation3::identity, |t| t.inverse());
        joints.push(ArmJoint {
            urdf_name: j.name.clone(),
            line: j.line,
            origin,
            xyz_m,
            rpy_rad,
            axis,
            folded: std::mem::take(&mut pending_names),
            turned: turn.is_some(),
            lower_rad: limit.lower_rad,
            upper_rad: limit.upper_rad,
            velocity_rad_s: limit.velocity_rad_s.filter(|v| *v > 0.0),
            mass: link_mass(d, &j.child, &back)?,
        });
        turned_before = turn.is_some();
        pending = Placement {
            rotation: back,
            translation_m: Vector3::zeros(),
        };
    }
    // The flange: one fixed joint's own numbers where nothing else is in it.
    let single = match (pending_names.as_slice(), turned_before) {
        ([one], false) => d.joints.iter().find(|j| &j.name == one),
        _ => None,
    };
    let flange_xyz_rpy = match single {
        Some(j) => (j.origin.xyz_m, j.origin.rpy_rad),
        None => (pending.translation_m.into(), rpy_of(&pending.rotation)),
    };
    Ok(ArmChain {
        base,
        tip,
        joints,
        flange: pending,
        flange_folded: pending_names,
        flange_xyz_rpy,
    })
}

fn check_origin(j: &Joint) -> Result<(), UrdfError> {
    for (k, v) in j.origin.xyz_m.iter().enumerate() {
        within(
            format!("joint {} <origin xyz>[{k}]", j.name),
            j.line,
            *v,
            bounds::MAX_LENGTH_M,
            "m",
            METRES,
        )?;
    }
    for (k, v) in j.origin.rpy_rad.iter().enumerate() {
        within(
            format!("joint {} <origin rpy>[{k}]", j.name),
            j.line,
            *v,
            bounds::MAX_ROTATION_DEG.to_radians(),
            "rad",
            RADIANS,
        )?;
    }
    Ok(())
}

fn check_limit(j: &Joint, l: &super::read::Limit) -> Result<(), UrdfError> {
    let max_rad = bounds::MAX_JOINT_DEG.to_radians();
    for (what, v) in [("lower", l.lower_rad), ("upper", l.upper_rad)] {
        within(
            format!("joint {} <limit {what}>", j.name),
            j.line,
            v,
            max_rad,
            "rad",
            RADIANS,
        )?;
    }
    if l.lower_rad > l.upper_rad {
        return Err(UrdfError::Limits {
            joint: j.name.clone(),
            line: j.line,
            lower_rad: l.lower_rad,
            upper_rad: l.upper_rad,
        });
    }
    if let Some(v) = l.velocity_rad_s.filter(|v| *v != 0.0) {
        let (lo, hi) = bounds::SPEED_DEG_S;
        let deg = v.to_degrees();
        if !(lo..=hi).contains(&deg) {
            return Err(UrdfError::OutOfRange {
                element: format!("joint {} <limit velocity>", j.name),
                line: j.line,
                value: v,
                range: format!("{:.4}..{:.1} rad/s", lo.to_radians(), hi.to_radians()),
                hint: "a URDF velocity is in rad/s: degrees per second? (0 means not given)",
            });
        }
    }
    Ok(())
}

/// The joint's axis as a coordinate axis, with the turn of its frame that puts a
/// slanted axis on `z` (none for a coordinate axis).
fn axis_of(j: &Joint) -> Result<(JointAxis, Option<Rotation3<f64>>), UrdfError> {
    let v = Vector3::from(j.axis);
    let n = v.norm();
    if !(n.is_finite() && n > 1e-9) {
        return Err(UrdfError::ZeroAxis {
            joint: j.name.clone(),
            line: j.line,
        });
    }
    let u = v / n;
    let coordinate = [
        (Vector3::x(), JointAxis::X),
        (-Vector3::x(), JointAxis::NegX),
        (Vector3::y(), JointAxis::Y),
        (-Vector3::y(), JointAxis::NegY),
        (Vector3::z(), JointAxis::Z),
        (-Vector3::z(), JointAxis::NegZ),
    ];
    if let Some((_, a)) = coordinate.iter().find(|(c, _)| *c == u) {
        return Ok((*a, None));
    }
    // Not ±z (those are coordinate axes): the shortest turn from z onto u exists.
    let turn =
        Rotation3::rotation_between(&Vector3::z(), &u).ok_or_else(|| UrdfError::ZeroAxis {
            joint: j.name.clone(),
            line: j.line,
        })?;
    Ok((JointAxis::Z, Some(turn)))
}

/// The mass hung on `link` by fixed joints (itself included), its centre in the frame
/// `back · link frame` (the joint's frame, turned back where its axis was turned).
fn link_mass(
    d: &Description,
    link: &str,
    back: &Rotation3<f64>,
) -> Result<Option<LinkMass>, UrdfError> {
    let mut kg = 0.0;
    let mut moment = Vector3::zeros();
    let mut names = Vec::new();
    // (link, its frame in the joint's), below fixed joints only.
    let mut stack = vec![(link.to_owned(), Placement::identity())];
    let mut seen = 0usize;
    while let Some((name, at)) = stack.pop() {
        seen += 1;
        if seen > d.links.len() {
            break;
        }
        if let Some(l) = d.links.iter().find(|l| l.name == name) {
            if let Some(Inertial { mass_kg, com_m }) = l.inertial {
                within(
                    format!("link {} <inertial><mass value>", l.name),
                    l.line,
                    mass_kg,
                    bounds::MAX_MASS_KG,
                    "kg",
                    "a URDF mass is in kilograms: grams?",
                )?;
                if mass_kg < 0.0 {
                    return Err(UrdfError::OutOfRange {
                        element: format!("link {} <inertial><mass value>", l.name),
                        line: l.line,
                        value: mass_kg,
                        range: format!("0..{} kg", bounds::MAX_MASS_KG),
                        hint: "a mass is not negative",
                    });
                }
                for (k, v) in com_m.iter().enumerate() {
                    within(
                        format!("link {} <inertial><origin xyz>[{k}]", l.name),
                        l.line,
                        *v,
                        bounds::MAX_LENGTH_M,
                        "m",
                        METRES,
                    )?;
                }
                kg += mass_kg;
                moment += (at.translation_m + at.rotation * com_m) * mass_kg;
                names.push(l.name.clone());
            }
        }
        for j in d
            .joints
            .iter()
            .filter(|j| j.parent == name && j.kind == JointKind::Fixed)
        {
            stack.push((
                j.child.clone(),
                compose(&at, &placement(j.origin.xyz_m, j.origin.rpy_rad)),
            ));
        }
    }
    if names.is_empty() {
        return Ok(None);
    }
    let com = if kg > 0.0 {
        moment / kg
    } else {
        Vector3::zeros()
    };
    Ok(Some(LinkMass {
        kg,
        com_m: back * com,
        links: names,
    }))
}
