//! Mip chains of cone maps that stay valid (§18.5).
//!
//! The book: "one should compute the mipmaps manually, by conservatively taking the minimum value
//! for each group of pixels". A coarse texel is read for every apex in its **bilinear support**,
//! which reaches half a coarse texel beyond its own footprint, so the minimum over its 2×2 group
//! alone is not enough: the apex can sit where none of the group's fine texels is valid.
//!
//! **Rule.** Level `l + 1` texel `J` (per axis) is the minimum of level-`l` texels
//! `2J − 1, 2J, 2J + 1, 2J + 2`: the 2×2 group and a one-texel ring (a 4×4 window), indices
//! resolved by the map's edge mode. Every channel (ratio, clearance, near cap) takes the same
//! minimum.
//!
//! **Proof.** Measure positions in level-`l` texel-centre coordinates (one unit = one level-`l`
//! texel). A level-`l` texel `K` is read bilinearly for apexes in `[K − 1, K + 1]` (per axis) and,
//! by induction (level 0: [`crate::cone`]), its value is at most `c*(p)` for every such apex.
//! Level-`l + 1` texel `J` covers level-`l` texels `2J` and `2J + 1`, so its centre is at
//! `2J + ½` and, being two units wide, it is read for apexes in `[2J − 3/2, 2J + 5/2]`. The
//! supports of `K = 2J − 1 … 2J + 2` cover `[2J − 2, 2J + 3]`, which contains it; so every apex
//! the coarse texel serves lies in the support of some `K` of the window, and the window's
//! minimum is at most `c*(p)` there. A bilinear blend of values that are each at most `c*(p)` is
//! at most `c*(p)`. The cone a tracer uses, `max(c, min(D/h, E))`, only grows with each channel,
//! so channel-wise minima keep it valid. ∎ The group alone covers `[2J − 1, 2J + 2]` and misses
//! the outer half texel on each side. (With nearest sampling a coarse texel serves
//! `[2J − ½, 2J + 3/2]` only, and the group's minimum would do; [`MipRule::Group`] is kept to
//! show the difference.)
//!
//! ## Quadrant layers ([`crate::quad`], §18.1)
//!
//! **Rule.** The same window, layer by layer ([`quad_chain`]): level `l + 1` of layer `Q` is the
//! 4×4-window minimum of level `l` of layer `Q`, every channel.
//!
//! **Proof.** A layer serves fewer rays, so the covering argument above stays and what has to be
//! redone is the invariant it carries. Fix a closed quadrant `Q`. The tracer picks the layer once
//! per ray from the ray's horizontal direction `u`, which is the same at every step, so every
//! fetch of layer `Q`, at any level, serves a ray with `u ∈ Q`, wherever along it the ray stands.
//! Let `c_Q(p, h)` be the exact limit of [`crate::check`] with the directions restricted to `Q`
//! (Lemma 1 of [`crate::bound`] with `u ∈ Q`; `h = ∞` the plain cone). At level 0, the bound of
//! any cell that contains `p`, run over the clipped vector boxes `W ∩ Q`, is a triple
//! `T = (c, D, E)` with `max(c, min(D/h, E)) ≤ c_Q(p, h)` for every `h` ([`crate::quad`],
//! [`crate::cone`]), and every level-0 texel read for the apex `p` (those whose bilinear support
//! `[K − 1, K + 1]²` contains `p`) took the channel-wise minimum over its four cells, one of
//! which contains `p`, so it is channel-wise `≤ T`. Suppose every level-`l` texel read for `p`
//! is `≤ T`. A level-`l + 1` texel `J` read for `p` has `p ∈ [2J − 3/2, 2J + 5/2]²` (per axis,
//! level-`l` units), which the supports of its window `K = 2J − 1 … 2J + 2` cover, so some `K` of
//! the window is read for `p` and `J ≤ K ≤ T`. So at every level the four texels the tracer
//! blends at `p` are each `≤ T`, so is their blend (convex weights), and the cone it uses,
//! `max(c, min(D/h, E))`, grows with each channel: it is at most `c_Q(p, h)`. ∎ (Clamp mode:
//! the resolved edge indices cover the border strips as in the isotropic case.)
//!
//! What the restriction cannot buy: a layer might seem to need only the window's side ahead of
//! its rays, since they move along `Q`. But the apex is where the ray stands, anywhere in the
//! coarse texel's support (it may have entered from behind, across the trailing edge, or start
//! there), and the cone it needs is `c_Q(p, ·)` of that point, which is not monotone along `Q`
//! (it depends on the apex depth `S(p)`). The apexes in `[2J − 3/2, 2J − 1)` lie only in the
//! support of `2J − 1` and those in `(2J + 2, 2J + 5/2]` only in that of `2J + 2`, so both sides
//! of the ring stay: `tests/mip.rs` shows that dropping either the trailing or the leading ring
//! column lets rays of the layer cross the surface twice on some map, as does the group alone.

