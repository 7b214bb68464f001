//! Hertz contact in plane strain: an elastic cylinder (radius R) pressed on
//! an elastic block by a line load P. Half model (u_x = 0 on x = 0). The
//! cylinder is represented by the part of it near the contact: the region
//! 0 ≤ x ≤ 0.8R between its circular bottom y = R − √(R² − x²) and its
//! centre line y = R, loaded by a uniform pressure on that line (statically
//! equivalent, far from the contact zone). The block is [0, 2R] × [−2R, 0],
//! supported (v = 0) at its bottom. Both are meshed by the built-in
//! structured triangulator, graded from the contact point outwards; the
//! interface nodes of the two bodies do not face each other away from x = 0
//! (the cylinder curves up), so B is the strip triangulation.
//!
//! Analytic values (half-spaces with the cylinder's curvature):
//! a = √(4PR / (πE*)), p₀ = 2P / (πa), 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.
//! With a = 0.02R (the default) the bodies span 40a (cylinder part) and
//! 100a (block), and a/R is small: the half-space values apply to ~0.1 %.

use std::collections::{BTreeMap, BTreeSet};

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::curve::Curve;
use crate::fem::element::{Jmin, Tempering, TriGeometry, elasticity_stiffness};
use crate::fem::material::{Material, PlaneMode};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder, graded};

/// Tag of the block's top edge (contact side a).
pub const TAG_BLOCK_TOP: i32 = 2;
/// Tag of the cylinder's curved edge (contact side b).
pub const TAG_CYLINDER: i32 = 3;
/// Tag of the cylinder's loaded centre line.
pub const TAG_LOAD: i32 = 4;
/// Tag of the block's supported bottom.
pub const TAG_SUPPORT: i32 = 1;

/// Parameters of the Hertz scene. [`Default`]: R = 1, a = 0.02 R (so that
/// the bodies span 40a and 100a), equal steel-like moduli, h = a/16 at the
/// contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    /// Cylinder radius R.
    pub radius: f64,
    /// The analytic contact half-width a the load is chosen for.
    pub half_width: f64,
    /// Young's modulus of the block (body 1).
    pub e_block: f64,
    /// Poisson ratio of the block.
    pub nu_block: f64,
    /// Young's modulus of the cylinder (body 2).
    pub e_cylinder: f64,
    /// Poisson ratio of the cylinder.
    pub nu_cylinder: f64,
    /// Element size at the contact (over 1.5a from the contact point).
    pub mesh_size: f64,
    /// The cylinder's element size at the contact over the block's (1: the
    /// same x positions on both sides at x = 0; else non-matching).
    pub cylinder_mesh_ratio: f64,
    /// Growth of the element size away from the contact region.
    pub grading: f64,
}

impl Default for Hertz {
    fn default() -> Self {
        Hertz {
            radius: 1.0,
            half_width: 0.02,
            e_block: 2e11,
            nu_block: 0.3,
            e_cylinder: 2e11,
            nu_cylinder: 0.3,
            mesh_size: 0.02 / 16.0,
            cylinder_mesh_ratio: 1.0,
            grading: 1.15,
        }
    }
}

/// The built Hertz scene.
pub struct HertzScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Block nodes on its top edge as built, sorted by x
    /// ([`HertzScene::measure`] reads them from the model's current mesh).
    pub block_top: Vec<usize>,
    /// Nodes of the block (the first ones); the rest belong to the cylinder.
    pub n_block_nodes: usize,
    /// The line load P (full cylinder, per unit thickness).
    pub load: f64,
}

/// Measured and analytic Hertz quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct HertzResult {
    /// Analytic half-width a.
    pub a_exact: f64,
    /// Analytic peak pressure p₀.
    pub p0_exact: f64,
    /// Contact half-width: where the nodal pressure ends (p² extrapolated
    /// linearly to zero from the last two loaded nodes of the block, at
    /// most to the first unloaded node; when the last is not the smaller,
    /// halfway to the first unloaded node).
    pub a: f64,
    /// Peak pressure: the block's nodal contact force at x = 0 over its
    /// tributary length.
    pub p0: f64,
    /// a and p₀ from a least-squares fit of p² = p₀²(1 − x²/a²) to the
    /// nodal pressures of the inner 80 % of the contact zone.
    pub a_fit: f64,
    /// See `a_fit`.
    pub p0_fit: f64,
    /// Nodal pressures (x, p) on the block's top edge.
    pub pressure: Vec<(f64, f64)>,
    /// The interface traction read from both sides
    /// (`contact::traction::interface_pressures`) at the block's top nodes
    /// that are nodes of B, (x, p), sorted by x.
    pub interface_pressure: Vec<(f64, f64)>,
    /// Its value on the axis.
    pub p0_interface: f64,
    /// The contact report.
    pub report: ContactReport,
}

