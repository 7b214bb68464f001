//! Frictionless contact by activating inverted elements of a contact mesh B
//! (METHOD.md §3): the contact pairs, the construction and checking of B,
//! and the constitutive law of its elements.
//!
//! A flat element of B on a conforming interface is exactly a spring between
//! two coincident nodes; with Jmin = h³/λ it is a node-to-node penalty of
//! about E_c·λ/h² per unit length, so interpenetration is O(h²).
//!
//! Each element of B carries its interface normal n (a flat element has
//! none of its own), its initial Jacobian J0 (zero for touching surfaces,
//! positive for a gap) and the length of its edge on the interface. Its
//! "opening" is the Jacobian linearised about the initial configuration,
//! J0 + Σ g_i·u_i, which for a flat conforming element is the node-pair
//! normal gap times the edge length. The element's stress acts on that
//! opening, not on the displacement jump alone, so an element that closes an
//! initial gap switches on without a force jump.

use std::collections::{BTreeMap, HashMap, HashSet};

use crate::element::{TriGeometry, b_hat};
use crate::error::{Error, Result};
use crate::material::Material;
use crate::mesh::Mesh;

/// The constitutive law of the contact elements.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactLaw {
    /// Only the normal strain is penalised: D_c = E_c m mᵀ with
    /// m = [n_x², n_y², n_x n_y]. Tangential slip is free.
    Frictionless = 0,
    /// Plain tempered isotropic elasticity in B (E_c, ν of the softer body):
    /// it also resists slip, so it ties the surfaces (sticking contact).
    Stick = 1,
}

/// How an element of B is found inverted.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InversionTest {
    /// J linearised about the initial configuration, J0 + Σ g_i·u_i < 0
    /// (consistent with small strain; for a flat conforming element, the
    /// node-pair normal gap). Under the frictionless law, only its normal
    /// part J0 + Σ (n·g_i)(n·u_i) — the element's normal opening: the
    /// node-to-segment gap at its apex times its interface edge, the very
    /// quantity the law penalises — so that an active element always pushes.
    /// The two differ by J0·ε_tt (the interface stretching times the initial
    /// gap): nothing on touching surfaces, but on a curved gap, where the
    /// bodies strain by a percent, enough to activate elements that then
    /// pull. The default.
    Linearised = 0,
    /// The seed's literal test, J(X + u) < 0. Its second-order term (slope
    /// times slip) can exceed the penalty penetration on fine meshes and make
    /// the loop cycle.
    Literal = 1,
}

/// Options of the contact solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactOptions {
    /// Constitutive law of B.
    pub law: ContactLaw,
    /// E_c; `None` = the smaller Young's modulus of the two bodies of each
    /// pair (stiffer values only worsen conditioning).
    pub contact_modulus: Option<f64>,
    /// λ of the contact elements (Jmin = h³/λ), a length in model units;
    /// `None` = the larger side of the mesh's bounding box.
    pub lambda: Option<f64>,
    /// The inversion test.
    pub test: InversionTest,
    /// Cap on active-set iterations.
    pub max_iterations: usize,
    /// Refactorise the whole matrix at every active-set iteration instead
    /// of condensing the changes on the interface (see
    /// [`crate::condensation`]); slower, kept for comparison.
    pub refactorize: bool,
}

impl Default for ContactOptions {
    fn default() -> Self {
        ContactOptions {
            law: ContactLaw::Frictionless,
            contact_modulus: None,
            lambda: None,
            test: InversionTest::Linearised,
            max_iterations: 50,
            refactorize: false,
        }
    }
}

impl ContactOptions {
    /// Checks the options.
    pub fn validate(&self) -> Result<()> {
        if let Some(e) = self.contact_modulus {
            if !(e.is_finite() && e > 0.0) {
                return Err(Error::argument(format!(
                    "contact modulus E_c = {e} must be finite and > 0"
                )));
            }
        }
        if let Some(l) = self.lambda {
            if !(l.is_finite() && l > 0.0) {
                return Err(Error::argument(format!(
                    "contact lambda = {l} must be finite and > 0"
                )));
            }
        }
        if self.max_iterations == 0 {
            return Err(Error::argument("max_iterations must be at least 1"));
        }
        Ok(())
    }
}

