//! The contact traction read back at the interface nodes and the actual
//! interpenetration of the two deformed interfaces (docs/method.md §6.11).
//!
//! With T_e = ℓ_e h_c²/λ the force of every element of B is κ ℓ_e/2 times
//! the gap at its apex (κ f_e/2 where only f_e of its edge faces the other
//! side), and the nodal forces of a uniform gap are the consistent loads
//! of a uniform traction on both sides: the contact force on a node over
//! its tributary length (∫ of its hat over its interface edges, half of
//! them where they wholly face the other side) is a traction. An element's own gap is its apex's distance from the line of
//! its interface edge, which may be extended beyond the edge; the actual
//! overlap of a node is measured against the edge of the other side its
//! projection falls on.
//!
//! Each pair is read on its own: a node's tributary is over the part of its
//! interface edges that faces the other side of *that* pair (covered by
//! the other side's edges projected on it: B reaches the edge across the
//! other side's end, which faces nothing past it), and its force is that
//! pair's. A node on several pairs (where three bodies meet) reads
//! its pairs' normal forces over their tributaries together. On rings
//! the forces are the whole ring's and a tributary is ∫ φ_i 2πr ds
//! ([`Section::span_shares`]).

use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet};

use super::ContactElement;
use super::mesh::Nodes;
use crate::fem::element::TriGeometry;
use crate::fem::material::Section;

/// The contact traction at one interface node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodalTraction {
    /// The node (0-based).
    pub node: usize,
    /// Normal contact force on the node over its tributary length,
    /// positive in compression.
    pub pressure: f64,
    /// Tangential contact force on the node over its tributary length,
    /// along the tangent (−n_y, n_x) of its body's outward normal n (the
    /// direction of travel along a counter-clockwise boundary): the shear
    /// the other body exerts on the node's body. The two sides of an
    /// interface read the same value for one traction.
    pub shear: f64,
    /// Its tributary length: the integral of its hat over its interface
    /// edges as far as they face the other side of its pair, half its
    /// edges where they face it whole (summed over its pairs for a node on
    /// several).
    pub tributary: f64,
}

/// For each element of B, whether its interface edge lies on side a (the
/// side its normal points away from): its apex is then on side b, and
/// moving the apex along +n opens the element (J grows).
pub fn edge_on_side_a(nodes: Nodes<'_>, elements: &[ContactElement]) -> Vec<bool> {
    elements
        .iter()
        .map(|el| {
            let geo = TriGeometry::new(&nodes.corners(&el.nodes));
            let g = geo.g[el.apex_position()];
            g[0] * el.normal[0] + g[1] * el.normal[1] > 0.0
        })
        .collect()
}

/// The elements of B at each of their nodes.
fn elements_at(elements: &[ContactElement]) -> BTreeMap<usize, Vec<usize>> {
    let mut at: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for (k, el) in elements.iter().enumerate() {
        for &v in &el.nodes {
            at.entry(v).or_default().push(k);
        }
    }
    at
}

/// The elements within two steps of the nodes `from`: those at a node of
/// an element at one of them.
fn near_elements(
    at: &BTreeMap<usize, Vec<usize>>,
    elements: &[ContactElement],
    from: &[usize],
) -> BTreeSet<usize> {
    let mut near = BTreeSet::new();
    for v in from {
        for &k in &at[v] {
            for &w in &elements[k].nodes {
                near.extend(at[&w].iter().copied());
            }
        }
    }
    near
}

