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
pub(crate) mod history;
pub(crate) mod linear;
pub(crate) mod memory;
pub(crate) mod mortar;
pub(crate) mod mortar_history;
pub mod report;
pub(crate) mod session;
pub mod system;

use active_set::{ActiveSetLoop, LoopInput, body_energy};
use condensed::Condensed;
use diagnostics::conditioning_warning;
use linear::{Structure, factor_and_solve};
use report::{ContactReport, SolveInfo, Timings};
use session::{Session, Settings, Wanted, factorisation};

use crate::contact::{
    ContactElement, ContactLaw, ContactOptions, ContactPair, ContactSet, ContactWeighting,
    ElementLaw, FrictionOutcome, Nodes, element_laws, softer,
};
use crate::error::{Result, ensure_finite};
use crate::fem::assembly::{DofMap, NOT_FREE};
use crate::fem::body::Softened;
use crate::fem::element_loop::{ElementLoop, element_values};
use crate::fem::mesh::Mesh;

/// What a solve reads of the problem.
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
    /// How the pairs' contact energy is weighted.
    pub weighting: ContactWeighting,
}

/// The displacements a solve produced.
pub(crate) enum Field {
    /// Over every global DOF.
    Global(Vec<f64>),
    /// A load step's interface values, the whole field recovered when
    /// asked for.
    Pending(Pending),
}

/// A load step whose field waits until asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Pending {
    /// Under the strip weighting ([`history::recover`]).
    Strip(history::Pending),
    /// Under the mortar weighting ([`mortar_history::recover`]).
    Mortar(mortar_history::Pending),
}

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
    /// Active flag of every element of B.
    pub active: Vec<bool>,
    /// Contact pressure of every element of B (zero when inactive).
    pub pressure: Vec<f64>,
    /// Each element's law.
    pub laws: Vec<ElementLaw>,
    /// The frictional state (docs/method.md §6.15), when frictional.
    pub friction: Option<FrictionOutcome>,
    /// The report (its `info` filled by the caller).
    pub report: ContactReport,
    /// The state under the mortar weighting (then `active`, `pressure`
    /// and `laws`, over the elements of B, are empty).
    pub mortar: Option<mortar::MortarState>,
}

/// Solves `input` on `session`: without contact when `options` is `None`.
pub(crate) fn solve(
    session: &mut Session,
    input: &Input<'_>,
    options: Option<&ContactOptions>,
    timings: &mut Timings,
) -> Result<Outcome> {
    let (info, warnings) = prepare(session, input, timings)?;
    match options {
        None => solve_plain(session, input, info, timings, warnings),
        Some(options) if input.weighting == ContactWeighting::Mortar => {
            let start = mortar::Start::default();
            mortar::solve_contact(session, input, options, (info, timings), (warnings, start))
        }
        Some(options) => solve_contact(session, input, options, info, timings, warnings),
    }
}

/// A load step under the mortar weighting at load factor `t` (`scaled`:
/// the problem with its loads and prescribed values times t; `unit`:
/// unscaled), from the slave nodes' set `warm` (`None`: a contact solve's
/// first set): a step of the session's history when it goes on (same
/// `key` and settings), else a contact solve that begins one
/// (docs/method.md §6.11). Also gives the interface factor before the
/// step when a history went on (what a revert puts back).
pub(crate) fn mortar_step(
    session: &mut Session,
    (scaled, unit): (&Input<'_>, &Input<'_>),
    (options, key, revision): (&ContactOptions, history::Key, u64),
    (t, warm, fresh): (f64, Option<&[bool]>, bool),
    timings: &mut Timings,
) -> Result<Option<(Outcome, Option<mortar_history::Snapshot>)>> {
    ensure_unknowns(&session.dofs)?;
    // Refused options leave the history to the next step.
    mortar::check_options(options, scaled.pairs)?;
    let goes_on = |h: &mortar_history::MortarHistory| h.continues(&key, scaled.settings);
    let going_on = match session.mortar_history.as_ref() {
        Some(h) if !fresh && goes_on(h) => session.mortar_history.take(),
        _ => None,
    };
    if let Some(mut h) = going_on {
        let before = h.snapshot();
        let stepped = mortar_history::step(
            session,
            (scaled, unit),
            options,
            &mut h,
            (t, warm, revision),
            timings,
        );
        if !matches!(stepped, Ok(Some(_))) {
            // A failed step changes nothing: the factor goes back.
            h.restore(&before);
        }
        session.mortar_history = Some(h);
        return Ok(stepped?.map(|outcome| (outcome, Some(before))));
    }
    // A history this step does not continue comes back if the step fails.
    let saved = session.mortar_history.take();
    let fresh_solve = |session: &mut Session, timings: &mut Timings| {
        let (info, warnings) = prepare(session, scaled, timings)?;
        let start = mortar::Start { warm };
        mortar::solve_settled(session, scaled, options, (info, timings), (warnings, start))
    };
    let (outcome, settled) = match fresh_solve(session, timings) {
        Ok(solved) => solved,
        Err(e) => {
            if let Some(h) = saved {
                mortar_history::put_back(session, unit, key.stiffness, h);
            }
            return Err(e);
        }
    };
    if let Some(settled) = settled {
        // Without a history the steps after solve afresh: slower, not
        // wrong, so a history that cannot begin is no error.
        let at = (key, revision);
        let begun = mortar_history::begin(session, unit, options, at, (settled, outcome.info));
        session.mortar_history = begun.ok();
    }
    Ok(Some((outcome, None)))
}

