//! B in three dimensions (docs/method.md §9, stage 3): the flat
//! tetrahedra that mesh the gap between two bodies' matching surfaces,
//! each a constraint of the active-set loop. A tetrahedron's gap is
//! g = J0 + w·u with the weights w_k = (n·a_k) n of its projection onto
//! the interface plane ([`gap_weights`]) and J0 = Σ_k (n·a_k)(n·x_k) its
//! initial gap (independent of the plane's offset: Σ_k a_k = 0); while on,
//! it adds K = (E_c/(6T_e)) w wᵀ ([`contact_stiffness`]) with the tie's
//! T_e = A_e h_c²/λ (A_e the facing area), which ties each pair of facing
//! nodes in proportion to its tributary area whatever the prisms' split.
//! It is on while g ≤ 0: overlapping, or touching (a body held only where
//! it touches keeps that hold).

use crate::error::{Error, Result, Status};
use crate::fem::tet::{TetGeometry, contact_stiffness, gap_weights};

/// One flat tetrahedron of B: its nodes and the unit normal of the
/// interface it lies on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GapTetrahedron {
    /// The four nodes, numbered so that J (six times the signed volume)
    /// grows as the gap opens: swapping two turns the gap g into −g, an
    /// open tetrahedron into a pressed one. [`super::prism_layer`] numbers
    /// them so.
    pub nodes: [usize; 4],
    /// The interface's unit normal.
    pub normal: [f64; 3],
}

/// What B's tetrahedra are built from besides themselves.
pub struct GapData<'a> {
    /// Every node's position.
    pub points: &'a [[f64; 3]],
    /// The contact modulus E_c of each tetrahedron.
    pub moduli: &'a [f64],
    /// The tie's length h_c of each tetrahedron (its interface's shortest
    /// edge: pairs meshed apart keep their own).
    pub h_c: &'a [f64],
    /// The tie's length λ (the model's size).
    pub lambda: f64,
    /// The unknown of global DOF g (3·node + component), if it has one.
    pub equation: &'a dyn Fn(usize) -> Option<usize>,
    /// Prescribed displacements, a global vector.
    pub prescribed: &'a [f64],
}

/// B's tetrahedra of one solve, each with its weights, initial gap and
/// matrix (module documentation).
#[derive(Debug, Clone, Default)]
pub struct GapTets {
    nodes: Vec<[usize; 4]>,
    areas: Vec<f64>,
    weights: Vec<[f64; 12]>,
    initial: Vec<f64>,
    scales: Vec<f64>,
    matrices: Vec<Vec<f64>>,
    unknowns: Vec<[Option<usize>; 12]>,
    loads: Vec<[f64; 12]>,
    gap_loads: Vec<[f64; 12]>,
}

impl GapTets {
    /// B's tetrahedra `elements` for the data `d`; a tetrahedron with a
    /// node out of range, a normal that is not a finite unit vector, no
    /// facing area, or a modulus or tie that is not finite and positive is
    /// refused, by its index.
    pub fn new(elements: &[GapTetrahedron], d: &GapData<'_>) -> Result<GapTets> {
        if !(d.lambda.is_finite() && d.lambda > 0.0) {
            return Err(Error::argument(format!(
                "the gap's tie needs λ > 0, finite: λ = {:?}",
                d.lambda
            )));
        }
        if d.prescribed.len() != 3 * d.points.len() {
            return Err(Error::argument(format!(
                "{} prescribed values for {} nodes (three each)",
                d.prescribed.len(),
                d.points.len()
            )));
        }
        for (what, len) in [
            ("contact moduli", d.moduli.len()),
            ("tie lengths", d.h_c.len()),
        ] {
            if len != elements.len() {
                return Err(Error::argument(format!(
                    "{len} {what} for {} gap tetrahedra",
                    elements.len()
                )));
            }
        }
        let mut set = GapTets::default();
        for (e, el) in elements.iter().enumerate() {
            set.push(e, el, d).map_err(|err| {
                Error::new(
                    err.status(),
                    format!("gap tetrahedron {e}: {}", err.message()),
                )
            })?;
        }
        Ok(set)
    }

