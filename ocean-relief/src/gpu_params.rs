//! The parameter blocks the GPU twins read, defined once here so that the WGSL uniforms
//! (ocean-gpu's `relief_common.wgsl` and `relief_cone.wgsl`), the CPU tracers and a C header share
//! one layout.
//!
//! - [`ReliefUniforms`]: the tracer's settings ([`crate::trace::Method`] as codes, the relief
//!   texture's size and edge mode, depth scale, shadow bias) and the scene of the relief-mapped
//!   quad (camera, quad, light, material). The tracer fields alone drive ocean-gpu's probe.
//! - [`ConeGenUniforms`]: what the cone-map generator's passes need ([`crate::ConeMap::generate`]'s
//!   grid, pyramid and cap, and the quadrant of a [`crate::QuadConeMap`] layer).
//!
//! Both are `#[repr(C)]`, every member 4 bytes, grouped in 16-byte rows with explicit padding:
//! the same under std140 (uniform buffers) and std430, and with no implicit padding (`Pod`).
//! The GPU cannot return errors, so everything is checked on the host before an upload
//! ([`ReliefUniforms::set_method`], [`ConeGenUniforms::new`]).

use bytemuck::{Pod, Zeroable};

use crate::bound::ConeKind;
use crate::cone::{ConeParams, MAX_RATIO_LIMIT};
use crate::map::Edge;
use crate::quadrant::Quadrant;
use crate::trace::{BinarySearch, MAX_STEPS, Method};
use crate::{ReliefError, check_range};

/// [`ReliefUniforms::trace`]`[1]` for [`Edge::Wrap`].
pub const EDGE_WRAP: u32 = 0;
/// [`ReliefUniforms::trace`]`[1]` for [`Edge::Clamp`].
pub const EDGE_CLAMP: u32 = 1;

/// [`ReliefUniforms::trace`]`[2]` for [`Method::Linear`].
pub const METHOD_LINEAR: u32 = 0;
/// [`ReliefUniforms::trace`]`[2]` for [`Method::ConeStep`].
pub const METHOD_CONE_STEP: u32 = 1;
/// [`ReliefUniforms::trace`]`[2]` for [`Method::Relaxed`].
pub const METHOD_RELAXED: u32 = 2;

/// [`ReliefUniforms::trace`]`[3]` for [`BinarySearch::LastStep`].
pub const SEARCH_LAST_STEP: u32 = 0;
/// [`ReliefUniforms::trace`]`[3]` for [`BinarySearch::Book`].
pub const SEARCH_BOOK: u32 = 1;
/// [`ReliefUniforms::trace`]`[3]` for [`BinarySearch::Shared`].
pub const SEARCH_SHARED: u32 = 2;

/// [`ReliefUniforms::steps`]`[2]` bit: trace the light ray for self-shadowing.
pub const FLAG_SHADOWS: u32 = 1;
/// [`ReliefUniforms::steps`]`[2]` bit: the shader sRGB-encodes its colour (for a non-sRGB
/// target).
pub const FLAG_SRGB_ENCODE: u32 = 2;

/// The code of an [`Edge`].
pub fn edge_code(edge: Edge) -> u32 {
    match edge {
        Edge::Wrap => EDGE_WRAP,
        Edge::Clamp => EDGE_CLAMP,
    }
}

/// `[method, search, steps, binary]` of a [`Method`]: the step counts are the linear steps
/// (linear search), the cone steps (cone step mapping, relaxed) and the bisections.
pub fn method_codes(method: &Method) -> [u32; 4] {
    match *method {
        Method::Linear { linear, binary } => [METHOD_LINEAR, SEARCH_LAST_STEP, linear, binary],
        Method::ConeStep { steps } => [METHOD_CONE_STEP, SEARCH_LAST_STEP, steps, 0],
        Method::Relaxed {
            cone,
            binary,
            search,
        } => {
            let s = match search {
                BinarySearch::LastStep => SEARCH_LAST_STEP,
                BinarySearch::Book => SEARCH_BOOK,
                BinarySearch::Shared => SEARCH_SHARED,
            };
            [METHOD_RELAXED, s, cone, binary]
        }
    }
}

