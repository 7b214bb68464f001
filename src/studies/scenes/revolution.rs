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

/// Tag of the lower cylinder's bottom (held axially).
pub const TAG_BASE: i32 = 1;
/// Tag of the lower cylinder's top (contact side a).
pub const TAG_LOWER_TOP: i32 = 2;
/// Tag of the upper cylinder's bottom (contact side b).
pub const TAG_UPPER_BOTTOM: i32 = 3;
/// Tag of the upper cylinder's top (loaded).
pub const TAG_TOP: i32 = 4;

/// The axisymmetric contact patch test: two coaxial cylinders (or tubes)
/// r0 ≤ r ≤ r0 + w stacked along z, the lower on [−H, 0] held axially at
/// its bottom, the upper on [0, H] pressed by a uniform pressure p on its
/// top, frictionless. Exact: σ_zz = −p in both, every other stress 0
/// (each body expands radially by ν p r/E). [`Default`]: a solid cylinder
/// (r0 = 0) of radius 1, H = 1/2, equal materials, 8 cells over the
/// radius below and 12 above (non-matching).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StackedCylinders {
    /// Inner radius r0 (0: solid cylinders, u_r = 0 on the axis).
    pub inner: f64,
    /// Wall width w.
    pub width: f64,
    /// Height H of each cylinder.
    pub height: f64,
    /// Cells over the width, lower and upper cylinder.
    pub cells: [usize; 2],
    /// Young's moduli, lower and upper.
    pub e: [f64; 2],
    /// Poisson ratios, lower and upper.
    pub nu: [f64; 2],
    /// The pressure p.
    pub pressure: f64,
}

impl Default for StackedCylinders {
    fn default() -> Self {
        StackedCylinders {
            inner: 0.0,
            width: 1.0,
            height: 0.5,
            cells: [8, 12],
            e: [1e3, 1e3],
            nu: [0.3, 0.3],
            pressure: 1.0,
        }
    }
}

/// The patch test's errors.
#[derive(Debug, Clone, Copy)]
pub struct PatchResult {
    /// Largest |σ − σ_exact| over the elements and components (hoop
    /// included), over p.
    pub stress_error: f64,
    /// Largest |p_node − p| over the contact nodes, over p.
    pub pressure_error: f64,
    /// The total reaction of the base against p π((r0 + w)² − r0²),
    /// relative.
    pub force_error: f64,
    /// Whether every element of B ended active.
    pub all_active: bool,
}

impl StackedCylinders {
    /// Builds, solves and measures the patch test.
    pub fn solve(&self) -> Result<PatchResult> {
        let (r0, w, hh) = (self.inner, self.width, self.height);
        let mut mb = MeshBuilder::new();
        let mut rows = Vec::new();
        for (k, zs) in [[-hh, 0.0], [0.0, hh]].iter().enumerate() {
            let n = self.cells[k];
            let rs: Vec<f64> = (0..=n).map(|i| r0 + w * i as f64 / n as f64).collect();
            let nz = ((hh / w) * n as f64).ceil().max(1.0) as usize;
            let zs: Vec<f64> = (0..=nz)
                .map(|j| zs[0] + (zs[1] - zs[0]) * j as f64 / nz as f64)
                .collect();
            rows.push(mb.add_grid(&rs, &zs, k as i32 + 1, Diagonal::Forward));
        }
        let (lower, upper) = (&rows[0], &rows[1]);
        let mut edges = Vec::new();
        let mut tags = Vec::new();
        let row_tag = [
            (&lower[0], TAG_BASE),
            (lower.last().expect("rows"), TAG_LOWER_TOP),
            (&upper[0], TAG_UPPER_BOTTOM),
            (upper.last().expect("rows"), TAG_TOP),
        ];
        for e in mb.boundary_edges() {
            if let Some((_, tag)) = row_tag
                .iter()
                .find(|(row, _)| row.contains(&e[0]) && row.contains(&e[1]))
            {
                edges.push(e);
                tags.push(*tag);
            }
        }
        let axis: Vec<usize> = match r0 == 0.0 {
            true => rows.iter().flatten().map(|row| row[0]).collect(),
            false => Vec::new(),
        };
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        for k in 0..2 {
            let what = format!("body {}", k + 1);
            let m = Material::new(self.e[k], self.nu[k], PlaneMode::Axisymmetric, &what)?;
            model.set_material(k as i32 + 1, m)?;
        }
        model.fix_edges(TAG_BASE, Component::Y, 0.0)?;
        for &v in &axis {
            model.fix(v, Component::X, 0.0)?;
        }
        model.add_pressure(TAG_TOP, self.pressure)?;
        model.add_contact_pair(TAG_LOWER_TOP, TAG_UPPER_BOTTOM)?;
        model.solve_contact(&crate::contact::ContactOptions::default())?;
        let p = self.pressure;
        let stresses = model.element_stresses()?;
        let hoop = model.element_out_of_plane_stresses()?;
        let stress_error = stresses
            .iter()
            .zip(&hoop)
            .map(|(s, h)| {
                let e = [s[0].abs(), (s[1] + p).abs(), s[2].abs(), h.abs()];
                e.into_iter().fold(0.0, f64::max) / p
            })
            .fold(0.0, f64::max);
        let nodal = model.contact_nodal_pressures()?;
        let contact_nodes: Vec<usize> = lower
            .last()
            .expect("rows")
            .iter()
            .chain(&upper[0])
            .copied()
            .collect();
        let pressure_error = contact_nodes
            .iter()
            .map(|&v| (nodal[v] - p).abs() / p)
            .fold(0.0, f64::max);
        let reactions = model.reactions()?;
        let base: f64 = lower[0].iter().map(|&v| reactions[v][1]).sum();
        let outer = r0 + w;
        let total = p * std::f64::consts::PI * (outer * outer - r0 * r0);
        Ok(PatchResult {
            stress_error,
            pressure_error,
            force_error: (base - total).abs() / total,
            all_active: model.contact_active()?.iter().all(|&a| a),
        })
    }
}

