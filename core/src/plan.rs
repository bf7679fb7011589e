//! Stage-2 pose planning: which θ3..θ6 targets to send the robot to, chosen before it
//! moves, so that the fit reaches the best accuracy the sensor window allows.
//!
//! How widely the joints vary inside the sensor window decides the accuracy
//! (METHOD.md, Reference figures): 30 random poses with the joints within ±30° give
//! ~0.0025° per axis, a planned handful does an order of magnitude better.
//!
//! The planner is an optimal experimental design on the linearised model:
//!
//! 1. **Candidates.** A seeded [`Xorshift64Star`] draws joint targets uniformly inside
//!    the joint limits and keeps those whose predicted readings (at zero offsets, with
//!    the model's base tilt and bias) stay within `window − margin`: the margin leaves
//!    room for the offsets not yet known. Each kept candidate stores its information
//!    `JᵢᵀJᵢ` (4×4, 2 readings).
//! 2. **Greedy build.** Poses are added one at a time, each the candidate that most
//!    increases `log det(JᵀJ)` (D-optimal, with a small ridge until the set has rank 4).
//! 3. **Exchange** (Fedorov-style). Each pose of the design is swapped for the candidate
//!    that most improves the criterion — D-optimal `max log det JᵀJ` or A-optimal
//!    `min trace (JᵀJ)⁻¹`, the sum of the predicted variances — until a pass improves
//!    nothing. A candidate is used at most once: distinct poses keep the plan robust to
//!    a model error at any one of them.
//! 4. **Check.** The plan's covariance bound ([`covariance_bound`]) gives the predicted
//!    1σ per axis; a plan that cannot separate some parameters (e.g. limits that pin
//!    θ4, so that Δθ3 and Δθ5 are one rotation about x) is refused with the parameters
//!    named, before the robot moves.
//!
//! No heap: the candidate pool is a buffer the caller provides (`&mut [Candidate<T>]`,
//! 56 bytes per candidate in `f32`, so 256 candidates are 14 KiB of the pendant's RAM),
//! the plan is a `heapless::Vec` of at most [`MAX_PLAN_POSES`].

use crate::error::{FitError, ParamSet};
use crate::fit::{covariance_bound, Stage2Model, MIN_POSES};
use crate::model::WRIST_JOINTS;
use crate::real::{deg_to_rad, rad_to_deg, Real};
use core::fmt;
use nalgebra::{Cholesky, Matrix4, SymmetricEigen};

/// Most poses a plan holds.
pub const MAX_PLAN_POSES: usize = 64;

/// A candidate pool size that works well: the D/A-optimal 8-pose plan from 256
/// candidates is within a few percent of the one from 4096.
pub const DEFAULT_POOL: usize = 256;

/// Entries of the upper triangle of a symmetric 4×4 matrix.
const PACKED: usize = WRIST_JOINTS * (WRIST_JOINTS + 1) / 2;

/// What "best" means for a pose set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Criterion {
    /// Minimise trace (JᵀJ)⁻¹: the sum of the four predicted variances.
    #[default]
    AOptimal,
    /// Maximise log det JᵀJ: the smallest joint confidence region.
    DOptimal,
}

impl Criterion {
    /// Parses `a` / `a-optimal` or `d` / `d-optimal` (case-insensitive).
    pub fn parse(s: &str) -> Option<Self> {
        let t = s.trim();
        if t.eq_ignore_ascii_case("a") || t.eq_ignore_ascii_case("a-optimal") {
            Some(Criterion::AOptimal)
        } else if t.eq_ignore_ascii_case("d") || t.eq_ignore_ascii_case("d-optimal") {
            Some(Criterion::DOptimal)
        } else {
            None
        }
    }
}

