//! The model: a mesh, materials per body, tempering, constraints, loads and
//! contact pairs; the solves and the results they produce.
//!
//! Every mutating call either succeeds or leaves the model exactly as it
//! was. Any change of the problem discards previous results; changes of the
//! structure (mesh, set of prescribed DOFs, contact pairs) also discard the
//! cached sparsity pattern and symbolic factorisation, which are otherwise
//! reused by later solves.

use std::collections::{BTreeMap, HashSet};
use std::time::Instant;

use rayon::prelude::*;

use crate::assembly::{Columns, DofMap, NOT_FREE, Pattern, Slots};
use crate::condensation::{ElementMatrix, Interface};
use crate::contact::{
    self, ContactElement, ContactOptions, ContactPair, ContactStiffness, InversionTest,
    contact_pressure, contact_stiffness, law_matrix, linearised_opening, opening_coefficient,
};
use crate::element::{
    Jmin, Tempering, TriGeometry, b_hat, elasticity_stiffness, elasticity_stiffness_into,
    jmin_of_lambda, tempered_jacobian,
};
use crate::error::{Error, Result, Status};
use crate::material::Material;
use crate::mesh::Mesh;
use crate::ordering::Ordering;
use crate::solution::{ContactReport, IterationRecord, SolveInfo, SystemMatrix, Timings};
use crate::solver::{Cholesky, FactorError};

/// A displacement component.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Component {
    /// Horizontal (u).
    X = 0,
    /// Vertical (v).
    Y = 1,
}

impl Component {
    /// Decodes the C ABI integer (0 = x, 1 = y).
    pub fn from_i32(value: i32) -> Option<Component> {
        match value {
            0 => Some(Component::X),
            1 => Some(Component::Y),
            _ => None,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum EdgeLoad {
    Pressure(f64),
    Traction([f64; 2]),
}

/// A solved state.
#[derive(Debug, Clone)]
struct Solved {
    u: Vec<f64>,
    f_ext: Vec<f64>,
    info: SolveInfo,
    contact: Option<ContactSolved>,
}

#[derive(Debug, Clone)]
struct ContactSolved {
    active: Vec<bool>,
    pressure: Vec<f64>,
    report: ContactReport,
    params: Vec<ContactParams>,
}

/// Per-element contact parameters: constitutive matrix and tempered J.
#[derive(Debug, Clone)]
struct ContactParams {
    d: [[f64; 3]; 3],
    t: f64,
}

/// The well-shaped elements that tempering softens: how many, and the
/// first.
type Softened = (usize, Option<usize>);

struct Cache {
    epoch: u64,
    dofs: DofMap,
    pattern: Pattern,
    /// The symbolic analysis, made on first need.
    chol: Option<Analysed>,
    contact: Vec<ContactElement>,
    /// Storage for the values on `pattern`, allocated with it and lent to
    /// every solve, which assembles into it and gives it back. Its pages
    /// are faulted in once per mesh, as the pattern is built once: faulting
    /// a fresh array in took 0.035 s of the 0.235 s body assembly at 1M
    /// unknowns.
    values: Vec<f64>,
    /// Each mesh triangle's [`Slots`] in `pattern`.
    slots: Vec<Slots>,
}

/// A symbolic analysis and what it was made for.
struct Analysed {
    /// The unknowns numbered last (the condensed contact interface, or none).
    last: Vec<usize>,
    /// The value positions it was told are zero.
    zeros: Vec<usize>,
    chol: Cholesky,
}

/// What a solve needs of the analysis.
struct Wanted<'a> {
    /// The unknowns to number last; `None` accepts any.
    last: Option<&'a [usize]>,
    /// Value positions that are zero in every matrix of this solve, for a
    /// new analysis (see [`structural_zeros`]).
    zeros: &'a [usize],
    /// Whether a value position is zero in every matrix of this solve: an
    /// existing analysis fits only while all of its zeros still are.
    is_zero: &'a dyn Fn(usize) -> bool,
}

/// The factorisation object of `slot`, analysed as `want` asks.
/// (Re-)analyses, timed, when needed.
fn analysed<'a>(
    slot: &'a mut Option<Analysed>,
    pattern: &Pattern,
    coords: impl FnOnce() -> Vec<[f64; 2]>,
    (ordering, parallel_subtrees): (Ordering, bool),
    want: Wanted<'_>,
    timings: &mut Timings,
) -> Result<&'a mut Cholesky> {
    let fits = slot.as_ref().is_some_and(|a| {
        want.last.is_none_or(|last| a.last == last) && a.zeros.iter().all(|&p| (want.is_zero)(p))
    });
    if !fits {
        let t0 = Instant::now();
        let last = want.last.unwrap_or(&[]);
        // Drop the old factor first: two at once may not fit in memory.
        *slot = None;
        // The unknowns' coordinates are only needed here (17 MB at 1M
        // unknowns), so they are not kept.
        let chol = Cholesky::analyse(
            pattern,
            ordering,
            Some(&coords()),
            last,
            want.zeros,
            parallel_subtrees,
        )?;
        *slot = Some(Analysed {
            last: last.to_vec(),
            zeros: want.zeros.to_vec(),
            chol,
        });
        timings.analysis += t0.elapsed().as_secs_f64();
    }
    Ok(&mut slot.as_mut().expect("just analysed").chol)
}

/// Value positions that hold zero in every matrix of a contact solve:
/// zero in the body part `body` and in every contact element's matrix.
/// The pattern couples nodes, every unknown of one with every unknown of
/// the other; a frictionless element with an axis-aligned normal couples
/// only the normal components, so that the tangential unknowns of the two
/// surfaces are not coupled at all. Sorted.
fn structural_zeros(
    pattern: &Pattern,
    body: &[f64],
    unknowns: &[[Option<usize>; 6]],
    stiffness: &[ContactStiffness],
) -> Vec<usize> {
    let (mut zero, mut nonzero) = (Vec::new(), Vec::new());
    for (u, cs) in unknowns.iter().zip(stiffness) {
        for a in 0..6 {
            for b in a..6 {
                let (Some(i), Some(j)) = (u[a], u[b]) else {
                    continue;
                };
                let Some(p) = pattern.position(i, j) else {
                    continue;
                };
                if cs.k[a * 6 + b] != 0.0 || cs.k[b * 6 + a] != 0.0 || body[p] != 0.0 {
                    nonzero.push(p);
                } else {
                    zero.push(p);
                }
            }
        }
    }
    nonzero.sort_unstable();
    zero.sort_unstable();
    zero.dedup();
    zero.retain(|p| nonzero.binary_search(p).is_err());
    zero
}

/// A 2D elasticity model solved with tempered P1 elements.
pub struct Model {
    mesh: Option<Mesh>,
    materials: BTreeMap<i32, Material>,
    tempering: Tempering,
    prescribed: BTreeMap<usize, f64>,
    edge_loads: Vec<(i32, EdgeLoad)>,
    nodal_forces: Vec<(usize, [f64; 2])>,
    body_forces: BTreeMap<i32, [f64; 2]>,
    pairs: Vec<ContactPair>,
    solved: Option<Solved>,
    cache: Option<Cache>,
    epoch: u64,
    solve_warnings: Vec<String>,
    ordering: Ordering,
    parallel_subtrees: bool,
}

impl Default for Model {
    fn default() -> Self {
        Model::new()
    }
}

