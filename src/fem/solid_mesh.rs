//! Tetrahedral meshes of bodies in space (docs/method.md §9): nodes,
//! linear tetrahedra with the body each belongs to, and tagged boundary
//! triangles that loads, constraints and contact pairs refer to — the 3D
//! counterpart of [`crate::mesh::Mesh`]'s triangles and tagged edges.
//! [`Brick`] meshes boxes by Kuhn's six tetrahedra per cell, for examples
//! and tests that need no mesh file.

use std::collections::{BTreeMap, HashMap, HashSet};

use super::tet::{TetGeometry, cross, dot, sub};
use crate::error::{Error, Result};

/// A tagged triangle on a body's boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BoundaryFace {
    /// Its three nodes (0-based).
    pub nodes: [usize; 3],
    /// Its tag (a Gmsh physical surface, say).
    pub tag: i32,
    /// The tetrahedron it is a face of (its outward side is away from that
    /// tetrahedron's fourth node).
    pub owner: usize,
}

/// A face's outward unit normal, area and centroid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceGeometry {
    /// The unit normal pointing out of its tetrahedron (zero where the
    /// triangle has no area).
    pub normal: [f64; 3],
    /// Its area.
    pub area: f64,
    /// Its centroid.
    pub centroid: [f64; 3],
}

/// A tetrahedral mesh of one or more bodies.
#[derive(Debug, Clone)]
pub struct SolidMesh {
    nodes: Vec<[f64; 3]>,
    tets: Vec<[usize; 4]>,
    body_of: Vec<i32>,
    faces: Vec<BoundaryFace>,
    node_body: Vec<Option<i32>>,
    bodies: Vec<i32>,
    index_base: usize,
    warnings: Vec<String>,
    /// The largest side of the bounding box, kept: every tetrahedron's
    /// default Jmin reads it.
    size: f64,
}

/// The largest side of the bounding box of `nodes`.
fn bounding_size(nodes: &[[f64; 3]]) -> f64 {
    (0..3)
        .map(|i| {
            let (lo, hi) = (nodes.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[i]), b.max(p[i]))
            });
            hi - lo
        })
        .fold(0.0, f64::max)
}

