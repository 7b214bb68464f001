//! The contact patch test: two blocks [0, L] × [−H1, 0] and [0, L] × [0, H2]
//! pressed together by a uniform pressure p on the whole top of the upper
//! one, the lower one on rollers (v = 0) along its whole bottom, u_x = 0 on
//! the line x = 0 in both. The exact solution has a uniform stress
//! σ_yy = −p, σ_xx = τ_xy = 0 in both blocks whatever their materials, and
//! a uniform contact pressure p: a contact discretisation passes the patch
//! test when it reproduces it.
//!
//! The interface is non-matching when the blocks are meshed with different
//! numbers of cells along x (`ratio`, the upper cell width over the lower);
//! `jitter` moves every interior grid column of each block by a
//! pseudo-random fraction of its width (a reproducible sequence from
//! `seed`), so that no two interface nodes line up by accident.

use crate::contact::ContactOptions;
use crate::contact::mesh::Nodes;
use crate::contact::traction::{interface_tractions, max_overlap, nodal_tractions};
use crate::error::{Error, Result};
use crate::fem::element::{Tempering, TriGeometry};
use crate::fem::material::{Material, PlaneMode, Section};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder};

/// Tag of the lower block's bottom (rollers).
pub const TAG_BOTTOM: i32 = 1;
/// Tag of the lower block's top (contact side a).
pub const TAG_CONTACT_LOWER: i32 = 2;
/// Tag of the upper block's bottom (contact side b).
pub const TAG_CONTACT_UPPER: i32 = 3;
/// Tag of the upper block's top (loaded).
pub const TAG_LOAD: i32 = 4;

/// Parameters of the patch test. [`Default`]: the seed's materials (the
/// upper block 10× stiffer), L = 1, H1 = H2 = 0.25, p = 1e7, h = 1/16,
/// matching meshes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchTest {
    /// Young's modulus of the lower block.
    pub e_lower: f64,
    /// Poisson ratio of the lower block.
    pub nu_lower: f64,
    /// Young's modulus of the upper block.
    pub e_upper: f64,
    /// Poisson ratio of the upper block.
    pub nu_upper: f64,
    /// Length L of both blocks.
    pub length: f64,
    /// Height of the lower block.
    pub h1: f64,
    /// Height of the upper block.
    pub h2: f64,
    /// The pressure.
    pub p: f64,
    /// Cell width of the lower block (its cells are about square).
    pub mesh_size: f64,
    /// Cell width of the upper block over the lower one's (1: matching).
    /// The upper block gets round(L / (ratio · h)) cells across.
    pub ratio: f64,
    /// Largest move of an interior grid column, as a fraction of the cell
    /// width (0: uniform grids; below 0.5).
    pub jitter: f64,
    /// Seed of the jitter's pseudo-random sequence.
    pub seed: u64,
    /// The upper block's offset above the lower one: an initial gap (> 0)
    /// that the pressure closes, or an initial overlap (< 0, an
    /// interference) that it pushes out. The exact stress is the same
    /// uniform −p either way (the upper block is free to translate).
    pub gap: f64,
}

impl Default for PatchTest {
    fn default() -> Self {
        PatchTest {
            e_lower: 1e10,
            nu_lower: 0.3,
            e_upper: 1e11,
            nu_upper: 0.3,
            length: 1.0,
            h1: 0.25,
            h2: 0.25,
            p: 1e7,
            mesh_size: 1.0 / 16.0,
            ratio: 1.0,
            jitter: 0.0,
            seed: 1,
            gap: 0.0,
        }
    }
}

/// The stress errors of a solved patch test, relative to p.
#[derive(Debug, Clone, Copy)]
pub struct StressErrors {
    /// The largest element's error |σ − σ_exact| / p.
    pub max: f64,
    /// The area-weighted L2 error / p.
    pub l2: f64,
    /// The centroid of the worst element.
    pub worst_at: [f64; 2],
}

/// The built patch test.
pub struct PatchScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// The lower block's interface nodes, by increasing x.
    pub lower: Vec<usize>,
    /// The upper block's interface nodes, by increasing x.
    pub upper: Vec<usize>,
    /// Cells across the lower and the upper block.
    pub cells: (usize, usize),
}

