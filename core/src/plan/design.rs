//! The experimental design behind the planner: the candidate pool with each pose's
//! rows of the Jacobian, the D/A-optimal scores, the greedy build, the exchange and the
//! travel order.
//!
//! A design's information is `M = Σᵢ JᵢᵀJᵢ + P` over its poses, P the stated priors
//! of the reducer terms and the held offsets ([`crate::stage2::add_held`]). Each pose
//! adds two rows, so adding or removing one changes M by rank two: the criteria of every
//! candidate against a design follow from `M⁻¹` by the determinant lemma and
//! Sherman-Morrison-Woodbury, `O(n²)` a candidate, with `M⁻¹` itself computed afresh
//! (Cholesky) at each step, so that rounding does not accumulate in `f32`.

use super::random::Xorshift64Star;
use super::{Criterion, PlanConfig, MAX_POSES};
use crate::linalg::{spd_inverse, Square};
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::real::Real;
use crate::stage2::transmission::loaded_side;
use crate::stage2::{add_held, Information, Layout, Stage2Model, MAX_PARAMS, ZEROS};

/// The information of a design: JᵀJ (and the priors) over the plan's parameters.
pub(super) type Gram<T> = Square<T, MAX_PARAMS>;

/// One feasible pose of the candidate pool, with its two rows of the Jacobian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate<T> {
    /// θ1..θ6 (rad).
    pub joints_rad: [T; JOINTS],
    /// The x and y readings' rows of J at zero offsets (first n used).
    rows: [[T; MAX_PARAMS]; 2],
}

impl<T: Real> Default for Candidate<T> {
    fn default() -> Self {
        Candidate {
            joints_rad: [T::zero(); JOINTS],
            rows: [[T::zero(); MAX_PARAMS]; 2],
        }
    }
}

impl<T: Real> Candidate<T> {
    /// `m += sign·JᵢᵀJᵢ`.
    fn add_to(&self, m: &mut Gram<T>, sign: T) {
        for row in &self.rows {
            m.add_outer(&row[..m.n], sign);
        }
    }
}

/// What a design's score is computed from: `M⁻¹`, `log det M`, and the zeros' rows of
/// `M⁻¹` (`L·M⁻¹`, [`crate::stage2::ZEROS`] of them).
pub(super) struct Inverse<T: Real> {
    inv: Gram<T>,
    log_det: T,
    l_inv: [[T; MAX_PARAMS]; ZEROS],
    /// `trace(L·M⁻¹·Lᵀ)`: the zeros' summed variance per unit reading noise.
    trace: T,
}

impl<T: Real> Inverse<T> {
    /// Of `m`, `None` if it is not positive definite.
    pub(super) fn of(m: &Gram<T>, l: &[[T; MAX_PARAMS]; ZEROS]) -> Option<Self> {
        let (inv, log_det) = spd_inverse(m)?;
        let n = m.n;
        let mut l_inv = [[T::zero(); MAX_PARAMS]; ZEROS];
        let mut trace = T::zero();
        for (li, lr) in l_inv.iter_mut().zip(l) {
            for (j, v) in li.iter_mut().enumerate().take(n) {
                *v = (0..n).fold(T::zero(), |acc, i| acc + lr[i] * inv.m[i][j]);
            }
            trace += (0..n).fold(T::zero(), |acc, j| acc + li[j] * lr[j]);
        }
        Some(Inverse {
            inv,
            log_det,
            l_inv,
            trace,
        })
    }

