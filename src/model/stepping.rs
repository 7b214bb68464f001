//! Load histories of a model (docs/method.md §6.12): the one owner of their
//! state — the history whose K₁ the session holds, what a revert brings
//! back, and the contact state a restart or an edit hands to the next step.
//!
//! A call that may overwrite the session's factor (a solve, a step that
//! begins another history) takes the history out, tries, and on failure
//! puts it back, rebuilding K₁ where the call overwrote it; on success the
//! history goes on, or ends.

use std::time::Instant;

use super::restart::{decode, encode, fingerprint_of};
use super::solution::{ContactReport, Solution, Timings};
use super::{Model, Problem, input_of, keep_matrix, session_of, solution_of};
use crate::contact::ContactOptions;
use crate::contact::discretisation::Discretisation;
use crate::error::{Error, Result};
use crate::solve::history::{Along, History, Key, Pending, StepState, check_load_factor};
use crate::solve::session::Session;
use crate::solve::{Input, Outcome};

/// The load-history state of a model.
#[derive(Default)]
pub(super) struct Stepping {
    /// The history the session's factor serves, if any.
    live: Option<Live>,
    /// Before the last load step: its results and contact state
    /// ([`Model::revert_step`]).
    undo: Option<(Option<Solution>, Undo)>,
    /// A contact state to continue from at the next load step, when no
    /// history holds it ([`Model::set_contact_state`], [`Model::revert_step`]).
    restored: Option<KeptState>,
    /// The contact state a frictional history reached before an edit ended
    /// it (a new prescribed DOF, new materials): the next step goes on from
    /// it.
    carried: Option<KeptState>,
}

/// A history and the contact epoch of the problem it began on.
pub(super) struct Live {
    history: History,
    contact: u64,
}

/// What [`Model::revert_step`] restores besides the results: the contact
/// epoch of the step, and the contact state before it.
struct Undo {
    contact: u64,
    state: StepState,
}

/// A contact state the model keeps, with the contact epoch of the problem
/// it belongs to ([`Problem::contact_epoch`]): once the contact mesh B or
/// its parts change (the mesh, its boundary edges, the contact pairs,
/// friction on/off or the weighting), it belongs to none. A change of the
/// set of prescribed DOFs keeps it: like new materials, it changes the
/// stiffness and so the interface factor, which a history restores only
/// into the interface system it was made from (by its fingerprint), not
/// the constraints, over which the active set and slip state are.
#[derive(Clone)]
struct KeptState {
    contact: u64,
    state: StepState,
}

/// What moves the problem's contact epoch ([`Problem::contact_epoch`]), in
/// messages: the structure but the set of prescribed DOFs.
pub(super) const CONTACT_STRUCTURE: &str =
    "the mesh, its boundary edges, the contact pairs, friction on/off or the weighting";

impl Stepping {
    /// The condensed unknowns of the live history (0 without one).
    pub fn interface_len(&self) -> usize {
        self.live.as_ref().map_or(0, |l| l.history.interface_len())
    }

    /// The state of the live history of contact epoch `epoch`, if it is
    /// frictional and no restored state waits: the path a frictional
    /// history reached, which the next step goes on from even where it
    /// begins another history (started from no slip, it forgot its path:
    /// 2.7 % on tests/history.rs's scene, a reviewer's comparison).
    fn frictional_state(&self, epoch: u64) -> Option<KeptState> {
        let live = self.live.as_ref().filter(|l| l.contact == epoch)?;
        if self.restored.is_some() || !live.history.is_frictional() {
            return None;
        }
        Some(KeptState {
            contact: epoch,
            state: live.history.state(),
        })
    }

    /// After an edit of the problem that dropped the session (its K₁ with
    /// it): the history ends, a frictional one's path carried to the next
    /// step where the contact mesh stayed (contact epoch `epoch` before and
    /// after).
    pub fn session_dropped(&mut self, epoch: Option<u64>) {
        if let Some(epoch) = epoch {
            if self.carried.is_none() {
                self.carried = self.frictional_state(epoch);
            }
        }
        self.live = None;
    }

    /// After a successful solve, which ends the history.
    pub fn solved(&mut self) {
        self.live = None;
        self.undo = None;
        self.carried = None;
    }

    /// The pending step's field, from the live history.
    pub fn recover(
        &self,
        session: &Session,
        input: &Input<'_>,
        pending: &Pending,
    ) -> Result<Vec<f64>> {
        let stale = || Error::state("the load step's factorisation is gone: run the step again");
        let live = self.live.as_ref().ok_or_else(stale)?;
        live.history.recover(session, input, pending)
    }

