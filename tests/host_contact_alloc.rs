//! `HostContact::evaluate` allocates nothing per call once set up (a host
//! calls it at every Newton iteration): counted with a global allocator
//! that records every allocation of this test binary.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use tfem::contact::HostContact;
use tfem::{ContactOptions, Material, PlaneMode};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn evaluating_the_contributions_allocates_nothing() {
    // Two facing chains of n edges along y = 0, lower body 1 below, upper
    // body 2 above; every DOF has an equation.
    let n = 50;
    let material = Material::new(1e3, 0.3, PlaneMode::Strain, "body").unwrap();
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    for (side, body) in [(0, 1), (1, 2)] {
        let first = side as i64 * (n as i64 + 1);
        let ids: Vec<i64> = (0..=n as i64).map(|i| first + i).collect();
        let xy: Vec<[f64; 2]> = (0..=n).map(|i| [i as f64 / n as f64, 0.0]).collect();
        let eq: Vec<[i64; 2]> = ids.iter().map(|&v| [2 * v, 2 * v + 1]).collect();
        // Body on the left: the lower body's top runs right to left, the
        // upper body's bottom left to right.
        let edges: Vec<[i64; 2]> = (0..n as i64)
            .map(|i| match side {
                0 => [first + i + 1, first + i],
                _ => [first + i, first + i + 1],
            })
            .collect();
        hc.add_side(side, body, material, &ids, &xy, &eq, &edges)
            .unwrap();
    }
    hc.add_pair(0, 1).unwrap();
    let entries = hc.pattern().unwrap().0.len();
    let u: Vec<f64> = (0..2 * hc.nodes().len())
        .map(|i| 1e-3 * (i as f64).sin())
        .collect();
    let mut values = vec![0.0; entries];
    let mut residual = vec![0.0; u.len()];
    // Once, to fault everything in; then counted.
    hc.evaluate(&u, Some(&mut values), Some(&mut residual))
        .unwrap();
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for _ in 0..10 {
        hc.evaluate(&u, Some(&mut values), Some(&mut residual))
            .unwrap();
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert_eq!(after - before, 0, "allocations in 10 evaluations");
    assert!(values.iter().any(|&v| v != 0.0) && residual.iter().any(|&r| r != 0.0));
}
