//! A URDF file read into its links and joints (roxmltree: a read-only XML tree that
//! keeps each node's position, so every refusal names the element and its line).
//!
//! Only what a profile takes is read: each link's name and `<inertial>` (mass and
//! centre of mass), each joint's name, type, parent, child, `<origin>`, `<axis>`,
//! `<limit>` and whether it has a `<mimic>`. Visuals, collisions, transmissions and
//! plugins are skipped, whatever they hold. Values keep the URDF's units (metres,
//! radians, rad/s, kg); the ranges are checked where a value is used
//! ([`super::chain`]).

use super::UrdfError;
use nalgebra::Vector3;

/// Largest URDF file read (bytes). An expanded ROS-Industrial description of a
/// six-axis arm is 5 to 10 KB (`data/urdf/`); a megabyte is a hundred times that, room
/// for long comments, transmissions and simulator plugins. A file beyond it is not one
/// arm's description (a mesh pasted in, a whole cell, a hostile file) and is not read.
pub const MAX_URDF_BYTES: usize = 1 << 20;

/// Most XML nodes read: a megabyte of the smallest elements; a bound on the tree's
/// memory whatever the bytes.
const MAX_NODES: u32 = 1 << 18;

/// A joint's type, as the URDF names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    /// Turns within limits.
    Revolute,
    /// Turns without limits.
    Continuous,
    /// Slides.
    Prismatic,
    /// Does not move.
    Fixed,
    /// Six degrees of freedom.
    Floating,
    /// Two translations and a rotation.
    Planar,
}

impl JointKind {
    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "revolute" => JointKind::Revolute,
            "continuous" => JointKind::Continuous,
            "prismatic" => JointKind::Prismatic,
            "fixed" => JointKind::Fixed,
            "floating" => JointKind::Floating,
            "planar" => JointKind::Planar,
            _ => return None,
        })
    }

    /// The URDF's word for it.
    pub fn name(self) -> &'static str {
        match self {
            JointKind::Revolute => "revolute",
            JointKind::Continuous => "continuous",
            JointKind::Prismatic => "prismatic",
            JointKind::Fixed => "fixed",
            JointKind::Floating => "floating",
            JointKind::Planar => "planar",
        }
    }
}

/// An `<origin>`: the child frame in the parent's (URDF: translation, then fixed-axis
/// roll, pitch, yaw).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Origin {
    /// `xyz` (m).
    pub xyz_m: [f64; 3],
    /// `rpy` (rad).
    pub rpy_rad: [f64; 3],
}

/// A link's `<inertial>`: what the sag model takes of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertial {
    /// `<mass value>` (kg).
    pub mass_kg: f64,
    /// Its `<origin xyz>`: the centre of mass in the link's frame (m).
    pub com_m: Vector3<f64>,
}

/// One `<link>`.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// Its name.
    pub name: String,
    /// Its line in the file.
    pub line: u32,
    /// Its `<inertial>`, if it has one.
    pub inertial: Option<Inertial>,
}

/// A joint's `<limit>`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// `lower` (rad).
    pub lower_rad: f64,
    /// `upper` (rad).
    pub upper_rad: f64,
    /// `velocity` (rad/s), if given.
    pub velocity_rad_s: Option<f64>,
}

/// One `<joint>`.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// Its name.
    pub name: String,
    /// Its line in the file.
    pub line: u32,
    /// Its type.
    pub kind: JointKind,
    /// `<parent link>`.
    pub parent: String,
    /// `<child link>`.
    pub child: String,
    /// `<origin>` (identity when absent, as the URDF specification has it).
    pub origin: Origin,
    /// `<axis xyz>` (the specification's default `1 0 0` when absent).
    pub axis: [f64; 3],
    /// `<limit>`, if given.
    pub limit: Option<Limit>,
    /// The joint a `<mimic>` follows, if it has one.
    pub mimic: Option<String>,
}

/// A URDF's robot: its name, links and joints in the file's order.
#[derive(Clone, Debug, PartialEq)]
pub struct Description {
    /// `<robot name>`.
    pub name: String,
    /// Every `<link>`.
    pub links: Vec<Link>,
    /// Every `<joint>`.
    pub joints: Vec<Joint>,
}

