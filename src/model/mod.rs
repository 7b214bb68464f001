//! The model: the [`Problem`] a user describes, the session a solve
//! derives from it, and the [`solution`] of the last solve, behind one
//! facade.
//!
//! Every mutating call either succeeds or leaves the model exactly as it
//! was. Results belong to one epoch of the problem: any change of the
//! problem makes them stale (their accessors then say so). What a solve
//! derives from the structure (the unknowns, the pattern, the contact mesh,
//! the symbolic factorisation) belongs to one structure epoch and is
//! reused by later solves while the epoch holds. Settings that change
//! nothing physical (the ordering) keep every result.

pub mod adapt;
pub mod estimate;
mod facing;
pub mod problem;
mod restart;
pub mod solid;
pub mod solution;
mod stepping;

use std::sync::OnceLock;
use std::time::Instant;

pub use problem::Problem;

use solution::{
    ContactReport, ContactSolution, PositiveZero, Solution, SolveInfo, SystemMatrix, Timings,
};

use crate::contact::mortar::SlaveNode;
use crate::contact::{ContactElement, ContactOptions, ContactPair, ContactWeighting};
use crate::error::{Error, Result};
use crate::fem::curve::Curve;
use crate::fem::element::{Tempering, TriGeometry};
use crate::fem::material::Material;
use crate::fem::mesh::Mesh;
use crate::linalg::Ordering;
use crate::solve::session::{Session, Settings};
use crate::solve::{self, Field, Input, Outcome};

/// A displacement component.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Component {
    /// Horizontal (u).
    X = 0,
    /// Vertical (v).
    Y = 1,
}

impl Component {
    /// Decodes the C ABI integer (0 = x, 1 = y).
    pub fn from_i32(value: i32) -> Option<Component> {
        match value {
            0 => Some(Component::X),
            1 => Some(Component::Y),
            _ => None,
        }
    }
}

/// A 2D elasticity model solved with tempered P1 elements.
pub struct Model {
    problem: Problem,
    settings: Settings,
    /// The model's own thread pool ([`Model::set_threads`]), or `None`
    /// for rayon's global one.
    pool: Option<std::sync::Arc<rayon::ThreadPool>>,
    session: Option<Session>,
    solution: Option<Solution>,
    solve_warnings: Vec<String>,
    /// The load history and what a revert or restart brings back.
    stepping: stepping::Stepping,
}

impl Default for Model {
    fn default() -> Self {
        Model::new()
    }
}

impl Model {
    /// The most threads [`Model::set_threads`] accepts.
    pub const MAX_THREADS: usize = 1024;

    /// An empty model (no mesh, default tempering [`Tempering::Auto`]).
    pub fn new() -> Model {
        Model {
            problem: Problem::new(),
            settings: Settings::default(),
            pool: None,
            session: None,
            solution: None,
            solve_warnings: Vec::new(),
            stepping: stepping::Stepping::default(),
        }
    }

    /// The problem the model solves.
    pub fn problem(&self) -> &Problem {
        &self.problem
    }

    /// Applies a change to the problem, then drops what it made stale: the
    /// session of another structure, results of another epoch.
    fn edit<T>(&mut self, change: impl FnOnce(&mut Problem) -> Result<T>) -> Result<T> {
        let contact = self.problem.contact_epoch();
        let out = change(&mut self.problem)?;
        if self
            .session
            .as_ref()
            .is_some_and(|s| s.structure_epoch() != self.problem.structure_epoch())
        {
            // A frictional history's path survives a change that keeps its
            // contact mesh (a new prescribed DOF), as it survives a revert.
            let kept = (self.problem.contact_epoch() == contact).then_some(contact);
            self.stepping.session_dropped(kept);
            self.session = None;
        }
        if self
            .solution
            .as_ref()
            .is_some_and(|s| s.epoch != self.problem.epoch())
        {
            self.solution = None;
        }
        Ok(out)
    }

    /// Chooses the fill-reducing ordering of the factorisation (default
    /// [`Ordering::Auto`]). Results do not depend on it beyond round-off;
    /// they are kept, and the next solve analyses the matrix anew.
    pub fn set_ordering(&mut self, ordering: Ordering) {
        self.settings.ordering = ordering;
    }

    /// Factorises the two subtrees of a nested-dissection ordering
    /// concurrently, the separator as a dense block (default on; it takes
    /// effect from 20 000 unknowns with two threads or more). Off: one faer
    /// factorisation of the whole tree, parallel only inside its dense
    /// blocks. Results do not depend on it beyond round-off; they are kept.
    pub fn set_parallel_subtrees(&mut self, on: bool) {
        self.settings.parallel_subtrees = on;
    }

    /// Runs the solves on `threads` threads (at most [`Model::MAX_THREADS`])
    /// of the model's own pool (1: no
    /// parallelism at all, for a host that runs its own threads); 0 goes
    /// back to rayon's global pool (as many threads as cores, or
    /// `RAYON_NUM_THREADS`). Results do not depend on it beyond round-off
    /// (from 20 000 unknowns, two threads or more factorise two subtrees
    /// at once); they are kept.
    pub fn set_threads(&mut self, threads: usize) -> Result<()> {
        if threads > Model::MAX_THREADS {
            return Err(Error::argument(format!(
                "threads = {threads} is more than {} (a count gone wrong would exhaust the \
                 machine's threads)",
                Model::MAX_THREADS
            )));
        }
        self.pool = match threads {
            0 => None,
            n => Some(std::sync::Arc::new(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(|e| {
                        Error::new(
                            crate::error::Status::OutOfMemory,
                            format!("cannot start {n} threads: {e}"),
                        )
                    })?,
            )),
        };
        Ok(())
    }

