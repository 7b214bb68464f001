//! Contact for codes that keep their own elements, assembly, solver and
//! Newton loop: the host describes the contact interfaces in its own
//! numbering (the interface nodes, their coordinates, the equation of each
//! node's x and y unknowns, and the edges of each side), tfem builds the
//! contact mesh B once and returns, at each evaluation, the contact
//! contributions in the host's equation numbering.
//!
//! B's topology never changes, so the pattern of its contributions is fixed
//! ([`HostContact::pattern`]: every element's 6×6 block, inactive elements
//! contributing zeros) and each evaluation only fills values. The law of an
//! element of B is linear (small strain): an active element contributes its
//! tempered stiffness K_e to the tangent and its internal force
//! K_e u_e − f0_e to the residual, f0_e the load of an initial gap (zero
//! for touching surfaces). A linear host adds the values to its matrix and
//! f0 (the residual at u = 0, negated) to its right-hand side; a Newton host
//! adds the values to its tangent and the residual at its current u to its
//! residual.
//!
//! Between solves the host asks [`HostContact::update`] which elements are
//! inverted (the same test and cycle detection as tfem's own loop, which is
//! a client of the same [`ContactSet`] and [`ActiveSet`]).

use std::collections::HashMap;

use super::mesh::{Nodes, Side, check_facing, checked_triangles, strip};
use super::set::{ActiveSet, ContactSet, Owners, element_laws, softer};
use super::{ContactElement, ContactOptions};
use crate::error::{Error, Result, Status, ensure_finite, out_of_memory, reserve_more, reserved};
use crate::fem::material::Material;

/// A pair of sides, with the contact mesh the host may give for it.
#[derive(Debug, Clone)]
struct HostPair {
    sides: [usize; 2],
    /// Triangles over local node indices, if the host gave B.
    triangles: Option<Vec<[usize; 3]>>,
}

/// What [`HostContact::setup`] builds.
struct Built {
    set: ContactSet<'static>,
    active: ActiveSet,
    /// The pattern: rows and columns in the host's numbering (index base
    /// applied), and the (element, a, b) each entry comes from.
    rows: Vec<i64>,
    cols: Vec<i64>,
    entries: Vec<(u32, u8, u8)>,
    /// Per-node values (2 per interface node) computed here and checked
    /// before they reach a caller's buffer: a failed call writes nothing,
    /// and evaluation allocates nothing.
    scratch: Vec<f64>,
}

/// The contact of a host code's bodies (module documentation).
pub struct HostContact {
    base: usize,
    options: ContactOptions,
    /// The interface nodes: coordinates, host numbers, equations (0-based).
    x: Vec<[f64; 2]>,
    node_id: Vec<i64>,
    local: HashMap<i64, usize>,
    equation: Vec<[Option<usize>; 2]>,
    /// Whether two DOFs share an equation (a host's tied DOFs): then
    /// [`HostContact::scatter_add`] checks running sums.
    shared_equations: bool,
    sides: Vec<(Side, Material)>,
    pairs: Vec<HostPair>,
    built: Option<Built>,
}

/// A side as the host gives it to [`HostContact::add_side`], named for
/// messages: what each step of adding it reads.
struct GivenSide<'a> {
    /// How messages name the side (`Side::name`).
    name: String,
    tag: i32,
    body: i32,
    /// The host's numbers of the side's interface nodes.
    nodes: &'a [i64],
    /// Each node's coordinates.
    xy: &'a [[f64; 2]],
    /// Each node's x and y equations (below the index base: none).
    equations: &'a [[i64; 2]],
    /// The side's edges as pairs of host node numbers.
    edges: &'a [[i64; 2]],
}

impl GivenSide<'_> {
    /// Refuses per-node arrays of different lengths.
    fn check_lengths(&self) -> Result<()> {
        let n = self.nodes.len();
        if self.xy.len() != n || self.equations.len() != n {
            return Err(Error::argument(format!(
                "{}: {n} nodes but {} coordinates and {} equation pairs",
                self.name,
                self.xy.len(),
                self.equations.len()
            )));
        }
        Ok(())
    }
}

/// A side's nodes and edges checked against the context without changing
/// it: what [`HostContact::add_side`] commits once the whole side is
/// accepted, so that on error nothing changes.
struct StagedSide {
    /// The side's nodes new to the context, in the order first given.
    fresh: Vec<FreshNode>,
    /// The context's node numbers and `fresh`'s, to local indices.
    local: HashMap<i64, usize>,
    /// The coordinates of the context's nodes, then `fresh`'s.
    x: Vec<[f64; 2]>,
    /// The side's edges over local indices.
    edges: Vec<[usize; 2]>,
}

/// An interface node as the context keeps it.
struct FreshNode {
    /// The host's number.
    id: i64,
    x: [f64; 2],
    /// The 0-based equations of its x and y unknowns.
    equations: [Option<usize>; 2],
}

/// The most values a host vector of `f64` can hold (a Rust slice, and any
/// C array, spans at most `isize::MAX` bytes): every equation is below it.
const MAX_EQUATIONS: usize = isize::MAX as usize / std::mem::size_of::<f64>();

