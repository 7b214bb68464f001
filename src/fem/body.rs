//! The bodies' part of the system: the tempered stiffness of every body
//! element on the [`Pattern`] and the load on the unknowns (external
//! forces minus the prescribed displacements' share), assembled by two
//! threads at once, each writing only its half of the columns.

use super::assembly::{Columns, DofMap, NOT_FREE, Pattern, Slots};
use super::element::{Jmin, WELL_SHAPED};
use super::element_loop::ElementLoop;
use crate::error::{Error, Result};

/// The well-shaped elements that tempering softens: how many, and the
/// first (a warning names it).
pub type Softened = (usize, Option<usize>);

/// Where the body part is assembled: the pattern, the numbering of its
/// unknowns and each mesh triangle's [`Slots`] in it.
#[derive(Clone, Copy)]
pub struct Target<'a> {
    /// The unknowns.
    pub dofs: &'a DofMap,
    /// The sparsity pattern (upper triangle).
    pub pattern: &'a Pattern,
    /// Each mesh triangle's slots in `pattern`.
    pub slots: &'a [Slots],
}

/// Assembles the body part into `values` (on `target.pattern`, every value
/// overwritten) and `rhs` (one value per unknown, overwritten): `f_ext` and
/// `prescribed` are global vectors (2 per node). Returns the elements that
/// tempering softens, or the first element that fails, named.
pub fn assemble(
    elements: &ElementLoop<'_>,
    target: Target<'_>,
    f_ext: &[f64],
    prescribed: &[f64],
    values: &mut [f64],
    rhs: &mut [f64],
) -> Result<Softened> {
    let dofs = target.dofs;
    rhs.fill(0.0);
    for (g, &f) in f_ext.iter().enumerate() {
        let fg = dofs.free(g);
        if fg != NOT_FREE {
            rhs[fg] += f;
        }
    }
    // Two column ranges assembled at the same time: each visits the
    // elements with an unknown in its range and writes only there.
    let mid = dofs.n_free() / 2;
    // The node of the first unknown above the cut.
    let cut = (0..f_ext.len())
        .find(|&g| dofs.free(g) == mid)
        .map_or(usize::MAX, |g| g / 2);
    let (rhs_lo, rhs_hi) = rhs.split_at_mut(mid);
    let (mut lo, mut hi) = target.pattern.split_columns(mid, values);
    let part = |cols: &mut Columns<'_>, rhs: &mut [f64], below: bool| {
        cols.clear();
        let side = CutSide { cut, below };
        assemble_columns(elements, target, prescribed, cols, rhs, side)
    };
    let (r_lo, r_hi) = rayon::join(
        || part(&mut lo, rhs_lo, true),
        || part(&mut hi, rhs_hi, false),
    );
    match (r_lo, r_hi) {
        (Err(a), Err(b)) => Err(if a.0 <= b.0 { a.1 } else { b.1 }),
        (Err(a), _) | (_, Err(a)) => Err(a.1),
        (Ok(a), Ok(b)) => Ok((a.0 + b.0, a.1.into_iter().chain(b.1).min())),
    }
}

/// Which side of the cut between the two column ranges one assembly
/// takes: the elements without unknowns are shared out by it, so that the
/// two sides check every element once.
#[derive(Clone, Copy)]
struct CutSide {
    /// The node of the first unknown above the cut.
    cut: usize,
    /// Whether this side is the lower column range.
    below: bool,
}

/// What the loop knows of a triangle before computing it, so that the
/// element's stiffness is computed only where this side needs it.
struct Selected {
    /// The global DOFs, node-major as in `DofMap::element_dofs`.
    gd: [usize; 6],
    /// Their unknowns ([`NOT_FREE`] where prescribed).
    free: [usize; 6],
    /// Whether this side owns the element (reports its tempering).
    owns: bool,
}