impl SolidMesh {
    /// The mesh of `tets` (four node indices each, 0-based) over `nodes`,
    /// tetrahedron e in body `body_of[e]`; `index_base` (0 for C, 1 for
    /// Fortran) is how messages print indices. Refused, naming the item: a
    /// body list of another length, a non-finite coordinate, a node out of
    /// range or repeated in a tetrahedron. A tetrahedron numbered with
    /// negative volume is renumbered (its last two nodes swapped) with a
    /// warning; flat ones are kept (TFEM tempers them).
    pub fn new(
        nodes: Vec<[f64; 3]>,
        mut tets: Vec<[usize; 4]>,
        body_of: Vec<i32>,
        index_base: usize,
    ) -> Result<SolidMesh> {
        let b = index_base;
        if body_of.len() != tets.len() {
            return Err(Error::mesh(format!(
                "{} body tags for {} tetrahedra",
                body_of.len(),
                tets.len()
            )));
        }
        if let Some(i) = nodes.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
            return Err(Error::mesh(format!(
                "node {} has a non-finite coordinate {:?}",
                i + b,
                nodes[i]
            )));
        }
        let n = nodes.len();
        for (e, t) in tets.iter().enumerate() {
            if let Some(&v) = t.iter().find(|&&v| v >= n) {
                return Err(Error::mesh(format!(
                    "tetrahedron {}: node index {} is out of range ({n} nodes)",
                    e + b,
                    v + b
                )));
            }
            for i in 0..4 {
                if t[i + 1..].contains(&t[i]) {
                    return Err(Error::mesh(format!(
                        "tetrahedron {} repeats node {}",
                        e + b,
                        t[i] + b
                    )));
                }
            }
        }
        let mut turned: BTreeMap<i32, (usize, usize)> = BTreeMap::new();
        for (e, t) in tets.iter_mut().enumerate() {
            if TetGeometry::new(&t.map(|v| nodes[v])).j < 0.0 {
                t.swap(2, 3);
                turned.entry(body_of[e]).or_insert((0, e)).0 += 1;
            }
        }
        let mut node_body = vec![None; n];
        for (t, &body) in tets.iter().zip(&body_of) {
            t.iter().for_each(|&v| {
                node_body[v].get_or_insert(body);
            });
        }
        let mut bodies = body_of.clone();
        bodies.sort_unstable();
        bodies.dedup();
        let mut warnings = Vec::new();
        for (body, (count, first)) in turned {
            warnings.push(format!(
                "body {body}: {count} tetrahedra numbered with negative volume (e.g. tetrahedron \
                 {}) were renumbered; results refer to the renumbered tetrahedra",
                first + b
            ));
        }
        let unused = node_body.iter().filter(|b| b.is_none()).count();
        if unused > 0 {
            let first = node_body.iter().position(|b| b.is_none()).unwrap_or(0);
            warnings.push(format!(
                "{unused} node(s) not used by any tetrahedron get no unknowns (e.g. node {})",
                first + b
            ));
        }
        Ok(SolidMesh {
            size: bounding_size(&nodes),
            nodes,
            tets,
            body_of,
            faces: Vec::new(),
            node_body,
            bodies,
            index_base,
            warnings,
        })
    }

    /// Sets the tagged boundary faces (0-based nodes), replacing previous
    /// ones. Each must be a face of exactly one tetrahedron, with volume
    /// (a flat one has no outward side); the same face with the same tag
    /// twice is refused (its loads would count twice). On error the mesh
    /// is unchanged.
    pub fn set_boundary_faces(&mut self, faces: &[[usize; 3]], tags: &[i32]) -> Result<()> {
        self.faces = self.checked_faces(faces, tags, &[])?;
        Ok(())
    }

    /// Adds tagged boundary faces to those already set, checked as
    /// [`SolidMesh::set_boundary_faces`] does. On error the mesh is
    /// unchanged.
    pub fn add_boundary_faces(&mut self, faces: &[[usize; 3]], tags: &[i32]) -> Result<()> {
        let mut added = self.checked_faces(faces, tags, &self.faces)?;
        self.faces.append(&mut added);
        Ok(())
    }

    fn checked_faces(
        &self,
        faces: &[[usize; 3]],
        tags: &[i32],
        existing: &[BoundaryFace],
    ) -> Result<Vec<BoundaryFace>> {
        let b = self.index_base;
        if faces.len() != tags.len() {
            return Err(Error::argument(format!(
                "{} boundary faces but {} tags",
                faces.len(),
                tags.len()
            )));
        }
        let n = self.nodes.len();
        if let Some((f, v)) = (faces.iter().enumerate())
            .find_map(|(f, t)| t.iter().find(|&&v| v >= n).map(|&v| (f, v)))
        {
            return Err(Error::mesh(format!(
                "boundary face {}: node index {} is out of range ({n} nodes)",
                f + b,
                v + b
            )));
        }
        let wanted: HashSet<[usize; 3]> = faces.iter().map(|f| sorted(*f)).collect();
        // Owners of the faces asked about only: (tetrahedron, count).
        let mut owners: HashMap<[usize; 3], (usize, u32)> = HashMap::new();
        for (e, t) in self.tets.iter().enumerate() {
            for skip in 0..4 {
                let mut face = [0; 3];
                let mut k = 0;
                for (i, &v) in t.iter().enumerate() {
                    if i != skip {
                        face[k] = v;
                        k += 1;
                    }
                }
                let key = sorted(face);
                if wanted.contains(&key) {
                    owners.entry(key).and_modify(|o| o.1 += 1).or_insert((e, 1));
                }
            }
        }
        let mut seen: HashSet<([usize; 3], i32)> =
            existing.iter().map(|f| (sorted(f.nodes), f.tag)).collect();
        let mut out = Vec::with_capacity(faces.len());
        for (f, (&nodes, &tag)) in faces.iter().zip(tags).enumerate() {
            let key = sorted(nodes);
            let owner = match owners.get(&key) {
                Some(&(e, 1)) => e,
                Some(&(_, count)) => {
                    return Err(Error::mesh(format!(
                        "boundary face {} (nodes {}) is shared by {count} tetrahedra: it is \
                         inside the mesh, not on its boundary",
                        f + b,
                        self.list(&nodes)
                    )));
                }
                None => {
                    return Err(Error::mesh(format!(
                        "boundary face {} (nodes {}) is not a face of any tetrahedron",
                        f + b,
                        self.list(&nodes)
                    )));
                }
            };
            let geo = self.geometry(owner);
            if geo.j.abs() <= 1e-12 * geo.h * geo.h * geo.h {
                return Err(Error::mesh(format!(
                    "boundary face {} (nodes {}) is a face of flat tetrahedron {} only: its \
                     outward side is undefined (tag a face of a tetrahedron with volume)",
                    f + b,
                    self.list(&nodes),
                    owner + b
                )));
            }
            if !seen.insert((key, tag)) {
                return Err(Error::mesh(format!(
                    "boundary face {} (nodes {}) is given tag {tag} twice: its loads would \
                     count twice",
                    f + b,
                    self.list(&nodes)
                )));
            }
            out.push(BoundaryFace { nodes, tag, owner });
        }
        Ok(out)
    }

    fn list(&self, nodes: &[usize; 3]) -> String {
        let b = self.index_base;
        format!("{}, {}, {}", nodes[0] + b, nodes[1] + b, nodes[2] + b)
    }

    /// Node coordinates.
    pub fn nodes(&self) -> &[[f64; 3]] {
        &self.nodes
    }

    /// Tetrahedra (0-based node indices, positive volume or flat).
    pub fn tets(&self) -> &[[usize; 4]] {
        &self.tets
    }

    /// Body tag of each tetrahedron.
    pub fn body_of(&self) -> &[i32] {
        &self.body_of
    }

    /// The distinct body tags, sorted.
    pub fn bodies(&self) -> &[i32] {
        &self.bodies
    }

    /// The body of each node (`None`: used by no tetrahedron).
    pub fn node_body(&self) -> &[Option<i32>] {
        &self.node_body
    }

    /// The tagged boundary faces.
    pub fn boundary_faces(&self) -> &[BoundaryFace] {
        &self.faces
    }

    /// The base messages print indices from (0: C, 1: Fortran).
    pub fn index_base(&self) -> usize {
        self.index_base
    }

    /// What was noticed when the mesh was built (renumbered tetrahedra,
    /// unused nodes).
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The largest side of the bounding box (the model size Jmin's default
    /// λ is).
    pub fn size(&self) -> f64 {
        self.size
    }

    /// The geometry of a tetrahedron.
    pub fn geometry(&self, e: usize) -> TetGeometry {
        TetGeometry::new(&self.tets[e].map(|v| self.nodes[v]))
    }

    /// A boundary face's outward normal, area and centroid.
    pub fn face_geometry(&self, face: &BoundaryFace) -> FaceGeometry {
        let x = face.nodes.map(|v| self.nodes[v]);
        let inside = (self.tets[face.owner].iter())
            .find(|v| !face.nodes.contains(v))
            .map_or(x[0], |&v| self.nodes[v]);
        let mut n = cross(sub(x[1], x[0]), sub(x[2], x[0]));
        if dot(n, sub(x[0], inside)) < 0.0 {
            n = n.map(|c| -c);
        }
        let twice = dot(n, n).sqrt();
        FaceGeometry {
            normal: if twice > 0.0 {
                n.map(|c| c / twice)
            } else {
                [0.0; 3]
            },
            area: 0.5 * twice,
            centroid: std::array::from_fn(|i| (x[0][i] + x[1][i] + x[2][i]) / 3.0),
        }
    }

    /// Node `i` as messages print it.
    pub fn node_name(&self, i: usize) -> String {
        (i + self.index_base).to_string()
    }

    /// A mesh of boxes, each a body of Kuhn tetrahedra with its six sides
    /// tagged; the boxes share no nodes (bodies in contact, not merged).
    /// Neighbouring cells of one box agree on their shared faces.
    pub fn bricks(bricks: &[Brick]) -> Result<SolidMesh> {
        let mut nodes = Vec::new();
        let mut tets = Vec::new();
        let mut body_of = Vec::new();
        let mut faces = Vec::new();
        let mut tags = Vec::new();
        for (k, brick) in bricks.iter().enumerate() {
            brick.check(k)?;
            brick.add_to(&mut nodes, &mut tets, &mut faces, &mut tags);
            body_of.resize(tets.len(), brick.body);
        }
        let mut mesh = SolidMesh::new(nodes, tets, body_of, 0)?;
        mesh.set_boundary_faces(&faces, &tags)?;
        Ok(mesh)
    }
}

