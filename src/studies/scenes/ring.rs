//! A ring inside a ring under a cos 2θ pressure, after Code_Aster's
//! validation case SSNP167 (V6.03.167, "contact between two rings";
//! modelings A/B: plane strain, E1 = E2 = 1e9 Pa, ν1 = ν2 = 0.2, pressure
//! p(θ) = 1e7 + 1e6 cos 2θ Pa on the outer edge r = R1 = 1; contact
//! interface r = R2 = 0.6; the inner ring is cut at R3 = 0.2, where the
//! displacements of the full disk are imposed — the geometry given with
//! its X-FEM twin SSNP169, V6.03.169 §1).
//!
//! The analytic solution (frictionless interface: u_r and σ_rr continuous,
//! σ_rθ = 0 on both sides) superposes the uniform pressure α0 and the
//! cos 2θ part α1, each solved with Michell's stress functions
//! (J. R. Barber, Elasticity, ch. 8 and Table 8.1): the uniform part
//! u_r = a r + b/r, the cos 2θ part φ = (A r² + B r⁴ + C r⁻² + D) cos 2θ,
//! with C = D = 0 and b = 0 in the inner disk (regular at r = 0). The
//! boundary and interface conditions give 3 + 6 linear equations for the
//! coefficients, solved in [`RingAnalytic::new`]; the contact pressure is
//! p_c(θ) = −σ_rr(R2, θ) = p0 + p2 cos 2θ (p0 = α0 for equal materials).
//!
//! The model is the quarter 0 ≤ θ ≤ π/2 with its symmetry conditions
//! (v = 0 on θ = 0, u = 0 on θ = π/2; the load is symmetric about both
//! axes), both rings meshed by the same polar grid (matching nodes on the
//! interface), the analytic displacements imposed on r = R3, the pressure
//! applied as consistent nodal forces on the polygonal outer edge.

use nalgebra::{DMatrix, DVector};

use crate::contact::ContactOptions;
use crate::contact::mesh::Nodes;
use crate::contact::traction::nodal_tractions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode, Section};
use crate::model::solution::ContactReport;
use crate::model::{Component, Model};
use crate::studies::meshgen::{Diagonal, MeshBuilder};
use crate::studies::scenes::lame::criss_cross;

/// Tag of the inner ring's outer arc (contact side a).
pub const TAG_INNER: i32 = 2;
/// Tag of the outer ring's inner arc (contact side b).
pub const TAG_OUTER: i32 = 3;

/// Parameters of the two-ring scene. [`Default`]: SSNP167's data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rings {
    /// Outer radius R1 (loaded).
    pub r1: f64,
    /// Interface radius R2.
    pub r2: f64,
    /// Inner radius R3 (displacements imposed).
    pub r3: f64,
    /// Young's modulus of the inner ring.
    pub e_inner: f64,
    /// Poisson ratio of the inner ring.
    pub nu_inner: f64,
    /// Young's modulus of the outer ring.
    pub e_outer: f64,
    /// Poisson ratio of the outer ring.
    pub nu_outer: f64,
    /// Uniform part α0 of the pressure.
    pub alpha0: f64,
    /// cos 2θ part α1 of the pressure.
    pub alpha1: f64,
    /// Cells along the quarter circle (radial cells: about square at R2).
    pub cells: usize,
    /// Each cell split into four triangles by its centre (true, the
    /// default: the mesh is mirror-symmetric about both axes, so the
    /// rollers are exact symmetry conditions of the discrete full ring)
    /// or into two by its "/" diagonal (a chiral mesh).
    pub criss_cross: bool,
}

impl Default for Rings {
    fn default() -> Self {
        Rings {
            r1: 1.0,
            r2: 0.6,
            r3: 0.2,
            e_inner: 1e9,
            nu_inner: 0.2,
            e_outer: 1e9,
            nu_outer: 0.2,
            alpha0: 1e7,
            alpha1: 1e6,
            cells: 16,
            criss_cross: true,
        }
    }
}

/// The analytic solution of [`Rings`] (plane strain).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingAnalytic {
    /// Uniform part of the inner disk: u_r = a r.
    pub a1: f64,
    /// Uniform part of the outer ring: u_r = a r + b / r.
    pub a2: f64,
    /// See `a2`.
    pub b2: f64,
    /// cos 2θ part of the inner disk: [A, B] (C = D = 0).
    pub inner: [f64; 2],
    /// cos 2θ part of the outer ring: [A, B, C, D].
    pub outer: [f64; 4],
    /// Contact pressure: p_c(θ) = p0 + p2 cos 2θ.
    pub p0: f64,
    /// See `p0`.
    pub p2: f64,
    mu: [f64; 2],
    kappa: [f64; 2],
}

