//! Gmsh meshes (MSH 4.1, ASCII or binary). Feature `gmsh`.
//!
//! [`read_msh`] reads 2D meshes, [`read_solid_msh`] tetrahedral ones
//! ([below](#three-dimensions)); both through the one reader of the file.
//!
//! In 2D, physical surfaces become bodies (the physical tag is the body tag) and
//! physical curves become boundary-edge tags, for loads, supports and
//! contact interfaces. A curve in several physical groups has its edges
//! under every one of their tags (a side in its own group 13 and in a
//! whole-boundary group 99 is loaded through 13 and fixed through 99). A
//! surface in several takes the first as its body (a triangle has one),
//! and physical points are not used (the model has no node groups): both
//! with a warning of the mesh naming the entities and groups (five entities
//! and ten groups of each at most, then how many more). A surface meshed clockwise (normal along −z) is
//! turned counter-clockwise as a whole. Only 3-node triangles and 2-node lines are accepted;
//! nodes must lie in the plane z = 0.
//!
//! # Three dimensions
//!
//! [`read_solid_msh`] takes the 4-node tetrahedra of the physical volumes
//! as the bodies (the physical tag is the body tag) and the 3-node
//! triangles of the physical surfaces as tagged boundary faces, a
//! triangle in several physical surfaces under every one of their tags,
//! as the 2D reader does with the lines of curves. As in 2D, a volume in no
//! physical group is refused (every volume must be a body), and the
//! triangles of surfaces in none carry nothing; unlike in 2D, a volume in
//! several physical groups is refused too: a [`SolidMesh`] holds no
//! warning of the reader's, and taking the first group without a word
//! could give a volume the wrong material. Lines and points, physical or
//! not, are not used (nothing of a solid mesh refers to them); elements of
//! higher order (10-node tetrahedra, 6-node triangles, 3-node lines) are
//! refused. Nodes are anywhere in space: the 2D reader's check of z = 0 is
//! not made. A tagged triangle must be the face of exactly one tetrahedron
//! (a side of the bodies, not an interface inside a body's mesh): the
//! mesh's check, its refusal naming the Gmsh element. A 2D file read as a
//! solid mesh is refused: it has no tetrahedra in a physical volume.
//!
//! # What is refused, and how it is said
//!
//! Content we cannot use is [`Status::InvalidMesh`] (the status
//! `tfem_load_gmsh` promises for unsupported content), a file that is not
//! well-formed MSH 4.1 [`Status::Io`]. Another version of the format (MSH
//! 2.2, 4.0, …) is unsupported content: the message names the version and
//! how to convert the file (`gmsh old.msh -save -format msh41 -o new.msh`,
//! or `Mesh.MshFileVersion = 4.1` in Gmsh). An error about an element or
//! a node names where the file puts it, its entity and physical group, by
//! tag and by the name `$PhysicalNames` gives it (`surface 1 in physical
//! group 7 "plate" has elements of Gmsh type 3 (4-node quadrangles)`,
//! `triangle 0 (Gmsh element 1 of surface 1 in physical group 7 "plate"):
//! node … is repeated`, `node 3 of surface 1 in physical group 7 "plate"
//! has z = 0.5`), as the file's user knows them.
//!
//! # The reader
//!
//! The file is read by a small reader of our own for the subset we use:
//! `$MeshFormat`, `$PhysicalNames` (for messages only), `$Entities`,
//! `$Nodes` and `$Elements`; any other section (`$Periodic`, `$NodeData`,
//! …) is skipped up to its `$End…` line. It replaced the `mshio` crate
//! (0.4.2), which cannot be made safe from outside:
//!
//! - it panics on malformed headers (`4.1 0 99999999999999999999`: an
//!   `unwrap` of the data size; `4.1 1 3`: `unimplemented!` for a 3-byte
//!   `size_t`), and on an empty `$Nodes` or `$Elements` section
//!   (`num_nodes - 1` underflows) when overflow checks are on; a panic
//!   prints on the caller's stderr through the default hook even when it
//!   is caught;
//! - its error message is a hex dump of the whole rest of the file from
//!   the error on (a 10 MB file gives a 47 MB message);
//! - skipping an unknown section is quadratic in a run of blanks (80 kB
//!   of spaces: 2 s);
//! - guarding its counts from outside would need a second parser anyway,
//!   to find the `$Nodes` header behind a binary `$Entities` section.
//!
//! (`mshio` itself never preallocated from a count: its repetitions go
//! through nom 5's `count`, which grows a `Vec` from empty, and its one
//! `Vec::with_capacity` is the node count of an element type. The abort
//! came from our own `Vec::with_capacity(num_nodes)`.)
//!
//! # Counts in the file
//!
//! No allocation is ever sized by a count read from the file: every list
//! grows by one item per item actually parsed. Each count is moreover
//! checked, before the items it counts are read, against what the rest of
//! the file can hold (`Reader::count`: in ASCII every value takes at
//! least a character and a separator, in binary its exact size), and a
//! count the file cannot hold is a [`Status::Io`] error naming the
//! section and the count:
//!
//! | count | at least, per item (ASCII values / binary bytes) |
//! |---|---|
//! | `$PhysicalNames` numPhysicalNames | 3 / — (ASCII in a binary file too) |
//! | `$Entities` numPoints | 5 / 4 + 3·8 + s |
//! | `$Entities` numCurves, numSurfaces, numVolumes | 9 / 4 + 6·8 + 2s |
//! | `$Entities` numPhysicalTags, numBounding… | 1 / 4 |
//! | `$Nodes` numEntityBlocks | 4 / 3·4 + s |
//! | `$Nodes` numNodes | 4 / s + 3·8 |
//! | `$Nodes` numNodesInBlock | 4 + p / s + (3 + p)·8 (p parametric coordinates) |
//! | `$Elements` numEntityBlocks | 4 / 3·4 + s |
//! | `$Elements` numElements | 2 / 2s |
//! | `$Elements` numElementsInBlock | 1 + k / (1 + k)·s (k nodes per element) |
//!
//! (s is the size of `size_t` given in the header, 4 or 8.) The tags are
//! never used as indices: `minNodeTag`/`maxNodeTag` and
//! `minElementTag`/`maxElementTag` only have to match the tags in the
//! file, and node tags are looked up in a hash map, so a tag of 2^62 costs
//! nothing. After a section, its header's total count and tag range must
//! match what the blocks held.
//!
//! The reader does not panic on any input: every read is bounds-checked,
//! every number is parsed with overflow checks, and every loop consumes at
//! least one value per turn. Work and memory are linear in the file size.

use std::collections::HashMap;
use std::fmt::Display;
use std::io::Read;
use std::path::Path;

use crate::error::{Error, Result, Status};
use crate::fem::mesh::{Mesh, Names, Places};
use crate::fem::solid_mesh::SolidMesh;

/// A failure while reading: the status and the message, without the path
/// or the section (added by [`read_msh`]).
struct Fail {
    status: Status,
    message: String,
}

impl Fail {
    /// Content we cannot use ([`Status::InvalidMesh`]).
    fn mesh(message: impl Into<String>) -> Self {
        Fail {
            status: Status::InvalidMesh,
            message: message.into(),
        }
    }

    /// Prefixes the message with where it happened.
    fn within(self, context: impl Display) -> Self {
        Fail {
            message: format!("{context}: {}", self.message),
            ..self
        }
    }
}

/// A malformed file ([`Status::Io`]).
impl From<String> for Fail {
    fn from(message: String) -> Self {
        Fail {
            status: Status::Io,
            message,
        }
    }
}

type Parse<T> = std::result::Result<T, Fail>;

#[derive(Clone, Copy, PartialEq)]
enum Encoding {
    Ascii,
    Binary { size_t: usize, big_endian: bool },
}

/// What one item of a counted list takes at least in the file.
#[derive(Clone, Copy)]
struct Cost {
    ints: u64,
    sizes: u64,
    floats: u64,
}

