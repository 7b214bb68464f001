//! The elements of B in one solve: each element's law (constitutive matrix
//! and tempered Jacobian), its stiffness and initial-gap load, its
//! unknowns, and the inversion test that decides which elements are
//! active. Built once per solve from B (which depends only on the mesh and
//! the pairs) and the solve's options.

use std::collections::BTreeMap;

use super::law::{
    ContactStiffness, contact_pressure, contact_stiffness, law_matrix, linearised_opening,
    opening_coefficient,
};
use super::{ContactElement, ContactOptions, ContactPair, InversionTest};
use crate::error::{Error, Result, Status, ensure_finite};
use crate::fem::assembly::{DofMap, NOT_FREE, Pattern};
use crate::fem::element::{TriGeometry, jmin_of_lambda};
use crate::fem::material::Material;
use crate::fem::mesh::Mesh;

/// The law of one contact element: its constitutive matrix and its
/// tempered Jacobian. An active element is inverted, so max(J, Jmin) =
/// Jmin: `t` is its Jmin, and its matrix does not change while it is
/// active.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementLaw {
    /// Constitutive matrix D_c (Voigt, engineering shear).
    pub d: [[f64; 3]; 3],
    /// Tempered Jacobian T = Jmin = h³/λ.
    pub t: f64,
}

/// The elements of B with everything a solve needs of them.
pub struct ContactSet<'a> {
    mesh: &'a Mesh,
    elements: &'a [ContactElement],
    options: ContactOptions,
    laws: Vec<ElementLaw>,
    geos: Vec<TriGeometry>,
    stiffness: Vec<ContactStiffness>,
    unknowns: Vec<[Option<usize>; 6]>,
    loads: Vec<[f64; 6]>,
}

