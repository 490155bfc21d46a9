//! Writes `examples/common/knot_mesh.rs`: the meshlet benchmark mesh, a
//! (2, 3) torus knot (a trefoil) whose tube carries helical ridges, 20,480
//! triangles over 10,240 shared vertices with unit normals, closed and wound
//! counter-clockwise from outside, split into clusters by
//! [`build_meshlets`]. At 320×240 with the standard 3D scene's camera it
//! spans most of the frame height at about 1–2 covered pixels per
//! front-facing triangle (printed on stderr). `tests/bench_mesh.rs` checks
//! the committed file against this generator.
//!
//! ```text
//! cargo run --example gen_bench_mesh > examples/common/knot_mesh.rs
//! ```
//!
//! The output is already as `rustfmt` leaves it (the arrays are
//! `#[rustfmt::skip]`), so `cargo fmt` keeps it equal to the generator's.
//!
//! The geometry uses only the crate's own `sqrt` and `sin_cos` (through
//! [`Scalar`]), exact `f32` arithmetic and rounding, so it is the same on
//! every target. Positions and normals are rounded to 4 decimals, which
//! keeps the file compact (shortest round-trip formatting) and moves nothing
//! by more than 5·10⁻⁵ (normals stay unit within 10⁻⁴).

use std::fmt::Write;

use microraster::math::{Fx, Scalar};
use microraster::mesh::{
    Mesh, Meshlet, bounding_sphere, build_meshlets, meshlet_bound, meshlet_scratch_len, meshlet_vertex_bound,
};

/// Samples along the knot.
pub const ALONG: usize = 320;
/// Samples around the tube.
pub const AROUND: usize = 32;
/// Torus the knot winds on: ring radius and tube radius (before [`SCALE`]).
pub const KNOT_R: (f32, f32) = (1.6, 0.7);
/// Radius of the mesh's tube and relative height of its ridges.
pub const TUBE: (f32, f32) = (0.36, 0.1);
/// Overall scale: fits the standard camera at 1–2 pixels per triangle.
pub const SCALE: f32 = 0.75;

/// The knot mesh in owned buffers, triangles in cluster order.
pub struct Knot {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub indices: Vec<[u16; 3]>,
    /// Its bounding sphere and clusters.
    pub f32: Clusters,
    /// The same mesh in 16.16 (the positions and normals
    /// `Fx::from_f32` of those above): its sphere and clusters, built
    /// from those values (`KNOT_FX`).
    pub fx: Clusters,
}

/// A mesh's bounding sphere and its clusters.
pub struct Clusters {
    pub sphere: ([f32; 3], f32),
    pub meshlets: Vec<Meshlet>,
    pub vertices: Vec<u16>,
    pub triangles: Vec<[u8; 3]>,
}

impl Knot {
    /// The plain mesh (triangles in cluster order).
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.normals, &self.indices, self.f32.sphere)
    }
}

