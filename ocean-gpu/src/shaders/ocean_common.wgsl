// The filtered ocean surface of Bruneton, Neyret & Holzschuch (2010), §3.2 and §7.1, shared by
// the renderer (ocean.wgsl) and its probes (ocean_probe.wgsl); prepended after grid_normal.wgsl
// (whose `unit_normal` turns the summed derivatives into the normal). The CPU twins are in
// `ocean_brdf::surface`: `pixel_ray`, `sea_plane_hit`, `pixel_footprint` and
// `FilteredSurface::{position, normal, variance}`; every function below follows one of them.
//
// Frames. World space is right-handed, y up, the sea at rest on y = 0. The shaders never see
// world coordinates: positions are relative to E = (o_x, eye_y, o_z), the camera's eye, and
// rest positions (x, z) relative to o = (o_x, o_z), the eye's horizontal position. So the
// numbers stay small wherever the camera is. The host forms in f64 the matrices of this frame
// and, per wave, the phase at o (see `waves` below), so a phase k·x − ωt + Φ that reaches 10⁸
// rad at t = 10⁶ s or 100 km from the origin never reaches f32 unreduced (ARCHITECTURE.md).
//
// Clip space is WebGPU's (z in [0, w]); the host folds an OpenGL [-1, 1] camera into it, and
// naga's GLSL export (ADJUST_COORDINATE_SPACE) maps it back. Pixel coordinates have their
// origin at the top-left corner, y down, pixel centres at half-integers (as @builtin(position)
// in a fragment shader).

const TAU: f32 = 6.2831853;
const INV_TAU: f32 = 0.15915494;
// `ocean_brdf::surface::MIN_DEPRESSION`: rays less steep than this meet the cap.
const MIN_DEPRESSION: f32 = 1e-6;
// The smallest footprint a weight is computed for, metres: guards λ/size against 0 and NaN.
const MIN_FOOTPRINT: f32 = 1e-9;

