//! Two full rings in a shrink fit (Lamé's inner ring a ≤ r ≤ b + δ in the
//! bore b ≤ r ≤ c of the outer one, plane strain), each meshed around by
//! its own number of cells with every interface node on its circle: the
//! interface's nodes match when the counts do, and not when they differ
//! (2:3, the coarser ring inside, is the case a user trying a press fit
//! met). The interface is cut into `pieces` contact pairs (1: one closed
//! loop). Each ring is held by three rigid-motion constraints on its far
//! surface (v at θ = 0 and π, u at θ = π/2), which carry nothing in the
//! exact solution: the rings are self-equilibrated.
//!
//! The closed form for circles is [`crate::scenes::lame::Lame`]'s; the
//! meshed rings are polygons, whose mean radial overlap differs from δ by
//! O(h²/b) ([`ShrinkFit::polygon_factor`]): Lamé's pressure of that
//! overlap is the one a discretisation of the meshed geometry converges to
//! at a given mesh.

use std::f64::consts::PI;

use crate::error::Result;
use crate::fem::material::{Material, PlaneMode};
use crate::model::{Component, Model};
use crate::studies::meshgen::MeshBuilder;
use crate::studies::scenes::lame::{Lame, LameSolution};

/// Tag of piece k of the inner ring's surface: `TAG_INNER + k`.
pub const TAG_INNER: i32 = 11;
/// Tag of piece k of the outer ring's bore: `TAG_OUTER + k`.
pub const TAG_OUTER: i32 = 21;

/// Parameters of the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShrinkFit {
    /// Cells around the inner ring.
    pub inner_cells: usize,
    /// Cells around the outer ring.
    pub outer_cells: usize,
    /// Contact pairs the interface is cut into (1: one closed loop).
    pub pieces: usize,
    /// The radial interference δ.
    pub interference: f64,
}

impl Default for ShrinkFit {
    fn default() -> Self {
        ShrinkFit {
            inner_cells: 128,
            outer_cells: 192,
            pieces: 2,
            interference: 1e-3,
        }
    }
}

/// The built scene.
pub struct ShrinkFitScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// The inner ring's surface nodes, by angle.
    pub inner: Vec<usize>,
    /// The outer ring's bore nodes, by angle.
    pub outer: Vec<usize>,
    /// The constrained nodes.
    pub supports: Vec<usize>,
    /// The closed form for circles.
    pub exact: LameSolution,
}

impl ShrinkFit {
    /// Lamé's geometry and materials with this interference.
    pub fn lame(&self) -> Lame {
        Lame {
            interference: self.interference,
            ..Lame::default()
        }
    }

    /// The meshed polygons' mean radial overlap over δ: Lamé's pressure of
    /// the meshed geometry is this times the circles' (the problem is
    /// linear in the overlap).
    pub fn polygon_factor(&self) -> f64 {
        let l = self.lame();
        let (b, b1) = (l.radius, l.radius + self.interference);
        let overlap = b1 * polygon_mean(self.inner_cells) - b * polygon_mean(self.outer_cells);
        overlap / self.interference
    }

    /// Builds the mesh, materials, constraints and contact pairs.
    pub fn build(&self) -> Result<ShrinkFitScene> {
        let l = self.lame();
        let (a, b, c) = (l.inner_radius, l.radius, l.outer_radius);
        let b1 = b + self.interference;
        let (n_in, n_out) = (self.inner_cells, self.outer_cells);
        let mut mb = MeshBuilder::new();
        let gi = ring(&mut mb, &radii(a, b1, 2.0 * PI * b / n_in as f64), n_in, 1);
        let go = ring(&mut mb, &radii(b, c, 2.0 * PI * b / n_out as f64), n_out, 2);
        let (inner, outer) = (gi[gi.len() - 1].clone(), go[0].clone());
        let (mut edges, mut tags) = (Vec::new(), Vec::new());
        for (row, n, base) in [(&inner, n_in, TAG_INNER), (&outer, n_out, TAG_OUTER)] {
            for j in 0..n {
                edges.push([row[j], row[(j + 1) % n]]);
                tags.push(base + (j * self.pieces / n) as i32);
            }
        }
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(1, Material::new(l.e_inner, l.nu_inner, plane, "inner")?)?;
        model.set_material(2, Material::new(l.e_outer, l.nu_outer, plane, "outer")?)?;
        let mut supports = Vec::new();
        for (row, n) in [(&gi[0], n_in), (&go[go.len() - 1], n_out)] {
            model.fix(row[0], Component::Y, 0.0)?;
            model.fix(row[n / 2], Component::Y, 0.0)?;
            model.fix(row[n / 4], Component::X, 0.0)?;
            supports.extend([row[0], row[n / 2], row[n / 4]]);
        }
        for k in 0..self.pieces as i32 {
            model.add_contact_pair(TAG_INNER + k, TAG_OUTER + k)?;
        }
        Ok(ShrinkFitScene {
            model,
            inner,
            outer,
            supports,
            exact: l.exact(),
        })
    }
}

