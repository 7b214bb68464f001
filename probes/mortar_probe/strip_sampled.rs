//! The *strip-sampled mortar*: the mortar weighted gaps of the probe,
//! written as linear combinations of the apex gaps of tfem's own elements
//! of B (docs/method.md (6.9)).
//!
//! Between consecutive merged nodes (both sides' nodes, ordered by x) the
//! gap of two linear polylines is linear. Its value at a merged node c is
//! what the strip element with apex c and the facing edge of the other side
//! (the edge whose x-range contains c; extrapolated only past the other
//! side's ends) reads:
//!
//!     g_e = o_e / ℓ_e,   o_e = J0_e + Σ_a (n·g_a)(n·u_a)
//!
//! (tfem's `linearised_opening`: the normal gap at the apex against the
//! edge's line, positive when open, whichever side the edge is on). So the
//! weighted gap of slave node i,
//!
//!     G_i = ∫ ψ_i g ds = Σ_e c_ie g_e,
//!
//! ψ_i the hat φ_i or Wohlmuth's dual 2φ_i − φ_j, is exact with
//! c_ie = Σ over the pieces [a, b] of i's slave edges that e bounds of
//! (ℓ_piece/6)(2ψ_i(e) + ψ_i(other end)): the integral of the product of
//! two linear functions. The energy Σ_i ½ (κ/m_i) G_i² (m_i = ∫ φ_i ds) is
//! then a rank-one penalty per slave node on a functional of the strip
//! elements around it, active while G_i < 0: the probe's `mortar_solve`
//! takes it as it takes the probe's own mortar.
//!
//! The element that samples a merged node is looked up in tfem's B (the
//! public `Model::contact_elements`). The nearest-midpoint strip does not
//! contain every such element, and no strip triangulation can: an edge
//! has one triangle, so where two nodes of the finer side face the same
//! edge of the coarser one, at most one of them is its apex. Measured, B
//! lacks the element of 24–40 % of the merged nodes of the non-matching
//! Hertz interfaces (2.5:1 and 1:2.5, a/16 … a/64; 0–40 % on the patch
//! test; 0–1 node matching), on Hertz every one at a node that is the apex
//! of no element at all (a node of the finer side whose two edges take the
//! same apex). What stands for such a sample ([`Missing`]):
//!
//! * `Synthesise`: the element of B whose edge is the facing edge, its apex
//!   replaced by c (same normal, same formula (6.9)): not one of B's
//!   elements; exact, and the scheme is then the probe's mortar with the
//!   gap read along B's normals;
//! * `Interpolate`: B's elements only, the sample left out (the gap
//!   integrated as the linear interpolant of B's apex samples): misses the
//!   polylines' kinks at those nodes and fails the patch test by O(p);
//! * `Combine`, `CombineCommonNormal`: B's elements only, the missing
//!   sample written as a combination of B's triangles near it (least
//!   squares over the DOF coefficients). On a straight interface it is
//!   exact with ≤ 8 of them (e.g. the gap at a node c inside the edge
//!   (c′, c) whose element's apex b is a node of c's facing edge F is the
//!   linear interpolation, at c, of that element's reading at b and the
//!   reading at c′ against F — itself a sample or such a combination). On
//!   the curved Hertz interface it is exact (residual ≤ 2e-14, ≤ 8
//!   triangles) only when the triangles are read with one normal (the
//!   missing sample's); with their own normals (tfem's, interpolated
//!   between side a's nodal normals) the residual stays 5–20 % even with
//!   70 triangles, since readings along different normals do not combine
//!   into one along n.
//!
//! Measured (`-- --dual --schemes mortar,sampled,sampled-ls-n,sampled-ls,sampled-b`
//! and `-- --patch`; largest nodal-pressure error within 0.8a over p₀,
//! each method's best reading, iterations with the finer side the slave):
//!
//! | cylinder mesh, a/64 | tfem | dual mortar | sampled, sampled-ls-n | sampled-ls | sampled-b |
//! |---|---|---|---|---|---|
//! | 2.5× coarser | 12, 9.55e-3 | 10, 8.72e-3 | 10, 9.04e-3 | 9, 8.71e-3 | 13, 6.97e-2 |
//! | 2.5× finer | 15, 4.46e-3 | 12, 2.14e-3 | 12, 2.17e-3 | 13, 2.90e-3 | 17, 3.60e-2 |
//! | matching | 11, 1.10e-3 | 9, 9.51e-4 | 9, 9.51e-4 | 9, 9.51e-4 | 9, 9.51e-4 |
//!
//! Patch test (3/2, 2/3 plain and jittered, 7/3, 3/7 jittered, h = 1/8,
//! 1/32, either slave, either basis): ≤ 5.2e-12 of p for `sampled`,
//! ≤ 6.4e-12 for `sampled-ls(-n)` (tfem 7.9e-12, the mortar 6.9e-12);
//! `sampled-b` 0.65 … 13 of p.

