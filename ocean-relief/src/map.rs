//! The height map: square, depth-convention, with a defined behaviour at its borders.
//!
//! ## Conventions
//!
//! - **Depth, not height.** The book stores *depth* (§18.2: "a depth map … scaled to the \[0,1\]
//!   range", black at the polygon): `0` at the polygon surface, `1` at the bottom of the relief.
//!   Inputs are heights (`1` = top) and are converted once, here: `depth = 1 − height`
//!   (in `f32`), or `(max − v)/max` for integer texels (the value a GPU reads from a unorm
//!   texture that stores `max − v`).
//! - **Texel centres.** Texel `(i, j)` is element `j·N + i` (row-major, row `j` along the
//!   texture's `v` axis) and its centre lies at texture coordinates `((i + ½)/N, (j + ½)/N)`.
//!   The surface the tracers see is the **bilinear interpolation** of the texel depths, exactly as
//!   a GPU's linear sampler reconstructs it ([`crate::sample`]).
//! - **Borders** ([`Edge`]): [`Edge::Wrap`] tiles the texture (addressing mode *repeat*);
//!   [`Edge::Clamp`] extends it by its border texels (*clamp-to-edge*): outside the square of
//!   texel centres the surface is constant along the outward axis. Cone maps, tracers and the
//!   ground truth all use the map's edge mode.
//! - **Range.** Heights must lie in `[0, 1]`; [`HeightRange::Normalize`] instead maps the
//!   smallest height to 0 and the largest to 1 (a constant map becomes a flat map at height 1,
//!   the polygon surface).

use alloc::vec::Vec;

use crate::ReliefError;

/// Largest side accepted, in texels (16.7 M texels). It keeps every texel coordinate exact in
/// `f32` with room to spare and bounds the memory of a cone-map generation: about 77 bytes a
/// texel (32 for the cells, 13 for the pyramid above them, 12 for the cells' cones, 12 for the
/// cone map, 4 for the heights, and the command's buffers), 1.29 GB at this size.
pub const MAX_SIDE: usize = 4096;

pub use crate::sample::Edge;

/// What to do with heights outside `[0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum HeightRange {
    /// Refuse them with [`ReliefError::HeightOutOfRange`].
    #[default]
    Refuse,
    /// Map `[min, max]` of the input affinely onto `[0, 1]` (a constant input becomes height 1).
    Normalize,
}

/// A square depth map with its edge mode (module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct HeightMap {
    size: usize,
    edge: Edge,
    depth: Vec<f32>,
}

/// Checks the dimensions shared by every constructor.
pub(crate) fn check_size(
    width: usize,
    height: usize,
    min: usize,
    max: usize,
) -> Result<usize, ReliefError> {
    if width < min || height < min || width > max || height > max {
        return Err(ReliefError::MapSize {
            width,
            height,
            min,
            max,
        });
    }
    if width != height {
        return Err(ReliefError::NotSquare { width, height });
    }
    Ok(width)
}

impl HeightMap {
    /// Smallest side: a bilinear cell needs two texel centres along each axis.
    pub const MIN_SIDE: usize = 2;

    /// A map from heights (`1` = the polygon surface, `0` = the bottom), row-major.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`] unless `2 ≤ width, height ≤ MAX_SIDE`;
    /// [`ReliefError::NotSquare`]; [`ReliefError::BufferSize`] unless `heights` holds
    /// `width·height` values; [`ReliefError::HeightNotFinite`]; with [`HeightRange::Refuse`],
    /// [`ReliefError::HeightOutOfRange`].
    pub fn from_heights(
        width: usize,
        height: usize,
        heights: &[f32],
        edge: Edge,
        range: HeightRange,
    ) -> Result<Self, ReliefError> {
        let n = check_size(width, height, Self::MIN_SIDE, MAX_SIDE)?;
        check_len("heights", n * n, heights.len())?;
        let mut lo = f32::INFINITY;
        let mut hi = f32::NEG_INFINITY;
        for (k, &h) in heights.iter().enumerate() {
            if !h.is_finite() {
                return Err(ReliefError::HeightNotFinite { x: k % n, y: k / n });
            }
            if range == HeightRange::Refuse && !(0.0..=1.0).contains(&h) {
                return Err(ReliefError::HeightOutOfRange {
                    x: k % n,
                    y: k / n,
                    value: h,
                });
            }
            lo = lo.min(h);
            hi = hi.max(h);
        }
        let depth = match range {
            HeightRange::Refuse => heights.iter().map(|&h| 1.0 - h).collect(),
            HeightRange::Normalize => {
                // In f64: the span of two finite f32 values never overflows there.
                let (lo, hi) = (f64::from(lo), f64::from(hi));
                let span = hi - lo;
                heights
                    .iter()
                    .map(|&h| {
                        if span > 0.0 {
                            // (hi − h)/span is the normalised depth; it lies in [0, 1].
                            ((hi - f64::from(h)) / span) as f32
                        } else {
                            0.0
                        }
                    })
                    .collect()
            }
        };
        Ok(Self {
            size: n,
            edge,
            depth,
        })
    }

