//! The constraints the active-set loop switches in one solve: the strip
//! pairs' elements of B ([`ContactSet`], docs/method.md §3), the mortar
//! pairs' weighted gaps ([`MortarSet`], §6.11) and, in three dimensions,
//! B's flat tetrahedra ([`GapTets`], §9), numbered as one list of parts
//! (the strip's first, then the weighted gaps, then the tetrahedra).
//!
//! Each part is a clique of unknowns with, while it is on, a symmetric
//! matrix and a load; the contact law gives a verdict on a solution (which
//! parts are on, and the friction loads of the frictional ones) and the
//! state the solve settles in. The loop, the condensed interface, the load
//! history and the assembled system read parts through this type only;
//! the shape of a part (a triangle of B, a slave node's gap) stays here.

use super::discretisation::Discretisation;
use super::gap_tets::GapTets;
use super::mesh::Nodes;
use super::mortar_set::{self, MortarSet, MortarState, PenaltyData};
use super::set::{ContactSet, FrictionOutcome, Verdict, element_laws, softer};
use super::{ContactLaw, ContactOptions, ContactPair};
use crate::error::Result;
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::element_loop::ElementLoop;
use crate::fem::material::Material;
use crate::fem::mesh::Mesh;

/// The constraints of one solve (module documentation).
pub struct Constraints<'a> {
    strip: ContactSet<'a>,
    mortar: MortarSet,
    gap: GapTets,
    /// Prescribed displacements, a global vector: the values of a part's
    /// DOFs that have no unknown.
    prescribed: &'a [f64],
}

/// What the constraints of one solve are built from.
pub struct Build<'a> {
    /// The bodies' elements with their materials (and the mesh).
    pub elements: ElementLoop<'a>,
    /// The contact pairs.
    pub pairs: &'a [ContactPair],
    /// How the pairs are discretised.
    pub discretisation: &'a Discretisation,
    /// The unknowns.
    pub dofs: &'a DofMap,
    /// Prescribed displacements, a global vector.
    pub prescribed: &'a [f64],
    /// The solve's options.
    pub options: &'a ContactOptions,
}

/// Which variant part `k` of the constraints is, and its index there.
enum Part {
    Strip(usize),
    Mortar(usize),
    Gap(usize),
}

/// The state a solve's constraints settled in, for its outputs.
pub struct Settled {
    /// The strip's elements: active flags, pressures (zero when off).
    pub active: Vec<bool>,
    /// See `active`.
    pub pressure: Vec<f64>,
    /// The frictional state, when frictional.
    pub friction: Option<FrictionOutcome>,
    /// The weighted gaps' state, when some pair is under the mortar
    /// weighting.
    pub mortar: Option<MortarState>,
}

impl<'a> Constraints<'a> {
    /// The constraints of a built-in solve: the strip pairs' elements of
    /// B, each element's law from its pair's softer body, frictional
    /// (docs/method.md §6.15) when a pair has μ > 0 under the frictionless
    /// law; and the mortar pairs' weighted gaps (§6.11) with the strip's
    /// penalty per pair. A frictional set starts from the slip `anchors`
    /// (empty: none).
    pub fn build(b: Build<'a>, anchors: &[f64]) -> Result<Constraints<'a>> {
        let strip = strip_set(&b, anchors)?;
        let mortar = mortar_penalties(&b)?;
        Ok(Constraints::new(strip, mortar, b.prescribed))
    }

    /// The constraints of the strip set `strip` and the weighted gaps
    /// `mortar`, for the prescribed displacements `prescribed` (a global
    /// vector) they were built with.
    pub fn new(strip: ContactSet<'a>, mortar: MortarSet, prescribed: &'a [f64]) -> Constraints<'a> {
        Constraints {
            strip,
            mortar,
            gap: GapTets::default(),
            prescribed,
        }
    }

