//! Trading a little information for travel, only where a session would run over its
//! robot-time aim ([`ROBOT_TIME_AIM_S`]).
//!
//! Why: the planner's exchange picks, among many nearly as informative candidates, the
//! most informative one, wherever the robot must go to reach it. On an arm whose joints
//! all run at the same modest speed (the UR5e, 18°/s at 10 %), a pose a half turn of a
//! wrist away from every other costs 15-20 s. Swapping such a pose for a candidate of
//! the same pool nearer its neighbours in the tour gives up a little information for a
//! shorter session.
//!
//! The rule: a swap is taken only while the session is over the aim; it must shorten
//! the session as [`super::session_plan`] orders it (the whole tour, whole turns and
//! revisits, not an estimate); and every joint's predicted k = 2 uncertainty (the
//! whole budget, [`predicted_k2_deg`]) must stay within [`TRAVEL_TRADE_TOLERANCE`] of
//! the planner's own. A plan within the aim is never changed; `--target-k2-deg` plans
//! are not traded (the target asks for information, not time).

use super::prediction::predicted_k2_deg;
use super::session_plan::unwound_plan;
use super::session_plan::{session_order, SessionOrder};
use crate::timing::{self, Pendant, SessionPoses, Timing};
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{with_revisits, Candidate, Plan, PlanConfig, PoseList, ROBOT_TIME_AIM_S};
use zerocal_core::stage2::{covariance_bound, geometry, FitConfig, Information, Stage2Model};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// How much each joint's predicted k = 2 uncertainty may grow, as a fraction of the
/// planner's, for a shorter session: 2 %. Why this much: the k = 2 of a default plan
/// is printed to two significant figures and a technician reads it so; 2 % of the
/// largest (j2, about 0.019° on the UR5e) is 0.0004°, below the last printed digit of
/// most joints and a fifth of the capture noise's 1σ (0.0008°).
pub const TRAVEL_TRADE_TOLERANCE: f64 = 0.02;

/// Swaps tried before the trade stops: bounds `zerocal plan`'s time where few swaps
/// pay (each try times the whole session, and predicts the budget where it is shorter:
/// a few milliseconds; the UR5e's default plan reaches its aim after about 500).
const MAX_TRIED: usize = 1000;

/// Least saving (s) a swap must promise, on its two legs, to be tried.
const MIN_LEG_SAVING_S: f64 = 1.0;

/// What the trade did.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TravelTrade {
    /// Poses swapped for a nearer candidate.
    pub swaps: usize,
    /// The session's robot time before the trade (s).
    pub before_s: f64,
    /// The predicted k = 2 (deg, j2..j6) before the trade.
    pub k2_before_deg: [f64; WRIST_JOINTS + 1],
    /// The most each joint's predicted k = 2 was allowed to grow (fraction):
    /// [`TRAVEL_TRADE_TOLERANCE`].
    pub tolerance: f64,
}

/// What the trade needs of the plan's making.
pub(super) struct TradeInputs<'a> {
    /// The robot.
    pub(super) profile: &'a Profile,
    /// The time model.
    pub(super) timing: &'a Timing,
    /// The planner's settings.
    pub(super) config: &'a PlanConfig<f64>,
    /// The fit's model.
    pub(super) model: &'a Stage2Model<f64>,
    /// The fit's settings.
    pub(super) fit: &'a FitConfig<f64>,
    /// Captures per pose.
    pub(super) captures_per_pose: usize,
    /// The planner's candidates (its feasible pool).
    pub(super) pool: &'a [Candidate<f64>],
}

