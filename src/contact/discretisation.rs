//! How the contact pairs of a model are discretised, chosen once per
//! structure (mesh, boundary edges, pairs, prescribed DOFs): each pair's
//! contact mesh B (docs/method.md §3), and for the pairs under the mortar
//! weighting their weighted gaps (§6.11). What a solve switches is built
//! from it ([`super::constraints::Constraints`]).

use super::mortar_set::{PairGaps, cliques, pair_gaps};
use super::{ContactElement, ContactPair, ContactWeighting, build_all};
use crate::error::Result;
use crate::fem::mesh::Mesh;

/// The discretisation of every contact pair of a model.
#[derive(Debug, Clone, Default)]
pub struct Discretisation {
    /// B of every pair: the strip pairs' elements, and for the mortar pairs
    /// what sets their penalty length h_c and tells a rigid side apart.
    elements: Vec<ContactElement>,
    /// Whether each pair is weighted by the mortar weighting.
    mortar: Vec<bool>,
    /// The elements of B of the strip pairs, when some pair is not one
    /// (`None`: all of [`Discretisation::elements`]).
    strip: Option<Vec<ContactElement>>,
    /// The weighted gaps of the mortar pairs.
    gaps: Vec<PairGaps>,
}

impl Discretisation {
    /// The discretisation of `pairs` on `mesh`, every pair under
    /// `weighting`.
    pub fn build(
        mesh: &Mesh,
        pairs: &[ContactPair],
        weighting: ContactWeighting,
    ) -> Result<Discretisation> {
        let elements = build_all(mesh, pairs)?;
        let mortar = vec![weighting == ContactWeighting::Mortar; pairs.len()];
        let gaps = pairs
            .iter()
            .enumerate()
            .filter(|(i, _)| mortar[*i])
            .map(|(i, p)| pair_gaps(mesh, i, p))
            .collect::<Result<Vec<_>>>()?;
        let strip = mortar.iter().any(|&m| m).then(|| {
            elements
                .iter()
                .filter(|e| !mortar[e.pair])
                .cloned()
                .collect()
        });
        Ok(Discretisation {
            elements,
            mortar,
            strip,
            gaps,
        })
    }

    /// B of every pair.
    pub fn elements(&self) -> &[ContactElement] {
        &self.elements
    }

    /// The elements of B that the strip pairs switch.
    pub fn strip(&self) -> &[ContactElement] {
        self.strip.as_deref().unwrap_or(&self.elements)
    }

    /// The weighted gaps of the mortar pairs.
    pub fn gaps(&self) -> &[PairGaps] {
        &self.gaps
    }

    /// Whether some pair is under the mortar weighting.
    pub fn has_mortar(&self) -> bool {
        self.mortar.iter().any(|&m| m)
    }

    /// Node triangles whose cliques cover every coupling a solve may
    /// switch on: the strip's elements and the weighted gaps' cliques.
    pub fn couplings(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        let strip = self.strip().iter().map(|e| e.nodes);
        strip.chain(cliques(&self.gaps))
    }
}
