//! What the solver reads of a mesh whatever its dimension: its nodes'
//! positions and bodies, and how to name a node to the user. The linear
//! solve names the node of a non-finite unknown and the bodies of a free
//! mode through this alone, so the loop above it serves triangles and
//! tetrahedra alike (docs/method.md §9).

use super::mesh::Mesh;
use crate::error::{Error, Result};

/// A mesh as the solver's diagnostics see it: `dimension()` displacement
/// components per node, numbered node-major.
pub trait Domain {
    /// Space dimension (2 or 3): the displacement components per node.
    fn dimension(&self) -> usize;
    /// Number of nodes.
    fn n_nodes(&self) -> usize;
    /// Coordinate `c` (< dimension) of node `v`.
    fn coordinate(&self, v: usize, c: usize) -> f64;
    /// The body of each node (`None`: in no body element).
    fn node_body(&self) -> &[Option<i32>];
    /// The bodies, ascending.
    fn bodies(&self) -> &[i32];
    /// Node `v` in the user's words ("node 12", in their index base).
    fn node_name(&self, v: usize) -> String;
}

impl Domain for Mesh {
    fn dimension(&self) -> usize {
        2
    }

    fn n_nodes(&self) -> usize {
        self.nodes().len()
    }

    fn coordinate(&self, v: usize, c: usize) -> f64 {
        self.nodes()[v][c]
    }

    fn node_body(&self) -> &[Option<i32>] {
        Mesh::node_body(self)
    }

    fn bodies(&self) -> &[i32] {
        Mesh::bodies(self)
    }

    fn node_name(&self, v: usize) -> String {
        Mesh::node_name(self, v)
    }
}

/// Nodes in space with their bodies: the [`Domain`] of a tetrahedral mesh.
#[derive(Debug, Clone)]
pub struct SolidNodes {
    points: Vec<[f64; 3]>,
    node_body: Vec<Option<i32>>,
    bodies: Vec<i32>,
}

impl SolidNodes {
    /// The nodes `points` of the tetrahedra `tets`, tetrahedron e in body
    /// `body[e]` (`None`: in none, as the flat tetrahedra of a gap). A node
    /// takes the body of the last body tetrahedron that holds it. A body
    /// list of another length than the tetrahedra's, or a node out of
    /// range, is refused.
    pub fn new(
        points: Vec<[f64; 3]>,
        tets: &[[usize; 4]],
        body: &[Option<i32>],
    ) -> Result<SolidNodes> {
        if body.len() != tets.len() {
            return Err(Error::argument(format!(
                "{} bodies for {} tetrahedra",
                body.len(),
                tets.len()
            )));
        }
        if let Some((e, _)) =
            (tets.iter().enumerate()).find(|(_, t)| t.iter().any(|&v| v >= points.len()))
        {
            return Err(Error::argument(format!(
                "tetrahedron {e} has a node out of range ({} nodes)",
                points.len()
            )));
        }
        let mut node_body = vec![None; points.len()];
        let mut bodies = Vec::new();
        for (t, b) in tets.iter().zip(body) {
            if let Some(b) = *b {
                t.iter().for_each(|&v| node_body[v] = Some(b));
                bodies.push(b);
            }
        }
        bodies.sort_unstable();
        bodies.dedup();
        Ok(SolidNodes {
            points,
            node_body,
            bodies,
        })
    }

    /// The nodes' positions.
    pub fn points(&self) -> &[[f64; 3]] {
        &self.points
    }
}

impl Domain for SolidNodes {
    fn dimension(&self) -> usize {
        3
    }

    fn n_nodes(&self) -> usize {
        self.points.len()
    }

    fn coordinate(&self, v: usize, c: usize) -> f64 {
        self.points[v][c]
    }

    fn node_body(&self) -> &[Option<i32>] {
        &self.node_body
    }

    fn bodies(&self) -> &[i32] {
        &self.bodies
    }

    fn node_name(&self, v: usize) -> String {
        format!("node {v}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solid_nodes_take_the_bodies_of_their_tetrahedra_and_not_of_the_gap() {
        let points = vec![[0.0; 3]; 6];
        let tets = [[0, 1, 2, 3], [1, 2, 3, 4], [4, 5, 3, 2]];
        let nodes = SolidNodes::new(points.clone(), &tets, &[Some(7), None, Some(2)]).unwrap();
        assert_eq!(
            nodes.node_body(),
            &[Some(7), Some(7), Some(2), Some(2), Some(2), Some(2)]
        );
        assert_eq!(nodes.bodies(), &[2, 7]);
        assert_eq!(nodes.dimension(), 3);
        let e = SolidNodes::new(points, &tets, &[Some(7)]).unwrap_err();
        assert!(e.message().contains("1 bodies for 3 tetrahedra"), "{e}");
    }
}