    /// The constraints of B's tetrahedra `gap` alone (three dimensions),
    /// for the prescribed displacements `prescribed` (a global vector, three
    /// per node) they were built with. Frictionless: no strip, no weighted
    /// gap.
    pub fn of_gap(gap: GapTets, prescribed: &'a [f64], options: &ContactOptions) -> Result<Self> {
        let none = Nodes {
            x: &[],
            base: 0,
            ids: None,
        };
        let strip = ContactSet::new(none, &[], Vec::new(), |_| None, &[], options)?;
        Ok(Constraints {
            strip,
            mortar: MortarSet::default(),
            gap,
            prescribed,
        })
    }

    /// The strip pairs' elements of B in this solve.
    pub fn strip(&self) -> &ContactSet<'a> {
        &self.strip
    }

    /// The mortar pairs' weighted gaps in this solve.
    pub fn mortar(&self) -> &MortarSet {
        &self.mortar
    }

    /// Number of parts: the strip's ([`ContactSet::parts`]: two per
    /// element when frictional), one per weighted gap and one per
    /// tetrahedron of B.
    pub fn parts(&self) -> usize {
        self.strip.parts() + self.mortar.len() + self.gap.len()
    }

    /// Which variant part `k` is.
    fn part(&self, k: usize) -> Part {
        let ns = self.strip.parts();
        match k.checked_sub(ns) {
            None => Part::Strip(k),
            Some(m) if m < self.mortar.len() => Part::Mortar(m),
            Some(m) => Part::Gap(m - self.mortar.len()),
        }
    }

    /// The unknown of each DOF of part `k` (`None`: prescribed).
    pub fn unknowns(&self, k: usize) -> &[Option<usize>] {
        match self.part(k) {
            Part::Strip(k) => self.strip.unknowns(k),
            Part::Mortar(m) => self.mortar.unknowns(m),
            Part::Gap(g) => self.gap.unknowns(g),
        }
    }

    /// Part `k`'s matrix while on, row-major over its DOFs.
    pub fn matrix(&self, k: usize) -> &[f64] {
        match self.part(k) {
            Part::Strip(k) => &self.strip.stiffness(k).k,
            Part::Mortar(m) => self.mortar.matrix(m),
            Part::Gap(g) => self.gap.matrix(g),
        }
    }

    /// Part `k`'s load on its unknowns while on (zero on prescribed DOFs):
    /// its initial gap's load less the prescribed displacements' share.
    pub fn load(&self, k: usize) -> &[f64] {
        match self.part(k) {
            Part::Strip(k) => self.strip.load(k),
            Part::Mortar(m) => self.mortar.load(m),
            Part::Gap(g) => self.gap.load(g),
        }
    }

    /// The part of part `k`'s load of its initial gap alone (what does not
    /// scale with a load step's factor), on every DOF.
    pub fn gap_load(&self, k: usize) -> &[f64] {
        match self.part(k) {
            Part::Strip(k) => &self.strip.stiffness(k).f0,
            Part::Mortar(m) => self.mortar.gap_load(m),
            Part::Gap(g) => self.gap.gap_load(g),
        }
    }

    /// The global DOF (dimension·node + component) of each DOF of part
    /// `k`.
    fn global_dofs(&self, k: usize) -> Vec<usize> {
        match self.part(k) {
            Part::Strip(k) => {
                let nodes = &self.strip.elements()[self.strip.element_of(k)].nodes;
                (0..6).map(|a| 2 * nodes[a / 2] + a % 2).collect()
            }
            Part::Mortar(m) => self.mortar.dofs(m).to_vec(),
            Part::Gap(g) => self.gap.dofs(g).to_vec(),
        }
    }

    /// The values of the DOFs of B's tetrahedron `g`: `value(i)` of
    /// unknown i, the prescribed value where a DOF has no unknown.
    fn gap_values(&self, g: usize, value: impl Fn(usize) -> f64) -> [f64; 12] {
        let (dofs, unknowns) = (self.gap.dofs(g), self.gap.unknowns(g));
        std::array::from_fn(|a| match unknowns[a] {
            Some(i) => value(i),
            None => self.prescribed[dofs[a]],
        })
    }

    /// The values of the DOFs of element `k` of the strip: `value(i)` of
    /// unknown i, the prescribed value where a DOF has no unknown.
    pub fn element_values(&self, k: usize, value: impl Fn(usize) -> f64) -> [f64; 6] {
        let (tri, unknowns) = (&self.strip.elements()[k].nodes, self.strip.unknowns(k));
        std::array::from_fn(|a| match unknowns[a] {
            Some(i) => value(i),
            None => self.prescribed[2 * tri[a / 2] + a % 2],
        })
    }

    /// Adds part `k`'s energy (r·K r, Σ |K_jj| r_j²) for a global vector
    /// `r` to `acc` (a near-null mode's judge, `solve::diagnostics`).
    pub fn add_energy(&self, k: usize, acc: &mut (f64, f64), r: &[f64]) {
        let re: Vec<f64> = self.global_dofs(k).iter().map(|&g| r[g]).collect();
        let (ke, n) = (self.matrix(k), re.len());
        for a in 0..n {
            let kr: f64 = (0..n).map(|b| ke[a * n + b] * re[b]).sum();
            acc.0 += re[a] * kr;
            acc.1 += ke[a * n + a].abs() * re[a] * re[a];
        }
    }

    /// The set a loop starts from: the strip's ([`ContactSet::initial_active`]),
    /// the weighted gaps' ([`MortarSet::initial_active`]) and B's
    /// tetrahedra's ([`GapTets::initial_active`]).
    pub fn initial_active(&self) -> Vec<bool> {
        let mut active = self.strip.initial_active();
        active.extend(self.mortar.initial_active());
        active.extend(self.gap.initial_active());
        active
    }

    /// The interface unknowns: those with a nonzero coefficient in a part
    /// (or in the strip's inversion test). Sorted.
    pub fn interface_unknowns(&self) -> Vec<usize> {
        let mut set = self.strip.interface_unknowns();
        if !self.mortar.is_empty() || !self.gap.is_empty() {
            for m in 0..self.mortar.len() {
                set.extend(self.mortar.unknowns(m).iter().flatten());
            }
            for g in 0..self.gap.len() {
                set.extend(self.gap.unknowns(g).iter().flatten());
            }
            set.sort_unstable();
            set.dedup();
        }
        set
    }

    /// Value positions of `pattern` that hold zero in every matrix of the
    /// solve: zero in the bodies' part `body` and in every part's matrix.
    /// Sorted.
    pub fn structural_zeros(&self, pattern: &Pattern, body: &[f64]) -> Vec<usize> {
        if self.mortar.is_empty() && self.gap.is_empty() {
            return self.strip.structural_zeros(pattern, body);
        }
        // The weighted gaps and B's tetrahedra couple every DOF of their
        // nodes.
        Vec::new()
    }

    /// The verdict of the contact law on the values of the unknowns read
    /// by `value`, for a solve with the flags `current` and friction load
    /// factors `c` ([`ContactSet::verdict`], [`MortarSet::verdict`],
    /// [`GapTets::verdict`]).
    pub fn verdict(
        &self,
        current: &[bool],
        c: &[f64],
        value: impl Fn(usize) -> f64,
    ) -> Result<Verdict> {
        let ns = self.strip.parts();
        let mut verdict = self
            .strip
            .verdict(&current[..ns], c, |k| self.element_values(k, &value))?;
        let nm = ns + self.mortar.len();
        verdict
            .flags
            .extend(self.mortar.verdict(&current[ns..nm], &value));
        let gap = self.gap.verdict(|g| self.gap_values(g, &value))?;
        verdict.flags.extend(gap);
        Ok(verdict)
    }

    /// Whether some part is frictional.
    pub fn is_frictional(&self) -> bool {
        self.strip.is_frictional()
    }

    /// The friction loads that go with the flags `active` at the loop's
    /// start ([`ContactSet::stick_loads`]; empty when frictionless).
    pub fn stick_loads(&self, active: &[bool]) -> Vec<f64> {
        self.strip.stick_loads(&active[..self.strip.parts()])
    }

    /// Adds the friction loads of the load factors `c` against `c_ref`
    /// ([`ContactSet::add_friction_loads`]).
    pub fn add_friction_loads(&self, c: &[f64], c_ref: &[f64], add: impl FnMut(usize, f64)) {
        self.strip.add_friction_loads(c, c_ref, add);
    }

    /// The frictional parts that slip under the flags `active`
    /// ([`ContactSet::slipping`]).
    pub fn slipping(&self, active: &[bool]) -> Vec<usize> {
        self.strip.slipping(&active[..self.strip.parts()])
    }

    /// The flags a step starts from after one that ended with `warm` and
    /// the friction loads `loads` ([`ContactSet::warm_flags`]).
    pub fn warm_flags(&self, warm: &[bool], loads: &[f64]) -> Vec<bool> {
        let ns = self.strip.parts();
        if warm.len() < ns {
            return warm.to_vec();
        }
        let mut flags = self.strip.warm_flags(&warm[..ns], loads);
        flags.extend_from_slice(&warm[ns..]);
        flags
    }

    /// The friction load factor of slipping part `k` for the values read
    /// by `value`, slipping as the factor `c` does
    /// ([`ContactSet::slip_load`]).
    pub fn slip_load(&self, k: usize, value: impl Fn(usize) -> f64, c: f64) -> f64 {
        let ue = self.element_values(k, value);
        self.strip.slip_load(k, &ue, c)
    }

    /// The slip coupling of slipping part `k` ([`ContactSet::slip_coupling`]):
    /// (μ, b_t, ∇p) over its DOFs, and its pressure for the DOFs' values
    /// `rest`.
    pub fn slip_coupling(&self, k: usize) -> Option<(f64, [f64; 6], [f64; 6])> {
        self.strip.slip_coupling(k)
    }

    /// The pressure of strip part `k` for its DOFs' values `ue`.
    pub fn slip_pressure(&self, k: usize, ue: &[f64; 6]) -> f64 {
        self.strip.pressure(k, ue)
    }

    /// The state the flags `active` and friction load factors `c` settled
    /// in for the unknowns' values read by `value`.
    pub fn settled(
        &self,
        active: &[bool],
        c: &[f64],
        value: impl Fn(usize) -> f64,
        mesh: &Mesh,
    ) -> Result<Settled> {
        let ns = self.strip.parts();
        let elements = |k: usize| self.element_values(k, &value);
        let friction = self.strip.friction_outcome(&active[..ns], c, elements);
        let mortar = match self.mortar.is_empty() {
            true => None,
            false => {
                let nm = ns + self.mortar.len();
                Some(self.mortar.settled(&active[ns..nm], &value, mesh)?)
            }
        };
        let n = self.strip.len();
        let mut pressure = vec![0.0; n];
        for k in (0..n).filter(|&k| active[k]) {
            pressure[k] = self.strip.pressure(k, &self.element_values(k, &value));
        }
        Ok(Settled {
            active: active[..n].to_vec(),
            pressure,
            friction,
            mortar,
        })
    }
}

