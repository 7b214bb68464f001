//! The active-set loop of the contact solve (docs/method.md §3): solve
//! with the active elements of B, find the inverted ones, switch them on
//! and the others off, until the set no longer changes.
//!
//! The first iteration factorises K₁ (bodies plus the initial set). When
//! the interface is condensed ([`Condensed`]), every later iteration is a
//! dense solve on the interface unknowns only, and the whole field is
//! recovered once, at the end, by one more sparse solve: one factorisation
//! per contact solve. Otherwise (or when the condensed matrix turns out
//! singular) every iteration updates the assembled system in place and
//! refactorises it. The loop works over the unknowns throughout; the caller
//! expands the result to global DOFs once.

use std::time::Instant;

use super::condensed::{Condensed, ElementMatrix, LowRank};
use super::diagnostics::add_energy;
use super::friction_loads::FrictionLoads;
use super::linear::{
    Bookkeeping, Energy, Structure, SystemAndFactor, check_finite, factor_and_solve,
};
use super::report::IterationRecord;
use crate::contact::constraints::Constraints;
use crate::contact::{ActiveSet, ContactOptions, SlipLoads, Verdict};
use crate::error::{Error, Result};
use crate::fem::element_loop::ElementLoop;
use crate::linalg::Cholesky;
use crate::linalg::refine::{Budget, norm_inf, refine, refine_by};

/// What the loop works with, borrowed from the session and the problem.
pub(crate) struct LoopInput<'a, 's> {
    /// Mesh, unknowns and pattern.
    pub at: Structure<'a>,
    /// The bodies' energy of a global vector (a near-null mode's judge,
    /// [`body_energy`] for triangles).
    pub body_energy: Energy<'a>,
    /// The constraints the loop switches, with their law.
    pub set: &'a Constraints<'s>,
    /// The interface unknowns to condense on, or `None` to refactorise at
    /// every iteration (the analysis numbered them last).
    pub interface: Option<Vec<usize>>,
    /// The options of the solve.
    pub options: ContactOptions,
}

/// The converged state of the loop.
pub(crate) struct Settled {
    /// The solution over the unknowns.
    pub x: Vec<f64>,
    /// The active set (over the set's parts).
    pub active: Vec<bool>,
    /// The friction load factors (empty when frictionless).
    pub friction_loads: Vec<f64>,
    /// One record per iteration.
    pub history: Vec<IterationRecord>,
    /// Bytes the condensed system held (0 when not condensed).
    pub condensed_bytes: usize,
    /// The openings of the strip's elements in the first iterate
    /// ([`ActiveSetLoop::predicted`]; empty when frictionless).
    pub predicted: Vec<f64>,
}

/// The condensed system with the solution x₁ of K₁ it is relative to, the
/// contact set K₁ holds (the reference of every change) and the set its
/// factor currently represents.
pub(crate) struct CondensedState {
    /// The interface system.
    pub system: Condensed,
    /// K₁⁻¹ times the right-hand side of K₁'s system.
    pub x1: Vec<f64>,
    /// The contact set K₁ holds.
    pub reference: Vec<bool>,
    /// The set the interface factor represents.
    pub factor_active: Vec<bool>,
    /// The friction load factors in K₁'s right-hand side (empty: none).
    pub reference_friction_loads: Vec<f64>,
}

/// How a loop that may stop at the interface settled.
pub(crate) enum Outcome {
    /// Settled on the interface, with the condensed state its values are
    /// relative to; the whole field is [`expand`]ed when needed.
    Interface(Box<InterfaceSettled>),
    /// Settled after a full solve (the condensation ended).
    Full(Box<Settled>),
}

/// A loop settled on the interface.
pub(crate) struct InterfaceSettled {
    /// The condensed state (its factor that of the final set).
    pub state: Box<CondensedState>,
    /// What it settled at.
    pub at_interface: AtInterface,
}

/// The state a loop settled in on the interface.
pub(crate) struct AtInterface {
    /// The interface values.
    pub ui: Vec<f64>,
    /// The final set.
    pub active: Vec<bool>,
    /// The final friction load factors (empty when frictionless).
    pub friction_loads: Vec<f64>,
    /// One record per iteration.
    pub history: Vec<IterationRecord>,
    /// The openings of the strip's elements in the first iterate
    /// ([`ActiveSetLoop::predicted`]; empty when frictionless).
    pub predicted: Vec<f64>,
}

/// A loop that failed: its error, and the condensed state it was resumed
/// with if it still held it (its factor possibly changed).
pub(crate) struct LoopFailure {
    /// Why it failed.
    pub error: Error,
    /// The condensed state, given back.
    pub state: Option<CondensedState>,
}