impl<'a> ContactSet<'a> {
    /// The set of `elements` (B of `pairs` on `mesh`) under `options`, on
    /// the unknowns of `dofs` with the prescribed displacements
    /// `prescribed` (a global vector). E_c defaults to the softer body's
    /// Young's modulus, λ to the mesh size.
    pub fn new(
        mesh: &'a Mesh,
        elements: &'a [ContactElement],
        pairs: &[ContactPair],
        material: impl Fn(i32) -> Material,
        (dofs, prescribed): (&DofMap, &[f64]),
        options: &ContactOptions,
    ) -> Result<ContactSet<'a>> {
        let laws = element_laws(mesh, elements, pairs, material, options)?;
        let geos: Vec<TriGeometry> = elements
            .iter()
            .map(|el| TriGeometry::new(&mesh.corners(&el.nodes)))
            .collect();
        // An active element is inverted, so its T = Jmin: its matrix and
        // initial-gap load do not change between iterations.
        let stiffness: Vec<ContactStiffness> = elements
            .iter()
            .enumerate()
            .map(|(k, el)| contact_stiffness(&geos[k], &laws[k].d, el.normal, el.j0, laws[k].t))
            .collect();
        let name = |k: usize| format!("contact element {}", k + mesh.index_base());
        let values = stiffness
            .iter()
            .flat_map(|cs| cs.k.iter().chain(&cs.f0).copied());
        ensure_finite(values, 42, "stiffness", name)?;
        let unknowns: Vec<[Option<usize>; 6]> = elements
            .iter()
            .map(|el| {
                let mut gd = [0usize; 6];
                dofs.element_dofs(&el.nodes, &mut gd);
                gd.map(|g| Some(dofs.free(g)).filter(|&f| f != NOT_FREE))
            })
            .collect();
        let loads = element_loads(elements, dofs, &stiffness, &unknowns, prescribed);
        Ok(ContactSet {
            mesh,
            elements,
            options: *options,
            laws,
            geos,
            stiffness,
            unknowns,
            loads,
        })
    }

    /// The mesh.
    pub fn mesh(&self) -> &'a Mesh {
        self.mesh
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.elements.len()
    }

    /// Whether B is empty.
    pub fn is_empty(&self) -> bool {
        self.elements.is_empty()
    }

    /// The elements of B.
    pub fn elements(&self) -> &'a [ContactElement] {
        self.elements
    }

    /// Each element's law.
    pub fn laws(&self) -> &[ElementLaw] {
        &self.laws
    }

    /// The stiffness and initial-gap load of element `k` when active.
    pub fn stiffness(&self, k: usize) -> &ContactStiffness {
        &self.stiffness[k]
    }

    /// The unknown of each of element `k`'s six DOFs (`None`: prescribed).
    pub fn unknowns(&self, k: usize) -> &[Option<usize>; 6] {
        &self.unknowns[k]
    }

    /// Element `k`'s load on its unknowns when active: its initial-gap load
    /// minus the prescribed displacements' share (zero on prescribed DOFs).
    pub fn load(&self, k: usize) -> &[f64; 6] {
        &self.loads[k]
    }

    /// The active set the loop starts from ([`initial_active_set`]).
    pub fn initial_active(&self) -> Vec<bool> {
        initial_active_set(self.elements)
    }

    /// The inversion test: which elements are inverted for the element
    /// displacements `values(k)` of element `k`.
    pub fn inverted(&self, values: impl Fn(usize) -> [f64; 6]) -> Vec<bool> {
        let (law, test) = (self.options.law, self.options.test);
        self.elements
            .iter()
            .enumerate()
            .map(|(k, el)| {
                let ue = values(k);
                let j = match test {
                    InversionTest::Linearised => {
                        linearised_opening(&self.geos[k], law, el.normal, &ue)
                    }
                    InversionTest::Literal => {
                        let mut x = self.mesh.corners(&el.nodes);
                        for (i, p) in x.iter_mut().enumerate() {
                            p[0] += ue[2 * i];
                            p[1] += ue[2 * i + 1];
                        }
                        TriGeometry::new(&x).j
                    }
                };
                j < 0.0
            })
            .collect()
    }

    /// The linearised opening of element `k` (the quantity the law
    /// penalises) for element displacements `ue`.
    pub fn opening(&self, k: usize, ue: &[f64; 6]) -> f64 {
        let el = &self.elements[k];
        linearised_opening(&self.geos[k], self.options.law, el.normal, ue)
    }

    /// The contact pressure of active element `k` for element displacements
    /// `ue` (positive in compression).
    pub fn pressure(&self, k: usize, ue: &[f64; 6]) -> f64 {
        let (el, law) = (&self.elements[k], &self.laws[k]);
        contact_pressure(&self.geos[k], &law.d, el.normal, el.j0, law.t, ue)
    }

    /// The interface unknowns: the free unknowns with a nonzero coefficient
    /// in an element of B — in its matrix, its load, or its inversion test
    /// (the literal test needs every unknown of its nodes). For a straight
    /// interface under the frictionless law these are the normal
    /// components only, half of the contact nodes' unknowns. Sorted.
    pub fn interface_unknowns(&self) -> Vec<usize> {
        let (test, law) = (self.options.test, self.options.law);
        let mut set = Vec::new();
        for (k, cs) in self.stiffness.iter().enumerate() {
            for a in 0..6 {
                let Some(i) = self.unknowns[k][a] else {
                    continue;
                };
                let coupled = cs.k[a * 6..a * 6 + 6].iter().any(|&v| v != 0.0)
                    || cs.f0[a] != 0.0
                    || match test {
                        InversionTest::Linearised => {
                            let n = self.elements[k].normal;
                            opening_coefficient(&self.geos[k], law, n, a) != 0.0
                        }
                        InversionTest::Literal => true,
                    };
                if coupled {
                    set.push(i);
                }
            }
        }
        set.sort_unstable();
        set.dedup();
        set
    }

    /// Value positions of `pattern` that hold zero in every matrix of the
    /// solve: zero in the body part `body` and in every element's matrix.
    /// The pattern couples nodes, every unknown of one with every unknown
    /// of the other; a frictionless element with an axis-aligned normal
    /// couples only the normal components, so that the tangential unknowns
    /// of the two surfaces are not coupled at all. Sorted.
    pub fn structural_zeros(&self, pattern: &Pattern, body: &[f64]) -> Vec<usize> {
        let (mut zero, mut nonzero) = (Vec::new(), Vec::new());
        for (u, cs) in self.unknowns.iter().zip(&self.stiffness) {
            for a in 0..6 {
                for b in a..6 {
                    let (Some(i), Some(j)) = (u[a], u[b]) else {
                        continue;
                    };
                    let Some(p) = pattern.position(i, j) else {
                        continue;
                    };
                    if cs.k[a * 6 + b] != 0.0 || cs.k[b * 6 + a] != 0.0 || body[p] != 0.0 {
                        nonzero.push(p);
                    } else {
                        zero.push(p);
                    }
                }
            }
        }
        nonzero.sort_unstable();
        zero.sort_unstable();
        zero.dedup();
        zero.retain(|p| nonzero.binary_search(p).is_err());
        zero
    }
}

