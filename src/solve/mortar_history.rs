//! Load histories under the mortar weighting (docs/method.md §6.11, "Load
//! steps under the mortar weighting"): the strip's design (§6.12) for the
//! weighted gaps.
//!
//! The first step is a mortar contact solve of its scaled loads; when its
//! condensed loop settled the set, the session keeps K₁'s factor (the
//! bodies and the initial set) with the condensed interface system, and
//! two solutions of K₁: x_load for the loads and prescribed displacements
//! at factor 1 (with the prescribed part of K₁'s penalty loads) and x_gap
//! for K₁'s penalty loads of the initial gaps. Every penalty's stiffness
//! (κ/m_i) c_i c_iᵀ is independent of the loads and its load
//! −(κ/m_i)G_i⁰(t) c_i is affine in t (G_i⁰(t) = G_i,initial + t c_i·u_p),
//! so K₁'s solution at t is x₁(t) = t x_load + x_gap, and a later step is
//! the condensed loop alone from the step before's set: dense work on the
//! interface, no assembly and no sparse solve. New loads cost one assembly
//! and one sparse solve (x_load anew). The field of a step is recovered
//! when asked for ([`recover`]): u = x₁ + K₁⁻¹P(Δg − ΔC u_I), refined
//! against the step's matrix (K₁'s held by the session, plus the switched
//! penalties), or solved with a factorisation of that matrix where the
//! refinement cannot reach working accuracy.

use super::active_set::RECOVERED;
use super::condensed::{Condensed, FactorSnapshot};
use super::diagnostics::singular_error;
use super::history::Key;
use super::linear::{Structure, check_finite};
use super::mortar::{
    Penalty, Run, Settled, add_changed_forces, at_interface, differing, outcome, session_penalties,
};
use super::report::{SolveInfo, Timings};
use super::session::{Session, Settings, Wanted, analyse, factorisation};
use super::{Field, Input, Outcome};
use crate::contact::{ActiveSet, ContactOptions};
use crate::error::{Error, Result, Status};
use crate::fem::assembly::{NOT_FREE, Pattern};
use crate::linalg::Cholesky;
use crate::linalg::refine::{Budget, norm_inf, refine, refine_by};

/// A mortar load history's state (module documentation).
pub(crate) struct MortarHistory {
    key: Key,
    /// The solver settings K₁ was factorised with.
    settings: Settings,
    /// The slave nodes whose penalties K₁ holds.
    reference: Vec<bool>,
    /// The problem revision whose loads `x_load` and `rhs_body` are of.
    loads: u64,
    /// The bodies' right-hand side at factor 1 (over the free unknowns).
    rhs_body: Vec<f64>,
    x_load: Vec<f64>,
    x_gap: Vec<f64>,
    /// The condensed interface system, its factor that of `factor_set`.
    sys: Condensed,
    factor_set: Vec<bool>,
    /// The statistics of the first step's solve (what a step reports for
    /// the residual and condition of K₁).
    first: SolveInfo,
    /// ‖K₁‖∞, against which a step's size is judged.
    k1_norm: f64,
}

/// A step whose whole field waits until asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Pending {
    /// The history it belongs to, and the loads' revision.
    key: Key,
    loads: u64,
    /// The load factor.
    pub t: f64,
    /// The interface values and the settled set.
    ui: Vec<f64>,
    active: Vec<bool>,
}

/// The interface factor of a history before a step: what a failed or
/// reverted step puts back, so that the next step goes on bit for bit.
#[derive(Debug, Clone)]
pub(crate) struct Snapshot {
    key: Key,
    factor_set: Vec<bool>,
    factor: FactorSnapshot,
}

impl MortarHistory {
    /// The condensed interface's unknowns.
    pub fn interface_len(&self) -> usize {
        self.sys.len()
    }

    /// Whether a step of `key` under `settings` goes on with this history.
    pub fn continues(&self, key: &Key, settings: Settings) -> bool {
        self.key == *key && self.settings == settings
    }

