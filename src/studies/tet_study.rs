//! The study of Jmin in three dimensions (docs/method.md §9, issue 41 stage
//! 1): a manufactured elasticity solution on the unit cube, solved with
//! tempered linear tetrahedra ([`crate::fem::tet`]) on the meshes of
//! [`crate::studies::tetmesh`], and its errors in L2 and in energy.
//!
//! This is a study, not the 3D product: its assembly is the plainest one
//! (every tetrahedron's 12 × 12 matrix added into the pattern of the
//! shared Cholesky solver), enough to decide the tempering rule before the
//! product's 3D assembly is built on it.

use std::time::Instant;

use super::tet_assembly::{
    analyse, block_stress_error, face_triangles, factorize, gradient, largest_face, lift, outward,
    unknowns_of, voigt_strain,
};
use super::tetmesh::{LAYER, LOWER, TetMesh};
use super::verification::StudyPoint;
use crate::error::{Error, Result};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::element::Tempering;
use crate::fem::tet::{TetGeometry, isotropic_d, stiffness};
use crate::linalg::ordering::Ordering;

/// How a tetrahedron's Jmin is chosen from its longest edge h: the
/// candidates of the study, and the product's rule.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TetTempering {
    /// Plain FEM (Jmin = 0).
    Off,
    /// The product's policy ([`Tempering::jmin_tet`]), with the unit
    /// cube's model size 1.
    Policy(Tempering),
    /// The tie of a flat layer (docs/method.md §9, stage 2): T_e = A_e
    /// h_c²/λ with A_e the tetrahedron's largest face, the 3D form of the
    /// 2D strip's T_e = ℓ_e h_c²/λ. Every tetrahedron of a split prism
    /// joins one pair of facing nodes and has the prism's triangle as its
    /// largest face, so each pair is tied with a stiffness proportional to
    /// its tributary area whatever the split: one penalty κ ∝ λ/h_c² over
    /// the interface.
    Tie {
        /// One length for the whole interface (its shortest edge).
        h_c: f64,
        /// The length λ.
        lambda: f64,
    },
    /// Jmin = min(c·h^k / λ^(k−3), cap·h³): k = 4 is the 2D rule's
    /// height criterion (a tetrahedron is tempered when its height over
    /// its largest face falls below about c·h²/λ, as a triangle's does
    /// below h²/λ); k = 3 is a fixed shape threshold (tempered when
    /// J/h³ < c), the same on every mesh. The cap keeps well-shaped
    /// tetrahedra (J ≥ cap·h³) plain on coarse meshes, as the 2D rule's
    /// J ≥ 0.1 h² does (infinite: no cap).
    Power {
        /// The exponent k.
        k: i32,
        /// The constant c.
        c: f64,
        /// The length λ (the solution's wavelength; 1 on the unit cube).
        lambda: f64,
        /// The shape quality J/h³ from which a tetrahedron stays plain.
        cap: f64,
    },
}

impl TetTempering {
    /// The Jmin of the tetrahedron `geo`.
    pub fn jmin(&self, geo: &TetGeometry) -> f64 {
        let h = geo.h;
        match *self {
            TetTempering::Off => 0.0,
            TetTempering::Policy(t) => t.jmin_tet(geo, 1.0),
            TetTempering::Tie { h_c, lambda } => largest_face(geo) * h_c * h_c / lambda,
            TetTempering::Power { k, c, lambda, cap } => {
                (c * h.powi(k) / lambda.powi(k - 3)).min(cap * h.powi(3))
            }
        }
    }
}

/// u = g(x)·c with g = sin πx sin πy sin πz and c = (1, −2, 1.5): zero on
/// the cube's faces, varying in every direction, with the body force
/// f = −div σ(u) = −(λ + μ) H(g) c + 3π² μ g c (H the Hessian of g).
#[derive(Debug, Clone, Copy)]
pub struct ManufacturedTets {
    lambda: f64,
    mu: f64,
}

const DIRECTION: [f64; 3] = [1.0, -2.0, 1.5];

