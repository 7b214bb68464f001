//! Meshes of P1 triangles with a body tag per triangle and tagged boundary
//! edges, and their validation.
//!
//! Degenerate (zero-area) and inverted triangles are legal: they are what
//! TFEM is for. Triangles numbered clockwise are turned
//! ([`super::orientation`]), so that only folds of the mesh count as
//! inverted. What is rejected is what no method can use: indices out of
//! range, a node repeated in a triangle, non-finite coordinates, an empty
//! mesh.

use std::collections::{BTreeMap, HashMap, HashSet};

use super::curve::Curve;
use super::element::TriGeometry;
use super::orientation::{Turned, orient};
use crate::error::{Error, Result, preflight, reserved};

/// A tagged boundary edge, with the triangle that owns it.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryEdge {
    /// The two end nodes (0-based).
    pub nodes: [usize; 2],
    /// The user's tag (physical group).
    pub tag: i32,
    /// The owning triangle and its third node, when exactly one triangle has
    /// this edge; `None` for an interior edge (usable for constraints only).
    pub owner: Option<(usize, usize)>,
}

/// A validated mesh.
#[derive(Debug, Clone)]
pub struct Mesh {
    nodes: Vec<[f64; 2]>,
    triangles: Vec<[usize; 3]>,
    body_of: Vec<i32>,
    edges: Vec<BoundaryEdge>,
    node_body: Vec<Option<i32>>,
    bodies: Vec<i32>,
    index_base: usize,
    warnings: Vec<String>,
    /// The curves declared on tags ([`Mesh::set_curve`]), by tag.
    curves: Vec<(i32, Curve)>,
}

const MAX_LISTED: usize = 5;

fn list<T: std::fmt::Display>(items: &[T]) -> String {
    let shown: Vec<String> = items
        .iter()
        .take(MAX_LISTED)
        .map(|i| i.to_string())
        .collect();
    let more = if items.len() > MAX_LISTED {
        format!(" and {} more", items.len() - MAX_LISTED)
    } else {
        String::new()
    };
    format!("{}{}", shown.join(", "), more)
}

/// Where a file puts each node, triangle and boundary edge, for messages:
/// its entity and physical group, as the file's user knows them ("surface
/// 1 in physical group 7 \"plate\""); `None` where the file says nothing.
pub trait Places: std::fmt::Debug {
    /// Where node `i` (0-based) lies.
    fn node(&self, i: usize) -> Option<String>;
    /// Where triangle `t` (0-based) lies.
    fn triangle(&self, t: usize) -> Option<String>;
    /// Where boundary edge `e` (by position in the edges given) lies.
    fn edge(&self, e: usize) -> Option<String>;
}

/// How the messages of [`Mesh::with_names`] and
/// [`Mesh::set_boundary_edges_with_names`] name nodes, triangles and
/// boundary edges: by index in the caller's numbering and, for a mesh read
/// from a file, by the file's own tags, which are what its user can look
/// up (a file's node 1001 may be index 0), and where the file puts them.
#[derive(Clone, Copy, Debug, Default)]
pub struct Names<'a> {
    /// How indices are printed: 0 (C) or 1 (Fortran).
    pub index_base: usize,
    /// What the file is, for the messages ("Gmsh"); unused without tags.
    pub file: &'a str,
    /// The file's tag of each node, by index.
    pub node_tags: Option<&'a [u64]>,
    /// The file's element tag of each triangle, by index.
    pub triangle_tags: Option<&'a [u64]>,
    /// The file's element tag of each boundary edge given, by position.
    pub edge_tags: Option<&'a [u64]>,
    /// Where the file puts them (entity, physical group).
    pub places: Option<&'a dyn Places>,
}

