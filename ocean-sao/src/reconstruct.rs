//! Camera-space z from depth (Eq. 2), position (Eq. 3), face normal (Eq. 4) and the
//! screen-space radius (Eq. 5).
//!
//! # Eq. 2 for every depth convention
//!
//! The paper writes the camera-space z (negative in front of the camera; ocean-core's view-space
//! z) of a depth-buffer value `d` as `z(d) = c₀ / (d·c₁ + c₂)`, with
//! `c = [z_n·z_f, z_n − z_f, z_f]` for a finite far plane and `c = [z_n, −1, +1]` for
//! `z_f = −∞`, where `z_n = −near` and `z_f = −far` are the planes' (negative) locations. Those
//! two triples are the forward `[0, 1]` case. Every perspective convention has such a triple,
//! derived here from the projection's parameters in `f64` and rounded once to `f32`:
//!
//! Let `d` map to NDC depth by `ndc = s·d + t` (`s = 1, t = 0` when the buffer holds NDC depth;
//! `s = 2, t = −1` for an OpenGL window depth in `[0, 1]` with a `[−1, 1]` NDC range), and let
//! `ζₙ`, `ζ_f` be the NDC depths of the near and far planes (ocean-core's
//! [`DepthConvention::near_ndc`] and [`DepthConvention::far_ndc`]). NDC depth is
//! `α + β/dist` with `α = (ζ_f·f − ζₙ·n)/(f − n)` and `β = (ζₙ − ζ_f)·n·f/(f − n)`, so
//!
//! ```text
//! finite far:    c₀ = (ζ_f − ζₙ)·n·f,  c₁ = s·(f − n),  c₂ = t·(f − n) + ζₙ·n − ζ_f·f
//! infinite far:  c₀ = (ζ_f − ζₙ)·n,    c₁ = s,          c₂ = t − ζ_f            (f → ∞)
//! ```
//!
//! all divided by `s` (exact: `s` is 1 or 2). The resulting triples:
//!
//! | convention | finite far `[c₀, c₁, c₂]` | infinite far |
//! |---|---|---|
//! | `[0,1]` forward (NDC = window) | `[n·f, f − n, −f]` (the paper's) | `[n, 1, −1]` (the paper's × −1) |
//! | `[0,1]` reversed | `[−n·f, f − n, n]` | `[−n, 1, 0]`: `z = −n/d` |
//! | `[−1,1]` forward, window depth `[0,1]` | `[n·f, f − n, −f]` (the paper's) | `[n, 1, −1]` |
//! | `[−1,1]` forward, NDC depth `[−1,1]` | `[2n·f, f − n, −(f + n)]` | `[2n, 1, −1]` |
//!
//! An orthographic camera maps depth *linearly* to z, which no `c₀/(d·c₁ + c₂)` can express, so
//! this crate evaluates the projective form with a fourth constant,
//!
//! ```text
//! z(d) = (c₀ + c₃·d) / (c₁·d + c₂)
//! ```
//!
//! with `c₃ = 0` for every perspective (exactly Eq. 2: `c₀ + 0·d = c₀` in floating point) and
//! `c₁ = 0` for orthographic, where `c₀ = −n·Δ − (t − ζₙ)·(f − n)`, `c₃ = −s·(f − n)`,
//! `c₂ = Δ = ζ_f − ζₙ` (again divided by `s`).
//!
//! The GPU twin evaluates exactly `(c.x + c.w * d) / (c.y * d + c.z)` in `f32` with
//! [`ZConstants::c`] as `c`.
//!
//! # Sky
//!
//! A depth equal to the far end of the range ([`ZConstants::far_depth`]: 1 forward, 0 reversed,
//! the value a depth buffer is cleared to) is background: its z is the finite sentinel
//! [`SKY_Z`] rather than `±∞` or a division by zero, because WGSL does not guarantee infinities
//! and the MIP filters must stay finite.

