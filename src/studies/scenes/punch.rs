//! Rigid indenters pressed into an elastic block (plane strain): a flat
//! punch ([`FlatPunch`]) and a cylinder ([`RigidCylinder`]).
//!
//! A rigid body is a body whose nodes all have a prescribed displacement
//! (`Model::fix` on both components of every node: here the indentation,
//! a rigid translation): its own elements then only load the prescribed
//! DOFs, and the contact pair joins it to the elastic body as any other
//! (docs/method.md §6.14). Its material does not matter: a pair with a
//! wholly prescribed side takes the contact modulus E_c from the other
//! body. The force it takes is its reaction.
//!
//! Flat punch (Sneddon; Johnson, *Contact Mechanics*, §5.2): a rigid flat
//! punch of half-width a pressed by a force P (per unit thickness) into a
//! half-space, frictionless, is in contact over its whole width with
//!
//! ```text
//!     p(x) = P / (π √(a² − x²)),   |x| < a,
//! ```
//!
//! singular at the edges; the shape does not depend on the elastic
//! constants. Half model (u = 0 on x = 0); the block is [0, W] × [−D, 0]
//! with W = D = 40a, supported (v = 0) at its bottom, meshed with h over
//! 1.5a from the axis and graded outwards; the punch is one row of cells of
//! height 2h over [0, a] with the block's x positions. The block's contact
//! side extends to 2a, beyond the punch, so that the extent of the contact
//! is the method's answer, not the mesh's.

use std::collections::BTreeSet;

use super::hertz::{Hertz, HertzResult};
use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder, graded, subdivide};

/// Tag of the block's top edge up to 2a (contact side a).
pub const TAG_BLOCK_TOP: i32 = 2;
/// Tag of the punch's flat face (contact side b).
pub const TAG_PUNCH: i32 = 3;
/// Tag of the block's supported bottom.
pub const TAG_SUPPORT: i32 = 1;

/// Parameters of the flat-punch scene. [`Default`]: a = 1, block 40a × 40a,
/// steel-like block, indentation 1e-3 a, h = a/16.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatPunch {
    /// Half-width a of the punch.
    pub half_width: f64,
    /// Half-width W and depth D of the block (in units of a).
    pub block_size: f64,
    /// Young's modulus of the block.
    pub e: f64,
    /// Poisson ratio of the block.
    pub nu: f64,
    /// Element size under the punch (over 1.5a from the axis).
    pub mesh_size: f64,
    /// Growth of the element size away from the punch.
    pub grading: f64,
    /// Prescribed downward displacement of the punch.
    pub indentation: f64,
}

impl Default for FlatPunch {
    fn default() -> Self {
        FlatPunch {
            half_width: 1.0,
            block_size: 40.0,
            e: 2e11,
            nu: 0.3,
            mesh_size: 1.0 / 16.0,
            grading: 1.15,
            indentation: 1e-3,
        }
    }
}

/// The built flat-punch scene.
pub struct FlatPunchScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Block nodes on its top edge, sorted by x.
    pub block_top: Vec<usize>,
    /// Nodes of the punch.
    pub punch: Vec<usize>,
    /// Nodes of the block's supported bottom.
    pub support: Vec<usize>,
}

/// Measured flat-punch quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct FlatPunchResult {
    /// The punch force P of the full model (twice the half model's), from
    /// the reactions of the punch's nodes.
    pub force: f64,
    /// |P_punch − P_support| / P: the punch's reaction against the block's
    /// support reaction.
    pub balance: f64,
    /// The contact length of the half model (ℓc of the report; a when the
    /// contact covers the punch exactly).
    pub contact_length: f64,
    /// Elements of B active at convergence, and in all.
    pub active: (usize, usize),
    /// Largest error of the block's nodal pressure against
    /// P/(π√(a² − x²)) over 0 ≤ x ≤ 0.8a, relative to the pressure there.
    pub pressure_error: f64,
    /// Nodal pressures (x, p) on the block's top edge up to 2a.
    pub pressure: Vec<(f64, f64)>,
    /// The contact report.
    pub report: ContactReport,
}

