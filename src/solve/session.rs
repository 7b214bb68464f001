//! What a solve derives from the structure of a problem — the unknowns,
//! the sparsity pattern, the element slots, the contact mesh B, the
//! symbolic analysis with its factor, and the storage of the assembled
//! system — kept and reused by every solve while the structure (mesh,
//! prescribed DOFs, contact pairs) is unchanged.

use std::time::Instant;

use rayon::prelude::*;

use super::linear::{Bookkeeping, Structure};
use super::memory;
use super::system::{AssembledSystem, SystemMatrix};
use crate::contact::discretisation::Discretisation;
use crate::contact::{ContactPair, ContactWeighting};
use crate::error::{Result, preflight};
use crate::fem::assembly::{DofMap, Pattern, Slots};
use crate::fem::body::{Softened, Target};
use crate::fem::element_loop::ElementLoop;
use crate::fem::mesh::Mesh;
use crate::linalg::{AnalyseParams, Cholesky, Ordering, Points};

/// Choices of the factorisation that change no result beyond round-off.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Settings {
    /// The fill-reducing ordering.
    pub ordering: Ordering,
    /// Factorise the two subtrees of a nested dissection concurrently.
    pub parallel_subtrees: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            ordering: Ordering::Auto,
            parallel_subtrees: true,
        }
    }
}

/// A symbolic analysis with its factor, and what it was made for.
pub(crate) struct Analysis {
    /// The unknowns numbered last (the condensed contact interface, or none).
    last: Vec<usize>,
    /// The value positions it was told are zero.
    zeros: Vec<usize>,
    /// The settings it was made with.
    settings: Settings,
    /// The factorisation.
    pub chol: Cholesky,
}

impl Analysis {
    /// The settings it was made with.
    pub fn settings(&self) -> Settings {
        self.settings
    }
}

/// What a solve asks of the analysis. An analysis is reused only when it
/// was made for exactly this request and the same settings, so that a
/// solve's result never depends on the solves before it (a refactorising
/// contact solve after a condensed one would otherwise inherit its
/// interface-last ordering, and its round-off).
#[derive(Clone, Copy)]
pub(crate) struct Wanted<'a> {
    /// The unknowns to number last.
    pub last: &'a [usize],
    /// Value positions that are zero in every matrix of this solve.
    pub zeros: &'a [usize],
}

/// Everything derived from one structure of a problem.
pub(crate) struct Session {
    /// The structure epoch of the problem it was built for.
    structure: u64,
    /// The unknowns.
    pub dofs: DofMap,
    /// The pattern of the reduced matrix: body triangles and every element
    /// of B (stored zeros while inactive, so that the symbolic analysis
    /// survives activation).
    pub pattern: Pattern,
    /// Each mesh triangle's [`Slots`] in `pattern`.
    pub slots: Vec<Slots>,
    /// How the contact pairs are discretised.
    pub contact: Discretisation,
    /// The symbolic analysis and factor, made on first need.
    pub analysis: Option<Analysis>,
    /// The assembled system: the storage of the matrix values, allocated
    /// with the pattern.
    pub system: AssembledSystem,
    /// What `system` and the factor hold.
    pub holds: Holds,
}

/// What the session's assembled system and factor hold, so that a call
/// that fails can tell what it overwrote: a solve's final system, a load
/// history's K₁ ([`super::history::History::intact`]), or neither.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Holds {
    /// Nothing another call relies on (a call is assembling or
    /// factorising).
    Nothing,
    /// The final system of the solve of this problem epoch.
    Solve(u64),
    /// K₁ of the load history of this number.
    History(u64),
}

impl Session {
    /// Derives the unknowns (the DOFs of used nodes that `is_prescribed`
    /// does not fix), B of every pair under `weighting`, the pattern and
    /// the slots.
    pub fn new(
        structure: u64,
        mesh: &Mesh,
        is_prescribed: impl Fn(usize) -> bool,
        pairs: &[ContactPair],
        weighting: ContactWeighting,
    ) -> Result<Session> {
        let n_nodes = mesh.nodes().len();
        let contact = Discretisation::build(mesh, pairs, weighting)?;
        let need = memory::session_bytes(n_nodes, mesh.triangles().len(), contact.elements().len());
        preflight(need, "the solve's set-up (unknowns and matrix pattern)")?;
        let used = mesh.node_body();
        let dofs = DofMap::new(n_nodes, 2, |g| used[g / 2].is_some() && !is_prescribed(g));
        let mut elements: Vec<[usize; 3]> = mesh.triangles().to_vec();
        // Every coupling a solve may switch on is in the pattern, so that
        // the symbolic analysis survives any active set.
        elements.extend(contact.couplings());
        let pattern = Pattern::build(&dofs, n_nodes, &elements);
        drop(elements);
        let system = AssembledSystem::new(pattern.nnz());
        let slots = triangle_slots(mesh, &dofs, &pattern);
        Ok(Session {
            structure,
            dofs,
            pattern,
            slots,
            contact,
            analysis: None,
            system,
            holds: Holds::Nothing,
        })
    }

