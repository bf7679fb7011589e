//! Robot time of a calibration session, and the stage-2 pose order that shortens it.
//!
//! The session a robot program drives (`zerocal program`): a stop to clip the pendant
//! to the upper arm, the stage-1 pose, joint 1 turned by 180°, joint 1 back with a
//! stop to clip the pendant to the flange, then every stage-2 pose of the plan. Its
//! robot time is modelled as:
//!
//! - **Moves.** Every move is a joint move that ends in an exact stop. Each joint runs
//!   a trapezoidal profile (constant acceleration `a` up to the speed `v`, cruise,
//!   constant deceleration) and the move lasts as long as its slowest joint:
//!   `t = d/v + v/a` for `d ≥ v²/a`, else `2·sqrt(d/a)`. A controller that
//!   synchronises the joints (all start and stop together) takes the same time.
//! - **Approach direction.** Gear backlash makes the stopping point depend on the
//!   direction a joint last moved: every target is reached with each joint's final
//!   motion in one direction, `approach[k]` (+1: from below). A move in which some
//!   joint would arrive the other way first goes to a point `approach_deg` short of
//!   the target on those joints, then on to the target ([`TimeModel::via`]).
//! - **Dwell.** At every captured pose the robot waits for the pendant: the settling
//!   of the arm after the stop, then the pendant's still window (core's
//!   [`crate::stillness::StillnessConfig`]), plus two sensor periods (the window
//!   completes on the first sample past its length; one more as margin).
//! - **Operator.** The two mountings of the pendant, and an OK on the
//!   pendant where its capture rule needs one (stage 1's second reading, and any
//!   stage-2 move that does not move the reading enough to arm the next capture).
//!
//! Poses here are in the joint coordinates the controller interpolates in and its
//! speed limits apply to (its own joint degrees): the caller converts. The functions
//! need no heap and run on the pendant as well as the desktop.

use super::MAX_POSES;
use crate::model::JOINTS;
use crate::real::Real;
use core::fmt;

/// Below this a joint's move counts as none (deg): rounding of the caller's
/// conversions, far below any controller's resolution (0.001°).
const NO_MOVE_DEG: f64 = 1e-9;

/// Local-search passes of [`shortest_tour`] at most (each tries every relocation and
/// reversal; a pass that improves nothing ends the search long before this).
const MAX_TOUR_PASSES: u32 = 200;

/// The robot-time model of a session.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeModel<T> {
    /// Each joint's speed during the session's moves (deg/s): the reduced speed the
    /// program commands.
    pub speed_deg_s: [T; JOINTS],
    /// Each joint's acceleration and deceleration (deg/s²).
    pub accel_deg_s2: [T; JOINTS],
    /// Each joint's final direction of motion at every target: +1 (approached from
    /// below) or −1 (from above).
    pub approach: [i8; JOINTS],
    /// How far short of a target a joint stops when it must turn round to arrive in
    /// its approach direction (deg).
    pub approach_deg: T,
    /// From the robot's stop to the start of the pendant's still window (s).
    pub settle_s: T,
    /// The pendant's still window (s).
    pub window_s: T,
    /// The sensor's reading period (s).
    pub sample_period_s: T,
    /// Clipping the pendant on (to the upper arm; from there to the flange) (s).
    pub remount_s: T,
    /// An operator's OK on the pendant at a stop of the program (s).
    pub operator_ok_s: T,
}

/// Which setting of a [`TimeModel`] is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TimeSetting {
    /// `speed_deg_s` of a joint (1..=6).
    Speed {
        /// Robot joint number.
        joint: u8,
    },
    /// `accel_deg_s2` of a joint (1..=6).
    Acceleration {
        /// Robot joint number.
        joint: u8,
    },
    /// `approach` of a joint (1..=6).
    Approach {
        /// Robot joint number.
        joint: u8,
    },
    /// `approach_deg`.
    ApproachDistance,
    /// `settle_s`, `window_s`, `sample_period_s`, `remount_s` or `operator_ok_s`.
    Duration,
}

