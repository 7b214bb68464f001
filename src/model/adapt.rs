//! The adaptive solve: solve, estimate, mark, refine, until the estimated
//! error meets a tolerance or a limit is reached (docs/method.md §8).

use std::time::Instant;

use super::Model;
use super::estimate::{Estimate, Scaled, estimate, scaled};
use super::facing::{facing_edges, in_step};
use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::refine::Refinement;

/// What the tolerance of an adaptive solve bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Goal {
    /// The relative error in energy, η/‖u‖_E.
    Energy,
    /// The relative error of the compliance f·u, estimated as (η/‖u‖_E)²
    /// (for a load-driven linear problem the compliance's error is the
    /// energy norm of the error squared).
    Compliance,
}

/// The parameters of [`Model::solve_adaptive`].
#[derive(Debug, Clone)]
pub struct AdaptOptions {
    /// The tolerance on the estimated relative error of `goal` (> 0).
    pub tolerance: f64,
    /// What the tolerance bounds.
    pub goal: Goal,
    /// Stop before a cycle would exceed this many unknowns (its mesh is
    /// not solved).
    pub max_unknowns: usize,
    /// At most this many solves.
    pub max_cycles: usize,
    /// Dörfler's bulk fraction θ ∈ (0, 1]: each cycle refines the fewest
    /// triangles holding θ of the estimate's square (0.5).
    pub fraction: f64,
    /// The contact solves' options (unused without contact pairs).
    pub contact: ContactOptions,
    /// Whether the edges of the contact zones must be resolved to the
    /// tolerance too (true): an interface edge with one end pressed and
    /// the other free locates the zone's edge only to its length ℓ_t, an
    /// error of the contact length ℓc the energy estimate does not see;
    /// while max ℓ_t/ℓc exceeds the tolerance the triangles that own such
    /// edges are refined as well, and the tolerance is not reached.
    pub resolve_contact_edges: bool,
    /// Called with each cycle as it ends (a progress line), if given.
    pub progress: Option<fn(&Cycle)>,
}

impl Default for AdaptOptions {
    fn default() -> Self {
        AdaptOptions {
            tolerance: 1e-2,
            goal: Goal::Energy,
            max_unknowns: 2_000_000,
            max_cycles: 30,
            fraction: 0.5,
            contact: ContactOptions::default(),
            resolve_contact_edges: true,
            progress: None,
        }
    }
}

impl AdaptOptions {
    /// Checks the parameters, naming the bad one.
    pub fn validate(&self) -> Result<()> {
        if !(self.tolerance.is_finite() && self.tolerance > 0.0) {
            return Err(Error::argument(format!(
                "tolerance = {:?} must be finite and > 0",
                self.tolerance
            )));
        }
        if !(self.fraction > 0.0 && self.fraction <= 1.0) {
            return Err(Error::argument(format!(
                "fraction = {:?} must lie in (0, 1]",
                self.fraction
            )));
        }
        if self.max_cycles == 0 || self.max_unknowns == 0 {
            return Err(Error::argument(
                "max_cycles and max_unknowns must be at least 1",
            ));
        }
        self.contact.validate()
    }
}

/// One cycle of an adaptive solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// Unknowns of its solve.
    pub unknowns: usize,
    /// Triangles of its mesh.
    pub triangles: usize,
    /// Its estimate of the goal's relative error.
    pub estimate: f64,
    /// How finely it locates the edges of its contact zones: the longest
    /// interface edge with one end pressed and one free, over the contact
    /// length ℓc (0 without contact, or when the edges are not to be
    /// resolved).
    pub contact_edge: f64,
    /// Seconds of the cycle: solve and estimate (refinement not counted).
    pub seconds: f64,
}

/// The outcome of [`Model::solve_adaptive`].
#[derive(Debug, Clone, PartialEq)]
pub struct AdaptReport {
    /// Every cycle, in order; the last is the model's solution.
    pub cycles: Vec<Cycle>,
    /// Whether the last estimate (and its contact edges, if they are to be
    /// resolved) meets the tolerance.
    pub reached: bool,
    /// Total seconds, refinements included.
    pub seconds: f64,
}

impl Model {
    /// The error estimate of the last solve (docs/method.md §8), computed
    /// on request.
    pub fn error_estimate(&self) -> Result<Estimate> {
        estimate(&self.problem, self.solution()?, self.field()?)
    }

