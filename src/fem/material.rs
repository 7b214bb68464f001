//! Linear isotropic elastic materials in plane strain or plane stress.

use crate::error::{Error, Result, Status};

/// The 2D idealisation of the out-of-plane direction.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaneMode {
    /// ε_zz = 0 (thick bodies; the seed's setting).
    Strain = 0,
    /// σ_zz = 0 (thin plates).
    Stress = 1,
}

impl PlaneMode {
    /// Decodes the C ABI integer (0 = strain, 1 = stress).
    pub fn from_i32(value: i32) -> Option<PlaneMode> {
        match value {
            0 => Some(PlaneMode::Strain),
            1 => Some(PlaneMode::Stress),
            _ => None,
        }
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
    /// (the 3D bulk modulus must be positive and finite) or outside
    /// (-1, 0.5] in plane stress (where ν = 0.5 keeps D finite).
    pub fn new(young: f64, poisson: f64, plane: PlaneMode, what: &str) -> Result<Material> {
        if !(young.is_finite() && young > 0.0) {
            return Err(Error::new(
                Status::InvalidMaterial,
                format!("{what}: Young's modulus E = {young:?} must be finite and > 0"),
            ));
        }
        let upper_ok = match plane {
            PlaneMode::Strain => poisson < 0.5,
            PlaneMode::Stress => poisson <= 0.5,
        };
        if !(poisson.is_finite() && poisson > -1.0 && upper_ok) {
            let range = match plane {
                PlaneMode::Strain => "(-1, 0.5) in plane strain",
                PlaneMode::Stress => "(-1, 0.5] in plane stress",
            };
            return Err(Error::new(
                Status::InvalidMaterial,
                format!("{what}: Poisson ratio nu = {poisson:?} must lie in {range}"),
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

    /// The 3x3 elasticity matrix D in Voigt notation with engineering shear:
    /// σ = D ε with ε = [ε_xx, ε_yy, γ_xy], σ = [σ_xx, σ_yy, σ_xy].
    pub fn d_matrix(&self) -> [[f64; 3]; 3] {
        let (e, nu) = (self.young, self.poisson);
        let mu = e / (2.0 * (1.0 + nu));
        // Lamé form: stays accurate as ν -> 0.5 (only λ grows).
        let lambda = match self.plane {
            PlaneMode::Strain => e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
            PlaneMode::Stress => e * nu / (1.0 - nu * nu),
        };
        [
            [lambda + 2.0 * mu, lambda, 0.0],
            [lambda, lambda + 2.0 * mu, 0.0],
            [0.0, 0.0, mu],
        ]
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
