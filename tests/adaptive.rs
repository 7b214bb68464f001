//! The adaptive solve (docs/method.md §8): the error estimate against the
//! true error, the refinement's bookkeeping, and what adaptivity buys on
//! the seed scene.
//!
//! Measured (release): effectivity of the estimate η/‖u − u_h‖_E on the
//! smooth manufactured field 1.020, 1.014, 1.006, 1.003 at h = 1/8 … 1/64;
//! on the seed scene (2C/L = 0.2) the compliance estimate (η/‖u_h‖_E)²
//! over its true error against the reference is 0.63 on uniform meshes
//! (h = 1/64 … 1/256) and 0.85–1.2 on the adapted ones; adapted from
//! h = 1/16 to a compliance tolerance of 1e-3 (20,919 unknowns, its contact
//! edges located to 1e-3 of ℓc too) the
//! compliance is within 8.3e-4 of the reference, where uniform meshes give
//! 8.9e-3 at 67k unknowns.

use std::sync::OnceLock;

use tfem::meshgen::{Diagonal, MeshBuilder, unit_square};
use tfem::model::adapt::{AdaptOptions, AdaptReport, Goal};
use tfem::scenes::{TwoBlocks, TwoBlocksResult};
use tfem::verification::{ManufacturedElasticity, energy_error, nodal_loads};
use tfem::{Component, ContactOptions, Material, Model, PlaneMode, Status};

/// The reference compliance of the seed scene, 2C/L = 0.2
/// (docs/reference/two_blocks_canonical.json; ±0.062).
const COMPLIANCE: f64 = 347.6378623325035;

fn manufactured(n: usize) -> (Model, f64) {
    let mat = Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").unwrap();
    let exact = ManufacturedElasticity::new(&mat);
    let b = unit_square(n, None);
    let mut fixed: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
    fixed.sort_unstable();
    fixed.dedup();
    let mesh = b.build().unwrap();
    let loads = nodal_loads(&mesh, |p| exact.body_force(p));
    let mut m = Model::new();
    m.set_mesh(mesh);
    m.set_material(1, mat).unwrap();
    for &v in &fixed {
        let u = exact.displacement(m.mesh().unwrap().nodes()[v]);
        m.fix(v, Component::X, u[0]).unwrap();
        m.fix(v, Component::Y, u[1]).unwrap();
    }
    for (v, f) in loads.iter().enumerate() {
        m.add_nodal_force(v, *f).unwrap();
    }
    m.solve().unwrap();
    let uh: Vec<f64> = m.displacements().unwrap().concat();
    let e = energy_error(m.mesh().unwrap(), &uh, &mat.d_matrix(), |p| {
        exact.gradient(p)
    });
    (m, e)
}

#[test]
fn the_estimate_matches_the_true_energy_error_of_a_smooth_field() {
    let mut last = f64::INFINITY;
    for n in [8, 16, 32] {
        let (m, e) = manufactured(n);
        let effectivity = m.error_estimate().unwrap().global / e;
        assert!(
            (0.9..1.1).contains(&effectivity),
            "h = 1/{n}: {effectivity}"
        );
        // Asymptotically exact: the effectivity tends to 1.
        assert!((effectivity - 1.0).abs() < last, "h = 1/{n}: {effectivity}");
        last = (effectivity - 1.0).abs();
    }
}

fn seed(h: f64) -> tfem::scenes::TwoBlocksScene {
    TwoBlocks {
        mesh_size: h,
        ..Default::default()
    }
    .build()
    .unwrap()
}

fn measured(s: &tfem::scenes::TwoBlocksScene) -> TwoBlocksResult {
    s.measure(s.model.contact_report().unwrap().clone())
        .unwrap()
}

/// The seed scene adapted from h = 1/16 to a compliance tolerance of
/// 10⁻³, once for the tests below.
fn adapted() -> &'static (TwoBlocksResult, AdaptReport, usize) {
    static RUN: OnceLock<(TwoBlocksResult, AdaptReport, usize)> = OnceLock::new();
    // (outputs, the adaptive report, the refined mesh's node count)
    RUN.get_or_init(|| {
        let mut s = seed(1.0 / 16.0);
        let options = AdaptOptions {
            tolerance: 1e-3,
            goal: Goal::Compliance,
            ..Default::default()
        };
        let report = s.model.solve_adaptive(&options).unwrap();
        let nodes = s.model.mesh().unwrap().nodes().len();
        (measured(&s), report, nodes)
    })
}