/// Shear modulus, λ and κ = 3 − 4ν of a plane-strain material.
fn lame(e: f64, nu: f64) -> (f64, f64, f64) {
    let mu = e / (2.0 * (1.0 + nu));
    let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    (mu, lambda, 3.0 - 4.0 * nu)
}

/// Coefficients of σ_rr, σ_rθ and 2μ u_r of the terms A, B, C, D of
/// φ = (A r² + B r⁴ + C r⁻² + D) cos 2θ at radius r (Barber, Table 8.1;
/// checked symbolically: the displacements give the stresses through
/// plane-strain Hooke's law).
fn michell(r: f64, kappa: f64) -> [[f64; 4]; 3] {
    [
        [-2.0, 0.0, -6.0 / r.powi(4), -4.0 / (r * r)],
        [2.0, 6.0 * r * r, -6.0 / r.powi(4), -2.0 / (r * r)],
        [
            -2.0 * r,
            (kappa - 3.0) * r.powi(3),
            2.0 / r.powi(3),
            (kappa + 1.0) / r,
        ],
    ]
}

fn solve(a: DMatrix<f64>, b: DVector<f64>) -> Result<DVector<f64>> {
    a.lu()
        .solve(&b)
        .ok_or_else(|| Error::argument("rings: the analytic system is singular"))
}

impl RingAnalytic {
    /// Solves the 3 + 6 interface and boundary conditions.
    pub fn new(s: &Rings) -> Result<RingAnalytic> {
        let (mu1, l1, k1) = lame(s.e_inner, s.nu_inner);
        let (mu2, l2, k2) = lame(s.e_outer, s.nu_outer);
        let (r1, r2) = (s.r1, s.r2);
        // Uniform part, unknowns [a1, a2, b2]: σ_rr2(R1) = −α0,
        // σ_rr1(R2) = σ_rr2(R2), u1(R2) = u2(R2).
        let m0 = DMatrix::from_row_slice(
            3,
            3,
            &[
                0.0,
                2.0 * (l2 + mu2),
                -2.0 * mu2 / (r1 * r1),
                2.0 * (l1 + mu1),
                -2.0 * (l2 + mu2),
                2.0 * mu2 / (r2 * r2),
                r2,
                -r2,
                -1.0 / r2,
            ],
        );
        let x0 = solve(m0, DVector::from_vec(vec![-s.alpha0, 0.0, 0.0]))?;
        // cos 2θ part, unknowns [A1, B1, A2, B2, C2, D2].
        let (o1, i2, o2) = (michell(r1, k2), michell(r2, k1), michell(r2, k2));
        let mut m2 = DMatrix::<f64>::zeros(6, 6);
        let mut rhs = DVector::<f64>::zeros(6);
        for j in 0..4 {
            m2[(0, 2 + j)] = o1[0][j]; // σ_rr2(R1) = −α1
            m2[(1, 2 + j)] = o1[1][j]; // σ_rθ2(R1) = 0
            m2[(3, 2 + j)] = o2[1][j]; // σ_rθ2(R2) = 0
            m2[(4, 2 + j)] = -o2[0][j]; // σ_rr1(R2) − σ_rr2(R2) = 0
            m2[(5, 2 + j)] = -o2[2][j] / (2.0 * mu2); // u_r1 − u_r2 = 0
        }
        for j in 0..2 {
            m2[(2, j)] = i2[1][j]; // σ_rθ1(R2) = 0
            m2[(4, j)] = i2[0][j];
            m2[(5, j)] = i2[2][j] / (2.0 * mu1);
        }
        rhs[0] = -s.alpha1;
        let x2 = solve(m2, rhs)?;
        let outer = [x2[2], x2[3], x2[4], x2[5]];
        let p2 = -(0..4).map(|j| o2[0][j] * outer[j]).sum::<f64>();
        let p0 = -(2.0 * (l1 + mu1) * x0[0]);
        Ok(RingAnalytic {
            a1: x0[0],
            a2: x0[1],
            b2: x0[2],
            inner: [x2[0], x2[1]],
            outer,
            p0,
            p2,
            mu: [mu1, mu2],
            kappa: [k1, k2],
        })
    }

    /// The contact pressure at polar angle θ.
    pub fn contact_pressure(&self, theta: f64) -> f64 {
        self.p0 + self.p2 * (2.0 * theta).cos()
    }

    /// The displacement (u_x, u_y) of the inner disk at (r, θ).
    pub fn inner_displacement(&self, r: f64, theta: f64) -> [f64; 2] {
        let ([a, b], mu, k) = (self.inner, self.mu[0], self.kappa[0]);
        let ur = self.a1 * r
            + (-2.0 * a * r + (k - 3.0) * b * r.powi(3)) / (2.0 * mu) * (2.0 * theta).cos();
        let ut = (2.0 * a * r + (k + 3.0) * b * r.powi(3)) / (2.0 * mu) * (2.0 * theta).sin();
        let (c, s) = (theta.cos(), theta.sin());
        [ur * c - ut * s, ur * s + ut * c]
    }

