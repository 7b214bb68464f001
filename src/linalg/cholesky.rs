//! Sparse Cholesky (faer) with the symbolic analysis kept for reuse,
//! symmetric diagonal (Jacobi) scaling, and detection of singular systems.
//!
//! The scaling is implicit: faer factorises K itself, K = LLᵀ, and the
//! factor of the scaled matrix S = DKD is DL (Cholesky commutes with
//! diagonal scaling up to rounding, exactly for powers of two), so
//! quantities of S are read off L without a scaled copy of the matrix
//! (80 MB at 1M unknowns).
//!
//! A stiffness matrix with an unrestrained rigid-body mode is singular in
//! exact arithmetic but, in floating point, its Cholesky factorisation may
//! succeed with a pivot of round-off size and return a huge, meaningless
//! solution. So after every factorisation a few steps of inverse iteration
//! bound the smallest eigenvalue of the scaled matrix from above; below
//! [`SINGULAR_TOL`] the system is declared singular and the near-null
//! vector tells the caller which unknowns (hence which body) are free.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, LltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
    factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, Mat, MatMut, Par, Side};

use std::sync::{Mutex, PoisonError};

use faer::perm::PermRef;

use super::ordering::{Graph, Ordering, nested_dissection, split_in_two};
use super::packed::packed_start;
use super::split::SplitCholesky;
use crate::error::{Error, Result, Status};
use crate::fem::assembly::Pattern;

/// Smallest eigenvalue of the Jacobi-scaled matrix (unit diagonal) below
/// which the system is declared singular. A rigid-body mode gives ~1e-16;
/// a legitimate stiffness matrix at 4M DOFs with a 1e9 stiffness contrast
/// stays above ~1e-11 after scaling.
pub const SINGULAR_TOL: f64 = 1e-12;

const INVERSE_ITERATIONS: usize = 3;

/// Why a factorisation failed.
#[derive(Debug, Clone)]
pub enum FactorError {
    /// The scaled matrix is (numerically) singular or indefinite; the vector
    /// (over unknowns) is the near-null mode, when one could be computed.
    Singular {
        /// Upper bound of the smallest eigenvalue of the scaled matrix.
        eigenvalue: f64,
        /// Near-null vector over the unknowns, if computed.
        mode: Option<Vec<f64>>,
        /// The factorisation itself succeeded: if the caller finds the mode
        /// restrained after all (an extreme but legitimate stiffness
        /// contrast), [`Cholesky::accept_ill_conditioned`] makes it usable.
        usable: bool,
    },
    /// An unknown has no stiffness at all (zero or negative diagonal).
    ZeroDiagonal {
        /// The unknown.
        unknown: usize,
    },
    /// Another error (memory).
    Other(Error),
}

/// What a symbolic analysis ([`Cholesky::analyse`]) is asked for.
#[derive(Debug, Clone, Copy)]
pub struct AnalyseParams<'a> {
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// One point per unknown, for nested dissection (`None`: AMD only).
    pub coords: Option<Points<'a>>,
    /// Unknowns numbered last, in this order (their Schur complement is
    /// then the trailing block of the factor).
    pub last: &'a [usize],
    /// Positions of the pattern's values that are zero in every matrix to
    /// be factorised.
    pub zeros: &'a [usize],
    /// Factorise the two subtrees of a nested dissection concurrently.
    pub parallel_subtrees: bool,
}

/// One point per unknown, in the plane or in space: where geometric
/// nested dissection cuts.
#[derive(Debug, Clone, Copy)]
pub enum Points<'a> {
    /// Triangles' unknowns.
    Plane(&'a [[f64; 2]]),
    /// Tetrahedra's unknowns.
    Space(&'a [[f64; 3]]),
}

impl Points<'_> {
    /// Nested dissection of the graph (`col_ptr`, `row_idx`: an upper
    /// triangle) whose vertex k is the point `subset[k]` (all, in order,
    /// when `subset` is `None`).
    fn dissect(self, col_ptr: &[usize], row_idx: &[usize], subset: Option<&[usize]>) -> Vec<usize> {
        fn cut<const D: usize>(
            col_ptr: &[usize],
            row_idx: &[usize],
            p: &[[f64; D]],
            subset: Option<&[usize]>,
        ) -> Vec<usize> {
            match subset {
                Some(s) => {
                    let picked: Vec<[f64; D]> = s.iter().map(|&i| p[i]).collect();
                    nested_dissection(col_ptr, row_idx, &picked)
                }
                None => nested_dissection(col_ptr, row_idx, p),
            }
        }
        match self {
            Points::Plane(p) => cut(col_ptr, row_idx, p, subset),
            Points::Space(p) => cut(col_ptr, row_idx, p, subset),
        }
    }
}

impl Default for AnalyseParams<'_> {
    /// AMD (no coordinates), nothing numbered last, no known zeros, one
    /// tree.
    fn default() -> Self {
        AnalyseParams {
            ordering: Ordering::Amd,
            coords: None,
            last: &[],
            zeros: &[],
            parallel_subtrees: false,
        }
    }
}

