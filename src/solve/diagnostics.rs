//! What to tell the user when a system is singular or ill-conditioned:
//! which bodies move freely and how (translation, rotation), whether a
//! near-null mode is a free body or an extreme but legitimate stiffness
//! contrast, and how many digits an ill-conditioned result keeps.

use std::collections::BTreeMap;

use super::report::SolveInfo;
use crate::error::{Error, Status};
use crate::fem::assembly::{DofMap, NOT_FREE};
use crate::fem::domain::Domain;
use crate::fem::element_loop::element_values;
use crate::linalg::FactorError;

/// Energy of a fitted rigid motion, relative to the element-wise diagonal
/// energy, above which the motion is restrained: a free body gives ~1e-16
/// (round-off of B̂ applied to a rigid motion); a body held only by a soft
/// contact against a 1e12 times stiffer one still gives ~1e-12.
pub const RIGID_ENERGY_TOL: f64 = 1e-13;

/// The nodes of a body and their centroid (z = 0 in the plane).
fn body_nodes(mesh: &dyn Domain, body: i32) -> (Vec<usize>, [f64; 3]) {
    let nodes: Vec<usize> = (0..mesh.n_nodes())
        .filter(|&v| mesh.node_body()[v] == Some(body))
        .collect();
    let nn = nodes.len() as f64;
    let mut c = [0.0; 3];
    for &v in &nodes {
        for (k, ck) in c.iter_mut().enumerate().take(mesh.dimension()) {
            *ck += mesh.coordinate(v, k) / nn;
        }
    }
    (nodes, c)
}

/// The position of node `v` relative to `c` (z = 0 in the plane).
fn relative(mesh: &dyn Domain, v: usize, c: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|k| match k < mesh.dimension() {
        true => mesh.coordinate(v, k) - c[k],
        false => 0.0,
    })
}

/// A body's motion `m` (a global vector) at its nodes reduced to what a
/// rigid motion about the centroid `c` sees: the mean translation, the
/// angular momentum L = Σ d × m and the inertia I = Σ |d|² 1 − d dᵀ (in
/// the plane, L and I are their z components).
struct Moments {
    translation: [f64; 3],
    /// Σ m over the nodes (nn times the translation, summed plainly).
    sum: [f64; 3],
    momentum: [f64; 3],
    inertia: [[f64; 3]; 3],
}

impl Moments {
    fn of(mesh: &dyn Domain, nodes: &[usize], c: &[f64; 3], m: &[f64]) -> Moments {
        let (dim, nn) = (mesh.dimension(), nodes.len() as f64);
        let mut r = Moments {
            translation: [0.0; 3],
            sum: [0.0; 3],
            momentum: [0.0; 3],
            inertia: [[0.0; 3]; 3],
        };
        for &v in nodes {
            let d = relative(mesh, v, c);
            let mv: [f64; 3] = std::array::from_fn(|k| if k < dim { m[dim * v + k] } else { 0.0 });
            for k in 0..dim {
                r.translation[k] += mv[k] / nn;
                r.sum[k] += mv[k];
            }
            if dim == 2 {
                r.momentum[2] += d[0] * mv[1] - d[1] * mv[0];
                r.inertia[2][2] += d[0] * d[0] + d[1] * d[1];
                continue;
            }
            let dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            for a in 0..3 {
                let (b, e) = ((a + 1) % 3, (a + 2) % 3);
                r.momentum[a] += d[b] * mv[e] - d[e] * mv[b];
                for (k, dk) in d.iter().enumerate() {
                    r.inertia[a][k] += if a == k { dd } else { 0.0 } - d[a] * dk;
                }
            }
        }
        r
    }

    /// The angular velocity ω = I⁻¹ L of the best-fitting rotation (zero
    /// when the inertia is singular: nodes on one line).
    fn omega(&self) -> [f64; 3] {
        let (i, l) = (&self.inertia, &self.momentum);
        if i[0][0] == 0.0 && i[1][1] == 0.0 {
            // The plane: about z only.
            return [0.0, 0.0, if i[2][2] > 0.0 { l[2] / i[2][2] } else { 0.0 }];
        }
        let det = i[0][0] * (i[1][1] * i[2][2] - i[1][2] * i[2][1])
            - i[0][1] * (i[1][0] * i[2][2] - i[1][2] * i[2][0])
            + i[0][2] * (i[1][0] * i[2][1] - i[1][1] * i[2][0]);
        let trace = i[0][0] + i[1][1] + i[2][2];
        if det.abs() <= 1e-12 * trace.powi(3) {
            return [0.0; 3];
        }
        // Cramer's rule on the symmetric 3×3 inertia.
        std::array::from_fn(|a| {
            let mut col = *i;
            for (row, la) in col.iter_mut().zip(l) {
                row[a] = *la;
            }
            (col[0][0] * (col[1][1] * col[2][2] - col[1][2] * col[2][1])
                - col[0][1] * (col[1][0] * col[2][2] - col[1][2] * col[2][0])
                + col[0][2] * (col[1][0] * col[2][1] - col[1][1] * col[2][0]))
                / det
        })
    }
}