/// Planner settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanConfig<T> {
    /// Poses to plan (`MIN_POSES..=MAX_PLAN_POSES`).
    pub poses: usize,
    /// The sensor window: readings must stay within ±this (rad).
    pub window_rad: T,
    /// Planned readings stay within ±(window − margin) at zero offsets (rad), so that
    /// the still unknown offsets cannot push a reading out of the window.
    pub margin_rad: T,
    /// (low, high) of θ3..θ6 (rad).
    pub limits_rad: [(T, T); WRIST_JOINTS],
    /// Seed of the candidate draw: the same seed gives the same plan.
    pub seed: u64,
    /// Feasible candidates to collect (at most the pool buffer's length).
    pub candidates: usize,
    /// Per-reading noise 1σ (rad), for the predicted 1σ.
    pub noise_sigma_rad: T,
    /// What to optimise.
    pub criterion: Criterion,
    /// Random draws before giving up on filling the pool.
    pub max_draws: u32,
    /// Exchange passes at most (each tries every candidate at every pose).
    pub max_exchange_passes: u32,
    /// Plans whose Jacobian is worse conditioned than this are refused: keep it equal
    /// to the fit's `FitConfig::max_condition_number`, or the fit refuses the plan.
    pub max_condition_number: T,
}

impl<T: Real> Default for PlanConfig<T> {
    /// 8 poses, the paper's ±10° window with a 1° margin, joints anywhere in ±180°,
    /// Table-4 noise (uniform ±0.002°, σ = 0.002°/√3), A-optimal, 256 candidates.
    fn default() -> Self {
        let full = deg_to_rad(T::lit(180.0));
        PlanConfig {
            poses: 8,
            window_rad: deg_to_rad(T::lit(10.0)),
            margin_rad: deg_to_rad(T::lit(1.0)),
            limits_rad: [(-full, full); WRIST_JOINTS],
            seed: 1,
            candidates: DEFAULT_POOL,
            noise_sigma_rad: deg_to_rad(T::lit(0.002 / 1.732_050_807_568_877_2)),
            criterion: Criterion::AOptimal,
            // ±180° joints in a 9° window accept about 1 draw in 160: 256 candidates
            // take ~40,000 draws; this cap only stops an impossible request.
            max_draws: 2_000_000,
            max_exchange_passes: 20,
            max_condition_number: T::lit(1000.0),
        }
    }
}

/// One feasible pose of the candidate pool, with its information matrix.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Candidate<T> {
    /// θ3..θ6 (rad).
    pub joints_rad: [T; WRIST_JOINTS],
    /// Upper triangle of JᵢᵀJᵢ at zero offsets, row by row.
    info: [T; PACKED],
}

/// A plan: the poses and what they promise.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan<T> {
    /// θ3..θ6 targets (rad), in a short travel order (nearest neighbour from the pose
    /// closest to all-zero joints).
    pub poses_rad: heapless::Vec<[T; WRIST_JOINTS], MAX_PLAN_POSES>,
    /// Predicted 1σ of Δθ3..Δθ6 (rad): the covariance bound at zero offsets.
    pub predicted_sigma_rad: [T; WRIST_JOINTS],
    /// Condition number of the plan's Jacobian.
    pub condition_number: T,
    /// log det JᵀJ of the plan.
    pub log_det: T,
    /// Largest |reading| of the plan at zero offsets (rad).
    pub max_reading_rad: T,
    /// Random draws spent on the pool.
    pub draws: u32,
    /// Feasible candidates in the pool.
    pub candidates: usize,
    /// Swaps the exchange made.
    pub exchanges: u32,
}

/// Which setting is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanSetting {
    /// `window_rad`.
    Window,
    /// `margin_rad`.
    Margin,
    /// `limits_rad` of a joint (3..=6).
    Limits {
        /// Robot joint number.
        joint: u8,
    },
    /// `noise_sigma_rad`.
    NoiseSigma,
    /// `candidates`.
    Candidates,
    /// `max_condition_number`.
    MaxConditionNumber,
}

impl fmt::Display for PlanSetting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PlanSetting::Window => f.write_str("window: must be a positive finite angle"),
            PlanSetting::Margin => {
                f.write_str("margin: must be finite, >= 0 and smaller than the window")
            }
            PlanSetting::Limits { joint } => {
                write!(f, "limits of joint {joint}: must be finite with min <= max")
            }
            PlanSetting::NoiseSigma => f.write_str("noise: must be a positive finite angle"),
            PlanSetting::Candidates => {
                f.write_str("candidates: must be at least the number of poses")
            }
            PlanSetting::MaxConditionNumber => {
                f.write_str("max condition number: must be finite and > 1")
            }
        }
    }
}