/// What every solve does first: the bodies' part assembled afresh (a load
/// history's K₁, strip or mortar, is gone), with the solve's statistics
/// begun and the tempering's warnings.
fn prepare(
    session: &mut Session,
    input: &Input<'_>,
    timings: &mut Timings,
) -> Result<(SolveInfo, Vec<String>)> {
    ensure_unknowns(&session.dofs)?;
    session.set_system_of(None);
    session.history = None;
    session.mortar_history = None;
    let mesh = input.elements.mesh();
    let t0 = std::time::Instant::now();
    let softened = session.assemble_body(&input.elements, (input.f_ext, input.prescribed))?;
    timings.assembly += t0.elapsed().as_secs_f64();
    let mut warnings = Vec::new();
    softening_warning(mesh, softened, input.lambda, &mut warnings);
    let info = SolveInfo {
        unknowns: session.dofs.n_free(),
        matrix_nnz: session.pattern.nnz(),
        ..Default::default()
    };
    Ok((info, warnings))
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
    (log, friction): (&[Vec<usize>], &[f64]),
) -> Result<()> {
    session.assemble_body(&input.elements, (input.f_ext, input.prescribed))?;
    if let (Some(options), ContactWeighting::Mortar) = (options, input.weighting) {
        return mortar::restore(session, input, options, log);
    }
    if let Some(options) = options {
        let Session {
            dofs,
            pattern,
            contact,
            system,
            ..
        } = &mut *session;
        let set = contact_set(input, input.prescribed, contact, dofs, options, &[])?;
        system.replay(log, &set, (dofs, pattern), input.prescribed);
        system.set_friction_loads(&set, friction);
    }
    Ok(())
}

/// The contact set of a built-in solve: B of the session's pairs, each
/// element's law from its pair's softer body, the session's unknowns;
/// frictional (docs/method.md §6.15) when a pair has μ > 0 under the
/// frictionless law, starting from the slip `anchors` (empty: none).
pub(crate) fn contact_set<'a>(
    input: &Input<'a>,
    prescribed: &[f64],
    contact: &'a [ContactElement],
    dofs: &DofMap,
    options: &ContactOptions,
    anchors: &[f64],
) -> Result<ContactSet<'a>> {
    let mesh = input.elements.mesh();
    let soft = pair_material(input, contact, dofs);
    let laws = element_laws(mesh.index_base(), contact, &soft, mesh.size(), options)?;
    let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
    let set = ContactSet::new(
        Nodes::of(mesh),
        contact,
        laws,
        equation,
        prescribed,
        options,
    )?;
    // μ = 0 everywhere is the frictionless set itself, bit for bit; the
    // stick law already ties the surfaces.
    let frictional =
        options.law == ContactLaw::Frictionless && input.pairs.iter().any(|p| p.friction > 0.0);
    if !frictional {
        return Ok(set);
    }
    let mu: Vec<f64> = contact
        .iter()
        .map(|e| input.pairs[e.pair].friction)
        .collect();
    // The stick part's shear modulus: G_c = E_c / (2(1 + ν)) of the pair's
    // softer body, as in the stick law.
    let shear: Vec<f64> = contact
        .iter()
        .map(|e| {
            let s = soft(e.pair);
            let e_c = options.contact_modulus.unwrap_or(s.young());
            e_c / (2.0 * (1.0 + s.poisson()))
        })
        .collect();
    set.with_friction(&mu, &shear, anchors, prescribed)
}

