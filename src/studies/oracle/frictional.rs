//! An exact quasi-static Coulomb friction solver for checking a frictional
//! TFEM: node-to-node Lagrange multipliers on the conforming straight
//! horizontal interface of the frictionless oracle, a primal-dual active set
//! (the semismooth Newton method of Hüeber, Stadler and Wohlmuth, exact in
//! one step per set in 2D) on the open/stick/slip sets, over a load history.
//! Like the frictionless oracle it shares nothing with the TFEM contact path
//! but the body stiffness (plain P1, no tempering).
//!
//! **The discrete problem of step k.** For each node pair i (lower node a,
//! upper node b, interface along x, normal y) with initial gap g₀ᵢ:
//! gap gᵢ = v_b − v_a + g₀ᵢ, tangential jump sᵢ = u_b − u_a and its
//! increment over the step Δsᵢ = sᵢ − sᵢ⁽ᵏ⁻¹⁾ (the jump of the last
//! converged step is the history). The multipliers are the contact forces
//! on the upper node (the lower one gets the opposite): λₙ upwards, λₜ along
//! +x. Equilibrium K u = f + Cᵀλ with the model's prescribed displacements,
//! and per pair
//!
//! * open: λₙ = 0, λₜ = 0 (gᵢ ≥ 0);
//! * stick: gᵢ = 0, Δsᵢ = 0 (λₙ ≥ 0, |λₜ| ≤ μλₙ);
//! * slip: gᵢ = 0, λₜ = −μ λₙ sign(Δsᵢ) (λₙ ≥ 0).
//!
//! The sets are updated from ñ = λₙ − cₙ g (λₙ for a pair in contact, −cₙ g
//! for an open one) and z = −λₜ + cₜ Δs: open if ñ ≤ 0, else stick if
//! |z| < μ ñ, else slip with sign(z) (cₙ: the mean diagonal of the
//! condensed stiffness; cₜ = cₙ/100, so that a slip that reverses under its
//! assumed direction becomes stick rather than the opposite slip; if the
//! sets ever cycle, cₜ is divided by 100 and the iteration goes on). For a
//! pair in contact the test on ñ is λₙ > 10⁻¹² max|λ|, for an open one
//! g < 0: the frictionless oracle's rules, so that μ = 0 reproduces it.
//! Each set gives a linear system; the iteration stops when the sets (with
//! the slip signs) repeat.
//!
//! **Solution.** The free DOFs of the pair nodes (I) are kept and the rest
//! (R) condensed once: S = K_II − K_IR K_RR⁻¹ K_RI (sparse Cholesky of K_RR,
//! |I| solves), so each iteration is a dense LU of [S −Cᵀ; rows of the sets]
//! of size |I| + 2·pairs, and each step two solves with K_RR. When S is
//! positive definite (no body floats) the iterations work on the
//! multipliers alone: u_I = S⁻¹(g + Cᵀλ), a dense system of size 2·pairs
//! on W = C S⁻¹ Cᵀ, computed once ([`FrictionalOracle::is_dual`]). The bodies
//! must be held by the prescribed displacements or by the pair nodes (K_RR
//! positive definite); a body held only by contact is allowed (S singular,
//! the saddle system is not).
//!
//! **Prescribed pair DOFs.** A prescribed DOF of a pair node enters its row
//! as a known value, and the contact force on it goes to the support's
//! reaction. If both tangential DOFs of a pair are prescribed (a symmetry
//! line), its tangential multiplier is not an unknown: it is reported 0 and
//! the pair, when in contact, as stick. Both normal DOFs prescribed is
//! refused.

use std::collections::HashSet;
use std::time::Instant;

use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::Llt;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, Mat, MatMut, Side};

use super::interface_pairs;
use crate::error::{Error, Result, Status};
use crate::fem::element::{Jmin, TriGeometry, elasticity_stiffness};
use crate::model::{Component, Model};

/// One load case: external forces and prescribed displacements as global
/// vectors (2 values per node: x, y). Only the DOFs the model prescribes may
/// have prescribed values; the others must be 0.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadCase {
    /// Nodal forces.
    pub forces: Vec<f64>,
    /// Prescribed displacements (read at the model's prescribed DOFs).
    pub prescribed: Vec<f64>,
}

impl LoadCase {
    /// The model's current loads (its consistent load vector) and
    /// prescribed values.
    pub fn of(model: &Model) -> Result<LoadCase> {
        let forces = model.load_vector()?;
        let mut prescribed = vec![0.0; forces.len()];
        for (g, v) in model.constraints() {
            prescribed[g] = v;
        }
        Ok(LoadCase { forces, prescribed })
    }

    /// No load and zero prescribed values, for a model of `nodes` nodes.
    pub fn zero(nodes: usize) -> LoadCase {
        LoadCase {
            forces: vec![0.0; 2 * nodes],
            prescribed: vec![0.0; 2 * nodes],
        }
    }

