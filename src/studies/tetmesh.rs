//! Structured tetrahedral meshes of the unit cube for the study of Jmin in
//! three dimensions (docs/method.md §9): Kuhn's six tetrahedra per box, and
//! bands of flat tetrahedra of three kinds across the plane z = 1/2 — the
//! 3D analogues of the 2D band of flat triangles
//! ([`crate::studies::meshgen::unit_square`]).

use crate::contact::prism_layer::split_prism;

/// A tetrahedral mesh: nodes and positively oriented tetrahedra (J ≥ 0;
/// flat ones have J = 0 up to round-off).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TetMesh {
    /// Node coordinates.
    pub nodes: Vec<[f64; 3]>,
    /// Tetrahedra, four node indices each.
    pub tets: Vec<[usize; 4]>,
    /// The part each tetrahedron belongs to (empty: one part). For
    /// [`TetMesh::tied_blocks`]: [`LOWER`], [`UPPER`] or [`LAYER`].
    pub parts: Vec<usize>,
}

/// The lower block of [`TetMesh::tied_blocks`].
pub const LOWER: usize = 0;
/// The upper block of [`TetMesh::tied_blocks`].
pub const UPPER: usize = 1;
/// The flat layer that ties them.
pub const LAYER: usize = 2;

/// How the prisms of a tied layer are split into tetrahedra: every
/// quadrilateral face from its lowest-ranked node (so that neighbours agree
/// and no prism meets a cycle of diagonals), the ranks given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Split {
    /// The ranks are the node indices.
    ByIndex,
    /// The ranks are a pseudo-random permutation drawn from this seed.
    Shuffled(u64),
}

/// A band of flat tetrahedra across z = 1/2, of thickness `eps` (the
/// argument of each case, far below h in the study).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Band {
    /// A slab of Kuhn boxes of height eps: the layer of prisms split into
    /// three tetrahedra each that the mesh of a closed 3D gap is made of —
    /// caps (a face and a vertex above one of its corners) and tetrahedra
    /// of an edge and an edge, all with a short vertical edge. Its flat
    /// elements tie the faces above and below node to node.
    Prisms(f64),
    /// Two staggered layers: a sheet of nodes at height eps above the cell
    /// centres of the grid z = 1/2, joined to the grids below and above by
    /// pyramids (each split into two caps whose apex lies over an edge's
    /// midpoint) and by slivers (a grid edge and the crossing edge of the
    /// sheet: four nearly coplanar nodes, no short edge). The analogue of
    /// the 2D band of caps, which constrains the field along it.
    Staggered(f64),
    /// Two Kuhn slabs of thickness eps crossing: x ∈ [1/2, 1/2 + eps] and
    /// z ∈ [1/2, 1/2 + eps]; where they cross, boxes eps × h × eps whose
    /// tetrahedra are needles (four nodes near a line).
    Needles(f64),
}

impl TetMesh {
    /// The unit cube with n boxes per side (n even) and, if given, a band.
    pub fn unit_cube(n: usize, band: Option<Band>) -> TetMesh {
        assert!(n >= 2 && n % 2 == 0, "the band sits on a grid plane");
        let grid: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
        let with_line = |eps: f64| {
            let mut g = grid.clone();
            g.insert(n / 2 + 1, 0.5 + eps);
            g
        };
        match band {
            None => TetMesh::kuhn(&grid, &grid, &grid),
            Some(Band::Prisms(eps)) => TetMesh::kuhn(&grid, &grid, &with_line(eps)),
            Some(Band::Needles(eps)) => TetMesh::kuhn(&with_line(eps), &grid, &with_line(eps)),
            Some(Band::Staggered(eps)) => TetMesh::staggered(n, eps),
        }
    }

    /// Kuhn's split of the tensor grid xs × ys × zs: each box into the six
    /// tetrahedra along its diagonal from its lowest corner, which makes
    /// every face's split the same and the mesh conforming.
    pub fn kuhn(xs: &[f64], ys: &[f64], zs: &[f64]) -> TetMesh {
        let mut mesh = TetMesh::default();
        let id = mesh.add_grid(xs, ys, zs);
        for k in 0..zs.len() - 1 {
            for j in 0..ys.len() - 1 {
                for i in 0..xs.len() - 1 {
                    mesh.add_kuhn_box(|a, b, c| id(i + a, j + b, k + c));
                }
            }
        }
        mesh
    }