/// What an active-set update changed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Update {
    /// Whether the active set changed (false: settled).
    pub changed: bool,
    /// Elements switched on.
    pub switched_on: usize,
    /// Elements switched off.
    pub switched_off: usize,
}

impl HostContact {
    /// An empty context whose node numbers and equations are in
    /// `index_base` (0 or 1), under `options` (law, E_c, λ, inversion
    /// test, and the cap on active-set updates before a loop counts as not
    /// converged).
    pub fn new(index_base: usize, options: ContactOptions) -> Result<HostContact> {
        if index_base > 1 {
            return Err(Error::argument(format!(
                "index_base = {index_base} must be 0 or 1"
            )));
        }
        options.validate()?;
        Ok(HostContact {
            base: index_base,
            options,
            x: Vec::new(),
            node_id: Vec::new(),
            local: HashMap::new(),
            equation: Vec::new(),
            shared_equations: false,
            sides: Vec::new(),
            pairs: Vec::new(),
            built: None,
        })
    }

    /// The index base of node numbers and equations.
    pub fn index_base(&self) -> usize {
        self.base
    }

    /// Replaces the options (before the contact mesh is built).
    pub fn set_options(&mut self, options: ContactOptions) -> Result<()> {
        self.check_open()?;
        options.validate()?;
        self.options = options;
        Ok(())
    }

    /// The number of interface nodes.
    pub fn n_nodes(&self) -> usize {
        self.x.len()
    }

    /// Adds per-node values (2 per interface node, as a residual) into the
    /// host's vector indexed by equation (index base applied); DOFs without
    /// an equation are left out; a non-finite value is refused, naming its
    /// node, and so is a sum that would not be finite (an entry of the
    /// host's vector that is not finite: `InvalidArgument`; an overflow:
    /// `NumericalFailure`), naming the node and the equation. Checked
    /// before anything is added.
    pub fn scatter_add(&self, per_node: &[f64], host: &mut [f64]) -> Result<()> {
        if per_node.len() != 2 * self.x.len() {
            return Err(Error::argument(format!(
                "`residual` holds {} values but the {} interface nodes need {}",
                per_node.len(),
                self.x.len(),
                2 * self.x.len()
            )));
        }
        self.check_equations(host.len())?;
        self.check_sums(per_node, host)?;
        for (v, eq) in self.equation.iter().enumerate() {
            for c in 0..2 {
                if let Some(e) = eq[c] {
                    host[e] += per_node[2 * v + c];
                }
            }
        }
        Ok(())
    }

    /// Refuses a non-finite value of an interface node's DOF, `value(v, c)`
    /// of node v, component c, read from the caller's array `what` (at the
    /// host equation `equation(v, c)` when it has one). A host's NaN would
    /// otherwise come back as a result with OK (`gather`) or be added into
    /// its vector (`scatter_add`), far from where it arose.
    fn check_finite(
        &self,
        what: &str,
        value: impl Fn(usize, usize) -> f64,
        equation: impl Fn(usize, usize) -> Option<usize>,
    ) -> Result<()> {
        for v in 0..self.x.len() {
            for c in 0..2 {
                let x = value(v, c);
                if !x.is_finite() {
                    return Err(self.not_finite(what, v, c, x, equation(v, c)));
                }
            }
        }
        Ok(())
    }

    /// The error for the non-finite value `x` of node v's DOF c in the
    /// caller's array `what` (at host equation `equation`, if any).
    fn not_finite(&self, what: &str, v: usize, c: usize, x: f64, equation: Option<usize>) -> Error {
        let at = match equation {
            Some(e) => format!(" (equation {})", e + self.base),
            None => String::new(),
        };
        Error::argument(format!(
            "`{what}`: the {} value of interface node {}{at} is {x}, not finite",
            ["x", "y"][c],
            self.node_id[v]
        ))
    }

    /// Refuses the addition of `per_node` into `host` (as
    /// [`HostContact::scatter_add`] makes it) when a value of `per_node` is
    /// not finite, or an entry it touches is not finite before or would
    /// not be after: the sums in the order of the addition, so that the
    /// host's vector is not written on error. Where no two DOFs share an
    /// equation (the common case, known from [`HostContact::add_side`]) one
    /// pass over the interface DOFs without allocation; else the running
    /// sums of the shared equations.
    fn check_sums(&self, per_node: &[f64], host: &[f64]) -> Result<()> {
        let mut running: HashMap<usize, f64> = HashMap::new();
        if self.shared_equations {
            let n = 2 * self.x.len();
            running
                .try_reserve(n)
                .map_err(|_| out_of_memory::<(usize, f64)>(n, "the sums of `residual`"))?;
        }
        for (v, eq) in self.equation.iter().enumerate() {
            for (c, &e) in eq.iter().enumerate() {
                let r = per_node[2 * v + c];
                if !r.is_finite() {
                    return Err(self.not_finite("residual", v, c, r, e));
                }
                let Some(e) = e else { continue };
                let before = match self.shared_equations {
                    true => *running.entry(e).or_insert(host[e]),
                    false => host[e],
                };
                let sum = before + r;
                if self.shared_equations {
                    running.insert(e, sum);
                }
                if sum.is_finite() {
                    continue;
                }
                let at = format!(
                    "equation {} ({} of interface node {})",
                    e + self.base,
                    ["x", "y"][c],
                    self.node_id[v]
                );
                return Err(match host[e].is_finite() {
                    false => Error::argument(format!(
                        "`host_vector` holds {} at {at}, not finite",
                        host[e]
                    )),
                    true => Error::new(
                        Status::NumericalFailure,
                        format!(
                            "adding `residual` into `host_vector` at {at} overflows \
                             ({before:e} + {r:e}): rescale the model or its loads"
                        ),
                    ),
                });
            }
        }
        Ok(())
    }

