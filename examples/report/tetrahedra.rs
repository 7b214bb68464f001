//! The study of Jmin in three dimensions (docs/method.md §9, issue 41 stage
//! 1): plain FEM against candidate tempering rules on regular tetrahedral
//! meshes and on bands of flat tetrahedra.

use std::fmt::Write as _;

use tfem::Tempering;
use tfem::studies::tet_study::{TetPoint, TetStudy, TetTempering, tied_patch_test};
use tfem::studies::tetmesh::{Band, Split, TetMesh};
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::{Curve, figure};

/// A mesh family of the study: its name and its band at level n.
struct Family {
    name: &'static str,
    band: fn(usize) -> Option<Band>,
}

const EPS: f64 = 1e-9;

fn families() -> [Family; 5] {
    [
        Family {
            name: "regular (Kuhn)",
            band: |_| None,
        },
        Family {
            name: "staggered band, eps = 1e-9",
            band: |_| Some(Band::Staggered(EPS)),
        },
        Family {
            name: "staggered band, eps = h²",
            band: |n| Some(Band::Staggered((n as f64).powi(-2))),
        },
        Family {
            name: "prism layer, eps = 1e-9",
            band: |_| Some(Band::Prisms(EPS)),
        },
        Family {
            name: "needles, eps = 1e-9",
            band: |_| Some(Band::Needles(EPS)),
        },
    ]
}

fn policies() -> Vec<(&'static str, TetTempering)> {
    let power = |k, c, cap| TetTempering::Power {
        k,
        c,
        lambda: 1.0,
        cap,
    };
    let inf = f64::INFINITY;
    vec![
        ("plain FEM", TetTempering::Off),
        ("k = 3, c = 0.01", power(3, 0.01, inf)),
        ("k = 3, c = 0.1", power(3, 0.1, inf)),
        ("k = 4, c = 0.1", power(4, 0.1, inf)),
        ("k = 4, c = 1", power(4, 1.0, inf)),
        (
            "**chosen**: min(h⁴/λ, 0.1 h³)",
            TetTempering::Policy(Tempering::Auto),
        ),
    ]
}

pub(crate) fn tetrahedra(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![4, 8]
    } else {
        vec![4, 8, 16, 32]
    };
    intro(report, &levels);
    let mut curves = Vec::new();
    let mut regular_l2: Vec<f64> = Vec::new();
    for (f, family) in families().iter().enumerate() {
        writeln!(report, "### {}\n", family.name).unwrap();
        write!(report, "| Jmin |").unwrap();
        for n in &levels {
            write!(report, " L2, h = 1/{n} |").unwrap();
        }
        writeln!(
            report,
            " L2 rate | energy | rate | energy off the band | rate | time [s] |"
        )
        .unwrap();
        writeln!(
            report,
            "|---{}|---|---|---|---|---|---|",
            "|---".repeat(levels.len())
        )
        .unwrap();
        for (name, tempering) in policies() {
            // The regular mesh: plain FEM, the chosen rule (which leaves it
            // plain) and k = 4 without its cap (which does not).
            let uncapped_k4 = matches!(tempering, TetTempering::Power { k: 4, c, .. } if c == 1.0);
            if f == 0
                && !(uncapped_k4
                    || matches!(tempering, TetTempering::Off | TetTempering::Policy(_)))
            {
                continue;
            }
            let points = run(family, tempering, &levels);
            row(report, name, &points);
            if let Ok(pts) = &points {
                if f == 0 && matches!(tempering, TetTempering::Off) {
                    regular_l2 = pts.iter().map(|p| p.point.l2).collect();
                }
                if f == 1 && matches!(tempering, TetTempering::Off | TetTempering::Policy(_)) {
                    curves.push(Curve {
                        label: format!("staggered band, {}", name.trim_matches('*')),
                        points: pts.iter().map(|p| (p.point.h, p.point.l2)).collect(),
                    });
                }
            }
        }
        writeln!(report).unwrap();
    }
    curves.push(Curve {
        label: "regular mesh".into(),
        points: levels
            .iter()
            .map(|&n| 1.0 / n as f64)
            .zip(regular_l2)
            .collect(),
    });
    tied(report, &levels);
    figure(
        report,
        a,
        "tetrahedra_l2.svg",
        "tetrahedra: L2 error on a band of caps and slivers",
        "h",
        "L2 error",
        &curves,
        "L2 error against h, tetrahedra",
    );
}

