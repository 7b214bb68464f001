//! The tempered P1 triangle (docs/method.md §2), in the adjugate form.
//!
//! With F = ∂x/∂ξ, J = det F and adj(F) its adjugate, the reference
//! gradients mapped by the adjugate are g_i = ∇_ξφ_i · adj(F), so that
//! ∇φ_i = g_i / J. Every stiffness here is written with g_i and a single
//! division by the tempered Jacobian T = max(J, Jmin):
//!
//! * Laplacian: K_ij = κ g_i·g_j / (2T)
//! * elasticity: K = B̂ᵀ D B̂ / (2T), B̂ the strain-displacement matrix built
//!   from the g_i
//!
//! which is finite for J = 0 and J < 0. Plain FEM (tempering off) divides by
//! |J| (the usual area weight) and refuses J = 0.

use super::material::Section;
use crate::error::{Error, Result, Status};

/// Adjugate-mapped gradients, Jacobian and size of one P1 triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriGeometry {
    /// g_i = ∇_ξφ_i · adj(F), i.e. (y_j - y_k, x_k - x_j) for (i, j, k) cyclic.
    pub g: [[f64; 2]; 3],
    /// J = det F = twice the signed area (positive for counter-clockwise).
    pub j: f64,
    /// The longest edge h_e.
    pub h: f64,
}

/// Accurate a*d - b*c: the Jacobian of a sliver is a difference of nearly
/// equal products. Without cancellation (|ad − bc| ≥ (|ad| + |bc|)/2) the
/// plain difference is within 3ε of it; otherwise Kahan's algorithm with
/// fused multiply-add (1.5ε), which costs two calls into libm where the
/// build target has no FMA instruction.
fn det2(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let (ad, bc) = (a * d, b * c);
    let plain = ad - bc;
    if plain.abs() >= 0.5 * (ad.abs() + bc.abs()) {
        return plain;
    }
    // Kahan: e is the rounding error of bc, f = ad − bc rounded once.
    let e = (-b).mul_add(c, bc);
    let f = a.mul_add(d, -bc);
    f + e
}

impl TriGeometry {
    /// Computes the geometry of the triangle with vertices `p`.
    #[inline(always)]
    pub fn new(p: &[[f64; 2]; 3]) -> TriGeometry {
        let [[x1, y1], [x2, y2], [x3, y3]] = *p;
        let g = [[y2 - y3, x3 - x2], [y3 - y1, x1 - x3], [y1 - y2, x2 - x1]];
        let j = det2(x2 - x1, x3 - x1, y2 - y1, y3 - y1);
        // One square root of the largest squared length; hypot (no
        // overflow or underflow, but ~10x slower) only when the squares
        // leave the normal range (coordinates beyond ~1e±150).
        let sq = |a: [f64; 2]| a[0] * a[0] + a[1] * a[1];
        let h2 = sq(g[0]).max(sq(g[1])).max(sq(g[2]));
        let h = if h2.is_normal() || (h2 == 0.0 && g.iter().flatten().all(|&c| c == 0.0)) {
            h2.sqrt()
        } else {
            let len = |a: [f64; 2]| a[0].hypot(a[1]);
            len(g[0]).max(len(g[1])).max(len(g[2]))
        };
        TriGeometry { g, j, h }
    }

    /// True when all three vertices coincide (every g_i is zero).
    pub fn is_point(&self) -> bool {
        self.h == 0.0
    }
}

/// How Jmin is chosen (docs/method.md §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tempering {
    /// Jmin = min(h_e³/λ, [`WELL_SHAPED`] h_e²) with λ = the larger side of
    /// the mesh's bounding box (the default; the seed's λ = 1 m for its 1 m
    /// model). It scales with the model, so metres and millimetres give the
    /// same physical answer. The cap, which acts only where h_e > λ/10,
    /// leaves every well-shaped element untouched (docs/method.md §6.1).
    Auto,
    /// Jmin = h_e³/λ with this λ, a length in model units.
    Lambda(f64),
    /// The same Jmin for every element (units of length²).
    Fixed(f64),
    /// Plain FEM: divide by |J|; a zero Jacobian is an error.
    Off,
}

impl Tempering {
    /// Checks the parameter of the policy.
    pub fn validate(&self) -> Result<()> {
        match *self {
            Tempering::Lambda(l) if !(l.is_finite() && l > 0.0) => Err(Error::argument(format!(
                "tempering lambda = {l:?} must be finite and > 0"
            ))),
            Tempering::Fixed(j) if !(j.is_finite() && j > 0.0) => Err(Error::argument(format!(
                "tempering jmin = {j:?} must be finite and > 0"
            ))),
            _ => Ok(()),
        }
    }
}

