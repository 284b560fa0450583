use super::*;
use crate::lighting_sea::*;
use crate::lighting_sky_map::*;
use crate::waves::OceanDVec2;
use glam::DVec2;
use ocean_brdf::SlopeVariance;
use ocean_brdf::sea::sea_color;

use crate::status::last_error;

fn lighting() -> *mut OceanLighting {
    let mut sky = OceanSkyParams::default();
    let mut sea = OceanSeaParams::default();
    let mut l = core::ptr::null_mut();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(ocean_sky_params_default(&mut sky), OceanStatus::Ok);
        assert_eq!(ocean_sea_params_default(&mut sea), OceanStatus::Ok);
        assert_eq!(ocean_lighting_create(&sky, &sea, &mut l), OceanStatus::Ok);
    }
    l
}

fn sky_map(l: *const OceanLighting, size: u32) -> *mut OceanSkyMap {
    let mut m = core::ptr::null_mut();
    // SAFETY: live lighting, writable out.
    let s = unsafe { ocean_lighting_sky_map_create(l, size, &mut m) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    m
}

/// The wrapper adds nothing to the arithmetic: the defaults, the derived radiances, the
/// sky map's levels and the sea's colour are the crate's, bit for bit.
#[test]
fn matches_the_crate_bit_for_bit() {
    let l = lighting();
    let core = Lighting::new(SkyParams::default(), SeaParams::default()).unwrap();
    let mut rgb = OceanRgb::default();
    // SAFETY: live handle, writable out.
    unsafe {
        assert_eq!(ocean_lighting_sea_radiance(l, &mut rgb), OceanStatus::Ok);
        assert_eq!(rgb.to_dvec3(), core.sea_radiance());
        assert_eq!(ocean_lighting_sky_irradiance(l, &mut rgb), OceanStatus::Ok);
        assert_eq!(rgb.to_dvec3(), core.sky().sky_irradiance());
    }
    let m = sky_map(l, 16);
    let core_map = core.sky_map(16).unwrap();
    for level in 0..5 {
        let mut side = 0;
        // SAFETY: live handle, writable out.
        let s = unsafe { ocean_sky_map_level_info(m, level, &mut side) };
        assert_eq!(s, OceanStatus::Ok);
        assert_eq!(side, 16 >> level);
        let n = (side * side * 4) as usize;
        let mut buf = vec![0.0f32; n];
        // SAFETY: n writable floats.
        let s = unsafe { ocean_sky_map_copy_level(m, level, buf.as_mut_ptr(), n) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let want: &[f32] = bytemuck::cast_slice(core_map.level(level).unwrap());
        assert_eq!(buf, want);
    }
    let input = OceanSeaColorInput {
        v: OceanDVec3 {
            x: 0.3,
            y: 0.8,
            z: -0.6,
        },
        n: OceanDVec3 {
            x: 0.1,
            y: 0.99,
            z: 0.05,
        },
        wind: OceanDVec2 { x: 1.0, z: 0.5 },
        sigma_x2: 0.02,
        sigma_y2: 0.01,
    };
    let nv = |d: OceanDVec3| {
        let v = DVec3::new(d.x, d.y, d.z).normalize();
        OceanDVec3 {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    };
    let input = OceanSeaColorInput {
        v: nv(input.v),
        n: nv(input.n),
        ..input
    };
    let mut one = OceanSeaLight::default();
    let mut batch = [OceanSeaLight::default(); 2];
    // SAFETY: live handles, writable outputs, two inputs and two outputs.
    unsafe {
        let s = ocean_sea_color(
            l,
            m,
            input.v,
            input.n,
            input.wind,
            input.sigma_x2,
            input.sigma_y2,
            &mut one,
        );
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let inputs = [input, input];
        let s = ocean_sea_color_batch(l, m, inputs.as_ptr(), 2, batch.as_mut_ptr());
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    }
    let want = sea_color(
        &core,
        &core_map,
        DVec3::new(input.v.x, input.v.y, input.v.z),
        DVec3::new(input.n.x, input.n.y, input.n.z),
        DVec2::new(1.0, 0.5),
        SlopeVariance { x: 0.02, y: 0.01 },
    )
    .unwrap();
    assert_eq!(one, OceanSeaLight::from_core(&want));
    assert_eq!(batch, [one, one]);
    ocean_sky_map_destroy(m);
    ocean_lighting_destroy(l);
}

#[test]
fn a_sky_map_of_another_lighting_is_refused() {
    let l = lighting();
    let mut sky = OceanSkyParams::default();
    let mut sea = OceanSeaParams::default();
    // SAFETY: valid pointers.
    unsafe {
        ocean_sky_params_default(&mut sky);
        ocean_sea_params_default(&mut sea);
    }
    sea.albedo.r = 0.5;
    let mut other = core::ptr::null_mut();
    // SAFETY: valid pointers.
    let s = unsafe { ocean_lighting_create(&sky, &sea, &mut other) };
    assert_eq!(s, OceanStatus::Ok);
    let m = sky_map(other, 4);
    let up = OceanDVec3 {
        x: 0.0,
        y: 1.0,
        z: 0.0,
    };
    let mut out = OceanSeaLight::default();
    // SAFETY: live handles.
    let s = unsafe {
        ocean_sea_color(
            l,
            m,
            up,
            up,
            OceanDVec2 { x: 1.0, z: 0.0 },
            0.0,
            0.0,
            &mut out,
        )
    };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(
        last_error().contains("another lighting"),
        "{}",
        last_error()
    );
    assert_eq!(out, OceanSeaLight::default());
    ocean_sky_map_destroy(m);
    ocean_lighting_destroy(other);
    ocean_lighting_destroy(l);
}

#[test]
fn misaligned_handles_and_buffers_are_refused() {
    let l = lighting();
    let m = sky_map(l, 4);
    let mut storage = [0u64; 16];
    let base = storage.as_mut_ptr().cast::<u8>();
    let bad_map = base.wrapping_add(4).cast::<OceanSkyMap>().cast_const();
    let mut side = 7;
    // SAFETY: refused before any access.
    let s = unsafe { ocean_sky_map_level_info(bad_map, 0, &mut side) };
    // A handle is an id, never an address: a pointer into the caller's memory is not one.
    assert_eq!(s, OceanStatus::InvalidHandle);
    assert_eq!(side, 7);
    let bad_rgba = base.wrapping_add(2).cast::<f32>();
    // SAFETY: refused before any access.
    let s = unsafe { ocean_sky_map_copy_level(m, 2, bad_rgba, 4) };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    assert!(storage.iter().all(|&v| v == 0));
    ocean_sky_map_destroy(bad_map.cast_mut());
    ocean_sky_map_destroy(m);
    ocean_lighting_destroy(l);
}