/// Tag of the shaft's surface (contact side a).
pub const TAG_SHAFT: i32 = 5;
/// Tag of the hub's bore (contact side b).
pub const TAG_HUB_BORE: i32 = 6;
/// Tag of the shaft's ends.
pub const TAG_SHAFT_ENDS: i32 = 7;
/// Tag of the hub's ends.
pub const TAG_HUB_ENDS: i32 = 8;

/// A hub b ≤ r ≤ c shrunk on a solid shaft of radius b + δ, both of length
/// ℓ, their ends held axially (ε_zz = 0: a slice of a long fit), so that
/// Lamé's plane-strain shrink fit is exact at every z: contact pressure
///
/// ```text
///   p = E' δ (c² − b²) / (2 b c²),   E' = E/(1 − ν²)
/// ```
///
/// (same material), hoop stress p (c² + b²)/(c² − b²) at the bore, −p in
/// the shaft. With friction μ, pushing the shaft's ends along the axis by
/// `push` slides it through the hub against the push-out force
/// F = 2π b ℓ μ p. [`Default`]: b = 1, c = 2, ℓ = 2, δ = 10⁻³ b, steel,
/// 8 cells over the shaft's radius and the hub's wall (h = 1/8), the hub's
/// 3 cells for the shaft's 2 along z (non-matching).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaftHub {
    /// Bore radius b.
    pub bore: f64,
    /// Outer radius c of the hub.
    pub outer: f64,
    /// Length ℓ.
    pub length: f64,
    /// Radial interference δ.
    pub interference: f64,
    /// Young's modulus (both).
    pub e: f64,
    /// Poisson ratio (both).
    pub nu: f64,
    /// Cells over the bore radius b (and per b along z, for the shaft).
    pub cells: usize,
    /// Cells of the hub along z per cell of the shaft, as a ratio
    /// (numerator, denominator): (1, 1) matching, (3, 2) non-matching.
    pub ratio: (usize, usize),
    /// Coulomb coefficient μ of the fit.
    pub mu: f64,
}

impl Default for ShaftHub {
    fn default() -> Self {
        ShaftHub {
            bore: 1.0,
            outer: 2.0,
            length: 2.0,
            interference: 1e-3,
            e: 210e3,
            nu: 0.3,
            cells: 8,
            ratio: (3, 2),
            mu: 0.0,
        }
    }
}

/// A built shaft–hub fit.
pub struct ShaftHubScene {
    /// The model, ready for `solve_contact` or load steps.
    pub model: Model,
    /// The shaft's surface nodes (r = b + δ), by z.
    pub shaft_surface: Vec<usize>,
    /// The hub's bore nodes (r = b), by z.
    pub hub_bore: Vec<usize>,
    /// The shaft's end nodes (z = 0 and ℓ).
    pub shaft_ends: Vec<usize>,
    /// The first triangle of the hub (the shaft's come first).
    pub first_hub_triangle: usize,
}

