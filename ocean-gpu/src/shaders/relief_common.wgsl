// Relief mapping by relaxed cone stepping (Policarpo & Oliveira, GPU Gems 3 ch. 18): the
// tracers, the self-shadow test and the relief normal, shared by the draw pass (relief_draw.wgsl)
// and the parity probe (relief_probe.wgsl).
//
// Every function here is the CPU twin's f32 arithmetic, operation for operation, in the same
// order (ocean_relief::sample, ::trace, ::shadow): the bilinear fetch is done by hand from four
// textureLoad()s with the weights and the edge handling of ocean_relief::sample::Taps (no
// hardware filtering, so the surface is bit for bit the one the CPU tracers and the cone maps
// see), and textureLoad() needs no implicit level of detail, so the marching loops may branch.
//
// Level of detail (ocean_relief::lod). The texture may hold mip levels, each a relief texture
// of its own box-filtered surface with its own cones (ReliefMips, QuadReliefMips), packed side
// by side in one texture level (the atlas of ocean_relief::lod: level 0 at (0, 0), level l >= 1
// at (N, N - (N >> (l - 1))); not a mip chain, because OpenGL leaves texelFetch of the levels
// of an unfilterable texture undefined). The draw pass picks one level per fragment before any
// loop (relief_lod(), from the derivatives of the polygon's texture coordinates) and
// relief_use_level() stores it and its atlas origin; every fetch of the viewing ray, its
// bisection, the light ray and the relief normal then read that level, whose side is
// N >> relief_level, resolving indices inside it before the origin is added. The tracers at
// level l are the level-0 tracers on that smaller map.
//
// Texture: rgba32float, N x N, texel (i, j) = [depth, cone ratio, clearance, near cap]
// (ocean_relief::ReliefTexture), declared by relief_texture.wgsl; or a
// 4-layer array of such texels, one layer per quadrant of the ray's direction
// (relief_texture_quad.wgsl, ocean_relief::QuadReliefTexture, section 18.1). relief_trace()
// picks the layer once per ray with relief_layer() before its loop; every fetch of the ray then
// reads that layer through relief_texel(), so the loops are the isotropic ones.
//
// Bit parity. The CPU rounds every + - * / to nearest, once. Shader compilers may fuse a
// product into a following addition (an fma rounds once where the CPU rounds twice) and may
// divide by multiplying with a reciprocal (two roundings where the CPU has one). So products
// that meet an addition go through relief_opq(), a bit-level identity the compiler cannot see
// through (it xors with relief.shading.z, a zero only known at run time), and divisions are
// relief_div(): a correctly rounded quotient from the hardware's estimate and an exact
// remainder. sqrt() and floor() are correctly rounded on every adapter tested (lavapipe,
// llvmpipe).

// Byte for byte ocean_relief::gpu_params::ReliefUniforms (256 bytes); the field documentation is
// there.
struct Relief {
    view_proj: mat4x4<f32>,
    quad_origin: vec4<f32>,
    quad_u: vec4<f32>,
    quad_v: vec4<f32>,
    tangent: vec4<f32>,
    bitangent: vec4<f32>,
    normal: vec4<f32>,
    view_dir: vec4<f32>,
    light: vec4<f32>,
    albedo: vec4<f32>,
    // size N, edge (0 wrap, 1 clamp), method (0 linear, 1 cone step, 2 relaxed),
    // binary search (0 last step, 1 book, 2 shared)
    trace: vec4<u32>,
    // steps, binary steps, flags (1 shadows, 2 sRGB-encode), probe items
    steps: vec4<u32>,
    // depth scale (texture widths), shadow bias, 0 (the opaque zero of relief_opq), mip
    // levels (a whole number; 0 reads as 1)
    shading: vec4<f32>,
    // the environment's light on the relief normal: order-2 spherical-harmonic rows (rgb) in
    // world space, evaluated by irradiance.wgsl's sh_irradiance; all zero adds nothing
    irradiance: array<vec4<f32>, 9>,
    // rgb: the light's colour, multiplying light.w
    light_color: vec4<f32>,
    // the polygon drawn: corners (s, t) in units of quad_u and quad_v, (s0, t0, s1, t1) and
    // (s2, t2, s3, t3), a convex fan counter-clockwise from the front
    polygon: array<vec4<f32>, 2>,
}

