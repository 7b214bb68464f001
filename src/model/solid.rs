//! The model of bodies in space (docs/method.md §9): a tetrahedral mesh
//! with tagged boundary faces, each body's material, prescribed
//! displacements, pressure, traction and nodal loads, and contact pairs
//! between tagged surfaces — B's flat tetrahedra built between each pair
//! ([`prism_layer`]) and switched by the one active-set loop
//! ([`crate::solve::solid::solve_gap_contact`]). The 3D counterpart of [`crate::Model`]: every
//! mutating call either succeeds or leaves the model as it was, and any
//! change of the problem drops the last solution.
//!
//! What 3D does not do yet is refused where it is asked for: a curved
//! surface a (B's prisms need a planar side to face across), friction,
//! and non-matching interfaces (docs/method.md §9).

use std::collections::{BTreeMap, BTreeSet};

use crate::contact::ContactOptions;
use crate::contact::gap_tets::{GapData, GapTetrahedron, GapTets};
use crate::contact::prism_layer::{FacingSurfaces, prism_layer};
use crate::error::{Error, Result};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::element::Tempering;
use crate::fem::solid_assembly::{SolidBodies, tet_cliques};
use crate::fem::solid_mesh::SolidMesh;
use crate::fem::tet::{dot, isotropic_d, sub};
use crate::linalg::Ordering;
use crate::solve::report::{IterationRecord, SolveInfo};
use crate::solve::solid::{SolidAnalysis, SolidSystem, solve_gap_contact_from};

/// A displacement component in space.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Axis {
    /// u_x.
    X = 0,
    /// u_y.
    Y = 1,
    /// u_z.
    Z = 2,
}

impl Axis {
    /// Decodes the C ABI integer (0 = x, 1 = y, 2 = z).
    pub fn from_i32(value: i32) -> Option<Axis> {
        match value {
            0 => Some(Axis::X),
            1 => Some(Axis::Y),
            2 => Some(Axis::Z),
            _ => None,
        }
    }
}

/// An isotropic linear elastic material in space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolidMaterial {
    young: f64,
    poisson: f64,
    d: [[f64; 6]; 6],
}

impl SolidMaterial {
    /// Young's modulus and Poisson's ratio; a modulus that is not finite
    /// and positive, or a ratio outside (−1, 1/2), is refused.
    pub fn new(young: f64, poisson: f64) -> Result<SolidMaterial> {
        Ok(SolidMaterial {
            young,
            poisson,
            d: isotropic_d(young, poisson)?,
        })
    }

    /// Young's modulus.
    pub fn young(&self) -> f64 {
        self.young
    }

    /// Poisson's ratio.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }
}

/// A load on the bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Load {
    /// A pressure on the faces of a tag (along minus their outward normal).
    Pressure { tag: i32, pressure: f64 },
    /// A traction vector on the faces of a tag.
    Traction { tag: i32, traction: [f64; 3] },
    /// A force at a node.
    Nodal { node: usize, force: [f64; 3] },
}

/// A contact pair: the faces tagged `tag_a`, planar, facing those tagged
/// `tag_b` node to node across the gap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SolidPair {
    /// The planar side's tag (its outward normal opens the gap).
    pub tag_a: i32,
    /// The facing side's tag.
    pub tag_b: i32,
}

/// B between the pairs: its tetrahedra and, for each, its pair, tie
/// length and contact modulus.
struct Layer {
    elements: Vec<GapTetrahedron>,
    pair_of: Vec<usize>,
    h_c: Vec<f64>,
    moduli: Vec<f64>,
}

/// What a solve found.
#[derive(Debug, Clone)]
struct SolidSolution {
    u: Vec<f64>,
    loads: Vec<f64>,
    gap: GapTets,
    pair_of: Vec<usize>,
    active: Vec<bool>,
    info: SolveInfo,
    history: Vec<IterationRecord>,
    warnings: Vec<String>,
}

