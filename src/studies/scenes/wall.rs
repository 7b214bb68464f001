//! A masonry wall of blocks laid in running bond: `rows` courses of height
//! H_b; even courses hold `blocks` full blocks of width W_b, odd courses a
//! half block at each end and `blocks − 1` full ones between, so that every
//! head joint (vertical) ends on the middle of a block of the course above
//! and below: the top corners of two neighbouring blocks and a point of the
//! bed face above are shared by three bodies. Each block is its own body
//! (block k is body k, its faces tagged [`super::stack::block_tag`]), all
//! of one material; the pairs are found by
//! `Model::add_contact_pairs_auto`.
//!
//! Supports: rollers (v = 0) under the first course, u = 0 on both ends of
//! the wall (a wall confined between rigid jambs). Loads: a pressure
//! p on the top of the last course over [0, `load_width`] (the whole top
//! when it is the wall's length) and, optionally, the self-weight ρg.
//!
//! Under a pressure over the whole top and no weight, the exact solution is
//! uniform: σ_yy = −p and, from ε_xx = 0 in plane strain,
//! σ_xx = −ν/(1 − ν) p, τ_xy = 0, every joint closed.

use std::collections::{BTreeMap, BTreeSet};

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::material::{Material, PlaneMode};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::subdivide;
use crate::studies::scenes::stack::{Face, Rect, block_tag, mesh_blocks};

/// Tag of the loaded part of the top.
pub const TAG_LOAD: i32 = 1;
/// Tag of the supported bottom.
pub const TAG_SUPPORT: i32 = 2;

/// Parameters of the wall. [`Default`]: 4 courses of 3 blocks 1 × 0.5,
/// E = 1e10, ν = 0.2, p = 1e6 over the whole top, no weight, h = 1/8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wall {
    /// Courses.
    pub rows: usize,
    /// Full blocks per even course.
    pub blocks: usize,
    /// Block width W_b.
    pub width: f64,
    /// Block height H_b.
    pub height: f64,
    /// Young's modulus.
    pub young: f64,
    /// Poisson ratio.
    pub poisson: f64,
    /// Pressure on the top.
    pub p: f64,
    /// The pressure acts on [0, load_width] of the top.
    pub load_width: f64,
    /// Weight per unit volume ρg (acting downwards).
    pub weight: f64,
    /// Cell size (W_b / 2 and H_b must be multiples of it).
    pub mesh_size: f64,
    /// Pairing tolerance (model units).
    pub tolerance: f64,
}

impl Default for Wall {
    fn default() -> Self {
        Wall {
            rows: 4,
            blocks: 3,
            width: 1.0,
            height: 0.5,
            young: 1e10,
            poisson: 0.2,
            p: 1e6,
            load_width: 3.0,
            weight: 0.0,
            mesh_size: 1.0 / 8.0,
            tolerance: 1e-6,
        }
    }
}

/// The built wall.
pub struct WallScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// The rectangle of each block (block k + 1 is `blocks[k]`).
    pub blocks: Vec<Rect>,
    /// The contact pairs found, as (tag_a, tag_b).
    pub pairs: Vec<(i32, i32)>,
}

/// The checks of a wall solve.
#[derive(Debug, Clone, PartialEq)]
pub struct WallResult {
    /// Largest, over the blocks, |Σ (loads + reactions + contact forces)|
    /// on the block's nodes, over the total applied load.
    pub block_imbalance: f64,
    /// |Σ contact forces over every node| over the total applied load (the
    /// contact forces are internal: they cancel).
    pub contact_imbalance: f64,
    /// Vertical contact force on the top course from the course below,
    /// over the load on the top course (1: it carries it all).
    pub top_course_support: f64,
    /// Largest stress error against the uniform solution (meaningful for
    /// a uniform pressure without weight), / p.
    pub max_uniform_error: f64,
    /// Largest |p_node − p_faces| / p over the nodes of B
    /// (`Model::contact_nodal_pressures` against [`WallScene::face_pressures`];
    /// meaningful for a uniform pressure without weight).
    pub max_nodal_pressure_error: f64,
    /// Elements of B released at convergence.
    pub released: usize,
    /// The contact report.
    pub report: ContactReport,
}