    /// The number of threads a solve runs on.
    pub fn threads(&self) -> usize {
        match &self.pool {
            Some(pool) => pool.current_num_threads(),
            None => rayon::current_num_threads(),
        }
    }

    /// Replaces the mesh. Constraints, loads, contact pairs and results are
    /// discarded (they refer to nodes and edges); materials and tempering
    /// are kept.
    pub fn set_mesh(&mut self, mesh: Mesh) {
        let _ = self.edit(|p| {
            p.set_mesh(mesh);
            Ok(())
        });
        self.solve_warnings.clear();
    }

    /// The mesh, if set.
    pub fn mesh(&self) -> Option<&Mesh> {
        self.problem.mesh()
    }

    /// Sets the tagged boundary edges (0-based nodes), replacing the
    /// previous ones; refused, naming the tag, when a load or contact pair
    /// already declared would lose its edges. See
    /// [`Problem::set_boundary_edges`].
    pub fn set_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        self.edit(|p| p.set_boundary_edges(edges, tags))
    }

    /// Declares the exact shape of the boundary tagged `tag`, so that an
    /// adaptive solve puts the nodes it adds there on the curve
    /// ([`Mesh::set_curve`]). Results of a solve stay valid.
    pub fn set_curve(&mut self, tag: i32, curve: Curve) -> Result<()> {
        self.edit(|p| p.set_curve(tag, curve))
    }

    /// Adds tagged boundary edges (0-based nodes) to those already set.
    /// See [`Problem::add_boundary_edges`].
    pub fn add_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        self.edit(|p| p.add_boundary_edges(edges, tags))
    }

    /// Sets the material of a body. Before a mesh is given any body tag is
    /// accepted; afterwards the body must exist.
    pub fn set_material(&mut self, body: i32, material: Material) -> Result<()> {
        self.edit(|p| p.set_material(body, material))
    }

    /// The material of a body.
    pub fn material(&self, body: i32) -> Option<&Material> {
        self.problem.material(body)
    }

    /// Sets how Jmin is chosen.
    pub fn set_tempering(&mut self, tempering: Tempering) -> Result<()> {
        self.edit(|p| p.set_tempering(tempering))
    }

    /// The tempering policy.
    pub fn tempering(&self) -> Tempering {
        self.problem.tempering()
    }

    /// The λ the tempering uses (None when off or fixed): the given one, or
    /// the larger side of the mesh's bounding box for [`Tempering::Auto`].
    pub fn tempering_lambda(&self) -> Option<f64> {
        self.problem.tempering_lambda()
    }

    /// Prescribes one displacement component of a node (0-based).
    pub fn fix(&mut self, node: usize, component: Component, value: f64) -> Result<()> {
        self.edit(|p| p.fix(node, component, value))
    }

    /// Prescribes a component on every node of the edges tagged `tag`
    /// (all or nothing: the checks come before any change).
    pub fn fix_edges(&mut self, tag: i32, component: Component, value: f64) -> Result<()> {
        self.edit(|p| p.fix_edges(tag, component, value))
    }

    /// Removes every prescribed displacement.
    pub fn clear_constraints(&mut self) {
        let _ = self.edit(|p| {
            p.clear_constraints();
            Ok(())
        });
    }

    /// Prescribed displacements, as (global DOF = 2·node + component, value).
    pub fn constraints(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.problem.constraints()
    }

    /// Applies a pressure (force per unit length, positive pushing into the
    /// body) on the edges tagged `tag`. Loads add up.
    pub fn add_pressure(&mut self, tag: i32, pressure: f64) -> Result<()> {
        self.edit(|p| p.add_pressure(tag, pressure))
    }

    /// Applies a traction vector (force per unit length) on the edges tagged
    /// `tag`. Loads add up.
    pub fn add_traction(&mut self, tag: i32, traction: [f64; 2]) -> Result<()> {
        self.edit(|p| p.add_traction(tag, traction))
    }

    /// Adds a point force at a node (0-based).
    pub fn add_nodal_force(&mut self, node: usize, force: [f64; 2]) -> Result<()> {
        self.edit(|p| p.add_nodal_force(node, force))
    }

    /// Sets the body force (per unit area) of a body.
    pub fn set_body_force(&mut self, body: i32, force: [f64; 2]) -> Result<()> {
        self.edit(|p| p.set_body_force(body, force))
    }

    /// Removes every load (pressures, tractions, nodal and body forces).
    pub fn clear_loads(&mut self) {
        let _ = self.edit(|p| {
            p.clear_loads();
            Ok(())
        });
    }

    /// Declares a potential contact interface between the edges tagged
    /// `tag_a` (on one body) and `tag_b` (on another). Returns the pair's
    /// index. The contact mesh B is built from matching nodes when the two
    /// interfaces' nodes match, else by triangulating the strip between them
    /// (see [`crate::contact::build`]); or hand one over with
    /// [`Model::add_contact_pair_with_mesh`].
    pub fn add_contact_pair(&mut self, tag_a: i32, tag_b: i32) -> Result<usize> {
        self.edit(|p| p.add_contact_pair(tag_a, tag_b))
    }

    /// Declares a contact pair with a contact mesh B handed over by the user
    /// (0-based triangles over interface nodes, as made with Gmsh). Its
    /// orientation is fixed where needed; returns (pair index, number of
    /// triangles flipped).
    pub fn add_contact_pair_with_mesh(
        &mut self,
        tag_a: i32,
        tag_b: i32,
        triangles: &[[usize; 3]],
    ) -> Result<(usize, usize)> {
        self.edit(|p| p.add_contact_pair_with_mesh(tag_a, tag_b, triangles))
    }

    /// [`Problem::add_contact_pairs_auto`] (docs/method.md §6.16): declares
    /// a contact pair for every two tags of different bodies facing each
    /// other within `tolerance` (model units) and returns the indices of the
    /// pairs added (empty when none faces within the tolerance). On error
    /// nothing changes.
    pub fn add_contact_pairs_auto(
        &mut self,
        tags: Option<&[i32]>,
        tolerance: f64,
    ) -> Result<Vec<usize>> {
        self.edit(|p| p.add_contact_pairs_auto(tags, tolerance))
    }

    /// Sets Coulomb's friction coefficient μ ≥ 0 of contact pair `pair`
    /// (docs/method.md §6.15; 0, the default, is frictionless bit for bit).
    pub fn set_friction(&mut self, pair: usize, mu: f64) -> Result<()> {
        self.edit(|p| p.set_friction(pair, mu))
    }

    /// Changes the value of a displacement component fixed before (a
    /// non-proportional load history goes on: the stiffness is the same).
    pub fn set_prescribed(&mut self, node: usize, component: Component, value: f64) -> Result<()> {
        self.edit(|p| p.set_prescribed(node, component, value))
    }

    /// Changes the prescribed value of a component on every node of the
    /// edges tagged `tag`, all or nothing
    /// ([`problem::Problem::set_prescribed_edges`]): the loads of a load
    /// history given per tag, as [`Model::fix_edges`] gives them.
    pub fn set_prescribed_edges(
        &mut self,
        tag: i32,
        component: Component,
        value: f64,
    ) -> Result<()> {
        self.edit(|p| p.set_prescribed_edges(tag, component, value))
    }

    /// Removes every contact pair.
    pub fn clear_contact_pairs(&mut self) {
        let _ = self.edit(|p| {
            p.clear_contact_pairs();
            Ok(())
        });
    }

    /// The declared contact pairs.
    pub fn contact_pairs(&self) -> &[ContactPair] {
        self.problem.contact_pairs()
    }

    /// Mesh warnings, what automatic pairing left out
    /// ([`Problem::pairing_warnings`]: a tag over several bodies, an
    /// interface found again under other tags), then those of the last
    /// solve or load step: tempering of well-shaped elements, an
    /// ill-conditioned system, contact pressures that carry fewer than six
    /// correct digits (a penalty whose overlaps approach the rounding of u,
    /// docs/method.md §6.14), after a solve (not a load step) a body whose
    /// reactions may carry fewer than six correct digits (a "rigid" body
    /// given a huge E, §6.14).
    pub fn warnings(&self) -> Vec<String> {
        let mut w: Vec<String> = self
            .problem
            .mesh()
            .map(|m| m.warnings().to_vec())
            .unwrap_or_default();
        w.extend(self.problem.pairing_warnings().iter().cloned());
        w.extend(self.solve_warnings.iter().cloned());
        w
    }

    /// The assembled external load vector (2 values per node: f_x, f_y) of
    /// the current loads: consistent edge loads, nodal and body forces.
    pub fn load_vector(&self) -> Result<Vec<f64>> {
        self.problem.load_vector()
    }

    /// Solves a scene without contact. On error the model is unchanged.
    pub fn solve(&mut self) -> Result<SolveInfo> {
        self.in_pool(|m| m.run(None).map(|s| s.info))
    }

    /// Checks, before a solve, a load step or a recovery, that the memory
    /// it takes besides the stages that check their own (the vectors, and
    /// the dense work on `n_interface` condensed unknowns of a history that
    /// goes on; [`crate::solve::memory`]) can be had, and
    /// has the threads that will factorise take the dense kernels'
    /// buffers ([`crate::linalg::workspace`]): TFEM_STATUS_OUT_OF_MEMORY
    /// otherwise, before anything is touched.
    fn check_memory(&self, n_interface: usize) -> Result<()> {
        crate::linalg::workspace::ensure()?;
        let n_global = self.problem.mesh_ref()?.nodes().len() * 2;
        let need = crate::solve::memory::solve_bytes(n_global, n_interface);
        crate::error::preflight(need, "the solve's vectors and interface matrices")
    }

    /// Runs `f` in the model's thread pool.
    fn in_pool<R: Send>(&mut self, f: impl FnOnce(&mut Model) -> R + Send) -> R {
        match self.pool.clone() {
            Some(pool) => pool.install(|| f(self)),
            None => f(self),
        }
    }

    /// Solves the contact problem with the active-set loop of
    /// docs/method.md §3. On error (singular, not converged) the model is
    /// unchanged.
    pub fn solve_contact(&mut self, options: &ContactOptions) -> Result<ContactReport> {
        options.validate()?;
        self.in_pool(|m| {
            let solution = m.run(Some(options))?;
            let contact = solution.contact.as_ref();
            Ok(contact
                .map(|c| c.report.clone())
                .expect("a contact solve has a contact state"))
        })
    }

    /// [`Model::solve_contact`] starting from the set the field `guess`
    /// inverts; from the usual initial set if that fails.
    pub(crate) fn solve_contact_from(
        &mut self,
        options: &ContactOptions,
        guess: &[f64],
    ) -> Result<ContactReport> {
        options.validate()?;
        let guessed = self.in_pool(|m| {
            m.run_from(Some(options), Some(guess))
                .map(|s| s.contact.as_ref().map(|c| c.report.clone()))
        });
        match guessed {
            Ok(Some(report)) => Ok(report),
            _ => self.solve_contact(options),
        }
    }

    /// Solves the current epoch of the problem and keeps its results.
    fn run(&mut self, options: Option<&ContactOptions>) -> Result<&Solution> {
        self.run_from(options, None)
    }

    /// [`Model::run`], a contact solve starting from the set the field
    /// `guess` (global) inverts ([`crate::solve::Input::guess`]).
    fn run_from(
        &mut self,
        options: Option<&ContactOptions>,
        guess: Option<&[f64]>,
    ) -> Result<&Solution> {
        let t_start = Instant::now();
        self.problem.check_ready(options.is_some())?;
        self.check_memory(0)?;
        let mut timings = Timings::default();
        let prescribed = self.problem.prescribed_vector()?;
        let f_ext = self.problem.load_vector()?;
        // A solve ends a load history: a step's field waiting for recovery
        // is recovered first (the results of a failed solve stay). A field
        // that cannot be recovered does not stop the solve, which replaces
        // it.
        self.recover_results();
        let mut input = input_of(&self.problem, self.settings, &prescribed, &f_ext)?;
        input.guess = guess;
        let stepping = &mut self.stepping;
        let session = session_of(&mut self.session, &self.problem, &mut timings, stepping)?;
        let epoch = self.problem.epoch();
        // A solve ends a load history; a failed one must not (the next step
        // continues it as if the solve had not been tried).
        let live = stepping.take();
        let had_matrix = session.system_matrix(epoch).is_some();
        let outcome = match solve::solve(session, &input, options, &mut timings) {
            Ok(outcome) => outcome,
            Err(e) => {
                if had_matrix {
                    keep_matrix(session, &input, self.solution.as_ref(), epoch);
                }
                stepping.solve_failed(live, session, &input, &self.problem);
                return Err(e);
            }
        };
        session.holds = crate::solve::session::Holds::Solve(epoch);
        let options = options.copied();
        let (solution, warnings) = solution_of(outcome, f_ext, options, timings, t_start, epoch);
        self.solve_warnings = warnings;
        if let Some(u) = solution.u.get() {
            reaction_warning(&self.problem, &solution, u, &mut self.solve_warnings);
        }
        self.stepping.solved();
        Ok(self.solution.insert(solution))
    }

    /// The field of the current solution, recovered now if it waits.
    fn field(&self) -> Result<&[f64]> {
        let solution = self.solution()?;
        if let Some(u) = solution.u.get() {
            return Ok(u);
        }
        let pending = solution
            .pending
            .as_ref()
            .expect("a field or a pending step");
        let session = self
            .session
            .as_ref()
            .ok_or_else(|| Error::state("the load step's session is gone"))?;
        // On the model's threads, like the step itself (a host that asked
        // for one thread gets no other).
        let recover = || -> Result<Vec<f64>> {
            self.check_memory(self.stepping.interface_len())?;
            let prescribed = self.problem.prescribed_vector()?;
            let f_ext = self.problem.load_vector()?;
            let input = input_of(&self.problem, self.settings, &prescribed, &f_ext)?;
            self.stepping.recover(session, &input, pending)
        };
        let u = match &self.pool {
            Some(pool) => pool.install(recover)?,
            None => recover()?,
        };
        let _ = solution.u.set(u);
        Ok(solution.u.get().expect("just set"))
    }

    fn solution(&self) -> Result<&Solution> {
        self.solution
            .as_ref()
            .filter(|s| s.epoch == self.problem.epoch())
            .ok_or_else(|| {
                Error::state(
                    "no results: solve the model first (results are discarded by any change)",
                )
            })
    }

    /// Nodal displacements [u, v] of the last solve.
    pub fn displacements(&self) -> Result<Vec<[f64; 2]>> {
        Ok(Solution::displacements(self.field()?).positive_zero())
    }

    /// Work of the external loads, Σ f·u (per unit thickness; the whole
    /// ring's for axisymmetric bodies): for a pressure load, the
    /// compliance ∫ p (−u·n).
    pub fn external_work(&self) -> Result<f64> {
        let work = self.solution()?.external_work(self.field()?);
        work.map(PositiveZero::positive_zero)
    }

    /// Statistics of the last solve.
    pub fn solve_info(&self) -> Result<SolveInfo> {
        Ok(self.solution()?.info)
    }

    /// The stiffness matrix of the last solve ([`SystemMatrix`]), borrowed:
    /// nothing is assembled or copied for it. Like the other results it
    /// outlives a failed solve (which rebuilds it, to the last bit, in the
    /// storage it borrowed).
    pub fn system_matrix(&self) -> Result<SystemMatrix<'_>> {
        let solution = self.solution()?;
        if solution.step {
            return Err(Error::state(
                "a load step keeps no system matrix (its factorisation is the history's first): \
                 call solve_contact for one",
            ));
        }
        let epoch = solution.epoch;
        self.session
            .as_ref()
            .and_then(|s| s.system_matrix(epoch))
            .ok_or_else(|| {
                Error::state("no matrix: the last solve failed (solve again for its matrix)")
            })
    }

    /// Element strains [ε_xx, ε_yy, γ_xy] (engineering shear), computed on
    /// request: B̂u / max(J, Jmin), the usual strain for J >= Jmin and the
    /// tempered one below (consistent with the tempered energy).
    pub fn element_strains(&self) -> Result<Vec<[f64; 3]>> {
        let strains = self.solution()?.strains(&self.problem, self.field()?);
        strains.map(PositiveZero::positive_zero)
    }

    /// Element stresses [σ_xx, σ_yy, σ_xy] = D ε, computed on request.
    pub fn element_stresses(&self) -> Result<Vec<[f64; 3]>> {
        let stresses = self.solution()?.stresses(&self.problem, self.field()?);
        stresses.map(PositiveZero::positive_zero)
    }

    /// Element stresses normal to the mesh's plane, computed on request:
    /// the hoop stress σ_θθ of axisymmetric bodies, σ_zz = λ(ε_xx + ε_yy)
    /// in plane strain, 0 in plane stress.
    pub fn element_out_of_plane_stresses(&self) -> Result<Vec<f64>> {
        let stresses = self
            .solution()?
            .out_of_plane_stresses(&self.problem, self.field()?);
        stresses.map(PositiveZero::positive_zero)
    }

    /// J (twice the signed area) of every triangle in the initial
    /// configuration. Needs only a mesh.
    pub fn element_jacobians(&self) -> Result<Vec<f64>> {
        let mesh = self.problem.mesh_ref()?;
        Ok(mesh
            .triangles()
            .iter()
            .map(|t| TriGeometry::new(&mesh.corners(t)).j)
            .collect())
    }

    /// Reaction forces [R_x, R_y] per node: K u − f at prescribed DOFs (zero
    /// elsewhere), computed on request. A solve bounds their rounding per
    /// body and warns where a body's may carry fewer than six correct
    /// digits ([`Model::warnings`]; docs/method.md §6.14).
    pub fn reactions(&self) -> Result<Vec<[f64; 2]>> {
        let reactions = self.solution()?.reactions(&self.problem, self.field()?);
        reactions.map(PositiveZero::positive_zero)
    }

    fn contact_solution(&self) -> Result<&ContactSolution> {
        self.solution()?
            .contact
            .as_ref()
            .ok_or_else(|| Error::state("no contact results: call solve_contact first"))
    }

    /// The elements of the contact mesh B of the last contact solve.
    /// Refused after a solve under the mortar weighting, which has no B
    /// ([`Model::contact_mesh`] still gives the strip the pairs would make).
    pub fn contact_elements(&self) -> Result<&[ContactElement]> {
        Ok(&self.contact_solution()?.state.strip()?.elements)
    }

    /// Active flag of every element of B at convergence. Refused after a
    /// solve under the mortar weighting (its state is per slave node:
    /// [`Model::contact_slave_nodes`]).
    pub fn contact_active(&self) -> Result<&[bool]> {
        Ok(&self.contact_solution()?.state.strip()?.active)
    }

    /// Contact pressure (positive in compression, zero when inactive) of
    /// every element of B. Refused after a solve under the mortar
    /// weighting ([`Model::contact_slave_nodes`]).
    pub fn contact_pressure(&self) -> Result<&[f64]> {
        Ok(&self.contact_solution()?.state.strip()?.pressure)
    }

    /// The state of every slave node (pair, node, tributary, mean gap,
    /// pressure, active) after a contact solve under the mortar weighting
    /// ([`ContactWeighting::Mortar`]); refused after one under the strip's.
    pub fn contact_slave_nodes(&self) -> Result<&[SlaveNode]> {
        self.contact_solution()?.state.slave_nodes()
    }

    /// Sets how every contact pair's energy is weighted along its
    /// interface (docs/method.md §6.11): [`ContactWeighting::Auto`] (the
    /// default: each pair what is right for its interface),
    /// [`ContactWeighting::Strip`] (the elements of B on every pair) or
    /// [`ContactWeighting::Mortar`] (a weighted gap per node of each
    /// interface's coarser side, frictionless). Refuses a weighting that
    /// cannot serve a declared pair (the mortar weighting a pair with
    /// friction or a contact mesh of its own), naming it, and leaves the
    /// model as it was. A change drops the results' validity like any edit
    /// of the contact pairs.
    pub fn set_contact_weighting(&mut self, weighting: ContactWeighting) -> Result<()> {
        self.edit(|p| p.set_contact_weighting(weighting))
    }

    /// How the contact pairs' energy is weighted.
    pub fn contact_weighting(&self) -> ContactWeighting {
        self.problem.contact_weighting()
    }

    /// The shear traction τ = n·σ·t (t = (−n_y, n_x), n the element's
    /// normal) of every element of B in the last contact solve: zero when
    /// open, |τ| ≤ μ p when sticking, μ p when slipping; all zero when the
    /// solve was frictionless.
    pub fn contact_shear(&self) -> Result<Vec<f64>> {
        Ok(self
            .contact_solution()?
            .state
            .strip()?
            .shear()
            .positive_zero())
    }

    /// The frictional state of every element of B in the last contact
    /// solve: 0 open, 1 stick, 2 slip (a frictionless solve: 2 where
    /// active, its surfaces slide freely).
    pub fn contact_friction_state(&self) -> Result<Vec<u8>> {
        Ok(self.contact_solution()?.state.strip()?.friction_state())
    }

    /// The energy dissipated by slip in the last step (or solve) at every
    /// element of B, per unit thickness (for a ring per unit length of
    /// its circumference): ½ τ Δγ_p ≥ 0 (docs/method.md
    /// §6.15); zero when frictionless.
    pub fn contact_dissipation(&self) -> Result<Vec<f64>> {
        Ok(self
            .contact_solution()?
            .state
            .strip()?
            .dissipation()
            .positive_zero())
    }

    /// The report of the last contact solve.
    pub fn contact_report(&self) -> Result<&ContactReport> {
        Ok(&self.contact_solution()?.report)
    }

    /// The force the contact exerts on every node of the last contact
    /// solve, [f_x, f_y] per node (zero off the interfaces; force per unit
    /// thickness), computed on request. It sums to zero over each pair.
    pub fn contact_forces(&self) -> Result<Vec<[f64; 2]>> {
        let forces = self
            .solution()?
            .contact_forces(&self.problem, self.field()?);
        forces.map(PositiveZero::positive_zero)
    }

    /// The contact pressure at every node of the last contact solve (force
    /// per unit area, positive in compression; zero off the interfaces),
    /// computed on request: the interface traction read from both sides
    /// (`contact::traction::interface_pressures`, docs/method.md §6.11) —
    /// exact for a uniform traction, matching or not, and on a curved
    /// non-matching interface much closer to the traction than either
    /// side's own nodal forces. Each pair is read with its own forces over
    /// the part of a node's edges that faces its other side; a node on
    /// several pairs (where three bodies meet) gets their normal forces
    /// over their tributaries together, Σ p_k m_k / Σ m_k: the pressure
    /// where its pairs continue one face (a head joint ending on a bed
    /// face), the tributary-weighted mean of its faces' pressures at a
    /// corner.
    ///
    /// Under the mortar weighting: each slave node's −κG_i/m_i, and at the
    /// nodes of the other side that its weighted gaps read, the slave's
    /// pressure interpolated along the nearest slave edge.
    pub fn contact_nodal_pressures(&self) -> Result<Vec<f64>> {
        self.nodal_pressures(None)
    }

    /// The contact pressure of pair `pair` (0-based) alone at every node of
    /// the last contact solve (zero off that pair's contact mesh; the first
    /// node past an end of the other side that falls inside an edge reads
    /// the other side's pressure near that end), computed on request:
    /// as [`Model::contact_nodal_pressures`] with that pair's forces over
    /// that pair's tributaries only, so that a node where three bodies meet
    /// reads each face on its own (at a block's corner, the bed's pressure
    /// on the bed pair and the head joint's on the head pair). An unknown
    /// pair is refused, naming it.
    pub fn contact_pair_nodal_pressures(&self, pair: usize) -> Result<Vec<f64>> {
        let n = self.contact_pairs().len();
        if pair >= n {
            return Err(crate::error::no_pair(pair, n));
        }
        self.nodal_pressures(Some(pair))
    }

    /// The contact traction at every node of the last contact solve, as
    /// [pressure, shear] per node (force per unit area; zero off the
    /// interfaces), computed on request and read as
    /// [`Model::contact_nodal_pressures`] reads the pressure: the pressure
    /// positive in compression; the shear the tangential traction the
    /// other body exerts on the node's body, along the tangent (−n_y, n_x)
    /// of the body's outward normal n (the direction of travel along a
    /// counter-clockwise boundary), so that both sides of an interface read
    /// one traction with one sign. Each part of the force is the law's
    /// own, split along the normal each element of B measures along (one
    /// normal per point of the interface, side a's): a frictionless
    /// interface reads no shear, to round-off, curved or not; a frictional
    /// one its Coulomb shear. Under the mortar weighting (frictionless) the
    /// shear is zero.
    pub fn contact_nodal_tractions(&self) -> Result<Vec<[f64; 2]>> {
        self.nodal_tractions(None)
    }

    /// The contact traction of pair `pair` (0-based) alone at every node,
    /// as [pressure, shear] ([`Model::contact_nodal_tractions`], read over
    /// that pair's forces and tributaries only, as
    /// [`Model::contact_pair_nodal_pressures`]). An unknown pair is
    /// refused, naming it.
    pub fn contact_pair_nodal_tractions(&self, pair: usize) -> Result<Vec<[f64; 2]>> {
        let n = self.contact_pairs().len();
        if pair >= n {
            return Err(crate::error::no_pair(pair, n));
        }
        self.nodal_tractions(Some(pair))
    }

    /// The strip pairs' contact forces on the nodes split along each
    /// element's normal and tangent
    /// ([`crate::contact::settled::ContactState::framed_forces`]), for the
    /// studies' own readings of them.
    #[cfg(feature = "studies")]
    pub(crate) fn contact_framed_forces(
        &self,
    ) -> Result<std::collections::BTreeMap<(usize, usize), [f64; 2]>> {
        let c = self.contact_solution()?;
        Ok(c.state
            .framed_forces(self.problem.mesh_ref()?, self.field()?))
    }

    /// The nodal pressures of every pair, or of pair `only`.
    fn nodal_pressures(&self, only: Option<usize>) -> Result<Vec<f64>> {
        Ok(self
            .nodal_tractions(only)?
            .into_iter()
            .map(|[p, _]| p)
            .collect())
    }

    /// The nodal tractions of every pair, or of pair `only`
    /// ([`crate::contact::settled::ContactState::nodal_tractions`]),
    /// refused where one is not finite, naming its node.
    fn nodal_tractions(&self, only: Option<usize>) -> Result<Vec<[f64; 2]>> {
        let c = self.contact_solution()?;
        let mesh = self.problem.mesh_ref()?;
        let pairs = self.problem.contact_pairs();
        let t =
            c.state
                .nodal_tractions(mesh, pairs, self.problem.section(), only, self.field()?)?;
        let values = t.iter().flatten().copied();
        crate::error::ensure_finite(values, 2, "contact traction", |v| mesh.node_name(v))?;
        Ok(t.into_iter().map(|t| t.map(f64::positive_zero)).collect())
    }

    /// The normal gap at every node of the last contact solve (zero off the
    /// interfaces; negative where the bodies interpenetrate), computed on
    /// request: the smallest distance, over the elements of B at the node,
    /// of an element's apex from its interface edge (deformed, linearised).
    /// Under the mortar weighting: a slave node's mean gap G_i/m_i, read
    /// at the master's nodes along the slave.
    pub fn contact_gaps(&self) -> Result<Vec<f64>> {
        let gaps = self.solution()?.contact_gaps(&self.problem, self.field()?);
        gaps.map(PositiveZero::positive_zero)
    }

    /// The contact mesh B of the declared pairs, available before any
    /// solve (the elements of pair i carry `pair = i`).
    pub fn contact_mesh(&self) -> Result<Vec<ContactElement>> {
        let problem = &self.problem;
        crate::contact::build_all(problem.mesh_ref()?, problem.contact_pairs())
    }
}

