//! The results of a solve: displacements, the external forces they
//! answer, statistics, and the contact state. Everything else — strains,
//! stresses, reactions — is computed from them when asked for.

use super::problem::Problem;
use crate::contact::ContactOptions;
use crate::contact::settled::ContactState;
use std::sync::OnceLock;

use crate::error::{Error, Result, ensure_finite};
use crate::fem::element::{b_hat, hoop_strain, tempered_jacobian};
use crate::fem::element_loop::element_values;
use crate::solve::Pending;

pub use crate::solve::report::{ContactReport, IterationRecord, SolveInfo, Timings};
pub use crate::solve::system::SystemMatrix;

/// Results carry +0.0 where a computation left −0.0 (a sum of nothing, a
/// product with a negative zero): a signed zero means nothing in a field or
/// a force, and an output printed "-0" reads as a sign that is not there (a
/// contact length of −0.0 was reported).
pub(crate) trait PositiveZero {
    /// The value with every −0.0 made +0.0 (nothing else changes: x + 0.0
    /// is x for every other double).
    fn positive_zero(self) -> Self;
}

impl PositiveZero for f64 {
    fn positive_zero(self) -> f64 {
        self + 0.0
    }
}

impl<const N: usize> PositiveZero for [f64; N] {
    fn positive_zero(self) -> [f64; N] {
        self.map(|v| v + 0.0)
    }
}

impl<T: PositiveZero> PositiveZero for Vec<T> {
    fn positive_zero(self) -> Vec<T> {
        self.into_iter().map(PositiveZero::positive_zero).collect()
    }
}

/// The results of one successful solve of one epoch of a problem.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    /// The problem epoch it solves.
    pub epoch: u64,
    /// Displacements over every global DOF: set by the solve, or recovered
    /// on first request from `pending` (a load step).
    pub u: OnceLock<Vec<f64>>,
    /// A load step's interface values, when its field waits for recovery.
    pub pending: Option<Pending>,
    /// External forces over every global DOF.
    pub f_ext: Vec<f64>,
    /// Statistics.
    pub info: SolveInfo,
    /// The contact state, for a contact solve.
    pub contact: Option<ContactSolution>,
    /// The contact elements its final system switched after the bodies'
    /// part, to rebuild that system after a failed solve.
    pub log: Vec<Vec<usize>>,
    /// Whether a load step made it (it then has no system matrix).
    pub step: bool,
}

/// The contact state of a solution.
#[derive(Debug, Clone)]
pub(crate) struct ContactSolution {
    /// The state the constraints settled in.
    pub state: ContactState,
    /// The report.
    pub report: ContactReport,
    /// The options of the solve.
    pub options: ContactOptions,
}

impl Solution {
    /// Nodal displacements [u, v] of the field `u`.
    pub fn displacements(u: &[f64]) -> Vec<[f64; 2]> {
        u.chunks_exact(2).map(|c| [c[0], c[1]]).collect()
    }

    /// Work of the external loads, Σ f·u.
    pub fn external_work(&self, u: &[f64]) -> Result<f64> {
        let w = self.f_ext.iter().zip(u).map(|(f, u)| f * u).sum();
        ensure_finite([w], 1, "work", |_| "the external loads".to_string())?;
        Ok(w)
    }

    /// Element strains [ε_xx, ε_yy, γ_xy]: B̂u / max(J, Jmin).
    pub fn strains(&self, problem: &Problem, u: &[f64]) -> Result<Vec<[f64; 3]>> {
        Ok(self
            .all_strains(problem, u)?
            .into_iter()
            .map(|(e, _)| e)
            .collect())
    }

    /// Each element's in-plane strain and its out-of-plane strain (a
    /// ring's hoop strain, [`hoop_strain`]; 0 in the plane modes).
    fn all_strains(&self, problem: &Problem, u: &[f64]) -> Result<Vec<([f64; 3], f64)>> {
        let elements = problem.elements()?;
        let mut out = Vec::with_capacity(elements.mesh().triangles().len());
        elements.for_each(|el| {
            let Some(t) = tempered_jacobian(&el.geo, el.jmin)? else {
                out.push(([0.0; 3], 0.0));
                return Ok(());
            };
            let b = b_hat(&el.geo);
            let ue = element_values(u, el.nodes);
            let eps = std::array::from_fn(|r| (0..6).map(|c| b[r][c] * ue[c]).sum::<f64>() / t);
            let normal = match el.section.is_revolution() {
                true => hoop_strain(&el.geo, el.x, t, &ue),
                false => 0.0,
            };
            out.push((eps, normal));
            Ok(())
        })?;
        let mesh = elements.mesh();
        let values = out.iter().flat_map(|(e, n)| e.iter().chain([n]).copied());
        ensure_finite(values, 4, "strain", |t| mesh.triangle_name(t))?;
        Ok(out)
    }

    /// Element stresses [σ_xx, σ_yy, σ_xy] = D ε (a ring's with the hoop
    /// strain's part).
    pub fn stresses(&self, problem: &Problem, u: &[f64]) -> Result<Vec<[f64; 3]>> {
        let strains = self.all_strains(problem, u)?;
        let elements = problem.elements()?;
        let stresses: Vec<[f64; 3]> = strains
            .iter()
            .zip(elements.mesh().body_of())
            .map(|((eps, hoop), &body)| elements.material(body).in_plane_stress(eps, *hoop))
            .collect();
        let mesh = elements.mesh();
        ensure_finite(stresses.iter().flatten().copied(), 3, "stress", |t| {
            mesh.triangle_name(t)
        })?;
        Ok(stresses)
    }

