//! Frictionless contact through the mesh of the gap in three dimensions, as
//! a study (docs/method.md §9, stage 3): two blocks of tempered
//! tetrahedra ([`TetMesh::stacked`]) and B, the layer of flat tetrahedra
//! between them, each switched on where it would invert — K = (E_c/(6T_e))
//! w wᵀ ([`crate::fem::tet::contact_stiffness`]) with the tie's T_e =
//! A_e h_c²/λ — by a primal active-set loop.
//!
//! This answers the method's question in 3D with measurements (the contact
//! patch test, the seed scene in 3D). Two loops solve it
//! ([`ContactLoop`]): the study's own primal loop, an independent
//! prototype, and the product's active-set loop with B's tetrahedra as its
//! third kind of constraint ([`crate::solve::solid`]: the interface
//! condensed where that pays); the tests hold the one to the other.

use std::time::Instant;

use super::tet_assembly::{
    analyse, block_stress_error, face_triangles, factorize, largest_face, lift, outward,
    unknowns_of,
};
use super::tetmesh::{LAYER, LOWER, TetMesh, UPPER};
use crate::contact::ContactOptions;
use crate::contact::gap_tets::{GapData, GapTetrahedron, GapTets};
use crate::error::{Error, Result, Status};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::domain::SolidNodes;
use crate::fem::element::Tempering;
use crate::fem::tet::{TetGeometry, contact_stiffness, gap_weights, isotropic_d, stiffness};
use crate::linalg::ordering::Ordering;
use crate::solve::report::Timings;
use crate::solve::solid::{SolidSystem, solve_gap_contact};

/// Which active-set loop solves a [`TetContactProblem`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactLoop {
    /// The study's own primal loop: every solve refactorises (the
    /// prototype the product is checked against).
    Study,
    /// The product's loop over B's tetrahedra as constraints
    /// ([`solve_gap_contact`]): the interface condensed into one
    /// factorisation where that pays, else refactorised per solve.
    Product,
}

/// A contact problem between the two blocks of a stacked mesh.
pub struct TetContactProblem<'a> {
    /// The mesh: parts [`LOWER`], [`UPPER`] and the layer B.
    pub mesh: &'a TetMesh,
    /// Young's modulus and Poisson's ratio of the lower and upper blocks.
    pub materials: [(f64, f64); 2],
    /// The interface's length h_c of the tie (its shortest edge).
    pub h_c: f64,
    /// The length λ of the tie.
    pub lambda: f64,
    /// The blocks' tempering (the model size as λ).
    pub tempering: Tempering,
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// The loop that solves it.
    pub contact_loop: ContactLoop,
    /// The displacement components prescribed at a node of a block (part,
    /// position), `None` where free: asked of every node, those inside a
    /// block and on the interface too.
    pub fixed: &'a dyn Fn(usize, [f64; 3]) -> [Option<f64>; 3],
    /// The traction on a boundary face of a block (part, centroid,
    /// outward unit normal).
    pub traction: &'a dyn Fn(usize, [f64; 3], [f64; 3]) -> [f64; 3],
}

/// The solution of a [`TetContactProblem`].
#[derive(Debug, Clone)]
pub struct TetContact {
    /// Three displacements per node.
    pub u: Vec<f64>,
    /// Whether each tetrahedron of B is switched on (by index in the mesh;
    /// false for the blocks').
    pub active: Vec<bool>,
    /// The consistent nodal forces of the tractions (three per node).
    pub loads: Vec<f64>,
    /// The force B exerts on the upper block: minus the active
    /// tetrahedra's internal forces at the upper block's nodes.
    pub transmitted: [f64; 3],
    /// The area of the interface in contact: each active tetrahedron of B
    /// stands for a third of its prism's triangle (projected).
    pub contact_area: f64,
    /// The contact pressure at each upper node of the interface: the
    /// normal force of its pair's tetrahedra over its tributary area (a
    /// third of each prism it belongs to).
    pub pressures: Vec<(usize, f64)>,
    /// Active-set iterations.
    pub iterations: usize,
    /// Numeric factorisations.
    pub factorizations: usize,
    /// Unknowns of the condensed interface (0: not condensed).
    pub interface_unknowns: usize,
    /// Unknowns.
    pub unknowns: usize,
    /// Entries of the Cholesky factor.
    pub factor_nnz: usize,
    /// Bytes one numeric factorisation needs at its peak (the factor, its
    /// structure and workspace; the product's loop only, else 0).
    pub factorization_bytes: usize,
    /// The time of each phase: the bodies' assembly (and, in the product's
    /// loop, B's switches), the analysis, the factorisations, the solves and
    /// the condensed interface's dense work.
    pub timings: Timings,
    /// Seconds of the whole solve.
    pub seconds: f64,
}

