//! Error against run time on manufactured elasticity solutions.

use std::fmt::Write as _;

use tfem::meshgen::unit_square;
use tfem::verification::{StudyPoint, fitted_rate, run_manufactured_elasticity};
use tfem::{Material, PlaneMode, Tempering};

use crate::Args;
use crate::common::{Curve, figure};

pub(crate) fn manufactured(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![8, 16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512, 724]
    };
    let mat = Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").expect("material");
    writeln!(
        report,
        "## Error against run time: manufactured elasticity\n"
    )
    .unwrap();
    writeln!(
        report,
        "u = (sin πx sin πy, sin 2πx sin πy) on the unit square, plane strain ν = 0.3, u prescribed on the \
         boundary. *Band*: the mesh contains a row of flattened caps of height 1e-9 along y = 1/2 \
         (docs/method.md §1). Energy error over the elements with J > 0 (the caps' true gradients are what \
         TFEM tempers, so on band meshes it measures the discrete function, not the tempered energy).\n"
    )
    .unwrap();
    let mut curves = Vec::new();
    for (name, band, tempering) in [
        ("regular, TFEM", None, Tempering::Auto),
        ("band, plain FEM", Some(1e-9), Tempering::Off),
        ("band, TFEM", Some(1e-9), Tempering::Auto),
    ] {
        writeln!(report, "### {name}\n\n| h | unknowns | time [s] | L2 error | energy error |\n|---|---|---|---|---|").unwrap();
        let mut pts: Vec<StudyPoint> = Vec::new();
        for &n in &levels {
            let n = if band.is_some() && n % 2 == 1 {
                n + 1
            } else {
                n
            };
            match run_manufactured_elasticity(unit_square(n, band), 1.0 / n as f64, mat, tempering)
            {
                Ok(p) => {
                    writeln!(
                        report,
                        "| 1/{n} | {} | {:.3} | {:.3e} | {:.3e} |",
                        p.unknowns, p.seconds, p.l2, p.energy
                    )
                    .unwrap();
                    pts.push(p);
                }
                Err(e) => writeln!(report, "| 1/{n} | – | – | {e} | |").unwrap(),
            }
        }
        let h: Vec<f64> = pts.iter().map(|p| p.h).collect();
        let l2: Vec<f64> = pts.iter().map(|p| p.l2).collect();
        let en: Vec<f64> = pts.iter().map(|p| p.energy).collect();
        let t: Vec<f64> = pts.iter().map(|p| p.seconds.max(1e-6)).collect();
        writeln!(
            report,
            "\nFitted rates in h: L2 {:.2}, energy {:.2}; L2 error against time: slope {:.2}.\n",
            fitted_rate(&h, &l2),
            fitted_rate(&h, &en),
            fitted_rate(&t, &l2)
        )
        .unwrap();
        curves.push(Curve {
            label: format!("{name} (L2)"),
            points: t.iter().copied().zip(l2).collect(),
        });
    }
    figure(
        report,
        a,
        "manufactured_error_time.svg",
        "manufactured elasticity: L2 error against wall time",
        "time [s]",
        "L2 error",
        &curves,
        "L2 error against time",
    );
}