use glam::{DMat4, Vec3};
use ocean_core::{Camera, DepthConvention, DepthRange, Far, Projection};

use crate::viewport::Viewport;
use crate::{SaoError, for_rows};

/// Camera-space z stored for background (sky) pixels: 10⁹ m, farther than any scene and beyond
/// any radius, yet small enough that its square and the cross products of Eq. 4 stay finite in
/// `f32`. The GPU twin writes the same value.
pub const SKY_Z: f32 = -1.0e9;

/// What the depth values handed to the passes hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum DepthSource {
    /// The value a depth texture holds (window depth, `glDepthRange(0, 1)`): always in `[0, 1]`.
    /// For a `[−1, 1]` convention it is `(ndc + 1)/2`; for `[0, 1]` it equals NDC depth.
    #[default]
    Window,
    /// NDC depth itself, in the convention's range (`[−1, 1]` for OpenGL's default).
    Ndc,
}

impl DepthSource {
    /// `(s, t)` with `ndc = s·d + t`.
    fn affine(self, convention: DepthConvention) -> (f64, f64) {
        match (self, convention.range()) {
            (DepthSource::Window, DepthRange::NegOneToOne) => (2.0, -1.0),
            _ => (1.0, 0.0),
        }
    }
}

/// Eq. 2's constants for one projection, depth convention and depth source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ZConstants {
    /// `[c₀, c₁, c₂, c₃]` with `z(d) = (c₀ + c₃·d) / (c₁·d + c₂)` (see the module doc).
    pub c: [f32; 4],
    /// Stored depth of the near plane.
    pub near_depth: f32,
    /// Stored depth of the far plane (or of infinity): the clear value, read as sky.
    pub far_depth: f32,
    /// Perspective (`true`) or orthographic.
    pub perspective: bool,
}

impl ZConstants {
    /// The exact constants `[c₀, c₁, c₂, c₃]` in `f64` (see the module doc).
    ///
    /// # Errors
    ///
    /// The projection's validation errors ([`SaoError::Camera`]).
    pub fn exact(
        projection: &Projection,
        convention: DepthConvention,
        source: DepthSource,
    ) -> Result<[f64; 4], SaoError> {
        projection.validate()?;
        let (s, t) = source.affine(convention);
        let zn = convention.near_ndc();
        let zf = convention.far_ndc();
        let c = match *projection {
            Projection::Perspective { near: n, far, .. } => match far {
                Far::Finite(f) => [
                    (zf - zn) * n * f,
                    s * (f - n),
                    t * (f - n) + zn * n - zf * f,
                    0.0,
                ],
                Far::Infinite => [(zf - zn) * n, s, t - zf, 0.0],
            },
            Projection::Orthographic {
                near: n, far: f, ..
            } => {
                let delta = zf - zn;
                [-n * delta - (t - zn) * (f - n), 0.0, delta, -s * (f - n)]
            }
        };
        Ok(c.map(|ci| ci / s))
    }

