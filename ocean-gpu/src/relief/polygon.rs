//! The polygon a relief draw covers: corners in the plane of its quad, and faces of meshes
//! placed as such polygons.

use glam::{DVec2, DVec3};

use super::{ReliefScene, invalid};
use crate::GpuError;

/// Largest `|s|` or `|t|` of a corner, in edges of the quad: beyond it the corner's world
/// position loses the precision of the quad's own `f32` edges.
pub const MAX_CORNER: f64 = 1.0e6;

/// The corners as the uniform block holds them: `(s₀, t₀, s₁, t₁)`, `(s₂, t₂, s₃, t₃)`.
pub(super) fn corner_block(corners: &[DVec2; 4]) -> [[f32; 4]; 2] {
    let c = corners.map(|c| c.as_vec2());
    [
        [c[0].x, c[0].y, c[1].x, c[1].y],
        [c[2].x, c[2].y, c[3].x, c[3].y],
    ]
}

/// Checks [`ReliefScene::corners`]: finite, within [`MAX_CORNER`], convex and
/// counter-clockwise seen from the front (every turn between consecutive distinct corners to
/// the left or straight on), enclosing an area.
pub(super) fn check_corners(corners: &[DVec2; 4]) -> Result<(), GpuError> {
    if !corners.iter().all(|c| c.is_finite()) {
        return Err(invalid("relief polygon", "its corners must be finite"));
    }
    if corners.iter().any(|c| c.abs().max_element() > MAX_CORNER) {
        return Err(invalid(
            "relief polygon",
            format!("a corner lies more than {MAX_CORNER} edges from the origin"),
        ));
    }
    let area = 0.5
        * (0..4)
            .map(|i| corners[i].perp_dot(corners[(i + 1) % 4]))
            .sum::<f64>();
    let scale = corners
        .iter()
        .map(|c| (*c - corners[0]).length_squared())
        .fold(0.0, f64::max);
    // Finite: every corner is finite and bounded.
    if area <= 1e-12 * scale {
        return Err(invalid(
            "relief polygon",
            format!(
                "its corners enclose no area counter-clockwise (signed area {area}): list them \
                 counter-clockwise seen from the front, edge_u x edge_v"
            ),
        ));
    }
    // Each corner's turn, from the edge that reaches it to the edge that leaves it, skipping
    // repeated corners (a triangle's fourth).
    let distinct: Vec<DVec2> = (0..4)
        .filter(|&i| corners[i] != corners[(i + 1) % 4])
        .map(|i| corners[i])
        .collect();
    let n = distinct.len();
    for i in 0..n {
        let (a, b, c) = (distinct[i], distinct[(i + 1) % n], distinct[(i + 2) % n]);
        if (b - a).perp_dot(c - b) < -1e-12 * scale {
            return Err(invalid(
                "relief polygon",
                format!(
                    "it is not convex: it turns right at corner ({}, {})",
                    b.x, b.y
                ),
            ));
        }
    }
    Ok(())
}

