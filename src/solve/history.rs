//! Quasi-static load histories: a sequence of contact solves whose loads
//! and prescribed displacements change from step to step while the
//! stiffness does not. One factorisation serves the whole history.
//!
//! The first step factorises K₁ — the bodies plus the constraints a
//! contact solve starts from — with the interface unknowns numbered last,
//! and keeps its condensed interface system (Ŝ₁, a dense factor) and two
//! solutions of K₁: x_load for the loads and prescribed displacements at
//! factor 1 (with K₁'s contact loads less their gap part), and x_gap for
//! the loads of K₁'s initial gaps. Everything a step needs is linear in its
//! load factor t: K₁'s solution is x₁(t) = t·x_load + x_gap, and each
//! constraint's load is t·(its load at 1) + (1 − t)·(its gap load). A
//! step is then the condensed active-set loop alone, warm-started from the
//! set of the step before: dense interface work, no sparse solve. New
//! loads (a non-proportional history) cost one sparse solve (x_load anew).
//! The whole field of a step is recovered when asked for ([`History::recover`]):
//! one sparse solve, or, where K₁'s factor is too poor an inverse of the
//! step's matrix for that to reach working accuracy, a factorisation of the
//! step's matrix itself.
//!
//! Where the interface is not condensed (the options ask for `refactorize`,
//! the interface is too large to hold densely, or it couples no free
//! unknown), each step is a contact solve of its scaled loads started from
//! the step before's state, which the history carries alike.
//!
//! A history lives outside the session it factorises into
//! (`model::stepping` owns it): a call that overwrites the session's
//! factor or system leaves it [`History::intact`] no more, and
//! [`History::rebuild`] makes K₁ again, to the bit, from what it kept.

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use super::active_set::{
    ActiveSetLoop, AtInterface, CondensedState, InterfaceSettled, LoopFailure, LoopInput,
    Outcome as LoopOutcome, RECOVERED, Settled, Target, body_energy, expand,
};
use super::condensed::{Condensed, FactorSnapshot};
use super::diagnostics::singular_error;
use super::linear::{Structure, check_finite, factor_and_solve};
use super::memory;
use super::report::{SolveInfo, Timings};
use super::session::{Holds, Session, Settings, Wanted, analyse, factorisation};
use super::{
    Field, Input, Outcome, Start, WarmStart, constraints, contact_outcome, finite_statistics,
};
use crate::contact::constraints::Constraints;
use crate::contact::settled;
use crate::contact::{ContactOptions, FrictionState};
use crate::error::{Error, Result, Status, preflight, reserved};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::body;
use crate::linalg::Cholesky;
use crate::linalg::refine::{Budget, norm_inf, refine_by};

/// What a history is valid for: the problem's stiffness epoch and the
/// contact options that make K₁ (all but the iteration cap).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Key {
    /// The problem's stiffness epoch.
    pub stiffness: u64,
    /// The contact options, with the iteration cap left out.
    options: ContactOptions,
}

impl Key {
    /// The key of a problem of stiffness epoch `stiffness` under `options`.
    pub fn new(stiffness: u64, options: &ContactOptions) -> Key {
        Key {
            stiffness,
            options: ContactOptions {
                max_iterations: 1,
                ..*options
            },
        }
    }
}

/// The contact state a history carries from step to step: the warm start
/// and the interface factor, which a restart needs to continue bit for bit.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct StepState {
    /// The active set of the last step (the next one starts from it).
    pub warm: Vec<bool>,
    /// The set the interface factor represents.
    pub factor_active: Vec<bool>,
    /// The interface factor (empty where the interface is not condensed).
    pub factor: FactorSnapshot,
    /// The slip and friction loads of the last step (empty when
    /// frictionless; docs/method.md §6.15).
    pub friction: FrictionState,
    /// The fingerprint of the interface system the history began with
    /// ([`History::restore`] restores `factor` only into the same one);
    /// `None` when not known (a state saved by an older version, or of a
    /// history that does not condense).
    pub base: Option<u64>,
}

impl StepState {
    /// Whether this state can continue a history of constraints with
    /// `parts` parts, of which `frictional` are elements with friction
    /// (a normal and a stick part each, with their slip and loads).
    pub fn fits(&self, parts: usize, frictional: usize) -> Result<()> {
        if self.is_fresh() {
            return Ok(());
        }
        if self.warm.len() != parts || self.factor_active.len() != parts {
            // Parts without friction, and with friction (a stick part more
            // per element of B).
            let plain = parts - frictional;
            let kind = |n: usize| match n {
                _ if n == plain => "frictionless",
                _ if n == 2 * plain || n == parts && frictional > 0 => "frictional",
                _ => "of other contact constraints",
            };
            return Err(Error::argument(format!(
                "the contact state is of {} contact parts ({}), this step's contact constraints \
                 have {parts} ({}): its friction, contact law or weighting differ from the \
                 state's history",
                self.warm.len(),
                kind(self.warm.len()),
                kind(parts)
            )));
        }
        let f = &self.friction;
        let sizes = [f.anchors.len(), f.loads.len()];
        let openings = f.openings.is_empty() || f.openings.len() == sizes[0];
        if sizes.iter().any(|&m| m != 0 && m != frictional) || sizes[0] != sizes[1] || !openings {
            return Err(Error::argument(format!(
                "the contact state's friction data ({} / {} values) do not fit {frictional} \
                 frictional contact elements",
                sizes[0], sizes[1]
            )));
        }
        Ok(())
    }
}

impl StepState {
    /// Whether it is the state before any step of a history that does not
    /// condense its interface (no set yet: its first step starts from the
    /// initial set of its own loads), which a revert of that step brings
    /// back.
    pub fn is_fresh(&self) -> bool {
        self.warm.is_empty()
    }
}

/// A step whose whole field is recovered when asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Pending {
    /// The history it belongs to.
    pub key: Key,
    /// The load factor.
    pub t: f64,
    /// The interface values.
    pub ui: Vec<f64>,
    /// The final set.
    pub active: Vec<bool>,
    /// The friction load factors it was solved with (empty: none).
    pub friction_loads: Vec<f64>,
}

/// The numbers of histories, so that the session knows whose K₁ it holds.
static HISTORIES: AtomicU64 = AtomicU64::new(1);

/// A load history (module documentation).
pub(crate) struct History {
    key: Key,
    /// Its number ([`Holds::History`]).
    id: u64,
    /// The active set of the last step.
    warm: Vec<bool>,
    /// The slip and friction loads of the last step (empty: frictionless
    /// or none yet).
    friction: FrictionState,
    /// The number of parts of its constraints.
    parts: usize,
    /// The number of frictional elements of its constraints (each has a
    /// normal and a stick part).
    frictional: usize,
    /// K₁ and its condensed interface, where the interface is condensed.
    k1: Option<K1>,
    /// The fingerprint of the loads of a problem epoch
    /// ([`History::load_key`]), kept for that epoch's steps.
    load_key: Option<(u64, u64)>,
}

