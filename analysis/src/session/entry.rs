//! The numbers to type on this robot. The controller pages leave the sign of an entry
//! (and for some families its unit) unknown; `zerocal check` measures, per joint, what
//! the controller took of what was typed, and records it for the robot's serial
//! (`zerocal_history::NewConvention`, the check's ID as its evidence). A session of
//! that serial prints each joint's Δq through it: the number to type is `Δq / f`,
//! where `f` is what the controller takes of a typed value. Without a measured
//! convention the number to type is Δq, as the controller page derives it.

use super::{JointJson, SessionJson};
use serde::{Deserialize, Serialize};
use zerocal_history::Convention;
use zerocal_profile::Family;

/// A joint's entry convention on this robot, as checks measured it.
#[derive(Serialize, Deserialize, Debug, Clone, PartialEq)]
pub struct EntryConvention {
    /// What the controller takes of a typed value (−1: the sign reversed).
    pub factor: f64,
    /// The check that measured it (recorded its evidence).
    pub measured_by_check: i64,
    /// The checks since that found entries taken with it.
    pub verified_by_checks: Vec<i64>,
}

impl EntryConvention {
    /// In words: `sign reversed`, `factor 2.0000`, `sign reversed and factor 2.0000`,
    /// or `as the controller page has it`.
    pub fn words(&self) -> String {
        let reversed = self.factor < 0.0;
        let scaled = (self.factor.abs() - 1.0).abs() > 1e-9;
        match (reversed, scaled) {
            (true, true) => format!("sign reversed and factor {:.4}", self.factor.abs()),
            (true, false) => "sign reversed".to_owned(),
            (false, true) => format!("factor {:.4}", self.factor),
            (false, false) => "as the controller page has it".to_owned(),
        }
    }

    /// Its evidence in words: measured by check N, verified by checks M, …
    pub fn evidence(&self) -> String {
        let mut s = format!("measured by check {}", self.measured_by_check);
        if !self.verified_by_checks.is_empty() {
            let ids: Vec<String> = self.verified_by_checks.iter().map(i64::to_string).collect();
            s.push_str(&format!(", verified by check {}", ids.join(", ")));
        }
        s
    }
}

/// Each joint's (2-6) convention in force from a serial's recorded conventions (in
/// recording order): the last measurement of a joint and the verifications after it.
pub fn in_force(recorded: &[Convention]) -> [Option<EntryConvention>; 5] {
    let mut out: [Option<EntryConvention>; 5] = Default::default();
    for c in recorded {
        let Some(slot) = out.get_mut(usize::from(c.new.joint).wrapping_sub(2)) else {
            continue;
        };
        match slot {
            Some(e) if c.new.verified && e.factor == c.new.factor => {
                e.verified_by_checks.push(c.new.check_id);
            }
            _ => {
                *slot = Some(EntryConvention {
                    factor: c.new.factor,
                    measured_by_check: c.new.check_id,
                    verified_by_checks: Vec::new(),
                });
            }
        }
    }
    out
}

impl JointJson {
    /// The number to type (deg, the controller's terms): Δq through this robot's
    /// convention, or Δq.
    pub fn to_enter(&self) -> f64 {
        self.to_enter_deg.unwrap_or(self.controller_offset_deg)
    }

    /// What the controller takes of a typed value on this robot, as the session printed
    /// its numbers: its convention's factor, or 1.
    pub fn entry_factor(&self) -> f64 {
        self.entry_convention.as_ref().map_or(1.0, |c| c.factor)
    }
}

/// Applies a serial's conventions to a session's numbers: each joint's number to type,
/// and a note per joint saying what it rests on.
pub fn apply(json: &mut SessionJson, serial: &str, recorded: &[Convention], family: Family) {
    let conventions = in_force(recorded);
    let mut measured = Vec::new();
    let mut unverified = Vec::new();
    for (joint, convention) in json.joints.iter_mut().zip(conventions) {
        match convention {
            Some(c) => {
                joint.to_enter_deg = Some(joint.controller_offset_deg / c.factor);
                measured.push(format!("{} {} ({})", joint.name, c.words(), c.evidence()));
                joint.entry_convention = Some(c);
            }
            None => {
                joint.to_enter_deg = Some(joint.controller_offset_deg);
                if joint.identifiable {
                    unverified.push(joint.name.clone());
                }
            }
        }
    }
    let entry = family.entry();
    if !measured.is_empty() {
        json.notes.push(format!(
            "entry conventions measured on robot {serial}: {}; the numbers to type are dq \
             through them",
            measured.join("; ")
        ));
    }
    if !unverified.is_empty() && entry.any_unknown() {
        json.notes.push(format!(
            "{} on robot {serial}: the controller page's convention, not yet verified on \
             this robot (its {} unknown): the check after the entry measures it and records \
             it for the next session",
            unverified.join(", "),
            match (entry.sign, entry.unit) {
                (zerocal_profile::Known::Unknown, zerocal_profile::Known::Unknown) => {
                    "sign and unit are"
                }
                (zerocal_profile::Known::Unknown, _) => "sign is",
                _ => "unit is",
            }
        ));
    }
}
