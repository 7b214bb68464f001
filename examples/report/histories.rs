//! Load histories: one factorisation for a hundred steps.

use std::fmt::Write as _;

use serde_json::Value;

use crate::Args;
use crate::speed::child;

pub(crate) fn histories(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick { vec![64] } else { vec![512, 1024] };
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    writeln!(report, "## Load histories\n").unwrap();
    writeln!(
        report,
        "The seed scene (2C/L = 0.2) loaded in 100 proportional steps (factors k/100, \
         `Model::step`), the last step's displacements recovered, against one contact solve of \
         the full load; each run in its own process. One factorisation serves the whole history \
         (the first step's); every later step is dense work on the contact interface, \
         warm-started from the step before. The last step equals the one-step answer to \
         round-off (`tests/history.rs`). Under the mortar weighting (the same matching scene) \
         the history works the same way on the weighted gaps (docs/method.md §6.11; \
         `tests/mortar_steps.rs`). *Field read at every step*: \
         the same history with the displacements asked for after each step (what a host \
         code that reads its results every step pays), at the coarsest level.\n"
    )
    .unwrap();
    writeln!(report, "| weighting | h | unknowns | one solve [s] | 100 steps [s] | of which recovery [s] | ratio | field read at every step [s] | factorisations | active-set iterations | peak RSS one solve / history [MB] |\n|---|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let runs = [
        ("strip", "condensed", "history100"),
        ("mortar", "mortar", "mortar-history100"),
    ];
    // A history that reads the field at every step pays a recovery per
    // step: measured at the coarsest level only.
    for ((weighting, solve, history), &n) in
        runs.iter().flat_map(|r| levels.iter().map(move |n| (r, n)))
    {
        let (Some(one), Some(h)) = (child(n, "nd", solve), child(n, "nd", history)) else {
            writeln!(report, "| {weighting} | 1/{n} | run failed |").unwrap();
            continue;
        };
        let read = match n == levels[0] {
            true => child(n, "nd", &format!("{history}-read"))
                .map_or("failed".to_string(), |r| format!("{:.2}", f(&r, "total"))),
            false => "—".to_string(),
        };
        writeln!(
            report,
            "| {weighting} | 1/{n} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {read} | {} | {} | {:.0} / {:.0} |",
            one["unknowns"],
            f(&one, "total"),
            f(&h, "total"),
            f(&h, "recovery"),
            f(&h, "total") / f(&one, "total"),
            h["factorizations"],
            h["iterations"],
            f(&one, "rss_peak") / 1e6,
            f(&h, "rss_peak") / 1e6,
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}
