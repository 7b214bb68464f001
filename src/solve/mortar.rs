//! The contact solve under the sampled mortar weighting
//! ([`ContactWeighting::Mortar`], docs/method.md §6.11): the active-set
//! loop over the weighted gaps of the slave nodes instead of the elements
//! of B.
//!
//! Each slave node i carries G_i = G_i0 + c_i·u ([`WeightedGap`]) and, while
//! active, the penalty energy ½ (κ/m_i) G_i²: the rank-one stiffness
//! (κ/m_i) c_i c_iᵀ and the load −(κ/m_i) G_i⁰ c_i on the free unknowns (G_i⁰
//! the gap with the free unknowns at rest: the initial one plus the
//! prescribed motion). κ = E_c λ_c / h_c² per pair, the strip's penalty
//! (`contact::law::contact_jmins`), so both weightings penalise a uniform
//! gap alike. A node is active where G_i < 0.
//!
//! The loop is the strip's (`active_set`) in its condensed form: one sparse
//! factorisation of K₁ (the bodies and the initial set, the unknowns of
//! every c_i numbered last), then each iteration a dense solve on those
//! interface unknowns (the factor updated node by node, rank one each, or
//! refactorised when many nodes switch), and the whole field recovered
//! once at the end and refined against the final matrix. Where the
//! interface is too large to hold densely, or the condensed system loses
//! its accuracy, every iteration refactorises the assembled system. The
//! session's pattern holds every c_i's couplings (`cliques`), so any
//! active set assembles.

use super::condensed::{Condensed, ElementMatrix};
use super::linear::{Structure, factor_and_solve};
use super::report::{IterationRecord, SolveInfo, Timings};
use super::session::{Session, Wanted, factorisation};
use super::system::AssembledSystem;
use super::{Input, Outcome};
use crate::contact::law::penalty_lengths;
use crate::contact::mesh::{Nodes, Side};
use crate::contact::mortar::{Basis, Slave, SlaveNode, WeightedGap, coarser_side, weighted_gaps};
use crate::contact::{ActiveSet, ContactLaw, ContactOptions, ContactPair, InversionTest};
use crate::error::{Error, Result, ensure_finite};
use crate::fem::assembly::{NOT_FREE, Pattern};
use crate::fem::mesh::Mesh;
use crate::linalg::Cholesky;
use crate::linalg::refine::{Budget, norm_inf, refine_by};

/// The state of a settled mortar solve, for its outputs: each slave
/// node's state and the weighted gaps they are of (pair by pair, in the
/// nodes' order).
#[derive(Debug, Clone)]
pub(crate) struct MortarState {
    /// Every slave node's state.
    pub nodes: Vec<SlaveNode>,
    /// The weighted gaps of every pair.
    pub gaps: Vec<PairGaps>,
}

/// The weighted gaps of one pair.
#[derive(Debug, Clone)]
pub(crate) struct PairGaps {
    /// The pair's index.
    pub pair: usize,
    /// Its slave side.
    pub slave: Slave,
    /// Its slave nodes' weighted gaps.
    pub gaps: Vec<WeightedGap>,
}

/// The weighted gaps of every pair, the coarser side of each as the slave
/// (a finer slave over-constrains a stiff master: docs/method.md §6.11,
/// "Which side is the slave"). Refuses a pair with a contact mesh of its
/// own (the weighting reads the two sides, not B), naming it.
pub(crate) fn build(mesh: &Mesh, pairs: &[ContactPair]) -> Result<Vec<PairGaps>> {
    let nodes = Nodes::of(mesh);
    let mut all = Vec::with_capacity(pairs.len());
    for (i, p) in pairs.iter().enumerate() {
        if p.user_mesh.is_some() {
            return Err(Error::contact(format!(
                "contact pair {i} (tags {} and {}) has a contact mesh of its own: the mortar \
                 weighting integrates the gap along the two sides and uses no mesh B; drop \
                 the pair's mesh or use the strip weighting",
                p.tag_a, p.tag_b
            )));
        }
        let (a, b) = (Side::of_tag(mesh, p.tag_a)?, Side::of_tag(mesh, p.tag_b)?);
        let named = |e: Error| {
            Error::new(
                e.status(),
                format!("contact pair {i} (mortar weighting): {}", e.message()),
            )
        };
        let slave = coarser_side(nodes, &a, &b).map_err(named)?;
        let gaps = weighted_gaps(nodes, &a, &b, slave, Basis::Dual).map_err(named)?;
        all.push(PairGaps {
            pair: i,
            slave,
            gaps,
        });
    }
    Ok(all)
}

