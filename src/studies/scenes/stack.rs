//! A stack of n rectangular blocks [0, L] × [y_k, y_k + H_k], each its own
//! body with its own material and mesh (so interfaces between blocks of
//! different cell widths are non-matching), the lowest on rollers (v = 0)
//! along its bottom, u_x = 0 on the line x = 0 of every block, a pressure p
//! on the top of the highest one. The exact solution has a uniform stress
//! σ_yy = −p, σ_xx = τ_xy = 0 in every block whatever the materials, and
//! every interface in contact at pressure p: the many-body patch test.
//!
//! With `support_half_width = Some(C)` the load and the support act only
//! over [L/2 − C, L/2 + C] and u_x = 0 holds on x = L/2 instead (the seed
//! scene's loading, docs/method.md §4, through every interface): contact
//! zones shrink over the active-set iterations, as the interface-cost
//! benchmark needs.
//!
//! Block k (1-based) is body k; its faces carry the tags
//! [`block_tag`]`(k, face)`.

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::{Tempering, TriGeometry};
use crate::fem::material::{Material, PlaneMode};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder, subdivide, subdivide_symmetric};

/// Face of a rectangular block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Face {
    /// y = y0.
    Bottom = 1,
    /// y = y1.
    Top = 2,
    /// x = x0.
    Left = 3,
    /// x = x1.
    Right = 4,
}

/// The tag of face `face` of block `block` (1-based): 10 · block + face.
pub fn block_tag(block: usize, face: Face) -> i32 {
    10 * block as i32 + face as i32
}

/// A rectangle meshed as one body.
#[derive(Debug, Clone, PartialEq)]
pub struct Rect {
    /// Grid columns (increasing; the first and last are the sides).
    pub xs: Vec<f64>,
    /// Grid rows (increasing; the first and last are the bottom and top).
    pub ys: Vec<f64>,
}

/// Adds rectangles to a builder (rectangle k is body k + 1), tags every
/// face of every block with [`block_tag`] and returns the builder, the
/// tagged edges and their tags. Rectangles have their own nodes: blocks
/// that touch have coincident, distinct nodes.
pub fn mesh_blocks(rects: &[Rect]) -> (MeshBuilder, Vec<[usize; 2]>, Vec<i32>) {
    let mut b = MeshBuilder::new();
    let mut first_node = Vec::with_capacity(rects.len() + 1);
    for (k, r) in rects.iter().enumerate() {
        first_node.push(b.nodes.len());
        b.add_grid(&r.xs, &r.ys, k as i32 + 1, Diagonal::Forward);
    }
    first_node.push(b.nodes.len());
    let (mut edges, mut tags) = (Vec::new(), Vec::new());
    for e in b.boundary_edges() {
        let k = first_node.partition_point(|&f| f <= e[0]) - 1;
        let r = &rects[k];
        let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
        let on = |c: usize, v: f64| p[c] == v && q[c] == v;
        let face = if on(1, r.ys[0]) {
            Face::Bottom
        } else if on(1, r.ys[r.ys.len() - 1]) {
            Face::Top
        } else if on(0, r.xs[0]) {
            Face::Left
        } else if on(0, r.xs[r.xs.len() - 1]) {
            Face::Right
        } else {
            continue;
        };
        edges.push(e);
        tags.push(block_tag(k + 1, face));
    }
    (b, edges, tags)
}

/// How the contact pairs are declared.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pairing {
    /// By hand: (top of block k, bottom of block k + 1) for each k.
    Declared,
    /// Found by `Model::add_contact_pairs_auto(None, tolerance)`.
    Auto {
        /// The pairing tolerance (model units).
        tolerance: f64,
    },
}

/// One block of the stack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layer {
    /// Height H_k.
    pub height: f64,
    /// Young's modulus.
    pub young: f64,
    /// Poisson ratio.
    pub poisson: f64,
    /// Cells across L (rows: about square cells, at least one).
    pub cells: usize,
}

/// Parameters of the stack.
#[derive(Debug, Clone, PartialEq)]
pub struct Stack {
    /// The blocks, from the bottom up.
    pub layers: Vec<Layer>,
    /// Width L.
    pub length: f64,
    /// The pressure p on the top.
    pub p: f64,
    /// `Some(C)`: load and support over [L/2 − C, L/2 + C] only, symmetry
    /// u_x = 0 on x = L/2; `None`: uniform pressure, u_x = 0 on x = 0.
    pub support_half_width: Option<f64>,
    /// How the pairs are declared.
    pub pairing: Pairing,
}

impl Stack {
    /// n blocks of height H, alternating materials E = 1e10 and 1e11 with
    /// ν = 0.3 and 0.2, cell counts across cycling through `cells`, L = 1,
    /// p = 1e7, uniform pressure, declared pairs.
    pub fn alternating(n: usize, height: f64, cells: &[usize]) -> Stack {
        Stack {
            layers: (0..n)
                .map(|k| Layer {
                    height,
                    young: if k % 2 == 0 { 1e10 } else { 1e11 },
                    poisson: if k % 2 == 0 { 0.3 } else { 0.2 },
                    cells: cells[k % cells.len()],
                })
                .collect(),
            length: 1.0,
            p: 1e7,
            support_half_width: None,
            pairing: Pairing::Declared,
        }
    }

