//! The finite elements: meshes of P1 triangles ([`mesh`]), materials
//! ([`material`]), the tempered element ([`element`]), the numbering of
//! unknowns and the sparsity pattern ([`assembly`]), loads ([`loads`]),
//! the one loop over body elements ([`element_loop`]), the bodies' part
//! of the system assembled on the pattern ([`body`]), the orientation
//! of triangles numbered clockwise ([`orientation`]), adaptive
//! refinement by newest-vertex bisection ([`refine`]) and the curves it
//! puts new boundary nodes on ([`curve`]); and the tempered linear
//! tetrahedron ([`tet`]), the first stage of three dimensions.

pub mod assembly;
pub mod body;
pub mod curve;
pub mod domain;
pub mod element;
pub mod element_loop;
pub mod loads;
pub mod material;
pub mod mesh;
pub mod orientation;
pub mod refine;
pub mod solid_assembly;
pub mod solid_mesh;
pub mod tet;