    /// Takes the live history out before a call that may overwrite its
    /// K₁ ([`Stepping::put_back`] if the call fails).
    pub fn take(&mut self) -> Option<Live> {
        self.live.take()
    }

    /// Puts back the history a failed call took out, its K₁ made again in
    /// `session` where the call overwrote it and a step may still continue
    /// it (a history of another stiffness goes back as it is: its contact
    /// state is still the model's). A rebuild that fails ends it (the next
    /// step begins another).
    fn put_back(
        &mut self,
        live: Option<Live>,
        session: &mut Session,
        input: &Input<'_>,
        stiffness: u64,
    ) {
        let Some(mut live) = live else { return };
        if live.history.key().stiffness == stiffness
            && !live.history.intact(session)
            && live.history.rebuild(session, input).is_err()
        {
            return;
        }
        self.live = Some(live);
    }
}

impl Model {
    /// One quasi-static load step: the contact problem with the loads and
    /// prescribed displacements as set, scaled by `load_factor`,
    /// warm-started from the contact state of the last step (the initial
    /// set of a contact solve for the first, or a state given by
    /// [`Model::set_contact_state`]). One factorisation serves every step
    /// while the stiffness (mesh, constraints, materials, tempering, pairs)
    /// and the options are unchanged: a step is dense work on the contact
    /// interface, plus one sparse solve when the loads changed since the
    /// last step (a non-proportional history). Its displacements, and
    /// everything computed from them, are recovered on first request (one
    /// sparse solve, or, where that cannot reach working accuracy on a very
    /// non-matching interface, a factorisation of the step's own matrix,
    /// made and dropped at that request). Where the interface is not
    /// condensed (`refactorize`, or an interface too large to hold densely)
    /// each step is a contact solve of its scaled loads started from the
    /// step before's state. A warm start that leads nowhere (a body left
    /// free, a cycle) is tried again from the first set of the history. The
    /// step is accepted as it is; [`Model::revert_step`] undoes it. On error
    /// the model is unchanged.
    pub fn step(&mut self, load_factor: f64, options: &ContactOptions) -> Result<ContactReport> {
        options.validate()?;
        self.in_pool(|m| m.run_step(load_factor, options))
    }

    fn run_step(&mut self, t: f64, options: &ContactOptions) -> Result<ContactReport> {
        let t_start = Instant::now();
        self.problem.check_ready(true)?;
        check_load_factor(t)?;
        self.check_memory(self.stepping.interface_len())?;
        let mut timings = Timings::default();
        let prescribed = self.problem.prescribed_vector()?;
        let f_ext = self.problem.load_vector()?;
        let key = Key::new(self.problem.stiffness_epoch(), options);
        let contact = self.problem.contact_epoch();
        let live = self.stepping.live.as_ref();
        let continues = live.is_some_and(|l| l.contact == contact && l.history.continues(&key));
        // A step that begins a new history ends the old one: a step's field
        // waiting for recovery is recovered first.
        if !continues {
            self.recover_results();
        }
        let carried = self.stepping.carried.take().or_else(|| {
            (!continues)
                .then(|| self.stepping.frictional_state(contact))
                .flatten()
        });
        let input = input_of(&self.problem, self.settings, &prescribed, &f_ext)?;
        let epoch = self.problem.epoch();
        let restored = self.stepping.restored.take();
        let stepping = &mut self.stepping;
        let session = session_of(&mut self.session, &self.problem, &mut timings, stepping)?;
        let had_matrix = session.system_matrix(epoch).is_some();
        let start = StepStart {
            key,
            epoch,
            contact,
            continues,
            state: restored
                .as_ref()
                .or(carried.as_ref())
                .filter(|k| k.contact == contact)
                .map(|k| &k.state),
        };
        let at = Along {
            t,
            epoch,
            options,
            retry: true,
        };
        let stepped = stepping.run(session, &input, start, &at, &mut timings);
        let (outcome, before, warnings) = match stepped {
            Ok(stepped) => stepped,
            Err(e) => {
                if had_matrix && session.system_matrix(epoch).is_none() {
                    keep_matrix(session, &input, self.solution.as_ref(), epoch);
                }
                // A failed step changes nothing: the next one carries it.
                (self.stepping.restored, self.stepping.carried) = (restored, carried);
                return Err(e);
            }
        };
        let dropped = restored.filter(|k| k.contact != contact);
        let f_scaled: Vec<f64> = f_ext.iter().map(|f| t * f).collect();
        let (mut solution, mut solve_warnings) =
            solution_of(outcome, f_scaled, Some(*options), timings, t_start, epoch);
        solve_warnings.splice(0..0, warnings);
        if dropped.is_some() {
            solve_warnings.push(dropped_warning(&self.problem));
        }
        solution.step = true;
        let undo = Undo {
            contact,
            state: before,
        };
        Ok(self.accept_step(solution, solve_warnings, undo))
    }