/// A potential contact interface: boundary edges tagged `tag_a` on one body
/// and `tag_b` on another.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    /// Tag of the edges on the first body.
    pub tag_a: i32,
    /// Tag of the edges on the second body.
    pub tag_b: i32,
    /// Body carrying `tag_a`.
    pub body_a: i32,
    /// Body carrying `tag_b`.
    pub body_b: i32,
    /// A contact mesh handed over by the user (0-based nodes), if any.
    pub user_mesh: Option<Vec<[usize; 3]>>,
}

/// One element of the contact mesh B.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactElement {
    /// Nodes, ordered so that J > 0 when the gap opens.
    pub nodes: [usize; 3],
    /// Unit interface normal, pointing from body a to body b.
    pub normal: [f64; 2],
    /// Initial Jacobian (0 for touching surfaces).
    pub j0: f64,
    /// Longest edge (for Jmin = h³/λ).
    pub h: f64,
    /// Length of the element's edge on the interface.
    pub edge_length: f64,
    /// Index of the pair it belongs to.
    pub pair: usize,
}

/// Interface nodes and edges of one side of a pair.
struct Side {
    body: i32,
    nodes: HashSet<usize>,
    /// edge (min, max) -> outward normal of the body
    edges: HashMap<(usize, usize), [f64; 2]>,
    /// edges as given, oriented so that the body lies on their right
    oriented: Vec<[usize; 2]>,
}

fn side_of(mesh: &Mesh, tag: i32) -> Result<Side> {
    let mut body = None;
    let mut side = Side {
        body: 0,
        nodes: HashSet::new(),
        edges: HashMap::new(),
        oriented: Vec::new(),
    };
    let b = mesh.index_base();
    for (k, e) in mesh.boundary_edges().iter().enumerate() {
        if e.tag != tag {
            continue;
        }
        let Some((t, _)) = e.owner else {
            return Err(Error::contact(format!(
                "boundary edge {} (tag {tag}) is interior to the mesh: it cannot bound a contact interface",
                k + b
            )));
        };
        let Some(n) = mesh.outward_normal(e) else {
            return Err(Error::contact(format!(
                "boundary edge {} (tag {tag}) has zero length",
                k + b
            )));
        };
        let tb = mesh.body_of()[t];
        match body {
            None => body = Some(tb),
            Some(b0) if b0 != tb => {
                return Err(Error::contact(format!(
                    "contact tag {tag} spans bodies {b0} and {tb}: each side of a pair must lie on one body"
                )));
            }
            _ => {}
        }
        let [p, q] = e.nodes;
        // Orient p -> q so that the outward normal is the left normal.
        let (xp, xq) = (mesh.nodes()[p], mesh.nodes()[q]);
        let left = [-(xq[1] - xp[1]), xq[0] - xp[0]];
        let pq = if left[0] * n[0] + left[1] * n[1] >= 0.0 {
            [p, q]
        } else {
            [q, p]
        };
        side.nodes.insert(p);
        side.nodes.insert(q);
        side.edges.insert((p.min(q), p.max(q)), n);
        side.oriented.push(pq);
    }
    match body {
        None => Err(Error::contact(format!(
            "no boundary edge has contact tag {tag}"
        ))),
        Some(bd) => {
            side.body = bd;
            Ok(side)
        }
    }
}

