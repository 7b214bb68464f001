//! Which edges of a curved contact interface face each other, so that an
//! adaptive solve bisects them together (docs/method.md §8.2, "Curved
//! boundaries").
//!
//! Two polygons that matched on a curve and are refined apart no longer
//! enclose the same overlap: a shrink fit's interference, smaller than the
//! coarse chords' sagitta, would vanish between them. Edges of the two
//! sides whose ends lie within half an edge of each other are therefore
//! kept in step; edges that face nothing (a non-matching curved interface)
//! refine apart, as straight interfaces do.

use std::collections::{HashMap, HashSet};

use crate::error::Result;
use crate::fem::mesh::Mesh;
use crate::fem::refine::Refinement;

/// Two interface edges that face each other across a pair, node for node,
/// with the triangles that own them.
#[derive(Debug)]
pub(crate) struct Facing {
    edges: [[usize; 2]; 2],
    owners: [usize; 2],
}

/// The facing edges of the pairs with a curve on either side
/// ([`crate::Mesh::set_curve`]): edges of the two sides whose ends are
/// each within half an edge of an end of the other. Two polygons that
/// matched on a curve and are refined apart no longer enclose the same
/// overlap (a shrink fit's interference, smaller than the coarse chords'
/// sagitta, would vanish between them), so such edges are bisected
/// together; straight interfaces refine apart (their non-matching
/// discretisation is exact on the patch test).
pub(crate) fn facing_edges(problem: &crate::Problem) -> Result<Vec<Facing>> {
    let mesh = problem.mesh_ref()?;
    let x = mesh.nodes();
    let dist = |p: usize, q: usize| (x[p][0] - x[q][0]).hypot(x[p][1] - x[q][1]);
    let mut out = Vec::new();
    for pair in problem.contact_pairs() {
        if mesh.curve(pair.tag_a).is_none() && mesh.curve(pair.tag_b).is_none() {
            continue;
        }
        let side = |tag: i32| -> Vec<([usize; 2], usize)> {
            (mesh.boundary_edges().iter())
                .filter(|e| e.tag == tag)
                .filter_map(|e| e.owner.map(|(t, _)| (e.nodes, t)))
                .collect()
        };
        let (a, b) = (side(pair.tag_a), side(pair.tag_b));
        // Each node's shortest edge on its side.
        let mut h: HashMap<usize, f64> = HashMap::new();
        for &([p, q], _) in a.iter().chain(&b) {
            for v in [p, q] {
                let e = h.entry(v).or_insert(f64::INFINITY);
                *e = e.min(dist(p, q));
            }
        }
        // Cells as long as side b's longest edge: a partner, within half an
        // edge, lies in the 3 × 3 cells around a node.
        let longest = b.iter().fold(0.0f64, |m, ([p, q], _)| m.max(dist(*p, *q)));
        let grid = NodeGrid::of(x, b.iter().flat_map(|(e, _)| *e), longest);
        let partner = |v: usize| {
            grid.nearest(x, x[v])
                .filter(|&w| dist(v, w) <= 0.5 * h[&v].min(h[&w]))
        };
        let on_b: HashMap<[usize; 2], usize> = (b.iter())
            .map(|&([p, q], t)| ([p.min(q), p.max(q)], t))
            .collect();
        for &([p, q], t) in &a {
            let (Some(fp), Some(fq)) = (partner(p), partner(q)) else {
                continue;
            };
            if let Some(&u) = on_b.get(&[fp.min(fq), fp.max(fq)]) {
                out.push(Facing {
                    edges: [[p.min(q), p.max(q)], [fp.min(fq), fp.max(fq)]],
                    owners: [t, u],
                });
            }
        }
    }
    Ok(out)
}

/// Adds to `marked` the owners of the facing edges that refinement would
/// otherwise bisect on one side only, until none is left (closure on one
/// side can bisect more of its edges: read again).
pub(crate) fn in_step(
    refinement: &Refinement,
    mesh: &Mesh,
    facing: &[Facing],
    marked: &mut Vec<usize>,
) -> Result<()> {
    if facing.is_empty() {
        return Ok(());
    }
    let mut added: HashSet<usize> = marked.iter().copied().collect();
    loop {
        let cut = refinement.bisected_edges(mesh, marked)?;
        let before = marked.len();
        for f in facing {
            let owner = match (cut.contains(&f.edges[0]), cut.contains(&f.edges[1])) {
                (true, false) => f.owners[1],
                (false, true) => f.owners[0],
                _ => continue,
            };
            // A triangle marked already whose edge is still not cut (one
            // collapsed to a point, which its mark does not refine) is not
            // marked again: the loop ends.
            if added.insert(owner) {
                marked.push(owner);
            }
        }
        if marked.len() == before {
            return Ok(());
        }
    }
}

/// Nodes bucketed on a square grid, for nearest-node queries.
struct NodeGrid {
    cell: f64,
    buckets: HashMap<(i64, i64), Vec<usize>>,
}

impl NodeGrid {
    fn of(x: &[[f64; 2]], nodes: impl Iterator<Item = usize>, cell: f64) -> NodeGrid {
        let mut grid = NodeGrid {
            cell: if cell > 0.0 { cell } else { 1.0 },
            buckets: HashMap::new(),
        };
        for v in nodes {
            grid.buckets.entry(grid.key(x[v])).or_default().push(v);
        }
        grid
    }

    fn key(&self, p: [f64; 2]) -> (i64, i64) {
        // `as` saturates: extreme coordinates land in the outermost cells.
        (
            (p[0] / self.cell).floor() as i64,
            (p[1] / self.cell).floor() as i64,
        )
    }

    /// The nearest bucketed node within a cell of `p`, if any.
    fn nearest(&self, x: &[[f64; 2]], p: [f64; 2]) -> Option<usize> {
        let (i, j) = self.key(p);
        let d = |v: usize| (x[v][0] - p[0]).hypot(x[v][1] - p[1]);
        (-1..=1)
            .flat_map(|di| (-1..=1).map(move |dj| (i.saturating_add(di), j.saturating_add(dj))))
            .filter_map(|k| self.buckets.get(&k))
            .flatten()
            .copied()
            .min_by(|&v, &w| d(v).total_cmp(&d(w)))
    }
}
