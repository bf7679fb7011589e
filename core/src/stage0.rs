//! Stage 0: the sensor's zero error, from readings on a bench at several headings.
//!
//! The pendant is read on any stable surface, turned about the vertical on the same
//! spot, and read again, at two or more headings. The surface's tilt `t` is a fixed
//! vector in the bench's frame; the pendant at heading ψ sees it turned by −ψ, so the
//! readings (bias-free) draw a circle of radius |t| about the sensor's bias
//! ([`BenchTurns::bias`]):
//!
//! - **Three or more headings, turned by hand**: the bias is the circle's centre, the
//!   headings come out of the readings themselves (Gauss-Newton on the exact model,
//!   from a circle fit through them), so how far the pendant was turned costs nothing
//!   on any bench tilt. With more than three the fit has residuals to show that the
//!   pendant was turned on the spot and not moved.
//! - **Two headings, half a turn apart (a reversal)**: the half turn negates both
//!   bias-free angles in either convention (u_x, u_y change sign, u_z does not), so the
//!   half-sum of the two readings is the bias exactly, if the turn is exactly half a
//!   turn: a turn off by δ moves it by δ·|t|/2, which the budget carries
//!   ([`crate::session::half_turn_half_width`]).
//!
//! The sensor's gain and cross-axis error turn the circle into an ellipse (1 % on a
//! bench tilted 0.5° is 0.005°); the session solves the bench again with the gain stage
//! 2 found ([`BenchTurns::bias_with_gain`]), as it solves stage 1 again.

use crate::error::StageError;
use crate::linalg::{spd_inverse, Square};
use crate::model::{Convention, Gain, SensorBias, SensorModel, Tilt};
use crate::real::{rad_to_deg, Real};
use nalgebra::Vector3;

/// Checks that a reading is finite and inside the sensor's range (stages 0 and 1).
pub(crate) fn check_reading<T: Real>(t: &Tilt<T>, range_rad: T) -> Result<(), StageError> {
    if !t.is_finite() {
        return Err(StageError::NonFiniteReading);
    }
    match t.axis_beyond(range_rad) {
        Some(axis) => Err(StageError::ReadingOutOfRange {
            axis,
            value_deg: rad_to_deg(t.get(axis)).to_f64() as f32,
            range_deg: rad_to_deg(range_rad).to_f64() as f32,
        }),
        None => Ok(()),
    }
}

/// Most headings a bench reading holds: four, the pendant's own, which fit one export
/// line ([`BENCH_HEADINGS`]).
pub const MAX_HEADINGS: usize = 4;

/// Headings the pendant guides on the bench (stage 0, the closing readings, a bracket's
/// calibration): four, about a quarter turn apart, by hand. Three determine the circle;
/// the fourth checks that the pendant was turned on the spot.
pub const BENCH_HEADINGS: usize = 4;

/// Unknowns of a bench solve besides the headings: the bias (2) and the bench's tilt (2).
const FIXED_UNKNOWNS: usize = 4;

/// Unknowns at most: the fixed four and a heading for every reading after the first.
const MAX_UNKNOWNS: usize = FIXED_UNKNOWNS + MAX_HEADINGS - 1;

/// The ridge on each heading's information (per rad², against a reading's 1 per rad of
/// bias): a heading's column is the bench's tilt, so this is a tilt of 1e-4 rad
/// (0.006°) over which the headings are held rather than fitted; at that tilt a heading
/// off by a radian moves a reading by less than a capture's noise.
const HEADING_RIDGE: f64 = 1e-8;

/// Gauss-Newton steps before the headings are held (and as many again before giving
/// up): from the circle fit two or three suffice.
const MAX_STEPS: u32 = 30;

/// A bench solve's residual (per degree of freedom) above this many readings' noise
/// (`noise_rad`, per reading), and above [`BENCH_RESIDUAL_FLOOR_DEG`], means the
/// pendant did not sit on one plane at every heading: moved, not turned on the spot, or
/// knocked.
pub const BENCH_RESIDUAL_LIMIT: f64 = 5.0;

/// A bench solve's residual below this (deg) is never refused: the sensor's own
/// non-linearity and its drift between headings leave a few thousandths on a bench
/// tilted by degrees (the simulator's largest over 600 healthy sessions: 0.0042°),
/// where a pendant moved to another spot of the bench reads hundredths apart.
pub const BENCH_RESIDUAL_FLOOR_DEG: f64 = 0.01;