    /// Element stresses normal to the mesh's plane: σ_zz in plane strain,
    /// 0 in plane stress, the hoop stress σ_θθ of a ring
    /// ([`crate::Material::out_of_plane_stress`]).
    pub fn out_of_plane_stresses(&self, problem: &Problem, u: &[f64]) -> Result<Vec<f64>> {
        let strains = self.all_strains(problem, u)?;
        let elements = problem.elements()?;
        let stresses: Vec<f64> = strains
            .iter()
            .zip(elements.mesh().body_of())
            .map(|((eps, normal), &body)| elements.material(body).out_of_plane_stress(eps, *normal))
            .collect();
        let mesh = elements.mesh();
        ensure_finite(stresses.iter().copied(), 1, "stress", |t| {
            mesh.triangle_name(t)
        })?;
        Ok(stresses)
    }

    /// Reaction forces [R_x, R_y] per node: K u − f at prescribed DOFs
    /// (zero elsewhere), the active contact elements included.
    pub fn reactions(&self, problem: &Problem, u: &[f64]) -> Result<Vec<[f64; 2]>> {
        let (r, _) = self.reactions_and_rounding(problem, u)?;
        Ok(r.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
    }

    /// The reactions over every global DOF (zero where free) and, per DOF,
    /// the rounding the sum K u leaves in them: ε Σ |K_ab u_b| over the
    /// terms summed (the terms' own rounding, and that of u, ε|u_b|, times
    /// the stiffness). Where the elements of a body are far stiffer than
    /// the forces its prescribed DOFs carry (a "rigid" body modelled with
    /// a huge E), the terms cancel to ε of their size and this bound
    /// exceeds the reactions (docs/method.md §6.14).
    pub fn reactions_and_rounding(
        &self,
        problem: &Problem,
        u: &[f64],
    ) -> Result<(Vec<f64>, Vec<f64>)> {
        let elements = problem.elements()?;
        let mesh = elements.mesh();
        let mut r = vec![0.0; u.len()];
        let mut bound = vec![0.0; u.len()];
        // A dense mask: a solve reads it for every element (a map look-up
        // per DOF cost 1.8 % of a 1M-DOF contact solve, a reviewer's
        // measurement).
        let mut fixed = vec![false; u.len()];
        for (g, _) in problem.constraints() {
            if let Some(f) = fixed.get_mut(g) {
                *f = true;
            }
        }
        let fixed = &fixed;
        let mut add = |tri: &[usize; 3], ke: &[f64; 36], f0: Option<&[f64; 6]>| {
            let ue = element_values(u, tri);
            for a in 0..6 {
                let g = 2 * tri[a / 2] + a % 2;
                if fixed[g] {
                    let (ku, size) = (0..6).fold((0.0, 0.0), |(s, m), b| {
                        let t = ke[a * 6 + b] * ue[b];
                        (s + t, m + t.abs())
                    });
                    r[g] += ku - f0.map_or(0.0, |f| f[a]);
                    bound[g] += f64::EPSILON * size;
                }
            }
        };
        let touches = |tri: &[usize; 3]| tri.iter().any(|&v| fixed[2 * v] || fixed[2 * v + 1]);
        elements.for_each(|el| {
            // Only rows of prescribed DOFs are read.
            if touches(el.nodes) {
                add(el.nodes, &elements.stiffness(el)?, None);
            }
            Ok(())
        })?;
        if let Some(c) = &self.contact {
            c.state.add_reactions(mesh, u, fixed, &mut r, &mut bound);
        }
        for (g, v) in r.iter_mut().enumerate() {
            if fixed[g] {
                *v -= self.f_ext[g];
            }
        }
        ensure_finite(r.iter().copied(), 2, "reaction", |v| mesh.node_name(v))?;
        Ok((r, bound))
    }

    /// The force the contact exerts on every node, [f_x, f_y] per node
    /// (zero off the interfaces): minus the internal force K_e u_e − f0_e
    /// of the active elements of B. It sums to zero over each pair.
    pub fn contact_forces(&self, problem: &Problem, u: &[f64]) -> Result<Vec<[f64; 2]>> {
        let mesh = problem.mesh_ref()?;
        let mut f = vec![0.0; u.len()];
        self.contact_state()?
            .state
            .forces(mesh, u, |_, g, v| f[g] += v);
        ensure_finite(f.iter().copied(), 2, "contact force", |v| mesh.node_name(v))?;
        Ok(f.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
    }

    /// The normal gap at every node ([`ContactState::gaps`]).
    pub fn contact_gaps(&self, problem: &Problem, u: &[f64]) -> Result<Vec<f64>> {
        let c = self.contact_state()?;
        let mesh = problem.mesh_ref()?;
        let gap = c.state.gaps(mesh, problem.contact_pairs(), u)?;
        ensure_finite(gap.iter().copied(), 1, "contact gap", |v| mesh.node_name(v))?;
        Ok(gap)
    }

    fn contact_state(&self) -> Result<&ContactSolution> {
        self.contact
            .as_ref()
            .ok_or_else(|| Error::state("no contact results: call solve_contact first"))
    }
}
