// The ocean renderer of Bruneton, Neyret & Holzschuch (2010), §7.1: a projected grid displaced by
// the filtered trochoids (vertex stage, Eq. 2), per-pixel filtered normals and slope variances
// (fragment stage, Eq. 3 and 4) lit by Algorithm 5.1, and a sky background. Assembled after
// grid_normal.wgsl, ocean_common.wgsl and ocean_light.wgsl; driven by `ocean_gpu::OceanRenderer`.
//
// Draw calls (no vertex buffers; bindings of ocean_common.wgsl, group 0):
// - `sky_vs`/`sky_fs`: 3 vertices, a full-screen triangle on the far plane: the sky map's
//   radiance towards each pixel's view direction (the below-horizon radiance under the
//   horizon) plus the Sun's disc. Drawn first, with no depth write.
// - `ocean_vs`/`ocean_fs`: the projected grid, frame.counts.x × frame.counts.y vertices,
//   vertex (i, j) at pixel frame.viewport.zw + cell_px (i, j), indexed as triangles of the
//   cells (vertex index j·counts.x + i). The grid overlaps the viewport by a margin on every
//   side, so waves that pull its edges inwards do not uncover the background.
// - `mesh_vs`/`mesh_fs`: the caller's own water mesh instead of the projected grid (a wave
//   train box scene's grid evaluated on the CPU each frame): vertex buffers at locations 0
//   (position relative to the mesh's grid point (0, 0) at rest, vec3) and 1 (unit normal,
//   vec3), vertex index j·mesh_counts.x + i for grid point (i, j), drawn as indexed
//   triangles with depth. It writes linear radiance to two targets, the direct (Sun) part at
//   location 0 and the ambient (sky and sea) part at location 1, alpha 1, for an ambient
//   obscurance pass to darken the ambient part alone.
// - `ocean_vs`/`ocean_layers_fs`: the projected grid with the light split as `mesh_fs` splits
//   it (direct and ambient targets), for a frame that other renderers share and an ambient
//   obscurance darkens (`OceanRenderer::render_layers`).
// - `sky_vs`/`compose_fs`: after the mesh pass (and the obscurance), the full-screen triangle
//   that writes each pixel's final colour: display(direct + A · ambient) where the mesh drew
//   (ambient alpha 1), the sky (as `sky_fs`) elsewhere. No depth test.
// - `sky_vs`/`compose_ms_fs`: `compose_fs` over multisampled (4×) targets: each sample's
//   radiance composed and tone-mapped, the four averaged, then encoded.
//
// Output: tone-mapped colour, sRGB-encoded by the shader when frame.counts.w bit 0 is set (a
// non-sRGB target such as rgba8unorm), linear otherwise (an sRGB target encodes it).

struct OceanVertex {
    @builtin(position) clip: vec4<f32>,
    // Rest position (x, z), relative to o: where the fragment evaluates Eq. 3 and 4.
    @location(0) rest: vec2<f32>,
    // Displaced position relative to the eye: −position is the direction towards the viewer.
    @location(1) position: vec3<f32>,
}

// How far above the sea plane a grid vertex is drawn: 0 where its pixel's ray meets the sea
// within the distance cap; beyond it, the height of the ray at the cap, at most the eye's
// height (rays along or above the horizon). `sea_plane_hit` stops those rays at the cap and
// projects the point onto the plane, which the eye sees below its pixel: the grid's far row
// would end a fraction of a pixel short of the horizon (0.25 px at 2160 rows from 6 m with the
// 50 km cap), and that band would show the sky's radiance below the horizon, a dark line
// beside the Sun's glitter. Lifted back onto its ray, the vertex projects onto its own pixel
// and the sea reaches the horizon. The rest position, and so the waves (filtered out at the
// cap's footprint) and the lighting, are `grid_point`'s.
fn cap_lift(ray: Ray) -> f32 {
    let height = ray.origin.y + frame.camera.x;
    let down = -ray.dir.y;
    if down > MIN_DEPRESSION && max(height, 0.0) <= down * frame.camera.y {
        return 0.0;
    }
    return clamp(height - down * frame.camera.y, 0.0, max(height, 0.0));
}

