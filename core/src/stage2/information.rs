//! The information of a pose set, J folded into a triangular factor as rows arrive
//! (a streaming QR by Givens rotations), and what it says about separability.
//!
//! J is never stored: any number of poses fits in a few hundred bytes, and the
//! conditioning is that of J, not of JᵀJ, which is what keeps `f32` on the pendant
//! within 2e-5° of `f64` on the desktop.

use super::params::{Layout, MAX_PARAMS};
use crate::error::ParamSet;
use crate::linalg::{svd, Square};
use crate::real::Real;

/// A parameter whose share of the weakest direction of J exceeds this (as a component
/// of the unit singular vector) is named as part of that direction: 0.3² ≈ 9 % of it.
pub const WEAK_DIRECTION_SHARE: f64 = 0.3;

/// One row of J (first `n` entries used).
pub type Row<T> = [T; MAX_PARAMS];

/// J folded into an upper-triangular factor R (JᵀJ = RᵀR) together with Qᵀ·r.
#[derive(Clone, Copy, Debug)]
pub struct Information<T: Real> {
    pub(crate) r: Square<T, MAX_PARAMS>,
    qtb: [T; MAX_PARAMS],
}

/// Singular-value summary of J.
pub(crate) struct Conditioning<T> {
    pub(crate) condition_number: T,
    /// Slots of the weakest direction (bit i = slot i).
    pub(crate) weakest_slots: u64,
    /// The weakest direction itself (unit, over the slots; columns scaled).
    pub(crate) weakest_direction: [T; MAX_PARAMS],
}

impl<T: Real> Conditioning<T> {
    /// The weakest direction's parameters, by name.
    pub(crate) fn weakest(&self, layout: &Layout) -> ParamSet {
        layout.names((0..MAX_PARAMS).filter(|i| self.weakest_slots & (1 << i) != 0))
    }
}

/// Most power- or inverse-iteration steps of [`Information::conditioning`]; each
/// multiplies the error of the eigenvalue estimate by the squared ratio of the two
/// nearest eigenvalues, and a step costs n² multiply-adds.
const CONDITIONING_STEPS: usize = 60;

/// An eigenvalue estimate that moved by less than this (relative) in a step is taken
/// as settled: a condition number is printed to three digits.
const CONDITIONING_SETTLED: f64 = 1e-6;

/// A start that no eigenvector of a real fit is orthogonal to: entries that differ in
/// size and sign (the inverse iteration's alternate, so the two do not share a bias).
fn start_vector<T: Real>(n: usize, alternate: bool) -> [T; MAX_PARAMS] {
    let mut x = [T::zero(); MAX_PARAMS];
    for (i, xi) in x.iter_mut().enumerate().take(n) {
        let size = T::one() + T::lit((i % 7) as f64 * 0.13);
        *xi = if alternate && i % 2 == 1 { -size } else { size };
    }
    x
}

/// Scales `x` to unit length over its first `n` entries in place; `false` if it has
/// no length (or not a finite one).
fn normalise<T: Real>(x: &mut [T; MAX_PARAMS], n: usize) -> bool {
    let length = x.iter().take(n).fold(T::zero(), |s, v| s + *v * *v).sqrt();
    if !length.is_finite() || length <= T::zero() {
        return false;
    }
    for v in x.iter_mut().take(n) {
        *v /= length;
    }
    true
}

/// The slots whose component in a unit direction exceeds [`WEAK_DIRECTION_SHARE`].
fn named_components<T: Real>(direction: &[T]) -> u64 {
    direction
        .iter()
        .enumerate()
        .filter(|(_, c)| c.abs() > T::lit(WEAK_DIRECTION_SHARE))
        .fold(0, |s, (i, _)| s | (1 << i))
}

/// The parameters along the weakest direction of a Gram matrix JᵀJ: what the planner
/// names when a plan is ill-conditioned, with the same rule as [`Information`]'s
/// check.
pub fn weakest_of_gram<T: Real>(gram: &Square<T, MAX_PARAMS>, layout: &Layout) -> ParamSet {
    // The Gram matrix's weakest eigenvector is J's weakest right singular vector: the
    // SVD of the symmetric matrix itself gives it.
    let s = svd(gram);
    layout.names((0..MAX_PARAMS).filter(|i| named_components(&s.weakest[..s.n]) & (1 << i) != 0))
}

