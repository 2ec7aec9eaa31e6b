//! A polyline path with a radius, and the normal-point rule of paper 003
//! ("Path following – improved path").
//!
//! The paper builds the path from connected line segments and follows
//! Reynolds/Shiffman: project the boid's predicted position on every
//! segment, keep only normal points that lie on their segment, and take
//! the closest. Two readings were needed where the text is ambiguous:
//!
//! * **Normal point off its segment.** The paper says "if there's no point
//!   on the path we use the end point of the line as a normal point". We
//!   clamp the projection to the *nearest* end of the segment (the paper's
//!   pseudocode always takes the far end `b`, which sends a boid behind a
//!   segment's start to that segment's end). Clamped candidates compete on
//!   distance like the others, so the result is the true closest point of
//!   the polyline. A literal "discard off-segment normals" would, outside a
//!   convex corner of the paper's rectangular pathway, pick a normal on the
//!   far side of the rectangle; a user would not expect that.
//! * **Closest wins, ties to the lowest segment index**, so the choice is
//!   deterministic.
//! * **Target ahead along the path.** The paper moves the target `x` ahead
//!   of the normal point along the segment, and "if we're at the end of the
//!   line we want to specify a target point on the next line". We measure
//!   the look-ahead as arc length along the polyline, which is that rule
//!   generalised: a target that would overshoot a segment's end continues
//!   on the next segment (wrapping on a closed path, stopping at the last
//!   point of an open one).
//!
//! Paths are validated on construction and on every edit; bad input gives a
//! [`CrowdError`], never a panic.

use glam::Vec2;

use crate::crowd::error::{check_range, CrowdError};

/// Largest accepted |coordinate|: keeps f32 arc lengths meaningful.
pub const MAX_COORDINATE: f32 = 1.0e7;

/// The normal point chosen for a query position (paper 003, Fig. 5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalPoint {
    /// The point on the path (on its segment, end points included).
    pub point: Vec2,
    /// Index of the segment it lies on (segment `i` runs from point `i` to
    /// point `i + 1`, the closing segment of a closed path is the last).
    pub segment: usize,
    /// Arc length from the path's first point to `point`, in world units.
    pub s: f32,
    /// Distance from the query position to `point`, in world units.
    pub distance: f32,
}

/// A polyline path with a radius (paper 003 `class path { points; radius }`).
#[derive(Clone, Debug, PartialEq)]
pub struct Path {
    points: Vec<Vec2>,
    closed: bool,
    radius: f32,
    /// Unit direction of each segment.
    dirs: Vec<Vec2>,
    /// Length of each segment.
    lens: Vec<f32>,
    /// Arc length at the start of each segment, plus the total at the end.
    starts: Vec<f32>,
}

impl Path {
    /// A path through `points` with half-width `radius` (world units).
    /// A `closed` path also runs from the last point back to the first.
    ///
    /// # Errors
    /// Fewer than 2 points (3 when closed), non-finite or huge coordinates,
    /// repeated consecutive points, or a radius that is not finite and > 0.
    pub fn new(points: Vec<Vec2>, radius: f32, closed: bool) -> Result<Self, CrowdError> {
        let mut p = Self {
            points: Vec::new(),
            closed,
            radius: 1.0,
            dirs: Vec::new(),
            lens: Vec::new(),
            starts: Vec::new(),
        };
        p.set_radius(radius)?;
        p.set_points(&points)?;
        Ok(p)
    }

    /// The paper's closed rectangular pathway: centre line a `width` ×
    /// `height` rectangle centred on `center`, travelled counter-clockwise
    /// in a y-up frame (clockwise on a y-down canvas).
    ///
    /// # Errors
    /// As [`Path::new`]; also a non-positive width or height.
    pub fn rectangle(
        center: Vec2,
        width: f32,
        height: f32,
        radius: f32,
    ) -> Result<Self, CrowdError> {
        check_range("width", width, 1e-3, MAX_COORDINATE)?;
        check_range("height", height, 1e-3, MAX_COORDINATE)?;
        let h = Vec2::new(width, height) * 0.5;
        Self::new(
            vec![
                center + Vec2::new(-h.x, -h.y),
                center + Vec2::new(h.x, -h.y),
                center + Vec2::new(h.x, h.y),
                center + Vec2::new(-h.x, h.y),
            ],
            radius,
            true,
        )
    }