fn finite2(v: [f64; 2], what: &str) -> Result<()> {
    if v[0].is_finite() && v[1].is_finite() {
        Ok(())
    } else {
        Err(Error::argument(format!(
            "{what} ({}, {}) is not finite",
            v[0], v[1]
        )))
    }
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

impl Model {
    /// An empty model (no mesh, default tempering [`Tempering::Auto`]).
    pub fn new() -> Model {
        Model {
            mesh: None,
            materials: BTreeMap::new(),
            tempering: Tempering::Auto,
            prescribed: BTreeMap::new(),
            edge_loads: Vec::new(),
            nodal_forces: Vec::new(),
            body_forces: BTreeMap::new(),
            pairs: Vec::new(),
            solved: None,
            cache: None,
            epoch: 0,
            solve_warnings: Vec::new(),
            ordering: Ordering::Auto,
            parallel_subtrees: true,
        }
    }

    /// Chooses the fill-reducing ordering of the factorisation (default
    /// [`Ordering::Auto`]). Results do not depend on it beyond round-off.
    pub fn set_ordering(&mut self, ordering: Ordering) {
        if self.ordering != ordering {
            self.ordering = ordering;
            self.cache = None;
        }
    }

    /// Factorises the two subtrees of a nested-dissection ordering
    /// concurrently, the separator as a dense block (default on; it takes
    /// effect from 20 000 unknowns with two threads or more). Off: one faer
    /// factorisation of the whole tree, parallel only inside its dense
    /// blocks. Results do not depend on it beyond round-off.
    pub fn set_parallel_subtrees(&mut self, on: bool) {
        if self.parallel_subtrees != on {
            self.parallel_subtrees = on;
            self.cache = None;
        }
    }

    fn changed_structure(&mut self) {
        self.epoch += 1;
        self.solved = None;
    }

    fn mesh_ref(&self) -> Result<&Mesh> {
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

    /// Replaces the mesh. Constraints, loads, contact pairs and results are
    /// discarded (they refer to nodes and edges); materials and tempering
    /// are kept.
    pub fn set_mesh(&mut self, mesh: Mesh) {
        self.mesh = Some(mesh);
        self.prescribed.clear();
        self.edge_loads.clear();
        self.nodal_forces.clear();
        self.body_forces.clear();
        self.pairs.clear();
        self.cache = None;
        self.solve_warnings.clear();
        self.changed_structure();
    }

    /// The mesh, if set.
    pub fn mesh(&self) -> Option<&Mesh> {
        self.mesh.as_ref()
    }

    /// Sets the tagged boundary edges (0-based nodes). See
    /// [`Mesh::set_boundary_edges`].
    pub fn set_boundary_edges(&mut self, edges: &[[usize; 2]], tags: &[i32]) -> Result<()> {
        let mesh = self
            .mesh
            .as_mut()
            .ok_or_else(|| Error::state("no mesh: call set_mesh first"))?;
        mesh.set_boundary_edges(edges, tags)?;
        self.changed_structure();
        Ok(())
    }

    /// Sets the material of a body. Before a mesh is given any body tag is
    /// accepted; afterwards the body must exist.
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
        self.materials.insert(body, material);
        self.solved = None;
        Ok(())
    }

    /// The material of a body.
    pub fn material(&self, body: i32) -> Option<&Material> {
        self.materials.get(&body)
    }

    /// Sets how Jmin is chosen.
    pub fn set_tempering(&mut self, tempering: Tempering) -> Result<()> {
        tempering.validate()?;
        self.tempering = tempering;
        self.solved = None;
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
                "prescribed displacement {value} of node {} is not finite",
                node + self.mesh_ref()?.index_base()
            )));
        }
        let g = 2 * node + component as usize;
        if self.prescribed.insert(g, value).is_none() {
            self.changed_structure();
        } else {
            self.solved = None;
        }
        Ok(())
    }

    /// Prescribes a component on every node of the edges tagged `tag`
    /// (all or nothing: the checks come before any change).
    pub fn fix_edges(&mut self, tag: i32, component: Component, value: f64) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if !value.is_finite() {
            return Err(Error::argument(format!(
                "prescribed displacement {value} on tag {tag} is not finite"
            )));
        }
        let nodes: Vec<usize> = mesh
            .boundary_edges()
            .iter()
            .filter(|e| e.tag == tag)
            .flat_map(|e| e.nodes)
            .collect();
        if nodes.is_empty() {
            return Err(Error::argument(format!("no boundary edge has tag {tag}")));
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
            self.changed_structure();
        }
    }

    /// Prescribed displacements, as (global DOF = 2·node + component, value).
    pub fn constraints(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.prescribed.iter().map(|(&g, &v)| (g, v))
    }

    fn check_loaded_tag(&self, tag: i32) -> Result<()> {
        let mesh = self.mesh_ref()?;
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

    /// Applies a pressure (force per unit length, positive pushing into the
    /// body) on the edges tagged `tag`. Loads add up.
    pub fn add_pressure(&mut self, tag: i32, pressure: f64) -> Result<()> {
        if !pressure.is_finite() {
            return Err(Error::argument(format!(
                "pressure {pressure} is not finite"
            )));
        }
        self.check_loaded_tag(tag)?;
        self.edge_loads.push((tag, EdgeLoad::Pressure(pressure)));
        self.solved = None;
        Ok(())
    }

    /// Applies a traction vector (force per unit length) on the edges tagged
    /// `tag`. Loads add up.
    pub fn add_traction(&mut self, tag: i32, traction: [f64; 2]) -> Result<()> {
        finite2(traction, "traction")?;
        self.check_loaded_tag(tag)?;
        self.edge_loads.push((tag, EdgeLoad::Traction(traction)));
        self.solved = None;
        Ok(())
    }

    /// Adds a point force at a node (0-based).
    pub fn add_nodal_force(&mut self, node: usize, force: [f64; 2]) -> Result<()> {
        self.check_node(node)?;
        finite2(force, "nodal force")?;
        self.nodal_forces.push((node, force));
        self.solved = None;
        Ok(())
    }

    /// Sets the body force (per unit area) of a body.
    pub fn set_body_force(&mut self, body: i32, force: [f64; 2]) -> Result<()> {
        let mesh = self.mesh_ref()?;
        if mesh.bodies().binary_search(&body).is_err() {
            return Err(Error::argument(format!("body {body} is not in the mesh")));
        }
        finite2(force, "body force")?;
        self.body_forces.insert(body, force);
        self.solved = None;
        Ok(())
    }

    /// Removes every load (pressures, tractions, nodal and body forces).
    pub fn clear_loads(&mut self) {
        self.edge_loads.clear();
        self.nodal_forces.clear();
        self.body_forces.clear();
        self.solved = None;
    }

    /// Declares a potential contact interface between the edges tagged
    /// `tag_a` (on one body) and `tag_b` (on another). Returns the pair's
    /// index. The contact mesh B is built from matching nodes when the two
    /// interfaces' nodes match, else by triangulating the strip between them
    /// (see [`contact::build`]); or hand one over with
    /// [`Model::add_contact_pair_with_mesh`].
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
        // Build it now so that a bad interface is reported by this call.
        contact::build(mesh, self.pairs.len(), tag_a, tag_b)?;
        self.pairs.push(ContactPair {
            tag_a,
            tag_b,
            body_a,
            body_b,
            user_mesh: None,
        });
        self.changed_structure();
        Ok(self.pairs.len() - 1)
    }

    /// Declares a contact pair with a contact mesh B handed over by the user
    /// (0-based triangles over interface nodes, as made with Gmsh). Its
    /// orientation is fixed where needed; returns (pair index, number of
    /// triangles flipped).
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
        let (elements, flipped) =
            contact::check_user_mesh(mesh, self.pairs.len(), tag_a, tag_b, triangles)?;
        self.pairs.push(ContactPair {
            tag_a,
            tag_b,
            body_a,
            body_b,
            user_mesh: Some(elements.iter().map(|e| e.nodes).collect()),
        });
        self.changed_structure();
        Ok((self.pairs.len() - 1, flipped))
    }

    /// Removes every contact pair.
    pub fn clear_contact_pairs(&mut self) {
        if !self.pairs.is_empty() {
            self.pairs.clear();
            self.changed_structure();
        }
    }

    /// The declared contact pairs.
    pub fn contact_pairs(&self) -> &[ContactPair] {
        &self.pairs
    }

    /// Mesh warnings plus those of the last solve (e.g. tempering of
    /// well-shaped elements).
    pub fn warnings(&self) -> Vec<String> {
        let mut w: Vec<String> = self
            .mesh
            .as_ref()
            .map(|m| m.warnings().to_vec())
            .unwrap_or_default();
        w.extend(self.solve_warnings.iter().cloned());
        w
    }

    fn body_jmin(&self, mesh: &Mesh) -> impl Fn(&TriGeometry) -> Jmin + use<> {
        let tempering = self.tempering;
        let size = mesh.size();
        move |geo: &TriGeometry| tempering.jmin(geo, size)
    }

    fn check_ready(&self, with_contact: bool) -> Result<&Mesh> {
        let mesh = self.mesh_ref()?;
        for &b in mesh.bodies() {
            if !self.materials.contains_key(&b) {
                return Err(Error::new(
                    Status::InvalidMaterial,
                    format!("body {b} has no material: call set_material"),
                ));
            }
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

    /// Solves a scene without contact. On error the model is unchanged.
    pub fn solve(&mut self) -> Result<SolveInfo> {
        self.run(None).map(|s| s.info)
    }

    /// Solves the contact problem with the active-set loop of METHOD.md §3.
    /// On error (singular, not converged) the model is unchanged.
    pub fn solve_contact(&mut self, options: &ContactOptions) -> Result<ContactReport> {
        options.validate()?;
        let solved = self.run(Some(*options))?;
        Ok(solved
            .contact
            .as_ref()
            .map(|c| c.report.clone())
            .expect("a contact solve has a contact state"))
    }

    fn run(&mut self, options: Option<ContactOptions>) -> Result<&Solved> {
        let t_start = Instant::now();
        self.check_ready(options.is_some())?;
        let mut timings = Timings::default();
        let cache = match self.cache.take() {
            Some(c) if c.epoch == self.epoch => c,
            _ => {
                let t0 = Instant::now();
                let c = self.analyse()?;
                timings.analysis = t0.elapsed().as_secs_f64();
                c
            }
        };
        let mut cache = cache;
        let result = self.run_with(&mut cache, options, &mut timings);
        self.cache = Some(cache);
        let (solved, warnings) = result?;
        let mut solved = solved;
        solved.info.timings.analysis = timings.analysis;
        solved.info.timings.total = t_start.elapsed().as_secs_f64();
        if let Some(c) = solved.contact.as_mut() {
            c.report.info = solved.info;
        }
        self.solve_warnings = warnings;
        self.solved = Some(solved);
        Ok(self.solved.as_ref().expect("just stored"))
    }

    fn analyse(&self) -> Result<Cache> {
        let mesh = self.mesh_ref()?;
        let n_nodes = mesh.nodes().len();
        let used = mesh.node_body();
        let dofs = DofMap::new(n_nodes, 2, |g| {
            used[g / 2].is_some() && !self.prescribed.contains_key(&g)
        });
        let mut contact = Vec::new();
        for (i, p) in self.pairs.iter().enumerate() {
            let mut elements = match &p.user_mesh {
                None => contact::build(mesh, i, p.tag_a, p.tag_b)?,
                Some(tris) => contact::check_user_mesh(mesh, i, p.tag_a, p.tag_b, tris)?.0,
            };
            contact.append(&mut elements);
        }
        // The pattern holds every element of B from the start (stored zeros
        // while inactive) so the symbolic analysis survives activation.
        let mut elements: Vec<[usize; 3]> = mesh.triangles().to_vec();
        elements.extend(contact.iter().map(|e| e.nodes));
        let pattern = Pattern::build(&dofs, n_nodes, &elements);
        let values = faulted_in(pattern.nnz());
        let mut slots = vec![Slots::SEARCH; mesh.triangles().len()];
        const CHUNK: usize = 1 << 14;
        slots
            .par_chunks_mut(CHUNK)
            .zip(mesh.triangles().par_chunks(CHUNK))
            .for_each(|(slots, tris)| {
                for (s, tri) in slots.iter_mut().zip(tris) {
                    let mut gd = [0usize; 6];
                    dofs.element_dofs(tri, &mut gd);
                    *s = pattern.slots(&gd.map(|g| dofs.free(g)));
                }
            });
        Ok(Cache {
            epoch: self.epoch,
            dofs,
            pattern,
            chol: None,
            contact,
            values,
            slots,
        })
    }

    /// The assembled external load vector (2 values per node: f_x, f_y) of
    /// the current loads: consistent edge loads, nodal and body forces.
    pub fn load_vector(&self) -> Result<Vec<f64>> {
        Ok(self.external_forces(self.mesh_ref()?))
    }

    /// External forces on every global DOF.
    fn external_forces(&self, mesh: &Mesh) -> Vec<f64> {
        let mut f = vec![0.0; 2 * mesh.nodes().len()];
        for &(tag, load) in &self.edge_loads {
            for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag) {
                let [p, q] = e.nodes;
                let (xp, xq) = (mesh.nodes()[p], mesh.nodes()[q]);
                let len = (xq[0] - xp[0]).hypot(xq[1] - xp[1]);
                let t = match load {
                    EdgeLoad::Traction(t) => t,
                    EdgeLoad::Pressure(pr) => {
                        let n = mesh
                            .outward_normal(e)
                            .expect("checked when the load was added");
                        [-pr * n[0], -pr * n[1]]
                    }
                };
                for v in [p, q] {
                    f[2 * v] += 0.5 * len * t[0];
                    f[2 * v + 1] += 0.5 * len * t[1];
                }
            }
        }
        for &(v, force) in &self.nodal_forces {
            f[2 * v] += force[0];
            f[2 * v + 1] += force[1];
        }
        if !self.body_forces.is_empty() {
            for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
                if let Some(b) = self.body_forces.get(body) {
                    // Inverted or flat elements carry no material volume.
                    let area = 0.5 * TriGeometry::new(&mesh.corners(tri)).j.max(0.0);
                    for &v in tri {
                        f[2 * v] += b[0] * area / 3.0;
                        f[2 * v + 1] += b[1] * area / 3.0;
                    }
                }
            }
        }
        f
    }

    fn prescribed_vector(&self, n_dofs: usize) -> Vec<f64> {
        let mut up = vec![0.0; n_dofs];
        for (&g, &v) in &self.prescribed {
            up[g] = v;
        }
        up
    }

    /// The body part of the reduced system: stiffness values on `pattern`
    /// (into `storage` when it has the right length) and the load on the
    /// unknowns (external forces minus the prescribed displacements'
    /// share), with the elements tempering softens.
    fn assemble_body(
        &self,
        mesh: &Mesh,
        (dofs, pattern, slots): (&DofMap, &Pattern, &[Slots]),
        storage: Vec<f64>,
        f_ext: &[f64],
        up: &[f64],
    ) -> Result<(Vec<f64>, Vec<f64>, Softened)> {
        let jmin_of = self.body_jmin(mesh);
        let mut values_body = storage;
        if values_body.len() != pattern.nnz() {
            values_body = faulted_in(pattern.nnz());
        }
        let mut rhs_body = vec![0.0; dofs.n_free()];
        for (g, &f) in f_ext.iter().enumerate() {
            let fg = dofs.free(g);
            if fg != NOT_FREE {
                rhs_body[fg] += f;
            }
        }
        // Two column ranges assembled at the same time: each visits the
        // elements with an unknown in its range and writes only there.
        let mid = dofs.n_free() / 2;
        // The node of the first unknown above the cut.
        let cut = (0..f_ext.len())
            .find(|&g| dofs.free(g) == mid)
            .map_or(usize::MAX, |g| g / 2);
        let (rhs_lo, rhs_hi) = rhs_body.split_at_mut(mid);
        let (mut lo, mut hi) = pattern.split_columns(mid, &mut values_body);
        let body_part = |cols: &mut Columns<'_>, rhs: &mut [f64], below: bool| {
            cols.clear();
            let side = (cut, below);
            let system = (dofs, pattern, slots);
            self.assemble_body_columns(mesh, system, up, &jmin_of, cols, rhs, side)
        };
        let (r_lo, r_hi) = rayon::join(
            || body_part(&mut lo, rhs_lo, true),
            || body_part(&mut hi, rhs_hi, false),
        );
        let softened = match (r_lo, r_hi) {
            (Err(a), Err(b)) => return Err(if a.0 <= b.0 { a.1 } else { b.1 }),
            (Err(a), _) | (_, Err(a)) => return Err(a.1),
            (Ok(a), Ok(b)) => (a.0 + b.0, a.1.into_iter().chain(b.1).min()),
        };
        Ok((values_body, rhs_body, softened))
    }

    /// Adds the body elements' stiffness into the columns of `cols` and
    /// their prescribed-displacement loads into `rhs` (the rows of the same
    /// range). Visits the elements with an unknown in the range and those
    /// without unknowns whose first node is on the `side` of node `cut`,
    /// so that the two sides of a cut check every element. Returns the
    /// elements that tempering softens among those it owns (first unknown
    /// in the range, or none and on its side): how many, and the first; or
    /// the first element that fails, with its index.
    ///
    /// Unknowns are numbered in node order, so the range's unknowns sit on
    /// nodes up to `cut` (below) or from `cut` on (above): an element
    /// entirely on the other side is skipped on its node numbers alone,
    /// without looking up its unknowns.
    #[allow(clippy::too_many_arguments)]
    fn assemble_body_columns(
        &self,
        mesh: &Mesh,
        (dofs, pattern, slots): (&DofMap, &Pattern, &[Slots]),
        up: &[f64],
        jmin_of: &(impl Fn(&TriGeometry) -> Jmin + Sync),
        cols: &mut Columns<'_>,
        rhs: &mut [f64],
        (cut, below): (usize, bool),
    ) -> std::result::Result<Softened, (usize, Error)> {
        debug_assert_eq!(dofs.per_node(), 2);
        let range = cols.range();
        let mut softened: Softened = (0, None);
        let mut d_cache: Option<(i32, [[f64; 3]; 3])> = None;
        let mut k = [[0.0; 6]; 6];
        for (e, (tri, &body)) in mesh.triangles().iter().zip(mesh.body_of()).enumerate() {
            let lowest = tri[0].min(tri[1]).min(tri[2]);
            let on_side = if below {
                lowest <= cut
            } else {
                tri[0].max(tri[1]).max(tri[2]) >= cut
            };
            if !on_side {
                continue;
            }
            // Global DOFs and unknowns, node-major as in
            // `DofMap::element_dofs`. (Plain loops: the array adaptors were
            // left as calls, whose results then stall on being read back.)
            let mut gd = [0usize; 6];
            let mut free = [NOT_FREE; 6];
            for q in 0..6 {
                gd[q] = 2 * tri[q / 2] + q % 2;
                free[q] = dofs.free(gd[q]);
            }
            // (NOT_FREE is the largest usize: the minimum is a free one.)
            let first = free.iter().copied().min().unwrap_or(NOT_FREE);
            let owns = if first == NOT_FREE {
                (lowest <= cut) == below
            } else {
                range.contains(&first)
            };
            if !owns && !free.iter().any(|f| range.contains(f)) {
                continue;
            }
            let d = match d_cache {
                Some((b, d)) if b == body => d,
                _ => {
                    let d = self.materials[&body].d_matrix();
                    d_cache = Some((body, d));
                    d
                }
            };
            let geo = TriGeometry::new(&mesh.corners(tri));
            let jm = jmin_of(&geo);
            if let Jmin::Tempered(jmin) = jm {
                if owns && geo.j < jmin && geo.j >= 0.1 * geo.h * geo.h {
                    softened.0 += 1;
                    softened.1.get_or_insert(e);
                }
            }
            if let Err(err) = elasticity_stiffness_into(&geo, &d, jm, &mut k) {
                let what = format!("{} (body {body})", mesh.triangle_name(e));
                let message = format!("{what}: {}", err.message());
                return Err((e, Error::new(err.status(), message)));
            }
            let ke = k.as_flattened();
            pattern.add_element_at(cols, &free, ke, slots[e]);
            if !free.contains(&NOT_FREE) {
                continue;
            }
            for a in 0..6 {
                if free[a] == NOT_FREE || !range.contains(&free[a]) {
                    continue;
                }
                let mut r = 0.0;
                for b in 0..6 {
                    if free[b] == NOT_FREE {
                        r -= ke[a * 6 + b] * up[gd[b]];
                    }
                }
                rhs[free[a] - range.start] += r;
            }
        }
        Ok(softened)
    }

    /// Adds an element matrix and its prescribed-DOF correction to the
    /// reduced system.
    #[allow(clippy::too_many_arguments)]
    fn scatter(
        dofs: &DofMap,
        pattern: &Pattern,
        values: &mut [f64],
        rhs: &mut [f64],
        tri: &[usize; 3],
        ke: &[f64; 36],
        f0: Option<&[f64; 6]>,
        up: &[f64],
    ) {
        let mut gd = [0usize; 6];
        dofs.element_dofs(tri, &mut gd);
        let free = gd.map(|g| dofs.free(g));
        pattern.add_element(values, &free, ke);
        if f0.is_none() && !free.contains(&NOT_FREE) {
            // The common case: nothing prescribed, no initial load.
            return;
        }
        for a in 0..6 {
            if free[a] == NOT_FREE {
                continue;
            }
            let mut r = f0.map_or(0.0, |f| f[a]);
            for b in 0..6 {
                if free[b] == NOT_FREE {
                    r -= ke[a * 6 + b] * up[gd[b]];
                }
            }
            rhs[free[a]] += r;
        }
    }

    fn run_with(
        &self,
        cache: &mut Cache,
        options: Option<ContactOptions>,
        timings: &mut Timings,
    ) -> Result<(Solved, Vec<String>)> {
        let mesh = self.mesh_ref()?;
        let n_dofs = 2 * mesh.nodes().len();
        let mut warnings = Vec::new();
        let up = self.prescribed_vector(n_dofs);
        let f_ext = self.external_forces(mesh);
        let Cache {
            dofs,
            pattern,
            chol: slot,
            contact,
            values: storage,
            slots,
            ..
        } = cache;
        let (dofs, pattern, contact) = (&*dofs, &*pattern, &*contact);
        let coords = || {
            dofs.free_to_global()
                .iter()
                .map(|&g| mesh.nodes()[g / 2])
                .collect()
        };

        // Body part of the system: assembled once, reused by every iteration.
        let t0 = Instant::now();
        // (A solve that failed did not give the storage back.)
        let storage_in = std::mem::take(storage);
        let (values_body, rhs_body, softened) =
            self.assemble_body(mesh, (dofs, pattern, slots), storage_in, &f_ext, &up)?;
        timings.assembly += t0.elapsed().as_secs_f64();
        if let (n, Some(e)) = softened {
            let cause = match self.tempering_lambda() {
                Some(l) => format!(
                    "λ = {l:e} is not much larger than the element size, so Jmin = h³/λ exceeds \
                     their J; increase λ"
                ),
                None => "the fixed Jmin exceeds their J; lower it".to_string(),
            };
            warnings.push(format!(
                "tempering softens {n} well-shaped element(s) (e.g. {}): {cause}",
                mesh.triangle_name(e)
            ));
        }

        let mut info = SolveInfo {
            unknowns: dofs.n_free(),
            matrix_nnz: pattern.nnz(),
            ..Default::default()
        };

        let Some(opts) = options else {
            let want = Wanted {
                last: None,
                zeros: &[],
                is_zero: &|p| values_body[p] == 0.0,
            };
            let settings = (self.ordering, self.parallel_subtrees);
            let chol = analysed(slot, pattern, coords, settings, want, timings)?;
            info.factor_nnz = chol.factor_nnz();
            info.factorization_bytes = chol.factorization_bytes();
            info.split_factorization = chol.is_split();
            let energy = |r: &[f64]| self.body_energy(mesh, r);
            let (u, values, rhs) = self.factor_and_solve(
                dofs,
                pattern,
                chol,
                values_body,
                rhs_body,
                &up,
                timings,
                &mut info,
                "",
                &energy,
                true,
            )?;
            info.relative_residual = residual(pattern, &values, &u_free(dofs, &u), &rhs);
            *storage = values;
            info.condition_estimate = chol.condition_estimate();
            info.memory_bytes = memory(pattern, chol);
            info.timings = *timings;
            conditioning_warning(&info, &mut warnings);
            return Ok((
                Solved {
                    u,
                    f_ext,
                    info,
                    contact: None,
                },
                warnings,
            ));
        };

        // Contact: per-element law and tempering.
        let lambda_c = opts.lambda.unwrap_or_else(|| mesh.size());
        let params: Vec<ContactParams> = contact
            .iter()
            .map(|el| {
                let p = &self.pairs[el.pair];
                let (ma, mb) = (self.materials[&p.body_a], self.materials[&p.body_b]);
                let soft = if mb.young() < ma.young() { mb } else { ma };
                let e_c = opts.contact_modulus.unwrap_or(soft.young());
                let d = law_matrix(opts.law, e_c, &soft, el.normal);
                let t = jmin_of_lambda(el.h, lambda_c);
                ContactParams { d, t }
            })
            .collect();
        if let Some((k, _)) = params
            .iter()
            .enumerate()
            .find(|(_, p)| !(p.t > 0.0 && p.t.is_finite()))
        {
            return Err(Error::new(
                Status::NumericalFailure,
                format!(
                    "contact element {}: Jmin = h³/λ is not a positive finite number",
                    k + mesh.index_base()
                ),
            ));
        }
        let geos: Vec<TriGeometry> = contact
            .iter()
            .map(|el| TriGeometry::new(&mesh.corners(&el.nodes)))
            .collect();
        // An active element is inverted, so its T = Jmin: its matrix and
        // initial-gap load do not change between iterations.
        let stiffness: Vec<ContactStiffness> = contact
            .iter()
            .enumerate()
            .map(|(k, el)| contact_stiffness(&geos[k], &params[k].d, el.normal, el.j0, params[k].t))
            .collect();
        let unknowns: Vec<[Option<usize>; 6]> = contact
            .iter()
            .map(|el| {
                let mut gd = [0usize; 6];
                dofs.element_dofs(&el.nodes, &mut gd);
                gd.map(|g| Some(dofs.free(g)).filter(|&f| f != NOT_FREE))
            })
            .collect();
        // Each element's load on its free unknowns: the initial-gap load
        // minus the share of the prescribed displacements.
        let loads: Vec<[f64; 6]> = contact
            .iter()
            .enumerate()
            .map(|(k, el)| {
                let mut gd = [0usize; 6];
                dofs.element_dofs(&el.nodes, &mut gd);
                std::array::from_fn(|a| {
                    if unknowns[k][a].is_none() {
                        return 0.0;
                    }
                    let mut r = stiffness[k].f0[a];
                    for b in 0..6 {
                        if unknowns[k][b].is_none() {
                            r -= stiffness[k].k[a * 6 + b] * up[gd[b]];
                        }
                    }
                    r
                })
            })
            .collect();
        let interface = if opts.refactorize {
            Vec::new()
        } else {
            interface_unknowns(contact, &stiffness, &unknowns, &geos, &opts)
        };
        let condense = Interface::worthwhile(interface.len(), pattern.nnz());
        let zeros = structural_zeros(pattern, &values_body, &unknowns, &stiffness);
        let want = Wanted {
            last: if condense { Some(&interface[..]) } else { None },
            zeros: &zeros,
            is_zero: &|p| zeros.binary_search(&p).is_ok(),
        };
        let settings = (self.ordering, self.parallel_subtrees);
        let chol = analysed(slot, pattern, coords, settings, want, timings)?;
        info.factor_nnz = chol.factor_nnz();
        info.factorization_bytes = chol.factorization_bytes();
        info.split_factorization = chol.is_split();
        let free_to_global = dofs.free_to_global();

        // The assembled system and the contact set it holds. Both loops move
        // the body part into the first system and later update that in
        // place by the elements whose state changed, so that the matrix
        // values (63 MB at 1M unknowns) are never copied: a pristine body
        // copy would be held beside the factor at every refactorisation.
        type System = (Vec<f64>, Vec<f64>, Vec<bool>);
        let mut body = Some((values_body, rhs_body));
        let mut held: Option<System> = None;
        let add_contact = |values: &mut [f64], rhs: &mut [f64], k: usize, sign: f64| {
            let cs = &stiffness[k];
            Self::scatter(
                dofs,
                pattern,
                values,
                rhs,
                &contact[k].nodes,
                &cs.k.map(|v| sign * v),
                Some(&cs.f0.map(|v| sign * v)),
                &up,
            );
        };
        let assemble = |active: &[bool],
                        body: &mut Option<(Vec<f64>, Vec<f64>)>,
                        held: &mut Option<System>|
         -> (Vec<f64>, Vec<f64>) {
            let (mut values, mut rhs, set) = held.take().unwrap_or_else(|| {
                let (values, rhs) = body.take().expect("the body part or a held system");
                (values, rhs, vec![false; contact.len()])
            });
            for k in (0..contact.len()).filter(|&k| active[k] != set[k]) {
                add_contact(&mut values, &mut rhs, k, if active[k] { 1.0 } else { -1.0 });
            }
            (values, rhs)
        };
        // Start from the elements at each pair's smallest gap (all of B for
        // touching or uniformly spaced surfaces, the seed's choice; the
        // first point of contact of curved ones). K₁ is the reference the
        // condensed iterations update.
        let initial = contact::initial_active_set(contact);
        let mut active = initial.clone();
        let mut seen: HashSet<Vec<bool>> = HashSet::new();
        seen.insert(active.clone());
        let mut history = Vec::new();
        // The condensed system and the first iteration's solution x₁ (over
        // the unknowns) it is relative to.
        let mut condensed: Option<(Interface, Vec<f64>)> = None;
        // The active set the interface factor currently represents.
        let mut factor_active = active.clone();
        let mut u = Vec::new();
        // Whether the last iterate was a full solve of the held system.
        let mut last_full = false;
        let mut converged = false;
        for it in 1..=opts.max_iterations {
            let n_active = active.iter().filter(|&&a| a).count();
            let context = format!(" (contact iteration {it}, {n_active} active contact elements)");
            let element = |k: usize, sign: f64| {
                (
                    ElementMatrix {
                        unknowns: &unknowns[k],
                        matrix: &stiffness[k].k,
                    },
                    sign,
                )
            };
            let mut done = false;
            if let Some((sys, x1)) = condensed.as_mut() {
                let t0 = Instant::now();
                // A few changes since the factorised set: update the factor;
                // many: refactorise Ŝ₁ minus the inactive elements.
                let changed: Vec<usize> = (0..contact.len())
                    .filter(|&k| active[k] != factor_active[k])
                    .collect();
                let sign = |k: usize| if active[k] { 1.0 } else { -1.0 };
                // Changes relative to K₁: elements added (+) or removed (−).
                let relative: Vec<usize> = (0..contact.len())
                    .filter(|&k| active[k] != initial[k])
                    .collect();
                // (Measured: a rank-1 update costs ~1/20 of a refactorisation
                // at 2000 interface unknowns.)
                let updated = 24 * changed.len() <= sys.len()
                    && sys.is_factored()
                    && sys
                        .update(changed.iter().map(|&k| element(k, sign(k))))
                        .is_ok();
                let factored = updated
                    || sys
                        .factorize(relative.iter().map(|&k| element(k, sign(k))))
                        .is_ok();
                factor_active.clone_from(&active);
                if factored {
                    let mut g = vec![0.0; sys.len()];
                    for &k in &relative {
                        for a in 0..6 {
                            if let Some(p) = unknowns[k][a].and_then(|i| sys.position(i)) {
                                g[p] += sign(k) * loads[k][a];
                            }
                        }
                    }
                    let ui = sys.solve(&sys.gather(x1), &g)?;
                    // Only interface values enter the inversion test (the
                    // others have zero coefficients); keep x₁ elsewhere.
                    for (p, &i) in sys.unknowns().iter().enumerate() {
                        u[free_to_global[i]] = ui[p];
                    }
                    last_full = false;
                    done = true;
                } else {
                    // Singular or nearly so: the full factorisation below
                    // names the free mode (or accepts an ill-conditioned but
                    // restrained system). The condensation ends here.
                    condensed = None;
                }
                timings.interface += t0.elapsed().as_secs_f64();
            }
            if !done {
                let t0 = Instant::now();
                let (values, rhs) = assemble(&active, &mut body, &mut held);
                timings.assembly += t0.elapsed().as_secs_f64();
                let energy = |r: &[f64]| {
                    let mut acc = self.body_energy(mesh, r);
                    for (k, el) in contact.iter().enumerate() {
                        if active[k] {
                            add_energy(&mut acc, &stiffness[k].k, r, &el.nodes);
                        }
                    }
                    acc
                };
                // A condensed loop refines its final solution against the
                // final matrix; refining x₁ as well would be wasted.
                let refine_here = !(it == 1 && condense);
                let (uk, values, rhs) = self.factor_and_solve(
                    dofs,
                    pattern,
                    chol,
                    values,
                    rhs,
                    &up,
                    timings,
                    &mut info,
                    &context,
                    &energy,
                    refine_here,
                )?;
                if it == 1 && condense {
                    let t0 = Instant::now();
                    let sys = Interface::new(chol, interface.clone())?;
                    info.interface_unknowns = sys.len();
                    condensed = Some((sys, u_free(dofs, &uk)));
                    timings.interface += t0.elapsed().as_secs_f64();
                }
                u = uk;
                held = Some((values, rhs, active.clone()));
                last_full = true;
            }
            let next: Vec<bool> = contact
                .iter()
                .enumerate()
                .map(|(k, el)| {
                    let ue = element_u(&u, &el.nodes);
                    let j = match opts.test {
                        InversionTest::Linearised => {
                            linearised_opening(&geos[k], opts.law, el.normal, &ue)
                        }
                        InversionTest::Literal => {
                            let mut x = mesh.corners(&el.nodes);
                            for (i, p) in x.iter_mut().enumerate() {
                                p[0] += ue[2 * i];
                                p[1] += ue[2 * i + 1];
                            }
                            TriGeometry::new(&x).j
                        }
                    };
                    j < 0.0
                })
                .collect();
            let on = next
                .iter()
                .zip(&active)
                .filter(|(n, a)| **n && !**a)
                .count();
            let off = next
                .iter()
                .zip(&active)
                .filter(|(n, a)| !**n && **a)
                .count();
            history.push(IterationRecord {
                active: n_active,
                switched_on: on,
                switched_off: off,
            });
            if next == active {
                converged = true;
                break;
            }
            if !seen.insert(next.clone()) {
                return Err(Error::new(
                    Status::NotConverged,
                    format!(
                        "the active set revisited an earlier state at iteration {it} (a cycle); history {}",
                        format_history(&history)
                    ),
                ));
            }
            active = next;
        }
        if !converged {
            return Err(Error::new(
                Status::NotConverged,
                format!(
                    "the active set did not settle in {} iterations; history {}",
                    opts.max_iterations,
                    format_history(&history)
                ),
            ));
        }
        let condensed_bytes = condensed
            .as_ref()
            .map_or(0, |(sys, x1)| sys.memory_bytes() + 8 * x1.len());
        let (values, rhs) = if last_full {
            let (values, rhs, _) = held.take().expect("the last full solve's system");
            if condense && history.len() == 1 {
                // Settled at once: x₁ is the answer, not yet refined.
                let t0 = Instant::now();
                let mut x = u_free(dofs, &u);
                refine(pattern, &values, &rhs, &mut x, &mut |r| chol.solve(r))?;
                u = self.global_field(dofs, &x, &up, &context_final(&history))?;
                timings.solve += t0.elapsed().as_secs_f64();
            }
            (values, rhs)
        } else {
            // The last iterate is condensed: recover the whole field,
            // u = x₁ + K₁⁻¹ P(Δg + ΔC u_I), refined against K itself.
            let (sys, x1) = condensed.take().expect("a condensed iterate");
            let t0 = Instant::now();
            let (values, rhs) = assemble(&active, &mut body, &mut held);
            timings.assembly += t0.elapsed().as_secs_f64();
            let t0 = Instant::now();
            // p = ΔC v_I − Δg over the unknowns, ΔC = C₁ − C and
            // Δg = g₁ − g: what the elements removed since K₁ took out of
            // it and its load, minus what the added ones put in.
            let interface_product = |v: &dyn Fn(usize) -> f64, with_load: bool| {
                let mut p = vec![0.0; dofs.n_free()];
                for k in (0..contact.len()).filter(|&k| active[k] != initial[k]) {
                    let removed = if initial[k] { 1.0 } else { -1.0 };
                    for a in 0..6 {
                        let Some(i) = unknowns[k][a] else { continue };
                        let mut r = if with_load { -loads[k][a] } else { 0.0 };
                        for b in 0..6 {
                            let c = stiffness[k].k[a * 6 + b];
                            // (Only interface unknowns have coefficients.)
                            if let (Some(j), true) = (unknowns[k][b], c != 0.0) {
                                r += c * v(j);
                            }
                        }
                        p[i] += removed * r;
                    }
                }
                p
            };
            let mut x = interface_product(&|j| u[free_to_global[j]], true);
            // Near the solve's memory peak: free the vectors done with.
            drop(std::mem::take(&mut u));
            chol.solve(&mut x)?;
            x.iter_mut().zip(&x1).for_each(|(a, b)| *a += b);
            drop(x1);
            let mut solve = |r: &mut [f64]| -> Result<()> {
                // K δ = r: y = K₁⁻¹r, S δ_I = S₁ y_I, δ = y + K₁⁻¹PΔC δ_I.
                chol.solve(r)?;
                let di = sys.solve(&sys.gather(r), &vec![0.0; sys.len()])?;
                let mut p = interface_product(
                    &|j| {
                        di[sys
                            .position(j)
                            .expect("coupled unknowns are on the interface")]
                    },
                    false,
                );
                chol.solve(&mut p)?;
                r.iter_mut().zip(&p).for_each(|(a, b)| *a += b);
                Ok(())
            };
            refine(pattern, &values, &rhs, &mut x, &mut solve)?;
            timings.solve += t0.elapsed().as_secs_f64();
            u = self.global_field(dofs, &x, &up, &context_final(&history))?;
            (values, rhs)
        };
        info.memory_bytes = memory(pattern, chol) + condensed_bytes;
        // The dense interface matrices (51 MB at 1M unknowns) are done
        // with: free them before the results' temporaries are allocated.
        drop(condensed);
        info.relative_residual = residual(pattern, &values, &u_free(dofs, &u), &rhs);
        *storage = values;
        info.condition_estimate = chol.condition_estimate();
        info.timings = *timings;
        conditioning_warning(&info, &mut warnings);

        let mut pressure = vec![0.0; contact.len()];
        let (mut lc, mut max_pen) = (0.0, 0.0f64);
        for (k, el) in contact.iter().enumerate() {
            if !active[k] {
                continue;
            }
            let ue = element_u(&u, &el.nodes);
            pressure[k] =
                contact_pressure(&geos[k], &params[k].d, el.normal, el.j0, params[k].t, &ue);
            lc += 0.5 * el.edge_length;
            let opening = linearised_opening(&geos[k], opts.law, el.normal, &ue);
            if el.edge_length > 0.0 {
                max_pen = max_pen.max(-opening / el.edge_length);
            }
        }
        let report = ContactReport {
            iterations: history.len(),
            elements: contact.len(),
            active: active.iter().filter(|&&a| a).count(),
            contact_length: lc,
            max_penetration: max_pen,
            history,
            info,
        };
        Ok((
            Solved {
                u,
                f_ext,
                info,
                contact: Some(ContactSolved {
                    active,
                    pressure,
                    report,
                    params,
                }),
            },
            warnings,
        ))
    }

    #[allow(clippy::too_many_arguments)]
    fn factor_and_solve(
        &self,
        dofs: &DofMap,
        pattern: &Pattern,
        chol: &mut Cholesky,
        values: Vec<f64>,
        rhs: Vec<f64>,
        up: &[f64],
        timings: &mut Timings,
        info: &mut SolveInfo,
        context: &str,
        rigid_energy: &dyn Fn(&[f64]) -> (f64, f64),
        refined: bool,
    ) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
        let mesh = self.mesh_ref()?;
        let t0 = Instant::now();
        let fact = chol.factorize(pattern, &values);
        timings.factorization += t0.elapsed().as_secs_f64();
        info.factorizations += 1;
        if let Err(e) = fact {
            let usable_hint = matches!(e, FactorError::Singular { usable: true, .. });
            let restrained = match &e {
                FactorError::Singular {
                    mode: Some(m),
                    usable: true,
                    ..
                } => {
                    // A tiny eigenvalue from an extreme stiffness contrast, or a
                    // free mode? Fit the rigid motion of each body to the mode and
                    // measure its energy element by element: round-off for a
                    // free body, the coupling's energy for a restrained one.
                    let r = rigid_fit(mesh, dofs, m);
                    let (energy, scale) = rigid_energy(&r);
                    energy > RIGID_ENERGY_TOL * scale
                }
                _ => false,
            };
            if !(restrained && chol.accept_ill_conditioned()) {
                let mut err = singular_error(mesh, dofs, e, context);
                if matches!(err.status(), Status::Singular) && usable_hint {
                    err = Error::new(
                        Status::Singular,
                        format!(
                            "{} — numerically singular: the free motion is resisted by less than \
                             1e-13 of the stiffness (a free body, or a stiffness contrast beyond \
                             double precision)",
                            err.message()
                        ),
                    );
                }
                return Err(err);
            }
        }
        let t0 = Instant::now();
        let mut x = rhs.clone();
        chol.solve(&mut x)?;
        if refined {
            refine(pattern, &values, &rhs, &mut x, &mut |r| chol.solve(r))?;
        }
        timings.solve += t0.elapsed().as_secs_f64();
        let u = self.global_field(dofs, &x, up, context)?;
        Ok((u, values, rhs))
    }

    /// The global displacement vector from the unknowns and the prescribed
    /// values; refuses a non-finite value, naming its node.
    fn global_field(
        &self,
        dofs: &DofMap,
        x: &[f64],
        up: &[f64],
        context: &str,
    ) -> Result<Vec<f64>> {
        let mesh = self.mesh_ref()?;
        let mut u = up.to_vec();
        for (f, &g) in dofs.free_to_global().iter().enumerate() {
            u[g] = x[f];
        }
        if let Some(g) = u.iter().position(|v| !v.is_finite()) {
            return Err(Error::new(
                Status::NumericalFailure,
                format!(
                    "the displacement of {} is not finite{context}",
                    mesh.node_name(g / 2)
                ),
            ));
        }
        Ok(u)
    }

    /// (rᵀKr, Σ diag energy) of the body elements for a global vector r.
    fn body_energy(&self, mesh: &Mesh, r: &[f64]) -> (f64, f64) {
        let jmin_of = self.body_jmin(mesh);
        let mut acc = (0.0, 0.0);
        for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
            let geo = TriGeometry::new(&mesh.corners(tri));
            if let Ok(k) =
                elasticity_stiffness(&geo, &self.materials[body].d_matrix(), jmin_of(&geo))
            {
                let ke: [f64; 36] = std::array::from_fn(|i| k[i / 6][i % 6]);
                add_energy(&mut acc, &ke, r, tri);
            }
        }
        acc
    }

    fn solved(&self) -> Result<&Solved> {
        self.solved.as_ref().ok_or_else(|| {
            Error::state("no results: solve the model first (results are discarded by any change)")
        })
    }

    /// Nodal displacements [u, v] of the last solve.
    pub fn displacements(&self) -> Result<Vec<[f64; 2]>> {
        let s = self.solved()?;
        Ok(s.u.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
    }

    /// Work of the external loads, Σ f·u (per unit thickness): for a
    /// pressure load, the compliance ∫ p (−u·n).
    pub fn external_work(&self) -> Result<f64> {
        let s = self.solved()?;
        Ok(s.f_ext.iter().zip(&s.u).map(|(f, u)| f * u).sum())
    }

    /// Statistics of the last solve.
    pub fn solve_info(&self) -> Result<SolveInfo> {
        Ok(self.solved()?.info)
    }

    /// The stiffness matrix of the last solve ([`SystemMatrix`]), borrowed:
    /// nothing is assembled or copied for it. Unlike the other results it
    /// does not outlive a failed solve, which reuses the matrix storage.
    pub fn system_matrix(&self) -> Result<SystemMatrix<'_>> {
        self.solved()?;
        let cache = self
            .cache
            .as_ref()
            .filter(|c| c.epoch == self.epoch && c.values.len() == c.pattern.nnz())
            .ok_or_else(|| {
                Error::state("no matrix: the last solve failed (solve again for its matrix)")
            })?;
        Ok(SystemMatrix {
            col_ptr: cache.pattern.col_ptr(),
            row_idx: cache.pattern.row_idx(),
            values: &cache.values,
            unknowns: cache.dofs.free_to_global(),
        })
    }

    /// Element strains [ε_xx, ε_yy, γ_xy] (engineering shear), computed on
    /// request: B̂u / max(J, Jmin), the usual strain for J >= Jmin and the
    /// tempered one below (consistent with the tempered energy).
    pub fn element_strains(&self) -> Result<Vec<[f64; 3]>> {
        let s = self.solved()?;
        let mesh = self.mesh_ref()?;
        let jmin_of = self.body_jmin(mesh);
        (0..mesh.triangles().len())
            .map(|e| {
                let geo = TriGeometry::new(&mesh.corners(&mesh.triangles()[e]));
                let jm = jmin_of(&geo);
                let Some(t) = tempered_jacobian(&geo, jm)? else {
                    return Ok([0.0; 3]);
                };
                let b = b_hat(&geo);
                let ue = element_u(&s.u, &mesh.triangles()[e]);
                Ok(std::array::from_fn(|r| {
                    (0..6).map(|c| b[r][c] * ue[c]).sum::<f64>() / t
                }))
            })
            .collect()
    }

    /// Element stresses [σ_xx, σ_yy, σ_xy] = D ε, computed on request.
    pub fn element_stresses(&self) -> Result<Vec<[f64; 3]>> {
        let strains = self.element_strains()?;
        let mesh = self.mesh_ref()?;
        Ok(strains
            .iter()
            .zip(mesh.body_of())
            .map(|(eps, body)| {
                let d = self.materials[body].d_matrix();
                std::array::from_fn(|r| d[r][0] * eps[0] + d[r][1] * eps[1] + d[r][2] * eps[2])
            })
            .collect())
    }

    /// J (twice the signed area) of every triangle in the initial
    /// configuration. Needs only a mesh.
    pub fn element_jacobians(&self) -> Result<Vec<f64>> {
        let mesh = self.mesh_ref()?;
        Ok(mesh
            .triangles()
            .iter()
            .map(|t| TriGeometry::new(&mesh.corners(t)).j)
            .collect())
    }

    /// Reaction forces [R_x, R_y] per node: K u − f at prescribed DOFs (zero
    /// elsewhere), computed on request.
    pub fn reactions(&self) -> Result<Vec<[f64; 2]>> {
        let s = self.solved()?;
        let mesh = self.mesh_ref()?;
        let mut r = vec![0.0; s.u.len()];
        let is_fixed = |g: usize| self.prescribed.contains_key(&g);
        let mut add = |tri: &[usize; 3], ke: &[f64; 36], f0: Option<&[f64; 6]>| {
            let ue = element_u(&s.u, tri);
            for a in 0..6 {
                let g = 2 * tri[a / 2] + a % 2;
                if is_fixed(g) {
                    let ku: f64 = (0..6).map(|b| ke[a * 6 + b] * ue[b]).sum();
                    r[g] += ku - f0.map_or(0.0, |f| f[a]);
                }
            }
        };
        let jmin_of = self.body_jmin(mesh);
        for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
            let geo = TriGeometry::new(&mesh.corners(tri));
            let k = elasticity_stiffness(&geo, &self.materials[body].d_matrix(), jmin_of(&geo))?;
            let ke: [f64; 36] = std::array::from_fn(|i| k[i / 6][i % 6]);
            add(tri, &ke, None);
        }
        if let (Some(c), Some(cache)) = (&s.contact, &self.cache) {
            for (k, el) in cache.contact.iter().enumerate() {
                if c.active[k] {
                    let geo = TriGeometry::new(&mesh.corners(&el.nodes));
                    let cs =
                        contact_stiffness(&geo, &c.params[k].d, el.normal, el.j0, c.params[k].t);
                    add(&el.nodes, &cs.k, Some(&cs.f0));
                }
            }
        }
        for (g, v) in r.iter_mut().enumerate() {
            if is_fixed(g) {
                *v -= s.f_ext[g];
            }
        }
        Ok(r.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
    }

    fn contact_solved(&self) -> Result<(&ContactSolved, &[ContactElement])> {
        let s = self.solved()?;
        match (&s.contact, &self.cache) {
            (Some(c), Some(cache)) => Ok((c, &cache.contact)),
            _ => Err(Error::state("no contact results: call solve_contact first")),
        }
    }

    /// The elements of the contact mesh B of the last contact solve.
    pub fn contact_elements(&self) -> Result<&[ContactElement]> {
        Ok(self.contact_solved()?.1)
    }

    /// Active flag of every element of B at convergence.
    pub fn contact_active(&self) -> Result<&[bool]> {
        Ok(&self.contact_solved()?.0.active)
    }

    /// Contact pressure (positive in compression, zero when inactive) of
    /// every element of B.
    pub fn contact_pressure(&self) -> Result<&[f64]> {
        Ok(&self.contact_solved()?.0.pressure)
    }

    /// The report of the last contact solve.
    pub fn contact_report(&self) -> Result<&ContactReport> {
        Ok(&self.contact_solved()?.0.report)
    }
}

