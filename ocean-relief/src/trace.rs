//! The CPU tracers: linear + binary search (Policarpo et al. 2005), cone step mapping
//! (Dummer 2006, §18.3) and relaxed cone stepping + binary search (Listing 18-3).
//!
//! They are written as the plain `f32` arithmetic the GPU port copies: one [`ReliefTexture::fetch`]
//! per step (four loads and `mix`, [`crate::sample`]), `+ − × ÷`, one square root, and `select`s
//! where a shader would branch.
//!
//! ## The ray (§18.2)
//!
//! A ray starts where the viewing ray meets the polygon, at texture coordinates `start` and depth
//! 0, and moves by `dir` per unit of depth after the book's scaling `ray_dir /= ray_dir.z`:
//! `dir.xy` is in texture widths per unit of normalised depth. For a unit view vector `V` in
//! tangent space (`z` out of the surface, `V.z < 0` looking at it) and a relief `depth` texture
//! widths deep, `dir.xy = depth·V.xy/(−V.z)` ([`Ray::from_view`]); rescaling the depth only
//! changes the ray, never the cones (§18.5, Fig. 18-11). A point is inside the relief when its
//! depth is at least the surface's: `z ≥ S(u, v)` (the book's test `bs_position.z < tex.w` for
//! "outside").
//!
//! ## Departures from Listing 18-3, and why
//!
//! - The binary search refines **the last cone step** `[J, K]` (the last position above the
//!   surface and the position after the last step), not `[f, K]` as the listing's code does
//!   (its text says `[H, K]`, its code starts at `H` but brackets `[f, K]`): with valid relaxed
//!   cones the last step crosses the surface at most once, so its bracket holds the first hit and
//!   is much shorter. [`BinarySearch::Book`] keeps the listing's search for comparison.
//! - The last position above the surface is kept with a `select` (one register more than the
//!   book wanted to spend, §18.4.2).
//! - [`BinarySearch::Shared`] spends one budget of fetches: cone steps while the ray is above the
//!   surface, bisections of the last step with the rest. The book's fixed loop keeps fetching
//!   after the ray is inside (each such step is 0) and bisects only 6 times; at grazing angles,
//!   where most rays need every step, the shared budget gives them all.
//! - Each step also reads the clearance and near cap ([`crate::cone`]): the step is
//!   `max(c·h/(ρ + c), min(D·h/(ρ·h + D), E·h/(ρ + E)))` ([`step_length`]); with a one-channel
//!   map (`D = E = 0`) it is the book's step.
//! - A vertical ray (`dir.xy = 0`) with a zero cone would divide 0 by 0 in the step formula; the
//!   step is then the height itself (the ray goes straight down, whatever the cone).
//! - Every method returns the midpoint of its final bracket (the book's binary search does the
//!   same; Policarpo's linear search returned the last point found inside). Cone step mapping,
//!   and a shared budget spent before the ray got inside, return the last point above the
//!   surface.

use glam::{Vec2, Vec3};

use crate::ReliefError;
use crate::relief::ReliefTexture;

/// Largest step count any method accepts (per phase).
pub const MAX_STEPS: u32 = 4096;

/// A ray into the relief (module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Texture coordinates where the ray enters the relief, at depth 0.
    pub start: Vec2,
    /// Direction; any positive `z` (the tracers divide by it).
    pub dir: Vec3,
}

/// Largest texture coordinate a ray may reach, texture widths: |start| plus the run to full
/// depth. Far beyond a float's texel resolution (already at 1e7 a float steps by a whole
/// texture width, and the texture tiles or clamps), but within it every tracer's arithmetic,
/// texel lookups of the largest maps included (1e30 · 4096 texels), stays finite; at
/// `FLT_MAX` the lookups overflowed to infinite hits.
pub const MAX_TEXCOORD: f64 = 1e30;

