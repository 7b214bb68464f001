//! The elements of B in one solve: each element's law (constitutive matrix
//! and tempered Jacobian), its stiffness and initial-gap load, its
//! unknowns, and the inversion test that decides which elements are
//! active, and the active set a loop carries from iteration to iteration
//! (with its history and the sets visited: a revisit is a cycle). Built
//! once per solve from B (which depends only on the mesh and the pairs)
//! and the solve's options; the built-in solver and a host code's own
//! loop use the same set.

use std::borrow::Cow;
use std::collections::{BTreeMap, HashSet};

use super::law::{
    ContactStiffness, contact_jmins, contact_pressure, contact_stiffness, law_geometry, law_matrix,
    linearised_opening, opening_coefficient, opening_rounding, pressure_per_opening, shear_vector,
    stick_stiffness,
};
use super::mesh::Nodes;
use super::{ContactElement, ContactOptions, InversionTest};
use crate::error::{Error, Result, Status, ensure_finite};
use crate::fem::assembly::Pattern;
use crate::fem::element::TriGeometry;
use crate::fem::material::Material;

/// The law of one contact element: its constitutive matrix and its
/// tempered Jacobian. An active element is inverted, so max(J, Jmin) =
/// Jmin: `t` is its Jmin, and its matrix does not change while it is
/// active.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementLaw {
    /// Constitutive matrix D_c (Voigt, engineering shear).
    pub d: [[f64; 3]; 3],
    /// Tempered Jacobian T = Jmin = ℓ_e h_c²/λ (docs/method.md §6.11).
    pub t: f64,
    /// The measure of its section at its centroid, which weighs every
    /// force and stiffness it gives the bodies (not its pressure or shear,
    /// which are tractions): 1 in the plane, 2πx̄ for a ring
    /// ([`crate::fem::material::Section::weight`]; docs/method.md §7).
    pub weight: f64,
}

impl ElementLaw {
    /// The element's stiffness and initial-gap load with its geometry
    /// `geo` (flattened by [`law_geometry`] where the law wants it),
    /// weighted by its section's measure.
    pub fn stiffness(&self, geo: &TriGeometry, el: &ContactElement) -> ContactStiffness {
        weighted(
            contact_stiffness(geo, &self.d, el.normal, el.j0, self.t),
            self.weight,
        )
    }
}

/// A contact element's matrix and load times the measure `w` of its
/// section (1 in the plane: unchanged to the bit).
pub fn weighted(mut cs: ContactStiffness, w: f64) -> ContactStiffness {
    if w != 1.0 {
        cs.k.iter_mut()
            .chain(cs.f0.iter_mut())
            .for_each(|v| *v *= w);
    }
    cs
}

/// The elements of B with everything a solve needs of them.
pub struct ContactSet<'a> {
    /// Coordinates of the nodes of B's elements.
    x: Cow<'a, [[f64; 2]]>,
    /// The index base of messages.
    base: usize,
    elements: Cow<'a, [ContactElement]>,
    options: ContactOptions,
    laws: Vec<ElementLaw>,
    geos: Vec<TriGeometry>,
    stiffness: Vec<ContactStiffness>,
    unknowns: Vec<[Option<usize>; 6]>,
    loads: Vec<[f64; 6]>,
    friction: Option<Friction>,
    /// Per element whose apex projects beyond its interface edge: the
    /// element with the same apex whose edge lies under it, its support
    /// ([`supports`]).
    supports: Vec<Option<usize>>,
}

/// The tangential side of the frictional law (docs/method.md §6.15), per
/// element of B: μ, G_c/T, the shear vector b_t, the stick part (matrix and
/// its prescribed share) and the slip γ_p the step starts from.
struct Friction {
    mu: Vec<f64>,
    g_over_t: Vec<f64>,
    bt: Vec<[f64; 6]>,
    stick: Vec<ContactStiffness>,
    stick_loads: Vec<[f64; 6]>,
    anchors: Vec<f64>,
}

/// How far past its switch, relative to its own traction, a frictional
/// element must be to switch: a sticking one slips when |τ| > μp(1 + tol), a
/// slipping one sticks when its slip turned back by more than tol of its
/// shear's compliance |τ|T/G_c. Without it, a step that repeats the last
/// one's loads (zero slip, |τ| = μp) judges round-off: its slip zone
/// switched between stick and slip for ever (found by the C boundary test).
pub const SWITCH_TOL: f64 = 1e-9;

/// How far beyond its pair's smallest gap, relative to its size, an
/// element's gap may be (round-off of the coordinates) for the element to
/// close with the first point of contact ([`ContactSet::with_friction`]).
pub const TOUCHING: f64 = 1e-9;

/// The verdict of the contact law on a solve ([`ContactSet::verdict`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Verdict {
    /// The active flags over parts.
    pub flags: Vec<bool>,
    /// The friction load factors (empty when frictionless).
    pub loads: Vec<f64>,
}

/// The frictional state of the elements of B after a converged step
/// ([`ContactSet::friction_outcome`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionOutcome {
    /// Per element: 0 open, 1 stick (also an element that closed in the
    /// step, which carries no shear in it), 2 slip.
    pub state: Vec<u8>,
    /// Per element: the shear traction τ = n·σ·t (t = (−n_y, n_x)), Pa.
    pub shear: Vec<f64>,
    /// Per element: the energy dissipated by slip in the step (per unit
    /// thickness), ½ τ Δγ_p ≥ 0.
    pub dissipation: Vec<f64>,
    /// What the next step starts from.
    pub next: FrictionState,
    /// The elements open at the step's start that closed in it, without
    /// shear: where along the step each closed is what a load history
    /// ends its sub-steps at (docs/method.md §6.15).
    pub closed: Vec<usize>,
}