/// Adds the body elements' stiffness into the columns of `cols` and
/// their prescribed-displacement loads into `rhs` (the rows of the same
/// range). Visits the elements with an unknown in the range and those
/// without unknowns whose lowest node is on `side` of its cut node,
/// so that the two sides of a cut check every element. Returns the
/// elements that tempering softens among those it owns (first unknown
/// in the range, or none and on its side): how many, and the first; or
/// the first element that fails, with its index.
///
/// Unknowns are numbered in node order, so the range's unknowns sit on
/// nodes up to the cut (below) or from the cut on (above): an element
/// entirely on the other side is skipped on its node numbers alone,
/// without looking up its unknowns.
fn assemble_columns(
    elements: &ElementLoop<'_>,
    Target {
        dofs,
        pattern,
        slots,
    }: Target<'_>,
    prescribed: &[f64],
    cols: &mut Columns<'_>,
    rhs: &mut [f64],
    CutSide { cut, below }: CutSide,
) -> std::result::Result<Softened, (usize, Error)> {
    debug_assert_eq!(dofs.per_node(), 2);
    let range = cols.range();
    let mut softened: Softened = (0, None);
    let mut k = [[0.0; 6]; 6];
    let select = |_: usize, tri: &[usize; 3]| -> Option<Selected> {
        let lowest = tri[0].min(tri[1]).min(tri[2]);
        let on_side = if below {
            lowest <= cut
        } else {
            tri[0].max(tri[1]).max(tri[2]) >= cut
        };
        if !on_side {
            return None;
        }
        // Global DOFs and unknowns, node-major as in
        // `DofMap::element_dofs`. (Plain loops: the array adaptors were
        // left as calls, whose results then stall on being read back.)
        let mut gd = [0usize; 6];
        let mut free = [NOT_FREE; 6];
        for q in 0..6 {
            gd[q] = 2 * tri[q / 2] + q % 2;
            free[q] = dofs.free(gd[q]);
        }
        // (NOT_FREE is the largest usize: the minimum is a free one.)
        let first = free.iter().copied().min().unwrap_or(NOT_FREE);
        let owns = if first == NOT_FREE {
            (lowest <= cut) == below
        } else {
            range.contains(&first)
        };
        if !owns && !free.iter().any(|f| range.contains(f)) {
            return None;
        }
        Some(Selected { gd, free, owns })
    };
    elements.visit(select, |el, Selected { gd, free, owns }| {
        let e = el.index;
        if let Jmin::Tempered(jmin) = el.jmin {
            if owns && el.geo.j < jmin && el.geo.j >= WELL_SHAPED * el.geo.h * el.geo.h {
                softened.0 += 1;
                softened.1.get_or_insert(e);
            }
        }
        elements
            .stiffness_into(el, &mut k)
            .map_err(|err| (e, err))?;
        let ke = k.as_flattened();
        pattern.add_element_at(cols, &free, ke, slots[e]);
        if !free.contains(&NOT_FREE) {
            return Ok(());
        }
        for a in 0..6 {
            if free[a] == NOT_FREE || !range.contains(&free[a]) {
                continue;
            }
            let mut r = 0.0;
            for b in 0..6 {
                if free[b] == NOT_FREE {
                    r -= ke[a * 6 + b] * prescribed[gd[b]];
                }
            }
            rhs[free[a] - range.start] += r;
        }
        Ok(())
    })?;
    Ok(softened)
}

/// The load on the unknowns alone (what [`assemble`] writes into `rhs`,
/// to the last bit): external forces minus the prescribed displacements'
/// share, for new loads on an unchanged stiffness. Visits only the elements
/// with a prescribed DOF of nonzero value.
pub fn rhs(
    elements: &ElementLoop<'_>,
    dofs: &DofMap,
    f_ext: &[f64],
    prescribed: &[f64],
) -> Result<Vec<f64>> {
    let mut rhs = vec![0.0; dofs.n_free()];
    for (g, &f) in f_ext.iter().enumerate() {
        let fg = dofs.free(g);
        if fg != NOT_FREE {
            rhs[fg] += f;
        }
    }
    let mut k = [[0.0; 6]; 6];
    let select = |_: usize, tri: &[usize; 3]| -> Option<[usize; 6]> {
        let gd: [usize; 6] = std::array::from_fn(|q| 2 * tri[q / 2] + q % 2);
        let loaded = gd
            .iter()
            .any(|&g| dofs.free(g) == NOT_FREE && prescribed[g] != 0.0);
        loaded.then_some(gd)
    };
    elements.visit(select, |el, gd| {
        let free = gd.map(|g| dofs.free(g));
        if !free.contains(&NOT_FREE) {
            return Ok(());
        }
        elements.stiffness_into(el, &mut k)?;
        let ke = k.as_flattened();
        for a in 0..6 {
            if free[a] == NOT_FREE {
                continue;
            }
            let mut r = 0.0;
            for b in 0..6 {
                if free[b] == NOT_FREE {
                    r -= ke[a * 6 + b] * prescribed[gd[b]];
                }
            }
            rhs[free[a]] += r;
        }
        Ok(())
    })?;
    Ok(rhs)
}
