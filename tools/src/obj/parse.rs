//! Wavefront OBJ → indexed triangle list, for `obj2rs`.
//!
//! Understood statements: `v x y z [w | r g b [a]]` (the first three numbers
//! are the position), `vn x y z`, `vt u [v [w]]` (only counted, to check
//! indices), and `f` with corners `v`, `v/vt`, `v//vn` or `v/vt/vn`; indices
//! are 1-based, negative ones count back from the latest element, and they
//! must refer to elements defined earlier in the file. Polygons are
//! triangulated as fans from their first corner. `#` starts a comment, a
//! trailing `\` continues a statement on the next line, and every other
//! statement (`o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, …) is ignored.
//!
//! Each distinct (position, normal) pair becomes one output vertex, in order
//! of first use; unused positions are dropped, as are triangles with a
//! repeated position. File normals are normalised; vertices without one (or
//! with a zero one) get the area-weighted average of the normals of the
//! triangles around their position.

use std::collections::HashMap;
use std::fmt;

use microraster::mesh::{MAX_VERTICES, Mesh, bounding_sphere};

/// A converted mesh: the data of a [`Mesh`] plus conversion statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjMesh {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Unit vertex normals, one per position.
    pub normals: Vec<[f32; 3]>,
    /// Triangles, with the file's winding.
    pub indices: Vec<[u16; 3]>,
    /// From [`bounding_sphere`].
    pub bounding_sphere: ([f32; 3], f32),
    /// Vertices whose normal was computed (area-weighted) rather than read.
    pub computed_normals: usize,
    /// Vertices with no usable normal at all (only degenerate triangles
    /// around them); they get `[0, 0, 1]`.
    pub arbitrary_normals: usize,
    /// Triangles dropped because two corners share a position.
    pub dropped_triangles: usize,
}

impl ObjMesh {
    /// The mesh, borrowing this data.
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, self.bounding_sphere)
    }
}

/// What is wrong with the input, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based line of the offending statement, or 0 for the file as a whole.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            f.write_str(&self.message)
        } else {
            write!(f, "line {}: {}", self.line, self.message)
        }
    }
}

impl std::error::Error for ParseError {}

fn error(line: usize, message: impl Into<String>) -> ParseError {
    ParseError { line, message: message.into() }
}

/// One output vertex: indices into the file's `v` and `vn` lists.
type Key = (usize, Option<usize>);

/// Parses OBJ text (see the module docs).
pub fn parse_obj(text: &str) -> Result<ObjMesh, ParseError> {
    let mut file_positions: Vec<[f32; 3]> = Vec::new();
    let mut file_normals: Vec<[f32; 3]> = Vec::new();
    let mut texcoords = 0usize;
    let mut keys: Vec<Key> = Vec::new();
    let mut vertex_of: HashMap<Key, u16> = HashMap::new();
    let mut indices: Vec<[u16; 3]> = Vec::new();
    let mut dropped_triangles = 0;
    let mut corners: Vec<u16> = Vec::new();

    for (line, statement) in statements(text) {
        let mut tokens = statement.split_whitespace();
        let Some(keyword) = tokens.next() else { continue };
        let args: Vec<&str> = tokens.collect();
        match keyword {
            "v" => {
                if !(3..=7).contains(&args.len()) {
                    return Err(error(line, format!("`v` needs 3 to 7 numbers, found {}", args.len())));
                }
                let mut p = [0.0; 3];
                for (k, a) in args.iter().enumerate() {
                    let x = number(a, line)?;
                    if k < 3 {
                        p[k] = x;
                    }
                }
                file_positions.push(p);
            }
            "vn" => {
                if args.len() != 3 {
                    return Err(error(line, format!("`vn` needs 3 numbers, found {}", args.len())));
                }
                let mut n = [0.0; 3];
                for (k, a) in args.iter().enumerate() {
                    n[k] = number(a, line)?;
                }
                file_normals.push(n);
            }
            "vt" => {
                if !(1..=3).contains(&args.len()) {
                    return Err(error(line, format!("`vt` needs 1 to 3 numbers, found {}", args.len())));
                }
                for a in &args {
                    number(a, line)?;
                }
                texcoords += 1;
            }
            "f" => {
                if args.len() < 3 {
                    return Err(error(
                        line,
                        format!("a face needs at least 3 corners, found {}", args.len()),
                    ));
                }
                corners.clear();
                for corner in &args {
                    let key = face_corner(corner, line, file_positions.len(), texcoords, file_normals.len())?;
                    let vertex = match vertex_of.get(&key) {
                        Some(&v) => v,
                        None => {
                            let Ok(v) = u16::try_from(keys.len()) else {
                                return Err(error(
                                    line,
                                    format!("more than {MAX_VERTICES} distinct vertices (indices are u16)"),
                                ));
                            };
                            keys.push(key);
                            vertex_of.insert(key, v);
                            v
                        }
                    };
                    corners.push(vertex);
                }
                for k in 1..corners.len() - 1 {
                    let tri = [corners[0], corners[k], corners[k + 1]];
                    let [a, b, c] = tri.map(|v| keys[usize::from(v)].0);
                    if a == b || b == c || c == a {
                        dropped_triangles += 1;
                    } else {
                        indices.push(tri);
                    }
                }
            }
            _ => {}
        }
    }
    if indices.is_empty() {
        return Err(error(0, "no (non-degenerate) faces in the file"));
    }

    let positions: Vec<[f32; 3]> = keys.iter().map(|&(p, _)| file_positions[p]).collect();
    // Area-weighted normals per file position, in f64: the sum of the
    // (unnormalised) cross products of the triangles around it.
    let mut weighted: HashMap<usize, [f64; 3]> = HashMap::new();
    for tri in &indices {
        let [a, b, c] = tri.map(|v| positions[usize::from(v)].map(f64::from));
        let n = cross(sub(b, a), sub(c, a));
        for v in tri {
            let sum = weighted.entry(keys[usize::from(*v)].0).or_insert([0.0; 3]);
            *sum = [sum[0] + n[0], sum[1] + n[1], sum[2] + n[2]];
        }
    }
    let (mut computed_normals, mut arbitrary_normals) = (0, 0);
    let normals = keys
        .iter()
        .map(|&(p, n)| {
            if let Some(n) = n.and_then(|n| unit(file_normals[n].map(f64::from))) {
                return n;
            }
            computed_normals += 1;
            weighted.get(&p).and_then(|&n| unit(n)).unwrap_or_else(|| {
                arbitrary_normals += 1;
                [0.0, 0.0, 1.0]
            })
        })
        .collect();

    let bounding_sphere = bounding_sphere(&positions);
    let r = bounding_sphere.1 * (1.0 + microraster::mesh::SPHERE_TOLERANCE);
    if !(r * r).is_finite() {
        return Err(error(0, "coordinates too large: the bounding radius must stay below 1.8e19"));
    }
    let mesh = ObjMesh {
        positions,
        normals,
        indices,
        bounding_sphere,
        computed_normals,
        arbitrary_normals,
        dropped_triangles,
    };
    if let Err(e) = mesh.mesh().validate() {
        return Err(error(0, format!("the converted mesh is invalid: {e}")));
    }
    Ok(mesh)
}