/// The largest variance of the bias (in units of one reading's noise variance) a bench
/// solve of three or more headings accepts: four times that of four headings a quarter
/// turn apart (0.5, the same as an exact half turn's two readings), so the bias is known
/// to at most twice their σ. Headings turned by hand a rough quarter turn apart stay far
/// inside it; a few degrees apart the factor is tens to thousands, and the circle's
/// centre (the bias) is a guess.
pub const HEADINGS_VARIANCE_LIMIT: f64 = 2.0;

/// The pendant read on a bench at two or more headings, turned about the vertical on
/// the same spot between them.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BenchTurns<T> {
    /// The readings, in the order taken (first `count`).
    pub readings: [Tilt<T>; MAX_HEADINGS],
    /// How many (2..=[`MAX_HEADINGS`]).
    pub count: u8,
}

/// What a bench solve found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BenchSolution<T> {
    /// The sensor's bias.
    pub bias: SensorBias<T>,
    /// The variance of each of its components in units of one reading's noise variance
    /// (½ for a reversal's half-sum).
    pub variance_factor: T,
    /// The bench's tilt the readings show (rad, the magnitude).
    pub tilt_rad: T,
    /// Whether the headings came from the readings (three or more) or a half turn was
    /// assumed (two).
    pub headings_solved: bool,
    /// The residual RMS of the solve (rad; 0 with exactly as many readings as unknowns).
    pub residual_rms_rad: T,
}

impl<T: Real> BenchTurns<T> {
    /// Two readings half a turn apart: a reversal.
    pub fn half_turn(first: Tilt<T>, second: Tilt<T>) -> Self {
        let mut readings = [Tilt::default(); MAX_HEADINGS];
        readings[0] = first;
        readings[1] = second;
        BenchTurns { readings, count: 2 }
    }

    /// The readings of `taken` (2..=[`MAX_HEADINGS`] of them), or `None`.
    pub fn from_readings(taken: &[Tilt<T>]) -> Option<Self> {
        if !(2..=MAX_HEADINGS).contains(&taken.len()) {
            return None;
        }
        let mut readings = [Tilt::default(); MAX_HEADINGS];
        readings[..taken.len()].copy_from_slice(taken);
        Some(BenchTurns {
            readings,
            count: taken.len() as u8,
        })
    }

    /// The readings taken.
    pub fn taken(&self) -> &[Tilt<T>] {
        &self.readings[..usize::from(self.count).min(MAX_HEADINGS)]
    }

    /// Each reading moved by `shift` (a bias change the caller studies).
    pub fn shifted(&self, shift: &Tilt<T>) -> Self {
        let mut out = *self;
        for r in out.readings.iter_mut().take(usize::from(self.count)) {
            *r = Tilt::new(r.x_rad + shift.x_rad, r.y_rad + shift.y_rad);
        }
        out
    }

    /// The bench's tilt as the first reading saw it, to first order (rad, x and y):
    /// the first reading less the circle's centre, for a reversal its half difference.
    pub fn tilt_seen_first(&self) -> Tilt<T> {
        let taken = self.taken();
        let centre = match taken.len() {
            0 | 1 => return Tilt::default(),
            2 => Tilt::new(
                (taken[0].x_rad + taken[1].x_rad) * T::lit(0.5),
                (taken[0].y_rad + taken[1].y_rad) * T::lit(0.5),
            ),
            _ => circle_centre(taken).unwrap_or(taken[0]),
        };
        taken[0].minus(&centre)
    }

    /// The bench's tilt (rad, the magnitude) where a half turn is assumed (two
    /// readings): what a turn off 180° moves the bias by, times half its error. 0 for
    /// three or more headings, which solve their own turns.
    pub fn half_turn_tilt_rad(&self) -> T {
        if self.count != 2 {
            return T::zero();
        }
        let t = self.tilt_seen_first();
        (t.x_rad * t.x_rad + t.y_rad * t.y_rad).sqrt()
    }

    /// The sensor bias, in `convention`'s terms ([`SensorModel::read_up`]), with a
    /// nominal gain.
    ///
    /// # Errors
    /// As [`Self::bias_with_gain`].
    pub fn bias(&self, convention: Convention, range_rad: T) -> Result<SensorBias<T>, StageError> {
        self.solve(convention, Gain::default(), range_rad, T::zero())
            .map(|s| s.bias)
    }

    /// The sensor bias with the sensor's gain and cross-axis errors known.
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn bias_with_gain(
        &self,
        convention: Convention,
        gain: Gain<T>,
        range_rad: T,
    ) -> Result<SensorBias<T>, StageError> {
        self.solve(convention, gain, range_rad, T::zero())
            .map(|s| s.bias)
    }

