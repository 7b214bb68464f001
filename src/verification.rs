//! Tools to verify a discretisation against known solutions: a quadrature
//! rule, consistent nodal loads of a body-force field, and error norms.

use crate::element::TriGeometry;
use crate::mesh::Mesh;

/// Barycentric coordinates of a degree-4 rule on triangles (Dunavant, 6 points).
pub const QUAD_POINTS: [[f64; 3]; 6] = [
    [0.108_103_018_168_070, 0.445_948_490_915_965, 0.445_948_490_915_965],
    [0.445_948_490_915_965, 0.108_103_018_168_070, 0.445_948_490_915_965],
    [0.445_948_490_915_965, 0.445_948_490_915_965, 0.108_103_018_168_070],
    [0.816_847_572_980_459, 0.091_576_213_509_771, 0.091_576_213_509_771],
    [0.091_576_213_509_771, 0.816_847_572_980_459, 0.091_576_213_509_771],
    [0.091_576_213_509_771, 0.091_576_213_509_771, 0.816_847_572_980_459],
];

/// Weights of [`QUAD_POINTS`], summing to 1 (multiply by the area).
pub const QUAD_WEIGHTS: [f64; 6] = [
    0.223_381_589_678_011,
    0.223_381_589_678_011,
    0.223_381_589_678_011,
    0.109_951_743_655_322,
    0.109_951_743_655_322,
    0.109_951_743_655_322,
];

fn point(x: &[[f64; 2]; 3], q: &[f64; 3]) -> [f64; 2] {
    [
        q[0] * x[0][0] + q[1] * x[1][0] + q[2] * x[2][0],
        q[0] * x[0][1] + q[1] * x[1][1] + q[2] * x[2][1],
    ]
}

/// Consistent nodal forces ∫ b φ_i of a body-force field over the mesh
/// (flat and inverted triangles carry no area).
pub fn nodal_loads(mesh: &Mesh, body_force: impl Fn([f64; 2]) -> [f64; 2]) -> Vec<[f64; 2]> {
    let mut f = vec![[0.0; 2]; mesh.nodes().len()];
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.max(0.0);
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let b = body_force(point(&x, q));
            for a in 0..3 {
                f[tri[a]][0] += w * area * b[0] * q[a];
                f[tri[a]][1] += w * area * b[1] * q[a];
            }
        }
    }
    f
}

/// L2 norm of (exact − discrete) for a P1 field with `ncomp` components per
/// node stored node-major in `uh`.
pub fn l2_error(mesh: &Mesh, uh: &[f64], ncomp: usize, exact: impl Fn([f64; 2]) -> Vec<f64>) -> f64 {
    let mut sum = 0.0;
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let area = 0.5 * TriGeometry::new(&x).j.abs();
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let ex = exact(point(&x, q));
            for c in 0..ncomp {
                let v: f64 = (0..3).map(|a| q[a] * uh[ncomp * tri[a] + c]).sum();
                sum += w * area * (ex[c] - v).powi(2);
            }
        }
    }
    sum.sqrt()
}

/// H1 seminorm of (exact − discrete): sqrt(∫ |∇u − ∇u_h|²), with the exact
/// gradient given as [∂u_c/∂x, ∂u_c/∂y] per component. Triangles with
/// J <= 0 have no area and are skipped.
pub fn h1_error(
    mesh: &Mesh,
    uh: &[f64],
    ncomp: usize,
    exact_grad: impl Fn([f64; 2]) -> Vec<[f64; 2]>,
) -> f64 {
    let mut sum = 0.0;
    for tri in mesh.triangles() {
        let x = mesh.corners(tri);
        let geo = TriGeometry::new(&x);
        if geo.j <= 0.0 {
            continue;
        }
        let area = 0.5 * geo.j;
        let grads: Vec<[f64; 2]> = (0..ncomp)
            .map(|c| {
                let mut g = [0.0; 2];
                for a in 0..3 {
                    let ua = uh[ncomp * tri[a] + c];
                    g[0] += geo.g[a][0] * ua / geo.j;
                    g[1] += geo.g[a][1] * ua / geo.j;
                }
                g
            })
            .collect();
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let ex = exact_grad(point(&x, q));
            for c in 0..ncomp {
                sum += w * area * ((ex[c][0] - grads[c][0]).powi(2) + (ex[c][1] - grads[c][1]).powi(2));
            }
        }
    }
    sum.sqrt()
}

/// Least-squares slope of log(e) against log(h): the observed convergence
/// rate.
pub fn fitted_rate(h: &[f64], e: &[f64]) -> f64 {
    let n = h.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = h.iter().zip(e).map(|(a, b)| (a.ln(), b.ln())).unzip();
    let mx = lx.iter().sum::<f64>() / n;
    let my = ly.iter().sum::<f64>() / n;
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadrature_integrates_quartics_exactly() {
        // ∫ over the unit right triangle of x^4 = 1/30 and x^2 y^2 = 1/180.
        let x = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let (mut a, mut b) = (0.0, 0.0);
        for (q, w) in QUAD_POINTS.iter().zip(QUAD_WEIGHTS) {
            let p = point(&x, q);
            a += 0.5 * w * p[0].powi(4);
            b += 0.5 * w * p[0].powi(2) * p[1].powi(2);
        }
        assert!((a - 1.0 / 30.0).abs() < 1e-13, "{a}");
        assert!((b - 1.0 / 180.0).abs() < 1e-13, "{b}");
    }

    #[test]
    fn fitted_rate_of_exact_power_law() {
        let h = [0.1, 0.05, 0.025];
        let e: Vec<f64> = h.iter().map(|h: &f64| 3.0 * h.powi(2)).collect();
        assert!((fitted_rate(&h, &e) - 2.0).abs() < 1e-12);
    }
}
