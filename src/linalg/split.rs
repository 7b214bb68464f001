//! A sparse Cholesky factorisation split at the top of its elimination
//! tree, so that the tree's two subtrees are factorised at the same time.
//!
//! faer's supernodal factorisation visits the supernodes one after the
//! other; only its dense kernels run in parallel, which leaves the many
//! small fronts of a 2D mesh on one core. A dissection makes the two
//! subtrees independent: with the unknowns ordered [A, B, T] (parts A and B
//! not coupled to each other, separator T last),
//!
//!   K = [K_AA 0 K_AT; 0 K_BB K_BT; K_TA K_TB K_TT].
//!
//! Only the separator unknowns T_A ⊂ T coupled to A enter A's part: the
//! principal submatrix M_A = K[A∪T_A] is positive definite whenever K is,
//! and is factorised (concurrently with M_B) with T_A last,
//! M_A = L_A L_Aᵀ with L_A = [L_AA 0; L_TA L_TT^A] and
//! L_TT^A L_TT^Aᵀ = K[T_A, T_A] − L_TA L_TAᵀ. The Schur complement of K on T
//! is then
//!
//!   S = K_TT − L_TA L_TAᵀ − L_TB L_TBᵀ
//!     = K_TT + Σ_p (L_TT^p L_TT^pᵀ − K[T_p, T_p])   (each on T_p × T_p),
//!
//! factorised densely as L_S L_Sᵀ, and K = LLᵀ with
//! L = [L_AA 0 0; 0 L_BB 0; L_TA L_TB L_S]. The price is that each part also
//! factorises its dense T_p block and S must be formed: small against the
//! subtrees while T is a separator or a contact interface (2054 unknowns at
//! 1M unknowns, of which each body's part holds its own side, 1027).
//!
//! Pattern entries declared zero in every matrix (the analysis's
//! `is_zero`) do not couple: a frictionless contact element with an
//! axis-aligned normal stores zeros between the tangential unknowns of the
//! two surfaces, which would otherwise join the two bodies. Each
//! factorisation checks that they are still zero.

use std::sync::{Mutex, PoisonError};

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::{
    LltRegularization, cholesky_in_place, cholesky_in_place_scratch,
};
use faer::linalg::matmul::triangular::{BlockStructure, matmul};
use faer::linalg::triangular_solve::{
    solve_lower_triangular_in_place, solve_upper_triangular_in_place,
};
use faer::sparse::linalg::cholesky::simplicial::{
    prefactorize_symbolic_cholesky, prefactorize_symbolic_cholesky_scratch,
};
use faer::sparse::linalg::cholesky::supernodal::{
    SupernodalLltRef, SymbolicSupernodalCholesky, factorize_supernodal_numeric_llt,
    factorize_supernodal_numeric_llt_scratch, factorize_supernodal_symbolic_cholesky,
    factorize_supernodal_symbolic_cholesky_scratch,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Accum, Conj, Mat, MatMut, MatRef, Par};

use super::packed::{pack_lower, packed_len};
use crate::error::{Error, Result, Status};
use crate::fem::assembly::Pattern;

/// `owner` of a separator unknown.
const TOP: u8 = 2;

fn oom(what: &str) -> Error {
    Error::new(
        Status::OutOfMemory,
        format!("cannot allocate the {what} of the split factorisation"),
    )
}

/// A Cholesky factorisation of K in two concurrent parts and a dense
/// separator block (module documentation).
pub(crate) struct SplitCholesky {
    parts: [Part; 2],
    /// The separator unknowns in factor order.
    top: Vec<usize>,
    /// Which part owns each unknown (0, 1, or [`TOP`]).
    owner: Vec<u8>,
    /// Each unknown's index within its part or within `top`.
    local: Vec<u32>,
    /// Lower Cholesky factor L_S of the Schur complement on `top`.
    top_factor: Mat<f64>,
    /// Positions of the matrix values declared zero (checked at every
    /// factorisation: the split may rely on them).
    zeros: Vec<usize>,
    /// Whether a factorisation keeps a copy of the Schur complement.
    keep_schur: bool,
    /// The Schur complement on `top` of the last factorisation (lower
    /// triangle packed by columns, [`super::packed::packed_start`]), when kept and not
    /// yet taken.
    schur: Option<Vec<f64>>,
}

/// What one numeric factorisation of a part needs besides the part:
/// allocated on the calling thread ([`SplitCholesky::factorize_parts`]).
struct Buffers {
    /// M's values, in the order of the part's `row_idx`.
    values: Vec<f64>,
    /// faer's workspace.
    workspace: MemBuffer,
    /// Each column's next position in `values` while M is copied.
    cursor: Vec<u32>,
}

/// The matrix a numeric factorisation factorises, K + shift·diag(K): both
/// parts and the separator block read their entries through it, so that
/// the shift is applied the same way everywhere.
#[derive(Clone, Copy)]
struct Shifted<'a> {
    /// The pattern of K (upper triangle).
    pattern: &'a Pattern,
    /// K's values on `pattern`.
    values: &'a [f64],
    /// The relative shift of the diagonal.
    shift: f64,
}

impl Shifted<'_> {
    /// The value at position `p` of the pattern, shifted when it is on the
    /// diagonal.
    fn value(&self, p: usize, on_diagonal: bool) -> f64 {
        if on_diagonal {
            self.values[p] * (1.0 + self.shift)
        } else {
            self.values[p]
        }
    }
}

