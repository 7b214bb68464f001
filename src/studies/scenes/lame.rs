//! Lamé shrink fit: two concentric rings that overlap initially — an inner
//! ring a ≤ r ≤ b + δ inside an outer ring b ≤ r ≤ c, δ > 0 the radial
//! interference — so that every element of B starts inverted (J0 < 0,
//! docs/method.md §6.14). A quarter of the rings is modelled, with rollers
//! on the symmetry lines (v = 0 on y = 0, u = 0 on x = 0): the rings are
//! then free to expand and contract radially and have no rigid motion
//! left. Both are meshed by the built-in structured triangulator in polar
//! coordinates, with the same angles on both sides of the interface.
//!
//! # The closed form
//!
//! A ring r_i ≤ r ≤ r_o under internal pressure p_i and external pressure
//! p_o (plane stress, modulus E, Poisson ratio ν) has
//!
//! ```text
//!     σ_rr = A − B/r²,   σ_θθ = A + B/r²,
//!     A = (p_i r_i² − p_o r_o²)/(r_o² − r_i²),   B = (p_i − p_o) r_i² r_o²/(r_o² − r_i²),
//!     u_r = (r/E) [(1 − ν) A + (1 + ν) B/r²]
//! ```
//!
//! (σ_rr(r_i) = −p_i, σ_rr(r_o) = −p_o; u_r = r ε_θθ = r (σ_θθ − ν σ_rr)/E).
//! In plane strain the stresses are the same and u_r takes E' = E/(1 − ν²),
//! ν' = ν/(1 − ν) in place of E, ν. The rings are taken as meshed: the inner
//! one ends at b₁ = b + δ, the outer one starts at b. Small strain puts the
//! equations on the initial configuration, where the contact transmits the
//! same force per radian to both surfaces (tfem's elements of B join nodes
//! at the same angle, and their forces on the two sides are opposite): a
//! pressure p on the outer ring at r = b is a pressure p₁ = p b/b₁ on the
//! inner ring at r = b₁. Compatibility — the two surfaces meet after the
//! fit, b₁ + u_r¹(b₁) = b + u_r²(b) — gives
//!
//! ```text
//!     δ = u_r²(b) − u_r¹(b₁) = p [U₂ − (b/b₁) U₁],
//! ```
//!
//! U₂ the outer ring's u_r(b) under a unit internal pressure (> 0), U₁ the
//! inner ring's u_r(b₁) under a unit external pressure (< 0). For equal
//! materials in plane stress and δ → 0 this is the textbook
//! p = (E δ/b) (b² − a²)(c² − b²) / (2 b² (c² − a²)) (checked below).

use std::collections::BTreeSet;
use std::f64::consts::FRAC_PI_2;

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::curve::Curve;
use crate::fem::material::{Material, PlaneMode};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::MeshBuilder;
use crate::studies::verification::energy_error_of_body;

/// Tag of the inner ring's outer surface (contact side a).
pub const TAG_INNER_RING: i32 = 1;
/// Tag of the outer ring's inner surface (contact side b).
pub const TAG_OUTER_RING: i32 = 2;
/// Tag of the inner ring's bore, r = a (free).
pub const TAG_BORE: i32 = 3;
/// Tag of the outer ring's rim, r = c (free).
pub const TAG_RIM: i32 = 4;

/// Parameters of the shrink fit. [`Default`]: a = 0.5, b = 1, c = 1.5,
/// δ = 1e-3 b, steel-like inner ring, an outer ring half as stiff, plane
/// strain, h = b/16 at the interface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lame {
    /// Inner radius a of the inner ring.
    pub inner_radius: f64,
    /// Inner radius b of the outer ring (the nominal interface).
    pub radius: f64,
    /// Outer radius c of the outer ring.
    pub outer_radius: f64,
    /// Radial interference δ: the inner ring's outer radius is b + δ.
    pub interference: f64,
    /// Young's modulus of the inner ring (body 1).
    pub e_inner: f64,
    /// Poisson ratio of the inner ring.
    pub nu_inner: f64,
    /// Young's modulus of the outer ring (body 2).
    pub e_outer: f64,
    /// Poisson ratio of the outer ring.
    pub nu_outer: f64,
    /// Plane strain or plane stress (both rings).
    pub plane: PlaneMode,
    /// Element size: the radial spacing, and the arc spacing at r = b.
    pub mesh_size: f64,
}

