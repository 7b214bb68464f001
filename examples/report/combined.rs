//! Normal and tangential load together: contact that forms under shear.

use std::fmt::Write as _;

use crate::Args;

/// A cylinder pressed and sheared together (docs/method.md §6.15, "Sub-
/// steps"): one step against 5, 20 and 100 and a one-shot solve, Mindlin's
/// proportional answer, and the path dependence of normal-then-shear.
pub(crate) fn combined(report: &mut String, a: &Args) {
    use tfem::scenes::cattaneo::{CattaneoMindlin, CombinedLoad, CombinedResult};
    let levels: Vec<f64> = if a.quick {
        vec![16.0]
    } else {
        vec![16.0, 32.0, 64.0]
    };
    let ratio = 0.15;
    writeln!(
        report,
        "## Normal and tangential load together\n\n\
         The cylinder of the Cattaneo–Mindlin scene (equal bodies, β = 0, μ = 0.3) pressed and \
         sheared together: its platen moved along ({ratio} δ, −δ), δ = P/E*, from rest, in N \
         equal load steps or one contact solve (N = 0; `CattaneoScene::combined`). Mindlin's \
         answer for proportional loading below μ: nothing slips and q = (Q/P)·p. Each element of \
         B that closes sticks from where along the load it closed, which a step finds by \
         sub-steps on its one factorisation. *diff to N = 100*: max |q − q₁₀₀|/(μp₀) over the \
         block's top nodes; *off Mindlin*: ‖q − (Q/P)p‖/‖(Q/P)p‖. Time: the steps (or the \
         solve) alone.\n\n\
         | h | N | time [s] | iterations | Q/P | slipping elements | diff to N = 100 | off Mindlin |\n\
         |---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let base = CattaneoMindlin::default();
    for &k in &levels {
        let cm = CattaneoMindlin {
            mesh_size: base.half_width / k,
            ..base
        };
        let run = |steps: usize| -> Result<CombinedResult, String> {
            let mut scene = cm.build().map_err(|e| e.to_string())?;
            let load = CombinedLoad { ratio, steps };
            scene.combined(&cm, load).map_err(|e| e.to_string())
        };
        let hundred = run(100);
        for steps in [0, 1, 5, 20, 100] {
            match (run(steps), hundred.as_ref()) {
                (Ok(r), Ok(h)) => writeln!(
                    report,
                    "| a/{k} | {steps} | {:.3} | {} | {:.5} | {} | {:.1e} | {:.3} |",
                    r.seconds,
                    r.iterations,
                    r.q_over_p,
                    r.slipping,
                    r.shear_difference(h),
                    r.off_proportional()
                )
                .unwrap(),
                (Err(e), _) => writeln!(report, "| a/{k} | {steps} | {e} | | | | | |").unwrap(),
                (_, Err(e)) => writeln!(report, "| a/{k} | {steps} | {e} | | | | | |").unwrap(),
            }
        }
    }
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / 16.0,
        ..base
    };
    for steps in [1, 5] {
        let load = CombinedLoad { ratio: 1.0, steps };
        match cm.build().and_then(|mut s| s.combined(&cm, load)) {
            Ok(r) => writeln!(
                report,
                "| a/16, along (δ, −δ) | {steps} | {:.3} | {} | {:.9} | {} | | |",
                r.seconds, r.iterations, r.q_over_p, r.slipping
            )
            .unwrap(),
            Err(e) => {
                writeln!(report, "| a/16, along (δ, −δ) | {steps} | {e} | | | | | |").unwrap()
            }
        }
    }
    writeln!(
        report,
        "\nAlong (δ, −δ) the shear exceeds μP: the interface slides whole, Q/P = μ.\n"
    )
    .unwrap();
    path_dependence(report, &base);
    unloading(report, &base);
}