    /// Solves the bench: the bias, its variance and the bench's tilt.
    ///
    /// With two readings, a half turn: `rpy` (angles plus a zero error) the half-sum
    /// `(r + r')/2` exactly; `axis` (an acceleration offset `o`) each reading gives the
    /// direction `nᵢ` of `aᵢ = λᵢ·nᵢ`; the half turn makes `a₁ = u + o`, `a₂ = u' + o`
    /// with `u' = (−u_x, −u_y, u_z)` and `o_z = 0`, so `λ₁n₁z = λ₂n₂z = u_z`, the half
    /// difference of the horizontal parts is `u_xy`, their half-sum `o_xy`, and
    /// `|u| = 1` fixes λ₁: exact for any surface tilt. With three or more, the headings
    /// are solved for with the bias and the tilt. `noise_rad` (one reading's 1σ) judges
    /// the residuals of four or more; 0: not judged.
    ///
    /// # Errors
    /// A non-finite reading or one outside `±range_rad`; fewer than two readings;
    /// readings no orientation can produce; readings that do not lie on one circle
    /// (the pendant moved between headings); no convergence.
    pub fn solve(
        &self,
        convention: Convention,
        gain: Gain<T>,
        range_rad: T,
        noise_rad: T,
    ) -> Result<BenchSolution<T>, StageError> {
        let taken = self.taken();
        if taken.len() < 2 {
            return Err(StageError::TooFewHeadings {
                got: taken.len() as u8,
            });
        }
        for r in taken {
            check_reading(r, range_rad)?;
        }
        if taken.len() == 2 && gain == Gain::default() {
            let bias = half_turn_bias(&taken[0], &taken[1], convention)?;
            let tilt = self.tilt_seen_first();
            return Ok(BenchSolution {
                bias,
                variance_factor: T::lit(0.5),
                tilt_rad: (tilt.x_rad * tilt.x_rad + tilt.y_rad * tilt.y_rad).sqrt(),
                headings_solved: false,
                residual_rms_rad: T::zero(),
            });
        }
        solve_headings(taken, convention, gain, noise_rad)
    }
}

/// The exact half-turn bias of docs/method.md (see [`BenchTurns::solve`]).
fn half_turn_bias<T: Real>(
    first: &Tilt<T>,
    second: &Tilt<T>,
    convention: Convention,
) -> Result<SensorBias<T>, StageError> {
    let half = T::lit(0.5);
    match convention {
        Convention::Rpy => Ok(Tilt::new(
            (first.x_rad + second.x_rad) * half,
            (first.y_rad + second.y_rad) * half,
        )),
        Convention::Axis => {
            let n1 = convention
                .up_from_reading(first)
                .ok_or(StageError::InconsistentReading)?;
            let n2 = convention
                .up_from_reading(second)
                .ok_or(StageError::InconsistentReading)?;
            if n2.z <= T::zero() || n1.z <= T::zero() {
                return Err(StageError::InconsistentReading);
            }
            let ratio = n1.z / n2.z;
            let (dx, dy) = ((n1.x - ratio * n2.x) * half, (n1.y - ratio * n2.y) * half);
            let lambda1 = T::one() / (dx * dx + dy * dy + n1.z * n1.z).sqrt();
            let ox = lambda1 * (n1.x + ratio * n2.x) * half;
            let oy = lambda1 * (n1.y + ratio * n2.y) * half;
            let b = Tilt::new(oy, -ox);
            if b.is_finite() {
                Ok(b)
            } else {
                Err(StageError::InconsistentReading)
            }
        }
    }
}

/// The centre of the circle through the readings, by the algebraic (Kåsa) fit:
/// `x² + y² + D·x + E·y + F = 0` in least squares; `None` for fewer than three or
/// points on a line.
fn circle_centre<T: Real>(readings: &[Tilt<T>]) -> Option<Tilt<T>> {
    if readings.len() < 3 {
        return None;
    }
    // Centred on the first reading, so the sums are of small numbers.
    let o = readings[0];
    let mut m = Square::<T, 3>::zeros(3);
    let mut b = [T::zero(); 3];
    for r in readings {
        let (x, y) = (r.x_rad - o.x_rad, r.y_rad - o.y_rad);
        let row = [x, y, T::one()];
        let rhs = -(x * x + y * y);
        for i in 0..3 {
            for j in 0..3 {
                m.m[i][j] += row[i] * row[j];
            }
            b[i] += row[i] * rhs;
        }
    }
    let (inv, _) = spd_inverse(&m)?;
    let d = (0..3).fold(T::zero(), |a, j| a + inv.m[0][j] * b[j]);
    let e = (0..3).fold(T::zero(), |a, j| a + inv.m[1][j] * b[j]);
    let c = Tilt::new(o.x_rad - d * T::lit(0.5), o.y_rad - e * T::lit(0.5));
    c.is_finite().then_some(c)
}

