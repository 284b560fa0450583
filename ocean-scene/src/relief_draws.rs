//! The relief textures of the rocks and the pier: each height map's mip chain with relaxed cones
//! ([`crate::cone_cache`]), a renderer holding it, and the faces that share it.

use glam::DVec3;
use ocean_gpu::{GpuContext, ReliefOptions, ReliefRenderer, ReliefScene};
use ocean_relief::{ConeParams, Edge, ReliefMips, ReliefTexture};

use crate::RockMesh;
use crate::SceneError;
use crate::cone_cache;
use crate::description::SceneDescription;
use crate::face_light::FaceLight;

/// Relief-mapped faces (of rocks, or of the pier's blocks) that share one relief texture: their
/// renderer and their faces.
pub(crate) struct RockDraw {
    pub(crate) renderer: ReliefRenderer,
    pub(crate) faces: Vec<ReliefScene>,
    /// How many of its levels' cone maps were generated and how many came from the cache.
    pub(crate) cones: (usize, usize),
}

/// Builds the relief texture of `heights` (an `n × n` map, wrapping) with its mip levels down to
/// 8 × 8 (`ocean_relief::lod`: each level's 2 × 2-mean map with its own relaxed cones, from the
/// cache on disk when there), so distant faces trace a coarser surface, and a renderer holding
/// it. A side that is not a power of two gets level 0 alone. Also returns how many levels' cones
/// were generated and how many came from the cache.
fn relief_renderer(
    ctx: &GpuContext,
    n: usize,
    heights: &[f32],
) -> Result<(ReliefRenderer, (usize, usize)), SceneError> {
    let relief_error = |e: ocean_relief::ReliefError| format!("relief: {e}");
    let params = ConeParams::relaxed(4.0);
    let map = ocean_relief::maps::to_map(n, heights, Edge::Wrap).map_err(relief_error)?;
    let maps = if n.is_power_of_two() && n > 8 {
        // log₂ n − 2 levels: n down to 8.
        let levels = ocean_relief::lod::max_levels(n) - 2;
        ocean_relief::lod::level_maps(&map, levels).map_err(relief_error)?
    } else {
        vec![map]
    };
    let (mut generated, mut cached) = (0, 0);
    let mut levels = Vec::with_capacity(maps.len());
    for map in &maps {
        let (cones, source) = cone_cache::cones(map, params).map_err(relief_error)?;
        match source {
            cone_cache::Source::Cached => cached += 1,
            cone_cache::Source::Generated => generated += 1,
        }
        levels.push(ReliefTexture::new(map, &cones).map_err(relief_error)?);
    }
    let mips = ReliefMips::from_levels(levels).map_err(relief_error)?;
    let mut renderer = ReliefRenderer::new(ctx, ReliefOptions::default())?;
    renderer.set_mips(ctx, &mips)?;
    Ok((renderer, (generated, cached)))
}

/// The rocks and the pier of `scene`: their relief textures and faces; `rocks` holds each
/// rock's centre and mesh ([`crate::rock_placement::Rock::mesh`]), in the scene's order.
pub(crate) fn rock_draws(
    ctx: &GpuContext,
    scene: &SceneDescription,
    rocks: &[(DVec3, RockMesh)],
    light: FaceLight,
) -> Result<Vec<RockDraw>, SceneError> {
    let mut draws = Vec::new();
    // Rocks with the same height map share one texture and one renderer, in the order of
    // their first rock.
    let mut maps: Vec<(usize, u64)> = Vec::new();
    for rock in &scene.rocks {
        if !maps.contains(&(rock.map_size, rock.map_seed)) {
            maps.push((rock.map_size, rock.map_seed));
        }
    }
    for (n, seed) in maps {
        let heights = ocean_relief::maps::value_noise(n, (n / 32).max(2), 5, seed);
        let (renderer, cones) = relief_renderer(ctx, n, &heights)?;
        let mut faces = Vec::new();
        for (rock, (centre, mesh)) in scene.rocks.iter().zip(rocks) {
            if (rock.map_size, rock.map_seed) == (n, seed) {
                faces.extend(rock.faces(*centre, mesh, light)?);
            }
        }
        draws.push(RockDraw {
            renderer,
            faces,
            cones,
        });
    }
    if let Some(pier) = &scene.pier {
        let (renderer, cones) = relief_renderer(ctx, pier.map_size, &pier.plank_heights())?;
        draws.push(RockDraw {
            renderer,
            faces: pier.deck().faces(light)?,
            cones,
        });
    }
    Ok(draws)
}
