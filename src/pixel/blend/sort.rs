//! Back-to-front ordering of whole transparent meshes.

use crate::math::{Mat4, Scalar, Vec3};
use crate::mesh::Mesh;

/// Sorts `items` farthest first by `depth` (larger = farther, e.g. from
/// [`view_depth`]), in place and without allocating (`core`'s unstable sort:
/// `O(n log n)`; items with equal depth end up in an unspecified but
/// deterministic order).
///
/// `depth` is called O(n log n) times; for costly depths, sort pairs of
/// `(item, depth)` computed once. Depths compare by [`f32::total_cmp`], so
/// NaN never disturbs the sort (a positive NaN counts as farthest).
///
/// Ordering whole meshes is all a per-mesh sort can do: where transparent
/// surfaces overlap (interpenetrating meshes, or a mesh seen through its own
/// back faces), blending stays order-dependent. Draw these meshes after every
/// opaque mesh, with
/// [`DepthState::READ_ONLY`](crate::depth::DepthState::READ_ONLY).
///
/// ```
/// use microraster::blend::back_to_front;
/// let mut meshes = [("near", 2.0f32), ("far", 9.5), ("middle", 4.0)];
/// back_to_front(&mut meshes, |m| m.1);
/// assert_eq!(meshes.map(|m| m.0), ["far", "middle", "near"]);
/// ```
pub fn back_to_front<T>(items: &mut [T], depth: impl Fn(&T) -> f32) {
    items.sort_unstable_by(|a, b| depth(b).total_cmp(&depth(a)));
}

/// [`back_to_front`] with any totally ordered key, larger = farther (e.g. the
/// [`Fx`](crate::math::Fx) depth of the fixed-point vertex stage, or an integer).
///
/// ```
/// use microraster::blend::back_to_front_by;
/// use microraster::math::Fx;
/// let mut meshes = [(0, Fx::from_bits(3 << 16)), (1, Fx::from_bits(7 << 16))];
/// back_to_front_by(&mut meshes, |m| m.1);
/// assert_eq!(meshes.map(|m| m.0), [1, 0]);
/// ```
pub fn back_to_front_by<T, K: Ord>(items: &mut [T], key: impl Fn(&T) -> K) {
    items.sort_unstable_by_key(|item| core::cmp::Reverse(key(item)));
}

/// The view-space depth of `mesh`'s bounding-sphere centre placed by `model`:
/// its distance in front of the camera along the view direction (`−z` after
/// `view · model`, as [`look_at`](crate::math::transform::look_at) looks down
/// −z). Larger is farther: the key for [`back_to_front`].
///
/// ```
/// use microraster::blend::view_depth;
/// use microraster::math::{transform::{look_at, translation}, Mat4, Vec3};
/// use microraster::mesh::Mesh;
/// static POS: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// let mesh = Mesh::new(&POS, &[], &[[0, 1, 2]], ([0.0, 0.0, 0.0], 1.0));
/// let view = look_at(Vec3::new(0.0f32, 0.0, 5.0), Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0))?;
/// assert_eq!(view_depth(&view, &Mat4::IDENTITY, &mesh), 5.0);
/// assert_eq!(view_depth(&view, &translation(Vec3::new(0.0, 0.0, -2.0)), &mesh), 7.0);
/// # Ok::<(), microraster::Error>(())
/// ```
pub fn view_depth<T: Scalar>(view: &Mat4<T>, model: &Mat4<T>, mesh: &Mesh<'_>) -> T {
    let c = Vec3::from_f32(mesh.bounding_sphere.0);
    -(*view * *model).transform_point(c).z
}