impl Ray {
    /// The ray of a unit view vector `view` in tangent space (`z` out of the surface; `view.z <
    /// 0`) entering at `start`, for a relief `depth` texture widths deep.
    ///
    /// # Errors
    ///
    /// [`ReliefError::RayDirection`] unless `view.z < 0` and everything is finite;
    /// [`ReliefError::OutOfRange`] for a negative `depth`.
    pub fn from_view(start: Vec2, view: Vec3, depth: f32) -> Result<Self, ReliefError> {
        if depth < 0.0 {
            return Err(ReliefError::OutOfRange {
                name: "depth",
                value: f64::from(depth),
                min: 0.0,
                max: f64::INFINITY,
            });
        }
        if view.z.is_nan()
            || view.z >= 0.0
            || !view.is_finite()
            || !depth.is_finite()
            || !start.is_finite()
        {
            return Err(ReliefError::RayDirection);
        }
        let ray = Self {
            start,
            dir: Vec3::new(depth * view.x / -view.z, depth * view.y / -view.z, 1.0),
        };
        ray.check()?;
        Ok(ray)
    }

    /// The direction scaled to `z = 1` (`ray_dir /= ray_dir.z`) and its horizontal length
    /// (`ray_ratio`), after checking the ray.
    fn scaled(&self) -> Result<(f32, f32, f32), ReliefError> {
        self.check()?;
        let dx = self.dir.x / self.dir.z;
        let dy = self.dir.y / self.dir.z;
        let ratio = libm::sqrtf(dx * dx + dy * dy);
        if !(dx.is_finite() && dy.is_finite() && ratio.is_finite()) {
            return Err(ReliefError::RayTooFlat);
        }
        // Every point the tracers visit lies within start ± the run to full depth: keep it
        // where a float holds it (at FLT_MAX the texel lookups overflow to infinity).
        let reach = self.start.abs().max_element() + ratio;
        if f64::from(reach) > MAX_TEXCOORD {
            return Err(ReliefError::OutOfRange {
                name: "ray start + run to full depth",
                value: f64::from(reach),
                min: 0.0,
                max: MAX_TEXCOORD,
            });
        }
        Ok((dx, dy, ratio))
    }

    fn check(&self) -> Result<(), ReliefError> {
        if self.dir.z.is_nan()
            || self.dir.z <= 0.0
            || !self.dir.is_finite()
            || !self.start.is_finite()
        {
            return Err(ReliefError::RayDirection);
        }
        Ok(())
    }
}

/// Where a tracer stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// `(u, v, depth)`: texture coordinates and normalised depth.
    pub pos: Vec3,
    /// Texture fetches spent.
    pub fetches: u32,
}

/// The binary search after relaxed cone stepping.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum BinarySearch {
    /// `cone` steps, then `binary` bisections of the last step (default).
    #[default]
    LastStep,
    /// Listing 18-3's: `cone` steps, then `binary` probes starting halfway from the entry point
    /// to the stop point.
    Book,
    /// One budget of `cone + binary` fetches: cone steps while the ray is above the surface,
    /// then bisections of the last step with every fetch left. No fetch is spent on a step that
    /// cannot move (the book's loop keeps fetching once the ray is inside), and a ray that needs
    /// more steps gets them.
    Shared,
}

/// A tracer and its step counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Policarpo et al. 2005: `linear` equal depth steps, then `binary` bisections of the step
    /// that first went inside.
    Linear {
        /// Linear steps.
        linear: u32,
        /// Binary steps.
        binary: u32,
    },
    /// Dummer 2006: `steps` conservative cone steps, no refinement (needs a conservative cone
    /// map).
    ConeStep {
        /// Cone steps.
        steps: u32,
    },
    /// Listing 18-3: `cone` relaxed cone steps, then `binary` bisections (needs a relaxed cone
    /// map).
    Relaxed {
        /// Cone steps.
        cone: u32,
        /// Binary steps.
        binary: u32,
        /// Which bracket the bisection refines.
        search: BinarySearch,
    },
}

impl Method {
    /// Texture fetches the method spends on every ray.
    pub fn fetches(&self) -> u32 {
        match *self {
            Method::Linear { linear, binary } => linear + binary,
            Method::ConeStep { steps } => steps,
            Method::Relaxed { cone, binary, .. } => cone + binary,
        }
    }

    fn check(&self) -> Result<(), ReliefError> {
        let (a, b) = match *self {
            Method::Linear { linear, binary } => (linear, binary),
            Method::ConeStep { steps } => (steps, 0),
            Method::Relaxed { cone, binary, .. } => (cone, binary),
        };
        crate::check_range("steps", f64::from(a), 1.0, f64::from(MAX_STEPS))?;
        crate::check_range("binary steps", f64::from(b), 0.0, f64::from(MAX_STEPS))
    }