    /// Refuses a host vector of `n` values that some equation does not fit.
    fn check_equations(&self, n: usize) -> Result<()> {
        for (v, eq) in self.equation.iter().enumerate() {
            if let Some(e) = eq.iter().flatten().find(|&&e| e >= n) {
                return Err(Error::argument(format!(
                    "the host vector holds {n} values but interface node {} has equation {}",
                    self.node_id[v],
                    e + self.base
                )));
            }
        }
        Ok(())
    }

    /// Adds one side of a contact interface, of body `body` with material
    /// `material` (its E is the default E_c when it is the softer side; the
    /// stick law takes its ν): its interface nodes (the host's numbers)
    /// with their coordinates and the equations of their x and y unknowns
    /// (below the index base: no unknown, the DOF is fixed), and its edges
    /// (pairs of those node numbers), each with the body on its left (an
    /// edge running against its neighbour is refused, naming it). A
    /// node given by two sides (a corner shared by bodies) must come with
    /// the same coordinates and equations. A node number below the index
    /// base is refused, naming the side, the node's entry and the number,
    /// and so is an equation no host vector can hold (from the base +
    /// `isize::MAX / 8` on), naming the node and the equation; the
    /// host's system size is checked by [`HostContact::gather`] and
    /// [`HostContact::scatter_add`], which see its vector. Returns the
    /// side's index (0-based). On error nothing changes.
    #[allow(clippy::too_many_arguments)]
    pub fn add_side(
        &mut self,
        tag: i32,
        body: i32,
        material: Material,
        nodes: &[i64],
        xy: &[[f64; 2]],
        equations: &[[i64; 2]],
        edges: &[[i64; 2]],
    ) -> Result<usize> {
        self.check_open()?;
        let given = GivenSide {
            // As every message of the context names a side (`Side::name`):
            // its index, which pairs are declared with, and the host's tag.
            name: format!("side {} (tag {tag})", self.sides.len()),
            tag,
            body,
            nodes,
            xy,
            equations,
            edges,
        };
        given.check_lengths()?;
        self.check_section(&given, &material)?;
        let mut staged = self.stage(&given)?;
        self.stage_nodes(&given, &mut staged)?;
        self.reserve_commit(&staged, &given.name)?;
        self.stage_edges(&given, &mut staged)?;
        let side = self.staged_side(&given, &staged)?;
        let shared = self.shared_with(&staged, &given.name)?;
        Ok(self.commit(staged, side, material, shared))
    }

    /// Refuses a side whose material's section (plane or axisymmetric)
    /// differs from the sides' before it, and an axisymmetric side with a
    /// node across the axis (x < 0), naming it.
    fn check_section(&self, given: &GivenSide, material: &Material) -> Result<()> {
        let ring = material.section().is_revolution();
        if let Some((i, (_, other))) =
            (self.sides.iter().enumerate()).find(|(_, (_, m))| m.section().is_revolution() != ring)
        {
            return Err(Error::argument(format!(
                "{}: a {} side cannot join side {i}, which is {}: a contact context is \
                 axisymmetric in every side or in none",
                given.name,
                material.plane().name(),
                other.plane().name()
            )));
        }
        if let Some(i) = (0..given.xy.len()).find(|&i| ring && given.xy[i][0] < 0.0) {
            return Err(Error::argument(format!(
                "{}: node {} (entry {}) has x = {} < 0: an axisymmetric side lies at x >= 0 \
                 (x is the radius)",
                given.name,
                given.nodes[i],
                i + self.base,
                given.xy[i][0]
            )));
        }
        Ok(())
    }

    /// An empty staging of `given` beside the context's nodes: every
    /// structure sized by the caller's counts reserved fallibly before any
    /// work (`error::reserved`), so that a count too large for memory is
    /// an error, not an abort of the host.
    fn stage(&self, given: &GivenSide) -> Result<StagedSide> {
        let what = &given.name;
        let fresh = reserved(given.nodes.len(), what)?;
        let edges = reserved(given.edges.len(), what)?;
        let x = reserved(self.x.len() + given.nodes.len(), what)?;
        let mut local = HashMap::new();
        let room = self.local.len() + given.nodes.len();
        local
            .try_reserve(room)
            .map_err(|_| out_of_memory::<(i64, usize)>(room, what))?;
        local.extend(self.local.iter().map(|(&k, &v)| (k, v)));
        Ok(StagedSide {
            fresh,
            local,
            x,
            edges,
        })
    }

