//! Two full rings in a shrink fit whose interface nodes do not match (2:3,
//! the coarser ring inside, every node on its circle): what a user gets by
//! default, with no choice to make (docs/method.md §6.11). Lamé's pressure
//! of the meshed polygons' overlap is the reference: the discretisation of
//! the meshed geometry converges to it.
//!
//! Measured at 128/192, 256/384, 512/768 and 1024/1536 cells (the last in
//! probes/ring_study.rs): mean nodal pressure over that reference −1e-3,
//! −3e-4, 0, 0; spread of the slave nodes' pressures ±10.9, 5.5, 2.8,
//! 1.4 %; contact length within δ/b of 2πb; reactions of the rigid-motion
//! constraints 3e-13 … 2e-10 of p·b.

use tfem::scenes::shrink_fit::{ShrinkFit, ShrinkFitScene};
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, ContactWeighting, Model};

fn solved(fit: ShrinkFit) -> ShrinkFitScene {
    let mut s = fit.build().unwrap();
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    s
}

fn fit(inner_cells: usize, pieces: usize) -> ShrinkFit {
    ShrinkFit {
        inner_cells,
        outer_cells: inner_cells * 3 / 2,
        pieces,
        ..Default::default()
    }
}

/// Lamé's pressure of the meshed polygons on the bore (r = b); on the
/// inner ring's surface (r = b + δ) it is b/(b + δ) of that.
fn reference(fit: &ShrinkFit, s: &ShrinkFitScene) -> f64 {
    s.exact.pressure * fit.polygon_factor()
}

/// The tributary-weighted mean and the extremes of the nodal pressures on
/// the ring surface `nodes` (a closed polygon, by angle).
fn mean_and_range(model: &Model, nodes: &[usize]) -> (f64, f64, f64) {
    let p = model.contact_nodal_pressures().unwrap();
    let x = model.mesh().unwrap().nodes();
    let n = nodes.len();
    let (mut sum, mut length) = (0.0, 0.0);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..n {
        let (v, w) = (nodes[k], nodes[(k + 1) % n]);
        let l = (x[w][0] - x[v][0]).hypot(x[w][1] - x[v][1]);
        sum += 0.5 * l * (p[v] + p[w]);
        length += l;
        lo = lo.min(p[v]);
        hi = hi.max(p[v]);
    }
    (sum / length, lo, hi)
}

#[test]
fn by_default_non_matching_rings_read_lames_pressure_of_the_meshed_geometry() {
    for cells in [128, 256] {
        let f = fit(cells, 2);
        let s = solved(f);
        let p = reference(&f, &s);
        let (mean, ..) = mean_and_range(&s.model, &s.inner);
        assert!(
            (mean / p - 1.0).abs() < 2e-3,
            "{cells}: mean {:.3e} of Lamé's",
            mean / p - 1.0
        );
    }
}

#[test]
fn by_default_the_nodal_pressures_of_non_matching_rings_converge() {
    let spreads: Vec<f64> = [128, 256, 512]
        .iter()
        .map(|&cells| {
            let f = fit(cells, 2);
            let s = solved(f);
            let p = reference(&f, &s);
            let (_, lo, hi) = mean_and_range(&s.model, &s.inner);
            (hi - lo) / (2.0 * p)
        })
        .collect();
    let hs = [1.0, 0.5, 0.25];
    let rate = fitted_rate(&hs, &spreads);
    assert!(
        rate > 0.9 && spreads[2] < 0.03,
        "spreads {spreads:?}, rate {rate}"
    );
}

#[test]
fn by_default_the_contact_length_of_non_matching_rings_is_the_circle() {
    let f = fit(128, 2);
    let mut s = f.build().unwrap();
    let report = s.model.solve_contact(&ContactOptions::default()).unwrap();
    let b = f.lame().radius;
    let circle = 2.0 * std::f64::consts::PI * b;
    let h = circle / 128.0;
    assert!(
        (report.contact_length - circle).abs() < h,
        "{:.4e} against {circle:.4e}",
        report.contact_length
    );
}

#[test]
fn the_supports_of_self_equilibrated_rings_carry_round_off_and_are_not_warned_about() {
    let f = fit(128, 2);
    let s = solved(f);
    let (p, b) = (reference(&f, &s), f.lame().radius);
    let r = s.model.reactions().unwrap();
    let largest = s
        .supports
        .iter()
        .fold(0.0f64, |m, &v| m.max(r[v][0].abs()).max(r[v][1].abs()));
    assert!(largest < 1e-10 * p * b, "{:.2e} p·b", largest / (p * b));
    let warnings = s.model.warnings();
    assert!(warnings.is_empty(), "{warnings:?}");
}

/// The largest difference of the nodal pressures of the rings cut into two
/// pairs and of the rings as one closed interface, over the largest.
fn halves_against_loop(cells: usize) -> f64 {
    let halves = solved(fit(cells, 2));
    let whole = solved(fit(cells, 1));
    let (a, b) = (
        halves.model.contact_nodal_pressures().unwrap(),
        whole.model.contact_nodal_pressures().unwrap(),
    );
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = a
        .iter()
        .zip(&b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    worst / scale
}

#[test]
fn a_ring_is_one_interface_read_as_its_two_halves_are() {
    // The junctions of the halves (one weighted gap per junction node)
    // read the master a little differently near its ends: measured
    // 1.13e-5, 5.75e-6, 3.11e-6 of the largest pressure at 128, 256, 512
    // cells, first order.
    let (coarse, fine) = (halves_against_loop(128), halves_against_loop(256));
    assert!(
        coarse < 2e-5 && fine < 0.6 * coarse,
        "{coarse:.2e}, {fine:.2e}"
    );
}

/// The contact length the strip forced on the rings reports over the
/// circle, and whether the solve warned "one-sided".
fn strip_forced(pieces: usize) -> (f64, bool) {
    let f = fit(128, pieces);
    let mut s = f.build().unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Strip)
        .unwrap();
    let report = s.model.solve_contact(&ContactOptions::default()).unwrap();
    let circle = 2.0 * std::f64::consts::PI * f.lame().radius;
    let warned = s.model.warnings().iter().any(|w| w.contains("one-sided"));
    (report.contact_length / circle, warned)
}

#[test]
fn the_strip_forced_on_non_matching_rings_is_warned_about() {
    let (length, warned) = strip_forced(2);
    // Each pressed element is a zone of its own: a third of the circle.
    assert!(length < 0.4, "{length}");
    assert!(warned);
}

#[test]
fn the_strip_forced_on_a_ring_as_one_closed_interface_is_built_and_warned_about() {
    // Walked over one turn of each loop, the strip reads the ring as it
    // reads its halves.
    let (halves, _) = strip_forced(2);
    let (ring, warned) = strip_forced(1);
    assert!((ring - halves).abs() < 1e-3, "{ring} against {halves}");
    assert!(warned);
}
