//! The state a solve's contact constraints settled in, and everything read
//! from it: the contact forces on the nodes, the reactions they carry, the
//! gaps and pressures at the nodes, and the per-family outputs (the strip's
//! elements of B, the mortar weighting's slave nodes). Above `contact/`
//! the results are read through this type only; the shape of a constraint
//! stays here.

use std::collections::BTreeMap;

use super::constraints::Constraints;
use super::law::{law_geometry, linearised_opening, shear_vector};
use super::mesh::Nodes;
use super::mortar::SlaveNode;
use super::mortar_set::MortarState;
use super::set::{ContactSet, ElementLaw, FrictionOutcome};
use super::{ContactElement, ContactLaw, ContactPair, conformity, traction};
use crate::error::{Error, Result, ensure_finite};
use crate::fem::element::TriGeometry;
use crate::fem::element_loop::element_values;
use crate::fem::material::Section;
use crate::fem::mesh::Mesh;

/// The settled state of the strip pairs' elements of B.
#[derive(Debug, Clone, PartialEq)]
pub struct StripState {
    /// The elements of B.
    pub elements: Vec<ContactElement>,
    /// Active flag of every element at convergence.
    pub active: Vec<bool>,
    /// Contact pressure of every element (zero when inactive).
    pub pressure: Vec<f64>,
    /// Each element's law.
    pub laws: Vec<ElementLaw>,
    /// The frictional state, when frictional (docs/method.md §6.15).
    pub friction: Option<FrictionOutcome>,
    /// The law of the elements (which sets their geometry).
    pub law: ContactLaw,
}

/// The state a solve's contact settled in (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactState {
    /// The strip pairs' elements.
    pub strip: StripState,
    /// The mortar pairs' slave nodes, when some pair is under the mortar
    /// weighting.
    pub mortar: Option<MortarState>,
}

impl ContactState {
    /// The strip's state, refused where every pair is under the mortar
    /// weighting (its state is per slave node).
    pub fn strip(&self) -> Result<&StripState> {
        match (&self.mortar, self.strip.elements.is_empty()) {
            (Some(_), true) => Err(Error::state(
                "the last contact solve used the mortar weighting for every pair: its state is \
                 per slave node (contact_slave_nodes, contact_nodal_pressures), not per element \
                 of B",
            )),
            _ => Ok(&self.strip),
        }
    }

    /// Every slave node's state, refused where no pair is under the mortar
    /// weighting.
    pub fn slave_nodes(&self) -> Result<&[SlaveNode]> {
        self.mortar.as_ref().map(|m| &m.nodes[..]).ok_or_else(|| {
            Error::state(
                "the last contact solve used the strip weighting for every pair: its state is \
                 per element of B (contact_active, contact_pressure), not per slave node",
            )
        })
    }

    /// Calls `add(pair, global DOF, value)` with the contact force of every
    /// active constraint on each of its DOFs, for the displacements `u`
    /// (global): an element of B's −(K_e u_e − f0_e + τ b_t), a slave node's
    /// p_i c_i.
    pub fn forces(&self, mesh: &Mesh, u: &[f64], mut add: impl FnMut(usize, usize, f64)) {
        let s = &self.strip;
        for (k, el) in s.elements.iter().enumerate() {
            if !s.active[k] {
                continue;
            }
            let f = s.element_force(mesh, u, k);
            for a in 0..6 {
                add(el.pair, 2 * el.nodes[a / 2] + a % 2, f[a]);
            }
        }
        if let Some(m) = &self.mortar {
            m.forces(add);
        }
    }

    /// The strip pairs' contact forces on their nodes, pair by pair, each
    /// active element's force on a node split along the element's own
    /// normal n (from side a to side b) and tangent t = (−n_y, n_x):
    /// (pair, node) → [Σ f·n, Σ f·t]. The split is the law's own — a
    /// frictionless element's force is along its n, so its tangential part
    /// is round-off, and a frictional one's is its shear — where a node's
    /// summed force split along one normal of the node would read the turn
    /// between its elements' normals on a curved interface as shear.
    pub fn framed_forces(&self, mesh: &Mesh, u: &[f64]) -> BTreeMap<(usize, usize), [f64; 2]> {
        let s = &self.strip;
        let mut framed: BTreeMap<(usize, usize), [f64; 2]> = BTreeMap::new();
        for (k, el) in s.elements.iter().enumerate() {
            if !s.active[k] {
                continue;
            }
            let f = s.element_force(mesh, u, k);
            let n = el.normal;
            for (i, &v) in el.nodes.iter().enumerate() {
                let fv = [f[2 * i], f[2 * i + 1]];
                let e = framed.entry((el.pair, v)).or_insert([0.0; 2]);
                e[0] += fv[0] * n[0] + fv[1] * n[1];
                e[1] += fv[1] * n[0] - fv[0] * n[1];
            }
        }
        framed
    }

