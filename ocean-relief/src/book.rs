//! The book's relaxed cone generator, Listing 18-2 (the shader form of Listing 18-1), run on
//! the CPU as printed: for every source texel, a ray from the top of its axis
//! `(s, t, 0)` through every destination texel's surface point, marched forward in
//! `search_steps` equal steps until it is outside the relief again, and
//! `ratio = |ray_pos.xy − src.xy| / (src_depth − ray_pos.z)` (1.0 when the exit lies below the
//! source's depth), the minimum over destinations, starting from 1.0.
//!
//! It is `Θ(N⁴·S)` and kept for small maps only, as the oracle of the book's semantics. Those
//! semantics differ from what the tracer needs ([`crate::bound`], Lemma 1): the listing only
//! casts rays from the **top** of the source's axis and only through texel centres, while
//! Listing 18-3 reuses each cone for rays that pass the axis at any depth, at any slope; the
//! crate's tests show book cones that let a ray enter and leave the surface inside one cone
//! ([`crate::check`]) and rays that go through a feature because of it.
//!
//! Transcription notes: the pair `dst == src` is skipped (the listing would divide 0 by 0), as is
//! a destination at depth 0 (the ray from `src` to it is horizontal at the top: `vec /= vec.z`
//! divides by 0). Offsets are `dst − src` without wrapping, as the listing's per-pass `Offset`;
//! the sampler follows the map's edge mode.

use alloc::vec;

use crate::cone::ConeMap;
use crate::map::HeightMap;
use crate::{ReliefError, check_range, for_rows};

/// Largest side the listing accepts: it is `Θ(N⁴·S)` (about 2·10⁹ fetches at 64² and 128 steps).
pub const MAX_BOOK_SIDE: usize = 64;

/// Listing 18-2's relaxed cones of `map`, marched with `search_steps` steps (the book uses 128).
///
/// # Errors
///
/// [`ReliefError::MapSize`] above [`MAX_BOOK_SIDE`]; [`ReliefError::OutOfRange`] unless
/// `2 ≤ search_steps ≤ 4096`.
pub fn listing_18_2(map: &HeightMap, search_steps: u32) -> Result<ConeMap, ReliefError> {
    crate::map::check_size(map.size(), map.size(), 2, MAX_BOOK_SIDE)?;
    check_range("search_steps", f64::from(search_steps), 2.0, 4096.0)?;
    let n = map.size();
    let nf = n as f32;
    let tex = |u: f32, v: f32| map.sample(u, v);
    let mut ratios = vec![0.0f32; n * n];
    for_rows(&mut ratios, n, |j, row| {
        for (i, out) in row.iter_mut().enumerate() {
            let tc = [(i as f32 + 0.5) / nf, (j as f32 + 0.5) / nf];
            let src_depth = tex(tc[0], tc[1]);
            let mut best = 1.0f32;
            for l in 0..n {
                for k in 0..n {
                    if k == i && l == j {
                        continue;
                    }
                    let offset = [(k as f32 - i as f32) / nf, (l as f32 - j as f32) / nf];
                    let dst = [tc[0] + offset[0], tc[1] + offset[1], 0.0];
                    let dst = [dst[0], dst[1], tex(dst[0], dst[1])];
                    if dst[2] <= 0.0 {
                        continue;
                    }
                    // vec = dst − src; vec /= vec.z; vec *= 1 − dst.z
                    let mut vec = [offset[0], offset[1], dst[2]];
                    vec = [vec[0] / vec[2], vec[1] / vec[2], 1.0];
                    let scale = 1.0 - dst[2];
                    vec = [vec[0] * scale, vec[1] * scale, vec[2] * scale];
                    let steps = search_steps as f32;
                    let fwd = [vec[0] / steps, vec[1] / steps, vec[2] / steps];
                    let mut pos = [dst[0] + fwd[0], dst[1] + fwd[1], dst[2] + fwd[2]];
                    for _ in 1..search_steps {
                        if tex(pos[0], pos[1]) <= pos[2] {
                            pos = [pos[0] + fwd[0], pos[1] + fwd[1], pos[2] + fwd[2]];
                        }
                    }
                    let ratio = if pos[2] >= src_depth {
                        1.0
                    } else {
                        let (dx, dy) = (pos[0] - tc[0], pos[1] - tc[1]);
                        libm::sqrtf(dx * dx + dy * dy) / (src_depth - pos[2])
                    };
                    best = best.min(ratio);
                }
            }
            *out = best;
        }
    });
    ConeMap::from_ratios(n, map.edge(), ratios)
}
