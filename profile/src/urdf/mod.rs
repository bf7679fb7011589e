//! A profile from a robot's URDF (`zerocal profile import`): the arm's chain read out of
//! the file, its fixed joints folded, and written as a profile in the `urdf` form with
//! each value citing the file by name and SHA-256. What a URDF cannot give (how the
//! controller shows its joints and takes an offset, the flange's bolt circle, where the
//! brackets register) is left out and said in `missing` with what it costs; the
//! stage-1 pose and the flange bracket's mounting are derived from the kinematics.
//!
//! [`read`] reads the XML, [`chain`] finds and folds the arm, [`write`] writes the
//! profile; the written text is then read back by [`crate::parse`], so an import gives
//! a profile the product takes or an error naming what stops it.

pub mod chain;
pub mod read;
mod write;

use crate::{Family, Profile, ProfileError};
use sha2::{Digest, Sha256};
use std::fmt;

pub use chain::{ArmChain, Ends};
pub use read::MAX_URDF_BYTES;

/// What `zerocal profile import` is told besides the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImportOptions {
    /// The file's name as the profile cites it (no directories).
    pub file_name: String,
    /// Where the chain starts and ends.
    pub ends: Ends,
    /// The controller family: `Generic` writes no `[controller]` table (offsets in model
    /// terms); another writes the ROS-Industrial driver's convention for it.
    pub family: Family,
    /// The profile's name (default: from `<robot name>`).
    pub name: Option<String>,
}

/// A profile imported from a URDF.
#[derive(Clone, Debug)]
pub struct Imported {
    /// The profile's TOML, as written.
    pub toml: String,
    /// That TOML read back.
    pub profile: Profile,
    /// The arm as the URDF gives it.
    pub chain: ArmChain,
    /// The file's SHA-256, in hex.
    pub sha256: String,
}

/// Why a URDF was not imported.
#[derive(Clone, Debug, PartialEq)]
pub enum UrdfError {
    /// Larger than [`MAX_URDF_BYTES`].
    TooLarge {
        /// Its size.
        bytes: usize,
        /// The most read.
        max: usize,
    },
    /// Not UTF-8 text.
    NotUtf8 {
        /// The first byte that is not.
        at_byte: usize,
    },
    /// A xacro, not expanded.
    Xacro {
        /// Where.
        line: u32,
        /// What was found.
        what: &'static str,
    },
    /// Not well-formed XML (the parser's message, with its position).
    Xml(String),
    /// The root element is not `<robot>`.
    NotUrdf {
        /// The root's name.
        root: String,
    },
    /// A required attribute or element is missing.
    Missing {
        /// Where.
        element: String,
        /// Line.
        line: u32,
        /// What.
        what: &'static str,
    },
    /// Not a finite number (or not three).
    BadNumber {
        /// Where.
        element: String,
        /// Line.
        line: u32,
        /// The attribute.
        attribute: &'static str,
        /// Its text (the first 40 characters).
        text: String,
    },
    /// A joint type the URDF specification does not have.
    UnknownType {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// The type given.
        kind: String,
    },
    /// Two links or joints with one name.
    Duplicate {
        /// `link` or `joint`.
        what: &'static str,
        /// The name.
        name: String,
        /// The second one's line.
        line: u32,
    },
    /// A joint names a link the file does not have.
    UnknownLink {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// The link.
        link: String,
    },
    /// A link is the child of two joints (a closed chain).
    TwoParents {
        /// The link.
        link: String,
        /// The two joints.
        joints: [String; 2],
    },
    /// Joints whose parents lead round in a circle.
    Loop {
        /// A link on it.
        link: String,
    },
    /// `--base` or `--tip` names no link.
    NoSuchLink {
        /// The option.
        option: &'static str,
        /// The link named.
        link: String,
    },
    /// Several roots and no `base_link`.
    NoBase {
        /// The roots.
        roots: Vec<String>,
    },
    /// No `tool0` or `flange` link and no `--tip`.
    NoTip {
        /// The leaf links.
        leaves: Vec<String>,
    },
    /// The tip is not below the base.
    NotBelow {
        /// The tip.
        tip: String,
        /// The base.
        base: String,
    },
    /// A continuous joint in the chain: zerocal needs every joint's limits.
    Continuous {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
    },
    /// A prismatic, floating or planar joint in the chain.
    NotRevolute {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// Its type.
        kind: &'static str,
    },
    /// A joint in the chain that follows another (`<mimic>`).
    Mimic {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// The joint it follows.
        of: String,
    },
    /// Not six revolute joints from base to tip.
    JointCount {
        /// The base.
        base: String,
        /// The tip.
        tip: String,
        /// The revolute joints found.
        names: Vec<String>,
    },
    /// A joint that moves off the chain before link 6.
    Branch {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// Its type.
        kind: &'static str,
    },
    /// A revolute joint without `<limit>`.
    NoLimit {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
    },
    /// `lower` above `upper`.
    Limits {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
        /// `lower` (rad).
        lower_rad: f64,
        /// `upper` (rad).
        upper_rad: f64,
    },
    /// An axis of zero length.
    ZeroAxis {
        /// The joint.
        joint: String,
        /// Line.
        line: u32,
    },
    /// A value outside its plausible range (`crate::bounds`).
    OutOfRange {
        /// Where.
        element: String,
        /// Line.
        line: u32,
        /// The value, in the URDF's unit.
        value: f64,
        /// The range.
        range: String,
        /// The likely mistake.
        hint: &'static str,
    },
    /// The arm gives no stage-1 pose or no flange mounting.
    Derive {
        /// The profile key.
        key: &'static str,
        /// Why.
        reason: String,
    },
    /// The written profile does not read back (the key and reason).
    Profile(ProfileError),
}