/// The bench with the headings unknown: Gauss-Newton on the exact model, unknowns
/// (bias x, bias y, tilt x, tilt y, ψ₂..ψₙ), ψ₁ = 0.
fn solve_headings<T: Real>(
    taken: &[Tilt<T>],
    convention: Convention,
    gain: Gain<T>,
    noise_rad: T,
) -> Result<BenchSolution<T>, StageError> {
    let n = taken.len();
    let unknowns = FIXED_UNKNOWNS + n - 1;
    // The start: the circle's centre (or, for two readings with a gain, the half-sum),
    // the tilt as the first reading sees it, each heading from the angle its reading
    // makes about the centre (the pendant turned by +ψ sees the tilt turned by −ψ).
    let centre = circle_centre(taken).unwrap_or(Tilt::new(
        (taken[0].x_rad + taken[1].x_rad) * T::lit(0.5),
        (taken[0].y_rad + taken[1].y_rad) * T::lit(0.5),
    ));
    let mut p = [T::zero(); MAX_UNKNOWNS];
    let first = taken[0].minus(&centre);
    let a0 = first.y_rad.atan2(first.x_rad);
    // In the axis convention the bias is an acceleration offset (−b_y, b_x) and the
    // reading is an angle of the tilted vector: to first order both conventions read
    // the up vector's horizontal part as (u_y, −u_x).
    p[0] = centre.x_rad;
    p[1] = centre.y_rad;
    // u = (u_x, u_y) with reading ≈ (u_y, −u_x): u_x = −r_y, u_y = r_x.
    p[2] = -first.y_rad;
    p[3] = first.x_rad;
    // On a bench that barely tilts the angles about the centre are noise: the headings
    // start spread evenly (they then barely matter, and the bias is the readings' mean).
    let spread = (first.x_rad * first.x_rad + first.y_rad * first.y_rad).sqrt();
    for i in 1..n {
        let r = taken[i].minus(&centre);
        p[FIXED_UNKNOWNS + i - 1] = if spread > T::lit(HEADING_RIDGE).sqrt() {
            -(r.y_rad.atan2(r.x_rad) - a0)
        } else {
            T::lit(2.0) * T::pi() * T::lit(i as f64) / T::lit(n as f64)
        };
    }
    if n == 2 {
        // Two readings: the half turn is assumed, not solved.
        p[FIXED_UNKNOWNS] = T::pi();
    }
    let sensor = SensorModel {
        gain,
        ..SensorModel::new(convention, Tilt::default())
    };
    let solved_unknowns = if n == 2 { FIXED_UNKNOWNS } else { unknowns };
    // Where the headings are held once the damping has crawled for MAX_STEPS.
    let mut held: Option<[T; MAX_UNKNOWNS]> = None;
    let mut converged = false;
    let mut jtj = Square::<T, MAX_UNKNOWNS>::zeros(solved_unknowns);
    let mut ssr = T::zero();
    for step in 0..2 * MAX_STEPS {
        if step == MAX_STEPS {
            held = Some(p);
        }
        let mut jtr = [T::zero(); MAX_UNKNOWNS];
        jtj = Square::zeros(solved_unknowns);
        ssr = T::zero();
        for (i, reading) in taken.iter().enumerate() {
            let (predicted, rows) = predict(&sensor, &p, i);
            let d = reading.minus(&predicted);
            for (axis, row) in rows.iter().enumerate() {
                let r = if axis == 0 { d.x_rad } else { d.y_rad };
                ssr += r * r;
                for a in 0..solved_unknowns {
                    jtr[a] += row[a] * r;
                    for b in 0..solved_unknowns {
                        jtj.m[a][b] += row[a] * row[b];
                    }
                }
            }
        }
        // A ridge far below the bias's own information (a reading's, 1 per rad) keeps
        // a bench that barely tilts solvable: its headings are then unseen (their
        // columns go as the tilt), and the bias is the readings' mean. As a damping it
        // converges to the readings' own optimum, but where a heading's information is
        // near the ridge (a levelled bench, tilt ~1e-4 rad) it closes only a fraction
        // ridge/(information + ridge) of the way a step and does not settle within
        // MAX_STEPS: the headings are then held where it left them (the ridge becomes a
        // prior centred there), moving the bias by less than the tilt times what is
        // left of their way, and the rest converges in a few steps.
        for a in FIXED_UNKNOWNS..solved_unknowns {
            jtj.m[a][a] += T::lit(HEADING_RIDGE);
            if let Some(h) = &held {
                jtr[a] -= T::lit(HEADING_RIDGE) * (p[a] - h[a]);
            }
        }
        let (inv, _) = spd_inverse(&jtj).ok_or(StageError::Unresolvable)?;
        let mut size = T::zero();
        for a in 0..solved_unknowns {
            let step = (0..solved_unknowns).fold(T::zero(), |s, b| s + inv.m[a][b] * jtr[b]);
            p[a] += step;
            let scale = if a < FIXED_UNKNOWNS {
                T::one()
            } else {
                T::lit(1e-3)
            };
            size = size.max((step * scale).abs());
        }
        if !p.iter().all(|v| v.is_finite()) {
            return Err(StageError::InconsistentReading);
        }
        if size < T::STEP_TOLERANCE_RAD {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(StageError::InconsistentReading);
    }
    let dof = (2 * n).saturating_sub(solved_unknowns);
    let residual_rms_rad = (ssr / T::lit((2 * n) as f64)).sqrt();
    if dof > 0 && noise_rad > T::zero() {
        let limit = (noise_rad * T::lit(BENCH_RESIDUAL_LIMIT))
            .max(crate::real::deg_to_rad(T::lit(BENCH_RESIDUAL_FLOOR_DEG)));
        // Judged, and reported, per degree of freedom: the RMS over all 2n readings
        // is smaller by the unknowns solved and could show a figure under its limit.
        let scatter_rad = (ssr / T::lit(dof as f64)).sqrt();
        if scatter_rad > limit {
            return Err(StageError::NotTurnedOnTheSpot {
                rms_deg: rad_to_deg(scatter_rad).to_f64() as f32,
                limit_deg: rad_to_deg(limit).to_f64() as f32,
            });
        }
    }
    let (inv, _) = spd_inverse(&jtj).ok_or(StageError::Unresolvable)?;
    let bias = Tilt::new(p[0], p[1]);
    let variance_factor = inv.m[0][0].max(inv.m[1][1]);
    if n > 2 && variance_factor > T::lit(HEADINGS_VARIANCE_LIMIT) {
        return Err(StageError::HeadingsTooClose {
            variance_factor: variance_factor.to_f64() as f32,
            limit: HEADINGS_VARIANCE_LIMIT as f32,
        });
    }
    Ok(BenchSolution {
        bias,
        variance_factor,
        tilt_rad: (p[2] * p[2] + p[3] * p[3]).sqrt(),
        headings_solved: n > 2,
        residual_rms_rad,
    })
}

/// Reading `i` of the bench model at unknowns `p`, and its rows of J.
fn predict<T: Real>(
    sensor: &SensorModel<T>,
    p: &[T; MAX_UNKNOWNS],
    i: usize,
) -> (Tilt<T>, [[T; MAX_UNKNOWNS]; 2]) {
    let (tx, ty) = (p[2], p[3]);
    let tz = (T::one() - tx * tx - ty * ty).max(T::zero()).sqrt();
    let psi = if i == 0 {
        T::zero()
    } else {
        p[FIXED_UNKNOWNS + i - 1]
    };
    let (s, c) = psi.fast_sin_cos();
    // The bench's up vector seen from heading ψ: turned by −ψ about z.
    let u = Vector3::new(c * tx + s * ty, -s * tx + c * ty, tz);
    let read = sensor.read_up(&u, &Tilt::new(p[0], p[1]));
    let through = |axis: usize, dv: &Vector3<T>| read.grad[axis].dot(&sensor.gain.apply_linear(dv));
    // ∂u/∂tx, ∂u/∂ty (tz follows |u| = 1), ∂u/∂ψ.
    let dz = |t: T| if tz > T::zero() { -t / tz } else { T::zero() };
    let du_tx = Vector3::new(c, -s, dz(tx));
    let du_ty = Vector3::new(s, c, dz(ty));
    let du_psi = Vector3::new(-s * tx + c * ty, -c * tx - s * ty, T::zero());
    let mut rows = [[T::zero(); MAX_UNKNOWNS]; 2];
    for (axis, row) in rows.iter_mut().enumerate() {
        row[0] = read.d_bias[axis][0];
        row[1] = read.d_bias[axis][1];
        row[2] = through(axis, &du_tx);
        row[3] = through(axis, &du_ty);
        if i > 0 {
            row[FIXED_UNKNOWNS + i - 1] = through(axis, &du_psi);
        }
    }
    (read.reading, rows)
}

/// Bench readings with the sensor's temperature during them (°C): stage 0's, or the
/// closing readings after stage 2.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BenchTurnsAt<T> {
    /// The readings.
    pub turns: BenchTurns<T>,
    /// The sensor's temperature during them (°C).
    pub temperature_c: Option<T>,
}