    /// The criterion of this design with candidate `c` added (larger is better):
    /// `log det(M + JᵀJ) = log det M + log det S` with `S = I + J·M⁻¹·Jᵀ` (2×2), and
    /// `trace L(M + JᵀJ)⁻¹Lᵀ = trace L·M⁻¹·Lᵀ − trace (L·M⁻¹·Jᵀ)·S⁻¹·(L·M⁻¹·Jᵀ)ᵀ`.
    fn with(&self, c: &Candidate<T>, criterion: Criterion) -> Option<T> {
        let n = self.inv.n;
        // u = M⁻¹·Jᵀ (n × 2).
        let mut u = [[T::zero(); 2]; MAX_PARAMS];
        for (i, ui) in u.iter_mut().enumerate().take(n) {
            for (a, row) in c.rows.iter().enumerate() {
                ui[a] = (0..n).fold(T::zero(), |acc, j| acc + self.inv.m[i][j] * row[j]);
            }
        }
        let mut s = [[T::zero(); 2]; 2];
        for (a, row) in c.rows.iter().enumerate() {
            for (b, sab) in s[a].iter_mut().enumerate() {
                *sab = (0..n).fold(T::zero(), |acc, i| acc + row[i] * u[i][b]);
            }
            s[a][a] += T::one();
        }
        let det = s[0][0] * s[1][1] - s[0][1] * s[1][0];
        if !det.is_finite() || det <= T::zero() {
            return None;
        }
        match criterion {
            Criterion::DOptimal => Some(self.log_det + det.ln()),
            Criterion::AOptimal => {
                let inv_s = [
                    [s[1][1] / det, -s[0][1] / det],
                    [-s[1][0] / det, s[0][0] / det],
                ];
                let mut fall = T::zero();
                for li in &self.l_inv {
                    // L·M⁻¹·Jᵀ for this zero: li·J (1 × 2).
                    let w =
                        [0, 1].map(|a| (0..n).fold(T::zero(), |acc, j| acc + li[j] * c.rows[a][j]));
                    fall += w[0] * (inv_s[0][0] * w[0] + inv_s[0][1] * w[1])
                        + w[1] * (inv_s[1][0] * w[0] + inv_s[1][1] * w[1]);
                }
                let trace = self.trace - fall;
                (trace > T::zero() && trace.is_finite()).then_some(-trace)
            }
        }
    }

    /// The criterion of the design itself.
    pub(super) fn score(&self, criterion: Criterion) -> T {
        match criterion {
            Criterion::DOptimal => self.log_det,
            Criterion::AOptimal => -self.trace,
        }
    }
}

/// `a` better than `b` by more than the rounding of the criterion.
pub(super) fn better<T: Real>(a: Option<T>, b: Option<T>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => {
            a - b > T::lit(100.0) * T::EPSILON * (a.abs().max(b.abs()).max(T::one()))
        }
        (Some(_), None) => true,
        _ => false,
    }
}

/// Largest |reading| of `joints_rad` at zero offsets (rad); `None` if not finite or
/// if the pendant would hang upside down (the `axis` angles cannot tell, but a real
/// sensor's cross-axis terms change sign there, and the low-noise modes are specified
/// near level only).
pub(super) fn reading_extent<T: Real>(
    model: &Stage2Model<T>,
    joints_rad: &[T; JOINTS],
) -> Option<T> {
    let z = model.up_at(joints_rad).z;
    if !z.is_finite() || z <= T::zero() {
        return None;
    }
    let t = model.predict(joints_rad, &[T::zero(); WRIST_JOINTS]);
    t.is_finite().then(|| t.x_rad.abs().max(t.y_rad.abs()))
}

/// A candidate pose: joint 1 where stage 1 had it, joint 2 there too or within its
/// stage-2 range, 3-6 drawn in the limits.
pub(super) fn draw<T: Real>(config: &PlanConfig<T>, rng: &mut Xorshift64Star) -> [T; JOINTS] {
    let mut q = [T::zero(); JOINTS];
    q[..2].copy_from_slice(&config.fixed_joints_rad);
    if let Some((lo, hi)) = config.joint2_range_rad {
        q[1] = rng.uniform(lo, hi);
    }
    for (qk, &limits) in q[2..].iter_mut().zip(&config.limits_rad) {
        let (lo, hi) = one_turn(limits);
        *qk = rng.uniform(lo, hi);
    }
    q
}