impl ManufacturedTets {
    /// The solution for Young's modulus `young` and Poisson's ratio
    /// `poisson`.
    pub fn new(young: f64, poisson: f64) -> ManufacturedTets {
        ManufacturedTets {
            lambda: young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson)),
            mu: young / (2.0 * (1.0 + poisson)),
        }
    }

    fn sines(p: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let pi = std::f64::consts::PI;
        (p.map(|x| (pi * x).sin()), p.map(|x| (pi * x).cos()))
    }

    /// The displacement at `p`.
    pub fn displacement(&self, p: [f64; 3]) -> [f64; 3] {
        let (s, _) = Self::sines(p);
        DIRECTION.map(|c| c * s[0] * s[1] * s[2])
    }

    /// ∇u at `p`: row i is ∇u_i.
    pub fn gradient(&self, p: [f64; 3]) -> [[f64; 3]; 3] {
        let pi = std::f64::consts::PI;
        let (s, c) = Self::sines(p);
        let dg = [
            pi * c[0] * s[1] * s[2],
            pi * s[0] * c[1] * s[2],
            pi * s[0] * s[1] * c[2],
        ];
        DIRECTION.map(|d| dg.map(|g| d * g))
    }

    /// The body force at `p`.
    pub fn body_force(&self, p: [f64; 3]) -> [f64; 3] {
        let pi2 = std::f64::consts::PI.powi(2);
        let (s, c) = Self::sines(p);
        let g = s[0] * s[1] * s[2];
        let hessian = [
            [-pi2 * g, pi2 * c[0] * c[1] * s[2], pi2 * c[0] * s[1] * c[2]],
            [pi2 * c[0] * c[1] * s[2], -pi2 * g, pi2 * s[0] * c[1] * c[2]],
            [pi2 * c[0] * s[1] * c[2], pi2 * s[0] * c[1] * c[2], -pi2 * g],
        ];
        std::array::from_fn(|i| {
            let hc: f64 = (0..3).map(|j| hessian[i][j] * DIRECTION[j]).sum();
            -(self.lambda + self.mu) * hc + 3.0 * pi2 * self.mu * g * DIRECTION[i]
        })
    }
}

/// A degree-3 rule on the reference tetrahedron: the conical product of
/// three-point Gauss–Legendre rules (Stroud), x = u, y = v(1 − u),
/// z = w(1 − u)(1 − v), weight (1 − u)²(1 − v). Barycentric coordinates
/// (of nodes 1, 2, 3; node 0 the rest) and weights summing to 1.
fn quadrature() -> Vec<([f64; 3], f64)> {
    let r = (0.6f64).sqrt();
    let gauss = [
        (0.5 * (1.0 - r), 5.0 / 18.0),
        (0.5, 8.0 / 18.0),
        (0.5 * (1.0 + r), 5.0 / 18.0),
    ];
    let mut rule = Vec::with_capacity(27);
    for &(u, wu) in &gauss {
        for &(v, wv) in &gauss {
            for &(w, ww) in &gauss {
                let point = [u, v * (1.0 - u), w * (1.0 - u) * (1.0 - v)];
                // ∫ over the reference tetrahedron = 1/6 of the weights' sum.
                let weight = 6.0 * wu * wv * ww * (1.0 - u).powi(2) * (1.0 - v);
                rule.push((point, weight));
            }
        }
    }
    rule
}

fn at(x: &[[f64; 3]; 4], b: [f64; 3]) -> [f64; 3] {
    let b0 = 1.0 - b[0] - b[1] - b[2];
    std::array::from_fn(|i| b0 * x[0][i] + b[0] * x[1][i] + b[1] * x[2][i] + b[2] * x[3][i])
}

/// One mesh level of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TetPoint {
    /// Size, unknowns, time, L2 error and the energy error over every
    /// tetrahedron (weighed by its true volume, as in 2D).
    pub point: StudyPoint,
    /// The energy error over the well-shaped tetrahedra alone (J ≥
    /// 0.01 h³): the field off the band, which a flat tetrahedron's own
    /// gradient does not enter.
    pub energy_well_shaped: f64,
}

/// The shape quality J/h³ from which [`TetPoint::energy_well_shaped`]
/// counts a tetrahedron (the Kuhn tetrahedron's is 0.19, a regular one's
/// 0.71).
pub const WELL_SHAPED_3D: f64 = 0.01;

/// One run of the study: the material and the tempering.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TetStudy {
    /// Young's modulus.
    pub young: f64,
    /// Poisson's ratio.
    pub poisson: f64,
    /// The rule for Jmin.
    pub tempering: TetTempering,
    /// The rule for Jmin in the flat layer of a tied mesh
    /// ([`TetMesh::tied_blocks`]; unused elsewhere).
    pub layer: TetTempering,
}

