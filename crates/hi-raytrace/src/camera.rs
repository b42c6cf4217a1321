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
