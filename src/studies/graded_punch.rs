//! The rigid flat cylindrical punch (Boussinesq) through the 3D model on a
//! block meshed by Gmsh, graded towards the punch's edge circle alone
//! (docs/method.md §9): where the pressure is singular, ~(a − r)^(−1/2),
//! and nowhere else. The tensor grid of [`super::tet_scenes::Punch3d`]
//! carries the edge's fine lines across the whole block; this mesh spends
//! its unknowns at the edge.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

use crate::contact::prism_layer::split_prism;
use crate::error::{Error, Result, Status};
use crate::fem::solid_mesh::SolidMesh;
use crate::fem::tet::TetGeometry;
use crate::io::gmsh::read_solid_msh;
use crate::model::solid::{Axis, SolidMaterial, SolidModel};

/// The quarter block [0, R]² × [−R, 0] (R = `extent`·a) on rollers at its
/// bottom and symmetry planes, the punch of radius a pressed δ into its
/// top, frictionless; Gmsh's tetrahedra of size a/`refinement` at the
/// edge circle, growing by `growth` per unit of distance from it, up to
/// R/8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradedPunch {
    /// The block's side and depth, in punch radii.
    pub extent: f64,
    /// Young's modulus of the block.
    pub young: f64,
    /// Poisson's ratio of the block.
    pub poisson: f64,
    /// The indentation δ, in punch radii.
    pub indentation: f64,
    /// The edge's element size is a over this.
    pub refinement: f64,
    /// How fast the element size grows away from the edge (size per
    /// distance).
    pub growth: f64,
}

impl Default for GradedPunch {
    fn default() -> Self {
        GradedPunch {
            extent: 200.0,
            young: 1.0,
            poisson: 0.3,
            indentation: 1e-3,
            refinement: 8.0,
            growth: 0.05,
        }
    }
}

/// What [`GradedPunch::solve`] measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradedPunchResult {
    /// P/(2aE*δ) − 1.
    pub load_error: f64,
    /// The contact area over πa² − 1 (the meshed disc's polygon).
    pub area_error: f64,
    /// Unknowns.
    pub unknowns: usize,
    /// Numeric factorisations of the contact solve.
    pub factorizations: usize,
    /// Seconds Gmsh took.
    pub mesh_seconds: f64,
    /// Seconds of the model's solve.
    pub solve_seconds: f64,
}

/// The tags of the block's faces in the Gmsh file.
const DISC: i32 = 2;
const PUNCH_BOTTOM: i32 = 3;
const SIDE_X: i32 = 11;
const SIDE_Y: i32 = 12;
const BOTTOM: i32 = 13;

impl GradedPunch {
    /// Meshes, solves and measures (Debian's `gmsh` on the PATH).
    pub fn solve(&self) -> Result<GradedPunchResult> {
        let ok = |x: f64| x.is_finite() && x > 0.0;
        let given = [self.extent - 2.0, self.young, self.indentation, self.growth];
        if !(given.iter().all(|&x| ok(x)) && self.refinement >= 1.0 && self.refinement <= 1e3) {
            return Err(Error::argument(format!("{self:?}: out of range")));
        }
        let dir = std::env::temp_dir().join(format!(
            "tfem_graded_punch_{}_{}",
            std::process::id(),
            self.refinement
        ));
        std::fs::create_dir_all(&dir).map_err(|e| Error::new(Status::Io, e.to_string()))?;
        let t0 = Instant::now();
        let block = self.mesh(&dir);
        let _ = std::fs::remove_dir_all(&dir);
        let block = block?;
        let mesh_seconds = t0.elapsed().as_secs_f64();
        let (mut model, punch) = self.model(block)?;
        let t0 = Instant::now();
        let info = model.solve()?;
        let solve_seconds = t0.elapsed().as_secs_f64();
        let r = model.reactions()?;
        let load: f64 = -4.0 * punch.map(|v| r[v][2]).sum::<f64>();
        let e_star = self.young / (1.0 - self.poisson * self.poisson);
        Ok(GradedPunchResult {
            load_error: load / (2.0 * e_star * self.indentation) - 1.0,
            area_error: 4.0 * model.contact_area()? / std::f64::consts::PI - 1.0,
            unknowns: info.unknowns,
            factorizations: info.factorizations,
            mesh_seconds,
            solve_seconds,
        })
    }

