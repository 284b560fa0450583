//! The ocean renderer drawing a caller's water mesh (`mesh_vs`, `mesh_fs`) and composing its
//! light with an ambient obscurance (`compose_fs`), through
//! `ocean_gpu::OceanRenderer::render_mesh_image`: the shaders an engine runs in its own
//! pipeline with the C ABI's `ocean_surface_uniforms` (examples/cpp-glfw).
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure (CI runs these on
//! lavapipe with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`).

use glam::{DVec2, DVec3};
use ocean_brdf::{Filter, FilteredSurface, Lighting, SeaParams, SkyParams, Spectrum};
use ocean_brdf::{SpectrumParams, surface::pixel_ray, surface::sea_plane_hit};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::{GpuContext, GpuError, MeshGeometry, MeshGrid, OceanOptions, OceanRenderer};
use ocean_tests::gpu_context_or_skip;

const W: u32 = 160;
const H: u32 = 96;

/// Short waves (3 m/s wind, 2 cm to 50 cm): too short for the projected grid's cells in the
/// views below, so the open sea is the plane y = 0 with per-pixel normals and variances.
fn ripples() -> (Spectrum, FilteredSurface) {
    let spectrum = Spectrum::new(SpectrumParams {
        wind_speed: 3.0,
        waves: 30,
        min_wavelength: 0.02,
        max_wavelength: 0.5,
        ..SpectrumParams::default()
    })
    .expect("spectrum");
    let surface = FilteredSurface::new(&spectrum, Filter::PAPER).expect("surface");
    (spectrum, surface)
}

fn renderer(ctx: &GpuContext) -> (OceanRenderer, Spectrum) {
    let (spectrum, surface) = ripples();
    let mut r = OceanRenderer::new(ctx, OceanOptions::default()).expect("renderer");
    r.set_surface(ctx, &surface).expect("surface");
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).expect("lighting");
    r.set_lighting(ctx, &lighting).expect("lighting");
    (r, spectrum)
}

