//! Contact scenes in three dimensions for stage 3
//! ([`super::tet_contact`], docs/method.md §9): the seed scene in 3D, a
//! sphere on a block (Hertz) and a rigid flat punch (Boussinesq).

use super::tet_contact::{ContactLoop, TetContactProblem, solve_contact};
use super::tetmesh::{LAYER, LOWER, Split, TetMesh, UPPER};
use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::solid_mesh::{Brick, SolidMesh};
use crate::linalg::ordering::Ordering;
use crate::model::solid::{Axis, SolidMaterial, SolidModel};
use crate::solve::report::Timings;

/// The seed scene in three dimensions (issue 41): Ω1 = [0, L]² × [−H1, 0]
/// below Ω2 = [0, L]² × [0, H2], a pressure p on the top square
/// [L/2 − C, L/2 + C]² of Ω2, u_z = 0 on the same square of Ω1's bottom,
/// frictionless, zero initial gap; solved on the quarter x, y ≤ L/2 with
/// u_x = 0 on x = L/2 and u_y = 0 on y = L/2. Uniform Kuhn meshes of size
/// h (which must divide C and the heights).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBlocks3d {
    /// Side L.
    pub l: f64,
    /// Heights H1 (lower) and H2 (upper).
    pub heights: [f64; 2],
    /// Young's moduli E1, E2.
    pub young: [f64; 2],
    /// Poisson's ratios ν1, ν2.
    pub poisson: [f64; 2],
    /// Pressure p.
    pub pressure: f64,
    /// Half-width C of the loaded and supported squares.
    pub c: f64,
    /// Mesh size h.
    pub h: f64,
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// The active-set loop that solves it.
    pub contact_loop: ContactLoop,
}

impl Default for TwoBlocks3d {
    /// The canonical parameters of the 2D scene.
    fn default() -> Self {
        TwoBlocks3d {
            l: 1.0,
            heights: [0.25, 0.25],
            young: [1e10, 1e11],
            poisson: [0.3, 0.3],
            pressure: 1e7,
            c: 0.1,
            h: 0.05,
            ordering: Ordering::Auto,
            contact_loop: ContactLoop::Product,
        }
    }
}

/// The outputs of [`TwoBlocks3d`] (of the whole scene, not the quarter).
#[derive(Debug, Clone, PartialEq)]
pub struct TwoBlocks3dResult {
    /// The area of the interface in contact.
    pub contact_area: f64,
    /// u_z of Ω2 minus u_z of Ω1 at the corner (0, 0, 0).
    pub gap_corner: f64,
    /// u_z of Ω2 at (L/2, L/2, H2).
    pub v_top: f64,
    /// ∫ p·(−u_z) over the loaded square.
    pub compliance: f64,
    /// The upward force the contact exerts on Ω2, over p·(2C)²: 1 in
    /// equilibrium.
    pub transmitted: f64,
    /// Unknowns of the quarter model.
    pub unknowns: usize,
    /// Entries of the Cholesky factor.
    pub factor_nnz: usize,
    /// Active-set solves.
    pub iterations: usize,
    /// Numeric factorisations of the solve.
    pub factorizations: usize,
    /// Bytes one numeric factorisation needs at its peak (the product's
    /// loop).
    pub factorization_bytes: usize,
    /// The time of each phase of the solve.
    pub timings: Timings,
    /// Seconds of the solve.
    pub seconds: f64,
    /// B's tetrahedra switched (on or off) after each active-set solve:
    /// the rank of the change to the next solve's matrix (from
    /// [`TwoBlocks3d::solve_model`]; empty from the study's loop).
    pub switches: Vec<usize>,
}

