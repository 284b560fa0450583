//! View and projection matrices, validated and computed in `f64`.
//!
//! # Conventions
//!
//! - Units: metres and radians. World space is right-handed with **y up**.
//! - View space is right-handed: x right, y up, and the camera looks down **−z**. A point in front
//!   of the camera therefore has a negative view-space `z`; its *distance along the view axis* is
//!   `d = −z`.
//! - Matrices are glam's column-major [`DMat4`] / [`Mat4`] acting on column vectors:
//!   `clip = proj * view * world`. The memory layout is the same as GLM's, so
//!   `Mat4::to_cols_array()` can be handed to `glUniformMatrix4fv(…, GL_FALSE, …)` or a WGSL
//!   `mat4x4<f32>` as is.
//! - Clip space: x and y are in `[−w, w]`; NDC x grows to the right and NDC y grows **up** (the
//!   OpenGL / D3D / wgpu convention; Vulkan users who want y down flip it in the viewport or
//!   negate row 1 of the projection).
//! - Depth: [`DepthRange::ZeroToOne`] (wgpu, Vulkan, D3D, and OpenGL with
//!   `glClipControl(…, GL_ZERO_TO_ONE)`) keeps `0 ≤ z ≤ w`; [`DepthRange::NegOneToOne`] (default
//!   OpenGL, WebGL) keeps `−w ≤ z ≤ w`. With [`DepthDirection::Forward`] the near plane maps to the
//!   low end of the range (0 or −1) and the far plane to 1; with [`DepthDirection::Reversed`] the
//!   near plane maps to 1 and the far plane to 0.
//!
//! ## Why reversed Z is refused with `[−1, 1]`
//!
//! Reversed Z pays off only because floating-point numbers are dense near 0, where the distant
//! geometry lands. In a `[−1, 1]` range the distant geometry lands near −1, and the hardware's
//! window transform `(z + 1) / 2` throws the extra precision away; the result is a depth buffer no
//! better than forward Z that also needs the opposite depth test. Asking for that combination is
//! nearly always a forgotten `glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)`, so
//! [`DepthConvention::new`] rejects it with [`CameraError::ReversedNegOneToOne`].
//!
//! # Precision
//!
//! Everything is computed in `f64` ([`DMat4`]); the `f32` variants round the finished `f64`
//! matrix once, so an `f32` matrix is the correctly rounded version of the exact one (at most
//! half an ulp per element) rather than the result of a chain of `f32` operations. The `f32`
//! variants fail with [`CameraError::NotRepresentableInF32`] when an element overflows `f32`.
//!
//! # Equivalents in glam 0.34
//!
//! glam 0.34 moved its projection constructors from `Mat4` methods into modules; the equivalents
//! of this module's matrices are (f32 in `glam::camera`, f64 in `glam::dcamera`):
//!
//! | this module | glam 0.34 | glam ≤ 0.30 name |
//! |---|---|---|
//! | perspective, finite, forward, `[0,1]` | `camera::rh::proj::directx::perspective` | `Mat4::perspective_rh` |
//! | perspective, infinite, forward, `[0,1]` | `camera::rh::proj::directx::perspective_infinite` | `Mat4::perspective_infinite_rh` |
//! | perspective, infinite, reversed, `[0,1]` | `camera::rh::proj::directx::perspective_infinite_reverse` | `Mat4::perspective_infinite_reverse_rh` |
//! | perspective, finite, forward, `[−1,1]` | `camera::rh::proj::opengl::perspective` | `Mat4::perspective_rh_gl` |
//! | orthographic, forward, `[0,1]` | `camera::rh::proj::directx::orthographic` | `Mat4::orthographic_rh` |
//! | orthographic, forward, `[−1,1]` | `camera::rh::proj::opengl::orthographic` | `Mat4::orthographic_rh_gl` |
//! | view matrix | `camera::rh::view::look_at_mat4` | `Mat4::look_at_rh` |
//!
//! The other combinations (finite reversed Z, infinite `[−1,1]`, reversed orthographic) have no
//! glam equivalent and are checked in the tests against their defining depth mapping.

