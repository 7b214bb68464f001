//! The problem as the user describes it: a mesh, a material per body,
//! the tempering, prescribed displacements, loads and contact pairs.
//!
//! Every setter either succeeds or leaves the problem exactly as it was.
//! Changes are counted by epochs: the *epoch* moves with every change
//! (results of an earlier epoch are stale); the *structure* epoch with
//! the changes that alter what a solve derives from the problem — the mesh
//! and its boundary edges, the set of prescribed DOFs, the contact pairs —
//! so that everything derived checks the epoch instead of being cleared by
//! hand; the *stiffness* epoch with the structure, the materials and the
//! tempering (what a load history's one factorisation is valid for); the
//! *contact* epoch with the structure but the set of prescribed DOFs: with
//! what the contact mesh B and its parts are made of, which a load step's
//! contact state belongs to.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use super::Component;
use crate::contact::{self, ContactPair, ContactWeighting};
use crate::error::{Error, Result, Status};
use crate::fem::curve::Curve;
use crate::fem::element::Tempering;
use crate::fem::element_loop::ElementLoop;
use crate::fem::loads::{EdgeLoad, Loads, check_loaded_tag};
use crate::fem::material::{Material, Section};
use crate::fem::mesh::{BoundaryEdge, Mesh};

/// A 2D elasticity (and contact) problem.
#[derive(Debug, Clone)]
pub struct Problem {
    mesh: Option<Mesh>,
    materials: BTreeMap<i32, Material>,
    tempering: Tempering,
    prescribed: BTreeMap<usize, f64>,
    loads: Loads,
    pairs: Vec<ContactPair>,
    /// How the pairs' contact energy is weighted.
    weighting: ContactWeighting,
    /// What automatic pairing left out, and why (kept until the pairs are
    /// cleared, the boundary edges set anew or the mesh replaced).
    pairing_warnings: Vec<String>,
    structure: u64,
    /// The contact epoch ([`Problem::contact_epoch`]) and what moved it
    /// last ([`Problem::contact_change`]).
    contact: u64,
    contact_change: &'static str,
    stiffness: u64,
    epoch: u64,
}

impl Default for Problem {
    fn default() -> Self {
        Problem::new()
    }
}

fn finite2(v: [f64; 2], what: &str) -> Result<()> {
    if v[0].is_finite() && v[1].is_finite() {
        Ok(())
    } else {
        Err(Error::argument(format!(
            "{what} ({:?}, {:?}) is not finite",
            v[0], v[1]
        )))
    }
}

impl Problem {
    /// An empty problem (no mesh, tempering [`Tempering::Auto`]).
    pub fn new() -> Problem {
        Problem {
            mesh: None,
            materials: BTreeMap::new(),
            tempering: Tempering::Auto,
            prescribed: BTreeMap::new(),
            loads: Loads::default(),
            pairs: Vec::new(),
            weighting: ContactWeighting::Auto,
            pairing_warnings: Vec::new(),
            structure: 0,
            contact: 0,
            contact_change: "nothing",
            stiffness: 0,
            epoch: 0,
        }
    }

    /// Counts a change; `structural` when it alters the structure.
    fn changed(&mut self, structural: bool) {
        self.epoch += 1;
        if structural {
            self.structure += 1;
            self.stiffness += 1;
        }
    }

    /// Counts a structural change that also remakes the contact mesh B or
    /// its parts: `what` changed, in messages ([`Problem::contact_change`]).
    fn changed_contact(&mut self, what: &'static str) {
        self.changed(true);
        self.contact += 1;
        self.contact_change = what;
    }

    /// Counts a change of the stiffness (materials, tempering) that leaves
    /// the structure alone.
    fn changed_stiffness(&mut self) {
        self.changed(false);
        self.stiffness += 1;
    }

    /// The epoch: moves with every change.
    pub fn epoch(&self) -> u64 {
        self.epoch
    }

    /// The structure epoch: moves with the mesh, its boundary edges, the
    /// set of prescribed DOFs and the contact pairs.
    pub fn structure_epoch(&self) -> u64 {
        self.structure
    }

    /// The contact epoch: moves with the mesh, its boundary edges, the
    /// contact pairs and friction on/off — what the contact mesh B and its
    /// parts are made of — but not with the set of prescribed DOFs, which
    /// changes the stiffness and the interface unknowns, not B. A load
    /// step's contact state (its active set and slip state over B) belongs
    /// to one contact epoch.
    pub fn contact_epoch(&self) -> u64 {
        self.contact
    }

