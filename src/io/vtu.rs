//! Results as a VTK XML unstructured grid (`.vtu`), for ParaView, VTK and
//! meshio. Feature `vtu`.
//!
//! # What the file holds
//!
//! Of a 2D model ([`write_vtu`]; a tetrahedral mesh: [below](#solid-meshes)),
//! the mesh in its initial configuration (points with z = 0, 3-node
//! triangles) and, by name:
//!
//! | array | on | type, components | what |
//! |---|---|---|---|
//! | `displacement` | points | Float64, 3 | [u, v, 0] ([`Model::displacements`]) |
//! | `contact_pressure` | points | Float64, 1 | after a contact solve: the contact pressure at each node, positive in compression, zero off the interfaces ([`Model::contact_nodal_pressures`]) |
//! | `contact_shear` | points | Float64, 1 | after a contact solve: the tangential contact traction at each node, along its body's counter-clockwise tangent ([`Model::contact_nodal_tractions`]) |
//! | `contact_force` | points | Float64, 3 | after a contact solve: [f_x, f_y, 0], the force the contact exerts on each node per unit thickness ([`Model::contact_forces`]) |
//! | `contact_gap` | points | Float64, 1 | after a contact solve: the normal gap at each node, negative where the bodies interpenetrate ([`Model::contact_gaps`]) |
//! | `body` | cells | Int32, 1 | the body tag of a triangle; −1 on the elements of B |
//! | `J` | cells | Float64, 1 | twice the signed area in the initial configuration (an element of B: its initial Jacobian) |
//! | `strain` | cells | Float64, 3 | [ε_xx, ε_yy, γ_xy] ([`Model::element_strains`]); zero on the elements of B |
//! | `stress` | cells | Float64, 3 | [σ_xx, σ_yy, σ_xy] ([`Model::element_stresses`]); zero on the elements of B |
//! | `out_of_plane_stress` | cells | Float64, 1 | the hoop stress σ_θθ of axisymmetric bodies, σ_zz in plane strain, 0 in plane stress ([`Model::element_out_of_plane_stresses`]); zero on the elements of B |
//! | `contact_element_active` | cells | UInt8, 1 | pairs weighted by B only: 1 on an active element of B, 0 elsewhere ([`Model::contact_active`]) |
//! | `contact_element_pressure` | cells | Float64, 1 | pairs weighted by B only: the pressure of each element of B, 0 on the body triangles ([`Model::contact_pressure`]) |
//!
//! The nodal contact arrays are there after every contact solve or load
//! step, under both weightings, and only then (after a solve without
//! contact the file has no contact array at all, rather than zeros that
//! would read as "no contact"). The elements of the contact mesh B of the
//! pairs weighted by it follow the body triangles as cells of their own
//! (body −1) with the two `contact_element_*` arrays; the pairs under the
//! mortar weighting ([`ContactWeighting::Mortar`](crate::ContactWeighting::Mortar)) have no B: their
//! contact state is per node, and the nodal arrays carry it.
//!
//! # Solid meshes
//!
//! [`write_solid_vtu`] writes a tetrahedral [`SolidMesh`] (points in
//! space, 4-node tetrahedra, VTK type 10) with the fields its caller gives
//! in [`SolidFields`], each array only where given:
//!
//! | array | on | type, components | what |
//! |---|---|---|---|
//! | `displacement` | points | Float64, 3 | [u, v, w] |
//! | `contact_pressure` | points | Float64, 1 | the contact pressure at each node, positive in compression |
//! | `body` | cells | Int32, 1 | the body tag of a tetrahedron |
//! | `J` | cells | Float64, 1 | six times the signed volume (flat tetrahedra, which TFEM tempers, show as J ≈ 0) |
//! | `stress` | cells | Float64, 6 | [σ_xx, σ_yy, σ_zz, σ_xy, σ_yz, σ_xz]: VTK's order of a symmetric tensor, which its tensor filters (principal stresses, glyphs) read, not Voigt's order the caller gives |
//!
//! # The format
//!
//! `<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian"
//! header_type="UInt64">` with one `Piece`; every `DataArray` is
//! `format="appended"`, its `offset` counting bytes from the one after the
//! `_` that opens `<AppendedData encoding="raw">`, where each array is its
//! byte count (UInt64) followed by its values, little-endian, with no
//! compression. Connectivity and offsets are Int32 when every index fits
//! (any mesh tfem can hold in memory today), else Int64; the cell types
//! UInt8 (5, `VTK_TRIANGLE`, or 10, `VTK_TETRA`). Raw appended data is the compact form both
//! VTK (ParaView's reader) and meshio read: 8 bytes per Float64, where the
//! inline base64 form takes 10.7 and ASCII about 24.
//!
//! # Why our own writer
//!
//! It replaced `vtkio` 0.6, whose dependencies nom 3.2.1 and quick-xml 0.22
//! hold code that a future Rust will reject. `vtkio`'s next version is a
//! release candidate (0.7.0-rc2) that writes arrays only inline in base64
//! (its raw appended output sits behind a feature it does not declare) and
//! builds the whole file in memory through serde; the format is small
//! enough to write here, streamed, with no dependency at all.

