//! Solving a problem: the `session` derived from its structure and
//! reused while the structure holds, the [`system`] assembled into it, the
//! `linear` solve with its `diagnostics`, the [`condensed`] interface
//! system and the `active_set` loop of the contact solve.
//!
//! A solve reads the problem through `Input` and returns an `Outcome`
//! (displacements over every global DOF, statistics, the contact state);
//! it changes nothing but the session, so that a failed solve leaves the
//! model's results as they were.

pub(crate) mod active_set;
pub mod condensed;
pub(crate) mod diagnostics;
#[cfg(test)]
mod fixtures;
pub(crate) mod friction_loads;
pub(crate) mod history;
pub(crate) mod linear;
pub(crate) mod memory;
pub mod report;
pub(crate) mod session;
pub mod solid;
pub mod system;

use active_set::{ActiveSetLoop, LoopInput, body_energy};
use condensed::Condensed;
use diagnostics::conditioning_warning;
use linear::{Bookkeeping, Structure, SystemAndFactor, factor_and_solve};
use report::{ContactReport, SolveInfo, Timings};
use session::{Session, Settings, Wanted, factorisation};

use crate::contact::constraints::{Build, Constraints};
use crate::contact::discretisation::Discretisation;
use crate::contact::settled::{self, ContactState};
use crate::contact::{ContactOptions, ContactPair, FrictionState};
use crate::error::{Result, ensure_finite};
use crate::fem::assembly::DofMap;
use crate::fem::body::Softened;
use crate::fem::element_loop::ElementLoop;
use crate::fem::mesh::Mesh;

/// What a solve reads of the problem.
#[derive(Clone, Copy)]
pub(crate) struct Input<'a> {
    /// The body elements with their materials and tempering.
    pub elements: ElementLoop<'a>,
    /// The contact pairs.
    pub pairs: &'a [ContactPair],
    /// Prescribed displacements, a global vector (zero where free).
    pub prescribed: &'a [f64],
    /// External forces, a global vector.
    pub f_ext: &'a [f64],
    /// The tempering's λ (for the warning about softened elements; `None`
    /// for a fixed Jmin).
    pub lambda: Option<f64>,
    /// The factorisation's settings.
    pub settings: Settings,
    /// A displacement field near the solution (global), from which a
    /// frictionless contact solve without a warm start takes its first set:
    /// the inversion test on it (an adaptive solve's coarser level).
    pub guess: Option<&'a [f64]>,
}

/// The displacements a solve produced.
pub(crate) enum Field {
    /// Over every global DOF.
    Global(Vec<f64>),
    /// A load step's interface values, the whole field recovered when
    /// asked for.
    Pending(Pending),
}

/// A load step whose field waits until asked for ([`history::recover`]).
pub(crate) use history::Pending;

/// What a successful solve produced.
pub(crate) struct Outcome {
    /// The displacements.
    pub u: Field,
    /// How the final system was assembled: the contact elements switched
    /// after the bodies' part ([`restore`] replays it).
    pub log: Vec<Vec<usize>>,
    /// Statistics (timings filled by the caller).
    pub info: SolveInfo,
    /// The contact state, for a contact solve.
    pub contact: Option<ContactOutcome>,
    /// Warnings of the solve.
    pub warnings: Vec<String>,
}

/// The contact state at convergence.
pub(crate) struct ContactOutcome {
    /// The final flags over the constraints' parts (what the next load
    /// step starts from).
    pub flags: Vec<bool>,
    /// The state the constraints settled in.
    pub state: ContactState,
    /// The report (its `info` filled by the caller).
    pub report: ContactReport,
    /// The openings of the strip's elements at the solve's load under the
    /// flags it started from: where along a load step its elements close
    /// (empty when frictionless, or not known).
    pub predicted: Vec<f64>,
}

/// Solves `input` on `session`: without contact when `options` is `None`.
pub(crate) fn solve(
    session: &mut Session,
    input: &Input<'_>,
    options: Option<&ContactOptions>,
    timings: &mut Timings,
) -> Result<Outcome> {
    let Some(options) = options else {
        let Begun { info, warnings } = prepare(session, input, timings)?;
        return solve_plain(session, input, info, timings, warnings);
    };
    let path = history::path_start(session, input, options, timings)?;
    let mut begun = prepare(session, input, timings)?;
    let start = path.as_ref().map(|(state, factorizations)| {
        begun.info.factorizations += factorizations;
        WarmStart {
            flags: &state.warm,
            friction: &state.friction,
        }
    });
    solve_contact(session, input, options, start, begun, timings)
}

/// The flags (and friction loads) a contact solve's loop starts from, when
/// not the constraints' initial set: a load step's warm start, or, for a
/// frictionless set, the inversion test on a guessed field (global).
fn first_flags(
    set: &Constraints<'_>,
    dofs: &DofMap,
    start: Start<'_>,
    guess: Option<&[f64]>,
) -> Result<Option<(Vec<bool>, Vec<f64>)>> {
    Ok(match (start, guess) {
        (Some(w), _) => Some(history::warm_start(set, w.flags, w.friction)),
        (None, Some(u)) if !set.is_frictional() => {
            let x = dofs.gather(u);
            let flags = set.verdict(&set.initial_active(), &[], |i| x[i])?.flags;
            Some((flags, Vec::new()))
        }
        _ => None,
    })
}

