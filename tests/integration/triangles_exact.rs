//! `TriangleSpans` must equal the brute-force exact reference on every pixel:
//! ≥ 100,000 random triangles for each `S` in `0..=8`, on a 64×48 screen with
//! random sub-clips, through both the `i32` and the `i64` path, and with each
//! cull mode dropping exactly one winding.

use crate::reference::{
    ExactTriangle, Rng, TieRule, coverage_and_ties, culled, exact_coverage, random_clip, random_triangle,
    spans_coverage,
};
use microraster::edge::{Cull, TriangleSpans, fast_path_extent_px};
use microraster::{ClipRect, SubPoint};

const W: i32 = 64;
const H: i32 = 48;
const CASES: usize = 100_000;

fn describe<const S: u32>(v: &[SubPoint<S>; 3], clip: ClipRect) -> String {
    let pts: Vec<_> = v.iter().map(|p| (p.x(), p.y())).collect();
    format!("S={S} SubPoint::new {pts:?} {clip:?}")
}

#[derive(Default, Debug)]
struct Counts {
    triangles: usize,
    covered_pixels: usize,
    /// Centres exactly on an edge (and inside the other two): decided by the tie rule.
    tie_pixels: usize,
    empty: usize,
    fast: usize,
    /// Not on the fast path, yet drawing pixels: the `i64` path.
    wide_drawn: usize,
    /// Bounding box larger than `fast_path_extent_px + 1` with pixels, by the reference.
    wide_expected: usize,
    cull_checked: [usize; 2],
}

fn check_exact<const S: u32>(cases: usize) -> Counts {
    let mut rng = Rng::new(0x5eed_0000 + S as u64);
    let mut n = Counts::default();
    let fast_px = fast_path_extent_px(S);
    for _ in 0..cases {
        let v = random_triangle::<S>(&mut rng, W, H);
        let clip = random_clip(&mut rng, W, H);
        let spans = TriangleSpans::new(v, clip, Cull::None);
        let fast = spans.is_fast_path();
        let got = spans_coverage(spans, clip);
        let (want, ties) = coverage_and_ties(v, clip, Cull::None, TieRule::TopLeft);
        n.tie_pixels += ties;
        if let Some((x, y, g, w)) = got.first_difference(&want) {
            panic!("{}: pixel ({x}, {y}) spans={g} reference={w}", describe(&v, clip));
        }
        n.triangles += 1;
        let count = want.count();
        n.covered_pixels += count;

        // Fast-path documentation: a bbox side ≤ fast_path_extent_px(S) px takes it,
        // one more than a pixel beyond cannot.
        let side = |f: fn(SubPoint<S>) -> i32| {
            let c = v.map(|p| f(p) as i64);
            c.iter().max().unwrap() - c.iter().min().unwrap()
        };
        let side = side(SubPoint::x).max(side(SubPoint::y));
        let one = 1i64 << S;
        if count > 0 && side <= fast_px * one {
            assert!(fast, "{}: bbox fits the fast path but took the wide one", describe(&v, clip));
        }
        if side > (fast_px + 1) * one {
            assert!(!fast, "{}: bbox too big for i32 but took the fast path", describe(&v, clip));
            n.wide_expected += (count > 0) as usize;
        }
        n.fast += fast as usize;
        n.wide_drawn += (!fast && count > 0) as usize;
        n.empty += (count == 0) as usize;

        // Culling: the reference decides the winding from its own signed area.
        let mut drawn = Vec::new();
        for cull in [Cull::Clockwise, Cull::CounterClockwise] {
            let got_c = spans_coverage(TriangleSpans::new(v, clip, cull), clip);
            let want_c = exact_coverage(v, clip, cull);
            if let Some((x, y, g, w)) = got_c.first_difference(&want_c) {
                panic!("{} {cull:?}: pixel ({x}, {y}) spans={g} reference={w}", describe(&v, clip));
            }
            drawn.push(!got_c.is_empty());
            if count > 0 && !got_c.is_empty() {
                assert!(got_c == got, "{} {cull:?} changed the pixels", describe(&v, clip));
            }
        }
        if count > 0 {
            assert!(drawn[0] != drawn[1], "{}: cull modes must drop exactly one winding", describe(&v, clip));
            n.cull_checked[drawn[0] as usize] += 1; // [clockwise, counter-clockwise] triangles
            let t = ExactTriangle::new(v).unwrap();
            assert_eq!(culled(Cull::Clockwise, t.clockwise), !drawn[0]);
        }
    }
    println!(
        "exact S={S}: {} triangles, {} covered pixels, {} tie pixels, {} empty, fast path {}, wide path drawing {} \
         (reference expects ≥ {} wide), cull checked cw/ccw {:?}",
        n.triangles,
        n.covered_pixels,
        n.tie_pixels,
        n.empty,
        n.fast,
        n.wide_drawn,
        n.wide_expected,
        n.cull_checked
    );
    assert_eq!(n.triangles, cases);
    // The generator aims ~3/16 of triangles at the i64 path, most others at i32,
    // and a third of all sizes are below a pixel (mostly empty).
    assert!(n.wide_expected >= cases / 20, "too few wide-path triangles: {n:?}");
    assert!(n.wide_drawn >= n.wide_expected, "{n:?}");
    assert!(n.fast >= cases / 5, "too few fast-path triangles: {n:?}");
    assert!(n.cull_checked.iter().all(|&c| c >= cases / 8), "{n:?}");
    assert!(n.covered_pixels >= cases, "{n:?}");
    // Grid-aligned kinds put many centres exactly on edges.
    assert!(n.tie_pixels >= cases / 10, "too few tie decisions: {n:?}");
    n
}

