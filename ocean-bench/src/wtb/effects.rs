//! Figure 4 of `ocean bench wtb`: the cost of each effect alone (the paper's Table 2) on
//! scenario 2, steady and on rebuild.

use super::*;

/// One switchable effect on top of basic Gerstner waves.
struct Variant {
    name: &'static str,
    effects: Effects,
    /// Part of the static modulation cached while the boxes are still.
    cached: bool,
}

fn variants() -> Vec<Variant> {
    let base = basic_effects();
    let with = |name, cached, effects| Variant {
        name,
        effects,
        cached,
    };
    vec![
        with("basic Gerstner", true, base),
        with(
            "depth refraction (phase shift)",
            true,
            Effects {
                refraction: Refraction::PhaseShift,
                ..base
            },
        ),
        with(
            "shoaling",
            true,
            Effects {
                shoaling: true,
                ..base
            },
        ),
        with(
            "round waves",
            true,
            Effects {
                round_waves: true,
                ..base
            },
        ),
        with(
            "noise",
            false,
            Effects {
                noise: Some(Noise {
                    amplitude: 0.02,
                    seed: 7,
                }),
                ..base
            },
        ),
        with(
            "irregular height",
            false,
            Effects {
                irregular: Some(Irregular {
                    scale: 0.3,
                    frequency: 0.15,
                    envelope_wavenumber: 0.05,
                    envelope_speed: 3.0,
                }),
                ..base
            },
        ),
        with(
            "dispersion refraction",
            false,
            Effects {
                refraction: Refraction::Dispersion,
                ..base
            },
        ),
    ]
}

/// Figure 4 on scenario 2 at `side`²: every variant still (interleaved), then the cached ones
/// with every box moved before every frame (interleaved, fewer rounds).
pub(super) fn effects_table(side: usize, runs: u32) -> Result<Value, String> {
    let vs = variants();
    let mut still: Vec<Case> = vs
        .iter()
        .map(|v| {
            let (scene, boxes) = scenario_2(side, v.effects);
            Case::new(scene, boxes, false, None)
        })
        .collect();
    // A settling function closes each round: on the shared virtual machine, a parallel
    // evaluation that follows a long single-threaded phase (the per-frame work of noise,
    // irregular height and dispersion runs on one thread) is slower for a few milliseconds, and
    // without it the first variant of the next round (basic Gerstner) paid for the last one's.
    // Its time is not reported.
    let mut settle = {
        let (scene, boxes) = scenario_2(side, vs[0].effects);
        Case::new(scene, boxes, false, None)
    };
    let steady: [f64; 7] = {
        let mut fs: Vec<Box<dyn FnMut() + '_>> = still
            .iter_mut()
            .map(|c| Box::new(move || c.step()) as Box<dyn FnMut()>)
            .collect();
        fs.push(Box::new(|| {
            for _ in 0..4 {
                settle.step();
            }
        }));
        let arr: [&mut dyn FnMut(); 8] = fs
            .iter_mut()
            .map(|f| f.as_mut() as &mut dyn FnMut())
            .collect::<Vec<_>>()
            .try_into()
            .map_err(|_| "seven effect variants and the settling function".to_string())?;
        let all = interleaved_medians(runs, arr);
        std::array::from_fn(|k| all[k])
    };
    if let Some(c) = still.iter().find(|c| c.rebuilt != 0 || c.alive != 7) {
        return Err(format!(
            "effects at {side}²: {} boxes alive, {} rebuilt in the steady state",
            c.alive, c.rebuilt
        ));
    }
    let cached: Vec<usize> = (0..vs.len()).filter(|&k| vs[k].cached).collect();
    let mut moving: Vec<Case> = cached
        .iter()
        .map(|&k| {
            let (scene, boxes) = scenario_2(side, vs[k].effects);
            Case::new(scene, boxes, true, None)
        })
        .collect();
    let rr = rebuild_runs(runs);
    let rebuild: [f64; 4] = {
        let mut fs: Vec<Box<dyn FnMut() + '_>> = moving
            .iter_mut()
            .map(|c| Box::new(move || c.step()) as Box<dyn FnMut()>)
            .collect();
        let arr: [&mut dyn FnMut(); 4] = fs
            .iter_mut()
            .map(|f| f.as_mut() as &mut dyn FnMut())
            .collect::<Vec<_>>()
            .try_into()
            .map_err(|_| "four cached variants".to_string())?;
        interleaved_medians(rr, arr)
    };
    if let Some(c) = moving.iter().find(|c| c.rebuilt != 7) {
        return Err(format!(
            "effects at {side}²: {} of 7 boxes rebuilt when moving",
            c.rebuilt
        ));
    }
    let base_steady = steady[0];
    let base_rebuild = rebuild[0];
    let rows: Vec<Value> = vs
        .iter()
        .enumerate()
        .map(|(k, v)| {
            let (prep, eval) = still[k].parts();
            let mut row = json!({
                "effect": v.name,
                "cached": v.cached,
                "steady_ms": steady[k],
                "steady_prepare_ms": prep,
                "steady_evaluate_ms": eval,
                "steady_cost_ms": steady[k] - base_steady,
                "steady_ratio": steady[k] / base_steady,
            });
            if let Some(m) = cached.iter().position(|&c| c == k) {
                let (prep, eval) = moving[m].parts();
                row["rebuild_ms"] = json!(rebuild[m]);
                row["rebuild_prepare_ms"] = json!(prep);
                row["rebuild_evaluate_ms"] = json!(eval);
                row["rebuild_cost_ms"] = json!(rebuild[m] - base_rebuild);
                row["rebuild_ratio"] = json!(rebuild[m] / base_rebuild);
            }
            row
        })
        .collect();
    Ok(json!({
        "side": side,
        "boxes": 7,
        "runs_steady": runs,
        "runs_rebuild": rr,
        "rows": rows,
    }))
}