use std::collections::BTreeMap;

use tfem::contact::ContactElement;
use tfem::contact::law::opening_coefficient;
use tfem::element::TriGeometry;

use super::WeightedGap;

/// A linearised apex gap: g = g0 + Σ c[k]·u_k (global DOFs).
struct ApexGap {
    g0: f64,
    c: Vec<(usize, f64)>,
}

/// The apex gap (6.9) of the triangle `nodes` read with normal `n` and
/// interface edge length `len` (tfem's opening over ℓ_e).
fn apex_gap(x: &[[f64; 2]], nodes: [usize; 3], n: [f64; 2], len: f64) -> ApexGap {
    let corners = [x[nodes[0]], x[nodes[1]], x[nodes[2]]];
    let geo = TriGeometry::new(&corners);
    let c = (0..6)
        .map(|a| {
            (
                2 * nodes[a / 2] + a % 2,
                opening_coefficient(&geo, n, a) / len,
            )
        })
        .collect();
    ApexGap { g0: geo.j / len, c }
}

/// tfem's B indexed by (apex, edge) and by edge.
struct StripIndex<'a> {
    elements: &'a [ContactElement],
    /// (apex, lower edge node, higher edge node) → element.
    by_apex_edge: BTreeMap<(usize, usize, usize), usize>,
    /// (lower, higher edge node) → element.
    by_edge: BTreeMap<(usize, usize), usize>,
}

impl<'a> StripIndex<'a> {
    fn new(elements: &'a [ContactElement]) -> Self {
        let mut by_apex_edge = BTreeMap::new();
        let mut by_edge = BTreeMap::new();
        for (k, el) in elements.iter().enumerate() {
            let e: Vec<usize> = el.nodes.iter().copied().filter(|&v| v != el.apex).collect();
            let edge = (e[0].min(e[1]), e[0].max(e[1]));
            by_apex_edge.insert((el.apex, edge.0, edge.1), k);
            by_edge.insert(edge, k);
        }
        StripIndex {
            elements,
            by_apex_edge,
            by_edge,
        }
    }

    /// The gap at `apex` against the edge (p, q): B's element when it has
    /// one (true), else the edge's element with its apex replaced (false).
    fn gap(&self, x: &[[f64; 2]], apex: usize, p: usize, q: usize) -> (ApexGap, bool) {
        let edge = (p.min(q), p.max(q));
        if let Some(&k) = self.by_apex_edge.get(&(apex, edge.0, edge.1)) {
            let el = &self.elements[k];
            return (apex_gap(x, el.nodes, el.normal, el.edge_length), true);
        }
        let k = *self
            .by_edge
            .get(&edge)
            .unwrap_or_else(|| panic!("edge ({p}, {q}) has no element of B"));
        let el = &self.elements[k];
        let nodes = el.nodes.map(|v| if v == el.apex { apex } else { v });
        (apex_gap(x, nodes, el.normal, el.edge_length), false)
    }

    /// Whether `v` is the apex of an element of B.
    fn is_apex(&self, v: usize) -> bool {
        self.elements.iter().any(|el| el.apex == v)
    }

    /// Whether B has the element (apex, edge (p, q)).
    fn has(&self, apex: usize, p: usize, q: usize) -> bool {
        self.by_apex_edge.contains_key(&(apex, p.min(q), p.max(q)))
    }
}

/// What to do with a merged node whose sampling element B lacks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Missing {
    /// Synthesise the element from the nodes (not one of B's).
    Synthesise,
    /// Leave the node unsampled: interpolate the nearest sampled merged
    /// nodes (B's elements only; not exact across the polylines' kinks).
    Interpolate,
    /// Write the missing sample as a least-squares combination of B's
    /// elements near it (B's elements only; exact where the residual is
    /// at round-off).
    Combine,
    /// As `Combine`, B's triangles near it read with the missing sample's
    /// normal instead of their own (one normal per combination).
    CombineCommonNormal,
}

