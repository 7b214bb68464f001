//! A measured prototype of a penalty *mortar* contact formulation on the
//! Hertz meshes of docs/method.md §6.11, beside tfem's own strip of flat
//! elements (B), to tell whether an integrated gap per node would reach the
//! matching mesh's accuracy and iteration counts on non-matching interfaces.
//! Nothing here is used by the library: it assembles the bodies' tempered
//! stiffness through the public element loop (`Problem::elements`), takes
//! the loads and constraints from the model, adds the mortar penalty and
//! solves with faer's sparse Cholesky (one symbolic analysis over the
//! pattern of every candidate node, a numeric factorisation per active-set
//! iteration: no condensation, so its times are to be set beside tfem's
//! `ContactOptions::refactorize`, not beside its condensed loop).
//!
//! Formulation (frictionless, small deformation, linear elements, geometry
//! fixed at the initial configuration, as in tfem):
//!
//! * one side is the *slave* (chosen per run, both measured), the other the
//!   *master*; both are polylines sorted by x;
//! * on a slave edge with unit normal ν (the edge's own chord normal,
//!   pointing to the master; `--vertical`: ν = ±e_y instead), a slave point
//!   x_s is projected along ν onto the master polyline, x_m = x_s + t ν, and
//!   the gap is g = ν·(x_m + u_m − x_s − u_s) = t + ν·(u_m − u_s)
//!   (g < 0: penetration);
//! * the weighted gap of slave node i is G_i = ∫ φ_i g ds, φ_i its hat
//!   function on the slave polyline (`--dual`: the dual function ψ_i =
//!   2φ_i − φ_j on each edge, ∫ψ_i φ_k = δ_ik ∫φ_k, Wohlmuth's biorthogonal
//!   basis), integrated exactly: every slave edge is split at the
//!   projections (along ν) of the master nodes, so g is linear on each
//!   piece and φ_i g quadratic: 2-point Gauss is exact;
//! * G_i = G_i0 + c_iᵀ u, with c_i over slave nodes i−1, i, i+1 and the
//!   master nodes under them; m_i = ∫ φ_i ds; only nodes whose whole
//!   support faces the master are candidates (see `weighted_gaps`);
//! * energy ½ (κ/m_i) G_i² per active node, κ = E_c λ/h_c² exactly as tfem
//!   (E_c the softer body's E, λ the model size, h_c the shortest
//!   interface edge of the pair, read from tfem's own B on the same scene;
//!   `--kappa-scale s` multiplies it); pressure p_i = −κ G_i/m_i: a uniform
//!   gap g gives p = −κ g on both sides (the consistent loads of a uniform
//!   traction), so the contact patch test holds (`--patch`);
//! * active set: start, like tfem (docs/method.md §6.6), from the slave
//!   nodes whose mean initial gap G_i0/m_i is within 1e-3 h_c of the
//!   smallest; then active ⇔ G_i < 0 in the last solve, until the set
//!   stands still (a revisited set is a cycle; cap 50).
//!
//! Readings, each against p_H(x) = p₀√(1 − x²/a²): the slave's −κG_i/m_i;
//! each side's nodal contact force over its tributary (tfem's reading of
//! the block); and tfem's both-sides recovery (6.12) on the block's nodes
//! applied to the mortar forces. The interpenetration is
//! `contact::traction::max_overlap` over tfem's B for both methods.
//!
//! What it measured (docs/method.md §6.11, "A mortar prototype", has the
//! tables): the patch test passes to 1e-11 for either slave and basis;
//! with the dual basis the loop takes 7–12 iterations at the default
//! ratios 2.5, 0.4 and 1 (tfem 10–15; not fewer at 5–10×), with
//! the standard one 7–27 (it releases an overshooting first set a node or
//! two at a time); the coarse side's reading is 2× better than tfem's
//! both-sides one with the cylinder 2.5× coarser and 1.5× with it 2.5×
//! finer, but not at the matching level: its error sits at the axis node
//! and is the coarse body's own discretisation error (the same cylinder
//! mesh under a block 4× finer reads the same axis value to 0.25 % of p₀
//! as slave, 0.7 % as master), which on a matching mesh the other body's
//! opposite error cancels.
//!
//! `--schemes mortar,sampled,sampled-ls-n,sampled-ls,sampled-b` adds the
//! *strip-sampled mortar* (`mortar_probe/strip_sampled.rs`): the same
//! weighted gaps G_i written exactly as Σ_e c_ie g_e over the apex gaps
//! g_e (6.9) of the strip elements whose apex is a merged node (both sides'
//! nodes) and whose edge faces it, solved by the same loop and read the
//! same way. B lacks 24–40 % of those elements on the non-matching Hertz
//! interfaces; `sampled` synthesises them from the nodes, `sampled-ls-n`
//! writes each as a local combination of B's triangles read with one
//! normal (exact: residual ≤ 2e-14), `sampled-ls` with their own normals
//! (not exact on a curve), `sampled-b` leaves them out. Measured (dual
//! basis; each method's best reading): `sampled` and `sampled-ls-n` reach
//! the dual mortar's accuracy and iterations — 2.17e-3 against 2.14e-3
//! (tfem 4.46e-3) with the cylinder 2.5× finer at a/64, 9.0e-3 against
//! 8.7e-3 (tfem 9.55e-3) with it 2.5× coarser, 9.5e-4 matching — and
//! pass the patch test to 7e-12 of p; `sampled-b` fails it by O(p) and
//! is 3–16× worse than tfem on Hertz.
//!
//! `--schemes library` takes the weighted gaps from the library
//! (`tfem::contact::mortar::weighted_gaps`, the `sampled` scheme built
//! from the pair's two sides alone); `--contrast 100` makes the cylinder
//! 100× stiffer than the block, the stiff curved tool on which tfem's
//! strip is one-sided (docs/method.md §6.11, "Which side is the slave").
//!
//!   cargo run --release --features studies --example mortar_probe -- --dual --schemes library --contrast 100 --ratios 0.4,2.5
//!   cargo run --release --features studies --example mortar_probe
//!   cargo run --release --features studies --example mortar_probe -- --dual --schemes mortar,sampled,sampled-ls-n,sampled-ls,sampled-b
//!   cargo run --release --features studies --example mortar_probe -- --patch --dual --schemes mortar,sampled,sampled-ls-n,sampled-ls,sampled-b
//!   cargo run --release --features studies --example mortar_probe -- --dual
//!   cargo run --release --features studies --example mortar_probe -- --levels 16,32 --ratios 2.5 --profile
//!   cargo run --release --features studies --example mortar_probe -- --vertical
//!   cargo run --release --features studies --example mortar_probe -- --refactorize
//!   cargo run --release --features studies --example mortar_probe -- --patch [--dual]

