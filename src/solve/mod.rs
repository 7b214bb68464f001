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
pub mod report;
pub(crate) mod session;
pub mod system;

use active_set::{ActiveSetLoop, LoopInput, body_energy};
use condensed::Condensed;
use diagnostics::conditioning_warning;
use linear::{Structure, factor_and_solve};
use report::{ContactReport, SolveInfo, Timings};
use session::{Session, Settings, Wanted, factorisation};

use crate::contact::constraints::Constraints;
use crate::contact::discretisation::Discretisation;
use crate::contact::law::penalty_lengths;
use crate::contact::mortar_set::{self, MortarSet, MortarState, PenaltyData};
use crate::contact::{
    ContactElement, ContactLaw, ContactOptions, ContactPair, ContactSet, ElementLaw,
    FrictionOutcome, FrictionState, Nodes, element_laws, softer,
};
use crate::error::{Result, ensure_finite};
use crate::fem::assembly::{DofMap, NOT_FREE};
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
    /// The weighted gaps' state, when some pair is under the mortar
    /// weighting.
    pub mortar: Option<MortarState>,
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
        Some(options) => solve_contact(session, input, options, None, (info, warnings), timings),
    }
}

/// Where a contact solve's loop starts: the constraints' initial set
/// (`None`), or a load step's warm start — the set and friction state a
/// step before ended with.
pub(crate) type Start<'s> = Option<(&'s [bool], &'s FrictionState)>;

/// What every solve does first: the bodies' part assembled afresh (a load
/// history's K₁, strip or mortar, is gone), with the solve's statistics
/// begun and the tempering's warnings.
pub(crate) fn prepare(
    session: &mut Session,
    input: &Input<'_>,
    timings: &mut Timings,
) -> Result<(SolveInfo, Vec<String>)> {
    ensure_unknowns(&session.dofs)?;
    session.holds = session::Holds::Nothing;
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

/// The constraints of a built-in solve: the strip pairs' elements of B,
/// each element's law from its pair's softer body, frictional
/// (docs/method.md §6.15) when a pair has μ > 0 under the frictionless
/// law, starting from the slip `anchors` (empty: none); and the mortar
/// pairs' weighted gaps (§6.11) with the strip's penalty per pair; over the
/// session's unknowns, for the prescribed displacements `prescribed`.
pub(crate) fn constraints<'a>(
    input: &Input<'a>,
    prescribed: &'a [f64],
    contact: &'a Discretisation,
    dofs: &DofMap,
    options: &ContactOptions,
    anchors: &[f64],
) -> Result<Constraints<'a>> {
    let strip = strip_set(input, prescribed, contact, dofs, options, anchors)?;
    let mortar = mortar_penalties(input, prescribed, contact, dofs, options)?;
    Ok(Constraints::new(strip, mortar, prescribed))
}

/// The strip pairs' elements of B in one solve ([`constraints`]).
fn strip_set<'a>(
    input: &Input<'a>,
    prescribed: &[f64],
    contact: &'a Discretisation,
    dofs: &DofMap,
    options: &ContactOptions,
    anchors: &[f64],
) -> Result<ContactSet<'a>> {
    let mesh = input.elements.mesh();
    let soft = pair_material(input, contact.elements(), dofs);
    let strip = contact.strip();
    let laws = element_laws(mesh.index_base(), strip, &soft, mesh.size(), options)?;
    let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
    let set = ContactSet::new(Nodes::of(mesh), strip, laws, equation, prescribed, options)?;
    // μ = 0 everywhere is the frictionless set itself, bit for bit; the
    // stick law already ties the surfaces.
    let frictional = options.law == ContactLaw::Frictionless
        && strip.iter().any(|e| input.pairs[e.pair].friction > 0.0);
    if !frictional {
        return Ok(set);
    }
    let mu: Vec<f64> = strip.iter().map(|e| input.pairs[e.pair].friction).collect();
    // The stick part's shear modulus: G_c = E_c / (2(1 + ν)) of the pair's
    // softer body, as in the stick law.
    let shear: Vec<f64> = strip
        .iter()
        .map(|e| {
            let s = soft(e.pair);
            let e_c = options.contact_modulus.unwrap_or(s.young());
            e_c / (2.0 * (1.0 + s.poisson()))
        })
        .collect();
    set.with_friction(&mu, &shear, anchors, prescribed)
}