use std::fmt::Write as _;
use std::io::{BufWriter, Write};
use std::path::Path;

use crate::contact::ContactElement;
use crate::error::{Error, Result, Status};
use crate::fem::element::TriGeometry;
use crate::fem::mesh::Mesh;
use crate::fem::solid_mesh::SolidMesh;
use crate::model::Model;

/// `VTK_TRIANGLE`.
const TRIANGLE: u8 = 5;
/// `VTK_TETRA`.
const TETRA: u8 = 10;

/// The scalar types of the arrays written, as VTK names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    Float64,
    Int32,
    Int64,
    UInt8,
}

impl Scalar {
    fn name(self) -> &'static str {
        match self {
            Scalar::Float64 => "Float64",
            Scalar::Int32 => "Int32",
            Scalar::Int64 => "Int64",
            Scalar::UInt8 => "UInt8",
        }
    }

    fn bytes(self) -> u64 {
        match self {
            Scalar::Float64 | Scalar::Int64 => 8,
            Scalar::Int32 => 4,
            Scalar::UInt8 => 1,
        }
    }
}

/// Streams an array's values, little-endian, into the file.
type Values<'a> = Box<dyn Fn(&mut dyn Write) -> std::io::Result<()> + 'a>;

/// One `DataArray`: its header and how to stream its values.
struct Array<'a> {
    name: &'static str,
    scalar: Scalar,
    /// The components' names, written (as `ComponentName0`, …) where
    /// there are several, for ParaView's menus.
    components: &'static [&'static str],
    /// Tuples (points or cells).
    tuples: usize,
    values: Values<'a>,
}

impl Array<'_> {
    fn bytes(&self) -> u64 {
        self.tuples as u64 * self.components.len() as u64 * self.scalar.bytes()
    }
}

/// One value per tuple.
const SCALAR: &[&str] = &["value"];
/// Vectors of the plane, z = 0.
const XYZ: &[&str] = &["x", "y", "z"];
/// Voigt components of a plane strain or stress.
const VOIGT: &[&str] = &["xx", "yy", "xy"];
/// A symmetric tensor in space, in the order VTK's tensor filters read
/// six components (`vtkTensorPrincipalInvariants` takes the fourth as
/// xy), not Voigt's.
const SYMMETRIC: &[&str] = &["xx", "yy", "zz", "xy", "yz", "xz"];

fn f64s<'a, I>(values: impl Fn() -> I + 'a) -> Values<'a>
where
    I: Iterator<Item = f64>,
{
    Box::new(move |w| values().try_for_each(|x| w.write_all(&x.to_le_bytes())))
}

/// Plane vectors as [x, y, 0].
fn planar<'a>(v: &'a [[f64; 2]]) -> Values<'a> {
    f64s(move || v.iter().flat_map(|d| [d[0], d[1], 0.0]))
}