/// The shape quality J/h_e² (the apex's height over the longest edge) from
/// which an element counts as well-shaped: [`Tempering::Auto`] never
/// softens it, and a solve warns when another policy does.
pub const WELL_SHAPED: f64 = 0.1;

impl Tempering {
    /// The Jmin of an element of longest edge `geo.h` in a model whose
    /// bounding box's larger side is `model_size` (the automatic λ).
    pub fn jmin(&self, geo: &TriGeometry, model_size: f64) -> Jmin {
        match *self {
            Tempering::Auto => {
                Jmin::Tempered(jmin_of_lambda(geo.h, model_size).min(WELL_SHAPED * geo.h * geo.h))
            }
            Tempering::Lambda(l) => Jmin::from_lambda(geo.h, l),
            Tempering::Fixed(j) => Jmin::Tempered(j),
            Tempering::Off => Jmin::Off,
        }
    }
}

/// The tempering applied to one element, resolved from a [`Tempering`]
/// policy and the model size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Jmin {
    /// Divide by max(J, jmin).
    Tempered(f64),
    /// Divide by |J| (plain FEM).
    Off,
}

impl Jmin {
    /// Jmin = h³/λ, written to avoid overflow/underflow of h³ when possible.
    pub fn from_lambda(h: f64, lambda: f64) -> Jmin {
        Jmin::Tempered(jmin_of_lambda(h, lambda))
    }
}

/// Jmin = h³/λ as a number.
pub fn jmin_of_lambda(h: f64, lambda: f64) -> f64 {
    (h / lambda) * h * h
}

/// The value T that replaces J in the denominator, or an error for an
/// element that plain FEM cannot integrate. `None` means the element is a
/// single point: its stiffness is exactly zero (all g_i vanish).
#[inline]
fn denominator(geo: &TriGeometry, jmin: Jmin) -> Result<Option<f64>> {
    let t = match jmin {
        Jmin::Tempered(jm) => geo.j.max(jm),
        Jmin::Off => geo.j.abs(),
    };
    if t > 0.0 {
        return Ok(Some(t));
    }
    if geo.is_point() && matches!(jmin, Jmin::Tempered(_)) {
        return Ok(None);
    }
    let why = match jmin {
        Jmin::Off => "zero Jacobian with tempering off (plain FEM cannot integrate it)",
        Jmin::Tempered(_) => "zero Jacobian and Jmin underflows to zero",
    };
    Err(Error::new(
        Status::DegenerateElement,
        format!("degenerate element: {why}"),
    ))
}

/// The tempered Jacobian T used for an element (J itself for a healthy one).
pub fn tempered_jacobian(geo: &TriGeometry, jmin: Jmin) -> Result<Option<f64>> {
    denominator(geo, jmin)
}

/// B̂ (3x6): strain-displacement matrix times J, Voigt [ε_xx, ε_yy, γ_xy],
/// DOFs ordered (u1, v1, u2, v2, u3, v3).
pub fn b_hat(geo: &TriGeometry) -> [[f64; 6]; 3] {
    let mut b = [[0.0; 6]; 3];
    for (i, gi) in geo.g.iter().enumerate() {
        b[0][2 * i] = gi[0];
        b[1][2 * i + 1] = gi[1];
        b[2][2 * i] = gi[1];
        b[2][2 * i + 1] = gi[0];
    }
    b
}

/// K = B̂ᵀ D B̂ / (2T) for any symmetric 3x3 D (isotropic, or the
/// frictionless contact law). Returns zeros for a point element.
pub fn elasticity_stiffness(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    jmin: Jmin,
) -> Result<[[f64; 6]; 6]> {
    let mut k = [[0.0; 6]; 6];
    elasticity_stiffness_into(geo, d, jmin, &mut k)?;
    Ok(k)
}