/// Which bench step a refusal came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BenchStep {
    /// Stage 0, before the robot.
    Stage0,
    /// The closing readings, after stage 2.
    Closing,
}

/// Below this temperature change (K) between the two bench readings the drift is not
/// estimated: the TEMP register resolves 0.053 K, and the readings' noise over a
/// smaller span would make the slope noisier than the drift it corrects.
pub const MIN_DRIFT_SPAN_K: f64 = 0.5;

/// The sensor's bias over the session: measured by stage 0 and, when the pendant was
/// read on the bench again after stage 2, changing linearly with its temperature
/// between the two (the SCL3300's offset drifts by up to ~0.009 °/K, docs/error-budget.md).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BiasOverTemperature<T> {
    /// The bias at `reference_c` (or at every temperature, if no drift is known).
    pub bias: SensorBias<T>,
    /// The temperature of stage 0 (°C).
    pub reference_c: Option<T>,
    /// The drift measured between the two (rad/K); zero with one.
    pub drift_per_k: Tilt<T>,
    /// The closing readings' temperature (°C), if the drift was measured.
    pub closing_c: Option<T>,
    /// Whether two bench solves too close in temperature were averaged.
    pub averaged: bool,
    /// Stage 0's bias variance in units of one reading's noise variance.
    pub start_factor: T,
    /// The closing bias variance in the same units (0 without).
    pub closing_factor: T,
}