    /// The interface factor now.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            key: self.key,
            factor_set: self.factor_set.clone(),
            factor: self.sys.factor_snapshot(),
        }
    }

    /// Puts back the interface factor of `snapshot`, if it is of this
    /// history.
    pub fn restore(&mut self, snapshot: &Snapshot) {
        if snapshot.key == self.key
            && snapshot.factor_set.len() == self.factor_set.len()
            && self.sys.restore_factor(&snapshot.factor).is_ok()
        {
            self.factor_set.clone_from(&snapshot.factor_set);
        }
    }

    /// K₁'s solution at load factor `t`.
    fn x1_at(&self, t: f64) -> Vec<f64> {
        self.x_load
            .iter()
            .zip(&self.x_gap)
            .map(|(l, g)| t * l + g)
            .collect()
    }
}

/// Begins a history after a first step settled by the condensed loop
/// (`settled`), whose statistics are `first`: the bodies' right-hand side
/// at factor 1 (`unit`: the problem's loads and prescribed values
/// unscaled), x_load and x_gap. Leaves the session's assembled system
/// holding K₁.
pub(crate) fn begin(
    session: &mut Session,
    unit: &Input<'_>,
    options: &ContactOptions,
    (key, revision): (Key, u64),
    (settled, first): (Settled, SolveInfo),
) -> Result<MortarHistory> {
    let Settled {
        reference,
        sys,
        factor_set,
    } = settled;
    let (rhs_body, x_load) = loads_of(session, unit, options, &reference)?;
    let penalties = session_penalties(session, unit, options)?;
    let mut r_gap = vec![0.0; rhs_body.len()];
    for (p, _) in penalties.iter().zip(&reference).filter(|(_, on)| **on) {
        add_load(p, p.g_initial, &mut r_gap);
    }
    let x_gap = k1_solve(session, r_gap)?;
    let k1_norm = norm_inf(&session.pattern, session.system.values());
    Ok(MortarHistory {
        key,
        settings: unit.settings,
        reference,
        loads: revision,
        rhs_body,
        x_load,
        x_gap,
        sys,
        factor_set,
        first,
        k1_norm,
    })
}

/// Puts back into the session the history `h` that a failed solve took
/// out (`Model::run`, a step that began a new history): K₁'s matrix
/// assembled again — the same operations in the same order, so the same
/// values to the bit — and factorised with the history's analysis, so that
/// the steps after, and the fields waiting on it, go on as if the solve
/// had not been tried. Dropped when the stiffness changed since (no step
/// continues it then) or the rebuild fails (the steps after factorise
/// anew).
pub(crate) fn put_back(session: &mut Session, unit: &Input<'_>, stiffness: u64, h: MortarHistory) {
    if h.key.stiffness == stiffness && rebuild(session, unit, &h).is_ok() {
        session.mortar_history = Some(h);
    }
}

/// K₁ of `h` in the session's system and factor.
fn rebuild(session: &mut Session, unit: &Input<'_>, h: &MortarHistory) -> Result<()> {
    assemble_k1(session, unit, h.key.options(), &h.reference)?;
    let Session {
        dofs,
        pattern,
        analysis,
        system,
        ..
    } = &mut *session;
    let want = Wanted {
        last: h.sys.unknowns(),
        zeros: &[],
    };
    let structure = (unit.elements.mesh(), &*dofs, &*pattern);
    let (mut timings, mut info) = (Timings::default(), SolveInfo::default());
    let chol = factorisation(
        analysis,
        structure,
        h.settings,
        want,
        &mut timings,
        &mut info,
    )?;
    chol.factorize(pattern, system.values())
        .map_err(|_| Error::state("K₁ of the load history could not be factorised again"))?;
    Ok(())
}

/// Adds −(κ/m_i) g c_i, the load of penalty `p` for the gap `g`, to `r`.
fn add_load(p: &Penalty, g: f64, r: &mut [f64]) {
    for (u, c) in p.unknowns.iter().zip(&p.coef) {
        if let Some(j) = u {
            r[*j] -= p.stiffness * g * c;
        }
    }
}

