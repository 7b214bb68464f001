//! The VTU files' independent reader, shared by tests/vtu.rs (triangles)
//! and tests/vtu_solid.rs (tetrahedra): our own XML and raw-block parser,
//! and the helpers that ask meshio and VTK's Python bindings for the same
//! arrays. Each test binary uses part of it.
#![allow(dead_code)]

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;

// ---------------------------------------------------------------------------
// A reader of our own: the XML up to `<AppendedData
// encoding="raw">` read tag by tag, then each array's block found at its
// offset from the byte after `_`, checking the layout rules as it goes.
// ---------------------------------------------------------------------------

/// One `DataArray` of the file.
#[derive(Debug)]
pub struct Array {
    /// Its section: `Points`, `Cells`, `PointData` or `CellData`.
    pub section: String,
    pub name: String,
    pub scalar: String,
    pub components: usize,
    pub component_names: Vec<String>,
    /// Its value bytes (after the byte count).
    pub bytes: Vec<u8>,
}

pub struct Vtu {
    pub root: HashMap<String, String>,
    /// The attributes of each section's tag.
    pub sections: HashMap<String, HashMap<String, String>>,
    pub points: usize,
    pub cells: usize,
    pub arrays: Vec<Array>,
}

/// The attributes of the tag text `text` (between `<` and `>`).
pub fn attributes(text: &str) -> HashMap<String, String> {
    let mut out = HashMap::new();
    let mut rest = text.split_once(char::is_whitespace).map_or("", |s| s.1);
    while let Some((key, after)) = rest.split_once("=\"") {
        let (value, tail) = after.split_once('"').expect("a closing quote");
        let previous = out.insert(key.trim().to_string(), value.to_string());
        assert!(previous.is_none(), "attribute {key} given twice");
        rest = tail;
    }
    out
}

pub fn scalar_size(scalar: &str) -> usize {
    match scalar {
        "Float64" | "Int64" | "UInt64" => 8,
        "Float32" | "Int32" | "UInt32" => 4,
        "UInt8" | "Int8" => 1,
        other => panic!("unexpected type {other}"),
    }
}

/// The file at `path`, its cells of `corners` nodes each.
pub fn read_vtu(path: &Path, corners: usize) -> Vtu {
    let file = std::fs::read(path).unwrap();
    let start_tag = b"<AppendedData encoding=\"raw\">";
    let at = file
        .windows(start_tag.len())
        .position(|w| w == start_tag)
        .expect("<AppendedData encoding=\"raw\">");
    let xml = std::str::from_utf8(&file[..at]).expect("the XML is text");
    let after_tag = at + start_tag.len();
    let underscore = after_tag
        + file[after_tag..]
            .iter()
            .position(|&b| b == b'_')
            .expect("the `_` that opens the data");
    assert!(
        file[after_tag..underscore]
            .iter()
            .all(u8::is_ascii_whitespace),
        "only blanks between <AppendedData> and `_`"
    );
    let data = &file[underscore + 1..];

    let (mut root, mut piece) = (None, None);
    let mut section = String::new();
    let mut sections = HashMap::new();
    let mut headers = Vec::new();
    for tag in xml.split('<').skip(1) {
        let text = tag.split_once('>').expect("a tag ends with >").0;
        let name = text.split_whitespace().next().unwrap_or("");
        match name {
            "?xml" => {}
            "VTKFile" => root = Some(attributes(text)),
            "UnstructuredGrid" | "/UnstructuredGrid" | "/Piece" => {}
            "Piece" => piece = Some(attributes(text)),
            "Points" | "Cells" | "PointData" | "CellData" => {
                assert!(section.is_empty(), "{name} inside {section}");
                section = name.to_string();
                let previous = sections.insert(section.clone(), attributes(text));
                assert!(previous.is_none(), "a second {name}");
            }
            "/Points" | "/Cells" | "/PointData" | "/CellData" => {
                assert_eq!(&name[1..], section, "{name} closes {section}");
                section.clear();
            }
            "DataArray" => {
                assert!(text.ends_with('/'), "an appended DataArray is empty");
                assert!(!section.is_empty(), "a DataArray outside a section");
                headers.push((section.clone(), attributes(text.trim_end_matches('/'))));
            }
            other => panic!("unexpected tag <{other}>"),
        }
    }
    let root = root.expect("<VTKFile>");
    let piece = piece.expect("<Piece>");
    let count = |key: &str| -> usize { piece[key].parse().unwrap() };
    let (points, cells) = (count("NumberOfPoints"), count("NumberOfCells"));

    // The blocks tile the data in the order of the headers, from offset 0.
    let mut next = 0usize;
    let mut arrays = Vec::new();
    for (section, a) in headers {
        assert_eq!(a["format"], "appended", "{a:?}");
        let offset: usize = a["offset"].parse().unwrap();
        assert_eq!(offset, next, "{a:?}: the blocks must follow each other");
        let length = u64::from_le_bytes(data[offset..offset + 8].try_into().unwrap()) as usize;
        let components: usize = a["NumberOfComponents"].parse().unwrap();
        let component_names = (0..components)
            .map_while(|k| a.get(&format!("ComponentName{k}")).cloned())
            .collect();
        let tuples = match section.as_str() {
            "Points" | "PointData" => points,
            "CellData" => cells,
            _ => match a["Name"].as_str() {
                "connectivity" => corners * cells,
                _ => cells,
            },
        };
        assert_eq!(
            length,
            tuples * components * scalar_size(&a["type"]),
            "{a:?}: the byte count"
        );
        arrays.push(Array {
            section,
            name: a["Name"].clone(),
            scalar: a["type"].clone(),
            components,
            component_names,
            bytes: data[offset + 8..offset + 8 + length].to_vec(),
        });
        next = offset + 8 + length;
    }
    let tail = std::str::from_utf8(&data[next..]).expect("text after the data");
    let words: Vec<&str> = tail.split_whitespace().collect();
    assert_eq!(words, ["</AppendedData>", "</VTKFile>"]);
    assert!(
        tail.starts_with('\n'),
        "a line break ends the data (meshio cuts the data at the last one)"
    );
    Vtu {
        root,
        sections,
        points,
        cells,
        arrays,
    }
}

