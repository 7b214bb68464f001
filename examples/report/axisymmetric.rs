//! Axisymmetric bodies (docs/method.md §7): error against run time on a
//! manufactured ring field (regular, band of caps), Lamé's thick cylinder,
//! the axisymmetric contact patch test and a hub shrunk on a shaft with
//! its push-out force.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::revolution::{
    ShaftHub, StackedCylinders, ThickCylinder, ring_square, run_manufactured_ring,
};
use tfem::scenes::sphere::{CylindricalPunch, Sphere};
use tfem::verification::{StudyPoint, fitted_rate};
use tfem::{Material, PlaneMode, Tempering};

use crate::Args;
use crate::common::{Curve, failure, figure};

pub(crate) fn axisymmetric(report: &mut String, a: &Args) {
    writeln!(report, "## Axisymmetric bodies\n").unwrap();
    writeln!(
        report,
        "x = r the radius, y = z the axis; every force the whole ring's (docs/method.md §7). The \
         tempered ring element is (J/max(J, Jmin))·K, semidefinite for every J.\n"
    )
    .unwrap();
    let mut curves = manufactured(report, a);
    thick_cylinder(report, a);
    patch_test(report);
    curves.push(shaft_hub(report, a));
    curves.extend(indentation(report));
    figure(
        report,
        a,
        "axisymmetric_error_time.svg",
        "Axisymmetric: error against run time",
        "solve time [s]",
        "error",
        &curves,
        "Error against run time: the manufactured ring field and the shrink fit's pressure",
    );
}

fn manufactured(report: &mut String, a: &Args) -> Vec<Curve> {
    let levels: Vec<usize> = if a.quick {
        vec![4, 8, 16, 32]
    } else {
        vec![8, 16, 32, 64, 128, 256]
    };
    let steel = Material::new(210e3, 0.3, PlaneMode::Axisymmetric, "body 1").expect("material");
    writeln!(
        report,
        "### A manufactured ring field\n\nu_r = r² sin z/10, u_z = z cos r/10 on [r0, r0 + 1] × [0, 1], \
         u prescribed on the boundary (u_r = 0 on the axis), ν = 0.3; L2 error weighted by 2πr. \
         *Band*: a row of caps of height h⁵ along z = 1/2.\n"
    )
    .unwrap();
    let mut curves = Vec::new();
    for (name, r0, band, tempering) in [
        ("axis in the mesh, TFEM", 0.0, false, Tempering::Auto),
        ("r in [1, 2], TFEM", 1.0, false, Tempering::Auto),
        ("band, axis, plain FEM", 0.0, true, Tempering::Off),
        ("band, axis, TFEM", 0.0, true, Tempering::Auto),
    ] {
        writeln!(
            report,
            "#### {name}\n\n| h | unknowns | time [s] | L2 error |\n|---|---|---|---|"
        )
        .unwrap();
        let mut pts: Vec<StudyPoint> = Vec::new();
        for &n in &levels {
            let eps = band.then(|| (1.0 / n as f64).powi(5));
            let h = 1.0 / n as f64;
            match run_manufactured_ring(ring_square(r0, n, eps), h, steel, tempering) {
                Ok(p) => {
                    writeln!(
                        report,
                        "| 1/{n} | {} | {:.3} | {:.3e} |",
                        p.unknowns, p.seconds, p.l2
                    )
                    .unwrap();
                    pts.push(p);
                }
                Err(e) => writeln!(report, "| 1/{n} | – | – | {} |", failure(&e)).unwrap(),
            }
        }
        let h: Vec<f64> = pts.iter().map(|p| p.h).collect();
        let l2: Vec<f64> = pts.iter().map(|p| p.l2).collect();
        let t: Vec<f64> = pts.iter().map(|p| p.seconds.max(1e-6)).collect();
        writeln!(
            report,
            "\nFitted L2 rate in h {:.2}; against time {:.2}.\n",
            fitted_rate(&h, &l2),
            fitted_rate(&t, &l2)
        )
        .unwrap();
        curves.push(Curve {
            label: format!("manufactured, {name}"),
            points: t.into_iter().zip(l2).collect(),
        });
    }
    curves
}