const fn cost(ints: u64, sizes: u64, floats: u64) -> Cost {
    Cost {
        ints,
        sizes,
        floats,
    }
}

fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b'\x0b' | b'\x0c')
}

/// File text for a message: quoted, printable and bounded, whatever the
/// bytes. Messages reach C callers as NUL-terminated strings and users'
/// terminals: a NUL would cut the message, raw binary garble the screen,
/// a long token make it megabytes long. At most 24 bytes are shown, each
/// control character escaped (`\0`, `\u{1b}`), invalid UTF-8 as U+FFFD,
/// and the quoted text stops at 48 characters.
fn show(token: &[u8]) -> String {
    quote(token, 24, 48)
}

/// [`show`] with its bounds: at most `bytes` of `token`, and at most
/// `chars` characters of their escapes.
fn quote(token: &[u8], bytes: usize, chars: usize) -> String {
    let cut = &token[..token.len().min(bytes)];
    let mut out = String::from("\"");
    let mut shown = 0;
    let mut short = cut.len() < token.len();
    // Cut between the escapes of whole characters, never inside one.
    for c in String::from_utf8_lossy(cut).chars() {
        let escaped: String = match c {
            '\'' => "'".to_string(),
            c => c.escape_debug().collect(),
        };
        shown += escaped.chars().count();
        if shown > chars {
            short = true;
            break;
        }
        out.push_str(&escaped);
    }
    out.push('"');
    if short {
        out.push('…');
    }
    out
}

/// A cursor over the bytes of the file.
struct Reader<'a> {
    bytes: &'a [u8],
    pos: usize,
    encoding: Encoding,
}

impl<'a> Reader<'a> {
    fn left(&self) -> usize {
        self.bytes.len() - self.pos
    }

    fn skip_blanks(&mut self) {
        while self.pos < self.bytes.len() && is_blank(self.bytes[self.pos]) {
            self.pos += 1;
        }
    }

    /// The next blank-separated token, if any.
    fn token(&mut self) -> Option<&'a [u8]> {
        self.skip_blanks();
        let start = self.pos;
        while self.pos < self.bytes.len() && !is_blank(self.bytes[self.pos]) {
            self.pos += 1;
        }
        (self.pos > start).then(|| &self.bytes[start..self.pos])
    }

    fn text(&mut self, what: &str) -> Parse<&'a [u8]> {
        self.token()
            .ok_or_else(|| format!("the file ends where {what} was expected").into())
    }

    fn raw<const N: usize>(&mut self, what: &str) -> Parse<[u8; N]> {
        let end = self.pos.saturating_add(N);
        let Some(b) = self.bytes.get(self.pos..end) else {
            return Err(format!("the file ends where {what} was expected").into());
        };
        self.pos = end;
        let mut out = [0; N];
        out.copy_from_slice(b);
        Ok(out)
    }

    /// One line break (`\n` or `\r\n`), exactly: binary data follows.
    fn line_break(&mut self, after: &str) -> Parse<()> {
        let rest = &self.bytes[self.pos..];
        if rest.starts_with(b"\r\n") {
            self.pos += 2;
        } else if rest.starts_with(b"\n") {
            self.pos += 1;
        } else {
            return Err(format!("expected a line break after {after}").into());
        }
        Ok(())
    }

    /// A `size_t`.
    fn size(&mut self, what: &str) -> Parse<u64> {
        match self.encoding {
            Encoding::Ascii => {
                let t = self.text(what)?;
                std::str::from_utf8(t)
                    .ok()
                    .filter(|s| s.bytes().all(|b| b.is_ascii_digit()))
                    .and_then(|s| s.parse::<u64>().ok())
                    .ok_or_else(|| {
                        format!(
                            "{what} must be an integer from 0 to {}, found {}",
                            u64::MAX,
                            show(t)
                        )
                        .into()
                    })
            }
            Encoding::Binary {
                size_t: 4,
                big_endian,
            } => {
                let b = self.raw::<4>(what)?;
                Ok(u64::from(if big_endian {
                    u32::from_be_bytes(b)
                } else {
                    u32::from_le_bytes(b)
                }))
            }
            Encoding::Binary { big_endian, .. } => {
                let b = self.raw::<8>(what)?;
                Ok(if big_endian {
                    u64::from_be_bytes(b)
                } else {
                    u64::from_le_bytes(b)
                })
            }
        }
    }

    /// An `int`.
    fn int(&mut self, what: &str) -> Parse<i32> {
        match self.encoding {
            Encoding::Ascii => {
                let t = self.text(what)?;
                std::str::from_utf8(t)
                    .ok()
                    .and_then(|s| s.parse::<i32>().ok())
                    .ok_or_else(|| {
                        format!(
                            "{what} must be an integer from {} to {}, found {}",
                            i32::MIN,
                            i32::MAX,
                            show(t)
                        )
                        .into()
                    })
            }
            Encoding::Binary { big_endian, .. } => {
                let b = self.raw::<4>(what)?;
                Ok(if big_endian {
                    i32::from_be_bytes(b)
                } else {
                    i32::from_le_bytes(b)
                })
            }
        }
    }

    /// A `double`.
    fn float(&mut self, what: &str) -> Parse<f64> {
        match self.encoding {
            Encoding::Ascii => {
                let t = self.text(what)?;
                std::str::from_utf8(t)
                    .ok()
                    .and_then(|s| s.parse::<f64>().ok())
                    .ok_or_else(|| format!("{what} must be a number, found {}", show(t)).into())
            }
            Encoding::Binary { big_endian, .. } => {
                let b = self.raw::<8>(what)?;
                Ok(if big_endian {
                    f64::from_be_bytes(b)
                } else {
                    f64::from_le_bytes(b)
                })
            }
        }
    }

    /// How many items of `cost` the rest of the file can hold at most.
    fn room_for(&self, cost: Cost) -> u64 {
        let left = self.left() as u64;
        match self.encoding {
            // Every value takes a character, and all but the last of the
            // file a separator.
            Encoding::Ascii => (left + 1) / (2 * (cost.ints + cost.sizes + cost.floats)),
            Encoding::Binary { size_t, .. } => {
                left / (4 * cost.ints + size_t as u64 * cost.sizes + 8 * cost.floats)
            }
        }
    }

    /// A count of items of `cost`, refused (before anything is read or
    /// allocated for them) if the rest of the file cannot hold that many.
    fn count(&mut self, what: &str, cost: Cost) -> Parse<usize> {
        let n = self.size(what)?;
        let room = self.room_for(cost);
        if n > room {
            return Err(format!(
                "{what} is {n}, but the {} bytes left in the file can hold at most {room}",
                self.left()
            )
            .into());
        }
        // n ≤ room ≤ the length of the file in memory.
        Ok(n as usize)
    }

    /// The line break after a section's start tag, before binary data.
    fn begin_data(&mut self, section: &str) -> Parse<()> {
        match self.encoding {
            Encoding::Ascii => Ok(()),
            Encoding::Binary { .. } => self.line_break(section),
        }
    }

    /// The end tag of a section.
    fn end(&mut self, tag: &str, after: &str) -> Parse<()> {
        match self.token() {
            Some(t) if t == tag.as_bytes() => Ok(()),
            Some(t) => Err(format!("expected {tag} after {after}, found {}", show(t)).into()),
            None => Err(format!("the file ends before {tag}").into()),
        }
    }

    /// Skips an unknown section `$name` up to its `$Endname` token.
    fn skip_section(&mut self, name: &[u8]) -> Parse<()> {
        if name.is_empty() || name.len() > 64 {
            return Err(format!("{} is not a section name", show(name)).into());
        }
        let mut end = b"$End".to_vec();
        end.extend_from_slice(name);
        let mut from = self.pos;
        while let Some(k) = self.bytes[from..].iter().position(|&b| b == b'$') {
            let at = from + k;
            let after = at + end.len();
            if self.bytes[at..].starts_with(&end)
                && at > 0
                && is_blank(self.bytes[at - 1])
                && self.bytes.get(after).is_none_or(|&b| is_blank(b))
            {
                self.pos = after;
                return Ok(());
            }
            from = at + 1;
        }
        Err(format!("the file ends before {}", show(&end)).into())
    }
}