/// The errors of a patch-test solve, relative to p.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchResult {
    /// Largest stress error over the elements, √(Σ (σ − σ_exact)²) / p.
    pub max_error: f64,
    /// Area-weighted L2 stress error over both blocks, / p.
    pub l2_error: f64,
    /// Centroid of the element with the largest error.
    pub worst_at: [f64; 2],
    /// Smallest and largest contact pressure of an active element of B,
    /// / p.
    pub element_pressure: (f64, f64),
    /// Smallest and largest nodal pressure, / p: the contact force on an
    /// interface node over its tributary length (half its interface
    /// edges), on both sides.
    pub nodal_pressure: (f64, f64),
    /// Elements of B not active at convergence (all should be: the whole
    /// interface is compressed).
    pub released: usize,
    /// The largest interpenetration the contact report gives.
    pub reported_penetration: f64,
    /// The largest actual interpenetration: over the interface nodes of
    /// both sides, how far the node lies beyond the other side's deformed
    /// polyline (interpolated at its x, not extrapolated).
    pub penetration: f64,
    /// Smallest and largest pressure of `contact::traction::nodal_pressures`
    /// over the interface nodes, / p (the library's recovery; the range
    /// above is this harness's own).
    pub traction: (f64, f64),
    /// The same for `contact::traction::interface_pressures` (both sides'
    /// mean).
    pub interface_traction: (f64, f64),
    /// `contact::traction::max_overlap` (the library's measure of the
    /// actual interpenetration).
    pub overlap: f64,
    /// The contact report.
    pub report: ContactReport,
}

/// x-coordinates of `n` cells over [0, l], interior ones moved by up to
/// `jitter` of a cell width (xorshift sequence from `state`).
fn columns(l: f64, n: usize, jitter: f64, state: &mut u64) -> Vec<f64> {
    let w = l / n as f64;
    (0..=n)
        .map(|i| {
            let x = if i == n { l } else { w * i as f64 };
            if i == 0 || i == n || jitter == 0.0 {
                return x;
            }
            *state ^= *state << 13;
            *state ^= *state >> 7;
            *state ^= *state << 17;
            let u = (*state >> 11) as f64 / (1u64 << 53) as f64; // [0, 1)
            x + jitter * w * (2.0 * u - 1.0)
        })
        .collect()
}

/// Rows of a block of height `height` with cells of about `w`.
fn rows(y0: f64, height: f64, w: f64) -> Vec<f64> {
    let n = (height / w).round().max(1.0) as usize;
    (0..=n)
        .map(|j| {
            if j == n {
                y0 + height
            } else {
                y0 + height * j as f64 / n as f64
            }
        })
        .collect()
}

impl PatchTest {
    /// Builds the mesh, materials, supports, load and contact pair.
    pub fn build(&self) -> Result<PatchScene> {
        let (l, h) = (self.length, self.mesh_size);
        if !(l > 0.0 && self.h1 > 0.0 && self.h2 > 0.0 && h > 0.0 && h <= l && self.ratio > 0.0) {
            return Err(Error::argument(format!(
                "patch test: need L, H1, H2 > 0, 0 < h <= L and a ratio > 0 (got L = {l}, h = {h}, ratio = {})",
                self.ratio
            )));
        }
        if !(0.0..0.5).contains(&self.jitter) {
            return Err(Error::argument(format!(
                "patch test: the jitter {} must lie in [0, 0.5)",
                self.jitter
            )));
        }
        let n1 = (l / h).round().max(1.0) as usize;
        let n2 = (l / (h * self.ratio)).round().max(1.0) as usize;
        let mut state = self.seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let xs1 = columns(l, n1, self.jitter, &mut state);
        let xs2 = columns(l, n2, self.jitter, &mut state);
        let ys1 = rows(-self.h1, self.h1, l / n1 as f64);
        let ys2 = rows(self.gap, self.h2, l / n2 as f64);
        let mut b = MeshBuilder::new();
        let lower = b.add_grid(&xs1, &ys1, 1, Diagonal::Forward);
        let n_lower = b.nodes.len();
        let upper = b.add_grid(&xs2, &ys2, 2, Diagonal::Forward);
        let (mut edges, mut tags) = (Vec::new(), Vec::new());
        for e in b.boundary_edges() {
            let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
            let in_lower = e[0] < n_lower;
            let both = |y: f64| p[1] == y && q[1] == y;
            let tag = if in_lower && both(-self.h1) {
                TAG_BOTTOM
            } else if in_lower && both(0.0) {
                TAG_CONTACT_LOWER
            } else if !in_lower && both(self.gap) {
                TAG_CONTACT_UPPER
            } else if !in_lower && both(self.gap + self.h2) {
                TAG_LOAD
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let left: Vec<usize> = (0..b.nodes.len())
            .filter(|&v| b.nodes[v][0] == 0.0)
            .collect();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(
            1,
            Material::new(self.e_lower, self.nu_lower, plane, "lower")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_upper, self.nu_upper, plane, "upper")?,
        )?;
        model.set_tempering(Tempering::Auto)?;
        for v in left {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_BOTTOM, Component::Y, 0.0)?;
        model.add_pressure(TAG_LOAD, self.p)?;
        model.add_contact_pair(TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)?;
        Ok(PatchScene {
            model,
            lower: lower[lower.len() - 1].clone(),
            upper: upper[0].clone(),
            cells: (n1, n2),
        })
    }
}

impl PatchScene {
    /// Solves and measures.
    pub fn solve(&mut self, test: &PatchTest, options: &ContactOptions) -> Result<PatchResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(test, report)
    }

