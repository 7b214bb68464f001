//! The seed's test case (docs/method.md §4): two rectangles in contact along
//! their whole length, a pressure on the top of the upper one over 2C, the
//! bottom of the lower one supported over 2C, u_x = 0 on the symmetry line.
//! Meshed by the built-in structured triangulator with nodes on x = L/2 and
//! x = L/2 ± C, mirror-symmetric about x = L/2.

pub mod cattaneo;
pub mod corner;
pub mod hertz;
pub mod lame;
pub mod patch;
pub mod punch;
pub mod revolution;
pub mod ring;
pub mod shrink_fit;
pub mod sphere;
pub mod stack;
pub mod wall;

use super::meshgen::{Diagonal, MeshBuilder, subdivide, subdivide_symmetric};
use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode};
use crate::fem::mesh::Mesh;
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};

/// Tag of the supported segment of the lower body's bottom edge.
pub const TAG_SUPPORT: i32 = 1;
/// Tag of the lower body's top edge (contact side a).
pub const TAG_CONTACT_LOWER: i32 = 2;
/// Tag of the upper body's bottom edge (contact side b).
pub const TAG_CONTACT_UPPER: i32 = 3;
/// Tag of the loaded segment of the upper body's top edge.
pub const TAG_LOAD: i32 = 4;

/// Parameters of the two-block scene. [`Default`] gives the canonical
/// parameters of docs/method.md §4 with 2C/L = 0.2 and h = 1/64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBlocks {
    /// Young's modulus of the lower body Ω1.
    pub e1: f64,
    /// Poisson ratio of Ω1.
    pub nu1: f64,
    /// Young's modulus of the upper body Ω2.
    pub e2: f64,
    /// Poisson ratio of Ω2.
    pub nu2: f64,
    /// Height of Ω1.
    pub h1: f64,
    /// Height of Ω2.
    pub h2: f64,
    /// Length L of both bodies.
    pub length: f64,
    /// Half-width C of the loaded and supported segments.
    pub c: f64,
    /// Pressure on the loaded segment.
    pub p: f64,
    /// Target element size h.
    pub mesh_size: f64,
    /// Element size of the upper body Ω2 if it differs (a non-conforming
    /// interface); `None`: both bodies use `mesh_size` (conforming).
    pub upper_mesh_size: Option<f64>,
    /// Initial gap between the bodies (0: touching, the seed's case).
    pub gap: f64,
    /// Prescribe u_x = 0 on x = L/2 in both bodies.
    pub symmetry: bool,
    /// Support the lower body (v = 0 on its bottom over 2C).
    pub support: bool,
    /// Plane mode of both bodies.
    pub plane: PlaneMode,
    /// Coulomb's friction coefficient μ of the interface (0: frictionless).
    pub mu: f64,
}

impl Default for TwoBlocks {
    fn default() -> Self {
        TwoBlocks {
            e1: 1e10,
            nu1: 0.3,
            e2: 1e11,
            nu2: 0.3,
            h1: 0.25,
            h2: 0.25,
            length: 1.0,
            c: 0.1,
            p: 1e7,
            mesh_size: 1.0 / 64.0,
            upper_mesh_size: None,
            gap: 0.0,
            symmetry: true,
            support: true,
            plane: PlaneMode::Strain,
            mu: 0.0,
        }
    }
}

/// The built scene: the model and the nodes the results are read at.
pub struct TwoBlocksScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Node of Ω1 at (0, 0).
    pub corner_lower: usize,
    /// Node of Ω2 at (0, gap).
    pub corner_upper: usize,
    /// Node of Ω2 at (L/2, gap + H2).
    pub top_center: usize,
    /// Nodes of Ω1 (the first ones); the rest belong to Ω2.
    pub n_lower_nodes: usize,
}

/// The seed scene's outputs (the quantities of the reference file).
#[derive(Debug, Clone, PartialEq)]
pub struct TwoBlocksResult {
    /// Contact length ℓc.
    pub lc: f64,
    /// v of Ω2 minus v of Ω1 at the corner (0, 0).
    pub gap_edge: f64,
    /// v of Ω2 at (L/2, H2).
    pub v_top: f64,
    /// Work of the applied pressure per unit thickness.
    pub compliance: f64,
    /// Sum of the support reactions (vertical).
    pub support_reaction: f64,
    /// Length of the interface in contact that sticks (reference
    /// configuration; 0 when frictionless).
    pub stick_length: f64,
    /// u_x of Ω2 minus u_x of Ω1 at (0, 0).
    pub slip_edge: f64,
    /// Largest shear traction |τ| on the interface (0 when frictionless).
    pub max_shear: f64,
    /// The contact report.
    pub report: ContactReport,
}