impl super::domain::Domain for SolidMesh {
    fn dimension(&self) -> usize {
        3
    }

    fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    fn coordinate(&self, v: usize, c: usize) -> f64 {
        self.nodes[v][c]
    }

    fn node_body(&self) -> &[Option<i32>] {
        &self.node_body
    }

    fn bodies(&self) -> &[i32] {
        &self.bodies
    }

    fn node_name(&self, v: usize) -> String {
        SolidMesh::node_name(self, v)
    }
}

fn sorted(mut f: [usize; 3]) -> [usize; 3] {
    f.sort_unstable();
    f
}

/// A box meshed by the grid xs × ys × zs (increasing coordinates), each
/// cell split into Kuhn's six tetrahedra, one body, its sides tagged.
#[derive(Debug, Clone, PartialEq)]
pub struct Brick {
    /// The grid's x coordinates.
    pub xs: Vec<f64>,
    /// The grid's y coordinates.
    pub ys: Vec<f64>,
    /// The grid's z coordinates.
    pub zs: Vec<f64>,
    /// Its body tag.
    pub body: i32,
    /// The tags of its sides x = min, x = max, y = min, y = max, z = min,
    /// z = max.
    pub side_tags: [i32; 6],
}

impl Brick {
    /// A box from `lo` to `hi` with `cells` equal cells along each axis.
    pub fn uniform(lo: [f64; 3], hi: [f64; 3], cells: [usize; 3], body: i32) -> Brick {
        let axis = |a: usize| -> Vec<f64> {
            let n = cells[a].max(1);
            (0..=n)
                .map(|i| lo[a] + (hi[a] - lo[a]) * i as f64 / n as f64)
                .collect()
        };
        Brick {
            xs: axis(0),
            ys: axis(1),
            zs: axis(2),
            body,
            side_tags: [1, 2, 3, 4, 5, 6],
        }
    }

