//! Axisymmetric indentation (x = r ≥ 0 the radius, y = z the axis; every
//! nodal force and reaction is the whole ring's, a pressure a force per
//! unit area): an elastic sphere on an elastic block ([`Sphere`], Hertz)
//! and a rigid flat cylindrical punch ([`CylindricalPunch`], Boussinesq).
//!
//! The block is a cylinder 0 ≤ r ≤ W, −D ≤ z ≤ 0, supported (u_z = 0) at
//! its bottom, meshed by the built-in structured triangulator with h near
//! the axis and graded outwards; every node on the axis has u_r = 0.
//!
//! **Sphere** (Hertz; Johnson, *Contact Mechanics*, §4.2): a sphere of
//! radius R pressed by a total force P on a half-space, frictionless,
//!
//! ```text
//!     a = (3PR / (4E*))^(1/3),   p(r) = p₀ √(1 − r²/a²),   p₀ = 3P / (2πa²),
//!     1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.
//! ```
//!
//! As in the plane Hertz scene ([`super::hertz`]) the sphere is represented
//! by the part of it near the contact: the region 0 ≤ r ≤ 0.8R between its
//! lower surface z = R − √(R² − r²) and its equatorial plane z = R, loaded
//! by a uniform pressure P/(π(0.8R)²) on that flat cut. With a = 0.02R (the
//! default) the cut is 50a above the contact: by Saint-Venant any
//! statically equivalent load gives the same field there, to (a/R)² ≈ 4e-4
//! of p₀, and a uniform pressure on a flat face is a clean load (a point
//! force on the axis would add its own stress singularity, 1/ρ², at the
//! sphere's pole, resolved by no mesh). The sphere's lower-surface nodes
//! stand above the block's top nodes at the same radii (the gap
//! r²/(2R) closes under the load), so B is the strip triangulation.
//!
//! **Flat cylindrical punch** (Boussinesq; Sneddon; Johnson §3.8): a rigid
//! flat punch of radius a pressed by δ into a half-space, frictionless,
//! takes
//!
//! ```text
//!     P = 2aE*δ,   p(r) = P / (2πa √(a² − r²)),   r < a,   E* = E/(1 − ν²).
//! ```
//!
//! The punch is rigid in the sense of docs/method.md §6.14: every one of
//! its nodes is prescribed (u_r = 0, u_z = −δ), and P is its reaction.
//! Unlike the plane punch, the half-space's compliance is finite: the
//! support at depth D and the free side at W stiffen the block by O(a/D)
//! (1.4 % at 40a, 0.1 % at 500a, against 2000a), so the block is much larger than the plane scene's
//! (default 500a, cheap with the grading). The edge singularity
//! p ∝ (a − r)^(−1/2) makes P converge at first order on a uniform mesh
//! (1.8 % high at h = a/32); the radii and the block's top depths are
//! therefore graded towards the punch's edge over a zone of 0.5a, element
//! sizes ∝ √(distance) (0.5 % at a/32). Its punch is one row of cells of
//! height 2h over [0, a] on the block's radii. The slivers at the edge
//! (5e-4a wide at h = a/32) make B stiff: the punch's reaction balances the
//! support's to ~1e-8 of P, and the library's bound on the rounding of its
//! reaction warns of six correct digits at h = a/32.

use std::collections::{BTreeMap, BTreeSet};
use std::f64::consts::PI;

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode, Section};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder, graded, subdivide};

/// Tag of the block's supported bottom.
pub const TAG_SUPPORT: i32 = 1;
/// Tag of the block's top face (contact side a).
pub const TAG_BLOCK_TOP: i32 = 2;
/// Tag of the indenter's contact face: the sphere's lower surface or the
/// punch's flat face (contact side b).
pub const TAG_INDENTER: i32 = 3;
/// Tag of the sphere's loaded equatorial cut.
pub const TAG_LOAD: i32 = 4;

/// Parameters of the sphere-on-block scene. [`Default`]: R = 1, a = 0.02R
/// (the sphere's part spans 40a, the block 100a), equal steel-like moduli,
/// h = a/16 at the contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    /// Sphere radius R.
    pub radius: f64,
    /// The analytic contact radius a the load is chosen for.
    pub contact_radius: f64,
    /// Young's modulus of the block (body 1).
    pub e_block: f64,
    /// Poisson ratio of the block.
    pub nu_block: f64,
    /// Young's modulus of the sphere (body 2).
    pub e_sphere: f64,
    /// Poisson ratio of the sphere.
    pub nu_sphere: f64,
    /// Element size at the contact (over 1.5a from the axis).
    pub mesh_size: f64,
    /// Growth of the element size away from the contact region.
    pub grading: f64,
    /// Radius W and depth D of the block, in units of R.
    pub block_size: f64,
}