/// What a load step replaced: the solution and the set the next step
/// would have started from.
#[derive(Debug)]
struct Undo {
    solution: Option<SolidSolution>,
    warm: Option<Vec<bool>>,
}

/// A 3D elasticity and contact model of tempered tetrahedra.
#[derive(Debug, Default)]
pub struct SolidModel {
    mesh: Option<SolidMesh>,
    materials: BTreeMap<i32, SolidMaterial>,
    tempering: Option<Tempering>,
    ordering: Ordering,
    fixed: BTreeMap<(usize, Axis), f64>,
    loads: Vec<Load>,
    pairs: Vec<SolidPair>,
    /// The structure's epoch: bumped by every change of what the unknowns,
    /// B, the pattern or the matrix depend on (not by loads or prescribed
    /// values).
    epoch: u64,
    /// What the last solve derived from the structure.
    derived: Option<solving::Derived>,
    solution: Option<SolidSolution>,
    /// The solution before the last load step ([`SolidModel::revert_step`]).
    undo: Option<Undo>,
    /// The active set the next load step starts from: the last solve's,
    /// kept across changes of loads and prescribed values.
    warm: Option<Vec<bool>>,
}

impl SolidModel {
    /// An empty model.
    pub fn new() -> SolidModel {
        SolidModel::default()
    }

    /// Sets the mesh; the constraints, loads and contact pairs (which name
    /// its nodes and tags) are cleared, the materials kept.
    pub fn set_mesh(&mut self, mesh: SolidMesh) {
        self.mesh = Some(mesh);
        self.fixed.clear();
        self.loads.clear();
        self.pairs.clear();
        self.changed(true);
    }

    /// The mesh, if set.
    pub fn mesh(&self) -> Option<&SolidMesh> {
        self.mesh.as_ref()
    }

    fn mesh_ref(&self) -> Result<&SolidMesh> {
        self.mesh
            .as_ref()
            .ok_or_else(|| Error::argument("the 3D model has no mesh: set one first"))
    }

    /// Sets the material of a body.
    pub fn set_material(&mut self, body: i32, material: SolidMaterial) {
        self.materials.insert(body, material);
        self.changed(true);
    }

    /// Sets how tetrahedra are tempered (default [`Tempering::Auto`]); a
    /// non-finite or non-positive λ or Jmin is refused.
    pub fn set_tempering(&mut self, tempering: Tempering) -> Result<()> {
        let bad = match tempering {
            Tempering::Lambda(x) | Tempering::Fixed(x) => !(x.is_finite() && x > 0.0),
            Tempering::Auto | Tempering::Off => false,
        };
        if bad {
            return Err(Error::argument(format!(
                "tempering {tempering:?}: its value must be finite and > 0"
            )));
        }
        self.tempering = Some(tempering);
        self.changed(true);
        Ok(())
    }

    /// Sets the fill-reducing ordering of the solve (results unchanged up
    /// to round-off).
    pub fn set_ordering(&mut self, ordering: Ordering) {
        self.ordering = ordering;
    }