/// Everything the relief-mapping shaders read, byte for byte the WGSL `Relief` block of
/// ocean-gpu's `relief_common.wgsl` (448 bytes).
///
/// World positions are relative to the eye (camera-relative rendering: the host subtracts the
/// eye in `f64`). Tangent space is the tracers' ([`crate::trace`]): `x` along the texture's `u`,
/// `y` along `v`, `z` out of the polygon, `z = tangent × bitangent`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ReliefUniforms {
    /// Camera-relative world position → clip space in WebGPU's depth range `[0, 1]` (a camera
    /// with OpenGL's `[−1, 1]` is folded into it), column-major.
    pub view_proj: [[f32; 4]; 4],
    /// `xyz`: the quad corner at texture coordinates `(0, 0)`, relative to the eye; `w`: 0.
    pub quad_origin: [f32; 4],
    /// `xyz`: the quad's edge along `u` (world); `w`: texture widths across it.
    pub quad_u: [f32; 4],
    /// `xyz`: the quad's edge along `v` (world); `w`: texture widths across it.
    pub quad_v: [f32; 4],
    /// `xyz`: unit tangent (`u` direction, world); `w`: relief depth in texture widths (the
    /// tracers' `depth`, [`crate::trace::Ray::from_view`]).
    pub tangent: [f32; 4],
    /// `xyz`: unit bitangent (`v` direction, world); `w`: relief depth in world units.
    pub bitangent: [f32; 4],
    /// `xyz`: unit normal `tangent × bitangent` (out of the polygon, world); `w`: relief depth
    /// in texels (the normal map's `depth`, [`crate::relief::normals`]).
    pub normal: [f32; 4],
    /// `xyz`: the camera's unit forward direction (world); `w`: 1 for an orthographic camera
    /// (every viewing ray is parallel to it), 0 for a perspective one (rays from the eye).
    pub view_dir: [f32; 4],
    /// `xyz`: unit direction towards the light (world); `w`: its intensity.
    pub light: [f32; 4],
    /// `rgb`: albedo; `a`: ambient light (the share of the albedo lit without the light).
    pub albedo: [f32; 4],
    /// Texture side `N`, edge code ([`EDGE_WRAP`], [`EDGE_CLAMP`]), method code
    /// ([`METHOD_LINEAR`], …), binary search code ([`SEARCH_LAST_STEP`], …).
    pub trace: [u32; 4],
    /// Steps (linear steps, cone steps), binary steps, flags ([`FLAG_SHADOWS`],
    /// [`FLAG_SRGB_ENCODE`]), probe item count.
    pub steps: [u32; 4],
    /// Depth scale (texture widths, as `tangent.w`), shadow bias (depth units,
    /// [`crate::shadow::in_shadow`]), 0 (must stay 0: the shader xors its bits into
    /// intermediate results, an identity the compiler cannot see through, so it cannot fuse or
    /// reassociate the tracer's arithmetic), the texture's mip levels as a whole number (the
    /// levels [`crate::lod::mip_level`] chooses among; 0 reads as 1, level 0 only).
    pub shading: [f32; 4],
    /// The environment light on the relief's normal: nine order-2 spherical-harmonic rows
    /// (`rgb`; `a` unused) in world space, y up, in the basis order of ocean-brdf's
    /// `irradiance::sh_basis`. The shader adds `albedo × max(Σ rowᵢ Yᵢ(n), 0)` to the ambient
    /// term, `n` the relief normal in world space; all zero (the default) adds nothing. For a
    /// Lambertian surface under an environment of irradiance `E`, the rows of `E/π`.
    pub irradiance: [[f32; 4]; 9],
    /// `rgb`: the light's colour, multiplying `light.w` (white: `1, 1, 1`; all zero leaves
    /// the directional light black); `a`: unused.
    pub light_color: [f32; 4],
    /// The polygon drawn: four corners `(s, t)` in the plane of the quad, the point
    /// `quad_origin + s·quad_u + t·quad_v`, as `(s₀, t₀, s₁, t₁)` and `(s₂, t₂, s₃, t₃)`,
    /// counter-clockwise seen from the front, convex (a triangle repeats its last corner). The
    /// vertex stage draws the fan `(0, 1, 2)`, `(0, 2, 3)`; the whole quad is the unit square.
    pub polygon: [[f32; 4]; 2],
}

impl ReliefUniforms {
    /// Sets the texture fields: side and edge mode.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`] outside `2 ..= MAX_SIDE`.
    pub fn set_texture(&mut self, size: usize, edge: Edge) -> Result<(), ReliefError> {
        crate::map::check_size(size, size, 2, crate::MAX_SIDE)?;
        self.trace[0] = size as u32;
        self.trace[1] = edge_code(edge);
        Ok(())
    }

