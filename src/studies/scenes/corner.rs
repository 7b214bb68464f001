//! A corner singularity with an exact elasticity solution: the L-shaped
//! domain [−1, 1]² without its quadrant x > 0, y < 0, and u = ∇φ with φ =
//! r^β sin βθ (θ ∈ [0, 3π/2]), β = 4/3. φ is harmonic, so u is
//! divergence-free and curl-free and the Navier equations hold with no body
//! force for any material: u = β r^(β−1) (sin (β−1)θ, cos (β−1)θ), whose
//! gradient ~ r^(−2/3) is singular at the re-entrant corner (finite energy).
//! u is prescribed on the whole boundary. Uniform meshes converge as
//! h^(1/3) = N^(−1/6) in energy; what adaptivity buys is measured
//! (tests/adaptive.rs, the report).

use std::f64::consts::PI;
use std::time::Instant;

use crate::error::Result;
use crate::fem::material::{Material, PlaneMode};
use crate::fem::mesh::Mesh;
use crate::fem::refine::Refinement;
use crate::model::adapt::dorfler;
use crate::model::{Component, Model};
use crate::studies::meshgen::MeshBuilder;
use crate::studies::verification::energy_error;

const BETA: f64 = 4.0 / 3.0;

/// The polar angle in [0, 2π).
fn angle(p: [f64; 2]) -> f64 {
    let t = p[1].atan2(p[0]);
    if t < 0.0 { t + 2.0 * PI } else { t }
}

/// The exact displacement at `p`.
pub fn displacement(p: [f64; 2]) -> [f64; 2] {
    let r = p[0].hypot(p[1]);
    if r == 0.0 {
        return [0.0; 2];
    }
    let (t, s) = (angle(p), BETA * r.powf(BETA - 1.0));
    [s * ((BETA - 1.0) * t).sin(), s * ((BETA - 1.0) * t).cos()]
}

/// The exact gradient [[∂u/∂x, ∂u/∂y], [∂v/∂x, ∂v/∂y]] at `p` (from
/// f'' = β(β−1) z^(β−2): u_x = Im f', u_y = Re f').
pub fn gradient(p: [f64; 2]) -> [[f64; 2]; 2] {
    let r = p[0].hypot(p[1]);
    if r == 0.0 {
        return [[0.0; 2]; 2];
    }
    let (t, s) = (angle(p), BETA * (BETA - 1.0) * r.powf(BETA - 2.0));
    let (im, re) = (s * ((BETA - 2.0) * t).sin(), s * ((BETA - 2.0) * t).cos());
    [[im, re], [re, -im]]
}

/// The L-shaped domain on a conforming grid of n × n cells per unit
/// square (three squares), split along "/".
pub fn l_shape(n: usize) -> MeshBuilder {
    let mut b = MeshBuilder::new();
    let m = 2 * n;
    let at = |i: usize| -1.0 + i as f64 / n as f64;
    let mut id = vec![vec![usize::MAX; m + 1]; m + 1];
    let inside = |i: usize, j: usize| !(at(i) > 1e-12 && at(j) < -1e-12);
    for (j, row) in id.iter_mut().enumerate() {
        for (i, v) in row.iter_mut().enumerate() {
            if inside(i, j) {
                *v = b.add_node([at(i), at(j)]);
            }
        }
    }
    for j in 0..m {
        for i in 0..m {
            // The cell's centre decides: the removed quadrant's cells go.
            let half = 0.5 / n as f64;
            if at(i) + half > 0.0 && at(j) + half < 0.0 {
                continue;
            }
            let (a, c) = (id[j][i], id[j + 1][i + 1]);
            let (bb, d) = (id[j][i + 1], id[j + 1][i]);
            b.triangles.push([a, bb, c]);
            b.triangles.push([a, c, d]);
            b.bodies.extend([1, 1]);
        }
    }
    b
}

/// One solve of the corner problem on `mesh`: its unknowns, energy error,
/// estimate (η) and seconds; the model for the next refinement.
pub struct CornerRun {
    /// The solved model.
    pub model: Model,
    /// Unknowns.
    pub unknowns: usize,
    /// ‖u − u_h‖_E.
    pub error: f64,
    /// The estimate η of it.
    pub estimate: f64,
    /// Seconds of the solve and the estimate.
    pub seconds: f64,
}

/// Solves on `mesh` with the exact u prescribed on its boundary (ν = 0.3,
/// E = 1, plane strain).
pub fn solve(mesh: Mesh) -> Result<CornerRun> {
    let material = Material::new(1.0, 0.3, PlaneMode::Strain, "body 1")?;
    let boundary = boundary_nodes(&mesh);
    let mut model = Model::new();
    model.set_mesh(mesh);
    model.set_material(1, material)?;
    for v in boundary {
        let u = displacement(model.mesh().expect("set").nodes()[v]);
        model.fix(v, Component::X, u[0])?;
        model.fix(v, Component::Y, u[1])?;
    }
    let t0 = Instant::now();
    let info = model.solve()?;
    let estimate = model.error_estimate()?.global;
    let seconds = t0.elapsed().as_secs_f64();
    let uh: Vec<f64> = model.displacements()?.concat();
    let mesh = model.mesh().expect("set");
    let error = energy_error(mesh, &uh, &material.d_matrix(), gradient);
    Ok(CornerRun {
        unknowns: info.unknowns,
        error,
        estimate,
        seconds,
        model,
    })
}

/// Adapts from the grid of `n` cells per unit until `max_unknowns`: each
/// cycle solves, marks by Dörfler (θ = ½) and bisects; the boundary data
/// of new nodes are the exact u (not interpolated: it is singular at the
/// corner). Every cycle's run.
pub fn adapt(n: usize, max_unknowns: usize) -> Result<Vec<CornerRun>> {
    let mesh = l_shape(n).build()?;
    let mut refinement = Refinement::new(&mesh);
    let mut runs = vec![solve(mesh)?];
    while runs.last().expect("a run").unknowns < max_unknowns {
        let last = runs.last().expect("a run");
        let est = last.model.error_estimate()?;
        let marked = dorfler(&est.squared, 0.5);
        let mesh = last.model.mesh().expect("set");
        let refined = refinement.refine(mesh, &marked)?;
        runs.push(solve(refined.mesh)?);
    }
    Ok(runs)
}

fn boundary_nodes(mesh: &Mesh) -> Vec<usize> {
    let mut count = std::collections::HashMap::new();
    for t in mesh.triangles() {
        for k in 0..3 {
            let (p, q) = (t[k], t[(k + 1) % 3]);
            *count.entry((p.min(q), p.max(q))).or_insert(0) += 1;
        }
    }
    let mut nodes: Vec<usize> = count
        .into_iter()
        .filter(|(_, c)| *c == 1)
        .flat_map(|((p, q), _)| [p, q])
        .collect();
    nodes.sort_unstable();
    nodes.dedup();
    nodes
}
