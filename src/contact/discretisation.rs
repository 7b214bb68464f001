//! How the contact pairs of a model are discretised, chosen once per
//! structure (mesh, boundary edges, pairs, prescribed DOFs) and pair by
//! pair: the strip's contact mesh B (docs/method.md §3) or the mortar
//! weighting's weighted gaps (§6.11). What a solve switches is built from
//! it ([`super::constraints::Constraints`]).
//!
//! Under [`ContactWeighting::Auto`] (the default) a pair gets what is right
//! for its interface: where the two sides' nodes match, B — the seed's
//! method, node-to-node and exact —, and where two straight sides do not,
//! B too (its strip is exact on the contact patch test there); where
//! curved sides do not match, the weighted gaps, converging where the
//! strip reads one side only (a curved tool: docs/method.md §6.11) or
//! splits into isolated elements (the 2:3 rings: a third of the contact
//! length, nodal pressures 0.3p–1.8p, no warning). A pair with a contact
//! mesh of its own, or with friction (which the weighted gaps do not carry
//! yet), keeps B; forced, the mortar weighting refuses such a pair where
//! it is set ([`serves`]).

use std::collections::BTreeMap;

use super::mesh::pair_strip;
use super::mesh::{Nodes, Side, matching, straight};
use super::mortar::{Basis, Slave, WeightedGap, facing_edges, penalty_length, weighted_gaps};
use super::mortar_set::PairGaps;
use super::{ContactElement, ContactPair, ContactWeighting};
use crate::error::{Error, Result};
use crate::fem::mesh::Mesh;

/// How one pair is discretised.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// The elements of B.
    Strip,
    /// The weighted gaps of its coarser side's nodes.
    Mortar,
}

/// The discretisation of every contact pair of a model.
#[derive(Debug, Clone, Default)]
pub struct Discretisation {
    /// B of the strip pairs.
    strip: Vec<ContactElement>,
    /// The weighted gaps of the mortar pairs.
    gaps: Vec<PairGaps>,
    /// The penalty length h_c of each mortar pair.
    h_c: BTreeMap<usize, f64>,
}

impl Discretisation {
    /// The discretisation of `pairs` on `mesh` under `weighting`.
    pub fn build(
        mesh: &Mesh,
        pairs: &[ContactPair],
        weighting: ContactWeighting,
    ) -> Result<Discretisation> {
        let families = pairs
            .iter()
            .map(|p| family_of(mesh, p, weighting))
            .collect::<Result<Vec<_>>>()?;
        let mut strip = Vec::new();
        for (i, p) in pairs.iter().enumerate() {
            if families[i] == Family::Strip {
                strip.append(&mut pair_strip(mesh, i, p)?);
            }
        }
        let mortar: Vec<usize> = (0..pairs.len())
            .filter(|&i| families[i] == Family::Mortar)
            .collect();
        let (gaps, h_c) = mortar_gaps(mesh, pairs, &mortar)?;
        Ok(Discretisation { strip, gaps, h_c })
    }

    /// The elements of B of the strip pairs.
    pub fn elements(&self) -> &[ContactElement] {
        &self.strip
    }

    /// The elements of B that the strip pairs switch.
    pub fn strip(&self) -> &[ContactElement] {
        &self.strip
    }

    /// The weighted gaps of the mortar pairs.
    pub fn gaps(&self) -> &[PairGaps] {
        &self.gaps
    }

    /// Whether some pair is under the mortar weighting.
    pub fn has_mortar(&self) -> bool {
        !self.gaps.is_empty()
    }

    /// The penalty length h_c of every pair: the shortest interface edge
    /// of its B (the strip's), or of its sides where they face each other
    /// (the mortar's).
    pub fn penalty_lengths(&self) -> BTreeMap<usize, f64> {
        let mut h = super::law::penalty_lengths(&self.strip);
        h.extend(self.h_c.iter().map(|(&k, &v)| (k, v)));
        h
    }

    /// The nodes each pair's constraints read, as (pair, node): B's, and
    /// those of the weighted gaps.
    pub fn contact_nodes(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let strip = (self.strip.iter()).flat_map(|e| e.nodes.iter().map(move |&n| (e.pair, n)));
        let mortar = self.gaps.iter().flat_map(|pg| {
            pg.gaps
                .iter()
                .flat_map(move |g| g.coefficients.iter().map(move |&(d, _)| (pg.pair, d / 2)))
        });
        strip.chain(mortar)
    }

