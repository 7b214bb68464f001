//! Many bodies (issue 22): automatic pairing of tagged boundaries, a stack
//! of n blocks (the many-body patch test), a ring inside a ring
//! (Code_Aster SSNP167) and a masonry wall in running bond (corners shared
//! by three bodies).

use tfem::ContactOptions;
use tfem::scenes::ring::Rings;
use tfem::scenes::stack::{Face, Pairing, Rect, Stack, block_tag, mesh_blocks};
use tfem::scenes::wall::Wall;
use tfem::verification::fitted_rate;
use tfem::{Component, Material, Model, PlaneMode};

/// Rectangles as blocks of one model (block k + 1 = `rects[k]`), each its
/// own body unless `bodies` says otherwise, faces tagged `block_tag`.
fn blocks(rects: &[Rect], bodies: Option<&[i32]>) -> Model {
    let (mut b, edges, tags) = mesh_blocks(rects);
    if let Some(bodies) = bodies {
        let per_block = b.bodies.len() / rects.len();
        for (t, body) in b.bodies.iter_mut().enumerate() {
            *body = bodies[t / per_block];
        }
    }
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_boundary_edges(&edges, &tags).unwrap();
    model
}

fn rect(x0: f64, x1: f64, y0: f64, y1: f64, n: usize) -> Rect {
    let grid = |a: f64, b: f64| (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    Rect {
        xs: grid(x0, x1),
        ys: grid(y0, y1),
    }
}

/// Blocks A = [0, 1] × [0, 1/2], B = [1, 2] × [0, 1/2] side by side and
/// C = [1/2, 3/2] × [1/2, 1] on both: the point (1, 1/2) is a corner of A
/// and B and a point of C's bottom.
fn three_bodies() -> Vec<Rect> {
    vec![
        rect(0.0, 1.0, 0.0, 0.5, 4),
        rect(1.0, 2.0, 0.0, 0.5, 4),
        rect(0.5, 1.5, 0.5, 1.0, 4),
    ]
}

fn pairs(model: &Model) -> Vec<(i32, i32)> {
    model
        .contact_pairs()
        .iter()
        .map(|p| (p.tag_a, p.tag_b))
        .collect()
}

#[test]
fn automatic_pairing_finds_exactly_the_facing_faces_of_three_bodies() {
    let mut model = blocks(&three_bodies(), None);
    let added = model.add_contact_pairs_auto(None, 1e-9).unwrap();
    // By construction: the head joint A|B and the bed joints A–C, B–C.
    // Faces that only share the corner (1, 1/2) — A's right and C's
    // bottom, A's top and B's left, … — meet at a point or at a right
    // angle: not pairs.
    let expected = vec![
        (block_tag(1, Face::Top), block_tag(3, Face::Bottom)),
        (block_tag(1, Face::Right), block_tag(2, Face::Left)),
        (block_tag(2, Face::Top), block_tag(3, Face::Bottom)),
    ];
    let mut found = pairs(&model);
    found.sort_unstable();
    let mut want = expected.clone();
    want.sort_unstable();
    assert_eq!(found, want);
    assert_eq!(added, vec![0, 1, 2]);
}

#[test]
fn automatic_pairing_restricted_to_given_tags_pairs_only_those() {
    let mut model = blocks(&three_bodies(), None);
    let tags = [block_tag(1, Face::Top), block_tag(3, Face::Bottom)];
    model.add_contact_pairs_auto(Some(&tags), 1e-9).unwrap();
    assert_eq!(pairs(&model), vec![(tags[0], tags[1])]);
}

#[test]
fn automatic_pairing_skips_pairs_already_declared() {
    let mut model = blocks(&three_bodies(), None);
    // Declared the other way round: still the same pair.
    model
        .add_contact_pair(block_tag(3, Face::Bottom), block_tag(1, Face::Top))
        .unwrap();
    let added = model.add_contact_pairs_auto(None, 1e-9).unwrap();
    assert_eq!(added, vec![1, 2]);
    assert_eq!(model.contact_pairs().len(), 3);
}

#[test]
fn two_pieces_of_one_body_facing_each_other_are_not_paired() {
    // A and C belong to body 1, B to body 2: A–C faces each other but is
    // self-contact (not supported), so only the pairs with B remain.
    let mut model = blocks(&three_bodies(), Some(&[1, 2, 1]));
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    let mut found = pairs(&model);
    found.sort_unstable();
    assert_eq!(
        found,
        vec![
            (block_tag(1, Face::Right), block_tag(2, Face::Left)),
            (block_tag(2, Face::Top), block_tag(3, Face::Bottom)),
        ]
    );
}

#[test]
fn a_tolerance_below_the_gap_finds_no_pair() {
    // Two blocks 1e-3 apart: found within 2e-3, none within 5e-4.
    let rects = [rect(0.0, 1.0, 0.0, 0.5, 4), rect(0.0, 1.0, 0.501, 1.001, 4)];
    let mut model = blocks(&rects, None);
    assert_eq!(
        model.add_contact_pairs_auto(None, 5e-4).unwrap(),
        Vec::<usize>::new()
    );
    assert!(model.contact_pairs().is_empty());
    assert_eq!(model.add_contact_pairs_auto(None, 2e-3).unwrap(), vec![0]);
    assert_eq!(
        pairs(&model),
        vec![(block_tag(1, Face::Top), block_tag(2, Face::Bottom))]
    );
}

/// Three unit blocks stacked: [0, 1] × [k, k + 1], k = 0, 1, 2.
fn three_stacked() -> Vec<Rect> {
    (0..3)
        .map(|k| rect(0.0, 1.0, k as f64, k as f64 + 1.0, 2))
        .collect()
}

fn bed_joints() -> Vec<(i32, i32)> {
    vec![
        (block_tag(1, Face::Top), block_tag(2, Face::Bottom)),
        (block_tag(2, Face::Top), block_tag(3, Face::Bottom)),
    ]
}

#[test]
fn outer_faces_back_to_back_never_pair_whatever_the_tolerance() {
    // Block 1's bottom (y = 0, facing down) and block 2's top (y = 2,
    // facing up) have opposed normals 2 apart, turned away from each
    // other: a probe paired them at δ = 2.5 and read a 2-unit overlap.
    let mut model = blocks(&three_stacked(), None);
    model.add_contact_pairs_auto(None, 2.5).unwrap();
    let mut found = pairs(&model);
    found.sort_unstable();
    assert_eq!(found, bed_joints());
}

#[test]
fn faces_with_a_body_between_them_do_not_pair() {
    // Block 1's top and block 3's bottom face each other 1 apart, across
    // block 2: within δ = 1.5, but not a contact.
    let mut model = blocks(&three_stacked(), None);
    model.add_contact_pairs_auto(None, 1.5).unwrap();
    let mut found = pairs(&model);
    found.sort_unstable();
    assert_eq!(found, bed_joints());
}

#[test]
fn faces_beside_a_narrower_body_between_them_still_pair() {
    // Block 2 covers only the left half of the gap between blocks 1 and
    // 3: the right halves of their faces see each other across 1 and pair
    // within δ = 1.5; within δ = 0.5 they do not.
    let rects = [
        rect(0.0, 1.0, 0.0, 1.0, 4),
        rect(0.0, 0.5, 1.0, 2.0, 2),
        rect(0.0, 1.0, 2.0, 3.0, 4),
    ];
    let across = (block_tag(1, Face::Top), block_tag(3, Face::Bottom));
    let mut model = blocks(&rects, None);
    model.add_contact_pairs_auto(None, 1.5).unwrap();
    assert!(pairs(&model).contains(&across), "{:?}", pairs(&model));
    let mut model = blocks(&rects, None);
    model.add_contact_pairs_auto(None, 0.5).unwrap();
    assert!(!pairs(&model).contains(&across), "{:?}", pairs(&model));
}

#[test]
fn a_press_fit_pairs_on_every_mesh() {
    // Two unit blocks overlapping by 0.02, within δ = 0.03: a reviewer
    // found no pair once the edges were shorter than twice the overlap
    // (h = 1/32) when "in front" allowed half an edge of overlap. It now
    // pairs while the overlap is below the elements' height (h = 1/64,
    // 0.0156, does not: declared by hand, docs/method.md §6.16).
    for n in [4, 16, 32] {
        let rects = [rect(0.0, 1.0, 0.0, 1.0, n), rect(0.0, 1.0, 0.98, 1.98, n)];
        let mut model = blocks(&rects, None);
        assert_eq!(
            model.add_contact_pairs_auto(None, 0.03).unwrap(),
            vec![0],
            "n = {n}"
        );
    }
}

#[test]
fn a_body_between_two_faces_over_part_of_an_edge_does_not_hide_the_rest() {
    // A shim under the left 0.3 of block B's bottom, on block A; A and B
    // are one cell across, so A's top is one edge: 70 % of it still faces
    // B across 0.001 and the pair stands (a reviewer found it dropped).
    let rects = [
        rect(0.0, 1.0, -1.0, 0.0, 1),
        rect(0.0, 0.3, 0.0, 0.001, 1),
        rect(0.0, 1.0, 0.001, 1.0, 1),
    ];
    let mut model = blocks(&rects, None);
    model.add_contact_pairs_auto(None, 0.01).unwrap();
    let across = (block_tag(1, Face::Top), block_tag(3, Face::Bottom));
    assert!(pairs(&model).contains(&across), "{:?}", pairs(&model));
}

#[test]
fn a_gap_of_exactly_the_tolerance_pairs() {
    // The gap computed from the coordinates, (1 + 0.1) − 1, is
    // 0.10000000000000009: a probe found no pair within δ = 0.1.
    for gap in [0.1, 0.01, 0.3] {
        let rects = [
            rect(0.0, 1.0, 0.0, 1.0, 2),
            rect(0.0, 1.0, 1.0 + gap, 2.0 + gap, 2),
        ];
        let mut model = blocks(&rects, None);
        assert_eq!(
            model.add_contact_pairs_auto(None, gap).unwrap(),
            vec![0],
            "gap {gap}"
        );
    }
}

/// Two unit blocks stacked, with every boundary edge of the lower one
/// also under tag 99 (a Gmsh file's "whole boundary" group).
fn stacked_with_a_whole_boundary_tag() -> Model {
    let rects = [rect(0.0, 1.0, 0.0, 1.0, 2), rect(0.0, 1.0, 1.0, 2.0, 2)];
    let mut model = blocks(&rects, None);
    let lower: Vec<[usize; 2]> = model
        .mesh()
        .unwrap()
        .boundary_edges()
        .iter()
        .filter(|e| {
            [Face::Bottom, Face::Right, Face::Top, Face::Left]
                .iter()
                .any(|&f| e.tag == block_tag(1, f))
        })
        .map(|e| e.nodes)
        .collect();
    model
        .add_boundary_edges(&lower, &vec![99; lower.len()])
        .unwrap();
    model
}

#[test]
fn a_pair_over_an_interface_already_paired_under_other_tags_is_refused() {
    // (99, bottom of block 2) is the interface (top of block 1, bottom of
    // block 2) again: declared too, its contact would count twice.
    let mut model = stacked_with_a_whole_boundary_tag();
    let bottom = block_tag(2, Face::Bottom);
    model
        .add_contact_pair(block_tag(1, Face::Top), bottom)
        .unwrap();
    let e = model.add_contact_pair(99, bottom).unwrap_err();
    assert!(
        e.message()
            .contains("covers the interface of contact pair 0"),
        "{}",
        e.message()
    );
    assert_eq!(model.contact_pairs().len(), 1);
}

#[test]
fn automatic_pairing_pairs_an_interface_once_under_its_most_specific_tags() {
    let mut model = stacked_with_a_whole_boundary_tag();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    assert_eq!(
        pairs(&model),
        vec![(block_tag(1, Face::Top), block_tag(2, Face::Bottom))]
    );
}

#[test]
fn automatic_pairing_names_an_interface_it_leaves_paired_under_other_tags() {
    // (99, bottom of block 2) is the interface (top of block 1, bottom of
    // block 2) again: not paired, and said (it was skipped without a word).
    let mut model = stacked_with_a_whole_boundary_tag();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    let (top, bottom) = (block_tag(1, Face::Top), block_tag(2, Face::Bottom));
    let w = model.warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains(&format!(
            "did not pair tags {bottom} (body 2) and 99 (body 1)"
        )) && w[0].contains(&format!("contact pair ({top}, {bottom})"))
            && w[0].contains("declare that pair by hand"),
        "{}",
        w[0]
    );
}

