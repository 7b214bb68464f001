//! The bodies' part of a tetrahedral system (docs/method.md §9): each
//! tempered tetrahedron's 12 × 12 matrix scattered on the pattern, the
//! prescribed displacements' share moved to the load, and the strains a
//! solved field gives back — what the solid model and the 3D studies
//! share.

use super::assembly::{DofMap, NOT_FREE, Pattern};
use super::element::Tempering;
use super::solid_mesh::SolidMesh;
use super::tet::{TetGeometry, stiffness};
use crate::error::{Error, Result};

/// Every tetrahedron's four faces, as the triangles [`Pattern::build`]
/// couples the nodes of (every pair of a tetrahedron's nodes is an edge of
/// one of them).
pub fn tet_cliques<'a>(tets: impl IntoIterator<Item = &'a [usize; 4]>) -> Vec<[usize; 3]> {
    (tets.into_iter())
        .flat_map(|t| {
            [
                [t[0], t[1], t[2]],
                [t[0], t[1], t[3]],
                [t[0], t[2], t[3]],
                [t[1], t[2], t[3]],
            ]
        })
        .collect()
}

/// The unknowns of a tetrahedron's 12 DOFs ([`NOT_FREE`] where prescribed).
pub fn unknowns_of(dofs: &DofMap, t: &[usize; 4]) -> [usize; 12] {
    std::array::from_fn(|i| dofs.free(3 * t[i / 3] + i % 3))
}

/// Moves the prescribed DOFs' share of an element matrix `ke` (12 × 12,
/// row-major) to the right-hand side.
pub fn lift(
    rhs: &mut [f64],
    unknowns: &[usize; 12],
    t: &[usize; 4],
    ke: &[f64],
    prescribed: &[f64],
) {
    for (i, &row) in unknowns.iter().enumerate() {
        if row == NOT_FREE {
            continue;
        }
        for (c, &col) in unknowns.iter().enumerate() {
            if col == NOT_FREE {
                rhs[row] -= ke[12 * i + c] * prescribed[3 * t[c / 3] + c % 3];
            }
        }
    }
}

/// The bodies of a tetrahedral mesh with their elasticity and tempering.
pub struct SolidBodies<'a> {
    /// The mesh.
    pub mesh: &'a SolidMesh,
    /// The elasticity matrix D of each tetrahedron's body, by the body's
    /// position in [`SolidMesh::bodies`].
    pub d: &'a [[[f64; 6]; 6]],
    /// How tetrahedra are tempered (the mesh's size as λ for `Auto`).
    pub tempering: Tempering,
}

impl SolidBodies<'_> {
    /// D of tetrahedron `e`.
    fn d_of(&self, e: usize) -> &[[f64; 6]; 6] {
        let bodies = self.mesh.bodies();
        let at = bodies.binary_search(&self.mesh.body_of()[e]).unwrap_or(0);
        &self.d[at]
    }

    /// Jmin of tetrahedron `e` of geometry `geo`.
    fn jmin(&self, geo: &TetGeometry) -> f64 {
        self.tempering.jmin_tet(geo, self.mesh.size())
    }

    /// Tetrahedron `e`'s tempered matrix, row-major, an error naming it.
    pub fn matrix(&self, e: usize) -> Result<Vec<f64>> {
        let geo = self.mesh.geometry(e);
        let k = stiffness(&geo, self.d_of(e), self.jmin(&geo)).map_err(|err| {
            Error::new(
                err.status(),
                format!(
                    "tetrahedron {}: {}",
                    e + self.mesh.index_base(),
                    err.message()
                ),
            )
        })?;
        Ok(k.iter().flatten().copied().collect())
    }

    /// The bodies' matrix on `pattern` (upper triangle).
    pub fn assemble(&self, dofs: &DofMap, pattern: &Pattern) -> Result<Vec<f64>> {
        let mut values = vec![0.0; pattern.nnz()];
        for (e, t) in self.mesh.tets().iter().enumerate() {
            let ke = self.matrix(e)?;
            pattern.add_element(&mut values, &unknowns_of(dofs, t), &ke);
        }
        Ok(values)
    }

    /// Adds the prescribed displacements' share −K_fp u_p to `rhs` (over
    /// the unknowns), from the tetrahedra with a non-zero prescribed
    /// value only.
    pub fn lift(&self, dofs: &DofMap, prescribed: &[f64], rhs: &mut [f64]) -> Result<()> {
        for (e, t) in self.mesh.tets().iter().enumerate() {
            let unknowns = unknowns_of(dofs, t);
            let moved =
                (0..12).any(|i| unknowns[i] == NOT_FREE && prescribed[3 * t[i / 3] + i % 3] != 0.0);
            if moved {
                lift(rhs, &unknowns, t, &self.matrix(e)?, prescribed);
            }
        }
        Ok(())
    }

    /// The internal forces K_e u_e of every tetrahedron summed at its
    /// nodes (three per node): the bodies' share of the reactions.
    pub fn internal_forces(&self, u: &[f64]) -> Result<Vec<f64>> {
        let mut f = vec![0.0; u.len()];
        for (e, t) in self.mesh.tets().iter().enumerate() {
            let ke = self.matrix(e)?;
            for i in 0..12 {
                let row: f64 = (0..12)
                    .map(|c| ke[12 * i + c] * u[3 * t[c / 3] + c % 3])
                    .sum();
                f[3 * t[i / 3] + i % 3] += row;
            }
        }
        Ok(f)
    }

    /// Each tetrahedron's strain (ε_xx, ε_yy, ε_zz, γ_yz, γ_xz, γ_xy) of
    /// the displacements `u` (three per node): ∇u with the gradients a_k
    /// over max(J, Jmin), the usual strain where J ≥ Jmin and the
    /// tempered one below, consistent with the tempered energy.
    pub fn strains(&self, u: &[f64]) -> Vec<[f64; 6]> {
        (self.mesh.tets().iter().enumerate())
            .map(|(e, t)| {
                let geo = self.mesh.geometry(e);
                let scale = geo.j.max(self.jmin(&geo));
                let g: [[f64; 3]; 3] = std::array::from_fn(|i| {
                    std::array::from_fn(|j| {
                        let s: f64 = (0..4).map(|k| u[3 * t[k] + i] * geo.a[k][j]).sum();
                        if scale > 0.0 { s / scale } else { 0.0 }
                    })
                });
                [
                    g[0][0],
                    g[1][1],
                    g[2][2],
                    g[1][2] + g[2][1],
                    g[0][2] + g[2][0],
                    g[0][1] + g[1][0],
                ]
            })
            .collect()
    }

    /// Each tetrahedron's stress D ε (Voigt, σ_xx, σ_yy, σ_zz, σ_yz, σ_xz,
    /// σ_xy).
    pub fn stresses(&self, u: &[f64]) -> Vec<[f64; 6]> {
        let strains = self.strains(u);
        (strains.iter().enumerate())
            .map(|(e, eps)| {
                let d = self.d_of(e);
                std::array::from_fn(|r| (0..6).map(|c| d[r][c] * eps[c]).sum())
            })
            .collect()
    }
}