    /// Σⱼ factors\[j\] · cases\[j\].
    pub fn combination(cases: &[LoadCase], factors: &[f64]) -> Result<LoadCase> {
        if cases.is_empty() || cases.len() != factors.len() {
            return Err(Error::argument(format!(
                "load combination: {} factors for {} cases (need as many, at least one)",
                factors.len(),
                cases.len()
            )));
        }
        let n = cases[0].forces.len();
        if cases
            .iter()
            .any(|c| c.forces.len() != n || c.prescribed.len() != n)
        {
            return Err(Error::argument(
                "load combination: the cases have different lengths",
            ));
        }
        if let Some(f) = factors.iter().find(|f| !f.is_finite()) {
            return Err(Error::argument(format!(
                "load combination: factor {f:?} is not finite"
            )));
        }
        let mut out = LoadCase::zero(n / 2);
        for (c, &f) in cases.iter().zip(factors) {
            for (o, v) in out.forces.iter_mut().zip(&c.forces) {
                *o += f * v;
            }
            for (o, v) in out.prescribed.iter_mut().zip(&c.prescribed) {
                *o += f * v;
            }
        }
        Ok(out)
    }

    /// Makes these the model's loads (as nodal forces) and prescribed values
    /// (on the DOFs it already prescribes), so that a solver that reads the
    /// model (the frictionless oracle, TFEM) sees this step.
    pub fn apply(&self, model: &mut Model) -> Result<()> {
        let fixed: Vec<usize> = model.constraints().map(|(g, _)| g).collect();
        let n = self.forces.len();
        if self.prescribed.len() != n || model.mesh().map(|m| 2 * m.nodes().len()) != Some(n) {
            return Err(Error::argument(
                "load case: its length does not match the model's mesh",
            ));
        }
        model.clear_constraints();
        for g in fixed {
            let c = if g % 2 == 0 {
                Component::X
            } else {
                Component::Y
            };
            model.fix(g / 2, c, self.prescribed[g])?;
        }
        model.clear_loads();
        for v in 0..n / 2 {
            let f = [self.forces[2 * v], self.forces[2 * v + 1]];
            if f != [0.0, 0.0] {
                model.add_nodal_force(v, f)?;
            }
        }
        Ok(())
    }
}

/// A quasi-static load history: step k applies
/// Σⱼ `factors[k][j]` · `cases[j]` (loads and prescribed values are totals,
/// not increments). Friction makes the result depend on the path: each step
/// is one increment of the incremental problem.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadHistory {
    /// The load cases.
    pub cases: Vec<LoadCase>,
    /// One row of factors per step, one factor per case.
    pub factors: Vec<Vec<f64>>,
}

impl LoadHistory {
    /// Step k applies `factors[k]` × (the model's loads and prescribed values).
    pub fn proportional(model: &Model, factors: &[f64]) -> Result<LoadHistory> {
        Ok(LoadHistory {
            cases: vec![LoadCase::of(model)?],
            factors: factors.iter().map(|&f| vec![f]).collect(),
        })
    }

    /// Number of steps.
    pub fn len(&self) -> usize {
        self.factors.len()
    }

    /// True without steps.
    pub fn is_empty(&self) -> bool {
        self.factors.is_empty()
    }

    /// The loads of step k.
    pub fn step(&self, k: usize) -> Result<LoadCase> {
        let f = self
            .factors
            .get(k)
            .ok_or_else(|| Error::argument(format!("load history: no step {k}")))?;
        LoadCase::combination(&self.cases, f)
    }
}

/// State of a node pair at the end of a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PairState {
    /// Not in contact: no force.
    Open,
    /// In contact, no slip over the step.
    Stick,
    /// In contact, slipping: |λₜ| = μ λₙ against the slip.
    Slip,
}

/// One node pair at the end of a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairResult {
    /// Node of the lower body.
    pub lower: usize,
    /// Node of the upper body.
    pub upper: usize,
    /// x of the pair.
    pub x: f64,
    /// Tributary interface length: half the lengths of the lower side's
    /// edges at the lower node.
    pub length: f64,
    /// Open, stick or slip.
    pub state: PairState,
    /// Normal force λₙ on the upper node (≥ 0, compressive).
    pub normal_force: f64,
    /// Tangential force λₜ on the upper node, along +x.
    pub tangential_force: f64,
    /// λₙ / length: the contact pressure.
    pub normal: f64,
    /// λₜ / length: the shear traction on the upper body (along +x).
    pub tangential: f64,
    /// Gap v_b − v_a + g₀.
    pub gap: f64,
    /// Accumulated tangential jump u_b − u_a (the history).
    pub jump: f64,
    /// Jump increment over the step (the slip increment when slipping).
    pub slip_increment: f64,
}

impl PairResult {
    /// Energy dissipated by friction at the pair over the step,
    /// −λₜ Δs (= μ λₙ |Δs| when slipping, 0 otherwise up to round-off).
    pub fn dissipation(&self) -> f64 {
        -self.tangential_force * self.slip_increment
    }
}

/// The oracle's state at the end of one load step.
#[derive(Debug, Clone)]
pub struct FrictionalStep {
    /// Displacements, 2 per node (u, v).
    pub u: Vec<f64>,
    /// K u − f at the prescribed DOFs (0 elsewhere), 2 per node.
    pub reactions: Vec<f64>,
    /// The node pairs, in the order of [`FrictionalOracle::pairs`].
    pub pairs: Vec<PairResult>,
    /// Active-set iterations (linear solves) of the step.
    pub iterations: usize,
    /// Wall time of the step.
    pub seconds: f64,
}

