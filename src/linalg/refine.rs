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

/// ‖v‖∞, NaN if any entry is (`f64::max` would pass over it, and a NaN
/// residual would read as zero).
fn inf(v: &[f64]) -> f64 {
    v.iter()
        .try_fold(0.0f64, |m, a| (!a.is_nan()).then(|| m.max(a.abs())))
        .unwrap_or(f64::NAN)
}

/// [`refine`] with K given by its product y = K v and its ‖K‖∞ (which only
/// the stopping test reads), within `budget`. Gives the backward error of
/// the refined x (0 for a zero residual; NaN for a non-finite one, which
/// the finiteness check reports). A correction that does not leave a
/// smaller residual (larger, or not finite) is taken back: with an
/// approximate inverse a step can diverge (measured: ×19 on a load step's
/// field, Hertz with the cylinder's mesh 40× finer), and x is left at the
/// best iterate.
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
    // The iterate before the last correction, to go back to (a copy, as
    // x − correction is not x again when the correction is huge).
    let mut best: Vec<f64> = Vec::new();
    let (mut previous, mut previous_omega) = (f64::INFINITY, f64::NAN);
    let mut step = 0;
    loop {
        product(x, &mut r);
        r.iter_mut().zip(rhs).for_each(|(k, b)| *k = b - *k);
        let rn = inf(&r);
        // (rn is NaN when the correction was not finite.)
        if step > 0 && (rn > previous || rn.is_nan()) {
            x.copy_from_slice(&best);
            return Ok(previous_omega);
        }
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
        (previous, previous_omega) = (rn, omega);
        solve(&mut r)?;
        best.clear();
        best.extend_from_slice(x);
        x.iter_mut().zip(&r).for_each(|(a, d)| *a += d);
        step += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K = diag(1, 2, 4) and its product.
    fn product(v: &[f64], y: &mut [f64]) {
        y.iter_mut()
            .zip(v)
            .zip([1.0, 2.0, 4.0])
            .for_each(|((y, v), k)| *y = k * v);
    }

    const RHS: [f64; 3] = [1.0, 2.0, 4.0];

    #[test]
    fn an_exact_inverse_is_met_at_once() {
        let mut x = [0.0; 3];
        let mut solve = |r: &mut [f64]| {
            r.iter_mut().zip([1.0, 2.0, 4.0]).for_each(|(r, k)| *r /= k);
            Ok(())
        };
        let omega = refine_by(&product, 4.0, &RHS, &mut x, &mut solve, Budget::DIRECT).unwrap();
        assert_eq!(x, [1.0; 3]);
        assert_eq!(omega, 0.0);
    }

    #[test]
    fn an_approximate_inverse_converges_within_its_budget() {
        // Each correction is 0.7 of the exact one: the residual shrinks by
        // 0.3 per step, which the direct budget (½) would also take, but
        // in three steps only.
        let mut solve = |r: &mut [f64]| {
            r.iter_mut()
                .zip([1.0, 2.0, 4.0])
                .for_each(|(r, k)| *r *= 0.7 / k);
            Ok(())
        };
        let mut x = [0.0; 3];
        let direct = refine_by(&product, 4.0, &RHS, &mut x, &mut solve, Budget::DIRECT).unwrap();
        assert!(direct > 1e-3, "three steps reach 0.3³: {direct:e}");
        let mut x = [0.0; 3];
        let omega =
            refine_by(&product, 4.0, &RHS, &mut x, &mut solve, Budget::APPROXIMATE).unwrap();
        assert!(omega < 1e-9, "twenty steps reach 0.3²⁰: {omega:e}");
    }

    /// Refines from x = 0 with corrections `gain[i]` times the exact one
    /// at the i-th step; gives x and the backward error.
    fn refined_with(gains: &[f64]) -> ([f64; 3], f64) {
        let mut calls = 0;
        let mut solve = |r: &mut [f64]| {
            let gain = gains[calls];
            calls += 1;
            r.iter_mut()
                .zip([1.0, 2.0, 4.0])
                .for_each(|(r, k)| *r *= gain / k);
            Ok(())
        };
        let mut x = [0.0; 3];
        let omega =
            refine_by(&product, 4.0, &RHS, &mut x, &mut solve, Budget::APPROXIMATE).unwrap();
        (x, omega)
    }

    #[test]
    fn a_correction_that_makes_the_residual_larger_is_taken_back() {
        // A first correction that gets x to 0.3, then one that overshoots
        // by a factor of 20, or so far that x − correction is not x.
        for overshoot in [20.0, 1e17, 1e300] {
            let (x, omega) = refined_with(&[0.3, overshoot]);
            assert_eq!(x, [0.3; 3], "the first correction's iterate");
            // Residual 0.7 × (1, 2, 4) against ‖K‖ ‖x‖ + ‖f‖ = 4 × 0.3 + 4.
            assert_eq!(omega, 0.7 * 4.0 / (4.0 * 0.3 + 4.0));
        }
    }

    #[test]
    fn a_correction_that_is_not_finite_is_taken_back() {
        for bad in [f64::NAN, f64::INFINITY] {
            let (x, omega) = refined_with(&[0.3, bad]);
            assert_eq!(x, [0.3; 3]);
            assert_eq!(omega, 0.7 * 4.0 / (4.0 * 0.3 + 4.0));
        }
    }

    #[test]
    fn a_residual_that_is_not_finite_reads_as_nan_not_as_solved() {
        let mut x = [f64::NAN, 1.0, 1.0];
        let mut solve = |_: &mut [f64]| Ok(());
        let omega = refine_by(&product, 4.0, &RHS, &mut x, &mut solve, Budget::DIRECT).unwrap();
        assert!(omega.is_nan());
    }
}