impl TetContact {
    /// The work of the loads, Σ f·u.
    pub fn compliance(&self) -> f64 {
        self.loads.iter().zip(&self.u).map(|(f, u)| f * u).sum()
    }
}

/// B as the loop sees it: each tetrahedron's index, gap weights, initial
/// gap J0 and matrix, and the scale E_c/(6T_e) of its force.
struct Layer {
    elements: Vec<usize>,
    /// The projected prism triangle's area of each.
    areas: Vec<f64>,
    weights: Vec<[f64; 12]>,
    initial: Vec<f64>,
    scales: Vec<f64>,
    matrices: Vec<Vec<f64>>,
}

impl Layer {
    /// B's tetrahedra of `mesh`, measured on their projection onto a plane
    /// z = const (flat, as the method builds B on touching surfaces), the
    /// differences of their nodes' heights their initial gap (J0 does not
    /// depend on the plane: Σ_k a_k = 0).
    fn new(problem: &TetContactProblem<'_>, e_c: f64) -> Result<Layer> {
        let mesh = problem.mesh;
        let mut layer = Layer {
            elements: Vec::new(),
            areas: Vec::new(),
            weights: Vec::new(),
            initial: Vec::new(),
            scales: Vec::new(),
            matrices: Vec::new(),
        };
        for (e, t) in mesh.tets.iter().enumerate() {
            if mesh.parts[e] != LAYER {
                continue;
            }
            let flat = t.map(|v| {
                let [x, y, _] = mesh.nodes[v];
                [x, y, 0.0]
            });
            let geo = TetGeometry::new(&flat);
            let w = gap_weights(&geo, [0.0, 0.0, 1.0]);
            let j0: f64 = (0..12)
                .map(|i| w[i] * (mesh.nodes[t[i / 3]][i % 3] - flat[i / 3][i % 3]))
                .sum();
            let t_e = largest_face(&geo) * problem.h_c * problem.h_c / problem.lambda;
            let k = contact_stiffness(&w, e_c, t_e)?;
            layer.elements.push(e);
            layer.areas.push(largest_face(&geo));
            layer.weights.push(w);
            layer.initial.push(j0);
            layer.scales.push(e_c / (6.0 * t_e));
            layer.matrices.push(k.iter().flatten().copied().collect());
        }
        Ok(layer)
    }

    /// The gap J0 + w·u of element i (negative: an overlap).
    fn gap(&self, i: usize, t: &[usize; 4], u: &[f64]) -> f64 {
        let w = &self.weights[i];
        self.initial[i] + (0..12).map(|k| w[k] * u[3 * t[k / 3] + k % 3]).sum::<f64>()
    }
}

/// The blocks assembled once, and what every solve adds to.
struct System {
    dofs: DofMap,
    pattern: Pattern,
    base: Vec<f64>,
    rhs: Vec<f64>,
    prescribed: Vec<f64>,
    loads: Vec<f64>,
    layer: Layer,
}