#[test]
fn automatic_pairing_names_a_tag_over_two_bodies_it_leaves_out() {
    // Block 1's top and block 2's right under one tag 5: it cannot be a
    // contact side, so the interface is not paired, and said (it was
    // left out without a word).
    let rects = [rect(0.0, 1.0, 0.0, 1.0, 2), rect(0.0, 1.0, 1.0, 2.0, 2)];
    let (b, edges, mut tags) = mesh_blocks(&rects);
    for t in tags.iter_mut() {
        if *t == block_tag(1, Face::Top) || *t == block_tag(2, Face::Right) {
            *t = 5;
        }
    }
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_boundary_edges(&edges, &tags).unwrap();
    assert!(model.add_contact_pairs_auto(None, 1e-9).unwrap().is_empty());
    let w = model.warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("left out tag 5: its edges bound bodies 1, 2")
            && w[0].contains("a tag of its own"),
        "{}",
        w[0]
    );
}

#[test]
fn pairing_warnings_are_not_repeated_and_go_with_the_pairs() {
    let mut model = stacked_with_a_whole_boundary_tag();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    assert_eq!(model.warnings().len(), 1, "{:?}", model.warnings());
    model.clear_contact_pairs();
    assert!(model.warnings().is_empty(), "{:?}", model.warnings());
}