use std::collections::{BTreeMap, HashSet};
use std::time::Instant;

use clap::{Parser, ValueEnum};

use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{Pair, SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Side};

use tfem::contact::ContactElement;
use tfem::contact::law::penalty_lengths;
use tfem::contact::mesh::{Nodes, Side as PairSide};
use tfem::contact::mortar::{self, Basis, Slave};
use tfem::contact::traction::max_overlap;
use tfem::element::{TriGeometry, b_hat};
use tfem::scenes::hertz::{Hertz, TAG_BLOCK_TOP, TAG_CYLINDER};
use tfem::scenes::nodes_by_x;
use tfem::scenes::patch::{PatchTest, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER};
use tfem::{ContactOptions, Mesh, Model};

#[path = "mortar_probe/strip_sampled.rs"]
mod strip_sampled;

/// How the weighted gaps G_i are built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Scheme {
    /// The probe's mortar: each slave edge split at the master nodes'
    /// projections along ν and integrated with 2-point Gauss.
    Mortar,
    /// The strip-sampled mortar (`strip_sampled`): G_i as a combination of
    /// the apex gaps of tfem's elements of B at the merged nodes (an
    /// element B lacks is synthesised from the nodes).
    Sampled,
    /// As `Sampled` with B's own elements only: a merged node B has no
    /// facing element for is interpolated from its sampled neighbours.
    SampledB,
    /// As `Sampled` with B's own elements only: a missing sample is the
    /// least-squares combination of B's elements near it.
    SampledLs,
    /// As `SampledLs`, the combined elements read with one common normal.
    SampledLsN,
    /// The library's sampled mortar weighting
    /// (`tfem::contact::mortar::weighted_gaps`): the same samples as
    /// `Sampled`, built from the pair's sides alone.
    Library,
}

/// The weighted gaps of one scheme, a label for the tables, the seconds
/// their construction took, and (sampled) a line on their make-up.
#[allow(clippy::too_many_arguments)]
fn scheme_gaps(
    scheme: Scheme,
    mesh: &Mesh,
    x: &[[f64; 2]],
    slave: &[usize],
    master: &[usize],
    slave_below: bool,
    vertical: bool,
    dual: bool,
    elements: &[ContactElement],
) -> (Vec<WeightedGap>, &'static str, f64, String) {
    let t0 = Instant::now();
    match scheme {
        Scheme::Library => {
            // Every pair of these scenes has the lower body's side as a.
            let tags = mesh_pair_tags(mesh);
            let side = |tag| PairSide::of_tag(mesh, tag).expect("side");
            let (a, b) = (side(tags.0), side(tags.1));
            let which = if slave_below { Slave::A } else { Slave::B };
            let basis = if dual { Basis::Dual } else { Basis::Standard };
            let gaps = mortar::weighted_gaps(Nodes::of(mesh), &a, &b, which, basis)
                .expect("weighted gaps")
                .into_iter()
                .map(|g| WeightedGap {
                    node: g.node,
                    m: g.tributary,
                    g0: g.initial,
                    c: g.coefficients,
                })
                .collect();
            (gaps, "library", t0.elapsed().as_secs_f64(), String::new())
        }
        Scheme::Mortar => {
            let gaps = weighted_gaps(x, slave, master, slave_below, vertical, dual);
            (gaps, "mortar", t0.elapsed().as_secs_f64(), String::new())
        }
        Scheme::Sampled | Scheme::SampledB | Scheme::SampledLs | Scheme::SampledLsN => {
            let missing = match scheme {
                Scheme::SampledB => strip_sampled::Missing::Interpolate,
                Scheme::SampledLs => strip_sampled::Missing::Combine,
                Scheme::SampledLsN => strip_sampled::Missing::CombineCommonNormal,
                _ => strip_sampled::Missing::Synthesise,
            };
            let s = strip_sampled::sampled_gaps(x, slave, master, elements, dual, missing);
            let (label, fill) = match missing {
                strip_sampled::Missing::Synthesise => ("strip-sampled", "synthesised".to_string()),
                strip_sampled::Missing::Interpolate => (
                    "strip-sampled, B only (interp.)",
                    "interpolated".to_string(),
                ),
                strip_sampled::Missing::Combine | strip_sampled::Missing::CombineCommonNormal => (
                    if missing == strip_sampled::Missing::Combine {
                        "strip-sampled, B only (comb.)"
                    } else {
                        "strip-sampled, B only (comb., one normal)"
                    },
                    format!(
                        "combined from ≤ {} of B's elements, residual ≤ {:.1e}",
                        s.combine_elements, s.combine_residual
                    ),
                ),
            };
            let info = format!(
                "{} merged-node samples from B's elements, {} not in B ({} at nodes \
                 that are no apex), {fill}; per node functional: ≤ {} samples (mean {:.2}), \
                 ≤ {} DOFs",
                s.from_b, s.synthesised, s.no_apex, s.max_elements, s.mean_elements, s.max_dofs
            );
            (s.gaps, label, t0.elapsed().as_secs_f64(), info)
        }
    }
}

