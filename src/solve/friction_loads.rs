//! The friction loads of an active-set loop (docs/method.md §6.15): each
//! frictional element's load factor c (its slip load c·b_t), moved to the
//! contact law's verdict after each solve — by Anderson mixing while the
//! flags stand still, where that update is an affine map — and brought to
//! a recovered field's pressures. The one place the loop meets friction
//! beside the law's verdict.

use std::borrow::Cow;

use crate::contact::constraints::Constraints;

/// Slip tractions that moved by less than this, relative to the largest
/// friction load, have converged. The fixed point on μ p stalls at the
/// round-off of the interface solve: measured 2e-11 to 3e-11 of the largest
/// slip load at h = 1/256 (seed scene, μ = 1), so 1e-11 never settled
/// there; 1e-9 keeps a margin of 30.
pub(crate) const FRICTION_TOL: f64 = 1e-9;

/// The friction load factors of a loop's next solve (empty when
/// frictionless), with what moves them.
pub(crate) struct FrictionLoads {
    /// c per element.
    pub c: Vec<f64>,
    /// The fixed point on the slip loads while the flags stand still.
    mixing: Anderson,
    /// Whether the last solve held the slip loads implicit (its slip loads
    /// follow from the flags and their signs).
    pub coupled: bool,
}

impl FrictionLoads {
    /// The loads `c`, no history.
    pub fn new(c: Vec<f64>) -> FrictionLoads {
        FrictionLoads {
            c,
            mixing: Anderson::default(),
            coupled: false,
        }
    }

    /// Moves the loads to the verdict's `next`; `flags_stand` when the
    /// verdict keeps the flags. True when they moved by more than
    /// [`FRICTION_TOL`] of the largest.
    pub fn advance(&mut self, next: Vec<f64>, flags_stand: bool) -> bool {
        let scale = next.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let moved = next
            .iter()
            .zip(&self.c)
            .any(|(a, b)| (a - b).abs() > FRICTION_TOL * scale);
        // With the flags standing still, the slip loads' update is an affine
        // map (one linear solve, pressures linear in it): Anderson mixing
        // finds its fixed point in a few steps where plain iteration
        // contracts by about μ per step.
        self.c = match moved && flags_stand {
            true => self.mixing.next(&self.c, next),
            false => {
                self.mixing = Anderson::default();
                next
            }
        };
        moved
    }

    /// The loads that, with the flags `flags`, tell the loop's states
    /// apart (`ActiveSet::advance_with`): a coupled solve's slip loads
    /// follow from its flags and their signs (rounding aside, which depends
    /// on the way the factor got there), so only their signs count; else
    /// every bit of every load.
    pub fn state_key(&self, flags: &[bool]) -> Cow<'_, [f64]> {
        if !self.coupled || self.c.is_empty() {
            return Cow::Borrowed(&self.c);
        }
        let n = self.c.len();
        let slipping = |k: usize| flags[k] && !flags[n + k];
        Cow::Owned(
            (0..n)
                .map(|k| match slipping(k) {
                    true => self.c[k].signum(),
                    false => self.c[k],
                })
                .collect(),
        )
    }

    /// The slip loads of the slipping elements of `set` under the flags
    /// `active`, (k, c_k), that go with the pressures of the field `x`
    /// (over the unknowns).
    fn of_field(&self, set: &Constraints<'_>, active: &[bool], x: &[f64]) -> Vec<(usize, f64)> {
        set.slipping(active)
            .into_iter()
            .map(|k| (k, set.slip_load(k, |i| x[i], self.c[k])))
            .collect()
    }

    /// Sets the slip loads to those of the pressures of the field `x`.
    pub fn take(&mut self, set: &Constraints<'_>, active: &[bool], x: &[f64]) {
        for (k, c) in self.of_field(set, active, x) {
            self.c[k] = c;
        }
    }

    /// Whether the slip loads agree with the pressures of the field `x`
    /// to [`FRICTION_TOL`] of the largest.
    pub fn hold(&self, set: &Constraints<'_>, active: &[bool], x: &[f64]) -> bool {
        let scale = self.c.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        self.of_field(set, active, x)
            .iter()
            .all(|&(k, c)| (c - self.c[k]).abs() <= FRICTION_TOL * scale)
    }
}

/// Anderson mixing (type II, memory [`Anderson::MEMORY`]) of a fixed-point
/// iteration c ← G(c).
#[derive(Default)]
struct Anderson {
    /// (c_j, G(c_j) − c_j) of the last iterations.
    history: Vec<(Vec<f64>, Vec<f64>)>,
}

impl Anderson {
    const MEMORY: usize = 6;

    /// The next iterate after G(`c`) = `g_of_c`: c + r − (ΔC + ΔR) γ, with γ
    /// the least-squares fit of the residual r = G(c) − c by the residuals'
    /// differences ΔR (plain iteration while the history is too short or
    /// its fit degenerate).
    fn next(&mut self, c: &[f64], g_of_c: Vec<f64>) -> Vec<f64> {
        let r: Vec<f64> = g_of_c.iter().zip(c).map(|(g, x)| g - x).collect();
        self.history.push((c.to_vec(), r.clone()));
        if self.history.len() > Self::MEMORY + 1 {
            self.history.remove(0);
        }
        let m = self.history.len() - 1;
        if m == 0 {
            return g_of_c;
        }
        let diff =
            |a: &[f64], b: &[f64]| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x - y).collect() };
        let h = &self.history;
        let dr: Vec<Vec<f64>> = (0..m).map(|j| diff(&h[j + 1].1, &h[j].1)).collect();
        let dc: Vec<Vec<f64>> = (0..m).map(|j| diff(&h[j + 1].0, &h[j].0)).collect();
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        // Normal equations (m ≤ 6), Gaussian elimination with pivoting.
        let mut a: Vec<Vec<f64>> = (0..m)
            .map(|i| {
                let mut row: Vec<f64> = (0..m).map(|j| dot(&dr[i], &dr[j])).collect();
                row.push(dot(&dr[i], &r));
                row
            })
            .collect();
        let scale = (0..m).fold(0.0f64, |s, i| s.max(a[i][i]));
        for i in 0..m {
            a[i][i] += 1e-12 * scale;
        }
        for col in 0..m {
            let pivot = (col..m)
                .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
                .expect("rows left");
            a.swap(col, pivot);
            if a[col][col] == 0.0 || a[col][col].is_nan() {
                self.history.clear();
                return g_of_c;
            }
            for row in col + 1..m {
                let f = a[row][col] / a[col][col];
                for k in col..=m {
                    a[row][k] -= f * a[col][k];
                }
            }
        }
        let mut gamma = vec![0.0; m];
        for i in (0..m).rev() {
            let s: f64 = (i + 1..m).map(|k| a[i][k] * gamma[k]).sum();
            gamma[i] = (a[i][m] - s) / a[i][i];
        }
        let next: Vec<f64> = (0..c.len())
            .map(|k| {
                let fit: f64 = (0..m).map(|j| (dc[j][k] + dr[j][k]) * gamma[j]).sum();
                c[k] + r[k] - fit
            })
            .collect();
        if next.iter().all(|v| v.is_finite()) {
            next
        } else {
            self.history.clear();
            g_of_c
        }
    }
}