/// The material that sets each pair's contact law: the softer body's, or
/// where one side is a rigid tool ([`rigid_sides`]), the other body's.
fn pair_material<'i>(
    input: &'i Input<'_>,
    contact: &[ContactElement],
    dofs: &DofMap,
) -> impl Fn(usize) -> crate::fem::material::Material + 'i {
    let rigid = rigid_sides(input.pairs, contact, input.elements.mesh(), dofs);
    move |pair: usize| {
        let p = &input.pairs[pair];
        let elements = &input.elements;
        let (a, b) = (*elements.material(p.body_a), *elements.material(p.body_b));
        match rigid[pair] {
            [true, false] => b,
            [false, true] => a,
            _ => softer(a, b),
        }
    }
}

/// E_c of every pair: the options' contact modulus, else the Young's
/// modulus of [`pair_material`].
pub(crate) fn pair_moduli(
    input: &Input<'_>,
    contact: &[ContactElement],
    dofs: &DofMap,
    options: &ContactOptions,
) -> Vec<f64> {
    let soft = pair_material(input, contact, dofs);
    (0..input.pairs.len())
        .map(|i| options.contact_modulus.unwrap_or(soft(i).young()))
        .collect()
}

/// For each pair, whether each side (a, b) is a rigid tool: every DOF of
/// its contact nodes prescribed. Such a side moves as prescribed whatever
/// its body's stiffness, so its material must not set the pair's contact
/// law — a "rigid" punch given a nominal E of 1e3 against a steel block
/// made E_c = 1e3, and the penalty overlap took 99.98 % of the indentation
/// with an OK status (an outside probe). The pair's law then follows the
/// other body (docs/method.md §6.14). A pair with no element (or
/// self-contact, where the sides are one body) keeps the softer body.
fn rigid_sides(
    pairs: &[ContactPair],
    contact: &[ContactElement],
    mesh: &Mesh,
    dofs: &DofMap,
) -> Vec<[bool; 2]> {
    let mut rigid = vec![[false; 2]; pairs.len()];
    let mut seen = vec![[false; 2]; pairs.len()];
    for el in contact {
        let p = &pairs[el.pair];
        if p.body_a == p.body_b {
            continue;
        }
        for &n in &el.nodes {
            let side = match mesh.node_body()[n] {
                Some(b) if b == p.body_a => 0,
                Some(b) if b == p.body_b => 1,
                _ => continue,
            };
            let fixed = (0..2).all(|c| dofs.free(2 * n + c) == NOT_FREE);
            if !seen[el.pair][side] {
                seen[el.pair][side] = true;
                rigid[el.pair][side] = true;
            }
            rigid[el.pair][side] &= fixed;
        }
    }
    rigid
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
    let chol = factorisation(
        analysis,
        (mesh, dofs, pattern),
        input.settings,
        want,
        timings,
        &mut info,
    )?;
    let energy = |r: &[f64]| body_energy(&input.elements, r);
    let x = factor_and_solve(at, chol, system, &energy, true, "", timings, &mut info)?;
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

/// A contact solve: the active-set loop over the elements of B.
fn solve_contact(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    mut info: SolveInfo,
    timings: &mut Timings,
    mut warnings: Vec<String>,
) -> Result<Outcome> {
    let mesh = input.elements.mesh();
    let Session {
        dofs,
        pattern,
        contact,
        analysis,
        system,
        ..
    } = &mut *session;
    let set = contact_set(input, input.prescribed, contact, dofs, options, &[])?;
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
    let structure = (mesh, &*dofs, &*pattern);
    let chol = factorisation(
        analysis,
        structure,
        input.settings,
        want,
        timings,
        &mut info,
    )?;
    let at = Structure {
        mesh,
        dofs,
        pattern,
    };
    let loop_input = LoopInput {
        at,
        elements: &input.elements,
        set: &set,
        prescribed: input.prescribed,
        interface: condense.then_some(interface),
        options: *options,
    };
    let settled = ActiveSetLoop::new(loop_input, (chol, system), (timings, &mut info)).run()?;
    info.memory_bytes = session_memory(at, system, chol) + settled.condensed_bytes;
    info.relative_residual = system.relative_residual(pattern, &settled.x);
    info.condition_estimate = chol.condition_estimate();
    info.timings = *timings;
    finite_statistics(&info)?;
    conditioning_warning(&info, &mut warnings);
    let u = dofs.expand(&settled.x, input.prescribed);
    drop(settled.x);
    let ue_of = |tri: &[usize; 3]| element_values(&u, tri);
    let verdict = (settled.active, &settled.friction[..]);
    let contact = contact_outcome(
        (&set, input.pairs),
        ue_of,
        verdict,
        settled.history,
        info,
        &mut warnings,
    )?;

    Ok(Outcome {
        u: Field::Global(u),
        log: system.log().to_vec(),
        info,
        contact: Some(contact),
        warnings,
    })
}

/// Below this many correct digits of the largest contact pressure a solve
/// warns (`precision_warning`).
const PRESSURE_DIGITS: f64 = 6.0;

/// The error of a solved u over the rounding bound of its value: the solve
/// adds its own. Measured on the flat punch (h = a/8, E_c = 1e15 … 1e21):
/// the punch's reaction is off from the support's by 2–40× the rounding
/// bound of the largest pressure, relative to it.
const SOLVE_ERROR_FACTOR: f64 = 10.0;

/// Warns when the contact pressures carry fewer than [`PRESSURE_DIGITS`]
/// correct digits because the penalty's overlaps approach the rounding of
/// the displacements (docs/method.md §6.14): a very stiff E_c against a
/// prescribed body leaves a well-conditioned system (no conditioning
/// warning: the penalty couples free to prescribed unknowns, so it enters
/// the load) whose forces are nevertheless rounding. The bound compared is
/// the largest error the displacements' own rounding leaves in an active
/// element's pressure, against the largest pressure.
fn precision_warning(
    set: &ContactSet<'_>,
    ue_of: impl Fn(&[usize; 3]) -> [f64; 6],
    active: &[bool],
    pressure: &[f64],
    warnings: &mut Vec<String>,
) {
    let (mut worst, mut at) = (0.0f64, None);
    for (k, el) in set.elements().iter().enumerate() {
        if active[k] {
            let r = SOLVE_ERROR_FACTOR * set.pressure_rounding(k, &ue_of(&el.nodes));
            if r > worst {
                (worst, at) = (r, Some(k));
            }
        }
    }
    let largest = pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    let Some(k) = at else { return };
    if worst <= 10f64.powf(-PRESSURE_DIGITS) * largest {
        return;
    }
    let digits = (largest / worst).log10().max(0.0);
    warnings.push(format!(
        "the contact pressures carry about {digits:.0} correct digits: the penalty's overlaps are \
         near the rounding of the displacements (at contact element {}, the pressure {:.3e} may be off \
         by {worst:.1e}, against a largest pressure of {largest:.3e}); where the contact carries a \
         load, lower E_c or λ (docs/method.md §6.14)",
        k + set.nodes().base,
        pressure[k]
    ));
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

/// Pressures, contact length and penetration of the settled set (flags over
/// parts, with its friction load factors), and its frictional state.
pub(crate) fn contact_outcome(
    (set, pairs): (&ContactSet<'_>, &[ContactPair]),
    ue_of: impl Fn(&[usize; 3]) -> [f64; 6],
    (mut active, friction): (Vec<bool>, &[f64]),
    history: Vec<report::IterationRecord>,
    info: SolveInfo,
    warnings: &mut Vec<String>,
) -> Result<ContactOutcome> {
    let elements = set.elements();
    let friction = set.friction_outcome(&active, friction, |k| ue_of(&elements[k].nodes));
    if let Some(f) = &friction {
        let name = |k: usize| format!("contact element {}", k + set.nodes().base);
        ensure_finite(f.shear.iter().copied(), 1, "shear traction", name)?;
        ensure_finite(f.dissipation.iter().copied(), 1, "slip dissipation", name)?;
    }
    active.truncate(set.len());
    let mut pressure = vec![0.0; set.len()];
    let (mut lc, mut max_pen) = (0.0, 0.0f64);
    for (k, el) in set.elements().iter().enumerate() {
        if !active[k] {
            continue;
        }
        let ue = ue_of(&el.nodes);
        pressure[k] = set.pressure(k, &ue);
        let opening = set.opening(k, &ue);
        if el.edge_length > 0.0 {
            max_pen = max_pen.max(-opening / el.edge_length);
        }
    }
    // The part of each edge that faces the other side, the longer-active
    // family of each contact zone (§6.8, §6.11).
    let (zones_lc, one_sided) =
        crate::contact::conformity::contact_length_and_warnings(elements, &active, pairs);
    lc += zones_lc;
    let name = |k: usize| format!("contact element {}", k + set.nodes().base);
    ensure_finite(pressure.iter().copied(), 1, "contact pressure", name)?;
    precision_warning(set, &ue_of, &active, &pressure, warnings);
    warnings.extend(one_sided);
    ensure_finite([lc, max_pen], 1, "contact length or penetration", |_| {
        "the contact report".to_string()
    })?;
    let report = ContactReport {
        iterations: history.len(),
        elements: set.len(),
        active: active.iter().filter(|&&a| a).count(),
        contact_length: lc,
        max_penetration: max_pen,
        history,
        info,
    };
    Ok(ContactOutcome {
        active,
        pressure,
        laws: set.laws().to_vec(),
        friction,
        report,
        mortar: None,
    })
}
