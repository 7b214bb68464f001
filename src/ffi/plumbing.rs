//! What every entry point shares: the model handle, the catching of
//! panics, the error slots (per model, and per thread for calls without a
//! model), and reading and writing caller-owned memory.

use std::cell::RefCell;
use std::collections::HashMap;
use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{LazyLock, Once, RwLock};

use crate::error::{Error, Result, Status};
use crate::fem::mesh::Mesh;
use crate::model::Model;

/// Opaque handle to a model. Create with `tfem_create`, free with
/// `tfem_destroy`.
pub struct TfemModel {
    pub(super) model: Model,
    pub(super) index_base: usize,
    pub(super) last_error: String,
    /// The cycles of the last `tfem_solve_adaptive`, for
    /// `tfem_get_adapt_cycles`.
    pub(super) adapt: Vec<crate::model::adapt::Cycle>,
}

thread_local! {
    pub(super) static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

pub(super) fn set_global_error(message: &str) {
    LAST_ERROR.with(|e| *e.borrow_mut() = message.to_string());
}

pub(super) fn null(what: &str) -> Error {
    Error::new(Status::NullPointer, format!("argument `{what}` is NULL"))
}

pub(super) fn panic_message(p: &(dyn std::any::Any + Send)) -> String {
    let text = p
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_string());
    format!("internal error (please report): {text}")
}

/// C calls in progress in the process.
static IN_CALL: AtomicUsize = AtomicUsize::new(0);

/// Runs `f` catching any panic, which is then reported through the error
/// slots and never printed: while a C call runs, the panic hook (installed
/// on the first call, chaining to the one before) stays silent. (It must
/// be process-wide: a panic in a worker thread of the solver runs the hook
/// on that thread.)
pub(super) fn guarded<R>(f: impl FnOnce() -> R) -> std::thread::Result<R> {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if IN_CALL.load(Ordering::SeqCst) == 0 {
                previous(info);
            }
        }));
    });
    IN_CALL.fetch_add(1, Ordering::SeqCst);
    let result = catch_unwind(AssertUnwindSafe(f));
    IN_CALL.fetch_sub(1, Ordering::SeqCst);
    result
}

/// A handle that keeps the message of its last failed call.
pub(super) trait Handle {
    /// The name of the handle argument in messages.
    const ARGUMENT: &'static str;
    /// What the handle is, and the function that makes one (messages).
    const KIND: &'static str;
    /// The handle's error slot.
    fn last_error(&mut self) -> &mut String;
}

/// The live handles: address → kind ([`Handle::KIND`]). A pointer that is
/// not one of them — a destroyed handle, a handle of the other kind (a
/// Fortran `type(c_ptr)` does not tell a model from a contact context),
/// anything else — is refused before it is read, instead of being read as
/// a handle. One read lock per call.
static LIVE: LazyLock<RwLock<HashMap<usize, &'static str>>> =
    LazyLock::new(|| RwLock::new(HashMap::new()));

/// Boxes `value` as a live handle; NULL when the registry cannot grow.
/// (The box itself, a few hundred bytes, is allocated infallibly.)
pub(super) fn register<H: Handle>(value: H) -> *mut H {
    let mut live = LIVE.write().unwrap_or_else(|e| e.into_inner());
    if live.try_reserve(1).is_err() {
        return std::ptr::null_mut();
    }
    let handle = Box::into_raw(Box::new(value));
    live.insert(handle as usize, H::KIND);
    handle
}

/// Takes `handle` out of the live handles: whether it was a live `H`
/// (only then may it be freed).
pub(super) fn unregister<H: Handle>(handle: *mut H) -> bool {
    let mut live = LIVE.write().unwrap_or_else(|e| e.into_inner());
    match live.get(&(handle as usize)) {
        Some(&kind) if kind == H::KIND => live.remove(&(handle as usize)).is_some(),
        _ => false,
    }
}