    /// Node triangles whose cliques cover every coupling a solve may
    /// switch on: the strip's elements and the weighted gaps' cliques.
    pub fn couplings(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        let strip = self.strip.iter().map(|e| e.nodes);
        strip.chain(super::mortar_set::cliques(&self.gaps))
    }
}

/// The family pair `p` takes under `weighting` (module documentation for
/// [`ContactWeighting::Auto`]). Whether the nodes face each other is read
/// both ways, so that either side may come first.
pub fn family_of(mesh: &Mesh, p: &ContactPair, weighting: ContactWeighting) -> Result<Family> {
    Ok(match weighting {
        ContactWeighting::Strip => Family::Strip,
        ContactWeighting::Mortar => Family::Mortar,
        ContactWeighting::Auto => {
            if p.user_mesh.is_some() || p.friction > 0.0 {
                return Ok(Family::Strip);
            }
            let (a, b) = (Side::of_tag(mesh, p.tag_a)?, Side::of_tag(mesh, p.tag_b)?);
            let nodes = Nodes::of(mesh);
            match matching(nodes, &a, &b)
                || matching(nodes, &b, &a)
                || straight(nodes, &a) && straight(nodes, &b)
            {
                true => Family::Strip,
                false => Family::Mortar,
            }
        }
    })
}

/// Refuses a pair — pair `i`, with friction coefficient `friction` and,
/// when `own_mesh`, a contact mesh of its own — that `weighting` cannot
/// serve, naming it: the mortar weighting's gaps are frictionless and
/// integrate the gap along the two sides, with no mesh B. The one place of
/// that rule, asked whenever a pair, its friction or the weighting is set.
pub fn serves(weighting: ContactWeighting, i: usize, friction: f64, own_mesh: bool) -> Result<()> {
    if weighting != ContactWeighting::Mortar {
        return Ok(());
    }
    if friction > 0.0 {
        return Err(Error::argument(format!(
            "contact pair {i} has friction (mu = {friction}): the mortar weighting is \
             frictionless; set mu = 0 or use the automatic or strip weighting"
        )));
    }
    if own_mesh {
        return Err(Error::argument(format!(
            "contact pair {i} has a contact mesh of its own: the mortar weighting integrates \
             the gap along the two sides and uses no mesh B; drop the pair's mesh or use the \
             automatic or strip weighting"
        )));
    }
    Ok(())
}

/// Checks that pair `i` of `pairs` can be discretised under `weighting`,
/// so that a bad interface is reported when the pair is declared.
pub fn check_pair(
    mesh: &Mesh,
    pairs: &[ContactPair],
    i: usize,
    weighting: ContactWeighting,
) -> Result<()> {
    match family_of(mesh, &pairs[i], weighting)? {
        Family::Strip => pair_strip(mesh, i, &pairs[i]).map(|_| ()),
        Family::Mortar => mortar_gaps(mesh, pairs, &[i]).map(|_| ()),
    }
}

/// The weighted gaps of the mortar pairs `which` and their penalty lengths.
/// The slave is the coarser side of each interface — the pairs between the
/// same two bodies together, so that an interface cut into several pairs
/// (a ring in halves, curves of a Gmsh geometry) has one slave side — and
/// a slave node that ends two of its pairs carries one weighted gap
/// ([`merge_shared`]).
fn mortar_gaps(
    mesh: &Mesh,
    pairs: &[ContactPair],
    which: &[usize],
) -> Result<(Vec<PairGaps>, BTreeMap<usize, f64>)> {
    let nodes = Nodes::of(mesh);
    let mut sides = Vec::with_capacity(which.len());
    for &i in which {
        let p = &pairs[i];
        serves(
            ContactWeighting::Mortar,
            i,
            p.friction,
            p.user_mesh.is_some(),
        )?;
        let (a, b) = (Side::of_tag(mesh, p.tag_a)?, Side::of_tag(mesh, p.tag_b)?);
        let edges = facing_edges(nodes, &a, &b).map_err(|e| named(e, i))?;
        sides.push((i, a, b, edges));
    }
    // The coarser body of each interface: the fewer facing edges.
    let mut counts: BTreeMap<(i32, i32), [usize; 2]> = BTreeMap::new();
    let interface = |p: &ContactPair| (p.body_a.min(p.body_b), p.body_a.max(p.body_b));
    for (i, _, _, [ea, eb]) in &sides {
        let p = &pairs[*i];
        let c = counts.entry(interface(p)).or_default();
        let (lower, upper) = if p.body_a <= p.body_b {
            (ea, eb)
        } else {
            (eb, ea)
        };
        c[0] += lower;
        c[1] += upper;
    }
    let mut gaps = Vec::with_capacity(sides.len());
    let mut h_c = BTreeMap::new();
    for (i, a, b, [ea, eb]) in &sides {
        let p = &pairs[*i];
        // The coarser side: of the interface's pairs together (of the pair
        // alone in self-contact), side a on a tie.
        let [ea, eb] = match p.body_a == p.body_b {
            true => [*ea, *eb],
            false => {
                let c = counts[&interface(p)];
                if p.body_a < p.body_b { c } else { [c[1], c[0]] }
            }
        };
        let slave = if eb < ea { Slave::B } else { Slave::A };
        gaps.push(PairGaps {
            pair: *i,
            slave,
            gaps: read_gaps(nodes, a, b, slave).map_err(|e| named(e, *i))?,
        });
        h_c.insert(*i, penalty_length(nodes, a, b).map_err(|e| named(e, *i))?);
    }
    merge_shared(pairs, &mut gaps);
    Ok((gaps, h_c))
}

