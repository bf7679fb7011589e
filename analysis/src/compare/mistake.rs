//! What went wrong with an entry, per joint, from what the check finds left against
//! what was to be entered, both in the controller's terms (its joint degrees, as it
//! shows each joint): the controller took `x = p − left` of the `p` it was to take.
//!
//! - `x ≈ p`: taken;
//! - `x ≈ 0`: not activated (or not entered);
//! - `x ≈ −p`: the sign reversed;
//! - `x_j ≈ p_k` and `x_k ≈ p_j`: joints j and k swapped;
//! - `x ≈ f·p` with `f` a unit conversion (π/180, 180/π, powers of ten, 60, 3600 and
//!   their inverses), or far from 1 (beyond ×5 or ÷5: a gear ratio or a scale), or the
//!   same `f` on two joints or more: a unit or gear-ratio factor `f`;
//! - anything else: a value typed wrong (the controller took `x`).
//!
//! "≈" is within the check's tolerance of each joint. An offset too small to tell
//! from its tolerance gives no ratio: only what the controller took.

use serde::{Deserialize, Serialize};

/// Unit conversions a value is commonly taken through by mistake: degrees and radians,
/// a misplaced decimal point, arc minutes and seconds.
const UNIT_FACTORS: [f64; 12] = [
    180.0 / core::f64::consts::PI,
    core::f64::consts::PI / 180.0,
    10.0,
    0.1,
    100.0,
    0.01,
    1000.0,
    0.001,
    60.0,
    1.0 / 60.0,
    3600.0,
    1.0 / 3600.0,
];

/// A factor beyond this (or below its inverse) is no typing slip but a scale: a gear
/// ratio (motor to joint: tens to hundreds) or counts per degree.
const SCALE_FACTOR: f64 = 5.0;

/// What happened to one joint's entry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Mistake {
    /// Taken as it was to be.
    Taken,
    /// Nothing of it taken: not entered, or not activated (not saved, not re-mastered,
    /// the controller not restarted).
    NotActivated,
    /// Taken with the sign reversed.
    SignReversed,
    /// Taken times a factor (a unit or a gear ratio): `factor` is what the controller
    /// took over what it was to take (negative: the sign reversed too).
    Factor {
        /// Taken over to be taken.
        factor: f64,
    },
    /// Swapped with another joint's value.
    Swapped {
        /// The other joint's name.
        with: String,
    },
    /// Another value taken: typed wrong.
    TypedWrong {
        /// What the controller took (deg, its terms).
        taken_deg: f64,
    },
}

impl Mistake {
    /// In words, for the report.
    pub fn words(&self) -> String {
        match self {
            Mistake::Taken => "taken".into(),
            Mistake::NotActivated => {
                "not activated: nothing of it was taken (not entered, not saved, the axis not \
                 re-mastered or the controller not restarted)"
                    .into()
            }
            Mistake::SignReversed => "the sign reversed: it was taken as its negative".into(),
            Mistake::Factor { factor } if *factor < 0.0 => format!(
                "the sign reversed and a unit or gear-ratio factor: taken {:.4} times",
                factor
            ),
            Mistake::Factor { factor } => format!(
                "a unit or gear-ratio factor: taken {factor:.4} times (the unit, the gear ratio \
                 or the counts per degree used)"
            ),
            Mistake::Swapped { with } => format!("swapped with {with}: it took {with}'s value"),
            Mistake::TypedWrong { taken_deg } => {
                format!("a value typed wrong: the controller took {taken_deg:+.5} deg")
            }
        }
    }

    /// The factor the controller took the value by, where the mistake is one of scale
    /// or sign (what a convention is): 1 taken, −1 reversed, `f` a factor.
    pub fn factor(&self) -> Option<f64> {
        match self {
            Mistake::Taken => Some(1.0),
            Mistake::SignReversed => Some(-1.0),
            Mistake::Factor { factor } => Some(*factor),
            _ => None,
        }
    }
}

/// One joint as the classification sees it (controller terms, deg).
#[derive(Clone, Debug, PartialEq)]
pub struct EntryJoint {
    /// The controller's name.
    pub name: String,
    /// What the controller was to take.
    pub to_take_deg: f64,
    /// What the check finds left.
    pub left_deg: f64,
    /// The check's tolerance.
    pub tolerance_deg: f64,
    /// Seen by the check.
    pub seen: bool,
}