/// The weighted gap of one slave node, linearised: G = g0 + Σ c[k]·u_k.
struct WeightedGap {
    /// The slave node.
    node: usize,
    /// ∫ φ_i ds over the part of its support facing the master.
    m: f64,
    /// G_i0 (initial geometry).
    g0: f64,
    /// Coefficients per global DOF (2 per node), merged.
    c: Vec<(usize, f64)>,
}

/// The tags (a, b) of the scene's only contact pair: the lower body's
/// side first (the Hertz block's top, the patch test's lower block).
fn mesh_pair_tags(mesh: &Mesh) -> (i32, i32) {
    let has = |tag: i32| mesh.boundary_edges().iter().any(|e| e.tag == tag);
    if has(TAG_BLOCK_TOP) && has(TAG_CYLINDER) {
        (TAG_BLOCK_TOP, TAG_CYLINDER)
    } else {
        (TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)
    }
}

/// The nodes of the edges tagged `tag`, sorted by x.
fn side_nodes(model: &Model, tag: i32) -> Vec<usize> {
    nodes_by_x(model.mesh().expect("mesh"), tag)
}

/// Solves [a b; c d] [x; y] = r (None when singular).
fn solve2(a: f64, b: f64, c: f64, d: f64, r: [f64; 2]) -> Option<(f64, f64)> {
    let det = a * d - b * c;
    if det.abs() < 1e-300 {
        return None;
    }
    Some(((r[0] * d - b * r[1]) / det, (a * r[1] - c * r[0]) / det))
}

/// The mortar weighted gaps of the slave polyline against the master one.
/// `slave_below`: the slave body lies below the interface (its normal
/// points up, to the master). `vertical`: project and measure along ±e_y
/// instead of the slave edge's normal. `dual`: weight G_i by the dual
/// function ψ_i instead of the hat φ_i.
fn weighted_gaps(
    x: &[[f64; 2]],
    slave: &[usize],
    master: &[usize],
    slave_below: bool,
    vertical: bool,
    dual: bool,
) -> Vec<WeightedGap> {
    let mut acc: Vec<(f64, f64, BTreeMap<usize, f64>)> =
        vec![(0.0, 0.0, BTreeMap::new()); slave.len()];
    // 2-point Gauss on [-1, 1].
    let gp = 1.0 / 3f64.sqrt();
    for k in 0..slave.len() - 1 {
        let (p, q) = (x[slave[k]], x[slave[k + 1]]);
        let d = [q[0] - p[0], q[1] - p[1]];
        let len = d[0].hypot(d[1]);
        // The chord's normal towards the master.
        let up = if slave_below { 1.0 } else { -1.0 };
        let nu = if vertical {
            [0.0, up]
        } else {
            [-d[1] / len * up, d[0] / len * up]
        };
        // Break points: the master nodes projected along ν on this edge.
        let mut xis = vec![0.0, 1.0];
        for &mnode in master {
            let r = [x[mnode][0] - p[0], x[mnode][1] - p[1]];
            // p + ξ d + t ν = x_m
            if let Some((xi, _)) = solve2(d[0], nu[0], d[1], nu[1], r) {
                if xi > 1e-12 && xi < 1.0 - 1e-12 {
                    xis.push(xi);
                }
            }
        }
        xis.sort_by(f64::total_cmp);
        // The master edge a slave point's ray along ν meets first
        // (smallest |t|): (edge index, t, η).
        let hit = |xi: f64| -> Option<(usize, f64, f64)> {
            let s = [p[0] + xi * d[0], p[1] + xi * d[1]];
            let mut best: Option<(usize, f64, f64)> = None;
            for j in 0..master.len() - 1 {
                let (m0, m1) = (x[master[j]], x[master[j + 1]]);
                let e = [m1[0] - m0[0], m1[1] - m0[1]];
                // s + t ν = m0 + η e
                let r = [m0[0] - s[0], m0[1] - s[1]];
                if let Some((t, eta)) = solve2(nu[0], -e[0], nu[1], -e[1], r) {
                    if (-1e-12..=1.0 + 1e-12).contains(&eta)
                        && best.is_none_or(|b: (usize, f64, f64)| t.abs() < b.1.abs())
                    {
                        best = Some((j, t, eta));
                    }
                }
            }
            best
        };
        for w in xis.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a < 1e-14 {
                continue;
            }
            // The piece maps into one master edge: the one its midpoint
            // meets (a piece facing nothing is outside the contact).
            let Some((j, _, _)) = hit(0.5 * (a + b)) else {
                continue;
            };
            let (m0, m1) = (x[master[j]], x[master[j + 1]]);
            let e = [m1[0] - m0[0], m1[1] - m0[1]];
            for sgn in [-1.0, 1.0] {
                let xi = 0.5 * (a + b) + sgn * gp * 0.5 * (b - a);
                let wq = 0.5 * (b - a) * len;
                let s = [p[0] + xi * d[0], p[1] + xi * d[1]];
                let r = [m0[0] - s[0], m0[1] - s[1]];
                let (t, eta) = solve2(nu[0], -e[0], nu[1], -e[1], r).expect("ray meets edge");
                // The weight of G_i: the hat φ_i (standard mortar) or its
                // dual ψ_i (∫ψ_i φ_j = δ_ij ∫φ_j on every edge: ψ = 2φ_i − φ_j).
                for (local, phi, psi) in
                    [(k, 1.0 - xi, 2.0 - 3.0 * xi), (k + 1, xi, 3.0 * xi - 1.0)]
                {
                    let entry = &mut acc[local];
                    entry.0 += wq * phi;
                    let wphi = wq * if dual { psi } else { phi };
                    entry.1 += wphi * t;
                    let terms = [
                        (master[j], wphi * (1.0 - eta)),
                        (master[j + 1], wphi * eta),
                        (slave[k], -wphi * (1.0 - xi)),
                        (slave[k + 1], -wphi * xi),
                    ];
                    for (node, coef) in terms {
                        for (c, nc) in nu.iter().enumerate() {
                            *entry.2.entry(2 * node + c).or_insert(0.0) += coef * nc;
                        }
                    }
                }
            }
        }
    }
    // Only nodes whose whole support faces the master are candidates: on a
    // partly covered support the dual ψ_i is no longer biorthogonal and,
    // having a negative lobe, can read a large open gap as a penetration
    // (measured: slave = block, 500× the load at the cylinder's far end,
    // x = 0.8R). On Hertz these nodes lie far from the contact; on the
    // patch test there are none.
    let len = |k: usize| {
        let (p, q) = (x[slave[k]], x[slave[k + 1]]);
        (q[0] - p[0]).hypot(q[1] - p[1])
    };
    slave
        .iter()
        .enumerate()
        .zip(acc)
        .filter(|((k, _), (m, _, _))| {
            let left = if *k > 0 { len(k - 1) } else { 0.0 };
            let right = if k + 1 < slave.len() { len(*k) } else { 0.0 };
            *m >= (1.0 - 1e-9) * 0.5 * (left + right)
        })
        .map(|((_, &node), (m, g0, c))| WeightedGap {
            node,
            m,
            g0,
            c: c.into_iter().filter(|(_, v)| *v != 0.0).collect(),
        })
        .collect()
}