/// Resolves the bodies of a pair of tags, checking that they are distinct.
pub fn pair_bodies(mesh: &Mesh, tag_a: i32, tag_b: i32) -> Result<(i32, i32)> {
    if tag_a == tag_b {
        return Err(Error::contact(format!(
            "a contact pair needs two different tags (got {tag_a} twice)"
        )));
    }
    let a = side_of(mesh, tag_a)?;
    let b = side_of(mesh, tag_b)?;
    if a.body == b.body {
        return Err(Error::contact(format!(
            "contact tags {tag_a} and {tag_b} are both on body {}: self-contact is not supported",
            a.body
        )));
    }
    Ok((a.body, b.body))
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Relative tangential mismatch above which two interface nodes are not
/// "matching" (the interface is then non-conforming).
const TANGENTIAL_TOL: f64 = 1e-6;

/// Builds B for a conforming pair: every pair of facing edges gives a flat
/// quad split into two triangles. Nodes are matched across the interface
/// when their offset is normal to it (a small initial gap is allowed, up to
/// half the local edge length) and tangentially within 1e-6 of the local
/// edge length; an unmatched node is an error naming it.
pub fn build_conforming(
    mesh: &Mesh,
    pair: usize,
    tag_a: i32,
    tag_b: i32,
) -> Result<Vec<ContactElement>> {
    let a = side_of(mesh, tag_a)?;
    let b = side_of(mesh, tag_b)?;
    let x = mesh.nodes();
    let base = mesh.index_base();

    // Local edge length and averaged outward normal at every node of side a.
    let mut local_h: HashMap<usize, f64> = HashMap::new();
    let mut normal_a: HashMap<usize, [f64; 2]> = HashMap::new();
    for (&(p, q), n) in &a.edges {
        let l = dist(x[p], x[q]);
        for v in [p, q] {
            let h = local_h.entry(v).or_insert(f64::INFINITY);
            *h = h.min(l);
            let m = normal_a.entry(v).or_insert([0.0, 0.0]);
            m[0] += n[0];
            m[1] += n[1];
        }
    }
    for &(p, q) in b.edges.keys() {
        let l = dist(x[p], x[q]);
        for v in [p, q] {
            let h = local_h.entry(v).or_insert(f64::INFINITY);
            *h = h.min(l);
        }
    }

    // Candidates along the major axis of side a.
    let mut a_nodes: Vec<usize> = a.nodes.iter().copied().collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for &v in &a_nodes {
        for k in 0..2 {
            lo[k] = lo[k].min(x[v][k]);
            hi[k] = hi[k].max(x[v][k]);
        }
    }
    let axis = usize::from(hi[1] - lo[1] > hi[0] - lo[0]);
    a_nodes.sort_unstable_by(|&p, &q| x[p][axis].total_cmp(&x[q][axis]).then(p.cmp(&q)));
    let keys: Vec<f64> = a_nodes.iter().map(|&v| x[v][axis]).collect();

    let mut partner_of_b: HashMap<usize, usize> = HashMap::new();
    let mut partner_of_a: HashMap<usize, usize> = HashMap::new();
    let mut b_nodes: Vec<usize> = b.nodes.iter().copied().collect();
    b_nodes.sort_unstable();
    for &vb in &b_nodes {
        let hb = local_h[&vb];
        let radius = 0.5 * hb;
        let key = x[vb][axis];
        let start = keys.partition_point(|&k| k < key - radius);
        let mut best: Option<(f64, usize)> = None;
        for (idx, &va) in a_nodes.iter().enumerate().skip(start) {
            if keys[idx] > key + radius {
                break;
            }
            let d = dist(x[va], x[vb]);
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, va));
            }
        }
        let matched = best.filter(|&(d, va)| {
            let h = hb.min(local_h[&va]);
            let n = normal_a[&va];
            let nn = n[0].hypot(n[1]).max(f64::MIN_POSITIVE);
            let off = [x[vb][0] - x[va][0], x[vb][1] - x[va][1]];
            let normal_part = (off[0] * n[0] + off[1] * n[1]) / nn;
            let tangential = (d * d - normal_part * normal_part).max(0.0).sqrt();
            d <= 0.5 * h && tangential <= TANGENTIAL_TOL * h
        });
        let Some((_, va)) = matched else {
            let hint = match best {
                Some((d, va)) => format!("nearest is node {} at distance {d:.3e}", va + base),
                None => "no node of the other side within half an edge".to_string(),
            };
            return Err(Error::contact(format!(
                "node {} (contact tag {tag_b}) has no matching node on tag {tag_a}: {hint} \
                 (non-conforming interfaces are not supported yet; hand over the contact mesh instead)",
                vb + base
            )));
        };
        if let Some(prev) = partner_of_a.insert(va, vb) {
            return Err(Error::contact(format!(
                "nodes {} and {} (tag {tag_b}) both match node {} (tag {tag_a})",
                prev + base,
                vb + base,
                va + base
            )));
        }
        partner_of_b.insert(vb, va);
    }
    if let Some(&va) = a_nodes.iter().find(|v| !partner_of_a.contains_key(v)) {
        return Err(Error::contact(format!(
            "node {} (contact tag {tag_a}) has no matching node on tag {tag_b} \
             (the interfaces differ in extent or are non-conforming)",
            va + base
        )));
    }

    let mut elements = Vec::with_capacity(2 * a.oriented.len());
    for &[a1, b1] in &a.oriented {
        let (a2, b2) = (partner_of_a[&a1], partner_of_a[&b1]);
        if !b.edges.contains_key(&(a2.min(b2), a2.max(b2))) {
            return Err(Error::contact(format!(
                "edge ({}, {}) of tag {tag_a} faces nodes {} and {} that are not an edge of tag {tag_b}",
                a1 + base,
                b1 + base,
                a2 + base,
                b2 + base
            )));
        }
        let n = a.edges[&(a1.min(b1), a1.max(b1))];
        for (tri, edge_len) in [
            ([a1, b1, b2], dist(x[a1], x[b1])),
            ([a1, b2, a2], dist(x[a2], x[b2])),
        ] {
            let geo = TriGeometry::new(&mesh.corners(&tri));
            elements.push(ContactElement {
                nodes: tri,
                normal: n,
                j0: geo.j,
                h: geo.h,
                edge_length: edge_len,
                pair,
            });
        }
    }
    Ok(elements)
}

