//! The safety checks of a program before anything is written: a format the profile's
//! controller runs (and, for INFORM, pulses per degree to write), every capture pose
//! read inside the sensor's range, and every point the robot is sent to inside the
//! profile's joint limits, named by why the robot goes there.

use super::steps::{Capture, Role, Side, Step};
use super::Format;
use crate::robot_time::{Mounting, TimeModel};
use crate::timing::{self, Pendant, SessionPoses};
use zerocal_core::stage2::MEMS_RANGE_DEG;
use zerocal_inputs::error::CliError;
use zerocal_profile::{OffsetUnit, Profile};

/// Refuses a format of another family than the profile's, and an INFORM job for a
/// profile without pulses per degree.
///
/// # Errors
/// Either of those, naming the profile and what to do.
pub fn check_format(profile: &Profile, format: Format) -> Result<(), CliError> {
    if let Some(f) = Format::of(profile.family) {
        if f != format {
            return Err(CliError::Input(format!(
                "--format {format}: profile {} is a {} robot; its controller runs --format {f}",
                profile.name,
                profile.family.name()
            )));
        }
    }
    if format == Format::Inform && !matches!(profile.controller.unit, OffsetUnit::Counts(Some(_))) {
        return Err(CliError::Refused(format!(
            "--format inform: an INFORM job holds pulses, and profile {} has no pulses per degree (controller.counts_per_deg; not public for the built-in Yaskawa profiles). Read them from your controller (MotoPlus GP_getPulseToRad, or its parameter file) into your own profile (docs/profiles.md, docs/controllers/yaskawa.md); nothing was written",
            profile.name
        )));
    }
    Ok(())
}

/// Refuses a capture pose the pendant would read past mode 4's range.
///
/// # Errors
/// The first such pose, with the reading.
pub fn check_capture_ranges(pendant: &Pendant<'_>, poses: &SessionPoses) -> Result<(), CliError> {
    for (i, (what, q)) in poses.capture_poses().into_iter().enumerate() {
        // Stage 1's two poses are captured on the upper arm, the rest on the flange.
        let mounting = if i < 2 {
            Mounting::UpperArm
        } else {
            Mounting::Flange
        };
        let r = pendant.reading_on(mounting, &q);
        let worst = r.x_rad.to_degrees().abs().max(r.y_rad.to_degrees().abs());
        if worst > MEMS_RANGE_DEG {
            return Err(CliError::Refused(format!(
                "{what}: the pendant would read {worst:.1} deg there, past its {MEMS_RANGE_DEG:.0} deg range (the SCL3300's mode 4): it cannot capture that pose (plan with zerocal plan); nothing was written"
            )));
        }
    }
    Ok(())
}

/// What a point the robot goes to is, for messages: `next` is the capture pose the
/// moves lead to, if any; `j1` joint 1's name.
fn point_name(role: Role, next: Option<Capture>, time: &TimeModel<f64>, j1: &str) -> String {
    let next = next.map_or_else(|| "a pose".to_owned(), Capture::describe);
    match role {
        Role::Mount(Mounting::UpperArm) => "the mounting pose for the upper arm".to_owned(),
        Role::Mount(Mounting::Flange) => "the mounting pose for the flange".to_owned(),
        Role::Park => "the park for the closing bench readings".to_owned(),
        Role::Turn => format!("{j1}'s half turn"),
        Role::Approach(Side::Below) => {
            format!("the point {} deg below {next}", time.approach_deg)
        }
        Role::Approach(Side::Above) => {
            format!("the point {} deg above {next}", time.overshoot_deg)
        }
        Role::Capture(c, _) => c.describe(),
    }
}

/// Refuses a move to a point outside the profile's joint limits.
///
/// # Errors
/// The first such point, named by why the robot goes there (`j1`: joint 1's name).
pub fn check_every_point(
    profile: &Profile,
    steps: &[Step],
    time: &TimeModel<f64>,
    j1: &str,
) -> Result<(), CliError> {
    for (n, s) in steps.iter().enumerate() {
        if let Step::Move {
            target_deg, role, ..
        } = s
        {
            let next_capture = steps[n + 1..].iter().find_map(|s| match s {
                Step::Move {
                    role: Role::Capture(c, _),
                    ..
                } => Some(*c),
                _ => None,
            });
            let what = point_name(*role, next_capture, time, j1);
            timing::check_limits(profile, target_deg, &what)?;
        }
    }
    Ok(())
}