impl Default for Sphere {
    fn default() -> Self {
        Sphere {
            radius: 1.0,
            contact_radius: 0.02,
            e_block: 2e11,
            nu_block: 0.3,
            e_sphere: 2e11,
            nu_sphere: 0.3,
            mesh_size: 0.02 / 16.0,
            grading: 1.15,
            block_size: 2.0,
        }
    }
}

/// The built sphere scene.
pub struct SphereScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Block nodes on its top face, sorted by r.
    pub block_top: Vec<usize>,
    /// Block nodes on its supported bottom.
    pub support: Vec<usize>,
    /// Nodes of the block (the first ones); the rest belong to the sphere.
    pub n_block_nodes: usize,
    /// The total force P (whole ring).
    pub load: f64,
}

/// Measured and analytic sphere quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereResult {
    /// Analytic contact radius a = (3PR/(4E*))^(1/3).
    pub a_exact: f64,
    /// Analytic peak pressure p₀ = 3P/(2πa²).
    pub p0_exact: f64,
    /// Contact radius: where the block's nodal pressure ends
    /// ([`contact_edge`]: p² extrapolated linearly to zero from the last
    /// two loaded nodes).
    pub a: f64,
    /// Peak pressure: the block's whole-ring contact force at the axis
    /// node over its ring tributary ∫ φ 2πr dr = πh²/3. First order in h
    /// (−1.6 % at a/32 for equal moduli, +1.3 % for a sphere 10× stiffer):
    /// the node is the corner of one triangle of the block and the reading
    /// of one element of B; `p0_fit` is the accurate peak pressure.
    pub p0: f64,
    /// The library's nodal pressure (`Model::contact_nodal_pressures`,
    /// read from both sides) at the block's axis node.
    pub p0_interface: f64,
    /// a and p₀ from a least-squares fit of p² = p₀²(1 − r²/a²) to the
    /// block's nodal pressures over the inner 80 % of the contact.
    pub a_fit: f64,
    /// See `a_fit`.
    pub p0_fit: f64,
    /// The block's nodal pressures (r, p): whole-ring contact force over
    /// the ring tributary.
    pub pressure: Vec<(f64, f64)>,
    /// The support's whole-ring reaction over P (1 at equilibrium).
    pub support_ratio: f64,
    /// The contact report.
    pub report: ContactReport,
}

impl SphereResult {
    /// The largest error of the block's nodal pressures off the axis
    /// against p₀√(1 − r²/a²) (analytic a, p₀) over 0 < r ≤ 0.8a, over p₀
    /// (the axis node is `p0`'s).
    pub fn inner_error(&self) -> f64 {
        let a = self.a_exact;
        self.pressure
            .iter()
            .filter(|(r, _)| *r > 0.0 && *r <= 0.8 * a)
            .map(|(r, p)| {
                (p - self.p0_exact * (1.0 - r * r / (a * a)).sqrt()).abs() / self.p0_exact
            })
            .fold(0.0, f64::max)
    }
}

/// Where a nodal pressure (r, p) sorted by r ends: p² is linear in r near
/// the edge of a Hertz contact (p ∝ √(a² − r²)), so it is extrapolated to
/// zero from the last two loaded nodes, at most to the first unloaded one
/// (halfway to it when the last is not the smaller). The plane Hertz
/// scene's reading ([`super::hertz::HertzScene::measure`]); NaN with fewer
/// than two loaded nodes.
pub fn contact_edge(pressure: &[(f64, f64)]) -> f64 {
    // Unloaded nodes carry round-off, ~1e-14 of p₀.
    let floor = 1e-9 * pressure.iter().fold(0.0f64, |m, p| m.max(p.1));
    let last = pressure
        .iter()
        .position(|&(_, p)| p <= floor)
        .unwrap_or(pressure.len());
    if last < 2 {
        return f64::NAN;
    }
    let ((x1, p1), (x2, p2)) = (pressure[last - 2], pressure[last - 1]);
    let x3 = pressure.get(last).map_or(f64::INFINITY, |p| p.0);
    if p1 > p2 {
        (x2 + p2 * p2 * (x2 - x1) / (p1 * p1 - p2 * p2)).min(x3)
    } else if x3.is_finite() {
        0.5 * (x2 + x3)
    } else {
        x2
    }
}

