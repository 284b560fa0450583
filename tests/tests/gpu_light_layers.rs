//! Split light targets (`ocean_gpu::LightTargets`): the sea (`OceanRenderer::render_layers`) and
//! relief quads (`ReliefRenderer::render_layers`) write their direct and ambient light apart,
//! and `OceanRenderer::compose` writes `display(direct + A · ambient)` and the sky: the path
//! of `ocean render`, whose obscurance darkens the ambient light alone.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure (CI runs these on
//! lavapipe with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`).

use glam::{DVec2, DVec3};
use ocean_brdf::{Filter, FilteredSurface, Lighting, SeaParams, SkyParams, Spectrum};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::wgpu;
use ocean_gpu::{
    ComposeInputs, GpuContext, GpuError, LightTargets, OceanOptions, OceanRenderer,
    RADIANCE_FORMAT, ReliefOptions, ReliefRenderer, ReliefScene,
};
use ocean_relief::{ConeMap, ConeParams, Edge, ReliefTexture};
use ocean_tests::gpu_context_or_skip;

const W: u32 = 128;
const H: u32 = 80;

/// 5 m above the sea looking 10° down towards −z (the default Sun's side), 60° field of view,
/// WebGPU's depth range.
fn camera() -> Camera {
    camera_towards(-1.0)
}

/// [`camera`] looking towards `z_sign` z.
fn camera_towards(z_sign: f64) -> Camera {
    let eye = DVec3::new(0.0, 5.0, 0.0);
    let p = 10f64.to_radians();
    Camera::look_at(
        eye,
        eye + DVec3::new(0.0, -p.sin(), z_sign * p.cos()),
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

fn sea(ctx: &GpuContext) -> OceanRenderer {
    sea_with(ctx, OceanOptions::default())
}

fn sea_with(ctx: &GpuContext, options: OceanOptions) -> OceanRenderer {
    let spectrum = Spectrum::new(ocean_brdf::SpectrumParams::default()).expect("spectrum");
    let surface = FilteredSurface::new(&spectrum, Filter::PAPER).expect("surface");
    let mut r = OceanRenderer::new(ctx, options).expect("renderer");
    r.set_surface(ctx, &surface).expect("surface");
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).expect("lighting");
    r.set_lighting(ctx, &lighting).expect("lighting");
    r
}

/// A frame's targets and an obscurance texture of one value.
struct Frame {
    direct: wgpu::Texture,
    ambient: wgpu::Texture,
    depth: wgpu::Texture,
    ao: wgpu::Texture,
    out: wgpu::Texture,
}

fn view(t: &wgpu::Texture) -> wgpu::TextureView {
    t.create_view(&wgpu::TextureViewDescriptor::default())
}

impl Frame {
    fn new(ctx: &GpuContext, a: f32) -> Self {
        Self::with_samples(ctx, a, 1)
    }

    /// Light and depth targets of `samples` samples per pixel (multisampled ones cannot be
    /// copied: no `COPY_SRC` then).
    fn with_samples(ctx: &GpuContext, a: f32, samples: u32) -> Self {
        let texture = |label, format, usage, sample_count| {
            ctx.device().create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: W,
                    height: H,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        use wgpu::TextureUsages as U;
        let light = if samples == 1 {
            U::RENDER_ATTACHMENT | U::TEXTURE_BINDING | U::COPY_SRC
        } else {
            U::RENDER_ATTACHMENT | U::TEXTURE_BINDING
        };
        let ao = texture(
            "ao",
            wgpu::TextureFormat::R32Float,
            U::TEXTURE_BINDING | U::COPY_DST,
            1,
        );
        ctx.queue().write_texture(
            ao.as_image_copy(),
            bytemuck::cast_slice(&vec![a; (W * H) as usize]),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * W),
                rows_per_image: Some(H),
            },
            ao.size(),
        );
        Self {
            direct: texture("direct", RADIANCE_FORMAT, light, samples),
            ambient: texture("ambient", RADIANCE_FORMAT, light, samples),
            depth: texture(
                "depth",
                wgpu::TextureFormat::Depth32Float,
                U::RENDER_ATTACHMENT | U::TEXTURE_BINDING,
                samples,
            ),
            ao,
            out: texture(
                "out",
                OceanOptions::default().color_format,
                U::RENDER_ATTACHMENT | U::COPY_SRC,
                1,
            ),
        }
    }

    /// Clears the light to transparent black and the depth to 1, then records `draw`.
    fn draw(
        &self,
        ctx: &GpuContext,
        draw: impl FnOnce(&mut wgpu::CommandEncoder, &LightTargets<'_>) -> Result<(), GpuError>,
    ) -> Result<(), GpuError> {
        let (d, a, z) = (view(&self.direct), view(&self.ambient), view(&self.depth));
        let mut e = ctx
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        let clear = |view| {
            Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })
        };
        e.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[clear(&d), clear(&a)],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &z,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        let targets = LightTargets {
            direct: &d,
            ambient: &a,
            depth: &z,
        };
        draw(&mut e, &targets)?;
        ctx.queue().submit([e.finish()]);
        Ok(())
    }

    fn compose(&self, ctx: &GpuContext, sea: &OceanRenderer) -> Vec<u8> {
        let (d, a, o) = (view(&self.direct), view(&self.ambient), view(&self.ao));
        let mut e = ctx
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        let inputs = ComposeInputs {
            direct: &d,
            ambient: &a,
            obscurance: &o,
        };
        sea.compose(ctx, &mut e, &inputs, &view(&self.out), (W, H))
            .expect("compose");
        ctx.queue().submit([e.finish()]);
        ocean_gpu::readback::read_texture(ctx, &self.out, 0)
            .expect("read")
            .data
    }
}