impl Names<'_> {
    /// Indices only, printed from `index_base`.
    pub fn indices(index_base: usize) -> Self {
        Names {
            index_base,
            ..Names::default()
        }
    }

    /// " of <place>" where the file says where an item lies, else "".
    fn of(place: Option<String>) -> String {
        place.map_or_else(String::new, |p| format!(" of {p}"))
    }

    /// Node `i`: "5", or "5 (Gmsh node 1006)".
    fn node(&self, i: usize) -> String {
        let n = i + self.index_base;
        match self.node_tags.and_then(|t| t.get(i)) {
            Some(tag) => format!("{n} ({} node {tag})", self.file),
            None => n.to_string(),
        }
    }

    /// Node `i` where a message is about the node itself: "5", or "5
    /// (Gmsh node 1006 of surface 1 in physical group 7)". (Where it is
    /// about a triangle, the triangle says where.)
    fn placed_node(&self, i: usize) -> String {
        let n = i + self.index_base;
        match self.node_tags.and_then(|t| t.get(i)) {
            Some(tag) => format!(
                "{n} ({} node {tag}{})",
                self.file,
                Self::of(self.places.and_then(|p| p.node(i)))
            ),
            None => n.to_string(),
        }
    }

    /// Triangle `t`: "triangle 3", "triangle 3 (Gmsh element 57)", or
    /// "triangle 3 (Gmsh element 57 of surface 1 in physical group 7)".
    fn triangle(&self, t: usize) -> String {
        let n = t + self.index_base;
        match self.triangle_tags.and_then(|tags| tags.get(t)) {
            Some(tag) => format!(
                "triangle {n} ({} element {tag}{})",
                self.file,
                Self::of(self.places.and_then(|p| p.triangle(t)))
            ),
            None => format!("triangle {n}"),
        }
    }

    /// Boundary edge `e`: "boundary edge 2", "Gmsh line element 7", or
    /// "Gmsh line element 7 of curve 1 in physical group 11".
    fn edge(&self, e: usize) -> String {
        match self.edge_tags.and_then(|t| t.get(e)) {
            Some(tag) => format!(
                "{} line element {tag}{}",
                self.file,
                Self::of(self.places.and_then(|p| p.edge(e)))
            ),
            None => format!("boundary edge {}", e + self.index_base),
        }
    }

    /// The ends of a boundary edge: "nodes 1, 3", or "Gmsh nodes 1001,
    /// 1003" (a file's edge is known by the file's nodes).
    fn ends(&self, p: usize, q: usize) -> String {
        match self.node_tags.and_then(|t| Some((t.get(p)?, t.get(q)?))) {
            Some((tp, tq)) => format!("{} nodes {tp}, {tq}", self.file),
            None => format!("nodes {}, {}", p + self.index_base, q + self.index_base),
        }
    }
}

/// The checks of [`Mesh::new`] on its raw data, each error naming the node
/// or triangle as `names` says. Gives whether some triangle is numbered
/// clockwise (its Jacobian is at hand here).
fn validate(
    nodes: &[[f64; 2]],
    triangles: &[[usize; 3]],
    body_of: &[i32],
    names: &Names,
) -> Result<bool> {
    let b = names.index_base;
    if nodes.is_empty() {
        return Err(Error::mesh("empty mesh: no nodes"));
    }
    if triangles.is_empty() {
        return Err(Error::mesh("empty mesh: no triangles"));
    }
    if body_of.len() != triangles.len() {
        return Err(Error::mesh(format!(
            "{} body tags for {} triangles",
            body_of.len(),
            triangles.len()
        )));
    }
    if let Some(i) = nodes
        .iter()
        .position(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(Error::mesh(format!(
            "node {}: coordinates ({:?}, {:?}) are not finite",
            names.placed_node(i),
            nodes[i][0],
            nodes[i][1]
        )));
    }
    let n = nodes.len();
    for (t, tri) in triangles.iter().enumerate() {
        for &v in tri {
            if v >= n {
                return Err(Error::mesh(format!(
                    "{}: node index {} is out of range ({} nodes, index base {})",
                    names.triangle(t),
                    v + b,
                    n,
                    b
                )));
            }
        }
        if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
            return Err(Error::mesh(format!(
                "{}: node {} is repeated ({}, {}, {})",
                names.triangle(t),
                names.node(if tri[0] == tri[1] || tri[0] == tri[2] {
                    tri[0]
                } else {
                    tri[1]
                }),
                names.node(tri[0]),
                names.node(tri[1]),
                names.node(tri[2])
            )));
        }
    }
    check_repeated(triangles, names)?;
    let mut any_clockwise = false;
    for (t, tri) in triangles.iter().enumerate() {
        let geo = TriGeometry::new(&[nodes[tri[0]], nodes[tri[1]], nodes[tri[2]]]);
        if !(geo.j.is_finite() && geo.h.is_finite()) {
            return Err(Error::mesh(format!(
                "{}: its size or area overflows (coordinates too large for double \
                 precision: rescale the model)",
                names.triangle(t)
            )));
        }
        any_clockwise |= geo.j < 0.0;
    }
    Ok(any_clockwise)
}

