//! Small dense linear algebra on fixed arrays with an active size `n ≤ N`: what the
//! fit and the planner need for a parameter set chosen at run time, without a heap and
//! without nalgebra's generic-dimension bounds.
//!
//! - [`Square`]: an `N×N` array of which the top-left `n×n` block is used.
//! - Cholesky factor, solve, inverse's trace and log-determinant of a symmetric
//!   positive-definite block (the planner's D- and A-optimal criteria).
//! - One-sided Jacobi SVD (Hestenes) of a block: accurate singular values of the
//!   fit's triangular factor, and the direction the data cannot see.

use crate::real::Real;

/// An `N×N` matrix of which `n×n` is used (row-major).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Square<T, const N: usize> {
    /// Entries, `m[row][col]`.
    pub m: [[T; N]; N],
    /// Active size.
    pub n: usize,
}

impl<T: Real, const N: usize> Square<T, N> {
    /// Zeros of active size `n` (clamped to `N`).
    pub fn zeros(n: usize) -> Self {
        Square {
            m: [[T::zero(); N]; N],
            n: n.min(N),
        }
    }

    /// The identity of active size `n`.
    pub fn identity(n: usize) -> Self {
        let mut s = Self::zeros(n);
        for i in 0..s.n {
            s.m[i][i] = T::one();
        }
        s
    }

    /// `self += w·v·vᵀ` on the active block (`v` has at least `n` entries).
    pub fn add_outer(&mut self, v: &[T], w: T) {
        for i in 0..self.n {
            for j in 0..self.n {
                self.m[i][j] += w * v[i] * v[j];
            }
        }
    }

    /// `AᵀA` of an (upper-triangular or any) active block.
    pub fn gram(&self) -> Self {
        let mut g = Self::zeros(self.n);
        for i in 0..self.n {
            for j in 0..self.n {
                let mut acc = T::zero();
                for k in 0..self.n {
                    acc += self.m[k][i] * self.m[k][j];
                }
                g.m[i][j] = acc;
            }
        }
        g
    }

    /// The trace.
    pub fn trace(&self) -> T {
        (0..self.n).fold(T::zero(), |a, i| a + self.m[i][i])
    }

    /// `A·B` of two blocks of the same size.
    pub fn mul(&self, b: &Self) -> Self {
        let mut out = Self::zeros(self.n);
        for i in 0..self.n {
            for j in 0..self.n {
                let mut acc = T::zero();
                for k in 0..self.n {
                    acc += self.m[i][k] * b.m[k][j];
                }
                out.m[i][j] = acc;
            }
        }
        out
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        let mut out = Self::zeros(self.n);
        for i in 0..self.n {
            for j in 0..self.n {
                out.m[i][j] = self.m[j][i];
            }
        }
        out
    }

    /// Lower Cholesky factor `L` (`A = L·Lᵀ`) of a symmetric block, or `None` if it is
    /// not positive definite (to rounding).
    pub fn cholesky(&self) -> Option<Self> {
        let mut l = Self::zeros(self.n);
        for j in 0..self.n {
            let mut d = self.m[j][j];
            for k in 0..j {
                d -= l.m[j][k] * l.m[j][k];
            }
            if d <= T::zero() || !d.is_finite() {
                return None;
            }
            let djj = d.sqrt();
            l.m[j][j] = djj;
            for i in (j + 1)..self.n {
                let mut s = self.m[i][j];
                for k in 0..j {
                    s -= l.m[i][k] * l.m[j][k];
                }
                l.m[i][j] = s / djj;
            }
        }
        Some(l)
    }

    /// `U·Uᵀ` of an upper-triangular block, in place: the product's strict lower
    /// triangle goes where U has zeros, then the diagonal (each reads only its own
    /// row), then the mirror. The fit's covariance at 61 parameters is a 15 KiB
    /// matrix in f32: a product and a transpose beside it were two more.
    pub fn upper_times_own_transpose(&mut self) {
        let n = self.n;
        for i in 0..n {
            for j in (i + 1)..n {
                let mut acc = T::zero();
                for k in j..n {
                    acc += self.m[i][k] * self.m[j][k];
                }
                self.m[j][i] = acc;
            }
        }
        for i in 0..n {
            let mut acc = T::zero();
            for k in i..n {
                acc += self.m[i][k] * self.m[i][k];
            }
            self.m[i][i] = acc;
        }
        for i in 0..n {
            for j in (i + 1)..n {
                self.m[i][j] = self.m[j][i];
            }
        }
    }

