//! The information of a pose set, J folded into a triangular factor as rows arrive
//! (a streaming QR by Givens rotations), and what it says about separability.
//!
//! J is never stored: any number of poses fits in a few hundred bytes, and the
//! conditioning is that of J, not of JᵀJ, which is what keeps `f32` on the pendant
//! within 2e-5° of `f64` on the desktop.

use crate::error::ParamSet;
use crate::model::WRIST_JOINTS;
use crate::real::Real;
use nalgebra::{Matrix4, SymmetricEigen, Vector4};

/// A parameter whose share of the weakest direction of J exceeds this (as a component
/// of the unit singular vector) is named as part of that direction: 0.3² ≈ 9 % of it.
pub const WEAK_DIRECTION_SHARE: f64 = 0.3;

/// J folded into an upper-triangular factor R (JᵀJ = RᵀR) together with Qᵀ·r.
#[derive(Clone, Copy, Debug)]
pub struct Information<T: Real> {
    pub(crate) r: Matrix4<T>,
    qtb: Vector4<T>,
}

impl<T: Real> Default for Information<T> {
    fn default() -> Self {
        Information {
            r: Matrix4::zeros(),
            qtb: Vector4::zeros(),
        }
    }
}

/// Singular-value summary of J.
pub(crate) struct Conditioning<T> {
    pub(crate) condition_number: T,
    pub(crate) weakest: ParamSet,
}

/// The parameters whose component in a unit direction exceeds
/// [`WEAK_DIRECTION_SHARE`].
fn named_components<T: Real>(component: impl Fn(usize) -> T) -> ParamSet {
    (0..WRIST_JOINTS)
        .filter(|&k| component(k).abs() > T::lit(WEAK_DIRECTION_SHARE))
        .fold(ParamSet::default(), ParamSet::with)
}

/// The parameters along the weakest direction of a Gram matrix JᵀJ (its eigenvector of
/// the smallest eigenvalue): what the planner names when a plan is ill-conditioned,
/// with the same rule as [`Information`]'s check.
pub fn weakest_of_gram<T: Real>(m: &Matrix4<T>) -> ParamSet {
    let Some(eig) = SymmetricEigen::try_new(*m, T::EPSILON, 1000) else {
        return ParamSet::default();
    };
    let imin = (1..WRIST_JOINTS).fold(0, |i, k| {
        if eig.eigenvalues[k] < eig.eigenvalues[i] {
            k
        } else {
            i
        }
    });
    named_components(|k| eig.eigenvectors[(k, imin)])
}

impl<T: Real> Information<T> {
    /// Folds in one row of `J·δ ≈ b` by Givens rotations.
    pub fn add_row(&mut self, mut a: Vector4<T>, mut b: T) {
        for k in 0..WRIST_JOINTS {
            if a[k] == T::zero() {
                continue;
            }
            let rkk = self.r[(k, k)];
            // |u| ≤ a few, so sqrt(x² + y²) cannot overflow; it is cheaper than hypot
            // on the Cortex-M4F.
            let rho = (rkk * rkk + a[k] * a[k]).fast_sqrt();
            let (c, s) = (rkk / rho, a[k] / rho);
            for j in k..WRIST_JOINTS {
                let (rkj, aj) = (self.r[(k, j)], a[j]);
                self.r[(k, j)] = c * rkj + s * aj;
                a[j] = c * aj - s * rkj;
            }
            let qk = self.qtb[k];
            self.qtb[k] = c * qk + s * b;
            b = c * b - s * qk;
        }
    }

    /// JᵀJ.
    pub fn matrix(&self) -> Matrix4<T> {
        self.r.transpose() * self.r
    }

    /// R⁻¹ by back substitution, or `None` if a pivot is zero.
    pub(crate) fn r_inverse(&self) -> Option<Matrix4<T>> {
        let mut inv = Matrix4::zeros();
        for col in 0..WRIST_JOINTS {
            for i in (0..=col).rev() {
                let mut acc = if i == col { T::one() } else { T::zero() };
                for j in (i + 1)..=col {
                    acc -= self.r[(i, j)] * inv[(j, col)];
                }
                let d = self.r[(i, i)];
                if d == T::zero() {
                    return None;
                }
                inv[(i, col)] = acc / d;
            }
        }
        Some(inv)
    }

    /// sqrt(diag((JᵀJ)⁻¹)): the 1σ per parameter for unit reading noise.
    pub(crate) fn unit_sigma(&self) -> Option<[T; WRIST_JOINTS]> {
        let inv = self.r_inverse()?;
        let mut out = [T::zero(); WRIST_JOINTS];
        for (k, o) in out.iter_mut().enumerate() {
            // (JᵀJ)⁻¹ = R⁻¹R⁻ᵀ: its diagonal is the squared row norms of R⁻¹.
            *o = inv.row(k).norm();
        }
        Some(out)
    }

    /// The least-squares step, optionally damped by λ (Levenberg-Marquardt).
    pub(crate) fn step(&self, lambda: T) -> Option<Vector4<T>> {
        let sys = if lambda > T::zero() {
            let mut damped = *self;
            let sl = lambda.sqrt();
            for k in 0..WRIST_JOINTS {
                let mut row = Vector4::zeros();
                row[k] = sl;
                damped.add_row(row, T::zero());
            }
            damped
        } else {
            *self
        };
        let mut x = Vector4::zeros();
        for i in (0..WRIST_JOINTS).rev() {
            let mut acc = sys.qtb[i];
            for j in (i + 1)..WRIST_JOINTS {
                acc -= sys.r[(i, j)] * x[j];
            }
            let d = sys.r[(i, i)];
            if d == T::zero() {
                return None;
            }
            x[i] = acc / d;
        }
        Some(x)
    }

    pub(crate) fn conditioning(&self) -> Conditioning<T> {
        let svd = self.r.svd(false, true);
        let sv = svd.singular_values;
        let (mut imax, mut imin) = (0, 0);
        for k in 1..WRIST_JOINTS {
            if sv[k] > sv[imax] {
                imax = k;
            }
            if sv[k] < sv[imin] {
                imin = k;
            }
        }
        let condition_number = if sv[imin] > T::zero() {
            sv[imax] / sv[imin]
        } else {
            T::max_value().unwrap_or(T::one() / T::EPSILON)
        };
        // The right singular vector of the smallest singular value is the direction
        // in parameter space the data cannot see: name its large components.
        let weakest = svd.v_t.map_or(ParamSet::default(), |vt| {
            named_components(|k| vt[(imin, k)])
        });
        Conditioning {
            condition_number,
            weakest,
        }
    }
}
