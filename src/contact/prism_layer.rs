//! B in three dimensions built from two facing surfaces (docs/method.md
//! §9, stage 3): each triangle of surface a faces a triangle of surface b
//! node to node along the interface's normal, the two span a prism of
//! the gap (flat where they touch), and the prism is split into three
//! tetrahedra from every quadrilateral face's lowest-numbered node
//! (Dompierre et al., *How to subdivide pyramids, prisms and hexahedra
//! into tetrahedra*, 1999), so that neighbouring prisms agree on their
//! shared faces whatever the order the triangles come in. The 3D analogue
//! of the strip's elements of B between two facing boundaries (§3), for
//! conforming planar interfaces; non-matching ones are stage 6's.

use std::collections::{HashMap, HashSet};

use super::gap_tets::GapTetrahedron;
use crate::error::{Error, Result};
use crate::fem::tet::{TetGeometry, cross, dot, sub};

/// Two triangulated surfaces that face each other across a plane.
pub struct FacingSurfaces<'a> {
    /// Every node's position.
    pub points: &'a [[f64; 3]],
    /// Surface a's triangles (node indices).
    pub a: &'a [[usize; 3]],
    /// Surface b's triangles.
    pub b: &'a [[usize; 3]],
    /// The interface plane's unit normal, pointing from a into b (a's
    /// outward normal): b moving along it opens the gap.
    pub normal: [f64; 3],
    /// The caller's number of node v, for messages (the mesh's index base,
    /// or a host code's own node numbers).
    pub number: &'a dyn Fn(usize) -> i64,
}

/// B's tetrahedra between `s.a` and `s.b`: every node of a must face a node
/// of b (the same position once projected onto the interface plane, up to
/// 1e-6 of a's shortest edge) and every triangle of a a triangle of b; an
/// error names the first that does not. Each tetrahedron is numbered so
/// that opening the gap makes its J positive.
pub fn prism_layer(s: &FacingSurfaces<'_>) -> Result<Vec<GapTetrahedron>> {
    let n = unit(s.normal)?;
    for (name, tris) in [("a", s.a), ("b", s.b)] {
        if let Some(v) = tris.iter().flatten().find(|&&v| v >= s.points.len()) {
            return Err(Error::argument(format!(
                "surface {name} uses node index {v} (0-based, internal), out of range ({} nodes)",
                s.points.len()
            )));
        }
    }
    let plane = Plane::new(n);
    let shortest = shortest_edge(s, &plane);
    if !(shortest.is_finite() && shortest > 0.0) {
        return Err(Error::argument(
            "surface a has a triangle with no extent on the interface plane".to_string(),
        ));
    }
    let facing = facing_nodes(s, &plane, shortest)?;
    let triangles_b: HashSet<[usize; 3]> = s.b.iter().map(|t| sorted(*t)).collect();
    let mut layer = Vec::with_capacity(3 * s.a.len());
    for tri in s.a {
        let top = tri.map(|v| facing[&v]);
        if !triangles_b.contains(&sorted(top)) {
            return Err(Error::argument(format!(
                "the triangle of surface a on nodes {:?} faces no triangle of surface b (nodes \
                 {:?} of b face it): the interface must match triangle to triangle",
                tri.map(s.number),
                top.map(s.number)
            )));
        }
        for t in split_prism(*tri, top, |v| v) {
            let nodes = opening_positive(t, tri, s.points, &plane, shortest);
            layer.push(GapTetrahedron { nodes, normal: n });
        }
    }
    Ok(layer)
}

/// The three tetrahedra of the prism with bottom triangle `bottom` and top
/// triangle `top` (node k of one over node k of the other), every
/// quadrilateral face split from its lowest-ranked node: from the lowest
/// node v of the six, the tetrahedron of v and the opposite triangle, then
/// the pyramid of v over the quadrilateral opposite it, split along that
/// face's own diagonal. Their orientation is the caller's to fix.
pub fn split_prism(
    bottom: [usize; 3],
    top: [usize; 3],
    rank: impl Fn(usize) -> usize,
) -> [[usize; 4]; 3] {
    let all = [bottom[0], bottom[1], bottom[2], top[0], top[1], top[2]];
    let lowest = (0..6).min_by_key(|&k| rank(all[k])).expect("six nodes");
    // Relabel so that the lowest node is a = near[0].
    let (near, far) = if lowest < 3 {
        (bottom, top)
    } else {
        (top, bottom)
    };
    let r = lowest % 3;
    let rot = |t: [usize; 3]| [t[r], t[(r + 1) % 3], t[(r + 2) % 3]];
    let ([a, b, c], [_, b2, c2]) = (rot(near), rot(far));
    let cap = [a, far[r], b2, c2];
    // The quadrilateral b c c2 b2, from its lowest node.
    let quad_lowest = [b, c, c2, b2]
        .into_iter()
        .min_by_key(|&v| rank(v))
        .expect("four");
    if quad_lowest == b || quad_lowest == c2 {
        [cap, [a, b, c, c2], [a, b, c2, b2]]
    } else {
        [cap, [a, b, c, b2], [a, c, c2, b2]]
    }
}

