//! The two families of B and one-sided contact (docs/method.md §6.8 and
//! §6.11, "One-sided contact").
//!
//! Every point of an interface lies under two elements of B, one with its
//! edge on either side (two families, each tiling the interface once), and
//! on touching sides that conform both are active. Where the two sides are
//! polygons that do not conform — a curved interface meshed with different
//! nodes on its two sides, a rigid curved tool, and in part any curved
//! contact (the chords of the convex side) — the nodes of one side touch
//! the other side's chords while the other side's nodes stand off the
//! first side's chords by the difference of their sagittas, far more than
//! the penalty's overlap: one family carries the contact alone. The solve
//! is then the exact contact of those two polygons; ℓc counts, contact
//! zone by zone, the family active over the longer length (the mean of the
//! two counts half the width of a one-sided contact: an outside probe's
//! rigid cylinder read ℓc 0.50 of 2a at h = a/64). Where
//! the carrying family's apices are the finer side's nodes, only those
//! nearest the other side's edge midpoints carry force, and the nodal
//! forces are lumpy (a Lamé fit with the outer ring 2× coarser: nodal
//! pressures 0.51 p … 2 p, hoop stress next to the interface off by
//! 0.73 p; a rigid cylinder 2.5× finer than the block: −15 % at the axis),
//! though with nearly matching nodes they can be right (a rigid cylinder:
//! 2e-3): [`one_sided_warnings`] says so.

use std::collections::HashMap;

use super::{ContactElement, ContactPair};

/// Below this share of the other family's active length a family counts
/// as missing. Measured, the smaller family's share: 1 on flat interfaces
/// (matching or not) and the seed scene; Hertz with equal moduli 0.52–0.8
/// (the matching mesh's cylinder chords, §6.2's chord-normal defect,
/// 0.65, 0.58, 0.52 at h = a/16 … a/64); one-sided pairs 0–0.1.
const SHARE: f64 = 0.2;

/// Fewer active elements than this in a zone say nothing (a contact a
/// few elements wide has no interior).
const MIN_ACTIVE: usize = 8;

/// One contact zone of a pair: its active elements connected through
/// shared nodes, split into the two families.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Zone {
    /// The pair of its elements.
    pub pair: usize,
    /// Σ f_e over its elements, per family.
    pub active_length: [f64; 2],
    /// Its elements.
    pub active: usize,
}

/// The contact zones of B, pair by pair: the active elements of a pair
/// connected through shared nodes, split into the two families by the
/// side of their edge. The two nodes of an element's edge are on one side
/// and its apex on the other, so the sides are the two colours of the
/// graph whose vertices are the stretches of each side joined by active
/// edges. A zone that cannot be so coloured (a user's B with an apex on
/// both sides of one edge chain, or an apex that is a node of its own
/// edge) forms no zone: its (pair, active length) is returned apart.
/// Pairs are coloured apart, so that sides shared by several pairs (a
/// block on two others) do not join their zones.
pub fn zones(elements: &[ContactElement], active: &[bool]) -> (Vec<Zone>, Vec<(usize, f64)>) {
    let mut by_pair: HashMap<usize, Vec<&ContactElement>> = HashMap::new();
    for (el, _) in elements.iter().zip(active).filter(|(_, a)| **a) {
        by_pair.entry(el.pair).or_default().push(el);
    }
    let mut pairs: Vec<usize> = by_pair.keys().copied().collect();
    pairs.sort_unstable();
    let (mut out, mut apart) = (Vec::new(), Vec::new());
    for pair in pairs {
        let (mut z, mut a) = pair_zones(pair, &by_pair[&pair]);
        out.append(&mut z);
        apart.append(&mut a);
    }
    (out, apart)
}

/// [`zones`] of one pair's active elements.
fn pair_zones(pair: usize, elements: &[&ContactElement]) -> (Vec<Zone>, Vec<(usize, f64)>) {
    let edge = |el: &ContactElement| {
        let mut e = el.nodes.iter().copied().filter(|&v| v != el.apex);
        (e.next().unwrap_or(el.apex), e.next().unwrap_or(el.apex))
    };
    let mut dsu = Dsu::default();
    for el in elements {
        let (p, q) = edge(el);
        dsu.union(p, q);
        dsu.find(el.apex);
    }
    // Stretches joined by elements: (edge's, apex's), coloured apart.
    let mut links: HashMap<usize, Vec<usize>> = HashMap::new();
    for el in elements {
        let (e, a) = (dsu.find(edge(el).0), dsu.find(el.apex));
        links.entry(e).or_default().push(a);
        links.entry(a).or_default().push(e);
    }
    let mut colour: HashMap<usize, (usize, u8)> = HashMap::new();
    let mut bad: Vec<bool> = Vec::new();
    let mut roots: Vec<usize> = links.keys().copied().collect();
    roots.sort_unstable();
    for r in roots {
        if colour.contains_key(&r) {
            continue;
        }
        let g = bad.len();
        bad.push(false);
        colour.insert(r, (g, 0));
        let mut stack = vec![r];
        while let Some(c) = stack.pop() {
            let (_, k) = colour[&c];
            for &n in &links[&c] {
                match colour.get(&n) {
                    None => {
                        colour.insert(n, (g, 1 - k));
                        stack.push(n);
                    }
                    Some(&(_, kn)) if kn == k => bad[g] = true,
                    Some(_) => {}
                }
            }
        }
    }
    let mut zones = vec![
        Zone {
            pair,
            ..Default::default()
        };
        bad.len()
    ];
    let mut apart = Vec::new();
    for el in elements {
        let (g, k) = colour[&dsu.find(edge(el).0)];
        if bad[g] {
            apart.push((pair, el.facing));
            continue;
        }
        zones[g].active_length[usize::from(k)] += el.facing;
        zones[g].active += 1;
    }
    zones.retain(|z| z.active > 0);
    (zones, apart)
}

