//! The handles a fuzzed call sequence holds, by kind, and the ones it destroyed (kept, never
//! dereferenced by the harness, for the misuse operations of `misuse.rs`).

use ocean::{
    OceanLighting, OceanReliefCones, OceanReliefMap, OceanReliefMips, OceanReliefQuadCones,
    OceanSao, OceanSkyMap, OceanSpectrum, OceanWaves, OceanWtbScene, ocean_lighting_destroy,
    ocean_relief_cones_destroy, ocean_relief_map_destroy, ocean_relief_mips_destroy,
    ocean_relief_quad_cones_destroy, ocean_sao_destroy, ocean_sky_map_destroy,
    ocean_spectrum_destroy, ocean_waves_destroy, ocean_wtb_scene_destroy,
};

use crate::input::Input;

/// At most this many live handles of one kind: a new one replaces the oldest, so that a long
/// input does not accumulate memory.
pub const MAX_PER_KIND: usize = 4;

/// A scene and what the harness must remember to call it correctly.
pub struct Scene {
    pub handle: *mut OceanWtbScene,
    /// nx * nz of its grid: the length of its evaluation buffers.
    pub points: usize,
    /// Box ids returned by `ocean_wtb_scene_add_box` (some may have been removed since).
    pub boxes: Vec<u32>,
    /// The buffers of `ocean_wtb_scene_evaluate_incremental`, kept from call to call as an engine
    /// keeps its vertex buffers.
    pub kept_pos: Vec<ocean::OceanVec3>,
    pub kept_normal: Vec<ocean::OceanVec3>,
}

/// A handle's kind, for the misuse operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Waves,
    Spectrum,
    Lighting,
    SkyMap,
    Scene,
    ReliefMap,
    Cones,
    QuadCones,
    Mips,
    Sao,
}

/// Calls whose cost dominates an execution (an integration over the sky, a spectrum's spread
/// tables, a cone map, a wave train march): each input makes at most [`Costly::limit`] of each,
/// which keeps the executions per second high without losing coverage (more of the same call
/// in one input reaches nothing new).
#[derive(Clone, Copy, Debug)]
pub enum Costly {
    Lighting,
    Spectrum,
    SkyMap,
    Cones,
    SceneEvaluate,
    Sao,
}

impl Costly {
    fn limit(self) -> u8 {
        match self {
            Costly::Lighting => 1,
            Costly::Spectrum | Costly::SkyMap | Costly::Sao => 2,
            Costly::Cones => 3,
            Costly::SceneEvaluate => 4,
        }
    }
}

/// Every live handle, by kind.
#[derive(Default)]
pub struct Live {
    /// How many of each [`Costly`] call this input made.
    pub spent: [u8; 6],
    pub waves: Vec<*mut OceanWaves>,
    pub spectra: Vec<*mut OceanSpectrum>,
    pub lightings: Vec<*mut OceanLighting>,
    pub sky_maps: Vec<*mut OceanSkyMap>,
    pub scenes: Vec<Scene>,
    pub maps: Vec<*mut OceanReliefMap>,
    pub cones: Vec<*mut OceanReliefCones>,
    pub quads: Vec<*mut OceanReliefQuadCones>,
    pub mips: Vec<*mut OceanReliefMips>,
    pub saos: Vec<*mut OceanSao>,
    /// The sky and sea each lighting was made of, to report with what its queries return.
    pub lighting_args: Vec<(
        *mut OceanLighting,
        (ocean::OceanSkyParams, ocean::OceanSeaParams),
    )>,
    /// The lighting each sky map was made from (as `lighting_args`), likewise.
    pub sky_map_args: Vec<(
        *mut OceanSkyMap,
        Option<(ocean::OceanSkyParams, ocean::OceanSeaParams)>,
    )>,
    /// Destroyed handles, for use-after-destroy and double destroy.
    pub dead: Vec<(Kind, *mut core::ffi::c_void)>,
}

/// Picks one of `items`: an index drawn from the input, `None` when there is none.
pub fn pick<'a, T>(inp: &mut Input, items: &'a [T]) -> Option<&'a T> {
    if items.is_empty() {
        None
    } else {
        Some(&items[inp.upto(items.len() - 1)])
    }
}

/// Picks one of `handles`, or NULL when there is none or one time in sixteen: the library
/// checks every handle for NULL (include/ocean.h), so NULL is a fair input, not misuse.
pub fn pick_or_null<T>(inp: &mut Input, handles: &[*mut T]) -> *mut T {
    if inp.u8() % 16 == 15 {
        return core::ptr::null_mut();
    }
    pick(inp, handles).copied().unwrap_or(core::ptr::null_mut())
}