impl TetStudy {
    /// Solves [`ManufacturedTets`] on `mesh` (u prescribed on its boundary
    /// nodes) and measures its errors; `h` is the nominal mesh size the
    /// point is reported at.
    pub fn run(&self, mesh: &TetMesh, h: f64) -> Result<TetPoint> {
        let exact = ManufacturedTets::new(self.young, self.poisson);
        let d = isotropic_d(self.young, self.poisson)?;
        let solution = solve(&TetProblem {
            mesh,
            d: &[d; 3],
            tempering: self.tempering,
            layer: self.layer,
            body_force: &|_, p| exact.body_force(p),
            boundary: &|_, p| exact.displacement(p),
            supported: &|_| true,
            free_stress: [[0.0; 3]; 3],
        })?;
        let e = errors(mesh, &solution.u, &exact, &d, &quadrature());
        Ok(TetPoint {
            point: StudyPoint {
                h,
                unknowns: solution.unknowns,
                l2: e.l2,
                energy: e.energy,
                seconds: solution.seconds,
            },
            energy_well_shaped: e.energy_well_shaped,
        })
    }
}

/// A linear elastic problem on a tetrahedral mesh: u prescribed at its
/// boundary nodes.
pub struct TetProblem<'a> {
    /// The mesh.
    pub mesh: &'a TetMesh,
    /// The elasticity matrix of each part of the mesh (one for a mesh
    /// without parts).
    pub d: &'a [[[f64; 6]; 6]],
    /// The rule for Jmin.
    pub tempering: TetTempering,
    /// The rule for Jmin in the part [`LAYER`] of a tied mesh.
    pub layer: TetTempering,
    /// The body force in a part at a point.
    pub body_force: &'a dyn Fn(usize, [f64; 3]) -> [f64; 3],
    /// The displacement prescribed at a boundary node of a part (the part
    /// of the first tetrahedron that holds the node).
    pub boundary: &'a dyn Fn(usize, [f64; 3]) -> [f64; 3],
    /// Whether a part's boundary nodes are prescribed; the others' faces
    /// carry the traction σ·n of `free_stress`.
    pub supported: &'a dyn Fn(usize) -> bool,
    /// The uniform stress whose tractions load the faces of the parts that
    /// are not supported.
    pub free_stress: [[f64; 3]; 3],
}

/// The nodal displacements of a [`TetProblem`].
pub struct TetSolution {
    /// Three per node, prescribed ones included.
    pub u: Vec<f64>,
    /// Unknowns solved for.
    pub unknowns: usize,
    /// Seconds of the analysis, assembly, factorisation and solve.
    pub seconds: f64,
}

/// Assembles and solves `problem`: each tetrahedron's tempered stiffness
/// and consistent load (true volume: none on flat ones) into the shared
/// Cholesky solver's pattern.
pub fn solve(problem: &TetProblem<'_>) -> Result<TetSolution> {
    let mesh = problem.mesh;
    let part = |t: usize| mesh.parts.get(t).copied().unwrap_or(0);
    let n = mesh.nodes.len();
    let mut part_of_node = vec![usize::MAX; n];
    for (e, t) in mesh.tets.iter().enumerate() {
        for &v in t {
            if part_of_node[v] == usize::MAX {
                part_of_node[v] = part(e);
            }
        }
    }
    let (fixed, force) = boundary(problem);
    let dofs = DofMap::new(n, 3, |g| !fixed[g / 3]);
    let pattern = Pattern::build(&dofs, n, &face_triangles(mesh));
    let t0 = Instant::now();
    let mut chol = analyse(&pattern, &dofs, mesh, Ordering::Auto)?;
    let mut values = vec![0.0; pattern.nnz()];
    let mut rhs = vec![0.0; dofs.n_free()];
    for (f, &g) in dofs.free_to_global().iter().enumerate() {
        rhs[f] = force[g];
    }
    let rule = quadrature();
    let prescribed: Vec<f64> = (0..3 * n)
        .map(|g| match part_of_node[g / 3] {
            usize::MAX => 0.0,
            p => (problem.boundary)(p, mesh.nodes[g / 3])[g % 3],
        })
        .collect();
    for (e, t) in mesh.tets.iter().enumerate() {
        let x = t.map(|v| mesh.nodes[v]);
        let geo = TetGeometry::new(&x);
        let d = problem.d.get(part(e)).ok_or_else(|| {
            Error::argument(format!("tetrahedron {e}: part {} has no material", part(e)))
        })?;
        let rule_e = if part(e) == LAYER && !mesh.parts.is_empty() {
            problem.layer
        } else {
            problem.tempering
        };
        let k = stiffness(&geo, d, rule_e.jmin(&geo)).map_err(|err| {
            Error::new(err.status(), format!("tetrahedron {e}: {}", err.message()))
        })?;
        let unknowns = unknowns_of(&dofs, t);
        let ke: Vec<f64> = k.iter().flatten().copied().collect();
        pattern.add_element(&mut values, &unknowns, &ke);
        lift(&mut rhs, &unknowns, t, &ke, &prescribed);
        let volume = geo.j.max(0.0) / 6.0;
        for (i, &row) in unknowns.iter().enumerate() {
            if row == NOT_FREE {
                continue;
            }
            for &(b, w) in &rule {
                let phi = [1.0 - b[0] - b[1] - b[2], b[0], b[1], b[2]];
                rhs[row] +=
                    w * volume * (problem.body_force)(part(e), at(&x, b))[i % 3] * phi[i / 3];
            }
        }
    }
    factorize(&mut chol, &pattern, &values, "the tetrahedral stiffness")?;
    chol.solve(&mut rhs)?;
    let seconds = t0.elapsed().as_secs_f64();
    let mut u = prescribed;
    for (f, &g) in dofs.free_to_global().iter().enumerate() {
        u[g] = rhs[f];
    }
    Ok(TetSolution {
        u,
        unknowns: dofs.n_free(),
        seconds,
    })
}

