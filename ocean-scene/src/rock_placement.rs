//! The rocks of `ocean render` (`[[rocks]]` in scene files): low-poly noise rocks
//! (`crate::rock`) standing on the island's shore, or anywhere, every triangle
//! relief-mapped by relaxed cone stepping (`ocean_gpu::ReliefScene::on_polygon`), the relief
//! carved into the rock.

use crate::{RockMesh, RockShape};
use glam::{DVec2, DVec3};
use ocean_gpu::ReliefScene;
use serde::Deserialize;

use crate::SceneError;
use crate::blocks::lit;
use crate::check::{Bad, range};
use crate::face_light::FaceLight;
use crate::island::IslandSection;

/// `[[rocks]]`: one rock.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct Rock {
    /// Bearing on the island's shore, degrees around its centre from +x towards +z: the
    /// rock's centre stands on the shoreline there.
    pub shore: f64,
    /// Metres further out to sea than the shoreline (negative: inland), with `shore`.
    pub offset: f64,
    /// Height of the rock's centre above the sea at rest, metres, with `shore`.
    pub elevation: f64,
    /// World position of the rock's centre, metres: when given, it replaces `shore`, `offset`
    /// and `elevation`.
    pub centre: Option<[f64; 3]>,
    /// Extents across, up and along its heading before the noise, metres.
    pub size: [f64; 3],
    /// Degrees from +z towards +x that the rock's length points.
    pub heading: f64,
    /// How far the noise moves the surface, a fraction of the radius in [0, 0.5].
    pub roughness: f64,
    /// Subdivisions of its icosahedron, 0 to 4 (20 × 4^detail triangles).
    pub detail: u32,
    /// Seed of its shape.
    pub seed: u64,
    /// Depth of the relief carved into each face, and the world size of one tile of the
    /// height map, metres.
    pub relief_depth: f64,
    pub tile: f64,
    /// Height-map side, texels (a power of two, 16 to 1024), and its seed (value noise, 5
    /// octaves). Rocks with the same side and seed share one relief texture.
    pub map_size: usize,
    pub map_seed: u64,
    /// Linear albedo.
    pub albedo: [f32; 3],
}

impl Default for Rock {
    fn default() -> Self {
        Self {
            shore: 126.0,
            offset: 4.0,
            elevation: 1.0,
            centre: None,
            size: [14.0, 9.0, 11.0],
            heading: 30.0,
            roughness: 0.3,
            detail: 2,
            seed: 1,
            relief_depth: 0.6,
            tile: 3.0,
            map_size: 256,
            map_seed: 1,
            albedo: [0.32, 0.29, 0.26],
        }
    }
}

impl Rock {
    /// Checks every key's range, and that a rock on the shore has an island.
    pub fn check(&self, island: Option<&IslandSection>) -> Result<(), Bad> {
        match self.centre {
            Some(c) => {
                for x in c {
                    range("rocks.centre", x, -1e6, 1e6)?;
                }
            }
            None => {
                range("rocks.shore", self.shore, -360.0, 360.0)?;
                if island.is_none() {
                    return Err((
                        "rocks.shore",
                        "needs an [island] section (or give `centre`)".to_owned(),
                    ));
                }
            }
        }
        range("rocks.offset", self.offset, -1e4, 1e4)?;
        range("rocks.elevation", self.elevation, -1e4, 1e4)?;
        for s in self.size {
            range("rocks.size", s, 1e-2, 1e4)?;
        }
        range("rocks.heading", self.heading, -360.0, 360.0)?;
        range(
            "rocks.roughness",
            self.roughness,
            0.0,
            crate::rock::MAX_ROUGHNESS,
        )?;
        if self.detail > crate::rock::MAX_DETAIL {
            return Err((
                "rocks.detail",
                format!("= {} is above {}", self.detail, crate::rock::MAX_DETAIL),
            ));
        }
        range("rocks.relief_depth", self.relief_depth, 0.0, 1e3)?;
        range("rocks.tile", self.tile, 1e-3, 1e4)?;
        if !(self.map_size.is_power_of_two() && (16..=1024).contains(&self.map_size)) {
            return Err((
                "rocks.map_size",
                format!("= {} is not a power of two from 16 to 1024", self.map_size),
            ));
        }
        if let Some(a) = self.albedo.iter().find(|a| !(a.is_finite() && **a >= 0.0)) {
            return Err((
                "rocks.albedo",
                format!("holds {a}: each component must be finite and >= 0"),
            ));
        }
        Ok(())
    }