    /// Adds tetrahedron `e`.
    fn push(&mut self, e: usize, el: &GapTetrahedron, d: &GapData<'_>) -> Result<()> {
        let n = el.normal;
        let norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        if !norm.is_finite() || (norm - 1.0).abs() > 1e-12 {
            return Err(Error::argument(format!(
                "its normal {n:?} is not a unit vector"
            )));
        }
        if let Some(&v) = el.nodes.iter().find(|&&v| v >= d.points.len()) {
            return Err(Error::argument(format!(
                "its node {v} is out of range ({} nodes)",
                d.points.len()
            )));
        }
        let x = el.nodes.map(|v| d.points[v]);
        // Its projection onto the interface plane through the origin.
        let flat = x.map(|p| {
            let h = n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
            [p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2]]
        });
        let geo = TetGeometry::new(&flat);
        let area = geo.largest_face();
        if !(area.is_finite() && area > 0.0) {
            return Err(Error::argument(
                "it has no facing area on the interface plane".to_string(),
            ));
        }
        let w = gap_weights(&geo, n);
        let j0: f64 = (0..12)
            .map(|i| w[i] * (x[i / 3][i % 3] - flat[i / 3][i % 3]))
            .sum();
        let h_c = d.h_c[e];
        if !(h_c.is_finite() && h_c > 0.0) {
            return Err(Error::argument(format!(
                "its tie length h_c = {h_c:?} must be finite and > 0"
            )));
        }
        let t_e = area * h_c * h_c / d.lambda;
        let k = contact_stiffness(&w, d.moduli[e], t_e)?;
        let unknowns: [Option<usize>; 12] =
            std::array::from_fn(|i| (d.equation)(3 * el.nodes[i / 3] + i % 3));
        let scale = d.moduli[e] / (6.0 * t_e);
        // The initial gap's load −s J0 w, less the prescribed DOFs' share.
        let gap_load: [f64; 12] = std::array::from_fn(|i| -scale * j0 * w[i]);
        let load: [f64; 12] = std::array::from_fn(|i| match unknowns[i] {
            None => 0.0,
            Some(_) => {
                let fixed: f64 = (0..12)
                    .filter(|&j| unknowns[j].is_none())
                    .map(|j| k[i][j] * d.prescribed[3 * el.nodes[j / 3] + j % 3])
                    .sum();
                gap_load[i] - fixed
            }
        });
        self.nodes.push(el.nodes);
        self.areas.push(area);
        self.weights.push(w);
        self.initial.push(j0);
        self.scales.push(scale);
        self.matrices.push(k.iter().flatten().copied().collect());
        self.unknowns.push(unknowns);
        self.loads.push(load);
        self.gap_loads.push(gap_load);
        Ok(())
    }

    /// Number of tetrahedra.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The nodes of tetrahedron `k`.
    pub fn nodes(&self, k: usize) -> &[usize; 4] {
        &self.nodes[k]
    }

    /// The unknown of each DOF of tetrahedron `k` (`None`: prescribed).
    pub fn unknowns(&self, k: usize) -> &[Option<usize>] {
        &self.unknowns[k]
    }

    /// The global DOF (3·node + component) of each DOF of tetrahedron `k`.
    pub fn dofs(&self, k: usize) -> [usize; 12] {
        std::array::from_fn(|i| 3 * self.nodes[k][i / 3] + i % 3)
    }

    /// Tetrahedron `k`'s matrix while on, row-major over its 12 DOFs.
    pub fn matrix(&self, k: usize) -> &[f64] {
        &self.matrices[k]
    }

    /// Tetrahedron `k`'s load on its unknowns while on.
    pub fn load(&self, k: usize) -> &[f64] {
        &self.loads[k]
    }

    /// Tetrahedron `k`'s load of its initial gap alone, on every DOF.
    pub fn gap_load(&self, k: usize) -> &[f64] {
        &self.gap_loads[k]
    }

    /// The weights w of tetrahedron `k`'s gap.
    pub fn weights(&self, k: usize) -> &[f64; 12] {
        &self.weights[k]
    }

    /// The facing area of tetrahedron `k` (its prism's triangle).
    pub fn area(&self, k: usize) -> f64 {
        self.areas[k]
    }

    /// The gap J0 + w·u of tetrahedron `k` for its DOFs' values `ue`
    /// (negative: an overlap).
    pub fn gap(&self, k: usize, ue: &[f64; 12]) -> f64 {
        let w = &self.weights[k];
        self.initial[k] + (0..12).map(|i| w[i] * ue[i]).sum::<f64>()
    }

    /// The factor s·g of tetrahedron `k`'s force s·g·w on its nodes while
    /// on (s = E_c/(6T_e); negative: pressed).
    pub fn force(&self, k: usize, ue: &[f64; 12]) -> f64 {
        self.scales[k] * self.gap(k, ue)
    }

    /// The set a loop starts from: those touching or overlapping at rest.
    pub fn initial_active(&self) -> Vec<bool> {
        self.initial.iter().map(|&j0| j0 <= 0.0).collect()
    }

    /// The verdict of the inversion test: on while the gap is not
    /// positive, for the values `ue(k)` of each tetrahedron's DOFs; a gap
    /// that is not finite is refused, naming the tetrahedron.
    pub fn verdict(&self, ue: impl Fn(usize) -> [f64; 12]) -> Result<Vec<bool>> {
        (0..self.len())
            .map(|k| {
                let g = self.gap(k, &ue(k));
                match g.is_finite() {
                    true => Ok(g <= 0.0),
                    false => Err(Error::new(
                        Status::NumericalFailure,
                        format!("the gap of gap tetrahedron {k} is not finite"),
                    )),
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat tetrahedron between facing nodes 0/1 (at z = 0 and z = g0)
    /// and two nodes of the lower surface.
    fn one(g0: f64) -> (Vec<[f64; 3]>, GapTetrahedron) {
        let points = vec![
            [0.0, 0.0, 0.0],
            [0.0, 0.0, g0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let el = GapTetrahedron {
            nodes: [0, 1, 2, 3],
            normal: [0.0, 0.0, 1.0],
        };
        (points, el)
    }

    fn build(points: &[[f64; 3]], el: GapTetrahedron, prescribed: &[f64]) -> Result<GapTets> {
        let equation = |g: usize| Some(g);
        let data = GapData {
            points,
            moduli: &[2.0],
            h_c: &[0.5],
            lambda: 1.0,
            equation: &equation,
            prescribed,
        };
        GapTets::new(&[el], &data)
    }

    #[test]
    fn the_initial_gap_is_the_facing_nodes_opening_times_twice_the_area() {
        let (points, el) = one(0.25);
        let set = build(&points, el, &[0.0; 12]).unwrap();
        // J0 = (n·a_1) g0 with n·a_1 = twice the facing triangle's area.
        assert!((set.gap(0, &[0.0; 12]) - 0.25).abs() < 1e-15);
        assert_eq!(set.initial_active(), vec![false]);
        // Closing the pair by 0.3 overlaps it by 0.05.
        let mut ue = [0.0; 12];
        ue[5] = -0.3;
        assert!((set.gap(0, &ue) + 0.05).abs() < 1e-15);
        assert_eq!(set.verdict(|_| ue).unwrap(), vec![true]);
    }

    #[test]
    fn an_initial_gap_loads_the_nodes_so_that_the_element_alone_closes_it() {
        let (points, el) = one(0.25);
        let set = build(&points, el, &[0.0; 12]).unwrap();
        // K u = f has the solution that closes the gap: g(u) = 0 for
        // u = −J0 w / |w|².
        let w = set.weights(0);
        let ww: f64 = w.iter().map(|x| x * x).sum();
        let u: [f64; 12] = std::array::from_fn(|i| -0.25 * w[i] / ww);
        let k = set.matrix(0);
        for i in 0..12 {
            let ku: f64 = (0..12).map(|j| k[i * 12 + j] * u[j]).sum();
            assert!((ku - set.load(0)[i]).abs() < 1e-12, "row {i}");
        }
        assert!(set.gap(0, &u).abs() < 1e-15);
    }

    #[test]
    fn a_tetrahedron_with_a_bad_normal_or_node_is_refused_by_its_index() {
        let (points, mut el) = one(0.0);
        el.normal = [0.0, 0.0, 2.0];
        let e = build(&points, el, &[0.0; 12]).unwrap_err();
        assert!(e.message().contains("gap tetrahedron 0"), "{}", e.message());
        let (points, mut el) = one(0.0);
        el.nodes[2] = 9;
        let e = build(&points, el, &[0.0; 12]).unwrap_err();
        assert!(e.message().contains("node 9"), "{}", e.message());
    }

    #[test]
    fn a_tetrahedron_edge_on_to_the_plane_is_refused() {
        let (mut points, el) = one(0.0);
        // All four nodes on the line x = y, z free: no facing area.
        points[2] = [0.0, 0.0, 1.0];
        points[3] = [0.0, 0.0, 2.0];
        let e = build(&points, el, &[0.0; 12]).unwrap_err();
        assert!(e.message().contains("facing area"), "{}", e.message());
    }
}
