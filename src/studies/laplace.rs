//! The scalar Laplacian with tempered P1 elements: −∇·(κ∇u) = f with
//! Dirichlet conditions. It reproduces the TFEM paper's locking study and
//! shares assembly and solver with the elasticity model.

use super::quadrature::{QUAD_POINTS, QUAD_WEIGHTS};
use crate::error::{Error, Result, Status};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::element::{Tempering, TriGeometry, laplacian_stiffness};
use crate::fem::mesh::Mesh;
use crate::linalg::ordering::Ordering;
use crate::linalg::{AnalyseParams, Cholesky, FactorError, Points};

/// Solves −κΔu = f on `mesh` with u prescribed at the nodes listed in
/// `dirichlet` (node, value). Returns the nodal values (prescribed ones
/// included, unused nodes zero).
pub fn solve_poisson(
    mesh: &Mesh,
    kappa: f64,
    tempering: Tempering,
    source: impl Fn([f64; 2]) -> f64,
    dirichlet: &[(usize, f64)],
) -> Result<Vec<f64>> {
    tempering.validate()?;
    if !(kappa.is_finite() && kappa > 0.0) {
        return Err(Error::argument(format!(
            "conductivity kappa = {kappa} must be finite and > 0"
        )));
    }
    let n = mesh.nodes().len();
    let mut value = vec![f64::NAN; n];
    for &(v, g) in dirichlet {
        if v >= n || !g.is_finite() {
            return Err(Error::argument(format!(
                "Dirichlet condition on node {v} = {g} is invalid"
            )));
        }
        value[v] = g;
    }
    let used = mesh.node_body();
    let dofs = DofMap::new(n, 1, |v| used[v].is_some() && value[v].is_nan());
    let pattern = Pattern::build(&dofs, n, mesh.triangles());
    let coords: Vec<[f64; 2]> = dofs
        .free_to_global()
        .iter()
        .map(|&v| mesh.nodes()[v])
        .collect();
    let params = AnalyseParams {
        ordering: Ordering::Auto,
        coords: Some(Points::Plane(&coords)),
        last: &[],
        zeros: &[],
        parallel_subtrees: true,
    };
    let mut chol = Cholesky::analyse(&pattern, &params)?;
    let size = mesh.size();
    let mut vals = vec![0.0; pattern.nnz()];
    let mut rhs = vec![0.0; dofs.n_free()];
    for (e, tri) in mesh.triangles().iter().enumerate() {
        let x = mesh.corners(tri);
        let geo = TriGeometry::new(&x);
        let jm = tempering.jmin(&geo, size);
        let k = laplacian_stiffness(&geo, kappa, jm).map_err(|err| {
            Error::new(
                err.status(),
                format!("{}: {}", mesh.triangle_name(e), err.message()),
            )
        })?;
        let ke: [f64; 9] = std::array::from_fn(|i| k[i / 3][i % 3]);
        pattern.add_element(&mut vals, &tri.map(|v| dofs.free(v)), &ke);
        // Load with the true area (zero for flat and inverted elements).
        let area = 0.5 * geo.j.max(0.0);
        for a in 0..3 {
            let fa = dofs.free(tri[a]);
            if fa == NOT_FREE {
                continue;
            }
            let mut r = 0.0;
            for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
                let p = [
                    q[0] * x[0][0] + q[1] * x[1][0] + q[2] * x[2][0],
                    q[0] * x[0][1] + q[1] * x[1][1] + q[2] * x[2][1],
                ];
                r += w * area * source(p) * q[a];
            }
            for b in 0..3 {
                if dofs.free(tri[b]) == NOT_FREE && used[tri[b]].is_some() {
                    r -= ke[a * 3 + b] * value[tri[b]];
                }
            }
            rhs[fa] += r;
        }
    }
    match chol.factorize(&pattern, &vals) {
        Ok(()) => {}
        Err(FactorError::Other(e)) => return Err(e),
        Err(_) => {
            return Err(Error::new(
                Status::Singular,
                "the Laplacian is singular: give a Dirichlet condition on every connected part",
            ));
        }
    }
    chol.solve(&mut rhs)?;
    let mut u: Vec<f64> = value
        .iter()
        .map(|v| if v.is_nan() { 0.0 } else { *v })
        .collect();
    for (f, &g) in dofs.free_to_global().iter().enumerate() {
        u[g] = rhs[f];
    }
    Ok(u)
}