// Matches `ocean_gpu::ocean::FrameUniform` (352 bytes).
struct Frame {
    // Camera-relative (minus E) position → clip, WebGPU depth range, the camera's direction.
    view_proj: mat4x4<f32>,
    // Its inverse: clip → camera-relative position.
    inv_view_proj: mat4x4<f32>,
    // x: eye height eye_y (> 0), y: distance cap of the sea-plane hits (m), z: NDC depth of
    // the near plane, w: NDC depth halfway to the far plane (both in WebGPU's range).
    camera: vec4<f32>,
    // xy: viewport size (px), zw: pixel position of grid vertex (0, 0) (−margin).
    viewport: vec4<f32>,
    // x: grid cell size (px), y: N_min, z: N_max, w: exposure.
    grid: vec4<f32>,
    // x: grid vertices per row, y: grid rows, z: number of waves, w: flags (bit 0: the shader
    // sRGB-encodes its output).
    counts: vec4<u32>,
    // xy: unit wind direction (x, z), the x axis of the slope variances; z: Fresnel R at
    // normal incidence; w: the Sun's solid angle Ω_sun (sr).
    sea: vec4<f32>,
    // xyz: unit vector towards the Sun; w: cos of the Sun's angular radius.
    sun_dir: vec4<f32>,
    // rgb: the Sun's radiance L_sun; w: NDC depth of the far plane (WebGPU's range).
    sun_radiance: vec4<f32>,
    // rgb: L_sea, the diffuse radiance leaving the water body (§5.3).
    sea_radiance: vec4<f32>,
    // x: sky map level-0 size (texels), y: its half-width E in the stereographic plane
    // (`SKY_MAP_EXTENT`), z: the least slope variance of the Sun's term (`SUN_MIN_VARIANCE`,
    // §5.1), w: unused.
    sky: vec4<f32>,
    // x: number of probe items (probe entry points only), yzw: unused.
    probe: vec4<u32>,
    // Local waves (§6, `ocean_brdf::local`): xy: the local grid's point (0, 0) relative to o,
    // z: 1 / its spacing (m⁻¹), w: unused.
    local: vec4<f32>,
    // x, y: the local grid's points per row and rows, z: number of local trains, w: unused.
    local_counts: vec4<u32>,
    // The caller's mesh (`mesh_vs`, ocean.wgsl): xyz: its grid point (0, 0) at rest relative
    // to E (so y = −eye_y), w: its grid spacing (m). Zero when no mesh is drawn.
    mesh_grid: vec4<f32>,
    // x, y: the mesh's grid points per row and rows, zw: unused.
    mesh_counts: vec4<u32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;
// One texel column per wave, longest wave first (rgba32float, textureLoad only):
//   row 0: (λ, k_x, k_z, θ₀) with θ₀ = [k·o − ωt + Φ mod 2π], formed in f64 on the host for
//          the frame, so θ(x) = k·(x − o) + θ₀;
//   row 1: (A, A k_x/|k|, A k_z/|k|, 0);
//   row 2: (k·A clamped to 1, (k̂·wind)², S_x, S_y), S the slope variance (Eq. 4, w_r = 1) of
//          this wave and every shorter one, summed in f64 on the host.
@group(0) @binding(1) var waves: texture_2d<f32>;
// The sky map (`ocean_brdf::sky_map::SkyMap`, rgba16float, full mip chain).
@group(0) @binding(2) var sky_map: texture_2d<f32>;
// Linear min/mag/mip filtering, clamp to edge.
@group(0) @binding(3) var sky_sampler: sampler;
// The effective Fresnel table (`ocean_brdf::fresnel_table`): D = M − (1 − cos θ_v)⁵, M of
// Eq. 24, at 33 × 33 nodes, texel (j, i) for cos θ_v = (i/32)² and σ_v = (j/32)² (r32float, textureLoad
// only; bindings 4 and 5 are the probes').
@group(0) @binding(6) var fresnel_table: texture_2d<f32>;
// Local waves' fields over the local grid (rg32float, textureLoad only), one texel per grid
// point: layer 0 holds (s, 0), the open sea's amplitude factor, layer 1 + k the complex
// amplitude μ = (m cos φ, m sin φ) of train set k.
@group(0) @binding(7) var local_fields: texture_2d_array<f32>;
// The local trains, one texel column each (rgba32float, textureLoad only), grouped by set:
//   row 0: (λ, k_x, k_z, θ₀), θ₀ formed per frame in f64 as for the open sea's waves;
//   row 1: (A, A k_x/|k|, A k_z/|k|, set index k);
//   row 2: (k·A clamped to 1, (k̂·wind)², 0, 0).
@group(0) @binding(8) var local_trains: texture_2d<f32>;

// w(N_min, N_max, λ/size) of §3.2 (`Filter::weight`): 0 up to N_min footprints per wavelength,
// 1 from N_max, the smoothstep 3x̄² − 2x̄³ between.
fn wave_weight(wavelength: f32, size: f32) -> f32 {
    let x = wavelength / max(size, MIN_FOOTPRINT);
    let t = clamp((x - frame.grid.y) / (frame.grid.z - frame.grid.y), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// The phase of wave `i` (row-0 texel `a`) at rest position `rest` (relative to o), reduced to
// [-π, π] before sin and cos: GPUs' sin and cos lose accuracy on large arguments.
fn wave_phase(a: vec4<f32>, rest: vec2<f32>) -> f32 {
    let theta = a.y * rest.x + a.z * rest.y + a.w;
    return theta - TAU * round(theta * INV_TAU);
}

// Eq. 2: the displacement Σ w_p t_i at `rest` for a grid cell of `cell` metres (the trochoids
// of ocean-core: Δx = −Σ k̂ A sin θ, y = Σ A cos θ, θ = k·x − ωt + Φ), in .xyz; in .w the number
// of waves summed. Waves are sorted longest first, so the loop stops at the first zero weight
// and distant views cost less (§7.1).
fn displacement(rest: vec2<f32>, cell: f32) -> vec4<f32> {
    var d = vec3<f32>(0.0);
    let n = frame.counts.z;
    let open = open_scale(rest);
    var i = 0u;
    for (; i < n; i++) {
        let a = textureLoad(waves, vec2<u32>(i, 0u), 0);
        let w0 = wave_weight(a.x, cell);
        if w0 <= 0.0 {
            break;
        }
        let w = w0 * open;
        let b = textureLoad(waves, vec2<u32>(i, 1u), 0);
        let theta = wave_phase(a, rest);
        let s = w * sin(theta);
        let c = w * cos(theta);
        d += vec3<f32>(-b.y * s, b.x * c, -b.z * s);
    }
    // The local trains (§6), each weighted by w_p and its set's μ.
    var last = LocalSet(0xffffffffu, vec2<f32>(0.0));
    for (var j = 0u; j < frame.local_counts.z; j++) {
        let a = textureLoad(local_trains, vec2<u32>(j, 0u), 0);
        let w = wave_weight(a.x, cell);
        if w <= 0.0 {
            continue;
        }
        let b = textureLoad(local_trains, vec2<u32>(j, 1u), 0);
        last = local_set(last, u32(b.w), rest);
        let sc = local_sin_cos(a, rest, last.mu, w);
        d += vec3<f32>(-b.y * sc.x, b.x * sc.y, -b.z * sc.x);
    }
    return vec4<f32>(d, f32(i));
}

// A bilinear read of layer `layer` of the local fields at rest position `rest` (relative to
// o), `outside` for the texels past the grid (`LocalWaves::bilinear`).
fn local_field(rest: vec2<f32>, layer: u32, outside: vec2<f32>) -> vec2<f32> {
    let n = vec2<i32>(frame.local_counts.xy);
    // Clamped before the conversion to i32, which is undefined beyond its range; every texel
    // of a point clamped there is outside anyway.
    let g = clamp((rest - frame.local.xy) * frame.local.z, vec2<f32>(-2.0), vec2<f32>(n + 1));
    let f = floor(g);
    let t = g - f;
    let i = vec2<i32>(f);
    let t00 = local_texel(i, n, layer, outside);
    let t10 = local_texel(i + vec2<i32>(1, 0), n, layer, outside);
    let t01 = local_texel(i + vec2<i32>(0, 1), n, layer, outside);
    let t11 = local_texel(i + vec2<i32>(1, 1), n, layer, outside);
    let a = t00 * (1.0 - t.x) + t10 * t.x;
    let b = t01 * (1.0 - t.x) + t11 * t.x;
    return a * (1.0 - t.y) + b * t.y;
}

fn local_texel(i: vec2<i32>, n: vec2<i32>, layer: u32, outside: vec2<f32>) -> vec2<f32> {
    if any(i < vec2<i32>(0)) || any(i >= n) {
        return outside;
    }
    return textureLoad(local_fields, i, layer, 0).xy;
}

// The open sea's amplitude factor s at `rest`: 1 beyond the local grid.
fn open_scale(rest: vec2<f32>) -> f32 {
    return clamp(local_field(rest, 0u, vec2<f32>(1.0, 0.0)).x, 0.0, 1.0);
}

// The set whose μ was read last, so that the trains of one set read it once.
struct LocalSet {
    index: u32,
    mu: vec2<f32>,
}

fn local_set(last: LocalSet, index: u32, rest: vec2<f32>) -> LocalSet {
    if index == last.index {
        return last;
    }
    return LocalSet(index, local_field(rest, index + 1u, vec2<f32>(0.0)));
}

// w·m sin(θ + φ) and w·m cos(θ + φ) of a local train (row-0 texel `a`) at `rest`, by angle
// addition with μ = (m cos φ, m sin φ) (`WaveSet::add_filtered_sums_f64`).
fn local_sin_cos(a: vec4<f32>, rest: vec2<f32>, mu: vec2<f32>, w: f32) -> vec2<f32> {
    let theta = wave_phase(a, rest);
    let s = sin(theta);
    let c = cos(theta);
    return w * vec2<f32>(s * mu.x + c * mu.y, c * mu.x - s * mu.y);
}

// What the fragment stage needs of the surface at one pixel (`ocean_brdf::PixelSurface`).
struct PixelSurface {
    // Eq. 3: the unit normal, each wave weighted by w_n.
    normal: vec3<f32>,
    // The unit normal of the displaced geometry (Eq. 2's waves, each weighted by w_p for the
    // grid-cell footprint L): the surface that masks (§3.2).
    geometry_normal: vec3<f32>,
    // Eq. 4: σ_x², σ_y² of what the normal does not resolve (w_r = 1 − w_n), along the wind
    // and across it.
    variance: vec2<f32>,
    // The slope variances of the waves the normal resolves and the geometry does not (weights
    // w_n − w_p, `VarianceTable::normal_only`): the slopes of `normal` relative to
    // `geometry_normal`, which the geometry does not mask (see `visible_normal`).
    normal_only: vec2<f32>,
    // Waves summed (those with w_n > 0).
    count: u32,
}

// The trochoid slope variance of steepness ka (Appendix A), 1 − √(1 − k²A²), in the form that
// keeps its digits for small ka (`ocean_brdf::variance::trochoid_slope_variance`).
fn trochoid_slope_variance(ka: f32) -> f32 {
    let s = ka * ka;
    return s / (1.0 + sqrt(max(1.0 - s, 0.0)));
}

// Eq. 3 and Eq. 4 at `rest` for a pixel footprint of `l` metres, and the geometry's normal
// and the normal-only variance for a grid-cell footprint of `cell` metres
// (`FilteredSurface::pixel`, `LocalWaves::point`), in one loop over the waves with w_n > 0
// (longest first, stopping at the first zero weight, §7.1; with cell ≥ l, as cell_px ≥ 1
// gives, every wave with w_p > 0 has w_n > 0 too).
//
// Eq. 4 is the total variance minus the resolved waves' share (§7.1). Formed as the total
// minus an f32 sum, that difference would cancel near the camera, where nearly every wave is
// resolved; so the host stores, per wave, the f64 variance S of that wave and all shorter ones,
// and the shader adds S at the first unresolved wave to what the partly resolved waves leave,
// Σ_{w_n > 0} var(k A w_r): the same sum, visiting the same waves, without cancellation. (§7.1
// evaluates Eq. 4 this way, so what it subtracts per wave is var(k A) − var(k A w_r), as
// `VarianceTable::unresolved` explains.)
fn pixel_surface(rest: vec2<f32>, l: f32, cell: f32) -> PixelSurface {
    var jxx = 1.0;
    var jxz = 0.0;
    var jzz = 1.0;
    var sx = 0.0;
    var sz = 0.0;
    // The geometry's sums, as the above with w_p.
    var gxx = 1.0;
    var gxz = 0.0;
    var gzz = 1.0;
    var gsx = 0.0;
    var gsz = 0.0;
    var variance = vec2<f32>(0.0);
    var normal_only = vec2<f32>(0.0);
    let n = frame.counts.z;
    let open = open_scale(rest);
    var i = 0u;
    for (; i < n; i++) {
        let a = textureLoad(waves, vec2<u32>(i, 0u), 0);
        let w = wave_weight(a.x, l);
        if w <= 0.0 {
            break;
        }
        let b = textureLoad(waves, vec2<u32>(i, 1u), 0);
        let v = textureLoad(waves, vec2<u32>(i, 2u), 0);
        let theta = wave_phase(a, rest);
        let sin_theta = sin(theta);
        let cos_theta = cos(theta);
        let s = w * open * sin_theta;
        let c = w * open * cos_theta;
        // ∂/∂x₀ and ∂/∂z₀ of Eq. 2's trochoid, as ocean-core's PointSums.
        jxx -= b.y * a.y * c;
        jxz -= b.y * a.z * c;
        jzz -= b.z * a.z * c;
        sx -= b.x * a.y * s;
        sz -= b.x * a.z * s;
        let wp = wave_weight(a.x, cell);
        let gs = wp * open * sin_theta;
        let gc = wp * open * cos_theta;
        gxx -= b.y * a.y * gc;
        gxz -= b.y * a.z * gc;
        gzz -= b.z * a.z * gc;
        gsx -= b.x * a.y * gs;
        gsz -= b.x * a.z * gs;
        let axes = vec2<f32>(v.y, 1.0 - v.y);
        variance += trochoid_slope_variance(v.x * (1.0 - w)) * axes;
        normal_only += trochoid_slope_variance(v.x * max(w - wp, 0.0)) * axes;
    }
    if i < n {
        variance += textureLoad(waves, vec2<u32>(i, 2u), 0).zw;
    }
    // The open sea's factor s scales its slopes by s and its variances by s² (small-slope
    // form, `ocean_brdf::local`).
    variance *= open * open;
    normal_only *= open * open;
    // The local trains (§6): their derivatives weighted by w_n and μ join the sums; what w_n
    // leaves, a trochoid of steepness k·A·|μ|·w_r, joins the variances.
    var last = LocalSet(0xffffffffu, vec2<f32>(0.0));
    for (var j = 0u; j < frame.local_counts.z; j++) {
        let a = textureLoad(local_trains, vec2<u32>(j, 0u), 0);
        let b = textureLoad(local_trains, vec2<u32>(j, 1u), 0);
        let v = textureLoad(local_trains, vec2<u32>(j, 2u), 0);
        last = local_set(last, u32(b.w), rest);
        let w = wave_weight(a.x, l);
        let wp = wave_weight(a.x, cell);
        if w > 0.0 {
            let sc_unit = local_sin_cos(a, rest, last.mu, 1.0);
            let sc = w * sc_unit;
            jxx -= b.y * a.y * sc.y;
            jxz -= b.y * a.z * sc.y;
            jzz -= b.z * a.z * sc.y;
            sx -= b.x * a.y * sc.x;
            sz -= b.x * a.z * sc.x;
            let gc = wp * sc_unit;
            gxx -= b.y * a.y * gc.y;
            gxz -= b.y * a.z * gc.y;
            gzz -= b.z * a.z * gc.y;
            gsx -= b.x * a.y * gc.x;
            gsz -= b.x * a.z * gc.x;
        }
        let m = length(last.mu);
        let axes = vec2<f32>(v.y, 1.0 - v.y);
        variance += trochoid_slope_variance(min(v.x * m * (1.0 - w), 1.0)) * axes;
        normal_only += trochoid_slope_variance(min(v.x * m * max(w - wp, 0.0), 1.0)) * axes;
    }
    var out: PixelSurface;
    out.normal = unit_normal(jxx, jxz, jzz, sx, sz);
    out.geometry_normal = unit_normal(gxx, gxz, gzz, gsx, gsz);
    out.variance = variance;
    out.normal_only = normal_only;
    out.count = i;
    return out;
}

// The camera-relative point of NDC `ndc` (WebGPU depth range).
fn unproject(ndc: vec3<f32>) -> vec3<f32> {
    let h = frame.inv_view_proj * vec4<f32>(ndc, 1.0);
    return h.xyz / h.w;
}

// `pixel_ray`: the view ray through a pixel, from its point on the near plane (camera-relative)
// along the unit direction towards its point halfway to the far plane in NDC (finite even for an
// infinite far plane; perspective and orthographic alike).
struct Ray {
    origin: vec3<f32>,
    dir: vec3<f32>,
}

fn pixel_ray(pixel: vec2<f32>) -> Ray {
    let ndc = vec2<f32>(pixel.x / frame.viewport.x * 2.0 - 1.0, 1.0 - pixel.y / frame.viewport.y * 2.0);
    let a = unproject(vec3<f32>(ndc, frame.camera.z));
    let b = unproject(vec3<f32>(ndc, frame.camera.w));
    return Ray(a, normalize(b - a));
}

// `sea_plane_hit`: where the ray meets y = 0, at most the distance cap along it; rays that go
// up, run along the horizon or would meet the plane beyond the cap stop at the cap, projected
// onto the plane (the grid's sky part folds onto the far sea). Relative to o.
fn sea_plane_hit(ray: Ray) -> vec2<f32> {
    let height = ray.origin.y + frame.camera.x;
    let down = -ray.dir.y;
    var s = frame.camera.y;
    if down > MIN_DEPRESSION {
        s = min(max(height, 0.0) / down, frame.camera.y);
    }
    return (ray.origin + ray.dir * s).xz;
}

fn pixel_hit(pixel: vec2<f32>) -> vec2<f32> {
    return sea_plane_hit(pixel_ray(pixel));
}

// `pixel_footprint`: the longer of the distances between the sea-plane hits of the rays through
// the pixel's opposite edge midpoints, horizontally and vertically (metres): the longer axis of
// the pixel's projection onto the sea, so no wave aliases in either direction.
fn pixel_footprint(pixel: vec2<f32>) -> f32 {
    let dx = pixel_hit(pixel + vec2<f32>(0.5, 0.0)) - pixel_hit(pixel - vec2<f32>(0.5, 0.0));
    let dy = pixel_hit(pixel + vec2<f32>(0.0, 0.5)) - pixel_hit(pixel - vec2<f32>(0.0, 0.5));
    return max(length(dx), length(dy));
}

// One vertex of the projected grid (§3.2, Fig. 3): a screen point projected on the sea at rest,
// displaced by Eq. 2 with w_p for the grid-cell footprint L = cell_px × pixel footprint.
struct GridPoint {
    // Rest position (x, z), relative to o.
    rest: vec2<f32>,
    // Displaced position (x, world y, z), horizontally relative to o.
    position: vec3<f32>,
    // L, metres.
    cell: f32,
    // Waves summed (those with w_p > 0).
    count: u32,
}

fn grid_point(pixel: vec2<f32>) -> GridPoint {
    let rest = pixel_hit(pixel);
    let cell = frame.grid.x * pixel_footprint(pixel);
    let d = displacement(rest, cell);
    var g: GridPoint;
    g.rest = rest;
    g.position = vec3<f32>(rest.x, 0.0, rest.y) + d.xyz;
    g.cell = cell;
    g.count = u32(d.w);
    return g;
}