@group(0) @binding(0) var<uniform> relief: Relief;

// The mip level every fetch reads and where it lies in the atlas: set once per fragment (or
// probe item) before tracing, by relief_use_level().
var<private> relief_level: i32 = 0;
var<private> relief_origin: vec2<i32> = vec2<i32>(0, 0);

// Selects level l for every later fetch (ocean_relief::lod::atlas_origin).
fn relief_use_level(l: i32) {
    let n = i32(relief.trace.x);
    relief_level = l;
    relief_origin = select(vec2<i32>(n, n - (n >> u32(max(l - 1, 0)))), vec2<i32>(0, 0), l == 0);
}

const METHOD_LINEAR: u32 = 0u;
const METHOD_CONE_STEP: u32 = 1u;
const SEARCH_BOOK: u32 = 1u;
const SEARCH_SHARED: u32 = 2u;
const FLAG_SHADOWS: u32 = 1u;
const FLAG_SRGB_ENCODE: u32 = 2u;

// x unchanged, but opaque to the compiler: shading.z is 0.0 at run time.
fn relief_opq(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) ^ bitcast<u32>(relief.shading.z));
}

fn relief_opq4(x: vec4<f32>) -> vec4<f32> {
    return bitcast<vec4<f32>>(bitcast<vec4<u32>>(x) ^ vec4<u32>(bitcast<u32>(relief.shading.z)));
}

// a * b rounded once and never fused into a neighbouring addition.
fn relief_mul(a: f32, b: f32) -> f32 {
    return relief_opq(a * b);
}

// (p, e) with p = a * b rounded to nearest and p + e = a * b exactly (Dekker's product, the
// operands split by masking their low 12 significand bits).
fn relief_two_prod(a_in: f32, b_in: f32) -> vec2<f32> {
    // Opaque inputs: an operand computed by a product must not fuse into a - ah.
    let a = relief_opq(a_in);
    let b = relief_opq(b_in);
    let ah = bitcast<f32>(bitcast<u32>(a) & 0xfffff000u);
    let bh = bitcast<f32>(bitcast<u32>(b) & 0xfffff000u);
    let al = relief_opq(a - ah);
    let bl = relief_opq(b - bh);
    let p = relief_mul(a, b);
    let e1 = relief_opq(relief_mul(ah, bh) - p);
    let e2 = relief_opq(e1 + relief_mul(ah, bl));
    let e3 = relief_opq(e2 + relief_mul(al, bh));
    return vec2<f32>(p, relief_opq(e3 + relief_mul(al, bl)));
}

// The neighbour of finite x one unit in the last place towards +inf (up) or -inf.
fn relief_next(x: f32, up: bool) -> f32 {
    if x == 0.0 {
        return select(-1.0e-45, 1.0e-45, up);
    }
    let bits = bitcast<u32>(x);
    let away = (x > 0.0) == up;
    return bitcast<f32>(select(bits - 1u, bits + 1u, away));
}

// a / b rounded to nearest (ties to even), as the CPU divides: the hardware's quotient, one
// correction with its remainder, then the exact decision between the two floats around the
// quotient from the exact remainder a - q b.
fn relief_div(a_in: f32, b_in: f32) -> f32 {
    let a = relief_opq(a_in);
    let b = relief_opq(b_in);
    var q = a / b;
    if a == 0.0 || b == 0.0 || abs(q) > 1.0e37 || abs(q) < 1.0e-30 || abs(b) > 1.0e37 {
        return q;
    }
    let p0 = relief_two_prod(q, b);
    let r0 = relief_opq(relief_opq(a - p0.x) - p0.y);
    q = relief_opq(q + r0 / b);
    // Exact remainder of the (now faithful) quotient.
    let p = relief_two_prod(q, b);
    let r = relief_opq(relief_opq(a - p.x) - p.y);
    if r == 0.0 {
        return q;
    }
    // The exact quotient lies between q and its neighbour n on the side of r / b.
    let up = (r > 0.0) == (b > 0.0);
    let n = relief_next(q, up);
    let gap = abs(n - q);
    // Compare |r| with |b| gap / 2 (a power-of-two scaling of b: exact).
    let half = abs(b) * gap * 0.5;
    if abs(r) > half {
        return n;
    }
    if abs(r) == half && (bitcast<u32>(q) & 1u) == 1u {
        return n;
    }
    return q;
}

