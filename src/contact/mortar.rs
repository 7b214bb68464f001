//! The sampled mortar weighting of a contact pair (docs/method.md §6.11,
//! "The sampled mortar weighting"): one weighted gap per node of one side
//! (the slave), G_i = ∫ ψ_i g ds over the part of its support that faces
//! the other side (the master), written exactly in terms of gap samples at
//! the merged nodes.
//!
//! A flat element of B samples the normal gap at its apex against the line
//! of its interface edge (6.9). Between consecutive merged nodes (both
//! sides' nodes, ordered along the interface) the gap of two polylines is
//! linear, so with one such sample at every merged node the integral of a
//! linear weight times the gap is exact: on each piece [p, q] of length ℓ,
//! ∫ ψ g = (ℓ/6)[ψ(p)(2g_p + g_q) + ψ(q)(g_p + 2g_q)]. On a slave edge
//! every sample is read along that edge's normal ν (one normal per slave
//! edge, as in mortar methods): at a master node c, the apex gap of the
//! triangle (slave edge, c); at the edge's own ends, the apex gap of the
//! triangle (master edge that the ray along ν meets, slave node), read
//! along ν — one of B's own triangles where B has it, made for the node
//! where it does not (no strip triangulation samples every merged node:
//! an edge has one triangle). A slave node's two edges read it along
//! their two normals. Each G_i is therefore a linear functional of the
//! displacements over the slave node, its two neighbours and the master
//! nodes facing its support (and one beyond each end of it), G_i = G_i0 +
//! c_i·u — 2·(3 + facing master nodes + 2) coefficients at most, 15 nodes
//! against a master 5× finer — and the penalty energy Σ_i ½ (κ/m_i) G_i²
//! (m_i = ∫ φ_i ds) a rank-one term per slave node.
//!
//! Why it passes the contact patch test on any pair of straight sides: a
//! uniform gap g makes every sample g, so G_i = g ∫ψ_i = g m_i and the
//! forces Σ_i (κ/m_i) G_i c_i = κ g Σ_i c_i, where Σ_i c_i is the
//! derivative of ∫ (Σ_i ψ_i) g ds = ∫ g ds: the consistent loads of the
//! uniform traction κ g on both sides. That needs Σ_i ψ_i = 1 and
//! ∫ ψ_i = ∫ φ_i on every covered slave edge, which the hats φ_i and
//! Wohlmuth's dual functions ψ_i = 2φ_i − φ_j (biorthogonal: ∫ ψ_i φ_j =
//! δ_ij ∫ φ_j) both satisfy. An edge across the end of the master is
//! covered in part only; there the dual functions are no longer
//! biorthogonal and a negative lobe can read a wide open gap as an
//! overlap, so such an edge weights with the hats (both conditions still
//! hold).
//!
//! Why one normal per slave edge: a first version read each node along
//! the facing edge of the other side (slave nodes along the master's
//! normals, master nodes along the slave's); a review measured that on
//! sides that are not parallel the samples then alternate between g and
//! about g cos θ (a straight wedge at 45°: G/m 0.347 where the gap along
//! the slave's normal is 0.386), that a node crossing a vertex of the
//! other side jumps by O(g θ²), and that a curved pair and its mirror
//! image differed by 13–19 % of m_i in the coefficients at matching nodes.
//! Along ν the gap is the ray's distance to a continuous polygon: all
//! three are gone (tests). On curved sides whose ends face each other,
//! the ends project a few d × (the sides' turn) apart (d their distance):
//! a slave end within the strip's slack of the master's counts as facing
//! it (`to_slave_ends`), so its end edge keeps the dual weights and its
//! whole tributary (they were 1–7 % short before).
//!
//! The solve over these gaps is `solve::mortar`
//! ([`crate::contact::ContactWeighting::Mortar`]), its load steps
//! `solve::mortar_history`; friction and the host blocks still take
//! elements of B.

use std::collections::BTreeMap;

use super::mesh::{Aligned, Nodes, Side, alignment};
use crate::error::{Error, Result};

/// The weight ψ_i of a slave node's gap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Basis {
    /// The node's hat φ_i (the standard mortar).
    Standard,
    /// Wohlmuth's dual function 2φ_i − φ_j on every edge the master covers
    /// whole (the hat on an edge it covers in part).
    Dual,
}

/// Which side of the pair carries the weighted gaps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slave {
    /// Side a (the pair's first tag).
    A,
    /// Side b.
    B,
}

/// The weighted gap of one slave node, linear in the displacements:
/// G = `initial` + Σ c·u over (global DOF, c) in `coefficients`; negative
/// where the sides overlap.
#[derive(Debug, Clone, PartialEq)]
pub struct WeightedGap {
    /// The slave node (0-based).
    pub node: usize,
    /// m_i = ∫ φ_i ds over the part of its support facing the master.
    pub tributary: f64,
    /// G_i in the initial geometry.
    pub initial: f64,
    /// ∂G_i/∂u per global DOF (2·node + component), each DOF once, sorted.
    pub coefficients: Vec<(usize, f64)>,
}

impl WeightedGap {
    /// G_i for the global displacement vector `u` (2 per node).
    pub fn value(&self, u: &[f64]) -> f64 {
        self.initial
            + self
                .coefficients
                .iter()
                .map(|&(g, c)| c * u[g])
                .sum::<f64>()
    }
}

/// The state of one slave node after a contact solve under the mortar
/// weighting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlaveNode {
    /// The pair (0-based).
    pub pair: usize,
    /// The slave node (0-based).
    pub node: usize,
    /// m_i = ∫ φ_i ds over the part of its support facing the master.
    pub tributary: f64,
    /// The mean gap G_i/m_i over its support (negative: overlap).
    pub gap: f64,
    /// The contact pressure −κ G_i/m_i (positive in compression; zero
    /// when inactive).
    pub pressure: f64,
    /// Whether its penalty was on at convergence.
    pub active: bool,
}

/// A gap sample, linear in the displacements: g0 + Σ c·u.
#[derive(Debug, Clone, PartialEq)]
struct Sample {
    g0: f64,
    /// (global DOF, coefficient).
    c: Vec<(usize, f64)>,
}