/// What the tied patch test measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiedPatch {
    /// The largest error of a block tetrahedron's stress over |σ|.
    pub stress_error: f64,
    /// The jump u(upper) − u(lower) across the layer, averaged over the
    /// interface's node pairs.
    pub jump: [f64; 3],
    /// The largest deviation of a pair's jump from that average, over its
    /// length.
    pub jump_spread: f64,
}

/// Which nodes are prescribed (those of the supported parts' boundary
/// faces) and the consistent forces of `free_stress` on the other parts'
/// boundary faces.
fn boundary(problem: &TetProblem<'_>) -> (Vec<bool>, Vec<f64>) {
    let mesh = problem.mesh;
    let n = mesh.nodes.len();
    let mut fixed = vec![false; n];
    let mut force = vec![0.0; 3 * n];
    for (e, f) in mesh.boundary_faces() {
        if (problem.supported)(mesh.parts.get(e).copied().unwrap_or(0)) {
            f.iter().for_each(|&v| fixed[v] = true);
            continue;
        }
        let inside = (mesh.tets[e].iter())
            .find(|v| !f.contains(v))
            .expect("a fourth node");
        let (unit, area, _) = outward(f.map(|v| mesh.nodes[v]), mesh.nodes[*inside]);
        let stress = &problem.free_stress;
        for &v in &f {
            for i in 0..3 {
                let t: f64 = (0..3).map(|j| stress[i][j] * unit[j]).sum();
                force[3 * v + i] += t * area / 3.0;
            }
        }
    }
    (fixed, force)
}