/// The `$MeshFormat` section: the encoding of the rest of the file.
fn header(r: &mut Reader) -> Parse<Encoding> {
    match r.token() {
        Some(b"$MeshFormat") => {}
        _ => {
            return Err(
                "the file does not start with $MeshFormat: not a Gmsh MSH file"
                    .to_string()
                    .into(),
            );
        }
    }
    let version = r.text("the format version")?;
    match std::str::from_utf8(version)
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
    {
        Some(4.1) => {}
        // Another version of the format: well-formed content we cannot use.
        Some(v) if v.is_finite() && v > 0.0 => {
            // It parsed as a number: ASCII, and short enough to quote
            // as it is unless padded.
            let shown = if version.len() <= 16 {
                String::from_utf8_lossy(version).into_owned()
            } else {
                show(version)
            };
            return Err(Fail::mesh(format!(
                "MSH {shown} is not supported: tfem reads MSH 4.1 only. Convert the file with \
                 `gmsh old.msh -save -format msh41 -o new.msh`, or have Gmsh write 4.1 \
                 (Mesh.MshFileVersion = 4.1; the default since Gmsh 4.1)"
            )));
        }
        _ => {
            return Err(format!(
                "the format version must be a number such as 4.1, found {}",
                show(version)
            )
            .into());
        }
    }
    let binary = match r.text("the file type")? {
        b"0" => false,
        b"1" => true,
        t => {
            return Err(format!(
                "the file type must be 0 (ASCII) or 1 (binary), found {}",
                show(t)
            )
            .into());
        }
    };
    let size_t = match r.text("the data size")? {
        b"8" => 8,
        b"4" => 4,
        t => {
            return Err(format!(
                "the data size (of size_t) must be 4 or 8, found {}",
                show(t)
            )
            .into());
        }
    };
    let encoding = if binary {
        while r.bytes.get(r.pos).is_some_and(|&b| b == b' ' || b == b'\t') {
            r.pos += 1;
        }
        r.line_break("the data size")?;
        let one = r.raw::<4>("the binary mark (the integer 1)")?;
        let big_endian = match (i32::from_le_bytes(one), i32::from_be_bytes(one)) {
            (1, _) => false,
            (_, 1) => true,
            _ => return Err("the binary mark is not the integer 1".to_string().into()),
        };
        Encoding::Binary { size_t, big_endian }
    } else {
        Encoding::Ascii
    };
    r.end("$EndMeshFormat", "the header")?;
    Ok(encoding)
}

/// Of `$Entities`: the physical tags of each curve, surface and volume,
/// and the points that have some.
#[derive(Debug, Default)]
struct Entities {
    curves: HashMap<i32, Vec<i32>>,
    surfaces: HashMap<i32, Vec<i32>>,
    volumes: HashMap<i32, Vec<i32>>,
    points: Vec<(i32, Vec<i32>)>,
}

/// Of `$PhysicalNames`: the name of each physical group by (dimension,
/// tag), quoted and bounded for messages.
type GroupNames = HashMap<(i32, i32), String>;

/// The `$PhysicalNames` section, ASCII in every file (binary ones too):
/// `numPhysicalNames`, then `dimension physicalTag "name"` per group. A
/// group named twice keeps its first name.
fn physical_names(r: &mut Reader) -> Parse<GroupNames> {
    let encoding = std::mem::replace(&mut r.encoding, Encoding::Ascii);
    let names = physical_names_ascii(r);
    r.encoding = encoding;
    names
}

fn physical_names_ascii(r: &mut Reader) -> Parse<GroupNames> {
    // Every name takes two integers and its quotes at least.
    const NAME: Cost = cost(3, 0, 0);
    let n = r.count("the number of physical names", NAME)?;
    let mut out = GroupNames::new();
    for k in 0..n {
        let within = |f: Fail| f.within(format!("physical name {} of {n}", k + 1));
        let dim = r.int("the dimension").map_err(within)?;
        let tag = r.int("the physical tag").map_err(within)?;
        let name = quoted_name(r).map_err(within)?;
        out.entry((dim, tag)).or_insert_with(|| quote(name, 64, 64));
    }
    Ok(out)
}

/// A name in double quotes on the current line.
fn quoted_name<'a>(r: &mut Reader<'a>) -> Parse<&'a [u8]> {
    while r.bytes.get(r.pos).is_some_and(|&b| b == b' ' || b == b'\t') {
        r.pos += 1;
    }
    if r.bytes.get(r.pos) != Some(&b'"') {
        let found = r
            .token()
            .map_or_else(|| "the end of the file".to_string(), show);
        return Err(format!("expected a name in double quotes, found {found}").into());
    }
    let start = r.pos + 1;
    match r.bytes[start..]
        .iter()
        .position(|&b| b == b'"' || b == b'\n')
    {
        Some(k) if r.bytes[start + k] == b'"' => {
            r.pos = start + k + 1;
            Ok(&r.bytes[start..start + k])
        }
        _ => Err(format!(
            "the name {} has no closing quote on its line",
            show(&r.bytes[r.pos..])
        )
        .into()),
    }
}

/// Names physical groups and the entities in them for messages, from what
/// the file has given so far (`$Entities` and `$PhysicalNames` come before
/// `$Nodes` and `$Elements` in the files Gmsh writes).
#[derive(Clone, Copy, Debug)]
struct Groups<'a> {
    entities: Option<&'a Entities>,
    names: &'a GroupNames,
}

/// What an entity of dimension `dim` is called.
fn entity_kind(dim: i32) -> &'static str {
    match dim {
        0 => "point",
        1 => "curve",
        2 => "surface",
        _ => "volume",
    }
}

impl<'a> Groups<'a> {
    /// The physical groups of an entity.
    fn of(&self, dim: i32, entity: i32) -> &'a [i32] {
        let Some(e) = self.entities else { return &[] };
        let found = match dim {
            0 => e.points.iter().find(|p| p.0 == entity).map(|p| &p.1),
            1 => e.curves.get(&entity),
            2 => e.surfaces.get(&entity),
            _ => e.volumes.get(&entity),
        };
        found.map_or(&[], Vec::as_slice)
    }

    /// Group `tag` of dimension `dim`: `7 "plate"`, or `7` unnamed.
    fn group(&self, dim: i32, tag: i32) -> String {
        match self.names.get(&(dim, tag)) {
            Some(name) => format!("{tag} {name}"),
            None => tag.to_string(),
        }
    }

    /// An entity and its physical groups: `surface 1 in physical group 7
    /// "plate"`, `curve 3 in physical groups 11 "bottom", 99` (ten at most,
    /// then how many more), or `curve 4` in none.
    fn place(&self, dim: i32, entity: i32) -> String {
        const SHOWN: usize = 10;
        let groups = self.of(dim, entity);
        let kind = entity_kind(dim);
        let mut out = match groups.len() {
            0 => return format!("{kind} {entity}"),
            1 => format!("{kind} {entity} in physical group "),
            _ => format!("{kind} {entity} in physical groups "),
        };
        let shown: Vec<String> = groups
            .iter()
            .take(SHOWN)
            .map(|&g| self.group(dim, g))
            .collect();
        out.push_str(&shown.join(", "));
        if groups.len() > SHOWN {
            out.push_str(&format!(" and {} more", groups.len() - SHOWN));
        }
        out
    }

    /// An entity in its one physical group `tag` (a triangle's body, an
    /// edge's tag): `surface 1 in physical group 7 "plate"`.
    fn place_in(&self, dim: i32, entity: i32, tag: i32) -> String {
        format!(
            "{} {entity} in physical group {}",
            entity_kind(dim),
            self.group(dim, tag)
        )
    }
}

