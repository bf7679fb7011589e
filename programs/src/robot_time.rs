//! Robot time of a calibration session, and the stage-2 pose order that shortens it.
//!
//! The session a robot program drives (`zerocal program`), as the project decided it:
//!
//! 1. **Stage 1.** The robot stands at a mounting pose (the pendant tilted past its
//!    range, so it cannot capture while it is clipped on) and the pendant is clipped to
//!    the upper arm. The stage-1 pose is captured twice: first with every joint arriving
//!    moving in its positive direction (from below), then, after every joint has gone
//!    past it, with every joint arriving moving negative (from above). Joint 1 is turned
//!    by 180° and the turned pose is captured twice the same way; an operator's OK arms
//!    the first of these (a half turn barely moves the reading: the pendant's rule).
//! 2. **Stage 2.** The robot goes to a second mounting pose, the pendant is moved to the
//!    flange, and every pose of the plan is captured twice the same way. The session
//!    solver averages the two captures of a pose (`zerocal_core::session::merge_repeats`): the
//!    reading at the middle of every gear's play.
//! 3. **The closing bench readings.** The robot parks, the pendant is taken off and read
//!    on the bench as in stage 0 ([`BENCH_HEADINGS`] captures, turned by hand about a
//!    quarter turn on the same spot between them, an OK arming each after the first): a
//!    third mounting. The robot's part ends when the pendant is off the flange: the
//!    program ends there, and the readings on the bench need no robot
//!    ([`SessionTime::closing_s`], not in the robot time).
//!
//! Its robot time is modelled as:
//!
//! - **Moves.** Every move is a joint move that ends in an exact stop. Each joint runs
//!   a trapezoidal profile (constant acceleration `a` up to the speed `v`, cruise,
//!   constant deceleration) and the move lasts as long as its slowest joint:
//!   `t = d/v + v/a` for `d ≥ v²/a`, else `2·sqrt(d/a)`. A controller that
//!   synchronises the joints (all start and stop together) takes the same time.
//! - **Both sides of the backlash.** A pose's first capture is reached through the point
//!   `approach_deg` below it on every joint ([`TimeModel::below`]), its second through the
//!   point `overshoot_deg` above it ([`TimeModel::above`]): the last move before each
//!   capture moves every joint, in one direction. The overshoot is also what re-arms the
//!   pendant between the two captures (it must move the reading by the pendant's re-arm
//!   threshold: the caller checks, `needs_ok`).
//! - **Dwell.** At every capture the robot waits for the pendant: the settling of the arm
//!   after the stop, then the pendant's still window (the procedure's
//!   [`zerocal_procedure::stillness::StillnessConfig`]), plus two sensor periods (the window
//!   completes on the first sample past its length; one more as margin).
//! - **Operator.** The three mountings of the pendant (upper arm, flange, bench), and an
//!   OK on the pendant where its capture rule needs one (after joint 1's half turn and
//!   each turn on the bench, and after any move that does not move the reading enough
//!   to arm the next capture).
//!
//! Poses here are in the joint coordinates the controller interpolates in and its
//! speed limits apply to (its own joint degrees): the caller converts. The tour is a
//! bounded list (`heapless`) of at most [`MAX_POSES`] poses, as the pendant's plan is.

use core::fmt;
use zerocal_core::model::JOINTS;
use zerocal_core::plan::MAX_POSES;
use zerocal_core::real::Real;
use zerocal_core::stage0::BENCH_HEADINGS;

/// Captures of every pose (stage 1's two and stage 2's): one from each side of the
/// backlash.
pub const CAPTURES_PER_POSE: usize = 2;

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
    /// How far below a pose every joint starts the last move to its first capture (deg).
    pub approach_deg: T,
    /// How far above a pose every joint goes before coming back for its second capture
    /// (deg): the excursion that re-arms the pendant.
    pub overshoot_deg: T,
    /// From the robot's stop to the start of the pendant's still window (s).
    pub settle_s: T,
    /// The pendant's still window (s).
    pub window_s: T,
    /// The sensor's reading period (s).
    pub sample_period_s: T,
    /// Clipping the pendant on or taking it off to the bench, each of the three
    /// mountings (s).
    pub remount_s: T,
    /// An operator's OK on the pendant at a stop of the program (s).
    pub operator_ok_s: T,
}

