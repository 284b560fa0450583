//! The quadrant scan of Fig. 2: every grid point inside a box is visited exactly once, for boxes of
//! every orientation and size, and nothing else is.

use std::collections::HashMap;
use std::f64::consts::PI;
use std::fmt::Write;

use glam::DVec2;
use ocean_wtb::WtbError;
use ocean_wtb::box_frame::{BoxFrame, Traversal};
use ocean_wtb::grid::WaterGrid;

/// What one traversal did, checked against the rules of `ocean_wtb::frame`.
struct Report {
    cells: usize,
    points: usize,
    max_per_cell: usize,
}

/// Traverses `frame` over `grid` and checks, for this one box:
/// - rays come in increasing order, steps in increasing order along each ray, each (ray, step) once;
/// - each cell yields at most 2 points, in increasing a, each owned by that cell by
///   `Traversal::classify`, with internal coordinates inside the cell's half-open square;
/// - every grid point that `classify` puts inside the box is visited exactly once, and no other;
/// - an independent plain-f64 evaluation of the inside rule agrees wherever a point is more than
///   1e-9 m from the box's edges (the exact rule only decides the points on the edges);
/// - the number of visited cells is at most (⌈L/s⌉ + 1)(⌈W/s⌉ + 1).
fn check(grid: &WaterGrid, frame: &BoxFrame, label: &str) -> Report {
    let t: Traversal = frame.traversal(grid).unwrap();
    let s = grid.spacing();
    let mut visits = vec![0u32; grid.len()];
    let mut last: Option<(u32, u32)> = None;
    let mut report = Report {
        cells: 0,
        points: 0,
        max_per_cell: 0,
    };
    let eps = 1e-9 * s.max(1.0) * (1.0 + frame.length().max(frame.width()) / s).max(1.0);
    t.for_each_cell(|ray, k, pts| {
        let r = ray.ray;
        if let Some((lr, lk)) = last {
            assert!(
                r > lr || (r == lr && k > lk),
                "{label}: order ({lr},{lk}) then ({r},{k})"
            );
        }
        last = Some((r, k));
        assert!(
            ray.steps.contains(&k),
            "{label}: step {k} outside {:?}",
            ray.steps
        );
        assert!(
            pts.len() <= 2,
            "{label}: {} points in cell ({r},{k})",
            pts.len()
        );
        report.cells += 1;
        report.points += pts.len();
        report.max_per_cell = report.max_per_cell.max(pts.len());
        for w in pts.windows(2) {
            assert!(w[0].a <= w[1].a, "{label}: points not in increasing a");
        }
        for p in pts {
            assert_eq!(p.index, grid.index(p.i as usize, p.j as usize).unwrap());
            assert_eq!(
                t.classify(p.i, p.j),
                Some((r, k)),
                "{label}: owner of ({}, {})",
                p.i,
                p.j
            );
            let ab = frame.internal(grid.point(p.i as usize, p.j as usize));
            assert!(
                (ab.x - p.a).abs() <= eps && (ab.y - p.b).abs() <= eps,
                "{label}: a, b"
            );
            let (kf, rf) = (k as f64 * s, r as f64 * s);
            assert!(
                p.a > kf - s - eps && p.a <= kf + eps,
                "{label}: a = {} not in step {k}",
                p.a
            );
            assert!(
                p.b > rf - s - eps && p.b <= rf + eps,
                "{label}: b = {} not in ray {r}",
                p.b
            );
            visits[p.index] += 1;
        }
    });
    for j in 0..grid.nz() {
        for i in 0..grid.nx() {
            let idx = grid.index(i, j).unwrap();
            let owned = t.classify(i as u32, j as u32).is_some();
            assert_eq!(
                visits[idx], owned as u32,
                "{label}: point ({i}, {j}) visited {} times",
                visits[idx]
            );
            let ab = frame.internal(grid.point(i, j));
            let margin = (ab.x)
                .min(frame.length() - ab.x)
                .min(ab.y)
                .min(frame.width() - ab.y);
            if margin > eps {
                assert!(owned, "{label}: inside point ({i}, {j}) {ab} not visited");
            } else if margin < -eps {
                assert!(!owned, "{label}: outside point ({i}, {j}) {ab} visited");
            }
        }
    }
    let bound = frame.step_count() as usize * frame.ray_count() as usize;
    assert!(
        report.cells <= bound,
        "{label}: {} cells > {bound}",
        report.cells
    );
    assert_eq!(t.is_empty(), report.cells == 0, "{label}");
    report
}