    /// Sets the method fields, with the checks [`Method::trace`] makes: at least one linear or
    /// cone step, at most [`MAX_STEPS`] per phase.
    ///
    /// # Errors
    ///
    /// [`ReliefError::OutOfRange`] for a step count out of range.
    pub fn set_method(&mut self, method: &Method) -> Result<(), ReliefError> {
        let [m, s, steps, binary] = method_codes(method);
        check_range("steps", f64::from(steps), 1.0, f64::from(MAX_STEPS))?;
        check_range("binary steps", f64::from(binary), 0.0, f64::from(MAX_STEPS))?;
        self.trace[2] = m;
        self.trace[3] = s;
        self.steps[0] = steps;
        self.steps[1] = binary;
        Ok(())
    }

    /// Sets the depth scale (texture widths, `≥ 0` and finite) and the shadow bias (depth units,
    /// in `[0, 1]`, as [`crate::shadow::in_shadow`] checks it).
    ///
    /// # Errors
    ///
    /// [`ReliefError::NotFinite`] / [`ReliefError::OutOfRange`].
    pub fn set_depth(&mut self, depth_scale: f32, shadow_bias: f32) -> Result<(), ReliefError> {
        check_range("depth scale", f64::from(depth_scale), 0.0, 1.0e6)?;
        check_range("bias", f64::from(shadow_bias), 0.0, 1.0)?;
        self.tangent[3] = depth_scale;
        self.shading[0] = depth_scale;
        self.shading[1] = shadow_bias;
        self.normal[3] = depth_scale * self.trace[0] as f32;
        Ok(())
    }

    /// Sets the number of mip levels the texture holds (`shading[3]`), after
    /// [`set_texture`](Self::set_texture): 1 ..= `log₂ N` for a power-of-two side `N`, 1
    /// otherwise ([`crate::lod`]).
    ///
    /// # Errors
    ///
    /// [`ReliefError::OutOfRange`] for a count outside that range.
    pub fn set_levels(&mut self, levels: usize) -> Result<(), ReliefError> {
        let most = crate::lod::max_levels(self.trace[0] as usize);
        check_range("mip levels", levels as f64, 1.0, most as f64)?;
        self.shading[3] = levels as f32;
        Ok(())
    }

    /// Sets or clears a flag bit of `steps[2]`.
    pub fn set_flag(&mut self, flag: u32, on: bool) {
        if on {
            self.steps[2] |= flag;
        } else {
            self.steps[2] &= !flag;
        }
    }
}

/// [`ConeGenUniforms::grid`]`[3]` for relaxed cones.
pub const KIND_RELAXED: u32 = 0;
/// [`ConeGenUniforms::grid`]`[3]` for conservative cones.
pub const KIND_CONSERVATIVE: u32 = 1;

/// [`ConeGenUniforms::sector`]`[0]` for cones that serve every direction.
pub const SECTOR_ALL: u32 = 0;

/// Most pyramid levels [`ConeGenUniforms`] describes (a pyramid of `2¹⁴` cells per side).
pub const MAX_LEVELS: usize = 16;

/// The cone-map generator's parameter block, byte for byte the WGSL `Gen` block of ocean-gpu's
/// `relief_cone.wgsl` (128 bytes): the grid of cells ([`crate::bound`]), the min-depth pyramid
/// over it, the cap ([`crate::cone`]) and the directions the cones serve ([`crate::quad`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ConeGenUniforms {
    /// Texels per side `N`, cells per side `nc` (`N` in wrap mode, `N + 1` in clamp mode),
    /// edge code, cone kind ([`KIND_RELAXED`], [`KIND_CONSERVATIVE`]).
    pub grid: [u32; 4],
    /// Pyramid side `P` (`nc` rounded up to a power of two), pyramid levels (`log₂ P + 1`),
    /// the level a reduction pass writes, and 0: a value the shader cannot know in advance,
    /// which keeps the compiler from rewriting the error-free transformations of its
    /// double-`f32` arithmetic.
    pub pyramid: [u32; 4],
    /// Cap ([`ConeParams::max_ratio`], texture widths per unit depth), 0, 0, 0.
    pub cap: [f32; 4],
    /// [`SECTOR_ALL`] (isotropic cones) or `1 +` the [`Quadrant::index`] of the one closed
    /// quadrant the cones serve (a layer of a [`crate::QuadConeMap`]), 0, 0, 0.
    pub sector: [u32; 4],
    /// Offset (in nodes) of pyramid level `l ≥ 1` in the pyramid buffer, at `[l / 4][l % 4]`
    /// (level 0 is the cell buffer itself).
    pub level_offsets: [[u32; 4]; MAX_LEVELS / 4],
}

