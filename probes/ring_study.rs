//! Non-matching curved interfaces, measured (a probe: docs/method.md §6.11
//! quotes its tables).
//!
//! Three scenes, each solved under the automatic choice (the default), the
//! strip and the mortar weighting forced (`--weighting auto|strip|mortar`),
//! one row per level:
//!
//!   ring_study rings [--levels 128,256,512,1024] [--ratio 1.5] [--pieces 2]
//!                    [--delta 1e-3] [--coarse-outside] [--dump DIR]
//!       Two full rings (Lamé's a = 0.5, b = 1, c = 1.5, steel-like inner,
//!       half as stiff outer, plane strain) in a shrink fit, structured
//!       criss-cross polar meshes with every interface node on its circle;
//!       the inner ring's surface has N segments, the outer ring's bore
//!       ratio·N (the coarser ring inside for ratio > 1). The interface is
//!       cut into `pieces` pairs (1: one closed loop). Each ring is held by
//!       three rigid-motion constraints on its far surface (v at θ = 0 and
//!       π, u at θ = π/2), which carry nothing in the exact solution.
//!   ring_study gmsh-rings [--levels 32,64] [--ratio 1] [--delta 1e-3]
//!                    [--rot 0] [--narcs 4]
//!       The same rings meshed by Gmsh (examples/meshes/rings.geo): each
//!       interface circle made of `narcs` arcs, grouped into two
//!       half-circles = two pairs; `rot` turns the arcs' junctions.
//!   ring_study gmsh-hertz [--levels 16,32,64]
//!       A cylinder on a block (the Hertz scene's geometry, half model)
//!       meshed by Gmsh (examples/meshes/hertz.geo).
//!   ring_study loops
//!       A ring as ONE interface (closed loop), matching and 2:3, under both
//!       weightings: what is refused and with which message.
//!
//! Columns: ℓc/truth − 1; mean nodal pressure (`Model::contact_nodal_pressures`,
//! weighted by the polygon tributaries) against Lamé's pressure for the
//! meshed geometry (p of the polygons' mean radial overlap); min/max nodal
//! pressure over p, per side; the resultant contact force and moment on the
//! inner ring; the reactions of the rigid-motion constraints (largest body
//! resultant, over p·b and p·b²); the hoop stress error in the elements
//! touching a constrained node and in the layer along the interface; the
//! iterations, the time, the warnings.

use std::collections::{BTreeMap, BTreeSet};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use tfem::io::gmsh::read_msh;
use tfem::meshgen::MeshBuilder;
use tfem::scenes::hertz::Hertz;
use tfem::scenes::lame::{Lame, LameSolution};
use tfem::scenes::shrink_fit::{polygon_mean, polygon_mean_radius, radii, ring};
use tfem::{Component, ContactOptions, ContactWeighting, Material, Mesh, Model, PlaneMode};

const TAG_IN: i32 = 10; // inner ring's surface, piece k: 11 + k
const TAG_OUT: i32 = 20; // outer ring's bore, piece k: 21 + k

/// A ring scene ready to solve.
struct RingScene {
    model: Model,
    /// Interface nodes of the inner ring and of the outer ring, each sorted
    /// by angle (closed loops).
    inner: Vec<usize>,
    outer: Vec<usize>,
    /// Constrained nodes.
    supports: Vec<usize>,
    /// The closed form for circles, and the factor δ_eff/δ for the meshed
    /// polygons.
    exact: LameSolution,
    poly: f64,
    b: f64,
    b1: f64,
    /// Junction angles (pair ends and arc junctions), for the dump.
    junctions: Vec<f64>,
}

fn lame(delta: f64) -> Lame {
    Lame {
        interference: delta,
        ..Lame::default()
    }
}

fn materials(model: &mut Model) {
    let l = Lame::default();
    model
        .set_material(
            1,
            Material::new(l.e_inner, l.nu_inner, PlaneMode::Strain, "inner").unwrap(),
        )
        .unwrap();
    model
        .set_material(
            2,
            Material::new(l.e_outer, l.nu_outer, PlaneMode::Strain, "outer").unwrap(),
        )
        .unwrap();
}

