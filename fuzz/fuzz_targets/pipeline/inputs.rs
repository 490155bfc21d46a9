//! Fuzzer bytes to the pipeline's inputs: vectors, moderate-or-extreme
//! values and matrices, on the `f32` or `Fx` path.

use microraster::math::{Mat4, Scalar, Vec3};
use microraster_fuzz::Input;

pub(super) fn vec3<T: Scalar>(inp: &mut Input) -> ([f32; 3], Vec3<T>) {
    let v = [inp.f32(), inp.f32(), inp.f32()];
    (v, Vec3::from_f32(v))
}

pub(super) fn small(inp: &mut Input) -> f32 {
    // Mostly moderate values so that something is visible; sometimes extreme.
    if inp.u8().is_multiple_of(8) { inp.f32() } else { (inp.u8() as i8) as f32 / 16.0 }
}

pub(super) fn matrix<T: Scalar>(inp: &mut Input) -> Mat4<T> {
    let mut m = [[0.0f32; 4]; 4];
    for c in &mut m {
        for e in c.iter_mut() {
            *e = small(inp);
        }
    }
    Mat4::from_f32(m)
}