/// Triangles whose node cliques cover the couplings of every weighted gap,
/// for the matrix pattern: (n₀, n_j, n_k) over the gap's nodes.
pub(crate) fn cliques(all: &[PairGaps]) -> Vec<[usize; 3]> {
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

/// One slave node's penalty over the unknowns.
pub(super) struct Penalty {
    /// Index of its pair.
    pair: usize,
    /// The slave node, its tributary m_i and κ/m_i.
    node: usize,
    tributary: f64,
    pub(super) stiffness: f64,
    /// G_i⁰: the gap with the free unknowns at rest.
    pub(super) g_rest: f64,
    /// The initial gap alone (G_i⁰ without the prescribed motion).
    pub(super) g_initial: f64,
    /// Each coefficient's global DOF, its unknown (`None` when
    /// prescribed) and its value.
    dofs: Vec<usize>,
    pub(super) unknowns: Vec<Option<usize>>,
    pub(super) coef: Vec<f64>,
    /// (κ/m_i) c cᵀ, row-major.
    matrix: Vec<f64>,
}

impl Penalty {
    /// G_i for the free unknowns' values read by `value`.
    pub(super) fn gap(&self, value: impl Fn(usize) -> f64) -> f64 {
        self.g_rest
            + self
                .unknowns
                .iter()
                .zip(&self.coef)
                .filter_map(|(u, c)| u.map(|j| c * value(j)))
                .sum::<f64>()
    }

    pub(super) fn element(&self) -> ElementMatrix<'_> {
        ElementMatrix {
            unknowns: &self.unknowns,
            matrix: &self.matrix,
        }
    }

    /// The load −(κ/m_i) G_i⁰ c_i on each free unknown, times `sign`.
    pub(super) fn loads(&self, sign: f64) -> impl Iterator<Item = (usize, f64)> + '_ {
        let f = -sign * self.stiffness * self.g_rest;
        self.unknowns
            .iter()
            .zip(&self.coef)
            .filter_map(move |(u, c)| u.map(|j| (j, f * c)))
    }

    /// Adds its energy (r·K r, Σ K_jj r_j²) for a global vector `r` to
    /// `acc`, as `diagnostics::add_energy` does for an element.
    fn add_energy(&self, acc: &mut (f64, f64), r: &[f64]) {
        let cr: f64 = self
            .dofs
            .iter()
            .zip(&self.coef)
            .map(|(&g, c)| c * r[g])
            .sum();
        acc.0 += self.stiffness * cr * cr;
        acc.1 += self
            .dofs
            .iter()
            .zip(&self.coef)
            .map(|(&g, c)| self.stiffness * (c * r[g]).powi(2))
            .sum::<f64>();
    }

    /// Adds (`sign` +1) or takes out (−1) the penalty in `system`.
    pub(super) fn toggle(&self, system: &mut AssembledSystem, pattern: &Pattern, sign: f64) {
        let unknowns: Vec<usize> = self
            .unknowns
            .iter()
            .map(|u| u.unwrap_or(NOT_FREE))
            .collect();
        let ke: Vec<f64> = self.matrix.iter().map(|v| sign * v).collect();
        system.add_functional(pattern, &unknowns, &ke, self.loads(sign));
    }
}