use crate::num::Num;
use glam::{DMat4, DVec3, DVec4, Mat4};

use crate::math::{cos, sin, sqrt};

/// Why a view or projection matrix could not be built, or a point could not be unprojected.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CameraError {
    /// A parameter is NaN or infinite.
    #[error("camera parameter `{name}` must be finite, got {}", Num(*.value))]
    NotFinite {
        /// Name of the parameter.
        name: &'static str,
        /// The offending value (for a vector, its first non-finite component).
        value: f64,
    },
    /// The eye and the target of a look-at view coincide, so there is no view direction.
    #[error("look-at eye and target coincide: there is no view direction")]
    EyeEqualsTarget,
    /// The up vector is zero or parallel to the view direction, so the camera's roll is undefined.
    #[error("up vector is zero or parallel to the view direction")]
    UpParallelToView,
    /// The vertical field of view must lie in the open interval (0, π) radians.
    #[error("vertical field of view must be in (0, pi) radians, got {}", Num(*.0))]
    FieldOfView(f64),
    /// The aspect ratio (width / height) must be > 0.
    #[error("aspect ratio must be > 0, got {}", Num(*.0))]
    Aspect(f64),
    /// A perspective near plane must be at a distance > 0 m.
    #[error("perspective near plane must be > 0 m, got {}", Num(*.0))]
    Near(f64),
    /// The far plane must lie beyond the near plane.
    #[error("far plane ({} m) must be beyond the near plane ({} m)", Num(*.far), Num(*.near))]
    FarNotBeyondNear {
        /// Near-plane distance (metres).
        near: f64,
        /// Far-plane distance (metres).
        far: f64,
    },
    /// An orthographic box needs `left < right`.
    #[error("orthographic box needs left < right, got left = {}, right = {}", Num(*.left), Num(*.right))]
    OrthoWidth {
        /// Left edge (view-space x, metres).
        left: f64,
        /// Right edge (view-space x, metres).
        right: f64,
    },
    /// An orthographic box needs `bottom < top`.
    #[error("orthographic box needs bottom < top, got bottom = {}, top = {}", Num(*.bottom), Num(*.top))]
    OrthoHeight {
        /// Bottom edge (view-space y, metres).
        bottom: f64,
        /// Top edge (view-space y, metres).
        top: f64,
    },
    /// Reversed Z needs the `[0, 1]` depth range (see the module documentation).
    #[error(
        "reversed Z needs the [0, 1] depth range; with OpenGL call glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)"
    )]
    ReversedNegOneToOne,
    /// The parameters are valid in `f64` but an element of the matrix overflows `f32`.
    #[error("the matrix has elements that overflow f32")]
    NotRepresentableInF32,
    /// The matrix cannot be inverted (it is singular or its inverse is not finite).
    #[error("the matrix is singular")]
    Singular,
    /// The clip-space point has `w = 0`: it lies at infinity (for example the far end of an
    /// infinite projection) and has no finite world position.
    #[error("the point lies at infinity (w = 0 after unprojection)")]
    AtInfinity,
    /// The view-space point is on the camera plane (`z = 0`), where perspective depth is undefined.
    #[error("perspective depth is undefined at view-space z = 0")]
    OnCameraPlane,
}

fn check(name: &'static str, value: f64) -> Result<f64, CameraError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(CameraError::NotFinite { name, value })
    }
}

fn check_vec(name: &'static str, v: DVec3) -> Result<DVec3, CameraError> {
    for value in v.to_array() {
        check(name, value)?;
    }
    Ok(v)
}

