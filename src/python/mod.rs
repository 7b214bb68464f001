//! The Python module `tfem._tfem` (feature `python`): the Rust API as
//! numpy users expect it, a thin translation layer like the C ABI's.
//!
//! Meshes and fields cross as numpy arrays: a C-contiguous input of the
//! right dtype is read in place (its buffer, no copy on the Python side;
//! the package's `tfem.Model` passes other layouts through
//! `numpy.ascontiguousarray`, which copies only then) into the library's
//! own storage, as the C ABI copies a caller's array; results are handed
//! over as new arrays that take the library's vectors without a copy.
//! Every status becomes an exception of the `tfem.Error` family, with the
//! status code (`status`) and name (`status_name`); warnings go to Python's
//! `warnings` as `tfem.Warning`. Solves release the GIL (`Python::detach`).

mod model;

use pyo3::exceptions::{PyException, PyUserWarning};
use pyo3::prelude::*;

use crate::error::{Error, Status};

pyo3::create_exception!(
    tfem,
    TfemError,
    PyException,
    "A tfem call failed: `status` (the C ABI's code), `status_name` and the message naming the offending item; the model is unchanged."
);
pyo3::create_exception!(
    tfem,
    InvalidArgument,
    TfemError,
    "An argument is out of its documented range."
);
pyo3::create_exception!(
    tfem,
    InvalidMesh,
    TfemError,
    "The mesh is invalid (the message names the node, triangle or edge)."
);
pyo3::create_exception!(
    tfem,
    InvalidMaterial,
    TfemError,
    "A material is invalid or missing (the message names the body)."
);
pyo3::create_exception!(
    tfem,
    InvalidState,
    TfemError,
    "The call is not allowed in the model's current state."
);
pyo3::create_exception!(
    tfem,
    Singular,
    TfemError,
    "The stiffness matrix is singular: a body is not restrained (the message names it)."
);
pyo3::create_exception!(
    tfem,
    NotConverged,
    TfemError,
    "The contact loop did not converge (the message gives its history)."
);
pyo3::create_exception!(
    tfem,
    DegenerateElement,
    TfemError,
    "A degenerate element cannot be integrated with tempering off."
);
pyo3::create_exception!(
    tfem,
    InvalidContact,
    TfemError,
    "A contact pair or contact mesh is invalid (the message names it)."
);
pyo3::create_exception!(
    tfem,
    NumericalFailure,
    TfemError,
    "A result is not finite, or a solve could not reach working accuracy."
);
pyo3::create_exception!(
    tfem,
    OutOfMemory,
    TfemError,
    "Memory could not be allocated (the message names what for)."
);
pyo3::create_exception!(
    tfem,
    IoError,
    TfemError,
    "A file could not be read or written (the message names it)."
);
pyo3::create_exception!(
    tfem,
    InternalError,
    TfemError,
    "An internal error: please report it."
);
pyo3::create_exception!(
    tfem,
    TfemWarning,
    PyUserWarning,
    "Something in a model or a solve is really wrong, but the call succeeded."
);

/// The exception of `e`'s status, carrying its code, name and message.
pub(crate) fn to_py(e: Error) -> PyErr {
    let message = e.message().to_string();
    let status = e.status();
    let err = match status {
        Status::InvalidArgument | Status::NullPointer | Status::BufferTooSmall => {
            InvalidArgument::new_err(message)
        }
        Status::InvalidMesh => InvalidMesh::new_err(message),
        Status::InvalidMaterial => InvalidMaterial::new_err(message),
        Status::InvalidState => InvalidState::new_err(message),
        Status::Singular => Singular::new_err(message),
        Status::NotConverged => NotConverged::new_err(message),
        Status::DegenerateElement => DegenerateElement::new_err(message),
        Status::InvalidContact => InvalidContact::new_err(message),
        Status::NumericalFailure => NumericalFailure::new_err(message),
        Status::OutOfMemory => OutOfMemory::new_err(message),
        Status::Io => IoError::new_err(message),
        Status::Internal | Status::Ok => InternalError::new_err(message),
    };
    Python::attach(|py| {
        let value = err.value(py);
        // Attributes on a fresh exception instance cannot fail but for
        // memory; the exception is raised either way.
        let _ = value.setattr("status", status as i32);
        let _ = value.setattr("status_name", status.name());
    });
    err
}

/// `tfem.Error`'s family, the model and the readers.
#[pymodule]
fn _tfem(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("Error", py.get_type::<TfemError>())?;
    m.add("InvalidArgument", py.get_type::<InvalidArgument>())?;
    m.add("InvalidMesh", py.get_type::<InvalidMesh>())?;
    m.add("InvalidMaterial", py.get_type::<InvalidMaterial>())?;
    m.add("InvalidState", py.get_type::<InvalidState>())?;
    m.add("Singular", py.get_type::<Singular>())?;
    m.add("NotConverged", py.get_type::<NotConverged>())?;
    m.add("DegenerateElement", py.get_type::<DegenerateElement>())?;
    m.add("InvalidContact", py.get_type::<InvalidContact>())?;
    m.add("NumericalFailure", py.get_type::<NumericalFailure>())?;
    m.add("OutOfMemory", py.get_type::<OutOfMemory>())?;
    m.add("IoError", py.get_type::<IoError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    m.add("Warning", py.get_type::<TfemWarning>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<model::PyModel>()?;
    Ok(())
}
