//! The check after offsets were entered: did the controller take them, with the right
//! sign and unit? What a measurement at the reference session's poses says is left of
//! each joint's offset, against a tolerance.

use super::Comparison;
use crate::session::Analysis;
use serde::{Deserialize, Serialize};
use zerocal_core::session::SESSION_JOINTS;

/// The default tolerance in the check's combined standard uncertainties: three, so
/// that a correct entry fails a joint about one time in 370 (normal, 99.73 %) while a
/// hundredth of a degree left stands out (the check's u is about 0.001-0.002°).
pub const CHECK_TOLERANCE_U: f64 = 3.0;

/// What the check expects to find.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Expected {
    /// The reference session's offsets were entered: every joint should now be at its
    /// kinematic zero, nothing left.
    Entered,
    /// A restore to the reference session's zero was entered: every joint should be
    /// where it was at the reference, no move.
    Restored,
}

/// One joint's check.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct JointCheck {
    /// The controller's name for the joint.
    pub name: String,
    /// What is left (deg, model terms: true − commanded). Joint 3's is what the flange
    /// sees of joints 2 and 3 together, Δθ3 + r·Δθ2 with `r`
    /// [`super::joint3_per_joint2`] (`with_joint2`), unless joint 2 was compared on the
    /// upper arm and did not take its entry: then joint 3's own.
    pub remaining_deg: f64,
    /// Joint 3's line holds joint 2's too (their combination at the flange).
    #[serde(default)]
    pub with_joint2: bool,
    /// The check's own expanded uncertainty, k = 2 (deg).
    pub expanded_k2_deg: f64,
    /// The tolerance it is judged against (deg).
    pub tolerance_deg: f64,
    /// Within it; `None` for a joint the check does not see (joint 2 without the upper
    /// arm's readings; a held twin).
    pub pass: Option<bool>,
}

/// The check's result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CheckResult {
    /// Joints 2-6.
    pub joints: Vec<JointCheck>,
    /// Every checked joint within its tolerance.
    pub pass: bool,
    /// The rule, in words.
    pub rule: String,
}

impl CheckResult {
    /// The joints outside their tolerance, by name.
    pub fn failed(&self) -> Vec<&str> {
        self.joints
            .iter()
            .filter(|j| j.pass == Some(false))
            .map(|j| j.name.as_str())
            .collect()
    }
}

/// Judges `comparison` (a measurement against `reference`) as a check: what is left is
/// the reference's offsets plus the zeros' move ([`Expected::Entered`]) or the move
/// alone ([`Expected::Restored`]). The tolerance of each joint is `tolerance_deg` where
/// given, else [`CHECK_TOLERANCE_U`] times the check's own combined standard
/// uncertainty, from the reference's budget less what cancels
/// ([`super::DifferenceBudget`]): a remaining offset the check can tell from zero was
/// not taken.
///
/// After a restore ([`Expected::Restored`]) what is left is the restore's own error as
/// well as the check's: `restore_combined_deg` is the restore's combined standard
/// uncertainty per joint (its comparison's, [`super::DifferenceBudget::combined_deg`]),
/// which joins the check's in quadrature; without it the restore's is taken as the
/// check's own (the same kind of measurement: a difference against the same reference
/// at its poses), √2 in all, which leaves out what only the restore has (a swapped
/// motor's reducer error over the zero's move).
pub fn judge(
    reference: &Analysis,
    comparison: &Comparison,
    expected: Expected,
    tolerance_deg: Option<f64>,
    restore_combined_deg: Option<&[f64; SESSION_JOINTS]>,
) -> CheckResult {
    let moved = comparison.moved_deg();
    let r = comparison.joint3_per_joint2;
    let budget = &comparison.budget;
    // After a session's offsets, the session's error is common to the reference and
    // the check, and cancels; after a restore, the restore's does not.
    let own = |k: usize| match (expected, restore_combined_deg) {
        (Expected::Entered, _) => budget.combined_deg[k],
        (Expected::Restored, Some(restore)) => budget.combined_deg[k].hypot(restore[k]),
        (Expected::Restored, None) => budget.combined_deg[k] * core::f64::consts::SQRT_2,
    };
    let tolerance = |k: usize| tolerance_deg.unwrap_or(CHECK_TOLERANCE_U * own(k));
    let entered = |i: usize| match expected {
        Expected::Entered => reference.json.joints[i].offset_deg,
        Expected::Restored => 0.0,
    };
    // Joint 2 on its own, where the upper arm was compared.
    let joint2_seen = comparison.identifiable[0];
    let left2 = entered(0) + moved[0];
    let joint2_fails = joint2_seen && left2.abs() > tolerance(0);
    let joints: Vec<JointCheck> = (0..SESSION_JOINTS)
        .map(|k| {
            let mut with_joint2 = false;
            let (remaining_deg, expanded, tolerance) = match k {
                0 => (left2, budget.expanded_deg[0], tolerance(0)),
                1 => {
                    // What the flange sees: joints 2 and 3 together, joint 2's entry r
                    // times in joint 3's line; far better known than either alone.
                    let together = entered(1) + r * entered(0) + moved[1];
                    if joint2_fails {
                        // Joint 2 did not take its entry: joint 3's own is the rest.
                        (
                            together - r * left2,
                            budget.expanded_deg[1].hypot(budget.expanded_deg[0]),
                            tolerance(1).hypot(tolerance(0)),
                        )
                    } else {
                        with_joint2 = true;
                        (together, budget.expanded_deg[1], tolerance(1))
                    }
                }
                _ => (entered(k) + moved[k], budget.expanded_deg[k], tolerance(k)),
            };
            let seen = comparison.identifiable[k];
            JointCheck {
                name: reference.json.joints[k].name.clone(),
                remaining_deg: if seen { remaining_deg } else { 0.0 },
                with_joint2,
                expanded_k2_deg: expanded,
                tolerance_deg: tolerance,
                pass: seen.then(|| remaining_deg.abs() <= tolerance),
            }
        })
        .collect();
    let pass = joints.iter().all(|j| j.pass != Some(false));
    let rule = match tolerance_deg {
        Some(t) => format!(
            "a joint passes when what is left of its offset is within +/-{t} deg (the \
             tolerance given)"
        ),
        None => format!(
            "a joint passes when what is left of its offset is within {CHECK_TOLERANCE_U} \
             times the check's own standard uncertainty (the reference session's budget less \
             the terms common to both measurements{}): more than that is an offset the \
             controller did not take (a sign, a unit, a joint mixed up, a value not activated)",
            match (expected, restore_combined_deg) {
                (Expected::Entered, _) => "",
                (Expected::Restored, Some(_)) => "; after a restore, with the restore's own",
                (Expected::Restored, None) =>
                    "; after a restore, with the restore's own taken as the check's: √2 times; \
                     --restore-export gives the restore's own",
            }
        ),
    };
    CheckResult { joints, pass, rule }
}
