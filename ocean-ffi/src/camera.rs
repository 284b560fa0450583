//! The one camera of the C ABI, `OceanCamera`: a view matrix, a projection matrix and the depth
//! convention the projection was built for. Every entry point that needs a camera takes it.
//!
//! The math crates take a projection by its parameters (a symmetric perspective frustum with a
//! finite or infinite far plane, or an orthographic box) and derive every constant of their
//! passes from them in `f64`. A C caller has a matrix (`glm::perspective`, `glm::ortho`,
//! `glm::infinitePerspective`, a reversed-Z matrix of its own), so this module recovers the
//! parameters from the matrix, in `f64`:
//!
//! ```text
//! perspective:  fov_y = 2·atan2(1, P11),  aspect = P11/P00,
//!               near = P23/(ζn + P22),  far = P23/(ζf + P22)  (infinite when ζf + P22 = 0)
//! orthographic: left = (−1 − P03)/P00, right = (1 − P03)/P00,
//!               bottom = (−1 − P13)/P11, top = (1 − P13)/P11,
//!               near = (P23 − ζn)/P22,  far = (P23 − ζf)/P22
//! ```
//!
//! with `Prc` the element in row r, column c (`projection[4c + r]`) and `ζn`, `ζf` the NDC
//! depths of the near and far planes under the depth convention (`DepthConvention::near_ndc`,
//! `far_ndc`). These invert `Projection::matrix_f64` (whose depth row is `−α`, `β` with
//! NDC = α + β/distance): `ζ = −P22 + P23/d` at distance `d` for a perspective, `ζ = P23 − P22·d`
//! for an orthographic box.
//!
//! The matrix checks the declared convention where it can: read under the wrong direction of
//! depth (forward against reversed), a perspective puts its far plane before its near plane
//! and is refused. It cannot tell [0, 1] from [-1, 1] for a forward-Z perspective: both
//! readings give a valid frustum, the [0, 1] reading of a [-1, 1] matrix with its near plane at
//! 2nf/(n + f), about twice as far (a test shows it), so the convention must be stated.

use glam::DMat4;
use ocean_core::Camera;
use ocean_core::camera::{CameraError, DepthConvention, Far, Projection};

use crate::boundary::{CEnum, CheckedStruct, EnumField, check_reserved, read_checked};
use crate::status::{Error, OceanStatus};

/// Depth convention of a projection matrix: the range of NDC depth (clip z / clip w) and which
/// end is near.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanDepthConvention {
    /// Depth in [0, 1], near at 0: wgpu, Vulkan, D3D, Metal (GLM with
    /// GLM_FORCE_DEPTH_ZERO_TO_ONE).
    #[default]
    ZeroToOne = 0,
    /// Depth in [0, 1], near at 1 (reversed Z).
    ZeroToOneReversed = 1,
    /// Depth in [-1, 1], near at -1: OpenGL and GLM's default.
    NegOneToOne = 2,
}

impl CEnum for OceanDepthConvention {
    const REFUSAL: &'static str = "is not an OceanDepthConvention (0, 1 or 2)";
}

/// A camera, as every entry point that needs one takes it: the view and projection matrices a
/// renderer draws with, and the depth convention the projection was built for.
///
/// Matrices are column-major, 16 doubles, element [4 * column + row]: GLM's layout
/// (`glm::value_ptr` of a `glm::dmat4`; convert a `glm::mat4` with `glm::dmat4(m)`). Column
/// vectors: clip = projection * view * world. The view matrix maps world space (right-handed,
/// y up) to view space, right-handed with the camera looking down its -z axis; every element
/// finite and the matrix invertible.
///
/// Accepted projections:
/// - a symmetric perspective, bottom row (0, 0, -1, 0): `glm::perspective`,
///   `glm::infinitePerspective`, and their [0, 1] and reversed-Z forms. Off-centre frusta
///   (`projection[8]`, `[9]`, `[12]`, `[13]` non-zero, as in a TAA-jittered matrix) are refused:
///   pass the unjittered matrix and jitter after;
/// - an orthographic box, bottom row (0, 0, 0, 1), centred or not (`glm::ortho`).
///
/// Both need a positive x scale `projection[0]` and y scale `projection[5]` (no mirrored or
/// y-flipped matrix) and zero skew (`projection[1]`, `[2]`, `[4]`, `[6]`). The near and far
/// planes are read from the depth row (`projection[10]`, `[14]`) under `depth_convention`, and
/// must come out as 0 < near < far (perspective; far may be infinite: `projection[10]` = -1, or
/// 0 reversed) or near < far (orthographic). A matrix read under the wrong direction of depth
/// (a forward-Z matrix declared `OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED`, or the reverse)
/// fails that test and is refused.
///
/// The depth row alone cannot tell `OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE` from
/// `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE` for a forward-Z perspective: a `glm::perspective`
/// matrix (GLM's default, [-1, 1]) read as [0, 1] gives a near plane at about twice its
/// distance, without any error. Pass the convention the matrix was built for (GLM: [-1, 1]
/// unless `GLM_FORCE_DEPTH_ZERO_TO_ONE`); `ocean_sao_describe` reports the planes read.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanCamera {
    /// World-to-view matrix, column-major.
    pub view: [f64; 16],
    /// View-to-clip (projection) matrix, column-major.
    pub projection: [f64; 16],
    /// The convention of `projection` (other values are refused).
    pub depth_convention: OceanDepthConvention,
    /// Must be 0: room for a later member, and no padding the caller cannot see.
    pub reserved: u32,
}

