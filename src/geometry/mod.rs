//! The geometry stage: meshes in, snapped screen triangles out (the math,
//! the meshes and their meshlets, lighting, 3D clipping and the vertex
//! stage). Nothing here knows about bands of pixels except as a row range.
pub mod clip3d;
pub mod light;
pub mod math;
pub mod mesh;
pub mod pipeline;