/// Checks a contact mesh handed over by the user for one pair: every
/// triangle must have nodes on both interfaces, with its two same-side
/// nodes forming an interface edge. Triangles oriented so that J decreases
/// when the gap opens are flipped (the count is returned); a triangle whose
/// J does not depend on the opening is rejected.
pub fn check_user_mesh(
    mesh: &Mesh,
    pair: usize,
    tag_a: i32,
    tag_b: i32,
    triangles: &[[usize; 3]],
) -> Result<(Vec<ContactElement>, usize)> {
    let a = side_of(mesh, tag_a)?;
    let b = side_of(mesh, tag_b)?;
    let x = mesh.nodes();
    let base = mesh.index_base();
    let n_nodes = x.len();
    let mut out = Vec::with_capacity(triangles.len());
    let mut flipped = 0;
    for (t, tri) in triangles.iter().enumerate() {
        let name = format!("contact triangle {}", t + base);
        if let Some(&v) = tri.iter().find(|&&v| v >= n_nodes) {
            return Err(Error::contact(format!(
                "{name}: node index {} is out of range",
                v + base
            )));
        }
        if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
            return Err(Error::contact(format!("{name}: a node is repeated")));
        }
        let on_a: Vec<bool> = tri.iter().map(|v| a.nodes.contains(v)).collect();
        if let Some(k) = (0..3).find(|&k| !on_a[k] && !b.nodes.contains(&tri[k])) {
            return Err(Error::contact(format!(
                "{name}: node {} is on neither interface (tags {tag_a}, {tag_b})",
                tri[k] + base
            )));
        }
        let count_a = on_a.iter().filter(|&&s| s).count();
        if count_a == 0 || count_a == 3 {
            return Err(Error::contact(format!(
                "{name}: all its nodes are on one interface; it must bridge both"
            )));
        }
        // The two nodes on the same side form its interface edge.
        let same_on_a = count_a == 2;
        let pairs: Vec<usize> = (0..3).filter(|&k| on_a[k] == same_on_a).collect();
        let (p, q) = (tri[pairs[0]], tri[pairs[1]]);
        let key = (p.min(q), p.max(q));
        let normal = if same_on_a {
            a.edges.get(&key).copied()
        } else {
            b.edges.get(&key).map(|n| [-n[0], -n[1]])
        };
        let Some(normal) = normal else {
            return Err(Error::contact(format!(
                "{name}: nodes {} and {} are not an edge of interface tag {}",
                p + base,
                q + base,
                if same_on_a { tag_a } else { tag_b }
            )));
        };
        let mut nodes = *tri;
        let mut geo = TriGeometry::new(&mesh.corners(&nodes));
        // dJ when the side-b nodes move along +n (the gap opens).
        let sens: f64 = (0..3)
            .filter(|&k| !on_a[k])
            .map(|k| geo.g[k][0] * normal[0] + geo.g[k][1] * normal[1])
            .sum();
        if sens.abs() <= 1e-12 * geo.h * geo.h {
            return Err(Error::contact(format!(
                "{name}: its Jacobian does not change when the gap opens (degenerate across the interface)"
            )));
        }
        if sens < 0.0 {
            nodes.swap(1, 2);
            geo = TriGeometry::new(&mesh.corners(&nodes));
            flipped += 1;
        }
        out.push(ContactElement {
            nodes,
            normal,
            j0: geo.j,
            h: geo.h,
            edge_length: dist(x[p], x[q]),
            pair,
        });
    }
    Ok((out, flipped))
}