impl Default for Lame {
    fn default() -> Self {
        Lame {
            inner_radius: 0.5,
            radius: 1.0,
            outer_radius: 1.5,
            interference: 1e-3,
            e_inner: 2e11,
            nu_inner: 0.3,
            e_outer: 1e11,
            nu_outer: 0.25,
            plane: PlaneMode::Strain,
            mesh_size: 1.0 / 16.0,
        }
    }
}

/// One ring of the closed form: r_i ≤ r ≤ r_o under the pressures p_i
/// (inside) and p_o (outside).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ring {
    /// Inner radius.
    pub r_in: f64,
    /// Outer radius.
    pub r_out: f64,
    /// Pressure on the inner surface (positive in compression).
    pub p_in: f64,
    /// Pressure on the outer surface.
    pub p_out: f64,
    /// Effective (plane-stress) Young's modulus: E, or E/(1 − ν²) in plane
    /// strain.
    pub e: f64,
    /// Effective Poisson ratio: ν, or ν/(1 − ν) in plane strain.
    pub nu: f64,
}

impl Ring {
    fn ab(&self) -> (f64, f64) {
        let (ri2, ro2) = (self.r_in * self.r_in, self.r_out * self.r_out);
        let a = (self.p_in * ri2 - self.p_out * ro2) / (ro2 - ri2);
        let b = (self.p_in - self.p_out) * ri2 * ro2 / (ro2 - ri2);
        (a, b)
    }

    /// Radial stress σ_rr at radius r.
    pub fn sigma_rr(&self, r: f64) -> f64 {
        let (a, b) = self.ab();
        a - b / (r * r)
    }

    /// Hoop stress σ_θθ at radius r.
    pub fn sigma_tt(&self, r: f64) -> f64 {
        let (a, b) = self.ab();
        a + b / (r * r)
    }

    /// Radial displacement u_r at radius r.
    pub fn u_r(&self, r: f64) -> f64 {
        let (a, b) = self.ab();
        r / self.e * ((1.0 - self.nu) * a + (1.0 + self.nu) * b / (r * r))
    }

    /// The displacement gradient [[∂u/∂x, ∂u/∂y], [∂v/∂x, ∂v/∂y]] at `p`:
    /// u = u_r(r) e_r, so ∇u = u_r′ e_r e_rᵀ + (u_r/r)(I − e_r e_rᵀ), with
    /// u_r′ = ε_rr = [(1 − ν) A − (1 + ν) B/r²]/E.
    pub fn gradient(&self, p: [f64; 2]) -> [[f64; 2]; 2] {
        let (a, b) = self.ab();
        let r = p[0].hypot(p[1]);
        let e = [p[0] / r, p[1] / r];
        let radial = ((1.0 - self.nu) * a - (1.0 + self.nu) * b / (r * r)) / self.e;
        let hoop = self.u_r(r) / r;
        let mut g = [[0.0; 2]; 2];
        for (i, row) in g.iter_mut().enumerate() {
            for (j, gij) in row.iter_mut().enumerate() {
                let delta = if i == j { 1.0 } else { 0.0 };
                *gij = radial * e[i] * e[j] + hoop * (delta - e[i] * e[j]);
            }
        }
        g
    }
}

/// The closed-form shrink fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LameSolution {
    /// Contact pressure on the outer ring's inner surface (r = b).
    pub pressure: f64,
    /// The inner ring (a ≤ r ≤ b + δ, pressure p b/(b + δ) outside).
    pub inner: Ring,
    /// The outer ring (b ≤ r ≤ c, pressure p inside).
    pub outer: Ring,
}

/// Effective plane-stress constants of a material in `plane`.
fn effective(e: f64, nu: f64, plane: PlaneMode) -> (f64, f64) {
    match plane {
        PlaneMode::Stress => (e, nu),
        PlaneMode::Strain => (e / (1.0 - nu * nu), nu / (1.0 - nu)),
        PlaneMode::Axisymmetric => unreachable!("the rings of this scene lie in the plane"),
    }
}

