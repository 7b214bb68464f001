//! Automatic contact pairing: which tagged boundaries of different bodies
//! face each other (docs/method.md §6.16).
//!
//! Two tags *face each other within a tolerance* δ (a distance in model
//! units, δ ≥ 0) when some boundary edge e of the one and some boundary
//! edge f of the other, bounding different bodies,
//!
//! * are at most δ apart: the shortest Euclidean distance between the two
//!   segments (0 when they touch or cross) is ≤ δ;
//! * have opposed outward normals: n_e · n_f ≤ −cos 30° (the two faces are
//!   parallel to within 30° and turned towards each other, so two faces of
//!   stacked blocks that only share a corner — side by side, normals
//!   parallel, or at a right angle — never pair);
//! * lie each in front of the other: the body of f (the third node of
//!   f's triangle) is on the outward side of e's line, and the same from
//!   f — so faces crossed by an initial overlap (a press fit) pair while it
//!   is below the elements' height along the interface (a deeper one is
//!   declared by hand), and the outer faces of two bodies, back to back,
//!   never pair;
//! * overlap along the interface: f projected on the line of e covers a
//!   part of e of positive length (more than 1e-9 of the shorter edge), so
//!   faces that meet at a single corner point do not pair;
//! * have no third body between them: the edges of other bodies that face
//!   e within δ nearer than f do not cover all of what f covers along e
//!   (and the same from f), so that a δ larger than a body's thickness
//!   does not pair faces across it.
//!
//! The distance is compared with δ up to the rounding of the coordinates
//! (4 ε times their magnitude), so a gap of exactly δ pairs.
//!
//! A tag is a candidate side only if all its edges are boundary edges of one
//! body (a contact side must be: [`super::mesh::Side`]). Edges of the same
//! body never pair (self-contact is not supported), whatever their
//! distance. The tolerance should still stay below the thickness of the
//! bodies: where a body between two faces covers only part of them, the
//! rest of the faces see each other and pair.
//!
//! The search bins the edges in a uniform grid (cells of the larger of δ
//! and the mean edge length), so its cost is linear in the number of
//! candidate edges for meshes of bounded grading.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use crate::error::{Error, Result};
use crate::fem::mesh::Mesh;

/// The largest angle between the turned-around outward normals of two edges
/// that face each other: 30°, as cos 30°.
pub const FACING_COSINE: f64 = 0.866_025_403_784_438_6;

/// Smallest overlap along the interface, relative to the shorter edge, for
/// two edges to face each other (above round-off, so that a shared corner
/// does not count).
pub const MIN_OVERLAP: f64 = 1e-9;

/// Two tags found facing each other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacingPair {
    /// The smaller of the two tags.
    pub tag_a: i32,
    /// The larger of the two tags.
    pub tag_b: i32,
    /// The body `tag_a` bounds.
    pub body_a: i32,
    /// The body `tag_b` bounds.
    pub body_b: i32,
    /// The smallest distance between two facing edges of the two tags.
    pub distance: f64,
}

/// One candidate edge.
struct Edge {
    p: [f64; 2],
    q: [f64; 2],
    /// The third node of the edge's triangle: a point inside its body.
    inner: [f64; 2],
    normal: [f64; 2],
    body: i32,
    tag: i32,
}

/// Checks a pairing tolerance: finite and ≥ 0.
pub fn check_tolerance(tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance >= 0.0 {
        Ok(())
    } else {
        Err(Error::argument(format!(
            "contact pairing tolerance {tolerance:?} must be a finite distance >= 0"
        )))
    }
}