impl TwoBlocks3d {
    /// The quarter model's mesh.
    pub fn mesh(&self) -> Result<TetMesh> {
        let steps = |a: f64, b: f64| -> Result<Vec<f64>> {
            let k = ((b - a) / self.h).round();
            if !(k >= 1.0 && ((b - a) / self.h - k).abs() < 1e-9 && k < 1e4) {
                return Err(Error::argument(format!(
                    "h = {} must divide the length {}",
                    self.h,
                    b - a
                )));
            }
            Ok((0..=k as usize)
                .map(|i| a + (b - a) * i as f64 / k)
                .collect())
        };
        let half = 0.5 * self.l;
        steps(half - self.c, half)?;
        let xs = steps(0.0, half)?;
        Ok(TetMesh::stacked(
            &xs,
            &xs,
            &steps(-self.heights[0], 0.0)?,
            &steps(0.0, self.heights[1])?,
            Split::ByIndex,
        ))
    }

    /// Solves the scene and measures its outputs.
    pub fn solve(&self) -> Result<TwoBlocks3dResult> {
        let mesh = self.mesh()?;
        let half = 0.5 * self.l;
        let inner = half - self.c - 1e-12 * self.l;
        let (bottom, top) = (-self.heights[0], self.heights[1]);
        let p = self.pressure;
        let r = solve_contact(&TetContactProblem {
            mesh: &mesh,
            materials: [
                (self.young[0], self.poisson[0]),
                (self.young[1], self.poisson[1]),
            ],
            h_c: self.h,
            lambda: self.l,
            tempering: Tempering::Auto,
            ordering: self.ordering,
            contact_loop: self.contact_loop,
            fixed: &|part, x| {
                let supported = part == LOWER && x[2] == bottom && x[0] >= inner && x[1] >= inner;
                [
                    (x[0] == half).then_some(0.0),
                    (x[1] == half).then_some(0.0),
                    supported.then_some(0.0),
                ]
            },
            traction: &|part, c, n| {
                let loaded =
                    part == UPPER && c[2] == top && n[2] > 0.5 && c[0] >= inner && c[1] >= inner;
                if loaded { [0.0, 0.0, -p] } else { [0.0; 3] }
            },
        })?;
        let at = |part: usize, x: [f64; 3]| -> Result<f64> {
            let v = (0..mesh.nodes.len())
                .find(|&v| mesh.nodes[v] == x && node_part(&mesh, v) == Some(part))
                .ok_or_else(|| Error::argument(format!("no node of part {part} at {x:?}")))?;
            Ok(r.u[3 * v + 2])
        };
        let corner = [0.0, 0.0, 0.0];
        Ok(TwoBlocks3dResult {
            contact_area: 4.0 * r.contact_area,
            gap_corner: at(UPPER, corner)? - at(LOWER, corner)?,
            v_top: at(UPPER, [half, half, top])?,
            compliance: 4.0 * r.compliance(),
            transmitted: 4.0 * r.transmitted[2] / (p * 4.0 * self.c * self.c),
            unknowns: r.unknowns,
            factor_nnz: r.factor_nnz,
            iterations: r.iterations,
            factorizations: r.factorizations,
            factorization_bytes: r.factorization_bytes,
            timings: r.timings,
            seconds: r.seconds,
            switches: Vec::new(),
        })
    }
}

/// The tags of [`TwoBlocks3d::model`]'s faces: each brick's sides (x = 0,
/// x = L/2, y = 0, y = L/2, bottom, top) and the squares within them.
pub mod tags {
    /// Ω1's sides.
    pub const LOWER_SIDES: [i32; 6] = [11, 12, 13, 14, 15, 16];
    /// Ω2's sides.
    pub const UPPER_SIDES: [i32; 6] = [21, 22, 23, 24, 25, 26];
    /// The supported square of Ω1's bottom.
    pub const SUPPORT: i32 = 17;
    /// The loaded square of Ω2's top.
    pub const LOAD: i32 = 27;
}