/// The combination Σ_e c_e g_e of B's elements lying within
/// [xc − w, xc + w] (every node) closest, in least squares over the DOF
/// coefficients, to `target` (each read with `common_normal` when given,
/// else its own); w grows from `w0` by 1.5× (up to 8×) until
/// the residual is below 1e-10 of |target|. Returns the combination, its
/// relative residual and the number of elements it used.
fn local_combination(
    index: &StripIndex<'_>,
    x: &[[f64; 2]],
    target: &ApexGap,
    common_normal: Option<[f64; 2]>,
    xc: f64,
    w0: f64,
) -> (ApexGap, f64, usize) {
    let norm: f64 = target.c.iter().map(|(_, v)| v * v).sum::<f64>().sqrt();
    let mut best: Option<(ApexGap, f64, usize)> = None;
    let mut w = w0;
    while w <= 8.0 * w0 {
        let picked: Vec<ApexGap> = index
            .elements
            .iter()
            .filter(|el| el.nodes.iter().all(|&v| (x[v][0] - xc).abs() <= w))
            .map(|el| {
                let n = common_normal.unwrap_or(el.normal);
                apex_gap(x, el.nodes, n, el.edge_length)
            })
            .collect();
        if !picked.is_empty() {
            // Rows: the DOFs any of them (or the target) reads.
            let mut dofs: BTreeMap<usize, usize> = BTreeMap::new();
            for g in picked.iter().chain([target]) {
                for &(d, _) in &g.c {
                    let next = dofs.len();
                    dofs.entry(d).or_insert(next);
                }
            }
            let mut m = nalgebra::DMatrix::<f64>::zeros(dofs.len(), picked.len());
            for (e, g) in picked.iter().enumerate() {
                for &(d, v) in &g.c {
                    m[(dofs[&d], e)] += v;
                }
            }
            let mut t = nalgebra::DVector::<f64>::zeros(dofs.len());
            for &(d, v) in &target.c {
                t[dofs[&d]] += v;
            }
            let svd = m.clone().svd(true, true);
            let c = svd
                .solve(&t, 1e-12 * svd.singular_values.max())
                .expect("svd");
            let residual = (&m * &c - &t).norm() / norm;
            let terms: Vec<(f64, &ApexGap)> = c.iter().copied().zip(&picked).collect();
            let g = combine(&terms);
            let n = picked.len();
            if best.as_ref().is_none_or(|b| residual < b.1) {
                best = Some((g, residual, n));
            }
            if residual < 1e-10 {
                break;
            }
        }
        w *= 1.5;
    }
    best.expect("no element of B near a merged node")
}

/// The strip-sampled weighted gaps and what their construction found.
pub struct SampledGaps {
    /// Per candidate slave node, in the probe's form.
    pub gaps: Vec<WeightedGap>,
    /// Merged-node samples taken from B's own elements.
    pub from_b: usize,
    /// Merged-node samples synthesised from the nodes (no such element in B;
    /// with `Missing::Interpolate`/`Combine`, replaced).
    pub synthesised: usize,
    /// Of those, at a node that is the apex of no element of B.
    pub no_apex: usize,
    /// `Missing::Combine`: the largest relative residual of a combination
    /// and the most elements one used.
    pub combine_residual: f64,
    pub combine_elements: usize,
    /// Largest number of sampling elements in one node's functional.
    pub max_elements: usize,
    /// Mean number of sampling elements per node's functional.
    pub mean_elements: f64,
    /// Largest number of DOFs in one node's functional.
    pub max_dofs: usize,
}

/// The facing edge (index into `side`) of abscissa `s` on a polyline
/// sorted by x: the edge whose x-range contains it, the end edges beyond
/// the ends. When `s` is a node of `side` (to 1e-12 of an edge) both edges
/// at it are returned, the left one first.
fn facing_edges(xs: &[f64], s: f64) -> Vec<usize> {
    let last = xs.len() - 2;
    let tol = 1e-12 * (xs[xs.len() - 1] - xs[0]);
    let mut out = Vec::new();
    for j in 0..=last {
        if s >= xs[j] - tol && s <= xs[j + 1] + tol {
            out.push(j);
        }
    }
    if out.is_empty() {
        out.push(if s < xs[0] { 0 } else { last });
    }
    out
}

