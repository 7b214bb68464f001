//! Sparse and dense linear algebra below the finite elements: the sparse
//! Cholesky factorisation with its symbolic analysis kept for reuse
//! ([`cholesky`]), its split into two concurrent subtrees (`split`), the
//! fill-reducing orderings ([`ordering`]), packed dense triangles
//! ([`packed`]), iterative refinement ([`refine`]) and the dense kernels'
//! packing buffers, taken before they are needed ([`workspace`]).
//!
//! Nothing here knows about meshes or contact: the matrices are symmetric,
//! given by the upper triangle on a [`crate::fem::assembly::Pattern`].

pub mod cholesky;
pub mod ordering;
pub mod packed;
pub mod refine;
mod split;
pub mod workspace;

pub use cholesky::{AnalyseParams, Cholesky, FactorError, Points, SINGULAR_TOL};
pub use ordering::Ordering;
