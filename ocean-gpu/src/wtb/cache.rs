//! What [`WtbMarchPass`](super::WtbMarchPass) keeps between calls: the terrain on the GPU and,
//! per box, its static march (the paper's action points "cached while the box is still").
//!
//! A box's march depends on its [`MarchBox`], the water grid and the terrain only; the plan's
//! time-dependent effects are applied afterwards by the `combine` dispatch, every call. An
//! entry is therefore reused while its box's `MarchBox` and the terrain compare equal to those
//! it was marched with, and re-marched (into its own buffers when they are large enough) when
//! either changes.

use ocean_wtb::Terrain;
use ocean_wtb::march::MarchBox;
use ocean_wtb::scene::BoxId;

use super::height::HeightBuffers;
use super::params::{BoxSetup, MarchParams};

/// Calls an entry outlives its box's absence from the plans (a box culled for a moment keeps
/// its march), after which its buffers are released.
pub const KEEP_CALLS: u64 = 64;

/// Counters of a [`WtbMarchPass`](super::WtbMarchPass)'s cache, to check that still boxes are
/// marched once and a frame loop allocates nothing in its steady state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WtbMarchStats {
    /// Boxes marched: a box's first call, and each call after its `MarchBox` or the terrain
    /// changed.
    pub marches: u64,
    /// Boxes whose cached march was reused.
    pub reuses: u64,
    /// Terrain uploads (the first call, and each call with another terrain).
    pub terrain_uploads: u64,
    /// Buffers created so far (four per new box, fewer when a moved box's buffers fit).
    pub buffers_created: u64,
    /// Boxes held in the cache now.
    pub cached_boxes: usize,
}

/// One box's static march on the GPU.
#[derive(Debug)]
pub(crate) struct CachedBox {
    pub(crate) id: BoxId,
    /// What the march read; `None` while the buffers hold no finished march.
    pub(crate) march: Option<MarchBox>,
    pub(crate) setup: BoxSetup,
    pub(crate) uniform: wgpu::Buffer,
    pub(crate) statics: wgpu::Buffer,
    /// base, land factor and its smoothing scratch: 16 bytes a rectangle point.
    pub(crate) work: wgpu::Buffer,
    /// The modulation the layers pass reads: 8 bytes a rectangle point.
    pub(crate) modulation: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
    /// The last call that used the entry.
    pub(crate) last_used: u64,
}

/// The terrain the entries were marched over, and its buffer.
#[derive(Debug)]
pub(crate) struct CachedTerrain {
    pub(crate) terrain: Terrain,
    pub(crate) buffer: wgpu::Buffer,
}

/// Everything kept between calls.
#[derive(Debug, Default)]
pub(crate) struct MarchCache {
    pub(crate) terrain: Option<CachedTerrain>,
    pub(crate) boxes: Vec<CachedBox>,
    /// The height pass's buffers, over the cached terrain's buffer.
    pub(crate) height: Option<HeightBuffers>,
    /// Calls so far.
    pub(crate) calls: u64,
    pub(crate) stats: WtbMarchStats,
}

/// What a planned box needs this call.
#[derive(Debug)]
pub(crate) enum Need {
    /// Entry `n` holds its march.
    Reuse(usize),
    /// It must be marched; entry `n` (of the same box id, not claimed by another planned box)
    /// lends its buffers, if any.
    March(Option<usize>, Box<BoxSetup>),
}

impl MarchCache {
    /// Whether the entries were marched over `terrain`.
    pub(crate) fn has_terrain(&self, terrain: &Terrain) -> bool {
        self.terrain.as_ref().is_some_and(|t| t.terrain == *terrain)
    }

    /// The entry to reuse for box `id` marching `march`, or the entry of the same id whose
    /// buffers it may take, skipping entries already `claimed` this call.
    pub(crate) fn lookup(
        &self,
        id: BoxId,
        march: &MarchBox,
        terrain_same: bool,
        claimed: &[bool],
    ) -> (Option<usize>, Option<usize>) {
        let mut same_id = None;
        for (n, e) in self.boxes.iter().enumerate() {
            if claimed.get(n).copied().unwrap_or(false) || e.id != id {
                continue;
            }
            if terrain_same && e.march.as_ref() == Some(march) {
                return (Some(n), None);
            }
            same_id.get_or_insert(n);
        }
        (None, same_id)
    }

    /// Drops the entries unused for [`KEEP_CALLS`] calls.
    pub(crate) fn evict(&mut self) {
        let now = self.calls;
        self.boxes.retain(|e| now - e.last_used < KEEP_CALLS);
        self.stats.cached_boxes = self.boxes.len();
    }

    /// Forgets everything (after a failed call, whose entries may be half written).
    pub(crate) fn clear(&mut self) {
        self.terrain = None;
        self.boxes.clear();
        self.height = None;
        self.stats.cached_boxes = 0;
    }
}

/// Whether an entry's buffers hold `setup`'s data.
pub(crate) fn fits(e: &CachedBox, setup: &BoxSetup) -> bool {
    e.statics.size() >= 4 * (setup.statics.len() as u64).max(4)
        && e.work.size() >= 16 * setup.points.max(1)
        && e.modulation.size() >= 8 * setup.points.max(1)
}

/// The uniform block's size.
pub(crate) const PARAMS_SIZE: u64 = std::mem::size_of::<MarchParams>() as u64;
