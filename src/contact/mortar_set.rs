//! The weighted gaps of the mortar weighting in one solve (docs/method.md
//! §6.11): each slave node's penalty over the unknowns, the set a loop
//! starts from, the verdict on a solution and the state it settles in.
//!
//! Slave node i carries G_i = G_i⁰ + c_i·u ([`WeightedGap`]) and, while
//! active, the penalty energy ½ (κ/m_i) G_i²: the rank-one stiffness
//! (κ/m_i) c_i c_iᵀ and the load −(κ/m_i) G_i⁰ c_i on the free unknowns (G_i⁰
//! the gap with the free unknowns at rest: the initial one plus the
//! prescribed motion). κ = E_c λ_c / h_c² per pair, the strip's penalty
//! (`contact::law::contact_jmins`), so both weightings penalise a uniform
//! gap alike. A node is active where G_i < 0.

use std::collections::BTreeMap;

use super::mesh::Side;
use super::mortar::{Slave, SlaveNode, WeightedGap};
use super::{ContactLaw, ContactOptions, ContactPair, InversionTest};
use crate::error::{Error, Result, ensure_finite};
use crate::fem::mesh::Mesh;

/// The weighted gaps of one pair.
#[derive(Debug, Clone, PartialEq)]
pub struct PairGaps {
    /// The pair's index.
    pub pair: usize,
    /// Its slave side.
    pub slave: Slave,
    /// Its slave nodes' weighted gaps.
    pub gaps: Vec<WeightedGap>,
}

/// Triangles whose node cliques cover the couplings of every weighted gap
/// of `all`, for the matrix pattern: (n₀, n_j, n_k) over the gap's nodes.
pub fn cliques(all: &[PairGaps]) -> Vec<[usize; 3]> {
    let mut tris = Vec::new();
    for wg in all.iter().flat_map(|p| &p.gaps) {
        let mut nodes: Vec<usize> = wg.coefficients.iter().map(|&(g, _)| g / 2).collect();
        nodes.dedup();
        let Some(&n0) = nodes.first() else { continue };
        if nodes.len() < 3 {
            tris.push([n0, nodes[nodes.len() - 1], n0]);
        }
        for j in 1..nodes.len() {
            for k in j + 1..nodes.len() {
                tris.push([n0, nodes[j], nodes[k]]);
            }
        }
    }
    tris
}

/// Refuses solve options the mortar weighting does not serve, naming the
/// first pair of `pairs` it weights: its gaps are frictionless (the stick
/// law needs B) and it activates a node on its linearised weighted gap
/// (the literal test needs B). Friction and own meshes are refused where
/// they are set ([`super::discretisation::serves`]).
pub fn check_options(
    options: &ContactOptions,
    mut pairs: impl Iterator<Item = usize>,
) -> Result<()> {
    let what = match (options.law, options.test) {
        (ContactLaw::Stick, _) => "is frictionless: the stick law (a tied interface)",
        (_, InversionTest::Literal) => {
            "activates a slave node on its linearised weighted gap: the literal inversion test"
        }
        _ => return Ok(()),
    };
    let pair = pairs
        .next()
        .map_or(String::new(), |i| format!("contact pair {i}: "));
    Err(Error::argument(format!(
        "{pair}the mortar weighting (the automatic choice where curved sides' nodes do not \
         match) {what} needs the elements of B: set the strip weighting"
    )))
}

/// One slave node's penalty over the unknowns.
#[derive(Debug, Clone)]
struct Penalty {
    /// Index of its pair.
    pair: usize,
    /// The slave node, its tributary m_i and κ/m_i.
    node: usize,
    tributary: f64,
    stiffness: f64,
    /// G_i⁰: the gap with the free unknowns at rest.
    g_rest: f64,
    /// Each coefficient's global DOF, its unknown (`None` when
    /// prescribed) and its value.
    dofs: Vec<usize>,
    unknowns: Vec<Option<usize>>,
    coef: Vec<f64>,
    /// (κ/m_i) c cᵀ, row-major.
    matrix: Vec<f64>,
    /// −(κ/m_i) G_i⁰ c on the free unknowns (0 on prescribed ones).
    load: Vec<f64>,
    /// The part of `load` of the initial gap, −(κ/m_i) G_i(0) c: what does
    /// not scale with a load step's factor.
    gap_load: Vec<f64>,
}

/// The share of the size of a weighted gap's terms within which its sign
/// is round-off ([`MortarSet::verdict`]): a solve's relative accuracy with
/// a margin of 1e4.
pub const UNDECIDED: f64 = 1e-12;