#[test]
fn new_boundary_edges_drop_what_automatic_pairing_said_of_the_old() {
    // A reviewer's case: following the warning's advice (retag the edges)
    // left it in place until the pairs were cleared.
    let mut model = stacked_with_a_whole_boundary_tag();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    assert_eq!(model.warnings().len(), 1, "{:?}", model.warnings());
    let (edges, tags): (Vec<[usize; 2]>, Vec<i32>) = model
        .mesh()
        .unwrap()
        .boundary_edges()
        .iter()
        .map(|e| (e.nodes, e.tag))
        .unzip();
    model.set_boundary_edges(&edges, &tags).unwrap();
    assert!(model.warnings().is_empty(), "{:?}", model.warnings());
}

#[test]
fn bad_pairing_input_is_refused_naming_it() {
    let mut model = blocks(&three_bodies(), None);
    for tol in [-1e-3, f64::NAN, f64::INFINITY] {
        let e = model.add_contact_pairs_auto(None, tol).unwrap_err();
        assert!(e.message().contains("tolerance"), "{}", e.message());
    }
    let e = model
        .add_contact_pairs_auto(Some(&[11, 999]), 1e-9)
        .unwrap_err();
    assert!(e.message().contains("999"), "{}", e.message());
    assert!(model.contact_pairs().is_empty());
}

#[test]
fn declared_and_automatic_pairs_give_the_same_solution() {
    let stack = Stack::alternating(4, 0.25, &[16, 24, 10]);
    let auto = Stack {
        pairing: Pairing::Auto { tolerance: 1e-9 },
        ..stack.clone()
    };
    let (mut a, mut b) = (stack.build().unwrap(), auto.build().unwrap());
    // The automatic pairs are the declared ones, in the same order.
    assert_eq!(pairs(&a.model), pairs(&b.model));
    let options = ContactOptions::default();
    a.model.solve_contact(&options).unwrap();
    b.model.solve_contact(&options).unwrap();
    // Same pairs in the same order: the same system, bit for bit.
    assert_eq!(
        a.model.displacements().unwrap(),
        b.model.displacements().unwrap()
    );
}

#[test]
fn a_stack_of_three_to_five_blocks_of_different_materials_carries_the_uniform_stress() {
    // Moduli 1e10/1e11, ν 0.3/0.2, non-matching interfaces (16, 24, 10
    // cells across): σ_yy = −p, σ_xx = τ_xy = 0 in every element (exact:
    // each interface is a straight strip of B, which passes the patch test,
    // docs/method.md §6.11). Round-off: ~1e-13 p here (condition ~1/h²);
    // 1e-10 leaves three orders of margin.
    for n in 3..=5 {
        let stack = Stack {
            pairing: Pairing::Auto { tolerance: 1e-9 },
            ..Stack::alternating(n, 0.25, &[16, 24, 10])
        };
        let mut scene = stack.build().unwrap();
        assert_eq!(scene.pairs.len(), n - 1);
        let r = scene.solve(stack.p, &ContactOptions::default()).unwrap();
        assert!(r.max_error < 1e-10, "{n} blocks: {:e}", r.max_error);
        assert_eq!(r.released, 0, "{n} blocks");
        for (k, (&a, &e)) in r
            .active_per_pair
            .iter()
            .zip(&r.elements_per_pair)
            .enumerate()
        {
            assert!(
                e > 0 && a == e,
                "{n} blocks, interface {k}: {a} of {e} active"
            );
        }
    }
}