/// Which setting of a [`TimeModel`] is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
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
    /// `approach_deg` or `overshoot_deg`.
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
            TimeSetting::ApproachDistance => {
                f.write_str("approach and overshoot distances: must be positive finite angles")
            }
            TimeSetting::Duration => {
                f.write_str("settle, window, sample period, remount and OK times: must be finite and >= 0 (window and period > 0)")
            }
        }
    }
}

/// Where the pendant is while the robot drives a path: which reading the caller's
/// `needs_ok` predicts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mounting {
    /// On the upper arm (stage 1).
    UpperArm,
    /// On the flange (stage 2).
    Flange,
}

/// The robot time of a session, by part (s).
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct SessionTime<T> {
    /// The robot moving.
    pub motion_s: T,
    /// Standing for settling and the still window at every capture on the robot.
    pub dwell_s: T,
    /// The pendant's three mountings (clipped to the upper arm, moved to the flange,
    /// taken off the flange to the bench).
    pub remount_s: T,
    /// Operator OKs at the pendant while it is on the robot.
    pub operator_s: T,
    /// The robot time: all of the above, from the first mounting until the pendant is
    /// off the flange.
    pub total_s: T,
    /// The closing bench readings after the robot's part (their dwells and the OKs
    /// between their headings): the operator's time on the bench, the robot free.
    pub closing_s: T,
    /// Moves.
    pub moves: u16,
    /// Captures on the robot (stage 1's four, two per stage-2 pose).
    pub captures: u16,
    /// Mountings of the pendant.
    pub mountings: u16,
    /// Stops for an operator's OK while the pendant is on the robot.
    pub ok_stops: u16,
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
    /// Where the robot parks while the pendant is taken off for the closing readings.
    pub park: [T; JOINTS],
}

