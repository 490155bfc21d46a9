//! microraster's integration tests, built as ONE test binary (`cargo test --test
//! integration`) so the shared reference code compiles once and every suite can
//! use it. Each suite is a module; add new ones below.
//!
//! - `reference`: independent brute-force rasterizers, PRNG and generators.
//! - `triangles_exact`: `TriangleSpans` vs the exact integer reference.
//! - `triangles_float`: snapping error vs an `f64` reference on unsnapped vertices.
//! - `triangles_skia`: against tiny-skia's non-anti-aliased fill.
//! - `watertight`: meshes tiling a region hit every pixel exactly once.
//! - `lines`: midpoint lines vs an `f64` reference and embedded-graphics' `Line`.
//! - `line_aa`: anti-aliased lines vs an `f64` Wu reference; band invariance.
//! - `blend`: every blend mode × colour format vs an `f64` reference; translucent drawing; depth sort.
//! - `gouraud`: Gouraud colour vs an `f64` barycentric reference.
//! - `bands`: identical images for every band height; one `fill_contiguous` per band.
//! - `damage`, `damage_bounds`: damage regions render and send only what changed, exactly;
//!   styled shapes' bounds hold every pixel they write; the dashboard's drive with damage.
//! - `dashboard`: the dashboard example: band invariance, text identical to plain e-g.
//! - `drawables`: embedded-graphics text, images and styled primitives drawn into bands
//!   match e-g into a framebuffer, for every band height; HUD over 3D.
//! - `mock_display`: embedded-graphics `MockDisplay` pattern tests (overdraw panics).
//! - `per_band`: the per-band vertex stage draws what the per-frame one draws.
//! - `capacity`: bins and vertex caches too small: the needed count, no partial mesh.
//! - `varyings`: per-vertex value vectors vs f64; the fragment hook's coverage.
//! - `discard`: a discarded fragment writes no depth.
//! - `fragment`: the fragment stage: Phong vs f64 and Gouraud, translucency, varyings through the clipper.
//! - `sprite`: sprites (alpha textures, scaled, rotated, nearest/bilinear) vs an f64 sampler;
//!   band invariance; bad input.
//! - `texture`: texture sampling vs f64; textured triangles (affine and perspective-correct).
//! - 3D: `depth3d`, `zfight`, `perspective`, `clip3d_raster`, `interpenetrate`, `pipeline3d` (references in `ref3d`, `clip3d_ref`).
//! - `antialias`, `antialias_images`: anti-aliasing (`microraster::aa`): coverage vs exact area,
//!   shared edges, uniform meshes, band invariance, modes, ranges.
//! - `view3d`: the one-call 3D front draws what the explicit API draws, for every band
//!   height; its defaults (culling, lighting, winding check) and errors.
//! - `fast_raster`: the fast tier's raster against the exact tier's on the same screen
//!   triangles: coverage, depth within one code, colour within one step (two at most).
//! - `view3d_colors`: the front's per-vertex and per-face colours.
//! - `ways`: the three documented ways to draw a mesh draw the same frame of a mesh
//!   converted by `obj2rs`'s default command; the front's accuracy tier.
//! - `mesh_range`: issue 60's whole-mesh checks: clip coordinates beyond ±2^64, a singular
//!   model before the first band, an inside-out `ValidMesh` on the explicit path.
//! - `fast_tier`: the fast accuracy tier against the exact one: whole frames within the colour,
//!   depth and coverage bounds; bad input the same error in both tiers.
//! - `framebuffer`: a recording host `DrawTarget` used by the suites above.

mod affine3d;
mod antialias;
mod antialias_images;
mod bands;
mod blend;
mod capacity;
mod clip3d_raster;
mod clip3d_ref;
mod damage;
mod damage_bounds;
mod damage_drive;
mod dashboard;
mod depth3d;
mod discard;
mod drawables;
mod fast_raster;
mod fast_tier;
mod fragment;
mod framebuffer;
mod gouraud;
mod integrity;
mod interpenetrate;
mod limits;
mod line_aa;
mod lines;
mod link;
mod link_async;
mod link_failures;
mod mesh_range;
mod meshlets;
mod mock_display;
mod passes;
mod per_band;
mod per_band_mesh;
mod perspective;
mod pipeline3d;
mod props;
mod props3d;
mod ref3d;
mod reference;
mod regressions;
mod shapes;
mod shapes_ref;
mod sprite;
mod texture;
mod triangles_exact;
mod triangles_float;
mod triangles_skia;
mod varyings;
mod view3d;
mod view3d_colors;
mod view3d_hud;
mod watertight;
mod watertight_clip;
mod ways;
mod zfight;