/// The penalties of every slave node: κ per pair from the pair's E_c
/// (`moduli`), λ_c and h_c.
fn penalties(
    session: &Session,
    mortar: &[PairGaps],
    moduli: &[f64],
    (options, size, prescribed): (&ContactOptions, f64, &[f64]),
) -> Result<Vec<Penalty>> {
    let h_c = penalty_lengths(&session.contact);
    let lambda_c = options.lambda.unwrap_or(size);
    let mut out = Vec::new();
    for pg in mortar {
        let h = h_c.get(&pg.pair).copied().unwrap_or(f64::NAN);
        let kappa = moduli[pg.pair] * lambda_c / (h * h);
        if !(kappa.is_finite() && kappa > 0.0) {
            return Err(Error::contact(format!(
                "contact pair {}: the mortar penalty κ = E_c λ/h_c² = {kappa:e} is not a positive \
                 finite number (E_c {:e}, λ {lambda_c:e}, h_c {h:e})",
                pg.pair, moduli[pg.pair]
            )));
        }
        for wg in &pg.gaps {
            let stiffness = kappa / wg.tributary;
            let (mut unknowns, mut coef) = (Vec::new(), Vec::new());
            let dofs = wg.coefficients.iter().map(|&(g, _)| g).collect();
            let mut g_rest = wg.initial;
            for &(g, c) in &wg.coefficients {
                let j = session.dofs.free(g);
                if j == NOT_FREE {
                    g_rest += c * prescribed[g];
                    unknowns.push(None);
                } else {
                    unknowns.push(Some(j));
                }
                coef.push(c);
            }
            let matrix = coef
                .iter()
                .flat_map(|a| coef.iter().map(move |b| stiffness * a * b))
                .collect();
            out.push(Penalty {
                pair: pg.pair,
                node: wg.node,
                tributary: wg.tributary,
                stiffness,
                g_rest,
                g_initial: wg.initial,
                dofs,
                unknowns,
                coef,
                matrix,
            });
        }
    }
    Ok(out)
}

/// The first set: in each pair, the slave nodes whose mean gap at rest
/// G_i⁰/m_i is within 1e-3 h_c of the pair's smallest (docs/method.md
/// §6.6, as the strip's).
fn initial_set(penalties: &[Penalty], h_c: &std::collections::BTreeMap<usize, f64>) -> Vec<bool> {
    let mut lowest: std::collections::BTreeMap<usize, f64> = Default::default();
    for p in penalties {
        let m = lowest.entry(p.pair).or_insert(f64::INFINITY);
        *m = m.min(p.g_rest / p.tributary);
    }
    penalties
        .iter()
        .map(|p| {
            let h = h_c.get(&p.pair).copied().unwrap_or(0.0);
            p.g_rest / p.tributary <= lowest[&p.pair] + 1e-3 * h
        })
        .collect()
}

/// Refuses options the mortar weighting does not serve (yet), naming them.
pub(super) fn check_options(options: &ContactOptions, pairs: &[ContactPair]) -> Result<()> {
    if options.law != ContactLaw::Frictionless {
        return Err(Error::argument(
            "the mortar weighting is frictionless: the stick law (ContactLaw::Stick) needs the \
             strip weighting",
        ));
    }
    if options.test != InversionTest::Linearised {
        return Err(Error::argument(
            "the mortar weighting activates a slave node on its linearised weighted gap: the \
             literal inversion test needs the strip weighting",
        ));
    }
    if let Some(i) = pairs.iter().position(|p| p.friction > 0.0) {
        return Err(Error::argument(format!(
            "contact pair {i} has friction (mu = {}): the mortar weighting is frictionless \
             for now; set mu = 0 or use the strip weighting",
            pairs[i].friction
        )));
    }
    Ok(())
}

/// How a solve starts: from the initial set, or from a load step's warm
/// start.
#[derive(Debug, Default)]
pub(crate) struct Start<'w> {
    /// The set to start from (`None`: the initial set).
    pub warm: Option<&'w [bool]>,
}

/// What a solve settled by the condensed loop leaves for a load history
/// to go on from ([`super::mortar_history::begin`]): K₁'s set, and the
/// condensed system with the set its factor is of.
pub(crate) struct Settled {
    /// The slave nodes whose penalties K₁ holds.
    pub reference: Vec<bool>,
    /// The condensed interface system.
    pub sys: Condensed,
    /// The set of its factor: the settled one (the loop settles on the
    /// set whose factor solved the last iterate).
    pub factor_set: Vec<bool>,
}