/// K₁ of a history that condenses its interface.
struct K1 {
    /// The problem epoch whose loads `x_load` solves.
    loads_epoch: u64,
    /// The set of constraints K₁ holds (also while `state` is lent).
    reference: Vec<bool>,
    /// K₁'s condensed state (lent to the loop during a step).
    state: Option<CondensedState>,
    x_load: Vec<f64>,
    x_gap: Vec<f64>,
    /// The bodies' right-hand side at factor 1.
    rhs_body: Vec<f64>,
    /// The statistics of K₁'s solve (the residual a step reports).
    first: SolveInfo,
    /// Whether x_load was solved apart for new loads ([`History::new_loads`])
    /// rather than with K₁'s first solve: a rebuild redoes the same.
    loads_apart: bool,
    /// The fingerprint of K₁'s interface factor
    /// ([`Condensed::factor_fingerprint`]): what a saved state's factor
    /// must have grown from to be restored.
    base: u64,
    /// ‖K₁‖∞, which bounds a step's recovery ([`check_size`]).
    norm: f64,
    /// The history's state while `state` is lent to a step's loop (a loop
    /// that refactorises does not give it back: K₁ is then rebuilt).
    kept: Option<StepState>,
}

impl K1 {
    fn condensed(&self) -> &CondensedState {
        self.state.as_ref().expect("the condensed state is back")
    }

    /// The set K₁ holds.
    fn reference(&self) -> Vec<bool> {
        self.reference.clone()
    }

    /// K₁'s solution at load factor `t`: t·x_load + x_gap.
    fn x1_at(&self, t: f64) -> Vec<f64> {
        let mut x1: Vec<f64> = self.x_load.iter().map(|a| t * a).collect();
        if !self.x_gap.is_empty() {
            x1.iter_mut().zip(&self.x_gap).for_each(|(a, b)| *a += b);
        }
        x1
    }
}

/// What a step gives: its outcome, the contact state before it (what a
/// revert brings back), and whether K₁ was lost on the way (the loop
/// solved whole: the history ends with this step).
pub(crate) struct Stepped {
    /// The step's outcome.
    pub outcome: Outcome,
    /// The history's state before the step.
    pub before: StepState,
    /// Whether the history ended with this step.
    pub ended: bool,
}

impl History {
    /// Begins a history for `key` on the loads of `input` (problem epoch
    /// `epoch`), from the contact state `restored` if given: K₁
    /// assembled and factorised (the only factorisation) with its condensed
    /// interface, or, where the interface is not condensed, nothing yet.
    pub fn begin(
        session: &mut Session,
        input: &Input<'_>,
        key: Key,
        epoch: u64,
        restored: Option<&StepState>,
        timings: &mut Timings,
    ) -> Result<(History, Vec<String>)> {
        let mut warnings = Vec::new();
        let (k1, sizes) = begin_k1(session, input, key, epoch, timings, &mut warnings)?;
        let id = HISTORIES.fetch_add(1, Ordering::Relaxed);
        let mut history = History {
            key,
            id,
            warm: k1
                .as_ref()
                .map_or_else(Vec::new, |k| k.condensed().reference.clone()),
            friction: FrictionState::default(),
            parts: sizes.parts,
            frictional: sizes.frictional,
            k1,
            load_key: None,
        };
        if history.k1.is_some() {
            session.holds = Holds::History(id);
        }
        if let Some(state) = restored {
            history.restore(state)?;
        }
        Ok((history, warnings))
    }

    /// Whether the session still holds this history's K₁ (a history that
    /// does not condense needs nothing of it).
    pub fn intact(&self, session: &Session) -> bool {
        self.k1.is_none() || session.holds == Holds::History(self.id)
    }

    /// Whether a step under `key` continues this history.
    pub fn continues(&self, key: &Key) -> bool {
        self.key == *key
    }

    /// The key it was made for.
    pub fn key(&self) -> &Key {
        &self.key
    }

    /// The condensed unknowns (0 without a condensed interface).
    pub fn interface_len(&self) -> usize {
        let state = self.k1.as_ref().and_then(|k| k.state.as_ref());
        state.map_or(0, |c| c.system.len())
    }

    /// The factorisations its beginning made.
    pub fn factorizations(&self) -> usize {
        self.k1.as_ref().map_or(0, |k| k.first.factorizations)
    }

    /// The contact state to continue from ([`History::restore`]).
    pub fn state(&self) -> StepState {
        if let Some(kept) = self.k1.as_ref().and_then(|k| k.kept.as_ref()) {
            return kept.clone();
        }
        let condensed = self.k1.as_ref().map(|k| (k.condensed(), k.base));
        StepState {
            warm: self.warm.clone(),
            factor_active: condensed
                .map_or_else(|| self.warm.clone(), |(c, _)| c.factor_active.clone()),
            factor: condensed
                .map_or_else(FactorSnapshot::default, |(c, _)| c.system.factor_snapshot()),
            friction: self.friction.clone(),
            base: condensed.map(|(_, base)| base),
        }
    }

    /// Whether it carries a slip state (a frictional history).
    pub fn is_frictional(&self) -> bool {
        self.frictional > 0
    }

    /// Continues from `state` (from [`History::state`]): from its active set
    /// and friction state, and, when it comes from a history of this very
    /// interface system (the same fingerprint), from its interface factor
    /// too, so that the steps go on bit for bit. A factor grown from
    /// another system (another geometry, stiffness or contact modulus
    /// under the same constraints) would solve the wrong interface
    /// problem: this history's own factor stays, and the loop updates it to
    /// the state's set.
    pub fn restore(&mut self, state: &StepState) -> Result<()> {
        state.fits(self.parts, self.frictional)?;
        if state.is_fresh() {
            // Back before the first step: its set, no slip.
            self.warm = match &self.k1 {
                Some(k1) => k1.reference(),
                None => Vec::new(),
            };
            self.friction = FrictionState::default();
            return Ok(());
        }
        if let Some(k1) = self.k1.as_mut().filter(|k| state.base == Some(k.base)) {
            let condensed = k1.state.as_mut().expect("the condensed state is back");
            condensed.system.restore_factor(&state.factor)?;
            condensed.factor_active.clone_from(&state.factor_active);
        }
        self.warm.clone_from(&state.warm);
        self.friction.clone_from(&state.friction);
        Ok(())
    }

    /// Makes K₁ again in `session` after a call overwrote it: the same
    /// assembly, factorisation and solves, then this history's own state,
    /// so that what follows is bit for bit what would have followed without
    /// that call. A rebuild that fails leaves the history unusable (its
    /// steps then fail, and the next one begins another).
    pub fn rebuild(&mut self, session: &mut Session, input: &Input<'_>) -> Result<()> {
        let Some(old) = self.k1.as_ref() else {
            return Ok(());
        };
        let (state, loads, loads_apart, first) =
            (self.state(), old.loads_epoch, old.loads_apart, old.first);
        let (mut timings, mut warnings) = (Timings::default(), Vec::new());
        let (k1, _) = begin_k1(session, input, self.key, loads, &mut timings, &mut warnings)?;
        let Some(mut k1) = k1 else {
            return Err(Error::state(
                "the load history's interface is no longer condensed",
            ));
        };
        k1.first = first;
        self.k1 = Some(k1);
        session.holds = Holds::History(self.id);
        if loads_apart {
            self.new_loads(session, input, loads, &mut timings)?;
        }
        self.restore(&state)
    }

