//! The solve of a [`SolidModel`]: the unknowns from the constraints, B
//! between the contact pairs, the bodies assembled, and the active-set
//! loop over B's tetrahedra.

use super::*;

/// What a solve derives from the model's structure — the unknowns, B,
/// the pattern, the bodies' matrix and the symbolic analysis — kept for
/// the next solve while the structure and the options that shape B hold.
pub(super) struct Derived {
    key: DerivedKey,
    dofs: DofMap,
    layer: Layer,
    pattern: Pattern,
    values: Vec<f64>,
    analysis: SolidAnalysis,
}

impl std::fmt::Debug for Derived {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Derived")
            .field("unknowns", &self.dofs.n_free())
            .field("gap_tetrahedra", &self.layer.elements.len())
            .field("analysis", &self.analysis)
            .finish()
    }
}

/// What a [`Derived`] was made for: the structure's epoch and B's E_c and
/// λ as the options set them.
#[derive(Debug, Clone, Copy, PartialEq)]
struct DerivedKey {
    epoch: u64,
    contact_modulus: Option<f64>,
    lambda: Option<f64>,
}

impl SolidModel {
    /// Solves without options: [`SolidModel::solve_contact`] with the
    /// default ones.
    pub fn solve(&mut self) -> Result<SolveInfo> {
        self.solve_contact(&ContactOptions::default())
    }

    /// Solves the model at its full loads: where it has contact pairs, B's
    /// tetrahedra are switched on where they would invert (frictionless;
    /// E_c and λ from `options` or their defaults: the smaller E of the
    /// pair's bodies, the other body's where one side is a rigid tool, and
    /// the mesh's size), from those touching or overlapping at rest;
    /// without pairs, one linear solve with no contact structure. What the
    /// structure gives (unknowns, B, pattern, matrix, analysis and the
    /// factor's storage) is kept for the next solve until the structure
    /// changes. Pairs whose B overlap (one given twice) are refused. On
    /// error the model keeps its previous solution.
    pub fn solve_contact(&mut self, options: &ContactOptions) -> Result<SolveInfo> {
        let solution = self.solve_at(1.0, options, None)?;
        Ok(self.settle(solution, false))
    }

    /// The solution at load factor `t` (loads and prescribed displacements
    /// times t, initial gaps as they are) from the active set `start`.
    pub(super) fn solve_at(
        &mut self,
        t: f64,
        options: &ContactOptions,
        start: Option<Vec<bool>>,
    ) -> Result<SolidSolution> {
        options.validate()?;
        let t0 = std::time::Instant::now();
        let key = DerivedKey {
            epoch: self.epoch,
            contact_modulus: options.contact_modulus,
            lambda: options.lambda,
        };
        let mut derived = match self.derived.take() {
            Some(d) if d.key == key => d,
            _ => self.derive(key, options)?,
        };
        let solved = self.solve_with(&mut derived, t, options, start, t0);
        self.derived = Some(derived);
        solved
    }

    /// Makes `solution` the model's and its set the next step's start,
    /// returning its statistics; with `undoable`, what it replaced is kept
    /// for [`SolidModel::revert_step`].
    pub(super) fn settle(&mut self, solution: SolidSolution, undoable: bool) -> SolveInfo {
        let info = solution.info;
        let warm = self.warm.replace(solution.active.clone());
        let previous = self.solution.replace(solution);
        self.undo = undoable.then_some(Undo {
            solution: previous,
            warm,
        });
        info
    }

    /// What the structure gives, for `key`.
    fn derive(&self, key: DerivedKey, options: &ContactOptions) -> Result<Derived> {
        let mesh = self.mesh_ref()?;
        let d = self.elasticity(mesh)?;
        let dofs = self.unknowns(mesh)?;
        let layer = self.layer(mesh, options)?;
        let gap_tets = layer.elements.iter().map(|e| &e.nodes);
        let cliques = tet_cliques(mesh.tets().iter().chain(gap_tets));
        let pattern = Pattern::build(&dofs, mesh.nodes().len(), &cliques);
        drop(cliques);
        let values = self.bodies(&d)?.assemble(&dofs, &pattern)?;
        Ok(Derived {
            key,
            dofs,
            layer,
            pattern,
            values,
            analysis: SolidAnalysis::default(),
        })
    }