/// [`elasticity_stiffness`] written into `k` (every entry), for the
/// assembly loop: no 288-byte result to move per triangle. On error `k`
/// holds garbage.
///
/// Written block by block on the nonzeros of B̂ (each node's columns are
/// [g_x, 0, g_y] and [0, g_y, g_x]): the same sums, term for term, as the
/// dense product B̂ᵀ (D B̂), so the values are the same to the last bit for
/// finite input, at about half its cost (82 → 45 ns per triangle with the
/// geometry, measured in isolation).
#[inline]
pub(crate) fn elasticity_stiffness_into(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    jmin: Jmin,
    k: &mut [[f64; 6]; 6],
) -> Result<()> {
    let Some(t) = denominator(geo, jmin)? else {
        *k = [[0.0; 6]; 6];
        return Ok(());
    };
    // DB = D B̂: node j's columns (u_j, v_j).
    let db: [[[f64; 2]; 3]; 3] = std::array::from_fn(|j| {
        let [gx, gy] = geo.g[j];
        std::array::from_fn(|r| [d[r][0] * gx + d[r][2] * gy, d[r][1] * gy + d[r][2] * gx])
    });
    let scale = 0.5 / t;
    for i in 0..3 {
        let [gx, gy] = geo.g[i];
        for j in i..3 {
            let x = &db[j];
            // Rows u_i = [g_x, 0, g_y] and v_i = [0, g_y, g_x] of B̂ᵀ; the
            // lower triangle mirrors the upper one.
            for c in 0..2 {
                let u = (gx * x[0][c] + gy * x[2][c]) * scale;
                let v = (gy * x[1][c] + gx * x[2][c]) * scale;
                k[2 * j + c][2 * i] = u;
                k[2 * j + c][2 * i + 1] = v;
                k[2 * i][2 * j + c] = u;
                k[2 * i + 1][2 * j + c] = v;
            }
        }
    }
    finite_or_error(k.iter().flatten())
}

/// The tempered stiffness of a body element of section `section` whose
/// centroid lies at abscissa `x` (docs/method.md §7), into `k`.
///
/// In the plane, [`elasticity_stiffness_into`]. For a ring, tfem's rule
/// K̃ = (J/T) K applied to the axisymmetric element of the one-point rule,
/// in the adjugate form: with H the hoop row (1/(3x̄) on each u_r) and
/// D₄ the 4×4 D,
///
/// K̃ = 2πx̄ (B̂ + J H)ᵀ D₄ (B̂ + J H) / (2T)
///   = 2πx̄ B̂ᵀDB̂/(2T) + [2πJ/3 (v eᵀ + e vᵀ) + D_θθ 2πJ²/(9x̄) e eᵀ] / (2T),
///
/// v = B̂ᵀ D₄'s hoop column (λ g_i on each node's two unknowns), e the u_r
/// indicator. A Gram form, so semidefinite for every J; plain FEM for
/// J ≥ Jmin; at J = 0 the planar tempered element weighted by 2πx̄. Its
/// hoop terms stay finite up to the axis: |J| ≤ 3x̄ h_e, so J²/x̄ ≤ 9x̄h_e².
#[inline]
pub(crate) fn section_stiffness_into(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    section: Section,
    x: f64,
    jmin: Jmin,
    k: &mut [[f64; 6]; 6],
) -> Result<()> {
    elasticity_stiffness_into(geo, d, jmin, k)?;
    let Section::Revolution { coupling, hoop } = section else {
        return Ok(());
    };
    let Some(t) = denominator(geo, jmin)? else {
        return Ok(());
    };
    let w = section.weight(x);
    for row in k.iter_mut() {
        for v in row.iter_mut() {
            *v *= w;
        }
    }
    let tau = std::f64::consts::TAU;
    let cross = tau * geo.j / 3.0 / (2.0 * t);
    let ring = match geo.j != 0.0 && x > 0.0 {
        true => hoop * tau * geo.j * geo.j / (9.0 * x) / (2.0 * t),
        false => 0.0,
    };
    // v: the hoop column of D₄ through B̂, λ (g_x, g_y) at each node; e:
    // the u_r indicator. Mirrored, not recomputed: exactly symmetric.
    let v: [f64; 6] = std::array::from_fn(|c| coupling * geo.g[c / 2][c % 2]);
    let e = |a: usize| if a % 2 == 0 { 1.0 } else { 0.0 };
    for a in 0..6 {
        for c in a..6 {
            let extra = cross * (e(a) * v[c] + v[a] * e(c)) + ring * e(a) * e(c);
            k[a][c] += extra;
            k[c][a] = k[a][c];
        }
    }
    finite_or_error(k.iter().flatten())
}

/// The tempered stiffness of a body element of section `section` with
/// corners `p`: in the plane B̂ᵀDB̂/(2T), for a ring 2πx̄ (B̂ + J H)ᵀ D₄
/// (B̂ + J H)/(2T), tfem's (J/T)·K (docs/method.md §7.2).
pub fn section_stiffness(
    p: &[[f64; 2]; 3],
    d: &[[f64; 3]; 3],
    section: Section,
    jmin: Jmin,
) -> Result<[[f64; 6]; 6]> {
    let mut k = [[0.0; 6]; 6];
    let x = (p[0][0] + p[1][0] + p[2][0]) / 3.0;
    section_stiffness_into(&TriGeometry::new(p), d, section, x, jmin, &mut k)?;
    Ok(k)
}