/// Voigt triples, then `zeros` triples of zeros (the elements of B have
/// no strain or stress of a body).
fn voigt(v: &[[f64; 3]], zeros: usize) -> Values<'_> {
    f64s(move || {
        v.iter()
            .flatten()
            .copied()
            .chain(std::iter::repeat_n(0.0, 3 * zeros))
    })
}

/// The Int32 or Int64 values of connectivity and offsets.
fn indices<'a, I>(wide: bool, values: impl Fn() -> I + 'a) -> Values<'a>
where
    I: Iterator<Item = usize>,
{
    // The caller chose Int32 only where every value fits.
    Box::new(move |w| {
        values().try_for_each(|v| {
            if wide {
                w.write_all(&(v as i64).to_le_bytes())
            } else {
                w.write_all(&(v as i32).to_le_bytes())
            }
        })
    })
}

/// Whether connectivity and offsets need Int64: a node index or an
/// offset (`corners` per cell) past `i32::MAX`.
fn wide_indices(points: usize, cells: usize, corners: usize) -> bool {
    let max = i32::MAX as usize;
    points > max || cells > max / corners
}

/// The `Cells` arrays of `n_cells` cells of one VTK type, `corners` nodes
/// each, listed by `connectivity` (the nodes of every cell in turn).
fn cell_arrays<'a, I>(
    n_points: usize,
    n_cells: usize,
    corners: usize,
    cell_type: u8,
    connectivity: impl Fn() -> I + 'a,
) -> Vec<Array<'a>>
where
    I: Iterator<Item = usize>,
{
    let wide = wide_indices(n_points, n_cells, corners);
    let index = if wide { Scalar::Int64 } else { Scalar::Int32 };
    vec![
        Array {
            name: "connectivity",
            scalar: index,
            components: SCALAR,
            tuples: corners * n_cells,
            values: indices(wide, connectivity),
        },
        Array {
            name: "offsets",
            scalar: index,
            components: SCALAR,
            tuples: n_cells,
            values: indices(wide, move || (1..=n_cells).map(move |k| corners * k)),
        },
        Array {
            name: "types",
            scalar: Scalar::UInt8,
            components: SCALAR,
            tuples: n_cells,
            values: Box::new(move |w| (0..n_cells).try_for_each(|_| w.write_all(&[cell_type]))),
        },
    ]
}

/// Writes the mesh in its initial configuration with the solved fields
/// (the arrays of the [module's table](self)): point data `displacement`
/// and, after a contact solve, `contact_pressure`, `contact_force` and
/// `contact_gap`; cell data `body`, `J`, `strain`, `stress` and
/// `out_of_plane_stress`, and under
/// the strip weighting the elements of the contact mesh B appended after
/// the body triangles (body −1) with `contact_element_active` and
/// `contact_element_pressure`.
///
/// Errors: [`Status::InvalidState`] before a solve (nothing is written),
/// [`Status::Io`] when the file cannot be written (the message names it
/// and the reason). The model is never changed.
pub fn write_vtu(model: &Model, path: &Path) -> Result<()> {
    let results = Results::of(model)?;
    write_file(&results.grid(), path)
        .map_err(|e| Error::new(Status::Io, format!("cannot write {}: {e}", path.display())))
}

/// What the file shows of a solved model, all read before anything is
/// written: a model that cannot give one of them writes no file at all.
struct Results<'a> {
    mesh: &'a Mesh,
    /// The displacement of every node.
    u: Vec<[f64; 2]>,
    /// Every triangle's strain (Voigt).
    strains: Vec<[f64; 3]>,
    /// Every triangle's stress (Voigt).
    stresses: Vec<[f64; 3]>,
    /// Every triangle's stress normal to the plane (a ring's hoop stress).
    normal_stresses: Vec<f64>,
    /// A contact solve's nodal results, under either weighting; `None`
    /// after a solve without contact.
    contact: Option<NodalContact>,
    /// The contact mesh B and its state, under the strip weighting only.
    strip: Option<StripContact<'a>>,
}