fn dir(deg: f64) -> DVec2 {
    let t = deg * PI / 180.0;
    DVec2::new(t.cos(), t.sin())
}

/// Directions: every degree of 0..360 by cos/sin (so 90° is (6e-17, 1)), plus the exact axes and
/// diagonals, and offsets of ±1e-9 and ±1e-12 rad around each axis.
fn directions() -> Vec<(String, DVec2)> {
    let mut out: Vec<(String, DVec2)> = (0..360)
        .map(|d| (format!("{d}deg"), dir(d as f64)))
        .collect();
    for (name, d) in [
        ("+x", DVec2::X),
        ("+z", DVec2::Y),
        ("-x", DVec2::NEG_X),
        ("-z", DVec2::NEG_Y),
        ("diag", DVec2::new(1.0, 1.0)),
        ("diag2", DVec2::new(-1.0, 1.0)),
        ("diag3", DVec2::new(-3.0, -3.0)),
        ("2:1", DVec2::new(2.0, 1.0)),
    ] {
        out.push((name.to_string(), d));
    }
    for axis in [0.0, 90.0, 180.0, 270.0] {
        for off in [1e-9, -1e-9, 1e-12, -1e-12] {
            let t = axis * PI / 180.0 + off;
            out.push((format!("{axis}{off:+e}rad"), DVec2::new(t.cos(), t.sin())));
        }
    }
    out
}

#[test]
fn every_point_once_for_all_orientations_and_sizes() {
    // A 20 × 16 grid with spacing 1 at an integer origin (so box corners on lattice points put
    // grid points exactly on cell edges), and a 17 × 19 grid with spacing 0.37 at an odd origin.
    let grids = [
        WaterGrid::new(DVec2::new(-10.0, -8.0), 1.0, 20, 16).unwrap(),
        WaterGrid::new(DVec2::new(103.713, -41.05), 0.37, 17, 19).unwrap(),
    ];
    // (length, width) in cells: smaller than a cell, exactly one, zero width, zero length,
    // fractional, a few cells, about the grid, larger than the grid.
    let sizes = [
        (0.4, 0.3),
        (1.0, 1.0),
        (6.0, 0.0),
        (0.0, 5.0),
        (3.7, 2.2),
        (9.0, 5.0),
        (14.5, 11.25),
        (60.0, 45.0),
    ];
    let dirs = directions();
    let mut cases = 0;
    let mut points = 0;
    let mut max_per_cell = 0;
    let mut saw_two = 0;
    for grid in &grids {
        let s = grid.spacing();
        let c = grid.origin() + DVec2::new(grid.nx() as f64, grid.nz() as f64) * (0.5 * s);
        // Box origins in grid units from the centre: on a lattice point, fractional, over an edge,
        // far outside.
        let origins = [
            grid.point(9, 7),
            c + DVec2::new(0.31, -0.77) * s,
            grid.origin() + DVec2::new(-2.5, 3.25) * s,
            grid.max_corner() + DVec2::new(-1.0, 0.5) * s,
            c + DVec2::new(-25.0, -25.0) * s,
            c + DVec2::new(500.0, 0.0) * s,
        ];
        for (name, d) in &dirs {
            for &(l, w) in &sizes {
                for (oi, &o) in origins.iter().enumerate() {
                    let frame = BoxFrame::new(o, *d, l * s, w * s, s).unwrap();
                    let label = format!("grid s={s} dir {name} size {l}x{w} origin #{oi}");
                    let rep = check(grid, &frame, &label);
                    cases += 1;
                    points += rep.points;
                    max_per_cell = max_per_cell.max(rep.max_per_cell);
                    if rep.max_per_cell == 2 {
                        saw_two += 1;
                    }
                }
            }
        }
    }
    // 2 grids × 384 directions × 8 sizes × 6 origins.
    assert_eq!(cases, 2 * 384 * 8 * 6);
    assert_eq!(max_per_cell, 2, "the bound of 2 is reached (rotated boxes)");
    assert!(saw_two > 1000, "{saw_two} boxes had a two-point cell");
    // 604 444 points were visited when this test was written.
    assert!(points > 500_000, "{points} points visited");
}