/// Logical statements with the line they start on: comments removed,
/// `\`-continued lines joined.
fn statements(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut pending: Option<(usize, String)> = None;
    for (i, raw) in text.lines().enumerate() {
        let content = raw.split('#').next().unwrap_or("").trim_end();
        let (content, continued) = match content.strip_suffix('\\') {
            Some(c) => (c, true),
            None => (content, false),
        };
        let (start, mut s) = pending.take().unwrap_or((i + 1, String::new()));
        s.push(' ');
        s.push_str(content);
        if continued {
            pending = Some((start, s));
        } else {
            out.push((start, s));
        }
    }
    out.extend(pending);
    out
}

fn number(token: &str, line: usize) -> Result<f32, ParseError> {
    match token.parse::<f32>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(error(line, format!("`{token}` is not a finite f32"))),
        Err(_) => Err(error(line, format!("`{token}` is not a number"))),
    }
}

/// Resolves one face corner to (position, normal) indices, checking every
/// index (texture coordinates included) against the elements defined so far.
fn face_corner(
    corner: &str,
    line: usize,
    positions: usize,
    texcoords: usize,
    normals: usize,
) -> Result<Key, ParseError> {
    let parts: Vec<&str> = corner.split('/').collect();
    let bad_form = || error(line, format!("bad face corner `{corner}` (expected v, v/vt, v//vn or v/vt/vn)"));
    let (v, vt, vn) = match parts[..] {
        [v] => (v, None, None),
        [v, vt] => (v, Some(vt), None),
        [v, "", vn] => (v, None, Some(vn)),
        [v, vt, vn] => (v, Some(vt), Some(vn)),
        _ => return Err(bad_form()),
    };
    if vt == Some("") || vn == Some("") {
        return Err(bad_form());
    }
    let p = index(v, positions, "position", line)?;
    if let Some(vt) = vt {
        index(vt, texcoords, "texture coordinate", line)?;
    }
    let n = vn.map(|vn| index(vn, normals, "normal", line)).transpose()?;
    Ok((p, n))
}

/// A 1-based or negative (relative) OBJ index into a list of `count`
/// elements, as a 0-based index.
fn index(token: &str, count: usize, what: &str, line: usize) -> Result<usize, ParseError> {
    let Ok(n) = token.parse::<i64>() else {
        return Err(error(line, format!("`{token}` is not a valid {what} index")));
    };
    let resolved = match n {
        0 => return Err(error(line, format!("{what} index 0 is invalid (OBJ indices start at 1)"))),
        n if n > 0 => usize::try_from(n - 1).ok().filter(|&i| i < count),
        n => usize::try_from(n.unsigned_abs()).ok().and_then(|back| count.checked_sub(back)),
    };
    resolved.ok_or_else(|| {
        error(line, format!("{what} index {n} is out of range ({count} {what}s defined so far)"))
    })
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `v / |v|` as `f32`, or `None` if `v` is zero (or not finite).
fn unit(v: [f64; 3]) -> Option<[f32; 3]> {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (len > 0.0 && len.is_finite()).then(|| v.map(|x| (x / len) as f32))
}