/// The poses of a check, in the controller's joint coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheckPath<'a, T> {
    /// Where the robot stands while the pendant is clipped to the flange.
    pub mount: [T; JOINTS],
    /// The check's poses (the session plan's, a subset), in order.
    pub poses: &'a [[T; JOINTS]],
    /// Where the robot parks while the pendant is taken off for the closing readings.
    pub park: [T; JOINTS],
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
        }
        if [self.approach_deg, self.overshoot_deg]
            .iter()
            .any(|d| !(d.is_finite() && *d > T::zero()))
        {
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

    /// The robot's wait at a capture (s): settling, the still window and two sensor
    /// periods.
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

    /// Time of the moves through `points` in turn.
    pub fn path_s(&self, points: &[[T; JOINTS]]) -> T {
        points
            .windows(2)
            .fold(T::zero(), |t, w| t + self.move_s(&w[0], &w[1]))
    }

    /// The point [`approach_deg`](Self::approach_deg) below `q` on every joint: where the
    /// last move to a pose's first capture starts.
    pub fn below(&self, q: &[T; JOINTS]) -> [T; JOINTS] {
        q.map(|v| v - self.approach_deg)
    }

    /// The point [`overshoot_deg`](Self::overshoot_deg) above `q` on every joint: where
    /// the last move to a pose's second capture starts.
    pub fn above(&self, q: &[T; JOINTS]) -> [T; JOINTS] {
        q.map(|v| v + self.overshoot_deg)
    }

    /// The path from `from` to the first capture of `q`: through [`below`](Self::below),
    /// so that every joint arrives moving in its positive direction.
    pub fn first_capture_path(&self, from: &[T; JOINTS], q: &[T; JOINTS]) -> [[T; JOINTS]; 3] {
        [*from, self.below(q), *q]
    }

    /// The path from the first capture of `q` to its second: past it to
    /// [`above`](Self::above) and back, every joint arriving moving negative.
    pub fn second_capture_path(&self, q: &[T; JOINTS]) -> [[T; JOINTS]; 3] {
        [*q, self.above(q), *q]
    }

    /// The path from the stage-1 pose's second capture to the turned pose's first:
    /// joint 1 alone turns (to [`approach_deg`](Self::approach_deg) short of its
    /// target), so that the reading stays put while it turns, then every joint comes up
    /// from [`below`](Self::below).
    pub fn turn_path(&self, stage1: &[T; JOINTS], turned: &[T; JOINTS]) -> [[T; JOINTS]; 4] {
        let mut turn = *stage1;
        turn[0] = turned[0] - self.approach_deg;
        [*stage1, turn, self.below(turned), *turned]
    }

    /// The robot time of a whole session along `path` (see the module's list): the
    /// pendant clipped to the upper arm at `mount1` (the move to it starts from a pose
    /// unknown here and is not counted), stage 1's four captures, the pendant moved to
    /// the flange at `mount2`, two captures of every stage-2 pose in order, then the
    /// robot parked at `park` and the pendant taken off it (a mounting). The closing
    /// readings on the bench ([`BENCH_HEADINGS`] captures, an OK before each after the
    /// first) follow with the robot free: [`SessionTime::closing_s`], not in the total.
    ///
    /// `needs_ok(mounting, path)` says whether driving `path` from the last capture
    /// (its first point) leaves the pendant's next capture unarmed, so that an
    /// operator's OK must arm it. The first capture after a mounting is armed by the
    /// mounting, the first after joint 1's half turn always by an OK.
    pub fn session_time(
        &self,
        path: &SessionPath<'_, T>,
        needs_ok: impl Fn(Mounting, &[[T; JOINTS]]) -> bool,
    ) -> SessionTime<T> {
        let mut s = SessionTime::default();
        let run = |s: &mut SessionTime<T>, points: &[[T; JOINTS]]| {
            s.motion_s += self.path_s(points);
            s.moves += points.len().saturating_sub(1) as u16;
        };
        let capture = |s: &mut SessionTime<T>| {
            s.dwell_s += self.dwell_s();
            s.captures += 1;
        };
        let ok = |s: &mut SessionTime<T>| {
            s.operator_s += self.operator_ok_s;
            s.ok_stops += 1;
        };
        let mount = |s: &mut SessionTime<T>| {
            s.remount_s += self.remount_s;
            s.mountings += 1;
        };
        // Stage 1 on the upper arm.
        mount(&mut s);
        run(&mut s, &self.first_capture_path(&path.mount1, &path.stage1));
        capture(&mut s);
        let p = self.second_capture_path(&path.stage1);
        run(&mut s, &p);
        capture(&mut s);
        if needs_ok(Mounting::UpperArm, &p) {
            ok(&mut s);
        }
        run(&mut s, &self.turn_path(&path.stage1, &path.turned));
        ok(&mut s);
        capture(&mut s);
        let p = self.second_capture_path(&path.turned);
        run(&mut s, &p);
        capture(&mut s);
        if needs_ok(Mounting::UpperArm, &p) {
            ok(&mut s);
        }
        // The pendant to the flange.
        run(&mut s, &[path.turned, path.mount2]);
        self.on_the_flange(&mut s, path.mount2, path.poses, path.park, &needs_ok);
        s
    }

    /// The robot time of a check along `path`: the pendant clipped to the flange at
    /// `mount` (the move to it starts from a pose unknown here and is not counted), two
    /// captures of every check pose in order, then the robot parked at `park` and the
    /// pendant taken off, the closing readings counted as a session's are. No stage 1. `needs_ok`
    /// as for [`session_time`](Self::session_time).
    pub fn check_time(
        &self,
        path: &CheckPath<'_, T>,
        needs_ok: impl Fn(Mounting, &[[T; JOINTS]]) -> bool,
    ) -> SessionTime<T> {
        let mut s = SessionTime::default();
        self.on_the_flange(&mut s, path.mount, path.poses, path.park, &needs_ok);
        s
    }

    /// The part a session and a check share, added to `s`: the pendant clipped to the
    /// flange at `mount`, two captures of every pose, the park and the pendant taken
    /// off; then the total, and the closing readings after it.
    fn on_the_flange(
        &self,
        s: &mut SessionTime<T>,
        mount2: [T; JOINTS],
        poses: &[[T; JOINTS]],
        park: [T; JOINTS],
        needs_ok: &impl Fn(Mounting, &[[T; JOINTS]]) -> bool,
    ) {
        let run = |s: &mut SessionTime<T>, points: &[[T; JOINTS]]| {
            s.motion_s += self.path_s(points);
            s.moves += points.len().saturating_sub(1) as u16;
        };
        let capture = |s: &mut SessionTime<T>| {
            s.dwell_s += self.dwell_s();
            s.captures += 1;
        };
        let ok = |s: &mut SessionTime<T>| {
            s.operator_s += self.operator_ok_s;
            s.ok_stops += 1;
        };
        let mount = |s: &mut SessionTime<T>| {
            s.remount_s += self.remount_s;
            s.mountings += 1;
        };
        mount(s);
        // Stage 2 (or the check's poses).
        let mut here = mount2;
        for (i, q) in poses.iter().enumerate() {
            let p = self.first_capture_path(&here, q);
            run(s, &p);
            if i > 0 && needs_ok(Mounting::Flange, &p) {
                ok(s);
            }
            capture(s);
            let p = self.second_capture_path(q);
            run(s, &p);
            if needs_ok(Mounting::Flange, &p) {
                ok(s);
            }
            capture(s);
            here = *q;
        }
        // Park and take the pendant off: the robot's part ends there.
        run(s, &[here, park]);
        mount(s);
        s.total_s = s.motion_s + s.dwell_s + s.remount_s + s.operator_s;
        // The closing readings on the bench, the robot free: a capture at every
        // heading, an OK arming each after a turn by hand.
        let headings = T::lit(BENCH_HEADINGS as f64);
        s.closing_s = self.dwell_s() * headings + self.operator_ok_s * (headings - T::one());
    }
}

