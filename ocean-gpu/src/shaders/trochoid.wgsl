// Trochoid (Gerstner) displacement of a regular grid: the GPU twin of
// `ocean_core::WaveSet::evaluate_grid`.
//
// Sum of trochoid waves (wave-train-boxes Eq. 6 and 7): for rest position p0 and wave i with
// phase θ_i = k_i·p0 − ω_i t + Φ_i,
//     p = p0 − Σ k̂_i A_i sin θ_i,   y = Σ A_i cos θ_i,
// and the normal from the analytic derivatives of p and y with respect to p0.
//
// Conventions: metres, right-handed, y up; positions are relative to the grid origin. The phase
// at point (i, j) splits into a row part R_j = k·origin − ωt + Φ + k_z j Δz and a column part
// C_i = k_x i Δx. The host (`WaveSet::grid_sin_cos`) forms and reduces each part to [-π, π] in
// f64 and uploads [sin, cos] of it per wave and row and per wave and column; this shader forms
//     sin θ = sin R cos C + cos R sin C,   cos θ = cos R cos C − sin R sin C
// in the CPU kernel's order of operations, so it evaluates no sine or cosine itself and never
// sees an unreduced phase, whatever the time or the distance from the world origin.
//
// Layout: point (i, j) of an nx × nz grid is element j·nx + i of both outputs (row-major, rows
// along z). positions[n] = (x, y, z, 1), normals[n] = (nx, ny, nz, 0), 16 bytes each, so the
// output buffers also serve as vertex buffers (Float32x4, or Float32x3 with a 16-byte stride).
//
// Work mapping: one invocation per point, 64 per workgroup, linear point index
// (workgroup_id.y · groups_x + workgroup_id.x) · 64 + local_invocation_index, so grids with more
// than 65535 workgroups fold into a second dispatch dimension.

// Matches `ocean_gpu::trochoid::TrochoidParams` (32 bytes).
struct Params {
    nx: u32,            // columns (along x)
    nz: u32,            // rows (along z)
    waves: u32,         // number of waves
    cols_offset: u32,   // index in `tables` of the first column entry (= waves · nz)
    groups_x: u32,      // workgroups along the x dimension of the dispatch
    _pad: u32,
    spacing_x: f32,     // grid spacing along x, metres
    spacing_z: f32,     // grid spacing along z, metres
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> coeffs: array<WaveCoeffs>;
// [sin, cos] of the row parts, tables[w · nz + j] for w < waves, j < nz, then of the column
// parts, tables[cols_offset + w · nx + i] for i < nx.
@group(0) @binding(2) var<storage, read> tables: array<vec2<f32>>;
@group(0) @binding(3) var<storage, read_write> positions: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> normals: array<vec4<f32>>;

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
    for (var w = 0u; w < params.waves; w++) {
        let row = tables[w * nz + j];                        // (sin R, cos R)
        let col = tables[params.cols_offset + w * nx + i];   // (sin C, cos C)
        let s = row.x * col.y + row.y * col.x;
        let co = row.y * col.y - row.x * col.x;
        add_wave(&g, coeffs[w], s, co);
    }

    let x0 = f32(i) * params.spacing_x;
    let z0 = f32(j) * params.spacing_z;
    let normal = unit_normal(g.jxx, g.jxz, g.jzz, g.sx, g.sz);

    positions[index] = vec4<f32>(x0 + g.dx, g.y, z0 + g.dz, 1.0);
    normals[index] = vec4<f32>(normal, 0.0);
}