#[test]
fn on_the_seed_scene_the_compliance_estimate_tracks_its_true_error() {
    let (r, report, _) = adapted();
    let last = report.cycles.last().unwrap();
    let error = (r.compliance - COMPLIANCE).abs() / COMPLIANCE;
    let effectivity = last.estimate / error;
    assert!(
        (0.5..2.0).contains(&effectivity),
        "{effectivity}: {report:?}"
    );
    // Uniform meshes: the estimate is 0.63 of the error (measured).
    let mut s = seed(1.0 / 64.0);
    let u = s.solve(&ContactOptions::default()).unwrap();
    let est = s.model.error_estimate().unwrap().relative().powi(2);
    let effectivity = est / ((u.compliance - COMPLIANCE).abs() / COMPLIANCE);
    assert!((0.5..2.0).contains(&effectivity), "uniform: {effectivity}");
}

#[test]
fn adapting_the_seed_scene_meets_the_tolerance_on_a_fraction_of_the_uniform_unknowns() {
    let (r, report, _) = adapted();
    assert!(report.reached, "{report:?}");
    let error = (r.compliance - COMPLIANCE).abs() / COMPLIANCE;
    assert!(error < 1e-3, "compliance error {error}");
    let unknowns = report.cycles.last().unwrap().unknowns;
    // Uniform h = 1/256 (67k unknowns) is 8.9e-3 away: first order, so
    // 1e-3 would take h ≈ 1/2300, about 5M unknowns. (Measured: 20,919,
    // of which ~1,300 locate the contact zone's edges to 1e-3 of ℓc.)
    assert!(unknowns < 25_000, "{unknowns} unknowns");
    // The estimates fall from cycle to cycle while they are above the
    // tolerance (cycles after it only locate the contact edges).
    for w in report.cycles.windows(2) {
        if w[0].estimate > 1e-3 {
            assert!(w[1].estimate < w[0].estimate, "{report:?}");
        }
    }
}

/// The seed scene's reference contact length, 2C/L = 0.2, and its error
/// bar (docs/reference/two_blocks_canonical.json).
const LC: (f64, f64) = (0.4965801725543994, 0.0005925009576252527);

#[test]
fn the_contact_zones_edges_are_located_to_the_tolerance_and_lc_falls_inside_the_references_bar() {
    let (_, report, _) = adapted();
    let last = report.cycles.last().unwrap();
    assert!(
        last.contact_edge > 0.0 && last.contact_edge <= 1e-3,
        "{report:?}"
    );
    // To 1e-3 of ℓc the edge is located to 5e-4, the reference's own bar:
    // at 3e-4 it shows where ℓc goes.
    let mut s = seed(1.0 / 16.0);
    let options = AdaptOptions {
        tolerance: 3e-4,
        goal: Goal::Compliance,
        ..Default::default()
    };
    s.model.solve_adaptive(&options).unwrap();
    let r = measured(&s);
    // Measured: ℓc − reference = −4.9e-4 (−4.0e-4 at 1e-4), the bar ±5.9e-4.
    assert!((r.lc - LC.0).abs() < LC.1, "lc = {}", r.lc);
}

#[test]
fn without_locating_the_contact_edges_the_energy_estimate_leaves_them_coarse() {
    let mut s = seed(1.0 / 16.0);
    let options = AdaptOptions {
        tolerance: 1e-3,
        goal: Goal::Compliance,
        resolve_contact_edges: false,
        ..Default::default()
    };
    let report = s.model.solve_adaptive(&options).unwrap();
    // The contact edge is not measured then; the mesh says how coarse it
    // stayed: an interface edge pressed at one end only, longer than 1e-3
    // of ℓc (measured: 1.4e-2 of ℓc, fourteen times the tolerance).
    let last = report.cycles.last().unwrap();
    assert_eq!(last.contact_edge, 0.0);
    let (lc, edge) = zone_edge(&s.model);
    assert!(edge / lc > 1e-3, "{edge} of {lc}");
}