    /// Makes a load step's `solution` the results, the results before it
    /// what [`Model::revert_step`] brings back with `undo`: its report.
    fn accept_step(
        &mut self,
        solution: Solution,
        warnings: Vec<String>,
        undo: Undo,
    ) -> ContactReport {
        self.solve_warnings = warnings;
        self.stepping.undo = Some((self.solution.take(), undo));
        let solution = self.solution.insert(solution);
        solution
            .contact
            .as_ref()
            .map(|c| c.report.clone())
            .expect("a step has a contact state")
    }

    /// Undoes the last load step: its results, and the contact state the
    /// next step starts from, go back to what they were before it. Once.
    ///
    /// Refused (the model unchanged) once the contact mesh B or its parts
    /// have changed since that step (the mesh, its boundary edges, the
    /// contact pairs, friction on/off or the weighting), naming the change:
    /// its contact state belongs to the contact mesh before. A change of the
    /// set of prescribed DOFs does not refuse it: like new materials, it
    /// changes the stiffness (and the interface factor, which the next step
    /// then makes anew), not B. The state brought back is the next step's
    /// start even if that step begins a new history (new materials, options
    /// or prescribed DOFs).
    pub fn revert_step(&mut self) -> Result<()> {
        let (_, before) = self
            .stepping
            .undo
            .as_ref()
            .ok_or_else(|| Error::state("no load step to revert"))?;
        if before.contact != self.problem.contact_epoch() {
            return Err(Error::state(format!(
                "the last load step cannot be reverted: {} changed since (a change of \
                 {CONTACT_STRUCTURE} remakes the contact mesh), and its contact state belongs \
                 to the contact mesh before",
                self.problem.contact_change()
            )));
        }
        // Into the history now, so that the step's results brought back
        // (whose field may wait on that history) stay readable; and kept
        // for the next step, which may begin another history (new
        // stiffness or options) and would otherwise lose it.
        if let Some(live) = self.stepping.live.as_mut() {
            live.history.restore(&before.state)?;
        }
        let (solution, before) = self.stepping.undo.take().expect("checked above");
        self.solution = solution;
        self.stepping.restored = Some(KeptState {
            contact: before.contact,
            state: before.state,
        });
        Ok(())
    }

    /// The contact state of the last load step, as bytes: the active set,
    /// the factor of the condensed interface system and the slip state, so
    /// that [`Model::set_contact_state`] continues bit for bit (in this
    /// model or another one holding the same problem).
    pub fn contact_state(&self) -> Result<Vec<u8>> {
        let contact = self.problem.contact_epoch();
        let stepping = &self.stepping;
        let live = stepping.live.as_ref().filter(|l| l.contact == contact);
        let restored = stepping.restored.as_ref().filter(|k| k.contact == contact);
        let carried = stepping.carried.as_ref().filter(|k| k.contact == contact);
        let state = match (live, restored.or(carried)) {
            (_, Some(kept)) => kept.state.clone(),
            (Some(l), None) => l.history.state(),
            (None, None) => return Err(Error::state("no load step yet: no contact state")),
        };
        Ok(encode(&state, fingerprint_of(&self.discretisation()?)))
    }