/// The unknown of global DOF g, if it has one.
fn equation(dofs: &DofMap) -> impl Fn(usize) -> Option<usize> + '_ {
    move |g| Some(dofs.free(g)).filter(|&f| f != NOT_FREE)
}

/// The strip pairs' elements of B in one solve ([`Constraints::build`]).
fn strip_set<'a>(b: &Build<'a>, anchors: &[f64]) -> Result<ContactSet<'a>> {
    let mesh = b.elements.mesh();
    let soft = pair_material(b);
    let strip = b.discretisation.strip();
    let laws = element_laws(Nodes::of(mesh), strip, &soft, mesh.size(), b.options)?;
    let set = ContactSet::new(
        Nodes::of(mesh),
        strip,
        laws,
        equation(b.dofs),
        b.prescribed,
        b.options,
    )?;
    // μ = 0 everywhere is the frictionless set itself, bit for bit; the
    // stick law already ties the surfaces.
    let frictional = b.options.law == ContactLaw::Frictionless
        && strip.iter().any(|e| b.pairs[e.pair].friction > 0.0);
    if !frictional {
        return Ok(set);
    }
    let mu: Vec<f64> = strip.iter().map(|e| b.pairs[e.pair].friction).collect();
    // The stick part's shear modulus: G_c = E_c / (2(1 + ν)) of the pair's
    // softer body, as in the stick law.
    let shear: Vec<f64> = strip
        .iter()
        .map(|e| {
            let s = soft(e.pair);
            let e_c = b.options.contact_modulus.unwrap_or(s.young());
            e_c / (2.0 * (1.0 + s.poisson()))
        })
        .collect();
    set.with_friction(&mu, &shear, anchors, b.prescribed)
}