impl ConeGenUniforms {
    /// The block for a map of side `size` with edge mode `edge` and cones `params`; also
    /// returns the pyramid's total node count above level 0.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`] outside `2 ..= MAX_SIDE`; [`ReliefError::NotFinite`] /
    /// [`ReliefError::OutOfRange`] for a `max_ratio` outside `(0, MAX_RATIO_LIMIT]` (as
    /// [`crate::ConeMap::generate`]).
    pub fn new(size: usize, edge: Edge, params: ConeParams) -> Result<(Self, u64), ReliefError> {
        crate::map::check_size(size, size, 2, crate::MAX_SIDE)?;
        check_range(
            "max_ratio",
            f64::from(params.max_ratio),
            f64::MIN_POSITIVE,
            f64::from(MAX_RATIO_LIMIT),
        )?;
        if params.parts != 0 {
            return Err(ReliefError::Unsupported(
                "ConeParams::parts above 0 on the GPU, which bounds whole cells: \
                 use ConeParams::with_parts(0), or the CPU generator",
            ));
        }
        let nc = match edge {
            Edge::Wrap => size,
            Edge::Clamp => size + 1,
        };
        let p = nc.next_power_of_two();
        let levels = p.trailing_zeros() as usize + 1;
        let mut u = Self {
            grid: [
                size as u32,
                nc as u32,
                edge_code(edge),
                match params.kind {
                    ConeKind::Relaxed => KIND_RELAXED,
                    ConeKind::Conservative => KIND_CONSERVATIVE,
                },
            ],
            pyramid: [p as u32, levels as u32, 0, 0],
            cap: [params.max_ratio, 0.0, 0.0, 0.0],
            sector: [SECTOR_ALL, 0, 0, 0],
            level_offsets: [[0; 4]; MAX_LEVELS / 4],
        };
        let mut offset = 0u64;
        for l in 1..levels {
            u.level_offsets[l / 4][l % 4] = offset as u32;
            let side = (p >> l) as u64;
            offset += side * side;
        }
        Ok((u, offset))
    }

    /// The same block for the cones of every direction (`None`, [`SECTOR_ALL`]) or of one
    /// closed quadrant (`1 + q.index()`).
    pub fn with_sector(mut self, sector: Option<Quadrant>) -> Self {
        self.sector[0] = sector.map_or(SECTOR_ALL, |q| 1 + q.index() as u32);
        self
    }

    /// Side of pyramid level `level`.
    pub fn level_side(&self, level: u32) -> u32 {
        self.pyramid[0] >> level
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_whole_std140_rows() {
        assert_eq!(core::mem::size_of::<ReliefUniforms>(), 448);
        assert_eq!(core::mem::size_of::<ConeGenUniforms>(), 128);
    }

    #[test]
    fn pyramid_offsets_follow_the_levels() {
        // Clamp mode, 6 texels: 7 cells, pyramid side 8, levels 8, 4, 2, 1: levels 1.. hold
        // 16 + 4 + 1 nodes.
        let (u, nodes) =
            ConeGenUniforms::new(6, Edge::Clamp, ConeParams::relaxed(1.0).with_parts(0)).unwrap();
        assert_eq!(u.grid, [6, 7, EDGE_CLAMP, KIND_RELAXED]);
        assert_eq!(u.pyramid[..2], [8, 4]);
        assert_eq!(u.level_offsets[0], [0, 0, 16, 20]);
        assert_eq!(nodes, 21);
        assert_eq!(u.sector, [SECTOR_ALL, 0, 0, 0]);
        // The quadrant codes follow the layer order: 1 + x_neg + 2 y_neg.
        let codes = Quadrant::ALL.map(|q| u.with_sector(Some(q)).sector[0]);
        assert_eq!(codes, [1, 2, 3, 4]);
        assert_eq!(u.with_sector(None), u);
        assert!(ConeGenUniforms::new(6, Edge::Wrap, ConeParams::relaxed(f32::NAN)).is_err());
        assert!(
            ConeGenUniforms::new(1, Edge::Wrap, ConeParams::relaxed(1.0).with_parts(0)).is_err()
        );
    }

    #[test]
    fn method_checks_match_the_tracer() {
        let mut u = ReliefUniforms::default();
        assert!(u.set_method(&Method::ConeStep { steps: 0 }).is_err());
        assert!(
            u.set_method(&Method::Linear {
                linear: 4,
                binary: MAX_STEPS + 1
            })
            .is_err()
        );
        u.set_method(&Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::Book,
        })
        .unwrap();
        assert_eq!(
            (u.trace[2], u.trace[3], u.steps[0], u.steps[1]),
            (METHOD_RELAXED, SEARCH_BOOK, 15, 6)
        );
        assert!(u.set_depth(f32::NAN, 0.0).is_err());
        assert!(u.set_depth(0.1, -1.0).is_err());
    }
}
