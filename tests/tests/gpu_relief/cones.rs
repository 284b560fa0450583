//! The GPU cone-map generator against `ConeMap::generate` and `QuadConeMap::generate`, and
//! its timing.

use super::*;

/// ULPs between two non-negative f32 values.
fn ulps(a: f32, b: f32) -> u32 {
    a.to_bits().abs_diff(b.to_bits())
}

/// Per channel (ratio, clearance, near cap): texels that differ and the largest difference in
/// ulps, and whether any GPU value lies above the CPU's.
fn compare_cones(cpu: &ConeMap, gpu: &ConeMap) -> ([usize; 3], [u32; 3], bool) {
    let mut diff = [0usize; 3];
    let mut worst = [0u32; 3];
    let mut above = false;
    let pairs = [
        (cpu.ratios(), gpu.ratios()),
        (cpu.clearance(), gpu.clearance()),
        (cpu.near_cap(), gpu.near_cap()),
    ];
    for (c, (a, b)) in pairs.into_iter().enumerate() {
        for (x, y) in a.iter().zip(b) {
            if x != y {
                diff[c] += 1;
                worst[c] = worst[c].max(ulps(*x, *y));
                above |= y > x;
            }
        }
    }
    (diff, worst, above)
}

/// Maps whose cells meet the bound's exact ties: 8-bit pyramids and ramps (planar cells seen
/// along their level direction, diagonal faces: the falling test's zero and the arcs' shared
/// end points), 16-bit terraces (flat cells), at sides that are not powers of two (a padded
/// pyramid), in both edge modes.
fn tie_maps() -> Vec<(String, HeightMap)> {
    let mut out = Vec::new();
    for (n, edge) in [(37usize, Edge::Clamp), (50, Edge::Wrap)] {
        let c = n as i64 / 2;
        let diamond: Vec<u8> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as i64, (k / n) as i64);
                (255 - 3 * ((x - c).abs() + (y - c).abs())).clamp(0, 255) as u8
            })
            .collect();
        out.push((
            format!("diamond {n}"),
            HeightMap::from_u8(n, n, &diamond, edge).unwrap(),
        ));
        let ramp: Vec<u8> = (0..n * n)
            .map(|k| (((k % n) + 2 * (k / n)) * 3 % 256) as u8)
            .collect();
        out.push((
            format!("ramp {n}"),
            HeightMap::from_u8(n, n, &ramp, edge).unwrap(),
        ));
        let terraces: Vec<u16> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as u32, (k / n) as u32);
                (((x / 4) * 7919 + (y / 3) * 104_729) % 65536) as u16
            })
            .collect();
        out.push((
            format!("terraces {n}"),
            HeightMap::from_u16(n, n, &terraces, edge).unwrap(),
        ));
    }
    out
}

/// The cone-map parity cases: the procedural maps of [`test_maps`] with relaxed and
/// conservative cones capped at 1 and the `extra` parameters, and the tie maps with those two,
/// a cap of 64 (many tile copies in wrap mode) and one of 0.01 (every texel capped).
fn cone_cases(extra: &[ConeParams]) -> Vec<(String, HeightMap, Vec<ConeParams>)> {
    let book = [
        ConeParams::relaxed(1.0).with_parts(0),
        ConeParams::conservative(1.0).with_parts(0),
    ];
    let procedural = test_maps()
        .into_iter()
        .map(|(name, map)| (name.to_owned(), map, [&book[..], extra].concat()));
    let ties = tie_maps().into_iter().map(|(name, map)| {
        let caps = [
            ConeParams::relaxed(64.0).with_parts(0),
            ConeParams::relaxed(0.01).with_parts(0),
        ];
        (name, map, [&book[..], &caps[..]].concat())
    });
    procedural.chain(ties).collect()
}

