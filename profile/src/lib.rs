//! Robot profiles: one robot model described to zerocal in a versioned TOML format
//! (`docs/profiles.md`), read into core's [`Arm`] and the controller's conventions.
//!
//! A profile gives the kinematics (URDF joint origins and axes, standard or modified
//! DH), the limits, what the controller shows for each joint (sign, zero, FANUC's J2/J3
//! coupling), how it takes a zero offset (degrees, motor radians, encoder counts), the
//! stage-1 pose, the flange bracket, and the source of every number. Where no source
//! gives a value, the profile leaves it out and says so in `missing`: zerocal refuses
//! what needs it rather than guess.
//!
//! Built-in profiles are the files of `data/robots/`, compiled in ([`builtin`]). A
//! profile of any other six-axis arm is imported from its URDF ([`urdf`]).

pub mod bounds;
mod controller;
mod entry;
pub mod flange;
mod raw;
pub mod urdf;

pub use controller::{Controller, Coupling, OffsetUnit, OffsetValue};
pub use entry::{EntryKnowledge, Known};
pub use flange::{FlangeInterface, Iso9409};

use nalgebra::{Rotation3, Unit, Vector3};
use std::fmt;
use zerocal_core::model::{
    rot_x, rot_z, rotation_from_rpy_deg, Arm, Joint, JointAxis, Placement, JOINTS,
};
use zerocal_core::stage2::MassModel;

/// The format this crate reads.
pub const FORMAT: u32 = 1;

/// The robot families zerocal knows the controllers of (`docs/controllers/`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// KUKA KRC.
    Kuka,
    /// ABB IRC5 / OmniCore.
    Abb,
    /// FANUC R-30iB.
    Fanuc,
    /// Yaskawa Motoman.
    Yaskawa,
    /// Stäubli CS8/CS9.
    Staubli,
    /// Universal Robots.
    Ur,
    /// Anything else (degrees, no controller conventions).
    Generic,
}

impl Family {
    /// The name in profiles and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Family::Kuka => "kuka",
            Family::Abb => "abb",
            Family::Fanuc => "fanuc",
            Family::Yaskawa => "yaskawa",
            Family::Staubli => "staubli",
            Family::Ur => "ur",
            Family::Generic => "generic",
        }
    }

    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "kuka" => Family::Kuka,
            "abb" => Family::Abb,
            "fanuc" => Family::Fanuc,
            "yaskawa" => Family::Yaskawa,
            "staubli" => Family::Staubli,
            "ur" => Family::Ur,
            "generic" => Family::Generic,
            _ => return None,
        })
    }
}

/// A cited source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Source {
    /// Its id (`S1`).
    pub id: String,
    /// What and where.
    pub cite: String,
}

/// One joint's limits and physical data, in the model's angle.
#[derive(Clone, Debug, PartialEq)]
pub struct JointInfo {
    /// The controller's name for it (`A2`, `J2`).
    pub name: String,
    /// Lowest angle (deg).
    pub min_deg: f64,
    /// Highest angle (deg).
    pub max_deg: f64,
    /// Top speed (deg/s), if a source gives it.
    pub max_speed_deg_s: Option<f64>,
}

