//! Load steps under the mortar weighting (docs/method.md §6.11): each step
//! the contact problem of the scaled loads, warm-started from the slave
//! nodes' set of the step before; the history itself is
//! `solve::mortar_history`.

use std::time::Instant;

use super::{Model, Solution, Undo, input_of, keep_matrix, session_of, solution_of};
use crate::contact::ContactOptions;
use crate::error::Result;
use crate::model::solution::{ContactReport, Timings};
use crate::solve::Outcome;
use crate::solve::mortar_history::{self, Pending as MortarPending, Snapshot};
use crate::solve::session::Session;
use crate::solve::{self, history};

impl Model {
    /// One load step of factor `t` under the mortar weighting
    /// ([`Model::step`]). On error the model is unchanged.
    pub(super) fn run_mortar_step(
        &mut self,
        t: f64,
        options: &ContactOptions,
        t_start: Instant,
    ) -> Result<ContactReport> {
        history::check_load_factor(t)?;
        self.check_memory(self.session.as_ref().map_or(0, |s| s.interface_len()))?;
        let mut timings = Timings::default();
        let prescribed = self.problem.prescribed_vector()?;
        let f_ext = self.problem.load_vector()?;
        let prescribed_t: Vec<f64> = prescribed.iter().map(|u| t * u).collect();
        let f_scaled: Vec<f64> = f_ext.iter().map(|f| t * f).collect();
        let contact = self.problem.contact_epoch();
        let key = history::Key::new(self.problem.stiffness(), options);
        let revision = self.problem.revision();
        let loads = (
            &prescribed[..],
            &f_ext[..],
            &prescribed_t[..],
            &f_scaled[..],
        );
        let (outcome, before) = self.mortar_outcome((t, options), key, loads, &mut timings)?;
        let session = self.session.as_ref().expect("the step's session");
        let elements = &session.contact;
        let (mut solution, warnings) = solution_of(
            outcome,
            f_scaled,
            (elements, Some(*options)),
            timings,
            t_start,
            revision,
        );
        solution.step = true;
        let undo = Undo {
            contact,
            state: None,
            mortar: before,
        };
        (self.restored, self.carried) = (None, None);
        self.history_epoch = Some(contact);
        Ok(self.accept_step((solution, warnings), undo))
    }

    /// The outcome of the step at `t` of history `key` (`loads`: the
    /// prescribed values and forces, unscaled and scaled), with the
    /// interface factor before it when it went on with the history.
    fn mortar_outcome(
        &mut self,
        (t, options): (f64, &ContactOptions),
        key: history::Key,
        (prescribed, f_ext, prescribed_t, f_scaled): (&[f64], &[f64], &[f64], &[f64]),
        timings: &mut Timings,
    ) -> Result<(Outcome, Option<Snapshot>)> {
        // A step that begins a new history ends the old one: the results'
        // field waiting on it is recovered first.
        let continues = self
            .session
            .as_ref()
            .and_then(|s| s.mortar_history.as_ref())
            .is_some_and(|h| h.continues(&key, self.settings));
        if !continues {
            self.recover_results();
        }
        let mut warm = self.mortar_warm_start(self.problem.contact_epoch());
        let revision = self.problem.revision();
        let mut fresh = false;
        loop {
            {
                let unit = input_of(&self.problem, self.settings, prescribed, f_ext)?;
                let scaled = input_of(&self.problem, self.settings, prescribed_t, f_scaled)?;
                let session = session_of(&mut self.session, &self.problem, timings)?;
                let had_matrix = session.system_matrix(revision).is_some();
                let stepped = solve::mortar_step(
                    session,
                    (&scaled, &unit),
                    (options, key, revision),
                    (t, warm.as_deref(), fresh),
                    timings,
                );
                match stepped {
                    Ok(Some(stepped)) => return Ok(stepped),
                    Ok(None) => {}
                    Err(e) => {
                        if had_matrix {
                            keep_matrix(session, &unit, self.solution.as_ref(), revision);
                        }
                        return Err(e);
                    }
                }
            }
            // The history's interface lost its accuracy: the step is solved
            // afresh, from a contact solve's first set (the warm one is what
            // lost it), which ends the history, so the results' field
            // waiting on it is recovered first.
            self.recover_results();
            (fresh, warm) = (true, None);
        }
    }

    /// The slave nodes' set the next mortar step of contact epoch
    /// `contact` starts from: the last step's, when the results held are
    /// a step of this history (also after [`Model::revert_step`] brought
    /// one back); `None` (a contact solve's first set) otherwise.
    fn mortar_warm_start(&self, contact: u64) -> Option<Vec<bool>> {
        if self.history_epoch != Some(contact) {
            return None;
        }
        let solution = self.solution.as_ref().filter(|s| s.step)?;
        let state = solution.contact.as_ref()?.mortar.as_ref()?;
        Some(state.nodes.iter().map(|n| n.active).collect())
    }
}

impl Model {
    /// The field of the mortar step `pending` (of the current problem's
    /// revision), recovered from the session's history.
    pub(super) fn mortar_field(
        &self,
        session: &Session,
        pending: &MortarPending,
    ) -> Result<Vec<f64>> {
        let scale = |v: Vec<f64>| -> Vec<f64> { v.iter().map(|a| pending.t * a).collect() };
        let prescribed = scale(self.problem.prescribed_vector()?);
        let f_ext = scale(self.problem.load_vector()?);
        let input = input_of(&self.problem, self.settings, &prescribed, &f_ext)?;
        mortar_history::recover(session, &input, pending)
    }

    /// Recovers the results' field if it waits on the session's load
    /// history, before a call that may replace the history (a solve, a step
    /// that begins a new one, whose results then become the revert's):
    /// what a failed call took out, it puts back
    /// (`mortar_history::put_back`).
    pub(super) fn recover_results(&mut self) {
        let revision = self.problem.revision();
        let waits =
            |s: &Solution| s.pending.is_some() && s.u.get().is_none() && s.revision == revision;
        if self.solution.as_ref().is_some_and(waits) {
            let _ = self.field();
        }
    }
}