    /// Traces `ray` through `texture`.
    ///
    /// # Errors
    ///
    /// [`ReliefError::RayDirection`] for a ray that does not point into the relief;
    /// [`ReliefError::OutOfRange`] for a step count of 0 (linear or cone) or above
    /// [`MAX_STEPS`].
    pub fn trace(&self, texture: &ReliefTexture, ray: &Ray) -> Result<Hit, ReliefError> {
        self.check()?;
        let (dx, dy, ratio) = ray.scaled()?;
        let s = [ray.start.x, ray.start.y];
        Ok(match *self {
            Method::Linear { linear, binary } => linear_search(texture, s, dx, dy, linear, binary),
            Method::ConeStep { steps } => cone_step(texture, s, dx, dy, ratio, steps),
            Method::Relaxed {
                cone,
                binary,
                search,
            } => relaxed(texture, s, dx, dy, ratio, cone, binary, search),
        })
    }
}

/// The distance along the ray (in depth units) to where it leaves the cone of ratio `cone`
/// standing on the surface `height` below it (Eq. 3): `d = cone·height/(ray_ratio + cone)`.
#[inline(always)]
pub fn cone_step_length(cone: f32, height: f32, ray_ratio: f32) -> f32 {
    let denom = ray_ratio + cone;
    // WGSL: select(height, cone * height / denom, denom > 0.0)
    if denom > 0.0 {
        cone * height / denom
    } else {
        height
    }
}

/// The step with the clearance `D` and the near cap `E` ([`crate::cone`]): the cone
/// `max(c, min(D/h, E))` is valid for a ray `h` above the surface, and since the step grows with
/// the ratio it is `max(step(c), min(step(D/h), step(E)))`, with `step(D/h) = D·h/(ρ·h + D)` —
/// no division by the height.
#[inline(always)]
pub fn step_length(texel: [f32; 4], height: f32, ray_ratio: f32) -> f32 {
    let [_, cone, clearance, near_cap] = texel;
    let a = cone_step_length(cone, height, ray_ratio);
    let denom = ray_ratio * height + clearance;
    // WGSL: select(height, clearance * height / denom, denom > 0.0)
    let b = if denom > 0.0 {
        clearance * height / denom
    } else {
        height
    };
    a.max(b.min(cone_step_length(near_cap, height, ray_ratio)))
}

