//! The z MIP hierarchy (§2.2) and the five filters of Table 1.
//!
//! Level 0 is the camera-space z of every input pixel (Eq. 2). Level `m + 1` has
//! `max(1, w_m >> 1) × max(1, h_m >> 1)` texels (the sizes of a hardware MIP chain); texel
//! `(x', y')` of level `m + 1` is a filter of the 2×2 children `(2x' + i, 2y' + j)` of level `m`,
//! each child coordinate clamped to the level's last column or row (odd sizes).
//!
//! ## The origin
//!
//! The levels can be anchored at an **origin** `o` (the same on both axes): level 1's children
//! are then level-0 pixels `(o + 2x' + i, o + 2y' + j)`, and input pixel `x` lies in texel
//! `(x − o) >> m` of level `m ≥ 1` (clamped: the `o` pixels left of the origin share texel 0).
//! [`crate::Sao`] anchors the levels at the guard band modulo `2^M` (`M` the highest level
//! built), so every texel boundary of every level falls where it would with a guard band that
//! is a multiple of `2^M`: the output interior does not depend on the guard band's width.
//! Without it a guard band of 5 px instead of 0 or 32 moved every texel by 5 px against the
//! output and changed the interior by up to 67/255.
//!
//! Only levels up to `max_mip` are built: the sample pass never reads beyond it (Eq. 9 clamps).

use alloc::vec;
use alloc::vec::Vec;

use crate::{SaoError, for_rows};

/// A filter that makes level `m + 1` from level `m` (Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum MipFilter {
    /// Rotated grid subsampling, `z^m(2x' + ((y' & 1) ^ 1), 2y' + ((x' & 1) ^ 1))`: true scene
    /// values, no bias. The paper's choice. (Without the `^ 1`, as some implementations write it,
    /// the other diagonal of the same rotated grid is picked.)
    #[default]
    RotatedGrid,
    /// Arithmetic mean `¼ Σ z` (preserves screen-space area), evaluated as
    /// `(((z₀₀ + z₁₀) + z₀₁) + z₁₁)·0.25`.
    ArithmeticMean,
    /// Harmonic mean (preserves world-space area). Table 1 prints `[Σ 4/z]⁻¹`, which is a
    /// sixteenth of the harmonic mean and fails the identity `mean(z, z, z, z) = z`; this is the
    /// harmonic mean `4 / (1/z₀₀ + 1/z₁₀ + 1/z₀₁ + 1/z₁₁)`. It is defined for values of one sign:
    /// when a child is `≥ 0` (geometry behind an orthographic camera) the arithmetic mean is used.
    HarmonicMean,
    /// Minimum z (the farthest child): conservative visibility.
    Min,
    /// Maximum z (the nearest child): conservative occlusion.
    Max,
}

impl MipFilter {
    /// Every filter, in Table 1's order.
    pub const ALL: [Self; 5] = [
        Self::RotatedGrid,
        Self::ArithmeticMean,
        Self::HarmonicMean,
        Self::Min,
        Self::Max,
    ];

    /// Table 1's name.
    pub fn name(self) -> &'static str {
        match self {
            Self::RotatedGrid => "rotated grid",
            Self::ArithmeticMean => "arithmetic mean",
            Self::HarmonicMean => "harmonic mean",
            Self::Min => "min",
            Self::Max => "max",
        }
    }
}

/// Number of z levels [`ZHierarchy::build`] makes for a
/// `width × height` level 0 and `max_mip`: level 0 plus one per halving, stopping at `max_mip`
/// or at the first 1×1 level, i.e. `1 + min(max_mip, ⌊log₂ max(width, height)⌋)` (the length
/// of a full hardware MIP chain when `max_mip` does not cut it).
pub fn level_count(width: usize, height: usize, max_mip: u32) -> u32 {
    let side = width.max(height).max(1);
    let halvings = usize::BITS - 1 - side.leading_zeros();
    1 + max_mip.min(halvings)
}

/// One level of the hierarchy: camera-space z, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct ZLevel {
    width: usize,
    height: usize,
    z: Vec<f32>,
}

impl ZLevel {
    /// Width in texels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The z values, row-major.
    pub fn z(&self) -> &[f32] {
        &self.z
    }

