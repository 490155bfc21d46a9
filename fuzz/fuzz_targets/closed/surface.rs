//! The closed surfaces the `closed` target draws: a tetrahedron, a deformed
//! cube, or the deformed cube with each face cut into `n × n` quads (enough
//! triangles for several meshlet clusters).

/// The tetrahedron's faces, wound one way round.
pub const TETRAHEDRON: [[u16; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// The faces of a cube with corners `x + 2y + 4z`, wound one way round:
/// face `f` is the quad `a b c d` of triangles `2f = [a, b, c]` and
/// `2f + 1 = [a, c, d]`.
pub const CUBE: [[u16; 3]; 12] = [
    [0, 2, 3],
    [0, 3, 1],
    [4, 5, 7],
    [4, 7, 6],
    [0, 1, 5],
    [0, 5, 4],
    [2, 6, 7],
    [2, 7, 3],
    [0, 4, 6],
    [0, 6, 2],
    [1, 3, 7],
    [1, 7, 5],
];

/// Largest `n` of [`subdivided_cube`]: `6n² + 2 = 602` vertices and
/// [`MAX_TRIANGLES`] triangles, at least ten clusters of 64 vertices.
pub const MAX_CUTS: usize = 10;
/// Most triangles of a mesh here: `12n²` for `n = MAX_CUTS`.
pub const MAX_TRIANGLES: usize = 12 * MAX_CUTS * MAX_CUTS;

/// The cube whose eight corners are `corners` (index `x + 2y + 4z`), each
/// face cut into `n × n` quads (`1 ≤ n ≤ MAX_CUTS`) of two triangles wound
/// as [`CUBE`]'s: positions and indices. A surface point is the trilinear
/// blend of the corners at its place on the unit cube, so points on a
/// shared edge depend only on that edge's two corners and the surface
/// stays closed however the corners lie (folded, flat or degenerate); each
/// grid point is one vertex, shared by its faces.
pub fn subdivided_cube(corners: &[[f32; 3]], n: usize) -> (Vec<[f32; 3]>, Vec<[u16; 3]>) {
    assert!(corners.len() == 8 && (1..=MAX_CUTS).contains(&n));
    let unit = |c: u16| [c & 1, (c >> 1) & 1, (c >> 2) & 1].map(usize::from);
    let side = n + 1;
    let mut index = vec![None::<u16>; side * side * side];
    let mut positions = Vec::new();
    let mut vertex = |g: [usize; 3], positions: &mut Vec<[f32; 3]>| -> u16 {
        *index[(g[2] * side + g[1]) * side + g[0]].get_or_insert_with(|| {
            let f = g.map(|k| k as f32 / n as f32);
            let mut p = [0.0f32; 3];
            for (c, q) in corners.iter().enumerate() {
                let w: f32 = (0..3).map(|a| if c >> a & 1 == 1 { f[a] } else { 1.0 - f[a] }).product();
                for a in 0..3 {
                    p[a] += w * q[a];
                }
            }
            positions.push(p);
            (positions.len() - 1) as u16
        })
    };
    let mut indices = Vec::new();
    for face in CUBE.chunks(2) {
        let [a, b, c] = face[0];
        debug_assert_eq!(face[1], [a, c, face[1][2]]);
        let (a, b, d) = (unit(a), unit(b), unit(face[1][2]));
        // Grid point (s, t) of the face: n·a + s·(b − a) + t·(d − a).
        let grid = |s: usize, t: usize| -> [usize; 3] {
            core::array::from_fn(|k| n * a[k] + s * b[k] + t * d[k] - (s + t) * a[k])
        };
        for s in 0..n {
            for t in 0..n {
                let q = [grid(s, t), grid(s + 1, t), grid(s + 1, t + 1), grid(s, t + 1)]
                    .map(|g| vertex(g, &mut positions));
                indices.push([q[0], q[1], q[2]]);
                indices.push([q[0], q[2], q[3]]);
            }
        }
    }
    (positions, indices)
}