/// Refuses a triangle given twice — the same three nodes in any order or
/// orientation, in one body or two: its stiffness would be added twice
/// and the solve would answer with a stiffer body and no word (found by a
/// probe: a unit square under pressure with one triangle repeated read
/// σ_yy = 0.55 p). Names the first repeat through `names` (the caller's
/// numbering, or a file's tags).
fn check_repeated(triangles: &[[usize; 3]], names: &Names<'_>) -> Result<()> {
    let mut keyed: Vec<([usize; 3], usize)> =
        reserved(triangles.len(), "the mesh's check for repeated triangles")?;
    keyed.extend(triangles.iter().enumerate().map(|(t, tri)| {
        let mut key = *tri;
        key.sort_unstable();
        (key, t)
    }));
    keyed.sort_unstable();
    let first = keyed
        .windows(2)
        .filter(|w| w[0].0 == w[1].0)
        .map(|w| (w[0].1, w[1].1))
        .min_by_key(|&(_, repeat)| repeat);
    match first {
        Some((t, repeat)) => {
            let n = triangles[repeat];
            Err(Error::mesh(format!(
                "{} (nodes {}, {}, {}) repeats {}: each triangle must be given once",
                names.triangle(repeat),
                names.node(n[0]),
                names.node(n[1]),
                names.node(n[2]),
                names.triangle(t)
            )))
        }
        None => Ok(()),
    }
}

impl Mesh {
    /// Validates and builds a mesh from 0-based data. `index_base` (0 or 1)
    /// only changes how indices are printed in messages, so that a Fortran
    /// user reads the numbers of their own mesh.
    pub fn new(
        nodes: Vec<[f64; 2]>,
        triangles: Vec<[usize; 3]>,
        body_of: Vec<i32>,
        index_base: usize,
    ) -> Result<Mesh> {
        Mesh::with_names(nodes, triangles, body_of, &Names::indices(index_base))
    }

    /// [`Mesh::new`] with its errors and warnings naming nodes and
    /// triangles as `names` says (by a file's tags, say); the mesh keeps
    /// `names.index_base` for later messages.
    pub fn with_names(
        mut nodes: Vec<[f64; 2]>,
        mut triangles: Vec<[usize; 3]>,
        mut body_of: Vec<i32>,
        names: &Names,
    ) -> Result<Mesh> {
        let index_base = names.index_base;
        let any_clockwise = validate(&nodes, &triangles, &body_of, names)?;
        let n = nodes.len();
        // What the mesh derives from its data: each node's body, a sort of
        // the nodes for duplicates, unused nodes (8 bytes per node each);
        // the bodies' tags; with a clockwise triangle, the Jacobians and the
        // orientation's edge list (three 32-byte entries per triangle) and
        // neighbour lists (about 80 bytes per triangle).
        let per_triangle = if any_clockwise { 256 } else { 64 };
        let need = n
            .saturating_mul(24)
            .saturating_add(triangles.len().saturating_mul(per_triangle))
            .saturating_add(1 << 20);
        preflight(need, "the mesh's derived arrays")?;
        let jacobian =
            |tri: &[usize; 3]| TriGeometry::new(&[nodes[tri[0]], nodes[tri[1]], nodes[tri[2]]]);
        // (No array of Jacobians unless some triangle is clockwise: 17 MB
        // at 1M unknowns, held in the allocator's pool afterwards.)
        let turned = if any_clockwise {
            let j: Vec<f64> = triangles.iter().map(|t| jacobian(t).j).collect();
            orient(&mut triangles, &body_of, &j)
        } else {
            Vec::new()
        };
        let mut node_body = vec![None; n];
        for (tri, &body) in triangles.iter().zip(&body_of) {
            for &v in tri {
                node_body[v].get_or_insert(body);
            }
        }
        let mut bodies = body_of.clone();
        bodies.sort_unstable();
        bodies.dedup();
        // A builder that grew these by doubling leaves up to half of their
        // capacity unused, held for the mesh's whole life (38 MB at 1M
        // unknowns).
        nodes.shrink_to_fit();
        triangles.shrink_to_fit();
        body_of.shrink_to_fit();
        let mut mesh = Mesh {
            nodes,
            triangles,
            body_of,
            edges: Vec::new(),
            node_body,
            bodies,
            index_base,
            warnings: Vec::new(),
            curves: Vec::new(),
        };
        mesh.collect_warnings(&turned, names);
        Ok(mesh)
    }