/// The knot's centre line at parameter `phi` ∈ [0, 2π): on the torus of
/// [`KNOT_R`], twice around the ring while three times around the tube. Also
/// the torus' outward normal there, which orients the tube's frame.
pub fn centre_line(phi: f32) -> ([f32; 3], [f32; 3]) {
    let (big_r, r) = KNOT_R;
    let (s2, c2) = Scalar::sin_cos(2.0 * phi);
    let (s3, c3) = Scalar::sin_cos(3.0 * phi);
    let rho = big_r + r * c3;
    ([rho * c2, rho * s2, r * s3], [c3 * c2, c3 * s2, s3])
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(v: [f32; 3]) -> [f32; 3] {
    let len = Scalar::sqrt(dot(v, v));
    v.map(|x| x / len)
}

/// `x` rounded to 4 decimals (the nearest `f32` to `k / 10⁴`).
fn round4(x: f32) -> f32 {
    (x * 1.0e4).round() / 1.0e4
}

/// Positions, normals and triangles.
pub type Arrays = (Vec<[f32; 3]>, Vec<[f32; 3]>, Vec<[u16; 3]>);

/// The knot's tube: positions, area-weighted vertex normals and the grid's
/// triangles (counter-clockwise from outside).
pub fn tube() -> Arrays {
    tube_of(ALONG, AROUND)
}

/// [`tube`] with `along` samples along the knot and `around` around the
/// tube (`2 · along · around` triangles).
pub fn tube_of(along: usize, around: usize) -> Arrays {
    let tau = core::f32::consts::TAU;
    let phi = |i: usize| tau * (i % along) as f32 / along as f32;
    let mut positions = Vec::with_capacity(along * around);
    for i in 0..along {
        let (c, out) = centre_line(phi(i));
        // Frame: tangent by central difference, normal = the torus normal
        // made perpendicular to it (periodic, so the tube closes).
        let t = normalize(sub(centre_line(phi(i + 1)).0, centre_line(phi(i + along - 1)).0));
        let n = normalize(sub(out, t.map(|x| x * dot(out, t))));
        let b = cross(t, n);
        for j in 0..around {
            let theta = tau * j as f32 / around as f32;
            let (st, ct) = Scalar::sin_cos(theta);
            let ridge = Scalar::sin_cos(5.0 * theta + 30.0 * phi(i)).1;
            let a = TUBE.0 * (1.0 + TUBE.1 * ridge);
            positions.push([0, 1, 2].map(|k| round4(SCALE * (c[k] + a * (ct * n[k] + st * b[k])))));
        }
    }
    let v = |i: usize, j: usize| ((i % along) * around + j % around) as u16;
    let mut indices = Vec::with_capacity(2 * along * around);
    for i in 0..along {
        for j in 0..around {
            // Along the knot × around the tube points inward: wind the other way.
            indices.push([v(i, j), v(i + 1, j + 1), v(i + 1, j)]);
            indices.push([v(i, j), v(i, j + 1), v(i + 1, j + 1)]);
        }
    }
    let mut sums = vec![[0.0f32; 3]; positions.len()];
    for t in &indices {
        let p = t.map(|k| positions[usize::from(k)]);
        let face = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        for k in t {
            for d in 0..3 {
                sums[usize::from(*k)][d] += face[d];
            }
        }
    }
    let normals = sums.into_iter().map(|s| normalize(s).map(round4)).collect();
    (positions, normals, indices)
}

/// [`tube_of`] as a Wavefront OBJ file, the way a modeller exports it
/// (`v` and `vn` in vertex order, `f` with one normal per position, in grid
/// order): what `obj2rs` converts for the front's rows of the firmware
/// benchmark (`cargo run --example gen_bench_mesh -- --obj 320 32`).
pub fn obj_text(along: usize, around: usize) -> String {
    let (positions, normals, indices) = tube_of(along, around);
    let mut s = format!("# The ridged (2, 3) torus knot, {along} x {around}: gen_bench_mesh --obj\n");
    for [x, y, z] in &positions {
        let _ = writeln!(s, "v {x:?} {y:?} {z:?}");
    }
    for [x, y, z] in &normals {
        let _ = writeln!(s, "vn {x:?} {y:?} {z:?}");
    }
    for t in &indices {
        let [a, b, c] = t.map(|k| u32::from(k) + 1);
        let _ = writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}");
    }
    s
}

/// The knot with its clusters.
pub fn knot() -> Result<Knot, String> {
    let (positions, normals, grid) = tube();
    let sphere = bounding_sphere(&positions);
    let f32 = clusters(Mesh::new(&positions, &normals, &grid, sphere))?;
    let fx = fx_clusters(&positions, &normals, &grid)?;
    let mut indices = Vec::with_capacity(grid.len());
    for c in &f32.meshlets {
        let local = &f32.vertices[c.vertex_offset as usize..][..usize::from(c.vertex_count)];
        for t in &f32.triangles[c.triangle_offset as usize..][..usize::from(c.triangle_count)] {
            indices.push(t.map(|k| local[usize::from(k)]));
        }
    }
    Ok(Knot { positions, normals, indices, f32, fx })
}

/// The sphere and clusters of the mesh in 16.16: its values differ from
/// the `f32` ones by up to 2^-17, beyond the spheres' tolerance, so
/// [`build_meshlets`] makes them from the 16.16 data.
fn fx_clusters(positions: &[[f32; 3]], normals: &[[f32; 3]], grid: &[[u16; 3]]) -> Result<Clusters, String> {
    let fx = |rows: &[[f32; 3]]| rows.iter().map(|r| r.map(Fx::from_f32)).collect::<Vec<_>>();
    let (p, n) = (fx(positions), fx(normals));
    let sphere = bounding_sphere(&p.iter().map(|r| r.map(Fx::to_f32)).collect::<Vec<_>>());
    clusters(Mesh::new_fx(&p, &n, grid, sphere))
}

