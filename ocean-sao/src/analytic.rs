//! Analytic test scenes (rectangles, boxes, rooms, spheres) and an exact CPU rasteriser that
//! produces the depth buffers the passes read, with the exact view-space z, normals and face ids
//! the accuracy tests compare against.
//!
//! Rasterising casts one ray per pixel centre through the camera (in `f64`), so every pixel's
//! visible point is exact. Its depth value is then produced the way a GPU produces it: the
//! view-space point is rounded to `f32` and multiplied by the `f32` projection matrix in `f32`
//! (`z_clip` and `w_clip` as 4-term dot products in column order), divided, mapped to the window
//! range (`0.5·ndc + 0.5` for a `[−1, 1]` convention read as [`DepthSource::Window`]), clamped
//! to the range and stored as `f32` or as 24-bit fixed point (`round(d·(2²⁴ − 1))`, read back as
//! `q/(2²⁴ − 1)`). This is the pipeline error the paper's §2.1 and Fig. 3 discuss.

use alloc::vec;
use alloc::vec::Vec;

use glam::{DMat4, DVec3, Mat4, Vec4};
use ocean_core::{Camera, DepthRange, Projection};

use crate::reconstruct::{DepthSource, ZConstants};
use crate::viewport::Viewport;
use crate::{SaoError, for_rows};

/// Face id of background pixels.
pub const NO_FACE: u32 = u32::MAX;

/// A two-sided rectangle `centre + a·u + b·v`, `|a|, |b| ≤ 1` (`u ⟂ v`).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Rect {
    centre: DVec3,
    u: DVec3,
    v: DVec3,
    normal: DVec3,
    face: u32,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Sphere {
    centre: DVec3,
    radius: f64,
    face: u32,
}

/// A ray hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter (distance along the unit direction).
    pub t: f64,
    /// World-space point.
    pub point: DVec3,
    /// Unit world-space normal, facing the ray's origin.
    pub normal: DVec3,
    /// Face id: one per rectangle and per sphere, in the order they were added.
    pub face: u32,
}

/// A scene of rectangles and spheres in world space (metres, y up).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    rects: Vec<Rect>,
    spheres: Vec<Sphere>,
    faces: u32,
}

impl Scene {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds the rectangle `centre + a·half_u + b·half_v` for `|a|, |b| ≤ 1`; `half_u` and
    /// `half_v` must be orthogonal and non-zero. Returns its face id.
    pub fn add_rect(&mut self, centre: DVec3, half_u: DVec3, half_v: DVec3) -> u32 {
        let face = self.faces;
        self.faces += 1;
        self.rects.push(Rect {
            centre,
            u: half_u,
            v: half_v,
            normal: half_u.cross(half_v).normalize(),
            face,
        });
        face
    }

    /// Adds the six faces of the axis-aligned box `[min, max]`. The faces are two-sided, so the
    /// same call makes a solid box seen from outside or a room seen from inside. Returns the
    /// first face id (`−x, +x, −y, +y, −z, +z` follow in order).
    pub fn add_box(&mut self, min: DVec3, max: DVec3) -> u32 {
        let c = 0.5 * (min + max);
        let h = 0.5 * (max - min);
        let (x, y, z) = (DVec3::X * h.x, DVec3::Y * h.y, DVec3::Z * h.z);
        let first = self.add_rect(c - x, y, z);
        self.add_rect(c + x, y, z);
        self.add_rect(c - y, z, x);
        self.add_rect(c + y, z, x);
        self.add_rect(c - z, x, y);
        self.add_rect(c + z, x, y);
        first
    }

    /// Adds a sphere. Returns its face id.
    pub fn add_sphere(&mut self, centre: DVec3, radius: f64) -> u32 {
        let face = self.faces;
        self.faces += 1;
        self.spheres.push(Sphere {
            centre,
            radius,
            face,
        });
        face
    }

    /// Whether face `face` is a sphere (curved: Eq. 4's face normal is only its tangent plane).
    pub fn is_sphere(&self, face: u32) -> bool {
        self.spheres.iter().any(|s| s.face == face)
    }