// Where a tracer stopped: (u, v, depth) and the texture fetches spent.
struct Hit {
    pos: vec3<f32>,
    fetches: u32,
}

// i.rem_euclid(n) for n > 0, in unsigned arithmetic: GLSL leaves % undefined for negative
// operands (Mesa's llvmpipe returns the unsigned remainder of the two's complement).
fn relief_rem_euclid(i: i32, n: i32) -> i32 {
    if i >= 0 {
        return i32(u32(i) % u32(n));
    }
    return n - 1 - i32(u32(-(i + 1)) % u32(n));
}

// A control word of the uniform (edge mode, method, search, step counts, flags) as the shader
// reads it: OR-ed with relief_side() >> 31, which is 0 (no side reaches 2^31) but not known
// before the shader runs, so no driver can fold the word into the shader. Lavapipe (Mesa 22.x)
// otherwise inlines the uniforms that decide branches and loop counts into a new variant of the
// shader and compiles it with LLVM whenever a draw binds another uniform buffer, which every
// draw does (a block per draw): seconds per draw where its disk cache has not seen the variant.
fn relief_ctl(word: u32) -> u32 {
    return word | (relief_side() >> 31u);
}

// Texel index i (any integer) resolved into 0 .. n by the edge mode (Edge::resolve).
fn relief_resolve(i: i32, n: i32) -> i32 {
    if relief_ctl(relief.trace.y) == 0u {
        return relief_rem_euclid(i, n);
    }
    return clamp(i, 0, n - 1);
}

// The side of the level relief_level reads: N >> level.
fn relief_level_side() -> i32 {
    return i32(relief.trace.x) >> u32(relief_level);
}

// The mip levels the texture holds (at least 1), opaque to the driver (relief_ctl).
fn relief_levels() -> i32 {
    let levels = i32(bitcast<f32>(relief_ctl(bitcast<u32>(relief.shading.w))));
    return max(levels, 1);
}

// The level for screen derivatives du, dv of the texture coordinates (texture widths per
// pixel), ocean_relief::lod::mip_level: with rho^2 = max(|du|^2, |dv|^2) N^2, the largest
// l < levels with rho^2 >= 2^(2l - 1), or 0. Products are rounded once each (relief_mul), as
// the CPU rounds them, so both pick the same level for the same derivatives.
fn relief_lod(du: vec2<f32>, dv: vec2<f32>) -> i32 {
    let sx = relief_mul(du.x, du.x) + relief_mul(du.y, du.y);
    let sy = relief_mul(dv.x, dv.x) + relief_mul(dv.y, dv.y);
    let n = f32(relief.trace.x);
    let s = relief_mul(max(sx, sy), relief_mul(n, n));
    let levels = relief_levels();
    var level = 0;
    var threshold = 2.0;
    // A NaN footprint fails every comparison and stays at level 0.
    while level + 1 < levels && s >= threshold {
        level += 1;
        threshold *= 4.0;
    }
    return level;
}

// WGSL's mix(a, b, t) as ocean_relief::sample::mix writes it: a(1 - t) + bt.
fn relief_mix(a: vec4<f32>, b: vec4<f32>, t: f32) -> vec4<f32> {
    return relief_opq4(a * (1.0 - t)) + relief_opq4(b * t);
}

