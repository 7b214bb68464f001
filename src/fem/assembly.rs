//! Degree-of-freedom numbering with Dirichlet elimination, and the sparse
//! pattern of the reduced matrix, computed once per mesh so that
//! re-assembly (every contact iteration) adds into fixed positions.

use std::ops::Range;

/// Marks a DOF that is not an unknown (prescribed, or on an unused node).
pub const NOT_FREE: usize = usize::MAX;

/// Maps global DOFs (`per_node * node + component`) to unknowns and back.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    per_node: usize,
    free: Vec<usize>,
    to_global: Vec<usize>,
}

impl DofMap {
    /// Numbers the DOFs for which `is_unknown(global_dof)` holds, in
    /// increasing global order (which keeps each column's rows sorted).
    pub fn new(n_nodes: usize, per_node: usize, is_unknown: impl Fn(usize) -> bool) -> DofMap {
        let mut free = vec![NOT_FREE; n_nodes * per_node];
        let mut n_free = 0;
        for (g, f) in free.iter_mut().enumerate() {
            if is_unknown(g) {
                *f = n_free;
                n_free += 1;
            }
        }
        let mut to_global = vec![0; n_free];
        for (g, &f) in free.iter().enumerate() {
            if f != NOT_FREE {
                to_global[f] = g;
            }
        }
        DofMap {
            per_node,
            free,
            to_global,
        }
    }

    /// DOFs per node.
    pub fn per_node(&self) -> usize {
        self.per_node
    }

    /// Number of unknowns.
    pub fn n_free(&self) -> usize {
        self.to_global.len()
    }

    /// Number of global DOFs (`per_node` per node).
    pub fn n_global(&self) -> usize {
        self.free.len()
    }

    /// Unknown index of a global DOF, or [`NOT_FREE`].
    #[inline]
    pub fn free(&self, global: usize) -> usize {
        self.free[global]
    }

    /// The global DOF of every unknown (increasing).
    pub fn free_to_global(&self) -> &[usize] {
        &self.to_global
    }

    /// The values of a global vector at the unknowns.
    pub fn gather(&self, global: &[f64]) -> Vec<f64> {
        self.to_global.iter().map(|&g| global[g]).collect()
    }

    /// The global vector with `x` at the unknowns and `prescribed` (a
    /// global vector) elsewhere.
    pub fn expand(&self, x: &[f64], prescribed: &[f64]) -> Vec<f64> {
        let mut u = prescribed.to_vec();
        for (&g, &v) in self.to_global.iter().zip(x) {
            u[g] = v;
        }
        u
    }

    /// The global DOFs of a triangle, node-major.
    pub fn element_dofs(&self, tri: &[usize; 3], out: &mut [usize]) {
        let p = self.per_node;
        for (a, &v) in tri.iter().enumerate() {
            for c in 0..p {
                out[a * p + c] = p * v + c;
            }
        }
    }
}

/// Upper-triangular CSC pattern of the reduced (free-DOF) matrix.
#[derive(Debug, Clone)]
pub struct Pattern {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
}

/// Where the off-diagonal node blocks of one vector triangle sit in a
/// [`Pattern`] ([`Pattern::slots`]): for its node pairs (0, 1), (0, 2) and
/// (1, 2), the offset, within the column of the pair's later first
/// unknown, of the row of its earlier one.
///
/// A full scatter map would take 4 bytes per element entry (84 MB at 1M
/// unknowns); these take 6 bytes per triangle (6 MB at 1M unknowns) and
/// replace the three column searches per triangle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Slots([u16; 3]);

impl Slots {
    /// For a triangle that has no slots (a prescribed DOF, unknowns not
    /// numbered in node pairs, or a column too long for 16 bits): its
    /// positions are searched.
    pub const SEARCH: Slots = Slots([u16::MAX; 3]);
}

/// The values of a contiguous range of a [`Pattern`]'s columns
/// ([`Pattern::split_columns`]).
pub struct Columns<'v> {
    range: Range<usize>,
    values: &'v mut [f64],
}

impl Columns<'_> {
    /// The columns (unknowns) covered.
    pub fn range(&self) -> Range<usize> {
        self.range.clone()
    }

    /// Sets every value of the range to zero.
    pub fn clear(&mut self) {
        self.values.fill(0.0);
    }
}