    /// The nearest hit with `t_min < t < t_max` along the unit direction `dir`.
    pub fn trace(&self, origin: DVec3, dir: DVec3, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_best = t_max;
        for r in &self.rects {
            let den = r.normal.dot(dir);
            if den == 0.0 {
                continue;
            }
            let t = r.normal.dot(r.centre - origin) / den;
            if !(t > t_min && t < t_best) {
                continue;
            }
            let p = origin + t * dir;
            let q = p - r.centre;
            // A relative tolerance of 10⁻⁹ closes the cracks where the faces of a box meet.
            let (uu, vv) = (r.u.length_squared(), r.v.length_squared());
            if q.dot(r.u).abs() <= uu * (1.0 + 1e-9) && q.dot(r.v).abs() <= vv * (1.0 + 1e-9) {
                t_best = t;
                let normal = if den > 0.0 { -r.normal } else { r.normal };
                best = Some(Hit {
                    t,
                    point: p,
                    normal,
                    face: r.face,
                });
            }
        }
        for s in &self.spheres {
            let oc = origin - s.centre;
            let b = oc.dot(dir);
            let c = oc.length_squared() - s.radius * s.radius;
            let disc = b * b - c;
            if disc < 0.0 {
                continue;
            }
            let sq = ocean_core::math::sqrt(disc);
            for t in [-b - sq, -b + sq] {
                if t > t_min && t < t_best {
                    t_best = t;
                    let p = origin + t * dir;
                    let mut normal = (p - s.centre) / s.radius;
                    if normal.dot(dir) > 0.0 {
                        normal = -normal;
                    }
                    best = Some(Hit {
                        t,
                        point: p,
                        normal,
                        face: s.face,
                    });
                    break;
                }
            }
        }
        best
    }

    /// Renders `camera`'s view of the scene into a `width × height` image (row 0 at the top).
    ///
    /// # Errors
    ///
    /// [`SaoError::ImageSize`]; the camera's errors; [`SaoError::UnsupportedFormat`] for 24-bit
    /// depth with [`DepthSource::Ndc`] and a `[−1, 1]` range (fixed point holds window depth).
    pub fn rasterise(
        &self,
        camera: &Camera,
        width: usize,
        height: usize,
        source: DepthSource,
        format: DepthFormat,
    ) -> Result<Raster, SaoError> {
        let viewport = Viewport::new(width, height, 0)?;
        if format == DepthFormat::Unorm24
            && source == DepthSource::Ndc
            && camera.depth().range() == DepthRange::NegOneToOne
        {
            return Err(SaoError::UnsupportedFormat(
                "24-bit fixed point holds window depth in [0, 1]",
            ));
        }
        let rays = CameraRays::new(camera, viewport.input_width(), viewport.input_height())?;
        let zc = ZConstants::from_camera(camera, source)?;
        let (dmin, dmax) = zc.depth_range();
        let window =
            source == DepthSource::Window && camera.depth().range() == DepthRange::NegOneToOne;
        let p32 = camera.projection_matrix()?;
        let n = width * height;
        let mut pixels = vec![RasterPixel::SKY; n];
        for_rows(&mut pixels, width, |y, row| {
            for (x, px) in row.iter_mut().enumerate() {
                let Some(hit) = rays.trace(self, x as f64 + 0.5, y as f64 + 0.5) else {
                    *px = RasterPixel {
                        depth: zc.far_depth,
                        ..RasterPixel::SKY
                    };
                    continue;
                };
                let pv = rays.to_view(hit.point);
                let d = gpu_depth(&p32, pv, window).max(dmin).min(dmax);
                let d = match format {
                    DepthFormat::F32 => d,
                    DepthFormat::Unorm24 => {
                        const MAX: f64 = 16_777_215.0;
                        let q = (f64::from(d) * MAX + 0.5) as u32;
                        (f64::from(q) / MAX) as f32
                    }
                };
                *px = RasterPixel {
                    depth: d,
                    view: pv,
                    normal: rays.dir_to_view(hit.normal),
                    face: hit.face,
                };
            }
        });
        Ok(Raster {
            width,
            height,
            depth: pixels.iter().map(|p| p.depth).collect(),
            view_position: pixels.iter().map(|p| p.view).collect(),
            view_normal: pixels.iter().map(|p| p.normal).collect(),
            face: pixels.iter().map(|p| p.face).collect(),
        })
    }
}