/// `p` ordered for the session and, where that session is over [`ROBOT_TIME_AIM_S`],
/// with poses swapped for nearer candidates of the pool by the module's rule; the
/// trade made, if any.
///
/// # Errors
/// As [`session_order`] and [`predicted_k2_deg`].
pub(super) fn traded_for_travel(
    inputs: &TradeInputs<'_>,
    p: &Plan<f64>,
) -> Result<(SessionOrder, Option<TravelTrade>), CliError> {
    let (profile, timing) = (inputs.profile, inputs.timing);
    let mut ordered = session_order(profile, timing, p)?;
    if ordered.time.total_s <= ROBOT_TIME_AIM_S {
        return Ok((ordered, None));
    }
    let before_s = ordered.time.total_s;
    let k2_before = inputs.k2(&ordered.plan.poses_rad)?;
    let ceiling = k2_before.map(|u| u * (1.0 + TRAVEL_TRADE_TOLERANCE));
    // Each candidate's whole turns, for the legs' estimate.
    let pool_poses: Vec<[f64; JOINTS]> = inputs.pool.iter().map(|c| c.joints_rad).collect();
    let pool_turns = timing::unwind::turn_options(profile, &pool_poses);
    let mut swaps = 0;
    let mut tried = 0;
    'trade: while ordered.time.total_s > ROBOT_TIME_AIM_S && tried < MAX_TRIED {
        for (slot, c) in inputs.offers(&ordered, &pool_poses, &pool_turns) {
            tried += 1;
            if let Some(o) = inputs.try_swap(&ordered, slot, c, &ceiling)? {
                ordered = o;
                swaps += 1;
                continue 'trade;
            }
            if tried >= MAX_TRIED {
                break;
            }
        }
        break;
    }
    if swaps == 0 {
        return Ok((ordered, None));
    }
    // The swapped poses toured afresh: kept where that is shorter still and within the
    // tolerance too (a new order visits other poses again, which the budget counts).
    if let Ok(toured) = session_order(profile, timing, &ordered.plan) {
        let within = inputs
            .k2(&toured.plan.poses_rad)
            .is_ok_and(|k2| within_ceiling(&k2, &ceiling));
        if toured.time.total_s < ordered.time.total_s && within {
            ordered = SessionOrder {
                time_unordered: ordered.time_unordered,
                ..toured
            };
        }
    }
    Ok((
        ordered,
        Some(TravelTrade {
            swaps,
            before_s,
            k2_before_deg: k2_before,
            tolerance: TRAVEL_TRADE_TOLERANCE,
        }),
    ))
}