    /// Adds the nodes of xs × ys × zs; returns their index by position.
    fn add_grid(
        &mut self,
        xs: &[f64],
        ys: &[f64],
        zs: &[f64],
    ) -> impl Fn(usize, usize, usize) -> usize + use<> {
        let first = self.nodes.len();
        for &z in zs {
            for &y in ys {
                for &x in xs {
                    self.nodes.push([x, y, z]);
                }
            }
        }
        let (nx, ny) = (xs.len(), ys.len());
        move |i, j, k| first + i + nx * (j + ny * k)
    }

    /// The six Kuhn tetrahedra of the box whose corner (a, b, c) ∈ {0,1}³
    /// is node `corner(a, b, c)`.
    fn add_kuhn_box(&mut self, corner: impl Fn(usize, usize, usize) -> usize) {
        // Paths from (0,0,0) to (1,1,1) by unit steps in every order; odd
        // orders are mirror images, numbered backwards to keep J ≥ 0.
        const ORDERS: [([usize; 3], bool); 6] = [
            ([0, 1, 2], true),
            ([1, 2, 0], true),
            ([2, 0, 1], true),
            ([0, 2, 1], false),
            ([2, 1, 0], false),
            ([1, 0, 2], false),
        ];
        for (order, even) in ORDERS {
            let mut p = [0usize; 3];
            let mut t = [corner(0, 0, 0); 4];
            for (s, &axis) in order.iter().enumerate() {
                p[axis] = 1;
                t[s + 1] = corner(p[0], p[1], p[2]);
            }
            if !even {
                t.swap(2, 3);
            }
            self.tets.push(t);
        }
    }

    /// Adds the tetrahedron a, b, c, d oriented so that J ≥ 0, deciding
    /// the orientation on the given reference positions (the mesh's, or
    /// an unflattened copy's where the element is flat).
    fn add_oriented(&mut self, t: [usize; 4], reference: &[[f64; 3]]) {
        let j = crate::fem::tet::TetGeometry::new(&t.map(|v| reference[v])).j;
        self.tets
            .push(if j < 0.0 { [t[0], t[1], t[3], t[2]] } else { t });
    }

    /// The staggered band (see [`Band::Staggered`]): Kuhn boxes below
    /// z = 1/2 and above z = 1/2 + h, between them a sheet S of nodes at
    /// z = 1/2 + eps over the cell centres (and the boundary's edge
    /// midpoints and corners), joined to the grid plane G₀ at z = 1/2 and
    /// to G₁ at z = 1/2 + h by the same staggered layer.
    fn staggered(n: usize, eps: f64) -> TetMesh {
        let h = 1.0 / n as f64;
        let grid: Vec<f64> = (0..=n).map(|i| i as f64 * h).collect();
        let lower: Vec<f64> = grid[..=n / 2].to_vec();
        let upper: Vec<f64> = grid[n / 2 + 1..].to_vec();
        let mut sheet: Vec<f64> = vec![0.0];
        sheet.extend((0..n).map(|i| (i as f64 + 0.5) * h));
        sheet.push(1.0);
        let mut mesh = TetMesh::default();
        let below = mesh.add_grid(&grid, &grid, &lower);
        let s = mesh.add_grid(&sheet, &sheet, &[0.5 + eps]);
        let above = mesh.add_grid(&grid, &grid, &upper);
        for k in 0..lower.len() - 1 {
            for j in 0..n {
                for i in 0..n {
                    mesh.add_kuhn_box(|a, b, c| below(i + a, j + b, k + c));
                }
            }
        }
        for k in 0..upper.len() - 1 {
            for j in 0..n {
                for i in 0..n {
                    mesh.add_kuhn_box(|a, b, c| above(i + a, j + b, k + c));
                }
            }
        }
        // Orientation is decided on a copy with the sheet at half the
        // layer's height, where no element of the layers is flat.
        let mut reference = mesh.nodes.clone();
        for j in 0..=n + 1 {
            for i in 0..=n + 1 {
                reference[s(i, j, 0)][2] = 0.5 + 0.5 * h;
            }
        }
        let g0 = |i, j| below(i, j, n / 2);
        let g1 = |i, j| above(i, j, 0);
        mesh.staggered_layer(n, &g0, &s, &reference);
        reference.iter_mut().for_each(|p| {
            if p[2] == 0.5 + 0.5 * h {
                p[2] = 0.5;
            }
        });
        mesh.staggered_layer(n, &g1, &s, &reference);
        mesh
    }