/// The built shrink-fit scene.
pub struct LameScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Nodes of the inner ring's outer surface, by increasing angle.
    pub inner_surface: Vec<usize>,
    /// Nodes of the outer ring's inner surface, by increasing angle.
    pub outer_surface: Vec<usize>,
    /// Triangles of the inner ring (the first ones); the rest are the
    /// outer ring's.
    pub n_inner_triangles: usize,
}

/// Errors of a solve against the closed form, each relative to the
/// closed-form contact pressure p (the scale of every stress of the fit).
#[derive(Debug, Clone, PartialEq)]
pub struct LameResult {
    /// The closed form.
    pub exact: LameSolution,
    /// Largest error of the nodal contact pressures, both surfaces: the
    /// nodal radial contact force over the node's share of the arc
    /// (r Δθ), against p (outer surface) and p b/(b + δ) (inner surface).
    pub pressure_error: f64,
    /// Largest error of the hoop stress σ_θθ of a grid cell (the
    /// area-weighted mean of its four triangles) against the closed form
    /// at the cell's centre, over both rings.
    pub hoop_error: f64,
    /// Largest error of the element radial stresses σ_rr, as `hoop_error`.
    pub radial_error: f64,
    /// The hoop stress along the outer ring's bore (its largest): the mean
    /// over the cells along the bore against the closed form at their mean
    /// radius, relative to that value.
    pub bore_hoop_error: f64,
    /// The contact report.
    pub report: ContactReport,
}

impl Lame {
    /// The closed form for these rings (docs above).
    pub fn exact(&self) -> LameSolution {
        let (a, b, c, d) = (
            self.inner_radius,
            self.radius,
            self.outer_radius,
            self.interference,
        );
        let b1 = b + d;
        let (e1, nu1) = effective(self.e_inner, self.nu_inner, self.plane);
        let (e2, nu2) = effective(self.e_outer, self.nu_outer, self.plane);
        let unit_inner = Ring {
            r_in: a,
            r_out: b1,
            p_in: 0.0,
            p_out: 1.0,
            e: e1,
            nu: nu1,
        };
        let unit_outer = Ring {
            r_in: b,
            r_out: c,
            p_in: 1.0,
            p_out: 0.0,
            e: e2,
            nu: nu2,
        };
        let p = d / (unit_outer.u_r(b) - (b / b1) * unit_inner.u_r(b1));
        LameSolution {
            pressure: p,
            inner: Ring {
                p_out: p * b / b1,
                ..unit_inner
            },
            outer: Ring {
                p_in: p,
                ..unit_outer
            },
        }
    }