/// What a frictional step carries to the next: per element of B, the slip
/// γ_p (the stress-free shear, in B̂u units) and the friction load factor c
/// of the last solve (element loads c·b_t).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FrictionState {
    /// γ_p per element; NaN for an element open at the end of the step,
    /// which has no slip to remember ([`ContactSet::closing`]).
    pub anchors: Vec<f64>,
    /// c per element.
    pub loads: Vec<f64>,
    /// Per element, its linearised opening at the step's end
    /// ([`ContactSet::opening`]); empty where not known (before the first
    /// step: each element's initial opening J₀ then). With `at`, where a
    /// history locates the closing of the elements open here.
    pub openings: Vec<f64>,
    /// The load factor of the step it ended (0 before the first; NaN
    /// where not known: a state restored from an older version's bytes).
    pub at: f64,
    /// A fingerprint of the loads that step applied (forces and prescribed
    /// values at factor 1): a step on the same loads goes on along the
    /// straight path from `at` (0: not known).
    pub load_key: u64,
}

/// What a set is made over: its nodes' coordinates and its elements of B,
/// borrowed from a model's mesh or owned (a host's contact, which copies
/// its sides' nodes).
pub struct Owners<'a> {
    /// The nodes' coordinates.
    pub x: Cow<'a, [[f64; 2]]>,
    /// The index base of the nodes and elements in messages.
    pub base: usize,
    /// The elements of B.
    pub elements: Cow<'a, [ContactElement]>,
}