// The bilinear fetch of [depth, cone, clearance, near cap] of `layer` at texture coordinates
// (u, v): ocean_relief::sample::Taps::new + blend4.
fn relief_fetch(layer: i32, u: f32, v: f32) -> vec4<f32> {
    let n = relief_level_side();
    let nf = f32(n);
    let x = relief_mul(u, nf) - 0.5;
    let y = relief_mul(v, nf) - 0.5;
    let x0 = floor(x);
    let y0 = floor(y);
    let fx = x - x0;
    let fy = y - y0;
    // The CPU converts to i64 (saturating); rays never get near 2^30 texels, and clamping here
    // keeps i + 1 from overflowing.
    let i = i32(clamp(x0, -1073741824.0, 1073741824.0));
    let j = i32(clamp(y0, -1073741824.0, 1073741824.0));
    let i0 = relief_resolve(i, n);
    let i1 = relief_resolve(i + 1, n);
    let j0 = relief_resolve(j, n);
    let j1 = relief_resolve(j + 1, n);
    let a = relief_texel(layer, i0, j0);
    let b = relief_texel(layer, i1, j0);
    let c = relief_texel(layer, i0, j1);
    let d = relief_texel(layer, i1, j1);
    return relief_mix(relief_mix(a, b, fx), relief_mix(c, d, fx), fy);
}

// Eq. 3: the distance along the ray (depth units) to where it leaves the cone of ratio `cone`
// standing on the surface `height` below it (trace::cone_step_length).
fn relief_cone_step(cone: f32, height: f32, ray_ratio: f32) -> f32 {
    let denom = ray_ratio + cone;
    return select(height, relief_div(cone * height, denom), denom > 0.0);
}

// The step with the clearance D and the near cap E (trace::step_length):
// max(c h/(rho + c), min(D h/(rho h + D), E h/(rho + E))).
fn relief_step(texel: vec4<f32>, height: f32, ray_ratio: f32) -> f32 {
    let a = relief_cone_step(texel.y, height, ray_ratio);
    let denom = relief_mul(ray_ratio, height) + texel.z;
    let b = select(height, relief_div(texel.z * height, denom), denom > 0.0);
    return max(a, min(b, relief_cone_step(texel.w, height, ray_ratio)));
}

fn relief_midpoint(lo: vec3<f32>, hi: vec3<f32>) -> vec3<f32> {
    return (lo + hi) * 0.5;
}

// Bisects [lo, hi] `steps` times; the midpoint of the final bracket (trace::bisect).
fn relief_bisect(layer: i32, lo_in: vec3<f32>, hi_in: vec3<f32>, steps: u32) -> vec3<f32> {
    var lo = lo_in;
    var hi = hi_in;
    for (var k = 0u; k < steps; k++) {
        let mid = relief_midpoint(lo, hi);
        let depth = relief_fetch(layer, mid.x, mid.y).x;
        let outside = mid.z < depth;
        lo = select(lo, mid, outside);
        hi = select(mid, hi, outside);
    }
    return relief_midpoint(lo, hi);
}

// Policarpo et al. 2005: linear steps, then bisections of the step that went inside.
fn relief_linear(layer: i32, s: vec2<f32>, dx: f32, dy: f32, linear: u32, binary: u32) -> Hit {
    let size = relief_div(1.0, f32(linear));
    var depth = 0.0;
    var fetches = 0u;
    for (var i = 0u; i < linear; i++) {
        depth = relief_mul(f32(i + 1u), size);
        let d = relief_fetch(layer, s.x + relief_mul(dx, depth), s.y + relief_mul(dy, depth)).x;
        fetches += 1u;
        if depth >= d {
            break;
        }
    }
    let z0 = depth - size;
    let lo = vec3<f32>(s.x + relief_mul(dx, z0), s.y + relief_mul(dy, z0), z0);
    let hi = vec3<f32>(s.x + relief_mul(dx, depth), s.y + relief_mul(dy, depth), depth);
    return Hit(relief_bisect(layer, lo, hi, binary), fetches + binary);
}

// One cone step from p: (new position, height above the surface before the step).
fn relief_advance(layer: i32, p: vec3<f32>, dx: f32, dy: f32, ratio: f32) -> vec4<f32> {
    let texel = relief_fetch(layer, p.x, p.y);
    // saturate(): 0 once the ray is inside, so it stays there (section 18.4.2).
    let height = clamp(texel.x - p.z, 0.0, 1.0);
    let d = relief_step(texel, height, ratio);
    return vec4<f32>(p.x + relief_mul(dx, d), p.y + relief_mul(dy, d), p.z + d, height);
}