/// The least-squares fit of p² = p₀²(1 − r²/a²) to the loaded points of
/// `pressure` (r, p) with r ≤ `reach`: (a, p₀), NaN with fewer than three.
pub fn elliptic_fit(pressure: &[(f64, f64)], reach: f64) -> (f64, f64) {
    let pts: Vec<(f64, f64)> = pressure
        .iter()
        .filter(|(r, p)| *p > 0.0 && *r <= reach)
        .map(|(r, p)| (r * r, p * p))
        .collect();
    if pts.len() < 3 {
        return (f64::NAN, f64::NAN);
    }
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    ((intercept / -slope).sqrt(), intercept.sqrt())
}

/// The nodal pressures (r, p) of a row of nodes of a flat face z = const
/// at radii `r` (sorted) under whole-ring axial forces `fz`: −f_z over the
/// node's ring tributary ∫ φ_i 2πr dr (both its edges along the row).
fn ring_pressures(r: &[f64], fz: &[f64]) -> Vec<(f64, f64)> {
    let ring = Section::Revolution {
        coupling: 0.0,
        hoop: 0.0,
    };
    let mut tributary = vec![0.0; r.len()];
    for k in 0..r.len().saturating_sub(1) {
        let [p, q] = ring.edge_shares(r[k], r[k + 1], r[k + 1] - r[k]);
        tributary[k] += p;
        tributary[k + 1] += q;
    }
    (0..r.len())
        .map(|k| (r[k], -fz[k] / tributary[k]))
        .collect()
}

/// The block 0 ≤ r ≤ W at radii `xs` (from 0 to W) and depths `depths`
/// below its top (from 0 to D), added to `mb` as body 1: the node rows,
/// bottom first.
fn add_block(mb: &mut MeshBuilder, xs: &[f64], depths: &[f64]) -> Vec<Vec<usize>> {
    let zs: Vec<f64> = depths.iter().rev().map(|d| -d).collect();
    mb.add_grid(xs, &zs, 1, Diagonal::Forward)
}

/// The boundary edges of `mb` whose both nodes lie in one of the sets,
/// tagged with its tag (the first set that holds both).
fn tag_edges(mb: &MeshBuilder, sets: &[(&BTreeSet<usize>, i32)]) -> (Vec<[usize; 2]>, Vec<i32>) {
    let mut edges = Vec::new();
    let mut tags = Vec::new();
    for e in mb.boundary_edges() {
        if let Some((_, tag)) = sets
            .iter()
            .find(|(s, _)| s.contains(&e[0]) && s.contains(&e[1]))
        {
            edges.push(e);
            tags.push(*tag);
        }
    }
    (edges, tags)
}

impl Sphere {
    /// E* of the pair.
    pub fn e_star(&self) -> f64 {
        let inv = (1.0 - self.nu_block * self.nu_block) / self.e_block
            + (1.0 - self.nu_sphere * self.nu_sphere) / self.e_sphere;
        1.0 / inv
    }

    /// The total force P giving the contact radius a: P = 4E*a³/(3R).
    pub fn load(&self) -> f64 {
        4.0 * self.e_star() * self.contact_radius.powi(3) / (3.0 * self.radius)
    }

