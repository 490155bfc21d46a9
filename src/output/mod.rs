//! The output stage: the band and depth buffers and the band loop, down to
//! the embedded-graphics `DrawTarget` (and the display link that sends
//! finished bands). Nothing here knows about meshes.
pub mod band;
pub mod blit;
pub mod depth;
pub mod render;