/// 6 m above the sea looking towards the Sun (−z), `pitch` degrees down, 60° field of view.
fn camera(pitch: f64) -> Camera {
    let eye = DVec3::new(3.0, 6.0, 2.0);
    let p = pitch.to_radians();
    Camera::look_at(
        eye,
        eye + DVec3::new(0.0, -p.sin(), -p.cos()),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 60f64.to_radians(),
            aspect: f64::from(W) / f64::from(H),
            near: 0.1,
            far: Far::Finite(10_000.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .expect("camera")
}

/// A flat mesh at rest: 0.5 m apart over x in [−100, 100], z in [−100, 5], normals +y.
struct FlatMesh {
    grid: MeshGrid,
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
}

fn flat_mesh() -> FlatMesh {
    let grid = MeshGrid {
        origin: DVec2::new(-100.0, -100.0),
        spacing: 0.5,
        nx: 401,
        nz: 211,
    };
    let mut positions = Vec::new();
    for j in 0..grid.nz {
        for i in 0..grid.nx {
            positions.push([i as f32 * 0.5, 0.0, j as f32 * 0.5]);
        }
    }
    let normals = vec![[0.0, 1.0, 0.0]; positions.len()];
    FlatMesh {
        grid,
        positions,
        normals,
    }
}

impl FlatMesh {
    fn geometry(&self) -> MeshGeometry<'_> {
        MeshGeometry {
            grid: self.grid,
            positions: &self.positions,
            normals: &self.normals,
        }
    }
}

/// Whether the centre of pixel `(x, y)` sees the sea plane inside the flat mesh (a margin of
/// one cell off its edges).
fn on_mesh(c: &Camera, x: u32, y: u32) -> bool {
    let Some((origin, dir)) = ray(c, x, y) else {
        return false;
    };
    if dir.y >= -1e-3 {
        return false;
    }
    let Some(hit) = sea_plane_hit(origin, dir, 1.0e6) else {
        return false;
    };
    (-99.5..=99.5).contains(&hit.x) && (-99.5..=4.5).contains(&hit.y)
}

/// The view ray (origin, unit direction) through the centre of pixel `(x, y)`.
fn ray(c: &Camera, x: u32, y: u32) -> Option<(DVec3, DVec3)> {
    let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
    pixel_ray(c, f64::from(W), f64::from(H), centre)
}

fn max_channel_diff(a: &[u8], b: &[u8]) -> u8 {
    a.iter()
        .zip(b)
        .take(3)
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

/// A flat mesh at rest carries no slope of its own and no unresolved variance (its slope's
/// derivatives are zero), so `mesh_fs` lights each pixel with the open sea's filtered normal
/// and variance exactly as `ocean_fs` does on the projected grid, which these waves leave flat:
/// the two images agree but for f32 rounding (rest positions interpolated over other
/// triangles, the normal normalised twice).
#[test]
fn a_flat_mesh_lights_like_the_open_sea() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (r, _) = renderer(&ctx);
    let c = camera(30.0);
    // Every wave is shorter than N_min = 1 grid cells (8 pixels) at the nearest pixels, so the
    // projected grid takes none of them (w_p = 0, the grid stays on y = 0, as the mesh), while
    // the pixels there resolve some in their normals (w_n > 0).
    let bottom = [
        DVec2::new(0.5, f64::from(H) - 0.5),
        DVec2::new(80.5, f64::from(H) - 0.5),
    ];
    for p in r
        .probe_surface(&ctx, &c, 4.0, W, H, &bottom)
        .expect("probe")
    {
        assert_eq!(p.position_waves, 0, "{p:?}");
        assert!(p.normal_waves > 0, "{p:?}");
    }
    let mesh = flat_mesh();
    let from_mesh = r
        .render_mesh_image(&ctx, &c, 4.0, &mesh.geometry(), None, W, H)
        .expect("mesh image");
    let from_grid = r.render_image(&ctx, &c, 4.0, W, H).expect("grid image");
    let (mut pixels, mut close, mut worst) = (0usize, 0usize, 0u8);
    for y in 0..H {
        for x in 0..W {
            if !on_mesh(&c, x, y) {
                continue;
            }
            let k = 4 * (y * W + x) as usize;
            let d = max_channel_diff(&from_mesh[k..k + 4], &from_grid[k..k + 4]);
            pixels += 1;
            close += usize::from(d <= 2);
            worst = worst.max(d);
        }
    }
    // The camera looks 30° down with a 30° half-angle: the mesh fills all but the top rows.
    assert!(
        pixels > (W * H) as usize * 9 / 10,
        "{pixels} pixels on the mesh"
    );
    assert!(
        close as f64 >= 0.995 * pixels as f64,
        "{close} of {pixels} pixels within 2/255 (worst {worst}) on {}",
        ctx.describe()
    );
}

/// The obscurance scales the ambient light alone, and only where the mesh drew: with A = 0 a
/// pixel keeps the Sun's reflection only (black away from the glitter), A = ½ lies between,
/// and the sky above the mesh is `sky_fs`'s sky whatever A.
#[test]
fn obscurance_darkens_only_the_ambient_light() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (r, _) = renderer(&ctx);
    // 15° down: the view's top edge is 15° above the horizon, so the sky shows.
    let c = camera(15.0);
    let mesh = flat_mesh();
    let n = (W * H) as usize;
    let image = |a: f32| {
        let ao = vec![a; n];
        r.render_mesh_image(&ctx, &c, 4.0, &mesh.geometry(), Some(&ao), W, H)
            .expect("mesh image")
    };
    let (full, half, none) = (image(1.0), image(0.5), image(0.0));
    let sky = r.render_image(&ctx, &c, 4.0, W, H).expect("grid image");
    let (mut on, mut black, mut darker, mut unsaturated, mut sky_pixels) = (0, 0, 0, 0, 0);
    for y in 0..H {
        for x in 0..W {
            let k = 4 * (y * W + x) as usize;
            let px = |img: &[u8]| [img[k], img[k + 1], img[k + 2]];
            let (_, dir) = ray(&c, x, y).expect("ray");
            if dir.y > 0.02 {
                // Above the horizon: nothing of the mesh, the same sky in every image.
                sky_pixels += 1;
                assert_eq!(px(&full), px(&none), "sky at ({x}, {y})");
                assert_eq!(px(&full), px(&half), "sky at ({x}, {y})");
                assert!(
                    max_channel_diff(&full[k..k + 4], &sky[k..k + 4]) <= 1,
                    "sky at ({x}, {y}): {:?} vs sky_fs {:?}",
                    px(&full),
                    px(&sky)
                );
            } else if on_mesh(&c, x, y) {
                on += 1;
                let (f, h, z) = (px(&full), px(&half), px(&none));
                // Tone mapping and sRGB encoding are monotonic in the radiance.
                assert!(
                    (0..3).all(|i| z[i] <= h[i] && h[i] <= f[i]),
                    "({x}, {y}): A = 0 {z:?}, ½ {h:?}, 1 {f:?}"
                );
                // Where the Sun's glitter makes a pixel nearly white, the tone map
                // 1 − exp(−e L) has flattened (its slope e (1 − y) is a few hundredths of its
                // slope at black above y = 240/255) and halving the ambient light changes no
                // byte; everywhere else it must show.
                if f.iter().any(|&v| v < 240) {
                    unsaturated += 1;
                    darker += usize::from((0..3).any(|i| h[i] < f[i]));
                }
                black += usize::from(z.iter().all(|&v| v <= 1));
            }
        }
    }
    assert!(
        sky_pixels > 0 && on > (W * H / 3) as usize,
        "{sky_pixels} sky, {on} mesh"
    );
    // The ambient light is most of the sea's colour: halving it darkens every pixel the
    // glitter does not saturate, and without it all but the glitter is black.
    assert_eq!(
        darker, unsaturated,
        "{darker} of {unsaturated} darker at A = ½"
    );
    assert!(black * 2 >= on, "{black} of {on} black at A = 0");
}

