//! What the tetrahedral studies ([`super::tet_study`],
//! [`super::tet_contact`]) share to assemble and solve: the pattern's
//! input, element scatter with prescribed values, boundary faces'
//! geometry, and the factorisation with its failure named.

use super::tetmesh::{LAYER, LOWER, TetMesh};
use crate::error::{Error, Result, Status};
use crate::fem::assembly::{DofMap, Pattern};
use crate::fem::tet::{TetGeometry, sub};
use crate::linalg::ordering::{Ordering, nested_dissection};
use crate::linalg::{AnalyseParams, Cholesky, FactorError};

pub use crate::fem::solid_assembly::{lift, unknowns_of};

/// Every tetrahedron's four faces, as the triangles
/// [`Pattern::build`] couples the nodes of.
pub fn face_triangles(mesh: &TetMesh) -> Vec<[usize; 3]> {
    crate::fem::solid_assembly::tet_cliques(&mesh.tets)
}

/// A boundary triangle's outward unit normal (away from its
/// tetrahedron's fourth node `inside`; zero for a degenerate triangle),
/// area and centroid.
pub fn outward(face: [[f64; 3]; 3], inside: [f64; 3]) -> ([f64; 3], f64, [f64; 3]) {
    let (u, v) = (sub(face[1], face[0]), sub(face[2], face[0]));
    let mut n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    if (0..3).map(|i| n[i] * (face[0][i] - inside[i])).sum::<f64>() < 0.0 {
        n = n.map(|x| -x);
    }
    let twice_area = n.iter().map(|c| c * c).sum::<f64>().sqrt();
    let centroid = std::array::from_fn(|i| (face[0][i] + face[1][i] + face[2][i]) / 3.0);
    let unit = if twice_area > 0.0 {
        n.map(|c| c / twice_area)
    } else {
        [0.0; 3]
    };
    (unit, 0.5 * twice_area, centroid)
}

/// ∇u of the linear field with nodal values `u` (three per node, global)
/// on tetrahedron `t` (J ≠ 0): row i is ∇u_i = Σ_k u_k,i a_k / J.
pub fn gradient(geo: &TetGeometry, t: &[usize; 4], u: &[f64]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).map(|k| u[3 * t[k] + i] * geo.a[k][j]).sum::<f64>() / geo.j)
    })
}

/// The strain of a displacement gradient, Voigt with engineering shears
/// (ε_xx, ε_yy, ε_zz, γ_yz, γ_xz, γ_xy), as [`crate::fem::tet`] orders it.
pub fn voigt_strain(g: &[[f64; 3]; 3]) -> [f64; 6] {
    [
        g[0][0],
        g[1][1],
        g[2][2],
        g[1][2] + g[2][1],
        g[0][2] + g[2][0],
        g[0][1] + g[1][0],
    ]
}

/// The largest error of a block tetrahedron's stress D_part ε(u) against
/// the uniform `target` (Voigt), over `scale`; the layer skipped, a block
/// tetrahedron with J ≤ 0 refused (a patch test needs valid blocks).
pub fn block_stress_error(
    mesh: &TetMesh,
    u: &[f64],
    d: &[[[f64; 6]; 6]],
    target: &[f64; 6],
    scale: f64,
) -> Result<f64> {
    let mut worst = 0.0f64;
    for (e, t) in mesh.tets.iter().enumerate() {
        let part = mesh.parts.get(e).copied().unwrap_or(LOWER);
        if part == LAYER {
            continue;
        }
        let geo = TetGeometry::new(&t.map(|v| mesh.nodes[v]));
        if geo.j <= 0.0 {
            return Err(Error::argument(format!(
                "block tetrahedron {e} has J = {:e}: the patch test needs valid blocks",
                geo.j
            )));
        }
        let strain = voigt_strain(&gradient(&geo, t, u));
        for (row, &want) in target.iter().enumerate() {
            let s: f64 = (0..6).map(|c| d[part][row][c] * strain[c]).sum();
            worst = worst.max((s - want).abs() / scale);
        }
    }
    Ok(worst)
}

/// The area of a tetrahedron's largest face
/// ([`TetGeometry::largest_face`]).
pub fn largest_face(geo: &TetGeometry) -> f64 {
    geo.largest_face()
}

/// The analysis of `pattern` with `ordering`: geometric nested dissection
/// on the nodes' positions in 3D ([`Ordering::Auto`]: from
/// [`Ordering::AUTO_THRESHOLD`] unknowns, as the 2D product chooses it),
/// or AMD.
pub fn analyse(
    pattern: &Pattern,
    dofs: &DofMap,
    mesh: &TetMesh,
    ordering: Ordering,
) -> Result<Cholesky> {
    if !ordering.use_nested_dissection(pattern.n()) {
        return Cholesky::analyse(pattern, &AnalyseParams::default());
    }
    let points: Vec<[f64; 3]> = (dofs.free_to_global().iter())
        .map(|&g| mesh.nodes[g / 3])
        .collect();
    let perm = nested_dissection(pattern.col_ptr(), pattern.row_idx(), &points);
    Cholesky::analyse_ordered(pattern, perm)
}

/// Factorises, a singular matrix an error saying what `system` is.
pub fn factorize(
    chol: &mut Cholesky,
    pattern: &Pattern,
    values: &[f64],
    system: &str,
) -> Result<()> {
    match chol.factorize(pattern, values) {
        Ok(()) => Ok(()),
        Err(FactorError::Other(e)) => Err(e),
        Err(FactorError::Singular { usable: true, .. }) if chol.accept_ill_conditioned() => Ok(()),
        Err(e) => Err(Error::new(
            Status::Singular,
            format!("{system} does not factorise: {e:?}"),
        )),
    }
}
