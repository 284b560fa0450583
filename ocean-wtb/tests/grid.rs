//! The water grid: validation, the size cap and index helpers.

use glam::DVec2;
use ocean_core::Grid;
use ocean_wtb::WtbError;
use ocean_wtb::grid::{MAX_SIDE, WaterGrid};

#[test]
fn positions_and_indices() {
    // 5 × 3 points 0.5 m apart from (10, −2): point (4, 2) is at (12, −1), index 2·5 + 4 = 14.
    let g = WaterGrid::new(DVec2::new(10.0, -2.0), 0.5, 5, 3).unwrap();
    assert_eq!(g.size(), (5, 3));
    assert_eq!(g.len(), 15);
    assert_eq!(g.point(4, 2), DVec2::new(12.0, -1.0));
    assert_eq!(g.max_corner(), DVec2::new(12.0, -1.0));
    assert_eq!(g.index(4, 2), Some(14));
    assert_eq!(g.index(5, 0), None);
    assert_eq!(g.index(0, 3), None);
    assert_eq!(g.ij(14), Some((4, 2)));
    assert_eq!(g.ij(15), None);
    assert!(g.contains_index(0, 0) && g.contains_index(4, 2));
    assert!(!g.contains_index(-1, 0) && !g.contains_index(5, 0) && !g.contains_index(0, 3));
    // It is ocean-core's grid, so core's evaluators see the same points.
    assert_eq!(
        *g.grid(),
        Grid {
            origin: DVec2::new(10.0, -2.0),
            spacing: DVec2::splat(0.5),
            size: (5, 3)
        }
    );
}

#[test]
fn world_to_index_is_floor_of_local_coordinates() {
    let g = WaterGrid::new(DVec2::new(10.0, -2.0), 0.5, 5, 3).unwrap();
    // (11.3, −1.1): local (2.6, 1.8) → cell (2, 1).
    assert!((g.to_local(DVec2::new(11.3, -1.1)) - DVec2::new(2.6, 1.8)).length() < 1e-12);
    assert_eq!(g.cell_of(DVec2::new(11.3, -1.1)), Some((2, 1)));
    // Left of and below the origin the floor goes negative (not truncation towards 0).
    assert_eq!(g.cell_of(DVec2::new(9.9, -2.1)), Some((-1, -1)));
    assert_eq!(g.cell_of(DVec2::new(10.0, -2.0)), Some((0, 0)));
    assert_eq!(g.cell_of(DVec2::new(f64::NAN, 0.0)), None);
    // locate: inside the closed rectangle only; the far edges belong to the last column/row.
    assert_eq!(g.locate(DVec2::new(11.3, -1.1)), Some((2, 1)));
    assert_eq!(g.locate(DVec2::new(12.0, -1.0)), Some((4, 2)));
    assert_eq!(g.locate(DVec2::new(12.01, -1.0)), None);
    assert_eq!(g.locate(DVec2::new(9.99, -1.0)), None);
    assert!(g.contains(DVec2::new(10.0, -2.0)) && !g.contains(DVec2::new(10.0, -2.001)));
}

#[test]
fn centred_matches_core() {
    let g = WaterGrid::centred(DVec2::new(100.0, 50.0), 2.0, 65).unwrap();
    assert_eq!(*g.grid(), Grid::centred(DVec2::new(100.0, 50.0), 2.0, 65));
    assert_eq!(g.point(32, 32), DVec2::new(100.0, 50.0));
}

#[test]
fn rejects_bad_grids() {
    let o = DVec2::ZERO;
    assert_eq!(
        WaterGrid::new(o, 1.0, 1, 8),
        Err(WtbError::GridSize {
            nx: 1,
            nz: 8,
            min: 2,
            max: MAX_SIDE
        })
    );
    assert_eq!(
        WaterGrid::new(o, 1.0, 8, 0),
        Err(WtbError::GridSize {
            nx: 8,
            nz: 0,
            min: 2,
            max: MAX_SIDE
        })
    );
    assert!(WaterGrid::new(o, 1.0, MAX_SIDE, MAX_SIDE).is_ok());
    assert_eq!(
        WaterGrid::new(o, 1.0, MAX_SIDE + 1, 2),
        Err(WtbError::GridSize {
            nx: MAX_SIDE + 1,
            nz: 2,
            min: 2,
            max: MAX_SIDE
        })
    );
    assert!(WaterGrid::new(o, 1.0, usize::MAX, usize::MAX).is_err());
    assert!(matches!(
        WaterGrid::new(o, f64::NAN, 8, 8),
        Err(WtbError::NotFinite(_))
    ));
    assert!(matches!(
        WaterGrid::new(o, f64::INFINITY, 8, 8),
        Err(WtbError::NotFinite(_))
    ));
    assert!(matches!(
        WaterGrid::new(o, 0.0, 8, 8),
        Err(WtbError::OutOfRange { .. })
    ));
    assert!(matches!(
        WaterGrid::new(o, -1.0, 8, 8),
        Err(WtbError::OutOfRange { .. })
    ));
    assert!(WaterGrid::new(o, 1e5, 8, 8).is_err());
    assert!(matches!(
        WaterGrid::new(DVec2::new(f64::NAN, 0.0), 1.0, 8, 8),
        Err(WtbError::NotFinite(_))
    ));
    assert!(WaterGrid::new(DVec2::new(0.0, f64::NEG_INFINITY), 1.0, 8, 8).is_err());
    assert!(WaterGrid::new(DVec2::new(2e9, 0.0), 1.0, 8, 8).is_err());
    assert!(WaterGrid::centred(o, 1.0, 0).is_err());
    assert!(WaterGrid::centred(DVec2::new(f64::NAN, 0.0), 1.0, 8).is_err());
    // Non-square spacing: a box's frame steps by one spacing along both u and v (§2).
    assert_eq!(
        WaterGrid::from_grid(Grid {
            origin: o,
            spacing: DVec2::new(1.0, 2.0),
            size: (8, 8)
        }),
        Err(WtbError::NonSquareSpacing { x: 1.0, z: 2.0 })
    );
}