#[test]
fn axis_aligned_box_on_lattice_takes_both_edges() {
    // u = +x, box corner on grid point (2, 3), 4 × 3 cells: the inside rule is closed, so the
    // 5 × 4 points with i in 2..=6 and j in 3..=6 are inside, each alone in its cell; ray 0 and
    // step 0 hold the points on the b = 0 and a = 0 edges.
    let grid = WaterGrid::new(DVec2::ZERO, 2.0, 10, 10).unwrap();
    let frame = BoxFrame::new(grid.point(2, 3), DVec2::X, 8.0, 6.0, 2.0).unwrap();
    let t = frame.traversal(&grid).unwrap();
    let mut seen = Vec::new();
    t.for_each_cell(|ray, k, pts| {
        assert!(
            pts.len() == 1,
            "ray {} step {k}: {} points",
            ray.ray,
            pts.len()
        );
        seen.push((ray.ray, k, pts[0].i, pts[0].j));
    });
    let mut want = Vec::new();
    for r in 0..=3u32 {
        for k in 0..=4u32 {
            // v = (−u.z, u.x) = +z: ray r is row 3 + r, step k is column 2 + k.
            want.push((r, k, 2 + k, 3 + r));
        }
    }
    assert_eq!(seen, want);
    assert_eq!(t.rays(), 0..4);
    assert_eq!(frame.ray_count(), 4);
    assert_eq!(frame.step_count(), 5);
}

#[test]
fn v_is_to_the_right_of_u() {
    // u = +x, y up, right-handed: facing +x the right hand points to +z = v; so is u × y.
    let f = BoxFrame::new(DVec2::ZERO, DVec2::new(3.0, 0.0), 1.0, 1.0, 1.0).unwrap();
    assert_eq!(f.u(), DVec2::X);
    assert_eq!(f.v(), DVec2::Y); // (x, z) = (0, 1)
    let u3 = glam::DVec3::X;
    assert_eq!(u3.cross(glam::DVec3::Y), glam::DVec3::Z);
    // Internal coordinates round-trip.
    let g = BoxFrame::new(DVec2::new(5.0, -2.0), dir(33.0), 10.0, 4.0, 0.5).unwrap();
    let p = DVec2::new(7.25, 1.5);
    assert!((g.world(g.internal(p)) - p).length() < 1e-12);
    assert!(g.contains(g.world(DVec2::new(9.9, 3.9))));
    assert!(!g.contains(g.world(DVec2::new(10.1, 2.0))));
    assert!(!g.contains(g.world(DVec2::new(5.0, -0.1))));
}

#[test]
fn rays_start_and_steps() {
    let grid = WaterGrid::new(DVec2::new(-50.0, -50.0), 1.0, 101, 101).unwrap();
    let frame = BoxFrame::new(DVec2::new(-20.0, -10.0), dir(30.0), 30.0, 12.0, 1.0).unwrap();
    let t = frame.traversal(&grid).unwrap();
    // The box lies inside the grid: all 13 rays and all 31 steps of each are visited.
    assert_eq!(t.rays(), 0..13);
    for r in t.rays() {
        let ray = t.ray(r);
        assert_eq!(ray.steps, 0..31, "ray {r}");
        let want = frame.origin() + frame.v() * r as f64;
        assert!((ray.start - want).length() < 1e-12);
        assert_eq!(ray.direction, frame.u());
    }
    // A ray outside the traversal's range has no steps and visits nothing.
    assert_eq!(t.ray(13).steps, 0..0);
    let mut n = 0;
    t.for_each_cell_in_ray(13, |_, _| n += 1);
    assert_eq!(n, 0);
}