@vertex
fn ocean_vs(@builtin(vertex_index) index: u32) -> OceanVertex {
    let nx = frame.counts.x;
    let ij = vec2<f32>(f32(index % nx), f32(index / nx));
    let pixel = frame.viewport.zw + ij * frame.grid.x;
    let g = grid_point(pixel);
    let lift = cap_lift(pixel_ray(pixel));
    let relative = vec3<f32>(g.position.x, g.position.y + lift - frame.camera.x, g.position.z);
    var out: OceanVertex;
    out.clip = frame.view_proj * vec4<f32>(relative, 1.0);
    out.rest = g.rest;
    out.position = relative;
    return out;
}

// Algorithm 5.1 for the projected grid's fragment at pixel `pixel` (`sea::pixel_color` of
// `FilteredSurface::pixel(rest, t, l, cell_px · l)`): the normal (Eq. 3) and the variance
// (Eq. 4) for the pixel's own footprint l (not the grid cell's: normals stay exact farther than
// the geometry, §3.2), the geometry's normal and the normal-only variance for the grid cell's
// footprint L = cell_px · l at the same pixel (what the vertex stage's w_p is made of, evaluated
// where the fragment is), and the masking-aware normal of the two (`visible_normal`).
fn grid_light(pixel: vec2<f32>, rest: vec2<f32>, position: vec3<f32>) -> SeaLight {
    let l = pixel_footprint(pixel);
    let s = pixel_surface(rest, l, frame.grid.x * l);
    let v = normalize(-position);
    let wind = frame.sea.xy;
    let n = visible_normal(v, s.normal, s.geometry_normal, wind, s.normal_only, s.variance);
    return sea_color(v, n, wind, s.variance);
}

@fragment
fn ocean_fs(in: OceanVertex) -> @location(0) vec4<f32> {
    let light = grid_light(in.clip.xy, in.rest, in.position);
    return display(light.sun + light.sky + light.sea);
}

// `ocean_fs` with its light split for an ambient obscurance pass (`MeshOutput`): the Sun's
// reflection (Eq. 15) at location 0, the sky's reflection and the refracted light (Eq. 21, 28)
// at location 1, linear, alpha 1. `compose_fs` composes the frame from them.
@fragment
fn ocean_layers_fs(in: OceanVertex) -> MeshOutput {
    let light = grid_light(in.clip.xy, in.rest, in.position);
    var out: MeshOutput;
    out.direct = vec4<f32>(light.sun, 1.0);
    out.ambient = vec4<f32>(light.sky + light.sea, 1.0);
    return out;
}

struct SkyVertex {
    @builtin(position) clip: vec4<f32>,
}

@vertex
fn sky_vs(@builtin(vertex_index) index: u32) -> SkyVertex {
    // (−1, −1), (3, −1), (−1, 3): one triangle covering the viewport.
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    var out: SkyVertex;
    out.clip = vec4<f32>(uv * 2.0 - vec2<f32>(1.0), frame.sun_radiance.w, 1.0);
    return out;
}

@fragment
fn sky_fs(in: SkyVertex) -> @location(0) vec4<f32> {
    return display(sky_radiance(in.clip.xy));
}

// The radiance the environment sends towards the viewer through `pixel`: the sky map, and the
// Sun's disc.
fn sky_radiance(pixel: vec2<f32>) -> vec3<f32> {
    let dir = pixel_ray(pixel).dir;
    // The sky map's level 0 (the sky is smooth at the scale of a pixel); outside the horizon
    // circle it holds the radiance the environment shows below the horizon (§6). The bilinear
    // blend across that circle would draw the texels' staircase along the horizon, so a
    // direction above (below) the horizon is read at least 1.5 texels inside (outside) it: all
    // four texels of its sample then lie on its side.
    let margin = 1.5 * 2.0 * frame.sky.y / frame.sky.x;
    var u = stereographic(dir);
    let len = length(u);
    let above = dir.y > 0.0;
    if above && len > 1.0 - margin {
        u *= (1.0 - margin) / len;
    } else if !above && len > 0.0 && len < 1.0 + margin {
        u *= (1.0 + margin) / len;
    }
    var radiance = textureSampleLevel(sky_map, sky_sampler, sky_texcoord(u), 0.0).rgb;
    if dot(dir, frame.sun_dir.xyz) >= frame.sun_dir.w {
        radiance += frame.sun_radiance.rgb;
    }
    return radiance;
}

