//! The `repr(C)` mirrors of the Rust types (enums, options, statistics,
//! reports) and the conversions between them, each refusing a value out of
//! range with a message naming the argument.

use std::ffi::c_int;

use super::plumbing::slice_in;
use crate::contact::{ContactLaw, ContactOptions, InversionTest};
use crate::error::{Error, Result};
use crate::fem::element::Jmin;
use crate::fem::material::PlaneMode;
use crate::model::Component;
use crate::model::solution::{ContactReport, SolveInfo};

/// How Jmin is chosen (argument `mode` of `tfem_set_tempering`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TemperingMode {
    /// Jmin = min(h³/λ, h²/10), λ = larger side of the mesh's bounding box
    /// (default): an element whose apex stands at least a tenth of its
    /// longest edge h above it is never softened.
    Auto = 0,
    /// Jmin = h³/λ with λ = `value` (a length in model units).
    Lambda = 1,
    /// Jmin = `value` for every element (length²).
    FixedJmin = 2,
    /// Plain FEM (no tempering); zero-Jacobian elements are an error.
    Off = 3,
}

/// The fill-reducing ordering of the factorisation (argument `ordering` of
/// `tfem_set_ordering`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OrderingMode {
    /// Nested dissection from 10 000 unknowns, AMD below (default).
    Auto = 0,
    /// faer's approximate minimum degree.
    Amd = 1,
    /// Geometric nested dissection on the node coordinates.
    NestedDissection = 2,
}

/// How the contact pairs' energy is weighted along their interfaces
/// (argument `weighting` of `tfem_set_contact_weighting`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactWeightingMode {
    /// The elements of the contact mesh B (the seed's method) for every
    /// pair.
    Strip = 0,
    /// The sampled mortar weighting for every pair: one weighted gap per
    /// node of each interface's coarser side; frictionless.
    Mortar = 1,
    /// Each pair what is right for its interface (the default): B where
    /// the two sides' nodes match, the mortar weighting where they do not,
    /// B for a pair with friction or a contact mesh of its own.
    Auto = 2,
}

/// Options of `tfem_solve_contact`. Fill with `tfem_contact_options_default`
/// and change what you need.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct TfemContactOptions {
    /// A `ContactLaw` value: 0 = frictionless (default), 1 = stick.
    pub law: c_int,
    /// E_c of the contact elements; 0 = the smaller E of the two bodies, or
    /// where one side of a pair has every DOF of its contact nodes prescribed
    /// (a rigid tool) the other body's E, so that a rigid tool's nominal E
    /// does not set the penalty. The
    /// host contact context (`tfem_contact_set_options`) still takes the
    /// smaller E of its two sides: give a rigid side its neighbour's E, or
    /// set `contact_modulus`.
    pub contact_modulus: f64,
    /// λ of the contact elements (Jmin = h³/λ), model length units; 0 = the
    /// larger side of the mesh's bounding box.
    pub lambda: f64,
    /// An `InversionTest` value: 0 = linearised J (default), 1 = literal J.
    pub inversion_test: c_int,
    /// Cap on active-set iterations (default 50).
    pub max_iterations: c_int,
    /// 1 = refactorise the matrix at every active-set iteration; 0 (default)
    /// = condense the changes on the contact interface (faster, exact).
    pub refactorize: c_int,
}

/// Statistics of a solve. Times are wall-clock seconds.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct TfemSolveInfo {
    /// Unknowns after Dirichlet elimination.
    pub unknowns: i64,
    /// Stored entries of the matrix's upper triangle.
    pub matrix_nnz: i64,
    /// Stored entries of the Cholesky factor.
    pub factor_nnz: i64,
    /// Numeric factorisations performed.
    pub factorizations: i64,
    /// Unknowns of the condensed contact interface (0 if not condensed).
    pub interface_unknowns: i64,
    /// ‖K u − f‖ / ‖f‖ of the final system.
    pub relative_residual: f64,
    /// Condition estimate of the Jacobi-scaled final matrix.
    pub condition_estimate: f64,
    /// Bytes held by pattern, matrix values, factor and dense interface.
    pub memory_bytes: i64,
    /// Bytes one numeric factorisation needs at its peak (factor, symbolic
    /// structure, workspace).
    pub factorization_bytes: i64,
    /// Pattern and symbolic analysis (0 when reused).
    pub time_analysis: f64,
    /// Element matrices and scatter-add.
    pub time_assembly: f64,
    /// Numeric factorisations, including the singularity check.
    pub time_factorization: f64,
    /// Triangular solves.
    pub time_solve: f64,
    /// Dense work on the condensed contact interface.
    pub time_interface: f64,
    /// The whole call.
    pub time_total: f64,
}

/// Report of `tfem_solve_contact`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct TfemContactReport {
    /// Active-set iterations (solves).
    pub iterations: c_int,
    /// Elements of the contact mesh B (under the mortar weighting,
    /// `tfem_set_contact_weighting`: slave nodes).
    pub elements: c_int,
    /// Active elements at convergence (under the mortar weighting: slave
    /// nodes).
    pub active: c_int,
    /// Contact length ℓc, model length units: the summed interface-edge
    /// length of the active elements, each as far as it faces the other
    /// side, of one of B's two families (edges on one side or on the other)
    /// in each contact zone (a pair's active elements connected through
    /// shared nodes), the one active over the longer length.
    /// (Not their mean, which counts half the width of a contact carried by
    /// one family alone; docs/method.md §6.8.) Under the
    /// mortar weighting: the active slave nodes' summed tributaries.
    pub contact_length: f64,
    /// Largest normal interpenetration, model length units (under the
    /// mortar weighting: of an active slave node's mean gap).
    pub max_penetration: f64,
    /// Solver statistics.
    pub info: TfemSolveInfo,
}

