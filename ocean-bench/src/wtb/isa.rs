//! Figure 7 of `ocean bench wtb`: scenario 1's layers with each instruction set this CPU runs,
//! one thread, outputs compared bit for bit.

use super::*;

/// Side of figure 7's grid.
const ISA_SIDE: usize = 1024;

/// Figure 7: scenario 1's layers (`ocean_core::evaluate_layers_isa`) at 1024² on one thread,
/// on every instruction set this CPU has, interleaved with a one-thread memory baseline. The
/// outputs are compared bit for bit as well (they must agree: `ocean_core::isa`).
pub(super) fn isa_figure(runs: u32) -> Result<Value, String> {
    let (mut scene, _) = scenario_1(ISA_SIDE, scenarios::paper_effects());
    let frame = scene.frame(T0, None).map_err(|e| e.to_string())?;
    let layers = frame.layers();
    let grid = frame.grid().grid();
    let n = ISA_SIDE * ISA_SIDE;
    let sets: Vec<Isa> = Isa::ALL.into_iter().filter(|i| i.is_available()).collect();
    let mut outs: Vec<(Vec<Vec3>, Vec<Vec3>)> = sets
        .iter()
        .map(|_| (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]))
        .collect();
    let (mut bp, mut bq) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); sets.len() + 1];
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .map_err(|e| e.to_string())?;
    one.install(|| -> Result<(), String> {
        for round in 0..runs + 2 {
            let t = Instant::now();
            memory_baseline(ISA_SIDE, &mut bp, &mut bq);
            std::hint::black_box((&bp, &bq));
            let base = t.elapsed().as_secs_f64() * 1e3;
            if round >= 2 {
                times[0].push(base);
            }
            for (k, (&isa, (p, q))) in sets.iter().zip(outs.iter_mut()).enumerate() {
                let t = Instant::now();
                ocean_core::evaluate_layers_isa(
                    isa,
                    grid,
                    frame.time(),
                    &layers,
                    frame.height_field(),
                    p,
                    q,
                )
                .map_err(|e| e.to_string())?;
                std::hint::black_box((&p, &q));
                if round >= 2 {
                    times[k + 1].push(t.elapsed().as_secs_f64() * 1e3);
                }
            }
        }
        Ok(())
    })?;
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let baseline_ms = median(&mut times[0]);
    let portable_ms = median(&mut times[1].clone());
    let identical = outs.windows(2).all(|w| {
        let bits = |v: &[Vec3]| {
            v.iter()
                .map(|p| p.to_array().map(f32::to_bits))
                .collect::<Vec<_>>()
        };
        bits(&w[0].0) == bits(&w[1].0) && bits(&w[0].1) == bits(&w[1].1)
    });
    if !identical {
        return Err("instruction sets disagree on scenario 1's bits".to_string());
    }
    let kernels: Vec<Value> = sets
        .iter()
        .zip(times.iter_mut().skip(1))
        .map(|(isa, t)| {
            let ms = median(t);
            json!({
                "isa": format!("{isa:?}"),
                "ms": ms,
                "over_memory_baseline": ms / baseline_ms,
                "speed_over_portable": portable_ms / ms,
            })
        })
        .collect();
    Ok(json!({
        "side": ISA_SIDE,
        "runs": runs,
        "threads": 1,
        "memory_baseline_ms": baseline_ms,
        "kernels": kernels,
        "bit_identical": identical,
    }))
}