/// Refuses a non-NULL `handle` that is not a live `H`, naming what it is.
pub(super) fn check_live<H: Handle>(handle: *const H) -> Result<()> {
    let live = LIVE.read().unwrap_or_else(|e| e.into_inner());
    match live.get(&(handle as usize)) {
        Some(&kind) if kind == H::KIND => Ok(()),
        Some(&kind) => Err(Error::argument(format!(
            "argument `{}` is not {}: it is {kind}",
            H::ARGUMENT,
            H::KIND
        ))),
        None => Err(Error::argument(format!(
            "argument `{}` is not {}: it was destroyed, or never made by it",
            H::ARGUMENT,
            H::KIND
        ))),
    }
}

impl Handle for TfemModel {
    const ARGUMENT: &'static str = "model";
    const KIND: &'static str = "a model (from tfem_create)";
    fn last_error(&mut self) -> &mut String {
        &mut self.last_error
    }
}

/// Runs `f` on a handle, catching panics and recording the message in the
/// handle (in the thread's slot when the handle is NULL).
pub(super) fn with_handle<H: Handle>(
    handle: *mut H,
    f: impl FnOnce(&mut H) -> Result<()>,
) -> Status {
    // SAFETY: the caller passes a handle from its create function (or
    // NULL), used by one thread at a time per the thread contract.
    if handle.is_null() {
        set_global_error(&format!("argument `{}` is NULL", H::ARGUMENT));
        return Status::NullPointer;
    }
    if let Err(e) = check_live(handle) {
        set_global_error(e.message());
        return e.status();
    }
    // SAFETY: a live handle of this kind (just checked).
    let Some(h) = (unsafe { handle.as_mut() }) else {
        return Status::NullPointer;
    };
    match guarded(|| f(h)) {
        Ok(Ok(())) => {
            h.last_error().clear();
            Status::Ok
        }
        Ok(Err(e)) => {
            *h.last_error() = e.message().to_string();
            e.status()
        }
        Err(p) => {
            *h.last_error() = panic_message(p.as_ref());
            Status::Internal
        }
    }
}

/// Runs `f` on a model handle ([`with_handle`]).
pub(super) fn with_model(
    model: *mut TfemModel,
    f: impl FnOnce(&mut TfemModel) -> Result<()>,
) -> Status {
    with_handle(model, f)
}

/// Runs a model-free call, catching panics; errors go to the thread's
/// last-error slot, which a success clears.
pub(super) fn without_model(f: impl FnOnce() -> Result<()>) -> Status {
    match guarded(f) {
        Ok(Ok(())) => {
            set_global_error("");
            Status::Ok
        }
        Ok(Err(e)) => {
            set_global_error(e.message());
            e.status()
        }
        Err(p) => {
            set_global_error(&panic_message(p.as_ref()));
            Status::Internal
        }
    }
}

/// A slice from a C pointer and count; NULL is allowed only for count 0.
pub(super) fn slice_in<'a, T>(ptr: *const T, len: usize, what: &str) -> Result<&'a [T]> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(null(what));
    }
    // SAFETY: the caller guarantees `len` readable elements at `ptr`.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// An empty vector with room for `n` items of the copy of the caller's
/// array `what`, reserved fallibly (`error::reserved`).
pub(super) fn reserve<U>(n: usize, what: &str) -> Result<Vec<U>> {
    crate::error::reserved(n, &format!("`{what}`"))
}

/// A caller's array read in items of `chunk` values, each mapped by `f`,
/// into a vector reserved as by [`reserve`].
pub(super) fn copy_in<T, U>(
    src: &[T],
    chunk: usize,
    what: &str,
    f: impl FnMut(&[T]) -> U,
) -> Result<Vec<U>> {
    let mut v = reserve(src.len() / chunk, what)?;
    v.extend(src.chunks_exact(chunk).map(f));
    Ok(v)
}

pub(super) fn count(n: i32, what: &str) -> Result<usize> {
    usize::try_from(n).map_err(|_| Error::argument(format!("{what} = {n} must be >= 0")))
}