    /// The loop on `derived` at load factor `t`.
    fn solve_with(
        &self,
        derived: &mut Derived,
        t: f64,
        options: &ContactOptions,
        start: Option<Vec<bool>>,
        t0: std::time::Instant,
    ) -> Result<SolidSolution> {
        let mesh = self.mesh_ref()?;
        let Derived {
            dofs,
            layer,
            pattern,
            values,
            analysis,
            ..
        } = derived;
        let prescribed = self.prescribed(mesh, t);
        let loads: Vec<f64> = self.load_vector(mesh)?.iter().map(|f| t * f).collect();
        let mut rhs = dofs.gather(&loads);
        let d = self.elasticity(mesh)?;
        self.bodies(&d)?.lift(dofs, &prescribed, &mut rhs)?;
        let gap = self.gap(mesh, layer, dofs, &prescribed, options)?;
        let energy = |r: &[f64]| body_energy(pattern, values, dofs, r);
        let system = SolidSystem {
            nodes: mesh,
            dofs,
            pattern,
            values: values.clone(),
            rhs,
            prescribed: &prescribed,
            body_energy: &energy,
        };
        let loop_options = ContactOptions {
            contact_modulus: None,
            lambda: None,
            ..*options
        };
        let assembly = t0.elapsed().as_secs_f64();
        let solved = solve_gap_contact_from(
            system,
            gap.clone(),
            &loop_options,
            self.ordering,
            analysis,
            start,
        )?;
        let mut warnings = mesh.warnings().to_vec();
        warnings.extend(solved.warnings);
        let mut info = solved.info;
        info.timings.assembly += assembly;
        info.timings.total = t0.elapsed().as_secs_f64();
        Ok(SolidSolution {
            u: solved.u,
            loads,
            gap,
            pair_of: layer.pair_of.clone(),
            active: solved.active,
            history: solved.history,
            info,
            warnings,
        })
    }

    /// B's tetrahedra for the prescribed values `prescribed`.
    fn gap(
        &self,
        mesh: &SolidMesh,
        layer: &Layer,
        dofs: &DofMap,
        prescribed: &[f64],
        options: &ContactOptions,
    ) -> Result<GapTets> {
        let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
        GapTets::new(
            &layer.elements,
            &GapData {
                points: mesh.nodes(),
                moduli: &layer.moduli,
                h_c: &layer.h_c,
                lambda: options.lambda.unwrap_or(mesh.size()),
                equation: &equation,
                prescribed,
            },
        )
    }

    /// The prescribed displacements times `t`, a global vector.
    fn prescribed(&self, mesh: &SolidMesh, t: f64) -> Vec<f64> {
        let mut prescribed = vec![0.0; 3 * mesh.nodes().len()];
        for (&(v, axis), &value) in &self.fixed {
            prescribed[3 * v + axis as usize] = t * value;
        }
        prescribed
    }

    /// D of each body, in the order of [`SolidMesh::bodies`]; a body with
    /// no material is refused by its tag.
    pub(super) fn elasticity(&self, mesh: &SolidMesh) -> Result<Vec<[[f64; 6]; 6]>> {
        (mesh.bodies().iter())
            .map(|b| {
                self.materials.get(b).map(|m| m.d).ok_or_else(|| {
                    Error::argument(format!("body {b} has no material: set one first"))
                })
            })
            .collect()
    }

    /// The unknowns: every DOF of a node of a body not prescribed.
    fn unknowns(&self, mesh: &SolidMesh) -> Result<DofMap> {
        let used = mesh.node_body();
        let free =
            |g: usize| used[g / 3].is_some() && !self.fixed.contains_key(&(g / 3, axis(g % 3)));
        let dofs = DofMap::new(mesh.nodes().len(), 3, free);
        if dofs.n_free() == 0 {
            return Err(Error::argument(
                "every displacement of the 3D model is prescribed: nothing to solve",
            ));
        }
        Ok(dofs)
    }

