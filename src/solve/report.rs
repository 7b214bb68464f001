//! What a solve reports: statistics, timings, and the contact report.

/// Wall-clock time of the stages of a solve, in seconds.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Timings {
    /// Sparsity pattern and symbolic analysis (zero when reused).
    pub analysis: f64,
    /// Element matrices and scatter-add, summed over iterations.
    pub assembly: f64,
    /// Numeric factorisations including the singularity check, summed.
    pub factorization: f64,
    /// Triangular solves, summed.
    pub solve: f64,
    /// Dense work on the condensed contact interface (reading its Schur
    /// complement, factorising and solving it at each iteration).
    pub interface: f64,
    /// The whole call.
    pub total: f64,
}

/// Statistics of a solve.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SolveInfo {
    /// Number of unknowns (DOFs after Dirichlet elimination).
    pub unknowns: usize,
    /// Stored entries of the upper triangle of the matrix.
    pub matrix_nnz: usize,
    /// Stored entries of the Cholesky factor.
    pub factor_nnz: usize,
    /// Numeric factorisations performed.
    pub factorizations: usize,
    /// Unknowns of the condensed contact interface (0 when the active-set
    /// loop refactorised instead).
    pub interface_unknowns: usize,
    /// ‖K u − f‖ / ‖f‖ over the unknowns, for the final system.
    pub relative_residual: f64,
    /// Condition estimate of the Jacobi-scaled final matrix.
    pub condition_estimate: f64,
    /// Bytes held by the pattern, matrix values, factor and (for a
    /// condensed contact solve) the dense interface matrices.
    pub memory_bytes: usize,
    /// Bytes one numeric factorisation needs at its peak: the factor, its
    /// symbolic structure and the factorisation workspace (not the matrix
    /// it reads). The yardstick for the memory of a whole solve.
    pub factorization_bytes: usize,
    /// Whether the factorisation ran as two concurrent subtrees and a
    /// dense separator block (`Model::set_parallel_subtrees`).
    pub split_factorization: bool,
    /// Stage timings.
    pub timings: Timings,
}

pub use crate::contact::IterationRecord;

/// Result of a contact solve.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactReport {
    /// Active-set iterations (solves) performed.
    pub iterations: usize,
    /// Elements of the contact mesh B (under the mortar weighting: slave
    /// nodes).
    pub elements: usize,
    /// Active (inverted) elements at convergence (under the mortar
    /// weighting: slave nodes with a negative weighted gap).
    pub active: usize,
    /// Contact length ℓc: in each contact zone (a pair's active elements of
    /// B connected through shared nodes), the summed
    /// interface-edge length (as far as it faces the other side) of the
    /// active elements of the family — edges on one side, or on the other;
    /// each tiles the interface once — active over the longer length
    /// (docs/method.md §6.8). Under
    /// the mortar weighting: the summed tributaries m_i of the active slave
    /// nodes.
    pub contact_length: f64,
    /// Largest normal interpenetration (−opening / edge length) of an active
    /// element, in model length units; 0 when nothing penetrates. Under the
    /// mortar weighting: the largest −G_i/m_i of an active slave node.
    pub max_penetration: f64,
    /// Per-iteration history.
    pub history: Vec<IterationRecord>,
    /// Solver statistics and timings.
    pub info: SolveInfo,
}