/// A message about pair `i` under the mortar weighting.
fn named(e: Error, i: usize) -> Error {
    Error::new(
        e.status(),
        format!("contact pair {i} (mortar weighting): {}", e.message()),
    )
}

/// The weighted gaps of the slave side of sides `a`, `b`: dual weights
/// (docs/method.md §6.11), the initial gap read with the hats. The dual
/// weights ψ = 2φ_i − φ_j read the initial gap almost pointwise, so the
/// faceting of a curved master is aliased into a ripple between slave
/// nodes that the bodies answer b/h times more stiffly than the mean, and
/// that peaks where the sides' nodes line up (at every junction of Gmsh
/// curves): ±0.75 % of δ in the initial gaps of the Lamé rings with dual
/// weights against ±0.05 % with the hats, a junction node read +26 % of p
/// at δ = 1e-4 (docs/issue42 of the ring study). The hats integrate the
/// same geometry smoothly and keep the patch test (they satisfy
/// Σψ = 1 and ∫ψ_i = ∫φ_i alike).
fn read_gaps(nodes: Nodes<'_>, a: &Side, b: &Side, slave: Slave) -> Result<Vec<WeightedGap>> {
    let mut gaps = weighted_gaps(nodes, a, b, slave, Basis::Dual)?;
    let hats = weighted_gaps(nodes, a, b, slave, Basis::Standard)?;
    for (g, h) in gaps.iter_mut().zip(&hats) {
        debug_assert_eq!(g.node, h.node);
        g.initial = h.initial;
    }
    Ok(gaps)
}

/// One weighted gap per slave node of an interface cut into several pairs
/// (the same two bodies, the same slave body): a node that ends two pairs
/// would carry two half-support penalties, each reading the gap on one
/// side of it, two constraints where the uncut interface has one (they
/// read ±2–4.5 % on the Gmsh rings' junctions, whose mean is right). Its
/// gaps are summed into the first pair's — the whole support, the whole
/// tributary — and dropped from the later pairs.
fn merge_shared(pairs: &[ContactPair], gaps: &mut [PairGaps]) {
    let key = |pg: &PairGaps, node: usize| {
        let p = &pairs[pg.pair];
        let (slave, master) = match pg.slave {
            Slave::A => (p.body_a, p.body_b),
            Slave::B => (p.body_b, p.body_a),
        };
        (slave, master, node)
    };
    let mut first: BTreeMap<(i32, i32, usize), (usize, usize)> = BTreeMap::new();
    let mut moves = Vec::new();
    for (k, pg) in gaps.iter().enumerate() {
        for (j, wg) in pg.gaps.iter().enumerate() {
            match first.get(&key(pg, wg.node)) {
                Some(&at) => moves.push((at, (k, j))),
                None => {
                    first.insert(key(pg, wg.node), (k, j));
                }
            }
        }
    }
    for &((k0, j0), (k1, j1)) in &moves {
        let add = gaps[k1].gaps[j1].clone();
        let g = &mut gaps[k0].gaps[j0];
        g.tributary += add.tributary;
        g.initial += add.initial;
        let mut c: BTreeMap<usize, f64> = g.coefficients.iter().copied().collect();
        for (d, v) in add.coefficients {
            *c.entry(d).or_insert(0.0) += v;
        }
        g.coefficients = c.into_iter().filter(|&(_, v)| v != 0.0).collect();
    }
    let mut dropped: Vec<(usize, usize)> = moves.iter().map(|m| m.1).collect();
    dropped.sort_unstable();
    for &(k, j) in dropped.iter().rev() {
        gaps[k].gaps.remove(j);
    }
}