/// The rigid motion (translation and rotation about the centroid) of each
/// body that best fits `mode` (over unknowns), zero on prescribed DOFs: a
/// global vector.
pub fn rigid_fit(mesh: &dyn Domain, dofs: &DofMap, mode: &[f64]) -> Vec<f64> {
    let (n, dim) = (mesh.n_nodes(), mesh.dimension());
    let m = dofs.expand(mode, &vec![0.0; dim * n]);
    let mut r = vec![0.0; dim * n];
    for &body in mesh.bodies() {
        let (nodes, c) = body_nodes(mesh, body);
        let moments = Moments::of(mesh, &nodes, &c, &m);
        let (t, w) = (moments.translation, moments.omega());
        for &v in &nodes {
            let d = relative(mesh, v, &c);
            // t + ω × d.
            let motion = [
                t[0] + (w[1] * d[2] - w[2] * d[1]),
                t[1] + (w[2] * d[0] - w[0] * d[2]),
                t[2] + (w[0] * d[1] - w[1] * d[0]),
            ];
            for (k, value) in motion.into_iter().enumerate().take(dim) {
                if dofs.free(dim * v + k) != NOT_FREE {
                    r[dim * v + k] = value;
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
pub fn singular_error(mesh: &dyn Domain, dofs: &DofMap, e: FactorError, context: &str) -> Error {
    let free_to_global = dofs.free_to_global();
    match e {
        FactorError::Other(err) => err,
        FactorError::ZeroDiagonal { unknown } => {
            let (g, dim) = (free_to_global[unknown], mesh.dimension());
            let node = g / dim;
            Error::new(
                Status::Singular,
                format!(
                    "{} (body {}) has no stiffness in {}{context}",
                    mesh.node_name(node),
                    mesh.node_body()[node].unwrap_or_default(),
                    ["x", "y", "z"][g % dim]
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
            let m = dofs.expand(&mode, &vec![0.0; mesh.dimension() * mesh.n_nodes()]);
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
pub fn describe_mode(mesh: &dyn Domain, m: &[f64]) -> String {
    let dim = mesh.dimension();
    let mut share: BTreeMap<i32, f64> = BTreeMap::new();
    for (v, body) in mesh.node_body().iter().enumerate() {
        if let Some(b) = body {
            *share.entry(*b).or_default() += (0..dim).map(|k| m[dim * v + k].powi(2)).sum::<f64>();
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
/// rotations about its centroid, in words.
fn motion_kind(mesh: &dyn Domain, body: i32, m: &[f64]) -> String {
    let (nodes, c) = body_nodes(mesh, body);
    let (nn, dim) = (nodes.len() as f64, mesh.dimension());
    let e: f64 = nodes
        .iter()
        .map(|&v| (0..dim).map(|k| m[dim * v + k].powi(2)).sum::<f64>())
        .sum();
    let moments = Moments::of(mesh, &nodes, &c, m);
    // The translations' share (Σ m)²/nn; the rotations' Lᵀ I⁻¹ L (L²/I in
    // the plane).
    let translation = moments.sum.map(|t| t * t / nn / e);
    let fr = match dim {
        2 => {
            let (l, i) = (moments.momentum[2], moments.inertia[2][2]);
            if i > 0.0 { l * l / i / e } else { 0.0 }
        }
        _ => {
            let w = moments.omega();
            (0..3).map(|a| w[a] * moments.momentum[a]).sum::<f64>() / e
        }
    };
    if translation.iter().sum::<f64>() + fr < 0.5 {
        return "a mechanism that is not a rigid motion".to_string();
    }
    let mut k = Vec::new();
    let named = [
        (translation[0], "translation in x"),
        (translation[1], "translation in y"),
        (translation[2], "translation in z"),
        (fr, "rotation"),
    ];
    for (f, name) in named {
        if f >= 0.05 {
            k.push(format!("{:.0}% {name}", 100.0 * f));
        }
    }
    k.join(", ")
}
