//! The experimental design behind the planner: the candidate pool with each pose's
//! information, the D/A-optimal scores, the greedy build, the exchange and the travel
//! order.

use super::random::Xorshift64Star;
use super::{Criterion, PlanConfig, MAX_POSES};
use crate::linalg::{inverse_diagonal, log_det, Square};
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::real::Real;
use crate::stage2::{information, Layout, Stage2Model, MAX_PARAMS};

/// Entries of the upper triangle of a symmetric matrix over the planned parameters.
const PACKED: usize = PLANNED_PARAMS * (PLANNED_PARAMS + 1) / 2;

/// The parameters a design is built for: the offsets, the sensor's and joints 2-3's
/// terms and the flange bias (every [`crate::stage2::Param`] before the geometric
/// ones). The geometric candidates are reduced against the design afterwards
/// ([`crate::stage2::geometry::identifiable`]): carrying them in every candidate's
/// packed information would take 2 kB per candidate, more than the pendant's RAM holds
/// for a pool.
pub const PLANNED_PARAMS: usize =
    MAX_PARAMS - crate::stage2::TILT_SLOTS - crate::stage2::WRIST_SAG_JOINTS;

/// The information of a design: JᵀJ over the plan's parameters.
pub(super) type Gram<T> = Square<T, MAX_PARAMS>;

/// One feasible pose of the candidate pool, with its information matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate<T> {
    /// θ1..θ6 (rad).
    pub joints_rad: [T; JOINTS],
    /// Upper triangle of JᵢᵀJᵢ at zero offsets, row by row (first n(n+1)/2 used).
    info: [T; PACKED],
}

impl<T: Real> Default for Candidate<T> {
    fn default() -> Self {
        Candidate {
            joints_rad: [T::zero(); JOINTS],
            info: [T::zero(); PACKED],
        }
    }
}

fn pack<T: Real>(m: &Gram<T>) -> [T; PACKED] {
    let mut out = [T::zero(); PACKED];
    let mut k = 0;
    for i in 0..m.n {
        for j in i..m.n {
            out[k] = m.m[i][j];
            k += 1;
        }
    }
    out
}

/// `m += sign·unpack(p)`.
fn add_packed<T: Real>(m: &mut Gram<T>, p: &[T; PACKED], sign: T) {
    let mut k = 0;
    for i in 0..m.n {
        for j in i..m.n {
            let v = p[k] * sign;
            m.m[i][j] += v;
            if i != j {
                m.m[j][i] += v;
            }
            k += 1;
        }
    }
}

/// The criterion as a score (larger is better), `None` if the matrix is singular.
pub(super) fn score<T: Real>(criterion: Criterion, m: &Gram<T>) -> Option<T> {
    match criterion {
        Criterion::DOptimal => log_det(m).filter(|v| v.is_finite()),
        Criterion::AOptimal => {
            // The sum of the offsets' variances only: the extra terms are nuisance
            // parameters, planned for but not optimised.
            let trace = trace_inverse_of_offsets(m)?;
            Some(-trace).filter(|v| v.is_finite() && trace > T::zero())
        }
    }
}

/// `trace` of the offsets' block of `m⁻¹` (the first four slots).
fn trace_inverse_of_offsets<T: Real>(m: &Gram<T>) -> Option<T> {
    let d = inverse_diagonal(m)?;
    Some(d.iter().take(WRIST_JOINTS).fold(T::zero(), |s, v| s + *v))
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

/// A candidate pose: joints 1 and 2 where the plan holds them, 3-6 drawn in the limits.
pub(super) fn draw<T: Real>(config: &PlanConfig<T>, rng: &mut Xorshift64Star) -> [T; JOINTS] {
    let mut q = [T::zero(); JOINTS];
    q[..2].copy_from_slice(&config.fixed_joints_rad);
    for (qk, &(lo, hi)) in q[2..].iter_mut().zip(&config.limits_rad) {
        *qk = rng.uniform(lo, hi);
    }
    q
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
        if !reading_extent(model, &q).is_some_and(|r| r <= limit) {
            continue;
        }
        let info = information(
            model,
            config.extras.without_geometry(),
            &[q],
            &[T::zero(); WRIST_JOINTS],
        )
        .gram();
        debug_assert_eq!(info.n, layout.len());
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

pub(super) fn information_of<T: Real>(
    pool: &[Candidate<T>],
    design: &[u16],
    layout: &Layout,
) -> Gram<T> {
    let mut m = Gram::zeros(layout.len());
    for &i in design {
        if let Some(c) = pool.get(usize::from(i)) {
            add_packed(&mut m, &c.info, T::one());
        }
    }
    m
}

/// Greedy D-optimal build of `n` distinct candidates.
pub(super) fn greedy<T: Real>(
    pool: &[Candidate<T>],
    n: usize,
    layout: &Layout,
) -> heapless::Vec<u16, MAX_POSES> {
    let mut design: heapless::Vec<u16, MAX_POSES> = heapless::Vec::new();
    // The ridge makes log det defined while the set has rank < n; per-pose information
    // is O(1) (a reading moves about one radian per radian of joint), so 1e-4 only
    // breaks ties among the first picks.
    let mut m = Gram::identity(layout.len());
    for i in 0..m.n {
        m.m[i][i] = T::lit(1e-4);
    }
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
    base: &Gram<T>,
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
    layout: &Layout,
) -> u32 {
    let mut swaps = 0;
    let mut m = information_of(pool, design, layout);
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
                m = information_of(pool, design, layout);
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

/// Orders the plan for short robot travel: start at the pose nearest the stage-1 pose
/// (joints 3-6 at zero), then always go to the nearest pose not yet visited (largest
/// joint move).
pub(super) fn travel_order<T: Real>(poses: &mut [[T; JOINTS]]) {
    let dist = |a: &[T; JOINTS], b: &[T; JOINTS]| {
        a.iter()
            .zip(b)
            .fold(T::zero(), |m, (x, y)| m.max((*x - *y).abs()))
    };
    let mut here = poses.first().copied().unwrap_or([T::zero(); JOINTS]);
    for q in here.iter_mut().skip(2) {
        *q = T::zero();
    }
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
