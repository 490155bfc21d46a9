//! The f64 reference clipper of `clip3d_raster`, with a first-order bound
//! on how far the `f32` pipeline's vertices can be from its vertices.
//!
//! Same planes in the same order as the library's documentation states
//! (`w ≥ w_min`, near `z ≥ 0`, far `z ≤ w`, guard band `|x|, |y| ≤ g·w`), a
//! trivial reject when all vertices are outside one plane, Sutherland–Hodgman
//! cutting every edge from its inside end, the new vertex put exactly on its
//! plane. Error bounds (`u = 2^-24`, view = model = identity so `mvp = P`):
//! * transform: `x = fl(P00·x)`, `y = fl(P11·y)`, `z = fl(fl(P22·z) + P23)`,
//!   `w = −z` exact: errors `u|x|`, `u|y|`, `u(|P22·z| + |z|)`, 0;
//! * a cut of edge `a → b` (a inside) at plane distance `d`: `t = d_a/(d_a − d_b)`
//!   with `|δt| ≤ (e_da + e_db)/(|d_a| + |d_b|) + 3u` (`e_d` the distance's
//!   error: the components' errors plus `u` per rounded operation); each lerped
//!   component errs by `(1 − t)e_a + t·e_b + |b − a|·|δt| + 3u(|a| + |b|)`; the
//!   snapped component is exact (`z = 0`, `w = w_min`) or `fl(g·w)`;
//! * divide and viewport: `(W/2)·((e_x + |x/w|·e_w)/w + 2u|x/w|)` px.

/// Unit roundoff of `f32`.
const U: f64 = 1.0 / 16777216.0;

#[derive(Clone, Copy, Debug)]
pub struct V {
    /// Clip coordinates `[x, y, z, w]`.
    pub c: [f64; 4],
    /// Absolute error bound of each coordinate in the `f32` pipeline.
    pub e: [f64; 4],
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Plane {
    W,
    Near,
    Far,
    XNeg,
    XPos,
    YNeg,
    YPos,
}
const PLANES: [Plane; 7] =
    [Plane::W, Plane::Near, Plane::Far, Plane::XNeg, Plane::XPos, Plane::YNeg, Plane::YPos];

pub struct Ref {
    /// The projection (rows) from the pipeline's `f32` entries.
    pub m: [[f64; 4]; 4],
    pub g: f64,
    pub w_min: f64,
    pub far: bool,
}

impl Ref {
    /// Signed distance (≥ 0 inside) and its error bound.
    fn dist(&self, v: &V, p: Plane) -> (f64, f64) {
        let ([x, y, z, w], [ex, ey, ez, ew]) = (v.c, v.e);
        let g = self.g;
        let side = |c: f64, e: f64, s: f64| {
            (g * w + s * c, g * ew + U * g * w.abs() + e + U * (g * w + s * c).abs())
        };
        match p {
            Plane::W => (w - self.w_min, ew + U * (w - self.w_min).abs()),
            Plane::Near => (z, ez),
            Plane::Far => (w - z, ew + ez + U * (w - z).abs()),
            Plane::XNeg => side(x, ex, 1.0),
            Plane::XPos => side(x, ex, -1.0),
            Plane::YNeg => side(y, ey, 1.0),
            Plane::YPos => side(y, ey, -1.0),
        }
    }

    fn active(&self, p: Plane) -> bool {
        self.far || p != Plane::Far
    }

    pub fn vertex(&self, p: [f32; 3]) -> V {
        let p = [p[0] as f64, p[1] as f64, p[2] as f64, 1.0];
        let row = |r: usize| (0..4).map(|k| self.m[r][k] * p[k]).sum::<f64>();
        let c = [row(0), row(1), row(2), row(3)];
        let ez = U * ((self.m[2][2] * p[2]).abs() + c[2].abs());
        V { c, e: [U * c[0].abs(), U * c[1].abs(), ez, 0.0] }
    }