    /// Builds the mesh, materials, supports, load and contact pairs.
    pub fn build(&self) -> Result<StackScene> {
        let l = self.length;
        if self.layers.len() < 2 || l.is_nan() || l <= 0.0 {
            return Err(Error::argument(format!(
                "stack: need at least two blocks and L > 0 (got {} blocks, L = {l})",
                self.layers.len()
            )));
        }
        let mid = 0.5 * l;
        if let Some(c) = self.support_half_width {
            if !(c > 0.0 && 2.0 * c <= l) {
                return Err(Error::argument(format!(
                    "stack: the support half-width C = {c} must satisfy 0 < 2C <= L"
                )));
            }
        }
        let mut rects = Vec::new();
        let mut y = 0.0;
        for (k, layer) in self.layers.iter().enumerate() {
            if !(layer.height > 0.0 && layer.cells > 0) {
                return Err(Error::argument(format!(
                    "stack: block {} needs a height > 0 and cells > 0",
                    k + 1
                )));
            }
            let w = l / layer.cells as f64;
            let xs = match self.support_half_width {
                None => subdivide(0.0, l, &[], w)?,
                Some(c) => subdivide_symmetric(0.0, l, &[mid - c, mid + c], w)?,
            };
            let ys = subdivide(y, y + layer.height, &[], w)?;
            y = ys[ys.len() - 1];
            rects.push(Rect { xs, ys });
        }
        let n = rects.len();
        let (b, edges, tags) = mesh_blocks(&rects);
        let within = |x: f64| match self.support_half_width {
            None => true,
            Some(c) => x >= mid - c && x <= mid + c,
        };
        // Support and load: the bottom and top faces restricted to 2C.
        let (mut support, mut load) = (Vec::new(), Vec::new());
        for (e, &t) in edges.iter().zip(&tags) {
            let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
            if t == block_tag(1, Face::Bottom) && within(p[0]) && within(q[0]) {
                support.push(*e);
            } else if t == block_tag(n, Face::Top) && within(p[0]) && within(q[0]) {
                load.push(*e);
            }
        }
        const TAG_SUPPORT: i32 = 1;
        const TAG_LOAD: i32 = 2;
        let x_fixed = if self.support_half_width.is_some() {
            mid
        } else {
            0.0
        };
        let symmetric: Vec<usize> = (0..b.nodes.len())
            .filter(|&v| b.nodes[v][0] == x_fixed)
            .collect();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        model.add_boundary_edges(&support, &vec![TAG_SUPPORT; support.len()])?;
        model.add_boundary_edges(&load, &vec![TAG_LOAD; load.len()])?;
        for (k, layer) in self.layers.iter().enumerate() {
            let m = Material::new(
                layer.young,
                layer.poisson,
                PlaneMode::Strain,
                &format!("block {}", k + 1),
            )?;
            model.set_material(k as i32 + 1, m)?;
        }
        model.set_tempering(Tempering::Auto)?;
        for v in symmetric {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        model.add_pressure(TAG_LOAD, self.p)?;
        let pairs = match self.pairing {
            Pairing::Declared => (1..n)
                .map(|k| {
                    model.add_contact_pair(block_tag(k, Face::Top), block_tag(k + 1, Face::Bottom))
                })
                .collect::<Result<Vec<usize>>>()?,
            Pairing::Auto { tolerance } => model.add_contact_pairs_auto(None, tolerance)?,
        };
        Ok(StackScene { model, pairs })
    }
}

/// The built stack.
pub struct StackScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// The indices of its contact pairs.
    pub pairs: Vec<usize>,
}

/// The errors of a uniform-pressure stack solve.
#[derive(Debug, Clone, PartialEq)]
pub struct StackResult {
    /// Largest stress error over the elements, √(Σ (σ − σ_exact)²) / p,
    /// with σ_exact = (0, −p, 0).
    pub max_error: f64,
    /// Elements of B not active at convergence.
    pub released: usize,
    /// Active elements of B in each pair.
    pub active_per_pair: Vec<usize>,
    /// Elements of B in each pair.
    pub elements_per_pair: Vec<usize>,
    /// The contact report.
    pub report: ContactReport,
}

impl StackScene {
    /// Solves and measures against the uniform stress.
    pub fn solve(&mut self, p: f64, options: &ContactOptions) -> Result<StackResult> {
        let report = self.model.solve_contact(options)?;
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let mut max_error = 0.0f64;
        for (t, s) in mesh.triangles().iter().zip(self.model.element_stresses()?) {
            // Degenerate triangles have no stress to check (none here).
            if TriGeometry::new(&mesh.corners(t)).j > 0.0 {
                let e = (s[0].powi(2) + (s[1] + p).powi(2) + s[2].powi(2)).sqrt() / p;
                max_error = max_error.max(e);
            }
        }
        let active = self.model.contact_active()?;
        let elements = self.model.contact_elements()?;
        let n_pairs = self.model.contact_pairs().len();
        let (mut active_per_pair, mut elements_per_pair) = (vec![0; n_pairs], vec![0; n_pairs]);
        for (el, &a) in elements.iter().zip(active) {
            elements_per_pair[el.pair] += 1;
            active_per_pair[el.pair] += a as usize;
        }
        Ok(StackResult {
            max_error,
            released: active.iter().filter(|a| !**a).count(),
            active_per_pair,
            elements_per_pair,
            report,
        })
    }
}
