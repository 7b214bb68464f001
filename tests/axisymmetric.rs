//! The axisymmetric mode (docs/method.md §7): the tempered ring element,
//! its loads and checks, a manufactured field, Lamé's thick cylinder, the
//! axisymmetric contact patch test and a hub shrunk on a shaft.
//!
//! Measured (release; errors at the meshes named):
//! - manufactured u_r = r² sin z/10, u_z = z cos r/10, weighted L2 error
//!   at h = 1/4 … 1/32: 2.0e-3 … 3.2e-5 (rate 2.00) with the axis, 5.7e-3
//!   … 9.0e-5 (1.99) on r ∈ [1, 2]; with a band of caps of height h⁵ TFEM
//!   keeps 6.8e-5 / 1.5e-4 at 1/32 (last rate 2.0), plain FEM locks.
//! - thick cylinder (a = 1, b = 2): largest element hoop error 6.5, 3.8,
//!   2.2, 1.2 % of p at 4 … 32 cells over the wall (first order: constant
//!   strain elements read at their centroid), nodal u_r 1.7e-2 … 7.3e-4 of
//!   u_r(a), the ends' axial force exact to 1e-12.
//! - contact patch test: largest stress error 8e-15 … 1.7e-13 of p over
//!   matching and non-matching cylinders and tubes, equal and 10× moduli.
//! - shaft and hub (b = 1, c = 2, δ = 10⁻³): mean pressure at mid-length
//!   −1.1e-2, −3.1e-3, −1.1e-3, −6.6e-4 of Lamé's at h = b/4 … b/32
//!   (matching), −3.9e-3 … −5.5e-4 (3:2); the push-out force with μ = 0.1
//!   within 0.1 % of 2πbℓμp once the whole interface slips.

use nalgebra::{DMatrix, SymmetricEigen};
use tfem::element::{Jmin, TriGeometry, section_stiffness};
use tfem::scenes::revolution::{
    ManufacturedRing, ShaftHub, StackedCylinders, ThickCylinder, ring_square, run_manufactured_ring,
};
use tfem::verification::fitted_rate;
use tfem::{
    Component, ContactOptions, ContactWeighting, Material, Mesh, Model, PlaneMode, Section, Status,
    Tempering,
};

fn ring_material(e: f64, nu: f64) -> Material {
    Material::new(e, nu, PlaneMode::Axisymmetric, "body 1").unwrap()
}

fn steel() -> Material {
    ring_material(210e3, 0.3)
}

fn ring_k(p: [[f64; 2]; 3], jmin: Jmin) -> [[f64; 6]; 6] {
    let m = ring_material(1.0, 0.3);
    section_stiffness(&p, &m.d_matrix(), m.section(), jmin).unwrap()
}

fn eigenvalues(k: &[[f64; 6]; 6]) -> Vec<f64> {
    let m = DMatrix::from_fn(6, 6, |i, j| k[i][j]);
    let mut e: Vec<f64> = SymmetricEigen::new(m).eigenvalues.iter().copied().collect();
    e.sort_by(f64::total_cmp);
    e
}

/// The textbook one-point ring element 2πr̄ (J/2) BᵀD₄B, B = B̂/J + H,
/// strains [ε_rr, ε_zz, ε_θθ, γ_rz], written out densely.
fn textbook(p: [[f64; 2]; 3], e: f64, nu: f64) -> [[f64; 6]; 6] {
    let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    let mu = e / (2.0 * (1.0 + nu));
    let d = [
        [lam + 2.0 * mu, lam, lam, 0.0],
        [lam, lam + 2.0 * mu, lam, 0.0],
        [lam, lam, lam + 2.0 * mu, 0.0],
        [0.0, 0.0, 0.0, mu],
    ];
    let j = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    let r = (p[0][0] + p[1][0] + p[2][0]) / 3.0;
    let mut b = [[0.0; 6]; 4];
    for i in 0..3 {
        let (pj, pk) = (p[(i + 1) % 3], p[(i + 2) % 3]);
        let (dr, dz) = ((pj[1] - pk[1]) / j, (pk[0] - pj[0]) / j);
        b[0][2 * i] = dr;
        b[1][2 * i + 1] = dz;
        b[2][2 * i] = 1.0 / (3.0 * r);
        b[3][2 * i] = dz;
        b[3][2 * i + 1] = dr;
    }
    let w = std::f64::consts::TAU * r * j / 2.0;
    std::array::from_fn(|a| {
        std::array::from_fn(|c| {
            (0..4)
                .map(|s| (0..4).map(|t| b[s][a] * d[s][t] * b[t][c]).sum::<f64>())
                .sum::<f64>()
                * w
        })
    })
}

