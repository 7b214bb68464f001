//! Axisymmetric scenes (x = r the radius, y = z the axis; docs/method.md
//! §7) with exact answers: a manufactured field ([`ManufacturedRing`]), a
//! thick cylinder under internal pressure ([`ThickCylinder`], Lamé), a hub
//! shrunk on a shaft ([`ShaftHub`]) and the axisymmetric contact patch
//! test ([`StackedCylinders`]).
//!
//! Every force here is the whole ring's (2π radians): a nodal force or a
//! reaction is a total around the circumference, a pressure a force per
//! unit area of the real surface.

use std::f64::consts::TAU;
use std::time::Instant;

use crate::error::{Error, Result};
use crate::fem::element::{Tempering, TriGeometry};
use crate::fem::material::{Material, PlaneMode};
use crate::fem::mesh::Mesh;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder, subdivide};
use crate::studies::quadrature::{QUAD_POINTS, QUAD_WEIGHTS};
use crate::studies::verification::{StudyPoint, point};

/// The manufactured ring field u_r = r² sin z / 10, u_z = z cos r / 10 (u_r
/// vanishes on the axis, as it must), with its strains and the body force
/// that makes it a solution, derived by hand below for the material's λ
/// and μ: b = −div σ in cylindrical coordinates,
///
/// ```text
///   b_r = −(∂σ_rr/∂r + ∂σ_rz/∂z + (σ_rr − σ_θθ)/r)
///   b_z = −(∂σ_rz/∂r + ∂σ_zz/∂z + σ_rz/r).
/// ```
#[derive(Debug, Clone, Copy)]
pub struct ManufacturedRing {
    lambda: f64,
    mu: f64,
}

impl ManufacturedRing {
    /// The field for an axisymmetric `material` (its 3D λ and μ).
    pub fn new(material: &Material) -> ManufacturedRing {
        let (e, nu) = (material.young(), material.poisson());
        ManufacturedRing {
            lambda: e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
            mu: e / (2.0 * (1.0 + nu)),
        }
    }

    /// The displacement [u_r, u_z] at (r, z).
    pub fn displacement(&self, [r, z]: [f64; 2]) -> [f64; 2] {
        [r * r * z.sin() / 10.0, z * r.cos() / 10.0]
    }

    /// The body force [b_r, b_z] per unit volume at (r, z).
    pub fn body_force(&self, [r, z]: [f64; 2]) -> [f64; 2] {
        let (l, m) = (self.lambda, self.mu);
        let (sz, cz, sr, cr) = (z.sin(), z.cos(), r.sin(), r.cos());
        // tr ε = 3r sin z/10 + cos r/10; ε_rr = r sin z/5, ε_θθ = r sin z/10,
        // ε_zz = cos r/10, γ_rz = r² cos z/10 − z sin r/10.
        let dtr_dr = (3.0 * sz - sr) / 10.0;
        let dtr_dz = 3.0 * r * cz / 10.0;
        let dsrr_dr = l * dtr_dr + 2.0 * m * sz / 5.0;
        let dsrz_dz = m * (-r * r * sz - sr) / 10.0;
        let hoop_diff_over_r = m * sz / 5.0; // 2μ(ε_rr − ε_θθ)/r
        let dsrz_dr = m * (2.0 * r * cz - z * cr) / 10.0;
        let dszz_dz = l * dtr_dz;
        // sin r / r → 1 on the axis.
        let sinc = if r == 0.0 { 1.0 } else { sr / r };
        let srz_over_r = m * (r * cz - z * sinc) / 10.0;
        [
            -(dsrr_dr + dsrz_dz + hoop_diff_over_r),
            -(dsrz_dr + dszz_dz + srz_over_r),
        ]
    }
}

/// The whole-ring nodal forces ∫ b φ_i 2πr dA of a body force field (a
/// quadrature exact for quartics; flat and inverted triangles carry none).
pub fn ring_nodal_loads(mesh: &Mesh, body_force: impl Fn([f64; 2]) -> [f64; 2]) -> Vec<[f64; 2]> {
    let mut f = vec![[0.0; 2]; mesh.nodes().len()];
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.max(0.0);
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let p = point(&x, q);
            let b = body_force(p);
            let measure = w * area * TAU * p[0];
            for a in 0..3 {
                f[tri[a]][0] += measure * b[0] * q[a];
                f[tri[a]][1] += measure * b[1] * q[a];
            }
        }
    }
    f
}

