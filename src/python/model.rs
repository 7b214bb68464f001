//! `tfem._tfem.Model`: the Rust [`Model`] behind numpy arrays.

use std::path::PathBuf;

use numpy::ndarray::Array2;
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::{TfemWarning, to_py};
use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::curve::Curve;
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode};
use crate::fem::mesh::Mesh;
use crate::model::adapt::{AdaptOptions, Goal};
use crate::model::{Component, Model};
use crate::solve::report::{ContactReport, SolveInfo};

/// Boundary edges (k, 2) with their tags (k,).
type TaggedEdges<'py> = (Bound<'py, PyArray2<i64>>, Bound<'py, PyArray1<i32>>);

/// A contact model: a mesh of bodies, their materials, constraints, loads
/// and contact pairs, and the results of its last solve. Node, triangle,
/// body and pair numbers are those of the arrays given (0-based).
#[pyclass(name = "Model", module = "tfem._tfem", subclass)]
pub struct PyModel {
    model: Model,
}

/// Reads a 2-column C-contiguous array as rows.
fn rows2<T: Copy + numpy::Element>(a: &PyReadonlyArray2<'_, T>, what: &str) -> Result<Vec<[T; 2]>> {
    let shape = a.shape();
    if shape[1] != 2 {
        return Err(Error::argument(format!(
            "{what} has shape {shape:?}: (n, 2) is needed"
        )));
    }
    let data = a
        .as_slice()
        .map_err(|_| Error::argument(format!("{what} is not C-contiguous")))?;
    Ok(data.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
}

/// 0-based indices in `0..n` from signed integers, naming the first bad
/// one by its row (`row_name`).
fn indices<const K: usize>(
    rows: &[[i64; K]],
    n: usize,
    row_name: impl Fn(usize) -> String,
) -> Result<Vec<[usize; K]>> {
    rows.iter()
        .enumerate()
        .map(|(r, row)| {
            let mut out = [0usize; K];
            for (o, &v) in out.iter_mut().zip(row) {
                *o = usize::try_from(v).ok().filter(|&v| v < n).ok_or_else(|| {
                    Error::mesh(format!(
                        "{}: node index {v} is out of range ({n} nodes, 0-based)",
                        row_name(r)
                    ))
                })?;
            }
            Ok(out)
        })
        .collect()
}

fn component(c: &Bound<'_, PyAny>) -> PyResult<Component> {
    if let Ok(s) = c.extract::<String>() {
        return match s.as_str() {
            "x" | "X" => Ok(Component::X),
            "y" | "Y" => Ok(Component::Y),
            _ => Err(to_py(Error::argument(format!(
                "component = {s:?} must be \"x\" or \"y\" (or 0, 1)"
            )))),
        };
    }
    let i: i64 = c.extract()?;
    i32::try_from(i)
        .ok()
        .and_then(Component::from_i32)
        .ok_or_else(|| {
            to_py(Error::argument(format!(
                "component = {i} must be 0 (x) or 1 (y)"
            )))
        })
}

fn plane(p: &str) -> Result<PlaneMode> {
    match p {
        "strain" => Ok(PlaneMode::Strain),
        "stress" => Ok(PlaneMode::Stress),
        "axisymmetric" => Ok(PlaneMode::Axisymmetric),
        _ => Err(Error::argument(format!(
            "plane = {p:?} must be \"strain\", \"stress\" or \"axisymmetric\""
        ))),
    }
}

fn rows_out<'py>(py: Python<'py>, v: Vec<[f64; 2]>) -> Bound<'py, PyArray2<f64>> {
    let n = v.len();
    let flat: Vec<f64> = v.into_iter().flatten().collect();
    Array2::from_shape_vec((n, 2), flat)
        .expect("n rows of 2")
        .into_pyarray(py)
}

fn info_dict<'py>(py: Python<'py>, info: &SolveInfo) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("unknowns", info.unknowns)?;
    d.set_item("matrix_nnz", info.matrix_nnz)?;
    d.set_item("factor_nnz", info.factor_nnz)?;
    d.set_item("factorizations", info.factorizations)?;
    d.set_item("relative_residual", info.relative_residual)?;
    d.set_item("condition_estimate", info.condition_estimate)?;
    d.set_item("memory_bytes", info.memory_bytes)?;
    d.set_item("seconds", info.timings.total)?;
    Ok(d)
}