/// The element matrix, its load from the initial gap, and the data needed
/// to evaluate its pressure, for one contact element.
pub struct ContactStiffness {
    /// 6x6 stiffness, row-major.
    pub k: [f64; 36],
    /// Equivalent nodal force of the initial opening J0 (zero when touching).
    pub f0: [f64; 6],
}

/// Voigt tensor n⊗n with engineering shear: [n_x², n_y², 2 n_x n_y].
fn e_n(n: [f64; 2]) -> [f64; 3] {
    [n[0] * n[0], n[1] * n[1], 2.0 * n[0] * n[1]]
}

/// The contact constitutive matrix: E_c m mᵀ with m = [n_x², n_y², n_x n_y]
/// for the frictionless law; for the stick law the isotropic D of `soft`
/// (the softer body's material: ν and plane mode) with Young's modulus E_c.
pub fn law_matrix(law: ContactLaw, e_c: f64, soft: &Material, n: [f64; 2]) -> [[f64; 3]; 3] {
    match law {
        ContactLaw::Frictionless => {
            let m = [n[0] * n[0], n[1] * n[1], n[0] * n[1]];
            let mut d = [[0.0; 3]; 3];
            for r in 0..3 {
                for c in 0..3 {
                    d[r][c] = e_c * m[r] * m[c];
                }
            }
            d
        }
        ContactLaw::Stick => soft.with_young(e_c).d_matrix(),
    }
}

/// The active set the loop starts from: per pair, the elements whose gap
/// (J₀ over the interface edge: the apex's distance from the edge) is within
/// 1e-3 of their size of the pair's smallest gap. Touching or uniformly
/// spaced surfaces start fully active (the seed's choice: the first solve
/// pulls a small uniform gap closed, which keeps a body held only by contact
/// restrained); curved ones start from their first points of contact, so
/// that the loop grows the set instead of releasing a glued interface one
/// element at a time.
pub fn initial_active_set(elements: &[ContactElement]) -> Vec<bool> {
    let gap = |e: &ContactElement| {
        if e.edge_length > 0.0 {
            e.j0 / e.edge_length
        } else {
            0.0
        }
    };
    let mut smallest: BTreeMap<usize, f64> = BTreeMap::new();
    for e in elements {
        let g = smallest.entry(e.pair).or_insert(f64::INFINITY);
        *g = g.min(gap(e));
    }
    elements
        .iter()
        .map(|e| gap(e) <= smallest[&e.pair] + 1e-3 * e.h)
        .collect()
}

/// Stiffness and initial-gap load of an active contact element. An active
/// element is inverted, so max(J, Jmin) = Jmin: `t` is its Jmin.
pub fn contact_stiffness(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    n: [f64; 2],
    j0: f64,
    t: f64,
) -> ContactStiffness {
    let b = b_hat(geo);
    let mut db = [[0.0; 6]; 3];
    for r in 0..3 {
        for c in 0..6 {
            db[r][c] = d[r][0] * b[0][c] + d[r][1] * b[1][c] + d[r][2] * b[2][c];
        }
    }
    let s = 0.5 / t;
    let mut k = [0.0; 36];
    for a in 0..6 {
        for c in a..6 {
            let v = (b[0][a] * db[0][c] + b[1][a] * db[1][c] + b[2][a] * db[2][c]) * s;
            k[a * 6 + c] = v;
            k[c * 6 + a] = v;
        }
    }
    // Pre-strain J0·(n⊗n): f0 = -(1/(2T)) B̂ᵀ D (J0 e_n).
    let en = e_n(n);
    let mut f0 = [0.0; 6];
    if j0 != 0.0 {
        let s0: Vec<f64> = (0..3)
            .map(|r| j0 * (d[r][0] * en[0] + d[r][1] * en[1] + d[r][2] * en[2]))
            .collect();
        for (a, f) in f0.iter_mut().enumerate() {
            *f = -s * (b[0][a] * s0[0] + b[1][a] * s0[1] + b[2][a] * s0[2]);
        }
    }
    ContactStiffness { k, f0 }
}

/// Contact pressure (positive in compression) of an active element with
/// element displacements `ue`: -n·σ·n with σ = D (B̂u + J0 n⊗n) / T.
pub fn contact_pressure(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    n: [f64; 2],
    j0: f64,
    t: f64,
    ue: &[f64; 6],
) -> f64 {
    let b = b_hat(geo);
    let en = e_n(n);
    let mut s = [0.0; 3];
    for r in 0..3 {
        s[r] = (0..6).map(|c| b[r][c] * ue[c]).sum::<f64>() + j0 * en[r];
    }
    let sigma: Vec<f64> = (0..3)
        .map(|r| (d[r][0] * s[0] + d[r][1] * s[1] + d[r][2] * s[2]) / t)
        .collect();
    -(en[0] * sigma[0] + en[1] * sigma[1] + en[2] * sigma[2])
}