    /// The rock's centre: `centre`, or its shore point `offset` metres out to sea at
    /// `elevation`.
    ///
    /// # Errors
    ///
    /// A message if the bearing finds no shoreline.
    pub fn position(&self, island: Option<&IslandSection>) -> Result<DVec3, SceneError> {
        if let Some(c) = self.centre {
            return Ok(DVec3::from_array(c));
        }
        let Some(island) = island else {
            return Err("a rock on the shore needs an [island]".to_owned().into());
        };
        let bearing = self.shore;
        let b = bearing.to_radians();
        let dir = DVec2::new(b.cos(), b.sin());
        let shore = island
            .shore(dir)
            .ok_or_else(|| format!("no shoreline at bearing {bearing} degrees"))?;
        let p = shore + self.offset * dir;
        Ok(DVec3::new(p.x, self.elevation, p.y))
    }

    /// The rock's centre ([`Rock::position`]) and its mesh in the world.
    ///
    /// # Errors
    ///
    /// A message for a shape the generator refuses or a shore not found.
    pub fn mesh(&self, island: Option<&IslandSection>) -> Result<(DVec3, RockMesh), SceneError> {
        let shape = RockShape {
            size: DVec3::from_array(self.size),
            roughness: self.roughness,
            detail: self.detail,
            seed: self.seed,
        };
        let mesh = shape.mesh()?;
        let centre = self.position(island)?;
        Ok((centre, mesh.placed(centre, self.heading.to_radians())))
    }

    /// The relief-mapped triangles of the rock's `mesh` ([`Rock::mesh`]), lit by `light`,
    /// their texture coordinates anchored at its `centre`.
    ///
    /// # Errors
    ///
    /// A message for a face the relief renderer refuses.
    pub fn faces(
        &self,
        centre: DVec3,
        mesh: &RockMesh,
        light: FaceLight,
    ) -> Result<Vec<ReliefScene>, SceneError> {
        mesh.faces()
            .map(|t| {
                let face = ReliefScene::on_polygon(&t, centre, self.tile)
                    .map_err(|e| format!("rock face: {e}"))?;
                Ok(lit(face, light, self.relief_depth, self.albedo))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light() -> FaceLight {
        FaceLight::for_tests()
    }

    /// A rock on the shore: its centre is on the shoreline (terrain height 0 there, land
    /// inland, sea seaward), and its faces are the mesh's triangles, facing out of the rock,
    /// with the relief of the table.
    #[test]
    fn a_shore_rock_stands_on_the_shoreline() {
        let island = IslandSection::default();
        let rock = Rock {
            offset: 0.0,
            ..Rock::default()
        };
        rock.check(Some(&island)).unwrap();
        let c = rock.position(Some(&island)).unwrap();
        assert_eq!(c.y, rock.elevation);
        let p = DVec2::new(c.x, c.z);
        assert!(island.height(p).abs() < 1e-6, "{}", island.height(p));
        let out = (p - DVec2::from_array(island.centre)).normalize();
        assert!(island.height(p + 2.0 * out) < 0.0 && island.height(p - 2.0 * out) > 0.0);
        // The offset moves it out to sea along its bearing.
        let moved = Rock {
            offset: 4.0,
            ..rock.clone()
        };
        let m = moved.position(Some(&island)).unwrap();
        assert!((DVec2::new(m.x, m.z) - (p + 4.0 * out)).length() < 1e-9);
        let (centre, mesh) = rock.mesh(Some(&island)).unwrap();
        assert_eq!(centre, c);
        let faces = rock.faces(centre, &mesh, light()).unwrap();
        assert_eq!(faces.len(), 320);
        for f in &faces {
            let n = f.edge_u.cross(f.edge_v);
            // The face's first corner lies on its plane; the centre lies behind it.
            let q = f.origin + f.corners[0].x * f.edge_u + f.corners[0].y * f.edge_v;
            assert!((q - c).dot(n) > 0.0);
            assert_eq!((f.depth, f.albedo), (rock.relief_depth, rock.albedo));
        }
    }

    #[test]
    fn a_centre_replaces_the_shore() {
        let island = IslandSection::default();
        assert_eq!(Rock::default().check(None).unwrap_err().0, "rocks.shore");
        Rock::default().check(Some(&island)).unwrap();
        let anywhere = Rock {
            centre: Some([1.0, 2.0, 3.0]),
            ..Rock::default()
        };
        anywhere.check(None).unwrap();
        for island in [None, Some(&island)] {
            assert_eq!(
                anywhere.position(island).unwrap(),
                DVec3::new(1.0, 2.0, 3.0)
            );
        }
    }
}