impl Wall {
    /// Builds the mesh, material, supports, loads and contact pairs.
    pub fn build(&self) -> Result<WallScene> {
        let (w, hb, h) = (self.width, self.height, self.mesh_size);
        if self.rows < 2 || self.blocks < 2 || !(w > 0.0 && hb > 0.0 && h > 0.0) {
            return Err(Error::argument(format!(
                "wall: need at least 2 courses of 2 blocks and W, H, h > 0 (got {} × {}, {w}, {hb}, {h})",
                self.rows, self.blocks
            )));
        }
        let length = self.blocks as f64 * w;
        let mut rects = Vec::new();
        let mut top_course = Vec::new();
        for r in 0..self.rows {
            let y0 = r as f64 * hb;
            let mut cuts = vec![0.0];
            if r % 2 == 1 {
                cuts.push(0.5 * w);
                for k in 1..self.blocks {
                    cuts.push((k as f64 + 0.5) * w);
                }
            } else {
                for k in 1..self.blocks {
                    cuts.push(k as f64 * w);
                }
            }
            cuts.push(length);
            for c in cuts.windows(2) {
                if r + 1 == self.rows {
                    top_course.push(rects.len());
                }
                rects.push(Rect {
                    xs: subdivide(c[0], c[1], &[], h)?,
                    ys: subdivide(y0, y0 + hb, &[], h)?,
                });
            }
        }
        let (b, edges, tags) = mesh_blocks(&rects);
        let n_first = rects.iter().take_while(|r| r.ys[0] == 0.0).count();
        let (mut load, mut support) = (Vec::new(), Vec::new());
        for (e, &t) in edges.iter().zip(&tags) {
            let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
            let block = (t / 10) as usize;
            if t % 10 == Face::Top as i32
                && top_course.contains(&(block - 1))
                && p[0].max(q[0]) <= self.load_width
            {
                load.push(*e);
            } else if t % 10 == Face::Bottom as i32 && block <= n_first {
                support.push(*e);
            }
        }
        if load.is_empty() {
            return Err(Error::argument(format!(
                "wall: no top edge lies within the load width {}",
                self.load_width
            )));
        }
        let ends: Vec<usize> = (0..b.nodes.len())
            .filter(|&v| b.nodes[v][0] == 0.0 || b.nodes[v][0] == length)
            .collect();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        model.add_boundary_edges(&load, &vec![TAG_LOAD; load.len()])?;
        model.add_boundary_edges(&support, &vec![TAG_SUPPORT; support.len()])?;
        let m = Material::new(self.young, self.poisson, PlaneMode::Strain, "masonry")?;
        for k in 0..rects.len() {
            model.set_material(k as i32 + 1, m)?;
            if self.weight != 0.0 {
                model.set_body_force(k as i32 + 1, [0.0, -self.weight])?;
            }
        }
        for v in ends {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        model.add_pressure(TAG_LOAD, self.p)?;
        model.add_contact_pairs_auto(None, self.tolerance)?;
        let pairs = model
            .contact_pairs()
            .iter()
            .map(|p| (p.tag_a, p.tag_b))
            .collect();
        Ok(WallScene {
            model,
            blocks: rects,
            pairs,
        })
    }

    /// The tags of the block faces that should pair: every head joint
    /// (right face, left face of the next block of the course) and every
    /// bed joint (top face, bottom face of each block of the next course
    /// it overlaps), as (smaller tag, larger tag), sorted: the independent
    /// expectation for the automatic pairing.
    pub fn expected_pairs(blocks: &[Rect]) -> Vec<(i32, i32)> {
        let mut out = Vec::new();
        let span = |r: &Rect| (r.xs[0], r.xs[r.xs.len() - 1], r.ys[0], r.ys[r.ys.len() - 1]);
        for (i, a) in blocks.iter().enumerate() {
            for (j, b) in blocks.iter().enumerate() {
                let ((ax0, ax1, ay0, ay1), (bx0, bx1, by0, _)) = (span(a), span(b));
                let (ta, tb) = if ay1 == by0 && ax0.max(bx0) < ax1.min(bx1) {
                    (block_tag(i + 1, Face::Top), block_tag(j + 1, Face::Bottom))
                } else if ax1 == bx0 && ay0 == by0 {
                    (block_tag(i + 1, Face::Right), block_tag(j + 1, Face::Left))
                } else {
                    continue;
                };
                out.push((ta.min(tb), ta.max(tb)));
            }
        }
        out.sort_unstable();
        out
    }
}

impl WallScene {
    /// The exact contact pressure, over p, at every node of B under a
    /// uniform pressure without weight: the mean of the pressures of the
    /// joints it lies on — 1 on a bed joint, ν/(1 − ν) on a head joint —
    /// its tributaries on them being equal (square cells, h/2 each), as
    /// `Model::contact_nodal_pressures` weighs them; with whether it lies
    /// on a head joint. Sorted by node.
    pub fn face_pressures(&self, wall: &Wall) -> Result<Vec<(usize, f64, bool)>> {
        let q = wall.poisson / (1.0 - wall.poisson);
        let mut bed = BTreeMap::new();
        let mut pairs_at: BTreeMap<usize, BTreeSet<usize>> = BTreeMap::new();
        for el in self.model.contact_elements()? {
            bed.insert(el.pair, el.normal[1].abs() > el.normal[0].abs());
            for &v in &el.nodes {
                pairs_at.entry(v).or_default().insert(el.pair);
            }
        }
        Ok(pairs_at
            .into_iter()
            .map(|(v, pairs)| {
                let beds = pairs.iter().filter(|k| bed[*k]).count();
                let heads = pairs.len() - beds;
                let want = (beds as f64 + q * heads as f64) / pairs.len() as f64;
                (v, want, heads > 0)
            })
            .collect())
    }