/// The normal gap at node `c` against the line of edge (p, q), read along
/// `n` (from side a to side b), positive when open: the apex gap (6.9) of
/// the flat triangle (p, q, c). `edge_on_a`: whether (p, q) is on side a
/// (then c is on b, and the gap is c's position less the edge's).
fn apex_sample(
    x: &[[f64; 2]],
    p: usize,
    q: usize,
    c: usize,
    n: [f64; 2],
    edge_on_a: bool,
) -> Sample {
    let (xp, xq, xc) = (x[p], x[q], x[c]);
    let e = [xq[0] - xp[0], xq[1] - xp[1]];
    let t = ((xc[0] - xp[0]) * e[0] + (xc[1] - xp[1]) * e[1]) / (e[0] * e[0] + e[1] * e[1]);
    let (np, nq) = (1.0 - t, t);
    let sign = if edge_on_a { 1.0 } else { -1.0 };
    let r = [
        xc[0] - np * xp[0] - nq * xq[0],
        xc[1] - np * xp[1] - nq * xq[1],
    ];
    let mut c_dofs = Vec::with_capacity(6);
    for (node, w) in [(c, sign), (p, -sign * np), (q, -sign * nq)] {
        for (k, nk) in n.iter().enumerate() {
            c_dofs.push((2 * node + k, w * nk));
        }
    }
    Sample {
        g0: sign * (n[0] * r[0] + n[1] * r[1]),
        c: c_dofs,
    }
}

/// The edge of the chain with abscissas `s` (non-decreasing) whose range
/// holds `at`: the first with s[k] ≤ at ≤ s[k + 1], the end edges beyond
/// the chain's ends; past edges of zero extent (a leg of the chain
/// standing across the interface, all its nodes at one abscissa) to the
/// nearest edge with extent. None for a chain of zero extent.
fn edge_at(s: &[f64], at: f64) -> Option<usize> {
    let last = s.len().checked_sub(2)?;
    let k = s[1..].partition_point(|&v| v < at).min(last);
    let extent = |j: &usize| s[j + 1] > s[*j];
    (k..=last)
        .find(extent)
        .or_else(|| (0..k).rev().find(extent))
}

/// `al` with its facing interval reaching a slave end that lies beyond
/// lo or hi by no more than the strip's slack ([`Aligned::end_slack`]):
/// on curved sides a distance d apart, two ends that face each other
/// project a few d × (the sides' turn) apart, and the slave's end edge
/// then faces the master whole (the dual weights, its full tributary),
/// not in part. Without it the Lamé rings' end nodes read 4 % low and
/// their neighbours 1.7 % high (a hat on the end edge, dual weights on the
/// others).
fn to_slave_ends(mut al: Aligned, x: &[[f64; 2]], slave: Slave) -> Aligned {
    let (tol_lo, tol_hi) = al.end_slack(x);
    let s = match slave {
        Slave::A => &al.s_a,
        Slave::B => &al.s_b,
    };
    let (first, last) = (s[0], s[s.len() - 1]);
    if first < al.lo && al.lo - first <= tol_lo {
        al.lo = first;
    }
    if last > al.hi && last - al.hi <= tol_hi {
        al.hi = last;
    }
    al
}

/// One slave edge as the weighted gaps integrate over it: its nodes, the
/// normal every gap sample on it is read along (one normal per slave edge,
/// as in mortar methods), and where it lies along a and faces the master.
struct SlaveEdge {
    /// Its first and second node, in the slave chain's order.
    nodes: (usize, usize),
    /// Its unit normal ν, from a to b.
    nu: [f64; 2],
    /// The abscissa of its first node along a.
    e0: f64,
    /// The abscissa of its second node.
    e1: f64,
    /// Where it starts facing the master: e0 clipped to the facing
    /// interval.
    c0: f64,
    /// Where it stops: e1 clipped likewise.
    c1: f64,
}

/// One merged point: its abscissa along side a, its node, and whether it
/// is a slave node (else a master node), with the edge of the master it
/// faces (a slave node's; the ray of its reading starts the search there).
struct Point {
    s: f64,
    node: usize,
    slave: bool,
    facing: usize,
}

/// The weighted gaps of every slave node of the pair (sides `a`, `b`, the
/// normal from a to b) whose support faces the master: on each slave
/// edge, one gap sample per merged node read along the edge's normal,
/// integrated exactly against `basis`. Refuses sides that branch,
/// close, fold back along each other or do not face each other.
pub fn weighted_gaps(
    nodes: Nodes<'_>,
    a: &Side,
    b: &Side,
    slave: Slave,
    basis: Basis,
) -> Result<Vec<WeightedGap>> {
    let al = alignment(nodes, a, b)?;
    let al = match al.turn {
        // Closed loops: the slave's whole turn faces the master.
        Some([a0, a1, b0, b1]) => {
            let (lo, hi) = match slave {
                Slave::A => (al.s_a[a0], al.s_a[a1]),
                Slave::B => (al.s_b[b0], al.s_b[b1]),
            };
            Aligned { lo, hi, ..al }
        }
        None => to_slave_ends(al, nodes.x, slave),
    };
    let merged = merged_points(&al, slave);
    let gaps = integrated(nodes.x, &al, slave, basis, &merged)
        .into_iter()
        .filter(|(_, a)| a.tributary > 0.0)
        .map(|(node, a)| WeightedGap {
            node,
            tributary: a.tributary,
            initial: a.initial,
            coefficients: a
                .coefficients
                .into_iter()
                .filter(|&(_, c)| c != 0.0)
                .collect(),
        })
        .collect::<Vec<_>>();
    if gaps.is_empty() {
        return Err(Error::contact(format!(
            "interfaces {} and {} face each other over no edge of the slave side",
            a.name(),
            b.name()
        )));
    }
    Ok(gaps)
}

/// The slave's and the master's chains with their abscissas along a.
type Chains<'c> = (&'c [usize], &'c [f64], &'c [usize], &'c [f64]);

fn chains(al: &Aligned, slave: Slave) -> Chains<'_> {
    match slave {
        Slave::A => (&al.chain_a, &al.s_a, &al.chain_b, &al.s_b),
        Slave::B => (&al.chain_b, &al.s_b, &al.chain_a, &al.s_a),
    }
}