    /// Builds the quarter rings, materials, rollers and the contact pair.
    pub fn build(&self) -> Result<LameScene> {
        let (a, b, c, d, h) = (
            self.inner_radius,
            self.radius,
            self.outer_radius,
            self.interference,
            self.mesh_size,
        );
        if !(a > 0.0 && a < b && b < c && d >= 0.0 && d < 0.1 * (b - a) && h > 0.0) {
            return Err(Error::argument(format!(
                "lame: need 0 < a < b < c, 0 <= delta < 0.1 (b - a) and h > 0 \
                 (got a = {a}, b = {b}, c = {c}, delta = {d}, h = {h})"
            )));
        }
        let b1 = b + d;
        let steps = |len: f64| ((len / h).ceil() as usize).max(1);
        let n_theta = 2 * steps(0.5 * FRAC_PI_2 * b);
        let thetas: Vec<f64> = (0..=n_theta)
            .map(|j| FRAC_PI_2 * j as f64 / n_theta as f64)
            .collect();
        let radii = |r0: f64, r1: f64| -> Vec<f64> {
            let n = steps(r1 - r0);
            (0..=n)
                .map(|i| {
                    if i == n {
                        r1
                    } else {
                        r0 + (r1 - r0) * i as f64 / n as f64
                    }
                })
                .collect()
        };
        // Exact zeros on the symmetry lines (cos(π/2) is 6e-17 in floating
        // point), so that the rollers act along the lines' normals.
        let polar = |r: f64, t: f64| {
            if t == 0.0 {
                [r, 0.0]
            } else if t == FRAC_PI_2 {
                [0.0, r]
            } else {
                [r * t.cos(), r * t.sin()]
            }
        };
        let mut mb = MeshBuilder::new();
        // Grid columns run clockwise from the y axis (s = π/2 − θ), rows
        // outwards: (s, r) ↦ polar(r, π/2 − s) is counter-clockwise on
        // every cell. Each cell is split into four triangles by its centre
        // (criss-cross): the mesh is then mirror-symmetric about every grid
        // line, so the quarter is the restriction of a ring meshed
        // symmetrically about both axes (the rollers are exact symmetry
        // conditions of the discrete ring) and every surface node sees the
        // same triangles. Measured at h = b/16 with two triangles per cell:
        // diagonals all one way make a chiral mesh whose discrete ring
        // twists, which the rollers resist (5.5 % errors in the nodal
        // pressure at the symmetry lines); diagonals mirrored at θ = π/4
        // leave nodes where the pattern turns (+5.5 %, −4.6 % there).
        let ss: Vec<f64> = thetas.iter().map(|t| FRAC_PI_2 - t).rev().collect();
        let map = |s: f64, r: f64| polar(r, FRAC_PI_2 - s);
        let inner = criss_cross(&mut mb, &ss, &radii(a, b1), map, 1);
        let n_inner_triangles = mb.triangles.len();
        let outer = criss_cross(&mut mb, &ss, &radii(b, c), map, 2);
        let inner_surface = inner[inner.len() - 1].clone();
        let outer_surface = outer[0].clone();
        let (on_inner, on_outer): (BTreeSet<usize>, BTreeSet<usize>) = (
            inner_surface.iter().copied().collect(),
            outer_surface.iter().copied().collect(),
        );
        let rows = |r: &[usize]| r.iter().copied().collect::<BTreeSet<usize>>();
        let (edges, tags) = tagged(
            mb.boundary_edges(),
            [
                (&on_inner, TAG_INNER_RING),
                (&on_outer, TAG_OUTER_RING),
                (&rows(&inner[0]), TAG_BORE),
                (&rows(&outer[outer.len() - 1]), TAG_RIM),
            ],
        );
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        self.declare_circles(&mut model)?;
        model.set_material(
            1,
            Material::new(self.e_inner, self.nu_inner, self.plane, "inner ring")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_outer, self.nu_outer, self.plane, "outer ring")?,
        )?;
        // Rollers: u = 0 on the column θ = π/2 (s = 0), v = 0 on the
        // column θ = 0.
        for grid in [&inner, &outer] {
            for row in grid.iter() {
                model.fix(row[0], Component::X, 0.0)?;
                model.fix(row[row.len() - 1], Component::Y, 0.0)?;
            }
        }
        model.add_contact_pair(TAG_INNER_RING, TAG_OUTER_RING)?;
        Ok(LameScene {
            model,
            inner_surface,
            outer_surface,
            n_inner_triangles,
        })
    }
}

/// The boundary edges with both ends in one of `sets`, with its tag.
fn tagged(
    boundary: Vec<[usize; 2]>,
    sets: [(&BTreeSet<usize>, i32); 4],
) -> (Vec<[usize; 2]>, Vec<i32>) {
    boundary
        .into_iter()
        .filter_map(|e| {
            let both = |s: &BTreeSet<usize>| s.contains(&e[0]) && s.contains(&e[1]);
            sets.iter().find(|(s, _)| both(s)).map(|&(_, tag)| (e, tag))
        })
        .unzip()
}

impl Lame {
    /// Declares the four surfaces' circles: an adaptive solve refines
    /// onto them.
    fn declare_circles(&self, model: &mut Model) -> Result<()> {
        let (a, b, c) = (self.inner_radius, self.radius, self.outer_radius);
        let b1 = b + self.interference;
        for (tag, radius) in [
            (TAG_INNER_RING, b1),
            (TAG_OUTER_RING, b),
            (TAG_BORE, a),
            (TAG_RIM, c),
        ] {
            model.set_curve(
                tag,
                Curve::Circle {
                    center: [0.0, 0.0],
                    radius,
                },
            )?;
        }
        Ok(())
    }
}

