//! The pier of `ocean render` (`[pier]`): a plank deck, its faces relief-mapped by relaxed cone
//! stepping ([`crate::blocks`]), on two rows of plain posts standing in the sea
//! ([`crate::solids`]). It is there for the
//! obscurance: the water under its deck and around its posts sees less of the sky, which the
//! SAO pass finds in the depth buffer and the composition takes out of the ambient light.

use glam::DVec3;
use serde::Deserialize;

use crate::blocks::{Block, Faces};
use crate::check::range;

/// `[pier]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct PierSection {
    /// World `[x, z]` of the landward end of the deck's centre line, metres.
    pub start: [f64; 2],
    /// Direction from the landward end to the seaward end, degrees from +x towards +z.
    pub direction: f64,
    /// Length and width of the deck, metres.
    pub length: f64,
    pub width: f64,
    /// Height of the deck's top above the sea at rest, and the deck's thickness, metres.
    pub deck_height: f64,
    pub deck_thickness: f64,
    /// Distance between neighbouring pairs of posts along the deck, metres.
    pub post_spacing: f64,
    /// Side of a post's square section, and how deep posts reach below the sea at rest, metres.
    pub post_width: f64,
    pub post_depth: f64,
    /// Width of one plank, metres.
    pub plank_width: f64,
    /// Depth of the relief (the gaps between planks, the grain), metres.
    pub relief_depth: f64,
    /// Side of the deck's and the posts' height maps, texels (a power of two, 16 to 1024).
    pub map_size: usize,
    /// Seed of the wood grain.
    pub seed: u64,
    /// Linear albedo.
    pub albedo: [f32; 3],
}

impl Default for PierSection {
    fn default() -> Self {
        Self {
            start: [25.0, -112.0],
            direction: 118.0,
            length: 70.0,
            width: 3.0,
            deck_height: 1.6,
            deck_thickness: 0.35,
            post_spacing: 5.0,
            post_width: 0.35,
            post_depth: 6.0,
            plank_width: 0.25,
            relief_depth: 0.05,
            map_size: 256,
            seed: 11,
            albedo: [0.30, 0.21, 0.13],
        }
    }
}

/// Planks per tile of the deck's height map: the tile is this many plank widths long.
const PLANKS_PER_TILE: usize = 8;

