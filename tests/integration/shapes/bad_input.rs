//! Bad shape, style and gradient input is a typed error.

use super::fill;
use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
use microraster::Error;
use microraster::shape::{
    Arc, Circle, Ellipse, LinearGradient, Polygon, Polyline, RadialGradient, Rect, RoundedRect, Sector,
    Shape, ShapeStyle,
};

#[test]
fn bad_input_is_a_typed_error() {
    let nan = f32::NAN;
    assert_eq!(Circle::new((nan, 0.0), 1.0), Err(Error::NonFiniteCoordinate));
    assert_eq!(Circle::new((0.0, 0.0), -1.0), Err(Error::InvalidParameter(microraster::Param::ShapeSize)));
    assert_eq!(Ellipse::new((0.0, 0.0), 1.0, f32::INFINITY), Err(Error::NonFiniteCoordinate));
    assert_eq!(Rect::new(0.0, 0.0, 1.0, -2.0), Err(Error::InvalidParameter(microraster::Param::ShapeSize)));
    assert_eq!(Arc::new((0.0, 0.0), 1.0, nan, 1.0), Err(Error::NonFiniteCoordinate));
    assert_eq!(
        Sector::new((0.0, 0.0), -0.5, 0.0, 1.0),
        Err(Error::InvalidParameter(microraster::Param::ShapeSize))
    );
    assert_eq!(Polygon::new(&[(0.0, 0.0), (nan, 1.0)]), Err(Error::NonFiniteCoordinate));
    assert_eq!(Polyline::new(&[(0.0, 0.0), (1.0, nan)]), Err(Error::NonFiniteCoordinate));
    let rect = Rect::new(0.0, 0.0, 4.0, 4.0).unwrap();
    assert_eq!(RoundedRect::new(rect, nan), Err(Error::NonFiniteCoordinate));
    let line = Polyline::new(&[(0.0, 0.0), (9.0, 3.0)]).unwrap();
    assert_eq!(
        line.styled(ShapeStyle::stroke(Gray8::WHITE, -1.0)).err(),
        Some(Error::InvalidParameter(microraster::Param::StrokeWidth))
    );
    assert_eq!(line.styled(ShapeStyle::stroke(Gray8::WHITE, nan)).err(), Some(Error::NonFiniteCoordinate));
    let mut bad_miter = ShapeStyle::stroke(Gray8::WHITE, 1.0);
    bad_miter.miter_limit = 0.5;
    assert_eq!(line.styled(bad_miter).err(), Some(Error::InvalidParameter(microraster::Param::MiterLimit)));
    let far = Polygon::new(&[(0.0, 0.0), (3e7, 0.0), (0.0, 5.0)]).unwrap();
    assert_eq!(far.styled(fill()).err(), Some(Error::CoordinateOutOfRange));
    // More edges than MAX_EDGES.
    let zigzag: Vec<(f32, f32)> = (0..400).map(|i| (i as f32 * 0.1, (i % 2) as f32 * 5.0)).collect();
    assert_eq!(Polygon::new(&zigzag).unwrap().styled(fill()).err(), Some(Error::BufferTooSmall));
    assert!(Polygon::new(&zigzag[..200]).unwrap().styled(fill()).is_ok());
    // Gradients: NaN or infinity anywhere, a zero-length axis, a radius that is not positive.
    let c = [Gray8::BLACK, Gray8::WHITE];
    assert_eq!(LinearGradient::new((nan, 0.0), (1.0, 0.0), c), Err(Error::NonFiniteCoordinate));
    assert_eq!(LinearGradient::new((0.0, 0.0), (1.0, f32::INFINITY), c), Err(Error::NonFiniteCoordinate));
    // Finite ends whose squared distance overflows.
    assert_eq!(LinearGradient::new((-3e38, 0.0), (3e38, 0.0), c), Err(Error::NonFiniteCoordinate));
    assert_eq!(
        LinearGradient::new((2.0, 3.0), (2.0, 3.0), c),
        Err(Error::InvalidParameter(microraster::Param::Gradient))
    );
    assert!(LinearGradient::new((2.0, 3.0), (2.0, 3.5), c).is_ok());
    assert_eq!(RadialGradient::new((0.0, nan), 1.0, c), Err(Error::NonFiniteCoordinate));
    assert_eq!(RadialGradient::new((0.0, 0.0), f32::INFINITY, c), Err(Error::NonFiniteCoordinate));
    assert_eq!(
        RadialGradient::new((0.0, 0.0), 0.0, c),
        Err(Error::InvalidParameter(microraster::Param::Gradient))
    );
    assert_eq!(
        RadialGradient::new((0.0, 0.0), -2.0, c),
        Err(Error::InvalidParameter(microraster::Param::Gradient))
    );
    assert!(RadialGradient::new((0.0, 0.0), 1e-3, c).is_ok());
}