impl TwoBlocks3d {
    /// The quarter model as a user builds it: two bricks (bodies 1 and 2)
    /// of the same Kuhn meshes as [`TwoBlocks3d::mesh`], the squares tagged
    /// ([`tags`]), the symmetry planes and the support prescribed, the
    /// pressure on the loaded square, one contact pair from Ω1's top to
    /// Ω2's bottom.
    pub fn model(&self) -> Result<SolidModel> {
        let grid = self.mesh()?;
        let half = 0.5 * self.l;
        let axis = |lo: f64, hi: f64| -> Vec<f64> {
            let mut v: Vec<f64> = (grid.nodes.iter())
                .map(|p| p[2])
                .filter(|&z| z >= lo && z <= hi)
                .collect();
            v.sort_by(f64::total_cmp);
            v.dedup();
            v
        };
        let mut xs: Vec<f64> = grid.nodes.iter().map(|p| p[0]).collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        let brick = |zs: Vec<f64>, body: i32, side_tags: [i32; 6]| Brick {
            xs: xs.clone(),
            ys: xs.clone(),
            zs,
            body,
            side_tags,
        };
        let (bottom, top) = (-self.heights[0], self.heights[1]);
        let mut mesh = SolidMesh::bricks(&[
            brick(axis(bottom, 0.0), 1, tags::LOWER_SIDES),
            brick(axis(0.0, top), 2, tags::UPPER_SIDES),
        ])?;
        let inner = half - self.c - 1e-12 * self.l;
        let square = |tag: i32, into: i32| -> (Vec<[usize; 3]>, Vec<i32>) {
            let faces: Vec<[usize; 3]> = (mesh.boundary_faces().iter())
                .filter(|f| f.tag == tag)
                .filter(|f| {
                    let c = mesh.face_geometry(f).centroid;
                    c[0] >= inner && c[1] >= inner
                })
                .map(|f| f.nodes)
                .collect();
            let n = faces.len();
            (faces, vec![into; n])
        };
        let (support, s_tags) = square(tags::LOWER_SIDES[4], tags::SUPPORT);
        let (load, l_tags) = square(tags::UPPER_SIDES[5], tags::LOAD);
        mesh.add_boundary_faces(&support, &s_tags)?;
        mesh.add_boundary_faces(&load, &l_tags)?;
        let mut model = SolidModel::new();
        model.set_mesh(mesh);
        model.set_material(1, SolidMaterial::new(self.young[0], self.poisson[0])?);
        model.set_material(2, SolidMaterial::new(self.young[1], self.poisson[1])?);
        model.set_ordering(self.ordering);
        for sides in [tags::LOWER_SIDES, tags::UPPER_SIDES] {
            model.fix_faces(sides[1], Axis::X, 0.0)?;
            model.fix_faces(sides[3], Axis::Y, 0.0)?;
        }
        model.fix_faces(tags::SUPPORT, Axis::Z, 0.0)?;
        model.add_pressure(tags::LOAD, self.pressure)?;
        model.add_contact_pair(tags::LOWER_SIDES[5], tags::UPPER_SIDES[4])?;
        Ok(model)
    }

    /// The contact options of the scene's model: λ = L, the full scene's
    /// size (the quarter's mesh is half as large).
    pub fn options(&self) -> ContactOptions {
        ContactOptions {
            lambda: Some(self.l),
            ..ContactOptions::default()
        }
    }