fn thick_cylinder(report: &mut String, a: &Args) {
    let levels: &[usize] = if a.quick {
        &[4, 8, 16, 32]
    } else {
        &[8, 16, 32, 64, 128]
    };
    writeln!(
        report,
        "### Lamé's thick cylinder\n\na = 1, b = 2, ℓ = 1, ends held axially, internal pressure p. \
         Element hoop and radial stresses at the centroid against Lamé's (over p), nodal u_r (over u_r(a)), \
         the ends' axial force against 2πνA(b² − a²).\n\n\
         | cells over the wall | unknowns | time [s] | hoop | radial | u_r | axial force |\n|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for &cells in levels {
        match (ThickCylinder {
            cells,
            ..Default::default()
        })
        .solve()
        {
            Ok(r) => writeln!(
                report,
                "| {cells} | {} | {:.3} | {:.2e} | {:.2e} | {:.2e} | {:.1e} |",
                r.unknowns,
                r.seconds,
                r.hoop_error,
                r.radial_error,
                r.displacement_error,
                r.axial_force_error
            )
            .unwrap(),
            Err(e) => writeln!(report, "| {cells} | {} |", failure(&e)).unwrap(),
        }
    }
    writeln!(
        report,
        "\nStresses of constant-strain elements read at their centroid converge at first order; \
         the displacements faster.\n"
    )
    .unwrap();
}

fn patch_test(report: &mut String) {
    writeln!(
        report,
        "### The axisymmetric contact patch test\n\nTwo coaxial cylinders (r0 = 0) or tubes (r0 = 1) of width 1 \
         stacked along z, uniform pressure p on top, frictionless; lower cells / upper cells over the width, \
         moduli lower / upper, ν 0.3 / 0.2. Largest error of any stress component (hoop included), of the nodal \
         pressures and of the base's force, over p.\n\n\
         | r0 | cells | moduli | stress | nodal pressure | base force | time [s] |\n|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for inner in [0.0, 1.0] {
        for cells in [[8, 8], [8, 12], [7, 3]] {
            for e in [[1e3, 1e3], [1e3, 1e4]] {
                let scene = StackedCylinders {
                    inner,
                    cells,
                    e,
                    nu: [0.3, 0.2],
                    ..Default::default()
                };
                let t0 = Instant::now();
                match scene.solve() {
                    Ok(r) => writeln!(
                        report,
                        "| {inner} | {}/{} | {:.0e}/{:.0e} | {:.1e} | {:.1e} | {:.1e} | {:.3} |",
                        cells[0],
                        cells[1],
                        e[0],
                        e[1],
                        r.stress_error,
                        r.pressure_error,
                        r.force_error,
                        t0.elapsed().as_secs_f64()
                    )
                    .unwrap(),
                    Err(e) => writeln!(report, "| {inner} | {} |", failure(&e)).unwrap(),
                }
            }
        }
    }
    writeln!(report).unwrap();
}

