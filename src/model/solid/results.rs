//! What a solved [`SolidModel`] gives back, each computed when asked.

use super::*;

impl SolidModel {
    fn solution(&self) -> Result<&SolidSolution> {
        self.solution.as_ref().ok_or_else(|| {
            Error::argument("the 3D model has no solution: solve it first (a change drops it)")
        })
    }

    /// The displacements [u_x, u_y, u_z] of every node.
    pub fn displacements(&self) -> Result<Vec<[f64; 3]>> {
        let u = &self.solution()?.u;
        Ok(u.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
    }

    /// The statistics of the last solve.
    pub fn solve_info(&self) -> Result<&SolveInfo> {
        Ok(&self.solution()?.info)
    }

    /// The active-set iterations of the last solve (1 without contact).
    pub fn iterations(&self) -> Result<usize> {
        Ok(self.solution()?.history.len())
    }

    /// One record per active-set iteration of the last solve: B's
    /// tetrahedra on in its solve and those the inversion test switched on
    /// and off after it (without contact pairs, one record of zeros). Each
    /// tetrahedron of B adds E_c/(6T_e)·w wᵀ, so the switches bound the
    /// rank of the change from one solve's matrix to the next's.
    pub fn contact_history(&self) -> Result<&[IterationRecord]> {
        Ok(&self.solution()?.history)
    }

    /// What the mesh and the last solve noticed but did not refuse.
    pub fn warnings(&self) -> Vec<String> {
        match &self.solution {
            Some(s) => s.warnings.clone(),
            None => self
                .mesh
                .as_ref()
                .map_or_else(Vec::new, |m| m.warnings().to_vec()),
        }
    }

    /// The work of the loads, Σ f·u (the compliance of a load).
    pub fn external_work(&self) -> Result<f64> {
        let s = self.solution()?;
        Ok(s.loads.iter().zip(&s.u).map(|(f, u)| f * u).sum())
    }

    /// B's tetrahedra (four nodes each, numbered so that opening the gap
    /// makes J positive), pair by pair.
    pub fn contact_tetrahedra(&self) -> Result<Vec<[usize; 4]>> {
        let gap = &self.solution()?.gap;
        Ok((0..gap.len()).map(|k| *gap.nodes(k)).collect())
    }

    /// Whether each of B's tetrahedra is on (pressed) in the solution.
    pub fn contact_active(&self) -> Result<&[bool]> {
        Ok(&self.solution()?.active)
    }

    /// The area of the interfaces in contact: each active tetrahedron of B
    /// stands for a third of its prism's facing triangle; +0.0 when none is
    /// on (an empty sum of floats is −0.0).
    pub fn contact_area(&self) -> Result<f64> {
        let s = self.solution()?;
        Ok((0..s.gap.len())
            .filter(|&k| s.active[k])
            .map(|k| s.gap.area(k) / 3.0)
            .sum::<f64>()
            + 0.0)
    }

    /// [`SolidModel::contact_area`] of one pair.
    pub fn contact_pair_area(&self, pair: usize) -> Result<f64> {
        let s = self.solution()?;
        if pair >= self.pairs.len() {
            return Err(Error::argument(format!(
                "contact pair {pair} does not exist ({} pairs)",
                self.pairs.len()
            )));
        }
        Ok((0..s.gap.len())
            .filter(|&k| s.active[k] && s.pair_of[k] == pair)
            .map(|k| s.gap.area(k) / 3.0)
            .sum::<f64>()
            + 0.0)
    }

    /// The force B exerts on each node (three per node; zero off the
    /// interfaces): minus its active tetrahedra's internal forces s·g·w.
    pub fn contact_forces(&self) -> Result<Vec<[f64; 3]>> {
        let s = self.solution()?;
        let mut f = vec![[0.0; 3]; s.u.len() / 3];
        for k in (0..s.gap.len()).filter(|&k| s.active[k]) {
            let t = s.gap.nodes(k);
            let ue: [f64; 12] = std::array::from_fn(|i| s.u[3 * t[i / 3] + i % 3]);
            let force = s.gap.force(k, &ue);
            let w = s.gap.weights(k);
            for i in 0..12 {
                f[t[i / 3]][i % 3] -= force * w[i];
            }
        }
        Ok(f)
    }

    /// The contact pressure at each node of the pairs' sides (zero
    /// elsewhere; positive pressed): the normal force B exerts on it over
    /// its tributary area, a third of each facing triangle it belongs to.
    pub fn contact_nodal_pressures(&self) -> Result<Vec<f64>> {
        let mesh = self.mesh_ref()?;
        let forces = self.contact_forces()?;
        let mut area = vec![0.0; forces.len()];
        // Each node's outward normal, its faces' weighted by their shares;
        // a face on a side of several pairs counts once.
        let mut normal = vec![[0.0; 3]; forces.len()];
        let tags: BTreeSet<i32> = self.pairs.iter().flat_map(|p| [p.tag_a, p.tag_b]).collect();
        let mut faces = BTreeSet::new();
        for face in mesh
            .boundary_faces()
            .iter()
            .filter(|f| tags.contains(&f.tag))
        {
            let mut key = face.nodes;
            key.sort_unstable();
            if !faces.insert(key) {
                continue;
            }
            let g = mesh.face_geometry(face);
            for &v in &face.nodes {
                area[v] += g.area / 3.0;
                (0..3).for_each(|c| normal[v][c] += g.normal[c] * g.area / 3.0);
            }
        }
        Ok((0..forces.len())
            .map(|v| {
                let n = dot(normal[v], normal[v]).sqrt();
                match area[v] > 0.0 && n > 0.0 {
                    // Pressed, B pushes a node into its body: against its
                    // outward normal.
                    true => -dot(forces[v], normal[v]) / (n * area[v]),
                    false => 0.0,
                }
            })
            .collect())
    }

    pub(super) fn bodies<'a>(&'a self, d: &'a [[[f64; 6]; 6]]) -> Result<SolidBodies<'a>> {
        Ok(SolidBodies {
            mesh: self.mesh_ref()?,
            d,
            tempering: self.tempering.unwrap_or(Tempering::Auto),
        })
    }

    /// Each tetrahedron's strain (ε_xx, ε_yy, ε_zz, γ_yz, γ_xz, γ_xy),
    /// tempered below Jmin as the stiffness is.
    pub fn element_strains(&self) -> Result<Vec<[f64; 6]>> {
        let d = self.elasticity(self.mesh_ref()?)?;
        Ok(self.bodies(&d)?.strains(&self.solution()?.u))
    }

    /// Each tetrahedron's stress D ε (σ_xx, σ_yy, σ_zz, σ_yz, σ_xz, σ_xy).
    pub fn element_stresses(&self) -> Result<Vec<[f64; 6]>> {
        let d = self.elasticity(self.mesh_ref()?)?;
        Ok(self.bodies(&d)?.stresses(&self.solution()?.u))
    }

    /// The reaction forces at prescribed DOFs: K u − f with B's active
    /// tetrahedra in K (zero at free DOFs).
    pub fn reactions(&self) -> Result<Vec<[f64; 3]>> {
        let s = self.solution()?;
        let d = self.elasticity(self.mesh_ref()?)?;
        let mut r = self.bodies(&d)?.internal_forces(&s.u)?;
        let contact = self.contact_forces()?;
        let mut out = vec![[0.0; 3]; r.len() / 3];
        for (v, o) in out.iter_mut().enumerate() {
            for (c, axis) in [Axis::X, Axis::Y, Axis::Z].into_iter().enumerate() {
                let g = 3 * v + c;
                r[g] -= contact[v][c] + s.loads[g];
                if self.fixed.contains_key(&(v, axis)) {
                    o[c] = r[g];
                }
            }
        }
        Ok(out)
    }
}