/// The part of each element's interface edge that faces the other side
/// of its pair, as disjoint spans of the edge's parameter t ∈ [0, 1] from
/// its first base node to its second: the edge covered by the other side's edges
/// near it (those of the elements within two steps), each projected on the
/// edge's line. B reaches one edge beyond the other side's end
/// (`contact::mesh::nonconforming`), which is covered only up to that end;
/// a side in pieces leaves its gaps uncovered. The other side's edges are
/// projected along the edge, not along the normal: on a curved interface
/// with a gap, the edge at the end of the concave side loses about g/2R of
/// its length. An interface edge wholly covered, as every one of a strip
/// but those at the other side's ends, is the one span (0, 1); a pair
/// whose elements all have their edge on one side (a user's B) is not
/// clipped. The elements must be of one pair.
fn facing_spans(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    on_a: &[bool],
) -> Vec<Vec<(f64, f64)>> {
    let x = nodes.x;
    let edge_of = |el: &ContactElement| {
        let mut base = el.nodes.iter().copied().filter(|&w| w != el.apex);
        (
            base.next().unwrap_or(el.apex),
            base.next().unwrap_or(el.apex),
        )
    };
    let at = elements_at(elements);
    let has_side = [false, true].map(|side| on_a.contains(&side));
    elements
        .iter()
        .enumerate()
        .map(|(k, el)| {
            if !has_side[usize::from(!on_a[k])] {
                return vec![(0.0, 1.0)];
            }
            let (p, q) = edge_of(el);
            let d = [x[q][0] - x[p][0], x[q][1] - x[p][1]];
            let len2 = d[0] * d[0] + d[1] * d[1];
            let t = |w: usize| ((x[w][0] - x[p][0]) * d[0] + (x[w][1] - x[p][1]) * d[1]) / len2;
            let near = near_elements(&at, elements, &el.nodes);
            let mut spans: Vec<(f64, f64)> = near
                .iter()
                .filter(|&&j| on_a[j] != on_a[k])
                .map(|&j| {
                    let (r, s) = edge_of(&elements[j]);
                    let (tr, ts) = (t(r), t(s));
                    (tr.min(ts).clamp(0.0, 1.0), tr.max(ts).clamp(0.0, 1.0))
                })
                .filter(|(lo, hi)| hi > lo)
                .collect();
            spans.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            // The union of the spans: merge the overlapping ones.
            let mut union = Vec::new();
            let mut current: Option<(f64, f64)> = None;
            for (lo, hi) in spans {
                current = match current {
                    Some((a, b)) if lo <= b => Some((a, b.max(hi))),
                    Some(span) => {
                        union.push(span);
                        Some((lo, hi))
                    }
                    None => Some((lo, hi)),
                };
            }
            union.extend(current);
            union
        })
        .collect()
}

/// The side of every node of B (true: side a).
fn node_sides(elements: &[ContactElement], on_a: &[bool]) -> BTreeMap<usize, bool> {
    let mut side = BTreeMap::new();
    for (el, &a) in elements.iter().zip(on_a) {
        for &v in &el.nodes {
            side.insert(v, if v == el.apex { !a } else { a });
        }
    }
    side
}

/// The tributary length of every node of B: ∫ φ_i ds over the part of
/// its interface edges that faces the other side ([`facing_spans`]; each
/// interface edge is the edge of exactly one element of B), φ_i its hat:
/// half its edges where they face the other side whole. The consistent
/// load of a uniform traction t on the node is t m_i, which is what the
/// strip puts on it (docs/method.md §6.11, also where the other side ends
/// inside an edge), so that t is read back at every node. Zero for a node
/// that is only an apex. The elements must be of one pair.
fn tributaries(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    on_a: &[bool],
    section: Section,
) -> BTreeMap<usize, f64> {
    let spans = facing_spans(nodes, elements, on_a);
    let mut tributary = BTreeMap::new();
    for (el, spans) in elements.iter().zip(&spans) {
        // ∫ (1 − t) w and ∫ t w over the spans, the hats of the edge's
        // first and second base nodes; (0, 1) gives ½ and ½ exactly in
        // the plane.
        let mut base_x = el
            .nodes
            .iter()
            .filter(|&&v| v != el.apex)
            .map(|&v| nodes.x[v][0]);
        let (x0, x1) = (base_x.next().unwrap_or(0.0), base_x.next().unwrap_or(0.0));
        let (mut first, mut second) = (0.0, 0.0);
        for &(lo, hi) in spans {
            let [f, s] = section.span_shares(x0, x1, lo, hi);
            first += f;
            second += s;
        }
        let mut base = 0;
        for &v in &el.nodes {
            let m = tributary.entry(v).or_insert(0.0);
            if v != el.apex {
                *m += el.edge_length * if base == 0 { first } else { second };
                base += 1;
            }
        }
    }
    tributary
}

