//! The assembled system K u = f over the unknowns: the single owner of the
//! matrix values. It is allocated with the pattern, once per mesh, holds
//! the bodies' part plus the contact elements that are switched on, and is
//! updated in place when the active set changes, so that the values (63 MB
//! at 1M unknowns) are never copied.

use crate::contact::constraints::Constraints;
use crate::error::Result;
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern, sym_mul_upper};
use crate::fem::body::{self, Softened, Target};
use crate::fem::element_loop::ElementLoop;

/// The matrix values on a pattern, the right-hand side on its unknowns,
/// and which contact constraints they hold.
pub(crate) struct AssembledSystem {
    /// The upper triangle's values on the session's pattern.
    values: Vec<f64>,
    /// The load on the unknowns.
    rhs: Vec<f64>,
    /// Whether each contact part's matrix and load are in.
    contact: Vec<bool>,
    /// The contact parts switched since the bodies' part was assembled,
    /// one list per update, in order: replaying it onto the bodies' part
    /// rebuilds the system to the last bit.
    log: Vec<Vec<usize>>,
    /// The friction load factors c the right-hand side holds (empty: none;
    /// docs/method.md §6.15).
    friction: Vec<f64>,
}

impl AssembledSystem {
    /// Storage for a matrix with `nnz` stored entries. Its pages are faulted
    /// in now, once per mesh, as the pattern is built once: faulting a fresh
    /// array in took 0.035 s of the 0.235 s body assembly at 1M unknowns.
    /// (Touched on one thread: two threads faulting pages in at once cost
    /// ~4× more on the test machine, 0.11 s against 0.03 s for 63 MB.)
    pub fn new(nnz: usize) -> AssembledSystem {
        let mut values = vec![0.0; nnz];
        values.fill(0.0);
        AssembledSystem {
            values,
            rhs: Vec::new(),
            contact: Vec::new(),
            log: Vec::new(),
            friction: Vec::new(),
        }
    }

    /// A system whose bodies' part a caller assembled: the matrix values
    /// `values` (upper triangle on the pattern) and the load `rhs` (over
    /// the unknowns), no contact part in.
    pub fn of_bodies(values: Vec<f64>, rhs: Vec<f64>) -> AssembledSystem {
        AssembledSystem {
            values,
            rhs,
            contact: Vec::new(),
            log: Vec::new(),
            friction: Vec::new(),
        }
    }

    /// The matrix values (upper triangle on the pattern).
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The right-hand side over the unknowns.
    pub fn rhs(&self) -> &[f64] {
        &self.rhs
    }

    /// Which contact parts the system holds.
    pub fn contact(&self) -> &[bool] {
        &self.contact
    }

    /// Bytes of the matrix values.
    pub fn memory_bytes(&self) -> usize {
        8 * self.values.len()
    }

    /// Assembles the bodies' part anew (no contact part in) for the global
    /// vectors of external forces `f_ext` and prescribed values
    /// `prescribed`. Returns the elements tempering softens.
    pub fn assemble_body(
        &mut self,
        elements: &ElementLoop<'_>,
        target: Target<'_>,
        f_ext: &[f64],
        prescribed: &[f64],
    ) -> Result<Softened> {
        self.rhs = vec![0.0; target.dofs.n_free()];
        self.contact.clear();
        self.log.clear();
        self.friction.clear();
        let (values, rhs) = (&mut self.values, &mut self.rhs);
        body::assemble(elements, target, f_ext, prescribed, values, rhs)
    }

    /// Switches contact parts on and off so that the system holds those
    /// of `active`: each one that changed is added (+) or taken out (−)
    /// with its load. Taking out what was added leaves round-off of an ulp
    /// in the entries it touches.
    pub fn set_contact(&mut self, active: &[bool], set: &Constraints<'_>, pattern: &Pattern) {
        if self.contact.len() < set.parts() {
            self.contact.resize(set.parts(), false);
        }
        let changed: Vec<usize> = (0..set.parts())
            .filter(|&k| active[k] != self.contact[k])
            .collect();
        self.toggle(changed, set, pattern);
    }

    /// Makes the right-hand side hold the friction loads of the load
    /// factors `c` (docs/method.md §6.15) in place of those it held.
    pub fn set_friction_loads(&mut self, set: &Constraints<'_>, c: &[f64]) {
        let rhs = &mut self.rhs;
        set.add_friction_loads(c, &self.friction, |i, v| rhs[i] += v);
        self.friction.clear();
        self.friction.extend_from_slice(c);
    }

    /// The contact parts switched since the bodies' part was assembled
    /// ([`AssembledSystem::replay`]).
    pub fn log(&self) -> &[Vec<usize>] {
        &self.log
    }

