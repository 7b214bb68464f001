//! The one loop over the body elements: each triangle with its geometry,
//! its body's constitutive matrix D and its resolved Jmin. The assembly,
//! the energy used to diagnose singular systems, the strains and the
//! reactions all visit the elements through it, so that they agree on
//! what an element is.

use std::collections::BTreeMap;

use super::element::{Jmin, Tempering, TriGeometry, section_stiffness_into};
use super::material::{Material, Section};
use super::mesh::Mesh;
use crate::error::{Error, Result};

/// The body elements of a mesh with their materials and tempering.
#[derive(Clone, Copy)]
pub struct ElementLoop<'a> {
    mesh: &'a Mesh,
    materials: &'a BTreeMap<i32, Material>,
    tempering: Tempering,
    /// The mesh size that [`Tempering::Auto`] takes for λ.
    size: f64,
}

/// One body element as the loop presents it.
pub struct ElementView<'a> {
    /// Index of the triangle in the mesh.
    pub index: usize,
    /// Its nodes.
    pub nodes: &'a [usize; 3],
    /// Its body.
    pub body: i32,
    /// Its geometry in the initial configuration.
    pub geo: TriGeometry,
    /// Its body's constitutive matrix (in-plane).
    pub d: [[f64; 3]; 3],
    /// What it stands for in 3D: a slab or a ring.
    pub section: Section,
    /// The abscissa of its centroid (a ring's mean radius).
    pub x: f64,
    /// Its resolved tempering.
    pub jmin: Jmin,
}

impl<'a> ElementLoop<'a> {
    /// The loop over the triangles of `mesh`. Every body must have a
    /// material (checked before a solve).
    pub fn new(
        mesh: &'a Mesh,
        materials: &'a BTreeMap<i32, Material>,
        tempering: Tempering,
    ) -> ElementLoop<'a> {
        ElementLoop {
            mesh,
            materials,
            tempering,
            size: mesh.size(),
        }
    }

    /// The mesh.
    pub fn mesh(&self) -> &'a Mesh {
        self.mesh
    }

    /// The material of a body.
    pub fn material(&self, body: i32) -> &'a Material {
        &self.materials[&body]
    }

    /// The Jmin of an element of geometry `geo`.
    pub fn jmin(&self, geo: &TriGeometry) -> Jmin {
        self.tempering.jmin(geo, self.size)
    }

    /// Visits, in mesh order, the elements for which `select` (given the
    /// triangle's index and nodes, before anything is computed for it)
    /// returns `Some`, passing that value on to `visit`. Stops at the first
    /// error of `visit`.
    #[inline]
    pub fn visit<S, E>(
        &self,
        mut select: impl FnMut(usize, &[usize; 3]) -> Option<S>,
        mut visit: impl FnMut(&ElementView<'a>, S) -> std::result::Result<(), E>,
    ) -> std::result::Result<(), E> {
        let mesh = self.mesh;
        // D changes only between bodies, which are mostly contiguous.
        let mut d_cache: Option<(i32, [[f64; 3]; 3], Section)> = None;
        for (e, (tri, &body)) in mesh.triangles().iter().zip(mesh.body_of()).enumerate() {
            let Some(selected) = select(e, tri) else {
                continue;
            };
            let (d, section) = match d_cache {
                Some((b, d, section)) if b == body => (d, section),
                _ => {
                    let material = &self.materials[&body];
                    let (d, section) = (material.d_matrix(), material.section());
                    d_cache = Some((body, d, section));
                    (d, section)
                }
            };
            let corners = mesh.corners(tri);
            let geo = TriGeometry::new(&corners);
            let view = ElementView {
                index: e,
                nodes: tri,
                body,
                geo,
                d,
                section,
                x: (corners[0][0] + corners[1][0] + corners[2][0]) / 3.0,
                jmin: self.jmin(&geo),
            };
            visit(&view, selected)?;
        }
        Ok(())
    }

    /// Visits every element.
    pub fn for_each(&self, mut visit: impl FnMut(&ElementView<'a>) -> Result<()>) -> Result<()> {
        self.visit(|_, _| Some(()), |el, ()| visit(el))
    }

    /// The tempered stiffness of an element into `k`; an error names the
    /// element and its body.
    #[inline]
    pub fn stiffness_into(&self, el: &ElementView<'_>, k: &mut [[f64; 6]; 6]) -> Result<()> {
        section_stiffness_into(&el.geo, &el.d, el.section, el.x, el.jmin, k).map_err(|err| {
            let what = format!("{} (body {})", self.mesh.triangle_name(el.index), el.body);
            Error::new(err.status(), format!("{what}: {}", err.message()))
        })
    }

    /// The tempered stiffness of an element, row-major.
    pub fn stiffness(&self, el: &ElementView<'_>) -> Result<[f64; 36]> {
        let mut k = [[0.0; 6]; 6];
        self.stiffness_into(el, &mut k)?;
        Ok(std::array::from_fn(|i| k[i / 6][i % 6]))
    }
}

/// The element values of a global vector (2 per node), node-major.
#[inline]
pub fn element_values(u: &[f64], tri: &[usize; 3]) -> [f64; 6] {
    std::array::from_fn(|a| u[2 * tri[a / 2] + a % 2])
}
