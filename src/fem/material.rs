//! Linear isotropic elastic materials in plane strain, plane stress or
//! axisymmetry, and the section a 2D element stands for ([`Section`]).

use crate::error::{Error, Result, Status};

/// The 2D idealisation of the out-of-plane direction.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaneMode {
    /// ε_zz = 0 (thick bodies; the seed's setting).
    Strain = 0,
    /// σ_zz = 0 (thin plates).
    Stress = 1,
    /// Bodies of revolution about the axis x = 0: x is the radius r ≥ 0,
    /// y the axial coordinate z, and the hoop strain ε_θθ = u_r/r. Every
    /// force and stiffness is that of the whole ring (2π radians):
    /// docs/method.md §7.
    Axisymmetric = 2,
}

impl PlaneMode {
    /// Decodes the C ABI integer (0 = strain, 1 = stress, 2 =
    /// axisymmetric).
    pub fn from_i32(value: i32) -> Option<PlaneMode> {
        match value {
            0 => Some(PlaneMode::Strain),
            1 => Some(PlaneMode::Stress),
            2 => Some(PlaneMode::Axisymmetric),
            _ => None,
        }
    }

    /// The mode's name in messages.
    pub fn name(self) -> &'static str {
        match self {
            PlaneMode::Strain => "plane strain",
            PlaneMode::Stress => "plane stress",
            PlaneMode::Axisymmetric => "axisymmetric",
        }
    }
}

/// What a 2D element stands for in 3D: a slab of unit thickness or a ring
/// about the axis x = 0. The one place where the plane modes differ in
/// kind; everything above `fem/` sees only the weight it gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// A slab of unit thickness: plane strain or plane stress.
    Plane,
    /// A ring about the axis: each point of the section weighs 2πr, and
    /// the hoop strain ε_θθ = u_r/r adds a fourth row to the strain with
    /// these entries of the 4×4 D (docs/method.md §7).
    Revolution {
        /// D_θθ,rr = D_θθ,zz = λ.
        coupling: f64,
        /// D_θθ,θθ = λ + 2μ.
        hoop: f64,
    },
}

impl Section {
    /// The measure of a point at abscissa `x` (the radius of a ring):
    /// 1 in the plane, 2πx for a ring (0 on or across the axis).
    #[inline]
    pub fn weight(&self, x: f64) -> f64 {
        match self {
            Section::Plane => 1.0,
            Section::Revolution { .. } => std::f64::consts::TAU * x.max(0.0),
        }
    }

    /// The shares ∫ φ_p w ds, ∫ φ_q w ds of a straight edge from abscissa
    /// `xp` to `xq` of length `len`: len/2 each in the plane; for a ring,
    /// 2π len (2x_p + x_q)/6 and 2π len (x_p + 2x_q)/6 (exact: w is linear).
    #[inline]
    pub fn edge_shares(&self, xp: f64, xq: f64, len: f64) -> [f64; 2] {
        match self {
            Section::Plane => [0.5 * len, 0.5 * len],
            Section::Revolution { .. } => {
                let (p, q) = (xp.max(0.0), xq.max(0.0));
                let s = std::f64::consts::TAU * len / 6.0;
                [s * (2.0 * p + q), s * (p + 2.0 * q)]
            }
        }
    }

    /// The nodal forces ∫ φ_i b w dA of a uniform body force `b` on a
    /// triangle of area `area` whose corners lie at abscissas `x`: b·area/3
    /// each in the plane; for a ring, b·2π area (2x_i + x_j + x_k)/12
    /// (exact).
    #[inline]
    pub fn corner_loads(&self, x: [f64; 3], area: f64, b: [f64; 2]) -> [[f64; 2]; 3] {
        match self {
            Section::Plane => [[b[0] * area / 3.0, b[1] * area / 3.0]; 3],
            Section::Revolution { .. } => {
                let x = x.map(|v| v.max(0.0));
                let s = std::f64::consts::TAU * area / 12.0;
                std::array::from_fn(|i| {
                    let share = s * (x[0] + x[1] + x[2] + x[i]);
                    [b[0] * share, b[1] * share]
                })
            }
        }
    }

