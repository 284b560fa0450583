//! The input image, its guard band and the output rectangle.
//!
//! The depth buffer is larger than the screen (paper §2: "the input depth buffer is larger than
//! the screen so that objects in a guard band slightly outside the frame can create
//! obscurance"). The projection describes the **whole input image**, guard band included, so
//! Eq. 3 uses the input's `w × h`; the output is the input inset by `guard` pixels on every side.
//!
//! Two kinds of integer pixel coordinates appear in the passes:
//!
//! - **input** coordinates `(x', y')`, `0 ≤ x' < input_width`, row 0 at the **top** (the layout
//!   of wgpu / Vulkan / D3D textures and of image files; OpenGL's `glReadPixels` returns rows
//!   bottom-up and must be flipped): depth, the z hierarchy, Eq. 3 and the sample positions of
//!   Eq. 10;
//! - **output** coordinates `(x, y) = (x' − guard, y' − guard)`: the AO images, the hash of
//!   Eq. 8, the 2×2 quads of Eq. 4 and of the quad bilateral (a compute shader over the output
//!   texture sees these), and the blur.

use crate::SaoError;

/// Largest image side accepted, in pixels. It bounds Eq. 8's hash below 2³² (so `u32`
/// arithmetic never wraps), keeps pixel coordinates exact in `f32` and is WebGPU's
/// `maxTextureDimension2D` on most hardware.
pub const MAX_SIDE: usize = 16_384;

/// Input size and guard band, validated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Viewport {
    input_width: usize,
    input_height: usize,
    guard: usize,
}

impl Viewport {
    /// An input image of `input_width × input_height` pixels (the depth buffer) with a guard
    /// band of `guard` pixels on every side.
    ///
    /// # Errors
    ///
    /// [`SaoError::ImageSize`] when a side is outside `2 ..= MAX_SIDE` (2 because Eq. 4 needs a
    /// neighbour along each axis); [`SaoError::GuardBand`] when `2·guard` is not below both
    /// sides (no output pixel would remain).
    pub fn new(input_width: usize, input_height: usize, guard: usize) -> Result<Self, SaoError> {
        let side = 2..=MAX_SIDE;
        if !side.contains(&input_width) || !side.contains(&input_height) {
            return Err(SaoError::ImageSize {
                width: input_width,
                height: input_height,
            });
        }
        let leaves_output = guard
            .checked_mul(2)
            .is_some_and(|g2| g2 < input_width && g2 < input_height);
        if !leaves_output {
            return Err(SaoError::GuardBand {
                guard,
                width: input_width,
                height: input_height,
            });
        }
        Ok(Self {
            input_width,
            input_height,
            guard,
        })
    }

    /// Input (depth buffer) width.
    pub fn input_width(&self) -> usize {
        self.input_width
    }

    /// Input (depth buffer) height.
    pub fn input_height(&self) -> usize {
        self.input_height
    }

    /// Guard band width on every side.
    pub fn guard(&self) -> usize {
        self.guard
    }

    /// Output width: `input_width − 2·guard`.
    pub fn output_width(&self) -> usize {
        self.input_width - 2 * self.guard
    }

    /// Output height: `input_height − 2·guard`.
    pub fn output_height(&self) -> usize {
        self.input_height - 2 * self.guard
    }

    /// Number of input pixels.
    pub fn input_len(&self) -> usize {
        self.input_width * self.input_height
    }

    /// Number of output pixels.
    pub fn output_len(&self) -> usize {
        self.output_width() * self.output_height()
    }
}
