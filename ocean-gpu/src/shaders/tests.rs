use super::*;

#[test]
fn every_shader_validates_with_the_requested_capabilities() {
    for s in all() {
        let (module, _) = s.module().unwrap_or_else(|e| panic!("{e}"));
        // The registry's entry-point table must match the source, stage included.
        let mut declared: Vec<(String, naga::ShaderStage)> = module
            .entry_points
            .iter()
            .map(|e| (e.name.clone(), e.stage))
            .collect();
        let mut listed: Vec<(String, naga::ShaderStage)> = s
            .entry_points
            .iter()
            .map(|e| (e.name.to_owned(), e.stage.to_naga()))
            .collect();
        declared.sort_by(|a, b| a.0.cmp(&b.0));
        listed.sort_by(|a, b| a.0.cmp(&b.0));
        assert_eq!(declared, listed, "{}", s.name);
        let compute = s.entry_points.iter().all(|e| e.stage == Stage::Compute);
        assert_eq!(compute, s.kind == ShaderKind::Compute, "{}", s.name);
    }
}

#[test]
fn registry_lookup() {
    assert!(get("trochoid").is_some());
    assert!(get("layers").is_some());
    assert!(get("no-such-shader").is_none());
    let e = export("no-such-shader", Language::Glsl).unwrap_err();
    assert!(e.to_string().contains("trochoid"), "{e}");
    let names: Vec<&str> = all().iter().map(|s| s.name).collect();
    let mut dedup = names.clone();
    dedup.dedup();
    assert_eq!(names, dedup, "shader names must be unique");
}

#[test]
fn language_names_round_trip() {
    for l in Language::ALL {
        assert_eq!(l.name().parse::<Language>().unwrap(), l);
    }
    assert!("cuda".parse::<Language>().is_err());
}

#[test]
fn invalid_wgsl_is_an_error_not_a_panic() {
    let bad = ShaderEntry {
        name: "bad",
        files: &[],
        source: "fn f() -> f32 { return 1u; }",
        kind: ShaderKind::Compute,
        entry_points: &[],
        description: "",
    };
    assert!(matches!(bad.module(), Err(ShaderError::Validation { .. })));
    let unparsable = ShaderEntry {
        source: "fn (",
        ..bad
    };
    assert!(matches!(
        unparsable.module(),
        Err(ShaderError::Parse { .. })
    ));
}

#[test]
fn trochoid_binding_layout() {
    // The layout TrochoidPass creates its bind group for: one uniform block, two read-only
    // and two read-write storage buffers (4 storage buffers: the downlevel limit).
    let b = get("trochoid").unwrap().bindings().unwrap();
    let summary: Vec<(u32, u32, &str, String, &str, u32)> = b
        .iter()
        .map(|b| {
            (
                b.group,
                b.binding,
                b.name.as_str(),
                b.kind.to_string(),
                b.ty.as_str(),
                b.size,
            )
        })
        .collect();
    assert_eq!(
        summary,
        vec![
            (0, 0, "params", "uniform".into(), "Params", 32),
            (
                0,
                1,
                "coeffs",
                "storage(read)".into(),
                "array<WaveCoeffs>",
                32
            ),
            (
                0,
                2,
                "tables",
                "storage(read)".into(),
                "array<vec2<f32>>",
                8
            ),
            (
                0,
                3,
                "positions",
                "storage(read_write)".into(),
                "array<vec4<f32>>",
                16
            ),
            (
                0,
                4,
                "normals",
                "storage(read_write)".into(),
                "array<vec4<f32>>",
                16
            ),
        ]
    );
    // Params members at the offsets of the Rust TrochoidParams.
    let offsets: Vec<(&str, u32)> = b[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.offset))
        .collect();
    assert_eq!(
        offsets,
        vec![
            ("nx", 0),
            ("nz", 4),
            ("waves", 8),
            ("cols_offset", 12),
            ("groups_x", 16),
            ("_pad", 20),
            ("spacing_x", 24),
            ("spacing_z", 28),
        ]
    );
}

#[test]
fn glsl_bindings_are_flattened_per_namespace() {
    // Uniform blocks and storage blocks are separate GL namespaces, each numbered from 0.
    let e = export("trochoid", Language::Glsl).unwrap();
    let gl: Vec<(&str, Option<u32>)> = e
        .bindings
        .iter()
        .map(|b| (b.name.as_str(), b.glsl_binding))
        .collect();
    assert_eq!(
        gl,
        vec![
            ("params", Some(0)),
            ("coeffs", Some(0)),
            ("tables", Some(1)),
            ("positions", Some(2)),
            ("normals", Some(3)),
        ]
    );
    let Code::Text(text) = &e.files[0].code else {
        panic!("GLSL is text")
    };
    assert!(
        text.starts_with("#version 430 core"),
        "{}",
        &text[..40.min(text.len())]
    );
    for b in &e.bindings {
        let name = b
            .glsl_name
            .as_deref()
            .expect("every buffer has a GLSL block name");
        assert!(text.contains(name), "{name} not in the GLSL");
    }
    let es = export("trochoid", Language::GlslEs).unwrap();
    let Code::Text(text) = &es.files[0].code else {
        panic!("GLSL ES is text")
    };
    assert!(text.starts_with("#version 310 es"));
}

