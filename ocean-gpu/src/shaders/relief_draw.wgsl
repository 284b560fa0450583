// The relief-mapped polygon (after relief_common.wgsl): the vertex stage places the polygon, the
// fragment stage traces the viewing ray through the relief texture with the uniform's method,
// shades the hit with the relief normal and a directional light (self-shadowed by tracing the
// light ray with the same cone map), and writes the hit's depth, so the relief occludes and is
// occluded correctly (section 18.2; ocean_relief::occlusion).

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    // Position on the polygon relative to the eye (world units).
    @location(0) rel: vec3<f32>,
    // Texture coordinates (texture widths).
    @location(1) uv: vec2<f32>,
}

// The polygon as a fan of two triangles, (0, 1, 2) and (0, 2, 3): 6 vertices, no vertex buffer.
// A triangle repeats its last corner, so the second triangle has no area.
@vertex
fn relief_vs(@builtin(vertex_index) index: u32) -> VsOut {
    var fan = array<u32, 6>(0u, 1u, 2u, 0u, 2u, 3u);
    let k = fan[min(index, 5u)];
    let pair = relief.polygon[k >> 1u];
    let c = select(pair.xy, pair.zw, (k & 1u) == 1u);
    let p = relief.quad_origin.xyz + c.x * relief.quad_u.xyz + c.y * relief.quad_v.xyz;
    var out: VsOut;
    out.clip = relief.view_proj * vec4<f32>(p, 1.0);
    out.rel = p;
    out.uv = vec2<f32>(c.x * relief.quad_u.w, c.y * relief.quad_v.w);
    return out;
}

struct FsOut {
    @location(0) color: vec4<f32>,
    @builtin(frag_depth) depth: f32,
}

// Linear to sRGB (the piecewise standard curve).
fn relief_srgb(c: vec3<f32>) -> vec3<f32> {
    let x = clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
    let lo = x * 12.92;
    let hi = 1.055 * pow(x, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(hi, lo, x <= vec3<f32>(0.0031308));
}

// The shading of one fragment: the hit's depth and its light, split into the directional
// light (self-shadowed) and the ambient term, linear.
struct ReliefShade {
    depth: f32,
    direct: vec3<f32>,
    ambient: vec3<f32>,
}

// Traces the fragment's viewing ray and shades the hit (discards the back of the quad).
fn relief_shade(in: VsOut) -> ReliefShade {
    // The level of detail, once, before anything branches (derivatives need uniform control
    // flow) and before the tracer's loops (ocean_relief::lod).
    relief_use_level(relief_lod(dpdx(in.uv), dpdy(in.uv)));
    let t = relief.tangent.xyz;
    let b = relief.bitangent.xyz;
    let n = relief.normal.xyz;
    // The unit viewing direction: parallel rays for an orthographic camera, from the eye for a
    // perspective one.
    var dir = relief.view_dir.xyz;
    if bitcast<f32>(relief_ctl(bitcast<u32>(relief.view_dir.w))) == 0.0 {
        dir = normalize(in.rel);
    }
    let view = vec3<f32>(dot(dir, t), dot(dir, b), dot(dir, n));
    if view.z >= 0.0 {
        // The back of the quad: the relief lies under its front.
        discard;
    }
    let depth_scale = relief.shading.x;
    let l = relief.light.xyz;
    let light = vec3<f32>(dot(l, t), dot(l, b), dot(l, n));
    let shadows = (relief_ctl(relief.steps.z) & FLAG_SHADOWS) != 0u;
    // The viewing ray, then (self-shadowing) the light ray to its hit, through one call site
    // of the tracer: shader compilers inline every call, and the tracer is most of the shader,
    // so a second call site would double its compile time (seconds on a software rasteriser).
    // relief_shadow, split around its trace.
    var hit: Hit;
    var shadow = 0.0;
    var start = in.uv;
    var ray = relief_view_ray(view, depth_scale);
    var rays = 1u;
    for (var k = 0u; k < rays; k++) {
        let h = relief_trace(start, ray);
        if k == 0u {
            hit = h;
            if shadows && light.z <= 0.0 {
                shadow = 1.0;
            } else if shadows {
                rays = 2u;
                start = relief_shadow_start(h.pos, light, depth_scale);
                ray = relief_view_ray(-light, depth_scale);
            }
        } else {
            shadow = relief_shadow_of(h, hit.pos, relief.shading.y).x;
        }
    }
    // occlusion::view_distance: the hit lies d depth_world / cos(theta) beyond the polygon.
    let cos_theta = -view.z / length(view);
    let distance = hit.pos.z * relief.bitangent.w / cos_theta;
    let p = in.rel + dir * distance;
    let clip = relief.view_proj * vec4<f32>(p, 1.0);
    var out: ReliefShade;
    out.depth = clamp(clip.z / clip.w, 0.0, 1.0);

    // normal.w is the depth in level-0 texels; a level-l texel is 2^l of them. The factor
    // 2^-l is built from its exponent bits (GLSL 330 has no ldexp), so the product is exact.
    let texel_scale = bitcast<f32>(u32(127 - relief_level) << 23u);
    let normal = relief_normal(hit.pos.x, hit.pos.y, relief.normal.w * texel_scale);
    let diffuse = max(dot(normal, light), 0.0) * relief.light.w * (1.0 - shadow);
    out.direct = relief.albedo.rgb * relief.light_color.rgb * diffuse;
    // The environment's light on the relief normal taken to world space, plus the constant
    // ambient.
    let world_normal = normalize(t * normal.x + b * normal.y + n * normal.z);
    let sky = sh_irradiance(relief.irradiance, world_normal);
    out.ambient = relief.albedo.rgb * (relief.albedo.a + sky);
    return out;
}

@fragment
fn relief_fs(in: VsOut) -> FsOut {
    let shade = relief_shade(in);
    var color = shade.direct + shade.ambient;
    if (relief_ctl(relief.steps.z) & FLAG_SRGB_ENCODE) != 0u {
        color = relief_srgb(color);
    }
    var out: FsOut;
    out.depth = shade.depth;
    out.color = vec4<f32>(color, 1.0);
    return out;
}

struct LayersOut {
    // The directional light's radiance, alpha 1.
    @location(0) direct: vec4<f32>,
    // The ambient term, alpha 1: what an ambient obscurance darkens.
    @location(1) ambient: vec4<f32>,
    @builtin(frag_depth) depth: f32,
}

// `relief_fs` into split light targets (`ocean_gpu::LightTargets`), linear, never encoded.
@fragment
fn relief_layers_fs(in: VsOut) -> LayersOut {
    let shade = relief_shade(in);
    var out: LayersOut;
    out.direct = vec4<f32>(shade.direct, 1.0);
    out.ambient = vec4<f32>(shade.ambient, 1.0);
    out.depth = shade.depth;
    return out;
}
