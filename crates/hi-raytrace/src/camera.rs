// SPDX-License-Identifier: MIT
//! The pinhole camera of the renderer (Hardy 2005, §5.6: rays o + td from the eye through each
//! pixel): look-at placement, vertical field of view, aspect ratio from the image.

use glam::DVec3;

use crate::error::{Error, check_finite, check_finite_scalar};
use crate::ray::Ray;

/// The smallest sine of the angle between the up vector and the view direction accepted.
const MIN_UP_SINE: f64 = 1e-9;

/// A pinhole camera at `eye` looking at `target`, with `up` giving the image's vertical and a
/// vertical field of view `fov_y` (radians). The aspect ratio is the image's.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_raytrace::Camera;
/// let cam = Camera::try_new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, DVec3::Y, 0.8)?;
/// // The centre of the image looks straight at the target.
/// let ray = cam.ray(0.5, 0.5, 1.0);
/// assert!((ray.dir - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-15);
/// assert!(Camera::try_new(DVec3::ZERO, DVec3::ZERO, DVec3::Y, 0.8).is_err()); // eye = target
/// # Ok::<(), hi_raytrace::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    // Invariant: finite; forward, right, up orthonormal; 0 < fov_y < π.
    eye: DVec3,
    forward: DVec3,
    right: DVec3,
    up: DVec3,
    fov_y: f64,
    tan_half: f64,
}