fn report_dict<'py>(py: Python<'py>, r: &ContactReport) -> PyResult<Bound<'py, PyDict>> {
    let d = info_dict(py, &r.info)?;
    d.set_item("iterations", r.iterations)?;
    d.set_item("elements", r.elements)?;
    d.set_item("active", r.active)?;
    d.set_item("contact_length", r.contact_length)?;
    d.set_item("max_penetration", r.max_penetration)?;
    Ok(d)
}

impl PyModel {
    /// Runs `f` on the model without the GIL, then raises its error or
    /// passes its warnings to Python's `warnings`.
    fn run<T: Send>(
        &mut self,
        py: Python<'_>,
        f: impl FnOnce(&mut Model) -> Result<T> + Send,
    ) -> PyResult<T> {
        let model = &mut self.model;
        let out = py.detach(|| f(model)).map_err(to_py)?;
        for w in self.model.warnings() {
            PyErr::warn(
                py,
                &py.get_type::<TfemWarning>(),
                &std::ffi::CString::new(w.replace('\0', " ")).expect("no NUL"),
                1,
            )?;
        }
        Ok(out)
    }
}

#[pymethods]
impl PyModel {
    /// An empty model.
    #[new]
    fn new() -> Self {
        PyModel {
            model: Model::new(),
        }
    }

    /// Sets the mesh: `nodes` (n, 2) float64, `triangles` (m, 3) int64
    /// (0-based node numbers), `bodies` (m,) int32 (each triangle's body).
    /// Replaces constraints, loads and pairs of an earlier mesh.
    fn set_mesh(
        &mut self,
        nodes: PyReadonlyArray2<'_, f64>,
        triangles: PyReadonlyArray2<'_, i64>,
        bodies: PyReadonlyArray1<'_, i32>,
    ) -> PyResult<()> {
        let mesh = (|| {
            let xy = rows2(&nodes, "nodes")?;
            let shape = triangles.shape();
            if shape[1] != 3 {
                return Err(Error::mesh(format!(
                    "triangles has shape {shape:?}: (m, 3) is needed"
                )));
            }
            let flat = (triangles.as_slice())
                .map_err(|_| Error::argument("triangles is not C-contiguous"))?;
            let rows: Vec<[i64; 3]> = flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
            let tris = indices(&rows, xy.len(), |t| format!("triangle {t}"))?;
            let body = (bodies.as_slice())
                .map_err(|_| Error::argument("bodies is not C-contiguous"))?
                .to_vec();
            Mesh::new(xy, tris, body, 0)
        })()
        .map_err(to_py)?;
        self.model.set_mesh(mesh);
        Ok(())
    }

    /// Sets the tagged boundary edges: `edges` (k, 2) int64 node pairs,
    /// `tags` (k,) int32; replaces the earlier ones (refused, naming the
    /// tag, if a load or pair would lose its edges).
    fn set_boundary_edges(
        &mut self,
        edges: PyReadonlyArray2<'_, i64>,
        tags: PyReadonlyArray1<'_, i32>,
    ) -> PyResult<()> {
        let (e, t) = self.edges_in(&edges, &tags).map_err(to_py)?;
        self.model.set_boundary_edges(&e, &t).map_err(to_py)
    }

    /// Adds tagged boundary edges to those already set.
    fn add_boundary_edges(
        &mut self,
        edges: PyReadonlyArray2<'_, i64>,
        tags: PyReadonlyArray1<'_, i32>,
    ) -> PyResult<()> {
        let (e, t) = self.edges_in(&edges, &tags).map_err(to_py)?;
        self.model.add_boundary_edges(&e, &t).map_err(to_py)
    }

    /// Sets body `body`'s material: Young's modulus, Poisson's ratio and
    /// the plane mode ("strain", "stress" or "axisymmetric").
    #[pyo3(signature = (body, young, poisson, plane = "strain"))]
    fn set_material(&mut self, body: i32, young: f64, poisson: f64, plane: &str) -> PyResult<()> {
        let m = Material::new(
            young,
            poisson,
            self::plane(plane).map_err(to_py)?,
            &format!("body {body}"),
        )
        .map_err(to_py)?;
        self.model.set_material(body, m).map_err(to_py)
    }

