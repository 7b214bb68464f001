//! The seed scene in three dimensions (docs/method.md §9): Ω1 = [0, L]² ×
//! [−H1, 0] under Ω2 = [0, L]² × [0, H2], pressed by p on the square
//! [L/2 − C, L/2 + C]² of Ω2's top and held on the same square of Ω1's
//! bottom, frictionless contact through B's flat tetrahedra. Solved on the
//! quarter x, y ≤ L/2 (its symmetry planes prescribed); prints the contact
//! area, the opening at the corner (0, 0, 0), u_z at the top's centre and
//! the compliance ∫ p·(−u_z), with CalculiX's C3D8 result on the same mesh
//! size where the repository has one (scripts/calculix/seed3d). Files only
//! when asked: `--vtu` writes the solved quarter for ParaView
//! (`<out>/two_blocks_3d.vtu`), `--picture` the deformed blocks, mirrored
//! whole and exaggerated, coloured by u_z (`<out>/two_blocks_3d.png`).
//!
//!   cargo run --release --example two_blocks_3d                    # h = 1/40
//!   cargo run --release --example two_blocks_3d -- --mesh-size 0.05 --json
//!   cargo run --release --example two_blocks_3d -- --picture --vtu --out results

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Parser;
use serde_json::json;
use tfem::io::vtu::{SolidFields, write_solid_vtu};
use tfem::model::solid::SolidModel;
use tfem::studies::tet_scenes::{TwoBlocks3d, tags};

#[path = "common/picture.rs"]
mod picture;

/// CalculiX's runs of the scene (C3D8, node-to-surface contact), one JSON
/// object per line.
const CALCULIX: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/scripts/calculix/seed3d/results.jsonl"
);

/// The seed scene of tfem in three dimensions.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// Young's modulus of the lower block Ω1 [Pa].
    #[arg(long, default_value_t = 1e10)]
    e1: f64,
    /// Poisson ratio of Ω1.
    #[arg(long, default_value_t = 0.3)]
    nu1: f64,
    /// Young's modulus of the upper block Ω2 [Pa].
    #[arg(long, default_value_t = 1e11)]
    e2: f64,
    /// Poisson ratio of Ω2.
    #[arg(long, default_value_t = 0.3)]
    nu2: f64,
    /// Height of Ω1 [m].
    #[arg(long, default_value_t = 0.25)]
    h1: f64,
    /// Height of Ω2 [m].
    #[arg(long, default_value_t = 0.25)]
    h2: f64,
    /// Side L of both blocks [m].
    #[arg(long, default_value_t = 1.0)]
    length: f64,
    /// Half-width C of the loaded and supported squares [m].
    #[arg(long, default_value_t = 0.1)]
    c: f64,
    /// Pressure on the loaded square [Pa].
    #[arg(long, default_value_t = 1e7)]
    p: f64,
    /// Element size h [m]: it must divide L/2, C and the heights.
    #[arg(long, default_value_t = 1.0 / 40.0)]
    mesh_size: f64,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
    /// Write the solved quarter as a VTK XML grid (`<out>/two_blocks_3d.vtu`:
    /// displacement, contact pressure, stress).
    #[arg(long)]
    vtu: bool,
    /// Draw the deformed blocks coloured by u_z (`<out>/two_blocks_3d.png`).
    #[arg(long)]
    picture: bool,
    /// Where `--vtu` and `--picture` write their files.
    #[arg(long, default_value = "out")]
    out: PathBuf,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a = Args::parse();
    let scene = TwoBlocks3d {
        l: a.length,
        heights: [a.h1, a.h2],
        young: [a.e1, a.e2],
        poisson: [a.nu1, a.nu2],
        pressure: a.p,
        c: a.c,
        h: a.mesh_size,
        ..TwoBlocks3d::default()
    };
    let t0 = Instant::now();
    let r = scene.solve_model()?;
    let seconds = t0.elapsed().as_secs_f64();
    let outputs = [
        ("contact_area", r.contact_area, "m²"),
        ("gap_corner", r.gap_corner, "m"),
        ("v_top", r.v_top, "m"),
        ("compliance", r.compliance, "J"),
    ];
    let calculix = canonical(&scene)
        .then(|| calculix_at(a.mesh_size))
        .flatten();
    if a.json {
        let mut out = json!({
            "unknowns": r.unknowns,
            "iterations": r.iterations,
            "factorizations": r.factorizations,
            "seconds": seconds,
        });
        for (name, value, _) in outputs {
            out[name] = json!(value);
        }
        println!("{out}");
    } else {
        println!(
            "two blocks in 3D, h = {} ({} unknowns in the quarter, {} active-set solves, \
             {seconds:.2} s):",
            a.mesh_size, r.unknowns, r.iterations
        );
        for (name, value, unit) in outputs {
            let beside = calculix.as_ref().map_or(String::new(), |c| {
                let q = c[name].as_f64().unwrap_or(f64::NAN);
                format!(
                    "   CalculiX C3D8 at this h: {q:.5e} ({:+.2e})",
                    value / q - 1.0
                )
            });
            println!("  {name:<13} {value:+.5e} {unit:<3}{beside}");
        }
        println!(
            "  load carried by the contact: {:.12} of p·(2C)²",
            r.transmitted
        );
    }
    if a.vtu || a.picture {
        std::fs::create_dir_all(&a.out)?;
        let mut model = scene.model()?;
        model.solve_contact(&scene.options())?;
        if a.vtu {
            write_vtu(&model, &a.out.join("two_blocks_3d.vtu"))?;
        }
        if a.picture {
            let path = a.out.join("two_blocks_3d.png");
            draw(&model, &scene, &path)?;
            eprintln!("wrote {}", path.display());
        }
    }
    Ok(())
}