/// Adds the grid xs × ys mapped by `map`, each cell split into four
/// triangles by a node at the mapped centre of the cell (counter-clockwise
/// when `map` is), and returns the grid's nodes by row (`rows[j][i]` at
/// `map(xs[i], ys[j])`). The four triangles of a cell are pushed one after
/// the other.
pub(crate) fn criss_cross(
    mb: &mut MeshBuilder,
    xs: &[f64],
    ys: &[f64],
    map: impl Fn(f64, f64) -> [f64; 2],
    body: i32,
) -> Vec<Vec<usize>> {
    let rows: Vec<Vec<usize>> = ys
        .iter()
        .map(|&y| xs.iter().map(|&x| mb.add_node(map(x, y))).collect())
        .collect();
    for j in 0..ys.len() - 1 {
        for i in 0..xs.len() - 1 {
            let centre = mb.add_node(map(0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1])));
            let ring = [
                rows[j][i],
                rows[j][i + 1],
                rows[j + 1][i + 1],
                rows[j + 1][i],
            ];
            for k in 0..4 {
                mb.triangles.push([ring[k], ring[(k + 1) % 4], centre]);
                mb.bodies.push(body);
            }
        }
    }
    rows
}

impl LameScene {
    /// The energy norm of the last solve's error against the closed form,
    /// (Σ over the rings ∫ (ε − ε_h)ᵀ D (ε − ε_h) dA)^½, on whatever mesh
    /// the model holds (refined ones included).
    pub fn energy_error(&self, lame: &Lame) -> Result<f64> {
        let exact = lame.exact();
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let uh: Vec<f64> = self.model.displacements()?.concat();
        let mut sum = 0.0;
        for (body, ring) in [(1, exact.inner), (2, exact.outer)] {
            let d = (self.model.material(body))
                .ok_or_else(|| Error::state(format!("no material for body {body}")))?
                .d_matrix();
            let e = energy_error_of_body(mesh, &uh, body, &d, |p| ring.gradient(p));
            sum += e * e;
        }
        Ok(sum.sqrt())
    }

