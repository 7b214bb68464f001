//! The orientation of a mesh's triangles: legacy codes number triangles
//! clockwise, or mix orientations, while TFEM reads a negative Jacobian as
//! an inverted element (one it softens). Two kinds of clockwise triangle
//! must therefore be told apart:
//!
//! * a triangle merely *numbered* clockwise traverses an edge it shares
//!   with a neighbour in the same direction as the neighbour does;
//! * a *fold* (a truly inverted element, what TFEM is for) keeps the
//!   numbering consistent with its neighbours while its geometry is turned
//!   over.
//!
//! So the numbering of each connected region of a body (triangles joined
//! by edges shared by exactly two of its triangles) is first made
//! consistent, neighbour by neighbour, and the region is then turned so
//! that most of its area is counter-clockwise. Triangles still clockwise
//! after that are folds, and stay as they are.

use std::collections::VecDeque;

/// One re-oriented body: how many of its triangles were turned, and the
/// first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Turned {
    /// The body.
    pub body: i32,
    /// Triangles turned.
    pub count: usize,
    /// The first one turned.
    pub first: usize,
}

/// Turns (swaps the last two nodes of) the triangles numbered against
/// their region's orientation, given each triangle's Jacobian `j` (twice
/// its signed area), and reports the bodies that had any. Costs one pass
/// when no triangle is clockwise.
pub fn orient(triangles: &mut [[usize; 3]], body_of: &[i32], j: &[f64]) -> Vec<Turned> {
    if j.iter().all(|&v| v >= 0.0) {
        return Vec::new();
    }
    let flip = flips(triangles, body_of, j);
    let mut turned: Vec<Turned> = Vec::new();
    for (t, tri) in triangles.iter_mut().enumerate() {
        if !flip[t] {
            continue;
        }
        tri.swap(1, 2);
        let body = body_of[t];
        match turned.iter_mut().find(|r| r.body == body) {
            Some(r) => r.count += 1,
            None => turned.push(Turned {
                body,
                count: 1,
                first: t,
            }),
        }
    }
    turned.sort_unstable_by_key(|r| r.body);
    turned
}

/// Whether each triangle must be turned.
fn flips(triangles: &[[usize; 3]], body_of: &[i32], j: &[f64]) -> Vec<bool> {
    let neighbours = neighbours(triangles, body_of);
    let n = triangles.len();
    let mut flip = vec![false; n];
    let mut seen = vec![false; n];
    let mut queue = VecDeque::new();
    let mut region = Vec::new();
    for root in 0..n {
        if seen[root] {
            continue;
        }
        // Consistent numbering within the region, relative to its root.
        seen[root] = true;
        queue.push_back(root);
        region.clear();
        while let Some(t) = queue.pop_front() {
            region.push(t);
            for &(s, same_direction) in &neighbours[t] {
                if !seen[s] {
                    seen[s] = true;
                    flip[s] = flip[t] ^ same_direction;
                    queue.push_back(s);
                }
            }
        }
        // Counter-clockwise by area.
        let area: f64 = region
            .iter()
            .map(|&t| if flip[t] { -j[t] } else { j[t] })
            .sum();
        if area < 0.0 {
            for &t in &region {
                flip[t] = !flip[t];
            }
        }
    }
    flip
}

/// For each triangle, its neighbours across edges shared by exactly two
/// triangles of one body, and whether the neighbour traverses the edge in
/// the same direction (numbered against it).
fn neighbours(triangles: &[[usize; 3]], body_of: &[i32]) -> Vec<Vec<(usize, bool)>> {
    // (low node, high node, triangle, traversed low → high)
    let mut sides: Vec<(usize, usize, usize, bool)> = Vec::with_capacity(3 * triangles.len());
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (p, q) = (tri[k], tri[(k + 1) % 3]);
            sides.push((p.min(q), p.max(q), t, p < q));
        }
    }
    sides.sort_unstable();
    let mut out = vec![Vec::new(); triangles.len()];
    let mut start = 0;
    while start < sides.len() {
        let key = (sides[start].0, sides[start].1);
        let mut end = start + 1;
        while end < sides.len() && (sides[end].0, sides[end].1) == key {
            end += 1;
        }
        if end - start == 2 {
            let (a, b) = (sides[start], sides[start + 1]);
            if body_of[a.2] == body_of[b.2] {
                let same = a.3 == b.3;
                out[a.2].push((b.2, same));
                out[b.2].push((a.2, same));
            }
        }
        start = end;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::element::TriGeometry;

    fn jacobians(nodes: &[[f64; 2]], tris: &[[usize; 3]]) -> Vec<f64> {
        tris.iter()
            .map(|t| TriGeometry::new(&[nodes[t[0]], nodes[t[1]], nodes[t[2]]]).j)
            .collect()
    }

    /// A 2×2 square of four triangles around its centre.
    fn fan() -> (Vec<[f64; 2]>, Vec<[usize; 3]>) {
        let nodes = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]];
        let tris = vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        (nodes, tris)
    }

    #[test]
    fn a_counter_clockwise_mesh_is_left_alone() {
        let (nodes, mut tris) = fan();
        let j = jacobians(&nodes, &tris);
        assert!(orient(&mut tris, &[1; 4], &j).is_empty());
        assert_eq!(tris, fan().1);
    }

    #[test]
    fn a_body_numbered_clockwise_is_turned_whole() {
        let (nodes, mut tris) = fan();
        tris.iter_mut().for_each(|t| t.swap(0, 1));
        let j = jacobians(&nodes, &tris);
        let turned = orient(&mut tris, &[7; 4], &j);
        assert_eq!(
            turned,
            [Turned {
                body: 7,
                count: 4,
                first: 0
            }]
        );
        assert!(jacobians(&nodes, &tris).iter().all(|&j| j > 0.0));
    }

    #[test]
    fn mixed_numbering_is_made_counter_clockwise_triangle_by_triangle() {
        let (nodes, mut tris) = fan();
        tris[1].swap(0, 2);
        tris[3].swap(1, 2);
        let j = jacobians(&nodes, &tris);
        let turned = orient(&mut tris, &[1; 4], &j);
        assert_eq!(
            turned,
            [Turned {
                body: 1,
                count: 2,
                first: 1
            }]
        );
        assert!(jacobians(&nodes, &tris).iter().all(|&j| j > 0.0));
    }

    #[test]
    fn a_fold_inside_a_counter_clockwise_body_stays_inverted() {
        // The centre pushed out beyond the right edge: the right triangle
        // is turned over, its numbering still agrees with its neighbours.
        let (mut nodes, mut tris) = fan();
        nodes[4] = [2.5, 1.0];
        let j = jacobians(&nodes, &tris);
        assert!(j[1] < 0.0);
        assert!(orient(&mut tris, &[1; 4], &j).is_empty());
        assert_eq!(tris, fan().1);
    }

    #[test]
    fn each_body_and_each_region_is_oriented_on_its_own() {
        // Two separate squares of two triangles: body 1 counter-clockwise,
        // body 2 clockwise.
        let nodes = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [2.0, 1.0],
        ];
        let mut tris = vec![[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6]];
        let j = jacobians(&nodes, &tris);
        let turned = orient(&mut tris, &[1, 1, 2, 2], &j);
        assert_eq!(
            turned,
            [Turned {
                body: 2,
                count: 2,
                first: 2
            }]
        );
        assert_eq!(&tris[..2], &[[0, 1, 2], [0, 2, 3]]);
        assert!(jacobians(&nodes, &tris).iter().all(|&j| j > 0.0));
    }
}