    /// The tetrahedra between the grid plane `g` ((n+1)² nodes) and the
    /// sheet `s` ((n+2)² nodes: the sheet node (i+1, j+1) over the centre
    /// of grid cell (i, j), sheet cell (I, J) around grid node (I, J)).
    fn staggered_layer(
        &mut self,
        n: usize,
        g: &impl Fn(usize, usize) -> usize,
        s: &impl Fn(usize, usize, usize) -> usize,
        reference: &[[f64; 3]],
    ) {
        let s = |i, j| s(i, j, 0);
        for j in 0..n {
            for i in 0..n {
                // The grid cell's pyramid to the sheet node over its
                // centre, split along the Kuhn diagonal of the boxes.
                let apex = s(i + 1, j + 1);
                let (a, b, c, d) = (g(i, j), g(i + 1, j), g(i + 1, j + 1), g(i, j + 1));
                self.add_oriented([a, b, c, apex], reference);
                self.add_oriented([a, c, d, apex], reference);
            }
        }
        for j in 0..=n {
            for i in 0..=n {
                // The sheet cell's pyramid to the grid node inside it.
                let apex = g(i, j);
                let (a, b, c, d) = (s(i, j), s(i + 1, j), s(i + 1, j + 1), s(i, j + 1));
                self.add_oriented([a, b, c, apex], reference);
                self.add_oriented([a, c, d, apex], reference);
            }
        }
        for j in 0..=n {
            for i in 0..n {
                // The grid edge along x and the sheet edge crossing it.
                let t = [g(i, j), g(i + 1, j), s(i + 1, j), s(i + 1, j + 1)];
                self.add_oriented(t, reference);
            }
        }
        for j in 0..n {
            for i in 0..=n {
                // The grid edge along y and the sheet edge crossing it.
                let t = [g(i, j), g(i, j + 1), s(i, j + 1), s(i + 1, j + 1)];
                self.add_oriented(t, reference);
            }
        }
    }

    /// Two Kuhn blocks of the unit cube, (0, 1)² × (0, 1/2) and
    /// (0, 1)² × (1/2, 1) with n boxes per side (n even), each with its own
    /// nodes on z = 1/2, joined by the layer of zero-volume prisms over the
    /// interface's (matching) triangles, each split into three flat
    /// tetrahedra as `split` says: stage 2 of docs/method.md §9.
    pub fn tied_blocks(n: usize, split: Split) -> TetMesh {
        assert!(n >= 2 && n % 2 == 0, "the interface sits on a grid plane");
        let grid: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
        TetMesh::stacked(&grid, &grid, &grid[..=n / 2], &grid[n / 2..], split)
    }

    /// The unit square's blocks of the 3D contact patch test, lower
    /// z ∈ [−1/2, 0] and upper z ∈ [0, 1/2] with n boxes per side (n even),
    /// the interface's nodes jittered by `jitter` of h.
    pub fn patch_blocks(n: usize, split: Split, jitter: f64) -> TetMesh {
        let h = 1.0 / n as f64;
        let xs: Vec<f64> = (0..=n).map(|i| i as f64 * h).collect();
        let lower: Vec<f64> = (0..=n / 2).map(|i| -0.5 + i as f64 * h).collect();
        let upper: Vec<f64> = (0..=n / 2).map(|i| i as f64 * h).collect();
        let mut mesh = TetMesh::stacked(&xs, &xs, &lower, &upper, split);
        mesh.jitter_interface(0.0, h, jitter, 17);
        mesh
    }

    /// Two Kuhn blocks xs × ys × `lower` and xs × ys × `upper` (the last
    /// of `lower` is the first of `upper`: the interface plane), each with
    /// its own nodes on the interface, joined by the layer of zero-volume
    /// prisms over its triangles split as `split` says; parts [`LOWER`],
    /// [`UPPER`], [`LAYER`].
    pub fn stacked(xs: &[f64], ys: &[f64], lower: &[f64], upper: &[f64], split: Split) -> TetMesh {
        let cover = [xs.len() - 1, ys.len() - 1];
        TetMesh::stacked_under(xs, ys, lower, upper, cover, split)
    }