fn max_channel_diff(a: &[u8], b: &[u8]) -> u8 {
    (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)
}

/// With A = 1 the split sea composes to `render`'s single-pass image: the same vertices, the
/// same Algorithm 5.1, its three terms summed in another order after a trip through
/// `rgba16float` (3 significant digits: about 1/2000 of the radiance, below one 8-bit level of
/// the tone-mapped value but where rounding straddles a level), and the same sky. Every pixel
/// within 2 levels, 99 % of them within 1.
#[test]
fn split_sea_composes_to_the_single_pass_image() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = sea(&ctx);
    let c = camera();
    let frame = Frame::new(&ctx, 1.0);
    frame
        .draw(&ctx, |e, t| sea.render_layers(&ctx, e, &c, 3.0, t, (W, H)))
        .expect("layers");
    let composed = frame.compose(&ctx, &sea);
    let single = sea.render_image(&ctx, &c, 3.0, W, H).expect("image");
    let (mut within1, mut worst) = (0usize, 0u8);
    for (a, b) in composed.chunks(4).zip(single.chunks(4)) {
        let d = max_channel_diff(a, b);
        worst = worst.max(d);
        within1 += usize::from(d <= 1);
    }
    let n = (W * H) as usize;
    assert!(worst <= 2, "worst {worst} levels on {}", ctx.describe());
    assert!(
        within1 as f64 >= 0.99 * n as f64,
        "{within1} of {n} within 1 level"
    );
}