/// `mesh`'s sphere and the clusters [`build_meshlets`] makes of it.
fn clusters<P: Scalar>(mesh: Mesh<'_, P>) -> Result<Clusters, String> {
    let (nv, nt) = (mesh.positions.len(), mesh.indices.len());
    let mut meshlets = vec![Meshlet::default(); meshlet_bound(nt)];
    let mut vertices = vec![0; meshlet_vertex_bound(nt)];
    let mut triangles = vec![[0; 3]; nt];
    let mut scratch = vec![0; meshlet_scratch_len(nv, nt)];
    let m = build_meshlets(mesh, &mut meshlets, &mut vertices, &mut triangles, &mut scratch)
        .map_err(|e| e.to_string())?;
    Ok(Clusters {
        sphere: mesh.bounding_sphere,
        meshlets: m.meshlets.to_vec(),
        vertices: m.vertices.to_vec(),
        triangles: m.triangles.to_vec(),
    })
}

/// A static array: its doc comment and attributes, then `items`,
/// `per_line` to a line, as `f` writes each.
fn static_array<T>(
    s: &mut String,
    (doc, name, ty): (&str, &str, &str),
    items: &[T],
    per_line: usize,
    f: impl Fn(&T) -> String,
) {
    let _ = writeln!(s, "/// {doc}\n#[rustfmt::skip]\n#[allow(clippy::approx_constant)]");
    let _ = writeln!(s, "pub static {name}: [{ty}; {}] = [", items.len());
    for chunk in items.chunks(per_line) {
        s.push_str("    ");
        for item in chunk {
            s.push_str(&f(item));
            s.push(',');
        }
        s.push('\n');
    }
    s.push_str("];\n\n");
}

/// A triangle's three indices as the generated file writes them.
fn tri<T: std::fmt::Display>(t: &[T; 3]) -> String {
    format!("[{},{},{}]", t[0], t[1], t[2])
}