/// An orthonormal basis (e₁, e₂) of the plane normal to n.
struct Plane {
    n: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
}

impl Plane {
    fn new(n: [f64; 3]) -> Plane {
        // The axis least aligned with n, made orthogonal to it.
        let k = (0..3)
            .min_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs()))
            .expect("three");
        let mut axis = [0.0; 3];
        axis[k] = 1.0;
        let e1 = normalised(sub(axis, scale(n, dot(axis, n))));
        let e2 = cross(n, e1);
        Plane { n, e1, e2 }
    }

    /// A point's coordinates in the plane.
    fn project(&self, p: [f64; 3]) -> [f64; 2] {
        [dot(p, self.e1), dot(p, self.e2)]
    }

    /// A point moved onto the plane through the origin.
    fn flatten(&self, p: [f64; 3]) -> [f64; 3] {
        sub(p, scale(self.n, dot(p, self.n)))
    }
}

/// The shortest edge of a's triangles, projected onto the plane.
fn shortest_edge(s: &FacingSurfaces<'_>, plane: &Plane) -> f64 {
    let mut shortest = f64::INFINITY;
    for t in s.a {
        for i in 0..3 {
            let (p, q) = (
                plane.project(s.points[t[i]]),
                plane.project(s.points[t[(i + 1) % 3]]),
            );
            shortest = shortest.min((p[0] - q[0]).hypot(p[1] - q[1]));
        }
    }
    shortest
}

/// The node of b that each node of a faces.
fn facing_nodes(
    s: &FacingSurfaces<'_>,
    plane: &Plane,
    shortest: f64,
) -> Result<HashMap<usize, usize>> {
    let (tol, cell) = (1e-6 * shortest, 1e-3 * shortest);
    let key = |p: [f64; 2]| [(p[0] / cell).floor() as i64, (p[1] / cell).floor() as i64];
    let mut grid: HashMap<[i64; 2], Vec<usize>> = HashMap::new();
    let nodes_b: HashSet<usize> = s.b.iter().flatten().copied().collect();
    for &v in &nodes_b {
        grid.entry(key(plane.project(s.points[v])))
            .or_default()
            .push(v);
    }
    let mut facing = HashMap::new();
    for &v in s.a.iter().flatten() {
        if facing.contains_key(&v) {
            continue;
        }
        let p = plane.project(s.points[v]);
        let [i, j] = key(p);
        let mut found = None;
        for (di, dj) in (-1..=1).flat_map(|di| (-1..=1).map(move |dj| (di, dj))) {
            for &w in grid.get(&[i + di, j + dj]).into_iter().flatten() {
                let q = plane.project(s.points[w]);
                if (p[0] - q[0]).hypot(p[1] - q[1]) <= tol {
                    if found.is_some_and(|f| f != w) {
                        return Err(Error::argument(format!(
                            "node {} of surface a faces two nodes of surface b",
                            (s.number)(v)
                        )));
                    }
                    found = Some(w);
                }
            }
        }
        let Some(w) = found else {
            return Err(Error::argument(format!(
                "node {} of surface a faces no node of surface b: the interface must match \
                 node to node",
                (s.number)(v)
            )));
        };
        if w == v {
            return Err(Error::argument(format!(
                "node {} is on both surfaces: each body needs its own nodes on the interface",
                (s.number)(v)
            )));
        }
        facing.insert(v, w);
    }
    Ok(facing)
}

/// `t` numbered so that its J is positive once the gap opens: a's nodes
/// (those of `bottom`) on the plane, b's lifted along the normal by `lift`.
fn opening_positive(
    t: [usize; 4],
    bottom: &[usize; 3],
    points: &[[f64; 3]],
    plane: &Plane,
    lift: f64,
) -> [usize; 4] {
    let opened = t.map(|v| {
        let flat = plane.flatten(points[v]);
        match bottom.contains(&v) {
            true => flat,
            false => [
                flat[0] + lift * plane.n[0],
                flat[1] + lift * plane.n[1],
                flat[2] + lift * plane.n[2],
            ],
        }
    });
    match TetGeometry::new(&opened).j < 0.0 {
        true => [t[0], t[1], t[3], t[2]],
        false => t,
    }
}