/// The mortar pairs' weighted gaps as penalties in one solve
/// ([`constraints`]); options the weighting does not serve are refused.
fn mortar_penalties(
    input: &Input<'_>,
    prescribed: &[f64],
    contact: &Discretisation,
    dofs: &DofMap,
    options: &ContactOptions,
) -> Result<MortarSet> {
    if !contact.has_mortar() {
        return Ok(MortarSet::default());
    }
    let pairs = contact
        .gaps()
        .iter()
        .map(|g| (g.pair, &input.pairs[g.pair]));
    mortar_set::check_options(options, pairs)?;
    let moduli = pair_moduli(input, contact.elements(), dofs, options);
    let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
    let data = PenaltyData {
        moduli: &moduli,
        lambda: options.lambda.unwrap_or(input.elements.mesh().size()),
        h_c: penalty_lengths(contact.elements()),
        equation: &equation,
        prescribed,
    };
    MortarSet::new(contact.gaps(), data)
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

/// A contact solve: the active-set loop over the constraints, from
/// `start`, on the bodies' part [`prepare`] assembled.
pub(crate) fn solve_contact(
    session: &mut Session,
    input: &Input<'_>,
    options: &ContactOptions,
    start: Start<'_>,
    (mut info, mut warnings): (SolveInfo, Vec<String>),
    timings: &mut Timings,
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
    let anchors = start.map_or(&[][..], |(_, f)| &f.anchors);
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
        interface: condense.then_some(interface),
        options: *options,
    };
    let flags = start.map(|warm| history::warm_start(&set, warm));
    let factor = (&mut *chol, &mut *system);
    let settled = ActiveSetLoop::new(loop_input, factor, (timings, &mut info), flags).run()?;
    info.memory_bytes = session_memory(at, system, chol) + settled.condensed_bytes;
    info.relative_residual = system.relative_residual(pattern, &settled.x);
    info.condition_estimate = chol.condition_estimate();
    info.timings = *timings;
    finite_statistics(&info)?;
    conditioning_warning(&info, &mut warnings);
    let x = &settled.x;
    let verdict = (settled.active, &settled.friction[..]);
    let contact = contact_outcome(
        (&set, input.pairs, mesh),
        |i| x[i],
        verdict,
        settled.history,
        info,
        &mut warnings,
    )?;
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
    ue_of: impl Fn(usize) -> [f64; 6],
    active: &[bool],
    pressure: &[f64],
    warnings: &mut Vec<String>,
) {
    let (mut worst, mut at) = (0.0f64, None);
    for k in 0..set.len() {
        if active[k] {
            let r = SOLVE_ERROR_FACTOR * set.pressure_rounding(k, &ue_of(k));
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

/// Pressures, contact length and penetration of the settled set (flags
/// over parts, with its friction load factors), the unknowns' values read
/// by `value`, and its frictional state.
pub(crate) fn contact_outcome(
    (set, pairs, mesh): (&Constraints<'_>, &[ContactPair], &Mesh),
    value: impl Fn(usize) -> f64,
    (active, friction): (Vec<bool>, &[f64]),
    history: Vec<report::IterationRecord>,
    info: SolveInfo,
    warnings: &mut Vec<String>,
) -> Result<ContactOutcome> {
    let settled = set.settled((&active, friction), &value, mesh)?;
    let strip = set.strip();
    let name = |k: usize| format!("contact element {}", k + strip.nodes().base);
    if let Some(f) = &settled.friction {
        ensure_finite(f.shear.iter().copied(), 1, "shear traction", name)?;
        ensure_finite(f.dissipation.iter().copied(), 1, "slip dissipation", name)?;
    }
    let ue_of = |k: usize| set.element_values(k, &value);
    let (mut lc, mut max_pen) = (0.0, 0.0f64);
    for (k, el) in strip.elements().iter().enumerate() {
        if settled.active[k] && el.edge_length > 0.0 {
            max_pen = max_pen.max(-strip.opening(k, &ue_of(k)) / el.edge_length);
        }
    }
    // The part of each edge that faces the other side, the longer-active
    // family of each contact zone (§6.8, §6.11).
    let (zones_lc, one_sided) = crate::contact::conformity::contact_length_and_warnings(
        strip.elements(),
        &settled.active,
        pairs,
    );
    lc += zones_lc;
    ensure_finite(
        settled.pressure.iter().copied(),
        1,
        "contact pressure",
        name,
    )?;
    precision_warning(strip, ue_of, &settled.active, &settled.pressure, warnings);
    warnings.extend(one_sided);
    let mut active_count = settled.active.iter().filter(|&&a| a).count();
    if let Some(m) = &settled.mortar {
        let on = || m.nodes.iter().filter(|n| n.active);
        lc += on().map(|n| n.tributary).sum::<f64>();
        max_pen = on().fold(max_pen, |worst, n| worst.max(-n.gap));
        active_count += on().count();
    }
    ensure_finite([lc, max_pen], 1, "contact length or penetration", |_| {
        "the contact report".to_string()
    })?;
    let report = ContactReport {
        iterations: history.len(),
        elements: strip.len() + set.mortar().len(),
        active: active_count,
        contact_length: lc,
        max_penetration: max_pen,
        history,
        info,
    };
    Ok(ContactOutcome {
        flags: active,
        active: settled.active,
        pressure: settled.pressure,
        laws: strip.laws().to_vec(),
        friction: settled.friction,
        report,
        mortar: settled.mortar,
    })
}