/// What a solved fit measures against Lamé.
#[derive(Debug, Clone, Copy)]
pub struct ShaftHubResult {
    /// Mean nodal contact pressure over the middle half of the length
    /// (ℓ/4 ≤ z ≤ 3ℓ/4, both sides), over Lamé's p, minus 1.
    pub pressure_error: f64,
    /// Largest |p_node/p − 1| over that middle half.
    pub pressure_spread: f64,
    /// Mean hoop stress of the hub's bore elements (their centroid within
    /// h of the bore) over the middle half, against Lamé's at their mean
    /// radius, relative.
    pub hub_hoop_error: f64,
    /// Mean hoop stress of the shaft's elements over the middle half
    /// against −p, relative.
    pub shaft_hoop_error: f64,
    /// Unknowns.
    pub unknowns: usize,
    /// Seconds for the contact solve.
    pub seconds: f64,
}

impl ShaftHub {
    /// Lamé's contact pressure of the fit (plane strain, same material).
    pub fn pressure(&self) -> f64 {
        let (b, c) = (self.bore, self.outer);
        let e_plane = self.e / (1.0 - self.nu * self.nu);
        e_plane * self.interference * (c * c - b * b) / (2.0 * b * c * c)
    }

    /// Lamé's hoop stress in the hub at radius r.
    pub fn hub_hoop(&self, r: f64) -> f64 {
        let (b, c) = (self.bore, self.outer);
        self.pressure() * b * b / (c * c - b * b) * (1.0 + c * c / (r * r))
    }

    /// The push-out force 2π b ℓ μ p.
    pub fn push_out_force(&self) -> f64 {
        TAU * self.bore * self.length * self.mu * self.pressure()
    }

