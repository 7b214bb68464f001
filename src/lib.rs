//! # tfem — the Tempered Finite Element Method for 2D elasticity and contact
//!
//! P1 triangles whose stiffness divides by max(J, Jmin) instead of J, so that
//! flat, degenerate and inverted elements stay finite and do not lock
//! (METHOD.md §2), and frictionless contact between bodies by activating the
//! inverted elements of a contact mesh (METHOD.md §3).
//!
//! The Rust API ([`Model`], [`Mesh`], [`Material`]) is the real API; the C
//! ABI in [`ffi`] is a thin translation layer over it.
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

pub mod assembly;
pub mod condensation;
pub mod contact;
pub mod element;
pub mod error;
pub mod ffi;
pub mod io;
pub mod laplace;
pub mod material;
pub mod mesh;
pub mod meshgen;
pub mod model;
pub mod oracle;
pub mod ordering;
pub mod scenes;
pub mod solution;
pub mod solver;
mod split;
pub mod verification;

pub use contact::{ContactLaw, ContactOptions, InversionTest};
pub use element::{Jmin, Tempering, TriGeometry};
pub use error::{Error, Result, Status};
pub use material::{Material, PlaneMode};
pub use mesh::Mesh;
pub use model::{Component, Model};
pub use ordering::Ordering;
pub use solution::{ContactReport, SolveInfo, SystemMatrix, Timings};
