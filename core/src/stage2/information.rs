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

    /// JᵀJ.
    pub fn gram(&self) -> Square<T, MAX_PARAMS> {
        self.r.gram()
    }

    /// (JᵀJ)⁻¹ = R⁻¹R⁻ᵀ, or `None` if a pivot is zero.
    // A frame of its own: its square matrices leave the stack when it returns
    // (the pendant's fit is stack-measured on target).
    #[inline(never)]
    pub(crate) fn inverse_gram(&self) -> Option<Square<T, MAX_PARAMS>> {
        let ri = self.r.upper_inverse()?;
        Some(ri.mul(&ri.transpose()))
    }

    /// sqrt(diag((JᵀJ)⁻¹)): the 1σ per parameter for unit reading noise.
    pub(crate) fn unit_sigma(&self) -> Option<[T; MAX_PARAMS]> {
        let ri = self.r.upper_inverse()?;
        let mut out = [T::zero(); MAX_PARAMS];
        for (k, o) in out.iter_mut().enumerate().take(self.r.n) {
            // The diagonal of R⁻¹R⁻ᵀ is the squared row norms of R⁻¹.
            *o = ri.m[k]
                .iter()
                .take(self.r.n)
                .fold(T::zero(), |s, v| s + *v * *v)
                .sqrt();
        }
        Some(out)
    }

    /// The least-squares step, optionally damped by λ (Levenberg-Marquardt).
    // A frame of its own: its square matrices leave the stack when it returns
    // (the pendant's fit is stack-measured on target).
    #[inline(never)]
    pub(crate) fn step(&self, lambda: T) -> Option<[T; MAX_PARAMS]> {
        let n = self.r.n;
        let sys = if lambda > T::zero() {
            let mut damped = *self;
            let sl = lambda.sqrt();
            for k in 0..n {
                let mut row = [T::zero(); MAX_PARAMS];
                row[k] = sl;
                damped.add_row(&row, T::zero());
            }
            damped
        } else {
            *self
        };
        let mut x = [T::zero(); MAX_PARAMS];
        for i in (0..n).rev() {
            let mut acc = sys.qtb[i];
            for j in (i + 1)..n {
                acc -= sys.r.m[i][j] * x[j];
            }
            let d = sys.r.m[i][i];
            if d == T::zero() {
                return None;
            }
            x[i] = acc / d;
        }
        Some(x)
    }

    /// The singular values of R (those of J) with its columns scaled to unit length,
    /// and J's weakest direction. Scaling makes the figure independent of the
    /// parameters' units: a cross-axis term's column is a hundred times shorter than an
    /// offset's (its effect grows with the tilt squared), which says nothing about
    /// whether the poses separate it.
    // A frame of its own: its square matrices leave the stack when it returns
    // (the pendant's fit is stack-measured on target).
    #[inline(never)]
    pub(crate) fn conditioning(&self) -> Conditioning<T> {
        let n = self.r.n;
        let mut scaled = self.r;
        for j in 0..n {
            let norm = (0..n)
                .fold(T::zero(), |s, i| s + self.r.m[i][j] * self.r.m[i][j])
                .sqrt();
            if norm > T::zero() {
                for i in 0..n {
                    scaled.m[i][j] /= norm;
                }
            }
        }
        let s = svd(&scaled);
        let mut weakest_direction = [T::zero(); MAX_PARAMS];
        weakest_direction[..s.n].copy_from_slice(&s.weakest[..s.n]);
        Conditioning {
            condition_number: s.condition_number(),
            weakest_slots: named_components(&s.weakest[..s.n]),
            weakest_direction,
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
}
