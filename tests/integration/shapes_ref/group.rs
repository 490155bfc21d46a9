//! Anti-aliased shapes sharing an edge (issue #60, item 6): drawn one after
//! the other they leave a dark seam (source-over blends the second over the
//! first's partial pixel); drawn as one `Group` the coverages are summed
//! before the blend and the seam is white.

use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::Band;
use microraster::shape::{Group, Polygon, Rect, Sector, Shape, ShapeStyle};

const W: usize = 40;
const H: usize = 40;

fn style() -> ShapeStyle<Gray8, microraster::shape::AntiAliased> {
    ShapeStyle::fill(Gray8::WHITE).antialiased()
}

/// Lumas of a 40 × 40 black band after `draw`.
fn frame(draw: impl FnOnce(&mut microraster::band::BandView<'_, Gray8, W>)) -> Vec<u8> {
    let mut band = Band::<Gray8, W, H>::new(Gray8::BLACK);
    draw(&mut band.view(0, H, Gray8::BLACK));
    band.rows().iter().flat_map(|r| r.iter().map(|c| c.luma())).collect()
}

fn separately<S: Shape + Copy>(members: &[S]) -> Vec<u8> {
    frame(|v| members.iter().for_each(|m| m.styled(style()).unwrap().draw_on(v)))
}

fn grouped<S: Shape>(members: &[S]) -> Vec<u8> {
    frame(|v| Group::new(members).styled(style()).unwrap().draw_on(v))
}

#[test]
fn a_vertical_seam_is_white_in_a_group() {
    for x in [10.5f32, 10.25, 10.1] {
        let halves =
            [Rect::new(2.0, 3.0, x - 2.0, 20.0).unwrap(), Rect::new(x, 3.0, 20.0 - x, 20.0).unwrap()];
        let whole = frame(|v| Rect::new(2.0, 3.0, 18.0, 20.0).unwrap().styled(style()).unwrap().draw_on(v));
        let (apart, group) = (separately(&halves), grouped(&halves));
        for y in 3..23 {
            // The seam pixel is column 10 for every x.
            let i = y * W + 10;
            assert!(apart[i] < 255, "x = {x}: drawn apart the seam was expected dark, got {}", apart[i]);
            assert_eq!(group[i], 255, "x = {x}, row {y}: the group's seam");
        }
        assert_eq!(group, whole, "x = {x}: the group is the whole bar");
    }
}

#[test]
fn a_diagonal_seam_is_white_in_a_group() {
    // A square split on its diagonal, the halves wound opposite ways.
    let (a, b, c, d) = ((4.0, 4.25), (33.5, 4.25), (33.5, 35.0), (4.0, 35.0));
    let (abc, adc) = ([a, b, c], [a, d, c]);
    let halves = [Polygon::new(&abc).unwrap(), Polygon::new(&adc).unwrap()];
    let whole = frame(|v| Polygon::new(&[a, b, c, d]).unwrap().styled(style()).unwrap().draw_on(v));
    let (apart, group) = (separately(&halves), grouped(&halves));
    let inside = |i: usize| (5..33).contains(&(i % W)) && (5..34).contains(&(i / W));
    let dark = (0..W * H).filter(|&i| inside(i) && apart[i] < 255).count();
    assert!(dark >= 18, "drawn apart: {dark} dark pixels on the diagonal");
    assert!((0..W * H).filter(|&i| inside(i)).all(|i| group[i] == 255), "the group's diagonal");
    assert_eq!(group, whole);
}

#[test]
fn pie_sectors_in_a_group_have_no_seams() {
    let (c, r) = ((20.0, 20.0), 16.0);
    let cuts = [0.0f32, 1.1, 2.05, 3.7, 5.0, std::f32::consts::TAU];
    let pie: Vec<Sector> = cuts.windows(2).map(|w| Sector::new(c, r, w[0], w[1] - w[0]).unwrap()).collect();
    let (apart, group) = (separately(&pie), grouped(&pie));
    // Pixels wholly inside the disc (corners within r − 0.1 of the centre).
    let inside = |i: usize| {
        let (x, y) = ((i % W) as f32, (i / W) as f32);
        [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
            .iter()
            .all(|d: &(f32, f32)| ((x + d.0 - c.0).powi(2) + (y + d.1 - c.1).powi(2)).sqrt() < r - 0.1)
    };
    assert!((0..W * H).filter(|&i| inside(i)).any(|i| apart[i] < 255), "drawn apart, no seam");
    let dark: Vec<usize> = (0..W * H).filter(|&i| inside(i) && group[i] < 255).collect();
    assert!(dark.is_empty(), "grouped, dark pixels inside the disc: {dark:?}");
}