/// A joint's range for planning: at most one turn, about the middle of its limits. A
/// wrist joint that turns further (±350° is common) reaches every angle within one
/// turn already, and poses a turn apart would only lengthen the robot's travel.
pub(super) fn one_turn<T: Real>((lo, hi): (T, T)) -> (T, T) {
    let half = T::pi();
    let mid = (lo + hi) * T::lit(0.5);
    ((mid - half).max(lo), (mid + half).min(hi))
}

/// Whether the load on joints 2 and 3 at `q` tells which flank of its play each sits
/// on: unloaded (the approaches average to the middle) or loaded well past friction
/// (gravity's flank), not in between ([`crate::stage2::transmission::loaded_side`]).
/// Always where the model has no masses or does not estimate the lost motion.
fn load_is_clear<T: Real>(model: &Stage2Model<T>, layout: &Layout, q: &[T; JOINTS]) -> bool {
    let wants = |i: u8| layout.slot(crate::stage2::Param::Lash(i)).is_some();
    let Some(m) = model.masses.as_ref().filter(|_| wants(0) || wants(1)) else {
        return true;
    };
    let tau = m.gravity_torques_nm(&model.arm, q);
    let most = m.stretched_torques_nm(&model.arm);
    (0..2u8).filter(|i| wants(*i)).all(|i| {
        let k = usize::from(i) + 1;
        let side = loaded_side(tau[k], most[k]).abs();
        side == T::zero() || side == T::one()
    })
}

/// Whether the flange at `q` stays at or above `min_m` in the base frame.
fn high_enough<T: Real>(model: &Stage2Model<T>, q: &[T; JOINTS], min_m: Option<T>) -> bool {
    let Some(min) = min_m else { return true };
    let (_, flange) = model.arm.frames(q);
    flange.translation_m.z >= min
}

/// Fills the pool with feasible candidates; returns (found, draws).
pub(super) fn draw_pool<T: Real>(
    model: &Stage2Model<T>,
    config: &PlanConfig<T>,
    layout: &Layout,
    pool: &mut [Candidate<T>],
) -> (usize, u32) {
    let limit = config.window_rad - config.margin_rad;
    let mut rng = Xorshift64Star::new(config.seed);
    let (mut found, mut draws) = (0, 0u32);
    while found < config.candidates && draws < config.max_draws {
        draws += 1;
        let q = draw(config, &mut rng);
        if !reading_extent(model, &q).is_some_and(|r| r <= limit)
            || !high_enough(model, &q, config.min_flange_height_m)
            || !load_is_clear(model, layout, &q)
        {
            continue;
        }
        if let Some(slot) = pool.get_mut(found) {
            *slot = Candidate {
                joints_rad: q,
                rows: crate::stage2::rows_at(model, layout, &q),
            };
            found += 1;
        }
    }
    (found, draws)
}

/// The priors and held offsets of `layout`'s extras: what every design starts from.
pub(super) fn prior_information<T: Real>(extras: &crate::stage2::Extras, noise_rad: T) -> Gram<T> {
    let mut info = Information::new(extras.layout().len());
    add_held(&mut info, extras, noise_rad);
    info.gram()
}

/// `base` plus the information of the design's candidates.
pub(super) fn information_of<T: Real>(
    pool: &[Candidate<T>],
    design: &[u16],
    base: &Gram<T>,
) -> Gram<T> {
    let mut m = *base;
    for &i in design {
        if let Some(c) = pool.get(usize::from(i)) {
            c.add_to(&mut m, T::one());
        }
    }
    m
}

