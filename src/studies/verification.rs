//! Tools to verify a discretisation against known solutions: a quadrature
//! rule, consistent nodal loads of a body-force field, error norms, and the
//! bodies' own nodal forces of a solution.

use std::time::Instant;

use super::laplace::solve_poisson;
use super::meshgen::MeshBuilder;
pub use super::quadrature::{QUAD_POINTS, QUAD_WEIGHTS};
use crate::error::Result;
use crate::fem::element::{Tempering, TriGeometry};
use crate::fem::material::Material;
use crate::fem::mesh::Mesh;
use crate::model::{Component, Model};

/// The point of barycentric coordinates `q` in the triangle `x`.
pub fn point(x: &[[f64; 2]; 3], q: &[f64; 3]) -> [f64; 2] {
    [
        q[0] * x[0][0] + q[1] * x[1][0] + q[2] * x[2][0],
        q[0] * x[0][1] + q[1] * x[1][1] + q[2] * x[2][1],
    ]
}

/// The forces the bodies' own (tempered) elements exert at each node for
/// the solved displacements, K u, less the supports' reactions: at a node
/// of a contact interface where no other load acts, the contact force,
/// read from the bodies instead of from the elements of B. The two are
/// equal in exact arithmetic; B's forces are a penalty stiffness times
/// openings a millionth of the displacements, so a field not solved to
/// working accuracy shows in them first.
pub fn body_forces(model: &Model) -> Result<Vec<[f64; 2]>> {
    let u = model.displacements()?;
    let mut f = vec![[0.0f64; 2]; u.len()];
    let body = model.problem().elements()?;
    body.for_each(|el| {
        let ke = body.stiffness(el)?;
        for a in 0..6 {
            f[el.nodes[a / 2]][a % 2] += (0..6)
                .map(|b| ke[6 * a + b] * u[el.nodes[b / 2]][b % 2])
                .sum::<f64>();
        }
        Ok(())
    })?;
    for (fb, r) in f.iter_mut().zip(model.reactions()?) {
        fb[0] -= r[0];
        fb[1] -= r[1];
    }
    Ok(f)
}

/// The largest |K u − f_contact| over the nodes of the contact elements,
/// over the largest contact force component: the bodies' own forces
/// ([`body_forces`]) against the contact forces read from B, which a field
/// solved to working accuracy makes equal.
pub fn contact_imbalance(model: &Model) -> Result<f64> {
    let f = model.contact_forces()?;
    let fbody = body_forces(model)?;
    let fmax = f
        .iter()
        .fold(0.0f64, |m, v| m.max(v[0].abs().max(v[1].abs())));
    // The interface nodes: those of B, or under the mortar weighting those
    // the weighted gaps load.
    let nodes: Vec<usize> = match model.contact_elements() {
        Ok(elements) => elements.iter().flat_map(|el| el.nodes).collect(),
        Err(_) => (0..f.len()).filter(|&v| f[v] != [0.0; 2]).collect(),
    };
    let off = nodes
        .into_iter()
        .map(|v| {
            (fbody[v][0] - f[v][0])
                .abs()
                .max((fbody[v][1] - f[v][1]).abs())
        })
        .fold(0.0f64, f64::max);
    Ok(off / fmax)
}

/// Consistent nodal forces ∫ b φ_i of a body-force field over the mesh
/// (flat and inverted triangles carry no area).
pub fn nodal_loads(mesh: &Mesh, body_force: impl Fn([f64; 2]) -> [f64; 2]) -> Vec<[f64; 2]> {
    let mut f = vec![[0.0; 2]; mesh.nodes().len()];
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.max(0.0);
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let b = body_force(point(&x, q));
            for a in 0..3 {
                f[tri[a]][0] += w * area * b[0] * q[a];
                f[tri[a]][1] += w * area * b[1] * q[a];
            }
        }
    }
    f
}

