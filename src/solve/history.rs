//! Quasi-static load histories: a sequence of contact solves whose loads
//! and prescribed displacements change from step to step while the
//! stiffness does not. One factorisation serves the whole history.
//!
//! The first step factorises K₁ — the bodies plus the contact set a
//! contact solve starts from — with the interface unknowns numbered last,
//! and keeps its condensed interface system (Ŝ₁, a dense factor) and two
//! solutions of K₁: x_load for the loads and prescribed displacements at
//! factor 1 (with K₁'s contact loads less their gap part), and x_gap for
//! the loads of K₁'s initial gaps. Everything a step needs is linear in its
//! load factor t: K₁'s solution is x₁(t) = t·x_load + x_gap, and each
//! contact element's load is t·(its load at 1) + (1 − t)·(its gap load).
//! A step is then the condensed active-set loop alone, warm-started from
//! the set of the step before: dense interface work, no sparse solve. New
//! loads (a non-proportional history) cost one sparse solve (x_load anew).
//! The whole field of a step is recovered when asked for
//! ([`recover`]): one sparse solve, or, where K₁'s factor is too poor an
//! inverse of the step's matrix for that to reach working accuracy, a
//! factorisation of the step's matrix itself.

use std::time::Instant;

use super::active_set::{
    ActiveSetLoop, CondensedState, LoopInput, Outcome as LoopOutcome, RECOVERED, Settled, Target,
    body_energy, expand,
};
use super::condensed::{Condensed, FactorSnapshot};
use super::diagnostics::singular_error;
use super::linear::{Structure, check_finite, factor_and_solve};
use super::memory;
use super::report::{IterationRecord, SolveInfo, Timings};
use super::session::{Analysis, Session, Settings, Wanted, analyse, factorisation};
use super::system::AssembledSystem;
use super::{Field, Input, Outcome, contact_outcome, contact_set, finite_statistics};
use crate::contact::{ContactOptions, ContactSet, FrictionState};
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
    /// The contact options it was made for (the iteration cap left out).
    pub fn options(&self) -> &ContactOptions {
        &self.options
    }

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
    /// The interface factor.
    pub factor: FactorSnapshot,
    /// The slip and friction loads of the last step (empty when
    /// frictionless; docs/method.md §6.15).
    pub friction: FrictionState,
    /// The fingerprint of the interface system the history began with
    /// ([`History::set_state`] restores `factor` only into the same one);
    /// `None` when not known (a state saved by an older version).
    pub base: Option<u64>,
}

impl StepState {
    /// Whether this state can continue a history of `elements` contact
    /// elements, frictional (two parts each, with their slip and loads)
    /// or not.
    pub fn fits(&self, elements: usize, frictional: bool) -> Result<()> {
        let parts = if frictional { 2 * elements } else { elements };
        if self.warm.len() != parts || self.factor_active.len() != parts {
            let kind = |n: usize| match n {
                _ if n == elements => "frictionless",
                _ if n == 2 * elements => "frictional",
                _ => "of another contact mesh",
            };
            return Err(Error::argument(format!(
                "the contact state is of {} contact parts ({}), this step's contact set has \
                 {parts} ({}): its friction or contact law differ from the state's history",
                self.warm.len(),
                kind(self.warm.len()),
                kind(parts)
            )));
        }
        let f = &self.friction;
        let frictional_elements = if frictional { elements } else { 0 };
        let sizes = [f.anchors.len(), f.loads.len()];
        if sizes.iter().any(|&m| m != 0 && m != frictional_elements) || sizes[0] != sizes[1] {
            return Err(Error::argument(format!(
                "the contact state's friction data ({} / {} values) do not fit \
                 {frictional_elements} frictional contact elements",
                sizes[0], sizes[1]
            )));
        }
        Ok(())
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
    pub friction: Vec<f64>,
}

/// The state of a load history (module documentation).
pub(crate) struct History {
    key: Key,
    /// The problem revision whose loads `x_load` solves.
    loads: u64,
    /// K₁'s condensed state (lent to the loop during a step).
    state: Option<CondensedState>,
    x_load: Vec<f64>,
    x_gap: Vec<f64>,
    /// The bodies' right-hand side at factor 1.
    rhs_body: Vec<f64>,
    /// The active set of the last step.
    warm: Vec<bool>,
    /// The slip and friction loads of the last step (empty: frictionless
    /// or none yet).
    friction: FrictionState,
    /// Whether the contact set is frictional (two parts per element).
    frictional: bool,
    /// The statistics of K₁'s solve (the residual a step reports).
    first: SolveInfo,
    /// Whether x_load was solved apart for new loads ([`new_loads`]) rather
    /// than with K₁'s first solve: a rebuilt history redoes the same.
    loads_apart: bool,
    /// The fingerprint of K₁'s interface factor
    /// ([`Condensed::factor_fingerprint`]): what a saved state's factor
    /// must have grown from to be restored.
    base: u64,
}

impl History {
    fn condensed(&self) -> &CondensedState {
        self.state.as_ref().expect("the condensed state is back")
    }

