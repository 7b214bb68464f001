//! Gmsh meshes (MSH 4.1, ASCII or binary) read with the `mshio` crate.
//! Feature `gmsh`.
//!
//! Physical surfaces become bodies (the physical tag is the body tag) and
//! physical curves become boundary-edge tags, for loads, supports and
//! contact interfaces. A surface meshed clockwise (normal along −z) is
//! turned counter-clockwise as a whole. Only 3-node triangles and 2-node lines are accepted;
//! nodes must lie in the plane z = 0.

use std::collections::HashMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use mshio::mshfile::ElementType;

use crate::error::{Error, Result, Status};
use crate::fem::mesh::Mesh;

fn io_error(path: &Path, what: impl std::fmt::Display) -> Error {
    Error::new(Status::Io, format!("{}: {what}", path.display()))
}

fn mesh_error(path: &Path, what: impl std::fmt::Display) -> Error {
    Error::new(Status::InvalidMesh, format!("{}: {what}", path.display()))
}

/// Reads a Gmsh MSH 4.1 file into a validated [`Mesh`] with its tagged
/// boundary edges. `index_base` only affects how messages number items.
pub fn read_msh(path: &Path, index_base: usize) -> Result<Mesh> {
    let bytes = std::fs::read(path).map_err(|e| io_error(path, e))?;
    // mshio still has a few `expect`s on malformed input: keep them inside.
    let parsed = catch_unwind(AssertUnwindSafe(|| {
        mshio::parse_msh_bytes(bytes.as_slice()).map_err(|e| e.to_string())
    }))
    .map_err(|_| io_error(path, "malformed MSH file"))?;
    let msh = parsed.map_err(|e| io_error(path, format!("not a readable MSH 4.1 file: {e}")))?;
    let data = msh.data;
    let entities = data
        .entities
        .ok_or_else(|| mesh_error(path, "no $Entities section: physical groups are needed"))?;
    let surface_body: HashMap<i32, Option<i32>> = entities
        .surfaces
        .iter()
        .map(|s| (s.tag, s.physical_tags.first().copied()))
        .collect();
    let curve_tag: HashMap<i32, Option<i32>> = entities
        .curves
        .iter()
        .map(|c| (c.tag, c.physical_tags.first().copied()))
        .collect();

    let node_data = data
        .nodes
        .ok_or_else(|| mesh_error(path, "no $Nodes section"))?;
    let mut nodes = Vec::with_capacity(node_data.num_nodes as usize);
    let mut index_of: HashMap<u64, usize> = HashMap::new();
    let mut next_tag = node_data.min_node_tag;
    for block in &node_data.node_blocks {
        let mut tags: Vec<u64> = match &block.node_tags {
            Some(map) => {
                let mut t = vec![0u64; block.nodes.len()];
                for (&tag, &i) in map {
                    t[i] = tag;
                }
                t
            }
            None => (0..block.nodes.len() as u64)
                .map(|k| next_tag + k)
                .collect(),
        };
        next_tag += block.nodes.len() as u64;
        for (node, tag) in block.nodes.iter().zip(tags.drain(..)) {
            index_of.insert(tag, nodes.len());
            nodes.push([node.x, node.y, node.z]);
        }
    }
    let scale = nodes
        .iter()
        .flat_map(|p| [p[0].abs(), p[1].abs()])
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    if let Some((k, p)) = nodes
        .iter()
        .enumerate()
        .find(|(_, p)| p[2].abs() > 1e-12 * scale)
    {
        let tag = index_of
            .iter()
            .find(|(_, i)| **i == k)
            .map_or(0, |(t, _)| *t);
        return Err(mesh_error(
            path,
            format!(
                "node {tag} has z = {}: only 2D meshes in the plane z = 0 are supported",
                p[2]
            ),
        ));
    }

    let elements = data
        .elements
        .ok_or_else(|| mesh_error(path, "no $Elements section"))?;
    let lookup = |tag: u64| -> Result<usize> {
        index_of.get(&tag).copied().ok_or_else(|| {
            mesh_error(
                path,
                format!("an element refers to node {tag}, which is not defined"),
            )
        })
    };
    let (mut triangles, mut bodies, mut edges, mut edge_tags) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for block in &elements.element_blocks {
        match (block.entity_dim, block.element_type) {
            (2, ElementType::Tri3) => {
                let body = surface_body
                    .get(&block.entity_tag)
                    .copied()
                    .flatten()
                    .ok_or_else(|| {
                        mesh_error(
                            path,
                            format!(
                                "surface {} has no physical group: every surface must be a body",
                                block.entity_tag
                            ),
                        )
                    })?;
                let first = triangles.len();
                let mut area = 0.0;
                for e in &block.elements {
                    let t = [
                        lookup(e.nodes[0])?,
                        lookup(e.nodes[1])?,
                        lookup(e.nodes[2])?,
                    ];
                    let [a, b, c] = t.map(|v| nodes[v]);
                    area += (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
                    triangles.push(t);
                    bodies.push(body);
                }
                // Gmsh orients a surface's triangles along its normal, which
                // may be −z: make the surface counter-clockwise as a whole
                // (individual inverted triangles, if any, stay inverted).
                if area < 0.0 {
                    for t in &mut triangles[first..] {
                        t.swap(1, 2);
                    }
                }
            }
            (2, other) => {
                return Err(mesh_error(
                    path,
                    format!(
                        "surface {} has elements of type {other:?}: only 3-node triangles are supported",
                        block.entity_tag
                    ),
                ));
            }
            (1, ElementType::Lin2) => {
                // Curves without a physical group carry no load or contact.
                if let Some(tag) = curve_tag.get(&block.entity_tag).copied().flatten() {
                    for e in &block.elements {
                        edges.push([lookup(e.nodes[0])?, lookup(e.nodes[1])?]);
                        edge_tags.push(tag);
                    }
                }
            }
            (1, other) => {
                return Err(mesh_error(
                    path,
                    format!(
                        "curve {} has elements of type {other:?}: only 2-node lines are supported",
                        block.entity_tag
                    ),
                ));
            }
            (0, _) => {}
            (d, _) => {
                return Err(mesh_error(
                    path,
                    format!(
                        "entity {} has dimension {d}: only 2D meshes are supported",
                        block.entity_tag
                    ),
                ));
            }
        }
    }
    if triangles.is_empty() {
        return Err(mesh_error(path, "no triangles in a physical surface"));
    }
    let coords: Vec<[f64; 2]> = nodes.iter().map(|p| [p[0], p[1]]).collect();
    let mut mesh = Mesh::new(coords, triangles, bodies, index_base)?;
    mesh.set_boundary_edges(&edges, &edge_tags)?;
    Ok(mesh)
}