use alloc::vec;
use alloc::vec::Vec;

use crate::ReliefError;
use crate::cone::ConeMap;
use crate::map::Edge;
use crate::quad::QuadConeMap;

/// How a coarse texel combines the finer level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum MipRule {
    /// The 4×4 window (module documentation): valid under bilinear sampling.
    #[default]
    Window,
    /// The book's 2×2 group minimum: valid under nearest sampling only.
    Group,
}

/// One level down: `n/2` texels per side.
fn reduce(fine: &[f32], n: usize, edge: Edge, rule: MipRule) -> Vec<f32> {
    let h = n / 2;
    let (lo, hi) = match rule {
        MipRule::Window => (-1i64, 2i64),
        MipRule::Group => (0, 1),
    };
    let mut out = vec![0.0f32; h * h];
    for (k, o) in out.iter_mut().enumerate() {
        let (i, j) = ((k % h) as i64, (k / h) as i64);
        let mut m = f32::INFINITY;
        for dj in lo..=hi {
            for di in lo..=hi {
                let x = edge.resolve(2 * i + di, n);
                let y = edge.resolve(2 * j + dj, n);
                m = m.min(fine[y * n + x]);
            }
        }
        *o = m;
    }
    out
}

/// The chain from `cones` (level 0) down to 1×1, with `rule`.
///
/// # Errors
///
/// [`ReliefError::NotPowerOfTwo`] unless the side is a power of two (coarse texels then cover
/// whole groups at every level, as a GPU mip chain does).
pub fn chain(cones: &ConeMap, rule: MipRule) -> Result<Vec<ConeMap>, ReliefError> {
    let n = cones.size();
    if !n.is_power_of_two() {
        return Err(ReliefError::NotPowerOfTwo(n));
    }
    let mut levels = vec![cones.clone()];
    let mut size = n;
    while size > 1 {
        let last = &levels[levels.len() - 1];
        let edge = last.edge();
        let next = ConeMap::from_channels(
            size / 2,
            edge,
            reduce(last.ratios(), size, edge, rule),
            reduce(last.clearance(), size, edge, rule),
            reduce(last.near_cap(), size, edge, rule),
        )?;
        levels.push(next);
        size /= 2;
    }
    Ok(levels)
}

/// The chain of every layer of `cones` (level 0) down to 1×1, with `rule` applied layer by layer
/// (module documentation, "Quadrant layers"): entry `l` holds level `l` of the four layers in
/// [`crate::Quadrant::index`] order.
///
/// # Errors
///
/// [`ReliefError::NotPowerOfTwo`] unless the side is a power of two.
pub fn quad_chain(cones: &QuadConeMap, rule: MipRule) -> Result<Vec<QuadConeMap>, ReliefError> {
    let [a, b, c, d] = cones.layers();
    let levels = chain(a, rule)?
        .into_iter()
        .zip(chain(b, rule)?)
        .zip(chain(c, rule)?)
        .zip(chain(d, rule)?);
    levels
        .map(|(((a, b), c), d)| QuadConeMap::from_layers([a, b, c, d]))
        .collect()
}