fn intro(report: &mut String, levels: &[usize]) {
    writeln!(report, "## Tempered tetrahedra: the choice of Jmin in 3D\n").unwrap();
    writeln!(
        report,
        "u = (1, −2, 1.5) sin πx sin πy sin πz on the unit cube, E = 1, ν = 0.3, u prescribed on the \
         boundary; Kuhn's six tetrahedra per box of side h = 1/n (n = {}). Bands across z = 1/2 \
         (`tfem::studies::tetmesh`): *staggered*, a sheet of nodes at height eps over the cell centres \
         joined to the grid planes by pyramids split into caps and by slivers (a grid edge and the \
         crossing sheet edge, no short edge) — the 3D analogue of the 2D band of caps; *prism layer*, \
         Kuhn boxes of height eps, the layer of split prisms a closed 3D gap is meshed with; *needles*, \
         two such slabs crossing (x and z), needles where they cross. Jmin = min(c·h^k/λ^(k−3), cap·h³) \
         with h the tetrahedron's longest edge and λ = 1; *chosen* is `Tempering::Auto` for \
         tetrahedra. L2 rate: fitted over the levels. *energy*: over every tetrahedron with its true \
         volume (as in 2D, a flat tetrahedron's own gradient enters); *off the band*: over the \
         tetrahedra with J ≥ 0.01 h³. One thread, AMD ordering, time of all levels' solves.\n",
        levels
            .iter()
            .map(|n| n.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )
    .unwrap();
}

fn run(family: &Family, tempering: TetTempering, levels: &[usize]) -> tfem::Result<Vec<TetPoint>> {
    let study = TetStudy {
        young: 1.0,
        poisson: 0.3,
        tempering,
        layer: tempering,
    };
    levels
        .iter()
        .map(|&n| study.run(&TetMesh::unit_cube(n, (family.band)(n)), 1.0 / n as f64))
        .collect()
}

fn row(report: &mut String, name: &str, points: &tfem::Result<Vec<TetPoint>>) {
    let pts = match points {
        Ok(p) => p,
        Err(e) => {
            writeln!(report, "| {name} | {} |", e.message()).unwrap();
            return;
        }
    };
    let h: Vec<f64> = pts.iter().map(|p| p.point.h).collect();
    let rate = |e: Vec<f64>| fitted_rate(&h, &e);
    write!(report, "| {name} |").unwrap();
    for p in pts {
        write!(report, " {:.3e} |", p.point.l2).unwrap();
    }
    let last = pts.last().expect("a level");
    writeln!(
        report,
        " {:.2} | {:.3e} | {:.2} | {:.3e} | {:.2} | {:.1} |",
        rate(pts.iter().map(|p| p.point.l2).collect()),
        last.point.energy,
        rate(pts.iter().map(|p| p.point.energy).collect()),
        last.energy_well_shaped,
        rate(pts.iter().map(|p| p.energy_well_shaped).collect()),
        pts.iter().map(|p| p.point.seconds).sum::<f64>()
    )
    .unwrap();
}

/// Stage 2: two blocks tied through a layer of zero-volume prisms.
fn tied(report: &mut String, levels: &[usize]) {
    writeln!(
        report,
        "### Two blocks tied through flat tetrahedra\n\n\
         `TetMesh::tied_blocks`: the cube cut at z = 1/2 into two Kuhn blocks with their own nodes on \
         the interface, joined by the layer of zero-volume prisms over its triangles, each split into \
         three tetrahedra from every quadrilateral face's lowest-ranked node (ranks: node indices or a \
         shuffle); *jittered*: interface nodes moved in the plane by up to 0.2 h. The layer's tie \
         T_e = A_e h_c²/λ (A_e the tetrahedron's largest face, h_c = h, λ = 1); the blocks tempered by \
         the chosen rule. *Patch test*: lower block E = 1 with its boundary prescribed, upper block \
         E = 10 loaded by the tractions of a uniform stress (σ_zz = 1, σ_xz = 0.3, σ_yz = −0.2, \
         σ_xx = σ_yy = ν/(1 − ν)) and held by the layer alone; largest stress error of a block \
         tetrahedron over |σ|, and the spread of the jump across the layer over its mean.\n"
    )
    .unwrap();
    writeln!(
        report,
        "| mesh | split | layer's Jmin | stress error | jump spread |\n|---|---|---|---|---|"
    )
    .unwrap();
    for n in [4, 8] {
        for (split, split_name) in [
            (Split::ByIndex, "by index"),
            (Split::Shuffled(1), "shuffled"),
        ] {
            for jitter in [0.0, 0.2] {
                let mut mesh = TetMesh::tied_blocks(n, split);
                mesh.jitter_interface(1.0 / n as f64, jitter, 99);
                let tie = TetTempering::Tie {
                    h_c: 1.0 / n as f64,
                    lambda: 1.0,
                };
                let blocks_rule = TetTempering::Policy(Tempering::Auto);
                for (rule, rule_name) in
                    [(tie, "tie A_e h_c²/λ"), (blocks_rule, "min(h⁴/λ, 0.1 h³)")]
                {
                    let mesh_name =
                        format!("h = 1/{n}{}", if jitter > 0.0 { ", jittered" } else { "" });
                    match tied_patch_test(&mesh, [1.0, 10.0], 0.3, rule) {
                        Ok(r) => writeln!(
                            report,
                            "| {mesh_name} | {split_name} | {rule_name} | {:.1e} | {:.1e} |",
                            r.stress_error, r.jump_spread
                        ),
                        Err(e) => writeln!(
                            report,
                            "| {mesh_name} | {split_name} | {rule_name} | {} | |",
                            e.message()
                        ),
                    }
                    .unwrap();
                }
            }
        }
    }
    writeln!(
        report,
        "\nThe manufactured field across the tied interface (split shuffled, tie as above) against one \
         body:\n\n| h | L2, tied | L2, one body | energy, tied | energy, one body |\n|---|---|---|---|---|"
    )
    .unwrap();
    let (mut h, mut tied_l2) = (Vec::new(), Vec::new());
    for &n in levels {
        let study = TetStudy {
            young: 1.0,
            poisson: 0.3,
            tempering: TetTempering::Policy(Tempering::Auto),
            layer: TetTempering::Tie {
                h_c: 1.0 / n as f64,
                lambda: 1.0,
            },
        };
        let size = 1.0 / n as f64;
        let tied = study.run(&TetMesh::tied_blocks(n, Split::Shuffled(5)), size);
        let one = study.run(&TetMesh::unit_cube(n, None), size);
        match (tied, one) {
            (Ok(t), Ok(o)) => {
                writeln!(
                    report,
                    "| 1/{n} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |",
                    t.point.l2, o.point.l2, t.energy_well_shaped, o.energy_well_shaped
                )
                .unwrap();
                h.push(size);
                tied_l2.push(t.point.l2);
            }
            (Err(e), _) | (_, Err(e)) => {
                writeln!(report, "| 1/{n} | {} | | | |", e.message()).unwrap()
            }
        }
    }
    if h.len() >= 2 {
        writeln!(
            report,
            "\nTied L2 rate: {:.2}.\n",
            fitted_rate(&h, &tied_l2)
        )
        .unwrap();
    }
}