impl Hertz {
    /// E* of the pair.
    pub fn e_star(&self) -> f64 {
        let inv = (1.0 - self.nu_block * self.nu_block) / self.e_block
            + (1.0 - self.nu_cylinder * self.nu_cylinder) / self.e_cylinder;
        1.0 / inv
    }

    /// The line load P giving the half-width a: P = π a² E* / (4R).
    pub fn load(&self) -> f64 {
        std::f64::consts::PI * self.half_width * self.half_width * self.e_star()
            / (4.0 * self.radius)
    }

    /// Builds the mesh, materials, supports, load and contact pair.
    pub fn build(&self) -> Result<HertzScene> {
        let (r, a, h) = (self.radius, self.half_width, self.mesh_size);
        if !(r > 0.0 && a > 0.0 && a < 0.3 * r && h > 0.0 && h <= a) {
            return Err(Error::argument(format!(
                "hertz: need R > 0, 0 < a < 0.3R and 0 < h <= a (got R = {r}, a = {a}, h = {h})"
            )));
        }
        if !(self.cylinder_mesh_ratio > 0.0 && self.grading >= 1.0 && self.grading < 2.0) {
            return Err(Error::argument(format!(
                "hertz: need a cylinder mesh ratio > 0 and a grading in [1, 2) (got {}, {})",
                self.cylinder_mesh_ratio, self.grading
            )));
        }
        let fine = 1.5 * a;
        let (w_block, w_cyl) = (2.0 * r, 0.8 * r);
        let xs = graded(0.0, w_block, h, fine, self.grading)?;
        let depth: Vec<f64> = graded(0.0, 2.0 * r, h, fine, self.grading)?
            .into_iter()
            .rev()
            .map(|d| -d)
            .collect();
        let hc = h * self.cylinder_mesh_ratio;
        let xs_cyl = graded(0.0, w_cyl, hc, fine, self.grading)?;
        // Heights above the circle, as fractions of the column: graded from
        // the contact (t = 0) to the centre line (t = 1).
        let ts: Vec<f64> = graded(0.0, r, hc, fine, self.grading)?
            .into_iter()
            .map(|y| y / r)
            .collect();
        let bottom = |x: f64| r - (r * r - x * x).sqrt();
        let mut b = MeshBuilder::new();
        let block = b.add_grid(&xs, &depth, 1, Diagonal::Forward);
        let n_block_nodes = b.nodes.len();
        let cylinder = b.add_mapped_grid(
            &xs_cyl,
            &ts,
            |x, t| [x, bottom(x) + t * (r - bottom(x))],
            2,
            Diagonal::Forward,
        );
        let row_set = |row: &[usize]| row.iter().copied().collect::<BTreeSet<_>>();
        let (curve, centre) = (
            row_set(&cylinder[0]),
            row_set(&cylinder[cylinder.len() - 1]),
        );
        let (top, base) = (row_set(&block[block.len() - 1]), row_set(&block[0]));
        let mut edges = Vec::new();
        let mut tags = Vec::new();
        for e in b.boundary_edges() {
            let both = |set: &BTreeSet<usize>| set.contains(&e[0]) && set.contains(&e[1]);
            let tag = if both(&top) {
                TAG_BLOCK_TOP
            } else if both(&base) {
                TAG_SUPPORT
            } else if both(&centre) {
                TAG_LOAD
            } else if both(&curve) {
                TAG_CYLINDER
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let block_top = block[block.len() - 1].clone();
        let axis: Vec<usize> = (0..b.nodes.len())
            .filter(|&v| b.nodes[v][0] == 0.0)
            .collect();
        let load = self.load();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(
            1,
            Material::new(self.e_block, self.nu_block, plane, "block")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_cylinder, self.nu_cylinder, plane, "cylinder")?,
        )?;
        model.set_tempering(Tempering::Auto)?;
        for v in axis {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        // Half the line load on the half model's centre line.
        model.add_pressure(TAG_LOAD, 0.5 * load / w_cyl)?;
        model.add_contact_pair(TAG_BLOCK_TOP, TAG_CYLINDER)?;
        // The cylinder's surface: an adaptive solve refines onto it.
        model.set_curve(
            TAG_CYLINDER,
            Curve::Circle {
                center: [0.0, r],
                radius: r,
            },
        )?;
        Ok(HertzScene {
            model,
            block_top,
            n_block_nodes,
            load,
        })
    }
}

impl HertzResult {
    /// The largest error of nodal pressures `p` ((x, p) pairs) against
    /// p₀√(1 − x²/a²) over the inner 80 % of the contact, over p₀.
    pub fn inner_error(&self, p: &[(f64, f64)]) -> f64 {
        let a = self.a_exact;
        p.iter()
            .filter(|(x, _)| x.abs() <= 0.8 * a)
            .map(|(x, q)| {
                (q - self.p0_exact * (1.0 - x * x / (a * a)).sqrt()).abs() / self.p0_exact
            })
            .fold(0.0, f64::max)
    }
}

impl HertzScene {
    /// Solves and measures.
    pub fn solve(&mut self, hertz: &Hertz, options: &ContactOptions) -> Result<HertzResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(hertz, report)
    }

    /// Reads a, p₀ from the last solve: nodal contact forces of the block
    /// (its internal forces at the top edge, where no other load acts).
    pub fn measure(&self, hertz: &Hertz, report: ContactReport) -> Result<HertzResult> {
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let u = self.model.displacements()?;
        // Read from the model's mesh, which an adaptive solve refines.
        let block_top = super::nodes_by_x(mesh, TAG_BLOCK_TOP);
        let on_top: BTreeMap<usize, usize> =
            block_top.iter().enumerate().map(|(k, &v)| (v, k)).collect();
        let mut force = vec![0.0; block_top.len()];
        let material = self
            .model
            .material(1)
            .ok_or_else(|| Error::state("no block material"))?;
        let d = material.d_matrix();
        for (tri, &body) in mesh.triangles().iter().zip(mesh.body_of()) {
            if body != 1 || !tri.iter().any(|v| on_top.contains_key(v)) {
                continue;
            }
            let ke = elasticity_stiffness(&TriGeometry::new(&mesh.corners(tri)), &d, Jmin::Off)?;
            for (i, v) in tri.iter().enumerate() {
                if let Some(&k) = on_top.get(v) {
                    let row = &ke[2 * i + 1];
                    force[k] += (0..6).map(|b| row[b] * u[tri[b / 2]][b % 2]).sum::<f64>();
                }
            }
        }
        let x: Vec<f64> = block_top.iter().map(|&v| mesh.nodes()[v][0]).collect();
        let pressure: Vec<(f64, f64)> = (0..x.len())
            .map(|k| {
                let left = if k > 0 { x[k] - x[k - 1] } else { 0.0 };
                let right = if k + 1 < x.len() {
                    x[k + 1] - x[k]
                } else {
                    0.0
                };
                // The block's internal force K u at a top node equals the
                // contact force on it, downwards in compression.
                (x[k], -force[k] / (0.5 * (left + right)))
            })
            .collect();
        let p0 = pressure.first().map_or(0.0, |p| p.1);
        // Where the nodal pressure ends: p² is linear in x near the edge of
        // contact (p ∝ √(a² − x²)), so extrapolate it from the last two
        // loaded nodes to zero.
        // (Unloaded nodes carry round-off, ~1e-14 of p₀.)
        let floor = 1e-9 * pressure.iter().fold(0.0f64, |m, p| m.max(p.1));
        let last = pressure
            .iter()
            .position(|&(_, p)| p <= floor)
            .unwrap_or(pressure.len());
        let a = if last >= 2 {
            let ((x1, p1), (x2, p2)) = (pressure[last - 2], pressure[last - 1]);
            // The edge lies before the first unloaded node, x3. Lumpy
            // pressures (a non-matching interface) need not fall towards
            // it: then no extrapolation, halfway to x3.
            let x3 = pressure.get(last).map_or(f64::INFINITY, |p| p.0);
            if p1 > p2 {
                (x2 + p2 * p2 * (x2 - x1) / (p1 * p1 - p2 * p2)).min(x3)
            } else if x3.is_finite() {
                0.5 * (x2 + x3)
            } else {
                x2
            }
        } else {
            f64::NAN
        };
        // p² = A − B x² over the inner 80 % of the contact zone.
        let pts: Vec<(f64, f64)> = pressure
            .iter()
            .filter(|(xk, pk)| *pk > 0.0 && *xk <= 0.8 * a)
            .map(|(xk, pk)| (xk * xk, pk * pk))
            .collect();
        let (a_fit, p0_fit) = if pts.len() >= 3 {
            let n = pts.len() as f64;
            let (sx, sy) = pts.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
            let (mx, my) = (sx / n, sy / n);
            let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
            let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
            let slope = sxy / sxx;
            let intercept = my - slope * mx;
            ((intercept / -slope).sqrt(), intercept.sqrt())
        } else {
            (f64::NAN, f64::NAN)
        };
        // The library's nodal pressures: under the mortar weighting the
        // slave's −κG_i/m_i, read at the master's nodes along the slave;
        // under the strip the interface traction of B's nodes.
        let traction: BTreeMap<usize, f64> = self
            .model
            .contact_nodal_pressures()?
            .into_iter()
            .enumerate()
            .collect();
        let interface_pressure: Vec<(f64, f64)> = block_top
            .iter()
            .filter_map(|v| Some((mesh.nodes()[*v][0], *traction.get(v)?)))
            .collect();
        let p0_interface = interface_pressure.first().map_or(0.0, |p| p.1);
        let load = self.load;
        let a_exact = hertz.half_width;
        Ok(HertzResult {
            a_exact,
            p0_exact: 2.0 * load / (std::f64::consts::PI * a_exact),
            a,
            p0,
            a_fit,
            p0_fit,
            pressure,
            interface_pressure,
            p0_interface,
            report,
        })
    }
}