/// Mindlin–Deresiewicz: loaded to Q/(μP) = 0.6 and unloaded to 0.3, against
/// loaded to 0.3 (Cattaneo's order: pressed, then sheared).
fn unloading(report: &mut String, base: &tfem::scenes::cattaneo::CattaneoMindlin) {
    use tfem::scenes::cattaneo::{
        CattaneoMindlin, cattaneo_mindlin, mindlin_deresiewicz, stick_half_width,
    };
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / 16.0,
        ..*base
    };
    let run = |ratios: &[f64]| cm.build().and_then(|mut s| s.solve_tfem(&cm, ratios));
    let (unloaded, loaded) = match (run(&[0.6, 0.3]), run(&[0.3])) {
        (Ok(u), Ok(l)) => (u, l),
        (Err(e), _) | (_, Err(e)) => {
            writeln!(report, "Mindlin–Deresiewicz: {e}\n").unwrap();
            return;
        }
    };
    let (su, sl) = (&unloaded.steps[2], &loaded.steps[1]);
    let (a, p0, mu) = (su.analytic.a, su.analytic.p0, cm.mu);
    let md = |x: f64| {
        let (c_star, c_back) = (stick_half_width(a, 0.6), stick_half_width(a, 0.15));
        mindlin_deresiewicz(a, c_star, c_back, p0, mu, x)
    };
    let cm_q = |x: f64| cattaneo_mindlin(a, stick_half_width(a, 0.3), p0, mu, x);
    let l2 = |t: &[(f64, f64, f64)], f: &dyn Fn(f64) -> f64| {
        let off: f64 = t.iter().map(|r| (r.2 - f(r.0)).powi(2)).sum();
        let size: f64 = t.iter().map(|r| f(r.0).powi(2)).sum();
        (off / size).sqrt()
    };
    let apart = su
        .traction
        .iter()
        .zip(&sl.traction)
        .map(|(u, l)| (u.2 - l.2).abs() / (mu * p0))
        .fold(0.0, f64::max);
    writeln!(
        report,
        "Unloading (Mindlin–Deresiewicz, Johnson §7.2), pressed then sheared at a/16: loaded to \
         Q/(μP) = 0.6 and unloaded to 0.3, the shear is {:.3} from Mindlin–Deresiewicz's (L2, \
         relative), reverse slip at the edges; loaded to 0.3 directly, {:.3} from \
         Cattaneo–Mindlin's; the two differ by up to {apart:.2} μp₀ at the same Q.\n",
        l2(&su.traction, &md),
        l2(&sl.traction, &cm_q)
    )
    .unwrap();
}

/// The same end point reached along another path: pressed first, then
/// sheared (Cattaneo's order), against both together.
fn path_dependence(report: &mut String, base: &tfem::scenes::cattaneo::CattaneoMindlin) {
    use tfem::scenes::cattaneo::{CattaneoMindlin, CombinedLoad};
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / 16.0,
        ..*base
    };
    let together = cm.build().and_then(|mut s| {
        s.combined(
            &cm,
            CombinedLoad {
                ratio: 0.15,
                steps: 1,
            },
        )
    });
    let first = cm.build().and_then(|mut s| {
        s.combined(
            &cm,
            CombinedLoad {
                ratio: 0.0,
                steps: 1,
            },
        )?;
        s.combined(
            &cm,
            CombinedLoad {
                ratio: 0.15,
                steps: 1,
            },
        )
    });
    match (together, first) {
        (Ok(t), Ok(f)) => writeln!(
            report,
            "\nThe path matters, as it should: the same platen move at a/16 taken pressed first \
             and sheared after (the shear as one load step from the pressed state) transmits Q/P = \
             {:.5} with {} elements slipping, against {:.5} and {} together; their shears differ \
             by up to {:.2} μp₀ (Cattaneo's order slips at the edges of contact, proportional \
             loading nowhere).\n",
            f.q_over_p,
            f.slipping,
            t.q_over_p,
            t.slipping,
            f.shear_difference(&t)
        )
        .unwrap(),
        (Err(e), _) | (_, Err(e)) => writeln!(report, "\nPath dependence: {e}\n").unwrap(),
    }
}