    /// The consistent nodal forces of the loads (three per node).
    fn load_vector(&self, mesh: &SolidMesh) -> Result<Vec<f64>> {
        let mut f = vec![0.0; 3 * mesh.nodes().len()];
        for load in &self.loads {
            match *load {
                Load::Nodal { node, force } => {
                    (0..3).for_each(|c| f[3 * node + c] += force[c]);
                }
                Load::Pressure { tag, .. } | Load::Traction { tag, .. } => {
                    for face in mesh.boundary_faces().iter().filter(|f| f.tag == tag) {
                        let g = mesh.face_geometry(face);
                        let t = match *load {
                            Load::Pressure { pressure, .. } => g.normal.map(|n| -pressure * n),
                            Load::Traction { traction, .. } => traction,
                            Load::Nodal { .. } => [0.0; 3],
                        };
                        // Linear shape functions: a third of the force per
                        // node, exact for a uniform traction.
                        for &v in &face.nodes {
                            (0..3).for_each(|c| f[3 * v + c] += t[c] * g.area / 3.0);
                        }
                    }
                }
            }
        }
        if let Some(g) = f.iter().position(|x| !x.is_finite()) {
            return Err(Error::argument(format!(
                "the load at node {} overflows",
                g / 3 + mesh.index_base()
            )));
        }
        Ok(f)
    }

    /// B between every contact pair.
    fn layer(&self, mesh: &SolidMesh, options: &ContactOptions) -> Result<Layer> {
        let mut layer = Layer {
            elements: Vec::new(),
            pair_of: Vec::new(),
            h_c: Vec::new(),
            moduli: Vec::new(),
        };
        for (k, pair) in self.pairs.iter().enumerate() {
            let name = |err: Error| {
                Error::new(
                    err.status(),
                    format!(
                        "contact pair {k} (tags {} and {}): {}",
                        pair.tag_a,
                        pair.tag_b,
                        err.message()
                    ),
                )
            };
            let side = |tag| Side::of(mesh, tag).map_err(name);
            let (a, b) = (side(pair.tag_a)?, side(pair.tag_b)?);
            if a.body == b.body {
                return Err(name(Error::argument(format!(
                    "both sides lie on body {}: self-contact is not available",
                    a.body
                ))));
            }
            let normal = a.plane_normal(mesh).map_err(name)?;
            let elements = prism_layer(&FacingSurfaces {
                points: mesh.nodes(),
                a: &a.triangles,
                b: &b.triangles,
                normal,
                number: &|v| (v + mesh.index_base()) as i64,
            })
            .map_err(name)?;
            let modulus = options
                .contact_modulus
                .unwrap_or_else(|| self.pair_modulus(&a, &b));
            let h_c = a.shortest_edge(mesh);
            layer
                .pair_of
                .resize(layer.pair_of.len() + elements.len(), k);
            layer.h_c.resize(layer.h_c.len() + elements.len(), h_c);
            layer
                .moduli
                .resize(layer.moduli.len() + elements.len(), modulus);
            layer.elements.extend(elements);
        }
        refuse_overlapping_pairs(&layer)?;
        Ok(layer)
    }

    /// E_c of a pair: the smaller E of its bodies, or the other body's
    /// where every DOF of one side's nodes is prescribed (a rigid tool).
    fn pair_modulus(&self, a: &Side, b: &Side) -> f64 {
        let young = |s: &Side| self.materials.get(&s.body).map_or(f64::NAN, |m| m.young);
        let rigid = |s: &Side| {
            (s.triangles.iter().flatten())
                .all(|&v| (0..3).all(|c| self.fixed.contains_key(&(v, axis(c)))))
        };
        match (rigid(a), rigid(b)) {
            (true, false) => young(b),
            (false, true) => young(a),
            _ => young(a).min(young(b)),
        }
    }
}

/// Refuses pairs whose B overlap (a pair given twice, or the other way
/// round, or two pairs over the same faces): B would tie those faces
/// twice as stiffly and count their contact twice.
fn refuse_overlapping_pairs(layer: &Layer) -> Result<()> {
    let mut seen: std::collections::HashMap<[usize; 4], usize> = Default::default();
    for (e, &k) in layer.elements.iter().zip(&layer.pair_of) {
        let mut key = e.nodes;
        key.sort_unstable();
        if let Some(first) = seen.insert(key, k).filter(|&first| first != k) {
            return Err(Error::argument(format!(
                "contact pairs {first} and {k} build B over the same faces: a pair given \
                 twice, or both ways round"
            )));
        }
    }
    Ok(())
}