impl<'a> ContactSet<'a> {
    /// The set of `elements` (B over `nodes`) under `options`, with each
    /// element's law from [`element_laws`]. `equation(g)` numbers the
    /// unknown of global DOF g = 2·node + component (`None`: no unknown);
    /// `prescribed` gives the values of the DOFs without one (a global
    /// vector; empty: zero), whose share goes into the elements' loads.
    pub fn new(
        nodes: Nodes<'a>,
        elements: &'a [ContactElement],
        laws: Vec<ElementLaw>,
        equation: impl Fn(usize) -> Option<usize>,
        prescribed: &[f64],
        options: &ContactOptions,
    ) -> Result<ContactSet<'a>> {
        let owners = Owners {
            x: Cow::Borrowed(nodes.x),
            base: nodes.base,
            elements: Cow::Borrowed(elements),
        };
        Self::build(owners, laws, equation, prescribed, options)
    }

    /// [`ContactSet::new`] owning its nodes' coordinates and its elements
    /// (`owners`).
    pub fn owned(
        owners: Owners<'static>,
        laws: Vec<ElementLaw>,
        equation: impl Fn(usize) -> Option<usize>,
        prescribed: &[f64],
        options: &ContactOptions,
    ) -> Result<ContactSet<'static>> {
        ContactSet::build(owners, laws, equation, prescribed, options)
    }

    fn build(
        Owners { x, base, elements }: Owners<'a>,
        laws: Vec<ElementLaw>,
        equation: impl Fn(usize) -> Option<usize>,
        prescribed: &[f64],
        options: &ContactOptions,
    ) -> Result<ContactSet<'a>> {
        let nodes = Nodes::new(&x, base);
        let geos: Vec<TriGeometry> = elements
            .iter()
            .map(|el| {
                let geo = TriGeometry::new(&nodes.corners(&el.nodes));
                law_geometry(geo, options.law, el.normal)
            })
            .collect();
        // An active element is inverted, so its T = Jmin: its matrix and
        // initial-gap load do not change between iterations.
        let stiffness: Vec<ContactStiffness> = elements
            .iter()
            .enumerate()
            .map(|(k, el)| laws[k].stiffness(&geos[k], el))
            .collect();
        let name = |k: usize| format!("contact element {}", k + nodes.base);
        let values = stiffness
            .iter()
            .flat_map(|cs| cs.k.iter().chain(&cs.f0).copied());
        ensure_finite(values, 42, "stiffness", name)?;
        let unknowns: Vec<[Option<usize>; 6]> = elements
            .iter()
            .map(|el| std::array::from_fn(|a| equation(2 * el.nodes[a / 2] + a % 2)))
            .collect();
        let loads = element_loads(&elements, &stiffness, &unknowns, prescribed);
        let supports = supports(nodes, &elements);
        Ok(ContactSet {
            x,
            base,
            elements,
            options: *options,
            laws,
            geos,
            stiffness,
            unknowns,
            loads,
            friction: None,
            supports,
        })
    }

    /// Makes the set frictional (docs/method.md §6.15): Coulomb's law with
    /// coefficient `mu[k]` and stick shear modulus `shear_modulus[k]` for
    /// element k, starting from the slip `anchors` (empty: none for the
    /// elements at their pair's smallest gap, [`TOUCHING`], NaN, open, for
    /// the others). A
    /// NaN anchor marks an element open at the step's start: should it
    /// close, it carries no shear in this step ([`ContactSet::verdict`]). Every
    /// element then has two parts ([`ContactSet::parts`]): its normal part,
    /// and its stick part k + n. `prescribed` as in [`ContactSet::new`].
    pub fn with_friction(
        mut self,
        mu: &[f64],
        shear_modulus: &[f64],
        anchors: &[f64],
        prescribed: &[f64],
    ) -> Result<ContactSet<'a>> {
        let n = self.len();
        if mu.len() != n || shear_modulus.len() != n || !(anchors.is_empty() || anchors.len() == n)
        {
            return Err(Error::argument(format!(
                "friction data of {} / {} / {} elements for {n} contact elements",
                mu.len(),
                shear_modulus.len(),
                anchors.len()
            )));
        }
        let g_over_t: Vec<f64> = (0..n).map(|k| shear_modulus[k] / self.laws[k].t).collect();
        let bt: Vec<[f64; 6]> = (0..n)
            .map(|k| {
                let el = &self.elements[k];
                shear_vector(&self.nodes().corners(&el.nodes), el.normal)
            })
            .collect();
        let stick: Vec<ContactStiffness> = (0..n)
            .map(|k| weighted(stick_stiffness(&bt[k], g_over_t[k]), self.laws[k].weight))
            .collect();
        let name = |k: usize| format!("contact element {}", k + self.base);
        let values = stick.iter().flat_map(|cs| cs.k.iter().copied());
        ensure_finite(values, 36, "stick stiffness", name)?;
        let stick_loads = element_loads(&self.elements, &stick, &self.unknowns, prescribed);
        let anchors = if anchors.is_empty() {
            // The elements at their pair's smallest gap (to round-off) close
            // first, all together: they stick from the unloaded state. The
            // others close later along the load, where is not known: open.
            within_smallest_gap(&self.elements, TOUCHING)
                .into_iter()
                .map(|first| if first { 0.0 } else { f64::NAN })
                .collect()
        } else {
            anchors.to_vec()
        };
        self.friction = Some(Friction {
            mu: mu.to_vec(),
            g_over_t,
            bt,
            stick,
            stick_loads,
            anchors,
        });
        Ok(self)
    }

    /// Whether the set is frictional.
    pub fn is_frictional(&self) -> bool {
        self.friction.is_some()
    }

    /// Number of parts: one per element (its normal part), plus its stick
    /// part when frictional (part k + n of element k). Active flags, the
    /// matrices and loads of the active-set loop run over parts.
    pub fn parts(&self) -> usize {
        match self.friction {
            Some(_) => 2 * self.len(),
            None => self.len(),
        }
    }

    /// The element of part `p`.
    pub fn element_of(&self, p: usize) -> usize {
        if p < self.len() { p } else { p - self.len() }
    }

    /// The nodes B is built on.
    pub fn nodes(&self) -> Nodes<'_> {
        Nodes::new(&self.x, self.base)
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.elements.len()
    }

    /// Whether B is empty.
    pub fn is_empty(&self) -> bool {
        self.elements.is_empty()
    }

    /// The elements of B.
    pub fn elements(&self) -> &[ContactElement] {
        &self.elements
    }

    /// Each element's law.
    pub fn laws(&self) -> &[ElementLaw] {
        &self.laws
    }

    /// The constitutive law of its elements (which sets their geometry).
    pub fn law(&self) -> super::ContactLaw {
        self.options.law
    }

    /// The stiffness and initial-gap load of part `k` when active
    /// ([`ContactSet::parts`]).
    pub fn stiffness(&self, k: usize) -> &ContactStiffness {
        match &self.friction {
            Some(f) if k >= self.len() => &f.stick[k - self.len()],
            _ => &self.stiffness[k],
        }
    }

    /// The unknown of each of part `k`'s six DOFs (`None`: prescribed).
    pub fn unknowns(&self, k: usize) -> &[Option<usize>; 6] {
        &self.unknowns[self.element_of(k)]
    }

    /// Part `k`'s load on its unknowns when active: its initial-gap load
    /// minus the prescribed displacements' share (zero on prescribed DOFs).
    pub fn load(&self, k: usize) -> &[f64; 6] {
        match &self.friction {
            Some(f) if k >= self.len() => &f.stick_loads[k - self.len()],
            _ => &self.loads[k],
        }
    }

    /// The active set the loop starts from ([`initial_active_set`]), over
    /// parts: a frictional element starts sticking, unless it closes in
    /// this step ([`ContactSet::closing`]).
    pub fn initial_active(&self) -> Vec<bool> {
        let mut active = initial_active_set(&self.elements);
        if self.friction.is_some() {
            let stick: Vec<bool> = (0..self.len())
                .map(|k| active[k] && !self.closing(k))
                .collect();
            active.extend(stick);
        }
        active
    }

    /// The friction loads that go with the active flags `active` (over
    /// parts) and the slip state `anchors` at the loop's start: c = G_c γ_p/T
    /// of every sticking element (its stick part's stress-free shear), zero
    /// elsewhere; the slipping elements' c comes from the loop. Empty when
    /// frictionless.
    pub fn stick_loads(&self, active: &[bool]) -> Vec<f64> {
        let Some(f) = &self.friction else {
            return Vec::new();
        };
        let n = self.len();
        (0..n)
            .map(|k| match active[n + k] && !f.anchors[k].is_nan() {
                true => f.g_over_t[k] * f.anchors[k],
                false => 0.0,
            })
            .collect()
    }

    /// Adds the friction loads Σ_e (c_e − c_ref,e) b_t,e, `add(unknown,
    /// value)`, for the load factors `c` against a reference `c_ref`
    /// (empty: zero). Nothing when frictionless.
    pub fn add_friction_loads(&self, c: &[f64], c_ref: &[f64], mut add: impl FnMut(usize, f64)) {
        let Some(f) = &self.friction else { return };
        for (k, &ck) in c.iter().enumerate() {
            let dc = ck - c_ref.get(k).copied().unwrap_or(0.0);
            if dc == 0.0 {
                continue;
            }
            let w = self.laws[k].weight;
            for (a, e) in self.unknowns[k].iter().enumerate() {
                if let Some(i) = e {
                    add(*i, dc * (w * f.bt[k][a]));
                }
            }
        }
    }

    /// The elements that slip under the flags `active` (over parts):
    /// active, not sticking, and not closing in this step (those carry no
    /// shear). Empty when frictionless.
    pub fn slipping(&self, active: &[bool]) -> Vec<usize> {
        let Some(f) = &self.friction else {
            return Vec::new();
        };
        let n = self.len();
        (0..n)
            .filter(|&k| active[k] && !active[n + k] && !f.anchors[k].is_nan())
            .collect()
    }

    /// The flags a step starts from after a step that ended with the flags
    /// `warm` and the friction loads `loads` (its [`FrictionState`], which
    /// this set was built with): `warm`, with the stick part on for every
    /// element that closed in that step. Those ended without a stick part
    /// (they carried no shear) and stick from the step's end, with the load
    /// c = G_c γ_p/T that [`ContactSet::friction_outcome`] gave them; left
    /// as they were, they would start the step slipping with c = 0, in no
    /// direction. Unchanged when frictionless.
    pub fn warm_flags(&self, warm: &[bool], loads: &[f64]) -> Vec<bool> {
        let mut flags = warm.to_vec();
        let Some(f) = &self.friction else {
            return flags;
        };
        let n = self.len();
        if loads.is_empty() && warm.len() == 2 * n {
            // No step yet: the state at no load, where only the elements
            // touching from the start are closed. The others start open,
            // so that the loop's first solve is the start's response along
            // the step, which says where each closes (a history's
            // sub-steps, docs/method.md §6.15).
            for k in (0..n).filter(|&k| f.anchors[k].is_nan()) {
                (flags[k], flags[n + k]) = (false, false);
            }
            return flags;
        }
        if loads.len() != n || warm.len() != 2 * n {
            return flags;
        }
        for k in 0..n {
            let closed = !f.anchors[k].is_nan() && loads[k] == f.g_over_t[k] * f.anchors[k];
            if warm[k] && !warm[n + k] && closed {
                flags[n + k] = true;
            }
        }
        flags
    }

    /// Whether element `k` was open at the step's start (its anchor is
    /// NaN): closed in this step, it carries no shear until the next.
    pub fn closing(&self, k: usize) -> bool {
        self.friction
            .as_ref()
            .is_some_and(|f| f.anchors[k].is_nan())
    }

    /// The slip traction of element `k` as a function of its displacements
    /// (docs/method.md §6.15): its friction load c b_t with c = s μ p(u_e),
    /// the pressure affine in u_e; p(0) is
    /// [`ContactSet::pressure`] of zero displacements. Gives (μ, b_t, ∇p);
    /// `None` when frictionless.
    pub fn slip_coupling(&self, k: usize) -> Option<(f64, [f64; 6], [f64; 6])> {
        let f = self.friction.as_ref()?;
        let p0 = self.pressure(k, &[0.0; 6]);
        // Exact differences: the pressure is affine in u_e.
        let gradient = std::array::from_fn(|c| {
            let mut e = [0.0; 6];
            e[c] = 1.0;
            self.pressure(k, &e) - p0
        });
        let w = self.laws[k].weight;
        Some((f.mu[k], f.bt[k].map(|v| w * v), gradient))
    }

    /// The friction load factor of slipping element `k` at element
    /// displacements `ue`, slipping the way the factor `c` it was solved
    /// with does: μ max(p, 0) with the sign of `c` — bit for bit what
    /// [`ContactSet::verdict`] gives it when it keeps slipping.
    pub fn slip_load(&self, k: usize, ue: &[f64; 6], c: f64) -> f64 {
        let mu = self.friction.as_ref().map_or(0.0, |f| f.mu[k]);
        (mu * self.pressure(k, ue).max(0.0)).copysign(c)
    }

    /// The verdict of the frictional law on element displacements
    /// `values(k)` of a solve with the flags `current` (over parts) and
    /// friction load factors `c` (docs/method.md §6.15): the active flags
    /// over parts — the inversion test for the normal parts, and for each
    /// active element whether it sticks — and the next load factors:
    /// G_c γ_p/T when sticking, −μ p sign(τ) when slipping, 0 when open.
    ///
    /// A sticking element slips when its shear τ = (G_c/T)(γ − γ_p) exceeds
    /// μ p, along τ. A slipping element (shear τ_s = −c) keeps slipping
    /// while its slip Δγ_p = γ − γ_p − τ_s T/G_c goes along τ_s, and sticks
    /// when its slip turns back: the smallest change that can restore the
    /// dissipation's sign. (Judging it by its trial shear (G_c/T)(γ − γ_p)
    /// instead, the penalty G_c/T magnifies any sway of the bodies past μp:
    /// slip zones swap direction from iteration to iteration and never
    /// stick.) An element that was not active in the solve but was closed
    /// at the step's start closes again slipping along its trial shear
    /// (G_c/T)(γ − γ_p), with the load factor ±0 (its direction): its
    /// pressure was that of a free element, so μp is not known yet, and
    /// its trial shear, from the slip its nodes made while it was open, is
    /// as large as that slip (G_c/T is the penalty's); closed sticking, it
    /// took that shear, which pulled it open again, and the edge of
    /// contact cycled (Cattaneo–Mindlin at a/64). A slip that turns back
    /// in the next solve sticks. An element open
    /// at the step's start ([`ContactSet::closing`]) that closes has its
    /// normal part only, no shear, for the rest of the step: where along the
    /// step it closed, hence its stress-free shear, is not known until the
    /// step ends, and anchored at the step's start, a closing element on a
    /// curved gap (whose γ moved while it was open) took a shear that opened
    /// it again, and the edge of contact cycled. Frictionless: the inversion
    /// test and no loads.
    pub fn verdict(
        &self,
        current: &[bool],
        c: &[f64],
        values: impl Fn(usize) -> [f64; 6],
    ) -> Result<Verdict> {
        let normal = self.inverted(current, &values)?;
        let Some(f) = &self.friction else {
            return Ok(Verdict {
                flags: normal,
                ..Verdict::default()
            });
        };
        let n = self.len();
        let mut flags = normal.clone();
        flags.resize(2 * n, false);
        let mut next = vec![0.0; n];
        for k in (0..n).filter(|&k| normal[k] && !f.anchors[k].is_nan()) {
            let ue = values(k);
            let limit = f.mu[k] * self.law_pressure(k, &ue).max(0.0);
            let gamma = 2.0 * dot6(&f.bt[k], &ue);
            let shear = f.g_over_t[k] * (gamma - f.anchors[k]);
            // The direction it slips in, if it slips.
            let slips_along = if !current[k] {
                // Closing again: it slips along its trial shear, with a
                // load of zero that the next solve makes μp (a coupled
                // solve at once), and sticks there if its slip turns back.
                if shear != 0.0 {
                    next[k] = -(0.0f64.copysign(shear));
                    continue;
                }
                None
            } else if current[n + k] {
                (shear.abs() > limit * (1.0 + SWITCH_TOL)).then_some(shear)
            } else {
                let tau = -c[k];
                let slip = gamma - f.anchors[k] - tau / f.g_over_t[k];
                match tau == 0.0 {
                    // No traction to judge the slip by: its shear decides.
                    true => (shear.abs() > limit).then_some(shear),
                    false => (slip * tau >= -SWITCH_TOL * tau * tau / f.g_over_t[k]).then_some(tau),
                }
            };
            match slips_along {
                Some(direction) => next[k] = -limit.copysign(direction),
                None => {
                    flags[n + k] = true;
                    next[k] = f.g_over_t[k] * f.anchors[k];
                }
            }
        }
        Ok(Verdict { flags, loads: next })
    }

    /// The frictional state of a converged solve: flags over parts, load
    /// factors `c` it was solved with, element displacements `values(k)`.
    /// `None` when frictionless.
    pub fn friction_outcome(
        &self,
        active: &[bool],
        c: &[f64],
        values: impl Fn(usize) -> [f64; 6],
    ) -> Option<FrictionOutcome> {
        let f = self.friction.as_ref()?;
        let n = self.len();
        let mut out = FrictionOutcome {
            state: vec![0; n],
            shear: vec![0.0; n],
            dissipation: vec![0.0; n],
            next: FrictionState {
                anchors: f.anchors.clone(),
                loads: c.to_vec(),
                openings: Vec::with_capacity(n),
                at: f64::NAN,
                load_key: 0,
            },
            closed: Vec::new(),
        };
        for k in 0..n {
            let ue = values(k);
            let gamma = 2.0 * dot6(&f.bt[k], &ue);
            out.next.openings.push(self.opening(k, &ue));
            let anchor = &mut out.next.anchors[k];
            if !active[k] {
                // An open element forgets its slip: should it close, it
                // carries no shear in that step, and sticks from where the
                // step left it.
                *anchor = f64::NAN;
            } else if anchor.is_nan() {
                // Closed in this step without shear: stress-free where the
                // step left it, sticking from there (its stick load, which
                // [`ContactSet::warm_flags`] recognises).
                out.state[k] = 1;
                *anchor = gamma;
                out.next.loads[k] = f.g_over_t[k] * gamma;
                out.closed.push(k);
            } else if active[n + k] {
                out.state[k] = 1;
                out.shear[k] = f.g_over_t[k] * (gamma - f.anchors[k]);
            } else {
                out.state[k] = 2;
                let tau = -c[k];
                out.shear[k] = tau;
                // Stress-free at the slipped position: τ = (G_c/T)(γ − γ_p).
                *anchor = gamma - tau / f.g_over_t[k];
                // The slip as the verdict judged it, which let it slip only
                // along τ; here γ is read from the refined field, so a slip
                // that vanishes may turn back in round-off: that counts
                // zero, not a negative dissipation.
                let slip = gamma - f.anchors[k] - tau / f.g_over_t[k];
                out.dissipation[k] = (0.5 * tau * slip).max(0.0);
            }
            // Reported as the traction, like the pressure; the forces
            // (`Solution`) scale it back by the facing share.
            out.shear[k] /= self.elements[k].facing_share();
        }
        Some(out)
    }

    /// The inversion test: which elements are inverted for the element
    /// displacements `values(k)` of element `k`, the flags `current` (over
    /// parts) being those the displacements were solved with. An element
    /// whose apex projects beyond its interface edge reads the gap on the
    /// edge's line extended to the apex, off the other body's surface by
    /// its bend there (docs/method.md §6.11): it switches on only when its
    /// support, the element with the same apex whose edge lies under it, is
    /// inverted too (the apex has crossed the other body's surface), and
    /// once on it stays on while it is inverted.
    ///
    /// A non-finite opening (displacements near the overflow threshold: the
    /// opening multiplies them by the element's size) is refused as
    /// `NumericalFailure` naming the element: compared with 0 it would
    /// read "open" and release the element, and the loop then reported the
    /// body as unrestrained (SINGULAR) instead of the overflow.
    pub fn inverted(
        &self,
        current: &[bool],
        values: impl Fn(usize) -> [f64; 6],
    ) -> Result<Vec<bool>> {
        let test = self.options.test;
        let j: Vec<f64> = self
            .elements
            .iter()
            .enumerate()
            .map(|(k, el)| {
                let ue = values(k);
                match test {
                    InversionTest::Linearised => linearised_opening(&self.geos[k], el.normal, &ue),
                    InversionTest::Literal => {
                        let mut x = self.nodes().corners(&el.nodes);
                        for (i, p) in x.iter_mut().enumerate() {
                            p[0] += ue[2 * i];
                            p[1] += ue[2 * i + 1];
                        }
                        TriGeometry::new(&x).j
                    }
                }
            })
            .collect();
        if let Some(k) = j.iter().position(|v| !v.is_finite()) {
            return Err(Error::new(
                Status::NumericalFailure,
                format!(
                    "contact element {}: its opening in the inversion test is {} (the displacements overflow it)",
                    k + self.base,
                    j[k]
                ),
            ));
        }
        Ok((0..j.len())
            .map(|k| j[k] < 0.0 && (current[k] || self.supports[k].is_none_or(|a| j[a] < 0.0)))
            .collect())
    }

    /// The linearised opening of element `k` (the quantity the law
    /// penalises) for element displacements `ue`.
    pub fn opening(&self, k: usize, ue: &[f64; 6]) -> f64 {
        let el = &self.elements[k];
        linearised_opening(&self.geos[k], el.normal, ue)
    }

    /// The contact pressure of active element `k` for element displacements
    /// `ue` (positive in compression): the traction κ × (overlap at its
    /// apex), also for an element whose edge faces the other side in part
    /// only, whose law's own pressure is f_e/ℓ_e of it ([`contact_jmins`]).
    pub fn pressure(&self, k: usize, ue: &[f64; 6]) -> f64 {
        self.law_pressure(k, ue) / self.elements[k].facing_share()
    }

    /// The pressure of element `k`'s law, −E_c o_e/T_e: the traction times
    /// the share of its edge that faces the other side. Its shear is
    /// scaled alike, so that the Coulomb limit compares the two as they act.
    fn law_pressure(&self, k: usize, ue: &[f64; 6]) -> f64 {
        let (el, law) = (&self.elements[k], &self.laws[k]);
        contact_pressure(&self.geos[k], &law.d, el.normal, el.j0, law.t, ue)
    }

    /// The least error in the pressure of element `k` ([`Self::pressure`],
    /// a traction) that the rounding of its displacements `ue` leaves
    /// (docs/method.md §6.14): the opening's rounding times the traction
    /// per unit opening (the law's, over the share of the edge that faces
    /// the other side).
    pub fn pressure_rounding(&self, k: usize, ue: &[f64; 6]) -> f64 {
        let (el, law) = (&self.elements[k], &self.laws[k]);
        opening_rounding(&self.geos[k], el.normal, ue)
            * pressure_per_opening(&law.d, el.normal, law.t)
            / el.facing_share()
    }

    /// The interface unknowns: the free unknowns with a nonzero coefficient
    /// in an element of B — in its matrix, its load, or its inversion test
    /// (the literal test needs every unknown of its nodes). For a straight
    /// interface under the frictionless law these are the normal
    /// components only, half of the contact nodes' unknowns. Sorted.
    pub fn interface_unknowns(&self) -> Vec<usize> {
        let test = self.options.test;
        let mut set = Vec::new();
        for part in 0..self.parts() {
            let (k, cs) = (self.element_of(part), self.stiffness(part));
            for a in 0..6 {
                let Some(i) = self.unknowns[k][a] else {
                    continue;
                };
                let coupled = cs.k[a * 6..a * 6 + 6].iter().any(|&v| v != 0.0)
                    || cs.f0[a] != 0.0
                    || match test {
                        InversionTest::Linearised => {
                            let n = self.elements[k].normal;
                            opening_coefficient(&self.geos[k], n, a) != 0.0
                        }
                        InversionTest::Literal => true,
                    };
                if coupled {
                    set.push(i);
                }
            }
        }
        set.sort_unstable();
        set.dedup();
        set
    }

    /// Value positions of `pattern` that hold zero in every matrix of the
    /// solve: zero in the body part `body` and in every element's matrix.
    /// The pattern couples nodes, every unknown of one with every unknown
    /// of the other; a frictionless element with an axis-aligned normal
    /// couples only the normal components, so that the tangential unknowns
    /// of the two surfaces are not coupled at all. Sorted.
    pub fn structural_zeros(&self, pattern: &Pattern, body: &[f64]) -> Vec<usize> {
        let (mut zero, mut nonzero) = (Vec::new(), Vec::new());
        for part in 0..self.parts() {
            let (u, cs) = (self.unknowns(part), self.stiffness(part));
            for a in 0..6 {
                for b in a..6 {
                    let (Some(i), Some(j)) = (u[a], u[b]) else {
                        continue;
                    };
                    let Some(p) = pattern.position(i, j) else {
                        continue;
                    };
                    if cs.k[a * 6 + b] != 0.0 || cs.k[b * 6 + a] != 0.0 || body[p] != 0.0 {
                        nonzero.push(p);
                    } else {
                        zero.push(p);
                    }
                }
            }
        }
        nonzero.sort_unstable();
        zero.sort_unstable();
        zero.dedup();
        zero.retain(|p| nonzero.binary_search(p).is_err());
        zero
    }
}

