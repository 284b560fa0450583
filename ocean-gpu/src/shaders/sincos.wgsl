// Deterministic sine and cosine: the WGSL twin of `ocean_core::sincos::sincos`.
//
// GPU `sin`/`cos` have no guaranteed accuracy (WGSL leaves it to the implementation), so the
// wave passes use the same Cody-Waite reduction and Cephes minimax polynomials as the CPU
// kernel, with the same constants and the same order of operations. The CPU rounds x·(2/π) to
// the nearest integer with the 1.5·2^23 trick; WGSL's `round` (ties to even) gives the same
// integer without relying on the shader compiler to keep `(a + M) - M` unsimplified.
//
// Valid for |x| <= 8192 (callers pass sums of two phases in [-π, π]).

const SINCOS_FRAC_2_PI: f32 = 0.63661975;
const SINCOS_PIO2_HI: f32 = 1.5703125;
const SINCOS_PIO2_MID: f32 = 4.837513e-4;
const SINCOS_PIO2_LO: f32 = 7.54979e-8;
const SINCOS_S1: f32 = -1.6666655e-1;
const SINCOS_S2: f32 = 8.332161e-3;
const SINCOS_S3: f32 = -1.9515296e-4;
const SINCOS_C1: f32 = 4.1666646e-2;
const SINCOS_C2: f32 = -1.3887316e-3;
const SINCOS_C3: f32 = 2.4433157e-5;

// Returns vec2(sin x, cos x).
fn ocean_sincos(x: f32) -> vec2<f32> {
    let q = round(x * SINCOS_FRAC_2_PI);
    let r = ((x - q * SINCOS_PIO2_HI) - q * SINCOS_PIO2_MID) - q * SINCOS_PIO2_LO;
    let z = r * r;
    let s0 = ((SINCOS_S3 * z + SINCOS_S2) * z + SINCOS_S1) * z * r + r;
    let c0 = ((SINCOS_C3 * z + SINCOS_C2) * z + SINCOS_C1) * z * z - 0.5 * z + 1.0;
    let qi = i32(q);
    let odd = (qi & 1) != 0;
    let s = select(s0, c0, odd);
    let c = select(c0, s0, odd);
    // Quadrant q: sin(x) = [s, c, -s, -c][q mod 4], cos(x) = [c, -s, -c, s][q mod 4]; the sign
    // is applied by flipping the IEEE sign bit, as the CPU does.
    let sin_sign = u32(qi & 2) << 30u;
    let cos_sign = u32((qi + 1) & 2) << 30u;
    return vec2<f32>(
        bitcast<f32>(bitcast<u32>(s) ^ sin_sign),
        bitcast<f32>(bitcast<u32>(c) ^ cos_sign),
    );
}