/// The linearised Jacobian J0 + Σ g_i·u_i.
/// The linearised opening the inversion test uses and the law penalises:
/// for the frictionless law the normal part of the linearised J,
/// J0 + Σ (n·g_i)(n·u_i); for the stick law the whole linearised J.
pub fn linearised_opening(geo: &TriGeometry, law: ContactLaw, n: [f64; 2], ue: &[f64; 6]) -> f64 {
    match law {
        ContactLaw::Stick => linearised_jacobian(geo, ue),
        ContactLaw::Frictionless => {
            geo.j
                + (0..3)
                    .map(|i| {
                        (geo.g[i][0] * n[0] + geo.g[i][1] * n[1])
                            * (ue[2 * i] * n[0] + ue[2 * i + 1] * n[1])
                    })
                    .sum::<f64>()
        }
    }
}

/// Coefficient of element DOF `a` (node a/2, component a%2) in
/// [`linearised_opening`].
pub fn opening_coefficient(geo: &TriGeometry, law: ContactLaw, n: [f64; 2], a: usize) -> f64 {
    let g = geo.g[a / 2];
    match law {
        ContactLaw::Stick => g[a % 2],
        ContactLaw::Frictionless => (g[0] * n[0] + g[1] * n[1]) * n[a % 2],
    }
}

/// The linearised Jacobian J0 + Σ g_i·u_i of an element with displacements
/// `ue`.
pub fn linearised_jacobian(geo: &TriGeometry, ue: &[f64; 6]) -> f64 {
    geo.j
        + (0..3)
            .map(|i| geo.g[i][0] * ue[2 * i] + geo.g[i][1] * ue[2 * i + 1])
            .sum::<f64>()
}

/// Builds B for a pair whose interface nodes do not match (METHOD.md §5):
/// both interfaces are chained into polylines running the same way, every
/// node gets the arclength parameter of its projection on the first
/// polyline (extended beyond its ends), and the strip between them is
/// triangulated by advancing along whichever polyline has the nearer next
/// node, over the range where the two interfaces face each other (plus one
/// edge at each end). Each triangle has an edge on one interface and a node
/// on the other; orientation and normals are set as for a user mesh.
pub fn build_nonconforming(
    mesh: &Mesh,
    pair: usize,
    tag_a: i32,
    tag_b: i32,
) -> Result<Vec<ContactElement>> {
    let a = side_of(mesh, tag_a)?;
    let b = side_of(mesh, tag_b)?;
    let x = mesh.nodes();
    let chain_a = chain(mesh, &a, tag_a)?;
    let mut chain_b = chain(mesh, &b, tag_b)?;
    // Each chain has its body on the right; facing each other they run in
    // opposite directions: turn b around.
    chain_b.reverse();
    // Arclength along a, and the projection of any point on it (extended
    // linearly beyond both ends).
    let mut s_a = vec![0.0; chain_a.len()];
    for k in 1..chain_a.len() {
        s_a[k] = s_a[k - 1] + dist(x[chain_a[k - 1]], x[chain_a[k]]);
    }
    let total = s_a[s_a.len() - 1];
    let project = |p: [f64; 2]| -> f64 {
        let mut best = (f64::INFINITY, 0.0);
        for k in 0..chain_a.len() - 1 {
            let (p0, p1) = (x[chain_a[k]], x[chain_a[k + 1]]);
            let d = [p1[0] - p0[0], p1[1] - p0[1]];
            let len2 = d[0] * d[0] + d[1] * d[1];
            let mut t = ((p[0] - p0[0]) * d[0] + (p[1] - p0[1]) * d[1]) / len2;
            let (lo, hi) = (
                if k == 0 { f64::NEG_INFINITY } else { 0.0 },
                if k + 2 == chain_a.len() {
                    f64::INFINITY
                } else {
                    1.0
                },
            );
            t = t.clamp(lo, hi);
            let q = [p0[0] + t * d[0], p0[1] + t * d[1]];
            let dd = dist(p, q);
            if dd < best.0 {
                best = (dd, s_a[k] + t * len2.sqrt());
            }
        }
        best.1
    };
    let s_b: Vec<f64> = chain_b.iter().map(|&v| project(x[v])).collect();
    let base = mesh.index_base();
    if let Some(k) = (1..s_b.len()).find(|&k| s_b[k] < s_b[k - 1]) {
        return Err(Error::contact(format!(
            "interface tag {tag_b} folds back along interface tag {tag_a} at node {}: the two interfaces must face each other",
            chain_b[k] + base
        )));
    }
    let (lo, hi) = (s_b[0].max(0.0), s_b[s_b.len() - 1].min(total));
    if hi.is_nan() || hi <= lo {
        return Err(Error::contact(format!(
            "interfaces tags {tag_a} and {tag_b} do not face each other (no overlap along the interface)"
        )));
    }
    // Keep the part of each chain over [lo, hi] plus one node beyond each end.
    let window = |s: &[f64]| -> (usize, usize) {
        let first = s.iter().rposition(|&v| v <= lo).unwrap_or(0);
        let last = s.iter().position(|&v| v >= hi).unwrap_or(s.len() - 1);
        (first, last.max(first + 1).min(s.len() - 1))
    };
    let (a0, a1) = window(&s_a);
    let (b0, b1) = window(&s_b);
    let (ca, sa) = (&chain_a[a0..=a1], &s_a[a0..=a1]);
    let (cb, sb) = (&chain_b[b0..=b1], &s_b[b0..=b1]);
    let mut tris = Vec::with_capacity(ca.len() + cb.len());
    let (mut i, mut j) = (0, 0);
    while i + 1 < ca.len() || j + 1 < cb.len() {
        let advance_a = if i + 1 == ca.len() {
            false
        } else if j + 1 == cb.len() {
            true
        } else {
            sa[i + 1] <= sb[j + 1]
        };
        if advance_a {
            tris.push([ca[i], ca[i + 1], cb[j]]);
            i += 1;
        } else {
            tris.push([ca[i], cb[j + 1], cb[j]]);
            j += 1;
        }
    }
    Ok(check_user_mesh(mesh, pair, tag_a, tag_b, &tris)?.0)
}