/// The current solution of the loop.
enum Iterate {
    /// Nothing solved yet.
    None,
    /// A full solve of the assembled system: every unknown.
    Full(Vec<f64>),
    /// The first solve, whose x₁ the condensed state holds (not refined).
    Reference,
    /// A condensed step: the interface values, in the interface's order
    /// (x₁ holds the others, which no contact element reads).
    Condensed(Vec<f64>),
}

/// The active-set loop over the contact elements of one solve.
pub(crate) struct ActiveSetLoop<'a, 's> {
    input: LoopInput<'a, 's>,
    /// The session's system, updated to each iteration's set, and its
    /// factor.
    linear: SystemAndFactor<'a>,
    /// Where the loop's time and statistics go.
    books: Bookkeeping<'a>,
    set: ActiveSet,
    /// The friction load factors of the next solve (docs/method.md §6.15;
    /// empty when frictionless).
    friction: FrictionLoads,
    condensed: Option<CondensedState>,
    iterate: Iterate,
    /// The openings of the strip's elements in the first iterate, solved
    /// with the flags the loop started from: along a load step from a
    /// settled state, that start's response at the step's end, linear in
    /// the load, which says where along the step an open element closes
    /// (a history's sub-steps, docs/method.md §6.15). Frictional sets only.
    predicted: Vec<f64>,
}

/// The backward error a field recovered from the condensed interface must
/// be refined to, or the loop finishes with a full solve instead (and a
/// load step's field is solved by a factorisation of its own matrix): a
/// contact force is a penalty stiffness times an opening a millionth of the
/// displacements, and at 1e-8 (measured: Hertz with the cylinder mesh 10×
/// finer, h = a/32, after three corrections) the forces read from the
/// field were wrong by five times the peak pressure; at 1e-12, by 1e-4 of
/// it.
pub(crate) const RECOVERED: f64 = 1e-12;

/// Passes that bring a condensed solve's slip loads to its recovered field
/// before the loop goes on with full solves instead.
const SLIP_PASSES: usize = 4;

impl<'a, 's> ActiveSetLoop<'a, 's> {
    /// A loop that starts from the constraints' initial set, or from the
    /// flags and friction load factors `start`; `linear`'s system holds the
    /// bodies' part, its factor an analysis of its pattern.
    pub fn new(
        input: LoopInput<'a, 's>,
        linear: SystemAndFactor<'a>,
        books: Bookkeeping<'a>,
        start: Option<(Vec<bool>, Vec<f64>)>,
    ) -> ActiveSetLoop<'a, 's> {
        let (initial, friction) = start.unwrap_or_else(|| {
            let initial = input.set.initial_active();
            let friction = input.set.stick_loads(&initial);
            (initial, friction)
        });
        ActiveSetLoop {
            input,
            linear,
            books,
            set: ActiveSet::new(initial),
            friction: FrictionLoads::new(friction),
            condensed: None,
            iterate: Iterate::None,
            predicted: Vec::new(),
        }
    }

    /// A loop that resumes from a condensed state (K₁ factorised, its
    /// interface system made) and starts from the set `warm` with the
    /// friction load factors `friction` (empty when frictionless).
    pub fn resume(
        input: LoopInput<'a, 's>,
        linear: SystemAndFactor<'a>,
        books: Bookkeeping<'a>,
        state: CondensedState,
        warm: Vec<bool>,
        friction: Vec<f64>,
    ) -> ActiveSetLoop<'a, 's> {
        ActiveSetLoop {
            input,
            linear,
            books,
            set: ActiveSet::new(warm),
            friction: FrictionLoads::new(friction),
            condensed: Some(state),
            iterate: Iterate::None,
            predicted: Vec::new(),
        }
    }

    /// Judges the iterate (the inversion test and, when frictional,
    /// Coulomb's law) and moves the flags and friction loads to the
    /// verdict: true when both stand still.
    fn advance(&mut self, iteration: usize) -> Result<bool> {
        let set = self.input.set;
        if iteration == 1 && set.is_frictional() {
            let strip = set.strip();
            self.predicted = (0..strip.len())
                .map(|k| strip.opening(k, &set.element_values(k, |i| self.value(i))))
                .collect();
        }
        let Verdict {
            flags: next,
            loads: friction,
        } = self.verdict()?;
        let moved = self.friction.advance(friction, next == self.set.active());
        let key = self.friction.state_key(&next).into_owned();
        let loads = SlipLoads { loads: &key, moved };
        self.set.advance_with(next, loads, iteration)
    }