    /// z at texel `(x, y)`, clamped to the level (`texelFetch` of a clamped coordinate).
    #[inline]
    pub fn fetch(&self, x: i32, y: i32) -> f32 {
        let xc = x.clamp(0, self.width as i32 - 1) as usize;
        let yc = y.clamp(0, self.height as i32 - 1) as usize;
        self.z[yc * self.width + xc]
    }

    /// The next level under `filter`.
    pub fn downsample(&self, filter: MipFilter) -> ZLevel {
        self.downsample_from(filter, 0)
    }

    /// The next level under `filter`, its children starting at `(origin, origin)`.
    fn downsample_from(&self, filter: MipFilter, origin: i32) -> ZLevel {
        let width = (self.width >> 1).max(1);
        let height = (self.height >> 1).max(1);
        let mut z = vec![0.0f32; width * height];
        for_rows(&mut z, width, |y, row| {
            for (x, out) in row.iter_mut().enumerate() {
                *out = self.filter_texel(filter, x as i32, y as i32, origin);
            }
        });
        ZLevel { width, height, z }
    }

    fn filter_texel(&self, filter: MipFilter, x: i32, y: i32, origin: i32) -> f32 {
        let (x2, y2) = (origin + 2 * x, origin + 2 * y);
        if filter == MipFilter::RotatedGrid {
            return self.fetch(x2 + ((y & 1) ^ 1), y2 + ((x & 1) ^ 1));
        }
        let a = self.fetch(x2, y2);
        let b = self.fetch(x2 + 1, y2);
        let c = self.fetch(x2, y2 + 1);
        let d = self.fetch(x2 + 1, y2 + 1);
        let mean = || (((a + b) + c) + d) * 0.25;
        match filter {
            MipFilter::RotatedGrid => unreachable!("handled above"),
            MipFilter::ArithmeticMean => mean(),
            MipFilter::HarmonicMean => {
                if a < 0.0 && b < 0.0 && c < 0.0 && d < 0.0 {
                    4.0 / (((1.0 / a + 1.0 / b) + 1.0 / c) + 1.0 / d)
                } else {
                    mean()
                }
            }
            MipFilter::Min => a.min(b).min(c).min(d),
            MipFilter::Max => a.max(b).max(c).max(d),
        }
    }
}

/// The z hierarchy: level 0 and the MIP levels built from it.
#[derive(Clone, Debug, PartialEq)]
pub struct ZHierarchy {
    levels: Vec<ZLevel>,
    filter: MipFilter,
    origin: i32,
}

impl ZHierarchy {
    /// Builds levels `0 ..= max_mip` (fewer when a level reaches 1×1) from level 0 `z0` of
    /// `width × height` texels.
    ///
    /// # Errors
    ///
    /// [`SaoError::BufferSize`] when `z0` does not hold `width·height` values;
    /// [`SaoError::ImageSize`] for a zero side.
    pub fn build(
        z0: Vec<f32>,
        width: usize,
        height: usize,
        filter: MipFilter,
        max_mip: u32,
    ) -> Result<Self, SaoError> {
        Self::build_anchored(z0, width, height, filter, max_mip, 0)
    }

    /// [`ZHierarchy::build`] with the levels anchored at `origin` (see the module docs); an
    /// origin outside level 0 is taken modulo its smaller side.
    ///
    /// # Errors
    ///
    /// As [`ZHierarchy::build`].
    pub fn build_anchored(
        z0: Vec<f32>,
        width: usize,
        height: usize,
        filter: MipFilter,
        max_mip: u32,
        origin: usize,
    ) -> Result<Self, SaoError> {
        if width == 0 || height == 0 {
            return Err(SaoError::ImageSize { width, height });
        }
        let expected = width * height;
        if z0.len() != expected {
            return Err(SaoError::BufferSize {
                name: "z level 0",
                expected,
                got: z0.len(),
            });
        }
        let mut levels = vec![ZLevel {
            width,
            height,
            z: z0,
        }];
        let origin = (origin % width.min(height)) as i32;
        for m in 0..max_mip {
            let last = &levels[levels.len() - 1];
            if last.width == 1 && last.height == 1 {
                break;
            }
            let next = last.downsample_from(filter, if m == 0 { origin } else { 0 });
            levels.push(next);
        }
        Ok(Self {
            levels,
            filter,
            origin,
        })
    }

