// The environment's irradiance on a unit normal from its nine order-2 spherical-harmonic rows
// (ocean_brdf::Irradiance::gpu_rows, rgb per row): E(n) = max(sum_i rows[i].rgb Y_i(n), 0),
// the basis in ocean_brdf::irradiance::sh_basis's order (1; x, y, z; xy, yz, 3y^2 - 1, xz,
// x^2 - z^2) with its normalisations. All-zero rows give 0.
fn sh_irradiance(rows: array<vec4<f32>, 9>, n: vec3<f32>) -> vec3<f32> {
    let c0 = 0.28209479;
    let c1 = 0.48860251;
    let c2 = 1.09254843;
    let c20 = 0.31539157;
    let c22 = 0.54627422;
    var e = rows[0].rgb * c0;
    e += rows[1].rgb * (c1 * n.x) + rows[2].rgb * (c1 * n.y) + rows[3].rgb * (c1 * n.z);
    e += rows[4].rgb * (c2 * n.x * n.y) + rows[5].rgb * (c2 * n.y * n.z);
    e += rows[6].rgb * (c20 * (3.0 * n.y * n.y - 1.0));
    e += rows[7].rgb * (c2 * n.x * n.z) + rows[8].rgb * (c22 * (n.x * n.x - n.z * n.z));
    return max(e, vec3<f32>(0.0));
}
