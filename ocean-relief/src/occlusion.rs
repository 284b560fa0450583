//! The depth of the hit point, for correct occlusion with the rest of the scene (§18.2:
//! "proper occlusion … is achieved simply by updating the z-buffer with the z coordinate of P
//! (expressed in camera space and after projection and division by w)").
//!
//! The tracer's hit is `(u, v, d)` with `d` the normalised depth. Along the viewing ray the hit
//! lies `d·depth_world / cos θ` beyond the fragment on the polygon, `depth_world` the relief's
//! depth in world units and `cos θ = −V·N` for the unit view vector `V` (tangent space, `z` out
//! of the surface). In view space (ocean-core's convention: the camera looks down −z) that moves
//! the fragment along its unit view direction; the window depth then follows from the
//! projection and depth convention ([`ocean_core::Projection::ndc_depth`]), which covers
//! forward and reversed, `[0, 1]` and `[−1, 1]`, finite and infinite far planes and orthographic
//! cameras.

use glam::{DVec3, Vec3};
use ocean_core::{DepthConvention, Projection};

use crate::ReliefError;

/// World-space distance along the viewing ray from the polygon fragment to a hit at normalised
/// depth `hit_depth`, for the unit tangent-space view vector `view` (`view.z < 0`) and a relief
/// `depth_world` world units deep.
///
/// # Errors
///
/// [`ReliefError::RayDirection`] unless `view.z < 0` and every input is finite.
pub fn view_distance(hit_depth: f32, view: Vec3, depth_world: f32) -> Result<f32, ReliefError> {
    let len = view.length();
    if view.z.is_nan()
        || view.z >= 0.0
        || !len.is_finite()
        || !hit_depth.is_finite()
        || !depth_world.is_finite()
    {
        return Err(ReliefError::RayDirection);
    }
    let cos = -view.z / len;
    Ok(hit_depth * depth_world / cos)
}

/// The hit's view-space position and its NDC depth: the fragment's view-space position moved by
/// `distance` (from [`view_distance`]) along `dir`, the view-space direction from the eye through
/// the fragment (any length).
///
/// # Errors
///
/// [`ReliefError::RayDirection`] for a zero or non-finite direction or a non-finite input; the
/// projection's errors ([`ReliefError::Camera`]), for example a point on the camera plane.
pub fn occlusion_depth(
    projection: &Projection,
    convention: DepthConvention,
    fragment: DVec3,
    dir: DVec3,
    distance: f64,
) -> Result<(DVec3, f64), ReliefError> {
    let len = dir.length();
    if len.is_nan()
        || len <= 0.0
        || !len.is_finite()
        || !fragment.is_finite()
        || !distance.is_finite()
    {
        return Err(ReliefError::RayDirection);
    }
    let p = fragment + dir * (distance / len);
    let ndc = projection.ndc_depth(convention, p.z)?;
    Ok((p, ndc))
}