impl fmt::Display for TimeSetting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            TimeSetting::Speed { joint } => {
                write!(f, "speed of joint {joint}: must be a positive finite deg/s")
            }
            TimeSetting::Acceleration { joint } => write!(
                f,
                "acceleration of joint {joint}: must be a positive finite deg/s²"
            ),
            TimeSetting::Approach { joint } => {
                write!(f, "approach direction of joint {joint}: must be +1 or -1")
            }
            TimeSetting::ApproachDistance => {
                f.write_str("approach distance: must be a positive finite angle")
            }
            TimeSetting::Duration => {
                f.write_str("settle, window, sample period, remount and OK times: must be finite and >= 0 (window and period > 0)")
            }
        }
    }
}

/// The robot time of a session, by part (s).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SessionTime<T> {
    /// The robot moving.
    pub motion_s: T,
    /// The robot standing at captured poses for settling and the still window.
    pub dwell_s: T,
    /// The pendant's two mountings (upper arm, then flange).
    pub remount_s: T,
    /// Operator OKs at the pendant.
    pub operator_s: T,
    /// All of it.
    pub total_s: T,
    /// Moves, approach moves included.
    pub moves: u16,
    /// Moves that stop short of a target to arrive in the approach direction.
    pub approach_moves: u16,
    /// Stops for an operator's OK (stage 1's second reading included).
    pub ok_stops: u16,
}

impl<T: Real> TimeModel<T> {
    /// Checks the settings.
    ///
    /// # Errors
    /// The first setting that is out of its domain.
    pub fn validate(&self) -> Result<(), TimeSetting> {
        for k in 0..JOINTS {
            let joint = k as u8 + 1;
            let v = self.speed_deg_s[k];
            if !(v.is_finite() && v > T::zero()) {
                return Err(TimeSetting::Speed { joint });
            }
            let a = self.accel_deg_s2[k];
            if !(a.is_finite() && a > T::zero()) {
                return Err(TimeSetting::Acceleration { joint });
            }
            if self.approach[k] != 1 && self.approach[k] != -1 {
                return Err(TimeSetting::Approach { joint });
            }
        }
        if !(self.approach_deg.is_finite() && self.approach_deg > T::zero()) {
            return Err(TimeSetting::ApproachDistance);
        }
        let non_negative = [self.settle_s, self.remount_s, self.operator_ok_s];
        let positive = [self.window_s, self.sample_period_s];
        if non_negative
            .iter()
            .any(|t| !(t.is_finite() && *t >= T::zero()))
            || positive.iter().any(|t| !(t.is_finite() && *t > T::zero()))
        {
            return Err(TimeSetting::Duration);
        }
        Ok(())
    }

    /// The robot's wait at a captured pose (s): settling, the still window and two
    /// sensor periods.
    pub fn dwell_s(&self) -> T {
        self.settle_s + self.window_s + self.sample_period_s * T::lit(2.0)
    }

    /// Time of one joint's trapezoidal move over `d_deg` (either sign).
    pub fn joint_move_s(&self, joint: usize, d_deg: T) -> T {
        let (Some(&v), Some(&a)) = (self.speed_deg_s.get(joint), self.accel_deg_s2.get(joint))
        else {
            return T::zero();
        };
        let d = d_deg.abs();
        if d <= T::lit(NO_MOVE_DEG) {
            T::zero()
        } else if d >= v * v / a {
            d / v + v / a
        } else {
            T::lit(2.0) * (d / a).sqrt()
        }
    }

    /// Time of a joint move from `from` to `to`: its slowest joint's.
    pub fn move_s(&self, from: &[T; JOINTS], to: &[T; JOINTS]) -> T {
        (0..JOINTS).fold(T::zero(), |m, k| {
            m.max(self.joint_move_s(k, to[k] - from[k]))
        })
    }

    /// Whether joint `k` moving from `from` to `to` arrives against its approach
    /// direction.
    fn against(&self, k: usize, from: T, to: T) -> bool {
        let d = to - from;
        d.abs() > T::lit(NO_MOVE_DEG) && (d * T::lit(f64::from(self.approach[k]))) < T::zero()
    }