/// Each joint's mistake (`None` for a joint the check does not see).
pub fn classify(joints: &[EntryJoint]) -> Vec<Option<Mistake>> {
    let taken: Vec<f64> = joints.iter().map(|j| j.to_take_deg - j.left_deg).collect();
    let failed: Vec<bool> = joints
        .iter()
        .map(|j| j.seen && j.left_deg.abs() > j.tolerance_deg)
        .collect();
    let near = |a: f64, b: f64, t: f64| (a - b).abs() <= t;
    // A factor is readable where the offset stands out of its tolerance.
    let factor_of = |k: usize| {
        let j = &joints[k];
        (j.to_take_deg.abs() > j.tolerance_deg).then(|| taken[k] / j.to_take_deg)
    };
    joints
        .iter()
        .enumerate()
        .map(|(k, j)| {
            if !j.seen {
                return None;
            }
            if !failed[k] {
                return Some(Mistake::Taken);
            }
            let t = j.tolerance_deg;
            let x = taken[k];
            let p = j.to_take_deg;
            if near(x, 0.0, t) {
                return Some(Mistake::NotActivated);
            }
            if near(x, -p, t) {
                return Some(Mistake::SignReversed);
            }
            let swapped = (0..joints.len()).find(|&m| {
                m != k
                    && failed[m]
                    && near(x, joints[m].to_take_deg, t)
                    && near(taken[m], p, joints[m].tolerance_deg)
            });
            if let Some(m) = swapped {
                return Some(Mistake::Swapped {
                    with: joints[m].name.clone(),
                });
            }
            let Some(f) = factor_of(k) else {
                return Some(Mistake::TypedWrong { taken_deg: x });
            };
            let unit = UNIT_FACTORS
                .iter()
                .any(|c| near(x, c * p, t) || near(x, -c * p, t));
            let scale = f.abs() >= SCALE_FACTOR || f.abs() <= 1.0 / SCALE_FACTOR;
            // Two joints share a factor where their ratios agree within both ratios'
            // tolerances (a joint's ratio is known to its tolerance over what it was to
            // take: a small offset's ratio is coarse, and judged against a large one's
            // alone it was taken for a typing slip).
            let shared = (0..joints.len()).any(|m| {
                m != k
                    && failed[m]
                    && factor_of(m).is_some_and(|g| {
                        near(
                            f,
                            g,
                            t / p.abs() + joints[m].tolerance_deg / joints[m].to_take_deg.abs(),
                        )
                    })
            });
            Some(if unit || scale || shared {
                Mistake::Factor { factor: f }
            } else {
                Mistake::TypedWrong { taken_deg: x }
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn joints(to_take: [f64; 5], taken: [f64; 5]) -> Vec<EntryJoint> {
        (0..5)
            .map(|k| EntryJoint {
                name: format!("J{}", k + 2),
                to_take_deg: to_take[k],
                left_deg: to_take[k] - taken[k],
                tolerance_deg: 0.005,
                seen: true,
            })
            .collect()
    }

    const P: [f64; 5] = [0.081, -0.573, 0.104, -0.2, 0.422];

    #[test]
    fn each_mistake_is_named_from_what_was_taken() {
        let kinds = |taken: [f64; 5]| classify(&joints(P, taken));
        assert!(kinds(P).iter().all(|m| *m == Some(Mistake::Taken)));
        let m = kinds([0.081, 0.0, 0.104, -0.2, 0.422]);
        assert_eq!(m[1], Some(Mistake::NotActivated));
        assert_eq!(m[0], Some(Mistake::Taken));
        let m = kinds([0.081, 0.573, 0.104, -0.2, 0.422]);
        assert_eq!(m[1], Some(Mistake::SignReversed));
        let m = kinds([0.081, -0.573, -0.2, 0.104, 0.422]);
        assert_eq!(m[2], Some(Mistake::Swapped { with: "J5".into() }));
        assert_eq!(m[3], Some(Mistake::Swapped { with: "J4".into() }));
        // The same factor on every joint: a unit or a scale.
        let m = kinds(P.map(|p| 2.0 * p));
        for x in &m {
            assert!(matches!(x, Some(Mistake::Factor { factor }) if (factor - 2.0).abs() < 0.1));
        }
        // The same factor where one joint's offset is small: its ratio is coarse (here
        // 2.44 for 2.5: 0.005 left over 0.08) and still read as the shared factor.
        let t = [0.08, -0.5, 0.1, -0.3, 0.4];
        let mut x = t.map(|v| 2.5 * v);
        x[0] -= 0.0045;
        let k = classify(&joints(t, x));
        assert!(
            matches!(k[0], Some(Mistake::Factor { factor }) if (factor - 2.44).abs() < 0.01),
            "{k:?}"
        );
        // Degrees typed where radians were meant, on one joint.
        let mut t = P;
        t[4] = P[4] * 180.0 / core::f64::consts::PI;
        assert!(
            matches!(kinds(t)[4], Some(Mistake::Factor { factor }) if (factor - 57.3).abs() < 0.1)
        );
        // Two digits transposed.
        let mut t = P;
        t[4] = 0.442;
        assert_eq!(kinds(t)[4], Some(Mistake::TypedWrong { taken_deg: 0.442 }));
    }
}
