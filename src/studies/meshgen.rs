//! A small structured triangulator: rectangular grids split into triangles,
//! strips between two rows of nodes, and boundary-edge extraction. It meshes
//! the seed scene and the verification problems with nothing but cargo.

use std::collections::HashMap;

use crate::error::{Error, Result};
use crate::fem::mesh::Mesh;

/// How each grid cell is split into two triangles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Diagonal {
    /// Along the cell's "/" diagonal.
    Forward,
    /// Along "/" left of `x`, "\" right of it: the mesh is mirror-symmetric
    /// about the vertical line `x` when the grid is.
    MirroredAt(f64),
}

/// Most points a 1D subdivision may have (a guard against a mistyped h
/// asking for an unbounded allocation).
pub const MAX_POINTS: f64 = 1e8;

/// Checks a < b finite and 0 < h with at most [`MAX_POINTS`] points.
fn check_interval(a: f64, b: f64, h: f64) -> Result<()> {
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Err(Error::argument(format!(
            "subdivision: need finite a < b (got a = {a}, b = {b})"
        )));
    }
    if !(h > 0.0 && (b - a) / h <= MAX_POINTS) {
        return Err(Error::argument(format!(
            "subdivision: spacing h = {h} must be > 0 and give at most {MAX_POINTS:e} points on [{a}, {b}]"
        )));
    }
    Ok(())
}

/// Points from `a` to `b` with spacing at most `h`, passing through every
/// breakpoint in `stops` (sorted, strictly inside (a, b)). Fails with
/// `INVALID_ARGUMENT` unless a < b and 0 < h (and the count is bounded).
pub fn subdivide(a: f64, b: f64, stops: &[f64], h: f64) -> Result<Vec<f64>> {
    check_interval(a, b, h)?;
    let mut knots = vec![a];
    knots.extend(stops.iter().copied().filter(|&s| s > a && s < b));
    knots.push(b);
    let mut out = vec![a];
    for w in knots.windows(2) {
        let n = ((w[1] - w[0]) / h - 1e-9).ceil().max(1.0) as usize;
        for k in 1..=n {
            out.push(if k == n {
                w[1]
            } else {
                w[0] + (w[1] - w[0]) * k as f64 / n as f64
            });
        }
    }
    Ok(out)
}

/// Like [`subdivide`] but exactly mirror-symmetric about (a + b) / 2 (which
/// is always a node).
pub fn subdivide_symmetric(a: f64, b: f64, stops: &[f64], h: f64) -> Result<Vec<f64>> {
    let mid = 0.5 * (a + b);
    let left: Vec<f64> = stops
        .iter()
        .copied()
        .filter(|&s| s > a && s < mid)
        .collect();
    let half = subdivide(a, mid, &left, h)?;
    let mut out = half.clone();
    for x in half.iter().rev().skip(1) {
        out.push(mid + (mid - x));
    }
    let last = out.len() - 1;
    out[last] = b;
    Ok(out)
}

/// Points from `a` to `b` (a < b): spacing `h` up to `a + fine`, then each
/// spacing `ratio` times the previous (a geometric grading away from a
/// region of interest at `a`), the last one stretched or merged to end at
/// `b` exactly. Fails with `INVALID_ARGUMENT` unless a < b, h > 0,
/// fine > 0 and 1 ≤ ratio ≤ 10.
pub fn graded(a: f64, b: f64, h: f64, fine: f64, ratio: f64) -> Result<Vec<f64>> {
    check_interval(a, b, h)?;
    if !(fine > 0.0 && (1.0..=10.0).contains(&ratio)) {
        return Err(Error::argument(format!(
            "graded subdivision: need fine > 0 and 1 <= ratio <= 10 (got {fine}, {ratio})"
        )));
    }
    let mut out = subdivide(a, (a + fine).min(b), &[], h)?;
    let mut step = (out[out.len() - 1] - out[out.len().saturating_sub(2)]).max(h);
    let mut x = out[out.len() - 1];
    while x < b {
        step *= ratio;
        x += step;
        if x + 0.5 * step >= b {
            x = b;
        }
        out.push(x.min(b));
    }
    out.dedup();
    Ok(out)
}

/// Nodes, triangles and body tags under construction.
#[derive(Debug, Clone, Default)]
pub struct MeshBuilder {
    /// Node coordinates.
    pub nodes: Vec<[f64; 2]>,
    /// Triangles (0-based, counter-clockwise).
    pub triangles: Vec<[usize; 3]>,
    /// Body tag of each triangle.
    pub bodies: Vec<i32>,
}

impl MeshBuilder {
    /// An empty builder.
    pub fn new() -> MeshBuilder {
        MeshBuilder::default()
    }