    /// What moved the contact epoch last, in messages ("the mesh", "the
    /// boundary edges", "the contact pairs", "friction on/off").
    pub fn contact_change(&self) -> &'static str {
        self.contact_change
    }

    /// The stiffness epoch: moves with the structure, the materials and the
    /// tempering — not with the loads.
    pub fn stiffness_epoch(&self) -> u64 {
        self.stiffness
    }

    /// The mesh, or an error naming the missing call.
    pub fn mesh_ref(&self) -> Result<&Mesh> {
        self.mesh
            .as_ref()
            .ok_or_else(|| Error::state("no mesh: call set_mesh first"))
    }

    fn check_node(&self, node: usize) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if node >= mesh.nodes().len() {
            return Err(Error::argument(format!(
                "node {} is out of range ({} nodes, index base {})",
                node + mesh.index_base(),
                mesh.nodes().len(),
                mesh.index_base()
            )));
        }
        Ok(())
    }

    /// Replaces the mesh. Constraints, loads and contact pairs are
    /// discarded (they refer to nodes and edges); materials and tempering
    /// are kept.
    pub fn set_mesh(&mut self, mesh: Mesh) {
        self.mesh = Some(mesh);
        self.prescribed.clear();
        self.loads.clear();
        self.pairs.clear();
        self.pairing_warnings.clear();
        self.changed_contact("the mesh");
    }

    /// The mesh, if set.
    pub fn mesh(&self) -> Option<&Mesh> {
        self.mesh.as_ref()
    }

    /// Sets the tagged boundary edges (0-based nodes), replacing the
    /// previous ones ([`Mesh::set_boundary_edges`]). The loads and contact
    /// pairs already declared must still find their tags on edges that
    /// can carry them: otherwise the call is refused, naming the tag, and
    /// nothing changes.
    pub fn set_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        let new = self.mesh_ref()?.checked_edges(edges, tags, &[])?;
        self.swap_edges(new)
    }

    /// Adds tagged boundary edges (0-based nodes) to those already set
    /// ([`Mesh::add_boundary_edges`]): one group at a time.
    pub fn add_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        let mesh = self.mesh_ref()?;
        let mut new = mesh.boundary_edges().to_vec();
        new.append(&mut mesh.checked_edges(edges, tags, mesh.boundary_edges())?);
        self.swap_edges(new)
    }

    /// Puts `edges` in place of the mesh's boundary edges if every load
    /// and pair still fits them; else restores the old ones.
    fn swap_edges(&mut self, edges: Vec<BoundaryEdge>) -> Result<()> {
        let mesh = self
            .mesh
            .as_mut()
            .ok_or_else(|| Error::state("no mesh: call set_mesh first"))?;
        let old = mesh.replace_edges(edges);
        match self.revalidated_pairs() {
            Ok(pairs) => {
                self.pairs = pairs;
                // What automatic pairing said of the old edges (a tag over
                // two bodies, to be split, a reviewer's case) no longer holds.
                self.pairing_warnings.clear();
                self.changed_contact("the boundary edges");
                Ok(())
            }
            Err(e) => {
                self.mesh.as_mut().expect("a mesh").replace_edges(old);
                Err(e)
            }
        }
    }

    /// Declares the exact shape of the boundary tagged `tag`
    /// ([`Mesh::set_curve`]): refinement puts its new nodes there. It
    /// changes nothing of a solve (no epoch moves: results stay valid).
    pub fn set_curve(&mut self, tag: i32, curve: Curve) -> Result<()> {
        self.mesh
            .as_mut()
            .ok_or_else(|| Error::state("no mesh: call set_mesh first"))?
            .set_curve(tag, curve)
    }

    /// The same problem on `mesh`, a refinement of its mesh whose first
    /// nodes are the old ones (same indices) and whose node k beyond them
    /// bisects the edge `parents[k − old]` ([`crate::fem::refine`]). The
    /// materials, tempering, weighting, loads (by tag, node and body) and
    /// pairs (by tag, with their friction) carry over as they are; a new
    /// node takes a prescribed component when both ends of its edge have
    /// it, at their mean, if the edge lies on the mesh's boundary, or one
    /// of its ends inside the mesh (a constraint line through a body, such
    /// as a symmetry line), or its body is prescribed whole in that
    /// component (a rigid tool) — an interior edge joining two fixed
    /// boundary nodes (across a clamped corner) is not a fixed edge.
    /// Refused for a pair with a contact mesh of its own (its nodes do not
    /// refine), naming it.
    pub fn refined(&self, mesh: Mesh, parents: &[[usize; 2]]) -> Result<Problem> {
        if let Some(i) = self.pairs.iter().position(|p| p.user_mesh.is_some()) {
            return Err(Error::argument(format!(
                "contact pair {i} has a contact mesh of its own, which refinement cannot carry: \
                 let tfem build it (add_contact_pair)"
            )));
        }
        let old = self.mesh_ref()?;
        let first_new = old.nodes().len();
        let on_boundary = boundary_edge_set(old);
        let boundary_nodes: std::collections::HashSet<usize> =
            on_boundary.iter().flat_map(|&(p, q)| [p, q]).collect();
        let whole = wholly_prescribed(old, &self.prescribed);
        let mut prescribed = self.prescribed.clone();
        for (k, &[p, q]) in parents.iter().enumerate() {
            let v = first_new + k;
            let edge = (p.min(q), p.max(q));
            let body = mesh.node_body().get(v).copied().flatten();
            for c in 0..2 {
                let (Some(&a), Some(&b)) =
                    (prescribed.get(&(2 * p + c)), prescribed.get(&(2 * q + c)))
                else {
                    continue;
                };
                let rigid = body.is_some_and(|b| whole.contains(&(b, c)));
                let through = !boundary_nodes.contains(&p) || !boundary_nodes.contains(&q);
                if on_boundary.contains(&edge) || through || rigid {
                    prescribed.insert(2 * v + c, 0.5 * (a + b));
                }
            }
        }
        let mut refined = self.clone();
        refined.mesh = Some(mesh);
        refined.prescribed = prescribed;
        refined.pairs = refined.revalidated_pairs()?;
        refined.changed_contact("the mesh (refined)");
        Ok(refined)
    }

    /// Checks the loads and pairs against the mesh's current boundary
    /// edges; returns the pairs with their bodies found anew.
    fn revalidated_pairs(&self) -> Result<Vec<ContactPair>> {
        let mesh = self.mesh_ref()?;
        let mut tags: Vec<i32> = self.loads.edge_loads().iter().map(|l| l.0).collect();
        tags.sort_unstable();
        tags.dedup();
        for tag in tags {
            check_loaded_tag(mesh, tag).map_err(|e| {
                Error::argument(format!(
                    "a load acts on tag {tag}, which these edges would take from it: {}",
                    e.message()
                ))
            })?;
        }
        let misfit = |i: usize, p: &ContactPair, e: Error| {
            Error::contact(format!(
                "contact pair {i} (tags {}, {}) no longer fits these edges: {}",
                p.tag_a,
                p.tag_b,
                e.message()
            ))
        };
        let mut pairs = self.pairs.clone();
        for (i, p) in pairs.iter_mut().enumerate() {
            (p.body_a, p.body_b) =
                contact::pair_bodies(mesh, p.tag_a, p.tag_b).map_err(|e| misfit(i, p, e))?;
        }
        for (i, p) in pairs.iter().enumerate() {
            contact::discretisation::check_pair(mesh, &pairs, i, self.weighting_in_use())
                .map_err(|e| misfit(i, p, e))?;
        }
        Ok(pairs)
    }

    /// Sets the material of a body. Before a mesh is given any body tag is
    /// accepted; afterwards the body must exist.
    ///
    /// Axisymmetric bodies do not mix with plane ones (refused, naming a
    /// body of the other kind), do not cross the axis x = 0 (refused,
    /// naming the first node with x < 0) and do not take the mortar
    /// weighting, which integrates along straight sides without the
    /// ring's measure (refused).
    pub fn set_material(&mut self, body: i32, material: Material) -> Result<()> {
        if let Some(mesh) = &self.mesh {
            if mesh.bodies().binary_search(&body).is_err() {
                return Err(Error::new(
                    Status::InvalidMaterial,
                    format!(
                        "body {body} is not in the mesh (bodies: {:?})",
                        mesh.bodies()
                    ),
                ));
            }
        }
        let ring = material.section().is_revolution();
        if let Some((other, m)) = self
            .materials
            .iter()
            .find(|(b, m)| **b != body && m.section().is_revolution() != ring)
        {
            return Err(Error::new(
                Status::InvalidMaterial,
                format!(
                    "body {body}: a {} material cannot join body {other}, which is {}: \
                     a model is axisymmetric in every body or in none",
                    material.plane().name(),
                    m.plane().name()
                ),
            ));
        }
        if ring {
            if self.weighting == ContactWeighting::Mortar {
                return Err(Error::new(
                    Status::InvalidMaterial,
                    format!(
                        "body {body}: axisymmetric bodies take the contact mesh B (the \
                         automatic or strip weighting), not the mortar weighting"
                    ),
                ));
            }
            if let Some(mesh) = &self.mesh {
                crossing_node(mesh, Some(body))
                    .map_or(Ok(()), |v| Err(crossing_error(mesh, v, body)))?;
            }
        }
        let was_ring = self.section().is_revolution();
        self.materials.insert(body, material);
        if was_ring != ring {
            // The weighting the pairs take and the loads' measure change.
            self.changed_contact("the bodies' section (plane or axisymmetric)");
        } else {
            self.changed_stiffness();
        }
        Ok(())
    }

    /// The weighting the pairs take: the one set, except that axisymmetric
    /// bodies take B where [`ContactWeighting::Auto`] would choose the
    /// mortar weighting (it has no ring measure).
    pub fn weighting_in_use(&self) -> ContactWeighting {
        match (self.weighting, self.section().is_revolution()) {
            (ContactWeighting::Auto, true) => ContactWeighting::Strip,
            (w, _) => w,
        }
    }

    /// The material of a body.
    pub fn material(&self, body: i32) -> Option<&Material> {
        self.materials.get(&body)
    }

    /// Sets how Jmin is chosen.
    pub fn set_tempering(&mut self, tempering: Tempering) -> Result<()> {
        tempering.validate()?;
        self.tempering = tempering;
        self.changed_stiffness();
        Ok(())
    }

    /// The tempering policy.
    pub fn tempering(&self) -> Tempering {
        self.tempering
    }

    /// The λ the tempering uses (None when off or fixed): the given one, or
    /// the larger side of the mesh's bounding box for [`Tempering::Auto`].
    pub fn tempering_lambda(&self) -> Option<f64> {
        match self.tempering {
            Tempering::Auto => self.mesh.as_ref().map(|m| m.size()),
            Tempering::Lambda(l) => Some(l),
            _ => None,
        }
    }

    /// Prescribes one displacement component of a node (0-based).
    pub fn fix(&mut self, node: usize, component: Component, value: f64) -> Result<()> {
        self.check_node(node)?;
        if !value.is_finite() {
            return Err(Error::argument(format!(
                "prescribed displacement {value:?} of node {} is not finite",
                node + self.mesh_ref()?.index_base()
            )));
        }
        let g = 2 * node + component as usize;
        self.check_unprescribed_or_equal(g, value)?;
        let new_dof = self.prescribed.insert(g, value).is_none();
        self.changed(new_dof);
        Ok(())
    }

    /// Changes the value of a displacement component [`Problem::fix`]ed
    /// before: the loads of a non-proportional load history. The set of
    /// prescribed DOFs, so the stiffness, stays: a load history goes on.
    pub fn set_prescribed(&mut self, node: usize, component: Component, value: f64) -> Result<()> {
        self.check_node(node)?;
        let base = self.mesh_ref()?.index_base();
        if !value.is_finite() {
            return Err(Error::argument(format!(
                "prescribed displacement {value:?} of node {} is not finite",
                node + base
            )));
        }
        let g = 2 * node + component as usize;
        match self.prescribed.get_mut(&g) {
            None => Err(Error::argument(format!(
                "node {} {} is not prescribed: fix it first",
                node + base,
                if g % 2 == 0 { "u_x" } else { "u_y" }
            ))),
            Some(v) => {
                if v.to_bits() != value.to_bits() {
                    *v = value;
                    self.changed(false);
                }
                Ok(())
            }
        }
    }

    /// Changes the value of component `component` on every node of the
    /// edges tagged `tag`, each prescribed before ([`Problem::fix_edges`]
    /// or [`Problem::fix`]): [`Problem::set_prescribed`] for a whole tag.
    /// All or nothing: an unknown tag, a value that is not finite or a
    /// node not prescribed in that component is refused, naming it, and
    /// nothing changes.
    pub fn set_prescribed_edges(
        &mut self,
        tag: i32,
        component: Component,
        value: f64,
    ) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if !value.is_finite() {
            return Err(Error::argument(format!(
                "prescribed displacement {value:?} on tag {tag} is not finite"
            )));
        }
        let nodes = tag_nodes(mesh, tag)?;
        let c = component as usize;
        if let Some(&v) = nodes
            .iter()
            .find(|&&v| !self.prescribed.contains_key(&(2 * v + c)))
        {
            return Err(Error::argument(format!(
                "node {} {} (tag {tag}) is not prescribed: fix it first",
                v + mesh.index_base(),
                if c == 0 { "u_x" } else { "u_y" }
            )));
        }
        for v in nodes {
            self.set_prescribed(v, component, value)?;
        }
        Ok(())
    }

    /// Refuses to prescribe global DOF `g` a value other than the one it
    /// already has: one of the two would silently win (a corner shared by
    /// two constrained edges, say).
    fn check_unprescribed_or_equal(&self, g: usize, value: f64) -> Result<()> {
        match self.prescribed.get(&g) {
            Some(&old) if old != value => Err(Error::argument(format!(
                "node {} {} is already prescribed {old:?}, not {value:?}: clear the constraints \
                 to change a prescribed value",
                g / 2 + self.mesh_ref()?.index_base(),
                if g % 2 == 0 { "u_x" } else { "u_y" }
            ))),
            _ => Ok(()),
        }
    }

    /// Prescribes a component on every node of the edges tagged `tag`
    /// (all or nothing: the checks come before any change).
    pub fn fix_edges(&mut self, tag: i32, component: Component, value: f64) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if !value.is_finite() {
            return Err(Error::argument(format!(
                "prescribed displacement {value:?} on tag {tag} is not finite"
            )));
        }
        let nodes = tag_nodes(mesh, tag)?;
        for &v in &nodes {
            self.check_unprescribed_or_equal(2 * v + component as usize, value)?;
        }
        for v in nodes {
            self.fix(v, component, value)?;
        }
        Ok(())
    }

    /// Removes every prescribed displacement.
    pub fn clear_constraints(&mut self) {
        if !self.prescribed.is_empty() {
            self.prescribed.clear();
            self.changed(true);
        }
    }

    /// Prescribed displacements, as (global DOF = 2·node + component, value).
    pub fn constraints(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.prescribed.iter().map(|(&g, &v)| (g, v))
    }

    /// Whether a global DOF is prescribed.
    pub fn is_prescribed(&self, dof: usize) -> bool {
        self.prescribed.contains_key(&dof)
    }

    /// The prescribed values as a global vector (zero where free).
    pub fn prescribed_vector(&self) -> Result<Vec<f64>> {
        let mut up = vec![0.0; 2 * self.mesh_ref()?.nodes().len()];
        for (&g, &v) in &self.prescribed {
            up[g] = v;
        }
        Ok(up)
    }

    /// Applies a pressure (force per unit length, positive pushing into the
    /// body) on the edges tagged `tag`. Loads add up.
    pub fn add_pressure(&mut self, tag: i32, pressure: f64) -> Result<()> {
        if !pressure.is_finite() {
            return Err(Error::argument(format!(
                "pressure {pressure:?} is not finite"
            )));
        }
        check_loaded_tag(self.mesh_ref()?, tag)?;
        self.loads.add_edge_load(tag, EdgeLoad::Pressure(pressure));
        self.changed(false);
        Ok(())
    }

    /// Applies a traction vector (force per unit length) on the edges tagged
    /// `tag`. Loads add up.
    pub fn add_traction(&mut self, tag: i32, traction: [f64; 2]) -> Result<()> {
        finite2(traction, "traction")?;
        check_loaded_tag(self.mesh_ref()?, tag)?;
        self.loads.add_edge_load(tag, EdgeLoad::Traction(traction));
        self.changed(false);
        Ok(())
    }

    /// Adds a point force at a node (0-based).
    pub fn add_nodal_force(&mut self, node: usize, force: [f64; 2]) -> Result<()> {
        self.check_node(node)?;
        finite2(force, "nodal force")?;
        self.loads.add_nodal_force(node, force);
        self.changed(false);
        Ok(())
    }

    /// Sets the body force (per unit area) of a body.
    pub fn set_body_force(&mut self, body: i32, force: [f64; 2]) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if mesh.bodies().binary_search(&body).is_err() {
            return Err(Error::argument(format!("body {body} is not in the mesh")));
        }
        finite2(force, "body force")?;
        self.loads.set_body_force(body, force);
        self.changed(false);
        Ok(())
    }

    /// Removes every load (pressures, tractions, nodal and body forces).
    pub fn clear_loads(&mut self) {
        self.loads.clear();
        self.changed(false);
    }

    /// The assembled external load vector (2 values per node: f_x, f_y) of
    /// the current loads: consistent edge loads, nodal and body forces.
    pub fn load_vector(&self) -> Result<Vec<f64>> {
        self.loads.nodal_vector(self.mesh_ref()?, self.section())
    }

    /// The section the model's bodies stand for: rings when their
    /// materials are axisymmetric (then all are: [`Problem::set_material`]),
    /// else slabs.
    pub fn section(&self) -> Section {
        self.materials
            .values()
            .next()
            .map_or(Section::Plane, Material::section)
    }

    /// Declares a potential contact interface between the edges tagged
    /// `tag_a` (on one body) and `tag_b` (on another). Returns the pair's
    /// index. The contact mesh B is built from matching nodes when the two
    /// interfaces' nodes match, else by triangulating the strip between them
    /// (see [`contact::build`]); or hand one over with
    /// [`Problem::add_contact_pair_with_mesh`]. A pair declared already, or
    /// one whose tags share boundary edges with both tags of a declared
    /// pair (the same interface under other tags: it would count twice),
    /// is refused.
    pub fn add_contact_pair(&mut self, tag_a: i32, tag_b: i32) -> Result<usize> {
        let mesh = self.mesh_ref()?;
        let (body_a, body_b) = contact::pair_bodies(mesh, tag_a, tag_b)?;
        if self
            .pairs
            .iter()
            .any(|p| (p.tag_a, p.tag_b) == (tag_a, tag_b) || (p.tag_a, p.tag_b) == (tag_b, tag_a))
        {
            return Err(Error::contact(format!(
                "contact pair ({tag_a}, {tag_b}) is already declared"
            )));
        }
        let shared = SharedTags::around(mesh, [tag_a, tag_b]);
        if let Some(k) = shared.covered_by(&self.pairs, tag_a, tag_b) {
            let p = &self.pairs[k];
            return Err(Error::contact(format!(
                "contact pair ({tag_a}, {tag_b}) covers the interface of contact pair {k} ({}, {}) \
                 again (their tags share boundary edges): its contact would count twice",
                p.tag_a, p.tag_b
            )));
        }
        let pair = ContactPair {
            tag_a,
            tag_b,
            body_a,
            body_b,
            user_mesh: None,
            friction: 0.0,
        };
        // Discretise it now so that a bad interface is reported by this
        // call.
        let mut pairs = self.pairs.clone();
        pairs.push(pair.clone());
        let i = self.pairs.len();
        crate::contact::discretisation::check_pair(mesh, &pairs, i, self.weighting_in_use())?;
        self.pairs.push(pair);
        self.changed_contact("the contact pairs");
        Ok(self.pairs.len() - 1)
    }

    /// Declares a contact pair with a contact mesh B handed over by the user
    /// (0-based triangles over interface nodes, as made with Gmsh), each
    /// given once (a repeated triangle is refused, naming both). Its
    /// orientation is fixed where needed; returns (pair index, number of
    /// triangles flipped). The triangles are the contact: unlike
    /// [`Problem::add_contact_pair`], tags declared already or sharing
    /// edges with a declared pair are not refused (several meshes may cover
    /// parts of one interface), so a part given twice counts twice.
    pub fn add_contact_pair_with_mesh(
        &mut self,
        tag_a: i32,
        tag_b: i32,
        triangles: &[[usize; 3]],
    ) -> Result<(usize, usize)> {
        let mesh = self.mesh_ref()?;
        let (body_a, body_b) = contact::pair_bodies(mesh, tag_a, tag_b)?;
        if triangles.is_empty() {
            return Err(Error::contact("the contact mesh has no triangles"));
        }
        contact::discretisation::serves(self.weighting, self.pairs.len(), 0.0, true)?;
        let (elements, flipped) =
            contact::check_user_mesh(mesh, self.pairs.len(), tag_a, tag_b, triangles)?;
        self.pairs.push(ContactPair {
            tag_a,
            tag_b,
            body_a,
            body_b,
            user_mesh: Some(elements.iter().map(|e| e.nodes).collect()),
            friction: 0.0,
        });
        self.changed_contact("the contact pairs");
        Ok((self.pairs.len() - 1, flipped))
    }

    /// Sets Coulomb's friction coefficient μ of contact pair `pair` (0, the
    /// default, is frictionless, bit for bit; docs/method.md §6.15). μ must
    /// be finite and ≥ 0 (a tied interface is [`ContactLaw::Stick`]).
    /// Changing μ starts a new load history; turning friction on or off
    /// changes the pair's contact parts (and, under the automatic
    /// weighting, may give it another family: a frictional pair keeps B),
    /// checked now.
    ///
    /// [`ContactLaw::Stick`]: crate::contact::ContactLaw::Stick
    pub fn set_friction(&mut self, pair: usize, mu: f64) -> Result<()> {
        let n = self.pairs.len();
        let Some(p) = self.pairs.get(pair) else {
            return Err(crate::error::no_pair(pair, n));
        };
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(Error::argument(format!(
                "friction coefficient mu = {mu:?} of contact pair {pair} must be finite and >= 0"
            )));
        }
        contact::discretisation::serves(self.weighting, pair, mu, p.user_mesh.is_some())?;
        if p.friction.to_bits() == mu.to_bits() {
            return Ok(());
        }
        // Turning friction on or off changes the pair's contact parts (a
        // frictional element also carries its slip), and under the
        // automatic weighting may change its family: the pair is checked
        // now. Otherwise μ decides which unknowns are on the interface, not
        // the structure: a new K₁, the same pattern.
        let rebuild = (p.friction > 0.0) != (mu > 0.0);
        let mut pairs = self.pairs.clone();
        pairs[pair].friction = mu;
        if rebuild {
            contact::discretisation::check_pair(
                self.mesh_ref()?,
                &pairs,
                pair,
                self.weighting_in_use(),
            )?;
        }
        self.pairs = pairs;
        match rebuild {
            true => self.changed_contact("friction on/off"),
            false => self.changed_stiffness(),
        }
        Ok(())
    }

    /// Removes every contact pair.
    pub fn clear_contact_pairs(&mut self) {
        self.pairing_warnings.clear();
        if !self.pairs.is_empty() {
            self.pairs.clear();
            self.changed_contact("the contact pairs");
        }
    }

    /// What automatic pairing ([`Problem::add_contact_pairs_auto`]) left
    /// out and why: a tag over several bodies, an interface found again
    /// under other tags. Kept, without repeats, until the contact pairs
    /// are cleared or the mesh is replaced.
    pub fn pairing_warnings(&self) -> &[String] {
        &self.pairing_warnings
    }

    /// The declared contact pairs.
    pub fn contact_pairs(&self) -> &[ContactPair] {
        &self.pairs
    }

    /// Sets how every pair's contact energy is weighted along its
    /// interface; refuses a weighting that cannot serve a declared pair
    /// (the mortar weighting a pair with friction or a contact mesh of its
    /// own), naming it. A change remakes the contact structures (the
    /// matrix pattern holds the mortar couplings) and ends any load
    /// history.
    pub fn set_contact_weighting(&mut self, weighting: ContactWeighting) -> Result<()> {
        if weighting == ContactWeighting::Mortar && self.section().is_revolution() {
            return Err(Error::argument(
                "the mortar weighting integrates along the sides without the ring's measure: \
                 axisymmetric bodies take the automatic or strip weighting",
            ));
        }
        for (i, p) in self.pairs.iter().enumerate() {
            contact::discretisation::serves(weighting, i, p.friction, p.user_mesh.is_some())?;
        }
        if self.weighting != weighting {
            self.weighting = weighting;
            self.changed_contact("the contact weighting");
        }
        Ok(())
    }

    /// How the pairs' contact energy is weighted.
    pub fn contact_weighting(&self) -> ContactWeighting {
        self.weighting
    }

    /// The mesh, once every body has a material and the pairs fit the kind
    /// of solve (`with_contact`).
    pub fn check_ready(&self, with_contact: bool) -> Result<&Mesh> {
        let mesh = self.mesh_ref()?;
        for &b in mesh.bodies() {
            if !self.materials.contains_key(&b) {
                return Err(Error::new(
                    Status::InvalidMaterial,
                    format!("body {b} has no material: call set_material"),
                ));
            }
        }
        if self.section().is_revolution() {
            self.check_axis(mesh)?;
        }
        match (with_contact, self.pairs.is_empty()) {
            (false, false) => Err(Error::state(format!(
                "the model has {} contact pair(s): use solve_contact",
                self.pairs.len()
            ))),
            (true, true) => Err(Error::state("no contact pair: call add_contact_pair first")),
            _ => Ok(mesh),
        }
    }

    /// Checks the nodes of an axisymmetric model against the axis: none
    /// across it (x < 0, beyond round-off), and u_r prescribed to 0 on every
    /// node on it (|x| within 10⁻¹² of the model's size), where the ring
    /// is a line and its radial displacement has no meaning.
    fn check_axis(&self, mesh: &Mesh) -> Result<()> {
        if let Some(v) = crossing_node(mesh, None) {
            return Err(crossing_error(
                mesh,
                v,
                mesh.node_body()[v].unwrap_or_default(),
            ));
        }
        let tol = AXIS_TOLERANCE * mesh.size();
        let used = mesh.node_body();
        for (v, x) in mesh.nodes().iter().enumerate() {
            if x[0].abs() > tol || used[v].is_none() {
                continue;
            }
            match self.prescribed.get(&(2 * v)) {
                Some(0.0) => {}
                other => {
                    let given = other.map_or("free".to_string(), |u| format!("prescribed to {u}"));
                    return Err(Error::new(
                        Status::InvalidArgument,
                        format!(
                            "{} lies on the axis (x = {}) of an axisymmetric model and its u_r \
                             is {given}: fix u_r = 0 on the axis (its edges' tag or its nodes)",
                            mesh.node_name(v),
                            x[0]
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The loop over the body elements (every body needs a material:
    /// [`Problem::check_ready`]).
    pub fn elements(&self) -> Result<ElementLoop<'_>> {
        Ok(ElementLoop::new(
            self.mesh_ref()?,
            &self.materials,
            self.tempering,
        ))
    }
}

/// The edges of `mesh`'s boundary (used by one triangle), as (low, high)
/// node pairs.
fn boundary_edge_set(mesh: &Mesh) -> std::collections::HashSet<(usize, usize)> {
    let mut count: std::collections::HashMap<(usize, usize), u32> = Default::default();
    for t in mesh.triangles() {
        for k in 0..3 {
            let (p, q) = (t[k], t[(k + 1) % 3]);
            *count.entry((p.min(q), p.max(q))).or_insert(0) += 1;
        }
    }
    count
        .into_iter()
        .filter(|(_, n)| *n == 1)
        .map(|(e, _)| e)
        .collect()
}

/// The (body, component) pairs prescribed at every node of the body.
fn wholly_prescribed(
    mesh: &Mesh,
    prescribed: &BTreeMap<usize, f64>,
) -> std::collections::HashSet<(i32, usize)> {
    let mut all: BTreeMap<(i32, usize), bool> = BTreeMap::new();
    for (v, body) in mesh.node_body().iter().enumerate() {
        let Some(b) = body else { continue };
        for c in 0..2 {
            let e = all.entry((*b, c)).or_insert(true);
            *e &= prescribed.contains_key(&(2 * v + c));
        }
    }
    all.into_iter()
        .filter(|(_, w)| *w)
        .map(|(k, _)| k)
        .collect()
}

/// How close to the axis, relative to the model's size, a node of an
/// axisymmetric model counts as on it (and further out to the left, as
/// across it).
const AXIS_TOLERANCE: f64 = 1e-12;

/// The first node of `body` (of any body: `None`) that lies across the
/// axis, x < −10⁻¹² × the model's size.
fn crossing_node(mesh: &Mesh, body: Option<i32>) -> Option<usize> {
    let tol = AXIS_TOLERANCE * mesh.size();
    let used = mesh.node_body();
    mesh.nodes().iter().enumerate().position(|(v, x)| {
        x[0] < -tol && used[v].is_some_and(|b| body.is_none_or(|want| want == b))
    })
}

fn crossing_error(mesh: &Mesh, v: usize, body: i32) -> Error {
    Error::new(
        Status::InvalidMaterial,
        format!(
            "body {body} crosses the axis of an axisymmetric model: {} has x = {} < 0 \
             (x is the radius)",
            mesh.node_name(v),
            mesh.nodes()[v][0]
        ),
    )
}

/// Automatic contact pairing (docs/method.md §6.16).
impl Problem {
    /// Declares a contact pair for every two tags of different bodies
    /// whose boundary edges face each other within `tolerance`, a distance
    /// in model units (some edge of the one within `tolerance` of some edge
    /// of the other, normals opposed, each in front of the other, overlapping along the
    /// interface, no third body between them: see
    /// [`contact::pairing`]). `tags`: the tags to consider (each must name
    /// boundary edges of one body, else an error naming it), or `None` for
    /// every tag that can be a contact side. Pairs already declared (either
    /// way round) are skipped, and so is an interface found again under
    /// other tags that share its edges (the pair with the fewest edges is
    /// kept); tags of one body never pair. What is left out without an
    /// error — with `tags` = `None`, a tag whose edges bound several
    /// bodies; an interface found again under other tags — is named in a
    /// warning ([`Problem::pairing_warnings`]). Returns the
    /// indices of the pairs added, in increasing (tag_a, tag_b) order with
    /// tag_a < tag_b: empty when nothing faces within the tolerance. All
    /// or nothing: if the contact mesh of one pair cannot be built, the
    /// error names it and no pair is added.
    pub fn add_contact_pairs_auto(
        &mut self,
        tags: Option<&[i32]>,
        tolerance: f64,
    ) -> Result<Vec<usize>> {
        let mesh = self.mesh_ref()?;
        let mut found = contact::pairing::facing_pairs(mesh, tags, tolerance)?;
        // Where tags share edges (a file's "whole boundary" group beside
        // its faces), one interface is found under several pairs of tags:
        // the most specific pair (fewest edges) is kept, the others would
        // count its contact again.
        let shared = SharedTags::of(mesh)?;
        found.sort_by_key(|f| {
            (
                shared.edges(f.tag_a) + shared.edges(f.tag_b),
                f.tag_a,
                f.tag_b,
            )
        });
        // A tag over several bodies cannot be a side: left out, and said
        // (searching every tag; a tag given by name is refused instead).
        let mut warnings = match tags {
            None => several_bodies_warnings(mesh),
            Some(_) => Vec::new(),
        };
        let mut new: Vec<ContactPair> = Vec::new();
        for f in found {
            let declared = self.pairs.iter().chain(&new).any(|p: &ContactPair| {
                (p.tag_a, p.tag_b) == (f.tag_a, f.tag_b) || (p.tag_a, p.tag_b) == (f.tag_b, f.tag_a)
            });
            if declared {
                continue;
            }
            let kept = shared
                .covered_by(&self.pairs, f.tag_a, f.tag_b)
                .map(|k| &self.pairs[k])
                .or_else(|| shared.covered_by(&new, f.tag_a, f.tag_b).map(|k| &new[k]));
            if let Some(p) = kept {
                warnings.push(paired_already_warning(&f, p));
                continue;
            }
            // Built now so that a bad interface is reported by this call.
            let index = self.pairs.len() + new.len();
            contact::build(mesh, index, f.tag_a, f.tag_b)
                .map_err(|e| unbuilt_pair_error(&f, tolerance, &e))?;
            new.push(ContactPair {
                tag_a: f.tag_a,
                tag_b: f.tag_b,
                body_a: f.body_a,
                body_b: f.body_b,
                user_mesh: None,
                friction: 0.0,
            });
        }
        for w in warnings {
            if !self.pairing_warnings.contains(&w) {
                self.pairing_warnings.push(w);
            }
        }
        let first = self.pairs.len();
        new.sort_by_key(|p| (p.tag_a, p.tag_b));
        if !new.is_empty() {
            self.pairs.append(&mut new);
            self.changed_contact("the contact pairs");
        }
        Ok((first..self.pairs.len()).collect())
    }
}

/// The nodes of the boundary edges tagged `tag` (an edge's two in turn),
/// refused when no edge has that tag.
fn tag_nodes(mesh: &Mesh, tag: i32) -> Result<Vec<usize>> {
    let nodes: Vec<usize> = mesh
        .boundary_edges()
        .iter()
        .filter(|e| e.tag == tag)
        .flat_map(|e| e.nodes)
        .collect();
    match nodes.is_empty() {
        true => Err(Error::argument(format!("no boundary edge has tag {tag}"))),
        false => Ok(nodes),
    }
}

/// What automatic pairing leaves out when it searches every tag: each tag
/// whose edges bound several bodies, named in a warning.
fn several_bodies_warnings(mesh: &Mesh) -> Vec<String> {
    contact::pairing::tags_on_several_bodies(mesh)
        .into_iter()
        .map(|(tag, bodies)| {
            let bodies: Vec<String> = bodies.iter().map(|b| b.to_string()).collect();
            format!(
                "automatic pairing left out tag {tag}: its edges bound bodies {}, and a \
                 contact side must lie on one body; if part of it faces another body, give \
                 that part a tag of its own, or declare the pair by hand",
                bodies.join(", ")
            )
        })
        .collect()
}

/// The warning for facing tags `f` left unpaired because pair `p` pairs
/// their interface already under tags that share its edges.
fn paired_already_warning(f: &contact::pairing::FacingPair, p: &ContactPair) -> String {
    format!(
        "automatic pairing did not pair tags {} (body {}) and {} (body {}), which face each \
         other: they share edges with the tags of contact pair ({}, {}), which pairs that \
         interface already (a second pair would count its contact twice); to pair it under \
         tags {} and {} instead, clear the contact pairs and declare that pair by hand",
        f.tag_a, f.body_a, f.tag_b, f.body_b, p.tag_a, p.tag_b, f.tag_a, f.tag_b
    )
}

/// The error for facing tags `f` (found within `tolerance`) whose contact
/// mesh cannot be built, with the reason `e`.
fn unbuilt_pair_error(f: &contact::pairing::FacingPair, tolerance: f64, e: &Error) -> Error {
    Error::contact(format!(
        "automatic pairing: tags {} (body {}) and {} (body {}) face each other ({:e} apart, \
         tolerance {tolerance:e}), but their contact mesh cannot be built: {}",
        f.tag_a,
        f.body_a,
        f.tag_b,
        f.body_b,
        f.distance,
        e.message()
    ))
}

/// Boundary tags that share edges (an edge listed under several tags: a
/// Gmsh file's curve in several physical groups), and each tag's number
/// of edges. Empty maps in the common case of one tag per edge.
struct SharedTags {
    with: BTreeMap<i32, BTreeSet<i32>>,
    edges: BTreeMap<i32, usize>,
}

impl SharedTags {
    fn of(mesh: &Mesh) -> Result<SharedTags> {
        let list = mesh.boundary_edges();
        let mut keyed: Vec<([usize; 2], i32)> =
            crate::error::reserved(list.len(), "the check of tags sharing edges")?;
        keyed.extend(list.iter().map(|e| {
            let [p, q] = e.nodes;
            ([p.min(q), p.max(q)], e.tag)
        }));
        keyed.sort_unstable();
        let mut shared = SharedTags {
            with: BTreeMap::new(),
            edges: BTreeMap::new(),
        };
        for &(_, tag) in &keyed {
            *shared.edges.entry(tag).or_default() += 1;
        }
        for run in keyed.chunk_by(|a, b| a.0 == b.0) {
            for &(_, t) in run {
                for &(_, u) in run {
                    if t != u {
                        shared.with.entry(t).or_default().insert(u);
                    }
                }
            }
        }
        Ok(shared)
    }

    /// The tags sharing edges with `tags` alone, in one pass over the
    /// boundary edges (a pair declared by hand: no sort of every edge per
    /// call). Enough for [`SharedTags::covered_by`] of a pair of them.
    fn around(mesh: &Mesh, tags: [i32; 2]) -> SharedTags {
        let key = |e: &BoundaryEdge| {
            let [p, q] = e.nodes;
            [p.min(q), p.max(q)]
        };
        let list = mesh.boundary_edges();
        let mut owners: HashMap<[usize; 2], Vec<i32>> = HashMap::new();
        for e in list.iter().filter(|e| tags.contains(&e.tag)) {
            owners.entry(key(e)).or_default().push(e.tag);
        }
        let mut with: BTreeMap<i32, BTreeSet<i32>> = BTreeMap::new();
        for e in list {
            if let Some(ts) = owners.get(&key(e)) {
                for &t in ts.iter().filter(|&&t| t != e.tag) {
                    with.entry(t).or_default().insert(e.tag);
                }
            }
        }
        SharedTags {
            with,
            edges: BTreeMap::new(),
        }
    }

    /// The number of boundary edges of `tag`.
    fn edges(&self, tag: i32) -> usize {
        self.edges.get(&tag).copied().unwrap_or(0)
    }

    /// Whether `u` is `t` or shares an edge with it.
    fn near(&self, t: i32, u: i32) -> bool {
        t == u || self.with.get(&t).is_some_and(|s| s.contains(&u))
    }

    /// The first of `pairs` whose two sides share edges with the sides of
    /// (tag_a, tag_b), either way round: the same interface again.
    fn covered_by(&self, pairs: &[ContactPair], tag_a: i32, tag_b: i32) -> Option<usize> {
        pairs.iter().position(|p| {
            (self.near(tag_a, p.tag_a) && self.near(tag_b, p.tag_b))
                || (self.near(tag_a, p.tag_b) && self.near(tag_b, p.tag_a))
        })
    }
}