fn max_abs(k: &[[f64; 6]; 6]) -> f64 {
    k.iter().flatten().fold(0.0, |m, v| m.max(v.abs()))
}

#[test]
fn the_ring_element_is_positive_semidefinite_for_every_jacobian() {
    // Regular, flat, inverted, on the axis, along the axis.
    let mut shapes: Vec<[[f64; 2]; 3]> =
        [1.0, 0.1, 1e-3, 1e-5, 1e-9, 0.0, -1e-9, -1e-3, -0.1, -1.0]
            .iter()
            .map(|&t| [[1.0, 0.0], [2.0, 0.0], [1.5, t]])
            .collect();
    for t in [1.0, 1e-3, -1e-3, -1.0] {
        shapes.push([[0.0, 0.0], [1.0, 0.0], [0.5, t]]);
        shapes.push([[0.0, 0.0], [1.0, 0.0], [0.0, t]]);
    }
    shapes.push([[0.0, 0.0], [1e-5, 0.5], [0.0, 1.0]]);
    for p in shapes {
        let k = ring_k(p, Jmin::Tempered(1e-3));
        let e = eigenvalues(&k);
        let largest = e[5].abs();
        assert!(
            e[0] >= -1e-12 * largest,
            "{p:?}: smallest eigenvalue {} of {largest}",
            e[0]
        );
        for (a, row) in k.iter().enumerate() {
            for (c, v) in row.iter().enumerate() {
                assert_eq!(*v, k[c][a], "{p:?}: not symmetric");
            }
        }
    }
}

#[test]
fn an_axial_translation_costs_no_energy_and_a_radial_one_does() {
    for p in [
        [[1.0, 0.0], [2.0, 0.0], [1.5, 0.8]],
        [[1.0, 0.0], [2.0, 0.0], [1.5, 0.0]],
        [[1.0, 0.0], [2.0, 0.0], [1.5, -0.5]],
        [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
    ] {
        let k = ring_k(p, Jmin::Tempered(1e-3));
        let axial = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0];
        for row in &k {
            let f: f64 = row.iter().zip(&axial).map(|(a, b)| a * b).sum();
            assert!(f.abs() <= 1e-13 * max_abs(&k), "{p:?}: K u_z = {f}");
        }
        let radial = [1.0, 0.0, 1.0, 0.0, 1.0, 0.0];
        let energy: f64 = (0..6)
            .map(|a| radial[a] * (0..6).map(|c| k[a][c] * radial[c]).sum::<f64>())
            .sum();
        // On a flat element (J = 0) the hoop strain is tempered away.
        if p[2][1] != 0.0 {
            assert!(energy > 1e-6 * max_abs(&k), "{p:?}: u_r = 1 costs {energy}");
        }
    }
}

#[test]
fn above_jmin_the_ring_element_is_the_textbook_one_point_element() {
    for p in [
        [[1.0, 0.0], [2.0, 0.2], [1.3, 0.9]],
        [[0.0, 0.0], [0.5, 0.1], [0.2, 0.7]],
        [[3.0, -1.0], [3.4, -0.9], [3.1, -0.2]],
    ] {
        for jmin in [Jmin::Off, Jmin::Tempered(1e-6)] {
            let m = ring_material(2.5, 0.27);
            let k = section_stiffness(&p, &m.d_matrix(), m.section(), jmin).unwrap();
            let r = textbook(p, 2.5, 0.27);
            for a in 0..6 {
                for c in 0..6 {
                    assert!(
                        (k[a][c] - r[a][c]).abs() <= 1e-13 * max_abs(&r),
                        "{p:?} {a} {c}"
                    );
                }
            }
        }
    }
}