/// The hoop strain ε_θθ that [`section_stiffness`] reads on a ring
/// element with centroid abscissa `x`, element values `ue` and tempered
/// Jacobian `t`: (J/T) ū_r/x̄ (ū_r/x̄ where J ≥ Jmin; 0 on the axis).
pub fn hoop_strain(geo: &TriGeometry, x: f64, t: f64, ue: &[f64; 6]) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    let mean = (ue[0] + ue[2] + ue[4]) / 3.0;
    let ratio = if geo.j == t { 1.0 } else { geo.j / t };
    ratio * mean / x
}

/// Scalar Laplacian K_ij = κ g_i·g_j / (2T). Returns zeros for a point
/// element.
pub fn laplacian_stiffness(geo: &TriGeometry, kappa: f64, jmin: Jmin) -> Result<[[f64; 3]; 3]> {
    let Some(t) = denominator(geo, jmin)? else {
        return Ok([[0.0; 3]; 3]);
    };
    let scale = 0.5 * kappa / t;
    let mut k = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            let v = (geo.g[i][0] * geo.g[j][0] + geo.g[i][1] * geo.g[j][1]) * scale;
            k[i][j] = v;
            k[j][i] = v;
        }
    }
    finite_or_error(k.iter().flatten())?;
    Ok(k)
}

#[inline]
fn finite_or_error<'a>(values: impl Iterator<Item = &'a f64>) -> Result<()> {
    // No short-circuit: one branch per element rather than one per entry
    // (nearly every element passes).
    if !values.fold(false, |bad, v| bad | !v.is_finite()) {
        Ok(())
    } else {
        Err(overflow())
    }
}