/// Each element's law: D_c of its pair's softer body `soft(pair)` with
/// E_c (default: that body's E), T = ℓ_e h_c²/λ_c (ℓ_e its interface
/// edge, h_c its pair's shortest one, default λ_c: `size`, the model size;
/// docs/method.md §6.11), and the measure of that body's section at the
/// element's centroid among `nodes`. Refuses a T that is not a positive
/// finite number.
pub fn element_laws(
    nodes: Nodes<'_>,
    elements: &[ContactElement],
    soft: impl Fn(usize) -> Material,
    size: f64,
    options: &ContactOptions,
) -> Result<Vec<ElementLaw>> {
    let lambda_c = options.lambda.unwrap_or(size);
    // docs/method.md §6.11: T_e = ℓ_e h_c² / λ, not h_e³ / λ.
    let jmins = contact_jmins(elements, lambda_c);
    let laws: Vec<ElementLaw> = elements
        .iter()
        .zip(jmins)
        .map(|(el, t)| {
            let soft = soft(el.pair);
            let e_c = options.contact_modulus.unwrap_or(soft.young());
            let d = law_matrix(options.law, e_c, &soft, el.normal);
            let x = nodes.corners(&el.nodes).iter().map(|c| c[0]).sum::<f64>() / 3.0;
            let weight = soft.section().weight(x);
            ElementLaw { d, t, weight }
        })
        .collect();
    if let Some(k) = laws.iter().position(|p| !(p.t > 0.0 && p.t.is_finite())) {
        return Err(Error::new(
            Status::NumericalFailure,
            format!(
                "contact element {}: Jmin = ℓ_e h_c²/λ is not a positive finite number",
                k + nodes.base
            ),
        ));
    }
    Ok(laws)
}

