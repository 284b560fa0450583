//! Layered control (§2.3): what runs this frame, chosen for a time budget.
//!
//! The paper orders the work so that the most important comes first and the rest can be dropped
//! when time is short: culling of whole boxes, then the basic wave trains, then the effects,
//! and the capillary noise last. [`select`] follows that order greedily against a [`CostModel`]:
//!
//! 1. culling is free here (it happens before, on whole boxes);
//! 2. trains are admitted rank by rank: every visible box's largest train, then every box's
//!    second largest, and so on, a train at a time while it fits;
//! 3. then each enabled effect in the order refraction, shoaling, round waves, irregular
//!    height, beach;
//! 4. then the noise.
//!
//! With [`Budget::Unlimited`] everything enabled runs; with [`Budget::Explicit`] the caller's
//! choice is used as it is. The cost model starts from defaults measured on this project's
//! benchmark machine and is refined from observed frame times with [`CostModel::observe`].

use alloc::vec::Vec;

use crate::effects::{Effects, Refraction};

/// What a frame may spend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Budget {
    /// Everything enabled runs.
    Unlimited,
    /// At most this many seconds of estimated work.
    Seconds(f64),
    /// Exactly these choices.
    Explicit(Selection),
}

/// The work chosen for one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Selection {
    /// At most this many trains per box (its largest ones); `usize::MAX` for all.
    pub max_trains: usize,
    /// The effects that run.
    pub effects: Effects,
}

/// One visible box's load: how many grid points it covers and how many trains it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxLoad {
    /// Grid points inside the box.
    pub points: usize,
    /// Its trains.
    pub trains: usize,
}

/// Estimated costs, in nanoseconds of one core.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CostModel {
    /// Per grid point of the whole grid: writing positions and normals.
    pub per_grid_point: f64,
    /// Per covered point and box: its modulation (side fade, land factor, envelope).
    pub per_box_point: f64,
    /// Per covered point and train.
    pub per_train_point: f64,
    /// Per covered point and enabled per-point effect (refraction, shoaling, round waves,
    /// irregular height, beach).
    pub per_effect_point: f64,
    /// Per grid point for the noise.
    pub per_noise_point: f64,
}

impl Default for CostModel {
    /// Order-of-magnitude figures from `ocean bench gerstner` (AMD EPYC, AVX2): about 3 ns to
    /// write a point, 0.35 ns per train and point; the per-box and per-effect costs are
    /// estimates of the same order as one train.
    fn default() -> Self {
        Self {
            per_grid_point: 3.0,
            per_box_point: 1.0,
            per_train_point: 0.35,
            per_effect_point: 0.5,
            per_noise_point: 2.0,
        }
    }
}

impl CostModel {
    /// Estimated nanoseconds for `selection` over `boxes` on a grid of `grid_points`.
    pub fn estimate(&self, grid_points: usize, boxes: &[BoxLoad], selection: &Selection) -> f64 {
        let effects = effect_count(&selection.effects) as f64;
        let mut ns = self.per_grid_point * grid_points as f64;
        for b in boxes {
            let trains = b.trains.min(selection.max_trains) as f64;
            ns += b.points as f64
                * (self.per_box_point
                    + trains * self.per_train_point
                    + effects * self.per_effect_point);
        }
        if selection.effects.noise.is_some() {
            ns += self.per_noise_point * grid_points as f64;
        }
        ns
    }

    /// Refines the model from a measured frame: scales every cost by the ratio of the measured
    /// to the estimated time, smoothed (weight `weight` in (0, 1] on the new ratio), so a
    /// steady budget holds on any machine. Ignores non-finite or non-positive figures.
    pub fn observe(&mut self, estimated_ns: f64, measured_ns: f64, weight: f64) {
        if !(estimated_ns > 0.0
            && measured_ns > 0.0
            && estimated_ns.is_finite()
            && measured_ns.is_finite())
        {
            return;
        }
        let w = weight.clamp(0.0, 1.0);
        let scale = 1.0 - w + w * (measured_ns / estimated_ns);
        self.per_grid_point *= scale;
        self.per_box_point *= scale;
        self.per_train_point *= scale;
        self.per_effect_point *= scale;
        self.per_noise_point *= scale;
    }
}

/// Number of per-point effects switched on (refraction, shoaling, round waves, irregular
/// height, beach).
pub fn effect_count(e: &Effects) -> usize {
    usize::from(e.refraction != Refraction::Off)
        + usize::from(e.shoaling)
        + usize::from(e.round_waves)
        + usize::from(e.irregular.is_some())
        + usize::from(e.beach.is_some())
}

