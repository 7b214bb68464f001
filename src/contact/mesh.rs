//! The contact mesh B of a pair: built from matching nodes
//! ([`build_conforming`]), by triangulating the strip between two
//! non-matching interfaces ([`build_nonconforming`]), or checked when the
//! user hands it over ([`check_user_mesh`]).

use std::collections::{HashMap, HashSet};

use super::{ContactElement, ContactPair};
use crate::error::{Error, Result, out_of_memory, reserved};
use crate::fem::element::TriGeometry;
use crate::fem::mesh::Mesh;

/// One side of a contact interface: a chain of edges of one body, each
/// with the body's outward normal.
#[derive(Debug, Clone)]
pub struct Side {
    /// The name of the side in messages (a boundary-edge tag, or the host
    /// code's own surface number).
    pub tag: i32,
    /// The body the side bounds.
    pub body: i32,
    /// The side's index in the host code's context
    /// ([`crate::contact::HostContact::add_side`]), `None` for a side of a
    /// mesh (known by its tag alone).
    index: Option<usize>,
    nodes: HashSet<usize>,
    /// edge (min, max) -> outward normal of the body
    edges: HashMap<(usize, usize), [f64; 2]>,
    /// edges as given, oriented so that the body lies on their right
    oriented: Vec<[usize; 2]>,
    /// node -> nodal outward normal ([`nodal_normals`])
    node_normals: HashMap<usize, [f64; 2]>,
}

impl Side {
    /// The side made of the boundary edges of `mesh` tagged `tag`, which
    /// must all bound one body (their owning triangles give the normals).
    pub fn of_tag(mesh: &Mesh, tag: i32) -> Result<Side> {
        side_of(mesh, tag)
    }

    /// Side `index` of a host code's context, of body `body`, made of
    /// `edges` (node pairs indexing `nodes`), each given with its body on
    /// the left of p → q (the counter-clockwise orientation of a body's
    /// boundary). Refuses an edge of zero length, given twice, or running
    /// against its neighbour (a node that starts or ends two edges), naming
    /// it (its position in `base`, its nodes as [`Nodes::name`] gives them).
    pub fn from_edges(
        nodes: Nodes<'_>,
        index: usize,
        tag: i32,
        body: i32,
        edges: &[[usize; 2]],
    ) -> Result<Side> {
        let (x, base) = (nodes.x, nodes.base);
        let mut side = Side {
            tag,
            body,
            index: Some(index),
            nodes: HashSet::new(),
            edges: HashMap::new(),
            oriented: Vec::new(),
            node_normals: HashMap::new(),
        };
        if edges.is_empty() {
            return Err(Error::contact(format!(
                "contact {} has no edges",
                side.name()
            )));
        }
        // The edge that starts, and the one that ends, at each node: along
        // a chain of consistently oriented edges each node starts and ends
        // at most one.
        let mut starts: HashMap<usize, usize> = HashMap::new();
        let mut ends: HashMap<usize, usize> = HashMap::new();
        for (k, &[p, q]) in edges.iter().enumerate() {
            let (xp, xq) = (x[p], x[q]);
            let len = dist(xp, xq);
            if len.is_nan() || len <= 0.0 {
                return Err(Error::contact(format!(
                    "edge {} (nodes {}, {}) of contact {} has zero length",
                    k + base,
                    nodes.name(p),
                    nodes.name(q),
                    side.name()
                )));
            }
            // Body on the left of p → q: the outward normal is the right
            // one, and q → p has the body on its right.
            let n = [(xq[1] - xp[1]) / len, -(xq[0] - xp[0]) / len];
            if side.edges.insert((p.min(q), p.max(q)), n).is_some() {
                return Err(Error::contact(format!(
                    "edge {} (nodes {}, {}) of contact {} is given twice",
                    k + base,
                    nodes.name(p),
                    nodes.name(q),
                    side.name()
                )));
            }
            for (v, seen) in [(p, &mut starts), (q, &mut ends)] {
                if let Some(j) = seen.insert(v, k) {
                    return Err(Error::contact(format!(
                        "edge {} (nodes {}, {}) of contact {} runs against edge {} at node {}: \
                         give every edge with its body on its left (counter-clockwise)",
                        k + base,
                        nodes.name(p),
                        nodes.name(q),
                        side.name(),
                        j + base,
                        nodes.name(v)
                    )));
                }
            }
            side.nodes.insert(p);
            side.nodes.insert(q);
            side.oriented.push([q, p]);
        }
        side.node_normals = nodal_normals(&side.edges);
        Ok(side)
    }

    /// Whether node `v` is on the side.
    pub fn contains(&self, v: usize) -> bool {
        self.nodes.contains(&v)
    }

    /// Its edges as given, each with the body on its right.
    pub fn edges(&self) -> &[[usize; 2]] {
        &self.oriented
    }

    /// The side in messages: `tag 3` for a side of a mesh, `side 0 (tag
    /// 3)` for a host code's side, whose tag is its own number and whose
    /// index is what its pairs are declared with.
    pub fn name(&self) -> String {
        match self.index {
            Some(i) => format!("side {i} (tag {})", self.tag),
            None => format!("tag {}", self.tag),
        }
    }
}

/// `v` scaled to unit length.
fn unit(v: [f64; 2]) -> [f64; 2] {
    let l = v[0].hypot(v[1]);
    [v[0] / l, v[1] / l]
}

/// The outward normal of a side at each of its nodes: the normalised sum of
/// the normals of the side's edges that end there. On a side that
/// discretises a curve by chords it is the normal of the curve at the node
/// to O(h²) (exactly on a circle cut into equal chords), where either
/// chord's own normal is off by half the turn between them; the end node of
/// an open side keeps its one edge's normal. Where every edge at a node has
/// the same normal to the bit (a straight side), the node keeps it
/// unchanged, so straight interfaces are built exactly as with edge
/// normals. The elements of a conforming B measure the gap of their node
/// pair along it (docs/method.md §6.2).
fn nodal_normals(edges: &HashMap<(usize, usize), [f64; 2]>) -> HashMap<usize, [f64; 2]> {
    let mut at: HashMap<usize, Vec<[f64; 2]>> = HashMap::new();
    for (&(p, q), &n) in edges {
        at.entry(p).or_default().push(n);
        at.entry(q).or_default().push(n);
    }
    at.into_iter()
        .map(|(v, mut ns)| {
            if ns.iter().all(|&n| n == ns[0]) {
                return (v, ns[0]);
            }
            // A fixed order of summation (the map's order is not).
            ns.sort_unstable_by(|m, n| m[0].total_cmp(&n[0]).then(m[1].total_cmp(&n[1])));
            (
                v,
                unit(
                    ns.iter()
                        .fold([0.0, 0.0], |s, n| [s[0] + n[0], s[1] + n[1]]),
                ),
            )
        })
        .collect()
}

