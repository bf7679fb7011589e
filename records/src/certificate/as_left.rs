//! The robot as left: the check recorded after the session's offsets were entered
//! (`zerocal check EXPORT --against ID`), read from its history record: what is left
//! of each joint's offset in the controller's terms, its U (k = 2), the check's verdict
//! per joint and the rule it applied.

use zerocal_history::{Record, RecordKind};

/// One joint as left.
#[derive(Clone, Debug, PartialEq)]
pub struct AsLeftJoint {
    /// The controller's name.
    pub name: String,
    /// What is left (deg, the controller's terms); `None` where the check did not see it.
    pub left_deg: Option<f64>,
    /// The check's U (k = 2) (deg).
    pub expanded_k2_deg: f64,
    /// Within the check's tolerance.
    pub pass: Option<bool>,
    /// Joint 3's line holds joint 2's too (what the flange sees of both).
    pub with_joint2: bool,
    /// What went wrong, in words, where the check named it.
    pub mistake: Option<String>,
}

/// The check after the entry.
#[derive(Clone, Debug, PartialEq)]
pub struct AsLeft {
    /// Its history record.
    pub record_id: i64,
    /// When it was measured.
    pub measured_on: String,
    /// Every seen joint within its tolerance.
    pub pass: bool,
    /// The rule it applied, in words.
    pub rule: String,
    /// Joints 2-6.
    pub joints: Vec<AsLeftJoint>,
}

/// Whether `check` was made after `session`'s offsets were entered (not a restore).
pub fn is_after_entry(check: &Record, session: i64) -> bool {
    let conditions: serde_json::Value =
        serde_json::from_str(&check.new.conditions_json).unwrap_or_default();
    check.new.kind == RecordKind::Check
        && check.new.reference_id == Some(session)
        && conditions["expected"].as_str() != Some("restored")
}

/// The check record `check` as the certificate states it.
///
/// # Errors
/// A record that is no check after `session`'s entry, or whose result does not read.
pub fn as_left(check: &Record, session: i64) -> Result<AsLeft, String> {
    if !is_after_entry(check, session) {
        return Err(format!(
            "record {} is not a check made after session {session}'s offsets were entered",
            check.id
        ));
    }
    let j: serde_json::Value = serde_json::from_str(&check.new.result_json)
        .map_err(|e| format!("record {}: its result does not read: {e}", check.id))?;
    let joints = j["joints"]
        .as_array()
        .ok_or_else(|| format!("record {}: its result holds no joints", check.id))?
        .iter()
        .map(|x| {
            let pass = x["pass"].as_bool();
            AsLeftJoint {
                name: x["name"].as_str().unwrap_or("?").to_owned(),
                left_deg: pass.and(x["controller_remaining_deg"].as_f64()),
                expanded_k2_deg: x["expanded_k2_deg"].as_f64().unwrap_or(f64::NAN),
                pass,
                with_joint2: x["with_joint2"].as_bool().unwrap_or(false),
                mistake: serde_json::from_value::<zerocal_analysis::compare::mistake::Mistake>(
                    x["mistake"].clone(),
                )
                .ok()
                .filter(|m| *m != zerocal_analysis::compare::mistake::Mistake::Taken)
                .map(|m| m.words()),
            }
        })
        .collect();
    Ok(AsLeft {
        record_id: check.id,
        measured_on: check.new.measured_on.clone(),
        pass: j["pass"].as_bool().unwrap_or(false),
        rule: j["rule"].as_str().unwrap_or("").to_owned(),
        joints,
    })
}
