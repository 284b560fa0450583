//! View frusta as six planes, and conservative visibility tests for points, spheres, axis-aligned
//! boxes and oriented boxes.
//!
//! # Planes from a matrix (Gribb & Hartmann 2001)
//!
//! G. Gribb, K. Hartmann, *Fast Extraction of Viewing Frustum Planes from the World-View-Projection
//! Matrix* (2001). For clip coordinates `c = M·p` (glam column-major storage, column vectors, so
//! `c_i = M.row(i) · p`), a point is inside the clip volume when
//!
//! - `−w ≤ x ≤ w`: left plane `row3 + row0`, right plane `row3 − row0`;
//! - `−w ≤ y ≤ w`: bottom plane `row3 + row1`, top plane `row3 − row1`;
//! - depth, [`DepthRange::ZeroToOne`] (`0 ≤ z ≤ w`): low plane `row2`, high plane `row3 − row2`;
//! - depth, [`DepthRange::NegOneToOne`] (`−w ≤ z ≤ w`): low plane `row3 + row2`, high plane
//!   `row3 − row2`.
//!
//! With [`DepthDirection::Forward`] the low plane is the near plane and the high plane the far
//! plane; with [`DepthDirection::Reversed`] they swap (near → 1, far → 0).
//!
//! The far plane `row3 − row2` is a difference of two nearly equal rows (their normals differ by
//! about `near/(far − near)`), so it inherits the matrix's rounding amplified by about
//! `far/near`: extract planes from the `f64` matrix ([`Frustum::from_camera`]) where possible;
//! from an `f32` matrix with far/near = 1000 the far-plane normal is good to about 1e-4.
//!
//! Each plane `(a, b, c, d)` is divided by `|(a, b, c)|`, so `n·p + d` is the signed distance in
//! metres (for a rigid view matrix) and is **≥ 0 inside**. If `M` is a projection alone the planes
//! are in view space; if it is `proj * view` they are in world space.
//!
//! # Infinite far planes
//!
//! For an infinite perspective the far plane degenerates to `(0, 0, 0, d)` with `d > 0`: every
//! finite point satisfies it. A plane whose normal length is at most `1e-12·|d|` and whose `d > 0`
//! is therefore dropped (it would lie more than 10¹² m away); [`Frustum::has_far_plane`] then
//! returns `false` and the tests use five planes. The same happens to a finite far plane that
//! rounding has already made infinite (an `f32` matrix with far/near above about 10⁷). A
//! degenerate plane with `d ≤ 0` (nothing inside) or a degenerate side or near plane means the
//! matrix is not a projection: [`FrustumError::Degenerate`].
//!
//! # Conservative tests
//!
//! Every shape is tested against each plane with an effective radius `r`: the shape is
//! [`Containment::Outside`] when it lies entirely on the outer side of **one** plane
//! (`n·c + d < −r`), [`Containment::Inside`] when it lies entirely on the inner side of **all**
//! planes (`n·c + d ≥ r` for each), and [`Containment::Intersecting`] otherwise. Radii:
//!
//! - sphere: its radius;
//! - axis-aligned box with half extents `e`: `r = e_x|n_x| + e_y|n_y| + e_z|n_z|`, the distance from
//!   the centre to the box's "p-vertex" along `n` (Akenine-Möller, Haines & Hoffman,
//!   *Real-Time Rendering*, 4th ed., chapter 22, "Plane/Box Intersection");
//! - oriented box with orthonormal axes `aᵢ` and half extents `hᵢ`: `r = Σ hᵢ |aᵢ·n|` (same
//!   section, and "View Frustum Intersection" in the same chapter).
//!
//! The results are **conservative**: `Outside` is only returned when a separating plane exists, so
//! a shape that touches the frustum is never reported `Outside`. The converse does not hold: a
//! shape outside the frustum near one of its edges or corners (outside two planes at once but
//! entirely outside neither) is reported `Intersecting`. `Inside` is exact up to rounding: every
//! point of the shape is inside the frustum.

use crate::num::Num;
use glam::{DMat4, DQuat, DVec3, DVec4, Mat4};

use crate::camera::{Camera, DepthConvention, DepthDirection, DepthRange};
use crate::math::sqrt;