    /// Stages the side's nodes, each checked ([`Self::checked_node`]):
    /// a node new to the context is added, one given before (by another
    /// side, a corner shared by bodies, or by this one) must come with the
    /// same coordinates and equations. Then the coordinates of all.
    fn stage_nodes(&self, given: &GivenSide, staged: &mut StagedSide) -> Result<()> {
        for i in 0..given.nodes.len() {
            let node = self.checked_node(given, i)?;
            match staged.local.get(&node.id) {
                Some(&k) => {
                    let (x0, e0) = match k < self.x.len() {
                        true => (self.x[k], self.equation[k]),
                        false => {
                            let known = &staged.fresh[k - self.x.len()];
                            (known.x, known.equations)
                        }
                    };
                    if x0 != node.x || e0 != node.equations {
                        return Err(Error::argument(format!(
                            "{}: node {} (entry {}) is given again with other \
                             coordinates or equations",
                            given.name,
                            node.id,
                            i + self.base
                        )));
                    }
                }
                None => {
                    staged
                        .local
                        .insert(node.id, self.x.len() + staged.fresh.len());
                    staged.fresh.push(node);
                }
            }
        }
        staged.x.extend_from_slice(&self.x);
        staged.x.extend(staged.fresh.iter().map(|f| f.x));
        Ok(())
    }