// Dummer 2006: conservative cone steps, no refinement.
fn relief_cone_stepping(layer: i32, s: vec2<f32>, dx: f32, dy: f32, ratio: f32, steps: u32) -> Hit {
    var p = vec3<f32>(s, 0.0);
    for (var k = 0u; k < steps; k++) {
        p = relief_advance(layer, p, dx, dy, ratio).xyz;
    }
    return Hit(p, steps);
}

// Binary search over a shared budget of fetches (BinarySearch::Shared).
fn relief_shared(layer: i32, s: vec2<f32>, dx: f32, dy: f32, ratio: f32, total: u32) -> Hit {
    var p = vec3<f32>(s, 0.0);
    var lo = p;
    var hi = p;
    var bracketed = false;
    for (var k = 0u; k < total; k++) {
        if bracketed {
            let mid = relief_midpoint(lo, hi);
            let depth = relief_fetch(layer, mid.x, mid.y).x;
            let outside = mid.z < depth;
            lo = select(lo, mid, outside);
            hi = select(mid, hi, outside);
        } else {
            let texel = relief_fetch(layer, p.x, p.y);
            let height = clamp(texel.x - p.z, 0.0, 1.0);
            if height > 0.0 {
                lo = p;
                // The last fetch only checks where the previous step ended.
                if k + 1u < total {
                    let d = relief_step(texel, height, ratio);
                    p = vec3<f32>(p.x + relief_mul(dx, d), p.y + relief_mul(dy, d), p.z + d);
                }
            } else {
                hi = p;
                bracketed = true;
            }
        }
    }
    if bracketed {
        return Hit(relief_midpoint(lo, hi), total);
    }
    return Hit(p, total);
}

// Listing 18-3: relaxed cone steps, then the binary search of trace::BinarySearch.
fn relief_relaxed(layer: i32, s: vec2<f32>, dx: f32, dy: f32, ratio: f32, cone: u32, binary: u32,
                  search: u32) -> Hit {
    if search == SEARCH_SHARED {
        return relief_shared(layer, s, dx, dy, ratio, cone + binary);
    }
    var p = vec3<f32>(s, 0.0);
    // The last position above the surface (J in Fig. 18-10).
    var last_out = p;
    for (var k = 0u; k < cone; k++) {
        let next = relief_advance(layer, p, dx, dy, ratio);
        last_out = select(last_out, p, next.w > 0.0);
        p = next.xyz;
    }
    if search == SEARCH_BOOK {
        // bs_range = 0.5 ray_dir pos.z; bs_position = ray_pos + bs_range.
        var range = vec3<f32>(0.5 * dx * p.z, 0.5 * dy * p.z, 0.5 * p.z);
        var b = vec3<f32>(s.x + range.x, s.y + range.y, range.z);
        for (var k = 0u; k < binary; k++) {
            let depth = relief_fetch(layer, b.x, b.y).x;
            range = range * 0.5;
            let sign = select(-1.0, 1.0, b.z < depth);
            b = vec3<f32>(
                b.x + relief_mul(sign, range.x),
                b.y + relief_mul(sign, range.y),
                b.z + relief_mul(sign, range.z),
            );
        }
        return Hit(b, cone + binary);
    }
    return Hit(relief_bisect(layer, last_out, p, binary), cone + binary);
}

// Traces the ray entering at `start` with direction `dir` (any positive z; the book's
// ray_dir /= ray_dir.z is applied here) with the uniform's method (Method::trace; through a
// quadrant texture QuadReliefTexture::trace: the layer of the scaled direction's quadrant).
fn relief_trace(start: vec2<f32>, dir: vec3<f32>) -> Hit {
    let dx = relief_div(dir.x, dir.z);
    let dy = relief_div(dir.y, dir.z);
    // Once per ray, before any loop (Quadrant::of).
    let layer = relief_layer(dx, dy);
    let ratio = sqrt(relief_mul(dx, dx) + relief_mul(dy, dy));
    let method = relief_ctl(relief.trace.z);
    let steps = relief_ctl(relief.steps.x);
    let binary = relief_ctl(relief.steps.y);
    if method == METHOD_LINEAR {
        return relief_linear(layer, start, dx, dy, steps, binary);
    }
    if method == METHOD_CONE_STEP {
        return relief_cone_stepping(layer, start, dx, dy, ratio, steps);
    }
    return relief_relaxed(layer, start, dx, dy, ratio, steps, binary, relief_ctl(relief.trace.w));
}

