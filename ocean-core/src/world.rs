//! Evaluation at world rest points given in `f64`, with world positions out.
//!
//! [`WaveSet::evaluate_points`] takes points relative to one `f64` origin as `f32` offsets:
//! right for a patch, wrong for scattered height queries, where one origin far from some point
//! leaves that point's offset coarse (an `f32` offset of 100 km is 7.8 mm coarse). Here each
//! point is evaluated relative to the corner of the [`CELL`]-metre lattice cell it lies in: the
//! corner is exact in `f64` (a multiple of a power of two), the offset below [`CELL`] is an
//! `f32` resolved to 2⁻¹⁸ m (4 µm), and the result depends on the point alone, never on the
//! points queried with it. Runs of consecutive points in one cell share one kernel call.

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, DVec3, Vec3};

use crate::error::EvalError;
use crate::trochoid::{WaveSet, check_outputs, check_time};

/// Side of the lattice cells, metres: a power of two, so that cell corners are exact doubles
/// and a point's offset from its corner is an `f32` resolved to 2⁻¹⁸ m.
pub const CELL: f64 = 64.0;

/// The corner of the lattice cell holding `p`.
fn corner(p: DVec2) -> DVec2 {
    (p / CELL).floor() * CELL
}

impl WaveSet {
    /// Evaluates world rest points `world[n]` at time `t` through the `f32` kernel, each
    /// relative to its lattice cell's corner (see the module documentation).
    ///
    /// Writes world positions (`world[n]` displaced: the corner in `f64` plus the kernel's
    /// `f32` position relative to it) and unit normals. The result for a point is bit-identical
    /// whatever points accompany it, in whatever order. Nothing is written on an error.
    ///
    /// # Errors
    ///
    /// [`EvalError::Empty`] for no points, [`EvalError::OutputLength`] for outputs of another
    /// length, [`EvalError::Time`] for a non-finite `t`, [`EvalError::Position`] for the first
    /// non-finite point.
    pub fn evaluate_world(
        &self,
        world: &[DVec2],
        t: f64,
        out_pos: &mut [DVec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        check_world(world, t, out_pos, out_nrm)?;
        let mut rel = vec![Vec3::ZERO; world.len()];
        let mut offsets = Vec::new();
        let mut start = 0;
        while start < world.len() {
            let o = corner(world[start]);
            let len = world[start..]
                .iter()
                .position(|&p| corner(p) != o)
                .unwrap_or(world.len() - start);
            let end = start + len;
            offsets.clear();
            offsets.extend(world[start..end].iter().map(|&p| (p - o).as_vec2()));
            // Cannot fail: the arguments were checked above.
            self.evaluate_points(
                o,
                &offsets,
                t,
                &mut rel[start..end],
                &mut out_nrm[start..end],
            )?;
            for (out, r) in out_pos[start..end].iter_mut().zip(&rel[start..end]) {
                *out = DVec3::new(o.x + f64::from(r.x), f64::from(r.y), o.y + f64::from(r.z));
            }
            start = end;
        }
        Ok(())
    }
}

/// The checks of [`WaveSet::evaluate_world`], made before anything is written.
fn check_world(
    world: &[DVec2],
    t: f64,
    out_pos: &[DVec3],
    out_nrm: &[Vec3],
) -> Result<(), EvalError> {
    check_outputs(world.len(), out_pos, out_nrm)?;
    check_time(t)?;
    if let Some(index) = world.iter().position(|p| !p.is_finite()) {
        return Err(EvalError::Position { index });
    }
    Ok(())
}

#[cfg(feature = "std")]
mod parallel {
    use rayon::prelude::*;

    use super::*;
    use crate::parallel::POINTS_PER_TASK;

    impl WaveSet {
        /// [`WaveSet::evaluate_world`] on the current rayon thread pool, in tasks of
        /// consecutive points; bit-identical to it, since a point's result depends on the
        /// point alone.
        pub fn evaluate_world_par(
            &self,
            world: &[DVec2],
            t: f64,
            out_pos: &mut [DVec3],
            out_nrm: &mut [Vec3],
        ) -> Result<(), EvalError> {
            check_world(world, t, out_pos, out_nrm)?;
            world
                .par_chunks(POINTS_PER_TASK)
                .zip(out_pos.par_chunks_mut(POINTS_PER_TASK))
                .zip(out_nrm.par_chunks_mut(POINTS_PER_TASK))
                .try_for_each(|((w, p), n)| self.evaluate_world(w, t, p, n))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Depth, WaveDesc};

    fn waves() -> WaveSet {
        WaveSet::from_descs(&[
            WaveDesc {
                amplitude: 0.4,
                wavelength: 23.0,
                direction: DVec2::new(1.0, 0.3),
                phase: 0.2,
                depth: Depth::Deep,
            },
            WaveDesc {
                amplitude: 0.1,
                wavelength: 3.7,
                direction: DVec2::new(-0.4, 1.0),
                phase: 1.0,
                depth: Depth::Finite(6.0),
            },
        ])
        .unwrap()
    }