    /// Adds to `r` the internal forces of the active constraints on the
    /// DOFs `fixed` for the displacements `u`, and to `bound` the rounding
    /// they may carry: the contact's share of the reactions K u − f.
    pub fn add_reactions(
        &self,
        mesh: &Mesh,
        u: &[f64],
        fixed: &[bool],
        r: &mut [f64],
        bound: &mut [f64],
    ) {
        let s = &self.strip;
        for (k, el) in s.elements.iter().enumerate() {
            if !s.active[k] {
                continue;
            }
            let (cs, tau, bt) = s.element(mesh, k);
            let ue = element_values(u, &el.nodes);
            for a in 0..6 {
                let g = 2 * el.nodes[a / 2] + a % 2;
                if fixed[g] {
                    let (ku, size) = (0..6).fold((0.0, 0.0), |(s, m), b| {
                        let t = cs.k[a * 6 + b] * ue[b];
                        (s + t, m + t.abs())
                    });
                    // The shear traction τ of a frictional element acts
                    // through b_t, on prescribed DOFs too.
                    let f0 = match &s.friction {
                        Some(_) => cs.f0[a] - tau * bt[a],
                        None => cs.f0[a],
                    };
                    r[g] += ku - f0;
                    bound[g] += f64::EPSILON * size;
                }
            }
        }
        if let Some(m) = &self.mortar {
            // The penalties' internal forces −p_i c_i on prescribed DOFs.
            m.forces(|_, g, f| {
                if fixed[g] {
                    r[g] -= f;
                    bound[g] += f64::EPSILON * f.abs();
                }
            });
        }
    }

    /// The normal gap at every node for the displacements `u` (zero off the
    /// interfaces): at a node of an element of B the smallest, over those
    /// elements, of the distance of the element's apex from its interface
    /// edge (linearised, the opening over the edge length); at a node a
    /// weighted gap reads, its slave's mean gap G_i/m_i. Negative: the
    /// bodies interpenetrate there.
    pub fn gaps(&self, mesh: &Mesh, pairs: &[ContactPair], u: &[f64]) -> Result<Vec<f64>> {
        let mut gap = vec![f64::INFINITY; mesh.nodes().len()];
        for el in &self.strip.elements {
            if el.edge_length <= 0.0 {
                continue;
            }
            let geo = TriGeometry::new(&mesh.corners(&el.nodes));
            let ue = element_values(u, &el.nodes);
            let g = linearised_opening(&geo, el.normal, &ue) / el.edge_length;
            for &v in &el.nodes {
                gap[v] = gap[v].min(g);
            }
        }
        if let Some(m) = &self.mortar {
            let (values, read) = m.nodal_values(mesh, pairs, None, |s| s.gap)?;
            overlay(&mut gap, &values, &read);
        }
        gap.iter_mut()
            .filter(|g| **g == f64::INFINITY)
            .for_each(|g| *g = 0.0);
        Ok(gap)
    }

    /// The contact traction at every node (zero off the interfaces), as
    /// [pressure, shear], of pair `only` alone when given, for the
    /// displacements `u` (global): on the strip pairs the interface
    /// traction read from both sides (`traction::interface_tractions`) of
    /// the elements' [`ContactState::framed_forces`]; on the mortar pairs
    /// (frictionless, no shear) each slave node's −κG_i/m_i and, at the
    /// nodes of the other side its weighted gaps read, the slave's pressure
    /// interpolated along the nearest slave edge.
    pub fn nodal_tractions(
        &self,
        mesh: &Mesh,
        pairs: &[ContactPair],
        section: Section,
        only: Option<usize>,
        u: &[f64],
    ) -> Result<Vec<[f64; 2]>> {
        let mut t = vec![[0.0; 2]; mesh.nodes().len()];
        let nodes = Nodes::of(mesh);
        let elements: Vec<ContactElement> = match only {
            Some(pair) => (self.strip.elements.iter())
                .filter(|e| e.pair == pair)
                .cloned()
                .collect(),
            None => self.strip.elements.clone(),
        };
        if !elements.is_empty() {
            let f = self.framed_forces(mesh, u);
            let force = |pair: usize, v: usize| f.get(&(pair, v)).copied().unwrap_or([0.0; 2]);
            for q in traction::interface_tractions(nodes, &elements, section, force) {
                t[q.node] = [q.pressure, q.shear];
            }
        }
        if let Some(m) = &self.mortar {
            let (values, read) = m.nodal_values(mesh, pairs, only, |s| s.pressure)?;
            for ((t, v), _) in t.iter_mut().zip(values).zip(read).filter(|(_, r)| *r) {
                *t = [v, 0.0];
            }
        }
        Ok(t)
    }
}