/// The tied patch test of docs/method.md §9, stage 2, on
/// [`TetMesh::tied_blocks`] (n boxes per side): Young's moduli `young`
/// for the lower and upper blocks (the layer takes the larger), Poisson's
/// ratio `poisson`, a uniform stress across the interface — σ_zz = 1,
/// σ_xz = 0.3, σ_yz = −0.2 and σ_xx = σ_yy = ν/(1 − ν), which leaves
/// both blocks' in-plane strains zero — the lower block's displacement
/// prescribed on its boundary, the upper block loaded by the stress's
/// tractions on its faces and held by the layer alone (its tie `tie`, the
/// blocks tempered as [`Tempering::Auto`]). Exact when every block
/// tetrahedron carries σ and the layer opens by one uniform jump.
pub fn tied_patch_test(
    mesh: &TetMesh,
    young: [f64; 2],
    poisson: f64,
    tie: TetTempering,
) -> Result<TiedPatch> {
    mesh.check_stacked()?;
    let nu = poisson;
    let side = nu / (1.0 - nu);
    let voigt = [side, side, 1.0, -0.2, 0.3, 0.0];
    let stress = [[side, 0.0, 0.3], [0.0, side, -0.2], [0.3, -0.2, 1.0]];
    let d = [
        isotropic_d(young[0], nu)?,
        isotropic_d(young[1], nu)?,
        isotropic_d(young[0].max(young[1]), nu)?,
    ];
    // The lower block's field: a rigid motion and ∂u/∂z = (γ_xz, γ_yz, ε_zz).
    let mu = young[0] / (2.0 * (1.0 + nu));
    let ezz = (voigt[2] - nu * (voigt[0] + voigt[1])) / young[0];
    let column = [voigt[4] / mu, voigt[3] / mu, ezz];
    let exact = |_: usize, p: [f64; 3]| -> [f64; 3] {
        let rigid = [0.1 - 0.01 * p[1], 0.2 + 0.01 * p[0], -0.3];
        std::array::from_fn(|i| rigid[i] + column[i] * (p[2] - 0.5))
    };
    let solution = solve(&TetProblem {
        mesh,
        d: &d,
        tempering: TetTempering::Policy(Tempering::Auto),
        layer: tie,
        body_force: &|_, _| [0.0; 3],
        boundary: &exact,
        supported: &|part| part == LOWER,
        free_stress: stress,
    })?;
    let u = &solution.u;
    if let Some(g) = u.iter().position(|x| !x.is_finite()) {
        return Err(Error::new(
            crate::error::Status::Internal,
            format!("the tied patch test's displacement {g} is not finite"),
        ));
    }
    let stress_error = block_stress_error(mesh, u, &d, &voigt, 1.0)?;
    let jumps = interface_jumps(mesh, u);
    let count = jumps.len().max(1) as f64;
    let jump: [f64; 3] = std::array::from_fn(|i| jumps.iter().map(|j| j[i]).sum::<f64>() / count);
    let length = jump.iter().map(|x| x * x).sum::<f64>().sqrt();
    let spread = (jumps.iter())
        .map(|j| (0..3).map(|i| (j[i] - jump[i]).powi(2)).sum::<f64>().sqrt())
        .fold(0.0, f64::max);
    Ok(TiedPatch {
        stress_error,
        jump,
        jump_spread: spread / length,
    })
}

/// u(upper copy) − u(lower copy) at each node pair of a tied mesh's
/// interface.
fn interface_jumps(mesh: &TetMesh, u: &[f64]) -> Vec<[f64; 3]> {
    (mesh.facing_pairs().into_iter())
        .map(|(a, b)| std::array::from_fn(|i| u[3 * b + i] - u[3 * a + i]))
        .collect()
}

/// The errors of a solution.
struct Errors {
    l2: f64,
    energy: f64,
    energy_well_shaped: f64,
}