/// The contact length and the longest interface edge with one end pressed
/// and the other free, read from the nodal pressures.
fn zone_edge(model: &Model) -> (f64, f64) {
    let p = model.contact_nodal_pressures().unwrap();
    let top = p.iter().fold(0.0f64, |m, &v| m.max(v));
    let mesh = model.mesh().unwrap();
    let tags: Vec<i32> = (model.contact_pairs().iter())
        .flat_map(|q| [q.tag_a, q.tag_b])
        .collect();
    let mut longest = 0.0f64;
    for e in mesh
        .boundary_edges()
        .iter()
        .filter(|e| tags.contains(&e.tag))
    {
        let [a, b] = e.nodes;
        if (p[a] > 1e-9 * top) != (p[b] > 1e-9 * top) {
            let (x, y) = (mesh.nodes()[a], mesh.nodes()[b]);
            longest = longest.max((x[0] - y[0]).hypot(x[1] - y[1]));
        }
    }
    (model.contact_report().unwrap().contact_length, longest)
}

#[test]
fn each_cycle_starts_its_contact_loop_from_the_coarser_levels_field() {
    let (r, _, _) = adapted();
    // Warm: the coarser field interpolated on the refined mesh gives the
    // set (measured: 1 iteration; 8–9 from the initial set of §6.6).
    assert!(
        r.report.iterations <= 2,
        "{} iterations",
        r.report.iterations
    );
}

#[test]
fn a_refined_mesh_keeps_the_given_nodes_and_the_seed_scenes_outputs_read_on() {
    let (r, _, nodes) = adapted();
    assert!(*nodes > 700, "refined: {nodes} nodes");
    // The corner and top-centre nodes keep their indices: v_top is read on.
    assert!(
        (r.v_top / -1.7587378152753418e-4 - 1.0).abs() < 2e-3,
        "{}",
        r.v_top
    );
    assert!((r.support_reaction / 2e6 - 1.0).abs() < 1e-9);
}

/// Two blocks [0, 1] × [−½, 0] and [0, 1] × [0, ½] on matching 4 × 2 grids,
/// the lower held (v = 0) at its bottom, both on rollers (u = 0) at x = 0,
/// a pressure p = 1 on top: exactly σ_yy = −1 everywhere.
fn patch_blocks() -> Model {
    let mut b = MeshBuilder::new();
    let xs: Vec<f64> = (0..=4).map(|i| i as f64 / 4.0).collect();
    let lower = b.add_grid(&xs, &[-0.5, -0.25, 0.0], 1, Diagonal::Forward);
    let upper = b.add_grid(&xs, &[0.0, 0.25, 0.5], 2, Diagonal::Forward);
    let mut edges = Vec::new();
    let mut tags = Vec::new();
    let rows = [
        (&lower[0], 1),
        (&lower[2], 2),
        (&upper[0], 3),
        (&upper[2], 4),
    ];
    for e in b.boundary_edges() {
        let p = [b.nodes[e[0]], b.nodes[e[1]]];
        if let Some((_, t)) = rows
            .iter()
            .find(|(r, _)| r.contains(&e[0]) && r.contains(&e[1]))
        {
            edges.push(e);
            tags.push(*t);
        } else if p[0][0] == 0.0 && p[1][0] == 0.0 {
            edges.push(e);
            tags.push(5);
        }
    }
    let mut m = Model::new();
    m.set_mesh(b.build().unwrap());
    m.set_boundary_edges(&edges, &tags).unwrap();
    for body in [1, 2] {
        let e = if body == 1 { 1e3 } else { 1e4 };
        m.set_material(body, Material::new(e, 0.3, PlaneMode::Strain, "b").unwrap())
            .unwrap();
    }
    m.fix_edges(1, Component::Y, 0.0).unwrap();
    m.fix_edges(5, Component::X, 0.0).unwrap();
    m.add_pressure(4, 1.0).unwrap();
    m.add_contact_pair(2, 3).unwrap();
    m
}

