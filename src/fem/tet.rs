//! The tempered linear tetrahedron: the first stage of the method in three
//! dimensions (docs/method.md §9).
//!
//! A tetrahedron x₀…x₃ has the Jacobian matrix J_m = [x₁ − x₀, x₂ − x₀,
//! x₃ − x₀] and J = det J_m, six times its signed volume. The gradients of
//! its shape functions are ∇φ_k = a_k / J with a_k the columns of the
//! cofactor matrix of J_m (for k = 1, 2, 3; a₀ = −a₁ − a₂ − a₃): the
//! adjugate, polynomial in the coordinates, defined for every J —
//! flat (J = 0) and inverted (J < 0) tetrahedra included. With A the 6 × 12
//! matrix of J·ε (Voigt, engineering shears: ε_xx, ε_yy, ε_zz, γ_yz, γ_xz,
//! γ_xy), the plain stiffness is V·Bᵀ D B = Aᵀ D A / (6J), and TFEM's is
//!
//! ```text
//!   K̃ = Aᵀ D A / (6 · max(J, Jmin))  =  (J / max(J, Jmin)) · K   (J > 0),
//! ```
//!
//! the 2D rule of docs/method.md §2 with the volume's 1/6: a Gram form,
//! symmetric positive semidefinite for every J, plain FEM above Jmin, and
//! finite where the tetrahedron is flat. A tetrahedron has more ways to be
//! flat than a triangle — caps and wedges (a vertex on the opposite face's
//! plane), needles, slivers (two opposite edges coplanar, no short edge) —
//! and all have J → 0 while their a_k stay bounded: the rule holds for
//! each. Which Jmin keeps the method's order in 3D was decided by a study
//! (docs/method.md §9): Jmin = min(h⁴/λ, 0.1 h³), [`Tempering::jmin_tet`].
//!
//! The matrix is checked against an independent implementation with Eigen
//! (c_tests/tet_reference.cpp, tests/c_programs.rs).

use crate::error::{Error, Result};
use crate::fem::element::Tempering;

/// The geometry of a tetrahedron that its stiffness needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TetGeometry {
    /// J = det[x₁ − x₀, x₂ − x₀, x₃ − x₀]: six times the signed volume.
    pub j: f64,
    /// a_k = J ∇φ_k for the four nodes (the adjugate's columns).
    pub a: [[f64; 3]; 4],
    /// The longest edge.
    pub h: f64,
}

/// p − q.
pub(crate) fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// u × v.
pub(crate) fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// u · v.
pub(crate) fn dot(u: [f64; 3], v: [f64; 3]) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

impl TetGeometry {
    /// The geometry of the tetrahedron with corners `x`.
    pub fn new(x: &[[f64; 3]; 4]) -> TetGeometry {
        let (e1, e2, e3) = (sub(x[1], x[0]), sub(x[2], x[0]), sub(x[3], x[0]));
        // The cofactor matrix's columns: a₁ = e₂ × e₃, a₂ = e₃ × e₁,
        // a₃ = e₁ × e₂ (so that a_k · e_l = J δ_kl).
        let (a1, a2, a3) = (cross(e2, e3), cross(e3, e1), cross(e1, e2));
        let a0 = [
            -(a1[0] + a2[0] + a3[0]),
            -(a1[1] + a2[1] + a3[1]),
            -(a1[2] + a2[2] + a3[2]),
        ];
        let mut h = 0.0f64;
        for i in 0..4 {
            for k in i + 1..4 {
                let d = sub(x[i], x[k]);
                h = h.max(dot(d, d).sqrt());
            }
        }
        TetGeometry {
            j: dot(e1, a1),
            a: [a0, a1, a2, a3],
            h,
        }
    }

    /// The area of the largest face: the largest |a_k|/2 (a_k is twice the
    /// opposite face's area along its normal). For a flat tetrahedron of B,
    /// the facing area its T_e is measured on.
    pub fn largest_face(&self) -> f64 {
        (self.a.iter())
            .map(|a| 0.5 * dot(*a, *a).sqrt())
            .fold(0.0, f64::max)
    }
}