/// The merged nodes in the facing interval, in order along a. Where a
/// master node coincides with a slave node (within round-off) the slave's
/// stands for the point; where master nodes coincide (a leg of the master
/// standing across the interface at an end of it), the one the master goes
/// on facing the slave from: the last of them at lo, the first elsewhere
/// (the first read a leg's far vertex: a gap of the leg's length where the
/// sides were 0.01 apart, a review's case).
fn merged_points(al: &Aligned, slave: Slave) -> Vec<Point> {
    let (sl_chain, sl_s, ms_chain, ms_s) = chains(al, slave);
    let inside = |s: f64| s >= al.lo - al.tol && s <= al.hi + al.tol;
    let mut points: Vec<Point> = Vec::with_capacity(sl_chain.len() + ms_chain.len());
    for (own, own_s, is_slave) in [(sl_chain, sl_s, true), (ms_chain, ms_s, false)] {
        for (&c, &sc) in own.iter().zip(own_s) {
            if !inside(sc) {
                continue;
            }
            let facing = match is_slave {
                true => match edge_at(ms_s, sc) {
                    Some(k) => k,
                    None => continue,
                },
                false => 0,
            };
            points.push(Point {
                s: sc.clamp(al.lo, al.hi),
                node: c,
                slave: is_slave,
                facing,
            });
        }
    }
    points.sort_by(|p, q| p.s.total_cmp(&q.s));
    let mut merged: Vec<Point> = Vec::with_capacity(points.len());
    for p in points {
        match merged.last_mut() {
            Some(last) if p.s - last.s <= al.tol => {
                let at_lo = p.s <= al.lo + al.tol;
                if !last.slave && (p.slave || at_lo) {
                    *last = p;
                }
            }
            _ => merged.push(p),
        }
    }
    merged
}

/// The gap at merged point `p` read along ν, the normal (from a to b) of
/// slave edge `edge`: a master node against the edge's line (the apex gap
/// (6.9) of the triangle (edge, node)); a slave node (an end of the edge)
/// against the master polygon (`ms_chain`), where the ray from it along ν
/// meets it (the apex gap of the triangle (that master edge, node) read
/// along ν). `slave_on_a`: whether the slave is side a. One normal per
/// slave edge, as in mortar methods: the gap is then continuous as a node
/// crosses a vertex of the other side, and a pair and its mirror image
/// read alike.
fn sample_on_edge(
    x: &[[f64; 2]],
    ms_chain: &[usize],
    slave_on_a: bool,
    edge: &SlaveEdge,
    p: &Point,
) -> Sample {
    let nu = edge.nu;
    if !p.slave {
        let (ep, eq) = edge.nodes;
        return apex_sample(x, ep, eq, p.node, nu, slave_on_a);
    }
    let c = x[p.node];
    let last = ms_chain.len() - 2;
    let mut k = p.facing.min(last);
    let mut hit = None;
    // Walk to the master edge the ray meets (a few steps from the one
    // facing by abscissa); the end edges extend beyond the chain's ends.
    for _ in 0..ms_chain.len() {
        let (xp, xq) = (x[ms_chain[k]], x[ms_chain[k + 1]]);
        let e = [xq[0] - xp[0], xq[1] - xp[1]];
        // c + g ν = p + t e.
        let det = e[0] * nu[1] - e[1] * nu[0];
        if det.abs() <= 1e-12 * (e[0].hypot(e[1])) {
            break;
        }
        let r = [c[0] - xp[0], c[1] - xp[1]];
        let t = (r[0] * nu[1] - r[1] * nu[0]) / det;
        let g = (r[0] * e[1] - r[1] * e[0]) / det;
        hit = Some((k, t, g));
        match (t < 0.0 && k > 0, t > 1.0 && k < last) {
            (true, _) => k -= 1,
            (_, true) => k += 1,
            _ => break,
        }
    }
    let Some((k, t, g)) = hit else {
        // The ray runs along the master: read against its facing edge's
        // line along that edge's normal instead.
        let k = p.facing.min(last);
        let n = left_normal(x, ms_chain, k);
        return apex_sample(x, ms_chain[k], ms_chain[k + 1], p.node, n, !slave_on_a);
    };
    // The gap is the master's position less the slave's along ν when the
    // slave is side a, the reverse when it is b.
    let sign = if slave_on_a { 1.0 } else { -1.0 };
    let mut coefficients = Vec::with_capacity(6);
    for (node, w) in [
        (p.node, -sign),
        (ms_chain[k], sign * (1.0 - t)),
        (ms_chain[k + 1], sign * t),
    ] {
        for (d, nd) in nu.iter().enumerate() {
            coefficients.push((2 * node + d, w * nd));
        }
    }
    Sample {
        g0: sign * g,
        c: coefficients,
    }
}

/// ∫ ψ_i g ds and m_i = ∫ φ_i ds of every slave node, over each slave
/// edge's part in the facing interval, cut at the `merged` points (g
/// linear between them: exact).
fn integrated(
    x: &[[f64; 2]],
    al: &Aligned,
    slave: Slave,
    basis: Basis,
    merged: &[Point],
) -> BTreeMap<usize, Accumulated> {
    let (sl_chain, sl_s, _, _) = chains(al, slave);
    let mut acc: BTreeMap<usize, Accumulated> = BTreeMap::new();
    for k in 0..sl_chain.len() - 1 {
        let (e0, e1) = (sl_s[k], sl_s[k + 1]);
        let (c0, c1) = (e0.max(al.lo), e1.min(al.hi));
        if e1 <= e0 || c1 - c0 <= al.tol {
            continue;
        }
        let length = dist(x[sl_chain[k]], x[sl_chain[k + 1]]);
        // ds along the slave edge per unit of abscissa along a.
        let jac = length / (e1 - e0);
        let whole = c0 - e0 <= al.tol && e1 - c1 <= al.tol;
        let edge = SlaveEdge {
            nodes: (sl_chain[k], sl_chain[k + 1]),
            // Both chains run with body a on their right (b was turned
            // round): every edge's left normal points from a to b.
            nu: left_normal(x, sl_chain, k),
            e0,
            e1,
            c0,
            c1,
        };
        let on_edge = edge_samples(x, al, slave, &edge, merged);
        // The dual weights read g at the nodes for a gap linear on the edge;
        // a gap that bends sharply across it (a step or a corner of the
        // master, far from contact) turns their negative lobe into a read
        // overlap where the sides stand apart (a review's stepped master:
        // G/m = −0.15 where the gap is at least 0.01): the hats there.
        let dual = whole && !bent(&on_edge, length) && basis == Basis::Dual;
        // φ of the edge's first and second node at abscissa s.
        let phi = |s: f64| {
            let t = (s - e0) / (e1 - e0);
            [1.0 - t, t]
        };
        let psi = |s: f64| {
            let [f0, f1] = phi(s);
            match dual {
                true => [2.0 * f0 - f1, 2.0 * f1 - f0],
                false => [f0, f1],
            }
        };
        for (end, &node) in [sl_chain[k], sl_chain[k + 1]].iter().enumerate() {
            let entry = acc.entry(node).or_default();
            let [f0, f1] = [phi(c0)[end], phi(c1)[end]];
            entry.tributary += jac * (c1 - c0) * 0.5 * (f0 + f1);
            for w in on_edge.windows(2) {
                let ((sp, gp), (sq, gq)) = (&w[0], &w[1]);
                let piece = jac * (sq - sp) / 6.0;
                let (wp, wq) = (psi(*sp)[end], psi(*sq)[end]);
                // ∫ψg over the piece = ℓ/6 [ψp(2gp + gq) + ψq(gp + 2gq)].
                let (cp, cq) = (piece * (2.0 * wp + wq), piece * (wp + 2.0 * wq));
                entry.add(gp, cp);
                entry.add(gq, cq);
            }
        }
    }
    acc
}