/// GPU cone maps against `ConeMap::generate` on the six procedural maps in both edge modes and
/// the tie maps, relaxed and conservative, with the book's cap (1), a wide one (4, and 64 on the
/// tie maps: many tile copies in wrap mode) and a tiny one (0.01: every texel capped).
/// Expected: bit-identical on software adapters (measured: every texel of every channel, on
/// lavapipe and llvmpipe); elsewhere within 4 ulps per value and never above the CPU's by more
/// than that (the CPU's cones round down; an `f64` value within 2⁻⁴⁴ of an `f32` boundary may
/// round to the other side in double-`f32`).
#[test]
fn cone_maps_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    let cases = cone_cases(&[ConeParams::relaxed(4.0).with_parts(0)]);
    let mut count = 0;
    for (name, map, params) in &cases {
        for &p in params {
            let cpu = ConeMap::generate(map, p).unwrap();
            let gpu = generator.generate(&ctx, map, p).unwrap();
            let (diff, worst, above) = compare_cones(&cpu, &gpu);
            let label = format!(
                "{name} {:?} {p:?}: differing {diff:?}, ulps {worst:?}",
                map.edge()
            );
            if exact {
                assert_eq!(diff, [0; 3], "{label}");
            }
            assert!(worst.iter().all(|&u| u <= 4), "{label} (above: {above})");
            count += 1;
        }
    }
    eprintln!("cone maps: {count} maps compared");
}

/// GPU quadrant cone maps (`ConeMapGenerator::generate_quad`, §18.1) against
/// `QuadConeMap::generate`, every layer and channel, on the maps of
/// [`cone_maps_match_the_cpu`] with its caps (the procedural maps without the cap of 4: the tie
/// maps' cap of 64 already sends the clipped search through many tile copies, and four layers
/// take four times as long). Expected as there, for the same reason: bit-identical on
/// software adapters, elsewhere within 4 ulps per value (the double-`f32` bound's values are
/// within about 2⁻⁴⁴ of the CPU's `f64` ones, and both round down to `f32`, so only a value that
/// close to an `f32` boundary can land one ulp away; 4 leaves room for the few such roundings
/// one value passes). The quadrant clip changes only which nodes and cells the search visits,
/// the vector boxes and the near-cell arcs, all exact integer or sign work, so it adds no
/// rounding. The GPU layers must differ from the isotropic cones wherever the CPU's do (else
/// the sector would not have reached the shader): everywhere but where every cone is capped.
#[test]
fn quad_cone_maps_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    let cases = cone_cases(&[]);
    let (mut count, mut wider) = (0, 0usize);
    for (name, map, params) in &cases {
        for &p in params {
            let cpu = QuadConeMap::generate(map, p).unwrap();
            let gpu = generator.generate_quad(&ctx, map, p).unwrap();
            let iso = ConeMap::generate(map, p).unwrap();
            let (mut cpu_from_iso, mut differs_from_iso) = (0, 0);
            for (k, (c, g)) in cpu.layers().iter().zip(gpu.layers()).enumerate() {
                let (diff, worst, above) = compare_cones(c, g);
                let label = format!(
                    "{name} {:?} {p:?} layer {k}: differing {diff:?}, ulps {worst:?}",
                    map.edge()
                );
                if exact {
                    assert_eq!(diff, [0; 3], "{label}");
                }
                assert!(worst.iter().all(|&u| u <= 4), "{label} (above: {above})");
                cpu_from_iso += compare_cones(&iso, c).0.iter().sum::<usize>();
                differs_from_iso += compare_cones(&iso, g).0.iter().sum::<usize>();
            }
            assert_eq!(
                differs_from_iso > 0,
                cpu_from_iso > 0,
                "{name} {p:?}: GPU layers vs isotropic"
            );
            wider += differs_from_iso;
            count += 1;
        }
    }
    assert!(wider > 0);
    eprintln!(
        "quad cone maps: {count} maps x 4 layers compared; {wider} layer values differ from \
         the isotropic maps"
    );
}

