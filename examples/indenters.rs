//! Initial overlap and rigid bodies (docs/method.md §6.14), against closed
//! forms over mesh levels, with fitted rates:
//!
//! * a Lamé shrink fit — two rings overlapping by δ, every element of B
//!   inverted at the start — in plane strain and plane stress, for
//!   δ/b = 1e-2 … 1e-6: nodal contact pressure, hoop and radial stresses;
//! * a flat rigid punch on a block: the pressure against
//!   P/(π√(a² − x²)) on |x| ≤ 0.8a, the contact length, the force balance;
//! * a rigid cylinder on the Hertz block: a and p₀ with E* of the block.
//!
//!   cargo run --release --example indenters

use std::time::Instant;

use tfem::scenes::hertz::Hertz;
use tfem::scenes::lame::Lame;
use tfem::scenes::punch::{FlatPunch, RigidCylinder};
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, PlaneMode};

fn main() {
    let options = ContactOptions::default();
    println!("Lamé shrink fit (a = 0.5, b = 1, c = 1.5; errors relative to p)");
    for plane in [PlaneMode::Strain, PlaneMode::Stress] {
        for delta in [1e-2, 1e-4, 1e-6] {
            let (mut hs, mut ep, mut eh, mut er) = (vec![], vec![], vec![], vec![]);
            for k in [8.0, 16.0, 32.0, 64.0, 128.0] {
                let lame = Lame {
                    interference: delta,
                    plane,
                    mesh_size: 1.0 / k,
                    ..Default::default()
                };
                let t = Instant::now();
                let r = lame.build().unwrap().solve(&lame, &options).unwrap();
                println!(
                    "  {plane:?} δ/b = {delta:.0e}, h = b/{k:<3}: p = {:.4e}, pressure {:.2e}, hoop {:.2e}, radial {:.2e}, bore hoop {:.2e} ({} iteration(s), {:.2} s)",
                    r.exact.pressure,
                    r.pressure_error,
                    r.hoop_error,
                    r.radial_error,
                    r.bore_hoop_error,
                    r.report.iterations,
                    t.elapsed().as_secs_f64()
                );
                hs.push(1.0 / k);
                ep.push(r.pressure_error);
                eh.push(r.hoop_error);
                er.push(r.radial_error);
            }
            println!(
                "    fitted rates: pressure {:.2}, hoop {:.2}, radial {:.2}",
                fitted_rate(&hs, &ep),
                fitted_rate(&hs, &eh),
                fitted_rate(&hs, &er)
            );
        }
    }

    println!("Flat rigid punch (a = 1, block 40a × 40a, plane strain)");
    let (mut hs, mut es) = (vec![], vec![]);
    for k in [8.0, 16.0, 32.0, 64.0, 128.0] {
        let punch = FlatPunch {
            mesh_size: 1.0 / k,
            ..Default::default()
        };
        let t = Instant::now();
        let r = punch.build().unwrap().solve(&punch, &options).unwrap();
        println!(
            "  h = a/{k:<3}: P = {:.4e}, pressure error on |x| <= 0.8a {:.2e}, ℓc/a = {:.12}, active {}/{}, |P − R_support|/P = {:.1e} ({:.2} s)",
            r.force,
            r.pressure_error,
            r.contact_length / punch.half_width,
            r.active.0,
            r.active.1,
            r.balance,
            t.elapsed().as_secs_f64()
        );
        hs.push(1.0 / k);
        es.push(r.pressure_error);
    }
    println!("    fitted rate {:.2}", fitted_rate(&hs, &es));

    println!("Rigid cylinder on the Hertz block (E* = E/(1 − ν²) of the block)");
    let (mut hs, mut ea, mut ep) = (vec![], vec![], vec![]);
    for k in [4.0, 8.0, 16.0, 32.0, 64.0] {
        let base = RigidCylinder::default();
        let rc = RigidCylinder {
            hertz: Hertz {
                mesh_size: base.hertz.half_width / k,
                ..base.hertz
            },
            ..base
        };
        let t = Instant::now();
        let r = rc.build().unwrap().solve(&rc, &options).unwrap();
        let h = &r.hertz;
        let rel = |v: f64, e: f64| (v - e) / e;
        println!(
            "  h = a/{k:<3}: P = {:.4e}, a = {:.5} R: a {:+.2e}, fitted p0 {:+.2e}, nodal p0 {:+.2e} ({} iterations, {:.2} s)",
            r.force,
            h.a_exact / rc.hertz.radius,
            rel(h.a, h.a_exact),
            rel(h.p0_fit, h.p0_exact),
            rel(h.p0, h.p0_exact),
            h.report.iterations,
            t.elapsed().as_secs_f64()
        );
        hs.push(1.0 / k);
        ea.push(rel(h.a, h.a_exact).abs());
        ep.push(rel(h.p0_fit, h.p0_exact).abs());
    }
    println!(
        "    fitted rates: a {:.2}, fitted p0 {:.2}",
        fitted_rate(&hs, &ea),
        fitted_rate(&hs, &ep)
    );
}