    /// Chooses Jmin: "auto" (the default), "off" (plain FEM), "lambda"
    /// (Jmin = h³/λ with λ = `parameter`, a length) or "fixed" (Jmin =
    /// `parameter`).
    #[pyo3(signature = (mode, parameter = None))]
    fn set_tempering(&mut self, mode: &str, parameter: Option<f64>) -> PyResult<()> {
        let needs = |what: &str| {
            parameter
                .ok_or_else(|| to_py(Error::argument(format!("tempering {what:?} needs a value"))))
        };
        let t = match mode {
            "auto" => Tempering::Auto,
            "off" => Tempering::Off,
            "lambda" => Tempering::Lambda(needs(mode)?),
            "fixed" => Tempering::Fixed(needs(mode)?),
            _ => {
                return Err(to_py(Error::argument(format!(
                    "tempering = {mode:?} must be \"auto\", \"off\", \"lambda\" or \"fixed\""
                ))));
            }
        };
        self.model.set_tempering(t).map_err(to_py)
    }

    /// Prescribes component `component` ("x" or "y") of node `node`.
    #[pyo3(signature = (node, component, value = 0.0))]
    fn fix(&mut self, node: usize, component: &Bound<'_, PyAny>, value: f64) -> PyResult<()> {
        let c = self::component(component)?;
        self.model.fix(node, c, value).map_err(to_py)
    }

    /// Prescribes component `component` of every node of the edges tagged
    /// `tag`.
    #[pyo3(signature = (tag, component, value = 0.0))]
    fn fix_edges(&mut self, tag: i32, component: &Bound<'_, PyAny>, value: f64) -> PyResult<()> {
        let c = self::component(component)?;
        self.model.fix_edges(tag, c, value).map_err(to_py)
    }

    /// Removes every prescribed displacement.
    fn clear_constraints(&mut self) {
        self.model.clear_constraints();
    }

    /// A pressure (force per unit area, positive into the body) on the
    /// edges tagged `tag`.
    fn add_pressure(&mut self, tag: i32, pressure: f64) -> PyResult<()> {
        self.model.add_pressure(tag, pressure).map_err(to_py)
    }

    /// A traction (tx, ty) on the edges tagged `tag`.
    fn add_traction(&mut self, tag: i32, tx: f64, ty: f64) -> PyResult<()> {
        self.model.add_traction(tag, [tx, ty]).map_err(to_py)
    }

    /// A force (fx, fy) on node `node`.
    fn add_nodal_force(&mut self, node: usize, fx: f64, fy: f64) -> PyResult<()> {
        self.model.add_nodal_force(node, [fx, fy]).map_err(to_py)
    }

    /// A body force (force per unit volume) on body `body`.
    fn set_body_force(&mut self, body: i32, bx: f64, by: f64) -> PyResult<()> {
        self.model.set_body_force(body, [bx, by]).map_err(to_py)
    }

    /// Removes every load.
    fn clear_loads(&mut self) {
        self.model.clear_loads();
    }

    /// A contact pair between the edges tagged `tag_a` and `tag_b`; its
    /// number.
    fn add_contact_pair(&mut self, tag_a: i32, tag_b: i32) -> PyResult<usize> {
        self.model.add_contact_pair(tag_a, tag_b).map_err(to_py)
    }

    /// Coulomb friction `mu` on pair `pair`.
    fn set_friction(&mut self, pair: usize, mu: f64) -> PyResult<()> {
        self.model.set_friction(pair, mu).map_err(to_py)
    }

    /// Declares that the edges tagged `tag` lie on the circle of centre
    /// (cx, cy) and radius `radius`: adaptive refinement puts its new
    /// nodes there.
    fn set_boundary_circle(&mut self, tag: i32, cx: f64, cy: f64, radius: f64) -> PyResult<()> {
        let curve = Curve::Circle {
            center: [cx, cy],
            radius,
        };
        self.model.set_curve(tag, curve).map_err(to_py)
    }