/// The bodies' right-hand side at factor 1 and x_load: the system
/// assembled for the unscaled loads, K₁'s set switched back in (so that
/// the system holds K₁ again, the same operations in the same order), and
/// K₁ solved for the bodies' loads with the prescribed part of the set's
/// penalty loads.
fn loads_of(
    session: &mut Session,
    unit: &Input<'_>,
    options: &ContactOptions,
    reference: &[bool],
) -> Result<(Vec<f64>, Vec<f64>)> {
    let (rhs_body, penalties) = assemble_k1(session, unit, options, reference)?;
    let mut r_load = rhs_body.clone();
    for (p, _) in penalties.iter().zip(reference).filter(|(_, on)| **on) {
        add_load(p, p.g_rest - p.g_initial, &mut r_load);
    }
    let x_load = k1_solve(session, r_load)?;
    Ok((rhs_body, x_load))
}

/// Makes the session's system K₁: the bodies assembled for `unit` (the
/// unscaled loads), then the penalties of `reference` switched in, in
/// order — the same operations as the first step's, so the same matrix
/// to the bit. Gives the bodies' right-hand side and the penalties at
/// factor 1.
fn assemble_k1(
    session: &mut Session,
    unit: &Input<'_>,
    options: &ContactOptions,
    reference: &[bool],
) -> Result<(Vec<f64>, Vec<Penalty>)> {
    session.assemble_body(&unit.elements, (unit.f_ext, unit.prescribed))?;
    let rhs_body = session.system.rhs().to_vec();
    let penalties = session_penalties(session, unit, options)?;
    let Session {
        pattern, system, ..
    } = &mut *session;
    for (p, _) in penalties.iter().zip(reference).filter(|(_, on)| **on) {
        p.toggle(system, pattern, 1.0);
    }
    Ok((rhs_body, penalties))
}

/// K₁⁻¹ r, refined against K₁ (which the session's system holds).
fn k1_solve(session: &Session, mut r: Vec<f64>) -> Result<Vec<f64>> {
    let chol = k1(session)?;
    let b = r.clone();
    chol.solve(&mut r)?;
    let values = session.system.values();
    refine(&session.pattern, values, &b, &mut r, &mut |v| chol.solve(v))?;
    Ok(r)
}

/// The factor of K₁.
fn k1(session: &Session) -> Result<&Cholesky> {
    session
        .analysis
        .as_ref()
        .map(|a| &a.chol)
        .ok_or_else(|| Error::state("the load step's factorisation is gone: run the step again"))
}

/// One step of the history `h` at load factor `t` (`scaled`: the problem's
/// loads and prescribed values times t; `unit`: unscaled), from the set
/// `warm` (`None`: K₁'s). `Ok(None)` when the condensed system lost its
/// accuracy (the caller solves the step afresh). On error the history is
/// as before but for its interface factor (see [`Snapshot`]).
pub(crate) fn step(
    session: &mut Session,
    (scaled, unit): (&Input<'_>, &Input<'_>),
    options: &ContactOptions,
    h: &mut MortarHistory,
    (t, warm, revision): (f64, Option<&[bool]>, u64),
    timings: &mut Timings,
) -> Result<Option<Outcome>> {
    super::mortar::check_options(options, scaled.pairs)?;
    let mut info = SolveInfo {
        unknowns: session.dofs.n_free(),
        matrix_nnz: session.pattern.nnz(),
        ..Default::default()
    };
    if h.loads != revision {
        // A non-proportional history: the new loads' x_load.
        let t0 = std::time::Instant::now();
        let (rhs_body, x_load) = loads_of(session, unit, options, &h.reference)?;
        (h.rhs_body, h.x_load, h.loads) = (rhs_body, x_load, revision);
        timings.solve += t0.elapsed().as_secs_f64();
    }
    let t0 = std::time::Instant::now();
    let penalties = session_penalties(session, scaled, options)?;
    let n = penalties.len();
    let first = warm
        .filter(|w| w.len() == n)
        .map_or_else(|| h.reference.clone(), <[bool]>::to_vec);
    let x1 = h.x1_at(t);
    check_size(h, &x1, t)?;
    let y = h.sys.gather(&x1);
    let mesh = scaled.elements.mesh();
    let Session {
        dofs,
        pattern,
        analysis,
        system,
        ..
    } = &mut *session;
    let chol = &mut analysis
        .as_mut()
        .ok_or_else(|| Error::state("the load history's factorisation is gone"))?
        .chol;
    let mut run = Run {
        at: Structure {
            mesh,
            dofs,
            pattern,
        },
        input: scaled,
        penalties: &penalties,
        chol,
        system,
        set: ActiveSet::new(first),
        in_system: h.reference.clone(),
        log: Vec::new(),
        max_iterations: options.max_iterations,
    };
    let reference = h.reference.clone();
    let ui = run.interface_loop(&mut h.sys, &y, &reference, &mut h.factor_set)?;
    timings.interface += t0.elapsed().as_secs_f64();
    let Some(ui) = ui else { return Ok(None) };
    let (active, history) = run.set.into_parts();
    info.interface_unknowns = h.sys.len();
    info.relative_residual = h.first.relative_residual;
    info.condition_estimate = h.first.condition_estimate;
    info.factor_nnz = h.first.factor_nnz;
    info.factorization_bytes = h.first.factorization_bytes;
    info.memory_bytes = h.first.memory_bytes;
    info.timings = *timings;
    let gaps = session.mortar.clone().unwrap_or_default();
    let value = |j: usize| ui[at_interface(&h.sys, j)];
    let contact = outcome((&penalties, gaps), &active, value, (history, info), mesh)?;
    let pending = Pending {
        key: h.key,
        loads: h.loads,
        t,
        ui,
        active,
    };
    Ok(Some(Outcome {
        u: Field::Pending(super::Pending::Mortar(pending)),
        log: Vec::new(),
        info,
        contact: Some(contact),
        warnings: Vec::new(),
    }))
}