    /// Solves and measures.
    pub fn solve(&mut self, lame: &Lame, options: &ContactOptions) -> Result<LameResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(lame, report)
    }

    /// Measures the last solve against the closed form.
    pub fn measure(&self, lame: &Lame, report: ContactReport) -> Result<LameResult> {
        let exact = lame.exact();
        let p = exact.pressure;
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let x = mesh.nodes();
        let polar = |v: usize| (x[v][0].hypot(x[v][1]), x[v][1].atan2(x[v][0]));
        let force = self.model.contact_forces()?;
        // The nodal pressure: radial contact force over the node's share of
        // the arc, r Δθ (the closed form's force per radian is p r). The
        // contact pushes the outer ring outwards and the inner ring inwards.
        let nodal_error = |surface: &[usize], sign: f64, exact: f64| -> f64 {
            let n = surface.len();
            (0..n)
                .map(|k| {
                    let v = surface[k];
                    let (r, t) = polar(v);
                    let t_lo = polar(surface[k.saturating_sub(1)]).1;
                    let t_hi = polar(surface[(k + 1).min(n - 1)]).1;
                    let share = 0.5 * r * (t_hi - t_lo).abs();
                    let f_r = (force[v][0] * t.cos() + force[v][1] * t.sin()) * sign;
                    (f_r / share - exact).abs()
                })
                .fold(0.0, f64::max)
        };
        let pressure_error = nodal_error(&self.inner_surface, -1.0, exact.inner.p_out)
            .max(nodal_error(&self.outer_surface, 1.0, p))
            / p;
        // Stresses per grid cell: the area-weighted mean of its four
        // triangles (pushed one after the other), at the cell's centre node.
        // The mean gradient of a cell is ∮ u_h n ds over its boundary, a
        // function of its corner values alone, which is exact for quadratic
        // fields at the centre of a parallelogram; a single triangle's is
        // off by O(h) at its centroid (the stress varies as 1/r² across the
        // ring: measured at h = b/64, 6.5 % of p).
        let stresses = self.model.element_stresses()?;
        let triangles = mesh.triangles();
        let (mut hoop, mut radial) = (0.0f64, 0.0f64);
        let (mut bore, mut bore_exact) = (f64::NAN, f64::NAN);
        let mut bore_layer: Vec<(f64, f64)> = Vec::new();
        let area = |tri: &[usize; 3]| {
            let [p0, p1, p2] = [x[tri[0]], x[tri[1]], x[tri[2]]];
            0.5 * ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])).abs()
        };
        for cell in 0..triangles.len() / 4 {
            let t0 = 4 * cell;
            let ring = if t0 < self.n_inner_triangles {
                &exact.inner
            } else {
                &exact.outer
            };
            let centre = triangles[t0]
                .iter()
                .copied()
                .find(|v| (t0 + 1..t0 + 4).all(|t| triangles[t].contains(v)))
                .ok_or_else(|| Error::state("lame: a cell's four triangles share no centre"))?;
            let (r, t) = polar(centre);
            let mut sig = [0.0; 3];
            let mut total = 0.0;
            for tri in t0..t0 + 4 {
                let w = area(&triangles[tri]);
                total += w;
                for (k, s) in sig.iter_mut().enumerate() {
                    *s += w * stresses[tri][k];
                }
            }
            sig.iter_mut().for_each(|s| *s /= total);
            let (cs, sn) = (t.cos(), t.sin());
            let s_rr = sig[0] * cs * cs + sig[1] * sn * sn + 2.0 * sig[2] * sn * cs;
            let s_tt = sig[0] * sn * sn + sig[1] * cs * cs - 2.0 * sig[2] * sn * cs;
            hoop = hoop.max((s_tt - ring.sigma_tt(r)).abs());
            radial = radial.max((s_rr - ring.sigma_rr(r)).abs());
            let on_bore = triangles[t0].iter().any(|v| self.outer_surface.contains(v));
            if t0 >= self.n_inner_triangles && on_bore {
                bore_layer.push((r, s_tt));
            }
        }
        // The bore's hoop stress (the outer ring's largest): the mean over
        // the cells along the bore, against the closed form at their mean
        // radius (moving it to r = b would need the gradient, i.e. the
        // answer).
        if !bore_layer.is_empty() {
            let n = bore_layer.len() as f64;
            let (r_mean, s_mean) = bore_layer
                .iter()
                .fold((0.0, 0.0), |m, v| (m.0 + v.0 / n, m.1 + v.1 / n));
            bore = s_mean;
            bore_exact = exact.outer.sigma_tt(r_mean);
        }
        Ok(LameResult {
            exact,
            pressure_error,
            hoop_error: hoop / p,
            radial_error: radial / p,
            bore_hoop_error: (bore - bore_exact).abs() / bore_exact.abs(),
            report,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_rings_in_plane_stress_give_the_textbook_fit_pressure() {
        // δ → 0 (1e-9 b): the b/b₁ corrections vanish to 1e-9.
        let (e, nu) = (2e11, 0.3);
        let lame = Lame {
            e_inner: e,
            nu_inner: nu,
            e_outer: e,
            nu_outer: nu,
            plane: PlaneMode::Stress,
            interference: 1e-9,
            ..Default::default()
        };
        let (a, b, c, d) = (0.5f64, 1.0f64, 1.5f64, 1e-9);
        let textbook =
            e * d / b * (b * b - a * a) * (c * c - b * b) / (2.0 * b * b * (c * c - a * a));
        let s = lame.exact();
        assert!(((s.pressure - textbook) / textbook).abs() < 1e-8);
        // The closed form's own boundary conditions.
        assert!((s.outer.sigma_rr(b) + s.pressure).abs() < 1e-12 * s.pressure);
        assert!(s.outer.sigma_rr(c).abs() < 1e-12 * s.pressure);
        assert!(s.inner.sigma_rr(a).abs() < 1e-12 * s.pressure);
        // The surfaces meet: b₁ + u¹(b₁) = b + u²(b), written without the
        // radii (which would leave only 1e-7 of δ = 1e-9 to round-off).
        let gap = s.outer.u_r(b) - s.inner.u_r(b + d) - d;
        assert!(gap.abs() < 1e-12 * d);
    }
}