impl OceanCamera {
    /// The C layout of a camera: its view and projection matrices (built from its parameters)
    /// and its depth convention.
    pub fn from_camera(c: &Camera) -> Self {
        let depth = c.depth();
        let depth_convention = if depth == DepthConvention::ZERO_TO_ONE_REVERSED {
            OceanDepthConvention::ZeroToOneReversed
        } else if depth == DepthConvention::NEG_ONE_TO_ONE {
            OceanDepthConvention::NegOneToOne
        } else {
            OceanDepthConvention::ZeroToOne
        };
        Self {
            view: c.view_f64().to_cols_array(),
            projection: c.projection_f64().to_cols_array(),
            depth_convention,
            reserved: 0,
        }
    }
}

impl CheckedStruct for OceanCamera {
    const ENUM_FIELDS: &'static [EnumField] = &[EnumField::of::<OceanDepthConvention>(
        "depth_convention",
        core::mem::offset_of!(OceanCamera, depth_convention),
    )];

    /// The matrices' finiteness, which the header's order reports before the convention.
    fn check_first(bits: &Self::Bits, name: &str) -> Result<(), Error> {
        check_matrices_finite(name, &bits.view, &bits.projection)
    }
}

/// `OCEAN_STATUS_NON_FINITE` naming the first NaN or infinite element, view then projection.
fn check_matrices_finite(
    name: &str,
    view: &[f64; 16],
    projection: &[f64; 16],
) -> Result<(), Error> {
    for (matrix, m) in [("view", view), ("projection", projection)] {
        if let Some(k) = m.iter().position(|v| !v.is_finite()) {
            return Err(Error::new(
                OceanStatus::NonFinite,
                format!("{name}->{matrix}[{k}] = {} is not finite", m[k]),
            ));
        }
    }
    Ok(())
}

fn convention_from(v: OceanDepthConvention) -> DepthConvention {
    match v {
        OceanDepthConvention::ZeroToOne => DepthConvention::ZERO_TO_ONE,
        OceanDepthConvention::ZeroToOneReversed => DepthConvention::ZERO_TO_ONE_REVERSED,
        OceanDepthConvention::NegOneToOne => DepthConvention::NEG_ONE_TO_ONE,
    }
}

fn convention_name(c: DepthConvention) -> &'static str {
    if c == DepthConvention::ZERO_TO_ONE {
        "[0, 1]"
    } else if c == DepthConvention::ZERO_TO_ONE_REVERSED {
        "[0, 1] reversed"
    } else {
        "[-1, 1]"
    }
}

fn invalid(message: String) -> Error {
    Error::new(OceanStatus::InvalidArgument, message)
}

/// Reads and validates the parameter `camera`: the view matrix, the projection recovered from
/// its matrix (see the module documentation), the convention.
///
/// # Safety
///
/// `c` must be NULL, misaligned or point to a readable `OceanCamera`.
pub(crate) unsafe fn read_camera(c: *const OceanCamera) -> Result<Camera, Error> {
    // SAFETY: forwarded from this function's contract.
    let c = unsafe { read_checked(c, "camera") }?;
    camera_from(&c)
}

/// Validates a camera (the parameter `camera`, as messages name it).
pub(crate) fn camera_from(c: &OceanCamera) -> Result<Camera, Error> {
    check_matrices_finite("camera", &c.view, &c.projection)?;
    let convention = convention_from(c.depth_convention);
    check_reserved("camera->reserved", c.reserved)?;
    let projection = projection_from_matrix(&c.projection, convention)?;
    Camera::new(DMat4::from_cols_array(&c.view), projection, convention).map_err(|e| {
        Error::new(
            camera_status(&e),
            format!("camera: the view matrix with this projection: {e}"),
        )
    })
}