/// After a failed solve or step: the results of this epoch stay, and
/// so does their matrix (a load step's results have none), rebuilt in the
/// session the failed call overwrote.
fn keep_matrix(session: &mut Session, input: &Input<'_>, solution: Option<&Solution>, epoch: u64) {
    let current = solution.filter(|s| s.epoch == epoch);
    if let Some(s) = current.filter(|s| !s.step) {
        let options = s.contact.as_ref().map(|c| &c.options);
        let friction = s
            .contact
            .as_ref()
            .and_then(|c| c.state.strip.friction.as_ref())
            .map_or(&[][..], |f| &f.next.loads[..]);
        if solve::restore(session, input, options, &s.log, friction).is_ok() {
            session.holds = crate::solve::session::Holds::Solve(epoch);
        }
    }
}

/// What a solve reads of `problem` with `settings`, and its global vectors
/// of prescribed displacements and external forces.
fn input_of<'a>(
    problem: &'a Problem,
    settings: Settings,
    prescribed: &'a [f64],
    f_ext: &'a [f64],
) -> Result<Input<'a>> {
    Ok(Input {
        elements: problem.elements()?,
        pairs: problem.contact_pairs(),
        prescribed,
        f_ext,
        lambda: problem.tempering_lambda(),
        settings,
        guess: None,
    })
}