/// The softer of two materials (the first when equal): the default E_c
/// and the stick law's ν of a pair.
pub fn softer(a: Material, b: Material) -> Material {
    if b.young() < a.young() { b } else { a }
}

fn dot6(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    (0..6).map(|i| a[i] * b[i]).sum()
}

/// Each element's load on its free unknowns: the initial-gap load minus
/// the share of the prescribed displacements.
fn element_loads(
    elements: &[ContactElement],
    stiffness: &[ContactStiffness],
    unknowns: &[[Option<usize>; 6]],
    prescribed: &[f64],
) -> Vec<[f64; 6]> {
    let value = |g: usize| prescribed.get(g).copied().unwrap_or(0.0);
    elements
        .iter()
        .enumerate()
        .map(|(k, el)| {
            std::array::from_fn(|a| {
                if unknowns[k][a].is_none() {
                    return 0.0;
                }
                let mut r = stiffness[k].f0[a];
                for b in 0..6 {
                    if unknowns[k][b].is_none() {
                        let g = 2 * el.nodes[b / 2] + b % 2;
                        r -= stiffness[k].k[a * 6 + b] * value(g);
                    }
                }
                r
            })
        })
        .collect()
}

/// One iteration of an active-set loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IterationRecord {
    /// Active contact elements used in this iteration's solve.
    pub active: usize,
    /// Elements the inversion test switched on after the solve.
    pub switched_on: usize,
    /// Elements the inversion test switched off after the solve.
    pub switched_off: usize,
}

