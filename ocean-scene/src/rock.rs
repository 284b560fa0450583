//! Low-poly rocks from noise: an icosphere whose vertices move along their directions by a
//! smooth 3D value noise, scaled to the rock's size and turned to its heading.
//!
//! The surface is star-shaped about the rock's centre (every vertex on its own ray, at a radius
//! between `1 − roughness` and `1 + roughness` of the unit sphere before scaling), so it never
//! intersects itself; the triangles are checked to face outwards, and a shape whose noise would
//! fold a triangle back is refused rather than returned. Triangles are counter-clockwise seen
//! from outside: a renderer that relief-maps them (`ocean_gpu::ReliefScene::on_polygon`)
//! carves the relief into the rock.
//!
//! Every vertex is computed from the parameters alone with `f64` arithmetic and ocean-core's
//! pure-Rust math, so a rock has the same bits on every platform.

use glam::DVec3;
use ocean_core::math;

use crate::SceneError;

/// Largest [`RockShape::detail`]: 5120 triangles.
pub const MAX_DETAIL: u32 = 4;
/// Largest [`RockShape::roughness`].
pub const MAX_ROUGHNESS: f64 = 0.5;

/// Lattice cells of the noise's first octave across the unit sphere's radius.
const NOISE_FREQUENCY: f64 = 1.3;
/// Octaves of the noise, each of twice the frequency and half the amplitude of the one before.
const NOISE_OCTAVES: u32 = 3;

/// The shape of a rock, before it is placed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RockShape {
    /// Extents along the rock's own `x` (across), `y` (up) and `z` (its heading) before the
    /// noise, metres (each `> 0`): the rock at rest is the ellipsoid of these diameters.
    pub size: DVec3,
    /// How far the noise moves a vertex along its direction, a fraction of the radius in
    /// `[0, MAX_ROUGHNESS]`.
    pub roughness: f64,
    /// Subdivisions of the icosahedron, `0..=MAX_DETAIL`: `20 × 4^detail` triangles.
    pub detail: u32,
    /// Seed of the noise.
    pub seed: u64,
}

impl Default for RockShape {
    /// A 6 × 4 × 5 m rock of 320 triangles (detail 2), roughness 0.3, seed 1.
    fn default() -> Self {
        Self {
            size: DVec3::new(6.0, 4.0, 5.0),
            roughness: 0.3,
            detail: 2,
            seed: 1,
        }
    }
}

/// A closed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RockMesh {
    /// Vertex positions, metres.
    pub positions: Vec<DVec3>,
    /// Vertex indices of each triangle, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

impl RockShape {
    /// The rock's mesh centred on the origin, its `y` up and its heading along `+z`.
    ///
    /// # Errors
    ///
    /// [`SceneError::Invalid`] for a size that is not finite and positive, a roughness outside
    /// `[0, MAX_ROUGHNESS]`, a detail above [`MAX_DETAIL`], or noise that folds a triangle
    /// back (measured never to happen within these bounds, see the tests).
    pub fn mesh(&self) -> Result<RockMesh, SceneError> {
        let s = self.size;
        if !(s.is_finite() && s.min_element() > 0.0) {
            return Err(SceneError::invalid(
                "rock size",
                format!("{s} must be finite and positive"),
            ));
        }
        if !(0.0..=MAX_ROUGHNESS).contains(&self.roughness) {
            return Err(SceneError::invalid(
                "rock roughness",
                format!("{} is outside [0, {MAX_ROUGHNESS}]", self.roughness),
            ));
        }
        if self.detail > MAX_DETAIL {
            return Err(SceneError::invalid(
                "rock detail",
                format!("{} is above {MAX_DETAIL}", self.detail),
            ));
        }
        let (directions, triangles) = icosphere(self.detail);
        let unit: Vec<DVec3> = directions
            .iter()
            .map(|&d| d * (1.0 + self.roughness * fbm(d * NOISE_FREQUENCY, self.seed)))
            .collect();
        // Star-shaped about the centre: a triangle faces outwards when the centre lies behind
        // its plane. A positive scaling keeps that, so it is checked before scaling.
        for t in &triangles {
            let [a, b, c] = t.map(|i| unit[i as usize]);
            if (b - a).cross(c - a).dot(a + b + c) <= 0.0 {
                return Err(SceneError::invalid(
                    "rock roughness",
                    format!(
                        "{} folds a triangle back at seed {}",
                        self.roughness, self.seed
                    ),
                ));
            }
        }
        Ok(RockMesh {
            positions: unit.iter().map(|&p| p * 0.5 * s).collect(),
            triangles,
        })
    }
}