/// Generates the quadrant cone maps of the noise map of [`time_generation`] at side `n` in both
/// edge modes on the CPU and the GPU, prints both times next to the isotropic GPU time, and
/// checks parity as [`quad_cone_maps_match_the_cpu`] does.
fn time_quad_generation(ctx: &GpuContext, n: usize) {
    let generator = ConeMapGenerator::new(ctx).unwrap();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let warm = to_map(16, &value_noise(16, 2, 2, 1), edge).unwrap();
        generator
            .generate_quad(ctx, &warm, ConeParams::relaxed(1.0).with_parts(0))
            .unwrap();
    }
    for edge in [Edge::Wrap, Edge::Clamp] {
        let map = to_map(n, &value_noise(n, 8, 5, 3), edge).unwrap();
        let p = ConeParams::relaxed(1.0).with_parts(0);
        let t = Instant::now();
        let cpu = QuadConeMap::generate(&map, p).unwrap();
        let cpu_time = t.elapsed();
        let (gpu, times) = generator.generate_quad_timed(ctx, &map, p).unwrap();
        let (_, iso) = generator.generate_timed(ctx, &map, p).unwrap();
        eprintln!(
            "quad cone map {n}² {edge:?}: CPU {cpu_time:?}, GPU {:?} (cells and pyramid {:?}, \
             search {:?}, texels and readback {:?}; isotropic GPU {:?}) on {}",
            times.total(),
            times.prepare,
            times.search,
            times.finish,
            iso.total(),
            ctx.describe()
        );
        for (k, (c, g)) in cpu.layers().iter().zip(gpu.layers()).enumerate() {
            let (diff, worst, _) = compare_cones(c, g);
            if software(ctx) {
                assert_eq!(diff, [0; 3], "{n}² {edge:?} layer {k}");
            }
            assert!(
                worst.iter().all(|&u| u <= 4),
                "{n}² {edge:?} layer {k}: {worst:?}"
            );
        }
    }
}

/// Quadrant generation at 128² (times printed; the assertion is parity).
#[test]
fn quad_cone_map_generation_128() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_quad_generation(&ctx, 128);
}

/// Quadrant generation at 256² (measured on lavapipe, 2 shared cores: 16.1 s in wrap mode and
/// 13.3 s in clamp mode, against 4.6 s and 4.2 s isotropic and 0.9 s on the CPU, so not run by
/// default: `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn quad_cone_map_generation_256() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_quad_generation(&ctx, 256);
}

/// Generates the cone maps of a smooth noise map of side `n` in both edge modes on the CPU and
/// the GPU, prints both times, and checks parity as [`cone_maps_match_the_cpu`] does. A 16²
/// map in each mode goes first: drivers compile the shader at its first dispatch (about 10 s
/// on llvmpipe), which is no part of a generation's time.
fn time_generation(ctx: &GpuContext, sizes: &[usize]) {
    let generator = ConeMapGenerator::new(ctx).unwrap();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let warm = to_map(16, &value_noise(16, 2, 2, 1), edge).unwrap();
        generator
            .generate(ctx, &warm, ConeParams::relaxed(1.0).with_parts(0))
            .unwrap();
    }
    for &n in sizes {
        for edge in [Edge::Wrap, Edge::Clamp] {
            let map = to_map(n, &value_noise(n, 8, 5, 3), edge).unwrap();
            let p = ConeParams::relaxed(1.0).with_parts(0);
            let t = Instant::now();
            let cpu = ConeMap::generate(&map, p).unwrap();
            let cpu_time = t.elapsed();
            let (gpu, times) = generator.generate_timed(ctx, &map, p).unwrap();
            eprintln!(
                "cone map {n}² {edge:?}: CPU {cpu_time:?}, GPU {:?} (cells and pyramid {:?}, \
                 search {:?}, texels and readback {:?}) on {}",
                times.total(),
                times.prepare,
                times.search,
                times.finish,
                ctx.describe()
            );
            let (diff, worst, _) = compare_cones(&cpu, &gpu);
            if software(ctx) {
                assert_eq!(diff, [0; 3], "{n}² {edge:?}");
            }
            assert!(worst.iter().all(|&u| u <= 4), "{n}² {edge:?}: {worst:?}");
        }
    }
}

/// Generation at 256² (times printed; the assertion is parity, as for the small maps).
#[test]
fn cone_map_generation_256() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_generation(&ctx, &[256]);
}

/// Generation at 512² and 1024² (15–18 s and 70–86 s each on llvmpipe, so not run by
/// default: `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn cone_map_generation_large() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_generation(&ctx, &[512, 1024]);
}