impl Pattern {
    /// Builds the pattern of the given triangles (any mix of bodies and
    /// contact elements) on the unknowns of `dofs`.
    pub fn build(dofs: &DofMap, n_nodes: usize, elements: &[[usize; 3]]) -> Pattern {
        let p = dofs.per_node();
        // Node adjacency (with self), as CSR, sorted and deduplicated.
        let mut count = vec![0usize; n_nodes + 1];
        for tri in elements {
            for &v in tri {
                count[v + 1] += 3;
            }
        }
        for i in 0..n_nodes {
            count[i + 1] += count[i];
        }
        let mut adj = vec![0usize; count[n_nodes]];
        let mut fill = count.clone();
        for tri in elements {
            for &v in tri {
                for &w in tri {
                    adj[fill[v]] = w;
                    fill[v] += 1;
                }
            }
        }
        let mut adj_ptr = vec![0usize; n_nodes + 1];
        let mut write = 0;
        for v in 0..n_nodes {
            let seg = &mut adj[count[v]..count[v + 1]];
            seg.sort_unstable();
            let mut last = usize::MAX;
            let start = count[v];
            for r in 0..seg.len() {
                let w = adj[start + r];
                if w != last {
                    adj[write] = w;
                    write += 1;
                    last = w;
                }
            }
            adj_ptr[v + 1] = write;
        }
        adj.truncate(write);

        let n = dofs.n_free();
        let mut col_ptr = Vec::with_capacity(n + 1);
        col_ptr.push(0);
        let mut row_idx = Vec::new();
        for v in 0..n_nodes {
            for c in 0..p {
                let j = dofs.free(p * v + c);
                if j == NOT_FREE {
                    continue;
                }
                for &w in &adj[adj_ptr[v]..adj_ptr[v + 1]] {
                    for c2 in 0..p {
                        let i = dofs.free(p * w + c2);
                        if i != NOT_FREE && i <= j {
                            row_idx.push(i);
                        }
                    }
                }
                col_ptr.push(row_idx.len());
            }
        }
        debug_assert_eq!(col_ptr.len(), n + 1);
        drop(adj);
        Pattern {
            n,
            col_ptr,
            row_idx,
        }
    }

    /// Number of unknowns (rows = columns).
    pub fn n(&self) -> usize {
        self.n
    }

    /// Stored entries of the upper triangle.
    pub fn nnz(&self) -> usize {
        self.row_idx.len()
    }

    /// Column pointers (CSC).
    pub fn col_ptr(&self) -> &[usize] {
        &self.col_ptr
    }

    /// Row indices (CSC, sorted within each column).
    pub fn row_idx(&self) -> &[usize] {
        &self.row_idx
    }

    /// Position in the values of the entry coupling unknowns `i` and `j`
    /// (either order), if the pattern stores it.
    pub fn position(&self, i: usize, j: usize) -> Option<usize> {
        let (i, j) = (i.min(j), i.max(j));
        if j >= self.n {
            return None;
        }
        let base = self.col_ptr[j];
        self.row_idx[base..self.col_ptr[j + 1]]
            .binary_search(&i)
            .ok()
            .map(|k| base + k)
    }

    /// Adds the dense k x k element matrix `ke` (row-major) on the
    /// unknowns `unknowns` (k of them; [`NOT_FREE`] for a prescribed DOF,
    /// whose rows and columns are skipped) into the upper-triangle `values`.
    ///
    /// Positions are found by search in the (short, sorted) columns; see
    /// [`Slots`] for a compact precomputed map.
    /// Panics if an entry lies outside the pattern (an element that was not
    /// given to [`Pattern::build`]).
    pub fn add_element(&self, values: &mut [f64], unknowns: &[usize], ke: &[f64]) {
        self.add_element_in(
            &mut Columns {
                range: 0..self.n,
                values,
            },
            unknowns,
            ke,
        );
    }