impl RockMesh {
    /// The mesh turned `heading` radians about `+y` (from `+z` towards `+x`) and moved by
    /// `centre`.
    pub fn placed(&self, centre: DVec3, heading: f64) -> RockMesh {
        let (sin, cos) = (math::sin(heading), math::cos(heading));
        let turn = |p: DVec3| DVec3::new(p.x * cos + p.z * sin, p.y, -p.x * sin + p.z * cos);
        RockMesh {
            positions: self.positions.iter().map(|&p| centre + turn(p)).collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// Each triangle's three corners.
    pub fn faces(&self) -> impl Iterator<Item = [DVec3; 3]> + '_ {
        self.triangles
            .iter()
            .map(|t| t.map(|i| self.positions[i as usize]))
    }

    /// The enclosed volume (the divergence theorem over the triangles), cubic metres.
    pub fn volume(&self) -> f64 {
        self.faces().map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum()
    }

    /// The corners of the axis-aligned box around the mesh, lowest then highest
    /// (`[+∞, −∞]` for an empty mesh).
    pub fn bounds(&self) -> [DVec3; 2] {
        self.positions.iter().fold(
            [DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)],
            |[lo, hi], &p| [lo.min(p), hi.max(p)],
        )
    }

    /// The highest point of the mesh straight above or below world `(x, z)`, or `None` where
    /// the mesh does not cover it: the rock's top surface, for terrain that carries it.
    pub fn top_at(&self, x: f64, z: f64) -> Option<f64> {
        let mut top: Option<f64> = None;
        for [a, b, c] in self.faces() {
            // Barycentric coordinates in the xz plane.
            let det = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
            if det == 0.0 {
                continue;
            }
            let u = ((x - a.x) * (c.z - a.z) - (c.x - a.x) * (z - a.z)) / det;
            let v = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / det;
            if u >= 0.0 && v >= 0.0 && u + v <= 1.0 {
                let y = a.y + u * (b.y - a.y) + v * (c.y - a.y);
                top = Some(top.map_or(y, |t| t.max(y)));
            }
        }
        top
    }
}

/// The unit icosphere: the icosahedron's faces split `detail` times into four, every new
/// vertex pushed onto the sphere. Directions and counter-clockwise (outward) triangles.
fn icosphere(detail: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let phi = 0.5 * (1.0 + math::sqrt(5.0));
    let mut points: Vec<DVec3> = [
        (-1.0, phi, 0.0),
        (1.0, phi, 0.0),
        (-1.0, -phi, 0.0),
        (1.0, -phi, 0.0),
        (0.0, -1.0, phi),
        (0.0, 1.0, phi),
        (0.0, -1.0, -phi),
        (0.0, 1.0, -phi),
        (phi, 0.0, -1.0),
        (phi, 0.0, 1.0),
        (-phi, 0.0, -1.0),
        (-phi, 0.0, 1.0),
    ]
    .into_iter()
    .map(|(x, y, z)| DVec3::new(x, y, z).normalize())
    .collect();
    let mut triangles: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..detail {
        let mut midpoints = std::collections::BTreeMap::new();
        let mut midpoint = |a: u32, b: u32, points: &mut Vec<DVec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                points.push((points[a as usize] + points[b as usize]).normalize());
                (points.len() - 1) as u32
            })
        };
        let mut next = Vec::with_capacity(4 * triangles.len());
        for [a, b, c] in triangles {
            let ab = midpoint(a, b, &mut points);
            let bc = midpoint(b, c, &mut points);
            let ca = midpoint(c, a, &mut points);
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        triangles = next;
    }
    (points, triangles)
}