/// Bisects `[lo, hi]` (`lo` outside, `hi` inside or the stop point) `steps` times and returns
/// the midpoint of the final bracket.
#[inline(always)]
fn bisect(t: &ReliefTexture, mut lo: [f32; 3], mut hi: [f32; 3], steps: u32) -> Vec3 {
    for _ in 0..steps {
        let mid = [
            (lo[0] + hi[0]) * 0.5,
            (lo[1] + hi[1]) * 0.5,
            (lo[2] + hi[2]) * 0.5,
        ];
        let [depth, ..] = t.fetch(mid[0], mid[1]);
        // WGSL: lo = select(lo, mid, outside); hi = select(mid, hi, outside)
        if mid[2] < depth {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Vec3::new(
        (lo[0] + hi[0]) * 0.5,
        (lo[1] + hi[1]) * 0.5,
        (lo[2] + hi[2]) * 0.5,
    )
}

fn linear_search(
    t: &ReliefTexture,
    s: [f32; 2],
    dx: f32,
    dy: f32,
    linear: u32,
    binary: u32,
) -> Hit {
    let size = 1.0 / linear as f32;
    let mut depth = 0.0f32;
    let mut fetches = 0;
    // The last step reaches depth 1, where every point is inside (depths are ≤ 1): the loop
    // always ends inside. A shader runs all steps and keeps the first hit; breaking out early
    // gives the same bracket.
    for i in 0..linear {
        depth = (i + 1) as f32 * size;
        let [d, ..] = t.fetch(s[0] + dx * depth, s[1] + dy * depth);
        fetches += 1;
        if depth >= d {
            break;
        }
    }
    let z0 = depth - size;
    let lo = [s[0] + dx * z0, s[1] + dy * z0, z0];
    let hi = [s[0] + dx * depth, s[1] + dy * depth, depth];
    Hit {
        pos: bisect(t, lo, hi, binary),
        fetches: fetches + binary,
    }
}

fn cone_step(t: &ReliefTexture, s: [f32; 2], dx: f32, dy: f32, ratio: f32, steps: u32) -> Hit {
    let mut p = [s[0], s[1], 0.0f32];
    for _ in 0..steps {
        let texel = t.fetch(p[0], p[1]);
        let height = (texel[0] - p[2]).clamp(0.0, 1.0);
        let d = step_length(texel, height, ratio);
        p = [p[0] + dx * d, p[1] + dy * d, p[2] + d];
    }
    Hit {
        pos: Vec3::from(p),
        fetches: steps,
    }
}

#[allow(clippy::too_many_arguments)]
fn relaxed(
    t: &ReliefTexture,
    s: [f32; 2],
    dx: f32,
    dy: f32,
    ratio: f32,
    cone_steps: u32,
    binary: u32,
    search: BinarySearch,
) -> Hit {
    let mut p = [s[0], s[1], 0.0f32];
    // The last position above the surface (J in Fig. 18-10).
    let mut last_out = p;
    for _ in 0..cone_steps {
        let texel = t.fetch(p[0], p[1]);
        // saturate(): 0 once the ray is inside, so it stays there (§18.4.2).
        let height = (texel[0] - p[2]).clamp(0.0, 1.0);
        let d = step_length(texel, height, ratio);
        // WGSL: last_out = select(last_out, p, height > 0.0)
        if height > 0.0 {
            last_out = p;
        }
        p = [p[0] + dx * d, p[1] + dy * d, p[2] + d];
    }
    if search == BinarySearch::Shared {
        return relaxed_shared(t, s, dx, dy, ratio, cone_steps + binary);
    }
    let pos = match search {
        BinarySearch::LastStep | BinarySearch::Shared => bisect(t, last_out, p, binary),
        BinarySearch::Book => {
            // Listing 18-3: bs_range = 0.5·ray_dir·pos.z; bs_position = ray_pos + bs_range.
            let mut range = [0.5 * dx * p[2], 0.5 * dy * p[2], 0.5 * p[2]];
            let mut b = [s[0] + range[0], s[1] + range[1], range[2]];
            for _ in 0..binary {
                let [depth, ..] = t.fetch(b[0], b[1]);
                range = [range[0] * 0.5, range[1] * 0.5, range[2] * 0.5];
                let sign = if b[2] < depth { 1.0 } else { -1.0 };
                b = [
                    b[0] + sign * range[0],
                    b[1] + sign * range[1],
                    b[2] + sign * range[2],
                ];
            }
            Vec3::from(b)
        }
    };
    Hit {
        pos,
        fetches: cone_steps + binary,
    }
}

/// [`BinarySearch::Shared`]: one loop of `total` fetches (WGSL: the same loop with `select`s on
/// `bracketed`).
fn relaxed_shared(t: &ReliefTexture, s: [f32; 2], dx: f32, dy: f32, ratio: f32, total: u32) -> Hit {
    let mut p = [s[0], s[1], 0.0f32];
    let mut lo = p;
    let mut hi = p;
    let mut bracketed = false;
    for k in 0..total {
        if bracketed {
            let mid = [
                (lo[0] + hi[0]) * 0.5,
                (lo[1] + hi[1]) * 0.5,
                (lo[2] + hi[2]) * 0.5,
            ];
            let [depth, ..] = t.fetch(mid[0], mid[1]);
            if mid[2] < depth {
                lo = mid;
            } else {
                hi = mid;
            }
        } else {
            let texel = t.fetch(p[0], p[1]);
            let height = (texel[0] - p[2]).clamp(0.0, 1.0);
            if height > 0.0 {
                lo = p;
                // The last fetch only checks where the previous step ended, so the answer is
                // either a bracket or a point known to be above the surface.
                if k + 1 < total {
                    let d = step_length(texel, height, ratio);
                    p = [p[0] + dx * d, p[1] + dy * d, p[2] + d];
                }
            } else {
                // Inside: [lo, p] holds the first hit (one crossing per valid step).
                hi = p;
                bracketed = true;
            }
        }
    }
    let pos = if bracketed {
        Vec3::new(
            (lo[0] + hi[0]) * 0.5,
            (lo[1] + hi[1]) * 0.5,
            (lo[2] + hi[2]) * 0.5,
        )
    } else {
        // Budget spent while stepping: the last point, known to be above the surface (cone step
        // mapping's answer).
        Vec3::from(p)
    };
    Hit {
        pos,
        fetches: total,
    }
}
