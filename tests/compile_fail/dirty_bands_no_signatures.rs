// error: DirtyBands needs room for at least one band signature
// Dirty-band skipping with room for no band at all.
use microraster::render::DirtyBands;

fn main() {
    let _ = DirtyBands::<(), 0>::new(());
}
