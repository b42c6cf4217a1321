// SPDX-License-Identifier: MIT
//! Point clouds for `cargo xtask bench fit` ([`super::clouds`]): points drawn uniformly by area
//! on a mesh's triangles, moved by Gaussian noise, from a fixed seed, and written as XYZ.
//!
//! - [`SplitMix64`]: the random stream (Steele, Lea and Flood's splitmix64), uniform numbers
//!   from its top 53 bits and Gaussian ones by the Box–Muller transform;
//! - [`sample_triangles`]: a triangle chosen with probability proportional to its area (binary
//!   search in the running sum of areas), then a point uniform on it,
//!   (1 − √r₁) a + √r₁ (1 − r₂) b + √r₁ r₂ c for r₁, r₂ uniform on [0, 1);
//! - [`with_noise`]: each point moved by an isotropic Gaussian, every coordinate independently
//!   N(0, σ²);
//! - [`torus_knot_tube`]: a genus-1 surface made here, a tube about the (2, 3) torus knot
//!   (the trefoil), as a triangle mesh to sample;
//! - [`write_xyz`] and [`cloud_file`]: the cache's files, written whole or not at all.

use std::f64::consts::TAU;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use glam::DVec3;

/// splitmix64: a deterministic stream of well-mixed 64-bit words from a seed.
#[derive(Clone, Debug)]
pub(crate) struct SplitMix64(u64);

impl SplitMix64 {
    /// The stream from `seed`.
    pub(crate) const fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next word.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number uniform on [0, 1): the top 53 bits of the next word, over 2⁵³.
    pub(crate) fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A standard normal number (Box–Muller: √(−2 ln u₁) cos 2πu₂, with u₁ in (0, 1]).
    pub(crate) fn gaussian(&mut self) -> f64 {
        let u1 = 1.0 - self.uniform();
        let u2 = self.uniform();
        (-2.0 * u1.ln()).sqrt() * (TAU * u2).cos()
    }
}

/// The length of the diagonal of the bounding box of `points` (0 for none).
pub(crate) fn diagonal(points: &[DVec3]) -> f64 {
    if points.is_empty() {
        return 0.0;
    }
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    (hi - lo).length()
}

/// `n` points uniform by area on the triangles of a mesh, from `rng`.
///
/// # Errors
///
/// When the triangles have no area (or there are none), or index a missing point.
pub(crate) fn sample_triangles(
    points: &[DVec3],
    triangles: &[[u32; 3]],
    n: usize,
    rng: &mut SplitMix64,
) -> Result<Vec<DVec3>> {
    let corner = |t: &[u32; 3]| -> Result<[DVec3; 3]> {
        let at =
            |k: u32| points.get(k as usize).copied().context("a triangle's index is out of range");
        Ok([at(t[0])?, at(t[1])?, at(t[2])?])
    };
    let mut running = Vec::with_capacity(triangles.len());
    let mut total = 0.0;
    for t in triangles {
        let [a, b, c] = corner(t)?;
        total += 0.5 * (b - a).cross(c - a).length();
        running.push(total);
    }
    if !(total > 0.0 && total.is_finite()) {
        bail!("the mesh has no area to sample");
    }
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        let at = rng.uniform() * total;
        // The first triangle whose running sum passes `at`: one of zero area never is.
        let k = running.partition_point(|s| *s <= at).min(triangles.len() - 1);
        let [a, b, c] = corner(&triangles[k])?;
        let (s, r2) = (rng.uniform().sqrt(), rng.uniform());
        out.push(a * (1.0 - s) + b * (s * (1.0 - r2)) + c * (s * r2));
    }
    Ok(out)
}

/// `points`, each moved by an isotropic Gaussian displacement: every coordinate independently
/// N(0, `sigma`²) (so the displacement along any direction, the normal included, has standard
/// deviation `sigma`, and its length has root mean square √3 `sigma`).
pub(crate) fn with_noise(points: Vec<DVec3>, sigma: f64, rng: &mut SplitMix64) -> Vec<DVec3> {
    points
        .into_iter()
        .map(|p| p + DVec3::new(rng.gaussian(), rng.gaussian(), rng.gaussian()) * sigma)
        .collect()
}

/// The centre line of the tube: the (2, 3) torus knot
/// ((2 + cos 3t) cos 2t, (2 + cos 3t) sin 2t, sin 3t), t in [0, 2π).
fn trefoil(t: f64) -> DVec3 {
    let r = 2.0 + (3.0 * t).cos();
    DVec3::new(r * (2.0 * t).cos(), r * (2.0 * t).sin(), (3.0 * t).sin())
}