#[test]
fn bad_meshes_are_refused() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (r, _) = renderer(&ctx);
    let c = camera(30.0);
    let mesh = flat_mesh();
    let short = MeshGeometry {
        positions: &mesh.positions[1..],
        ..mesh.geometry()
    };
    let thin = MeshGeometry {
        grid: MeshGrid { nz: 1, ..mesh.grid },
        positions: &mesh.positions[..401],
        normals: &mesh.normals[..401],
    };
    let mut nan = mesh.normals.clone();
    nan[7] = [f32::NAN, 1.0, 0.0];
    let bad_normal = MeshGeometry {
        normals: &nan,
        ..mesh.geometry()
    };
    for (what, m) in [("short", short), ("thin", thin), ("nan", bad_normal)] {
        let e = r.render_mesh_image(&ctx, &c, 0.0, &m, None, W, H);
        assert!(
            matches!(e, Err(GpuError::InvalidInput { what: "mesh", .. })),
            "{what}: {e:?}"
        );
    }
    let ao = vec![1.5f32; (W * H) as usize];
    let e = r.render_mesh_image(&ctx, &c, 0.0, &mesh.geometry(), Some(&ao), W, H);
    assert!(
        matches!(
            e,
            Err(GpuError::InvalidInput {
                what: "obscurance",
                ..
            })
        ),
        "{e:?}"
    );
    let bare = OceanRenderer::new(&ctx, OceanOptions::default()).expect("renderer");
    let e = bare.render_mesh_image(&ctx, &c, 0.0, &mesh.geometry(), None, W, H);
    assert!(matches!(e, Err(GpuError::NotConfigured { .. })), "{e:?}");
}