    fn check(&self, k: usize) -> Result<()> {
        for (name, axis) in [("x", &self.xs), ("y", &self.ys), ("z", &self.zs)] {
            let increasing = axis.windows(2).all(|w| w[0] < w[1]);
            if axis.len() < 2 || !increasing || axis.iter().any(|x| !x.is_finite()) {
                return Err(Error::argument(format!(
                    "brick {k}: its {name} coordinates must be at least two, finite and \
                     increasing"
                )));
            }
        }
        Ok(())
    }

    /// Appends the brick's nodes, tetrahedra and tagged sides.
    fn add_to(
        &self,
        nodes: &mut Vec<[f64; 3]>,
        tets: &mut Vec<[usize; 4]>,
        faces: &mut Vec<[usize; 3]>,
        tags: &mut Vec<i32>,
    ) {
        let first = nodes.len();
        let (nx, ny, nz) = (self.xs.len(), self.ys.len(), self.zs.len());
        for &z in &self.zs {
            for &y in &self.ys {
                for &x in &self.xs {
                    nodes.push([x, y, z]);
                }
            }
        }
        let id = |i: usize, j: usize, k: usize| first + i + nx * (j + ny * k);
        let start = tets.len();
        for k in 0..nz - 1 {
            for j in 0..ny - 1 {
                for i in 0..nx - 1 {
                    kuhn_box(tets, |a, b, c| id(i + a, j + b, k + c));
                }
            }
        }
        // Each side's triangles are the faces its cells' tetrahedra have
        // on it.
        let cells = [nx - 1, ny - 1, nz - 1];
        for t in &tets[start..] {
            for skip in 0..4 {
                let face: Vec<usize> = (0..4).filter(|&i| i != skip).map(|i| t[i]).collect();
                let grid = |v: usize| {
                    let r = v - first;
                    [r % nx, (r / nx) % ny, r / (nx * ny)]
                };
                for axis in 0..3 {
                    for (end, at) in [(0, 0), (1, cells[axis])] {
                        if face.iter().all(|&v| grid(v)[axis] == at) {
                            faces.push([face[0], face[1], face[2]]);
                            tags.push(self.side_tags[2 * axis + end]);
                        }
                    }
                }
            }
        }
    }
}