impl StripState {
    /// Element `k`'s stiffness and gap load, its shear traction τ (scaled to
    /// the share of its edge that carries it) and shear vector b_t (zero when
    /// frictionless).
    /// The contact force of active element `k` on its nodes' DOFs for the
    /// displacements `u` (global): −(K_e u_e − f0_e + τ b_t).
    fn element_force(&self, mesh: &Mesh, u: &[f64], k: usize) -> [f64; 6] {
        let (cs, tau, bt) = self.element(mesh, k);
        let ue = element_values(u, &self.elements[k].nodes);
        std::array::from_fn(|a| {
            let ku: f64 = (0..6).map(|b| cs.k[a * 6 + b] * ue[b]).sum();
            -(ku - cs.f0[a] + tau * bt[a])
        })
    }

    fn element(&self, mesh: &Mesh, k: usize) -> (super::ContactStiffness, f64, [f64; 6]) {
        let el = &self.elements[k];
        let corners = mesh.corners(&el.nodes);
        let geo = law_geometry(TriGeometry::new(&corners), self.law, el.normal);
        let law = &self.laws[k];
        let cs = law.stiffness(&geo, el);
        match &self.friction {
            Some(fr) => (
                cs,
                fr.shear[k] * el.facing_share(),
                shear_vector(&corners, el.normal).map(|v| law.weight * v),
            ),
            None => (cs, 0.0, [0.0; 6]),
        }
    }

    /// The shear traction of every element (zero when frictionless).
    pub fn shear(&self) -> Vec<f64> {
        match &self.friction {
            Some(f) => f.shear.clone(),
            None => vec![0.0; self.elements.len()],
        }
    }

    /// The frictional state of every element: 0 open, 1 stick, 2 slip (a
    /// frictionless solve: 2 where active, its surfaces slide freely).
    pub fn friction_state(&self) -> Vec<u8> {
        match &self.friction {
            Some(f) => f.state.clone(),
            None => self.active.iter().map(|&a| if a { 2 } else { 0 }).collect(),
        }
    }

    /// The energy dissipated by slip at every element (zero when
    /// frictionless).
    pub fn dissipation(&self) -> Vec<f64> {
        match &self.friction {
            Some(f) => f.dissipation.clone(),
            None => vec![0.0; self.elements.len()],
        }
    }
}

/// What a solve's constraints settled in ([`settle`]): its state, the final
/// flags over the constraints' parts (what the next load step starts
/// from), and the report's figures.
pub struct Settlement {
    /// The final flags over parts.
    pub flags: Vec<bool>,
    /// The state.
    pub state: ContactState,
    /// Elements of B and slave nodes.
    pub parts: usize,
    /// Those active.
    pub active: usize,
    /// The contact length: the part of each active element's edge that
    /// faces the other side, the longer-active family of each contact zone
    /// (docs/method.md §6.8, §6.11), and the active slave nodes'
    /// tributaries.
    pub contact_length: f64,
    /// The largest penetration (an active element's opening over its edge,
    /// a slave node's mean gap), positive.
    pub max_penetration: f64,
}

/// The mesh a solve's constraints were built on with its contact pairs:
/// what a settlement is read against (the weighted gaps' nodes, the
/// pairs' contact zones).
#[derive(Clone, Copy)]
pub struct PairedMesh<'a> {
    /// The mesh.
    pub mesh: &'a Mesh,
    /// Its contact pairs.
    pub pairs: &'a [ContactPair],
}