/// The session of the problem's structure in `slot`, built (and timed as
/// analysis) when there is none of that structure.
fn session_of<'s>(
    slot: &'s mut Option<Session>,
    p: &Problem,
    timings: &mut Timings,
    stepping: &mut stepping::Stepping,
) -> Result<&'s mut Session> {
    if slot
        .as_ref()
        .is_some_and(|s| s.structure_epoch() != p.structure_epoch())
    {
        *slot = None;
    }
    if slot.is_none() {
        // A history's K₁ goes with the session it was factorised in.
        stepping.session_dropped(None);
        let t0 = Instant::now();
        let prescribed = |g| p.is_prescribed(g);
        let s = Session::new(
            p.structure_epoch(),
            p.mesh_ref()?,
            prescribed,
            p.contact_pairs(),
            p.weighting_in_use(),
        )?;
        timings.analysis = t0.elapsed().as_secs_f64();
        *slot = Some(s);
    }
    Ok(slot.as_mut().expect("just built"))
}

/// The solution (and the solve's warnings) of a solve's outcome under the
/// contact `options` (none: a solve without contact) for the external
/// forces `f_ext`; fills in the timings of the whole call.
fn solution_of(
    outcome: Outcome,
    f_ext: Vec<f64>,
    options: Option<ContactOptions>,
    mut timings: Timings,
    t_start: Instant,
    epoch: u64,
) -> (Solution, Vec<String>) {
    let mut info = outcome.info;
    timings.total = t_start.elapsed().as_secs_f64();
    info.timings.analysis = timings.analysis;
    info.timings.total = timings.total;
    let contact = outcome.contact.map(|c| {
        let mut report = c.report;
        report.info = info;
        ContactSolution {
            state: c.state,
            report,
            options: options.expect("a contact solve has options"),
        }
    });
    let (u, pending) = match outcome.u {
        Field::Global(u) => (OnceLock::from(u), None),
        Field::Pending(p) => (OnceLock::new(), Some(p)),
    };
    let solution = Solution {
        epoch,
        u,
        pending,
        f_ext,
        info,
        contact,
        log: outcome.log,
        step: false,
    };
    (solution, outcome.warnings)
}