/// Where a contact solve's loop starts: the constraints' initial set
/// (`None`), or a load step's warm start — the set and friction state a
/// step before ended with.
pub(crate) type Start<'s> = Option<WarmStart<'s>>;

/// A load step's warm start: the flags and friction state the step before
/// ended with.
#[derive(Clone, Copy)]
pub(crate) struct WarmStart<'s> {
    /// The flags over the constraints' parts.
    pub flags: &'s [bool],
    /// The slip state and friction loads.
    pub friction: &'s FrictionState,
}

/// What a solve begins with ([`prepare`]): its statistics so far and the
/// tempering's warnings.
pub(crate) struct Begun {
    /// The statistics.
    pub info: SolveInfo,
    /// The warnings.
    pub warnings: Vec<String>,
}

/// What every solve does first: the bodies' part assembled afresh (a load
/// history's K₁, strip or mortar, is gone), with the solve's statistics
/// begun and the tempering's warnings.
pub(crate) fn prepare(
    session: &mut Session,
    input: &Input<'_>,
    timings: &mut Timings,
) -> Result<Begun> {
    ensure_unknowns(&session.dofs)?;
    session.holds = session::Holds::Nothing;
    let mesh = input.elements.mesh();
    let t0 = std::time::Instant::now();
    let softened = session.assemble_body(&input.elements, input.f_ext, input.prescribed)?;
    timings.assembly += t0.elapsed().as_secs_f64();
    let mut warnings = Vec::new();
    softening_warning(mesh, softened, input.lambda, &mut warnings);
    let info = SolveInfo {
        unknowns: session.dofs.n_free(),
        matrix_nnz: session.pattern.nnz(),
        ..Default::default()
    };
    Ok(Begun { info, warnings })
}

/// Refuses a model whose every DOF is prescribed: there is no system to
/// solve, and the factorisation of its empty matrix read as singular ("body
/// 1 is not restrained (free mode: )", found by an outside probe).
pub(crate) fn ensure_unknowns(dofs: &DofMap) -> Result<()> {
    if dofs.n_free() > 0 {
        return Ok(());
    }
    Err(crate::error::Error::state(format!(
        "every DOF of the model is prescribed ({} DOFs): there is nothing to solve — the \
         displacements are the prescribed values; leave at least one DOF free",
        dofs.n_global()
    )))
}

/// Rebuilds in `session` the final system of an earlier successful solve of
/// `input` (with contact `options`, whose system switched the elements of
/// `log`), after a failed solve reused its storage: the same operations in
/// the same order, so the same values to the last bit.
pub(crate) fn restore(
    session: &mut Session,
    input: &Input<'_>,
    options: Option<&ContactOptions>,
    log: &[Vec<usize>],
    friction: &[f64],
) -> Result<()> {
    session.assemble_body(&input.elements, input.f_ext, input.prescribed)?;
    if let Some(options) = options {
        let Session {
            dofs,
            pattern,
            contact,
            system,
            ..
        } = &mut *session;
        let set = constraints(input, input.prescribed, contact, dofs, options, &[])?;
        system.replay(log, &set, pattern);
        system.set_friction_loads(&set, friction);
    }
    Ok(())
}

/// The constraints of a built-in solve ([`Constraints::build`]) of
/// `input`, for the prescribed displacements `prescribed`, over the
/// session's unknowns `dofs`, starting from the slip `anchors` (empty:
/// none).
pub(crate) fn constraints<'a>(
    input: &Input<'a>,
    prescribed: &'a [f64],
    contact: &'a Discretisation,
    dofs: &'a DofMap,
    options: &'a ContactOptions,
    anchors: &[f64],
) -> Result<Constraints<'a>> {
    let build = Build {
        elements: input.elements,
        pairs: input.pairs,
        discretisation: contact,
        dofs,
        prescribed,
        options,
    };
    Constraints::build(build, anchors)
}

/// The warning about well-shaped elements that tempering softens.
pub(crate) fn softening_warning(
    mesh: &Mesh,
    softened: Softened,
    lambda: Option<f64>,
    warnings: &mut Vec<String>,
) {
    let (n, Some(e)) = softened else {
        return;
    };
    let cause = match lambda {
        Some(l) => format!(
            "λ = {l:e} is not much larger than the element size, so Jmin = h³/λ exceeds \
             their J; increase λ"
        ),
        None => "the fixed Jmin exceeds their J; lower it".to_string(),
    };
    warnings.push(format!(
        "tempering softens {n} well-shaped element(s) (e.g. {}): {cause}",
        mesh.triangle_name(e)
    ));
}

