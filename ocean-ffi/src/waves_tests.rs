use super::*;

use crate::status::last_error;

const DESCS: [OceanWaveDesc; 2] = [
    OceanWaveDesc {
        amplitude: 0.5,
        wavelength: 12.0,
        direction_x: 1.0,
        direction_z: 0.5,
        phase: 0.3,
        depth: f64::INFINITY,
    },
    OceanWaveDesc {
        amplitude: 0.2,
        wavelength: 5.0,
        direction_x: -0.4,
        direction_z: 1.0,
        phase: -1.0,
        depth: 2.5,
    },
];

fn create() -> *mut OceanWaves {
    let mut w = core::ptr::null_mut();
    // SAFETY: valid array and out pointer.
    let s = unsafe { ocean_waves_create(DESCS.as_ptr(), DESCS.len(), &mut w) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    w
}

fn core_set() -> WaveSet {
    WaveSet::from_descs(&[
        WaveDesc {
            amplitude: 0.5,
            wavelength: 12.0,
            direction: DVec2::new(1.0, 0.5),
            phase: 0.3,
            depth: Depth::Deep,
        },
        WaveDesc {
            amplitude: 0.2,
            wavelength: 5.0,
            direction: DVec2::new(-0.4, 1.0),
            phase: -1.0,
            depth: Depth::Finite(2.5),
        },
    ])
    .unwrap()
}

/// The wrapper adds nothing to the arithmetic: its outputs are the core's, bit for bit, for
/// points (each relative to the corner of its 64 m cell, in double precision) and grids
/// (origin-relative), on both sides of the parallel threshold; and a point gives the same
/// bits alone as in a batch.
#[test]
fn matches_the_core_bit_for_bit() {
    let w = create();
    let set = core_set();
    for n in [5, PARALLEL_POINTS + 3] {
        let xz: Vec<OceanDVec2> = (0..n)
            .map(|i| OceanDVec2 {
                x: (i % 97) as f64 * 1.5 - 60.0,
                z: (i / 97) as f64 * 0.75 - 20.0,
            })
            .collect();
        let mut pos = vec![OceanDVec3::default(); n];
        let mut nrm = vec![OceanVec3::default(); n];
        // SAFETY: n elements in each buffer.
        let s = unsafe {
            ocean_waves_evaluate(w, xz.as_ptr(), n, 42.5, pos.as_mut_ptr(), nrm.as_mut_ptr())
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        for (i, p) in xz.iter().enumerate().step_by(if n > 100 { 257 } else { 1 }) {
            let world = DVec2::new(p.x, p.z);
            let corner = (world / 64.0).floor() * 64.0;
            let (mut cp, mut cn) = ([Vec3::ZERO], [Vec3::ZERO]);
            set.evaluate_points(
                corner,
                &[(world - corner).as_vec2()],
                42.5,
                &mut cp,
                &mut cn,
            )
            .unwrap();
            let want = [
                corner.x + f64::from(cp[0].x),
                f64::from(cp[0].y),
                corner.y + f64::from(cp[0].z),
            ];
            assert_eq!([pos[i].x, pos[i].y, pos[i].z], want, "point {i}");
            assert_eq!(
                [nrm[i].x, nrm[i].y, nrm[i].z],
                cn[0].to_array(),
                "point {i}"
            );
            let (mut one, mut one_n) = ([OceanDVec3::default()], [OceanVec3::default()]);
            // SAFETY: one element in each buffer.
            let s = unsafe {
                ocean_waves_evaluate(w, p, 1, 42.5, one.as_mut_ptr(), one_n.as_mut_ptr())
            };
            assert_eq!(s, OceanStatus::Ok);
            assert_eq!((one[0], one_n[0]), (pos[i], nrm[i]), "point {i} alone");
        }
    }

    let g = OceanGrid {
        origin_x: 5000.5,
        origin_z: -123.25,
        spacing_x: 0.5,
        spacing_z: 0.25,
        nx: 19,
        nz: 7,
    };
    let mut pos = vec![OceanVec3::default(); 19 * 7];
    let mut nrm = pos.clone();
    // SAFETY: nx * nz elements in each buffer.
    let s = unsafe { ocean_waves_evaluate_grid(w, &g, 8.0, pos.as_mut_ptr(), nrm.as_mut_ptr()) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    let grid = Grid {
        origin: DVec2::new(5000.5, -123.25),
        spacing: DVec2::new(0.5, 0.25),
        size: (19, 7),
    };
    let mut cp = vec![Vec3::ZERO; 19 * 7];
    let mut cn = cp.clone();
    set.evaluate_grid(&grid, 8.0, &mut cp, &mut cn).unwrap();
    assert!(
        pos.iter()
            .zip(&cp)
            .all(|(a, b)| [a.x, a.y, a.z] == b.to_array())
    );
    assert!(
        nrm.iter()
            .zip(&cn)
            .all(|(a, b)| [a.x, a.y, a.z] == b.to_array())
    );
    ocean_waves_destroy(w);
}

/// 100 km from the origin a point is as precise as at it: within 0.1 mm of the f64
/// reference (`WaveSet::sample_f64`, rest position plus displacement) at (10, 20) and at
/// (1e5 + 10, -4e4 + 20). Rest positions rounded to floats there (a float resolves 7.8 mm
/// at 1e5 m) were off by up to 3.9 mm.
#[test]
fn far_from_the_origin_a_point_is_as_precise_as_near_it() {
    let w = create();
    let set = core_set();
    for base in [DVec2::ZERO, DVec2::new(1.0e5, -4.0e4)] {
        let rest: Vec<DVec2> = (0..200)
            .map(|i| base + DVec2::new(10.0 + 0.37 * i as f64, 20.0 - 0.2311 * i as f64))
            .collect();
        let xz: Vec<OceanDVec2> = rest.iter().map(|p| OceanDVec2 { x: p.x, z: p.y }).collect();
        let mut pos = vec![OceanDVec3::default(); xz.len()];
        let mut nrm = vec![OceanVec3::default(); xz.len()];
        // SAFETY: as many elements in each buffer as points.
        let s = unsafe {
            ocean_waves_evaluate(
                w,
                xz.as_ptr(),
                xz.len(),
                42.5,
                pos.as_mut_ptr(),
                nrm.as_mut_ptr(),
            )
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let worst = rest
            .iter()
            .zip(&pos)
            .map(|(r, p)| {
                let d = set.sample_f64(*r, 42.5).unwrap().displacement;
                let want = glam::DVec3::new(r.x + d.x, d.y, r.y + d.z);
                (glam::DVec3::new(p.x, p.y, p.z) - want).abs().max_element()
            })
            .fold(0.0, f64::max);
        assert!(worst < 1e-4, "{base}: worst error {worst} m");
    }
    ocean_waves_destroy(w);
}

/// Misaligned pointers (which C code cannot even form without undefined behaviour, but
/// other languages' FFIs can pass) are refused before any access.
#[test]
fn misaligned_pointers_are_refused() {
    let w = create();
    let mut storage = [0u64; 32]; // 8-aligned, so base + 4 is not
    let xz = [OceanDVec2::default(); 4];
    let base = storage.as_mut_ptr().cast::<u8>();
    // Four bytes past an 8-aligned address: misaligned for double structs. Never
    // dereferenced.
    let bad_out = base.wrapping_add(4).cast::<OceanDVec3>();
    let good_pos = base.wrapping_add(128).cast::<OceanDVec3>();
    let good_nrm = base.wrapping_add(200).cast::<OceanVec3>();
    // SAFETY: the library refuses the misaligned pointer before touching any buffer.
    let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, bad_out, good_nrm) };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    assert!(last_error().contains("out_pos"), "{}", last_error());
    let bad_in = base.wrapping_add(4).cast::<OceanDVec2>().cast_const();
    // SAFETY: as above.
    let s = unsafe { ocean_waves_evaluate(w, bad_in, 4, 0.0, good_pos, good_nrm) };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    let mut count = 0usize;
    let bad_handle = base.wrapping_add(4).cast::<OceanWaves>().cast_const();
    // SAFETY: as above.
    let s = unsafe { ocean_waves_count(bad_handle, &mut count) };
    // A handle is an id, never an address: a pointer into the caller's memory is not one.
    assert_eq!(s, OceanStatus::InvalidHandle);
    assert!(
        storage.iter().all(|&v| v == 0),
        "a refused call wrote memory"
    );
    ocean_waves_destroy(bad_handle.cast_mut());
    ocean_waves_destroy(w);
}

/// Partly overlapping arrays (not only identical pointers) are refused: creating `&` and
/// `&mut` slices over them would be undefined behaviour.
#[test]
fn overlapping_buffers_are_refused() {
    let w = create();
    // 10 double positions (240 bytes): room for 4 positions and 8 normals after them.
    let mut buf = vec![OceanDVec3::default(); 10];
    let xz = [OceanDVec2::default(); 4];
    let p = buf.as_mut_ptr();
    let normals_at = |bytes: usize| p.cast::<u8>().wrapping_add(bytes).cast::<OceanVec3>();
    // out_normal starts inside out_pos's 4 elements (96 bytes).
    // SAFETY: refused before any access; the buffer holds 240 bytes anyway.
    let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, p, normals_at(84)) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    // Adjacent, non-overlapping ranges are fine.
    // SAFETY: bytes 0..96 and 96..144 of a 240-byte buffer.
    let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, p, normals_at(96)) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    // Input overlapping an output.
    let xz_alias = p.wrapping_add(8).cast::<OceanDVec2>().cast_const();
    // SAFETY: refused before any access (1 point = 16 bytes inside element 8).
    let s = unsafe { ocean_waves_evaluate(w, xz_alias, 1, 0.0, p.wrapping_add(8), normals_at(0)) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    ocean_waves_destroy(w);
}

#[test]
fn depth_infinity_is_deep_water_and_other_non_finite_depths_are_refused() {
    // depth = +INFINITY must give the same wave as the core's Depth::Deep.
    let deep = wave_desc(0, &DESCS[0]).unwrap();
    assert_eq!(deep.depth, Depth::Deep);
    for (d, status) in [
        (f64::NAN, OceanStatus::NonFinite),
        (f64::NEG_INFINITY, OceanStatus::NonFinite),
    ] {
        let desc = OceanWaveDesc {
            depth: d,
            ..DESCS[0]
        };
        assert_eq!(wave_desc(0, &desc).unwrap_err().status, status);
    }
    let mut w = core::ptr::null_mut();
    let desc = OceanWaveDesc {
        depth: -1.0,
        ..DESCS[1]
    };
    // SAFETY: valid pointers.
    let s = unsafe { ocean_waves_create(&desc, 1, &mut w) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(w.is_null());
    assert!(last_error().contains("depth"), "{}", last_error());
}