#[test]
fn ring_in_ring_contact_pressure_converges_to_the_analytic_one() {
    // SSNP167 (E = 1e9, ν = 0.2, p = 1e7 + 1e6 cos 2θ, R = 1, 0.6, 0.2):
    // nodal contact pressures against p_c(θ) = p0 + p2 cos 2θ (Michell's
    // solution, frictionless interface), on the criss-cross mesh (the
    // quarter is the exact restriction of a symmetric full ring). Every
    // element of B of the curved matching interface measures its node
    // pair's gap along the nodal normal (docs/method.md §6.2), so slip is
    // not read as an opening: nothing is released, one iteration.
    // Measured (N = 32, 64, 128 cells on the quarter): max error 8.67e-4,
    // 2.17e-4, 5.43e-5 of max p_c, fitted rate 2.00; the cos 2θ amplitude
    // 1.30e-3, 3.27e-4, 8.18e-5 (rate 2.00). With the chord normals (the
    // law before) 15, 51, 117 elements were released and the max error
    // was 2.0e-2, 1.2e-2, 6.5e-3 (rate 0.83). Bounds: rates 0.2 below the
    // measured ones, the error at N = 128 twice the measured one.
    let levels = [32, 64, 128];
    let (mut h, mut e, mut amp) = (Vec::new(), Vec::new(), Vec::new());
    for cells in levels {
        let rings = Rings {
            cells,
            ..Default::default()
        };
        let mut scene = rings.build().unwrap();
        let r = scene.solve(&ContactOptions::default()).unwrap();
        assert_eq!(r.released, 0, "N = {cells}: {} released", r.released);
        assert_eq!(r.report.iterations, 1, "N = {cells}");
        h.push(1.0 / cells as f64);
        e.push(r.max_error);
        amp.push(r.amplitude_error);
    }
    // The analytic solution itself: p0 = α0 for equal materials (a
    // uniform pressure crosses a frictionless interface unchanged).
    let exact = Rings::default().build().unwrap().exact;
    assert!((exact.p0 - 1e7).abs() < 1e-6 * 1e7, "{}", exact.p0);
    let rate = fitted_rate(&h, &e);
    assert!(rate > 1.8, "rate {rate}, errors {e:?}");
    let rate_amp = fitted_rate(&h, &amp);
    assert!(rate_amp > 1.8, "amplitude rate {rate_amp}, errors {amp:?}");
    assert!(e[2] < 1.1e-4, "{e:?}");
}

#[test]
fn ring_in_ring_on_a_chiral_mesh_releases_nothing_and_its_amplitude_converges_at_second_order() {
    // The same rings, each cell split by its "/" diagonal: the discrete
    // quarter twists against its rollers, which spoils the nodal pressure
    // at the symmetry lines (max error 6.65e-3, 3.88e-3, 2.07e-3 at
    // N = 32, 64, 128: first order, a property of the body mesh, as for
    // the Lamé rings, docs/method.md §6.14). B is not at fault: nothing
    // is released, and the cos 2θ amplitude converges at second order
    // (2.82e-3, 7.32e-4, 1.83e-4, rate 1.97; with the chord normals it
    // was 1.5e-1, 8.0e-2, 4.1e-2 with 15, 51, 117 elements released).
    // Bound: the rate 0.2 below the measured one.
    let (mut h, mut amp) = (Vec::new(), Vec::new());
    for cells in [32, 64, 128] {
        let rings = Rings {
            cells,
            criss_cross: false,
            ..Default::default()
        };
        let r = rings
            .build()
            .unwrap()
            .solve(&ContactOptions::default())
            .unwrap();
        assert_eq!(r.released, 0, "N = {cells}: {} released", r.released);
        h.push(1.0 / cells as f64);
        amp.push(r.amplitude_error);
    }
    let rate = fitted_rate(&h, &amp);
    assert!(rate > 1.77, "amplitude rate {rate}, errors {amp:?}");
}

#[test]
fn a_confined_wall_under_uniform_pressure_converges_to_the_uniform_stress() {
    // Running bond, 4 courses: σ_yy = −p, σ_xx = −ν/(1−ν) p everywhere.
    // The bed joints pass the patch test; the head joints, compressed by
    // σ_xx between the jambs, open their penalty overlap σ_xx/κ,
    // κ = E λ/h², at every joint, a consistency error of O(h²/λ) in ε_xx:
    // the stress error falls as h² (measured 1.35e-3 p at h = 1/8).
    let (mut h, mut e, mut pn) = (Vec::new(), Vec::new(), Vec::new());
    for n in [8, 16, 32] {
        let wall = Wall {
            mesh_size: 1.0 / n as f64,
            ..Default::default()
        };
        let mut scene = wall.build().unwrap();
        assert_eq!(scene.pairs, Wall::expected_pairs(&scene.blocks));
        let r = scene.solve(&wall, &ContactOptions::default()).unwrap();
        assert_eq!(r.released, 0);
        h.push(wall.mesh_size);
        e.push(r.max_uniform_error);
        pn.push(r.max_nodal_pressure_error);
    }
    let rate = fitted_rate(&h, &e);
    assert!((rate - 2.0).abs() < 0.2, "rate {rate}, errors {e:?}");
    // The nodal pressures, on nodes of one pair or several, follow.
    let rate = fitted_rate(&h, &pn);
    assert!((rate - 2.0).abs() < 0.2, "nodal rate {rate}, errors {pn:?}");
}