#[test]
fn refinement_carries_loads_constraints_and_pairs_and_keeps_the_patch_test_exact() {
    let mut m = patch_blocks();
    let before = m.mesh().unwrap().nodes().len();
    // The exact solution is in the space: the estimate is round-off and
    // any refinement it asks for must keep the stress uniform.
    let options = AdaptOptions {
        tolerance: 1e-300,
        max_cycles: 4,
        ..Default::default()
    };
    let report = m.solve_adaptive(&options).unwrap();
    assert!(!report.reached);
    let mesh = m.mesh().unwrap();
    assert!(mesh.nodes().len() > before, "refined");
    for s in m.element_stresses().unwrap() {
        assert!(
            s[0].abs() < 1e-12 && (s[1] + 1.0).abs() < 1e-12 && s[2].abs() < 1e-12,
            "{s:?}"
        );
    }
    // The load's total and the support's reaction are the pressure's.
    let f = m.load_vector().unwrap();
    let total: f64 = f.iter().skip(1).step_by(2).sum();
    assert!((total + 1.0).abs() < 1e-14, "{total}");
    // New nodes on the support and the rollers are held; none inside.
    for (v, x) in mesh.nodes().iter().enumerate().skip(before) {
        let fixed: Vec<usize> = m
            .constraints()
            .filter(|(g, _)| g / 2 == v)
            .map(|(g, _)| g % 2)
            .collect();
        let expect: Vec<usize> = match (x[0] == 0.0, x[1] == -0.5) {
            (true, true) => vec![0, 1],
            (true, false) => vec![0],
            (false, true) => vec![1],
            (false, false) => vec![],
        };
        assert_eq!(fixed, expect, "node {v} at {x:?}");
    }
    assert!(
        m.warnings().iter().any(|w| w.contains("limit of cycles")),
        "{:?}",
        m.warnings()
    );
}

#[test]
fn bad_adaptive_options_are_refused_and_change_nothing() {
    let mut m = patch_blocks();
    let nodes = m.mesh().unwrap().nodes().len();
    for (options, needle) in [
        (
            AdaptOptions {
                tolerance: 0.0,
                ..Default::default()
            },
            "tolerance",
        ),
        (
            AdaptOptions {
                tolerance: f64::NAN,
                ..Default::default()
            },
            "tolerance",
        ),
        (
            AdaptOptions {
                tolerance: -1.0,
                ..Default::default()
            },
            "tolerance",
        ),
        (
            AdaptOptions {
                fraction: 1.5,
                ..Default::default()
            },
            "fraction",
        ),
        (
            AdaptOptions {
                max_cycles: 0,
                ..Default::default()
            },
            "max_cycles",
        ),
    ] {
        let e = m.solve_adaptive(&options).unwrap_err();
        assert_eq!(e.status(), Status::InvalidArgument);
        assert!(e.message().contains(needle), "{}", e.message());
        assert_eq!(m.mesh().unwrap().nodes().len(), nodes);
    }
}

#[test]
fn a_failed_solve_during_adaptation_restores_the_model_as_given() {
    let mut m = patch_blocks();
    m.clear_constraints();
    let nodes = m.mesh().unwrap().nodes().len();
    let e = m.solve_adaptive(&AdaptOptions::default()).unwrap_err();
    assert_eq!(e.status(), Status::Singular, "{}", e.message());
    assert_eq!(m.mesh().unwrap().nodes().len(), nodes);
    assert_eq!(m.contact_pairs().len(), 1);
}

#[test]
fn an_unknowns_limit_stops_with_a_warning_saying_the_estimate_reached() {
    let mut s = seed(1.0 / 16.0);
    let options = AdaptOptions {
        tolerance: 1e-6,
        max_unknowns: 2_000,
        ..Default::default()
    };
    let report = s.model.solve_adaptive(&options).unwrap();
    assert!(!report.reached);
    assert!(
        report.cycles.iter().all(|c| c.unknowns <= 2_000),
        "{report:?}"
    );
    let warning = s
        .model
        .warnings()
        .into_iter()
        .find(|w| w.contains("limit of unknowns"));
    assert!(warning.is_some_and(|w| w.contains("estimated relative error")));
}

