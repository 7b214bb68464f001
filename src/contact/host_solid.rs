//! Contact for 3D host codes that keep their own elements, assembly,
//! solver and Newton loop (docs/method.md §9): the host describes each
//! contact side in its own numbering — the side's nodes, their
//! coordinates, the equations of their x, y and z unknowns, and its
//! triangles numbered counter-clockwise seen from outside the body — and
//! tfem builds B between each pair once ([`prism_layer`]) and returns, at
//! each evaluation, B's contributions in the host's equation numbering:
//! the 3D counterpart of [`super::host::HostContact`].
//!
//! B's topology never changes, so the pattern of its contributions is
//! fixed ([`SolidHostContact::pattern`]: every tetrahedron's 12×12 block,
//! inactive ones contributing zeros) and each evaluation only fills
//! values. A tetrahedron of B is linear: while on it contributes its
//! matrix K_e = s w wᵀ to the tangent and K_e u_e − f0_e to the residual,
//! f0_e = −s J0 w the load of its initial gap J0. Between solves the host
//! asks [`SolidHostContact::update`] which tetrahedra would invert (the
//! same verdict and cycle detection as tfem's own loop).
//!
//! The displacements `u` every call takes are the interface nodes' whole
//! values: a DOF without an equation that the host prescribes to a
//! non-zero value (a rigid tool pressed by δ) must carry that value in
//! `u` ([`SolidHostContact::gather`] reads such DOFs as 0). A linear host
//! then adds minus the residual at u₀ (zero at free DOFs, the prescribed
//! values elsewhere) to its right-hand side: the load of the initial gaps
//! and of the prescribed values together. The default λ is the interface
//! nodes' bounding box, as the plane's host API takes it (the model takes
//! the whole mesh's); a host that wants the model's answer sets λ.

use std::collections::HashMap;

use super::ContactOptions;
use super::gap_tets::{GapData, GapTets};
use super::host::Update;
use super::prism_layer::{FacingSurfaces, prism_layer};
use super::set::ActiveSet;
use crate::error::{Error, Result, Status, ensure_finite};
use crate::fem::tet::{cross, dot, sub};

/// One side of an interface as the host gave it.
#[derive(Debug, Clone)]
struct HostSide {
    body: i32,
    young: f64,
    /// Triangles over local node indices.
    triangles: Vec<[usize; 3]>,
}

/// What [`SolidHostContact::setup`] builds.
#[derive(Debug)]
struct Built {
    gap: GapTets,
    active: ActiveSet,
    /// The pattern (host numbering, index base applied) and, per entry,
    /// the (tetrahedron, row, column) it comes from.
    rows: Vec<i64>,
    cols: Vec<i64>,
    entries: Vec<(u32, u8, u8)>,
    /// Per-node values (3 per interface node) computed and checked before
    /// they reach a caller's buffer.
    scratch: Vec<f64>,
}

/// The 3D contact of a host code's bodies (module documentation).
#[derive(Debug)]
pub struct SolidHostContact {
    base: usize,
    options: ContactOptions,
    x: Vec<[f64; 3]>,
    node_id: Vec<i64>,
    local: HashMap<i64, usize>,
    equation: Vec<[Option<usize>; 3]>,
    sides: Vec<HostSide>,
    pairs: Vec<[usize; 2]>,
    built: Option<Built>,
}

/// The side of [`SolidHostContact::add_side`]: its interface nodes in
/// the host's numbering, their coordinates and the equations of their
/// x, y and z unknowns (below the index base: no unknown, the DOF is
/// fixed), and its triangles over those node numbers, counter-clockwise
/// seen from outside the body.
#[derive(Debug, Clone, Copy)]
pub struct HostSurface<'a> {
    /// The side's tag, for messages.
    pub tag: i32,
    /// Its body (the two sides of a pair must be two bodies).
    pub body: i32,
    /// Its body's Young's modulus (the default E_c is the smaller of a
    /// pair's).
    pub young: f64,
    /// The host's numbers of its nodes.
    pub nodes: &'a [i64],
    /// Each node's coordinates.
    pub xyz: &'a [[f64; 3]],
    /// Each node's three equations.
    pub equations: &'a [[i64; 3]],
    /// Its triangles (host node numbers).
    pub triangles: &'a [[i64; 3]],
}