/// Depth range of normalised device coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthRange {
    /// `0 ≤ z_ndc ≤ 1` (clip `0 ≤ z ≤ w`): wgpu, WebGPU, Vulkan, Direct3D, Metal, and OpenGL with
    /// `glClipControl(…, GL_ZERO_TO_ONE)`.
    ZeroToOne,
    /// `−1 ≤ z_ndc ≤ 1` (clip `−w ≤ z ≤ w`): default OpenGL and WebGL.
    NegOneToOne,
}

impl DepthRange {
    /// The window depth in `[0, 1]` (what a depth buffer holds under WebGPU, Vulkan, Direct3D,
    /// Metal, and OpenGL's default `glDepthRange(0, 1)`) of an NDC depth in this range:
    /// `(z + 1)/2` for `[−1, 1]`, `z` for `[0, 1]`.
    pub fn window_depth(self, ndc_depth: f64) -> f64 {
        match self {
            Self::NegOneToOne => 0.5 * ndc_depth + 0.5,
            Self::ZeroToOne => ndc_depth,
        }
    }

    /// [`DepthRange::window_depth`] as a matrix acting on clip coordinates: multiplied on the
    /// left of a projection in this range, it gives the projection in WebGPU's `[0, 1]` range
    /// (the identity for [`DepthRange::ZeroToOne`]).
    pub fn to_zero_to_one(self) -> DMat4 {
        match self {
            Self::NegOneToOne => DMat4::from_cols(
                DVec4::X,
                DVec4::Y,
                DVec4::new(0.0, 0.0, 0.5, 0.0),
                DVec4::new(0.0, 0.0, 0.5, 1.0),
            ),
            Self::ZeroToOne => DMat4::IDENTITY,
        }
    }
}

/// Which end of the depth range the near plane maps to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthDirection {
    /// Near plane → low end (0 or −1), far plane → 1. Depth test `LESS`.
    Forward,
    /// Near plane → 1, far plane (or infinity) → 0. Depth test `GREATER`; clear depth to 0.
    /// Only valid with [`DepthRange::ZeroToOne`].
    Reversed,
}

/// A validated depth range and direction: the pair that decides where the near and far planes land
/// in NDC.
///
/// Built with [`DepthConvention::new`], which rejects reversed Z with the `[−1, 1]` range (see the
/// module documentation), or with one of the constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DepthConvention {
    range: DepthRange,
    direction: DepthDirection,
}

impl DepthConvention {
    /// `[0, 1]`, forward: wgpu / Vulkan / D3D default.
    pub const ZERO_TO_ONE: Self = Self {
        range: DepthRange::ZeroToOne,
        direction: DepthDirection::Forward,
    };
    /// `[0, 1]`, reversed: the precise choice for wgpu / Vulkan / D3D (near → 1, far → 0).
    pub const ZERO_TO_ONE_REVERSED: Self = Self {
        range: DepthRange::ZeroToOne,
        direction: DepthDirection::Reversed,
    };
    /// `[−1, 1]`, forward: default OpenGL / WebGL.
    pub const NEG_ONE_TO_ONE: Self = Self {
        range: DepthRange::NegOneToOne,
        direction: DepthDirection::Forward,
    };

    /// Every valid convention, for exhaustive tests.
    pub const ALL: [Self; 3] = [
        Self::ZERO_TO_ONE,
        Self::ZERO_TO_ONE_REVERSED,
        Self::NEG_ONE_TO_ONE,
    ];

    /// Validates a range and direction.
    ///
    /// # Errors
    ///
    /// [`CameraError::ReversedNegOneToOne`] for reversed Z with [`DepthRange::NegOneToOne`].
    pub const fn new(range: DepthRange, direction: DepthDirection) -> Result<Self, CameraError> {
        match (range, direction) {
            (DepthRange::NegOneToOne, DepthDirection::Reversed) => {
                Err(CameraError::ReversedNegOneToOne)
            }
            _ => Ok(Self { range, direction }),
        }
    }

    /// The NDC depth range.
    pub const fn range(self) -> DepthRange {
        self.range
    }