    /// Runs the loop like [`ActiveSetLoop::run`], but stops at the
    /// interface when the last iterate is condensed. On error, gives back
    /// the condensed state it was resumed with (its factor possibly
    /// changed), if the loop still held it.
    pub fn run_to_interface(mut self) -> std::result::Result<Outcome, Box<LoopFailure>> {
        let max_iterations = self.input.options.max_iterations;
        for iteration in 1..=max_iterations {
            let settled = self.solve(iteration).and_then(|()| self.advance(iteration));
            let settled = match settled {
                Ok(s) => s,
                Err(error) => {
                    let state = self.condensed.take();
                    return Err(Box::new(LoopFailure { error, state }));
                }
            };
            if settled {
                return match std::mem::replace(&mut self.iterate, Iterate::None) {
                    Iterate::Condensed(ui) => {
                        let (active, history) = self.set.into_parts();
                        let state = Box::new(self.condensed.expect("a condensed iterate"));
                        let at_interface = AtInterface {
                            ui,
                            active,
                            friction_loads: self.friction.c,
                            history,
                            predicted: self.predicted,
                        };
                        Ok(Outcome::Interface(Box::new(InterfaceSettled {
                            state,
                            at_interface,
                        })))
                    }
                    other => {
                        self.iterate = other;
                        self.recover()
                            .map(|s| Outcome::Full(Box::new(s)))
                            .map_err(|error| Box::new(LoopFailure { error, state: None }))
                    }
                };
            }
        }
        let e = self.set.not_settled(max_iterations);
        let state = self.condensed.take();
        Err(Box::new(LoopFailure { error: e, state }))
    }

    /// Runs the loop (docs/method.md §3): solve with the active elements,
    /// test which are inverted, stop when the set is unchanged, refuse a
    /// set visited before (a cycle) or too many iterations.
    pub fn run(mut self) -> Result<Settled> {
        let max_iterations = self.input.options.max_iterations;
        for iteration in 1..=max_iterations {
            self.solve(iteration)?;
            if self.advance(iteration)? {
                match self.recover_or_go_on()? {
                    Ok(settled) => return Ok(settled),
                    Err(back) => self = *back,
                }
            }
        }
        Err(self.set.not_settled(max_iterations))
    }

    /// One iteration's solve with the current active set: a condensed step
    /// when the interface is condensed and its matrix is definite, else a
    /// full solve.
    fn solve(&mut self, iteration: usize) -> Result<()> {
        if self.condensed.is_some() && self.condensed_step()? {
            return Ok(());
        }
        self.full_step(iteration)
    }

    /// Solves the interface system for the current set; false (and the
    /// condensation ends) when its matrix is singular or nearly so, so that
    /// the full factorisation names the free mode, or accepts an
    /// ill-conditioned but restrained system.
    fn condensed_step(&mut self) -> Result<bool> {
        let t0 = Instant::now();
        let set = self.input.set;
        let state = self.condensed.as_mut().expect("a condensed system");
        let active = self.set.active();
        let sign = |k: usize| if active[k] { 1.0 } else { -1.0 };
        let element = |k: usize| {
            (
                ElementMatrix {
                    unknowns: set.unknowns(k),
                    matrix: set.matrix(k),
                },
                sign(k),
            )
        };
        // Changes since the factorised set, and relative to K₁.
        let changed = differing(active, &state.factor_active);
        let relative = differing(active, &state.reference);
        // A few changes: update the factor (measured: a rank-1 update costs
        // ~1/20 of a refactorisation at 2000 interface unknowns); many:
        // refactorise Ŝ₁ plus the changes relative to K₁.
        let sys = &mut state.system;
        let updated = 24 * changed.len() <= sys.len()
            && sys.is_factored()
            && sys.update(changed.iter().map(|&k| element(k))).is_ok();
        let factored = updated || sys.factorize(relative.iter().map(|&k| element(k))).is_ok();
        state.factor_active.clear();
        state.factor_active.extend_from_slice(active);
        if factored {
            let (ui, coupled) =
                interface_solve(set, state, active, &relative, &mut self.friction.c)?;
            self.friction.coupled = coupled;
            self.iterate = Iterate::Condensed(ui);
        } else {
            self.condensed = None;
        }
        self.books.timings.interface += t0.elapsed().as_secs_f64();
        Ok(factored)
    }