    /// Rounds [`ZConstants::exact`] to `f32` and checks that the result can tell depths apart.
    ///
    /// # Errors
    ///
    /// [`SaoError::Camera`] for an invalid projection; [`SaoError::DegenerateProjection`] when a
    /// constant that must be non-zero rounds to zero or overflows, when z at the near plane is
    /// not finite (or not negative for a perspective), when z does not fall from the near plane
    /// to the middle of the range, or when Eq. 2's pole lies strictly inside the range.
    pub fn new(
        projection: &Projection,
        convention: DepthConvention,
        source: DepthSource,
    ) -> Result<Self, SaoError> {
        let exact = Self::exact(projection, convention, source)?;
        let c = exact.map(|ci| ci as f32);
        if c.iter().any(|ci| !ci.is_finite()) {
            return Err(SaoError::DegenerateProjection("Eq. 2 constants"));
        }
        let perspective = matches!(projection, Projection::Perspective { .. });
        let nonzero_ok = if perspective {
            c[0] != 0.0 && c[1] != 0.0
        } else {
            c[2] != 0.0 && c[3] != 0.0
        };
        if !nonzero_ok {
            return Err(SaoError::DegenerateProjection("Eq. 2 constants"));
        }
        let (s, t) = source.affine(convention);
        let near_depth = ((convention.near_ndc() - t) / s) as f32;
        let far_depth = ((convention.far_ndc() - t) / s) as f32;
        let out = Self {
            c,
            near_depth,
            far_depth,
            perspective,
        };
        let z_near = out.z_raw(near_depth);
        let z_mid = out.z_raw(0.5 * (near_depth + far_depth));
        let falls = z_mid < z_near;
        if !z_near.is_finite() || (perspective && z_near >= 0.0) || !falls {
            return Err(SaoError::DegenerateProjection("z at the near plane"));
        }
        if perspective {
            // The pole of Eq. 2 (after rounding) must not fall strictly inside the range: z
            // would change sign there. It sits exactly at the far end for an infinite far plane.
            let pole = -f64::from(c[2]) / f64::from(c[1]);
            let (lo, hi) = out.depth_range();
            if pole > f64::from(lo) && pole < f64::from(hi) {
                return Err(SaoError::DegenerateProjection(
                    "Eq. 2 pole inside the range",
                ));
            }
        }
        Ok(out)
    }

    /// [`ZConstants::new`] from a camera's projection and depth convention.
    ///
    /// # Errors
    ///
    /// As [`ZConstants::new`].
    pub fn from_camera(camera: &Camera, source: DepthSource) -> Result<Self, SaoError> {
        Self::new(&camera.projection(), camera.depth(), source)
    }

    /// The accepted depth range `(min, max)` (either order of near and far).
    pub fn depth_range(&self) -> (f32, f32) {
        (
            self.near_depth.min(self.far_depth),
            self.near_depth.max(self.far_depth),
        )
    }

    /// Whether `d` is the far end (background).
    #[inline]
    pub fn is_sky(&self, d: f32) -> bool {
        d == self.far_depth
    }

    /// Eq. 2 without the sky test: `(c₀ + c₃·d) / (c₁·d + c₂)` in `f32`.
    #[inline]
    pub fn z_raw(&self, d: f32) -> f32 {
        let [c0, c1, c2, c3] = self.c;
        (c0 + c3 * d) / (c1 * d + c2)
    }

    /// Eq. 2: camera-space z of a (valid) depth value; [`SKY_Z`] for the far end, and never
    /// below it (a depth within a few ulps of an infinite far plane would otherwise overflow to
    /// `−∞`: geometry beyond 10⁹ m is as unoccluding as the sky).
    #[inline]
    pub fn z(&self, d: f32) -> f32 {
        if self.is_sky(d) {
            SKY_Z
        } else {
            self.z_raw(d).max(SKY_Z)
        }
    }

    /// Checks a depth buffer as [`ZConstants::z_pass`] reads it: `viewport.input_len()` values,
    /// each finite and within [`ZConstants::depth_range`].
    ///
    /// # Errors
    ///
    /// [`SaoError::BufferSize`], [`SaoError::DepthNotFinite`], [`SaoError::DepthOutOfRange`]
    /// for the first offending pixel in row-major order.
    pub fn check_depth(&self, viewport: &Viewport, depth: &[f32]) -> Result<(), SaoError> {
        let w = viewport.input_width();
        let expected = viewport.input_len();
        if depth.len() != expected {
            return Err(SaoError::BufferSize {
                name: "depth",
                expected,
                got: depth.len(),
            });
        }
        let (min, max) = self.depth_range();
        for (i, &d) in depth.iter().enumerate() {
            if !d.is_finite() {
                return Err(SaoError::DepthNotFinite { x: i % w, y: i / w });
            }
            if d < min || d > max {
                return Err(SaoError::DepthOutOfRange {
                    x: i % w,
                    y: i / w,
                    value: d,
                    min,
                    max,
                });
            }
        }
        Ok(())
    }