/// Why there is no plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlanError {
    /// A setting is out of its domain.
    InvalidSetting(PlanSetting),
    /// Fewer poses asked for than the fit needs.
    TooFewPoses {
        /// Asked for.
        got: usize,
        /// Needed.
        min: usize,
    },
    /// More poses asked for than a plan holds.
    TooManyPoses {
        /// Asked for.
        got: usize,
        /// Most a plan holds.
        max: usize,
    },
    /// The pool buffer is smaller than the candidates asked for.
    PoolTooSmall {
        /// Buffer length.
        pool: usize,
        /// Candidates asked for.
        needed: usize,
    },
    /// Too few poses inside the limits keep the readings inside the window.
    WindowUnreachable {
        /// Draws tried.
        draws: u32,
        /// Feasible candidates found.
        found: usize,
    },
    /// The best plan inside these limits cannot separate some parameters: the fit
    /// would refuse it ([`FitError::RankDeficient`] or [`FitError::IllConditioned`],
    /// naming them).
    Unobservable(FitError),
}

impl fmt::Display for PlanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PlanError::InvalidSetting(s) => write!(f, "invalid plan setting: {s}"),
            PlanError::TooFewPoses { got, min } => {
                write!(f, "too few poses: {got} asked for, the fit needs at least {min}")
            }
            PlanError::TooManyPoses { got, max } => {
                write!(f, "too many poses: {got} asked for, a plan holds at most {max}")
            }
            PlanError::PoolTooSmall { pool, needed } => write!(
                f,
                "candidate pool buffer holds {pool}, {needed} candidates asked for"
            ),
            PlanError::WindowUnreachable { draws, found } => write!(
                f,
                "only {found} of {draws} random poses inside the joint limits keep the readings inside the window: widen the limits or the window"
            ),
            PlanError::Unobservable(e) => write!(f, "plan refused: {e}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for PlanError {}

/// A small deterministic PRNG (xorshift64*, seeded through SplitMix64): the same seed
/// gives the same plan on the pendant and on the desktop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Xorshift64Star {
    state: u64,
}

impl Xorshift64Star {
    /// A generator from any seed (0 included).
    pub fn new(seed: u64) -> Self {
        // SplitMix64 spreads nearby seeds apart and never yields the all-zero state
        // that would stall xorshift, except for one input mapped to a fixed constant.
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        Xorshift64Star {
            state: if z == 0 { 0x2545_F491_4F6C_DD1D } else { z },
        }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.state;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.state = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub fn unit_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi] (`lo` when the interval is empty).
    pub fn uniform<T: Real>(&mut self, lo: T, hi: T) -> T {
        let u = T::lit(self.unit_f64());
        if hi > lo {
            lo + (hi - lo) * u
        } else {
            lo
        }
    }
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
fn score<T: Real>(criterion: Criterion, m: &Matrix4<T>) -> Option<T> {
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
fn better<T: Real>(a: Option<T>, b: Option<T>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => {
            a - b > T::lit(100.0) * T::EPSILON * (a.abs().max(b.abs()).max(T::one()))
        }
        (Some(_), None) => true,
        _ => false,
    }
}

fn validate<T: Real>(config: &PlanConfig<T>, pool_len: usize) -> Result<(), PlanError> {
    let bad = |s| Err(PlanError::InvalidSetting(s));
    if config.poses < MIN_POSES {
        return Err(PlanError::TooFewPoses {
            got: config.poses,
            min: MIN_POSES,
        });
    }
    if config.poses > MAX_PLAN_POSES {
        return Err(PlanError::TooManyPoses {
            got: config.poses,
            max: MAX_PLAN_POSES,
        });
    }
    if !(config.window_rad.is_finite() && config.window_rad > T::zero()) {
        return bad(PlanSetting::Window);
    }
    let m = config.margin_rad;
    if !(m.is_finite() && m >= T::zero() && m < config.window_rad) {
        return bad(PlanSetting::Margin);
    }
    for (k, &(lo, hi)) in config.limits_rad.iter().enumerate() {
        if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
            return bad(PlanSetting::Limits { joint: k as u8 + 3 });
        }
    }
    if !(config.noise_sigma_rad.is_finite() && config.noise_sigma_rad > T::zero()) {
        return bad(PlanSetting::NoiseSigma);
    }
    let c = config.max_condition_number;
    if !(c.is_finite() && c > T::one()) {
        return bad(PlanSetting::MaxConditionNumber);
    }
    if config.candidates < config.poses || config.candidates > usize::from(u16::MAX) {
        return bad(PlanSetting::Candidates);
    }
    if pool_len < config.candidates {
        return Err(PlanError::PoolTooSmall {
            pool: pool_len,
            needed: config.candidates,
        });
    }
    Ok(())
}