/// The L2 error ‖u − u_h‖ and the energy error (∫ ε(e):σ(e))^½, e = u − u_h,
/// each tetrahedron weighed by its true volume.
fn errors(
    mesh: &TetMesh,
    u: &[f64],
    exact: &ManufacturedTets,
    d: &[[f64; 6]; 6],
    rule: &[([f64; 3], f64)],
) -> Errors {
    let (mut l2, mut energy, mut well_shaped) = (0.0, 0.0, 0.0);
    for t in &mesh.tets {
        let x = t.map(|v| mesh.nodes[v]);
        let geo = TetGeometry::new(&x);
        if geo.j <= 0.0 {
            continue;
        }
        let volume = geo.j / 6.0;
        let nodal: [[f64; 3]; 4] = t.map(|v| [u[3 * v], u[3 * v + 1], u[3 * v + 2]]);
        // ∇u_h = Σ u_k ⊗ a_k / J.
        let grad_h = gradient(&geo, t, u);
        let mut element_energy = 0.0;
        for &(b, w) in rule {
            let p = at(&x, b);
            let phi = [1.0 - b[0] - b[1] - b[2], b[0], b[1], b[2]];
            let ue = exact.displacement(p);
            for i in 0..3 {
                let uh: f64 = (0..4).map(|k| phi[k] * nodal[k][i]).sum();
                l2 += w * volume * (ue[i] - uh).powi(2);
            }
            let g = exact.gradient(p);
            let e: [[f64; 3]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|j| g[i][j] - grad_h[i][j]));
            let strain = voigt_strain(&e);
            let mut s = 0.0;
            for r in 0..6 {
                for c in 0..6 {
                    s += strain[r] * d[r][c] * strain[c];
                }
            }
            element_energy += w * volume * s;
        }
        energy += element_energy;
        if geo.j >= WELL_SHAPED_3D * geo.h.powi(3) {
            well_shaped += element_energy;
        }
    }
    Errors {
        l2: l2.sqrt(),
        energy: energy.sqrt(),
        energy_well_shaped: well_shaped.sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quadrature_integrates_cubics_exactly() {
        // Over the reference tetrahedron: ∫1 = 1/6, ∫x³ = 1/120,
        // ∫xyz = 1/720, ∫x²y = 1/360.
        let rule = quadrature();
        let integral = |f: &dyn Fn([f64; 3]) -> f64| -> f64 {
            rule.iter().map(|&(p, w)| w * f(p)).sum::<f64>() / 6.0
        };
        for (f, exact) in [
            (&(|_: [f64; 3]| 1.0) as &dyn Fn([f64; 3]) -> f64, 1.0 / 6.0),
            (&|p: [f64; 3]| p[0].powi(3), 1.0 / 120.0),
            (&|p: [f64; 3]| p[0] * p[1] * p[2], 1.0 / 720.0),
            (&|p: [f64; 3]| p[0] * p[0] * p[1], 1.0 / 360.0),
        ] {
            let got = integral(f);
            assert!((got - exact).abs() < 1e-15, "{got} against {exact}");
        }
    }

    #[test]
    fn the_body_force_balances_the_stress_of_the_manufactured_field() {
        // −div σ by central differences of σ(∇u) against the closed form.
        let m = ManufacturedTets::new(2.0, 0.3);
        let stress = |p: [f64; 3]| -> [[f64; 3]; 3] {
            let g = m.gradient(p);
            let div = g[0][0] + g[1][1] + g[2][2];
            std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    m.mu * (g[i][j] + g[j][i]) + if i == j { m.lambda * div } else { 0.0 }
                })
            })
        };
        let p = [0.31, 0.47, 0.73];
        let step = 1e-5;
        let f = m.body_force(p);
        for i in 0..3 {
            let mut div = 0.0;
            for j in 0..3 {
                let (mut a, mut b) = (p, p);
                a[j] += step;
                b[j] -= step;
                div += (stress(a)[i][j] - stress(b)[i][j]) / (2.0 * step);
            }
            assert!(
                (f[i] + div).abs() < 1e-7 * f[i].abs().max(1.0),
                "component {i}: {} against {}",
                f[i],
                -div
            );
        }
    }

    /// A right-corner tetrahedron whose longest edge is `h`.
    fn with_h(h: f64) -> TetGeometry {
        let l = h / 2f64.sqrt();
        TetGeometry::new(&[[0.0, 0.0, 0.0], [l, 0.0, 0.0], [0.0, l, 0.0], [0.0, 0.0, l]])
    }

    #[test]
    fn jmin_follows_its_power_of_h() {
        let k4 = TetTempering::Power {
            k: 4,
            c: 2.0,
            lambda: 0.5,
            cap: f64::INFINITY,
        };
        assert!((k4.jmin(&with_h(0.1)) - 2.0 * 1e-4 / 0.5).abs() < 1e-17);
        let k3 = TetTempering::Power {
            k: 3,
            c: 0.01,
            lambda: 7.0,
            cap: f64::INFINITY,
        };
        assert!((k3.jmin(&with_h(0.1)) - 1e-5).abs() < 1e-17);
        let capped = TetTempering::Power {
            k: 4,
            c: 1.0,
            lambda: 1.0,
            cap: 0.01,
        };
        assert!(
            (capped.jmin(&with_h(2.0)) - 0.08).abs() < 1e-15,
            "the cap, 0.01 h³, is the smaller"
        );
        assert!(
            (capped.jmin(&with_h(0.001)) - 1e-12).abs() < 1e-23,
            "c h⁴ is the smaller"
        );
        assert_eq!(TetTempering::Off.jmin(&with_h(0.1)), 0.0);
    }

    #[test]
    fn the_automatic_policy_is_k_4_with_c_1_capped_at_a_tenth_of_h_cubed() {
        let chosen = TetTempering::Power {
            k: 4,
            c: 1.0,
            lambda: 1.0,
            cap: 0.1,
        };
        for h in [1e-3, 0.01, 0.05, 0.1, 0.2, 0.5, 1.0] {
            let geo = with_h(h);
            let (a, b) = (
                TetTempering::Policy(Tempering::Auto).jmin(&geo),
                chosen.jmin(&geo),
            );
            assert!((a - b).abs() <= 1e-15 * b, "h = {h}: {a} against {b}");
        }
    }
}