    fn collect_warnings(&mut self, turned: &[Turned], names: &Names) {
        let unused: Vec<String> = (0..self.nodes.len())
            .filter(|&i| self.node_body[i].is_none())
            .map(|i| names.node(i))
            .collect();
        if !unused.is_empty() {
            self.warnings.push(format!(
                "{} node(s) not used by any triangle get no unknowns: {}",
                unused.len(),
                list(&unused)
            ));
        }
        // Coincident nodes are expected across a contact interface; inside
        // one body they usually mean an unmerged mesh (a hidden crack).
        let mut order: Vec<usize> = (0..self.nodes.len())
            .filter(|&i| self.node_body[i].is_some())
            .collect();
        order.sort_unstable_by(|&i, &j| {
            let (p, q) = (self.nodes[i], self.nodes[j]);
            p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
        });
        let dupes: Vec<String> = order
            .windows(2)
            .filter(|w| {
                self.nodes[w[0]] == self.nodes[w[1]] && self.node_body[w[0]] == self.node_body[w[1]]
            })
            .map(|w| format!("{}={}", names.node(w[0]), names.node(w[1])))
            .collect();
        if !dupes.is_empty() {
            self.warnings.push(format!(
                "{} pair(s) of coincident nodes inside one body (unmerged mesh, a crack?): {}",
                dupes.len(),
                list(&dupes)
            ));
        }
        for r in turned {
            self.warnings.push(format!(
                "body {}: {} triangle(s) numbered clockwise (e.g. {}) were turned \
                 counter-clockwise, numbering each region of the body consistently across shared \
                 edges; results refer to the turned triangles",
                r.body,
                r.count,
                names.triangle(r.first)
            ));
        }
        // Still clockwise after the turning: folds of the mesh.
        let mut inverted: BTreeMap<i32, usize> = BTreeMap::new();
        for (tri, &body) in self.triangles.iter().zip(&self.body_of) {
            if TriGeometry::new(&self.corners(tri)).j < 0.0 {
                *inverted.entry(body).or_default() += 1;
            }
        }
        for (body, n_inv) in inverted {
            self.warnings.push(format!(
                "body {body}: {n_inv} inverted triangle(s) (J < 0): TFEM tempers them with Jmin; \
                 plain FEM (tempering off) integrates them with |J|, a wrong stiffness"
            ));
        }
    }

