//! Relief-mapped blocks: the pier of `ocean render` as boxes whose faces are
//! quads relief-mapped by relaxed cone stepping (`ocean_gpu::ReliefRenderer`), each face's
//! relief carved inwards from it and writing its hit's depth, so that blocks occlude each other,
//! the sea and the terrain correctly and the obscurance pass sees their true shape.

use glam::{DVec2, DVec3};
use ocean_gpu::ReliefScene;

use crate::SceneError;
use crate::face_light::FaceLight;

/// Which faces of a block are drawn (a face the camera can never see costs a relief trace per
/// pixel only when drawn: the back of a quad is discarded before tracing, but its pixels are
/// still rasterised).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Faces {
    /// The four vertical sides.
    pub sides: bool,
    pub top: bool,
    pub bottom: bool,
}

/// A box: its centre, its horizontal `right` axis (unit), its size along `right`, up (+y) and
/// `forward = right × y`, and its surface.
#[derive(Clone, Copy, Debug)]
pub struct Block {
    pub centre: DVec3,
    pub right: DVec3,
    pub size: DVec3,
    pub faces: Faces,
    /// World size of one tile of the relief texture, metres.
    pub tile: f64,
    /// Depth of the relief below each face, metres.
    pub depth: f64,
    pub albedo: [f32; 3],
}

impl Block {
    /// The drawn faces of non-zero area, in the order front (the face whose outward normal is
    /// `forward`), back, right, left, top, bottom.
    ///
    /// A face with outward normal `m` takes `u` along one of its edges and `v = m × u`, so that
    /// `u × v = m` (the relief renderer's convention: the relief lies behind the face, against
    /// its normal).
    pub fn quads(&self) -> Vec<Quad> {
        let r = self.right.normalize_or_zero();
        let forward = r.cross(DVec3::Y);
        let (w, h, d) = (self.size.x, self.size.y, self.size.z);
        // (outward normal, u axis, extent along u, extent along v, size along the normal)
        let mut list = Vec::new();
        if self.faces.sides {
            list.extend([
                (forward, r, w, h, d),
                (-forward, -r, w, h, d),
                (r, -forward, d, h, w),
                (-r, forward, d, h, w),
            ]);
        }
        if self.faces.top {
            list.push((DVec3::Y, r, w, d, h));
        }
        if self.faces.bottom {
            list.push((DVec3::NEG_Y, r, w, d, h));
        }
        list.into_iter()
            // A face of zero area (a block of zero thickness has no sides) is not drawn.
            .filter(|&(_, _, eu, ev, _)| eu > 0.0 && ev > 0.0)
            .map(|(m, u, eu, ev, thickness)| {
                let v = m.cross(u);
                Quad {
                    normal: m,
                    origin: self.centre + 0.5 * thickness * m - 0.5 * eu * u - 0.5 * ev * v,
                    edge_u: eu * u,
                    edge_v: ev * v,
                }
            })
            .collect()
    }

    /// The relief quads of [`Block::quads`], lit by `light`: the Sun, and the environment's
    /// irradiance on the relief's own normal at every hit (no constant ambient).
    ///
    /// # Errors
    ///
    /// A message if a face's frame is refused (a degenerate size or axis).
    pub fn faces(&self, light: FaceLight) -> Result<Vec<ReliefScene>, SceneError> {
        self.quads()
            .into_iter()
            .map(|q| {
                let quad = ReliefScene {
                    origin: q.origin,
                    edge_u: q.edge_u,
                    edge_v: q.edge_v,
                    tiles: DVec2::new(q.edge_u.length(), q.edge_v.length()) / self.tile,
                    ..ReliefScene::default()
                };
                let face = lit(quad, light, self.depth, self.albedo);
                face.tangent_frame().map_err(|e| e.to_string())?;
                Ok(face)
            })
            .collect()
    }
}

/// `face` with a relief `depth` metres deep and `albedo`, lit by `light`: the Sun, and the
/// environment's irradiance on the relief's own normal at every hit (no constant ambient).
pub fn lit(face: ReliefScene, light: FaceLight, depth: f64, albedo: [f32; 3]) -> ReliefScene {
    ReliefScene {
        depth,
        light_dir: light.sun_dir,
        light_intensity: 1.0,
        light_color: light.sun.as_vec3().to_array(),
        albedo,
        ambient: 0.0,
        sky: Some(light.sky),
        ..face
    }
}

/// A rectangle: its outward normal, a corner and the edges from it (`edge_u × edge_v` along
/// `normal`).
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    pub normal: DVec3,
    pub origin: DVec3,
    pub edge_u: DVec3,
    pub edge_v: DVec3,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light() -> FaceLight {
        FaceLight::for_tests()
    }

    #[test]
    fn faces_enclose_the_block_with_outward_normals() {
        // A 4 × 2 × 6 block turned 30°: each face's centre lies half the block's size along
        // its normal from the block's centre, its normal (u × v) points away from the centre,
        // and its area is the product of the two sizes it spans.
        let b = Block {
            centre: DVec3::new(1.0, 2.0, 3.0),
            // Turned 30°.
            right: DVec3::new(0.866_025_403_784_438_6, 0.0, -0.5),
            size: DVec3::new(4.0, 2.0, 6.0),
            faces: Faces {
                sides: true,
                top: true,
                bottom: true,
            },
            tile: 2.0,
            depth: 0.1,
            albedo: [0.5; 3],
        };
        let faces = b.faces(light()).unwrap();
        assert_eq!(faces.len(), 6);
        let mut areas: Vec<f64> = faces
            .iter()
            .map(|f| {
                let c = f.origin + 0.5 * f.edge_u + 0.5 * f.edge_v;
                let n = f.edge_u.cross(f.edge_v);
                let area = n.length();
                let n = n / area;
                let half = (c - b.centre).dot(n);
                // The centre's offset is along the normal only.
                assert!(((c - b.centre) - half * n).length() < 1e-12);
                assert!(half > 0.0, "normal {n} points inwards");
                assert!(f.edge_u.dot(f.edge_v).abs() < 1e-12);
                (area * 1e9).round() / 1e9
            })
            .collect();
        areas.sort_by(f64::total_cmp);
        // Front and back 4 × 2, left and right 6 × 2, top and bottom 4 × 6.
        assert_eq!(areas, [8.0, 8.0, 12.0, 12.0, 24.0, 24.0]);
    }

    #[test]
    fn faces_carry_the_sun_and_the_sky() {
        let b = Block {
            centre: DVec3::ZERO,
            right: DVec3::X,
            size: DVec3::ONE,
            faces: Faces {
                sides: true,
                top: true,
                bottom: true,
            },
            tile: 1.0,
            depth: 0.1,
            albedo: [0.5; 3],
        };
        let l = light();
        for f in b.faces(l).unwrap() {
            // The sky's light depends on the relief normal the shader finds, so the face
            // carries the whole irradiance and no constant ambient of its own.
            assert_eq!((f.ambient, f.sky), (0.0, Some(l.sky)));
            assert_eq!((f.light_dir, f.light_intensity), (l.sun_dir, 1.0));
            assert_eq!(f.light_color, [0.3, 0.25, 0.2]);
        }
    }
}