/// A mortar solve's outcome.
struct MortarSolution {
    /// Displacements, 2 per node.
    u: Vec<f64>,
    /// Per weighted gap: G_i at convergence.
    g: Vec<f64>,
    /// Per weighted gap: active in the last solve.
    active: Vec<bool>,
    /// Solves made (the last one confirmed the set).
    iterations: usize,
    /// Active nodes in the first set.
    start: usize,
    /// Active nodes per iteration (after the solve's update).
    history: Vec<usize>,
    /// False when the loop met a cycle or the cap.
    converged: bool,
    /// Seconds: assembly + symbolic, and the whole solve.
    t_setup: f64,
    t_total: f64,
}

/// The penalty mortar solve on `model` (its bodies' tempered stiffness,
/// loads and constraints).
fn mortar_solve(model: &Model, gaps: &[WeightedGap], kappa: f64, h_c: f64) -> MortarSolution {
    let t0 = Instant::now();
    let mesh = model.mesh().expect("mesh");
    let n = 2 * mesh.nodes().len();
    let fixed: BTreeMap<usize, f64> = model.constraints().collect();
    let mut free = vec![usize::MAX; n];
    let mut nf = 0;
    for (g, f) in free.iter_mut().enumerate() {
        if !fixed.contains_key(&g) {
            *f = nf;
            nf += 1;
        }
    }
    let mut u_fixed = vec![0.0; n];
    for (&g, &v) in &fixed {
        u_fixed[g] = v;
    }
    let f_ext = model.load_vector().expect("loads");
    // Lower triangle of the free-free block; the free-fixed part goes to
    // the right-hand side.
    let mut idx: Vec<Pair<usize, usize>> = Vec::new();
    let mut val: Vec<f64> = Vec::new();
    let mut rhs_b: Vec<f64> = vec![0.0; nf];
    for g in 0..n {
        if free[g] != usize::MAX {
            rhs_b[free[g]] += f_ext[g];
        }
    }
    let elements = model.problem().elements().expect("elements");
    elements
        .for_each(|el| {
            let ke = elements.stiffness(el)?;
            let dofs: [usize; 6] = std::array::from_fn(|a| 2 * el.nodes[a / 2] + a % 2);
            for a in 0..6 {
                let fa = free[dofs[a]];
                if fa == usize::MAX {
                    continue;
                }
                for b in 0..6 {
                    let fb = free[dofs[b]];
                    if fb == usize::MAX {
                        rhs_b[fa] -= ke[6 * a + b] * u_fixed[dofs[b]];
                    } else if fa >= fb {
                        idx.push(Pair { row: fa, col: fb });
                        val.push(ke[6 * a + b]);
                    }
                }
            }
            Ok(())
        })
        .expect("stiffness");
    let n_body = val.len();
    // Every weighted gap's pattern, zero while inactive: one symbolic
    // analysis serves every active set.
    let mut slots: Vec<Vec<(usize, f64)>> = Vec::with_capacity(gaps.len());
    for wg in gaps {
        let mut s = Vec::new();
        for &(ga, ca) in &wg.c {
            let fa = free[ga];
            if fa == usize::MAX {
                continue;
            }
            for &(gb, cb) in &wg.c {
                let fb = free[gb];
                if fb != usize::MAX && fa >= fb {
                    s.push((val.len(), (kappa / wg.m) * ca * cb));
                    idx.push(Pair { row: fa, col: fb });
                    val.push(0.0);
                }
            }
        }
        slots.push(s);
    }
    let (symbolic, argsort) =
        SymbolicSparseColMat::try_new_from_indices(nf, nf, &idx).expect("pattern");
    let sym_llt = SymbolicLlt::try_new(symbolic.as_ref(), Side::Lower).expect("symbolic");
    let t_setup = t0.elapsed().as_secs_f64();
    // The first set: the smallest mean initial gaps (docs/method.md §6.6).
    let mean: Vec<f64> = gaps.iter().map(|w| w.g0 / w.m).collect();
    let lo = mean.iter().copied().fold(f64::INFINITY, f64::min);
    let mut active: Vec<bool> = mean.iter().map(|&m| m <= lo + 1e-3 * h_c).collect();
    let start = active.iter().filter(|&&v| v).count();
    let mut seen: HashSet<Vec<bool>> = HashSet::new();
    let mut history = Vec::new();
    let mut u = vec![0.0; n];
    let mut g = vec![0.0; gaps.len()];
    let mut converged = false;
    let mut iterations = 0;
    for it in 1..=50 {
        iterations = it;
        seen.insert(active.clone());
        val[n_body..].iter_mut().for_each(|v| *v = 0.0);
        let mut rhs = rhs_b.clone();
        for ((wg, s), &on) in gaps.iter().zip(&slots).zip(&active) {
            if !on {
                continue;
            }
            for &(slot, v) in s {
                val[slot] += v;
            }
            // −(κ/m) (G0 + c_fixed·u_fixed) c_free
            let g_fixed: f64 = wg.g0
                + wg.c
                    .iter()
                    .filter(|(gd, _)| free[*gd] == usize::MAX)
                    .map(|(gd, c)| c * u_fixed[*gd])
                    .sum::<f64>();
            for &(gd, c) in &wg.c {
                if free[gd] != usize::MAX {
                    rhs[free[gd]] -= (kappa / wg.m) * g_fixed * c;
                }
            }
        }
        let k = SparseColMat::new_from_argsort(symbolic.clone(), &argsort, &val).expect("matrix");
        let llt = Llt::try_new_with_symbolic(sym_llt.clone(), k.as_ref(), Side::Lower)
            .expect("Cholesky (a free body?)");
        let mut x = rhs.clone();
        llt.solve_in_place_with_conj(Conj::No, MatMut::from_column_major_slice_mut(&mut x, nf, 1));
        for gd in 0..n {
            u[gd] = if free[gd] == usize::MAX {
                u_fixed[gd]
            } else {
                x[free[gd]]
            };
        }
        for (gi, wg) in g.iter_mut().zip(gaps) {
            *gi = wg.g0 + wg.c.iter().map(|(gd, c)| c * u[*gd]).sum::<f64>();
        }
        let next: Vec<bool> = g.iter().map(|&v| v < 0.0).collect();
        history.push(next.iter().filter(|&&a| a).count());
        if next == active {
            converged = true;
            break;
        }
        if seen.contains(&next) {
            active = next;
            break;
        }
        active = next;
    }
    MortarSolution {
        u,
        g,
        active,
        iterations,
        start,
        history,
        converged,
        t_setup,
        t_total: t0.elapsed().as_secs_f64(),
    }
}

