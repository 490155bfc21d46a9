extern crate std;
use super::*;
use crate::shape::flatten::arc_edges;

/// A rounded rectangle's contour as four independent `arc_edges` calls,
/// each computing its own chord count, step and end angles: what
/// `RoundedRect::contour` shares between its corners must give the same
/// values.
fn reference<const N: usize>(
    rr: &RoundedRect,
    e: &mut EdgeList<N>,
    d: f32,
    reverse: bool,
) -> Result<(), Error> {
    let Rect { x, y, w, h } = rr.rect;
    let r = (rr.r + d).max(0.0);
    let (x0, y0, x1, y1) = (x - d, y - d, x + w + d, y + h + d);
    if x1 <= x0 || y1 <= y0 {
        return Ok(());
    }
    let centres = [
        (x1 - r, y0 + r, -FRAC_PI_2),
        (x1 - r, y1 - r, 0.0),
        (x0 + r, y1 - r, FRAC_PI_2),
        (x0 + r, y0 + r, PI),
    ];
    e.close()?;
    for k in 0..4 {
        let (cx, cy, a) = centres[if reverse { 3 - k } else { k }];
        let (start, sweep) = if reverse { (a + FRAC_PI_2, -FRAC_PI_2) } else { (a, FRAC_PI_2) };
        arc_edges(e, (cx, cy), (r, r), start, sweep)?;
    }
    e.close()
}

#[test]
fn rounded_corners_share_their_steps_without_moving_a_point() {
    let mut rng = crate::test_rng::Rng(0x2026_1207_0000_0042);
    for case in 0..3_000 {
        let (x, y) = (rng.unit(400.0) - 100.0, rng.unit(400.0) - 100.0);
        let (w, h) = (rng.unit(300.0), rng.unit(200.0));
        let radius = [rng.unit(60.0), 0.0, 1e-3, 1e4][case % 4];
        let rr = RoundedRect::new(Rect::new(x, y, w, h).unwrap(), radius).unwrap();
        let d = [0.0, rng.unit(8.0), -rng.unit(8.0)][case % 3];
        let reverse = case % 2 == 1;
        // Whole lists, and windowed ones (which cull chords).
        let win = [None, Some((rng.in_range(4000) as i32, 0))][case % 2].map(|(lo, _)| (lo, lo + 256));
        let (mut a, mut b) = (EdgeList::<256>::new(), EdgeList::<256>::new());
        if let Some((lo, hi)) = win {
            a.window(lo, hi);
            b.window(lo, hi);
        }
        let (ra, rb) = (rr.contour(&mut a, d, reverse), reference(&rr, &mut b, d, reverse));
        assert_eq!(ra, rb, "case {case}");
        assert_eq!(a.edges(), b.edges(), "case {case}: {rr:?} d {d} reverse {reverse} window {win:?}");
    }
}