fn shaft_hub(report: &mut String, a: &Args) -> Curve {
    let levels: &[usize] = if a.quick {
        &[4, 8, 16, 32]
    } else {
        &[8, 16, 32, 64, 128]
    };
    writeln!(
        report,
        "### A hub shrunk on a shaft\n\nb = 1, c = 2, ℓ = 2, δ = 10⁻³ b, steel, ends held axially; hub and shaft \
         nodes 3:2 along the interface. Mean contact pressure over the middle half of the length and its largest \
         nodal deviation, hub hoop stress at the bore and shaft hoop stress, against Lamé's plane-strain shrink \
         fit; with μ = 0.1 the shaft pushed by δ (one more load step on the same factorisation): the push-out \
         force against 2πbℓμp.\n\n\
         | h | unknowns | fit [s] | pressure | spread | hub hoop | shaft hoop | push-out | push-out [s] |\n\
         |---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut points = Vec::new();
    for &cells in levels {
        let fit = ShaftHub {
            cells,
            mu: 0.1,
            ..Default::default()
        };
        let solved = fit.solve();
        let t0 = Instant::now();
        let push = fit.push_out(fit.interference, 1);
        let push_seconds = t0.elapsed().as_secs_f64();
        match (solved, push) {
            (Ok((_, r)), Ok((force, _))) => {
                writeln!(
                    report,
                    "| b/{cells} | {} | {:.3} | {:+.2e} | {:.2e} | {:+.2e} | {:+.2e} | {:+.2e} | {:.3} |",
                    r.unknowns,
                    r.seconds,
                    r.pressure_error,
                    r.pressure_spread,
                    r.hub_hoop_error,
                    r.shaft_hoop_error,
                    force / fit.push_out_force() - 1.0,
                    push_seconds
                )
                .unwrap();
                points.push((r.seconds.max(1e-6), r.pressure_error.abs()));
            }
            (Err(e), _) | (_, Err(e)) => {
                writeln!(report, "| b/{cells} | {} |", failure(&e)).unwrap()
            }
        }
    }
    writeln!(
        report,
        "\nThe mean pressure levels off at −δ/(2b) and the shaft's hoop stress at −δ/b: the O(δ/b) left \
         between the meshed geometry (the shaft's surface at b + δ) and Lamé's small-interference formula. \
         CalculiX on the same mesh: docs/calculix.md.\n"
    )
    .unwrap();
    Curve {
        label: "shrink fit, mean pressure".to_string(),
        points,
    }
}

fn indentation(report: &mut String) -> Vec<Curve> {
    writeln!(
        report,
        "### A sphere on a block (Hertz) and a rigid flat punch (Boussinesq)\n\nSphere R = 1 on a block of \
         radius and depth 100a (a = 0.02R), frictionless, P a pressure on the sphere's equatorial cut; a from \
         the contact's extent, p₀ fitted to the nodal pressures within 0.8a (the axis node alone converges at \
         first order: it carries a tributary of πh²/3). Punch of radius a into a block of 500a graded towards \
         the punch's edge: P from its whole-ring reactions against 2aE*δ, and the largest error of p(r) within \
         0.8a.\n\n| case | h | unknowns | time [s] | a | p₀ | P | p(r) |\n|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let rel = |x: f64, y: f64| x / y - 1.0;
    let mut curves = Vec::new();
    for (name, ratio) in [("sphere, equal moduli", 1.0), ("sphere 10× stiffer", 10.0)] {
        let mut points = Vec::new();
        for k in [8.0, 16.0, 32.0] {
            let base = Sphere::default();
            let s = Sphere {
                mesh_size: base.contact_radius / k,
                e_sphere: ratio * base.e_block,
                ..base
            };
            let t0 = Instant::now();
            match s
                .build()
                .and_then(|mut b| b.solve(&s, &ContactOptions::default()))
            {
                Ok(r) => {
                    let t = t0.elapsed().as_secs_f64();
                    writeln!(
                        report,
                        "| {name} | a/{k} | {} | {t:.3} | {:+.2e} | {:+.2e} | | |",
                        r.report.info.unknowns,
                        rel(r.a, r.a_exact),
                        rel(r.p0_fit, r.p0_exact)
                    )
                    .unwrap();
                    points.push((t, rel(r.p0_fit, r.p0_exact).abs()));
                }
                Err(e) => writeln!(report, "| {name} | a/{k} | {} |", failure(&e)).unwrap(),
            }
        }
        curves.push(Curve {
            label: format!("Hertz p0, {name}"),
            points,
        });
    }
    let mut points = Vec::new();
    for k in [8.0, 16.0, 32.0] {
        let p = CylindricalPunch {
            mesh_size: 1.0 / k,
            ..Default::default()
        };
        let t0 = Instant::now();
        match p
            .build()
            .and_then(|mut b| b.solve(&p, &ContactOptions::default()))
        {
            Ok(r) => {
                let t = t0.elapsed().as_secs_f64();
                writeln!(
                    report,
                    "| flat punch | a/{k} | {} | {t:.3} | | | {:+.2e} | {:.2e} |",
                    r.report.info.unknowns,
                    rel(r.force, r.force_exact),
                    r.pressure_error
                )
                .unwrap();
                points.push((t, rel(r.force, r.force_exact).abs()));
            }
            Err(e) => writeln!(report, "| flat punch | a/{k} | {} |", failure(&e)).unwrap(),
        }
    }
    curves.push(Curve {
        label: "punch P".to_string(),
        points,
    });
    writeln!(report).unwrap();
    curves
}