#[derive(Clone, Copy, Debug)]
struct RasterPixel {
    depth: f32,
    view: DVec3,
    normal: DVec3,
    face: u32,
}

impl RasterPixel {
    const SKY: Self = Self {
        depth: 0.0,
        view: DVec3::new(0.0, 0.0, f64::NEG_INFINITY),
        normal: DVec3::ZERO,
        face: NO_FACE,
    };
}

/// NDC (or window) depth of a view-space point as the GPU computes it in `f32`.
fn gpu_depth(p: &Mat4, pv: DVec3, window: bool) -> f32 {
    let v = Vec4::new(pv.x as f32, pv.y as f32, pv.z as f32, 1.0);
    let row = |r: usize| {
        let (a, b, c, d) = (p.x_axis[r], p.y_axis[r], p.z_axis[r], p.w_axis[r]);
        ((a * v.x + b * v.y) + c * v.z) + d * v.w
    };
    let ndc = row(2) / row(3);
    if window { ndc * 0.5 + 0.5 } else { ndc }
}

/// How the rasteriser stores depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthFormat {
    /// 32-bit float (`Depth32Float`).
    F32,
    /// 24-bit fixed point (`Depth24Plus` on most hardware, `GL_DEPTH_COMPONENT24`).
    Unorm24,
}

/// A rasterised image with its exact per-pixel data.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    /// Width.
    pub width: usize,
    /// Height.
    pub height: usize,
    /// The depth buffer (what the passes read).
    pub depth: Vec<f32>,
    /// Exact view-space position of each pixel's visible point (`z = −∞` for background).
    pub view_position: Vec<DVec3>,
    /// Exact unit view-space normal facing the camera (zero for background).
    pub view_normal: Vec<DVec3>,
    /// Face id ([`NO_FACE`] for background).
    pub face: Vec<u32>,
}

/// Rays through continuous pixel positions of a camera, for an image of a given size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraRays {
    view: DMat4,
    inv_view: DMat4,
    proj: DMat4,
    perspective: bool,
    near: f64,
    far: f64,
    width: f64,
    height: f64,
}

/// A world-space ray segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin.
    pub origin: DVec3,
    /// Unit direction.
    pub dir: DVec3,
    /// Start (the near plane).
    pub t_min: f64,
    /// End (the far plane, or `∞`).
    pub t_max: f64,
}

impl CameraRays {
    /// Rays of `camera` over a `width × height` image.
    ///
    /// # Errors
    ///
    /// [`SaoError::Camera`] when the view matrix cannot be inverted.
    pub fn new(camera: &Camera, width: usize, height: usize) -> Result<Self, SaoError> {
        let view = camera.view_f64();
        let inv_view = view
            .try_inverse()
            .ok_or(SaoError::Camera(ocean_core::CameraError::Singular))?;
        let projection = camera.projection();
        let far = match projection.far() {
            ocean_core::Far::Finite(f) => f,
            ocean_core::Far::Infinite => f64::INFINITY,
        };
        Ok(Self {
            view,
            inv_view,
            proj: camera.projection_f64(),
            perspective: matches!(projection, Projection::Perspective { .. }),
            near: projection.near(),
            far,
            width: width as f64,
            height: height as f64,
        })
    }

    /// The ray through continuous pixel position `(px, py)` (pixel `(x, y)`'s centre is
    /// `(x + ½, y + ½)`; rows from the top), clipped to the near and far planes.
    pub fn ray(&self, px: f64, py: f64) -> Ray {
        let ndc_x = 2.0 * px / self.width - 1.0;
        let ndc_y = 1.0 - 2.0 * py / self.height;
        let p = &self.proj;
        let (origin_v, dir_v, scale) = if self.perspective {
            // x = −z (ndc_x + P₀₂)/P₀₀ at z = −1.
            let d = DVec3::new(
                (ndc_x + p.z_axis.x) / p.x_axis.x,
                (ndc_y + p.z_axis.y) / p.y_axis.y,
                -1.0,
            );
            let len = d.length();
            (DVec3::ZERO, d / len, len)
        } else {
            let o = DVec3::new(
                (ndc_x - p.w_axis.x) / p.x_axis.x,
                (ndc_y - p.w_axis.y) / p.y_axis.y,
                0.0,
            );
            (o, DVec3::NEG_Z, 1.0)
        };
        // Depth along the view axis is t/scale.
        Ray {
            origin: self.inv_view.transform_point3(origin_v),
            dir: self.inv_view.transform_vector3(dir_v).normalize(),
            t_min: self.near * scale,
            t_max: self.far * scale,
        }
    }