/// The forces each body carries: the sizes of the external and contact
/// forces on its nodes, summed. A body whose reactions balance nothing (a
/// ring held by rigid-motion constraints in a shrink fit: its reactions
/// are zero, their rounding all there is) is judged against what it
/// carries: its reactions are right to that many digits of its forces
/// (the warning fired on 35 of 36 self-equilibrated ring solves, and on
/// self-balanced solves without contact).
fn carried_forces(
    problem: &Problem,
    solution: &Solution,
    u: &[f64],
) -> std::collections::BTreeMap<i32, f64> {
    let mut carried = std::collections::BTreeMap::new();
    let Ok(mesh) = problem.mesh_ref() else {
        return carried;
    };
    let contact = solution.contact_forces(problem, u).unwrap_or_default();
    for (v, body) in mesh.node_body().iter().enumerate() {
        let Some(body) = body else { continue };
        let external = solution.f_ext.get(2 * v..2 * v + 2).unwrap_or(&[0.0, 0.0]);
        let c = contact.get(v).copied().unwrap_or([0.0; 2]);
        *carried.entry(*body).or_insert(0.0) += external[0].hypot(external[1]) + c[0].hypot(c[1]);
    }
    carried
}

/// Below this many correct digits of a body's reactions (at worst) a
/// solve warns ([`reaction_warning`]).
const REACTION_DIGITS: f64 = 6.0;