/// The mean radius over the angle of the closed polygon through `points`
/// (by angle around the origin): Σ over its chords of ∫ r dθ, over 2π. Of
/// two rings' facing polygons, the difference is their mean radial
/// overlap, whose Lamé pressure a discretisation of the meshed rings
/// converges to.
pub fn polygon_mean_radius(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    let mut total = 0.0;
    for k in 0..n {
        let (p, q) = (points[k], points[(k + 1) % n]);
        let e = [q[0] - p[0], q[1] - p[1]];
        let length = e[0].hypot(e[1]);
        // The chord's distance from the origin, and where p and q lie
        // along it from the foot: ∫ r dθ = ∫ d sec φ dφ, φ = atan(t/d).
        let d = (p[0] * q[1] - p[1] * q[0]).abs() / length;
        let along = |x: [f64; 2]| (x[0] * e[0] + x[1] * e[1]) / length;
        let primitive = |t: f64| {
            let phi = (t / d).atan();
            d * (1.0 / phi.cos() + phi.tan()).ln()
        };
        total += primitive(along(q)) - primitive(along(p));
    }
    total / (2.0 * PI)
}

/// Mean radius over the angle of a regular n-gon inscribed in the unit
/// circle: ∫ r dθ / 2π over its chords, r = cos(π/n)/cos φ on each.
pub fn polygon_mean(n: usize) -> f64 {
    let al = PI / n as f64;
    al.cos() * (1.0 / al.cos() + al.tan()).ln() / al
}

/// A point at radius `r` and angle 2πj/n, exact on the axes.
fn polar(r: f64, j: usize, n: usize) -> [f64; 2] {
    if (4 * j) % n == 0 {
        return match (4 * j / n) % 4 {
            0 => [r, 0.0],
            1 => [0.0, r],
            2 => [-r, 0.0],
            _ => [0.0, -r],
        };
    }
    let t = 2.0 * PI * j as f64 / n as f64;
    [r * t.cos(), r * t.sin()]
}

/// A full ring meshed with `n` cells around and the rows `radii`, each
/// cell cut in four by its centre (mirror-symmetric: the rigid-motion
/// constraints are then symmetry conditions of the discrete ring); its
/// nodes `rows[i][j]` at radius i, angle j.
pub fn ring(mb: &mut MeshBuilder, radii: &[f64], n: usize, body: i32) -> Vec<Vec<usize>> {
    let rows: Vec<Vec<usize>> = radii
        .iter()
        .map(|&r| (0..n).map(|j| mb.add_node(polar(r, j, n))).collect())
        .collect();
    for i in 0..radii.len() - 1 {
        for j in 0..n {
            let jn = (j + 1) % n;
            let rm = 0.5 * (radii[i] + radii[i + 1]);
            let t = 2.0 * PI * (j as f64 + 0.5) / n as f64;
            let centre = mb.add_node([rm * t.cos(), rm * t.sin()]);
            let q = [rows[i][j], rows[i + 1][j], rows[i + 1][jn], rows[i][jn]];
            for k in 0..4 {
                mb.triangles.push([q[k], q[(k + 1) % 4], centre]);
                mb.bodies.push(body);
            }
        }
    }
    rows
}

/// Rows from r0 to r1 at about `h` apart.
pub fn radii(r0: f64, r1: f64, h: f64) -> Vec<f64> {
    let m = ((r1 - r0) / h).ceil().max(1.0) as usize;
    (0..=m)
        .map(|i| match i == m {
            true => r1,
            false => r0 + (r1 - r0) * i as f64 / m as f64,
        })
        .collect()
}
