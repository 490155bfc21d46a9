// temporary probe (not committed)
#[path = "../benches/common/mod.rs"]
mod common;
#[path = "../benches/common/knot.rs"]
mod knot;
#[path = "common/knot_mesh.rs"]
mod knot_mesh;
use common::*;
use microraster::Band;
use microraster::depth::{Depth16, DepthBand};
use microraster::pipeline::ClusterCache;
use microraster::raster3d::{Affine, PerspectiveCorrect};
fn main() {
    let n: usize = std::env::args().nth(1).unwrap().parse().unwrap();
    let persp = std::env::args().nth(2).is_some();
    let p = pipeline3d::<f32, 4>();
    let mut cache = ClusterCache::<f32, 4>::new();
    let mut band = Box::new(Band::<_, W, 16>::new(BG3));
    let mut depth = Box::new(DepthBand::<Depth16, W, 16>::new());
    let mut slice = SliceFb::default();
    for _ in 0..n {
        if persp {
            knot::mr_knot::<f32, PerspectiveCorrect>(&p, &mut cache, &mut band, &mut depth, &mut slice);
        } else {
            knot::mr_knot::<f32, Affine>(&p, &mut cache, &mut band, &mut depth, &mut slice);
        }
    }
    let t = std::time::Instant::now();
    for _ in 0..(if n > 0 { 50 } else { 0 }) {
        knot::mr_knot::<f32, PerspectiveCorrect>(&p, &mut cache, &mut band, &mut depth, &mut slice);
    }
    if n > 0 {
        println!("{:?}", t.elapsed() / 50);
    }
}
