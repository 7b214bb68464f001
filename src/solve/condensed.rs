//! The condensed system of the active-set loop: the contact changes
//! condensed on the interface unknowns.
//!
//! Between active-set iterations only contact elements change, and they
//! couple only the interface unknowns I (the unknowns of the contact nodes
//! with a nonzero coefficient in an element of B). With I numbered last, the
//! one sparse factorisation of K₁ (the first iteration's matrix) ends with
//! the dense Cholesky factor of its Schur complement S₁ on I
//! ([`Cholesky::last_block_factor`]). Any later matrix is
//! K = K₁ − P ΔC Pᵀ with ΔC supported on I, so its Schur complement is
//! S = S₁ − ΔC and the interface displacements solve the small dense system
//!
//!   S u_I = S₁ x₁|_I + Δg,
//!
//! where x₁ solves the first iteration and Δg is the change of the contact
//! loads. The inversion test needs only u_I; the full field is recovered
//! once, at convergence, by one more sparse solve:
//! u = x₁ + K₁⁻¹ P (Δg + ΔC u_I). Exact, no refactorisation.
//!
//! Everything dense is held in the Jacobi scaling s of K₁ (Ŝ = diag(s) S
//! diag(s)), where the diagonal is ~1 and the singularity test of the
//! sparse factorisation carries over.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{cholesky_in_place, cholesky_in_place_scratch};
use faer::linalg::cholesky::llt::update::rank_r_update_clobber;
use faer::linalg::matmul::triangular::{BlockStructure, matmul};
use faer::linalg::triangular_solve::{
    solve_lower_triangular_in_place, solve_upper_triangular_in_place,
};
use faer::{Accum, Mat, MatMut, Par};

use crate::error::{Error, Result, Status};
use crate::linalg::packed::{pack_lower, packed_len, packed_start};
use crate::linalg::{Cholesky, SINGULAR_TOL};

fn singular_error(eig: f64) -> Error {
    Error::new(
        Status::Singular,
        format!("the condensed interface matrix is singular (smallest eigenvalue ≤ {eig:.1e})"),
    )
}

/// A copy of a condensed system's factor ([`Condensed::factor_snapshot`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FactorSnapshot {
    /// The lower triangle, packed by columns.
    pub packed: Vec<f64>,
    /// Whether it is usable.
    pub factored: bool,
    /// Its smallest-eigenvalue bound.
    pub min_eigenvalue: f64,
}

/// Marks an unknown outside the interface.
const OUTSIDE: u32 = u32::MAX;

/// An element's contribution to the interface: its unknowns (indices over
/// the free unknowns, `None` when prescribed) and its n×n matrix, n the
/// number of its DOFs (6 for an element of B; more for a functional that
/// couples more nodes, such as a mortar weighted gap). Every unknown it
/// couples must be an interface unknown ([`Condensed::factorize`] and
/// [`Condensed::update`] refuse one that is not).
pub struct ElementMatrix<'a> {
    /// Free-unknown index of each element DOF.
    pub unknowns: &'a [Option<usize>],
    /// Row-major n×n element matrix (n = `unknowns.len()`).
    pub matrix: &'a [f64],
}

/// The condensed system of one factorised reference matrix K₁: the
/// interface Schur complement Ŝ₁, the factor of the current Ŝ, and the
/// positions of the interface unknowns.
pub struct Condensed {
    unknowns: Vec<usize>,
    position: Vec<u32>,
    scale: Vec<f64>,
    /// Ŝ₁, its lower triangle packed by columns ([`packed_start`]): half
    /// the memory of a square matrix (17 MB at 2 000 unknowns).
    s_ref: Vec<f64>,
    /// The Cholesky factor of the current Ŝ (lower triangle).
    factor: Mat<f64>,
    factored: bool,
    min_eigenvalue: f64,
    par: Par,
    /// Counts the factors: a cached solve with the factor is valid while
    /// it stands.
    epoch: u64,
    /// The capacitance system of the last low-rank change solved with.
    capacitance: Option<Capacitance>,
}

/// An unsymmetric low-rank change U Vᵀ of the interface matrix (the slip
/// coupling of docs/method.md §6.15): column j of U and of V as
/// (interface position, value) lists, unscaled.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LowRank {
    /// The columns of U.
    pub u: Vec<Vec<(usize, f64)>>,
    /// The columns of V.
    pub v: Vec<Vec<(usize, f64)>>,
}

impl LowRank {
    /// Its rank bound: the number of columns.
    pub fn rank(&self) -> usize {
        self.u.len()
    }
}

