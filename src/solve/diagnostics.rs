//! What to tell the user when a system is singular or ill-conditioned:
//! which bodies move freely and how (translation, rotation), whether a
//! near-null mode is a free body or an extreme but legitimate stiffness
//! contrast, and how many digits an ill-conditioned result keeps.

use std::collections::BTreeMap;

use super::report::SolveInfo;
use crate::error::{Error, Status};
use crate::fem::assembly::{DofMap, NOT_FREE};
use crate::fem::element_loop::element_values;
use crate::fem::mesh::Mesh;
use crate::linalg::FactorError;

/// Energy of a fitted rigid motion, relative to the element-wise diagonal
/// energy, above which the motion is restrained: a free body gives ~1e-16
/// (round-off of B̂ applied to a rigid motion); a body held only by a soft
/// contact against a 1e12 times stiffer one still gives ~1e-12.
pub const RIGID_ENERGY_TOL: f64 = 1e-13;

/// The nodes of a body and their centroid.
fn body_nodes(mesh: &Mesh, body: i32) -> (Vec<usize>, [f64; 2]) {
    let nodes: Vec<usize> = (0..mesh.nodes().len())
        .filter(|&v| mesh.node_body()[v] == Some(body))
        .collect();
    let nn = nodes.len() as f64;
    let c = nodes.iter().fold([0.0, 0.0], |acc, &v| {
        [
            acc[0] + mesh.nodes()[v][0] / nn,
            acc[1] + mesh.nodes()[v][1] / nn,
        ]
    });
    (nodes, c)
}

/// The rigid motion (translation and rotation about the centroid) of each
/// body that best fits `mode` (over unknowns), zero on prescribed DOFs: a
/// global vector.
pub fn rigid_fit(mesh: &Mesh, dofs: &DofMap, mode: &[f64]) -> Vec<f64> {
    let n = mesh.nodes().len();
    let m = dofs.expand(mode, &vec![0.0; 2 * n]);
    let mut r = vec![0.0; 2 * n];
    for &body in mesh.bodies() {
        let (nodes, c) = body_nodes(mesh, body);
        let nn = nodes.len() as f64;
        let (mut t, mut rot, mut rr) = ([0.0, 0.0], 0.0, 0.0);
        for &v in &nodes {
            let (dx, dy) = (mesh.nodes()[v][0] - c[0], mesh.nodes()[v][1] - c[1]);
            t[0] += m[2 * v] / nn;
            t[1] += m[2 * v + 1] / nn;
            rot += dx * m[2 * v + 1] - dy * m[2 * v];
            rr += dx * dx + dy * dy;
        }
        let theta = if rr > 0.0 { rot / rr } else { 0.0 };
        for &v in &nodes {
            let (dx, dy) = (mesh.nodes()[v][0] - c[0], mesh.nodes()[v][1] - c[1]);
            for (k, value) in [t[0] - theta * dy, t[1] + theta * dx]
                .into_iter()
                .enumerate()
            {
                if dofs.free(2 * v + k) != NOT_FREE {
                    r[2 * v + k] = value;
                }
            }
        }
    }
    r
}

/// Adds rᵀ K_e r and Σ_a K_e[a][a] r_a² of one element to `acc` (`r` a
/// global vector).
pub fn add_energy(acc: &mut (f64, f64), ke: &[f64; 36], r: &[f64], tri: &[usize; 3]) {
    let re = element_values(r, tri);
    for a in 0..6 {
        let kr: f64 = (0..6).map(|b| ke[a * 6 + b] * re[b]).sum();
        acc.0 += re[a] * kr;
        acc.1 += ke[a * 6 + a].abs() * re[a] * re[a];
    }
}