/// A robot profile, checked and ready.
#[derive(Clone, Debug)]
pub struct Profile {
    /// What `--robot` takes.
    pub name: String,
    /// The robot's name.
    pub title: String,
    /// Its controller family.
    pub family: Family,
    /// What no public source gave.
    pub missing: Vec<String>,
    /// The sources.
    pub sources: Vec<Source>,
    /// Joints 1-6.
    pub joints: Vec<JointInfo>,
    /// The kinematics with the two brackets placed.
    pub arm: Arm<f64>,
    /// The links' masses from the sources, if every link beyond joint 2 has one.
    pub masses: Option<MassModel<f64>>,
    /// What the controller shows and takes.
    pub controller: Controller,
    /// Whether the profile has a `[controller]` table; without one, [`Self::controller`]
    /// is [`Controller::model_terms`]: offsets in model terms only.
    pub controller_stated: bool,
    /// Whether its `[controller]` says in what unit and where an offset is entered
    /// (`offset_unit`, `offset_where`, `offset_source`).
    pub offset_entry_stated: bool,
    /// The stage-1 pose in the model's angles (rad): the profile's `stage1.pose_deg`
    /// turned to no gravity torque on joints 2 and 3 (`zerocal_core::plan::stage1`),
    /// as the pendant, the program and every shown pose use it.
    pub stage1_joints_rad: [f64; JOINTS],
    /// The profile's `stage1.pose_deg` in the model's angles (rad): where the search
    /// for [`Self::stage1_joints_rad`] starts.
    pub stage1_stated_rad: [f64; JOINTS],
    /// The flange's bolt circle and dowel (`[flange] iso9409`, `dowel_hole_mm`), where
    /// a source gives them: what `zerocal bracket` drills the flange bracket to.
    pub flange_interface: Option<FlangeInterface>,
    /// What the upper-arm bracket registers on (`stage1.registers_on`).
    pub upper_arm_registers_on: Option<String>,
    /// What the flange bracket registers on (`stage2.registers_on`).
    pub flange_registers_on: Option<String>,
}

/// What is wrong with a profile: the key and the reason.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProfileError {
    /// Where (`joint 3: axis`, `controller.sign`).
    pub key: String,
    /// Why.
    pub reason: String,
}

impl ProfileError {
    fn new(key: impl Into<String>, reason: impl Into<String>) -> Self {
        ProfileError {
            key: key.into(),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.reason)
    }
}

impl std::error::Error for ProfileError {}

/// The built-in profiles' TOML, by file stem.
const BUILTIN: [(&str, &str); 12] = [
    (
        "paper-wrist",
        include_str!("../../data/robots/paper-wrist.toml"),
    ),
    (
        "abb-irb140",
        include_str!("../../data/robots/abb-irb140.toml"),
    ),
    (
        "abb-irb2600",
        include_str!("../../data/robots/abb-irb2600.toml"),
    ),
    (
        "kuka-kr6-r900-sixx",
        include_str!("../../data/robots/kuka-kr6-r900-sixx.toml"),
    ),
    (
        "kuka-kr16",
        include_str!("../../data/robots/kuka-kr16.toml"),
    ),
    (
        "fanuc-lrmate200id",
        include_str!("../../data/robots/fanuc-lrmate200id.toml"),
    ),
    (
        "fanuc-m20ia",
        include_str!("../../data/robots/fanuc-m20ia.toml"),
    ),
    (
        "yaskawa-gp7",
        include_str!("../../data/robots/yaskawa-gp7.toml"),
    ),
    (
        "yaskawa-mh5lf",
        include_str!("../../data/robots/yaskawa-mh5lf.toml"),
    ),
    (
        "staubli-tx2-60",
        include_str!("../../data/robots/staubli-tx2-60.toml"),
    ),
    ("ur5e", include_str!("../../data/robots/ur5e.toml")),
    ("puma560", include_str!("../../data/robots/puma560.toml")),
];

/// The names of the built-in profiles.
pub fn builtin_names() -> impl Iterator<Item = &'static str> {
    BUILTIN.iter().map(|(name, _)| *name)
}

