//! Probe: the rigid flat cylindrical punch on a block meshed by Gmsh,
//! graded towards the punch's edge circle only, through the 3D model.
//! Prints P/(2aE*δ) − 1 per edge size. Measurement driver, not an example.
//!
//!   cargo run --release --example punch_gmsh -- 8 16 32

use std::process::Command;
use std::time::Instant;

use tfem::contact::prism_layer::split_prism;
use tfem::fem::solid_mesh::SolidMesh;
use tfem::fem::tet::TetGeometry;
use tfem::io::gmsh::read_solid_msh;
use tfem::model::solid::{Axis, SolidMaterial, SolidModel};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let ks: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let extent: f64 = std::env::var("EXTENT").map_or(200.0, |s| s.parse().unwrap());
    let growth: f64 = std::env::var("GROWTH").map_or(0.25, |s| s.parse().unwrap());
    for k in ks {
        let t0 = Instant::now();
        let mesh = mesh(k, extent, growth)?;
        let meshed = t0.elapsed().as_secs_f64();
        let (err, unknowns, area) = solve(mesh, k)?;
        println!(
            "a/{k}: extent {extent}a growth {growth}: P error {:+.3}%, area error {:+.3}%, {unknowns} unknowns, mesh {meshed:.1} s, total {:.1} s",
            100.0 * err,
            100.0 * area,
            t0.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// The quarter block [0, R]² × [−R, 0] with the quarter disc r < a on its
/// top (tag 2), sides x = 0 (11), y = 0 (12), bottom (13), meshed by Gmsh
/// with size a/k at the edge circle growing by `growth` per unit distance.
fn mesh(k: f64, r: f64, growth: f64) -> Result<SolidMesh, Box<dyn std::error::Error>> {
    let dir = std::env::temp_dir().join(format!("tfem_punch_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let geo = dir.join("punch.geo");
    let h0 = 1.0 / k;
    let hmax = r / 8.0;
    std::fs::write(
        &geo,
        format!(
            r#"a = 1; R = {r}; e = 1e-6 * R;
Point(1) = {{0, 0, 0}}; Point(2) = {{a, 0, 0}}; Point(3) = {{0, a, 0}};
Point(4) = {{R, 0, 0}}; Point(5) = {{R, R, 0}}; Point(6) = {{0, R, 0}};
Circle(1) = {{2, 1, 3}};
Line(2) = {{1, 2}}; Line(3) = {{3, 1}};
Line(4) = {{2, 4}}; Line(5) = {{4, 5}}; Line(6) = {{5, 6}}; Line(7) = {{6, 3}};
Curve Loop(1) = {{2, 1, 3}}; Plane Surface(1) = {{1}};
Curve Loop(2) = {{4, 5, 6, 7, -1}}; Plane Surface(2) = {{2}};
Extrude {{0, 0, -R}} {{ Surface{{1, 2}}; }}
Physical Volume(1) = {{1, 2}};
Physical Surface(2) = {{1}};
Physical Surface(11) = Surface In BoundingBox{{-e, -e, -R - e, e, R + e, e}};
Physical Surface(12) = Surface In BoundingBox{{-e, -e, -R - e, R + e, e, e}};
Physical Surface(13) = Surface In BoundingBox{{-e, -e, -R - e, R + e, R + e, -R + e}};
Field[1] = Distance; Field[1].CurvesList = {{1}}; Field[1].NumPointsPerCurve = 400;
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = {h0};
Field[2].SizeMax = {hmax}; Field[2].DistMin = 0; Field[2].DistMax = {dmax};
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
"#,
            dmax = (hmax - h0) / growth
        ),
    )?;
    let msh = dir.join("punch.msh");
    let out = Command::new("gmsh")
        .arg("-3")
        .arg("-format")
        .arg("msh41")
        .arg("-nt")
        .arg("2")
        .arg(&geo)
        .arg("-o")
        .arg(&msh)
        .output()?;
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).into());
    }
    Ok(read_solid_msh(&msh, 0)?)
}

/// The punch (body 2): a layer of prisms over the disc's triangles, of
/// thickness a/k, every node prescribed; frictionless contact between the
/// disc (side a) and the punch's bottom.
fn solve(block: SolidMesh, k: f64) -> Result<(f64, usize, f64), Box<dyn std::error::Error>> {
    let (young, poisson, delta) = (1.0, 0.3, 1e-3);
    let mut nodes = block.nodes().to_vec();
    let n0 = nodes.len();
    let mut tets = block.tets().to_vec();
    let mut body = block.body_of().to_vec();
    let disc: Vec<[usize; 3]> = (block.boundary_faces().iter())
        .filter(|f| f.tag == 2)
        .map(|f| f.nodes)
        .collect();
    let mut copy = std::collections::BTreeMap::new();
    for &v in disc.iter().flatten() {
        copy.entry(v).or_insert_with(|| {
            let [x, y, z] = nodes[v];
            nodes.push([x, y, z]);
            nodes.push([x, y, z + 1.0 / k]);
            (nodes.len() - 2, nodes.len() - 1)
        });
    }
    let mut bottoms = Vec::new();
    for tri in &disc {
        let bottom = tri.map(|v| copy[&v].0);
        let top = tri.map(|v| copy[&v].1);
        for t in split_prism(bottom, top, |v| v) {
            let j = TetGeometry::new(&t.map(|v| nodes[v])).j;
            tets.push(if j < 0.0 { [t[0], t[1], t[3], t[2]] } else { t });
            body.push(2);
        }
        bottoms.push(bottom);
    }
    let mut faces: Vec<[usize; 3]> = Vec::new();
    let mut tags = Vec::new();
    for f in block.boundary_faces() {
        faces.push(f.nodes);
        tags.push(f.tag);
    }
    faces.extend(&bottoms);
    tags.resize(faces.len(), 3);
    let mut mesh = SolidMesh::new(nodes, tets, body, 0)?;
    mesh.set_boundary_faces(&faces, &tags)?;
    let mut model = SolidModel::new();
    let side = |tag: i32| -> Vec<usize> {
        let mut v: Vec<usize> = (mesh.boundary_faces().iter())
            .filter(|f| f.tag == tag)
            .flat_map(|f| f.nodes)
            .collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    let (xs, ys, bottom) = (side(11), side(12), side(13));
    let n = mesh.nodes().len();
    model.set_mesh(mesh);
    model.set_material(1, SolidMaterial::new(young, poisson)?);
    model.set_material(2, SolidMaterial::new(young, poisson)?);
    for v in xs {
        model.fix(v, Axis::X, 0.0)?;
    }
    for v in ys {
        model.fix(v, Axis::Y, 0.0)?;
    }
    for v in bottom {
        model.fix(v, Axis::Z, 0.0)?;
    }
    for v in n0..n {
        model.fix(v, Axis::X, 0.0)?;
        model.fix(v, Axis::Y, 0.0)?;
        model.fix(v, Axis::Z, -delta)?;
    }
    model.add_contact_pair(2, 3)?;
    let info = model.solve()?;
    let r = model.reactions()?;
    let p: f64 = -4.0 * (n0..n).map(|v| r[v][2]).sum::<f64>();
    let exact = 2.0 * young / (1.0 - poisson * poisson) * delta;
    let area = 4.0 * model.contact_area()? / std::f64::consts::PI - 1.0;
    Ok((p / exact - 1.0, info.unknowns, area))
}