/// Solves the contact problem: the blocks assembled once, then solves with
/// the active tetrahedra of B added, each switched on while its gap
/// J0 + Σ w_k·u_k is not positive (an overlap, or touching: a body held
/// only where it touches, unloaded, keeps that hold) and off while it
/// opens, from
/// those touching at rest on (J0 ≤ 0), until the set repeats (at most 50
/// solves).
pub fn solve_contact(problem: &TetContactProblem<'_>) -> Result<TetContact> {
    problem.mesh.check_stacked()?;
    let t0 = Instant::now();
    let system = assemble(problem)?;
    let assembly = t0.elapsed().as_secs_f64();
    let mesh = problem.mesh;
    let solved = match problem.contact_loop {
        ContactLoop::Study => active_set(&system, problem)?,
        ContactLoop::Product => product_loop(&system, problem)?,
    };
    let Solved {
        u,
        active,
        iterations,
        factorizations,
        interface_unknowns,
        factor_nnz,
        factorization_bytes,
        mut timings,
    } = solved;
    timings.assembly += assembly;
    timings.total = t0.elapsed().as_secs_f64();
    let mut on = vec![false; mesh.tets.len()];
    let mut transmitted = [0.0; 3];
    let upper = upper_nodes(mesh);
    let layer = &system.layer;
    // Per upper node: tributary area and normal force.
    let mut pair = std::collections::BTreeMap::<usize, (f64, f64)>::new();
    for (i, &e) in layer.elements.iter().enumerate() {
        on[e] = active[i];
        let t = &mesh.tets[e];
        // Its force on its nodes is scale·g·w; on the upper block minus that.
        let force = if active[i] {
            layer.scales[i] * layer.gap(i, t, &u)
        } else {
            0.0
        };
        for r in 0..12 {
            let w = layer.weights[i][r];
            if upper[t[r / 3]] {
                transmitted[r % 3] -= force * w;
                if r % 3 == 2 && w != 0.0 {
                    let entry = pair.entry(t[r / 3]).or_insert((0.0, 0.0));
                    entry.0 += w.abs() / 6.0;
                    entry.1 -= force * w;
                }
            }
        }
    }
    let contact_area = (0..layer.elements.len())
        .filter(|&i| active[i])
        .map(|i| layer.areas[i] / 3.0)
        .sum();
    let pressures = (pair.into_iter())
        .map(|(v, (area, force))| (v, force / area))
        .collect();
    Ok(TetContact {
        u,
        active: on,
        loads: system.loads,
        transmitted,
        contact_area,
        pressures,
        iterations,
        factorizations,
        interface_unknowns,
        unknowns: system.dofs.n_free(),
        factor_nnz,
        factorization_bytes,
        timings,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// The pattern of blocks and B, its analysis, the blocks' values and the
/// loads.
fn assemble(problem: &TetContactProblem<'_>) -> Result<System> {
    let mesh = problem.mesh;
    let n = mesh.nodes.len();
    let (prescribed, fixed, loads) = boundary(problem)?;
    let dofs = DofMap::new(n, 3, |g| !fixed[g]);
    let pattern = Pattern::build(&dofs, n, &face_triangles(mesh));
    let mut base = vec![0.0; pattern.nnz()];
    let mut rhs = vec![0.0; dofs.n_free()];
    for (f, &g) in dofs.free_to_global().iter().enumerate() {
        rhs[f] = loads[g];
    }
    let size = mesh.size();
    let d = [
        isotropic_d(problem.materials[0].0, problem.materials[0].1)?,
        isotropic_d(problem.materials[1].0, problem.materials[1].1)?,
    ];
    for (e, t) in mesh.tets.iter().enumerate() {
        if mesh.parts[e] == LAYER {
            continue;
        }
        let geo = TetGeometry::new(&t.map(|v| mesh.nodes[v]));
        let jmin = problem.tempering.jmin_tet(&geo, size);
        let k = stiffness(&geo, &d[mesh.parts[e]], jmin).map_err(|err| {
            Error::new(err.status(), format!("tetrahedron {e}: {}", err.message()))
        })?;
        let unknowns = unknowns_of(&dofs, t);
        let ke: Vec<f64> = k.iter().flatten().copied().collect();
        pattern.add_element(&mut base, &unknowns, &ke);
        lift(&mut rhs, &unknowns, t, &ke, &prescribed);
    }
    let e_c = problem.materials[0].0.min(problem.materials[1].0);
    Ok(System {
        dofs,
        pattern,
        base,
        rhs,
        prescribed,
        loads,
        layer: Layer::new(problem, e_c)?,
    })
}

/// What a loop settled in: the displacements, B's final set (by layer
/// element), the iterations, the factorisations, the condensed interface
/// and the factor's size.
struct Solved {
    u: Vec<f64>,
    active: Vec<bool>,
    iterations: usize,
    factorizations: usize,
    interface_unknowns: usize,
    factor_nnz: usize,
    factorization_bytes: usize,
    timings: Timings,
}

/// The primal active-set loop of the study, refactorising every solve.
fn active_set(system: &System, problem: &TetContactProblem<'_>) -> Result<Solved> {
    let (layer, mesh) = (&system.layer, problem.mesh);
    let mut timings = Timings::default();
    let t0 = Instant::now();
    let mut chol = analyse(&system.pattern, &system.dofs, mesh, problem.ordering)?;
    timings.analysis = t0.elapsed().as_secs_f64();
    // From the touching elements on (every one on touching surfaces).
    let mut active: Vec<bool> = layer.initial.iter().map(|&j0| j0 <= 0.0).collect();
    for iterations in 1..=50 {
        let mut values = system.base.clone();
        let mut b = system.rhs.clone();
        for (i, &e) in layer.elements.iter().enumerate() {
            if active[i] {
                let t = &mesh.tets[e];
                let unknowns = unknowns_of(&system.dofs, t);
                system
                    .pattern
                    .add_element(&mut values, &unknowns, &layer.matrices[i]);
                lift(&mut b, &unknowns, t, &layer.matrices[i], &system.prescribed);
                // The initial gap's load, −scale·J0·w.
                for (k, &row) in unknowns.iter().enumerate() {
                    if row != NOT_FREE {
                        b[row] -= layer.scales[i] * layer.initial[i] * layer.weights[i][k];
                    }
                }
            }
        }
        let t0 = Instant::now();
        factorize(&mut chol, &system.pattern, &values, "the 3D contact system")?;
        timings.factorization += t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        chol.solve(&mut b)?;
        timings.solve += t0.elapsed().as_secs_f64();
        let mut u = system.prescribed.clone();
        for (f, &g) in system.dofs.free_to_global().iter().enumerate() {
            u[g] = b[f];
        }
        if let Some(g) = u.iter().position(|x| !x.is_finite()) {
            return Err(Error::new(
                Status::Internal,
                format!("the 3D contact study's displacement {g} is not finite"),
            ));
        }
        let next: Vec<bool> = (layer.elements.iter().enumerate())
            .map(|(i, &e)| layer.gap(i, &mesh.tets[e], &u) <= 0.0)
            .collect();
        if next == active {
            return Ok(Solved {
                u,
                active,
                iterations,
                factorizations: iterations,
                interface_unknowns: 0,
                factor_nnz: chol.factor_nnz(),
                factorization_bytes: 0,
                timings,
            });
        }
        active = next;
    }
    Err(Error::new(
        Status::NotConverged,
        "the 3D contact study's active set did not settle in 50 solves",
    ))
}

/// The product's loop ([`solve_gap_contact`]) on the study's assembly:
/// B's tetrahedra as its constraints, with the tie the study's layer has.
fn product_loop(system: &System, problem: &TetContactProblem<'_>) -> Result<Solved> {
    let mesh = problem.mesh;
    let body: Vec<Option<i32>> = (mesh.parts.iter())
        .map(|&p| (p != LAYER).then_some(p as i32))
        .collect();
    let nodes = SolidNodes::new(mesh.nodes.clone(), &mesh.tets, &body)?;
    let layer = &system.layer;
    let elements: Vec<GapTetrahedron> = (layer.elements.iter())
        .map(|&e| GapTetrahedron {
            nodes: mesh.tets[e],
            normal: [0.0, 0.0, 1.0],
        })
        .collect();
    let e_c = problem.materials[0].0.min(problem.materials[1].0);
    let dofs = &system.dofs;
    let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
    let data = GapData {
        points: &mesh.nodes,
        moduli: &vec![e_c; elements.len()],
        h_c: &vec![problem.h_c; elements.len()],
        lambda: problem.lambda,
        equation: &equation,
        prescribed: &system.prescribed,
    };
    let gap = GapTets::new(&elements, &data)?;
    // The bodies' energy of a global vector, over its unknowns.
    let energy = |r: &[f64]| {
        let x = dofs.gather(r);
        let mut kx = vec![0.0; x.len()];
        system.pattern.sym_mul(&system.base, &x, &mut kx);
        // The diagonal ends each column of the upper triangle.
        let diag: f64 = (0..x.len())
            .map(|i| system.base[system.pattern.col_ptr()[i + 1] - 1].abs() * x[i] * x[i])
            .sum();
        (x.iter().zip(&kx).map(|(a, b)| a * b).sum(), diag)
    };
    let solid = SolidSystem {
        nodes: &nodes,
        dofs,
        pattern: &system.pattern,
        values: system.base.clone(),
        rhs: system.rhs.clone(),
        prescribed: &system.prescribed,
        body_energy: &energy,
    };
    let r = solve_gap_contact(solid, gap, &ContactOptions::default(), problem.ordering)?;
    Ok(Solved {
        u: r.u,
        active: r.active,
        iterations: r.history.len(),
        factorizations: r.info.factorizations,
        interface_unknowns: r.info.interface_unknowns,
        factor_nnz: r.info.factor_nnz,
        factorization_bytes: r.info.factorization_bytes,
        timings: r.info.timings,
    })
}

/// Whether each node belongs to the upper block.
fn upper_nodes(mesh: &TetMesh) -> Vec<bool> {
    let mut upper = vec![false; mesh.nodes.len()];
    for (e, t) in mesh.tets.iter().enumerate() {
        if mesh.parts[e] == UPPER {
            t.iter().for_each(|&v| upper[v] = true);
        }
    }
    upper
}

/// The prescribed values and flags (per DOF) and the consistent loads of
/// the tractions.
fn boundary(problem: &TetContactProblem<'_>) -> Result<(Vec<f64>, Vec<bool>, Vec<f64>)> {
    let mesh = problem.mesh;
    let n = mesh.nodes.len();
    let mut prescribed = vec![0.0; 3 * n];
    let mut fixed = vec![false; 3 * n];
    let mut loads = vec![0.0; 3 * n];
    // Every node of a block, those on the interface too (a rigid tool's).
    let mut part_of = vec![None; n];
    for (t, &p) in mesh.tets.iter().zip(&mesh.parts) {
        if p == LOWER || p == UPPER {
            t.iter().for_each(|&v| part_of[v] = Some(p));
        }
    }
    for (v, part) in part_of.into_iter().enumerate() {
        let Some(part) = part else { continue };
        for (c, value) in (problem.fixed)(part, mesh.nodes[v]).into_iter().enumerate() {
            if let Some(x) = value {
                prescribed[3 * v + c] = x;
                fixed[3 * v + c] = true;
            }
        }
    }
    for (e, f) in mesh.boundary_faces() {
        let part = mesh.parts[e];
        if part != LOWER && part != UPPER {
            continue;
        }
        let inside = (mesh.tets[e].iter())
            .find(|v| !f.contains(v))
            .expect("a fourth node");
        let (unit, area, centroid) = outward(f.map(|v| mesh.nodes[v]), mesh.nodes[*inside]);
        let t = (problem.traction)(part, centroid, unit);
        if t.iter().any(|c| !c.is_finite()) {
            return Err(Error::argument(format!(
                "a traction on tetrahedron {e}'s face is not finite"
            )));
        }
        for &v in &f {
            (0..3).for_each(|c| loads[3 * v + c] += t[c] * area / 3.0);
        }
    }
    Ok((prescribed, fixed, loads))
}

/// What the 3D contact patch test measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPatch {
    /// The largest error of a block tetrahedron's stress, over p.
    pub stress_error: f64,
    /// The largest deviation of a facing pair's normal overlap from their
    /// mean, over the mean.
    pub overlap_spread: f64,
    /// Whether every tetrahedron of B is on.
    pub all_active: bool,
}

/// The contact patch test in 3D on a stacked mesh of the unit square's
/// blocks (lower z < 0, upper z > 0): the upper block's top pressed by a
/// uniform pressure `p`, the lower block's bottom on rollers (u_z = 0),
/// the planes x = 0 and y = 0 of both on rollers; Young's moduli `young`
/// (lower, upper), Poisson's ratio `poisson`. Exact: σ = −p e_z ⊗ e_z in
/// every block tetrahedron, the blocks sliding on each other as their
/// Poisson expansions differ, one uniform overlap.
pub fn contact_patch_test(
    mesh: &TetMesh,
    young: [f64; 2],
    poisson: f64,
    p: f64,
) -> Result<ContactPatch> {
    mesh.check_stacked()?;
    let bottom = (mesh.nodes.iter()).fold(f64::INFINITY, |m, x| m.min(x[2]));
    let top = (mesh.nodes.iter()).fold(f64::NEG_INFINITY, |m, x| m.max(x[2]));
    let h_c = shortest_interface_edge(mesh);
    let r = solve_contact(&TetContactProblem {
        mesh,
        materials: [(young[0], poisson), (young[1], poisson)],
        h_c,
        lambda: 1.0,
        tempering: Tempering::Auto,
        ordering: Ordering::Auto,
        contact_loop: ContactLoop::Product,
        fixed: &|_, x| {
            [
                (x[0] == 0.0).then_some(0.0),
                (x[1] == 0.0).then_some(0.0),
                (x[2] == bottom).then_some(0.0),
            ]
        },
        traction: &|_, c, n| {
            if c[2] == top && n[2] > 0.5 {
                [0.0, 0.0, -p]
            } else {
                [0.0; 3]
            }
        },
    })?;
    let d = [
        isotropic_d(young[0], poisson)?,
        isotropic_d(young[1], poisson)?,
    ];
    let target = [0.0, 0.0, -p, 0.0, 0.0, 0.0];
    let stress_error = block_stress_error(mesh, &r.u, &d, &target, p)?;
    let overlaps: Vec<f64> = mesh
        .facing_pairs()
        .into_iter()
        .map(|(a, b)| r.u[3 * a + 2] - r.u[3 * b + 2])
        .collect();
    let mean = overlaps.iter().sum::<f64>() / overlaps.len().max(1) as f64;
    let spread = overlaps
        .iter()
        .map(|o| (o - mean).abs())
        .fold(0.0, f64::max);
    Ok(ContactPatch {
        stress_error,
        overlap_spread: spread / mean.abs(),
        all_active: (0..mesh.tets.len()).all(|e| mesh.parts[e] != LAYER || r.active[e]),
    })
}

/// The shortest edge of the interface's triangles (h_c).
pub fn shortest_interface_edge(mesh: &TetMesh) -> f64 {
    let mut shortest = f64::INFINITY;
    for (e, t) in mesh.tets.iter().enumerate() {
        if mesh.parts[e] != LAYER {
            continue;
        }
        for i in 0..4 {
            for j in i + 1..4 {
                let (p, q) = (mesh.nodes[t[i]], mesh.nodes[t[j]]);
                let l = (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>().sqrt();
                if l > 0.0 {
                    shortest = shortest.min(l);
                }
            }
        }
    }
    shortest
}