impl Camera {
    /// The camera at `eye` looking at `target`, `up` pointing up in the image, vertical field of
    /// view `fov_y` radians.
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] for a NaN or infinite coordinate or angle;
    /// [`Error::DegenerateCamera`] when `eye` = `target`, `up` is zero or parallel to the view
    /// direction, or `fov_y` is not in (0, π).
    pub fn try_new(eye: DVec3, target: DVec3, up: DVec3, fov_y: f64) -> Result<Self, Error> {
        check_finite("camera eye", eye)?;
        check_finite("camera target", target)?;
        check_finite("camera up vector", up)?;
        check_finite_scalar("camera field of view", fov_y)?;
        if !(fov_y > 0.0 && fov_y < std::f64::consts::PI) {
            return Err(Error::DegenerateCamera {
                reason: "the field of view must be in (0, π) radians",
            });
        }
        let view = target - eye;
        let Some(forward) = view.try_normalize() else {
            return Err(Error::DegenerateCamera { reason: "the eye is at the target" });
        };
        let Some(up_dir) = up.try_normalize() else {
            return Err(Error::DegenerateCamera { reason: "the up vector is zero" });
        };
        let cross = forward.cross(up_dir);
        if cross.length() <= MIN_UP_SINE {
            return Err(Error::DegenerateCamera {
                reason: "the up vector is parallel to the view direction",
            });
        }
        let right = cross.normalize();
        let up = right.cross(forward);
        Ok(Camera { eye, forward, right, up, fov_y, tan_half: (0.5 * fov_y).tan() })
    }

    /// A camera looking at a sphere (`center`, `radius`) from direction `from` (pointing from the
    /// centre to the eye), far enough for the sphere to fit the vertical field of view `fov_y`
    /// with 10 % to spare; `up` as for [`Camera::try_new`].
    ///
    /// # Errors
    ///
    /// As [`Camera::try_new`], and [`Error::InvalidValue`] for a radius that is not positive.
    pub fn framing(
        center: DVec3,
        radius: f64,
        from: DVec3,
        up: DVec3,
        fov_y: f64,
    ) -> Result<Self, Error> {
        let radius = crate::error::check_positive("framing radius", radius)?;
        check_finite("framing direction", from)?;
        check_finite_scalar("camera field of view", fov_y)?;
        let Some(dir) = from.try_normalize() else {
            return Err(Error::DegenerateCamera { reason: "the framing direction is zero" });
        };
        if !(fov_y > 0.0 && fov_y < std::f64::consts::PI) {
            return Err(Error::DegenerateCamera {
                reason: "the field of view must be in (0, π) radians",
            });
        }
        let distance = 1.1 * radius / (0.5 * fov_y).sin();
        Camera::try_new(center + dir * distance, center, up, fov_y)
    }

    /// A camera looking at `points` from direction `from` (from the points towards the eye),
    /// as close as it can be with every point inside the central `fill` of the image's width
    /// and height (0.8: a tenth of the frame left free at each side), and the points' extent
    /// centred in the image; `up`, `fov_y` as for [`Camera::try_new`], `aspect` = width/height
    /// of the image it will render. Unlike [`Camera::framing`], which fits a bounding sphere
    /// (a long or flat object then fills a third of the frame), this frames what the points
    /// cover as seen from `from`.
    ///
    /// Computed in the camera's frame (right x, up y, towards the eye z, about the target): a
    /// point is inside when |x| ≤ fill·tan(φₓ/2)·(d − z) (φₓ the horizontal field of view) and
    /// the same in y, so the least distance d is the largest of z + |x|/(fill·tan(φₓ/2)) and
    /// z + |y|/(fill·tan(φᵧ/2));
    /// the target is then moved across the view to the middle of the points' projected
    /// extent and d found again, until the extent is centred (to 10⁻⁶ of the view, at most 32
    /// times).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_raytrace::Camera;
    /// // A 4 × 1 × 1 box seen from the front: it is framed by its width.
    /// let corners: Vec<DVec3> = (0..8)
    ///     .map(|k| DVec3::new([-2.0, 2.0][k & 1], [-0.5, 0.5][(k >> 1) & 1], [-0.5, 0.5][k >> 2]))
    ///     .collect();
    /// let cam = Camera::fitting(&corners, DVec3::Y, DVec3::Z, 0.6, 4.0 / 3.0, 0.8)?;
    /// let widest = corners
    ///     .iter()
    ///     .map(|p| {
    ///         let v = *p - cam.eye();
    ///         v.dot(cam.right()).abs() / (v.dot(cam.forward()) * (0.3f64).tan() * 4.0 / 3.0)
    ///     })
    ///     .fold(0.0, f64::max);
    /// assert!((widest - 0.8).abs() < 1e-9);
    /// # Ok::<(), hi_raytrace::Error>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`Error::InvalidValue`] for no points, `fill` outside (0, 1] or `aspect` not positive;
    /// [`Error::NonFinite`] for a non-finite point; the errors of [`Camera::try_new`].
    pub fn fitting(
        points: &[DVec3],
        from: DVec3,
        up: DVec3,
        fov_y: f64,
        aspect: f64,
        fill: f64,
    ) -> Result<Self, Error> {
        if points.is_empty() {
            return Err(Error::InvalidValue {
                what: "points to frame",
                value: 0.0,
                expected: "at least one point",
            });
        }
        if let Some(p) = points.iter().find(|p| !p.is_finite()) {
            check_finite("a point to frame", *p)?;
        }
        if !(fill > 0.0 && fill <= 1.0) {
            return Err(Error::InvalidValue {
                what: "frame fill",
                value: fill,
                expected: "a fraction in (0, 1]",
            });
        }
        let aspect = crate::error::check_positive("image aspect ratio", aspect)?;
        let (lo, hi) = points
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let mut target = 0.5 * (lo + hi);
        let size = (hi - lo).length().max(f64::MIN_POSITIVE.sqrt());
        // The orientation only (the distance comes below).
        let probe = Camera::try_new(target + from.normalize_or_zero() * size, target, up, fov_y)?;
        let (right, up_dir, back) = (probe.right, probe.up, -probe.forward);
        let tan_y = (0.5 * fov_y).tan();
        let tan_x = tan_y * aspect;
        // The least distance from `target` with every point inside the frame (and in front).
        let fit = |target: DVec3| {
            points.iter().fold(f64::NEG_INFINITY, |d, p| {
                let v = *p - target;
                let z = v.dot(back);
                d.max(z + v.dot(right).abs() / (fill * tan_x))
                    .max(z + v.dot(up_dir).abs() / (fill * tan_y))
                    .max(z + 1e-6 * size)
            })
        };
        let mut distance = fit(target);
        for _ in 0..32 {
            // The middle of the projected extent (in units of the distance), moved to the
            // centre of the image.
            let (mut x0, mut x1, mut y0, mut y1) =
                (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
            for p in points {
                let v = *p - target;
                let depth = distance - v.dot(back);
                let (x, y) = (v.dot(right) / depth, v.dot(up_dir) / depth);
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
            let (mx, my) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            if mx.abs().max(my.abs()) < 1e-6 {
                break;
            }
            target += (right * mx + up_dir * my) * distance;
            distance = fit(target);
        }
        Camera::try_new(target + back * distance, target, up, fov_y)
    }

    /// The unit vector to the right in the image.
    #[must_use]
    pub fn right(&self) -> DVec3 {
        self.right
    }

    /// The unit vector up in the image.
    #[must_use]
    pub fn up(&self) -> DVec3 {
        self.up
    }

    /// The eye point.
    #[must_use]
    pub fn eye(&self) -> DVec3 {
        self.eye
    }

    /// The unit view direction.
    #[must_use]
    pub fn forward(&self) -> DVec3 {
        self.forward
    }

    /// The vertical field of view, radians.
    #[must_use]
    pub fn fov_y(&self) -> f64 {
        self.fov_y
    }

    /// The tangent of half the vertical field of view.
    pub(crate) fn tan_half(&self) -> f64 {
        self.tan_half
    }

    /// Where `point` appears in the image of aspect ratio `aspect`: the (x, y) in [0, 1]² (x
    /// to the right, y down) whose [`Camera::ray`] passes through it, or `None` when it is not
    /// in front of the eye (on or behind the plane through the eye normal to the view).
    #[must_use]
    pub(crate) fn project(&self, point: DVec3, aspect: f64) -> Option<(f64, f64)> {
        let v = point - self.eye;
        let z = v.dot(self.forward);
        if z <= 0.0 || z.is_nan() {
            return None;
        }
        let (sx, sy) = (v.dot(self.right) / z, v.dot(self.up) / z);
        Some((0.5 * (sx / (self.tan_half * aspect) + 1.0), 0.5 * (1.0 - sy / self.tan_half)))
    }

    /// The ray through the image point (`x`, `y`) in [0, 1]² (x to the right, y down; (0.5, 0.5)
    /// is the centre) of an image with aspect ratio `aspect` = width/height. Its direction has
    /// unit length.
    #[must_use]
    pub fn ray(&self, x: f64, y: f64, aspect: f64) -> Ray {
        let sx = (2.0 * x - 1.0) * self.tan_half * aspect;
        let sy = (1.0 - 2.0 * y) * self.tan_half;
        let dir = (self.forward + self.right * sx + self.up * sy).normalize();
        Ray::new(self.eye, dir)
    }
}