impl<T: Real> BiasOverTemperature<T> {
    /// One bench solve, no drift; `factor` its variance in units of one reading's
    /// (½ for a reversal).
    pub fn constant(bias: SensorBias<T>, reference_c: Option<T>) -> Self {
        BiasOverTemperature {
            bias,
            reference_c,
            drift_per_k: Tilt::default(),
            closing_c: None,
            averaged: false,
            start_factor: T::lit(0.5),
            closing_factor: T::zero(),
        }
    }

    /// From stage 0's bench readings and, if any, the closing ones, solved with the
    /// sensor's `gain`.
    ///
    /// # Errors
    /// Either bench solve's refusal, with the step it was.
    pub fn measure(
        start: &BenchTurnsAt<T>,
        closing: Option<&BenchTurnsAt<T>>,
        convention: Convention,
        gain: Gain<T>,
        range_rad: T,
        noise_rad: T,
    ) -> Result<Self, (BenchStep, StageError)> {
        let s0 = start
            .turns
            .solve(convention, gain, range_rad, noise_rad)
            .map_err(|e| (BenchStep::Stage0, e))?;
        let start_c = start.temperature_c;
        let b0 = s0.bias;
        let Some(end) = closing else {
            return Ok(BiasOverTemperature {
                start_factor: s0.variance_factor,
                ..Self::constant(b0, start_c)
            });
        };
        let s1 = end
            .turns
            .solve(convention, gain, range_rad, noise_rad)
            .map_err(|e| (BenchStep::Closing, e))?;
        let b1 = s1.bias;
        match (start_c, end.temperature_c) {
            (Some(t0), Some(t1)) if (t1 - t0).abs() >= T::lit(MIN_DRIFT_SPAN_K) => {
                let span = t1 - t0;
                Ok(BiasOverTemperature {
                    bias: b0,
                    reference_c: Some(t0),
                    drift_per_k: Tilt::new(
                        (b1.x_rad - b0.x_rad) / span,
                        (b1.y_rad - b0.y_rad) / span,
                    ),
                    closing_c: Some(t1),
                    averaged: false,
                    start_factor: s0.variance_factor,
                    closing_factor: s1.variance_factor,
                })
            }
            // Too small a span to see a slope: the two average.
            _ => {
                let half = T::lit(0.5);
                Ok(BiasOverTemperature {
                    averaged: true,
                    start_factor: s0.variance_factor,
                    closing_factor: s1.variance_factor,
                    ..Self::constant(
                        Tilt::new((b0.x_rad + b1.x_rad) * half, (b0.y_rad + b1.y_rad) * half),
                        start_c,
                    )
                })
            }
        }
    }

    /// The bias at a temperature (the reference's if unknown).
    pub fn at(&self, temperature_c: Option<T>) -> SensorBias<T> {
        let dt = match (temperature_c, self.reference_c) {
            (Some(t), Some(r)) => t - r,
            _ => T::zero(),
        };
        Tilt::new(
            self.bias.x_rad + self.drift_per_k.x_rad * dt,
            self.bias.y_rad + self.drift_per_k.y_rad * dt,
        )
    }