/// Largest |reading| of `joints_rad` at zero offsets (rad); `None` if not finite.
fn reading_extent<T: Real>(model: &Stage2Model<T>, joints_rad: &[T; WRIST_JOINTS]) -> Option<T> {
    let t = model.predict(joints_rad, &[T::zero(); WRIST_JOINTS]);
    t.is_finite().then(|| t.x_rad.abs().max(t.y_rad.abs()))
}

/// Fills the pool with feasible candidates; returns (found, draws).
fn draw_pool<T: Real>(
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

fn information_of<T: Real>(pool: &[Candidate<T>], design: &[u16]) -> Matrix4<T> {
    let mut m = Matrix4::zeros();
    for &i in design {
        if let Some(c) = pool.get(usize::from(i)) {
            add_packed(&mut m, &c.info, T::one());
        }
    }
    m
}

/// Greedy D-optimal build of `n` distinct candidates.
fn greedy<T: Real>(pool: &[Candidate<T>], n: usize) -> heapless::Vec<u16, MAX_PLAN_POSES> {
    let mut design: heapless::Vec<u16, MAX_PLAN_POSES> = heapless::Vec::new();
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
fn exchange<T: Real>(
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
fn travel_order<T: Real>(poses: &mut [[T; WRIST_JOINTS]]) {
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

/// The parameters along the weakest direction of JᵀJ (components above 0.3).
fn weakest_params<T: Real>(m: &Matrix4<T>) -> ParamSet {
    let mut set = ParamSet::default();
    if let Some(eig) = SymmetricEigen::try_new(*m, T::EPSILON, 1000) {
        let mut imin = 0;
        for k in 1..WRIST_JOINTS {
            if eig.eigenvalues[k] < eig.eigenvalues[imin] {
                imin = k;
            }
        }
        for k in 0..WRIST_JOINTS {
            if eig.eigenvectors[(k, imin)].abs() > T::lit(0.3) {
                set = set.with(k);
            }
        }
    }
    set
}

/// Plans `config.poses` stage-2 poses for `model` (its chain, the base tilt from
/// stage 1, the sensor's convention and bias).
///
/// `pool` is scratch space for the candidates; it must hold `config.candidates`.
///
/// # Errors
/// An invalid setting (naming it); too few or too many poses; a pool buffer too small;
/// a window that too few poses inside the limits reach; a plan that cannot separate
/// some parameters ([`PlanError::Unobservable`], naming them).
pub fn plan<T: Real>(
    model: &Stage2Model<T>,
    config: &PlanConfig<T>,
    pool: &mut [Candidate<T>],
) -> Result<Plan<T>, PlanError> {
    validate(config, pool.len())?;
    let (found, draws) = draw_pool(model, config, pool);
    // Fewer candidates than asked for is fine as long as the exchange has a choice.
    if found < config.poses.max(MIN_POSES) * 2 && found < config.candidates {
        return Err(PlanError::WindowUnreachable { draws, found });
    }
    let pool = &pool[..found];
    let mut design = greedy(pool, config.poses);
    let exchanges = exchange(
        pool,
        &mut design,
        config.criterion,
        config.max_exchange_passes,
    );

    let mut poses_rad: heapless::Vec<[T; WRIST_JOINTS], MAX_PLAN_POSES> = heapless::Vec::new();
    for &i in &design {
        if let Some(c) = pool.get(usize::from(i)) {
            // The design never exceeds MAX_PLAN_POSES (validated), so this cannot fail.
            let _ = poses_rad.push(c.joints_rad);
        }
    }
    travel_order(&mut poses_rad);

    let zero = [T::zero(); WRIST_JOINTS];
    let bound = covariance_bound(model, poses_rad.iter(), &zero, config.noise_sigma_rad)
        .map_err(PlanError::Unobservable)?;
    let m = information_of(pool, &design);
    if bound.condition_number > config.max_condition_number {
        return Err(PlanError::Unobservable(FitError::IllConditioned {
            condition_number: bound.condition_number.to_f64() as f32,
            limit: config.max_condition_number.to_f64() as f32,
            params: weakest_params(&m),
        }));
    }
    let log_det = score(Criterion::DOptimal, &m).unwrap_or(T::zero());
    let max_reading_rad = poses_rad.iter().fold(T::zero(), |a, q| {
        a.max(reading_extent(model, q).unwrap_or(a))
    });
    Ok(Plan {
        poses_rad,
        predicted_sigma_rad: bound.sigma_rad,
        condition_number: bound.condition_number,
        log_det,
        max_reading_rad,
        draws,
        candidates: found,
        exchanges,
    })
}

/// Converts per-joint (min, max) limits in degrees to radians.
pub fn limits_from_deg<T: Real>(limits_deg: [(T, T); WRIST_JOINTS]) -> [(T, T); WRIST_JOINTS] {
    limits_deg.map(|(lo, hi)| (deg_to_rad(lo), deg_to_rad(hi)))
}

impl<T: Real> Plan<T> {
    /// Predicted 1σ per axis (deg).
    pub fn predicted_sigma_deg(&self) -> [T; WRIST_JOINTS] {
        self.predicted_sigma_rad.map(rad_to_deg)
    }
}

/// Poses in the pendant's default plan: three times the fit's minimum, a few minutes of
/// jogging (`zerocal plan --poses 12` prints the 1σ it predicts).
pub const PENDANT_PLAN_POSES: usize = 12;

/// The plan the pendant uses when none was uploaded: this planner with its default
/// settings on the pendant's wrist and convention, a level base and no bias (the real
/// ones are not known before stages 0-1; the planner's 1° margin inside the ±10°
/// window absorbs them), and the fit's own conditioning limit.
///
/// Seeded, so the same every time: the firmware computes it when it is built.
///
/// # Errors
/// As [`plan`].
pub fn pendant_default<T: Real>(
    config: &crate::procedure::ProcedureConfig<T>,
    pool: &mut [Candidate<T>],
) -> Result<crate::procedure::Plan<T>, PlanError> {
    let model = Stage2Model {
        chain: config.chain,
        base_tilt: crate::model::BaseTilt::level(),
        sensor: crate::model::SensorModel {
            convention: config.convention,
            bias: crate::model::Tilt::default(),
        },
    };
    let plan_config = PlanConfig {
        poses: PENDANT_PLAN_POSES,
        max_condition_number: config.fit.max_condition_number,
        ..PlanConfig::default()
    };
    let planned = plan(&model, &plan_config, pool)?;
    let mut poses = crate::procedure::Plan::new();
    for q in &planned.poses_rad {
        // Both hold 64 poses (MAX_PLAN_POSES = MAX_POSES).
        let _ = poses.push(*q);
    }
    Ok(poses)
}

#[cfg(test)]
// A failed test panics with the error it got: that is the report.
#[allow(clippy::panic)]
mod tests {
    use super::*;
    use crate::model::{BaseTilt, SensorModel, Tilt, WristChain};

    fn pool64() -> std::vec::Vec<Candidate<f64>> {
        std::vec![Candidate::default(); DEFAULT_POOL]
    }

    #[test]
    fn prng_is_deterministic_and_uniform() {
        let mut a = Xorshift64Star::new(7);
        let mut b = Xorshift64Star::new(7);
        let mut c = Xorshift64Star::new(8);
        let (mut sum, n) = (0.0, 10_000);
        for _ in 0..n {
            let x = a.unit_f64();
            assert_eq!(x, b.unit_f64());
            assert!((0.0..1.0).contains(&x));
            sum += x;
        }
        assert_ne!(a.next_u64(), c.next_u64());
        // Mean of 10,000 U(0,1): σ = 1/√(12·10⁴) ≈ 0.0029; 0.015 is 5σ.
        assert!((sum / n as f64 - 0.5).abs() < 0.015);
        // Seed 0 does not stall.
        let mut z = Xorshift64Star::new(0);
        assert_ne!(z.next_u64(), z.next_u64());
    }

    #[test]
    fn default_plan_is_feasible_and_accurate() {
        let model = Stage2Model::<f64>::default();
        let config = PlanConfig::default();
        let p = plan(&model, &config, &mut pool64()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(p.poses_rad.len(), 8);
        let limit = config.window_rad - config.margin_rad;
        for q in &p.poses_rad {
            let t = model.predict(q, &[0.0; 4]);
            assert!(t.x_rad.abs() <= limit && t.y_rad.abs() <= limit, "{t:?}");
            for (qk, (lo, hi)) in q.iter().zip(config.limits_rad) {
                assert!((lo..=hi).contains(qk));
            }
        }
        let s = p.predicted_sigma_deg();
        // METHOD.md: 30 random poses in ±30° give 0.0025°; the brief asks 8 planned
        // ones to be at least 5× better, 0.0005°.
        assert!(s.iter().all(|&x| x > 0.0 && x < 0.0005), "{s:?}");
        // Joints free over a full turn: the design is near orthogonal (JᵀJ ∝ I).
        assert!(p.condition_number < 1.5, "{}", p.condition_number);
    }

    #[test]
    fn exchange_never_worsens_the_greedy_design() {
        let model = Stage2Model::<f64>::default();
        let config = PlanConfig::default();
        let mut pool = pool64();
        let (found, _) = draw_pool(&model, &config, &mut pool);
        let pool = &pool[..found];
        for criterion in [Criterion::AOptimal, Criterion::DOptimal] {
            let mut design = greedy(pool, 8);
            let before = score(criterion, &information_of(pool, &design));
            exchange(pool, &mut design, criterion, 20);
            let after = score(criterion, &information_of(pool, &design));
            assert!(
                !better(before, after),
                "{criterion:?}: {before:?} -> {after:?}"
            );
            let mut sorted = design.clone();
            sorted.sort_unstable();
            assert!(sorted.windows(2).all(|w| w[0] != w[1]), "distinct poses");
        }
    }

    #[test]
    fn same_seed_same_plan_other_seed_other_plan() {
        let model = Stage2Model::<f64>::default();
        let config = PlanConfig::default();
        let a = plan(&model, &config, &mut pool64());
        let b = plan(&model, &config, &mut pool64());
        assert_eq!(a, b);
        let c = plan(&model, &PlanConfig { seed: 2, ..config }, &mut pool64());
        assert_ne!(a.map(|p| p.poses_rad), c.map(|p| p.poses_rad));
    }

    #[test]
    fn pinned_joint_4_is_refused_naming_j3_and_j5() {
        // θ4 ≡ 0: Rx(θ3)·Rx(θ5) is one rotation, Δθ3 and Δθ5 cannot be told apart.
        let model = Stage2Model::<f64>::default();
        let mut config = PlanConfig::default();
        config.limits_rad[1] = (0.0, 0.0);
        let r = plan(&model, &config, &mut pool64());
        match r {
            Err(PlanError::Unobservable(FitError::RankDeficient { params })) => {
                assert_eq!(params, ParamSet::default().with(0).with(2), "{params}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn nearly_pinned_joint_4_is_ill_conditioned() {
        // θ4 within ±0.05°: separable in principle, not in practice.
        let model = Stage2Model::<f64>::default();
        let mut config = PlanConfig::default();
        config.limits_rad[1] = (-deg_to_rad(0.05), deg_to_rad(0.05));
        match plan(&model, &config, &mut pool64()) {
            Err(PlanError::Unobservable(FitError::IllConditioned { params, .. })) => {
                assert!(params.contains(0) && params.contains(2), "{params}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn bad_settings_are_named() {
        let model = Stage2Model::<f64>::default();
        let base = PlanConfig::<f64>::default();
        let cases: [(PlanConfig<f64>, PlanError); 6] = [
            (
                PlanConfig { poses: 3, ..base },
                PlanError::TooFewPoses { got: 3, min: 4 },
            ),
            (
                PlanConfig { poses: 65, ..base },
                PlanError::TooManyPoses { got: 65, max: 64 },
            ),
            (
                PlanConfig {
                    margin_rad: base.window_rad,
                    ..base
                },
                PlanError::InvalidSetting(PlanSetting::Margin),
            ),
            (
                PlanConfig {
                    window_rad: f64::NAN,
                    ..base
                },
                PlanError::InvalidSetting(PlanSetting::Window),
            ),
            (
                PlanConfig {
                    limits_rad: [(0.0, 0.1), (0.0, 0.1), (0.2, 0.1), (0.0, 0.1)],
                    ..base
                },
                PlanError::InvalidSetting(PlanSetting::Limits { joint: 5 }),
            ),
            (
                PlanConfig {
                    candidates: 300,
                    ..base
                },
                PlanError::PoolTooSmall {
                    pool: 256,
                    needed: 300,
                },
            ),
        ];
        for (config, expected) in cases {
            assert_eq!(plan(&model, &config, &mut pool64()), Err(expected));
        }
        let msg = std::format!(
            "{}",
            PlanError::InvalidSetting(PlanSetting::Limits { joint: 5 })
        );
        assert!(msg.contains("joint 5"), "{msg}");
    }

    #[test]
    fn unreachable_window_is_reported() {
        // θ3 in [40°, 50°] with the other joints near 0 reads x ≈ 45°: never in ±9°.
        let model = Stage2Model::<f64>::default();
        let config = PlanConfig {
            limits_rad: limits_from_deg([(40.0, 50.0), (-5.0, 5.0), (-5.0, 5.0), (-5.0, 5.0)]),
            max_draws: 5_000,
            ..PlanConfig::default()
        };
        assert!(matches!(
            plan(&model, &config, &mut pool64()),
            Err(PlanError::WindowUnreachable {
                found: 0,
                draws: 5_000
            })
        ));
    }

    #[test]
    fn plans_for_a_tilted_base_and_biased_sensor_stay_in_the_window() {
        let model = Stage2Model {
            chain: WristChain::paper(),
            base_tilt: BaseTilt::from_deg(0.5, -0.4),
            sensor: SensorModel {
                convention: crate::model::Convention::Axis,
                bias: Tilt::from_deg(0.05, -0.03),
            },
        };
        let config = PlanConfig::default();
        let p = plan(&model, &config, &mut pool64()).unwrap_or_else(|e| panic!("{e}"));
        assert!(p.max_reading_rad <= config.window_rad - config.margin_rad);
    }

    #[test]
    fn f32_plan_on_the_pendant_matches_f64_quality() {
        let model = Stage2Model::<f32>::default();
        let config = PlanConfig::<f32>::default();
        let mut pool = std::vec![Candidate::<f32>::default(); DEFAULT_POOL];
        let p = plan(&model, &config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        let p64 = plan(
            &Stage2Model::default(),
            &PlanConfig::default(),
            &mut pool64(),
        )
        .unwrap_or_else(|e| panic!("{e}"));
        // Same seed, same candidates up to f32 rounding; the exchange may settle on a
        // slightly different set, so compare quality, not poses: within 20 %.
        for k in 0..4 {
            let r = f64::from(p.predicted_sigma_rad[k]) / p64.predicted_sigma_rad[k];
            assert!((0.8..1.25).contains(&r), "j{}: {r}", k + 3);
        }
    }
}
