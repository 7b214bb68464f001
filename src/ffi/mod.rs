//! The C ABI: a thin translation layer over [`crate::Model`],
//! [`crate::contact::HostContact`], the 3D
//! [`crate::model::solid::SolidModel`] and the 3D contact for host codes
//! [`crate::contact::host_solid::SolidHostContact`], in six parts: the
//! entry points of the model (`entry`), of the contact context for host
//! codes (`host`), of the 3D model (`solid`, `tfem_solid_*`) and of the 3D
//! contact context (`solid_contact`, `tfem_solid_contact_*`), the plumbing
//! every entry point shares
//! (handles, panics, errors, caller buffers: `plumbing`) and the `repr(C)`
//! mirrors of the Rust types with their conversions (`convert`).
//!
//! Conventions (repeated in the generated header):
//! * Every function returns a [`crate::Status`]; `TFEM_STATUS_OK` (0) is success.
//!   `tfem_last_error` gives the message of the last failed call.
//! * Indices (nodes, triangles, edges) use the `index_base` given to
//!   `tfem_set_mesh` (0 for C, 1 for Fortran) in every later call and in
//!   every message.
//! * Output buffers are owned by the caller; their length (in elements, not
//!   bytes) is checked, and nothing is written when it is too short.
//! * A call that returns an error writes none of its outputs (buffers,
//!   values and structs given back through pointers): every check, and
//!   every result, comes before the first write (`plumbing::copy_out`,
//!   `plumbing::write`). The exceptions are the message copies
//!   (`tfem_last_error`, `tfem_contact_last_error`, `tfem_get_warning`),
//!   which write a truncated message with `TFEM_STATUS_BUFFER_TOO_SMALL`
//!   and the message refusing a handle that is not live.
//! * A failed call leaves the model as it was. No panic crosses the
//!   boundary: it is caught and reported as `TFEM_STATUS_INTERNAL`.

#![allow(clippy::missing_safety_doc)]

mod convert;
mod entry;
mod host;
mod plumbing;
mod solid;
mod solid_contact;

pub use convert::{
    ContactWeightingMode, OrderingMode, TemperingMode, TfemContactOptions, TfemContactReport,
    TfemSolveInfo,
};
pub use entry::*;
pub use host::*;
pub use plumbing::TfemModel;
pub use solid::*;
pub use solid_contact::*;
