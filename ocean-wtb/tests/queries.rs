//! Height queries against what they answer for.
//!
//! - The drawn query against the drawn mesh, computed here from the vertices `Frame::evaluate`
//!   writes: every triangle of the documented triangulation that a vertical line meets, by
//!   Cramer's rule, the highest one where several do. Sample points: every vertex, both
//!   diagonals of every cell, across every box edge and the strip beyond it, overlaps, the
//!   shore, and random points on and off the grid, on the paper's scenarios, the island, boxes
//!   turned at odd angles with hard edges, and trains shorter than 4 cells.
//! - The continuous query against the model evaluated forwards in `f64`
//!   (`WaveSet::add_sums_f64` at dense rest positions, μ bilinear between grid points).
//! - Queries next to every side and corner of a box's rectangle, and a property test over
//!   random boxes and points: no query fails or panics.

use glam::{DVec2, DVec3, Vec3};
use ocean_core::{Depth, Pcg32, PointSums, WaveDesc};
use ocean_wtb::scenarios::{self, spec, steady_wind};
use ocean_wtb::scene::{BoxSpec, DrawnSample, Frame, HeightSample, Scene};
use ocean_wtb::{BoxFrame, Terrain, TrainSource, WaterGrid, Wind};

/// A drawn query must match the mesh to a tenth of a millimetre.
const DRAWN_TOLERANCE: f64 = 1e-4;

/// The continuous query must match the model to a millimetre.
const CONTINUOUS_TOLERANCE: f64 = 1e-3;

fn evaluate(frame: &Frame) -> Vec<Vec3> {
    let n = frame.grid().len();
    let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    frame.evaluate(&mut p, &mut q).unwrap();
    p
}

/// The drawn mesh of a grid's vertices, intersected by brute force.
struct Mesh<'a> {
    grid: &'a WaterGrid,
    pos: &'a [Vec3],
    /// The largest horizontal displacement of any vertex, grid units.
    reach: f64,
}

impl<'a> Mesh<'a> {
    fn new(grid: &'a WaterGrid, pos: &'a [Vec3]) -> Self {
        let s = grid.spacing();
        let mut reach = 0.0f64;
        for j in 0..grid.nz() {
            for i in 0..grid.nx() {
                let p = pos[j * grid.nx() + i];
                let d = DVec2::new(f64::from(p.x) - i as f64 * s, f64::from(p.z) - j as f64 * s);
                reach = reach.max(d.length() / s);
            }
        }
        Self { grid, pos, reach }
    }

    fn xz(&self, i: usize, j: usize) -> DVec2 {
        let p = self.pos[j * self.grid.nx() + i];
        DVec2::new(f64::from(p.x), f64::from(p.z))
    }

    /// The height of the highest triangle over world `at`, or `None` off the mesh.
    fn height(&self, at: DVec2) -> Option<f64> {
        self.heights(at).0
    }

