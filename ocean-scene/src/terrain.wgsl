// The island's terrain in `ocean render`: a height field drawn as a grid of triangles, lit by
// the same Sun and sky as the sea (Lambert: albedo/π times the Sun's irradiance on the facet
// plus the environment's, from its order-2 spherical harmonics: sh_irradiance, prepended from
// ocean-gpu's irradiance.wgsl), written
// as linear radiance into the frame's split light targets (`ocean_gpu::LightTargets`): the
// Sun's part and the sky's part, which the ambient obscurance darkens before the sea's
// `compose_fs` tone maps the frame. Positions are relative to the eye, so the numbers stay
// small wherever the island is.
//
// Draw: counts.x × counts.y vertices (vertex j·counts.x + i is height texel (i, j)), indexed as
// two triangles per cell.

struct Terrain {
    // Eye-relative position → clip (WebGPU depth range).
    view_proj: mat4x4<f32>,
    // xyz: grid point (0, 0) at y = 0, relative to the eye; w: spacing, metres.
    origin: vec4<f32>,
    // x, y: points per row and rows; zw: unused.
    counts: vec4<u32>,
    // xyz: unit vector towards the Sun; w: unused.
    sun_dir: vec4<f32>,
    // rgb: the Sun's irradiance on a surface facing it (L_sun Ω_sun).
    sun: vec4<f32>,
    // The environment's irradiance (sky above the horizon, sea below): order-2 spherical
    // harmonic rows, rgb (ocean_brdf::Irradiance::gpu_rows).
    irradiance: array<vec4<f32>, 9>,
}

@group(0) @binding(0) var<uniform> terrain: Terrain;
// Heights, metres above the sea at rest (r32float, textureLoad only).
@group(0) @binding(1) var heights: texture_2d<f32>;

struct Vertex {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) height: f32,
}

fn height_at(i: i32, j: i32) -> f32 {
    let n = vec2<i32>(terrain.counts.xy);
    return textureLoad(heights, clamp(vec2<i32>(i, j), vec2<i32>(0), n - 1), 0).x;
}

@vertex
fn terrain_vs(@builtin(vertex_index) index: u32) -> Vertex {
    let nx = terrain.counts.x;
    let i = i32(index % nx);
    let j = i32(index / nx);
    let s = terrain.origin.w;
    let h = height_at(i, j);
    // Central differences (one-sided at the edges).
    let dx = (height_at(i + 1, j) - height_at(i - 1, j)) / (f32(min(i + 1, i32(nx) - 1) - max(i - 1, 0)) * s);
    let dz = (height_at(i, j + 1) - height_at(i, j - 1)) / (f32(min(j + 1, i32(terrain.counts.y) - 1) - max(j - 1, 0)) * s);
    let p = terrain.origin.xyz + vec3<f32>(f32(i) * s, h, f32(j) * s);
    var out: Vertex;
    out.clip = terrain.view_proj * vec4<f32>(p, 1.0);
    out.normal = normalize(vec3<f32>(-dx, 1.0, -dz));
    out.height = h;
    return out;
}

// Linear albedo by height and slope: wet sand at the waterline, dry sand, grass, rock on the
// steep parts.
fn albedo(height: f32, n: vec3<f32>) -> vec3<f32> {
    let wet = vec3<f32>(0.20, 0.17, 0.12);
    let sand = vec3<f32>(0.50, 0.44, 0.32);
    let grass = vec3<f32>(0.10, 0.17, 0.05);
    let rock = vec3<f32>(0.26, 0.24, 0.22);
    var c = mix(wet, sand, smoothstep(0.2, 0.8, height));
    c = mix(c, grass, smoothstep(1.6, 3.0, height));
    return mix(c, rock, smoothstep(0.25, 0.45, 1.0 - n.y));
}

struct Light {
    // albedo/π × the Sun's irradiance on the facet: direct light, alpha 1.
    @location(0) direct: vec4<f32>,
    // albedo/π × the environment's irradiance on the facet: ambient light, alpha 1, what the ambient
    // obscurance darkens.
    @location(1) ambient: vec4<f32>,
}

// A Lambertian surface of linear `albedo` and unit normal `n`.
fn lambert(albedo: vec3<f32>, n: vec3<f32>) -> Light {
    let a = albedo / 3.14159265;
    var out: Light;
    out.direct = vec4<f32>(a * terrain.sun.rgb * max(dot(n, terrain.sun_dir.xyz), 0.0), 1.0);
    out.ambient = vec4<f32>(a * sh_irradiance(terrain.irradiance, n), 1.0);
    return out;
}

@fragment
fn terrain_fs(in: Vertex) -> Light {
    let n = normalize(in.normal);
    return lambert(albedo(in.height, n), n);
}

// Solids (the pier's posts): triangles from vertex buffers, world positions at location 0,
// unit normals at 1 and linear albedos at 2; `terrain.origin.xyz` is then the world origin
// relative to the eye.
struct SolidVertex {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) albedo: vec3<f32>,
}

@vertex
fn solid_vs(
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
) -> SolidVertex {
    var out: SolidVertex;
    out.clip = terrain.view_proj * vec4<f32>(terrain.origin.xyz + position, 1.0);
    out.normal = normal;
    out.albedo = albedo;
    return out;
}

@fragment
fn solid_fs(in: SolidVertex) -> Light {
    return lambert(in.albedo, normalize(in.normal));
}