#[test]
fn at_zero_jacobian_the_ring_element_is_the_planar_tempered_one_times_two_pi_r() {
    let p = [[1.0, 0.0], [3.0, 0.0], [2.2, 0.0]];
    let m = ring_material(1.0, 0.3);
    let ring = section_stiffness(&p, &m.d_matrix(), m.section(), Jmin::Tempered(1e-2)).unwrap();
    let plane = section_stiffness(&p, &m.d_matrix(), Section::Plane, Jmin::Tempered(1e-2)).unwrap();
    let w = std::f64::consts::TAU * (1.0 + 3.0 + 2.2) / 3.0;
    for a in 0..6 {
        for c in 0..6 {
            assert!((ring[a][c] - w * plane[a][c]).abs() <= 1e-14 * max_abs(&ring));
        }
    }
    assert_eq!(TriGeometry::new(&p).j, 0.0);
}

fn manufactured_errors(r0: f64, band: bool, tempering: Tempering) -> (Vec<f64>, Vec<f64>) {
    let (mut h, mut e) = (Vec::new(), Vec::new());
    for n in [4, 8, 16, 32] {
        let eps = band.then(|| (1.0 / n as f64).powi(5));
        let p = run_manufactured_ring(ring_square(r0, n, eps), 1.0 / n as f64, steel(), tempering)
            .unwrap();
        h.push(p.h);
        e.push(p.l2);
    }
    (h, e)
}

#[test]
fn a_manufactured_ring_field_converges_at_second_order_with_and_without_the_axis() {
    for r0 in [0.0, 1.0] {
        let (h, e) = manufactured_errors(r0, false, Tempering::Auto);
        let rate = fitted_rate(&h, &e);
        assert!(rate > 1.95, "r0 = {r0}: L2 rate {rate} ({e:?})");
    }
}

#[test]
fn on_a_band_of_flat_caps_tempering_keeps_second_order_where_plain_fem_locks() {
    for r0 in [0.0, 1.0] {
        let (h, tempered) = manufactured_errors(r0, true, Tempering::Auto);
        let (_, plain) = manufactured_errors(r0, true, Tempering::Off);
        let last = (tempered[2] / tempered[3]).log2();
        assert!(last > 1.9, "r0 = {r0}: last L2 rate {last} ({tempered:?})");
        assert!(fitted_rate(&h, &tempered) > 1.7, "{tempered:?}");
        // Plain FEM on caps of height h⁵: stuck far above.
        assert!(plain[3] > 20.0 * tempered[3], "r0 = {r0}: plain {plain:?}");
    }
}

#[test]
fn a_thick_cylinder_under_internal_pressure_converges_to_lame() {
    let runs: Vec<_> = [4, 8, 16, 32]
        .iter()
        .map(|&cells| {
            ThickCylinder {
                cells,
                ..Default::default()
            }
            .solve()
            .unwrap()
        })
        .collect();
    let h: Vec<f64> = [4.0, 8.0, 16.0, 32.0].iter().map(|n| 1.0 / n).collect();
    let hoop: Vec<f64> = runs.iter().map(|r| r.hoop_error).collect();
    let disp: Vec<f64> = runs.iter().map(|r| r.displacement_error).collect();
    assert!(fitted_rate(&h, &hoop) > 0.8, "hoop {hoop:?}");
    assert!(hoop[3] < 0.013, "hoop {hoop:?}");
    assert!(fitted_rate(&h, &disp) > 1.4, "u_r {disp:?}");
    for r in &runs {
        assert!(r.axial_force_error < 1e-11, "{r:?}");
    }
}

#[test]
fn the_axisymmetric_contact_patch_test_is_passed_to_round_off() {
    for inner in [0.0, 1.0] {
        for cells in [[8, 8], [8, 12], [12, 8], [7, 3]] {
            for e in [[1e3, 1e3], [1e3, 1e4]] {
                let scene = StackedCylinders {
                    inner,
                    cells,
                    e,
                    nu: [0.3, 0.2],
                    ..Default::default()
                };
                let r = scene.solve().unwrap();
                assert!(r.all_active, "{scene:?}");
                assert!(r.stress_error < 1e-12, "{scene:?}: {r:?}");
                assert!(r.pressure_error < 1e-12, "{scene:?}: {r:?}");
                assert!(r.force_error < 1e-12, "{scene:?}: {r:?}");
            }
        }
    }
}

