//! Load steps under the mortar weighting (docs/method.md §6.11): each step
//! a contact solve of the scaled loads, warm-started from the slave nodes'
//! set of the step before, with the factor of the history's K₁ reused
//! while the stiffness and the options are unchanged.

use std::time::Instant;

use super::{Model, Undo, input_of, keep_matrix, session_of, solution_of};
use crate::contact::ContactOptions;
use crate::error::Result;
use crate::model::solution::{ContactReport, Timings};
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
        self.check_memory(0)?;
        let mut timings = Timings::default();
        let prescribed: Vec<f64> = self.problem.prescribed_vector()?;
        let f_ext: Vec<f64> = self.problem.load_vector()?;
        let prescribed: Vec<f64> = prescribed.iter().map(|u| t * u).collect();
        let f_scaled: Vec<f64> = f_ext.iter().map(|f| t * f).collect();
        let input = input_of(&self.problem, self.settings, &prescribed, &f_scaled)?;
        let contact = self.problem.contact_epoch();
        let warm = self.mortar_warm_start(contact);
        let stiffness = self.problem.stiffness();
        let session = session_of(&mut self.session, &self.problem, &mut timings)?;
        let revision = self.problem.revision();
        let had_matrix = session.system_matrix(revision).is_some();
        let key = history::Key::new(stiffness, options);
        let stepped = solve::mortar_step(
            session,
            &input,
            (options, key),
            warm.as_deref(),
            &mut timings,
        );
        let outcome = match stepped {
            Ok(outcome) => outcome,
            Err(e) => {
                if had_matrix {
                    keep_matrix(session, &input, self.solution.as_ref(), revision);
                }
                return Err(e);
            }
        };
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
        self.solve_warnings = warnings;
        let before = Undo {
            contact,
            state: None,
        };
        self.undo = Some((self.solution.take(), before));
        (self.restored, self.carried) = (None, None);
        self.history_epoch = Some(contact);
        let solution = self.solution.insert(solution);
        Ok(solution
            .contact
            .as_ref()
            .map(|c| c.report.clone())
            .expect("a step has a contact state"))
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