    /// One load step at factor `t` of the loads and prescribed
    /// displacements of `input` (epoch `epoch`), warm-started from
    /// the last step's set. On error the history is as it was (but K₁,
    /// which the caller rebuilds where it is not [`History::intact`]). A
    /// warm start that leads nowhere (a free body, a cycle: unloading to
    /// zero from a loaded set passes through no contact at all) is tried
    /// again from the initial set of the step's own loads.
    ///
    /// A frictional step ends sub-steps where elements open at its start
    /// close (docs/method.md §6.15): each closes at the factor its opening
    /// reaches zero, interpolated along the step, and sticks or slips from
    /// there, so that contact formed under shear carries its shear within
    /// the step that forms it. The step reports the sum of its sub-steps'
    /// iterations, and a revert goes back before all of them.
    pub fn step(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        check_load_factor(at.t)?;
        super::ensure_unknowns(&session.dofs)?;
        match self.on_path(input, at.epoch) {
            true => self.sub_steps(session, input, at, timings),
            false => self.step_once(session, input, at, timings),
        }
    }

    /// Whether a frictional step on the loads of `input` (problem epoch
    /// `epoch`) starts on the straight path to its own factor: from no
    /// load at all, or from a step on the same loads (the same
    /// fingerprint, in this model or the one a restored state came from),
    /// at a known factor.
    fn on_path(&mut self, input: &Input<'_>, epoch: u64) -> bool {
        let (at, key) = (self.friction.at, self.friction.load_key);
        let frictional = self.frictional > 0;
        frictional && at == 0.0
            || frictional
                && !self.friction.anchors.is_empty()
                && at.is_finite()
                && key == self.load_key(input, epoch)
    }

    /// The fingerprint of the loads of `input` (forces and prescribed
    /// values at factor 1), computed once per problem epoch `epoch`.
    fn load_key(&mut self, input: &Input<'_>, epoch: u64) -> u64 {
        if let Some((_, key)) = self.load_key.filter(|&(e, _)| e == epoch) {
            return key;
        }
        let values = input.f_ext.iter().chain(input.prescribed);
        let key = values.fold(0xcbf2_9ce4_8422_2325u64, |h, v| {
            (h ^ v.to_bits()).wrapping_mul(0x100_0000_01b3)
        });
        self.load_key = Some((epoch, key));
        key
    }

    /// A frictional step to `at.t` in sub-steps: each goes from the
    /// history's state towards a target (at first the step's end); one
    /// that closes elements open at its start goes back and stops where
    /// the first of them closes, and is accepted there (they stick or slip
    /// from there); one that fails (a body held by nothing yet, a cycle)
    /// is tried again to half its length, and once halving is done the
    /// rest of the step once from the initial set
    /// ([`SubSteps::after_failure`]); an accepted one short of the end
    /// is followed by another to the end. Each is a warm-started loop on
    /// the condensed interface. Gives the last, with the state before the
    /// whole step and the iterations of all.
    fn sub_steps(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        let before = self.state();
        let mut plan = SubSteps::new(before.friction.at, at.t, self.frictional);
        loop {
            let start = self.friction.at;
            plan.attempts += 1;
            let target = Along {
                t: plan.target,
                retry: std::mem::take(&mut plan.retry),
                ..*at
            };
            let stepped = match self.step_once(session, input, &target, timings) {
                Ok(stepped) => stepped,
                Err(e) => {
                    let again = plan.after_failure(start, &e);
                    if again && (self.intact(session) || self.rebuild(session, input).is_ok()) {
                        continue;
                    }
                    self.restore_or_keep(&before)?;
                    return Err(e);
                }
            };
            plan.iterations += iterations_of(&stepped.outcome);
            let closing = closing_in(session, &stepped.before.friction, &stepped.outcome);
            if let Some(target) = plan.stop_at(start, closing) {
                // Back to the start, and on to where the first closes.
                self.restore(&stepped.before)?;
                plan.target = target;
                continue;
            }
            if stepped.ended && plan.target != at.t {
                self.restore_or_keep(&before)?;
                return Err(Error::new(
                    Status::NotConverged,
                    format!(
                        "the load step's sub-step to factor {:?} needed a factorisation of its \
                         own (its condensed interface was singular): split the step",
                        plan.target
                    ),
                ));
            }
            if stepped.ended || plan.target == at.t {
                return Ok(plan.finish(stepped, before));
            }
            (plan.target, plan.halvings) = (at.t, 0);
        }
    }

    /// Back at `before` after a failed step: its state restored, or, where
    /// the failure lost K₁'s condensed state, kept for the rebuild that
    /// makes K₁ again ([`History::rebuild`]).
    fn restore_or_keep(&mut self, before: &StepState) -> Result<()> {
        match self.k1.as_mut() {
            Some(k1) if k1.state.is_none() => {
                k1.kept = Some(before.clone());
                Ok(())
            }
            _ => self.restore(before),
        }
    }

    /// One step to `at.t` from the history's state, without sub-steps; a
    /// frictional history's state then stands at `at.t`.
    fn step_once(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        let stepped = self.step_at(session, input, at, timings)?;
        if !self.friction.anchors.is_empty() {
            self.friction.at = at.t;
            self.friction.load_key = self.load_key(input, at.epoch);
        }
        Ok(stepped)
    }

    /// One step to `at.t`: on the condensed interface from the last
    /// step's set, tried again from the initial set where that leads
    /// nowhere, or afresh where the interface is not condensed.
    fn step_at(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        if self.k1.is_none() {
            return self.step_afresh(session, input, at, timings);
        }
        let old_loads = self.loads_of(at.epoch, session, input, timings)?;
        let mut stepped = self.step_condensed(session, input, at, false, timings);
        let retry = match &stepped {
            Err(e) => at.retry && matches!(e.status(), Status::Singular | Status::NotConverged),
            Ok(_) => false,
        };
        if retry {
            if !self.intact(session) {
                self.rebuild(session, input)?;
            }
            stepped = self.step_condensed(session, input, at, true, timings);
        }
        if stepped.is_err() {
            if let (Some(old), Some(k1)) = (old_loads, self.k1.as_mut()) {
                (k1.x_load, k1.rhs_body, k1.loads_epoch) = old;
            }
        }
        stepped
    }

    /// Makes x_load that of the loads of epoch `epoch` if it is not:
    /// gives the loads it replaced (x_load, the bodies' right-hand side,
    /// their epoch), which a failed step puts back.
    #[allow(clippy::type_complexity)]
    fn loads_of(
        &mut self,
        epoch: u64,
        session: &mut Session,
        input: &Input<'_>,
        timings: &mut Timings,
    ) -> Result<Option<(Vec<f64>, Vec<f64>, u64)>> {
        if self.k1.as_ref().is_none_or(|k| k.loads_epoch == epoch) {
            return Ok(None);
        }
        self.new_loads(session, input, epoch, timings).map(Some)
    }

