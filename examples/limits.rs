//! Prints the documented limits: coordinate range and fast-path extent per
//! subpixel setting, and band memory for common displays. The README's tables
//! are this program's output: `cargo run --example limits`.

use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
use microraster::depth::{Depth8, Depth16, Depth24, Depth32, DepthBand, NoDepth};
use microraster::edge::fast_path_extent_px;
use microraster::raster3d::ScreenTriangle;
use microraster::{Band, MAX_FRAME_DIM, SubPoint};
use microraster_scenes::scenes3d::{BINS, Scene3d};

fn main() {
    println!(
        "| subpixel bits S | resolution (px) | coordinate range (px) | i32 fast path: triangle extent up to (px) |"
    );
    println!("|---|---|---|---|");
    macro_rules! row {
        ($($s:literal),*) => {$(
            let range = SubPoint::<$s>::MAX_SUBPIXELS / SubPoint::<$s>::ONE;
            println!("| {} | 1/{} | ±{} | {} |", $s, 1u32 << $s, range, fast_path_extent_px($s));
        )*};
    }
    row!(0, 1, 2, 3, 4, 5, 6, 7, 8);
    println!("\nFrames and bands: 1 to {MAX_FRAME_DIM} px in each direction.\n");
    println!("| display | colour | band rows | band bytes | full framebuffer, same pixel storage |");
    println!("|---|---|---|---|---|");
    macro_rules! band {
        ($w:literal x $h:literal, $c:ty, $rows:literal) => {
            println!(
                "| {}×{} | {} | {} | {} | {} |",
                $w,
                $h,
                stringify!($c),
                $rows,
                Band::<$c, $w, $rows>::BYTES,
                $w * $h * core::mem::size_of::<$c>()
            );
        };
    }
    band!(160 x 128, Rgb565, 8);
    band!(240 x 240, Rgb565, 16);
    band!(320 x 240, Rgb565, 16);
    band!(320 x 240, Rgb888, 16);
    band!(320 x 240, Gray8, 32);
    band!(480 x 320, Rgb565, 16);

    println!("\nColour + depth per 320-wide, 16-row band:\n");
    println!("| colour | depth | colour bytes | depth bytes | band total |");
    println!("|---|---|---|---|---|");
    macro_rules! cd {
        ($c:ty, $d:ty) => {
            let (c, d) = (Band::<$c, 320, 16>::BYTES, DepthBand::<$d, 320, 16>::BYTES);
            println!("| {} | {} | {} | {} | {} |", stringify!($c), stringify!($d), c, d, c + d);
        };
    }
    cd!(Rgb565, NoDepth);
    cd!(Rgb565, Depth8);
    cd!(Rgb565, Depth16);
    cd!(Rgb565, Depth24);
    cd!(Rgb565, Depth32);
    cd!(Rgb888, Depth16);
    cd!(Gray8, Depth16);
    let (c, d) = (Band::<Rgb565, 320, 16>::BYTES, DepthBand::<Depth16, 320, 16>::BYTES);
    let tri = core::mem::size_of::<ScreenTriangle<4>>();
    let bins = tri * BINS;
    let flash: usize =
        Scene3d::new().meshes().iter().map(|m| m.vertex_count() * 24 + m.triangle_count() * 6).sum();
    let full = 320 * 240 * 2;
    println!("\nWorked example: 320×240 Rgb565, 16-bit depth, 16-row bands, the standard 3D scene:");
    println!("- colour band {c} B + depth band {d} B = {} B", c + d);
    println!("- bins: {BINS} screen triangles × {tri} B = {bins} B");
    println!("- meshes: {flash} B of flash (statics), no RAM");
    println!(
        "- total {} B, against {full} B for one full Rgb565 framebuffer ({}% of it) and {} B with a full 16-bit z-buffer",
        c + d + bins,
        (c + d + bins) * 100 / full,
        full * 2
    );
}