/// Where every unknown sits, shared by both parts.
#[derive(Clone, Copy)]
struct Layout<'a> {
    /// The separator unknowns in factor order.
    top: &'a [usize],
    /// Which part owns each unknown (0, 1, or [`TOP`]).
    owner: &'a [u8],
    /// Each unknown's index within its part or within `top`.
    local: &'a [u32],
    /// Positions of the values that are zero in every matrix (empty: none
    /// known); only the analysis needs them.
    is_zero: &'a [bool],
}

fn zero_at(is_zero: &[bool], p: usize) -> bool {
    is_zero.get(p).copied().unwrap_or(false)
}

/// Marks a separator unknown that a part is not coupled to.
const NONE: u32 = u32::MAX;

/// The unknowns of one part's matrix M = K[own ∪ T_p]: what
/// [`Members::visit`] walks, both before the part exists (its analysis) and
/// after (each factorisation), so that both meet M's entries in one order.
#[derive(Clone, Copy)]
struct Members<'a> {
    /// The part (0 or 1, as in [`Layout::owner`]).
    who: u8,
    /// The part's unknowns in factor order.
    own: &'a [usize],
    /// T_p as ascending indices into the separator.
    seps: &'a [u32],
    /// Each separator index's position in `seps`, or [`NONE`].
    sep_pos: &'a [u32],
}

/// One part's factorisation of M = K[own ∪ T_p], own first, where T_p is
/// the separator unknowns coupled to the part. The others contribute
/// nothing to the part's Schur complement, so leaving them out keeps the
/// part's dense trailing front small: for a contact interface, T_p is the
/// part's own side, half of the separator.
struct Part {
    /// The part's unknowns in factor order (local indices 0..own.len()).
    own: Vec<usize>,
    /// T_p as ascending indices into the separator (local indices
    /// own.len()..).
    seps: Vec<u32>,
    /// Each separator index's position in `seps`, or [`NONE`].
    sep_pos: Vec<u32>,
    /// Lower triangle of M in local numbering (CSC), entries in the order
    /// [`Members::visit`] meets them.
    col_ptr: Vec<u32>,
    row_idx: Vec<u32>,
    symbolic: SymbolicSupernodalCholesky<u32>,
    l_values: Vec<f64>,
    factor_req: StackReq,
    /// Workspace of the triangular solves (the longest supernode pattern).
    /// The solve workspace (behind a lock, so that solves take `&self`).
    solve_mem: Mutex<MemBuffer>,
}

impl SplitCholesky {
    /// Symbolic analysis for parts `parts` (each in its fill-reducing
    /// order) and separator `top` (in factor order) of the unknowns of
    /// `pattern`, where the positions marked in `is_zero` (empty: none)
    /// hold zero in every matrix to be factorised. `None` if the parts are
    /// coupled to each other (not a dissection) or a part is empty.
    pub(crate) fn analyse(
        pattern: &Pattern,
        parts: [Vec<usize>; 2],
        top: Vec<usize>,
        is_zero: &[bool],
    ) -> Result<Option<SplitCholesky>> {
        let n = pattern.n();
        if parts.iter().any(|p| p.is_empty())
            || parts[0].len() + parts[1].len() + top.len() != n
            || n > u32::MAX as usize / 2
        {
            return Ok(None);
        }
        let mut owner = vec![u8::MAX; n];
        let mut local = vec![0u32; n];
        for (h, part) in parts.iter().enumerate() {
            for (k, &u) in part.iter().enumerate() {
                owner[u] = h as u8;
                local[u] = k as u32;
            }
        }
        for (k, &u) in top.iter().enumerate() {
            owner[u] = TOP;
            local[u] = k as u32;
        }
        if owner.contains(&u8::MAX) {
            return Ok(None);
        }
        let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
        for j in 0..n {
            for p in cp[j]..cp[j + 1] {
                let i = ri[p];
                if owner[i] != TOP
                    && owner[j] != TOP
                    && owner[i] != owner[j]
                    && !zero_at(is_zero, p)
                {
                    return Ok(None);
                }
            }
        }
        let [a, b] = parts;
        let layout = Layout {
            top: &top,
            owner: &owner,
            local: &local,
            is_zero,
        };
        let (pa, pb) = rayon::join(
            || Part::analyse(pattern, 0, a, layout),
            || Part::analyse(pattern, 1, b, layout),
        );
        let (pa, pb) = (pa?, pb?);
        let t = top.len();
        // Allocated last, once both parts hold their factors' memory: where
        // that leaves no room for it, the analysis fails cleanly.
        let mut top_factor = Mat::new();
        top_factor
            .try_reserve(t, t)
            .map_err(|_| oom("dense separator block"))?;
        top_factor.resize_with(t, t, |_, _| 0.0);
        Ok(Some(SplitCholesky {
            parts: [pa, pb],
            top,
            owner,
            local,
            top_factor,
            zeros: (0..is_zero.len()).filter(|&p| is_zero[p]).collect(),
            keep_schur: false,
            schur: None,
        }))
    }

    /// The separator unknowns in factor order.
    pub(crate) fn top(&self) -> &[usize] {
        &self.top
    }

