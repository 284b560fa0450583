// Sums of modulated wave sets on a regular grid (the evaluation primitive of wave train boxes):
// the GPU twin of `ocean_core::evaluate_layers`.
//
// A layer is a wave set acting on a rectangle of the grid, its contribution at each point of the
// rectangle multiplied by a complex amplitude μ = m·e^{iφ}, stored as [m cos φ, m sin φ]: the
// point's trains take amplitude m·A_i and phase θ_i + φ (wave-train-boxes Eq. 6 and 7:
// p = p0 − Σ k̂_i m A_i sin(θ_i + φ), y = Σ m A_i cos(θ_i + φ)). m carries what scales a box's
// waves locally (side smoothing, build-up envelope, land, shadow, shoaling), φ what shifts them
// (refraction, round waves). Layers add up where they overlap; outside its rectangle a layer
// contributes nothing. An optional additive height field (one value per grid point) is added to
// the heights last. Normals treat μ as locally constant, as on the CPU.
//
// Arithmetic, in the CPU kernel's order: for each layer in order, for each of its waves in
// order, with the host's [sin, cos] tables of the row and column phase parts (R, C, reduced to
// [-π, π] in f64 on the host by `WaveSet::grid_sin_cos`, so no sine, cosine or unreduced phase
// is evaluated here):
//     sin θ = sin R cos C + cos R sin C,    cos θ = cos R cos C − sin R sin C,
//     s  = sin θ·mr + cos θ·mi               (= m sin(θ + φ)),
//     co = cos θ·mr − sin θ·mi               (= m cos(θ + φ)),
// then accumulated exactly as in trochoid.wgsl; finally y += height and the position and
// normal (same degenerate-normal rule). A point no layer covers stays at rest, normal +y.
//
// Inputs: `layers` holds one descriptor per layer; `data` one array of f32 words holding, at
// the word offsets the descriptors and `params` give, each layer's wave coefficients (8 words a
// wave, `WaveCoeffs` order), its sin/cos tables restricted to its rectangle (rows then columns,
// 2 words a pair), its modulation (2 words a rectangle point, row-major over the rectangle) and
// the height field (1 word a grid point). Packing them into one buffer keeps the pass at four
// storage buffers, the WebGPU/downlevel per-stage limit.
//
// Layout and work mapping as in trochoid.wgsl: point (i, j) of an nx × nz grid is element
// j·nx + i of both outputs; positions (x, y, z, 1), normals (nx, ny, nz, 0); 64 invocations per
// workgroup, linear index (workgroup_id.y · groups_x + workgroup_id.x) · 64 + local index.

// Matches `ocean_gpu::layers::LayersParams` (32 bytes).
struct Params {
    nx: u32,            // grid columns (along x)
    nz: u32,            // grid rows (along z)
    layers: u32,        // number of layer descriptors
    groups_x: u32,      // workgroups along the x dimension of the dispatch
    has_height: u32,    // 1: add data[height + index] to each height; 0: no height field
    height: u32,        // word offset in `data` of the height field
    spacing_x: f32,     // grid spacing along x, metres
    spacing_z: f32,     // grid spacing along z, metres
}

// Matches `ocean_gpu::layers::LayerDesc` (48 bytes). Offsets are in f32 words of `data`.
struct LayerDesc {
    i0: u32,            // first grid column of the rectangle
    j0: u32,            // first grid row of the rectangle
    nx: u32,            // columns of the rectangle
    nz: u32,            // rows of the rectangle
    waves: u32,         // number of waves
    coeffs: u32,        // wave w's coefficients: data[coeffs + 8w .. coeffs + 8w + 8]
    rows: u32,          // [sin R, cos R] of wave w, rectangle row r: data[rows + 2(w·nz + r)]
    cols: u32,          // [sin C, cos C] of wave w, rectangle column c: data[cols + 2(w·nx + c)]
    modulation: u32,    // [m cos φ, m sin φ] at rectangle point (c, r): data[modulation + 2(r·nx + c)]
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> layers: array<LayerDesc>;
@group(0) @binding(2) var<storage, read> data: array<f32>;
@group(0) @binding(3) var<storage, read_write> positions: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> normals: array<vec4<f32>>;

fn pair(offset: u32) -> vec2<f32> {
    return vec2<f32>(data[offset], data[offset + 1u]);
}

@compute @workgroup_size(64)
fn displace(
    @builtin(workgroup_id) group: vec3<u32>,
    @builtin(local_invocation_index) local: u32,
) {
    let index = grid_index(group, local, params.groups_x);
    let nx = params.nx;
    let nz = params.nz;
    // Total point count is checked on the host to fit in u32.
    if index >= nx * nz {
        return;
    }
    let i = index % nx;
    let j = index / nx;

    var g = no_waves();
    for (var l = 0u; l < params.layers; l++) {
        let d = layers[l];
        // Unsigned differences wrap for points before the rectangle, so one test per axis.
        let c = i - d.i0;
        let r = j - d.j0;
        if c >= d.nx || r >= d.nz {
            continue;
        }
        let m = pair(d.modulation + 2u * (r * d.nx + c));   // (mr, mi) = (m cos φ, m sin φ)
        for (var w = 0u; w < d.waves; w++) {
            let k = d.coeffs + 8u * w;
            let row = pair(d.rows + 2u * (w * d.nz + r));    // (sin R, cos R)
            let col = pair(d.cols + 2u * (w * d.nx + c));    // (sin C, cos C)
            let sin_t = row.x * col.y + row.y * col.x;
            let cos_t = row.y * col.y - row.x * col.x;
            let s = sin_t * m.x + cos_t * m.y;
            let co = cos_t * m.x - sin_t * m.y;
            let coeffs = WaveCoeffs(
                data[k], data[k + 1u], data[k + 2u], data[k + 3u],
                data[k + 4u], data[k + 5u], data[k + 6u], data[k + 7u],
            );
            add_wave(&g, coeffs, s, co);
        }
    }
    if params.has_height != 0u {
        g.y += data[params.height + index];
    }

    let x0 = f32(i) * params.spacing_x;
    let z0 = f32(j) * params.spacing_z;
    let normal = unit_normal(g.jxx, g.jxz, g.jzz, g.sx, g.sz);

    positions[index] = vec4<f32>(x0 + g.dx, g.y, z0 + g.dz, 1.0);
    normals[index] = vec4<f32>(normal, 0.0);
}