/// The slip tractions' load factors of a frictional loop's next solve, and
/// whether they moved in this iteration ([`ActiveSet::advance_with`]).
#[derive(Debug, Clone, Copy)]
pub struct SlipLoads<'l> {
    /// The load factors (empty when frictionless).
    pub loads: &'l [f64],
    /// Whether they changed since the last solve.
    pub moved: bool,
}

impl SlipLoads<'_> {
    /// No slip loads: a frictionless loop.
    pub const NONE: SlipLoads<'static> = SlipLoads {
        loads: &[],
        moved: false,
    };
}

/// The active set of a loop over the elements of B: the current flags,
/// the set it started from, the sets visited (coming back to one is a
/// cycle) and the history of the iterations.
#[derive(Debug, Clone)]
pub struct ActiveSet {
    active: Vec<bool>,
    initial: Vec<bool>,
    visited: HashSet<Vec<bool>>,
    history: Vec<IterationRecord>,
}

impl ActiveSet {
    /// A loop starting from `initial`.
    pub fn new(initial: Vec<bool>) -> ActiveSet {
        let visited = HashSet::from([initial.clone()]);
        ActiveSet {
            active: initial.clone(),
            initial,
            visited,
            history: Vec::new(),
        }
    }

    /// The current flags.
    pub fn active(&self) -> &[bool] {
        &self.active
    }

