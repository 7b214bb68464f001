//! Load histories of a [`SolidModel`] (docs/method.md §9): steps whose
//! loads and prescribed displacements are the model's times a load
//! factor, each started from the active set the step before settled in,
//! on the structure, pattern and symbolic analysis the first solve
//! derived. Frictionless contact has no memory, so a step's answer is the
//! direct solve's at its factor; the history saves the analysis and the
//! active-set iterations a cold start would repeat. With the interface
//! condensed (small interfaces), each step factorises once; otherwise
//! once per active-set iteration (docs/method.md §9: B spans whole
//! surfaces in 3D).

use super::*;
use crate::solve::history::check_load_factor;

impl SolidModel {
    /// Solves at `load_factor` times the loads and prescribed
    /// displacements (initial gaps as they are), started from the active
    /// set of the last solve or step (from the touching set if there was
    /// none, or the structure changed since). The loads may change between
    /// steps (a non-proportional history). A factor that is not finite is
    /// refused; on error the model is unchanged.
    pub fn step(&mut self, load_factor: f64, options: &ContactOptions) -> Result<SolveInfo> {
        check_load_factor(load_factor)?;
        let solution = self.solve_at(load_factor, options, self.warm.clone())?;
        Ok(self.settle(solution, true))
    }

    /// Takes back the last load step: the solution and the set the next
    /// step starts from are those before it. Only the last step can be
    /// taken back, and none after a change of the model.
    pub fn revert_step(&mut self) -> Result<()> {
        let undo = self.undo.take().ok_or_else(|| {
            Error::argument("no load step to revert (one step back, none after a change)")
        })?;
        self.solution = undo.solution;
        self.warm = undo.warm;
        Ok(())
    }
}