    /// [`TetMesh::stacked`] with the upper block over the first
    /// `cover[0]` × `cover[1]` cells of the lower one's top only (a tool
    /// smaller than the block; a cover beyond the grid is the whole top),
    /// the layer under it.
    pub fn stacked_under(
        xs: &[f64],
        ys: &[f64],
        lower: &[f64],
        upper: &[f64],
        cover: [usize; 2],
        split: Split,
    ) -> TetMesh {
        let (nx, ny) = (xs.len() - 1, ys.len() - 1);
        let [cx, cy] = [cover[0].min(nx), cover[1].min(ny)];
        let mut mesh = TetMesh::default();
        let below = mesh.add_grid(xs, ys, lower);
        mesh.add_kuhn_boxes(nx, ny, lower.len() - 1, &below);
        mesh.parts = vec![LOWER; mesh.tets.len()];
        let above = mesh.add_grid(&xs[..=cx], &ys[..=cy], upper);
        mesh.add_kuhn_boxes(cx, cy, upper.len() - 1, &above);
        mesh.parts.resize(mesh.tets.len(), UPPER);
        let rank = ranks(mesh.nodes.len(), split);
        // Orientation is decided with the upper face lifted: flat, every
        // layer tetrahedron has J = 0.
        let mut reference = mesh.nodes.clone();
        let lift = upper[1] - upper[0];
        for j in 0..=cy {
            for i in 0..=cx {
                reference[above(i, j, 0)][2] += 0.5 * lift;
            }
        }
        let top_of_lower = lower.len() - 1;
        for j in 0..cy {
            for i in 0..cx {
                // The interface's two triangles of cell (i, j), as the Kuhn
                // boxes split it: along the diagonal (i, j)-(i+1, j+1).
                for tri in [
                    [(i, j), (i + 1, j), (i + 1, j + 1)],
                    [(i, j), (i + 1, j + 1), (i, j + 1)],
                ] {
                    let bottom = tri.map(|(a, b)| below(a, b, top_of_lower));
                    let top = tri.map(|(a, b)| above(a, b, 0));
                    for t in split_prism(bottom, top, |v| rank[v]) {
                        mesh.add_oriented(t, &reference);
                    }
                }
            }
        }
        mesh.parts.resize(mesh.tets.len(), LAYER);
        mesh
    }

    /// The Kuhn boxes of an nx × ny × nz grid of nodes `id`.
    fn add_kuhn_boxes(
        &mut self,
        nx: usize,
        ny: usize,
        nz: usize,
        id: &impl Fn(usize, usize, usize) -> usize,
    ) {
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    self.add_kuhn_box(|a, b, c| id(i + a, j + b, k + c));
                }
            }
        }
    }

    /// Moves the nodes of the plane z = `plane` that are not on the unit
    /// square's sides within the plane, each by up to `fraction` of `h` in
    /// x and y, pseudo-randomly from `seed` and from its position, so that
    /// the two copies of a tied interface move together: a non-uniform
    /// interface triangulation.
    pub fn jitter_interface(&mut self, plane: f64, h: f64, fraction: f64, seed: u64) {
        for p in &mut self.nodes {
            if p[2] != plane || p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0 {
                continue;
            }
            let mut state = seed ^ p[0].to_bits().rotate_left(17) ^ p[1].to_bits();
            let mut next = || {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
            };
            let (dx, dy) = (next(), next());
            p[0] += fraction * h * dx;
            p[1] += fraction * h * dy;
        }
    }

    /// The faces that belong to one tetrahedron only, each with that
    /// tetrahedron's index.
    pub fn boundary_faces(&self) -> Vec<(usize, [usize; 3])> {
        let mut faces: Vec<([usize; 3], usize, [usize; 3])> = (self.tets.iter().enumerate())
            .flat_map(|(e, t)| {
                [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]].map(|f| {
                    let face = f.map(|k| t[k]);
                    let mut key = face;
                    key.sort_unstable();
                    (key, e, face)
                })
            })
            .collect();
        faces.sort_unstable();
        let mut open = Vec::new();
        let mut i = 0;
        while i < faces.len() {
            let mut j = i + 1;
            while j < faces.len() && faces[j].0 == faces[i].0 {
                j += 1;
            }
            if j - i == 1 {
                open.push((faces[i].1, faces[i].2));
            }
            i = j;
        }
        open
    }

    /// Checks that the mesh is a stacked one ([`TetMesh::stacked`]): a part
    /// for every tetrahedron, a [`LAYER`] and facing nodes across it.
    pub fn check_stacked(&self) -> crate::error::Result<()> {
        if self.parts.len() != self.tets.len() {
            return Err(crate::error::Error::argument(format!(
                "the mesh has {} tetrahedra but {} parts: build it with TetMesh::stacked",
                self.tets.len(),
                self.parts.len()
            )));
        }
        if !self.parts.contains(&LAYER) || self.facing_pairs().is_empty() {
            return Err(crate::error::Error::argument(
                "the mesh has no layer between facing blocks: build it with TetMesh::stacked",
            ));
        }
        Ok(())
    }

    /// The largest side of the bounding box.
    pub fn size(&self) -> f64 {
        (0..3)
            .map(|i| {
                let (lo, hi) = (self.nodes.iter())
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                        (a.min(p[i]), b.max(p[i]))
                    });
                hi - lo
            })
            .fold(0.0, f64::max)
    }

    /// The node pairs (lower copy, upper copy) that face each other across
    /// the [`LAYER`] of a stacked mesh, matched by their x and y.
    pub fn facing_pairs(&self) -> Vec<(usize, usize)> {
        let mut side = vec![usize::MAX; self.nodes.len()];
        let mut on_layer = vec![false; self.nodes.len()];
        for (e, t) in self.tets.iter().enumerate() {
            for &v in t {
                if self.parts[e] == LAYER {
                    on_layer[v] = true;
                } else {
                    side[v] = self.parts[e];
                }
            }
        }
        let key = |v: &usize| (self.nodes[*v][0].to_bits(), self.nodes[*v][1].to_bits());
        let pick = |part: usize| {
            let mut nodes: Vec<usize> = (0..self.nodes.len())
                .filter(|&v| on_layer[v] && side[v] == part)
                .collect();
            nodes.sort_by_key(key);
            nodes
        };
        pick(LOWER).into_iter().zip(pick(UPPER)).collect()
    }

    /// The nodes on the boundary: those of faces that belong to one
    /// tetrahedron only.
    pub fn boundary_nodes(&self) -> Vec<usize> {
        let mut nodes: Vec<usize> = (self.boundary_faces().into_iter())
            .flat_map(|(_, f)| f)
            .collect();
        nodes.sort_unstable();
        nodes.dedup();
        nodes
    }
}