/// A reusable Cholesky solver for one sparsity pattern.
pub struct Cholesky {
    engine: Engine,
    scale: Vec<f64>,
    factored: bool,
    usable: bool,
    min_eigenvalue: f64,
    max_eigenvalue_bound: f64,
    n_last: usize,
}

fn oom(what: &str) -> Error {
    Error::new(
        Status::OutOfMemory,
        format!("cannot allocate the {what} of the factorisation"),
    )
}

/// The factorisation proper, in one piece or split at the top of the
/// elimination tree.
enum Engine {
    Whole(Box<Whole>),
    Split(Box<SplitCholesky>),
}

/// One faer factorisation of the whole matrix.
struct Whole {
    symbolic: SymbolicCholesky<usize>,
    l_values: Vec<f64>,
    factor_req: faer::dyn_stack::StackReq,
    /// The solve workspace (behind a lock, so that solves take `&self`).
    solve_mem: Mutex<MemBuffer>,
    solve_bytes: usize,
    par: Par,
}

/// Unknown count from which a nested-dissection factorisation is split
/// into two concurrent subtrees (below it the whole factorisation takes
/// milliseconds).
const SPLIT_MIN: usize = 20_000;

impl Cholesky {
    /// Symbolic analysis of `pattern` as `params` asks
    /// ([`AnalyseParams`]): a fill-reducing ordering, AMD, or
    /// geometric nested dissection when `coords` (one point per unknown)
    /// are given and `ordering` asks for it. The unknowns in `last` are
    /// numbered last, in that order, so that the trailing block of the
    /// factor is the Cholesky factor of their Schur complement (see
    /// [`Cholesky::last_block_factor`]); the others are ordered as asked.
    ///
    /// With `parallel_subtrees`, nested dissection in the plane, at least
    /// 20 000 unknowns and two threads or more, the factorisation is split
    /// at the top of the elimination tree: the two subtrees are factorised
    /// concurrently and the separator (with `last`) as a dense block.
    ///
    /// `zeros` lists positions in the pattern's values that hold zero in
    /// every matrix to be factorised (stored only because the pattern is
    /// built node by node): the split may then treat those unknowns as
    /// uncoupled, and its [`Cholesky::factorize`] fails on a matrix where
    /// one of them is not zero.
    pub fn analyse(pattern: &Pattern, params: &AnalyseParams<'_>) -> Result<Cholesky> {
        let AnalyseParams {
            ordering,
            coords,
            last,
            zeros,
            parallel_subtrees,
        } = *params;
        let n = pattern.n();
        if let Some(&p) = zeros.iter().find(|&&p| p >= pattern.nnz()) {
            return Err(Error::argument(format!(
                "zero position {p} is outside the pattern ({} entries)",
                pattern.nnz()
            )));
        }
        let split = match coords {
            // The split cuts the plane only.
            Some(Points::Plane(c))
                if parallel_subtrees
                    && n >= SPLIT_MIN
                    && ordering.use_nested_dissection(n - last.len())
                    && rayon::current_num_threads() >= 2 =>
            {
                analyse_split(pattern, c, last, zeros)?
            }
            _ => None,
        };
        let engine = match split {
            Some(mut split) => {
                // The Schur complement the split forms is then that of
                // `last`, which the condensation would otherwise rebuild.
                if !last.is_empty() && split.top().len() == last.len() {
                    split.keep_schur();
                }
                Engine::Split(Box::new(split))
            }
            None => Engine::Whole(Box::new(Whole::analyse(pattern, ordering, coords, last)?)),
        };
        Ok(Cholesky {
            engine,
            scale: vec![0.0; n],
            factored: false,
            usable: false,
            min_eigenvalue: f64::NAN,
            max_eigenvalue_bound: f64::NAN,
            n_last: last.len(),
        })
    }

    /// Symbolic analysis of `pattern` with a given fill-reducing
    /// permutation (`perm[new] = old`), as a caller with its own ordering
    /// (the 3D studies' nested dissection) needs; one tree, nothing
    /// numbered last. An invalid permutation is refused.
    pub fn analyse_ordered(pattern: &Pattern, perm: Vec<usize>) -> Result<Cholesky> {
        let n = pattern.n();
        let mut seen = vec![false; n];
        if perm.len() != n
            || perm
                .iter()
                .any(|&p| p >= n || std::mem::replace(&mut seen[p], true))
        {
            return Err(Error::argument(format!(
                "the ordering is not a permutation of the {n} unknowns"
            )));
        }
        Ok(Cholesky {
            engine: Engine::Whole(Box::new(Whole::with_permutation(pattern, Some(perm))?)),
            scale: vec![0.0; n],
            factored: false,
            usable: false,
            min_eigenvalue: f64::NAN,
            max_eigenvalue_bound: f64::NAN,
            n_last: 0,
        })
    }