    /// Prescribes component `axis` of node `node` (0-based) to `value`.
    pub fn fix(&mut self, node: usize, axis: Axis, value: f64) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if node >= mesh.nodes().len() {
            return Err(Error::argument(format!(
                "node {} is out of range ({} nodes)",
                node + mesh.index_base(),
                mesh.nodes().len()
            )));
        }
        finite(value, "prescribed value")?;
        let new = self.fixed.insert((node, axis), value).is_none();
        self.changed(new);
        Ok(())
    }

    /// Prescribes component `axis` of every node of the faces tagged `tag`
    /// to `value`.
    pub fn fix_faces(&mut self, tag: i32, axis: Axis, value: f64) -> Result<()> {
        finite(value, "prescribed value")?;
        let nodes = self.tagged_nodes(tag)?;
        let mut new = false;
        for v in nodes {
            new |= self.fixed.insert((v, axis), value).is_none();
        }
        self.changed(new);
        Ok(())
    }

    /// The prescribed displacements: (node, component, value).
    pub fn constraints(&self) -> impl Iterator<Item = (usize, Axis, f64)> + '_ {
        self.fixed.iter().map(|(&(v, a), &x)| (v, a, x))
    }

    /// Removes every prescribed displacement.
    pub fn clear_constraints(&mut self) {
        self.fixed.clear();
        self.changed(true);
    }

    /// A pressure on the faces tagged `tag` (positive pushes into the
    /// body).
    pub fn add_pressure(&mut self, tag: i32, pressure: f64) -> Result<()> {
        finite(pressure, "pressure")?;
        self.tagged_nodes(tag)?;
        self.loads.push(Load::Pressure { tag, pressure });
        self.changed(false);
        Ok(())
    }

    /// A traction (force per area) on the faces tagged `tag`.
    pub fn add_traction(&mut self, tag: i32, traction: [f64; 3]) -> Result<()> {
        traction.iter().try_for_each(|&t| finite(t, "traction"))?;
        self.tagged_nodes(tag)?;
        self.loads.push(Load::Traction { tag, traction });
        self.changed(false);
        Ok(())
    }

    /// A force at node `node` (0-based).
    pub fn add_nodal_force(&mut self, node: usize, force: [f64; 3]) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if node >= mesh.nodes().len() {
            return Err(Error::argument(format!(
                "node {} is out of range ({} nodes)",
                node + mesh.index_base(),
                mesh.nodes().len()
            )));
        }
        force.iter().try_for_each(|&f| finite(f, "nodal force"))?;
        self.loads.push(Load::Nodal { node, force });
        self.changed(false);
        Ok(())
    }

    /// Removes every load.
    pub fn clear_loads(&mut self) {
        self.loads.clear();
        self.changed(false);
    }

    /// Adds a contact pair between the faces tagged `tag_a` (planar: its
    /// outward normal is the direction that opens the gap) and those tagged
    /// `tag_b`, which must face them node to node (checked at the solve);
    /// returns its index.
    pub fn add_contact_pair(&mut self, tag_a: i32, tag_b: i32) -> Result<usize> {
        if tag_a == tag_b {
            return Err(Error::argument(format!(
                "a contact pair needs two tags: both are {tag_a}"
            )));
        }
        self.tagged_nodes(tag_a)?;
        self.tagged_nodes(tag_b)?;
        self.pairs.push(SolidPair { tag_a, tag_b });
        self.changed(true);
        Ok(self.pairs.len() - 1)
    }

    /// The contact pairs.
    pub fn contact_pairs(&self) -> &[SolidPair] {
        &self.pairs
    }

    /// Removes every contact pair.
    pub fn clear_contact_pairs(&mut self) {
        self.pairs.clear();
        self.changed(true);
    }

    /// Drops the results a change makes stale; a change of the structure
    /// (`structure`) also drops what solves derived from it.
    fn changed(&mut self, structure: bool) {
        self.solution = None;
        self.undo = None;
        if structure {
            self.epoch += 1;
            self.derived = None;
            self.warm = None;
        }
    }

    /// The nodes of the faces tagged `tag`, an error if none is.
    fn tagged_nodes(&self, tag: i32) -> Result<BTreeSet<usize>> {
        let mesh = self.mesh_ref()?;
        let nodes: BTreeSet<usize> = (mesh.boundary_faces().iter())
            .filter(|f| f.tag == tag)
            .flat_map(|f| f.nodes)
            .collect();
        if nodes.is_empty() {
            return Err(Error::argument(format!("no boundary face has tag {tag}")));
        }
        Ok(nodes)
    }
}

fn finite(x: f64, what: &str) -> Result<()> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Error::argument(format!("{what} {x:?} is not finite")))
    }
}

mod results;
mod solving;
mod stepping;