/// The ranks of `n` nodes for [`Split`].
fn ranks(n: usize, split: Split) -> Vec<usize> {
    let mut rank: Vec<usize> = (0..n).collect();
    if let Split::Shuffled(seed) = split {
        // Fisher–Yates with a 64-bit LCG: reproducible, no dependency.
        let mut state = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        for i in (1..n).rev() {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let j = ((state >> 33) as usize) % (i + 1);
            rank.swap(i, j);
        }
    }
    rank
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::tet::TetGeometry;

    fn geometries(m: &TetMesh) -> Vec<TetGeometry> {
        (m.tets.iter())
            .map(|t| TetGeometry::new(&t.map(|v| m.nodes[v])))
            .collect()
    }

    fn meshes() -> Vec<(&'static str, TetMesh)> {
        vec![
            ("tied", TetMesh::tied_blocks(4, Split::Shuffled(3))),
            ("regular", TetMesh::unit_cube(4, None)),
            ("prisms", TetMesh::unit_cube(4, Some(Band::Prisms(1e-3)))),
            (
                "staggered",
                TetMesh::unit_cube(4, Some(Band::Staggered(1e-3))),
            ),
            ("needles", TetMesh::unit_cube(4, Some(Band::Needles(1e-3)))),
        ]
    }

    #[test]
    fn every_mesh_fills_the_cube_once_with_positive_volumes() {
        for (name, m) in meshes() {
            let geo = geometries(&m);
            let layer = |e: usize| m.parts.get(e) == Some(&LAYER);
            assert!((0..geo.len()).all(|e| geo[e].j > 0.0 || layer(e)), "{name}");
            let volume: f64 = geo.iter().map(|g| g.j / 6.0).sum();
            assert!((volume - 1.0).abs() < 1e-13, "{name}: volume {volume}");
        }
    }

    #[test]
    fn every_interior_face_is_shared_by_two_tetrahedra_and_the_rest_lie_on_the_cube() {
        for (name, m) in meshes() {
            let mut faces: Vec<[usize; 3]> = (m.tets.iter())
                .flat_map(|t| {
                    [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]].map(|f| {
                        let mut face = f.map(|k| t[k]);
                        face.sort_unstable();
                        face
                    })
                })
                .collect();
            faces.sort_unstable();
            let mut counts = std::collections::HashMap::new();
            for f in &faces {
                *counts.entry(*f).or_insert(0) += 1;
            }
            for (f, c) in counts {
                assert!(c <= 2, "{name}: face {f:?} in {c} tetrahedra");
                if c == 1 {
                    let on_a_side = (0..3).any(|axis| {
                        let x = f.map(|v| m.nodes[v][axis]);
                        x.iter().all(|&a| a == 0.0) || x.iter().all(|&a| a == 1.0)
                    });
                    assert!(on_a_side, "{name}: open face {f:?} inside the cube");
                }
            }
        }
    }

    #[test]
    fn the_bands_are_flat_where_intended_and_nowhere_else() {
        let n = 4;
        let h = 1.0 / n as f64;
        for (name, m) in meshes() {
            let flat = geometries(&m)
                .iter()
                .filter(|g| g.j < 1e-2 * h * h * h)
                .count();
            let expected = match name {
                "regular" => 0,
                "tied" => 6 * n * n,
                // 6 per box of the slab.
                "prisms" => 6 * n * n,
                // Per layer: 2 per grid cell and per sheet cell, one per
                // grid edge; only the layer of height eps is flat.
                "staggered" => 2 * n * n + 2 * (n + 1) * (n + 1) + 2 * n * (n + 1),
                // Two slabs of n(n + 1) boxes sharing a row of n.
                "needles" => 6 * (2 * n * (n + 1) - n),
                _ => unreachable!(),
            };
            assert_eq!(flat, expected, "{name}");
        }
    }

    #[test]
    fn a_zero_thickness_band_is_still_oriented_and_conforming() {
        for band in [Band::Prisms(0.0), Band::Staggered(0.0), Band::Needles(0.0)] {
            let m = TetMesh::unit_cube(4, Some(band));
            let volume: f64 = geometries(&m).iter().map(|g| g.j / 6.0).sum();
            assert!((volume - 1.0).abs() < 1e-13, "{band:?}: volume {volume}");
            assert!(geometries(&m).iter().all(|g| g.j > -1e-15), "{band:?}");
        }
    }

    #[test]
    fn a_prism_splits_into_three_tetrahedra_that_fill_it_for_every_ranking() {
        // Bottom (0,0,0), (1,0,0), (0,1,0); top at z = 1: volume 1/2.
        let nodes = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
        ];
        for seed in 0..50 {
            let rank = ranks(6, Split::Shuffled(seed));
            let tets = split_prism([0, 1, 2], [3, 4, 5], |v| rank[v]);
            let volumes: Vec<f64> = (tets.iter())
                .map(|t| TetGeometry::new(&t.map(|v| nodes[v])).j.abs() / 6.0)
                .collect();
            assert!(
                volumes.iter().all(|&v| v > 1e-3),
                "seed {seed}: {volumes:?}"
            );
            let total: f64 = volumes.iter().sum();
            assert!((total - 0.5).abs() < 1e-15, "seed {seed}: {total}");
        }
    }

    #[test]
    fn tied_blocks_are_two_conforming_blocks_and_a_layer_of_exactly_flat_tetrahedra() {
        let n = 4;
        for split in [Split::ByIndex, Split::Shuffled(7)] {
            let m = TetMesh::tied_blocks(n, split);
            let geo = geometries(&m);
            let layer: Vec<usize> = (0..m.tets.len()).filter(|&e| m.parts[e] == LAYER).collect();
            assert_eq!(layer.len(), 3 * 2 * n * n, "three per interface triangle");
            assert!(layer.iter().all(|&e| geo[e].j == 0.0), "{split:?}");
            let blocks = (0..m.tets.len()).filter(|&e| m.parts[e] != LAYER);
            assert!(blocks.clone().all(|e| geo[e].j > 0.0));
            let volume: f64 = blocks.map(|e| geo[e].j / 6.0).sum();
            assert!((volume - 1.0).abs() < 1e-13, "{volume}");
            // Each node of z = 1/2 twice, once per block.
            let on_interface = (m.nodes.iter()).filter(|p| p[2] == 0.5).count();
            assert_eq!(on_interface, 2 * (n + 1) * (n + 1));
        }
    }

    #[test]
    fn boundary_nodes_are_those_on_the_cube_faces() {
        for (name, m) in meshes() {
            let on_cube = |p: [f64; 3]| p.iter().any(|&x| x == 0.0 || x == 1.0);
            let expected: Vec<usize> = (0..m.nodes.len())
                .filter(|&v| on_cube(m.nodes[v]))
                .collect();
            assert_eq!(m.boundary_nodes(), expected, "{name}");
        }
    }
}