#[test]
fn visited_cells_scale_with_area() {
    // A 300 m × 200 m box at 37° inside a 512² grid of 1 m: it has (300 + 1)(200 + 1) cells, all
    // visited, and about 300·200 points (one per m²), at most 2 % more than the area.
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, 512, 512).unwrap();
    let frame = BoxFrame::new(DVec2::new(250.0, 30.0), dir(37.0), 300.0, 200.0, 1.0).unwrap();
    let rep = check(&grid, &frame, "37deg 300x200");
    assert_eq!(rep.cells, 301 * 201);
    let area = 300.0 * 200.0;
    assert!(
        (rep.points as f64 - area).abs() < 0.02 * area,
        "{} points",
        rep.points
    );

    // A box far larger than the grid (20 km × 20 km at 30° over 256 × 256 points): every grid
    // point is visited once, and the clipped scan visits at most the grid's area grown by 3
    // cells on each side — not the box's 4·10⁸ cells.
    let grid = WaterGrid::new(DVec2::new(1000.0, 1000.0), 1.0, 256, 256).unwrap();
    let frame = BoxFrame::new(
        DVec2::new(-5000.0, -5000.0),
        dir(30.0),
        20_000.0,
        20_000.0,
        1.0,
    )
    .unwrap();
    let f = BoxFrame::new(
        DVec2::new(-5000.0, -12000.0),
        dir(30.0),
        20_000.0,
        20_000.0,
        1.0,
    )
    .unwrap();
    let mut covered = None;
    for fr in [frame, f] {
        let t = fr.traversal(&grid).unwrap();
        let mut pts = 0usize;
        let mut cells = 0usize;
        t.for_each_cell(|_, _, p| {
            cells += 1;
            pts += p.len();
        });
        if pts == grid.len() {
            covered = Some(cells);
        }
    }
    let cells = covered.expect("one of the two big boxes covers the whole grid");
    assert!(cells <= 262 * 262, "{cells} cells for a 256² grid");
    assert!(cells >= 256 * 256, "{cells}");
}

#[test]
fn box_wholly_outside_visits_nothing() {
    // Boxes more than a cell away from the grid's rectangle visit no cell at all (closer ones may
    // visit empty cells: the clipping is conservative by one cell).
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, 32, 32).unwrap();
    for (o, d) in [
        (DVec2::new(40.0, 0.0), DVec2::X),      // beyond +x, blowing away
        (DVec2::new(-20.0, 0.0), DVec2::NEG_X), // behind the grid, blowing away
        (DVec2::new(0.0, -2.5), DVec2::NEG_Y),  // v = (1, 0): the box lies below z = -2.5
        (DVec2::new(1e8, 1e8), dir(45.0)),      // very far
    ] {
        let frame = BoxFrame::new(o, d, 10.0, 10.0, 1.0).unwrap();
        let t = frame.traversal(&grid).unwrap();
        assert!(t.is_empty(), "{o} {d}");
        let mut n = 0;
        t.for_each_cell(|_, _, _| n += 1);
        assert_eq!(n, 0);
        assert_eq!(t.classify(0, 0), None);
    }
}