    /// The shares ∫ (1 − t) w dt and ∫ t w dt over t ∈ [lo, hi] of an edge
    /// running from abscissa `x0` (t = 0) to `x1` (t = 1), per unit
    /// length: a node's tributary over part of the edge. In the plane
    /// (hi − lo) − (hi² − lo²)/2 and (hi² − lo²)/2.
    pub fn span_shares(&self, x0: f64, x1: f64, lo: f64, hi: f64) -> [f64; 2] {
        match self {
            Section::Plane => {
                let half_moment = 0.5 * (hi * hi - lo * lo);
                [(hi - lo) - half_moment, half_moment]
            }
            Section::Revolution { .. } => {
                // w = 2π(x0 (1 − t) + x1 t): ∫(1−t)², ∫t(1−t), ∫t².
                let (a, b) = (x0.max(0.0), x1.max(0.0));
                let cube = |t: f64| t * t * t;
                let outer = (cube(1.0 - lo) - cube(1.0 - hi)) / 3.0;
                let mixed = 0.5 * (hi * hi - lo * lo) - (cube(hi) - cube(lo)) / 3.0;
                let inner = (cube(hi) - cube(lo)) / 3.0;
                let tau = std::f64::consts::TAU;
                [tau * (a * outer + b * mixed), tau * (a * mixed + b * inner)]
            }
        }
    }

    /// Whether the section is a ring.
    pub fn is_revolution(&self) -> bool {
        matches!(self, Section::Revolution { .. })
    }
}

/// A linear isotropic elastic material: Young's modulus, Poisson ratio and
/// plane mode. Stresses are per unit thickness in the units of `young`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    young: f64,
    poisson: f64,
    plane: PlaneMode,
}

impl Material {
    /// Checks and builds a material. `what` names its owner in messages
    /// (e.g. "body 2").
    ///
    /// Rejects E <= 0 or non-finite, and ν outside (-1, 0.5) in plane strain
    /// and axisymmetry (the 3D bulk modulus must be positive and finite) or
    /// outside (-1, 0.5] in plane stress (where ν = 0.5 keeps D finite).
    pub fn new(young: f64, poisson: f64, plane: PlaneMode, what: &str) -> Result<Material> {
        if !(young.is_finite() && young > 0.0) {
            return Err(Error::new(
                Status::InvalidMaterial,
                format!("{what}: Young's modulus E = {young:?} must be finite and > 0"),
            ));
        }
        let (upper_ok, range) = match plane {
            PlaneMode::Strain | PlaneMode::Axisymmetric => (poisson < 0.5, "(-1, 0.5)"),
            PlaneMode::Stress => (poisson <= 0.5, "(-1, 0.5]"),
        };
        if !(poisson.is_finite() && poisson > -1.0 && upper_ok) {
            return Err(Error::new(
                Status::InvalidMaterial,
                format!(
                    "{what}: Poisson ratio nu = {poisson:?} must lie in {range} in {}",
                    plane.name()
                ),
            ));
        }
        Ok(Material {
            young,
            poisson,
            plane,
        })
    }

    /// The same material with another Young's modulus (already checked to
    /// be finite and > 0 by the caller).
    pub fn with_young(&self, young: f64) -> Material {
        debug_assert!(young.is_finite() && young > 0.0);
        Material { young, ..*self }
    }

    /// Young's modulus.
    pub fn young(&self) -> f64 {
        self.young
    }

    /// Poisson ratio.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// Plane mode.
    pub fn plane(&self) -> PlaneMode {
        self.plane
    }

