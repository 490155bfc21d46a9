//! The clipper's output invariants for any input.

use super::{clip_w, rare_wild, wild};
use crate::props::{Tally, runner};
use microraster::clip3d::{ClipPlanes, ClipVertex, clip_line, clip_triangle};
use microraster::math::{Fx, Scalar};
use proptest::prelude::*;

fn planes() -> impl Strategy<Value = ClipPlanes> {
    prop_oneof![
        2 => Just(ClipPlanes::DEFAULT),
        1 => Just(ClipPlanes::NO_FAR),
        1 => wild().prop_map(|g| ClipPlanes::DEFAULT.with_guard_band(g)),
        1 => wild().prop_map(|w| ClipPlanes::DEFAULT.with_w_min(w)),
        1 => (1u32..4096, 1u32..4096, 0u32..9).prop_map(|(w, h, s)| ClipPlanes::for_viewport(w, h, s)),
    ]
}

/// The documented guarantees of a clipped vertex, evaluated in `T`.
fn vertex_ok<T: Scalar>(v: &[T; 4], p: ClipPlanes) -> bool {
    let w_min = T::from_f32(p.w_min());
    let w_min = if w_min > T::ZERO { w_min } else { T::from_f32(ClipPlanes::W_MIN) };
    let gw = T::from_f32(p.guard_band()) * v[3];
    v.iter().all(|c| c.is_finite())
        && v[3] >= w_min
        && v[2] >= T::ZERO
        && (!p.far() || v[2] <= v[3])
        && v[0] <= gw
        && -gw <= v[0]
        && v[1] <= gw
        && -gw <= v[1]
}

fn check_clip<T: Scalar>(
    pos: [[f32; 4]; 3],
    attr: [f32; 3],
    p: ClipPlanes,
    tally: &Tally,
) -> Result<(), TestCaseError> {
    let v: [ClipVertex<T, 1>; 3] =
        core::array::from_fn(|i| ClipVertex { pos: pos[i].map(T::from_f32), attr: [T::from_f32(attr[i])] });
    let invalid = pos.iter().flatten().chain(&attr).any(|c| !c.is_finite() || c.abs() > 1.8446744e19);
    let poly = clip_triangle(v, p);
    let n = poly.vertices().len();
    prop_assert!(n == 0 || (3..=10).contains(&n), "{} vertices", n);
    if invalid && T::from_f32(f32::NAN).to_f32().is_nan() {
        prop_assert!(poly.is_empty(), "invalid input not discarded");
        tally.add("invalid → empty");
    }
    for x in poly.vertices() {
        prop_assert!(vertex_ok(&x.pos, p), "vertex {:?} breaks the guarantees of {:?}", x.pos, p);
        prop_assert!(x.attr.iter().all(|a| a.is_finite()));
    }
    if pos.iter().all(|q| q[3] < 0.0) {
        prop_assert!(poly.is_empty(), "a triangle behind the eye survived");
        tally.add("behind → empty");
    }
    tally.add(if poly.is_empty() {
        "empty"
    } else if n == 3 {
        "3 vertices"
    } else {
        "clipped"
    });
    prop_assert_eq!(poly.triangles().count(), n.saturating_sub(2));
    // clip_line on the first edge: same guarantees.
    if let Some((a, b)) = clip_line(v[0], v[1], p) {
        prop_assert!(vertex_ok(&a.pos, p) && vertex_ok(&b.pos, p), "clip_line {:?} {:?}", a.pos, b.pos);
    }
    Ok(())
}

#[test]
fn prop_clipper_output_invariants() {
    let mild = (-4.0f32..4.0, -4.0f32..4.0, -0.5f32..1.5, clip_w())
        .prop_map(|(x, y, z, w)| [x * w.abs().max(1.0), y * w.abs().max(1.0), z * w, w]);
    let vert =
        prop_oneof![8 => mild, 1 => (wild(), wild(), wild(), clip_w()).prop_map(|(x, y, z, w)| [x, y, z, w])];
    let strat = ([vert.clone(), vert.clone(), vert], [rare_wild(), rare_wild(), rare_wild()], planes());
    for (name, fx) in [("f32", false), ("Fx", true)] {
        let tally = Tally::default();
        runner(6000)
            .run(&strat, |(pos, attr, p)| {
                if fx {
                    check_clip::<Fx>(pos, attr, p, &tally)
                } else {
                    check_clip::<f32>(pos, attr, p, &tally)
                }
            })
            .unwrap();
        tally.report(&format!("props3d: clipper invariants, {name}"));
        assert!(
            tally.get("clipped") >= 600
                && tally.get("behind → empty") >= 100
                && tally.get("3 vertices") >= 300,
            "{name}"
        );
        assert!(fx || tally.get("invalid → empty") >= 300, "{name}");
    }
}
