// Relaxed (and conservative) cone maps on the GPU: ocean_relief::ConeMap::generate, pass for
// pass. The CPU computes the cell bound (ocean_relief::bound, ::arc) and the branch-and-bound
// over the min-depth pyramid (ocean_relief::search) in f64; WGSL has no f64, so this file
// carries the same computations in double-f32 ("df": an unevaluated sum hi + lo of two f32,
// about 46 significand bits), operation for operation, and keeps the CPU's exact steps exact:
//
// - differences of two f32 depths, products of an f32 with an integer below 2^24, and sums of
//   such terms are exact in df as they are in f64, so every sign test (the falling test, the
//   twist, the angular order of the arcs) decides as the CPU does;
// - the values (cone bounds, arc lengths, the Lipschitz and rise bounds) are within about 2^-44
//   relative of the CPU's f64 values, and every value reaches the cone map through a directed
//   rounding to f32 (down for cones, up for the Lipschitz and rise bounds) that this file
//   performs exactly on its df value, so the f32 results differ from the CPU's only when an f64
//   value lies within about 2^-44 of an f32 boundary;
// - the error-free transformations under the df arithmetic (two_sum, two_prod) need every + -
//   * rounded once, in the written order: each intermediate goes through opq(), a bit-level
//   identity the compiler cannot see through (xor with gen.pyramid.w, a zero only known at run
//   time), so no compiler may fuse, reassociate or simplify them.
//
// Passes (each one dispatch of 8 x 8 workgroups over its grid):
// 1. cells: per cell (the unit square between four texel centres), what the bound needs
//    (ocean_relief::bound::Cell): smallest and largest corner depth, the gradient boxes rounded
//    outwards, the Lipschitz bound rounded up, the twist's sign, flatness.
// 2. reduce (once per pyramid level >= 1): the min-depth pyramid (ocean_relief::search::Pyramid)
//    with the largest Lipschitz bound of each node (the root's is L over all cells).
// 3. search: per apex cell, the branch-and-bound of ocean_relief::search::Search::cell_cone with
//    an explicit stack; writes c, D and E of the cell, each already divided by N and rounded
//    down to f32 (down32(v / N) of the CPU, which commutes with the minima that follow). For a
//    quadrant cone map (ocean_relief::quad, gen.sector.x = 1 + the quadrant's layer index) the
//    pass runs once per layer and clips every box of vectors to the quadrant (Apex::within,
//    Apex::vectors): a node or cell whose clipped box is empty is skipped, distances, falling
//    tests and the near-cell rise take the clipped box, and a clipped box that holds the origin
//    has its directions on the quadrant's closed arc (arc::quadrant_arc).
// 4. texels: each texel takes the smallest value of its four cells (ocean_relief::cone).

// Byte for byte ocean_relief::gpu_params::ConeGenUniforms (128 bytes).
struct Gen {
    // N, cells per side nc, edge (0 wrap, 1 clamp), kind (0 relaxed, 1 conservative)
    grid: vec4<u32>,
    // pyramid side P, levels, the level a reduce pass writes, 0 (the opaque zero)
    pyramid: vec4<u32>,
    // max_ratio, 0, 0, 0
    cap: vec4<f32>,
    // 0 (every direction) or 1 + the quadrant's layer index (x_neg + 2 y_neg), 0, 0, 0
    sector: vec4<u32>,
    // offset of pyramid level l >= 1 in `pyramid`, in nodes, at [l / 4][l % 4]
    level_offsets: array<vec4<u32>, 4>,
}

@group(0) @binding(0) var<uniform> gen: Gen;
// Depths, row-major, N x N.
@group(0) @binding(1) var<storage, read> depths: array<f32>;
// Cells, two vec4 each: (m, smax, gx0, gx1), (gy0, gy1, lip, (twist + 1) + 3 flat).
@group(0) @binding(2) var<storage, read_write> cells_out: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read> cells: array<vec4<f32>>;
// Pyramid levels >= 1, six f32 per node: m, gx0, gx1, gy0, gy1, lip.
@group(0) @binding(4) var<storage, read_write> pyramid_out: array<f32>;
@group(0) @binding(5) var<storage, read> pyramid: array<f32>;
// Per cell: (c, D, E, 0), texture widths (per unit depth for c and E), rounded down.
@group(0) @binding(6) var<storage, read_write> cones_out: array<vec4<f32>>;
@group(0) @binding(7) var<storage, read> cones: array<vec4<f32>>;
// Per texel: (depth, c, D, E), the relief texture.
@group(0) @binding(8) var<storage, read_write> texels_out: array<vec4<f32>>;

// A stand-in for infinity (shader compilers may assume there are none): larger than every
// value the bound can produce, whose products with cell extents stay finite in df.
const HUGE: f32 = 1.0e30;
// Empty pyramid node extents, as ocean_relief::search's EMPTY (the infinities of the CPU).
const EMPTY_M: f32 = 3.0e38;
// ocean_relief::bound::BIG, the extent of a clamp-mode border strip.
const BIG: i32 = 1073741824;
// ocean_relief::bound::K_LIP and the side of the near neighbourhood.
const K_LIP: i32 = 3;
const NEAR: i32 = 7;

// ---------------------------------------------------------------------------------------------
// Double-f32 arithmetic. A df is vec2(hi, lo), always normalised: hi = RN(hi + lo), so two dfs
// compare exactly by (hi, then lo).