/// The elements of B grouped by pair, in pair order (one pair: borrowed).
fn by_pair(elements: &[ContactElement]) -> Vec<(usize, Cow<'_, [ContactElement]>)> {
    match elements.first() {
        None => Vec::new(),
        Some(first) if elements.iter().all(|el| el.pair == first.pair) => {
            vec![(first.pair, Cow::Borrowed(elements))]
        }
        Some(_) => {
            let mut groups: BTreeMap<usize, Vec<ContactElement>> = BTreeMap::new();
            for el in elements {
                groups.entry(el.pair).or_default().push(el.clone());
            }
            groups
                .into_iter()
                .map(|(pair, els)| (pair, Cow::Owned(els)))
                .collect()
        }
    }
}

/// Each pair's readings `read(pair, its elements)` put together: a node
/// on one pair keeps that pair's; a node on several reads their normal
/// forces over their tributaries together, Σ p_k m_k / Σ m_k (the plain
/// mean of the p_k where no pair gives it a tributary; a pair that gives
/// it none, where it is only an apex, then counts for nothing beside one
/// that does). Sorted by node.
fn per_pair(
    elements: &[ContactElement],
    mut read: impl FnMut(usize, &[ContactElement]) -> Vec<NodalTraction>,
) -> Vec<NodalTraction> {
    let mut at: BTreeMap<usize, Vec<NodalTraction>> = BTreeMap::new();
    for (pair, els) in by_pair(elements) {
        for q in read(pair, &els) {
            at.entry(q.node).or_default().push(q);
        }
    }
    at.into_values()
        .map(|qs| {
            if let [one] = qs.as_slice() {
                return *one;
            }
            let m: f64 = qs.iter().map(|q| q.tributary).sum();
            let mean = |value: fn(&NodalTraction) -> f64| match m > 0.0 {
                true => qs.iter().map(|q| value(q) * q.tributary).sum::<f64>() / m,
                false => qs.iter().map(value).sum::<f64>() / qs.len() as f64,
            };
            NodalTraction {
                node: qs[0].node,
                pressure: mean(|q| q.pressure),
                shear: mean(|q| q.shear),
                tributary: m,
            }
        })
        .collect()
}

/// The contact traction at every node of B from the forces
/// `force(pair, node)` of each pair's elements on the node, split along
/// each element's own normal and tangent (`ContactState::framed_forces`:
/// [Σ f·n, Σ f·t], n from side a to side b, t = (−n_y, n_x)): the normal
/// and tangential forces on the node over its tributary length (the part
/// of its interface edges that faces the other side), the pressure
/// positive when it pushes the node into its body, the shear along its
/// body's counter-clockwise tangent. A node on several pairs reads their
/// forces over their tributaries together. Sorted by node.
pub fn nodal_tractions(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    section: Section,
    force: impl Fn(usize, usize) -> [f64; 2],
) -> Vec<NodalTraction> {
    per_pair(elements, |pair, els| {
        own_tractions(nodes, els, section, |v| force(pair, v))
    })
}

/// [`nodal_tractions`] of the elements of one pair.
fn own_tractions(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    section: Section,
    force: impl Fn(usize) -> [f64; 2],
) -> Vec<NodalTraction> {
    let on_a = edge_on_side_a(nodes, elements);
    let (side, tributary) = (
        node_sides(elements, &on_a),
        tributaries(nodes, elements, &on_a, section),
    );
    side.iter()
        .map(|(&node, &on_side_a)| {
            let ([normal, tangential], m) = (force(node), tributary[&node]);
            // n points from a to b, the outward normal of side a: compression
            // pushes a along −n, b along +n; side b's tangent is −t.
            let (push, shear) = match on_side_a {
                true => (-normal, tangential),
                false => (normal, -tangential),
            };
            let per_length = |f: f64| if m > 0.0 { f / m } else { 0.0 };
            NodalTraction {
                node,
                pressure: per_length(push),
                shear: per_length(shear),
                tributary: m,
            }
        })
        .collect()
}