/// The edges of one side chained into a single polyline, in their
/// orientation (body on the right).
fn chain(mesh: &Mesh, side: &Side, tag: i32) -> Result<Vec<usize>> {
    let base = mesh.index_base();
    let mut next: HashMap<usize, usize> = HashMap::new();
    let mut has_prev: HashSet<usize> = HashSet::new();
    for &[p, q] in &side.oriented {
        if next.insert(p, q).is_some() {
            return Err(Error::contact(format!(
                "interface tag {tag} branches at node {}: it must be a single chain of edges",
                p + base
            )));
        }
        has_prev.insert(q);
    }
    let starts: Vec<usize> = next
        .keys()
        .copied()
        .filter(|v| !has_prev.contains(v))
        .collect();
    let start = match starts.as_slice() {
        [s] => *s,
        [] => {
            return Err(Error::contact(format!(
                "interface tag {tag} is a closed loop: open it into a chain of edges"
            )));
        }
        _ => {
            return Err(Error::contact(format!(
                "interface tag {tag} has {} separate pieces: use one contact pair per piece",
                starts.len()
            )));
        }
    };
    let mut out = vec![start];
    let mut v = start;
    while let Some(&w) = next.get(&v) {
        out.push(w);
        v = w;
        if out.len() > side.oriented.len() + 1 {
            break;
        }
    }
    if out.len() != side.oriented.len() + 1 {
        return Err(Error::contact(format!(
            "interface tag {tag} is not a single chain of edges (near node {})",
            v + base
        )));
    }
    Ok(out)
}

/// Builds B for a pair: conforming (node-to-node quads) when the nodes of
/// the two interfaces match, else by triangulating the strip between them.
pub fn build(mesh: &Mesh, pair: usize, tag_a: i32, tag_b: i32) -> Result<Vec<ContactElement>> {
    match build_conforming(mesh, pair, tag_a, tag_b) {
        Ok(elements) => Ok(elements),
        Err(conforming) => build_nonconforming(mesh, pair, tag_a, tag_b).map_err(|e| {
            Error::contact(format!(
                "{} (as a conforming interface: {})",
                e.message(),
                conforming.message()
            ))
        }),
    }
}