/// A built-in profile's TOML text, by name.
pub fn builtin_text(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// A built-in profile by name.
///
/// # Errors
/// An unknown name (the message lists the known ones), or a built-in that does not
/// read (a bug: the tests read them all).
pub fn builtin(name: &str) -> Result<Profile, ProfileError> {
    let (_, text) = BUILTIN.iter().find(|(n, _)| *n == name).ok_or_else(|| {
        ProfileError::new(
            "robot",
            format!(
                "no built-in profile '{name}'; known: {}",
                builtin_names().collect::<Vec<_>>().join(", ")
            ),
        )
    })?;
    parse(text)
}

/// Whether [`load`] reads `name_or_path` as a file: not a built-in name, and a path
/// ending in `.toml` or naming something that exists.
pub fn is_file(name_or_path: &str) -> bool {
    if builtin_names().any(|n| n == name_or_path) {
        return false;
    }
    let path = std::path::Path::new(name_or_path);
    path.extension().is_some_and(|e| e == "toml") || path.exists()
}

/// Parses the text of the profile file `path`: as [`parse`], each key prefixed by the
/// path.
///
/// # Errors
/// What [`parse`] refuses.
pub fn parse_file(path: &str, text: &str) -> Result<Profile, ProfileError> {
    parse(text).map_err(|e| ProfileError::new(format!("{path}: {}", e.key), e.reason))
}

/// Reads a profile: a built-in name, or a TOML file's path (at most
/// [`bounds::MAX_PROFILE_BYTES`], read no further).
///
/// # Errors
/// An unreadable or too long file, or what [`parse`] refuses.
pub fn load(name_or_path: &str) -> Result<Profile, ProfileError> {
    if !is_file(name_or_path) {
        return builtin(name_or_path);
    }
    let cap = bounds::MAX_PROFILE_BYTES;
    let mut bytes = Vec::new();
    std::fs::File::open(name_or_path)
        .and_then(|f| {
            std::io::Read::read_to_end(&mut std::io::Read::take(f, cap as u64 + 1), &mut bytes)
        })
        .map_err(|e| ProfileError::new(name_or_path, format!("cannot read: {e}")))?;
    if bytes.len() > cap {
        return Err(ProfileError::new(
            name_or_path,
            format!("longer than {cap} bytes, the most a profile file holds; not read"),
        ));
    }
    let text =
        String::from_utf8(bytes).map_err(|_| ProfileError::new(name_or_path, "not UTF-8 text"))?;
    parse_file(name_or_path, &text)
}

/// Parses and checks a profile.
///
/// # Errors
/// Unknown keys, a wrong format, not six joints, a bad axis, limits or pose, mount axes
/// that are not perpendicular, an undefined source id: each naming the key.
pub fn parse(text: &str) -> Result<Profile, ProfileError> {
    let raw: raw::Profile =
        toml::from_str(text).map_err(|e| ProfileError::new("toml", e.message().to_owned()))?;
    raw.build()
}

/// A signed coordinate axis from a unit vector.
fn joint_axis(v: [f64; 3], key: &str) -> Result<JointAxis, ProfileError> {
    let axis = match v {
        [x, y, z] if y == 0.0 && z == 0.0 && x == 1.0 => JointAxis::X,
        [x, y, z] if y == 0.0 && z == 0.0 && x == -1.0 => JointAxis::NegX,
        [x, y, z] if x == 0.0 && z == 0.0 && y == 1.0 => JointAxis::Y,
        [x, y, z] if x == 0.0 && z == 0.0 && y == -1.0 => JointAxis::NegY,
        [x, y, z] if x == 0.0 && y == 0.0 && z == 1.0 => JointAxis::Z,
        [x, y, z] if x == 0.0 && y == 0.0 && z == -1.0 => JointAxis::NegZ,
        _ => {
            return Err(ProfileError::new(
                key,
                format!("{v:?} is not ±x, ±y or ±z (format 1 takes coordinate axes only)"),
            ))
        }
    };
    Ok(axis)
}

/// `Tz(d)·Tx(a)·Rx(α)` as a placement: the part of a standard DH transform after the
/// joint's rotation about z.
fn dh_after(a_m: f64, alpha_deg: f64, d_m: f64) -> Placement<f64> {
    Placement {
        rotation: rot_x(alpha_deg.to_radians()),
        translation_m: Vector3::new(a_m, 0.0, d_m),
    }
}

/// `p ∘ q`: q placed in p.
fn compose(p: &Placement<f64>, q: &Placement<f64>) -> Placement<f64> {
    Placement {
        rotation: p.rotation * q.rotation,
        translation_m: p.translation_m + p.rotation * q.translation_m,
    }
}

/// The pendant on the upper arm: its x along joint 2's axis, its z up, at the stage-1
/// pose of `arm` (model angles, level base).
fn upper_arm_mount(arm: &Arm<f64>, stage1: &[f64; JOINTS]) -> Result<Rotation3<f64>, ProfileError> {
    let link2 = arm.link2(
        &zerocal_core::model::BaseTilt::level(),
        stage1[0],
        stage1[1],
    );
    let axis2 = link2 * arm.joints[1].axis.unit::<f64>();
    let up = Vector3::z();
    if axis2.dot(&up).abs() > 1e-9 {
        return Err(ProfileError::new(
            "stage1.pose_deg",
            format!(
                "joint 2's axis is {:.3} deg from horizontal there: the half turn of axis 1 needs it level",
                axis2.dot(&up).asin().to_degrees()
            ),
        ));
    }
    let x = Unit::new_normalize(Vector3::new(axis2.x, axis2.y, 0.0)).into_inner();
    let y = up.cross(&x);
    let sensor = Rotation3::from_basis_unchecked(&[x, y, up]);
    Ok(link2.inverse() * sensor)
}

/// The pendant on the flange from the two axes the profile names.
fn flange_mount(z: &str, x: &str) -> Result<Rotation3<f64>, ProfileError> {
    let axis = |s: &str, key: &str| {
        let a = match s.trim() {
            "x" | "+x" => Vector3::x(),
            "-x" => -Vector3::x(),
            "y" | "+y" => Vector3::y(),
            "-y" => -Vector3::y(),
            "z" | "+z" => Vector3::z(),
            "-z" => -Vector3::z(),
            other => {
                return Err(ProfileError::new(
                    key,
                    format!("'{other}' is not one of x, -x, y, -y, z, -z"),
                ))
            }
        };
        Ok(a)
    };
    let zv = axis(z, "stage2.mount_z")?;
    let xv = axis(x, "stage2.mount_x")?;
    if zv.dot(&xv) != 0.0 {
        return Err(ProfileError::new(
            "stage2.mount_x",
            "must be perpendicular to mount_z",
        ));
    }
    Ok(Rotation3::from_basis_unchecked(&[xv, zv.cross(&xv), zv]))
}

/// Builds the placements of a profile's joints and its flange.
fn kinematics(raw: &raw::Profile) -> Result<([Joint<f64>; JOINTS], Placement<f64>), ProfileError> {
    let form = raw.kinematics.form.as_str();
    let mut joints = [Joint {
        origin: Placement::identity(),
        axis: JointAxis::Z,
    }; JOINTS];
    // The DH forms: what follows joint k's rotation before joint k+1's frame.
    let mut after_previous = Placement::identity();
    for (k, j) in raw.joint.iter().enumerate() {
        let key = |what: &str| format!("joint {}: {what}", k + 1);
        let need = |v: Option<f64>, what: &str| {
            v.filter(|x| x.is_finite()).ok_or_else(|| {
                ProfileError::new(key(what), format!("form '{form}' needs a finite {what}"))
            })
        };
        match form {
            "urdf" => {
                let xyz = j
                    .xyz_m
                    .ok_or_else(|| ProfileError::new(key("xyz_m"), "missing"))?;
                let rpy = j
                    .rpy_deg
                    .ok_or_else(|| ProfileError::new(key("rpy_deg"), "missing"))?;
                let axis = j
                    .axis
                    .ok_or_else(|| ProfileError::new(key("axis"), "missing"))?;
                if xyz.iter().chain(&rpy).chain(&axis).any(|v| !v.is_finite()) {
                    return Err(ProfileError::new(key("origin"), "not finite"));
                }
                joints[k] = Joint {
                    origin: Placement {
                        rotation: rotation_from_rpy_deg(rpy[0], rpy[1], rpy[2]),
                        translation_m: Vector3::from(xyz),
                    },
                    axis: joint_axis(axis, &key("axis"))?,
                };
            }
            "dh" => {
                let (a, alpha, d, theta) = (
                    need(j.a_m, "a_m")?,
                    need(j.alpha_deg, "alpha_deg")?,
                    need(j.d_m, "d_m")?,
                    need(j.theta_deg, "theta_deg")?,
                );
                let offset = Placement {
                    rotation: rot_z(theta.to_radians()),
                    translation_m: Vector3::zeros(),
                };
                joints[k] = Joint {
                    origin: compose(&after_previous, &offset),
                    axis: JointAxis::Z,
                };
                after_previous = dh_after(a, alpha, d);
            }
            "mdh" => {
                let (a, alpha, d, theta) = (
                    need(j.a_m, "a_m")?,
                    need(j.alpha_deg, "alpha_deg")?,
                    need(j.d_m, "d_m")?,
                    need(j.theta_deg, "theta_deg")?,
                );
                // Craig: Rx(α_{i−1})·Tx(a_{i−1})·Rz(θᵢ)·Tz(dᵢ); Tz commutes with Rz.
                joints[k] = Joint {
                    origin: Placement {
                        rotation: rot_x(alpha.to_radians()) * rot_z(theta.to_radians()),
                        translation_m: Vector3::new(a, 0.0, 0.0)
                            + rot_x(alpha.to_radians()) * Vector3::new(0.0, 0.0, d),
                    },
                    axis: JointAxis::Z,
                };
            }
            other => {
                return Err(ProfileError::new(
                    "kinematics.form",
                    format!("'{other}' is not urdf, dh or mdh"),
                ))
            }
        }
    }
    let flange_raw = raw.flange.as_ref();
    let flange = Placement {
        rotation: flange_raw
            .and_then(|f| f.rpy_deg)
            .map_or(Rotation3::identity(), |r| {
                rotation_from_rpy_deg(r[0], r[1], r[2])
            }),
        translation_m: flange_raw
            .and_then(|f| f.xyz_m)
            .map_or(Vector3::zeros(), Vector3::from),
    };
    let flange = if form == "dh" {
        compose(&after_previous, &flange)
    } else {
        flange
    };
    Ok((joints, flange))
}

impl Profile {
    /// The controller's values (deg) of a pose in the model's angles (rad).
    pub fn shown_deg(&self, model_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        self.controller.shown_deg(model_rad)
    }

    /// The model's angles (rad) of a pose in the controller's values (deg).
    pub fn model_rad(&self, shown_deg: &[f64; JOINTS]) -> [f64; JOINTS] {
        self.controller.model_rad(shown_deg)
    }

    /// Whether a pose (model angles) is inside the joint limits; else the first joint
    /// outside (1-based) and its limits (deg).
    pub fn outside_limits(&self, model_rad: &[f64; JOINTS]) -> Option<(usize, f64, f64, f64)> {
        self.joints
            .iter()
            .zip(model_rad)
            .enumerate()
            .find_map(|(k, (j, q))| {
                let d = q.to_degrees();
                (!(j.min_deg..=j.max_deg).contains(&d)).then_some((k + 1, d, j.min_deg, j.max_deg))
            })
    }

    /// The sag model's masses: the sources' with the pendant on the flange
    /// (`MassModel::with_pendant`), or links of uniform mass per metre (the stated
    /// default, `MassModel::uniform`: relative masses only, so no pendant in kilograms
    /// beside them). `None` for an arm without lengths.
    pub fn mass_model(&self) -> Option<MassModel<f64>> {
        mass_model_of(self.masses, &self.arm)
    }
}

/// The sources' masses, or links of uniform mass per metre; `None` when the links
/// beyond joint 2 have no length (nothing for gravity to load).
fn mass_model_of(masses: Option<MassModel<f64>>, arm: &Arm<f64>) -> Option<MassModel<f64>> {
    if let Some(m) = masses {
        return Some(m.with_pendant(0.0));
    }
    let uniform = MassModel::uniform(arm);
    uniform
        .link_kg
        .iter()
        .skip(2)
        .any(|m| *m > 0.0)
        .then_some(uniform)
}

#[cfg(test)]
mod tests;