/// The interface edge of the other side that each node of B faces: for
/// every node, the nearest edge of the other side (among those of the
/// elements within two steps) that its projection falls on, as (p, q, t)
/// with the point (1 − t) x_p + t x_q, in the initial configuration.
/// Nodes beyond the other side's ends face nothing.
fn facing_edges(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    on_a: &[bool],
    side: &BTreeMap<usize, bool>,
) -> BTreeMap<usize, Option<(usize, usize, f64)>> {
    let x = nodes.x;
    let at = elements_at(elements);
    side.iter()
        .map(|(&v, &v_on_a)| {
            let near = near_elements(&at, elements, &[v]);
            let mut best: Option<(f64, (usize, usize, f64))> = None;
            for &k in &near {
                let el = &elements[k];
                if on_a[k] == v_on_a {
                    continue; // an edge of v's own side
                }
                let mut base = el.nodes.iter().copied().filter(|&w| w != el.apex);
                let (Some(p), Some(q)) = (base.next(), base.next()) else {
                    continue;
                };
                let d = [x[q][0] - x[p][0], x[q][1] - x[p][1]];
                let len2 = d[0] * d[0] + d[1] * d[1];
                let t = ((x[v][0] - x[p][0]) * d[0] + (x[v][1] - x[p][1]) * d[1]) / len2;
                if !(-1e-12..=1.0 + 1e-12).contains(&t) {
                    continue;
                }
                let t = t.clamp(0.0, 1.0);
                let c = [x[p][0] + t * d[0], x[p][1] + t * d[1]];
                let dist = (x[v][0] - c[0]).hypot(x[v][1] - c[1]);
                if best.is_none_or(|(bd, _)| dist < bd) {
                    best = Some((dist, (p, q, t)));
                }
            }
            (v, best.map(|(_, e)| e))
        })
        .collect()
}

/// The contact traction at every node of B read from both sides at once:
/// the mean of the node's own [`nodal_tractions`] value and the other
/// side's, the other side's normal forces over its tributaries weighted by
/// w_ij = φ_j(x_i) + φ_i(x_j) — interpolated where that side is coarser,
/// averaged over the node's support where it is finer (docs/method.md
/// §6.11, "Pressure as a traction", (6.12)); then a node of a side more
/// than 1.8× finer than the edge it faces takes that edge's values,
/// interpolated, blended with its own from 1.2× ((6.13)). One value per point of a matching interface. A
/// uniform traction is read exactly, as by [`nodal_tractions`]; on a
/// curved non-matching interface the two sides' own readings err at the
/// scale of the meshes with opposite signs, and this one is 3–6× closer
/// to the traction, as close as a mortar's with the cylinder 2.5× coarser
/// (Hertz). Nodes that face
/// nothing (beyond the other side's ends) keep their own value. Each pair
/// is read on its own (`force(pair, node)`, as for [`nodal_tractions`]); a
/// node on several pairs reads them together. Sorted by node.
pub fn interface_tractions(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    section: Section,
    force: impl Fn(usize, usize) -> [f64; 2],
) -> Vec<NodalTraction> {
    per_pair(elements, |pair, els| {
        both_sides(nodes, els, section, |v| force(pair, v))
    })
}

