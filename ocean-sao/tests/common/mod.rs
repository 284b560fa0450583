//! Helpers shared by the integration tests: cameras, rendering an analytic view, masks and the
//! snapshot format.
#![allow(dead_code)]

use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_sao::analytic::{AnalyticView, DepthFormat, NO_FACE, Raster};
use ocean_sao::{DepthSource, Sao, SaoParams, Stages, Viewport};

/// Near plane of every test camera (m).
pub const NEAR: f64 = 0.1;
/// Finite far plane of the test cameras (m).
pub const FAR: f64 = 100.0;

/// A 1-radian vertical field of view over a `w × h` input.
pub fn perspective(w: usize, h: usize, far: Far) -> Projection {
    Projection::Perspective {
        fov_y: 1.0,
        aspect: w as f64 / h as f64,
        near: NEAR,
        far,
    }
}

/// An orthographic box 6 m tall over a `w × h` input, depth 0.05 .. 40 m.
pub fn orthographic(w: usize, h: usize) -> Projection {
    let half_w = 3.0 * w as f64 / h as f64;
    Projection::Orthographic {
        left: -half_w,
        right: half_w,
        bottom: -3.0,
        top: 3.0,
        near: 0.05,
        far: 40.0,
    }
}

/// Every (projection name, projection) the accuracy tests sweep.
pub fn projections(w: usize, h: usize) -> Vec<(&'static str, Projection)> {
    vec![
        ("finite", perspective(w, h, Far::Finite(FAR))),
        ("infinite", perspective(w, h, Far::Infinite)),
        ("ortho", orthographic(w, h)),
    ]
}

/// Short name of a depth convention.
pub fn convention_name(c: DepthConvention) -> &'static str {
    if c == DepthConvention::ZERO_TO_ONE {
        "[0,1] fwd"
    } else if c == DepthConvention::ZERO_TO_ONE_REVERSED {
        "[0,1] rev"
    } else {
        "[-1,1] fwd"
    }
}

/// A view rendered with one camera set-up.
pub struct Render {
    pub view: AnalyticView,
    pub camera: Camera,
    pub source: DepthSource,
    pub raster: Raster,
    pub viewport: Viewport,
}

impl Render {
    pub fn new(
        view: AnalyticView,
        projection: Projection,
        convention: DepthConvention,
        source: DepthSource,
        format: DepthFormat,
        (w, h, guard): (usize, usize, usize),
    ) -> Self {
        let camera = view.camera(projection, convention).unwrap();
        let raster = view.scene.rasterise(&camera, w, h, source, format).unwrap();
        Self {
            view,
            camera,
            source,
            raster,
            viewport: Viewport::new(w, h, guard).unwrap(),
        }
    }

    /// The default test render: reversed-Z `[0, 1]`, infinite far, `f32` depth.
    pub fn standard(view: AnalyticView, size: (usize, usize, usize)) -> Self {
        Self::new(
            view,
            perspective(size.0, size.1, Far::Infinite),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            DepthSource::Window,
            DepthFormat::F32,
            size,
        )
    }

    pub fn sao(&self, params: SaoParams) -> Sao {
        Sao::from_camera(&self.camera, self.source, self.viewport, params).unwrap()
    }

    pub fn stages(&self, params: SaoParams) -> Stages {
        self.sao(params).stages(&self.raster.depth).unwrap()
    }

    /// Input index of output pixel `i`.
    pub fn input_index(&self, i: usize) -> usize {
        let ow = self.viewport.output_width();
        let g = self.viewport.guard();
        (i / ow + g) * self.viewport.input_width() + i % ow + g
    }

    /// Whether output pixel `i` shows geometry (not background).
    pub fn is_geometry(&self, i: usize) -> bool {
        self.raster.face[self.input_index(i)] != NO_FACE
    }

    /// World-space point of output pixel `i` (exact).
    pub fn world_point(&self, i: usize) -> glam::DVec3 {
        self.camera
            .view_f64()
            .inverse()
            .transform_point3(self.raster.view_position[self.input_index(i)])
    }
}

/// The snapshot format: the image averaged over 2×2 blocks, quantised to u8 and written as two
/// hex digits per block, one line per block row.
pub fn hex_grid(img: &[f32], w: usize) -> String {
    let h = img.len() / w;
    let mut out = String::new();
    for by in 0..h / 2 {
        for bx in 0..w / 2 {
            let mut s = 0.0f32;
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                s += img[(2 * by + dy) * w + 2 * bx + dx];
            }
            out += &format!("{:02x}", ocean_sao::pack::quantise_ao(s * 0.25));
        }
        out.push('\n');
    }
    out
}
