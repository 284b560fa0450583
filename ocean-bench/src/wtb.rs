//! `ocean bench wtb`: the wave train boxes figures (performance against the paper's §3).
//!
//! Every figure is a median of interleaved rounds ([`interleaved_medians`]) taken in the same
//! run as the figure it is compared with:
//!
//! 1. **Scenario 1** (the paper's §3: two boxes covering most of the grid, one train and two
//!    trains, depth refraction by phase shift) on 64² … 2048² grids, 1 m apart, over a floor
//!    sloping from 30 m to 1 m deep: `Scene::frame` (prepare) + `Frame::evaluate_par`
//!    (evaluate) with still boxes, against the memory baseline (the same output buffers
//!    written once, with the same threads and task partition).
//! 2. **Scaling**: t(2048²) / t(512²), the two frames of figure 1 timed again in the same
//!    rounds.
//! 3. **Culling**: the paper's scenario 2 (seven boxes, one train each, 256²) with a frustum that
//!    sees every box against one that sees none.
//! 4. **Effects** (the paper's Table 2, on scenario 2 at 256² and 512²): each effect alone on top
//!    of basic Gerstner waves, in the steady state (still boxes, static modulation cached) and,
//!    for the effects that are cached, on rebuild (every box moved before every frame).
//! 5. **Height queries**: `Frame::continuous_heights[_par]` and `Frame::drawn_heights[_par]` at random points over
//!    scenario 1 at 512².
//! 6. **GPU**: scenario 1's frames on the GPU (unless `--no-gpu`).
//! 7. **Instruction sets**: scenario 1's layers at 1024² on one thread with each kernel this
//!    CPU can run (`ocean_core::Isa`), against a one-thread memory baseline, outputs compared
//!    bit for bit.

use std::time::Instant;

use glam::{DVec2, DVec3, Vec3};
use ocean_core::Isa;
use ocean_core::camera::{Camera, DepthConvention, Far, Projection};
use ocean_core::frustum::Frustum;
use ocean_core::rng::Pcg32;
use ocean_wtb::effects::{Effects, Irregular, Noise, Refraction};
use ocean_wtb::scenarios;
use ocean_wtb::scene::{
    BoxId, BoxSpec, Coverage, DrawnSample, HeightSample, QUERY_TOLERANCE, Scene,
};
use serde_json::{Value, json};

use crate::options::BenchOptions;
use crate::timing::{cpu_name, interleaved_medians, memory_baseline};

mod effects;
mod isa;
mod print;

use effects::effects_table;
use isa::isa_figure;
pub use print::print;

/// Grid sides of figure 1.
const SIDES: [usize; 6] = [64, 128, 256, 512, 1024, 2048];
/// Grid spacing, metres (the scenarios': the boxes grow with the grid).
const SPACING: f64 = scenarios::SPACING;
/// Frame step, seconds: every timed frame is a new instant.
const DT: f64 = 1.0 / 60.0;
/// Start time, seconds.
const T0: f64 = 1234.5;
/// Number of height queries per call.
const QUERIES: usize = 1 << 15;

const TARGET_RATIO_1024: f64 = 3.0;
const TARGET_SCALING: (f64, f64) = (13.0, 19.0);
const TARGET_CULLING: f64 = 0.02;
const TARGET_QUERIES: f64 = 5.0e6;

/// Rounds for the rebuild figures, where every frame marches every ray of every box again:
/// half of `runs` (at least 5).
fn rebuild_runs(runs: u32) -> u32 {
    (runs / 2).max(5).min(runs)
}

/// Basic Gerstner waves only.
fn basic_effects() -> Effects {
    Effects {
        refraction: Refraction::Off,
        shoaling: false,
        ..Effects::default()
    }
}

/// `ocean_wtb::scenarios::build`, with each box's id beside its spec (moved every frame by
/// the rebuild figures).
fn build(side: usize, effects: Effects, specs: Vec<BoxSpec>) -> (Scene, Vec<(BoxId, BoxSpec)>) {
    let (scene, ids) = scenarios::build(side, effects, &specs).expect("benchmark scene");
    (scene, ids.into_iter().zip(specs).collect())
}

/// The paper's scenario 1 (`ocean_wtb::scenarios::scenario_1_boxes`) on `side`².
fn scenario_1(side: usize, effects: Effects) -> (Scene, Vec<(BoxId, BoxSpec)>) {
    build(side, effects, scenarios::scenario_1_boxes(side))
}