    /// Whether the factorisation is split into two concurrent subtrees.
    pub fn is_split(&self) -> bool {
        matches!(self.engine, Engine::Split(_))
    }

    /// The Jacobi scaling s of the last factorisation: the factor is that of
    /// diag(s) K diag(s), which has a unit diagonal.
    pub fn scale(&self) -> &[f64] {
        &self.scale
    }

    /// The trailing diagonal block L₂₂ of the factor of the scaled matrix
    /// (dense, lower triangular), over the unknowns given as `last` to
    /// [`Cholesky::analyse`], in that order. With K = [K₁₁ K₁₂; K₂₁ K₂₂]
    /// (the `last` unknowns second), L₂₂L₂₂ᵀ = diag(s₂) S diag(s₂) where
    /// S = K₂₂ − K₂₁K₁₁⁻¹K₁₂ is their Schur complement: the exact condensed
    /// stiffness, for free, from the factorisation already paid for.
    /// Requires a successful [`Cholesky::factorize`].
    pub fn last_block_factor(&self) -> Result<Mat<f64>> {
        if !self.factored {
            return Err(Error::state("no successful factorisation to read"));
        }
        let m = self.n_last;
        match &self.engine {
            Engine::Whole(w) => Ok(w.last_block_factor(m, &self.scale)),
            Engine::Split(sp) => {
                let top = sp.top();
                let first = top.len() - m;
                let f = sp.top_factor();
                // DL is the factor of DKD: rows scaled by s.
                Ok(Mat::from_fn(m, m, |i, j| {
                    if i >= j {
                        self.scale[top[first + i]] * f[(first + i, first + j)]
                    } else {
                        0.0
                    }
                }))
            }
        }
    }

    /// The Schur complement S of the `last` unknowns (see
    /// [`Cholesky::last_block_factor`]) of the last successful
    /// factorisation, scaled (diag(s₂) S diag(s₂)), its lower triangle
    /// packed by columns (column j holds rows j.., from
    /// [`packed_start`]`(m, j)`), when the factorisation formed it anyway:
    /// a split one whose separator is exactly those unknowns (two bodies
    /// meeting at the contact interface). Taken out: a second call returns
    /// `None`.
    pub fn take_last_schur(&mut self) -> Option<Vec<f64>> {
        let Engine::Split(sp) = &mut self.engine else {
            return None;
        };
        if !self.factored || self.n_last == 0 || sp.top().len() != self.n_last {
            return None;
        }
        let mut s = sp.take_schur()?;
        let d: Vec<f64> = sp.top().iter().map(|&u| self.scale[u]).collect();
        let t = d.len();
        for j in 0..t {
            let start = packed_start(t, j);
            for (i, v) in (j..t).zip(&mut s[start..start + t - j]) {
                *v *= d[i] * d[j];
            }
        }
        Some(s)
    }

    /// Number of unknowns.
    pub fn n(&self) -> usize {
        self.scale.len()
    }

    /// Stored entries of the Cholesky factor.
    pub fn factor_nnz(&self) -> usize {
        match &self.engine {
            Engine::Whole(w) => w.l_values.len(),
            Engine::Split(sp) => sp.factor_nnz(),
        }
    }

    /// Bytes held by the factor, the scaling and the solve workspace.
    pub fn memory_bytes(&self) -> usize {
        8 * self.scale.len()
            + match &self.engine {
                Engine::Whole(w) => 8 * w.l_values.len() + w.solve_bytes,
                Engine::Split(sp) => sp.memory_bytes(),
            }
    }

    /// Bytes the numeric factorisation needs at its peak: the factor, the
    /// symbolic structure and the workspace (which exists only during a
    /// factorisation), not counting the matrix it reads (but counting the
    /// copies a split factorisation makes of it).
    pub fn factorization_bytes(&self) -> usize {
        match &self.engine {
            Engine::Whole(w) => w.factorization_bytes(),
            Engine::Split(sp) => sp.factorization_bytes(),
        }
    }

    /// Upper bound of the smallest eigenvalue of the scaled matrix, from the
    /// last successful factorisation.
    pub fn min_eigenvalue_estimate(&self) -> f64 {
        self.min_eigenvalue
    }

    /// Condition number estimate of the scaled matrix: a Gershgorin bound of
    /// the largest eigenvalue over the inverse-iteration estimate of the
    /// smallest. It is a lower bound of the true condition number up to the
    /// Gershgorin factor (at most the row count).
    pub fn condition_estimate(&self) -> f64 {
        self.max_eigenvalue_bound / self.min_eigenvalue
    }

