//! Lower triangles of dense symmetric matrices packed by columns: half the
//! memory of a square array, for the Schur complements the split
//! factorisation forms and the condensed contact interface keeps.

use faer::MatRef;

/// Length of the lower triangle of an m×m matrix packed by columns.
pub fn packed_len(m: usize) -> usize {
    m * (m + 1) / 2
}

/// Where column j (rows j..m) starts in the lower triangle of an m×m
/// matrix packed by columns.
pub fn packed_start(m: usize, j: usize) -> usize {
    j * m - j * j.saturating_sub(1) / 2
}

/// Appends the lower triangle of the square `m`, packed by columns, to
/// `out` (which the caller reserves: [`packed_len`]).
pub fn pack_lower(m: MatRef<'_, f64>, out: &mut Vec<f64>) {
    let n = m.nrows();
    for j in 0..n {
        out.extend(m.col(j).subrows(j, n - j).iter());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_follow_each_other_without_gaps() {
        for m in [1, 2, 5, 17] {
            let mut next = 0;
            for j in 0..m {
                assert_eq!(packed_start(m, j), next, "m = {m}, column {j}");
                next += m - j;
            }
            assert_eq!(next, packed_len(m));
        }
    }

    #[test]
    fn packing_keeps_the_lower_triangle_column_by_column() {
        let a = faer::Mat::from_fn(3, 3, |i, j| (10 * i + j) as f64);
        let mut out = Vec::with_capacity(packed_len(3));
        pack_lower(a.as_ref(), &mut out);
        assert_eq!(out, [0.0, 10.0, 20.0, 11.0, 21.0, 22.0]);
    }
}