    /// The depth direction.
    pub const fn direction(self) -> DepthDirection {
        self.direction
    }

    /// NDC depth of the near plane: 0 (forward `[0,1]`), −1 (forward `[−1,1]`) or 1 (reversed).
    pub const fn near_ndc(self) -> f64 {
        match (self.range, self.direction) {
            (_, DepthDirection::Reversed) => 1.0,
            (DepthRange::ZeroToOne, DepthDirection::Forward) => 0.0,
            (DepthRange::NegOneToOne, DepthDirection::Forward) => -1.0,
        }
    }

    /// NDC depth of the far plane (the limit at infinity for an infinite far plane): 1 (forward)
    /// or 0 (reversed).
    pub const fn far_ndc(self) -> f64 {
        match self.direction {
            DepthDirection::Forward => 1.0,
            DepthDirection::Reversed => 0.0,
        }
    }

    /// NDC depth that the depth buffer should be cleared to (the far end): [`Self::far_ndc`].
    pub const fn clear_depth(self) -> f64 {
        self.far_ndc()
    }
}

/// The far plane of a perspective projection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Far {
    /// A far plane at this distance (metres, > near).
    Finite(f64),
    /// No far plane: depth approaches [`DepthConvention::far_ndc`] as distance → ∞.
    Infinite,
}

/// A projection, described by its parameters; [`Projection::matrix`] validates them and builds the
/// matrix for a [`DepthConvention`].
///
/// All distances are metres along the view direction (positive in front of the camera; view-space
/// `z = −distance`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Symmetric perspective frustum.
    Perspective {
        /// Vertical field of view (radians), in (0, π).
        fov_y: f64,
        /// Width / height of the viewport, > 0.
        aspect: f64,
        /// Near-plane distance (metres), > 0.
        near: f64,
        /// Far plane.
        far: Far,
    },
    /// Orthographic box in view space.
    Orthographic {
        /// View-space x of the left edge (metres), < `right`.
        left: f64,
        /// View-space x of the right edge (metres).
        right: f64,
        /// View-space y of the bottom edge (metres), < `top`.
        bottom: f64,
        /// View-space y of the top edge (metres).
        top: f64,
        /// Near-plane distance (metres); may be zero or negative (behind the camera), < `far`.
        near: f64,
        /// Far-plane distance (metres), finite.
        far: f64,
    },
}

impl Projection {
    /// Checks every parameter; the matrix builders call this first.
    ///
    /// # Errors
    ///
    /// [`CameraError::NotFinite`] for NaN or infinite parameters; [`CameraError::FieldOfView`],
    /// [`CameraError::Aspect`], [`CameraError::Near`] for a perspective near plane ≤ 0,
    /// [`CameraError::FarNotBeyondNear`], [`CameraError::OrthoWidth`], [`CameraError::OrthoHeight`].
    pub fn validate(&self) -> Result<(), CameraError> {
        match *self {
            Projection::Perspective {
                fov_y,
                aspect,
                near,
                far,
            } => {
                check("fov_y", fov_y)?;
                check("aspect", aspect)?;
                check("near", near)?;
                if !(fov_y > 0.0 && fov_y < core::f64::consts::PI) {
                    return Err(CameraError::FieldOfView(fov_y));
                }
                if aspect <= 0.0 {
                    return Err(CameraError::Aspect(aspect));
                }
                if near <= 0.0 {
                    return Err(CameraError::Near(near));
                }
                if let Far::Finite(far) = far {
                    check("far", far)?;
                    if far <= near {
                        return Err(CameraError::FarNotBeyondNear { near, far });
                    }
                }
            }
            Projection::Orthographic {
                left,
                right,
                bottom,
                top,
                near,
                far,
            } => {
                check("left", left)?;
                check("right", right)?;
                check("bottom", bottom)?;
                check("top", top)?;
                check("near", near)?;
                check("far", far)?;
                check("right - left", right - left)?;
                check("top - bottom", top - bottom)?;
                check("far - near", far - near)?;
                if left >= right {
                    return Err(CameraError::OrthoWidth { left, right });
                }
                if bottom >= top {
                    return Err(CameraError::OrthoHeight { bottom, top });
                }
                if far <= near {
                    return Err(CameraError::FarNotBeyondNear { near, far });
                }
            }
        }
        Ok(())
    }

