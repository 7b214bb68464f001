//! Rigid indenters (docs/method.md §6.14): a rigid body is a body whose
//! nodes all have a prescribed displacement (`Model::fix`), joined to an
//! elastic body by an ordinary contact pair. Checked against closed forms
//! for plane strain:
//!
//! * a flat rigid punch of half-width a on a block 40a × 40a (half model):
//!   contact over exactly the punch's width, p(x) = P/(π√(a² − x²))
//!   (Sneddon; Johnson §5.2) on |x| ≤ 0.8a, the punch's reaction against
//!   the support's;
//! * a rigid cylinder on the Hertz block: a = √(4PR/(πE*)), p₀ = 2P/(πa)
//!   with E* = E/(1 − ν²) of the block alone, P the cylinder's reaction.
//!
//! Measured numbers are in the comments; the bounds leave a margin of
//! about 2× over them, the rates 0.2–0.3 below the fitted ones.

use tfem::ContactOptions;
use tfem::scenes::hertz::{Hertz, TAG_BLOCK_TOP, TAG_CYLINDER};
use tfem::scenes::punch::{FlatPunch, FlatPunchResult, RigidCylinder, RigidCylinderResult};
use tfem::verification::fitted_rate;
use tfem::{Material, PlaneMode};

const PUNCH_LEVELS: [f64; 4] = [8.0, 16.0, 32.0, 64.0];

fn punch_runs() -> Vec<FlatPunchResult> {
    PUNCH_LEVELS
        .iter()
        .map(|k| {
            let p = FlatPunch {
                mesh_size: 1.0 / k,
                ..Default::default()
            };
            p.build()
                .unwrap()
                .solve(&p, &ContactOptions::default())
                .unwrap()
        })
        .collect()
}

#[test]
fn a_flat_punch_is_in_contact_over_exactly_its_width() {
    // The block's contact side runs to 2a; the strip of B covers the part
    // facing the punch, every element of it stays active (the pressure is
    // largest at the edges), and nothing beyond the punch's corner touches.
    for r in punch_runs() {
        assert_eq!(r.active.0, r.active.1, "elements released: {:?}", r.active);
        // ℓc sums edge lengths of the uniform grid under the punch: a to
        // round-off.
        assert!(
            (r.contact_length - 1.0).abs() < 1e-12,
            "ℓc = {}",
            r.contact_length
        );
        assert!(
            r.pressure
                .iter()
                .all(|&(x, p)| x <= 1.0 + 1e-12 || p == 0.0),
            "pressure beyond the punch"
        );
    }
}

#[test]
fn a_flat_punch_follows_sneddons_pressure_and_converges() {
    // Measured max relative error on 0 ≤ x ≤ 0.8a: 1.13e-1, 6.25e-2,
    // 3.34e-2, 1.63e-2 (rate 0.93). The discrete pressure is low inside
    // and the corner node takes the excess: the edge singularity
    // p ∝ (a − x)^(-1/2) pollutes the whole contact at first order.
    let rs = punch_runs();
    let e: Vec<f64> = rs.iter().map(|r| r.pressure_error).collect();
    let h: Vec<f64> = PUNCH_LEVELS.iter().map(|k| 1.0 / k).collect();
    let rate = fitted_rate(&h, &e);
    assert!(rate > 0.7, "errors {e:?}, rate {rate}");
    assert!(e[3] < 3e-2, "errors {e:?}");
}

#[test]
fn the_punch_force_balances_the_support_reaction() {
    // No load but the prescribed motion: the punch's reaction and the
    // support's are the two ends of one equilibrium, equal to round-off of
    // the solve (measured 1e-12 … 2.3e-11, growing with the unknowns).
    for r in punch_runs() {
        assert!(r.force > 0.0);
        assert!(r.balance < 1e-9, "imbalance {:e}", r.balance);
    }
}