fn entities(r: &mut Reader) -> Parse<Entities> {
    const POINT: Cost = cost(1, 1, 3);
    const BOUNDED: Cost = cost(1, 2, 6);
    let counts = [
        r.count("the number of points", POINT)?,
        r.count("the number of curves", BOUNDED)?,
        r.count("the number of surfaces", BOUNDED)?,
        r.count("the number of volumes", BOUNDED)?,
    ];
    let mut out = Entities::default();
    for (dim, (&n, name)) in counts
        .iter()
        .zip(["point", "curve", "surface", "volume"])
        .enumerate()
    {
        for k in 0..n {
            let (tag, physical) =
                entity(r, dim).map_err(|f| f.within(format!("{name} {} of {n}", k + 1)))?;
            match dim {
                0 if !physical.is_empty() => out.points.push((tag, physical)),
                1 => {
                    out.curves.insert(tag, physical);
                }
                2 => {
                    out.surfaces.insert(tag, physical);
                }
                3 => {
                    out.volumes.insert(tag, physical);
                }
                _ => {}
            }
        }
    }
    Ok(out)
}

/// One entity of dimension `dim`: its tag and physical tags (each once:
/// an edge given a tag twice would carry its loads twice).
fn entity(r: &mut Reader, dim: usize) -> Parse<(i32, Vec<i32>)> {
    const TAG: Cost = cost(1, 0, 0);
    let tag = r.int("the entity tag")?;
    // A point has its coordinates, the others their bounding box.
    for _ in 0..if dim == 0 { 3 } else { 6 } {
        r.float("a coordinate")?;
    }
    let n = r.count("the number of physical tags", TAG)?;
    let mut physical = Vec::new();
    for _ in 0..n {
        let p = r.int("a physical tag")?;
        if !physical.contains(&p) {
            physical.push(p);
        }
    }
    if dim > 0 {
        let n = r.count("the number of bounding entities", TAG)?;
        for _ in 0..n {
            r.int("a bounding entity tag")?;
        }
    }
    Ok((tag, physical))
}

/// Of `$Nodes`: coordinates, tags, the index of each tag, and the entity
/// of each block.
#[derive(Default)]
struct Nodes {
    xyz: Vec<[f64; 3]>,
    tags: Vec<u64>,
    index_of: HashMap<u64, usize>,
    /// (first node, entity dimension, entity tag) of each block, in order.
    blocks: Vec<(usize, i32, i32)>,
}

/// The block of item `i` among blocks given by their first items, in
/// order (an empty block shares its first item with the next one).
fn block_of<T>(blocks: &[T], first: impl Fn(&T) -> usize, i: usize) -> Option<&T> {
    let k = blocks.partition_point(|b| first(b) <= i);
    k.checked_sub(1).map(|k| &blocks[k])
}

/// What a section's header announces of the items in its blocks, read
/// before the blocks and checked against them after
/// ([`check_header`]).
#[derive(Clone, Copy)]
struct Announced {
    /// How many items the blocks hold.
    count: usize,
    /// The smallest tag among them.
    min: u64,
    /// The largest tag among them.
    max: u64,
}

/// A section's header against what its blocks held: `found` items, their
/// tags running over `range` (smallest, largest: a genuine pair, as
/// [`tag_range`] gives it).
fn check_header(what: &str, claimed: Announced, found: usize, range: (u64, u64)) -> Parse<()> {
    let Announced { count: n, min, max } = claimed;
    if found != n {
        return Err(format!("the header announces {n} {what}s but the blocks hold {found}").into());
    }
    if n > 0 && range != (min, max) {
        return Err(format!(
            "the header gives {what} tags from {min} to {max}, but the tags in the file run from {} to {}",
            range.0, range.1
        )
        .into());
    }
    Ok(())
}

/// The smallest and largest of `tags`.
fn tag_range(tags: impl Iterator<Item = u64>) -> (u64, u64) {
    tags.fold((u64::MAX, 0), |(lo, hi), t| (lo.min(t), hi.max(t)))
}

fn nodes(r: &mut Reader) -> Parse<Nodes> {
    const BLOCK: Cost = cost(3, 1, 0);
    const NODE: Cost = cost(0, 1, 3);
    let n_blocks = r.count("the number of entity blocks", BLOCK)?;
    let claimed = Announced {
        count: r.count("the number of nodes", NODE)?,
        min: r.size("the minimum node tag")?,
        max: r.size("the maximum node tag")?,
    };
    let mut out = Nodes::default();
    for b in 0..n_blocks {
        node_block(r, &mut out)
            .map_err(|f| f.within(format!("entity block {} of {n_blocks}", b + 1)))?;
    }
    check_header(
        "node",
        claimed,
        out.xyz.len(),
        tag_range(out.tags.iter().copied()),
    )?;
    Ok(out)
}

fn node_block(r: &mut Reader, out: &mut Nodes) -> Parse<()> {
    let dim = r.int("the entity dimension")?;
    if !(0..=3).contains(&dim) {
        return Err(format!("the entity dimension must be 0 to 3, found {dim}").into());
    }
    let entity = r.int("the entity tag")?;
    out.blocks.push((out.xyz.len(), dim, entity));
    // Parametric nodes carry `dim` parametric coordinates after x y z.
    let params = match r.int("the parametric flag")? {
        0 => 0,
        1 => dim as u64,
        p => return Err(format!("the parametric flag must be 0 or 1, found {p}").into()),
    };
    let n = r.count("the number of nodes in the block", cost(0, 1, 3 + params))?;
    let first = out.xyz.len();
    for k in 0..n {
        let tag = r.size("a node tag")?;
        if tag == 0 {
            return Err("node tag 0 is reserved".to_string().into());
        }
        if out.index_of.insert(tag, first + k).is_some() {
            return Err(format!("node {tag} is defined twice").into());
        }
        out.tags.push(tag);
    }
    for k in 0..n {
        let mut p = [0.0; 3];
        for (c, name) in p.iter_mut().zip(["x", "y", "z"]) {
            *c = r
                .float(name)
                .map_err(|f| f.within(format!("node {}", out.tags[first + k])))?;
        }
        for _ in 0..params {
            r.float("a parametric coordinate")?;
        }
        out.xyz.push(p);
    }
    Ok(())
}

/// Of `$Elements`: a block of triangles (dimension 2) or lines
/// (dimension 1) as node tags, `nodes_per` per element.
struct Block {
    dim: i32,
    entity: i32,
    nodes_per: usize,
    /// The element tags, for messages.
    tags: Vec<u64>,
    node_tags: Vec<u64>,
}

/// A Gmsh element type for a message.
fn type_name(ty: i32) -> String {
    let name = match ty {
        1 => "2-node lines",
        2 => "3-node triangles",
        3 => "4-node quadrangles",
        4 => "4-node tetrahedra",
        5 => "8-node hexahedra",
        6 => "6-node prisms",
        7 => "5-node pyramids",
        8 => "3-node lines",
        9 => "6-node triangles",
        10 => "9-node quadrangles",
        11 => "10-node tetrahedra",
        15 => "1-node points",
        16 => "8-node quadrangles",
        20 => "9-node triangles",
        21 => "10-node triangles",
        26 => "4-node lines",
        _ => return format!("Gmsh type {ty}"),
    };
    format!("Gmsh type {ty} ({name})")
}

/// Which mesh the file is read for: what elements it may hold.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Dims {
    /// A 2D mesh ([`read_msh`]): triangles and lines, no volume elements.
    Plane,
    /// A 3D mesh ([`read_solid_msh`]): tetrahedra, triangles and lines.
    Solid,
}

