//! Bounds of the memory a solve's stages take, checked before each stage
//! starts ([`crate::error::preflight`]), so that a solve that cannot have
//! its memory fails with TFEM_STATUS_OUT_OF_MEMORY and the model unchanged
//! instead of aborting the host.
//!
//! Each bound counts the stage's arrays at their largest, in 8-byte words
//! per node, triangle, unknown or stored entry, with the growth of the
//! arrays built by pushing; the sparse factor and faer's workspaces are not
//! in them (they are reserved fallibly where they are made). The bounds are
//! checked by the C test that solves under address-space limits from a few
//! kilobytes to what the solve needs (c_tests/boundary_test.c,
//! `a_solve_under_any_memory_limit_fails_cleanly_or_succeeds`).

/// Bytes of one word.
const WORD: usize = 8;

/// The room a stage gets beyond its arrays: the allocator's fragmentation
/// and the small allocations nobody counts.
fn with_margin(words: usize) -> usize {
    let bytes = words.saturating_mul(WORD);
    bytes.saturating_add(bytes / 4).saturating_add(1 << 20)
}

/// An upper bound of the stored entries of the stiffness matrix's upper
/// triangle for `n_nodes` nodes and `n_elements` three-node elements (mesh
/// triangles and contact elements): each element has three edges, each
/// edge couples two nodes' 2×2 blocks (four entries), each node's own
/// block has three.
pub fn matrix_entries(n_nodes: usize, n_elements: usize) -> usize {
    n_elements
        .saturating_mul(12)
        .saturating_add(n_nodes.saturating_mul(3))
}

/// The session's set-up (unknown numbering, the matrix pattern built from
/// the node adjacency, the triangles' slots, the matrix values) for
/// `n_nodes` nodes, `n_triangles` triangles and `n_contact` contact
/// elements.
pub fn session_bytes(n_nodes: usize, n_triangles: usize, n_contact: usize) -> usize {
    let elements = n_triangles.saturating_add(n_contact);
    let entries = matrix_entries(n_nodes, elements);
    // Unknown numbering (2 per node, both ways); the element list (3) and
    // the adjacency with repeats (9 per element); three node counters; the
    // pattern's columns, rows (pushed: up to twice their length) and
    // values; the slots (6 bytes per triangle).
    let words = [
        4 * n_nodes,
        12 * elements,
        3 * n_nodes,
        2 * n_nodes,
        3 * entries,
        n_triangles,
    ];
    with_margin(words.iter().fold(0usize, |s, w| s.saturating_add(*w)))
}

/// The symbolic analysis before its factor is made: the unknowns'
/// coordinates, the symmetric graph of `entries` stored entries over `n`
/// unknowns, and the ordering's own arrays (a few per unknown).
pub fn analysis_bytes(n: usize, entries: usize) -> usize {
    let words = [2 * n, 2 * entries, 2 * n, 16 * n];
    with_margin(words.iter().fold(0usize, |s, w| s.saturating_add(*w)))
}

/// What a solve takes besides its factor: vectors over the `n_global`
/// DOFs and the unknowns (right-hand sides, solutions, refinement and
/// inverse-iteration work, the field, its expansion and outputs: 40 in
/// all), and, with `n_interface` unknowns condensed, the dense interface
/// matrices (Ŝ₁ packed, its factor, the product forming it, the
/// capacitance of a low-rank change: 4 n²).
pub fn solve_bytes(n_global: usize, n_interface: usize) -> usize {
    let dense = n_interface.saturating_mul(n_interface).saturating_mul(4);
    with_margin(n_global.saturating_mul(40).saturating_add(dense))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_matrix_bound_holds_for_a_structured_mesh() {
        // An n × n grid of squares cut in two: (n+1)² nodes, 2n² triangles,
        // 3n² + 2n edges; the upper triangle stores 3 per node and 4 per
        // edge.
        let n = 20;
        let nodes = (n + 1) * (n + 1);
        let exact = 3 * nodes + 4 * (3 * n * n + 2 * n);
        assert!(matrix_entries(nodes, 2 * n * n) >= exact);
    }

    #[test]
    fn bounds_saturate_instead_of_overflowing() {
        assert_eq!(session_bytes(usize::MAX, usize::MAX, 1), usize::MAX);
        assert_eq!(solve_bytes(usize::MAX, usize::MAX), usize::MAX);
    }
}