/// The tube of `radius` about the trefoil torus knot, as a closed triangle mesh of
/// `along` × `around` quads (each split in two): circles in the normal planes of the curve,
/// in its Frenet frame (the knot's curvature stays between 0.38 and 0.70, so the frame is
/// defined everywhere and periodic; its strands are at least 1.66 apart, so a radius below
/// 0.8 keeps the tube embedded). A torus, knotted: genus 1.
pub(crate) fn torus_knot_tube(
    radius: f64,
    along: usize,
    around: usize,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let h = 1e-4;
    let mut points = Vec::with_capacity(along * around);
    for i in 0..along {
        let t = TAU * i as f64 / along as f64;
        let c = trefoil(t);
        let d1 = (trefoil(t + h) - trefoil(t - h)) / (2.0 * h);
        let d2 = (trefoil(t + h) - 2.0 * c + trefoil(t - h)) / (h * h);
        let tangent = d1.normalize();
        let normal = (d2 - tangent * d2.dot(tangent)).normalize();
        let binormal = tangent.cross(normal);
        for j in 0..around {
            let a = TAU * j as f64 / around as f64;
            points.push(c + (normal * a.cos() + binormal * a.sin()) * radius);
        }
    }
    let index = |i: usize, j: usize| ((i % along) * around + j % around) as u32;
    let mut triangles = Vec::with_capacity(2 * along * around);
    for i in 0..along {
        for j in 0..around {
            let (a, b, c, d) = (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    (points, triangles)
}

/// The cache file of a cloud: `DIR/NAME-N-sSEED.xyz`, keyed by model, size and seed (the
/// noise is the same for every cloud).
pub(crate) fn cloud_file(dir: &Path, name: &str, n: usize, seed: u64) -> PathBuf {
    dir.join(format!("{name}-{n}-s{seed}.xyz"))
}

/// Writes `points` as XYZ (x y z per line, nine significant digits after the first), to a
/// temporary file renamed into place, so that an interrupted run leaves no partial cache.
///
/// # Errors
///
/// When the file cannot be written.
pub(crate) fn write_xyz(path: &Path, points: &[DVec3]) -> Result<()> {
    let partial = path.with_extension("xyz.partial");
    let file = std::fs::File::create(&partial)
        .with_context(|| format!("creating {}", partial.display()))?;
    let mut w = std::io::BufWriter::new(file);
    for p in points {
        writeln!(w, "{:.9e} {:.9e} {:.9e}", p.x, p.y, p.z)?;
    }
    w.flush()?;
    drop(w);
    std::fs::rename(&partial, path).with_context(|| format!("writing {}", path.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_gives_the_reference_stream() {
        // The first outputs of splitmix64 from seed 0, as in Vigna's reference implementation.
        let mut rng = SplitMix64::new(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(rng.next_u64(), 0x06C4_5D18_8009_454F);
        // The top 53 bits over 2⁵³.
        let mut rng = SplitMix64::new(0);
        let u = rng.uniform();
        assert_eq!(u, (0xE220_A839_7B1D_CDAF_u64 >> 11) as f64 / 2f64.powi(53));
        assert!((0.0..1.0).contains(&u));
    }

    #[test]
    fn gaussian_numbers_have_mean_zero_and_variance_one() {
        let mut rng = SplitMix64::new(7);
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| rng.gaussian()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / n as f64;
        // Standard errors: 1/√n ≈ 0.0022 for the mean, √(2/n) ≈ 0.0032 for the variance.
        assert!(mean.abs() < 0.011, "mean {mean}");
        assert!((var - 1.0).abs() < 0.016, "variance {var}");
        // P(|x| < 1) = erf(1/√2) = 0.682689…
        let inside = xs.iter().filter(|x| x.abs() < 1.0).count() as f64 / n as f64;
        assert!((inside - 0.682_689).abs() < 0.005, "within one σ: {inside}");
    }

    #[test]
    fn samples_lie_on_the_triangles_in_proportion_to_their_areas() {
        // Two triangles in z = 0 of areas 1/2 and 3/2, and one of zero area, which is never
        // drawn.
        let points = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(5.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
        ];
        let triangles = [[0, 1, 2], [0, 1, 3], [3, 4, 5]];
        let n = 40_000;
        let cloud = sample_triangles(&points, &triangles, n, &mut SplitMix64::new(1)).unwrap();
        assert_eq!(cloud.len(), n);
        let first = cloud.iter().filter(|p| p.x <= 1.0 + 1e-12).count();
        let second = cloud.iter().filter(|p| p.x >= 2.0 - 1e-12).count();
        assert_eq!(first + second, n, "every point is on one of the two triangles");
        assert!(cloud.iter().all(|p| p.z == 0.0 && p.x >= 0.0 && p.y >= 0.0));
        assert!(cloud.iter().filter(|p| p.x <= 1.0).all(|p| p.x + p.y <= 1.0 + 1e-12));
        assert!(
            cloud.iter().filter(|p| p.x >= 2.0).all(|p| (p.x - 2.0) / 3.0 + p.y <= 1.0 + 1e-12)
        );
        // Expected fraction 1/4 on the first; binomial standard error √(pq/n) ≈ 0.0022.
        let share = first as f64 / n as f64;
        assert!((share - 0.25).abs() < 0.011, "share {share}");
        // Uniform on a triangle: the mean is the centroid, (5/3, 1/3) on the second.
        let mean = cloud.iter().filter(|p| p.x >= 2.0).sum::<DVec3>() / second as f64;
        assert!((mean - DVec3::new(2.0 + 1.0, 1.0 / 3.0, 0.0)).length() < 0.02, "{mean}");
        // The same seed gives the same cloud.
        let again = sample_triangles(&points, &triangles, n, &mut SplitMix64::new(1)).unwrap();
        assert_eq!(cloud, again);
        assert!(sample_triangles(&points, &[[0, 1, 1]], 1, &mut SplitMix64::new(1)).is_err());
        assert!(sample_triangles(&points, &[[0, 1, 9]], 1, &mut SplitMix64::new(1)).is_err());
    }

    #[test]
    fn noise_has_the_stated_deviation_along_every_axis() {
        let n = 100_000;
        let noisy = with_noise(vec![DVec3::ZERO; n], 0.5, &mut SplitMix64::new(3));
        for axis in [DVec3::X, DVec3::Y, DVec3::Z, DVec3::ONE.normalize()] {
            let var = noisy.iter().map(|p| p.dot(axis).powi(2)).sum::<f64>() / n as f64;
            assert!((var.sqrt() - 0.5).abs() < 0.005, "σ along {axis}: {}", var.sqrt());
        }
        let rms = (noisy.iter().map(|p| p.length_squared()).sum::<f64>() / n as f64).sqrt();
        assert!((rms - 0.5 * 3f64.sqrt()).abs() < 0.005, "length RMS {rms}");
    }

    #[test]
    fn the_knot_tube_is_a_closed_torus_at_the_stated_radius() {
        let (along, around) = (200, 12);
        let (points, triangles) = torus_knot_tube(0.4, along, around);
        assert_eq!(points.len(), along * around);
        assert_eq!(triangles.len(), 2 * along * around);
        // Euler characteristic V − E + F = 0 (genus 1): every edge is shared by two triangles.
        let mut edges = std::collections::HashMap::new();
        for t in &triangles {
            for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        assert!(edges.values().all(|&k| k == 2), "closed");
        let chi = points.len() as i64 - edges.len() as i64 + triangles.len() as i64;
        assert_eq!(chi, 0, "genus 1");
        // Each ring is a circle of radius 0.4 about the knot, in the curve's normal plane.
        for i in [0, 37, 199] {
            let t = TAU * i as f64 / along as f64;
            let tangent = (trefoil(t + 1e-6) - trefoil(t - 1e-6)).normalize();
            for p in &points[i * around..(i + 1) * around] {
                assert!(((*p - trefoil(t)).length() - 0.4).abs() < 1e-9);
                assert!((*p - trefoil(t)).dot(tangent).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn clouds_are_cached_by_model_size_and_seed_and_written_whole() {
        let dir = Path::new("/cache");
        assert_eq!(cloud_file(dir, "bunny", 200_000, 1), Path::new("/cache/bunny-200000-s1.xyz"));
        assert_ne!(cloud_file(dir, "bunny", 200_000, 1), cloud_file(dir, "bunny", 200_000, 2));
        let tmp = std::env::temp_dir().join(format!("xtask-xyz-{}", std::process::id()));
        std::fs::create_dir_all(&tmp).unwrap();
        let path = tmp.join("c.xyz");
        write_xyz(&path, &[DVec3::new(1.0, -0.5, 1e-3), DVec3::new(0.1, 2.0, 3.0)]).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(
            text,
            "1.000000000e0 -5.000000000e-1 1.000000000e-3\n1.000000000e-1 2.000000000e0 3.000000000e0\n"
        );
        assert!(!tmp.join("c.xyz.partial").exists());
        std::fs::remove_dir_all(&tmp).unwrap();
    }
}