impl Penalty {
    /// G_i for the free unknowns' values read by `value`, and the size of
    /// its terms |G_i⁰| + Σ |c_j u_j|.
    fn gap_and_size(&self, value: impl Fn(usize) -> f64) -> (f64, f64) {
        let (mut gap, mut size) = (self.g_rest, self.g_rest.abs());
        for (u, c) in self.unknowns.iter().zip(&self.coef) {
            if let Some(j) = u {
                let term = c * value(*j);
                gap += term;
                size += term.abs();
            }
        }
        (gap, size)
    }

    /// G_i for the free unknowns' values read by `value`.
    fn gap(&self, value: impl Fn(usize) -> f64) -> f64 {
        self.g_rest
            + self
                .unknowns
                .iter()
                .zip(&self.coef)
                .filter_map(|(u, c)| u.map(|j| c * value(j)))
                .sum::<f64>()
    }
}

/// The weighted gaps of the mortar pairs in one solve, as penalties over
/// the unknowns.
#[derive(Debug, Clone, Default)]
pub struct MortarSet {
    penalties: Vec<Penalty>,
    /// The weighted gaps they are of, pair by pair, in the penalties'
    /// order (for the outputs).
    gaps: Vec<PairGaps>,
    /// h_c of each pair that has one.
    h_c: BTreeMap<usize, f64>,
}

/// What the penalties of [`MortarSet::new`] are made of besides the gaps:
/// each pair's E_c, λ_c and h_c, how a global DOF is numbered, and the
/// prescribed values.
pub struct PenaltyData<'d> {
    /// E_c of every pair.
    pub moduli: &'d [f64],
    /// λ_c.
    pub lambda: f64,
    /// The penalty length h_c of each pair (`contact::law::penalty_lengths`).
    pub h_c: BTreeMap<usize, f64>,
    /// The unknown of global DOF g (`None`: prescribed).
    pub equation: &'d dyn Fn(usize) -> Option<usize>,
    /// Prescribed displacements, a global vector.
    pub prescribed: &'d [f64],
}

impl MortarSet {
    /// The penalties of the weighted gaps `gaps`: κ = E_c λ_c/h_c² per pair
    /// (refused, naming the pair, when not a positive finite number).
    pub fn new(gaps: &[PairGaps], data: PenaltyData<'_>) -> Result<MortarSet> {
        let mut penalties = Vec::new();
        for pg in gaps {
            let h = data.h_c.get(&pg.pair).copied().unwrap_or(f64::NAN);
            let modulus = data.moduli[pg.pair];
            let kappa = modulus * data.lambda / (h * h);
            if !(kappa.is_finite() && kappa > 0.0) {
                return Err(Error::contact(format!(
                    "contact pair {}: the mortar penalty κ = E_c λ/h_c² = {kappa:e} is not a \
                     positive finite number (E_c {modulus:e}, λ {:e}, h_c {h:e})",
                    pg.pair, data.lambda
                )));
            }
            for wg in &pg.gaps {
                penalties.push(penalty(pg.pair, wg, kappa, &data));
            }
        }
        Ok(MortarSet {
            penalties,
            gaps: gaps.to_vec(),
            h_c: data.h_c,
        })
    }

    /// Number of penalties (slave nodes).
    pub fn len(&self) -> usize {
        self.penalties.len()
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.penalties.is_empty()
    }

    /// The unknowns of penalty `k`'s coefficients (`None`: prescribed).
    pub fn unknowns(&self, k: usize) -> &[Option<usize>] {
        &self.penalties[k].unknowns
    }

    /// Its matrix (κ/m_i) c cᵀ, row-major.
    pub fn matrix(&self, k: usize) -> &[f64] {
        &self.penalties[k].matrix
    }

    /// Its load when on.
    pub fn load(&self, k: usize) -> &[f64] {
        &self.penalties[k].load
    }

    /// Its initial gap's load.
    pub fn gap_load(&self, k: usize) -> &[f64] {
        &self.penalties[k].gap_load
    }

    /// The global DOFs of its coefficients.
    pub fn dofs(&self, k: usize) -> &[usize] {
        &self.penalties[k].dofs
    }

    /// The first set: in each pair, the slave nodes whose mean gap at rest
    /// G_i⁰/m_i is within 1e-3 h_c of the pair's smallest (docs/method.md
    /// §6.6, as the strip's).
    pub fn initial_active(&self) -> Vec<bool> {
        let mut lowest: BTreeMap<usize, f64> = BTreeMap::new();
        for p in &self.penalties {
            let m = lowest.entry(p.pair).or_insert(f64::INFINITY);
            *m = m.min(p.g_rest / p.tributary);
        }
        self.penalties
            .iter()
            .map(|p| {
                let h = self.h_c.get(&p.pair).copied().unwrap_or(0.0);
                p.g_rest / p.tributary <= lowest[&p.pair] + 1e-3 * h
            })
            .collect()
    }