    /// Solves [`TwoBlocks3d::model`] and measures its outputs (of the whole
    /// scene).
    pub fn solve_model(&self) -> Result<TwoBlocks3dResult> {
        let mut model = self.model()?;
        let t0 = std::time::Instant::now();
        let info = model.solve_contact(&self.options())?;
        let seconds = t0.elapsed().as_secs_f64();
        let mesh = model.mesh().expect("set");
        let u = model.displacements()?;
        let half = 0.5 * self.l;
        let at = |body: i32, x: [f64; 3]| -> Result<f64> {
            let v = (0..mesh.nodes().len())
                .find(|&v| mesh.nodes()[v] == x && mesh.node_body()[v] == Some(body))
                .ok_or_else(|| Error::argument(format!("no node of body {body} at {x:?}")))?;
            Ok(u[v][2])
        };
        let corner = [0.0; 3];
        let forces = model.contact_forces()?;
        let upward: f64 = (0..forces.len())
            .filter(|&v| mesh.node_body()[v] == Some(2))
            .map(|v| forces[v][2])
            .sum();
        let p = self.pressure;
        Ok(TwoBlocks3dResult {
            contact_area: 4.0 * model.contact_area()?,
            gap_corner: at(2, corner)? - at(1, corner)?,
            v_top: at(2, [half, half, self.heights[1]])?,
            compliance: 4.0 * model.external_work()?,
            transmitted: 4.0 * upward / (p * 4.0 * self.c * self.c),
            unknowns: info.unknowns,
            factor_nnz: info.factor_nnz,
            iterations: model.iterations()?,
            factorizations: info.factorizations,
            factorization_bytes: info.factorization_bytes,
            timings: info.timings,
            seconds,
            switches: (model.contact_history()?.iter())
                .map(|r| r.switched_on + r.switched_off)
                .collect(),
        })
    }
}

/// The block a node belongs to (None for a node of no block).
fn node_part(mesh: &TetMesh, v: usize) -> Option<usize> {
    (mesh.tets.iter().enumerate())
        .find(|(e, t)| mesh.parts[*e] != LAYER && t.contains(&v))
        .map(|(e, _)| mesh.parts[e])
}

/// A sphere on a block (Hertz) in 3D: a body whose underside is the
/// sphere z = R − √(R² − r²) over the block's top z = 0, its nodes
/// straight above the block's (B's prisms span the initial gap), pressed
/// by the load P of contact radius `a` (P = 4E*a³/(3R)) spread over its
/// flat top; both bodies of side and depth `extent`·a, equal moduli;
/// solved on the quarter x, y ≥ 0 with its symmetry planes. Meshes graded
/// from a/`refinement` within 1.5a, growing by 1.3 beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz3d {
    /// Sphere radius R.
    pub radius: f64,
    /// The contact radius a the load is chosen for (Hertz).
    pub a: f64,
    /// Side and depth of the bodies over a.
    pub extent: f64,
    /// Young's modulus (both) and Poisson's ratio.
    pub young: f64,
    /// Poisson's ratio.
    pub poisson: f64,
    /// The mesh size near the contact is a / refinement.
    pub refinement: f64,
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// The active-set loop that solves it.
    pub contact_loop: ContactLoop,
}

impl Default for Hertz3d {
    fn default() -> Self {
        Hertz3d {
            radius: 1.0,
            a: 0.02,
            extent: 25.0,
            young: 1.0,
            poisson: 0.3,
            refinement: 4.0,
            ordering: Ordering::Auto,
            contact_loop: ContactLoop::Product,
        }
    }
}

/// The outputs of [`Hertz3d`], relative errors against Hertz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz3dResult {
    /// The contact radius from the contact area, √(area/π), over a, − 1.
    pub a_error: f64,
    /// p0 fitted to the nodal pressures within 0.8a (measured a), over
    /// Hertz's 3P/(2πa²), − 1.
    pub p0_error: f64,
    /// The force transmitted over P (1 in equilibrium).
    pub transmitted: f64,
    /// Unknowns (quarter).
    pub unknowns: usize,
    /// Entries of the Cholesky factor.
    pub factor_nnz: usize,
    /// Active-set solves.
    pub iterations: usize,
    /// Numeric factorisations of the solve.
    pub factorizations: usize,
    /// Seconds.
    pub seconds: f64,
}

impl Hertz3d {
    /// The load P of Hertz's contact radius a.
    pub fn load(&self) -> f64 {
        let e_star = self.young / (2.0 * (1.0 - self.poisson * self.poisson));
        4.0 * e_star * self.a.powi(3) / (3.0 * self.radius)
    }

