//! What each configuration is called in the table (its key in
//! `docs/data/fw-bench.tsv` derives from it) and which of the firmware's
//! buffers it uses.

use super::Interp::{Affine as Aff, Perspective as Persp};
use super::Vertex::{F32, Fx as Fix};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use super::{Eye, Interp, Vertex};
use super::{Stage, Work};
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
use microraster::raster3d::Precision;
use microraster::raster3d::Precision::{Exact, Fast};

impl Work {
    /// How the frame is produced, for the table.
    pub fn describe(&self) -> &'static str {
        match self {
            Work::Clear => "clear + send each band",
            Work::Frame2d(_) => "primitives in RAM",
            Work::Streamed2d(_) => "regenerated per band",
            Work::Vertex3d(F32) => "f32 vertex stage only",
            Work::Vertex3d(Fix) => "Fx vertex stage only",
            Work::Vertex3dCached => "f32 vertex stage only, vertex cache",
            Work::Vertex3dChunked => "f32 vertex stage only, 64-vertex cache (chunks)",
            Work::Frame3dChunked => "f32, affine, 64-vertex cache (chunks)",
            Work::VertexPerBand3d(F32) => "f32 vertex stage only, per band",
            Work::VertexPerBand3d(Fix) => "Fx vertex stage only, per band",
            Work::Frame3d(F32, Persp) => "f32, persp.-correct",
            Work::Frame3d(F32, Aff) => "f32, affine",
            Work::Frame3d(Fix, Persp) => "Fx, persp.-correct",
            Work::Frame3d(Fix, Aff) => "Fx, affine",
            Work::PerBand3d(F32, Persp) => "f32 per band, persp.-correct",
            Work::PerBand3d(F32, Aff) => "f32 per band, affine",
            Work::PerBand3d(Fix, Persp) => "Fx per band, persp.-correct",
            Work::PerBand3d(Fix, Aff) => "Fx per band, affine",
            Work::Meshlets(F32, Aff) => "meshlets per band, f32, affine",
            Work::Meshlets(F32, Persp) => "meshlets per band, f32, persp.-correct",
            Work::Meshlets(Fix, Aff) => "meshlets per band, Fx, affine",
            Work::Meshlets(Fix, Persp) => "meshlets per band, Fx, persp.-correct",
            Work::MeshletsFar(Aff) => "meshlets per band, f32, affine, viewer at infinity",
            Work::MeshletsFar(Persp) => "meshlets per band, f32, persp.-correct, viewer at infinity",
            Work::KnotStage(F32, Stage::Vertex) => "f32 affine: band loop + vertex stage only",
            Work::KnotStage(F32, Stage::Coverage) => "f32 affine: + coverage, no planes",
            Work::KnotStage(F32, Stage::NoWrites) => "f32 affine: all but pixel writes",
            Work::KnotStage(Fix, Stage::Vertex) => "Fx affine: band loop + vertex stage only",
            Work::KnotStage(Fix, Stage::Coverage) => "Fx affine: + coverage, no planes",
            Work::KnotStage(Fix, Stage::NoWrites) => "Fx affine: all but pixel writes",
            Work::Dashboard => "2D kit, drawn per band",
            Work::DashboardDrive => "2D kit, link.rs drive, damage regions, per frame",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTier(p, eye, t, i) => describe_tier(*p, *eye, *t, *i),
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTallTier(p, rows) => match (p, rows) {
                (Exact, 20) => "meshlets, f32, affine, 20-row bands, exact tier",
                (Exact, 32) => "meshlets, f32, affine, 32-row bands",
                (Exact, 48) => "meshlets, f32, affine, 48-row bands, exact tier",
                (Fast, 20) => "meshlets, f32, affine, 20-row bands, fast tier",
                (Fast, 32) => "meshlets, f32, affine, 32-row bands, fast tier",
                (Fast, 48) => "meshlets, f32, affine, 48-row bands, fast tier",
                _ => "meshlets, f32, affine, other bands, by tier",
            },
            Work::Frame3dTier(Exact, ..) => "exact tier, binned per frame",
            Work::Frame3dTier(Fast, F32, Persp) => "f32, persp.-correct, fast tier",
            Work::Frame3dTier(Fast, F32, Aff) => "f32, affine, fast tier",
            Work::Frame3dTier(Fast, Fix, Persp) => "Fx, persp.-correct, fast tier",
            Work::Frame3dTier(Fast, Fix, Aff) => "Fx, affine, fast tier",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Front3d => "View3d front, f32, persp.-correct, per band",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Ways(knot, way) => {
                use super::ways::{Knot::*, Way::*};
                match (knot, way) {
                    (K20, Front) => "obj2rs knot 20k: View3d front, f32, persp.-correct",
                    (K20, Meshlets) => "obj2rs knot 20k: meshlets per band, f32, persp.-correct",
                    (K20, Bins) => "obj2rs knot 20k: full-frame bins, f32, persp.-correct",
                    (K5, Front) => "obj2rs knot 5k: View3d front, f32, persp.-correct",
                    (K5, Meshlets) => "obj2rs knot 5k: meshlets per band, f32, persp.-correct",
                    (K5, Bins) => "obj2rs knot 5k: full-frame bins, f32, persp.-correct",
                }
            }
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotVertexRows(rows) => match rows {
                16 => "f32 vertex stage only, 16-row bands",
                32 => "f32 vertex stage only, 32-row bands",
                48 => "f32 vertex stage only, 48-row bands",
                80 => "f32 vertex stage only, 80-row bands",
                240 => "f32 vertex stage only, one 240-row band",
                _ => "f32 vertex stage only, other bands",
            },
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTall(rows) => match rows {
                20 => "meshlets, f32, affine, 20-row bands",
                48 => "meshlets, f32, affine, 48-row bands",
                240 => "meshlets, f32, affine, one 240-row band",
                _ => "meshlets, f32, affine, other bands",
            },
        }
    }

    /// The buffers it uses (names of the firmware's statics).
    pub fn buffers(&self) -> &'static str {
        match self {
            Work::Clear | Work::Streamed2d(_) | Work::Dashboard | Work::DashboardDrive => "BAND",
            Work::Frame2d(_) => "BAND,PRIMS",
            Work::Vertex3d(_) | Work::VertexPerBand3d(_) => "BINS",
            Work::Vertex3dCached => "BINS,CACHE",
            Work::Vertex3dChunked => "BINS,CHUNK",
            Work::Frame3dChunked => "BAND,DEPTH,BINS,CHUNK",
            Work::Frame3d(..) | Work::PerBand3d(..) | Work::Frame3dTier(..) => "BAND,DEPTH,BINS",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTier(_, _, F32, _) => "BAND,DEPTH,CLUSTER",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTier(_, _, Fix, _) => "BAND,DEPTH,CLUSTER_FX",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTallTier(_, rows) => match rows {
                20 => "BAND20,DEPTH20,CLUSTER",
                32 => "BAND32,DEPTH32,CLUSTER",
                _ => "BAND48,DEPTH48,CLUSTER",
            },
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Front3d | Work::Ways(_, super::ways::Way::Front) => "VIEW",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Ways(_, super::ways::Way::Meshlets) => "BAND,DEPTH,CLUSTER",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Ways(super::ways::Knot::K20, super::ways::Way::Bins) => "BAND,DEPTH,KNOT_BINS",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::Ways(super::ways::Knot::K5, super::ways::Way::Bins) => "BAND,DEPTH,KNOT5K_BINS",
            Work::Meshlets(F32, _) | Work::MeshletsFar(_) | Work::KnotStage(F32, _) => "BAND,DEPTH,CLUSTER",
            Work::Meshlets(Fix, _) | Work::KnotStage(Fix, _) => "BAND,DEPTH,CLUSTER_FX",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotVertexRows(_) => "CLUSTER",
            #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
            Work::KnotTall(rows) => match rows {
                20 => "BAND20,DEPTH20,CLUSTER",
                48 => "BAND48,DEPTH48,CLUSTER",
                _ => "BAND240,DEPTH240,CLUSTER",
            },
        }
    }

    /// Whether it only counts the vertex stage's triangles ([`Work::KnotVertexRows`]).
    fn counts_only(&self) -> bool {
        #[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
        if let Work::KnotVertexRows(_) = self {
            return true;
        }
        false
    }

    /// Whether it sends pixels (a frame CRC and covered pixels mean something).
    pub fn draws(&self) -> bool {
        !matches!(
            self,
            Work::Vertex3d(_)
                | Work::Vertex3dCached
                | Work::Vertex3dChunked
                | Work::VertexPerBand3d(_)
                | Work::KnotStage(..)
        ) && !self.counts_only()
    }
}