    /// The verdict on the free unknowns' values read by `value` for a
    /// solve with the flags `current`: active where G_i < 0. A G_i within
    /// [`UNDECIDED`] of the size of its terms has no sign to read (a
    /// touching node unloaded: −1.7e-24 at rest, +6e-39 after the solve, on
    /// tests/mortar_steps.rs's Hertz at zero load, which released it and
    /// left the cylinder free): its node keeps its state.
    pub fn verdict(&self, current: &[bool], value: impl Fn(usize) -> f64) -> Vec<bool> {
        self.penalties
            .iter()
            .zip(current)
            .map(|(p, &on)| {
                let (gap, size) = p.gap_and_size(&value);
                match gap.abs() <= UNDECIDED * size {
                    true => on,
                    false => gap < 0.0,
                }
            })
            .collect()
    }

    /// Each slave node's state for the flags `active` and the free
    /// unknowns' values read by `value` (the interface's at least), refused
    /// (naming the node) when a gap or pressure is not finite.
    pub fn settled(
        &self,
        active: &[bool],
        value: impl Fn(usize) -> f64,
        mesh: &Mesh,
    ) -> Result<MortarState> {
        let nodes: Vec<SlaveNode> = self
            .penalties
            .iter()
            .zip(active)
            .map(|(p, &on)| {
                let g = p.gap(&value);
                SlaveNode {
                    pair: p.pair,
                    node: p.node,
                    tributary: p.tributary,
                    gap: g / p.tributary,
                    pressure: if on { -p.stiffness * g } else { 0.0 },
                    active: on,
                }
            })
            .collect();
        ensure_finite(
            nodes.iter().flat_map(|n| [n.gap, n.pressure]),
            2,
            "mortar gap or pressure",
            |i| format!("slave {}", mesh.node_name(nodes[i].node)),
        )?;
        Ok(MortarState {
            nodes,
            gaps: self.gaps.clone(),
        })
    }
}

/// The penalty of slave node `wg` of pair `pair` with κ = `kappa`.
fn penalty(pair: usize, wg: &WeightedGap, kappa: f64, data: &PenaltyData<'_>) -> Penalty {
    let stiffness = kappa / wg.tributary;
    let (mut unknowns, mut coef) = (Vec::new(), Vec::new());
    let dofs = wg.coefficients.iter().map(|&(g, _)| g).collect();
    let mut g_rest = wg.initial;
    for &(g, c) in &wg.coefficients {
        let j = (data.equation)(g);
        if j.is_none() {
            g_rest += c * data.prescribed[g];
        }
        unknowns.push(j);
        coef.push(c);
    }
    let matrix = coef
        .iter()
        .flat_map(|a| coef.iter().map(move |b| stiffness * a * b))
        .collect();
    let on_free = |g: f64| -> Vec<f64> {
        let f = -stiffness * g;
        unknowns
            .iter()
            .zip(&coef)
            .map(|(u, c)| if u.is_some() { f * c } else { 0.0 })
            .collect()
    };
    let (load, gap_load) = (on_free(g_rest), on_free(wg.initial));
    Penalty {
        pair,
        node: wg.node,
        tributary: wg.tributary,
        stiffness,
        g_rest,
        dofs,
        unknowns,
        coef,
        matrix,
        load,
        gap_load,
    }
}

/// The interfaces by (slave body, master body), and the interface of each
/// pair ([`MortarState::interfaces`]).
type Interfaces<'s> = (
    BTreeMap<(i32, i32), Interface<'s>>,
    BTreeMap<usize, (i32, i32)>,
);

/// One interface of the slave nodes ([`MortarState::nodal_values`]).
#[derive(Default)]
struct Interface<'s> {
    /// Its slave nodes' states.
    slaves: Vec<&'s SlaveNode>,
    /// The master nodes its weighted gaps read.
    masters: std::collections::BTreeSet<usize>,
    /// Its slave edges.
    edges: Vec<[usize; 2]>,
}

/// The state of a settled solve's weighted gaps, for its outputs: each
/// slave node's state and the weighted gaps they are of (pair by pair, in
/// the nodes' order).
#[derive(Debug, Clone, PartialEq)]
pub struct MortarState {
    /// Every slave node's state.
    pub nodes: Vec<SlaveNode>,
    /// The weighted gaps of every pair.
    pub gaps: Vec<PairGaps>,
}

impl MortarState {
    /// The contact force of every active slave node on each global DOF its
    /// weighted gap reads: p_i c_i, −∂/∂u of its penalty energy, as (pair,
    /// global DOF, value).
    pub fn forces(&self, mut add: impl FnMut(usize, usize, f64)) {
        let gaps = self.gaps.iter().flat_map(|p| &p.gaps);
        for (wg, s) in gaps.zip(&self.nodes).filter(|(_, s)| s.active) {
            for &(g, c) in &wg.coefficients {
                add(s.pair, g, s.pressure * c);
            }
        }
    }