    /// Sets the tagged boundary edges (0-based nodes), replacing previous
    /// ones. Each edge must be a side of at least one triangle. On error the
    /// mesh is unchanged.
    pub fn set_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        self.edges = self.checked_edges(edges, tags, &[])?;
        Ok(())
    }

    /// [`Mesh::set_boundary_edges`] with its errors naming the edges and
    /// their nodes as `names` says (by a file's tags, say).
    pub fn set_boundary_edges_with_names(
        &mut self,
        edges: &[[usize; 2]],
        tags: &[i32],
        names: &Names,
    ) -> Result<()> {
        self.edges = self.checked_edges_named(edges, tags, &[], names)?;
        Ok(())
    }

    /// Adds tagged boundary edges to those already set (one group at a
    /// time, say). An edge given again with a tag it already has is
    /// refused (its loads would count twice). On error the mesh is
    /// unchanged.
    pub fn add_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        let mut added = self.checked_edges(edges, tags, &self.edges)?;
        self.edges.append(&mut added);
        Ok(())
    }

    /// Replaces the boundary edges by `edges` (checked with
    /// [`Mesh::checked_edges`]), returning the previous ones.
    pub fn replace_edges(&mut self, edges: Vec<BoundaryEdge>) -> Vec<BoundaryEdge> {
        std::mem::replace(&mut self.edges, edges)
    }

    /// Validates tagged edges (0-based nodes) to join `existing` ones: each
    /// must be a side of a triangle, and no (edge, tag) may be given twice.
    pub fn checked_edges(
        &self,
        edges: &[[usize; 2]],
        tags: &[i32],
        existing: &[BoundaryEdge],
    ) -> Result<Vec<BoundaryEdge>> {
        self.checked_edges_named(edges, tags, existing, &Names::indices(self.index_base))
    }

    fn checked_edges_named(
        &self,
        edges: &[[usize; 2]],
        tags: &[i32],
        existing: &[BoundaryEdge],
        names: &Names,
    ) -> Result<Vec<BoundaryEdge>> {
        let b = names.index_base;
        if edges.len() != tags.len() {
            return Err(Error::argument(format!(
                "{} boundary edges but {} tags",
                edges.len(),
                tags.len()
            )));
        }
        let n = self.nodes.len();
        let mut owners: HashMap<(usize, usize), (usize, usize, u32)> = HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (p, q, r) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
                owners
                    .entry((p.min(q), p.max(q)))
                    .and_modify(|e| e.2 += 1)
                    .or_insert((t, r, 1));
            }
        }
        let mut seen: HashSet<(usize, usize, i32)> = existing
            .iter()
            .map(|e| {
                (
                    e.nodes[0].min(e.nodes[1]),
                    e.nodes[0].max(e.nodes[1]),
                    e.tag,
                )
            })
            .collect();
        let mut out = crate::error::reserved(edges.len(), "the boundary edges")?;
        for (e, (&[p, q], &tag)) in edges.iter().zip(tags).enumerate() {
            if p >= n || q >= n {
                return Err(Error::mesh(format!(
                    "{}: node index {} is out of range ({} nodes)",
                    names.edge(e),
                    if p >= n { p + b } else { q + b },
                    n
                )));
            }
            if p == q {
                return Err(Error::mesh(format!(
                    "{}: both ends are node {}",
                    names.edge(e),
                    names.node(p)
                )));
            }
            let owner = match owners.get(&(p.min(q), p.max(q))) {
                None => {
                    return Err(Error::mesh(format!(
                        "{} ({}) is not a side of any triangle",
                        names.edge(e),
                        names.ends(p, q)
                    )));
                }
                Some(&(t, r, 1)) => Some((t, r)),
                Some(_) => None,
            };
            let key = (p.min(q), p.max(q), tag);
            if !seen.insert(key) {
                return Err(Error::mesh(format!(
                    "{} ({}) is given tag {tag} twice: its loads would count twice",
                    names.edge(e),
                    names.ends(p, q)
                )));
            }
            out.push(BoundaryEdge {
                nodes: [p, q],
                tag,
                owner,
            });
        }
        Ok(out)
    }

    /// Node coordinates.
    pub fn nodes(&self) -> &[[f64; 2]] {
        &self.nodes
    }

    /// Triangles (0-based node indices).
    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// Body tag of each triangle.
    pub fn body_of(&self) -> &[i32] {
        &self.body_of
    }

    /// The distinct body tags, sorted.
    pub fn bodies(&self) -> &[i32] {
        &self.bodies
    }

    /// The body of the first triangle using each node (`None`: unused node).
    pub fn node_body(&self) -> &[Option<i32>] {
        &self.node_body
    }

    /// Tagged boundary edges.
    pub fn boundary_edges(&self) -> &[BoundaryEdge] {
        &self.edges
    }

    /// Declares the exact shape of the boundary tagged `tag`, so that
    /// refinement ([`crate::fem::refine`]) puts the nodes it adds on that
    /// tag's edges on the curve rather than at their chords' midpoints; it
    /// replaces a curve declared on the tag before. Refused, the mesh
    /// unchanged, if the curve is ill defined, no edge has the tag, or a
    /// node of the tag's edges lies farther from the curve than
    /// [`crate::fem::curve::CURVE_TOLERANCE`] of its size (naming the node
    /// and its distance).
    pub fn set_curve(&mut self, tag: i32, curve: Curve) -> Result<()> {
        curve.validate()?;
        let mut any = false;
        for e in self.edges.iter().filter(|e| e.tag == tag) {
            any = true;
            for v in e.nodes {
                let d = curve.distance(self.nodes[v]);
                // NaN (a non-finite node) is off the curve too.
                if d.is_nan() || d > curve.tolerance() {
                    return Err(Error::argument(format!(
                        "{} of an edge tagged {tag} lies {d:.3e} from the curve declared on \
                         the tag (at most {:.3e}): {curve:?}",
                        self.node_name(v),
                        curve.tolerance()
                    )));
                }
            }
        }
        if !any {
            return Err(Error::argument(format!(
                "no boundary edge has tag {tag}: a curve is declared on a tag of edges"
            )));
        }
        self.curves.retain(|(t, _)| *t != tag);
        self.curves.push((tag, curve));
        Ok(())
    }

    /// The curve declared on `tag`, if any.
    pub fn curve(&self, tag: i32) -> Option<&Curve> {
        self.curves.iter().find(|(t, _)| *t == tag).map(|(_, c)| c)
    }

    /// The curves declared on tags, with their tags.
    pub fn curves(&self) -> &[(i32, Curve)] {
        &self.curves
    }

    /// Gives this mesh (a refinement of `from`, whose nodes on curves are
    /// on them) the curves of `from`.
    pub(crate) fn carry_curves(&mut self, from: &Mesh) {
        self.curves = from.curves.clone();
    }

    /// Index base used in messages (0 for C, 1 for Fortran).
    pub fn index_base(&self) -> usize {
        self.index_base
    }

    /// Warnings found by validation (unused nodes, coincident nodes in one
    /// body, inverted or clockwise triangles).
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// Adds a warning about the mesh (say, what a file held that the mesh
    /// cannot: a reader's, after building it).
    pub fn warn(&mut self, warning: String) {
        self.warnings.push(warning);
    }

    /// The corners of a triangle.
    #[inline]
    pub fn corners(&self, tri: &[usize; 3]) -> [[f64; 2]; 3] {
        [self.nodes[tri[0]], self.nodes[tri[1]], self.nodes[tri[2]]]
    }

    /// The larger side of the bounding box: the default tempering
    /// wavelength λ and the length scale of tolerances.
    pub fn size(&self) -> f64 {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &self.nodes {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }

    /// Unit outward normal of a boundary edge, or `None` for an interior
    /// edge or a zero-length one.
    pub fn outward_normal(&self, edge: &BoundaryEdge) -> Option<[f64; 2]> {
        let (t, third) = edge.owner?;
        let [p, q] = edge.nodes;
        let (a, c) = (self.nodes[p], self.nodes[q]);
        let tv = [c[0] - a[0], c[1] - a[1]];
        let len = tv[0].hypot(tv[1]);
        if len == 0.0 {
            return None;
        }
        let left = [-tv[1] / len, tv[0] / len];
        let r = self.nodes[third];
        let side = left[0] * (r[0] - a[0]) + left[1] * (r[1] - a[1]);
        let interior_on_left = if side != 0.0 {
            side > 0.0
        } else {
            // Flat owner: trust the triangle's cyclic order (counter-clockwise
            // means the interior is on the left of p -> q).
            let tri = self.triangles[t];
            let k = tri.iter().position(|&v| v == p).unwrap_or(0);
            tri[(k + 1) % 3] == q
        };
        Some(if interior_on_left {
            [-left[0], -left[1]]
        } else {
            left
        })
    }

    /// Names node `i` in the user's index base.
    pub fn node_name(&self, i: usize) -> String {
        format!("node {}", i + self.index_base)
    }

    /// Names triangle `t` in the user's index base.
    pub fn triangle_name(&self, t: usize) -> String {
        format!("triangle {}", t + self.index_base)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Status;

    fn square() -> (Vec<[f64; 2]>, Vec<[usize; 3]>) {
        (
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            vec![[0, 1, 2], [0, 2, 3]],
        )
    }

    #[test]
    fn rejects_out_of_range_index_in_the_users_base() {
        let (n, _) = square();
        let e = Mesh::new(n, vec![[0, 1, 4]], vec![1], 1).unwrap_err();
        assert_eq!(e.status(), Status::InvalidMesh);
        assert!(e.message().contains("triangle 1"), "{}", e.message());
        assert!(e.message().contains("node index 5"), "{}", e.message());
    }

    #[test]
    fn rejects_repeated_node() {
        let (n, _) = square();
        let e = Mesh::new(n, vec![[0, 1, 2], [2, 3, 2]], vec![1, 1], 0).unwrap_err();
        assert!(
            e.message().contains("triangle 1: node 2 is repeated"),
            "{}",
            e.message()
        );
    }

    #[test]
    fn a_triangle_given_twice_is_refused_naming_both() {
        let (nodes, mut tris) = square();
        // The first triangle again, numbered the other way round.
        let t = tris[0];
        tris.push([t[0], t[2], t[1]]);
        let bodies = vec![1; tris.len()];
        let e = Mesh::new(nodes, tris, bodies, 1).unwrap_err();
        assert_eq!(e.status(), Status::InvalidMesh);
        assert!(
            e.message().contains("triangle 3") && e.message().contains("repeats triangle 1"),
            "{}",
            e.message()
        );
    }

    #[test]
    fn rejects_non_finite_coordinates() {
        let (mut n, t) = square();
        n[2][1] = f64::NAN;
        let e = Mesh::new(n, t, vec![1, 1], 0).unwrap_err();
        assert!(e.message().contains("node 2"), "{}", e.message());
    }

    #[test]
    fn rejects_empty_mesh() {
        assert!(Mesh::new(vec![], vec![], vec![], 0).is_err());
        let (n, _) = square();
        assert!(Mesh::new(n, vec![], vec![], 0).is_err());
    }

    #[test]
    fn degenerate_and_inverted_triangles_are_legal() {
        let n = vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [0.0, 1.0]];
        let m = Mesh::new(n, vec![[0, 1, 2], [0, 3, 1]], vec![1, 1], 0).unwrap();
        assert_eq!(m.triangles().len(), 2);
        assert!(m.warnings().iter().any(|w| w.contains("clockwise")));
    }

    #[test]
    fn warns_about_unused_and_coincident_nodes() {
        let n = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 0.0], [5.0, 5.0]];
        let m = Mesh::new(n, vec![[0, 1, 2], [3, 2, 1]], vec![1, 1], 0).unwrap();
        let w = m.warnings().join("\n");
        assert!(w.contains("not used") && w.contains('4'), "{w}");
        assert!(w.contains("coincident") && w.contains("1=3"), "{w}");
    }

    #[test]
    fn outward_normal_points_away_from_the_owner() {
        let (n, t) = square();
        let mut m = Mesh::new(n, t, vec![1, 1], 0).unwrap();
        m.set_boundary_edges(&[[1, 0], [2, 3]], &[5, 6]).unwrap();
        let n0 = m.outward_normal(&m.boundary_edges()[0]).unwrap();
        let n1 = m.outward_normal(&m.boundary_edges()[1]).unwrap();
        assert_eq!(n0, [0.0, -1.0]);
        assert_eq!(n1, [0.0, 1.0]);
    }

    #[test]
    fn boundary_edge_must_be_a_triangle_side_and_failure_keeps_old_edges() {
        let (n, t) = square();
        let mut m = Mesh::new(n, t, vec![1, 1], 0).unwrap();
        m.set_boundary_edges(&[[0, 1]], &[1]).unwrap();
        let e = m.set_boundary_edges(&[[1, 3]], &[1]).unwrap_err();
        assert!(e.message().contains("not a side"), "{}", e.message());
        let e = m
            .set_boundary_edges(&[[0, 1], [1, 2], [1, 7]], &[1, 1, 1])
            .unwrap_err();
        assert!(e.message().contains("boundary edge 2"), "{}", e.message());
        assert_eq!(m.boundary_edges().len(), 1);
    }
}
