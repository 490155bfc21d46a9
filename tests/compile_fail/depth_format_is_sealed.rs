// error: Sealed
// Depth formats are a closed set (NoDepth, Depth8/16/24/32).
use microraster::depth::DepthFormat;

struct Depth12;

impl DepthFormat for Depth12 {
    type Storage = u16;
    const BITS: u32 = 12;
    const ENABLED: bool = true;
    const MAX: u32 = 4095;
    const FAR: u16 = 4095;
    fn from_u32(v: u32) -> u16 {
        v.min(4095) as u16
    }
    fn to_u32(s: u16) -> u32 {
        u32::from(s)
    }
}

fn main() {}