#[test]
fn an_axisymmetric_fit_adapts_too() {
    use tfem::scenes::revolution::ShaftHub;
    let mut scene = ShaftHub {
        cells: 4,
        ..Default::default()
    }
    .build()
    .unwrap();
    let options = AdaptOptions {
        tolerance: 0.02,
        ..Default::default()
    };
    let report = scene.model.solve_adaptive(&options).unwrap();
    assert!(report.reached, "{report:?}");
    assert!(report.cycles.len() > 1);
}

#[test]
fn an_adapted_punch_beats_a_hand_graded_mesh_on_fewer_unknowns() {
    // A rigid flat cylindrical punch (axisymmetric, Boussinesq's P =
    // 2aE*δ): from h = a/4 to 4 % in energy, against the scene's own mesh
    // graded by hand towards the punch's edge at a/32 (32,623 unknowns, P
    // within 4.9e-3). Measured: 18,484 unknowns, P within 3.2e-3.
    use tfem::scenes::sphere::CylindricalPunch;
    let punch = CylindricalPunch {
        mesh_size: 0.25,
        ..Default::default()
    };
    let mut scene = punch.build().unwrap();
    let options = AdaptOptions {
        tolerance: 0.05,
        ..Default::default()
    };
    let report = scene.model.solve_adaptive(&options).unwrap();
    let r = scene
        .measure(&punch, scene.model.contact_report().unwrap().clone())
        .unwrap();
    let unknowns = report.cycles.last().unwrap().unknowns;
    assert!(unknowns < 32_623, "{unknowns}");
    assert!(
        (r.force / r.force_exact - 1.0).abs() < 4.9e-3,
        "{}",
        r.force / r.force_exact
    );
    assert!(r.balance < 1e-6);
}

#[test]
fn at_a_re_entrant_corner_adaptivity_restores_the_optimal_order() {
    // u = ∇(r^(4/3) sin(4θ/3)) on the L-shape (scenes::corner): energy
    // error N^(−1/6) on uniform meshes (measured 0.660 … 0.256 from 66 to
    // 24,066 unknowns), N^(−1/2) adapted (2.74e-2 at 24,116), the estimate
    // within 0.96–1.07 of the true error throughout.
    use tfem::scenes::corner::{adapt, l_shape, solve};
    let uniform: Vec<_> = [4, 8, 16, 32]
        .iter()
        .map(|&n| solve(l_shape(n).build().unwrap()).unwrap())
        .collect();
    let adapted = adapt(4, 6_000).unwrap();
    let order = |runs: &[tfem::scenes::corner::CornerRun]| {
        let n: Vec<f64> = runs.iter().map(|r| r.unknowns as f64).collect();
        let e: Vec<f64> = runs.iter().map(|r| r.error).collect();
        -tfem::verification::fitted_rate(&n, &e)
    };
    let (u, a) = (order(&uniform), order(&adapted[adapted.len() - 6..]));
    assert!(u < 0.2, "uniform order {u}");
    assert!(a > 0.45, "adaptive order {a}");
    for r in uniform.iter().chain(&adapted) {
        let effectivity = r.estimate / r.error;
        assert!(
            (0.9..1.1).contains(&effectivity),
            "{} unknowns: {effectivity}",
            r.unknowns
        );
    }
}

#[test]
fn a_solve_failing_before_any_refinement_keeps_the_earlier_results() {
    let mut s = seed(1.0 / 16.0);
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    let u = s.model.displacements().unwrap();
    let options = AdaptOptions {
        contact: ContactOptions {
            max_iterations: 1,
            ..Default::default()
        },
        ..Default::default()
    };
    let e = s.model.solve_adaptive(&options).unwrap_err();
    assert_eq!(e.status(), Status::NotConverged, "{}", e.message());
    assert_eq!(s.model.displacements().unwrap(), u);
}

