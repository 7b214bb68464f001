//! The contact solve of a tetrahedral mesh (docs/method.md §9, stage 3):
//! B's flat tetrahedra ([`GapTets`]) as the constraints of the one
//! active-set loop (`solve::active_set`), as in the plane: the interface
//! condensed into one factorisation per solve when its dense Schur
//! complement is small beside the matrix, else refactorised at each
//! iteration (B spans whole surfaces in 3D, so mostly the latter: docs/
//! method.md §9). The bodies' part is the caller's: a tetrahedral mesh's
//! assembly on its pattern.

use super::active_set::{ActiveSetLoop, LoopInput};
use super::condensed::Condensed;
use super::linear::{Bookkeeping, Energy, Structure, SystemAndFactor};
use super::report::{IterationRecord, SolveInfo, Timings};
use super::session::{Analysis, Settings, Wanted, factorisation};
use super::system::AssembledSystem;
use super::{conditioning_warning, finite_statistics};
use crate::contact::constraints::Constraints;
use crate::contact::gap_tets::GapTets;
use crate::contact::{ContactLaw, ContactOptions};
use crate::error::{Error, Result};
use crate::fem::assembly::{DofMap, Pattern};
use crate::fem::domain::Domain;
use crate::linalg::Ordering;

/// A tetrahedral mesh's system before contact: its bodies' part assembled.
pub struct SolidSystem<'a> {
    /// The nodes and their bodies.
    pub nodes: &'a dyn Domain,
    /// The unknowns (three per node).
    pub dofs: &'a DofMap,
    /// The pattern of the bodies' tetrahedra and B's.
    pub pattern: &'a Pattern,
    /// The bodies' matrix (upper triangle on the pattern).
    pub values: Vec<f64>,
    /// The bodies' load over the unknowns (the prescribed displacements'
    /// share included).
    pub rhs: Vec<f64>,
    /// Prescribed displacements, a global vector.
    pub prescribed: &'a [f64],
    /// The bodies' energy of a global vector r: (rᵀKr, Σ |K_jj| r_j²), the
    /// judge of whether a near-null mode is a free body.
    pub body_energy: Energy<'a>,
}

impl SolidSystem<'_> {
    /// Refuses sizes that do not fit together, and a `gap` whose couplings
    /// the pattern lacks.
    fn check(&self, gap: &GapTets) -> Result<()> {
        let (dofs, pattern) = (self.dofs, self.pattern);
        let sizes = [
            ("DOFs", dofs.n_global(), 3 * self.nodes.n_nodes()),
            ("prescribed values", self.prescribed.len(), dofs.n_global()),
            ("pattern's unknowns", pattern.n(), dofs.n_free()),
            ("matrix values", self.values.len(), pattern.nnz()),
            ("load values", self.rhs.len(), dofs.n_free()),
        ];
        for (what, got, want) in sizes {
            if got != want {
                return Err(Error::argument(format!(
                    "the 3D system has {got} {what} where {want} are needed"
                )));
            }
        }
        for k in 0..gap.len() {
            let unknowns: Vec<usize> = gap.unknowns(k).iter().flatten().copied().collect();
            for &i in &unknowns {
                let coupled = |j: usize| pattern.position(i.min(j), i.max(j)).is_some();
                if i >= pattern.n() || !unknowns.iter().all(|&j| coupled(j)) {
                    return Err(Error::argument(format!(
                        "gap tetrahedron {k} couples unknown {i} outside the pattern"
                    )));
                }
            }
        }
        Ok(())
    }
}

/// Refuses the options B's tetrahedra do not read.
fn check_options(options: &ContactOptions) -> Result<()> {
    options.validate()?;
    let default = ContactOptions::default();
    if options.law != ContactLaw::Frictionless || options.test != default.test {
        return Err(Error::argument(format!(
            "contact in 3D is frictionless with its own inversion test (g ≤ 0): law {:?} and \
             test {:?} are not available",
            options.law, options.test
        )));
    }
    if options.contact_modulus.is_some() || options.lambda.is_some() {
        return Err(Error::argument(
            "in 3D, E_c and λ are B's tetrahedra's own (`GapData`): leave them unset in the \
             options"
                .to_string(),
        ));
    }
    Ok(())
}

/// A settled contact solve of a tetrahedral mesh.
#[derive(Debug, Clone)]
pub struct SolidContact {
    /// Three displacements per node.
    pub u: Vec<f64>,
    /// Whether each tetrahedron of B is on.
    pub active: Vec<bool>,
    /// One record per active-set iteration.
    pub history: Vec<IterationRecord>,
    /// The solve's statistics (factorisations, interface, residual).
    pub info: SolveInfo,
    /// What went wrong but not enough to fail (an ill-conditioned system).
    pub warnings: Vec<String>,
}

/// What one tetrahedral contact solve hands the next on the same
/// structure (unknowns, pattern, ordering): the symbolic analysis and its
/// factor's storage, so that a load history analyses once.
#[derive(Default)]
pub struct SolidAnalysis {
    analysis: Option<Analysis>,
}

impl std::fmt::Debug for SolidAnalysis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolidAnalysis")
            .field("analysed", &self.analysis.is_some())
            .finish()
    }
}

/// Solves `system` with B's tetrahedra `gap` switched on where they would
/// invert (frictionless), by the active-set loop under `options` (its
/// iterations and `refactorize`; B's law, E_c and λ are `gap`'s own, so
/// another law, test, modulus or λ is refused): the interface condensed
/// when that pays, else refactorised per iteration; the unknowns ordered
/// by `ordering`. `gap` must be built with `system`'s unknowns and
/// prescribed values, and the pattern hold its couplings; sizes that do
/// not fit are refused, naming them.
pub fn solve_gap_contact(
    system: SolidSystem<'_>,
    gap: GapTets,
    options: &ContactOptions,
    ordering: Ordering,
) -> Result<SolidContact> {
    let mut fresh = SolidAnalysis::default();
    solve_gap_contact_from(system, gap, options, ordering, &mut fresh, None)
}