    /// The level-0 pixel at which level 1's texel 0 starts (see the module docs).
    pub fn origin(&self) -> usize {
        self.origin as usize
    }

    /// The texel of level `m` that input coordinate `x` lies in (unclamped).
    #[inline]
    fn texel_of(&self, m: u32, x: i32) -> i32 {
        if m == 0 { x } else { (x - self.origin) >> m }
    }

    /// The levels, level 0 first.
    pub fn levels(&self) -> &[ZLevel] {
        &self.levels
    }

    /// Level 0 (full resolution).
    pub fn base(&self) -> &ZLevel {
        &self.levels[0]
    }

    /// The filter the levels were built with.
    pub fn filter(&self) -> MipFilter {
        self.filter
    }

    /// Highest level index built.
    pub fn max_level(&self) -> u32 {
        (self.levels.len() - 1) as u32
    }

    /// Eq. 10: z at full-resolution input pixel `(x, y)` read from level `m` (clamped to the
    /// levels built): texel `((x − o) >> m, (y − o) >> m)` for `m ≥ 1` (an arithmetic shift;
    /// `o` the origin), clamped to the level.
    #[inline]
    pub fn fetch(&self, m: u32, x: i32, y: i32) -> f32 {
        let m = m.min(self.max_level());
        self.levels[m as usize].fetch(self.texel_of(m, x), self.texel_of(m, y))
    }

    /// Eq. 10 with the screen position the value stands for: z of the texel of level `m` that
    /// [`ZHierarchy::fetch`] reads and the continuous input position
    /// `(u, v)` (pixel `(x', y')`'s centre is `(x' + ½, y' + ½)`) at which Eq. 3 must
    /// reconstruct it.
    ///
    /// The paper only says "we apply eqn. 3 to reconstruct each Q_i from z_i"; its released
    /// shader reconstructs at the tap's own pixel. But a level-`m` value comes from up to
    /// `2^m − 1` pixels away, and pairing it with the tap's pixel puts `Q_i` off the surface
    /// (on a floor seen at a grazing angle, by centimetres): a flat open plane then occludes
    /// itself, against the rotated grid's promise of "true scene values, no bias". So `Q_i` is
    /// reconstructed where its value comes from:
    ///
    /// - rotated grid: the level-0 pixel the texel was copied from, found by descending
    ///   `(x, y) ← clamp((2x + ((y & 1) ^ 1), 2y + ((x & 1) ^ 1)) + o_l, 0, size_(l−1) − 1)`
    ///   from level `m` to level 1, with `o_l` the origin when descending to level 0 and 0
    ///   above. `Q_i` is then exactly a depth-buffer point;
    /// - the other filters: the centre of the texel's footprint,
    ///   `(o + t_x·2^m + 2^m·½, o + t_y·2^m + 2^m·½)` (for `m = 0`, the pixel centre).
    #[inline]
    pub fn sample(&self, m: u32, x: i32, y: i32) -> (f32, f32, f32) {
        let m = m.min(self.max_level());
        let level = &self.levels[m as usize];
        let tx = self.texel_of(m, x).clamp(0, level.width as i32 - 1);
        let ty = self.texel_of(m, y).clamp(0, level.height as i32 - 1);
        let z = level.z[ty as usize * level.width + tx as usize];
        if self.filter == MipFilter::RotatedGrid {
            let (mut sx, mut sy) = (tx, ty);
            for l in (0..m as usize).rev() {
                let below = &self.levels[l];
                let o = if l == 0 { self.origin } else { 0 };
                let cx = (o + 2 * sx + ((sy & 1) ^ 1)).min(below.width as i32 - 1);
                let cy = (o + 2 * sy + ((sx & 1) ^ 1)).min(below.height as i32 - 1);
                (sx, sy) = (cx, cy);
            }
            (z, sx as f32 + 0.5, sy as f32 + 0.5)
        } else {
            let size = (1i32 << m) as f32;
            let o = if m == 0 { 0 } else { self.origin };
            (
                z,
                (o + (tx << m)) as f32 + size * 0.5,
                (o + (ty << m)) as f32 + size * 0.5,
            )
        }
    }
}