    /// New loads on the same stiffness: x_load anew (one sparse solve).
    /// Returns the loads replaced (x_load, the bodies' right-hand side and
    /// their epoch).
    fn new_loads(
        &mut self,
        session: &Session,
        input: &Input<'_>,
        epoch: u64,
        timings: &mut Timings,
    ) -> Result<(Vec<f64>, Vec<f64>, u64)> {
        let k1 = self.k1.as_mut().expect("a condensed history");
        let t0 = Instant::now();
        let rhs_body = body::rhs(
            &input.elements,
            &session.dofs,
            input.f_ext,
            input.prescribed,
        )?;
        let options = self.key.options;
        let set = constraints(
            input,
            input.prescribed,
            &session.contact,
            &session.dofs,
            &options,
            &[],
        )?;
        let mut a = rhs_body.clone();
        let reference = &k1.condensed().reference;
        for k in (0..set.parts()).filter(|&k| reference[k]) {
            let (load, f0) = (set.load(k), set.gap_load(k));
            for (q, e) in set.unknowns(k).iter().enumerate() {
                if let Some(i) = e {
                    a[*i] += load[q] - f0[q];
                }
            }
        }
        timings.assembly += t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let chol = &session
            .analysis
            .as_ref()
            .expect("the history's factor")
            .chol;
        chol.solve(&mut a)?;
        timings.solve += t0.elapsed().as_secs_f64();
        let x_load = std::mem::replace(&mut k1.x_load, a);
        let old_rhs = std::mem::replace(&mut k1.rhs_body, rhs_body);
        let loads = std::mem::replace(&mut k1.loads_epoch, epoch);
        k1.loads_apart = true;
        Ok((x_load, old_rhs, loads))
    }

    /// A step of a history that does not condense: the contact solve of
    /// the scaled loads, started from the last step's state.
    fn step_afresh(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        let before = self.state();
        let (prescribed, f_ext) = (scaled(input.prescribed, at.t), scaled(input.f_ext, at.t));
        let step_input = Input {
            prescribed: &prescribed,
            f_ext: &f_ext,
            ..*input
        };
        let begun = super::prepare(session, &step_input, timings)?;
        let start: Start<'_> = (!self.warm.is_empty()).then_some(WarmStart {
            flags: &self.warm,
            friction: &self.friction,
        });
        let outcome =
            super::solve_contact(session, &step_input, at.options, start, begun, timings)?;
        let contact = outcome.contact.as_ref().expect("a contact outcome");
        self.warm = contact.flags.clone();
        if let Some(f) = &contact.state.strip.friction {
            self.friction = f.next.clone();
        }
        Ok(Stepped {
            outcome,
            before,
            ended: false,
        })
    }

    /// A step on the condensed interface, from the last step's set, or
    /// (`from_initial`) from the initial set of its own scaled problem.
    fn step_condensed(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        at: &Along<'_>,
        from_initial: bool,
        timings: &mut Timings,
    ) -> Result<Stepped> {
        let mesh = input.elements.mesh();
        let prescribed = scaled(input.prescribed, at.t);
        let before = self.state();
        let Session {
            dofs,
            pattern,
            contact,
            analysis,
            system,
            holds,
            ..
        } = &mut *session;
        let anchors = &self.friction.anchors;
        let set = constraints(input, &prescribed, contact, dofs, at.options, anchors)?;
        let start = self.start(&set, from_initial);
        let condensed = self.lend(at.t, &before)?;
        let chol = &mut analysis.as_mut().expect("the history's factor").chol;
        let mut info = step_info(dofs, pattern, chol, condensed.system.len());
        let structure = Structure {
            mesh,
            dofs,
            pattern,
        };
        let energy = |r: &[f64]| body_energy(&input.elements, r);
        let loop_input = LoopInput {
            at: structure,
            body_energy: &energy,
            set: &set,
            interface: None,
            options: *at.options,
        };
        // The loop may refactorise the session's system (its condensed
        // matrix singular): K₁ is the session's again only if it did not.
        *holds = Holds::Nothing;
        let run = ActiveSetLoop::resume(
            loop_input,
            super::linear::SystemAndFactor { chol, system },
            super::linear::Bookkeeping::new(timings, &mut info),
            condensed,
            start.0,
            start.1,
        )
        .run_to_interface();
        info.condition_estimate = chol.condition_estimate();
        info.timings = *timings;
        let step = Step {
            set: &set,
            pairs: input.pairs,
            mesh,
            prescribed: &prescribed,
            dofs,
            at: (self.key, at.t),
        };
        match run {
            Ok(LoopOutcome::Interface(settled)) => {
                let InterfaceSettled {
                    state,
                    at_interface,
                } = *settled;
                self.give_back(holds, state);
                let outcome = on_interface(self.k1(), step, at_interface, info);
                self.settled(outcome, before)
            }
            // The condensed system was singular: solved whole, K₁ is gone
            // and the history ends with this step.
            Ok(LoopOutcome::Full(settled)) => Ok(Stepped {
                outcome: on_full_solve(step, system, pattern, *settled, info)?,
                before,
                ended: true,
            }),
            Err(failed) => Err(self.loop_failed(holds, *failed, &before)),
        }
    }

    /// The flags and friction loads a step starts from: the last step's, or
    /// (`from_initial`) the initial set of the step's constraints `set`.
    fn start(&self, set: &Constraints<'_>, from_initial: bool) -> (Vec<bool>, Vec<f64>) {
        match from_initial {
            true => {
                let initial = set.initial_active();
                let loads = set.stick_loads(&initial);
                (initial, loads)
            }
            false => warm_start(set, &self.warm, &self.friction),
        }
    }

    /// The history after a step's loop failed with `e`: back at `before`
    /// with its condensed state if the loop gave it back (else K₁ is lost,
    /// and rebuilt by the caller).
    fn loop_failed(&mut self, holds: &mut Holds, failed: LoopFailure, before: &StepState) -> Error {
        let LoopFailure { error: e, state } = failed;
        if let Some(mut state) = state {
            state.x1 = Vec::new();
            self.give_back(holds, Box::new(state));
            if let Err(e) = self.restore(before) {
                return e;
            }
        }
        e
    }

    /// K₁ of a condensed history.
    fn k1(&self) -> &K1 {
        self.k1.as_ref().expect("a condensed history")
    }

    /// Lends K₁'s condensed state to a step's loop at load factor `t` (its
    /// x₁(t) in), keeping the history's state `before` while it is out.
    /// Refuses a step whose field would overflow ([`check_size`]).
    fn lend(&mut self, t: f64, before: &StepState) -> Result<CondensedState> {
        let k1 = self.k1.as_mut().expect("a condensed history");
        let x1 = k1.x1_at(t);
        check_size(k1, &x1, t)?;
        let mut condensed = k1.state.take().expect("the condensed state is back");
        condensed.x1 = x1;
        k1.kept = Some(before.clone());
        Ok(condensed)
    }

    /// Takes back the condensed state a loop gave back: the session holds
    /// K₁ again.
    fn give_back(&mut self, holds: &mut Holds, state: Box<CondensedState>) {
        let k1 = self.k1.as_mut().expect("a condensed history");
        k1.state = Some(*state);
        k1.kept = None;
        *holds = Holds::History(self.id);
    }

    /// The history after a step settled on the interface with `outcome`:
    /// its warm start and slip state move on, or, on error, it is back at
    /// `before`.
    fn settled(&mut self, outcome: Result<Outcome>, before: StepState) -> Result<Stepped> {
        let outcome = match outcome {
            Ok(outcome) => outcome,
            Err(e) => {
                self.restore(&before)?;
                return Err(e);
            }
        };
        let contact = outcome.contact.as_ref().expect("a contact outcome");
        self.warm = contact.flags.clone();
        if let Some(f) = &contact.state.strip.friction {
            self.friction = f.next.clone();
        }
        Ok(Stepped {
            outcome,
            before,
            ended: false,
        })
    }

    /// The whole field of a pending step (global DOFs): u = x₁(t) +
    /// K₁⁻¹P(Δg + ΔC u_I), refined against the matrix of the step's set; if
    /// that stalls above [`RECOVERED`], solved with a factorisation of that
    /// matrix ([`solved_whole`]).
    pub fn recover(
        &self,
        session: &Session,
        input: &Input<'_>,
        pending: &Pending,
    ) -> Result<Vec<f64>> {
        let stale = || Error::state("the load step's factorisation is gone: run the step again");
        let k1 = self.k1.as_ref().ok_or_else(stale)?;
        if self.key != pending.key || self.warm != pending.active || !self.intact(session) {
            return Err(stale());
        }
        let t = pending.t;
        let mesh = input.elements.mesh();
        let prescribed = scaled(input.prescribed, t);
        let Session {
            dofs,
            pattern,
            contact,
            analysis,
            system,
            ..
        } = session;
        let set = constraints(input, &prescribed, contact, dofs, &self.key.options, &[])?;
        let chol = &analysis.as_ref().ok_or_else(stale)?.chol;
        let x1 = k1.x1_at(t);
        let active = &pending.active;
        let rhs = step_rhs(&set, &k1.rhs_body, pending);
        let matrix = StepMatrix::of(pattern, system, &set, active);
        let product = |v: &[f64], y: &mut [f64]| matrix.mul(v, y);
        let at = Structure {
            mesh,
            dofs,
            pattern,
        };
        let target = Target {
            at,
            set: &set,
            active,
            product: &product,
            k_norm: &|| norm_inf(pattern, matrix.values),
            rhs: &rhs,
            // K₁'s right-hand side of a history holds no friction load.
            friction_loads: &pending.friction_loads,
            reference_friction_loads: &[],
        };
        let state = (&k1.condensed().system, &k1.condensed().reference[..]);
        let (mut x, mut omega) = expand(target, chol, state.0, state.1, x1, pending.ui.clone())?;
        let context = format!(" (load step at factor {t:?})");
        if omega.is_nan() || omega > RECOVERED || x.iter().any(|v| !v.is_finite()) {
            // K₁'s factor is too poor an inverse of the step's matrix for
            // the refinement to reach working accuracy (measured: Hertz
            // with the cylinder's mesh 20× finer, h = a/16, stalled at
            // 5.5e-8): the step's matrix is factorised itself, as the loop's
            // full solve does, but beside K₁, which the steps after still
            // need.
            drop(x);
            let settings = analysis.as_ref().ok_or_else(stale)?.settings();
            (x, omega) = solved_whole(at, settings, &matrix, &rhs, &context)?;
        }
        if omega.is_nan() || omega > RECOVERED {
            return Err(Error::new(
                Status::NumericalFailure,
                format!(
                    "the field could not be solved to working accuracy (backward error \
                     {omega:.1e}, above {RECOVERED:.0e}){context}"
                ),
            ));
        }
        Ok(dofs.expand(&x, &prescribed))
    }
}