/// Refuses a step whose K₁ solution `x1`, or its product with K₁, is not
/// a finite double: a load factor so large that the residual of the
/// step's recovery could overflow (as a solve's does). ‖K₁‖‖x₁‖ bounds
/// what the recovery computes, so this refuses a little before a contact
/// solve of the same loads would (at 10^299.75 rather than above 1e300 on
/// a review's two-block scene; on Hertz both refuse from 1e296).
fn check_size(h: &MortarHistory, x1: &[f64], t: f64) -> Result<()> {
    let size = x1.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let loads = h.rhs_body.iter().fold(0.0f64, |m, v| m.max((t * v).abs()));
    if (h.k1_norm * size).is_finite() && loads.is_finite() {
        return Ok(());
    }
    Err(Error::new(
        Status::NumericalFailure,
        format!(
            "the load step at factor {t:e} overflows: ‖K₁‖·‖u‖ = {:e} is beyond double \
             precision; scale the loads, the prescribed displacements or the units",
            h.k1_norm * size
        ),
    ))
}

/// The whole field of a pending step (global DOFs), `scaled` the problem
/// with its loads and prescribed values times the step's factor (module
/// documentation).
pub(crate) fn recover(
    session: &Session,
    scaled: &Input<'_>,
    pending: &Pending,
) -> Result<Vec<f64>> {
    let stale = || Error::state("the load step's factorisation is gone: run the step again");
    let h = session.mortar_history.as_ref().ok_or_else(stale)?;
    if h.key != pending.key || h.loads != pending.loads {
        return Err(stale());
    }
    let chol = k1(session)?;
    let penalties = session_penalties(session, scaled, h.key.options())?;
    let active = &pending.active;
    let changes: Vec<(usize, f64)> = differing(active, &h.reference)
        .into_iter()
        .map(|k| (k, if active[k] { 1.0 } else { -1.0 }))
        .collect();
    let sys = &h.sys;
    let x1 = h.x1_at(pending.t);
    let mut x = vec![0.0; x1.len()];
    add_changed_forces(&penalties, &changes, (sys, &pending.ui), true, &mut x);
    chol.solve(&mut x)?;
    x.iter_mut().zip(&x1).for_each(|(a, b)| *a += b);
    // The step's system: K₁ (held by the session) with the switched
    // penalties, and its right-hand side.
    let mut rhs: Vec<f64> = h.rhs_body.iter().map(|b| pending.t * b).collect();
    for (p, _) in penalties.iter().zip(active).filter(|(_, on)| **on) {
        add_load(p, p.g_rest, &mut rhs);
    }
    let (pattern, values) = (&session.pattern, session.system.values());
    let product = |v: &[f64], y: &mut [f64]| {
        pattern.sym_mul(values, v, y);
        for &(k, s) in &changes {
            let p = &penalties[k];
            let cv = p.gap(|j| v[j]) - p.g_rest;
            add_load(p, -s * cv, y);
        }
    };
    // The interface factor is the step's own when no step came after it.
    let exact = h.factor_set == *active && sys.is_factored();
    let mut approx = |r: &mut [f64]| -> Result<()> {
        chol.solve(r)?;
        if exact {
            let di = sys.solve(&sys.gather(r), &vec![0.0; sys.len()])?;
            let mut p = vec![0.0; r.len()];
            add_changed_forces(&penalties, &changes, (sys, &di), false, &mut p);
            chol.solve(&mut p)?;
            r.iter_mut().zip(&p).for_each(|(a, b)| *a += b);
        }
        Ok(())
    };
    let k_norm = norm_inf(pattern, values);
    let budget = Budget::APPROXIMATE;
    let mut omega = refine_by(&product, k_norm, &rhs, &mut x, &mut approx, budget)?;
    let mesh = scaled.elements.mesh();
    let at = Structure {
        mesh,
        dofs: &session.dofs,
        pattern,
    };
    let context = format!(" (mortar load step at factor {:?})", pending.t);
    if omega.is_nan() || omega > RECOVERED || x.iter().any(|v| !v.is_finite()) {
        // K₁'s factor is too poor an inverse of the step's matrix (or the
        // interface factor is a later step's): the step's matrix is
        // factorised itself, beside K₁, which the steps after still need.
        let step = (&penalties[..], &changes[..]);
        (x, omega) = solved_whole(at, h.settings, (values, step), &rhs, &context)?;
    }
    if omega.is_nan() || omega > RECOVERED {
        return Err(Error::new(
            Status::NumericalFailure,
            format!(
                "the field could not be solved to working accuracy (backward error \
                 {omega:.1e}, above {RECOVERED:.0e}){context}"
            ),
        ));
    }
    check_finite(at, &x, &context)?;
    Ok(session.dofs.expand(&x, scaled.prescribed))
}