#[test]
fn every_node_of_a_rigid_body_moves_with_it() {
    let p = FlatPunch::default();
    let mut scene = p.build().unwrap();
    scene.solve(&p, &ContactOptions::default()).unwrap();
    let u = scene.model.displacements().unwrap();
    for &v in &scene.punch {
        assert_eq!(u[v], [0.0, -p.indentation]);
    }
}

const CYLINDER_LEVELS: [f64; 4] = [4.0, 8.0, 16.0, 32.0];

fn cylinder_runs() -> Vec<RigidCylinderResult> {
    CYLINDER_LEVELS
        .iter()
        .map(|k| {
            let base = RigidCylinder::default();
            let rc = RigidCylinder {
                hertz: Hertz {
                    mesh_size: base.hertz.half_width / k,
                    ..base.hertz
                },
                ..base
            };
            let r = rc
                .build()
                .unwrap()
                .solve(&rc, &ContactOptions::default())
                .unwrap();
            assert!(r.hertz.report.iterations <= 20);
            r
        })
        .collect()
}

#[test]
fn a_rigid_cylinder_gives_hertz_with_the_elastic_bodys_modulus_alone() {
    // h = a/4 … a/32 of the target a = 0.02R (the indentation gives
    // a = 0.0204R … 0.0201R: P from the reactions, 7.2e7 … 7.0e7 N/m).
    // Measured: a (where p² extrapolates to zero) 1.25e-2, 9.8e-3, 6.3e-3,
    // 2.5e-3 (rate 0.75: it is read from the last two loaded nodes);
    // p₀ (Hertz profile fitted to the nodal pressures) 5.4e-2, 1.5e-2,
    // 2.8e-3, 1.1e-3 (rate 1.9). The raw nodal value at the axis converges
    // slowly under a stiff indenter, as for the 100× stiffer elastic
    // cylinder of tests/hertz.rs, and is not checked.
    let rs = cylinder_runs();
    let rel = |v: f64, e: f64| ((v - e) / e).abs();
    let ea: Vec<f64> = rs.iter().map(|r| rel(r.hertz.a, r.hertz.a_exact)).collect();
    let ep: Vec<f64> = rs
        .iter()
        .map(|r| rel(r.hertz.p0_fit, r.hertz.p0_exact))
        .collect();
    let h: Vec<f64> = CYLINDER_LEVELS.iter().map(|k| 1.0 / k).collect();
    let (ra, rp) = (fitted_rate(&h, &ea), fitted_rate(&h, &ep));
    assert!(ra > 0.5 && ea[3] < 5e-3, "a errors {ea:?}, rate {ra}");
    assert!(rp > 1.5 && ep[3] < 3e-3, "p0 errors {ep:?}, rate {rp}");
}

#[test]
fn a_rigid_bodys_nominal_modulus_does_not_set_the_contact_penalty() {
    // Found by an outside probe: a punch given E = 1e3 against the block's
    // 2e11 made E_c = 1e3 (the smaller of the pair); on this scene the
    // force was 5.15e3 against 8.40e7 (measured, h = a/8), with an OK
    // status (the probe's own scene: 99.98 % of the indentation taken by
    // the overlap). A wholly prescribed side now leaves E_c to the
    // other body: the same force as a punch given the block's E (up to the
    // rounding of the punch's own K u, zero for its rigid translation).
    let p = FlatPunch {
        mesh_size: 1.0 / 8.0,
        ..Default::default()
    };
    let force = |punch_e: f64| {
        let mut scene = p.build().unwrap();
        let m = tfem::Material::new(punch_e, p.nu, tfem::PlaneMode::Strain, "punch").unwrap();
        scene.model.set_material(2, m).unwrap();
        scene.solve(&p, &ContactOptions::default()).unwrap().force
    };
    let reference = force(p.e);
    assert!(reference > 1e7, "{reference}");
    for e in [1e3, 1e9] {
        let f = force(e);
        assert!(
            (f - reference).abs() <= 1e-13 * reference,
            "punch E = {e:e}: {f} against {reference}"
        );
    }
}