/// The contact state a one-shot solve of a frictional problem starts from
/// where contact forms along its load (docs/method.md §6.15): the end of a
/// one-step load history from no load, whose sub-steps find where along
/// the load each element closes, and so the shear it carries. The solve
/// then settles from that state, with its own factorisation (its matrix
/// and field are a solve's). With the factorisations it took; `None`
/// where no pair is frictional or every element touches from the start
/// (the solve's own start is then the path's).
pub(crate) fn path_start(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    timings: &mut Timings,
) -> Result<Option<(StepState, usize)>> {
    if input.pairs.iter().all(|p| p.friction == 0.0) {
        return Ok(None);
    }
    let forms = {
        let set = constraints(
            input,
            input.prescribed,
            &session.contact,
            &session.dofs,
            options,
            &[],
        )?;
        let strip = set.strip();
        set.is_frictional() && (0..strip.len()).any(|k| strip.closing(k))
    };
    if !forms {
        return Ok(None);
    }
    let key = Key::new(0, options);
    let (mut history, _) = History::begin(session, input, key, 0, None, timings)?;
    let at = Along {
        t: 1.0,
        epoch: 0,
        options,
        retry: true,
    };
    let stepped = history.step(session, input, &at, timings)?;
    let factorizations = history.factorizations() + stepped.outcome.info.factorizations;
    Ok(Some((history.state(), factorizations)))
}

/// Where a step goes: its load factor, the problem epoch whose loads
/// it applies, and its contact options.
#[derive(Clone, Copy)]
pub(crate) struct Along<'o> {
    /// The load factor.
    pub t: f64,
    /// The problem epoch of the loads.
    pub epoch: u64,
    /// The contact options.
    pub options: &'o ContactOptions,
    /// Whether a step that leads nowhere from the last step's set (a free
    /// body, a cycle) is tried again from the initial set of its loads. A
    /// frictional step's sub-steps are halved first: the initial set's
    /// first solve says nothing of where elements close.
    pub retry: bool,
}

/// The plan of a frictional step's sub-steps ([`History::sub_steps`]).
struct SubSteps {
    /// The load factor the step starts from.
    first: f64,
    /// The step's end.
    end: f64,
    /// Where the next sub-step goes.
    target: f64,
    /// Sub-steps that stopped where elements closed.
    closings: usize,
    /// How many of those a step takes at most.
    cap: usize,
    /// Halvings in a row of a failing sub-step.
    halvings: usize,
    /// Sub-steps tried, accepted or not.
    attempts: usize,
    /// How many a step tries before it stops locating or halving.
    budget: usize,
    /// Whether the next sub-step, should it lead nowhere from the last
    /// set, is tried again from the initial set.
    retry: bool,
    /// Whether the step has tried its rest from the initial set.
    retried: bool,
    /// Active-set iterations of every sub-step.
    iterations: usize,
}

impl SubSteps {
    /// The plan of a step from `first` to `end` of a history with
    /// `frictional` frictional elements.
    fn new(first: f64, end: f64, frictional: usize) -> SubSteps {
        SubSteps {
            first,
            end,
            target: end,
            closings: 0,
            cap: MAX_SUB_STEPS.max(4 * frictional),
            halvings: 0,
            attempts: 0,
            budget: 8 * MAX_SUB_STEPS.max(4 * frictional),
            retry: false,
            retried: false,
            iterations: 0,
        }
    }