/// Multisampled targets (4 samples, `MSAA_SAMPLES`): a pixel that one surface covers whole
/// runs its fragment once, at its centre, as a single-sampled frame does, and `compose_ms_fs`
/// tone-maps the four equal samples and averages them to the same value; only the pixels an
/// edge crosses change. Here the edges are the horizon (rows 0–24 are sky and rows from 31
/// sea, see `the_obscurance_leaves_the_suns_light_and_the_sky`), one row of 128 pixels, 1.25 %
/// of them, and the crests that hide troughs behind them (measured on lavapipe: 132 pixels
/// differ in all, in the horizon's row and three others). So at least 98 % of the pixels must
/// be within 1 level of the single-sampled frame, and the horizon rows must hold some that are
/// not: a pixel partly covered by sky blends the sky and the sea, its blue moved by more than 4
/// levels from its single-sampled value to a value strictly between that and its
/// single-sampled neighbour's above or below. Where multisampled targets are lost (wgpu's GL
/// backend) the renderer must refuse them.
#[test]
fn multisampled_targets_compose_to_the_single_sampled_image_but_at_edges() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = sea(&ctx);
    let c = camera();
    if !ctx.supports_multisampled_light() {
        // wgpu's GL backend: refused, not drawn wrong.
        let frame = Frame::with_samples(&ctx, 1.0, ocean_gpu::MSAA_SAMPLES);
        let refused = frame.draw(&ctx, |e, t| sea.render_layers(&ctx, e, &c, 3.0, t, (W, H)));
        assert!(
            matches!(refused, Err(GpuError::UnsuitableAdapter { .. })),
            "{refused:?}"
        );
        eprintln!("multisampled light targets refused on {}", ctx.describe());
        return;
    }
    let image = |samples| {
        let frame = Frame::with_samples(&ctx, 1.0, samples);
        frame
            .draw(&ctx, |e, t| sea.render_layers(&ctx, e, &c, 3.0, t, (W, H)))
            .expect("layers");
        frame.compose(&ctx, &sea)
    };
    let (one, four) = (image(1), image(ocean_gpu::MSAA_SAMPLES));
    let (mut within1, mut rows) = (0usize, std::collections::BTreeSet::new());
    for (k, (a, b)) in one.chunks(4).zip(four.chunks(4)).enumerate() {
        if max_channel_diff(a, b) <= 1 {
            within1 += 1;
        } else {
            rows.insert(k as u32 / W);
        }
    }
    let n = (W * H) as usize;
    assert!(
        within1 as f64 >= 0.98 * n as f64,
        "{within1} of {n} within 1 level on {}; rows that differ: {rows:?}",
        ctx.describe()
    );
    assert!(
        rows.iter().any(|&y| (24..=31).contains(&y)),
        "rows that differ: {rows:?}"
    );
    let blue = |img: &[u8], x: u32, y: u32| i32::from(img[4 * (y * W + x) as usize + 2]);
    let between = |v: i32, a: i32, b: i32| v > a.min(b) && v < a.max(b);
    let blended = (0..W).any(|x| {
        (24..=31).any(|y| {
            let (here, aa) = (blue(&one, x, y), blue(&four, x, y));
            (aa - here).abs() > 4
                && (between(aa, here, blue(&one, x, y - 1))
                    || between(aa, here, blue(&one, x, y + 1)))
        })
    });
    assert!(blended, "no horizon pixel blends the sky and the sea");
}

/// The sea reaches the horizon: every pixel whose centre's view ray descends is drawn (ambient
/// alpha 1), however near the horizon. With a 400 m distance cap, 5 m up, the cap's circle
/// lies atan(5/400) = 0.72° below the horizon, 0.95 px at 80 rows over 60°: the horizon of
/// [`camera`] crosses the image at y = 40 − 40 tan 10°/tan 30° = 27.79, so row 28's centres
/// (y = 28.5) look below the horizon but above the cap. The grid's vertices beyond the cap are
/// drawn on their own rays (`cap_lift`); projected onto the sea plane at the cap, as their rest
/// positions are, they would leave row 28 to the sky below the horizon, a dark line beside the
/// Sun's glitter. Above the horizon nothing is drawn.
#[test]
fn the_sea_reaches_the_horizon() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = sea_with(
        &ctx,
        OceanOptions {
            max_distance: 400.0,
            ..OceanOptions::default()
        },
    );
    let c = camera();
    let frame = Frame::new(&ctx, 1.0);
    frame
        .draw(&ctx, |e, t| sea.render_layers(&ctx, e, &c, 3.0, t, (W, H)))
        .expect("layers");
    let bytes = ocean_gpu::readback::read_texture(&ctx, &frame.ambient, 0)
        .expect("read")
        .data;
    let alpha = |x: u32, y: u32| {
        let k = 8 * (y * W + x) as usize + 6;
        f16_to_f32(u16::from_le_bytes([bytes[k], bytes[k + 1]]))
    };
    let horizon = 40.0 - 40.0 * 10f64.to_radians().tan() / 30f64.to_radians().tan();
    for y in 0..H {
        let below = f64::from(y) + 0.5 > horizon;
        for x in 0..W {
            assert_eq!(
                alpha(x, y),
                if below { 1.0 } else { 0.0 },
                "pixel ({x}, {y}), horizon at {horizon:.2}"
            );
        }
    }
}