    /// The flags the loop started from.
    pub fn initial(&self) -> &[bool] {
        &self.initial
    }

    /// One record per iteration so far.
    pub fn history(&self) -> &[IterationRecord] {
        &self.history
    }

    /// Takes the inversion test's verdict `next` on the solution of
    /// iteration `iteration` (solved with the current flags): true when the
    /// set is settled (unchanged); else the flags become `next`, unless
    /// they were visited before — a cycle, refused with the history.
    pub fn advance(&mut self, next: Vec<bool>, iteration: usize) -> Result<bool> {
        self.advance_with(next, SlipLoads::NONE, iteration)
    }

    /// [`ActiveSet::advance`] for a loop whose loads also move (the slip
    /// tractions of a frictional solve, `loads`): settled only when the
    /// flags and the loads both stand still. A cycle
    /// is a revisit of the same flags with the same loads, to the bit: the
    /// same system solved again.
    pub fn advance_with(
        &mut self,
        next: Vec<bool>,
        loads: SlipLoads<'_>,
        iteration: usize,
    ) -> Result<bool> {
        if !loads.loads.is_empty() {
            let state = Self::state_key(&next, loads.loads);
            self.history.push(self.record(&next));
            if next == self.active && !loads.moved {
                return Ok(true);
            }
            if !self.visited.insert(state) {
                return Err(self.not_converged(format!(
                    "the active set and the slip tractions revisited an earlier state at \
                     iteration {iteration} (a cycle)"
                )));
            }
            self.active = next;
            return Ok(false);
        }
        self.history.push(self.record(&next));
        if next == self.active {
            return Ok(true);
        }
        if !self.visited.insert(next.clone()) {
            return Err(self.not_converged(format!(
                "the active set revisited an earlier state at iteration {iteration} (a cycle)"
            )));
        }
        self.active = next;
        Ok(false)
    }

    /// The flags with the loads' fingerprint, as flags, beside them.
    fn state_key(next: &[bool], loads: &[f64]) -> Vec<bool> {
        let key = loads.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, v| {
            (h ^ v.to_bits()).wrapping_mul(0x100_0000_01b3)
        });
        let mut state = next.to_vec();
        state.extend((0..64).map(|b| key >> b & 1 == 1));
        state
    }

    fn record(&self, next: &[bool]) -> IterationRecord {
        let pairs = || next.iter().zip(&self.active);
        IterationRecord {
            active: self.active.iter().filter(|&&a| a).count(),
            switched_on: pairs().filter(|(n, a)| **n && !**a).count(),
            switched_off: pairs().filter(|(n, a)| !**n && **a).count(),
        }
    }

    /// The error of a loop that did not settle in `max_iterations`.
    pub fn not_settled(&self, max_iterations: usize) -> Error {
        self.not_converged(format!(
            "the active set did not settle in {max_iterations} iterations"
        ))
    }

    fn not_converged(&self, what: String) -> Error {
        Error::new(
            Status::NotConverged,
            format!("{what}; history {}", format_history(&self.history)),
        )
    }

    /// The flags and the history.
    pub fn into_parts(self) -> (Vec<bool>, Vec<IterationRecord>) {
        (self.active, self.history)
    }
}