// The mesh pass's targets and the ambient obscurance, read by `compose_fs` one texel per pixel
// (textureLoad only): the linear direct and ambient radiances `mesh_fs` wrote (rgba32float;
// or rgba16float, whose 3 significant digits and 65504 limit the tone map cannot tell apart
// from f32 as long as exposure × 65504 saturates it, as the default exposure 8 does), and the
// obscurance A in [0, 1] (r32float, 1 = unoccluded; an ambient obscurance pass's output, such
// as the exported `sao_blur`'s, covering the viewport pixel for pixel).
@group(0) @binding(9) var mesh_direct: texture_2d<f32>;
@group(0) @binding(10) var mesh_ambient: texture_2d<f32>;
@group(0) @binding(11) var obscurance: texture_2d<f32>;
// The same direct and ambient radiances in multisampled targets (4 samples per pixel, WebGPU's
// one multisample count), read by `compose_ms_fs` sample by sample.
@group(0) @binding(12) var mesh_direct_ms: texture_multisampled_2d<f32>;
@group(0) @binding(13) var mesh_ambient_ms: texture_multisampled_2d<f32>;

struct MeshVertex {
    @builtin(position) clip: vec4<f32>,
    // The grid point's rest position (x, z), relative to o: where the open sea's waves are
    // evaluated (Eq. 3 and 4), as `OceanVertex::rest`.
    @location(0) rest: vec2<f32>,
    // Position relative to the eye.
    @location(1) position: vec3<f32>,
    // The mesh's normal.
    @location(2) normal: vec3<f32>,
}

@vertex
fn mesh_vs(
    @builtin(vertex_index) index: u32,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
) -> MeshVertex {
    // Grid point (i, j) of vertex j·nx + i rests at mesh_grid.xz + (i, j)·spacing.
    let nx = max(frame.mesh_counts.x, 1u);
    let ij = vec2<f32>(f32(index % nx), f32(index / nx));
    let relative = frame.mesh_grid.xyz + position;
    var out: MeshVertex;
    out.clip = frame.view_proj * vec4<f32>(relative, 1.0);
    out.rest = frame.mesh_grid.xz + ij * frame.mesh_grid.w;
    out.position = relative;
    out.normal = normal;
    return out;
}

struct MeshOutput {
    // Linear radiance of the Sun's reflection (Eq. 15), alpha 1.
    @location(0) direct: vec4<f32>,
    // Linear radiance of the sky's reflection and the refracted light (Eq. 21, 28), alpha 1:
    // the part an ambient obscurance darkens.
    @location(1) ambient: vec4<f32>,
}

// A grid-cell footprint (metres) for which no wave has a weight w_p > 0: `mesh_fs`'s open sea
// is in no geometry.
const NO_GEOMETRY_CELL: f32 = 1e30;

// The least y of a unit normal whose slope is taken (a slope of 10³): the mesh's normals and
// the filtered ones point up, and a grazing one must not divide by zero.
const MIN_NORMAL_Y: f32 = 1e-3;

// The slope (∂y/∂x, ∂y/∂z) of the surface whose unit normal is `n`.
fn normal_slope(n: vec3<f32>) -> vec2<f32> {
    return -n.xz / max(n.y, MIN_NORMAL_Y);
}

