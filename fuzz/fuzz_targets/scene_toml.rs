//! `scene_toml`: the scene files of `ocean render` (ocean-scene/src/description.rs), parsed,
//! checked and turned into what the renderer builds from them on the CPU before it needs a GPU
//! (`SceneRenderer::with_context` in ocean-scene/src/renderer.rs): cameras, spectrum, lighting,
//! rock meshes, the island with its wave train boxes, the pier. Invariant: no panic; a bad file
//! is an `Err(SceneError)`.
#![no_main]

use libfuzzer_sys::fuzz_target;
use ocean_brdf::{Filter, FilteredSurface, Spectrum};
use ocean_scene::island::Island;
use ocean_scene::{Preset, SceneDescription};

/// Past these sizes the island (grid_size² points, each box marched over them) and the rocks
/// (subdivision `detail`) take too long for a fuzz execution; the parser and the checks still
/// see every size.
const MAX_GRID: usize = 48;
const MAX_BOXES: usize = 3;
const MAX_DETAIL: u32 = 3;
const MAX_WAVES: usize = 256;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = SceneDescription::parse(text, "fuzz.toml") else {
        return;
    };
    scene
        .check_overrides()
        .expect("a parsed scene passes its own checks again");
    let r = &scene.render;
    for preset in [
        None,
        Some(Preset::Shore),
        Some(Preset::Horizon),
        Some(Preset::High),
        Some(Preset::Orbit),
    ] {
        for k in [0.0, 1.0, 1e3] {
            let _ = scene.camera(preset, r.time + k / r.fps, r.width, r.height);
        }
    }
    let _ = scene.lighting();
    if scene.spectrum.waves <= MAX_WAVES
        && let Ok(spectrum) = Spectrum::new(scene.spectrum())
    {
        let _ = FilteredSurface::new(&spectrum, Filter::PAPER);
    }
    let mut meshes = Vec::new();
    for rock in &scene.rocks {
        if rock.detail <= MAX_DETAIL
            && let Ok((_, mesh)) = rock.mesh(scene.island.as_ref())
        {
            meshes.push(mesh);
        }
    }
    if let Some(island) = &scene.island
        && island.grid_size <= MAX_GRID
        && scene.boxes.len() <= MAX_BOXES
    {
        let rocks: Vec<_> = meshes.iter().collect();
        let _ = Island::new(island, &scene.boxes, &rocks);
    }
    if let Some(pier) = &scene.pier {
        let _ = pier.deck();
        let _ = pier.posts();
        let _ = pier.plank_heights();
    }
});