/// The penalties switched since K₁: (index, +1 in or −1 out).
type Changes<'c> = (&'c [Penalty], &'c [(usize, f64)]);

/// The field of a step's system — K₁'s `values` with the `changes` of
/// `penalties` — by a factorisation of its own matrix, refined: the field
/// and its backward error.
fn solved_whole(
    at: Structure<'_>,
    settings: Settings,
    (values, (penalties, changes)): (&[f64], Changes<'_>),
    rhs: &[f64],
    context: &str,
) -> Result<(Vec<f64>, f64)> {
    let whole = Wanted {
        last: &[],
        zeros: &[],
    };
    let mut chol = analyse((at.mesh, at.dofs, at.pattern), settings, whole)?;
    let mut matrix = crate::error::reserved::<f64>(values.len(), "the load step's matrix")?;
    matrix.extend_from_slice(values);
    for &(k, s) in changes {
        add_penalty(at.pattern, &mut matrix, &penalties[k], s);
    }
    chol.factorize(at.pattern, &matrix)
        .map_err(|e| singular_error(at.mesh, at.dofs, e, context))?;
    let mut x = rhs.to_vec();
    chol.solve(&mut x)?;
    let product = |v: &[f64], y: &mut [f64]| at.pattern.sym_mul(&matrix, v, y);
    let k_norm = norm_inf(at.pattern, &matrix);
    let mut solve = |r: &mut [f64]| chol.solve(r);
    let omega = refine_by(&product, k_norm, rhs, &mut x, &mut solve, Budget::DIRECT)?;
    Ok((x, omega))
}

/// Adds `sign` times the stiffness of penalty `p` into `matrix`.
fn add_penalty(pattern: &Pattern, matrix: &mut [f64], p: &Penalty, sign: f64) {
    let unknowns: Vec<usize> = p.unknowns.iter().map(|u| u.unwrap_or(NOT_FREE)).collect();
    let ke: Vec<f64> = p
        .coef
        .iter()
        .flat_map(|a| p.coef.iter().map(move |b| sign * p.stiffness * a * b))
        .collect();
    pattern.add_element(matrix, &unknowns, &ke);
}