    /// The in-plane 3x3 elasticity matrix D in Voigt notation with
    /// engineering shear: σ = D ε with ε = [ε_xx, ε_yy, γ_xy], σ = [σ_xx,
    /// σ_yy, σ_xy] (for a ring, the block of the 4×4 D without the hoop
    /// row, which [`Material::section`] gives).
    pub fn d_matrix(&self) -> [[f64; 3]; 3] {
        let (lambda, mu) = self.lame();
        [
            [lambda + 2.0 * mu, lambda, 0.0],
            [lambda, lambda + 2.0 * mu, 0.0],
            [0.0, 0.0, mu],
        ]
    }

    /// The in-plane λ and the shear modulus μ; Lamé form, which stays
    /// accurate as ν -> 0.5 (only λ grows).
    fn lame(&self) -> (f64, f64) {
        let (e, nu) = (self.young, self.poisson);
        let mu = e / (2.0 * (1.0 + nu));
        let lambda = match self.plane {
            PlaneMode::Strain | PlaneMode::Axisymmetric => e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
            PlaneMode::Stress => e * nu / (1.0 - nu * nu),
        };
        (lambda, mu)
    }

    /// The section an element of this material stands for.
    pub fn section(&self) -> Section {
        match self.plane {
            PlaneMode::Strain | PlaneMode::Stress => Section::Plane,
            PlaneMode::Axisymmetric => {
                let (lambda, mu) = self.lame();
                Section::Revolution {
                    coupling: lambda,
                    hoop: lambda + 2.0 * mu,
                }
            }
        }
    }

    /// The stress normal to the mesh's plane for the in-plane strain `eps`
    /// and the out-of-plane strain `normal` (ε_θθ of a ring; 0 otherwise):
    /// σ_zz = λ(ε_xx + ε_yy) in plane strain, 0 in plane stress, the hoop
    /// stress λ(ε_rr + ε_zz) + (λ + 2μ) ε_θθ for a ring.
    pub fn out_of_plane_stress(&self, eps: &[f64; 3], normal: f64) -> f64 {
        let (lambda, mu) = self.lame();
        match self.plane {
            PlaneMode::Strain => lambda * (eps[0] + eps[1]),
            PlaneMode::Stress => 0.0,
            PlaneMode::Axisymmetric => lambda * (eps[0] + eps[1]) + (lambda + 2.0 * mu) * normal,
        }
    }

    /// The in-plane stress [σ_xx, σ_yy, σ_xy] for the in-plane strain `eps`
    /// and the hoop strain `hoop` (read by a ring only, through λ).
    pub fn in_plane_stress(&self, eps: &[f64; 3], hoop: f64) -> [f64; 3] {
        let d = self.d_matrix();
        let mut sigma: [f64; 3] =
            std::array::from_fn(|r| d[r][0] * eps[0] + d[r][1] * eps[1] + d[r][2] * eps[2]);
        if let Section::Revolution { coupling, .. } = self.section() {
            sigma[0] += coupling * hoop;
            sigma[1] += coupling * hoop;
        }
        sigma
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_nonpositive_young_naming_the_body() {
        let e = Material::new(0.0, 0.3, PlaneMode::Strain, "body 7").unwrap_err();
        assert_eq!(e.status(), Status::InvalidMaterial);
        assert!(e.message().contains("body 7"));
    }

    #[test]
    fn rejects_incompressible_plane_strain_but_accepts_plane_stress() {
        assert!(Material::new(1.0, 0.5, PlaneMode::Strain, "b").is_err());
        assert!(Material::new(1.0, 0.5, PlaneMode::Stress, "b").is_ok());
        assert!(Material::new(1.0, -1.0, PlaneMode::Stress, "b").is_err());
        assert!(Material::new(1.0, f64::NAN, PlaneMode::Stress, "b").is_err());
    }

    #[test]
    fn plane_stress_matrix_matches_textbook_form() {
        let m = Material::new(2.0, 0.25, PlaneMode::Stress, "b").unwrap();
        let d = m.d_matrix();
        let c = 2.0 / (1.0 - 0.0625);
        assert!((d[0][0] - c).abs() < 1e-14);
        assert!((d[0][1] - c * 0.25).abs() < 1e-14);
        assert!((d[2][2] - c * 0.375).abs() < 1e-14);
    }
}