    /// Builds the model: shaft body 1, hub body 2, ends held axially, u_r =
    /// 0 on the axis, the pair (shaft, bore) with friction μ.
    pub fn build(&self) -> Result<ShaftHubScene> {
        let (b, c, l, d) = (self.bore, self.outer, self.length, self.interference);
        if !(b > 0.0 && c > b && l > 0.0 && d >= 0.0 && d < 0.1 * b && self.cells >= 2) {
            return Err(Error::argument(
                "shaft and hub: need 0 < b < c, ℓ > 0, 0 <= δ < b/10, cells >= 2",
            ));
        }
        let h = b / self.cells as f64;
        let (num, den) = self.ratio;
        let shaft_r = subdivide(0.0, b + d, &[], h)?;
        let hub_r = subdivide(b, c, &[], h)?;
        let shaft_z = subdivide(0.0, l, &[], h)?;
        let hub_z = subdivide(0.0, l, &[], h * den as f64 / num as f64)?;
        let mut mb = MeshBuilder::new();
        let shaft = mb.add_grid(&shaft_r, &shaft_z, 1, Diagonal::Forward);
        let first_hub_triangle = mb.triangles.len();
        let hub = mb.add_grid(&hub_r, &hub_z, 2, Diagonal::Forward);
        let shaft_surface: Vec<usize> = shaft
            .iter()
            .map(|row| *row.last().expect("cells"))
            .collect();
        let hub_bore: Vec<usize> = hub.iter().map(|row| row[0]).collect();
        let axis: Vec<usize> = shaft.iter().map(|row| row[0]).collect();
        let shaft_ends: Vec<usize> = shaft[0]
            .iter()
            .chain(shaft.last().expect("rows"))
            .copied()
            .collect();
        let hub_ends: Vec<usize> = hub[0]
            .iter()
            .chain(hub.last().expect("rows"))
            .copied()
            .collect();
        let (mut edges, mut tags) = (Vec::new(), Vec::new());
        for e in mb.boundary_edges() {
            let both = |s: &[usize]| s.contains(&e[0]) && s.contains(&e[1]);
            let tag = if both(&shaft_surface) {
                TAG_SHAFT
            } else if both(&hub_bore) {
                TAG_HUB_BORE
            } else if both(&shaft_ends) && mb.nodes[e[0]][1] == mb.nodes[e[1]][1] {
                TAG_SHAFT_ENDS
            } else if both(&hub_ends) && mb.nodes[e[0]][1] == mb.nodes[e[1]][1] {
                TAG_HUB_ENDS
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        for (body, what) in [(1, "shaft"), (2, "hub")] {
            let m = Material::new(self.e, self.nu, PlaneMode::Axisymmetric, what)?;
            model.set_material(body, m)?;
        }
        for &v in &axis {
            model.fix(v, Component::X, 0.0)?;
        }
        for &v in shaft_ends.iter().chain(&hub_ends) {
            model.fix(v, Component::Y, 0.0)?;
        }
        let pair = model.add_contact_pair(TAG_SHAFT, TAG_HUB_BORE)?;
        if self.mu > 0.0 {
            model.set_friction(pair, self.mu)?;
        }
        Ok(ShaftHubScene {
            model,
            shaft_surface,
            hub_bore,
            shaft_ends,
            first_hub_triangle,
        })
    }

    /// Builds and solves the fit (one contact solve) and measures it.
    pub fn solve(&self) -> Result<(ShaftHubScene, ShaftHubResult)> {
        let mut scene = self.build()?;
        let t0 = Instant::now();
        let report = scene
            .model
            .solve_contact(&crate::contact::ContactOptions::default())?;
        let seconds = t0.elapsed().as_secs_f64();
        let result = self.measure(&scene, report.info.unknowns, seconds)?;
        Ok((scene, result))
    }

    /// The push-out force: the fit made in one load step, then the
    /// shaft's ends moved along the axis by `push` in `steps` more (the
    /// hub's stay held); the force is the shaft ends' axial reaction (the
    /// whole ring's). Gives it with the elements that slip at the end
    /// over all of them.
    pub fn push_out(&self, push: f64, steps: usize) -> Result<(f64, f64)> {
        let mut scene = self.build()?;
        let options = crate::contact::ContactOptions::default();
        scene.model.step(1.0, &options)?;
        for k in 1..=steps {
            let at = push * k as f64 / steps as f64;
            for &v in &scene.shaft_ends {
                scene.model.set_prescribed(v, Component::Y, at)?;
            }
            scene.model.step(1.0, &options)?;
        }
        let reactions = scene.model.reactions()?;
        let force: f64 = scene.shaft_ends.iter().map(|&v| reactions[v][1]).sum();
        let states = scene.model.contact_friction_state()?;
        let closed = states.iter().filter(|&&s| s != 0).count();
        let slipping = states.iter().filter(|&&s| s == 2).count();
        Ok((force.abs(), slipping as f64 / closed.max(1) as f64))
    }

    /// The fit's pressure and hoop stresses against Lamé over the middle
    /// half of the length.
    pub fn measure(
        &self,
        scene: &ShaftHubScene,
        unknowns: usize,
        seconds: f64,
    ) -> Result<ShaftHubResult> {
        let model = &scene.model;
        let mesh = model.mesh().expect("built");
        let l = self.length;
        let middle = |z: f64| (0.25 * l..=0.75 * l).contains(&z);
        let p = self.pressure();
        let nodal = model.contact_nodal_pressures()?;
        let ratios: Vec<f64> = (scene.shaft_surface.iter().chain(&scene.hub_bore))
            .filter(|&&v| middle(mesh.nodes()[v][1]))
            .map(|&v| nodal[v] / p)
            .collect();
        let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
        let spread = ratios.iter().map(|r| (r - 1.0).abs()).fold(0.0, f64::max);
        let hoop = model.element_out_of_plane_stresses()?;
        let h = self.bore / self.cells as f64;
        let (mut hub, mut hub_exact, mut shaft, mut n_shaft) = (0.0, 0.0, 0.0, 0usize);
        for (t, tri) in mesh.triangles().iter().enumerate() {
            let x = mesh.corners(tri);
            let [r, z] = [0, 1].map(|c| (x[0][c] + x[1][c] + x[2][c]) / 3.0);
            if !middle(z) {
                continue;
            }
            if t >= scene.first_hub_triangle {
                if r < self.bore + h {
                    hub += hoop[t];
                    hub_exact += self.hub_hoop(r);
                }
            } else {
                shaft += hoop[t];
                n_shaft += 1;
            }
        }
        Ok(ShaftHubResult {
            pressure_error: mean - 1.0,
            pressure_spread: spread,
            hub_hoop_error: hub / hub_exact - 1.0,
            shaft_hoop_error: (shaft / n_shaft as f64) / (-p) - 1.0,
            unknowns,
            seconds,
        })
    }
}
