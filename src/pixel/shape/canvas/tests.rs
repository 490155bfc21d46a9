use super::*;
use crate::Band;
use crate::shape::{Circle, Polygon, Rect, RoundedRect, Shape, ShapeStyle};
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use embedded_graphics_core::prelude::*;
use embedded_graphics_core::primitives::Rectangle;

/// A 24 × 24 frame that counts its `fill_solid` calls.
struct Counting([[Gray8; 24]; 24], usize);
impl OriginDimensions for Counting {
    fn size(&self) -> Size {
        Size::new(24, 24)
    }
}
impl DrawTarget for Counting {
    type Color = Gray8;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, px: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            if let Some(q) = self.0.get_mut(p.y as usize).and_then(|r| r.get_mut(p.x as usize)) {
                *q = c;
            }
        }
        Ok(())
    }
    fn fill_solid(&mut self, r: &Rectangle, c: Gray8) -> Result<(), Self::Error> {
        self.1 += 1;
        self.fill_contiguous(r, core::iter::repeat(c))
    }
}

/// Partial pixels mixed over the background first (exact there, as
/// nothing is under them yet), then aliased shapes of several colours
/// overlapping: the pending rectangles keep the writes in order, so the
/// frame equals the band pixel for pixel.
#[test]
fn joined_rows_give_the_pixels_of_the_band() {
    let bg = Gray8::new(7);
    let rounded = RoundedRect::new(Rect::new(1.0, 1.0, 20.0, 14.0).unwrap(), 5.0).unwrap();
    let rect = Rect::new(2.0, 3.0, 9.0, 5.0).unwrap();
    let disc = Circle::new((12.0, 12.0), 9.5).unwrap();
    let tri = [(0.0, 0.0), (23.0, 4.0), (6.0, 22.0)];
    let mut frame = Counting([[bg; 24]; 24], 0);
    let mut band = Band::<Gray8, 24, 24>::new(bg);
    let mut view = band.view(0, 24, bg);
    let soft = rounded.styled(ShapeStyle::fill(Gray8::new(200)).antialiased()).unwrap();
    let card = rect.styled(ShapeStyle::fill(Gray8::WHITE)).unwrap();
    let ring = disc.styled(ShapeStyle::stroke(Gray8::new(90), 2.0)).unwrap();
    let wedge = Polygon::new(&tri).unwrap().styled(ShapeStyle::fill(Gray8::new(150))).unwrap();
    let mut canvas = TargetCanvas::new(&mut frame).over(bg);
    soft.draw_on(&mut canvas);
    card.draw_on(&mut canvas);
    ring.draw_on(&mut canvas);
    wedge.draw_on(&mut canvas);
    card.draw_on(&mut canvas);
    canvas.finish().unwrap();
    soft.draw_on(&mut view);
    card.draw_on(&mut view);
    ring.draw_on(&mut view);
    wedge.draw_on(&mut view);
    card.draw_on(&mut view);
    assert_eq!(frame.0, *band.rows());
    assert!(frame.0.iter().flatten().any(|&c| c != bg && c.luma() < 150 && c.luma() > 7));
}

#[test]
fn a_solid_rectangle_is_one_fill_solid_and_a_disc_one_per_run() {
    let bg = Gray8::BLACK;
    let mut frame = Counting([[bg; 24]; 24], 0);
    let card = Rect::new(2.0, 3.0, 9.0, 5.0).unwrap().styled(ShapeStyle::fill(Gray8::WHITE)).unwrap();
    card.draw_on(&mut TargetCanvas::new(&mut frame)); // dropped: flushed
    assert_eq!(frame.1, 1);
    let lit = frame.0.iter().flatten().filter(|&&c| c == Gray8::WHITE).count();
    assert_eq!(lit, 9 * 5);
    assert!(frame.0[3][2] == Gray8::WHITE && frame.0[7][10] == Gray8::WHITE && frame.0[8][10] == bg);
    // A disc: rows of equal spans merge, so fewer calls than rows.
    let mut frame = Counting([[bg; 24]; 24], 0);
    let disc = Circle::new((12.0, 12.0), 9.5).unwrap().styled(ShapeStyle::fill(Gray8::WHITE)).unwrap();
    let mut canvas = TargetCanvas::new(&mut frame);
    disc.draw_on(&mut canvas);
    canvas.finish().unwrap();
    let rows = frame.0.iter().filter(|r| r.contains(&Gray8::WHITE)).count();
    assert!(frame.1 < rows, "{} calls for {rows} rows", frame.1);
}