    /// Updates the assembled system to the current set, factorises and
    /// solves it. In the first iteration of a condensed loop, its factor
    /// gives the condensed system.
    fn full_step(&mut self, iteration: usize) -> Result<()> {
        let input = &self.input;
        let (at, set) = (input.at, input.set);
        let t0 = Instant::now();
        let active = self.set.active();
        self.linear.system.set_contact(active, set, at.pattern);
        self.linear.system.set_friction_loads(set, &self.friction.c);
        self.friction.coupled = false;
        self.books.timings.assembly += t0.elapsed().as_secs_f64();
        let energy = |r: &[f64]| {
            let mut acc = (input.body_energy)(r);
            for k in (0..set.parts()).filter(|&k| active[k]) {
                set.add_energy(k, &mut acc, r);
            }
            acc
        };
        let n_active = active.iter().filter(|&&a| a).count();
        let context =
            format!(" (contact iteration {iteration}, {n_active} active contact elements)");
        let condense = iteration == 1 && input.interface.is_some();
        // A condensed loop refines its final solution against the final
        // matrix; refining x₁ as well would be wasted.
        let (linear, books) = (&mut self.linear, &mut self.books);
        let x = factor_and_solve(at, linear, &energy, !condense, &context, books)?;
        if !condense {
            self.iterate = Iterate::Full(x);
            return Ok(());
        }
        let t0 = Instant::now();
        let interface = input.interface.clone().expect("condensing");
        let system = Condensed::new(self.linear.chol, interface)?;
        self.books.info.interface_unknowns = system.len();
        self.condensed = Some(CondensedState {
            system,
            x1: x,
            reference: self.set.active().to_vec(),
            factor_active: self.set.active().to_vec(),
            reference_friction_loads: self.friction.c.clone(),
        });
        self.iterate = Iterate::Reference;
        self.books.timings.interface += t0.elapsed().as_secs_f64();
        Ok(())
    }

    /// The value of unknown `i` in the current iterate.
    fn value(&self, i: usize) -> f64 {
        match (&self.iterate, &self.condensed) {
            (Iterate::Full(x), _) => x[i],
            (Iterate::Reference, Some(c)) => c.x1[i],
            (Iterate::Condensed(ui), Some(c)) => match c.system.position(i) {
                Some(p) => ui[p],
                None => c.x1[i],
            },
            _ => unreachable!("an iterate without its condensed system"),
        }
    }

    /// The contact law's verdict on the current iterate
    /// ([`ContactSet::verdict`]).
    fn verdict(&self) -> Result<Verdict> {
        let (active, c) = (self.set.active(), &self.friction.c[..]);
        self.input.set.verdict(active, c, |i| self.value(i))
    }

    /// The settled solution over all unknowns, refined against the final
    /// system, which the assembled system then holds.
    fn recover(self) -> Result<Settled> {
        match self.recover_or_go_on()? {
            Ok(settled) => Ok(settled),
            Err(_) => unreachable!("only a condensed iterate goes on"),
        }
    }

    /// [`ActiveSetLoop::recover`], or the loop back (`Err`) when the field
    /// recovered from a condensed iterate is not refined below
    /// [`RECOVERED`], or its slip loads disagree with its pressures by more
    /// than [`FRICTION_TOL`](super::friction_loads::FRICTION_TOL): the interface solve lost that much to
    /// round-off (measured: 0.7 % on a model with a DOF prescribed at
    /// 1e30). The loop then goes on with full solves of the assembled
    /// system, which holds the final set.
    #[allow(clippy::type_complexity)]
    fn recover_or_go_on(mut self) -> Result<std::result::Result<Settled, Box<Self>>> {
        let condensed_bytes = self
            .condensed
            .as_ref()
            .map_or(0, |c| c.system.memory_bytes() + 8 * c.x1.len());
        let context = format!(
            " (contact solution after {} iterations)",
            self.set.history().len()
        );
        let x = match std::mem::replace(&mut self.iterate, Iterate::None) {
            Iterate::Full(x) => x,
            Iterate::Reference => self.refine_reference(&context)?,
            Iterate::Condensed(ui) => {
                let (x, omega) = self.expand_condensed(ui, &context)?;
                let holds = self.friction.hold(self.input.set, self.set.active(), &x);
                if omega.is_nan() || omega > RECOVERED || !holds {
                    self.friction.coupled = false;
                    return Ok(Err(Box::new(self)));
                }
                x
            }
            Iterate::None => unreachable!("the loop solved before settling"),
        };
        let (active, history) = self.set.into_parts();
        Ok(Ok(Settled {
            x,
            active,
            friction_loads: self.friction.c,
            history,
            condensed_bytes,
            predicted: self.predicted,
        }))
    }

    /// Settled at once: x₁ is the answer, not yet refined.
    fn refine_reference(&mut self, context: &str) -> Result<Vec<f64>> {
        let state = self.condensed.take().expect("x₁ of the condensed loop");
        let t0 = Instant::now();
        let mut x = state.x1;
        drop(state.system);
        let (pattern, chol) = (self.input.at.pattern, &mut *self.linear.chol);
        let (values, rhs) = (self.linear.system.values(), self.linear.system.rhs());
        refine(pattern, values, rhs, &mut x, &mut |r| chol.solve(r))?;
        check_finite(self.input.at, &x, context)?;
        self.books.timings.solve += t0.elapsed().as_secs_f64();
        Ok(x)
    }