/// The nodal results of a contact solve, one value per node.
struct NodalContact {
    /// Contact traction [pressure, shear], the pressure positive in
    /// compression.
    traction: Vec<[f64; 2]>,
    /// Force the contact exerts on the node.
    force: Vec<[f64; 2]>,
    /// Normal gap, negative where the bodies interpenetrate.
    gap: Vec<f64>,
}

/// The elements of the contact mesh B under the strip weighting, written
/// as cells after the body triangles, with their state.
#[derive(Clone, Copy)]
struct StripContact<'a> {
    elements: &'a [ContactElement],
    /// Each element's active flag.
    active: &'a [bool],
    /// Each element's contact pressure.
    pressure: &'a [f64],
}

impl<'a> Results<'a> {
    /// The results of `model`, as its accessors give them.
    fn of(model: &'a Model) -> Result<Results<'a>> {
        let mesh = model
            .mesh()
            .ok_or_else(|| Error::state("no mesh to write"))?;
        let u = model.displacements()?;
        let strains = model.element_strains()?;
        let stresses = model.element_stresses()?;
        let normal_stresses = model.element_out_of_plane_stresses()?;
        let contact = match model.contact_report() {
            Ok(_) => Some(NodalContact {
                traction: model.contact_nodal_tractions()?,
                force: model.contact_forces()?,
                gap: model.contact_gaps()?,
            }),
            Err(_) => None,
        };
        // Refused when every pair is under the mortar weighting: no B.
        let strip = match (&contact, model.contact_elements()) {
            (Some(_), Ok(elements)) if !elements.is_empty() => Some(StripContact {
                elements,
                active: model.contact_active()?,
                pressure: model.contact_pressure()?,
            }),
            _ => None,
        };
        Ok(Results {
            mesh,
            u,
            strains,
            stresses,
            normal_stresses,
            contact,
            strip,
        })
    }

    /// The elements of B written as cells (none but under the strip
    /// weighting).
    fn b(&self) -> &'a [ContactElement] {
        self.strip.map_or(&[], |s| s.elements)
    }

    fn n_points(&self) -> usize {
        self.mesh.nodes().len()
    }

    /// The body triangles and the elements of B.
    fn n_cells(&self) -> usize {
        self.mesh.triangles().len() + self.b().len()
    }