/// The mortar pairs' weighted gaps as penalties in one solve
/// ([`Constraints::build`]); options the weighting does not serve are
/// refused.
fn mortar_penalties(b: &Build<'_>) -> Result<MortarSet> {
    let d = b.discretisation;
    if !d.has_mortar() {
        return Ok(MortarSet::default());
    }
    mortar_set::check_options(b.options, d.gaps().iter().map(|g| g.pair))?;
    let soft = pair_material(b);
    let moduli: Vec<f64> = (0..b.pairs.len())
        .map(|i| b.options.contact_modulus.unwrap_or(soft(i).young()))
        .collect();
    let equation = equation(b.dofs);
    let data = PenaltyData {
        moduli: &moduli,
        lambda: b.options.lambda.unwrap_or(b.elements.mesh().size()),
        h_c: d.penalty_lengths(),
        equation: &equation,
        prescribed: b.prescribed,
    };
    MortarSet::new(d.gaps(), data)
}

/// The material that sets each pair's contact law: the softer body's, or
/// where one side is a rigid tool ([`rigid_sides`]), the other body's.
fn pair_material<'b>(b: &'b Build<'_>) -> impl Fn(usize) -> Material + 'b {
    let mesh = b.elements.mesh();
    let rigid = rigid_sides(b.pairs, b.discretisation.contact_nodes(), mesh, b.dofs);
    move |pair: usize| {
        let p = &b.pairs[pair];
        let (m_a, m_b) = (
            *b.elements.material(p.body_a),
            *b.elements.material(p.body_b),
        );
        match rigid[pair] {
            [true, false] => m_b,
            [false, true] => m_a,
            _ => softer(m_a, m_b),
        }
    }
}