    /// The point short of `to` that a move from `from` must pass so that every joint
    /// arrives at `to` in its approach direction: `None` if the move already does.
    /// Joints that would arrive the wrong way stop `approach_deg` short of the
    /// target (on the approach side); the others go straight to it.
    pub fn via(&self, from: &[T; JOINTS], to: &[T; JOINTS]) -> Option<[T; JOINTS]> {
        let mut any = false;
        let mut v = *to;
        for k in 0..JOINTS {
            if self.against(k, from[k], to[k]) {
                any = true;
                v[k] = to[k] - self.approach_deg * T::lit(f64::from(self.approach[k]));
            }
        }
        any.then_some(v)
    }

    /// The point `approach_deg` short of `to` on every joint: where a session starts
    /// from a pose it does not know.
    pub fn entry(&self, to: &[T; JOINTS]) -> [T; JOINTS] {
        core::array::from_fn(|k| to[k] - self.approach_deg * T::lit(f64::from(self.approach[k])))
    }

    /// Time from `from` to `to`, through [`via`](Self::via) when needed.
    pub fn leg_s(&self, from: &[T; JOINTS], to: &[T; JOINTS]) -> T {
        match self.via(from, to) {
            Some(v) => self.move_s(from, &v) + self.move_s(&v, to),
            None => self.move_s(from, to),
        }
    }

    /// The robot time of a whole session along `path`: from the
    /// [`entry`](Self::entry) point of the first mounting pose (the move to the entry
    /// point starts from a pose unknown here and is not counted) to that pose, the
    /// pendant clipped to the upper arm there, the stage-1 pose, joint 1 turned (an
    /// OK arms that reading), the second mounting pose and the remount, then the
    /// stage-2 poses in order. Every move arrives in the approach direction, so that
    /// a joint a later move leaves alone stays on the right side of its backlash. `needs_ok(a, b)` says whether a move between stage-2 poses `a` → `b`
    /// leaves the pendant's next capture unarmed (an operator's OK then arms it); the
    /// first stage-2 pose is armed by the remount.
    pub fn session_time(
        &self,
        path: &SessionPath<'_, T>,
        needs_ok: impl Fn(&[T; JOINTS], &[T; JOINTS]) -> bool,
    ) -> SessionTime<T> {
        let mut s = SessionTime::default();
        let go = |s: &mut SessionTime<T>, from: &[T; JOINTS], to: &[T; JOINTS]| {
            if let Some(v) = self.via(from, to) {
                s.motion_s += self.move_s(from, &v) + self.move_s(&v, to);
                s.moves += 2;
                s.approach_moves += 1;
            } else {
                s.motion_s += self.move_s(from, to);
                s.moves += 1;
            }
        };
        // Stage 1: clip the pendant on, its pose, joint 1 turned (an OK arms that
        // reading).
        go(&mut s, &self.entry(&path.mount1), &path.mount1);
        s.remount_s += self.remount_s;
        go(&mut s, &path.mount1, &path.stage1);
        s.dwell_s += self.dwell_s();
        go(&mut s, &path.stage1, &path.turned);
        s.dwell_s += self.dwell_s();
        s.operator_s += self.operator_ok_s;
        s.ok_stops += 1;
        // The pendant to the flange.
        go(&mut s, &path.turned, &path.mount2);
        s.remount_s += self.remount_s;
        // Stage 2.
        let mut here = path.mount2;
        for (i, q) in path.poses.iter().enumerate() {
            go(&mut s, &here, q);
            s.dwell_s += self.dwell_s();
            if i > 0 && needs_ok(&here, q) {
                s.operator_s += self.operator_ok_s;
                s.ok_stops += 1;
            }
            here = *q;
        }
        s.total_s = s.motion_s + s.dwell_s + s.remount_s + s.operator_s;
        s
    }
}

/// The poses of a session, in the controller's joint coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SessionPath<'a, T> {
    /// Where the robot stands while the pendant is clipped to the upper arm.
    pub mount1: [T; JOINTS],
    /// The stage-1 pose.
    pub stage1: [T; JOINTS],
    /// The stage-1 pose with joint 1 turned by 180°.
    pub turned: [T; JOINTS],
    /// Where the robot stands while the pendant is moved to the flange.
    pub mount2: [T; JOINTS],
    /// The stage-2 poses, in order.
    pub poses: &'a [[T; JOINTS]],
}

