//! The exact frictional oracle (`tfem::oracle::frictional`: node-to-node
//! multipliers, primal-dual active set on open/stick/slip, quasi-static
//! load history) and the Cattaneo–Mindlin solution (Johnson §7.1), each
//! checked on its own before TFEM has a friction law:
//!
//! * μ = 0 is the frictionless oracle, to round-off;
//! * μ = ∞ (and a huge μ) glues the interface: the same displacements as a
//!   mesh whose pair nodes are merged, solved without contact;
//! * on the Cattaneo–Mindlin scene (μ = 0.3, Q/(μP) = 0.3 then 0.6) the
//!   stick half-width and the shear traction converge to the analytic ones
//!   with h, the open/stick/slip sets are those of the analysis, and slip
//!   dissipates at every pair and step.
//!
//! Bounds are from measured runs (`cargo run --release --example
//! cattaneo`, numbers in the comments), with margins.

use std::collections::{BTreeMap, HashMap};
use std::sync::OnceLock;

use tfem::oracle::{
    FrictionalOracle, LoadCase, LoadHistory, PairState, frictional_oracle, frictionless_oracle,
};
use tfem::scenes::cattaneo::{
    CattaneoMindlin, CattaneoSolution, TAG_BLOCK_TOP, TAG_CYLINDER, cattaneo_mindlin,
    hertz_pressure, stick_half_width,
};
use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TAG_LOAD, TAG_SUPPORT, TwoBlocks};
use tfem::verification::fitted_rate;
use tfem::{Component, Mesh, Model, Tempering};

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Errors as `[1.23e-4, …]`.
fn sci(v: &[f64]) -> String {
    let s: Vec<String> = v.iter().map(|x| format!("{x:.2e}")).collect();
    format!("[{}]", s.join(", "))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

// ---------------------------------------------------------------- μ = 0

#[test]
fn mu_zero_is_the_frictionless_oracle_on_the_two_blocks() {
    // Measured: |Δu| / max|u| = 2.2e-13 (no gap), 4.5e-13 (gap 1e-6).
    for scene in [
        TwoBlocks {
            mesh_size: 1.0 / 32.0,
            ..Default::default()
        },
        TwoBlocks {
            mesh_size: 1.0 / 32.0,
            gap: 1e-6,
            ..Default::default()
        },
    ] {
        let mut s = scene.build().unwrap();
        let factors = [0.25, 0.5, 1.0];
        let history = LoadHistory::proportional(&s.model, &factors).unwrap();
        let sol = frictional_oracle(
            &s.model,
            TAG_CONTACT_LOWER,
            TAG_CONTACT_UPPER,
            0.0,
            &history,
        )
        .unwrap();
        for (k, step) in sol.steps.iter().enumerate() {
            history.step(k).unwrap().apply(&mut s.model).unwrap();
            let exact =
                frictionless_oracle(&s.model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
            let err = max_diff(&step.u, &exact.u) / max_abs(&exact.u);
            eprintln!(
                "two blocks, gap {}, step {k}, μ = 0: |Δu|/|u| = {err:.1e}",
                scene.gap
            );
            assert!(
                err < 1e-10,
                "gap {}, step {k}: |Δu|/|u| = {err:e}",
                scene.gap
            );
            let closed: Vec<(usize, usize)> = step
                .pairs
                .iter()
                .filter(|p| p.state != PairState::Open)
                .map(|p| (p.lower, p.upper))
                .collect();
            assert_eq!(closed, exact.active.iter().copied().collect::<Vec<_>>());
            for p in &step.pairs {
                assert_eq!(p.tangential_force, 0.0);
                assert!(p.normal_force >= 0.0 && p.gap >= -1e-12 * max_abs(&exact.u));
            }
        }
    }
}

#[test]
fn mu_zero_is_the_frictionless_oracle_on_the_cattaneo_scene() {
    // The normal step of the Cattaneo–Mindlin scene (platen pushed down),
    // then a tangential platen displacement: without friction the cylinder
    // slides, and each step is the frictionless solution of its loads.
    // Measured: |Δu|/|u| = 2.0e-12, 1.6e-12.
    let cm = CattaneoMindlin {
        mesh_size: CattaneoMindlin::default().half_width / 8.0,
        ..Default::default()
    };
    let mut scene = cm.build().unwrap();
    let oracle = FrictionalOracle::new(&scene.model, TAG_BLOCK_TOP, TAG_CYLINDER).unwrap();
    // Both bodies are held by the platen and the support: the multiplier form.
    assert!(oracle.is_dual());
    let dn = 2.0 * scene.load / cm.e_star();
    let loads = [
        scene.platen_loads(0.0, dn).unwrap(),
        scene.platen_loads(0.3 * dn, dn).unwrap(),
    ];
    let mut prev = None;
    for l in &loads {
        let step = oracle.step(0.0, prev.as_ref(), l).unwrap();
        l.apply(&mut scene.model).unwrap();
        let exact = frictionless_oracle(&scene.model, TAG_BLOCK_TOP, TAG_CYLINDER).unwrap();
        let err = max_diff(&step.u, &exact.u) / max_abs(&exact.u);
        eprintln!("cattaneo, μ = 0: |Δu|/|u| = {err:.1e}");
        assert!(err < 1e-10, "|Δu|/|u| = {err:e}");
        assert_eq!(step.contact_resultant()[1], 0.0);
        prev = Some(step);
    }
}

// ---------------------------------------------------------------- μ = ∞

/// The two-block scene loaded and supported over its whole width (the
/// interface stays closed), with the upper block's interface nodes merged
/// into the lower block's: a single mesh solved without contact (plain P1).
fn glued(scene: &TwoBlocks, model: &Model) -> Vec<f64> {
    let mesh = model.mesh().unwrap();
    let pairs = tfem::oracle::interface_pairs(model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    let merged: HashMap<usize, usize> = pairs.iter().map(|&(a, b)| (b, a)).collect();
    let n = mesh.nodes().len();
    // New numbering: every node but the merged upper ones.
    let mut new_of = vec![usize::MAX; n];
    let mut nodes = Vec::new();
    for (v, new) in new_of.iter_mut().enumerate() {
        if !merged.contains_key(&v) {
            *new = nodes.len();
            nodes.push(mesh.nodes()[v]);
        }
    }
    let to_new = |v: usize| new_of[*merged.get(&v).unwrap_or(&v)];
    let triangles: Vec<[usize; 3]> = mesh
        .triangles()
        .iter()
        .map(|t| [to_new(t[0]), to_new(t[1]), to_new(t[2])])
        .collect();
    let mut g = Model::new();
    g.set_mesh(Mesh::new(nodes.clone(), triangles, mesh.body_of().to_vec(), 0).unwrap());
    let (edges, tags): (Vec<[usize; 2]>, Vec<i32>) = mesh
        .boundary_edges()
        .iter()
        .filter(|e| e.tag == TAG_SUPPORT || e.tag == TAG_LOAD)
        .map(|e| ([to_new(e.nodes[0]), to_new(e.nodes[1])], e.tag))
        .unzip();
    g.set_boundary_edges(&edges, &tags).unwrap();
    for body in [1, 2] {
        g.set_material(body, *model.material(body).unwrap())
            .unwrap();
    }
    g.set_tempering(Tempering::Off).unwrap();
    for (v, p) in nodes.iter().enumerate() {
        if p[0] == 0.5 * scene.length {
            g.fix(v, Component::X, 0.0).unwrap();
        }
    }
    g.fix_edges(TAG_SUPPORT, Component::Y, 0.0).unwrap();
    g.add_pressure(TAG_LOAD, scene.p).unwrap();
    g.solve().unwrap();
    let u = g.displacements().unwrap();
    (0..n).flat_map(|v| u[to_new(v)]).collect()
}

#[test]
fn infinite_mu_glues_the_interface() {
    // Two blocks of moduli 1e10 and 1e11 compressed over their whole width:
    // they expand sideways differently, so the glued interface carries shear.
    // Measured: |Δu|/|u| = 6.3e-14 (μ = ∞ and μ = 1e6).
    let scene = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        c: 0.5,
        ..Default::default()
    };
    let s = scene.build().unwrap();
    let u_glued = glued(&scene, &s.model);
    let history = LoadHistory::proportional(&s.model, &[1.0]).unwrap();
    let oracle = FrictionalOracle::new(&s.model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    let mut ratio = 0.0;
    for mu in [f64::INFINITY, 1e6] {
        let step = &oracle.solve(mu, &history).unwrap().steps[0];
        let err = max_diff(&step.u, &u_glued) / max_abs(&u_glued);
        eprintln!("glued, μ = {mu}: |Δu|/|u| = {err:.1e}");
        assert!(err < 1e-10, "μ = {mu}: |Δu|/|u| = {err:e}");
        // Every pair is stuck (the one on the symmetry line, whose
        // tangential DOFs are both prescribed, is reported stick too).
        assert!(step.pairs.iter().all(|p| p.state == PairState::Stick));
        ratio = step
            .pairs
            .iter()
            .map(|p| (p.tangential_force / p.normal_force).abs())
            .fold(0.0, f64::max);
    }
    // Measured: the glued interface needs |λt|/λn up to 0.476 (at the
    // blocks' ends). Below that some pairs slip and the solution is no
    // longer the glued one.
    eprintln!("glued: max |λt|/λn = {ratio:.3}");
    assert!(ratio > 0.1, "max |λt|/λn = {ratio}");
    let step = &oracle.solve(0.5 * ratio, &history).unwrap().steps[0];
    assert!(step.counts()[2] > 0);
    assert!(max_diff(&step.u, &u_glued) / max_abs(&u_glued) > 1e-6);
}

#[test]
fn the_multiplier_and_saddle_point_forms_agree() {
    // Measured: |Δu|/|u| = 4.2e-13, |Δλ|/max|λ| = 6e-13.
    let cm = CattaneoMindlin {
        mesh_size: CattaneoMindlin::default().half_width / 8.0,
        ..Default::default()
    };
    let scene = cm.build().unwrap();
    let dual = FrictionalOracle::new(&scene.model, TAG_BLOCK_TOP, TAG_CYLINDER).unwrap();
    let saddle = FrictionalOracle::new(&scene.model, TAG_BLOCK_TOP, TAG_CYLINDER)
        .unwrap()
        .saddle_only();
    assert!(dual.is_dual() && !saddle.is_dual());
    let dn = 2.0 * scene.load / cm.e_star();
    let history = LoadHistory {
        cases: vec![scene.normal_case(), scene.tangential_case()],
        factors: vec![vec![dn, 0.0], vec![dn, 0.05 * dn], vec![dn, 0.1 * dn]],
    };
    let (a, b) = (
        dual.solve(cm.mu, &history).unwrap(),
        saddle.solve(cm.mu, &history).unwrap(),
    );
    for (sa, sb) in a.steps.iter().zip(&b.steps) {
        let eu = max_diff(&sa.u, &sb.u) / max_abs(&sb.u);
        let la: Vec<f64> = sa
            .pairs
            .iter()
            .flat_map(|p| [p.normal_force, p.tangential_force])
            .collect();
        let lb: Vec<f64> = sb
            .pairs
            .iter()
            .flat_map(|p| [p.normal_force, p.tangential_force])
            .collect();
        let el = max_diff(&la, &lb) / max_abs(&lb);
        eprintln!(
            "dual vs saddle: |Δu|/|u| = {eu:.1e}, |Δλ|/|λ| = {el:.1e}, counts {:?}",
            sa.counts()
        );
        assert!(eu < 1e-10 && el < 1e-9, "{eu:e} {el:e}");
        assert!(
            sa.pairs
                .iter()
                .zip(&sb.pairs)
                .all(|(p, q)| p.state == q.state)
        );
    }
    assert!(a.steps[2].counts()[2] > 0, "the last step slips");
}

#[test]
fn infinite_mu_sticks_the_whole_hertz_contact() {
    let cm = CattaneoMindlin {
        mesh_size: CattaneoMindlin::default().half_width / 8.0,
        mu: f64::INFINITY,
        ..Default::default()
    };
    let scene = cm.build().unwrap();
    let oracle = FrictionalOracle::new(&scene.model, TAG_BLOCK_TOP, TAG_CYLINDER).unwrap();
    let dn = 2.0 * scene.load / cm.e_star();
    let mut prev = None;
    for dt in [0.0, 0.1 * dn] {
        let step = oracle
            .step(cm.mu, prev.as_ref(), &scene.platen_loads(dt, dn).unwrap())
            .unwrap();
        assert_eq!(step.counts()[2], 0, "no slip with μ = ∞");
        assert!(step.counts()[1] > 10);
        for p in step.pairs.iter().filter(|p| p.state == PairState::Stick) {
            assert!(p.slip_increment.abs() < 1e-12 * dn, "{p:?}");
        }
        prev = Some(step);
    }
}

// ---------------------------------------------------------------- analytic

#[test]
fn the_cattaneo_mindlin_traction_carries_q_and_meets_the_coulomb_limit() {
    let (a, p0, mu) = (2.0, 3.0, 0.3);
    let p = std::f64::consts::PI * a * p0 / 2.0;
    for ratio in [0.0, 0.3, 0.6, 1.0] {
        let c = stick_half_width(a, ratio);
        assert!((c - a * (1.0f64 - ratio).sqrt()).abs() < 1e-15);
        // ∫q dx = Q = ratio μP (midpoint rule on a fine grid).
        let n = 200_000;
        let dx = 2.0 * a / n as f64;
        let q: f64 = (0..n)
            .map(|i| cattaneo_mindlin(a, c, p0, mu, -a + (i as f64 + 0.5) * dx) * dx)
            .sum();
        assert!(
            (q - ratio * mu * p).abs() < 1e-6 * mu * p,
            "Q/(μP) = {ratio}: ∫q = {q}"
        );
        for i in 0..=100 {
            let x = -1.2 * a + 2.4 * a * i as f64 / 100.0;
            let t = cattaneo_mindlin(a, c, p0, mu, x);
            let limit = mu * hertz_pressure(a, p0, x);
            assert!(
                t >= 0.0 && t <= limit * (1.0 + 1e-15),
                "x = {x}: q {t} > μp {limit}"
            );
            if x.abs() >= c {
                assert_eq!(t, limit);
            }
        }
    }
    // Continuous at c.
    let c = stick_half_width(a, 0.5);
    let (l, r) = (
        cattaneo_mindlin(a, c, p0, mu, c * (1.0 - 1e-12)),
        cattaneo_mindlin(a, c, p0, mu, c),
    );
    assert!((l - r).abs() < 1e-5 * r);
}

// ---------------------------------------------------------------- Cattaneo–Mindlin

const LEVELS: [f64; 3] = [8.0, 16.0, 32.0];
const RATIOS: [f64; 2] = [0.3, 0.6];

/// The scene at h = a/8, a/16, a/32, solved once for all the tests below.
fn series() -> &'static [CattaneoSolution] {
    static SERIES: OnceLock<Vec<CattaneoSolution>> = OnceLock::new();
    SERIES.get_or_init(|| {
        LEVELS
            .iter()
            .map(|k| {
                let cm = CattaneoMindlin {
                    mesh_size: CattaneoMindlin::default().half_width / k,
                    ..Default::default()
                };
                assert_eq!(cm.dundurs_beta(), 0.0);
                cm.build().unwrap().solve(&cm, &RATIOS).unwrap()
            })
            .collect()
    })
}

fn h() -> Vec<f64> {
    LEVELS.iter().map(|k| 1.0 / k).collect()
}

#[test]
fn the_steps_reach_their_loads() {
    let cm = CattaneoMindlin::default();
    for sol in series() {
        assert!((sol.normal.p - cm.load()).abs() < 1e-10 * cm.load());
        assert_eq!(sol.tangential.len(), RATIOS.len());
        for (s, r) in sol.tangential.iter().zip(RATIOS) {
            assert!((s.q / (cm.mu * s.p) - r).abs() < 1e-9);
            // δₙ is held: P moves by the tangential loading only through
            // the bodies' finite size. Measured: 1.3e-5 (a/8), 3.5e-6 (a/16),
            // 9.9e-7 (a/32) at most; 3 to 6 iterations.
            let drift = (s.p - sol.normal.p).abs() / sol.normal.p;
            eprintln!(
                "{} pairs, Q/(μP) = {r}: P drift {drift:.1e}, {} iterations",
                sol.pairs, s.step.iterations
            );
            assert!(drift < 1e-4, "P drift {drift:e}");
            assert!(s.step.iterations <= 10, "{} iterations", s.step.iterations);
        }
    }
}

#[test]
fn the_stick_half_width_converges_at_second_order() {
    // c from a least-squares fit of the stick zone's deficit (μp − q)²;
    // errors / a. Measured, Q/(μP) = 0.3: 3.4e-2, 7.5e-3, 1.35e-3 (rate
    // 2.3); 0.6: 3.3e-2, 1.4e-2, 2.5e-3 (rate 1.9).
    // The two-node extrapolation `c` converges at first order only, with a
    // staircase: 3.9e-2, 2.0e-2, 1.0e-2 (0.3); 7.1e-2, 5.7e-3, 2.5e-3 (0.6).
    let rs = series();
    for (k, r) in RATIOS.iter().enumerate() {
        let e: Vec<f64> = rs
            .iter()
            .map(|s| {
                let t = &s.tangential[k];
                ((t.c_fit - t.analytic.c) / t.analytic.a).abs()
            })
            .collect();
        let rate = fitted_rate(&h(), &e);
        eprintln!("Q/(μP) = {r}: c (fit) errors {}, rate {rate:.2}", sci(&e));
        assert!(rate > 1.6, "Q/(μP) = {r}: c errors {e:?}, rate {rate}");
        assert!(e[2] < 4e-3, "Q/(μP) = {r}: c errors {e:?}");
        let e1: Vec<f64> = rs
            .iter()
            .map(|s| {
                let t = &s.tangential[k];
                ((t.c - t.analytic.c) / t.analytic.a).abs()
            })
            .collect();
        eprintln!("Q/(μP) = {r}: extrapolated c errors {}", sci(&e1));
        assert!(e1[2] < 2e-2, "Q/(μP) = {r}: extrapolated c errors {e1:?}");
    }
}

#[test]
fn the_shear_traction_converges_at_first_order() {
    // Discrete L2 error of the nodal q against the analytic profile,
    // relative. Measured, Q/(μP) = 0.3: 1.4e-1, 1.2e-1, 3.9e-2 (rate 0.93);
    // 0.6: 9.2e-2, 5.5e-2, 3.0e-2 (rate 0.81). The max error (at the node
    // next to c, where q has a square-root cusp) stays 0.06–0.13 μp₀:
    // 8.8e-2, 1.3e-1, 6.2e-2 (0.3); 1.2e-1, 9.6e-2, 9.2e-2 (0.6).
    let rs = series();
    for (k, r) in RATIOS.iter().enumerate() {
        let e: Vec<f64> = rs.iter().map(|s| s.tangential[k].q_error_l2).collect();
        let rate = fitted_rate(&h(), &e);
        eprintln!("Q/(μP) = {r}: q L2 errors {}, rate {rate:.2}", sci(&e));
        assert!(rate > 0.6, "Q/(μP) = {r}: q errors {e:?}, rate {rate}");
        assert!(e[2] < 6e-2, "Q/(μP) = {r}: q errors {e:?}");
        let m: Vec<f64> = rs.iter().map(|s| s.tangential[k].q_error_max).collect();
        eprintln!("Q/(μP) = {r}: q max errors / μp₀ {}", sci(&m));
        assert!(m.iter().all(|&m| m < 0.25), "max errors {m:?}");
    }
}

#[test]
fn the_pressure_stays_hertzian() {
    // a from p², errors relative: measured 1.4e-3–1.5e-3, 6.6e-4–7.2e-4,
    // 3.2e-4–3.5e-4 at every step (first order, as in the Hertz scene).
    for s in series() {
        for t in std::iter::once(&s.normal).chain(&s.tangential) {
            let e = ((t.a - t.analytic.a) / t.analytic.a).abs();
            eprintln!("{} pairs, Q/(μP) = {}: a error {e:.2e}", s.pairs, t.target);
            assert!(e < 2e-3, "a error {e}");
        }
    }
}

#[test]
fn stick_inside_c_slip_out_to_a_open_beyond() {
    // Every pair farther than h from c and a has the analytic state, at
    // every level and step; the stick zone is one interval around x = 0.
    for s in series() {
        for t in &s.tangential {
            assert_eq!(t.misclassified, 0);
            let states: BTreeMap<i64, PairState> = t
                .step
                .pairs
                .iter()
                .map(|p| ((p.x * 1e9) as i64, p.state))
                .collect();
            let stick: Vec<i64> = states
                .iter()
                .filter(|(_, s)| **s == PairState::Stick)
                .map(|(x, _)| *x)
                .collect();
            let inside = states
                .range(stick[0]..=stick[stick.len() - 1])
                .all(|(_, s)| *s == PairState::Stick);
            assert!(inside, "the stick zone is not an interval");
            // Slip on both sides, then open.
            let [open, nstick, slip] = t.step.counts();
            assert!(open > 0 && nstick > 0 && slip >= 2);
        }
    }
}

#[test]
fn coulomb_holds_and_slip_dissipates_at_every_pair_and_step() {
    for s in series() {
        for t in std::iter::once(&s.normal).chain(&s.tangential) {
            let fmax = t
                .step
                .pairs
                .iter()
                .map(|p| p.normal_force)
                .fold(0.0, f64::max);
            let smax = t
                .step
                .pairs
                .iter()
                .map(|p| p.slip_increment.abs())
                .fold(0.0, f64::max);
            let mu = CattaneoMindlin::default().mu;
            for p in &t.step.pairs {
                let d = p.dissipation();
                assert!(d >= -1e-12 * fmax * smax, "{p:?}: dissipation {d}");
                match p.state {
                    PairState::Open => {
                        assert!(p.normal_force == 0.0 && p.gap >= 0.0);
                    }
                    PairState::Stick => {
                        assert!(p.normal_force > 0.0);
                        assert!(p.tangential_force.abs() <= mu * p.normal_force * (1.0 + 1e-12));
                        assert!(p.slip_increment.abs() <= 1e-12 * smax.max(1e-300) + 1e-20);
                    }
                    PairState::Slip => {
                        assert!(p.normal_force > 0.0);
                        let limit = mu * p.normal_force;
                        assert!((p.tangential_force.abs() - limit).abs() <= 1e-9 * limit);
                        assert!(d > 0.0 || p.slip_increment == 0.0);
                    }
                }
            }
        }
    }
}

#[test]
fn load_cases_combine_and_apply() {
    let s = TwoBlocks {
        mesh_size: 1.0 / 8.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    let base = LoadCase::of(&s.model).unwrap();
    let h = LoadHistory::proportional(&s.model, &[0.5, 2.0]).unwrap();
    assert_eq!(h.len(), 2);
    let two = h.step(1).unwrap();
    assert!(
        two.forces
            .iter()
            .zip(&base.forces)
            .all(|(a, b)| *a == 2.0 * b)
    );
    assert!(h.step(2).is_err());
    let mut m = s.model;
    two.apply(&mut m).unwrap();
    let again = LoadCase::of(&m).unwrap();
    assert!(max_diff(&again.forces, &two.forces) <= 1e-9 * max_abs(&two.forces));
    assert_eq!(again.prescribed, two.prescribed);
    // A prescribed value on a free DOF is refused.
    let oracle = FrictionalOracle::new(&m, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    let mut bad = two.clone();
    let free = (0..bad.prescribed.len())
        .find(|&g| m.constraints().all(|(c, _)| c != g))
        .unwrap();
    bad.prescribed[free] = 1.0;
    assert!(oracle.step(0.3, None, &bad).is_err());
    assert!(oracle.step(-1.0, None, &two).is_err());
}

#[test]
fn unequal_moduli_with_beta_zero_follow_the_same_solution() {
    // A cylinder 1.7 times stiffer than the block with ν chosen so that
    // Dundurs' β = 0 (G₂(1 − 2ν₁) = G₁(1 − 2ν₂)): the shear problem is
    // again Cattaneo–Mindlin's. Measured at h = a/16, a/32, Q/(μP) = 0.3:
    // c (fit) errors / a 8.3e-3, 1.6e-3, q L2 errors 1.1e-1, 2.9e-2; 0.6:
    // 1.5e-2, 2.7e-3 and 5.7e-2, 2.8e-2 (as with equal bodies).
    let base = CattaneoMindlin::default();
    let g1 = base.e_block / (2.0 * (1.0 + base.nu_block));
    let nu2 = 0.1;
    let g2 = g1 * (1.0 - 2.0 * nu2) / (1.0 - 2.0 * base.nu_block);
    let cm = CattaneoMindlin {
        e_cylinder: 2.0 * g2 * (1.0 + nu2),
        nu_cylinder: nu2,
        ..base
    };
    assert!(cm.dundurs_beta().abs() < 1e-15, "β = {}", cm.dundurs_beta());
    for k in [16.0, 32.0] {
        let cm = CattaneoMindlin {
            mesh_size: cm.half_width / k,
            ..cm
        };
        let sol = cm.build().unwrap().solve(&cm, &RATIOS).unwrap();
        for t in &sol.tangential {
            let ec = ((t.c_fit - t.analytic.c) / t.analytic.a).abs();
            eprintln!(
                "β = 0, E₂/E₁ = {:.2}, a/{k}, Q/(μP) = {}: c (fit) error {ec:.2e}, q L2 error {:.2e}, misclassified {}",
                cm.e_cylinder / cm.e_block,
                t.target,
                t.q_error_l2,
                t.misclassified
            );
            assert_eq!(t.misclassified, 0);
            if k == 32.0 {
                assert!(ec < 4e-3 && t.q_error_l2 < 6e-2);
            }
        }
    }
}
