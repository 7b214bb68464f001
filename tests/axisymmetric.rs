//! The axisymmetric mode (docs/method.md §7): the tempered ring element,
//! a manufactured field, Lamé's thick cylinder, the contact patch test and
//! a hub shrunk on a shaft.

use tfem::scenes::revolution::{ThickCylinder, ring_square, run_manufactured_ring};
use tfem::verification::fitted_rate;
use tfem::{Material, PlaneMode, Tempering};

fn steel() -> Material {
    Material::new(210e3, 0.3, PlaneMode::Axisymmetric, "body 1").unwrap()
}

#[test]
fn probe() {
    for cells in [4, 8, 16, 32] {
        let r = ThickCylinder {
            cells,
            ..Default::default()
        }
        .solve()
        .unwrap();
        eprintln!("{cells} {:?}", r);
    }
    for band in [None, Some(1e-9)] {
        for r0 in [0.0, 1.0] {
            let mut h = vec![];
            let mut e = vec![];
            for n in [4, 8, 16, 32] {
                let eps = band.map(|_| (1.0 / n as f64).powi(5));
                let p = run_manufactured_ring(
                    ring_square(r0, n, eps),
                    1.0 / n as f64,
                    steel(),
                    Tempering::Auto,
                )
                .unwrap();
                h.push(p.h);
                e.push(p.l2);
            }
            eprintln!("band {band:?} r0 {r0}: {e:?} rate {}", fitted_rate(&h, &e));
        }
    }
}