#[cold]
fn overflow() -> Error {
    Error::new(
        Status::NumericalFailure,
        "element stiffness overflows (coordinates or moduli too extreme)",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const D_UNIT: [[f64; 3]; 3] = [[2.0, 0.5, 0.0], [0.5, 2.0, 0.0], [0.0, 0.0, 0.75]];

    #[test]
    fn jacobian_is_twice_the_signed_area() {
        let g = TriGeometry::new(&[[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]]);
        assert_eq!(g.j, 2.0);
        let g = TriGeometry::new(&[[0.0, 0.0], [0.0, 1.0], [2.0, 0.0]]);
        assert_eq!(g.j, -2.0);
    }

    #[test]
    fn a_sliver_jacobian_is_exact_where_the_plain_difference_cancels() {
        // a·d − b·c with a = d = 1 + 2⁻³⁰, b = 1, c = 1 + 2⁻²⁹ is exactly
        // 2⁻⁶⁰, below the last bit of either product: the plain difference
        // of the rounded products gives 0.
        let e = 2f64.powi(-30);
        let (a, b, c, d) = (1.0 + e, 1.0, 1.0 + 2.0 * e, 1.0 + e);
        assert_eq!(a * d - b * c, 0.0);
        let geo = TriGeometry::new(&[[0.0, 0.0], [a, c], [b, d]]);
        assert_eq!(geo.j, 2f64.powi(-60));
    }

    /// K = B̂ᵀ (D B̂) / (2T) as dense products, the definition the block
    /// kernel must reproduce.
    fn dense_stiffness(geo: &TriGeometry, d: &[[f64; 3]; 3], jmin: Jmin) -> [[f64; 6]; 6] {
        let t = tempered_jacobian(geo, jmin).unwrap().unwrap();
        let b = b_hat(geo);
        let mut db = [[0.0; 6]; 3];
        for r in 0..3 {
            for c in 0..6 {
                db[r][c] = d[r][0] * b[0][c] + d[r][1] * b[1][c] + d[r][2] * b[2][c];
            }
        }
        let mut k = [[0.0; 6]; 6];
        for a in 0..6 {
            for c in a..6 {
                let v = (b[0][a] * db[0][c] + b[1][a] * db[1][c] + b[2][a] * db[2][c]) * (0.5 / t);
                k[a][c] = v;
                k[c][a] = v;
            }
        }
        k
    }

    #[test]
    fn block_kernel_equals_the_dense_product_to_the_last_bit() {
        // A full symmetric D (like the contact law's) exercises every term.
        let d = [[2.0, 0.5, 0.3], [0.5, 1.7, -0.2], [0.3, -0.2, 0.75]];
        for p in [
            [[0.1, 0.2], [1.3, -0.1], [0.4, 0.9]],
            [[0.0, 0.0], [1.0, 0.0], [0.5, 1e-7]],
            [[0.0, 0.0], [0.3, 1.1], [1.0, 0.1]],
            [[3.0, 1.0], [1.0, 2.0], [2.0, 2.0]],
        ] {
            let geo = TriGeometry::new(&p);
            for jmin in [Jmin::Off, Jmin::Tempered(0.05)] {
                let k = elasticity_stiffness(&geo, &d, jmin).unwrap();
                assert_eq!(k, dense_stiffness(&geo, &d, jmin), "{p:?} {jmin:?}");
            }
        }
    }

    #[test]
    fn a_stiffness_that_overflows_is_an_error_not_infinity() {
        let geo = TriGeometry::new(&[[0.0, 0.0], [1e100, 0.0], [0.0, 1e100]]);
        let huge = [[1e300, 0.0, 0.0], [0.0, 1e300, 0.0], [0.0, 0.0, 1e300]];
        let e = elasticity_stiffness(&geo, &huge, Jmin::Off).unwrap_err();
        assert_eq!(e.status(), Status::NumericalFailure);
        assert!(e.message().contains("overflows"));
    }

    #[test]
    fn healthy_element_is_untouched_by_tempering() {
        let geo = TriGeometry::new(&[[0.0, 0.0], [1.0, 0.0], [0.2, 0.9]]);
        let plain = elasticity_stiffness(&geo, &D_UNIT, Jmin::Off).unwrap();
        let tempered =
            elasticity_stiffness(&geo, &D_UNIT, Jmin::from_lambda(geo.h, 100.0)).unwrap();
        assert_eq!(plain, tempered);
    }

    #[test]
    fn flat_cap_is_finite_and_softened_by_j_over_jmin() {
        let eps = 1e-9;
        let geo = TriGeometry::new(&[[0.0, 0.0], [1.0, 0.0], [0.5, eps]]);
        let jmin = 1e-3;
        let plain = laplacian_stiffness(&geo, 1.0, Jmin::Off).unwrap();
        let tempered = laplacian_stiffness(&geo, 1.0, Jmin::Tempered(jmin)).unwrap();
        let ratio = geo.j / jmin;
        for i in 0..3 {
            for j in 0..3 {
                assert!((tempered[i][j] - ratio * plain[i][j]).abs() <= 1e-12 * plain[i][j].abs());
            }
        }
    }

    #[test]
    fn exactly_degenerate_and_inverted_elements_are_finite_when_tempered() {
        for p in [
            [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]],
            [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0]],
            [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]],
        ] {
            let geo = TriGeometry::new(&p);
            let k = elasticity_stiffness(&geo, &D_UNIT, Jmin::from_lambda(geo.h, 10.0)).unwrap();
            assert!(k.iter().flatten().all(|v| v.is_finite()));
            assert!(k.iter().flatten().any(|v| *v != 0.0));
        }
    }

    #[test]
    fn plain_fem_refuses_a_zero_jacobian() {
        let geo = TriGeometry::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]);
        let e = elasticity_stiffness(&geo, &D_UNIT, Jmin::Off).unwrap_err();
        assert_eq!(e.status(), Status::DegenerateElement);
    }

    #[test]
    fn element_collapsed_to_a_point_has_zero_stiffness_not_nan() {
        let geo = TriGeometry::new(&[[1.0, 2.0]; 3]);
        let k = elasticity_stiffness(&geo, &D_UNIT, Jmin::from_lambda(geo.h, 10.0)).unwrap();
        assert!(k.iter().flatten().all(|v| *v == 0.0));
        let k = laplacian_stiffness(&geo, 1.0, Jmin::from_lambda(geo.h, 10.0)).unwrap();
        assert!(k.iter().flatten().all(|v| *v == 0.0));
    }

    #[test]
    fn rigid_motions_produce_no_force_even_for_flat_elements() {
        for p in [
            [[0.0, 0.0], [1.0, 0.0], [0.3, 0.8]],
            [[0.0, 0.0], [1.0, 0.0], [0.5, 0.0]],
        ] {
            let geo = TriGeometry::new(&p);
            let k = elasticity_stiffness(&geo, &D_UNIT, Jmin::Tempered(0.01)).unwrap();
            let rot: Vec<f64> = p.iter().flat_map(|q| [-q[1], q[0]]).collect();
            for row in &k {
                let f: f64 = row.iter().zip(&rot).map(|(a, b)| a * b).sum();
                assert!(f.abs() < 1e-12 * row.iter().map(|v| v.abs()).sum::<f64>());
            }
        }
    }
}