    /// The highest and the lowest height of the triangles over world `at`.
    fn heights(&self, at: DVec2) -> (Option<f64>, f64) {
        let q = at - self.grid.origin();
        let g = q / self.grid.spacing();
        let r = self.reach + 1.0;
        let (nx, nz) = (self.grid.nx() as i64, self.grid.nz() as i64);
        let lo = |v: f64| (v - r).floor().max(0.0) as i64;
        let hi = |v: f64, n: i64| ((v + r).floor() as i64).min(n - 2);
        let mut best: Option<f64> = None;
        let mut lowest = f64::INFINITY;
        for j in lo(g.y)..=hi(g.y, nz) {
            for i in lo(g.x)..=hi(g.x, nx) {
                let (i, j) = (i as usize, j as usize);
                for tri in [
                    [(i, j), (i + 1, j), (i, j + 1)],
                    [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
                ] {
                    // q = a + u·(b − a) + v·(c − a), by Cramer's rule.
                    let [a, b, c] = tri.map(|(i, j)| self.xz(i, j));
                    let (e1, e2, d) = (b - a, c - a, q - a);
                    let det = e1.x * e2.y - e1.y * e2.x;
                    if det == 0.0 {
                        continue;
                    }
                    let u = (d.x * e2.y - d.y * e2.x) / det;
                    let v = (e1.x * d.y - e1.y * d.x) / det;
                    let tol = -1e-9;
                    if u < tol || v < tol || 1.0 - u - v < tol {
                        continue;
                    }
                    let y = |(i, j): (usize, usize)| f64::from(self.pos[j * self.grid.nx() + i].y);
                    let h = y(tri[0]) + u * (y(tri[1]) - y(tri[0])) + v * (y(tri[2]) - y(tri[0]));
                    best = Some(best.map_or(h, |b: f64| b.max(h)));
                    lowest = lowest.min(h);
                }
            }
        }
        (best, lowest)
    }
}

/// The sample points of a frame: vertices, both diagonals of every cell, the box edges and
/// the strips beyond them (both sides, out to 2 cells), random points on and around the grid.
fn sample_points(boxes: &[BoxFrame], frame: &Frame, pos: &[Vec3], seed: u64) -> Vec<DVec2> {
    let grid = frame.grid();
    let (nx, nz, s, o) = (grid.nx(), grid.nz(), grid.spacing(), grid.origin());
    let v = |i: usize, j: usize| {
        let p = pos[j * nx + i];
        o + DVec2::new(f64::from(p.x), f64::from(p.z))
    };
    let mut at = Vec::new();
    for j in 0..nz {
        for i in 0..nx {
            at.push(v(i, j));
            if i + 1 < nx && j + 1 < nz {
                for f in [0.25, 0.5, 0.75] {
                    at.push(v(i, j).lerp(v(i + 1, j + 1), f));
                    at.push(v(i + 1, j).lerp(v(i, j + 1), f));
                }
            }
        }
    }
    for f in boxes {
        let (u, w) = (f.u(), f.v());
        let corners = [
            f.origin(),
            f.origin() + u * f.length(),
            f.origin() + u * f.length() + w * f.width(),
            f.origin() + w * f.width(),
        ];
        for e in 0..4 {
            let (a, b) = (corners[e], corners[(e + 1) % 4]);
            let along = (b - a).normalize_or_zero();
            let out = DVec2::new(along.y, -along.x);
            let steps = ((b - a).length() / (0.25 * s)).ceil() as usize;
            for k in 0..=steps {
                let p = a.lerp(b, k as f64 / steps.max(1) as f64);
                for d in -8..=8 {
                    at.push(p + out * (0.25 * s * d as f64));
                }
            }
        }
    }
    let mut rng = Pcg32::new(seed, 9);
    let ext = DVec2::new((nx - 1) as f64, (nz - 1) as f64) * s;
    for _ in 0..10_000 {
        at.push(o - ext * 0.1 + ext * 1.2 * DVec2::new(rng.next_f64(), rng.next_f64()));
    }
    at
}

/// Drawn queries against the brute-force mesh at `points`; returns the worst error, metres.
fn check_drawn(frame: &Frame, pos: &[Vec3], points: &[DVec2], name: &str) -> f64 {
    let mesh = Mesh::new(frame.grid(), pos);
    let mut out = vec![DrawnSample::default(); points.len()];
    frame.drawn_heights_par(points, &mut out).unwrap();
    let mut worst = 0.0f64;
    for (p, o) in points.iter().zip(&out) {
        let want = mesh.height(*p);
        let got = o.triangle.map(|_| o.height);
        match (want, got) {
            (Some(w), Some(g)) => {
                let e = (w - g).abs();
                assert!(e <= DRAWN_TOLERANCE, "{name}: at {p}: drawn {g}, mesh {w}");
                worst = worst.max(e);
            }
            (None, None) => assert!(o.height == 0.0 && o.normal == DVec3::Y),
            // On the mesh's outline within the brute force's wider edge tolerance: the same
            // height either way only if the mesh is at rest there.
            (w, g) => {
                let (w, g) = (w.unwrap_or(0.0), g.unwrap_or(0.0));
                assert!(
                    (w - g).abs() <= DRAWN_TOLERANCE,
                    "{name}: at {p}: drawn {g}, mesh {w}"
                );
            }
        }
        assert!(o.height.is_finite() && (o.normal.length() - 1.0).abs() < 1e-9);
        assert!((o.shading_normal.length() - 1.0).abs() < 1e-9 && o.normal.y > 0.0);
    }
    worst
}

/// The rectangles of the boxes alive at `t`.
fn box_frames(scene: &Scene, t: f64) -> Vec<BoxFrame> {
    let plan = scene.plan(t, None).unwrap();
    plan.boxes.iter().map(|b| b.march.frame).collect()
}

fn turned_hard_edged_scene() -> Scene {
    // Two boxes at odd angles with no side smoothing (hard edges), overlapping, over a sloping
    // floor; one leaves the grid through its left and top edges.
    let (grid, terrain) = scenarios::sloping(64).unwrap();
    let mut scene = Scene::new(grid, terrain).unwrap();
    for (speed, dir, origin, width, fetch, seed) in [
        (
            7.0,
            DVec2::new(0.8, 0.6),
            DVec2::new(-10.0, 12.0),
            40.0,
            50.0,
            3,
        ),
        (
            6.0,
            DVec2::new(-0.3, 1.0),
            DVec2::new(50.0, -6.0),
            30.0,
            45.0,
            4,
        ),
    ] {
        scene
            .add_box(BoxSpec {
                smoothing: 0.0,
                ..spec(steady_wind(speed, dir, origin, width, fetch, 2, seed))
            })
            .unwrap();
    }
    scene
}

/// Trains of 2.5 to 3.8 grid cells, steep enough to matter, over the whole grid.
fn short_trains_scene() -> Scene {
    let grid = WaterGrid::new(DVec2::new(1.0e5, -3.0e4), 1.0, 64, 64).unwrap();
    let terrain = Terrain::deep(&grid);
    let mut scene = Scene::new(grid, terrain).unwrap();
    let trains = [(2.5, 0.06, 0.3), (3.1, 0.08, 1.9), (3.8, 0.1, 4.0)]
        .map(|(wavelength, amplitude, angle): (f64, f64, f64)| WaveDesc {
            amplitude,
            wavelength,
            direction: DVec2::new(angle.cos(), angle.sin()),
            phase: angle,
            depth: Depth::Deep,
        })
        .to_vec();
    scene
        .add_box(BoxSpec {
            wind: Wind {
                origin: DVec2::new(1.0e5 - 5.0, -3.0e4 + 3.0),
                ..steady_wind(6.0, DVec2::new(1.0, 0.2), DVec2::ZERO, 60.0, 70.0, 1, 1)
            },
            trains: TrainSource::Explicit(trains),
            smoothing: 3.0,
            recovery: None,
        })
        .unwrap();
    scene
}

fn scenes() -> Vec<(&'static str, Scene)> {
    vec![
        ("scenario 1", scenarios::scenario_1(64).unwrap()),
        ("scenario 2", scenarios::scenario_2(64).unwrap()),
        ("island", scenarios::island(64).unwrap()),
        ("turned, hard edges", turned_hard_edged_scene()),
        ("short trains", short_trains_scene()),
    ]
}

#[test]
fn drawn_queries_are_the_drawn_mesh() {
    let mut total = 0usize;
    for (k, (name, mut scene)) in scenes().into_iter().enumerate() {
        for t in [3.0, 11.75] {
            let boxes = box_frames(&scene, t);
            let frame = scene.frame(t, None).unwrap();
            let pos = evaluate(&frame);
            let points = sample_points(&boxes, &frame, &pos, k as u64);
            let worst = check_drawn(&frame, &pos, &points, name);
            println!(
                "{name}, t = {t}: {} points, worst {worst:.2e} m",
                points.len()
            );
            total += points.len();
        }
    }
    assert!(total >= 100_000, "{total} points");
}

/// The model evaluated forwards at world rest position `p0`: displaced (x, z) and height, from
/// each layer's waves in `f64` at μ interpolated bilinearly between grid points.
fn forward(frame: &Frame, p0: DVec2) -> (DVec2, f64) {
    let grid = frame.grid();
    let g = (p0 - grid.origin()) / grid.spacing();
    let (nx, nz) = (grid.nx(), grid.nz());
    let inside = g.x >= 0.0 && g.y >= 0.0 && g.x <= (nx - 1) as f64 && g.y <= (nz - 1) as f64;
    if !inside {
        return (p0, 0.0);
    }
    let (i, j) = ((g.x as usize).min(nx - 2), (g.y as usize).min(nz - 2));
    let (fx, fz) = (g.x - i as f64, g.y - j as f64);
    let corners = [
        (i, j, (1.0 - fx) * (1.0 - fz)),
        (i + 1, j, fx * (1.0 - fz)),
        (i, j + 1, (1.0 - fx) * fz),
        (i + 1, j + 1, fx * fz),
    ];
    let mut sums = PointSums::REST;
    for layer in frame.layers() {
        let mut mu = [0.0f64; 2];
        for (ci, cj, w) in corners {
            let m = layer.modulation.at(ci, cj);
            mu[0] += w * f64::from(m[0]);
            mu[1] += w * f64::from(m[1]);
        }
        layer
            .waves
            .add_sums_f64(p0, frame.time(), mu, &mut sums)
            .unwrap();
    }
    let h: f64 = frame.height_field().map_or(0.0, |h| {
        corners
            .iter()
            .map(|&(ci, cj, w)| w * f64::from(h[cj * nx + ci]))
            .sum()
    });
    (p0 + DVec2::new(sums.dx, sums.dz), sums.y + h)
}

#[test]
fn continuous_queries_are_the_model() {
    for (name, mut scene) in scenes() {
        let t = 7.5;
        let frame = scene.frame(t, None).unwrap();
        let grid = frame.grid();
        let (o, s) = (grid.origin(), grid.spacing());
        // Rest positions every fifth of a cell over the grid's rectangle, its edges included:
        // the surface is their image (beyond it the sea is at rest, but where the image
        // reaches past the rectangle the surface is the image, so rest positions outside are
        // not samples of it).
        let (mut at, mut want) = (Vec::new(), Vec::new());
        for j in 0..=(5 * (grid.nz() - 1) as i64) {
            for i in 0..=(5 * (grid.nx() - 1) as i64) {
                let p0 = o + DVec2::new(i as f64, j as f64) * (0.2 * s);
                let (x, y) = forward(&frame, p0);
                at.push(x);
                want.push(y);
            }
        }
        let mut out = vec![HeightSample::default(); at.len()];
        frame.continuous_heights_par(&at, &mut out).unwrap();
        let mut worst = 0.0f64;
        for ((p, w), o) in at.iter().zip(&want).zip(&out) {
            let e = (o.height - w).abs();
            assert!(
                e <= CONTINUOUS_TOLERANCE,
                "{name}: at {p}: query {}, model {w}",
                o.height
            );
            worst = worst.max(e);
        }
        println!("{name}: {} points, worst {worst:.2e} m", at.len());
    }
}

/// Points next to every side and corner of each box's grid rectangle (the cells just inside,
/// on and just outside its edges), where the modulation's fast path must not take a cell
/// outside the rectangle for one inside it.
fn around_rectangles(frame: &Frame) -> Vec<DVec2> {
    let grid = frame.grid();
    let (o, s) = (grid.origin(), grid.spacing());
    let mut at = Vec::new();
    for l in frame.layers() {
        let r = l.rect();
        let (i0, j0) = (r.i0 as f64, r.j0 as f64);
        let (i1, j1) = ((r.i0 + r.nx - 1) as f64, (r.j0 + r.nz - 1) as f64);
        let xs: Vec<f64> = [i0, i1]
            .iter()
            .flat_map(|&c| [c - 1.5, c - 0.5, c, c + 0.5])
            .collect();
        let zs: Vec<f64> = [j0, j1]
            .iter()
            .flat_map(|&c| [c - 1.5, c - 0.5, c, c + 0.5])
            .collect();
        for &x in &xs {
            for k in 0..=20 {
                let z = j0 - 2.0 + (j1 - j0 + 4.0) * f64::from(k) / 20.0;
                at.push(o + DVec2::new(x, z) * s);
                at.push(o + DVec2::new(z, x) * s);
            }
            for &z in &zs {
                at.push(o + DVec2::new(x, z) * s);
            }
        }
    }
    at
}

/// The continuous query left of and above a box's rectangle reads the modulation of the cells
/// there (zero outside the rectangle), not another row's: against the forward model.
#[test]
fn queries_beside_every_side_and_corner_of_a_rectangle() {
    for (name, mut scene) in scenes() {
        let frame = scene.frame(4.25, None).unwrap();
        let pos = evaluate(&frame);
        let at = around_rectangles(&frame);
        assert!(!at.is_empty());
        check_drawn(&frame, &pos, &at, name);
        for p in at.iter().filter(|p| frame.grid().contains(**p)) {
            // Rest positions right at these points: the model's height there, displaced.
            let (x, y) = forward(&frame, *p);
            let q = frame.continuous_height_at(x).unwrap();
            assert!(
                (q.height - y).abs() <= CONTINUOUS_TOLERANCE,
                "{name}: {p}: {} vs {y}",
                q.height
            );
        }
    }
}

/// Random boxes (any angle, size and place, partly off the grid, overlapping, hard or smooth
/// edges) and random points on and off the grid: every query answers, finite, and the drawn
/// query is the mesh.
#[test]
fn no_query_fails_on_random_boxes() {
    let mut rng = Pcg32::new(0x0c3a_9e11, 1);
    let mut points = 0usize;
    for case in 0..24 {
        let n = 24 + (rng.next_f64() * 40.0) as usize;
        let spacing = 0.5 + rng.next_f64() * 2.0;
        let origin = DVec2::new(rng.next_f64() - 0.5, rng.next_f64() - 0.5) * 2.0e4;
        let grid = WaterGrid::new(origin, spacing, n, n + case % 5).unwrap();
        let ext = DVec2::new((grid.nx() - 1) as f64, (grid.nz() - 1) as f64) * spacing;
        let mut scene = Scene::new(grid, Terrain::deep(&grid)).unwrap();
        for k in 0..1 + case % 4 {
            let a = rng.next_f64() * std::f64::consts::TAU;
            let wind = steady_wind(
                3.0 + 6.0 * rng.next_f64(),
                DVec2::new(a.cos(), a.sin()),
                origin - ext * 0.3 + ext * 1.1 * DVec2::new(rng.next_f64(), rng.next_f64()),
                (0.1 + rng.next_f64()) * ext.x,
                (0.1 + rng.next_f64()) * ext.y,
                1 + k as u32 % 3,
                (case * 10 + k) as u64,
            );
            let spec = BoxSpec {
                smoothing: if k % 2 == 0 { 0.0 } else { 4.0 * spacing },
                ..spec(wind)
            };
            // A box that cannot reach the grid is refused; that is not what is tested here.
            let _ = scene.add_box(spec);
        }
        let t = 100.0 * rng.next_f64();
        let frame = scene.frame(t, None).unwrap();
        let pos = evaluate(&frame);
        let mut at: Vec<DVec2> = (0..2000)
            .map(|_| origin - ext * 0.2 + ext * 1.4 * DVec2::new(rng.next_f64(), rng.next_f64()))
            .collect();
        at.extend(around_rectangles(&frame));
        check_drawn(&frame, &pos, &at, &format!("case {case}"));
        let mut out = vec![HeightSample::default(); at.len()];
        frame.continuous_heights(&at, &mut out).unwrap();
        assert!(
            out.iter()
                .all(|o| o.height.is_finite() && o.normal.is_finite())
        );
        points += at.len();
    }
    assert!(points > 40_000);
}

/// The largest |drawn − continuous| over cell centres and edge midpoints of the grid's
/// interior: how far the mesh is from the model between its vertices.
fn mesh_to_model(frame: &Frame) -> f64 {
    let grid = frame.grid();
    let (o, s) = (grid.origin(), grid.spacing());
    let mut at = Vec::new();
    for j in 4..grid.nz() - 4 {
        for i in 4..grid.nx() - 4 {
            for f in [
                DVec2::new(0.5, 0.5),
                DVec2::new(0.5, 0.0),
                DVec2::new(0.0, 0.5),
            ] {
                at.push(o + (DVec2::new(i as f64, j as f64) + f) * s);
            }
        }
    }
    let mut drawn = vec![DrawnSample::default(); at.len()];
    frame.drawn_heights(&at, &mut drawn).unwrap();
    let mut cont = vec![HeightSample::default(); at.len()];
    frame.continuous_heights(&at, &mut cont).unwrap();
    drawn
        .iter()
        .zip(&cont)
        .map(|(d, c)| (d.height - c.height).abs())
        .fold(0.0, f64::max)
}

/// Trains of 2.5, 3.1 and 3.8 cells are weighted by w_p = w(2, 4, λ/s) in the geometry, the
/// frame reports them and the slope variance they lose, and the mesh then holds the model
/// far better; with the filter off they are drawn whole and the mesh misses them by a large
/// share of their amplitude.
#[test]
fn grids_filter_the_trains_they_cannot_carry() {
    let mut scene = short_trains_scene();
    let expected: f64 = [(2.5, 0.06), (3.1, 0.08), (3.8, 0.1)]
        .iter()
        .map(|&(l, a): &(f64, f64)| {
            let x = ((l - 2.0) / 2.0).clamp(0.0, 1.0);
            let w = x * x * (3.0 - 2.0 * x);
            let lost = (1.0 - w) * std::f64::consts::TAU / l * a;
            0.5 * lost * lost
        })
        .sum();
    let filtered = {
        let frame = scene.frame(5.0, None).unwrap();
        let st = *frame.stats();
        assert_eq!(
            (st.trains, st.filtered_trains, st.removed_trains),
            (3, 3, 0)
        );
        let v = st.filtered_slope_variance;
        assert!(
            (v - expected).abs() <= 1e-12 * expected,
            "{v} vs {expected}"
        );
        mesh_to_model(&frame)
    };
    scene.set_train_filter(None);
    let whole = {
        let frame = scene.frame(5.0, None).unwrap();
        let st = *frame.stats();
        assert_eq!(
            (st.trains, st.filtered_trains, st.filtered_slope_variance),
            (3, 0, 0.0)
        );
        mesh_to_model(&frame)
    };
    println!("mesh to model: {whole:.4} m whole, {filtered:.4} m filtered");
    // A train of wavelength λ is cut by A·(1 − cos(π·s/λ)) between vertices: 0.06 m at
    // 2.5 cells loses 0.041 m, 0.08 m at 3.1 cells 0.037 m, 0.1 m at 3.8 cells 0.032 m.
    assert!(whole > 0.04, "{whole}");
    assert!(filtered < 0.5 * whole, "{filtered} vs {whole}");
    // A train shorter than 2 cells is left out, not built.
    scene.set_train_filter(Some(ocean_wtb::TrainFilter::new(3.5, 8.0).unwrap()));
    let st = *scene.frame(5.0, None).unwrap().stats();
    assert_eq!(
        (st.trains, st.filtered_trains, st.removed_trains),
        (1, 3, 2)
    );
}

/// A drawn answer depends on its point only: single queries, batches below and above the
/// grid-order threshold, the whole mesh built once, and any number of threads give the same
/// bits.
#[test]
fn drawn_answers_do_not_depend_on_batch_mesh_or_threads() {
    let mut scene = scenarios::island(64).unwrap();
    let frame = scene.frame(6.5, None).unwrap();
    let mut rng = Pcg32::new(17, 5);
    let at: Vec<DVec2> = (0..1000)
        .map(|_| DVec2::new(rng.next_f64() * 80.0 - 8.0, rng.next_f64() * 80.0 - 8.0))
        .collect();
    let want: Vec<DrawnSample> = at
        .iter()
        .map(|p| frame.drawn_height_at(*p).unwrap())
        .collect();
    assert!(want.iter().any(|w| w.triangle.is_none()) && want.iter().any(|w| w.height != 0.0));
    let mesh = frame.drawn_mesh().unwrap();
    for n in [255, 256, 1000] {
        let mut out = vec![DrawnSample::default(); n];
        frame.drawn_heights(&at[..n], &mut out).unwrap();
        assert!(out == want[..n], "{n} queries, one thread");
        mesh.heights(&at[..n], &mut out).unwrap();
        assert!(out == want[..n], "{n} queries on the whole mesh");
        for threads in [1, 2, 8] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| frame.drawn_heights_par(&at[..n], &mut out))
                .unwrap();
            assert!(out == want[..n], "{n} queries, {threads} threads");
            let m = pool.install(|| frame.drawn_mesh_par()).unwrap();
            pool.install(|| m.heights_par(&at[..n], &mut out)).unwrap();
            assert!(
                out == want[..n],
                "{n} queries, {threads} threads, whole mesh"
            );
        }
    }
    assert!(frame.drawn_height_at(DVec2::new(f64::NAN, 0.0)).is_err());
    assert!(mesh.height_at(DVec2::new(0.0, f64::INFINITY)).is_err());
    let mut short = vec![DrawnSample::default(); 3];
    assert!(frame.drawn_heights(&at[..4], &mut short).is_err());
}