/// The error of a failed factorisation, naming the unknown without
/// stiffness or the bodies of the near-null mode; `context` says where in
/// the solve it happened.
pub fn singular_error(mesh: &Mesh, dofs: &DofMap, e: FactorError, context: &str) -> Error {
    let free_to_global = dofs.free_to_global();
    match e {
        FactorError::Other(err) => err,
        FactorError::ZeroDiagonal { unknown } => {
            let g = free_to_global[unknown];
            let node = g / 2;
            Error::new(
                Status::Singular,
                format!(
                    "{} (body {}) has no stiffness in {}{context}",
                    mesh.node_name(node),
                    mesh.node_body()[node].unwrap_or_default(),
                    if g % 2 == 0 { "x" } else { "y" }
                ),
            )
        }
        FactorError::Singular { mode: None, .. } => Error::new(
            Status::Singular,
            format!("the stiffness matrix is indefinite{context}"),
        ),
        FactorError::Singular {
            mode: Some(mode), ..
        } => {
            let m = dofs.expand(&mode, &vec![0.0; 2 * mesh.nodes().len()]);
            Error::new(
                Status::Singular,
                format!(
                    "singular stiffness matrix: {}{context}",
                    describe_mode(mesh, &m)
                ),
            )
        }
    }
}

/// Warns when the scaled system is so ill-conditioned that results lose
/// digits (an extreme stiffness contrast or penalty).
pub fn conditioning_warning(info: &SolveInfo, warnings: &mut Vec<String>) {
    if info.condition_estimate > 1e10 || info.relative_residual > 1e-8 {
        warnings.push(format!(
            "ill-conditioned system: condition estimate {:.1e}, relative residual {:.1e}; \
             expect about {:.0} correct digits",
            info.condition_estimate,
            info.relative_residual,
            (-(info.condition_estimate * f64::EPSILON).log10()).clamp(0.0, 16.0)
        ));
    }
}

/// Names the bodies that move in a near-null mode `m` (a global vector)
/// and the kind of motion.
pub fn describe_mode(mesh: &Mesh, m: &[f64]) -> String {
    let mut share: BTreeMap<i32, f64> = BTreeMap::new();
    for (v, body) in mesh.node_body().iter().enumerate() {
        if let Some(b) = body {
            *share.entry(*b).or_default() += m[2 * v].powi(2) + m[2 * v + 1].powi(2);
        }
    }
    let total: f64 = share.values().sum();
    let mut ranked: Vec<(i32, f64)> = share
        .into_iter()
        .map(|(b, s)| (b, s / total.max(f64::MIN_POSITIVE)))
        .collect();
    ranked.sort_by(|a, b| b.1.total_cmp(&a.1));
    let top = ranked[0].1;
    let named: Vec<(i32, f64)> = ranked
        .into_iter()
        .filter(|&(_, s)| s >= 0.1 * top)
        .collect();
    // Three bodies at most: the message stays short.
    let mut parts = Vec::new();
    for &(body, _) in named.iter().take(3) {
        parts.push(format!(
            "body {body} is not restrained (free mode: {})",
            motion_kind(mesh, body, m)
        ));
    }
    if named.len() > 3 {
        parts.push(format!("and {} more bodies", named.len() - 3));
    }
    parts.join("; ")
}

/// The fractions of a body's motion in `m` that are rigid translations and
/// rotation about its centroid (three orthogonal modes), in words.
fn motion_kind(mesh: &Mesh, body: i32, m: &[f64]) -> String {
    let (nodes, c) = body_nodes(mesh, body);
    let nn = nodes.len() as f64;
    let (mut tx, mut ty, mut rot, mut rr, mut e) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &v in &nodes {
        let (dx, dy) = (mesh.nodes()[v][0] - c[0], mesh.nodes()[v][1] - c[1]);
        let (a, b) = (m[2 * v], m[2 * v + 1]);
        tx += a;
        ty += b;
        rot += -dy * a + dx * b;
        rr += dx * dx + dy * dy;
        e += a * a + b * b;
    }
    let fx = tx * tx / nn / e;
    let fy = ty * ty / nn / e;
    let fr = if rr > 0.0 { rot * rot / rr / e } else { 0.0 };
    if fx + fy + fr < 0.5 {
        return "a mechanism that is not a rigid motion".to_string();
    }
    let mut k = Vec::new();
    for (f, name) in [
        (fx, "translation in x"),
        (fy, "translation in y"),
        (fr, "rotation"),
    ] {
        if f >= 0.05 {
            k.push(format!("{:.0}% {name}", 100.0 * f));
        }
    }
    k.join(", ")
}