    /// Numeric factorisation of the symmetric matrix with upper triangle
    /// `values` on the analysed pattern.
    pub fn factorize(
        &mut self,
        pattern: &Pattern,
        values: &[f64],
    ) -> std::result::Result<(), FactorError> {
        self.factored = false;
        self.usable = false;
        let n = pattern.n();
        let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
        for j in 0..n {
            let last = cp[j + 1] - 1;
            let d = values[last];
            debug_assert_eq!(ri[last], j);
            if !(d > 0.0 && d.is_finite()) {
                return Err(FactorError::ZeroDiagonal { unknown: j });
            }
            self.scale[j] = 1.0 / d.sqrt();
        }
        let mut row_sum = vec![0.0; n];
        for j in 0..n {
            for p in cp[j]..cp[j + 1] {
                let i = ri[p];
                let a = values[p] * self.scale[i] * self.scale[j];
                row_sum[i] += a.abs();
                if i != j {
                    row_sum[j] += a.abs();
                }
            }
        }
        self.max_eigenvalue_bound = row_sum.iter().cloned().fold(0.0, f64::max);
        drop(row_sum);
        match self.factor_shifted(pattern, values, 0.0)? {
            true => {
                let (eig, mode) = self.inverse_iteration();
                self.min_eigenvalue = eig;
                if eig < SINGULAR_TOL || !eig.is_finite() {
                    self.usable = eig.is_finite();
                    return Err(FactorError::Singular {
                        eigenvalue: eig,
                        mode: Some(self.unscale(mode)),
                        usable: self.usable,
                    });
                }
                self.factored = true;
                Ok(())
            }
            false => {
                // Not positive definite: find the offending mode with a
                // shifted factorisation, whose inverse iteration converges to
                // the (near-)null space.
                for shift in [1e-10, 1e-6, 1e-2] {
                    if self.factor_shifted(pattern, values, shift)? {
                        let (_, mode) = self.inverse_iteration();
                        return Err(FactorError::Singular {
                            eigenvalue: 0.0,
                            mode: Some(self.unscale(mode)),
                            usable: false,
                        });
                    }
                }
                Err(FactorError::Singular {
                    eigenvalue: f64::NEG_INFINITY,
                    mode: None,
                    usable: false,
                })
            }
        }
    }

    /// A mode of the scaled matrix, in the original unknowns.
    fn unscale(&self, mut mode: Vec<f64>) -> Vec<f64> {
        mode.iter_mut().zip(&self.scale).for_each(|(m, s)| *m *= s);
        mode
    }

    /// Factorises K + shift·diag(K), i.e. the scaled matrix plus shift·I;
    /// whether it is positive definite.
    fn factor_shifted(
        &mut self,
        pattern: &Pattern,
        values: &[f64],
        shift: f64,
    ) -> std::result::Result<bool, FactorError> {
        match &mut self.engine {
            Engine::Whole(w) => w.factorize(pattern, values, shift),
            Engine::Split(sp) => sp
                .factorize(pattern, values, shift)
                .map_err(FactorError::Other),
        }
    }

    /// x ← K⁻¹x with the factor of K.
    fn solve_unscaled(&self, x: &mut [f64]) {
        match &self.engine {
            Engine::Whole(w) => w.solve(x),
            Engine::Split(sp) => sp.solve(x),
        }
    }

    /// x ← S⁻¹x = D⁻¹K⁻¹D⁻¹x for the scaled matrix S = DKD.
    fn solve_scaled(&self, x: &mut [f64]) {
        x.iter_mut().zip(&self.scale).for_each(|(v, s)| *v /= s);
        self.solve_unscaled(x);
        x.iter_mut().zip(&self.scale).for_each(|(v, s)| *v /= s);
    }

    fn inverse_iteration(&mut self) -> (f64, Vec<f64>) {
        let n = self.n();
        // Deterministic pseudo-random start (no component is systematically
        // zero, unlike a constant vector that may be orthogonal to a mode).
        let mut state = 0x2545F4914F6CDD1Du64;
        let mut x: Vec<f64> = (0..n)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            })
            .collect();
        let norm = |v: &[f64]| v.iter().map(|a| a * a).sum::<f64>().sqrt();
        let n0 = norm(&x);
        x.iter_mut().for_each(|a| *a /= n0);
        let mut estimate = f64::INFINITY;
        for _ in 0..INVERSE_ITERATIONS {
            self.solve_scaled(&mut x);
            let nx = norm(&x);
            if !(nx.is_finite() && nx > 0.0) {
                return (0.0, x);
            }
            estimate = 1.0 / nx;
            x.iter_mut().for_each(|a| *a /= nx);
        }
        (estimate, x)
    }

    /// Uses a factorisation that [`Cholesky::factorize`] flagged as
    /// singular although it succeeded, once the caller has established that
    /// the near-null mode is restrained (ill-conditioned, not singular).
    /// Returns whether the factorisation is now usable.
    pub fn accept_ill_conditioned(&mut self) -> bool {
        self.factored = self.usable;
        self.factored
    }

    /// Solves K x = b in place (b over the unknowns, unscaled). Requires a
    /// successful [`Cholesky::factorize`].
    pub fn solve(&self, b: &mut [f64]) -> Result<()> {
        if !self.factored {
            return Err(Error::state("solve before a successful factorisation"));
        }
        self.solve_unscaled(b);
        Ok(())
    }
}