/// Least-squares fit of p² = p₀²(1 − x²/a²) to (x, p) with p > 0, |x| ≤ xmax.
fn fit(p: &[(f64, f64)], xmax: f64) -> (f64, f64) {
    let pts: Vec<(f64, f64)> = p
        .iter()
        .filter(|(x, q)| *q > 0.0 && x.abs() <= xmax)
        .map(|(x, q)| (x * x, q * q))
        .collect();
    if pts.len() < 3 {
        return (f64::NAN, f64::NAN);
    }
    let nn = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |s, q| (s.0 + q.0 / nn, s.1 + q.1 / nn));
    let sxx: f64 = pts.iter().map(|q| (q.0 - mx) * (q.0 - mx)).sum();
    let sxy: f64 = pts.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    ((intercept / -slope).sqrt(), intercept.sqrt())
}

/// Largest |p − p_H(x)|/p₀ over |x| ≤ 0.8a, and the signed error at x = 0.
fn hertz_errors(p: &[(f64, f64)], a: f64, p0: f64) -> (f64, f64) {
    let inner = p
        .iter()
        .filter(|(x, _)| x.abs() <= 0.8 * a)
        .map(|(x, q)| (q - p0 * (1.0 - x * x / (a * a)).sqrt()).abs() / p0)
        .fold(0.0, f64::max);
    let axis = p
        .iter()
        .find(|(x, _)| *x == 0.0)
        .map_or(f64::NAN, |(_, q)| (q - p0) / p0);
    (inner, axis)
}

/// Normal pressure on the nodes of one side (`nodes`, sorted by x): the
/// mortar forces on each node over its tributary (half its edges'
/// lengths), (x, p) sorted by x: the reading tfem's `HertzScene::measure`
/// makes of the block (force over tributary).
fn force_pressure(
    x: &[[f64; 2]],
    nodes: &[usize],
    gaps: &[WeightedGap],
    sol: &MortarSolution,
    kappa: f64,
) -> Vec<(f64, f64)> {
    let mut force: BTreeMap<usize, [f64; 2]> = BTreeMap::new();
    for ((wg, &gi), &on) in gaps.iter().zip(&sol.g).zip(&sol.active) {
        if !on {
            continue;
        }
        let lam = -kappa * gi / wg.m;
        for &(gd, c) in &wg.c {
            force.entry(gd / 2).or_insert([0.0; 2])[gd % 2] += lam * c;
        }
    }
    nodes
        .iter()
        .enumerate()
        .map(|(k, &v)| {
            let len = |a: usize, b: usize| (x[a][0] - x[b][0]).hypot(x[a][1] - x[b][1]);
            let mut trib = 0.0;
            if k > 0 {
                trib += 0.5 * len(v, nodes[k - 1]);
            }
            if k + 1 < nodes.len() {
                trib += 0.5 * len(v, nodes[k + 1]);
            }
            let f = force.get(&v).copied().unwrap_or([0.0; 2]);
            (x[v][0], f[0].hypot(f[1]) / trib)
        })
        .collect()
}

/// Tributary length of each node of a polyline (half its edges).
fn tributaries(x: &[[f64; 2]], nodes: &[usize]) -> Vec<f64> {
    let len = |a: usize, b: usize| (x[a][0] - x[b][0]).hypot(x[a][1] - x[b][1]);
    (0..nodes.len())
        .map(|k| {
            let left = if k > 0 {
                len(nodes[k], nodes[k - 1])
            } else {
                0.0
            };
            let right = if k + 1 < nodes.len() {
                len(nodes[k], nodes[k + 1])
            } else {
                0.0
            };
            0.5 * (left + right)
        })
        .collect()
}