/// ℓc (docs/method.md §6.8) and the one-sided warnings of an active set
/// ([`contact_length`], [`one_sided_warnings`]) from one pass over B.
pub fn contact_length_and_warnings(
    elements: &[ContactElement],
    active: &[bool],
    pairs: &[ContactPair],
) -> (f64, Vec<String>) {
    let (zones, apart) = zones(elements, active);
    (length_of(&zones, &apart), warnings_of(&zones, pairs))
}

/// ℓc (docs/method.md §6.8): zone by zone, the active length of the family
/// active over the longer length; elements that form no zone count half,
/// as each point lies under two of them.
pub fn contact_length(elements: &[ContactElement], active: &[bool]) -> f64 {
    let (zones, apart) = zones(elements, active);
    length_of(&zones, &apart)
}

fn length_of(zones: &[Zone], apart: &[(usize, f64)]) -> f64 {
    // Folded from +0.0: `Sum` for f64 starts from −0.0, which an empty
    // active set would return.
    let whole = zones.iter().fold(0.0, |sum, z| {
        sum + z.active_length[0].max(z.active_length[1])
    });
    apart.iter().fold(whole, |sum, (_, l)| sum + 0.5 * l)
}

/// A warning for each zone that one family carries alone (active over
/// less than 0.2 of the other's length, with at least 8 active elements),
/// naming the pair by its tags.
pub fn one_sided_warnings(
    elements: &[ContactElement],
    active: &[bool],
    pairs: &[ContactPair],
) -> Vec<String> {
    warnings_of(&zones(elements, active).0, pairs)
}

fn warnings_of(zones: &[Zone], pairs: &[ContactPair]) -> Vec<String> {
    let mut warnings = Vec::new();
    for z in zones.iter().chain(&scattered(zones)) {
        let [la, lb] = z.active_length;
        let (long, short) = (la.max(lb), la.min(lb));
        if z.active < MIN_ACTIVE || short >= SHARE * long {
            continue;
        }
        let p = &pairs[z.pair];
        warnings.push(format!(
            "contact pair {} (tags {}, {}) is one-sided: the elements of B with their edge on one \
             side are active over {long:.3e}, those with their edge on the other over \
             {short:.3e}; the two sides' polygons do not conform (a curved interface meshed with \
             different nodes on its two sides, or a stiff or rigid curved tool), and the nodal \
             contact pressures and the stresses next to the interface can be off by O(p) \
             (docs/method.md §6.11, \"One-sided contact\"); give the sides matching nodes where \
             the interface is curved",
            z.pair, p.tag_a, p.tag_b
        ));
    }
    warnings
}

/// For each pair whose contact falls apart into zones too small to judge
/// one by one, every one carried by one family, the pair's zones judged
/// together: Σ of each zone's longer family against Σ of its shorter.
/// The 2:3 shrink-fit rings, the coarser ring inside, press only the fine
/// edges facing a coarse node: each active element is a zone of its own,
/// the contact length a third of the circle, and no zone reached
/// [`MIN_ACTIVE`] to say so.
fn scattered(zones: &[Zone]) -> Vec<Zone> {
    let mut whole: std::collections::BTreeMap<usize, Zone> = Default::default();
    for z in zones.iter().filter(|z| z.active < MIN_ACTIVE) {
        let [la, lb] = z.active_length;
        let w = whole.entry(z.pair).or_insert(Zone {
            pair: z.pair,
            active_length: [0.0; 2],
            active: 0,
        });
        w.active_length[0] += la.max(lb);
        w.active_length[1] += la.min(lb);
        w.active += z.active;
    }
    whole
        .into_values()
        .filter(|w| {
            zones
                .iter()
                .all(|z| z.pair != w.pair || z.active < MIN_ACTIVE)
        })
        .collect()
}

/// Union–find over node numbers.
#[derive(Default)]
struct Dsu {
    parent: HashMap<usize, usize>,
}