/// Greedy D-optimal build of `n` distinct candidates from `base` (with a small ridge
/// until the set has full rank).
pub(super) fn greedy<T: Real>(
    pool: &[Candidate<T>],
    n: usize,
    base: &Gram<T>,
    zeros: &[[T; MAX_PARAMS]; ZEROS],
) -> heapless::Vec<u16, MAX_POSES> {
    let mut design: heapless::Vec<u16, MAX_POSES> = heapless::Vec::new();
    // The ridge makes log det defined while the set has rank < n; per-pose information
    // is O(1) (a reading moves about one radian per radian of joint), so 1e-4 only
    // breaks ties among the first picks.
    let mut m = *base;
    for i in 0..m.n {
        m.m[i][i] += T::lit(1e-4);
    }
    while design.len() < n {
        let Some(inverse) = Inverse::of(&m, zeros) else {
            break;
        };
        let Some((c, _)) = best_addition(pool, &design, &inverse, Criterion::DOptimal, None) else {
            break;
        };
        if let Some(cand) = pool.get(usize::from(c)) {
            cand.add_to(&mut m, T::one());
        }
        if design.push(c).is_err() {
            break;
        }
    }
    design
}

/// Among the pool candidates not in `design`, the one whose information added to the
/// design of `inverse` scores best under `criterion`; given a `bar`, only one that
/// beats it.
fn best_addition<T: Real>(
    pool: &[Candidate<T>],
    design: &[u16],
    inverse: &Inverse<T>,
    criterion: Criterion,
    bar: Option<Option<T>>,
) -> Option<(u16, Option<T>)> {
    let mut best: Option<(u16, Option<T>)> = None;
    for (c, cand) in pool.iter().enumerate() {
        let c = c as u16;
        if design.contains(&c) {
            continue;
        }
        let s = inverse.with(cand, criterion);
        let to_beat = best.map(|(_, bs)| bs).or(bar);
        if to_beat.is_none_or(|b| better(s, b)) {
            best = Some((c, s));
        }
    }
    best
}

/// Fedorov-style exchange: swaps design points for pool candidates while the
/// criterion improves. Returns the swaps made.
pub(super) fn exchange<T: Real>(
    pool: &[Candidate<T>],
    design: &mut [u16],
    criterion: Criterion,
    max_passes: u32,
    base: &Gram<T>,
    zeros: &[[T; MAX_PARAMS]; ZEROS],
) -> u32 {
    let mut swaps = 0;
    let mut m = information_of(pool, design, base);
    let mut current = Inverse::of(&m, zeros).map(|i| i.score(criterion));
    for _ in 0..max_passes {
        let mut improved = false;
        for i in 0..design.len() {
            let Some(out) = pool.get(usize::from(design[i])) else {
                continue;
            };
            let mut without = m;
            out.add_to(&mut without, -T::one());
            let Some(inverse) = Inverse::of(&without, zeros) else {
                continue;
            };
            if let Some((c, _)) = best_addition(pool, design, &inverse, criterion, Some(current)) {
                design[i] = c;
                // Recomputed, not updated, so rounding does not accumulate in f32.
                m = information_of(pool, design, base);
                current = Inverse::of(&m, zeros).map(|i| i.score(criterion));
                swaps += 1;
                improved = true;
            }
        }
        if !improved {
            break;
        }
    }
    swaps
}

/// The planner's measure of travel between two poses: their largest joint move (rad).
/// A joint move's time grows with its angle and the joints move together, so the
/// largest move stands for the move's time without the robot's speeds.
pub(super) fn joint_distance<T: Real>(a: &[T; JOINTS], b: &[T; JOINTS]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |m, (x, y)| m.max((*x - *y).abs()))
}

/// Orders the plan for short robot travel: start at the pose nearest the stage-1 pose
/// (joints 3-6 at zero), then always go to the nearest pose not yet visited
/// ([`joint_distance`]).
pub(super) fn travel_order<T: Real>(poses: &mut [[T; JOINTS]], stage1: &[T; 2]) {
    let dist = joint_distance::<T>;
    let mut here = [T::zero(); JOINTS];
    here[..2].copy_from_slice(stage1);
    for i in 0..poses.len() {
        let mut best = i;
        for j in (i + 1)..poses.len() {
            if dist(&here, &poses[j]) < dist(&here, &poses[best]) {
                best = j;
            }
        }
        poses.swap(i, best);
        here = poses[i];
    }
}