impl SolidHostContact {
    /// An empty context whose node numbers and equations are in
    /// `index_base` (0 or 1), under `options` (E_c, λ and the cap on
    /// active-set updates; 3D contact is frictionless with its own
    /// inversion test, so another law or test is refused).
    pub fn new(index_base: usize, options: ContactOptions) -> Result<SolidHostContact> {
        if index_base > 1 {
            return Err(Error::argument(format!(
                "index_base = {index_base} must be 0 or 1"
            )));
        }
        options.validate()?;
        let default = ContactOptions::default();
        if options.law != default.law || options.test != default.test {
            return Err(Error::argument(format!(
                "contact in 3D is frictionless with its own inversion test: law {:?} and test \
                 {:?} are not available",
                options.law, options.test
            )));
        }
        Ok(SolidHostContact {
            base: index_base,
            options,
            x: Vec::new(),
            node_id: Vec::new(),
            local: HashMap::new(),
            equation: Vec::new(),
            sides: Vec::new(),
            pairs: Vec::new(),
            built: None,
        })
    }

    /// The index base of node numbers and equations.
    pub fn index_base(&self) -> usize {
        self.base
    }

    /// The interface nodes, in the order of every per-node array (host
    /// numbers).
    pub fn nodes(&self) -> &[i64] {
        &self.node_id
    }

    /// The host equations (index base applied) of the x, y and z unknowns
    /// of interface node `v` (an index into [`SolidHostContact::nodes`]),
    /// `None` where the DOF has none: what a caller checks its own vectors
    /// against before handing them over — the C ABI refuses a non-finite
    /// entry of the host's vector as the caller's input, naming the node
    /// and the equation, before [`SolidHostContact::scatter_add`] would
    /// call it an overflow. Panics if `v` is not an interface node.
    pub fn equations(&self, v: usize) -> [Option<i64>; 3] {
        self.equation[v].map(|e| e.map(|e| (e + self.base) as i64))
    }