    /// Solves and checks equilibrium (and the uniform stress).
    pub fn solve(&mut self, wall: &Wall, options: &ContactOptions) -> Result<WallResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(wall, report)
    }

    /// The checks of the last solve (its `report`).
    pub fn measure(&self, wall: &Wall, report: ContactReport) -> Result<WallResult> {
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let f_ext = self.model.load_vector()?;
        let reactions = self.model.reactions()?;
        let contact = self.model.contact_forces()?;
        let node_body = mesh.node_body();
        let n_blocks = self.blocks.len();
        let mut per_block = vec![[0.0f64; 2]; n_blocks];
        let mut total_load = 0.0f64;
        let mut contact_sum = [0.0f64; 2];
        let top_y = self.blocks.iter().map(|r| r.ys[0]).fold(0.0, f64::max);
        let (mut top_load, mut top_contact) = (0.0, 0.0);
        for v in 0..mesh.nodes().len() {
            let Some(body) = node_body[v] else { continue };
            let k = body as usize - 1;
            let load = [f_ext[2 * v], f_ext[2 * v + 1]];
            total_load += load[0].hypot(load[1]);
            for c in 0..2 {
                per_block[k][c] += load[c] + reactions[v][c] + contact[v][c];
                contact_sum[c] += contact[v][c];
            }
            if self.blocks[k].ys[0] == top_y {
                top_load += load[1];
                top_contact += contact[v][1];
            }
        }
        let block_imbalance = per_block
            .iter()
            .map(|f| f[0].hypot(f[1]))
            .fold(0.0, f64::max)
            / total_load;
        let (sxx, syy) = (-wall.poisson / (1.0 - wall.poisson) * wall.p, -wall.p);
        let max_uniform_error = self
            .model
            .element_stresses()?
            .iter()
            .map(|s| ((s[0] - sxx).powi(2) + (s[1] - syy).powi(2) + s[2].powi(2)).sqrt())
            .fold(0.0, f64::max)
            / wall.p;
        let read = self.model.contact_nodal_pressures()?;
        let max_nodal_pressure_error = self
            .face_pressures(wall)?
            .iter()
            .map(|&(v, want, _)| (read[v] / wall.p - want).abs())
            .fold(0.0, f64::max);
        Ok(WallResult {
            block_imbalance,
            max_nodal_pressure_error,
            contact_imbalance: contact_sum[0].hypot(contact_sum[1]) / total_load,
            top_course_support: -top_contact / top_load,
            max_uniform_error,
            released: self.model.contact_active()?.iter().filter(|a| !**a).count(),
            report,
        })
    }
}