/// A lattice value in `[0, 1)`: the SplitMix64 finaliser of the point and the seed.
fn lattice(i: i64, j: i64, k: i64, seed: u64) -> f64 {
    let mut x = seed
        ^ (i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (j as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (k as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^= x >> 31;
    (x >> 11) as f64 / (1u64 << 53) as f64
}

fn smooth(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// Value noise at `p` in `[0, 1]`: the lattice values trilinearly blended with smoothstep
/// weights.
fn value_noise(p: DVec3, seed: u64) -> f64 {
    let f = p.floor();
    let (i, j, k) = (f.x as i64, f.y as i64, f.z as i64);
    let w = (p - f).to_array().map(smooth);
    let mut sum = 0.0;
    for (dk, wk) in [(0, 1.0 - w[2]), (1, w[2])] {
        for (dj, wj) in [(0, 1.0 - w[1]), (1, w[1])] {
            for (di, wi) in [(0, 1.0 - w[0]), (1, w[0])] {
                sum += wi * wj * wk * lattice(i + di, j + dj, k + dk, seed);
            }
        }
    }
    sum
}

/// Fractional Brownian motion of [`value_noise`] in `[−1, 1]`: [`NOISE_OCTAVES`] octaves.
fn fbm(p: DVec3, seed: u64) -> f64 {
    let (mut sum, mut amplitude, mut total, mut frequency) = (0.0, 1.0, 0.0, 1.0);
    for octave in 0..NOISE_OCTAVES {
        let n = value_noise(p * frequency, seed.wrapping_add(u64::from(octave)));
        sum += amplitude * (2.0 * n - 1.0);
        total += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    sum / total
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;

    /// Every directed edge appears once and its reverse once: the mesh is closed, two-manifold
    /// and consistently oriented.
    fn closed(mesh: &RockMesh) -> bool {
        let mut edges = BTreeMap::new();
        for t in &mesh.triangles {
            for e in 0..3 {
                *edges.entry((t[e], t[(e + 1) % 3])).or_insert(0) += 1;
            }
        }
        edges
            .iter()
            .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
    }

    #[test]
    fn the_icosphere_is_a_closed_outward_sphere() {
        for detail in 0..=MAX_DETAIL {
            let (p, t) = icosphere(detail);
            // Euler: V − E + F = 2 with E = 3F/2; F = 20·4^d.
            let f = 20 * 4usize.pow(detail);
            assert_eq!(t.len(), f);
            assert_eq!(p.len(), 2 + f / 2);
            let mesh = RockMesh {
                positions: p,
                triangles: t,
            };
            assert!(closed(&mesh), "detail {detail}");
            // Outward: positive volume, approaching the unit ball's 4π/3 from below.
            let v = mesh.volume();
            assert!(v > 0.0 && v < 4.0 / 3.0 * std::f64::consts::PI, "{v}");
        }
        let (p, t) = icosphere(4);
        let v = RockMesh {
            positions: p,
            triangles: t,
        }
        .volume();
        assert!(v > 0.99 * 4.0 / 3.0 * std::f64::consts::PI, "{v}");
    }

    /// Over 200 seeds at the largest roughness and every detail: closed, every triangle
    /// outward, every vertex within the roughness band of its ellipsoid.
    #[test]
    fn rocks_are_closed_outward_and_within_their_band() {
        for detail in 0..=MAX_DETAIL {
            for seed in 0..200 {
                let shape = RockShape {
                    size: DVec3::new(8.0, 3.0, 5.0),
                    roughness: MAX_ROUGHNESS,
                    detail,
                    seed,
                };
                let mesh = shape.mesh().unwrap();
                assert!(closed(&mesh));
                for p in &mesh.positions {
                    // The radius of the unscaled vertex.
                    let r = (*p / (0.5 * shape.size)).length();
                    assert!(
                        (1.0 - MAX_ROUGHNESS..=1.0 + MAX_ROUGHNESS).contains(&r),
                        "{r}"
                    );
                }
                for [a, b, c] in mesh.faces() {
                    let n = (b - a).cross(c - a);
                    assert!(n.dot(a + b + c) > 0.0, "seed {seed} detail {detail}");
                }
            }
        }
    }

    #[test]
    fn the_noise_makes_rocks_irregular_and_seeds_differ() {
        let shape = RockShape::default();
        let a = shape.mesh().unwrap();
        let b = RockShape { seed: 2, ..shape }.mesh().unwrap();
        assert_ne!(a, b);
        // Deterministic.
        assert_eq!(a, shape.mesh().unwrap());
        // Radii spread well beyond the icosphere's own (which are all 1).
        let radii: Vec<f64> = a
            .positions
            .iter()
            .map(|p| (*p / (0.5 * shape.size)).length())
            .collect();
        let (lo, hi) = radii
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), &r| (l.min(r), h.max(r)));
        assert!(hi - lo > 0.25, "radii {lo}..{hi}");
        // Roughness 0 is the ellipsoid's icosphere.
        let smooth = RockShape {
            roughness: 0.0,
            ..shape
        }
        .mesh()
        .unwrap();
        for p in &smooth.positions {
            assert!(((*p / (0.5 * shape.size)).length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn placing_turns_and_moves_and_keeps_the_volume() {
        let mesh = RockShape::default().mesh().unwrap();
        let centre = DVec3::new(10.0, -1.0, 3.0);
        let placed = mesh.placed(centre, std::f64::consts::FRAC_PI_2);
        assert!((placed.volume() - mesh.volume()).abs() < 1e-9 * mesh.volume());
        // A quarter turn takes local +z to world +x.
        for (p, q) in mesh.positions.iter().zip(&placed.positions) {
            let want = centre + DVec3::new(p.z, p.y, -p.x);
            assert!((*q - want).length() < 1e-12);
        }
    }

    #[test]
    fn the_top_is_the_highest_crossing() {
        let mesh = RockShape::default()
            .mesh()
            .unwrap()
            .placed(DVec3::new(0.0, 1.0, 0.0), 0.3);
        // Above the centre the top lies between the band's radii; outside the footprint none.
        let top = mesh.top_at(0.0, 0.0).unwrap();
        assert!((1.0 + 2.0 * 0.7..=1.0 + 2.0 * 1.3).contains(&top), "{top}");
        assert_eq!(mesh.top_at(20.0, 0.0), None);
        // Every vertex lies in the bounds, and each bound is some vertex's coordinate.
        let [lo, hi] = mesh.bounds();
        assert!(
            mesh.positions
                .iter()
                .all(|p| p.cmpge(lo).all() && p.cmple(hi).all())
        );
        assert!(
            mesh.positions.iter().any(|p| p.y == hi.y)
                && mesh.positions.iter().any(|p| p.x == lo.x)
        );
        // A vertex of the top half is its own top where no other face lies above it: the
        // highest vertex.
        let high = mesh
            .positions
            .iter()
            .copied()
            .fold(DVec3::splat(f64::MIN), |a, p| if p.y > a.y { p } else { a });
        let t = mesh.top_at(high.x, high.z).unwrap();
        assert!((t - high.y).abs() < 1e-9, "{t} against {}", high.y);
    }

    #[test]
    fn bad_shapes_are_refused() {
        let ok = RockShape::default();
        for bad in [
            RockShape {
                size: DVec3::new(0.0, 1.0, 1.0),
                ..ok
            },
            RockShape {
                size: DVec3::new(f64::INFINITY, 1.0, 1.0),
                ..ok
            },
            RockShape {
                roughness: 0.51,
                ..ok
            },
            RockShape {
                roughness: f64::NAN,
                ..ok
            },
            RockShape { detail: 5, ..ok },
        ] {
            assert!(
                matches!(bad.mesh(), Err(SceneError::Invalid { .. })),
                "{bad:?}"
            );
        }
    }
}