    /// Adds one side of a contact interface; returns its index (0-based).
    /// Refused, naming the item: arrays of different lengths, a node
    /// number below the index base, a coordinate that is not finite, an
    /// equation no host vector can hold, a triangle over a node the side
    /// did not give, a node given by two sides with other coordinates or
    /// equations, a modulus that is not finite and positive, and any side
    /// after the pattern is built. On error nothing changes.
    pub fn add_side(&mut self, side: &HostSurface<'_>) -> Result<usize> {
        if self.built.is_some() {
            return Err(Error::state(
                "the pattern is built: sides cannot be added after the first evaluation",
            ));
        }
        let name = format!("side {} (tag {})", self.sides.len() + self.base, side.tag);
        let n = side.nodes.len();
        if side.xyz.len() != n || side.equations.len() != n {
            return Err(Error::argument(format!(
                "{name}: {n} nodes, {} coordinates and {} equation triples",
                side.xyz.len(),
                side.equations.len()
            )));
        }
        if !(side.young.is_finite() && side.young > 0.0) {
            return Err(Error::argument(format!(
                "{name}: Young's modulus {:?} must be finite and > 0",
                side.young
            )));
        }
        let mut added: HashMap<i64, usize> = HashMap::new();
        let mut new_nodes = Vec::new();
        for (i, (&id, (&x, &eq))) in (side.nodes.iter())
            .zip(side.xyz.iter().zip(side.equations))
            .enumerate()
        {
            let equation = self.node_equations(&name, i, id, x, eq)?;
            let at = match self.local.get(&id) {
                Some(&v) if self.x[v] == x && self.equation[v] == equation => v,
                Some(_) => {
                    return Err(Error::argument(format!(
                        "{name}: node {id} was given before with other coordinates or equations"
                    )));
                }
                None => match added.get(&id) {
                    // Given twice in this side: the same node only if alike.
                    Some(&v) => {
                        let (_, x0, eq0) = new_nodes[v - self.x.len()];
                        if (x0, eq0) != (x, equation) {
                            return Err(Error::argument(format!(
                                "{name}: node {id} is given twice with other coordinates or \
                                 equations"
                            )));
                        }
                        v
                    }
                    None => {
                        new_nodes.push((id, x, equation));
                        self.x.len() + new_nodes.len() - 1
                    }
                },
            };
            added.insert(id, at);
        }
        let mut triangles = Vec::with_capacity(side.triangles.len());
        for (t, tri) in side.triangles.iter().enumerate() {
            let mut local = [0; 3];
            for (k, id) in tri.iter().enumerate() {
                local[k] = *added.get(id).ok_or_else(|| {
                    Error::argument(format!(
                        "{name}: triangle {} uses node {id}, which the side does not give",
                        t + self.base
                    ))
                })?;
            }
            triangles.push(local);
        }
        if triangles.is_empty() {
            return Err(Error::argument(format!("{name} has no triangle")));
        }
        for (id, x, equation) in new_nodes {
            self.local.insert(id, self.x.len());
            self.x.push(x);
            self.node_id.push(id);
            self.equation.push(equation);
        }
        self.sides.push(HostSide {
            body: side.body,
            young: side.young,
            triangles,
        });
        Ok(self.sides.len() - 1)
    }

    /// Node `id`'s equations (0-based, `None`: fixed), its number and
    /// coordinates checked.
    fn node_equations(
        &self,
        name: &str,
        i: usize,
        id: i64,
        x: [f64; 3],
        eq: [i64; 3],
    ) -> Result<[Option<usize>; 3]> {
        let base = self.base as i64;
        if id < base {
            return Err(Error::argument(format!(
                "{name}: node entry {} has number {id}, below the index base {base}",
                i + self.base
            )));
        }
        if x.iter().any(|c| !c.is_finite()) {
            return Err(Error::argument(format!(
                "{name}: node {id} has a non-finite coordinate {x:?}"
            )));
        }
        let most = (isize::MAX / 8) as i64;
        let mut out = [None; 3];
        for c in 0..3 {
            if eq[c] >= base.saturating_add(most) {
                return Err(Error::argument(format!(
                    "{name}: node {id}'s equation {} is beyond any host vector",
                    eq[c]
                )));
            }
            out[c] = (eq[c] >= base).then(|| (eq[c] - base) as usize);
        }
        Ok(out)
    }

    /// Adds a contact pair: side `a` (planar; its outward normal opens the
    /// gap) facing side `b` node to node; returns its index. Two sides of
    /// one body, or sides that do not exist, are refused.
    pub fn add_pair(&mut self, a: usize, b: usize) -> Result<usize> {
        if self.built.is_some() {
            return Err(Error::state(
                "the pattern is built: pairs cannot be added after the first evaluation",
            ));
        }
        let n = self.sides.len();
        for s in [a, b] {
            if s >= n {
                return Err(Error::argument(format!(
                    "side {} does not exist ({n} sides)",
                    s + self.base
                )));
            }
        }
        if self.sides[a].body == self.sides[b].body {
            return Err(Error::argument(format!(
                "sides {} and {} are both of body {}: self-contact is not available",
                a + self.base,
                b + self.base,
                self.sides[a].body
            )));
        }
        self.pairs.push([a, b]);
        Ok(self.pairs.len() - 1)
    }