/// Each element's law: D_c of the pair's softer body with E_c, and
/// T = h³/λ_c.
fn element_laws(
    mesh: &Mesh,
    elements: &[ContactElement],
    pairs: &[ContactPair],
    material: impl Fn(i32) -> Material,
    options: &ContactOptions,
) -> Result<Vec<ElementLaw>> {
    let lambda_c = options.lambda.unwrap_or_else(|| mesh.size());
    let laws: Vec<ElementLaw> = elements
        .iter()
        .map(|el| {
            let p = &pairs[el.pair];
            let (ma, mb) = (material(p.body_a), material(p.body_b));
            let soft = if mb.young() < ma.young() { mb } else { ma };
            let e_c = options.contact_modulus.unwrap_or(soft.young());
            let d = law_matrix(options.law, e_c, &soft, el.normal);
            let t = jmin_of_lambda(el.h, lambda_c);
            ElementLaw { d, t }
        })
        .collect();
    if let Some(k) = laws.iter().position(|p| !(p.t > 0.0 && p.t.is_finite())) {
        return Err(Error::new(
            Status::NumericalFailure,
            format!(
                "contact element {}: Jmin = h³/λ is not a positive finite number",
                k + mesh.index_base()
            ),
        ));
    }
    Ok(laws)
}

/// Each element's load on its free unknowns: the initial-gap load minus
/// the share of the prescribed displacements.
fn element_loads(
    elements: &[ContactElement],
    dofs: &DofMap,
    stiffness: &[ContactStiffness],
    unknowns: &[[Option<usize>; 6]],
    prescribed: &[f64],
) -> Vec<[f64; 6]> {
    elements
        .iter()
        .enumerate()
        .map(|(k, el)| {
            let mut gd = [0usize; 6];
            dofs.element_dofs(&el.nodes, &mut gd);
            std::array::from_fn(|a| {
                if unknowns[k][a].is_none() {
                    return 0.0;
                }
                let mut r = stiffness[k].f0[a];
                for b in 0..6 {
                    if unknowns[k][b].is_none() {
                        r -= stiffness[k].k[a * 6 + b] * prescribed[gd[b]];
                    }
                }
                r
            })
        })
        .collect()
}

/// The active set the loop starts from: per pair, the elements whose gap
/// (J₀ over the interface edge: the apex's distance from the edge) is within
/// 1e-3 of their size of the pair's smallest gap. Touching or uniformly
/// spaced surfaces start fully active (the seed's choice: the first solve
/// pulls a small uniform gap closed, which keeps a body held only by contact
/// restrained); curved ones start from their first points of contact, so
/// that the loop grows the set instead of releasing a glued interface one
/// element at a time.
pub fn initial_active_set(elements: &[ContactElement]) -> Vec<bool> {
    let gap = |e: &ContactElement| {
        if e.edge_length > 0.0 {
            e.j0 / e.edge_length
        } else {
            0.0
        }
    };
    let mut smallest: BTreeMap<usize, f64> = BTreeMap::new();
    for e in elements {
        let g = smallest.entry(e.pair).or_insert(f64::INFINITY);
        *g = g.min(gap(e));
    }
    elements
        .iter()
        .map(|e| gap(e) <= smallest[&e.pair] + 1e-3 * e.h)
        .collect()
}