    /// Entry `i` of the side's nodes on its own: its number (a number
    /// below the base would name no node of the host's, and was accepted,
    /// read back as if it did), its equations ([`Self::equation_of`]) and
    /// its coordinates (finite).
    fn checked_node(&self, given: &GivenSide, i: usize) -> Result<FreshNode> {
        let (id, p, eq) = (given.nodes[i], given.xy[i], given.equations[i]);
        if id < self.base as i64 {
            return Err(Error::argument(format!(
                "{}: node {id} (entry {}) is below the index base {}",
                given.name,
                i + self.base,
                self.base
            )));
        }
        let mut unknowns = [None; 2];
        for c in 0..2 {
            unknowns[c] = self.equation_of(eq[c]).map_err(|limit| {
                Error::argument(format!(
                    "{}: node {id} (entry {}) has equation {} for its {} \
                     unknown, beyond any host vector (equations run from the index base \
                     {} to at most {limit})",
                    given.name,
                    i + self.base,
                    eq[c],
                    ["x", "y"][c],
                    self.base
                ))
            })?;
        }
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(Error::argument(format!(
                "{}: node {id} has coordinates ({:?}, {:?})",
                given.name, p[0], p[1]
            )));
        }
        Ok(FreshNode {
            id,
            x: p,
            equations: unknowns,
        })
    }

    /// Room for the staged nodes in the context's own lists, so that
    /// [`Self::commit`] cannot fail halfway.
    fn reserve_commit(&mut self, staged: &StagedSide, what: &str) -> Result<()> {
        reserve_more(&mut self.node_id, staged.fresh.len(), what)?;
        reserve_more(&mut self.equation, staged.fresh.len(), what)
    }

    /// Stages the side's edges over local indices: an edge must name nodes
    /// the context now knows.
    fn stage_edges(&self, given: &GivenSide, staged: &mut StagedSide) -> Result<()> {
        for (e, &[p, q]) in given.edges.iter().enumerate() {
            let find = |id: i64| {
                staged.local.get(&id).copied().ok_or_else(|| {
                    Error::argument(format!(
                        "{}: edge {} names node {id}, not one of the side's nodes",
                        given.name,
                        e + self.base
                    ))
                })
            };
            let edge = [find(p)?, find(q)?];
            staged.edges.push(edge);
        }
        Ok(())
    }

    /// The side over the context's nodes and the staged ones, its edges
    /// checked to run one way ([`Side::from_edges`]).
    fn staged_side(&self, given: &GivenSide, staged: &StagedSide) -> Result<Side> {
        let mut ids = reserved(staged.x.len(), &given.name)?;
        ids.extend_from_slice(&self.node_id);
        ids.extend(staged.fresh.iter().map(|f| f.id));
        let named = Nodes {
            x: &staged.x,
            base: self.base,
            ids: Some(&ids),
        };
        let index = self.sides.len();
        Side::from_edges(named, index, given.tag, given.body, &staged.edges)
    }

    /// Whether two DOFs share an equation once the staged nodes are added
    /// (then [`HostContact::scatter_add`] checks running sums).
    fn shared_with(&self, staged: &StagedSide, what: &str) -> Result<bool> {
        if self.shared_equations {
            return Ok(true);
        }
        let n_dofs = 2 * (self.equation.len() + staged.fresh.len());
        let equations = self
            .equation
            .iter()
            .chain(staged.fresh.iter().map(|f| &f.equations));
        shares_equations(equations.flatten().copied(), n_dofs, what)
    }

    /// Makes the staged side the context's; cannot fail (its memory is
    /// reserved), so that an error before leaves the context as it was.
    /// Returns the side's index.
    fn commit(
        &mut self,
        staged: StagedSide,
        side: Side,
        material: Material,
        shared: bool,
    ) -> usize {
        self.x = staged.x;
        for node in staged.fresh {
            self.node_id.push(node.id);
            self.equation.push(node.equations);
        }
        self.local = staged.local;
        self.shared_equations = shared;
        self.sides.push((side, material));
        self.sides.len() - 1
    }

    /// Declares sides `a` and `b` (indices from [`HostContact::add_side`],
    /// on different bodies) a contact pair: B is built from their matching
    /// nodes, or by triangulating the strip between them. Two sides whose
    /// normals point the same way where they face each other (one given
    /// clockwise) are refused, naming both ([`check_facing`]); so are two
    /// sides already paired (either way round: their contact would count
    /// twice). Returns the pair's index.
    pub fn add_pair(&mut self, a: usize, b: usize) -> Result<usize> {
        self.add_pair_with(a, b, None)
    }

    /// Declares a pair with the contact mesh B the host gives: triangles
    /// over interface nodes of the two sides (host numbers), each given
    /// once (a repeated triangle is refused, naming both). A node number
    /// below the index base is refused, naming the pair, the triangle and
    /// the node's place in it. Returns the pair's index.
    pub fn add_pair_with_mesh(
        &mut self,
        a: usize,
        b: usize,
        triangles: &[[i64; 3]],
    ) -> Result<usize> {
        let mut local = reserved(triangles.len(), "the contact mesh")?;
        for (t, tri) in triangles.iter().enumerate() {
            let mut l = [0; 3];
            for k in 0..3 {
                // Named as such rather than as a node on no side: the
                // number itself is wrong.
                if tri[k] < self.base as i64 {
                    return Err(Error::argument(format!(
                        "pair {} (sides {a} and {b}), contact triangle {}: node {} (its {}) \
                         is below the index base {}",
                        self.pairs.len(),
                        t + self.base,
                        tri[k],
                        ["first", "second", "third"][k],
                        self.base
                    )));
                }
                l[k] = *self.local.get(&tri[k]).ok_or_else(|| {
                    Error::argument(format!(
                        "contact triangle {}: node {} is on no side",
                        t + self.base,
                        tri[k]
                    ))
                })?;
            }
            local.push(l);
        }
        self.add_pair_with(a, b, Some(local))
    }

    fn add_pair_with(
        &mut self,
        a: usize,
        b: usize,
        triangles: Option<Vec<[usize; 3]>>,
    ) -> Result<usize> {
        self.check_open()?;
        for s in [a, b] {
            if s >= self.sides.len() {
                return Err(Error::argument(format!(
                    "side {s} does not exist ({} sides, 0-based)",
                    self.sides.len()
                )));
            }
        }
        let (sa, sb) = (&self.sides[a].0, &self.sides[b].0);
        if sa.body == sb.body {
            return Err(Error::contact(format!(
                "{} and {} are both on body {}: self-contact is not supported",
                sa.name(),
                sb.name(),
                sa.body
            )));
        }
        // A pair declared twice (either way round) would be two copies of
        // its B, doubling the contact stiffness, residual and length.
        if let Some(p) = self
            .pairs
            .iter()
            .position(|p| p.sides == [a, b] || p.sides == [b, a])
        {
            // INVALID_CONTACT, as the model's pair declared twice.
            return Err(Error::contact(format!(
                "contact pair ({a}, {b}) of {} and {} is already declared (pair {p})",
                sa.name(),
                sb.name()
            )));
        }
        // Build it now, so that a bad pair is reported by this call.
        let pair = HostPair {
            sides: [a, b],
            triangles,
        };
        self.elements_of(self.pairs.len(), &pair)?;
        self.pairs.push(pair);
        Ok(self.pairs.len() - 1)
    }

    /// The 0-based equation of a host's equation number `e` (index base
    /// applied): `None` below the base (the documented mark of a DOF
    /// without an equation, `i64::MIN` included), or, as the error, the
    /// largest equation number any host vector can hold when `e` is beyond
    /// it. The host's system size is not known here: `gather` and
    /// `scatter_add` check each equation against the vector they are
    /// given; what is refused here could be valid in no vector (one of
    /// `f64` holds at most `isize::MAX` bytes), and was found accepted up
    /// to `i64::MAX`, or read as "no equation" where `usize` is 32 bits.
    fn equation_of(&self, e: i64) -> std::result::Result<Option<usize>, i64> {
        let limit = MAX_EQUATIONS - 1;
        let Some(e) = e.checked_sub(self.base as i64) else {
            return Ok(None);
        };
        match usize::try_from(e) {
            Err(_) if e < 0 => Ok(None),
            Ok(e) if e <= limit => Ok(Some(e)),
            _ => Err(limit as i64 + self.base as i64),
        }
    }

    fn check_open(&self) -> Result<()> {
        match self.built {
            Some(_) => Err(Error::state(
                "the contact mesh is built: sides and pairs are fixed (create a new context)",
            )),
            None => Ok(()),
        }
    }

    fn elements_of(&self, index: usize, pair: &HostPair) -> Result<Vec<ContactElement>> {
        let nodes = Nodes {
            x: &self.x,
            base: self.base,
            ids: Some(&self.node_id),
        };
        let (a, b) = (&self.sides[pair.sides[0]].0, &self.sides[pair.sides[1]].0);
        // The host's sides carry the normals it gave (a mesh's come from
        // its triangles): a side given clockwise is refused here.
        check_facing(&self.x, a, b)?;
        match &pair.triangles {
            None => strip(nodes, index, a, b),
            Some(t) => Ok(checked_triangles(nodes, index, a, b, t)?.0),
        }
    }

    /// Builds B of every pair, its laws and the pattern; the sides and
    /// pairs are fixed from then on. Called by the first call that needs
    /// them. The active set starts as tfem's own loop does (per pair, the
    /// elements at the smallest gap).
    pub fn setup(&mut self) -> Result<()> {
        if self.built.is_some() {
            return Ok(());
        }
        if self.pairs.is_empty() {
            return Err(Error::state("no contact pair: call add_pair first"));
        }
        let mut elements = Vec::new();
        for (i, pair) in self.pairs.iter().enumerate() {
            elements.append(&mut self.elements_of(i, pair)?);
        }
        let soft = |pair: usize| {
            let [a, b] = self.pairs[pair].sides;
            softer(self.sides[a].1, self.sides[b].1)
        };
        let laws = element_laws(
            Nodes::new(&self.x, self.base),
            &elements,
            soft,
            self.size(),
            &self.options,
        )?;
        let equation = |g: usize| self.equation[g / 2][g % 2];
        let owners = Owners {
            x: std::borrow::Cow::Owned(self.x.clone()),
            base: self.base,
            elements: std::borrow::Cow::Owned(elements),
        };
        let set = ContactSet::owned(owners, laws, equation, &[], &self.options)?;
        let active = ActiveSet::new(set.initial_active());
        let (mut rows, mut cols, mut entries) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..set.len() {
            let eq = set.unknowns(k);
            for a in 0..6 {
                for b in 0..6 {
                    if let (Some(i), Some(j)) = (eq[a], eq[b]) {
                        rows.push((i + self.base) as i64);
                        cols.push((j + self.base) as i64);
                        entries.push((k as u32, a as u8, b as u8));
                    }
                }
            }
        }
        self.built = Some(Built {
            set,
            active,
            rows,
            cols,
            entries,
            scratch: vec![0.0; 2 * self.x.len()],
        });
        Ok(())
    }

    /// The default λ: the larger side of the interface nodes' bounding box.
    fn size(&self) -> f64 {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &self.x {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }

    fn built(&mut self) -> Result<&mut Built> {
        self.setup()?;
        Ok(self.built.as_mut().expect("just built"))
    }

    /// [`HostContact::built`] borrowing the field only (beside the others).
    fn ready(built: &mut Option<Built>) -> &mut Built {
        built.as_mut().expect("set up")
    }

    /// The interface nodes, in the order of every per-node array (host
    /// numbers).
    pub fn nodes(&self) -> &[i64] {
        &self.node_id
    }

    /// The elements of B (nodes as indices into [`HostContact::nodes`]).
    pub fn elements(&mut self) -> Result<&[ContactElement]> {
        Ok(self.built()?.set.elements())
    }

    /// The fixed pattern of the contributions: (rows, columns) in the
    /// host's equation numbering (index base applied). Element after
    /// element of B; within one, its 6×6 block row by row over its DOFs
    /// (x then y of its first node, of its second, of its third), the
    /// entries of DOFs without an equation left out. Both triangles of each
    /// block; duplicates (a DOF pair shared by elements) are to be summed.
    pub fn pattern(&mut self) -> Result<(&[i64], &[i64])> {
        let b = self.built()?;
        Ok((&b.rows, &b.cols))
    }

    /// The equation of each of element `k`'s six DOFs (index base
    /// applied), `None` where the DOF has none.
    pub fn element_equations(&mut self, k: usize) -> Result<[Option<i64>; 6]> {
        let base = self.base as i64;
        let b = self.built()?;
        if k >= b.set.len() {
            return Err(Error::argument(format!(
                "contact element {} does not exist ({} elements)",
                k + base as usize,
                b.set.len()
            )));
        }
        Ok(b.set.unknowns(k).map(|e| e.map(|e| e as i64 + base)))
    }

    /// The 6×6 block (row-major) element `k` contributes to the tangent:
    /// its stiffness when active, zeros when not.
    pub fn element_block(&mut self, k: usize, out: &mut [f64; 36]) -> Result<()> {
        self.element_equations(k)?;
        let b = self.built()?;
        *out = match b.active.active()[k] {
            true => b.set.stiffness(k).k,
            false => [0.0; 36],
        };
        Ok(())
    }

    /// The contact length of the current active set (docs/method.md §6.8):
    /// per contact zone (a pair's active elements connected through shared
    /// nodes), the facing interface-edge length of the
    /// active elements of the family (edges on one side, or on the other)
    /// active over the longer length; +0.0 when none is (their mean would
    /// read half the width where one family alone carries a contact).
    pub fn contact_length(&mut self) -> Result<f64> {
        let b = self.built()?;
        let active = b.active.active();
        Ok(super::conformity::contact_length(b.set.elements(), active))
    }

    /// The active flag of every element of B.
    pub fn active(&mut self) -> Result<&[bool]> {
        Ok(self.built()?.active.active())
    }

    /// Sets the active flags (a warm start, or a restored state); the
    /// history and cycle detection start anew.
    pub fn set_active(&mut self, active: &[bool]) -> Result<()> {
        let b = self.built()?;
        if active.len() != b.set.len() {
            return Err(Error::argument(format!(
                "{} active flags for {} contact elements",
                active.len(),
                b.set.len()
            )));
        }
        b.active = ActiveSet::new(active.to_vec());
        Ok(())
    }

    /// Starts a new active-set loop from the current flags (a new load
    /// step): the history and the sets visited are forgotten.
    pub fn restart(&mut self) -> Result<()> {
        let b = self.built()?;
        b.active = ActiveSet::new(b.active.active().to_vec());
        Ok(())
    }

    /// Checks a per-node displacement array (2 per interface node): its
    /// length, and every value finite (`InvalidArgument` naming the node).
    fn check_u(&self, u: &[f64]) -> Result<()> {
        if u.len() != 2 * self.x.len() {
            return Err(Error::argument(format!(
                "`u` holds {} values but the {} interface nodes need {}",
                u.len(),
                self.x.len(),
                2 * self.x.len()
            )));
        }
        // A non-finite displacement is the caller's input, not an
        // overflow of tfem's: refused as such, naming the node.
        let equation = |v: usize, c: usize| self.equation[v][c];
        self.check_finite("u", |v, c| u[2 * v + c], equation)
    }

    /// The per-node displacements of the host's solution vector `u_eq`
    /// (indexed by equation, index base applied); DOFs without an equation
    /// count as fixed at zero; a non-finite entry at an interface node's
    /// equation is refused, naming both. Checked before anything is written.
    pub fn gather(&self, u_eq: &[f64], u: &mut [f64]) -> Result<()> {
        if u.len() != 2 * self.x.len() {
            return Err(Error::argument(format!(
                "`u` holds {} values but the {} interface nodes need {}",
                u.len(),
                self.x.len(),
                2 * self.x.len()
            )));
        }
        self.check_equations(u_eq.len())?;
        let equation = |v: usize, c: usize| self.equation[v][c];
        let value = |v: usize, c: usize| equation(v, c).map_or(0.0, |e| u_eq[e]);
        self.check_finite("u_equations", value, equation)?;
        for (v, eq) in self.equation.iter().enumerate() {
            for c in 0..2 {
                u[2 * v + c] = eq[c].map_or(0.0, |e| u_eq[e]);
            }
        }
        Ok(())
    }

    /// The contact contributions at the per-node displacements `u`: the
    /// tangent's values in the order of [`HostContact::pattern`] (zeros for
    /// inactive elements) into `values` when given, and the residual
    /// Σ_active (K_e u_e − f0_e), 2 per interface node, into `residual` when
    /// given. A non-finite `u` is refused (`InvalidArgument`, naming the
    /// node and the value; so in every call taking `u`), a result that
    /// overflows is `NumericalFailure`. Allocates nothing.
    pub fn evaluate(
        &mut self,
        u: &[f64],
        values: Option<&mut [f64]>,
        residual: Option<&mut [f64]>,
    ) -> Result<()> {
        self.check_u(u)?;
        self.setup()?;
        let n_nodes = self.x.len();
        let b = Self::ready(&mut self.built);
        // Every check first, then the writes: on error the caller's
        // buffers are as they were.
        if let Some(values) = &values
            && values.len() != b.entries.len()
        {
            return Err(Error::argument(format!(
                "`values` holds {} values but the pattern has {}",
                values.len(),
                b.entries.len()
            )));
        }
        if let Some(residual) = &residual
            && residual.len() != 2 * n_nodes
        {
            return Err(Error::argument(format!(
                "`residual` holds {} values but the {} interface nodes need {}",
                residual.len(),
                n_nodes,
                2 * n_nodes
            )));
        }
        let active = b.active.active();
        let value = |&(k, a, c): &(u32, u8, u8)| match active[k as usize] {
            true => b.set.stiffness(k as usize).k[6 * a as usize + c as usize],
            false => 0.0,
        };
        if values.is_some() {
            let base = self.base;
            let name = |k: usize| format!("pattern entry {}", k + base);
            ensure_finite(b.entries.iter().map(value), 1, "contact tangent", name)?;
        }
        if residual.is_some() {
            let r = &mut b.scratch;
            r.fill(0.0);
            for (k, el) in b.set.elements().iter().enumerate() {
                if !active[k] {
                    continue;
                }
                let cs = b.set.stiffness(k);
                let ue: [f64; 6] = std::array::from_fn(|a| u[2 * el.nodes[a / 2] + a % 2]);
                for a in 0..6 {
                    let ku: f64 = (0..6).map(|c| cs.k[6 * a + c] * ue[c]).sum();
                    r[2 * el.nodes[a / 2] + a % 2] += ku - cs.f0[a];
                }
            }
            let name = |v: usize| format!("interface node {}", self.node_id[v]);
            ensure_finite(r.iter().copied(), 2, "contact residual", name)?;
        }
        if let Some(values) = values {
            for (v, e) in values.iter_mut().zip(&b.entries) {
                *v = value(e);
            }
        }
        if let Some(residual) = residual {
            residual.copy_from_slice(&b.scratch);
        }
        Ok(())
    }

    /// The inversion test at the per-node displacements `u` (the solution
    /// of a solve with the current active set): switches the elements that
    /// the test finds inverted on and the others off, and says what
    /// changed. A set visited before (a cycle), or more updates than the
    /// options allow, is refused with `NotConverged` and the history; the
    /// flags then stay as they were.
    pub fn update(&mut self, u: &[f64]) -> Result<Update> {
        self.check_u(u)?;
        let cap = self.options.max_iterations;
        let b = self.built()?;
        let elements = b.set.elements();
        let verdict = b.set.inverted(b.active.active(), |k| {
            let tri = &elements[k].nodes;
            std::array::from_fn(|a| u[2 * tri[a / 2] + a % 2])
        })?;
        let iteration = b.active.history().len() + 1;
        if iteration > cap {
            return Err(b.active.not_settled(cap));
        }
        let before: Vec<bool> = b.active.active().to_vec();
        let settled = b.active.advance(verdict, iteration)?;
        let now = b.active.active();
        let on = now.iter().zip(&before).filter(|(n, o)| **n && !**o).count();
        let off = now.iter().zip(&before).filter(|(n, o)| !**n && **o).count();
        Ok(Update {
            changed: !settled,
            switched_on: on,
            switched_off: off,
        })
    }

    /// The normal gap at every interface node for the displacements `u`
    /// (linearised; negative: interpenetration): the smallest, over the
    /// elements of B at the node, of the distance of an element's apex from
    /// its interface edge. A node in no element of B (on a part of its side
    /// beyond the other side's end, facing nothing) has no gap and reads 0:
    /// it is not in contact (no force acts there); such nodes are those
    /// absent from [`HostContact::elements`].
    pub fn gaps(&mut self, u: &[f64], out: &mut [f64]) -> Result<()> {
        self.check_u(u)?;
        let n = self.x.len();
        if out.len() != n {
            return Err(Error::argument(format!(
                "`gaps` holds {} values but there are {n} interface nodes",
                out.len()
            )));
        }
        self.setup()?;
        let b = Self::ready(&mut self.built);
        // NaN marks a node no element has reached yet (f64::min would
        // swallow a NaN gap, and an infinite one would pass for "none").
        let g = &mut b.scratch[..n];
        g.fill(f64::NAN);
        for (k, el) in b.set.elements().iter().enumerate() {
            if el.edge_length <= 0.0 {
                continue;
            }
            let ue: [f64; 6] = std::array::from_fn(|a| u[2 * el.nodes[a / 2] + a % 2]);
            let gap = b.set.opening(k, &ue) / el.edge_length;
            if !gap.is_finite() {
                let name = |k: usize| format!("contact element {}", k + self.base);
                return ensure_finite([gap], 1, "normal gap", |_| name(k));
            }
            for &v in &el.nodes {
                g[v] = if g[v].is_nan() { gap } else { g[v].min(gap) };
            }
        }
        g.iter_mut().filter(|g| g.is_nan()).for_each(|g| *g = 0.0);
        out.copy_from_slice(g);
        Ok(())
    }

    /// The contact pressure of every element of B for the displacements
    /// `u` (a stress, positive in compression; zero when inactive).
    pub fn pressures(&mut self, u: &[f64], out: &mut [f64]) -> Result<()> {
        self.check_u(u)?;
        self.setup()?;
        let base = self.base;
        let b = Self::ready(&mut self.built);
        if out.len() != b.set.len() {
            return Err(Error::argument(format!(
                "`pressures` holds {} values but there are {} contact elements",
                out.len(),
                b.set.len()
            )));
        }
        let elements = b.set.elements();
        let pressure = |k: usize| match b.active.active()[k] {
            true => {
                let tri = &elements[k].nodes;
                let ue: [f64; 6] = std::array::from_fn(|a| u[2 * tri[a / 2] + a % 2]);
                b.set.pressure(k, &ue)
            }
            false => 0.0,
        };
        // Checked before anything is written (a pass more: cheap beside
        // an allocation, which evaluation avoids).
        let name = |k: usize| format!("contact element {}", k + base);
        ensure_finite(
            (0..elements.len()).map(pressure),
            1,
            "contact pressure",
            name,
        )?;
        for (k, p) in out.iter_mut().enumerate() {
            *p = pressure(k);
        }
        Ok(())
    }
}

/// Whether two of the `equations` (those of every interface DOF, `None`
/// without one; `n` of them) are the same: a host's tied DOFs.
fn shares_equations(
    mut equations: impl Iterator<Item = Option<usize>>,
    n: usize,
    what: &str,
) -> Result<bool> {
    let mut seen = std::collections::HashSet::new();
    seen.try_reserve(n)
        .map_err(|_| out_of_memory::<usize>(n, what))?;
    Ok(!equations.all(|e| e.is_none_or(|e| seen.insert(e))))
}