/// A draw pass (vertex + fragment) with a uniform block, a texture and a sampler, to check
/// the GLSL 3.30 path: no `binding =` qualifiers there (3.30 lacks them), so
/// `glsl_binding` is `None` and the engine binds by `glsl_name`; ES 3.10 does write them.
const DRAW_TEST: ShaderEntry = ShaderEntry {
    name: "draw_test",
    files: &[],
    source: "
        struct View { view_proj: mat4x4<f32>, tint: vec4<f32> }
        @group(0) @binding(0) var<uniform> view: View;
        @group(0) @binding(1) var albedo: texture_2d<f32>;
        @group(0) @binding(2) var albedo_sampler: sampler;
        struct VsOut { @builtin(position) clip: vec4<f32>, @location(0) uv: vec2<f32> }
        @vertex fn vs(@location(0) p: vec4<f32>) -> VsOut {
            return VsOut(view.view_proj * vec4<f32>(p.xyz, 1.0), p.xz);
        }
        @fragment fn fs(v: VsOut) -> @location(0) vec4<f32> {
            return view.tint * textureSample(albedo, albedo_sampler, v.uv);
        }",
    kind: ShaderKind::Draw,
    entry_points: &[
        EntryPoint {
            name: "vs",
            stage: Stage::Vertex,
        },
        EntryPoint {
            name: "fs",
            stage: Stage::Fragment,
        },
    ],
    description: "test draw pass",
};

#[test]
fn draw_passes_export_glsl_330_without_binding_qualifiers() {
    let e = DRAW_TEST.export(Language::Glsl).unwrap();
    let names: Vec<&str> = e.files.iter().map(|f| f.file_name.as_str()).collect();
    assert_eq!(names, ["draw_test.vs.vert.glsl", "draw_test.fs.frag.glsl"]);
    for f in &e.files {
        let Code::Text(t) = &f.code else {
            panic!("GLSL is text")
        };
        assert!(t.starts_with("#version 330 core"), "{}", f.file_name);
        assert!(
            !t.contains("binding ="),
            "GLSL 3.30 has no binding qualifier"
        );
    }
    let kinds: Vec<String> = e.bindings.iter().map(|b| b.kind.to_string()).collect();
    assert_eq!(kinds, ["uniform", "texture", "sampler"]);
    assert!(e.bindings.iter().all(|b| b.glsl_binding.is_none()));
    // The uniform block and the combined texture+sampler have GLSL names to bind by.
    assert!(e.bindings[0].glsl_name.is_some() && e.bindings[1].glsl_name.is_some());
    assert_eq!(e.bindings[0].size, 80, "mat4x4 (64) + vec4 (16)");

    // ES 3.10 writes explicit bindings: uniform block 0, texture unit 0.
    let es = DRAW_TEST.export(Language::GlslEs).unwrap();
    let gl: Vec<Option<u32>> = es.bindings.iter().map(|b| b.glsl_binding).collect();
    assert_eq!(gl, [Some(0), Some(0), None]);
    let Code::Text(vs) = &es.files[0].code else {
        panic!("GLSL ES is text")
    };
    assert!(vs.starts_with("#version 310 es") && vs.contains("binding = 0"));
    // Every other language translates the draw pass too.
    for l in [Language::Hlsl, Language::Msl, Language::SpirV] {
        DRAW_TEST
            .export(l)
            .unwrap_or_else(|err| panic!("{l}: {err}"));
    }
}

#[test]
fn wgsl_degenerate_normal_threshold_is_f32_min_positive() {
    // The CPU kernel takes the normal as +y where |n|² < f32::MIN_POSITIVE; the WGSL
    // literal must round to exactly that f32, or the two sides disagree next to cusps.
    for name in ["trochoid", "layers"] {
        let (module, _) = get(name).unwrap().module().unwrap();
        let (_, c) = module
            .constants
            .iter()
            .find(|(_, c)| c.name.as_deref() == Some("F32_MIN_POSITIVE"))
            .expect("WGSL constant F32_MIN_POSITIVE");
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::F32(v)) => {
                assert_eq!(v.to_bits(), f32::MIN_POSITIVE.to_bits(), "{name}: {v:e}");
            }
            ref other => panic!("{name}: F32_MIN_POSITIVE is {other:?}"),
        }
    }
}