    /// Builds the mesh, materials, axis conditions, support, load and
    /// contact pair.
    pub fn build(&self) -> Result<SphereScene> {
        let (r, a, h, g) = (
            self.radius,
            self.contact_radius,
            self.mesh_size,
            self.grading,
        );
        if !(r > 0.0 && a > 0.0 && a < 0.3 * r && h > 0.0 && h <= a) {
            return Err(Error::argument(format!(
                "sphere: need R > 0, 0 < a < 0.3R and 0 < h <= a (got R = {r}, a = {a}, h = {h})"
            )));
        }
        if !(self.block_size >= 1.0 && self.block_size.is_finite() && (1.0..2.0).contains(&g)) {
            return Err(Error::argument(format!(
                "sphere: need a block of at least R and a grading in [1, 2) (got {}, {g})",
                self.block_size
            )));
        }
        let fine = 1.5 * a;
        let (w_block, w_sphere) = (self.block_size * r, 0.8 * r);
        let xs = graded(0.0, w_block, h, fine, g)?;
        let xs_sphere = graded(0.0, w_sphere, h, fine, g)?;
        // Heights above the lower surface, as fractions of the column:
        // graded from the contact (t = 0) to the equatorial cut (t = 1).
        let ts: Vec<f64> = graded(0.0, r, h, fine, g)?
            .into_iter()
            .map(|y| y / r)
            .collect();
        let bottom = |x: f64| r - (r * r - x * x).sqrt();
        let mut mb = MeshBuilder::new();
        let block = add_block(&mut mb, &xs, &graded(0.0, w_block, h, fine, g)?);
        let n_block_nodes = mb.nodes.len();
        let sphere = mb.add_mapped_grid(
            &xs_sphere,
            &ts,
            |x, t| [x, bottom(x) + t * (r - bottom(x))],
            2,
            Diagonal::Forward,
        );
        let set = |row: &[usize]| row.iter().copied().collect::<BTreeSet<_>>();
        let (top, base) = (set(&block[block.len() - 1]), set(&block[0]));
        let (surface, cut) = (set(&sphere[0]), set(&sphere[sphere.len() - 1]));
        let (edges, tags) = tag_edges(
            &mb,
            &[
                (&top, TAG_BLOCK_TOP),
                (&base, TAG_SUPPORT),
                (&cut, TAG_LOAD),
                (&surface, TAG_INDENTER),
            ],
        );
        let axis: Vec<usize> = (0..mb.nodes.len())
            .filter(|&v| mb.nodes[v][0] == 0.0)
            .collect();
        let load = self.load();
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let ring = PlaneMode::Axisymmetric;
        model.set_material(
            1,
            Material::new(self.e_block, self.nu_block, ring, "block")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_sphere, self.nu_sphere, ring, "sphere")?,
        )?;
        model.set_tempering(Tempering::Auto)?;
        for v in axis {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        // P over the cut's area π(0.8R)²: a pressure is per unit area.
        model.add_pressure(TAG_LOAD, load / (PI * w_sphere * w_sphere))?;
        model.add_contact_pair(TAG_BLOCK_TOP, TAG_INDENTER)?;
        Ok(SphereScene {
            model,
            block_top: block[block.len() - 1].clone(),
            support: block[0].clone(),
            n_block_nodes,
            load,
        })
    }
}

impl SphereScene {
    /// Solves and measures.
    pub fn solve(&mut self, sphere: &Sphere, options: &ContactOptions) -> Result<SphereResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(sphere, report)
    }

    /// Reads a and p₀ from the last solve: the whole-ring contact forces on
    /// the block's top nodes over their ring tributaries.
    pub fn measure(&self, sphere: &Sphere, report: ContactReport) -> Result<SphereResult> {
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let contact = self.model.contact_forces()?;
        let rs: Vec<f64> = self.block_top.iter().map(|&v| mesh.nodes()[v][0]).collect();
        let fz: Vec<f64> = self.block_top.iter().map(|&v| contact[v][1]).collect();
        let pressure = ring_pressures(&rs, &fz);
        let a = contact_edge(&pressure);
        let p0 = pressure.first().map_or(f64::NAN, |p| p.1);
        let (a_fit, p0_fit) = elliptic_fit(&pressure, 0.8 * a);
        let interface: BTreeMap<usize, f64> = self
            .model
            .contact_nodal_pressures()?
            .into_iter()
            .enumerate()
            .collect();
        let p0_interface = interface
            .get(&self.block_top[0])
            .copied()
            .unwrap_or(f64::NAN);
        let reactions = self.model.reactions()?;
        let support: f64 = self.support.iter().map(|&v| reactions[v][1]).sum();
        let a_exact = sphere.contact_radius;
        Ok(SphereResult {
            a_exact,
            p0_exact: 3.0 * self.load / (2.0 * PI * a_exact * a_exact),
            a,
            p0,
            p0_interface,
            a_fit,
            p0_fit,
            pressure,
            support_ratio: support / self.load,
            report,
        })
    }
}

/// Parameters of the rigid flat cylindrical punch. [`Default`]: a = 1, a
/// block of radius and depth 500a, steel-like, δ = 1e-3 a, h = a/16 under
/// the punch, graded towards its edge over 0.5a.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylindricalPunch {
    /// Radius a of the punch.
    pub radius: f64,
    /// Radius W and depth D of the block, in units of a.
    pub block_size: f64,
    /// Young's modulus of the block.
    pub e: f64,
    /// Poisson ratio of the block.
    pub nu: f64,
    /// Element size under the punch.
    pub mesh_size: f64,
    /// Width ℓ of the zone around the punch's edge (in units of a, in
    /// [0, 0.5]) where the radii and the block's depths are graded towards
    /// the edge, at distances ℓ(k/n)² (the last step ≈ h): element sizes
    /// ∝ √d, to resolve the singularity p ∝ (a − r)^(−1/2). 0: a uniform
    /// spacing under the punch.
    pub edge_zone: f64,
    /// Growth of the element size away from the punch.
    pub grading: f64,
    /// Prescribed downward displacement δ of the punch.
    pub indentation: f64,
}