impl Whole {
    fn analyse(
        pattern: &Pattern,
        ordering: Ordering,
        coords: Option<Points<'_>>,
        last: &[usize],
    ) -> Result<Whole> {
        let n = pattern.n();
        let perm = if last.is_empty() {
            match coords {
                Some(c) if ordering.use_nested_dissection(n) => {
                    Some(c.dissect(pattern.col_ptr(), pattern.row_idx(), None))
                }
                _ => None,
            }
        } else {
            Some(order_with_last(pattern, ordering, coords, last)?)
        };
        Whole::with_permutation(pattern, perm)
    }

    /// The symbolic analysis with the permutation `perm` (`perm[new] =
    /// old`), or AMD without one.
    fn with_permutation(pattern: &Pattern, perm: Option<Vec<usize>>) -> Result<Whole> {
        let n = pattern.n();
        let sym =
            SymbolicSparseColMatRef::new_checked(n, n, pattern.col_ptr(), None, pattern.row_idx());
        let inv = perm.as_ref().map(|fwd| {
            let mut inv = vec![0usize; n];
            for (new, &old) in fwd.iter().enumerate() {
                inv[old] = new;
            }
            inv
        });
        let ord = match (&perm, &inv) {
            (Some(fwd), Some(inv)) => SymmetricOrdering::Custom(PermRef::new_checked(fwd, inv, n)),
            _ => SymmetricOrdering::Amd,
        };
        let symbolic =
            factorize_symbolic_cholesky(sym, Side::Upper, ord, CholeskySymbolicParams::default())
                .map_err(|_| oom("symbolic analysis"))?;
        let par = Par::rayon(0);
        let factor_req = symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default());
        let solve_req = symbolic.solve_in_place_scratch::<f64>(1, par);
        let solve_mem = MemBuffer::try_new(solve_req).map_err(|_| oom("workspace"))?;
        let mut l_values = Vec::new();
        l_values
            .try_reserve_exact(symbolic.len_val())
            .map_err(|_| oom("factor"))?;
        l_values.resize(symbolic.len_val(), 0.0);
        Ok(Whole {
            symbolic,
            l_values,
            factor_req,
            solve_mem: Mutex::new(solve_mem),
            solve_bytes: solve_req.unaligned_bytes_required(),
            par,
        })
    }

    fn factorization_bytes(&self) -> usize {
        let symbolic = match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => s.col_ptr().len() + s.row_idx().len(),
            SymbolicCholeskyRaw::Supernodal(s) => {
                s.supernode_begin().len()
                    + s.col_ptr_for_row_idx().len()
                    + s.col_ptr_for_val().len()
                    + s.row_idx().len()
            }
        };
        let perm = if self.symbolic.perm().is_some() {
            2 * self.scale_len()
        } else {
            0
        };
        8 * (self.l_values.len() + symbolic + perm) + self.factor_req.unaligned_bytes_required()
    }

    fn scale_len(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Factorises K + shift·diag(K); whether it is positive definite.
    fn factorize(
        &mut self,
        pattern: &Pattern,
        values: &[f64],
        shift: f64,
    ) -> std::result::Result<bool, FactorError> {
        let n = pattern.n();
        let cp = pattern.col_ptr();
        let shifted;
        let vals: &[f64] = if shift == 0.0 {
            values
        } else {
            let mut v = values.to_vec();
            for j in 0..n {
                v[cp[j + 1] - 1] *= 1.0 + shift;
            }
            shifted = v;
            &shifted
        };
        let sym = SymbolicSparseColMatRef::new_checked(n, n, cp, None, pattern.row_idx());
        let a = SparseColMatRef::new(sym, vals);
        // The workspace (143 MB at 1M unknowns) lives only during the
        // factorisation, so that what follows can reuse its pages.
        let mut mem = MemBuffer::try_new(self.factor_req)
            .map_err(|_| FactorError::Other(oom("workspace")))?;
        let stack = MemStack::new(&mut mem);
        Ok(self
            .symbolic
            .factorize_numeric_llt(
                &mut self.l_values,
                a,
                Side::Upper,
                LltRegularization::default(),
                self.par,
                stack,
                Default::default(),
            )
            .is_ok())
    }

    fn solve(&self, x: &mut [f64]) {
        let n = x.len();
        let llt = LltRef::new(&self.symbolic, &self.l_values);
        let rhs = MatMut::from_column_major_slice_mut(x, n, 1);
        let mut mem = self
            .solve_mem
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        llt.solve_in_place_with_conj(Conj::No, rhs, self.par, MemStack::new(&mut mem));
    }

    /// The trailing m×m block of the factor, rows scaled by `scale`.
    fn last_block_factor(&self, m: usize, scale: &[f64]) -> Mat<f64> {
        let n = self.scale_len();
        let first = n - m;
        let mut l = Mat::<f64>::zeros(m, m);
        // The scaling of the trailing unknowns, in factor order: DL is the
        // factor of DKD (row i of L scaled by s_i).
        let row_scale: Vec<f64> = match self.symbolic.perm() {
            Some(p) => p.arrays().0[first..]
                .iter()
                .map(|&old| scale[old])
                .collect(),
            None => scale[first..].to_vec(),
        };
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => {
                let (cp, ri) = (s.col_ptr(), s.row_idx());
                for j in first..n {
                    for p in cp[j]..cp[j + 1] {
                        // Every row of a trailing column is itself trailing.
                        l[(ri[p] - first, j - first)] = row_scale[ri[p] - first] * self.l_values[p];
                    }
                }
            }
            SymbolicCholeskyRaw::Supernodal(s) => {
                let llt = SupernodalLltRef::new(s, &self.l_values);
                for k in 0..s.n_supernodes() {
                    let node = llt.supernode(k);
                    let (start, val, pattern) = (node.start(), node.val(), node.pattern());
                    let ncols = val.ncols();
                    if start + ncols <= first {
                        continue;
                    }
                    for c in 0..ncols {
                        let j = start + c;
                        if j < first {
                            continue;
                        }
                        for r in c..ncols {
                            let i = start + r - first;
                            l[(i, j - first)] = row_scale[i] * val[(r, c)];
                        }
                        for (r, &i) in pattern.iter().enumerate() {
                            l[(i - first, j - first)] = row_scale[i - first] * val[(ncols + r, c)];
                        }
                    }
                }
            }
        }
        l
    }
}