    /// The variance of the bias at `temperature_c` in units of one reading's noise
    /// variance: stage 0's own for one solve, `w₀²·v₀ + w₁²·v₁` between two (with
    /// `w₁ = (t − t₀)/(t₁ − t₀)`), `(v₀ + v₁)/4` for two averaged.
    pub fn variance_factor(&self, temperature_c: Option<T>) -> T {
        let (v0, v1) = (self.start_factor, self.closing_factor);
        match (self.reference_c, self.closing_c, temperature_c) {
            (Some(t0), Some(t1), Some(t)) => {
                let w1 = (t - t0) / (t1 - t0);
                let w0 = T::one() - w1;
                w0 * w0 * v0 + w1 * w1 * v1
            }
            _ if self.averaged => (v0 + v1) * T::lit(0.25),
            _ => v0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{rot_x, rot_y, rot_z, SensorModel};

    fn bench(a_deg: f64, b_deg: f64) -> nalgebra::Rotation3<f64> {
        rot_y(a_deg.to_radians()) * rot_x(b_deg.to_radians())
    }

    #[test]
    fn a_half_turn_recovers_the_bias_on_a_tilted_bench_in_both_conventions() {
        // Exactness: 1e-12 rad is rounding on a handful of trig calls.
        for conv in [Convention::Rpy, Convention::Axis] {
            let bias = Tilt::from_deg(1.1_f64, -1.4);
            let sensor = SensorModel::new(conv, bias);
            for (a, b, h) in [
                (2.0_f64, -1.5_f64, 0.3_f64),
                (-3.0, 0.5, 2.5),
                (0.0, 0.0, -1.0),
            ] {
                let surface = bench(a, b) * rot_z(h);
                let rev = BenchTurns::half_turn(
                    sensor.reading(&surface),
                    sensor.reading(&(surface * rot_z(core::f64::consts::PI))),
                );
                let found = rev.bias(conv, 0.5).unwrap();
                assert!(
                    (found.x_rad - bias.x_rad).abs() < 1e-12,
                    "{conv:?} {found:?}"
                );
                assert!(
                    (found.y_rad - bias.y_rad).abs() < 1e-12,
                    "{conv:?} {found:?}"
                );
            }
        }
    }

    #[test]
    fn headings_turned_by_hand_recover_the_bias_whatever_the_turns() {
        // Three and four headings at arbitrary turns (none a half or quarter turn) on a
        // bench tilted 0.5-2°, the chip offset 1°: the bias to 1e-10 rad, where a
        // half-sum of the first two would be off by δ·|t|/2 (0.0044° at 1° off on 0.5°).
        for conv in [Convention::Rpy, Convention::Axis] {
            let bias = Tilt::from_deg(1.0_f64, -0.7);
            let sensor = SensorModel::new(conv, bias);
            for (a, b, turns) in [
                (0.5_f64, 0.2_f64, &[0.0, 1.9, 4.1][..]),
                (-2.0, 1.0, &[0.3, 1.4, 3.3, 4.9][..]),
                (0.05, -0.03, &[0.0, 1.5, 3.2, 4.6][..]),
            ] {
                let readings: Vec<Tilt<f64>> = turns
                    .iter()
                    .map(|h| sensor.reading(&(bench(a, b) * rot_z(*h))))
                    .collect();
                let turns = BenchTurns::from_readings(&readings).unwrap();
                let s = turns.solve(conv, Gain::default(), 0.5, 1e-5).unwrap();
                assert!(s.headings_solved);
                assert!((s.bias.x_rad - bias.x_rad).abs() < 1e-10, "{conv:?} {s:?}");
                assert!((s.bias.y_rad - bias.y_rad).abs() < 1e-10, "{conv:?} {s:?}");
            }
        }
    }

    #[test]
    fn a_pendant_moved_between_headings_is_refused_by_name() {
        let sensor = SensorModel::new(Convention::Axis, Tilt::from_deg(0.3, 0.2));
        let mut readings: Vec<Tilt<f64>> = [0.0, 1.6, 3.1, 4.7]
            .iter()
            .map(|h| sensor.reading(&(bench(0.6, -0.4) * rot_z(*h))))
            .collect();
        // The last on another spot of the bench, tilted 0.05° more.
        readings[3] = sensor.reading(&(bench(0.65, -0.4) * rot_z(4.7)));
        let turns = BenchTurns::from_readings(&readings).unwrap();
        let noise = 0.0008_f64.to_radians();
        let refused = turns.solve(Convention::Axis, Gain::default(), 0.5, noise);
        let Err(StageError::NotTurnedOnTheSpot { rms_deg, limit_deg }) = refused else {
            panic!("not refused by name: {refused:?}");
        };
        // The figure the message shows is the one judged: above its limit.
        assert!(
            rms_deg > limit_deg,
            "{rms_deg} deg shown against {limit_deg} deg"
        );
    }

    /// A levelled bench (tilts of thousandths of a degree, where a heading barely shows
    /// in the readings) is solved in both conventions and in the pendant's f32, not
    /// refused as "readings that cannot come from one orientation": a bracket's
    /// reference plate is levelled on purpose. Noise-free, the bias to a tenth of a
    /// capture's noise (0.0008°, docs/error-budget.md): the headings held where they
    /// cannot be seen move it by less; with the noise of one capture (uniform ±0.0008°)
    /// on each reading, within that noise.
    #[test]
    fn a_levelled_bench_is_solved_not_refused() {
        let capture_noise_deg = 0.0008_f64;
        for conv in [Convention::Rpy, Convention::Axis] {
            let bias = Tilt::from_deg(1.0_f64, -0.7);
            let sensor = SensorModel::new(conv, bias);
            for tilt_deg in [0.0_f64, 0.0005, 0.002, 0.004, 0.006, 0.01, 0.02, 0.05] {
                for noise_deg in [0.0, capture_noise_deg] {
                    let mut rng = crate::plan::Xorshift64Star::new(7);
                    let n = noise_deg.to_radians();
                    let readings: Vec<Tilt<f64>> = [0.0, 1.5, 3.2, 4.6]
                        .iter()
                        .map(|h| {
                            let surface = bench(tilt_deg * 0.8, tilt_deg * 0.6) * rot_z(*h);
                            let r = sensor.reading(&surface);
                            Tilt::new(r.x_rad + rng.uniform(-n, n), r.y_rad + rng.uniform(-n, n))
                        })
                        .collect();
                    let within_deg = if noise_deg > 0.0 {
                        capture_noise_deg
                    } else {
                        capture_noise_deg / 10.0
                    };
                    let noise_rad = capture_noise_deg.to_radians();
                    let s = BenchTurns::from_readings(&readings)
                        .unwrap()
                        .solve(conv, Gain::default(), 0.5, noise_rad)
                        .unwrap_or_else(|e| panic!("{conv:?} tilt {tilt_deg}: {e:?}"));
                    let readings32: Vec<Tilt<f32>> = readings
                        .iter()
                        .map(|r| Tilt::new(r.x_rad as f32, r.y_rad as f32))
                        .collect();
                    let s32 = BenchTurns::from_readings(&readings32)
                        .unwrap()
                        .solve(conv, Gain::default(), 0.5, noise_rad as f32)
                        .unwrap_or_else(|e| panic!("{conv:?} tilt {tilt_deg} f32: {e:?}"));
                    for (x, y) in [
                        (s.bias.x_rad, s.bias.y_rad),
                        (f64::from(s32.bias.x_rad), f64::from(s32.bias.y_rad)),
                    ] {
                        let off_deg = (x - bias.x_rad)
                            .abs()
                            .max((y - bias.y_rad).abs())
                            .to_degrees();
                        assert!(
                            off_deg < within_deg,
                            "{conv:?} tilt {tilt_deg} noise {noise_deg}: bias off by {off_deg} deg"
                        );
                    }
                }
            }
        }
    }

    /// Headings a few degrees apart on a tilted bench leave the circle's centre (the
    /// bias) a guess: refused by name, where the same bench read at rough quarter turns
    /// (each off a true quarter by up to 30°) is accepted within the limit.
    #[test]
    fn headings_too_close_are_refused_by_name_and_rough_quarter_turns_are_not() {
        let noise = 0.0008_f64.to_radians();
        for conv in [Convention::Rpy, Convention::Axis] {
            let sensor = SensorModel::new(conv, Tilt::from_deg(0.3, 0.2));
            let read = |turns: &[f64]| {
                let readings: Vec<Tilt<f64>> = turns
                    .iter()
                    .map(|h| sensor.reading(&(bench(0.5, -0.3) * rot_z(*h))))
                    .collect();
                BenchTurns::from_readings(&readings).unwrap().solve(
                    conv,
                    Gain::default(),
                    0.5,
                    noise,
                )
            };
            let close = read(&[0.0, 0.09, 0.17, 0.26]);
            assert!(
                matches!(close, Err(StageError::HeadingsTooClose { .. })),
                "{conv:?}: {close:?}"
            );
            for turns in [
                &[0.0, 1.6, 3.1, 4.7][..],
                &[0.0, 1.05, 2.6, 4.2][..],
                &[0.3, 2.1, 3.2, 5.2][..],
            ] {
                let s = read(turns).unwrap_or_else(|e| panic!("{conv:?} {turns:?}: {e:?}"));
                assert!(s.variance_factor <= HEADINGS_VARIANCE_LIMIT, "{s:?}");
            }
        }
    }
}
