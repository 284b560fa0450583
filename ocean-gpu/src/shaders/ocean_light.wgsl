// Ocean lighting (Bruneton, Neyret & Holzschuch 2010, §4 and §5): Algorithm 5.1 (Fig. 9) for one
// pixel, the Sun's reflection (Eq. 15), the sky's (Eq. 21, 26, 27) and the refracted light
// (Eq. 28), then tone mapping. Prepended after ocean_common.wgsl (it reads `frame`, `sky_map`
// and `sky_sampler`). The CPU twins are `ocean_brdf::sea::sea_color_unchecked`,
// `ocean_brdf::ross::sun_radiance_unchecked`, `ocean_brdf::fresnel` and
// `ocean_brdf::sky_map::SkyMap::grad_fetch`; the numerically careful forms of ocean_brdf::ross
// (Λ cos θ finite at grazing, the symmetric shadowing term, 0/x = 0) are kept, in f32.
//
// Tangent frames: x along the wind projected on the surface, y across it, z along the normal.

const PI: f32 = 3.14159265;
const SQRT_PI: f32 = 1.77245385;
const SQRT_2: f32 = 1.41421356;
const SQRT_2PI: f32 = 2.50662827;
const FRAC_1_SQRT_2PI: f32 = 0.39894228;
// `ocean_brdf::sea::SLOPE_EPSILON` (Fig. 9: ε = 10⁻³).
const SLOPE_EPSILON: f32 = 1e-3;
// √3, the outer node of the 3-point Gauss–Hermite rule.
const SQRT_3: f32 = 1.73205081;

// erfc(x) for x ≥ 0 as t·exp(−x² + q(t)), t = 1/(1 + x/2), returning (t, q(t)): the Chebyshev
// fit of Numerical Recipes' `erfcc`, fractional error below 1.2·10⁻⁷ everywhere (WGSL has no
// erfc). Split so that Λ can factor exp(−x²) out of both of its terms.
fn erfc_parts(x: f32) -> vec2<f32> {
    let t = 1.0 / (1.0 + 0.5 * x);
    let q = -1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806
        + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))));
    return vec2<f32>(t, q);
}

fn erfc_pos(x: f32) -> f32 {
    let p = erfc_parts(x);
    return p.x * exp(p.y - x * x);
}

// Smith's Λ(a) for a ≥ 1, Eq. 8: (exp(−a²) − a√π erfc(a)) / (2a√π), written
// exp(−a²)(1 − a√π t e^q)/(2a√π) so the two terms are not formed separately (ocean_brdf::ross
// uses a continued fraction above a = 2 for the same reason; in f32, with Λ(3) ≈ 6·10⁻⁷, the
// remaining cancellation costs nothing that 1 + Λ can see).
fn smith_lambda(a: f32) -> f32 {
    let p = erfc_parts(a);
    let r = 1.0 - a * SQRT_PI * p.x * exp(p.y);
    return max(exp(-a * a) * r / (2.0 * a * SQRT_PI), 0.0);
}

// `ross::lambda_cos`: Λ(a) cos θ for a unit direction above or on the horizon, finite at
// grazing (where Λ → ∞ and cos θ → 0): with c = σ_φ sin θ and a = cos θ/(√2 c), Eq. 8 times
// cos θ is c exp(−a²)/√(2π) − cos θ erfc(a)/2 below a = 1, cos θ Λ(a) above.
fn lambda_cos(dir: vec3<f32>, var2: vec2<f32>) -> f32 {
    let c = length(sqrt(var2) * dir.xy);
    let z = max(dir.z, 0.0);
    if c == 0.0 {
        return 0.0;
    }
    let a = z / (SQRT_2 * c);
    if a < 1.0 {
        return c * exp(-a * a) / SQRT_2PI - 0.5 * z * erfc_pos(a);
    }
    return z * smith_lambda(a);
}

// The Gaussian slope density p(ζ), Eq. 7.
fn slope_pdf(zeta: vec2<f32>, var2: vec2<f32>) -> f32 {
    let e = zeta.x * zeta.x / var2.x + zeta.y * zeta.y / var2.y;
    return exp(-0.5 * e) / (2.0 * PI * sqrt(var2.x) * sqrt(var2.y));
}