    /// Adds a node and returns its index.
    pub fn add_node(&mut self, p: [f64; 2]) -> usize {
        self.nodes.push(p);
        self.nodes.len() - 1
    }

    /// Adds the tensor grid xs × ys as its own nodes (so two grids sharing a
    /// line have coincident, distinct nodes there) and splits every cell.
    /// Returns the node indices by row: `rows[j][i]` is at `(xs[i], ys[j])`.
    pub fn add_grid(
        &mut self,
        xs: &[f64],
        ys: &[f64],
        body: i32,
        diagonal: Diagonal,
    ) -> Vec<Vec<usize>> {
        self.add_mapped_grid(xs, ys, |x, y| [x, y], body, diagonal)
    }

    /// Like [`MeshBuilder::add_grid`], with node (xs\[i\], ys\[j\]) placed at
    /// `map(xs[i], ys[j])`: a structured mesh of a curved region. The map
    /// must keep every cell convex and counter-clockwise (checked when the
    /// mesh is built).
    pub fn add_mapped_grid(
        &mut self,
        xs: &[f64],
        ys: &[f64],
        map: impl Fn(f64, f64) -> [f64; 2],
        body: i32,
        diagonal: Diagonal,
    ) -> Vec<Vec<usize>> {
        let rows: Vec<Vec<usize>> = ys
            .iter()
            .map(|&y| xs.iter().map(|&x| self.add_node(map(x, y))).collect())
            .collect();
        for j in 0..ys.len() - 1 {
            for i in 0..xs.len() - 1 {
                let (a, b) = (rows[j][i], rows[j][i + 1]);
                let (c, d) = (rows[j + 1][i + 1], rows[j + 1][i]);
                let forward = match diagonal {
                    Diagonal::Forward => true,
                    Diagonal::MirroredAt(x) => 0.5 * (xs[i] + xs[i + 1]) < x,
                };
                if forward {
                    self.push(body, [a, b, c]);
                    self.push(body, [a, c, d]);
                } else {
                    self.push(body, [a, b, d]);
                    self.push(body, [b, c, d]);
                }
            }
        }
        rows
    }

    /// Triangulates the strip between two rows of nodes sorted by x (the
    /// lower row below the upper one), advancing along whichever row has
    /// the nearer next node. The rows must span the same x range.
    pub fn add_strip(&mut self, lower: &[usize], upper: &[usize], body: i32) {
        let (mut i, mut j) = (0, 0);
        while i + 1 < lower.len() || j + 1 < upper.len() {
            let advance_lower = if i + 1 == lower.len() {
                false
            } else if j + 1 == upper.len() {
                true
            } else {
                self.nodes[lower[i + 1]][0] <= self.nodes[upper[j + 1]][0]
            };
            if advance_lower {
                self.push(body, [lower[i], lower[i + 1], upper[j]]);
                i += 1;
            } else {
                self.push(body, [lower[i], upper[j + 1], upper[j]]);
                j += 1;
            }
        }
    }

    fn push(&mut self, body: i32, t: [usize; 3]) {
        self.triangles.push(t);
        self.bodies.push(body);
    }

    /// Edges used by exactly one triangle, oriented with the triangle's
    /// interior on their left.
    pub fn boundary_edges(&self) -> Vec<[usize; 2]> {
        let mut count: HashMap<(usize, usize), (usize, [usize; 2])> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (p, q) = (t[k], t[(k + 1) % 3]);
                count
                    .entry((p.min(q), p.max(q)))
                    .and_modify(|e| e.0 += 1)
                    .or_insert((1, [p, q]));
            }
        }
        let mut out: Vec<[usize; 2]> = count
            .into_values()
            .filter(|e| e.0 == 1)
            .map(|e| e.1)
            .collect();
        out.sort_unstable();
        out
    }

    /// The boundary edges whose two end nodes both satisfy `pred`.
    pub fn boundary_edges_where(&self, pred: impl Fn([f64; 2]) -> bool) -> Vec<[usize; 2]> {
        self.boundary_edges()
            .into_iter()
            .filter(|e| pred(self.nodes[e[0]]) && pred(self.nodes[e[1]]))
            .collect()
    }

    /// Validates into a [`Mesh`] (0-based messages).
    pub fn build(self) -> Result<Mesh> {
        Mesh::new(self.nodes, self.triangles, self.bodies, 0)
    }
}