/// Whether the scene has the canonical parameters CalculiX was run with.
fn canonical(scene: &TwoBlocks3d) -> bool {
    let d = TwoBlocks3d::default();
    (
        scene.l,
        scene.heights,
        scene.young,
        scene.poisson,
        scene.pressure,
        scene.c,
    ) == (d.l, d.heights, d.young, d.poisson, d.pressure, d.c)
}

/// CalculiX's node-to-surface run at mesh size `h`, if the repository
/// has one that converged.
fn calculix_at(h: f64) -> Option<serde_json::Value> {
    let text = std::fs::read_to_string(CALCULIX).ok()?;
    (text.lines())
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .find(|v| {
            v["contact"] == "n2s"
                && v["converged"] != false
                && (v["h"].as_f64().unwrap_or(0.0) / h - 1.0).abs() < 1e-9
        })
}

fn write_vtu(model: &SolidModel, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let displacement = model.displacements()?;
    let stress = model.element_stresses()?;
    let pressure = model.contact_nodal_pressures()?;
    let fields = SolidFields {
        displacement: Some(&displacement),
        stress: Some(&stress),
        contact_pressure: Some(&pressure),
    };
    write_solid_vtu(model.mesh().expect("set"), &fields, path)?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// The blocks' outer faces, deformed (exaggerated so that the largest
/// displacement is 4 % of L) and mirrored into the whole scene, seen from
/// above a corner and drawn back to front, coloured by u_z.
fn draw(
    model: &SolidModel,
    scene: &TwoBlocks3d,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let mesh = model.mesh().expect("set");
    let u = model.displacements()?;
    let largest = u.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let scale = 0.04 * scene.l / largest.max(f64::MIN_POSITIVE);
    let half = 0.5 * scene.l;
    // The symmetry planes' faces and the interface are inside the whole
    // scene; the squares repeat faces of the sides.
    let hidden = [
        tags::LOWER_SIDES[1],
        tags::LOWER_SIDES[3],
        tags::LOWER_SIDES[5],
        tags::UPPER_SIDES[1],
        tags::UPPER_SIDES[3],
        tags::UPPER_SIDES[4],
        tags::SUPPORT,
        tags::LOAD,
    ];
    let faces: Vec<_> = (mesh.boundary_faces().iter())
        .filter(|f| !hidden.contains(&f.tag))
        .map(|f| (f.nodes, mesh.face_geometry(f).normal))
        .collect();
    let (mut points, mut values, mut triangles) = (Vec::new(), Vec::new(), Vec::new());
    // View from direction d: screen axes e1, e2, depth along d.
    let d = normalise([1.0, 0.6, 0.8]);
    let e1 = normalise([-d[1], d[0], 0.0]);
    let e2 = [
        d[1] * e1[2] - d[2] * e1[1],
        d[2] * e1[0] - d[0] * e1[2],
        d[0] * e1[1] - d[1] * e1[0],
    ];
    let mut depth = Vec::new();
    for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
        let first = points.len();
        for (x, du) in mesh.nodes().iter().zip(&u) {
            let q = [
                half + sx * (x[0] + scale * du[0] - half),
                half + sy * (x[1] + scale * du[1] - half),
                x[2] + scale * du[2],
            ];
            points.push([dot(q, e1), dot(q, e2)]);
            depth.push(dot(q, d));
            values.push(du[2]);
        }
        // Only the faces turned towards the viewer (the scene is two
        // boxes: what faces away is behind).
        for (f, n) in &faces {
            let facing = dot([sx * n[0], sy * n[1], n[2]], d);
            if facing > 0.0 {
                triangles.push((f.map(|v| first + v), 0.55 + 0.45 * facing));
            }
        }
    }
    let mean = |t: &[usize; 3]| t.iter().map(|&v| depth[v]).sum::<f64>();
    triangles.sort_by(|a, b| mean(&a.0).total_cmp(&mean(&b.0)));
    let (triangles, shade): (Vec<[usize; 3]>, Vec<f64>) = triangles.into_iter().unzip();
    let title = format!(
        "two blocks in 3D: u_z [m], displacements x{scale:.0}, h = {}",
        scene.h
    );
    picture::shaded_field_png(&points, &triangles, &values, &shade, &title, path)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn normalise(a: [f64; 3]) -> [f64; 3] {
    let n = dot(a, a).sqrt();
    a.map(|x| x / n)
}