// Schlick's Fresnel factor, Eq. 14.
fn schlick(cos_theta: f32, r: f32) -> f32 {
    let x = 1.0 - clamp(cos_theta, 0.0, 1.0);
    return r + (1.0 - r) * (x * x) * (x * x) * x;
}

// I_sun / L_sun, Eq. 15 (`ross::sun_radiance_unchecked` with L_sun = 1):
// Ω_sun cos θ_l p(ζ_h) F(v·h) / (4 h_z⁴ cos θ_v cos θ_l (1 + Λ_v + Λ_l)), in the tangent frame.
// Zero when v or l is on or below the surface; a zero numerator wins over the denominator.
fn sun_reflection(v: vec3<f32>, l: vec3<f32>, var2: vec2<f32>, omega: f32, r: f32) -> f32 {
    if v.z <= 0.0 || l.z <= 0.0 {
        return 0.0;
    }
    let sum = v + l;
    let len = sqrt(dot(sum, sum));
    let h = sum / len;
    // v·h = |v + l|/2 for unit v and l.
    let v_dot_h = 0.5 * len;
    let p = slope_pdf(-h.xy / h.z, var2);
    let f = schlick(v_dot_h, r);
    // cos θ_v cos θ_l (1 + Λ_v + Λ_l), symmetric and finite at grazing.
    let shadowing = v.z * l.z + (l.z * lambda_cos(v, var2) + v.z * lambda_cos(l, var2));
    let hz2 = h.z * h.z;
    let num = p * f;
    if num == 0.0 {
        return 0.0;
    }
    let brdf = num / (4.0 * hz2 * hz2 * shadowing);
    let light = omega * l.z;
    if light == 0.0 || brdf == 0.0 {
        return 0.0;
    }
    return light * brdf;
}

// The effective Fresnel reflectance of Eq. 24 from its table, R + (1 − R) M(cos θ_v, σ_v) with
// M = (1 − cos θ_v)⁵ + D and D, the stored roughness correction, bilinear in (√cos θ_v, √σ_v),
// as `fresnel_table::effective_fresnel_table` (closer to Eq. 24 than the fit of Eq. 26 at
// grazing views, and exactly Schlick's F for a smooth sea).
const FRESNEL_TABLE_LAST: f32 = 32.0;
const FRESNEL_TABLE_SIGMA_MAX: f32 = 1.0;
fn effective_fresnel(cos_theta_v: f32, sigma_v: f32, r: f32) -> f32 {
    let u = sqrt(clamp(cos_theta_v, 0.0, 1.0)) * FRESNEL_TABLE_LAST;
    let w = sqrt(clamp(sigma_v, 0.0, FRESNEL_TABLE_SIGMA_MAX) / FRESNEL_TABLE_SIGMA_MAX)
        * FRESNEL_TABLE_LAST;
    let i0 = min(floor(u), FRESNEL_TABLE_LAST - 1.0);
    let j0 = min(floor(w), FRESNEL_TABLE_LAST - 1.0);
    let fu = u - i0;
    let fw = w - j0;
    let i = i32(i0);
    let j = i32(j0);
    let d00 = textureLoad(fresnel_table, vec2<i32>(j, i), 0).x;
    let d01 = textureLoad(fresnel_table, vec2<i32>(j + 1, i), 0).x;
    let d10 = textureLoad(fresnel_table, vec2<i32>(j, i + 1), 0).x;
    let d11 = textureLoad(fresnel_table, vec2<i32>(j + 1, i + 1), 0).x;
    let d = (d00 * (1.0 - fw) + d01 * fw) * (1.0 - fu) + (d10 * (1.0 - fw) + d11 * fw) * fu;
    let x = 1.0 - u * u / (FRESNEL_TABLE_LAST * FRESNEL_TABLE_LAST);
    let schlick_part = (x * x) * (x * x) * x;
    return r + (1.0 - r) * (schlick_part + d);
}