/// The isotropic elasticity matrix D (6 × 6, Voigt with engineering
/// shears) of Young's modulus `young` and Poisson's ratio `poisson`; an
/// error naming the bad one.
pub fn isotropic_d(young: f64, poisson: f64) -> Result<[[f64; 6]; 6]> {
    if !(young.is_finite() && young > 0.0) {
        return Err(Error::argument(format!(
            "Young's modulus E = {young:?} must be finite and > 0"
        )));
    }
    if !(poisson.is_finite() && poisson > -1.0 && poisson < 0.5) {
        return Err(Error::argument(format!(
            "Poisson's ratio nu = {poisson:?} must lie in (-1, 0.5)"
        )));
    }
    let lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    let mu = young / (2.0 * (1.0 + poisson));
    let mut d = [[0.0; 6]; 6];
    for (r, row) in d.iter_mut().enumerate().take(3) {
        for (c, v) in row.iter_mut().enumerate().take(3) {
            *v = lambda + if r == c { 2.0 * mu } else { 0.0 };
        }
    }
    for k in 3..6 {
        d[k][k] = mu;
    }
    Ok(d)
}

/// The 6 × 3 block of A (J·ε per unit displacement) of a node with
/// adjugate column `a`.
fn block(a: [f64; 3]) -> [[f64; 3]; 6] {
    let [x, y, z] = a;
    [
        [x, 0.0, 0.0],
        [0.0, y, 0.0],
        [0.0, 0.0, z],
        [0.0, z, y],
        [z, 0.0, x],
        [y, x, 0.0],
    ]
}

/// The tempered stiffness K̃ = Aᵀ D A / (6 max(J, Jmin)) (12 × 12, DOFs
/// node by node: x, y, z). `jmin` ≥ 0; an error when max(J, Jmin) is not
/// positive (a flat or inverted tetrahedron without tempering), naming J.
pub fn stiffness(geo: &TetGeometry, d: &[[f64; 6]; 6], jmin: f64) -> Result<[[f64; 12]; 12]> {
    if !(jmin.is_finite() && jmin >= 0.0) {
        return Err(Error::argument(format!(
            "Jmin = {jmin:?} must be finite and >= 0"
        )));
    }
    if !geo.j.is_finite() {
        return Err(Error::argument(format!(
            "a tetrahedron with J = {:?}: its corners are not finite",
            geo.j
        )));
    }
    let denom = geo.j.max(jmin);
    if denom.is_nan() || denom <= 0.0 {
        return Err(Error::new(
            crate::error::Status::DegenerateElement,
            format!(
                "a tetrahedron with J = {:e} and Jmin = {jmin:e} has no stiffness: temper it \
                 (Jmin > 0)",
                geo.j
            ),
        ));
    }
    let blocks = geo.a.map(block);
    // D·A per node: 6 × 3.
    let da = blocks.map(|b| {
        let mut out = [[0.0; 3]; 6];
        for (r, row) in out.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v = (0..6).map(|k| d[r][k] * b[k][c]).sum();
            }
        }
        out
    });
    let scale = 1.0 / (6.0 * denom);
    let mut k = [[0.0; 12]; 12];
    for (i, bi) in blocks.iter().enumerate() {
        for (l, dal) in da.iter().enumerate() {
            for p in 0..3 {
                for q in 0..3 {
                    k[3 * i + p][3 * l + q] =
                        scale * (0..6).map(|r| bi[r][p] * dal[r][q]).sum::<f64>();
                }
            }
        }
    }
    Ok(k)
}

/// The gap weights of a tetrahedron of B, the mesh of the gap between two
/// bodies (docs/method.md §9, stage 3): w_k = (n·a_k) n for the interface
/// normal n (unit), so that g = Σ_k w_k·u_k is the change of J by the
/// displacements' normal parts — for a flat tetrahedron of a split prism,
/// twice its facing area times the normal opening of its pair of facing
/// nodes (negative: penetration). The 3D form of the strip's
/// w_(i,c) = (n·g_i) n_c (§6.1).
pub fn gap_weights(geo: &TetGeometry, n: [f64; 3]) -> [f64; 12] {
    std::array::from_fn(|i| dot(n, geo.a[i / 3]) * n[i % 3])
}

/// The frictionless contact stiffness of a tetrahedron of B:
/// K = (E_c / (6T)) w wᵀ, the energy ½ E_c ε_nn² of its (tempered)
/// volume: only the normal opening is resisted, tangential sliding is
/// free. `t` is the tetrahedron's T_e; E_c and T_e must be finite and
/// positive, and the matrix finite (an error naming the bad value).
pub fn contact_stiffness(w: &[f64; 12], e_c: f64, t: f64) -> Result<[[f64; 12]; 12]> {
    if !(e_c.is_finite() && e_c > 0.0 && t.is_finite() && t > 0.0) {
        return Err(Error::argument(format!(
            "a contact tetrahedron needs E_c > 0 and T_e > 0, finite: E_c = {e_c:?}, T_e = {t:?}"
        )));
    }
    let scale = e_c / (6.0 * t);
    let k: [[f64; 12]; 12] = std::array::from_fn(|i| std::array::from_fn(|j| scale * w[i] * w[j]));
    if k.iter().flatten().any(|x| !x.is_finite()) {
        return Err(Error::argument(format!(
            "a contact tetrahedron's stiffness overflows (E_c = {e_c:e}, T_e = {t:e})"
        )));
    }
    Ok(k)
}