impl Dsu {
    fn find(&mut self, v: usize) -> usize {
        let mut r = *self.parent.entry(v).or_insert(v);
        while self.parent[&r] != r {
            r = self.parent[&r];
        }
        // Path compression.
        let mut c = v;
        while self.parent[&c] != r {
            let next = self.parent[&c];
            self.parent.insert(c, r);
            c = next;
        }
        r
    }

    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.parent.insert(ra.max(rb), ra.min(rb));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The strip between side a (nodes 0..=n along y = 0) and side b
    /// (nodes n+1..=2n+1, matching, along y = 0): edge (i, i+1) of a with
    /// apex b_{i+1}, edge (b_i, b_{i+1}) with apex a_i, unit edges.
    fn matching_strip(n: usize) -> Vec<ContactElement> {
        let b = |i: usize| n + 1 + i;
        let el = |nodes: [usize; 3], apex: usize| ContactElement {
            nodes,
            normal: [0.0, 1.0],
            j0: 0.0,
            h: 1.0,
            edge_length: 1.0,
            facing: 1.0,
            pair: 0,
            apex,
        };
        (0..n)
            .flat_map(|i| {
                [
                    el([i, i + 1, b(i + 1)], b(i + 1)),
                    el([b(i + 1), b(i), i], i),
                ]
            })
            .collect()
    }

    #[test]
    fn both_families_active_count_the_interface_once() {
        let els = matching_strip(4);
        assert_eq!(contact_length(&els, &vec![true; els.len()]), 4.0);
    }

    #[test]
    fn one_family_active_alone_counts_its_whole_length() {
        let els = matching_strip(4);
        let active: Vec<bool> = (0..els.len()).map(|k| k % 2 == 0).collect();
        assert_eq!(contact_length(&els, &active), 4.0);
    }

    #[test]
    fn families_that_disagree_count_the_longer() {
        let els = matching_strip(4);
        // Family a over 3 edges, family b over 2.
        let active: Vec<bool> = (0..els.len())
            .map(|k| if k % 2 == 0 { k / 2 < 3 } else { k / 2 < 2 })
            .collect();
        assert_eq!(contact_length(&els, &active), 3.0);
    }

    /// `els` shifted to nodes from `first` on and to pair `pair`.
    fn moved(els: &[ContactElement], first: usize, pair: usize) -> Vec<ContactElement> {
        els.iter()
            .map(|e| ContactElement {
                nodes: e.nodes.map(|v| v + first),
                apex: e.apex + first,
                pair,
                ..e.clone()
            })
            .collect()
    }

    #[test]
    fn pairs_whose_sides_close_an_odd_cycle_keep_their_own_zones() {
        // A reviewer's case: three pairs whose sides share corner nodes
        // (two blocks on a third) close a cycle that cannot be coloured in
        // two; coloured together, every element fell back to the half
        // count. Pair 0 one-sided over 4 edges; pairs 1 and 2 share its
        // nodes through their own elements.
        let mut els: Vec<ContactElement> = matching_strip(4)
            .into_iter()
            .enumerate()
            .filter(|(k, _)| k % 2 == 0)
            .map(|(_, e)| e)
            .collect();
        let n = els.len();
        els.extend(moved(&matching_strip(4), 4, 1));
        els.extend(moved(&matching_strip(4), 5, 2));
        let active: Vec<bool> = (0..els.len()).map(|k| k < n).collect();
        assert_eq!(contact_length(&els, &active), 4.0);
    }

    #[test]
    fn two_zones_carried_by_opposite_families_count_both() {
        let els = matching_strip(8);
        // Edges 0..4 by family a alone, 4..8 by family b alone.
        let active: Vec<bool> = (0..els.len())
            .map(|k| if k % 2 == 0 { k / 2 < 4 } else { k / 2 >= 5 })
            .collect();
        assert_eq!(contact_length(&els, &active), 7.0);
    }

    #[test]
    fn a_one_sided_zone_beside_a_conforming_one_is_warned_about() {
        let mut els = matching_strip(10);
        let n = els.len();
        els.extend(moved(&matching_strip(10), 100, 0));
        // The first zone conforming, the second one-sided.
        let active: Vec<bool> = (0..els.len()).map(|k| k < n || k % 2 == 0).collect();
        let pairs = [ContactPair {
            tag_a: 1,
            tag_b: 2,
            body_a: 1,
            body_b: 2,
            user_mesh: None,
            friction: 0.0,
        }];
        let (lc, w) = contact_length_and_warnings(&els, &active, &pairs);
        assert_eq!(lc, 20.0);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].contains("contact pair 0 (tags 1, 2) is one-sided"),
            "{w:?}"
        );
    }

    #[test]
    fn nothing_active_is_plus_zero() {
        let els = matching_strip(3);
        let lc = contact_length(&els, &vec![false; els.len()]);
        assert!(lc == 0.0 && lc.is_sign_positive());
    }
}