    /// Near-plane distance (metres).
    pub fn near(&self) -> f64 {
        match *self {
            Projection::Perspective { near, .. } | Projection::Orthographic { near, .. } => near,
        }
    }

    /// Far plane.
    pub fn far(&self) -> Far {
        match *self {
            Projection::Perspective { far, .. } => far,
            Projection::Orthographic { far, .. } => Far::Finite(far),
        }
    }

    /// Coefficients `(A, B)` of the depth row: `z_clip = A·z_view + B·w_view`.
    ///
    /// Perspective (`w_clip = −z_view = d`): NDC depth is `α + β/d` with
    /// `β = (z_n − z_f)·n·f/(f − n)` and `α = (z_f·f − z_n·n)/(f − n)`, the unique such function
    /// taking `z_n` at `d = n` and `z_f` at `d = f`; so `A = −α`, `B = β`. With `f → ∞`:
    /// `α = z_f`, `β = (z_n − z_f)·n`.
    ///
    /// Orthographic (`w_clip = 1`): NDC depth is linear in `d`,
    /// `z_n + (z_f − z_n)(d − n)/(f − n)`.
    fn depth_row(&self, depth: DepthConvention) -> (f64, f64) {
        let zn = depth.near_ndc();
        let zf = depth.far_ndc();
        match *self {
            Projection::Perspective { near: n, far, .. } => match far {
                Far::Finite(f) => {
                    let inv = 1.0 / (f - n);
                    let alpha = (zf * f - zn * n) * inv;
                    let beta = (zn - zf) * n * f * inv;
                    (-alpha, beta)
                }
                Far::Infinite => (-zf, (zn - zf) * n),
            },
            Projection::Orthographic {
                near: n, far: f, ..
            } => {
                let scale = (zf - zn) / (f - n);
                (-scale, zn - scale * n)
            }
        }
    }

    /// The projection matrix in `f64`.
    ///
    /// Perspective: `x_clip = (cot(fov_y/2)/aspect)·x`, `y_clip = cot(fov_y/2)·y`,
    /// `w_clip = −z`, and the depth row puts the near plane at [`DepthConvention::near_ndc`] and
    /// the far plane (or infinity) at [`DepthConvention::far_ndc`].
    ///
    /// Orthographic: `[left, right] × [bottom, top]` → `[−1, 1]²`, `w_clip = 1`, depth linear.
    ///
    /// # Errors
    ///
    /// As [`Projection::validate`].
    pub fn matrix_f64(&self, depth: DepthConvention) -> Result<DMat4, CameraError> {
        self.validate()?;
        let (a, b) = self.depth_row(depth);
        let m = match *self {
            Projection::Perspective { fov_y, aspect, .. } => {
                let half = 0.5 * fov_y;
                let h = cos(half) / sin(half);
                DMat4::from_cols(
                    DVec4::new(h / aspect, 0.0, 0.0, 0.0),
                    DVec4::new(0.0, h, 0.0, 0.0),
                    DVec4::new(0.0, 0.0, a, -1.0),
                    DVec4::new(0.0, 0.0, b, 0.0),
                )
            }
            Projection::Orthographic {
                left,
                right,
                bottom,
                top,
                ..
            } => {
                let w_inv = 1.0 / (right - left);
                let h_inv = 1.0 / (top - bottom);
                DMat4::from_cols(
                    DVec4::new(2.0 * w_inv, 0.0, 0.0, 0.0),
                    DVec4::new(0.0, 2.0 * h_inv, 0.0, 0.0),
                    DVec4::new(0.0, 0.0, a, 0.0),
                    DVec4::new(-(right + left) * w_inv, -(top + bottom) * h_inv, b, 1.0),
                )
            }
        };
        if m.is_finite() {
            Ok(m)
        } else {
            // Only reachable for extreme but finite inputs (a field of view of 1e-320 rad).
            Err(CameraError::NotFinite {
                name: "projection matrix",
                value: f64::INFINITY,
            })
        }
    }

