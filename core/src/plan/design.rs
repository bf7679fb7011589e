//! The experimental design behind the planner: the candidate pool with each pose's
//! information, the D/A-optimal scores, the greedy build, the exchange and the travel
//! order.

use super::random::Xorshift64Star;
use super::{Criterion, PlanConfig, MAX_POSES};
use crate::model::WRIST_JOINTS;
use crate::real::Real;
use crate::stage2::Stage2Model;
use nalgebra::{Cholesky, Matrix4};

/// Entries of the upper triangle of a symmetric 4×4 matrix.
const PACKED: usize = WRIST_JOINTS * (WRIST_JOINTS + 1) / 2;

/// One feasible pose of the candidate pool, with its information matrix.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Candidate<T> {
    /// θ3..θ6 (rad).
    pub joints_rad: [T; WRIST_JOINTS],
    /// Upper triangle of JᵢᵀJᵢ at zero offsets, row by row.
    info: [T; PACKED],
}

fn pack<T: Real>(m: &Matrix4<T>) -> [T; PACKED] {
    let mut out = [T::zero(); PACKED];
    let mut n = 0;
    for i in 0..WRIST_JOINTS {
        for j in i..WRIST_JOINTS {
            out[n] = m[(i, j)];
            n += 1;
        }
    }
    out
}

/// `m += sign·unpack(p)`.
fn add_packed<T: Real>(m: &mut Matrix4<T>, p: &[T; PACKED], sign: T) {
    let mut n = 0;
    for i in 0..WRIST_JOINTS {
        for j in i..WRIST_JOINTS {
            let v = p[n] * sign;
            m[(i, j)] += v;
            if i != j {
                m[(j, i)] += v;
            }
            n += 1;
        }
    }
}

/// The criterion as a score (larger is better), `None` if the matrix is singular.
pub(super) fn score<T: Real>(criterion: Criterion, m: &Matrix4<T>) -> Option<T> {
    let chol = Cholesky::new(*m)?;
    let l = chol.l_dirty();
    match criterion {
        Criterion::DOptimal => {
            let mut log_det = T::zero();
            for k in 0..WRIST_JOINTS {
                log_det += l[(k, k)].ln();
            }
            let two = T::one() + T::one();
            Some(two * log_det).filter(|v| v.is_finite())
        }
        Criterion::AOptimal => {
            let trace = chol.inverse().trace();
            Some(-trace).filter(|v| v.is_finite() && trace > T::zero())
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

/// Largest |reading| of `joints_rad` at zero offsets (rad); `None` if not finite.
pub(super) fn reading_extent<T: Real>(
    model: &Stage2Model<T>,
    joints_rad: &[T; WRIST_JOINTS],
) -> Option<T> {
    let t = model.predict(joints_rad, &[T::zero(); WRIST_JOINTS]);
    t.is_finite().then(|| t.x_rad.abs().max(t.y_rad.abs()))
}

/// Fills the pool with feasible candidates; returns (found, draws).
pub(super) fn draw_pool<T: Real>(
    model: &Stage2Model<T>,
    config: &PlanConfig<T>,
    pool: &mut [Candidate<T>],
) -> (usize, u32) {
    let zero = [T::zero(); WRIST_JOINTS];
    let limit = config.window_rad - config.margin_rad;
    let mut rng = Xorshift64Star::new(config.seed);
    let (mut found, mut draws) = (0, 0u32);
    while found < config.candidates && draws < config.max_draws {
        draws += 1;
        let mut q = [T::zero(); WRIST_JOINTS];
        for (qk, &(lo, hi)) in q.iter_mut().zip(&config.limits_rad) {
            *qk = rng.uniform(lo, hi);
        }
        if !reading_extent(model, &q).is_some_and(|r| r <= limit) {
            continue;
        }
        let info = model.information(core::iter::once(&q), &zero).matrix();
        if let Some(slot) = pool.get_mut(found) {
            *slot = Candidate {
                joints_rad: q,
                info: pack(&info),
            };
            found += 1;
        }
    }
    (found, draws)
}

pub(super) fn information_of<T: Real>(pool: &[Candidate<T>], design: &[u16]) -> Matrix4<T> {
    let mut m = Matrix4::zeros();
    for &i in design {
        if let Some(c) = pool.get(usize::from(i)) {
            add_packed(&mut m, &c.info, T::one());
        }
    }
    m
}

/// Greedy D-optimal build of `n` distinct candidates.
pub(super) fn greedy<T: Real>(pool: &[Candidate<T>], n: usize) -> heapless::Vec<u16, MAX_POSES> {
    let mut design: heapless::Vec<u16, MAX_POSES> = heapless::Vec::new();
    // The ridge makes log det defined while the set has rank < 4; per-pose information
    // is O(1) (a reading moves about one radian per radian of joint), so 1e-4 only
    // breaks ties among the first picks.
    let mut m = Matrix4::identity() * T::lit(1e-4);
    while design.len() < n {
        let Some((c, _)) = best_addition(pool, &design, &m, Criterion::DOptimal, None) else {
            break;
        };
        if let Some(cand) = pool.get(usize::from(c)) {
            add_packed(&mut m, &cand.info, T::one());
        }
        if design.push(c).is_err() {
            break;
        }
    }
    design
}

/// Among the pool candidates not in `design`, the one whose information added to
/// `base` scores best under `criterion`; given a `bar`, only one that beats it.
fn best_addition<T: Real>(
    pool: &[Candidate<T>],
    design: &[u16],
    base: &Matrix4<T>,
    criterion: Criterion,
    bar: Option<Option<T>>,
) -> Option<(u16, Option<T>)> {
    let mut best: Option<(u16, Option<T>)> = None;
    for (c, cand) in pool.iter().enumerate() {
        let c = c as u16;
        if design.contains(&c) {
            continue;
        }
        let mut trial = *base;
        add_packed(&mut trial, &cand.info, T::one());
        let s = score(criterion, &trial);
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
) -> u32 {
    let mut swaps = 0;
    let mut m = information_of(pool, design);
    let mut current = score(criterion, &m);
    for _ in 0..max_passes {
        let mut improved = false;
        for i in 0..design.len() {
            let Some(out) = pool.get(usize::from(design[i])) else {
                continue;
            };
            let mut without = m;
            add_packed(&mut without, &out.info, -T::one());
            if let Some((c, _)) = best_addition(pool, design, &without, criterion, Some(current)) {
                design[i] = c;
                // Recomputed, not updated, so rounding does not accumulate in f32.
                m = information_of(pool, design);
                current = score(criterion, &m);
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

/// Orders the plan for short robot travel: start at the pose nearest all-zero joints,
/// then always go to the nearest pose not yet visited (largest joint move).
pub(super) fn travel_order<T: Real>(poses: &mut [[T; WRIST_JOINTS]]) {
    let dist = |a: &[T; WRIST_JOINTS], b: &[T; WRIST_JOINTS]| {
        a.iter()
            .zip(b)
            .fold(T::zero(), |m, (x, y)| m.max((*x - *y).abs()))
    };
    let mut here = [T::zero(); WRIST_JOINTS];
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