/// Result of a visibility test.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Containment {
    /// Entirely outside one frustum plane: certainly invisible.
    Outside,
    /// Crosses at least one plane, or could not be proven inside or outside (near edges and
    /// corners): possibly visible.
    Intersecting,
    /// Entirely inside every plane: certainly inside the frustum.
    Inside,
}

/// Identifies one of the six planes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PlaneId {
    /// `x = −w` in clip space.
    Left,
    /// `x = w`.
    Right,
    /// `y = −w`.
    Bottom,
    /// `y = w`.
    Top,
    /// The near plane (low depth end for forward Z, high end for reversed Z).
    Near,
    /// The far plane (absent for an infinite perspective).
    Far,
}

impl PlaneId {
    /// All six, in storage order.
    pub const ALL: [PlaneId; 6] = [
        PlaneId::Left,
        PlaneId::Right,
        PlaneId::Bottom,
        PlaneId::Top,
        PlaneId::Near,
        PlaneId::Far,
    ];
}

/// Why a frustum or a shape could not be built, or a point could not be tested.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FrustumError {
    /// An input is NaN or infinite.
    #[error("`{0}` must be finite")]
    NotFinite(&'static str),
    /// A plane extracted from the matrix has no usable normal (the matrix is not a projection).
    #[error("the {0:?} plane of the matrix is degenerate")]
    Degenerate(PlaneId),
    /// A radius or half extent is negative.
    #[error("`{name}` must be >= 0, got {}", Num(*.value))]
    Negative {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// An AABB's minimum corner exceeds its maximum corner on some axis.
    #[error("aabb min corner exceeds max corner")]
    MinAboveMax,
    /// OBB axes must be unit length and mutually orthogonal (within 1e-6).
    #[error("obb axes must be orthonormal (within 1e-6)")]
    AxesNotOrthonormal,
    /// A rotation quaternion is zero.
    #[error("rotation quaternion is zero")]
    ZeroRotation,
}

fn finite3(name: &'static str, v: DVec3) -> Result<DVec3, FrustumError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(FrustumError::NotFinite(name))
    }
}

fn non_negative3(name: &'static str, v: DVec3) -> Result<DVec3, FrustumError> {
    finite3(name, v)?;
    for value in v.to_array() {
        if value < 0.0 {
            return Err(FrustumError::Negative { name, value });
        }
    }
    Ok(v)
}

/// A plane `normal · p + d = 0` with a unit normal pointing into the frustum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Unit normal, pointing to the inside.
    pub normal: DVec3,
    /// Offset: `normal · p + d` is the signed distance of `p`, ≥ 0 inside.
    pub d: f64,
}

impl Plane {
    /// Signed distance of `p` from the plane (positive inside).
    #[inline]
    pub fn signed_distance(&self, p: DVec3) -> f64 {
        self.normal.dot(p) + self.d
    }

    /// The plane as `(nx, ny, nz, d)`.
    pub fn to_vec4(self) -> DVec4 {
        self.normal.extend(self.d)
    }
}

/// A sphere (centre, radius ≥ 0, metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    centre: DVec3,
    radius: f64,
}