/// The gap samples on slave edge `edge` of `al` (slave `slave`; abscissas
/// [e0, e1], facing the master over [c0, c1]), in order, each read along
/// the edge's normal ν: its ends as merged (slave nodes, or the facing
/// interval's bounds), and inside it every master vertex whose foot on the
/// edge's line falls inside, at its foot. The gap along ν kinks where the
/// ray passes a master vertex: at the vertex's foot, wherever the merged
/// order (by projection on a) put the vertex. On curved sides a vertex
/// facing a slave node projects onto one of the node's two chords only (a
/// tie broken by round-off), yet the other chord's rays pass it too:
/// without its foot there that chord read the ray's gap past the kink,
/// δ cos(Δθ/2)/cos Δθ, along its whole length instead of δ cos(Δθ/2) —
/// O(δ Δθ²) on some interior nodes but not on the end nodes, the Lamé
/// rings' 1 % end error at first order.
fn edge_samples(
    x: &[[f64; 2]],
    al: &Aligned,
    slave: Slave,
    edge: &SlaveEdge,
    merged: &[Point],
) -> Vec<(f64, Sample)> {
    let (_, _, ms_chain, ms_s) = chains(al, slave);
    let SlaveEdge {
        nodes,
        e0,
        e1,
        c0,
        c1,
        ..
    } = *edge;
    let first = merged.partition_point(|p| p.s < c0 - al.tol);
    let last = merged.partition_point(|p| p.s <= c1 + al.tol);
    let (xp, xq) = (x[nodes.0], x[nodes.1]);
    let ev = [xq[0] - xp[0], xq[1] - xp[1]];
    let ee = ev[0] * ev[0] + ev[1] * ev[1];
    let span = e1 - e0;
    let at_bound = |s: f64| s - c0 <= al.tol || c1 - s <= al.tol;
    let mut pts: Vec<(f64, &Point)> = merged[first..last]
        .iter()
        .filter(|p| p.slave || at_bound(p.s))
        .map(|p| (p.s, p))
        .collect();
    let j0 = ms_s.partition_point(|&v| v < c0 - span);
    let j1 = ms_s.partition_point(|&v| v <= c1 + span);
    let feet: Vec<Point> = (j0..j1)
        .filter(|&j| !pts.iter().any(|(_, p)| !p.slave && p.node == ms_chain[j]))
        .filter_map(|j| {
            let xc = x[ms_chain[j]];
            let t = ((xc[0] - xp[0]) * ev[0] + (xc[1] - xp[1]) * ev[1]) / ee;
            let sf = e0 + t * span;
            (sf > c0 + al.tol && sf < c1 - al.tol).then_some(Point {
                s: sf,
                node: ms_chain[j],
                slave: false,
                facing: 0,
            })
        })
        .collect();
    pts.extend(feet.iter().map(|p| (p.s, p)));
    pts.sort_by(|p, q| p.0.total_cmp(&q.0));
    let slave_on_a = slave == Slave::A;
    pts.iter()
        .map(|&(s, p)| (s, sample_on_edge(x, ms_chain, slave_on_a, edge, p)))
        .collect()
}

/// How far the initial gap on a slave edge may depart from the line
/// through its end values, over the edge's length, for the edge to keep
/// the dual weights: 0.1, far beyond what curvature makes (a circle of
/// radius R bends a gap by ℓ/(8R) of an edge ℓ) and far below a step or a
/// corner of the master.
const BENT: f64 = 0.1;

/// Whether the initial gap of the samples `on_edge` (in order) departs from
/// the line through the first and last by more than [`BENT`] × `length`.
fn bent(on_edge: &[(f64, Sample)], length: f64) -> bool {
    let (Some((s0, g0)), Some((s1, g1))) = (on_edge.first(), on_edge.last()) else {
        return false;
    };
    let slope = if s1 > s0 {
        (g1.g0 - g0.g0) / (s1 - s0)
    } else {
        0.0
    };
    on_edge
        .iter()
        .any(|(s, g)| (g.g0 - g0.g0 - slope * (s - s0)).abs() > BENT * length)
}

