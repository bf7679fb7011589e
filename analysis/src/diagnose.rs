//! When a session's residuals are far above the noise, or its fit does not settle, the
//! robot's model is wrong more often than the robot: a joint's positive direction the
//! other way round, a bracket fitted in another orientation than the profile says, the
//! other reading convention. Each of these is tried on the same readings; one that fits
//! at the noise level is named, so the technician fixes the profile or the bracket
//! instead of entering wrong zeros.

use nalgebra::{Matrix3, Rotation3, Vector3};
use zerocal_core::model::{Arm, Convention, JOINTS};
use zerocal_core::session::{solve, SessionReadings};
use zerocal_core::stage2::FitConfig;

/// A change to the model that made the readings fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnosis {
    /// What was changed, in words.
    pub change: String,
    /// The residual RMS it reaches (deg).
    pub residual_rms_deg: f64,
}

/// The 24 orientations of a bracket whose axes lie along the flange frame's axes.
fn axis_aligned_rotations() -> Vec<Rotation3<f64>> {
    let axes: [Vector3<f64>; 6] = [
        Vector3::x(),
        -Vector3::x(),
        Vector3::y(),
        -Vector3::y(),
        Vector3::z(),
        -Vector3::z(),
    ];
    let mut out = Vec::new();
    for x in &axes {
        for z in &axes {
            if x.dot(z).abs() > 0.5 {
                continue;
            }
            let y = z.cross(x);
            out.push(Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[
                *x, y, *z,
            ])));
        }
    }
    out
}

/// Names of an axis-aligned vector (for the message).
fn axis_name(v: &Vector3<f64>) -> &'static str {
    let names = [
        (Vector3::x(), "x"),
        (-Vector3::x(), "-x"),
        (Vector3::y(), "y"),
        (-Vector3::y(), "-y"),
        (Vector3::z(), "z"),
        (-Vector3::z(), "-z"),
    ];
    names
        .iter()
        .find(|(a, _)| (a - v).norm() < 1e-9)
        .map_or("?", |(_, n)| n)
}

/// Tries the model changes on `readings` and returns those whose fit passes
/// `config`'s residual ceiling (or, without one, reaches `noise_level_deg`), best
/// first. `joint_names` are the controller's names of joints 1-6.
pub fn diagnose(
    readings: &SessionReadings<'_, f64>,
    config: &FitConfig<f64>,
    joint_names: &[String],
    noise_level_deg: f64,
) -> Vec<Diagnosis> {
    let mut found = Vec::new();
    let mut try_variant = |arm: Arm<f64>, convention: Convention, change: String| {
        let r = SessionReadings {
            arm,
            convention,
            ..*readings
        };
        if let Ok(s) = solve(&r, config).result {
            let rms = s.fit.residual_rms_rad.to_degrees();
            if rms <= noise_level_deg {
                found.push(Diagnosis {
                    change,
                    residual_rms_deg: rms,
                });
            }
        }
    };
    let name = |k: usize| {
        joint_names.get(k).map_or(format!("joint {}", k + 1), |n| {
            format!("{n} (joint {})", k + 1)
        })
    };
    for k in 1..JOINTS {
        let mut arm = readings.arm;
        arm.joints[k].axis = arm.joints[k].axis.negated();
        try_variant(
            arm,
            readings.convention,
            format!(
                "{} turning the other way: its `axis` in the profile has the wrong sign",
                name(k)
            ),
        );
    }
    let flange_in_flange_frame = readings.arm.flange_mount;
    for r in axis_aligned_rotations() {
        if (r.matrix() - flange_in_flange_frame.matrix()).norm() < 1e-9 {
            continue;
        }
        let mut arm = readings.arm;
        arm.flange_mount = r;
        let (x, z) = (r * Vector3::x(), r * Vector3::z());
        try_variant(
            arm,
            readings.convention,
            format!(
                "the flange bracket with the pendant's z along the flange frame's {} and x along its {} (`[stage2] mount_z = \"{}\"`, `mount_x = \"{}\"`): the bracket is fitted otherwise than the profile says",
                axis_name(&z),
                axis_name(&x),
                axis_name(&z),
                axis_name(&x)
            ),
        );
    }
    let mut arm = readings.arm;
    arm.upper_arm_mount *= Rotation3::from_axis_angle(&Vector3::z_axis(), core::f64::consts::PI);
    try_variant(
        arm,
        readings.convention,
        "the upper-arm bracket turned half a turn (the pendant's x against joint 2's positive direction)".to_owned(),
    );
    let other = match readings.convention {
        Convention::Axis => Convention::Rpy,
        Convention::Rpy => Convention::Axis,
    };
    try_variant(
        readings.arm,
        other,
        format!(
            "the `{}` reading convention (the export says `{}`)",
            other.name(),
            readings.convention.name()
        ),
    );
    found.sort_by(|a, b| a.residual_rms_deg.total_cmp(&b.residual_rms_deg));
    found
}