impl FrictionalStep {
    /// Total normal and tangential contact force on the upper body
    /// (Σλₙ, Σλₜ).
    pub fn contact_resultant(&self) -> [f64; 2] {
        self.pairs.iter().fold([0.0, 0.0], |s, p| {
            [s[0] + p.normal_force, s[1] + p.tangential_force]
        })
    }

    /// Number of pairs in each state (open, stick, slip).
    pub fn counts(&self) -> [usize; 3] {
        let mut c = [0; 3];
        for p in &self.pairs {
            c[p.state as usize] += 1;
        }
        c
    }
}

/// The solution over a load history.
#[derive(Debug, Clone)]
pub struct FrictionalSolution {
    /// One state per step.
    pub steps: Vec<FrictionalStep>,
    /// Wall time of the assembly and condensation.
    pub setup_seconds: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Dof {
    Fixed,
    Interface(usize),
    Rest(usize),
}

/// A pair DOF in the condensed system: an interface unknown or a prescribed
/// DOF (whose value comes from the step).
#[derive(Debug, Clone, Copy)]
enum PairDof {
    Unknown(usize),
    Prescribed(usize),
}

/// The multiplier form of the condensed problem, when S is positive
/// definite (every body held by its prescribed displacements).
struct Dual {
    /// Dense Cholesky factor of S.
    s_llt: faer::linalg::solvers::Llt<f64>,
    /// Z = S⁻¹Cᵀ (|I| × 2·pairs).
    z: Mat<f64>,
    /// scale · C Z.
    w: Mat<f64>,
    /// max |w|.
    w_scale: f64,
}

/// The assembled and condensed problem: build once, then solve histories or
/// single steps (cheaply: the condensation is the expensive part).
pub struct FrictionalOracle {
    n: usize,
    pairs: Vec<(usize, usize)>,
    x: Vec<f64>,
    length: Vec<f64>,
    gap0: Vec<f64>,
    /// [u_a, v_a, u_b, v_b] per pair.
    pair_dofs: Vec<[PairDof; 4]>,
    /// Both tangential DOFs prescribed.
    tangent_prescribed: Vec<bool>,
    k: SparseColMat<usize, f64>,
    dof: Vec<Dof>,
    interface: Vec<usize>,
    rest: Vec<usize>,
    k_rr: Option<Llt<usize, f64>>,
    schur: Mat<f64>,
    dual: Option<Dual>,
    /// Complementarity parameter (force per length).
    c: f64,
    /// Scale of the constraint rows and multiplier columns.
    scale: f64,
    setup_seconds: f64,
}

fn singular(what: &str) -> Error {
    Error::new(
        Status::Singular,
        format!("the frictional oracle: {what} is singular"),
    )
}

impl FrictionalOracle {
    /// Assembles the plain P1 stiffness of the model's bodies, matches the
    /// node pairs of the interface between the edges tagged `tag_lower` and
    /// `tag_upper` (horizontal, conforming: the lower side's nodes each have
    /// an upper partner at the same x) and condenses the stiffness onto the
    /// free DOFs of the pair nodes. The model's prescribed DOFs are the
    /// prescribed DOFs of every step (their values come from the steps).
    pub fn new(model: &Model, tag_lower: i32, tag_upper: i32) -> Result<FrictionalOracle> {
        let t0 = Instant::now();
        let mesh = model
            .mesh()
            .ok_or_else(|| Error::state("the model has no mesh"))?;
        let n = 2 * mesh.nodes().len();
        let pairs = interface_pairs(model, tag_lower, tag_upper)?;
        let mut fixed = vec![false; n];
        for (g, _) in model.constraints() {
            fixed[g] = true;
        }
        let gap0 = pairs
            .iter()
            .map(|&(a, b)| mesh.nodes()[b][1] - mesh.nodes()[a][1])
            .collect();
        let x = pairs.iter().map(|&(a, _)| mesh.nodes()[a][0]).collect();
        let mut tributary = vec![0.0; n / 2];
        for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag_lower) {
            let (p, q) = (mesh.nodes()[e.nodes[0]], mesh.nodes()[e.nodes[1]]);
            let half = 0.5 * (p[0] - q[0]).hypot(p[1] - q[1]);
            tributary[e.nodes[0]] += half;
            tributary[e.nodes[1]] += half;
        }
        let length = pairs.iter().map(|&(a, _)| tributary[a]).collect();