/// The edges of the candidate tags. With `tags` given, each must name
/// boundary edges of one body (else an error naming it); with `None`, the
/// tags that cannot be a contact side (interior edges, several bodies) are
/// left out.
fn candidate_edges(mesh: &Mesh, tags: Option<&[i32]>) -> Result<Vec<Edge>> {
    let wanted: Option<Vec<i32>> = tags.map(|t| {
        let mut t = t.to_vec();
        t.sort_unstable();
        t.dedup();
        t
    });
    let base = mesh.index_base();
    // Per tag: its edges, or why it cannot be a side.
    let mut by_tag: BTreeMap<i32, std::result::Result<Vec<Edge>, String>> = BTreeMap::new();
    for (k, e) in mesh.boundary_edges().iter().enumerate() {
        if wanted
            .as_ref()
            .is_some_and(|w| w.binary_search(&e.tag).is_err())
        {
            continue;
        }
        let entry = by_tag.entry(e.tag).or_insert_with(|| Ok(Vec::new()));
        let Ok(list) = entry else { continue };
        let normal = mesh.outward_normal(e);
        let (Some((t, third)), Some(normal)) = (e.owner, normal) else {
            *entry = Err(format!(
                "boundary edge {} (tag {}) is interior to the mesh or of zero length: \
                 it cannot bound a contact interface",
                k + base,
                e.tag
            ));
            continue;
        };
        let body = mesh.body_of()[t];
        if let Some(first) = list.first().filter(|f| f.body != body) {
            *entry = Err(format!(
                "tag {} spans bodies {} and {body}: each side of a pair must lie on one body",
                e.tag, first.body
            ));
            continue;
        }
        let [p, q] = e.nodes;
        list.push(Edge {
            p: mesh.nodes()[p],
            q: mesh.nodes()[q],
            inner: mesh.nodes()[third],
            normal,
            body,
            tag: e.tag,
        });
    }
    if let Some(w) = &wanted {
        if let Some(t) = w.iter().find(|t| !by_tag.contains_key(t)) {
            return Err(Error::argument(format!(
                "contact pairing: no boundary edge has tag {t}"
            )));
        }
    }
    let mut out = Vec::new();
    for (tag, edges) in by_tag {
        match edges {
            Ok(mut e) => out.append(&mut e),
            Err(why) if wanted.is_some() => {
                return Err(Error::contact(format!(
                    "contact pairing: tag {tag} cannot be a contact side: {why}"
                )));
            }
            Err(_) => {}
        }
    }
    Ok(out)
}

