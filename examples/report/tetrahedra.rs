//! The study of Jmin in three dimensions (docs/method.md §9, issue 41 stage
//! 1): plain FEM against candidate tempering rules on regular tetrahedral
//! meshes and on bands of flat tetrahedra.

use std::fmt::Write as _;

use tfem::studies::graded_punch::GradedPunch;
use tfem::studies::tet_contact::contact_patch_test;
use tfem::studies::tet_scenes::{Hertz3d, Punch3d, TwoBlocks3d, TwoBlocks3dResult};
use tfem::studies::tet_study::{TetPoint, TetStudy, TetTempering, tied_patch_test};
use tfem::studies::tetmesh::{Band, Split, TetMesh};
use tfem::verification::fitted_rate;
use tfem::{Ordering, Tempering};

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
    contact(report, a);
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
         tetrahedra with J ≥ 0.01 h³. The machine's threads (2), AMD below 10k unknowns and nested dissection above, time of all levels' solves.\n",
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
                mesh.jitter_interface(0.5, 1.0 / n as f64, jitter, 99);
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
    tied_convergence(report, levels);
}

/// The manufactured field across a tied interface against one body.
fn tied_convergence(report: &mut String, levels: &[usize]) {
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

/// Stage 3 as a study: contact through B in 3D.
fn contact(report: &mut String, a: &Args) {
    writeln!(
        report,
        "### Contact through a layer of flat tetrahedra (stage 3)\n\n\
         `tfem::studies::tet_contact`: two Kuhn blocks, B the layer of zero-volume prisms between their \
         matching surfaces (split from node ranks), each tetrahedron of B switched on where it would \
         invert (g = Σ w_k·u_k < 0, w_k = (n·a_k) n) with K = (E_c/(6T_e)) w wᵀ, T_e = A_e h_c²/λ, \
         E_c the smaller modulus, from the elements touching at rest. Solved by the product's active-set \
         loop, B's tetrahedra its third kind of constraint (`contact::gap_tets`, `solve::solid`: the \
         interface condensed where that pays); tests/tet_contact.rs holds it to the study's own primal \
         loop, an independent prototype (the same sets, values to 1e-10). *Patch test*: the unit square's blocks (z < 0 with E = 1, z > 0 with \
         E = 10, ν = 0.3), the top pressed by p, the bottom and the planes x = 0, y = 0 on rollers; \
         largest stress error of a block tetrahedron over p and spread of the overlap over its mean.\n\n\
         | h | split | interface | stress error | overlap spread | all in contact |\n|---|---|---|---|---|---|"
    )
    .unwrap();
    for n in [4, 8] {
        for (split, name) in [
            (Split::ByIndex, "by index"),
            (Split::Shuffled(1), "shuffled"),
        ] {
            for jitter in [0.0, 0.2] {
                let mesh = TetMesh::patch_blocks(n, split, jitter);
                let kind = if jitter > 0.0 {
                    "jittered 0.2 h"
                } else {
                    "uniform"
                };
                match contact_patch_test(&mesh, [1.0, 10.0], 0.3, 1.0) {
                    Ok(r) => writeln!(
                        report,
                        "| 1/{n} | {name} | {kind} | {:.1e} | {:.1e} | {} |",
                        r.stress_error, r.overlap_spread, r.all_active
                    ),
                    Err(e) => writeln!(report, "| 1/{n} | {name} | {kind} | {} | | |", e.message()),
                }
                .unwrap();
            }
        }
    }
    seed_3d(report, a);
    hertz_3d(report, a);
    punch_3d(report, a);
    ordering_3d(report, a);
}

/// A rigid flat cylindrical punch in 3D against Boussinesq.
fn punch_3d(report: &mut String, a: &Args) {
    let scene = Punch3d::default();
    writeln!(
        report,
        "A rigid flat cylindrical punch in 3D (`Punch3d`: radius a, indentation δ = 1e-3a, E = 1, \
         ν = {}; the block on rollers at its bottom; the punch a layer of tetrahedra over the disc \
         r ≤ a, every node prescribed (0, 0, −δ), B between, frictionless; quarter model). The \
         block's top follows the punch's circle: a grid of step a/k at the punch's edge and at the \
         top, each step `growth` times the last away from them, its square [0, a]² mapped onto the \
         disc. P against Boussinesq's 2aE*δ, E* = E/(1 − ν²), for a half-space; the contact area (every \
         element of B on) against πa².\n",
        scene.poisson
    )
    .unwrap();
    let series: Vec<(&str, Vec<Punch3d>)> = match a.quick {
        true => vec![(
            "growth 1.3, block 25a",
            vec![Punch3d {
                extent: 25.0,
                refinement: 4.0,
                ..scene
            }],
        )],
        false => {
            let at = |refinement, extent, growth| Punch3d {
                refinement,
                extent,
                growth,
                ..scene
            };
            vec![
                (
                    "convergence: growth 1.15, block 200a",
                    [8.0, 16.0, 32.0].map(|k| at(k, 200.0, 1.15)).to_vec(),
                ),
                (
                    "the block's size: a/16, growth 1.3",
                    [25.0, 50.0, 100.0, 200.0, 400.0]
                        .map(|e| at(16.0, e, 1.3))
                        .to_vec(),
                ),
            ]
        }
    };
    writeln!(
        report,
        "| series | k | block | unknowns | factorisations | time [s] | P | contact area |\n\
         |---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (name, runs) in series {
        for run in runs {
            match run.solve() {
                Ok(r) => writeln!(
                    report,
                    "| {name} | a/{} | {}a | {} | {} | {:.1} | {:+.2e} | {:+.2e} |",
                    run.refinement,
                    run.extent,
                    r.unknowns,
                    r.factorizations,
                    r.seconds,
                    r.load_error,
                    r.area_error
                ),
                Err(e) => writeln!(
                    report,
                    "| {name} | a/{} | {} |",
                    run.refinement,
                    e.message()
                ),
            }
            .unwrap();
        }
    }
    writeln!(
        report,
        "\nP converges from the stiff side; the finite block's share falls as 1/extent.\n"
    )
    .unwrap();
    graded_punch(report, a);
}

/// The punch on Gmsh's block graded towards the edge circle alone,
/// through the 3D model (`GradedPunch`).
fn graded_punch(report: &mut String, a: &Args) {
    let scene = GradedPunch::default();
    writeln!(
        report,
        "The same punch through the 3D model (`SolidModel`) on a block meshed by Gmsh \
         (`GradedPunch`, Debian's gmsh, one thread): tetrahedra of size a/k at the edge circle, \
         growing by {} per unit of distance from it up to {}a, block {}a; the punch a layer of \
         prisms over the disc's triangles, every node prescribed; P from the reactions.\n\n\
         | k | unknowns | factorisations | Gmsh [s] | solve [s] | P | contact area |\n\
         |---|---|---|---|---|---|---|",
        if a.quick { 0.1 } else { scene.growth },
        scene.extent / 8.0,
        scene.extent
    )
    .unwrap();
    let (ks, growth): (&[f64], f64) = match a.quick {
        true => (&[4.0, 8.0], 0.1),
        false => (&[8.0, 16.0, 32.0, 64.0], scene.growth),
    };
    let mut errors = Vec::new();
    for &k in ks {
        let run = GradedPunch {
            refinement: k,
            growth,
            ..scene
        };
        match run.solve() {
            Ok(r) => {
                errors.push((k, r.load_error));
                writeln!(
                    report,
                    "| a/{k} | {} | {} | {:.1} | {:.1} | {:+.2e} | {:+.2e} |",
                    r.unknowns,
                    r.factorizations,
                    r.mesh_seconds,
                    r.solve_seconds,
                    r.load_error,
                    r.area_error
                )
            }
            Err(e) => writeln!(report, "| a/{k} | {} |", e.message()),
        }
        .unwrap();
    }
    if let [.., (_, e1), (_, e2), (_, e3)] = errors[..] {
        let (d1, d2) = (e1 - e2, e2 - e3);
        writeln!(
            report,
            "\nDifferences {:.2e}, {:.2e} (first order in the edge's size halves them); \
             extrapolated, P {:+.2e}, of which the finite block's share is about +3.4e-3 (the \
             tensor grid's series above).\n",
            d1,
            d2,
            e3 - d2 * d2 / (d1 - d2)
        )
        .unwrap();
    } else {
        writeln!(report).unwrap();
    }
}

/// AMD against geometric nested dissection in 3D, on the seed scene.
fn ordering_3d(report: &mut String, a: &Args) {
    let sizes: &[f64] = if a.quick {
        &[0.05]
    } else {
        &[0.05, 0.025, 1.0 / 60.0]
    };
    writeln!(
        report,
        "The fill-reducing ordering in 3D (the seed scene; nested dissection cuts the nodes' bounding \
         box across its longest side, `linalg::ordering::nested_dissection` in 3D; the machine's threads (2); the \
         whole active-set solve, one factorisation per solve):\n\n\
         | h | unknowns | ordering | factor entries | per unknown | time [s] | compliance |\n\
         |---|---|---|---|---|---|---|"
    )
    .unwrap();
    for &h in sizes {
        let mut times = Vec::new();
        for (ordering, name) in [
            (Ordering::Amd, "AMD"),
            (Ordering::NestedDissection, "nested dissection"),
        ] {
            match (TwoBlocks3d {
                h,
                ordering,
                ..Default::default()
            })
            .solve()
            {
                Ok(r) => {
                    writeln!(
                        report,
                        "| 1/{:.0} | {} | {name} | {} | {:.0} | {:.2} | {:.10} |",
                        1.0 / h,
                        r.unknowns,
                        r.factor_nnz,
                        r.factor_nnz as f64 / r.unknowns as f64,
                        r.seconds,
                        r.compliance
                    )
                    .unwrap();
                    times.push(r.seconds);
                }
                Err(e) => writeln!(
                    report,
                    "| 1/{:.0} | | {name} | {} | | | |",
                    1.0 / h,
                    e.message()
                )
                .unwrap(),
            }
        }
        if let [amd, nd] = times[..] {
            writeln!(report, "| | | AMD / ND time | | | {:.2} | |", amd / nd).unwrap();
        }
    }
    writeln!(report).unwrap();
}

/// A sphere on a block in 3D against Hertz.
fn hertz_3d(report: &mut String, a: &Args) {
    let refinements: &[f64] = if a.quick { &[2.0] } else { &[2.0, 4.0, 8.0] };
    let scene = Hertz3d::default();
    writeln!(
        report,
        "A sphere on a block in 3D (`Hertz3d`: R = 1, a = 0.02R, equal moduli E = 1, ν = 0.3, both \
         bodies {}a wide and deep, the sphere's underside z = R − √(R² − r²) straight above the block's \
         nodes so that B spans the initial gap, g = J0 + w·u with J0 from the heights; P = 4E*a³/(3R) \
         spread over the sphere body's flat top; quarter model; meshes graded from a/k within 1.5a, \
         by 1.3 beyond; the bodies plain, B tempered by the tie). a from the contact area √(A/π); p₀ \
         fitted to the nodal pressures within 0.8a.\n\n\
         | h | unknowns | solves | time [s] | a | p₀ | transmitted |\n|---|---|---|---|---|---|---|",
        scene.extent
    )
    .unwrap();
    for &k in refinements {
        match (Hertz3d {
            refinement: k,
            ..scene
        })
        .solve()
        {
            Ok(r) => writeln!(
                report,
                "| a/{k} | {} | {} | {:.1} | {:+.2e} | {:+.2e} | {:.12} |",
                r.unknowns, r.iterations, r.seconds, r.a_error, r.p0_error, r.transmitted
            ),
            Err(e) => writeln!(report, "| a/{k} | {} |", e.message()),
        }
        .unwrap();
    }
    writeln!(report).unwrap();
}

/// The seed scene in 3D, by mesh size, and the values extrapolated from
/// the three finest; then the cost of each phase.
fn seed_3d(report: &mut String, a: &Args) {
    let sizes: &[f64] = if a.quick {
        &[0.05]
    } else {
        &[0.05, 0.025, 1.0 / 60.0, 1.0 / 80.0]
    };
    writeln!(
        report,
        "\nThe seed scene in 3D (issue 41's statement: L = 1, H1 = H2 = 0.25, E1 = 1e10, E2 = 1e11, \
         ν = 0.3, p = 1e7, C = 0.1, frictionless, zero gap; the quarter x, y ≤ L/2 with its symmetry \
         planes; uniform Kuhn meshes of size h). *transmitted*: the upward force of the contact on Ω2 \
         over p(2C)² (1 in equilibrium). Values of the whole scene; the machine's threads (2), nested \
         dissection from 10k unknowns. The interface (every node of both surfaces) is too large to \
         condense with profit here (n_I² > 4 nnz(K)), so the loop refactorises at each solve.\n\n\
         | h | unknowns | solves | factorisations | time [s] | contact_area | gap_corner | v_top | compliance | transmitted |\n\
         |---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut rows = Vec::new();
    let mut results = Vec::new();
    for &h in sizes {
        match (TwoBlocks3d {
            h,
            ..Default::default()
        })
        .solve()
        {
            Ok(r) => {
                writeln!(
                    report,
                    "| 1/{:.0} | {} | {} | {} | {:.2} | {:.5} | {:.4e} | {:.5e} | {:.5} | {:.12} |",
                    1.0 / h,
                    r.unknowns,
                    r.iterations,
                    r.factorizations,
                    r.seconds,
                    r.contact_area,
                    r.gap_corner,
                    r.v_top,
                    r.compliance,
                    r.transmitted
                )
                .unwrap();
                rows.push((h, [r.contact_area, r.gap_corner, r.v_top, r.compliance]));
                results.push((h, r));
            }
            Err(e) => writeln!(report, "| 1/{:.0} | {} |", 1.0 / h, e.message()).unwrap(),
        }
    }
    writeln!(report).unwrap();
    calculix_3d(report, &rows);
    if rows.len() >= 3 {
        let names = ["contact_area", "gap_corner", "v_top", "compliance"];
        let last = &rows[rows.len() - 3..];
        let line: Vec<String> = (0..4)
            .map(|k| {
                let q: Vec<(f64, f64)> = last.iter().map(|(h, v)| (*h, v[k])).collect();
                match extrapolate(&q) {
                    Some((value, order)) => format!(
                        "{} → {value:.5e} (order {order:.2}; finest off by {:+.1e})",
                        names[k],
                        q[2].1 / value - 1.0
                    ),
                    None => format!("{}: no fit of that form", names[k]),
                }
            })
            .collect();
        writeln!(
            report,
            "\nExtrapolated from the three finest meshes (q = q∞ + K h^s): {}.\n",
            line.join("; ")
        )
        .unwrap();
    }
    speed_3d(report, &results);
}

/// Where the 3D seed scene's time and memory go, by mesh size.
fn speed_3d(report: &mut String, results: &[(f64, TwoBlocks3dResult)]) {
    writeln!(
        report,
        "Where the time and memory go (the same runs; seconds summed over the solves; *assembly*: \
         the bodies' tetrahedra once and B's switches; *peak factorisation*: the bytes one numeric \
         factorisation holds at its peak, factor and workspace):\n\n\
         | h | unknowns | assembly | analysis | factorisations | solves | total [s] | factor entries per unknown | peak factorisation [MB] | per unknown [kB] |\n\
         |---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (h, r) in results {
        let t = &r.timings;
        writeln!(
            report,
            "| 1/{:.0} | {} | {:.2} | {:.2} | {:.2} ({}) | {:.2} | {:.2} | {:.0} | {:.0} | {:.1} |",
            1.0 / h,
            r.unknowns,
            t.assembly,
            t.analysis,
            t.factorization,
            r.factorizations,
            t.solve,
            t.total,
            r.factor_nnz as f64 / r.unknowns as f64,
            r.factorization_bytes as f64 / 1e6,
            r.factorization_bytes as f64 / r.unknowns as f64 / 1e3
        )
        .unwrap();
    }
    writeln!(report).unwrap();
    if let [.., (h1, r1), (h2, r2)] = results {
        let growth = |a: f64, b: f64| (b / a).ln() / (r2.unknowns as f64 / r1.unknowns as f64).ln();
        writeln!(
            report,
            "From h = 1/{:.0} to 1/{:.0}, factor entries grow as N^{:.2}, one factorisation's time \
             as N^{:.2} (nested dissection on a 3D grid: N^(4/3) and N² in theory).\n",
            1.0 / h1,
            1.0 / h2,
            growth(r1.factor_nnz as f64, r2.factor_nnz as f64),
            growth(
                r1.timings.factorization / r1.factorizations as f64,
                r2.timings.factorization / r2.factorizations as f64
            )
        )
        .unwrap();
    }
}

/// CalculiX's C3D8 runs of the same scene (scripts/calculix/seed3d/,
/// node-to-surface frictionless contact, one thread, ccx's wall time),
/// side by side, and their extrapolation beside tfem's.
fn calculix_3d(report: &mut String, tfem_rows: &[(f64, [f64; 4])]) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scripts/calculix/seed3d/results.jsonl"
    );
    let Ok(text) = std::fs::read_to_string(path) else {
        writeln!(report, "CalculiX: no results file ({path}).\n").unwrap();
        return;
    };
    let runs: Vec<serde_json::Value> = (text.lines())
        .filter_map(|l| serde_json::from_str(l).ok())
        .filter(|v: &serde_json::Value| {
            v["contact"] == "n2s" && v["converged"] != false && v["retimed"] != true
        })
        .collect();
    writeln!(
        report,
        "CalculiX 2.20 on the same scene (scripts/calculix/seed3d: C3D8 hexahedra, two meshes \
         with coincident unmerged interface nodes, node-to-surface frictionless contact with a \
         penalty of 1e15 Pa/m — largest penetration 3.7e-9 m, 3e-5 of v_top; its surface-to-surface \
         contact agreed to 2e-5 at 1/20 and 1/40 and did not settle at 1/60; contact_area from the \
         tributary areas of the slave nodes in contact; one thread, ccx's wall time on a shared \
         machine):\n\n\
         | h | equations | ccx [s] | contact_area | gap_corner | v_top | compliance |\n|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut rows = Vec::new();
    for v in &runs {
        let f = |k: &str| v[k].as_f64().unwrap_or(f64::NAN);
        writeln!(
            report,
            "| 1/{:.0} | {} | {:.1} | {:.5} | {:.4e} | {:.5e} | {:.5} |",
            1.0 / f("h"),
            v["equations"],
            f("ccx_seconds"),
            f("contact_area"),
            f("gap_corner"),
            f("v_top"),
            f("compliance")
        )
        .unwrap();
        rows.push((
            f("h"),
            [
                f("contact_area"),
                f("gap_corner"),
                f("v_top"),
                f("compliance"),
            ],
        ));
    }
    rows.sort_by(|a, b| b.0.total_cmp(&a.0));
    let finest = |r: &[(f64, [f64; 4])], k: usize| -> Option<(f64, f64)> {
        let q: Vec<(f64, f64)> = r
            .iter()
            .rev()
            .take(3)
            .rev()
            .map(|(h, v)| (*h, v[k]))
            .collect();
        (q.len() == 3).then(|| extrapolate(&q)).flatten()
    };
    let names = ["contact_area", "gap_corner", "v_top", "compliance"];
    let line: Vec<String> = (0..4)
        .map(|k| {
            let show = |x: Option<(f64, f64)>| match x {
                Some((q, s)) => format!("{q:.4e} (order {s:.2})"),
                None => "no fit".into(),
            };
            format!(
                "{}: CalculiX {}, tfem {}",
                names[k],
                show(finest(&rows, k)),
                show(finest(tfem_rows, k))
            )
        })
        .collect();
    writeln!(
        report,
        "\nExtrapolated from each code's three finest meshes: {}.\n",
        line.join("; ")
    )
    .unwrap();
}

/// q∞ and s of q = q∞ + K h^s through three points (h decreasing), or
/// None when the differences change sign (no such fit).
pub(crate) fn extrapolate(q: &[(f64, f64)]) -> Option<(f64, f64)> {
    let [(h1, q1), (h2, q2), (h3, q3)] = [q[0], q[1], q[2]];
    let ratio = (q1 - q2) / (q2 - q3);
    if !(ratio > 0.0 && ratio.is_finite()) {
        return None;
    }
    let f = |s: f64| (h1.powf(s) - h2.powf(s)) / (h2.powf(s) - h3.powf(s)) - ratio;
    let (mut lo, mut hi) = (0.05, 6.0);
    if f(lo).signum() == f(hi).signum() {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid).signum() == f(lo).signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let s = 0.5 * (lo + hi);
    Some((q3 - (q2 - q3) * h3.powf(s) / (h2.powf(s) - h3.powf(s)), s))
}