// The stereographic projection of a direction (y up) from the nadir, u = (r_x, r_z)/(1 + r_y)
// (§5.2, `sky::stereographic`), capped at a length of 10⁶ at the nadir.
fn stereographic(r: vec3<f32>) -> vec2<f32> {
    let d = 1.0 + r.y;
    if d > 1e-12 {
        return r.xz / d;
    }
    let len = length(r.xz);
    if len > 0.0 {
        return r.xz * (1e6 / len);
    }
    return vec2<f32>(1e6, 0.0);
}

// U(ζ) of Fig. 9 (`sea::reflected_u`): the stereographic coordinates of v reflected by the facet
// of slopes ζ in the tangent frame (t_x, t_y, n).
fn reflected_u(v: vec3<f32>, n: vec3<f32>, tx: vec3<f32>, ty: vec3<f32>, zeta: vec2<f32>) -> vec2<f32> {
    let f0 = normalize(vec3<f32>(-zeta.x, -zeta.y, 1.0));
    let f = tx * f0.x + ty * f0.y + n * f0.z;
    return stereographic(f * (2.0 * dot(f, v)) - v);
}

// Where the sky map is read (Eq. 27): the centre u0 = U(0) and the axes Δu_x = 2σ_x ∂U/∂ζ_x,
// Δu_y = 2σ_y ∂U/∂ζ_y by forward differences of step ε (Fig. 9; `sea::sky_footprint`).
struct SkyFootprint {
    u0: vec2<f32>,
    du_x: vec2<f32>,
    du_y: vec2<f32>,
}

fn sky_footprint(v: vec3<f32>, n: vec3<f32>, tx: vec3<f32>, ty: vec3<f32>, var2: vec2<f32>) -> SkyFootprint {
    let u0 = reflected_u(v, n, tx, ty, vec2<f32>(0.0));
    let s = sqrt(var2);
    let ux = reflected_u(v, n, tx, ty, vec2<f32>(SLOPE_EPSILON, 0.0));
    let uy = reflected_u(v, n, tx, ty, vec2<f32>(0.0, SLOPE_EPSILON));
    return SkyFootprint(u0, (ux - u0) * (2.0 * s.x / SLOPE_EPSILON), (uy - u0) * (2.0 * s.y / SLOPE_EPSILON));
}

// The sky footprint over the slopes the viewer sees (`sea::visible_sky_footprint`, the CPU
// twin's refinement of Eq. 22): L̄ averaged over the visible slopes q^e_vn (Eq. 10), as F̄ is,
// instead of over p (which darkens grazing views with mirror directions of hidden facets). In
// whitened slopes, along e = (σ_x v_x, σ_y v_y)/c the density is a Gaussian times the ramp
// (v_z − c s)⁺, with a = v_z/c, Z = a Φ(a) + φ(a): mean −Φ(a)/Z, second moment
// (a Φ(a) + 2 φ(a))/Z; across e it stays standard normal. The footprint is the Gaussian with
// these moments mapped through U at the mean slope (forward differences of step ε along both
// axes); with c = 0 it is `sky_footprint`.
fn visible_sky_footprint(v: vec3<f32>, n: vec3<f32>, tx: vec3<f32>, ty: vec3<f32>, var2: vec2<f32>) -> SkyFootprint {
    let s = sqrt(var2);
    let v_t = vec3<f32>(dot(v, tx), dot(v, ty), dot(v, n));
    let axis = s * v_t.xy;
    let c = length(axis);
    if !(c > 0.0) {
        return sky_footprint(v, n, tx, ty, var2);
    }
    let e = axis / c;
    let a = max(v_t.z, 0.0) / c;
    // Φ(a) = erfc(−a/√2)/2 = 1 − erfc(a/√2)/2 for a ≥ 0.
    let cdf = 1.0 - 0.5 * erfc_pos(a / SQRT_2);
    let pdf = exp(-0.5 * a * a) * FRAC_1_SQRT_2PI;
    let z = a * cdf + pdf;
    let mean = -cdf / z;
    let spread = max((a * cdf + 2.0 * pdf) / z - mean * mean, 0.0);
    let along = s * e * sqrt(spread);
    let across = s * vec2<f32>(-e.y, e.x);
    let zeta0 = s * e * mean;
    let u0 = reflected_u(v, n, tx, ty, zeta0);
    return SkyFootprint(
        u0,
        footprint_axis(v, n, tx, ty, zeta0, u0, along),
        footprint_axis(v, n, tx, ty, zeta0, u0, across),
    );
}