    /// Where a sub-step from `start` whose elements closed as `closing`
    /// says goes back to: just past the first closing, by the least
    /// sub-step of the whole step (at the closing itself the element sits
    /// on the inversion test's threshold, and the loop cycles on it;
    /// closings nearer together are taken at once), or, where that is not
    /// known, half-way. `None` where it stands: nothing closed before its
    /// end, it is the least sub-step already, or the plan has taken its
    /// cap.
    fn stop_at(&mut self, start: f64, closing: Closing) -> Option<f64> {
        let length = self.target - start;
        let least = (SUB_STEP_LEAST * (self.end - self.first)).abs();
        if length.abs() <= least || self.closings >= self.cap || self.attempts >= self.budget {
            return None;
        }
        let share = match closing {
            Closing::AtEnd => return None,
            Closing::At(s) if s + 2.0 * least / length.abs() >= 1.0 => return None,
            Closing::At(s) => s + least / length.abs(),
            Closing::Unforeseen => 0.5,
        };
        self.closings += 1;
        self.halvings = 0;
        Some(start + share * length)
    }

    /// After a sub-step from `start` failed with `e`: whether to go on,
    /// and how. Where a shorter sub-step can avoid the failure (fewer
    /// elements closing in it) and the halvings and the budget allow, its
    /// target is halved towards `start`; else, once per step, the whole
    /// rest of the step is tried from the initial set, as a step of its own
    /// would be; else the failure stands.
    fn after_failure(&mut self, start: f64, e: &Error) -> bool {
        if !matches!(e.status(), Status::Singular | Status::NotConverged) {
            return false;
        }
        if self.halvings < MAX_HALVINGS && self.target != start && self.attempts < self.budget {
            self.halvings += 1;
            self.target = start + 0.5 * (self.target - start);
            return true;
        }
        if self.retried {
            return false;
        }
        (self.retried, self.retry, self.target) = (true, true, self.end);
        true
    }

    /// The step's outcome: the last sub-step's, with the state `before`
    /// the whole step, the iterations of all, and a warning where the cap
    /// or the budget stopped the locating.
    fn finish(&self, mut stepped: Stepped, before: StepState) -> Stepped {
        if let Some(c) = stepped.outcome.contact.as_mut() {
            c.report.iterations = self.iterations;
        }
        if self.closings >= self.cap || self.attempts >= self.budget {
            stepped.outcome.warnings.push(format!(
                "this load step stopped locating where contact forms along it after {} \
                 closings in {} sub-steps: the elements closing later carry no shear until the \
                 step's end; split the step",
                self.closings, self.attempts
            ));
        }
        stepped.before = before;
        stepped
    }
}

/// The halvings in a row a failing sub-step is tried with.
const MAX_HALVINGS: usize = 20;

/// The least sub-steps a step takes before it stops locating where
/// contact forms along it (then the elements closing later carry no shear
/// until its end, with a warning); more where the history has more
/// frictional elements (four sub-steps each).
const MAX_SUB_STEPS: usize = 64;

/// The least sub-step, as a share of its step: closings nearer together
/// along the step are taken at once.
const SUB_STEP_LEAST: f64 = 1e-6;

/// What the elements that closed in a sub-step say of where it should
/// have stopped ([`closing_in`]).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Closing {
    /// Nowhere before its end: none closed, or all at the end.
    AtEnd,
    /// Where the first of them closed, as a share of the sub-step.
    At(f64),
    /// An element closed that the start's response leaves open: something
    /// else changed first (an element slipped or opened), which that
    /// response does not see, so where is not known.
    Unforeseen,
}

/// Where in a sub-step (0 at its start, 1 at its end) the first of the
/// elements that closed in it (`outcome`'s friction, from the state
/// `start`) reaches zero opening: the start's response is linear in the
/// load until something changes, so its opening goes from the one at the
/// start (its initial opening J₀ before any step) to the one the loop's
/// first solve predicted at the end, under the start's flags.
fn closing_in(session: &Session, start: &FrictionState, outcome: &Outcome) -> Closing {
    let Some(contact) = outcome.contact.as_ref() else {
        return Closing::AtEnd;
    };
    let Some(f) = contact.state.strip.friction.as_ref() else {
        return Closing::AtEnd;
    };
    let elements = session.contact.elements();
    let opening = |k: usize| start.openings.get(k).copied().unwrap_or(elements[k].j0);
    let predicted = |k: usize| contact.predicted.get(k).copied().unwrap_or(f64::NAN);
    let mut first = 1.0f64;
    for &k in &f.closed {
        let (o0, o1) = (opening(k), predicted(k));
        if o0.is_nan() || o0 <= 0.0 {
            // Closed (or held open past zero) at the start already.
            continue;
        }
        // Predicted to close by the end, to rounding of its opening.
        if o1.is_nan() || o1 >= CLOSED_AT_END * o0 {
            return Closing::Unforeseen;
        }
        first = first.min(o0 / (o0 - o1.min(0.0)));
    }
    match first < 1.0 {
        true => Closing::At(first),
        false => Closing::AtEnd,
    }
}

/// An element whose predicted opening at a sub-step's end is below this
/// share of its opening at the start closes by that end.
const CLOSED_AT_END: f64 = 1e-9;

/// The active-set iterations of a step's outcome.
fn iterations_of(outcome: &Outcome) -> usize {
    outcome.contact.as_ref().map_or(0, |c| c.report.iterations)
}

/// Refuses a load factor that is not finite or beyond 1e300 in magnitude.
pub(crate) fn check_load_factor(t: f64) -> Result<()> {
    if t.is_finite() && t.abs() <= 1e300 {
        return Ok(());
    }
    Err(Error::argument(format!(
        "load_factor = {t:?} must be finite and at most 1e300 in magnitude"
    )))
}

/// K₁ of a history for `key` at problem epoch `epoch`: the bodies'
/// part at factor 1 with the initial constraints, factorised with the
/// interface unknowns last, its condensed interface system and its two
/// solutions; `None` where the interface is not condensed (each step then
/// solves afresh).
fn begin_k1(
    session: &mut Session,
    input: &Input<'_>,
    key: Key,
    epoch: u64,
    timings: &mut Timings,
    warnings: &mut Vec<String>,
) -> Result<(Option<K1>, Sizes)> {
    let rhs_body = assemble_bodies(session, input, timings, warnings)?;
    let Session {
        dofs,
        pattern,
        contact,
        analysis,
        system,
        ..
    } = &mut *session;
    let set = constraints(input, input.prescribed, contact, dofs, &key.options, &[])?;
    let sizes = Sizes {
        parts: set.parts(),
        frictional: if set.is_frictional() {
            set.strip().len()
        } else {
            0
        },
    };
    let interface = set.interface_unknowns();
    let condensed = !key.options.refactorize
        && !interface.is_empty()
        && Condensed::worthwhile(interface.len(), pattern.nnz());
    if !condensed {
        return Ok((None, sizes));
    }
    let at = Structure {
        mesh: input.elements.mesh(),
        dofs,
        pattern,
    };
    let reference = set.initial_active();
    let k1 = K1Set {
        set: &set,
        interface: &interface,
        reference: &reference,
    };
    let (chol, x, mut info) = solve_k1(analysis, at, system, input, k1, timings)?;
    let norm = norm_inf(pattern, system.values());
    let (x_load, x_gap) = split_gap(chol, system, &set, &reference, x)?;
    let t0 = Instant::now();
    let condensed = Condensed::new(chol, interface)?;
    let base = condensed.factor_fingerprint();
    timings.interface += t0.elapsed().as_secs_f64();
    info.interface_unknowns = condensed.len();
    let k1 = K1 {
        loads_epoch: epoch,
        reference: reference.clone(),
        state: Some(CondensedState {
            system: condensed,
            x1: Vec::new(),
            reference: reference.clone(),
            factor_active: reference,
            // K₁'s right-hand side holds no friction load.
            reference_friction_loads: Vec::new(),
        }),
        x_load,
        x_gap,
        rhs_body,
        first: info,
        loads_apart: false,
        base,
        norm,
        kept: None,
    };
    Ok((Some(k1), sizes))
}

