//! Optional file I/O, each format behind its own Cargo feature so that an
//! embedder links only the core.

#[cfg(feature = "vtu")]
pub mod vtu;

#[cfg(feature = "gmsh")]
pub mod gmsh;