/// The name of the 16.16 clusters' array: the `f32` one where `items`
/// equal it, else a new static array written with `what` (as
/// [`static_array`]).
fn shared_or_own<T: PartialEq>(
    s: &mut String,
    (items, f32_items, f32_name): (&[T], &[T], &'static str),
    what: (&str, &'static str, &str),
    per_line: usize,
    f: impl Fn(&T) -> String,
) -> &'static str {
    if items == f32_items {
        return f32_name;
    }
    static_array(s, what, items, per_line, f);
    what.1
}

fn v3(v: &[f32; 3]) -> String {
    format!("[{:?},{:?},{:?}]", v[0], v[1], v[2])
}

/// The Rust source of `examples/common/knot_mesh.rs`.
pub fn rust_source(k: &Knot) -> String {
    let (nv, nt, nc) = (k.positions.len(), k.indices.len(), k.f32.meshlets.len());
    let mut s = String::new();
    s += "//! The meshlet benchmark mesh: a ridged (2, 3) torus knot, closed, counter-clockwise\n";
    s += "//! from outside, with unit normals, and its clusters. Generated by\n";
    s += "//! `cargo run --example gen_bench_mesh > examples/common/knot_mesh.rs`; do not edit.\n";
    let _ = writeln!(s, "//! {nv} vertices, {nt} triangles, {nc} clusters.\n");
    s += "// Not every program that includes the file draws both variants.\n#![allow(dead_code)]\n\n";
    s += "use microraster::math::Fx;\nuse microraster::mesh::{Mesh, Meshlet, MeshletMesh, ValidMeshletMesh, fx_rows};\n\n";
    let what = ("Vertex positions of [`KNOT`].", "KNOT_POSITIONS", "[f32; 3]");
    static_array(&mut s, what, &k.positions, 6, v3);
    static_array(&mut s, ("Unit vertex normals of [`KNOT`].", "KNOT_NORMALS", "[f32; 3]"), &k.normals, 6, v3);
    let doc = "Triangles of [`KNOT`] in cluster order (the clusters' triangles, expanded).";
    static_array(&mut s, (doc, "KNOT_INDICES", "[u16; 3]"), &k.indices, 8, tri);
    let doc = "Mesh vertex of each cluster-local vertex.";
    static_array(&mut s, (doc, "KNOT_MESHLET_VERTICES", "u16"), &k.f32.vertices, 20, |v| v.to_string());
    let what = ("Cluster-local triangles.", "KNOT_MESHLET_TRIANGLES", "[u8; 3]");
    static_array(&mut s, what, &k.f32.triangles, 10, tri);
    s += "/// One cluster: offsets, counts, sphere, cone.\n";
    s += "#[allow(clippy::too_many_arguments)]\n";
    s += "const fn m(vo: u32, to: u32, vc: u8, tc: u8, c: [f32; 3], r: f32, a: [f32; 3], k: f32) -> Meshlet {\n";
    s += "    Meshlet {\n        vertex_offset: vo,\n        triangle_offset: to,\n        vertex_count: vc,\n";
    s += "        triangle_count: tc,\n        sphere: (c, r),\n        cone: (a, k),\n    }\n}\n\n";
    static_array(
        &mut s,
        ("The clusters of [`KNOT`].", "KNOT_MESHLETS", "Meshlet"),
        &k.f32.meshlets,
        1,
        meshlet,
    );
    let ([cx, cy, cz], r) = k.f32.sphere;
    s += "/// The knot as a plain mesh (triangles in cluster order).\n";
    let _ = writeln!(
        s,
        "pub static KNOT_MESH: Mesh<'static> = Mesh::new(\n    &KNOT_POSITIONS,\n    &KNOT_NORMALS,\n    &KNOT_INDICES,\n    ([{cx:?}, {cy:?}, {cz:?}], {r:?}),\n);\n"
    );
    s += "/// The knot with its clusters.\npub static KNOT: MeshletMesh<'static> = MeshletMesh {\n";
    s += "    mesh: KNOT_MESH,\n    meshlets: &KNOT_MESHLETS,\n    vertices: &KNOT_MESHLET_VERTICES,\n";
    s += "    triangles: &KNOT_MESHLET_TRIANGLES,\n};\n\n";
    s += "/// [`KNOT`], validated at compile time (a few seconds of constant evaluation).\n";
    s += "pub static VALID_KNOT: ValidMeshletMesh<'static> = ValidMeshletMesh::new_const(KNOT);\n";
    fx_source(&mut s, k);
    s
}

/// The `KNOT_FX` part of [`rust_source`]: the data converted at compile
/// time, its own clusters (sharing the `f32` mesh's arrays where equal).
fn fx_source(s: &mut String, k: &Knot) {
    let (nv, fx) = (k.positions.len(), &k.fx);
    s.push('\n');
    let _ = writeln!(
        s,
        "/// [`KNOT_POSITIONS`] in 16.16, converted at compile time.\npub static KNOT_POSITIONS_FX: [[Fx; 3]; {nv}] = fx_rows(&KNOT_POSITIONS);\n"
    );
    let _ = writeln!(
        s,
        "/// [`KNOT_NORMALS`] in 16.16, converted at compile time.\npub static KNOT_NORMALS_FX: [[Fx; 3]; {nv}] = fx_rows(&KNOT_NORMALS);\n"
    );
    let doc = "Mesh vertex of each cluster-local vertex of [`KNOT_FX`].";
    let vertices = shared_or_own(
        s,
        (&fx.vertices, &k.f32.vertices, "KNOT_MESHLET_VERTICES"),
        (doc, "KNOT_MESHLET_VERTICES_FX", "u16"),
        20,
        |v| v.to_string(),
    );
    let what = ("Cluster-local triangles of [`KNOT_FX`].", "KNOT_MESHLET_TRIANGLES_FX", "[u8; 3]");
    let triangles =
        shared_or_own(s, (&fx.triangles, &k.f32.triangles, "KNOT_MESHLET_TRIANGLES"), what, 10, tri);
    let what = ("The clusters of [`KNOT_FX`], made from its 16.16 data.", "KNOT_MESHLETS_FX", "Meshlet");
    static_array(s, what, &fx.meshlets, 1, meshlet);
    let ([cx, cy, cz], r) = fx.sphere;
    *s += "/// [`KNOT`] in 16.16, for the fixed-point vertex stage (no conversion per vertex).\n";
    *s += "pub static KNOT_FX: MeshletMesh<'static, Fx> = MeshletMesh {\n";
    let _ = writeln!(
        s,
        "    mesh: Mesh::new_fx(\n        &KNOT_POSITIONS_FX,\n        &KNOT_NORMALS_FX,\n        &[],\n        ([{cx:?}, {cy:?}, {cz:?}], {r:?}),\n    ),"
    );
    let _ = writeln!(
        s,
        "    meshlets: &KNOT_MESHLETS_FX,\n    vertices: &{vertices},\n    triangles: &{triangles},\n}};\n"
    );
    *s += "/// [`KNOT_FX`], validated at compile time (reading 16.16 as `f32` takes the\n/// constant evaluation past the compiler's default step budget: allowed).\n";
    *s += "#[allow(long_running_const_eval)]\npub static VALID_KNOT_FX: ValidMeshletMesh<'static, Fx> = ValidMeshletMesh::new_fx_const(KNOT_FX);\n";
}

/// One cluster as the generated file writes it (its `m(…)` call).
fn meshlet(c: &Meshlet) -> String {
    let (centre, r) = c.sphere;
    let (axis, cut) = c.cone;
    format!(
        "m({},{},{},{},{},{r:?},{},{cut:?})",
        c.vertex_offset,
        c.triangle_offset,
        c.vertex_count,
        c.triangle_count,
        v3(&centre),
        v3(&axis)
    )
}

/// Pixels per front-facing triangle with the standard 3D scene's camera at
/// 320×240 (eye (0, 1.9, 5.6) looking at the origin, vertical field of view
/// 0.9 rad), from the summed projected areas (overlaps counted), and the
/// number of front-facing triangles.
pub fn pixels_per_triangle(mesh: &Mesh<'_>) -> (f64, usize) {
    let eye = [0.0, 1.9, 5.6f64];
    let f = {
        let l = (eye[1] * eye[1] + eye[2] * eye[2]).sqrt();
        [0.0, -eye[1] / l, -eye[2] / l]
    };
    // right = forward × world up = +x; up = right × forward.
    let right = [1.0, 0.0, 0.0f64];
    let up = [0.0, -f[2], f[1]];
    let scale = 120.0 / (0.45f64).tan();
    let project = |p: [f32; 3]| {
        let d = [0, 1, 2].map(|k| f64::from(p[k]) - eye[k]);
        let z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
        let x = d[0] * right[0] + d[1] * right[1] + d[2] * right[2];
        let y = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
        (x / z * scale, y / z * scale)
    };
    let (mut area, mut front) = (0.0, 0);
    for t in mesh.indices {
        let [a, b, c] = t.map(|k| project(mesh.positions[usize::from(k)]));
        let twice = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        if twice > 0.0 {
            area += twice / 2.0;
            front += 1;
        }
    }
    (area / front.max(1) as f64, front)
}

#[allow(dead_code)]
fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let [flag, along, around] = &args[..] {
        if flag == "--obj" {
            let n = |a: &str| a.parse::<usize>().map_err(|e| format!("{a}: {e}"));
            print!("{}", obj_text(n(along)?, n(around)?));
            return Ok(());
        }
    }
    let k = knot()?;
    let (ppt, front) = pixels_per_triangle(&k.mesh());
    let n = k.f32.meshlets.len() as f64;
    let mean = |f: &dyn Fn(&Meshlet) -> f64| k.f32.meshlets.iter().map(f).sum::<f64>() / n;
    let src = rust_source(&k);
    eprintln!(
        "gen_bench_mesh: {} vertices, {} triangles, {} clusters ({:.1} vertices, {:.1} triangles, radius {:.4} on average; mesh radius {:.4}); {front} front-facing triangles at {ppt:.2} px each; {} bytes",
        k.positions.len(),
        k.indices.len(),
        k.f32.meshlets.len(),
        mean(&|c| f64::from(c.vertex_count)),
        mean(&|c| f64::from(c.triangle_count)),
        mean(&|c| f64::from(c.sphere.1)),
        k.f32.sphere.1,
        src.len()
    );
    print!("{src}");
    Ok(())
}