#[test]
fn every_node_of_a_wall_reads_the_pressure_of_the_faces_it_lies_on() {
    // Uniform pressure, h = 1/8 (square cells: a node's tributary on each
    // of its joints is h/2). Bed joints carry p exactly; head joints carry
    // q = ν/(1−ν) p up to the penalty's O(h²/λ) error of the scene (its
    // stress error). A node where a head joint ends on a bed face lies on
    // two bed pairs and reads p; a block's corner lies on a bed and a head
    // pair and reads their mean, (p + q)/2 (`WallScene::face_pressures`).
    let wall = Wall::default();
    let mut scene = wall.build().unwrap();
    let r = scene.solve(&wall, &ContactOptions::default()).unwrap();
    let pressures = scene.model.contact_nodal_pressures().unwrap();
    let elements = scene.model.contact_elements().unwrap();
    let pairs_at = |v: usize| {
        let pairs: std::collections::BTreeSet<usize> = elements
            .iter()
            .filter(|el| el.nodes.contains(&v))
            .map(|el| el.pair)
            .collect();
        pairs.len()
    };
    let (mut on_two_beds, mut corners) = (0, 0);
    for (v, want, on_head) in scene.face_pressures(&wall).unwrap() {
        let got = pressures[v] / wall.p;
        if on_head {
            // A head-joint node reads the joint's σ_xx, whose error is the
            // scene's stress error (equal to 11 digits, measured): a 1e-6
            // relative margin for the reading's round-off.
            let tol = r.max_uniform_error * (1.0 + 1e-6);
            assert!((got - want).abs() <= tol, "node {v}: {got} against {want}");
            corners += usize::from(pairs_at(v) == 2);
        } else {
            assert!((got - 1.0).abs() < 1e-10, "bed node {v}: {got}");
            on_two_beds += usize::from(pairs_at(v) == 2);
        }
    }
    assert!(on_two_beds > 0 && corners > 0, "{on_two_beds} {corners}");
}

#[test]
fn each_pair_of_a_wall_read_alone_gives_its_own_face_pressure_at_the_corners() {
    // `Model::contact_pair_nodal_pressures`: a bed pair reads p at every
    // node it gives a value, a head pair q = ν/(1−ν) p within the scene's
    // stress error (as in the test above), a block's corner included —
    // where the pairs read together give the mean (p + q)/2. Every node
    // the pairs together load is read by at least one pair alone, and
    // each corner by two.
    let wall = Wall::default();
    let mut scene = wall.build().unwrap();
    let r = scene.solve(&wall, &ContactOptions::default()).unwrap();
    let q = wall.poisson / (1.0 - wall.poisson);
    let head_tol = r.max_uniform_error * (1.0 + 1e-6);
    let elements = scene.model.contact_elements().unwrap().to_vec();
    let together = scene.model.contact_nodal_pressures().unwrap();
    let mut read_by = vec![0usize; together.len()];
    for pair in 0..scene.model.contact_pairs().len() {
        let el = elements.iter().find(|el| el.pair == pair).unwrap();
        let bed = el.normal[1].abs() > el.normal[0].abs();
        let (want, tol) = if bed { (1.0, 1e-10) } else { (q, head_tol) };
        let alone = scene.model.contact_pair_nodal_pressures(pair).unwrap();
        for (v, &pv) in alone.iter().enumerate().filter(|(_, pv)| **pv != 0.0) {
            read_by[v] += 1;
            let got = pv / wall.p;
            assert!(
                (got - want).abs() <= tol,
                "pair {pair} node {v}: {got} against {want}"
            );
        }
    }
    let mut corners = 0;
    for (v, &t) in together.iter().enumerate().filter(|(_, t)| **t != 0.0) {
        assert!(read_by[v] >= 1, "node {v} read by no pair alone");
        if (t / wall.p - 0.5 * (1.0 + q)).abs() <= head_tol {
            assert_eq!(read_by[v], 2, "corner {v}");
            corners += 1;
        }
    }
    assert!(corners > 0);
    let n = scene.model.contact_pairs().len();
    let e = scene.model.contact_pair_nodal_pressures(n).unwrap_err();
    assert!(
        e.message().contains(&format!("contact pair {n}")),
        "{}",
        e.message()
    );
}

#[test]
fn a_wall_with_an_eccentric_load_converges_without_cycling_and_balances_its_loads() {
    // Self-weight ρg = 2e4 N/m³ and p = 1e6 over the left third of the
    // top: joints open under the unloaded part. The loop must end on a
    // fixed point (no revisited set, within the default cap), and every
    // block must be in equilibrium: loads + reactions + contact forces = 0
    // on its nodes (round-off: 1e-14 of the load measured; 1e-10 allows
    // for the conditioning of finer meshes).
    let wall = Wall {
        load_width: 1.0,
        weight: 2e4,
        ..Default::default()
    };
    let mut scene = wall.build().unwrap();
    assert_eq!(scene.pairs, Wall::expected_pairs(&scene.blocks));
    let r = scene.solve(&wall, &ContactOptions::default()).unwrap();
    assert!(
        r.report.iterations <= 10,
        "{} iterations",
        r.report.iterations
    );
    assert!(r.released > 0, "joints open under the unloaded part");
    assert!(r.block_imbalance < 1e-10, "{:e}", r.block_imbalance);
    assert!(r.contact_imbalance < 1e-10, "{:e}", r.contact_imbalance);
    // The course below carries the whole top course (its weight and the
    // pressure).
    assert!(
        (r.top_course_support - 1.0).abs() < 1e-10,
        "{}",
        r.top_course_support
    );
}

