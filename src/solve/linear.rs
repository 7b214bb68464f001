//! One linear solve: factorise the assembled matrix (a singular one is
//! diagnosed: which body moves, and how), solve, refine; then check that
//! every unknown is finite. Works over the unknowns throughout.

use std::time::Instant;

use super::diagnostics::{RIGID_ENERGY_TOL, rigid_fit, singular_error};
use super::report::{SolveInfo, Timings};
use super::system::AssembledSystem;
use crate::error::{Error, Result, Status};
use crate::fem::assembly::{DofMap, Pattern};
use crate::fem::domain::Domain;
use crate::linalg::refine::refine;
use crate::linalg::{Cholesky, FactorError};

/// The structure a linear solve works on.
#[derive(Clone, Copy)]
pub(crate) struct Structure<'a> {
    /// The mesh (for naming nodes and bodies in errors).
    pub mesh: &'a dyn Domain,
    /// The unknowns.
    pub dofs: &'a DofMap,
    /// The matrix pattern.
    pub pattern: &'a Pattern,
}

/// The energy (rᵀKr, Σ diag energy) of the assembled elements for a
/// global vector r: tells a free rigid mode from a restrained one.
pub(crate) type Energy<'e> = &'e dyn Fn(&[f64]) -> (f64, f64);

/// The session's assembled system with the factor its matrix is
/// factorised into, borrowed together: a solve updates the one and
/// refactorises the other, and the factor's analysis fits the system's
/// pattern.
pub(crate) struct SystemAndFactor<'a> {
    /// The factor (its symbolic analysis made for the system's pattern).
    pub chol: &'a mut Cholesky,
    /// The assembled system (matrix values and right-hand side).
    pub system: &'a mut AssembledSystem,
}

/// Where a solve's bookkeeping goes: the time of each phase and the
/// statistics of the call, which every factorisation and solve adds to.
pub(crate) struct Bookkeeping<'b> {
    /// The time of each phase.
    pub timings: &'b mut Timings,
    /// The statistics of the call.
    pub info: &'b mut SolveInfo,
}

impl<'b> Bookkeeping<'b> {
    /// Bookkeeping into the caller's `timings` and `info`, which it reads
    /// once the solve is done.
    pub fn new(timings: &'b mut Timings, info: &'b mut SolveInfo) -> Bookkeeping<'b> {
        Bookkeeping { timings, info }
    }
}

/// Factorises `linear`'s system with its factor (whose analysis fits its
/// pattern) and solves it; refines the solution when `refined`. Returns
/// the unknowns, all finite. `context` ends every error message; the time
/// and the factorisation go to `books`.
pub(crate) fn factor_and_solve(
    at: Structure<'_>,
    linear: &mut SystemAndFactor<'_>,
    energy: Energy<'_>,
    refined: bool,
    context: &str,
    books: &mut Bookkeeping<'_>,
) -> Result<Vec<f64>> {
    let (chol, system) = (&mut *linear.chol, &*linear.system);
    let t0 = Instant::now();
    let fact = chol.factorize(at.pattern, system.values());
    books.timings.factorization += t0.elapsed().as_secs_f64();
    books.info.factorizations += 1;
    if let Err(e) = fact {
        accept_or_explain(at, chol, e, energy, context)?;
    }
    let t0 = Instant::now();
    let mut x = system.rhs().to_vec();
    chol.solve(&mut x)?;
    if refined {
        refine(
            at.pattern,
            system.values(),
            system.rhs(),
            &mut x,
            &mut |r| chol.solve(r),
        )?;
    }
    books.timings.solve += t0.elapsed().as_secs_f64();
    check_finite(at, &x, context)?;
    Ok(x)
}

/// After a failed factorisation: accepts an ill-conditioned but restrained
/// system (a tiny eigenvalue from an extreme stiffness contrast), else the
/// error naming the free mode.
fn accept_or_explain(
    at: Structure<'_>,
    chol: &mut Cholesky,
    e: FactorError,
    energy: Energy<'_>,
    context: &str,
) -> Result<()> {
    let usable_hint = matches!(e, FactorError::Singular { usable: true, .. });
    let restrained = match &e {
        FactorError::Singular {
            mode: Some(m),
            usable: true,
            ..
        } => {
            // A tiny eigenvalue from an extreme stiffness contrast, or a
            // free mode? Fit the rigid motion of each body to the mode and
            // measure its energy element by element: round-off for a
            // free body, the coupling's energy for a restrained one.
            let r = rigid_fit(at.mesh, at.dofs, m);
            let (energy, scale) = energy(&r);
            energy > RIGID_ENERGY_TOL * scale
        }
        _ => false,
    };
    if restrained && chol.accept_ill_conditioned() {
        return Ok(());
    }
    let mut err = singular_error(at.mesh, at.dofs, e, context);
    if matches!(err.status(), Status::Singular) && usable_hint {
        err = Error::new(
            Status::Singular,
            format!(
                "{} — numerically singular: the free motion is resisted by less than \
                 1e-13 of the stiffness (a free body, or a stiffness contrast beyond \
                 double precision)",
                err.message()
            ),
        );
    }
    Err(err)
}

/// Refuses a non-finite unknown, naming its node.
pub(crate) fn check_finite(at: Structure<'_>, x: &[f64], context: &str) -> Result<()> {
    match x.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(f) => Err(Error::new(
            Status::NumericalFailure,
            format!(
                "the displacement of {} is not finite{context}",
                at.mesh
                    .node_name(at.dofs.free_to_global()[f] / at.mesh.dimension())
            ),
        )),
    }
}