@fragment
fn mesh_fs(in: MeshVertex) -> MeshOutput {
    // The mesh's own slope at the pixel, and an estimate of what the pixel does not resolve of
    // it. The lighting paper's model takes any waves whose slope variance is known (§6, "local
    // waves"); a mesh brings no statistics of its own, so its unresolved slope variance is
    // estimated from the screen-space derivatives of its interpolated slope: a slope varying
    // linearly by d_x per pixel across and d_y per pixel down, over a pixel's square, has the
    // variance (d_x² + d_y²)/12 along each axis (a uniform distribution over [−½, ½]²). Where
    // the mesh's cells shrink below a pixel, the differences between neighbouring pixels grow
    // with the mesh's detail that the pixel averages, and the estimate turns that detail into
    // roughness instead of aliasing. Measured along the wind and across it, the axes of the
    // variances of Eq. 4. (Derivatives first: they need uniform control flow.)
    let mesh_slope = normal_slope(normalize(in.normal));
    let dx = dpdx(mesh_slope);
    let dy = dpdy(mesh_slope);
    let wind = frame.sea.xy;
    let across = vec2<f32>(-wind.y, wind.x);
    let along_var = dot(dx, wind) * dot(dx, wind) + dot(dy, wind) * dot(dy, wind);
    let across_var = dot(dx, across) * dot(dx, across) + dot(dy, across) * dot(dy, across);
    let mesh_variance = vec2<f32>(along_var, across_var) / 12.0;

    // The open sea's waves at the mesh's rest position, filtered for the pixel (Eq. 3, 4), as
    // `ocean_fs` does; the mesh carries the geometry, these waves only the normal and the
    // BRDF. Without a spectrum (no waves) the normal is +y and the variance 0.
    let l = pixel_footprint(in.clip.xy);
    let s = pixel_surface(in.rest, l, NO_GEOMETRY_CELL);
    // The two surfaces superposed as height fields: slopes add (the spectrum's waves ride on
    // the mesh, their horizontal displacement neglected), and so do the independent slope
    // variances.
    let slope = mesh_slope + normal_slope(s.normal);
    let n = normalize(vec3<f32>(-slope.x, 1.0, -slope.y));
    let v = normalize(-in.position);
    let variance = s.variance + mesh_variance;
    // Masking (§3.2, `visible_normal`): here the geometry is the mesh's own, so its normal is the
    // geometry's normal, and none of the open sea's waves is in it: every slope they add to the
    // normal is unmasked, with the variances of w_n (w_p = 0 for all, `NO_GEOMETRY_CELL`), while
    // the BRDF's slopes are the open sea's unresolved ones and the mesh's own.
    let n_visible = visible_normal(v, n, normalize(in.normal), wind, s.normal_only, variance);
    let light = sea_color(v, n_visible, wind, variance);
    var out: MeshOutput;
    out.direct = vec4<f32>(light.sun, 1.0);
    out.ambient = vec4<f32>(light.sky + light.sea, 1.0);
    return out;
}

@fragment
fn compose_fs(in: SkyVertex) -> @location(0) vec4<f32> {
    let p = vec2<i32>(in.clip.xy);
    let ambient = textureLoad(mesh_ambient, p, 0);
    if ambient.a == 0.0 {
        return display(sky_radiance(in.clip.xy));
    }
    let direct = textureLoad(mesh_direct, p, 0).rgb;
    let a = clamp(textureLoad(obscurance, p, 0).x, 0.0, 1.0);
    return display(direct + a * ambient.rgb);
}

// The resolve of an antialiased frame. Each sample is composed as `compose_fs` composes a
// pixel (A of the pixel: the obscurance is computed once per pixel; the sky towards the
// sample's own position where nothing covered it) and tone-mapped on its own, and the display
// values are averaged before the encoding: what a supersampled image shows. Averaging the
// radiances first would let a Sun glint or a bright sky that covers one sample of an edge
// pixel saturate the whole pixel. The sky is looked up per sample because the horizon crosses
// pixels: a pixel whose centre lies just below it has samples above it that the sea does not
// cover, and the sky towards the centre is the radiance below the horizon (a grey line).
@fragment
fn compose_ms_fs(in: SkyVertex) -> @location(0) vec4<f32> {
    let p = vec2<i32>(in.clip.xy);
    let a = clamp(textureLoad(obscurance, p, 0).x, 0.0, 1.0);
    // WebGPU's (and Vulkan's, D3D's) standard positions of 4 samples, from the pixel's centre
    // in pixels, y down.
    var offsets = array<vec2<f32>, 4>(
        vec2<f32>(-0.125, -0.375),
        vec2<f32>(0.375, -0.125),
        vec2<f32>(-0.375, 0.125),
        vec2<f32>(0.125, 0.375),
    );
    var sum = vec3<f32>(0.0);
    for (var i = 0; i < 4; i++) {
        let ambient = textureLoad(mesh_ambient_ms, p, i);
        var radiance: vec3<f32>;
        if ambient.a == 0.0 {
            radiance = sky_radiance(in.clip.xy + offsets[i]);
        } else {
            radiance = textureLoad(mesh_direct_ms, p, i).rgb + a * ambient.rgb;
        }
        sum += tone_map(radiance);
    }
    return encode_display(0.25 * sum);
}