#[test]
fn a_pair_with_its_own_contact_mesh_is_refused_before_solving() {
    let mut m = patch_blocks();
    m.solve_contact(&ContactOptions::default()).unwrap();
    let u = m.displacements().unwrap();
    m.clear_contact_pairs();
    // The conforming strip between the blocks' matching interface nodes,
    // handed over as the pair's own mesh.
    let elements: Vec<[usize; 3]> = patch_strip(&m);
    m.add_contact_pair_with_mesh(2, 3, &elements).unwrap();
    m.solve_contact(&ContactOptions::default()).unwrap();
    let u_own = m.displacements().unwrap();
    let e = m.solve_adaptive(&AdaptOptions::default()).unwrap_err();
    assert!(e.message().contains("contact pair 0"), "{}", e.message());
    assert_eq!(m.displacements().unwrap(), u_own);
    assert_eq!(u.len(), u_own.len());
}

/// The strip of triangles between the patch blocks' interface rows
/// (y = 0, lower nodes 10..=14, upper 15..=19 of [`patch_blocks`]).
fn patch_strip(m: &Model) -> Vec<[usize; 3]> {
    let x = m.mesh().unwrap().nodes();
    let row = |lower: bool| -> Vec<usize> {
        let mut v: Vec<usize> = (0..x.len())
            .filter(|&v| {
                x[v][1] == 0.0
                    && (m.mesh().unwrap().node_body()[v] == Some(if lower { 1 } else { 2 }))
            })
            .collect();
        v.sort_by(|&a, &b| x[a][0].total_cmp(&x[b][0]));
        v
    };
    let (lo, up) = (row(true), row(false));
    (0..lo.len() - 1)
        .flat_map(|i| [[lo[i], lo[i + 1], up[i + 1]], [lo[i], up[i + 1], up[i]]])
        .collect()
}

/// [`patch_blocks`] with the upper block prescribed whole (a rigid tool).
fn rigid_patch() -> Model {
    let mut m = patch_blocks();
    let n = m.mesh().unwrap().nodes().len();
    for v in 0..n {
        if m.mesh().unwrap().node_body()[v] == Some(2) {
            for c in [Component::X, Component::Y] {
                if !m.constraints().any(|(g, _)| g == 2 * v + c as usize) {
                    m.fix(v, c, 0.0).unwrap();
                }
            }
        }
    }
    m
}

#[test]
fn the_unknowns_limit_holds_with_a_rigid_body() {
    for limit in [37, 60, 205] {
        let mut model = rigid_patch();
        let options = AdaptOptions {
            tolerance: 1e-300,
            max_unknowns: limit,
            max_cycles: 10,
            ..Default::default()
        };
        let report = model.solve_adaptive(&options).unwrap();
        assert!(
            report.cycles.iter().all(|c| c.unknowns <= limit),
            "{limit}: {report:?}"
        );
    }
}

#[test]
fn a_constraint_line_through_a_body_stays_fixed_on_the_refined_mesh() {
    // The seed scene holds u_x = 0 on the symmetry line x = L/2, inside
    // both blocks: the nodes bisecting it must be held too.
    let mut s = seed(1.0 / 16.0);
    let options = AdaptOptions {
        tolerance: 1e-3,
        goal: Goal::Compliance,
        ..Default::default()
    };
    s.model.solve_adaptive(&options).unwrap();
    let mesh = s.model.mesh().unwrap();
    let held: Vec<usize> = s
        .model
        .constraints()
        .filter(|(g, _)| g % 2 == 0)
        .map(|(g, _)| g / 2)
        .collect();
    let on_line: Vec<usize> = (0..mesh.nodes().len())
        .filter(|&v| mesh.nodes()[v][0] == 0.5)
        .collect();
    assert!(on_line.len() > 40, "{} nodes on the line", on_line.len());
    for v in on_line {
        assert!(
            held.contains(&v),
            "node {v} at {:?} is free",
            mesh.nodes()[v]
        );
    }
}

#[test]
fn the_relative_estimate_does_not_depend_on_the_load_scale() {
    // Linear problem: the relative estimate is scale-free, also where the
    // squares of the stresses would overflow a double.
    let relative = |p: f64| {
        let mut s = TwoBlocks {
            mesh_size: 1.0 / 16.0,
            p,
            ..Default::default()
        }
        .build()
        .unwrap();
        s.model.solve_contact(&ContactOptions::default()).unwrap();
        s.model.error_estimate().unwrap().relative()
    };
    let (base, huge) = (relative(1e7), relative(6e148));
    assert!((huge / base - 1.0).abs() < 1e-9, "{base} vs {huge}");
}