/// For each pair, whether each side (a, b) is a rigid tool: every DOF of
/// its contact nodes prescribed. Such a side moves as prescribed whatever
/// its body's stiffness, so its material must not set the pair's contact
/// law — a "rigid" punch given a nominal E of 1e3 against a steel block
/// made E_c = 1e3, and the penalty overlap took 99.98 % of the indentation
/// with an OK status (an outside probe). The pair's law then follows the
/// other body (docs/method.md §6.14). A pair with no element (or
/// self-contact, where the sides are one body) keeps the softer body.
fn rigid_sides(
    pairs: &[ContactPair],
    contact: impl Iterator<Item = (usize, usize)>,
    mesh: &Mesh,
    dofs: &DofMap,
) -> Vec<[bool; 2]> {
    let mut rigid = vec![[false; 2]; pairs.len()];
    let mut seen = vec![[false; 2]; pairs.len()];
    for (pair, n) in contact {
        let p = &pairs[pair];
        if p.body_a == p.body_b {
            continue;
        }
        let side = match mesh.node_body()[n] {
            Some(b) if b == p.body_a => 0,
            Some(b) if b == p.body_b => 1,
            _ => continue,
        };
        let fixed = (0..2).all(|c| dofs.free(2 * n + c) == NOT_FREE);
        if !seen[pair][side] {
            seen[pair][side] = true;
            rigid[pair][side] = true;
        }
        rigid[pair][side] &= fixed;
    }
    rigid
}