/// The sizes of a history's constraints.
struct Sizes {
    /// Parts.
    parts: usize,
    /// Frictional elements.
    frictional: usize,
}

/// Assembles the bodies' part at factor 1 into the session's system, which
/// then holds no solve's final matrix, and warns of the elements tempering
/// softens. Gives the bodies' right-hand side.
fn assemble_bodies(
    session: &mut Session,
    input: &Input<'_>,
    timings: &mut Timings,
    warnings: &mut Vec<String>,
) -> Result<Vec<f64>> {
    session.holds = Holds::Nothing;
    let t0 = Instant::now();
    let softened = session.assemble_body(&input.elements, input.f_ext, input.prescribed)?;
    timings.assembly += t0.elapsed().as_secs_f64();
    super::softening_warning(input.elements.mesh(), softened, input.lambda, warnings);
    Ok(session.system.rhs().to_vec())
}

/// K₁ — the bodies `system` holds plus the parts of `reference` in `set` —
/// factorised with the `interface` unknowns numbered last, and solved at
/// factor 1 (refined). Gives the factor, the solution and the solve's
/// statistics.
fn solve_k1<'a>(
    analysis: &'a mut Option<super::session::Analysis>,
    at: Structure<'_>,
    system: &mut super::system::AssembledSystem,
    input: &Input<'_>,
    k1: K1Set<'_, '_>,
    timings: &mut Timings,
) -> Result<(&'a mut Cholesky, Vec<f64>, SolveInfo)> {
    let K1Set {
        set,
        interface,
        reference,
    } = k1;
    // The zeros are the bodies' alone: no contact part is in yet.
    let zeros = set.structural_zeros(at.pattern, system.values());
    let want = Wanted {
        last: interface,
        zeros: &zeros,
    };
    let mut info = SolveInfo::default();
    let chol = factorisation(
        analysis,
        at,
        input.settings,
        want,
        &mut super::linear::Bookkeeping::new(timings, &mut info),
    )?;
    let t0 = Instant::now();
    system.set_contact(reference, set, at.pattern);
    timings.assembly += t0.elapsed().as_secs_f64();
    let energy = |r: &[f64]| {
        let mut acc = body_energy(&input.elements, r);
        for k in (0..set.parts()).filter(|&k| reference[k]) {
            set.add_energy(k, &mut acc, r);
        }
        acc
    };
    let context = " (the first load step)";
    let x = factor_and_solve(
        at,
        &mut super::linear::SystemAndFactor { chol, system },
        &energy,
        true,
        context,
        &mut super::linear::Bookkeeping::new(timings, &mut info),
    )?;
    info.relative_residual = system.relative_residual(at.pattern, &x);
    info.condition_estimate = chol.condition_estimate();
    finite_statistics(&info)?;
    Ok((chol, x, info))
}

/// The constraints K₁ is made with: the set, the interface unknowns it
/// condenses on, and the parts it holds.
struct K1Set<'c, 's> {
    /// The constraints.
    set: &'c Constraints<'s>,
    /// The interface unknowns, numbered last.
    interface: &'c [usize],
    /// The parts K₁ holds (the initial set).
    reference: &'c [bool],
}

/// K₁'s solution `x` at factor 1 split into x_load and x_gap (module
/// documentation): the gap part of the loads of `reference` does not scale
/// with the load factor, so it is solved apart. Without gap loads, x is
/// x_load and x_gap is empty.
fn split_gap(
    chol: &Cholesky,
    system: &super::system::AssembledSystem,
    set: &Constraints<'_>,
    reference: &[bool],
    x: Vec<f64>,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let gap = gap_loads(set, reference, x.len());
    if gap.iter().all(|&g| g == 0.0) {
        return Ok((x, Vec::new()));
    }
    let mut x_gap = gap.clone();
    chol.solve(&mut x_gap)?;
    let mut x_load = system.rhs().to_vec();
    x_load.iter_mut().zip(&gap).for_each(|(a, g)| *a -= g);
    chol.solve(&mut x_load)?;
    Ok((x_load, x_gap))
}

/// The initial gaps' loads of the parts of `active`, over the unknowns.
fn gap_loads(set: &Constraints<'_>, active: &[bool], n: usize) -> Vec<f64> {
    let mut g = vec![0.0; n];
    for k in (0..set.parts()).filter(|&k| active[k]) {
        for (e, f0) in set.unknowns(k).iter().zip(set.gap_load(k)) {
            if let Some(i) = e {
                g[*i] += f0;
            }
        }
    }
    g
}

/// Refuses a step whose K₁ solution `x1`, or its product with K₁, is not
/// a finite double: a load factor so large that the residual of the
/// step's recovery could overflow (as a solve's does). ‖K₁‖‖x₁‖ bounds
/// what the recovery computes, so this refuses a little before a contact
/// solve of the same loads would (at 10^299.75 rather than above 1e300 on
/// a review's two-block scene; on Hertz both refuse from 1e296).
fn check_size(k1: &K1, x1: &[f64], t: f64) -> Result<()> {
    let size = x1.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let loads = k1.rhs_body.iter().fold(0.0f64, |m, v| m.max((t * v).abs()));
    if (k1.norm * size).is_finite() && loads.is_finite() {
        return Ok(());
    }
    Err(Error::new(
        Status::NumericalFailure,
        format!(
            "the load step at factor {t:e} overflows: ‖K₁‖·‖u‖ = {:e} is beyond double \
             precision; scale the loads, the prescribed displacements or the units",
            k1.norm * size
        ),
    ))
}

/// The scaled values of a step.
fn scaled(v: &[f64], t: f64) -> Vec<f64> {
    v.iter().map(|a| t * a).collect()
}

/// The flags and friction loads a step starts from after a step that ended
/// with the set `warm` and the friction state `friction`: those, or, where
/// it left no friction loads, those of sticking.
pub(crate) fn warm_start(
    set: &Constraints<'_>,
    warm: &[bool],
    friction: &FrictionState,
) -> (Vec<bool>, Vec<f64>) {
    let warm = set.warm_flags(warm, &friction.loads);
    let loads = match friction.loads.is_empty() {
        true => set.stick_loads(&warm),
        false => friction.loads.clone(),
    };
    (warm, loads)
}

/// The statistics a step starts from: the sizes of its unknowns, matrix
/// and factor, with `interface` unknowns condensed.
fn step_info(dofs: &DofMap, pattern: &Pattern, chol: &Cholesky, interface: usize) -> SolveInfo {
    SolveInfo {
        unknowns: dofs.n_free(),
        matrix_nnz: pattern.nnz(),
        factor_nnz: chol.factor_nnz(),
        factorization_bytes: chol.factorization_bytes(),
        split_factorization: chol.is_split(),
        interface_unknowns: interface,
        ..Default::default()
    }
}