fn unit(n: [f64; 3]) -> Result<[f64; 3]> {
    let norm = dot(n, n).sqrt();
    if !norm.is_finite() || (norm - 1.0).abs() > 1e-12 {
        return Err(Error::argument(format!(
            "the interface normal {n:?} is not a unit vector"
        )));
    }
    Ok(n)
}

fn sorted(mut t: [usize; 3]) -> [usize; 3] {
    t.sort_unstable();
    t
}

fn scale(p: [f64; 3], s: f64) -> [f64; 3] {
    [s * p[0], s * p[1], s * p[2]]
}

fn normalised(p: [f64; 3]) -> [f64; 3] {
    scale(p, 1.0 / dot(p, p).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Node positions and two surfaces' triangles.
    type Surfaces = (Vec<[f64; 3]>, Vec<[usize; 3]>, Vec<[usize; 3]>);

    /// The unit square as two triangles twice: a at z = 0 (nodes 0–3), b
    /// at z = `gap` (nodes 4–7).
    fn squares(gap: f64) -> Surfaces {
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut points: Vec<[f64; 3]> = corners.iter().map(|c| [c[0], c[1], 0.0]).collect();
        points.extend(corners.iter().map(|c| [c[0], c[1], gap]));
        let a = vec![[0, 1, 2], [0, 2, 3]];
        let b = vec![[4, 6, 5], [4, 7, 6]];
        (points, a, b)
    }

    fn build(
        points: &[[f64; 3]],
        a: &[[usize; 3]],
        b: &[[usize; 3]],
    ) -> Result<Vec<GapTetrahedron>> {
        prism_layer(&FacingSurfaces {
            points,
            a,
            b,
            normal: [0.0, 0.0, 1.0],
            number: &|v| v as i64 + 1,
        })
    }

    #[test]
    fn each_facing_pair_of_triangles_gives_three_tetrahedra_that_open_positive() {
        let (points, a, b) = squares(0.25);
        let layer = build(&points, &a, &b).unwrap();
        assert_eq!(layer.len(), 6);
        for t in &layer {
            let j = TetGeometry::new(&t.nodes.map(|v| points[v])).j;
            assert!(j >= 0.0, "{t:?}: J = {j}");
        }
        // The prisms fill the slab of height 0.25: Σ J/6 = its volume.
        let volume: f64 = (layer.iter())
            .map(|t| TetGeometry::new(&t.nodes.map(|v| points[v])).j / 6.0)
            .sum();
        assert!((volume - 0.25).abs() < 1e-15, "{volume}");
    }

    #[test]
    fn neighbouring_prisms_split_their_shared_face_alike() {
        let (points, a, b) = squares(0.25);
        let layer = build(&points, &a, &b).unwrap();
        // The quadrilateral 0-2-6-4 between the two prisms is cut by one
        // diagonal: the faces of the layer on it pair up.
        let mut faces: Vec<[usize; 3]> = Vec::new();
        for t in &layer {
            for skip in 0..4 {
                let f: Vec<usize> = (0..4).filter(|&k| k != skip).map(|k| t.nodes[k]).collect();
                if f.iter().all(|v| [0, 2, 4, 6].contains(v)) {
                    faces.push(sorted([f[0], f[1], f[2]]));
                }
            }
        }
        faces.sort_unstable();
        assert_eq!(faces.len(), 4, "{faces:?}");
        assert_eq!(faces[0], faces[1]);
        assert_eq!(faces[2], faces[3]);
    }

    #[test]
    fn a_node_without_a_facing_node_is_named_in_the_callers_numbering() {
        let (mut points, a, b) = squares(0.0);
        points[6][0] += 0.1;
        let e = build(&points, &a, &b).unwrap_err();
        // Node 2 (0-based) is node 3 in `build`'s 1-based numbering.
        assert!(
            e.message().contains("node 3 of surface a faces no node"),
            "{e}"
        );
    }

    #[test]
    fn a_triangle_without_a_facing_triangle_is_named_by_its_nodes() {
        let (points, a, _) = squares(0.0);
        // b split along the other diagonal.
        let b = vec![[4, 5, 7], [5, 6, 7]];
        let e = build(&points, &a, &b).unwrap_err();
        assert!(
            e.message()
                .contains("triangle of surface a on nodes [1, 2, 3]"),
            "{e}"
        );
    }

    #[test]
    fn shared_nodes_and_bad_normals_are_refused() {
        let (points, a, _) = squares(0.0);
        let e = build(&points, &a, &a).unwrap_err();
        assert!(e.message().contains("on both surfaces"), "{e}");
        let e = prism_layer(&FacingSurfaces {
            points: &points,
            a: &a,
            b: &a,
            normal: [0.0, 0.0, 2.0],
            number: &|v| v as i64,
        })
        .unwrap_err();
        assert!(e.message().contains("not a unit vector"), "{e}");
    }
}
