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

/// How long a refinement goes on: at most `steps` corrections, each of
/// which must shrink the residual by `contraction` at least.
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    /// The most corrections.
    pub steps: usize,
    /// The factor each correction must shrink the residual by, or stop.
    pub contraction: f64,
}

impl Budget {
    /// For a backward-stable solve (a Cholesky factor of K itself): met at
    /// once, normally; a correction that does not halve the residual is at
    /// the round-off floor.
    pub const DIRECT: Budget = Budget {
        steps: 3,
        contraction: 0.5,
    };
    /// For an approximate inverse of K (the condensed interface: K₁'s
    /// factor and a dense interface solve, whose penalties may make it
    /// lose most of its digits): each correction gains what the
    /// approximation is worth, which was measured to shrink the residual by
    /// 0.01 to 0.54 per step (Hertz, cylinder mesh 10× finer, h = a/32:
    /// nine corrections from 3e-8 to 4e-15).
    pub const APPROXIMATE: Budget = Budget {
        steps: 20,
        contraction: 0.9,
    };
}

/// Iterative refinement of K x = rhs while the normwise backward error
/// ‖r‖∞ / (‖K‖∞‖x‖∞ + ‖f‖∞) exceeds [`BACKWARD_ERROR_TOL`] and each step at
/// least halves the residual ([`Budget::DIRECT`]). `solve` applies (an
/// approximation of) K⁻¹ in place. A backward-stable solve costs one
/// product.
pub fn refine(
    pattern: &Pattern,
    values: &[f64],
    rhs: &[f64],
    x: &mut [f64],
    solve: &mut dyn FnMut(&mut [f64]) -> Result<()>,
) -> Result<()> {
    let product = |v: &[f64], y: &mut [f64]| pattern.sym_mul(values, v, y);
    refine_by(
        &product,
        norm_inf(pattern, values),
        rhs,
        x,
        solve,
        Budget::DIRECT,
    )?;
    Ok(())
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
/// the stopping test reads), within `budget`. Gives the backward error of
/// the refined x (0 for a zero residual; NaN for a non-finite one, which
/// the finiteness check reports).
pub fn refine_by(
    product: &dyn Fn(&[f64], &mut [f64]),
    k_norm: f64,
    rhs: &[f64],
    x: &mut [f64],
    solve: &mut dyn FnMut(&mut [f64]) -> Result<()>,
    budget: Budget,
) -> Result<f64> {
    let f_norm = inf(rhs);
    let mut r = vec![0.0; x.len()];
    let mut previous = f64::INFINITY;
    let mut step = 0;
    loop {
        product(x, &mut r);
        r.iter_mut().zip(rhs).for_each(|(k, b)| *k = b - *k);
        let rn = inf(&r);
        if rn == 0.0 {
            // Solved exactly (a zero field for a zero right-hand side too,
            // where the ratio below would be 0/0).
            return Ok(0.0);
        }
        let omega = rn / (k_norm * inf(x) + f_norm);
        if rn.is_nan() || omega.is_nan() {
            return Ok(f64::NAN);
        }
        if omega <= BACKWARD_ERROR_TOL || rn > budget.contraction * previous || step == budget.steps
        {
            return Ok(omega);
        }
        previous = rn;
        solve(&mut r)?;
        x.iter_mut().zip(&r).for_each(|(a, d)| *a += d);
        step += 1;
    }
}