/// The piece (0-based) of angle index j of n for `pieces` pieces.
fn piece(j: usize, n: usize, pieces: usize) -> i32 {
    // Edge (j, j+1) lies in piece floor(j·pieces/n).
    (j * pieces / n) as i32
}

fn structured(n_in: usize, n_out: usize, pieces: usize, delta: f64) -> Result<RingScene, String> {
    let l = lame(delta);
    let (a, b, c) = (l.inner_radius, l.radius, l.outer_radius);
    let b1 = b + delta;
    let mut mb = MeshBuilder::new();
    let gi = ring(&mut mb, &radii(a, b1, 2.0 * PI * b / n_in as f64), n_in, 1);
    let go = ring(&mut mb, &radii(b, c, 2.0 * PI * b / n_out as f64), n_out, 2);
    let (inner, outer) = (gi[gi.len() - 1].clone(), go[0].clone());
    let (mut edges, mut tags) = (Vec::new(), Vec::new());
    for (row, n, base) in [(&inner, n_in, TAG_IN), (&outer, n_out, TAG_OUT)] {
        for j in 0..n {
            edges.push([row[j], row[(j + 1) % n]]);
            tags.push(base + 1 + piece(j, n, pieces));
        }
    }
    let mut model = Model::new();
    model.set_mesh(mb.build().unwrap());
    model.set_boundary_edges(&edges, &tags).unwrap();
    materials(&mut model);
    let mut supports = Vec::new();
    for (row, n) in [(&gi[0], n_in), (&go[go.len() - 1], n_out)] {
        model.fix(row[0], Component::Y, 0.0).unwrap();
        model.fix(row[n / 2], Component::Y, 0.0).unwrap();
        model.fix(row[n / 4], Component::X, 0.0).unwrap();
        supports.extend([row[0], row[n / 2], row[n / 4]]);
    }
    for k in 0..pieces as i32 {
        model
            .add_contact_pair(TAG_IN + 1 + k, TAG_OUT + 1 + k)
            .map_err(|e| format!("add_contact_pair: {}", e.message()))?;
    }
    let d_eff = b1 * polygon_mean(n_in) - b * polygon_mean(n_out);
    Ok(RingScene {
        model,
        inner,
        outer,
        supports,
        exact: l.exact(),
        poly: d_eff / delta,
        b,
        b1,
        junctions: (0..pieces)
            .map(|k| 2.0 * PI * k as f64 / pieces as f64)
            .collect(),
    })
}

fn gmsh(geo: &str, out: &Path, numbers: &[(&str, f64)]) -> PathBuf {
    let geo = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/meshes")
        .join(geo);
    let mut cmd = Command::new("gmsh");
    cmd.args(["-2", "-format", "msh41", "-v", "2"]);
    for (k, v) in numbers {
        cmd.args(["-setnumber", k, &v.to_string()]);
    }
    let o = cmd.arg(&geo).arg("-o").arg(out).output().expect("gmsh");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out.to_path_buf()
}