/// L2 norm of (exact − discrete) for a P1 field with `ncomp` components per
/// node stored node-major in `uh`.
pub fn l2_error(
    mesh: &Mesh,
    uh: &[f64],
    ncomp: usize,
    exact: impl Fn([f64; 2]) -> Vec<f64>,
) -> f64 {
    let mut sum = 0.0;
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.abs();
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let ex = exact(point(&x, q));
            for c in 0..ncomp {
                let v: f64 = (0..3).map(|a| q[a] * uh[ncomp * tri[a] + c]).sum();
                sum += w * area * (ex[c] - v).powi(2);
            }
        }
    }
    sum.sqrt()
}

/// H1 seminorm of (exact − discrete): sqrt(∫ |∇u − ∇u_h|²), with the exact
/// gradient given as [∂u_c/∂x, ∂u_c/∂y] per component. Triangles with
/// J <= 0 have no area and are skipped.
pub fn h1_error(
    mesh: &Mesh,
    uh: &[f64],
    ncomp: usize,
    exact_grad: impl Fn([f64; 2]) -> Vec<[f64; 2]>,
) -> f64 {
    let mut sum = 0.0;
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let geo = TriGeometry::new(&x);
        if geo.j <= 0.0 {
            continue;
        }
        let area = 0.5 * geo.j;
        let grads: Vec<[f64; 2]> = (0..ncomp)
            .map(|c| {
                let mut g = [0.0; 2];
                for a in 0..3 {
                    let ua = uh[ncomp * tri[a] + c];
                    g[0] += geo.g[a][0] * ua / geo.j;
                    g[1] += geo.g[a][1] * ua / geo.j;
                }
                g
            })
            .collect();
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let ex = exact_grad(point(&x, q));
            for c in 0..ncomp {
                sum += w
                    * area
                    * ((ex[c][0] - grads[c][0]).powi(2) + (ex[c][1] - grads[c][1]).powi(2));
            }
        }
    }
    sum.sqrt()
}

/// Energy norm of (exact − discrete) for elasticity:
/// sqrt(∫ (ε − ε_h)ᵀ D (ε − ε_h)), ε Voigt with engineering shear, the
/// exact displacement gradient given as [[∂u/∂x, ∂u/∂y], [∂v/∂x, ∂v/∂y]].
/// Triangles with J <= 0 have no area and are skipped.
pub fn energy_error(
    mesh: &Mesh,
    uh: &[f64],
    d: &[[f64; 3]; 3],
    exact_grad: impl Fn([f64; 2]) -> [[f64; 2]; 2],
) -> f64 {
    energy_error_where(mesh, uh, d, exact_grad, |_| true)
}

/// [`energy_error`] over the triangles of body `body` alone (bodies of
/// other materials or other exact fields are measured on their own).
pub fn energy_error_of_body(
    mesh: &Mesh,
    uh: &[f64],
    body: i32,
    d: &[[f64; 3]; 3],
    exact_grad: impl Fn([f64; 2]) -> [[f64; 2]; 2],
) -> f64 {
    energy_error_where(mesh, uh, d, exact_grad, |t| mesh.body_of()[t] == body)
}

fn energy_error_where(
    mesh: &Mesh,
    uh: &[f64],
    d: &[[f64; 3]; 3],
    exact_grad: impl Fn([f64; 2]) -> [[f64; 2]; 2],
    keep: impl Fn(usize) -> bool,
) -> f64 {
    let mut sum = 0.0;
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if !keep(t) {
            continue;
        }
        let x = mesh.corners(tri);
        let geo = TriGeometry::new(&x);
        if geo.j <= 0.0 {
            continue;
        }
        let mut gh = [[0.0; 2]; 2];
        for a in 0..3 {
            for c in 0..2 {
                gh[c][0] += geo.g[a][0] * uh[2 * tri[a] + c] / geo.j;
                gh[c][1] += geo.g[a][1] * uh[2 * tri[a] + c] / geo.j;
            }
        }
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let g = exact_grad(point(&x, q));
            let e = [
                g[0][0] - gh[0][0],
                g[1][1] - gh[1][1],
                g[0][1] + g[1][0] - gh[0][1] - gh[1][0],
            ];
            let mut de = 0.0;
            for r in 0..3 {
                for c in 0..3 {
                    de += e[r] * d[r][c] * e[c];
                }
            }
            sum += w * 0.5 * geo.j * de;
        }
    }
    sum.sqrt()
}