    /// The visible hit through `(px, py)`.
    pub fn trace(&self, scene: &Scene, px: f64, py: f64) -> Option<Hit> {
        let r = self.ray(px, py);
        scene.trace(r.origin, r.dir, r.t_min, r.t_max)
    }

    /// World → view space (a point).
    pub fn to_view(&self, p: DVec3) -> DVec3 {
        self.view.transform_point3(p)
    }

    /// World → view space (a direction of a rigid view).
    pub fn dir_to_view(&self, d: DVec3) -> DVec3 {
        self.view.transform_vector3(d)
    }

    /// Eq. 5's `S'` in `f64`: `h·P₁₁/2`.
    pub fn pixels_per_metre(&self) -> f64 {
        0.5 * self.height * self.proj.y_axis.y
    }

    /// Whether the camera is a perspective.
    pub fn is_perspective(&self) -> bool {
        self.perspective
    }
}

/// A named analytic scene with a camera placement (eye, target; y up).
#[derive(Clone, Debug, PartialEq)]
pub struct AnalyticView {
    /// Name (for reports and snapshot files).
    pub name: &'static str,
    /// The scene.
    pub scene: Scene,
    /// Camera position.
    pub eye: DVec3,
    /// Point looked at.
    pub target: DVec3,
}

impl AnalyticView {
    /// A flat floor 2 km wide (y = 0) seen from eye height, looking down 30° or so: nothing in
    /// it can occlude anything.
    pub fn open_plane() -> Self {
        let mut scene = Scene::new();
        scene.add_rect(DVec3::ZERO, DVec3::X * 1000.0, DVec3::Z * 1000.0);
        Self {
            name: "open_plane",
            scene,
            eye: DVec3::new(0.0, 1.6, 0.0),
            target: DVec3::new(0.3, 0.0, -3.0),
        }
    }

    /// A 90° crease: the floor y = 0 meets the wall z = −4 along the line y = 0, z = −4; the
    /// camera looks at it from 4 m away, so the crease is a horizontal line across the image.
    pub fn crease() -> Self {
        let mut scene = Scene::new();
        scene.add_rect(DVec3::new(0.0, 0.0, 21.0), DVec3::X * 50.0, DVec3::Z * 25.0);
        scene.add_rect(
            DVec3::new(0.0, 25.0, -4.0),
            DVec3::X * 50.0,
            DVec3::Y * 25.0,
        );
        Self {
            name: "crease",
            scene,
            eye: DVec3::new(0.0, 1.6, 0.5),
            target: DVec3::new(0.0, 0.3, -4.0),
        }
    }

    /// A 1 m box on the floor of an 8 × 3 × 9 m room, seen from eye height near the back wall.
    /// Face ids: room 0–5 (`−x, +x, floor, ceiling, far wall, back wall`), box 6–11.
    pub fn box_in_room() -> Self {
        let mut scene = Scene::new();
        scene.add_box(DVec3::new(-4.0, 0.0, -7.0), DVec3::new(4.0, 3.0, 2.0));
        scene.add_box(DVec3::new(-0.2, 0.0, -3.6), DVec3::new(0.8, 1.0, -2.6));
        Self {
            name: "box_in_room",
            scene,
            eye: DVec3::new(-1.2, 1.7, 1.2),
            target: DVec3::new(0.3, 0.4, -3.1),
        }
    }