    /// Every array of the file, section by section.
    fn grid(&self) -> Grid<'_> {
        Grid {
            n_points: self.n_points(),
            n_cells: self.n_cells(),
            points: self.points(),
            cells: self.cells(),
            point_attributes: DISPLACEMENT_VECTORS,
            point_data: self.point_data(),
            cell_data: self.cell_data(),
        }
    }

    /// The points: the nodes in the initial configuration.
    fn points(&self) -> Vec<Array<'a>> {
        vec![Array {
            name: "Points",
            scalar: Scalar::Float64,
            components: XYZ,
            tuples: self.n_points(),
            values: planar(self.mesh.nodes()),
        }]
    }

    /// The cells: the body triangles, then the elements of B.
    fn cells(&self) -> Vec<Array<'a>> {
        let (triangles, b) = (self.mesh.triangles(), self.b());
        cell_arrays(self.n_points(), self.n_cells(), 3, TRIANGLE, move || {
            triangles
                .iter()
                .chain(b.iter().map(|e| &e.nodes))
                .flatten()
                .copied()
        })
    }

    /// The arrays on the points: the displacement, and the nodal contact
    /// results after a contact solve.
    fn point_data(&self) -> Vec<Array<'_>> {
        let n_points = self.n_points();
        let mut point_data = vec![Array {
            name: "displacement",
            scalar: Scalar::Float64,
            components: XYZ,
            tuples: n_points,
            values: planar(&self.u),
        }];
        if let Some(NodalContact {
            traction,
            force,
            gap,
        }) = &self.contact
        {
            point_data.extend([
                Array {
                    name: "contact_pressure",
                    scalar: Scalar::Float64,
                    components: SCALAR,
                    tuples: n_points,
                    values: f64s(|| traction.iter().map(|t| t[0])),
                },
                Array {
                    name: "contact_shear",
                    scalar: Scalar::Float64,
                    components: SCALAR,
                    tuples: n_points,
                    values: f64s(|| traction.iter().map(|t| t[1])),
                },
                Array {
                    name: "contact_force",
                    scalar: Scalar::Float64,
                    components: XYZ,
                    tuples: n_points,
                    values: planar(force),
                },
                Array {
                    name: "contact_gap",
                    scalar: Scalar::Float64,
                    components: SCALAR,
                    tuples: n_points,
                    values: f64s(|| gap.iter().copied()),
                },
            ]);
        }
        point_data
    }

    /// The strain and stresses of the bodies' triangles, zero on the
    /// `zeros` elements of B after them.
    fn body_fields(&self, n_cells: usize, zeros: usize) -> [Array<'_>; 3] {
        [
            Array {
                name: "strain",
                scalar: Scalar::Float64,
                components: VOIGT,
                tuples: n_cells,
                values: voigt(&self.strains, zeros),
            },
            Array {
                name: "stress",
                scalar: Scalar::Float64,
                components: VOIGT,
                tuples: n_cells,
                values: voigt(&self.stresses, zeros),
            },
            Array {
                name: "out_of_plane_stress",
                scalar: Scalar::Float64,
                components: SCALAR,
                tuples: n_cells,
                values: f64s(move || {
                    (self.normal_stresses.iter().copied()).chain(std::iter::repeat_n(0.0, zeros))
                }),
            },
        ]
    }

    /// The arrays on the cells: body, J, strain and stress of every cell,
    /// and the state of the elements of B under the strip weighting.
    fn cell_data(&self) -> Vec<Array<'_>> {
        let (mesh, triangles, b) = (self.mesh, self.mesh.triangles(), self.b());
        let n_cells = self.n_cells();
        let mut cell_data = vec![
            Array {
                name: "body",
                scalar: Scalar::Int32,
                components: SCALAR,
                tuples: n_cells,
                values: Box::new(move |w| {
                    mesh.body_of()
                        .iter()
                        .copied()
                        .chain(std::iter::repeat_n(-1, b.len()))
                        .try_for_each(|t: i32| w.write_all(&t.to_le_bytes()))
                }),
            },
            Array {
                name: "J",
                scalar: Scalar::Float64,
                components: SCALAR,
                tuples: n_cells,
                values: f64s(move || {
                    triangles
                        .iter()
                        .map(|t| TriGeometry::new(&mesh.corners(t)).j)
                        .chain(b.iter().map(|e| e.j0))
                }),
            },
        ];
        cell_data.extend(self.body_fields(n_cells, b.len()));
        if let Some(StripContact {
            active, pressure, ..
        }) = self.strip
        {
            let before = triangles.len();
            cell_data.extend([
                Array {
                    name: "contact_element_active",
                    scalar: Scalar::UInt8,
                    components: SCALAR,
                    tuples: n_cells,
                    values: Box::new(move |w| {
                        std::iter::repeat_n(0, before)
                            .chain(active.iter().map(|&a| u8::from(a)))
                            .try_for_each(|a| w.write_all(&[a]))
                    }),
                },
                Array {
                    name: "contact_element_pressure",
                    scalar: Scalar::Float64,
                    components: SCALAR,
                    tuples: n_cells,
                    values: f64s(move || {
                        std::iter::repeat_n(0.0, before).chain(pressure.iter().copied())
                    }),
                },
            ]);
        }
        cell_data
    }
}

/// The fields written with a tetrahedral mesh by [`write_solid_vtu`], each
/// where given: a solid solve's results are plain arrays (there is no 3D
/// model to read them from), so the caller hands over those it has.
#[derive(Clone, Copy, Debug, Default)]
pub struct SolidFields<'a> {
    /// The displacement of every node.
    pub displacement: Option<&'a [[f64; 3]]>,
    /// The stress of every tetrahedron, in Voigt's order [σ_xx, σ_yy,
    /// σ_zz, σ_yz, σ_xz, σ_xy].
    pub stress: Option<&'a [[f64; 6]]>,
    /// The contact pressure at every node, positive in compression.
    pub contact_pressure: Option<&'a [f64]>,
}