    /// The radial displacement of the outer ring at (r, θ).
    pub fn outer_radial(&self, r: f64, theta: f64) -> f64 {
        let m = michell(r, self.kappa[1]);
        let u2: f64 = (0..4).map(|j| m[2][j] * self.outer[j]).sum::<f64>() / (2.0 * self.mu[1]);
        self.a2 * r + self.b2 / r + u2 * (2.0 * theta).cos()
    }
}

/// The built scene.
pub struct RingScene {
    /// The model, ready for `solve_contact`.
    pub model: Model,
    /// The analytic solution.
    pub exact: RingAnalytic,
    /// The interface nodes of both rings.
    pub interface: Vec<usize>,
}

/// The contact pressure of a solve against the analytic one.
#[derive(Debug, Clone, PartialEq)]
pub struct RingResult {
    /// max over interface nodes |p_h − p_c| / max p_c, p_h the nodal
    /// pressure: the radial contact force on the node (the direction of the
    /// analytic traction) over its tributary length
    /// (`contact::traction::nodal_pressures`' half edges).
    pub max_error: f64,
    /// The same error of the cos 2θ amplitude alone: |p2_h − p2| / |p2|,
    /// p2_h the least-squares fit of p0_h + p2_h cos 2θ to the nodal
    /// pressures.
    pub amplitude_error: f64,
    /// Elements of B released at convergence (none: p_c > 0 everywhere).
    pub released: usize,
    /// The contact report.
    pub report: ContactReport,
}

impl Rings {
    /// Builds the mesh, materials, constraints, load and contact pair.
    pub fn build(&self) -> Result<RingScene> {
        use std::f64::consts::FRAC_PI_2;
        if !(self.r3 > 0.0 && self.r3 < self.r2 && self.r2 < self.r1 && self.cells >= 2) {
            return Err(Error::argument(format!(
                "rings: need 0 < R3 < R2 < R1 and at least 2 cells (got {}, {}, {}, {})",
                self.r3, self.r2, self.r1, self.cells
            )));
        }
        let exact = RingAnalytic::new(self)?;
        let n = self.cells;
        let thetas: Vec<f64> = (0..=n)
            .map(|j| {
                if j == n {
                    FRAC_PI_2
                } else {
                    FRAC_PI_2 * j as f64 / n as f64
                }
            })
            .collect();
        let h = self.r2 * FRAC_PI_2 / n as f64;
        let radii = |a: f64, b: f64| -> Vec<f64> {
            let m = ((b - a) / h).round().max(1.0) as usize;
            (0..=m)
                .map(|i| {
                    if i == m {
                        b
                    } else {
                        a + (b - a) * i as f64 / m as f64
                    }
                })
                .collect()
        };
        let polar = |r: f64, t: f64| {
            if t == FRAC_PI_2 {
                [0.0, r]
            } else {
                [r * t.cos(), r * t.sin()]
            }
        };
        let mut b = MeshBuilder::new();
        let grid = |b: &mut MeshBuilder, rs: &[f64], body: i32| {
            if self.criss_cross {
                criss_cross(b, rs, &thetas, polar, body)
            } else {
                b.add_mapped_grid(rs, &thetas, polar, body, Diagonal::Forward)
            }
        };
        let inner = grid(&mut b, &radii(self.r3, self.r2), 1);
        let outer = grid(&mut b, &radii(self.r2, self.r1), 2);
        // rows[j][i]: angle j, radius i.
        let last = |g: &Vec<Vec<usize>>| g[0].len() - 1;
        let arc =
            |g: &Vec<Vec<usize>>, i: usize| -> Vec<usize> { g.iter().map(|row| row[i]).collect() };
        let inner_arc = arc(&inner, last(&inner));
        let outer_arc = arc(&outer, 0);
        let loaded = arc(&outer, last(&outer));
        let cut = arc(&inner, 0);
        let (mut edges, mut tags) = (Vec::new(), Vec::new());
        for w in inner_arc.windows(2) {
            edges.push([w[0], w[1]]);
            tags.push(TAG_INNER);
        }
        for w in outer_arc.windows(2) {
            edges.push([w[0], w[1]]);
            tags.push(TAG_OUTER);
        }
        let x = b.nodes.clone();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(
            1,
            Material::new(self.e_inner, self.nu_inner, plane, "inner ring")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_outer, self.nu_outer, plane, "outer ring")?,
        )?;
        model.set_tempering(Tempering::Auto)?;
        // The analytic displacements on r = R3 (exactly 0 across the
        // symmetry lines, where the analytic value is 0 up to rounding).
        for (j, &v) in cut.iter().enumerate() {
            let u = exact.inner_displacement(self.r3, thetas[j]);
            model.fix(v, Component::X, if j == n { 0.0 } else { u[0] })?;
            model.fix(v, Component::Y, if j == 0 { 0.0 } else { u[1] })?;
        }
        for g in [&inner, &outer] {
            for &v in &g[0] {
                model.fix(v, Component::Y, 0.0)?;
            }
            for &v in &g[n] {
                model.fix(v, Component::X, 0.0)?;
            }
        }
        // Consistent nodal forces of −p(θ) n on each chord of the outer
        // edge (3-point Gauss; p at the polar angle of the point).
        let gauss = [
            (0.5 - 0.5 * 0.6f64.sqrt(), 5.0 / 18.0),
            (0.5, 8.0 / 18.0),
            (0.5 + 0.5 * 0.6f64.sqrt(), 5.0 / 18.0),
        ];
        for w in loaded.windows(2) {
            let (p, q) = (x[w[0]], x[w[1]]);
            let len = (q[0] - p[0]).hypot(q[1] - p[1]);
            // The outward normal of a chord running counter-clockwise.
            let nrm = [(q[1] - p[1]) / len, -(q[0] - p[0]) / len];
            let (mut fp, mut fq) = (0.0, 0.0);
            for (s, wgt) in gauss {
                let pt = [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
                let pr = self.alpha0 + self.alpha1 * (2.0 * pt[1].atan2(pt[0])).cos();
                fp += wgt * len * (1.0 - s) * pr;
                fq += wgt * len * s * pr;
            }
            model.add_nodal_force(w[0], [-fp * nrm[0], -fp * nrm[1]])?;
            model.add_nodal_force(w[1], [-fq * nrm[0], -fq * nrm[1]])?;
        }
        model.add_contact_pair(TAG_INNER, TAG_OUTER)?;
        let mut interface = inner_arc;
        interface.extend(outer_arc);
        Ok(RingScene {
            model,
            exact,
            interface,
        })
    }
}

