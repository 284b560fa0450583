use std::mem::{offset_of, size_of};

use ocean_relief::gpu_params::ConeGenUniforms;

use super::*;

/// The Rust blocks and the WGSL structs agree field for field: names in order and byte
/// offsets, and the total size.
#[test]
fn uniform_blocks_match_the_wgsl_structs() {
    let b = shaders::get("relief").unwrap().bindings().unwrap();
    assert_eq!((b[0].name.as_str(), b[0].size as usize), ("relief", 448));
    assert_eq!(size_of::<ReliefUniforms>(), 448);
    let offsets: Vec<(&str, u32)> = b[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.offset))
        .collect();
    let o = |off: usize| off as u32;
    assert_eq!(
        offsets,
        vec![
            ("view_proj", o(offset_of!(ReliefUniforms, view_proj))),
            ("quad_origin", o(offset_of!(ReliefUniforms, quad_origin))),
            ("quad_u", o(offset_of!(ReliefUniforms, quad_u))),
            ("quad_v", o(offset_of!(ReliefUniforms, quad_v))),
            ("tangent", o(offset_of!(ReliefUniforms, tangent))),
            ("bitangent", o(offset_of!(ReliefUniforms, bitangent))),
            ("normal", o(offset_of!(ReliefUniforms, normal))),
            ("view_dir", o(offset_of!(ReliefUniforms, view_dir))),
            ("light", o(offset_of!(ReliefUniforms, light))),
            ("albedo", o(offset_of!(ReliefUniforms, albedo))),
            ("trace", o(offset_of!(ReliefUniforms, trace))),
            ("steps", o(offset_of!(ReliefUniforms, steps))),
            ("shading", o(offset_of!(ReliefUniforms, shading))),
            ("irradiance", o(offset_of!(ReliefUniforms, irradiance))),
            ("light_color", o(offset_of!(ReliefUniforms, light_color))),
            ("polygon", o(offset_of!(ReliefUniforms, polygon))),
        ]
    );
    // The probe and the quadrant variants declare the same block; the quadrant variants'
    // texture is the 4-layer array (`relief_texture_quad.wgsl`).
    for name in ["relief_probe", "relief_quad", "relief_quad_probe"] {
        let p = shaders::get(name).unwrap().bindings().unwrap();
        assert_eq!(p[0].members, b[0].members, "{name}");
        let expected = if name.starts_with("relief_quad") {
            "texture_2d_array<f32>"
        } else {
            "texture_2d<f32>"
        };
        assert_eq!(p[1].name, "relief_map", "{name}");
        assert_eq!(p[1].ty, expected, "{name}");
    }

    let g = shaders::get("relief_cone").unwrap().bindings().unwrap();
    assert_eq!((g[0].name.as_str(), g[0].size as usize), ("gen", 128));
    assert_eq!(size_of::<ConeGenUniforms>(), 128);
    let offsets: Vec<(&str, u32)> = g[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.offset))
        .collect();
    assert_eq!(
        offsets,
        vec![
            ("grid", o(offset_of!(ConeGenUniforms, grid))),
            ("pyramid", o(offset_of!(ConeGenUniforms, pyramid))),
            ("cap", o(offset_of!(ConeGenUniforms, cap))),
            ("sector", o(offset_of!(ConeGenUniforms, sector))),
            (
                "level_offsets",
                o(offset_of!(ConeGenUniforms, level_offsets))
            ),
        ]
    );
}

/// The quad's checks: a valid quad's frame, and each refusal.
#[test]
fn tangent_frame_checks_the_quad() {
    let s = ReliefScene::default();
    let f = s.tangent_frame().unwrap();
    assert_eq!(f.normal, DVec3::Y);
    assert_eq!((f.texture_width, f.depth_scale), (1.0, 0.1));
    let refused = |m: fn(&mut ReliefScene)| {
        let mut s = ReliefScene::default();
        m(&mut s);
        matches!(s.tangent_frame(), Err(GpuError::InvalidInput { .. }))
    };
    assert!(refused(|s| s.edge_v = DVec3::new(0.01, 0.0, -1.0)));
    assert!(refused(|s| s.tiles.y = 1.01));
    assert!(refused(|s| s.depth = -1.0));
    assert!(refused(|s| s.depth = 2.0e6));
    assert!(refused(|s| s.tiles.x = 0.0));
    assert!(refused(|s| s.edge_u = DVec3::splat(f64::NAN)));
    assert!(refused(|s| s.tiles = DVec2::splat(1.0e-320)));
}
