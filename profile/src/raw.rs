//! The TOML as written, with every key known (`deny_unknown_fields`), and its checks.

use crate::bounds::{self, symmetric, text};
use crate::controller::{Controller, Coupling, OffsetUnit};
use crate::flange::{self, FlangeInterface};
use crate::{
    flange_mount, kinematics, upper_arm_mount, Family, JointInfo, ProfileError, Source, FORMAT,
};
use serde::Deserialize;
use std::collections::BTreeSet;
use zerocal_core::model::JOINTS;
use zerocal_core::plan::stage1::unloaded_stage1_pose;
use zerocal_core::stage2::MassModel;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Profile {
    format: u32,
    name: String,
    title: String,
    family: String,
    #[serde(default)]
    missing: Vec<String>,
    #[serde(default)]
    source: Vec<RawSource>,
    pub(crate) kinematics: Kinematics,
    pub(crate) joint: Vec<RawJoint>,
    pub(crate) flange: Option<Flange>,
    /// Absent: the controller shows the model's angles (offsets in model terms only).
    controller: Option<RawController>,
    stage1: Stage1,
    stage2: Stage2,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSource {
    id: String,
    cite: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Kinematics {
    pub(crate) form: String,
    source: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawJoint {
    name: String,
    pub(crate) xyz_m: Option<[f64; 3]>,
    pub(crate) rpy_deg: Option<[f64; 3]>,
    pub(crate) axis: Option<[f64; 3]>,
    pub(crate) a_m: Option<f64>,
    pub(crate) alpha_deg: Option<f64>,
    pub(crate) d_m: Option<f64>,
    pub(crate) theta_deg: Option<f64>,
    min_deg: f64,
    max_deg: f64,
    max_speed_deg_s: Option<f64>,
    limits_source: Option<String>,
    mass_kg: Option<f64>,
    com_m: Option<[f64; 3]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Flange {
    pub(crate) xyz_m: Option<[f64; 3]>,
    pub(crate) rpy_deg: Option<[f64; 3]>,
    iso9409: Option<String>,
    dowel_hole_mm: Option<f64>,
    interface_source: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawController {
    sign: [i8; JOINTS],
    zero_deg: [f64; JOINTS],
    coupling: String,
    source: String,
    /// `offset_unit`, `offset_where` and `offset_source` go together; absent, the
    /// offset is given in the controller's joint degrees, where to enter it unsaid.
    offset_unit: Option<String>,
    offset_where: Option<String>,
    offset_source: Option<String>,
    gear_ratio: Option<[f64; JOINTS]>,
    counts_per_deg: Option<[f64; JOINTS]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Stage1 {
    pose_deg: [f64; JOINTS],
    registers_on: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Stage2 {
    mount_z: String,
    mount_x: String,
    registers_on: Option<String>,
}

impl Profile {
    pub(crate) fn build(self) -> Result<crate::Profile, ProfileError> {
        if self.format != FORMAT {
            return Err(ProfileError::new(
                "format",
                format!(
                    "{} is not a format this zerocal reads ({FORMAT})",
                    self.format
                ),
            ));
        }
        self.check_bounds()?;
        let name_ok = !self.name.is_empty()
            && self
                .name
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
        if !name_ok {
            return Err(ProfileError::new(
                "name",
                "lowercase letters, digits and '-' only",
            ));
        }
        let family = Family::parse(&self.family).ok_or_else(|| {
            ProfileError::new(
                "family",
                format!(
                    "'{}' is not kuka, abb, fanuc, yaskawa, staubli, ur or generic",
                    self.family
                ),
            )
        })?;
        if self.joint.len() != JOINTS {
            return Err(ProfileError::new(
                "joint",
                format!("{} [[joint]] tables; a profile has six", self.joint.len()),
            ));
        }
        let ids: BTreeSet<&str> = self.source.iter().map(|s| s.id.as_str()).collect();
        let cited = |id: &str, key: &str| {
            if ids.contains(id) {
                Ok(())
            } else {
                Err(ProfileError::new(
                    key,
                    format!("source '{id}' is not defined by any [[source]]"),
                ))
            }
        };
        cited(&self.kinematics.source, "kinematics.source")?;
        if let Some(c) = &self.controller {
            cited(&c.source, "controller.source")?;
            if let Some(id) = &c.offset_source {
                cited(id, "controller.offset_source")?;
            }
        }
        let mut infos = Vec::with_capacity(JOINTS);
        for (k, j) in self.joint.iter().enumerate() {
            let key = |what: &str| format!("joint {}: {what}", k + 1);
            if !(j.min_deg.is_finite() && j.max_deg.is_finite() && j.min_deg <= j.max_deg) {
                return Err(ProfileError::new(
                    key("min_deg"),
                    "limits must be finite with min_deg <= max_deg",
                ));
            }
            if j.max_speed_deg_s
                .is_some_and(|v| !(v.is_finite() && v > 0.0))
            {
                return Err(ProfileError::new(key("max_speed_deg_s"), "must be > 0"));
            }
            if let Some(id) = &j.limits_source {
                cited(id, &key("limits_source"))?;
            }
            if j.mass_kg.is_some_and(|m| !(m.is_finite() && m >= 0.0)) {
                return Err(ProfileError::new(key("mass_kg"), "must be >= 0"));
            }
            if j.mass_kg.is_some() != j.com_m.is_some() {
                return Err(ProfileError::new(
                    key("mass_kg"),
                    "mass_kg and com_m go together",
                ));
            }
            infos.push(JointInfo {
                name: j.name.clone(),
                min_deg: j.min_deg,
                max_deg: j.max_deg,
                max_speed_deg_s: j.max_speed_deg_s,
            });
        }
        let flange_interface = self.flange_interface(&ids)?;
        let (joints, flange) = kinematics(&self)?;
        let controller = self.controller()?;
        let stated_rad = controller.model_rad(&self.stage1.pose_deg);
        let mut arm = zerocal_core::model::Arm {
            joints,
            flange,
            upper_arm_mount: nalgebra::Rotation3::identity(),
            flange_mount: flange_mount(&self.stage2.mount_z, &self.stage2.mount_x)?,
        };
        check_stage1(&infos, &stated_rad)?;
        let masses = self.masses();
        let stage1_joints_rad = unloaded_stage1(&arm, masses, &infos, &stated_rad)?;
        arm.upper_arm_mount = upper_arm_mount(&arm, &stage1_joints_rad)?;
        Ok(crate::Profile {
            name: self.name,
            title: self.title,
            family,
            missing: self.missing,
            sources: self
                .source
                .into_iter()
                .map(|s| Source {
                    id: s.id,
                    cite: s.cite,
                })
                .collect(),
            joints: infos,
            arm,
            masses,
            controller_stated: self.controller.is_some(),
            offset_entry_stated: self
                .controller
                .as_ref()
                .is_some_and(|c| c.offset_unit.is_some()),
            controller,
            stage1_joints_rad,
            stage1_stated_rad: stated_rad,
            flange_interface,
            upper_arm_registers_on: self.stage1.registers_on,
            flange_registers_on: self.stage2.registers_on,
        })
    }

    /// The `[flange]` interface keys, read and checked: a designation needs its source,
    /// a dowel or a source without a designation is refused (nothing to drill it on).
    fn flange_interface(
        &self,
        ids: &BTreeSet<&str>,
    ) -> Result<Option<FlangeInterface>, ProfileError> {
        let Some(f) = &self.flange else {
            return Ok(None);
        };
        let Some(text) = &f.iso9409 else {
            if f.dowel_hole_mm.is_some() {
                return Err(ProfileError::new(
                    flange::DOWEL_KEY,
                    "given without flange.iso9409: a dowel is placed on the bolt circle",
                ));
            }
            if f.interface_source.is_some() {
                return Err(ProfileError::new(
                    "flange.interface_source",
                    "given without flange.iso9409: nothing for it to be the source of",
                ));
            }
            return Ok(None);
        };
        let iso9409 = flange::parse_iso9409(text)?;
        if let Some(d) = f.dowel_hole_mm {
            flange::check_dowel(d, &iso9409)?;
        }
        let source = f.interface_source.clone().ok_or_else(|| {
            ProfileError::new(
                "flange.interface_source",
                "missing: flange.iso9409 needs the [[source]] that gives it",
            )
        })?;
        if !ids.contains(source.as_str()) {
            return Err(ProfileError::new(
                "flange.interface_source",
                format!("source '{source}' is not defined by any [[source]]"),
            ));
        }
        Ok(Some(FlangeInterface {
            iso9409,
            dowel_hole_mm: f.dowel_hole_mm,
            source,
        }))
    }

    /// Every text within its length and every number within its plausible range
    /// (`crate::bounds`), each refusal naming the key.
    fn check_bounds(&self) -> Result<(), ProfileError> {
        if self.name.len() > bounds::MAX_NAME_BYTES {
            return Err(ProfileError::new(
                "name",
                format!(
                    "longer than {} bytes (what the pendant stores)",
                    bounds::MAX_NAME_BYTES
                ),
            ));
        }
        text("title", &self.title, bounds::MAX_TITLE_CHARS)?;
        text("family", &self.family, bounds::MAX_TEXT_CHARS)?;
        bounds::list("missing", self.missing.len())?;
        for m in &self.missing {
            text("missing", m, bounds::MAX_TEXT_CHARS)?;
        }
        bounds::list("source", self.source.len())?;
        for s in &self.source {
            text("source.id", &s.id, bounds::MAX_TEXT_CHARS)?;
            text("source.cite", &s.cite, bounds::MAX_TEXT_CHARS)?;
        }
        text(
            "kinematics.form",
            &self.kinematics.form,
            bounds::MAX_TEXT_CHARS,
        )?;
        text(
            "kinematics.source",
            &self.kinematics.source,
            bounds::MAX_TEXT_CHARS,
        )?;
        let (deg, m) = ("deg", "m");
        for (k, j) in self.joint.iter().enumerate().take(JOINTS) {
            let key = |what: &str| format!("joint {}: {what}", k + 1);
            text(&key("name"), &j.name, bounds::MAX_JOINT_NAME_CHARS)?;
            if j.name.is_empty() {
                return Err(ProfileError::new(key("name"), "empty"));
            }
            let three = |v: Option<[f64; 3]>| v.map_or_else(Vec::new, |a| a.to_vec());
            let one = |v: Option<f64>| v.map_or_else(Vec::new, |x| vec![x]);
            for (what, v) in [
                ("xyz_m", three(j.xyz_m)),
                ("com_m", three(j.com_m)),
                ("a_m", one(j.a_m)),
                ("d_m", one(j.d_m)),
            ] {
                symmetric(&key(what), &v, bounds::MAX_LENGTH_M, m)?;
            }
            for (what, v) in [
                ("rpy_deg", three(j.rpy_deg)),
                ("alpha_deg", one(j.alpha_deg)),
                ("theta_deg", one(j.theta_deg)),
            ] {
                symmetric(&key(what), &v, bounds::MAX_ROTATION_DEG, deg)?;
            }
            symmetric(&key("min_deg"), &[j.min_deg], bounds::MAX_JOINT_DEG, deg)?;
            symmetric(&key("max_deg"), &[j.max_deg], bounds::MAX_JOINT_DEG, deg)?;
            if let Some(v) = j.max_speed_deg_s {
                let (lo, hi) = bounds::SPEED_DEG_S;
                bounds::number(&key("max_speed_deg_s"), v, lo, hi, "deg/s")?;
            }
            if let Some(v) = j.mass_kg {
                bounds::number(&key("mass_kg"), v, 0.0, bounds::MAX_MASS_KG, "kg")?;
            }
            if let Some(id) = &j.limits_source {
                text(&key("limits_source"), id, bounds::MAX_TEXT_CHARS)?;
            }
        }
        if let Some(f) = &self.flange {
            symmetric(
                "flange.xyz_m",
                &f.xyz_m.unwrap_or_default(),
                bounds::MAX_LENGTH_M,
                m,
            )?;
            symmetric(
                "flange.rpy_deg",
                &f.rpy_deg.unwrap_or_default(),
                bounds::MAX_ROTATION_DEG,
                deg,
            )?;
            for (key, t) in [
                (flange::ISO9409_KEY, &f.iso9409),
                ("flange.interface_source", &f.interface_source),
            ] {
                if let Some(t) = t {
                    text(key, t, bounds::MAX_TEXT_CHARS)?;
                }
            }
        }
        for (key, t) in [
            ("stage1.registers_on", &self.stage1.registers_on),
            ("stage2.registers_on", &self.stage2.registers_on),
        ] {
            if let Some(t) = t {
                text(key, t, bounds::MAX_TEXT_CHARS)?;
            }
        }
        if let Some(c) = &self.controller {
            symmetric(
                "controller.zero_deg",
                &c.zero_deg,
                bounds::MAX_JOINT_DEG,
                deg,
            )?;
            if let Some(r) = &c.gear_ratio {
                let (lo, hi) = bounds::GEAR_RATIO;
                bounds::numbers(
                    "controller.gear_ratio",
                    r,
                    lo,
                    hi,
                    "motor turns per joint turn",
                )?;
            }
            if let Some(r) = &c.counts_per_deg {
                let (lo, hi) = bounds::COUNTS_PER_DEG;
                bounds::numbers("controller.counts_per_deg", r, lo, hi, "counts/deg")?;
            }
            for (key, t) in [
                ("controller.coupling", Some(&c.coupling)),
                ("controller.source", Some(&c.source)),
                ("controller.offset_unit", c.offset_unit.as_ref()),
                ("controller.offset_where", c.offset_where.as_ref()),
                ("controller.offset_source", c.offset_source.as_ref()),
            ] {
                if let Some(t) = t {
                    text(key, t, bounds::MAX_TEXT_CHARS)?;
                }
            }
        }
        for (key, t) in [
            ("stage2.mount_z", &self.stage2.mount_z),
            ("stage2.mount_x", &self.stage2.mount_x),
        ] {
            text(key, t, bounds::MAX_TEXT_CHARS)?;
        }
        symmetric(
            "stage1.pose_deg",
            &self.stage1.pose_deg,
            bounds::MAX_JOINT_DEG,
            deg,
        )
    }

    /// The `[controller]` table read and checked; without one, the model's own angles
    /// ([`Controller::model_terms`]).
    fn controller(&self) -> Result<Controller, ProfileError> {
        let Some(c) = &self.controller else {
            return Ok(Controller::model_terms());
        };
        if let Some(k) = c.sign.iter().position(|s| *s != 1 && *s != -1) {
            return Err(ProfileError::new(
                format!("controller.sign[{k}]"),
                "must be 1 or -1",
            ));
        }
        if c.zero_deg.iter().any(|z| !z.is_finite()) {
            return Err(ProfileError::new("controller.zero_deg", "must be finite"));
        }
        let coupling = match c.coupling.as_str() {
            "none" => Coupling::None,
            "j3-minus-j2" => Coupling::J3MinusJ2,
            other => {
                return Err(ProfileError::new(
                    "controller.coupling",
                    format!("'{other}' is not none or j3-minus-j2"),
                ))
            }
        };
        let positive = |v: &Option<[f64; JOINTS]>, key: &str| match v {
            Some(a) if a.iter().any(|x| !(x.is_finite() && *x > 0.0)) => {
                Err(ProfileError::new(key, "every entry must be > 0"))
            }
            _ => Ok(*v),
        };
        let (unit, offset_where) = match (&c.offset_unit, &c.offset_where, &c.offset_source) {
            (Some(unit), Some(offset_where), Some(_)) => {
                let unit = match unit.as_str() {
                    "deg" => OffsetUnit::Degrees,
                    "motor_rad" => {
                        OffsetUnit::MotorRadians(positive(&c.gear_ratio, "controller.gear_ratio")?)
                    }
                    "counts" => OffsetUnit::Counts(positive(
                        &c.counts_per_deg,
                        "controller.counts_per_deg",
                    )?),
                    other => {
                        return Err(ProfileError::new(
                            "controller.offset_unit",
                            format!("'{other}' is not deg, motor_rad or counts"),
                        ))
                    }
                };
                (unit, offset_where.clone())
            }
            (None, None, None) => {
                for (key, given) in [
                    ("controller.gear_ratio", c.gear_ratio.is_some()),
                    ("controller.counts_per_deg", c.counts_per_deg.is_some()),
                ] {
                    if given {
                        return Err(ProfileError::new(
                            key,
                            "given without controller.offset_unit: nothing to scale",
                        ));
                    }
                }
                (
                    OffsetUnit::Degrees,
                    String::from(crate::controller::OFFSET_ENTRY_NOT_STATED),
                )
            }
            _ => return Err(ProfileError::new(
                "controller.offset_unit",
                "offset_unit, offset_where and offset_source go together: give all three or none",
            )),
        };
        Ok(Controller {
            sign: c.sign,
            zero_deg: c.zero_deg,
            coupling,
            unit,
            offset_where,
        })
    }

    /// The sources' link masses, if every link beyond joint 2 has one.
    fn masses(&self) -> Option<MassModel<f64>> {
        let mut link_kg = [0.0; JOINTS];
        let mut com_m = [nalgebra::Vector3::zeros(); JOINTS];
        for (k, j) in self.joint.iter().enumerate() {
            match (j.mass_kg, j.com_m) {
                (Some(m), Some(c)) => {
                    link_kg[k] = m;
                    let c = nalgebra::Vector3::from(c);
                    com_m[k] = match (self.kinematics.form.as_str(), j.a_m, j.alpha_deg, j.d_m) {
                        // DH: the centre of mass is given in frame i, after the link's
                        // own Tz(d)·Tx(a)·Rx(α).
                        ("dh", Some(a), Some(alpha), Some(d)) => {
                            let p = crate::dh_after(a, alpha, d);
                            p.translation_m + p.rotation * c
                        }
                        _ => c,
                    };
                }
                _ if k >= 2 => return None,
                _ => {}
            }
        }
        Some(MassModel {
            link_kg,
            com_m,
            pendant_kg: 0.0,
            pendant_com_m: nalgebra::Vector3::zeros(),
        })
    }
}

/// The pose stage 1 stands at: the stated one (model angles) turned to no gravity
/// torque on joints 2 and 3 (`zerocal_core::plan::stage1`), so that joint 2 is not
/// pulled to one side of its play in the two captures; as stated for an arm without
/// lengths (nothing to load it).
fn unloaded_stage1(
    arm: &zerocal_core::model::Arm<f64>,
    masses: Option<MassModel<f64>>,
    joints: &[JointInfo],
    stated_rad: &[f64; JOINTS],
) -> Result<[f64; JOINTS], ProfileError> {
    let Some(masses) = crate::mass_model_of(masses, arm) else {
        return Ok(*stated_rad);
    };
    let mut limits_rad = [(0.0, 0.0); JOINTS];
    for (l, j) in limits_rad.iter_mut().zip(joints) {
        *l = (j.min_deg.to_radians(), j.max_deg.to_radians());
    }
    unloaded_stage1_pose(arm, &masses, stated_rad, &limits_rad).map_err(|e| {
        ProfileError::new(
            "stage1.pose_deg",
            format!("{e} (the stated pose is where the search for a pose free of gravity torque starts)"),
        )
    })
}

/// The stage-1 pose inside the limits, and joint 1's half turn too.
fn check_stage1(joints: &[JointInfo], q: &[f64; JOINTS]) -> Result<(), ProfileError> {
    for (k, (j, v)) in joints.iter().zip(q).enumerate() {
        let d = v.to_degrees();
        if !(j.min_deg..=j.max_deg).contains(&d) {
            return Err(ProfileError::new(
                "stage1.pose_deg",
                format!(
                    "joint {} at {d:.3} deg is outside its limits {}..{} deg",
                    k + 1,
                    j.min_deg,
                    j.max_deg
                ),
            ));
        }
    }
    let turned = (q[0] + std::f64::consts::PI).to_degrees();
    if turned > joints[0].max_deg {
        return Err(ProfileError::new(
            "stage1.pose_deg",
            format!(
                "joint 1's half turn ends at {turned:.1} deg, past its limit {} deg: start it lower",
                joints[0].max_deg
            ),
        ));
    }
    Ok(())
}