fn elements(r: &mut Reader, groups: Groups, dims: Dims) -> Parse<Vec<Block>> {
    const BLOCK: Cost = cost(3, 1, 0);
    // The smallest element: a point, its tag and one node.
    const ELEMENT: Cost = cost(0, 2, 0);
    let n_blocks = r.count("the number of entity blocks", BLOCK)?;
    let claimed = Announced {
        count: r.count("the number of elements", ELEMENT)?,
        min: r.size("the minimum element tag")?,
        max: r.size("the maximum element tag")?,
    };
    let mut blocks = Vec::new();
    let (mut found, mut range) = (0, (u64::MAX, 0));
    for b in 0..n_blocks {
        let block = element_block(r, groups, dims, &mut found, &mut range)
            .map_err(|f| f.within(format!("entity block {} of {n_blocks}", b + 1)))?;
        // Points carry nothing we use.
        if block.dim > 0 {
            blocks.push(block);
        }
    }
    check_header("element", claimed, found, range)?;
    Ok(blocks)
}

/// One block; counts its elements in `found` and widens `range` (smallest,
/// largest: a genuine pair) to their tags. An element type we cannot use
/// is refused naming the entity and its physical groups.
fn element_block(
    r: &mut Reader,
    groups: Groups,
    dims: Dims,
    found: &mut usize,
    range: &mut (u64, u64),
) -> Parse<Block> {
    let dim = r.int("the entity dimension")?;
    let entity = r.int("the entity tag")?;
    let ty = r.int("the element type")?;
    let place = || groups.place(dim, entity);
    let nodes_per = match (dim, ty) {
        (3, 4) if dims == Dims::Solid => 4,
        (3, _) if dims == Dims::Solid => {
            return Err(Fail::mesh(format!(
                "{} has elements of {}: only 4-node tetrahedra are supported",
                place(),
                type_name(ty)
            )));
        }
        (2, 2) => 3,
        (1, 1) => 2,
        (0, 15) => 1,
        (2, _) => {
            return Err(Fail::mesh(format!(
                "{} has elements of {}: only 3-node triangles are supported",
                place(),
                type_name(ty)
            )));
        }
        (1, _) => {
            return Err(Fail::mesh(format!(
                "{} has elements of {}: only 2-node lines are supported",
                place(),
                type_name(ty)
            )));
        }
        (0, _) => {
            return Err(Fail::mesh(format!(
                "{} has elements of {}: only 1-node points are supported there",
                place(),
                type_name(ty)
            )));
        }
        (3, _) => {
            return Err(Fail::mesh(format!(
                "{} has elements of {}: only 2D meshes are supported",
                place(),
                type_name(ty)
            )));
        }
        (d, _) => return Err(format!("the entity dimension must be 0 to 3, found {d}").into()),
    };
    let n = r.count(
        "the number of elements in the block",
        cost(0, 1 + nodes_per as u64, 0),
    )?;
    let (mut tags, mut node_tags) = (Vec::new(), Vec::new());
    for _ in 0..n {
        let tag = r.size("an element tag")?;
        tags.push(tag);
        *range = (range.0.min(tag), range.1.max(tag));
        for _ in 0..nodes_per {
            node_tags.push(
                r.size("a node tag")
                    .map_err(|f| f.within(format!("element {tag}")))?,
            );
        }
    }
    *found += n;
    Ok(Block {
        dim,
        entity,
        nodes_per,
        tags,
        node_tags,
    })
}

/// What the file holds, section by section.
struct MshFile {
    names: Option<GroupNames>,
    entities: Option<Entities>,
    nodes: Option<Nodes>,
    elements: Option<Vec<Block>>,
}

/// A failure within a section.
fn in_section<T>(section: &str, result: Parse<T>) -> Parse<T> {
    result.map_err(|f| f.within(section))
}

fn parse(bytes: &[u8], dims: Dims) -> Parse<MshFile> {
    let mut r = Reader {
        bytes,
        pos: 0,
        encoding: Encoding::Ascii,
    };
    r.encoding = in_section("$MeshFormat", header(&mut r))?;
    let mut file = MshFile {
        names: None,
        entities: None,
        nodes: None,
        elements: None,
    };
    // The last section read, for messages.
    let mut last = "$MeshFormat".to_string();
    while let Some(tag) = r.token() {
        let section = match tag {
            b"$PhysicalNames" => "$PhysicalNames",
            b"$Entities" => "$Entities",
            b"$Nodes" => "$Nodes",
            b"$Elements" => "$Elements",
            t if t.len() > 1 && t.starts_with(b"$") && !t.starts_with(b"$End") => {
                // The name is file text, maybe binary and of any length.
                let name = show(t);
                let context = format!("{name} (a section after {last}, skipped)");
                in_section(&context, r.skip_section(&t[1..]))?;
                last = name;
                continue;
            }
            t => {
                return Err(Fail::from(format!(
                    "after {last}: expected a section such as $Nodes, found {}",
                    show(t)
                )));
            }
        };
        let present = match section {
            "$PhysicalNames" => file.names.is_some(),
            "$Entities" => file.entities.is_some(),
            "$Nodes" => file.nodes.is_some(),
            _ => file.elements.is_some(),
        };
        if present {
            return Err(Fail::from(format!(
                "{section}: a second {section} section: only one is supported"
            )));
        }
        // Its data is ASCII in every file.
        if section != "$PhysicalNames" {
            in_section(section, r.begin_data(section))?;
        }
        let no_names = GroupNames::new();
        let groups = Groups {
            entities: file.entities.as_ref(),
            names: file.names.as_ref().unwrap_or(&no_names),
        };
        match section {
            "$PhysicalNames" => {
                file.names = Some(in_section(section, physical_names(&mut r))?);
            }
            "$Entities" => file.entities = Some(in_section(section, entities(&mut r))?),
            "$Nodes" => file.nodes = Some(in_section(section, nodes(&mut r))?),
            _ => file.elements = Some(in_section(section, elements(&mut r, groups, dims))?),
        }
        let end = format!("$End{}", &section[1..]);
        in_section(section, r.end(&end, "the data the header announces"))?;
        last = section.to_string();
    }
    Ok(file)
}

/// Why a file system object that is not a regular file is refused, for a
/// message.
fn not_regular(t: std::fs::FileType) -> std::io::Error {
    std::io::Error::other(format!("not a regular file but {}", kind(t)))
}

/// What a file system object that is not a regular file is.
fn kind(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (a named pipe)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "a special file"
    }
}

/// The whole file, refusing what is not a regular file (a device or a
/// pipe could be endless) and a file too large for memory.
///
/// The path is looked up (`metadata`) before it is opened: opening a FIFO
/// for reading blocks until a writer comes, so a check after `open` would
/// never be reached. On Unix the file is moreover opened with
/// `O_NONBLOCK`, so that a FIFO put in its place between the look-up and
/// the open cannot block either (the open returns at once, and the check
/// of the opened file refuses it); on a regular file the flag changes
/// nothing.
fn read_file(path: &Path) -> std::io::Result<Vec<u8>> {
    let meta = std::fs::metadata(path)?;
    if !meta.is_file() {
        return Err(not_regular(meta.file_type()));
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(not_regular(meta.file_type()));
    }
    let len = usize::try_from(meta.len()).map_err(std::io::Error::other)?;
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(len)
        .map_err(|_| std::io::Error::other(format!("{len} bytes do not fit in memory")))?;
    // A file growing meanwhile is read as it was when opened.
    file.take(len as u64).read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// Reads a Gmsh MSH 4.1 file into a validated [`Mesh`] with its tagged
/// boundary edges. `index_base` only affects how messages number items.
///
/// Errors: [`Status::Io`] for a file that cannot be read or is not a
/// well-formed MSH 4.1 file (the message names the section and what is
/// wrong, e.g. a count the file cannot hold), [`Status::InvalidMesh`] for
/// well-formed content we cannot use: another version of the format (MSH
/// 2.2, with how to convert it), an element type, node or triangle we
/// cannot take (named with its entity and physical group).
pub fn read_msh(path: &Path, index_base: usize) -> Result<Mesh> {
    read_with(path, |bytes| build(bytes, index_base))
}

/// Reads a Gmsh MSH 4.1 file into a tetrahedral [`SolidMesh`] with its
/// tagged boundary faces: the tetrahedra of the physical volumes are the
/// bodies, the triangles of the physical surfaces the faces that loads,
/// supports and contact refer to ([module documentation](self#three-dimensions)).
/// `index_base` only affects how messages number items.
///
/// Errors as [`read_msh`]'s: [`Status::Io`] for a file that cannot be
/// read or is not well-formed MSH 4.1, [`Status::InvalidMesh`] for content
/// a tetrahedral mesh cannot take (no tetrahedra in a physical volume, as
/// in a 2D file; elements of higher order; a tagged triangle that is not
/// the face of exactly one tetrahedron), named by the file's element and
/// node tags and physical groups.
pub fn read_solid_msh(path: &Path, index_base: usize) -> Result<SolidMesh> {
    read_with(path, |bytes| build_solid(bytes, index_base))
}

/// What `build` makes of the file at `path`, its failures prefixed with
/// the path: a caller reading several files must know which one failed.
fn read_with<T>(path: &Path, build: impl FnOnce(&[u8]) -> Parse<T>) -> Result<T> {
    // The system's message for it would name nothing (": No such file or
    // directory").
    if path.as_os_str().is_empty() {
        return Err(Error::new(Status::Io, "the path is empty: no file to read"));
    }
    let bytes =
        read_file(path).map_err(|e| Error::new(Status::Io, format!("{}: {e}", path.display())))?;
    build(&bytes).map_err(|f| Error::new(f.status, format!("{}: {}", path.display(), f.message)))
}

/// Where the file puts each node, triangle and edge of the mesh built
/// from it, by the blocks they came in.
#[derive(Debug)]
struct FilePlaces<'a> {
    groups: Groups<'a>,
    /// (first node, entity dimension, entity tag) of each `$Nodes` block.
    nodes: &'a [(usize, i32, i32)],
    /// (first triangle, surface, body) of each block of triangles.
    triangles: &'a [(usize, i32, i32)],
    /// (first edge, curve) of each block of lines; an edge's physical
    /// group is its tag.
    edges: &'a [(usize, i32)],
    edge_tags: &'a [i32],
}

