//! # tfem — the Tempered Finite Element Method for elasticity and contact
//!
//! P1 triangles (and, in 3D, linear tetrahedra: [`model::solid`],
//! docs/method.md §9) whose stiffness divides by max(J, Jmin) instead of J, so that
//! flat, degenerate and inverted elements stay finite and do not lock
//! (docs/method.md §2), and contact between bodies, frictionless or with
//! Coulomb friction (docs/method.md §6.15), by activating the inverted
//! elements of a contact mesh (docs/method.md §3) or, where the automatic
//! weighting chooses the mortar weighting ([`ContactWeighting::Mortar`]),
//! the slave nodes whose mortar weighted gap is negative (docs/method.md
//! §6.11).
//!
//! The Rust API ([`Model`], [`Mesh`], [`Material`]) is the real API; the C
//! ABI in [`ffi`] is a thin translation layer over it.
//!
//! The crate is layered; each layer imports only those below it:
//!
//! | layer | modules |
//! |---|---|
//! | C ABI, verification studies | [`ffi`], `studies` (feature `studies`) |
//! | the model | [`model`]: [`Problem`], the solution, [`Model`] |
//! | solving | [`solve`]: session, assembled system, linear solve, condensed interface, active-set loop |
//! | contact and linear algebra | [`contact`]: B, laws, the contact set; [`linalg`]: Cholesky, orderings |
//! | finite elements | [`fem`]: mesh, material, element, assembly, loads, the element loop |
//! | errors | [`error`] |
//!
//! ```
//! use tfem::{Component, Material, Mesh, Model, PlaneMode, Tempering};
//! // A unit square of two triangles, clamped on the left, pulled on the right.
//! let nodes = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let mesh = Mesh::new(nodes, vec![[0, 1, 2], [0, 2, 3]], vec![1, 1], 0).unwrap();
//! let mut model = Model::new();
//! model.set_mesh(mesh);
//! model.set_material(1, Material::new(1e3, 0.0, PlaneMode::Stress, "body 1").unwrap()).unwrap();
//! // Two triangles for the whole body: h is the body size, so the default
//! // λ (the body size) would temper them; this solution is linear (λ = ∞).
//! model.set_tempering(Tempering::Lambda(1e6)).unwrap();
//! model.set_boundary_edges(&[[1, 2]], &[10]).unwrap();
//! for n in [0, 3] { model.fix(n, Component::X, 0.0).unwrap(); }
//! model.fix(0, Component::Y, 0.0).unwrap();
//! model.add_traction(10, [1.0, 0.0]).unwrap();
//! model.solve().unwrap();
//! let u = model.displacements().unwrap();
//! assert!((u[1][0] - 1e-3).abs() < 1e-15); // σ/E with ν = 0
//! ```

// Index loops mirror the element formulas (B̂ᵀ D B̂, g_i·g_j) term by term.
#![allow(clippy::needless_range_loop)]
#![warn(missing_docs)]

pub mod contact;
pub mod error;
pub mod fem;
pub mod ffi;
pub mod io;
pub mod linalg;
pub mod model;
#[cfg(feature = "python")]
mod python;
pub mod solve;
#[cfg(feature = "studies")]
pub mod studies;

// The paths of the flat layout before the layers (kept for users).
pub use fem::{assembly, element, material, mesh};
pub use linalg::cholesky as solver;
pub use linalg::ordering;
pub use model::solution;
pub use solve::condensed as condensation;
#[cfg(feature = "studies")]
pub use studies::{laplace, meshgen, oracle, scenes, verification};

pub use contact::{ContactLaw, ContactOptions, ContactWeighting, InversionTest};
pub use element::{Jmin, Tempering, TriGeometry};
pub use error::{Error, Result, Status};
pub use fem::curve::Curve;
pub use material::{Material, PlaneMode, Section};
pub use mesh::Mesh;
pub use model::{Component, Model, Problem};
pub use ordering::Ordering;
pub use solution::{ContactReport, SolveInfo, SystemMatrix, Timings};