    /// A value of the slave nodes (`value` of each) at every node of the
    /// mesh: a slave node's own; a master node that a weighted gap reads,
    /// the value interpolated along the nearest slave edge (zero at a slave
    /// node whose support does not face the master); zero elsewhere. A node
    /// on several pairs (where three bodies meet) gets the mean of its
    /// pairs' values. Pair `only` when given: its interface read whole (a
    /// slave node ending two of its pairs carries one weighted gap, and a
    /// weighted gap reads master nodes on either side of a cut), at the
    /// nodes of that pair's two sides only. Gives the values and which
    /// nodes were read.
    pub fn nodal_values(
        &self,
        mesh: &Mesh,
        pairs: &[ContactPair],
        only: Option<usize>,
        value: impl Fn(&SlaveNode) -> f64,
    ) -> Result<(Vec<f64>, Vec<bool>)> {
        let x = mesh.nodes();
        let mut sum = vec![0.0; x.len()];
        let mut count = vec![0u32; x.len()];
        let every: std::collections::HashMap<usize, f64> =
            self.nodes.iter().map(|s| (s.node, value(s))).collect();
        let of = |v: usize| every.get(&v).copied().unwrap_or(0.0);
        let (interfaces, of_pair) = self.interfaces(mesh, pairs)?;
        let mine = only.map(|o| of_pair.get(&o).copied());
        for (key, interface) in &interfaces {
            if mine.is_some_and(|k| k != Some(*key)) {
                continue;
            }
            for s in &interface.slaves {
                sum[s.node] += value(s);
                count[s.node] += 1;
            }
            // A master node reads the slave's value along the nearest
            // slave edge of its interface, whichever pair the edge is of.
            for &m in &interface.masters {
                let (mut best, mut val) = (f64::INFINITY, 0.0);
                for &[p, q] in &interface.edges {
                    let e = [x[q][0] - x[p][0], x[q][1] - x[p][1]];
                    let r = [x[m][0] - x[p][0], x[m][1] - x[p][1]];
                    let t =
                        ((r[0] * e[0] + r[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
                    let d = (r[0] - t * e[0]).hypot(r[1] - t * e[1]);
                    if d < best {
                        (best, val) = (d, (1.0 - t) * of(p) + t * of(q));
                    }
                }
                sum[m] += val;
                count[m] += 1;
            }
        }
        if let Some(o) = only {
            let p = &pairs[o];
            let mut on = vec![false; x.len()];
            for tag in [p.tag_a, p.tag_b] {
                for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag) {
                    e.nodes.iter().for_each(|&v| on[v] = true);
                }
            }
            for (c, _) in count.iter_mut().zip(&on).filter(|(_, on)| !**on) {
                *c = 0;
            }
        }
        let values = sum
            .iter()
            .zip(&count)
            .map(|(s, &c)| if c > 0 { s / f64::from(c) } else { 0.0 })
            .collect();
        Ok((values, count.iter().map(|&c| c > 0).collect()))
    }

    /// The interfaces of the slave nodes — the pairs between the same slave
    /// body and master body together (a ring cut into pairs is one
    /// interface) —, by (slave body, master body): each one's slave nodes,
    /// the master nodes its weighted gaps read, and its slave edges; and
    /// the interface of each pair.
    fn interfaces(&self, mesh: &Mesh, pairs: &[ContactPair]) -> Result<Interfaces<'_>> {
        let mut by_bodies: BTreeMap<(i32, i32), Interface<'_>> = BTreeMap::new();
        let mut of_pair = BTreeMap::new();
        let mut first = 0;
        for pg in &self.gaps {
            let mine = &self.nodes[first..first + pg.gaps.len()];
            first += pg.gaps.len();
            let p = &pairs[pg.pair];
            let (slave_tag, master_body) = match pg.slave {
                Slave::A => (p.tag_a, p.body_b),
                Slave::B => (p.tag_b, p.body_a),
            };
            let slave_side = Side::of_tag(mesh, slave_tag)?;
            let key = (slave_side.body, master_body);
            of_pair.insert(pg.pair, key);
            if mine.is_empty() {
                continue;
            }
            let interface = by_bodies.entry(key).or_default();
            interface.slaves.extend(mine);
            interface.edges.extend(slave_side.edges().iter().copied());
            // The master's nodes: those of the other body (a slave node
            // merged from a pair beside this one reads its own value).
            let slave_body = Some(slave_side.body);
            for wg in &pg.gaps {
                interface.masters.extend(
                    wg.coefficients
                        .iter()
                        .map(|&(g, _)| g / 2)
                        .filter(|&v| mesh.node_body()[v] != slave_body),
                );
            }
        }
        Ok((by_bodies, of_pair))
    }
}