// 2 ∂U/∂t along `dir` at ζ₀ (a slope offset of `dir` per unit t), by a forward difference of
// slope step ε: the axis of the footprint whose standard deviation is `dir`.
fn footprint_axis(v: vec3<f32>, n: vec3<f32>, tx: vec3<f32>, ty: vec3<f32>, zeta0: vec2<f32>, u0: vec2<f32>, dir: vec2<f32>) -> vec2<f32> {
    let len = length(dir);
    if len > 0.0 {
        let h = SLOPE_EPSILON / len;
        return (reflected_u(v, n, tx, ty, zeta0 + dir * h) - u0) * (2.0 / h);
    }
    return vec2<f32>(0.0);
}

// The sky map's texture coordinates of a stereographic point (`SkyMap::texcoord`).
fn sky_texcoord(u: vec2<f32>) -> vec2<f32> {
    return u / (2.0 * frame.sky.y) + vec2<f32>(0.5);
}

// `SkyMap::gaussian_lod`: the mip level whose texel is as wide as the smallest standard
// deviation of the Gaussian with axes a, b (texture units), log2(N √λ_min), at least 0. λ_min
// is taken as det/λ_max = (a × b)²/(mean + dev), equal to the CPU's mean − dev but free of its
// cancellation for thin ellipses (grazing views), which f32 could not afford.
fn gaussian_lod(a: vec2<f32>, b: vec2<f32>) -> f32 {
    let p = a.x * a.x + b.x * b.x;
    let q = a.x * a.y + b.x * b.y;
    let r = a.y * a.y + b.y * b.y;
    let mean = 0.5 * (p + r);
    let dev = length(vec2<f32>(0.5 * (p - r), q));
    let cross = a.x * b.y - a.y * b.x;
    let lambda_max = mean + dev;
    let lambda_min = select(cross * cross / lambda_max, 0.0, lambda_max <= 0.0);
    let texels = sqrt(lambda_min) * frame.sky.x;
    return select(0.0, log2(texels), texels > 1.0);
}

// Eq. 27 (`SkyMap::grad_fetch`): the sky map averaged over the slopes' Gaussian mapped to the
// stereographic plane, centred on u0 with standard deviations du_x/2 and du_y/2, by the 3×3
// Gauss–Hermite rule (nodes 0 and ±√3, weights 2/3 and 1/6) of trilinear samples at an
// explicit level of detail: deterministic on every GPU (no hardware anisotropy, no implicit
// derivatives), and the nine samples the paper found to fix texture2DGrad's horizon artefacts
// (§7.3).
fn sky_fetch(fp: SkyFootprint) -> vec3<f32> {
    let scale = 1.0 / (2.0 * frame.sky.y);
    let a = fp.du_x * (0.5 * scale);
    let b = fp.du_y * (0.5 * scale);
    let t0 = sky_texcoord(fp.u0);
    let lod = gaussian_lod(a, b);
    let nodes = array<vec2<f32>, 3>(
        vec2<f32>(-SQRT_3, 1.0 / 6.0),
        vec2<f32>(0.0, 2.0 / 3.0),
        vec2<f32>(SQRT_3, 1.0 / 6.0),
    );
    var sum = vec3<f32>(0.0);
    for (var i = 0u; i < 3u; i++) {
        for (var j = 0u; j < 3u; j++) {
            let t = t0 + a * nodes[i].x + b * nodes[j].x;
            sum += textureSampleLevel(sky_map, sky_sampler, t, lod).rgb * (nodes[i].y * nodes[j].y);
        }
    }
    return sum;
}