    /// Graded abscissas 0 … extent·a: a/refinement up to 1.5a, then each
    /// step 1.3 times the last.
    fn graded(&self) -> Vec<f64> {
        let (h0, end) = (self.a / self.refinement, self.extent * self.a);
        let mut x = vec![0.0];
        let fine = (1.5 * self.refinement).round() as usize;
        x.extend((1..=fine).map(|i| i as f64 * h0));
        let mut step = h0;
        while *x.last().expect("a point") < end {
            step *= 1.3;
            let next = x.last().expect("a point") + step;
            x.push(if end - next < 0.5 * step { end } else { next });
        }
        x
    }

    /// The quarter model's mesh: the block below z = 0, the sphere's body
    /// above its underside, B between. Refuses parameters for which the
    /// sphere does not cover the block (extent·a·√2 ≥ R) or the graded
    /// region does not fit (extent < 2, refinement < 1).
    pub fn mesh(&self) -> Result<TetMesh> {
        let valid = |x: f64| x.is_finite() && x > 0.0;
        if !(valid(self.radius)
            && valid(self.a)
            && valid(self.young)
            && self.extent >= 2.0
            && self.refinement >= 1.0)
        {
            return Err(Error::argument(format!(
                "Hertz3d parameters out of range: {self:?}"
            )));
        }
        if self.extent * self.a * 2f64.sqrt() >= self.radius {
            return Err(Error::argument(format!(
                "the block ({} a wide) reaches beyond the sphere (R = {})",
                self.extent, self.radius
            )));
        }
        let xs = self.graded();
        let depth: Vec<f64> = xs.iter().rev().map(|z| -z).collect();
        let mut mesh = TetMesh::stacked(&xs, &xs, &depth, &xs, Split::ByIndex);
        let top = self.extent * self.a;
        let r2 = self.radius * self.radius;
        let mut upper = vec![false; mesh.nodes.len()];
        for (e, t) in mesh.tets.iter().enumerate() {
            if mesh.parts[e] == UPPER {
                t.iter().for_each(|&v| upper[v] = true);
            }
        }
        for (v, p) in mesh.nodes.iter_mut().enumerate() {
            if upper[v] && p[2] < top {
                let under = self.radius - (r2 - p[0] * p[0] - p[1] * p[1]).sqrt();
                p[2] = under + p[2] * (top - under) / top;
            }
        }
        Ok(mesh)
    }

    /// Solves and measures.
    pub fn solve(&self) -> Result<Hertz3dResult> {
        let mesh = self.mesh()?;
        let side = self.extent * self.a;
        let p = self.load();
        let q = p / (4.0 * side * side);
        let r = solve_contact(&TetContactProblem {
            mesh: &mesh,
            materials: [(self.young, self.poisson); 2],
            h_c: self.a / self.refinement,
            lambda: side,
            tempering: Tempering::Off,
            ordering: self.ordering,
            contact_loop: self.contact_loop,
            fixed: &|_, x| {
                [
                    (x[0] == 0.0).then_some(0.0),
                    (x[1] == 0.0).then_some(0.0),
                    (x[2] == -side).then_some(0.0),
                ]
            },
            traction: &|part, c, n| {
                if part == UPPER && c[2] == side && n[2] > 0.5 {
                    [0.0, 0.0, -q]
                } else {
                    [0.0; 3]
                }
            },
        })?;
        let area = 4.0 * r.contact_area;
        let a = (area / std::f64::consts::PI).sqrt();
        // p0 by least squares of p_i ≈ p0 √(1 − r_i²/a²) within 0.8a.
        let (mut num, mut den) = (0.0, 0.0);
        for &(v, pressure) in &r.pressures {
            let x = mesh.nodes[v];
            let rho2 = (x[0] * x[0] + x[1] * x[1]) / (a * a);
            if rho2 < 0.64 {
                let shape = (1.0 - rho2).sqrt();
                num += pressure * shape;
                den += shape * shape;
            }
        }
        if den == 0.0 {
            return Err(Error::argument(
                "no pressed node within 0.8a: refine the mesh",
            ));
        }
        let p0_hertz = 3.0 * p / (2.0 * std::f64::consts::PI * self.a * self.a);
        Ok(Hertz3dResult {
            a_error: a / self.a - 1.0,
            p0_error: num / den / p0_hertz - 1.0,
            transmitted: 4.0 * r.transmitted[2] / p,
            unknowns: r.unknowns,
            factor_nnz: r.factor_nnz,
            iterations: r.iterations,
            factorizations: r.factorizations,
            seconds: r.seconds,
        })
    }
}