impl Places for FilePlaces<'_> {
    fn node(&self, i: usize) -> Option<String> {
        block_of(self.nodes, |b| b.0, i).map(|&(_, dim, entity)| self.groups.place(dim, entity))
    }

    fn triangle(&self, t: usize) -> Option<String> {
        block_of(self.triangles, |b| b.0, t)
            .map(|&(_, surface, body)| self.groups.place_in(2, surface, body))
    }

    fn edge(&self, e: usize) -> Option<String> {
        let &(_, curve) = block_of(self.edges, |b| b.0, e)?;
        Some(self.groups.place_in(1, curve, *self.edge_tags.get(e)?))
    }
}

/// The mesh of the file's bytes: its sections checked, its elements
/// taken as triangles and tagged edges, the mesh validated with messages
/// in the file's terms, and what the model cannot hold said in warnings.
fn build(bytes: &[u8], index_base: usize) -> Parse<Mesh> {
    let Sections {
        entities,
        nodes,
        blocks,
        names,
    } = parse(bytes, Dims::Plane)?.required()?;
    let groups = Groups {
        entities: Some(&entities),
        names: &names,
    };
    check_planar(&nodes, groups)?;
    let index = NodeIndex {
        nodes: &nodes,
        groups,
    };
    let (mut triangles, mut edges) = (Triangles::default(), Edges::default());
    for block in &blocks {
        if block.dim == 2 {
            triangles.add_block(block, &index)?;
        } else if let Some(physical) = entities.curves.get(&block.entity) {
            edges.add_block(block, physical, &index)?;
        }
    }
    if triangles.nodes.is_empty() {
        return Err(Fail::mesh("$Elements: no triangles in a physical surface"));
    }
    let mut mesh = validated_mesh(&nodes, triangles, &edges, groups, index_base)?;
    warn_surfaces_in_several_groups(&mut mesh, &blocks, groups);
    warn_physical_points(&mut mesh, &entities.points);
    Ok(mesh)
}

/// The sections a mesh is built from, all present.
struct Sections {
    entities: Entities,
    nodes: Nodes,
    blocks: Vec<Block>,
    /// Empty when the file names no group.
    names: GroupNames,
}

impl MshFile {
    /// The sections a mesh needs, a missing one refused by name:
    /// `$Entities` too, as bodies and tags are its physical groups.
    fn required(self) -> Parse<Sections> {
        let entities = self.entities.ok_or_else(|| {
            Fail::mesh("$Entities: no such section, and physical groups are needed")
        })?;
        let nodes = self
            .nodes
            .ok_or_else(|| Fail::mesh("$Nodes: no such section"))?;
        let blocks = self
            .elements
            .ok_or_else(|| Fail::mesh("$Elements: no such section"))?;
        Ok(Sections {
            entities,
            nodes,
            blocks,
            names: self.names.unwrap_or_default(),
        })
    }
}

/// Refuses a node off the plane z = 0 (a NaN z too), named by its tag and
/// entity: the model is 2D, and dropping z would solve another geometry
/// without a word.
fn check_planar(nodes: &Nodes, groups: Groups) -> Parse<()> {
    let scale = nodes
        .xyz
        .iter()
        .flat_map(|p| [p[0].abs(), p[1].abs()])
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let Some((k, p)) = nodes
        .xyz
        .iter()
        .enumerate()
        .find(|(_, p)| p[2].is_nan() || p[2].abs() > 1e-12 * scale)
    else {
        return Ok(());
    };
    // Where the node lies: its block's entity.
    let place =
        block_of(&nodes.blocks, |b| b.0, k).map(|&(_, dim, entity)| groups.place(dim, entity));
    let of = place.map_or_else(String::new, |p| format!(" of {p}"));
    Err(Fail::mesh(format!(
        "$Nodes: node {}{of} has z = {:?}: only 2D meshes in the plane z = 0 are supported",
        nodes.tags[k], p[2]
    )))
}

/// The nodes of the file's elements, looked up by tag: the file's tags
/// are not indices (node tag 1001 may be index 0).
struct NodeIndex<'a> {
    nodes: &'a Nodes,
    /// For naming the element of a tag `$Nodes` does not define.
    groups: Groups<'a>,
}

impl NodeIndex<'_> {
    /// The index of node `tag` of element `element` of `block`, or an
    /// error naming the element and its entity.
    fn of(&self, block: &Block, element: u64, tag: u64) -> Parse<usize> {
        self.nodes.index_of.get(&tag).copied().ok_or_else(|| {
            Fail::mesh(format!(
                "$Elements: element {element} of {} refers to node {tag}, which is not defined \
                 in $Nodes",
                self.groups.place(block.dim, block.entity)
            ))
        })
    }
}

/// The triangles of the physical surfaces as the mesh takes them, with
/// where each came from in the file, for messages.
#[derive(Default)]
struct Triangles {
    nodes: Vec<[usize; 3]>,
    bodies: Vec<i32>,
    /// The file's element tag of each triangle.
    elements: Vec<u64>,
    /// (first triangle, surface, body) of each block.
    blocks: Vec<(usize, i32, i32)>,
}