/// The split analysis ([`SplitCholesky`]): the unknowns other than `last`
/// cut in two parts and a separator, numbered before `last`, ignoring the
/// couplings at the positions `zeros`. `None` when they do not split (or
/// the dense separator block would be too large: over 64 entries per
/// unknown).
fn analyse_split(
    pattern: &Pattern,
    coords: &[[f64; 2]],
    last: &[usize],
    zeros: &[usize],
) -> Result<Option<SplitCholesky>> {
    let n = pattern.n();
    let mut is_zero = Vec::new();
    if !zeros.is_empty() {
        // (Positions checked by `Cholesky::analyse`.)
        is_zero = vec![false; pattern.nnz()];
        for &p in zeros {
            is_zero[p] = true;
        }
    }
    let (rest, col_ptr, row_idx) = restricted(pattern, last, &is_zero)?;
    let graph = Graph::from_upper(&col_ptr, &row_idx);
    drop((col_ptr, row_idx));
    let c: Vec<[f64; 2]> = rest.iter().map(|&i| coords[i]).collect();
    let Some((parts, sep)) = split_in_two(&graph, &c) else {
        return Ok(None);
    };
    drop(graph);
    let t = sep.len() + last.len();
    if t * t > 64 * n {
        return Ok(None);
    }
    let parts = parts.map(|p| p.into_iter().map(|k| rest[k]).collect());
    let top = sep
        .into_iter()
        .map(|k| rest[k])
        .chain(last.iter().copied())
        .collect();
    SplitCholesky::analyse(pattern, parts, top, &is_zero)
}

/// The unknowns not in `last` and the pattern restricted to them (upper
/// CSC over their indices in that list), without the positions marked in
/// `is_zero` (empty: none).
#[allow(clippy::type_complexity)]
fn restricted(
    pattern: &Pattern,
    last: &[usize],
    is_zero: &[bool],
) -> Result<(Vec<usize>, Vec<usize>, Vec<usize>)> {
    const LAST: usize = usize::MAX;
    let n = pattern.n();
    let mut sub = vec![0usize; n];
    for &i in last {
        if i >= n || sub[i] == LAST {
            return Err(Error::argument(format!(
                "unknown {i} is out of range or repeated in the set numbered last"
            )));
        }
        sub[i] = LAST;
    }
    let rest: Vec<usize> = (0..n).filter(|&i| sub[i] != LAST).collect();
    for (k, &i) in rest.iter().enumerate() {
        sub[i] = k;
    }
    let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
    let mut col_ptr = Vec::with_capacity(rest.len() + 1);
    let mut row_idx = Vec::new();
    col_ptr.push(0);
    for &j in &rest {
        row_idx.extend(
            (cp[j]..cp[j + 1])
                .filter(|&p| sub[ri[p]] != LAST && !is_zero.get(p).copied().unwrap_or(false))
                .map(|p| sub[ri[p]]),
        );
        col_ptr.push(row_idx.len());
    }
    Ok((rest, col_ptr, row_idx))
}