    /// Inverse of an upper-triangular block by back substitution, `None` if a pivot is
    /// zero.
    pub fn upper_inverse(&self) -> Option<Self> {
        let mut inv = Self::zeros(self.n);
        for col in 0..self.n {
            for i in (0..=col).rev() {
                let mut acc = if i == col { T::one() } else { T::zero() };
                for j in (i + 1)..=col {
                    acc -= self.m[i][j] * inv.m[j][col];
                }
                let d = self.m[i][i];
                if d == T::zero() {
                    return None;
                }
                inv.m[i][col] = acc / d;
            }
        }
        Some(inv)
    }
}

/// `A⁻¹` and `log det A` of a symmetric positive-definite block, from its Cholesky
/// factor (`A⁻¹ = L⁻ᵀ·L⁻¹`), or `None` if it is not positive definite.
pub fn spd_inverse<T: Real, const N: usize>(a: &Square<T, N>) -> Option<(Square<T, N>, T)> {
    let l = a.cholesky()?;
    let log_det = (0..l.n).fold(T::zero(), |s, i| s + T::lit(2.0) * l.m[i][i].ln());
    let li = l.transpose().upper_inverse()?;
    Some((li.mul(&li.transpose()), log_det))
}

/// `log det A` of a symmetric positive-definite block, from its Cholesky factor.
pub fn log_det<T: Real, const N: usize>(a: &Square<T, N>) -> Option<T> {
    let l = a.cholesky()?;
    Some((0..l.n).fold(T::zero(), |s, i| s + T::lit(2.0) * l.m[i][i].ln()))
}

/// The diagonal of `A⁻¹` for a symmetric positive-definite block: `(A⁻¹)ₖₖ = ‖L⁻¹eₖ‖²`
/// with `A = L·Lᵀ`.
pub fn inverse_diagonal<T: Real, const N: usize>(a: &Square<T, N>) -> Option<[T; N]> {
    let l = a.cholesky()?;
    let n = l.n;
    let mut out = [T::zero(); N];
    for (col, o) in out.iter_mut().enumerate().take(n) {
        // Forward substitution of L·x = e_col.
        let mut x = [T::zero(); N];
        for i in col..n {
            let mut acc = if i == col { T::one() } else { T::zero() };
            for (k, xk) in x.iter().enumerate().take(i).skip(col) {
                acc -= l.m[i][k] * *xk;
            }
            x[i] = acc / l.m[i][i];
        }
        *o = x.iter().take(n).fold(T::zero(), |s, v| s + *v * *v);
    }
    Some(out)
}

/// `trace A⁻¹` of a symmetric positive-definite block.
pub fn trace_inverse<T: Real, const N: usize>(a: &Square<T, N>) -> Option<T> {
    let d = inverse_diagonal(a)?;
    Some(d.iter().take(a.n).fold(T::zero(), |s, v| s + *v))
}

/// Singular values of a block and the right singular vector of the smallest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Svd<T, const N: usize> {
    /// Singular values (unsorted), first `n`.
    pub values: [T; N],
    /// The unit right singular vector of the smallest singular value, first `n`.
    pub weakest: [T; N],
    /// Active size.
    pub n: usize,
}

impl<T: Real, const N: usize> Svd<T, N> {
    /// Largest over smallest singular value; the largest float if the smallest is 0.
    pub fn condition_number(&self) -> T {
        let (lo, hi) = self.values[..self.n].iter().fold(
            (T::max_value().unwrap_or(T::one() / T::EPSILON), T::zero()),
            |(lo, hi), &v| (lo.min(v), hi.max(v)),
        );
        if lo > T::zero() {
            hi / lo
        } else {
            T::max_value().unwrap_or(T::one() / T::EPSILON)
        }
    }
}