#[test]
fn an_adapted_shrink_fit_keeps_its_interference_and_its_circles() {
    // The Lamé fit from h = b/4 (chords' sagitta 4.8e-3 b, five times the
    // interference): its curved interface refined in step on both sides.
    // Measured: 1,976 unknowns, true energy error 3.0e-2, effectivity 0.992.
    use tfem::scenes::lame::{Lame, TAG_BORE, TAG_INNER_RING, TAG_OUTER_RING, TAG_RIM};
    let lame = Lame {
        mesh_size: 0.25,
        ..Default::default()
    };
    let mut s = lame.build().unwrap();
    let options = AdaptOptions {
        tolerance: 3e-2,
        ..Default::default()
    };
    let report = s.model.solve_adaptive(&options).unwrap();
    assert!(report.reached && report.cycles.len() > 2, "{report:?}");
    let est = s.model.error_estimate().unwrap();
    let error = s.energy_error(&lame).unwrap();
    assert!(error / est.energy < 3.5e-2, "{}", error / est.energy);
    let effectivity = est.global / error;
    assert!((0.9..1.1).contains(&effectivity), "{effectivity}");
    let mesh = s.model.mesh().unwrap();
    let b = lame.radius;
    for (tag, r) in [
        (TAG_INNER_RING, b + lame.interference),
        (TAG_OUTER_RING, b),
        (TAG_BORE, lame.inner_radius),
        (TAG_RIM, lame.outer_radius),
    ] {
        for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag) {
            for v in e.nodes {
                let [x, y] = mesh.nodes()[v];
                assert!((x.hypot(y) - r).abs() < 1e-14, "tag {tag}: node {v}");
            }
        }
    }
    // Every element of the fit is in contact: refined apart, the coarse
    // inner polygon would have stood clear of the finer outer one.
    let active = s.model.contact_report().unwrap().active;
    assert!(active > 0, "{active}");
    let p = s.model.contact_nodal_pressures().unwrap();
    let on_bore: Vec<usize> = (mesh.boundary_edges().iter())
        .filter(|e| e.tag == TAG_OUTER_RING)
        .flat_map(|e| e.nodes)
        .collect();
    let exact = lame.exact().pressure;
    for v in on_bore {
        assert!(
            (p[v] / exact - 1.0).abs() < 0.05,
            "node {v}: {} of {exact}",
            p[v]
        );
    }
}

#[test]
fn an_adapted_hertz_contact_refines_onto_its_cylinder() {
    // From h = a/2 to 5 % in energy. Measured: 9,880 unknowns, a +6.1e-4,
    // p0 (fitted) +1.0e-3 against the half-space values.
    use tfem::scenes::hertz::{Hertz, TAG_CYLINDER};
    let base = Hertz::default();
    let hz = Hertz {
        mesh_size: base.half_width / 2.0,
        ..base
    };
    let mut s = hz.build().unwrap();
    let options = AdaptOptions {
        tolerance: 0.05,
        ..Default::default()
    };
    let report = s.model.solve_adaptive(&options).unwrap();
    assert!(report.reached, "{report:?}");
    let r = s
        .measure(&hz, s.model.contact_report().unwrap().clone())
        .unwrap();
    assert!(
        (r.a / r.a_exact - 1.0).abs() < 2e-3,
        "a {}",
        r.a / r.a_exact
    );
    assert!(
        (r.p0_fit / r.p0_exact - 1.0).abs() < 3e-3,
        "p0 {}",
        r.p0_fit / r.p0_exact
    );
    let mesh = s.model.mesh().unwrap();
    let radius = hz.radius;
    for e in mesh
        .boundary_edges()
        .iter()
        .filter(|e| e.tag == TAG_CYLINDER)
    {
        for v in e.nodes {
            let [x, y] = mesh.nodes()[v];
            assert!((x.hypot(y - radius) - radius).abs() < 1e-14, "node {v}");
        }
    }
}