/// How to expand a xacro, for its refusal.
pub const EXPAND_HINT: &str = "expand it first: in a ROS workspace `xacro FILE.xacro > FILE.urdf` (ROS 2: `ros2 run xacro xacro ...`); without ROS, `pip install xacro` gives the same expander, with each $(find PKG) pointed at your copy of the package (data/urdf/expand.py does this; docs/profiles.md)";

impl fmt::Display for UrdfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UrdfError::TooLarge { bytes, max } => write!(
                f,
                "{bytes} bytes: a URDF of one arm is kilobytes; at most {max} bytes are read (a mesh or a whole cell pasted in?)"
            ),
            UrdfError::NotUtf8 { at_byte } => {
                write!(f, "not UTF-8 text (byte {at_byte}): not a URDF")
            }
            UrdfError::Xacro { line, what } => write!(
                f,
                "line {line}: {what}: this is a xacro, not an expanded URDF; {EXPAND_HINT}"
            ),
            UrdfError::Xml(m) => write!(f, "not well-formed XML: {m}"),
            UrdfError::NotUrdf { root } => {
                write!(f, "the root element is <{root}>, not <robot>: not a URDF")
            }
            UrdfError::Missing {
                element,
                line,
                what,
            } => write!(f, "line {line}: {element} has no {what}"),
            UrdfError::BadNumber {
                element,
                line,
                attribute,
                text,
            } => write!(
                f,
                "line {line}: {element} {attribute}=\"{text}\" is not {}",
                if matches!(*attribute, "xyz" | "rpy") {
                    "three finite numbers"
                } else {
                    "a finite number"
                }
            ),
            UrdfError::UnknownType { joint, line, kind } => write!(
                f,
                "line {line}: joint {joint} has type \"{kind}\", which the URDF specification does not have"
            ),
            UrdfError::Duplicate { what, name, line } => {
                write!(f, "line {line}: a second {what} named {name}")
            }
            UrdfError::UnknownLink { joint, line, link } => {
                write!(f, "line {line}: joint {joint} names link {link}, which the file does not have")
            }
            UrdfError::TwoParents { link, joints } => write!(
                f,
                "link {link} is the child of two joints ({} and {}): a closed chain (a parallel linkage?); zerocal calibrates an open chain of six revolute joints",
                joints[0], joints[1]
            ),
            UrdfError::Loop { link } => write!(f, "the joints above link {link} lead round in a loop"),
            UrdfError::NoSuchLink { option, link } => {
                write!(f, "{option} {link}: the file has no such link")
            }
            UrdfError::NoBase { roots } => write!(
                f,
                "{} root links ({}) and none is base_link: name the arm's base with --base",
                roots.len(),
                roots.join(", ")
            ),
            UrdfError::NoTip { leaves } => write!(
                f,
                "no tool0 or flange link: name the flange frame with --tip (the chains end at: {})",
                leaves.join(", ")
            ),
            UrdfError::NotBelow { tip, base } => {
                write!(f, "link {tip} is not below link {base}: no chain joins them (check --base and --tip)")
            }
            UrdfError::Continuous { joint, line } => write!(
                f,
                "line {line}: joint {joint} is continuous: zerocal needs every joint's limits (the plan, the program's safety checks and stage 1's half turn stay inside them); make it revolute with the controller's <limit lower upper>"
            ),
            UrdfError::NotRevolute { joint, line, kind } => write!(
                f,
                "line {line}: joint {joint} is {kind}: zerocal calibrates six revolute joints, and a {kind} joint in the chain (a track, a lift?) is not one; give --base after it"
            ),
            UrdfError::Mimic { joint, line, of } => write!(
                f,
                "line {line}: joint {joint} mimics {of}: a joint that follows another is not one zerocal can find the zero of"
            ),
            UrdfError::JointCount { base, tip, names } => write!(
                f,
                "{} revolute joints from {base} to {tip} ({}): zerocal calibrates six-axis arms (a 7th axis or a track: pick the six with --base and --tip)",
                names.len(),
                if names.is_empty() { String::from("none") } else { names.join(", ") }
            ),
            UrdfError::Branch { joint, line, kind } => write!(
                f,
                "line {line}: joint {joint} ({kind}) moves off the arm's chain before link 6: a branch (a second arm, an external axis, a linkage) that zerocal's model of one chain cannot hold"
            ),
            UrdfError::NoLimit { joint, line } => write!(
                f,
                "line {line}: revolute joint {joint} has no <limit>: the URDF specification requires one, and zerocal plans within it"
            ),
            UrdfError::Limits {
                joint,
                line,
                lower_rad,
                upper_rad,
            } => write!(
                f,
                "line {line}: joint {joint} <limit lower=\"{lower_rad}\"> is above upper=\"{upper_rad}\""
            ),
            UrdfError::ZeroAxis { joint, line } => {
                write!(f, "line {line}: joint {joint} <axis xyz> has no direction")
            }
            UrdfError::OutOfRange {
                element,
                line,
                value,
                range,
                hint,
            } => write!(
                f,
                "line {line}: {element} = {} is outside {range} ({hint})",
                crate::bounds::short(*value)
            ),
            UrdfError::Derive { key, reason } => write!(f, "{key}: {reason}"),
            UrdfError::Profile(e) => write!(f, "the written profile does not read: {e}"),
        }
    }
}

impl std::error::Error for UrdfError {}

/// The file's SHA-256, in lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Imports a URDF: read, chain, profile written and read back.
///
/// # Errors
/// What [`read::read`] and [`chain::arm_chain`] refuse; an arm with no stage-1 pose or
/// flange mounting; a written profile that does not read (its key named).
pub fn import(bytes: &[u8], options: &ImportOptions) -> Result<Imported, UrdfError> {
    let description = read::read(bytes)?;
    let chain = chain::arm_chain(&description, &options.ends)?;
    let sha256 = sha256_hex(bytes);
    let toml = write::profile_toml(&description, &chain, options, &sha256)?;
    let profile = crate::parse(&toml).map_err(UrdfError::Profile)?;
    Ok(Imported {
        toml,
        profile,
        chain,
        sha256,
    })
}

#[cfg(test)]
mod tests;