// The tangent frame of Algorithm 5.1 (`sea::tangent_frame`): t_x along the wind projected on
// the surface, t_y = n × t_x; any tangent (glam's `any_orthonormal_vector`) should the wind be
// parallel to n.
fn tangent_x(n: vec3<f32>, wind: vec2<f32>) -> vec3<f32> {
    let w = vec3<f32>(wind.x, 0.0, wind.y);
    let tx = w - n * dot(w, n);
    let len = length(tx);
    if len > 1e-9 * length(w) && len > 0.0 {
        return tx / len;
    }
    let sign = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    return vec3<f32>(b, sign + n.y * n.y * a, -n.y);
}

// `ross::facet_normal`: the unit normal (−ζ_x, −ζ_y, 1)/|·| of the facet of slopes ζ in its
// tangent frame, scaled by the largest of |ζ_x|, |ζ_y|, 1 first so steep slopes cannot overflow.
fn facet_normal(zeta: vec2<f32>) -> vec3<f32> {
    let m = max(max(abs(zeta.x), abs(zeta.y)), 1.0);
    let f = vec3<f32>(-zeta.x / m, -zeta.y / m, 1.0 / m);
    return f / sqrt(dot(f, f));
}

// The masking-aware normal of a pixel (§3.2, Eq. 10; `sea::visible_normal`, whose documentation
// derives it): Eq. 3's normal n, whose slopes relative to the geometry's normal n_geo come from
// the waves the normal resolves and the geometry does not (variances `normal_only`), with those
// slopes moved to the first two moments of their visible density, summed with the BRDF's slopes
// (variances `brdf`, Eq. 4). In the tangent frame of n_geo, whitened, along the axis e of
// (σ_nx v_x, σ_ny v_y) (length c_n; c_r likewise for the BRDF's, c² = c_n² + c_r²), the visible
// density of the combined coordinate is a Gaussian times the ramp (a − t)⁺, a = v_z/c, of mean
// μ = −Φ(a)/Z and second moment (a Φ(a) + 2 φ(a))/Z, Z = a Φ(a) + φ(a); the normal-only
// coordinate gets the mean (c_n/c) μ and the variance (c_n/c)² Var t + (c_r/c)², an affine map
// of the pixel's own coordinate along e; across e nothing changes. n is returned as it is where
// nothing is unmasked (c_n = 0, either variance axis 0) or v or n is below the geometry's plane.
// Vectors unit, in world space; `wind` the variances' axis.
fn visible_normal(v: vec3<f32>, n: vec3<f32>, n_geo: vec3<f32>, wind: vec2<f32>, normal_only: vec2<f32>, brdf: vec2<f32>) -> vec3<f32> {
    let tx = tangent_x(n_geo, wind);
    let ty = cross(n_geo, tx);
    let v_t = vec3<f32>(dot(v, tx), dot(v, ty), dot(v, n_geo));
    let n_t = vec3<f32>(dot(n, tx), dot(n, ty), dot(n, n_geo));
    let sn = sqrt(normal_only);
    let sr = sqrt(brdf);
    let axis = sn * v_t.xy;
    let c_n = length(axis);
    let c_r = length(sr * v_t.xy);
    if !(c_n > 0.0 && v_t.z > 0.0 && n_t.z > 0.0 && min(sn.x, sn.y) > 0.0) {
        return n;
    }
    let c = length(vec2<f32>(c_n, c_r));
    let e = axis / c_n;
    let a = v_t.z / c;
    // Φ(a) = 1 − erfc(a/√2)/2 for a > 0.
    let cdf = 1.0 - 0.5 * erfc_pos(a / SQRT_2);
    let pdf = exp(-0.5 * a * a) * FRAC_1_SQRT_2PI;
    let z = a * cdf + pdf;
    let mean_t = -cdf / z;
    let var_t = max((a * cdf + 2.0 * pdf) / z - mean_t * mean_t, 0.0);
    let kn = c_n / c;
    let kr = c_r / c;
    let mean = kn * mean_t;
    let dev = sqrt(kn * kn * var_t + kr * kr);
    // The pixel's slopes relative to the geometry, whitened, moved along e.
    let u = (-n_t.xy / n_t.z) / sn;
    let along = dot(u, e);
    let moved = u + e * (mean + dev * along - along);
    let f = facet_normal(moved * sn);
    return normalize(tx * f.x + ty * f.y + n_geo * f.z);
}