    /// The dense lower factor of the Schur complement on [`Self::top`].
    pub(crate) fn top_factor(&self) -> MatRef<'_, f64> {
        self.top_factor.as_ref()
    }

    /// Makes every factorisation keep a copy of the Schur complement on
    /// [`Self::top`] for [`Self::take_schur`] (t(t + 1)/2 more values).
    pub(crate) fn keep_schur(&mut self) {
        self.keep_schur = true;
    }

    /// The Schur complement S on [`Self::top`] formed by the last
    /// factorisation (lower triangle packed by columns), if kept and not
    /// taken yet.
    pub(crate) fn take_schur(&mut self) -> Option<Vec<f64>> {
        self.schur.take()
    }

    /// Stored factor entries (both parts, the separator block).
    pub(crate) fn factor_nnz(&self) -> usize {
        let t = self.top.len();
        self.parts.iter().map(|p| p.l_values.len()).sum::<usize>() + t * (t + 1) / 2
    }

    /// Bytes held between factorisations.
    pub(crate) fn memory_bytes(&self) -> usize {
        let t = self.top.len();
        self.parts.iter().map(Part::held_bytes).sum::<usize>()
            + 8 * (t * t + self.top.len())
            + 5 * self.owner.len()
    }

    /// Bytes a numeric factorisation needs at its peak: what is held, plus
    /// both parts' matrix copies and workspaces (live at the same time) and
    /// the kept Schur complement.
    pub(crate) fn factorization_bytes(&self) -> usize {
        let t = self.top.len();
        self.memory_bytes()
            + if self.keep_schur {
                8 * packed_len(t)
            } else {
                0
            }
            + self
                .parts
                .iter()
                .map(|p| 8 * p.row_idx.len() + p.factor_req.unaligned_bytes_required())
                .sum::<usize>()
    }

    /// Factorises K + shift·diag(K) (upper triangle `values` on `pattern`);
    /// whether it is positive definite.
    pub(crate) fn factorize(
        &mut self,
        pattern: &Pattern,
        values: &[f64],
        shift: f64,
    ) -> Result<bool> {
        self.schur = None;
        self.check_declared_zeros(values)?;
        let matrix = Shifted {
            pattern,
            values,
            shift,
        };
        if !self.factorize_parts(matrix)? {
            return Ok(false);
        }
        self.form_schur(matrix);
        let kept = match self.keep_schur {
            true => Some(self.schur_copy()?),
            false => None,
        };
        let r = self.factorize_top()?;
        if r {
            self.schur = kept;
        }
        Ok(r)
    }

    /// Refuses values where the analysis was told of zeros: the parts were
    /// split on them, and a value there would couple them unseen.
    fn check_declared_zeros(&self, values: &[f64]) -> Result<()> {
        match self.zeros.iter().find(|&&p| values[p] != 0.0) {
            Some(&p) => Err(Error::state(format!(
                "matrix entry {p} was analysed as zero but holds {:e}",
                values[p]
            ))),
            None => Ok(()),
        }
    }

    /// Factorises both parts at the same time (the point of the split);
    /// whether both are positive definite.
    fn factorize_parts(&mut self, matrix: Shifted<'_>) -> Result<bool> {
        let layout = Layout {
            top: &self.top,
            owner: &self.owner,
            local: &self.local,
            is_zero: &[],
        };
        let [pa, pb] = &mut self.parts;
        // Buffers are allocated here, not on the worker threads, so that
        // they come from (and return to) this thread's heap rather than
        // leaving memory in per-thread allocator arenas.
        let (ba, bb) = (pa.buffers()?, pb.buffers()?);
        let (ra, rb) = rayon::join(
            || pa.factorize(matrix, layout, ba),
            || pb.factorize(matrix, layout, bb),
        );
        Ok(ra && rb)
    }

    /// Forms the Schur complement S on the separator in `top_factor`
    /// (lower triangle) from the factorised parts:
    /// S = K_TT + Σ_p (L_TT^p L_TT^pᵀ − K[T_p, T_p]). Each part's trailing
    /// product is K[T_p, T_p] minus its contribution to S, so an entry of
    /// K_TT held by both parts is subtracted once more.
    fn form_schur(&mut self, matrix: Shifted<'_>) {
        let par = Par::rayon(0);
        let s = &mut self.top_factor;
        s.fill(0.0);
        for part in &self.parts {
            part.add_trailing_product(s.as_mut(), par);
        }
        let (cp, ri) = (matrix.pattern.col_ptr(), matrix.pattern.row_idx());
        for (kj, &j) in self.top.iter().enumerate() {
            for p in cp[j]..cp[j + 1] {
                let i = ri[p];
                if self.owner[i] == TOP {
                    let ki = self.local[i] as usize;
                    let in_both =
                        |part: &Part| part.sep_pos[ki] != NONE && part.sep_pos[kj] != NONE;
                    let copies = self.parts.iter().filter(|q| in_both(q)).count() as f64;
                    let v = matrix.value(p, i == j);
                    s[(ki.max(kj), ki.min(kj))] += (1.0 - copies) * v;
                }
            }
        }
    }

    /// A packed copy of the Schur complement just formed, for
    /// [`Self::take_schur`]: the dense factorisation overwrites it.
    fn schur_copy(&self) -> Result<Vec<f64>> {
        // Packed, half of t². (It cannot live in the factor's unused
        // triangle: faer's dense Cholesky writes both, seen in 0.24.)
        let mut copy = Vec::new();
        copy.try_reserve_exact(packed_len(self.top.len()))
            .map_err(|_| oom("Schur complement copy"))?;
        pack_lower(self.top_factor.as_ref(), &mut copy);
        Ok(copy)
    }

    /// Factorises the Schur complement in `top_factor` in place (dense,
    /// the last step of the split); whether it is positive definite.
    fn factorize_top(&mut self) -> Result<bool> {
        let t = self.top.len();
        let par = Par::rayon(0);
        let mut mem =
            MemBuffer::try_new(cholesky_in_place_scratch::<f64>(t, par, Default::default()))
                .map_err(|_| oom("separator workspace"))?;
        Ok(cholesky_in_place(
            self.top_factor.as_mut(),
            LltRegularization::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .is_ok())
    }

    /// x ← K⁻¹x with the last successful factorisation.
    pub(crate) fn solve(&self, x: &mut [f64]) {
        let [pa, pb] = &self.parts;
        let xr: &[f64] = x;
        let t = self.top.len();
        // Allocated on this thread (see `factorize`).
        let (mut wa, mut wb) = (vec![0.0; pa.n()], vec![0.0; pb.n()]);
        let (mut ca, mut cb) = (vec![0.0; t], vec![0.0; t]);
        rayon::join(
            || pa.forward(xr, &mut wa, &mut ca),
            || pb.forward(xr, &mut wb, &mut cb),
        );
        // L_S L_Sᵀ x_T = b_T − L_TA y_A − L_TB y_B.
        let mut r = Mat::<f64>::zeros(self.top.len(), 1);
        for (k, &u) in self.top.iter().enumerate() {
            r[(k, 0)] = x[u] + ca[k] + cb[k];
        }
        solve_lower_triangular_in_place(self.top_factor.as_ref(), r.as_mut(), Par::Seq);
        solve_upper_triangular_in_place(self.top_factor.as_ref().transpose(), r.as_mut(), Par::Seq);
        let r = r.col(0).try_as_col_major().expect("a column").as_slice();
        rayon::join(|| pa.backward(&mut wa, r), || pb.backward(&mut wb, r));
        for (part, w) in [(pa, &wa), (pb, &wb)] {
            for (k, &u) in part.own.iter().enumerate() {
                x[u] = w[k];
            }
        }
        for (k, &u) in self.top.iter().enumerate() {
            x[u] = r[k];
        }
    }
}