impl Sphere {
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`], [`FrustumError::Negative`] for a negative radius.
    pub fn new(centre: DVec3, radius: f64) -> Result<Self, FrustumError> {
        finite3("centre", centre)?;
        if !radius.is_finite() {
            return Err(FrustumError::NotFinite("radius"));
        }
        if radius < 0.0 {
            return Err(FrustumError::Negative {
                name: "radius",
                value: radius,
            });
        }
        Ok(Self { centre, radius })
    }

    /// Centre.
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    /// Radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// An axis-aligned box given by its centre and half extents (≥ 0, metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    centre: DVec3,
    half_extents: DVec3,
}

impl Aabb {
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`], [`FrustumError::Negative`] for a negative half extent.
    pub fn new(centre: DVec3, half_extents: DVec3) -> Result<Self, FrustumError> {
        finite3("centre", centre)?;
        non_negative3("half_extents", half_extents)?;
        Ok(Self {
            centre,
            half_extents,
        })
    }

    /// From the minimum and maximum corners.
    ///
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`] (also when the size overflows), [`FrustumError::MinAboveMax`].
    pub fn from_min_max(min: DVec3, max: DVec3) -> Result<Self, FrustumError> {
        finite3("min", min)?;
        finite3("max", max)?;
        if min.cmpgt(max).any() {
            return Err(FrustumError::MinAboveMax);
        }
        let half = finite3("max - min", max - min)? * 0.5;
        Self::new(min + half, half)
    }

    /// Centre.
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    /// Half extents.
    pub fn half_extents(&self) -> DVec3 {
        self.half_extents
    }
}

/// An oriented box: centre, three orthonormal axes and a half extent along each (metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Obb {
    centre: DVec3,
    axes: [DVec3; 3],
    half_extents: DVec3,
}

impl Obb {
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`], [`FrustumError::Negative`],
    /// [`FrustumError::AxesNotOrthonormal`] when an axis length differs from 1, or a pairwise dot
    /// product from 0, by more than 1e-6.
    pub fn new(centre: DVec3, axes: [DVec3; 3], half_extents: DVec3) -> Result<Self, FrustumError> {
        finite3("centre", centre)?;
        for a in axes {
            finite3("axes", a)?;
        }
        non_negative3("half_extents", half_extents)?;
        const TOL: f64 = 1e-6;
        for i in 0..3 {
            if (axes[i].length_squared() - 1.0).abs() > TOL {
                return Err(FrustumError::AxesNotOrthonormal);
            }
            if axes[i].dot(axes[(i + 1) % 3]).abs() > TOL {
                return Err(FrustumError::AxesNotOrthonormal);
            }
        }
        Ok(Self {
            centre,
            axes,
            half_extents,
        })
    }

    /// A box rotated by `rotation` (normalised here) about its centre: its axes are the rotated
    /// x, y and z axes.
    ///
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`], [`FrustumError::ZeroRotation`], [`FrustumError::Negative`].
    pub fn from_rotation(
        centre: DVec3,
        rotation: DQuat,
        half_extents: DVec3,
    ) -> Result<Self, FrustumError> {
        if !rotation.is_finite() {
            return Err(FrustumError::NotFinite("rotation"));
        }
        let len = sqrt(rotation.length_squared());
        if len == 0.0 || !len.is_finite() {
            return Err(FrustumError::ZeroRotation);
        }
        let q = rotation / len;
        Self::new(
            centre,
            [q * DVec3::X, q * DVec3::Y, q * DVec3::Z],
            half_extents,
        )
    }

    /// An axis-aligned box seen as an oriented one.
    pub fn from_aabb(aabb: &Aabb) -> Self {
        Self {
            centre: aabb.centre,
            axes: [DVec3::X, DVec3::Y, DVec3::Z],
            half_extents: aabb.half_extents,
        }
    }

    /// Centre.
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    /// Orthonormal axes.
    pub fn axes(&self) -> [DVec3; 3] {
        self.axes
    }

    /// Half extents along the axes.
    pub fn half_extents(&self) -> DVec3 {
        self.half_extents
    }

    /// The point `centre + Σ tᵢ hᵢ aᵢ` for local coordinates `t ∈ [−1, 1]³`.
    pub fn point(&self, t: DVec3) -> DVec3 {
        self.centre
            + self.axes[0] * (t.x * self.half_extents.x)
            + self.axes[1] * (t.y * self.half_extents.y)
            + self.axes[2] * (t.z * self.half_extents.z)
    }
}

/// A view frustum: five or six inward-facing unit planes (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    /// Planes in [`PlaneId::ALL`] order; only the first `len` are used (the far plane is last and
    /// is left out when infinite).
    planes: [Plane; 6],
    len: usize,
}

impl Frustum {
    /// Extracts the planes of a view-projection matrix (Gribb & Hartmann 2001).
    ///
    /// `depth` must be the convention the matrix was built for: it decides which rows bound the
    /// depth and which of them is the near plane.
    ///
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`] for a non-finite matrix, [`FrustumError::Degenerate`] for a
    /// plane without a usable normal (other than an infinite far plane, which is dropped).
    pub fn from_view_projection(m: DMat4, depth: DepthConvention) -> Result<Self, FrustumError> {
        if !m.is_finite() {
            return Err(FrustumError::NotFinite("view-projection matrix"));
        }
        let (r0, r1, r2, r3) = (m.row(0), m.row(1), m.row(2), m.row(3));
        let low = match depth.range() {
            DepthRange::ZeroToOne => r2,
            DepthRange::NegOneToOne => r3 + r2,
        };
        let high = r3 - r2;
        let (near, far) = match depth.direction() {
            DepthDirection::Forward => (low, high),
            DepthDirection::Reversed => (high, low),
        };
        let raw = [r3 + r0, r3 - r0, r3 + r1, r3 - r1, near, far];
        let mut planes = [Plane {
            normal: DVec3::ZERO,
            d: 0.0,
        }; 6];
        let mut len = 0;
        for (id, v) in PlaneId::ALL.into_iter().zip(raw) {
            let n = v.truncate();
            // Not NaN: the matrix is finite.
            let n_len = sqrt(n.length_squared());
            if n_len <= 1e-12 * v.w.abs() {
                if id == PlaneId::Far && v.w > 0.0 {
                    continue; // infinitely far: always inside
                }
                return Err(FrustumError::Degenerate(id));
            }
            planes[len] = Plane {
                normal: n / n_len,
                d: v.w / n_len,
            };
            len += 1;
        }
        Ok(Self { planes, len })
    }

    /// As [`Frustum::from_view_projection`], for an `f32` matrix (widened exactly to `f64`).
    ///
    /// # Errors
    ///
    /// As [`Frustum::from_view_projection`].
    pub fn from_view_projection_f32(m: Mat4, depth: DepthConvention) -> Result<Self, FrustumError> {
        Self::from_view_projection(m.as_dmat4(), depth)
    }

    /// The world-space frustum of a camera.
    ///
    /// # Errors
    ///
    /// As [`Frustum::from_view_projection`] (not expected for a valid camera).
    pub fn from_camera(camera: &Camera) -> Result<Self, FrustumError> {
        Self::from_view_projection(camera.view_projection_f64(), camera.depth())
    }

    /// The planes in use, in [`PlaneId::ALL`] order (five when the far plane is infinite).
    pub fn planes(&self) -> &[Plane] {
        &self.planes[..self.len]
    }

    /// One plane; `None` for the far plane of an infinite perspective.
    pub fn plane(&self, id: PlaneId) -> Option<Plane> {
        let i = PlaneId::ALL.iter().position(|&p| p == id).unwrap_or(6);
        self.planes().get(i).copied()
    }

    /// Whether the frustum has a far plane (`false` for an infinite perspective).
    pub fn has_far_plane(&self) -> bool {
        self.len == 6
    }

    /// Core test: a shape with centre `c` whose extent along a plane normal `n` is `radius(n)`.
    #[inline]
    fn classify(&self, c: DVec3, radius: impl Fn(DVec3) -> f64) -> Containment {
        let mut result = Containment::Inside;
        for plane in self.planes() {
            let dist = plane.signed_distance(c);
            let r = radius(plane.normal);
            if dist < -r {
                return Containment::Outside;
            }
            if dist < r {
                result = Containment::Intersecting;
            }
        }
        result
    }

    /// Tests a point: [`Containment::Outside`] when it is strictly outside a plane,
    /// [`Containment::Intersecting`] when it lies exactly on a plane, else
    /// [`Containment::Inside`].
    ///
    /// # Errors
    ///
    /// [`FrustumError::NotFinite`] for a NaN or infinite coordinate.
    pub fn test_point(&self, p: DVec3) -> Result<Containment, FrustumError> {
        finite3("point", p)?;
        let mut result = Containment::Inside;
        for plane in self.planes() {
            let dist = plane.signed_distance(p);
            if dist < 0.0 {
                return Ok(Containment::Outside);
            }
            if dist == 0.0 {
                result = Containment::Intersecting;
            }
        }
        Ok(result)
    }

    /// Tests a sphere (effective radius: its radius).
    pub fn test_sphere(&self, s: &Sphere) -> Containment {
        self.classify(s.centre, |_| s.radius)
    }

    /// Tests an axis-aligned box (effective radius `e·|n|`).
    pub fn test_aabb(&self, b: &Aabb) -> Containment {
        self.classify(b.centre, |n| b.half_extents.dot(n.abs()))
    }

    /// Tests an oriented box (effective radius `Σ hᵢ |aᵢ·n|`, Akenine-Möller & Haines).
    pub fn test_obb(&self, b: &Obb) -> Containment {
        self.classify(b.centre, |n| {
            b.half_extents.x * b.axes[0].dot(n).abs()
                + b.half_extents.y * b.axes[1].dot(n).abs()
                + b.half_extents.z * b.axes[2].dot(n).abs()
        })
    }
}