    /// The projection matrix rounded to `f32` (see [`Projection::matrix_f64`]).
    ///
    /// # Errors
    ///
    /// As [`Projection::validate`], or [`CameraError::NotRepresentableInF32`].
    pub fn matrix(&self, depth: DepthConvention) -> Result<Mat4, CameraError> {
        to_f32(self.matrix_f64(depth)?)
    }

    /// NDC depth of a point at view-space `z` (negative in front of the camera), computed from the
    /// closed form rather than through the matrix.
    ///
    /// For an infinite perspective, `view_z = −∞` gives the limit [`DepthConvention::far_ndc`].
    ///
    /// # Errors
    ///
    /// As [`Projection::validate`]; [`CameraError::NotFinite`] for a NaN `view_z` (or an infinite
    /// one outside the infinite-perspective case); [`CameraError::OnCameraPlane`] for
    /// `view_z = 0` in a perspective projection.
    pub fn ndc_depth(&self, depth: DepthConvention, view_z: f64) -> Result<f64, CameraError> {
        self.validate()?;
        let (a, b) = self.depth_row(depth);
        match self {
            Projection::Perspective { far, .. } => {
                if view_z.is_nan() {
                    return Err(CameraError::NotFinite {
                        name: "view_z",
                        value: view_z,
                    });
                }
                if view_z.is_infinite() {
                    return match far {
                        Far::Infinite => Ok(-a),
                        Far::Finite(_) => Err(CameraError::NotFinite {
                            name: "view_z",
                            value: view_z,
                        }),
                    };
                }
                if view_z == 0.0 {
                    return Err(CameraError::OnCameraPlane);
                }
                Ok((a * view_z + b) / -view_z)
            }
            Projection::Orthographic { .. } => Ok(a * check("view_z", view_z)? + b),
        }
    }

    /// View-space `z` (negative in front of the camera) of a point at NDC depth `ndc_z`: the
    /// inverse of [`Projection::ndc_depth`]. Useful to linearise a depth buffer.
    ///
    /// # Errors
    ///
    /// As [`Projection::validate`]; [`CameraError::NotFinite`] for a non-finite `ndc_z`;
    /// [`CameraError::AtInfinity`] for the far end of an infinite perspective.
    pub fn view_z(&self, depth: DepthConvention, ndc_z: f64) -> Result<f64, CameraError> {
        self.validate()?;
        check("ndc_z", ndc_z)?;
        let (a, b) = self.depth_row(depth);
        match self {
            // ndc = (a z + b) / (−z)  ⇒  z = −b / (ndc + a)
            Projection::Perspective { .. } => {
                let den = ndc_z + a;
                if den == 0.0 {
                    return Err(CameraError::AtInfinity);
                }
                Ok(-b / den)
            }
            Projection::Orthographic { .. } => Ok((ndc_z - b) / a),
        }
    }
}

fn to_f32(m: DMat4) -> Result<Mat4, CameraError> {
    let f = m.as_mat4();
    if f.is_finite() {
        Ok(f)
    } else {
        Err(CameraError::NotRepresentableInF32)
    }
}