/// Chooses the work for a frame: see the module documentation for the order.
pub fn select(
    budget: &Budget,
    model: &CostModel,
    grid_points: usize,
    boxes: &[BoxLoad],
    enabled: &Effects,
) -> Selection {
    let limit_ns = match *budget {
        Budget::Explicit(s) => return s,
        Budget::Unlimited => {
            return Selection {
                max_trains: usize::MAX,
                effects: *enabled,
            };
        }
        Budget::Seconds(s) => s * 1e9,
    };
    let nothing = Effects {
        refraction: Refraction::Off,
        shoaling: false,
        irregular: None,
        noise: None,
        round_waves: false,
        beach: None,
    };
    let mut sel = Selection {
        max_trains: 0,
        effects: nothing,
    };
    let fits = |s: &Selection| model.estimate(grid_points, boxes, s) <= limit_ns;
    // Trains rank by rank.
    let most = boxes.iter().map(|b| b.trains).max().unwrap_or(0);
    while sel.max_trains < most {
        let next = Selection {
            max_trains: sel.max_trains + 1,
            ..sel
        };
        if !fits(&next) {
            return sel;
        }
        sel = next;
    }
    sel.max_trains = usize::MAX;
    // Effects in the paper's order of importance, then the noise.
    let steps: [fn(&mut Effects, &Effects); 6] = [
        |e, on| e.refraction = on.refraction,
        |e, on| e.shoaling = on.shoaling,
        |e, on| e.round_waves = on.round_waves,
        |e, on| e.irregular = on.irregular,
        |e, on| e.beach = on.beach,
        |e, on| e.noise = on.noise,
    ];
    for step in steps {
        let mut next = sel;
        step(&mut next.effects, enabled);
        if next != sel {
            if !fits(&next) {
                break;
            }
            sel = next;
        }
    }
    sel
}

/// Indices of a box's trains from most to least important (largest amplitude first; ties keep
/// their order), so that `max_trains` keeps the largest.
pub fn train_order(amplitudes: &[f64]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..amplitudes.len()).collect();
    idx.sort_by(|&a, &b| amplitudes[b].total_cmp(&amplitudes[a]));
    idx
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::Noise;

    fn all_on() -> Effects {
        Effects {
            noise: Some(Noise {
                amplitude: 0.01,
                seed: 1,
            }),
            round_waves: true,
            ..Effects::default()
        }
    }

    #[test]
    fn unlimited_and_explicit() {
        let m = CostModel::default();
        let boxes = [BoxLoad {
            points: 1000,
            trains: 3,
        }];
        let s = select(&Budget::Unlimited, &m, 4096, &boxes, &all_on());
        assert_eq!(s.max_trains, usize::MAX);
        assert_eq!(s.effects, all_on());
        let explicit = Selection {
            max_trains: 1,
            effects: Effects::default(),
        };
        assert_eq!(
            select(&Budget::Explicit(explicit), &m, 4096, &boxes, &all_on()),
            explicit
        );
    }

    #[test]
    fn layers_are_admitted_in_order() {
        // A 10 000-point grid covered by one box with 3 trains; each budget below is the
        // model's own estimate of a selection, so exactly that selection must come back.
        let m = CostModel::default();
        let boxes = [BoxLoad {
            points: 10_000,
            trains: 3,
        }];
        let on = all_on();
        let cost = |max_trains, effects| {
            m.estimate(
                10_000,
                &boxes,
                &Selection {
                    max_trains,
                    effects,
                },
            )
        };
        let none = Effects {
            refraction: Refraction::Off,
            shoaling: false,
            irregular: None,
            noise: None,
            round_waves: false,
            beach: None,
        };
        // Exactly enough for two trains and nothing else.
        let two = cost(2, none);
        let s = select(&Budget::Seconds(two * 1e-9), &m, 10_000, &boxes, &on);
        assert_eq!((s.max_trains, s.effects), (2, none));
        // All trains plus refraction, not shoaling.
        let with_refraction = Effects {
            refraction: on.refraction,
            ..none
        };
        let budget = cost(usize::MAX, with_refraction);
        let s = select(&Budget::Seconds(budget * 1e-9), &m, 10_000, &boxes, &on);
        assert_eq!(s.max_trains, usize::MAX);
        assert_eq!(s.effects, with_refraction);
        // A generous budget runs everything enabled, noise last.
        let s = select(&Budget::Seconds(1.0), &m, 10_000, &boxes, &on);
        assert_eq!(s.effects, on);
        // Too little for even one train: nothing but the base.
        let s = select(&Budget::Seconds(1e-9), &m, 10_000, &boxes, &on);
        assert_eq!(s.max_trains, 0);
    }

    #[test]
    fn observation_rescales_the_model() {
        let mut m = CostModel::default();
        let before = m.per_train_point;
        m.observe(100.0, 200.0, 1.0);
        assert!((m.per_train_point - 2.0 * before).abs() < 1e-12);
        m.observe(100.0, 100.0, 0.5);
        assert!((m.per_train_point - 2.0 * before).abs() < 1e-12);
        m.observe(f64::NAN, 1.0, 1.0);
        assert!((m.per_train_point - 2.0 * before).abs() < 1e-12);
    }

    #[test]
    fn trains_by_amplitude() {
        assert_eq!(train_order(&[0.1, 0.5, 0.3, 0.5]), [1, 3, 2, 0]);
    }
}
