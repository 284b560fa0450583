// The ocean renderer of Bruneton, Neyret & Holzschuch (2010), §7.1: a projected grid displaced by
// the filtered trochoids (vertex stage, Eq. 2), per-pixel filtered normals and slope variances
// (fragment stage, Eq. 3 and 4) lit by Algorithm 5.1, and a sky background. Assembled after
// surface.wgsl, ocean_common.wgsl and ocean_light.wgsl; driven by `ocean_gpu::OceanRenderer`.
//
// Draw calls (no vertex buffers; bindings of ocean_common.wgsl, group 0):
// - `sky_vs`/`sky_fs`: 3 vertices, a full-screen triangle on the far plane: the sky map's
//   radiance towards each pixel's view direction (the below-horizon radiance under the
//   horizon) plus the Sun's disc. Drawn first, with no depth write.
// - `ocean_vs`/`ocean_fs`: the projected grid, frame.counts.x × frame.counts.y vertices,
//   vertex (i, j) at pixel frame.viewport.zw + cell_px (i, j), indexed as triangles of the
//   cells (vertex index j·counts.x + i). The grid overlaps the viewport by a margin on every
//   side, so waves that pull its edges inwards do not uncover the background (DESIGN.md).
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

@vertex
fn ocean_vs(@builtin(vertex_index) index: u32) -> OceanVertex {
    let nx = frame.counts.x;
    let ij = vec2<f32>(f32(index % nx), f32(index / nx));
    let g = grid_point(frame.viewport.zw + ij * frame.grid.x);
    let relative = vec3<f32>(g.position.x, g.position.y - frame.camera.x, g.position.z);
    var out: OceanVertex;
    out.clip = frame.view_proj * vec4<f32>(relative, 1.0);
    out.rest = g.rest;
    out.position = relative;
    return out;
}

@fragment
fn ocean_fs(in: OceanVertex) -> @location(0) vec4<f32> {
    // The pixel's own footprint l (not the grid cell's): normals stay exact farther than the
    // geometry (§3.2).
    let l = pixel_footprint(in.clip.xy);
    let s = pixel_surface(in.rest, l);
    let v = normalize(-in.position);
    let light = sea_color(v, s.normal, frame.sea.xy, s.variance);
    return display(light.sun + light.sky + light.sea);
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
    let dir = pixel_ray(in.clip.xy).dir;
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
    return display(radiance);
}