impl RingScene {
    /// Solves and compares the nodal contact pressures with the analytic
    /// ones.
    pub fn solve(&mut self, options: &ContactOptions) -> Result<RingResult> {
        let report = self.model.solve_contact(options)?;
        let mesh = self.model.mesh().ok_or_else(|| Error::state("no mesh"))?;
        let f = self.model.contact_forces()?;
        let elements = self.model.contact_elements()?;
        let x = mesh.nodes();
        // The contact pushes the inner ring inwards and the outer one
        // outwards: the pressure is ∓ the radial force over the tributary
        // length. (The library's normal at an end node is its one chord's,
        // tilted by half a cell from the radial direction.)
        let inner: std::collections::BTreeSet<usize> = self.interface[..self.interface.len() / 2]
            .iter()
            .copied()
            .collect();
        let framed = self.model.contact_framed_forces()?;
        let force = |pair, v| framed.get(&(pair, v)).copied().unwrap_or([0.0; 2]);
        let pressures: Vec<(usize, f64)> =
            nodal_tractions(Nodes::of(mesh), elements, Section::Plane, force)
                .iter()
                .map(|q| {
                    let (v, r) = (q.node, x[q.node][0].hypot(x[q.node][1]));
                    let radial = (f[v][0] * x[v][0] + f[v][1] * x[v][1]) / r;
                    let sign = if inner.contains(&v) { -1.0 } else { 1.0 };
                    (v, sign * radial / q.tributary)
                })
                .collect();
        let scale = self.exact.p0 + self.exact.p2.abs();
        let mut max_error = 0.0f64;
        // Least squares of p0_h + p2_h c over the nodes (c = cos 2θ).
        let (mut s1, mut sc, mut scc, mut sp, mut spc) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for &(v, p) in &pressures {
            let theta = x[v][1].atan2(x[v][0]);
            max_error = max_error.max((p - self.exact.contact_pressure(theta)).abs() / scale);
            let c = (2.0 * theta).cos();
            (s1, sc, scc, sp, spc) = (s1 + 1.0, sc + c, scc + c * c, sp + p, spc + p * c);
        }
        let p2_h = (s1 * spc - sc * sp) / (s1 * scc - sc * sc);
        let released = self.model.contact_active()?.iter().filter(|a| !**a).count();
        Ok(RingResult {
            max_error,
            amplitude_error: (p2_h - self.exact.p2).abs() / self.exact.p2.abs(),
            released,
            report,
        })
    }
}