#[test]
fn bad_input() {
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, 8, 8).unwrap();
    assert!(matches!(
        BoxFrame::new(DVec2::ZERO, DVec2::ZERO, 1.0, 1.0, 1.0),
        Err(WtbError::ZeroDirection(_))
    ));
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::new(f64::NAN, 1.0), 1.0, 1.0, 1.0).is_err());
    assert!(BoxFrame::new(DVec2::new(f64::INFINITY, 0.0), DVec2::X, 1.0, 1.0, 1.0).is_err());
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::X, -1.0, 1.0, 1.0).is_err());
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::X, 1.0, f64::NAN, 1.0).is_err());
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::X, 1.0, 1.0, 0.0).is_err());
    // 2²⁴ cells is the cap on either extent.
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::X, 16_777_216.0, 1.0, 1.0).is_ok());
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::X, 16_777_217.0, 1.0, 1.0).is_err());
    // Tiny and huge direction vectors are fine.
    let f = BoxFrame::new(DVec2::ZERO, DVec2::new(1e-300, 1e-300), 1.0, 1.0, 1.0).unwrap();
    assert!((f.u() - DVec2::splat(0.5f64.sqrt())).length() < 1e-15);
    assert!(BoxFrame::new(DVec2::ZERO, DVec2::new(1e300, -1e300), 1.0, 1.0, 1.0).is_ok());
    // The frame's spacing must be the grid's.
    let f = BoxFrame::new(DVec2::ZERO, DVec2::X, 4.0, 4.0, 0.5).unwrap();
    assert_eq!(
        f.traversal(&grid),
        Err(WtbError::SpacingMismatch {
            frame: 0.5,
            grid: 1.0
        })
    );
    assert!(f.obb(f64::NAN).is_err());
    assert!(f.obb(-1.0).is_err());
}

#[test]
fn obb_encloses_the_box() {
    // A 40 × 10 box at 30° with crest height 2: the OBB's centre is the rectangle's centre at
    // y = 0, its axes are u, y, v and its half extents (20, 2, 5); its corners are the box's
    // corners at y = ±2.
    let f = BoxFrame::new(DVec2::new(3.0, 4.0), dir(30.0), 40.0, 10.0, 1.0).unwrap();
    let obb = f.obb(2.0).unwrap();
    let c = f.world(DVec2::new(20.0, 5.0));
    assert!((obb.centre() - glam::DVec3::new(c.x, 0.0, c.y)).length() < 1e-12);
    assert_eq!(obb.half_extents(), glam::DVec3::new(20.0, 2.0, 5.0));
    let corner = obb.point(glam::DVec3::new(1.0, 1.0, 1.0));
    let want = f.world(DVec2::new(40.0, 10.0));
    assert!((corner - glam::DVec3::new(want.x, 2.0, want.y)).length() < 1e-12);
    // Every corner of the box, at y = ±2, is a corner of the OBB.
    for (tx, ty, tz) in [
        (-1.0, -1.0, -1.0),
        (1.0, 1.0, -1.0),
        (-1.0, 1.0, 1.0),
        (1.0, -1.0, 1.0),
    ] {
        let p = obb.point(glam::DVec3::new(tx, ty, tz));
        let w = f.world(DVec2::new(20.0 * (1.0 + tx), 5.0 * (1.0 + tz)));
        assert!((p - glam::DVec3::new(w.x, 2.0 * ty, w.y)).length() < 1e-12);
    }
}

#[test]
fn traversal_snapshot() {
    // A 3.5 × 2 box at 30° over a 6 × 6 grid: the full list of (ray, step) → points, to catch any
    // change of the conventions.
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, 6, 6).unwrap();
    let frame = BoxFrame::new(DVec2::new(1.0, 0.5), dir(30.0), 3.5, 2.0, 1.0).unwrap();
    let t = frame.traversal(&grid).unwrap();
    let mut out = String::new();
    let mut owners = HashMap::new();
    t.for_each_cell(|ray, k, pts| {
        write!(out, "ray {} step {k}:", ray.ray).unwrap();
        for p in pts {
            write!(out, " ({},{}) a={:.4} b={:.4}", p.i, p.j, p.a, p.b).unwrap();
            owners.insert((p.i, p.j), (ray.ray, k));
        }
        out.push('\n');
    });
    insta::assert_snapshot!(out);
}
