//! Safe owners of C ABI handles whose methods call the `extern "C"` entry points exactly as a C
//! caller does (same symbols, same checks): what `ocean bench ffi` times against the Rust
//! calls they wrap, from a crate that forbids `unsafe`. Not a Rust API: use the crates.

use core::ffi::CStr;

use crate::lighting::OceanLighting;
use crate::lighting_sea::{OceanSeaColorInput, OceanSeaLight};
use crate::lighting_sky_map::OceanSkyMap;
use crate::status::{OceanStatus, ocean_last_error_message};
use crate::waves::{OceanDVec2, OceanDVec3, OceanVec3, OceanWaveDesc, OceanWaves};
use crate::wtb::OceanWtbScene;
use crate::wtb_params::{OceanBoxDesc, OceanEffects, OceanWaterGridDesc};
use crate::wtb_query::OceanHeightSample;

/// `Ok` for `OCEAN_STATUS_OK`, else the status and the thread's last-error message.
pub fn check(status: OceanStatus) -> Result<(), String> {
    if status == OceanStatus::Ok {
        return Ok(());
    }
    // SAFETY: the last-error text is a valid NUL-terminated string until the next
    // status-returning call on this thread; it is copied at once.
    let message = unsafe { CStr::from_ptr(ocean_last_error_message()) };
    Err(format!("{status:?}: {}", message.to_string_lossy()))
}

/// An `OceanWaves` handle.
pub struct Waves(*mut OceanWaves);

impl Waves {
    /// `ocean_waves_create`.
    pub fn new(descs: &[OceanWaveDesc]) -> Result<Self, String> {
        let mut h = core::ptr::null_mut();
        // SAFETY: `descs.len()` readable descriptions, a writable out-pointer.
        check(unsafe { crate::ocean_waves_create(descs.as_ptr(), descs.len(), &mut h) })?;
        Ok(Self(h))
    }

    /// `ocean_waves_evaluate` (the three slices must have one length).
    pub fn evaluate(
        &self,
        xz: &[OceanDVec2],
        time: f64,
        pos: &mut [OceanDVec3],
        nrm: &mut [OceanVec3],
    ) -> OceanStatus {
        assert!(pos.len() == xz.len() && nrm.len() == xz.len());
        // SAFETY: `xz.len()` readable points and as many writable outputs each (asserted).
        unsafe {
            crate::ocean_waves_evaluate(
                self.0,
                xz.as_ptr(),
                xz.len(),
                time,
                pos.as_mut_ptr(),
                nrm.as_mut_ptr(),
            )
        }
    }

    /// `ocean_waves_count`: a call that only crosses the boundary.
    pub fn count(&self) -> (OceanStatus, usize) {
        let mut n = 0;
        // SAFETY: a writable count.
        let s = unsafe { crate::ocean_waves_count(self.0, &mut n) };
        (s, n)
    }
}

impl Drop for Waves {
    fn drop(&mut self) {
        crate::ocean_waves_destroy(self.0);
    }
}

/// An `OceanWtbScene` handle.
pub struct Scene(*mut OceanWtbScene);

impl Scene {
    /// `ocean_wtb_scene_create`, `ocean_wtb_scene_set_effects` and `ocean_wtb_scene_add_box` for each box.
    pub fn new(
        grid: &OceanWaterGridDesc,
        terrain: &[f32],
        effects: &OceanEffects,
        boxes: &[OceanBoxDesc],
    ) -> Result<Self, String> {
        let mut h = core::ptr::null_mut();
        // SAFETY: a readable grid, `terrain.len()` readable floats, a writable out-pointer.
        check(unsafe {
            crate::ocean_wtb_scene_create(grid, terrain.as_ptr(), terrain.len(), &mut h)
        })?;
        let scene = Self(h);
        // SAFETY: readable effects.
        check(unsafe { crate::ocean_wtb_scene_set_effects(scene.0, effects) })?;
        for b in boxes {
            let mut id = 0;
            // SAFETY: a readable description, no explicit trains, a writable id.
            check(unsafe {
                crate::ocean_wtb_scene_add_box(scene.0, b, core::ptr::null(), 0, &mut id)
            })?;
        }
        Ok(scene)
    }

    /// `ocean_wtb_scene_heights_continuous` (the slices must have one length).
    pub fn heights_continuous(
        &self,
        time: f64,
        xz: &[OceanDVec2],
        out: &mut [OceanHeightSample],
    ) -> OceanStatus {
        assert_eq!(out.len(), xz.len());
        // SAFETY: `xz.len()` readable points and writable samples (asserted).
        unsafe {
            crate::ocean_wtb_scene_heights_continuous(
                self.0,
                time,
                xz.as_ptr(),
                xz.len(),
                out.as_mut_ptr(),
            )
        }
    }
}

impl Drop for Scene {
    fn drop(&mut self) {
        crate::ocean_wtb_scene_destroy(self.0);
    }
}

/// An `OceanLighting` of the default sky and sea with its sky map.
pub struct SeaColor(*mut OceanLighting, *mut OceanSkyMap);

impl SeaColor {
    /// `ocean_lighting_create` of the defaults and `ocean_lighting_sky_map_create`.
    pub fn new(sky_map_size: u32) -> Result<Self, String> {
        let (mut sky, mut sea) = Default::default();
        // SAFETY: writable.
        check(unsafe { crate::ocean_sky_params_default(&mut sky) })?;
        // SAFETY: writable.
        check(unsafe { crate::ocean_sea_params_default(&mut sea) })?;
        let mut l = core::ptr::null_mut();
        // SAFETY: readable parameters, a writable out-pointer.
        check(unsafe { crate::ocean_lighting_create(&sky, &sea, &mut l) })?;
        let mut m = core::ptr::null_mut();
        // SAFETY: a writable out-pointer.
        let s = unsafe { crate::ocean_lighting_sky_map_create(l, sky_map_size, &mut m) };
        let both = Self(l, m);
        check(s)?;
        Ok(both)
    }

    /// `ocean_sea_color_batch` (the slices must have one length).
    pub fn batch(&self, inputs: &[OceanSeaColorInput], out: &mut [OceanSeaLight]) -> OceanStatus {
        assert_eq!(out.len(), inputs.len());
        // SAFETY: `inputs.len()` readable inputs and writable outputs (asserted).
        unsafe {
            crate::ocean_sea_color_batch(
                self.0,
                self.1,
                inputs.as_ptr(),
                inputs.len(),
                out.as_mut_ptr(),
            )
        }
    }
}

impl Drop for SeaColor {
    fn drop(&mut self) {
        crate::ocean_sky_map_destroy(self.1);
        crate::ocean_lighting_destroy(self.0);
    }
}

/// `ocean_wtb_effects_default`.
pub fn effects_default() -> Result<OceanEffects, String> {
    let mut e = OceanEffects::default();
    // SAFETY: writable.
    check(unsafe { crate::ocean_wtb_effects_default(&mut e) })?;
    Ok(e)
}