impl Part {
    fn n(&self) -> usize {
        self.col_ptr.len() - 1
    }

    fn held_bytes(&self) -> usize {
        let s = &self.symbolic;
        8 * (self.l_values.len() + self.own.len())
            + 4 * (self.seps.len()
                + self.sep_pos.len()
                + self.col_ptr.len()
                + self.row_idx.len()
                + s.supernode_begin().len()
                + s.col_ptr_for_row_idx().len()
                + s.col_ptr_for_val().len()
                + s.row_idx().len())
    }

    /// The separator unknowns coupled to part `who` (its unknowns `own`),
    /// as ascending indices into the separator.
    fn coupled_separator(pattern: &Pattern, who: u8, own: &[usize], at: Layout<'_>) -> Vec<u32> {
        let mut coupled = vec![false; at.top.len()];
        let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
        // The upper triangle holds each coupling once, in the column of
        // the larger index: look in the part's columns and the separator's.
        for &j in own {
            for p in cp[j]..cp[j + 1] {
                if at.owner[ri[p]] == TOP && !zero_at(at.is_zero, p) {
                    coupled[at.local[ri[p]] as usize] = true;
                }
            }
        }
        for (k, &j) in at.top.iter().enumerate() {
            if (cp[j]..cp[j + 1]).any(|p| at.owner[ri[p]] == who && !zero_at(at.is_zero, p)) {
                coupled[k] = true;
            }
        }
        (0..at.top.len() as u32)
            .filter(|&k| coupled[k as usize])
            .collect()
    }