    /// Switches the parts of `log` (from [`AssembledSystem::log`]) in
    /// order: onto the same bodies' part, it rebuilds that system exactly.
    pub fn replay(&mut self, log: &[Vec<usize>], set: &Constraints<'_>, pattern: &Pattern) {
        if self.contact.len() < set.parts() {
            self.contact.resize(set.parts(), false);
        }
        for ks in log {
            self.toggle(ks.clone(), set, pattern);
        }
    }

    /// Switches each of `ks` (ascending) on or off: its matrix added to
    /// the values, its load (which holds the prescribed displacements'
    /// share) to the right-hand side.
    fn toggle(&mut self, ks: Vec<usize>, set: &Constraints<'_>, pattern: &Pattern) {
        if ks.is_empty() {
            return;
        }
        for &k in &ks {
            let sign = if self.contact[k] { -1.0 } else { 1.0 };
            let unknowns = set.unknowns(k);
            let free: Vec<usize> = unknowns.iter().map(|u| u.unwrap_or(NOT_FREE)).collect();
            let ke: Vec<f64> = set.matrix(k).iter().map(|v| sign * v).collect();
            pattern.add_element(&mut self.values, &free, &ke);
            for (u, f) in unknowns.iter().zip(set.load(k)) {
                if let Some(i) = u {
                    self.rhs[*i] += sign * f;
                }
            }
            self.contact[k] = !self.contact[k];
        }
        self.log.push(ks);
    }

    /// ‖K x − f‖₂ / ‖f‖₂ (‖K x − f‖₂ when f = 0). The norms are summed
    /// plainly and, only if that overflows (or underflows to 0), scaled by
    /// the largest entry.
    pub fn relative_residual(&self, pattern: &Pattern, x: &[f64]) -> f64 {
        let mut r = vec![0.0; x.len()];
        pattern.sym_mul(&self.values, x, &mut r);
        r.iter_mut().zip(&self.rhs).for_each(|(a, b)| *a -= b);
        let nf = norm2(&self.rhs);
        if nf > 0.0 { norm2(&r) / nf } else { norm2(&r) }
    }

    /// The matrix as a [`SystemMatrix`] view.
    pub fn matrix<'a>(&'a self, pattern: &'a Pattern, dofs: &'a DofMap) -> SystemMatrix<'a> {
        SystemMatrix {
            col_ptr: pattern.col_ptr(),
            row_idx: pattern.row_idx(),
            values: &self.values,
            unknowns: dofs.free_to_global(),
        }
    }
}

/// ‖v‖₂ without overflow or harmful underflow: the plain sum of squares
/// when it is a normal number, else scaled by the largest |v_i|.
pub(crate) fn norm2(v: &[f64]) -> f64 {
    let plain = v.iter().map(|a| a * a).sum::<f64>();
    if plain.is_normal() || plain == 0.0 && v.iter().all(|&a| a == 0.0) {
        return plain.sqrt();
    }
    let m = v.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    if !(m > 0.0 && m.is_finite()) {
        return m;
    }
    m * v.iter().map(|a| (a / m) * (a / m)).sum::<f64>().sqrt()
}

/// The stiffness matrix K of the last solve on its unknowns (the DOFs left
/// after Dirichlet elimination), borrowed from the model without a copy:
/// the upper triangle in compressed sparse columns, rows ascending within
/// each column. For a contact solve it holds the contact elements active in
/// the final state, so that K u = f is the system the reported displacements
/// solve. Meant for checking a solve against another code, or timing a
/// solver on the very matrix tfem factorised.
#[derive(Debug, Clone)]
pub struct SystemMatrix<'a> {
    /// Column pointers: column j is `col_ptr[j]..col_ptr[j + 1]` (n + 1
    /// entries).
    pub col_ptr: &'a [usize],
    /// Row index of each stored entry (≤ its column).
    pub row_idx: &'a [usize],
    /// Value of each stored entry.
    pub values: &'a [f64],
    /// The global DOF (2·node + component, component 0 = x) of each unknown.
    pub unknowns: &'a [usize],
}

impl SystemMatrix<'_> {
    /// Number of unknowns (rows = columns).
    pub fn n(&self) -> usize {
        self.unknowns.len()
    }

    /// y = K x over the unknowns (the symmetric product of the stored upper
    /// triangle).
    ///
    /// # Panics
    /// If `x` does not have one value per unknown.
    pub fn mul_vec(&self, x: &[f64]) -> Vec<f64> {
        assert_eq!(x.len(), self.n(), "x needs one value per unknown");
        let mut y = vec![0.0; self.n()];
        sym_mul_upper(self.col_ptr, self.row_idx, self.values, x, &mut y);
        y
    }
}