fn tmp_dir() -> PathBuf {
    let d = std::env::temp_dir().join("ring_study");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Nodes of the edges tagged `tags`, sorted by angle.
fn tagged_nodes(mesh: &Mesh, tags: &[i32]) -> Vec<usize> {
    let set: BTreeSet<usize> = mesh
        .boundary_edges()
        .iter()
        .filter(|e| tags.contains(&e.tag))
        .flat_map(|e| e.nodes)
        .collect();
    let x = mesh.nodes();
    let mut v: Vec<usize> = set.into_iter().collect();
    v.sort_by(|&p, &q| x[p][1].atan2(x[p][0]).total_cmp(&x[q][1].atan2(x[q][0])));
    v
}

fn nearest(mesh: &Mesh, p: [f64; 2]) -> usize {
    let x = mesh.nodes();
    (0..x.len())
        .min_by(|&i, &j| {
            let d = |k: usize| (x[k][0] - p[0]).hypot(x[k][1] - p[1]);
            d(i).total_cmp(&d(j))
        })
        .unwrap()
}

fn gmsh_rings(h: f64, ratio: f64, delta: f64, rot: f64, narcs: usize) -> RingScene {
    let out = tmp_dir().join(format!("rings_{h}_{ratio}_{delta}_{rot}_{narcs}.msh"));
    gmsh(
        "rings.geo",
        &out,
        &[
            ("h", h),
            ("ratio", ratio),
            ("delta", delta),
            ("rot", rot),
            ("narcs", narcs as f64),
        ],
    );
    let mesh = read_msh(&out, 0).unwrap();
    let l = lame(delta);
    let (a, b, c) = (l.inner_radius, l.radius, l.outer_radius);
    let b1 = b + delta;
    let inner = tagged_nodes(&mesh, &[11, 12]);
    let outer = tagged_nodes(&mesh, &[21, 22]);
    let x = mesh.nodes().to_vec();
    let mut supports = Vec::new();
    let mut model = Model::new();
    for r in [a, c] {
        let s = [
            nearest(&mesh, [r, 0.0]),
            nearest(&mesh, [-r, 0.0]),
            nearest(&mesh, [0.0, r]),
        ];
        supports.extend(s);
    }
    model.set_mesh(mesh);
    materials(&mut model);
    for k in 0..2 {
        let s = &supports[3 * k..3 * k + 3];
        model.fix(s[0], Component::Y, 0.0).unwrap();
        model.fix(s[1], Component::Y, 0.0).unwrap();
        model.fix(s[2], Component::X, 0.0).unwrap();
    }
    model.add_contact_pair(11, 21).unwrap();
    model.add_contact_pair(12, 22).unwrap();
    let pts = |v: &[usize]| v.iter().map(|&k| x[k]).collect::<Vec<_>>();
    let d_eff = polygon_mean_radius(&pts(&inner)) - polygon_mean_radius(&pts(&outer));
    RingScene {
        model,
        inner,
        outer,
        supports,
        exact: l.exact(),
        poly: d_eff / delta,
        b,
        b1,
        junctions: (0..narcs)
            .map(|k| rot + 2.0 * PI * k as f64 / narcs as f64)
            .collect(),
    }
}

/// One level's measurements.
#[derive(Default)]
struct Row {
    lc: f64,
    mean: [f64; 2],
    min: [f64; 2],
    max: [f64; 2],
    slave_spread: [f64; 2],
    force_in: [f64; 3],
    reaction: f64,
    hoop_support: f64,
    hoop_interface: f64,
    iterations: usize,
    time: f64,
    warnings: Vec<String>,
    families: Option<[f64; 2]>,
}

fn hoop_exact(s: &RingScene, body: i32, r: f64) -> f64 {
    let ring = if body == 1 {
        &s.exact.inner
    } else {
        &s.exact.outer
    };
    ring.sigma_tt(r)
}

fn measure(
    s: &mut RingScene,
    weighting: ContactWeighting,
    dump: Option<&Path>,
) -> Result<Row, String> {
    s.model.set_contact_weighting(weighting).unwrap();
    let t = Instant::now();
    let report = s
        .model
        .solve_contact(&ContactOptions::default())
        .map_err(|e| e.message().to_string())?;
    let time = t.elapsed().as_secs_f64();
    let mesh = s.model.mesh().unwrap().clone();
    let x = mesh.nodes();
    let p = s.exact.pressure;
    let pn = s.model.contact_nodal_pressures().unwrap();
    let mut row = Row {
        lc: report.contact_length / (2.0 * PI * s.b) - 1.0,
        iterations: report.iterations,
        time,
        warnings: s.model.warnings(),
        ..Row::default()
    };
    let mut lines = Vec::new();
    for (k, (nodes, p_side)) in [(&s.inner, p * s.b / s.b1), (&s.outer, p)]
        .into_iter()
        .enumerate()
    {
        let n = nodes.len();
        let (mut sum, mut msum) = (0.0, 0.0);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..n {
            let (v, prev, next) = (nodes[i], nodes[(i + n - 1) % n], nodes[(i + 1) % n]);
            let d = |a: usize, b: usize| (x[a][0] - x[b][0]).hypot(x[a][1] - x[b][1]);
            let m = 0.5 * (d(v, prev) + d(v, next));
            sum += pn[v] * m;
            msum += m;
            lo = lo.min(pn[v] / p_side);
            hi = hi.max(pn[v] / p_side);
            lines.push(format!(
                "{k} {:.9} {:.6e}",
                x[v][1].atan2(x[v][0]),
                pn[v] / p_side
            ));
        }
        row.mean[k] = sum / msum / p_side - 1.0;
        row.min[k] = lo;
        row.max[k] = hi;
    }
    if let Some(dir) = dump {
        std::fs::write(dir, lines.join("\n")).unwrap();
    }
    if s.model.contact_slave_nodes().is_ok() {
        // The slave nodes' own −κG/m, per side.
        let inner: BTreeSet<usize> = s.inner.iter().copied().collect();
        let mut spread = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
        if let Some(d) = dump {
            let text: Vec<String> = s
                .model
                .contact_slave_nodes()
                .unwrap()
                .iter()
                .map(|sn| {
                    format!(
                        "{} {} {:.9} {:.6e} {:.6e} {}",
                        sn.pair,
                        sn.node,
                        x[sn.node][1].atan2(x[sn.node][0]),
                        sn.tributary,
                        sn.pressure / p,
                        sn.active
                    )
                })
                .collect();
            std::fs::write(d.with_extension("slaves"), text.join("\n")).unwrap();
        }
        let mut sides = BTreeMap::new();
        for sn in s.model.contact_slave_nodes().unwrap() {
            sides.insert(
                sn.pair,
                if inner.contains(&sn.node) {
                    "inner"
                } else {
                    "outer"
                },
            );
        }
        eprintln!("slave sides by pair: {sides:?}");
        for sn in s.model.contact_slave_nodes().unwrap() {
            let k = usize::from(!inner.contains(&sn.node));
            let ps = if k == 0 { p * s.b / s.b1 } else { p };
            spread[k][0] = spread[k][0].min(sn.pressure / ps);
            spread[k][1] = spread[k][1].max(sn.pressure / ps);
        }
        row.slave_spread = [
            (spread[0][1] - spread[0][0]) * 0.5,
            (spread[1][1] - spread[1][0]) * 0.5,
        ];
    } else {
        let inner: BTreeSet<usize> = s.inner.iter().copied().collect();
        let els = s.model.contact_elements().unwrap();
        let act = s.model.contact_active().unwrap();
        let mut fam = [0.0; 2];
        for (e, &on) in els.iter().zip(act) {
            if on {
                let edge_inner = e
                    .nodes
                    .iter()
                    .filter(|&&v| v != e.apex)
                    .all(|v| inner.contains(v));
                fam[usize::from(!edge_inner)] += e.facing;
            }
        }
        row.families = Some(fam.map(|f| f / (2.0 * PI * s.b)));
    }
    let body = mesh.node_body();
    let f = s.model.contact_forces().unwrap();
    for (v, fv) in f.iter().enumerate() {
        if body[v] == Some(1) {
            row.force_in[0] += fv[0];
            row.force_in[1] += fv[1];
            row.force_in[2] += x[v][0] * fv[1] - x[v][1] * fv[0];
        }
    }
    let pb = p * s.b;
    row.force_in = [
        row.force_in[0] / pb,
        row.force_in[1] / pb,
        row.force_in[2] / (pb * s.b),
    ];
    let r = s.model.reactions().unwrap();
    for bd in [1, 2] {
        let mut res = [0.0; 3];
        for &v in &s.supports {
            if body[v] == Some(bd) {
                res[0] += r[v][0];
                res[1] += r[v][1];
                res[2] += x[v][0] * r[v][1] - x[v][1] * r[v][0];
            }
        }
        let m = (res[0].hypot(res[1]) / pb).max(res[2].abs() / (pb * s.b));
        row.reaction = row.reaction.max(m);
        // Also the largest single reaction.
        for &v in &s.supports {
            row.reaction = row.reaction.max(r[v][0].hypot(r[v][1]) / pb);
        }
    }
    let sig = s.model.element_stresses().unwrap();
    let supports: BTreeSet<usize> = s.supports.iter().copied().collect();
    let iface: BTreeSet<usize> = s.inner.iter().chain(&s.outer).copied().collect();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        let c = [
            (x[tri[0]][0] + x[tri[1]][0] + x[tri[2]][0]) / 3.0,
            (x[tri[0]][1] + x[tri[1]][1] + x[tri[2]][1]) / 3.0,
        ];
        let (r, th) = (c[0].hypot(c[1]), c[1].atan2(c[0]));
        let (cs, sn) = (th.cos(), th.sin());
        let st = sig[t][0] * sn * sn + sig[t][1] * cs * cs - 2.0 * sig[t][2] * sn * cs;
        let err = (st - hoop_exact(s, mesh.body_of()[t], r)).abs() / p;
        if tri.iter().any(|v| supports.contains(v)) {
            row.hoop_support = row.hoop_support.max(err);
        }
        if tri.iter().any(|v| iface.contains(v)) {
            row.hoop_interface = row.hoop_interface.max(err);
        }
    }
    Ok(row)
}