impl TwoBlocks {
    /// Builds the mesh, materials, constraints, load and contact pair.
    pub fn build(&self) -> Result<TwoBlocksScene> {
        let (l, c, h) = (self.length, self.c, self.mesh_size);
        if !(l > 0.0 && self.h1 > 0.0 && self.h2 > 0.0 && h > 0.0 && c > 0.0 && 2.0 * c <= l) {
            return Err(Error::argument(format!(
                "two blocks: need L, H1, H2, h > 0 and 0 < 2C <= L (got L = {l}, H1 = {}, H2 = {}, C = {c}, h = {h})",
                self.h1, self.h2
            )));
        }
        if !(self.gap >= 0.0 && self.gap < 0.5 * h) {
            return Err(Error::argument(format!(
                "two blocks: the gap {} must lie in [0, h/2)",
                self.gap
            )));
        }
        let mid = 0.5 * l;
        let h_up = self.upper_mesh_size.unwrap_or(h);
        if h_up.is_nan() || h_up <= 0.0 {
            return Err(Error::argument(format!(
                "two blocks: upper mesh size {h_up} must be > 0"
            )));
        }
        let xs = subdivide_symmetric(0.0, l, &[mid - c, mid + c], h)?;
        let xs2 = subdivide_symmetric(0.0, l, &[mid - c, mid + c], h_up)?;
        let ys1 = subdivide(-self.h1, 0.0, &[], h)?;
        let ys2: Vec<f64> = subdivide(0.0, self.h2, &[], h_up)?
            .iter()
            .map(|y| y + self.gap)
            .collect();
        let mut b = MeshBuilder::new();
        let lower = b.add_grid(&xs, &ys1, 1, Diagonal::MirroredAt(mid));
        let n_lower_nodes = b.nodes.len();
        let upper = b.add_grid(&xs2, &ys2, 2, Diagonal::MirroredAt(mid));
        let i_mid = xs.iter().position(|&x| x == mid).expect("L/2 is a node");
        let i_mid2 = xs2.iter().position(|&x| x == mid).expect("L/2 is a node");
        let loaded = |x: f64| x >= mid - c && x <= mid + c;
        let mut edges = Vec::new();
        let mut tags = Vec::new();
        for e in b.boundary_edges() {
            let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
            let in_lower = e[0] < n_lower_nodes;
            let tag =
                if in_lower && p[1] == -self.h1 && q[1] == -self.h1 && loaded(p[0]) && loaded(q[0])
                {
                    TAG_SUPPORT
                } else if in_lower && p[1] == 0.0 && q[1] == 0.0 {
                    TAG_CONTACT_LOWER
                } else if !in_lower && p[1] == ys2[0] && q[1] == ys2[0] {
                    TAG_CONTACT_UPPER
                } else if !in_lower
                    && p[1] == ys2[ys2.len() - 1]
                    && q[1] == p[1]
                    && loaded(p[0])
                    && loaded(q[0])
                {
                    TAG_LOAD
                } else {
                    continue;
                };
            edges.push(e);
            tags.push(tag);
        }
        let symmetric_nodes: Vec<usize> = lower
            .iter()
            .map(|row| row[i_mid])
            .chain(upper.iter().map(|row| row[i_mid2]))
            .collect();
        let corner_lower = lower[lower.len() - 1][0];
        let corner_upper = upper[0][0];
        let top_center = upper[upper.len() - 1][i_mid2];

        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        model.set_material(1, Material::new(self.e1, self.nu1, self.plane, "body 1")?)?;
        model.set_material(2, Material::new(self.e2, self.nu2, self.plane, "body 2")?)?;
        model.set_tempering(Tempering::Auto)?;
        if self.symmetry {
            for v in symmetric_nodes {
                model.fix(v, Component::X, 0.0)?;
            }
        }
        if self.support {
            model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        }
        model.add_pressure(TAG_LOAD, self.p)?;
        let pair = model.add_contact_pair(TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)?;
        model.set_friction(pair, self.mu)?;
        Ok(TwoBlocksScene {
            model,
            corner_lower,
            corner_upper,
            top_center,
            n_lower_nodes,
        })
    }
}

impl TwoBlocksScene {
    /// Solves the contact problem and reads the seed scene's outputs.
    pub fn solve(&mut self, options: &ContactOptions) -> Result<TwoBlocksResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(report)
    }

    /// Reads the outputs of the last solve.
    pub fn measure(&self, report: ContactReport) -> Result<TwoBlocksResult> {
        let u = self.model.displacements()?;
        let r = self.model.reactions()?;
        let support_reaction = self
            .model
            .constraints()
            .filter(|(g, _)| g % 2 == 1)
            .map(|(g, _)| r[g / 2][1])
            .sum();
        // Under the mortar weighting the state is per slave node, and
        // frictionless: nothing sticks, no shear.
        let mortar = self.model.contact_weighting() == crate::ContactWeighting::Mortar;
        let state = match mortar {
            true => Vec::new(),
            false => self.model.contact_friction_state()?,
        };
        let b = self.model.contact_mesh()?;
        // Half of each element's edge: two elements of B face each edge
        // pair, as in ℓc.
        let stick_length = b
            .iter()
            .zip(&state)
            .filter(|(_, s)| **s == 1)
            .fold(0.0, |l, (e, _)| l + 0.5 * e.facing);
        let shear = match mortar {
            true => Vec::new(),
            false => self.model.contact_shear()?,
        };
        Ok(TwoBlocksResult {
            lc: report.contact_length,
            gap_edge: u[self.corner_upper][1] - u[self.corner_lower][1],
            v_top: u[self.top_center][1],
            compliance: self.model.external_work()?,
            support_reaction,
            stick_length,
            slip_edge: u[self.corner_upper][0] - u[self.corner_lower][0],
            max_shear: shear.iter().fold(0.0, |m: f64, t| m.max(t.abs())),
            report,
        })
    }
}

/// The nodes of the boundary edges tagged `tag`, each once, sorted by x
/// (a side along x: a contact side of the Hertz, Cattaneo or patch scenes).
pub fn nodes_by_x(mesh: &Mesh, tag: i32) -> Vec<usize> {
    let mut v: Vec<usize> = mesh
        .boundary_edges()
        .iter()
        .filter(|e| e.tag == tag)
        .flat_map(|e| e.nodes)
        .collect();
    v.sort_unstable();
    v.dedup();
    let x = mesh.nodes();
    v.sort_by(|&a, &b| x[a][0].total_cmp(&x[b][0]));
    v
}