// The ray of a tangent-space view vector (z < 0 looking at the surface) entering at `start`,
// for a relief `depth` texture widths deep (Ray::from_view).
fn relief_view_ray(view: vec3<f32>, depth: f32) -> vec3<f32> {
    return vec3<f32>(relief_div(depth * view.x, -view.z), relief_div(depth * view.y, -view.z), 1.0);
}

// Self-shadowing (shadow::in_shadow; QuadReliefTexture::in_shadow, the light ray tracing
// through the layer of its own quadrant): whether the light from tangent-space direction `light`
// is blocked before it reaches `point` = (u, v, depth). x: 1 in shadow, 0 lit; y: the light
// ray's hit depth; z: its fetches.
fn relief_shadow(point: vec3<f32>, light: vec3<f32>, depth_scale: f32, bias: f32) -> vec3<f32> {
    if light.z <= 0.0 {
        return vec3<f32>(1.0, 0.0, 0.0);
    }
    let hit = relief_trace(relief_shadow_start(point, light, depth_scale), relief_view_ray(-light, depth_scale));
    return relief_shadow_of(hit, point, bias);
}

// Where the light ray towards `point` enters the relief (light.z > 0): the point moved back
// along the light's direction to the polygon.
fn relief_shadow_start(point: vec3<f32>, light: vec3<f32>, depth_scale: f32) -> vec2<f32> {
    let per_depth = vec2<f32>(-light.x, -light.y) * relief_div(depth_scale, light.z);
    return vec2<f32>(
        point.x - relief_mul(per_depth.x, point.z),
        point.y - relief_mul(per_depth.y, point.z),
    );
}

// relief_shadow's result from the light ray's hit.
fn relief_shadow_of(hit: Hit, point: vec3<f32>, bias: f32) -> vec3<f32> {
    return vec3<f32>(select(0.0, 1.0, hit.pos.z < point.z - bias), hit.pos.z, f32(hit.fetches));
}

// The depth gradient (per texel) at texel (i, j) by central differences (relief::normals);
// every layer holds the same depths, layer 0's are read.
fn relief_gradient(i: i32, j: i32, n: i32) -> vec2<f32> {
    let l = relief_texel(0, relief_resolve(i - 1, n), j).x;
    let r = relief_texel(0, relief_resolve(i + 1, n), j).x;
    let t = relief_texel(0, i, relief_resolve(j - 1, n)).x;
    let b = relief_texel(0, i, relief_resolve(j + 1, n)).x;
    return vec2<f32>((r - l) * 0.5, (b - t) * 0.5);
}

// The tangent-space relief normal at (u, v): the bilinear blend of the four texels' central
// differences, normalize(depth du, depth dv, 1) with `depth_texels` the relief depth in texels
// of the level read (relief::normals, blended as a linear sampler would blend a normal map of
// its gradients).
fn relief_normal(u: f32, v: f32, depth_texels: f32) -> vec3<f32> {
    let n = relief_level_side();
    let nf = f32(n);
    let x = u * nf - 0.5;
    let y = v * nf - 0.5;
    let x0 = floor(x);
    let y0 = floor(y);
    let fx = x - x0;
    let fy = y - y0;
    let i = i32(clamp(x0, -1073741824.0, 1073741824.0));
    let j = i32(clamp(y0, -1073741824.0, 1073741824.0));
    let i0 = relief_resolve(i, n);
    let i1 = relief_resolve(i + 1, n);
    let j0 = relief_resolve(j, n);
    let j1 = relief_resolve(j + 1, n);
    let top = mix(relief_gradient(i0, j0, n), relief_gradient(i1, j0, n), fx);
    let bottom = mix(relief_gradient(i0, j1, n), relief_gradient(i1, j1, n), fx);
    let g = mix(top, bottom, fy);
    return normalize(vec3<f32>(depth_texels * g.x, depth_texels * g.y, 1.0));
}