/// The hat function of node k of a polyline sorted by x, evaluated at
/// abscissa `s` (the interface is a graph over x here).
fn hat(xs: &[f64], k: usize, s: f64) -> f64 {
    if k > 0 && s >= xs[k - 1] && s <= xs[k] {
        (s - xs[k - 1]) / (xs[k] - xs[k - 1])
    } else if k + 1 < xs.len() && s >= xs[k] && s <= xs[k + 1] {
        (xs[k + 1] - s) / (xs[k + 1] - xs[k])
    } else if s == xs[k] {
        1.0
    } else {
        0.0
    }
}

/// tfem's both-sides reading (docs/method.md (6.12)) applied to the mortar
/// forces, on the nodes of side `own`: p_i = ½ (p_i^own + Σ_j w_ij F_j /
/// Σ_j w_ij m_j), j over the other side's nodes, F_j = p_j m_j,
/// w_ij = φ_j(x_i) + φ_i(x_j) (hats over x). The same recovery as tfem's
/// "both sides" column, so that the two methods are read alike.
fn both_sides(
    x: &[[f64; 2]],
    own: &[usize],
    p_own: &[(f64, f64)],
    other: &[usize],
    p_other: &[(f64, f64)],
) -> Vec<(f64, f64)> {
    let xo: Vec<f64> = own.iter().map(|&v| x[v][0]).collect();
    let xt: Vec<f64> = other.iter().map(|&v| x[v][0]).collect();
    let mt = tributaries(x, other);
    (0..own.len())
        .map(|i| {
            let (mut num, mut den) = (0.0, 0.0);
            for j in 0..other.len() {
                let w = hat(&xt, j, xo[i]) + hat(&xo, i, xt[j]);
                if w > 0.0 {
                    num += w * p_other[j].1 * mt[j];
                    den += w * mt[j];
                }
            }
            let p = if den > 0.0 {
                0.5 * (p_own[i].1 + num / den)
            } else {
                p_own[i].1
            };
            (xo[i], p)
        })
        .collect()
}

/// One row of the Hertz table: a pressure reading's errors.
#[allow(clippy::too_many_arguments)]
fn row(
    method: &str,
    reading: &str,
    iterations: &str,
    p: &[(f64, f64)],
    a: f64,
    p0: f64,
    overlap: f64,
    time: &str,
) {
    let (inner, axis) = hertz_errors(p, a, p0);
    let (fa, fp) = fit(p, 0.8 * a);
    println!(
        "| {method} | {reading} | {iterations} | {inner:.2e} | {axis:+.2e} | {:+.2e} | {:+.2e} | {overlap:.2e} | {time} |",
        (fp - p0) / p0,
        (fa - a) / a,
    );
}

/// How a Hertz case is run.
#[derive(Clone, Copy)]
struct Setup<'a> {
    /// The weighted-gap schemes to run beside tfem.
    schemes: &'a [Scheme],
    vertical: bool,
    dual: bool,
    refactorize: bool,
    profile: bool,
    /// κ over tfem's E_c λ/h_c².
    kappa_scale: f64,
}