// The three terms of the sea's radiance towards the viewer (linear RGB).
struct SeaLight {
    sun: vec3<f32>,
    sky: vec3<f32>,
    sea: vec3<f32>,
}

// Algorithm 5.1, SEACOLOR (`sea::sea_color_unchecked`): v the unit vector towards the viewer, n
// the filtered unit normal (Eq. 3), wind the horizontal direction (x, z) the variances σ_x², σ_y²
// of Eq. 4 are measured along.
fn sea_color(v: vec3<f32>, n_in: vec3<f32>, wind: vec2<f32>, variance: vec2<f32>) -> SeaLight {
    // §3.2: a normal filtered apart from the geometry can face away from the viewer; reflect it
    // about the plane normal to v (n·v becomes −n·v, n stays unit).
    let n_dot_v = dot(n_in, v);
    let n = select(n_in, n_in - v * (2.0 * n_dot_v), n_dot_v < 0.0);
    let tx = tangent_x(n, wind);
    let ty = cross(n, tx);
    let v_t = vec3<f32>(dot(v, tx), dot(v, ty), dot(v, n));
    let l = frame.sun_dir.xyz;
    let l_t = vec3<f32>(dot(l, tx), dot(l, ty), dot(l, n));
    let r = frame.sea.z;

    // Sun, Eq. 15, with the variances raised to the solar disc's (§5.1).
    let sun_var = max(variance, vec2<f32>(frame.sky.z));
    let sun = frame.sun_radiance.rgb * sun_reflection(v_t, l_t, sun_var, frame.sea.w, r);

    // Effective Fresnel, Eq. 25–26; cos φ_v, sin φ_v from v's tangent components (φ_v = 0 at
    // normal incidence, as atan2(0, 0)).
    let cos_theta_v = clamp(v_t.z, 0.0, 1.0);
    let xy = length(v_t.xy);
    let cs = select(vec2<f32>(1.0, 0.0), v_t.xy / xy, xy > 0.0);
    let sigma_v = sqrt(variance.x * cs.x * cs.x + variance.y * cs.y * cs.y);
    let f_bar = effective_fresnel(cos_theta_v, sigma_v, r);

    // Sky, Eq. 21 and 27, over the visible slopes.
    let l_bar = sky_fetch(visible_sky_footprint(v, n, tx, ty, variance));

    return SeaLight(sun, l_bar * f_bar, frame.sea_radiance.rgb * (1.0 - f_bar));
}

// `tonemap::tone_map`: 1 − exp(−exposure L) per channel, in [0, 1]; negative or NaN radiance
// gives 0.
fn tone_map(radiance: vec3<f32>) -> vec3<f32> {
    let y = vec3<f32>(1.0) - exp(-frame.grid.w * radiance);
    return select(vec3<f32>(0.0), min(y, vec3<f32>(1.0)), y > vec3<f32>(0.0));
}

// `tonemap::linear_to_srgb` per channel.
fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let x = clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
    let hi = 1.055 * pow(max(x, vec3<f32>(0.0031308)), vec3<f32>(1.0 / 2.4)) - vec3<f32>(0.055);
    return select(hi, 12.92 * x, x <= vec3<f32>(0.0031308));
}

// What a pixel of radiance `radiance` writes: tone mapped, then encoded (`encode_display`).
fn display(radiance: vec3<f32>) -> vec4<f32> {
    return encode_display(tone_map(radiance));
}

// What a pixel of tone-mapped colour `c` writes: sRGB-encoded by the shader when the target is
// not an sRGB format (flag bit 0), else left for the hardware to encode.
fn encode_display(c: vec3<f32>) -> vec4<f32> {
    let encoded = select(c, linear_to_srgb(c), (frame.counts.w & 1u) != 0u);
    return vec4<f32>(encoded, 1.0);
}
