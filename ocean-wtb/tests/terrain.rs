//! Terrain: heights on the water grid, depth, land and bilinear sampling.

use glam::DVec2;
use ocean_core::Depth;
use ocean_wtb::WtbError;
use ocean_wtb::grid::WaterGrid;
use ocean_wtb::terrain::{Terrain, to_depth};

fn grid() -> WaterGrid {
    // 3 × 2 points, 2 m apart, from (0, 0).
    WaterGrid::new(DVec2::ZERO, 2.0, 3, 2).unwrap()
}

#[test]
fn heights_depths_and_land() {
    // Row 0: −10, −4, 0; row 1: −6, 2, 1.5 (metres above the sea at rest).
    let t = Terrain::from_heights(&grid(), vec![-10.0, -4.0, 0.0, -6.0, 2.0, 1.5]).unwrap();
    assert_eq!(t.height(1, 0), -4.0);
    assert_eq!(t.depth(0, 0), 10.0);
    assert_eq!(t.water_depth(0, 0), Some(Depth::Finite(10.0)));
    // Height 0 is land: no water above it.
    assert!(t.is_land(2, 0));
    assert_eq!(t.water_depth(2, 0), None);
    assert!(t.is_land(1, 1) && !t.is_land(0, 1));
    assert!(t.has_land());
    // Outside the grid: deep water.
    assert_eq!(t.height(3, 0), f32::NEG_INFINITY);
    assert_eq!(t.depth(0, 2), f64::INFINITY);
    assert_eq!(t.water_depth(9, 9), Some(Depth::Deep));
    assert!(!t.is_land(3, 0));
    assert_eq!(t.height_at_index(5), 1.5);
    assert_eq!(t.height_at_index(6), f32::NEG_INFINITY);
}

#[test]
fn bilinear_sampling() {
    let t = Terrain::from_heights(&grid(), vec![-10.0, -4.0, 0.0, -6.0, 2.0, 1.5]).unwrap();
    // At grid points: the stored heights exactly.
    assert_eq!(t.height_at(DVec2::new(2.0, 0.0)), -4.0);
    assert_eq!(t.height_at(DVec2::new(4.0, 2.0)), 1.5);
    // Midway along x in row 0: (−10 − 4)/2 = −7; cell centre of the first cell:
    // (−10 − 4 − 6 + 2)/4 = −4.5; a quarter of the way: (1, 0.5) → x-fraction 0.5, z-fraction
    // 0.25: row 0 −7, row 1 −2, → −7 + 0.25·5 = −5.75.
    assert_eq!(t.height_at(DVec2::new(1.0, 0.0)), -7.0);
    assert_eq!(t.height_at(DVec2::new(1.0, 1.0)), -4.5);
    assert_eq!(t.height_at(DVec2::new(1.0, 0.5)), -5.75);
    assert_eq!(t.depth_at(DVec2::new(1.0, 0.5)), 5.75);
    // The far edge uses the last cell: (3, 2) lies between 2 and 1.5 → 1.75, land.
    assert_eq!(t.height_at(DVec2::new(3.0, 2.0)), 1.75);
    assert!(t.is_land_at(DVec2::new(3.0, 2.0)));
    // Outside the grid's rectangle: deep water.
    assert_eq!(t.height_at(DVec2::new(-0.01, 1.0)), f64::NEG_INFINITY);
    assert_eq!(t.depth_at(DVec2::new(4.01, 1.0)), f64::INFINITY);
    assert_eq!(t.height_at(DVec2::new(f64::NAN, 1.0)), f64::NEG_INFINITY);
}

#[test]
fn deep_sea_and_constructors() {
    let g = grid();
    let deep = Terrain::deep(&g);
    assert!(!deep.has_land());
    assert_eq!(deep.heights(), None);
    assert_eq!(deep.water_depth(1, 1), Some(Depth::Deep));
    assert_eq!(deep.height_at(DVec2::new(1.0, 1.0)), f64::NEG_INFINITY);
    // from_fn samples each point's world position: height = x − 5 gives −5, −3, −1 per row.
    let t = Terrain::from_fn(&g, |p| (p.x - 5.0) as f32).unwrap();
    assert_eq!(t.heights().unwrap(), &[-5.0, -3.0, -1.0, -5.0, -3.0, -1.0]);
    assert!(!t.has_land());
    let s = Terrain::from_slice(&g, &[-5.0, -3.0, -1.0, -5.0, -3.0, -1.0]).unwrap();
    assert_eq!(s, t);
    assert_eq!(*t.grid(), g);
    assert_eq!(to_depth(0.0), None);
    assert_eq!(to_depth(f64::NAN), None);
    assert_eq!(to_depth(f64::INFINITY), Some(Depth::Deep));
}

#[test]
fn rejects_bad_terrain() {
    let g = grid();
    assert_eq!(
        Terrain::from_heights(&g, vec![0.0; 5]),
        Err(WtbError::TerrainSize {
            expected: 6,
            got: 5
        })
    );
    assert_eq!(
        Terrain::from_slice(&g, &[0.0; 7]),
        Err(WtbError::TerrainSize {
            expected: 6,
            got: 7
        })
    );
    assert_eq!(
        Terrain::from_heights(&g, vec![0.0, 0.0, f32::NAN, 0.0, f32::INFINITY, 0.0]),
        Err(WtbError::TerrainNotFinite { index: 2 })
    );
    assert_eq!(
        Terrain::from_fn(&g, |p| if p.y > 0.0 { f32::NEG_INFINITY } else { -1.0 }),
        Err(WtbError::TerrainNotFinite { index: 3 })
    );
}