impl TradeInputs<'_> {
    /// The whole budget's predicted k = 2 (deg, j2..j6) on `poses` (revisits included).
    fn k2(&self, poses: &[[f64; JOINTS]]) -> Result<[f64; WRIST_JOINTS + 1], CliError> {
        predicted_k2_deg(
            self.profile,
            self.model,
            poses,
            self.fit,
            self.captures_per_pose,
        )
    }

    /// The swaps worth trying, most promising first: `(place in the session's distinct
    /// poses, pool index)`. The estimate is the two legs' time in the session's order
    /// (each leg the short way round where a joint may turn); at least
    /// [`MIN_LEG_SAVING_S`].
    fn offers(
        &self,
        ordered: &SessionOrder,
        pool_poses: &[[f64; JOINTS]],
        pool_turns: &[[Vec<i32>; JOINTS]],
    ) -> Vec<(usize, usize)> {
        let tour = ordered.plan.distinct_poses();
        let model = &self.timing.model;
        let shown = |q: &[f64; JOINTS]| self.profile.shown_deg(q);
        let no_turns: [Vec<i32>; JOINTS] = core::array::from_fn(|_| vec![0]);
        let leg = |from: &[f64; JOINTS], to: &[f64; JOINTS], turns: &[Vec<i32>; JOINTS]| {
            model.move_s(
                &shown(from),
                &shown(&timing::unwind::nearest(from, to, turns)),
            )
        };
        let mut offers = Vec::new();
        for (k, here) in tour.iter().enumerate() {
            if is_revisited(k, tour.len()) {
                continue;
            }
            let prev = k.checked_sub(1).and_then(|i| tour.get(i));
            let next = tour.get(k + 1);
            let legs = |q: &[f64; JOINTS], turns: &[Vec<i32>; JOINTS]| {
                let q = prev.map_or(*q, |a| timing::unwind::nearest(a, q, turns));
                prev.map_or(0.0, |a| leg(a, &q, &no_turns))
                    + next.map_or(0.0, |b| leg(&q, b, &no_turns))
            };
            let now = legs(here, &no_turns);
            for (c, (q, turns)) in pool_poses.iter().zip(pool_turns).enumerate() {
                let saving = now - legs(q, turns);
                if saving >= MIN_LEG_SAVING_S && !tour.iter().any(|d| same_pose(d, q)) {
                    offers.push((k, c, saving));
                }
            }
        }
        offers.sort_by(|a, b| b.2.total_cmp(&a.2));
        offers.into_iter().map(|(k, c, _)| (k, c)).collect()
    }

    /// The session with its distinct pose `slot` (in the session's order) replaced by
    /// pool candidate `c`, its joints turned to least travel, if the session is then
    /// shorter, every joint's predicted k = 2 within `ceiling` and the stage-2 bound
    /// within the planner's condition number.
    fn try_swap(
        &self,
        ordered: &SessionOrder,
        slot: usize,
        c: usize,
        ceiling: &[f64; WRIST_JOINTS + 1],
    ) -> Result<Option<SessionOrder>, CliError> {
        let plan = &ordered.plan;
        let (Some(candidate), mut distinct) = (self.pool.get(c), plan.distinct_poses()) else {
            return Ok(None);
        };
        let Some(q) = distinct.get_mut(slot) else {
            return Ok(None);
        };
        *q = candidate.joints_rad;
        let n = distinct.len();
        let mut poses: PoseList<f64> = distinct.clone();
        with_revisits(&mut poses, n, plan.revisits);
        let swapped = unwound_plan(
            self.profile,
            &Plan {
                poses_rad: poses,
                ..plan.clone()
            },
            &ordered.poses.turned,
        );
        let Ok(session) =
            SessionPoses::new(self.profile, &swapped.poses_rad).with_mounts(self.profile)
        else {
            return Ok(None);
        };
        let time = timing::session_time(&Pendant::new(self.profile), &self.timing.model, &session);
        if time.total_s >= ordered.time.total_s {
            return Ok(None);
        }
        // What the fit will estimate on these poses: the geometry they separate, as
        // the planner identifies it on its own poses.
        let configured = match self.config.joint2_range_rad {
            Some(_) => self.config.extras,
            None => self.config.extras.without_joint2(),
        };
        let (extras, _) = geometry::identifiable(
            &mut Information::new(0),
            self.model,
            configured,
            distinct.iter().copied(),
            &[0.0; WRIST_JOINTS],
            geometry::GEOMETRY_CONDITION,
            self.config.noise_sigma_rad,
        );
        let Ok(bound) = covariance_bound(
            self.model,
            extras,
            &distinct,
            &[0.0; WRIST_JOINTS],
            self.config.noise_sigma_rad,
        ) else {
            return Ok(None);
        };
        if bound.condition_number > self.config.max_condition_number {
            return Ok(None);
        }
        // A budget the poses cannot carry is no swap, not an error of the plan.
        let Ok(k2) = self.k2(&swapped.poses_rad) else {
            return Ok(None);
        };
        if !within_ceiling(&k2, ceiling) {
            return Ok(None);
        }
        let max_reading_rad = distinct.iter().fold(0.0f64, |m, q| {
            let t = self.model.predict(q, &[0.0; WRIST_JOINTS]);
            m.max(t.x_rad.abs()).max(t.y_rad.abs())
        });
        Ok(Some(SessionOrder {
            plan: Plan {
                extras,
                predicted_sigma_rad: bound.sigma_rad,
                predicted_zeros_sigma_rad: bound.zeros_sigma_rad,
                condition_number: bound.condition_number,
                max_reading_rad,
                ..swapped
            },
            poses: session,
            time,
            time_unordered: ordered.time_unordered,
        }))
    }
}

/// Every joint's k = 2 within its ceiling.
fn within_ceiling(k2: &[f64; WRIST_JOINTS + 1], ceiling: &[f64; WRIST_JOINTS + 1]) -> bool {
    k2.iter().zip(ceiling).all(|(u, c)| u <= c)
}

/// Whether the session's distinct pose `k` of `n` is visited again (core's
/// `with_revisits`: the first and the middle one): a swap there would move its revisits
/// too, so it is left as the planner chose it.
fn is_revisited(k: usize, n: usize) -> bool {
    k == 0 || k == n / 2
}

/// `a` and `b` (model rad) are the same pose up to whole turns of their joints.
fn same_pose(a: &[f64; JOINTS], b: &[f64; JOINTS]) -> bool {
    a.iter().zip(b).all(|(a, b)| {
        let turns = ((a - b) / core::f64::consts::TAU).round();
        (a - b - turns * core::f64::consts::TAU).abs() < 1e-9
    })
}