macro_rules! exact_tests {
    ($($name:ident => $s:literal),* $(,)?) => {$(
        #[test]
        fn $name() {
            check_exact::<$s>(CASES);
        }
    )*};
}

exact_tests!(
    exact_s0 => 0, exact_s1 => 1, exact_s2 => 2, exact_s3 => 3, exact_s4 => 4,
    exact_s5 => 5, exact_s6 => 6, exact_s7 => 7, exact_s8 => 8,
);

/// Hand-checked ties, so a reference bug cannot hide behind an identical one.
#[test]
fn exact_reference_known_ties() {
    let p = |x, y| SubPoint::<1>::new(x, y).unwrap(); // half pixels
    let clip = ClipRect::new(0, 0, 8, 8);
    // The square (0.5,0.5)-(4.5,4.5) as two triangles has centres on all four
    // edges and the diagonal: covered on the top and left ones only, i.e.
    // columns 0..4 and rows 0..4, and the diagonal exactly once.
    let (a, b, c, d) = (p(1, 1), p(9, 1), p(9, 9), p(1, 9));
    for tri in [[a, b, c], [a, c, d], [a, c, b], [a, d, c]] {
        let cov = exact_coverage(tri, clip, Cull::None);
        let spans = spans_coverage(TriangleSpans::new(tri, clip, Cull::None), clip);
        assert!(cov == spans);
    }
    let mut both = exact_coverage([a, b, c], clip, Cull::None);
    for (x, y) in exact_coverage([a, c, d], clip, Cull::None).pixels() {
        assert!(!both.set(x, y), "shared diagonal covered twice at ({x}, {y})");
    }
    let want: Vec<_> = (0..4).flat_map(|y| (0..4).map(move |x| (x, y))).collect();
    assert_eq!(both.pixels().collect::<Vec<_>>(), want);
    // Screen-clockwise (y down) triangle: dropped by Cull::Clockwise only.
    let cw = [p(0, 0), p(8, 0), p(0, 8)];
    assert!(exact_coverage(cw, clip, Cull::Clockwise).is_empty());
    // x + y < 4 at centres, the hypotenuse (a right edge) excluded: X + Y ≤ 2.
    assert_eq!(exact_coverage(cw, clip, Cull::CounterClockwise).count(), 6);
}