    /// Solves to a tolerance: solve (a contact solve when the model has
    /// pairs), estimate, refine the triangles that hold `fraction` of the
    /// estimate by newest-vertex bisection, and again, until the estimate
    /// of the goal's relative error meets `tolerance`, or the next mesh
    /// would exceed `max_unknowns`, or `max_cycles` solves are done —
    /// then a warning ([`Model::warnings`]) says what was reached. The
    /// model keeps the refined mesh (nodes appended after the given ones,
    /// which keep their indices), its loads, constraints and pairs carried
    /// over ([`crate::Problem::refined`]), and the last solve's results.
    /// Bad options, and a pair with a contact mesh of its own (which does
    /// not refine), are refused before anything changes; a solve or a
    /// refinement that fails leaves the model as it was given, earlier
    /// results included (the cycles run on a copy of the problem, which
    /// the model takes only when they succeed).
    pub fn solve_adaptive(&mut self, options: &AdaptOptions) -> Result<AdaptReport> {
        options.validate()?;
        if let Some(i) = (self.problem.contact_pairs().iter()).position(|p| p.user_mesh.is_some()) {
            return Err(Error::argument(format!(
                "contact pair {i} has a contact mesh of its own, which refinement cannot carry: \
                 let tfem build it (add_contact_pair)"
            )));
        }
        let mut work = Model {
            problem: self.problem.clone(),
            settings: self.settings,
            pool: self.pool.clone(),
            session: None,
            solution: None,
            solve_warnings: Vec::new(),
            stepping: Default::default(),
        };
        let report = work.adapt(options)?;
        // The refined problem's epochs run on from the given one's, past
        // every result and session the model holds: all are replaced.
        *self = work;
        Ok(report)
    }

    fn adapt(&mut self, options: &AdaptOptions) -> Result<AdaptReport> {
        let t_start = Instant::now();
        let mut refinement = Refinement::new(self.problem.mesh_ref()?);
        let mut cycles = Vec::new();
        // The coarser level's field on the refined mesh: where the next
        // contact solve starts.
        let mut guess: Option<Vec<f64>> = None;
        loop {
            let (cycle, est, edges) = self.cycle(options, guess.as_deref())?;
            if let Some(progress) = options.progress {
                progress(&cycle);
            }
            cycles.push(cycle);
            let goal_met = cycle.estimate <= options.tolerance;
            let edges_met = cycle.contact_edge <= options.tolerance;
            if goal_met && edges_met {
                break;
            }
            if cycles.len() >= options.max_cycles {
                self.warn_unreached(options, &cycle, "cycles");
                break;
            }
            let mut marked = if goal_met {
                Vec::new()
            } else {
                dorfler(&est.squared, options.fraction)
            };
            if !edges_met {
                marked.extend(edges.owners);
            }
            if marked.is_empty() {
                // An estimate of exactly zero: no mesh is better.
                break;
            }
            let mesh = self.problem.mesh_ref()?;
            in_step(
                &refinement,
                mesh,
                &facing_edges(&self.problem)?,
                &mut marked,
            )?;
            let refined = refinement.refine(mesh, &marked)?;
            let interpolated = refined.interpolate(self.field()?, 2)?;
            let next = self.problem.refined(refined.mesh, &refined.parents)?;
            if unknowns_of(&next)? > options.max_unknowns {
                self.warn_unreached(options, &cycle, "unknowns");
                break;
            }
            guess = Some(interpolated);
            self.edit(|p| {
                *p = next;
                Ok(())
            })?;
        }
        let reached = cycles.last().is_some_and(|c| {
            c.estimate <= options.tolerance && c.contact_edge <= options.tolerance
        });
        Ok(AdaptReport {
            cycles,
            reached,
            seconds: t_start.elapsed().as_secs_f64(),
        })
    }

