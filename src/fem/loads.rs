//! Loads: pressures and tractions on tagged boundary edges, point forces at
//! nodes and body forces per body, and their consistent nodal vector.

use std::collections::BTreeMap;

use super::element::TriGeometry;
use super::material::Section;
use super::mesh::Mesh;
use crate::error::{Error, Result};

/// A load on the boundary edges of one tag.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EdgeLoad {
    /// Force per unit length along the inward normal.
    Pressure(f64),
    /// Force per unit length, a fixed vector.
    Traction([f64; 2]),
}

/// Every load of a problem. Loads of the same kind add up.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Loads {
    edge: Vec<(i32, EdgeLoad)>,
    nodal: Vec<(usize, [f64; 2])>,
    body: BTreeMap<i32, [f64; 2]>,
}

impl Loads {
    /// Adds a load on the edges tagged `tag` (checked by the caller with
    /// [`check_loaded_tag`]).
    pub fn add_edge_load(&mut self, tag: i32, load: EdgeLoad) {
        self.edge.push((tag, load));
    }

    /// Adds a point force at a node (0-based).
    pub fn add_nodal_force(&mut self, node: usize, force: [f64; 2]) {
        self.nodal.push((node, force));
    }

    /// Sets the body force (per unit area) of a body.
    pub fn set_body_force(&mut self, body: i32, force: [f64; 2]) {
        self.body.insert(body, force);
    }

    /// Removes every load.
    pub fn clear(&mut self) {
        *self = Loads::default();
    }

    /// The edge loads, in the order they were added.
    pub fn edge_loads(&self) -> &[(i32, EdgeLoad)] {
        &self.edge
    }

    /// The consistent nodal vector of the loads on `mesh` of sections
    /// `section` (2 values per node: f_x, f_y): edge loads and body forces
    /// integrated against each node's hat with the section's measure
    /// ([`Section::edge_shares`], [`Section::corner_loads`]; in the plane,
    /// split equally between the edge's nodes or the triangle's corners).
    /// Point forces are taken as given: for a ring, the force of the whole
    /// ring. Fails, naming the edge, if a pressure acts on an edge without
    /// an outward normal (which [`check_loaded_tag`] refuses beforehand).
    pub fn nodal_vector(&self, mesh: &Mesh, section: Section) -> Result<Vec<f64>> {
        let mut f = vec![0.0; 2 * mesh.nodes().len()];
        for &(tag, load) in &self.edge {
            for (k, e) in mesh.boundary_edges().iter().enumerate() {
                if e.tag != tag {
                    continue;
                }
                let [p, q] = e.nodes;
                let (xp, xq) = (mesh.nodes()[p], mesh.nodes()[q]);
                let len = (xq[0] - xp[0]).hypot(xq[1] - xp[1]);
                let t = match load {
                    EdgeLoad::Traction(t) => t,
                    EdgeLoad::Pressure(pr) => {
                        let n = mesh.outward_normal(e).ok_or_else(|| {
                            Error::argument(format!(
                                "boundary edge {} (tag {tag}) is interior or has zero length: \
                                 it cannot carry a pressure",
                                k + mesh.index_base()
                            ))
                        })?;
                        [-pr * n[0], -pr * n[1]]
                    }
                };
                let shares = section.edge_shares(xp[0], xq[0], len);
                for (v, share) in [p, q].into_iter().zip(shares) {
                    f[2 * v] += share * t[0];
                    f[2 * v + 1] += share * t[1];
                }
            }
        }
        for &(v, force) in &self.nodal {
            f[2 * v] += force[0];
            f[2 * v + 1] += force[1];
        }
        if !self.body.is_empty() {
            for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
                if let Some(b) = self.body.get(body) {
                    // Inverted or flat elements carry no material volume.
                    let corners = mesh.corners(tri);
                    let area = 0.5 * TriGeometry::new(&corners).j.max(0.0);
                    let loads = section.corner_loads(corners.map(|c| c[0]), area, *b);
                    for (&v, load) in tri.iter().zip(loads) {
                        f[2 * v] += load[0];
                        f[2 * v + 1] += load[1];
                    }
                }
            }
        }
        Ok(f)
    }
}

/// Checks that the edges tagged `tag` exist and can carry a load (each is
/// a side of exactly one triangle and has a length).
pub fn check_loaded_tag(mesh: &Mesh, tag: i32) -> Result<()> {
    let mut any = false;
    for (k, e) in mesh.boundary_edges().iter().enumerate() {
        if e.tag != tag {
            continue;
        }
        any = true;
        if mesh.outward_normal(e).is_none() {
            return Err(Error::argument(format!(
                "boundary edge {} (tag {tag}) is interior or has zero length: it cannot carry a load",
                k + mesh.index_base()
            )));
        }
    }
    if any {
        Ok(())
    } else {
        Err(Error::argument(format!("no boundary edge has tag {tag}")))
    }
}