#[test]
fn a_block_touching_two_others_is_held_by_both_pairs() {
    // The three-body corner under load: C pressed on A and B (rollers
    // under both, u = 0 along x = 0 and x = 2); C's load reaches the
    // ground through both bed joints, half each by symmetry.
    let mut model = blocks(&three_bodies(), None);
    let (b, _, _) = mesh_blocks(&three_bodies());
    let m = Material::new(1e10, 0.3, PlaneMode::Strain, "block").unwrap();
    for body in 1..=3 {
        model.set_material(body, m).unwrap();
    }
    model
        .fix_edges(block_tag(1, Face::Bottom), Component::Y, 0.0)
        .unwrap();
    model
        .fix_edges(block_tag(2, Face::Bottom), Component::Y, 0.0)
        .unwrap();
    model
        .fix_edges(block_tag(1, Face::Left), Component::X, 0.0)
        .unwrap();
    model
        .fix_edges(block_tag(2, Face::Right), Component::X, 0.0)
        .unwrap();
    // C's horizontal position: u = 0 on its axis x = 1 (symmetry).
    for (v, x) in b.nodes.iter().enumerate() {
        if x[0] == 1.0 && x[1] >= 0.5 && b.nodes.len() / 3 * 2 <= v {
            model.fix(v, Component::X, 0.0).unwrap();
        }
    }
    let p = 1e6;
    model.add_pressure(block_tag(3, Face::Top), p).unwrap();
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    model.solve_contact(&ContactOptions::default()).unwrap();
    let f = model.contact_forces().unwrap();
    let node_body = model.mesh().unwrap().node_body().to_vec();
    let on = |body: i32| -> f64 {
        (0..f.len())
            .filter(|&v| node_body[v] == Some(body))
            .map(|v| f[v][1])
            .sum()
    };
    // The load on C is p × 1 (its top is 1 long), downwards: C's contact
    // forces carry it exactly (equilibrium; 1e-10 for round-off) and A
    // and B take it back (action and reaction). Each takes about half: the
    // scene is symmetric about x = 1 but its "/" diagonals are not (0.25 %
    // measured), hence 1 %.
    let (a, b_, c) = (on(1) / p, on(2) / p, on(3) / p);
    assert!((c - 1.0).abs() < 1e-10, "C: {c}");
    assert!((a + b_ + 1.0).abs() < 1e-10, "A + B: {}", a + b_);
    for (name, share) in [("A", a), ("B", b_)] {
        assert!((share + 0.5).abs() < 1e-2, "{name}: {share}");
    }
}

