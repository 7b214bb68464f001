//! Fill-reducing orderings for the sparse Cholesky factorisation.
//!
//! faer's AMD works on the graph alone. For finite-element meshes (2D, and
//! the 3D studies through [`crate::linalg::Cholesky::analyse_ordered`]) a
//! geometric nested dissection does better on large meshes: split the
//! unknowns at the median coordinate along the longer extent, take the
//! unknowns of one half adjacent to the other as the separator, recurse, and
//! number separators last. (METIS would be the general tool; a crate binding
//! it needs a C toolchain and libmetis at build time, which the core avoids.)

/// Which fill-reducing ordering the factorisation uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ordering {
    /// Nested dissection above [`Ordering::AUTO_THRESHOLD`] unknowns, AMD below.
    #[default]
    Auto,
    /// faer's approximate minimum degree.
    Amd,
    /// Geometric nested dissection on the node coordinates.
    NestedDissection,
}

impl Ordering {
    /// Size from which [`Ordering::Auto`] picks nested dissection.
    /// (Measured on the seed scene, whole contact solve with its analysis,
    /// median of 5–7 runs, AMD time over ND time: 0.84 at 4.5k unknowns,
    /// 0.86 at 6.7k, 1.03 at 8.3k, 1.17 at 9.8k, 1.10 at 17k, 1.42 at 35k,
    /// 1.68 at 67k. It was 50 000, which left 10k–50k on the slower AMD.)
    pub const AUTO_THRESHOLD: usize = 10_000;

    /// Whether nested dissection is used for `n` unknowns.
    pub fn use_nested_dissection(self, n: usize) -> bool {
        match self {
            Ordering::Auto => n >= Ordering::AUTO_THRESHOLD,
            Ordering::Amd => false,
            Ordering::NestedDissection => true,
        }
    }
}

/// Subsets smaller than this are numbered as they come. (Measured on the
/// seed scene: 16 gives a factor 7 % smaller and 4–8 % faster than 64 at
/// 67k … 1M unknowns; 8 is no better.)
const LEAF: usize = 16;

/// The adjacency of a symmetric graph (both triangles, no self loops).
pub(crate) struct Graph {
    xadj: Vec<usize>,
    adj: Vec<usize>,
}

impl Graph {
    /// The graph of the upper-triangular CSC pattern (`col_ptr`, `row_idx`).
    pub(crate) fn from_upper(col_ptr: &[usize], row_idx: &[usize]) -> Graph {
        let n = col_ptr.len() - 1;
        let mut xadj = vec![0usize; n + 1];
        for j in 0..n {
            for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
                if i != j {
                    xadj[i + 1] += 1;
                    xadj[j + 1] += 1;
                }
            }
        }
        for k in 0..n {
            xadj[k + 1] += xadj[k];
        }
        let mut adj = vec![0usize; xadj[n]];
        let mut fill = xadj.clone();
        for j in 0..n {
            for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
                if i != j {
                    adj[fill[i]] = j;
                    fill[i] += 1;
                    adj[fill[j]] = i;
                    fill[j] += 1;
                }
            }
        }
        Graph { xadj, adj }
    }

    fn n(&self) -> usize {
        self.xadj.len() - 1
    }

    fn neighbours(&self, v: usize) -> &[usize] {
        &self.adj[self.xadj[v]..self.xadj[v + 1]]
    }
}

/// One dissection step: splits `set` at the median coordinate along its
/// longer extent into (left, right, separator), the separator being the
/// right vertices adjacent to the left ones. Gives `set` back when all its
/// coordinates are equal along that axis. `mark` is all zero on entry and
/// on exit.
#[allow(clippy::type_complexity)]
fn bisect<const D: usize>(
    graph: &Graph,
    coords: &[[f64; D]],
    set: Vec<usize>,
    mark: &mut [bool],
) -> std::result::Result<(Vec<usize>, Vec<usize>, Vec<usize>), Vec<usize>> {
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for &v in &set {
        for k in 0..D {
            lo[k] = lo[k].min(coords[v][k]);
            hi[k] = hi[k].max(coords[v][k]);
        }
    }
    // The longest extent; the first axis among equals (in 2D: y only when
    // strictly longer than x).
    let mut axis = 0;
    for k in 1..D {
        if hi[k] - lo[k] > hi[axis] - lo[axis] {
            axis = k;
        }
    }
    let mut sorted = set;
    let mid = sorted.len() / 2;
    sorted.select_nth_unstable_by(mid, |&a, &b| coords[a][axis].total_cmp(&coords[b][axis]));
    let m = coords[sorted[mid]][axis];
    let (left, right): (Vec<usize>, Vec<usize>) =
        sorted.into_iter().partition(|&v| coords[v][axis] < m);
    if left.is_empty() {
        return Err(right);
    }
    for &v in &left {
        mark[v] = true;
    }
    let (sep, rest): (Vec<usize>, Vec<usize>) = right
        .into_iter()
        .partition(|&v| graph.neighbours(v).iter().any(|&w| mark[w]));
    for &v in &left {
        mark[v] = false;
    }
    Ok((left, rest, sep))
}

