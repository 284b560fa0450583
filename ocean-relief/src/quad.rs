//! Quad-directional cone maps (§18.1: "four different radii for each fragment (in the directions
//! north, south, east, and west)", QDCSM; Fig. 18-8b stores "cone ratios for the four major
//! directions into separate texture channels"), here relaxed as well as conservative, and with the
//! same guarantee as the isotropic maps of [`crate::cone`].
//!
//! ## Definition
//!
//! A ray's horizontal direction `u = dir.xy` never changes along it, so a cone only has to be
//! valid for the rays that can use it. Split the directions into the four **closed quadrants**
//! `Q = {u : sₓ·uₓ ≥ 0, s_y·u_y ≥ 0}` (`sₓ, s_y = ±1`, [`Quadrant`]) and give every texel one cone
//! per quadrant: Lemma 1 of [`crate::bound`] with `u` restricted to `Q`,
//! `c*_Q(p) = inf { s/(S(p) − M(s)) : u ∈ Q, g(s) > M(s), M(s) < S(p) }`. An isotropic cone is
//! limited by every peak around the apex; a quadrant cone only by the peaks ahead of the rays that
//! use it, which is what lets a grazing ray take long steps down the lee side of a hill (the book
//! notes QDCSM only "slightly" reduces conservative cone stepping's artifacts; relaxed quadrant
//! cones are measured in [`crate::accuracy`]).
//!
//! ## The cell bound still holds
//!
//! [`crate::bound`]'s theorem takes, for one `(u, s)`, the exit point `b = p + s_e·u`; with
//! `u ∈ Q`, the vector `b − p` lies in `Q`. So only the vectors of `W ∩ Q` matter (`W = C − q` the
//! box of vectors from the apex cell to the candidate), and because quadrants are axis-aligned
//! `W ∩ Q` is again a box (`Apex::vectors` in `bound.rs`): a cell is a candidate only if it is
//! non-empty, `A` uses its shortest vector instead of `dist(q, C)`, the falling test (condition 2,
//! the twist included) takes its vectors, and the near-cell rise takes its directions (the
//! quadrant's closed arc when it holds the origin). `B`'s path argument is unchanged. Each step of
//! the proof only shrinks the set it ranges over, so the theorem holds for `c*_Q`, and the
//! clearance `D` and near cap `E` of [`crate::cone`] follow as before. The branch-and-bound skips a
//! pyramid node whose clipped box is empty (none of its cells can be reached by a ray of the
//! quadrant); the brute force visits every cell with the same clipped expression, and the two
//! agree bit for bit. Mathematically every quadrant cone is at least the isotropic one (fewer
//! candidates, longer vectors, fewer directions).
//!
//! Texel `k` of each layer takes the minimum over its four cells ([`crate::cone`]), so each layer
//! is valid under the bilinear fetch; values are rounded down to `f32` and quantised rounding
//! down ([`crate::storage`]), layer by layer. Mip chains keep the isotropic 4×4-window rule
//! layer by layer ([`crate::mip::quad_chain`], whose module proves it for quadrant cones).
//!
//! ## Storage and the tracer (the GPU's arithmetic)
//!
//! Each layer is a full [`ConeMap`] (plain cone, clearance, near cap). The GPU layout is a
//! **4-layer texture array** whose layer `k` holds `[depth, c_k, D_k, E_k]`, the isotropic relief
//! texel of [`ReliefTexture`] with the quadrant's cones: the shader picks the layer once per ray,
//! `layer = select(0, 1, dir.x < 0) + select(0, 2, dir.y < 0)` on the scaled direction
//! ([`Quadrant::of`]), and every step is then the same single RGBA fetch and the same arithmetic
//! as the isotropic tracer ([`crate::trace`]); memory is four times the isotropic texture's,
//! bandwidth per step the same. The book's layout (one RGBA texel of the four plain ratios,
//! depth in a second texture, two fetches per step, no clearance or near cap) is
//! [`QuadConeMap::plain_rgba`]; [`QuadConeMap::plain`] is the cone map it holds. Normals stay in
//! their own texture ([`crate::relief::normals`]), as §18.2 recommends.

use alloc::vec::Vec;

use crate::cone::{ConeMap, ConeParams};
use crate::map::HeightMap;
use crate::progress::{BANDS, NoProgress, Progress};
pub use crate::quadrant::Quadrant;
use crate::relief::ReliefTexture;
use crate::storage::Encoding;
use crate::trace::{Hit, Method, Ray};
use crate::{ReliefError, check_range};
use glam::Vec3;

/// One [`ConeMap`] per quadrant, in [`Quadrant::index`] order (module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct QuadConeMap {
    layers: [ConeMap; 4],
}

