//! The plan a program drives: a file `zerocal plan` wrote (`--csv` rows or its
//! `--json`, model degrees), checked against the robot's profile, or the plan
//! `zerocal plan` makes with its defaults.

use crate::plan::flags::MAX_JOINT2_SWING_DEG;
use crate::plan::PlanArgs;
use std::path::Path;
use zerocal_core::model::JOINTS;
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// Reads a plan file: `zerocal plan --csv` rows (model degrees) or its `--json`.
///
/// # Errors
/// An unreadable file, a malformed row (naming the line), another robot's plan.
pub fn read_plan(path: &Path, profile: &Profile) -> Result<Vec<[f64; JOINTS]>, CliError> {
    let text =
        zerocal_inputs::input::read_capped(path, zerocal_inputs::input::MAX_PLAN_BYTES, "plan")?;
    parse_plan(&text, path, profile)
}

/// Parses a plan file's text (`path` names it in errors): as [`read_plan`].
///
/// # Errors
/// A malformed row (naming the line), another robot's plan.
pub fn parse_plan(
    text: &str,
    path: &Path,
    profile: &Profile,
) -> Result<Vec<[f64; JOINTS]>, CliError> {
    let bad = |m: String| CliError::Input(format!("{}: {m}", path.display()));
    let poses_deg = if text.trim_start().starts_with('{') {
        poses_of_json(text, profile)
    } else {
        poses_of_csv(text)
    }
    .map_err(bad)?;
    check_plan_poses(&poses_deg, profile).map_err(bad)?;
    Ok(poses_deg)
}

/// The poses of `zerocal plan --json` (model degrees), if it is `profile`'s plan.
fn poses_of_json(text: &str, profile: &Profile) -> Result<Vec<[f64; JOINTS]>, String> {
    let v: serde_json::Value = serde_json::from_str(text).map_err(|e| format!("not JSON: {e}"))?;
    if let Some(robot) = v.get("robot").and_then(|r| r.as_str()) {
        if robot != profile.name {
            return Err(format!(
                "the plan is for robot '{robot}', not '{}'",
                profile.name
            ));
        }
    }
    let rows = v
        .get("poses_deg")
        .and_then(|p| p.as_array())
        .ok_or_else(|| "no \"poses_deg\" array (write it with zerocal plan --json)".to_owned())?;
    rows.iter()
        .enumerate()
        .map(|(i, r)| {
            let a = r
                .as_array()
                .filter(|a| a.len() == JOINTS)
                .ok_or_else(|| format!("poses_deg[{i}]: not {JOINTS} numbers"))?;
            let mut q = [0.0; JOINTS];
            for (k, x) in a.iter().enumerate() {
                q[k] = x
                    .as_f64()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| format!("poses_deg[{i}][{k}]: not a finite number"))?;
            }
            Ok(q)
        })
        .collect()
}

/// The poses of `zerocal plan --csv` rows (model degrees): six a line, a header and
/// `#` comments allowed.
fn poses_of_csv(text: &str) -> Result<Vec<[f64; JOINTS]>, String> {
    let mut rows = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() || line.starts_with("j1_deg") {
            continue;
        }
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() != JOINTS {
            return Err(format!(
                "line {}: {} fields, expected j1_deg..j6_deg",
                i + 1,
                f.len()
            ));
        }
        let mut q = [0.0; JOINTS];
        for (k, x) in f.iter().enumerate() {
            q[k] = x
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "line {}: field j{}_deg: '{x}' is not a finite number",
                        i + 1,
                        k + 1
                    )
                })?;
        }
        rows.push(q);
    }
    Ok(rows)
}

/// Refuses a plan of too few or too many poses, or one that is not of the profile's
/// stage-1 pose (another robot's or another stage-1 pose's plan): stage 2 holds joint 1
/// at stage 1's angle (the base tilt stage 1 measured is about that heading) and swings
/// joint 2 at most [`MAX_JOINT2_SWING_DEG`] either side of its stage-1 angle (its
/// reducer's error is told from its zero so; the session checks joint 1 the same way,
/// `zerocal_core::session::STAGE1_JOINT1_TOLERANCE_DEG`).
fn check_plan_poses(poses_deg: &[[f64; JOINTS]], profile: &Profile) -> Result<(), String> {
    if poses_deg.len() < zerocal_core::stage2::MIN_POSES
        || poses_deg.len() > zerocal_core::plan::MAX_POSES
    {
        return Err(format!(
            "{} poses; a plan has {}-{}",
            poses_deg.len(),
            zerocal_core::stage2::MIN_POSES,
            zerocal_core::plan::MAX_POSES
        ));
    }
    let q1 = profile.stage1_joints_rad.map(f64::to_degrees);
    let another = "a plan for another robot or stage-1 pose";
    for (i, q) in poses_deg.iter().enumerate() {
        // The plan prints 6 decimals: 1e-5 deg covers its rounding.
        if (q[0] - q1[0]).abs() > 1e-5 {
            return Err(format!(
                "pose {}: joint 1 at {} deg is not the profile's stage-1 value {:.6} (model \
                 degrees; stage 2 holds joint 1 where stage 1 had it): {another}",
                i + 1,
                q[0],
                q1[0]
            ));
        }
        if (q[1] - q1[1]).abs() > MAX_JOINT2_SWING_DEG + 1e-5 {
            return Err(format!(
                "pose {}: joint 2 at {} deg is more than {MAX_JOINT2_SWING_DEG} deg from the \
                 profile's stage-1 value {:.6} (model degrees), the widest swing a plan \
                 gives it: {another}",
                i + 1,
                q[1],
                q1[1]
            ));
        }
    }
    Ok(())
}

/// The plan `zerocal plan --robot R` makes with its defaults, in the session's order
/// (model radians). Always at the stated timing defaults, whatever speed a program is
/// then written for: the poses and their order (and a trade of information for travel
/// where the session would run over its aim) must be the same for the robot program
/// and the pendant's `load-profile`, which plans without timing options.
pub fn default_plan(robot: &str) -> Result<Vec<[f64; JOINTS]>, CliError> {
    plan_with(robot, &[])
}

/// The plan `zerocal plan --robot ROBOT` makes with the further `flags` (at the stated
/// timing defaults, as [`default_plan`]).
///
/// # Errors
/// As [`default_plan`].
pub fn plan_with(robot: &str, flags: &[&str]) -> Result<Vec<[f64; JOINTS]>, CliError> {
    let mut argv = vec!["--robot", robot];
    argv.extend_from_slice(flags);
    let args = PlanArgs::from_flags(&argv).map_err(|e| CliError::Input(e.to_string()))?;
    let sp = crate::plan::make_plan(&args)?;
    Ok(sp.plan.poses_rad.iter().copied().collect())
}