/// A visiting order of at most [`MAX_POSES`] poses (indices into the caller's list).
pub type Tour = heapless::Vec<u8, MAX_POSES>;

/// The cost of the path through `order` as `visits` goes through it: `visits` holds
/// positions in `order` (a position twice is a pose visited again), the legs between
/// consecutive visits costed by `cost`, the first by `from_start`.
fn tour_cost<T: Real>(
    order: &[u8],
    visits: &[usize],
    from_start: &impl Fn(usize) -> T,
    cost: &impl Fn(usize, usize) -> T,
) -> T {
    let pose = |v: &usize| order.get(*v).map(|&p| usize::from(p));
    let mut seq = visits.iter().filter_map(pose);
    let Some(first) = seq.next() else {
        return T::zero();
    };
    let mut total = from_start(first);
    let mut last = first;
    for p in seq {
        total += cost(last, p);
        last = p;
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
    let visits: heapless::Vec<usize, MAX_POSES> = (0..n.min(MAX_POSES)).collect();
    shortest_tour_visiting(n, &visits, from_start, cost)
}

/// [`shortest_tour`] for a session that visits some poses again: `visits` lists the
/// positions in the order the robot visits them (a position twice: the pose in that
/// place of the tour visited again, as core's `with_revisits` places them), and the
/// path costed is that visiting sequence, so the tour puts the revisited poses where
/// going back to them costs least.
pub fn shortest_tour_visiting<T: Real>(
    n: usize,
    visits: &[usize],
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
        let g = tour_cost(&given, visits, &from_start, &cost);
        let nn = tour_cost(&nearest, visits, &from_start, &cost);
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
                    let c = tour_cost(&trial, visits, &from_start, &cost);
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
                let c = tour_cost(&trial, visits, &from_start, &cost);
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
    use zerocal_core::plan::{plan, Candidate, PlanConfig, DEFAULT_POOL};
    use zerocal_core::stage2::{covariance_bound, Extras, Stage2Model};
    use zerocal_core::testing::isclose;

    fn model() -> TimeModel<f64> {
        TimeModel {
            speed_deg_s: [10.0, 10.0, 20.0, 30.0, 30.0, 60.0],
            accel_deg_s2: [100.0; JOINTS],
            approach_deg: 1.0,
            overshoot_deg: 2.0,
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
        let b = [90.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let c = [90.0, 0.0, 0.0, 0.0, 0.0, 90.0];
        assert!(isclose(m.move_s(&a, &c), 9.1, 0.0, 1e-12));
        assert_eq!(m.move_s(&a, &a), 0.0);
        assert!(isclose(m.path_s(&[a, b, a]), 18.2, 0.0, 1e-12));
    }

    /// Every capture's last move moves every joint, by the approach distance in the
    /// positive direction (first capture) or by the overshoot in the negative one
    /// (second); the half turn moves joint 1 alone.
    #[test]
    fn captures_are_reached_from_both_sides_on_every_joint() {
        let m = model();
        let from = [0.0, 0.0, 10.0, 0.0, 0.0, 0.0];
        let q = [5.0, 5.0, 0.0, -3.0, 0.0, 7.0];
        let first = m.first_capture_path(&from, &q);
        let second = m.second_capture_path(&q);
        assert_eq!(first[0], from);
        for k in 0..JOINTS {
            assert!(
                isclose(first[2][k] - first[1][k], 1.0, 0.0, 1e-12),
                "j{}",
                k + 1
            );
            assert!(
                isclose(second[2][k] - second[1][k], -2.0, 0.0, 1e-12),
                "j{}",
                k + 1
            );
            assert!(
                isclose(second[1][k] - second[0][k], 2.0, 0.0, 1e-12),
                "j{}",
                k + 1
            );
        }
        assert_eq!((first[2], second[0], second[2]), (q, q, q));
        let s1 = [-90.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let turned = [90.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let t = m.turn_path(&s1, &turned);
        // Joint 1 alone turns (to 89°), the others stand.
        assert_eq!(t[1], [89.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert_eq!(t[2], [89.0, -1.0, -1.0, -1.0, -1.0, -1.0]);
        assert_eq!(t[3], turned);
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
            park: mount2,
        };
        let t = m.session_time(&path, |_, _| true);
        let j = |k, d| m.joint_move_s(k, d);
        // Every approach move is 1° on every joint (0.2 s on each: the slowest joints'
        // boundary, the others' triangles), every overshoot 2° out and back (joint 1's
        // 0.3 s each way).
        let up = 0.2;
        let over = 2.0 * j(0, 2.0);
        let expect_motion = j(1, 46.0) + up           // mount1 (joint 2 at 45°) to stage 1
            + over                                    // stage 1's second capture
            + j(0, 179.0) + up + up                   // the half turn, then up from below
            + over                                    // the turned pose's second
            + j(0, 180.0)                             // to the flange's mount (joint 1 slowest)
            + j(4, 46.0) + up + over                  // pose 1: joint 5 down 45° and 1° more
            + j(2, 29.0) + up + over                  // pose 2: joint 3 up 29°, then 1°
            + j(4, 45.0); // park at the flange's mount
        assert!(isclose(t.motion_s, expect_motion, 0.0, 1e-9), "{t:?}");
        assert_eq!(t.moves, 2 + 2 + 3 + 2 + 1 + 2 * 4 + 1);
        // Stage 1's four captures and two per pose on the robot.
        let bench = BENCH_HEADINGS as u16;
        assert_eq!(t.captures, 4 + 2 * 2);
        assert!(isclose(t.dwell_s, 8.0 * 3.1, 0.0, 1e-12));
        assert_eq!(t.mountings, 3);
        // The half turn's OK and one after every move that may need one: stage 1's
        // two seconds, pose 1's second, pose 2's both.
        assert_eq!(t.ok_stops, 1 + 5);
        assert!(isclose(
            t.total_s,
            t.motion_s + t.dwell_s + 3.0 * 60.0 + 6.0 * 10.0,
            0.0,
            1e-9
        ));
        // The closing readings on the bench, the robot free: a dwell at each heading,
        // an OK before each after the first; not in the robot time.
        let closing = f64::from(bench) * 3.1 + f64::from(bench - 1) * 10.0;
        assert!(isclose(t.closing_s, closing, 0.0, 1e-12), "{t:?}");
        // Nothing needs an OK but the half turn.
        assert_eq!(m.session_time(&path, |_, _| false).ok_stops, 1);
        assert!(m.validate().is_ok());
        let mut bad = m;
        bad.overshoot_deg = 0.0;
        assert_eq!(bad.validate(), Err(TimeSetting::ApproachDistance));
        bad = m;
        bad.speed_deg_s[5] = f64::NAN;
        assert_eq!(bad.validate(), Err(TimeSetting::Speed { joint: 6 }));
        bad = m;
        bad.window_s = 0.0;
        assert_eq!(bad.validate(), Err(TimeSetting::Duration));
    }

    /// A check is the session without stage 1: its flange part alone, the same moves,
    /// captures and OKs from the flange's mounting on.
    #[test]
    fn check_time_is_the_sessions_flange_part() {
        let m = model();
        let mount2 = [0.0, 0.0, 30.0, 0.0, 45.0, 0.0];
        let poses = [
            [0.0, 0.0, 30.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 60.0, 0.0, 0.0, 0.0],
        ];
        let check = m.check_time(
            &CheckPath {
                mount: mount2,
                poses: &poses,
                park: mount2,
            },
            |_, _| true,
        );
        let j = |k, d| m.joint_move_s(k, d);
        let (up, over) = (0.2, 2.0 * j(0, 2.0));
        let expect_motion = j(4, 46.0) + up + over + j(2, 29.0) + up + over + j(4, 45.0);
        assert!(
            isclose(check.motion_s, expect_motion, 0.0, 1e-9),
            "{check:?}"
        );
        // Two captures a pose; the flange mounting and taking the pendant off; pose
        // 1's second and pose 2's both. The closing readings follow, the robot free.
        let bench = BENCH_HEADINGS as u16;
        assert_eq!((check.captures, check.mountings, check.ok_stops), (4, 2, 3));
        assert!(isclose(
            check.total_s,
            check.motion_s + 4.0 * 3.1 + 2.0 * 60.0 + 3.0 * 10.0,
            0.0,
            1e-9
        ));
        let closing = f64::from(bench) * 3.1 + f64::from(bench - 1) * 10.0;
        assert!(isclose(check.closing_s, closing, 0.0, 1e-12));
    }

    /// Costs between points on a line, visited from 0: the shortest path is sorted.
    #[test]
    /// Poses on a line, the first pose visited again in the middle and the first and
    /// the middle at the end (core's `with_revisits` with 3): costed with its revisits,
    /// the tour is shorter through them than the plain sorted tour, and still visits
    /// every pose once.
    fn a_tour_costed_with_its_revisits_places_them_where_they_cost_least() {
        let x: [f64; 5] = [0.0, 1.0, 2.0, 3.0, 100.0];
        let visits = [0usize, 1, 0, 2, 3, 4, 0, 2];
        let from_start = |i: usize| x[i].abs();
        let cost = |i: usize, j: usize| (x[j] - x[i]).abs();
        let plain = shortest_tour(x.len(), from_start, cost);
        let aware = shortest_tour_visiting(x.len(), &visits, from_start, cost);
        let with_visits = |o: &Tour| tour_cost(o, &visits, &from_start, &cost);
        assert!(
            with_visits(&aware) < with_visits(&plain) - 1.0,
            "{} vs {}",
            with_visits(&aware),
            with_visits(&plain)
        );
        let mut seen = [false; 5];
        for &i in &aware {
            seen[usize::from(i)] = true;
        }
        assert!(seen.iter().all(|s| *s) && aware.len() == 5);
    }

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
        let leg = |a: &[f64; JOINTS], b: &[f64; JOINTS]| m.path_s(&m.first_capture_path(a, b));
        let order = shortest_tour(
            deg.len(),
            |i| leg(&start, &deg[i]),
            |i, j| leg(&deg[i], &deg[j]),
        );
        let tour: std::vec::Vec<[f64; JOINTS]> =
            order.iter().map(|&i| deg[usize::from(i)]).collect();
        let path = |poses| SessionPath {
            mount1: start,
            stage1: start,
            turned: [180.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            mount2: start,
            poses,
            park: start,
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
