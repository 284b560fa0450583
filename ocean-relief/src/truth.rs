//! Ground truth: the exact first intersection of a ray with the bilinear surface, by walking the
//! texel cells along the ray ([`crate::line`]) and solving the quadratic on each, in `f64`; and
//! a dense march with bisection to cross-check it.

use glam::DVec3;

use crate::ReliefError;
use crate::line::walk;
use crate::map::HeightMap;
use crate::trace::Ray;

/// The ray's direction per unit depth in `f64` (`dir /= dir.z`), checked as the tracers check it
/// (in `f32`), so that both accept the same rays.
fn scaled(ray: &Ray) -> Result<(f64, f64), ReliefError> {
    if ray.dir.z.is_nan() || ray.dir.z <= 0.0 || !ray.dir.is_finite() || !ray.start.is_finite() {
        return Err(ReliefError::RayDirection);
    }
    let (fx, fy) = (ray.dir.x / ray.dir.z, ray.dir.y / ray.dir.z);
    if !(fx.is_finite() && fy.is_finite() && libm::sqrtf(fx * fx + fy * fy).is_finite()) {
        return Err(ReliefError::RayDirection);
    }
    let (dx, dy) = (
        f64::from(ray.dir.x) / f64::from(ray.dir.z),
        f64::from(ray.dir.y) / f64::from(ray.dir.z),
    );
    if !(dx.is_finite() && dy.is_finite()) {
        return Err(ReliefError::RayDirection);
    }
    Ok((dx, dy))
}

/// The first point `(u, v, depth)` where the ray is inside the relief (`depth ≥ S`). Every ray
/// has one: at depth 1 every point is inside.
///
/// # Errors
///
/// [`ReliefError::RayDirection`] for a ray that does not point into the relief.
pub fn first_hit(map: &HeightMap, ray: &Ray) -> Result<DVec3, ReliefError> {
    let (dx, dy) = scaled(ray)?;
    let n = map.size() as f64;
    let (u0, v0) = (f64::from(ray.start.x), f64::from(ray.start.y));
    let (px, py) = (u0 * n - 0.5, v0 * n - 0.5);
    // Horizontal texels per unit depth.
    let rho = libm::sqrt(dx * dx + dy * dy) * n;
    if rho == 0.0 {
        let z = map.surface_f64(px, py);
        return Ok(DVec3::new(u0, v0, z));
    }
    let (ux, uy) = (dx * n / rho, dy * n / rho);
    let mut hit = None;
    // f(s) = s/ρ − S(s): the ray is inside where f ≥ 0.
    walk(map, px, py, ux, uy, rho, |pc| {
        let f = |s: f64| s / rho - pc.at(s);
        if f(pc.s0) >= 0.0 {
            hit = Some(pc.s0);
            return false;
        }
        // On the piece f is quadratic; it reaches 0 iff its maximum on [s0, s1] does, at s1 or,
        // when concave, at its vertex. Before that point f increases from f(s0) < 0 and crosses 0
        // once; bisection finds it to the last bit.
        let (a, b) = (-pc.k2, 1.0 / rho - pc.k1);
        let mut end = pc.s1;
        if a < 0.0 {
            let v = pc.s0 - b / (2.0 * a);
            if v > pc.s0 && v < pc.s1 && f(v) >= 0.0 {
                end = v;
            }
        }
        if f(end) < 0.0 {
            return true;
        }
        let (mut lo, mut hi) = (pc.s0, end);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if f(mid) >= 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hit = Some(hi);
        false
    });
    // Rounding at depth exactly 1 can leave the walk without a hit; the bottom is then the hit.
    let s = hit.unwrap_or(rho);
    let z = s / rho;
    Ok(DVec3::new(u0 + dx * z, v0 + dy * z, z))
}

/// The depth at which the ray first leaves the solid after depth `z_hit` (its first hit): a
/// tracer whose answer lies deeper than this went through the feature it should have stopped
/// at. `f64::INFINITY` when the ray stays inside down to depth 1 (or is vertical).
///
/// # Errors
///
/// [`ReliefError::RayDirection`] for a ray that does not point into the relief.
pub fn exit_after(map: &HeightMap, ray: &Ray, z_hit: f64) -> Result<f64, ReliefError> {
    let (dx, dy) = scaled(ray)?;
    let n = map.size() as f64;
    let (px, py) = (
        f64::from(ray.start.x) * n - 0.5,
        f64::from(ray.start.y) * n - 0.5,
    );
    let rho = libm::sqrt(dx * dx + dy * dy) * n;
    if rho == 0.0 {
        return Ok(f64::INFINITY);
    }
    let (ux, uy) = (dx * n / rho, dy * n / rho);
    let s_hit = z_hit * rho;
    let mut exit = None;
    // g(s) = S(s) − s/ρ: the ray is outside where g > 0.
    walk(map, px, py, ux, uy, rho, |pc| {
        if pc.s1 <= s_hit {
            return true;
        }
        let g = |s: f64| pc.at(s) - s / rho;
        let start = pc.s0.max(s_hit);
        // The largest g on [start, s1] is at an end or, when concave, at the vertex.
        let (a, b) = (pc.k2, pc.k1 - 1.0 / rho);
        let mut end = pc.s1;
        if a < 0.0 {
            let v = pc.s0 - b / (2.0 * a);
            if v > start && v < pc.s1 && g(v) > 0.0 {
                end = v;
            }
        }
        if g(end) <= 0.0 {
            return true;
        }
        if g(start) > 0.0 {
            exit = Some(start);
            return false;
        }
        let (mut lo, mut hi) = (start, end);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if g(mid) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        exit = Some(hi);
        false
    });
    Ok(exit.map_or(f64::INFINITY, |s| s / rho))
}

/// The first hit found by marching in depth steps of `1/steps` and bisecting the first step that
/// ends inside (60 times). It misses slivers thinner than a step, so it is never earlier than
/// [`first_hit`]; on smooth maps with fine steps it agrees with it.
///
/// # Errors
///
/// [`ReliefError::RayDirection`]; [`ReliefError::OutOfRange`] for `steps` outside
/// `1 ..= 2²⁴`.
pub fn march(map: &HeightMap, ray: &Ray, steps: u32) -> Result<DVec3, ReliefError> {
    crate::check_range("steps", f64::from(steps), 1.0, 16_777_216.0)?;
    let (dx, dy) = scaled(ray)?;
    let n = map.size() as f64;
    let (u0, v0) = (f64::from(ray.start.x), f64::from(ray.start.y));
    let inside = |z: f64| z >= map.surface_f64((u0 + dx * z) * n - 0.5, (v0 + dy * z) * n - 0.5);
    if inside(0.0) {
        return Ok(DVec3::new(u0, v0, 0.0));
    }
    let mut lo = 0.0;
    let mut hi = 1.0;
    for k in 1..=steps {
        let z = f64::from(k) / f64::from(steps);
        if inside(z) {
            hi = z;
            break;
        }
        lo = z;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if inside(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(DVec3::new(u0 + dx * hi, v0 + dy * hi, hi))
}