/// Writes a tetrahedral mesh in its initial configuration with the fields
/// given (the arrays of the [module's table](self#solid-meshes)): cell
/// data `body` and `J` always; point data `displacement` and
/// `contact_pressure`, cell data `stress`, each where `fields` has it.
///
/// Errors: [`Status::InvalidArgument`] for a field of another length than
/// the mesh's nodes or tetrahedra (the message names the field and both
/// lengths; nothing is written), [`Status::Io`] when the file cannot be
/// written (the message names it and the reason).
pub fn write_solid_vtu(mesh: &SolidMesh, fields: &SolidFields<'_>, path: &Path) -> Result<()> {
    let (n_points, n_cells) = (mesh.nodes().len(), mesh.tets().len());
    let check = |name: &str, len: Option<usize>, want: usize, of: &str| match len {
        Some(len) if len != want => Err(Error::argument(format!(
            "{name} has {len} values for the mesh's {want} {of}"
        ))),
        _ => Ok(()),
    };
    check(
        "displacement",
        fields.displacement.map(<[_]>::len),
        n_points,
        "nodes",
    )?;
    check(
        "stress",
        fields.stress.map(<[_]>::len),
        n_cells,
        "tetrahedra",
    )?;
    check(
        "contact_pressure",
        fields.contact_pressure.map(<[_]>::len),
        n_points,
        "nodes",
    )?;
    write_file(&solid_grid(mesh, fields), path)
        .map_err(|e| Error::new(Status::Io, format!("cannot write {}: {e}", path.display())))
}

/// Every array of a solid mesh's file, section by section.
fn solid_grid<'a>(mesh: &'a SolidMesh, fields: &SolidFields<'a>) -> Grid<'a> {
    let (n_points, n_cells) = (mesh.nodes().len(), mesh.tets().len());
    let nodes = mesh.nodes();
    let tets = mesh.tets();
    let mut point_data = Vec::new();
    if let Some(u) = fields.displacement {
        point_data.push(Array {
            name: "displacement",
            scalar: Scalar::Float64,
            components: XYZ,
            tuples: n_points,
            values: f64s(move || u.iter().flatten().copied()),
        });
    }
    if let Some(p) = fields.contact_pressure {
        point_data.push(Array {
            name: "contact_pressure",
            scalar: Scalar::Float64,
            components: SCALAR,
            tuples: n_points,
            values: f64s(move || p.iter().copied()),
        });
    }
    let mut cell_data = vec![
        Array {
            name: "body",
            scalar: Scalar::Int32,
            components: SCALAR,
            tuples: n_cells,
            values: Box::new(move |w| {
                (mesh.body_of().iter()).try_for_each(|t| w.write_all(&t.to_le_bytes()))
            }),
        },
        Array {
            name: "J",
            scalar: Scalar::Float64,
            components: SCALAR,
            tuples: n_cells,
            values: f64s(move || (0..n_cells).map(move |e| mesh.geometry(e).j)),
        },
    ];
    if let Some(stress) = fields.stress {
        cell_data.push(Array {
            name: "stress",
            scalar: Scalar::Float64,
            components: SYMMETRIC,
            tuples: n_cells,
            // Voigt's [xx, yy, zz, yz, xz, xy] in VTK's order.
            values: f64s(move || {
                stress
                    .iter()
                    .flat_map(|s| [s[0], s[1], s[2], s[5], s[3], s[4]])
            }),
        });
    }
    Grid {
        n_points,
        n_cells,
        points: vec![Array {
            name: "Points",
            scalar: Scalar::Float64,
            components: XYZ,
            tuples: n_points,
            values: f64s(move || nodes.iter().flatten().copied()),
        }],
        cells: cell_arrays(n_points, n_cells, 4, TETRA, move || {
            tets.iter().flatten().copied()
        }),
        point_attributes: if fields.displacement.is_some() {
            DISPLACEMENT_VECTORS
        } else {
            ""
        },
        point_data,
        cell_data,
    }
}