/// The L2 norm over the solid of revolution, (∫ |u − u_h|² 2πr dA)^½, of a
/// P1 field `uh` (2 values per node) against `exact`.
pub fn ring_l2_error(mesh: &Mesh, uh: &[f64], exact: impl Fn([f64; 2]) -> [f64; 2]) -> f64 {
    let mut sum = 0.0;
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.abs();
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let p = point(&x, q);
            let ex = exact(p);
            for c in 0..2 {
                let v: f64 = (0..3).map(|a| q[a] * uh[2 * tri[a] + c]).sum();
                sum += w * area * TAU * p[0] * (ex[c] - v).powi(2);
            }
        }
    }
    sum.sqrt()
}

/// Solves [`ManufacturedRing`] on the mesh of `builder` (x the radius,
/// every node of its boundary prescribed to the exact field, which gives
/// u_r = 0 on the axis) and measures the weighted L2 error.
pub fn run_manufactured_ring(
    builder: MeshBuilder,
    h: f64,
    material: Material,
    tempering: Tempering,
) -> Result<StudyPoint> {
    let exact = ManufacturedRing::new(&material);
    let mut boundary: Vec<usize> = builder.boundary_edges().into_iter().flatten().collect();
    boundary.sort_unstable();
    boundary.dedup();
    let mesh = builder.build()?;
    let loads = ring_nodal_loads(&mesh, |p| exact.body_force(p));
    let mut model = Model::new();
    model.set_mesh(mesh);
    model.set_material(1, material)?;
    model.set_tempering(tempering)?;
    for &v in &boundary {
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
    let l2 = ring_l2_error(mesh, &uh, |p| exact.displacement(p));
    Ok(StudyPoint {
        h,
        unknowns: info.unknowns,
        l2,
        energy: f64::NAN,
        seconds,
    })
}

/// The square [r0, r0 + 1] × [0, 1] of the (r, z) plane with n × n cells
/// and, when `band` is `Some(eps)`, the band of caps of height eps along
/// z = 1/2 ([`crate::studies::meshgen::unit_square`]).
pub fn ring_square(r0: f64, n: usize, band: Option<f64>) -> MeshBuilder {
    let mut b = crate::studies::meshgen::unit_square(n, band);
    b.nodes.iter_mut().for_each(|p| p[0] += r0);
    b
}

/// Tag of a thick cylinder's bore (r = a), which carries the pressure.
pub const TAG_BORE: i32 = 1;
/// Tag of a thick cylinder's ends (z = 0 and z = ℓ), held axially.
pub const TAG_ENDS: i32 = 2;

/// A thick-walled cylinder a ≤ r ≤ b, 0 ≤ z ≤ ℓ, under internal pressure p,
/// its ends held axially (u_z = 0: plane strain, ε_zz = 0), so that the
/// exact field is Lamé's at every z. [`Default`]: a = 1, b = 2, ℓ = 1,
/// steel-like, p = 100, 8 cells over the wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThickCylinder {
    /// Bore radius a.
    pub inner: f64,
    /// Outer radius b.
    pub outer: f64,
    /// Length ℓ.
    pub length: f64,
    /// Young's modulus.
    pub e: f64,
    /// Poisson ratio.
    pub nu: f64,
    /// Internal pressure p.
    pub pressure: f64,
    /// Cells over the wall (and per unit of length as many per unit r).
    pub cells: usize,
}

impl Default for ThickCylinder {
    fn default() -> Self {
        ThickCylinder {
            inner: 1.0,
            outer: 2.0,
            length: 1.0,
            e: 210e3,
            nu: 0.3,
            pressure: 100.0,
            cells: 8,
        }
    }
}

/// The solved thick cylinder against Lamé.
#[derive(Debug, Clone, Copy)]
pub struct ThickCylinderResult {
    /// Largest |σ_θθ − Lamé| over the elements, over p.
    pub hoop_error: f64,
    /// Largest |σ_rr − Lamé| over the elements, over p.
    pub radial_error: f64,
    /// Largest |u_r − Lamé| over the nodes, over Lamé's u_r at the bore.
    pub displacement_error: f64,
    /// The axial reaction of the ends against 2πν p a²/(1 − … ) (Lamé's
    /// σ_zz = 2νA over the annulus), relative.
    pub axial_force_error: f64,
    /// Unknowns.
    pub unknowns: usize,
    /// Seconds for the solve.
    pub seconds: f64,
}