/// [`Work::KnotTier`]'s description.
#[cfg(any(not(target_os = "none"), target_abi = "eabihf"))]
const fn describe_tier(p: Precision, eye: Eye, t: Vertex, i: Interp) -> &'static str {
    match (p, eye, t, i) {
        (Fast, Eye::Standard, F32, Aff) => "meshlets per band, f32, affine, fast tier",
        (Fast, Eye::Standard, F32, Persp) => "meshlets per band, f32, persp.-correct, fast tier",
        (Fast, Eye::Standard, Fix, Aff) => "meshlets per band, Fx, affine, fast tier",
        (Fast, Eye::Standard, Fix, Persp) => "meshlets per band, Fx, persp.-correct, fast tier",
        (Exact, Eye::Close, F32, Aff) => "meshlets per band, f32, affine, eye twice as close",
        (Exact, Eye::Close, F32, Persp) => "meshlets per band, f32, persp.-correct, eye twice as close",
        (Fast, Eye::Close, F32, Aff) => "meshlets per band, f32, affine, fast tier, eye twice as close",
        (Fast, Eye::Close, F32, Persp) => {
            "meshlets per band, f32, persp.-correct, fast tier, eye twice as close"
        }
        (_, Eye::Close, Fix, _) => "meshlets per band, Fx, eye twice as close, by tier",
        (Exact, Eye::Standard, ..) => "meshlets per band, exact tier, by tier",
    }
}