/// A visiting order of at most [`MAX_POSES`] poses (indices into the caller's list).
pub type Tour = heapless::Vec<u8, MAX_POSES>;

fn tour_cost<T: Real>(
    order: &[u8],
    from_start: &impl Fn(usize) -> T,
    cost: &impl Fn(usize, usize) -> T,
) -> T {
    let Some(&first) = order.first() else {
        return T::zero();
    };
    let mut total = from_start(usize::from(first));
    for w in order.windows(2) {
        total += cost(usize::from(w[0]), usize::from(w[1]));
    }
    total
}

/// `a` better than `b` by more than rounding.
fn shorter<T: Real>(a: T, b: T) -> bool {
    b - a > T::lit(1e3) * T::EPSILON * b.abs().max(T::one())
}

/// The order of `n` poses (at most [`MAX_POSES`]) that makes the session short: the
/// path from the start through every pose once, costs `from_start(i)` for the first
/// leg and `cost(i, j)` for each next one (asymmetric costs allowed: the approach
/// direction makes them so).
///
/// Nearest neighbour from the start, or the given order if that is shorter, then
/// local search (moving a run of up to three poses elsewhere, reversing a stretch)
/// while a change shortens the path. Never longer than the given order `0..n`.
pub fn shortest_tour<T: Real>(
    n: usize,
    from_start: impl Fn(usize) -> T,
    cost: impl Fn(usize, usize) -> T,
) -> Tour {
    let n = n.min(MAX_POSES);
    let mut given = Tour::new();
    let mut nearest = Tour::new();
    let mut used = [false; MAX_POSES];
    for i in 0..n {
        // n ≤ MAX_POSES ≤ 255: neither push can fail.
        let _ = given.push(i as u8);
        let mut best: Option<(usize, T)> = None;
        for (j, u) in used.iter().enumerate().take(n) {
            if *u {
                continue;
            }
            let c = match nearest.last() {
                None => from_start(j),
                Some(&last) => cost(usize::from(last), j),
            };
            if best.is_none_or(|(_, b)| c < b) {
                best = Some((j, c));
            }
        }
        if let Some((j, _)) = best {
            used[j] = true;
            let _ = nearest.push(j as u8);
        }
    }
    let (mut order, mut total) = {
        let g = tour_cost(&given, &from_start, &cost);
        let nn = tour_cost(&nearest, &from_start, &cost);
        if nn < g {
            (nearest, nn)
        } else {
            (given, g)
        }
    };
    for _ in 0..MAX_TOUR_PASSES {
        let mut improved = false;
        // Relocate a run of 1-3 poses to another place.
        for len in 1..=3usize {
            if len >= order.len() {
                break;
            }
            let mut i = 0;
            while i + len <= order.len() {
                for j in 0..=order.len() - len {
                    if j == i {
                        continue;
                    }
                    let mut trial = order.clone();
                    let mut run = [0u8; 3];
                    run[..len].copy_from_slice(&trial[i..i + len]);
                    // Remove the run, then insert it at j (an index in the shortened list).
                    for _ in 0..len {
                        trial.remove(i);
                    }
                    for (m, &p) in run[..len].iter().enumerate() {
                        let _ = trial.insert(j + m, p);
                    }
                    let c = tour_cost(&trial, &from_start, &cost);
                    if shorter(c, total) {
                        order = trial;
                        total = c;
                        improved = true;
                    }
                }
                i += 1;
            }
        }
        // Reverse a stretch.
        for i in 0..order.len() {
            for j in (i + 2)..=order.len() {
                let mut trial = order.clone();
                trial[i..j].reverse();
                let c = tour_cost(&trial, &from_start, &cost);
                if shorter(c, total) {
                    order = trial;
                    total = c;
                    improved = true;
                }
            }
        }
        if !improved {
            break;
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{plan, Candidate, PlanConfig, DEFAULT_POOL};
    use crate::stage2::{covariance_bound, Extras, Stage2Model};
    use crate::testing::isclose;

    fn model() -> TimeModel<f64> {
        TimeModel {
            speed_deg_s: [10.0, 10.0, 20.0, 30.0, 30.0, 60.0],
            accel_deg_s2: [100.0; JOINTS],
            approach: [1; JOINTS],
            approach_deg: 1.0,
            settle_s: 1.0,
            window_s: 2.0,
            sample_period_s: 0.05,
            remount_s: 60.0,
            operator_ok_s: 10.0,
        }
    }

    #[test]
    fn trapezoid_and_triangle_times() {
        let m = model();
        // Cruise: 90° at 10°/s with 100°/s²: 9 s + the 0.1 s the ramps lose.
        assert!(isclose(m.joint_move_s(0, 90.0), 9.1, 0.0, 1e-12));
        // Short: 0.5° never reaches 10°/s (needs 1°): 2·sqrt(0.5/100) s.
        assert!(isclose(
            m.joint_move_s(0, -0.5),
            2.0 * 0.005f64.sqrt(),
            0.0,
            1e-12
        ));
        // At the boundary both formulas agree: 1° → 0.2 s.
        assert!(isclose(m.joint_move_s(0, 1.0), 0.2, 0.0, 1e-12));
        // The slowest joint sets the move: 90° on joint 1 (9.1 s) beats 90° on joint 6.
        let a = [0.0; JOINTS];
        let b = [90.0, 0.0, 0.0, 0.0, 0.0, 90.0];
        assert!(isclose(m.move_s(&a, &b), 9.1, 0.0, 1e-12));
        assert_eq!(m.move_s(&a, &a), 0.0);
    }

    #[test]
    fn moves_arriving_the_wrong_way_go_through_an_approach_point() {
        let mut m = model();
        m.approach = [1, -1, 1, 1, 1, 1];
        let from = [0.0, 0.0, 10.0, 0.0, 0.0, 0.0];
        let to = [5.0, 5.0, 0.0, 0.0, 0.0, 0.0];
        let v = m.via(&from, &to).unwrap_or([f64::NAN; JOINTS]);
        // Joint 2 (from above) moves up and joint 3 (from below) moves down: both stop
        // 1° beyond on their approach side; joint 1 goes straight to its target.
        assert_eq!(v, [5.0, 6.0, -1.0, 0.0, 0.0, 0.0]);
        for k in 0..JOINTS {
            let last = to[k] - v[k];
            assert!(last * f64::from(m.approach[k]) >= 0.0, "joint {}", k + 1);
        }
        assert!(m
            .via(&[0.0; JOINTS], &[1.0, -1.0, 1.0, 0.0, 0.0, 0.0])
            .is_none());
        let e = m.entry(&to);
        assert_eq!(e, [4.0, 6.0, -1.0, -1.0, -1.0, -1.0]);
        assert!(m.leg_s(&from, &to) > m.move_s(&from, &to));
    }

    #[test]
    fn session_time_adds_its_parts() {
        let m = model();
        let s1 = [0.0; JOINTS];
        let mount1 = [0.0, 45.0, 0.0, 0.0, 0.0, 0.0];
        let turned = [180.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mount2 = [0.0, 0.0, 30.0, 0.0, 45.0, 0.0];
        let poses = [
            [0.0, 0.0, 30.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 60.0, 0.0, 0.0, 0.0],
        ];
        let path = SessionPath {
            mount1,
            stage1: s1,
            turned,
            mount2,
            poses: &poses,
        };
        let t = m.session_time(&path, |_, _| true);
        // Entry (1° on every joint: the slowest, 10°/s joints, take 0.2 s); joint 2
        // down 45° from above: through -1°, 46° then 1°; the turn 18.1 s; back to the
        // flange mount: joint 1 -180° through -1° (181° then 1°), 30° on joint 3 and
        // 45° on joint 5 meanwhile; then joint 5 down 45° to pose 1 through -1° (46°
        // at 30°/s and 1°); 30° on joint 3 (1.5 + 0.2 s, 20°/s loses 0.2 s).
        let j = |k, d| m.joint_move_s(k, d);
        let expect_motion = 0.2
            + (j(1, 46.0) + j(1, 1.0))
            + 18.1
            + (j(0, 181.0) + j(0, 1.0))
            + (j(4, 46.0) + j(4, 1.0))
            + 1.7;
        assert!(isclose(t.motion_s, expect_motion, 0.0, 1e-9), "{t:?}");
        assert!(isclose(t.dwell_s, 4.0 * m.dwell_s(), 0.0, 1e-12));
        // Stage 1's OK and the second stage-2 pose's (the first is armed by the remount).
        assert_eq!(t.ok_stops, 2);
        assert_eq!(t.approach_moves, 3);
        assert!(isclose(
            t.total_s,
            t.motion_s + t.dwell_s + 120.0 + 20.0,
            0.0,
            1e-9
        ));
        assert!(m.validate().is_ok());
        let mut bad = m;
        bad.approach[3] = 0;
        assert_eq!(bad.validate(), Err(TimeSetting::Approach { joint: 4 }));
        bad = m;
        bad.speed_deg_s[5] = f64::NAN;
        assert_eq!(bad.validate(), Err(TimeSetting::Speed { joint: 6 }));
        bad = m;
        bad.window_s = 0.0;
        assert_eq!(bad.validate(), Err(TimeSetting::Duration));
    }

    /// Costs between points on a line, visited from 0: the shortest path is sorted.
    #[test]
    fn tour_finds_the_sorted_order_on_a_line_and_is_a_permutation() {
        let x: [f64; 9] = [5.0, 1.0, 9.0, 3.0, 7.0, 2.0, 8.0, 4.0, 6.0];
        let order = shortest_tour(x.len(), |i| x[i], |i, j| (x[j] - x[i]).abs());
        let visited: std::vec::Vec<f64> = order.iter().map(|&i| x[usize::from(i)]).collect();
        assert_eq!(visited, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        let mut seen = [false; 9];
        for &i in &order {
            seen[usize::from(i)] = true;
        }
        assert!(seen.iter().all(|s| *s));
        assert!(shortest_tour::<f64>(0, |_| 0.0, |_, _| 0.0).is_empty());
    }

    /// The planner's own 12-pose plan: the time-ordered tour is no longer than the
    /// planner's order, and the predicted 1σ is the same set of poses' (the
    /// information is a sum over poses: order cannot change it beyond rounding).
    #[test]
    fn tour_shortens_the_session_and_keeps_the_predicted_sigma() {
        let model2 = Stage2Model::<f64>::default();
        let config = PlanConfig {
            poses: 12,
            ..PlanConfig::default()
        };
        let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
        let p = plan(&model2, &config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        let deg: std::vec::Vec<[f64; JOINTS]> =
            p.poses_rad.iter().map(|q| q.map(f64::to_degrees)).collect();
        let m = model();
        let start = [0.0; JOINTS];
        let order = shortest_tour(
            deg.len(),
            |i| m.leg_s(&start, &deg[i]),
            |i, j| m.leg_s(&deg[i], &deg[j]),
        );
        let tour: std::vec::Vec<[f64; JOINTS]> =
            order.iter().map(|&i| deg[usize::from(i)]).collect();
        let path = |poses| SessionPath {
            mount1: start,
            stage1: start,
            turned: [180.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            mount2: start,
            poses,
        };
        let t0 = m.session_time(&path(&deg), |_, _| false);
        let t1 = m.session_time(&path(&tour), |_, _| false);
        assert!(t1.motion_s <= t0.motion_s, "{t1:?} vs {t0:?}");
        std::println!(
            "12 planned poses: motion {:.1} s in the planner's order, {:.1} s toured",
            t0.motion_s,
            t1.motion_s
        );
        let rad: std::vec::Vec<[f64; JOINTS]> =
            tour.iter().map(|q| q.map(f64::to_radians)).collect();
        let noise = config.noise_sigma_rad;
        let a = covariance_bound(&model2, Extras::NONE, &p.poses_rad, &[0.0; 4], noise);
        let b = covariance_bound(&model2, Extras::NONE, &rad, &[0.0; 4], noise);
        let (Ok(a), Ok(b)) = (a, b) else {
            panic!("bound refused");
        };
        for k in 0..4 {
            // Sums of the same 12 terms in another order, through degrees and back:
            // relative rounding of order 1e-12.
            assert!(
                isclose(b.sigma_rad[k], a.sigma_rad[k], 1e-9, 0.0),
                "j{}",
                k + 3
            );
        }
    }
}
