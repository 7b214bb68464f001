//! The packing buffer of the dense kernels, taken before a factorisation
//! needs it, where running out of memory is an error and not an abort.
//!
//! faer's dense products (private-gemm on x86-64, which the supernodal
//! Cholesky calls for every supernode) keep one packing buffer per thread,
//! twice the last-level cache, allocated at the thread's first product and
//! kept for its life. That allocation is infallible: under an address-space
//! limit (`ulimit -v`) with too little room, the host process aborts in the
//! middle of a factorisation. [`ensure`] checks that the room is there and
//! makes every thread that may run a product take its buffer then, so that
//! the factorisation itself never asks for it.

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};

use faer::Mat;
use faer::linalg::matmul::matmul;
use faer::{Accum, Par};

use crate::error::{Error, Result, Status, preflight};

thread_local! {
    /// Whether this thread has taken its packing buffer.
    static READY: Cell<bool> = const { Cell::new(false) };
}

/// The last-level cache size assumed where it cannot be read (Linux's
/// sysfs): larger than any single cache of current x86-64 parts but the
/// stacked ones.
const FALLBACK_CACHE: usize = 64 << 20;

/// An upper bound of one thread's packing buffer: private-gemm takes twice
/// the largest of its last-level cache share, four times its L2 and 1 MiB;
/// bounded here by twice the largest of the caches the system lists (four
/// times for a second-level one), plus a page-rounding margin.
pub fn buffer_bound() -> usize {
    2 * largest_cache().unwrap_or(FALLBACK_CACHE).max(1 << 20) + (1 << 20)
}

/// The largest cache of CPU 0 in Linux's sysfs (sizes like "32768K"), an
/// L2 counted four times.
fn largest_cache() -> Option<usize> {
    let dir = std::fs::read_dir("/sys/devices/system/cpu/cpu0/cache").ok()?;
    dir.filter_map(|e| e.ok())
        .filter_map(|e| {
            let size = parse_size(std::fs::read_to_string(e.path().join("size")).ok()?.trim())?;
            let level = std::fs::read_to_string(e.path().join("level")).ok()?;
            Some(if level.trim() == "2" { 4 * size } else { size })
        })
        .max()
}

/// "32768K", "1M" or "512" (bytes) to bytes.
fn parse_size(s: &str) -> Option<usize> {
    let (digits, unit) = match s.char_indices().find(|(_, c)| !c.is_ascii_digit()) {
        Some((i, _)) => s.split_at(i),
        None => (s, ""),
    };
    let n: usize = digits.parse().ok()?;
    let factor = match unit {
        "" => 1,
        "K" => 1 << 10,
        "M" => 1 << 20,
        "G" => 1 << 30,
        _ => return None,
    };
    n.checked_mul(factor)
}

/// Makes the calling thread and every thread of the current rayon pool
/// take its packing buffer, after checking that the room for the buffers
/// still missing is there: TFEM_STATUS_OUT_OF_MEMORY otherwise, with
/// nothing taken. Cheap once every thread has its buffer.
pub fn ensure() -> Result<()> {
    // A pool's own thread is one of those the broadcast reaches.
    let outside = rayon::current_thread_index().is_none();
    if outside && !GLOBAL_POOL_STARTED.load(Ordering::Acquire) {
        // rayon starts its global pool once per process: threads that
        // cannot be started then leave it unusable for good (every later
        // parallel call panics), so their stacks are checked first.
        preflight(
            global_pool_threads().saturating_mul(thread_bound()),
            "the global thread pool's threads",
        )?;
    }
    // The first broadcast outside any pool starts the global pool: where
    // its threads still cannot start (a limit the preflight's bound did not
    // foresee: the system's thread count, its per-thread heaps), rayon
    // panics, and the pool stays unusable for the process — an
    // out-of-memory status, not an internal error.
    let first = outside && !GLOBAL_POOL_STARTED.load(Ordering::Acquire);
    let busy = if first {
        std::panic::catch_unwind(|| rayon::broadcast(|_| !READY.get())).map_err(|_| {
            Error::new(
                Status::OutOfMemory,
                "the global thread pool's threads could not be started (a memory or thread \
                 limit); a model with its own pool (set_threads) may still run",
            )
        })?
    } else {
        rayon::broadcast(|_| !READY.get())
    };
    let missing = usize::from(outside && !READY.get()) + busy.into_iter().filter(|&m| m).count();
    if missing == 0 {
        return Ok(());
    }
    preflight(
        missing.saturating_mul(buffer_bound()),
        "the dense kernels' packing buffers",
    )?;
    take_buffer();
    rayon::broadcast(|_| take_buffer());
    if outside {
        GLOBAL_POOL_STARTED.store(true, Ordering::Release);
    }
    Ok(())
}

/// Whether a call of [`ensure`] outside any pool has found rayon's global
/// pool running.
static GLOBAL_POOL_STARTED: AtomicBool = AtomicBool::new(false);

/// An upper bound of what one pool thread takes: its stack (Rust's default
/// 2 MiB, or `RUST_MIN_STACK`), its guard page and rayon's per-thread state.
fn thread_bound() -> usize {
    let stack = std::env::var("RUST_MIN_STACK")
        .ok()
        .and_then(|v| v.parse::<usize>().ok())
        .unwrap_or(2 << 20);
    stack.saturating_add(1 << 20)
}

/// The threads rayon's global pool starts with: `RAYON_NUM_THREADS` when
/// set to a positive count, else the available parallelism.
fn global_pool_threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.parse::<usize>().ok())
        .filter(|&n| n > 0)
        .or_else(|| std::thread::available_parallelism().ok().map(|n| n.get()))
        .unwrap_or(1)
}

/// One product large enough for the packed path, on this thread.
fn take_buffer() {
    if READY.get() {
        return;
    }
    // Above faer's small-product threshold (16³), below any cost.
    let a = Mat::<f64>::from_fn(24, 24, |i, j| (i + j) as f64);
    let mut c = Mat::<f64>::zeros(24, 24);
    matmul(
        c.as_mut(),
        Accum::Replace,
        a.as_ref(),
        a.as_ref(),
        1.0,
        Par::Seq,
    );
    READY.set(true);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cache_sizes_read_in_sysfs_units() {
        assert_eq!(parse_size("32768K"), Some(32 << 20));
        assert_eq!(parse_size("1M"), Some(1 << 20));
        assert_eq!(parse_size("512"), Some(512));
        assert_eq!(parse_size("12Q"), None);
        assert_eq!(parse_size(""), None);
    }

    #[test]
    fn a_thread_is_ready_after_ensure() {
        ensure().expect("room for the buffers");
        assert!(READY.get());
        assert!(rayon::broadcast(|_| READY.get()).into_iter().all(|r| r));
    }
}