/// [`interface_tractions`] of the elements of one pair.
fn both_sides(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    section: Section,
    force: impl Fn(usize) -> [f64; 2],
) -> Vec<NodalTraction> {
    let own = own_tractions(nodes, elements, section, force);
    let at: BTreeMap<usize, NodalTraction> = own.iter().map(|q| (q.node, *q)).collect();
    let on_a = edge_on_side_a(nodes, elements);
    let side = node_sides(elements, &on_a);
    let facing = facing_edges(nodes, elements, &on_a, &side);
    // The other side's reading at node i: Σ_j w_ij F_j / Σ_j w_ij m_j over
    // its nodes j, F_j = p_j m_j the normal force, w_ij = φ_j(x_i) + φ_i(x_j)
    // (each node's hat evaluated at the other's projection): the other
    // side's values interpolated where it is coarser, averaged over i's
    // support where it is finer, and a uniform traction read exactly.
    // The shear is read alike: both sides read one traction's shear with
    // one sign (NodalTraction::shear).
    let mut acc: BTreeMap<usize, [f64; 3]> = BTreeMap::new();
    let load = |w: usize| {
        let r = at[&w];
        [r.pressure * r.tributary, r.shear * r.tributary, r.tributary]
    };
    let mut add = |to: usize, weight: f64, f: [f64; 3]| {
        let e = acc.entry(to).or_insert([0.0; 3]);
        *e = std::array::from_fn(|c| e[c] + weight * f[c]);
    };
    for (&v, face) in &facing {
        let Some((p, q, t)) = *face else { continue };
        add(v, 1.0 - t, load(p));
        add(v, t, load(q));
        add(p, 1.0 - t, load(v));
        add(q, t, load(v));
    }
    let read: Vec<NodalTraction> = own
        .iter()
        .map(|q| {
            let other = acc
                .get(&q.node)
                .filter(|f| f[2] > 0.0)
                .map(|f| [f[0] / f[2], f[1] / f[2]]);
            let [pressure, shear] = match (q.tributary > 0.0, other) {
                (true, Some(o)) => [0.5 * (q.pressure + o[0]), 0.5 * (q.shear + o[1])],
                (false, Some(o)) => o,
                (_, None) => [q.pressure, q.shear],
            };
            NodalTraction {
                pressure,
                shear,
                ..*q
            }
        })
        .collect();
    from_the_coarser_side(nodes, elements, &facing, read)
}

/// From how much longer the other side's edge than a node's own edges
/// the node starts to take the other side's reading, and from how much it
/// takes it alone ([`from_the_coarser_side`]): a blend in between, so that
/// no mesh ratio (2:3 is 1.5, a jittered one anything near) flips the
/// reading node by node; nearly matching meshes read both sides alike.
const COARSER: (f64, f64) = (1.2, 1.8);

/// The both-sides reading `read`, with each node whose facing edge of the
/// other side is r times as long as its own edges given that edge's
/// reading instead, interpolated at the node's projection, for r ≥ 1.8
/// ([`COARSER`]); blended linearly with its own from r = 1.2. Where one side is coarser, its (6.12) averages the finer
/// side's lumps over its support and is as close to the traction as a
/// mortar's (Hertz, cylinder 2.5× coarser, a/64: 9.6e-3 of p₀ within 0.8a,
/// the mortar prototype 8.7e-3), while the finer side's reads them (1.9e-2):
/// the finer side takes the coarser side's values. A uniform traction stays
/// exact; matching meshes are unchanged.
fn from_the_coarser_side(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    facing: &BTreeMap<usize, Option<(usize, usize, f64)>>,
    read: Vec<NodalTraction>,
) -> Vec<NodalTraction> {
    // The mean length of each node's own interface edges.
    let mut own: BTreeMap<usize, (f64, usize)> = BTreeMap::new();
    for el in elements {
        for &v in el.nodes.iter().filter(|&&v| v != el.apex) {
            let e = own.entry(v).or_insert((0.0, 0));
            *e = (e.0 + el.edge_length, e.1 + 1);
        }
    }
    let value: BTreeMap<usize, [f64; 2]> = read
        .iter()
        .map(|q| (q.node, [q.pressure, q.shear]))
        .collect();
    let x = nodes.x;
    read.iter()
        .map(|q| {
            let Some(&Some((p, r, t))) = facing.get(&q.node) else {
                return *q;
            };
            let Some(&(sum, n)) = own.get(&q.node) else {
                return *q;
            };
            let ratio = (x[r][0] - x[p][0]).hypot(x[r][1] - x[p][1]) / (sum / n as f64);
            let w = ((ratio - COARSER.0) / (COARSER.1 - COARSER.0)).clamp(0.0, 1.0);
            match (value.get(&p), value.get(&r)) {
                (Some(vp), Some(vr)) if w > 0.0 => {
                    let blend =
                        |own: f64, c: usize| (1.0 - w) * own + w * ((1.0 - t) * vp[c] + t * vr[c]);
                    NodalTraction {
                        pressure: blend(q.pressure, 0),
                        shear: blend(q.shear, 1),
                        ..*q
                    }
                }
                _ => *q,
            }
        })
        .collect()
}