/// The manufactured elasticity solution on the unit square used by the
/// convergence studies: u = sin πx sin πy, v = sin 2πx sin πy (zero on the
/// boundary), with the body force f = −[(λ+μ)∇(∇·u) + μΔu] of an isotropic
/// material with Lamé constants (λ, μ).
#[derive(Debug, Clone, Copy)]
pub struct ManufacturedElasticity {
    /// Lamé's first parameter (plane strain: Eν/((1+ν)(1−2ν))).
    pub lame: f64,
    /// Shear modulus.
    pub mu: f64,
}

impl ManufacturedElasticity {
    /// For a material in plane strain or plane stress.
    pub fn new(material: &crate::Material) -> ManufacturedElasticity {
        let d = material.d_matrix();
        ManufacturedElasticity {
            lame: d[0][1],
            mu: d[2][2],
        }
    }

    /// The exact displacement.
    pub fn displacement(&self, p: [f64; 2]) -> [f64; 2] {
        let pi = std::f64::consts::PI;
        let (x, y) = (p[0], p[1]);
        [
            (pi * x).sin() * (pi * y).sin(),
            (2.0 * pi * x).sin() * (pi * y).sin(),
        ]
    }

    /// The exact gradient [[u_x, u_y], [v_x, v_y]].
    pub fn gradient(&self, p: [f64; 2]) -> [[f64; 2]; 2] {
        let pi = std::f64::consts::PI;
        let (x, y) = (p[0], p[1]);
        [
            [
                pi * (pi * x).cos() * (pi * y).sin(),
                pi * (pi * x).sin() * (pi * y).cos(),
            ],
            [
                2.0 * pi * (2.0 * pi * x).cos() * (pi * y).sin(),
                pi * (2.0 * pi * x).sin() * (pi * y).cos(),
            ],
        ]
    }

    /// The body force that makes [`Self::displacement`] the solution.
    pub fn body_force(&self, p: [f64; 2]) -> [f64; 2] {
        let pi = std::f64::consts::PI;
        let pi2 = pi * pi;
        let (x, y) = (p[0], p[1]);
        let a = (pi * x).sin() * (pi * y).sin();
        let b = (2.0 * pi * x).sin() * (pi * y).sin();
        let (a_xx, a_yy, a_xy) = (-pi2 * a, -pi2 * a, pi2 * (pi * x).cos() * (pi * y).cos());
        let (b_xx, b_yy, b_xy) = (
            -4.0 * pi2 * b,
            -pi2 * b,
            2.0 * pi2 * (2.0 * pi * x).cos() * (pi * y).cos(),
        );
        let lm = self.lame + self.mu;
        [
            -(lm * (a_xx + b_xy) + self.mu * (a_xx + a_yy)),
            -(lm * (a_xy + b_yy) + self.mu * (b_xx + b_yy)),
        ]
    }
}

/// One mesh level of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyPoint {
    /// Nominal mesh size.
    pub h: f64,
    /// Unknowns.
    pub unknowns: usize,
    /// L2 error.
    pub l2: f64,
    /// Energy-norm error (elasticity) or H1-seminorm error (Laplacian).
    pub energy: f64,
    /// Wall time of the solve, seconds.
    pub seconds: f64,
}

fn boundary_nodes(builder: &MeshBuilder) -> Vec<usize> {
    let mut nodes: Vec<usize> = builder.boundary_edges().into_iter().flatten().collect();
    nodes.sort_unstable();
    nodes.dedup();
    nodes
}