impl<T: Real> Information<T> {
    /// No rows yet, for `n` parameters.
    pub fn new(n: usize) -> Self {
        Information {
            r: Square::zeros(n),
            qtb: [T::zero(); MAX_PARAMS],
        }
    }

    /// Parameters.
    pub fn len(&self) -> usize {
        self.r.n
    }

    /// Never true: a fit has at least the four offsets.
    pub fn is_empty(&self) -> bool {
        self.r.n == 0
    }

    /// Folds in one row of `J·δ ≈ b` by Givens rotations.
    pub fn add_row(&mut self, a: &Row<T>, mut b: T) {
        let n = self.r.n;
        let mut a = *a;
        for k in 0..n {
            if a[k] == T::zero() {
                continue;
            }
            let rkk = self.r.m[k][k];
            // |a| ≤ a few, so sqrt(x² + y²) cannot overflow; it is cheaper than hypot
            // on the Cortex-M4F.
            let rho = (rkk * rkk + a[k] * a[k]).fast_sqrt();
            let (c, s) = (rkk / rho, a[k] / rho);
            for j in k..n {
                let (rkj, aj) = (self.r.m[k][j], a[j]);
                self.r.m[k][j] = c * rkj + s * aj;
                a[j] = c * aj - s * rkj;
            }
            let qk = self.qtb[k];
            self.qtb[k] = c * qk + s * b;
            b = c * b - s * qk;
        }
    }

    /// The length of J's column `slot` (the square root of JᵀJ's diagonal entry).
    pub(crate) fn column_norm(&self, slot: usize) -> T {
        (0..=slot.min(self.r.n.saturating_sub(1)))
            .fold(T::zero(), |s, i| s + self.r.m[i][slot] * self.r.m[i][slot])
            .sqrt()
    }

    /// JᵀJ.
    pub fn gram(&self) -> Square<T, MAX_PARAMS> {
        self.r.gram()
    }

    /// Empties the factor for `n` parameters, in place (no n×n temporary).
    pub(crate) fn reset(&mut self, n: usize) {
        for row in self.r.m.iter_mut() {
            row.fill(T::zero());
        }
        self.r.n = n.min(MAX_PARAMS);
        self.qtb.fill(T::zero());
    }

    /// Turns the factor into (JᵀJ)⁻¹ = R⁻¹R⁻ᵀ where it stands and returns it, or `None`
    /// if a pivot is zero (the factor is then left part-inverted). The factor is gone
    /// afterwards: at 61 parameters each n×n matrix is 15 KiB in f32, and the
    /// pendant's stack holds the fit's factor and one more, not a third.
    // A frame of its own: the pendant's fit is stack-measured on target.
    #[inline(never)]
    pub(crate) fn invert_in_place(&mut self) -> Option<&Square<T, MAX_PARAMS>> {
        let n = self.r.n;
        if (0..n).any(|i| self.r.m[i][i] == T::zero()) {
            return None;
        }
        // R⁻¹ row by row from the bottom, each row from the right: an entry reads its
        // own row of R left of where it is written (not yet overwritten) and the rows
        // below, already R⁻¹; the diagonal goes last.
        let m = &mut self.r.m;
        for i in (0..n).rev() {
            for j in ((i + 1)..n).rev() {
                let mut acc = T::zero();
                for k in (i + 1)..=j {
                    acc += m[i][k] * m[k][j];
                }
                m[i][j] = -acc / m[i][i];
            }
            m[i][i] = T::one() / m[i][i];
        }
        self.r.upper_times_own_transpose();
        Some(&self.r)
    }

