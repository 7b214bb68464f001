//! The TFEM paper's locking study: manufactured solutions on the unit square
//! whose mesh contains a band of flattened triangles (caps of height 1e-9
//! along y = 1/2). Plain FEM locks (the band forces the solution to be
//! linear along it); tempered FEM keeps the optimal rates. Also the regular
//! mesh for comparison.
//!
//!   cargo run --release --example locking

use tfem::meshgen::unit_square;
use tfem::verification::{
    StudyPoint, fitted_rate, run_manufactured_elasticity, run_manufactured_laplace,
};
use tfem::{Material, PlaneMode, Tempering};

fn table(name: &str, run: impl Fn(usize) -> tfem::Result<StudyPoint>) -> tfem::Result<()> {
    let pts: Vec<StudyPoint> = [8, 16, 32, 64, 128]
        .iter()
        .map(|&n| run(n))
        .collect::<tfem::Result<_>>()?;
    println!("\n{name}");
    println!("| h | unknowns | L2 error | energy/H1 error | time [s] |");
    println!("|---|---|---|---|---|");
    for p in &pts {
        println!(
            "| 1/{:.0} | {} | {:.3e} | {:.3e} | {:.3} |",
            1.0 / p.h,
            p.unknowns,
            p.l2,
            p.energy,
            p.seconds
        );
    }
    let h: Vec<f64> = pts.iter().map(|p| p.h).collect();
    let l2: Vec<f64> = pts.iter().map(|p| p.l2).collect();
    let en: Vec<f64> = pts.iter().map(|p| p.energy).collect();
    println!(
        "fitted rates: L2 {:.2}, energy/H1 {:.2}",
        fitted_rate(&h, &l2),
        fitted_rate(&h, &en)
    );
    Ok(())
}

fn main() -> tfem::Result<()> {
    let band = Some(1e-9);
    let mat = Material::new(1.0, 0.3, PlaneMode::Strain, "body 1")?;
    table("Laplacian, regular mesh, TFEM", |n| {
        run_manufactured_laplace(unit_square(n, None), 1.0 / n as f64, Tempering::Auto)
    })?;
    table("Laplacian, band of flat caps, plain FEM", |n| {
        run_manufactured_laplace(unit_square(n, band), 1.0 / n as f64, Tempering::Off)
    })?;
    table("Laplacian, band of flat caps, TFEM (λ = 1)", |n| {
        run_manufactured_laplace(unit_square(n, band), 1.0 / n as f64, Tempering::Auto)
    })?;
    table("Elasticity, regular mesh, TFEM", |n| {
        run_manufactured_elasticity(unit_square(n, None), 1.0 / n as f64, mat, Tempering::Auto)
    })?;
    table("Elasticity, band of flat caps, plain FEM", |n| {
        run_manufactured_elasticity(unit_square(n, band), 1.0 / n as f64, mat, Tempering::Off)
    })?;
    table("Elasticity, band of flat caps, TFEM (λ = 1)", |n| {
        run_manufactured_elasticity(unit_square(n, band), 1.0 / n as f64, mat, Tempering::Auto)
    })?;
    Ok(())
}