/// The rigid cylinder at h = a/`k` with its mesh `ratio` times the block's
/// (1: nearly matching nodes): the solved scene's report and warnings.
fn rigid_cylinder(k: f64, ratio: f64) -> (RigidCylinderResult, Vec<String>) {
    let base = RigidCylinder::default();
    let rc = RigidCylinder {
        hertz: Hertz {
            mesh_size: base.hertz.half_width / k,
            cylinder_mesh_ratio: ratio,
            ..base.hertz
        },
        ..base
    };
    let mut scene = rc.build().unwrap();
    let r = scene.solve(&rc, &ContactOptions::default()).unwrap();
    (r, scene.scene.model.warnings())
}

#[test]
fn the_contact_length_of_a_rigid_cylinder_is_its_contact_width() {
    // Found by an outside probe: one family of B (edges on the cylinder's
    // chords, apices the block's nodes) carries a rigid curved contact
    // alone, and ℓc, the mean of the two families, read half the width
    // (ℓc/a − 1 = −0.44 … −0.50 at h = a/8 … a/64) while the pressures
    // followed Hertz to 2e-3. ℓc is now the longer-active family's (the
    // half model: ℓc ≈ a, resolved to an edge).
    for k in [8.0, 16.0, 32.0] {
        let (r, _) = rigid_cylinder(k, 1.0);
        let (lc, a) = (r.hertz.report.contact_length, r.hertz.a_exact);
        assert!(
            (lc - a).abs() <= 1.5 * a / k,
            "h = a/{k}: ℓc = {lc:e}, a = {a:e}"
        );
    }
}

#[test]
fn a_rigid_curved_tool_is_carried_by_both_families_of_b_without_a_warning() {
    // A rigid curved tool keeps its polygon. Measured along each element's
    // own edge normal, one family of B carried it alone (the shorter
    // family active over 0.125, 0.06, 0.03 of the longer's length at
    // h = a/16, a/32, a/64) and the one-sided warning fired; measured
    // along one normal per point (the block's, side a) both families
    // carry it: 0.94, 0.97, 0.98, and no warning (the warning itself:
    // contact::conformity's tests). An elastic cylinder with a mesh 2.5×
    // coarser is not warned about either.
    for k in [16.0, 32.0, 64.0] {
        let (_, warnings) = rigid_cylinder(k, 1.0);
        assert!(warnings.is_empty(), "a/{k}: {warnings:?}");
    }
    let elastic = Hertz {
        mesh_size: Hertz::default().half_width / 16.0,
        cylinder_mesh_ratio: 2.5,
        ..Default::default()
    };
    let mut scene = elastic.build().unwrap();
    scene.solve(&elastic, &ContactOptions::default()).unwrap();
    let quiet = scene.model.warnings();
    assert!(quiet.iter().all(|w| !w.contains("one-sided")), "{quiet:?}");
}

/// The flat punch at h = a/8 under contact modulus `e_c`: the model's
/// warnings after the solve.
fn punch_warnings(e_c: Option<f64>) -> Vec<String> {
    let p = FlatPunch {
        mesh_size: 1.0 / 8.0,
        ..Default::default()
    };
    let mut scene = p.build().unwrap();
    let options = ContactOptions {
        contact_modulus: e_c,
        ..Default::default()
    };
    scene.solve(&p, &options).unwrap();
    scene.model.warnings()
}

#[test]
fn a_penalty_too_stiff_to_resolve_its_overlap_is_warned_about() {
    // E_c = 1e23 against the block's 2e11: the overlap p/κ falls below the
    // rounding of u, so the contact forces are rounding (docs/method.md
    // §6.14) while the system stays well conditioned. Measured, the
    // punch's reaction against the support's: off by 4.7e-12 at the
    // default E_c (silent), 1.8e-6 at 1e17 (warned: "about 5 correct
    // digits"), 0.80 at 1e23 (warned: 0 digits).
    let quiet = punch_warnings(None);
    assert!(
        quiet.iter().all(|w| !w.contains("correct digits")),
        "{quiet:?}"
    );
    let loud = punch_warnings(Some(1e23));
    assert!(
        loud.iter()
            .any(|w| w.contains("contact pressures carry about")),
        "{loud:?}"
    );
}