    /// A map from depths in the book's convention (`0` = the polygon surface, `1` = the
    /// bottom). Same checks as [`HeightMap::from_heights`]; `Normalize` maps the smallest depth
    /// to 0 and the largest to 1.
    ///
    /// # Errors
    ///
    /// As [`HeightMap::from_heights`].
    pub fn from_depths(
        width: usize,
        height: usize,
        depths: &[f32],
        edge: Edge,
        range: HeightRange,
    ) -> Result<Self, ReliefError> {
        let n = check_size(width, height, Self::MIN_SIDE, MAX_SIDE)?;
        check_len("depths", n * n, depths.len())?;
        for (k, &d) in depths.iter().enumerate() {
            if !d.is_finite() {
                return Err(ReliefError::HeightNotFinite { x: k % n, y: k / n });
            }
            if range == HeightRange::Refuse && !(0.0..=1.0).contains(&d) {
                return Err(ReliefError::HeightOutOfRange {
                    x: k % n,
                    y: k / n,
                    value: 1.0 - d,
                });
            }
        }
        let depth = match range {
            HeightRange::Refuse => depths.to_vec(),
            HeightRange::Normalize => {
                let lo = depths
                    .iter()
                    .fold(f64::INFINITY, |a, &d| a.min(f64::from(d)));
                let hi = depths
                    .iter()
                    .fold(f64::NEG_INFINITY, |a, &d| a.max(f64::from(d)));
                let span = hi - lo;
                depths
                    .iter()
                    .map(|&d| {
                        if span > 0.0 {
                            ((f64::from(d) - lo) / span) as f32
                        } else {
                            0.0
                        }
                    })
                    .collect()
            }
        };
        Ok(Self {
            size: n,
            edge,
            depth,
        })
    }

    /// A map from 8-bit heights: height `v/255`, depth `(255 − v)/255`.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`], [`ReliefError::NotSquare`], [`ReliefError::BufferSize`].
    pub fn from_u8(
        width: usize,
        height: usize,
        heights: &[u8],
        edge: Edge,
    ) -> Result<Self, ReliefError> {
        let n = check_size(width, height, Self::MIN_SIDE, MAX_SIDE)?;
        check_len("heights", n * n, heights.len())?;
        let depth = heights
            .iter()
            .map(|&v| f32::from(255 - v) / 255.0)
            .collect();
        Ok(Self {
            size: n,
            edge,
            depth,
        })
    }

    /// A map from 16-bit heights: height `v/65535`, depth `(65535 − v)/65535`.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`], [`ReliefError::NotSquare`], [`ReliefError::BufferSize`].
    pub fn from_u16(
        width: usize,
        height: usize,
        heights: &[u16],
        edge: Edge,
    ) -> Result<Self, ReliefError> {
        let n = check_size(width, height, Self::MIN_SIDE, MAX_SIDE)?;
        check_len("heights", n * n, heights.len())?;
        let depth = heights
            .iter()
            .map(|&v| f32::from(65535 - v) / 65535.0)
            .collect();
        Ok(Self {
            size: n,
            edge,
            depth,
        })
    }

    /// Side `N` in texels.
    pub fn size(&self) -> usize {
        self.size
    }

    /// The edge mode.
    pub fn edge(&self) -> Edge {
        self.edge
    }

    /// The same depths with another edge mode.
    pub fn with_edge(mut self, edge: Edge) -> Self {
        self.edge = edge;
        self
    }

    /// Depths, row-major, in `[0, 1]`.
    pub fn depths(&self) -> &[f32] {
        &self.depth
    }

    /// Depth of texel `(i, j)`, any integers, resolved by the edge mode.
    #[inline(always)]
    pub fn depth(&self, i: i64, j: i64) -> f32 {
        let n = self.size;
        self.depth[self.edge.resolve(j, n) * n + self.edge.resolve(i, n)]
    }

    /// The bilinear surface at texture coordinates `(u, v)`, in the tracers' `f32` arithmetic
    /// ([`crate::sample`]).
    pub fn sample(&self, u: f32, v: f32) -> f32 {
        let t = crate::sample::Taps::new(self.size, self.edge, u, v);
        t.blend(|k| self.depth[k])
    }

    /// The bilinear surface at texel-centre coordinates `(x, y)` (texel `(i, j)`'s centre is
    /// `(i, j)`), in `f64`: the exact surface the ground truth and the validity check use.
    pub fn surface_f64(&self, x: f64, y: f64) -> f64 {
        let (x0, y0) = (libm::floor(x), libm::floor(y));
        let (fx, fy) = (x - x0, y - y0);
        let (i, j) = (x0 as i64, y0 as i64);
        let d = |a: i64, b: i64| f64::from(self.depth(a, b));
        let top = d(i, j) * (1.0 - fx) + d(i + 1, j) * fx;
        let bottom = d(i, j + 1) * (1.0 - fx) + d(i + 1, j + 1) * fx;
        top * (1.0 - fy) + bottom * fy
    }
}

pub(crate) fn check_len(
    name: &'static str,
    expected: usize,
    got: usize,
) -> Result<(), ReliefError> {
    if expected != got {
        return Err(ReliefError::BufferSize {
            name,
            expected,
            got,
        });
    }
    Ok(())
}