impl Default for CylindricalPunch {
    fn default() -> Self {
        CylindricalPunch {
            radius: 1.0,
            block_size: 500.0,
            e: 2e11,
            nu: 0.3,
            mesh_size: 1.0 / 16.0,
            edge_zone: 0.5,
            grading: 1.15,
            indentation: 1e-3,
        }
    }
}

/// The built punch scene.
pub struct CylindricalPunchScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// Block nodes on its top face up to 2a, sorted by r.
    pub block_top: Vec<usize>,
    /// Nodes of the punch.
    pub punch: Vec<usize>,
    /// Block nodes on its supported bottom.
    pub support: Vec<usize>,
}

/// Measured punch quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct CylindricalPunchResult {
    /// The punch force P: minus the sum of the punch nodes' whole-ring
    /// axial reactions.
    pub force: f64,
    /// Boussinesq's P = 2aE*δ, E* = E/(1 − ν²).
    pub force_exact: f64,
    /// |P_punch − P_support| / P.
    pub balance: f64,
    /// The contact length ℓc of the report (a when the contact covers the
    /// punch's face exactly).
    pub contact_length: f64,
    /// Largest error of the block's nodal pressure against
    /// P/(2πa√(a² − r²)) (P the measured force) over 0 ≤ r ≤ 0.8a,
    /// relative to the exact pressure there.
    pub pressure_error: f64,
    /// The block's nodal pressures (r, p) up to 2a: whole-ring contact
    /// force over the ring tributary.
    pub pressure: Vec<(f64, f64)>,
    /// The contact report.
    pub report: ContactReport,
}

impl CylindricalPunch {
    /// E* = E/(1 − ν²) of the block.
    pub fn e_star(&self) -> f64 {
        self.e / (1.0 - self.nu * self.nu)
    }