    /// The z pass: Eq. 2 at every pixel of `depth` (row-major, `viewport`'s input size),
    /// checking every value first.
    ///
    /// # Errors
    ///
    /// [`SaoError::BufferSize`]; [`SaoError::DepthNotFinite`] and [`SaoError::DepthOutOfRange`]
    /// for the first offending pixel in row-major order.
    pub fn z_pass(
        &self,
        viewport: &Viewport,
        depth: &[f32],
    ) -> Result<alloc::vec::Vec<f32>, SaoError> {
        self.check_depth(viewport, depth)?;
        let w = viewport.input_width();
        let expected = viewport.input_len();
        let mut z = alloc::vec![0.0f32; expected];
        for_rows(&mut z, w, |j, row| {
            for (zi, &d) in row.iter_mut().zip(&depth[j * w..(j + 1) * w]) {
                *zi = self.z(d);
            }
        });
        Ok(z)
    }
}

/// Eq. 3 and Eq. 5's constants: camera-space position of a pixel from its z, and the pixel size
/// of a 1 m object.
///
/// For a pixel at input coordinates `(x', y')` (row 0 at the top) with `u = x' + ½`,
/// `v = y' + ½`:
///
/// ```text
/// C = ((scale.x·u + offset.x)·m, (scale.y·v + offset.y)·m, z),   m = z (perspective) or 1
/// ```
///
/// evaluated in `f32` in that order. With the projection matrix `P` (row, column) and the input
/// size `w × h`:
///
/// - perspective: `scale = (−2/(w·P₀₀), 2/(h·P₁₁))`, `offset = ((1 − P₀₂)/P₀₀, −(1 + P₁₂)/P₁₁)`;
/// - orthographic: `scale = (2/(w·P₀₀), −2/(h·P₁₁))`, `offset = (−(1 + P₀₃)/P₀₀, (1 − P₁₃)/P₁₁)`.
///
/// The x component is the paper's Eq. 3. Its printed y component,
/// `z·((1 + P₁₂)/P₁₁ − (−2(y' + ½))/(h·P₁₁))`, fails the identity that the centre pixel of a
/// symmetric projection lies on the view axis (it gives `2z/P₁₁`, not 0) in either row order;
/// the form above is the inverse of the projection for rows counted from the top, and the tests
/// check it by reprojecting.
///
/// Eq. 5: `S' = h·P₁₁/2` (pixels per metre at `z = −1` m for a perspective, pixels per metre
/// everywhere for an orthographic camera), so the screen radius of a ball of radius `r` is
/// `r' = r·S'/(−z)` (perspective) or `r·S'` (orthographic).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectionInfo {
    /// `(scale.x, scale.y)`.
    pub scale: [f32; 2],
    /// `(offset.x, offset.y)`.
    pub offset: [f32; 2],
    /// Perspective (`true`: multiply by z) or orthographic.
    pub perspective: bool,
    /// Eq. 5's `S'`.
    pub pixels_per_metre: f32,
}