    /// The last iterate is condensed: recovers the whole field, with its
    /// backward error.
    fn expand_condensed(&mut self, ui: Vec<f64>, context: &str) -> Result<(Vec<f64>, f64)> {
        let CondensedState {
            system,
            x1,
            reference,
            reference_friction_loads,
            ..
        } = self.condensed.take().expect("condensed");
        let input = &self.input;
        let t0 = Instant::now();
        let active = self.set.active();
        self.linear
            .system
            .set_contact(active, input.set, input.at.pattern);
        self.linear
            .system
            .set_friction_loads(input.set, &self.friction.c);
        self.books.timings.assembly += t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let (values, rhs) = (self.linear.system.values(), self.linear.system.rhs());
        let pattern = input.at.pattern;
        let target = Target {
            at: input.at,
            set: input.set,
            active,
            product: &|v: &[f64], y: &mut [f64]| pattern.sym_mul(values, v, y),
            k_norm: &|| norm_inf(pattern, values),
            rhs,
            friction_loads: &self.friction.c,
            reference_friction_loads: &reference_friction_loads,
        };
        let (mut x, mut omega) = expand(target, self.linear.chol, &system, &reference, x1, ui)?;
        if x.iter().any(|v| !v.is_finite()) {
            // Lost in the condensed solve: the loop goes on with full
            // solves (which report an overflow of the problem itself), and
            // no slip load is taken from it.
            self.books.timings.solve += t0.elapsed().as_secs_f64();
            return Ok((x, f64::NAN));
        }
        // The slip loads came from the interface solve; the refined field's
        // pressures differ by its round-off (measured 1e-10 to 5e-9 of the
        // largest slip load from 67k to 1M unknowns, seed scene, μ = 0.3):
        // bring the loads to the field, a refinement each.
        for _ in 0..SLIP_PASSES {
            let input = &self.input;
            if self.friction.hold(input.set, self.set.active(), &x) {
                break;
            }
            self.friction.take(input.set, self.set.active(), &x);
            self.linear
                .system
                .set_friction_loads(input.set, &self.friction.c);
            let (values, rhs) = (self.linear.system.values(), self.linear.system.rhs());
            let target = Target {
                at: input.at,
                set: input.set,
                active: self.set.active(),
                product: &|v: &[f64], y: &mut [f64]| pattern.sym_mul(values, v, y),
                k_norm: &|| norm_inf(pattern, values),
                rhs,
                friction_loads: &self.friction.c,
                reference_friction_loads: &reference_friction_loads,
            };
            omega = refine_expanded(target, self.linear.chol, &system, &reference, &mut x)?;
        }
        self.books.timings.solve += t0.elapsed().as_secs_f64();
        check_finite(self.input.at, &x, context)?;
        Ok((x, omega))
    }
}

/// Solves the interface system of the factored condensed `state` for the
/// flags `active` (`relative`: the parts that differ from K₁'s set). With
/// slipping elements their slip loads are implicit (docs/method.md §6.15)
/// and `friction` becomes the loads the solve implied, as the verdict reads
/// them; without, or when the coupled solve declines, the loads `friction`
/// are explicit. Gives u_I, and whether the slip loads were implicit (or
/// there were none).
fn interface_solve(
    set: &Constraints<'_>,
    state: &mut CondensedState,
    active: &[bool],
    relative: &[usize],
    friction: &mut [f64],
) -> Result<(Vec<f64>, bool)> {
    let sys = &mut state.system;
    let sign = |k: usize| if active[k] { 1.0 } else { -1.0 };
    let mut g = vec![0.0; sys.len()];
    for &k in relative {
        for (u, f) in set.unknowns(k).iter().zip(set.load(k)) {
            if let Some(p) = u.and_then(|i| sys.position(i)) {
                g[p] += sign(k) * f;
            }
        }
    }
    let y = sys.gather(&state.x1);
    let slipping = set.slipping(active);
    if !slipping.is_empty() {
        let (coupling, loads) = slip_coupling(set, sys, &state.x1, friction, &slipping);
        let mut g = g.clone();
        add_friction_loads(set, sys, &loads, &state.reference_friction_loads, &mut g);
        if let Some(ui) = sys.solve_with(&y, &g, &coupling)? {
            for &k in &slipping {
                let value = |i: usize| sys.position(i).map_or(state.x1[i], |p| ui[p]);
                friction[k] = set.slip_load(k, value, friction[k]);
            }
            return Ok((ui, true));
        }
    }
    add_friction_loads(set, sys, friction, &state.reference_friction_loads, &mut g);
    Ok((sys.solve(&y, &g)?, slipping.is_empty()))
}