/// The six Kuhn tetrahedra of the box whose corner (a, b, c) ∈ {0,1}³ is
/// node `corner(a, b, c)`: paths from (0,0,0) to (1,1,1) by unit steps in
/// every order, the odd orders numbered backwards to keep J > 0.
fn kuhn_box(tets: &mut Vec<[usize; 4]>, corner: impl Fn(usize, usize, usize) -> usize) {
    const ORDERS: [([usize; 3], bool); 6] = [
        ([0, 1, 2], true),
        ([1, 2, 0], true),
        ([2, 0, 1], true),
        ([0, 2, 1], false),
        ([2, 1, 0], false),
        ([1, 0, 2], false),
    ];
    for (order, even) in ORDERS {
        let mut p = [0usize; 3];
        let mut t = [corner(0, 0, 0); 4];
        for (s, &axis) in order.iter().enumerate() {
            p[axis] = 1;
            t[s + 1] = corner(p[0], p[1], p[2]);
        }
        if !even {
            t.swap(2, 3);
        }
        tets.push(t);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> SolidMesh {
        SolidMesh::bricks(&[Brick::uniform([0.0; 3], [1.0; 3], [2, 2, 2], 1)]).unwrap()
    }

    #[test]
    fn a_brick_fills_its_volume_with_positive_tetrahedra() {
        let mesh = cube();
        assert_eq!(mesh.tets().len(), 48);
        let volume: f64 = (0..48).map(|e| mesh.geometry(e).j / 6.0).sum();
        assert!((volume - 1.0).abs() < 1e-14);
        assert!((0..48).all(|e| mesh.geometry(e).j > 0.0));
        assert!(mesh.warnings().is_empty());
    }

    #[test]
    fn a_bricks_sides_are_tagged_with_outward_normals_summing_to_its_area() {
        let mesh = cube();
        for (tag, normal) in [
            (1, [-1.0, 0.0, 0.0]),
            (4, [0.0, 1.0, 0.0]),
            (6, [0.0, 0.0, 1.0]),
        ] {
            let faces: Vec<_> = (mesh.boundary_faces().iter())
                .filter(|f| f.tag == tag)
                .collect();
            assert_eq!(faces.len(), 8, "side {tag}");
            let area: f64 = faces.iter().map(|f| mesh.face_geometry(f).area).sum();
            assert!((area - 1.0).abs() < 1e-14);
            for f in faces {
                assert_eq!(mesh.face_geometry(f).normal, normal);
            }
        }
    }

    #[test]
    fn a_negatively_numbered_tetrahedron_is_renumbered_with_a_warning() {
        let nodes = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mesh = SolidMesh::new(nodes, vec![[0, 2, 1, 3]], vec![7], 1).unwrap();
        assert!(mesh.geometry(0).j > 0.0);
        assert!(
            mesh.warnings()[0].contains("body 7: 1 tetrahedra"),
            "{:?}",
            mesh.warnings()
        );
        assert!(mesh.warnings()[0].contains("tetrahedron 1"));
    }

    #[test]
    fn bad_tetrahedra_are_refused_by_name() {
        let nodes = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let out = SolidMesh::new(nodes.clone(), vec![[0, 1, 2, 4]], vec![1], 0).unwrap_err();
        assert!(
            out.message().contains("tetrahedron 0: node index 4"),
            "{}",
            out.message()
        );
        let twice = SolidMesh::new(nodes.clone(), vec![[0, 1, 1, 3]], vec![1], 0).unwrap_err();
        assert!(
            twice.message().contains("repeats node 1"),
            "{}",
            twice.message()
        );
        let mut nan = nodes;
        nan[2][1] = f64::NAN;
        let out = SolidMesh::new(nan, vec![[0, 1, 2, 3]], vec![1], 0).unwrap_err();
        assert!(
            out.message().contains("node 2 has a non-finite"),
            "{}",
            out.message()
        );
    }

    #[test]
    fn a_face_of_a_flat_tetrahedron_alone_is_refused() {
        let nodes = vec![[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let mut mesh = SolidMesh::new(nodes, vec![[0, 1, 2, 3]], vec![1], 0).unwrap();
        let out = mesh.set_boundary_faces(&[[0, 1, 3]], &[4]).unwrap_err();
        assert!(
            out.message().contains("flat tetrahedron 0"),
            "{}",
            out.message()
        );
        assert!(mesh.boundary_faces().is_empty());
    }

    #[test]
    fn inner_and_unknown_faces_are_refused_and_the_faces_kept() {
        let mut mesh = cube();
        let before = mesh.boundary_faces().to_vec();
        // Kuhn's first two tetrahedra of a cell share the face 0, 1+…
        let t = mesh.tets()[0];
        let inner = [t[0], t[1], t[3]];
        let out = mesh.set_boundary_faces(&[inner], &[9]).unwrap_err();
        assert!(
            out.message().contains("shared by 2 tetrahedra"),
            "{}",
            out.message()
        );
        let out = mesh.set_boundary_faces(&[[0, 1, 26]], &[9]).unwrap_err();
        assert!(out.message().contains("not a face"), "{}", out.message());
        let face = before[0];
        let out = mesh
            .add_boundary_faces(&[face.nodes], &[face.tag])
            .unwrap_err();
        assert!(out.message().contains("twice"), "{}", out.message());
        assert_eq!(mesh.boundary_faces(), &before[..]);
    }
}