    /// Continues the load history from `bytes` (from
    /// [`Model::contact_state`]): the next [`Model::step`] starts from that
    /// contact state. Refused, with the model unchanged, if the bytes are
    /// not such a state, belong to another contact mesh, or are frictional
    /// where no pair has friction. From a history of the same problem the
    /// steps go on bit for bit; from one whose interface system differs
    /// (the same contact mesh, another shape or stiffness) they start from
    /// its active set and slip state with this problem's own interface
    /// factor, also when the next step begins a new history (new materials,
    /// options or prescribed DOFs). A change of the contact mesh or its
    /// parts before the next step (the mesh, its boundary edges, the
    /// contact pairs, friction on/off or the weighting) drops the state,
    /// with a warning.
    pub fn set_contact_state(&mut self, bytes: &[u8]) -> Result<()> {
        let d = self.discretisation()?;
        let state = decode(bytes, fingerprint_of(&d))?;
        // Without a history to check it against, check it against the
        // constraints: the elements of B and the weighted gaps, with a
        // stick part more per element when a pair has friction (and the
        // step's law is frictionless).
        let elements = d.strip().len();
        let gaps: usize = d.gaps().iter().map(|p| p.gaps.len()).sum();
        let frictional = self
            .problem
            .contact_pairs()
            .iter()
            .any(|p| p.friction > 0.0);
        state
            .fits(elements + gaps, 0)
            .or_else(|e| match frictional {
                true => state.fits(2 * elements + gaps, elements),
                false => Err(e),
            })?;
        // A step's field waits on the history's contact state, which this
        // replaces: recover it first, so that the results stay readable.
        // (A field that can no longer be recovered stays as it was.)
        if self.solution.as_ref().is_some_and(|s| s.u.get().is_none()) {
            let _ = self.field();
        }
        // Into the current history, and kept for the next step, which may
        // begin another one (as in revert_step).
        if let Some(live) = self.stepping.live.as_mut() {
            let history = &mut live.history;
            let before = history.state();
            if let Err(e) = history.restore(&state) {
                history.restore(&before)?;
                return Err(e);
            }
        }
        self.stepping.restored = Some(KeptState {
            contact: self.problem.contact_epoch(),
            state,
        });
        self.stepping.undo = None;
        Ok(())
    }

    /// The contact discretisation of the declared pairs.
    fn discretisation(&self) -> Result<Discretisation> {
        let p = &self.problem;
        Discretisation::build(p.mesh_ref()?, p.contact_pairs(), p.weighting_in_use())
    }

    /// Recovers the results' field if it waits on the live load history,
    /// before a call that may replace the history (a solve, a step that
    /// begins a new one, whose results then become the revert's).
    pub(super) fn recover_results(&mut self) {
        let epoch = self.problem.epoch();
        let waits = |s: &Solution| s.pending.is_some() && s.u.get().is_none() && s.epoch == epoch;
        if self.solution.as_ref().is_some_and(waits) {
            let _ = self.field();
        }
    }
}

/// Where a step starts: the history's key and the problem's epoch and
/// contact epoch, whether it continues the live history, and the contact
/// state it starts from when it begins one.
struct StepStart<'s> {
    key: Key,
    epoch: u64,
    contact: u64,
    continues: bool,
    state: Option<&'s StepState>,
}

/// A step's outcome, the contact state before it, and the warnings of
/// beginning its history.
type StepResult = (Outcome, StepState, Vec<String>);

impl Stepping {
    /// One step at factor `t` on `session`: continues the live history or
    /// begins another in its place; on error puts back what was there.
    fn run(
        &mut self,
        session: &mut Session,
        input: &Input<'_>,
        start: StepStart<'_>,
        at: &Along<'_>,
        timings: &mut Timings,
    ) -> Result<StepResult> {
        let old = self.take();
        let (mut history, replaced, warnings) = match old {
            Some(live) if start.continues => (live.history, None, Vec::new()),
            other => {
                let (key, epoch) = (start.key, start.epoch);
                match History::begin(session, input, key, epoch, start.state, timings) {
                    Ok((history, warnings)) => (history, other, warnings),
                    Err(e) => {
                        self.put_back(other, session, input, start.key.stiffness);
                        return Err(e);
                    }
                }
            }
        };
        let begun = if start.continues {
            0
        } else {
            history.factorizations()
        };
        match history.step(session, input, at, timings) {
            Ok(mut stepped) => {
                stepped.outcome.info.factorizations += begun;
                if let Some(c) = stepped.outcome.contact.as_mut() {
                    c.report.info.factorizations += begun;
                }
                if !stepped.ended {
                    let contact = start.contact;
                    self.live = Some(Live { history, contact });
                }
                Ok((stepped.outcome, stepped.before, warnings))
            }
            Err(e) => {
                let back = match start.continues {
                    true => Some(Live {
                        history,
                        contact: start.contact,
                    }),
                    false => replaced,
                };
                self.put_back(back, session, input, start.key.stiffness);
                Err(e)
            }
        }
    }

    /// After a failed solve: puts back the history it took out.
    pub fn solve_failed(
        &mut self,
        live: Option<Live>,
        session: &mut Session,
        input: &Input<'_>,
        problem: &Problem,
    ) {
        self.put_back(live, session, input, problem.stiffness_epoch());
    }
}

/// The warning of a step whose given (or reverted) contact state belonged
/// to the contact mesh before a change of `problem`.
fn dropped_warning(problem: &Problem) -> String {
    format!(
        "the contact state given to set_contact_state (or brought back by revert_step) belonged \
         to the contact mesh before {} changed (a change of {CONTACT_STRUCTURE} remakes it): this \
         step started afresh",
        problem.contact_change()
    )
}
