//! An exact frictionless contact solver for checking TFEM: node-to-node
//! Lagrange multipliers on a conforming straight horizontal interface,
//! primal-dual active set, sparse LU of the saddle-point system. It shares
//! nothing with the TFEM contact path but the body stiffness, so on the same
//! mesh it gives the exact discrete frictionless solution TFEM approximates
//! (TFEM's penalty-like contact elements converge to it as h → 0).
//!
//! [`frictional`] adds the quasi-static Coulomb friction oracle on the same
//! node pairs ([`frictional_oracle`], [`FrictionalOracle`]).

pub mod frictional;

pub use frictional::{
    FrictionalOracle, FrictionalSolution, FrictionalStep, LoadCase, LoadHistory, PairResult,
    PairState, frictional_oracle,
};

use std::collections::{BTreeSet, HashMap};

use faer::linalg::solvers::SolveCore;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, MatMut};

use crate::error::{Error, Result, Status};
use crate::fem::element::{Jmin, TriGeometry, elasticity_stiffness};
use crate::model::Model;

/// The oracle's solution.
#[derive(Debug, Clone)]
pub struct OracleSolution {
    /// Displacements, 2 per node (u, v).
    pub u: Vec<f64>,
    /// The node pairs (lower node, upper node) in contact.
    pub active: BTreeSet<(usize, usize)>,
    /// Primal-dual active-set iterations.
    pub iterations: usize,
}

/// Node pairs across a horizontal conforming interface between the edges
/// tagged `tag_lower` and `tag_upper`, matched by x (bitwise).
pub fn interface_pairs(
    model: &Model,
    tag_lower: i32,
    tag_upper: i32,
) -> Result<Vec<(usize, usize)>> {
    let mesh = model
        .mesh()
        .ok_or_else(|| Error::state("the model has no mesh"))?;
    let side = |tag: i32| -> BTreeSet<usize> {
        mesh.boundary_edges()
            .iter()
            .filter(|e| e.tag == tag)
            .flat_map(|e| e.nodes)
            .collect()
    };
    let upper: HashMap<u64, usize> = side(tag_upper)
        .into_iter()
        .map(|v| (mesh.nodes()[v][0].to_bits(), v))
        .collect();
    side(tag_lower)
        .into_iter()
        .map(|a| {
            upper
                .get(&mesh.nodes()[a][0].to_bits())
                .map(|&b| (a, b))
                .ok_or_else(|| {
                    Error::new(
                        Status::InvalidContact,
                        format!(
                            "the oracle needs matching interface nodes: {} has no partner",
                            mesh.node_name(a)
                        ),
                    )
                })
        })
        .collect()
}

/// Exact frictionless contact on the node pairs of a horizontal conforming
/// interface (lower body below): minimises the energy subject to
/// v_b − v_a + g₀ ≥ 0 by a primal-dual active set on [K −Cᵀ; C 0], starting
/// from all pairs in contact. Plain P1 body stiffness (no tempering).
pub fn frictionless_oracle(
    model: &Model,
    tag_lower: i32,
    tag_upper: i32,
) -> Result<OracleSolution> {
    let mesh = model
        .mesh()
        .ok_or_else(|| Error::state("the model has no mesh"))?;
    let n = 2 * mesh.nodes().len();
    let fixed: HashMap<usize, f64> = model.constraints().collect();
    let f = model.load_vector()?;
    let pairs = interface_pairs(model, tag_lower, tag_upper)?;
    let gap0: Vec<f64> = pairs
        .iter()
        .map(|&(a, b)| mesh.nodes()[b][1] - mesh.nodes()[a][1])
        .collect();
    let mut k_triplets = Vec::new();
    for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
        let geo = TriGeometry::new(&mesh.corners(tri));
        let material = model
            .material(*body)
            .ok_or_else(|| Error::state(format!("body {body} has no material")))?;
        let ke = elasticity_stiffness(&geo, &material.d_matrix(), Jmin::Off)?;
        for a in 0..6 {
            let ga = 2 * tri[a / 2] + a % 2;
            if fixed.contains_key(&ga) {
                continue;
            }
            for b in 0..6 {
                let gb = 2 * tri[b / 2] + b % 2;
                k_triplets.push(Triplet::new(ga, gb, ke[a][b]));
            }
        }
    }
    // Identity rows and constraint rows are scaled like the stiffness so
    // that the LU's pivoting sees one scale.
    let s = k_triplets.iter().map(|t| t.val.abs()).fold(0.0, f64::max);
    for &g in fixed.keys() {
        k_triplets.push(Triplet::new(g, g, s));
    }
    // DOFs of nodes outside every element (none in a valid model) would make
    // the system singular; give them identity rows too.
    let mut used = vec![false; n];
    for t in &k_triplets {
        used[t.row] = true;
    }
    for (g, _) in used.iter().enumerate().filter(|(_, u)| !**u) {
        k_triplets.push(Triplet::new(g, g, s));
    }
    let failed = || {
        Error::new(
            Status::Singular,
            "the oracle's saddle-point system is singular",
        )
    };
    let mut active: Vec<bool> = vec![true; pairs.len()];
    for iteration in 1..=100 {
        let idx: Vec<usize> = (0..pairs.len()).filter(|&i| active[i]).collect();
        let m = idx.len();
        let mut t = k_triplets.clone();
        for (r, &i) in idx.iter().enumerate() {
            let (a, b) = pairs[i];
            for (g, sign) in [(2 * b + 1, s), (2 * a + 1, -s)] {
                t.push(Triplet::new(n + r, g, sign));
                t.push(Triplet::new(g, n + r, -sign));
            }
        }
        let mut rhs: Vec<f64> = (0..n)
            .map(|g| fixed.get(&g).map_or(f[g], |v| s * v))
            .collect();
        rhs.extend(idx.iter().map(|&i| -s * gap0[i]));
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n + m, n + m, &t)
            .map_err(|_| Error::new(Status::OutOfMemory, "oracle matrix"))?;
        let lu = a.sp_lu().map_err(|_| failed())?;
        let mut x = rhs.clone();
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut x, n + m, 1),
        );
        // Two steps of iterative refinement.
        for _ in 0..2 {
            let mut r = rhs.clone();
            for tr in &t {
                r[tr.row] -= tr.val * x[tr.col];
            }
            lu.solve_in_place_with_conj(
                Conj::No,
                MatMut::from_column_major_slice_mut(&mut r, n + m, 1),
            );
            x.iter_mut().zip(&r).for_each(|(a, b)| *a += b);
        }
        if x.iter().any(|v| !v.is_finite()) {
            return Err(failed());
        }
        let (u, lambda) = x.split_at(n);
        let scale = lambda
            .iter()
            .fold(0.0f64, |s, l| s.max(l.abs()))
            .max(1e-300);
        let mut next = vec![false; pairs.len()];
        let mut row = 0;
        for (i, &(a, b)) in pairs.iter().enumerate() {
            next[i] = if active[i] {
                row += 1;
                lambda[row - 1] > 1e-12 * scale
            } else {
                u[2 * b + 1] - u[2 * a + 1] + gap0[i] < 0.0
            };
        }
        if next == active {
            return Ok(OracleSolution {
                u: u.to_vec(),
                active: (0..pairs.len())
                    .filter(|&i| active[i])
                    .map(|i| pairs[i])
                    .collect(),
                iterations: iteration,
            });
        }
        active = next;
    }
    Err(Error::new(
        Status::NotConverged,
        "the oracle's active set did not settle in 100 iterations",
    ))
}