impl QuadConeMap {
    /// Relaxed or conservative quadrant cones of `map` by branch-and-bound, the four layers in
    /// turn (rows in parallel with `std`; the same bits for any thread count).
    ///
    /// # Errors
    ///
    /// As [`ConeMap::generate`].
    pub fn generate(map: &HeightMap, params: ConeParams) -> Result<Self, ReliefError> {
        Self::each(|q| {
            ConeMap::generate_sector(map, params, Some(q), None::<&mut NoProgress>, BANDS)
        })
    }

    /// [`QuadConeMap::generate`] with progress reports and cancellation ([`crate::progress`]),
    /// under [`ConeMap::generate_with`]'s contract over the whole job: the unit of work is a
    /// row of bilinear cells of one layer, so `total` is `4 R` (`R = N` in wrap mode, `N + 1` in
    /// clamp mode); `progress` is called once with `done = 0`, then after each band (each layer
    /// in at most [`BANDS`]` / 4` bands, so at most `BANDS + 1` calls in all), the last call
    /// with `done = total`. The result is bit-identical to [`QuadConeMap::generate`]'s.
    ///
    /// # Errors
    ///
    /// As [`ConeMap::generate_with`].
    pub fn generate_with<P: Progress + ?Sized>(
        map: &HeightMap,
        params: ConeParams,
        progress: &mut P,
    ) -> Result<Self, ReliefError> {
        let mut layer = 0;
        Self::each(|q| {
            // Layer `k`'s reports shifted by `k R` of `4 R`; its opening `done = 0` repeats
            // the previous layer's last report and is not passed on.
            let first = layer == 0;
            let mut shifted = |done: usize, rows: usize| {
                if done == 0 && !first {
                    return true;
                }
                progress.report(layer * rows + done, 4 * rows)
            };
            let cones =
                ConeMap::generate_sector(map, params, Some(q), Some(&mut shifted), BANDS / 4);
            layer += 1;
            cones
        })
    }

    /// The same cones by visiting every pair of cells: the oracle of
    /// [`QuadConeMap::generate`], for maps up to [`crate::MAX_BRUTE_SIDE`].
    ///
    /// # Errors
    ///
    /// As [`ConeMap::brute_force`].
    pub fn brute_force(map: &HeightMap, params: ConeParams) -> Result<Self, ReliefError> {
        crate::map::check_size(map.size(), map.size(), 2, crate::MAX_BRUTE_SIDE)?;
        Self::each(|q| ConeMap::brute_force_sector(map, params, Some(q)))
    }

    fn each(
        mut f: impl FnMut(Quadrant) -> Result<ConeMap, ReliefError>,
    ) -> Result<Self, ReliefError> {
        let [a, b, c, d] = Quadrant::ALL;
        Ok(Self {
            layers: [f(a)?, f(b)?, f(c)?, f(d)?],
        })
    }

    /// Four layers, for example decoded from storage, in [`Quadrant::index`] order.
    ///
    /// # Errors
    ///
    /// [`ReliefError::Mismatch`] unless they share one size and edge mode.
    pub fn from_layers(layers: [ConeMap; 4]) -> Result<Self, ReliefError> {
        let (n, e) = (layers[0].size(), layers[0].edge());
        if layers.iter().any(|l| l.size() != n || l.edge() != e) {
            return Err(ReliefError::Mismatch("quadrant layers"));
        }
        Ok(Self { layers })
    }

    /// The cones of quadrant `q`.
    pub fn layer(&self, q: Quadrant) -> &ConeMap {
        &self.layers[q.index()]
    }

    /// The layers in [`Quadrant::index`] order.
    pub fn layers(&self) -> &[ConeMap; 4] {
        &self.layers
    }

    /// Side in texels.
    pub fn size(&self) -> usize {
        self.layers[0].size()
    }

    /// The plain cones alone (clearance and near cap 0): what the book's one-texel layout
    /// ([`QuadConeMap::plain_rgba`]) holds.
    ///
    /// # Errors
    ///
    /// None in practice (the ratios are checked again).
    pub fn plain(&self) -> Result<Self, ReliefError> {
        let mut out = Vec::with_capacity(4);
        for l in &self.layers {
            out.push(ConeMap::from_ratios(
                l.size(),
                l.edge(),
                l.ratios().to_vec(),
            )?);
        }
        let [a, b, c, d]: [ConeMap; 4] = out
            .try_into()
            .map_err(|_| ReliefError::Mismatch("quadrant layers"))?;
        Ok(Self {
            layers: [a, b, c, d],
        })
    }