impl PierSection {
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        for x in self.start {
            range("pier.start", x, -1e6, 1e6)?;
        }
        range("pier.direction", self.direction, -1e6, 1e6)?;
        range("pier.length", self.length, 0.1, 1e4)?;
        range("pier.width", self.width, 0.1, 1e3)?;
        range("pier.deck_height", self.deck_height, 0.0, 1e3)?;
        range("pier.deck_thickness", self.deck_thickness, 1e-3, 1e2)?;
        range("pier.post_spacing", self.post_spacing, 0.1, 1e4)?;
        range("pier.post_width", self.post_width, 1e-3, self.width)?;
        range("pier.post_depth", self.post_depth, 0.0, 1e3)?;
        range("pier.plank_width", self.plank_width, 1e-3, 1e2)?;
        range("pier.relief_depth", self.relief_depth, 0.0, 1e2)?;
        if !(self.map_size.is_power_of_two() && (16..=1024).contains(&self.map_size)) {
            return Err((
                "pier.map_size",
                format!("= {} is not a power of two from 16 to 1024", self.map_size),
            ));
        }
        if self.deck_thickness >= self.deck_height + self.post_depth {
            return Err((
                "pier.deck_thickness",
                format!(
                    "= {} leaves no post between the deck and {} m below the sea",
                    self.deck_thickness, self.post_depth
                ),
            ));
        }
        for c in self.albedo {
            range("pier.albedo", f64::from(c), 0.0, 1.0)?;
        }
        Ok(())
    }

    /// Unit vectors along the deck (landward to seaward) and across it (`across × y = along`).
    fn axes(&self) -> (DVec3, DVec3) {
        let d = self.direction.to_radians();
        let along = DVec3::new(d.cos(), 0.0, d.sin());
        (along, DVec3::Y.cross(along))
    }

    /// The deck: one block, planks across it.
    pub fn deck(&self) -> Block {
        let (along, across) = self.axes();
        let start = DVec3::new(self.start[0], 0.0, self.start[1]);
        Block {
            centre: start
                + 0.5 * self.length * along
                + (self.deck_height - 0.5 * self.deck_thickness) * DVec3::Y,
            right: across,
            size: DVec3::new(self.width, self.deck_thickness, self.length),
            faces: Faces {
                sides: true,
                top: true,
                bottom: true,
            },
            tile: PLANKS_PER_TILE as f64 * self.plank_width,
            depth: self.relief_depth,
            albedo: self.albedo,
        }
    }

    /// The posts: pairs `post_spacing` apart along the deck, the first half a spacing from the
    /// landward end, each from `post_depth` below the sea up to the deck's underside.
    pub fn posts(&self) -> Vec<Block> {
        let (along, across) = self.axes();
        let start = DVec3::new(self.start[0], 0.0, self.start[1]);
        let bottom = -self.post_depth;
        let top = self.deck_height - self.deck_thickness;
        let offset = 0.5 * (self.width - self.post_width);
        let count = (self.length / self.post_spacing).floor().max(1.0) as usize;
        (0..count)
            .flat_map(|k| {
                let s = (k as f64 + 0.5) * self.post_spacing;
                [-offset, offset].map(|a| Block {
                    centre: start + s * along + a * across + 0.5 * (bottom + top) * DVec3::Y,
                    right: across,
                    size: DVec3::new(self.post_width, top - bottom, self.post_width),
                    faces: Faces {
                        sides: true,
                        top: false,
                        bottom: false,
                    },
                    tile: 1.0,
                    depth: 0.0,
                    albedo: self.albedo.map(|c| 0.8 * c),
                })
            })
            .collect()
    }

    /// The deck's height map (`n × n`, 1 = the deck's surface): `PLANKS_PER_TILE` (8) planks
    /// along the texture's rows, a gap of a tenth of a plank at the bottom between neighbours,
    /// and a shallow grain (value noise stretched along each plank) on their tops.
    pub fn plank_heights(&self) -> Vec<f32> {
        let n = self.map_size;
        let grain = ocean_relief::maps::value_noise(n, 4, 3, self.seed);
        let plank = n / PLANKS_PER_TILE;
        let gap = (plank / 10).max(1);
        (0..n * n)
            .map(|k| {
                let (i, j) = (k % n, k / n);
                if j % plank < gap {
                    0.0
                } else {
                    // The grain varies slowly along the plank (u) and fast across it (v).
                    let g = grain[(j * 8 % n) * n + i / 4];
                    0.8 + 0.2 * g
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::face_light::FaceLight;

    fn light() -> FaceLight {
        FaceLight {
            sun_dir: DVec3::Y,
            sun: DVec3::splat(0.3),
            sky: ocean_brdf::Irradiance::from_radiance(|d| DVec3::splat(0.1 * d.y.max(0.0))),
        }
    }

    #[test]
    fn posts_hold_the_deck_and_stand_in_the_sea() {
        let p = PierSection::default();
        let deck = p.deck();
        let underside = deck.centre.y - 0.5 * deck.size.y;
        assert!((underside - (p.deck_height - p.deck_thickness)).abs() < 1e-12);
        let posts = p.posts();
        // floor(70 / 5) = 14 pairs.
        assert_eq!(posts.len(), 28);
        let (along, _) = p.axes();
        let start = DVec3::new(p.start[0], 0.0, p.start[1]);
        for post in &posts {
            let top = post.centre.y + 0.5 * post.size.y;
            let bottom = post.centre.y - 0.5 * post.size.y;
            assert!((top - underside).abs() < 1e-12, "post top {top}");
            assert!(
                (bottom + p.post_depth).abs() < 1e-12,
                "post bottom {bottom}"
            );
            // Under the deck: within its length and its width.
            let rel = post.centre - start;
            let s = rel.dot(along);
            let a = (rel - s * along - rel.y * DVec3::Y).length();
            assert!(s > 0.0 && s < p.length, "along {s}");
            assert!(
                a + 0.5 * p.post_width <= 0.5 * p.width + 1e-12,
                "across {a}"
            );
        }
        assert_eq!(deck.faces(light()).unwrap().len(), 6);
        assert!(posts.iter().all(|b| b.quads().len() == 4));
    }

    #[test]
    fn planks_have_gaps_between_them() {
        let p = PierSection {
            map_size: 64,
            ..PierSection::default()
        };
        let h = p.plank_heights();
        // 64 texels, 8 planks of 8 rows, the first row of each a gap (8 / 10 rounds to 1).
        for j in 0..64 {
            let row = &h[j * 64..(j + 1) * 64];
            if j % 8 == 0 {
                assert!(row.iter().all(|&x| x == 0.0), "row {j}");
            } else {
                assert!(row.iter().all(|&x| (0.8..=1.0).contains(&x)), "row {j}");
            }
        }
    }

    #[test]
    fn bad_values_are_named() {
        let p = PierSection {
            post_width: 5.0,
            ..PierSection::default()
        };
        assert_eq!(p.check().unwrap_err().0, "pier.post_width");
        let p = PierSection {
            deck_thickness: 10.0,
            post_depth: 1.0,
            ..PierSection::default()
        };
        assert_eq!(p.check().unwrap_err().0, "pier.deck_thickness");
    }
}