    /// Replaces the points, keeping radius and closedness. On error the path
    /// is left unchanged.
    ///
    /// # Errors
    /// See [`Path::new`].
    pub fn set_points(&mut self, points: &[Vec2]) -> Result<(), CrowdError> {
        let need = if self.closed { 3 } else { 2 };
        if points.len() < need {
            return Err(CrowdError::TooFewPoints {
                got: points.len(),
                need,
            });
        }
        for (i, p) in points.iter().enumerate() {
            if !p.is_finite() {
                return Err(CrowdError::NonFinitePoint(i));
            }
            check_range(
                "path point coordinate",
                p.abs().max_element(),
                0.0,
                MAX_COORDINATE,
            )?;
        }
        let n_seg = if self.closed {
            points.len()
        } else {
            points.len() - 1
        };
        let mut dirs = Vec::with_capacity(n_seg);
        let mut lens = Vec::with_capacity(n_seg);
        let mut starts = Vec::with_capacity(n_seg + 1);
        let mut s = 0.0f32;
        for i in 0..n_seg {
            let a = points[i];
            let b = points[(i + 1) % points.len()];
            // Finite: coordinates were checked above.
            let len = (b - a).length();
            if len <= 1e-4 {
                return Err(CrowdError::DegenerateSegment(i));
            }
            dirs.push((b - a) / len);
            lens.push(len);
            starts.push(s);
            s += len;
        }
        starts.push(s);
        self.points = points.to_vec();
        self.dirs = dirs;
        self.lens = lens;
        self.starts = starts;
        Ok(())
    }

    /// [`Path::set_points`] from a flat `[x0, y0, x1, y1, ...]` buffer (the
    /// layout a front end hands over).
    ///
    /// # Errors
    /// An odd number of values, or see [`Path::new`].
    pub fn set_points_flat(&mut self, xy: &[f32]) -> Result<(), CrowdError> {
        if xy.len() % 2 != 0 {
            return Err(CrowdError::OddCoordinateCount(xy.len()));
        }
        let pts: Vec<Vec2> = xy.chunks_exact(2).map(|c| Vec2::new(c[0], c[1])).collect();
        self.set_points(&pts)
    }

    /// Opens or closes the path (a closed path also runs from the last point
    /// back to the first). On error the path is left unchanged.
    ///
    /// # Errors
    /// Closing a 2-point path, or a closing segment of zero length.
    pub fn set_closed(&mut self, closed: bool) -> Result<(), CrowdError> {
        let old = self.closed;
        self.closed = closed;
        let points = self.points.clone();
        self.set_points(&points).inspect_err(|_| self.closed = old)
    }

    /// Sets the path radius (half-width, world units). On error the path is
    /// left unchanged.
    ///
    /// # Errors
    /// Radius not finite or not in `(0, 1e6]`.
    pub fn set_radius(&mut self, radius: f32) -> Result<(), CrowdError> {
        check_range("path radius", radius, 1e-3, 1e6)?;
        self.radius = radius;
        Ok(())
    }

    /// The path's points.
    #[must_use]
    pub fn points(&self) -> &[Vec2] {
        &self.points
    }

    /// The path's points as a flat `[x0, y0, x1, y1, ...]` buffer (for a
    /// front end; allocates).
    #[must_use]
    pub fn points_flat(&self) -> Vec<f32> {
        self.points.iter().flat_map(|p| p.to_array()).collect()
    }