/// Makes every element of a pair's B measure its gap along side a's
/// normal at the point it measures (docs/method.md §6.15, "One normal per
/// point"): at its apex when the apex is on side a; else at the apex's
/// projection on its edge (on side a), between the edge's nodal normals.
/// Each point of the interface is measured by two elements, one with its
/// edge on either side; on a curved strip their edges' own normals differ
/// by the turn between the chords, so the pair of them also resists the
/// tangential jump there, with κθ² (θ that angle), and an element reads
/// θ times the slip as an opening. Frictionless contact barely slides on
/// the scenes verified, but a slipping frictional element did, and the
/// edge of contact cycled (Cattaneo–Mindlin). A side's end node, which has
/// one edge, takes the normal extrapolated from its neighbour's (on a
/// circle cut into equal chords, exact); its edge's own normal is off by
/// half the turn. Where side a is straight the normals are its edges' and
/// nothing changes.
pub fn shared_normals(nodes: Nodes<'_>, a: &Side, elements: &mut [ContactElement]) {
    let mut edges_at: HashMap<usize, usize> = HashMap::new();
    for &(p, q) in a.edges.keys() {
        *edges_at.entry(p).or_default() += 1;
        *edges_at.entry(q).or_default() += 1;
    }
    let mut normals = a.node_normals.clone();
    for (&(p, q), &n) in &a.edges {
        for (end, next) in [(p, q), (q, p)] {
            if edges_at[&end] == 1 && edges_at[&next] == 2 && a.node_normals[&next] != n {
                let m = a.node_normals[&next];
                normals.insert(end, unit([2.0 * n[0] - m[0], 2.0 * n[1] - m[1]]));
            }
        }
    }
    let x = nodes.x;
    for el in elements.iter_mut() {
        if let Some(&n) = normals.get(&el.apex) {
            el.normal = n;
            continue;
        }
        let mut edge = el.nodes.iter().copied().filter(|&v| v != el.apex);
        let (Some(p), Some(q)) = (edge.next(), edge.next()) else {
            continue;
        };
        let (Some(&np), Some(&nq)) = (normals.get(&p), normals.get(&q)) else {
            continue;
        };
        el.normal = if np == nq {
            np
        } else {
            let e = [x[q][0] - x[p][0], x[q][1] - x[p][1]];
            let r = [x[el.apex][0] - x[p][0], x[el.apex][1] - x[p][1]];
            let s = ((r[0] * e[0] + r[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
            unit([(1.0 - s) * np[0] + s * nq[0], (1.0 - s) * np[1] + s * nq[1]])
        };
    }
}

fn side_of(mesh: &Mesh, tag: i32) -> Result<Side> {
    let mut body = None;
    let mut side = Side {
        tag,
        body: 0,
        index: None,
        nodes: HashSet::new(),
        edges: HashMap::new(),
        oriented: Vec::new(),
        node_normals: HashMap::new(),
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
            side.node_normals = nodal_normals(&side.edges);
            Ok(side)
        }
    }
}

/// The node coordinates B is built on and how its messages name nodes.
#[derive(Clone, Copy)]
pub struct Nodes<'a> {
    /// Coordinates of every node an element of B may use.
    pub x: &'a [[f64; 2]],
    /// The index base of messages.
    pub base: usize,
    /// The caller's own number of each node, where it is not its index
    /// plus `base` (a host code's node numbers); `None`: the index.
    pub ids: Option<&'a [i64]>,
}

impl<'a> Nodes<'a> {
    /// The nodes `x`, named by their index plus `base`.
    pub fn new(x: &'a [[f64; 2]], base: usize) -> Nodes<'a> {
        Nodes { x, base, ids: None }
    }

    /// The nodes of a mesh.
    pub fn of(mesh: &'a Mesh) -> Nodes<'a> {
        Nodes::new(mesh.nodes(), mesh.index_base())
    }

    /// Node `v` in messages: the caller's number of it (in the index base
    /// in use), never a position inside a side or a pair.
    pub fn name(&self, v: usize) -> i64 {
        match self.ids {
            Some(ids) => ids[v],
            None => (v + self.base) as i64,
        }
    }

    /// The corners of a triangle of these nodes.
    pub fn corners(&self, tri: &[usize; 3]) -> [[f64; 2]; 3] {
        [self.x[tri[0]], self.x[tri[1]], self.x[tri[2]]]
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

/// The arclength of each node along the polyline through `chain`.
fn arclengths(x: &[[f64; 2]], chain: &[usize]) -> Vec<f64> {
    let mut s = vec![0.0; chain.len()];
    for k in 1..chain.len() {
        s[k] = s[k - 1] + dist(x[chain[k - 1]], x[chain[k]]);
    }
    s
}

/// The abscissa of `p` along the polyline through `chain` (arclengths
/// `s`): that of its nearest point, the polyline extended linearly beyond
/// both ends.
fn abscissa(x: &[[f64; 2]], chain: &[usize], s: &[f64], p: [f64; 2]) -> f64 {
    let mut best = (f64::INFINITY, 0.0);
    for k in 0..chain.len() - 1 {
        let (p0, p1) = (x[chain[k]], x[chain[k + 1]]);
        let d = [p1[0] - p0[0], p1[1] - p0[1]];
        let len2 = d[0] * d[0] + d[1] * d[1];
        let mut t = ((p[0] - p0[0]) * d[0] + (p[1] - p0[1]) * d[1]) / len2;
        let (lo, hi) = (
            if k == 0 { f64::NEG_INFINITY } else { 0.0 },
            if k + 2 == chain.len() {
                f64::INFINITY
            } else {
                1.0
            },
        );
        t = t.clamp(lo, hi);
        let q = [p0[0] + t * d[0], p0[1] + t * d[1]];
        let dd = dist(p, q);
        if dd < best.0 {
            best = (dd, s[k] + t * len2.sqrt());
        }
    }
    best.1
}

/// Where two sides stop facing each other: the interval [lo, hi] of
/// abscissas along side a, and how far beyond each end a node must lie
/// for the edge across it to be cut (docs/method.md §6.11, "Sides that
/// end inside an edge").
struct Ends {
    lo: f64,
    hi: f64,
    tol_lo: f64,
    tol_hi: f64,
}

impl Ends {
    /// The ends of `al`'s chains windowed by `window` ([a0, a1, b0, b1],
    /// [`windows_and_ends`]) over its [lo, hi]. Round-off (`al.tol`) does
    /// not cut an end, nor does an offset that curvature alone makes: on
    /// curved sides a distance d apart (a gap or an overlap) the other
    /// side's end, projected on this side, lands off its end by up to d
    /// times the sides' turn there although the two ends face each other
    /// (the Lamé rings' quarter with 1e-2 of overlap was cut, and its
    /// pressure error went from 8.9e-5 to 1.3e-4 of p). The distance is the
    /// inner end node's from the other side; on straight sides the turn is
    /// zero and every offset beyond round-off cuts.
    fn new(x: &[[f64; 2]], al: &Aligned, window: [usize; 4]) -> Ends {
        let [a0, a1, b0, b1] = window;
        let (ca, cb) = (&al.chain_a[a0..=a1], &al.chain_b[b0..=b1]);
        let total = al.s_a[al.s_a.len() - 1];
        // Whether b's first/last node is the one inside (else a's).
        let inner = (al.s_b[b0] > 0.0, al.s_b[b1] < total);
        let (lo, hi, tol) = (al.lo, al.hi, al.tol);
        let slack = |inner: usize, other: &[usize], turns: [f64; 2]| {
            tol + distance_to_chain(x, x[inner], other) * turns[0].max(turns[1])
        };
        let (na, nb) = (ca.len(), cb.len());
        let tol_lo = match inner.0 {
            true => slack(cb[0], ca, [turn(x, ca), turn(x, cb)]),
            false => slack(ca[0], cb, [turn(x, ca), turn(x, cb)]),
        };
        let rev_a: Vec<usize> = ca[na.saturating_sub(3)..].iter().rev().copied().collect();
        let rev_b: Vec<usize> = cb[nb.saturating_sub(3)..].iter().rev().copied().collect();
        let tol_hi = match inner.1 {
            true => slack(cb[nb - 1], ca, [turn(x, &rev_a), turn(x, &rev_b)]),
            false => slack(ca[na - 1], cb, [turn(x, &rev_a), turn(x, &rev_b)]),
        };
        Ends {
            lo,
            hi,
            tol_lo,
            tol_hi,
        }
    }

    /// No ends: two closed loops, which face each other all round.
    fn none() -> Ends {
        Ends {
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
            tol_lo: 0.0,
            tol_hi: 0.0,
        }
    }

    /// Whether a chain of abscissas `s` starts before lo and ends beyond hi.
    fn beyond(&self, s: &[f64]) -> (bool, bool) {
        (
            s[0] < self.lo - self.tol_lo,
            s[s.len() - 1] > self.hi + self.tol_hi,
        )
    }

    /// The part of the edge over [s0, s1] that faces the other side, as a
    /// fraction of the edge (1: all of it).
    fn share(&self, s0: f64, s1: f64) -> f64 {
        let (c0, c1) = (
            if s0 < self.lo - self.tol_lo {
                self.lo
            } else {
                s0
            },
            if s1 > self.hi + self.tol_hi {
                self.hi
            } else {
                s1
            },
        );
        if c0 == s0 && c1 == s1 {
            1.0
        } else {
            ((c1 - c0) / (s1 - s0)).clamp(0.0, 1.0)
        }
    }
}

/// The strip between `al`'s chains windowed by `window` ([a0, a1, b0,
/// b1]; nodes and abscissas along side a) with the ends `ends`: its
/// triangles (an edge of one side, an apex on the other), each edge's apex
/// the node of the other side nearest to its midpoint but at a cut end,
/// and the share of each triangle's edge that faces the other side.
fn walk_strip(al: &Aligned, window: [usize; 4], ends: &Ends) -> (Vec<[usize; 3]>, Vec<f64>) {
    let [a0, a1, b0, b1] = window;
    let (ca, sa) = (&al.chain_a[a0..=a1], &al.s_a[a0..=a1]);
    let (cb, sb) = (&al.chain_b[b0..=b1], &al.s_b[b0..=b1]);
    let ((a_before, a_after), (b_before, b_after)) = (ends.beyond(sa), ends.beyond(sb));
    let mut tris = Vec::with_capacity(ca.len() + cb.len());
    let mut fractions = Vec::with_capacity(ca.len() + cb.len());
    let (mut i, mut j) = (0, 0);
    while i + 1 < ca.len() || j + 1 < cb.len() {
        let advance_a = if i + 1 == ca.len() {
            false
        } else if j + 1 == cb.len() {
            true
        } else if i == 0 && a_before {
            // An edge across the other side's start takes that start as
            // its apex, and one across its end that end: every apex then
            // lies where the sides face each other, and the strip is that
            // of the clipped sides, which the patch test holds for
            // (docs/method.md §6.11, "Sides that end inside an edge").
            true
        } else if (j == 0 && b_before) || (i + 2 == ca.len() && a_after) {
            false
        } else if j + 2 == cb.len() && b_after {
            true
        } else {
            // The next edge whose midpoint comes first: each edge's apex is
            // then the node of the other side nearest to its midpoint
            // (docs/method.md §6.11).
            sa[i] + sa[i + 1] <= sb[j] + sb[j + 1]
        };
        if advance_a {
            tris.push([ca[i], ca[i + 1], cb[j]]);
            fractions.push(ends.share(sa[i], sa[i + 1]));
            i += 1;
        } else {
            tris.push([ca[i], cb[j + 1], cb[j]]);
            fractions.push(ends.share(sb[j], sb[j + 1]));
            j += 1;
        }
    }
    (tris, fractions)
}

/// The sine of the turn of a polyline at its second node (0 with fewer
/// than three nodes): how much it bends at its end.
fn turn(x: &[[f64; 2]], chain: &[usize]) -> f64 {
    let [p, q, r] = match chain {
        [p, q, r, ..] => [x[*p], x[*q], x[*r]],
        _ => return 0.0,
    };
    let (u, v) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    let cross = u[0] * v[1] - u[1] * v[0];
    (cross / (dist(p, q) * dist(q, r))).abs()
}

/// The distance from `p` to the polyline through `chain`'s nodes.
fn distance_to_chain(x: &[[f64; 2]], p: [f64; 2], chain: &[usize]) -> f64 {
    chain
        .windows(2)
        .map(|e| {
            let (q0, q1) = (x[e[0]], x[e[1]]);
            let d = [q1[0] - q0[0], q1[1] - q0[1]];
            let len2 = d[0] * d[0] + d[1] * d[1];
            let t = match len2 > 0.0 {
                true => (((p[0] - q0[0]) * d[0] + (p[1] - q0[1]) * d[1]) / len2).clamp(0.0, 1.0),
                false => 0.0,
            };
            dist(p, [q0[0] + t * d[0], q0[1] + t * d[1]])
        })
        .fold(f64::INFINITY, f64::min)
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
    let (a, b) = (side_of(mesh, tag_a)?, side_of(mesh, tag_b)?);
    conforming(Nodes::of(mesh), pair, &a, &b).map_err(|e| {
        Error::new(
            e.status(),
            format!(
                "{}; non-matching sides take the strip triangulation of B (docs/method.md \
                 §6.11) or a handed-over contact mesh",
                e.message()
            ),
        )
    })
}

/// [`build_conforming`] on two sides.
pub fn conforming(
    nodes: Nodes<'_>,
    pair: usize,
    a: &Side,
    b: &Side,
) -> Result<Vec<ContactElement>> {
    let partner_of_a = match_nodes(nodes, a, b)?;
    quads(nodes, pair, a, b, &partner_of_a)
}

/// The lengths a match across the interface is judged by.
struct Scales {
    /// node of either side -> the length of its shortest edge on its side
    local_h: HashMap<usize, f64>,
    /// node of side a -> the sum of the outward normals of its edges (not
    /// of unit length)
    normal_a: HashMap<usize, [f64; 2]>,
}

impl Scales {
    /// The scales at the nodes of sides `a` and `b`.
    fn of(x: &[[f64; 2]], a: &Side, b: &Side) -> Scales {
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
        Scales { local_h, normal_a }
    }

    /// For node `vb` of side b (local length `hb`) at distance `d` from
    /// node `va` of side a: the local length of the pair (the smaller) and
    /// the offset's part along the interface (across the normal at `va`).
    /// An initial gap is the normal part, which may be up to half an edge;
    /// the part along is what says the nodes do not face each other.
    fn along(&self, x: &[[f64; 2]], hb: f64, vb: usize, va: usize, d: f64) -> (f64, f64) {
        let h = hb.min(self.local_h[&va]);
        let n = self.normal_a[&va];
        // The sum of the edge normals only gives a direction; its length is
        // kept away from zero for a side folding back on itself, whose
        // normals cancel at the fold.
        let nn = n[0].hypot(n[1]).max(f64::MIN_POSITIVE);
        let off = [x[vb][0] - x[va][0], x[vb][1] - x[va][1]];
        let normal_part = (off[0] * n[0] + off[1] * n[1]) / nn;
        (h, (d * d - normal_part * normal_part).max(0.0).sqrt())
    }
}

/// The nodes of side a sorted along the axis (x or y) over which the side
/// extends further, so that the candidates for a node of side b, within
/// half an edge of it, are found by bisection rather than among every node
/// of side a (n² on a long interface).
struct AxisOrder {
    /// 0 for x, 1 for y
    axis: usize,
    /// the nodes of side a by their coordinate along `axis`, then by index
    /// (so that the order does not depend on the side's set)
    nodes: Vec<usize>,
    /// their coordinates along `axis`
    keys: Vec<f64>,
}

impl AxisOrder {
    /// The nodes of side `a` in order.
    fn of(x: &[[f64; 2]], a: &Side) -> AxisOrder {
        let mut nodes: Vec<usize> = a.nodes.iter().copied().collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for &v in &nodes {
            for k in 0..2 {
                lo[k] = lo[k].min(x[v][k]);
                hi[k] = hi[k].max(x[v][k]);
            }
        }
        let axis = usize::from(hi[1] - lo[1] > hi[0] - lo[0]);
        nodes.sort_unstable_by(|&p, &q| x[p][axis].total_cmp(&x[q][axis]).then(p.cmp(&q)));
        let keys: Vec<f64> = nodes.iter().map(|&v| x[v][axis]).collect();
        AxisOrder { axis, nodes, keys }
    }

    /// The node nearest to node `vb` and its distance, among those within
    /// `radius` of it along the axis (of equally near ones, the first in
    /// the order); `None` when there are none.
    fn nearest(&self, x: &[[f64; 2]], vb: usize, radius: f64) -> Option<(f64, usize)> {
        let key = x[vb][self.axis];
        let start = self.keys.partition_point(|&k| k < key - radius);
        let mut best: Option<(f64, usize)> = None;
        for (idx, &va) in self.nodes.iter().enumerate().skip(start) {
            if self.keys[idx] > key + radius {
                break;
            }
            let d = dist(x[va], x[vb]);
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, va));
            }
        }
        best
    }
}

/// The node of side b matched to each node of side a, by the criteria of
/// [`build_conforming`]. Refuses, naming the node, a node of either side
/// left without a match, or a node of side a matched twice.
fn match_nodes(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<HashMap<usize, usize>> {
    let (name_a, name_b) = (a.name(), b.name());
    let x = nodes.x;
    let scales = Scales::of(x, a, b);
    let order = AxisOrder::of(x, a);
    let mut partner_of_a: HashMap<usize, usize> = HashMap::new();
    // In index order, so that which node an error names does not depend on
    // the order of the side's set.
    let mut b_nodes: Vec<usize> = b.nodes.iter().copied().collect();
    b_nodes.sort_unstable();
    for &vb in &b_nodes {
        let hb = scales.local_h[&vb];
        let best = order.nearest(x, vb, 0.5 * hb);
        let matched = best.filter(|&(d, va)| {
            let (h, tangential) = scales.along(x, hb, vb, va, d);
            d <= 0.5 * h && tangential <= TANGENTIAL_TOL * h
        });
        let Some((_, va)) = matched else {
            return Err(unmatched(nodes, &scales, a, b, vb, best));
        };
        if let Some(prev) = partner_of_a.insert(va, vb) {
            return Err(Error::contact(format!(
                "nodes {} and {} ({name_b}) both match node {} ({name_a})",
                nodes.name(prev),
                nodes.name(vb),
                nodes.name(va)
            )));
        }
    }
    // Every node of side b has a partner of its own; a node of side a left
    // over is one the other side lacks.
    if let Some(&va) = order.nodes.iter().find(|v| !partner_of_a.contains_key(v)) {
        return Err(Error::contact(format!(
            "node {} (contact {name_a}) has no matching node on {name_b} \
             (the interfaces differ in extent or are non-conforming)",
            nodes.name(va)
        )));
    }
    Ok(partner_of_a)
}

/// The error for node `vb` of side b, which has no match on side a: it
/// names the nearest candidate (`best`) with how far it is from being a
/// match, so that a user can tell a near miss (a tolerance) from sides that
/// do not conform, and points to what takes non-matching sides.
fn unmatched(
    nodes: Nodes<'_>,
    scales: &Scales,
    a: &Side,
    b: &Side,
    vb: usize,
    best: Option<(f64, usize)>,
) -> Error {
    let (name_a, name_b) = (a.name(), b.name());
    let x = nodes.x;
    let hb = scales.local_h[&vb];
    let radius = 0.5 * hb;
    let hint = match best {
        Some((d, va)) => {
            let (h, tangential) = scales.along(x, hb, vb, va, d);
            format!(
                "nearest node {} is {d:.3e} away, {tangential:.3e} along the interface \
                 (a match: at most {:.3e} away, {:.3e} along)",
                nodes.name(va),
                0.5 * h,
                TANGENTIAL_TOL * h
            )
        }
        None => format!("no node of {name_a} within half an edge ({radius:.3e})"),
    };
    Error::contact(format!(
        "node {} (contact {name_b}) has no matching node on {name_a}: {hint}",
        nodes.name(vb)
    ))
}

/// The two triangles of the flat quad between each edge of side a and the
/// nodes of side b matched to its ends (`partner_of_a`, from
/// [`match_nodes`]). Refuses an edge whose partners are not an edge of
/// side b (the sides match node by node but not edge by edge), naming it.
fn quads(
    nodes: Nodes<'_>,
    pair: usize,
    a: &Side,
    b: &Side,
    partner_of_a: &HashMap<usize, usize>,
) -> Result<Vec<ContactElement>> {
    let x = nodes.x;
    let mut elements = Vec::with_capacity(2 * a.oriented.len());
    for &[a1, b1] in &a.oriented {
        let (a2, b2) = (partner_of_a[&a1], partner_of_a[&b1]);
        if !b.edges.contains_key(&(a2.min(b2), a2.max(b2))) {
            return Err(Error::contact(format!(
                "edge ({}, {}) of {} faces nodes {} and {} that are not an edge of {}",
                nodes.name(a1),
                nodes.name(b1),
                a.name(),
                nodes.name(a2),
                nodes.name(b2),
                b.name()
            )));
        }
        // Each triangle is a spring on one node pair, (b1, b2) or (a1, a2):
        // it measures the pair's gap along side a's nodal normal there, not
        // along the chord's normal, which on a curved interface is tilted
        // by half the chords' turn and reads tangential slip as an opening
        // (docs/method.md §6.2; the same on a straight interface).
        for (tri, edge_len, apex, normal) in [
            ([a1, b1, b2], dist(x[a1], x[b1]), b2, a.node_normals[&b1]),
            ([a1, b2, a2], dist(x[a2], x[b2]), a1, a.node_normals[&a1]),
        ] {
            let geo = TriGeometry::new(&nodes.corners(&tri));
            elements.push(ContactElement {
                nodes: tri,
                normal,
                j0: geo.j,
                h: geo.h,
                edge_length: edge_len,
                facing: edge_len,
                pair,
                apex,
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
    let (a, b) = (side_of(mesh, tag_a)?, side_of(mesh, tag_b)?);
    checked_triangles(Nodes::of(mesh), pair, &a, &b, triangles)
}

/// [`check_user_mesh`] on two sides: each triangle checked in turn
/// (`check_corners`, `check_once`) and made an element of B
/// (`user_element`). Gives the elements and how many were turned.
pub fn checked_triangles(
    nodes_of: Nodes<'_>,
    pair: usize,
    a: &Side,
    b: &Side,
    triangles: &[[usize; 3]],
) -> Result<(Vec<ContactElement>, usize)> {
    let mut out = reserved(triangles.len(), "the contact mesh")?;
    // Each triangle's nodes, sorted -> its index: a triangle given twice
    // would be two elements of B on one spot, doubling its contact.
    let mut seen: HashMap<[usize; 3], usize> = HashMap::new();
    seen.try_reserve(triangles.len())
        .map_err(|_| out_of_memory::<([usize; 3], usize)>(triangles.len(), "the contact mesh"))?;
    let mut flipped = 0;
    for (t, tri) in triangles.iter().enumerate() {
        let name = format!("contact triangle {}", t + nodes_of.base);
        check_corners(nodes_of, tri, &name)?;
        check_once(nodes_of, &mut seen, t, tri)?;
        let (element, turned) = user_element(nodes_of, [a, b], tri, &name, pair)?;
        flipped += usize::from(turned);
        out.push(element);
    }
    Ok((out, flipped))
}

/// Refuses a user's triangle `tri` (named `name`) with a node out of range
/// or repeated.
fn check_corners(nodes_of: Nodes<'_>, tri: &[usize; 3], name: &str) -> Result<()> {
    if let Some(&v) = tri.iter().find(|&&v| v >= nodes_of.x.len()) {
        return Err(Error::contact(format!(
            "{name}: node index {} is out of range",
            v + nodes_of.base
        )));
    }
    if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
        return Err(Error::contact(format!("{name}: a node is repeated")));
    }
    Ok(())
}

/// Refuses user's triangle `t` (nodes `tri`) when its nodes were given
/// before, naming both; `seen` maps each triangle's sorted nodes to it.
fn check_once(
    nodes_of: Nodes<'_>,
    seen: &mut HashMap<[usize; 3], usize>,
    t: usize,
    tri: &[usize; 3],
) -> Result<()> {
    let mut key = *tri;
    key.sort_unstable();
    match seen.insert(key, t) {
        None => Ok(()),
        Some(first) => Err(Error::contact(format!(
            "contact triangle {} repeats contact triangle {} (nodes {}, {}, {}): each element \
             of B is given once",
            t + nodes_of.base,
            first + nodes_of.base,
            nodes_of.name(tri[0]),
            nodes_of.name(tri[1]),
            nodes_of.name(tri[2])
        ))),
    }
}

/// How a user's triangle bridges the two sides: which of its nodes are on
/// side a, whether its interface edge (the two nodes on one side) is on
/// side a, that edge, and its normal from a to b.
struct Bridge {
    on_a: [bool; 3],
    edge_on_a: bool,
    edge: (usize, usize),
    normal: [f64; 2],
}

/// The bridge of user's triangle `tri` (named `name`) between sides
/// `[a, b]`, refused when a node is on neither side, all are on one, or
/// its two nodes on one side are not an edge of it.
fn bridge(nodes_of: Nodes<'_>, [a, b]: [&Side; 2], tri: &[usize; 3], name: &str) -> Result<Bridge> {
    let on_a = tri.map(|v| a.nodes.contains(&v));
    if let Some(k) = (0..3).find(|&k| !on_a[k] && !b.nodes.contains(&tri[k])) {
        return Err(Error::contact(format!(
            "{name}: node {} is on neither interface ({}, {})",
            nodes_of.name(tri[k]),
            a.name(),
            b.name()
        )));
    }
    let count_a = on_a.iter().filter(|&&s| s).count();
    if count_a == 0 || count_a == 3 {
        return Err(Error::contact(format!(
            "{name}: all its nodes are on one interface; it must bridge both"
        )));
    }
    // The two nodes on the same side form its interface edge.
    let edge_on_a = count_a == 2;
    let pairs: Vec<usize> = (0..3).filter(|&k| on_a[k] == edge_on_a).collect();
    let (p, q) = (tri[pairs[0]], tri[pairs[1]]);
    let key = (p.min(q), p.max(q));
    let normal = match edge_on_a {
        true => a.edges.get(&key).copied(),
        false => b.edges.get(&key).map(|n| [-n[0], -n[1]]),
    };
    let Some(normal) = normal else {
        return Err(Error::contact(format!(
            "{name}: nodes {} and {} are not an edge of interface {}",
            nodes_of.name(p),
            nodes_of.name(q),
            if edge_on_a { a.name() } else { b.name() }
        )));
    };
    Ok(Bridge {
        on_a,
        edge_on_a,
        edge: (p, q),
        normal,
    })
}

/// User's triangle `tri` (named `name`) of pair `pair` as an element of B
/// between sides `[a, b]`, its nodes ordered so that J grows as the gap
/// opens; and whether they were turned for that. Refused where J does
/// not depend on the opening.
fn user_element(
    nodes_of: Nodes<'_>,
    sides: [&Side; 2],
    tri: &[usize; 3],
    name: &str,
    pair: usize,
) -> Result<(ContactElement, bool)> {
    let Bridge {
        on_a,
        edge_on_a,
        edge: (p, q),
        normal,
    } = bridge(nodes_of, sides, tri, name)?;
    let mut nodes = *tri;
    let mut geo = TriGeometry::new(&nodes_of.corners(&nodes));
    // dJ when the side-b nodes move along +n (the gap opens).
    let sens: f64 = (0..3)
        .filter(|&k| !on_a[k])
        .map(|k| geo.g[k][0] * normal[0] + geo.g[k][1] * normal[1])
        .sum();
    // J is an area and the opening a length, so `sens` is a length: the
    // interface edge's length times the cosine between the normal and the
    // edge's normal. Compared with the longest edge h it gives a pure
    // number, and the test is the same at every length scale (against h²,
    // it refused every non-matching pair beyond ~1e12 length units and let
    // through near-degenerate ones at 1e-9).
    if sens.abs() <= 1e-12 * geo.h {
        return Err(Error::contact(format!(
            "{name}: its Jacobian does not change when the gap opens (degenerate across the interface)"
        )));
    }
    let turned = sens < 0.0;
    if turned {
        nodes.swap(1, 2);
        geo = TriGeometry::new(&nodes_of.corners(&nodes));
    }
    let apex = tri[(0..3)
        .find(|&k| on_a[k] != edge_on_a)
        .expect("one node apart")];
    let x = nodes_of.x;
    let element = ContactElement {
        nodes,
        normal,
        j0: geo.j,
        h: geo.h,
        edge_length: dist(x[p], x[q]),
        // Whole: a user's B says nothing of where the sides end
        // ([`nonconforming`] clips its own).
        facing: dist(x[p], x[q]),
        pair,
        apex,
    };
    Ok((element, turned))
}

/// Builds B for a pair whose interface nodes do not match (docs/method.md §5,
/// §6.11): both interfaces are chained into polylines running the same way,
/// every node gets the arclength parameter of its projection on the first
/// polyline (extended beyond its ends), and the strip between them is
/// triangulated by advancing along whichever polyline's next edge has the
/// nearer midpoint, over the range where the two interfaces face each other
/// (plus, where a side goes on beyond the other's end, its edge across that
/// end): every edge's apex is the node of the other side nearest to its
/// midpoint, but an edge across the other side's end, whose apex is that
/// end. Such an edge faces the other side over part of its length only,
/// which its element's [`ContactElement::facing`] holds. Two closed loops
/// (a ring in a bore) face each other all round: the strip is walked over
/// one turn of each and closes on its first rung. Each triangle has an edge
/// on one interface and a node on the other; orientation and normals are
/// set as for a user mesh.
pub fn build_nonconforming(
    mesh: &Mesh,
    pair: usize,
    tag_a: i32,
    tag_b: i32,
) -> Result<Vec<ContactElement>> {
    let (a, b) = (side_of(mesh, tag_a)?, side_of(mesh, tag_b)?);
    nonconforming(Nodes::of(mesh), pair, &a, &b)
}

/// [`build_nonconforming`] on two sides.
pub fn nonconforming(
    nodes: Nodes<'_>,
    pair: usize,
    a: &Side,
    b: &Side,
) -> Result<Vec<ContactElement>> {
    let al = alignment(nodes, a, b)?;
    // Two closed loops face each other all round: the strip is walked over
    // one turn of each, its last rung the first, and no edge is cut.
    let (w, ends) = match al.turn {
        Some(w) => (w, Ends::none()),
        None => windows_and_ends(nodes.x, &al),
    };
    let (tris, fractions) = walk_strip(&al, w, &ends);
    let mut elements = checked_triangles(nodes, pair, a, b, &tris)?.0;
    for (el, f) in elements.iter_mut().zip(fractions) {
        if f < 1.0 {
            el.facing = el.edge_length * f;
        }
    }
    Ok(elements)
}

/// Each of `al`'s chains' window — the part over [lo, hi] plus, where the
/// chain goes on beyond an end, the node beyond it (the edge across the
/// end faces the other side over part of its length) — as [a0, a1, b0,
/// b1], and the [`Ends`] of the windowed chains.
fn windows_and_ends(x: &[[f64; 2]], al: &Aligned) -> ([usize; 4], Ends) {
    let (lo, hi, tol) = (al.lo, al.hi, al.tol);
    let window = |s: &[f64]| -> (usize, usize) {
        let first = s.iter().rposition(|&v| v <= lo + tol).unwrap_or(0);
        let last = s.iter().position(|&v| v >= hi - tol).unwrap_or(s.len() - 1);
        (first, last.max(first + 1).min(s.len() - 1))
    };
    let (a0, a1) = window(&al.s_a);
    let (b0, b1) = window(&al.s_b);
    let w = [a0, a1, b0, b1];
    (w, Ends::new(x, al, w))
}

impl Aligned {
    /// How far beyond lo and beyond hi a node must lie for the edge
    /// across that end to face the other side in part only: round-off,
    /// plus on curved sides the offset curvature alone makes between two
    /// ends that face each other (the strip's own rule, [`Ends`];
    /// docs/method.md §6.11, "Sides that end inside an edge").
    pub(crate) fn end_slack(&self, x: &[[f64; 2]]) -> (f64, f64) {
        let (_, ends) = windows_and_ends(x, self);
        (ends.tol_lo, ends.tol_hi)
    }
}

/// Two facing sides chained and laid along side a: a's nodes with their
/// arclengths, b's (turned to run the same way) with the abscissas of
/// their projections on a (extended beyond its ends), and the interval
/// [lo, hi] of abscissas over which the sides face each other. `tol`: how
/// close to lo or hi a node counts as at it (1e-9 of the shortest edge,
/// the round-off of the projection).
pub(crate) struct Aligned {
    /// Side a's nodes in order.
    pub chain_a: Vec<usize>,
    /// Their arclengths along a.
    pub s_a: Vec<f64>,
    /// Side b's nodes, running the way a's do.
    pub chain_b: Vec<usize>,
    /// Their abscissas along a (non-decreasing).
    pub s_b: Vec<f64>,
    /// Where the sides start facing each other.
    pub lo: f64,
    /// Where they stop.
    pub hi: f64,
    /// Round-off of an abscissa.
    pub tol: f64,
    /// For two closed loops ([`alignment`]): the index ranges [a0, a1, b0,
    /// b1] of one turn of each chain, which carries two nodes of the turn
    /// before and after it (their abscissas ∓ the loop's length), so that
    /// a node's support reaches across the seam. `None` for open chains.
    pub turn: Option<[usize; 4]>,
}

/// [`Aligned`] of two sides; refuses sides that branch, close, fold back
/// along each other or do not face each other.
pub(crate) fn aligned(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<Aligned> {
    let (name_a, name_b) = (a.name(), b.name());
    let x = nodes.x;
    let chain_a = chain(nodes, a)?;
    let mut chain_b = chain(nodes, b)?;
    // Each chain has its body on the right; facing each other they run in
    // opposite directions: turn b around.
    chain_b.reverse();
    // Arclength along a, and each node of b's abscissa along it.
    let s_a = arclengths(x, &chain_a);
    let total = s_a[s_a.len() - 1];
    let s_b: Vec<f64> = chain_b
        .iter()
        .map(|&v| abscissa(x, &chain_a, &s_a, x[v]))
        .collect();
    if let Some(k) = (1..s_b.len()).find(|&k| s_b[k] < s_b[k - 1]) {
        return Err(Error::contact(format!(
            "interface {name_b} folds back along interface {name_a} at node {}: the two interfaces must face each other",
            nodes.name(chain_b[k])
        )));
    }
    let (lo, hi) = (s_b[0].max(0.0), s_b[s_b.len() - 1].min(total));
    if hi.is_nan() || hi <= lo {
        return Err(Error::contact(format!(
            "interfaces {name_a} and {name_b} do not face each other (no overlap along the interface)"
        )));
    }
    // Nodes within `tol` of an end of [lo, hi] are at it: the two sides'
    // ends meet there up to the round-off of the projection, and an edge
    // clipped by round-off would lose the bitwise equality with the
    // unclipped strip (docs/method.md §6.11). 1e-9 of the shortest edge,
    // as the overlap `contact::pairing` asks of two facing sides.
    let shortest = chain_a
        .windows(2)
        .chain(chain_b.windows(2))
        .map(|e| dist(x[e[0]], x[e[1]]))
        .fold(f64::INFINITY, f64::min);
    Ok(Aligned {
        chain_a,
        s_a,
        chain_b,
        s_b,
        lo,
        hi,
        tol: 1e-9 * shortest,
        turn: None,
    })
}

/// The edges of a side as a closed loop [v0, …, v_{n−1}, v0] from its
/// smallest node, in their orientation; `None` when the side is not one
/// loop.
fn closed_loop(side: &Side) -> Option<Vec<usize>> {
    let mut next: HashMap<usize, usize> = HashMap::new();
    for &[p, q] in &side.oriented {
        if next.insert(p, q).is_some() {
            return None;
        }
    }
    let start = *next.keys().min()?;
    let mut out = vec![start];
    let mut v = start;
    while out.len() <= side.oriented.len() {
        v = *next.get(&v)?;
        out.push(v);
        if v == start {
            break;
        }
    }
    (out.len() == side.oriented.len() + 1 && v == start).then_some(out)
}

/// [`aligned`], also for two sides that are closed loops (a ring in a
/// bore, a shaft in a hole): a's loop from its smallest node, b's turned
/// round and started at the node whose projection on a comes first, each
/// laid along a's arclength and carrying two nodes of wrap-around at
/// either end ([`Aligned::turn`]); [lo, hi] is a's turn.
pub(crate) fn alignment(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<Aligned> {
    let (Some(loop_a), Some(loop_b)) = (closed_loop(a), closed_loop(b)) else {
        return aligned(nodes, a, b);
    };
    let x = nodes.x;
    let s_loop = arclengths(x, &loop_a);
    let total = s_loop[s_loop.len() - 1];
    let mut loop_b = loop_b;
    // Facing each other, the loops run opposite ways.
    loop_b.reverse();
    let nb = loop_b.len() - 1;
    let on_a: Vec<f64> = loop_b[..nb]
        .iter()
        .map(|&v| loop_abscissa(x, &loop_a, &s_loop, x[v]))
        .collect();
    let first = (0..nb)
        .min_by(|&i, &j| on_a[i].total_cmp(&on_a[j]))
        .unwrap_or(0);
    let (mut chain_b, mut s_b) = (Vec::with_capacity(nb + 1), Vec::with_capacity(nb + 1));
    let mut turns = 0.0;
    for t in 0..=nb {
        let k = (first + t) % nb;
        let mut sv = on_a[k] + turns;
        if s_b
            .last()
            .is_some_and(|&prev: &f64| sv < prev - 0.5 * total)
        {
            turns += total;
            sv += total;
        }
        chain_b.push(loop_b[k]);
        s_b.push(sv);
    }
    if let Some(k) = (1..s_b.len()).find(|&k| s_b[k] < s_b[k - 1]) {
        return Err(Error::contact(format!(
            "interface {} folds back along interface {} at node {}: the two interfaces must \
             face each other",
            b.name(),
            a.name(),
            nodes.name(chain_b[k])
        )));
    }
    let (chain_a, s_a) = wrapped(&loop_a, &s_loop, total);
    let (chain_b, s_b) = wrapped(&chain_b, &s_b, total);
    let shortest = chain_a
        .windows(2)
        .chain(chain_b.windows(2))
        .map(|e| dist(x[e[0]], x[e[1]]))
        .fold(f64::INFINITY, f64::min);
    let (na, nb) = (chain_a.len(), chain_b.len());
    Ok(Aligned {
        lo: s_a[WRAP],
        hi: s_a[na - 1 - WRAP],
        chain_a,
        s_a,
        chain_b,
        s_b,
        tol: 1e-9 * shortest,
        turn: Some([WRAP, na - 1 - WRAP, WRAP, nb - 1 - WRAP]),
    })
}

/// Whether the nodes of sides `a` and `b` face each other across the
/// interface, node for node, where the sides are close (within half an
/// edge, where contact can form): [`conforming`] pairs them, or, the sides
/// laid along each other by `aligned`, every node of either side within
/// half its edge of the other side sits at the abscissa of a node of the
/// other side that is close too, within `FACING_TOL` of the local edge.
/// Looser than [`conforming`]'s test, which needs every node paired (a
/// cylinder over a block, meshed alike near the contact, differs where
/// the gap is wide) with its offset normal to the interface (the end
/// nodes of two concentric arcs read a radial offset δ as δ Δθ/2 along the
/// interface: the end's normal is its chord's).
pub fn matching(nodes: Nodes<'_>, a: &Side, b: &Side) -> bool {
    if conforming(nodes, 0, a, b).is_ok() {
        return true;
    }
    let Ok(al) = aligned(nodes, a, b) else {
        return false;
    };
    let x = nodes.x;
    // (abscissa, local edge) of a chain's nodes within half an edge of the
    // other chain.
    let close = |(chain, s): (&[usize], &[f64]), other: &[usize]| -> Vec<(f64, f64)> {
        (0..chain.len())
            .map(|k| {
                let before = (k > 0).then(|| dist(x[chain[k - 1]], x[chain[k]]));
                let after = (k + 1 < chain.len()).then(|| dist(x[chain[k]], x[chain[k + 1]]));
                let h = before
                    .into_iter()
                    .chain(after)
                    .fold(f64::INFINITY, f64::min);
                (k, h)
            })
            .filter(|&(k, h)| distance_to_chain(x, x[chain[k]], other) <= 0.5 * h)
            .map(|(k, h)| (s[k], h))
            .collect()
    };
    let on_a = close((&al.chain_a, &al.s_a), &al.chain_b);
    let on_b = close((&al.chain_b, &al.s_b), &al.chain_a);
    !on_a.is_empty()
        && on_a.len() == on_b.len()
        && on_a
            .iter()
            .zip(&on_b)
            .all(|(&(sa, ha), &(sb, hb))| (sa - sb).abs() <= FACING_TOL * ha.min(hb))
}

/// Whether side `side` is straight: one chain whose nodes all lie on the
/// line through its ends, within round-off of its length.
pub fn straight(nodes: Nodes<'_>, side: &Side) -> bool {
    let Ok(chain) = chain(nodes, side) else {
        return false;
    };
    let x = nodes.x;
    let (p, q) = (x[chain[0]], x[chain[chain.len() - 1]]);
    let d = [q[0] - p[0], q[1] - p[1]];
    let length = d[0].hypot(d[1]);
    length > 0.0
        && chain.iter().all(|&v| {
            let r = [x[v][0] - p[0], x[v][1] - p[1]];
            (r[0] * d[1] - r[1] * d[0]).abs() <= STRAIGHT_TOL * length * length
        })
}

/// How far from the line through its ends, relative to its length, a
/// straight side's nodes may lie ([`straight`]): round-off of coordinates.
const STRAIGHT_TOL: f64 = 1e-9;

/// How far along the interface, relative to the local edge, two nodes may
/// be and still face each other ([`matching`]): above the offset two
/// concentric arcs' end nodes read (their gap times half an edge's turn;
/// 5e-4 for the Lamé rings at δ = b/1000), below any non-matching mesh's
/// (a third of an edge at 2:3).
const FACING_TOL: f64 = 1e-2;

/// The nodes of the turns before and after that a closed loop's chain
/// carries at either end ([`alignment`]): enough for a slave node's support
/// and the master edge it faces to reach across the seam.
const WRAP: usize = 2;

/// A closed loop's chain [v0, …, v0] with abscissas `s` (one turn of
/// length `total`) extended by [`WRAP`] nodes of the turns before and
/// after.
fn wrapped(chain: &[usize], s: &[f64], total: f64) -> (Vec<usize>, Vec<f64>) {
    let n = chain.len() - 1;
    let mut c: Vec<usize> = (n - WRAP..n).map(|k| chain[k]).collect();
    let mut t: Vec<f64> = (n - WRAP..n).map(|k| s[k] - total).collect();
    c.extend_from_slice(chain);
    t.extend_from_slice(s);
    c.extend((1..=WRAP).map(|k| chain[k]));
    t.extend((1..=WRAP).map(|k| s[k] + total));
    (c, t)
}

/// The abscissa on a closed loop (`chain` with arclengths `s`) of its point
/// nearest to `p`, in [0, the loop's length).
fn loop_abscissa(x: &[[f64; 2]], chain: &[usize], s: &[f64], p: [f64; 2]) -> f64 {
    let total = s[s.len() - 1];
    let mut best = (f64::INFINITY, 0.0);
    for k in 0..chain.len() - 1 {
        let (p0, p1) = (x[chain[k]], x[chain[k + 1]]);
        let d = [p1[0] - p0[0], p1[1] - p0[1]];
        let len2 = d[0] * d[0] + d[1] * d[1];
        let t = (((p[0] - p0[0]) * d[0] + (p[1] - p0[1]) * d[1]) / len2).clamp(0.0, 1.0);
        let foot = [p0[0] + t * d[0], p0[1] + t * d[1]];
        let dd = dist(p, foot);
        if dd < best.0 {
            best = (dd, (s[k] + t * len2.sqrt()).rem_euclid(total));
        }
    }
    best.1
}

/// The edges of one side chained into a single polyline, in their
/// orientation (body on the right).
fn chain(nodes: Nodes<'_>, side: &Side) -> Result<Vec<usize>> {
    let name = side.name();
    let mut next: HashMap<usize, usize> = HashMap::new();
    let mut has_prev: HashSet<usize> = HashSet::new();
    for &[p, q] in &side.oriented {
        if next.insert(p, q).is_some() {
            return Err(Error::contact(format!(
                "interface {name} branches at node {}: it must be a single chain of edges",
                nodes.name(p)
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
                "interface {name} is a closed loop: open it into a chain of edges"
            )));
        }
        _ => {
            return Err(Error::contact(format!(
                "interface {name} has {} separate pieces: use one contact pair per piece",
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
            "interface {name} is not a single chain of edges (near node {})",
            nodes.name(v)
        )));
    }
    Ok(out)
}

/// B of every pair in turn (pair i's elements carry `pair = i`), each
/// as [`pair_strip`] makes it.
pub fn build_all(mesh: &Mesh, pairs: &[ContactPair]) -> Result<Vec<ContactElement>> {
    let mut all = Vec::new();
    for (i, p) in pairs.iter().enumerate() {
        all.append(&mut pair_strip(mesh, i, p)?);
    }
    Ok(all)
}

/// B of pair `i`: built, or the user's mesh checked, its elements
/// measuring along [`shared_normals`] — one normal per point of the
/// interface for every pair, frictional or not, so that a tangential slip
/// is never read as an opening and a frictionless interface transmits no
/// tangential traction (docs/method.md §6.15, "One normal per point").
pub fn pair_strip(mesh: &Mesh, i: usize, p: &ContactPair) -> Result<Vec<ContactElement>> {
    let mut elements = match &p.user_mesh {
        None => build(mesh, i, p.tag_a, p.tag_b)?,
        Some(tris) => check_user_mesh(mesh, i, p.tag_a, p.tag_b, tris)?.0,
    };
    shared_normals(Nodes::of(mesh), &side_of(mesh, p.tag_a)?, &mut elements);
    Ok(elements)
}

/// Builds B for a pair: conforming (node-to-node quads) when the nodes of
/// the two interfaces match, else by triangulating the strip between them.
pub fn build(mesh: &Mesh, pair: usize, tag_a: i32, tag_b: i32) -> Result<Vec<ContactElement>> {
    let (a, b) = (side_of(mesh, tag_a)?, side_of(mesh, tag_b)?);
    strip(Nodes::of(mesh), pair, &a, &b)
}

/// Refuses two sides whose outward normals point the same way where they
/// face each other: one of them given with its body on the right
/// (clockwise), its normals turned inward, would start every element of B
/// inverted. Judged locally, so that curved sides facing each other over
/// any arc pass: up to 64 edges of `a`, evenly spread, each against the
/// edge of `b` with the nearest midpoint; refused when more of them point
/// the same way as their partner than against it. Two sides both given
/// clockwise cannot be told from two given right from the interface alone:
/// the contract (body on the left) is the caller's.
pub fn check_facing(x: &[[f64; 2]], a: &Side, b: &Side) -> Result<()> {
    let mid = |[p, q]: [usize; 2]| [0.5 * (x[p][0] + x[q][0]), 0.5 * (x[p][1] + x[q][1])];
    // Outward normal of an oriented edge (body on its right): its left normal.
    let normal = |[p, q]: [usize; 2]| [-(x[q][1] - x[p][1]), x[q][0] - x[p][0]];
    let step = a.oriented.len().div_ceil(64).max(1);
    let (mut same, mut opposed) = (0usize, 0usize);
    for &ea in a.oriented.iter().step_by(step) {
        let ma = mid(ea);
        let nearest = b.oriented.iter().min_by(|&&e, &&f| {
            let (me, mf) = (mid(e), mid(f));
            let d = |m: [f64; 2]| (m[0] - ma[0]).hypot(m[1] - ma[1]);
            d(me).total_cmp(&d(mf))
        });
        let Some(&eb) = nearest else { continue };
        let (na, nb) = (normal(ea), normal(eb));
        let dot = na[0] * nb[0] + na[1] * nb[1];
        if dot > 0.0 {
            same += 1;
        } else if dot < 0.0 {
            opposed += 1;
        }
    }
    if same > opposed {
        return Err(Error::contact(format!(
            "contact {} and {} do not face each other: their outward normals point the \
             same way at {same} of {} sampled edges, so one of them is given with its body on the \
             right; give every edge with its body on its left (counter-clockwise)",
            a.name(),
            b.name(),
            same + opposed
        )));
    }
    Ok(())
}

/// [`build`] on two sides.
pub fn strip(nodes: Nodes<'_>, pair: usize, a: &Side, b: &Side) -> Result<Vec<ContactElement>> {
    match conforming(nodes, pair, a, b) {
        Ok(elements) => Ok(elements),
        // The strip's reason first, then why the strip was tried: the
        // conforming test's message (which node has no partner) where both
        // fit in a message, else only that the nodes do not match — whole
        // clauses, never a message cut to a length (it ended mid-number,
        // "… 6.544e-").
        Err(conforming) => nonconforming(nodes, pair, a, b).map_err(|e| {
            let whole = format!(
                "{} (as the strip triangulation; as a conforming interface: {})",
                e.message(),
                conforming.message()
            );
            Error::contact(match whole.len() <= crate::error::MESSAGE_BYTES {
                true => whole,
                false => format!(
                    "{} (the two sides' nodes do not match, so B is the strip triangulation \
                     between them)",
                    e.message()
                ),
            })
        }),
    }
}

/// Two straight interfaces along y = 0 with nodes at `xa` (side a, the
/// body below) and `xb` (side b, above): nodes, sides. For tests.
#[cfg(test)]
pub(crate) fn straight_sides(xa: &[f64], xb: &[f64]) -> (Vec<[f64; 2]>, Side, Side) {
    let line = |xs: &[f64]| xs.iter().map(|&v| [v, 0.0]).collect::<Vec<_>>();
    polyline_sides(&line(xa), &line(xb))
}

/// Side a through the points `pa` (its body on the right as it runs: below
/// a left-to-right line) and side b through `pb` (its body on the left:
/// above); the nodes are a's points, then b's. For tests.
#[cfg(test)]
pub(crate) fn polyline_sides(pa: &[[f64; 2]], pb: &[[f64; 2]]) -> (Vec<[f64; 2]>, Side, Side) {
    let mut x = pa.to_vec();
    x.extend_from_slice(pb);
    let na = pa.len();
    // Body on the left of p → q: right to left for a, left to right for b.
    let ea: Vec<[usize; 2]> = (0..na - 1).map(|i| [i + 1, i]).collect();
    let eb: Vec<[usize; 2]> = (0..pb.len() - 1).map(|i| [na + i, na + i + 1]).collect();
    let a = Side::from_edges(Nodes::new(&x, 0), 0, 1, 1, &ea).unwrap();
    let b = Side::from_edges(Nodes::new(&x, 0), 1, 2, 2, &eb).unwrap();
    (x, a, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Side a on y = 0 with nodes at 0, 1e-13 and 1, side b at 0 and 1,
    /// all scaled by `s`: the triangle on a's first edge has an interface
    /// edge 1e-13 of its longest one (its Jacobian barely changes when the
    /// gap opens); the one on a's second edge is a plain touching element.
    fn sliver_and_plain(s: f64) -> Result<Vec<ContactElement>> {
        let (x, a, b) = straight_sides(&[0.0, 1e-13 * s, s], &[0.0, s]);
        let sliver = checked_triangles(Nodes::new(&x, 0), 0, &a, &b, &[[0, 1, 4]]);
        assert!(sliver.is_err(), "scale {s:e}: the sliver is accepted");
        checked_triangles(Nodes::new(&x, 0), 0, &a, &b, &[[1, 2, 4]]).map(|r| r.0)
    }

    /// A disc's boundary polygon of `na` nodes at radius 1 (side a, the
    /// disc inside) and a bore's of `nb` nodes at radius `rb` (side b, the
    /// body outside), the bore's first node half a step round.
    fn ring_sides(na: usize, nb: usize, rb: f64) -> (Vec<[f64; 2]>, Side, Side) {
        let at = |r: f64, t: f64| [r * t.cos(), r * t.sin()];
        let tau = std::f64::consts::TAU;
        let mut x: Vec<[f64; 2]> = (0..na)
            .map(|k| at(1.0, tau * k as f64 / na as f64))
            .collect();
        x.extend((0..nb).map(|k| at(rb, tau * (k as f64 + 0.5) / nb as f64)));
        // The disc on the left of p → q: counter-clockwise; the bore's
        // body outside: clockwise.
        let ea: Vec<[usize; 2]> = (0..na).map(|k| [k, (k + 1) % na]).collect();
        let eb: Vec<[usize; 2]> = (0..nb).map(|k| [na + (k + 1) % nb, na + k]).collect();
        let a = Side::from_edges(Nodes::new(&x, 0), 0, 1, 1, &ea).unwrap();
        let b = Side::from_edges(Nodes::new(&x, 0), 1, 2, 2, &eb).unwrap();
        (x, a, b)
    }

    #[test]
    fn the_strip_between_two_closed_loops_has_one_triangle_on_every_edge_of_either() {
        for (na, nb) in [(8, 12), (12, 8), (7, 7), (64, 96)] {
            let (x, a, b) = ring_sides(na, nb, 1.001);
            let elements = nonconforming(Nodes::new(&x, 0), 0, &a, &b)
                .unwrap_or_else(|e| panic!("{na}:{nb}: {}", e.message()));
            assert_eq!(elements.len(), na + nb, "{na}:{nb}");
            let mut edges: Vec<[usize; 2]> = elements
                .iter()
                .map(|e| {
                    let mut v: Vec<usize> =
                        e.nodes.iter().copied().filter(|&n| n != e.apex).collect();
                    v.sort_unstable();
                    [v[0], v[1]]
                })
                .collect();
            edges.sort_unstable();
            edges.dedup();
            assert_eq!(
                edges.len(),
                na + nb,
                "{na}:{nb}: an edge carries two triangles"
            );
            // Every element faces the other side over its whole edge.
            assert!(elements.iter().all(|e| e.facing == e.edge_length));
        }
    }

    #[test]
    fn the_degeneracy_test_of_a_contact_triangle_is_the_same_at_every_length_scale() {
        for s in [1e-9, 1.0, 1e13, 1e100] {
            let plain =
                sliver_and_plain(s).unwrap_or_else(|e| panic!("scale {s:e}: {}", e.message()));
            assert_eq!(plain[0].edge_length, s - 1e-13 * s, "scale {s:e}");
        }
    }
}