/// [`solve_gap_contact`] reusing `analysis` where it was made for the same
/// structure and ordering (else analysing anew into it), and starting from
/// the set `start` (one flag per tetrahedron of `gap`; `None`: those
/// touching or overlapping at rest) — a step of a load history,
/// warm-started from the step before.
pub fn solve_gap_contact_from(
    system: SolidSystem<'_>,
    gap: GapTets,
    options: &ContactOptions,
    ordering: Ordering,
    analysis: &mut SolidAnalysis,
    start: Option<Vec<bool>>,
) -> Result<SolidContact> {
    check_options(options)?;
    system.check(&gap)?;
    if let Some(set) = start.as_ref().filter(|s| s.len() != gap.len()) {
        return Err(Error::argument(format!(
            "a start of {} flags for {} gap tetrahedra",
            set.len(),
            gap.len()
        )));
    }
    let (dofs, pattern) = (system.dofs, system.pattern);
    let set = Constraints::of_gap(gap, system.prescribed, options)?;
    let interface = match options.refactorize {
        true => Vec::new(),
        false => set.interface_unknowns(),
    };
    let condense = Condensed::worthwhile(interface.len(), pattern.nnz());
    let want = Wanted {
        last: if condense { &interface } else { &[] },
        zeros: &[],
    };
    let at = Structure {
        mesh: system.nodes,
        dofs,
        pattern,
    };
    let (mut timings, mut info) = (Timings::default(), SolveInfo::default());
    info.unknowns = dofs.n_free();
    info.matrix_nnz = pattern.nnz();
    let mut books = Bookkeeping::new(&mut timings, &mut info);
    let settings = Settings {
        ordering,
        ..Settings::default()
    };
    let analysis = &mut analysis.analysis;
    let chol = factorisation(analysis, at, settings, want, &mut books)?;
    let mut assembled = AssembledSystem::of_bodies(system.values, system.rhs);
    let input = LoopInput {
        at,
        body_energy: system.body_energy,
        set: &set,
        interface: condense.then_some(interface),
        options: *options,
    };
    let linear = SystemAndFactor {
        chol,
        system: &mut assembled,
    };
    let start = start.map(|s| (s, Vec::new()));
    let settled = ActiveSetLoop::new(input, linear, books, start).run()?;
    info.relative_residual = assembled.relative_residual(pattern, &settled.x);
    info.timings = timings;
    if let Some(a) = analysis.as_ref() {
        info.condition_estimate = a.chol.condition_estimate();
    }
    finite_statistics(&info)?;
    let mut warnings = Vec::new();
    conditioning_warning(&info, &mut warnings);
    Ok(SolidContact {
        u: dofs.expand(&settled.x, system.prescribed),
        active: settled.active,
        history: settled.history,
        info,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::gap_tets::{GapData, GapTetrahedron};
    use crate::fem::domain::SolidNodes;

    /// One tetrahedron of body 0 and, above its top face, a flat one of B
    /// to a fourth node: every DOF free.
    struct Scene {
        nodes: SolidNodes,
        dofs: DofMap,
        pattern: Pattern,
        gap: GapTets,
    }

    fn scene() -> Scene {
        let points = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0],
        ];
        let tets = [[0, 1, 2, 3], [0, 1, 2, 4]];
        let nodes = SolidNodes::new(points.clone(), &tets[..1], &[Some(0)]).unwrap();
        let dofs = DofMap::new(5, 3, |_| true);
        // Every pair of a tetrahedron's nodes is an edge of a face.
        let faces: Vec<[usize; 3]> = (tets.iter())
            .flat_map(|t| [[t[0], t[1], t[2]], [t[0], t[1], t[3]], [t[0], t[2], t[3]]])
            .collect();
        let pattern = Pattern::build(&dofs, 5, &faces);
        let equation = |g: usize| Some(g);
        let data = GapData {
            points: &points,
            moduli: &[1.0],
            h_c: &[0.5],
            lambda: 1.0,
            equation: &equation,
            prescribed: &[0.0; 15],
        };
        let element = GapTetrahedron {
            nodes: [0, 1, 2, 4],
            normal: [0.0, 0.0, 1.0],
        };
        let gap = GapTets::new(&[element], &data).unwrap();
        Scene {
            nodes,
            dofs,
            pattern,
            gap,
        }
    }

    fn solve(s: &Scene, rhs: usize, options: &ContactOptions) -> Result<SolidContact> {
        let energy = |_: &[f64]| (0.0, 0.0);
        let system = SolidSystem {
            nodes: &s.nodes,
            dofs: &s.dofs,
            pattern: &s.pattern,
            values: vec![0.0; s.pattern.nnz()],
            rhs: vec![0.0; rhs],
            prescribed: &[0.0; 15],
            body_energy: &energy,
        };
        solve_gap_contact(system, s.gap.clone(), options, Ordering::Auto)
    }

    #[test]
    fn sizes_that_do_not_fit_are_refused_by_name() {
        let s = scene();
        let e = solve(&s, 14, &ContactOptions::default()).unwrap_err();
        assert!(e.message().contains("14 load values where 15"), "{e}");
    }

    #[test]
    fn options_the_tetrahedra_do_not_read_are_refused() {
        let s = scene();
        let options = ContactOptions {
            contact_modulus: Some(1.0),
            ..Default::default()
        };
        let e = solve(&s, 15, &options).unwrap_err();
        assert!(e.message().contains("leave them unset"), "{e}");
    }
}