/// Energy of a fitted rigid motion, relative to the element-wise diagonal
/// energy, above which the motion is restrained: a free body gives ~1e-16
/// (round-off of B̂ applied to a rigid motion); a body held only by a soft
/// contact against a 1e12 times stiffer one still gives ~1e-12.
const RIGID_ENERGY_TOL: f64 = 1e-13;

/// The rigid motion (translation and rotation about the centroid) of each
/// body that best fits `mode` (over unknowns), zero on prescribed DOFs.
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

fn rigid_fit(mesh: &Mesh, dofs: &DofMap, mode: &[f64]) -> Vec<f64> {
    let n = mesh.nodes().len();
    let mut m = vec![0.0; 2 * n];
    for (f, g) in dofs.free_to_global().into_iter().enumerate() {
        m[g] = mode[f];
    }
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

/// Adds rᵀ K_e r and Σ_a K_e[a][a] r_a² of one element to `acc`.
fn add_energy(acc: &mut (f64, f64), ke: &[f64; 36], r: &[f64], tri: &[usize; 3]) {
    let re = element_u(r, tri);
    for a in 0..6 {
        let kr: f64 = (0..6).map(|b| ke[a * 6 + b] * re[b]).sum();
        acc.0 += re[a] * kr;
        acc.1 += ke[a * 6 + a].abs() * re[a] * re[a];
    }
}

fn singular_error(mesh: &Mesh, dofs: &DofMap, e: FactorError, context: &str) -> Error {
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
            let n = mesh.nodes().len();
            let mut m = vec![0.0; 2 * n];
            for (f, &g) in free_to_global.iter().enumerate() {
                m[g] = mode[f];
            }
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

/// Normwise backward error of x for K x = rhs below which refinement stops:
/// ~45 ulps. A Cholesky solve is backward stable, so this is normally met at
/// once; refining further in working precision cannot improve the forward
/// error by more than the same small factor. (The relative residual
/// ‖Kx − f‖/‖f‖, reported in `SolveInfo`, is no criterion: it grows with
/// ‖K‖‖x‖/‖f‖, to 1e-10 at 1M unknowns and 1e-5 with a 1e8 stiffness
/// contrast, where refinement only halves it.)
const BACKWARD_ERROR_TOL: f64 = 1e-14;

/// Iterative refinement of K x = rhs while the normwise backward error
/// ‖r‖∞ / (‖K‖∞‖x‖∞ + ‖f‖∞) exceeds [`BACKWARD_ERROR_TOL`] and each step at
/// least halves the residual. A backward-stable solve costs one product.
fn refine(
    pattern: &Pattern,
    values: &[f64],
    rhs: &[f64],
    x: &mut [f64],
    solve: &mut dyn FnMut(&mut [f64]) -> Result<()>,
) -> Result<()> {
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    // One n-vector at a time: this runs near the solve's memory peak.
    let k_norm = {
        let mut row_sums = vec![0.0f64; x.len()];
        let (cp, ri) = (pattern.col_ptr(), pattern.row_idx());
        for j in 0..x.len() {
            for p in cp[j]..cp[j + 1] {
                row_sums[ri[p]] += values[p].abs();
                if ri[p] != j {
                    row_sums[j] += values[p].abs();
                }
            }
        }
        inf(&row_sums)
    };
    let f_norm = inf(rhs);
    let mut r = vec![0.0; x.len()];
    let mut previous = f64::INFINITY;
    for _ in 0..3 {
        pattern.sym_mul(values, x, &mut r);
        r.iter_mut().zip(rhs).for_each(|(k, b)| *k = b - *k);
        let rn = inf(&r);
        let omega = rn / (k_norm * inf(x) + f_norm);
        // (A NaN residual also stops: the finiteness check reports it.)
        if rn.is_nan() || omega.is_nan() || omega <= BACKWARD_ERROR_TOL || rn > 0.5 * previous {
            break;
        }
        previous = rn;
        solve(&mut r)?;
        x.iter_mut().zip(&r).for_each(|(a, d)| *a += d);
    }
    Ok(())
}

/// The free unknowns of the condensed contact interface: those with a
/// nonzero coefficient in an element of B — in its matrix, its load, or its
/// inversion test (the literal test needs every unknown of its nodes). For
/// a straight interface under the frictionless law these are the normal
/// components only, half of the contact nodes' unknowns.
fn interface_unknowns(
    contact: &[ContactElement],
    stiffness: &[ContactStiffness],
    unknowns: &[[Option<usize>; 6]],
    geos: &[TriGeometry],
    opts: &ContactOptions,
) -> Vec<usize> {
    let (test, law) = (opts.test, opts.law);
    let mut set = Vec::new();
    for (k, cs) in stiffness.iter().enumerate() {
        for a in 0..6 {
            let Some(i) = unknowns[k][a] else { continue };
            let coupled = cs.k[a * 6..a * 6 + 6].iter().any(|&v| v != 0.0)
                || cs.f0[a] != 0.0
                || match test {
                    InversionTest::Linearised => {
                        opening_coefficient(&geos[k], law, contact[k].normal, a) != 0.0
                    }
                    InversionTest::Literal => true,
                };
            if coupled {
                set.push(i);
            }
        }
    }
    set.sort_unstable();
    set.dedup();
    set
}

fn context_final(history: &[IterationRecord]) -> String {
    format!(" (contact solution after {} iterations)", history.len())
}

fn element_u(u: &[f64], tri: &[usize; 3]) -> [f64; 6] {
    std::array::from_fn(|a| u[2 * tri[a / 2] + a % 2])
}

fn u_free(dofs: &DofMap, u: &[f64]) -> Vec<f64> {
    dofs.free_to_global().iter().map(|&g| u[g]).collect()
}

fn residual(pattern: &Pattern, values: &[f64], x: &[f64], rhs: &[f64]) -> f64 {
    let mut r = vec![0.0; x.len()];
    pattern.sym_mul(values, x, &mut r);
    r.iter_mut().zip(rhs).for_each(|(a, b)| *a -= b);
    let nf = norm(rhs);
    if nf > 0.0 { norm(&r) / nf } else { norm(&r) }
}

/// A zeroed array whose pages are already faulted in. Touched on one
/// thread: two threads faulting pages in at once cost ~4× more on the test
/// machine (0.11 s against 0.03 s for 63 MB).
fn faulted_in(n: usize) -> Vec<f64> {
    let mut v = vec![0.0; n];
    v.fill(0.0);
    v
}

fn memory(pattern: &Pattern, chol: &Cholesky) -> usize {
    pattern.memory_bytes() + 8 * pattern.nnz() + chol.memory_bytes()
}

/// Warns when the scaled system is so ill-conditioned that results lose
/// digits (an extreme stiffness contrast or penalty).
fn conditioning_warning(info: &SolveInfo, warnings: &mut Vec<String>) {
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

fn format_history(h: &[IterationRecord]) -> String {
    let items: Vec<String> = h
        .iter()
        .map(|r| {
            format!(
                "[active {}, +{}, -{}]",
                r.active, r.switched_on, r.switched_off
            )
        })
        .collect();
    items.join(" ")
}

/// Names the bodies that move in a near-null mode and the kind of motion.
fn describe_mode(mesh: &Mesh, m: &[f64]) -> String {
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
    let mut parts = Vec::new();
    for &(body, _) in &named {
        // Fractions of the body's motion that are rigid translations and
        // rotation about its centroid (three orthogonal modes).
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
        let kind = if fx + fy + fr < 0.5 {
            "a mechanism that is not a rigid motion".to_string()
        } else {
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
        };
        parts.push(format!("body {body} is not restrained (free mode: {kind})"));
    }
    parts.join("; ")
}