    /// The condensed unknowns (0 while its state is out).
    pub fn interface_len(&self) -> usize {
        self.state.as_ref().map_or(0, |c| c.system.len())
    }

    /// K₁'s solution at load factor `t`: t·x_load + x_gap.
    fn x1_at(&self, t: f64) -> Vec<f64> {
        let mut x1: Vec<f64> = self.x_load.iter().map(|a| t * a).collect();
        if !self.x_gap.is_empty() {
            x1.iter_mut().zip(&self.x_gap).for_each(|(a, b)| *a += b);
        }
        x1
    }

    /// The contact state to continue from ([`History::set_state`]).
    pub fn step_state(&self) -> StepState {
        let state = self.condensed();
        StepState {
            warm: self.warm.clone(),
            factor_active: state.factor_active.clone(),
            factor: state.system.factor_snapshot(),
            friction: self.friction.clone(),
            base: Some(self.base),
        }
    }

    /// What rebuilds this history in `state` ([`rebuild`]).
    fn kept(&self, state: StepState) -> Box<Kept> {
        Box::new(Kept {
            key: self.key,
            state,
            loads_apart: self.loads_apart,
            first: self.first,
        })
    }

    /// Continues from `state` (from [`History::step_state`]): from its
    /// active set and friction state, and, when it comes from a history
    /// of this very interface system (the same fingerprint), from its
    /// interface factor too, so that the steps go on bit for bit. A
    /// factor grown from another system (another geometry, stiffness or
    /// contact modulus under the same contact mesh) would solve the wrong
    /// interface problem: this history's own factor stays, and the loop
    /// updates it to the state's set.
    pub fn set_state(&mut self, state: &StepState) -> Result<()> {
        let parts = self.warm.len();
        let elements = if self.frictional { parts / 2 } else { parts };
        state.fits(elements, self.frictional)?;
        if state.base == Some(self.base) {
            let condensed = self.state.as_mut().expect("the condensed state is back");
            condensed.system.restore_factor(&state.factor)?;
            condensed.factor_active.clone_from(&state.factor_active);
        }
        self.warm.clone_from(&state.warm);
        self.friction.clone_from(&state.friction);
        Ok(())
    }
}

/// What rebuilds a history destroyed by a failed call ([`rebuild`]): its
/// key, its contact state, and whether its x_load is solved apart (for new
/// loads) rather than with K₁'s first solve.
#[derive(Clone)]
pub(crate) struct Kept {
    key: Key,
    state: StepState,
    loads_apart: bool,
    /// The statistics of the first solve (its residual is every step's).
    first: SolveInfo,
}

/// A history taken out of the session before a call that may replace
/// it, to be put back if the call fails ([`restore`]).
pub(crate) enum Saved {
    /// Of the current stiffness: its sparse factor will be overwritten, so
    /// it is rebuilt from what it was.
    Rebuild(Box<Kept>),
    /// Of an older stiffness: no step continues it and nothing uses its
    /// sparse factor any more, but its contact state is still the
    /// model's; it goes back as it is.
    Stale(Box<History>),
}

/// Takes the session's history out before a call at problem revision
/// `revision` and stiffness epoch `stiffness` that replaces or ends it.
pub(crate) fn save(session: &mut Session, revision: u64, stiffness: u64) -> Option<Saved> {
    let h = session.history.take()?;
    Some(match h.key.stiffness == stiffness {
        true => Saved::Rebuild(Box::new(Kept {
            key: h.key,
            state: h.step_state(),
            loads_apart: h.loads_apart || h.loads != revision,
            first: h.first,
        })),
        false => Saved::Stale(Box::new(h)),
    })
}

/// Puts back, after a failed call, the history [`save`] took out.
pub(crate) fn restore(session: &mut Session, input: &Input<'_>, revision: u64, saved: Saved) {
    match saved {
        Saved::Rebuild(kept) => rebuild(session, input, revision, &kept),
        Saved::Stale(history) => session.history = Some(*history),
    }
}

/// One load step at factor `t` of the loads and prescribed displacements
/// of `input` (revision `revision` of a problem of stiffness epoch
/// `key.stiffness`), warm-started from the last step's set: starts a
/// history when there is none for `key`. On error the history is as it
/// was. A step whose condensed system turns out singular is solved whole
/// (and the history ends).
pub(crate) fn step(
    session: &mut Session,
    input: &Input<'_>,
    (options, stiffness, revision): (&ContactOptions, u64, u64),
    (t, restored): (f64, Option<&StepState>),
    timings: &mut Timings,
) -> Result<(Outcome, StepState)> {
    let key = Key::new(stiffness, options);
    check_load_factor(t)?;
    super::ensure_unknowns(&session.dofs)?;
    let mut warnings = Vec::new();
    let current = session.history.as_ref().is_some_and(|h| h.key == key);
    // What a failed step must put back: the history it continues or
    // replaces (a pending earlier step is recovered from it, and the next
    // step continues it), and the loads it held.
    let (mut factorizations, mut replaced, mut old_loads) = (0, None, None);
    if !current {
        let at = (key, revision, restored);
        (factorizations, replaced) = start(session, input, at, timings, &mut warnings)?;
    } else if session
        .history
        .as_ref()
        .is_some_and(|h| h.loads != revision)
    {
        old_loads = Some(new_loads(session, input, revision, timings)?);
    }
    let stepped = step_in_history(session, input, (key, options), t, timings, warnings);
    let (mut outcome, before) = match stepped {
        Ok(done) => done,
        Err((e, lost)) => {
            let undo = Undo {
                current,
                replaced,
                old_loads,
                lost,
            };
            put_back(session, input, revision, undo);
            return Err(e);
        }
    };
    outcome.info.factorizations += factorizations;
    if let Some(c) = outcome.contact.as_mut() {
        c.report.info.factorizations += factorizations;
    }
    Ok((outcome, before))
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

/// Whether a step under `options` on a problem of stiffness epoch
/// `stiffness` continues the session's history.
pub(crate) fn continues(session: &Session, options: &ContactOptions, stiffness: u64) -> bool {
    let key = Key::new(stiffness, options);
    session.history.as_ref().is_some_and(|h| h.key == key)
}

/// Rebuilds, after a failed call at problem revision `revision`, the
/// history it destroyed, in the state kept before: the same factorisation of the same
/// matrix, the same solves, then the saved interface factor and warm
/// start, so that what follows is bit for bit what would have followed
/// without the failed step. A rebuild that fails leaves no history (the
/// next step starts one; a pending step's field is then lost, with a
/// message saying so).
fn rebuild(session: &mut Session, input: &Input<'_>, revision: u64, kept: &Kept) {
    let (mut timings, mut warnings) = (Timings::default(), Vec::new());
    let rebuilt = begin(
        session,
        input,
        kept.key,
        revision,
        &mut timings,
        &mut warnings,
    )
    .and_then(|mut history| {
        history.set_state(&kept.state)?;
        history.first = kept.first;
        Ok(history)
    });
    session.history = rebuilt.ok();
    if kept.loads_apart
        && session.history.is_some()
        && new_loads(session, input, revision, &mut timings).is_err()
    {
        session.history = None;
    }
}

/// Starts a history: the bodies' part at factor 1, K₁ with the initial
/// contact set, its factorisation (the only one) and condensed interface
/// system, and its two solutions.
fn begin(
    session: &mut Session,
    input: &Input<'_>,
    key: Key,
    revision: u64,
    timings: &mut Timings,
    warnings: &mut Vec<String>,
) -> Result<History> {
    let rhs_body = assemble_bodies(session, input, timings, warnings)?;
    let Session {
        dofs,
        pattern,
        contact,
        analysis,
        system,
        ..
    } = &mut *session;
    let set = contact_set(input, input.prescribed, contact, dofs, &key.options, &[])?;
    let interface = set.interface_unknowns();
    check_condensable(&key.options, interface.len(), pattern.nnz())?;
    let at = Structure {
        mesh: input.elements.mesh(),
        dofs,
        pattern,
    };
    let reference = set.initial_active();
    let k1 = (&set, &interface[..], &reference[..]);
    let (chol, x, mut info) = solve_k1(analysis, at, system, input, k1, timings)?;
    let (x_load, x_gap) = split_gap(chol, system, (&set, &reference), x)?;
    let t0 = Instant::now();
    let condensed = Condensed::new(chol, interface)?;
    let base = condensed.factor_fingerprint();
    timings.interface += t0.elapsed().as_secs_f64();
    info.interface_unknowns = condensed.len();
    Ok(History {
        key,
        loads: revision,
        state: Some(CondensedState {
            system: condensed,
            x1: Vec::new(),
            reference: reference.clone(),
            factor_active: reference.clone(),
            // K₁'s right-hand side holds no friction load.
            friction_ref: Vec::new(),
        }),
        x_load,
        x_gap,
        rhs_body,
        warm: reference,
        friction: FrictionState::default(),
        frictional: set.is_frictional(),
        first: info,
        loads_apart: false,
        base,
    })
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
    session.set_system_of(None);
    let t0 = Instant::now();
    let softened = session.assemble_body(&input.elements, (input.f_ext, input.prescribed))?;
    timings.assembly += t0.elapsed().as_secs_f64();
    super::softening_warning(input.elements.mesh(), softened, input.lambda, warnings);
    Ok(session.system.rhs().to_vec())
}

/// Refuses a history that could not condense its interface: one of
/// `interface` unknowns not worth condensing beside a matrix of `nnz`
/// values, or `options` that ask for refactorisation.
fn check_condensable(options: &ContactOptions, interface: usize, nnz: usize) -> Result<()> {
    let why = if options.refactorize {
        "the options ask for `refactorize`".to_string()
    } else if interface == 0 {
        // Not "too many": an outside probe read "0 interface unknowns are
        // too many for it" for a contact between prescribed sides.
        "the contact couples no free unknown (every DOF of its nodes is prescribed), so there \
         is no interface to condense"
            .to_string()
    } else if !Condensed::worthwhile(interface, nnz) {
        format!("{interface} interface unknowns are too many for it")
    } else {
        return Ok(());
    };
    Err(Error::new(
        Status::InvalidArgument,
        format!(
            "a load history condenses the contact interface, and {why}; solve each step with \
             solve_contact"
        ),
    ))
}

/// K₁ — the bodies `system` holds plus the elements of `reference` in
/// `set` — factorised with the `interface` unknowns numbered last, and
/// solved at factor 1 (refined). Gives the factor, the solution and the
/// solve's statistics.
fn solve_k1<'a>(
    analysis: &'a mut Option<Analysis>,
    at: Structure<'_>,
    system: &mut AssembledSystem,
    input: &Input<'_>,
    (set, interface, reference): (&ContactSet<'_>, &[usize], &[bool]),
    timings: &mut Timings,
) -> Result<(&'a mut Cholesky, Vec<f64>, SolveInfo)> {
    // The zeros are the bodies' alone: no contact element is in yet.
    let zeros = set.structural_zeros(at.pattern, system.values());
    let want = Wanted {
        last: interface,
        zeros: &zeros,
    };
    let mut info = SolveInfo::default();
    let chol = factorisation(
        analysis,
        (at.mesh, at.dofs, at.pattern),
        input.settings,
        want,
        timings,
        &mut info,
    )?;
    let t0 = Instant::now();
    system.set_contact(reference, set, (at.dofs, at.pattern), input.prescribed);
    timings.assembly += t0.elapsed().as_secs_f64();
    let energy = |r: &[f64]| body_energy(&input.elements, r);
    let context = " (the first load step)";
    let x = factor_and_solve(at, chol, system, &energy, true, context, timings, &mut info)?;
    info.relative_residual = system.relative_residual(at.pattern, &x);
    info.condition_estimate = chol.condition_estimate();
    finite_statistics(&info)?;
    Ok((chol, x, info))
}

/// K₁'s solution `x` at factor 1 split into x_load and x_gap (module
/// documentation): the gap part of the contact loads of `reference` does
/// not scale with the load factor, so it is solved apart. Without gap
/// loads, x is x_load and x_gap is empty.
fn split_gap(
    chol: &Cholesky,
    system: &AssembledSystem,
    (set, reference): (&ContactSet<'_>, &[bool]),
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

/// The gap loads f0 of the elements of `active`, over the unknowns.
fn gap_loads(set: &ContactSet<'_>, active: &[bool], n: usize) -> Vec<f64> {
    let mut g = vec![0.0; n];
    for k in (0..set.parts()).filter(|&k| active[k]) {
        for (a, e) in set.unknowns(k).iter().enumerate() {
            if let Some(i) = e {
                g[*i] += set.stiffness(k).f0[a];
            }
        }
    }
    g
}

/// New loads on the same stiffness: x_load anew (one sparse solve).
/// Returns the loads replaced (x_load, the bodies' right-hand side and
/// their revision), which a failed step puts back.
fn new_loads(
    session: &mut Session,
    input: &Input<'_>,
    revision: u64,
    timings: &mut Timings,
) -> Result<(Vec<f64>, Vec<f64>, u64)> {
    let t0 = Instant::now();
    let rhs_body = body::rhs(
        &input.elements,
        &session.dofs,
        input.f_ext,
        input.prescribed,
    )?;
    let history = session.history.as_mut().expect("a history");
    let options = history.key.options;
    let set = contact_set(
        input,
        input.prescribed,
        &session.contact,
        &session.dofs,
        &options,
        &[],
    )?;
    let mut a = rhs_body.clone();
    let reference = &history.condensed().reference;
    for k in (0..set.parts()).filter(|&k| reference[k]) {
        let (load, f0) = (set.load(k), &set.stiffness(k).f0);
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
    let x_load = std::mem::replace(&mut history.x_load, a);
    let old_rhs = std::mem::replace(&mut history.rhs_body, rhs_body);
    let loads = std::mem::replace(&mut history.loads, revision);
    history.loads_apart = true;
    Ok((x_load, old_rhs, loads))
}

/// The scaled prescribed displacements of a step.
fn scaled(v: &[f64], t: f64) -> Vec<f64> {
    v.iter().map(|a| t * a).collect()
}

/// A failed step's error, with what rebuilds the history if the step
/// destroyed it.
type StepFailure = (Error, Option<Box<Kept>>);

/// Starts a history for `key` at problem revision `revision` (at the
/// contact state `restored` if given), saving the session's history it
/// replaces; if it cannot start, the session is back as it was. Gives the
/// factorisations made and the history replaced.
fn start(
    session: &mut Session,
    input: &Input<'_>,
    (key, revision, restored): (Key, u64, Option<&StepState>),
    timings: &mut Timings,
    warnings: &mut Vec<String>,
) -> Result<(usize, Option<Saved>)> {
    let replaced = save(session, revision, key.stiffness);
    let started =
        begin(session, input, key, revision, timings, warnings).and_then(|mut history| {
            if let Some(state) = restored {
                history.set_state(state)?;
            }
            Ok(history)
        });
    match started {
        Ok(history) => {
            let factorizations = history.first.factorizations;
            session.history = Some(history);
            Ok((factorizations, replaced))
        }
        Err(e) => {
            session.history = None;
            if let Some(saved) = replaced {
                restore(session, input, revision, saved);
            }
            Err(e)
        }
    }
}

/// What puts the session back after a failed step.
struct Undo {
    /// Whether the step continued the session's history (else it started
    /// one in place of `replaced`).
    current: bool,
    replaced: Option<Saved>,
    /// The history's loads before the step's new ones (x_load, the
    /// bodies' right-hand side, the loads' revision).
    old_loads: Option<(Vec<f64>, Vec<f64>, u64)>,
    /// What rebuilds the history if the step lost K₁.
    lost: Option<Box<Kept>>,
}

/// Puts the session's history back as it was before a failed step.
fn put_back(session: &mut Session, input: &Input<'_>, revision: u64, undo: Undo) {
    match (undo.current, session.history.as_mut()) {
        (false, _) => {
            session.history = None;
            if let Some(saved) = undo.replaced {
                restore(session, input, revision, saved);
            }
        }
        (true, Some(h)) => {
            if let Some((x_load, rhs_body, loads)) = undo.old_loads {
                h.x_load = x_load;
                h.rhs_body = rhs_body;
                h.loads = loads;
            }
        }
        // The loop refactorised and lost K₁: the history is rebuilt as it
        // was before the step (its loads are this revision's: a failed
        // step on new loads changed none of its results).
        (true, None) => {
            if let Some(mut kept) = undo.lost {
                kept.loads_apart |= undo.old_loads.is_some();
                rebuild(session, input, revision, &kept);
            }
        }
    }
}

/// The condensed loop of one step from the warm start.
fn step_in_history(
    session: &mut Session,
    input: &Input<'_>,
    (key, options): (Key, &ContactOptions),
    t: f64,
    timings: &mut Timings,
    warnings: Vec<String>,
) -> std::result::Result<(Outcome, StepState), StepFailure> {
    let mesh = input.elements.mesh();
    let prescribed = scaled(input.prescribed, t);
    let Session {
        dofs,
        pattern,
        contact,
        analysis,
        system,
        history,
        ..
    } = &mut *session;
    let h = history.as_mut().expect("a history");
    let anchors = &h.friction.anchors;
    let set =
        contact_set(input, &prescribed, contact, dofs, options, anchors).map_err(|e| (e, None))?;
    let chol = &mut analysis.as_mut().expect("the history's factor").chol;
    let before = h.step_state();
    let mut condensed = h.state.take().expect("the condensed state is back");
    condensed.x1 = h.x1_at(t);
    let mut info = step_info((dofs, pattern), chol, condensed.system.len());
    let loop_input = LoopInput {
        at: Structure {
            mesh,
            dofs,
            pattern,
        },
        elements: &input.elements,
        set: &set,
        prescribed: &prescribed,
        interface: None,
        options: *options,
    };
    let run = ActiveSetLoop::resume(
        loop_input,
        (chol, system),
        (timings, &mut info),
        condensed,
        warm_start(&set, h),
    )
    .run_to_interface();
    let step = Step {
        set: &set,
        pairs: input.pairs,
        prescribed: &prescribed,
        dofs,
        at: (key, t),
        before,
        warnings,
    };
    match run {
        Ok(LoopOutcome::Interface {
            state,
            ui,
            active,
            friction,
            history: records,
        }) => {
            h.state = Some(*state);
            info.relative_residual = h.first.relative_residual;
            info.condition_estimate = chol.condition_estimate();
            info.timings = *timings;
            on_interface(history, step, (ui, active, friction, records), info)
        }
        Ok(LoopOutcome::Full(settled)) => {
            // The condensed system was singular: solved whole, K₁ is gone
            // (rebuilt by the caller if this step fails after all).
            let kept = h.kept(step.before.clone());
            *history = None;
            info.relative_residual = system.relative_residual(pattern, &settled.x);
            info.condition_estimate = chol.condition_estimate();
            info.timings = *timings;
            on_full_solve(step, *settled, info).map_err(|e| (e, Some(kept)))
        }
        Err(failed) => Err(on_loop_error(history, step.before, *failed)),
    }
}

/// The flags and friction loads a step of `h` starts from: the last
/// step's, or, where it left no friction loads, those of sticking.
fn warm_start(set: &ContactSet<'_>, h: &History) -> (Vec<bool>, Vec<f64>) {
    let warm = set.warm_flags(&h.warm, &h.friction.loads);
    let friction = match h.friction.loads.is_empty() {
        true => set.stick_loads(&warm),
        false => h.friction.loads.clone(),
    };
    (warm, friction)
}

/// The statistics a step starts from: the sizes of its unknowns, matrix
/// and factor, with `interface` unknowns condensed.
fn step_info((dofs, pattern): (&DofMap, &Pattern), chol: &Cholesky, interface: usize) -> SolveInfo {
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

/// The history after a step's loop failed with `e` (and `state`, the
/// condensed state, if K₁ survived): back at `before`, or dropped with what
/// rebuilds it.
fn on_loop_error(
    history: &mut Option<History>,
    before: StepState,
    (e, state): (Error, Option<CondensedState>),
) -> StepFailure {
    let h = history.as_mut().expect("a history");
    match state {
        Some(mut state) => {
            state.x1 = Vec::new();
            h.state = Some(state);
            (e, back_to(history, before))
        }
        // The loop refactorised: K₁ is gone; the caller rebuilds it.
        None => {
            let kept = h.kept(before);
            *history = None;
            (e, Some(kept))
        }
    }
}

/// A step being judged: what its loop solved with, and the history's state
/// before it (to go back to on error).
struct Step<'a, 's> {
    set: &'a ContactSet<'s>,
    pairs: &'a [crate::contact::ContactPair],
    prescribed: &'a [f64],
    dofs: &'a DofMap,
    /// The history's key and the step's load factor.
    at: (Key, f64),
    before: StepState,
    warnings: Vec<String>,
}

/// The outcome of a step whose loop settled on the interface (values `ui`
/// with the final set, friction loads and records): its field stays
/// pending. Everything that can fail comes before the history moves on, so
/// that on error it is back where it was.
fn on_interface(
    history: &mut Option<History>,
    mut step: Step<'_, '_>,
    (ui, active, friction, records): (Vec<f64>, Vec<bool>, Vec<f64>, Vec<IterationRecord>),
    info: SolveInfo,
) -> std::result::Result<(Outcome, StepState), StepFailure> {
    let h = history.as_mut().expect("a history");
    let judged = finite_statistics(&info).and_then(|()| {
        let x1 = &h.condensed().x1;
        let sys = &h.condensed().system;
        let value = |g: usize| match step.dofs.free(g) {
            NOT_FREE => step.prescribed[g],
            i => sys.position(i).map_or(x1[i], |p| ui[p]),
        };
        let ue_of = |tri: &[usize; 3]| std::array::from_fn(|a| value(2 * tri[a / 2] + a % 2));
        contact_outcome(
            (step.set, step.pairs),
            ue_of,
            (active.clone(), &friction),
            records,
            info,
            &mut step.warnings,
        )
    });
    let contact = match judged {
        Ok(contact) => contact,
        Err(e) => return Err((e, back_to(history, step.before))),
    };
    h.warm.clone_from(&active);
    if let Some(f) = contact.friction.as_ref() {
        h.friction = f.next.clone();
    }
    let (key, t) = step.at;
    let pending = Pending {
        key,
        t,
        ui,
        active,
        friction,
    };
    let outcome = Outcome {
        u: Field::Pending(super::Pending::Strip(pending)),
        log: Vec::new(),
        info,
        contact: Some(contact),
        warnings: step.warnings,
    };
    Ok((outcome, step.before))
}

/// The outcome of a step whose loop ended with a full solve (`settled`,
/// the history already dropped): its whole field at once.
fn on_full_solve(
    mut step: Step<'_, '_>,
    settled: Settled,
    info: SolveInfo,
) -> Result<(Outcome, StepState)> {
    finite_statistics(&info)?;
    super::diagnostics::conditioning_warning(&info, &mut step.warnings);
    let u = step.dofs.expand(&settled.x, step.prescribed);
    let ue_of = |tri: &[usize; 3]| crate::fem::element_loop::element_values(&u, tri);
    let verdict = (settled.active, &settled.friction[..]);
    let contact = contact_outcome(
        (step.set, step.pairs),
        ue_of,
        verdict,
        settled.history,
        info,
        &mut step.warnings,
    )?;
    let outcome = Outcome {
        u: Field::Global(u),
        log: Vec::new(),
        info,
        contact: Some(contact),
        warnings: step.warnings,
    };
    Ok((outcome, step.before))
}

/// Puts the history back in `before` after a failed step; if even that
/// fails, drops it and returns what rebuilds it.
fn back_to(history: &mut Option<History>, before: StepState) -> Option<Box<Kept>> {
    let h = history.as_mut()?;
    match h.set_state(&before) {
        Ok(()) => None,
        Err(_) => {
            let kept = h.kept(before);
            *history = None;
            Some(kept)
        }
    }
}

/// The whole field of a pending step (global DOFs): u = x₁(t) +
/// K₁⁻¹P(Δg + ΔC u_I), refined against the matrix of the step's set; if
/// that stalls above [`RECOVERED`], solved with a factorisation of that
/// matrix ([`solved_whole`]).
pub(crate) fn recover(session: &Session, input: &Input<'_>, pending: &Pending) -> Result<Vec<f64>> {
    let stale = || Error::state("the load step's factorisation is gone: run the step again");
    let h = session.history.as_ref().ok_or_else(stale)?;
    if h.key != pending.key || h.warm != pending.active {
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
    let set = contact_set(input, &prescribed, contact, dofs, &h.key.options, &[])?;
    let chol = &analysis.as_ref().ok_or_else(stale)?.chol;
    let x1 = h.x1_at(t);
    let active = &pending.active;
    let rhs = step_rhs(&set, &h.rhs_body, pending);
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
        friction: (&pending.friction, &[]),
    };
    let state = (&h.condensed().system, &h.condensed().reference[..]);
    let (mut x, mut omega) = expand(target, chol, state, x1, pending.ui.clone())?;
    let context = format!(" (load step at factor {t:?})");
    if omega.is_nan() || omega > RECOVERED || x.iter().any(|v| !v.is_finite()) {
        // K₁'s factor is too poor an inverse of the step's matrix for the
        // refinement to reach working accuracy (measured: Hertz with the
        // cylinder's mesh 20× finer, h = a/16, stalled at 5.5e-8): the
        // step's matrix is factorised itself, as the loop's full solve
        // does, but beside K₁, which the steps after still need.
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

/// The right-hand side of a pending step's system: the bodies' loads
/// `rhs_body` (at factor 1) scaled to the step, with its active contact
/// elements' loads and its friction loads.
fn step_rhs(set: &ContactSet<'_>, rhs_body: &[f64], pending: &Pending) -> Vec<f64> {
    let mut rhs: Vec<f64> = rhs_body.iter().map(|a| pending.t * a).collect();
    for k in (0..set.parts()).filter(|&k| pending.active[k]) {
        for (q, e) in set.unknowns(k).iter().enumerate() {
            if let Some(i) = e {
                rhs[*i] += set.load(k)[q];
            }
        }
    }
    set.add_friction_loads(&pending.friction, &[], |i, v| rhs[i] += v);
    rhs
}

/// A step's matrix: the assembled `values` (of whatever set they hold)
/// with the contact elements whose state differs added (+1) or taken out
/// (−1).
struct StepMatrix<'a, 's> {
    pattern: &'a Pattern,
    values: &'a [f64],
    set: &'a ContactSet<'s>,
    changed: Vec<(usize, f64)>,
}

impl<'a, 's> StepMatrix<'a, 's> {
    /// The matrix of the flags `active` from `system`'s.
    fn of(
        pattern: &'a Pattern,
        system: &'a AssembledSystem,
        set: &'a ContactSet<'s>,
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
            let (eq, ke) = (self.set.unknowns(k), &self.set.stiffness(k).k);
            for a in 0..6 {
                let Some(i) = eq[a] else { continue };
                let mut acc = 0.0;
                for b in 0..6 {
                    if let Some(j) = eq[b] {
                        acc += ke[6 * a + b] * v[j];
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
    let mut chol = analyse((at.mesh, at.dofs, at.pattern), settings, whole)?;
    // Beside the second factor, the solve's vectors, as for any solve.
    let need = memory::solve_bytes(at.mesh.nodes().len() * 2, 0);
    preflight(need, "the load step's solve")?;
    let mut matrix = reserved::<f64>(step.values.len(), "the load step's matrix")?;
    matrix.extend_from_slice(step.values);
    for &(k, sign) in &step.changed {
        let free = step.set.unknowns(k).map(|e| e.unwrap_or(NOT_FREE));
        let ke = step.set.stiffness(k).k.map(|v| sign * v);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::fixtures::{assembled, contact_set, two_blocks};

    fn inf(v: &[f64]) -> f64 {
        v.iter().fold(0.0f64, |m, a| m.max(a.abs()))
    }

    #[test]
    fn a_step_matrix_is_the_assembled_matrix_of_the_steps_set_and_is_solved_whole() {
        for frictional in [false, true] {
            let p = two_blocks(6, 6);
            let (mut session, prescribed) = assembled(&p);
            let mesh = p.mesh().unwrap();
            let Session {
                dofs,
                pattern,
                contact,
                system,
                ..
            } = &mut session;
            let options = ContactOptions::default();
            let mut set = contact_set(&p, (contact, dofs), &prescribed, &options);
            if frictional {
                let n = set.len();
                let (mu, g) = (vec![0.3; n], vec![400.0; n]);
                set = set.with_friction(&mu, &g, &[], &prescribed).unwrap();
            }
            // The assembled system holds one set (K₁'s), the step another:
            // parts switched both ways, stick parts (k ≥ n) among them.
            let held: Vec<bool> = (0..set.parts()).map(|k| k % 2 == 0).collect();
            let active: Vec<bool> = (0..set.parts()).map(|k| k % 2 == 1 || k % 3 == 0).collect();
            let structure = (&*dofs, &*pattern);
            system.set_contact(&active, &set, structure, &prescribed);
            let (expected, rhs) = (system.values().to_vec(), system.rhs().to_vec());
            system.set_contact(&held, &set, structure, &prescribed);
            let n = dofs.n_free();
            let v: Vec<f64> = (0..n).map(|i| (0.37 * i as f64).sin()).collect();
            let (mut y, mut y_expected) = (vec![0.0; n], vec![0.0; n]);
            let step = StepMatrix::of(pattern, system, &set, &active);
            assert!(!step.changed.is_empty());
            step.mul(&v, &mut y);
            pattern.sym_mul(&expected, &v, &mut y_expected);
            let d: Vec<f64> = y.iter().zip(&y_expected).map(|(a, b)| a - b).collect();
            assert!(
                inf(&d) <= 1e-13 * inf(&y_expected),
                "frictional {frictional}"
            );
            let at = Structure {
                mesh,
                dofs,
                pattern,
            };
            let (x, omega) = solved_whole(at, Settings::default(), &step, &rhs, "").unwrap();
            assert!(omega <= 1e-14, "backward error {omega:e}");
            // Its residual against the assembled matrix of the step's set.
            let mut r = vec![0.0; n];
            pattern.sym_mul(&expected, &x, &mut r);
            r.iter_mut().zip(&rhs).for_each(|(a, b)| *a -= b);
            let scale = inf(&expected) * inf(&x) + inf(&rhs);
            assert!(inf(&r) <= 1e-13 * scale, "frictional {frictional}");
        }
    }
}