    fn cut(&self, a: &V, b: &V, p: Plane) -> V {
        let ((da, ea), (db, eb)) = (self.dist(a, p), self.dist(b, p));
        let t = da / (da - db);
        let dt = (ea + eb) / (da.abs() + db.abs()) + 3.0 * U;
        let mut v = V { c: [0.0; 4], e: [0.0; 4] };
        for i in 0..4 {
            v.c[i] = a.c[i] + t * (b.c[i] - a.c[i]);
            v.e[i] = (1.0 - t) * a.e[i]
                + t * b.e[i]
                + (b.c[i] - a.c[i]).abs() * dt
                + 3.0 * U * (a.c[i].abs() + b.c[i].abs());
        }
        let gw = |v: &V| (self.g * v.c[3], self.g * v.e[3] + U * (self.g * v.c[3]).abs());
        match p {
            Plane::W => (v.c[3], v.e[3]) = (self.w_min, 0.0),
            Plane::Near => (v.c[2], v.e[2]) = (0.0, 0.0),
            Plane::Far => (v.c[2], v.e[2]) = (v.c[3], v.e[3]),
            Plane::XNeg | Plane::XPos => {
                let (c, e) = gw(&v);
                (v.c[0], v.e[0]) = (if p == Plane::XNeg { -c } else { c }, e);
            }
            Plane::YNeg | Plane::YPos => {
                let (c, e) = gw(&v);
                (v.c[1], v.e[1]) = (if p == Plane::YNeg { -c } else { c }, e);
            }
        }
        v
    }

    /// The clipped polygon (empty if nothing is left).
    pub fn clip(&self, tri: [V; 3]) -> Vec<V> {
        let out = |v: &V, p| self.active(p) && self.dist(v, p).0 < 0.0;
        if PLANES.iter().any(|&p| tri.iter().all(|v| out(v, p))) {
            return Vec::new();
        }
        let mut poly = tri.to_vec();
        for p in PLANES.into_iter().filter(|&p| self.active(p)) {
            let mut next = Vec::new();
            for i in 0..poly.len() {
                let (prev, cur) = (poly[(i + poly.len() - 1) % poly.len()], poly[i]);
                let (pin, cin) = (self.dist(&prev, p).0 >= 0.0, self.dist(&cur, p).0 >= 0.0);
                if pin != cin {
                    next.push(if pin { self.cut(&prev, &cur, p) } else { self.cut(&cur, &prev, p) });
                }
                if cin {
                    next.push(cur);
                }
            }
            if next.len() < 3 {
                return Vec::new();
            }
            poly = next;
        }
        poly
    }

    /// Screen position and `f32` error bound per axis (px, snapping excluded)
    /// of a clipped vertex.
    pub fn screen(&self, v: &V, width: usize, height: usize) -> ((f64, f64), (f64, f64)) {
        let ([x, y, _, w], [ex, ey, _, ew]) = (v.c, v.e);
        let (hw, hh) = (width as f64 / 2.0, height as f64 / 2.0);
        let (nx, ny) = (x / w, y / w);
        let err = |h: f64, e: f64, n: f64| h * ((e + n.abs() * ew) / w + 2.0 * U * n.abs());
        ((hw * (1.0 + nx), hh * (1.0 - ny)), (err(hw, ex, nx), err(hh, ey, ny)))
    }
}

/// `min over s ∈ [0, 1] of |c − r(s)| − δ(s)` along the edge `r(s)` from
/// `a` to `b`, with `δ` interpolated linearly between the vertices' bounds
/// (convex in `s`: ternary search), and `δ` at the minimum. A centre can
/// change sides only where this is ≤ 0 for some edge: the boundary point
/// `r(s)` moves by at most `δ(s)` when the vertices move by their bounds.
pub fn slack(c: (f64, f64), (a, da): ((f64, f64), f64), (b, db): ((f64, f64), f64)) -> (f64, f64) {
    let f = |s: f64| {
        let r = (a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1));
        let d = da + s * (db - da);
        ((c.0 - r.0).hypot(c.1 - r.1) - d, d)
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..100 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if f(m1).0 <= f(m2).0 { hi = m2 } else { lo = m1 }
    }
    f(0.5 * (lo + hi))
}

/// Strictly inside the convex polygon `p` (either orientation)?
pub fn inside(p: &[(f64, f64)], q: (f64, f64)) -> bool {
    let e: Vec<f64> = (0..p.len())
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            (b.0 - a.0) * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0)
        })
        .collect();
    e.iter().all(|&v| v > 0.0) || e.iter().all(|&v| v < 0.0)
}