/// The largest interpenetration of the deformed interfaces (linearised:
/// positions X + u along the initial normals; 0 when none) for the nodal
/// displacements `disp`: over the nodes of B, how far a node lies beyond
/// the interface edge of the other side that its projection falls on
/// (interpolated on that edge, not extended). An element's own
/// −opening/ℓ_e measures its apex against the extended line of its edge,
/// which overstates the overlap when the apex lies beyond the edge's ends.
pub fn max_overlap(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    disp: impl Fn(usize) -> [f64; 2],
) -> f64 {
    let on_a = edge_on_side_a(nodes, elements);
    let side = node_sides(elements, &on_a);
    let facing = facing_edges(nodes, elements, &on_a, &side);
    let x = nodes.x;
    let point = |w: usize| {
        let uw = disp(w);
        [x[w][0] + uw[0], x[w][1] + uw[1]]
    };
    // The normal of the element whose edge (p, q) is.
    let normal: BTreeMap<(usize, usize), [f64; 2]> = elements
        .iter()
        .filter_map(|el| {
            let mut base = el.nodes.iter().copied().filter(|&w| w != el.apex);
            Some(((base.next()?, base.next()?), el.normal))
        })
        .collect();
    let mut worst = 0.0f64;
    for (&v, &v_on_a) in &side {
        let Some((p, q, t)) = facing[&v] else {
            continue;
        };
        let (pp, pq) = (point(p), point(q));
        let on_edge = [(1.0 - t) * pp[0] + t * pq[0], (1.0 - t) * pp[1] + t * pq[1]];
        let xv = point(v);
        // Gap along n (from a to b): b's point minus a's point.
        let (pa, pb) = if v_on_a { (xv, on_edge) } else { (on_edge, xv) };
        let n = normal[&(p, q)];
        let gap = n[0] * (pb[0] - pa[0]) + n[1] * (pb[1] - pa[1]);
        worst = worst.max(-gap);
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::mesh::{Side, conforming, nonconforming, straight_sides};

    /// Side a along y = 0 at `xa` (body below), side b at `xb` (body
    /// above), and the strip between them.
    fn strip(xa: &[f64], xb: &[f64]) -> (Vec<[f64; 2]>, Vec<ContactElement>) {
        let (x, a, b) = straight_sides(xa, xb);
        let elements = nonconforming(Nodes::new(&x, 0), 0, &a, &b).unwrap();
        (x, elements)
    }

    #[test]
    fn an_edge_beyond_the_other_sides_end_faces_nothing() {
        // Side b covers [0, 1.5] of side a's [0, 3]: B reaches side a's edge
        // [1, 2], which b's end cuts in half, and the edge beyond it, which
        // faces nothing.
        let (x, elements) = strip(&[0.0, 1.0, 2.0, 3.0], &[0.0, 0.75, 1.5]);
        let nodes = Nodes::new(&x, 0);
        let on_a = edge_on_side_a(nodes, &elements);
        let m = tributaries(nodes, &elements, &on_a, Section::Plane);
        assert_eq!(m[&0], 0.5);
        // ∫ φ over [1, 1.5] of the cut edge: 3/8 to node 1, 1/8 to node 2,
        // the consistent loads the strip puts there (a uniform traction
        // reads back as itself).
        assert_eq!(m[&1], 0.5 + 0.375);
        assert_eq!(m[&2], 0.125);
        assert_eq!(m.get(&3).copied().unwrap_or(0.0), 0.0);
        // Side b lies wholly over a: its tributaries are its half edges.
        assert_eq!(m[&4], 0.375);
        assert_eq!(m[&5], 0.75);
        assert_eq!(m[&6], 0.375);
    }

    /// The tributaries of a pair's nodes.
    fn tributaries_of(x: &[[f64; 2]], elements: &[ContactElement]) -> BTreeMap<usize, f64> {
        let nodes = Nodes::new(x, 0);
        tributaries(
            nodes,
            elements,
            &edge_on_side_a(nodes, elements),
            Section::Plane,
        )
    }

    #[test]
    fn on_a_ring_a_tributary_is_the_hat_integrated_against_two_pi_r() {
        // The strip of the test above with x the radius: node 0 on the
        // axis takes ∫₀¹ (1 − r) 2πr dr = π/3; node 2 (r = 2) the facing
        // part [1, 1.5] of its edge, ∫ (r − 1) 2πr dr = π/3 too; node 1
        // both, ∫₀¹ r·2πr dr + ∫₁^1.5 (2 − r) 2πr dr = 2π/3 + 2π·11/24.
        let (x, elements) = strip(&[0.0, 1.0, 2.0, 3.0], &[0.0, 0.75, 1.5]);
        let nodes = Nodes::new(&x, 0);
        let ring = Section::Revolution {
            coupling: 1.0,
            hoop: 3.0,
        };
        let m = tributaries(nodes, &elements, &edge_on_side_a(nodes, &elements), ring);
        let pi = std::f64::consts::PI;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * b.abs();
        assert!(close(m[&0], pi / 3.0), "{}", m[&0]);
        assert!(close(m[&2], pi / 3.0), "{}", m[&2]);
        assert!(
            close(m[&1], 2.0 * pi / 3.0 + 2.0 * pi * 11.0 / 24.0),
            "{}",
            m[&1]
        );
    }

    #[test]
    fn a_corner_of_the_interface_clips_no_edge_whatever_its_angle() {
        // Body a is an L: its top y = 0 over [0, 3] and a leg up from the
        // origin to (eps, 0.8); body b sits in the corner, its nodes on a's.
        // The leg ends the other side near the floor's first edge: any
        // angle, even one off 90° by round-off, must leave the floor whole.
        for eps in [0.0, 1e-12, -1e-12, 0.15] {
            let floor = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0], [eps, 0.8]];
            let x: Vec<[f64; 2]> = floor.iter().chain(&floor).copied().collect();
            let a = Side::from_edges(
                Nodes::new(&x, 0),
                0,
                1,
                1,
                &[[3, 2], [2, 1], [1, 0], [0, 4]],
            )
            .unwrap();
            let b = Side::from_edges(
                Nodes::new(&x, 0),
                1,
                2,
                2,
                &[[9, 5], [5, 6], [6, 7], [7, 8]],
            )
            .unwrap();
            let elements = conforming(Nodes::new(&x, 0), 0, &a, &b).unwrap();
            let m = tributaries_of(&x, &elements);
            for (v, want) in [(1, 1.0), (2, 1.0), (3, 0.5), (6, 1.0), (7, 1.0), (8, 0.5)] {
                assert_eq!(m[&v], want, "eps {eps:e}, node {v}");
            }
        }
    }

    #[test]
    fn a_side_in_two_pieces_keeps_every_edge() {
        let xs = [0.0, 1.0, 1.5, 2.5];
        let x: Vec<[f64; 2]> = xs.iter().chain(&xs).map(|&v| [v, 0.0]).collect();
        let a = Side::from_edges(Nodes::new(&x, 0), 0, 1, 1, &[[1, 0], [3, 2]]).unwrap();
        let b = Side::from_edges(Nodes::new(&x, 0), 1, 2, 2, &[[4, 5], [6, 7]]).unwrap();
        let elements = conforming(Nodes::new(&x, 0), 0, &a, &b).unwrap();
        for (v, m) in tributaries_of(&x, &elements) {
            assert_eq!(m, 0.5, "node {v}");
        }
    }

    #[test]
    fn a_gap_wider_than_an_edge_clips_as_a_closed_one() {
        for gap in [0.0, 0.5, 1.5] {
            let (mut x, elements) = strip(&[0.0, 1.0, 2.0, 3.0], &[0.0, 0.75, 1.5]);
            for p in x.iter_mut().skip(4) {
                p[1] = gap;
            }
            let m = tributaries_of(&x, &elements);
            assert_eq!((m[&0], m[&1], m[&2]), (0.5, 0.875, 0.125), "gap {gap}");
        }
    }
}