impl Vtu {
    pub fn has(&self, section: &str, name: &str) -> bool {
        self.arrays
            .iter()
            .any(|a| a.section == section && a.name == name)
    }

    pub fn array(&self, section: &str, name: &str) -> &Array {
        self.arrays
            .iter()
            .find(|a| a.section == section && a.name == name)
            .unwrap_or_else(|| panic!("{section}/{name} missing"))
    }

    pub fn names(&self, section: &str) -> Vec<&str> {
        self.arrays
            .iter()
            .filter(|a| a.section == section)
            .map(|a| a.name.as_str())
            .collect()
    }

    pub fn f64s(&self, section: &str, name: &str, components: usize) -> Vec<f64> {
        let a = self.array(section, name);
        assert_eq!((a.scalar.as_str(), a.components), ("Float64", components));
        a.bytes
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
            .collect()
    }

    pub fn ints(&self, section: &str, name: &str) -> Vec<i64> {
        let a = self.array(section, name);
        assert_eq!(a.components, 1);
        match a.scalar.as_str() {
            "Int32" => a
                .bytes
                .chunks_exact(4)
                .map(|b| i64::from(i32::from_le_bytes(b.try_into().unwrap())))
                .collect(),
            "Int64" => a
                .bytes
                .chunks_exact(8)
                .map(|b| i64::from_le_bytes(b.try_into().unwrap()))
                .collect(),
            "UInt8" => a.bytes.iter().map(|&b| i64::from(b)).collect(),
            other => panic!("{name} is {other}"),
        }
    }
}

pub fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Asserts `read` and `expected` are the same values, bit for bit.
pub fn same(what: &str, read: &[f64], expected: &[f64]) {
    assert_eq!(read.len(), expected.len(), "{what}: lengths");
    assert!(bits(read) == bits(expected), "{what}: values differ");
}

/// Runs `script` (Python, given the file's path) if `python3` can import
/// `module`; None, with a note on stdout, where it cannot.
pub fn python_arrays(module: &str, script: &str, path: &Path) -> Option<HashMap<String, Vec<u8>>> {
    let probe = Command::new("python3")
        .args(["-c", &format!("import {module}")])
        .output();
    if !probe.is_ok_and(|o| o.status.success()) {
        println!("note: skipped: python3 cannot import {module} (pip install {module} to run it)");
        return None;
    }
    let out = Command::new("python3")
        .args(["-c", script])
        .arg(path)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{module} failed:\n{stderr}");
    assert!(stderr.trim().is_empty(), "{module} complained:\n{stderr}");
    let text = String::from_utf8(out.stdout).unwrap();
    let hex = |s: &str| -> Vec<u8> {
        (0..s.len())
            .step_by(2)
            .map(|k| u8::from_str_radix(&s[k..k + 2], 16).unwrap())
            .collect()
    };
    Some(
        text.lines()
            .map(|l| {
                let (name, bytes) = l.split_once(' ').unwrap_or((l, ""));
                (name.to_string(), hex(bytes))
            })
            .collect(),
    )
}

pub fn as_f64(bytes: &[u8]) -> Vec<f64> {
    bytes
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

pub fn as_i64(bytes: &[u8]) -> Vec<i64> {
    bytes
        .chunks_exact(8)
        .map(|b| i64::from_le_bytes(b.try_into().unwrap()))
        .collect()
}