impl Triangles {
    /// Adds a block of triangles, of the body of its surface's first
    /// physical group (a surface in none is refused: every surface must be
    /// a body), the surface turned counter-clockwise as a whole.
    fn add_block(&mut self, block: &Block, index: &NodeIndex) -> Parse<()> {
        // A triangle has one body: the first group.
        let body = index.groups.of(2, block.entity).first().copied().ok_or_else(|| {
                Fail::mesh(format!(
                    "$Elements: surface {} has no physical group in $Entities: every surface must be a body",
                    block.entity
                ))
            })?;
        let first = self.nodes.len();
        self.blocks.push((first, block.entity, body));
        let mut area = 0.0;
        for (&element, e) in block
            .tags
            .iter()
            .zip(block.node_tags.chunks_exact(block.nodes_per))
        {
            let t = [
                index.of(block, element, e[0])?,
                index.of(block, element, e[1])?,
                index.of(block, element, e[2])?,
            ];
            let [a, b, c] = t.map(|v| index.nodes.xyz[v]);
            area += (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            self.nodes.push(t);
            self.bodies.push(body);
            self.elements.push(element);
        }
        // Gmsh orients a surface's triangles along its normal, which
        // may be −z: make the surface counter-clockwise as a whole
        // (individual inverted triangles, if any, stay inverted).
        if area < 0.0 {
            for t in &mut self.nodes[first..] {
                t.swap(1, 2);
            }
        }
        Ok(())
    }
}

/// The tagged boundary edges of the physical curves as the mesh takes
/// them, with where each came from in the file, for messages.
#[derive(Default)]
struct Edges {
    ends: Vec<[usize; 2]>,
    /// The tag of each edge: a physical group of its curve.
    tags: Vec<i32>,
    /// The file's element tag of each edge.
    elements: Vec<u64>,
    /// (first edge, curve) of each block.
    blocks: Vec<(usize, i32)>,
}

impl Edges {
    /// Adds a block of lines of a curve in the groups `physical`, each
    /// line once per group: a curve may be in its own group and in "the
    /// whole boundary" (the mesh holds an edge under several tags). Curves
    /// without a physical group carry no load or contact.
    fn add_block(&mut self, block: &Block, physical: &[i32], index: &NodeIndex) -> Parse<()> {
        self.blocks.push((self.ends.len(), block.entity));
        for (&element, e) in block
            .tags
            .iter()
            .zip(block.node_tags.chunks_exact(block.nodes_per))
        {
            let ends = [
                index.of(block, element, e[0])?,
                index.of(block, element, e[1])?,
            ];
            for &tag in physical {
                self.ends.push(ends);
                self.tags.push(tag);
                self.elements.push(element);
            }
        }
        Ok(())
    }
}

/// The mesh of the file's nodes, triangles and edges, validated with
/// messages that name nodes and elements as the file does: the user knows
/// them by their tags and physical groups, not by our indices.
fn validated_mesh(
    nodes: &Nodes,
    triangles: Triangles,
    edges: &Edges,
    groups: Groups,
    index_base: usize,
) -> Parse<Mesh> {
    let coords: Vec<[f64; 2]> = nodes.xyz.iter().map(|p| [p[0], p[1]]).collect();
    let mesh_error = |e: Error| Fail {
        status: e.status(),
        message: e.message().to_string(),
    };
    let places = FilePlaces {
        groups,
        nodes: &nodes.blocks,
        triangles: &triangles.blocks,
        edges: &edges.blocks,
        edge_tags: &edges.tags,
    };
    let names = Names {
        index_base,
        file: "Gmsh",
        node_tags: Some(&nodes.tags),
        triangle_tags: Some(&triangles.elements),
        edge_tags: Some(&edges.elements),
        places: Some(&places),
    };
    let mut mesh =
        Mesh::with_names(coords, triangles.nodes, triangles.bodies, &names).map_err(mesh_error)?;
    mesh.set_boundary_edges_with_names(&edges.ends, &edges.tags, &names)
        .map_err(mesh_error)?;
    Ok(mesh)
}

/// Warns of the surfaces in several physical groups, each with the body
/// it takes (the first) and the groups dropped: what the file says and
/// the model cannot hold (a triangle has one body), said rather than
/// dropped without a word.
fn warn_surfaces_in_several_groups(mesh: &mut Mesh, blocks: &[Block], groups: Groups) {
    let mut several = std::collections::BTreeMap::new();
    for block in blocks.iter().filter(|b| b.dim == 2) {
        if let [body, dropped @ ..] = groups.of(2, block.entity) {
            if !dropped.is_empty() {
                several.insert(block.entity, (*body, dropped));
            }
        }
    }
    if several.is_empty() {
        return;
    }
    let items: Vec<String> = several
        .iter()
        .map(|(surface, (body, dropped))| {
            format!("surface {surface} (body {body}; dropped {})", tags(dropped))
        })
        .collect();
    mesh.warn(format!(
        "{} surface(s) in several physical groups: a triangle has one body, the first \
         group; the others are dropped: {}",
        items.len(),
        bounded_list(&items)
    ));
}

/// Warns of the points in physical groups, which the model has no use
/// for (it has no node groups), rather than dropping them without a word.
fn warn_physical_points(mesh: &mut Mesh, points: &[(i32, Vec<i32>)]) {
    if points.is_empty() {
        return;
    }
    let items: Vec<String> = points
        .iter()
        .map(|(point, groups)| format!("point {point} (group {})", tags(groups)))
        .collect();
    mesh.warn(format!(
        "{} point(s) in physical groups, which are not used (the model has no node \
         groups: fix or load nodes by index): {}",
        items.len(),
        bounded_list(&items)
    ));
}

/// Physical tags for a message: "8, 9"; past ten, the first ten, how many
/// more and how many in all ("101, …, 110 and 1490 more, 1500 in all"), so
/// that an entity in thousands of groups gives a warning of a few hundred
/// bytes, not of kilobytes.
fn tags(groups: &[i32]) -> String {
    const SHOWN: usize = 10;
    let shown: Vec<String> = groups.iter().take(SHOWN).map(i32::to_string).collect();
    let mut out = shown.join(", ");
    if groups.len() > SHOWN {
        out.push_str(&format!(
            " and {} more, {} in all",
            groups.len() - SHOWN,
            groups.len()
        ));
    }
    out
}

/// At most five items of a list for a message, then how many more.
fn bounded_list(items: &[String]) -> String {
    const SHOWN: usize = 5;
    let mut out = items[..items.len().min(SHOWN)].join(", ");
    if items.len() > SHOWN {
        out.push_str(&format!(" and {} more", items.len() - SHOWN));
    }
    out
}

// ---------------------------------------------------------------------------
// Tetrahedral meshes (read_solid_msh).
// ---------------------------------------------------------------------------

/// The tetrahedral mesh of the file's bytes: the same sections as
/// [`build`]'s, the tetrahedra of the physical volumes as bodies and the
/// triangles of the physical surfaces as tagged faces, checked with
/// messages in the file's terms.
fn build_solid(bytes: &[u8], index_base: usize) -> Parse<SolidMesh> {
    let Sections {
        entities,
        nodes,
        blocks,
        names,
    } = parse(bytes, Dims::Solid)?.required()?;
    let groups = Groups {
        entities: Some(&entities),
        names: &names,
    };
    let index = NodeIndex {
        nodes: &nodes,
        groups,
    };
    let (mut tets, mut faces) = (Tets::default(), Faces::default());
    for block in &blocks {
        match block.dim {
            3 => tets.add_block(block, &index)?,
            2 => {
                if let Some(physical) = entities.surfaces.get(&block.entity) {
                    faces.add_block(block, physical, &index)?;
                }
            }
            // Lines: nothing of a solid mesh refers to them.
            _ => {}
        }
    }
    if tets.nodes.is_empty() {
        let surfaces_only = blocks.iter().any(|b| b.dim == 2);
        return Err(Fail::mesh(format!(
            "$Elements: no tetrahedra in a physical volume: a 3D mesh needs 4-node tetrahedra \
             in physical volumes{}",
            if surfaces_only {
                " (the file has surface elements only: a 2D mesh?)"
            } else {
                ""
            }
        )));
    }
    check_finite(&nodes, groups, index_base)?;
    let Nodes {
        xyz,
        tags: node_tags,
        ..
    } = nodes;
    let names = SolidNames {
        index_base,
        node_tags: &node_tags,
        groups,
        faces: &faces,
    };
    names.check_tets(&tets)?;
    let mut mesh = SolidMesh::new(xyz, tets.nodes, tets.bodies, index_base).map_err(from_error)?;
    set_faces(&mut mesh, &names)?;
    Ok(mesh)
}

/// A mesh's error as a reader's failure.
fn from_error(e: Error) -> Fail {
    Fail {
        status: e.status(),
        message: e.message().to_string(),
    }
}

/// Refuses a node with a coordinate that is not finite, named by its tag
/// and entity (the mesh would name it by an index the user cannot look
/// up in the file).
fn check_finite(nodes: &Nodes, groups: Groups, index_base: usize) -> Parse<()> {
    let Some((k, p)) =
        (nodes.xyz.iter().enumerate()).find(|(_, p)| p.iter().any(|x| !x.is_finite()))
    else {
        return Ok(());
    };
    let place =
        block_of(&nodes.blocks, |b| b.0, k).map(|&(_, dim, entity)| groups.place(dim, entity));
    let of = place.map_or_else(String::new, |p| format!(" of {p}"));
    Err(Fail::mesh(format!(
        "node {} (Gmsh node {}{of}): coordinates ({:?}, {:?}, {:?}) are not finite",
        k + index_base,
        nodes.tags[k],
        p[0],
        p[1],
        p[2]
    )))
}

/// The tetrahedra of the physical volumes, with where each came from in
/// the file, for messages.
#[derive(Default)]
struct Tets {
    nodes: Vec<[usize; 4]>,
    bodies: Vec<i32>,
    /// The file's element tag of each tetrahedron.
    elements: Vec<u64>,
    /// (first tetrahedron, volume, body) of each block.
    blocks: Vec<(usize, i32, i32)>,
}

impl Tets {
    /// Adds a block of tetrahedra, of the body of its volume's physical
    /// group. A volume in none is refused, as a surface is in 2D: every
    /// volume must be a body. A volume in several is refused too: a
    /// tetrahedron has one body, and a solid mesh has no warnings to say
    /// which group was dropped.
    fn add_block(&mut self, block: &Block, index: &NodeIndex) -> Parse<()> {
        let body = match index.groups.of(3, block.entity) {
            [body] => *body,
            [] => {
                return Err(Fail::mesh(format!(
                    "$Elements: volume {} has no physical group in $Entities: every volume must \
                     be a body",
                    block.entity
                )));
            }
            _ => {
                return Err(Fail::mesh(format!(
                    "$Elements: {}: a tetrahedron has one body, so a volume must be in one \
                     physical group",
                    index.groups.place(3, block.entity)
                )));
            }
        };
        self.blocks.push((self.nodes.len(), block.entity, body));
        for (&element, e) in block
            .tags
            .iter()
            .zip(block.node_tags.chunks_exact(block.nodes_per))
        {
            self.nodes.push([
                index.of(block, element, e[0])?,
                index.of(block, element, e[1])?,
                index.of(block, element, e[2])?,
                index.of(block, element, e[3])?,
            ]);
            self.bodies.push(body);
            self.elements.push(element);
        }
        Ok(())
    }
}

/// The tagged triangles of the physical surfaces, with where each came
/// from in the file, for messages.
#[derive(Default)]
struct Faces {
    nodes: Vec<[usize; 3]>,
    /// The tag of each face: a physical group of its surface.
    tags: Vec<i32>,
    /// The file's element tag of each face.
    elements: Vec<u64>,
    /// (first face, surface) of each block.
    blocks: Vec<(usize, i32)>,
}

impl Faces {
    /// Adds a block of triangles of a surface in the groups `physical`,
    /// each triangle once per group, as [`Edges::add_block`] does with
    /// lines: a side may be in its own group and in "the whole boundary".
    fn add_block(&mut self, block: &Block, physical: &[i32], index: &NodeIndex) -> Parse<()> {
        self.blocks.push((self.nodes.len(), block.entity));
        for (&element, e) in block
            .tags
            .iter()
            .zip(block.node_tags.chunks_exact(block.nodes_per))
        {
            let nodes = [
                index.of(block, element, e[0])?,
                index.of(block, element, e[1])?,
                index.of(block, element, e[2])?,
            ];
            for &tag in physical {
                self.nodes.push(nodes);
                self.tags.push(tag);
                self.elements.push(element);
            }
        }
        Ok(())
    }
}

/// Names the nodes, tetrahedra and faces of a solid mesh as the file
/// does, for messages: by index and by the file's tags and groups.
struct SolidNames<'a> {
    index_base: usize,
    node_tags: &'a [u64],
    groups: Groups<'a>,
    faces: &'a Faces,
}