/// A fill-reducing ordering (`perm[new] = old`) of the unknowns not in
/// `last`, followed by `last`. The others are ordered on their own graph
/// (the pattern restricted to them), by nested dissection or AMD.
fn order_with_last(
    pattern: &Pattern,
    ordering: Ordering,
    coords: Option<Points<'_>>,
    last: &[usize],
) -> Result<Vec<usize>> {
    let (rest, col_ptr, row_idx) = restricted(pattern, last, &[])?;
    let m = rest.len();
    let order = match coords {
        Some(c) if ordering.use_nested_dissection(m) => c.dissect(&col_ptr, &row_idx, Some(&rest)),
        _ => {
            let (mut fwd, mut inv) = (vec![0usize; m], vec![0usize; m]);
            let sym = SymbolicSparseColMatRef::new_checked(m, m, &col_ptr, None, &row_idx);
            let mut mem = MemBuffer::try_new(faer::sparse::linalg::amd::order_scratch::<usize>(
                m,
                row_idx.len(),
            ))
            .map_err(|_| oom("ordering workspace"))?;
            faer::sparse::linalg::amd::order(
                &mut fwd,
                &mut inv,
                sym,
                Default::default(),
                MemStack::new(&mut mem),
            )
            .map_err(|_| oom("ordering"))?;
            fwd
        }
    };
    Ok(order
        .into_iter()
        .map(|k| rest[k])
        .chain(last.iter().copied())
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::assembly::DofMap;
    use crate::linalg::packed::packed_len;

    fn chain(n: usize, grounded: bool) -> (Pattern, Vec<f64>) {
        // A chain of scalar springs 0-1-2-...; triangles (i, i+1, i+1) are not
        // allowed, so use the path as overlapping triangles (i, i+1, i+2).
        // Stiffnesses grow along the chain so that the diagonal, hence the
        // Jacobi scaling, differs from unknown to unknown.
        let tris: Vec<[usize; 3]> = (0..n - 2).map(|i| [i, i + 1, i + 2]).collect();
        let dofs = DofMap::new(n, 1, |_| true);
        let p = Pattern::build(&dofs, n, &tris);
        let mut v = vec![0.0; p.nnz()];
        for e in 0..tris.len() {
            let w = 1.0 + e as f64;
            let ke = [1.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 1.0].map(|k| w * k);
            p.add_element(&mut v, &tris[e], &ke);
        }
        if grounded {
            v[0] += 1.0;
        }
        (p, v)
    }

    #[test]
    fn solves_a_grounded_chain() {
        let (p, v) = chain(50, true);
        let mut c = Cholesky::analyse(&p, &AnalyseParams::default()).unwrap();
        c.factorize(&p, &v).unwrap();
        let mut b = vec![0.0; 50];
        b[49] = 1.0;
        let rhs = b.clone();
        c.solve(&mut b).unwrap();
        let mut r = vec![0.0; 50];
        p.sym_mul(&v, &b, &mut r);
        let err: f64 = r
            .iter()
            .zip(&rhs)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-10, "{err}");
        assert!(c.condition_estimate() > 1.0);
    }

    #[test]
    fn the_trailing_block_of_the_factor_is_the_schur_complement_of_the_last_unknowns() {
        let n = 40;
        let (p, v) = chain(n, true);
        let last = [30usize, 5, 17];
        let mut c = Cholesky::analyse(
            &p,
            &AnalyseParams {
                last: &last,
                ..Default::default()
            },
        )
        .unwrap();
        c.factorize(&p, &v).unwrap();
        let l = c.last_block_factor().unwrap();
        // Independent dense Schur complement (nalgebra): K22 − K21 K11⁻¹ K12.
        let mut k = nalgebra::DMatrix::<f64>::zeros(n, n);
        let (cp, ri) = (p.col_ptr(), p.row_idx());
        for j in 0..n {
            for q in cp[j]..cp[j + 1] {
                k[(ri[q], j)] = v[q];
                k[(j, ri[q])] = v[q];
            }
        }
        let rest: Vec<usize> = (0..n).filter(|i| !last.contains(i)).collect();
        let k11 = k.select_rows(&rest).select_columns(&rest);
        let k12 = k.select_rows(&rest).select_columns(&last);
        let k22 = k.select_rows(&last).select_columns(&last);
        let s = &k22 - k12.transpose() * k11.cholesky().unwrap().solve(&k12);
        for a in 0..3 {
            for b in 0..3 {
                let llt: f64 = (0..3).map(|m| l[(a, m)] * l[(b, m)]).sum();
                let got = llt / (c.scale()[last[a]] * c.scale()[last[b]]);
                let want = s[(a, b)];
                assert!(
                    (got - want).abs() <= 1e-12 * s.norm(),
                    "S[{a},{b}] = {got} vs {want}"
                );
            }
        }
    }

    /// Two grids of NX × NY scalar nodes, one above the other, joined by a
    /// strip of triangles between A's top row and B's bottom row, each
    /// grounded along its outer edge; those two rows are the "interface".
    fn two_blocks() -> (Pattern, Vec<f64>, Vec<[f64; 2]>, Vec<usize>) {
        const NX: usize = 100;
        const NY: usize = 101;
        let node = |b: usize, x: usize, y: usize| b * NX * NY + y * NX + x;
        let mut tris = Vec::new();
        let mut coords = vec![[0.0; 2]; 2 * NX * NY];
        for b in 0..2 {
            for y in 0..NY {
                for x in 0..NX {
                    let y0 = if b == 0 { 0.0 } else { NY as f64 + 0.5 };
                    coords[node(b, x, y)] = [x as f64, y0 + y as f64];
                    if x + 1 < NX && y + 1 < NY {
                        tris.push([node(b, x, y), node(b, x + 1, y), node(b, x + 1, y + 1)]);
                        tris.push([node(b, x, y), node(b, x + 1, y + 1), node(b, x, y + 1)]);
                    }
                }
            }
        }
        for x in 0..NX - 1 {
            let (a0, a1) = (node(0, x, NY - 1), node(0, x + 1, NY - 1));
            let (b0, b1) = (node(1, x, 0), node(1, x + 1, 0));
            tris.push([a0, a1, b0]);
            tris.push([a1, b1, b0]);
        }
        let n = 2 * NX * NY;
        let dofs = DofMap::new(n, 1, |_| true);
        let p = Pattern::build(&dofs, n, &tris);
        let mut v = vec![0.0; p.nnz()];
        for (e, t) in tris.iter().enumerate() {
            let w = 1.0 + (e % 5) as f64;
            let ke = [2.0, -1.0, -1.0, -1.0, 2.0, -1.0, -1.0, -1.0, 2.0].map(|k| w * k);
            p.add_element(&mut v, t, &ke);
        }
        let cp = p.col_ptr();
        for x in 0..NX {
            for u in [node(0, x, 0), node(1, x, NY - 1)] {
                v[cp[u + 1] - 1] += 1.0;
            }
        }
        let mut last: Vec<usize> = (0..NX)
            .flat_map(|x| [node(0, x, NY - 1), node(1, x, 0)])
            .collect();
        last.sort_unstable();
        (p, v, coords, last)
    }

    #[test]
    fn a_split_at_the_last_unknowns_hands_over_their_schur_complement() {
        let (p, v, coords, last) = two_blocks();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        pool.install(|| {
            let mut c = Cholesky::analyse(
                &p,
                &AnalyseParams {
                    ordering: Ordering::NestedDissection,
                    coords: Some(Points::Plane(&coords)),
                    last: &last,
                    zeros: &[],
                    parallel_subtrees: true,
                },
            )
            .unwrap();
            assert!(c.is_split());
            c.factorize(&p, &v).unwrap();
            let s = c.take_last_schur().expect("the kept Schur complement");
            // Against the trailing factor block (itself checked against a
            // dense Schur complement above): Ŝ = L₂₂L₂₂ᵀ.
            let l = c.last_block_factor().unwrap();
            let m = last.len();
            assert_eq!(s.len(), packed_len(m));
            let at = |i: usize, j: usize| s[packed_start(m, j) + i - j];
            let norm = (0..m).map(|i| at(i, i).abs()).fold(0.0, f64::max);
            for b in 0..m {
                for a in b..m {
                    let llt: f64 = (0..=b).map(|k| l[(a, k)] * l[(b, k)]).sum();
                    assert!(
                        (at(a, b) - llt).abs() <= 1e-12 * norm,
                        "S[{a},{b}] = {} vs {llt}",
                        at(a, b)
                    );
                }
            }
            assert!(c.take_last_schur().is_none());
        });
    }

    #[test]
    fn a_zero_position_outside_the_pattern_is_refused_and_named() {
        let (p, _) = chain(10, true);
        let bad = p.nnz();
        let err = Cholesky::analyse(
            &p,
            &AnalyseParams {
                zeros: &[0, bad],
                ..Default::default()
            },
        )
        .err()
        .expect("refused");
        assert_eq!(err.status(), Status::InvalidArgument);
        assert!(
            err.message().contains(&format!("zero position {bad}")),
            "{}",
            err.message()
        );
    }

    #[test]
    fn detects_a_floating_chain_and_returns_its_constant_mode() {
        let (p, v) = chain(30, false);
        let mut c = Cholesky::analyse(&p, &AnalyseParams::default()).unwrap();
        match c.factorize(&p, &v) {
            Err(FactorError::Singular { mode: Some(m), .. }) => {
                let mean = m.iter().sum::<f64>() / m.len() as f64;
                let spread = m.iter().map(|a| (a - mean).abs()).fold(0.0, f64::max);
                assert!(spread < 1e-3 * mean.abs(), "mode is the constant: {m:?}");
            }
            other => panic!("expected singular, got {other:?}"),
        }
        let mut b = vec![1.0; 30];
        assert_eq!(c.solve(&mut b).unwrap_err().status(), Status::InvalidState);
    }
}