/// Where the mesh folds over itself (two overlapping boxes whose trains sum past the
/// trochoid's limit, Σ k·A = 1.7), a vertical line meets several triangles and the drawn query
/// answers for the highest, as the brute force does.
#[test]
fn drawn_queries_take_the_highest_triangle_where_the_mesh_folds() {
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, 64, 64).unwrap();
    let mut scene = Scene::new(grid, Terrain::deep(&grid)).unwrap();
    for (k, origin) in [DVec2::new(-4.0, -4.0), DVec2::new(8.0, 6.0)]
        .into_iter()
        .enumerate()
    {
        let train = WaveDesc {
            amplitude: 0.85 * 12.0 / std::f64::consts::TAU,
            wavelength: 12.0,
            direction: DVec2::new(1.0, 0.1),
            phase: k as f64,
            depth: Depth::Deep,
        };
        scene
            .add_box(BoxSpec {
                wind: steady_wind(7.0, DVec2::new(1.0, 0.1), origin, 60.0, 60.0, 1, 1),
                trains: TrainSource::Explicit(vec![train]),
                smoothing: 0.0,
                recovery: None,
            })
            .unwrap();
    }
    let boxes = box_frames(&scene, 2.0);
    let frame = scene.frame(2.0, None).unwrap();
    let pos = evaluate(&frame);
    let at = sample_points(&boxes, &frame, &pos, 3);
    let mesh = Mesh::new(frame.grid(), &pos);
    // Points over two layers of the mesh at heights more than a centimetre apart.
    let folded = at
        .iter()
        .filter(|p| match mesh.heights(**p) {
            (Some(top), low) => top - low > 0.01,
            (None, _) => false,
        })
        .count();
    println!("{folded} of {} points under a fold", at.len());
    assert!(folded > 1000, "the scene does not fold: {folded}");
    check_drawn(&frame, &pos, &at, "folded");
}
