use super::*;
use glam::Vec3;

#[test]
fn structs_match_the_wgsl_layout() {
    let b = crate::shaders::get("layers").unwrap().bindings().unwrap();
    assert_eq!(std::mem::size_of::<LayersParams>(), 32);
    assert_eq!(b[0].size as usize, std::mem::size_of::<LayersParams>());
    let params: Vec<(&str, u32)> = b[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.offset))
        .collect();
    assert_eq!(
        params,
        [
            ("nx", 0),
            ("nz", 4),
            ("layers", 8),
            ("groups_x", 12),
            ("has_height", 16),
            ("height", 20),
            ("spacing_x", 24),
            ("spacing_z", 28),
        ]
    );
    // The descriptor array's element is the 48-byte LayerDesc.
    assert_eq!(std::mem::size_of::<LayerDesc>(), 48);
    assert_eq!(b[1].size as usize, std::mem::size_of::<LayerDesc>());
    assert_eq!(b[2].size, 4, "data is an array of f32 words");
}

#[test]
fn validation_is_the_cpus() {
    use glam::DVec2;
    use ocean_core::{Depth, GridRect, WaveDesc, WaveSet};
    let grid = Grid {
        origin: DVec2::ZERO,
        spacing: DVec2::ONE,
        size: (8, 6),
    };
    let waves = WaveSet::from_descs(&[WaveDesc {
        amplitude: 0.1,
        wavelength: 10.0,
        direction: DVec2::X,
        phase: 0.0,
        depth: Depth::Deep,
    }])
    .unwrap();
    let h = vec![0.5f32; 48];
    let mut h_inf = h.clone();
    h_inf[40] = f32::INFINITY;
    let full = GridRect {
        i0: 0,
        j0: 0,
        nx: 8,
        nz: 6,
    };
    let m = |rect: GridRect| ocean_core::Modulation::unit(rect).unwrap();
    let (m_full, m_right, m_down, m_wide) = (
        m(full),
        m(GridRect { i0: 1, ..full }),
        m(GridRect { j0: 1, ..full }),
        m(GridRect { nx: 9, ..full }),
    );
    // A rectangle whose end overflows usize is outside the grid, not an overflow panic.
    let m_far = m(GridRect {
        i0: usize::MAX,
        nx: 2,
        ..full
    });
    let layer = |modulation| Layer {
        waves: &waves,
        modulation,
    };
    type Case<'a> = (f64, Vec<Layer<'a>>, Option<&'a [f32]>);
    let cases: Vec<Case<'_>> = vec![
        (0.0, vec![layer(&m_full)], Some(&h)),
        (0.0, vec![], None),
        (f64::NAN, vec![layer(&m_full)], None),
        (f64::INFINITY, vec![], None),
        (0.0, vec![layer(&m_right)], None),
        (0.0, vec![layer(&m_down)], None),
        (0.0, vec![layer(&m_wide)], None),
        (0.0, vec![layer(&m_far)], None),
        (0.0, vec![layer(&m_full)], Some(&h[..47])),
        (0.0, vec![layer(&m_full)], Some(&h_inf)),
    ];
    for (k, (t, layers, height)) in cases.iter().enumerate() {
        let mut pos = vec![Vec3::ZERO; 48];
        let mut nrm = vec![Vec3::ZERO; 48];
        let cpu = ocean_core::evaluate_layers(&grid, *t, layers, *height, &mut pos, &mut nrm);
        let gpu = validate_layers(&grid, *t, layers, *height);
        // Compared as text: EvalError::Time(NaN) != itself under PartialEq.
        assert_eq!(
            format!("{:?}", cpu.err()),
            format!("{:?}", gpu.err()),
            "case {k}"
        );
        assert_eq!(cpu.is_ok(), k < 2, "case {k}");
    }
    assert_eq!(
        validate_layers(&grid, 0.0, &[layer(&m_far)], None),
        Err(EvalError::Grid("layer rectangle outside the grid"))
    );
}