fn hertz_case(hz: &Hertz, setup: Setup<'_>) {
    let Setup {
        schemes,
        vertical,
        dual,
        refactorize,
        profile,
        kappa_scale,
    } = setup;
    let a = hz.half_width;
    let mut scene = hz.build().expect("scene");
    // tfem's own solve on the same scene, timed alone.
    let options = ContactOptions {
        refactorize,
        ..Default::default()
    };
    let t0 = Instant::now();
    let report = scene.model.solve_contact(&options).expect("tfem solve");
    let t_tfem = t0.elapsed().as_secs_f64();
    let r = scene.measure(hz, report).expect("measure");
    let mesh = scene.model.mesh().expect("mesh").clone();
    let x = mesh.nodes();
    let elements = scene.model.contact_elements().expect("B").to_vec();
    let disp_t = scene.model.displacements().expect("u");
    // The actual interpenetration, node against the other side's edge
    // (the same measure for both methods).
    let overlap_tfem = max_overlap(Nodes::of(&mesh), &elements, |v| disp_t[v]);
    // κ = E_c λ/h_c² exactly as tfem's: h_c its pair's penalty length.
    let h_c = penalty_lengths(&elements)[&0];
    let e_c = scene
        .model
        .material(1)
        .expect("block")
        .young()
        .min(scene.model.material(2).expect("cylinder").young());
    let lambda = mesh.size();
    let kappa = kappa_scale * e_c * lambda / (h_c * h_c);
    let p0 = r.p0_exact;
    let it = r.report.iterations.to_string();
    let t = format!("{t_tfem:.3}");
    let tfem = format!("tfem ({} unknowns)", r.report.info.unknowns);
    row(
        &tfem,
        "block's own",
        &it,
        &r.pressure,
        a,
        p0,
        overlap_tfem,
        &t,
    );
    row(
        &tfem,
        "both sides",
        &it,
        &r.interface_pressure,
        a,
        p0,
        overlap_tfem,
        &t,
    );
    let block = side_nodes(&scene.model, TAG_BLOCK_TOP);
    let cylinder = side_nodes(&scene.model, TAG_CYLINDER);
    for (slave_is_block, &scheme) in [true, false]
        .into_iter()
        .flat_map(|s| schemes.iter().map(move |m| (s, m)))
    {
        let (slave, master) = if slave_is_block {
            (&block, &cylinder)
        } else {
            (&cylinder, &block)
        };
        let (gaps, label, t_gaps, info) = scheme_gaps(
            scheme,
            &mesh,
            x,
            slave,
            master,
            slave_is_block,
            vertical,
            dual,
            &elements,
        );
        let sol = mortar_solve(&scene.model, &gaps, kappa, h_c);
        // p_i = −κ G_i/m_i: the nodal values of the multiplier field.
        let p_slave: Vec<(f64, f64)> = gaps
            .iter()
            .zip(&sol.g)
            .zip(&sol.active)
            .map(|((wg, &gi), &on)| (x[wg.node][0], if on { -kappa * gi / wg.m } else { 0.0 }))
            .collect();
        // Force over tributary on either side (tfem's reading of the block).
        let p_master = force_pressure(x, master, &gaps, &sol, kappa);
        let p_slave_f = force_pressure(x, slave, &gaps, &sol, kappa);
        let disp: Vec<[f64; 2]> = (0..x.len())
            .map(|v| [sol.u[2 * v], sol.u[2 * v + 1]])
            .collect();
        let overlap = max_overlap(Nodes::of(&mesh), &elements, |v| disp[v]);
        let total: f64 = gaps
            .iter()
            .zip(&p_slave)
            .map(|(wg, (_, p))| p * wg.m)
            .sum::<f64>()
            / (0.5 * scene.load);
        let (sname, mname) = if slave_is_block {
            ("block", "cylinder")
        } else {
            ("cylinder", "block")
        };
        let method = format!("{label}, slave = {sname}");
        let it = format!(
            "{}{}",
            sol.iterations,
            if sol.converged { "" } else { " NOT CONVERGED" }
        );
        let t = format!(
            "{:.3} (setup {:.3}, gaps {:.4})",
            sol.t_total, sol.t_setup, t_gaps
        );
        let reading = format!("{sname} (slave): −κG/m");
        row(&method, &reading, &it, &p_slave, a, p0, overlap, &t);
        let reading = format!("{sname} (slave): force/tributary");
        row(&method, &reading, &it, &p_slave_f, a, p0, overlap, &t);
        let reading = format!("{mname} (master): force/tributary");
        row(&method, &reading, &it, &p_master, a, p0, overlap, &t);
        let p_block_both = if slave_is_block {
            both_sides(x, slave, &p_slave_f, master, &p_master)
        } else {
            both_sides(x, master, &p_master, slave, &p_slave_f)
        };
        let reading = "block: both sides (6.12)";
        row(&method, reading, &it, &p_block_both, a, p0, overlap, &t);
        eprintln!(
            "    {method}: start {} active, after each solve {:?}; Σ p m / (P/2) = {:.6}",
            sol.start, sol.history, total
        );
        if !info.is_empty() {
            println!("    {method}: {info}");
        }
        if profile {
            let ph = |x: f64| p0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt();
            for (k, (xs, p)) in p_slave
                .iter()
                .enumerate()
                .filter(|(_, (xs, _))| *xs <= 1.2 * a)
            {
                eprintln!(
                    "      slave x/a {:.4} p_H/p0 {:.4} −κG/m {:.4} force/trib {:.4}",
                    xs / a,
                    ph(*xs) / p0,
                    p / p0,
                    p_slave_f[k].1 / p0
                );
            }
            for (xs, p) in p_master.iter().filter(|(xs, _)| *xs <= 1.2 * a) {
                eprintln!(
                    "      master x/a {:.4} p_H/p0 {:.4} force/trib {:.4}",
                    xs / a,
                    ph(*xs) / p0,
                    p / p0
                );
            }
        }
    }
    if profile {
        eprintln!("    tfem history {:?}", r.report.history);
    }
}

/// Largest error of the stress over p in any triangle of the patch test's
/// mesh with displacements `u` (2 per node): σ_yy = −p, σ_xx = σ_xy = 0
/// everywhere (tempering inactive on these well-shaped elements: J ≥ Jmin).
fn patch_stress_error(model: &Model, u: &[f64], p: f64) -> f64 {
    let mesh = model.mesh().expect("mesh");
    let mut serr: f64 = 0.0;
    for (tri, &body) in mesh.triangles().iter().zip(mesh.body_of()) {
        let geo = TriGeometry::new(&mesh.corners(tri));
        let b = b_hat(&geo);
        let ue: [f64; 6] = std::array::from_fn(|k| u[2 * tri[k / 2] + k % 2]);
        let eps: [f64; 3] =
            std::array::from_fn(|r| (0..6).map(|c| b[r][c] * ue[c]).sum::<f64>() / geo.j);
        let d = model.material(body).unwrap().d_matrix();
        let s: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| d[r][c] * eps[c]).sum());
        serr = serr
            .max(s[0].abs() / p)
            .max((s[1] + p).abs() / p)
            .max(s[2].abs() / p);
    }
    serr
}