impl ReliefScene {
    /// The face of a mesh with corners `points` (3 or 4, counter-clockwise seen from the
    /// front, coplanar, convex), relief-mapped with textures `texture_width` world units wide;
    /// every other field is [`ReliefScene::default`]'s.
    ///
    /// The texture coordinates are the world position projected on the face's plane and
    /// measured from `anchor` (projected there too), along `u`, the world axis (`x`, `y`, `z`,
    /// the first on a tie) least aligned with the face's normal `n` taken into the plane, and
    /// `v = n × u`. Faces of one mesh that share an anchor and nearly share a plane thus
    /// continue each other's relief across their common edge.
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for a count other than 3 or 4, a non-finite value, a width
    /// that is not positive, points that enclose no area, are not coplanar (relative tolerance
    /// 10⁻⁶ of the face's size) or not convex.
    pub fn on_polygon(
        points: &[DVec3],
        anchor: DVec3,
        texture_width: f64,
    ) -> Result<ReliefScene, GpuError> {
        if !(3..=4).contains(&points.len()) {
            return Err(invalid(
                "relief polygon",
                format!("has {} points, not 3 or 4", points.len()),
            ));
        }
        if !(points.iter().all(|p| p.is_finite()) && anchor.is_finite()) {
            return Err(invalid("relief polygon", "every coordinate must be finite"));
        }
        if !(texture_width > 0.0 && texture_width.is_finite()) {
            return Err(invalid(
                "relief texture width",
                "must be positive and finite",
            ));
        }
        // Newell's normal: twice the area vector, along the counter-clockwise side.
        let k = points.len();
        let area = (0..k)
            .map(|i| points[i].cross(points[(i + 1) % k]))
            .fold(DVec3::ZERO, |a, b| a + b);
        let n = area.normalize_or_zero();
        if n == DVec3::ZERO {
            return Err(invalid("relief polygon", "its points enclose no area"));
        }
        let size = points
            .iter()
            .map(|p| (*p - points[0]).length())
            .fold(0.0, f64::max);
        if points
            .iter()
            .any(|p| (*p - points[0]).dot(n).abs() > super::SHAPE_TOLERANCE * size)
        {
            return Err(invalid("relief polygon", "its points are not coplanar"));
        }
        let axes = [DVec3::X, DVec3::Y, DVec3::Z];
        let mut axis = axes[0];
        for a in axes {
            if a.dot(n).abs() < axis.dot(n).abs() {
                axis = a;
            }
        }
        let u = (axis - axis.dot(n) * n).normalize();
        let v = n.cross(u);
        let origin = anchor - (anchor - points[0]).dot(n) * n;
        let corner = |p: DVec3| {
            let d = p - origin;
            DVec2::new(d.dot(u), d.dot(v)) / texture_width
        };
        let corners = [0, 1, 2, k - 1].map(|i| corner(points[i]));
        check_corners(&corners)?;
        Ok(ReliefScene {
            origin,
            edge_u: u * texture_width,
            edge_v: v * texture_width,
            tiles: DVec2::ONE,
            corners,
            ..ReliefScene::default()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(corners: [DVec2; 4]) -> bool {
        matches!(check_corners(&corners), Err(GpuError::InvalidInput { .. }))
    }

    #[test]
    fn the_whole_quad_and_triangles_are_accepted() {
        assert!(check_corners(&ReliefScene::QUAD).is_ok());
        let t = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(0.5, 1.0),
            DVec2::new(0.5, 1.0),
        ];
        assert!(check_corners(&t).is_ok());
    }

    #[test]
    fn bad_polygons_are_refused() {
        let q = ReliefScene::QUAD;
        // Clockwise: the back of the quad.
        assert!(refused([q[0], q[3], q[2], q[1]]));
        // All zero: a C caller's zeroed struct.
        assert!(refused([DVec2::ZERO; 4]));
        // A bow tie.
        assert!(refused([q[0], q[1], q[3], q[2]]));
        // Concave (a dart).
        assert!(refused([q[0], q[1], DVec2::new(0.3, 0.3), q[3]]));
        // Collinear.
        assert!(refused([
            q[0],
            q[1],
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 0.0)
        ]));
        assert!(refused([q[0], q[1], q[2], DVec2::new(f64::NAN, 1.0)]));
        assert!(refused([q[0], q[1], q[2], DVec2::new(0.0, 2e6)]));
    }

    #[test]
    fn a_mesh_face_is_its_own_polygon() {
        // A sloped triangle, counter-clockwise from above.
        let p = [
            DVec3::new(1.0, 0.5, 2.0),
            DVec3::new(3.0, 1.0, 1.0),
            DVec3::new(2.0, 2.5, -1.0),
        ];
        let w = 0.75;
        let s = ReliefScene::on_polygon(&p, DVec3::new(10.0, -3.0, 4.0), w).unwrap();
        let f = s.tangent_frame().unwrap();
        let expected = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
        assert!((f.normal - expected).length() < 1e-12, "{:?}", f.normal);
        assert!((f.texture_width - w).abs() < 1e-12);
        // Each corner maps back onto its point.
        for (i, c) in [0, 1, 2, 2].into_iter().zip(s.corners) {
            let q = s.origin + c.x * s.edge_u + c.y * s.edge_v;
            assert!(
                (q - p[i]).length() < 1e-12,
                "corner {i}: {q} against {}",
                p[i]
            );
        }
        // The same points clockwise face the other way.
        let back = ReliefScene::on_polygon(&[p[0], p[2], p[1]], DVec3::ZERO, w).unwrap();
        let fb = back.tangent_frame().unwrap();
        assert!((fb.normal + expected).length() < 1e-12);
        // Not coplanar, too few points, zero width.
        let bent = [p[0], p[1], p[2], DVec3::new(0.0, 5.0, 0.0)];
        assert!(ReliefScene::on_polygon(&bent, DVec3::ZERO, w).is_err());
        assert!(ReliefScene::on_polygon(&p[..2], DVec3::ZERO, w).is_err());
        assert!(ReliefScene::on_polygon(&p, DVec3::ZERO, 0.0).is_err());
    }

    #[test]
    fn faces_that_share_a_plane_continue_the_texture() {
        // Two triangles of one square, anchored at one point: a shared corner has one (s, t).
        let a = DVec3::new(0.0, 0.0, 0.0);
        let b = DVec3::new(2.0, 0.0, 0.0);
        let c = DVec3::new(2.0, 0.5, -2.0);
        let d = DVec3::new(0.0, 0.5, -2.0);
        let anchor = DVec3::new(1.0, 5.0, 1.0);
        let f1 = ReliefScene::on_polygon(&[a, b, c], anchor, 1.0).unwrap();
        let f2 = ReliefScene::on_polygon(&[a, c, d], anchor, 1.0).unwrap();
        assert!((f1.origin - f2.origin).length() < 1e-12);
        assert!((f1.corners[0] - f2.corners[0]).length() < 1e-12);
        assert!((f1.corners[2] - f2.corners[1]).length() < 1e-12);
    }
}
