//! The constitutive law of the elements of B: their tempered stiffness,
//! the load of an initial gap, the contact pressure and the linearised
//! opening that the inversion test reads.

use std::collections::BTreeMap;

use super::{ContactElement, ContactLaw};
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

/// The linearised opening the inversion test uses and the law penalises,
/// the normal part of the linearised J: J0 + Σ (n·g_i)(n·u_i), under
/// either law (docs/method.md §6.5). The stick law penalises it too: its
/// element is flattened ([`law_geometry`]), so its whole linearised J is
/// this normal part (the J0 ε_tt of the unflattened element read the
/// bodies' tangential stretching as an opening).
pub fn linearised_opening(geo: &TriGeometry, n: [f64; 2], ue: &[f64; 6]) -> f64 {
    geo.j
        + (0..3)
            .map(|i| {
                (geo.g[i][0] * n[0] + geo.g[i][1] * n[1])
                    * (ue[2 * i] * n[0] + ue[2 * i + 1] * n[1])
            })
            .sum::<f64>()
}

/// The least error the rounding of the displacements leaves in
/// [`linearised_opening`]: ε (|J0| + Σ |n·g_i| |n·u_i|). Each u_i is known
/// to ε|u_i| at best, so an opening below this bound — the overlap of a
/// very stiff penalty, far below the displacements themselves — is
/// rounding, not a measurement (docs/method.md §6.14).
pub fn opening_rounding(geo: &TriGeometry, n: [f64; 2], ue: &[f64; 6]) -> f64 {
    let terms = (0..3)
        .map(|i| {
            ((geo.g[i][0] * n[0] + geo.g[i][1] * n[1]) * (ue[2 * i] * n[0] + ue[2 * i + 1] * n[1]))
                .abs()
        })
        .sum::<f64>();
    f64::EPSILON * (geo.j.abs() + terms)
}

/// How much an element's contact pressure changes per unit of its opening:
/// n·D·n / T (E_c/T for the frictionless law, whose D is E_c m mᵀ with
/// m·(n⊗n) = 1; the normal modulus of the stick law's D).
pub fn pressure_per_opening(d: &[[f64; 3]; 3], n: [f64; 2], t: f64) -> f64 {
    let en = e_n(n);
    let dn: f64 = (0..3)
        .map(|r| en[r] * (d[r][0] * en[0] + d[r][1] * en[1] + d[r][2] * en[2]))
        .sum();
    dn.abs() / t
}

/// Coefficient of element DOF `a` (node a/2, component a%2) in
/// [`linearised_opening`].
pub fn opening_coefficient(geo: &TriGeometry, n: [f64; 2], a: usize) -> f64 {
    let g = geo.g[a / 2];
    (g[0] * n[0] + g[1] * n[1]) * n[a % 2]
}