impl FlatPunch {
    /// Builds the mesh, materials, supports, the punch's motion and the
    /// contact pair.
    pub fn build(&self) -> Result<FlatPunchScene> {
        let (a, h, g) = (self.half_width, self.mesh_size, self.grading);
        let size = self.block_size * a;
        if !(a > 0.0 && h > 0.0 && h <= 0.25 * a && self.block_size >= 4.0) {
            return Err(Error::argument(format!(
                "flat punch: need a > 0, 0 < h <= a/4 and a block of at least 4a (got a = {a}, h = {h}, size {})",
                self.block_size
            )));
        }
        // Small strain: the indentation is a boundary value of the linear
        // problem, any positive size gives the same pressure shape.
        if !(self.indentation.is_finite() && self.indentation > 0.0) {
            return Err(Error::argument(format!(
                "flat punch: the indentation {} must be finite and > 0",
                self.indentation
            )));
        }
        // Uniform spacing over [0, a] (the punch's nodes), then graded.
        let under = subdivide(0.0, a, &[], h)?;
        let beyond = graded(a, size, under[1], 0.5 * a, g)?;
        let xs: Vec<f64> = under.iter().chain(&beyond[1..]).copied().collect();
        let depth: Vec<f64> = graded(0.0, size, under[1], 1.5 * a, g)?
            .into_iter()
            .rev()
            .map(|d| -d)
            .collect();
        let mut mb = MeshBuilder::new();
        let block = mb.add_grid(&xs, &depth, 1, Diagonal::Forward);
        let first_punch_node = mb.nodes.len();
        let punch_rows = mb.add_grid(&under, &[0.0, 2.0 * under[1]], 2, Diagonal::Forward);
        let punch: Vec<usize> = (first_punch_node..mb.nodes.len()).collect();
        let top = block[block.len() - 1].clone();
        let contact_top: BTreeSet<usize> = top
            .iter()
            .copied()
            .filter(|&v| mb.nodes[v][0] <= 2.0 * a * (1.0 + 1e-12))
            .collect();
        let face: BTreeSet<usize> = punch_rows[0].iter().copied().collect();
        let support: Vec<usize> = block[0].clone();
        let base: BTreeSet<usize> = support.iter().copied().collect();
        let mut edges = Vec::new();
        let mut tags = Vec::new();
        for e in mb.boundary_edges() {
            let both = |s: &BTreeSet<usize>| s.contains(&e[0]) && s.contains(&e[1]);
            let tag = if both(&contact_top) {
                TAG_BLOCK_TOP
            } else if both(&face) {
                TAG_PUNCH
            } else if both(&base) {
                TAG_SUPPORT
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let axis: Vec<usize> = block.iter().map(|row| row[0]).collect();
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(1, Material::new(self.e, self.nu, plane, "block")?)?;
        // The punch's material plays no part (a rigid side, §6.14).
        model.set_material(2, Material::new(self.e, self.nu, plane, "punch")?)?;
        model.set_tempering(Tempering::Auto)?;
        for v in axis {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        // The rigid punch: every node translated by (0, −d).
        for &v in &punch {
            model.fix(v, Component::X, 0.0)?;
            model.fix(v, Component::Y, -self.indentation)?;
        }
        model.add_contact_pair(TAG_BLOCK_TOP, TAG_PUNCH)?;
        let block_top = top
            .into_iter()
            .filter(|v| contact_top.contains(v))
            .collect();
        Ok(FlatPunchScene {
            model,
            block_top,
            punch,
            support,
        })
    }
}

impl FlatPunchScene {
    /// Solves and measures.
    pub fn solve(
        &mut self,
        punch: &FlatPunch,
        options: &ContactOptions,
    ) -> Result<FlatPunchResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(punch, report)
    }

    /// Measures the last solve.
    pub fn measure(&self, punch: &FlatPunch, report: ContactReport) -> Result<FlatPunchResult> {
        let a = punch.half_width;
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let x = mesh.nodes();
        let reactions = self.model.reactions()?;
        // The constraints hold the punch down against the block (R_y < 0)
        // and the block up (R_y > 0).
        let force = -2.0 * self.punch.iter().map(|&v| reactions[v][1]).sum::<f64>();
        let support = 2.0 * self.support.iter().map(|&v| reactions[v][1]).sum::<f64>();
        let contact = self.model.contact_forces()?;
        let xs: Vec<f64> = self.block_top.iter().map(|&v| x[v][0]).collect();
        let n = xs.len();
        let pressure: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                let left = if k > 0 { xs[k] - xs[k - 1] } else { 0.0 };
                let right = if k + 1 < n { xs[k + 1] - xs[k] } else { 0.0 };
                // The contact pushes the block's top down: f_y < 0.
                (
                    xs[k],
                    -contact[self.block_top[k]][1] / (0.5 * (left + right)),
                )
            })
            .collect();
        let pressure_error = pressure
            .iter()
            .filter(|(xk, _)| *xk <= 0.8 * a * (1.0 + 1e-12))
            .map(|&(xk, pk)| {
                let exact = force / (std::f64::consts::PI * (a * a - xk * xk).sqrt());
                ((pk - exact) / exact).abs()
            })
            .fold(0.0, f64::max);
        let active = self.model.contact_active()?;
        Ok(FlatPunchResult {
            force,
            balance: (force - support).abs() / force.abs(),
            contact_length: report.contact_length,
            active: (active.iter().filter(|&&b| b).count(), active.len()),
            pressure_error,
            pressure,
            report,
        })
    }
}