/// Reads a URDF: at most [`MAX_URDF_BYTES`], UTF-8, expanded (no xacro left), well-formed
/// XML with a `<robot>` root, every link and joint with what the specification requires
/// and every number finite.
///
/// # Errors
/// The first of those that fails, naming the element, its line and the attribute.
pub fn read(bytes: &[u8]) -> Result<Description, UrdfError> {
    if bytes.len() > MAX_URDF_BYTES {
        return Err(UrdfError::TooLarge {
            bytes: bytes.len(),
            max: MAX_URDF_BYTES,
        });
    }
    let text = std::str::from_utf8(bytes).map_err(|e| UrdfError::NotUtf8 {
        at_byte: e.valid_up_to(),
    })?;
    let options = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, options).map_err(|e| {
        // A xacro whose namespace is not declared is not XML: say what it is.
        match xacro_element_in_text(text) {
            Some(line) => UrdfError::Xacro {
                line,
                what: "a <xacro:...> element",
            },
            None => UrdfError::Xml(e.to_string()),
        }
    })?;
    let root = doc.root_element();
    if let Some((line, what)) = xacro_left(&doc) {
        return Err(UrdfError::Xacro { line, what });
    }
    if root.tag_name().name() != "robot" {
        return Err(UrdfError::NotUrdf {
            root: root.tag_name().name().to_owned(),
        });
    }
    let line = |n: roxmltree::Node<'_, '_>| doc.text_pos_at(n.range().start).row;
    let mut links = Vec::new();
    let mut joints = Vec::new();
    for node in root.children().filter(roxmltree::Node::is_element) {
        match node.tag_name().name() {
            "link" => links.push(Link {
                name: required(node, "name", line(node))?.to_owned(),
                line: line(node),
                inertial: inertial(node, line)?,
            }),
            "joint" => joints.push(joint(node, line)?),
            _ => {}
        }
    }
    Ok(Description {
        name: root.attribute("name").unwrap_or("").to_owned(),
        links,
        joints,
    })
}

/// The line of the first `<xacro:` in the text, for a file that is not XML.
fn xacro_element_in_text(text: &str) -> Option<u32> {
    text.lines()
        .position(|l| l.contains("<xacro:"))
        .map(|i| u32::try_from(i + 1).unwrap_or(u32::MAX))
}

/// What is left of xacro in a parsed file, with its line: an element of its namespace
/// (`<xacro:include>`, `<xacro:macro>`, ...), or a `${...}` expression or `$(...)`
/// substitution in an attribute. The namespace declaration alone is not: ROS 1's xacro
/// leaves it on the `<robot>` it expanded. Comments may hold anything: not read.
fn xacro_left(doc: &roxmltree::Document<'_>) -> Option<(u32, &'static str)> {
    doc.descendants().find_map(|n| {
        let at = |pos: usize| doc.text_pos_at(pos).row;
        if n.is_element()
            && n.tag_name()
                .namespace()
                .is_some_and(|ns| ns.contains("wiki/xacro"))
        {
            return Some((at(n.range().start), "a <xacro:...> element"));
        }
        n.attributes().find_map(|a| {
            let what = if a.value().contains("${") {
                "an unexpanded ${...} expression"
            } else if a.value().contains("$(") {
                "an unexpanded $(...) substitution"
            } else {
                return None;
            };
            Some((at(a.range().start), what))
        })
    })
}

type Node<'a, 'i> = roxmltree::Node<'a, 'i>;

fn required<'a>(
    node: Node<'a, '_>,
    attribute: &'static str,
    line: u32,
) -> Result<&'a str, UrdfError> {
    node.attribute(attribute).ok_or_else(|| UrdfError::Missing {
        element: node.tag_name().name().to_owned(),
        line,
        what: attribute,
    })
}

fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// A finite number.
fn number(text: &str, element: &str, line: u32, attribute: &'static str) -> Result<f64, UrdfError> {
    let bad = || UrdfError::BadNumber {
        element: element.to_owned(),
        line,
        attribute,
        text: text.chars().take(40).collect(),
    };
    let v: f64 = text.trim().parse().map_err(|_| bad())?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(bad())
    }
}