    /// sqrt(diag((JᵀJ)⁻¹)): the 1σ per parameter for unit reading noise, or `None` if
    /// a pivot is zero.
    ///
    /// The diagonal of R⁻¹R⁻ᵀ is the squared row norms of R⁻¹: each column of R⁻¹ is
    /// solved in turn and its squares added to its rows, so no n×n inverse is held.
    pub(crate) fn unit_sigma(&self) -> Option<[T; MAX_PARAMS]> {
        let n = self.r.n;
        let r = &self.r.m;
        let mut squares = [T::zero(); MAX_PARAMS];
        let mut column = [T::zero(); MAX_PARAMS];
        for col in 0..n {
            for i in (0..=col).rev() {
                let mut acc = if i == col { T::one() } else { T::zero() };
                for j in (i + 1)..=col {
                    acc -= r[i][j] * column[j];
                }
                if r[i][i] == T::zero() {
                    return None;
                }
                column[i] = acc / r[i][i];
                squares[i] += column[i] * column[i];
            }
        }
        for s in squares.iter_mut().take(n) {
            *s = s.sqrt();
        }
        Some(squares)
    }

    /// The least-squares step, optionally damped by λ (Levenberg-Marquardt): with
    /// λ > 0 the damped factor is built in `scratch` (overwritten), so that no n×n
    /// copy lives on this frame.
    pub(crate) fn step(&self, lambda: T, scratch: &mut Self) -> Option<[T; MAX_PARAMS]> {
        if lambda > T::zero() {
            *scratch = *self;
            let sl = lambda.sqrt();
            let mut row = [T::zero(); MAX_PARAMS];
            for k in 0..self.r.n {
                row[k] = sl;
                scratch.add_row(&row, T::zero());
                row[k] = T::zero();
            }
            scratch.back_substitute()
        } else {
            self.back_substitute()
        }
    }

    /// R·x = Qᵀb, or `None` if a pivot is zero.
    pub(crate) fn back_substitute(&self) -> Option<[T; MAX_PARAMS]> {
        let n = self.r.n;
        let mut x = [T::zero(); MAX_PARAMS];
        for i in (0..n).rev() {
            let mut acc = self.qtb[i];
            for j in (i + 1)..n {
                acc -= self.r.m[i][j] * x[j];
            }
            let d = self.r.m[i][i];
            if d == T::zero() {
                return None;
            }
            x[i] = acc / d;
        }
        Some(x)
    }