/// A frictionless contact solve under the mortar weighting.
pub(crate) fn solve_contact(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    (info, timings): (SolveInfo, &mut Timings),
    (warnings, start): (Vec<String>, Start<'_>),
) -> Result<Outcome> {
    let (outcome, _) = solve_settled(session, input, options, (info, timings), (warnings, start))?;
    Ok(outcome)
}

/// [`solve_contact`], with what the condensed loop leaves when it settled
/// the set (`None` when the loop refactorised).
pub(crate) fn solve_settled(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    (mut info, timings): (SolveInfo, &mut Timings),
    (mut warnings, start): (Vec<String>, Start<'_>),
) -> Result<(Outcome, Option<Settled>)> {
    check_options(options, input.pairs)?;
    let mesh = input.elements.mesh();
    let penalties = session_penalties(session, input, options)?;
    let n = penalties.len();
    let interface = interface_of(&penalties);
    let condense =
        !options.refactorize && Condensed::worthwhile(interface.len(), session.pattern.nnz());
    let warm = start.warm.filter(|w| w.len() == n).map(<[bool]>::to_vec);
    let reference = match &warm {
        // Refactorising at every iteration, the first factor is the warm
        // set's own.
        Some(w) if !condense => w.clone(),
        _ => initial_set(&penalties, &penalty_lengths(&session.contact)),
    };
    let first = warm.unwrap_or_else(|| reference.clone());
    let Session {
        dofs,
        pattern,
        analysis,
        system,
        ..
    } = &mut *session;
    for (p, _) in penalties.iter().zip(&reference).filter(|(_, on)| **on) {
        p.toggle(system, pattern, 1.0);
    }
    let want = Wanted {
        last: if condense { &interface } else { &[] },
        zeros: &[],
    };
    let structure = (mesh, &*dofs, &*pattern);
    let chol = factorisation(
        analysis,
        structure,
        input.settings,
        want,
        timings,
        &mut info,
    )?;
    let at = Structure {
        mesh,
        dofs,
        pattern,
    };
    let mut run = Run {
        at,
        input,
        penalties: &penalties,
        chol,
        system,
        set: ActiveSet::new(first),
        log: vec![(0..n).filter(|&k| reference[k]).collect()],
        in_system: reference.clone(),
        max_iterations: options.max_iterations,
    };
    let (x, sys) = run.solve(condense.then_some(interface), timings, &mut info)?;
    let log = std::mem::take(&mut run.log);
    let (active, history) = run.set.into_parts();
    info.memory_bytes = at.pattern.memory_bytes()
        + run.system.memory_bytes()
        + run.chol.memory_bytes()
        + sys.as_ref().map_or(0, |s| s.memory_bytes() + 8 * x.len());
    info.relative_residual = run.system.relative_residual(at.pattern, &x);
    info.condition_estimate = run.chol.condition_estimate();
    info.timings = *timings;
    super::finite_statistics(&info)?;
    super::diagnostics::conditioning_warning(&info, &mut warnings);
    let u = dofs.expand(&x, input.prescribed);
    let gaps = session.mortar.clone().unwrap_or_default();
    let contact = outcome((&penalties, gaps), &active, |j| x[j], (history, info), mesh)?;
    let outcome = Outcome {
        u: super::Field::Global(u),
        log,
        info,
        contact: Some(contact),
        warnings,
    };
    let settled = sys.map(|sys| Settled {
        reference,
        sys,
        factor_set: active,
    });
    Ok((outcome, settled))
}

/// The interface unknowns: every free unknown a penalty reads, sorted.
pub(super) fn interface_of(penalties: &[Penalty]) -> Vec<usize> {
    let mut interface: Vec<usize> = penalties
        .iter()
        .flat_map(|p| p.unknowns.iter().flatten().copied())
        .collect();
    interface.sort_unstable();
    interface.dedup();
    interface
}

/// The penalties of the session's weighted gaps for `input` and `options`.
pub(super) fn session_penalties(
    session: &Session,
    input: &Input<'_>,
    options: &ContactOptions,
) -> Result<Vec<Penalty>> {
    let mortar = session.mortar.as_deref().ok_or_else(|| {
        Error::state("the session holds no weighted gaps: its structure predates the weighting")
    })?;
    let moduli = super::pair_moduli(input, &session.contact, &session.dofs, options);
    let size = input.elements.mesh().size();
    penalties(session, mortar, &moduli, (options, size, input.prescribed))
}

/// The loop's state.
pub(super) struct Run<'r, 'a> {
    pub(super) at: Structure<'r>,
    pub(super) input: &'r Input<'a>,
    pub(super) penalties: &'r [Penalty],
    pub(super) chol: &'r mut Cholesky,
    pub(super) system: &'r mut AssembledSystem,
    pub(super) set: ActiveSet,
    /// The penalties the assembled system holds.
    pub(super) in_system: Vec<bool>,
    /// The penalties each assembly switched, in order: replayed onto the
    /// bodies' part, the same operations give the same matrix to the bit
    /// ([`restore`]).
    pub(super) log: Vec<Vec<usize>>,
    pub(super) max_iterations: usize,
}

impl Run<'_, '_> {
    /// Runs the loop to a settled set: the unknowns, and the condensed
    /// system when it settled the loop.
    fn solve(
        &mut self,
        interface: Option<Vec<usize>>,
        timings: &mut Timings,
        info: &mut SolveInfo,
    ) -> Result<(Vec<f64>, Option<Condensed>)> {
        let x1 = self.full_solve(timings, info)?;
        if let Some(interface) = interface {
            if let Some((x, sys)) = self.condensed(interface, x1.clone(), timings, info)? {
                return Ok((x, Some(sys)));
            }
            // Lost to round-off in the condensed system: go on with full
            // solves of the assembled system, which holds the current set.
            return Ok((self.full_loop(None, timings, info)?, None));
        }
        // Refactorising, K₁ holds the first set: its solution is the first
        // iterate.
        Ok((self.full_loop(Some(x1), timings, info)?, None))
    }

    /// Factorises the assembled system and solves it.
    fn full_solve(&mut self, timings: &mut Timings, info: &mut SolveInfo) -> Result<Vec<f64>> {
        let elements = &self.input.elements;
        let (penalties, on) = (self.penalties, &self.in_system);
        // A body held by the penalties alone is restrained: their energy
        // counts when a near-null mode is judged.
        let energy = |r: &[f64]| {
            let mut acc = super::active_set::body_energy(elements, r);
            for (p, _) in penalties.iter().zip(on).filter(|(_, on)| **on) {
                p.add_energy(&mut acc, r);
            }
            acc
        };
        let context = format!(
            " (mortar contact, iteration {})",
            self.set.history().len() + 1
        );
        factor_and_solve(
            self.at,
            self.chol,
            self.system,
            &energy,
            true,
            &context,
            timings,
            info,
        )
    }

    /// The verdict on a solution: active where G_i < 0.
    fn verdict(&self, value: impl Fn(usize) -> f64) -> Vec<bool> {
        self.penalties.iter().map(|p| p.gap(&value) < 0.0).collect()
    }

    /// Makes the assembled system hold the current set.
    fn assemble_set(&mut self) {
        let active = self.set.active().to_vec();
        self.log.push(differing(&active, &self.in_system));
        for (k, p) in self.penalties.iter().enumerate() {
            if active[k] != self.in_system[k] {
                p.toggle(
                    self.system,
                    self.at.pattern,
                    if active[k] { 1.0 } else { -1.0 },
                );
            }
        }
        self.in_system = active;
    }

    /// Iterations that each refactorise the assembled system, from the
    /// solution `x` of its current set (`None`: solve it first).
    fn full_loop(
        &mut self,
        mut x: Option<Vec<f64>>,
        timings: &mut Timings,
        info: &mut SolveInfo,
    ) -> Result<Vec<f64>> {
        loop {
            let xs = match x.take() {
                Some(xs) => xs,
                None => {
                    self.assemble_set();
                    self.full_solve(timings, info)?
                }
            };
            let iteration = self.set.history().len() + 1;
            let next = self.verdict(|j| xs[j]);
            if self.set.advance(next, iteration)? {
                return Ok(xs);
            }
            if iteration >= self.max_iterations {
                return Err(self.set.not_settled(self.max_iterations));
            }
        }
    }

    /// Iterations on the interface, from the solution `x1` of the assembled
    /// system (K₁); the field recovered and refined once settled, with the
    /// bytes the condensed system held. `Ok(None)` when the condensed
    /// system lost its accuracy.
    fn condensed(
        &mut self,
        interface: Vec<usize>,
        x1: Vec<f64>,
        timings: &mut Timings,
        info: &mut SolveInfo,
    ) -> Result<Option<(Vec<f64>, Condensed)>> {
        let t0 = std::time::Instant::now();
        let mut sys = Condensed::new(self.chol, interface)?;
        info.interface_unknowns = sys.len();
        let reference = self.in_system.clone();
        let y = sys.gather(&x1);
        let mut factor_set = reference.clone();
        let ui = self.interface_loop(&mut sys, &y, &reference, &mut factor_set);
        timings.interface += t0.elapsed().as_secs_f64();
        let Some(ui) = ui? else { return Ok(None) };
        let t0 = std::time::Instant::now();
        let x = self.recovered(&sys, x1, &ui, &reference);
        timings.solve += t0.elapsed().as_secs_f64();
        Ok(x?.map(|x| (x, sys)))
    }

    /// The active-set iterations on the interface (S u_I = S₁ y + Δg), from
    /// the reference set K₁ holds, to the settled set's interface values;
    /// `Ok(None)` when the interface matrix of a set is not positive
    /// definite to working accuracy.
    pub(super) fn interface_loop(
        &mut self,
        sys: &mut Condensed,
        y: &[f64],
        reference: &[bool],
        factor_set: &mut Vec<bool>,
    ) -> Result<Option<Vec<f64>>> {
        // A warm start (a load step's) begins with its own set's solve.
        let mut ui = match self.set.active() == reference {
            true => y.to_vec(),
            false => match self.set_solve(sys, y, reference, factor_set)? {
                Some(ui) => ui,
                None => return Ok(None),
            },
        };
        loop {
            let iteration = self.set.history().len() + 1;
            let next = self.verdict(|j| ui[at_interface(sys, j)]);
            if self.set.advance(next, iteration)? {
                return Ok(Some(ui));
            }
            if iteration >= self.max_iterations {
                return Err(self.set.not_settled(self.max_iterations));
            }
            match self.set_solve(sys, y, reference, factor_set)? {
                Some(next) => ui = next,
                None => return Ok(None),
            }
        }
    }

    /// The interface values of the current set: its interface factor made
    /// from the one of `factor_set` (updated node by node, or refactorised
    /// from the reference's), then solved. `Ok(None)` when the set's
    /// interface matrix is not positive definite to working accuracy.
    fn set_solve(
        &self,
        sys: &mut Condensed,
        y: &[f64],
        reference: &[bool],
        factor_set: &mut Vec<bool>,
    ) -> Result<Option<Vec<f64>>> {
        let active = self.set.active();
        let element = |k: usize| {
            let sign = if active[k] { 1.0 } else { -1.0 };
            (self.penalties[k].element(), sign)
        };
        // A rank-one update per node is O(n²), a refactorisation O(n³/3):
        // update while fewer than n/6 nodes switch.
        let changed = differing(active, factor_set);
        let updated = 6 * changed.len() <= sys.len()
            && sys.update(changed.iter().map(|&k| element(k))).is_ok();
        let from_reference = differing(active, reference);
        if !updated
            && sys
                .factorize(from_reference.iter().map(|&k| element(k)))
                .is_err()
        {
            return Ok(None);
        }
        *factor_set = active.to_vec();
        let mut dg = vec![0.0; sys.len()];
        for k in from_reference {
            for (j, f) in self.penalties[k].loads(element(k).1) {
                dg[at_interface(sys, j)] += f;
            }
        }
        Ok(Some(sys.solve(y, &dg)?))
    }

    /// The whole field of the settled set from its interface values `ui`:
    /// u = x₁ + K₁⁻¹P(Δg − ΔC u_I), refined against the final matrix (the
    /// assembled system is brought to the settled set) with the condensed
    /// system as its approximate inverse. `Ok(None)` when the refinement
    /// does not reach [`super::active_set::RECOVERED`].
    fn recovered(
        &mut self,
        sys: &Condensed,
        x1: Vec<f64>,
        ui: &[f64],
        reference: &[bool],
    ) -> Result<Option<Vec<f64>>> {
        self.assemble_set();
        let active = self.set.active();
        let changes: Vec<(usize, f64)> = differing(active, reference)
            .into_iter()
            .map(|k| (k, if active[k] { 1.0 } else { -1.0 }))
            .collect();
        let penalties = self.penalties;
        let mut x = vec![0.0; x1.len()];
        add_changed_forces(penalties, &changes, (sys, ui), true, &mut x);
        self.chol.solve(&mut x)?;
        x.iter_mut().zip(&x1).for_each(|(a, b)| *a += b);
        let (values, rhs) = (self.system.values(), self.system.rhs());
        let (pattern, chol) = (self.at.pattern, &*self.chol);
        let mut approx = |r: &mut [f64]| -> Result<()> {
            // K δ = r: y = K₁⁻¹r, S δ_I = S₁ y_I, δ = y − K₁⁻¹PΔC δ_I.
            chol.solve(r)?;
            let di = sys.solve(&sys.gather(r), &vec![0.0; sys.len()])?;
            let mut p = vec![0.0; r.len()];
            add_changed_forces(penalties, &changes, (sys, &di), false, &mut p);
            chol.solve(&mut p)?;
            r.iter_mut().zip(&p).for_each(|(a, b)| *a += b);
            Ok(())
        };
        let product = |v: &[f64], out: &mut [f64]| pattern.sym_mul(values, v, out);
        let k_norm = norm_inf(pattern, values);
        let omega = refine_by(
            &product,
            k_norm,
            rhs,
            &mut x,
            &mut approx,
            Budget::APPROXIMATE,
        )?;
        let recovered = omega <= super::active_set::RECOVERED && x.iter().all(|v| v.is_finite());
        Ok(recovered.then_some(x))
    }
}

/// The position of free unknown `j` on the interface of `sys` (every
/// penalty's unknowns are there by construction).
pub(super) fn at_interface(sys: &Condensed, j: usize) -> usize {
    sys.position(j)
        .expect("a penalty's unknowns are on the interface")
}

/// Adds −s (κ/m_i)(c_i·v + G_i⁰ if `rest`) c_i of every change (k, s) to
/// `out` (over the free unknowns), v given on the interface of `sys`: the
/// penalty forces −ΔC v of the penalties switched since K₁, with their
/// loads Δg when `rest`.
pub(super) fn add_changed_forces(
    penalties: &[Penalty],
    changes: &[(usize, f64)],
    (sys, v): (&Condensed, &[f64]),
    rest: bool,
    out: &mut [f64],
) {
    for &(k, s) in changes {
        let p = &penalties[k];
        let g = p.gap(|j| v[at_interface(sys, j)]) - if rest { 0.0 } else { p.g_rest };
        for (u, c) in p.unknowns.iter().zip(&p.coef) {
            if let Some(j) = u {
                out[*j] -= s * p.stiffness * g * c;
            }
        }
    }
}

/// The indices where `a` and `b` differ.
pub(super) fn differing(a: &[bool], b: &[bool]) -> Vec<usize> {
    (0..a.len()).filter(|&k| a[k] != b[k]).collect()
}

/// The contact state of the settled loop (the free unknowns' values read
/// by `value`, the interface's at least): each slave node's gap and
/// pressure, the contact length (the active nodes' tributaries) and the
/// largest penetration (of a mean gap G_i/m_i).
pub(super) fn outcome(
    (penalties, gaps): (&[Penalty], Vec<PairGaps>),
    active: &[bool],
    value: impl Fn(usize) -> f64,
    (history, info): (Vec<IterationRecord>, SolveInfo),
    mesh: &Mesh,
) -> Result<super::ContactOutcome> {
    let nodes: Vec<SlaveNode> = penalties
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
    let contact_length = nodes.iter().filter(|n| n.active).map(|n| n.tributary).sum();
    let max_penetration = nodes
        .iter()
        .filter(|n| n.active)
        .fold(0.0f64, |m, n| m.max(-n.gap));
    let report = super::report::ContactReport {
        iterations: history.len(),
        elements: nodes.len(),
        active: nodes.iter().filter(|n| n.active).count(),
        contact_length,
        max_penetration,
        history,
        info,
    };
    Ok(super::ContactOutcome {
        active: Vec::new(),
        pressure: Vec::new(),
        laws: Vec::new(),
        friction: None,
        report,
        mortar: Some(MortarState { nodes, gaps }),
    })
}

/// Rebuilds the final system of a mortar solve onto the bodies' part the
/// session holds: the penalties of each list of `log` (from the solve's
/// `Outcome::log`) switched in turn, in the solve's own order, so that the
/// matrix is the same to the bit.
pub(crate) fn restore(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    log: &[Vec<usize>],
) -> Result<()> {
    let penalties = session_penalties(session, input, options)?;
    let Session {
        system, pattern, ..
    } = &mut *session;
    let mut on = vec![false; penalties.len()];
    for &k in log.iter().flatten() {
        if let Some(p) = penalties.get(k) {
            on[k] = !on[k];
            p.toggle(system, pattern, if on[k] { 1.0 } else { -1.0 });
        }
    }
    Ok(())
}

/// The contact force of every active slave node of `state` on each
/// global DOF its weighted gap reads: p_i c_i, −∂/∂u of its penalty
/// energy, as (pair, global DOF, value).
pub(crate) fn forces(state: &MortarState, mut add: impl FnMut(usize, usize, f64)) {
    let gaps = state.gaps.iter().flat_map(|p| &p.gaps);
    for (wg, s) in gaps.zip(&state.nodes).filter(|(_, s)| s.active) {
        for &(g, c) in &wg.coefficients {
            add(s.pair, g, s.pressure * c);
        }
    }
}

/// A value of the slave nodes (`value` of each) at every node of the mesh:
/// a slave node's own; a master node that a weighted gap reads, the value
/// interpolated along the nearest slave edge (zero at a slave node whose
/// support does not face the master); zero elsewhere. A node on several
/// pairs (where three bodies meet) gets the mean of its pairs' values.
/// Only pair `only` when given.
pub(crate) fn nodal_values(
    mesh: &Mesh,
    pairs: &[ContactPair],
    state: &MortarState,
    only: Option<usize>,
    value: impl Fn(&SlaveNode) -> f64,
) -> Result<Vec<f64>> {
    let x = mesh.nodes();
    let (slaves, gaps) = (&state.nodes, &state.gaps);
    let mut sum = vec![0.0; x.len()];
    let mut count = vec![0u32; x.len()];
    let mut first = 0;
    for pg in gaps {
        let mine = &slaves[first..first + pg.gaps.len()];
        first += pg.gaps.len();
        if only.is_some_and(|o| o != pg.pair) || mine.is_empty() {
            continue;
        }
        let p = &pairs[pg.pair];
        let (a, b) = (Side::of_tag(mesh, p.tag_a)?, Side::of_tag(mesh, p.tag_b)?);
        let slave_side = match pg.slave {
            Slave::A => a,
            Slave::B => b,
        };
        let at: std::collections::HashMap<usize, f64> =
            mine.iter().map(|s| (s.node, value(s))).collect();
        let of = |v: usize| at.get(&v).copied().unwrap_or(0.0);
        let mut read = std::collections::BTreeSet::new();
        for (wg, s) in pg.gaps.iter().zip(mine) {
            sum[s.node] += value(s);
            count[s.node] += 1;
            read.extend(
                wg.coefficients
                    .iter()
                    .map(|&(g, _)| g / 2)
                    .filter(|v| !slave_side.contains(*v)),
            );
        }
        for m in read {
            let (mut best, mut val) = (f64::INFINITY, 0.0);
            for &[p, q] in slave_side.edges() {
                let e = [x[q][0] - x[p][0], x[q][1] - x[p][1]];
                let r = [x[m][0] - x[p][0], x[m][1] - x[p][1]];
                let t = ((r[0] * e[0] + r[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
                let d = (r[0] - t * e[0]).hypot(r[1] - t * e[1]);
                if d < best {
                    (best, val) = (d, (1.0 - t) * of(p) + t * of(q));
                }
            }
            sum[m] += val;
            count[m] += 1;
        }
    }
    Ok(sum
        .iter()
        .zip(&count)
        .map(|(s, &c)| if c > 0 { s / f64::from(c) } else { 0.0 })
        .collect())
}