/// Three finite numbers separated by white space.
fn three(
    text: &str,
    element: &str,
    line: u32,
    attribute: &'static str,
) -> Result<[f64; 3], UrdfError> {
    let parts: Vec<&str> = text.split_whitespace().collect();
    if parts.len() != 3 {
        return Err(UrdfError::BadNumber {
            element: element.to_owned(),
            line,
            attribute,
            text: text.chars().take(40).collect(),
        });
    }
    let mut out = [0.0; 3];
    for (o, p) in out.iter_mut().zip(parts) {
        // The whole attribute in the message, not the one bad number.
        *o = number(p, element, line, attribute).map_err(|_| UrdfError::BadNumber {
            element: element.to_owned(),
            line,
            attribute,
            text: text.chars().take(40).collect(),
        })?;
    }
    Ok(out)
}

/// An `<origin>` child of `node`, identity when absent; `what` names the owner in
/// messages (`joint joint_a2`).
fn origin(node: Node<'_, '_>, what: &str, line: u32) -> Result<Origin, UrdfError> {
    let Some(o) = child(node, "origin") else {
        return Ok(Origin {
            xyz_m: [0.0; 3],
            rpy_rad: [0.0; 3],
        });
    };
    let element = format!("{what} <origin>");
    Ok(Origin {
        xyz_m: o
            .attribute("xyz")
            .map_or(Ok([0.0; 3]), |t| three(t, &element, line, "xyz"))?,
        rpy_rad: o
            .attribute("rpy")
            .map_or(Ok([0.0; 3]), |t| three(t, &element, line, "rpy"))?,
    })
}

fn inertial(
    link: Node<'_, '_>,
    line: impl Fn(Node<'_, '_>) -> u32,
) -> Result<Option<Inertial>, UrdfError> {
    let Some(i) = child(link, "inertial") else {
        return Ok(None);
    };
    let name = link.attribute("name").unwrap_or("");
    let at = line(i);
    let element = format!("link {name} <inertial>");
    let mass = child(i, "mass").ok_or_else(|| UrdfError::Missing {
        element: element.clone(),
        line: at,
        what: "<mass>",
    })?;
    let mass_kg = number(
        required(mass, "value", line(mass))?,
        &format!("{element} <mass>"),
        line(mass),
        "value",
    )?;
    let o = origin(i, &element, at)?;
    Ok(Some(Inertial {
        mass_kg,
        com_m: Vector3::from(o.xyz_m),
    }))
}

fn joint(node: Node<'_, '_>, line: impl Fn(Node<'_, '_>) -> u32) -> Result<Joint, UrdfError> {
    let at = line(node);
    let name = required(node, "name", at)?.to_owned();
    let what = format!("joint {name}");
    let kind_text = required(node, "type", at)?;
    let kind = JointKind::parse(kind_text).ok_or_else(|| UrdfError::UnknownType {
        joint: name.clone(),
        line: at,
        kind: kind_text.chars().take(40).collect(),
    })?;
    let link_of = |tag: &'static str| -> Result<String, UrdfError> {
        let n = child(node, tag).ok_or_else(|| UrdfError::Missing {
            element: what.clone(),
            line: at,
            what: tag,
        })?;
        Ok(required(n, "link", line(n))?.to_owned())
    };
    let parent = link_of("parent")?;
    let child_link = link_of("child")?;
    let axis = match child(node, "axis") {
        Some(a) => three(
            required(a, "xyz", line(a))?,
            &format!("{what} <axis>"),
            line(a),
            "xyz",
        )?,
        None => [1.0, 0.0, 0.0],
    };
    let limit = match child(node, "limit") {
        None => None,
        Some(l) => {
            let element = format!("{what} <limit>");
            let at = line(l);
            let get = |attribute: &'static str, default: Option<f64>| match l.attribute(attribute) {
                Some(t) => number(t, &element, at, attribute).map(Some),
                None => Ok(default),
            };
            Some(Limit {
                // The specification's defaults: 0 for lower and upper.
                lower_rad: get("lower", Some(0.0))?.unwrap_or(0.0),
                upper_rad: get("upper", Some(0.0))?.unwrap_or(0.0),
                velocity_rad_s: get("velocity", None)?,
            })
        }
    };
    let mimic = child(node, "mimic").map(|m| m.attribute("joint").unwrap_or("").to_owned());
    Ok(Joint {
        origin: origin(node, &what, at)?,
        name,
        line: at,
        kind,
        parent,
        child: child_link,
        axis,
        limit,
        mimic,
    })
}