/// The shape quality J/h³ from which [`Tempering::Auto`] leaves a
/// tetrahedron plain (Kuhn's tetrahedron has 0.19, the regular one 0.71).
pub const WELL_SHAPED_TET: f64 = 0.1;

impl Tempering {
    /// The Jmin of a tetrahedron of longest edge `geo.h` in a model whose
    /// bounding box's largest side is `model_size` (the automatic λ), in
    /// J's units (length³); 0 for plain FEM.
    ///
    /// [`Tempering::Auto`] is Jmin = min(h⁴/λ, [`WELL_SHAPED_TET`] h³):
    /// the 2D rule's criterion on the height (a triangle is tempered below
    /// a height of h²/λ over its longest edge, a tetrahedron below about
    /// h²/λ over its largest face), capped as in 2D so that no well-shaped
    /// tetrahedron is softened on coarse meshes. Chosen by the study of
    /// docs/method.md §9 (its numbers there): on a band of caps and
    /// slivers where plain FEM locks it keeps O(h²) in L2, a few per cent
    /// below the band-free mesh's error, with the band's energy falling at
    /// about rate 2 as in 2D; a fixed shape threshold (Jmin = c h³) either
    /// loses O(h²) on other bands (c = 0.1) or leaves the bands' energy
    /// falling at about 0.7 (c = 0.01). [`Tempering::Lambda`] is h⁴/λ,
    /// [`Tempering::Fixed`] the given value (then a volume scale, length³).
    pub fn jmin_tet(&self, geo: &TetGeometry, model_size: f64) -> f64 {
        let h = geo.h;
        match *self {
            Tempering::Auto => ((h / model_size) * h * h * h).min(WELL_SHAPED_TET * h * h * h),
            Tempering::Lambda(l) => (h / l) * h * h * h,
            Tempering::Fixed(j) => j,
            Tempering::Off => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];

    fn apply(k: &[[f64; 12]; 12], u: &[f64; 12]) -> [f64; 12] {
        let mut out = [0.0; 12];
        for (o, row) in out.iter_mut().zip(k) {
            *o = row.iter().zip(u).map(|(a, b)| a * b).sum();
        }
        out
    }

    /// The six rigid motions at the corners `x`: three translations, three
    /// infinitesimal rotations u = ω × x.
    fn rigid(x: &[[f64; 3]; 4]) -> Vec<[f64; 12]> {
        let mut modes = Vec::new();
        for axis in 0..3 {
            let mut t = [0.0; 12];
            let mut w = [0.0; 3];
            w[axis] = 1.0;
            let mut r = [0.0; 12];
            for n in 0..4 {
                t[3 * n + axis] = 1.0;
                let u = cross(w, x[n]);
                r[3 * n..3 * n + 3].copy_from_slice(&u);
            }
            modes.push(t);
            modes.push(r);
        }
        modes
    }

    #[test]
    fn the_unit_tetrahedron_has_j_one_and_the_gradients_of_its_shape_functions() {
        let g = TetGeometry::new(&UNIT);
        assert_eq!(g.j, 1.0);
        assert_eq!(
            g.a,
            [
                [-1.0, -1.0, -1.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0]
            ]
        );
        assert_eq!(g.h, 2f64.sqrt());
    }

    #[test]
    fn rigid_motions_cost_nothing_flat_or_not() {
        let d = isotropic_d(1.0, 0.3).unwrap();
        let flat = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.3, 0.4, 0.0],
        ];
        for x in [UNIT, flat] {
            let k = stiffness(&TetGeometry::new(&x), &d, 1e-3).unwrap();
            let size = k.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
            for r in rigid(&x) {
                let f = apply(&k, &r);
                assert!(f.iter().all(|v| v.abs() < 1e-14 * size), "{f:?}");
            }
        }
    }

    #[test]
    fn a_uniform_strain_stores_the_volume_times_its_energy_density() {
        let d = isotropic_d(2.0, 0.25).unwrap();
        let x = [
            [0.1, 0.0, 0.2],
            [1.3, 0.1, 0.0],
            [0.2, 0.9, 0.1],
            [0.3, 0.2, 1.1],
        ];
        let g = TetGeometry::new(&x);
        let k = stiffness(&g, &d, 0.0).unwrap();
        // u = E x with a symmetric E: ε = (E_xx, E_yy, E_zz, 2E_yz, 2E_xz, 2E_xy).
        let e = [
            [1e-3, 2e-4, -3e-4],
            [2e-4, -5e-4, 1e-4],
            [-3e-4, 1e-4, 2e-3],
        ];
        let mut u = [0.0; 12];
        for n in 0..4 {
            for i in 0..3 {
                u[3 * n + i] = (0..3).map(|j| e[i][j] * x[n][j]).sum();
            }
        }
        let eps = [
            e[0][0],
            e[1][1],
            e[2][2],
            2.0 * e[1][2],
            2.0 * e[0][2],
            2.0 * e[0][1],
        ];
        let density: f64 = (0..6)
            .flat_map(|r| (0..6).map(move |c| (r, c)))
            .map(|(r, c)| eps[r] * d[r][c] * eps[c])
            .sum();
        let energy: f64 = u.iter().zip(apply(&k, &u)).map(|(a, b)| a * b).sum();
        let want = g.j / 6.0 * density;
        assert!((energy - want).abs() < 1e-13 * want, "{energy} vs {want}");
    }

    #[test]
    fn below_jmin_the_stiffness_is_scaled_by_j_over_jmin() {
        let d = isotropic_d(1.0, 0.3).unwrap();
        let g = TetGeometry::new(&UNIT);
        let (plain, tempered) = (
            stiffness(&g, &d, 0.5).unwrap(),
            stiffness(&g, &d, 4.0).unwrap(),
        );
        for (p, t) in plain.iter().flatten().zip(tempered.iter().flatten()) {
            assert!(
                (t - p / 4.0).abs() <= 1e-16 * p.abs().max(1.0),
                "{t} vs {p}"
            );
        }
    }

    #[test]
    fn a_flat_tetrahedron_without_tempering_is_refused() {
        let d = isotropic_d(1.0, 0.3).unwrap();
        let flat = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        let e = stiffness(&TetGeometry::new(&flat), &d, 0.0).unwrap_err();
        assert!(e.message().contains("J = 0"), "{e}");
    }

    #[test]
    fn bad_moduli_are_refused_naming_them() {
        assert!(
            isotropic_d(0.0, 0.3)
                .unwrap_err()
                .message()
                .contains("Young")
        );
        assert!(
            isotropic_d(1.0, 0.5)
                .unwrap_err()
                .message()
                .contains("Poisson")
        );
    }

    #[test]
    fn gap_weights_measure_the_normal_opening_of_a_flat_prism_tetrahedron() {
        // The cap of a flat prism over the triangle (0,0), (1,0), (0,1) at
        // z = 0: bottom node 0, top nodes 1, 2, 3 over bottom nodes 0, 1, 2.
        let x = [
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let geo = TetGeometry::new(&x);
        assert_eq!(geo.j, 0.0);
        let w = gap_weights(&geo, [0.0, 0.0, 1.0]);
        let opening = |d: [f64; 3]| -> f64 {
            // The top nodes move by d, the bottom one stays.
            (3..12).map(|i| w[i] * d[i % 3]).sum()
        };
        // Twice the facing area (1/2) times the normal opening.
        assert!((opening([0.0, 0.0, 0.3]).abs() - 0.3).abs() < 1e-15);
        assert_eq!(opening([0.7, -0.2, 0.0]), 0.0, "sliding is not an opening");
        let k = contact_stiffness(&w, 2.0, 0.5).unwrap();
        let u: Vec<f64> = (0..12)
            .map(|i| if i >= 3 && i % 3 == 0 { 1.0 } else { 0.0 })
            .collect();
        let energy: f64 = (0..12)
            .map(|i| (0..12).map(|j| u[i] * k[i][j] * u[j]).sum::<f64>())
            .sum();
        assert_eq!(energy, 0.0, "a tangential slide of the top costs nothing");
        for (e_c, t) in [
            (0.0, 1.0),
            (1.0, 0.0),
            (f64::NAN, 1.0),
            (1.0, f64::INFINITY),
        ] {
            assert!(
                contact_stiffness(&w, e_c, t).is_err(),
                "E_c = {e_c}, T = {t}"
            );
        }
        assert!(
            contact_stiffness(&w, 1e300, 1e-300).is_err(),
            "an overflow is refused"
        );
    }
}