/// The obscurance scales the sea's ambient light alone: with A = 0 only the Sun's reflection
/// is left, and the sky (where nothing drew) is untouched. Looking away from the Sun (25° up
/// behind the camera) no facet of this sea reflects it towards the eye, so the sea is black.
#[test]
fn the_obscurance_leaves_the_suns_light_and_the_sky() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = sea(&ctx);
    let c = camera_towards(1.0);
    let image = |a: f32| {
        let frame = Frame::new(&ctx, a);
        frame
            .draw(&ctx, |e, t| sea.render_layers(&ctx, e, &c, 3.0, t, (W, H)))
            .expect("layers");
        frame.compose(&ctx, &sea)
    };
    let (full, none) = (image(1.0), image(0.0));
    let single = sea.render_image(&ctx, &c, 3.0, W, H).expect("image");
    // The horizon of a camera 10° down with a 30° half-angle lies at 0.5 − tan 10°/(2 tan 30°)
    // ≈ 0.347 of the height from the top: rows above 25 are sky.
    let (mut sea_pixels, mut black) = (0, 0);
    for y in 0..H {
        for x in 0..W {
            let k = 4 * (y * W + x) as usize;
            if y < 25 {
                assert_eq!(full[k..k + 3], none[k..k + 3], "sky at ({x}, {y})");
                assert!(max_channel_diff(&full[k..], &single[k..]) <= 1);
            } else if y > 30 {
                sea_pixels += 1;
                assert!((0..3).all(|i| none[k + i] <= full[k + i]));
                black += usize::from(none[k..k + 3].iter().all(|&v| v <= 1));
            }
        }
    }
    // The Sun (the default sky's, behind the camera's right) glitters on few of these pixels.
    assert!(
        black * 10 >= sea_pixels * 9,
        "{black} of {sea_pixels} black"
    );
}

/// A relief quad's split light: the ambient target holds albedo × ambient exactly where the
/// quad drew (alpha 1) and nothing elsewhere (alpha 0); direct + ambient is `render_image`'s
/// linear colour (within its 8-bit sRGB encoding), and the depth equals its depth.
#[test]
fn relief_quads_split_their_light() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let n = 64;
    let heights = ocean_relief::maps::value_noise(n, 4, 4, 3);
    let map = ocean_relief::maps::to_map(n, &heights, Edge::Wrap).expect("map");
    let cones = ConeMap::generate(&map, ConeParams::relaxed(4.0)).expect("cones");
    let texture = ReliefTexture::new(&map, &cones).expect("texture");
    let options = ReliefOptions {
        color_format: wgpu::TextureFormat::Rgba8UnormSrgb,
        ..ReliefOptions::default()
    };
    let mut relief = ReliefRenderer::new(&ctx, options).expect("relief");
    relief.set_texture(&ctx, &texture).expect("texture");
    // A 4 m square face 12 m ahead, facing the camera, lit from the upper left.
    let scene = ReliefScene {
        origin: DVec3::new(-2.0, 2.0, -12.0),
        edge_u: DVec3::new(4.0, 0.0, 0.0),
        edge_v: DVec3::new(0.0, 4.0, 0.0),
        tiles: DVec2::ONE,
        depth: 0.4,
        light_dir: DVec3::new(-1.0, 1.0, 1.0),
        light_intensity: 0.7,
        albedo: [0.5, 0.4, 0.3],
        ambient: 0.2,
        ..ReliefScene::default()
    };
    let c = camera();
    let frame = Frame::new(&ctx, 1.0);
    frame
        .draw(&ctx, |e, t| {
            relief.render_layers(&ctx, e, &c, std::slice::from_ref(&scene), t, (W, H))
        })
        .expect("layers");
    let read = |t: &wgpu::Texture| -> Vec<f32> {
        let bytes = ocean_gpu::readback::read_texture(&ctx, t, 0)
            .expect("read")
            .data;
        bytes
            .chunks(2)
            .map(|b| f16_to_f32(u16::from_le_bytes([b[0], b[1]])))
            .collect()
    };
    let (direct, ambient) = (read(&frame.direct), read(&frame.ambient));
    let image = relief.render_image(&ctx, &c, &scene, W, H).expect("image");
    let (mut drawn, mut colour_off) = (0, 0);
    for k in 0..(W * H) as usize {
        let (d, a) = (&direct[4 * k..4 * k + 4], &ambient[4 * k..4 * k + 4]);
        let far = image.depth[k] >= 1.0;
        if far {
            assert_eq!(a[3], 0.0, "pixel {k} drawn");
            continue;
        }
        drawn += 1;
        assert_eq!((d[3], a[3]), (1.0, 1.0), "pixel {k}");
        for c in 0..3 {
            let want = scene.albedo[c] * scene.ambient;
            // rgba16float keeps 11 significant bits: within 2⁻¹⁰ relative (the conversion
            // may round towards zero).
            assert!(
                (a[c] - want).abs() <= want / 1024.0,
                "ambient {} vs {want}",
                a[c]
            );
            let linear = srgb_to_linear(image.rgba[4 * k + c]);
            let sum = (d[c] + a[c]).min(1.0);
            // One level of 8-bit sRGB spans at most 1/80 in linear near white.
            if (sum - linear).abs() > 1.0 / 80.0 {
                colour_off += 1;
            }
        }
    }
    assert!(drawn > 500, "{drawn} pixels drawn");
    assert_eq!(colour_off, 0, "{colour_off} channels off");
}