/// One-sided Jacobi (Hestenes) SVD of the active block: columns are rotated pairwise
/// until orthogonal; their norms are the singular values, the accumulated rotations
/// the right singular vectors. Accurate to rounding for the small matrices here.
pub fn svd<T: Real, const N: usize>(a: &Square<T, N>) -> Svd<T, N> {
    let n = a.n;
    let mut u = a.m;
    let mut v = Square::<T, N>::identity(n).m;
    // Columns are orthogonal to working precision within a few sweeps; 40 only stops
    // a pathological input.
    for _ in 0..40 {
        let mut rotated = false;
        for i in 0..n {
            for j in (i + 1)..n {
                let (mut alpha, mut beta, mut gamma) = (T::zero(), T::zero(), T::zero());
                for row in u.iter().take(n) {
                    alpha += row[i] * row[i];
                    beta += row[j] * row[j];
                    gamma += row[i] * row[j];
                }
                if gamma == T::zero() || gamma.abs() <= T::EPSILON * (alpha * beta).sqrt() {
                    continue;
                }
                rotated = true;
                let zeta = (beta - alpha) / (T::lit(2.0) * gamma);
                let t = zeta.signum() / (zeta.abs() + (T::one() + zeta * zeta).sqrt());
                let c = T::one() / (T::one() + t * t).sqrt();
                let s = c * t;
                for row in u.iter_mut().take(n) {
                    let (x, y) = (row[i], row[j]);
                    row[i] = c * x - s * y;
                    row[j] = s * x + c * y;
                }
                for row in v.iter_mut().take(n) {
                    let (x, y) = (row[i], row[j]);
                    row[i] = c * x - s * y;
                    row[j] = s * x + c * y;
                }
            }
        }
        if !rotated {
            break;
        }
    }
    let mut values = [T::zero(); N];
    for (j, value) in values.iter_mut().enumerate().take(n) {
        *value = u
            .iter()
            .take(n)
            .fold(T::zero(), |s, row| s + row[j] * row[j])
            .sqrt();
    }
    let imin = (0..n).fold(0, |m, j| if values[j] < values[m] { j } else { m });
    let mut weakest = [T::zero(); N];
    for (w, row) in weakest.iter_mut().zip(v.iter()).take(n) {
        *w = row[imin];
    }
    Svd { values, weakest, n }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::isclose;

    fn sample() -> Square<f64, 6> {
        let mut a = Square::zeros(3);
        a.m[0][..3].copy_from_slice(&[4.0, 1.0, 0.5]);
        a.m[1][..3].copy_from_slice(&[1.0, 3.0, 0.2]);
        a.m[2][..3].copy_from_slice(&[0.5, 0.2, 2.0]);
        a
    }

    #[test]
    fn cholesky_and_its_criteria_match_nalgebra() {
        let a = sample();
        let m = nalgebra::Matrix3::from_fn(|i, j| a.m[i][j]);
        let inv = m.try_inverse().unwrap();
        // Both in f64 on a well-conditioned 3×3: rounding only.
        assert!(isclose(trace_inverse(&a).unwrap(), inv.trace(), 1e-13, 0.0));
        assert!(isclose(
            log_det(&a).unwrap(),
            m.determinant().ln(),
            1e-13,
            0.0
        ));
        let l = a.cholesky().unwrap();
        let back = l.mul(&l.transpose());
        for i in 0..3 {
            for j in 0..3 {
                assert!(isclose(back.m[i][j], a.m[i][j], 0.0, 1e-14));
            }
        }
        let mut not_pd = a;
        not_pd.m[2][2] = -1.0;
        assert!(not_pd.cholesky().is_none());
    }

    #[test]
    fn jacobi_svd_matches_nalgebra_and_finds_the_null_direction() {
        let a = sample();
        let m = nalgebra::Matrix3::from_fn(|i, j| a.m[i][j]);
        let mut want: Vec<f64> = m
            .svd(false, false)
            .singular_values
            .iter()
            .copied()
            .collect();
        let s = svd(&a);
        let mut got: Vec<f64> = s.values[..3].to_vec();
        want.sort_by(f64::total_cmp);
        got.sort_by(f64::total_cmp);
        for (g, w) in got.iter().zip(&want) {
            assert!(isclose(*g, *w, 1e-13, 0.0), "{got:?} {want:?}");
        }
        // Columns 0 and 2 equal: the null direction is (1, 0, −1)/√2.
        let mut b = Square::<f64, 6>::zeros(3);
        for (i, row) in [[1.0, 2.0, 1.0], [0.0, 1.0, 0.0], [3.0, 0.5, 3.0]]
            .iter()
            .enumerate()
        {
            b.m[i][..3].copy_from_slice(row);
        }
        let s = svd(&b);
        assert!(s.condition_number() > 1e12);
        let w = s.weakest;
        assert!(isclose(w[0].abs(), 0.5f64.sqrt(), 0.0, 1e-12) && w[1].abs() < 1e-12);
        assert!(isclose(w[0], -w[2], 0.0, 1e-12));
    }
}
