//! An a posteriori error estimate of a solved model: Zienkiewicz–Zhu
//! stress recovery (docs/method.md §8).
//!
//! Each body's nodal stress σ* is the average of the stresses of the
//! triangles around the node, weighted by their measure (area, or area ×
//! 2πr̄ for a ring; flat and inverted triangles, which carry no material,
//! weigh nothing unless a node has nothing else), and interpolated linearly
//! on each triangle. The estimate of triangle e is its energy
//!
//! ```text
//!   η_e² = ∫_e (σ* − σ_h)ᵀ D⁻¹ (σ* − σ_h) dμ
//! ```
//!
//! (dμ = dA in the plane, 2πr dA for a ring; the hoop component included
//! for a ring, σ_zz is not independent in plane strain and not there in
//! plane stress), integrated exactly by the three edge-midpoint rule. Why
//! recovery rather than residuals: the contact enters through the stresses
//! the bodies carry on either side of the interface (each body is
//! recovered on its own nodes, so the interface's traction jump is not
//! smeared across it), the estimate needs no constant of the element
//! shapes — which TFEM's flat elements would break — and it is
//! asymptotically exact where the solution is smooth. Its effectivity is
//! measured, not assumed (tests/adaptive.rs, the report).

use crate::error::{Result, ensure_finite};
use crate::fem::element::TriGeometry;
use crate::fem::material::Material;
use crate::model::problem::Problem;
use crate::model::solution::Solution;

/// The error estimate of a solved field.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// η_e² of every triangle (energy units: force × length).
    pub squared: Vec<f64>,
    /// η = (Σ η_e²)^½, the estimate of the energy norm of the error.
    pub global: f64,
    /// The energy norm of the field, (uᵀ K u)^½ over the bodies, from the
    /// same stresses: ∫ σ_hᵀ D⁻¹ σ_h dμ.
    pub energy: f64,
}

impl Estimate {
    /// η over the field's energy norm: the relative error in energy.
    pub fn relative(&self) -> f64 {
        if self.energy > 0.0 {
            self.global / self.energy
        } else {
            self.global
        }
    }
}

/// A stress with its out-of-plane component: [σ_xx, σ_yy, σ_xy, σ_n].
type Stress4 = [f64; 4];

/// Estimates the error of the field `u` of `solution` on `problem`.
pub(crate) fn estimate(problem: &Problem, solution: &Solution, u: &[f64]) -> Result<Estimate> {
    let elements = problem.elements()?;
    let mesh = elements.mesh();
    let section = problem.section();
    let in_plane = solution.stresses(problem, u)?;
    let normal = solution.out_of_plane_stresses(problem, u)?;
    let stresses: Vec<Stress4> = (in_plane.iter().zip(&normal))
        .map(|(s, n)| [s[0], s[1], s[2], *n])
        .collect();
    let triangles = mesh.triangles();
    let geos: Vec<TriGeometry> = (triangles.iter())
        .map(|t| TriGeometry::new(&mesh.corners(t)))
        .collect();
    // The recovery weights: the measure of the material each triangle
    // holds; a node with none (only flat triangles) takes them equally.
    let measure: Vec<f64> = (triangles.iter().zip(&geos))
        .map(|(t, g)| {
            let x = mesh.corners(t).iter().map(|c| c[0]).sum::<f64>() / 3.0;
            0.5 * g.j.max(0.0) * section.weight(x)
        })
        .collect();
    let n = mesh.nodes().len();
    let (mut sum, mut weight) = (vec![[0.0; 4]; n], vec![0.0; n]);
    let (mut flat_sum, mut flat_count) = (vec![[0.0; 4]; n], vec![0.0f64; n]);
    for (e, tri) in triangles.iter().enumerate() {
        for &v in tri {
            for c in 0..4 {
                sum[v][c] += measure[e] * stresses[e][c];
                flat_sum[v][c] += stresses[e][c];
            }
            weight[v] += measure[e];
            flat_count[v] += 1.0;
        }
    }
    let recovered: Vec<Stress4> = (0..n)
        .map(|v| match weight[v] > 0.0 {
            true => sum[v].map(|s| s / weight[v]),
            false => flat_sum[v].map(|s| s / flat_count[v].max(1.0)),
        })
        .collect();
    let mut squared = Vec::with_capacity(triangles.len());
    let mut energy = 0.0;
    for (e, tri) in triangles.iter().enumerate() {
        let material = elements.material(mesh.body_of()[e]);
        let corners = mesh.corners(tri);
        let area = 0.5 * geos[e].j.max(0.0);
        let (mut eta, mut own) = (0.0, 0.0);
        // Edge midpoints: exact for the quadratic integrand in the plane
        // (and for a ring's cubic one, weighted by the midpoint's radius,
        // to O(h) of it: the recovery is not sharper than that).
        for k in 0..3 {
            let (a, b) = (k, (k + 1) % 3);
            let x = 0.5 * (corners[a][0] + corners[b][0]);
            let w = area / 3.0 * section.weight(x);
            let diff: Stress4 = std::array::from_fn(|c| {
                0.5 * (recovered[tri[a]][c] + recovered[tri[b]][c]) - stresses[e][c]
            });
            eta += w * complementary(material, &diff);
            own += w * complementary(material, &stresses[e]);
        }
        squared.push(eta);
        energy += own;
    }
    ensure_finite(squared.iter().copied(), 1, "error estimate", |t| {
        mesh.triangle_name(t)
    })?;
    let global = squared.iter().sum::<f64>().sqrt();
    Ok(Estimate {
        squared,
        global,
        energy: energy.sqrt(),
    })
}

/// σᵀ D⁻¹ σ of the material for the stress `s` = [σ_xx, σ_yy, σ_xy, σ_n]:
/// the complementary energy density (twice it), in closed form. In the
/// plane the in-plane D is inverted (σ_n is not independent); for a ring
/// the 3D isotropic compliance over the four components.
fn complementary(material: &Material, s: &Stress4) -> f64 {
    let (e, nu) = (material.young(), material.poisson());
    let shear = 2.0 * (1.0 + nu) / e * s[2] * s[2];
    match material.section().is_revolution() {
        true => {
            // ε = ((1+ν)σ − ν tr σ)/E over rr, zz, θθ.
            let normal = [s[0], s[1], s[3]];
            let tr: f64 = normal.iter().sum();
            let sq: f64 = normal.iter().map(|v| v * v).sum();
            ((1.0 + nu) * sq - nu * tr * tr) / e + shear
        }
        false => {
            // The in-plane D = [[a, l], [l, a]] ⊕ [μ] inverted.
            let d = material.d_matrix();
            let (a, l) = (d[0][0], d[0][1]);
            let det = a * a - l * l;
            (a * (s[0] * s[0] + s[1] * s[1]) - 2.0 * l * s[0] * s[1]) / det + s[2] * s[2] / d[2][2]
        }
    }
}