/// A linear combination of apex gaps.
fn combine(terms: &[(f64, &ApexGap)]) -> ApexGap {
    let mut c: BTreeMap<usize, f64> = BTreeMap::new();
    let mut g0 = 0.0;
    for &(w, g) in terms {
        g0 += w * g.g0;
        for &(d, v) in &g.c {
            *c.entry(d).or_insert(0.0) += w * v;
        }
    }
    ApexGap {
        g0,
        c: c.into_iter().collect(),
    }
}

/// The strip-sampled weighted gaps of the slave polyline (nodes sorted by
/// x) against the master one, from tfem's B (`elements`). `dual`: weigh
/// with ψ_i = 2φ_i − φ_j instead of φ_i. Candidates, as in the probe's
/// mortar: slave nodes whose whole support faces the master (here: lies
/// within the master's x-range).
///
/// `missing`: what stands for a merged node's sample when B lacks its
/// element (see [`Missing`]). With `Interpolate` the gap is integrated as
/// the piecewise linear interpolant of B's apex samples, exact for a
/// linear gap but not across the polylines' kinks at unsampled nodes.
pub fn sampled_gaps(
    x: &[[f64; 2]],
    slave: &[usize],
    master: &[usize],
    elements: &[ContactElement],
    dual: bool,
    missing: Missing,
) -> SampledGaps {
    let index = StripIndex::new(elements);
    let xs: Vec<f64> = slave.iter().map(|&v| x[v][0]).collect();
    let xm: Vec<f64> = master.iter().map(|&v| x[v][0]).collect();
    let (lo, hi) = (xm[0], xm[xm.len() - 1]);
    let tol = 1e-12 * (hi - lo);
    let inside = |k: usize| xs[k] >= lo - tol && xs[k] <= hi + tol;
    // The merged nodes in x order: (slave edge k, ξ on it, sample), the
    // slave nodes (ξ = 0 of their right edge, or ξ = 1 of the last edge)
    // against their facing master edge (the one B has the element of, when
    // the node is a master node's too), the master nodes strictly inside a
    // slave edge against that edge.
    let mut merged: Vec<(usize, f64, Option<ApexGap>)> = Vec::new();
    let (mut from_b, mut synthesised, mut no_apex) = (0, 0, 0);
    let (mut combine_residual, mut combine_elements) = (0.0f64, 0);
    let mut sample = |apex: usize, p: usize, q: usize| -> Option<ApexGap> {
        let (g, real) = index.gap(x, apex, p, q);
        if real {
            from_b += 1;
            return Some(g);
        }
        synthesised += 1;
        if !index.is_apex(apex) {
            no_apex += 1;
        }
        match missing {
            Missing::Synthesise => Some(g),
            Missing::Interpolate => None,
            Missing::Combine | Missing::CombineCommonNormal => {
                let w0 = (x[p][0] - x[q][0]).abs().max(1e-300);
                let normal = (missing == Missing::CombineCommonNormal)
                    .then(|| index.elements[index.by_edge[&(p.min(q), p.max(q))]].normal);
                let (c, r, n) = local_combination(&index, x, &g, normal, x[apex][0], w0);
                combine_residual = combine_residual.max(r);
                combine_elements = combine_elements.max(n);
                Some(c)
            }
        }
    };
    for (k, &s) in slave.iter().enumerate() {
        if !inside(k) {
            continue;
        }
        let edges = facing_edges(&xm, xs[k]);
        let j = edges
            .iter()
            .copied()
            .find(|&j| index.has(s, master[j], master[j + 1]))
            .unwrap_or(edges[0]);
        let last = k + 1 == slave.len();
        let (edge, xi) = if last { (k - 1, 1.0) } else { (k, 0.0) };
        merged.push((edge, xi, sample(s, master[j], master[j + 1])));
        if last || !inside(k + 1) {
            continue;
        }
        for (j, &m) in master.iter().enumerate() {
            if xm[j] > xs[k] + tol && xm[j] < xs[k + 1] - tol {
                let xi = (xm[j] - xs[k]) / (xs[k + 1] - xs[k]);
                merged.push((k, xi, sample(m, slave[k], slave[k + 1])));
            }
        }
    }
    // B only: an unsampled merged node takes the interpolation (in x) of
    // the nearest sampled ones.
    let at = |&(k, xi, _): &(usize, f64, Option<ApexGap>)| xs[k] + xi * (xs[k + 1] - xs[k]);
    let filled: Vec<ApexGap> = (0..merged.len())
        .map(|m| {
            if let Some(g) = &merged[m].2 {
                return combine(&[(1.0, g)]);
            }
            let left = (0..m).rev().find(|&l| merged[l].2.is_some());
            let right = (m + 1..merged.len()).find(|&r| merged[r].2.is_some());
            let (l, r) = match (left, right) {
                (Some(l), Some(r)) => (l, r),
                // Past the last sample: extrapolate the two nearest.
                (Some(l), None) => ((0..l).rev().find(|&q| merged[q].2.is_some()).unwrap(), l),
                (None, Some(r)) => (
                    r,
                    (r + 1..merged.len())
                        .find(|&q| merged[q].2.is_some())
                        .unwrap(),
                ),
                (None, None) => panic!("no sample at all"),
            };
            let (xl, xr, xc) = (at(&merged[l]), at(&merged[r]), at(&merged[m]));
            let t = (xc - xl) / (xr - xl);
            let gl = merged[l].2.as_ref().unwrap();
            let gr = merged[r].2.as_ref().unwrap();
            combine(&[(1.0 - t, gl), (t, gr)])
        })
        .collect();
    // Per slave node: m_i and Σ_e c_ie g_e, accumulated as (m, g0, DOF map,
    // number of pieces).
    let mut acc: Vec<(f64, f64, BTreeMap<usize, f64>, usize)> =
        vec![(0.0, 0.0, BTreeMap::new(), 0); slave.len()];
    // Consecutive merged nodes on one slave edge bound a piece (the slave
    // node ending an edge is the next edge's ξ = 0, or the last ξ = 1).
    for m in 0..merged.len().saturating_sub(1) {
        let (ka, a, _) = merged[m];
        let (kb, mut b, _) = merged[m + 1];
        if kb == ka + 1 && b == 0.0 {
            b = 1.0;
        } else if kb != ka {
            continue;
        }
        let k = ka;
        let (p, q) = (x[slave[k]], x[slave[k + 1]]);
        let l = (q[0] - p[0]).hypot(q[1] - p[1]) * (b - a);
        let (ga, gb) = (&filled[m], &filled[m + 1]);
        for (local, phi, psi) in [
            (k, (1.0 - a, 1.0 - b), (2.0 - 3.0 * a, 2.0 - 3.0 * b)),
            (k + 1, (a, b), (3.0 * a - 1.0, 3.0 * b - 1.0)),
        ] {
            let wt = if dual { psi } else { phi };
            let entry = &mut acc[local];
            entry.0 += 0.5 * l * (phi.0 + phi.1);
            // ∫ of two linear functions over the piece.
            let ca = l / 6.0 * (2.0 * wt.0 + wt.1);
            let cb = l / 6.0 * (wt.0 + 2.0 * wt.1);
            for (cw, g) in [(ca, ga), (cb, gb)] {
                entry.1 += cw * g.g0;
                for &(d, v) in &g.c {
                    *entry.2.entry(d).or_insert(0.0) += cw * v;
                }
            }
            entry.3 += 1;
        }
    }
    // Candidates: the whole support within the master's range.
    let mut gaps = Vec::new();
    let mut counts = Vec::new();
    for (k, (m, g0, c, pieces)) in acc.into_iter().enumerate() {
        let left_in = k == 0 || xs[k - 1] >= lo - tol;
        let right_in = k + 1 == xs.len() || xs[k + 1] <= hi + tol;
        if m <= 0.0 || !left_in || !right_in {
            continue;
        }
        // Distinct samples: the pieces' ends, the node's own counted once.
        counts.push(pieces + 1);
        gaps.push(WeightedGap {
            node: slave[k],
            m,
            g0,
            c: c.into_iter().filter(|(_, v)| *v != 0.0).collect(),
        });
    }
    let max_elements = counts.iter().copied().max().unwrap_or(0);
    let mean_elements = counts.iter().sum::<usize>() as f64 / counts.len().max(1) as f64;
    let max_dofs = gaps.iter().map(|g| g.c.len()).max().unwrap_or(0);
    SampledGaps {
        gaps,
        from_b,
        synthesised,
        no_apex,
        combine_residual,
        combine_elements,
        max_elements,
        mean_elements,
        max_dofs,
    }
}