    /// The structure epoch it was built for.
    pub fn structure_epoch(&self) -> u64 {
        self.structure
    }

    /// Assembles the bodies' part into the system (no contact element in)
    /// for the global vectors of external forces `f_ext` and prescribed
    /// values `prescribed`. Returns the elements tempering softens.
    pub fn assemble_body(
        &mut self,
        elements: &ElementLoop<'_>,
        f_ext: &[f64],
        prescribed: &[f64],
    ) -> Result<Softened> {
        let target = Target {
            dofs: &self.dofs,
            pattern: &self.pattern,
            slots: &self.slots,
        };
        self.system
            .assemble_body(elements, target, f_ext, prescribed)
    }

    /// The final matrix of the solve of problem epoch `epoch`.
    pub fn system_matrix(&self, epoch: u64) -> Option<SystemMatrix<'_>> {
        (self.holds == Holds::Solve(epoch)).then(|| self.system.matrix(&self.pattern, &self.dofs))
    }
}

/// Each mesh triangle's [`Slots`] in `pattern`.
fn triangle_slots(mesh: &Mesh, dofs: &DofMap, pattern: &Pattern) -> Vec<Slots> {
    let mut slots = vec![Slots::SEARCH; mesh.triangles().len()];
    const CHUNK: usize = 1 << 14;
    slots
        .par_chunks_mut(CHUNK)
        .zip(mesh.triangles().par_chunks(CHUNK))
        .for_each(|(slots, tris)| {
            for (s, tri) in slots.iter_mut().zip(tris) {
                let mut gd = [0usize; 6];
                dofs.element_dofs(tri, &mut gd);
                *s = pattern.slots(&gd.map(|g| dofs.free(g)));
            }
        });
    slots
}

/// A new symbolic analysis of `at`'s pattern as `want` asks with
/// `settings`, once the memory it takes is checked.
pub(crate) fn analyse(at: Structure<'_>, settings: Settings, want: Wanted<'_>) -> Result<Cholesky> {
    let Structure {
        mesh,
        dofs,
        pattern,
    } = at;
    let need = memory::analysis_bytes(pattern.n(), pattern.nnz());
    preflight(need, "the symbolic analysis (ordering)")?;
    // The unknowns' coordinates are only needed here (16 MB at 1M
    // unknowns in the plane, 24 MB in space), so they are not kept.
    let dim = mesh.dimension();
    let point = |g: usize| -> [f64; 3] {
        std::array::from_fn(|k| {
            if k < dim {
                mesh.coordinate(g / dim, k)
            } else {
                0.0
            }
        })
    };
    let unknowns = dofs.free_to_global().iter();
    let (plane, space): (Vec<[f64; 2]>, Vec<[f64; 3]>) = match dim {
        2 => (
            unknowns
                .map(|&g| {
                    let p = point(g);
                    [p[0], p[1]]
                })
                .collect(),
            Vec::new(),
        ),
        _ => (Vec::new(), unknowns.map(|&g| point(g)).collect()),
    };
    let coords = match dim {
        2 => Points::Plane(&plane),
        _ => Points::Space(&space),
    };
    let params = AnalyseParams {
        ordering: settings.ordering,
        coords: Some(coords),
        last: want.last,
        zeros: want.zeros,
        parallel_subtrees: settings.parallel_subtrees,
    };
    Cholesky::analyse(pattern, &params)
}

/// The factorisation of `analysis` for `at`, analysed as `want` asks with
/// `settings`: the existing one while it fits, else a new symbolic
/// analysis (timed in `books`). Fills the factor's sizes into `books`'
/// statistics.
pub(crate) fn factorisation<'a>(
    analysis: &'a mut Option<Analysis>,
    at: Structure<'_>,
    settings: Settings,
    want: Wanted<'_>,
    books: &mut Bookkeeping<'_>,
) -> Result<&'a mut Cholesky> {
    let fits = analysis
        .as_ref()
        .is_some_and(|a| a.settings == settings && a.last == want.last && a.zeros == want.zeros);
    if !fits {
        let t0 = Instant::now();
        let last = want.last;
        // Drop the old factor first: two at once may not fit in memory.
        *analysis = None;
        let chol = analyse(at, settings, want)?;
        *analysis = Some(Analysis {
            last: last.to_vec(),
            zeros: want.zeros.to_vec(),
            settings,
            chol,
        });
        books.timings.analysis += t0.elapsed().as_secs_f64();
    }
    // What the solve takes besides the factor, now that it holds its
    // memory (with the interface condensed, its dense matrices too).
    let need = memory::solve_bytes(at.dofs.n_global(), want.last.len());
    preflight(need, "the solve's vectors and interface matrices")?;
    let chol = &mut analysis.as_mut().expect("just analysed").chol;
    books.info.factor_nnz = chol.factor_nnz();
    books.info.factorization_bytes = chol.factorization_bytes();
    books.info.split_factorization = chol.is_split();
    Ok(chol)
}