/// The projection parameters of a matrix (see the module documentation).
pub(crate) fn projection_from_matrix(
    m: &[f64; 16],
    convention: DepthConvention,
) -> Result<Projection, Error> {
    if let Some(k) = m.iter().position(|v| !v.is_finite()) {
        return Err(Error::new(
            OceanStatus::NonFinite,
            format!("camera->projection[{k}] = {} is not finite", m[k]),
        ));
    }
    let e = |k: usize| m[k];
    let bottom = [m[3], m[7], m[11], m[15]];
    let perspective = if bottom == [0.0, 0.0, -1.0, 0.0] {
        true
    } else if bottom == [0.0, 0.0, 0.0, 1.0] {
        false
    } else {
        return Err(invalid(format!(
            "camera->projection's bottom row (elements 3, 7, 11, 15) is {bottom:?}: neither \
             (0, 0, -1, 0), a right-handed perspective (w_clip = -z_view), nor (0, 0, 0, 1), an \
             orthographic projection"
        )));
    };
    for k in [1, 2, 4, 6] {
        if m[k] != 0.0 {
            return Err(invalid(format!(
                "camera->projection[{k}] = {} must be 0: skewed or rotated projections are not \
                 supported",
                m[k]
            )));
        }
    }
    if perspective {
        for k in [8, 9, 12, 13] {
            if m[k] != 0.0 {
                return Err(invalid(format!(
                    "camera->projection[{k}] = {} must be 0: off-centre (asymmetric or jittered) \
                     perspective frusta are not supported; pass the unjittered symmetric matrix",
                    m[k]
                )));
            }
        }
    } else {
        for k in [8, 9] {
            if m[k] != 0.0 {
                return Err(invalid(format!(
                    "camera->projection[{k}] = {} must be 0 for an orthographic projection \
                     (x and y may not depend on z)",
                    m[k]
                )));
            }
        }
    }
    let (p00, p11) = (e(0), e(5));
    if p00 <= 0.0 {
        return Err(invalid(format!(
            "camera->projection[0] (x scale) = {p00} must be > 0: mirrored projections are not \
             supported"
        )));
    }
    if p11 <= 0.0 {
        return Err(invalid(format!(
            "camera->projection[5] (y scale) = {p11} must be > 0: y-flipped projections are not \
             supported (depth rows already run top-down; pass the unflipped matrix)"
        )));
    }
    let (zn, zf) = (convention.near_ndc(), convention.far_ndc());
    let (a, b) = (e(10), e(14));
    let name = convention_name(convention);
    let projection = if perspective {
        let near = b / (zn + a);
        if !(near.is_finite() && near > 0.0) {
            return Err(invalid(format!(
                "camera->projection's depth row (projection[10] = {a}, projection[14] = {b}) \
                 puts the near plane at {near} m under the {name} depth convention: not a \
                 perspective projection for that convention"
            )));
        }
        let far = if zf + a == 0.0 {
            Far::Infinite
        } else {
            let far = b / (zf + a);
            if !far.is_finite() {
                return Err(invalid(format!(
                    "camera->projection's depth row (projection[10] = {a}, projection[14] = \
                     {b}) puts the far plane at {far} m under the {name} depth convention"
                )));
            }
            Far::Finite(far)
        };
        Projection::Perspective {
            fov_y: 2.0 * ocean_core::math::atan2(1.0, p11),
            aspect: p11 / p00,
            near,
            far,
        }
    } else {
        if a == 0.0 {
            return Err(invalid(
                "camera->projection[10] = 0: an orthographic depth that does not vary with \
                 distance"
                    .to_owned(),
            ));
        }
        let (p03, p13) = (e(12), e(13));
        Projection::Orthographic {
            left: (-1.0 - p03) / p00,
            right: (1.0 - p03) / p00,
            bottom: (-1.0 - p13) / p11,
            top: (1.0 - p13) / p11,
            near: (b - zn) / a,
            far: (b - zf) / a,
        }
    };
    projection.validate().map_err(|e| {
        invalid(format!(
            "camera->projection, read under the {name} depth convention as {}: {e}",
            describe(&projection)
        ))
    })?;
    Ok(projection)
}