fn opq(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) ^ gen.pyramid.w);
}

// (s, e): s = RN(a + b), s + e = a + b exactly (Knuth).
fn two_sum(a_in: f32, b_in: f32) -> vec2<f32> {
    let a = opq(a_in);
    let b = opq(b_in);
    let s = opq(a + b);
    let bb = opq(s - a);
    let t = opq(s - bb);
    return vec2<f32>(s, opq(opq(a - t) + opq(b - bb)));
}

// two_sum for |a| >= |b| (or a = 0) (Dekker).
fn fast_two_sum(a_in: f32, b_in: f32) -> vec2<f32> {
    let a = opq(a_in);
    let b = opq(b_in);
    let s = opq(a + b);
    return vec2<f32>(s, opq(b - opq(s - a)));
}

// (p, e): p = RN(a b), p + e = a b exactly (Dekker, operands split by masking their low 12
// significand bits, so every partial product is exact).
fn two_prod(a_in: f32, b_in: f32) -> vec2<f32> {
    let a = opq(a_in);
    let b = opq(b_in);
    let ah = bitcast<f32>(bitcast<u32>(a) & 0xfffff000u);
    let bh = bitcast<f32>(bitcast<u32>(b) & 0xfffff000u);
    let al = opq(a - ah);
    let bl = opq(b - bh);
    let p = opq(a * b);
    let e1 = opq(opq(ah * bh) - p);
    let e2 = opq(e1 + opq(ah * bl));
    let e3 = opq(e2 + opq(al * bh));
    return vec2<f32>(p, opq(e3 + opq(al * bl)));
}

fn df(x: f32) -> vec2<f32> {
    return vec2<f32>(x, 0.0);
}

// An integer of magnitude below 2^31, exactly.
fn df_i(i: i32) -> vec2<f32> {
    let hi = f32(i);
    // |i| < 2^31 - 2^7, so hi is below 2^31 and i32(hi) exists.
    return vec2<f32>(hi, f32(i - i32(hi)));
}

fn d_neg(a: vec2<f32>) -> vec2<f32> {
    return -a;
}

// Accurate addition (QD's ieee_add): relative error about 2^-44 of the exact sum, so the sign
// of a sum is always right and a zero sum is exactly zero.
fn d_add(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let s = two_sum(a.x, b.x);
    let t = two_sum(a.y, b.y);
    let u = fast_two_sum(s.x, opq(s.y + t.x));
    return fast_two_sum(u.x, opq(u.y + t.y));
}

fn d_sub(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return d_add(a, -b);
}

fn d_mul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let p = two_prod(a.x, b.x);
    let cross = opq(opq(a.x * b.y) + opq(a.y * b.x));
    return fast_two_sum(p.x, opq(p.y + cross));
}

fn d_mul_f(a: vec2<f32>, b: f32) -> vec2<f32> {
    let p = two_prod(a.x, b);
    return fast_two_sum(p.x, opq(p.y + opq(a.y * b)));
}

fn d_div(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let q1 = opq(a.x / b.x);
    var r = d_sub(a, d_mul_f(b, q1));
    let q2 = opq(r.x / b.x);
    r = d_sub(r, d_mul_f(b, q2));
    let q3 = opq(r.x / b.x);
    return d_add(fast_two_sum(q1, q2), df(q3));
}

fn d_sqrt(a: vec2<f32>) -> vec2<f32> {
    if a.x <= 0.0 {
        return vec2<f32>(0.0);
    }
    let s = opq(sqrt(a.x));
    let r = d_sub(a, two_prod(s, s));
    return fast_two_sum(s, opq(r.x / opq(2.0 * s)));
}

