//! Iterative refinement of a solve with a symmetric matrix stored as the
//! upper triangle of a [`Pattern`].

use crate::error::Result;
use crate::fem::assembly::Pattern;

/// Normwise backward error of x for K x = rhs below which refinement stops:
/// ~45 ulps. A Cholesky solve is backward stable, so this is normally met at
/// once; refining further in working precision cannot improve the forward
/// error by more than the same small factor. (The relative residual
/// ‖Kx − f‖/‖f‖, reported in `SolveInfo`, is no criterion: it grows with
/// ‖K‖‖x‖/‖f‖, to 1e-10 at 1M unknowns and 1e-5 with a 1e8 stiffness
/// contrast, where refinement only halves it.)
pub const BACKWARD_ERROR_TOL: f64 = 1e-14;

/// Iterative refinement of K x = rhs while the normwise backward error
/// ‖r‖∞ / (‖K‖∞‖x‖∞ + ‖f‖∞) exceeds [`BACKWARD_ERROR_TOL`] and each step at
/// least halves the residual. `solve` applies (an approximation of) K⁻¹ in
/// place. A backward-stable solve costs one product.
pub fn refine(
    pattern: &Pattern,
    values: &[f64],
    rhs: &[f64],
    x: &mut [f64],
    solve: &mut dyn FnMut(&mut [f64]) -> Result<()>,
) -> Result<()> {
    let product = |v: &[f64], y: &mut [f64]| pattern.sym_mul(values, v, y);
    refine_by(&product, norm_inf(pattern, values), rhs, x, solve)
}

/// ‖K‖∞ of the symmetric matrix with upper triangle `values` on `pattern`.
pub fn norm_inf(pattern: &Pattern, values: &[f64]) -> f64 {
    // One n-vector at a time: this runs near the solve's memory peak.
    let mut row_sums = vec![0.0f64; pattern.n()];
    let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
    for j in 0..pattern.n() {
        for p in cp[j]..cp[j + 1] {
            row_sums[ri[p]] += values[p].abs();
            if ri[p] != j {
                row_sums[j] += values[p].abs();
            }
        }
    }
    inf(&row_sums)
}

fn inf(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, a| m.max(a.abs()))
}

/// [`refine`] with K given by its product y = K v and its ‖K‖∞ (which only
/// the stopping test reads).
pub fn refine_by(
    product: &dyn Fn(&[f64], &mut [f64]),
    k_norm: f64,
    rhs: &[f64],
    x: &mut [f64],
    solve: &mut dyn FnMut(&mut [f64]) -> Result<()>,
) -> Result<()> {
    let f_norm = inf(rhs);
    let mut r = vec![0.0; x.len()];
    let mut previous = f64::INFINITY;
    for _ in 0..3 {
        product(x, &mut r);
        r.iter_mut().zip(rhs).for_each(|(k, b)| *k = b - *k);
        let rn = inf(&r);
        let omega = rn / (k_norm * inf(x) + f_norm);
        // (A NaN residual also stops: the finiteness check reports it.)
        if rn.is_nan() || omega.is_nan() || omega <= BACKWARD_ERROR_TOL || rn > 0.5 * previous {
            break;
        }
        previous = rn;
        solve(&mut r)?;
        x.iter_mut().zip(&r).for_each(|(a, d)| *a += d);
    }
    Ok(())
}