/// Adds the friction loads Σ_e (c_e − c_ref,e) b_t,e to the interface
/// right-hand side `g` (they are on the interface, where b_t is).
fn add_friction_loads(
    set: &Constraints<'_>,
    sys: &Condensed,
    c: &[f64],
    c_ref: &[f64],
    g: &mut [f64],
) {
    set.add_friction_loads(c, c_ref, |i, v| {
        g[sys
            .position(i)
            .expect("friction loads are on the interface")] += v;
    });
}

/// The slip coupling of the slipping elements `(k, c_k)` on the interface
/// (docs/method.md §6.15): element k's friction load c b_t with
/// c = s μ p(u_e), s the sign of c_k and the pressure p affine in u_e, is
/// the unsymmetric rank-one term −s μ b_t ∇pᵀ on the interface unknowns
/// (moved to the matrix) plus the load s μ p(u_e⁰) b_t, u_e⁰ the element's
/// values off the interface (prescribed, or x₁'s). Gives the change
/// U Vᵀ and the friction load factors with that constant part in place of
/// the slipping elements' c_k (the others unchanged).
fn slip_coupling(
    set: &Constraints<'_>,
    sys: &Condensed,
    x1: &[f64],
    c: &[f64],
    slipping: &[usize],
) -> (LowRank, Vec<f64>) {
    let mut change = LowRank::default();
    let mut loads = c.to_vec();
    for &k in slipping {
        let (mu, bt, gradient) = set.slip_coupling(k).expect("a frictional set");
        let s = c[k].signum();
        let (mut u, mut v) = (Vec::with_capacity(6), Vec::with_capacity(6));
        // Off the interface: prescribed, or x₁'s.
        let rest = set.element_values(k, |i| sys.position(i).map_or(x1[i], |_| 0.0));
        for (a, unknown) in set.unknowns(k).iter().enumerate() {
            if let Some(p) = unknown.and_then(|i| sys.position(i)) {
                if bt[a] != 0.0 {
                    u.push((p, -s * mu * bt[a]));
                }
                if gradient[a] != 0.0 {
                    v.push((p, gradient[a]));
                }
            }
        }
        loads[k] = s * mu * set.slip_pressure(k, &rest);
        change.u.push(u);
        change.v.push(v);
    }
    (change, loads)
}

/// The system a condensed solution is expanded for: the contact set with
/// its active flags, and the matrix (its product and norm) and right-hand
/// side of that set (for the refinement).
pub(crate) struct Target<'t, 's> {
    /// Mesh, unknowns and pattern.
    pub at: Structure<'t>,
    /// The constraints.
    pub set: &'t Constraints<'s>,
    /// The final set.
    pub active: &'t [bool],
    /// y = K v with the matrix of the final set.
    pub product: &'t dyn Fn(&[f64], &mut [f64]),
    /// ‖K‖∞, computed when the refinement needs it.
    pub k_norm: &'t dyn Fn() -> f64,
    /// The right-hand side of the final set.
    pub rhs: &'t [f64],
    /// The final friction loads (empty: none).
    pub friction_loads: &'t [f64],
    /// The friction loads of K₁'s right-hand side (empty: none).
    pub reference_friction_loads: &'t [f64],
}

/// Recovers the whole field from the interface values `ui` of the final
/// set, u = x₁ + K₁⁻¹ P(Δg + ΔC u_I) — ΔC and Δg the changes of the
/// contact elements' matrices and loads relative to K₁'s set — refined
/// against the final matrix itself, with its backward error
/// ([`refine_expanded`]). One sparse solve (and two per refinement step,
/// normally none).
pub(crate) fn expand(
    target: Target<'_, '_>,
    chol: &Cholesky,
    sys: &Condensed,
    reference: &[bool],
    x1: Vec<f64>,
    ui: Vec<f64>,
) -> Result<(Vec<f64>, f64)> {
    let changes = Changes::of(&target, reference);
    let mut x = changes.product(&|j| ui[interface_position(sys, j)], true);
    // Near the solve's memory peak: free the vectors done with.
    drop(ui);
    chol.solve(&mut x)?;
    x.iter_mut().zip(&x1).for_each(|(a, b)| *a += b);
    drop(x1);
    let omega = refine_expanded(target, chol, sys, reference, &mut x)?;
    Ok((x, omega))
}

/// Refines a field `x` of the final set against its matrix and right-hand
/// side (`target`), each correction solved through the condensed system
/// like [`expand`], which is only an approximate inverse of the final
/// matrix ([`Budget::APPROXIMATE`]); gives the backward error reached.
pub(crate) fn refine_expanded(
    target: Target<'_, '_>,
    chol: &Cholesky,
    sys: &Condensed,
    reference: &[bool],
    x: &mut [f64],
) -> Result<f64> {
    let changes = Changes::of(&target, reference);
    let mut solve = |r: &mut [f64]| -> Result<()> {
        // K δ = r: y = K₁⁻¹r, S δ_I = S₁ y_I, δ = y + K₁⁻¹PΔC δ_I.
        chol.solve(r)?;
        let di = sys.solve(&sys.gather(r), &vec![0.0; sys.len()])?;
        let mut p = changes.product(&|j| di[interface_position(sys, j)], false);
        chol.solve(&mut p)?;
        r.iter_mut().zip(&p).for_each(|(a, b)| *a += b);
        Ok(())
    };
    let k_norm = (target.k_norm)();
    refine_by(
        target.product,
        k_norm,
        target.rhs,
        x,
        &mut solve,
        Budget::APPROXIMATE,
    )
}