    /// Builds B of every pair and the pattern; the sides and pairs are
    /// fixed from then on. Called by the first call that needs them. The
    /// active set starts from the tetrahedra touching or overlapping at
    /// rest.
    pub fn setup(&mut self) -> Result<()> {
        if self.built.is_some() {
            return Ok(());
        }
        if self.pairs.is_empty() {
            return Err(Error::state("no contact pair: call add_pair first"));
        }
        let (mut elements, mut moduli, mut h_c) = (Vec::new(), Vec::new(), Vec::new());
        for (k, &[a, b]) in self.pairs.iter().enumerate() {
            let name = |e: Error| {
                Error::new(
                    e.status(),
                    format!(
                        "contact pair {} (sides {} and {}): {}",
                        k + self.base,
                        a + self.base,
                        b + self.base,
                        e.message()
                    ),
                )
            };
            let normal = self.facing_normal(a, b).map_err(name)?;
            let layer = prism_layer(&FacingSurfaces {
                points: &self.x,
                a: &self.sides[a].triangles,
                b: &self.sides[b].triangles,
                normal,
                number: &|v| self.node_id[v],
            })
            .map_err(name)?;
            let modulus = (self.options.contact_modulus)
                .unwrap_or(self.sides[a].young.min(self.sides[b].young));
            let shortest = self.shortest_edge(a);
            moduli.resize(moduli.len() + layer.len(), modulus);
            h_c.resize(h_c.len() + layer.len(), shortest);
            elements.extend(layer);
        }
        let prescribed = vec![0.0; 3 * self.x.len()];
        let local = |g: usize| Some(g);
        let gap = GapTets::new(
            &elements,
            &GapData {
                points: &self.x,
                moduli: &moduli,
                h_c: &h_c,
                lambda: self.options.lambda.unwrap_or(self.size()),
                equation: &local,
                prescribed: &prescribed,
            },
        )?;
        let (mut rows, mut cols, mut entries) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..gap.len() {
            let eq = self.tet_equations(&gap, k);
            for a in 0..12 {
                for b in 0..12 {
                    if let (Some(i), Some(j)) = (eq[a], eq[b]) {
                        rows.push((i + self.base) as i64);
                        cols.push((j + self.base) as i64);
                        entries.push((k as u32, a as u8, b as u8));
                    }
                }
            }
        }
        self.built = Some(Built {
            active: ActiveSet::new(gap.initial_active()),
            gap,
            rows,
            cols,
            entries,
            scratch: vec![0.0; 3 * self.x.len()],
        });
        Ok(())
    }