impl ProjectionInfo {
    /// The constants for `projection` over an input image of `width × height` pixels, computed
    /// in `f64` from the projection matrix and rounded once to `f32`.
    ///
    /// # Errors
    ///
    /// [`SaoError::Camera`]; [`SaoError::DegenerateProjection`] when a constant is not finite or
    /// a scale rounds to zero.
    pub fn new(
        projection: &Projection,
        convention: DepthConvention,
        width: usize,
        height: usize,
    ) -> Result<Self, SaoError> {
        let p: DMat4 = projection.matrix_f64(convention)?;
        let (p00, p11) = (p.x_axis.x, p.y_axis.y);
        let (w, h) = (width as f64, height as f64);
        let perspective = matches!(projection, Projection::Perspective { .. });
        let (scale, offset) = if perspective {
            let (p02, p12) = (p.z_axis.x, p.z_axis.y);
            (
                [-2.0 / (w * p00), 2.0 / (h * p11)],
                [(1.0 - p02) / p00, -(1.0 + p12) / p11],
            )
        } else {
            let (p03, p13) = (p.w_axis.x, p.w_axis.y);
            (
                [2.0 / (w * p00), -2.0 / (h * p11)],
                [-(1.0 + p03) / p00, (1.0 - p13) / p11],
            )
        };
        let out = Self {
            scale: scale.map(|v| v as f32),
            offset: offset.map(|v| v as f32),
            perspective,
            pixels_per_metre: (0.5 * h * p11) as f32,
        };
        let finite = out.scale.iter().chain(&out.offset).all(|v| v.is_finite())
            && out.pixels_per_metre.is_finite();
        if !finite || out.scale.contains(&0.0) || out.pixels_per_metre <= 0.0 {
            return Err(SaoError::DegenerateProjection("Eq. 3 or Eq. 5 constants"));
        }
        Ok(out)
    }

    /// Eq. 3: camera-space position of input pixel `(x, y)` at camera-space depth `z`.
    #[inline]
    pub fn position(&self, x: i32, y: i32, z: f32) -> Vec3 {
        self.position_at(x as f32 + 0.5, y as f32 + 0.5, z)
    }

    /// Eq. 3 at the continuous input position `(u, v)` (pixel `(x', y')`'s centre is
    /// `(x' + ½, y' + ½)`).
    #[inline]
    pub fn position_at(&self, u: f32, v: f32, z: f32) -> Vec3 {
        let m = if self.perspective { z } else { 1.0 };
        Vec3::new(
            (self.scale[0] * u + self.offset[0]) * m,
            (self.scale[1] * v + self.offset[1]) * m,
            z,
        )
    }

    /// Eq. 5: screen-space radius in pixels of a ball of radius `radius_s = r·S'` (precomputed)
    /// at camera-space depth `z`, clamped to `[0, 2²⁴]` (any larger radius only places samples
    /// off the largest image, which are skipped anyway, and the clamp keeps `i32` conversions
    /// defined on the GPU).
    #[inline]
    pub fn screen_radius(&self, radius_s: f32, z: f32) -> f32 {
        let r = if self.perspective {
            radius_s / -z
        } else {
            radius_s
        };
        // A negative or NaN quotient (z ≥ 0 behind an orthographic camera) goes to 0.
        if r > 0.0 { r.min(16_777_216.0) } else { 0.0 }
    }
}

/// Result of Eq. 4 at one pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FaceNormal {
    /// The unit normal, facing the camera.
    Valid(Vec3),
    /// The cross product is zero or not finite (a pixel with no extent, e.g. all three pixels
    /// equal): no orientation.
    Undefined,
    /// Rejected by the depth-edge test ([`NormalRejection`]).
    Rejected,
}

/// How the sample pass reconstructs a pixel's face normal ([`face_normal`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum NormalEstimate {
    /// Eq. 4: differences within the pixel's 2×2 quad (the paper's `ddx`/`ddy`). A pixel on a
    /// silhouette whose quad partner lies on the background gets a normal spanning the depth
    /// edge, which draws a dotted dark line along the silhouette.
    Quad,
    /// Along each axis, the difference to whichever adjacent pixel is nearer in z: both sides
    /// agree on a plane, and at a depth edge the side on the pixel's own surface is taken.
    #[default]
    Nearest,
}