/// Right-handed look-at view matrix in `f64`: the camera at `eye` looks at `target`, with `up`
/// giving the roll. In view space the camera looks down −z, x is to the right, y is up.
///
/// With `f = normalize(target − eye)`, `s = normalize(f × up)`, `u = s × f`, the rows of the
/// rotation are `s`, `u`, `−f` and the translation is `(−s·eye, −u·eye, f·eye)` (the classic
/// `gluLookAt`; the same as glam's `camera::rh::view::look_at_mat4` and GLM's `lookAtRH`).
///
/// # Errors
///
/// [`CameraError::NotFinite`]; [`CameraError::EyeEqualsTarget`];
/// [`CameraError::UpParallelToView`] when `up` is zero or the sine of the angle between `up` and
/// the view direction is below 1e-9.
pub fn look_at(eye: DVec3, target: DVec3, up: DVec3) -> Result<DMat4, CameraError> {
    check_vec("eye", eye)?;
    check_vec("target", target)?;
    check_vec("up", up)?;
    let dir = target - eye;
    check_vec("target - eye", dir)?;
    look_to(eye, dir, up)
}

/// Right-handed view matrix in `f64` from an eye position and a view direction (need not be
/// unit length); see [`look_at`].
///
/// # Errors
///
/// As [`look_at`] ([`CameraError::EyeEqualsTarget`] for a zero direction).
pub fn look_to(eye: DVec3, dir: DVec3, up: DVec3) -> Result<DMat4, CameraError> {
    check_vec("eye", eye)?;
    check_vec("dir", dir)?;
    check_vec("up", up)?;
    let f = unit(dir).ok_or(CameraError::EyeEqualsTarget)?;
    let up = unit(up).ok_or(CameraError::UpParallelToView)?;
    let s = f.cross(up);
    let s_len = sqrt(s.length_squared());
    if s_len < 1e-9 {
        return Err(CameraError::UpParallelToView);
    }
    let s = s / s_len;
    let u = s.cross(f);
    Ok(DMat4::from_cols(
        DVec4::new(s.x, u.x, -f.x, 0.0),
        DVec4::new(s.y, u.y, -f.y, 0.0),
        DVec4::new(s.z, u.z, -f.z, 0.0),
        DVec4::new(-eye.dot(s), -eye.dot(u), eye.dot(f), 1.0),
    ))
}

/// `v / |v|`, or `None` for a zero (or underflowing) vector. Scales first so huge vectors do not
/// overflow `|v|²`.
fn unit(v: DVec3) -> Option<DVec3> {
    let m = v.abs().max_element();
    if m == 0.0 || !m.is_finite() {
        return None;
    }
    let v = v / m;
    let len = sqrt(v.length_squared());
    Some(v / len)
}

/// A camera: a view matrix, a projection and a depth convention, with the combined matrices and
/// their inverse precomputed in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    view: DMat4,
    projection: Projection,
    depth: DepthConvention,
    proj: DMat4,
    view_proj: DMat4,
    inv_view_proj: DMat4,
    eye: DVec3,
}

impl Camera {
    /// Builds a camera from any view matrix (world → view space, right-handed, looking down −z).
    ///
    /// # Errors
    ///
    /// [`CameraError::NotFinite`] for a non-finite view matrix, the errors of
    /// [`Projection::validate`], and [`CameraError::Singular`] when `proj * view` cannot be inverted.
    pub fn new(
        view: DMat4,
        projection: Projection,
        depth: DepthConvention,
    ) -> Result<Self, CameraError> {
        if !view.is_finite() {
            return Err(CameraError::NotFinite {
                name: "view matrix",
                value: f64::NAN,
            });
        }
        let proj = projection.matrix_f64(depth)?;
        let view_proj = proj * view;
        let inv_view_proj = view_proj.try_inverse().ok_or(CameraError::Singular)?;
        // `new` accepts any invertible view, not only rigid ones, so use the general inverse.
        let eye = view
            .try_inverse()
            .ok_or(CameraError::Singular)?
            .w_axis
            .truncate();
        Ok(Self {
            view,
            projection,
            depth,
            proj,
            view_proj,
            inv_view_proj,
            eye,
        })
    }