/// A rectangle [x0, x1] × [y0, y1] with `nx` × `ny` cells.
fn cells(x0: f64, x1: f64, y0: f64, y1: f64, nx: usize, ny: usize) -> Rect {
    let grid =
        |a: f64, b: f64, n: usize| (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    Rect {
        xs: grid(x0, x1, nx),
        ys: grid(y0, y1, ny),
    }
}

/// Solves blocks `rects` (block k + 1 = `rects[k]`, moduli `young`, ν =
/// 0.3) with every face within 1e-9 paired, `fix` applied, the pressure
/// `p` on the tops of blocks `loaded`; returns the model and its report.
fn solve_blocks(
    rects: &[Rect],
    young: &[f64],
    fix: &[(usize, Face, Component)],
    loaded: &[usize],
    p: f64,
) -> (Model, tfem::ContactReport) {
    let mut model = blocks(rects, None);
    for (k, &e) in young.iter().enumerate() {
        let m = Material::new(e, 0.3, PlaneMode::Strain, "block").unwrap();
        model.set_material(k as i32 + 1, m).unwrap();
    }
    for &(block, face, c) in fix {
        model.fix_edges(block_tag(block, face), c, 0.0).unwrap();
    }
    for &block in loaded {
        model.add_pressure(block_tag(block, Face::Top), p).unwrap();
    }
    model.add_contact_pairs_auto(None, 1e-9).unwrap();
    let report = model.solve_contact(&ContactOptions::default()).unwrap();
    (model, report)
}

/// Per block, the largest |σ_yy + p|, |τ_xy| and spread of σ_xx over its
/// elements, over p, and its mean σ_xx: a uniform state with σ_yy = −p.
/// (σ_xx of a block confined across closed head joints is −ν/(1 − ν) p
/// only up to the joints' penalty overlap: 1.1e-2 of p at the corner's
/// default penalty, the same with a base node under the corner.)
fn uniform_stress_errors(model: &Model, blocks: usize, p: f64) -> (Vec<f64>, Vec<f64>) {
    let stresses = model.element_stresses().unwrap();
    let bodies = model.mesh().unwrap().body_of().to_vec();
    let (mut lo, mut hi) = (vec![f64::INFINITY; blocks], vec![f64::NEG_INFINITY; blocks]);
    let mut err = vec![0.0f64; blocks];
    for (s, &b) in stresses.iter().zip(&bodies) {
        let k = b as usize - 1;
        (lo[k], hi[k]) = (lo[k].min(s[0]), hi[k].max(s[0]));
        err[k] = err[k].max((s[1] + p).abs().max(s[2].abs()) / p);
    }
    for k in 0..blocks {
        err[k] = err[k].max((hi[k] - lo[k]) / p);
    }
    let mean = lo.iter().zip(&hi).map(|(l, h)| 0.5 * (l + h)).collect();
    (err, mean)
}

#[test]
fn a_three_body_corner_with_no_base_node_under_it_carries_the_uniform_stress() {
    // The outside probe's corner (docs/method.md §6.11, "Sides that end
    // inside an edge"): base C = [0, 2] × [−1, 0] (E = 1e9) under A =
    // [0, 1] × [0, 1] (2e9) and B = [1, 2] × [0, 1] (5e8), the head joint
    // A|B closed by u = 0 on A's left and B's right, C free to the right;
    // p on A and B. An odd count of C cells puts no C node under the
    // corner (1, 0): the base edge across it faces A over part of its
    // length and B over the rest. Exact: σ_yy = −p everywhere, σ_xx = 0
    // in C and uniform in A and B (confined: −ν/(1 − ν) p up to the head
    // joint's penalty overlap), ℓc = 2 + 1. Before
    // the clipping both pairs counted that edge whole: 4.7e-2 of p at
    // 7 C cells (falling at first order), ℓc = 3.1429. Round-off is
    // ~1e-13 p here; 1e-9 as the probe asks.
    let p = 1e6;
    for (nc, na, nb) in [(7, 4, 4), (9, 4, 5), (13, 8, 6), (27, 16, 16)] {
        let rects = [
            cells(0.0, 2.0, -1.0, 0.0, nc, 3),
            cells(0.0, 1.0, 0.0, 1.0, na, 4),
            cells(1.0, 2.0, 0.0, 1.0, nb, 5),
        ];
        let fix = [
            (1, Face::Bottom, Component::Y),
            (1, Face::Left, Component::X),
            (2, Face::Left, Component::X),
            (3, Face::Right, Component::X),
        ];
        let (model, report) = solve_blocks(&rects, &[1e9, 2e9, 5e8], &fix, &[2, 3], p);
        let (err, sxx) = uniform_stress_errors(&model, 3, p);
        for (k, e) in err.iter().enumerate() {
            assert!(*e <= 1e-9, "C cells {nc}: block {}: {e:e}", k + 1);
        }
        assert!(
            sxx[0].abs() <= 1e-9 * p,
            "C cells {nc}: σ_xx in C {}",
            sxx[0]
        );
        assert_eq!(report.active, report.elements, "C cells {nc}");
        assert!(
            (report.contact_length - 3.0).abs() < 1e-12,
            "C cells {nc}: ℓc = {}",
            report.contact_length
        );
        // Every element reports the traction of its pair (p on the bed
        // joints, −σ_xx of A on the head joint), the cut ones too.
        for (&pe, el) in model
            .contact_pressure()
            .unwrap()
            .iter()
            .zip(model.contact_mesh().unwrap())
        {
            let want = if el.normal[0].abs() > 0.5 { -sxx[1] } else { p };
            assert!(
                (pe - want).abs() <= 1e-9 * p,
                "C cells {nc}: {pe} vs {want}"
            );
        }
        // And every node of an interface reads it.
        let nodal = model.contact_nodal_pressures().unwrap();
        let x = model.mesh().unwrap().nodes().to_vec();
        for (v, &pn) in nodal.iter().enumerate() {
            if pn != 0.0 && x[v][1] == 0.0 && x[v][0] > 0.0 && x[v][0] < 2.0 && x[v][0] != 1.0 {
                assert!((pn - p).abs() <= 1e-9 * p, "C cells {nc}, node {v}: {pn}");
            }
        }
    }
}

#[test]
fn two_courses_in_running_bond_with_cut_edges_at_both_ends_of_a_joint_carry_the_uniform_stress() {
    // Shifted blocks: a lower course [0, 1.5] | [1.5, 3] (height 1) under an
    // upper one [0, 1] | [1, 2] | [2, 3], head joints closed by u = 0 at
    // x = 0 and x = 3 in both courses, p on the upper course. The middle
    // upper block's bed faces [1, 1.5] of the left lower block and
    // [1.5, 2] of the right one: each side of those pairs ends inside an
    // edge of the other (no lower node at x = 1, 2; no upper node at 1.5),
    // and the end blocks' pairs have a cut edge at one end. Exact: σ_yy =
    // −p, σ_xx uniform in each block (confined across the head joints),
    // ℓc = 3 (beds) + 1 + 2 (heads).
    let p = 1e6;
    for (lower, upper) in [(4, 3), (5, 5), (8, 7), (16, 11)] {
        let rects = [
            cells(0.0, 1.5, 0.0, 1.0, lower, 3),
            cells(1.5, 3.0, 0.0, 1.0, lower, 4),
            cells(0.0, 1.0, 1.0, 2.0, upper, 3),
            cells(1.0, 2.0, 1.0, 2.0, upper, 4),
            cells(2.0, 3.0, 1.0, 2.0, upper + 2, 3),
        ];
        let fix = [
            (1, Face::Bottom, Component::Y),
            (2, Face::Bottom, Component::Y),
            (1, Face::Left, Component::X),
            (2, Face::Right, Component::X),
            (3, Face::Left, Component::X),
            (5, Face::Right, Component::X),
        ];
        // The lower course of one material, stiffer than the upper one,
        // and its edges longer than the middle block's: both pairs under
        // that block then have one penalty κ (E_c and h_c of that block),
        // the same overlap, and the block stays level (any two penalties
        // would tilt it, with or without cut edges).
        let young = [3e9, 3e9, 2e9, 5e8, 1e9];
        let (model, report) = solve_blocks(&rects, &young, &fix, &[3, 4, 5], p);
        let (err, _) = uniform_stress_errors(&model, 5, p);
        for (k, e) in err.iter().enumerate() {
            assert!(*e <= 1e-9, "cells {lower}/{upper}: block {}: {e:e}", k + 1);
        }
        assert_eq!(report.active, report.elements, "cells {lower}/{upper}");
        assert!(
            (report.contact_length - 6.0).abs() < 1e-12,
            "cells {lower}/{upper}: ℓc = {}",
            report.contact_length
        );
    }
}

#[test]
fn the_contact_length_of_a_block_pressed_inside_a_wider_one_is_its_width() {
    // A block [0.3, 0.8] × [0, 0.25] (5 cells) pressed on [0, 1] × [−0.5, 0]
    // (8 cells: no node at 0.3 or 0.8): the edges of the lower block
    // across the upper one's ends face it over part of their length, and
    // ℓc counts that part only. Every element stays closed (a flat punch).
    // Before the clipping they counted whole: ℓc = 0.5625.
    let p = 1e6;
    let rects = [
        cells(0.0, 1.0, -0.5, 0.0, 8, 4),
        cells(0.3, 0.8, 0.0, 0.25, 5, 2),
    ];
    let fix = [
        (1, Face::Bottom, Component::Y),
        (1, Face::Left, Component::X),
        (2, Face::Left, Component::X),
    ];
    let (_, report) = solve_blocks(&rects, &[1e9, 2e9], &fix, &[2], p);
    assert_eq!(report.active, report.elements);
    assert!(
        (report.contact_length - 0.5).abs() < 1e-12,
        "ℓc = {}",
        report.contact_length
    );
}

#[test]
fn a_straight_side_is_cut_at_the_other_sides_end_across_any_gap() {
    // The block of the test above lifted by a gap g and pressed down onto
    // the wider one: ℓc = 0.5 at every gap. A first version of the
    // curvature slack took the sides' distance alone and stopped cutting
    // once g exceeded the overhang (0.05 here): ℓc 0.5625 at g = 0.2.
    for gap in [1e-3, 0.04, 0.2] {
        let rects = [
            cells(0.0, 1.0, -0.5, 0.0, 8, 4),
            cells(0.3, 0.8, gap, gap + 0.25, 5, 2),
        ];
        let mut model = blocks(&rects, None);
        for k in 1..=2 {
            let m = Material::new(1e9 * k as f64, 0.3, PlaneMode::Strain, "block").unwrap();
            model.set_material(k, m).unwrap();
        }
        model
            .fix_edges(block_tag(1, Face::Bottom), Component::Y, 0.0)
            .unwrap();
        model
            .fix_edges(block_tag(1, Face::Left), Component::X, 0.0)
            .unwrap();
        model
            .fix_edges(block_tag(2, Face::Left), Component::X, 0.0)
            .unwrap();
        model
            .fix_edges(block_tag(2, Face::Top), Component::Y, -gap - 1e-3)
            .unwrap();
        model
            .add_contact_pair(block_tag(1, Face::Top), block_tag(2, Face::Bottom))
            .unwrap();
        let report = model.solve_contact(&ContactOptions::default()).unwrap();
        assert_eq!(report.active, report.elements, "gap {gap}");
        assert!(
            (report.contact_length - 0.5).abs() < 1e-12,
            "gap {gap}: ℓc = {}",
            report.contact_length
        );
    }
}

#[test]
fn a_stack_tall_enough_to_lose_digits_is_warned_about_as_ill_conditioned() {
    // 3000 blocks of 4 cells across (54 k unknowns, solved whole: too many
    // interface unknowns to condense) under the default contact λ (the
    // model's size, 750): measured condition estimate 3.0e10, relative
    // residual 4.5e-8, stress error 1.9e-7 of p; warned. (300 blocks:
    // 7.9e6, silent; 3000 blocks of 16 cells: 5.9e11, error 3.7e-6 of p,
    // warned.)
    let stack = Stack::alternating(3000, 0.25, &[4]);
    let mut scene = stack.build().unwrap();
    let r = scene.solve(stack.p, &ContactOptions::default()).unwrap();
    let info = &r.report.info;
    assert!(info.condition_estimate > 1e10, "{info:?}");
    assert!(
        r.max_error > 1e-9 && r.max_error < 1e-5,
        "{:e}",
        r.max_error
    );
    let w = scene.model.warnings();
    assert!(
        w.iter().any(|w| w.starts_with("ill-conditioned system")),
        "{w:?}"
    );
}

#[test]
fn a_condensed_contact_solve_of_a_stiffness_contrast_is_warned_about_as_ill_conditioned() {
    // Four blocks 64 cells across, E alternating 1e10 and 1e18: the
    // interface (390 unknowns) is condensed; measured condition estimate
    // 1.0e13, stress error 8.2e-4 of p; warned (1e14 and 1e10: 1.0e9 and
    // 7.8e5, silent).
    let mut stack = Stack::alternating(4, 1.0, &[64]);
    for (k, layer) in stack.layers.iter_mut().enumerate() {
        layer.young = if k % 2 == 0 { 1e10 } else { 1e18 };
    }
    let mut scene = stack.build().unwrap();
    let r = scene.solve(stack.p, &ContactOptions::default()).unwrap();
    let info = &r.report.info;
    assert!(info.interface_unknowns > 0, "{info:?}");
    assert!(info.condition_estimate > 1e10, "{info:?}");
    let w = scene.model.warnings();
    assert!(
        w.iter().any(|w| w.starts_with("ill-conditioned system")),
        "{w:?}"
    );
}