    /// The values of columns [0, mid) and [mid, n), to be assembled at the
    /// same time.
    pub fn split_columns<'v>(
        &self,
        mid: usize,
        values: &'v mut [f64],
    ) -> (Columns<'v>, Columns<'v>) {
        let (lo, hi) = values.split_at_mut(self.col_ptr[mid]);
        (
            Columns {
                range: 0..mid,
                values: lo,
            },
            Columns {
                range: mid..self.n,
                values: hi,
            },
        )
    }

    /// [`Pattern::add_element`] restricted to the entries whose column
    /// lies in the range of `cols`.
    pub fn add_element_in(&self, cols: &mut Columns<'_>, unknowns: &[usize], ke: &[f64]) {
        let k = unknowns.len();
        debug_assert_eq!(ke.len(), k * k);
        if is_vector_triangle(unknowns) {
            let cp = &self.col_ptr;
            self.add_vector_element(cols, unknowns, ke, |_, j, i| {
                self.row_idx[cp[j]..cp[j + 1]]
                    .binary_search(&i)
                    .expect("the pattern holds every entry of its elements")
            });
            return;
        }
        let off = self.col_ptr[cols.range.start];
        for (b, &j) in unknowns.iter().enumerate() {
            if j == NOT_FREE || !cols.range.contains(&j) {
                continue;
            }
            let base = self.col_ptr[j];
            let col = &self.row_idx[base..self.col_ptr[j + 1]];
            for (a, &i) in unknowns.iter().enumerate() {
                // Each unordered pair once, in the column of the larger.
                if i == NOT_FREE || i > j || (i == j && a != b) {
                    continue;
                }
                let pos = col
                    .binary_search(&i)
                    .expect("the pattern holds every entry of its elements");
                cols.values[base + pos - off] += ke[a * k + b];
            }
        }
    }

    /// The [`Slots`] of the triangle on `unknowns` (six, per node in
    /// turn), or [`Slots::SEARCH`]. Panics, like [`Pattern::add_element`],
    /// if the triangle was not given to [`Pattern::build`].
    pub fn slots(&self, unknowns: &[usize]) -> Slots {
        if !is_vector_triangle(unknowns) {
            return Slots::SEARCH;
        }
        let first = [unknowns[0], unknowns[2], unknowns[4]];
        let mut slots = [0u16; 3];
        for (pair, (v, w)) in [(0, 1), (0, 2), (1, 2)].into_iter().enumerate() {
            let (i, j) = (first[v].min(first[w]), first[v].max(first[w]));
            let col = &self.row_idx[self.col_ptr[j]..self.col_ptr[j + 1]];
            let at = col
                .binary_search(&i)
                .expect("the pattern holds every entry of its elements");
            match u16::try_from(at) {
                Ok(at) if at != u16::MAX => slots[pair] = at,
                _ => return Slots::SEARCH,
            }
        }
        Slots(slots)
    }

    /// [`Pattern::add_element_in`] for a triangle whose [`Slots`] were
    /// computed on this pattern (by [`Pattern::slots`] with the same
    /// unknowns): no search.
    pub fn add_element_at(
        &self,
        cols: &mut Columns<'_>,
        unknowns: &[usize],
        ke: &[f64],
        slots: Slots,
    ) {
        if slots == Slots::SEARCH {
            self.add_element_in(cols, unknowns, ke);
            return;
        }
        debug_assert!(is_vector_triangle(unknowns));
        self.add_vector_element(cols, unknowns, ke, |pair, _, _| slots.0[pair] as usize);
    }

    /// [`Pattern::add_element_in`] for a vector triangle (two free unknowns
    /// per node, numbered consecutively; the common case): the columns of a
    /// node's two unknowns hold the same rows below it, so one position per
    /// pair of nodes places all four entries of their block, and diagonal
    /// blocks sit at the ends of their columns. `offset(pair, j, i)` is
    /// where row i sits in column j, for node pair `pair` as in [`Slots`].
    fn add_vector_element(
        &self,
        cols: &mut Columns<'_>,
        unknowns: &[usize],
        ke: &[f64],
        offset: impl Fn(usize, usize, usize) -> usize,
    ) {
        let cp = &self.col_ptr;
        let off = cp[cols.range.start];
        let first = [unknowns[0], unknowns[2], unknowns[4]];
        let values = &mut *cols.values;
        for v in 0..3 {
            let j = first[v];
            // The node's two columns j and j + 1 (a range may end between).
            let (in_a, in_b) = (cols.range.contains(&j), cols.range.contains(&(j + 1)));
            if !(in_a || in_b) {
                continue;
            }
            let (a, b) = (2 * v, 2 * v + 1);
            debug_assert_eq!(self.row_idx[cp[j + 1] - 1], j);
            if in_a {
                values[cp[j + 1] - 1 - off] += ke[a * 6 + a];
            }
            if in_b {
                values[cp[j + 2] - 2 - off] += ke[a * 6 + b];
                values[cp[j + 2] - 1 - off] += ke[b * 6 + b];
            }
            for w in 0..3 {
                let i = first[w];
                if i >= j {
                    continue;
                }
                // Pairs (0, 1), (0, 2), (1, 2) are numbered v + w − 1.
                let pos = cp[j] + offset(v + w - 1, j, i);
                debug_assert_eq!(self.row_idx[pos], i);
                let next = cp[j + 1] + (pos - cp[j]);
                debug_assert_eq!(self.row_idx[next + 1], i + 1);
                let (c, d) = (2 * w, 2 * w + 1);
                if in_a {
                    values[pos - off] += ke[c * 6 + a];
                    values[pos + 1 - off] += ke[d * 6 + a];
                }
                if in_b {
                    values[next - off] += ke[c * 6 + b];
                    values[next + 1 - off] += ke[d * 6 + b];
                }
            }
        }
    }

    /// Bytes held by the pattern.
    pub fn memory_bytes(&self) -> usize {
        (self.col_ptr.len() + self.row_idx.len()) * std::mem::size_of::<usize>()
    }

    /// y = A x for the symmetric matrix whose upper triangle is `values`.
    pub fn sym_mul(&self, values: &[f64], x: &[f64], y: &mut [f64]) {
        sym_mul_upper(&self.col_ptr, &self.row_idx, values, x, y);
    }
}