fn axis(c: usize) -> Axis {
    [Axis::X, Axis::Y, Axis::Z][c]
}

/// One side of a contact pair: its triangles and their body.
struct Side {
    tag: i32,
    triangles: Vec<[usize; 3]>,
    normals: Vec<[f64; 3]>,
    body: i32,
}

impl Side {
    /// The faces tagged `tag`, which must lie on one body.
    fn of(mesh: &SolidMesh, tag: i32) -> Result<Side> {
        let faces: Vec<_> = (mesh.boundary_faces().iter())
            .filter(|f| f.tag == tag)
            .collect();
        let body_of = |f: &&crate::fem::solid_mesh::BoundaryFace| mesh.body_of()[f.owner];
        let body = faces
            .first()
            .map(body_of)
            .ok_or_else(|| Error::argument(format!("no boundary face has tag {tag}")))?;
        if let Some(f) = faces.iter().find(|f| body_of(f) != body) {
            return Err(Error::argument(format!(
                "the faces tagged {tag} lie on bodies {body} and {}: a contact side is one \
                 body's",
                body_of(f)
            )));
        }
        Ok(Side {
            tag,
            triangles: faces.iter().map(|f| f.nodes).collect(),
            normals: faces.iter().map(|f| mesh.face_geometry(f).normal).collect(),
            body,
        })
    }

    /// The side's common outward normal; a side that is not planar is
    /// refused (B's prisms face across a plane: docs/method.md §9).
    fn plane_normal(&self, mesh: &SolidMesh) -> Result<[f64; 3]> {
        let mut sum = [0.0; 3];
        for n in &self.normals {
            (0..3).for_each(|c| sum[c] += n[c]);
        }
        let norm = dot(sum, sum).sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(Error::argument(format!(
                "side a (tag {}) has no area: its faces' normals cancel",
                self.tag
            )));
        }
        let n = sum.map(|c| c / norm);
        let x0 = mesh.nodes()[self.triangles[0][0]];
        let extent = mesh.size();
        for (tri, m) in self.triangles.iter().zip(&self.normals) {
            let off_plane =
                (tri.iter()).any(|&v| dot(sub(mesh.nodes()[v], x0), n).abs() > 1e-9 * extent);
            if dot(*m, n) < 1.0 - 1e-9 || off_plane {
                return Err(Error::argument(format!(
                    "side a (tag {}) is not planar: its face on nodes {} leaves the plane of \
                     the side; B in 3D needs a planar side a (docs/method.md §9)",
                    self.tag,
                    names(mesh, tri)
                )));
            }
        }
        Ok(n)
    }

    /// The shortest edge of its triangles (h_c of the tie).
    fn shortest_edge(&self, mesh: &SolidMesh) -> f64 {
        let x = mesh.nodes();
        (self.triangles.iter())
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(p, q)| {
                let d = sub(x[p], x[q]);
                dot(d, d).sqrt()
            })
            .fold(f64::INFINITY, f64::min)
    }
}

fn names(mesh: &SolidMesh, tri: &[usize; 3]) -> String {
    let b = mesh.index_base();
    format!("{}, {}, {}", tri[0] + b, tri[1] + b, tri[2] + b)
}

/// The bodies' energy of a global vector r: (rᵀKr, Σ |K_jj| r_j²) over its
/// unknowns, the judge of whether a near-null mode is a free body.
fn body_energy(pattern: &Pattern, values: &[f64], dofs: &DofMap, r: &[f64]) -> (f64, f64) {
    let x = dofs.gather(r);
    let mut kx = vec![0.0; x.len()];
    pattern.sym_mul(values, &x, &mut kx);
    // The diagonal ends each column of the upper triangle.
    let diag: f64 = (0..x.len())
        .map(|i| values[pattern.col_ptr()[i + 1] - 1].abs() * x[i] * x[i])
        .sum();
    (x.iter().zip(&kx).map(|(a, b)| a * b).sum(), diag)
}