impl SolidNames<'_> {
    /// Node `i`: "5 (Gmsh node 1006)".
    fn node(&self, i: usize) -> String {
        format!("{} (Gmsh node {})", i + self.index_base, self.node_tags[i])
    }

    /// Tetrahedron `e`: "tetrahedron 3 (Gmsh element 57 of volume 1 in
    /// physical group 7)".
    fn tet(&self, tets: &Tets, e: usize) -> String {
        let place = block_of(&tets.blocks, |b| b.0, e)
            .map_or_else(String::new, |&(_, volume, body)| {
                format!(" of {}", self.groups.place_in(3, volume, body))
            });
        format!(
            "tetrahedron {} (Gmsh element {}{place})",
            e + self.index_base,
            tets.elements[e]
        )
    }

    /// Face `f`: "Gmsh triangle element 12 of surface 3 in physical group
    /// 20 (Gmsh nodes 5, 6, 9)".
    fn face(&self, f: usize) -> String {
        let place = block_of(&self.faces.blocks, |b| b.0, f).map_or_else(String::new, |b| {
            format!(" of {}", self.groups.place_in(2, b.1, self.faces.tags[f]))
        });
        let [p, q, r] = self.faces.nodes[f].map(|v| self.node_tags[v]);
        format!(
            "Gmsh triangle element {}{place} (Gmsh nodes {p}, {q}, {r})",
            self.faces.elements[f]
        )
    }

    /// Refuses a tetrahedron with a repeated node, and one given twice
    /// (the same four nodes in any order: its stiffness would count twice,
    /// as the 2D mesh refuses a triangle given twice).
    fn check_tets(&self, tets: &Tets) -> Parse<()> {
        for (e, t) in tets.nodes.iter().enumerate() {
            if let Some(&v) = (0..4).find_map(|i| t[i + 1..].iter().find(|&&w| w == t[i])) {
                return Err(Fail::mesh(format!(
                    "{}: node {} is repeated ({})",
                    self.tet(tets, e),
                    self.node(v),
                    t.map(|v| self.node(v)).join(", ")
                )));
            }
        }
        let mut keyed: Vec<([usize; 4], usize)> = (tets.nodes.iter().enumerate())
            .map(|(e, t)| {
                let mut key = *t;
                key.sort_unstable();
                (key, e)
            })
            .collect();
        keyed.sort_unstable();
        if let Some(w) = keyed.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(Fail::mesh(format!(
                "{} has the nodes of {}: a tetrahedron given twice would count twice",
                self.tet(tets, w[1].1),
                self.tet(tets, w[0].1)
            )));
        }
        Ok(())
    }
}

/// Gives `mesh` the file's tagged faces, or the mesh's refusal of the
/// first face it refuses, named as the file names it: the mesh's message
/// says "boundary face 7", an index the user cannot look up in the file.
fn set_faces(mesh: &mut SolidMesh, names: &SolidNames) -> Parse<()> {
    let (faces, tags) = (&names.faces.nodes, &names.faces.tags);
    let Err(mut error) = mesh.set_boundary_faces(faces, tags) else {
        return Ok(());
    };
    // The mesh checks each face against the tetrahedra and the faces
    // before it, so the shortest prefix refused ends with the first face
    // refused: found by bisection (a few passes over the mesh, on the
    // error path only), `ok` accepted and `bad` refused.
    let (mut ok, mut bad) = (0, faces.len());
    while bad - ok > 1 {
        let mid = ok + (bad - ok) / 2;
        match mesh.set_boundary_faces(&faces[..mid], &tags[..mid]) {
            Ok(()) => ok = mid,
            Err(e) => (bad, error) = (mid, e),
        }
    }
    Err(Fail {
        status: error.status(),
        message: format!(
            "$Elements: {}: {}",
            names.face(bad.max(1) - 1),
            error.message()
        ),
    })
}