/// Ẑ = Ŝ⁻¹Û and the LU factors of the capacitance matrix I + V̂ᵀẐ of a
/// [`LowRank`] change (scaled: Û = diag(s)U, V̂ = diag(s)V), for the factor
/// of epoch `epoch`.
struct Capacitance {
    epoch: u64,
    change: LowRank,
    z: Mat<f64>,
    lu: nalgebra::linalg::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl Condensed {
    /// Largest interface handled densely.
    pub const MAX_UNKNOWNS: usize = 8192;

    /// Whether condensing `n_interface` unknowns pays for a matrix with
    /// `matrix_nnz` stored entries: the dense interface matrices must stay
    /// small beside the sparse factor (which holds many times the matrix).
    pub fn worthwhile(n_interface: usize, matrix_nnz: usize) -> bool {
        n_interface > 0
            && n_interface <= Self::MAX_UNKNOWNS
            && n_interface * n_interface <= 4 * matrix_nnz
    }

    /// Reads Ŝ₁ from the factorisation of K₁, analysed with `unknowns`
    /// (sorted free-unknown indices) numbered last: takes it when the
    /// factorisation kept it ([`Cholesky::take_last_schur`]), else forms it
    /// from the trailing factor block as L₂₂L₂₂ᵀ.
    pub fn new(chol: &mut Cholesky, unknowns: Vec<usize>) -> Result<Condensed> {
        let n = unknowns.len();
        let mut position = vec![OUTSIDE; chol.n()];
        for (k, &i) in unknowns.iter().enumerate() {
            position[i] = k as u32;
        }
        let scale: Vec<f64> = unknowns.iter().map(|&i| chol.scale()[i]).collect();
        let l = chol.last_block_factor()?;
        let par = Par::rayon(0);
        let s_ref = match chol.take_last_schur() {
            Some(s) => s,
            None => {
                let mut s = Mat::<f64>::zeros(n, n);
                matmul(
                    s.as_mut(),
                    BlockStructure::TriangularLower,
                    Accum::Replace,
                    l.as_ref(),
                    BlockStructure::TriangularLower,
                    l.as_ref().transpose(),
                    BlockStructure::TriangularUpper,
                    1.0,
                    par,
                );
                let mut packed = Vec::with_capacity(packed_len(n));
                pack_lower(s.as_ref(), &mut packed);
                packed
            }
        };
        Ok(Condensed {
            unknowns,
            position,
            scale,
            s_ref,
            // L₂₂ is already the factor of Ŝ₁, checked with the sparse factor.
            factor: l,
            factored: true,
            min_eigenvalue: chol.min_eigenvalue_estimate(),
            par,
            epoch: 0,
            capacitance: None,
        })
    }

    /// Number of interface unknowns.
    pub fn len(&self) -> usize {
        self.unknowns.len()
    }

    /// Whether the interface is empty.
    pub fn is_empty(&self) -> bool {
        self.unknowns.is_empty()
    }

    /// Bytes held by the dense matrices (the factor, Ŝ₁ packed).
    pub fn memory_bytes(&self) -> usize {
        8 * (self.len() * self.len() + self.s_ref.len())
    }

    /// The free-unknown indices of the interface, in order.
    pub fn unknowns(&self) -> &[usize] {
        &self.unknowns
    }

    /// Upper bound of the smallest eigenvalue of the last factorised Ŝ.
    pub fn min_eigenvalue_estimate(&self) -> f64 {
        self.min_eigenvalue
    }

    /// Refuses a change whose matrix is not n×n over its n DOFs, or that
    /// couples an unknown outside the interface (Ŝ has no place for it:
    /// dropping it would change the system silently).
    fn check_change(&self, e: &ElementMatrix<'_>) -> Result<()> {
        let n = e.unknowns.len();
        if e.matrix.len() != n * n {
            return Err(Error::state(format!(
                "an interface change has {} matrix entries for {n} DOFs",
                e.matrix.len()
            )));
        }
        for (a, unknown) in e.unknowns.iter().enumerate() {
            let outside =
                matches!(unknown, Some(i) if self.position.get(*i).is_none_or(|&p| p == OUTSIDE));
            if outside && e.matrix[a * n..a * n + n].iter().any(|&v| v != 0.0) {
                return Err(Error::state(format!(
                    "an interface change couples unknown {} outside the interface",
                    unknown.unwrap_or_default()
                )));
            }
        }
        Ok(())
    }

    fn add(
        position: &[u32],
        scale: &[f64],
        m: &mut MatMut<'_, f64>,
        e: &ElementMatrix<'_>,
        sign: f64,
    ) {
        let n = e.unknowns.len();
        debug_assert_eq!(e.matrix.len(), n * n);
        for a in 0..n {
            let Some(pa) = e.unknowns[a].map(|i| position[i]) else {
                continue;
            };
            if pa == OUTSIDE {
                continue;
            }
            for b in 0..n {
                let Some(pb) = e.unknowns[b].map(|i| position[i]) else {
                    continue;
                };
                if pb == OUTSIDE {
                    continue;
                }
                let (pa, pb) = (pa as usize, pb as usize);
                if pa >= pb {
                    m[(pa, pb)] += sign * scale[pa] * e.matrix[a * n + b] * scale[pb];
                }
            }
        }
    }

    /// Factorises Ŝ = Ŝ₁ + Σ sign·Ĉₑ over the element changes relative to
    /// K₁. Fails with [`Status::Singular`] when Ŝ is not positive definite
    /// or its smallest eigenvalue is below [`SINGULAR_TOL`]; the caller
    /// then falls back to a full factorisation, which names the free mode.
    pub fn factorize<'a>(
        &mut self,
        changes: impl Iterator<Item = (ElementMatrix<'a>, f64)>,
    ) -> Result<()> {
        let changes: Vec<(ElementMatrix<'a>, f64)> = changes.collect();
        for (e, _) in &changes {
            self.check_change(e)?;
        }
        self.factored = false;
        self.epoch += 1;
        let n = self.len();
        {
            let mut f = self.factor.as_mut();
            // Ŝ₁'s lower triangle: all the dense Cholesky reads.
            for j in 0..n {
                let start = packed_start(n, j);
                for i in j..n {
                    f[(i, j)] = self.s_ref[start + i - j];
                }
            }
            for (e, sign) in changes {
                Self::add(&self.position, &self.scale, &mut f, &e, sign);
            }
        }
        let mut mem = MemBuffer::try_new(cholesky_in_place_scratch::<f64>(
            n,
            self.par,
            Default::default(),
        ))
        .map_err(|_| Error::new(Status::OutOfMemory, "interface factorisation workspace"))?;
        cholesky_in_place(
            self.factor.as_mut(),
            Default::default(),
            self.par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .map_err(|_| singular_error(0.0))?;
        self.check()
    }

    /// Updates the current factor for element changes relative to the
    /// matrix it factorises (not to Ŝ₁): each change's scaled matrix is split
    /// into its eigenpairs (one for a frictionless element of B or a mortar
    /// weighted gap, up to three for a frictional element, at most its
    /// number of DOFs) and applied as a rank-r update, O(n²r) instead of the
    /// O(n³) refactorisation. Fails like [`Condensed::factorize`], and also
    /// when a downdate loses definiteness in round-off; the factor is then
    /// unusable and the caller refactorises.
    pub fn update<'a>(
        &mut self,
        changes: impl Iterator<Item = (ElementMatrix<'a>, f64)>,
    ) -> Result<()> {
        if !self.factored {
            return Err(Error::state("interface update without a factor"));
        }
        let changes: Vec<(ElementMatrix<'a>, f64)> = changes.collect();
        if changes.is_empty() {
            // Nothing changed: the factor (and what was solved with it) stands.
            return Ok(());
        }
        for (e, _) in &changes {
            self.check_change(e)?;
        }
        self.factored = false;
        self.epoch += 1;
        let mut columns: Vec<(Vec<(usize, f64)>, f64)> = Vec::new();
        for (e, sign) in changes {
            let dofs = e.unknowns.len();
            let on: Vec<(usize, usize)> = (0..dofs)
                .filter_map(|a| {
                    let i = e.unknowns[a]?;
                    (self.position[i] != OUTSIDE).then_some((a, self.position[i] as usize))
                })
                .collect();
            if on.is_empty() {
                continue;
            }
            let m = on.len();
            let km = nalgebra::DMatrix::from_fn(m, m, |r, c| {
                let ((a, pa), (b, pb)) = (on[r], on[c]);
                self.scale[pa] * e.matrix[a * dofs + b] * self.scale[pb]
            });
            let eig = km.symmetric_eigen();
            let top = eig.eigenvalues.amax();
            for (k, &lambda) in eig.eigenvalues.iter().enumerate() {
                // Eigenvalues at round-off level of the largest are the
                // element's exact zeros (its rank deficiency), not data.
                if lambda.abs() > 64.0 * f64::EPSILON * top {
                    let v = eig.eigenvectors.column(k);
                    let col = on
                        .iter()
                        .enumerate()
                        .map(|(r, &(_, p))| (p, v[r]))
                        .collect();
                    columns.push((col, sign * lambda));
                }
            }
        }
        let n = self.len();
        let mut w = Mat::<f64>::zeros(n, columns.len());
        let mut alpha = faer::diag::Diag::<f64>::zeros(columns.len());
        for (j, (col, a)) in columns.iter().enumerate() {
            for &(p, v) in col {
                w[(p, j)] += v;
            }
            alpha[j] = *a;
        }
        rank_r_update_clobber(self.factor.as_mut(), w.as_mut(), alpha.as_mut())
            .map_err(|_| singular_error(0.0))?;
        self.check()
    }

    /// Whether the current factor is usable.
    pub fn is_factored(&self) -> bool {
        self.factored
    }

    /// A fingerprint of the current factor's bits (lower triangle, by
    /// columns): two systems with the same fingerprint are, to a 64-bit
    /// hash, the same system factorised the same way. Hashed in place: a
    /// copy would cost n²/2 values.
    pub fn factor_fingerprint(&self) -> u64 {
        let n = self.len();
        let mut h = 0xcbf2_9ce4_8422_2325u64 ^ n as u64;
        for j in 0..n {
            for v in self.factor.col(j).subrows(j, n - j).iter() {
                // FNV-1a over 64-bit words, with the high bits folded back
                // so that every bit of every value reaches the result.
                h = (h ^ v.to_bits()).wrapping_mul(0x100_0000_01b3);
                h ^= h >> 29;
            }
        }
        h
    }

    /// The current factor (lower triangle packed by columns), whether it
    /// is usable, and its eigenvalue bound: enough to continue exactly
    /// where this system is ([`Condensed::restore_factor`]).
    pub fn factor_snapshot(&self) -> FactorSnapshot {
        let n = self.len();
        let mut packed = Vec::with_capacity(packed_len(n));
        pack_lower(self.factor.as_ref(), &mut packed);
        FactorSnapshot {
            packed,
            factored: self.factored,
            min_eigenvalue: self.min_eigenvalue,
        }
    }

    /// Puts back a factor from [`Condensed::factor_snapshot`] of a system
    /// of the same size.
    pub fn restore_factor(&mut self, snapshot: &FactorSnapshot) -> Result<()> {
        let n = self.len();
        if snapshot.packed.len() != packed_len(n) {
            return Err(Error::argument(format!(
                "the saved interface factor holds {} values, not the {} of {n} interface unknowns",
                snapshot.packed.len(),
                packed_len(n)
            )));
        }
        let mut f = self.factor.as_mut();
        for j in 0..n {
            let start = packed_start(n, j);
            for i in j..n {
                f[(i, j)] = snapshot.packed[start + i - j];
            }
        }
        self.factored = snapshot.factored;
        self.min_eigenvalue = snapshot.min_eigenvalue;
        self.epoch += 1;
        Ok(())
    }

    /// Inverse-iteration bound of the smallest eigenvalue of the freshly
    /// factorised Ŝ; marks the factor usable when it passes.
    fn check(&mut self) -> Result<()> {
        let n = self.len();
        let mut x: Vec<f64> = (0..n).map(|i| 1.0 + (i % 7) as f64 * 0.1).collect();
        let mut eig = f64::INFINITY;
        for _ in 0..3 {
            let nx = x.iter().map(|a| a * a).sum::<f64>().sqrt();
            x.iter_mut().for_each(|a| *a /= nx);
            self.solve_scaled(&mut x);
            eig = 1.0 / x.iter().map(|a| a * a).sum::<f64>().sqrt();
        }
        self.min_eigenvalue = eig;
        if eig >= SINGULAR_TOL {
            self.factored = true;
            Ok(())
        } else {
            Err(singular_error(eig))
        }
    }

    fn solve_scaled(&self, x: &mut [f64]) {
        let n = x.len();
        let mut rhs = MatMut::from_column_major_slice_mut(x, n, 1);
        solve_lower_triangular_in_place(self.factor.as_ref(), rhs.as_mut(), self.par);
        solve_upper_triangular_in_place(self.factor.as_ref().transpose(), rhs, self.par);
    }

    /// Solves S u_I = S₁ y_I + g_I for u_I (all over the interface, in its
    /// order, unscaled), with the last factorised S: the interface values of
    /// K⁻¹(b + P g) for any b with y = K₁⁻¹ b.
    pub fn solve(&self, y: &[f64], g: &[f64]) -> Result<Vec<f64>> {
        if !self.factored {
            return Err(Error::state("interface solve before a factorisation"));
        }
        let mut x = self.scaled_rhs(y, g);
        self.solve_scaled(&mut x);
        for (xk, s) in x.iter_mut().zip(&self.scale) {
            *xk *= s;
        }
        Ok(x)
    }

    /// The scaled right-hand side diag(s)(S₁y + g) of [`Condensed::solve`].
    fn scaled_rhs(&self, y: &[f64], g: &[f64]) -> Vec<f64> {
        let n = self.len();
        let yh: Vec<f64> = (0..n).map(|k| y[k] / self.scale[k]).collect();
        // x = Ŝ₁ŷ from the packed lower triangle, column by column: the
        // column below the diagonal adds to x below j and to x_j.
        let mut x = vec![0.0; n];
        for j in 0..n {
            let start = packed_start(n, j);
            let col = &self.s_ref[start..start + n - j];
            let (yj, mut dot) = (yh[j], 0.0);
            for ((xi, &s), &yi) in x[j + 1..].iter_mut().zip(&col[1..]).zip(&yh[j + 1..]) {
                *xi += s * yj;
                dot += s * yi;
            }
            x[j] += col[0] * yj + dot;
        }
        for k in 0..n {
            x[k] += self.scale[k] * g[k];
        }
        x
    }

    /// (LLᵀ + ÛV̂ᵀ) x̂ for a scaled x̂: the coupled matrix as the factor
    /// holds it.
    fn coupled_product(&self, xh: &[f64], change: &LowRank) -> Vec<f64> {
        let n = self.len();
        let l = self.factor.as_ref();
        // w = Lᵀx̂ (lower triangle only), then LLᵀx̂ = L w.
        let mut w = vec![0.0; n];
        for (j, wj) in w.iter_mut().enumerate() {
            *wj = (j..n).map(|i| l[(i, j)] * xh[i]).sum();
        }
        let mut out = vec![0.0; n];
        for (j, &wj) in w.iter().enumerate() {
            for (i, o) in out.iter_mut().enumerate().skip(j) {
                *o += l[(i, j)] * wj;
            }
        }
        for (u, v) in change.u.iter().zip(&change.v) {
            // Vᵀx = V̂ᵀx̂ with V̂ = DV and x = Dx̂.
            let vx: f64 = v.iter().map(|&(p, c)| c * self.scale[p] * xh[p]).sum();
            for &(p, c) in u {
                out[p] += self.scale[p] * c * vx;
            }
        }
        out
    }

    /// Solves (S + U Vᵀ) u_I = S₁ y_I + g_I like [`Condensed::solve`], with
    /// the unsymmetric low-rank `change` U Vᵀ added to the last factorised
    /// (symmetric) S, by the Sherman–Morrison–Woodbury formula
    /// u = x − Z (I + VᵀZ)⁻¹ Vᵀx, x = S⁻¹(S₁y + g), Z = S⁻¹U. Z and the LU
    /// factors of the capacitance matrix I + VᵀZ are kept while the factor
    /// and the change stand, so that a step of a history with the same
    /// contact state costs one solve more than without the change.
    /// `Ok(None)` when the capacitance matrix is singular (its smallest LU
    /// pivot below 1e-12 of the largest): S + U Vᵀ is then singular or
    /// nearly so.
    pub fn solve_with(
        &mut self,
        y: &[f64],
        g: &[f64],
        change: &LowRank,
    ) -> Result<Option<Vec<f64>>> {
        if change.rank() == 0 {
            return self.solve(y, g).map(Some);
        }
        if !self.factored {
            return Err(Error::state("interface solve before a factorisation"));
        }
        if !self.capacitance_for(change) {
            return Ok(None);
        }
        let b = self.scaled_rhs(y, g);
        let mut x = b.clone();
        self.woodbury_scaled(&mut x, change);
        // One step of refinement against the factor and the change: the
        // formula loses what the capacitance matrix's condition costs.
        let ax = self.coupled_product(&x, change);
        let mut r: Vec<f64> = b.iter().zip(&ax).map(|(b, a)| b - a).collect();
        self.woodbury_scaled(&mut r, change);
        for ((xk, rk), s) in x.iter_mut().zip(&r).zip(&self.scale) {
            *xk = (*xk + rk) * s;
        }
        Ok(Some(x))
    }

    /// Makes Ẑ = Ŝ⁻¹Û and the LU factors of I + V̂ᵀẐ those of `change`
    /// and the current factor; false when the capacitance matrix is
    /// singular (its smallest LU pivot below 1e-12 of the largest).
    fn capacitance_for(&mut self, change: &LowRank) -> bool {
        let fresh = self
            .capacitance
            .as_ref()
            .is_some_and(|c| c.epoch == self.epoch && &c.change == change);
        if fresh {
            return true;
        }
        self.capacitance = None;
        let (n, m) = (self.len(), change.rank());
        let mut z = Mat::<f64>::zeros(n, m);
        for (j, col) in change.u.iter().enumerate() {
            for &(p, v) in col {
                z[(p, j)] += self.scale[p] * v;
            }
        }
        solve_lower_triangular_in_place(self.factor.as_ref(), z.as_mut(), self.par);
        solve_upper_triangular_in_place(self.factor.as_ref().transpose(), z.as_mut(), self.par);
        let cap = nalgebra::DMatrix::from_fn(m, m, |i, j| {
            let vz: f64 = change.v[i]
                .iter()
                .map(|&(p, v)| v * self.scale[p] * z[(p, j)])
                .sum();
            vz + if i == j { 1.0 } else { 0.0 }
        });
        let lu = cap.lu();
        let (lo, hi) = lu
            .u()
            .diagonal()
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), d| {
                (lo.min(d.abs()), hi.max(d.abs()))
            });
        // (NaN pivots fail too.)
        let regular = lo > 1e-12 * hi;
        if !regular {
            return false;
        }
        self.capacitance = Some(Capacitance {
            epoch: self.epoch,
            change: change.clone(),
            z,
            lu,
        });
        true
    }

    /// x̂ ← (Ŝ + ÛV̂ᵀ)⁻¹x̂ by the Sherman–Morrison–Woodbury formula with the
    /// capacitance system of [`Condensed::capacitance_for`].
    fn woodbury_scaled(&self, x: &mut [f64], change: &LowRank) {
        self.solve_scaled(x);
        let c = self.capacitance.as_ref().expect("the capacitance system");
        let m = change.rank();
        let t = nalgebra::DVector::from_fn(m, |i, _| {
            change.v[i]
                .iter()
                .map(|&(p, v)| v * self.scale[p] * x[p])
                .sum::<f64>()
        });
        let w = c.lu.solve(&t).expect("a regular capacitance matrix");
        for j in 0..m {
            let wj = w[j];
            for (p, xp) in x.iter_mut().enumerate() {
                *xp -= c.z[(p, j)] * wj;
            }
        }
    }

    /// Gathers the interface values of a vector over the free unknowns.
    pub fn gather(&self, v: &[f64]) -> Vec<f64> {
        self.unknowns.iter().map(|&i| v[i]).collect()
    }

    /// Interface position of a free unknown, if it is on the interface.
    pub fn position(&self, unknown: usize) -> Option<usize> {
        match self.position[unknown] {
            OUTSIDE => None,
            p => Some(p as usize),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A symmetric positive definite n×n matrix, lower triangle only, and
    /// `upper` in its strict upper triangle.
    fn spd(n: usize, upper: f64) -> Mat<f64> {
        Mat::from_fn(n, n, |i, j| match i.cmp(&j) {
            std::cmp::Ordering::Less => upper,
            std::cmp::Ordering::Equal => n as f64 + 2.0,
            std::cmp::Ordering::Greater => {
                1.0 / (1.0 + (i - j) as f64) + ((i * j) % 5) as f64 * 0.1
            }
        })
    }

    fn lower_bits(m: &Mat<f64>) -> Vec<u64> {
        let n = m.nrows();
        (0..n)
            .flat_map(|j| (j..n).map(move |i| (i, j)))
            .map(|(i, j)| m[(i, j)].to_bits())
            .collect()
    }

    /// The condensed system of the two-block fixture (its interface: the
    /// unknowns of its B).
    fn fixture_condensed() -> Condensed {
        use crate::contact::ContactOptions;
        use crate::solve::fixtures::{assembled, contact_set, two_blocks};
        use crate::solve::linear::{Bookkeeping, Structure};
        use crate::solve::report::{SolveInfo, Timings};
        use crate::solve::session::{Session, Settings, Wanted, factorisation};
        let p = two_blocks(4, 4);
        let (mut session, prescribed) = assembled(&p);
        let mesh = p.mesh().unwrap();
        let Session {
            dofs,
            pattern,
            contact,
            analysis,
            system,
            ..
        } = &mut session;
        let set = contact_set(
            &p,
            contact.strip(),
            dofs,
            &prescribed,
            &ContactOptions::default(),
        );
        let set =
            crate::contact::constraints::Constraints::new(set, Default::default(), &prescribed);
        let interface = set.interface_unknowns();
        // Every element of B on: K₁ then holds the upper block.
        let all = vec![true; set.parts()];
        system.set_contact(&all, &set, pattern);
        let want = Wanted {
            last: &interface,
            zeros: &[],
        };
        let (mut timings, mut info) = (Timings::default(), SolveInfo::default());
        let at = Structure {
            mesh,
            dofs,
            pattern,
        };
        let mut books = Bookkeeping::new(&mut timings, &mut info);
        let chol = factorisation(analysis, at, Settings::default(), want, &mut books).unwrap();
        chol.factorize(pattern, system.values()).unwrap();
        Condensed::new(chol, interface).unwrap()
    }

    /// A rank-one penalty k c cᵀ over `unknowns` (some `None`).
    fn rank_one(c: &[f64], k: f64) -> Vec<f64> {
        c.iter()
            .flat_map(|&a| c.iter().map(move |&b| k * a * b))
            .collect()
    }

    #[test]
    fn a_change_over_more_than_six_dofs_updates_the_factor_as_a_refactorisation_does() {
        let mut sys = fixture_condensed();
        let n = sys.len();
        assert!(n >= 10, "{n} interface unknowns");
        // A weighted gap over 12 DOFs, two of them prescribed.
        let picks: Vec<usize> = (0..12).map(|k| sys.unknowns()[(7 * k) % n]).collect();
        let unknowns: Vec<Option<usize>> = picks
            .iter()
            .enumerate()
            .map(|(k, &i)| (k % 5 != 3).then_some(i))
            .collect();
        let c: Vec<f64> = (0..12).map(|k| ((k as f64) * 0.9).sin()).collect();
        let matrix = rank_one(&c, 5e3);
        let change = || {
            std::iter::once((
                ElementMatrix {
                    unknowns: &unknowns,
                    matrix: &matrix,
                },
                1.0,
            ))
        };
        let y: Vec<f64> = (0..n).map(|k| (k as f64).cos()).collect();
        let g: Vec<f64> = (0..n).map(|k| 1e-3 * (k as f64 * 0.3).sin()).collect();
        sys.factorize(change()).unwrap();
        let refactorised = sys.solve(&y, &g).unwrap();
        sys.factorize(std::iter::empty()).unwrap();
        let without = sys.solve(&y, &g).unwrap();
        sys.update(change()).unwrap();
        let updated = sys.solve(&y, &g).unwrap();
        let scale = refactorised.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let apart = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .map(|(p, q)| (p - q).abs())
                .fold(0.0, f64::max)
                / scale
        };
        assert!(apart(&updated, &refactorised) < 1e-12);
        // And the change is felt: not the solution without it.
        assert!(apart(&without, &refactorised) > 1e-6);
    }

    #[test]
    fn a_dof_repeated_within_one_change_adds_up_in_an_update_as_in_a_refactorisation() {
        let mut sys = fixture_condensed();
        let u = sys.unknowns().to_vec();
        // DOF u[2] twice: the change is k (c₀ + c₃)² on it.
        let unknowns = [Some(u[0]), Some(u[2]), Some(u[5]), Some(u[2])];
        let matrix = rank_one(&[1.0, 2.0, -1.5, 0.5], 2e3);
        let change = || {
            std::iter::once((
                ElementMatrix {
                    unknowns: &unknowns,
                    matrix: &matrix,
                },
                1.0,
            ))
        };
        let n = sys.len();
        let y: Vec<f64> = (0..n).map(|k| (k as f64 * 0.4).sin()).collect();
        let g = vec![0.0; n];
        sys.factorize(change()).unwrap();
        let refactorised = sys.solve(&y, &g).unwrap();
        sys.factorize(std::iter::empty()).unwrap();
        sys.update(change()).unwrap();
        let updated = sys.solve(&y, &g).unwrap();
        let scale = refactorised.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in updated.iter().zip(&refactorised) {
            assert!((a - b).abs() < 1e-12 * scale, "{a} against {b}");
        }
    }

    #[test]
    fn a_change_of_the_wrong_size_or_outside_the_interface_is_refused() {
        let mut sys = fixture_condensed();
        let u = sys.unknowns().to_vec();
        let short = [Some(u[0]), Some(u[1])];
        let three = [1.0, 2.0, 3.0];
        let e = ElementMatrix {
            unknowns: &short,
            matrix: &three,
        };
        let err = sys.factorize(std::iter::once((e, 1.0))).unwrap_err();
        assert!(
            err.to_string().contains("3 matrix entries for 2 DOFs"),
            "{err}"
        );
        // An unknown that is not on the interface (the first free unknown
        // of the lower block's bottom row is not).
        let outside = (0..).find(|i| !u.contains(i)).unwrap();
        let with_outside = [Some(u[0]), Some(outside)];
        let m = rank_one(&[1.0, 1.0], 1.0);
        sys.factorize(std::iter::empty()).unwrap();
        let e = ElementMatrix {
            unknowns: &with_outside,
            matrix: &m,
        };
        let err = sys.update(std::iter::once((e, 1.0))).unwrap_err();
        assert!(err.to_string().contains("outside the interface"), "{err}");
        // Refused before it touched the factor.
        assert!(sys.is_factored());
    }

    #[test]
    fn an_element_padded_with_absent_dofs_changes_the_factor_as_the_element_alone() {
        let mut sys = fixture_condensed();
        let u = sys.unknowns().to_vec();
        let six: Vec<Option<usize>> = (0..6).map(|k| Some(u[k])).collect();
        let c: Vec<f64> = (0..6).map(|k| 1.0 + k as f64).collect();
        let m6 = rank_one(&c, 1e3);
        let mut padded = six.clone();
        padded.extend([None; 4]);
        let mut c10 = c.clone();
        c10.extend([7.0, -3.0, 2.0, 1.0]);
        let m10 = rank_one(&c10, 1e3);
        let n = sys.len();
        let y: Vec<f64> = (0..n).map(|k| (k as f64 * 0.7).cos()).collect();
        let g = vec![0.0; n];
        let mut solve = |unknowns: &[Option<usize>], matrix: &[f64]| {
            let e = ElementMatrix { unknowns, matrix };
            sys.factorize(std::iter::once((e, 1.0))).unwrap();
            sys.solve(&y, &g).unwrap()
        };
        let alone = solve(&six, &m6);
        let with_absent = solve(&padded, &m10);
        assert_eq!(alone, with_absent);
    }

    /// The interface refills only the lower triangle of its factor's
    /// storage before refactorising (the upper one holds what the last
    /// factorisation left there: faer's kernels write it), so faer's dense
    /// Cholesky, rank-r update and triangular solves must not read it. NaN
    /// there would leak into any result that did; the results must match
    /// those with zeros bit for bit.
    #[test]
    fn faer_dense_kernels_read_only_the_lower_triangle() {
        for n in [1, 2, 7, 33, 64, 65, 130, 257, 600, 1201] {
            let run = |upper: f64| {
                let mut f = spd(n, upper);
                let par = Par::rayon(0);
                let mut mem =
                    MemBuffer::new(cholesky_in_place_scratch::<f64>(n, par, Default::default()));
                cholesky_in_place(
                    f.as_mut(),
                    Default::default(),
                    par,
                    MemStack::new(&mut mem),
                    Default::default(),
                )
                .expect("positive definite");
                let after_factor = lower_bits(&f);
                let mut w = Mat::from_fn(n, 3, |i, k| ((i + 3 * k) % 7) as f64 * 0.1);
                let mut alpha = faer::diag::Diag::<f64>::zeros(3);
                for (k, a) in [0.5, -0.25, 1.0].into_iter().enumerate() {
                    alpha[k] = a;
                }
                rank_r_update_clobber(f.as_mut(), w.as_mut(), alpha.as_mut()).expect("definite");
                let mut x: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
                let mut rhs = MatMut::from_column_major_slice_mut(&mut x, n, 1);
                solve_lower_triangular_in_place(f.as_ref(), rhs.as_mut(), par);
                solve_upper_triangular_in_place(f.as_ref().transpose(), rhs, par);
                (f, after_factor, x)
            };
            let (f0, factor0, x0) = run(0.0);
            let (f1, factor1, x1) = run(f64::NAN);
            assert_eq!(
                factor0, factor1,
                "n = {n}: the factor depends on the upper triangle"
            );
            assert_eq!(lower_bits(&f0), lower_bits(&f1), "n = {n}: the update does");
            let bits = |v: &[f64]| v.iter().map(|a| a.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&x0), bits(&x1), "n = {n}: the solves do");
        }
    }
}