/// A rigid flat cylindrical punch in 3D (Boussinesq): a punch of radius a
/// pressed a depth δ into a block, frictionless; the half-space's load is
/// P = 2aE*δ with E* = E/(1 − ν²). Solved on the quarter x, y ≥ 0 with
/// its symmetry planes: the block of side and depth `extent`·a on rollers
/// at its bottom; the punch a layer of tetrahedra over the disc r ≤ a with
/// every node prescribed (0, 0, −δ), B between. The block's top is meshed
/// to follow the punch's circle: a grid graded from a/`refinement` at the
/// punch's edge (where the pressure is singular, ~(a − r)^(−1/2)) and at
/// the top, each step 1.3 times the last away from them, whose square
/// [0, a]² is mapped onto the quarter disc (each square shell onto its
/// circle), blended back to the grid by 2a.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Punch3d {
    /// The punch's radius a.
    pub a: f64,
    /// Side and depth of the block over a.
    pub extent: f64,
    /// Young's modulus of the block.
    pub young: f64,
    /// Poisson's ratio of the block.
    pub poisson: f64,
    /// The indentation δ.
    pub indentation: f64,
    /// The mesh size at the punch's edge and the top is a / refinement.
    pub refinement: f64,
    /// Each step of the mesh is this many times the last away from the
    /// edge and the top.
    pub growth: f64,
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// The active-set loop that solves it.
    pub contact_loop: ContactLoop,
}

impl Default for Punch3d {
    fn default() -> Self {
        Punch3d {
            a: 1.0,
            extent: 100.0,
            young: 1.0,
            poisson: 0.3,
            indentation: 1e-3,
            refinement: 8.0,
            growth: 1.3,
            ordering: Ordering::Auto,
            contact_loop: ContactLoop::Product,
        }
    }
}

/// The outputs of [`Punch3d`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Punch3dResult {
    /// The load P the punch takes over Boussinesq's 2aE*δ, − 1.
    pub load_error: f64,
    /// The contact area over πa², − 1 (every tetrahedron of B on: 0 up to
    /// the polygon's area against the circle's).
    pub area_error: f64,
    /// Unknowns (quarter).
    pub unknowns: usize,
    /// Entries of the Cholesky factor.
    pub factor_nnz: usize,
    /// Active-set iterations.
    pub iterations: usize,
    /// Numeric factorisations of the solve.
    pub factorizations: usize,
    /// Seconds.
    pub seconds: f64,
}

impl Punch3d {
    /// Boussinesq's load 2aE*δ.
    pub fn load(&self) -> f64 {
        let e_star = self.young / (1.0 - self.poisson * self.poisson);
        2.0 * self.a * e_star * self.indentation
    }