    /// The condition number of J with its columns scaled to unit length, and J's
    /// weakest direction. Scaling makes the figure independent of the parameters'
    /// units: a cross-axis term's column is a hundred times shorter than an offset's
    /// (its effect grows with the tilt squared), which says nothing about whether the
    /// poses separate it.
    ///
    /// Matrix-free: the largest and smallest eigenvalues of SᵀS (S = R·D⁻¹, D the
    /// column norms) by power and inverse iteration on the triangular factor itself,
    /// O(n²) a step and no n×n copy. A Jacobi SVD of S held three n×n matrices (45 KiB
    /// in f32 at 61 parameters, more than the pendant's stack) and cost O(n³) a sweep.
    // A frame of its own: the pendant's fit is stack-measured on target.
    #[inline(never)]
    pub(crate) fn conditioning(&self) -> Conditioning<T> {
        let n = self.r.n;
        let r = &self.r.m;
        let mut norm = [T::zero(); MAX_PARAMS];
        for (j, nj) in norm.iter_mut().enumerate().take(n) {
            *nj = (0..=j).fold(T::zero(), |s, i| s + r[i][j] * r[i][j]).sqrt();
        }
        let singular = |direction: [T; MAX_PARAMS]| Conditioning {
            condition_number: T::max_value().unwrap_or(T::one() / T::EPSILON),
            weakest_slots: named_components(&direction[..n]),
            weakest_direction: direction,
        };
        // A zero pivot: R (and J) is singular; its null vector is the weakest direction.
        if let Some(k) = (0..n).find(|&k| r[k][k] == T::zero() || norm[k] == T::zero()) {
            let mut w = [T::zero(); MAX_PARAMS];
            w[k] = T::one();
            for i in (0..k).rev() {
                let acc = ((i + 1)..=k).fold(T::zero(), |s, j| s + r[i][j] * w[j]);
                w[i] = -acc / r[i][i];
            }
            // In scaled coordinates z = D·w.
            for (wi, ni) in w.iter_mut().zip(norm.iter()).take(n) {
                *wi *= *ni;
            }
            if !normalise(&mut w, n) {
                w = [T::zero(); MAX_PARAMS];
                w[k] = T::one();
            }
            return singular(w);
        }
        // S·x and Sᵀ·y on the triangle, and (SᵀS)⁻¹·x by two triangular solves, each
        // into a buffer of the caller's (no array is copied a step).
        let mut inverse_norm = [T::zero(); MAX_PARAMS];
        for (v, nj) in inverse_norm.iter_mut().zip(norm.iter()).take(n) {
            *v = T::one() / *nj;
        }
        let s_times = |x: &[T; MAX_PARAMS], y: &mut [T; MAX_PARAMS]| {
            for i in 0..n {
                y[i] = (i..n).fold(T::zero(), |s, j| s + r[i][j] * (x[j] * inverse_norm[j]));
            }
        };
        let st_times = |y: &[T; MAX_PARAMS], x: &mut [T; MAX_PARAMS]| {
            for j in 0..n {
                x[j] = (0..=j).fold(T::zero(), |s, i| s + r[i][j] * y[i]) / norm[j];
            }
        };
        let solve = |x: &[T; MAX_PARAMS], y: &mut [T; MAX_PARAMS], z: &mut [T; MAX_PARAMS]| {
            // Sᵀ·y = x forward, then S·z = y backward (S = R·D⁻¹).
            for j in 0..n {
                let acc = (0..j).fold(x[j] * norm[j], |s, i| s - r[i][j] * y[i]);
                y[j] = acc / r[j][j];
            }
            for i in (0..n).rev() {
                let acc = ((i + 1)..n).fold(y[i], |s, j| s - r[i][j] * z[j]);
                z[i] = acc / r[i][i];
            }
            for j in 0..n {
                z[j] *= norm[j];
            }
        };
        let dot = |a: &[T; MAX_PARAMS], b: &[T; MAX_PARAMS]| {
            (0..n).fold(T::zero(), |s, i| s + a[i] * b[i])
        };
        let mut y = [T::zero(); MAX_PARAMS];
        // Largest eigenvalue of SᵀS: x ← SᵀS·x, its Rayleigh quotient ‖S·x‖² (x unit).
        let mut top = start_vector(n, false);
        let mut next = [T::zero(); MAX_PARAMS];
        let mut largest = T::zero();
        if !normalise(&mut top, n) {
            return singular([T::zero(); MAX_PARAMS]);
        }
        for _ in 0..CONDITIONING_STEPS {
            s_times(&top, &mut y);
            let estimate = dot(&y, &y);
            st_times(&y, &mut next);
            core::mem::swap(&mut top, &mut next);
            let settled = (estimate - largest).abs() <= T::lit(CONDITIONING_SETTLED) * estimate;
            largest = estimate;
            if settled || !normalise(&mut top, n) {
                break;
            }
        }
        // Smallest: x ← (SᵀS)⁻¹·x, its Rayleigh quotient xᵀ(SᵀS)⁻¹x = 1/λ (x unit).
        let mut weakest = start_vector(n, true);
        let mut smallest = T::zero();
        if !normalise(&mut weakest, n) {
            return singular([T::zero(); MAX_PARAMS]);
        }
        for _ in 0..CONDITIONING_STEPS {
            solve(&weakest, &mut y, &mut next);
            let inverse = dot(&weakest, &next);
            core::mem::swap(&mut weakest, &mut next);
            let estimate = T::one() / inverse;
            let settled = (estimate - smallest).abs() <= T::lit(CONDITIONING_SETTLED) * estimate;
            smallest = estimate;
            if !normalise(&mut weakest, n) {
                return singular(next);
            }
            if settled {
                break;
            }
        }
        if !smallest.is_finite() || smallest <= T::zero() || !largest.is_finite() {
            return singular(weakest);
        }
        Conditioning {
            condition_number: (largest / smallest).sqrt(),
            weakest_slots: named_components(&weakest[..n]),
            weakest_direction: weakest,
        }
    }