    /// Per texel, row-major, the four plain ratios `[c₀, c₁, c₂, c₃]` in [`Quadrant::index`]
    /// order: one RGBA texel (Fig. 18-8b's layout; the depth then lives in a texture of its own).
    pub fn plain_rgba(&self) -> Vec<[f32; 4]> {
        let [a, b, c, d] = &self.layers;
        (0..a.ratios().len())
            .map(|k| [a.ratios()[k], b.ratios()[k], c.ratios()[k], d.ratios()[k]])
            .collect()
    }

    /// Every layer after a round trip through `encoding` ([`ConeMap::quantized`]): each value is
    /// at most the original.
    ///
    /// # Errors
    ///
    /// As [`ConeMap::quantized`].
    pub fn quantized(&self, encoding: Encoding) -> Result<Self, ReliefError> {
        let [a, b, c, d] = &self.layers;
        Ok(Self {
            layers: [
                a.quantized(encoding)?,
                b.quantized(encoding)?,
                c.quantized(encoding)?,
                d.quantized(encoding)?,
            ],
        })
    }
}

/// The texture array the quadrant tracer reads: per layer `[depth, c_k, D_k, E_k]` (module
/// documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct QuadReliefTexture {
    layers: [ReliefTexture; 4],
}

impl QuadReliefTexture {
    /// Pairs the depths of `map` with each layer of `cones`.
    ///
    /// # Errors
    ///
    /// [`ReliefError::Mismatch`] if the cone map has another size or edge mode.
    pub fn new(map: &HeightMap, cones: &QuadConeMap) -> Result<Self, ReliefError> {
        let [a, b, c, d] = &cones.layers;
        Ok(Self {
            layers: [
                ReliefTexture::new(map, a)?,
                ReliefTexture::new(map, b)?,
                ReliefTexture::new(map, c)?,
                ReliefTexture::new(map, d)?,
            ],
        })
    }

    /// Layer `q` (an isotropic relief texture holding quadrant `q`'s cones).
    pub fn layer(&self, q: Quadrant) -> &ReliefTexture {
        &self.layers[q.index()]
    }

    /// The layers in [`Quadrant::index`] order: layer `k` of the GPU's texture array.
    pub fn layers(&self) -> &[ReliefTexture; 4] {
        &self.layers
    }

    /// Side `N` of every layer, texels.
    pub fn size(&self) -> usize {
        self.layers[0].size()
    }

    /// The edge mode of every layer.
    pub fn edge(&self) -> crate::Edge {
        self.layers[0].edge()
    }

    /// The texture array's texels: layer 0's `N²` texels row-major, then layer 1's, 2's and
    /// 3's (the upload order of a 4-layer `rgba32float` array).
    pub fn texels(&self) -> Vec<[f32; 4]> {
        self.layers
            .iter()
            .flat_map(|l| l.texels().iter().copied())
            .collect()
    }

    /// The quadrant the tracer picks for `ray`: [`Quadrant::of`] its direction scaled to
    /// `z = 1`, in the tracer's `f32` arithmetic.
    ///
    /// # Errors
    ///
    /// [`ReliefError::RayDirection`] for a ray that does not point into the relief.
    pub fn quadrant(ray: &Ray) -> Result<Quadrant, ReliefError> {
        let z = ray.dir.z;
        check_range("ray direction z", f64::from(z), f64::MIN_POSITIVE, f64::MAX)
            .map_err(|_| ReliefError::RayDirection)?;
        Ok(Quadrant::of(ray.dir.x / z, ray.dir.y / z))
    }

    /// Traces `ray` with `method` through the layer of its quadrant: the tracer of
    /// [`crate::trace`] unchanged, on the cones valid for its direction. With a relaxed quadrant
    /// map use [`Method::Relaxed`]; with a conservative one [`Method::ConeStep`] is QDCSM
    /// (§18.1); [`Method::Linear`] reads the depth alone and gives the same hit on every layer.
    ///
    /// # Errors
    ///
    /// As [`Method::trace`].
    pub fn trace(&self, method: &Method, ray: &Ray) -> Result<Hit, ReliefError> {
        let q = Self::quadrant(ray)?;
        method.trace(self.layer(q), ray)
    }

    /// Self-shadowing through the quadrant layers ([`crate::shadow::in_shadow`], §18.2): the
    /// light ray towards `point` is traced by [`QuadReliefTexture::trace`], so it reads the
    /// layer of its own quadrant, not the viewing ray's.
    ///
    /// # Errors
    ///
    /// As [`crate::shadow::in_shadow`].
    pub fn in_shadow(
        &self,
        method: &Method,
        point: Vec3,
        light: Vec3,
        depth_scale: f32,
        bias: f32,
    ) -> Result<bool, ReliefError> {
        match crate::shadow::light_ray(point, light, depth_scale, bias)? {
            None => Ok(true),
            Some(ray) => Ok(self.trace(method, &ray)?.pos.z < point.z - bias),
        }
    }
}