    /// Side a's outward unit normal: its triangles must share it (a
    /// planar side), and side b's must point against it on the whole (the
    /// sides face each other, both numbered counter-clockwise from
    /// outside).
    fn facing_normal(&self, a: usize, b: usize) -> Result<[f64; 3]> {
        let normals = |s: usize| -> Vec<[f64; 3]> {
            (self.sides[s].triangles.iter())
                .map(|t| {
                    let [p, q, r] = t.map(|v| self.x[v]);
                    cross(sub(q, p), sub(r, p))
                })
                .collect()
        };
        let sum = |v: &[[f64; 3]]| {
            v.iter()
                .fold([0.0; 3], |s, n| [s[0] + n[0], s[1] + n[1], s[2] + n[2]])
        };
        let na = normals(a);
        let total = sum(&na);
        let norm = dot(total, total).sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(Error::argument("side a has no area".to_string()));
        }
        let n = total.map(|c| c / norm);
        for (k, m) in na.iter().enumerate() {
            let len = dot(*m, *m).sqrt();
            if !(len.is_finite() && len > 0.0) || dot(*m, n) < (1.0 - 1e-9) * len {
                return Err(Error::argument(format!(
                    "triangle {} of side a leaves its plane, or is numbered the other way: side \
                     a must be planar, its triangles counter-clockwise seen from outside",
                    k + self.base
                )));
            }
        }
        if dot(sum(&normals(b)), n) >= 0.0 {
            return Err(Error::argument(
                "the sides do not face each other: number each side's triangles \
                 counter-clockwise seen from outside its body"
                    .to_string(),
            ));
        }
        Ok(n)
    }

    /// The shortest edge of side `s`'s triangles (h_c of its pair's tie).
    fn shortest_edge(&self, s: usize) -> f64 {
        (self.sides[s].triangles.iter())
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(p, q)| {
                let d = sub(self.x[p], self.x[q]);
                dot(d, d).sqrt()
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The default λ: the larger side of the interface nodes' bounding box.
    fn size(&self) -> f64 {
        (0..3)
            .map(|i| {
                let (lo, hi) = (self.x.iter())
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                        (a.min(p[i]), b.max(p[i]))
                    });
                hi - lo
            })
            .fold(0.0, f64::max)
    }

    /// The host equation (0-based) of each of tetrahedron `k`'s 12 DOFs.
    fn tet_equations(&self, gap: &GapTets, k: usize) -> [Option<usize>; 12] {
        let t = gap.nodes(k);
        std::array::from_fn(|i| self.equation[t[i / 3]][i % 3])
    }

    fn built(&mut self) -> Result<&mut Built> {
        self.setup()?;
        Ok(self.built.as_mut().expect("just built"))
    }

    /// B's tetrahedra (four nodes each, as indices into
    /// [`SolidHostContact::nodes`]).
    pub fn tetrahedra(&mut self) -> Result<Vec<[usize; 4]>> {
        let b = self.built()?;
        Ok((0..b.gap.len()).map(|k| *b.gap.nodes(k)).collect())
    }

    /// The fixed pattern of the contributions: (rows, columns) in the
    /// host's equation numbering (index base applied), tetrahedron after
    /// tetrahedron of B, each one's 12×12 block row by row over its DOFs
    /// (x, y, z of its first node, then its second …), the entries of DOFs
    /// without an equation left out. Both triangles of each block;
    /// duplicates (a DOF pair shared by tetrahedra) are to be summed.
    pub fn pattern(&mut self) -> Result<(&[i64], &[i64])> {
        let b = self.built()?;
        Ok((&b.rows, &b.cols))
    }

    /// The equation of each of tetrahedron `k`'s 12 DOFs (index base
    /// applied), `None` where the DOF has none.
    pub fn element_equations(&mut self, k: usize) -> Result<[Option<i64>; 12]> {
        let base = self.base;
        self.setup()?;
        let b = self.built.as_ref().expect("built");
        if k >= b.gap.len() {
            return Err(Error::argument(format!(
                "contact tetrahedron {} does not exist ({} tetrahedra)",
                k + base,
                b.gap.len()
            )));
        }
        Ok(self
            .tet_equations(&b.gap, k)
            .map(|e| e.map(|e| (e + base) as i64)))
    }

    /// The 12×12 block (row-major) tetrahedron `k` contributes to the
    /// tangent: its matrix while on, zeros while off.
    pub fn element_block(&mut self, k: usize, out: &mut [f64; 144]) -> Result<()> {
        self.element_equations(k)?;
        let b = self.built()?;
        match b.active.active()[k] {
            true => out.copy_from_slice(b.gap.matrix(k)),
            false => out.fill(0.0),
        }
        Ok(())
    }

    /// The active flag of every tetrahedron of B.
    pub fn active(&mut self) -> Result<&[bool]> {
        Ok(self.built()?.active.active())
    }

    /// Sets the active flags (a warm start, or a restored state); the
    /// history and cycle detection start anew.
    pub fn set_active(&mut self, active: &[bool]) -> Result<()> {
        let b = self.built()?;
        if active.len() != b.gap.len() {
            return Err(Error::argument(format!(
                "{} active flags for {} contact tetrahedra",
                active.len(),
                b.gap.len()
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

    /// The area in contact: each active tetrahedron stands for a third of
    /// its prism's facing triangle; +0.0 when none is on (an empty sum of
    /// floats is −0.0).
    pub fn contact_area(&mut self) -> Result<f64> {
        let b = self.built()?;
        Ok((0..b.gap.len())
            .filter(|&k| b.active.active()[k])
            .map(|k| b.gap.area(k) / 3.0)
            .sum::<f64>()
            + 0.0)
    }

    /// Checks a per-node displacement array (3 per interface node).
    fn check_u(&self, u: &[f64]) -> Result<()> {
        if u.len() != 3 * self.x.len() {
            return Err(Error::argument(format!(
                "`u` holds {} values but the {} interface nodes need {}",
                u.len(),
                self.x.len(),
                3 * self.x.len()
            )));
        }
        if let Some(i) = u.iter().position(|x| !x.is_finite()) {
            return Err(Error::argument(format!(
                "`u` of interface node {} is not finite ({:?})",
                self.node_id[i / 3],
                u[i]
            )));
        }
        Ok(())
    }

    /// The per-node displacements (3 per interface node) of the host's
    /// solution vector `u_eq` (indexed by equation, index base applied);
    /// DOFs without an equation read 0 (a host prescribing them to other
    /// values sets those itself: module documentation). An equation beyond
    /// `u_eq` or a non-finite value there is refused, naming the node;
    /// nothing is written then.
    pub fn gather(&self, u_eq: &[f64], u: &mut [f64]) -> Result<()> {
        if u.len() != 3 * self.x.len() {
            return Err(Error::argument(format!(
                "`u` holds {} values but the {} interface nodes need {}",
                u.len(),
                self.x.len(),
                3 * self.x.len()
            )));
        }
        for (v, eq) in self.equation.iter().enumerate() {
            for e in eq.iter().flatten() {
                match u_eq.get(*e) {
                    None => {
                        return Err(Error::argument(format!(
                            "interface node {}'s equation {} is beyond the host's vector of {}",
                            self.node_id[v],
                            e + self.base,
                            u_eq.len()
                        )));
                    }
                    Some(x) if !x.is_finite() => {
                        return Err(Error::argument(format!(
                            "the host's value at equation {} (interface node {}) is not finite",
                            e + self.base,
                            self.node_id[v]
                        )));
                    }
                    Some(_) => {}
                }
            }
        }
        for (v, eq) in self.equation.iter().enumerate() {
            for c in 0..3 {
                u[3 * v + c] = eq[c].map_or(0.0, |e| u_eq[e]);
            }
        }
        Ok(())
    }

    /// Adds per-node values (3 per interface node, as a residual) into the
    /// host's vector indexed by equation (index base applied); DOFs
    /// without an equation are left out. A wrong length, an equation
    /// beyond `host`, or a value or sum that is not finite is refused
    /// before anything is added.
    pub fn scatter_add(&self, per_node: &[f64], host: &mut [f64]) -> Result<()> {
        if per_node.len() != 3 * self.x.len() {
            return Err(Error::argument(format!(
                "`residual` holds {} values but the {} interface nodes need {}",
                per_node.len(),
                self.x.len(),
                3 * self.x.len()
            )));
        }
        let mut sums: HashMap<usize, f64> = HashMap::new();
        for (v, eq) in self.equation.iter().enumerate() {
            for c in 0..3 {
                let Some(e) = eq[c] else { continue };
                let Some(&h) = host.get(e) else {
                    return Err(Error::argument(format!(
                        "interface node {}'s equation {} is beyond the host's vector of {}",
                        self.node_id[v],
                        e + self.base,
                        host.len()
                    )));
                };
                let sum = sums.entry(e).or_insert(h);
                *sum += per_node[3 * v + c];
                if !sum.is_finite() {
                    return Err(Error::new(
                        Status::NumericalFailure,
                        format!(
                            "adding interface node {}'s value at equation {} gives {sum:?}",
                            self.node_id[v],
                            e + self.base
                        ),
                    ));
                }
            }
        }
        for (e, s) in sums {
            host[e] = s;
        }
        Ok(())
    }

    /// B's contributions at the per-node displacements `u`: the tangent's
    /// values in the order of [`SolidHostContact::pattern`] (zeros for
    /// inactive tetrahedra) into `values` when given, and the residual
    /// Σ_active (K_e u_e − f0_e), 3 per interface node, into `residual`
    /// when given. Every check comes before any write.
    pub fn evaluate(
        &mut self,
        u: &[f64],
        values: Option<&mut [f64]>,
        residual: Option<&mut [f64]>,
    ) -> Result<()> {
        self.check_u(u)?;
        self.setup()?;
        let n_nodes = self.x.len();
        let node_id = &self.node_id;
        let b = self.built.as_mut().expect("built");
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
            && residual.len() != 3 * n_nodes
        {
            return Err(Error::argument(format!(
                "`residual` holds {} values but the {} interface nodes need {}",
                residual.len(),
                n_nodes,
                3 * n_nodes
            )));
        }
        let active = b.active.active();
        let gap = &b.gap;
        let value = |&(k, r, c): &(u32, u8, u8)| match active[k as usize] {
            true => gap.matrix(k as usize)[12 * r as usize + c as usize],
            false => 0.0,
        };
        if residual.is_some() {
            let r = &mut b.scratch;
            r.fill(0.0);
            for k in (0..gap.len()).filter(|&k| active[k]) {
                let t = gap.nodes(k);
                let ue: [f64; 12] = std::array::from_fn(|i| u[3 * t[i / 3] + i % 3]);
                let (ke, f0) = (gap.matrix(k), gap.gap_load(k));
                for i in 0..12 {
                    let ku: f64 = (0..12).map(|j| ke[12 * i + j] * ue[j]).sum();
                    r[3 * t[i / 3] + i % 3] += ku - f0[i];
                }
            }
            let name = |v: usize| format!("interface node {}", node_id[v]);
            ensure_finite(r.iter().copied(), 3, "contact residual", name)?;
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

    /// The verdict at the per-node displacements `u` (the solution of a
    /// solve with the current flags): the tetrahedra whose gap is not
    /// positive on, the others off, and what changed. A set visited
    /// before (a cycle), or more updates than the options allow, is
    /// refused with `NotConverged`; the flags then stay as they were.
    pub fn update(&mut self, u: &[f64]) -> Result<Update> {
        self.check_u(u)?;
        let cap = self.options.max_iterations;
        let b = self.built()?;
        let gap = &b.gap;
        let verdict = gap.verdict(|k| {
            let t = gap.nodes(k);
            std::array::from_fn(|i| u[3 * t[i / 3] + i % 3])
        })?;
        let iteration = b.active.history().len() + 1;
        if iteration > cap {
            return Err(b.active.not_settled(cap));
        }
        let before = b.active.active().to_vec();
        let settled = b.active.advance(verdict, iteration)?;
        let now = b.active.active();
        Ok(Update {
            changed: !settled,
            switched_on: now.iter().zip(&before).filter(|(n, o)| **n && !**o).count(),
            switched_off: now.iter().zip(&before).filter(|(n, o)| !**n && **o).count(),
        })
    }

    /// The opening of every tetrahedron of B at the displacements `u`:
    /// its gap J0 + w·u over twice its facing area, the distance across
    /// the interface (negative: an overlap).
    pub fn gaps(&mut self, u: &[f64], out: &mut [f64]) -> Result<()> {
        self.check_u(u)?;
        let b = self.built()?;
        if out.len() != b.gap.len() {
            return Err(Error::argument(format!(
                "`gaps` holds {} values but there are {} contact tetrahedra",
                out.len(),
                b.gap.len()
            )));
        }
        for (k, g) in out.iter_mut().enumerate() {
            let t = b.gap.nodes(k);
            let ue: [f64; 12] = std::array::from_fn(|i| u[3 * t[i / 3] + i % 3]);
            *g = b.gap.gap(k, &ue) / (2.0 * b.gap.area(k));
        }
        Ok(())
    }
}