#[test]
fn a_hub_shrunk_on_a_shaft_has_lames_pressure_and_hoop_stress_at_mid_length() {
    for ratio in [(1, 1), (3, 2)] {
        let runs: Vec<_> = [4, 8, 16]
            .iter()
            .map(|&cells| {
                ShaftHub {
                    cells,
                    ratio,
                    ..Default::default()
                }
                .solve()
                .unwrap()
                .1
            })
            .collect();
        for w in runs.windows(2) {
            assert!(
                w[1].pressure_error.abs() < w[0].pressure_error.abs(),
                "{runs:?}"
            );
        }
        let fine = &runs[2];
        assert!(fine.pressure_error.abs() < 0.01, "{fine:?}");
        assert!(fine.pressure_spread < 0.01, "{fine:?}");
        assert!(fine.hub_hoop_error.abs() < 0.01, "{fine:?}");
        assert!(fine.shaft_hoop_error.abs() < 0.01, "{fine:?}");
    }
}

#[test]
fn the_push_out_force_of_a_fit_is_two_pi_b_l_mu_p() {
    for ratio in [(1, 1), (3, 2)] {
        let fit = ShaftHub {
            cells: 8,
            ratio,
            mu: 0.1,
            ..Default::default()
        };
        let (force, slipping) = fit.push_out(1e-3, 1).unwrap();
        assert_eq!(slipping, 1.0, "{ratio:?}: not all slip");
        let error = force / fit.push_out_force() - 1.0;
        assert!(error.abs() < 0.02, "{ratio:?}: F/F0 − 1 = {error}");
    }
}

/// A ring square [r0, r0 + 1]² of 2 × 2 cells, axisymmetric, u_z held at
/// the bottom.
fn small_ring(r0: f64) -> Model {
    let b = ring_square(r0, 2, None);
    let bottom: Vec<usize> = (0..b.nodes.len())
        .filter(|&v| b.nodes[v][1] == 0.0)
        .collect();
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_material(1, steel()).unwrap();
    for v in bottom {
        model.fix(v, Component::Y, 0.0).unwrap();
    }
    model
}

#[test]
fn a_node_on_the_axis_with_a_free_radial_displacement_is_named() {
    let mut model = small_ring(0.0);
    model.add_nodal_force(8, [0.0, -1.0]).unwrap();
    let e = model.solve().unwrap_err();
    assert_eq!(e.status(), Status::InvalidArgument);
    assert!(
        e.message().contains("node 0") && e.message().contains("axis"),
        "{}",
        e.message()
    );
    for v in [0, 3, 6] {
        model.fix(v, Component::X, 0.0).unwrap();
    }
    model.solve().unwrap();
}

#[test]
fn a_body_across_the_axis_is_refused_naming_the_node() {
    let b = ring_square(-0.5, 2, None);
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    let e = model.set_material(1, steel()).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMaterial);
    assert!(
        e.message().contains("node 0") && e.message().contains("crosses"),
        "{}",
        e.message()
    );
    assert!(model.material(1).is_none());
}

#[test]
fn axisymmetric_and_plane_bodies_do_not_mix() {
    let mut b = ring_square(1.0, 2, None);
    let n = b.triangles.len();
    b.bodies[n / 2..].iter_mut().for_each(|t| *t = 2);
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_material(1, steel()).unwrap();
    let plane = Material::new(1.0, 0.3, PlaneMode::Strain, "body 2").unwrap();
    let e = model.set_material(2, plane).unwrap_err();
    assert!(e.message().contains("body 1"), "{}", e.message());
    assert!(model.material(2).is_none());
}

#[test]
fn axisymmetric_bodies_refuse_the_mortar_weighting() {
    let mut model = small_ring(1.0);
    let e = model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap_err();
    assert!(e.message().contains("axisymmetric"), "{}", e.message());
    assert_eq!(model.contact_weighting(), ContactWeighting::Auto);
}

#[test]
fn an_incompressible_ring_is_refused() {
    let e = Material::new(1.0, 0.5, PlaneMode::Axisymmetric, "body 3").unwrap_err();
    assert_eq!(e.status(), Status::InvalidMaterial);
    assert!(e.message().contains("axisymmetric") && e.message().contains("body 3"));
}

