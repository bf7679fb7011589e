//! `zerocal plan --limits FILE`: narrower joint limits than the profile's, read from a
//! small CSV file, one joint per line, by number (1-6) or by the profile's name for it
//! (`A5`), model degrees:
//!
//! ```text
//! # joint,min_deg,max_deg     (a header line and '#' comments are allowed)
//! joint,min_deg,max_deg
//! 3,-170,170
//! A5,-100,100
//! ```
//! Joints not listed keep the profile's limits; a listed joint's limits must lie
//! within the profile's (a wider range is the profile's to state: `zerocal program`
//! checks every point against it). A bad line is named by its number and field.

use crate::timing;
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// Per-joint (min, max) limits of joints 3-6 (deg).
pub type LimitsDeg = [(f64, f64); WRIST_JOINTS];

/// The limits a limits file lists (format in the module doc), per joint 1-6 (model
/// degrees); `names` are the profile's joint names. Errors name the line and field.
pub fn parse_limits(
    text: &str,
    names: &[String; JOINTS],
) -> Result<[Option<(f64, f64)>; JOINTS], String> {
    let mut limits = [None; JOINTS];
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields
            .first()
            .is_some_and(|f| f.eq_ignore_ascii_case("joint"))
        {
            continue; // header
        }
        if fields.len() != 3 {
            return Err(format!(
                "limits line {line_no}: expected 3 fields joint,min_deg,max_deg, got {}",
                fields.len()
            ));
        }
        let (k, (lo, hi)) = limits_line(line_no, &fields, names)?;
        if limits[k].is_some() {
            return Err(format!(
                "limits line {line_no}: joint {} is listed twice",
                k + 1
            ));
        }
        limits[k] = Some((lo, hi));
    }
    Ok(limits)
}

/// One line's three fields `joint,min_deg,max_deg`: the joint (0-based, by number or
/// by one of `names`) and its (min, max) limits (deg).
fn limits_line(
    line_no: usize,
    fields: &[&str],
    names: &[String; JOINTS],
) -> Result<(usize, (f64, f64)), String> {
    let k = fields[0]
        .parse::<usize>()
        .ok()
        .filter(|j| (1..=JOINTS).contains(j))
        .map(|j| j - 1)
        .or_else(|| names.iter().position(|n| n.eq_ignore_ascii_case(fields[0])))
        .ok_or_else(|| {
            format!(
                "limits line {line_no}: field joint: '{}' is not a joint 1-6 or one of the profile's {}",
                fields[0].chars().take(16).collect::<String>(),
                names.join(", ")
            )
        })?;
    let num = |f: usize, name: &str| -> Result<f64, String> {
        fields[f]
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                format!(
                    "limits line {line_no}: field {name}: '{}' is not a finite number",
                    fields[f].chars().take(32).collect::<String>()
                )
            })
    };
    let (lo, hi) = (num(1, "min_deg")?, num(2, "max_deg")?);
    if lo > hi {
        return Err(format!(
            "limits line {line_no}: min_deg {lo} is above max_deg {hi}"
        ));
    }
    Ok((k, (lo, hi)))
}

/// `profile` with the limits a limits file lists (`name` names the file in
/// messages); the joints it does not list keep the profile's.
///
/// # Errors
/// A malformed line; a listed range wider than the profile's (naming the joint).
pub fn narrow_limits(mut profile: Profile, text: &str, name: &str) -> Result<Profile, CliError> {
    let names: [String; JOINTS] = core::array::from_fn(|k| {
        profile
            .joints
            .get(k)
            .map_or_else(|| format!("J{}", k + 1), |j| j.name.clone())
    });
    let labels: [String; JOINTS] = core::array::from_fn(|k| timing::joint_label(&profile, k));
    let listed = parse_limits(text, &names).map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    let robot = profile.name.clone();
    for ((j, l), label) in profile.joints.iter_mut().zip(listed).zip(labels) {
        let Some((lo, hi)) = l else { continue };
        if lo < j.min_deg || hi > j.max_deg {
            return Err(CliError::Input(format!(
                "{name}: {label}: {lo}..{hi} deg reaches outside profile {robot}'s limits {}..{} deg; --limits only narrows them (a wider range belongs in the profile, which zerocal program checks every point against)",
                j.min_deg, j.max_deg
            )));
        }
        (j.min_deg, j.max_deg) = (lo, hi);
    }
    Ok(profile)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_file_parses_and_names_bad_lines() {
        let names: [String; JOINTS] = core::array::from_fn(|k| format!("A{}", k + 1));
        let ok = parse_limits(
            "# KR 6\njoint,min_deg,max_deg\n3,-170,170\na4, -30 , 30\n",
            &names,
        );
        assert_eq!(
            ok,
            Ok([
                None,
                None,
                Some((-170.0, 170.0)),
                Some((-30.0, 30.0)),
                None,
                None
            ])
        );
        let e = parse_limits("3,-170,170\n5,-10,abc\n", &names).unwrap_err();
        assert!(e.contains("line 2") && e.contains("max_deg"), "{e}");
        let e = parse_limits("7,0,1\n", &names).unwrap_err();
        assert!(e.contains("line 1") && e.contains("joint"), "{e}");
        let e = parse_limits("3,1,0\n", &names).unwrap_err();
        assert!(e.contains("above"), "{e}");
        let e = parse_limits("3,0,1\nA3,0,1\n", &names).unwrap_err();
        assert!(e.contains("twice"), "{e}");
        let e = parse_limits("3,0\n", &names).unwrap_err();
        assert!(e.contains("3 fields"), "{e}");
    }
}