/// Destroys a handle of `kind`. Used for the live ones, and by `misuse.rs` for the dead ones.
///
/// # Safety
///
/// `handle` must have come from the `_create` function of `kind`; destroying it twice, or
/// as another kind, is the misuse that `ocean-ffi` is to detect.
pub unsafe fn destroy(kind: Kind, handle: *mut core::ffi::c_void) {
    // The destroy functions check the handle themselves (the registry): nothing to promise.
    match kind {
        Kind::Waves => ocean_waves_destroy(handle.cast()),
        Kind::Spectrum => ocean_spectrum_destroy(handle.cast()),
        Kind::Lighting => ocean_lighting_destroy(handle.cast()),
        Kind::SkyMap => ocean_sky_map_destroy(handle.cast()),
        Kind::Scene => ocean_wtb_scene_destroy(handle.cast()),
        Kind::ReliefMap => ocean_relief_map_destroy(handle.cast()),
        Kind::Cones => ocean_relief_cones_destroy(handle.cast()),
        Kind::QuadCones => ocean_relief_quad_cones_destroy(handle.cast()),
        Kind::Mips => ocean_relief_mips_destroy(handle.cast()),
        Kind::Sao => ocean_sao_destroy(handle.cast()),
    }
}

impl Live {
    /// Whether this input may make one more `call`; counts it if so.
    pub fn afford(&mut self, call: Costly) -> bool {
        let spent = &mut self.spent[call as usize];
        if *spent < call.limit() {
            *spent += 1;
            true
        } else {
            false
        }
    }

    /// Adds a new handle of `kind` to `list`, destroying the oldest if the kind is full.
    pub fn push<T>(
        list: &mut Vec<*mut T>,
        dead: &mut Vec<(Kind, *mut core::ffi::c_void)>,
        kind: Kind,
        h: *mut T,
    ) {
        assert!(
            !h.is_null(),
            "a _create function succeeded but returned NULL ({kind:?})"
        );
        if list.len() == MAX_PER_KIND {
            let old = list.remove(0);
            // SAFETY: `old` is a live handle of `kind`, removed from the table before it dies.
            unsafe { destroy(kind, old.cast()) };
            dead.push((kind, old.cast()));
        }
        // The allocator may hand a freed handle's address to a new one: that address is live
        // again, no longer a dead handle to misuse.
        dead.retain(|&(_, d)| d != h.cast());
        list.push(h);
    }

    /// Destroys the handle at `index` of `list` and remembers it as dead.
    pub fn kill<T>(
        list: &mut Vec<*mut T>,
        dead: &mut Vec<(Kind, *mut core::ffi::c_void)>,
        kind: Kind,
        index: usize,
    ) {
        let h = list.remove(index);
        // SAFETY: `h` is a live handle of `kind`, removed from the table before it dies.
        unsafe { destroy(kind, h.cast()) };
        dead.push((kind, h.cast()));
    }

    /// Adds a scene, destroying the oldest if there are [`MAX_PER_KIND`].
    pub fn push_scene(&mut self, scene: Scene) {
        assert!(
            !scene.handle.is_null(),
            "ocean_wtb_scene_create succeeded but returned NULL"
        );
        if self.scenes.len() == MAX_PER_KIND {
            self.kill_scene(0);
        }
        self.dead.retain(|&(_, d)| d != scene.handle.cast());
        self.scenes.push(scene);
    }

    /// Destroys the scene at `index`.
    pub fn kill_scene(&mut self, index: usize) {
        let s = self.scenes.remove(index);
        // SAFETY: `s.handle` is a live scene, removed from the table before it dies.
        unsafe { destroy(Kind::Scene, s.handle.cast()) };
        self.dead.push((Kind::Scene, s.handle.cast()));
    }

    /// One live handle of `kind`, if any, as an untyped pointer.
    pub fn any_of(&self, kind: Kind, inp: &mut Input) -> Option<*mut core::ffi::c_void> {
        fn one<T>(inp: &mut Input, v: &[*mut T]) -> Option<*mut core::ffi::c_void> {
            pick(inp, v).map(|h| h.cast())
        }
        match kind {
            Kind::Waves => one(inp, &self.waves),
            Kind::Spectrum => one(inp, &self.spectra),
            Kind::Lighting => one(inp, &self.lightings),
            Kind::SkyMap => one(inp, &self.sky_maps),
            Kind::Scene => pick(inp, &self.scenes).map(|s| s.handle.cast()),
            Kind::ReliefMap => one(inp, &self.maps),
            Kind::Cones => one(inp, &self.cones),
            Kind::QuadCones => one(inp, &self.quads),
            Kind::Mips => one(inp, &self.mips),
            Kind::Sao => one(inp, &self.saos),
        }
    }
}

impl Drop for Live {
    fn drop(&mut self) {
        fn all<T>(kind: Kind, v: &mut Vec<*mut T>) {
            for h in v.drain(..) {
                // SAFETY: every handle in the table is live and of the table's kind.
                unsafe { destroy(kind, h.cast()) };
            }
        }
        all(Kind::Waves, &mut self.waves);
        all(Kind::Spectrum, &mut self.spectra);
        all(Kind::Lighting, &mut self.lightings);
        all(Kind::SkyMap, &mut self.sky_maps);
        for s in self.scenes.drain(..) {
            // SAFETY: as above.
            unsafe { destroy(Kind::Scene, s.handle.cast()) };
        }
        all(Kind::ReliefMap, &mut self.maps);
        all(Kind::Cones, &mut self.cones);
        all(Kind::QuadCones, &mut self.quads);
        all(Kind::Mips, &mut self.mips);
        all(Kind::Sao, &mut self.saos);
    }
}