/// y = A x for the symmetric matrix whose upper triangle is stored in
/// compressed sparse columns (`col_ptr`, `row_idx`, `values`).
pub(crate) fn sym_mul_upper(
    col_ptr: &[usize],
    row_idx: &[usize],
    values: &[f64],
    x: &[f64],
    y: &mut [f64],
) {
    y.fill(0.0);
    for (j, w) in col_ptr.windows(2).enumerate() {
        for p in w[0]..w[1] {
            let (i, a) = (row_idx[p], values[p]);
            y[i] += a * x[j];
            if i != j {
                y[j] += a * x[i];
            }
        }
    }
}

/// Whether `unknowns` are those of a vector triangle: six, two free ones
/// per node, numbered consecutively.
fn is_vector_triangle(unknowns: &[usize]) -> bool {
    unknowns.len() == 6
        && unknowns
            .chunks(2)
            .all(|c| c[0] != NOT_FREE && c[1] == c[0] + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pattern_of_two_triangles_with_a_fixed_node() {
        // Square 0-1-2-3 split along 0-2; node 0 fully fixed (scalar DOFs).
        let dofs = DofMap::new(4, 1, |g| g != 0);
        let tris = [[0, 1, 2], [0, 2, 3]];
        let p = Pattern::build(&dofs, 4, &tris);
        assert_eq!(p.n(), 3);
        // Unknowns 0,1,2 = nodes 1,2,3; node 1 and node 3 are not adjacent.
        assert_eq!(p.col_ptr(), &[0, 1, 3, 5]);
        assert_eq!(p.row_idx(), &[0, 0, 1, 1, 2]);
        let mut values = vec![0.0; p.nnz()];
        let ke = [1.0, 2.0, 3.0, 2.0, 4.0, 5.0, 3.0, 5.0, 6.0];
        p.add_element(&mut values, &[NOT_FREE, 0, 1], &ke);
        // Element 0 = nodes (0,1,2): node 0 dropped; (1,1)=4, (1,2)=5, (2,2)=6.
        assert_eq!(values, vec![4.0, 5.0, 6.0, 0.0, 0.0]);
    }

    #[test]
    fn position_finds_stored_entries_in_either_order_and_only_those() {
        let dofs = DofMap::new(4, 1, |g| g != 0);
        let p = Pattern::build(&dofs, 4, &[[0, 1, 2], [0, 2, 3]]);
        // Upper-triangle storage: (0,0) (0,1) (1,1) (1,2) (2,2).
        assert_eq!(p.position(1, 2), Some(3));
        assert_eq!(p.position(2, 1), Some(3));
        assert_eq!(p.position(0, 0), Some(0));
        // Nodes 1 and 3 share no element; unknown 3 does not exist.
        assert_eq!(p.position(0, 2), None);
        assert_eq!(p.position(1, 3), None);
    }

    #[test]
    fn assembling_column_ranges_separately_gives_the_whole_assembly() {
        // Two vector triangles (the fast path) and one with a fixed DOF
        // (the general path); every cut, including between a node's two
        // columns.
        let tris = [[0, 1, 2], [2, 3, 0], [3, 4, 2]];
        let dofs = DofMap::new(5, 2, |g| g != 9);
        let p = Pattern::build(&dofs, 5, &tris);
        let ke: Vec<f64> = (0..36)
            .map(|q| (1 + (q / 6).min(q % 6) * 6 + (q / 6).max(q % 6)) as f64)
            .collect();
        let add_all = |cols: &mut Columns<'_>| {
            for t in &tris {
                let mut u = [0; 6];
                dofs.element_dofs(t, &mut u);
                let u = u.map(|g| dofs.free(g));
                p.add_element_in(cols, &u, &ke);
            }
        };
        let mut whole = vec![0.0; p.nnz()];
        add_all(&mut p.split_columns(p.n(), &mut whole).0);
        for cut in 0..=p.n() {
            let mut parts = vec![0.0; p.nnz()];
            let (mut lo, mut hi) = p.split_columns(cut, &mut parts);
            add_all(&mut lo);
            add_all(&mut hi);
            assert_eq!(parts, whole, "cut at column {cut}");
        }
    }

    #[test]
    fn slots_place_every_entry_where_the_column_search_does() {
        // Two vector triangles and one with a prescribed DOF (no slots).
        let tris = [[0, 1, 2], [2, 3, 0], [3, 4, 2]];
        let dofs = DofMap::new(5, 2, |g| g != 9);
        let p = Pattern::build(&dofs, 5, &tris);
        let unknowns: Vec<[usize; 6]> = tris
            .iter()
            .map(|t| {
                let mut u = [0; 6];
                dofs.element_dofs(t, &mut u);
                u.map(|g| dofs.free(g))
            })
            .collect();
        let slots: Vec<Slots> = unknowns.iter().map(|u| p.slots(u)).collect();
        assert_ne!(slots[0], Slots::SEARCH);
        assert_ne!(slots[1], Slots::SEARCH);
        assert_eq!(slots[2], Slots::SEARCH);
        let ke: Vec<f64> = (0..36)
            .map(|q| (1 + (q / 6).min(q % 6) * 6 + (q / 6).max(q % 6)) as f64)
            .collect();
        let mut searched = vec![0.0; p.nnz()];
        for u in &unknowns {
            p.add_element(&mut searched, u, &ke);
        }
        for cut in 0..=p.n() {
            let mut placed = vec![0.0; p.nnz()];
            let (mut lo, mut hi) = p.split_columns(cut, &mut placed);
            for (u, &s) in unknowns.iter().zip(&slots) {
                p.add_element_at(&mut lo, u, &ke, s);
                p.add_element_at(&mut hi, u, &ke, s);
            }
            assert_eq!(placed, searched, "cut at column {cut}");
        }
    }

    /// Dense symmetric matrix of `values` (upper triangle) on `p`.
    fn dense(p: &Pattern, values: &[f64]) -> Vec<Vec<f64>> {
        let mut a = vec![vec![0.0; p.n()]; p.n()];
        for j in 0..p.n() {
            for q in p.col_ptr()[j]..p.col_ptr()[j + 1] {
                let i = p.row_idx()[q];
                a[i][j] = values[q];
                a[j][i] = values[q];
            }
        }
        a
    }

    /// Assembles two vector triangles sharing an edge with the given free
    /// DOFs and compares with the dense sum of their element matrices.
    fn check_vector_assembly(is_unknown: impl Fn(usize) -> bool) {
        let tris = [[0, 1, 2], [2, 3, 0]];
        let dofs = DofMap::new(4, 2, is_unknown);
        let p = Pattern::build(&dofs, 4, &tris);
        let mut values = vec![0.0; p.nnz()];
        let mut expected = vec![vec![0.0; p.n()]; p.n()];
        for (e, tri) in tris.iter().enumerate() {
            // A symmetric matrix whose entries all differ.
            let ke: Vec<f64> = (0..36)
                .map(|q| {
                    let (a, b) = (q / 6, q % 6);
                    (1 + a.min(b) * 6 + a.max(b) + 40 * e) as f64
                })
                .collect();
            let mut gd = [0; 6];
            dofs.element_dofs(tri, &mut gd);
            let free = gd.map(|g| dofs.free(g));
            p.add_element(&mut values, &free, &ke);
            for a in 0..6 {
                for b in 0..6 {
                    if free[a] != NOT_FREE && free[b] != NOT_FREE {
                        expected[free[a]][free[b]] += ke[a * 6 + b];
                    }
                }
            }
        }
        assert_eq!(dense(&p, &values), expected);
    }

    #[test]
    fn vector_elements_with_all_dofs_free_assemble_exactly() {
        check_vector_assembly(|_| true);
    }

    #[test]
    fn vector_elements_with_prescribed_dofs_assemble_exactly() {
        check_vector_assembly(|g| g != 3 && g != 4);
    }

    #[test]
    fn symmetric_product_uses_both_triangles() {
        let dofs = DofMap::new(3, 1, |_| true);
        let p = Pattern::build(&dofs, 3, &[[0, 1, 2]]);
        let mut v = vec![0.0; p.nnz()];
        p.add_element(
            &mut v,
            &[0, 1, 2],
            &[2.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 2.0],
        );
        let mut y = vec![0.0; 3];
        p.sym_mul(&v, &[1.0, 1.0, 1.0], &mut y);
        assert_eq!(y, vec![1.0, 0.0, 1.0]);
    }
}
