//! Self-shadowing (§18.2, §18.4): a surface point is lit when the light ray reaches it before
//! reaching any other point of the relief. The light ray is traced like a viewing ray, with the
//! same tracer and the same cone map, from where it enters the relief (depth 0) towards the
//! point; the point is in shadow when that ray stops clearly before it.

use glam::{Vec2, Vec3};

use crate::ReliefError;
use crate::relief::ReliefTexture;
use crate::trace::{Method, Ray};

/// Whether the light from direction `light` (tangent space, unit or not, pointing from the
/// surface towards the light, `light.z > 0` above the polygon) is blocked before it reaches
/// `point = (u, v, depth)`, for a relief `depth_scale` texture widths deep. The light ray's hit
/// must lie at least `bias` (depth units) above the point to count: the tracer's final bracket
/// (its last step over `2^binary`) needs that margin, or the point shadows itself.
///
/// A light at or below the polygon's plane (`light.z ≤ 0`) leaves every point in shadow, and
/// so does a light so close above it that its ray's run per unit depth overflows a float.
///
/// # Errors
///
/// [`ReliefError::RayDirection`] for non-finite inputs; the tracer's errors for `method`;
/// [`ReliefError::OutOfRange`] for a negative or non-finite `bias`.
pub fn in_shadow(
    texture: &ReliefTexture,
    method: &Method,
    point: Vec3,
    light: Vec3,
    depth_scale: f32,
    bias: f32,
) -> Result<bool, ReliefError> {
    match light_ray(point, light, depth_scale, bias)? {
        None => Ok(true),
        Some(ray) => Ok(method.trace(texture, &ray)?.pos.z < point.z - bias),
    }
}

/// The checks of [`in_shadow`] and its light ray: `None` for a light at or below the polygon's
/// plane (every point in shadow), else the ray that enters the relief at depth 0 and runs
/// towards `point` (shared by [`crate::QuadReliefTexture::in_shadow`], whose layer is the light
/// ray's quadrant).
pub(crate) fn light_ray(
    point: Vec3,
    light: Vec3,
    depth_scale: f32,
    bias: f32,
) -> Result<Option<Ray>, ReliefError> {
    if !point.is_finite() || !light.is_finite() || !depth_scale.is_finite() {
        return Err(ReliefError::RayDirection);
    }
    crate::check_range("bias", f64::from(bias), 0.0, 1.0)?;
    if light.z <= 0.0 {
        return Ok(None);
    }
    // The ray towards the point, scaled like a viewing ray: per unit depth it moves
    // depth_scale·(−light.xy)/light.z; it enters the relief where it is at depth 0.
    let per_depth = Vec2::new(-light.x, -light.y) * (depth_scale / light.z);
    let start = Vec2::new(point.x, point.y) - per_depth * point.z;
    if !(per_depth.is_finite() && start.is_finite()) {
        // A light so close to the plane (light.z = 1e-45 beside a unit light.xy) that its run
        // per unit depth overflows a float is on the plane for every texel: in shadow.
        return Ok(None);
    }
    Ray::from_view(start, -light, depth_scale).map(Some)
}