/// The tags whose boundary edges bound several bodies, with those bodies:
/// not a contact side, so automatic pairing over every tag leaves them
/// out (and says so: [`crate::model::Problem::add_contact_pairs_auto`]).
pub fn tags_on_several_bodies(mesh: &Mesh) -> BTreeMap<i32, BTreeSet<i32>> {
    let mut bodies: BTreeMap<i32, BTreeSet<i32>> = BTreeMap::new();
    for e in mesh.boundary_edges() {
        if let Some((t, _)) = e.owner {
            bodies.entry(e.tag).or_default().insert(mesh.body_of()[t]);
        }
    }
    bodies.retain(|_, b| b.len() > 1);
    bodies
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// Distance from point `x` to segment [p, q].
fn point_segment(x: [f64; 2], p: [f64; 2], q: [f64; 2]) -> f64 {
    let d = sub(q, p);
    let len2 = dot(d, d);
    let t = if len2 > 0.0 {
        (dot(sub(x, p), d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let c = [p[0] + t * d[0], p[1] + t * d[1]];
    (x[0] - c[0]).hypot(x[1] - c[1])
}

/// Shortest distance between segments [a, b] and [c, d]: zero when they
/// cross, else the least of the four point-to-segment distances.
pub fn segment_distance(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    let (ab, cd) = (sub(b, a), sub(d, c));
    let (s1, s2) = (cross(ab, sub(c, a)), cross(ab, sub(d, a)));
    let (s3, s4) = (cross(cd, sub(a, c)), cross(cd, sub(b, c)));
    if s1 * s2 < 0.0 && s3 * s4 < 0.0 {
        return 0.0;
    }
    point_segment(a, c, d)
        .min(point_segment(b, c, d))
        .min(point_segment(c, a, b))
        .min(point_segment(d, a, b))
}

fn length(e: &Edge) -> f64 {
    let d = sub(e.q, e.p);
    d[0].hypot(d[1])
}

fn midpoint(e: &Edge) -> [f64; 2] {
    [0.5 * (e.p[0] + e.q[0]), 0.5 * (e.p[1] + e.q[1])]
}

/// How far `f` lies in front of `e`, along `e`'s outward normal (negative
/// when behind it: an overlap, or the far side of a body).
fn separation(e: &Edge, f: &Edge) -> f64 {
    dot(sub(midpoint(f), e.p), e.normal)
}

/// The interval [lo, hi] that `f` covers along `e` (abscissas from e.p).
fn shadow(e: &Edge, f: &Edge) -> (f64, f64) {
    let d = sub(e.q, e.p);
    let len_e = length(e);
    let (t0, t1) = (dot(sub(f.p, e.p), d) / len_e, dot(sub(f.q, e.p), d) / len_e);
    (t0.min(t1), t0.max(t1))
}

/// Whether two edges face each other (normals opposed, each body in front
/// of the other's face, positive overlap along the first): the distance is
/// checked apart. A body is in front of a face when the third node of its
/// edge's triangle, inside it, lies on the face's outward side: an initial
/// overlap (a press fit, faces crossed) pairs while it is below the height
/// of the elements along the interface, and two faces back to back — the
/// outer faces of two bodies, normals opposed but turned away from each
/// other — never pair, whatever the tolerance (a probe paired the bottom
/// of a block with the top of the block under it at δ = 2.5 and the solve
/// read a 2-unit overlap). Locally a deeper overlap and two faces back to
/// back look the same (each body's face behind the other's, its interior
/// towards it); such a press fit is declared by hand.
fn facing(e: &Edge, f: &Edge) -> bool {
    if dot(e.normal, f.normal) > -FACING_COSINE {
        return false;
    }
    let in_front = |a: &Edge, b: &Edge| dot(sub(b.inner, a.p), a.normal) > 0.0;
    if !(in_front(e, f) && in_front(f, e)) {
        return false;
    }
    let (len_e, len_f) = (length(e), length(f));
    let (lo, hi) = shadow(e, f);
    let overlap = hi.min(len_e) - lo.max(0.0);
    overlap > MIN_OVERLAP * len_e.min(len_f)
}

/// Whether the edges `gs` of third bodies, facing `e` nearer than `f`,
/// cover the whole of what `f` covers along `e`: then every strip between
/// `e` and `f` would cross those bodies (a probe paired the faces of
/// blocks 1 and 3 across block 2 once δ exceeded a block's height). Part
/// covered is not enough: the rest of `f` sees `e` (a thin shim under part
/// of a coarse edge must not hide it).
fn hidden<'a>(e: &Edge, f: &Edge, gs: impl Iterator<Item = &'a Edge>) -> bool {
    let len_e = length(e);
    let (f0, f1) = shadow(e, f);
    let (f0, f1) = (f0.max(0.0), f1.min(len_e));
    let mut covers: Vec<(f64, f64)> = gs
        .filter(|g| g.body != e.body && g.body != f.body && separation(e, g) < separation(e, f))
        .map(|g| {
            let (g0, g1) = shadow(e, g);
            (g0.max(f0), g1.min(f1))
        })
        .filter(|(lo, hi)| hi > lo)
        .collect();
    covers.sort_by(|a, b| a.0.total_cmp(&b.0));
    let slack = MIN_OVERLAP * len_e.min(length(f));
    let mut reach = f0;
    for (lo, hi) in covers {
        if lo > reach + slack {
            break;
        }
        reach = reach.max(hi);
    }
    reach >= f1 - slack
}

/// The pairs of tags of different bodies whose boundary edges face each
/// other within `tolerance` (see the module documentation for how it is
/// measured), sorted by (tag_a, tag_b) with tag_a < tag_b. `tags`: the tags
/// to consider (each must name boundary edges of one body, else an error
/// naming it), or `None` for every tag that can be a contact side. An
/// empty result means no two tags face each other within the tolerance.
pub fn facing_pairs(mesh: &Mesh, tags: Option<&[i32]>, tolerance: f64) -> Result<Vec<FacingPair>> {
    check_tolerance(tolerance)?;
    let edges = candidate_edges(mesh, tags)?;
    if edges.len() < 2 {
        return Ok(Vec::new());
    }
    let bins = Bins::new(&edges, tolerance);
    let near = near_facing(&edges, &bins, tolerance);
    Ok(tag_pairs(&edges, &near))
}

/// The candidate edges binned in a uniform grid, so that the edges near
/// one are looked for in a few cells rather than among all edges.
struct Bins {
    /// The lower corner of the edges' bounding box.
    lo: [f64; 2],
    /// The side of a cell.
    cell: f64,
    /// The edges whose bounding box meets each cell.
    cells: HashMap<(i64, i64), Vec<usize>>,
}

impl Bins {
    /// Cells of the larger of δ and the mean edge length, coarsened if
    /// there would be many more cells than edges.
    fn new(edges: &[Edge], tolerance: f64) -> Bins {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        let mut total = 0.0;
        for e in edges {
            for k in 0..2 {
                lo[k] = lo[k].min(e.p[k]).min(e.q[k]);
                hi[k] = hi[k].max(e.p[k]).max(e.q[k]);
            }
            total += sub(e.q, e.p)[0].hypot(sub(e.q, e.p)[1]);
        }
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let mut cell = (total / edges.len() as f64).max(tolerance);
        let cap = (4 * edges.len()) as f64;
        if (extent / cell).powi(2) > cap {
            cell = extent / cap.sqrt();
        }
        let mut bins = Bins {
            lo,
            cell,
            cells: HashMap::new(),
        };
        for (k, e) in edges.iter().enumerate() {
            for c in bins.cells_of(e, 0.0) {
                bins.cells.entry(c).or_default().push(k);
            }
        }
        bins
    }

    /// The cell index of coordinate `x` along axis `k`.
    fn index(&self, x: f64, k: usize) -> i64 {
        ((x - self.lo[k]) / self.cell).floor() as i64
    }

    /// The cells that the bounding box of `e`, grown by `grow`, meets.
    fn cells_of(&self, e: &Edge, grow: f64) -> impl Iterator<Item = (i64, i64)> + use<> {
        let (x0, x1) = (e.p[0].min(e.q[0]) - grow, e.p[0].max(e.q[0]) + grow);
        let (y0, y1) = (e.p[1].min(e.q[1]) - grow, e.p[1].max(e.q[1]) + grow);
        let rows = self.index(y0, 1)..=self.index(y1, 1);
        (self.index(x0, 0)..=self.index(x1, 0)).flat_map(move |i| rows.clone().map(move |j| (i, j)))
    }

    /// The edges binned in cell `c`, its (column, row): a genuine pair,
    /// as the cells are keyed.
    fn edges_in(&self, c: (i64, i64)) -> &[usize] {
        self.cells.get(&c).map_or(&[], Vec::as_slice)
    }
}

/// An edge found facing another within the tolerance.
#[derive(Clone, Copy)]
struct Near {
    /// The edge's index among the candidates.
    edge: usize,
    /// Its distance from the other.
    distance: f64,
}

/// For every edge, the edges of other bodies that face it ([`facing`])
/// within `tolerance`: each pair found once, and listed under both edges.
fn near_facing(edges: &[Edge], bins: &Bins, tolerance: f64) -> Vec<Vec<Near>> {
    // The last edge whose neighbourhood each edge was met in: an edge in
    // several of its cells is looked at once.
    let mut seen = vec![usize::MAX; edges.len()];
    let mut near: Vec<Vec<Near>> = vec![Vec::new(); edges.len()];
    for (k, e) in edges.iter().enumerate() {
        for c in bins.cells_of(e, tolerance) {
            for &m in bins.edges_in(c) {
                if m <= k || seen[m] == k {
                    continue;
                }
                seen[m] = k;
                let f = &edges[m];
                if f.body == e.body || !facing(e, f) {
                    continue;
                }
                let Some(distance) = distance_within(e, f, tolerance) else {
                    continue;
                };
                near[k].push(Near { edge: m, distance });
                near[m].push(Near { edge: k, distance });
            }
        }
    }
    near
}

/// The distance between edges `e` and `f` if it is at most `tolerance`
/// up to the rounding of their coordinates: the distance is computed from
/// coordinates, so a gap of exactly δ may exceed it by their rounding (a
/// probe's gap of 0.1 read 0.10000000000000009), and must still pair.
fn distance_within(e: &Edge, f: &Edge, tolerance: f64) -> Option<f64> {
    let scale = [e.p, e.q, f.p, f.q]
        .iter()
        .fold(0.0f64, |m, x| m.max(x[0].abs()).max(x[1].abs()));
    let distance = segment_distance(e.p, e.q, f.p, f.q);
    (distance <= tolerance + 4.0 * f64::EPSILON * scale).then_some(distance)
}

/// The pairs of tags of the edges facing each other with no third body
/// between them ([`hidden`]), each at the smallest distance of its
/// edges, sorted by tags.
fn tag_pairs(edges: &[Edge], near: &[Vec<Near>]) -> Vec<FacingPair> {
    let hidden = |a: usize, b: &Edge| hidden(&edges[a], b, near[a].iter().map(|n| &edges[n.edge]));
    let mut found: BTreeMap<(i32, i32), FacingPair> = BTreeMap::new();
    for (k, e) in edges.iter().enumerate() {
        for &Near { edge: m, distance } in &near[k] {
            let f = &edges[m];
            if m <= k || hidden(k, f) || hidden(m, e) {
                continue;
            }
            let (a, b) = if e.tag < f.tag { (e, f) } else { (f, e) };
            let entry = found.entry((a.tag, b.tag)).or_insert(FacingPair {
                tag_a: a.tag,
                tag_b: b.tag,
                body_a: a.body,
                body_b: b.body,
                distance,
            });
            entry.distance = entry.distance.min(distance);
        }
    }
    found.into_values().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_segments_are_at_distance_zero() {
        let d = segment_distance([0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]);
        assert_eq!(d, 0.0);
    }

    #[test]
    fn parallel_segments_are_at_their_offset() {
        let d = segment_distance([0.0, 0.0], [1.0, 0.0], [0.5, 0.25], [2.0, 0.25]);
        assert!((d - 0.25).abs() < 1e-15);
    }

    #[test]
    fn a_negative_or_nan_tolerance_is_refused_by_name() {
        for t in [-1.0, f64::NAN, f64::INFINITY] {
            let e = check_tolerance(t).unwrap_err();
            assert!(e.message().contains("tolerance"), "{}", e.message());
        }
    }
}