/// A rigid cylinder pressed into an elastic block: the Hertz scene
/// ([`Hertz`], half model) with the cylinder's load removed and every
/// cylinder node translated by (0, −d). Hertz for a rigid indenter:
/// E* = E/(1 − ν²) of the block alone, a = √(4PR/(πE*)), p₀ = 2P/(πa), P
/// the cylinder's reaction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidCylinder {
    /// The Hertz scene it modifies (its cylinder modulus is only E_c's: it
    /// is set to the block's).
    pub hertz: Hertz,
    /// Prescribed downward displacement of the cylinder.
    pub indentation: f64,
}

impl Default for RigidCylinder {
    fn default() -> Self {
        let hertz = Hertz::default();
        RigidCylinder {
            hertz: Hertz {
                e_cylinder: hertz.e_block,
                nu_cylinder: hertz.nu_block,
                ..hertz
            },
            // Measured to give a ≈ 0.02R (the Hertz scene's a) with the
            // default block.
            indentation: RIGID_CYLINDER_INDENTATION,
        }
    }
}

/// The indentation of [`RigidCylinder::default`]: it gives a contact
/// half-width of about 0.02R on the default Hertz block (measured; the
/// half-width against which errors are taken is computed from the force).
pub const RIGID_CYLINDER_INDENTATION: f64 = 1.15e-3;

/// Measured rigid-cylinder quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidCylinderResult {
    /// The line load P of the full cylinder: twice the half model's
    /// reactions on the cylinder's nodes.
    pub force: f64,
    /// E* = E/(1 − ν²) of the block.
    pub e_star: f64,
    /// a and p₀ from P (`a_exact`, `p0_exact`) and measured as for two
    /// elastic bodies (`a`, `p0`, `a_fit`, `p0_fit`).
    pub hertz: HertzResult,
}

impl RigidCylinder {
    /// Builds the Hertz scene, removes the cylinder's load and prescribes
    /// its translation.
    pub fn build(&self) -> Result<RigidCylinderScene> {
        let mut scene = self.hertz.build()?;
        scene.model.clear_loads();
        let n = scene
            .model
            .mesh()
            .ok_or_else(|| Error::state("no mesh"))?
            .nodes()
            .len();
        let cylinder: Vec<usize> = (scene.n_block_nodes..n).collect();
        for &v in &cylinder {
            // The axis nodes already have u = 0: the same value again.
            scene.model.fix(v, Component::X, 0.0)?;
            scene.model.fix(v, Component::Y, -self.indentation)?;
        }
        Ok(RigidCylinderScene { scene, cylinder })
    }
}

/// The built rigid-cylinder scene.
pub struct RigidCylinderScene {
    /// The Hertz scene, its cylinder made rigid.
    pub scene: super::hertz::HertzScene,
    /// Nodes of the cylinder.
    pub cylinder: Vec<usize>,
}

impl RigidCylinderScene {
    /// Solves and measures: a and p₀ against Hertz for the force the
    /// cylinder takes.
    pub fn solve(
        &mut self,
        rigid: &RigidCylinder,
        options: &ContactOptions,
    ) -> Result<RigidCylinderResult> {
        let report = self.scene.model.solve_contact(options)?;
        let reactions = self.scene.model.reactions()?;
        let force = -2.0 * self.cylinder.iter().map(|&v| reactions[v][1]).sum::<f64>();
        let hz = &rigid.hertz;
        let e_star = hz.e_block / (1.0 - hz.nu_block * hz.nu_block);
        let mut hertz = self.scene.measure(hz, report)?;
        let a_exact = (4.0 * force * hz.radius / (std::f64::consts::PI * e_star)).sqrt();
        hertz.a_exact = a_exact;
        hertz.p0_exact = 2.0 * force / (std::f64::consts::PI * a_exact);
        Ok(RigidCylinderResult {
            force,
            e_star,
            hertz,
        })
    }
}