/// The unit square with n × n cells and, when `band` is `Some(eps)`, a band
/// of flattened triangles along y = 1/2 (n even): a row of nodes at height
/// 1/2 + eps placed at the midpoints between the nodes of the row y = 1/2,
/// so that the band consists of caps of height eps (docs/method.md §1; the
/// locking study of the TFEM paper). Returns the builder; its boundary is
/// the square's.
pub fn unit_square(n: usize, band: Option<f64>) -> MeshBuilder {
    let mut b = MeshBuilder::new();
    let xs: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
    let Some(eps) = band else {
        b.add_grid(&xs, &xs, 1, Diagonal::Forward);
        return b;
    };
    assert!(n % 2 == 0, "the band sits on the grid line y = 1/2");
    let lower_ys: Vec<f64> = (0..=n / 2).map(|j| j as f64 / n as f64).collect();
    let upper_ys: Vec<f64> = (n / 2 + 1..=n).map(|j| j as f64 / n as f64).collect();
    let lower = b.add_grid(&xs, &lower_ys, 1, Diagonal::Forward);
    let mid_row: Vec<usize> = {
        let mut xm = vec![0.0];
        xm.extend((0..n).map(|i| (i as f64 + 0.5) / n as f64));
        xm.push(1.0);
        xm.iter().map(|&x| b.add_node([x, 0.5 + eps])).collect()
    };
    b.add_strip(lower.last().expect("rows"), &mid_row, 1);
    let top_first: Vec<usize> = xs.iter().map(|&x| b.add_node([x, upper_ys[0]])).collect();
    b.add_strip(&mid_row, &top_first, 1);
    let mut prev = top_first;
    for &y in &upper_ys[1..] {
        let row: Vec<usize> = xs.iter().map(|&x| b.add_node([x, y])).collect();
        b.add_strip(&prev, &row, 1);
        prev = row;
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::element::TriGeometry;

    #[test]
    fn bad_subdivision_arguments_are_invalid_arguments_not_hangs() {
        use crate::error::Status;
        for (a, b, h) in [
            (0.0, 1.0, 0.0),
            (0.0, 1.0, -1.0),
            (0.0, 1.0, f64::NAN),
            (1.0, 0.0, 0.1),
            (0.0, 1.0, 1e-12),
        ] {
            assert_eq!(
                subdivide(a, b, &[], h).unwrap_err().status(),
                Status::InvalidArgument
            );
        }
        for ratio in [0.5, f64::NAN, 100.0] {
            let e = graded(0.0, 1.0, 0.1, 0.2, ratio).unwrap_err();
            assert_eq!(e.status(), Status::InvalidArgument, "{}", e.message());
        }
    }

    #[test]
    fn graded_spacing_is_fine_then_grows_and_ends_at_b() {
        let x = graded(0.0, 10.0, 0.1, 1.0, 1.2).unwrap();
        assert_eq!((x[0], x[x.len() - 1]), (0.0, 10.0));
        assert!(x.windows(2).all(|w| w[1] > w[0]));
        assert!(
            x.windows(2)
                .take(10)
                .all(|w| (w[1] - w[0] - 0.1).abs() < 1e-12)
        );
        assert!(x.len() < 40, "grading coarsens: {} points", x.len());
    }

    #[test]
    fn subdivide_hits_breakpoints_and_respects_spacing() {
        let x = subdivide(0.0, 1.0, &[0.3, 0.5], 0.12).unwrap();
        assert!(x.contains(&0.3) && x.contains(&0.5));
        assert!(
            x.windows(2)
                .all(|w| w[1] - w[0] <= 0.12 + 1e-12 && w[1] > w[0])
        );
    }

    #[test]
    fn symmetric_subdivision_is_a_mirror_image() {
        let x = subdivide_symmetric(0.0, 1.0, &[0.4], 0.07).unwrap();
        let n = x.len();
        for i in 0..n {
            assert!((x[i] + x[n - 1 - i] - 1.0).abs() < 1e-15);
        }
        assert!(x.contains(&0.5) && x.contains(&0.4));
    }

    #[test]
    fn grids_and_strips_are_counter_clockwise_and_fill_the_square() {
        for band in [None, Some(1e-3)] {
            let b = unit_square(8, band);
            let area: f64 = b
                .triangles
                .iter()
                .map(|t| {
                    let j = TriGeometry::new(&[b.nodes[t[0]], b.nodes[t[1]], b.nodes[t[2]]]).j;
                    assert!(j > 0.0);
                    0.5 * j
                })
                .sum();
            assert!((area - 1.0).abs() < 1e-12, "{area}");
            let edges = b.boundary_edges();
            let perimeter: f64 = edges
                .iter()
                .map(|e| {
                    let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
                    (p[0] - q[0]).hypot(p[1] - q[1])
                })
                .sum();
            assert!((perimeter - 4.0).abs() < 1e-12, "{perimeter}");
        }
    }
}