/// The contact elements whose state differs between K₁ (the initial set)
/// and the final set.
struct Changes<'c, 's> {
    set: &'c Constraints<'s>,
    active: &'c [bool],
    initial: &'c [bool],
    n: usize,
    /// The final friction loads.
    friction_loads: &'c [f64],
    /// K₁'s friction loads.
    reference_friction_loads: &'c [f64],
}

/// The interface position of an unknown a contact element couples.
fn interface_position(sys: &Condensed, j: usize) -> usize {
    sys.position(j)
        .expect("coupled unknowns are on the interface")
}

impl<'c, 's> Changes<'c, 's> {
    /// The changes of `target`'s set relative to K₁'s set `reference`.
    fn of(target: &Target<'c, 's>, reference: &'c [bool]) -> Changes<'c, 's> {
        Changes {
            set: target.set,
            active: target.active,
            initial: reference,
            n: target.at.dofs.n_free(),
            friction_loads: target.friction_loads,
            reference_friction_loads: target.reference_friction_loads,
        }
    }

    /// p = ΔC v_I − Δg over the unknowns (the load only `with_load`),
    /// ΔC = C₁ − C and Δg = g₁ − g: what the elements removed since K₁ took
    /// out of it and its load, minus what the added ones put in. `v` gives
    /// the value of an interface unknown.
    fn product(&self, v: &dyn Fn(usize) -> f64, with_load: bool) -> Vec<f64> {
        let set = self.set;
        let mut p = vec![0.0; self.n];
        for k in differing(self.active, self.initial) {
            let removed = if self.initial[k] { 1.0 } else { -1.0 };
            let (unknowns, stiffness) = (set.unknowns(k), set.matrix(k));
            let n = unknowns.len();
            for a in 0..n {
                let Some(i) = unknowns[a] else { continue };
                let mut r = if with_load { -set.load(k)[a] } else { 0.0 };
                for b in 0..n {
                    let c = stiffness[a * n + b];
                    // (Only interface unknowns have coefficients.)
                    if let (Some(j), true) = (unknowns[b], c != 0.0) {
                        r += c * v(j);
                    }
                }
                p[i] += removed * r;
            }
        }
        if with_load {
            let (loads, reference) = (self.friction_loads, self.reference_friction_loads);
            set.add_friction_loads(loads, reference, |i, v| p[i] += v);
        }
        p
    }
}

/// The elements whose flags differ between two sets.
fn differing(a: &[bool], b: &[bool]) -> Vec<usize> {
    (0..a.len()).filter(|&k| a[k] != b[k]).collect()
}

