//! Speed and scaling: contact solves, faer alone and the orderings, each in its own process.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use serde_json::Value;

use tfem::scenes::TwoBlocks;
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, Ordering};

use crate::Args;
use crate::common::peak_rss;

/// A proportional history of `steps` load steps of the seed scene (factors
/// k/steps), its last step's displacements recovered, timed as a whole.
fn history_run(model: &mut tfem::Model, mode: &str, rss_mesh: Option<f64>) -> ! {
    // "N": N steps, the field read after the last; "N-read": after each.
    let (steps, read_each) = match mode.strip_suffix("-read") {
        Some(n) => (n, true),
        None => (mode, false),
    };
    let steps: usize = steps.parse().expect("a step count");
    let options = ContactOptions::default();
    let t0 = Instant::now();
    let (mut factorizations, mut iterations) = (0, 0);
    for k in 1..=steps {
        let r = model
            .step(k as f64 / steps as f64, &options)
            .expect("a load step");
        factorizations += r.info.factorizations;
        iterations += r.iterations;
        if read_each {
            model.displacements().expect("the step's field");
        }
    }
    let stepping = t0.elapsed().as_secs_f64();
    let u = model.displacements().expect("the last step's field");
    let total = t0.elapsed().as_secs_f64();
    println!(
        "{}",
        serde_json::json!({
            "steps": steps, "total": total, "stepping": stepping, "recovery": total - stepping,
            "factorizations": factorizations, "iterations": iterations,
            "u_checksum": u.iter().flatten().sum::<f64>(),
            "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

/// One contact solve of the seed scene in a fresh process (so that its
/// peak memory is its own): `report --speed-run N ORDERING MODE` prints one
/// JSON line. ORDERING: `nd`, `amd` or `nd-one-tree`; MODE: `condensed`
/// (the default loop), `refactorize`, `single` (its first iteration
/// only), `mortar`, `historyN` or `mortar-historyN` (N proportional load
/// steps).
pub(crate) fn speed_run(n: usize, ordering: &str, mode: &str) -> ! {
    let rss0 = peak_rss();
    let mut s = TwoBlocks {
        mesh_size: 1.0 / n as f64,
        ..Default::default()
    }
    .build()
    .expect("scene");
    let rss_mesh = peak_rss();
    s.model.set_ordering(match ordering {
        "amd" => Ordering::Amd,
        _ => Ordering::NestedDissection,
    });
    // "nd-one-tree": nested dissection factorised as one tree.
    s.model.set_parallel_subtrees(ordering != "nd-one-tree");
    // "single": the first iteration only (one assembly, factorisation and
    // solve of the seed scene's matrix with the initial contact set), whose
    // peak memory is what a factorisation + solve of that matrix takes in
    // this library; the solve then stops short of convergence.
    if let Some(steps) = mode.strip_prefix("history") {
        history_run(&mut s.model, steps, rss_mesh);
    }
    // "mortar-historyN": the same history under the mortar weighting.
    if let Some(steps) = mode.strip_prefix("mortar-history") {
        s.model
            .set_contact_weighting(tfem::ContactWeighting::Mortar)
            .expect("a frictionless scene");
        history_run(&mut s.model, steps, rss_mesh);
    }
    let single = mode == "single";
    // "mortar": the condensed loop under the mortar weighting.
    if mode == "mortar" {
        s.model
            .set_contact_weighting(tfem::ContactWeighting::Mortar)
            .expect("a frictionless scene");
    }
    let mut options = ContactOptions {
        refactorize: !matches!(mode, "condensed" | "mortar"),
        ..Default::default()
    };
    if single {
        options.max_iterations = 1;
    }
    let t0 = Instant::now();
    let r = s.model.solve_contact(&options);
    let total = t0.elapsed().as_secs_f64();
    if single {
        let status = r.as_ref().map_or_else(|e| e.status().name(), |_| "ok");
        println!(
            "{}",
            serde_json::json!({
                "status": status, "total": total, "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
            })
        );
        std::process::exit(0)
    }
    let r = r.expect("contact solve");
    let i = r.info;
    let t = i.timings;
    println!(
        "{}",
        serde_json::json!({
            "unknowns": i.unknowns, "interface": i.interface_unknowns, "factor_nnz": i.factor_nnz,
            "matrix_nnz": i.matrix_nnz, "factorization_bytes": i.factorization_bytes,
            "allocated": i.memory_bytes, "analysis": t.analysis, "assembly": t.assembly,
            "factorization": t.factorization, "solve": t.solve, "dense": t.interface, "total": total,
            "iterations": r.iterations, "factorizations": i.factorizations,
            "rss_start": rss0, "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

/// `report --export-matrix N FILE`: solves the seed scene (default options)
/// and writes the matrix of its converged system with a nested-dissection
/// permutation of it, for [`faer_alone`]. Little-endian: n, nnz (u64), the
/// column pointers and row indices (u64), the values (f64), the permutation
/// (u64, `perm[new] = old`).
pub(crate) fn export_matrix(n: usize, file: &Path) -> ! {
    let mut s = TwoBlocks {
        mesh_size: 1.0 / n as f64,
        ..Default::default()
    }
    .build()
    .expect("scene");
    s.model
        .solve_contact(&ContactOptions::default())
        .expect("contact solve");
    let k = s.model.system_matrix().expect("the converged matrix");
    // tfem's pattern also holds the inactive contact elements, as stored
    // zeros; the matrix handed over has only its nonzeros (and diagonal), so
    // that faer's factor is not inflated by them.
    let (mut col_ptr, mut row_idx, mut values) = (vec![0], Vec::new(), Vec::new());
    for (j, w) in k.col_ptr.windows(2).enumerate() {
        for p in w[0]..w[1] {
            if k.values[p] != 0.0 || k.row_idx[p] == j {
                row_idx.push(k.row_idx[p]);
                values.push(k.values[p]);
            }
        }
        col_ptr.push(row_idx.len());
    }
    let nodes = s.model.mesh().expect("mesh").nodes();
    let coords: Vec<[f64; 2]> = k.unknowns.iter().map(|&g| nodes[g / 2]).collect();
    let perm = tfem::ordering::nested_dissection(&col_ptr, &row_idx, &coords);
    let mut w = std::io::BufWriter::new(std::fs::File::create(file).expect("matrix file"));
    let words = [k.n(), values.len()].into_iter().chain(col_ptr);
    for x in words.chain(row_idx).map(|x| x as u64) {
        std::io::Write::write_all(&mut w, &x.to_le_bytes()).expect("write");
    }
    for x in values {
        std::io::Write::write_all(&mut w, &x.to_le_bytes()).expect("write");
    }
    for &x in &perm {
        std::io::Write::write_all(&mut w, &(x as u64).to_le_bytes()).expect("write");
    }
    std::io::Write::flush(&mut w).expect("write");
    std::process::exit(0)
}

/// Reads `len` little-endian 8-byte words, 1 MiB at a time so that reading
/// costs no more memory than the result.
fn read_words<T>(r: &mut impl std::io::Read, len: usize, from: fn([u8; 8]) -> T) -> Vec<T> {
    let mut out = Vec::with_capacity(len);
    let mut buf = vec![0u8; 1 << 20];
    while out.len() < len {
        let m = (len - out.len()).min(buf.len() / 8);
        r.read_exact(&mut buf[..8 * m]).expect("matrix file");
        out.extend(
            buf[..8 * m]
                .chunks_exact(8)
                .map(|c| from(c.try_into().unwrap())),
        );
    }
    out
}

/// `report --faer-alone FILE`: the baseline of "the factorisation alone" —
/// a process that holds the matrix of [`export_matrix`] and nothing else,
/// and runs faer's supernodal Cholesky on it with the given
/// nested-dissection permutation (symbolic analysis with the factor's
/// storage, one numeric factorisation, one solve). Prints its times and
/// peak memory as JSON.
pub(crate) fn faer_alone(file: &Path) -> ! {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::cholesky::llt::factor::LltRegularization;
    use faer::perm::PermRef;
    use faer::sparse::linalg::cholesky::{
        CholeskySymbolicParams, LltRef, SymmetricOrdering, factorize_symbolic_cholesky,
    };
    use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
    use faer::{Conj, MatMut, Par, Side};

    let mut r = std::io::BufReader::new(std::fs::File::open(file).expect("matrix file"));
    let u64le = |b: [u8; 8]| u64::from_le_bytes(b) as usize;
    let head = read_words(&mut r, 2, u64le);
    let (n, nnz) = (head[0], head[1]);
    let col_ptr = read_words(&mut r, n + 1, u64le);
    let row_idx = read_words(&mut r, nnz, u64le);
    let values = read_words(&mut r, nnz, f64::from_le_bytes);
    let perm = read_words(&mut r, n, u64le);
    drop(r);
    let mut inv = vec![0usize; n];
    for (new, &old) in perm.iter().enumerate() {
        inv[old] = new;
    }
    let rss_matrix = peak_rss();

    let t0 = Instant::now();
    let sym = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
    let ord = SymmetricOrdering::Custom(PermRef::new_checked(&perm, &inv, n));
    let symbolic =
        factorize_symbolic_cholesky(sym, Side::Upper, ord, CholeskySymbolicParams::default())
            .expect("symbolic");
    // The factor's storage is allocated and its pages written in the
    // analysis, as tfem does: otherwise the first-touch page faults (~900 MB
    // at 1M unknowns) would be timed as factorisation here and as analysis
    // there.
    let mut l_values = Vec::with_capacity(symbolic.len_val());
    l_values.resize(symbolic.len_val(), 0.0);
    let analysis = t0.elapsed().as_secs_f64();
    let par = Par::rayon(0);
    let t0 = Instant::now();
    let mut mem =
        MemBuffer::new(symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()));
    let a = SparseColMatRef::new(sym, &values);
    symbolic
        .factorize_numeric_llt(
            &mut l_values,
            a,
            Side::Upper,
            LltRegularization::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .expect("positive definite");
    drop(mem);
    let factorization = t0.elapsed().as_secs_f64();
    let t0 = Instant::now();
    let mut x = vec![1.0; n];
    let mut mem = MemBuffer::new(symbolic.solve_in_place_scratch::<f64>(1, par));
    LltRef::new(&symbolic, &l_values).solve_in_place_with_conj(
        Conj::No,
        MatMut::from_column_major_slice_mut(&mut x, n, 1),
        par,
        MemStack::new(&mut mem),
    );
    let solve = t0.elapsed().as_secs_f64();
    assert!(
        x.iter().all(|v| v.is_finite()),
        "faer's solve is not finite"
    );
    println!(
        "{}",
        serde_json::json!({
            "unknowns": n, "matrix_nnz": nnz, "factor_nnz": symbolic.len_val(),
            "analysis": analysis, "factorization": factorization, "solve": solve,
            "rss_matrix": rss_matrix, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

/// The seed scene's converged matrix at h = 1/n through [`export_matrix`]
/// and [`faer_alone`], each in its own process; the file is removed.
fn faer_child(n: usize) -> Option<Value> {
    let exe = std::env::current_exe().ok()?;
    let file =
        std::env::temp_dir().join(format!("tfem-report-matrix-{}-{n}.bin", std::process::id()));
    let file_arg = file.to_str()?;
    let exported = std::process::Command::new(&exe)
        .args(["--export-matrix", &n.to_string(), file_arg])
        .status()
        .ok()?
        .success();
    let out = exported
        .then(|| {
            std::process::Command::new(&exe)
                .args(["--faer-alone", file_arg])
                .output()
                .ok()
        })
        .flatten();
    let _ = std::fs::remove_file(&file);
    let text = String::from_utf8_lossy(&out?.stdout).into_owned();
    serde_json::from_str(text.lines().last()?).ok()
}

pub(crate) fn child(n: usize, ordering: &str, mode: &str) -> Option<Value> {
    let out = std::process::Command::new(std::env::current_exe().ok()?)
        .args(["--speed-run", &n.to_string(), ordering, mode])
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.lines().last()?).ok()
}

pub(crate) fn speed(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![64, 128]
    } else {
        vec![128, 256, 512, 1024, 1448]
    };
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    writeln!(report, "## Speed and scaling\n").unwrap();
    writeln!(
        report,
        "Seed scene, 2C/L = 0.2, nested-dissection ordering; each run in its own process (peak \
         memory = that process's VmHWM). *fact.+solve*: one numeric factorisation with its \
         singularity check (three inverse-iteration solves) plus one solve, from the refactorising \
         loop (its mean per iteration). *condensed*: the default loop (one factorisation with the \
         interface numbered last, dense interface updates, final recovery and refinement). \
         *ratio*: condensed loop without the symbolic analysis (paid once per mesh, kept across \
         solves) over fact.+solve; *ratio incl.*: with it. *factorisation [MB]*: what one numeric \
         factorisation needs at its peak — factor values, symbolic structure and faer's workspace \
         (`SolveInfo::factorization_bytes`); *matrix*: the CSC matrix it reads (pattern and values). \
         *peak / fact.*: the condensed solve's peak RSS (mesh, model, matrix, factor, interface, \
         results, allocator) over the factorisation; *peak / (fact. + matrix)*: over the \
         factorisation with its input; *fact.+solve peak*: the peak RSS of a process that builds \
         the same scene and runs only the first iteration (one assembly, one factorisation + solve \
         of the matrix with the initial contact set, no interface), i.e. what one factorisation + \
         solve of that matrix takes in this library; *peak / fact.+solve peak*: the whole contact \
         solve's peak over it.\n"
    )
    .unwrap();
    writeln!(report, "| h | unknowns | interface unknowns | iterations | analysis [s] | fact.+solve [s] | refactorising loop [s] | condensed loop [s] | ratio | ratio incl. | dense interface [s] | assembly / fact. | factorisation [MB] | matrix [MB] | peak RSS [MB] | peak / fact. | peak / (fact. + matrix) | fact.+solve peak [MB] | peak / fact.+solve peak |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut scaling: Vec<(f64, f64, f64)> = Vec::new();
    let mut orderings = Vec::new();
    let mut against_faer = Vec::new();
    let mut mortar = Vec::new();
    for &n in &levels {
        let (Some(full), Some(cond)) = (child(n, "nd", "refactorize"), child(n, "nd", "condensed"))
        else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        let per = (f(&full, "factorization") + f(&full, "solve")) / f(&full, "factorizations");
        let factorization = f(&cond, "factorization_bytes");
        let matrix = 8.0 * (f(&cond, "unknowns") + 1.0 + 2.0 * f(&cond, "matrix_nnz"));
        let peak = f(&cond, "rss_peak");
        // Only a run that got through its one iteration is a baseline (it
        // stops with "not converged", or "ok" if one iteration settled).
        let single_peak = child(n, "nd", "single")
            .filter(|v| matches!(v["status"].as_str(), Some("not converged" | "ok")))
            .map_or(f64::NAN, |v| f(&v, "rss_peak"));
        writeln!(
            report,
            "| 1/{n} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.3} | {:.0} | {:.0} | {:.0} | {:.2} | {:.2} | {:.0} | {:.2} |",
            cond["unknowns"],
            cond["interface"],
            cond["iterations"],
            f(&cond, "analysis"),
            per,
            f(&full, "total"),
            f(&cond, "total"),
            (f(&cond, "total") - f(&cond, "analysis")) / per,
            f(&cond, "total") / per,
            f(&cond, "dense"),
            f(&cond, "assembly") / f(&cond, "factorization"),
            factorization / 1e6,
            matrix / 1e6,
            peak / 1e6,
            peak / factorization,
            peak / (factorization + matrix),
            single_peak / 1e6,
            peak / single_peak,
        )
        .unwrap();
        scaling.push((f(&cond, "unknowns"), f(&cond, "total"), peak));
        mortar.push((n, child(n, "nd", "mortar"), cond.clone()));
        against_faer.push((n, faer_child(n), cond.clone()));
        if let (Some(amd), Some(one)) = (
            child(n, "amd", "condensed"),
            child(n, "nd-one-tree", "condensed"),
        ) {
            orderings.push((n, amd, one, cond));
        }
    }
    if scaling.len() >= 2 {
        let d: Vec<f64> = scaling.iter().map(|s| s.0).collect();
        let t: Vec<f64> = scaling.iter().map(|s| s.1).collect();
        let m: Vec<f64> = scaling.iter().map(|s| s.2).collect();
        writeln!(
            report,
            "\nFitted exponents against unknowns (condensed contact solve): time ∝ N^{:.2}, peak memory ∝ N^{:.2}.\n",
            fitted_rate(&d, &t),
            fitted_rate(&d, &m)
        )
        .unwrap();
    }
    writeln!(
        report,
        "### Under the mortar weighting\n\nThe same scene and loop under \
         `ContactWeighting::Mortar` (one weighted gap per node of the coarser side; on this \
         matching interface it gives the strip's numbers), each in its own process, against the \
         strip's condensed loop of the table above.\n\n\
         | h | unknowns | interface unknowns | iterations | mortar [s] | strip [s] | time ratio | mortar peak RSS [MB] | strip peak RSS [MB] | memory ratio |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (n, m, cond) in &mortar {
        let Some(m) = m else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        writeln!(
            report,
            "| 1/{n} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {:.0} | {:.0} | {:.2} |",
            m["unknowns"],
            m["interface"],
            m["iterations"],
            f(m, "total"),
            f(cond, "total"),
            f(m, "total") / f(cond, "total"),
            f(m, "rss_peak") / 1e6,
            f(cond, "rss_peak") / 1e6,
            f(m, "rss_peak") / f(cond, "rss_peak"),
        )
        .unwrap();
    }
    writeln!(
        report,
        "\n### Against faer alone\n\nThe factorisation alone, measured: a process that reads the \
         converged matrix of the same scene (written by another process; its nonzeros, without \
         the inactive contact elements' stored zeros) with a nested-dissection permutation of \
         it, holds nothing else, and runs faer's supernodal Cholesky once (symbolic analysis, which \
         also allocates and writes the factor's storage as tfem's does; numeric factorisation; \
         one solve; `report --faer-alone`). Its peak \
         RSS includes the matrix it reads. Against it, the whole condensed contact solve of the \
         table above (its own process: mesh, model, every iteration, results). *time ratio*: the \
         contact solve without its symbolic analysis over faer's factorisation + solve; *incl.*: \
         both with their analyses.\n\n\
         | h | unknowns | faer factor nnz | faer analysis [s] | faer factorisation [s] | faer solve [s] | faer peak RSS [MB] | contact solve [s] | contact peak RSS [MB] | time ratio | time ratio incl. | memory ratio |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (n, alone, cond) in &against_faer {
        let Some(alone) = alone else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        let fact_solve = f(alone, "factorization") + f(alone, "solve");
        writeln!(
            report,
            "| 1/{n} | {} | {:.3e} | {:.2} | {:.2} | {:.2} | {:.0} | {:.2} | {:.0} | {:.2} | {:.2} | {:.2} |",
            alone["unknowns"],
            f(alone, "factor_nnz"),
            f(alone, "analysis"),
            f(alone, "factorization"),
            f(alone, "solve"),
            f(alone, "rss_peak") / 1e6,
            f(cond, "total"),
            f(cond, "rss_peak") / 1e6,
            (f(cond, "total") - f(cond, "analysis")) / fact_solve,
            f(cond, "total") / (f(alone, "analysis") + fact_solve),
            f(cond, "rss_peak") / f(alone, "rss_peak"),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
    writeln!(
        report,
        "### Orderings\n\nThe one factorisation (with its singularity check) of the condensed loop, \
         each in its own process, with the interface numbered last: faer's AMD on the whole \
         matrix; geometric nested dissection factorised by faer as one tree (*ND, one tree*: \
         parallel only inside dense blocks); and nested dissection as tfem runs it by default, \
         the two bodies (the subtrees below the interface) factorised concurrently and the \
         interface as a dense block (*ND*; `Model::set_parallel_subtrees`).\n\n\
         | h | unknowns | factor nnz AMD | factor nnz ND, one tree | factor nnz ND | factorisation AMD [s] | ND, one tree [s] | ND [s] | AMD / ND, one tree | AMD / ND |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (n, amd, one, nd) in &orderings {
        writeln!(
            report,
            "| 1/{n} | {} | {:.3e} | {:.3e} | {:.3e} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
            nd["unknowns"],
            f(amd, "factor_nnz"),
            f(one, "factor_nnz"),
            f(nd, "factor_nnz"),
            f(amd, "factorization"),
            f(one, "factorization"),
            f(nd, "factorization"),
            f(amd, "factorization") / f(one, "factorization"),
            f(amd, "factorization") / f(nd, "factorization"),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}