#[test]
fn a_pressure_on_an_annulus_carries_p_times_its_area_and_a_nodal_force_is_the_rings() {
    // The top face z = 1 of the ring square over r ∈ [1, 2].
    let b = ring_square(1.0, 4, None);
    let top = b.boundary_edges_where(|p| p[1] == 1.0);
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_boundary_edges(&top, &vec![9; top.len()]).unwrap();
    model.set_material(1, steel()).unwrap();
    model.add_pressure(9, 3.0).unwrap();
    model.add_nodal_force(0, [0.0, 5.0]).unwrap();
    let f = model.load_vector().unwrap();
    let total: f64 = f.iter().skip(1).step_by(2).sum();
    let annulus = 3.0 * std::f64::consts::PI * (4.0 - 1.0);
    assert!((total - (5.0 - annulus)).abs() < 1e-12 * annulus, "{total}");
}

#[test]
fn a_ring_held_axially_at_one_node_only_has_no_mechanism() {
    // The one-point rule leaves each element a centroid rotation of zero
    // energy; assembled, only the axial translation may be free.
    let b = ring_square(1.0, 4, None);
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_material(1, steel()).unwrap();
    model.fix(0, Component::Y, 0.0).unwrap();
    model.add_nodal_force(24, [1.0, 1.0]).unwrap();
    model.solve().unwrap();
    let u = model.displacements().unwrap();
    assert!(
        u.iter().flatten().all(|v| v.is_finite() && v.abs() < 1e-3),
        "{u:?}"
    );
}

#[test]
fn the_manufactured_body_force_balances_the_exact_stress() {
    // An independent check of the oracle: −div σ by central differences of
    // the exact stresses equals the derived body force.
    let m = ManufacturedRing::new(&steel());
    let (l, mu) = (210e3 * 0.3 / (1.3 * 0.4), 210e3 / 2.6);
    let stress = |[r, z]: [f64; 2]| {
        let u = |p: [f64; 2]| m.displacement(p);
        let d = 1e-6;
        let dr = |c: usize| (u([r + d, z])[c] - u([r - d, z])[c]) / (2.0 * d);
        let dz = |c: usize| (u([r, z + d])[c] - u([r, z - d])[c]) / (2.0 * d);
        let (err, ezz, ett, grz) = (dr(0), dz(1), u([r, z])[0] / r, dz(0) + dr(1));
        let tr = err + ezz + ett;
        [
            l * tr + 2.0 * mu * err,
            l * tr + 2.0 * mu * ezz,
            l * tr + 2.0 * mu * ett,
            mu * grz,
        ]
    };
    for p in [[0.7, 0.3], [1.5, 0.9], [0.2, 0.5]] {
        let [r, z] = p;
        let d = 1e-4;
        let s = stress(p);
        let ds_dr = |c: usize| (stress([r + d, z])[c] - stress([r - d, z])[c]) / (2.0 * d);
        let ds_dz = |c: usize| (stress([r, z + d])[c] - stress([r, z - d])[c]) / (2.0 * d);
        let br = -(ds_dr(0) + ds_dz(3) + (s[0] - s[2]) / r);
        let bz = -(ds_dr(3) + ds_dz(1) + s[3] / r);
        let b = m.body_force(p);
        let scale = b[0].abs().max(b[1].abs());
        assert!(
            (br - b[0]).abs() < 1e-4 * scale && (bz - b[1]).abs() < 1e-4 * scale,
            "{p:?}: {b:?} vs {br}, {bz}"
        );
    }
}

#[test]
fn a_mesh_without_an_axisymmetric_material_is_unchanged_by_the_mode() {
    // The same ring square solved as plane strain and as a ring: the
    // modes differ (the ring feels its hoop strain), and the plane one is
    // the plane solve as before (no measure applied).
    let solve = |plane: PlaneMode| {
        let b = ring_square(1.0, 2, None);
        let mesh: Mesh = b.build().unwrap();
        let mut model = Model::new();
        model.set_mesh(mesh);
        model
            .set_material(1, Material::new(1.0, 0.3, plane, "b").unwrap())
            .unwrap();
        for v in [0, 1, 2] {
            model.fix(v, Component::X, 0.0).unwrap();
            model.fix(v, Component::Y, 0.0).unwrap();
        }
        model.add_nodal_force(7, [0.0, 1.0]).unwrap();
        model.solve().unwrap();
        model.displacements().unwrap()[7][1]
    };
    let (plane, ring) = (solve(PlaneMode::Strain), solve(PlaneMode::Axisymmetric));
    assert!(
        plane > 0.0 && ring > 0.0 && (plane / ring) > 3.0,
        "{plane} {ring}"
    );
    let _ = ContactOptions::default();
}