/// Solves [`ManufacturedElasticity`] on the mesh of `builder` (u prescribed
/// on the whole boundary) and measures its errors.
pub fn run_manufactured_elasticity(
    builder: MeshBuilder,
    h: f64,
    material: Material,
    tempering: Tempering,
) -> Result<StudyPoint> {
    let exact = ManufacturedElasticity::new(&material);
    let fixed = boundary_nodes(&builder);
    let mesh = builder.build()?;
    let loads = nodal_loads(&mesh, |p| exact.body_force(p));
    let mut model = Model::new();
    model.set_mesh(mesh);
    model.set_material(1, material)?;
    model.set_tempering(tempering)?;
    for &v in &fixed {
        let u = exact.displacement(model.mesh().expect("set").nodes()[v]);
        model.fix(v, Component::X, u[0])?;
        model.fix(v, Component::Y, u[1])?;
    }
    for (v, f) in loads.iter().enumerate() {
        if f[0] != 0.0 || f[1] != 0.0 {
            model.add_nodal_force(v, *f)?;
        }
    }
    let t0 = Instant::now();
    let info = model.solve()?;
    let seconds = t0.elapsed().as_secs_f64();
    let uh: Vec<f64> = model.displacements()?.into_iter().flatten().collect();
    let mesh = model.mesh().expect("set");
    let l2 = l2_error(mesh, &uh, 2, |p| exact.displacement(p).to_vec());
    let energy = energy_error(mesh, &uh, &material.d_matrix(), |p| exact.gradient(p));
    Ok(StudyPoint {
        h,
        unknowns: info.unknowns,
        l2,
        energy,
        seconds,
    })
}

/// Solves −Δu = 2π² sin πx sin πy (exact u = sin πx sin πy, zero on the
/// boundary of the unit square) on the mesh of `builder`.
pub fn run_manufactured_laplace(
    builder: MeshBuilder,
    h: f64,
    tempering: Tempering,
) -> Result<StudyPoint> {
    let pi = std::f64::consts::PI;
    let exact = move |p: [f64; 2]| (pi * p[0]).sin() * (pi * p[1]).sin();
    let fixed: Vec<(usize, f64)> = boundary_nodes(&builder)
        .into_iter()
        .map(|v| (v, exact(builder.nodes[v])))
        .collect();
    let mesh = builder.build()?;
    let t0 = Instant::now();
    let uh = solve_poisson(&mesh, 1.0, tempering, |p| 2.0 * pi * pi * exact(p), &fixed)?;
    let seconds = t0.elapsed().as_secs_f64();
    let l2 = l2_error(&mesh, &uh, 1, |p| vec![exact(p)]);
    let energy = h1_error(&mesh, &uh, 1, |p| {
        vec![[
            pi * (pi * p[0]).cos() * (pi * p[1]).sin(),
            pi * (pi * p[0]).sin() * (pi * p[1]).cos(),
        ]]
    });
    Ok(StudyPoint {
        h,
        unknowns: uh.len() - fixed.len(),
        l2,
        energy,
        seconds,
    })
}

/// Least-squares slope of log(e) against log(h): the observed convergence
/// rate.
pub fn fitted_rate(h: &[f64], e: &[f64]) -> f64 {
    let n = h.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = h.iter().zip(e).map(|(a, b)| (a.ln(), b.ln())).unzip();
    let mx = lx.iter().sum::<f64>() / n;
    let my = ly.iter().sum::<f64>() / n;
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadrature_integrates_quartics_exactly() {
        // ∫ over the unit right triangle of x^4 = 1/30 and x^2 y^2 = 1/180.
        let x = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let (mut a, mut b) = (0.0, 0.0);
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let p = point(&x, q);
            a += 0.5 * w * p[0].powi(4);
            b += 0.5 * w * p[0].powi(2) * p[1].powi(2);
        }
        assert!((a - 1.0 / 30.0).abs() < 1e-13, "{a}");
        assert!((b - 1.0 / 180.0).abs() < 1e-13, "{b}");
    }

    #[test]
    fn fitted_rate_of_exact_power_law() {
        let h = [0.1, 0.05, 0.025];
        let e: Vec<f64> = h.iter().map(|h: &f64| 3.0 * h.powi(2)).collect();
        assert!((fitted_rate(&h, &e) - 2.0).abs() < 1e-12);
    }
}