/// (rᵀKr, Σ diag energy) of the body elements for a global vector r.
pub(crate) fn body_energy(elements: &ElementLoop<'_>, r: &[f64]) -> (f64, f64) {
    let mut acc = (0.0, 0.0);
    let _ = elements.for_each(|el| {
        if let Ok(ke) = elements.stiffness(el) {
            add_energy(&mut acc, &ke, r, el.nodes);
        }
        Ok(())
    });
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::InversionTest;
    use crate::model::{Component, Problem};
    use crate::solve::fixtures::{assembled, contact_set, two_blocks};
    use crate::solve::report::{SolveInfo, Timings};
    use crate::solve::session::{Session, Settings, Wanted, factorisation};

    /// Solves `p` with the active set `active` held fixed: one loop
    /// iteration from it, refactorising (`condense` false) or condensing
    /// the changes relative to the initial set. Returns the final iterate's
    /// values over the unknowns after `recover`, and the interface unknowns.
    fn solve_with(
        p: &Problem,
        active: Option<Vec<bool>>,
        condense: bool,
    ) -> (Vec<f64>, Vec<usize>) {
        let (mut session, prescribed) = assembled(p);
        let mesh = p.mesh().unwrap();
        let elements = p.elements().unwrap();
        let Session {
            dofs,
            pattern,
            contact,
            analysis,
            system,
            ..
        } = &mut session;
        let options = ContactOptions {
            test: InversionTest::Linearised,
            ..Default::default()
        };
        let set = contact_set(p, contact.strip(), dofs, &prescribed, &options);
        let set = Constraints::new(set, Default::default(), &prescribed);
        let interface = set.interface_unknowns();
        let want = Wanted {
            last: if condense { &interface } else { &[] },
            zeros: &[],
        };
        let (mut timings, mut info) = (Timings::default(), SolveInfo::default());
        let at = Structure {
            mesh,
            dofs,
            pattern,
        };
        let mut books = Bookkeeping::new(&mut timings, &mut info);
        let chol = factorisation(analysis, at, Settings::default(), want, &mut books).unwrap();
        let energy = |r: &[f64]| body_energy(&elements, r);
        let input = LoopInput {
            at,
            body_energy: &energy,
            set: &set,
            interface: condense.then(|| interface.clone()),
            options,
        };
        let linear = SystemAndFactor { chol, system };
        let mut lp = ActiveSetLoop::new(input, linear, books, None);
        // The set switched to `active` (when given) is recorded as the
        // verdict of an iteration, as the loop would.
        match active {
            // The initial set, solved once (and condensed when asked).
            None => lp.solve(1).unwrap(),
            Some(active) if condense => {
                lp.solve(1).unwrap();
                assert!(!lp.set.advance(active, 1).unwrap());
                assert!(
                    lp.condensed_step().unwrap(),
                    "the interface matrix is definite"
                );
                assert!(matches!(lp.iterate, Iterate::Condensed(_)));
            }
            Some(active) => {
                assert!(!lp.set.advance(active, 0).unwrap());
                lp.solve(1).unwrap();
            }
        }
        let settled = lp.set.active().to_vec();
        assert!(lp.set.advance(settled, 2).unwrap());
        (lp.recover().unwrap().x, interface)
    }

    fn assert_close(a: &[f64], b: &[f64], tol: f64) {
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, (x, y)) in a.iter().zip(b).enumerate() {
            assert!(
                (x - y).abs() <= tol * scale,
                "unknown {i}: {x} vs {y} (scale {scale})"
            );
        }
    }

    /// The set with the first `k` elements of B switched off.
    fn released(p: &Problem, k: usize) -> Vec<bool> {
        let mesh = p.mesh().unwrap();
        let b = crate::contact::build(mesh, 0, 11, 20).unwrap();
        (0..b.len()).map(|e| e >= k).collect()
    }

    #[test]
    fn a_condensed_step_gives_the_interface_values_of_a_full_solve_of_its_set() {
        let p = two_blocks(8, 8);
        let active = released(&p, 4);
        let (full, interface) = solve_with(&p, Some(active.clone()), false);
        let (condensed, _) = solve_with(&p, Some(active), true);
        let pick = |x: &[f64]| interface.iter().map(|&i| x[i]).collect::<Vec<_>>();
        assert_close(&pick(&condensed), &pick(&full), 1e-12);
    }

    #[test]
    fn the_recovery_after_a_condensed_step_gives_the_whole_field_of_a_full_solve() {
        let p = two_blocks(8, 8);
        let active = released(&p, 6);
        let (full, _) = solve_with(&p, Some(active.clone()), false);
        let (recovered, _) = solve_with(&p, Some(active), true);
        assert_close(&recovered, &full, 1e-12);
    }

    #[test]
    fn settling_at_once_refines_the_first_solution_into_the_full_solve() {
        let p = two_blocks(8, 8);
        let (full, _) = solve_with(&p, None, false);
        let (reference, _) = solve_with(&p, None, true);
        assert_close(&reference, &full, 1e-13);
    }

    #[test]
    fn a_loop_that_does_not_settle_stops_at_the_cap_with_its_history() {
        // Pressed on its left quarter only, the upper block lifts off at
        // the right: the first inversion test changes the set.
        let mut model = crate::Model::new();
        let p = two_blocks(8, 2);
        model.set_mesh(p.mesh().unwrap().clone());
        for body in [1, 2] {
            model
                .set_material(body, *p.material(body).unwrap())
                .unwrap();
        }
        for (g, v) in p.constraints() {
            let c = if g % 2 == 0 {
                Component::X
            } else {
                Component::Y
            };
            model.fix(g / 2, c, v).unwrap();
        }
        model.add_pressure(22, 1.0).unwrap();
        model.add_contact_pair(11, 20).unwrap();
        let capped = ContactOptions {
            max_iterations: 1,
            ..Default::default()
        };
        let err = model
            .solve_contact(&capped)
            .expect_err("one iteration is not enough");
        assert_eq!(err.status(), crate::Status::NotConverged);
        assert!(
            err.message().starts_with(
                "the active set did not settle in 1 iterations; history [active 16, +0, -"
            ),
            "{}",
            err.message()
        );
        let settled = model.solve_contact(&ContactOptions::default()).unwrap();
        assert!(settled.iterations > 1 && settled.active < 16);
    }
}