/// The attribute of `PointData` that makes the displacement its active
/// vectors (ParaView's "Warp By Vector" picks it).
const DISPLACEMENT_VECTORS: &str = " Vectors=\"displacement\"";

/// The arrays of a piece, section by section.
struct Grid<'a> {
    n_points: usize,
    n_cells: usize,
    points: Vec<Array<'a>>,
    cells: Vec<Array<'a>>,
    /// The attributes of `PointData` naming its active arrays: none where
    /// the array they would name is not written.
    point_attributes: &'static str,
    point_data: Vec<Array<'a>>,
    cell_data: Vec<Array<'a>>,
}

impl Grid<'_> {
    /// The sections in the order of the file, each with its tag and the
    /// attributes that name its active arrays.
    fn sections(&self) -> [(&'static str, &'static str, &[Array<'_>]); 4] {
        [
            ("PointData", self.point_attributes, &self.point_data),
            ("CellData", "", &self.cell_data),
            ("Points", "", &self.points),
            ("Cells", "", &self.cells),
        ]
    }

    /// The XML up to the first byte of appended data.
    fn header(&self) -> String {
        let mut x = String::new();
        // Writing into a String cannot fail.
        let _ = write!(
            x,
            "<?xml version=\"1.0\"?>\n\
             <VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" \
             header_type=\"UInt64\">\n  <UnstructuredGrid>\n    \
             <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
            self.n_points, self.n_cells
        );
        let mut offset = 0u64;
        for (tag, attributes, arrays) in self.sections() {
            let _ = writeln!(x, "      <{tag}{attributes}>");
            for a in arrays {
                let _ = write!(
                    x,
                    "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"",
                    a.scalar.name(),
                    a.name,
                    a.components.len()
                );
                if a.components.len() > 1 {
                    for (k, c) in a.components.iter().enumerate() {
                        let _ = write!(x, " ComponentName{k}=\"{c}\"");
                    }
                }
                let _ = writeln!(x, " format=\"appended\" offset=\"{offset}\"/>");
                offset += 8 + a.bytes();
            }
            let _ = writeln!(x, "      </{tag}>");
        }
        x.push_str("    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
        x
    }
}

fn write_file(grid: &Grid<'_>, path: &Path) -> std::io::Result<()> {
    let file = std::fs::File::create(path)?;
    let mut w = BufWriter::with_capacity(1 << 20, file);
    w.write_all(grid.header().as_bytes())?;
    for (_, _, arrays) in grid.sections() {
        for a in arrays {
            w.write_all(&a.bytes().to_le_bytes())?;
            (a.values)(&mut w)?;
        }
    }
    // The line break before the end tag is where meshio's reader of raw
    // data ends the data (it cuts at the last one).
    w.write_all(b"\n  </AppendedData>\n</VTKFile>\n")?;
    w.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_are_int32_up_to_the_largest_node_index_and_offset_that_fit() {
        let max = i32::MAX as usize;
        assert!(!wide_indices(max, max / 3, 3));
        assert!(wide_indices(max + 1, 1, 3));
        assert!(wide_indices(1, max / 3 + 1, 3));
        assert!(!wide_indices(max, max / 4, 4));
        assert!(wide_indices(1, max / 4 + 1, 4));
    }

    #[test]
    fn wide_indices_are_written_as_int64_little_endian() {
        let mut out = Vec::new();
        indices(true, || [1usize, 1 << 40].into_iter())(&mut out).unwrap();
        assert_eq!(out[..8], 1i64.to_le_bytes());
        assert_eq!(out[8..], (1i64 << 40).to_le_bytes());
    }

    #[test]
    fn narrow_indices_are_written_as_int32_little_endian() {
        let mut out = Vec::new();
        indices(false, || [7usize, 300].into_iter())(&mut out).unwrap();
        assert_eq!(out, [7, 0, 0, 0, 44, 1, 0, 0]);
    }
}