fn d_lt(a: vec2<f32>, b: vec2<f32>) -> bool {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

fn d_max(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return select(a, b, d_lt(a, b));
}

fn d_min(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return select(a, b, d_lt(b, a));
}

fn d_abs(a: vec2<f32>) -> vec2<f32> {
    return select(a, -a, a.x < 0.0);
}

// 1 / l for an f32 l >= 0, HUGE (the CPU's infinity) for 0.
fn inverse(l: f32) -> vec2<f32> {
    if l > 0.0 {
        return d_div(df(1.0), df(l));
    }
    return df(HUGE);
}

// The neighbour of finite x towards +inf (up) or -inf.
fn next_f32(x: f32, up: bool) -> f32 {
    if x == 0.0 {
        return select(-1.0e-45, 1.0e-45, up);
    }
    let bits = bitcast<u32>(x);
    let away = (x > 0.0) == up;
    return bitcast<f32>(select(bits - 1u, bits + 1u, away));
}

// ocean_relief::bound::down32 / up32 of a df value: exact, since hi = RN(hi + lo).
fn down32(a: vec2<f32>) -> f32 {
    return select(a.x, next_f32(a.x, false), a.y < 0.0);
}

fn up32(a: vec2<f32>) -> f32 {
    return select(a.x, next_f32(a.x, true), a.y > 0.0);
}

// down32(v / n) for v >= 0 and an integer n: the largest f32 f with f n <= v, decided exactly
// (f n is exact in df).
fn down_div(v: vec2<f32>, n: f32) -> f32 {
    var f = opq(v.x / n);
    for (var k = 0; k < 4; k++) {
        if d_lt(v, two_prod(f, n)) {
            f = next_f32(f, false);
        }
    }
    for (var k = 0; k < 4; k++) {
        let g = next_f32(f, true);
        if !d_lt(v, two_prod(g, n)) {
            f = g;
        }
    }
    return f;
}

// ---------------------------------------------------------------------------------------------
// The grid of cells (ocean_relief::bound::Grid).

fn wrap_mode() -> bool {
    return gen.grid.z == 0u;
}

fn relaxed() -> bool {
    return gen.grid.w == 0u;
}

fn origin() -> i32 {
    return select(-1, 0, wrap_mode());
}

// i.rem_euclid(n) for n > 0, in unsigned arithmetic: GLSL leaves % undefined for negative
// operands (Mesa's llvmpipe returns the unsigned remainder of the two's complement).
fn rem_euclid(i: i32, n: i32) -> i32 {
    if i >= 0 {
        return i32(u32(i) % u32(n));
    }
    return n - 1 - i32(u32(-(i + 1)) % u32(n));
}

// Depth of texel (i, j), any integers, resolved by the edge mode (HeightMap::depth).
fn depth_at(i: i32, j: i32) -> f32 {
    let n = i32(gen.grid.x);
    var x = clamp(i, 0, n - 1);
    var y = clamp(j, 0, n - 1);
    if wrap_mode() {
        x = rem_euclid(i, n);
        y = rem_euclid(j, n);
    }
    return depths[y * n + x];
}

// Index of the cell at spatial position (ci, cj), or -1 (Grid::index).
fn cell_index(ci: i32, cj: i32) -> i32 {
    let n = i32(gen.grid.x);
    let nc = i32(gen.grid.y);
    if wrap_mode() {
        return rem_euclid(cj, n) * nc + rem_euclid(ci, n);
    }
    let x = ci + 1;
    let y = cj + 1;
    if x >= 0 && x < nc && y >= 0 && y < nc {
        return y * nc + x;
    }
    return -1;
}

struct Cell {
    m: f32,
    smax: f32,
    // [gx0, gx1, gy0, gy1]
    g: vec4<f32>,
    lip: f32,
    twist: i32,
    flat: bool,
}

fn load_cell(k: i32) -> Cell {
    let a = cells[2 * k];
    let b = cells[2 * k + 1];
    let code = i32(b.w);
    return Cell(a.x, a.y, vec4<f32>(a.z, a.w, b.x, b.y), b.z, (code % 3) - 1, code >= 3);
}

// 1 + 1e-12 and 1 + 1e-9, the CPU's safety factors, in df.
fn one_plus(e: f32) -> vec2<f32> {
    return vec2<f32>(1.0, e);
}

@compute @workgroup_size(8, 8)
fn cells_pass(@builtin(global_invocation_id) id: vec3<u32>) {
    let nc = gen.grid.y;
    if id.x >= nc || id.y >= nc {
        return;
    }
    let i = i32(id.x) + origin();
    let j = i32(id.y) + origin();
    let a = depth_at(i, j);
    let b = depth_at(i + 1, j);
    let c = depth_at(i, j + 1);
    let d = depth_at(i + 1, j + 1);
    // Differences of two f32 values, exactly.
    let ex0 = two_sum(b, -a);
    let ex1 = two_sum(d, -c);
    let ey0 = two_sum(c, -a);
    let ey1 = two_sum(d, -b);
    let mx = d_max(d_abs(ex0), d_abs(ex1));
    let my = d_max(d_abs(ey0), d_abs(ey1));
    // |grad| <= sqrt(mx^2 + my^2) in the cell; the factor covers the CPU's roundings.
    let lip = up32(d_mul(d_sqrt(d_add(d_mul(mx, mx), d_mul(my, my))), one_plus(1.0e-12)));
    let t = d_add(d_add(two_sum(a, -b), df(-c)), df(d));
    let twist = select(select(0, -1, t.x < 0.0), 1, t.x > 0.0);
    let flat = a == b && a == c && a == d;
    let k = id.y * nc + id.x;
    cells_out[2u * k] = vec4<f32>(
        min(min(a, b), min(c, d)),
        max(max(a, b), max(c, d)),
        down32(d_min(ex0, ex1)),
        up32(d_max(ex0, ex1)),
    );
    cells_out[2u * k + 1u] = vec4<f32>(
        down32(d_min(ey0, ey1)),
        up32(d_max(ey0, ey1)),
        lip,
        f32(twist + 1 + select(0, 3, flat)),
    );
}

// ---------------------------------------------------------------------------------------------
// The min-depth pyramid (ocean_relief::search::Pyramid).

struct Node {
    m: f32,
    g: vec4<f32>,
    lip: f32,
}

fn empty_node() -> Node {
    return Node(EMPTY_M, vec4<f32>(EMPTY_M, -EMPTY_M, EMPTY_M, -EMPTY_M), 0.0);
}

fn merge(a: Node, b: Node) -> Node {
    return Node(
        min(a.m, b.m),
        vec4<f32>(min(a.g.x, b.g.x), max(a.g.y, b.g.y), min(a.g.z, b.g.z), max(a.g.w, b.g.w)),
        max(a.lip, b.lip),
    );
}

fn level_offset(level: u32) -> u32 {
    return gen.level_offsets[level / 4u][level % 4u];
}

// Level 0 node (x, y): the cell, or empty outside the grid and, for relaxed cones, for flat
// cells (which keep lip 0, the same as an empty node's).
fn base_node(x: u32, y: u32) -> Node {
    let nc = gen.grid.y;
    if x >= nc || y >= nc {
        return empty_node();
    }
    let c = load_cell(i32(y * nc + x));
    if relaxed() && c.flat {
        return empty_node();
    }
    return Node(c.m, c.g, c.lip);
}

fn stored_node(level: u32, x: u32, y: u32) -> Node {
    let side = gen.pyramid.x >> level;
    let k = 6u * (level_offset(level) + y * side + x);
    return Node(
        pyramid[k],
        vec4<f32>(pyramid[k + 1u], pyramid[k + 2u], pyramid[k + 3u], pyramid[k + 4u]),
        pyramid[k + 5u],
    );
}

fn node_at(level: u32, x: u32, y: u32) -> Node {
    if level == 0u {
        return base_node(x, y);
    }
    return stored_node(level, x, y);
}

// The reduce pass reads the level below from the buffer it writes.
fn node_rw(level: u32, x: u32, y: u32) -> Node {
    if level == 0u {
        return base_node(x, y);
    }
    let side = gen.pyramid.x >> level;
    let k = 6u * (level_offset(level) + y * side + x);
    return Node(
        pyramid_out[k],
        vec4<f32>(pyramid_out[k + 1u], pyramid_out[k + 2u], pyramid_out[k + 3u], pyramid_out[k + 4u]),
        pyramid_out[k + 5u],
    );
}

@compute @workgroup_size(8, 8)
fn reduce_pass(@builtin(global_invocation_id) id: vec3<u32>) {
    let level = gen.pyramid.z;
    let side = gen.pyramid.x >> level;
    if id.x >= side || id.y >= side {
        return;
    }
    let below = level - 1u;
    let x = 2u * id.x;
    let y = 2u * id.y;
    let node = merge(
        merge(node_rw(below, x, y), node_rw(below, x + 1u, y)),
        merge(node_rw(below, x, y + 1u), node_rw(below, x + 1u, y + 1u)),
    );
    let k = 6u * (level_offset(level) + id.y * side + id.x);
    pyramid_out[k] = node.m;
    pyramid_out[k + 1u] = node.g.x;
    pyramid_out[k + 2u] = node.g.y;
    pyramid_out[k + 3u] = node.g.z;
    pyramid_out[k + 4u] = node.g.w;
    pyramid_out[k + 5u] = node.lip;
}

// ---------------------------------------------------------------------------------------------
// The apex cell (ocean_relief::bound::Apex).

struct Apex {
    qi: i32,
    qj: i32,
    // [x0, x1, y0, y1], +-BIG for clamp-mode border strips.
    rect: vec4<i32>,
    smax: f32,
    // The closed box [wx0, wx1, wy0, wy1] of vectors the cone serves (Apex::clip): +-UNBOUNDED
    // (every vector) or one closed quadrant.
    clip: vec4<i32>,
    // The quadrant's layer index, or -1 for every direction (Apex::sector).
    sector: i32,
}

// Beyond every vector component (|w| <= BIG + 2 nc < 2^31 - 1): the CPU's infinite clip.
const UNBOUNDED: i32 = 2147483647;

// The closed quadrant of layer k (ocean_relief::Quadrant::vectors): x_neg = k & 1 clips
// w_x to <= 0, else >= 0; y_neg = k >> 1 likewise w_y.
fn quadrant_clip(k: i32) -> vec4<i32> {
    var c = vec4<i32>(0, UNBOUNDED, 0, UNBOUNDED);
    if (k & 1) != 0 {
        c.x = -UNBOUNDED;
        c.y = 0;
    }
    if (k & 2) != 0 {
        c.z = -UNBOUNDED;
        c.w = 0;
    }
    return c;
}

var<private> apex: Apex;
// Largest lip within Chebyshev distance r of the apex cell, and 1/lring (HUGE for 0).
var<private> lring: array<f32, 4>;
var<private> inv_lring: array<vec2<f32>, 4>;
// Per offset (dx, dy) in [-3, 3]^2, row-major: the union of the gradient boxes of the cells in
// the bounding box of the apex cell and that cell.
var<private> path: array<vec4<f32>, 49>;
// L over all cells and 1 / L (HUGE for 0): the floor of every candidate's value.
var<private> lip_global: f32;
var<private> inv_lip_global: vec2<f32>;
// The best c, D and E so far, texels (per unit depth for c and E).
var<private> best: array<vec2<f32>, 3>;

fn own_box(dx: i32, dy: i32) -> vec4<f32> {
    let k = cell_index(apex.qi + dx, apex.qj + dy);
    if k < 0 {
        return vec4<f32>(EMPTY_M, -EMPTY_M, EMPTY_M, -EMPTY_M);
    }
    return load_cell(k).g;
}

fn union_box(a: vec4<f32>, b: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(min(a.x, b.x), max(a.y, b.y), min(a.z, b.z), max(a.w, b.w));
}

fn path_at(dx: i32, dy: i32) -> i32 {
    return (dy + K_LIP) * NEAR + dx + K_LIP;
}

fn make_apex(qi: i32, qj: i32) {
    let n = i32(gen.grid.x);
    let cell = load_cell(cell_index(qi, qj));
    var rect = vec4<i32>(qi, qi + 1, qj, qj + 1);
    if !wrap_mode() {
        if qi == -1 {
            rect.x = -BIG;
        }
        if qi == n - 1 {
            rect.y = BIG;
        }
        if qj == -1 {
            rect.z = -BIG;
        }
        if qj == n - 1 {
            rect.w = BIG;
        }
    }
    var clip = vec4<i32>(-UNBOUNDED, UNBOUNDED, -UNBOUNDED, UNBOUNDED);
    let sector = i32(gen.sector.x) - 1;
    if sector >= 0 {
        clip = quadrant_clip(sector);
    }
    apex = Apex(qi, qj, rect, cell.smax, clip, sector);
    for (var r = 0; r <= K_LIP; r++) {
        var m = 0.0;
        for (var dj = -r; dj <= r; dj++) {
            for (var di = -r; di <= r; di++) {
                let k = cell_index(qi + di, qj + dj);
                if k >= 0 {
                    m = max(m, load_cell(k).lip);
                }
            }
        }
        lring[r] = m;
        inv_lring[r] = inverse(m);
    }
    for (var sy = -1; sy <= 1; sy += 2) {
        for (var sx = -1; sx <= 1; sx += 2) {
            for (var ady = 0; ady <= K_LIP; ady++) {
                for (var adx = 0; adx <= K_LIP; adx++) {
                    let dx = sx * adx;
                    let dy = sy * ady;
                    var b = own_box(dx, dy);
                    if adx > 0 {
                        b = union_box(b, path[path_at(dx - sx, dy)]);
                    }
                    if ady > 0 {
                        b = union_box(b, path[path_at(dx, dy - sy)]);
                    }
                    path[path_at(dx, dy)] = b;
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The cell bound (ocean_relief::bound).

// The largest g w over g in [g0, g1] and w in [w0, w1].
fn max_product(g0: f32, g1: f32, w0: i32, w1: i32) -> vec2<f32> {
    let a = df_i(w0);
    let b = df_i(w1);
    return d_max(
        d_max(d_mul_f(a, g0), d_mul_f(b, g0)),
        d_max(d_mul_f(a, g1), d_mul_f(b, g1)),
    );
}

// The box of vectors from the apex box into `rect` that the cone serves, clipped to the apex's
// quadrant (Apex::vectors); empty (see `is_empty`) when no such vector exists.
fn vectors_to(rect: vec4<i32>) -> vec4<i32> {
    let q = apex.rect;
    let c = apex.clip;
    return vec4<i32>(
        max(rect.x - q.y, c.x),
        min(rect.y - q.x, c.y),
        max(rect.z - q.w, c.z),
        min(rect.w - q.z, c.w),
    );
}

fn is_empty(w: vec4<i32>) -> bool {
    return w.x > w.y || w.z > w.w;
}

// The largest g w over gradients in the box g and the vectors of the box w.
fn growth(w: vec4<i32>, g: vec4<f32>) -> vec2<f32> {
    return d_add(max_product(g.x, g.y, w.x, w.y), max_product(g.z, g.w, w.z, w.w));
}

// Condition 2 for a pyramid node (bound::falling), w its clipped box of vectors.
fn falling(w: vec4<i32>, g: vec4<f32>) -> bool {
    return growth(w, g).x >= 0.0;
}

// Condition 2 for one cell (bound::falling_cell), w its clipped box of vectors.
fn falling_cell(w: vec4<i32>, cell: Cell) -> bool {
    let f = growth(w, cell.g);
    if f.x > 0.0 {
        return true;
    }
    if f.x < 0.0 {
        return false;
    }
    if cell.twist == 1 {
        return (w.y > 0 && w.w > 0) || (w.x < 0 && w.z < 0);
    }
    if cell.twist == -1 {
        return (w.y > 0 && w.z < 0) || (w.x < 0 && w.w > 0);
    }
    return false;
}

// The shortest vector of the clipped box w (bound::distance): without a quadrant the Euclidean
// distance between the apex box and the rectangle.
fn distance(w: vec4<i32>) -> vec2<f32> {
    let gx = max(max(w.x, -w.y), 0);
    let gy = max(max(w.z, -w.w), 0);
    if gx == 0 {
        return df_i(gy);
    }
    if gy == 0 {
        return df_i(gx);
    }
    let fx = f32(gx);
    let fy = f32(gy);
    return d_sqrt(d_add(two_prod(fx, fx), two_prod(fy, fy)));
}

// ---------------------------------------------------------------------------------------------
// Arcs of directions (ocean_relief::arc). A vector is vec4(x.hi, x.lo, y.hi, y.lo).

struct Arc {
    start: vec4<f32>,
    end: vec4<f32>,
    // pseudo-angle of start, pseudo-angular length
    p0: vec2<f32>,
    len: vec2<f32>,
    ok: bool,
}

fn no_arc() -> Arc {
    return Arc(vec4<f32>(0.0), vec4<f32>(0.0), vec2<f32>(0.0), vec2<f32>(0.0), false);
}

// The diamond angle of a non-zero vector, in [0, 4) (arc::pseudo).
fn pseudo(v: vec4<f32>) -> vec2<f32> {
    let x = v.xy;
    let y = v.zw;
    let zero = vec2<f32>(0.0);
    if !d_lt(y, zero) {
        if !d_lt(x, zero) {
            return d_div(y, d_add(x, y));
        }
        return d_sub(df(1.0), d_div(x, d_add(-x, y)));
    }
    if d_lt(x, zero) {
        return d_sub(df(2.0), d_div(y, d_add(-x, -y)));
    }
    let a = d_add(df(3.0), d_div(x, d_sub(x, y)));
    if !d_lt(a, df(4.0)) {
        return zero;
    }
    return a;
}

// a - b wrapped into [0, 4) (arc::ahead).
fn ahead(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let d = d_sub(a, b);
    if d.x < 0.0 {
        return d_add(d, df(4.0));
    }
    return d;
}

fn make_arc(start: vec4<f32>, end: vec4<f32>, len: vec2<f32>) -> Arc {
    return Arc(start, end, pseudo(start), len, true);
}

fn arc_contains(arc: Arc, v: vec4<f32>) -> bool {
    return !d_lt(arc.len, ahead(pseudo(v), arc.p0));
}

fn cross2(a: vec4<f32>, b: vec4<f32>) -> vec2<f32> {
    return d_sub(d_mul(a.xy, b.zw), d_mul(a.zw, b.xy));
}

fn nonzero(v: vec4<f32>) -> bool {
    return v.x != 0.0 || v.z != 0.0;
}

// The directions of a box of vectors that does not contain the origin (arc::box_directions);
// the box is [x0, x1] x [y0, y1] in df.
fn box_directions(x0: vec2<f32>, x1: vec2<f32>, y0: vec2<f32>, y1: vec2<f32>) -> Arc {
    let zero = vec2<f32>(0.0);
    if !d_lt(zero, x0) && !d_lt(x1, zero) && !d_lt(zero, y0) && !d_lt(y1, zero) {
        return no_arc();
    }
    var c = array<vec4<f32>, 4>(
        vec4<f32>(x0, y0),
        vec4<f32>(x1, y0),
        vec4<f32>(x0, y1),
        vec4<f32>(x1, y1),
    );
    var start = -1;
    var end = -1;
    for (var i = 0; i < 4; i++) {
        if !nonzero(c[i]) {
            continue;
        }
        var first = true;
        var last = true;
        for (var j = 0; j < 4; j++) {
            if !nonzero(c[j]) {
                continue;
            }
            if d_lt(cross2(c[i], c[j]), zero) {
                first = false;
            }
            if d_lt(cross2(c[j], c[i]), zero) {
                last = false;
            }
        }
        if first && start < 0 {
            start = i;
        }
        if last && end < 0 {
            end = i;
        }
    }
    if start < 0 || end < 0 {
        return no_arc();
    }
    let s = c[start];
    let e = c[end];
    return make_arc(s, e, ahead(pseudo(e), pseudo(s)));
}

// The closed quarter turn of the directions of quadrant k, counter-clockwise from its first
// axis to its second (arc::quadrant_arc).
fn quadrant_arc(k: i32) -> Arc {
    let sx = select(1.0, -1.0, (k & 1) != 0);
    let sy = select(1.0, -1.0, (k & 2) != 0);
    let ax = vec4<f32>(sx, 0.0, 0.0, 0.0);
    let ay = vec4<f32>(0.0, 0.0, sy, 0.0);
    if sx * sy > 0.0 {
        return make_arc(ax, ay, df(1.0));
    }
    return make_arc(ay, ax, df(1.0));
}

// The closed arc of directions u with g u <= 0 for every g in the gradient box (arc::non_growing).
fn non_growing(g: vec4<f32>) -> Arc {
    let span = box_directions(df(g.x), df(g.y), df(g.z), df(g.w));
    if !span.ok {
        return no_arc();
    }
    // From end + 1/4 turn to start + 3/4 turn.
    let start = vec4<f32>(-span.end.zw, span.end.xy);
    let end = vec4<f32>(span.start.zw, -span.start.xy);
    return make_arc(start, end, d_sub(df(2.0), span.len));
}

// The largest rate at which the path can rise along a direction from the apex box into the
// candidate (w) along which the candidate may fall (gc), given the path's gradient box gp
// (arc::max_rise), rounded up. With a quadrant, a box that holds the origin has its directions
// on the quadrant's closed arc, not on the whole circle.
fn max_rise(w: vec4<i32>, gc: vec4<f32>, gp: vec4<f32>) -> f32 {
    var d = box_directions(df_i(w.x), df_i(w.y), df_i(w.z), df_i(w.w));
    if !d.ok && apex.sector >= 0 {
        d = quadrant_arc(apex.sector);
    }
    let x = non_growing(gc);
    // arc::subtract: d (or the whole circle) minus the closed arc x.
    var arcs = array<Arc, 2>(no_arc(), no_arc());
    var full = false;
    if !x.ok {
        arcs[0] = d;
        full = !d.ok;
    } else {
        let rest = make_arc(x.end, x.start, d_sub(df(4.0), x.len));
        if !d.ok {
            arcs[0] = rest;
        } else {
            let a = ahead(rest.p0, d.p0);
            var k = 0;
            for (var s = 0; s < 2; s++) {
                let lo = d_add(a, df(select(0.0, -4.0, s == 1)));
                let hi = d_add(lo, rest.len);
                if d_lt(hi, vec2<f32>(0.0)) || d_lt(d.len, lo) {
                    continue;
                }
                var st = d.start;
                var sp = vec2<f32>(0.0);
                if lo.x > 0.0 {
                    st = rest.start;
                    sp = lo;
                }
                var en = d.end;
                var ep = d.len;
                if d_lt(hi, d.len) {
                    en = rest.end;
                    ep = hi;
                }
                arcs[k] = make_arc(st, en, d_sub(ep, sp));
                k += 1;
            }
        }
    }
    // Corners of the support of -gp.
    var e = array<vec2<f32>, 4>(
        vec2<f32>(-gp.y, -gp.w),
        vec2<f32>(-gp.x, -gp.w),
        vec2<f32>(-gp.y, -gp.z),
        vec2<f32>(-gp.x, -gp.z),
    );
    var best_rise = vec2<f32>(0.0);
    for (var i = 0; i < 4; i++) {
        let ex = e[i].x;
        let ey = e[i].y;
        let norm = d_sqrt(d_add(two_prod(ex, ex), two_prod(ey, ey)));
        if norm.x == 0.0 {
            continue;
        }
        if full {
            best_rise = d_max(best_rise, norm);
            continue;
        }
        let v = vec4<f32>(ex, 0.0, ey, 0.0);
        for (var j = 0; j < 2; j++) {
            let arc = arcs[j];
            if !arc.ok {
                continue;
            }
            if arc_contains(arc, v) {
                best_rise = d_max(best_rise, norm);
            }
            for (var t = 0; t < 2; t++) {
                let u = select(arc.start, arc.end, t == 1);
                let l = d_sqrt(d_add(d_mul(u.xy, u.xy), d_mul(u.zw, u.zw)));
                if l.x > 0.0 {
                    let dot = d_add(d_mul_f(u.xy, ex), d_mul_f(u.zw, ey));
                    best_rise = d_max(best_rise, d_div(dot, l));
                }
            }
        }
    }
    return up32(d_mul(best_rise, one_plus(1.0e-9)));
}

// A candidate cell's dist(q, C), Smax(q) - m_C and B; ok false when the cell is not a
// candidate (bound::candidate).
struct Candidate {
    dist: vec2<f32>,
    depth: vec2<f32>,
    b: vec2<f32>,
    ok: bool,
}

fn candidate(cell: Cell, ci: i32, cj: i32) -> Candidate {
    var out = Candidate(vec2<f32>(0.0), vec2<f32>(0.0), vec2<f32>(0.0), false);
    if cell.m >= apex.smax || (relaxed() && cell.flat) {
        return out;
    }
    let rect = vec4<i32>(ci, ci + 1, cj, cj + 1);
    let w = vectors_to(rect);
    if is_empty(w) {
        return out;
    }
    if relaxed() && !falling_cell(w, cell) {
        return out;
    }
    let dx = ci - apex.qi;
    let dy = cj - apex.qj;
    let cheb = max(abs(dx), abs(dy));
    var b = inv_lip_global;
    if cheb <= K_LIP {
        b = inv_lring[cheb];
    }
    if cheb <= K_LIP {
        // The direction-consistent bound of near cells; a conservative cone excludes no
        // direction (a gradient box around the origin excludes none).
        let g = select(vec4<f32>(-1.0, 1.0, -1.0, 1.0), cell.g, relaxed());
        let rise = max_rise(w, g, path[path_at(dx, dy)]);
        if rise <= 0.0 {
            return out;
        }
        b = d_max(b, d_div(df(1.0), df(rise)));
    }
    out.dist = distance(w);
    out.depth = two_sum(apex.smax, -cell.m);
    out.b = b;
    out.ok = true;
    return out;
}

// ---------------------------------------------------------------------------------------------
// The search (ocean_relief::search::Search).

// The plain bound max(dist / depth, 1 / L) of a node (or cell).
fn plain_bound(dist: vec2<f32>, depth: vec2<f32>) -> vec2<f32> {
    return d_max(d_div(dist, depth), inv_lip_global);
}

// Whether a node (or cell) with this distance and plain bound can still lower some channel
// (Search::open).
fn open(dist: vec2<f32>, plain: vec2<f32>) -> bool {
    return d_lt(plain, best[0]) || d_lt(dist, best[1])
        || (dist.x < 1.0 && d_lt(plain, best[2]));
}

fn offer(ci: i32, cj: i32, k: i32) {
    let cand = candidate(load_cell(k), ci, cj);
    if !cand.ok {
        return;
    }
    let value = d_max(d_div(cand.dist, cand.depth), cand.b);
    let near = cand.dist.x < 1.0;
    if d_lt(value, best[0]) {
        best[0] = value;
    }
    if !near && d_lt(cand.dist, best[1]) {
        best[1] = cand.dist;
    }
    if near && d_lt(value, best[2]) {
        best[2] = value;
    }
}

// A pending pyramid node with its distance and plain bound (the CPU keeps the depth and
// recomputes the same bound from it).
struct Entry {
    dist: vec2<f32>,
    plain: vec2<f32>,
    level: u32,
    x: u32,
    y: u32,
}

// Distance and plain bound of a node, or ok = false when it is skipped.
struct Measure {
    dist: vec2<f32>,
    plain: vec2<f32>,
    ok: bool,
}

fn measure(level: u32, x: u32, y: u32, ox: i32, oy: i32) -> Measure {
    var out = Measure(vec2<f32>(0.0), vec2<f32>(0.0), false);
    let node = node_at(level, x, y);
    if node.m >= apex.smax {
        return out;
    }
    let nc = gen.grid.y;
    let x0 = x << level;
    let y0 = y << level;
    if x0 >= nc || y0 >= nc {
        return out;
    }
    let x1 = min((x + 1u) << level, nc);
    let y1 = min((y + 1u) << level, nc);
    let rect = vec4<i32>(ox + i32(x0), ox + i32(x1), oy + i32(y0), oy + i32(y1));
    // No direction the cone serves reaches the node: none of its cells is a candidate.
    let w = vectors_to(rect);
    if is_empty(w) {
        return out;
    }
    let dist = distance(w);
    let plain = plain_bound(dist, two_sum(apex.smax, -node.m));
    if !open(dist, plain) {
        return out;
    }
    if relaxed() && !falling(w, node.g) {
        return out;
    }
    out.dist = dist;
    out.plain = plain;
    out.ok = true;
    return out;
}

// Most entries the depth-first stack can hold: three pending siblings per level below the root
// plus the node being expanded (levels <= 14).
const STACK: i32 = 48;

// Depth-first search of the copy of the pyramid whose cell (0, 0) is at (ox, oy).
fn visit(ox: i32, oy: i32) {
    let top = gen.pyramid.y - 1u;
    let root = measure(top, 0u, 0u, ox, oy);
    if !root.ok {
        return;
    }
    var stack: array<Entry, STACK>;
    var sp = 0;
    stack[0] = Entry(root.dist, root.plain, top, 0u, 0u);
    sp = 1;
    let nc = i32(gen.grid.y);
    while sp > 0 {
        sp -= 1;
        let e = stack[sp];
        if !open(e.dist, e.plain) {
            continue;
        }
        if e.level == 0u {
            offer(ox + i32(e.x), oy + i32(e.y), i32(e.y) * nc + i32(e.x));
            continue;
        }
        let l = e.level - 1u;
        var kids: array<Entry, 4>;
        var count = 0;
        for (var c = 0u; c < 4u; c++) {
            let x = 2u * e.x + (c & 1u);
            let y = 2u * e.y + (c >> 1u);
            let m = measure(l, x, y, ox, oy);
            if m.ok {
                kids[count] = Entry(m.dist, m.plain, l, x, y);
                count += 1;
            }
        }
        // Farthest pushed first, so the nearest is popped first.
        var pushed = 0u;
        for (var t = 0; t < count; t++) {
            var pick = -1;
            for (var c = 0; c < count; c++) {
                if (pushed & (1u << u32(c))) != 0u {
                    continue;
                }
                if pick < 0 || d_lt(kids[pick].dist, kids[c].dist) {
                    pick = c;
                }
            }
            pushed |= 1u << u32(pick);
            if sp < STACK {
                stack[sp] = kids[pick];
                sp += 1;
            }
        }
    }
}

@compute @workgroup_size(8, 8)
fn search_pass(@builtin(global_invocation_id) id: vec3<u32>) {
    let nc = gen.grid.y;
    if id.x >= nc || id.y >= nc {
        return;
    }
    let n = i32(gen.grid.x);
    make_apex(i32(id.x) + origin(), i32(id.y) + origin());
    let top = gen.pyramid.y - 1u;
    let root = node_at(top, 0u, 0u);
    lip_global = root.lip;
    inv_lip_global = inverse(lip_global);
    // The cap, max_ratio N texels, exactly.
    let cap = two_prod(gen.cap.x, f32(n));
    best[0] = cap;
    best[1] = cap;
    best[2] = cap;
    // No cell anywhere is higher than the apex's deepest corner: no candidate in any copy.
    if root.m < apex.smax {
        if wrap_mode() {
            // Copies on ring r >= 1 are at least (r - 1) N away with depth <= 1; the cap
            // (at most 64 N) ends the rings by r = 66.
            for (var r = 0; r < 100; r++) {
                let gap = df_i(max(r - 1, 0) * n);
                if r >= 1 && !open(gap, plain_bound(gap, df(1.0))) {
                    break;
                }
                for (var b = -r; b <= r; b++) {
                    for (var a = -r; a <= r; a++) {
                        if max(abs(a), abs(b)) == r {
                            visit(a * n, b * n);
                        }
                    }
                }
            }
        } else {
            visit(-1, -1);
        }
    }
    // A cell whose plain cone is the cap keeps no clearance or near cap: the tracer's cone
    // max(c, min(D/h, E)) is c there whatever they hold (E <= cap), so both are the cap
    // (ocean_relief::search::Search::cell_cone).
    if !d_lt(best[0], cap) {
        best[1] = cap;
        best[2] = cap;
    }
    let nf = f32(n);
    cones_out[id.y * nc + id.x] = vec4<f32>(
        down_div(best[0], nf),
        down_div(best[1], nf),
        down_div(best[2], nf),
        0.0,
    );
}

@compute @workgroup_size(8, 8)
fn texels_pass(@builtin(global_invocation_id) id: vec3<u32>) {
    let n = gen.grid.x;
    if id.x >= n || id.y >= n {
        return;
    }
    let i = i32(id.x);
    let j = i32(id.y);
    // The cells whose corner is texel (i, j) sit at spatial positions i - 1 and i.
    var v = vec3<f32>(EMPTY_M);
    for (var cj = j - 1; cj <= j; cj++) {
        for (var ci = i - 1; ci <= i; ci++) {
            let k = cell_index(ci, cj);
            if k >= 0 {
                v = min(v, cones[k].xyz);
            }
        }
    }
    texels_out[id.y * n + id.x] = vec4<f32>(depths[id.y * n + id.x], v);
}