/// Copies `src` into a caller buffer of `len` elements.
pub(super) fn copy_out<T: Copy>(src: &[T], out: *mut T, len: usize, what: &str) -> Result<()> {
    if out.is_null() {
        return Err(null(what));
    }
    if len < src.len() {
        return Err(too_small(what, len, src.len()));
    }
    // SAFETY: `out` has room for `len >= src.len()` elements.
    unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), out, src.len()) };
    Ok(())
}

/// Writes `f` of each element of `src` into a caller buffer of `len`
/// elements, with no intermediate copy (the matrix's index arrays are
/// ~70 MB at 1M unknowns).
pub(super) fn map_out<T: Copy, U>(
    src: &[T],
    out: *mut U,
    len: usize,
    what: &str,
    f: impl Fn(T) -> U,
) -> Result<()> {
    if out.is_null() {
        return Err(null(what));
    }
    if len < src.len() {
        return Err(Error::new(
            Status::BufferTooSmall,
            format!("`{what}` holds {len} values but {} are needed", src.len()),
        ));
    }
    for (i, &v) in src.iter().enumerate() {
        // SAFETY: `out` has room for `len >= src.len()` elements; raw
        // writes, as the caller's buffer may be uninitialised.
        unsafe { out.add(i).write(f(v)) };
    }
    Ok(())
}

/// Writes `value` to an output the header documents as "may be NULL":
/// nothing when it is.
pub(super) fn write_optional<T>(out: *mut T, value: T) {
    if !out.is_null() {
        // SAFETY: non-null pointer to a caller-owned T.
        unsafe { out.write(value) };
    }
}

pub(super) fn write<T>(out: *mut T, value: T, what: &str) -> Result<()> {
    if out.is_null() {
        return Err(null(what));
    }
    // SAFETY: non-null pointer to a caller-owned T.
    unsafe { out.write(value) };
    Ok(())
}

impl TfemModel {
    pub(super) fn index(&self, i: i32, n: usize, what: &str) -> Result<usize> {
        let b = self.index_base as i64;
        let v = i as i64 - b;
        if v < 0 || v as usize >= n {
            return Err(Error::argument(format!(
                "{what} {i} is out of range ({n} available, index base {b})"
            )));
        }
        Ok(v as usize)
    }

    pub(super) fn n_nodes(&self) -> Result<usize> {
        self.mesh().map(|m| m.nodes().len())
    }

    /// The model's mesh, or INVALID_STATE when none is set.
    pub(super) fn mesh(&self) -> Result<&Mesh> {
        self.model
            .mesh()
            .ok_or_else(|| Error::state("no mesh: call tfem_set_mesh first"))
    }
}

/// BUFFER_TOO_SMALL for the caller's array `what` of `len` values where
/// `need` are needed (the message `copy_out` gives).
pub(super) fn too_small(what: &str, len: usize, need: usize) -> Error {
    Error::new(
        Status::BufferTooSmall,
        format!("`{what}` holds {len} values but {need} are needed"),
    )
}

pub(super) fn copy_message(text: &str, buffer: *mut c_char, length: usize) -> Status {
    if buffer.is_null() || length == 0 {
        return if buffer.is_null() {
            Status::NullPointer
        } else {
            Status::BufferTooSmall
        };
    }
    let bytes = text.as_bytes();
    let mut n = bytes.len().min(length - 1);
    // Do not cut a UTF-8 sequence in half.
    while n > 0 && n < bytes.len() && (bytes[n] & 0xC0) == 0x80 {
        n -= 1;
    }
    // SAFETY: `buffer` has room for `length > n` bytes.
    unsafe {
        std::ptr::copy_nonoverlapping(bytes.as_ptr().cast::<c_char>(), buffer, n);
        *buffer.add(n) = 0;
    }
    if n < bytes.len() {
        Status::BufferTooSmall
    } else {
        Status::Ok
    }
}