    /// Builds a camera at `eye` looking at `target` (see [`look_at`]).
    ///
    /// # Errors
    ///
    /// As [`look_at`] and [`Camera::new`].
    pub fn look_at(
        eye: DVec3,
        target: DVec3,
        up: DVec3,
        projection: Projection,
        depth: DepthConvention,
    ) -> Result<Self, CameraError> {
        Self::new(look_at(eye, target, up)?, projection, depth)
    }

    /// The projection parameters.
    pub fn projection(&self) -> Projection {
        self.projection
    }

    /// The depth convention.
    pub fn depth(&self) -> DepthConvention {
        self.depth
    }

    /// World → view matrix.
    pub fn view_f64(&self) -> DMat4 {
        self.view
    }

    /// View → clip matrix.
    pub fn projection_f64(&self) -> DMat4 {
        self.proj
    }

    /// World → clip matrix, `proj * view`.
    pub fn view_projection_f64(&self) -> DMat4 {
        self.view_proj
    }

    /// Clip → world matrix, the inverse of [`Camera::view_projection_f64`].
    pub fn inverse_view_projection_f64(&self) -> DMat4 {
        self.inv_view_proj
    }

    /// World → view matrix in `f32`.
    ///
    /// For a camera far from the origin prefer subtracting the eye in `f64` before rounding
    /// (camera-relative rendering): `f32` keeps about 7 significant digits.
    ///
    /// # Errors
    ///
    /// [`CameraError::NotRepresentableInF32`].
    pub fn view(&self) -> Result<Mat4, CameraError> {
        to_f32(self.view)
    }

    /// View → clip matrix in `f32`.
    ///
    /// # Errors
    ///
    /// [`CameraError::NotRepresentableInF32`].
    pub fn projection_matrix(&self) -> Result<Mat4, CameraError> {
        to_f32(self.proj)
    }

    /// World → clip matrix in `f32`, rounded once from the `f64` product.
    ///
    /// # Errors
    ///
    /// [`CameraError::NotRepresentableInF32`].
    pub fn view_projection(&self) -> Result<Mat4, CameraError> {
        to_f32(self.view_proj)
    }

    /// Projects a world-space point to clip space (before the perspective divide).
    pub fn world_to_clip(&self, world: DVec3) -> DVec4 {
        self.view_proj * world.extend(1.0)
    }

    /// Projects a world-space point to NDC (after the divide by `w`). Returns `None` when the point
    /// is on or behind the camera plane (`w ≤ 0`), where the divide would mirror it.
    pub fn world_to_ndc(&self, world: DVec3) -> Option<DVec3> {
        let c = self.world_to_clip(world);
        if c.w > 0.0 && c.is_finite() {
            Some(c.truncate() / c.w)
        } else {
            None
        }
    }

    /// Unprojects an NDC point (x, y in [−1, 1], z in the depth range) to world space.
    ///
    /// # Errors
    ///
    /// [`CameraError::NotFinite`] for a non-finite input; [`CameraError::AtInfinity`] when the
    /// point has no finite preimage (the far end of an infinite perspective), which is decided as
    /// `|w| ≤ 1e-15 · max(|x|, |y|, |z|)` after the inverse transform.
    pub fn ndc_to_world(&self, ndc: DVec3) -> Result<DVec3, CameraError> {
        check_vec("ndc", ndc)?;
        let h = self.inv_view_proj * ndc.extend(1.0);
        // The preimage is at infinity when w vanishes relative to the spatial part.
        let scale = h.truncate().abs().max_element();
        if h.w == 0.0 || h.w.abs() <= scale * 1e-15 {
            return Err(CameraError::AtInfinity);
        }
        let p = h.truncate() / h.w;
        check_vec("unprojected point", p)
            .map_err(|_| CameraError::AtInfinity)
            .map(|_| p)
    }

    /// World-space position of the camera (the translation of the inverse view matrix).
    pub fn eye(&self) -> DVec3 {
        self.eye
    }
}