fn header() {
    println!(
        "| level | weighting | it | time s | ℓc/2πb−1 | mean in | mean out | min..max in | min..max out | slave ±spread in/out or families a/b | F_in (x, y, M) /pb | max reaction /pb | hoop err @supports | hoop err @interface | warnings |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
}

fn print(level: &str, w: ContactWeighting, r: &Result<Row, String>) {
    let w = if w == ContactWeighting::Strip {
        "strip"
    } else {
        "mortar"
    };
    match r {
        Err(e) => println!("| {level} | {w} | refused: {e} |"),
        Ok(r) => {
            let extra = match r.families {
                Some(f) => format!("fam in {:.4}, out {:.4}", f[0], f[1]),
                None => format!(
                    "slave ±{:.2e}",
                    r.slave_spread[0].max(r.slave_spread[1]).max(0.0)
                ),
            };
            let warn = match r.warnings.first() {
                Some(s) => format!(
                    "{}: {}",
                    r.warnings.len(),
                    s.chars().take(70).collect::<String>()
                ),
                None => "0".into(),
            };
            println!(
                "| {level} | {w} | {} | {:.1} | {:+.3e} | {:+.2e} | {:+.2e} | {:.3}..{:.3} | {:.3}..{:.3} | {extra} | {:.1e}, {:.1e}, {:.1e} | {:.2e} | {:.2e} | {:.2e} | {warn} |",
                r.iterations,
                r.time,
                r.lc,
                r.mean[0],
                r.mean[1],
                r.min[0],
                r.max[0],
                r.min[1],
                r.max[1],
                r.force_in[0],
                r.force_in[1],
                r.force_in[2],
                r.reaction,
                r.hoop_support,
                r.hoop_interface
            );
        }
    }
}

fn weightings(arg: &str) -> Vec<ContactWeighting> {
    match arg {
        "strip" => vec![ContactWeighting::Strip],
        "mortar" => vec![ContactWeighting::Mortar],
        "auto" => vec![ContactWeighting::Auto],
        _ => vec![
            ContactWeighting::Auto,
            ContactWeighting::Strip,
            ContactWeighting::Mortar,
        ],
    }
}

fn junction_dump(s: &RingScene, path: &Path) {
    // The junction angles, appended to the dump.
    let mut text = std::fs::read_to_string(path).unwrap_or_default();
    for j in &s.junctions {
        text.push_str(&format!("\n# junction {j:.9}"));
    }
    std::fs::write(path, text).unwrap();
}

fn hertz(levels: &[usize], ws: &[ContactWeighting]) {
    let hz = Hertz::default();
    let (a, load) = (hz.half_width, hz.load());
    let p0 = 2.0 * load / (PI * a);
    println!(
        "| a/h | weighting | it | time s | ℓc/a−1 | families block/cyl (/a) | p(0)/p0−1 | max err in 0.8a /p0 | warnings |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for &lv in levels {
        let h = a / lv as f64;
        let out = tmp_dir().join(format!("hertz_{lv}.msh"));
        gmsh("hertz.geo", &out, &[("h", h), ("a", a)]);
        for &w in ws {
            let mesh = read_msh(&out, 0).unwrap();
            let x = mesh.nodes().to_vec();
            let top = tagged_nodes(&mesh, &[2]);
            let cyl: BTreeSet<usize> = tagged_nodes(&mesh, &[3]).into_iter().collect();
            let mut model = Model::new();
            model.set_mesh(mesh);
            for (b, e, nu) in [
                (1, hz.e_block, hz.nu_block),
                (2, hz.e_cylinder, hz.nu_cylinder),
            ] {
                model
                    .set_material(b, Material::new(e, nu, PlaneMode::Strain, "b").unwrap())
                    .unwrap();
            }
            model.fix_edges(5, Component::X, 0.0).unwrap();
            model.fix_edges(1, Component::Y, 0.0).unwrap();
            model
                .add_pressure(4, 0.5 * load / (0.8 * hz.radius))
                .unwrap();
            model.add_contact_pair(2, 3).unwrap();
            model.set_contact_weighting(w).unwrap();
            let t = Instant::now();
            let rep = match model.solve_contact(&ContactOptions::default()) {
                Ok(r) => r,
                Err(e) => {
                    println!("| {lv} | {w:?} | failed: {} |", e.message());
                    continue;
                }
            };
            let time = t.elapsed().as_secs_f64();
            let pn = model.contact_nodal_pressures().unwrap();
            let axis = top.iter().copied().find(|&v| x[v][0] == 0.0).unwrap();
            let err = top
                .iter()
                .filter(|&&v| x[v][0] <= 0.8 * a)
                .map(|&v| (pn[v] - p0 * (1.0 - (x[v][0] / a).powi(2)).sqrt()).abs() / p0)
                .fold(0.0, f64::max);
            let fam = if model.contact_slave_nodes().is_err() {
                let els = model.contact_elements().unwrap();
                let act = model.contact_active().unwrap();
                let mut f = [0.0; 2];
                for (e, &on) in els.iter().zip(act) {
                    if on {
                        let on_cyl = e
                            .nodes
                            .iter()
                            .filter(|&&v| v != e.apex)
                            .all(|v| cyl.contains(v));
                        f[usize::from(on_cyl)] += e.facing;
                    }
                }
                format!("{:.4} / {:.4}", f[0] / a, f[1] / a)
            } else {
                "-".into()
            };
            let warn = model.warnings();
            println!(
                "| {lv} | {w:?} | {} | {time:.1} | {:+.3e} | {fam} | {:+.3e} | {:.2e} | {} |",
                rep.iterations,
                rep.contact_length / a - 1.0,
                pn[axis] / p0 - 1.0,
                err,
                warn.first().map_or("0".into(), |s| format!(
                    "{}: {}",
                    warn.len(),
                    s.chars().take(60).collect::<String>()
                ))
            );
        }
    }
}

fn loops() {
    println!("| case | weighting | outcome |");
    println!("|---|---|---|");
    for (label, n_in, n_out) in [("matching 64/64", 64, 64), ("2:3 64/96", 64, 96)] {
        for w in weightings("both") {
            let r = structured(n_in, n_out, 1, 1e-3).and_then(|mut s| measure(&mut s, w, None));
            let out = match r {
                Ok(r) => format!(
                    "solved: ℓc/2πb−1 {:+.2e}, mean out {:+.2e}, it {}",
                    r.lc, r.mean[1], r.iterations
                ),
                Err(e) => format!("refused: {e}"),
            };
            println!("| {label} | {w:?} | {out} |");
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mode = args
        .first()
        .map(String::as_str)
        .unwrap_or("rings")
        .to_string();
    let get = |k: &str| {
        args.iter()
            .position(|a| a == k)
            .map(|i| args[i + 1].clone())
    };
    let levels: Vec<usize> = get("--levels")
        .map(|s| s.split(',').map(|v| v.parse().unwrap()).collect())
        .unwrap_or_else(|| match mode.as_str() {
            "rings" => vec![128, 256, 512, 1024],
            "gmsh-rings" => vec![32, 64],
            _ => vec![16, 32, 64],
        });
    let ws = weightings(&get("--weighting").unwrap_or_else(|| "both".into()));
    let delta: f64 = get("--delta").map_or(1e-3, |v| v.parse().unwrap());
    let dump = get("--dump").map(PathBuf::from);
    match mode.as_str() {
        "rings" => {
            let ratio: f64 = get("--ratio").map_or(1.5, |v| v.parse().unwrap());
            let pieces: usize = get("--pieces").map_or(2, |v| v.parse().unwrap());
            let coarse_outside = args.iter().any(|a| a == "--coarse-outside");
            header();
            for &n in &levels {
                let m = (n as f64 * ratio).round() as usize;
                let (n_in, n_out) = if coarse_outside { (m, n) } else { (n, m) };
                for &w in &ws {
                    let mut s = match structured(n_in, n_out, pieces, delta) {
                        Ok(s) => s,
                        Err(e) => {
                            print(&format!("{n_in}/{n_out}"), w, &Err(e));
                            continue;
                        }
                    };
                    let d = dump
                        .as_ref()
                        .map(|d| d.join(format!("rings_{n_in}_{n_out}_{w:?}.txt")));
                    if let Some(d) = &dump {
                        std::fs::create_dir_all(d).unwrap();
                    }
                    let r = measure(&mut s, w, d.as_deref());
                    print(&format!("{n_in}/{n_out} (p_poly/p {:.5})", s.poly), w, &r);
                    if let Some(d) = &d {
                        junction_dump(&s, d);
                    }
                }
            }
        }
        "gmsh-rings" => {
            let ratio: f64 = get("--ratio").map_or(1.0, |v| v.parse().unwrap());
            let rot: f64 = get("--rot").map_or(0.0, |v| v.parse().unwrap());
            let narcs: usize = get("--narcs").map_or(4, |v| v.parse().unwrap());
            header();
            for &lv in &levels {
                for &w in &ws {
                    let mut s = gmsh_rings(1.0 / lv as f64, ratio, delta, rot, narcs);
                    let d = dump
                        .as_ref()
                        .map(|d| d.join(format!("gmsh_{lv}_{w:?}_{rot}.txt")));
                    if let Some(d) = &dump {
                        std::fs::create_dir_all(d).unwrap();
                    }
                    let r = measure(&mut s, w, d.as_deref());
                    let label = format!(
                        "b/{lv} ({}/{} nodes, p_poly/p {:.5})",
                        s.inner.len(),
                        s.outer.len(),
                        s.poly
                    );
                    print(&label, w, &r);
                    if let Some(d) = &d {
                        junction_dump(&s, d);
                    }
                }
            }
        }
        "gmsh-hertz" => hertz(&levels, &ws),
        "loops" => loops(),
        "gaps" => {
            // The initial weighted gaps G_i/m_i of each pair's slave nodes
            // (geometry only), on the Gmsh rings.
            let ratio: f64 = get("--ratio").map_or(1.0, |v| v.parse().unwrap());
            let rot: f64 = get("--rot").map_or(0.0, |v| v.parse().unwrap());
            let narcs: usize = get("--narcs").map_or(4, |v| v.parse().unwrap());
            for &lv in &levels {
                let s = gmsh_rings(1.0 / lv as f64, ratio, delta, rot, narcs);
                let mesh = s.model.mesh().unwrap();
                let x = mesh.nodes();
                use tfem::contact::mesh::{Nodes, Side};
                use tfem::contact::mortar::{Basis, coarser_side, weighted_gaps};
                for (pair, (ta, tb)) in [(11, 21), (12, 22)].into_iter().enumerate() {
                    let (a, b) = (
                        Side::of_tag(mesh, ta).unwrap(),
                        Side::of_tag(mesh, tb).unwrap(),
                    );
                    let slave = coarser_side(Nodes::of(mesh), &a, &b).unwrap();
                    for basis in [Basis::Dual, Basis::Standard] {
                        let g = weighted_gaps(Nodes::of(mesh), &a, &b, slave, basis).unwrap();
                        for wg in &g {
                            let t = x[wg.node][1].atan2(x[wg.node][0]);
                            println!(
                                "{pair} {basis:?} {slave:?} {} {t:.6} {:.6e} {:.6e}",
                                wg.node,
                                wg.tributary,
                                wg.initial / wg.tributary / delta
                            );
                        }
                    }
                }
            }
        }
        other => panic!("unknown mode {other}"),
    }
    let _ = BTreeMap::<usize, usize>::new();
}