    /// The quarter model's mesh: the block below z = 0, the punch above the
    /// quarter disc, B between. Refuses parameters out of range.
    pub fn mesh(&self) -> Result<TetMesh> {
        let valid = |x: f64| x.is_finite() && x > 0.0;
        if !(valid(self.a)
            && valid(self.young)
            && valid(self.indentation)
            && valid(self.extent)
            && valid(self.refinement)
            && self.extent >= 3.0
            && self.refinement >= 1.0
            && self.growth >= 1.01
            && self.growth <= 2.0
            && self.poisson > -1.0
            && self.poisson < 0.5)
        {
            return Err(Error::argument(format!(
                "Punch3d parameters out of range: {self:?}"
            )));
        }
        let (h0, end) = (self.a / self.refinement, self.extent * self.a);
        let inner = graded_abscissas(h0, 1, self.growth, self.a);
        // Across: from the edge inwards (mirrored) and outwards.
        let mut xs: Vec<f64> = inner.iter().rev().map(|x| self.a - x).collect();
        let cover = xs.len() - 1;
        xs.extend(
            graded_abscissas(h0, 1, self.growth, end - self.a)
                .iter()
                .skip(1)
                .map(|x| self.a + x),
        );
        let depth: Vec<f64> = graded_abscissas(h0, 1, self.growth, end)
            .iter()
            .rev()
            .map(|z| -z)
            .collect();
        let upper = [0.0, h0];
        let mut mesh = TetMesh::stacked_under(&xs, &xs, &depth, &upper, [cover; 2], Split::ByIndex);
        for p in &mut mesh.nodes {
            let [x, y] = disc_map([p[0], p[1]], self.a, 2.0 * self.a);
            p[0] = x;
            p[1] = y;
        }
        Ok(mesh)
    }

    /// Solves and measures.
    pub fn solve(&self) -> Result<Punch3dResult> {
        let mesh = self.mesh()?;
        let side = self.extent * self.a;
        let delta = self.indentation;
        let r = solve_contact(&TetContactProblem {
            mesh: &mesh,
            materials: [(self.young, self.poisson); 2],
            h_c: self.a / self.refinement,
            lambda: side,
            tempering: Tempering::Off,
            ordering: self.ordering,
            contact_loop: self.contact_loop,
            fixed: &|part, x| match part {
                UPPER => [Some(0.0), Some(0.0), Some(-delta)],
                _ => [
                    (x[0] == 0.0).then_some(0.0),
                    (x[1] == 0.0).then_some(0.0),
                    (x[2] == -side).then_some(0.0),
                ],
            },
            traction: &|_, _, _| [0.0; 3],
        })?;
        let disc = std::f64::consts::PI * self.a * self.a;
        Ok(Punch3dResult {
            load_error: 4.0 * r.transmitted[2] / self.load() - 1.0,
            area_error: 4.0 * r.contact_area / disc - 1.0,
            unknowns: r.unknowns,
            factor_nnz: r.factor_nnz,
            iterations: r.iterations,
            factorizations: r.factorizations,
            seconds: r.seconds,
        })
    }
}

/// Abscissas 0 … `end`: `fine` steps of `h0`, then each step `growth`
/// times the last (the last one stretched or merged to end at `end`).
fn graded_abscissas(h0: f64, fine: usize, growth: f64, end: f64) -> Vec<f64> {
    let mut x: Vec<f64> = (0..=fine).map(|i| i as f64 * h0).collect();
    let mut step = h0;
    while *x.last().expect("a point") < end {
        step *= growth;
        let next = x.last().expect("a point") + step;
        x.push(if end - next < 0.5 * step { end } else { next });
    }
    x
}

/// Maps the quarter plane so that the square [0, r]² lands on the quarter
/// disc of radius r, each square shell max(x, y) = ρ on the circle of
/// radius ρ, blended back to the identity between the shells ρ = r and
/// ρ = `blend`. Keeps the axes and the points beyond `blend`.
fn disc_map(p: [f64; 2], r: f64, blend: f64) -> [f64; 2] {
    let rho = p[0].max(p[1]);
    let norm = p[0].hypot(p[1]);
    if rho >= blend || norm == 0.0 {
        return p;
    }
    let s = rho / norm;
    let t = ((rho - r) / (blend - r)).max(0.0);
    let k = (1.0 - t) * s + t;
    [k * p[0], k * p[1]]
}