    fn analyse(pattern: &Pattern, who: u8, own: Vec<usize>, at: Layout<'_>) -> Result<Part> {
        let seps = Self::coupled_separator(pattern, who, &own, at);
        let mut sep_pos = vec![NONE; at.top.len()];
        for (q, &k) in seps.iter().enumerate() {
            sep_pos[k as usize] = q as u32;
        }
        let members = Members {
            who,
            own: &own,
            seps: &seps,
            sep_pos: &sep_pos,
        };
        let m = own.len() + seps.len();
        let mut col_ptr = vec![0u32; m + 1];
        members.visit(pattern, at, |c, _, _| col_ptr[c + 1] += 1);
        for k in 0..m {
            col_ptr[k + 1] += col_ptr[k];
        }
        let mut cursor = col_ptr.clone();
        let mut row_idx = vec![0u32; col_ptr[m] as usize];
        members.visit(pattern, at, |c, r, _| {
            row_idx[cursor[c] as usize] = r as u32;
            cursor[c] += 1;
        });
        // faer's symbolic analysis reads the upper triangle, its numeric
        // factorisation the lower one: the analysis gets the transpose.
        let (up_ptr, up_idx) = transpose(m, &col_ptr, &row_idx);
        let upper = SymbolicSparseColMatRef::new_unsorted_checked(m, m, &up_ptr, None, &up_idx);
        let mut etree = vec![0i32; m];
        let mut col_counts = vec![0u32; m];
        let mut mem = MemBuffer::try_new(StackReq::any_of(&[
            prefactorize_symbolic_cholesky_scratch::<u32>(m, up_idx.len()),
            factorize_supernodal_symbolic_cholesky_scratch::<u32>(m),
        ]))
        .map_err(|_| oom("symbolic workspace"))?;
        let tree = prefactorize_symbolic_cholesky(
            &mut etree,
            &mut col_counts,
            upper,
            MemStack::new(&mut mem),
        );
        let symbolic = factorize_supernodal_symbolic_cholesky(
            upper,
            tree,
            &col_counts,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .map_err(|_| oom("symbolic analysis"))?;
        drop((up_ptr, up_idx, etree, col_counts, mem));
        let factor_req = factorize_supernodal_numeric_llt_scratch::<u32, f64>(
            &symbolic,
            Par::Seq,
            Default::default(),
        );
        let solve_mem = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, Par::Seq))
            .map_err(|_| oom("solve workspace"))?;
        let mut l_values = Vec::new();
        l_values
            .try_reserve_exact(symbolic.len_val())
            .map_err(|_| oom("factor"))?;
        l_values.resize(symbolic.len_val(), 0.0);
        Ok(Part {
            own,
            seps,
            sep_pos,
            col_ptr,
            row_idx,
            symbolic,
            l_values,
            factor_req,
            solve_mem: Mutex::new(solve_mem),
        })
    }

    /// The part's members, as its analysis walked them.
    fn members(&self, who: u8) -> Members<'_> {
        Members {
            who,
            own: &self.own,
            seps: &self.seps,
            sep_pos: &self.sep_pos,
        }
    }

    /// Copies M out of `matrix` and factorises it into the part's factor;
    /// whether M is positive definite.
    fn factorize(&mut self, matrix: Shifted<'_>, at: Layout<'_>, buffers: Buffers) -> bool {
        let Buffers {
            values: mut vals,
            workspace: mut mem,
            mut cursor,
        } = buffers;
        let top_start = self.own.len();
        let who = at.owner[self.own[0]];
        self.members(who).visit(matrix.pattern, at, |c, r, p| {
            vals[cursor[c] as usize] = matrix.value(p, r == c);
            cursor[c] += 1;
        });
        drop(cursor);
        let m = self.n();
        let sym =
            SymbolicSparseColMatRef::new_unsorted_checked(m, m, &self.col_ptr, None, &self.row_idx);
        let a = SparseColMatRef::new(sym, &vals);
        let s = &self.symbolic;
        let ok = factorize_supernodal_numeric_llt(
            &mut self.l_values,
            a,
            LltRegularization::default(),
            s,
            Par::Seq,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .is_ok();
        if ok {
            self.zero_upper_of_trailing_blocks(top_start);
        }
        ok
    }

    /// The buffers of one numeric factorisation: the matrix copy, faer's
    /// workspace and the column cursors of the copy.
    fn buffers(&self) -> Result<Buffers> {
        let mut vals = Vec::new();
        vals.try_reserve_exact(self.row_idx.len())
            .map_err(|_| oom("matrix copy"))?;
        vals.resize(self.row_idx.len(), 0.0);
        let workspace = MemBuffer::try_new(self.factor_req).map_err(|_| oom("workspace"))?;
        Ok(Buffers {
            values: vals,
            workspace,
            cursor: self.col_ptr.clone(),
        })
    }

    /// Zeroes the strict upper triangles of the diagonal blocks of the
    /// supernodes holding separator columns, so that those supernodes can
    /// be multiplied as plain dense blocks.
    fn zero_upper_of_trailing_blocks(&mut self, first: usize) {
        let s = &self.symbolic;
        let (begin, end) = (s.supernode_begin(), s.supernode_end());
        let val_ptr = s.col_ptr_for_val();
        let row_ptr = s.col_ptr_for_row_idx();
        for k in 0..s.n_supernodes() {
            let (start, end) = (begin[k] as usize, end[k] as usize);
            if end <= first {
                continue;
            }
            let ncols = end - start;
            let nrows = ncols + (row_ptr[k + 1] - row_ptr[k]) as usize;
            let base = val_ptr[k] as usize;
            for c in 0..ncols {
                for r in 0..c {
                    self.l_values[base + c * nrows + r] = 0.0;
                }
            }
        }
    }

    /// Each supernode's block of separator columns.
    fn trailing_blocks(&self) -> Vec<Trailing<'_>> {
        let first = self.own.len();
        let s = &self.symbolic;
        let llt = SupernodalLltRef::new(s, &self.l_values);
        let mut out = Vec::new();
        for k in 0..s.n_supernodes() {
            let node = llt.supernode(k);
            let (start, val) = (node.start(), node.val());
            let ncols = val.ncols();
            if start + ncols <= first {
                continue;
            }
            let c0 = first.saturating_sub(start);
            let rows: Vec<usize> = (start + c0..start + ncols)
                .chain(node.pattern().iter().map(|&i| i as usize))
                .map(|i| self.seps[i - first] as usize)
                .collect();
            out.push(Trailing {
                first: start + c0 - first,
                rows,
                block: val.get(c0.., c0..),
            });
        }
        out
    }

    /// s += L_TT L_TTᵀ (lower triangle) for this part's separator block.
    fn add_trailing_product(&self, mut s: MatMut<'_, f64>, par: Par) {
        for Trailing { rows, block, .. } in self.trailing_blocks() {
            let r = rows.len();
            let contiguous = rows.last().is_some_and(|&l| l + 1 == rows[0] + r);
            if contiguous {
                matmul(
                    s.as_mut().submatrix_mut(rows[0], rows[0], r, r),
                    BlockStructure::TriangularLower,
                    Accum::Add,
                    block,
                    BlockStructure::Rectangular,
                    block.transpose(),
                    BlockStructure::Rectangular,
                    1.0,
                    par,
                );
            } else {
                let mut g = Mat::<f64>::zeros(r, r);
                matmul(
                    g.as_mut(),
                    BlockStructure::TriangularLower,
                    Accum::Replace,
                    block,
                    BlockStructure::Rectangular,
                    block.transpose(),
                    BlockStructure::Rectangular,
                    1.0,
                    par,
                );
                for b in 0..r {
                    for a in b..r {
                        s[(rows[a], rows[b])] += g[(a, b)];
                    }
                }
            }
        }
    }

    /// Forward substitution of the part: w = L⁻¹[b_own; 0], and
    /// c = L_TT w_T = −L_TA y (y = L_AA⁻¹ b_own), over the separator.
    fn forward(&self, b: &[f64], w: &mut [f64], c: &mut [f64]) {
        let first = self.own.len();
        for (k, &u) in self.own.iter().enumerate() {
            w[k] = b[u];
        }
        w[first..].fill(0.0);
        c.fill(0.0);
        let n = self.n();
        let s = &self.symbolic;
        SupernodalLltRef::new(s, &self.l_values).l_solve_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(w, n, 1),
            Par::Seq,
            MemStack::new(
                &mut self
                    .solve_mem
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner),
            ),
        );
        let wt = &w[first..];
        for Trailing {
            first: c0,
            rows,
            block,
        } in self.trailing_blocks()
        {
            for col in 0..block.ncols() {
                let x = wt[c0 + col];
                for (row, &i) in rows.iter().enumerate().skip(col) {
                    c[i] += block[(row, col)] * x;
                }
            }
        }
    }

    /// Back substitution of the part given the separator values x_T:
    /// w_own ← L_AA⁻ᵀ(y − L_TAᵀ x_T).
    fn backward(&self, w: &mut [f64], x_top: &[f64]) {
        let first = self.own.len();
        // w_T = L_TTᵀ x_T, so that the transposed solve recovers x_T there
        // and subtracts L_TAᵀ x_T from the part.
        w[first..].fill(0.0);
        for Trailing {
            first: c0,
            rows,
            block,
        } in self.trailing_blocks()
        {
            for col in 0..block.ncols() {
                let mut acc = 0.0;
                for (row, &i) in rows.iter().enumerate().skip(col) {
                    acc += block[(row, col)] * x_top[i];
                }
                w[first + c0 + col] = acc;
            }
        }
        let n = self.n();
        let s = &self.symbolic;
        SupernodalLltRef::new(s, &self.l_values).l_transpose_solve_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(w, n, 1),
            Par::Seq,
            MemStack::new(
                &mut self
                    .solve_mem
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner),
            ),
        );
    }
}

