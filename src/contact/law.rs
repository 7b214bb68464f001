//! The constitutive law of the elements of B: their tempered stiffness,
//! the load of an initial gap, the contact pressure and the linearised
//! opening that the inversion test reads.

use super::ContactLaw;
use crate::fem::element::{TriGeometry, b_hat};
use crate::fem::material::Material;

/// The element matrix, its load from the initial gap, and the data needed
/// to evaluate its pressure, for one contact element.
pub struct ContactStiffness {
    /// 6x6 stiffness, row-major.
    pub k: [f64; 36],
    /// Equivalent nodal force of the initial opening J0 (zero when touching).
    pub f0: [f64; 6],
}

/// Voigt tensor n⊗n with engineering shear: [n_x², n_y², 2 n_x n_y].
fn e_n(n: [f64; 2]) -> [f64; 3] {
    [n[0] * n[0], n[1] * n[1], 2.0 * n[0] * n[1]]
}

/// The contact constitutive matrix: E_c m mᵀ with m = [n_x², n_y², n_x n_y]
/// for the frictionless law; for the stick law the isotropic D of `soft`
/// (the softer body's material: ν and plane mode) with Young's modulus E_c.
pub fn law_matrix(law: ContactLaw, e_c: f64, soft: &Material, n: [f64; 2]) -> [[f64; 3]; 3] {
    match law {
        ContactLaw::Frictionless => {
            let m = [n[0] * n[0], n[1] * n[1], n[0] * n[1]];
            let mut d = [[0.0; 3]; 3];
            for r in 0..3 {
                for c in 0..3 {
                    d[r][c] = e_c * m[r] * m[c];
                }
            }
            d
        }
        ContactLaw::Stick => soft.with_young(e_c).d_matrix(),
    }
}

/// Stiffness and initial-gap load of an active contact element. An active
/// element is inverted, so max(J, Jmin) = Jmin: `t` is its Jmin.
pub fn contact_stiffness(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    n: [f64; 2],
    j0: f64,
    t: f64,
) -> ContactStiffness {
    let b = b_hat(geo);
    let mut db = [[0.0; 6]; 3];
    for r in 0..3 {
        for c in 0..6 {
            db[r][c] = d[r][0] * b[0][c] + d[r][1] * b[1][c] + d[r][2] * b[2][c];
        }
    }
    let s = 0.5 / t;
    let mut k = [0.0; 36];
    for a in 0..6 {
        for c in a..6 {
            let v = (b[0][a] * db[0][c] + b[1][a] * db[1][c] + b[2][a] * db[2][c]) * s;
            k[a * 6 + c] = v;
            k[c * 6 + a] = v;
        }
    }
    // Pre-strain J0·(n⊗n): f0 = -(1/(2T)) B̂ᵀ D (J0 e_n).
    let en = e_n(n);
    let mut f0 = [0.0; 6];
    if j0 != 0.0 {
        let s0: Vec<f64> = (0..3)
            .map(|r| j0 * (d[r][0] * en[0] + d[r][1] * en[1] + d[r][2] * en[2]))
            .collect();
        for (a, f) in f0.iter_mut().enumerate() {
            *f = -s * (b[0][a] * s0[0] + b[1][a] * s0[1] + b[2][a] * s0[2]);
        }
    }
    ContactStiffness { k, f0 }
}

/// Contact pressure (positive in compression) of an active element with
/// element displacements `ue`: -n·σ·n with σ = D (B̂u + J0 n⊗n) / T.
pub fn contact_pressure(
    geo: &TriGeometry,
    d: &[[f64; 3]; 3],
    n: [f64; 2],
    j0: f64,
    t: f64,
    ue: &[f64; 6],
) -> f64 {
    let b = b_hat(geo);
    let en = e_n(n);
    let mut s = [0.0; 3];
    for r in 0..3 {
        s[r] = (0..6).map(|c| b[r][c] * ue[c]).sum::<f64>() + j0 * en[r];
    }
    let sigma: Vec<f64> = (0..3)
        .map(|r| (d[r][0] * s[0] + d[r][1] * s[1] + d[r][2] * s[2]) / t)
        .collect();
    -(en[0] * sigma[0] + en[1] * sigma[1] + en[2] * sigma[2])
}

/// The linearised Jacobian J0 + Σ g_i·u_i.
/// The linearised opening the inversion test uses and the law penalises:
/// for the frictionless law the normal part of the linearised J,
/// J0 + Σ (n·g_i)(n·u_i); for the stick law the whole linearised J.
pub fn linearised_opening(geo: &TriGeometry, law: ContactLaw, n: [f64; 2], ue: &[f64; 6]) -> f64 {
    match law {
        ContactLaw::Stick => linearised_jacobian(geo, ue),
        ContactLaw::Frictionless => {
            geo.j
                + (0..3)
                    .map(|i| {
                        (geo.g[i][0] * n[0] + geo.g[i][1] * n[1])
                            * (ue[2 * i] * n[0] + ue[2 * i + 1] * n[1])
                    })
                    .sum::<f64>()
        }
    }
}

/// Coefficient of element DOF `a` (node a/2, component a%2) in
/// [`linearised_opening`].
pub fn opening_coefficient(geo: &TriGeometry, law: ContactLaw, n: [f64; 2], a: usize) -> f64 {
    let g = geo.g[a / 2];
    match law {
        ContactLaw::Stick => g[a % 2],
        ContactLaw::Frictionless => (g[0] * n[0] + g[1] * n[1]) * n[a % 2],
    }
}

/// The linearised Jacobian J0 + Σ g_i·u_i of an element with displacements
/// `ue`.
pub fn linearised_jacobian(geo: &TriGeometry, ue: &[f64; 6]) -> f64 {
    geo.j
        + (0..3)
            .map(|i| geo.g[i][0] * ue[2 * i] + geo.g[i][1] * ue[2 * i + 1])
            .sum::<f64>()
}