/// The option to reject unreliable reconstructed normals at depth edges.
///
/// The length of Eq. 4's cross product, `|∂C/∂y' × ∂C/∂x'|`, is the camera-space area of the
/// pixel's footprint. A surface whose normal makes an angle `γ` with the view ray at off-axis
/// angle `ψ` has footprint `|scale.x·scale.y|·m²·cos ψ / cos γ` (`m = z` for a perspective, 1
/// for orthographic), so the footprint measures how grazing the surface looks. Across a depth
/// edge the 2×2 difference spans two surfaces, the footprint is huge and the normal is
/// meaningless; the peer's fix (later G3D code) treats such pixels as unoccluded instead of
/// letting the wrong normal draw one-pixel dark lines.
///
/// A pixel is rejected when the footprint exceeds `|scale.x·scale.y|·m² / cos γ_max`: an
/// apparent incidence beyond `γ_max` (slightly earlier off-axis, by the factor `cos ψ`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalRejection {
    /// `γ_max` in radians, in `(0, π/2)`.
    pub max_incidence: f32,
}

/// Eq. 4: the face normal of output pixel `(x, y)` from screen-space differences of z.
///
/// With [`NormalEstimate::Quad`] (the paper) the partner along x is the quad partner `x ^ 1`
/// (output coordinates; a fine screen-space derivative), or `x − 1` when `x ^ 1` falls outside
/// the input image (only possible without guard band); likewise along y. With
/// [`NormalEstimate::Nearest`] it is whichever of the adjacent input pixels `x' ± 1` inside the
/// input has the smaller `|z − z_C|` (`x' + 1` on a tie); likewise along y. With `C(·)` from
/// Eq. 3 at input coordinates (output + guard) and `z` from level 0,
/// `∂C/∂x' = C(right) − C(left)`, `∂C/∂y' = C(lower row) − C(upper row)`, and the normal is
/// `normalize(∂C/∂y' × ∂C/∂x')`, which faces the camera for rows counted from the top.
///
/// `limit` is `1/cos γ_max` of the rejection (or `None`).
pub fn face_normal(
    info: &ProjectionInfo,
    viewport: &Viewport,
    z0: &[f32],
    x: usize,
    y: usize,
    estimate: NormalEstimate,
    limit: Option<f32>,
) -> FaceNormal {
    let g = viewport.guard();
    let (w, h) = (viewport.input_width(), viewport.input_height());
    let (xi, yi) = (x + g, y + g);
    let z_c = z0[yi * w + xi];
    let quad = |o: usize, len: usize| {
        let p = o ^ 1;
        (if p + g < len { p } else { o - 1 }) + g
    };
    // The adjacent pixel nearer in z along an axis; `zat(i)` is z at index `i` on that axis.
    let nearest = |i: usize, len: usize, zat: &dyn Fn(usize) -> f32| {
        if i + 1 >= len {
            return i - 1;
        }
        if i == 0 {
            return i + 1;
        }
        if (zat(i - 1) - z_c).abs() < (zat(i + 1) - z_c).abs() {
            i - 1
        } else {
            i + 1
        }
    };
    let (xp, yp) = match estimate {
        NormalEstimate::Quad => (quad(x, w), quad(y, h)),
        NormalEstimate::Nearest => (
            nearest(xi, w, &|i| z0[yi * w + i]),
            nearest(yi, h, &|j| z0[j * w + xi]),
        ),
    };
    let at = |xx: usize, yy: usize| info.position(xx as i32, yy as i32, z0[yy * w + xx]);
    let c = at(xi, yi);
    let cx = at(xp, yi);
    let cy = at(xi, yp);
    let dx = if xp > xi { cx - c } else { c - cx };
    let dy = if yp > yi { cy - c } else { c - cy };
    let n = dy.cross(dx);
    let len = ocean_core::math::sqrtf(n.dot(n));
    if len == 0.0 || !len.is_finite() {
        return FaceNormal::Undefined;
    }
    if let Some(limit) = limit {
        let m = if info.perspective { c.z } else { 1.0 };
        let footprint = (info.scale[0] * info.scale[1]).abs() * (m * m);
        if len > limit * footprint {
            return FaceNormal::Rejected;
        }
    }
    FaceNormal::Valid(n / len)
}
