//! The exact shape of a curved boundary, declared on the tag of its edges
//! so that refinement puts new nodes on it.
//!
//! A mesh approximates a curved boundary by the chords between its nodes.
//! Bisecting a chord at its midpoint keeps that polygon: however often a
//! curved boundary is refined, the domain keeps the coarse mesh's facets
//! and a geometry error of the size of their sagitta ℓ²/(8R) — at the
//! contact of a cylinder, the very place an adaptive solve refines most,
//! where it then measures a flattened cylinder. A [`Curve`] declared on
//! the tag of the boundary's edges ([`crate::fem::mesh::Mesh::set_curve`])
//! lets [`crate::fem::refine`] place each new node of such an edge on the
//! curve instead (the midpoint projected onto it), so that the refined
//! boundary converges to the curve.

use crate::error::{Error, Result};

/// The exact shape of a tagged boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Curve {
    /// A circle (or an arc of it): the boundary of a cylinder, a ring or a
    /// hole in the plane, a sphere or a torus in a ring's section.
    Circle {
        /// Its centre.
        center: [f64; 2],
        /// Its radius (> 0).
        radius: f64,
    },
}

/// How far from its curve a node may lie, relative to the curve's size
/// (the radius): a mesh written with seven significant digits meets it;
/// a curve declared with the wrong centre or radius does not.
pub const CURVE_TOLERANCE: f64 = 1e-6;

impl Curve {
    /// Checks that the curve is well defined, naming what is not.
    pub fn validate(&self) -> Result<()> {
        match *self {
            Curve::Circle { center, radius } => {
                if !(center[0].is_finite() && center[1].is_finite()) {
                    return Err(Error::argument(format!(
                        "the circle's centre ({:?}, {:?}) is not finite",
                        center[0], center[1]
                    )));
                }
                if !(radius.is_finite() && radius > 0.0) {
                    return Err(Error::argument(format!(
                        "the circle's radius = {radius:?} must be finite and > 0"
                    )));
                }
                Ok(())
            }
        }
    }

    /// The distance of `p` from the curve.
    pub fn distance(&self, p: [f64; 2]) -> f64 {
        match *self {
            Curve::Circle { center, radius } => {
                ((p[0] - center[0]).hypot(p[1] - center[1]) - radius).abs()
            }
        }
    }

    /// The largest distance a node on the curve may lie from it
    /// ([`CURVE_TOLERANCE`] of its size).
    pub fn tolerance(&self) -> f64 {
        match *self {
            Curve::Circle { radius, .. } => CURVE_TOLERANCE * radius,
        }
    }

    /// Where the node bisecting the chord from `a` to `b` goes: the chord's
    /// midpoint projected onto the curve (for a circle, along the radius
    /// through it: the middle of the shorter arc). `None` when the midpoint
    /// does not say where (the centre of a circle: a chord through it).
    pub fn bisect(&self, a: [f64; 2], b: [f64; 2]) -> Option<[f64; 2]> {
        let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        match *self {
            Curve::Circle { center, radius } => {
                let d = [mid[0] - center[0], mid[1] - center[1]];
                let r = d[0].hypot(d[1]);
                (r > self.tolerance())
                    // radius · (d/r): the unit direction first, so that a
                    // huge circle does not overflow (its points carry the
                    // absolute round-off of its size, as any would).
                    .then(|| {
                        [
                            center[0] + radius * (d[0] / r),
                            center[1] + radius * (d[1] / r),
                        ]
                    })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Curve = Curve::Circle {
        center: [1.0, -2.0],
        radius: 3.0,
    };

    #[test]
    fn a_chord_is_bisected_at_the_middle_of_its_arc() {
        let (t0, t1) = (0.3f64, 0.9f64);
        let on = |t: f64| [1.0 + 3.0 * t.cos(), -2.0 + 3.0 * t.sin()];
        let m = UNIT.bisect(on(t0), on(t1)).expect("a point");
        let want = on(0.6);
        assert!((m[0] - want[0]).abs() < 1e-15 && (m[1] - want[1]).abs() < 1e-15);
        assert!(UNIT.distance(m) < 1e-15);
    }

    #[test]
    fn a_huge_circle_bisects_without_overflow_or_lost_digits() {
        // Nearly straight: the arc's midpoint is the chord's to 1e-32.
        for big in [1e30, 1e155, 1e300] {
            let c = Curve::Circle {
                center: [-big, 0.125],
                radius: big,
            };
            let m = c.bisect([0.0, 0.0], [0.0, 0.25]).expect("a point");
            assert!(
                m[0].abs() < 1e-12 && (m[1] - 0.125).abs() < 1e-12,
                "{big}: {m:?}"
            );
        }
    }

    #[test]
    fn a_chord_through_the_centre_has_no_bisecting_point() {
        assert_eq!(UNIT.bisect([-2.0, -2.0], [4.0, -2.0]), None);
    }

    #[test]
    fn a_circle_needs_a_finite_centre_and_a_positive_radius() {
        for bad in [
            Curve::Circle {
                center: [f64::NAN, 0.0],
                radius: 1.0,
            },
            Curve::Circle {
                center: [0.0, 0.0],
                radius: 0.0,
            },
            Curve::Circle {
                center: [0.0, 0.0],
                radius: f64::INFINITY,
            },
        ] {
            assert!(bad.validate().is_err(), "{bad:?}");
        }
        assert!(UNIT.validate().is_ok());
    }
}
