//! Frictionless contact by activating inverted elements of a contact mesh B
//! (docs/method.md §3): the contact pairs and options, the construction and
//! checking of B ([`mesh`]), the constitutive law of its elements
//! ([`law`]) and the set of its elements in one solve, which owns their
//! data and the inversion test ([`set`]), and the mortar-weighted gaps of a
//! pair ([`mortar`], solved by `solve::mortar` under
//! [`ContactWeighting::Mortar`]).
//!
//! A flat element of B on a conforming interface is exactly a spring between
//! two coincident nodes; with Jmin = h³/λ it is a node-to-node penalty of
//! about E_c·λ/h² per unit length, so interpenetration is O(h²).
//!
//! Each element of B carries its interface normal n (a flat element has
//! none of its own), its initial Jacobian J0 (zero for touching surfaces,
//! positive for a gap) and the length of its edge on the interface. Its
//! "opening" is the Jacobian linearised about the initial configuration,
//! J0 + Σ g_i·u_i, which for a flat conforming element is the node-pair
//! normal gap times the edge length. The element's stress acts on that
//! opening, not on the displacement jump alone, so an element that closes an
//! initial gap switches on without a force jump.

pub mod conformity;
pub(crate) mod constraints;
pub(crate) mod discretisation;
pub mod gap_tets;
pub mod host;
pub mod host_solid;
pub mod law;
pub mod mesh;
pub mod mortar;
pub(crate) mod mortar_set;
pub mod pairing;
pub mod prism_layer;
pub mod set;
pub(crate) mod settled;
pub mod traction;

pub use host::{HostContact, Update};
pub use law::{
    ContactStiffness, contact_pressure, contact_stiffness, law_geometry, law_matrix,
    linearised_jacobian, linearised_opening, opening_coefficient, shear_vector, stick_stiffness,
};
pub use mesh::{
    Nodes, Side, build, build_all, build_conforming, build_nonconforming, check_user_mesh,
    pair_bodies, shared_normals,
};
pub use set::{
    ActiveSet, ContactSet, ElementLaw, FrictionOutcome, FrictionState, IterationRecord, Owners,
    SlipLoads, Verdict, element_laws, initial_active_set, softer,
};

use crate::error::{Error, Result};

/// The constitutive law of the contact elements.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactLaw {
    /// Only the normal strain is penalised: D_c = E_c m mᵀ with
    /// m = [n_x², n_y², n_x n_y]. Tangential slip is free.
    Frictionless = 0,
    /// Tempered isotropic elasticity in B (E_c, ν of the softer body) on the
    /// element flattened onto its interface line
    /// (`contact::law_geometry`): a normal and a
    /// tangential spring on the jump between the surfaces, so it also
    /// resists slip and ties them (sticking contact). Flattened because,
    /// across an initial gap or overlap, the element itself would also
    /// read the bodies' tangential stretching, and its Poisson stress
    /// broke the patch test (docs/method.md §6.4).
    Stick = 1,
}

/// How an element of B is found inverted.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InversionTest {
    /// J linearised about the initial configuration, J0 + Σ g_i·u_i < 0
    /// (consistent with small strain; for a flat conforming element, the
    /// node-pair normal gap). Under the frictionless law, only its normal
    /// part J0 + Σ (n·g_i)(n·u_i) — the element's normal opening: the
    /// node-to-segment gap at its apex times its interface edge, the very
    /// quantity the law penalises — so that an active element always pushes.
    /// The two differ by J0·ε_tt (the interface stretching times the initial
    /// gap): nothing on touching surfaces, but on a curved gap, where the
    /// bodies strain by a percent, enough to activate elements that then
    /// pull. The default.
    Linearised = 0,
    /// The seed's literal test, J(X + u) < 0. Its second-order term (slope
    /// times slip) can exceed the penalty penetration on fine meshes and make
    /// the loop cycle.
    Literal = 1,
}

/// How the contact energy of a pair is weighted along its interface
/// (docs/method.md §6.11): chosen pair by pair by default, or forced for
/// every pair (an expert's override).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ContactWeighting {
    /// Each pair what is right for its interface
    /// ([`discretisation`](crate::contact)): where the two sides' nodes
    /// match, the strip's elements of B (the seed's method); where they do
    /// not, the mortar weighting — but for a pair with friction or a
    /// contact mesh of its own, which keeps B. The default.
    #[default]
    Auto,
    /// The elements of B for every pair, each a penalty on the gap at its
    /// apex over its interface edge: the seed's method. On a curved
    /// interface whose nodes do not match, B reads one side only (a
    /// warning says so where it does).
    Strip,
    /// The sampled mortar weighting ([`mortar`]) for every pair: one
    /// weighted gap G_i = ∫ ψ_i g ds per node of the coarser side of each
    /// interface (the slave), a penalty ½ (κ/m_i) G_i², active where
    /// G_i < 0. Exact on the contact patch test whatever the two sides'
    /// nodes; frictionless (no friction or host contact yet).
    Mortar,
}