    /// One cycle's solve (a contact solve from `guess` where given) and
    /// what it says of its error.
    fn cycle(
        &mut self,
        options: &AdaptOptions,
        guess: Option<&[f64]>,
    ) -> Result<(Cycle, Scaled, ContactEdges)> {
        let t0 = Instant::now();
        let with_contact = !self.problem.contact_pairs().is_empty();
        let info = match (with_contact, guess) {
            (true, Some(u)) => self.solve_contact_from(&options.contact, u)?.info,
            (true, None) => self.solve_contact(&options.contact)?.info,
            (false, _) => self.solve()?,
        };
        // Scaled: the estimate an adaptive solve reads cannot overflow.
        let est = scaled(&self.problem, self.solution()?, self.field()?)?;
        let relative = match options.goal {
            Goal::Energy => est.relative(),
            Goal::Compliance => est.relative() * est.relative(),
        };
        let edges = if with_contact && options.resolve_contact_edges {
            self.contact_edges()?
        } else {
            ContactEdges::default()
        };
        let cycle = Cycle {
            unknowns: info.unknowns,
            triangles: self.problem.mesh_ref()?.triangles().len(),
            estimate: relative,
            contact_edge: edges.relative,
            seconds: t0.elapsed().as_secs_f64(),
        };
        Ok((cycle, est, edges))
    }

    /// The edges of the contact zones of the last contact solve: the
    /// interface edges (boundary edges of a pair's tags) with one end
    /// pressed and the other free, read from the nodal pressures (pressed:
    /// above 1e-9 of the largest, round-off below).
    fn contact_edges(&self) -> Result<ContactEdges> {
        let pressure = self.contact_nodal_pressures()?;
        let length = self.contact_report()?.contact_length;
        let largest = pressure.iter().fold(0.0f64, |m, &p| m.max(p));
        let pressed = |v: usize| pressure[v] > 1e-9 * largest;
        let mesh = self.problem.mesh_ref()?;
        let tags: Vec<i32> = (self.problem.contact_pairs().iter())
            .flat_map(|p| [p.tag_a, p.tag_b])
            .collect();
        let mut out = ContactEdges::default();
        let mut longest = 0.0f64;
        for e in mesh.boundary_edges() {
            let [p, q] = e.nodes;
            let (Some((owner, _)), true) = (e.owner, tags.contains(&e.tag)) else {
                continue;
            };
            if pressed(p) != pressed(q) {
                let (a, b) = (mesh.nodes()[p], mesh.nodes()[q]);
                longest = longest.max((a[0] - b[0]).hypot(a[1] - b[1]));
                out.owners.push(owner);
            }
        }
        if length > 0.0 {
            out.relative = longest / length;
        }
        Ok(out)
    }

    fn warn_unreached(&mut self, options: &AdaptOptions, reached: &Cycle, limit: &str) {
        let mut unmet = Vec::new();
        if reached.estimate > options.tolerance {
            unmet.push(format!(
                "an estimated relative error of {:.3e}",
                reached.estimate
            ));
        }
        if reached.contact_edge > options.tolerance {
            unmet.push(format!(
                "the contact zones' edges located to {:.3e} of the contact length",
                reached.contact_edge
            ));
        }
        self.solve_warnings.push(format!(
            "the adaptive solve stopped at its limit of {limit} with {}, above the tolerance {:.3e}",
            unmet.join(" and "),
            options.tolerance
        ));
    }
}

/// Where a contact solve locates the edges of its zones only coarsely.
#[derive(Debug, Default)]
struct ContactEdges {
    /// The longest interface edge with one end pressed and one free, over
    /// the contact length (0 without contact).
    relative: f64,
    /// The triangles that own such edges.
    owners: Vec<usize>,
}

/// The unknowns a solve of `problem` would have: the DOFs of the nodes
/// of bodies that are not prescribed.
fn unknowns_of(problem: &crate::Problem) -> Result<usize> {
    let mesh = problem.mesh_ref()?;
    let used = mesh.node_body().iter().filter(|b| b.is_some()).count();
    let fixed = problem
        .constraints()
        .filter(|(g, _)| mesh.node_body()[g / 2].is_some())
        .count();
    Ok(2 * used - fixed)
}

/// Dörfler's marking: the fewest triangles whose η_e² sum to at least
/// `fraction` of the total, largest first.
pub fn dorfler(squared: &[f64], fraction: f64) -> Vec<usize> {
    let total: f64 = squared.iter().sum();
    let mut order: Vec<usize> = (0..squared.len()).collect();
    order.sort_by(|&a, &b| squared[b].total_cmp(&squared[a]));
    let mut marked = Vec::new();
    let mut sum = 0.0;
    for e in order {
        if sum >= fraction * total || squared[e] <= 0.0 {
            break;
        }
        sum += squared[e];
        marked.push(e);
    }
    marked
}
