//! The verification harness, outside the shipped core (Cargo feature
//! `studies`, off by default): the seed's scenes, Hertz contact and
//! Cattaneo–Mindlin ([`scenes`]), independent exact contact solvers,
//! frictionless and Coulomb-frictional ([`oracle`]),
//! manufactured solutions and norms ([`verification`]), a tempered Poisson
//! solver ([`laplace`]), structured and graded triangulations
//! ([`meshgen`]) and the quadrature their norms use ([`quadrature`]), and
//! the study of Jmin in three dimensions: tetrahedral meshes of the cube
//! with bands of flat tetrahedra ([`tetmesh`]) and a manufactured solution
//! solved on them ([`tet_study`]), and contact through a layer of flat
//! tetrahedra ([`tet_contact`]) on 3D scenes ([`tet_scenes`]).
//!
//! The tests, examples and the report use it; the C library does not carry
//! it. Its modules keep their old paths (`tfem::scenes`, …) as
//! re-exports.

#[cfg(feature = "gmsh")]
pub mod graded_punch;
pub mod laplace;
pub mod meshgen;
pub mod oracle;
pub mod quadrature;
pub mod scenes;
pub mod tet_assembly;
pub mod tet_contact;
pub mod tet_scenes;
pub mod tet_study;
pub mod tetmesh;
pub mod verification;