/// The paper's scenario 2 (`ocean_wtb::scenarios::scenario_2_boxes`) on `side`².
fn scenario_2(side: usize, effects: Effects) -> (Scene, Vec<(BoxId, BoxSpec)>) {
    build(side, effects, scenarios::scenario_2_boxes(side))
}

/// A camera straight above the centre of a `side`² grid, looking down (`up = false`, its view
/// holds the whole grid and every box) or straight up (nothing of the water in view).
fn frustum(side: usize, up: bool) -> Frustum {
    let c = (side - 1) as f64 * SPACING / 2.0;
    let h = 1.5 * side as f64 * SPACING;
    let eye = DVec3::new(c, h, c);
    let target = DVec3::new(c, if up { 2.0 * h } else { 0.0 }, c);
    let cam = Camera::look_at(
        eye,
        target,
        DVec3::Z,
        Projection::Perspective {
            fov_y: 1.2,
            aspect: 1.0,
            near: 0.1,
            far: Far::Finite(4.0 * h),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .expect("benchmark camera");
    Frustum::from_camera(&cam).expect("benchmark frustum")
}

/// One timed workload: a scene, its output buffers and the split of its frame times.
struct Case {
    scene: Scene,
    /// Boxes moved before every frame (empty: still boxes, the steady state).
    moving: Vec<(BoxId, BoxSpec)>,
    view: Option<Frustum>,
    /// Evaluate incrementally into the kept buffers (`Frame::evaluate_incremental`).
    incremental: Option<Coverage>,
    pos: Vec<Vec3>,
    nrm: Vec<Vec3>,
    t: f64,
    calls: u64,
    prepare: Vec<f64>,
    evaluate: Vec<f64>,
    /// Boxes rebuilt / culled in the last frame (sanity checks of the setup).
    rebuilt: usize,
    culled: usize,
    alive: usize,
    trains: usize,
}

impl Case {
    fn new(
        scene: Scene,
        boxes: Vec<(BoxId, BoxSpec)>,
        moving: bool,
        view: Option<Frustum>,
    ) -> Self {
        let n = scene.grid().len();
        Self {
            scene,
            moving: if moving { boxes } else { Vec::new() },
            view,
            incremental: None,
            pos: vec![Vec3::ZERO; n],
            nrm: vec![Vec3::ZERO; n],
            t: T0,
            calls: 0,
            prepare: Vec::new(),
            evaluate: Vec::new(),
            rebuilt: 0,
            culled: 0,
            alive: 0,
            trains: 0,
        }
    }

    /// One frame: move the boxes (if moving), prepare, evaluate on all threads.
    fn step(&mut self) {
        self.calls += 1;
        self.t += DT;
        if !self.moving.is_empty() {
            // A quarter cell back and forth: a new frame for every box, every frame.
            let dx = if self.calls.is_multiple_of(2) {
                0.0
            } else {
                0.25 * SPACING
            };
            for (id, s) in &self.moving {
                let mut s = s.clone();
                s.wind.origin.x += dx;
                self.scene.update_box(*id, s).expect("moved box");
            }
        }
        let start = Instant::now();
        let frame = self.scene.frame(self.t, self.view.as_ref()).expect("frame");
        let mid = Instant::now();
        match &mut self.incremental {
            Some(coverage) => frame
                .evaluate_incremental(coverage, &mut self.pos, &mut self.nrm)
                .expect("evaluate"),
            None => frame
                .evaluate_par(&mut self.pos, &mut self.nrm)
                .expect("evaluate"),
        }
        let end = Instant::now();
        let stats = *frame.stats();
        std::hint::black_box((&self.pos, &self.nrm));
        self.prepare.push((mid - start).as_secs_f64() * 1e3);
        self.evaluate.push((end - mid).as_secs_f64() * 1e3);
        (self.rebuilt, self.culled, self.alive) = (stats.rebuilt, stats.culled, stats.alive);
        self.trains = stats.trains;
    }

    /// Medians of the prepare and evaluate parts over the calls after the two warm-up rounds
    /// of [`interleaved_medians`] (each round calls every function twice).
    fn parts(&self) -> (f64, f64) {
        (
            median_after(&self.prepare, 4),
            median_after(&self.evaluate, 4),
        )
    }
}

fn median_after(v: &[f64], skip: usize) -> f64 {
    let mut v: Vec<f64> = v
        .iter()
        .skip(skip.min(v.len().saturating_sub(1)))
        .copied()
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The memory baseline on a `side`² grid: its own buffers, written once per call.
struct Baseline {
    side: usize,
    pos: Vec<Vec3>,
    nrm: Vec<Vec3>,
}

impl Baseline {
    fn new(side: usize) -> Self {
        Self {
            side,
            pos: vec![Vec3::ZERO; side * side],
            nrm: vec![Vec3::ZERO; side * side],
        }
    }

    fn step(&mut self) {
        memory_baseline(self.side, &mut self.pos, &mut self.nrm);
    }
}

pub fn wtb(args: &BenchOptions) -> Result<Value, String> {
    let runs = args.runs;
    let threads = rayon::current_num_threads();
    let started = Instant::now();

    // 1. Scenario 1 on every grid.
    let mut scenario = Vec::new();
    let mut kept = Vec::new();
    for side in SIDES {
        let (scene, boxes) = scenario_1(side, scenarios::paper_effects());
        let mut case = Case::new(scene, boxes, false, None);
        let mut base = Baseline::new(side);
        let [baseline_ms, frame_ms] =
            interleaved_medians(runs, [&mut || base.step(), &mut || case.step()]);
        if case.rebuilt != 0 || case.alive != 2 {
            return Err(format!(
                "scenario 1 at {side}²: {} boxes alive, {} rebuilt in the steady state",
                case.alive, case.rebuilt
            ));
        }
        let (prepare_ms, evaluate_ms) = case.parts();
        scenario.push(json!({
            "side": side,
            "points": side * side,
            "runs": runs,
            "trains": case.trains,
            "prepare_ms": prepare_ms,
            "evaluate_ms": evaluate_ms,
            "frame_ms": frame_ms,
            "memory_baseline_ms": baseline_ms,
            "frame_over_baseline": frame_ms / baseline_ms,
            "ns_per_point": frame_ms * 1e6 / (side * side) as f64,
        }));
        if side == 512 || side == 2048 {
            kept.push(case);
        }
    }
    let at = |side: usize| {
        scenario
            .iter()
            .find(|c| c["side"] == side)
            .expect("measured side")
    };
    let ratio_1024 = at(1024)["frame_over_baseline"].as_f64().unwrap_or(f64::NAN);
    // 2. Scaling: both grids again, interleaved in the same rounds, so that a slow spell of
    // the machine between two figure-1 measurements cannot bend the ratio.
    let (t512, t2048) = match kept.as_mut_slice() {
        [small, large] => {
            let [a, b] = interleaved_medians(runs, [&mut || small.step(), &mut || large.step()]);
            (a, b)
        }
        _ => return Err("scaling: the 512² and 2048² cases".to_string()),
    };
    drop(kept);
    let scaling = t2048 / t512;

    // 3. Culling on scenario 2 at 256².
    let culling = {
        let side = 256;
        let (scene, boxes) = scenario_2(side, scenarios::paper_effects());
        let mut all = Case::new(
            scene.clone(),
            boxes.clone(),
            false,
            Some(frustum(side, false)),
        );
        let mut none = Case::new(
            scene.clone(),
            boxes.clone(),
            false,
            Some(frustum(side, true)),
        );
        // The same two views with buffers kept from frame to frame (an engine's vertex
        // buffers): only what visible boxes cover, now or in the previous frame, is written.
        let incremental = |view| {
            let mut c = Case::new(scene.clone(), boxes.clone(), false, Some(view));
            c.incremental = Some(Coverage::everything(c.scene.grid()));
            c
        };
        let mut all_inc = incremental(frustum(side, false));
        let mut none_inc = incremental(frustum(side, true));
        let mut no_view = Case::new(scene, boxes, false, None);
        let mut base = Baseline::new(side);
        let [
            baseline_ms,
            all_ms,
            none_ms,
            no_view_ms,
            all_inc_ms,
            none_inc_ms,
        ] = interleaved_medians(
            runs,
            [
                &mut || base.step(),
                &mut || all.step(),
                &mut || none.step(),
                &mut || no_view.step(),
                &mut || all_inc.step(),
                &mut || none_inc.step(),
            ],
        );
        if all.culled != 0 || none.culled != 7 || all.alive != 7 {
            return Err(format!(
                "culling setup: {} of {} culled with the full view, {} with the empty one",
                all.culled, all.alive, none.culled
            ));
        }
        let (all_prep, all_eval) = all.parts();
        let (none_prep, none_eval) = none.parts();
        json!({
            "side": side,
            "boxes": 7,
            "runs": runs,
            "all_visible_ms": all_ms,
            "all_visible_prepare_ms": all_prep,
            "all_visible_evaluate_ms": all_eval,
            "none_visible_ms": none_ms,
            "none_visible_prepare_ms": none_prep,
            "none_visible_evaluate_ms": none_eval,
            "no_frustum_ms": no_view_ms,
            "memory_baseline_ms": baseline_ms,
            "none_over_all": none_ms / all_ms,
            "baseline_over_all": baseline_ms / all_ms,
            "incremental_all_visible_ms": all_inc_ms,
            "incremental_none_visible_ms": none_inc_ms,
            "incremental_none_over_all": none_inc_ms / all_inc_ms,
        })
    };

    // 4. Effects on scenario 2.
    let mut effect_tables = Vec::new();
    for side in [256, 512] {
        effect_tables.push(effects_table(side, runs)?);
    }

    // 5. Height queries on scenario 1 at 512².
    let queries = {
        let side = 512;
        let (mut scene, _) = scenario_1(side, scenarios::paper_effects());
        let frame = scene.frame(T0, None).map_err(|e| e.to_string())?;
        let mut rng = Pcg32::new(0x5157_4254, 3);
        let far = (side - 1) as f64 * SPACING;
        let at: Vec<DVec2> = (0..QUERIES)
            .map(|_| DVec2::new(rng.next_f64() * far, rng.next_f64() * far))
            .collect();
        let blank = HeightSample {
            height: 0.0,
            normal: DVec3::Y,
            rest: DVec2::ZERO,
            residual: 0.0,
        };
        let (mut one, mut par) = (vec![blank; QUERIES], vec![blank; QUERIES]);
        // Measured apart, not interleaved: a parallel call that follows a long single-threaded
        // one is slower for a few milliseconds on the shared virtual machine.
        let [threads_ms] = interleaved_medians(
            runs,
            [&mut || {
                frame
                    .continuous_heights_par(&at, &mut par)
                    .expect("queries")
            }],
        );
        let [single_ms] = interleaved_medians(
            runs,
            [&mut || frame.continuous_heights(&at, &mut one).expect("queries")],
        );
        let worst = par.iter().map(|s| s.residual).fold(0.0, f64::max);
        // Queries whose Newton iteration stopped above its tolerance, and of those the ones
        // within 1 m of the grid's edge (where the rest point lies outside the grid).
        let unconverged: Vec<&DVec2> = at
            .iter()
            .zip(&par)
            .filter(|(_, s)| s.residual > QUERY_TOLERANCE)
            .map(|(p, _)| p)
            .collect();
        let near_edge = unconverged
            .iter()
            .filter(|p| p.min_element() < 1.0 || p.max_element() > far - 1.0)
            .count();
        let per_s = QUERIES as f64 / (threads_ms * 1e-3);
        // The drawn surface: the same points on the frame's triangles.
        let (mut drawn_one, mut drawn_par) = (
            vec![DrawnSample::default(); QUERIES],
            vec![DrawnSample::default(); QUERIES],
        );
        let [drawn_threads_ms] = interleaved_medians(
            runs,
            [&mut || {
                frame
                    .drawn_heights_par(&at, &mut drawn_par)
                    .expect("queries")
            }],
        );
        let [drawn_single_ms] = interleaved_medians(
            runs,
            [&mut || frame.drawn_heights(&at, &mut drawn_one).expect("queries")],
        );
        assert!(
            drawn_one == drawn_par,
            "drawn queries depend on the thread count"
        );
        // The whole mesh built once (about one evaluation of the grid), then batches that
        // only walk it: many batches on one frame.
        let [mesh_ms] = interleaved_medians(
            runs,
            [&mut || {
                std::hint::black_box(frame.drawn_mesh_par().expect("mesh"));
            }],
        );
        let mesh = frame.drawn_mesh_par().map_err(|e| e.to_string())?;
        let [walk_ms] = interleaved_medians(
            runs,
            [&mut || mesh.heights_par(&at, &mut drawn_one).expect("queries")],
        );
        assert!(drawn_one == drawn_par, "the whole mesh answers otherwise");
        let mesh_to_model = drawn_par
            .iter()
            .zip(&par)
            .filter(|(d, _)| d.triangle.is_some())
            .map(|(d, c)| (d.height - c.height).abs())
            .fold(0.0, f64::max);
        json!({
            "side": side,
            "drawn_threads_ms": drawn_threads_ms,
            "drawn_single_thread_ms": drawn_single_ms,
            "drawn_per_s_threads": QUERIES as f64 / (drawn_threads_ms * 1e-3),
            "drawn_per_s_single_thread": QUERIES as f64 / (drawn_single_ms * 1e-3),
            "drawn_mesh_build_ms": mesh_ms,
            "drawn_mesh_walk_ms": walk_ms,
            "drawn_mesh_per_s_threads": QUERIES as f64 / (walk_ms * 1e-3),
            "max_drawn_minus_continuous_m": mesh_to_model,
            "queries": QUERIES,
            "runs": runs,
            "single_thread_ms": single_ms,
            "threads_ms": threads_ms,
            "threads": threads,
            "per_s_single_thread": QUERIES as f64 / (single_ms * 1e-3),
            "per_s_threads": per_s,
            "per_s_per_core_threads": per_s / threads as f64,
            "worst_residual_m": worst,
            "tolerance_m": QUERY_TOLERANCE,
            "above_tolerance": unconverged.len(),
            "above_tolerance_within_1m_of_edge": near_edge,
        })
    };

    // 6. The same frames on the GPU (LayersPass from the CPU's march, and WtbMarchPass marching
    // the rays itself), scenario 1 at 512² and 1024².
    let gpu = if args.no_gpu {
        json!({ "unavailable": "skipped (--no-gpu)" })
    } else {
        match crate::gpu::Bench::new() {
            Ok(bench) => {
                let mut sizes = Vec::new();
                for side in [512, 1024] {
                    let (mut scene, _) = scenario_1(side, scenarios::paper_effects());
                    let frame = scene.frame(T0, None).map_err(|e| e.to_string())?;
                    let mut v = bench.layers(&frame, runs)?;
                    v["side"] = json!(side);
                    v["march"] = bench.march(&scene, T0, runs)?;
                    sizes.push(v);
                }
                json!({ "device": bench.describe(), "scenario_1": sizes })
            }
            Err(e) => json!({ "unavailable": e }),
        }
    };

    // 7. The layers kernel on each instruction set this CPU has, one thread.
    let isa = isa_figure(runs)?;

    // Judged on the incremental path: with buffers kept between frames, a grid no box covers
    // needs no rewriting, so the ratio measures the wave work culling removes (the paper's
    // "water calculation"); the full-rewrite ratio is reported beside it.
    let culling_ratio = culling["incremental_none_over_all"]
        .as_f64()
        .unwrap_or(f64::NAN);
    let queries_per_s = queries["per_s_threads"].as_f64().unwrap_or(f64::NAN);
    let drawn_per_s = queries["drawn_per_s_threads"].as_f64().unwrap_or(f64::NAN);
    let report = json!({
        "suite": "wtb",
        "cpu": cpu_name(),
        "threads": threads,
        "isa": format!("{:?}", Isa::best()),
        "runs": runs,
        "scenario_1": scenario,
        "scaling": {
            "runs": runs,
            "t_512_ms": t512,
            "t_2048_ms": t2048,
            "t2048_over_t512": scaling,
        },
        "culling": culling,
        "effects": effect_tables,
        "queries": queries,
        "gpu": gpu,
        "isa_kernels": isa,
        "targets": [
            target("scenario 1 at 1024²: frame / memory baseline", "max", json!(TARGET_RATIO_1024), ratio_1024, ratio_1024 <= TARGET_RATIO_1024),
            target("scaling t(2048²) / t(512²)", "range", json!([TARGET_SCALING.0, TARGET_SCALING.1]), scaling, (TARGET_SCALING.0..=TARGET_SCALING.1).contains(&scaling)),
            target("culling: none visible / all visible (incremental)", "max", json!(TARGET_CULLING), culling_ratio, culling_ratio <= TARGET_CULLING),
            target("continuous height queries per second, all threads", "min", json!(TARGET_QUERIES), queries_per_s, queries_per_s >= TARGET_QUERIES),
            target("drawn height queries per second, all threads", "min", json!(TARGET_QUERIES), drawn_per_s, drawn_per_s >= TARGET_QUERIES),
        ],
        "wall_s": started.elapsed().as_secs_f64(),
    });
    Ok(report)
}

fn target(name: &str, kind: &str, bound: Value, measured: f64, met: bool) -> Value {
    json!({ "name": name, "kind": kind, "target": bound, "measured": measured, "met": met })
}