/// The history in a message: every iteration up to eight, else the first
/// three and the last three (a message stays short).
pub fn format_history(h: &[IterationRecord]) -> String {
    let item = |r: &IterationRecord| {
        format!(
            "[active {}, +{}, -{}]",
            r.active, r.switched_on, r.switched_off
        )
    };
    let items: Vec<String> = if h.len() <= 8 {
        h.iter().map(item).collect()
    } else {
        let mut v: Vec<String> = h[..3].iter().map(item).collect();
        v.push(format!("… {} more …", h.len() - 6));
        v.extend(h[h.len() - 3..].iter().map(item));
        v
    };
    items.join(" ")
}

/// Per element of B whose apex projects beyond its interface edge (strip
/// triangulations of non-matching interfaces, docs/method.md §6.11): its
/// support, the element of the same pair with the same apex whose edge the
/// apex projects onto, if any (the first). `None` for every other element,
/// and for all of a conforming B, where each node is the apex of one
/// element.
fn supports(nodes: Nodes<'_>, elements: &[ContactElement]) -> Vec<Option<usize>> {
    // Whether the apex projects on the edge (its ends included); a
    // degenerate edge counts as over it, and has no support.
    let over = |e: &ContactElement| {
        let mut edge = e
            .nodes
            .iter()
            .filter(|&&v| v != e.apex)
            .map(|&v| nodes.x[v]);
        let (Some(p), Some(q)) = (edge.next(), edge.next()) else {
            return true;
        };
        let c = nodes.x[e.apex];
        let d = [q[0] - p[0], q[1] - p[1]];
        let s = ((c[0] - p[0]) * d[0] + (c[1] - p[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]);
        s.is_nan() || (0.0..=1.0).contains(&s)
    };
    let over: Vec<bool> = elements.iter().map(over).collect();
    let mut under: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for (k, e) in elements.iter().enumerate().filter(|&(k, _)| over[k]) {
        under.entry((e.pair, e.apex)).or_insert(k);
    }
    elements
        .iter()
        .enumerate()
        .map(|(k, e)| match over[k] {
            true => None,
            false => under.get(&(e.pair, e.apex)).copied(),
        })
        .collect()
}

/// The active set the loop starts from: per pair, the elements whose gap
/// (J₀ over the interface edge: the apex's distance from the edge) is within
/// 1e-3 of their size of the pair's smallest gap. Touching or uniformly
/// spaced surfaces start fully active (the seed's choice: the first solve
/// pulls a small uniform gap closed, which keeps a body held only by contact
/// restrained); curved ones start from their first points of contact, so
/// that the loop grows the set instead of releasing a glued interface one
/// element at a time.
pub fn initial_active_set(elements: &[ContactElement]) -> Vec<bool> {
    within_smallest_gap(elements, 1e-3)
}

/// Per element: whether its gap is within `tol` of its size of its pair's
/// smallest gap.
fn within_smallest_gap(elements: &[ContactElement], tol: f64) -> Vec<bool> {
    let gap = |e: &ContactElement| {
        if e.edge_length > 0.0 {
            e.j0 / e.edge_length
        } else {
            0.0
        }
    };
    let mut smallest: BTreeMap<usize, f64> = BTreeMap::new();
    for e in elements {
        let g = smallest.entry(e.pair).or_insert(f64::INFINITY);
        *g = g.min(gap(e));
    }
    elements
        .iter()
        .map(|e| gap(e) <= smallest[&e.pair] + tol * e.h)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_set_visited_before_is_a_cycle_and_a_new_one_is_not() {
        let mut set = ActiveSet::new(vec![true, false, true]);
        assert!(!set.advance(vec![true, true, true], 1).unwrap());
        assert!(!set.advance(vec![false, false, false], 2).unwrap());
        let err = set.advance(vec![true, false, true], 3).unwrap_err();
        assert_eq!(err.status(), Status::NotConverged);
        assert!(
            err.message().starts_with(
                "the active set revisited an earlier state at iteration 3 (a cycle); history \
                 [active 2, +1, -0] [active 3, +0, -3] [active 0, +2, -0]"
            ),
            "{}",
            err.message()
        );
    }

    #[test]
    fn an_unchanged_set_is_settled_and_recorded() {
        let mut set = ActiveSet::new(vec![true, true]);
        assert!(set.advance(vec![true, true], 1).unwrap());
        assert_eq!(set.history().len(), 1);
        assert_eq!(set.active(), [true, true]);
    }

    #[test]
    fn a_long_history_is_cut_to_its_first_and_last_iterations() {
        let record = |k: usize| IterationRecord {
            active: k,
            switched_on: 0,
            switched_off: 1,
        };
        let short: Vec<IterationRecord> = (0..8).map(record).collect();
        assert_eq!(format_history(&short).matches("[active").count(), 8);
        let long: Vec<IterationRecord> = (0..50).map(record).collect();
        let text = format_history(&long);
        assert!(text.starts_with("[active 0, +0, -1] [active 1"), "{text}");
        assert!(
            text.contains("… 44 more …") && text.ends_with("[active 49, +0, -1]"),
            "{text}"
        );
    }
}