/// The share of the largest resultant reaction of the bodies below which
/// a body's resultant is judged against that share: a body whose
/// prescribed DOFs carry next to nothing (a symmetry line) is not warned
/// about for losing the digits of nothing.
const REACTION_FLOOR: f64 = 1e-3;

/// The share of the sum of a body's reactions' sizes below which its
/// resultant is judged against that share: a body whose reactions balance
/// each other (stretched between clamps, a patch test) is not warned
/// about for the rounding of a zero resultant.
const REACTION_OWN_FLOOR: f64 = 1e-6;

/// Warns, per body, when its reactions (read later, [`Model::reactions`])
/// may carry fewer than [`REACTION_DIGITS`] correct digits: where a body
/// is so stiff against the forces at its prescribed DOFs (a "rigid" body
/// given E = 1e25, docs/method.md §6.14) that K u − f cancels its terms to
/// their rounding. The bound of a body is the sum over its prescribed DOFs
/// of ε Σ |K_ab u_b| ([`Solution::reactions_and_rounding`]), compared with
/// its resultant reaction (at least [`REACTION_FLOOR`] of the largest
/// body's, [`REACTION_OWN_FLOOR`] of the sum of its reactions' sizes, and
/// the forces it carries, [`carried_forces`]).
/// A bound: measured on the
/// rigid cylinder of `tests/rigid.rs` (h = a/8, the cylinder's E = 1e17 …
/// 1e25 against the block's 2e11), the resultant was off by 1/240 … 1/100
/// of it.
fn reaction_warning(problem: &Problem, solution: &Solution, u: &[f64], warnings: &mut Vec<String>) {
    // Reactions that cannot be computed (not finite) are refused when read.
    let (Ok(mesh), Ok((r, bound))) = (
        problem.mesh_ref(),
        solution.reactions_and_rounding(problem, u),
    ) else {
        return;
    };
    // Per body: the resultant, Σ |R| and the bound.
    let mut per_body: std::collections::BTreeMap<i32, ([f64; 2], f64, f64)> = Default::default();
    for (g, _) in problem.constraints() {
        if let (Some(&rg), Some(&bg), Some(&Some(body))) =
            (r.get(g), bound.get(g), mesh.node_body().get(g / 2))
        {
            let e = per_body.entry(body).or_default();
            e.0[g % 2] += rg;
            e.1 += rg.abs();
            e.2 += bg;
        }
    }
    let norm = |f: [f64; 2]| f[0].hypot(f[1]);
    let largest = per_body.values().fold(0.0f64, |m, v| m.max(norm(v.0)));
    let carried = carried_forces(problem, solution, u);
    for (body, (resultant, sizes, err)) in per_body {
        let force = norm(resultant);
        let judged = force
            .max(REACTION_FLOOR * largest)
            .max(REACTION_OWN_FLOOR * sizes)
            .max(carried.get(&body).copied().unwrap_or(0.0));
        if err <= 10f64.powf(-REACTION_DIGITS) * judged {
            continue;
        }
        let digits = (judged / err).log10().max(0.0);
        let young = problem.material(body).map_or(f64::NAN, |m| m.young());
        warnings.push(format!(
            "the reactions of body {body} (E = {young:.1e}) may carry as few as {digits:.0} \
             correct digits: its stiffness times the rounding of the displacements may put up \
             to {err:.1e} in them, against a resultant reaction of {force:.3e}; a rigid body is \
             modelled by prescribed motion with a modulus like that of the bodies it touches, \
             not by a huge E (docs/method.md §6.14)"
        ));
    }
}