/// The geometry through which the law of an element of B acts
/// (docs/method.md §6.4, "The stick law on a gap"): for the stick law the
/// element flattened onto its interface line, g_i → (n·g_i) n (J0, h_e
/// unchanged); for the frictionless law `geo` itself, whose law reads only
/// n·g_i, which flattening keeps.
///
/// Why: an element of B is an interface spring on the jump between the
/// surfaces, Σ (n·g_i) u_i = ℓ_e × (the jump at its apex). Across a gap or
/// an overlap (J0 ≠ 0) the unflattened B̂u also reads J0 × the bodies'
/// strain, and isotropic D turns that strain into stresses: a uniform
/// tangential stretch of both bodies made a normal pressure, and the
/// strip's tangential stress (ν/(1 − ν) of its pressure) acted on the
/// strip's ends, thick |J0|/ℓ_e, as point forces: the patch test with an
/// initial overlap failed by overlap/h. The flattened element has no
/// tangential strain (t·g_i = 0), so only the jump is penalised. On a
/// touching straight interface with an axis-aligned normal flattening is
/// the identity to the bit.
pub fn law_geometry(geo: TriGeometry, law: ContactLaw, n: [f64; 2]) -> TriGeometry {
    match law {
        ContactLaw::Frictionless => geo,
        ContactLaw::Stick => TriGeometry {
            g: geo.g.map(|g| {
                let a = g[0] * n[0] + g[1] * n[1];
                [a * n[0], a * n[1]]
            }),
            ..geo
        },
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

/// The shear vector b_t = ½ B̂ᵀ s of an element with corners `x` and
/// interface normal `n` (docs/method.md §6.15), s = [2 n_x t_x, 2 n_y t_y,
/// n_x t_y + n_y t_x] the engineering shear strain γ_nt of a Voigt strain,
/// t = (−n_y, n_x), and B̂ that of the element flattened onto its interface
/// line (each corner projected along n). It carries the whole tangential
/// side of the frictional law: γ(u) = 2 b_t·u_e (in B̂u units, like the
/// opening); a shear stress τ on the element puts the nodal forces τ b_t;
/// and the stick stiffness is the rank-one (2 G_c / T) b_t b_tᵀ.
///
/// Why flattened: the B̂ of an element with a gap also reads the rotation
/// of its edges (∂u_n/∂t times the gap), so its "slip" would move with the
/// normal closing of a curved gap, and its slip traction would push
/// normally; the flattened element reads the tangential jump alone (exactly
/// the unflattened one on a touching interface).
pub fn shear_vector(x: &[[f64; 2]; 3], n: [f64; 2]) -> [f64; 6] {
    let t = [-n[1], n[0]];
    let c = [
        (x[0][0] + x[1][0] + x[2][0]) / 3.0,
        (x[0][1] + x[1][1] + x[2][1]) / 3.0,
    ];
    let flat: [[f64; 2]; 3] = std::array::from_fn(|i| {
        let s = (x[i][0] - c[0]) * t[0] + (x[i][1] - c[1]) * t[1];
        [c[0] + s * t[0], c[1] + s * t[1]]
    });
    let geo = TriGeometry::new(&flat);
    let s = [
        2.0 * n[0] * t[0],
        2.0 * n[1] * t[1],
        n[0] * t[1] + n[1] * t[0],
    ];
    let b = b_hat(&geo);
    std::array::from_fn(|a| 0.5 * (b[0][a] * s[0] + b[1][a] * s[1] + b[2][a] * s[2]))
}

/// The stick stiffness (2 G_c / T) b_t b_tᵀ of an element with shear
/// vector `bt` ([`shear_vector`]) and G_c / T = `g_over_t`: the tangential
/// part of the stick state, no load of its own.
pub fn stick_stiffness(bt: &[f64; 6], g_over_t: f64) -> ContactStiffness {
    let mut k = [0.0; 36];
    for a in 0..6 {
        for c in a..6 {
            // Mirrored, not recomputed: exactly symmetric for the Cholesky.
            let v = 2.0 * g_over_t * bt[a] * bt[c];
            k[a * 6 + c] = v;
            k[c * 6 + a] = v;
        }
    }
    ContactStiffness { k, f0: [0.0; 6] }
}

/// The penalty length h_c of each pair (indexed by pair): the shortest
/// interface edge of the pair's elements of B (docs/method.md §6.11). One
/// length per pair keeps the penalty κ = E_c λ / h_c² uniform along the
/// interface, which the patch test requires.
pub fn penalty_lengths(elements: &[ContactElement]) -> BTreeMap<usize, f64> {
    let mut h: BTreeMap<usize, f64> = BTreeMap::new();
    for el in elements {
        let v = h.entry(el.pair).or_insert(f64::INFINITY);
        *v = v.min(el.edge_length);
    }
    h
}

/// The tempered Jacobian of every element of B (docs/method.md §6.11):
/// T_e = ℓ_e h_c² / λ, with ℓ_e the element's interface edge and h_c its
/// pair's penalty length ([`penalty_lengths`]). Its stiffness is then
/// κ ℓ_e / 2 on the gap at its apex, κ = E_c λ / h_c², and its pressure
/// −E_c o_e / T_e = −κ × (the gap at its apex) is the contact traction,
/// whatever the shape of the triangle: any triangulation of the strip then
/// passes the patch test exactly. On a conforming interface of edges h it
/// is the seed's Jmin = h³/λ (to the bit when every edge has the same
/// length).
///
/// An element whose edge faces the other side over f_e < ℓ_e only (the
/// other side ends inside it) gets T_e × ℓ_e/f_e, hence the stiffness
/// κ f_e/2: the strip is then that of the sides clipped to where they face
/// each other, and the patch test holds there too (§6.11, "Sides that end
/// inside an edge"). Its law's pressure is then f_e/ℓ_e of the traction
/// ([`crate::contact::ContactSet::pressure`] reports the traction).
pub fn contact_jmins(elements: &[ContactElement], lambda: f64) -> Vec<f64> {
    let h = penalty_lengths(elements);
    elements
        .iter()
        .map(|el| {
            let hc = h[&el.pair];
            let t = (el.edge_length / lambda) * hc * hc;
            // Whole edges keep the expression above, to the bit.
            match el.facing < el.edge_length {
                true => t * (el.edge_length / el.facing),
                false => t,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::mesh::{Nodes, conforming, nonconforming, straight_sides};
    use crate::fem::element::jmin_of_lambda;
    use crate::fem::material::{Material, PlaneMode};

    #[test]
    fn a_uniform_conforming_interface_keeps_the_seeds_jmin_to_the_bit() {
        let xs: Vec<f64> = (0..=16).map(|i| i as f64 / 16.0).collect();
        let (x, a, b) = straight_sides(&xs, &xs);
        let nodes = Nodes::new(&x, 0);
        let elements = conforming(nodes, 0, &a, &b).unwrap();
        let lambda = 1.0;
        for (el, t) in elements.iter().zip(contact_jmins(&elements, lambda)) {
            assert_eq!(t, jmin_of_lambda(el.h, lambda));
        }
    }

    /// The nodal forces of a uniform gap across the strip between straight
    /// sides at `xa` (below) and `xb` (above) against the consistent loads
    /// κ g ∫_I φ_i of the traction over the interval I where they face each
    /// other (docs/method.md §6.11); every element's pressure must be that
    /// traction.
    fn assert_uniform_gap_gives_the_traction_over_the_overlap(xa: &[f64], xb: &[f64]) {
        let (x, a, b) = straight_sides(xa, xb);
        let nodes = Nodes::new(&x, 0);
        let elements = nonconforming(nodes, 0, &a, &b).unwrap();
        let (e_c, lambda) = (2.0, 3.0);
        let soft = Material::new(e_c, 0.3, PlaneMode::Strain, "soft").unwrap();
        let jmins = contact_jmins(&elements, lambda);
        let hc = penalty_lengths(&elements)[&0];
        let kappa = e_c * lambda / (hc * hc);
        // Side b moved by g along n = (0, 1): the gap g everywhere.
        let g = -1e-3;
        let mut force = vec![0.0; x.len()];
        for (el, &t) in elements.iter().zip(&jmins) {
            let geo = TriGeometry::new(&nodes.corners(&el.nodes));
            let d = law_matrix(ContactLaw::Frictionless, e_c, &soft, el.normal);
            let cs = contact_stiffness(&geo, &d, el.normal, el.j0, t);
            let ue: [f64; 6] = std::array::from_fn(|c| {
                if c % 2 == 1 && el.nodes[c / 2] >= xa.len() {
                    g
                } else {
                    0.0
                }
            });
            for r in 0..6 {
                if r % 2 == 1 {
                    force[el.nodes[r / 2]] -= (0..6).map(|c| cs.k[r * 6 + c] * ue[c]).sum::<f64>();
                }
            }
            // The element's pressure is the traction −κ g (its law's, the
            // share of it its edge faces).
            let p = contact_pressure(&geo, &d, el.normal, el.j0, t, &ue) / el.facing_share();
            assert!((p + kappa * g).abs() < 1e-12 * kappa * g.abs(), "{p}");
        }
        let (lo, hi) = (xa[0].max(xb[0]), xa[xa.len() - 1].min(xb[xb.len() - 1]));
        // ∫ over [lo, hi] of the hat of node i of the side at `xs`.
        let consistent = |xs: &[f64], i: usize| {
            let mut m = 0.0;
            for (k, e) in xs.windows(2).enumerate() {
                let (s0, s1) = (e[0].max(lo), e[1].min(hi));
                if s1 <= s0 || (k != i && k + 1 != i) {
                    continue;
                }
                // The hat is linear on the edge: its mean over [s0, s1]
                // is its value at the midpoint.
                let mid = 0.5 * (s0 + s1);
                let phi = if k == i {
                    (e[1] - mid) / (e[1] - e[0])
                } else {
                    (mid - e[0]) / (e[1] - e[0])
                };
                m += (s1 - s0) * phi;
            }
            m
        };
        for (i, f) in force.iter().enumerate() {
            let (m, sign) = if i < xa.len() {
                (consistent(xa, i), 1.0)
            } else {
                (consistent(xb, i - xa.len()), -1.0)
            };
            // Compression pushes side a down and side b up.
            let expected = sign * kappa * g * m;
            assert!(
                (f - expected).abs() < 1e-12 * kappa * g.abs(),
                "xa {xa:?}, xb {xb:?}, node {i}: {f} vs {expected}"
            );
        }
    }

    #[test]
    fn a_uniform_gap_across_any_strip_loads_both_sides_with_a_uniform_traction() {
        // docs/method.md §6.11, the patch-test theorem: 5 against 7 jittered
        // edges over [0, 1].
        assert_uniform_gap_gives_the_traction_over_the_overlap(
            &[0.0, 0.17, 0.43, 0.58, 0.81, 1.0],
            &[0.0, 0.12, 0.33, 0.41, 0.62, 0.7, 0.93, 1.0],
        );
    }

    #[test]
    fn a_uniform_gap_loads_sides_that_end_inside_an_edge_with_the_traction_over_their_overlap() {
        // docs/method.md §6.11, "Sides that end inside an edge": one side
        // ending inside an edge of the other at one end, at both ends, the
        // sides shifted (each ends inside the other's edge), short and
        // long overhangs, coarse against fine.
        let a = [0.0, 0.17, 0.43, 0.58, 0.81, 1.0];
        for xb in [
            vec![0.3, 0.33, 0.41, 0.62, 0.7, 0.93, 1.0],
            vec![0.05, 0.12, 0.33, 0.41, 0.62, 0.7, 0.75],
            vec![0.42, 0.45, 0.5, 0.55, 0.57],
            vec![0.2, 0.3, 0.41, 0.62, 0.7, 0.93, 1.1, 1.3],
            vec![-0.3, -0.01, 0.12, 0.33, 0.41, 0.62, 0.7, 0.8],
            vec![0.16, 0.9],
            vec![0.001, 0.999],
        ] {
            assert_uniform_gap_gives_the_traction_over_the_overlap(&a, &xb);
            assert_uniform_gap_gives_the_traction_over_the_overlap(&xb, &a);
        }
    }
}