/// A step being judged: what its loop solved with.
struct Step<'a, 's> {
    set: &'a Constraints<'s>,
    pairs: &'a [crate::contact::ContactPair],
    mesh: &'a crate::fem::mesh::Mesh,
    prescribed: &'a [f64],
    dofs: &'a DofMap,
    /// The history's key and the step's load factor.
    at: (Key, f64),
}

/// The outcome of a step whose loop settled on the interface (`settled`:
/// the interface values with the final set, friction loads and records):
/// its field stays pending. Its statistics report K₁'s residual.
fn on_interface(
    k1: &K1,
    step: Step<'_, '_>,
    settled: AtInterface,
    mut info: SolveInfo,
) -> Result<Outcome> {
    info.relative_residual = k1.first.relative_residual;
    finite_statistics(&info)?;
    let mut warnings = Vec::new();
    let AtInterface {
        ui,
        active,
        friction_loads: friction,
        history,
        predicted,
    } = settled;
    let contact = {
        let x1 = &k1.condensed().x1;
        let sys = &k1.condensed().system;
        let value = |i: usize| sys.position(i).map_or(x1[i], |p| ui[p]);
        let paired = settled::PairedMesh {
            mesh: step.mesh,
            pairs: step.pairs,
        };
        let active = active.clone();
        let s = settled::settle(step.set, active, &friction, value, paired, &mut warnings)?;
        contact_outcome(s, history, info, predicted)
    };
    let (key, t) = step.at;
    let pending = Pending {
        key,
        t,
        ui,
        active,
        friction_loads: friction,
    };
    Ok(Outcome {
        u: Field::Pending(pending),
        log: Vec::new(),
        info,
        contact: Some(contact),
        warnings,
    })
}

/// The outcome of a step whose loop ended with a full solve (`settled`,
/// of the final system `system` on `pattern`): its whole field at once.
fn on_full_solve(
    step: Step<'_, '_>,
    system: &super::system::AssembledSystem,
    pattern: &Pattern,
    settled: Settled,
    mut info: SolveInfo,
) -> Result<Outcome> {
    info.relative_residual = system.relative_residual(pattern, &settled.x);
    finite_statistics(&info)?;
    let mut warnings = Vec::new();
    super::diagnostics::conditioning_warning(&info, &mut warnings);
    let x = &settled.x;
    let paired = settled::PairedMesh {
        mesh: step.mesh,
        pairs: step.pairs,
    };
    let (active, friction) = (settled.active, &settled.friction_loads);
    let s = settled::settle(step.set, active, friction, |i| x[i], paired, &mut warnings)?;
    let contact = contact_outcome(s, settled.history, info, settled.predicted);
    let u = step.dofs.expand(&settled.x, step.prescribed);
    Ok(Outcome {
        u: Field::Global(u),
        log: Vec::new(),
        info,
        contact: Some(contact),
        warnings,
    })
}

/// The right-hand side of a pending step's system: the bodies' loads
/// `rhs_body` (at factor 1) scaled to the step, with its active parts'
/// loads and its friction loads.
fn step_rhs(set: &Constraints<'_>, rhs_body: &[f64], pending: &Pending) -> Vec<f64> {
    let mut rhs: Vec<f64> = rhs_body.iter().map(|a| pending.t * a).collect();
    for k in (0..set.parts()).filter(|&k| pending.active[k]) {
        for (e, f) in set.unknowns(k).iter().zip(set.load(k)) {
            if let Some(i) = e {
                rhs[*i] += f;
            }
        }
    }
    set.add_friction_loads(&pending.friction_loads, &[], |i, v| rhs[i] += v);
    rhs
}

/// A step's matrix: the assembled `values` (of whatever set they hold)
/// with the parts whose state differs added (+1) or taken out (−1).
struct StepMatrix<'a, 's> {
    pattern: &'a Pattern,
    values: &'a [f64],
    set: &'a Constraints<'s>,
    changed: Vec<(usize, f64)>,
}

impl<'a, 's> StepMatrix<'a, 's> {
    /// The matrix of the flags `active` from `system`'s.
    fn of(
        pattern: &'a Pattern,
        system: &'a super::system::AssembledSystem,
        set: &'a Constraints<'s>,
        active: &[bool],
    ) -> StepMatrix<'a, 's> {
        let held = system.contact();
        let changed = (0..set.parts())
            .filter(|&k| active[k] != held.get(k).copied().unwrap_or(false))
            .map(|k| (k, if active[k] { 1.0 } else { -1.0 }))
            .collect();
        StepMatrix {
            pattern,
            values: system.values(),
            set,
            changed,
        }
    }

    /// y = K v.
    fn mul(&self, v: &[f64], y: &mut [f64]) {
        self.pattern.sym_mul(self.values, v, y);
        for &(k, sign) in &self.changed {
            let (eq, ke) = (self.set.unknowns(k), self.set.matrix(k));
            let n = eq.len();
            for a in 0..n {
                let Some(i) = eq[a] else { continue };
                let mut acc = 0.0;
                for b in 0..n {
                    if let Some(j) = eq[b] {
                        acc += ke[n * a + b] * v[j];
                    }
                }
                y[i] += sign * acc;
            }
        }
    }
}

/// The field of a step's system (`step`, right-hand side `rhs`) by a
/// factorisation of its own matrix. Gives the field and its backward error
/// after refinement.
fn solved_whole(
    at: Structure<'_>,
    settings: Settings,
    step: &StepMatrix<'_, '_>,
    rhs: &[f64],
    context: &str,
) -> Result<(Vec<f64>, f64)> {
    let whole = Wanted {
        last: &[],
        zeros: &[],
    };
    let mut chol = analyse(at, settings, whole)?;
    // Beside the second factor, the solve's vectors, as for any solve.
    let need = memory::solve_bytes(at.dofs.n_global(), 0);
    preflight(need, "the load step's solve")?;
    let mut matrix = reserved::<f64>(step.values.len(), "the load step's matrix")?;
    matrix.extend_from_slice(step.values);
    for &(k, sign) in &step.changed {
        let free: Vec<usize> = step
            .set
            .unknowns(k)
            .iter()
            .map(|e| e.unwrap_or(NOT_FREE))
            .collect();
        let ke: Vec<f64> = step.set.matrix(k).iter().map(|v| sign * v).collect();
        at.pattern.add_element(&mut matrix, &free, &ke);
    }
    chol.factorize(at.pattern, &matrix)
        .map_err(|e| singular_error(at.mesh, at.dofs, e, context))?;
    let mut x = reserved::<f64>(rhs.len(), "the load step's field")?;
    x.extend_from_slice(rhs);
    chol.solve(&mut x)?;
    let product = |v: &[f64], y: &mut [f64]| at.pattern.sym_mul(&matrix, v, y);
    let k_norm = norm_inf(at.pattern, &matrix);
    let mut solve = |r: &mut [f64]| chol.solve(r);
    let omega = refine_by(&product, k_norm, rhs, &mut x, &mut solve, Budget::DIRECT)?;
    check_finite(at, &x, context)?;
    Ok((x, omega))
}