    /// The path's half-width in world units.
    #[must_use]
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// Whether the last point connects back to the first.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// Number of segments (points − 1, or points when closed).
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.dirs.len()
    }

    /// Total arc length in world units.
    #[must_use]
    pub fn length(&self) -> f32 {
        self.starts[self.dirs.len()]
    }

    /// The closest normal point of `p` on the path (module docs: nearest
    /// end point when the projection leaves its segment; closest wins; ties
    /// to the lowest segment index). O(segments).
    #[must_use]
    pub fn normal_point(&self, p: Vec2) -> NormalPoint {
        // Runs for every boid, every step: zipped slices instead of
        // indexing (no bounds checks) and `f32::clamp`'s comparisons
        // written out (the same result, NaN kept, without its `min ≤ max`
        // assertion: `len` > 0 by construction); the arc length is formed
        // once, for the winner. Same bits.
        let (mut best_q, mut best_i, mut best_t) = (self.points[0], 0, 0.0);
        let mut best_d2 = f32::INFINITY;
        for (i, ((&a, &dir), &len)) in self
            .points
            .iter()
            .zip(&self.dirs)
            .zip(&self.lens)
            .enumerate()
        {
            let mut t = (p - a).dot(dir);
            if t < 0.0 {
                t = 0.0;
            }
            if t > len {
                t = len;
            }
            let q = a + dir * t;
            let d2 = p.distance_squared(q);
            if d2 < best_d2 {
                best_d2 = d2;
                (best_q, best_i, best_t) = (q, i, t);
            }
        }
        if best_d2 == f32::INFINITY {
            return NormalPoint {
                point: self.points[0],
                segment: 0,
                s: 0.0,
                distance: f32::INFINITY,
            };
        }
        NormalPoint {
            point: best_q,
            segment: best_i,
            s: self.starts[best_i] + best_t,
            distance: best_d2.sqrt(),
        }
    }

    /// Signed lateral offset of `p` from the centre line at its normal
    /// point: positive to the left of the travel direction.
    #[must_use]
    pub fn lateral_offset(&self, p: Vec2, n: &NormalPoint) -> f32 {
        let side = self.dirs[n.segment].perp_dot(p - n.point);
        if side < 0.0 {
            -n.distance
        } else {
            n.distance
        }
    }

    /// Normalises an arc length: wrapped into `[0, length)` on a closed
    /// path, clamped to `[0, length]` on an open one.
    #[must_use]
    pub fn wrap_s(&self, s: f32) -> f32 {
        let total = self.length();
        if self.closed {
            // Common cases first: no fmod for s in [-L, 2L).
            let w = if (0.0..total).contains(&s) {
                s
            } else if (total..2.0 * total).contains(&s) {
                s - total
            } else if (-total..0.0).contains(&s) {
                s + total
            } else {
                s.rem_euclid(total)
            };
            if w >= total {
                0.0
            } else {
                w
            }
        } else {
            s.clamp(0.0, total)
        }
    }

    fn segment_at(&self, s: f32) -> usize {
        // `starts` is increasing; the last segment also owns s == length.
        let k = self.starts[..self.dirs.len()].partition_point(|&x| x <= s);
        k.saturating_sub(1)
    }

    /// The point at arc length `s` (see [`Path::wrap_s`]).
    #[must_use]
    pub fn point_at(&self, s: f32) -> Vec2 {
        let s = self.wrap_s(s);
        let i = self.segment_at(s);
        let t = (s - self.starts[i]).clamp(0.0, self.lens[i]);
        self.points[i] + self.dirs[i] * t
    }

    /// Unit travel direction at arc length `s` (see [`Path::wrap_s`]).
    #[must_use]
    pub fn tangent_at(&self, s: f32) -> Vec2 {
        self.dirs[self.segment_at(self.wrap_s(s))]
    }

    /// The seek target `ahead` world units further along the path than the
    /// normal point `n` (paper: "a point on the path a bit further from the
    /// normal point"; continues on the next segment at a segment's end).
    #[must_use]
    pub fn target_ahead(&self, n: &NormalPoint, ahead: f32) -> Vec2 {
        self.point_at(n.s + ahead)
    }
}
