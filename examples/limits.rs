//! Prints the documented limits: coordinate range and fast-path extent per
//! subpixel setting, and band memory for common displays. The README's tables
//! are this program's output: `cargo run --example limits`.

use embedded_graphics_core::pixelcolor::{Gray8, Rgb565, Rgb888};
use microraster::edge::fast_path_extent_px;
use microraster::{Band, MAX_FRAME_DIM, SubPoint};

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
}