/// Nested-dissection order of the vertices in `set` (a subset of the
/// graph's vertices with no edge to the rest of the graph other than through
/// vertices numbered after them).
fn dissect<const D: usize>(
    graph: &Graph,
    coords: &[[f64; D]],
    set: Vec<usize>,
    mark: &mut [bool],
) -> Vec<usize> {
    let mut out = Vec::with_capacity(set.len());
    // Explicit stack: (subset, separator to append after both halves).
    enum Task {
        Split(Vec<usize>),
        Emit(Vec<usize>),
    }
    let mut stack = vec![Task::Split(set)];
    while let Some(task) = stack.pop() {
        let set = match task {
            Task::Emit(sep) => {
                out.extend(sep);
                continue;
            }
            Task::Split(set) => set,
        };
        if set.len() <= LEAF {
            out.extend(set);
            continue;
        }
        match bisect(graph, coords, set, mark) {
            // All coordinates equal along the axis: nothing to split on.
            Err(set) => out.extend(set),
            Ok((left, rest, sep)) => {
                // Processed in reverse: left, then rest, then the separator.
                stack.push(Task::Emit(sep));
                stack.push(Task::Split(rest));
                stack.push(Task::Split(left));
            }
        }
    }
    out
}

/// Nested-dissection permutation (`perm[new] = old`) of the symmetric graph
/// given by the upper-triangular CSC pattern (`col_ptr`, `row_idx`), with a
/// point per vertex in D dimensions (planes cut across the longest extent).
pub fn nested_dissection<const D: usize>(
    col_ptr: &[usize],
    row_idx: &[usize],
    coords: &[[f64; D]],
) -> Vec<usize> {
    let graph = Graph::from_upper(col_ptr, row_idx);
    let mut mark = vec![false; graph.n()];
    dissect(&graph, coords, (0..graph.n()).collect(), &mut mark)
}

/// The top level of a dissection for a factorisation in two independent
/// parts: the vertices split into two parts with no edge between them and a
/// separator, each part in nested-dissection order (the separator as it
/// comes). Disconnected pieces (two bodies once their contact interface is
/// numbered last) are shared out whole when that balances the parts within
/// 1:3; otherwise the graph is bisected geometrically. `None` when no split
/// leaves two nonempty parts.
pub(crate) fn split_in_two(
    graph: &Graph,
    coords: &[[f64; 2]],
) -> Option<([Vec<usize>; 2], Vec<usize>)> {
    let n = graph.n();
    let mut mark = vec![false; n];
    let (parts, sep) = match two_bins_of_components(graph) {
        Some(parts) => (parts, Vec::new()),
        None => {
            let (left, right, sep) = bisect(graph, coords, (0..n).collect(), &mut mark).ok()?;
            ([left, right], sep)
        }
    };
    if parts.iter().any(|p| p.is_empty()) {
        return None;
    }
    let [a, b] = parts;
    let (a, b) = rayon::join(
        || dissect(graph, coords, a, &mut mark),
        || dissect(graph, coords, b, &mut vec![false; n]),
    );
    Some(([a, b], sep))
}

/// The connected components shared into two bins, largest first into the
/// lighter bin; `None` for a connected graph or bins further apart than 1:3.
fn two_bins_of_components(graph: &Graph) -> Option<[Vec<usize>; 2]> {
    const NONE: usize = usize::MAX;
    let n = graph.n();
    let mut component = vec![NONE; n];
    let mut members: Vec<Vec<usize>> = Vec::new();
    for root in 0..n {
        if component[root] != NONE {
            continue;
        }
        let c = members.len();
        component[root] = c;
        let mut list = vec![root];
        let mut head = 0;
        while head < list.len() {
            let v = list[head];
            head += 1;
            for &w in graph.neighbours(v) {
                if component[w] == NONE {
                    component[w] = c;
                    list.push(w);
                }
            }
        }
        members.push(list);
    }
    if members.len() < 2 {
        return None;
    }
    members.sort_by_key(|m| std::cmp::Reverse(m.len()));
    let mut bins: [Vec<usize>; 2] = [Vec::new(), Vec::new()];
    for m in members {
        let lighter = usize::from(bins[1].len() < bins[0].len());
        bins[lighter].extend(m);
    }
    let (small, large) = (
        bins[0].len().min(bins[1].len()),
        bins[0].len().max(bins[1].len()),
    );
    (3 * small >= large).then_some(bins)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_dissection_is_a_permutation_numbering_the_separator_last() {
        // A path 0-1-2-...-199 on a line: the first split puts a middle
        // vertex last.
        let n = 200;
        let col_ptr: Vec<usize> = std::iter::once(0)
            .chain((0..n).map(|j| if j == 0 { 1 } else { 2 * j + 1 }))
            .collect();
        let mut row_idx = Vec::new();
        for j in 0..n {
            if j > 0 {
                row_idx.push(j - 1);
            }
            row_idx.push(j);
        }
        let coords: Vec<[f64; 2]> = (0..n).map(|i| [i as f64, 0.0]).collect();
        let p = nested_dissection(&col_ptr, &row_idx, &coords);
        let mut seen = p.clone();
        seen.sort_unstable();
        assert_eq!(seen, (0..n).collect::<Vec<_>>());
        assert_eq!(p[n - 1], 100, "the separator of the first split is last");
    }
}