    /// ‖R‖²: the trace of JᵀJ (the scale of Levenberg-Marquardt's damping).
    pub(crate) fn norm_squared(&self) -> T {
        self.r
            .m
            .iter()
            .take(self.r.n)
            .flat_map(|row| row.iter().take(self.r.n))
            .fold(T::zero(), |s, v| s + *v * *v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::isclose;

    #[test]
    fn givens_factor_reproduces_normal_equations() {
        let mut info = Information::<f64>::new(4);
        let rows = [
            [1.0, 2.0, 0.0, -1.0],
            [0.5, -1.0, 3.0, 0.0],
            [0.0, 0.3, 1.0, 2.0],
            [2.0, 0.0, -1.0, 1.0],
            [1.0, 1.0, 1.0, 1.0],
        ];
        let mut ata = Square::<f64, MAX_PARAMS>::zeros(4);
        for r in rows {
            let mut row = [0.0; MAX_PARAMS];
            row[..4].copy_from_slice(&r);
            ata.add_outer(&row, 1.0);
            info.add_row(&row, 1.0);
        }
        let g = info.gram();
        for i in 0..4 {
            for j in 0..4 {
                // Sums of a few products of O(1) numbers: rounding only.
                assert!(isclose(g.m[i][j], ata.m[i][j], 0.0, 1e-12), "{i} {j}");
            }
        }
    }

    /// A factor of `n` rows drawn from a fixed sequence, some columns nearly
    /// dependent (scaled by `weak`).
    fn sample(n: usize, weak: f64) -> Information<f64> {
        let mut info = Information::<f64>::new(n);
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        for _ in 0..(2 * n + 3) {
            let mut row = [0.0; MAX_PARAMS];
            for v in row.iter_mut().take(n) {
                *v = next();
            }
            // Column 1 nearly follows column 0: the weakest direction is theirs.
            row[1] = row[0] + weak * row[1];
            row[n - 1] *= 100.0;
            info.add_row(&row, 1.0);
        }
        info
    }

    #[test]
    fn conditioning_agrees_with_the_jacobi_svd_of_the_scaled_factor() {
        for (n, weak) in [(4, 0.5), (12, 0.05), (MAX_PARAMS, 0.01), (MAX_PARAMS, 1e-4)] {
            let info = sample(n, weak);
            let mut scaled = info.r;
            for j in 0..n {
                let norm = (0..n).map(|i| scaled.m[i][j].powi(2)).sum::<f64>().sqrt();
                for i in 0..n {
                    scaled.m[i][j] /= norm;
                }
            }
            let reference = svd(&scaled);
            let c = info.conditioning();
            // Iterated to a relative change of 1e-6 in the eigenvalues: the condition
            // number within 1e-4 of the SVD's, far below the one printed digit.
            assert!(
                isclose(c.condition_number, reference.condition_number(), 1e-4, 0.0),
                "n {n}: {} vs {}",
                c.condition_number,
                reference.condition_number()
            );
            let dot: f64 = (0..n)
                .map(|i| c.weakest_direction[i] * reference.weakest[i])
                .sum();
            assert!(
                dot.abs() > 0.999,
                "n {n}: weakest directions differ ({dot})"
            );
            assert!(
                c.weakest_slots & 0b11 == 0b11,
                "n {n}: {:b}",
                c.weakest_slots
            );
        }
    }

    #[test]
    fn a_zero_pivot_is_singular_and_names_its_column() {
        let mut info = Information::<f64>::new(3);
        for row in [[1.0, 2.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]] {
            let mut r = [0.0; MAX_PARAMS];
            r[..3].copy_from_slice(&row);
            info.add_row(&r, 0.0);
        }
        let c = info.conditioning();
        assert!(c.condition_number > 1e30);
        assert_eq!(c.weakest_slots, 0b100);
    }

    #[test]
    fn the_inverse_gram_in_place_is_r_inverse_times_its_transpose() {
        let info = sample(MAX_PARAMS, 0.3);
        let ri = info.r.upper_inverse().unwrap_or_else(|| Square::zeros(0));
        let reference = ri.mul(&ri.transpose());
        let sigma = info.unit_sigma().unwrap_or([0.0; MAX_PARAMS]);
        let mut info = info;
        let inverse = *info.invert_in_place().unwrap_or(&Square::zeros(0));
        assert_eq!(inverse.n, MAX_PARAMS);
        for (i, s) in sigma.iter().enumerate() {
            assert!(isclose(s * s, reference.m[i][i], 1e-9, 0.0), "{i}");
        }
        for i in 0..MAX_PARAMS {
            for j in 0..MAX_PARAMS {
                assert!(
                    isclose(inverse.m[i][j], reference.m[i][j], 1e-9, 1e-12),
                    "{i} {j}"
                );
            }
        }
    }
}