/// A solve without contact: one factorisation of the bodies' part.
fn solve_plain(
    session: &mut Session,
    input: &Input<'_>,
    mut info: SolveInfo,
    timings: &mut Timings,
    mut warnings: Vec<String>,
) -> Result<Outcome> {
    let mesh = input.elements.mesh();
    let Session {
        dofs,
        pattern,
        analysis,
        system,
        ..
    } = &mut *session;
    let want = Wanted {
        last: &[],
        zeros: &[],
    };
    let at = Structure {
        mesh,
        dofs,
        pattern,
    };
    let mut books = Bookkeeping::new(timings, &mut info);
    let chol = factorisation(analysis, at, input.settings, want, &mut books)?;
    let energy = |r: &[f64]| body_energy(&input.elements, r);
    let mut linear = SystemAndFactor { chol, system };
    let x = factor_and_solve(at, &mut linear, &energy, true, "", &mut books)?;
    info.relative_residual = system.relative_residual(pattern, &x);
    info.condition_estimate = chol.condition_estimate();
    info.memory_bytes = session_memory(at, system, chol);
    info.timings = *timings;
    finite_statistics(&info)?;
    conditioning_warning(&info, &mut warnings);
    Ok(Outcome {
        u: Field::Global(dofs.expand(&x, input.prescribed)),
        log: Vec::new(),
        info,
        contact: None,
        warnings,
    })
}

/// A contact solve: the active-set loop over the constraints, from
/// `start`, on the bodies' part [`prepare`] assembled.
pub(crate) fn solve_contact(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    start: Start<'_>,
    begun: Begun,
    timings: &mut Timings,
) -> Result<Outcome> {
    let Begun {
        mut info,
        mut warnings,
    } = begun;
    let mesh = input.elements.mesh();
    let Session {
        dofs,
        pattern,
        contact,
        analysis,
        system,
        ..
    } = &mut *session;
    let anchors = start.map_or(&[][..], |w| &w.friction.anchors);
    let set = constraints(input, input.prescribed, contact, dofs, options, anchors)?;
    let interface = if options.refactorize {
        Vec::new()
    } else {
        set.interface_unknowns()
    };
    let condense = Condensed::worthwhile(interface.len(), pattern.nnz());
    let zeros = set.structural_zeros(pattern, system.values());
    let want = Wanted {
        last: if condense { &interface } else { &[] },
        zeros: &zeros,
    };
    let at = Structure {
        mesh,
        dofs,
        pattern,
    };
    let mut books = Bookkeeping::new(timings, &mut info);
    let chol = factorisation(analysis, at, input.settings, want, &mut books)?;
    let energy = |r: &[f64]| body_energy(&input.elements, r);
    let loop_input = LoopInput {
        at,
        body_energy: &energy,
        set: &set,
        interface: condense.then_some(interface),
        options: *options,
    };
    let flags = first_flags(&set, dofs, start, input.guess)?;
    let linear = SystemAndFactor { chol, system };
    let settled = ActiveSetLoop::new(loop_input, linear, books, flags).run()?;
    info.memory_bytes = session_memory(at, system, chol) + settled.condensed_bytes;
    info.relative_residual = system.relative_residual(pattern, &settled.x);
    info.condition_estimate = chol.condition_estimate();
    info.timings = *timings;
    finite_statistics(&info)?;
    conditioning_warning(&info, &mut warnings);
    let x = &settled.x;
    let paired = settled::PairedMesh {
        mesh,
        pairs: input.pairs,
    };
    let (active, friction) = (settled.active, &settled.friction_loads);
    let s = settled::settle(&set, active, friction, |i| x[i], paired, &mut warnings)?;
    let contact = contact_outcome(s, settled.history, info, settled.predicted);
    let u = dofs.expand(&settled.x, input.prescribed);
    drop(settled.x);
    Ok(Outcome {
        u: Field::Global(u),
        log: system.log().to_vec(),
        info,
        contact: Some(contact),
        warnings,
    })
}

/// Bytes held by the pattern, the matrix values and the factor.
fn session_memory(
    at: Structure<'_>,
    system: &system::AssembledSystem,
    chol: &crate::linalg::Cholesky,
) -> usize {
    at.pattern.memory_bytes() + system.memory_bytes() + chol.memory_bytes()
}

/// Refuses statistics that overflowed (a relative residual or condition
/// estimate of a system scaled beyond double precision).
pub(crate) fn finite_statistics(info: &SolveInfo) -> Result<()> {
    let values = [info.relative_residual, info.condition_estimate];
    ensure_finite(values, 1, "relative residual or condition estimate", |_| {
        "the solved system".to_string()
    })
}

/// The contact outcome of a solve that settled as `s`
/// ([`settled::settle`]) after the iterations `history`, with the
/// statistics `info` and the openings `predicted` of its first solve: its
/// state and report.
pub(crate) fn contact_outcome(
    s: settled::Settlement,
    history: Vec<report::IterationRecord>,
    info: SolveInfo,
    predicted: Vec<f64>,
) -> ContactOutcome {
    let report = ContactReport {
        iterations: history.len(),
        elements: s.parts,
        active: s.active,
        contact_length: s.contact_length,
        max_penetration: s.max_penetration,
        history,
        info,
    };
    ContactOutcome {
        flags: s.flags,
        state: s.state,
        report,
        predicted,
    }
}