/// The settlement of the constraints `set` in the flags `active` (over
/// parts) with the friction load factors `friction`, the unknowns' values
/// read by `value`, on `paired`'s mesh and pairs. Its warnings (pressures
/// near round-off, one-sided readings) go to `warnings`. Refuses a value
/// that is not finite, naming its element.
pub fn settle(
    set: &Constraints<'_>,
    active: Vec<bool>,
    friction: &[f64],
    value: impl Fn(usize) -> f64,
    paired: PairedMesh<'_>,
    warnings: &mut Vec<String>,
) -> Result<Settlement> {
    let PairedMesh { mesh, pairs } = paired;
    let settled = set.settled(&active, friction, &value, mesh)?;
    let strip = set.strip();
    let name = |k: usize| format!("contact element {}", k + strip.nodes().base);
    if let Some(f) = &settled.friction {
        ensure_finite(f.shear.iter().copied(), 1, "shear traction", name)?;
        ensure_finite(f.dissipation.iter().copied(), 1, "slip dissipation", name)?;
    }
    let ue_of = |k: usize| set.element_values(k, &value);
    let (mut lc, mut max_pen) = (0.0, 0.0f64);
    for (k, el) in strip.elements().iter().enumerate() {
        if settled.active[k] && el.edge_length > 0.0 {
            max_pen = max_pen.max(-strip.opening(k, &ue_of(k)) / el.edge_length);
        }
    }
    let (zones_lc, one_sided) =
        conformity::contact_length_and_warnings(strip.elements(), &settled.active, pairs);
    lc += zones_lc;
    ensure_finite(
        settled.pressure.iter().copied(),
        1,
        "contact pressure",
        name,
    )?;
    precision_warning(strip, ue_of, &settled.active, &settled.pressure, warnings);
    warnings.extend(one_sided);
    let mut active_count = settled.active.iter().filter(|&&a| a).count();
    if let Some(m) = &settled.mortar {
        let on = || m.nodes.iter().filter(|n| n.active);
        lc += on().map(|n| n.tributary).sum::<f64>();
        max_pen = on().fold(max_pen, |worst, n| worst.max(-n.gap));
        active_count += on().count();
    }
    ensure_finite([lc, max_pen], 1, "contact length or penetration", |_| {
        "the contact report".to_string()
    })?;
    // +0.0 where a computation left −0.0 (a signed zero means nothing here;
    // a contact length of −0.0 was reported): x + 0.0 changes nothing else.
    let (lc, max_pen) = (lc + 0.0, max_pen + 0.0);
    let mut mortar = settled.mortar;
    for node in mortar.iter_mut().flat_map(|m| &mut m.nodes) {
        (node.gap, node.pressure) = (node.gap + 0.0, node.pressure + 0.0);
    }
    let state = ContactState {
        strip: StripState {
            elements: strip.elements().to_vec(),
            active: settled.active,
            pressure: settled.pressure.iter().map(|p| p + 0.0).collect(),
            laws: strip.laws().to_vec(),
            friction: settled.friction,
            law: strip.law(),
        },
        mortar,
    };
    Ok(Settlement {
        flags: active,
        state,
        parts: strip.len() + set.mortar().len(),
        active: active_count,
        contact_length: lc,
        max_penetration: max_pen,
    })
}

/// Below this many correct digits of the largest contact pressure a solve
/// warns (`precision_warning`).
const PRESSURE_DIGITS: f64 = 6.0;

/// The error of a solved u over the rounding bound of its value: the solve
/// adds its own. Measured on the flat punch (h = a/8, E_c = 1e15 … 1e21):
/// the punch's reaction is off from the support's by 2–40× the rounding
/// bound of the largest pressure, relative to it.
const SOLVE_ERROR_FACTOR: f64 = 10.0;

/// Warns when the contact pressures carry fewer than [`PRESSURE_DIGITS`]
/// correct digits because the penalty's overlaps approach the rounding of
/// the displacements (docs/method.md §6.14): a very stiff E_c against a
/// prescribed body leaves a well-conditioned system (no conditioning
/// warning: the penalty couples free to prescribed unknowns, so it enters
/// the load) whose forces are nevertheless rounding. The bound compared is
/// the largest error the displacements' own rounding leaves in an active
/// element's pressure, against the largest pressure.
fn precision_warning(
    set: &ContactSet<'_>,
    ue_of: impl Fn(usize) -> [f64; 6],
    active: &[bool],
    pressure: &[f64],
    warnings: &mut Vec<String>,
) {
    let (mut worst, mut at) = (0.0f64, None);
    for k in 0..set.len() {
        if active[k] {
            let r = SOLVE_ERROR_FACTOR * set.pressure_rounding(k, &ue_of(k));
            if r > worst {
                (worst, at) = (r, Some(k));
            }
        }
    }
    let largest = pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    let Some(k) = at else { return };
    if worst <= 10f64.powf(-PRESSURE_DIGITS) * largest {
        return;
    }
    let digits = (largest / worst).log10().max(0.0);
    warnings.push(format!(
        "the contact pressures carry about {digits:.0} correct digits: the penalty's overlaps are \
         near the rounding of the displacements (at contact element {}, the pressure {:.3e} may be off \
         by {worst:.1e}, against a largest pressure of {largest:.3e}); where the contact carries a \
         load, lower E_c or λ (docs/method.md §6.14)",
        k + set.nodes().base,
        pressure[k]
    ));
}

/// Puts `values` in `target` where `read`.
fn overlay(target: &mut [f64], values: &[f64], read: &[bool]) {
    for ((t, v), _) in target.iter_mut().zip(values).zip(read).filter(|(_, r)| **r) {
        *t = *v;
    }
}