    /// Three spheres (radii 0.3, 0.5 and 0.8 m) resting on the floor in front of a wall.
    pub fn spheres() -> Self {
        let mut scene = Scene::new();
        scene.add_rect(DVec3::new(0.0, 0.0, 0.0), DVec3::X * 50.0, DVec3::Z * 10.0);
        scene.add_rect(
            DVec3::new(0.0, 10.0, -6.0),
            DVec3::X * 50.0,
            DVec3::Y * 10.0,
        );
        scene.add_sphere(DVec3::new(-1.3, 0.3, -3.5), 0.3);
        scene.add_sphere(DVec3::new(0.0, 0.5, -4.5), 0.5);
        scene.add_sphere(DVec3::new(1.6, 0.8, -5.0), 0.8);
        Self {
            name: "spheres",
            scene,
            eye: DVec3::new(0.0, 1.5, 0.5),
            target: DVec3::new(0.0, 0.4, -4.5),
        }
    }

    /// Three boxes on a floor (1 m cubes at the origin and at (1.7, −1.1), a 1 × 0.6 × 1.4 m
    /// block at (−1.9, −0.5)), seen from `elevation` above the horizon and `azimuth` around the
    /// vertical (radians; azimuth 0 looks down −z), `distance` metres from (0, 0.4, 0): faces
    /// at every angle to the view, contact creases and silhouettes against the floor.
    pub fn boxes(elevation: f64, azimuth: f64, distance: f64) -> Self {
        let mut scene = Scene::new();
        scene.add_rect(DVec3::ZERO, DVec3::X * 50.0, DVec3::Z * 50.0);
        scene.add_box(DVec3::new(-0.5, 0.0, -0.5), DVec3::new(0.5, 1.0, 0.5));
        scene.add_box(DVec3::new(1.2, 0.0, -1.6), DVec3::new(2.2, 1.0, -0.6));
        scene.add_box(DVec3::new(-2.4, 0.0, -1.2), DVec3::new(-1.4, 0.6, 0.2));
        let (se, ce) = (libm::sin(elevation), libm::cos(elevation));
        let (sa, ca) = (libm::sin(azimuth), libm::cos(azimuth));
        let target = DVec3::new(0.0, 0.4, 0.0);
        Self {
            name: "boxes",
            scene,
            eye: target + distance * DVec3::new(ce * sa, se, ce * ca),
            target,
        }
    }

    /// Every view, in a fixed order.
    pub fn all() -> Vec<Self> {
        vec![
            Self::open_plane(),
            Self::crease(),
            Self::box_in_room(),
            Self::spheres(),
        ]
    }

    /// The camera at this view's eye and target.
    ///
    /// # Errors
    ///
    /// As [`Camera::look_at`].
    pub fn camera(
        &self,
        projection: Projection,
        convention: ocean_core::DepthConvention,
    ) -> Result<Camera, SaoError> {
        Ok(Camera::look_at(
            self.eye,
            self.target,
            DVec3::Y,
            projection,
            convention,
        )?)
    }
}

/// A perspective over an `out` output plus a guard band of `guard` px on every side, with the
/// output's vertical field of view `fov_y` for every guard band: the input's field of view grows
/// with it, so output pixel `(x, y)` sees the same ray whatever the guard band (up to
/// rounding). For guard-band studies.
pub fn guarded_perspective(out: (usize, usize), guard: usize, fov_y: f64) -> Projection {
    let (w, h) = (out.0 + 2 * guard, out.1 + 2 * guard);
    Projection::Perspective {
        fov_y: 2.0 * libm::atan(libm::tan(0.5 * fov_y) * h as f64 / out.1 as f64),
        aspect: w as f64 / h as f64,
        near: 0.1,
        far: ocean_core::Far::Infinite,
    }
}

/// The largest absolute difference between `interior(g)` and `interior(a)` for every guard
/// band `g` in `0..=max`, `a` the multiple of `align` at or below `g`, and the `g` it occurs
/// at (the first on ties; `(0, 0)` when all agree).
pub fn worst_against_aligned(
    max: usize,
    align: usize,
    mut interior: impl FnMut(usize) -> Vec<f32>,
) -> (f32, usize) {
    let aligned: Vec<Vec<f32>> = (0..=max / align).map(|k| interior(align * k)).collect();
    let mut worst = (0.0f32, 0);
    for g in 0..=max {
        let d = interior(g)
            .iter()
            .zip(&aligned[g / align])
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f32, f32::max);
        if d > worst.0 {
            worst = (d, g);
        }
    }
    worst
}