fn patch_case(test: &PatchTest, schemes: &[Scheme], vertical: bool, dual: bool) {
    let mut scene = test.build().expect("patch scene");
    let t0 = Instant::now();
    let report = scene
        .model
        .solve_contact(&ContactOptions::default())
        .expect("tfem");
    let t_tfem = t0.elapsed().as_secs_f64();
    let mesh = scene.model.mesh().expect("mesh").clone();
    let x = mesh.nodes();
    let elements = scene.model.contact_elements().expect("B").to_vec();
    let h_c = penalty_lengths(&elements)[&0];
    let e_c = test.e_lower.min(test.e_upper);
    let kappa = e_c * mesh.size() / (h_c * h_c);
    let u_tfem: Vec<f64> = scene
        .model
        .displacements()
        .expect("u")
        .iter()
        .flat_map(|d| [d[0], d[1]])
        .collect();
    let lower = side_nodes(&scene.model, TAG_CONTACT_LOWER);
    let upper = side_nodes(&scene.model, TAG_CONTACT_UPPER);
    // tfem's nodal pressures (both sides' reading) on the interface nodes.
    let p_nodes = scene
        .model
        .contact_nodal_pressures()
        .expect("nodal pressures");
    let p_tfem = lower
        .iter()
        .chain(&upper)
        .map(|&v| (p_nodes[v] - test.p).abs() / test.p)
        .fold(0.0, f64::max);
    let mesh_name = format!(
        "{} × {} cells, jitter {}",
        scene.cells.0, scene.cells.1, test.jitter
    );
    let active_tfem = scene.model.contact_active().expect("active");
    println!(
        "| {mesh_name} | tfem's strip | – | {} | {}/{} | {p_tfem:.2e} | {:.2e} | {t_tfem:.4} |",
        report.iterations,
        active_tfem.iter().filter(|&&v| v).count(),
        active_tfem.len(),
        patch_stress_error(&scene.model, &u_tfem, test.p),
    );
    for (slave_is_lower, &scheme) in [true, false]
        .into_iter()
        .flat_map(|s| schemes.iter().map(move |m| (s, m)))
    {
        let (slave, master) = if slave_is_lower {
            (&lower, &upper)
        } else {
            (&upper, &lower)
        };
        let (gaps, label, _, info) = scheme_gaps(
            scheme,
            &mesh,
            x,
            slave,
            master,
            slave_is_lower,
            vertical,
            dual,
            &elements,
        );
        let sol = mortar_solve(&scene.model, &gaps, kappa, h_c);
        let perr = gaps
            .iter()
            .zip(&sol.g)
            .map(|(wg, gi)| (-kappa * gi / wg.m - test.p).abs() / test.p)
            .fold(0.0, f64::max);
        println!(
            "| {mesh_name} | {label} | {} | {}{} | {}/{} | {perr:.2e} | {:.2e} | {:.4} |",
            if slave_is_lower { "lower" } else { "upper" },
            sol.iterations,
            if sol.converged { "" } else { " NOT CONVERGED" },
            sol.active.iter().filter(|&&v| v).count(),
            gaps.len(),
            patch_stress_error(&scene.model, &sol.u, test.p),
            sol.t_total,
        );
        if !info.is_empty() {
            eprintln!("    {mesh_name}, {label}, slave {slave_is_lower}: {info}");
        }
    }
}

/// A penalty-mortar prototype beside tfem's strip on the Hertz meshes.
#[derive(Parser, Debug)]
struct Args {
    /// Element sizes at the contact, as a/h (comma-separated).
    #[arg(long, value_delimiter = ',', default_values_t = [16.0, 32.0, 64.0])]
    levels: Vec<f64>,
    /// The cylinder's element size over the block's (comma-separated).
    #[arg(long, value_delimiter = ',', default_values_t = [2.5, 0.4, 1.0])]
    ratios: Vec<f64>,
    /// Project and measure the gap along ±e_y instead of the slave edge's normal.
    #[arg(long)]
    vertical: bool,
    /// Time tfem with `ContactOptions::refactorize` (a factorisation per iteration).
    #[arg(long)]
    refactorize: bool,
    /// Run the contact patch test instead of Hertz.
    #[arg(long)]
    patch: bool,
    /// Print the mortar pressures node by node.
    #[arg(long)]
    profile: bool,
    /// Weigh the gaps with the dual (biorthogonal) functions ψ_i.
    #[arg(long)]
    dual: bool,
    /// Multiply the penalty κ by this factor.
    #[arg(long, default_value_t = 1.0)]
    kappa_scale: f64,
    /// The cylinder's Young's modulus over the block's (100: a stiff
    /// curved tool, whose non-matching contact tfem's strip makes
    /// one-sided, docs/method.md §6.11).
    #[arg(long, default_value_t = 1.0)]
    contrast: f64,
    /// The weighted-gap schemes to run beside tfem's strip
    /// (comma-separated): the probe's mortar and/or the strip-sampled one.
    #[arg(long, value_delimiter = ',', default_value = "mortar")]
    schemes: Vec<Scheme>,
}

fn main() {
    let Args {
        levels,
        ratios,
        vertical,
        refactorize,
        patch,
        profile,
        dual,
        kappa_scale,
        contrast,
        schemes,
    } = Args::parse();
    if patch {
        println!(
            "| mesh | scheme | slave | iterations | active | max |p_i − p|/p | max stress error / p | time [s] |"
        );
        println!("|---|---|---|---|---|---|---|---|");
        for (ratio, jitter) in [
            (1.5, 0.0),
            (2.0 / 3.0, 0.0),
            (1.5, 0.3),
            (2.0 / 3.0, 0.3),
            (7.0 / 3.0, 0.3),
            (3.0 / 7.0, 0.3),
        ] {
            for level in [8.0, 32.0] {
                let test = PatchTest {
                    mesh_size: 1.0 / level,
                    ratio,
                    jitter,
                    ..Default::default()
                };
                patch_case(&test, &schemes, vertical, dual);
            }
        }
        return;
    }
    let setup = Setup {
        schemes: &schemes,
        vertical,
        dual,
        refactorize,
        profile,
        kappa_scale,
    };
    println!(
        "κ = {kappa_scale} × E_c λ/h_c²; projection and gap direction: {}; weights of G_i: {}",
        if vertical {
            "vertical (±e_y)"
        } else {
            "slave edge normal"
        },
        if dual {
            "dual ψ_i"
        } else {
            "standard hats φ_i"
        }
    );
    for &ratio in &ratios {
        for &level in &levels {
            let base = Hertz::default();
            let hz = Hertz {
                mesh_size: base.half_width / level,
                cylinder_mesh_ratio: ratio,
                e_cylinder: contrast * base.e_block,
                ..base
            };
            println!("\ncylinder_mesh_ratio {ratio}, h = a/{level}");
            println!(
                "| method | reading | iterations | max err in 0.8a | axis err | p0 fit err | a fit err | max overlap | time [s] |"
            );
            println!("|---|---|---|---|---|---|---|---|---|");
            hertz_case(&hz, setup);
        }
    }
}
