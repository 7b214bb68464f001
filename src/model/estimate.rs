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

/// Estimates the error of the field `u` of `solution` on `problem`; an
/// error if η² or the energy exceed the doubles' range.
pub(crate) fn estimate(problem: &Problem, solution: &Solution, u: &[f64]) -> Result<Estimate> {
    let s = scaled(problem, solution, u)?;
    let s2 = s.scale * s.scale;
    let squared: Vec<f64> = s.squared.iter().map(|v| v * s2).collect();
    let mesh = problem.mesh_ref()?;
    ensure_finite(squared.iter().copied(), 1, "error estimate", |t| {
        mesh.triangle_name(t)
    })?;
    let (global, energy) = (s.global * s.scale, s.energy * s.scale);
    ensure_finite([global, energy], 1, "error estimate", |_| {
        "the whole mesh (its sum)".to_string()
    })?;
    Ok(Estimate {
        squared,
        global,
        energy,
    })
}

/// The estimate of stresses divided by their largest component, `scale`:
/// the same numbers over scale (η, the energy) and scale² (η_e²), which
/// do not overflow where the stresses' squares would; what the adaptive
/// solve marks and compares.
pub(crate) struct Scaled {
    /// η_e² / scale².
    pub squared: Vec<f64>,
    /// η / scale.
    pub global: f64,
    /// The energy norm / scale.
    pub energy: f64,
    /// The largest stress component (1 when all are zero).
    pub scale: f64,
}

impl Scaled {
    /// η over the field's energy norm.
    pub fn relative(&self) -> f64 {
        if self.energy > 0.0 {
            self.global / self.energy
        } else {
            self.global
        }
    }
}

/// [`estimate`] on the stresses scaled to their largest component.
pub(crate) fn scaled(problem: &Problem, solution: &Solution, u: &[f64]) -> Result<Scaled> {
    let elements = problem.elements()?;
    let mesh = elements.mesh();
    let section = problem.section();
    let in_plane = solution.stresses(problem, u)?;
    let normal = solution.out_of_plane_stresses(problem, u)?;
    let largest = (in_plane.iter().flatten().chain(&normal)).fold(0.0f64, |m, v| m.max(v.abs()));
    let scale = if largest > 0.0 { largest } else { 1.0 };
    let stresses: Vec<Stress4> = (in_plane.iter().zip(&normal))
        .map(|(s, n)| [s[0] / scale, s[1] / scale, s[2] / scale, *n / scale])
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
    let recovered = Recovery::of(mesh, &stresses, &measure);
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
            let body = mesh.body_of()[e];
            let (sa, sb) = (recovered.at(tri[a], body), recovered.at(tri[b], body));
            let diff: Stress4 = std::array::from_fn(|c| 0.5 * (sa[c] + sb[c]) - stresses[e][c]);
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
    let energy = energy.sqrt();
    ensure_finite([global, energy], 1, "error estimate", |_| {
        "the whole mesh (its sum)".to_string()
    })?;
    Ok(Scaled {
        squared,
        global,
        energy,
        scale,
    })
}

/// σᵀ D⁻¹ σ of the material for the stress `s` = [σ_xx, σ_yy, σ_xy, σ_n]:
/// the complementary energy density (twice it), in closed form, computed
/// on the stress scaled to its largest component so that only a value
/// beyond the doubles' range overflows (and is then an error, not 0).
fn complementary(material: &Material, s: &Stress4) -> f64 {
    let scale = s.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 {
        return 0.0;
    }
    let unit = s.map(|v| v / scale);
    compliance_form(material, &unit) * scale * scale
}

/// [`complementary`] of a stress of moderate size. In the plane the
/// in-plane D is inverted (σ_n is not independent); for a ring the 3D
/// isotropic compliance over the four components.
fn compliance_form(material: &Material, s: &Stress4) -> f64 {
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
            // 1/(a² − l²) as (1/(a − l))·(1/(a + l)), each factor formed
            // alone: no product of two moduli, which overflows for E ~ 1e300.
            let inv = 1.0 / (a - l);
            let (c, m) = (inv * (a / (a + l)), inv * (l / (a + l)));
            c * (s[0] * s[0] + s[1] * s[1]) - 2.0 * m * s[0] * s[1] + s[2] * s[2] / d[2][2]
        }
    }
}

/// The recovered nodal stresses σ*, one per node and body: a node shared
/// by bodies of different materials (tied, conforming) gets one per body,
/// so that the stress jump between them is not smeared.
struct Recovery {
    /// σ* of each node for its first body (the body of its first
    /// triangle).
    first: Vec<Stress4>,
    /// The first body of each node.
    body: Vec<i32>,
    /// σ* of (node, body) for the node's other bodies.
    others: std::collections::HashMap<(usize, i32), Stress4>,
}

impl Recovery {
    /// Averages the triangles' `stresses` at their nodes, weighted by
    /// `measure` (a node whose triangles all have none takes them
    /// equally).
    fn of(mesh: &crate::fem::mesh::Mesh, stresses: &[Stress4], measure: &[f64]) -> Recovery {
        let n = mesh.nodes().len();
        let mut body = vec![i32::MIN; n];
        // Per (node, body): Σ w σ, Σ w, Σ σ, count.
        type Acc = (Stress4, f64, Stress4, f64);
        let mut first: Vec<Acc> = vec![([0.0; 4], 0.0, [0.0; 4], 0.0); n];
        let mut others: std::collections::HashMap<(usize, i32), Acc> = Default::default();
        for (e, (tri, &b)) in mesh.triangles().iter().zip(mesh.body_of()).enumerate() {
            for &v in tri {
                if body[v] == i32::MIN {
                    body[v] = b;
                }
                let acc = match body[v] == b {
                    true => &mut first[v],
                    false => others
                        .entry((v, b))
                        .or_insert(([0.0; 4], 0.0, [0.0; 4], 0.0)),
                };
                for c in 0..4 {
                    acc.0[c] += measure[e] * stresses[e][c];
                    acc.2[c] += stresses[e][c];
                }
                acc.1 += measure[e];
                acc.3 += 1.0;
            }
        }
        let mean = |(sum, w, flat, count): &Acc| match *w > 0.0 {
            true => sum.map(|s| s / w),
            false => flat.map(|s| s / count.max(1.0)),
        };
        Recovery {
            first: first.iter().map(mean).collect(),
            body,
            others: others.iter().map(|(k, a)| (*k, mean(a))).collect(),
        }
    }

    /// σ* of node `v` for body `b`.
    fn at(&self, v: usize, b: i32) -> Stress4 {
        match self.body[v] == b {
            true => self.first[v],
            false => self.others.get(&(v, b)).copied().unwrap_or([0.0; 4]),
        }
    }
}