fn srgb_to_linear(v: u8) -> f32 {
    let c = f32::from(v) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// IEEE 754 binary16 to f32 (normal, subnormal, zero; the targets hold no infinities).
fn f16_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exp = i32::from((h >> 10) & 0x1f);
    let frac = f32::from(h & 0x3ff);
    match exp {
        0 => sign * frac * 2f32.powi(-24),
        31 => sign * f32::INFINITY,
        e => sign * (1.0 + frac / 1024.0) * 2f32.powi(e - 15),
    }
}

/// Targets of another format, or a renderer without depth, are refused before anything is
/// recorded.
#[test]
fn bad_targets_are_refused() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = sea(&ctx);
    let c = camera();
    let frame = Frame::new(&ctx, 1.0);
    // The display-format texture as a light target.
    let out = view(&frame.out);
    let (a, z) = (view(&frame.ambient), view(&frame.depth));
    let wrong = LightTargets {
        direct: &out,
        ambient: &a,
        depth: &z,
    };
    let mut e = ctx
        .device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    let r = sea.render_layers(&ctx, &mut e, &c, 0.0, &wrong, (W, H));
    assert!(
        matches!(r, Err(GpuError::InvalidResource { what, .. }) if what == "direct light target"),
        "{r:?}"
    );
    // A viewport larger than the targets.
    let d = view(&frame.direct);
    let right = LightTargets {
        direct: &d,
        ambient: &a,
        depth: &z,
    };
    let r = sea.render_layers(&ctx, &mut e, &c, 0.0, &right, (W + 1, H));
    assert!(matches!(r, Err(GpuError::InvalidResource { .. })), "{r:?}");
    // The obscurance in another format than R32Float.
    let inputs = ComposeInputs {
        direct: &d,
        ambient: &a,
        obscurance: &a,
    };
    let r = sea.compose(&ctx, &mut e, &inputs, &out, (W, H));
    assert!(
        matches!(r, Err(GpuError::InvalidResource { what, .. }) if what == "obscurance"),
        "{r:?}"
    );
    // A renderer without a depth format.
    let no_depth = OceanRenderer::new(
        &ctx,
        OceanOptions {
            depth_format: None,
            ..OceanOptions::default()
        },
    )
    .expect("renderer");
    let r = no_depth.render_layers(&ctx, &mut e, &c, 0.0, &right, (W, H));
    assert!(
        matches!(r, Err(GpuError::InvalidInput { what, .. }) if what == "depth_format"),
        "{r:?}"
    );
}