/// What the tolerance of `tfem_solve_adaptive` bounds (argument `goal`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AdaptGoal {
    /// The relative error in the energy norm.
    Energy = 0,
    /// The relative error of the compliance (f·u), the square of the
    /// energy's.
    Compliance = 1,
}

/// Report of `tfem_solve_adaptive`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct TfemAdaptReport {
    /// Solves made (cycles); each cycle's numbers from
    /// `tfem_get_adapt_cycles`.
    pub cycles: c_int,
    /// 1 if the last estimate meets the tolerance (and, with contact, the
    /// contact zones' edges are located to it), 0 if a limit stopped the
    /// refinement first (a warning then says what was reached).
    pub reached: c_int,
    /// Unknowns of the last solve.
    pub unknowns: i64,
    /// Triangles of the refined mesh.
    pub triangles: i64,
    /// The last estimate of the goal's relative error.
    pub estimate: f64,
    /// Seconds of the whole adaptive solve, refinements included.
    pub seconds: f64,
}

pub(super) fn component(c: i32) -> Result<Component> {
    Component::from_i32(c)
        .ok_or_else(|| Error::argument(format!("component = {c} must be 0 (x) or 1 (y)")))
}

pub(super) fn plane(p: i32) -> Result<PlaneMode> {
    PlaneMode::from_i32(p).ok_or_else(|| {
        Error::argument(format!(
            "plane = {p} must be 0 (plane strain), 1 (plane stress) or 2 (axisymmetric)"
        ))
    })
}

pub(super) fn info_out(i: &SolveInfo) -> TfemSolveInfo {
    TfemSolveInfo {
        unknowns: i.unknowns as i64,
        matrix_nnz: i.matrix_nnz as i64,
        factor_nnz: i.factor_nnz as i64,
        interface_unknowns: i.interface_unknowns as i64,
        factorizations: i.factorizations as i64,
        relative_residual: i.relative_residual,
        condition_estimate: i.condition_estimate,
        memory_bytes: i.memory_bytes as i64,
        factorization_bytes: i.factorization_bytes as i64,
        time_analysis: i.timings.analysis,
        time_assembly: i.timings.assembly,
        time_factorization: i.timings.factorization,
        time_solve: i.timings.solve,
        time_interface: i.timings.interface,
        time_total: i.timings.total,
    }
}

pub(super) fn report_out(r: &ContactReport) -> TfemContactReport {
    TfemContactReport {
        iterations: r.iterations as c_int,
        elements: r.elements as c_int,
        active: r.active as c_int,
        contact_length: r.contact_length,
        max_penetration: r.max_penetration,
        info: info_out(&r.info),
    }
}

pub(super) fn jmin_arg(jmin: f64) -> Result<Jmin> {
    if jmin == 0.0 {
        Ok(Jmin::Off)
    } else if jmin.is_finite() && jmin > 0.0 {
        Ok(Jmin::Tempered(jmin))
    } else {
        Err(Error::argument(format!(
            "jmin = {jmin:?} must be > 0 (tempered) or 0 (plain FEM)"
        )))
    }
}

pub(super) fn corners_arg(xy: *const f64) -> Result<[[f64; 2]; 3]> {
    let xy = slice_in(xy, 6, "xy")?;
    if let Some(k) = xy.iter().position(|v| !v.is_finite()) {
        return Err(Error::argument(format!(
            "xy[{k}] = {:?} is not finite",
            xy[k]
        )));
    }
    Ok([[xy[0], xy[1]], [xy[2], xy[3]], [xy[4], xy[5]]])
}

pub(super) fn options_in(o: &TfemContactOptions) -> Result<ContactOptions> {
    let law = match o.law {
        0 => ContactLaw::Frictionless,
        1 => ContactLaw::Stick,
        l => {
            return Err(Error::argument(format!(
                "options.law = {l} must be 0 (frictionless) or 1 (stick)"
            )));
        }
    };
    let test = match o.inversion_test {
        0 => InversionTest::Linearised,
        1 => InversionTest::Literal,
        t => {
            return Err(Error::argument(format!(
                "options.inversion_test = {t} must be 0 (linearised) or 1 (literal)"
            )));
        }
    };
    let opt = |v: f64, what: &str| -> Result<Option<f64>> {
        if v == 0.0 {
            Ok(None)
        } else if v.is_finite() && v > 0.0 {
            Ok(Some(v))
        } else {
            Err(Error::argument(format!(
                "options.{what} = {v:?} must be > 0, or 0 for the default"
            )))
        }
    };
    let max_iterations = usize::try_from(o.max_iterations)
        .ok()
        .filter(|&n| n > 0)
        .ok_or_else(|| {
            Error::argument(format!(
                "options.max_iterations = {} must be >= 1",
                o.max_iterations
            ))
        })?;
    let refactorize = match o.refactorize {
        0 => false,
        1 => true,
        r => {
            return Err(Error::argument(format!(
                "options.refactorize = {r} must be 0 (condense on the interface) or 1"
            )));
        }
    };
    Ok(ContactOptions {
        law,
        contact_modulus: opt(o.contact_modulus, "contact_modulus")?,
        lambda: opt(o.lambda, "lambda")?,
        test,
        max_iterations,
        refactorize,
    })
}