impl ThickCylinder {
    /// Lamé's stresses at radius r: (σ_rr, σ_θθ) = (A − B/r², A + B/r²),
    /// A = p a²/(b² − a²), B = p a² b²/(b² − a²); σ_zz = 2νA.
    pub fn lame(&self, r: f64) -> (f64, f64) {
        let (a, b, p) = (self.inner, self.outer, self.pressure);
        let big_a = p * a * a / (b * b - a * a);
        let big_b = big_a * b * b;
        (big_a - big_b / (r * r), big_a + big_b / (r * r))
    }

    /// Lamé's radial displacement at r (plane strain):
    /// u_r = r (σ_θθ − ν(σ_rr + σ_zz))/E.
    pub fn lame_displacement(&self, r: f64) -> f64 {
        let (srr, stt) = self.lame(r);
        let szz = self.nu * (srr + stt);
        r * (stt - self.nu * (srr + szz)) / self.e
    }

    /// Builds and solves the cylinder, and compares it with Lamé.
    pub fn solve(&self) -> Result<ThickCylinderResult> {
        let (a, b, l) = (self.inner, self.outer, self.length);
        if !(a > 0.0 && b > a && l > 0.0 && self.cells >= 1) {
            return Err(Error::argument(
                "thick cylinder: need 0 < a < b, ℓ > 0, cells >= 1",
            ));
        }
        let h = (b - a) / self.cells as f64;
        let rs = subdivide(a, b, &[], h)?;
        let zs = subdivide(0.0, l, &[], h)?;
        let mut mb = MeshBuilder::new();
        let rows = mb.add_grid(&rs, &zs, 1, Diagonal::Forward);
        let (mut edges, mut tags) = (Vec::new(), Vec::new());
        for e in mb.boundary_edges() {
            let [p, q] = [mb.nodes[e[0]], mb.nodes[e[1]]];
            let tag = if p[0] == a && q[0] == a {
                TAG_BORE
            } else if (p[1] == 0.0 && q[1] == 0.0) || (p[1] == l && q[1] == l) {
                TAG_ENDS
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let m = Material::new(self.e, self.nu, PlaneMode::Axisymmetric, "cylinder")?;
        model.set_material(1, m)?;
        model.fix_edges(TAG_ENDS, Component::Y, 0.0)?;
        model.add_pressure(TAG_BORE, self.pressure)?;
        let t0 = Instant::now();
        let info = model.solve()?;
        let seconds = t0.elapsed().as_secs_f64();
        let mesh = model.mesh().expect("set");
        let stresses = model.element_stresses()?;
        let hoop = model.element_out_of_plane_stresses()?;
        let (mut hoop_error, mut radial_error) = (0.0f64, 0.0f64);
        for (t, tri) in mesh.triangles().iter().enumerate() {
            let x = mesh.corners(tri);
            let r = (x[0][0] + x[1][0] + x[2][0]) / 3.0;
            let (srr, stt) = self.lame(r);
            hoop_error = hoop_error.max((hoop[t] - stt).abs() / self.pressure);
            radial_error = radial_error.max((stresses[t][0] - srr).abs() / self.pressure);
        }
        let u = model.displacements()?;
        let scale = self.lame_displacement(a).abs();
        let displacement_error = rows
            .iter()
            .flatten()
            .map(|&v| (u[v][0] - self.lame_displacement(mesh.nodes()[v][0])).abs() / scale)
            .fold(0.0, f64::max);
        // The ends carry σ_zz = 2νA over the annulus: ∫ 2πr dr = π(b² − a²).
        let (big_a, _) = self.lame(f64::INFINITY);
        let axial = 2.0 * self.nu * big_a * std::f64::consts::PI * (b * b - a * a);
        let reactions = model.reactions()?;
        let bottom: f64 = rows[0].iter().map(|&v| reactions[v][1]).sum();
        Ok(ThickCylinderResult {
            hoop_error,
            radial_error,
            displacement_error,
            // The support pulls the end down: −σ_zz over the annulus.
            axial_force_error: (bottom + axial).abs() / axial.abs(),
            unknowns: info.unknowns,
            seconds,
        })
    }
}