impl Members<'_> {
    /// Calls `f(column, row, position in the global values)` for every
    /// entry of the lower triangle of M in local numbering, always in the
    /// same order.
    fn visit(&self, pattern: &Pattern, at: Layout<'_>, mut f: impl FnMut(usize, usize, usize)) {
        let n_own = self.own.len();
        let lid = |u: usize| -> Option<usize> {
            match at.owner[u] {
                TOP => match self.sep_pos[at.local[u] as usize] {
                    NONE => None,
                    k => Some(n_own + k as usize),
                },
                h if h == self.who => Some(at.local[u] as usize),
                _ => None,
            }
        };
        let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
        // Every entry of M has its (global) column in own ∪ T_p.
        let top_columns = self.seps.iter().map(|&k| at.top[k as usize]);
        for j in self.own.iter().copied().chain(top_columns) {
            let lj = lid(j).expect("a column of the part");
            for p in cp[j]..cp[j + 1] {
                if let Some(li) = lid(ri[p]) {
                    f(li.min(lj), li.max(lj), p);
                }
            }
        }
    }
}

/// A supernode's block of a part's separator columns.
struct Trailing<'a> {
    /// Position in T_p of the block's first column.
    first: usize,
    /// The block's rows as separator indices (ascending): its columns'
    /// own rows first, then the rows below them.
    rows: Vec<usize>,
    /// The dense block, rows × columns.
    block: MatRef<'a, f64>,
}