    /// Runs the solves on `threads` threads (0: as many as cores).
    fn set_threads(&mut self, threads: usize) -> PyResult<()> {
        self.model.set_threads(threads).map_err(to_py)
    }

    /// Solves without contact; a dict of solver statistics.
    fn solve<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let info = self.run(py, |m| m.solve())?;
        info_dict(py, &info)
    }

    /// Solves with contact (frictionless or Coulomb as the pairs say); a
    /// dict of the contact report and solver statistics.
    #[pyo3(signature = (max_iterations = None))]
    fn solve_contact<'py>(
        &mut self,
        py: Python<'py>,
        max_iterations: Option<usize>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mut options = ContactOptions::default();
        if let Some(n) = max_iterations {
            options.max_iterations = n;
        }
        let r = self.run(py, |m| m.solve_contact(&options))?;
        report_dict(py, &r)
    }

    /// One quasi-static load step with the loads scaled by `load_factor`,
    /// warm-started from the last step's contact state (one factorisation
    /// serves a history).
    fn step<'py>(&mut self, py: Python<'py>, load_factor: f64) -> PyResult<Bound<'py, PyDict>> {
        let r = self.run(py, |m| m.step(load_factor, &ContactOptions::default()))?;
        report_dict(py, &r)
    }

    /// Undoes the last load step.
    fn revert_step(&mut self) -> PyResult<()> {
        self.model.revert_step().map_err(to_py)
    }

    /// Solves to a tolerance on the estimated relative error of `goal`
    /// ("energy" or "compliance"), refining the mesh (with contact, also
    /// until the contact zones' edges are located to the tolerance unless
    /// `resolve_contact_edges` is false); a dict with
    /// `reached`, `seconds` and `cycles` (unknowns, estimate, contact_edge,
    /// seconds of each).
    #[pyo3(signature = (
        tolerance,
        goal = "energy",
        max_unknowns = 2_000_000,
        max_cycles = 30,
        resolve_contact_edges = true
    ))]
    fn solve_adaptive<'py>(
        &mut self,
        py: Python<'py>,
        tolerance: f64,
        goal: &str,
        max_unknowns: usize,
        max_cycles: usize,
        resolve_contact_edges: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let goal = match goal {
            "energy" => Goal::Energy,
            "compliance" => Goal::Compliance,
            g => {
                return Err(to_py(Error::argument(format!(
                    "goal = {g:?} must be \"energy\" or \"compliance\""
                ))));
            }
        };
        let options = AdaptOptions {
            tolerance,
            goal,
            max_unknowns,
            max_cycles,
            resolve_contact_edges,
            ..AdaptOptions::default()
        };
        let r = self.run(py, |m| m.solve_adaptive(&options))?;
        let d = PyDict::new(py);
        d.set_item("reached", r.reached)?;
        d.set_item("seconds", r.seconds)?;
        let cycles: Vec<Bound<'py, PyDict>> = (r.cycles.iter())
            .map(|c| {
                let e = PyDict::new(py);
                e.set_item("unknowns", c.unknowns)?;
                e.set_item("triangles", c.triangles)?;
                e.set_item("estimate", c.estimate)?;
                e.set_item("contact_edge", c.contact_edge)?;
                e.set_item("seconds", c.seconds)?;
                Ok(e)
            })
            .collect::<PyResult<_>>()?;
        d.set_item("cycles", cycles)?;
        Ok(d)
    }

    /// The nodes (n, 2) of the model's mesh (refined ones included).
    fn mesh_nodes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let mesh = self.mesh()?;
        Ok(rows_out(py, mesh.nodes().to_vec()))
    }

    /// The triangles (m, 3) of the model's mesh, 0-based.
    fn mesh_triangles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let mesh = self.mesh()?;
        let flat: Vec<i64> = (mesh.triangles().iter())
            .flatten()
            .map(|&v| v as i64)
            .collect();
        Ok(Array2::from_shape_vec((mesh.triangles().len(), 3), flat)
            .expect("m rows of 3")
            .into_pyarray(py))
    }

    /// Each triangle's body (m,).
    fn mesh_bodies<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<i32>>> {
        Ok(self.mesh()?.body_of().to_vec().into_pyarray(py))
    }

    /// The tagged boundary edges: (edges (k, 2) int64, tags (k,) int32).
    fn boundary_edges<'py>(&self, py: Python<'py>) -> PyResult<TaggedEdges<'py>> {
        let be = self.mesh()?.boundary_edges();
        let flat: Vec<i64> = be.iter().flat_map(|e| e.nodes).map(|v| v as i64).collect();
        let tags: Vec<i32> = be.iter().map(|e| e.tag).collect();
        Ok((
            Array2::from_shape_vec((be.len(), 2), flat)
                .expect("k rows of 2")
                .into_pyarray(py),
            tags.into_pyarray(py),
        ))
    }

    /// Nodal displacements (n, 2) of the last solve.
    fn displacements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        Ok(rows_out(py, self.model.displacements().map_err(to_py)?))
    }

    /// Reactions (n, 2) at the prescribed nodes (zero elsewhere).
    fn reactions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        Ok(rows_out(py, self.model.reactions().map_err(to_py)?))
    }

    /// Element stresses (m, 3): σ_xx, σ_yy, σ_xy.
    fn element_stresses<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let s = self.model.element_stresses().map_err(to_py)?;
        let n = s.len();
        let flat: Vec<f64> = s.into_iter().flatten().collect();
        Ok(Array2::from_shape_vec((n, 3), flat)
            .expect("m rows of 3")
            .into_pyarray(py))
    }

    /// The contact pressure at every node (positive in compression).
    fn contact_nodal_pressures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        Ok(self
            .model
            .contact_nodal_pressures()
            .map_err(to_py)?
            .into_pyarray(py))
    }

    /// The contact traction at every node, (n, 2): pressure, shear.
    fn contact_nodal_tractions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        Ok(rows_out(
            py,
            self.model.contact_nodal_tractions().map_err(to_py)?,
        ))
    }

    /// The work of the loads on the last solve's displacements.
    fn external_work(&self) -> PyResult<f64> {
        self.model.external_work().map_err(to_py)
    }

    /// The error estimate of the last solve: (per-triangle η_e² (m,),
    /// η, the energy norm of the field).
    fn error_estimate<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, f64, f64)> {
        let e = self.model.error_estimate().map_err(to_py)?;
        Ok((e.squared.into_pyarray(py), e.global, e.energy))
    }

    /// What the model and its last solve warn of.
    fn warnings(&self) -> Vec<String> {
        self.model.warnings()
    }

    /// Reads a Gmsh MSH 4.1 file: physical surfaces become bodies,
    /// physical curves boundary-edge tags. Replaces the mesh.
    fn read_msh(&mut self, path: PathBuf) -> PyResult<()> {
        let mesh = crate::io::gmsh::read_msh(&path, 0).map_err(to_py)?;
        self.model.set_mesh(mesh);
        Ok(())
    }

    /// Writes the mesh and the last solve's fields as a VTU file.
    fn write_vtu(&self, path: PathBuf) -> PyResult<()> {
        crate::io::vtu::write_vtu(&self.model, &path).map_err(to_py)
    }
}

impl PyModel {
    fn mesh(&self) -> PyResult<&Mesh> {
        self.model
            .mesh()
            .ok_or_else(|| to_py(Error::state("no mesh: call set_mesh first")))
    }

    fn edges_in(
        &self,
        edges: &PyReadonlyArray2<'_, i64>,
        tags: &PyReadonlyArray1<'_, i32>,
    ) -> Result<(Vec<[usize; 2]>, Vec<i32>)> {
        let n = self
            .model
            .mesh()
            .ok_or_else(|| Error::state("no mesh: call set_mesh first"))?
            .nodes()
            .len();
        let rows = rows2(edges, "edges")?;
        let e = indices(&rows, n, |k| format!("edge {k}"))?;
        let t = (tags.as_slice())
            .map_err(|_| Error::argument("tags is not C-contiguous"))?
            .to_vec();
        if t.len() != e.len() {
            return Err(Error::argument(format!(
                "{} tags for {} edges",
                t.len(),
                e.len()
            )));
        }
        Ok((e, t))
    }
}
