//! The knot's two cameras (issue 61): the standard scene's eye, where every
//! knot row stands, and the same eye twice as close, where the per-pixel
//! cost shows on its own. TGX was measured from both
//! (`docs/data/peers-tgx.tsv`). Shared by `examples/fw_bench`, the report
//! and the demo, so all three draw the same frames.

use microraster::Error;
use microraster::math::{Scalar, Vec3, transform};
use microraster::pipeline::{Pipeline, Shade};
use microraster::raster3d::Precision;
use microraster_scenes::scenes3d::Scene3d;

/// Where the camera stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Eye {
    /// The standard scene's eye (0, 1.9, 5.6), as every other knot row.
    Standard,
    /// Twice as close ([`CLOSE_EYE`]): about 3.6 times the covered pixels.
    Close,
}

/// The close camera's eye: the standard one halved, looking at the same
/// origin.
pub const CLOSE_EYE: [f32; 3] = [0.0, 0.95, 2.8];

/// The standard scene's pipeline ([`Scene3d::pipeline`]: lens, light,
/// Gouraud shading) seen from `eye`, in accuracy tier `precision`, for a
/// `width × height` frame with `S` subpixel bits.
pub fn pipeline<T: Scalar, const S: u32>(
    eye: Eye,
    precision: Precision,
    width: u32,
    height: u32,
) -> Result<Pipeline<T, S>, Error> {
    let p = match eye {
        Eye::Standard => Scene3d::pipeline::<T, S>(width, height)?,
        Eye::Close => {
            let f = T::from_f32;
            let [x, y, z] = CLOSE_EYE;
            let view = transform::look_at(
                Vec3::new(f(x), f(y), f(z)),
                Vec3::new(f(0.0), f(0.0), f(0.0)),
                Vec3::new(f(0.0), f(1.0), f(0.0)),
            )?;
            // Scene3d::pipeline's lens, light and shading.
            let mut p = Pipeline::perspective(view, f(0.9), f(1.0), f(20.0), width, height)?
                .with_lighting(Scene3d::lighting());
            p.shade = Shade::Gouraud;
            p
        }
    };
    Ok(p.with_precision(precision))
}