/// The transpose of an m×m CSC pattern.
fn transpose(m: usize, col_ptr: &[u32], row_idx: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let mut ptr = vec![0u32; m + 1];
    for &r in row_idx {
        ptr[r as usize + 1] += 1;
    }
    for k in 0..m {
        ptr[k + 1] += ptr[k];
    }
    let mut cursor = ptr.clone();
    let mut idx = vec![0u32; row_idx.len()];
    for c in 0..m {
        for &r in &row_idx[col_ptr[c] as usize..col_ptr[c + 1] as usize] {
            idx[cursor[r as usize] as usize] = c as u32;
            cursor[r as usize] += 1;
        }
    }
    (ptr, idx)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::assembly::DofMap;
    use nalgebra::{DMatrix, DVector};

    const NX: usize = 9;
    const NY: usize = 6;

    /// A scalar diffusion matrix on an NX × NY grid of triangles with
    /// conductivities varying by element and the left column grounded.
    fn grid() -> (Pattern, Vec<f64>) {
        let node = |x: usize, y: usize| y * NX + x;
        let mut tris = Vec::new();
        for y in 0..NY - 1 {
            for x in 0..NX - 1 {
                tris.push([node(x, y), node(x + 1, y), node(x + 1, y + 1)]);
                tris.push([node(x, y), node(x + 1, y + 1), node(x, y + 1)]);
            }
        }
        let n = NX * NY;
        let dofs = DofMap::new(n, 1, |_| true);
        let p = Pattern::build(&dofs, n, &tris);
        let mut v = vec![0.0; p.nnz()];
        for (e, t) in tris.iter().enumerate() {
            let w = 1.0 + (e % 7) as f64;
            let ke = [2.0, -1.0, -1.0, -1.0, 2.0, -1.0, -1.0, -1.0, 2.0].map(|k| w * k);
            p.add_element(&mut v, t, &ke);
        }
        let cp = p.col_ptr();
        for y in 0..NY {
            let j = node(0, y);
            v[cp[j + 1] - 1] += 3.0;
        }
        (p, v)
    }

    fn dense(p: &Pattern, v: &[f64]) -> DMatrix<f64> {
        let n = p.n();
        let mut k = DMatrix::zeros(n, n);
        let (cp, ri) = (p.col_ptr(), p.row_idx());
        for j in 0..n {
            for q in cp[j]..cp[j + 1] {
                k[(ri[q], j)] = v[q];
                k[(j, ri[q])] = v[q];
            }
        }
        k
    }

    /// Asserts that the factorised `c` solves K x = b like nalgebra's dense
    /// Cholesky of `k`.
    fn assert_solves_like_dense(c: &mut SplitCholesky, k: DMatrix<f64>, b: Vec<f64>) {
        let mut x = b.clone();
        c.solve(&mut x);
        let want = k.cholesky().unwrap().solve(&DVector::from_vec(b));
        let err = (DVector::from_vec(x) - &want).amax();
        assert!(err <= 1e-12 * want.amax(), "{err}");
    }

    /// Parts left and right of the middle column x = 4, which is the
    /// separator, followed by two unknowns taken out of the parts.
    fn dissection() -> ([Vec<usize>; 2], Vec<usize>) {
        let last = [NX + 1, 3 * NX + 7];
        let keep = |u: &usize| !last.contains(u);
        let left = (0..NX * NY).filter(|u| u % NX < 4).filter(keep).collect();
        let right = (0..NX * NY).filter(|u| u % NX > 4).filter(keep).collect();
        let top = (0..NY).map(|y| y * NX + 4).chain(last).collect();
        ([left, right], top)
    }

    #[test]
    fn solves_like_a_dense_factorisation() {
        let (p, v) = grid();
        let (parts, top) = dissection();
        let mut c = SplitCholesky::analyse(&p, parts, top, &[])
            .unwrap()
            .unwrap();
        assert!(c.factorize(&p, &v, 0.0).unwrap());
        let b: Vec<f64> = (0..p.n()).map(|i| (i as f64 * 0.37).sin()).collect();
        assert_solves_like_dense(&mut c, dense(&p, &v), b);
    }

    #[test]
    fn the_separator_factor_is_that_of_the_schur_complement() {
        let (p, v) = grid();
        let (parts, top) = dissection();
        let mut c = SplitCholesky::analyse(&p, parts, top.clone(), &[])
            .unwrap()
            .unwrap();
        assert!(c.factorize(&p, &v, 0.0).unwrap());
        let k = dense(&p, &v);
        let rest: Vec<usize> = (0..p.n()).filter(|i| !top.contains(i)).collect();
        let k11 = k.select_rows(&rest).select_columns(&rest);
        let k12 = k.select_rows(&rest).select_columns(&top);
        let k22 = k.select_rows(&top).select_columns(&top);
        let s = &k22 - k12.transpose() * k11.cholesky().unwrap().solve(&k12);
        let f = c.top_factor();
        let t = top.len();
        for a in 0..t {
            for b in 0..=a {
                let llt: f64 = (0..=b).map(|m| f[(a, m)] * f[(b, m)]).sum();
                assert!(
                    (llt - s[(a, b)]).abs() <= 1e-12 * s.norm(),
                    "S[{a},{b}] = {llt} vs {}",
                    s[(a, b)]
                );
            }
        }
    }

    #[test]
    fn a_part_holds_only_the_separator_unknowns_it_is_coupled_to() {
        // A separator two columns thick: x = 4 touches only the left part,
        // x = 5 only the right one.
        let (p, v) = grid();
        let left: Vec<usize> = (0..NX * NY).filter(|u| u % NX < 4).collect();
        let right: Vec<usize> = (0..NX * NY).filter(|u| u % NX > 5).collect();
        let top: Vec<usize> = (0..NX * NY)
            .filter(|u| (4..=5).contains(&(u % NX)))
            .collect();
        let (n_left, n_right) = (left.len(), right.len());
        let mut c = SplitCholesky::analyse(&p, [left, right], top, &[])
            .unwrap()
            .unwrap();
        assert_eq!(c.parts[0].n(), n_left + NY);
        assert_eq!(c.parts[1].n(), n_right + NY);
        assert!(c.factorize(&p, &v, 0.0).unwrap());
        let b: Vec<f64> = (0..p.n()).map(|i| (i as f64 * 0.73).cos()).collect();
        assert_solves_like_dense(&mut c, dense(&p, &v), b);
    }

    #[test]
    fn a_shift_factorises_the_matrix_with_a_scaled_diagonal() {
        let (p, v) = grid();
        let (parts, top) = dissection();
        let mut c = SplitCholesky::analyse(&p, parts, top, &[])
            .unwrap()
            .unwrap();
        assert!(c.factorize(&p, &v, 0.5).unwrap());
        let mut k = dense(&p, &v);
        for i in 0..p.n() {
            k[(i, i)] *= 1.5;
        }
        let b: Vec<f64> = (0..p.n()).map(|i| 1.0 + (i % 5) as f64).collect();
        assert_solves_like_dense(&mut c, k, b);
    }

    #[test]
    fn an_indefinite_matrix_is_not_positive_definite() {
        let (p, mut v) = grid();
        let (parts, top) = dissection();
        // A separator unknown's stiffness far below its couplings.
        let cp = p.col_ptr();
        let j = top[2];
        v[cp[j + 1] - 1] = 1e-3;
        let mut c = SplitCholesky::analyse(&p, parts, top, &[])
            .unwrap()
            .unwrap();
        assert!(!c.factorize(&p, &v, 0.0).unwrap());
    }

    #[test]
    fn uncoupled_parts_need_no_separator() {
        // Two strips of triangles sharing no node.
        let n = 20;
        let mut tris = Vec::new();
        for base in [0, 10] {
            for i in 0..8 {
                tris.push([base + i, base + i + 1, base + i + 2]);
            }
        }
        let dofs = DofMap::new(n, 1, |_| true);
        let p = Pattern::build(&dofs, n, &tris);
        let mut v = vec![0.0; p.nnz()];
        for t in &tris {
            p.add_element(
                &mut v,
                t,
                &[3.0, -1.0, -1.0, -1.0, 3.0, -1.0, -1.0, -1.0, 3.0],
            );
        }
        let parts = [(0..10).collect(), (10..20).collect()];
        let mut c = SplitCholesky::analyse(&p, parts, Vec::new(), &[])
            .unwrap()
            .unwrap();
        assert!(c.factorize(&p, &v, 0.0).unwrap());
        let b: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        assert_solves_like_dense(&mut c, dense(&p, &v), b);
    }

    /// The grid cut between columns x = 4 and x = 5, with every value
    /// coupling them zeroed and the right edge grounded too: the parts
    /// [x ≤ 4] and [x ≥ 5] are coupled only through stored zeros, which
    /// `is_zero` marks.
    fn grid_cut_by_zeros() -> (Pattern, Vec<f64>, [Vec<usize>; 2], Vec<bool>) {
        let (p, mut v) = grid();
        let (cp, ri) = (p.col_ptr(), p.row_idx());
        let mut is_zero = vec![false; p.nnz()];
        for j in 0..p.n() {
            for q in cp[j]..cp[j + 1] {
                if (ri[q] % NX <= 4) != (j % NX <= 4) {
                    is_zero[q] = true;
                    v[q] = 0.0;
                }
            }
        }
        for y in 0..NY {
            let j = y * NX + NX - 1;
            v[cp[j + 1] - 1] += 3.0;
        }
        let left = (0..NX * NY).filter(|u| u % NX <= 4).collect();
        let right = (0..NX * NY).filter(|u| u % NX > 4).collect();
        (p, v, [left, right], is_zero)
    }

    #[test]
    fn parts_coupled_only_through_declared_zeros_split_without_a_separator() {
        let (p, v, parts, is_zero) = grid_cut_by_zeros();
        let mut c = SplitCholesky::analyse(&p, parts, Vec::new(), &is_zero)
            .unwrap()
            .expect("a split");
        assert!(c.factorize(&p, &v, 0.0).unwrap());
        let b: Vec<f64> = (0..p.n()).map(|i| (i as f64 * 0.41).sin()).collect();
        assert_solves_like_dense(&mut c, dense(&p, &v), b);
    }

    #[test]
    fn a_declared_zero_that_holds_a_value_fails_the_factorisation() {
        let (p, mut v, parts, is_zero) = grid_cut_by_zeros();
        let mut c = SplitCholesky::analyse(&p, parts, Vec::new(), &is_zero)
            .unwrap()
            .expect("a split");
        let q = is_zero.iter().position(|&z| z).unwrap();
        v[q] = -0.5;
        let err = c.factorize(&p, &v, 0.0).unwrap_err();
        assert_eq!(err.status(), Status::InvalidState);
        assert!(
            err.message().contains(&format!("entry {q}")),
            "{}",
            err.message()
        );
    }

    #[test]
    fn parts_coupled_to_each_other_are_refused() {
        let (p, _) = grid();
        // Without a separator, the middle column joins the left part to
        // the right one.
        let left: Vec<usize> = (0..NX * NY).filter(|u| u % NX <= 4).collect();
        let right: Vec<usize> = (0..NX * NY).filter(|u| u % NX > 4).collect();
        assert!(
            SplitCholesky::analyse(&p, [left, right], Vec::new(), &[])
                .unwrap()
                .is_none()
        );
    }
}