    /// Gmsh's block of unit punch radius, in `dir`.
    fn mesh(&self, dir: &Path) -> Result<SolidMesh> {
        let (h0, r) = (1.0 / self.refinement, self.extent);
        let hmax = r / 8.0;
        let geo = dir.join("punch.geo");
        let script = format!(
            "a = 1; R = {r}; e = 1e-6 * R;\n\
             Point(1) = {{0, 0, 0}}; Point(2) = {{a, 0, 0}}; Point(3) = {{0, a, 0}};\n\
             Point(4) = {{R, 0, 0}}; Point(5) = {{R, R, 0}}; Point(6) = {{0, R, 0}};\n\
             Circle(1) = {{2, 1, 3}};\n\
             Line(2) = {{1, 2}}; Line(3) = {{3, 1}};\n\
             Line(4) = {{2, 4}}; Line(5) = {{4, 5}}; Line(6) = {{5, 6}}; Line(7) = {{6, 3}};\n\
             Curve Loop(1) = {{2, 1, 3}}; Plane Surface(1) = {{1}};\n\
             Curve Loop(2) = {{4, 5, 6, 7, -1}}; Plane Surface(2) = {{2}};\n\
             Extrude {{0, 0, -R}} {{ Surface{{1, 2}}; }}\n\
             Physical Volume(1) = {{1, 2}};\n\
             Physical Surface({DISC}) = {{1}};\n\
             Physical Surface({SIDE_X}) = Surface In BoundingBox{{-e, -e, -R - e, e, R + e, e}};\n\
             Physical Surface({SIDE_Y}) = Surface In BoundingBox{{-e, -e, -R - e, R + e, e, e}};\n\
             Physical Surface({BOTTOM}) = Surface In BoundingBox{{-e, -e, -R - e, R + e, R + e, -R + e}};\n\
             Field[1] = Distance; Field[1].CurvesList = {{1}}; Field[1].NumPointsPerCurve = 400;\n\
             Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = {h0};\n\
             Field[2].SizeMax = {hmax}; Field[2].DistMin = 0; Field[2].DistMax = {dmax};\n\
             Background Field = 2;\n\
             Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;\n\
             Mesh.MeshSizeFromCurvature = 0;\n",
            dmax = (hmax - h0) / self.growth
        );
        let io = |e: std::io::Error| Error::new(Status::Io, format!("gmsh: {e}"));
        std::fs::write(&geo, script).map_err(io)?;
        let msh = dir.join("punch.msh");
        let out = Command::new("gmsh")
            .args(["-3", "-format", "msh41", "-nt", "1"])
            .arg(&geo)
            .arg("-o")
            .arg(&msh)
            .output()
            .map_err(io)?;
        if !out.status.success() {
            return Err(Error::new(
                Status::Io,
                format!("gmsh failed: {}", String::from_utf8_lossy(&out.stderr)),
            ));
        }
        read_solid_msh(&msh, 0)
    }

    /// The model: the block (body 1) and the punch (body 2), a layer of
    /// prisms of height a/`refinement` over the disc's triangles, its
    /// nodes returned (all prescribed); the pair from the disc to the
    /// punch's bottom.
    fn model(&self, block: SolidMesh) -> Result<(SolidModel, std::ops::Range<usize>)> {
        let mut nodes = block.nodes().to_vec();
        let first = nodes.len();
        let (mut tets, mut body) = (block.tets().to_vec(), block.body_of().to_vec());
        let disc: Vec<[usize; 3]> = (block.boundary_faces().iter())
            .filter(|f| f.tag == DISC)
            .map(|f| f.nodes)
            .collect();
        // Each disc node's copies at the bottom and the top of the punch.
        let mut copy = std::collections::BTreeMap::new();
        for &v in disc.iter().flatten() {
            copy.entry(v).or_insert_with(|| {
                let [x, y, z] = nodes[v];
                nodes.push([x, y, z]);
                nodes.push([x, y, z + 1.0 / self.refinement]);
                (nodes.len() - 2, nodes.len() - 1)
            });
        }
        let mut faces: Vec<[usize; 3]> = block.boundary_faces().iter().map(|f| f.nodes).collect();
        let mut tags: Vec<i32> = block.boundary_faces().iter().map(|f| f.tag).collect();
        for tri in &disc {
            let (bottom, top) = (tri.map(|v| copy[&v].0), tri.map(|v| copy[&v].1));
            for t in split_prism(bottom, top, |v| v) {
                let j = TetGeometry::new(&t.map(|v| nodes[v])).j;
                tets.push(if j < 0.0 { [t[0], t[1], t[3], t[2]] } else { t });
                body.push(2);
            }
            faces.push(bottom);
            tags.push(PUNCH_BOTTOM);
        }
        let punch = first..nodes.len();
        let mut mesh = SolidMesh::new(nodes, tets, body, 0)?;
        mesh.set_boundary_faces(&faces, &tags)?;
        let mut model = SolidModel::new();
        model.set_mesh(mesh);
        model.set_material(1, SolidMaterial::new(self.young, self.poisson)?);
        model.set_material(2, SolidMaterial::new(self.young, self.poisson)?);
        model.fix_faces(SIDE_X, Axis::X, 0.0)?;
        model.fix_faces(SIDE_Y, Axis::Y, 0.0)?;
        model.fix_faces(BOTTOM, Axis::Z, 0.0)?;
        for v in punch.clone() {
            model.fix(v, Axis::X, 0.0)?;
            model.fix(v, Axis::Y, 0.0)?;
            model.fix(v, Axis::Z, -self.indentation)?;
        }
        model.add_contact_pair(DISC, PUNCH_BOTTOM)?;
        Ok((model, punch))
    }
}
