//! Errors and the status codes shared by the Rust API and the C ABI.

use std::fmt;

/// Outcome of a call. The numbers are part of the C ABI and are fixed
/// forever: a code is never renumbered or reused, new codes are appended.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Status {
    /// Success.
    Ok = 0,
    /// A required pointer argument was NULL.
    NullPointer = 1,
    /// An argument is out of its documented range (the message names it).
    InvalidArgument = 2,
    /// The mesh is invalid (the message names the node, triangle or edge).
    InvalidMesh = 3,
    /// A material is invalid or missing (the message names the body).
    InvalidMaterial = 4,
    /// The call is not allowed in the model's current state (e.g. a solve
    /// before a mesh was given, results before a solve).
    InvalidState = 5,
    /// A caller-owned output buffer is shorter than required.
    BufferTooSmall = 6,
    /// The stiffness matrix is singular or indefinite: some body is not
    /// restrained (the message names it).
    Singular = 7,
    /// The contact active-set loop did not converge (the message gives the
    /// history).
    NotConverged = 8,
    /// A degenerate element cannot be integrated (zero Jacobian with
    /// tempering off); the message names it.
    DegenerateElement = 9,
    /// A contact pair or contact mesh is invalid (the message names it).
    InvalidContact = 10,
    /// A computed result is not finite (overflow), or a solve could not
    /// reach working accuracy even with a factorisation of its own matrix
    /// (the message says which); nothing was returned.
    NumericalFailure = 11,
    /// An internal error (a caught panic): please report it.
    Internal = 12,
    /// Memory could not be allocated (the message names what for): the
    /// library's copy of a caller's array and the structures a mesh or a
    /// contact side derives from it; every stage of a solve, a load step
    /// or a step's recovery, checked before the stage starts (set-up,
    /// ordering, factorisation, vectors, the threads and their dense
    /// kernels' buffers). The bounds checked are conservative: a call may
    /// be refused a little before memory is truly exhausted. Other
    /// allocations (declarations, results read after a solve, files) are
    /// small beside these and not checked: where they fail, the process
    /// aborts.
    OutOfMemory = 13,
    /// A file could not be read or written (the message names it).
    Io = 14,
}

impl Status {
    /// A short, stable, human-readable name of the status.
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::NullPointer => "null pointer",
            Status::InvalidArgument => "invalid argument",
            Status::InvalidMesh => "invalid mesh",
            Status::InvalidMaterial => "invalid material",
            Status::InvalidState => "invalid state",
            Status::BufferTooSmall => "buffer too small",
            Status::Singular => "singular system",
            Status::NotConverged => "not converged",
            Status::DegenerateElement => "degenerate element",
            Status::InvalidContact => "invalid contact",
            Status::NumericalFailure => "numerical failure",
            Status::Internal => "internal error",
            Status::OutOfMemory => "out of memory",
            Status::Io => "input/output error",
        }
    }
}

/// The length, in bytes, a message built of clauses keeps within, so that
/// with the context a caller's layer puts before it (a pair, the automatic
/// pairing) it stays within the 512 bytes a C caller's buffer commonly
/// holds: a clause that would take it beyond is left out whole, never cut.
pub const MESSAGE_BYTES: usize = 360;

/// An error of the tfem API: a status code plus a message naming the
/// offending item (node, element, body, edge or argument).
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    status: Status,
    message: String,
}

impl Error {
    /// Builds an error. `status` must not be [`Status::Ok`].
    pub fn new(status: Status, message: impl Into<String>) -> Self {
        debug_assert!(status != Status::Ok);
        Error {
            status,
            message: message.into(),
        }
    }

    /// The status code of this error.
    pub fn status(&self) -> Status {
        self.status
    }

    /// The message, naming the offending item.
    pub fn message(&self) -> &str {
        &self.message
    }

    pub(crate) fn argument(message: impl Into<String>) -> Self {
        Error::new(Status::InvalidArgument, message)
    }

    pub(crate) fn mesh(message: impl Into<String>) -> Self {
        Error::new(Status::InvalidMesh, message)
    }

    pub(crate) fn state(message: impl Into<String>) -> Self {
        Error::new(Status::InvalidState, message)
    }

    pub(crate) fn contact(message: impl Into<String>) -> Self {
        Error::new(Status::InvalidContact, message)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.status.name(), self.message)
    }
}

impl std::error::Error for Error {}

/// Refuses a result with a value that is not finite (an overflow):
/// `values` holds `per` values per item, and the error names the first
/// such item with `name` and says which `quantity` overflowed.
pub(crate) fn ensure_finite(
    values: impl IntoIterator<Item = f64>,
    per: usize,
    quantity: &str,
    name: impl Fn(usize) -> String,
) -> Result<()> {
    match values.into_iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::new(
            Status::NumericalFailure,
            format!(
                "the {quantity} of {} is not finite (an overflow: rescale the model or its loads)",
                name(i / per.max(1))
            ),
        )),
    }
}

/// The error for a contact pair index `pair` that is not one of the `n`
/// declared (0-based).
pub(crate) fn no_pair(pair: impl std::fmt::Display, n: usize) -> Error {
    Error::argument(format!(
        "contact pair {pair} does not exist ({n} declared, 0-based)"
    ))
}

/// An empty vector with room for `n` items, reserved fallibly: memory for
/// `what` (sized by a caller's count) that cannot be had is
/// [`Status::OutOfMemory`] naming it, where Rust's infallible allocation
/// would abort the process — a host code with it.
pub(crate) fn reserved<T>(n: usize, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| out_of_memory::<T>(n, what))?;
    Ok(v)
}

/// Grows `v` fallibly by room for `n` more items (see [`reserved`]).
pub(crate) fn reserve_more<T>(v: &mut Vec<T>, n: usize, what: &str) -> Result<()> {
    v.try_reserve(n).map_err(|_| out_of_memory::<T>(n, what))
}

/// Checks that `bytes` more memory can be had now, by reserving them and
/// giving them back: for a stage whose own allocations are not checked
/// one by one (they would abort the host when memory runs out), so that it
/// fails before it starts, with TFEM_STATUS_OUT_OF_MEMORY naming `what`.
/// Under an address-space limit (`ulimit -v`) the check is exact up to
/// fragmentation; without one it refuses only what the system would never
/// grant. `bytes` must bound the stage's peak.
pub(crate) fn preflight(bytes: usize, what: &str) -> Result<()> {
    let mut room: Vec<u8> = Vec::new();
    room.try_reserve_exact(bytes).map_err(|_| {
        Error::new(
            Status::OutOfMemory,
            format!("{what}: no memory for the {bytes} bytes it needs"),
        )
    })?;
    // An allocation nothing reads may be optimised away, and the check
    // with it (measured: the mesh's check passed under any limit).
    std::hint::black_box(room.as_mut_ptr());
    Ok(())
}

/// The error for memory for `n` items of `T` of `what` that cannot be had.
pub(crate) fn out_of_memory<T>(n: usize, what: &str) -> Error {
    Error::new(
        Status::OutOfMemory,
        format!(
            "{what}: no memory for {n} items ({} bytes)",
            n.saturating_mul(std::mem::size_of::<T>())
        ),
    )
}

/// Result type of the tfem API.
pub type Result<T> = std::result::Result<T, Error>;