impl ContactWeighting {
    /// Decodes the C ABI integer (0 = strip, 1 = mortar, 2 = automatic).
    pub fn from_i32(value: i32) -> Option<ContactWeighting> {
        match value {
            0 => Some(ContactWeighting::Strip),
            1 => Some(ContactWeighting::Mortar),
            2 => Some(ContactWeighting::Auto),
            _ => None,
        }
    }

    /// The C ABI integer ([`ContactWeighting::from_i32`]).
    pub fn to_i32(self) -> i32 {
        match self {
            ContactWeighting::Strip => 0,
            ContactWeighting::Mortar => 1,
            ContactWeighting::Auto => 2,
        }
    }
}

/// Options of the contact solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactOptions {
    /// Constitutive law of B.
    pub law: ContactLaw,
    /// E_c; `None` = the smaller Young's modulus of the two bodies of each
    /// pair (stiffer values only worsen conditioning), or, where one side of
    /// the pair is a rigid tool (every DOF of its contact nodes prescribed),
    /// the other body's (docs/method.md §6.14); [`HostContact`] keeps the
    /// smaller E of its two sides.
    pub contact_modulus: Option<f64>,
    /// λ of the contact elements (Jmin = h³/λ), a length in model units;
    /// `None` = the larger side of the mesh's bounding box.
    pub lambda: Option<f64>,
    /// The inversion test.
    pub test: InversionTest,
    /// Cap on active-set iterations.
    pub max_iterations: usize,
    /// Refactorise the whole matrix at every active-set iteration instead
    /// of condensing the changes on the interface (see
    /// [`crate::condensation`]); slower, kept for comparison.
    pub refactorize: bool,
}

impl Default for ContactOptions {
    fn default() -> Self {
        ContactOptions {
            law: ContactLaw::Frictionless,
            contact_modulus: None,
            lambda: None,
            test: InversionTest::Linearised,
            max_iterations: 50,
            refactorize: false,
        }
    }
}

impl ContactOptions {
    /// Checks the options.
    pub fn validate(&self) -> Result<()> {
        if let Some(e) = self.contact_modulus {
            if !(e.is_finite() && e > 0.0) {
                return Err(Error::argument(format!(
                    "contact modulus E_c = {e:?} must be finite and > 0"
                )));
            }
        }
        if let Some(l) = self.lambda {
            if !(l.is_finite() && l > 0.0) {
                return Err(Error::argument(format!(
                    "contact lambda = {l:?} must be finite and > 0"
                )));
            }
        }
        if self.max_iterations == 0 {
            return Err(Error::argument("max_iterations must be at least 1"));
        }
        Ok(())
    }
}

/// A potential contact interface: boundary edges tagged `tag_a` on one body
/// and `tag_b` on another.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    /// Tag of the edges on the first body.
    pub tag_a: i32,
    /// Tag of the edges on the second body.
    pub tag_b: i32,
    /// Body carrying `tag_a`.
    pub body_a: i32,
    /// Body carrying `tag_b`.
    pub body_b: i32,
    /// A contact mesh handed over by the user (0-based nodes), if any.
    pub user_mesh: Option<Vec<[usize; 3]>>,
    /// Coulomb's friction coefficient μ ≥ 0 (0: frictionless; docs/method.md
    /// §6.15).
    pub friction: f64,
}

/// One element of the contact mesh B.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactElement {
    /// Nodes, ordered so that J > 0 when the gap opens.
    pub nodes: [usize; 3],
    /// Unit interface normal, pointing from body a to body b.
    pub normal: [f64; 2],
    /// Initial Jacobian (0 for touching surfaces).
    pub j0: f64,
    /// Longest edge (for Jmin = h³/λ).
    pub h: f64,
    /// Length of the element's edge on the interface.
    pub edge_length: f64,
    /// Length of that edge that faces the other side of the pair, f_e ≤
    /// ℓ_e: all of it but where the other side ends inside the edge
    /// (docs/method.md §6.11, "Sides that end inside an edge"). The
    /// element is a penalty κ f_e/2 on its gap, and it counts f_e in ℓc.
    pub facing: f64,
    /// Index of the pair it belongs to.
    pub pair: usize,
    /// Its apex: the node alone on its side of the interface (0-based),
    /// whose distance from the interface edge is the element's gap.
    pub apex: usize,
}

impl ContactElement {
    /// The position of its apex in `nodes`.
    pub fn apex_position(&self) -> usize {
        self.nodes.iter().position(|&v| v == self.apex).unwrap_or(2)
    }

    /// f_e/ℓ_e: the share of its interface edge that faces the other side,
    /// 1 exactly where it all does. Its law's pressure and shear are this
    /// share of the traction (its T_e is ℓ_e/f_e larger;
    /// [`law::contact_jmins`]).
    pub fn facing_share(&self) -> f64 {
        match self.facing < self.edge_length {
            true => self.facing / self.edge_length,
            false => 1.0,
        }
    }
}