    /// The element stresses' errors of the last solve against the uniform
    /// exact stress σ_yy = −p.
    pub fn stress_errors(&self, test: &PatchTest) -> Result<StressErrors> {
        let p = test.p;
        let model = &self.model;
        let mesh = model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let (mut sum, mut area, mut max) = (0.0, 0.0, 0.0f64);
        let mut worst_at = [0.0; 2];
        for (t, sig) in mesh.triangles().iter().zip(model.element_stresses()?) {
            let c = mesh.corners(t);
            let a = 0.5 * TriGeometry::new(&c).j;
            let e2 = ((sig[1] + p).powi(2) + sig[0].powi(2) + sig[2].powi(2)) / (p * p);
            sum += a * e2;
            area += a;
            if e2.sqrt() > max {
                max = e2.sqrt();
                worst_at = [
                    (c[0][0] + c[1][0] + c[2][0]) / 3.0,
                    (c[0][1] + c[1][1] + c[2][1]) / 3.0,
                ];
            }
        }
        Ok(StressErrors {
            max,
            l2: (sum / area).sqrt(),
            worst_at,
        })
    }

    /// The errors of the last solve.
    pub fn measure(&self, test: &PatchTest, report: ContactReport) -> Result<PatchResult> {
        let p = test.p;
        let model = &self.model;
        let mesh = model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let stress = self.stress_errors(test)?;
        let (max_error, worst_at) = (stress.max, stress.worst_at);
        let range = |v: &mut dyn Iterator<Item = f64>| {
            v.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            })
        };
        let active = model.contact_active()?;
        let pressure = model.contact_pressure()?;
        let element_pressure = range(
            &mut pressure
                .iter()
                .zip(active)
                .filter(|(_, a)| **a)
                .map(|(q, _)| q / p),
        );
        let released = active.iter().filter(|a| !**a).count();
        let f = model.contact_forces()?;
        let x = mesh.nodes();
        let u = model.displacements()?;
        let mut nodal = Vec::new();
        for (side, sign) in [(&self.lower, -1.0), (&self.upper, 1.0)] {
            for (k, &v) in side.iter().enumerate() {
                let left = if k > 0 {
                    x[v][0] - x[side[k - 1]][0]
                } else {
                    0.0
                };
                let right = if k + 1 < side.len() {
                    x[side[k + 1]][0] - x[v][0]
                } else {
                    0.0
                };
                nodal.push(sign * f[v][1] / (0.5 * (left + right)) / p);
            }
        }
        let nodal_pressure = range(&mut nodal.into_iter());
        // Actual overlap: each node against the other side's polyline.
        let mut penetration = 0.0f64;
        for (side, other, sign) in [
            (&self.lower, &self.upper, 1.0),
            (&self.upper, &self.lower, -1.0),
        ] {
            let xs: Vec<f64> = other.iter().map(|&v| x[v][0]).collect();
            for &v in side.iter() {
                let xv = x[v][0];
                let k = xs.partition_point(|&s| s <= xv).clamp(1, xs.len() - 1);
                let (a, b) = (other[k - 1], other[k]);
                let t = (xv - xs[k - 1]) / (xs[k] - xs[k - 1]);
                let v_other = (1.0 - t) * u[a][1] + t * u[b][1];
                // Lower node: overlap when it is above the upper polyline.
                let overlap = sign * (u[v][1] - v_other);
                penetration = penetration.max(overlap);
            }
        }
        let elements = model.contact_elements()?;
        let nodes = Nodes::of(mesh);
        let framed = model.contact_framed_forces()?;
        let force = |pair, v| framed.get(&(pair, v)).copied().unwrap_or([0.0; 2]);
        let traction = range(
            &mut nodal_tractions(nodes, elements, Section::Plane, force)
                .into_iter()
                .map(|q| q.pressure / p),
        );
        let interface_traction = range(
            &mut interface_tractions(nodes, elements, Section::Plane, force)
                .into_iter()
                .map(|q| q.pressure / p),
        );
        let overlap = max_overlap(nodes, elements, |v| u[v]);
        Ok(PatchResult {
            max_error,
            l2_error: stress.l2,
            worst_at,
            element_pressure,
            nodal_pressure,
            released,
            reported_penetration: report.max_penetration,
            penetration,
            traction,
            interface_traction,
            overlap,
            report,
        })
    }
}