fn describe(p: &Projection) -> String {
    match *p {
        Projection::Perspective {
            fov_y,
            aspect,
            near,
            far,
        } => {
            let far = match far {
                Far::Finite(f) => format!("{f} m"),
                Far::Infinite => "infinity".to_owned(),
            };
            format!(
                "a perspective with fov_y {fov_y} rad, aspect {aspect}, near {near} m, far {far}"
            )
        }
        Projection::Orthographic {
            left,
            right,
            bottom,
            top,
            near,
            far,
        } => format!(
            "an orthographic box x [{left}, {right}], y [{bottom}, {top}], near {near} m, far \
             {far} m"
        ),
    }
}

/// A camera error that `Projection::validate` cannot raise for a matrix with finite elements is
/// still mapped, for completeness: a NaN parameter is `OCEAN_STATUS_NON_FINITE`.
pub(crate) fn camera_status(e: &CameraError) -> OceanStatus {
    match e {
        CameraError::NotFinite { .. } => OceanStatus::NonFinite,
        _ => OceanStatus::InvalidArgument,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::enums::read_poked;

    fn perspective(far: Far) -> Projection {
        Projection::Perspective {
            fov_y: 1.0,
            aspect: 4.0 / 3.0,
            near: 0.1,
            far,
        }
    }

    fn projections() -> Vec<Projection> {
        vec![
            perspective(Far::Finite(100.0)),
            perspective(Far::Finite(1.0e5)),
            perspective(Far::Infinite),
            Projection::Perspective {
                fov_y: 0.01,
                aspect: 0.5,
                near: 3.0,
                far: Far::Finite(7.0),
            },
            Projection::Orthographic {
                left: -4.0,
                right: 4.0,
                bottom: -3.0,
                top: 3.0,
                near: 0.05,
                far: 40.0,
            },
            // Off-centre and starting behind the camera: both are orthographic boxes too.
            Projection::Orthographic {
                left: 1.0,
                right: 9.0,
                bottom: -1.0,
                top: 2.0,
                near: -5.0,
                far: 20.0,
            },
        ]
    }

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * a.abs().max(b.abs()).max(1.0e-30)
    }

    /// Every parameter comes back from the `f32` matrix that `Projection::matrix` builds, to
    /// the `f32` rounding of its elements, for every convention; infinite stays infinite; and
    /// the matrix rebuilt from the recovered parameters is the caller's, element by element.
    #[test]
    fn parameters_are_recovered_from_the_f32_matrix() {
        for p in projections() {
            for convention in DepthConvention::ALL {
                let m = p.matrix(convention).unwrap().to_cols_array();
                let q = projection_from_matrix(&m.map(f64::from), convention)
                    .unwrap_or_else(|e| panic!("{p:?} {convention:?}: {}", e.message));
                // f32 elements carry a relative error of 2^-24 each; the near and far planes
                // of a perspective come from differences like 1 + P22 (far = 1e5 m: 1e-6 of
                // P22), which amplify it by far/near at most.
                let rel = match (p, q) {
                    (
                        Projection::Perspective {
                            fov_y: f0,
                            aspect: a0,
                            near: n0,
                            far: far0,
                        },
                        Projection::Perspective {
                            fov_y: f1,
                            aspect: a1,
                            near: n1,
                            far: far1,
                        },
                    ) => {
                        assert!(close(f0, f1, 2.0e-7), "{p:?} -> {q:?}");
                        assert!(close(a0, a1, 2.0e-7), "{p:?} -> {q:?}");
                        assert!(close(n0, n1, 1.0e-6), "{p:?} -> {q:?}");
                        match (far0, far1) {
                            (Far::Infinite, Far::Infinite) => {}
                            (Far::Finite(x), Far::Finite(y)) => {
                                let amplification = x / n0;
                                assert!(
                                    close(x, y, 2.0e-7 * amplification.max(1.0)),
                                    "{p:?} -> {q:?}"
                                );
                            }
                            _ => panic!("{p:?} -> {q:?}: the far plane changed kind"),
                        }
                        2.0e-7
                    }
                    (
                        Projection::Orthographic {
                            left: l0,
                            right: r0,
                            bottom: b0,
                            top: t0,
                            near: n0,
                            far: f0,
                        },
                        Projection::Orthographic {
                            left: l1,
                            right: r1,
                            bottom: b1,
                            top: t1,
                            near: n1,
                            far: f1,
                        },
                    ) => {
                        let span = (r0 - l0).max(t0 - b0).max(f0 - n0);
                        for (x, y) in [(l0, l1), (r0, r1), (b0, b1), (t0, t1), (n0, n1), (f0, f1)] {
                            assert!((x - y).abs() <= 4.0e-7 * span, "{p:?} -> {q:?}");
                        }
                        2.0e-7
                    }
                    _ => panic!("{p:?} -> {q:?}: the kind changed"),
                };
                let rebuilt = q.matrix_f64(convention).unwrap().to_cols_array();
                for k in 0..16 {
                    let scale = f64::from(m[k].abs());
                    assert!(
                        (rebuilt[k] - f64::from(m[k])).abs() <= 2.0 * rel * scale,
                        "{p:?} {convention:?}: element {k}: {} rebuilt as {}",
                        m[k],
                        rebuilt[k]
                    );
                }
            }
        }
    }

    /// GLM's matrices, written out as GLM builds them (glm/ext/matrix_clip_space.inl), are read
    /// with the planes they were built from.
    #[test]
    fn glm_matrices_are_read_as_built() {
        let (n, f, fovy, aspect) = (0.1f32, 100.0f32, 1.0f32, 1.5f32);
        let t = (fovy / 2.0).tan();
        let mut gl = [0.0f32; 16];
        gl[0] = 1.0 / (aspect * t);
        gl[5] = 1.0 / t;
        gl[10] = -(f + n) / (f - n);
        gl[11] = -1.0;
        gl[14] = -(2.0 * f * n) / (f - n);
        let mut zo = gl;
        zo[10] = f / (n - f);
        zo[14] = -(f * n) / (f - n);
        let mut inf = gl;
        inf[10] = -1.0;
        inf[14] = -2.0 * n;
        let mut reversed_inf = gl;
        reversed_inf[10] = 0.0;
        reversed_inf[14] = n;
        for (m, convention, far) in [
            (gl, DepthConvention::NEG_ONE_TO_ONE, Some(f)),
            (zo, DepthConvention::ZERO_TO_ONE, Some(f)),
            (inf, DepthConvention::NEG_ONE_TO_ONE, None),
            (reversed_inf, DepthConvention::ZERO_TO_ONE_REVERSED, None),
        ] {
            let Projection::Perspective {
                fov_y,
                aspect: a,
                near,
                far: far_read,
            } = projection_from_matrix(&m.map(f64::from), convention).unwrap()
            else {
                panic!("not a perspective");
            };
            assert!(close(fov_y, f64::from(fovy), 1.0e-6), "{fov_y}");
            assert!(close(a, f64::from(aspect), 1.0e-6), "{a}");
            assert!(close(near, f64::from(n), 1.0e-5), "{near}");
            match (far, far_read) {
                (None, Far::Infinite) => {}
                (Some(x), Far::Finite(y)) => assert!(close(f64::from(x), y, 1.0e-3), "{y}"),
                other => panic!("{other:?}"),
            }
        }
        // The ambiguity the documentation warns about: GLM's [-1, 1] matrix read as [0, 1]
        // is accepted, with the near plane at 2nf/(n + f).
        let Projection::Perspective { near, .. } =
            projection_from_matrix(&gl.map(f64::from), DepthConvention::ZERO_TO_ONE).unwrap()
        else {
            panic!("not a perspective");
        };
        let expected = 2.0 * f64::from(n) * f64::from(f) / f64::from(n + f);
        assert!(close(near, expected, 1.0e-5), "{near}");
        // Read as reversed Z, the same matrix puts the far plane before the near plane.
        let e = projection_from_matrix(&gl.map(f64::from), DepthConvention::ZERO_TO_ONE_REVERSED)
            .unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument);
        assert!(e.message.contains("far plane"), "{}", e.message);
    }

    #[test]
    fn matrices_that_are_not_supported_projections_are_refused_with_a_reason() {
        let good = perspective(Far::Finite(100.0))
            .matrix(DepthConvention::ZERO_TO_ONE)
            .unwrap()
            .to_cols_array();
        let ortho = projections()[4]
            .matrix(DepthConvention::ZERO_TO_ONE)
            .unwrap()
            .to_cols_array();
        let with = |base: [f32; 16], k: usize, v: f32| {
            let mut m = base;
            m[k] = v;
            m
        };
        let cases: Vec<([f32; 16], OceanStatus, &str)> = vec![
            (
                with(good, 5, f32::NAN),
                OceanStatus::NonFinite,
                "projection[5]",
            ),
            (
                with(good, 14, f32::INFINITY),
                OceanStatus::NonFinite,
                "projection[14]",
            ),
            ([0.0; 16], OceanStatus::InvalidArgument, "bottom row"),
            // Left-handed (glm::perspectiveLH): w_clip = +z_view.
            (
                with(good, 11, 1.0),
                OceanStatus::InvalidArgument,
                "bottom row",
            ),
            (
                with(good, 8, 0.01),
                OceanStatus::InvalidArgument,
                "off-centre",
            ),
            (
                with(good, 13, -0.5),
                OceanStatus::InvalidArgument,
                "off-centre",
            ),
            (with(good, 4, 0.1), OceanStatus::InvalidArgument, "skewed"),
            (
                with(good, 5, -good[5]),
                OceanStatus::InvalidArgument,
                "y-flipped",
            ),
            (with(good, 0, 0.0), OceanStatus::InvalidArgument, "mirrored"),
            // Depth rows that put the near plane behind the camera or at infinity.
            (
                with(good, 14, 0.5),
                OceanStatus::InvalidArgument,
                "near plane",
            ),
            (
                with(good, 10, 0.0),
                OceanStatus::InvalidArgument,
                "near plane",
            ),
            (
                with(ortho, 10, 0.0),
                OceanStatus::InvalidArgument,
                "does not vary",
            ),
            (
                with(ortho, 9, 0.2),
                OceanStatus::InvalidArgument,
                "orthographic",
            ),
            (
                with(ortho, 10, -ortho[10]),
                OceanStatus::InvalidArgument,
                "far plane",
            ),
        ];
        for (m, status, needle) in cases {
            let e = projection_from_matrix(&m.map(f64::from), DepthConvention::ZERO_TO_ONE)
                .unwrap_err();
            assert_eq!(e.status, status, "{m:?}: {}", e.message);
            assert!(
                e.message.contains(needle),
                "{needle:?} not in {}",
                e.message
            );
        }
    }

    /// The C camera reads back as the camera it was made from, and its enumeration, reserved
    /// member and view matrix are checked in the header's order.
    #[test]
    fn cameras_are_read_and_checked() {
        let view = ocean_core::camera::look_at(
            glam::DVec3::new(3.0, 2.0, 5.0),
            glam::DVec3::ZERO,
            glam::DVec3::Y,
        )
        .unwrap();
        let camera = Camera::new(
            view,
            perspective(Far::Infinite),
            DepthConvention::ZERO_TO_ONE_REVERSED,
        )
        .unwrap();
        let c = OceanCamera::from_camera(&camera);
        assert_eq!(c.depth_convention, OceanDepthConvention::ZeroToOneReversed);
        let read = camera_from(&c).unwrap();
        assert_eq!(read.depth(), DepthConvention::ZERO_TO_ONE_REVERSED);
        assert_eq!(read.view_f64(), view);
        let Projection::Perspective { near, far, .. } = read.projection() else {
            panic!("not a perspective");
        };
        assert!(
            close(near, 0.1, 1e-12) && far == Far::Infinite,
            "{near} {far:?}"
        );
        let refused = |c: OceanCamera, status: OceanStatus, needle: &str| {
            let e = camera_from(&c).unwrap_err();
            assert_eq!(e.status, status, "{}", e.message);
            assert!(
                e.message.contains(needle),
                "{needle:?} not in {}",
                e.message
            );
        };
        let at = core::mem::offset_of!(OceanCamera, depth_convention);
        let e = read_poked(&c, "camera", at, 3).unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument, "{}", e.message);
        assert_eq!(
            e.message,
            "camera->depth_convention = 3 is not an OceanDepthConvention (0, 1 or 2)"
        );
        // A NaN is reported before the enumeration (NON_FINITE, then ranges).
        let mut nan = c;
        nan.projection[0] = f64::NAN;
        let e = read_poked(&nan, "camera", at, 3).unwrap_err();
        assert_eq!(e.status, OceanStatus::NonFinite, "{}", e.message);
        assert!(e.message.contains("camera->projection[0]"), "{}", e.message);
        refused(nan, OceanStatus::NonFinite, "camera->projection[0]");
        let mut bad = c;
        bad.reserved = 1;
        refused(bad, OceanStatus::InvalidArgument, "camera->reserved");
        let mut bad = c;
        bad.view = [0.0; 16];
        refused(bad, OceanStatus::InvalidArgument, "view matrix");
        // A reversed-Z matrix declared forward puts its far plane before its near plane.
        let mut bad = c;
        bad.depth_convention = OceanDepthConvention::ZeroToOne;
        refused(bad, OceanStatus::InvalidArgument, "plane");
    }
}