    /// Points on both sides of cell borders, far from the origin and negative: each result is
    /// `evaluate_points` at its own cell corner (the definition), the same alone, in a batch,
    /// reversed and on threads; the `f64` reference is met to the `f32` kernel's accuracy.
    #[test]
    fn a_point_is_evaluated_at_its_own_cell_corner_whatever_the_batch() {
        let w = waves();
        let t = 1.0e6 + 0.37;
        let world: Vec<DVec2> = [
            (0.0, 0.0),
            (63.999_999, -0.000_001),
            (64.0, 64.0),
            (-64.0, -63.5),
            (1.0e5 + 0.123_456_7, -2.0e5 - 0.5),
            (1.0e5 + 63.9, -2.0e5 - 0.5),
            (1.0e5 + 64.1, -2.0e5 - 0.5),
            (-7.5e6, 3.25e6),
        ]
        .iter()
        .map(|&(x, z)| DVec2::new(x, z))
        .collect();
        let n = world.len();
        let (mut pos, mut nrm) = (vec![DVec3::ZERO; n], vec![Vec3::ZERO; n]);
        w.evaluate_world(&world, t, &mut pos, &mut nrm).unwrap();
        for (i, &p) in world.iter().enumerate() {
            let o = corner(p);
            assert!(o.x % CELL == 0.0 && o.y % CELL == 0.0 && (p - o).max_element() < CELL);
            let (mut r, mut m) = ([Vec3::ZERO], [Vec3::ZERO]);
            w.evaluate_points(o, &[(p - o).as_vec2()], t, &mut r, &mut m)
                .unwrap();
            let want = DVec3::new(
                o.x + f64::from(r[0].x),
                f64::from(r[0].y),
                o.y + f64::from(r[0].z),
            );
            assert_eq!((pos[i], nrm[i]), (want, m[0]), "point {i}");
            // Alone: the same bits.
            let (mut p1, mut n1) = ([DVec3::ZERO], [Vec3::ZERO]);
            w.evaluate_world(&[p], t, &mut p1, &mut n1).unwrap();
            assert_eq!((p1[0], n1[0]), (pos[i], nrm[i]), "point {i} alone");
            // Against the f64 reference at the world point: within the f32 kernel's error.
            let s = w.sample_f64(p, t).unwrap();
            let exact = DVec3::new(p.x, 0.0, p.y) + s.displacement;
            assert!((pos[i] - exact).abs().max_element() < 2e-5, "point {i}");
        }
        let rev: Vec<DVec2> = world.iter().rev().copied().collect();
        let (mut pr, mut nr) = (vec![DVec3::ZERO; n], vec![Vec3::ZERO; n]);
        w.evaluate_world(&rev, t, &mut pr, &mut nr).unwrap();
        pr.reverse();
        nr.reverse();
        assert_eq!((pr, nr), (pos.clone(), nrm.clone()));
    }

    /// Many points over many cells: the threaded path is the serial one, bit for bit.
    #[cfg(feature = "std")]
    #[test]
    fn threads_change_nothing() {
        let w = waves();
        let world: Vec<DVec2> = (0..40_000)
            .map(|i| {
                DVec2::new(
                    f64::from(i) * 0.37 - 5000.0,
                    f64::from(i % 977) * 1.3 + 1.0e5,
                )
            })
            .collect();
        let n = world.len();
        let (mut a, mut an) = (vec![DVec3::ZERO; n], vec![Vec3::ZERO; n]);
        let (mut b, mut bn) = (vec![DVec3::ZERO; n], vec![Vec3::ZERO; n]);
        w.evaluate_world(&world, 12.5, &mut a, &mut an).unwrap();
        w.evaluate_world_par(&world, 12.5, &mut b, &mut bn).unwrap();
        assert!(a == b && an == bn);
    }

    /// Bad arguments are refused before anything is written.
    #[test]
    fn errors_write_nothing() {
        let w = waves();
        let sentinel = DVec3::splat(7.0);
        let mut pos = vec![sentinel; 3];
        let mut nrm = vec![Vec3::splat(7.0); 3];
        let bad = [
            DVec2::new(1.0, 2.0),
            DVec2::new(3.0, 4.0),
            DVec2::new(f64::NAN, 0.0),
        ];
        assert_eq!(
            w.evaluate_world(&bad, 0.0, &mut pos, &mut nrm),
            Err(EvalError::Position { index: 2 })
        );
        assert_eq!(
            w.evaluate_world(&bad[..2], f64::INFINITY, &mut pos[..2], &mut nrm[..2]),
            Err(EvalError::Time(f64::INFINITY))
        );
        assert!(matches!(
            w.evaluate_world(&bad[..2], 0.0, &mut pos, &mut nrm),
            Err(EvalError::OutputLength { expected: 2, .. })
        ));
        assert_eq!(
            w.evaluate_world(&[], 0.0, &mut [], &mut []),
            Err(EvalError::Empty)
        );
        assert!(pos.iter().all(|&p| p == sentinel) && nrm.iter().all(|&v| v == Vec3::splat(7.0)));
    }
}
