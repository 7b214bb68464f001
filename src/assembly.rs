//! Degree-of-freedom numbering with Dirichlet elimination, and a sparse
//! pattern computed once with a precomputed scatter map per element, so
//! that re-assembly (every contact iteration) is a pure scatter-add.

use crate::error::{Error, Result, Status};

/// Marks a DOF that is not an unknown (prescribed, or on an unused node).
pub const NOT_FREE: usize = usize::MAX;
const NO_SLOT: u32 = u32::MAX;

/// Maps global DOFs (`per_node * node + component`) to unknowns.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    per_node: usize,
    free: Vec<usize>,
    n_free: usize,
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
        DofMap {
            per_node,
            free,
            n_free,
        }
    }

    /// DOFs per node.
    pub fn per_node(&self) -> usize {
        self.per_node
    }

    /// Number of unknowns.
    pub fn n_free(&self) -> usize {
        self.n_free
    }

    /// Unknown index of a global DOF, or [`NOT_FREE`].
    pub fn free(&self, global: usize) -> usize {
        self.free[global]
    }

    /// The global DOF of every unknown.
    pub fn free_to_global(&self) -> Vec<usize> {
        let mut out = vec![0; self.n_free];
        for (g, &f) in self.free.iter().enumerate() {
            if f != NOT_FREE {
                out[f] = g;
            }
        }
        out
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

/// Upper-triangular CSC pattern of the reduced (free-DOF) matrix, plus the
/// slot of every upper-triangle entry of every element matrix.
#[derive(Debug, Clone)]
pub struct Pattern {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    k: usize,
    slots: Vec<u32>,
}

impl Pattern {
    /// Builds the pattern of the given triangles (any mix of bodies and
    /// contact elements) on the unknowns of `dofs`.
    pub fn build(dofs: &DofMap, n_nodes: usize, elements: &[[usize; 3]]) -> Result<Pattern> {
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
        if row_idx.len() >= NO_SLOT as usize {
            return Err(Error::new(
                Status::OutOfMemory,
                format!(
                    "the matrix has {} stored entries, more than the 2^32 - 1 this version supports",
                    row_idx.len()
                ),
            ));
        }
        drop(adj);

        let k = 3 * p;
        let per_elem = k * (k + 1) / 2;
        let mut slots = vec![NO_SLOT; elements.len() * per_elem];
        let mut gd = vec![0usize; k];
        for (e, tri) in elements.iter().enumerate() {
            dofs.element_dofs(tri, &mut gd);
            let out = &mut slots[e * per_elem..(e + 1) * per_elem];
            let mut s = 0;
            for a in 0..k {
                for b in a..k {
                    let (fa, fb) = (dofs.free(gd[a]), dofs.free(gd[b]));
                    if fa != NOT_FREE && fb != NOT_FREE {
                        let (i, j) = (fa.min(fb), fa.max(fb));
                        let col = &row_idx[col_ptr[j]..col_ptr[j + 1]];
                        let pos = col
                            .binary_search(&i)
                            .expect("pattern holds every element entry");
                        out[s] = (col_ptr[j] + pos) as u32;
                    }
                    s += 1;
                }
            }
        }
        Ok(Pattern {
            n,
            col_ptr,
            row_idx,
            k,
            slots,
        })
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

    /// Adds the upper triangle of element `e`'s dense k x k matrix into
    /// `values`; entries on prescribed DOFs are skipped.
    pub fn add_element(&self, values: &mut [f64], e: usize, ke: &[f64]) {
        let k = self.k;
        let per_elem = k * (k + 1) / 2;
        let slots = &self.slots[e * per_elem..(e + 1) * per_elem];
        let mut s = 0;
        for a in 0..k {
            for b in a..k {
                let slot = slots[s];
                if slot != NO_SLOT {
                    values[slot as usize] += ke[a * k + b];
                }
                s += 1;
            }
        }
    }

    /// Bytes held by the pattern and the scatter map.
    pub fn memory_bytes(&self) -> usize {
        (self.col_ptr.len() + self.row_idx.len()) * std::mem::size_of::<usize>()
            + self.slots.len() * std::mem::size_of::<u32>()
    }

    /// y = A x for the symmetric matrix whose upper triangle is `values`.
    pub fn sym_mul(&self, values: &[f64], x: &[f64], y: &mut [f64]) {
        y.fill(0.0);
        for j in 0..self.n {
            for p in self.col_ptr[j]..self.col_ptr[j + 1] {
                let i = self.row_idx[p];
                let a = values[p];
                y[i] += a * x[j];
                if i != j {
                    y[j] += a * x[i];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pattern_of_two_triangles_with_a_fixed_node() {
        // Square 0-1-2-3 split along 0-2; node 0 fully fixed (scalar DOFs).
        let dofs = DofMap::new(4, 1, |g| g != 0);
        let tris = [[0, 1, 2], [0, 2, 3]];
        let p = Pattern::build(&dofs, 4, &tris).unwrap();
        assert_eq!(p.n(), 3);
        // Unknowns 0,1,2 = nodes 1,2,3; node 1 and node 3 are not adjacent.
        assert_eq!(p.col_ptr(), &[0, 1, 3, 5]);
        assert_eq!(p.row_idx(), &[0, 0, 1, 1, 2]);
        let mut values = vec![0.0; p.nnz()];
        let ke = [1.0, 2.0, 3.0, 2.0, 4.0, 5.0, 3.0, 5.0, 6.0];
        p.add_element(&mut values, 0, &ke);
        // Element 0 = nodes (0,1,2): node 0 dropped; (1,1)=4, (1,2)=5, (2,2)=6.
        assert_eq!(values, vec![4.0, 5.0, 6.0, 0.0, 0.0]);
    }

    #[test]
    fn symmetric_product_uses_both_triangles() {
        let dofs = DofMap::new(3, 1, |_| true);
        let p = Pattern::build(&dofs, 3, &[[0, 1, 2]]).unwrap();
        let mut v = vec![0.0; p.nnz()];
        p.add_element(
            &mut v,
            0,
            &[2.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 2.0],
        );
        let mut y = vec![0.0; 3];
        p.sym_mul(&v, &[1.0, 1.0, 1.0], &mut y);
        assert_eq!(y, vec![1.0, 0.0, 1.0]);
    }
}