/// The side a solve should take as the slave: the coarser one over the
/// part where the sides face each other (the longer mean edge there; a on
/// a tie). Measured (docs/method.md §6.11, "Which side is the slave"):
/// against a stiff master, a finer slave has more weighted gaps than the
/// master can follow and its pressures oscillate (the axis of a 100×
/// stiffer cylinder read zero), while the coarser slave converges on
/// either mesh ratio.
pub fn coarser_side(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<Slave> {
    let [edges_a, edges_b] = facing_edges(nodes, a, b)?;
    Ok(if edges_b < edges_a {
        Slave::B
    } else {
        Slave::A
    })
}

/// The number of edges of side a and of side b over the part where they
/// face each other: [`coarser_side`]'s measure, summed over the pairs of
/// one interface where it is cut into several.
pub fn facing_edges(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<[usize; 2]> {
    let al = alignment(nodes, a, b)?;
    if let Some([a0, a1, b0, b1]) = al.turn {
        // Closed loops face each other whole: a turn's edges.
        return Ok([a1 - a0, b1 - b0]);
    }
    let inside = |s: &[f64]| {
        s.iter()
            .filter(|&&v| v > al.lo + al.tol && v < al.hi - al.tol)
            .count()
    };
    // Edges over [lo, hi]: one more than the nodes strictly inside.
    Ok([inside(&al.s_a) + 1, inside(&al.s_b) + 1])
}

/// The penalty length h_c of a pair weighted by its sides `a` and `b`: the
/// shortest edge of either side over the part where they face each other
/// (with the edges across its ends), as the strip's B holds them
/// (`contact::law::penalty_lengths`): both weightings penalise a uniform
/// gap alike.
pub fn penalty_length(nodes: Nodes<'_>, a: &Side, b: &Side) -> Result<f64> {
    let al = alignment(nodes, a, b)?;
    let x = nodes.x;
    let shortest = |chain: &[usize], s: &[f64]| {
        (0..chain.len() - 1)
            .filter(|&k| s[k + 1] > al.lo - al.tol && s[k] < al.hi + al.tol)
            .map(|k| dist(x[chain[k]], x[chain[k + 1]]))
            .fold(f64::INFINITY, f64::min)
    };
    Ok(shortest(&al.chain_a, &al.s_a).min(shortest(&al.chain_b, &al.s_b)))
}

/// A weighted gap being summed.
#[derive(Default)]
struct Accumulated {
    tributary: f64,
    initial: f64,
    coefficients: BTreeMap<usize, f64>,
}

impl Accumulated {
    fn add(&mut self, sample: &Sample, w: f64) {
        self.initial += w * sample.g0;
        for &(g, c) in &sample.c {
            *self.coefficients.entry(g).or_insert(0.0) += w * c;
        }
    }
}

/// The unit normal of edge k of `chain` on its left as it runs.
fn left_normal(x: &[[f64; 2]], chain: &[usize], k: usize) -> [f64; 2] {
    let (p, q) = (x[chain[k]], x[chain[k + 1]]);
    let len = dist(p, q);
    [-(q[1] - p[1]) / len, (q[0] - p[0]) / len]
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn sides(xa: &[[f64; 2]], xb: &[[f64; 2]]) -> (Vec<[f64; 2]>, Side, Side) {
        crate::contact::mesh::polyline_sides(xa, xb)
    }

    /// `n + 1` abscissas over [lo, hi], the inner ones moved by up to
    /// `jitter` of a cell (a fixed pseudo-random pattern).
    fn abscissas(n: usize, (lo, hi): (f64, f64), jitter: f64) -> Vec<f64> {
        let h = (hi - lo) / n as f64;
        (0..=n)
            .map(|i| {
                let wiggle = if i == 0 || i == n {
                    0.0
                } else {
                    jitter * ((i as f64 * 2.399).sin())
                };
                lo + (i as f64 + wiggle) * h
            })
            .collect()
    }

    fn line(xs: &[f64], y: f64) -> Vec<[f64; 2]> {
        xs.iter().map(|&v| [v, y]).collect()
    }

    fn gaps(x: &[[f64; 2]], a: &Side, b: &Side, slave: Slave, basis: Basis) -> Vec<WeightedGap> {
        weighted_gaps(Nodes::new(x, 0), a, b, slave, basis).unwrap()
    }

    /// The integral of the hat of node k of the abscissas `xs` over
    /// [lo, hi]: the trapezoidal rule on the pieces between the nodes and
    /// lo, hi (exact for a function linear on each; an independent reading
    /// of the tributary).
    fn hat_integral(xs: &[f64], k: usize, (lo, hi): (f64, f64)) -> f64 {
        let mut cuts: Vec<f64> = xs.iter().copied().filter(|&s| s > lo && s < hi).collect();
        cuts.insert(0, lo);
        cuts.push(hi);
        cuts.windows(2)
            .map(|w| 0.5 * (w[1] - w[0]) * (hat(xs, k, w[0]) + hat(xs, k, w[1])))
            .sum()
    }

    fn hat(xs: &[f64], k: usize, s: f64) -> f64 {
        if k > 0 && s >= xs[k - 1] && s <= xs[k] {
            (s - xs[k - 1]) / (xs[k] - xs[k - 1])
        } else if k + 1 < xs.len() && s >= xs[k] && s <= xs[k + 1] {
            (xs[k + 1] - s) / (xs[k + 1] - xs[k])
        } else {
            0.0
        }
    }

    const CASES: [(usize, usize, f64); 4] = [(3, 7, 0.0), (7, 3, 0.3), (5, 8, 0.3), (8, 8, 0.0)];
    const SLAVES: [Slave; 2] = [Slave::A, Slave::B];
    const BASES: [Basis; 2] = [Basis::Standard, Basis::Dual];

    #[test]
    fn a_uniform_gap_weighs_as_the_slave_nodes_tributary() {
        for (na, nb, jitter) in CASES {
            let (xa, xb) = (
                abscissas(na, (0.0, 1.0), jitter),
                abscissas(nb, (0.0, 1.0), jitter),
            );
            let (x, a, b) = sides(&line(&xa, 0.0), &line(&xb, 0.25));
            for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
                let all = gaps(&x, &a, &b, slave, basis);
                let (xs, offset) = match slave {
                    Slave::A => (&xa, 0),
                    Slave::B => (&xb, xa.len()),
                };
                assert_eq!(all.len(), xs.len(), "{na}:{nb} {slave:?} {basis:?}");
                // A uniform lift of b by w: G = (0.25 + w) m everywhere.
                let w = 1e-3;
                let u: Vec<f64> = (0..x.len())
                    .flat_map(|v| [0.0, if v >= xa.len() { w } else { 0.0 }])
                    .collect();
                for g in &all {
                    let k = g.node - offset;
                    let m = hat_integral(xs, k, (0.0, 1.0));
                    assert!(
                        (g.tributary - m).abs() < 1e-9,
                        "{} against {m}",
                        g.tributary
                    );
                    let expected = (0.25 + w) * g.tributary;
                    assert!(
                        (g.value(&u) - expected).abs() < 1e-15,
                        "{na}:{nb} {slave:?} {basis:?} node {k}: {} against {expected}",
                        g.value(&u)
                    );
                }
            }
        }
    }

    /// Σ_i c_i: the loads of a unit uniform traction the weighted gaps
    /// apply together (their derivative of ∫ g ds).
    fn summed_coefficients(all: &[WeightedGap], n_dofs: usize) -> Vec<f64> {
        let mut f = vec![0.0; n_dofs];
        for g in all {
            for &(d, c) in &g.coefficients {
                f[d] += c;
            }
        }
        f
    }

    #[test]
    fn together_the_weighted_gaps_load_both_sides_with_the_consistent_loads_of_a_uniform_traction()
    {
        for (na, nb, jitter) in CASES {
            let (xa, xb) = (
                abscissas(na, (0.0, 1.0), jitter),
                abscissas(nb, (0.0, 1.0), jitter),
            );
            let (x, a, b) = sides(&line(&xa, 0.0), &line(&xb, 0.0));
            for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
                let f = summed_coefficients(&gaps(&x, &a, &b, slave, basis), 2 * x.len());
                for (v, xv) in x.iter().enumerate() {
                    let (m, sign) = match v < xa.len() {
                        true => (hat_integral(&xa, v, (0.0, 1.0)), -1.0),
                        false => (hat_integral(&xb, v - xa.len(), (0.0, 1.0)), 1.0),
                    };
                    assert!(f[2 * v].abs() < 1e-15, "tangential load at {xv:?}");
                    assert!(
                        (f[2 * v + 1] - sign * m).abs() < 1e-9,
                        "{na}:{nb} {slave:?} {basis:?} node {v}: {} against {}",
                        f[2 * v + 1],
                        sign * m
                    );
                }
            }
        }
    }

    /// ∫ ψ_i g over the slave edges of node i, g = (b + v_b) − (a + v_a)
    /// read from both sides' piecewise linear interpolants, integrated
    /// by 2-point Gauss on the pieces between all nodes (exact): an
    /// independent reading of the weighted gap on horizontal sides.
    fn direct_weighted_gap(
        (xs_slave, xs_master): (&[f64], &[f64]),
        (v_slave, v_master): (&[f64], &[f64]),
        slave_below: bool,
        k: usize,
        basis: Basis,
    ) -> f64 {
        let interp = |xs: &[f64], v: &[f64], s: f64| -> f64 {
            (0..xs.len()).map(|j| hat(xs, j, s) * v[j]).sum()
        };
        let mut total = 0.0;
        for e in [k.checked_sub(1), Some(k)].into_iter().flatten() {
            if e + 1 >= xs_slave.len() {
                continue;
            }
            let (e0, e1) = (xs_slave[e], xs_slave[e + 1]);
            let mut cuts: Vec<f64> = xs_master
                .iter()
                .copied()
                .filter(|&s| s > e0 && s < e1)
                .collect();
            cuts.insert(0, e0);
            cuts.push(e1);
            let gp = 0.5 / 3f64.sqrt();
            for w in cuts.windows(2) {
                for t in [0.5 - gp, 0.5 + gp] {
                    let s = w[0] + t * (w[1] - w[0]);
                    let phi_k = hat(xs_slave, k, s);
                    let psi = match basis {
                        Basis::Standard => phi_k,
                        Basis::Dual => 2.0 * phi_k - (1.0 - phi_k),
                    };
                    let jump = interp(xs_master, v_master, s) - interp(xs_slave, v_slave, s);
                    let g = if slave_below { jump } else { -jump };
                    total += 0.5 * (w[1] - w[0]) * psi * g;
                }
            }
        }
        total
    }

    #[test]
    fn on_straight_sides_the_weighted_gap_is_the_integral_of_the_weighted_normal_gap() {
        for (na, nb, jitter) in CASES {
            let (xa, xb) = (
                abscissas(na, (0.0, 1.0), jitter),
                abscissas(nb, (0.0, 1.0), jitter),
            );
            let (x, a, b) = sides(&line(&xa, 0.0), &line(&xb, 0.0));
            // Normal displacements of some amplitude, and tangential ones
            // that a straight pair's gap must ignore.
            let u: Vec<f64> = (0..2 * x.len())
                .map(|d| 1e-3 * ((d as f64) * 1.7).sin())
                .collect();
            let v: Vec<f64> = (0..x.len()).map(|n| u[2 * n + 1]).collect();
            let (va, vb) = v.split_at(xa.len());
            for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
                let all = gaps(&x, &a, &b, slave, basis);
                for g in &all {
                    let direct = match slave {
                        Slave::A => direct_weighted_gap((&xa, &xb), (va, vb), true, g.node, basis),
                        Slave::B => {
                            let k = g.node - xa.len();
                            direct_weighted_gap((&xb, &xa), (vb, va), false, k, basis)
                        }
                    };
                    assert!(
                        (g.value(&u) - direct).abs() < 1e-15,
                        "{na}:{nb} {slave:?} {basis:?} node {}: {} against {direct}",
                        g.node,
                        g.value(&u)
                    );
                }
            }
        }
    }

    /// The pair through `xa`, `xb` and the displacements `u` rotated by
    /// `angle` about the origin.
    fn rotated(points: &[[f64; 2]], angle: f64) -> Vec<[f64; 2]> {
        let (s, c) = angle.sin_cos();
        points
            .iter()
            .map(|p| [c * p[0] - s * p[1], s * p[0] + c * p[1]])
            .collect()
    }

    #[test]
    fn weighted_gaps_do_not_depend_on_the_orientation_of_the_pair() {
        let (xa, xb) = (abscissas(5, (0.0, 1.0), 0.3), abscissas(8, (0.0, 1.0), 0.3));
        let (pa, pb) = (line(&xa, 0.0), line(&xb, 0.01));
        let (x, a, b) = sides(&pa, &pb);
        let u: Vec<[f64; 2]> = (0..x.len())
            .map(|n| [1e-3 * (n as f64).cos(), 1e-3 * (n as f64 * 1.3).sin()])
            .collect();
        let flat = |u: &[[f64; 2]]| u.iter().flat_map(|d| *d).collect::<Vec<f64>>();
        for basis in BASES {
            let level = gaps(&x, &a, &b, Slave::B, basis);
            let angle = 0.7;
            let (xr, ar, br) = sides(&rotated(&pa, angle), &rotated(&pb, angle));
            let turned = gaps(&xr, &ar, &br, Slave::B, basis);
            let ur = flat(&rotated(&u, angle));
            for (g, t) in level.iter().zip(&turned) {
                assert_eq!(g.node, t.node);
                let (l, r) = (g.value(&flat(&u)), t.value(&ur));
                assert!(
                    (l - r).abs() < 1e-15,
                    "{basis:?} node {}: {l} against {r}",
                    g.node
                );
            }
        }
    }

    /// Side a on the circle of radius r0 (body a inside) and b on radius
    /// r1 > r0 (body b outside), over the angles [θ0, θ1], with na and nb
    /// edges.
    fn arcs(
        r0: f64,
        r1: f64,
        (na, nb): (usize, usize),
        (t0, t1): (f64, f64),
    ) -> (Vec<[f64; 2]>, Side, Side) {
        // a runs with its body on the right: clockwise, from θ1 to θ0;
        // b likewise from θ1 to θ0 with its body (outside) on its left.
        let arc = |r: f64, n: usize| -> Vec<[f64; 2]> {
            (0..=n)
                .map(|i| {
                    let t = t1 - (t1 - t0) * i as f64 / n as f64;
                    [r * t.cos(), r * t.sin()]
                })
                .collect()
        };
        sides(&arc(r0, na), &arc(r1, nb))
    }

    #[test]
    fn rigid_motions_of_a_curved_pair_leave_its_weighted_gaps_unchanged() {
        let (x, a, b) = arcs(1.0, 1.01, (7, 17), (0.2, 1.3));
        for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
            let all = gaps(&x, &a, &b, slave, basis);
            // A translation and an infinitesimal rotation about (0.3, -2).
            let (t, theta, c) = ([0.7, -1.1], 1.0, [0.3, -2.0]);
            let u: Vec<f64> = x
                .iter()
                .flat_map(|p| [t[0] - theta * (p[1] - c[1]), t[1] + theta * (p[0] - c[0])])
                .collect();
            for g in &all {
                let change = g.value(&u) - g.initial;
                let scale: f64 = g.coefficients.iter().map(|(_, v)| v.abs()).sum::<f64>() * 3.0;
                assert!(
                    change.abs() < 1e-14 * scale,
                    "{slave:?} {basis:?} node {}: {change:e}",
                    g.node
                );
            }
        }
    }

    #[test]
    fn a_slave_node_facing_the_master_whole_has_half_its_two_chords_as_tributary_also_at_curved_ends()
     {
        // The outer arc as the slave: its abscissas are projections on the
        // inner arc, so its lengths go through the edge's Jacobian.
        let (x, a, b) = arcs(1.0, 1.05, (9, 13), (0.0, 1.2));
        for (slave, offset) in [(Slave::A, 0), (Slave::B, 10)] {
            let chain: Vec<usize> = (offset..offset + if offset == 0 { 10 } else { 14 }).collect();
            let chord = |k: usize| {
                let (p, q) = (x[chain[k]], x[chain[k + 1]]);
                (p[0] - q[0]).hypot(p[1] - q[1])
            };
            for g in gaps(&x, &a, &b, slave, Basis::Dual) {
                let k = g.node - offset;
                // The two arcs' ends face each other (the same angles): the
                // end edges face the master whole, up to curvature
                // (`to_slave_ends`), and their end nodes have half a chord.
                let left = if k > 0 { chord(k - 1) } else { 0.0 };
                let right = if k + 1 < chain.len() { chord(k) } else { 0.0 };
                let half = 0.5 * (left + right);
                assert!(
                    (g.tributary - half).abs() < 1e-14,
                    "{slave:?} node {k}: {} against {half}",
                    g.tributary
                );
            }
        }
    }

    #[test]
    fn against_a_tilted_master_the_dual_weighted_gap_is_the_gap_along_the_slave_normal_at_the_node()
    {
        // Slave a flat, master b on the line y = 0.1 + x tan α: along the
        // slave's normal the gap is linear, so the dual functions read its
        // value at each node, ∫ψ_i g = m_i g(x_i).
        for angle in [5f64, 30.0, 45.0] {
            let slope = angle.to_radians().tan();
            let xa = abscissas(7, (0.0, 1.0), 0.2);
            // b's nodes above a's range, spaced along its own line.
            let xb = abscissas(5, (0.0, 1.0), 0.3);
            let pb: Vec<[f64; 2]> = xb.iter().map(|&v| [v, 0.1 + v * slope]).collect();
            let (x, a, b) = sides(&line(&xa, 0.0), &pb);
            for g in gaps(&x, &a, &b, Slave::A, Basis::Dual) {
                let expected = 0.1 + xa[g.node] * slope;
                let read = g.initial / g.tributary;
                assert!(
                    (read - expected).abs() < 1e-13,
                    "{angle}° node {}: {read} against {expected}",
                    g.node
                );
            }
        }
    }

    #[test]
    fn a_pair_and_its_mirror_image_have_mirrored_weighted_gaps() {
        // Arcs symmetric about the y axis: the mirror x → −x maps node k of
        // a side of n + 1 nodes onto node n − k of the same side.
        let half = 0.5;
        let (t0, t1) = (FRAC_PI_2 - half, FRAC_PI_2 + half);
        for (na, nb, gap) in [(8, 8, 0.0), (8, 8, 0.01), (6, 9, 0.01), (7, 5, -0.004)] {
            let (x, a, b) = arcs(1.0, 1.0 + gap, (na, nb), (t0, t1));
            let mirror = |v: usize| {
                if v <= na {
                    na - v
                } else {
                    na + 1 + (na + 1 + nb - v)
                }
            };
            for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
                let all = gaps(&x, &a, &b, slave, basis);
                let by_node: BTreeMap<usize, &WeightedGap> =
                    all.iter().map(|g| (g.node, g)).collect();
                for g in &all {
                    let m = by_node[&mirror(g.node)];
                    let scale = g.tributary;
                    assert!((g.initial - m.initial).abs() < 1e-15 * scale.max(1.0));
                    let mirrored: BTreeMap<usize, f64> = m
                        .coefficients
                        .iter()
                        .map(|&(d, c)| (2 * mirror(d / 2) + d % 2, if d % 2 == 0 { -c } else { c }))
                        .collect();
                    for &(d, c) in &g.coefficients {
                        let other = mirrored.get(&d).copied().unwrap_or(0.0);
                        assert!(
                            (c - other).abs() < 1e-12 * scale,
                            "{na}:{nb} gap {gap} {slave:?} {basis:?} node {} DOF {d}: {c} against {other}",
                            g.node
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn on_concentric_arcs_the_weighted_gap_converges_to_their_distance_at_second_order() {
        let gap = 0.01;
        for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
            let errors: Vec<f64> = [8, 16, 32, 64]
                .iter()
                .map(|&n| {
                    let (x, a, b) = arcs(1.0, 1.0 + gap, (2 * n, 5 * n), (0.0, 1.0));
                    gaps(&x, &a, &b, slave, basis)
                        .iter()
                        .map(|g| (g.initial / g.tributary - gap).abs())
                        .fold(0.0, f64::max)
                })
                .collect();
            let rates: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
            assert!(
                rates.iter().all(|&r| (r - 2.0).abs() < 0.05),
                "{slave:?} {basis:?}: errors {errors:?}, rates {rates:?}"
            );
        }
    }

    #[test]
    fn overlapping_concentric_arcs_with_matching_angles_read_one_gap_at_every_node_ends_included() {
        // The Lamé rings' interface: each master vertex lies inside the
        // corner of the slave node at its angle, its feet on both of the
        // node's chords; either chord must see it (before: the chord it did
        // not project on read δ cos(Δθ/2)/cos Δθ, the end chords δ cos(Δθ/2):
        // a spread of δ Δθ²/4 that put the end pressures 1 % off).
        let delta = 1e-3;
        for n in [13, 26, 52] {
            let (x, a, b) = arcs(1.0 + delta, 1.0, (n, n), (0.0, FRAC_PI_2));
            for slave in SLAVES {
                let all = gaps(&x, &a, &b, slave, Basis::Dual);
                let reads: Vec<f64> = all.iter().map(|g| g.initial / g.tributary).collect();
                let (lo, hi) = reads
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(l, h), &r| (l.min(r), h.max(r)));
                assert_eq!(all.len(), n + 1);
                // What is left is the rise of the gap over the pieces of
                // length δ sin(Δθ/2) between a slave node and its vertex's
                // feet: O(δ² Δθ²); the spread was δ Δθ²/4.
                let turn = FRAC_PI_2 / n as f64;
                assert!(
                    hi - lo < 1e-2 * delta * turn * turn,
                    "{n} {slave:?}: {lo:e} .. {hi:e}"
                );
            }
        }
    }

    #[test]
    fn a_master_leg_standing_across_the_interface_at_its_start_reads_the_gap_at_its_foot() {
        // Side b an L: a leg down x = 1 from y = 1 to 0.01, then along
        // y = 0.01; side a on y = 0. Every leg vertex projects on a at
        // x = 1; the sides are 0.01 apart wherever they face each other.
        // The leg's far vertex stood for the point (node 1 read G/m = 1.0
        // with the dual weights) and a slave node at the leg's abscissa was
        // dropped (a review's cases).
        let leg = [[1.0, 1.0], [1.0, 0.5], [1.0, 0.01]];
        let cases: [(&[f64], &[f64]); 2] = [
            (&[0.0, 1.0, 2.0, 3.0], &[2.0, 3.0]),
            (&[0.0, 1.5, 3.0], &[2.5, 3.0]),
        ];
        for (xa, xb) in cases {
            let pa: Vec<[f64; 2]> = xa.iter().map(|&v| [v, 0.0]).collect();
            let mut pb = leg.to_vec();
            pb.extend(xb.iter().map(|&v| [v, 0.01]));
            let (x, a, b) = sides(&pa, &pb);
            for basis in BASES {
                for g in gaps(&x, &a, &b, Slave::A, basis) {
                    let read = g.initial / g.tributary;
                    assert!(
                        (read - 0.01).abs() < 1e-12,
                        "{xa:?} {basis:?} node {}: {read}",
                        g.node
                    );
                }
            }
        }
    }

    #[test]
    fn a_step_of_the_master_across_a_slave_edge_reads_no_overlap() {
        // Side b steps up from y = 0.01 to 0.5 at x = 1, inside a's edge
        // [0, 1.5]: the gap is at least 0.01 everywhere. The dual weights'
        // negative lobe read G/m = −0.15 at node 0 (a review's case): an
        // edge across which the gap rises that steeply takes the hats.
        let pa = [[0.0, 0.0], [1.5, 0.0], [3.0, 0.0]];
        let pb = [[0.0, 0.01], [1.0, 0.01], [1.0, 0.5], [2.0, 0.5], [3.0, 0.5]];
        let (x, a, b) = sides(&pa, &pb);
        for basis in BASES {
            for g in gaps(&x, &a, &b, Slave::A, basis) {
                let read = g.initial / g.tributary;
                assert!(read >= 0.01 - 1e-12, "{basis:?} node {}: {read}", g.node);
            }
        }
    }

    #[test]
    fn where_the_master_ends_inside_a_slave_edge_the_weighted_gaps_still_load_the_facing_part_consistently()
     {
        let (lo, hi) = (0.3, 0.8);
        let (xa, xb) = (abscissas(5, (0.0, 1.0), 0.2), abscissas(4, (lo, hi), 0.2));
        let (x, a, b) = sides(&line(&xa, 0.0), &line(&xb, 0.0));
        for (slave, basis) in SLAVES.into_iter().flat_map(|s| BASES.map(|b| (s, b))) {
            let all = gaps(&x, &a, &b, slave, basis);
            let f = summed_coefficients(&all, 2 * x.len());
            for v in 0..x.len() {
                let (m, sign) = match v < xa.len() {
                    true => (hat_integral(&xa, v, (lo, hi)), -1.0),
                    false => (hat_integral(&xb, v - xa.len(), (lo, hi)), 1.0),
                };
                assert!(
                    (f[2 * v + 1] - sign * m).abs() < 1e-9,
                    "{slave:?} {basis:?} node {v}: {} against {}",
                    f[2 * v + 1],
                    sign * m
                );
            }
            for g in &all {
                let gap = 0.02;
                let u: Vec<f64> = (0..x.len())
                    .flat_map(|n| [0.0, if n >= xa.len() { gap } else { 0.0 }])
                    .collect();
                assert!((g.value(&u) - gap * g.tributary).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn the_coarser_side_over_the_facing_part_is_the_slave() {
        let line_of = |n: usize, lo: f64, hi: f64| line(&abscissas(n, (lo, hi), 0.0), 0.0);
        // b finer than a: a is the slave, and the other way round.
        let (x, a, b) = sides(&line_of(4, 0.0, 1.0), &line_of(10, 0.0, 1.0));
        assert_eq!(coarser_side(Nodes::new(&x, 0), &a, &b).unwrap(), Slave::A);
        let (x, a, b) = sides(&line_of(10, 0.0, 1.0), &line_of(4, 0.0, 1.0));
        assert_eq!(coarser_side(Nodes::new(&x, 0), &a, &b).unwrap(), Slave::B);
        // Only the facing part counts: a has 20 edges over [0, 2] but 5
        // over the [0.5, 1] that b (3 edges) faces.
        let (x, a, b) = sides(&line_of(20, 0.0, 2.0), &line_of(3, 0.5, 1.0));
        assert_eq!(coarser_side(Nodes::new(&x, 0), &a, &b).unwrap(), Slave::B);
        let (x, a, b) = sides(&line_of(20, 0.0, 2.0), &line_of(8, 0.5, 1.0));
        assert_eq!(coarser_side(Nodes::new(&x, 0), &a, &b).unwrap(), Slave::A);
    }

    #[test]
    fn sides_that_do_not_face_each_other_are_refused_by_name() {
        let (x, a, b) = sides(&line(&[0.0, 0.5, 1.0], 0.0), &line(&[2.0, 3.0], 0.0));
        let e = weighted_gaps(Nodes::new(&x, 0), &a, &b, Slave::A, Basis::Dual).unwrap_err();
        assert!(e.to_string().contains("do not face each other"), "{e}");
    }
}