        let mut triplets = Vec::with_capacity(36 * mesh.triangles().len());
        for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
            let geo = TriGeometry::new(&mesh.corners(tri));
            let material = model
                .material(*body)
                .ok_or_else(|| Error::state(format!("body {body} has no material")))?;
            let ke = elasticity_stiffness(&geo, &material.d_matrix(), Jmin::Off)?;
            for a in 0..6 {
                for b in 0..6 {
                    triplets.push(Triplet::new(
                        2 * tri[a / 2] + a % 2,
                        2 * tri[b / 2] + b % 2,
                        ke[a][b],
                    ));
                }
            }
        }
        let k = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &triplets)
            .map_err(|_| Error::new(Status::OutOfMemory, "oracle stiffness"))?;
        drop(triplets);

        let mut on_pair = vec![false; n];
        for &(a, b) in &pairs {
            for v in [a, b] {
                on_pair[2 * v] = true;
                on_pair[2 * v + 1] = true;
            }
        }
        let (mut interface, mut rest) = (Vec::new(), Vec::new());
        let dof: Vec<Dof> = (0..n)
            .map(|g| {
                if fixed[g] {
                    Dof::Fixed
                } else if on_pair[g] {
                    interface.push(g);
                    Dof::Interface(interface.len() - 1)
                } else {
                    rest.push(g);
                    Dof::Rest(rest.len() - 1)
                }
            })
            .collect();
        let pair_dof = |g: usize| match dof[g] {
            Dof::Interface(i) => PairDof::Unknown(i),
            _ => PairDof::Prescribed(g),
        };
        let pair_dofs: Vec<[PairDof; 4]> = pairs
            .iter()
            .map(|&(a, b)| {
                [
                    pair_dof(2 * a),
                    pair_dof(2 * a + 1),
                    pair_dof(2 * b),
                    pair_dof(2 * b + 1),
                ]
            })
            .collect();
        for (i, d) in pair_dofs.iter().enumerate() {
            if matches!(
                (d[1], d[3]),
                (PairDof::Prescribed(_), PairDof::Prescribed(_))
            ) {
                return Err(Error::new(
                    Status::InvalidContact,
                    format!(
                        "the frictional oracle: both normal displacements of the pair ({}, {}) are prescribed",
                        mesh.node_name(pairs[i].0),
                        mesh.node_name(pairs[i].1)
                    ),
                ));
            }
        }
        let tangent_prescribed = pair_dofs
            .iter()
            .map(|d| {
                matches!(
                    (d[0], d[2]),
                    (PairDof::Prescribed(_), PairDof::Prescribed(_))
                )
            })
            .collect();

        // K_RR and its Cholesky factor.
        let (col_ptr, row_idx, val) = (k.symbolic().col_ptr(), k.symbolic().row_idx(), k.val());
        let k_rr = if rest.is_empty() {
            None
        } else {
            let mut t = Vec::new();
            for (jr, &gj) in rest.iter().enumerate() {
                for p in col_ptr[gj]..col_ptr[gj + 1] {
                    if let Dof::Rest(ir) = dof[row_idx[p]] {
                        if ir >= jr {
                            t.push(Triplet::new(ir, jr, val[p]));
                        }
                    }
                }
            }
            let m = SparseColMat::<usize, f64>::try_new_from_triplets(rest.len(), rest.len(), &t)
                .map_err(|_| Error::new(Status::OutOfMemory, "oracle K_RR"))?;
            Some(
                m.sp_cholesky(Side::Lower)
                    .map_err(|_| singular("the stiffness away from the interface"))?,
            )
        };

        // S = K_II − K_IR K_RR⁻¹ K_RI, by blocks of columns.
        let ni = interface.len();
        let mut schur = Mat::<f64>::zeros(ni, ni);
        for (j, &gj) in interface.iter().enumerate() {
            for p in col_ptr[gj]..col_ptr[gj + 1] {
                if let Dof::Interface(i) = dof[row_idx[p]] {
                    schur[(i, j)] += val[p];
                }
            }
        }
        if let Some(llt) = &k_rr {
            const BLOCK: usize = 64;
            let mut x = Mat::<f64>::zeros(rest.len(), BLOCK);
            for j0 in (0..ni).step_by(BLOCK) {
                let j1 = (j0 + BLOCK).min(ni);
                x.fill(0.0);
                for j in j0..j1 {
                    let gj = interface[j];
                    for p in col_ptr[gj]..col_ptr[gj + 1] {
                        if let Dof::Rest(r) = dof[row_idx[p]] {
                            x[(r, j - j0)] = val[p];
                        }
                    }
                }
                llt.solve_in_place_with_conj(Conj::No, x.as_mut().subcols_mut(0, j1 - j0));
                for (i, &gi) in interface.iter().enumerate() {
                    for p in col_ptr[gi]..col_ptr[gi + 1] {
                        if let Dof::Rest(r) = dof[row_idx[p]] {
                            let kv = val[p];
                            for j in j0..j1 {
                                schur[(i, j)] -= kv * x[(r, j - j0)];
                            }
                        }
                    }
                }
            }
        }
        let c = if ni > 0 {
            (0..ni).map(|i| schur[(i, i)]).sum::<f64>() / ni as f64
        } else {
            1.0
        };
        let mut scale = 0.0f64;
        for j in 0..ni {
            for i in 0..ni {
                scale = scale.max(schur[(i, j)].abs());
            }
        }
        let scale = if scale > 0.0 { scale } else { 1.0 };
        let dual = Self::dual(&schur, &pair_dofs, scale);
        Ok(FrictionalOracle {
            dual,
            n,
            pairs,
            x,
            length,
            gap0,
            pair_dofs,
            tangent_prescribed,
            k,
            dof,
            interface,
            rest,
            k_rr,
            schur,
            c,
            scale,
            setup_seconds: t0.elapsed().as_secs_f64(),
        })
    }

    /// Z and W when S is positive definite (its Cholesky pivots above
    /// 10⁻¹² of its largest diagonal: no body floats).
    fn dual(schur: &Mat<f64>, pair_dofs: &[[PairDof; 4]], scale: f64) -> Option<Dual> {
        let ni = schur.nrows();
        let m = pair_dofs.len();
        if ni == 0 || m == 0 {
            return None;
        }
        let s_llt = schur.llt(Side::Lower).ok()?;
        let dmax = (0..ni).map(|i| schur[(i, i)]).fold(0.0, f64::max);
        let l = s_llt.L();
        if (0..ni).any(|i| l[(i, i)] * l[(i, i)] < 1e-12 * dmax) {
            return None;
        }
        // Cᵀ: column 2p the normal row of pair p (v_b − v_a), 2p + 1 the
        // tangential one (u_b − u_a), on the unknown DOFs.
        let rows = |r: usize| -> [(PairDof, f64); 2] {
            let d = pair_dofs[r / 2];
            if r % 2 == 0 {
                [(d[1], -1.0), (d[3], 1.0)]
            } else {
                [(d[0], -1.0), (d[2], 1.0)]
            }
        };
        let mut z = Mat::<f64>::zeros(ni, 2 * m);
        for j in 0..2 * m {
            for (d, c) in rows(j) {
                if let PairDof::Unknown(i) = d {
                    z[(i, j)] += c;
                }
            }
        }
        s_llt.solve_in_place_with_conj(Conj::No, z.as_mut());
        let mut w = Mat::<f64>::zeros(2 * m, 2 * m);
        let mut w_scale = 0.0f64;
        for j in 0..2 * m {
            for r in 0..2 * m {
                let mut v = 0.0;
                for (d, c) in rows(r) {
                    if let PairDof::Unknown(i) = d {
                        v += c * z[(i, j)];
                    }
                }
                w[(r, j)] = scale * v;
                w_scale = w_scale.max(w[(r, j)].abs());
            }
        }
        Some(Dual {
            s_llt,
            z,
            w,
            w_scale: if w_scale > 0.0 { w_scale } else { 1.0 },
        })
    }

    /// Whether the multiplier (dual) form is used: S positive definite.
    pub fn is_dual(&self) -> bool {
        self.dual.is_some()
    }

    /// Drops the multiplier form: every iteration solves the saddle-point
    /// system (to check one form against the other).
    pub fn saddle_only(mut self) -> FrictionalOracle {
        self.dual = None;
        self
    }

    /// The node pairs (lower node, upper node), sorted by lower node.
    pub fn pairs(&self) -> &[(usize, usize)] {
        &self.pairs
    }

    /// Tributary interface length of each pair.
    pub fn tributary_lengths(&self) -> &[f64] {
        &self.length
    }

    /// Wall time of the assembly and condensation.
    pub fn setup_seconds(&self) -> f64 {
        self.setup_seconds
    }

    /// Number of condensed (interface) unknowns.
    pub fn interface_unknowns(&self) -> usize {
        self.interface.len()
    }

    /// y = K x (K symmetric, stored by columns).
    fn k_times(&self, x: &[f64]) -> Vec<f64> {
        let (cp, ri, val) = (
            self.k.symbolic().col_ptr(),
            self.k.symbolic().row_idx(),
            self.k.val(),
        );
        let mut y = vec![0.0; self.n];
        for j in 0..self.n {
            if x[j] != 0.0 {
                for p in cp[j]..cp[j + 1] {
                    y[ri[p]] += val[p] * x[j];
                }
            }
        }
        y
    }

    fn solve_rest(&self, rhs: &mut [f64]) {
        if let Some(llt) = &self.k_rr {
            let len = rhs.len();
            llt.solve_in_place_with_conj(
                Conj::No,
                MatMut::from_column_major_slice_mut(rhs, len, 1),
            );
        }
    }

    fn check_loads(&self, loads: &LoadCase) -> Result<()> {
        if loads.forces.len() != self.n || loads.prescribed.len() != self.n {
            return Err(Error::argument(format!(
                "frictional oracle: a load case has {} / {} values for {} DOFs",
                loads.forces.len(),
                loads.prescribed.len(),
                self.n
            )));
        }
        if let Some(g) = (0..self.n).find(|&g| {
            !loads.forces[g].is_finite()
                || !loads.prescribed[g].is_finite()
                || (loads.prescribed[g] != 0.0 && self.dof[g] != Dof::Fixed)
        }) {
            return Err(Error::argument(format!(
                "frictional oracle: DOF {g} of a load case is not finite, or has a prescribed \
                 value but the model does not prescribe it"
            )));
        }
        Ok(())
    }

    /// Known part (prescribed values) of up − lo for a pair component.
    fn known(lo: PairDof, up: PairDof, loads: &LoadCase) -> f64 {
        let v = |d: PairDof| match d {
            PairDof::Prescribed(g) => loads.prescribed[g],
            PairDof::Unknown(_) => 0.0,
        };
        v(up) - v(lo)
    }

    /// The linear system of one set of pair states, [S −Cᵀ; rows of the
    /// sets], by dense LU: returns (u_I, λ/scale per pair (n, t)).
    fn solve_saddle(
        &self,
        set: &[(PairState, i8)],
        mu: f64,
        g_i: &[f64],
        prev_jump: &[f64],
        loads: &LoadCase,
    ) -> Result<Vec<f64>> {
        let ni = self.interface.len();
        let size = ni + 2 * self.pairs.len();
        let s = self.scale;
        let mut a = Mat::<f64>::zeros(size, size);
        let mut rhs = vec![0.0; size];
        for j in 0..ni {
            for i in 0..ni {
                a[(i, j)] = self.schur[(i, j)];
            }
        }
        rhs[..ni].copy_from_slice(g_i);
        for (p, d) in self.pair_dofs.iter().enumerate() {
            let (rn, rt) = (ni + 2 * p, ni + 2 * p + 1);
            // Forces: +λ on the upper node, −λ on the lower one.
            for (k, sign) in [(0, -1.0), (2, 1.0)] {
                if let PairDof::Unknown(i) = d[k] {
                    a[(i, rt)] -= sign * s;
                }
                if let PairDof::Unknown(i) = d[k + 1] {
                    a[(i, rn)] -= sign * s;
                }
            }
            let known = |lo, up| Self::known(lo, up, loads);
            let (state, sign) = set[p];
            if state == PairState::Open {
                a[(rn, rn)] = s;
                a[(rt, rt)] = s;
                continue;
            }
            for (k, c) in [(1, -1.0), (3, 1.0)] {
                if let PairDof::Unknown(i) = d[k] {
                    a[(rn, i)] = c * s;
                }
            }
            rhs[rn] = s * (-self.gap0[p] - known(d[1], d[3]));
            if self.tangent_prescribed[p] {
                a[(rt, rt)] = s;
            } else if state == PairState::Stick {
                for (k, c) in [(0, -1.0), (2, 1.0)] {
                    if let PairDof::Unknown(i) = d[k] {
                        a[(rt, i)] = c * s;
                    }
                }
                rhs[rt] = s * (prev_jump[p] - known(d[0], d[2]));
            } else {
                // λₜ = −μ σ λₙ.
                a[(rt, rt)] = s;
                a[(rt, rn)] = s * mu * sign as f64;
            }
        }
        let lu = a.partial_piv_lu();
        let mut x = rhs.clone();
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut x, size, 1),
        );
        // One step of iterative refinement.
        let mut r = rhs.clone();
        for j in 0..size {
            if x[j] != 0.0 {
                for i in 0..size {
                    r[i] -= a[(i, j)] * x[j];
                }
            }
        }
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut r, size, 1),
        );
        x.iter_mut().zip(&r).for_each(|(a, b)| *a += b);
        if x.iter().any(|v| !v.is_finite()) {
            return Err(singular("the saddle-point system of the contact sets"));
        }
        Ok(x)
    }

    /// The same system on the multipliers alone when S is positive
    /// definite: u_I = u₀ + Z λ (Z = S⁻¹Cᵀ), the kinematic rows
    /// C Z λ = r − C u₀, the others as in the saddle system.
    fn solve_dual(
        &self,
        dual: &Dual,
        set: &[(PairState, i8)],
        mu: f64,
        u0: &[f64],
        prev_jump: &[f64],
        loads: &LoadCase,
    ) -> Result<Vec<f64>> {
        let ni = self.interface.len();
        let m = self.pairs.len();
        let (s, ws) = (self.scale, dual.w_scale);
        // C u₀ per row.
        let cu0: Vec<f64> = (0..2 * m)
            .map(|r| {
                let (p, t) = (r / 2, r % 2);
                let d = self.pair_dofs[p];
                let (lo, up) = if t == 0 { (d[1], d[3]) } else { (d[0], d[2]) };
                let v = |d: PairDof| match d {
                    PairDof::Unknown(i) => u0[i],
                    PairDof::Prescribed(_) => 0.0,
                };
                v(up) - v(lo)
            })
            .collect();
        let mut a = Mat::<f64>::zeros(2 * m, 2 * m);
        let mut rhs = vec![0.0; 2 * m];
        for (p, d) in self.pair_dofs.iter().enumerate() {
            let (rn, rt) = (2 * p, 2 * p + 1);
            let (state, sign) = set[p];
            if state == PairState::Open {
                a[(rn, rn)] = ws;
                a[(rt, rt)] = ws;
                continue;
            }
            for j in 0..2 * m {
                a[(rn, j)] = dual.w[(rn, j)];
            }
            rhs[rn] = -self.gap0[p] - Self::known(d[1], d[3], loads) - cu0[rn];
            if self.tangent_prescribed[p] {
                a[(rt, rt)] = ws;
            } else if state == PairState::Stick {
                for j in 0..2 * m {
                    a[(rt, j)] = dual.w[(rt, j)];
                }
                rhs[rt] = prev_jump[p] - Self::known(d[0], d[2], loads) - cu0[rt];
            } else {
                a[(rt, rt)] = ws;
                a[(rt, rn)] = ws * mu * sign as f64;
            }
        }
        // Unknowns y = λ/s; the kinematic rows are s W y = r − C u₀.
        let lu = a.partial_piv_lu();
        let mut y = rhs.clone();
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut y, 2 * m, 1),
        );
        let mut r = rhs.clone();
        for j in 0..2 * m {
            if y[j] != 0.0 {
                for i in 0..2 * m {
                    r[i] -= a[(i, j)] * y[j];
                }
            }
        }
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut r, 2 * m, 1),
        );
        y.iter_mut().zip(&r).for_each(|(a, b)| *a += b);
        if y.iter().any(|v| !v.is_finite()) {
            return Err(singular("the multiplier system of the contact sets"));
        }
        // u_I = u₀ + Z λ, λ = s y.
        let mut x = Vec::with_capacity(ni + 2 * m);
        x.extend_from_slice(u0);
        for (j, &yj) in y.iter().enumerate() {
            if yj != 0.0 {
                let f = s * yj;
                for i in 0..ni {
                    x[i] += dual.z[(i, j)] * f;
                }
            }
        }
        x.extend_from_slice(&y);
        Ok(x)
    }

    /// Solves a load history from the undeformed, unloaded state.
    pub fn solve(&self, mu: f64, history: &LoadHistory) -> Result<FrictionalSolution> {
        let mut steps: Vec<FrictionalStep> = Vec::with_capacity(history.len());
        for k in 0..history.len() {
            let next = self.step(mu, steps.last(), &history.step(k)?)?;
            steps.push(next);
        }
        Ok(FrictionalSolution {
            steps,
            setup_seconds: self.setup_seconds,
        })
    }

    /// One increment: from the state `from` (the previous step; `None`: the
    /// undeformed state, jumps 0, all pairs tried in stick) to the total
    /// loads `loads`. The stick condition and the slip direction refer to
    /// the jumps of `from`.
    pub fn step(
        &self,
        mu: f64,
        from: Option<&FrictionalStep>,
        loads: &LoadCase,
    ) -> Result<FrictionalStep> {
        let t0 = Instant::now();
        if mu.is_nan() || mu < 0.0 {
            return Err(Error::argument(format!(
                "frictional oracle: μ = {mu:?} must be >= 0 (or +∞)"
            )));
        }
        self.check_loads(loads)?;
        let m = self.pairs.len();
        if let Some(f) = from {
            if f.pairs.len() != m {
                return Err(Error::argument(
                    "frictional oracle: the previous step is from another oracle",
                ));
            }
        }
        let prev_jump: Vec<f64> = match from {
            Some(f) => f.pairs.iter().map(|p| p.jump).collect(),
            None => vec![0.0; m],
        };
        // Set of each pair: 0 open, 1 stick, 2 slip, with a slip sign.
        let mut set: Vec<(PairState, i8)> = match from {
            Some(f) => f
                .pairs
                .iter()
                .map(|p| {
                    let sign = if p.state == PairState::Slip {
                        if p.tangential_force > 0.0 { -1 } else { 1 }
                    } else {
                        0
                    };
                    (p.state, if mu == 0.0 && sign != 0 { 1 } else { sign })
                })
                .collect(),
            None => vec![(PairState::Stick, 0); m],
        };

        // Condensed load: b = f − K u_F; y = K_RR⁻¹ b_R; g = b_I − K_IR y.
        let uf: Vec<f64> = (0..self.n)
            .map(|g| {
                if self.dof[g] == Dof::Fixed {
                    loads.prescribed[g]
                } else {
                    0.0
                }
            })
            .collect();
        let kuf = self.k_times(&uf);
        let b: Vec<f64> = (0..self.n).map(|g| loads.forces[g] - kuf[g]).collect();
        let mut y: Vec<f64> = self.rest.iter().map(|&g| b[g]).collect();
        self.solve_rest(&mut y);
        let mut y_full = vec![0.0; self.n];
        for (r, &g) in self.rest.iter().enumerate() {
            y_full[g] = y[r];
        }
        let ky = self.k_times(&y_full);
        let g_i: Vec<f64> = self.interface.iter().map(|&g| b[g] - ky[g]).collect();

        let ni = self.interface.len();
        let s = self.scale;
        // With S positive definite: u₀ = S⁻¹ g.
        let u0 = match &self.dual {
            Some(dual) => {
                let mut u0 = g_i.clone();
                dual.s_llt.solve_in_place_with_conj(
                    Conj::No,
                    MatMut::from_column_major_slice_mut(&mut u0, ni, 1),
                );
                u0
            }
            None => Vec::new(),
        };
        let value = |d: PairDof, x: &[f64]| match d {
            PairDof::Unknown(i) => x[i],
            PairDof::Prescribed(g) => loads.prescribed[g],
        };
        let mut seen: HashSet<Vec<(PairState, i8)>> = HashSet::new();
        let mut iterations = 0;
        let mut c_t = 1e-2 * self.c;
        let (mut cycles, mut single) = (0, false);
        let solution = loop {
            iterations += 1;
            if iterations > 200 {
                return Err(Error::new(
                    Status::NotConverged,
                    "the frictional oracle's active set did not settle in 200 iterations",
                ));
            }
            seen.insert(set.clone());
            let x = match &self.dual {
                Some(dual) => self.solve_dual(dual, &set, mu, &u0, &prev_jump, loads),
                None => self.solve_saddle(&set, mu, &g_i, &prev_jump, loads),
            }?;
            let lambda_n: Vec<f64> = (0..m).map(|p| s * x[ni + 2 * p]).collect();
            let lambda_t: Vec<f64> = (0..m).map(|p| s * x[ni + 2 * p + 1]).collect();
            let gap: Vec<f64> = (0..m)
                .map(|p| {
                    let d = self.pair_dofs[p];
                    value(d[3], &x) - value(d[1], &x) + self.gap0[p]
                })
                .collect();
            let jump: Vec<f64> = (0..m)
                .map(|p| {
                    let d = self.pair_dofs[p];
                    value(d[2], &x) - value(d[0], &x)
                })
                .collect();
            let force_scale = lambda_n
                .iter()
                .chain(&lambda_t)
                .fold(0.0f64, |a, l| a.max(l.abs()))
                .max(1e-300);
            let next: Vec<(PairState, i8)> = (0..m)
                .map(|p| {
                    let (state, _) = set[p];
                    let closed = if state == PairState::Open {
                        gap[p] < 0.0
                    } else {
                        lambda_n[p] > 1e-12 * force_scale
                    };
                    if !closed {
                        return (PairState::Open, 0);
                    }
                    if self.tangent_prescribed[p] || mu == f64::INFINITY {
                        return (PairState::Stick, 0);
                    }
                    // A pair closing: stick iff |Δs| < μ|g| (cₜ = cₙ).
                    let (n_tilde, z) = if state == PairState::Open {
                        (-self.c * gap[p], self.c * (jump[p] - prev_jump[p]))
                    } else {
                        (lambda_n[p], -lambda_t[p] + c_t * (jump[p] - prev_jump[p]))
                    };
                    if z.abs() < mu * n_tilde {
                        (PairState::Stick, 0)
                    } else if mu == 0.0 || z >= 0.0 {
                        (PairState::Slip, 1)
                    } else {
                        (PairState::Slip, -1)
                    }
                })
                .collect();
            if next == set {
                break (x, lambda_n, lambda_t, gap, jump);
            }
            if seen.contains(&next) {
                // A cycle: first retry from here with a smaller cₜ (a
                // reversed slip becomes stick), then change one pair at a
                // time (the first that differs).
                cycles += 1;
                if cycles > 6 {
                    return Err(Error::new(
                        Status::NotConverged,
                        format!(
                            "the frictional oracle's active set cycles (iteration {iterations})"
                        ),
                    ));
                }
                seen.clear();
                if cycles <= 3 {
                    c_t *= 1e-2;
                } else {
                    single = true;
                }
            }
            if single {
                let p = (0..m)
                    .find(|&p| next[p] != set[p])
                    .expect("the sets differ");
                set[p] = next[p];
            } else {
                set = next;
            }
        };
        let (x, lambda_n, lambda_t, gap, jump) = solution;

        // Displacements: u_I from x, u_R = y − K_RR⁻¹ K_RI u_I.
        let mut u = uf;
        for (i, &g) in self.interface.iter().enumerate() {
            u[g] = x[i];
        }
        let mut ui_full = vec![0.0; self.n];
        for (i, &g) in self.interface.iter().enumerate() {
            ui_full[g] = x[i];
        }
        let kui = self.k_times(&ui_full);
        let mut z: Vec<f64> = self.rest.iter().map(|&g| kui[g]).collect();
        self.solve_rest(&mut z);
        for (r, &g) in self.rest.iter().enumerate() {
            u[g] = y[r] - z[r];
        }
        let ku = self.k_times(&u);
        let reactions = (0..self.n)
            .map(|g| {
                if self.dof[g] == Dof::Fixed {
                    ku[g] - loads.forces[g]
                } else {
                    0.0
                }
            })
            .collect();
        let pairs = (0..m)
            .map(|p| {
                let (state, _) = set[p];
                let (ln, lt) = match state {
                    PairState::Open => (0.0, 0.0),
                    // Exactly on the Coulomb limit (and 0 for μ = 0).
                    PairState::Slip if !self.tangent_prescribed[p] => {
                        let sign = set[p].1 as f64;
                        (
                            lambda_n[p],
                            if mu == 0.0 {
                                0.0
                            } else {
                                -mu * sign * lambda_n[p]
                            },
                        )
                    }
                    _ => (lambda_n[p], lambda_t[p]),
                };
                PairResult {
                    lower: self.pairs[p].0,
                    upper: self.pairs[p].1,
                    x: self.x[p],
                    length: self.length[p],
                    state,
                    normal_force: ln,
                    tangential_force: lt,
                    normal: ln / self.length[p],
                    tangential: lt / self.length[p],
                    gap: gap[p],
                    jump: jump[p],
                    slip_increment: jump[p] - prev_jump[p],
                }
            })
            .collect();
        Ok(FrictionalStep {
            u,
            reactions,
            pairs,
            iterations,
            seconds: t0.elapsed().as_secs_f64(),
        })
    }
}

/// Exact quasi-static Coulomb friction with coefficient `mu` (≥ 0, may be
/// `f64::INFINITY`: no slip) on the node pairs of the conforming horizontal
/// interface between the edges tagged `tag_lower` and `tag_upper`, over a
/// load history (see [`FrictionalOracle`]). μ = 0 is the frictionless
/// oracle's problem.
pub fn frictional_oracle(
    model: &Model,
    tag_lower: i32,
    tag_upper: i32,
    mu: f64,
    history: &LoadHistory,
) -> Result<FrictionalSolution> {
    FrictionalOracle::new(model, tag_lower, tag_upper)?.solve(mu, history)
}