/// The rigid cylinder at h = a/8 with the cylinder's Young's modulus
/// `e_cylinder` (E_c stays the block's, the smaller): the cylinder's
/// vertical reaction against the block's, relative, and the model's
/// warnings.
fn cylinder_of_modulus(e_cylinder: f64) -> (f64, Vec<String>) {
    let base = RigidCylinder::default();
    let rc = RigidCylinder {
        hertz: Hertz {
            mesh_size: base.hertz.half_width / 8.0,
            ..base.hertz
        },
        ..base
    };
    let mut scene = rc.build().unwrap();
    let model = &mut scene.scene.model;
    let m = Material::new(e_cylinder, 0.3, PlaneMode::Strain, "cylinder").unwrap();
    model.set_material(2, m).unwrap();
    model.solve_contact(&ContactOptions::default()).unwrap();
    let r = model.reactions().unwrap();
    let body = model.mesh().unwrap().node_body().to_vec();
    let on = |b: i32| -> f64 {
        (0..r.len())
            .filter(|&v| body[v] == Some(b))
            .map(|v| r[v][1])
            .sum()
    };
    let (cylinder, block) = (on(2), on(1));
    (((cylinder + block) / block).abs(), model.warnings())
}

#[test]
fn the_reactions_of_a_rigid_body_as_stiff_as_the_block_are_not_warned_about() {
    // Measured: the cylinder's reaction against the block's 1.2e-12.
    let (imbalance, w) = cylinder_of_modulus(2e11);
    assert!(imbalance < 1e-10, "imbalance {imbalance:e}");
    assert!(w.iter().all(|w| !w.contains("reactions")), "{w:?}");
}

#[test]
fn a_rigid_body_modelled_by_a_huge_modulus_has_its_reactions_warned_about() {
    // E = 1e25 against the block's 2e11 (docs/method.md §6.14): the
    // cylinder's reaction K u − f cancels terms of ε‖K‖|u| — measured
    // +5.56e8 against the block's 3.58e7 (16.6 × off), without a word
    // before — while the contact pressures (E_c = 2e11) are sound. The
    // bound ε Σ|K_ab u_b| read 1.4e11.
    let (imbalance, w) = cylinder_of_modulus(1e25);
    assert!(imbalance > 1.0, "imbalance {imbalance:e}");
    assert!(
        w.iter().any(|w| w
            .contains("the reactions of body 2 (E = 1.0e25) may carry as few as 0 correct digits")),
        "{w:?}"
    );
    assert!(
        w.iter().all(|w| !w.contains("reactions of body 1")),
        "{w:?}"
    );
}

#[test]
fn the_automatic_weighting_gives_a_pair_its_family_whichever_side_is_first() {
    // Measured (a/16): with the cylinder first, the nodes that face each
    // other were read along the cylinder's polygon only, and a matching
    // rigid cylinder got the mortar weighting where block-first got B.
    for (ratio, strip) in [(1.0, true), (2.5, false), (0.4, false)] {
        for cylinder_first in [false, true] {
            let base = RigidCylinder::default();
            let rc = RigidCylinder {
                hertz: Hertz {
                    mesh_size: base.hertz.half_width / 16.0,
                    cylinder_mesh_ratio: ratio,
                    ..base.hertz
                },
                ..base
            };
            let mut scene = rc.build().unwrap();
            if cylinder_first {
                let model = &mut scene.scene.model;
                model.clear_contact_pairs();
                model.add_contact_pair(TAG_CYLINDER, TAG_BLOCK_TOP).unwrap();
            }
            scene.solve(&rc, &ContactOptions::default()).unwrap();
            let got = scene.scene.model.contact_elements().is_ok();
            assert_eq!(
                got, strip,
                "ratio {ratio}, cylinder first: {cylinder_first}"
            );
        }
    }
}