    /// Builds the block, the punch (one row of cells of height 2h over
    /// [0, a] on the block's radii, every node prescribed), the axis
    /// conditions, the support and the contact pair (the block's top up to
    /// 2a against the punch's face).
    pub fn build(&self) -> Result<CylindricalPunchScene> {
        let (a, h, g) = (self.radius, self.mesh_size, self.grading);
        let size = self.block_size * a;
        if !(a > 0.0 && h > 0.0 && h <= 0.25 * a && self.block_size >= 4.0) {
            return Err(Error::argument(format!(
                "cylindrical punch: need a > 0, 0 < h <= a/4 and a block of at least 4a (got a = {a}, h = {h}, size {})",
                self.block_size
            )));
        }
        if !(self.indentation.is_finite()
            && self.indentation > 0.0
            && (1.0..2.0).contains(&g)
            && (0.0..=0.5).contains(&self.edge_zone))
        {
            return Err(Error::argument(format!(
                "cylindrical punch: need an indentation > 0, a grading in [1, 2) and an edge zone in [0, 0.5] (got {}, {g}, {})",
                self.indentation, self.edge_zone
            )));
        }
        // Distances from the punch's edge: ℓ(k/n)² over the edge zone ℓ,
        // the last step ≈ h.
        let zone = self.edge_zone * a;
        let n = (2.0 * zone / h).ceil() as usize;
        let d: Vec<f64> = (0..=n)
            .map(|k| zone * (k as f64 / n.max(1) as f64).powi(2))
            .collect();
        // The punch's radii: spacing h from the axis, then refined towards
        // the edge; beyond it the mirror image, then graded outwards. The
        // block's depths: the same refinement below its top, then h down to
        // 1.5a, then graded.
        let mut under = subdivide(0.0, a - zone, &[], h)?;
        under.extend(d.iter().rev().skip(1).map(|t| a - t));
        let mut xs = under.clone();
        xs.extend(d.iter().skip(1).map(|t| a + t));
        xs.extend(&graded(a + zone, size, h, h, g)?[1..]);
        let mut depths = d[..n].to_vec();
        depths.extend(graded(zone, size, h, 1.5 * a - zone, g)?);
        let mut mb = MeshBuilder::new();
        let block = add_block(&mut mb, &xs, &depths);
        let first_punch_node = mb.nodes.len();
        let punch_rows = mb.add_grid(&under, &[0.0, 2.0 * h], 2, Diagonal::Forward);
        let punch: Vec<usize> = (first_punch_node..mb.nodes.len()).collect();
        let top = block[block.len() - 1].clone();
        let contact_top: BTreeSet<usize> = top
            .iter()
            .copied()
            .filter(|&v| mb.nodes[v][0] <= 2.0 * a * (1.0 + 1e-12))
            .collect();
        let face: BTreeSet<usize> = punch_rows[0].iter().copied().collect();
        let support = block[0].clone();
        let base: BTreeSet<usize> = support.iter().copied().collect();
        let (edges, tags) = tag_edges(
            &mb,
            &[
                (&contact_top, TAG_BLOCK_TOP),
                (&face, TAG_INDENTER),
                (&base, TAG_SUPPORT),
            ],
        );
        let axis: Vec<usize> = block.iter().map(|row| row[0]).collect();
        let mut model = Model::new();
        model.set_mesh(mb.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let ring = PlaneMode::Axisymmetric;
        model.set_material(1, Material::new(self.e, self.nu, ring, "block")?)?;
        // The punch's material plays no part (a rigid side, §6.14).
        model.set_material(2, Material::new(self.e, self.nu, ring, "punch")?)?;
        model.set_tempering(Tempering::Auto)?;
        for v in axis {
            model.fix(v, Component::X, 0.0)?;
        }
        model.fix_edges(TAG_SUPPORT, Component::Y, 0.0)?;
        // The rigid punch: every node translated by (0, −δ) (u_r = 0 also
        // holds its axis node).
        for &v in &punch {
            model.fix(v, Component::X, 0.0)?;
            model.fix(v, Component::Y, -self.indentation)?;
        }
        model.add_contact_pair(TAG_BLOCK_TOP, TAG_INDENTER)?;
        let block_top = top
            .into_iter()
            .filter(|v| contact_top.contains(v))
            .collect();
        Ok(CylindricalPunchScene {
            model,
            block_top,
            punch,
            support,
        })
    }
}

impl CylindricalPunchScene {
    /// Solves and measures.
    pub fn solve(
        &mut self,
        punch: &CylindricalPunch,
        options: &ContactOptions,
    ) -> Result<CylindricalPunchResult> {
        let report = self.model.solve_contact(options)?;
        self.measure(punch, report)
    }

    /// Measures the last solve.
    pub fn measure(
        &self,
        punch: &CylindricalPunch,
        report: ContactReport,
    ) -> Result<CylindricalPunchResult> {
        let a = punch.radius;
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let reactions = self.model.reactions()?;
        // The constraints hold the punch down against the block (R_z < 0)
        // and the block up (R_z > 0); whole-ring totals.
        // Read on the mesh as it is: an adaptive solve adds nodes to the
        // punch, its face, the block's top and its support.
        let punch_body = mesh.node_body()[self.punch[0]];
        let force = -(0..mesh.nodes().len())
            .filter(|&v| mesh.node_body()[v] == punch_body)
            .map(|v| reactions[v][1])
            .sum::<f64>();
        let support: f64 = (super::nodes_by_x(mesh, TAG_SUPPORT).iter())
            .map(|&v| reactions[v][1])
            .sum();
        let contact = self.model.contact_forces()?;
        let block_top = super::nodes_by_x(mesh, TAG_BLOCK_TOP);
        let rs: Vec<f64> = block_top.iter().map(|&v| mesh.nodes()[v][0]).collect();
        let fz: Vec<f64> = block_top.iter().map(|&v| contact[v][1]).collect();
        let pressure = ring_pressures(&rs, &fz);
        let pressure_error = pressure
            .iter()
            .filter(|(r, _)| *r <= 0.8 * a * (1.0 + 1e-12))
            .map(|&(r, p)| {
                let exact = force / (2.0 * PI * a * (a * a - r * r).sqrt());
                ((p - exact) / exact).abs()
            })
            .fold(0.0, f64::max);
        Ok(CylindricalPunchResult {
            force,
            force_exact: 2.0 * a * punch.e_star() * punch.indentation,
            balance: (force - support).abs() / force.abs(),
            contact_length: report.contact_length,
            pressure_error,
            pressure,
            report,
        })
    }
}
