// SPDX-License-Identifier: MIT
//! The renderer (Hardy 2005, §5.5, §5.6): rays through the pixels, supersampled, shaded in linear
//! light and written as sRGB PNG; tiles in parallel.
//!
//! **Determinism.** Every pixel's samples come from a fixed pattern — the pixel centre for one
//! sample, otherwise the first points of the (0, 2)-sequence in base 2, shifted per pixel by a
//! hash of the pixel's position (a fixed seed) — and each pixel is computed by one thread from its own samples, so a render is
//! the same, byte for byte, whatever the number of threads and the order they run in.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use hi_mesh::linear_to_srgb;
use hi_par::*;

use crate::bins::{LightGrids, ScreenBins};
use crate::camera::Camera;
use crate::error::Error;
use crate::ray::Ray;
use crate::scene::{Geometry, Scene};

/// Largest width or height accepted.
pub const MAX_SIZE: u32 = 1 << 14;

/// Most samples per pixel accepted.
pub const MAX_SAMPLES: u32 = 1024;

/// Image size and sampling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RenderOptions {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Samples per pixel (1 = the pixel centre).
    pub samples_per_pixel: u32,
    /// Side of the square tiles rendered in parallel.
    pub tile_size: u32,
    /// Adaptive supersampling: when above 0 and below `samples_per_pixel`, each pixel first
    /// takes this many samples, and only where they differ by more than [`ADAPTIVE_SPREAD`]
    /// in a channel, or their mean differs that much from a neighbouring pixel's (an edge, a
    /// shadow's border, a highlight, a feature thinner than a pixel), is it rendered again with
    /// all `samples_per_pixel` (the same samples a plain render takes there, so edges come out
    /// exactly as in one: the first samples are kept and the rest added); elsewhere the first
    /// samples' mean is the pixel. 0: every pixel takes `samples_per_pixel`.
    pub first_pass: u32,
}

/// The spread of linear colour between a pixel's first samples above which
/// [`RenderOptions::first_pass`] renders it with every sample.
pub const ADAPTIVE_SPREAD: f32 = 0.02;

impl Default for RenderOptions {
    /// 512 × 512, 4 samples per pixel, 16-pixel tiles, no first pass.
    fn default() -> Self {
        RenderOptions {
            width: 512,
            height: 512,
            samples_per_pixel: 4,
            tile_size: 16,
            first_pass: 0,
        }
    }
}

/// How many rays a render cast.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RayCounts {
    /// Rays from the eye.
    pub camera: usize,
    /// Rays towards lights.
    pub shadow: usize,
    /// Camera rays that met an object.
    pub hits: usize,
    /// Camera-ray hits where a light in front of the surface was blocked.
    pub shadowed: usize,
}

/// A finished render: the sRGB image, ray counts and the time taken.
#[derive(Clone, Debug)]
pub struct Rendering {
    /// The image width in pixels.
    pub width: u32,
    /// The image height in pixels.
    pub height: u32,
    /// The pixels, 8-bit sRGB, row by row from the top left (`width × height` of them).
    pub pixels: Vec<[u8; 3]>,
    /// The rays cast.
    pub counts: RayCounts,
    /// Wall-clock time of the render.
    pub elapsed: Duration,
}

impl Rendering {
    /// The pixel at column `x`, row `y` (from the top left); `None` outside the image.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 3]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.pixels.get(y as usize * self.width as usize + x as usize).copied()
    }

    /// The image as PNG bytes (the `png` feature).
    ///
    /// # Errors
    ///
    /// [`Error::PixelCount`] if the pixels do not fill the image; [`Error::WriteImage`] if
    /// encoding fails.
    #[cfg(feature = "png")]
    pub fn png_bytes(&self) -> Result<Vec<u8>, Error> {
        let raw: Vec<u8> = self.pixels.iter().flatten().copied().collect();
        let image =
            image::RgbImage::from_raw(self.width, self.height, raw).ok_or(Error::PixelCount {
                width: self.width,
                height: self.height,
                pixels: self.pixels.len(),
            })?;
        let mut out = std::io::Cursor::new(Vec::new());
        image.write_to(&mut out, image::ImageFormat::Png).map_err(|e| Error::WriteImage {
            kind: match e {
                image::ImageError::IoError(e) => e.kind(),
                image::ImageError::Limits(_) => std::io::ErrorKind::OutOfMemory,
                _ => std::io::ErrorKind::InvalidData,
            },
        })?;
        Ok(out.into_inner())
    }

    /// Writes the image as PNG to `w` (the `png` feature).
    ///
    /// # Errors
    ///
    /// [`Error::PixelCount`] and [`Error::WriteImage`] as [`Rendering::png_bytes`], and
    /// [`Error::WriteImage`] if writing fails.
    #[cfg(feature = "png")]
    pub fn write_png<W: std::io::Write>(&self, mut w: W) -> Result<(), Error> {
        let bytes = self.png_bytes()?;
        w.write_all(&bytes).map_err(|e| Error::WriteImage { kind: e.kind() })
    }
}

/// A progress report: tiles finished and tiles in all.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// Checks the options against the limits.
fn check_options(options: &RenderOptions) -> Result<(), Error> {
    let (w, h) = (options.width, options.height);
    if w == 0 || h == 0 {
        return Err(Error::ZeroSizeImage { width: w, height: h });
    }
    for (what, value) in [("image width", w), ("image height", h)] {
        if value > MAX_SIZE {
            return Err(Error::InvalidValue {
                what,
                value: f64::from(value),
                expected: "at most 16384",
            });
        }
    }
    if !(1..=MAX_SAMPLES).contains(&options.samples_per_pixel) {
        return Err(Error::InvalidValue {
            what: "samples per pixel",
            value: f64::from(options.samples_per_pixel),
            expected: "1 to 1024",
        });
    }
    if options.tile_size == 0 {
        return Err(Error::InvalidValue { what: "tile size", value: 0.0, expected: "at least 1" });
    }
    Ok(())
}

/// `SplitMix64`: a fixed, well-mixed hash.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The base-2 radical inverse of `i` (van der Corput): the first dimension of Sobol's sequence.
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) / 4_294_967_296.0
}

/// The second dimension of Sobol's sequence (generator matrix: Pascal's triangle mod 2), in
/// [0, 1). With [`radical_inverse`] it makes the (0, 2)-sequence in base 2: its first 2ᵏ points
/// are a (0, k, 2)-net, one point in every elementary box of area 2⁻ᵏ.
fn sobol_second(mut i: u32) -> f64 {
    let (mut v, mut r) = (1u32 << 31, 0u32);
    while i != 0 {
        if i & 1 == 1 {
            r ^= v;
        }
        i >>= 1;
        v ^= v >> 1;
    }
    f64::from(r) / 4_294_967_296.0
}

/// Sample `s` of `n` in pixel (`x`, `y`), as an offset in [0, 1)² within the pixel: the pixel
/// centre for one sample, otherwise point `s` of the (0, 2)-sequence shifted (Cranley–Patterson)
/// by a hash of the pixel. Any first 4 or 16 samples are stratified on their own, so a pixel
/// refined from 4 samples to 16 keeps the first 4 ([`RenderOptions::first_pass`]).
fn sample_offset(x: u32, y: u32, s: u32, n: u32) -> (f64, f64) {
    if n == 1 {
        return (0.5, 0.5);
    }
    let h = mix((u64::from(x) << 32) ^ u64::from(y) ^ 0x5EED_2005);
    let (rx, ry) =
        ((h >> 11) as f64 / (1u64 << 53) as f64, (mix(h) >> 11) as f64 / (1u64 << 53) as f64);
    // (Both sums lie in [0, 2): wrapping by one subtraction is `fract`, without its call.)
    let wrap = |a: f64| if a >= 1.0 { a - 1.0 } else { a };
    (wrap(radical_inverse(s) + rx), wrap(sobol_second(s) + ry))
}

/// Renders `scene` through `camera`. `progress`, if given, is called after each tile with the
/// tiles finished and the total.
///
/// # Errors
///
/// [`Error::ZeroSizeImage`] for a width or height of 0; [`Error::InvalidValue`] for a size above
/// [`MAX_SIZE`], samples per pixel outside 1..=[`MAX_SAMPLES`] or a zero tile size.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_raytrace::*;
///
/// let torus = HarmonicObject::try_new(hi_surface::torus(2.0, 0.5), &HarmonicOptions::default())?;
/// let light = Light::Directional { direction: DVec3::new(1.0, 1.0, 2.0), intensity: [1.0; 3] };
/// let scene = Scene::try_new(vec![SceneObject::new(Geometry::Harmonic(torus))], vec![light], [0.1; 3])?;
/// let camera = Camera::try_new(DVec3::new(0.0, -6.0, 4.0), DVec3::ZERO, DVec3::Z, 0.7)?;
/// let options =
///     RenderOptions { width: 24, height: 16, samples_per_pixel: 1, tile_size: 8, first_pass: 0 };
/// let out = render(&scene, &camera, &options, None)?;
/// assert_eq!((out.width, out.height, out.pixels.len()), (24, 16, 24 * 16));
/// assert_eq!(out.counts.camera, 24 * 16);
/// assert!(out.counts.hits > 0);
/// # Ok::<(), hi_raytrace::Error>(())
/// ```
pub fn render(
    scene: &Scene,
    camera: &Camera,
    options: &RenderOptions,
    progress: Option<Progress<'_>>,
) -> Result<Rendering, Error> {
    check_options(options)?;
    let start = Instant::now();
    let (w, h, ts) = (options.width, options.height, options.tile_size);
    let (nx, ny) = (w.div_ceil(ts), h.div_ceil(ts));
    let n_tiles = (nx * ny) as usize;
    let done = AtomicUsize::new(0);
    let aspect = f64::from(w) / f64::from(h);
    let background = scene.background();
    // The meshes' triangles binned for the camera rays and for the shadow rays of each
    // directional light (`crate::bins`): the same hits as the BVH's, found faster.
    let accel =
        Accel { screen: ScreenBins::new(scene, camera, w, h), lights: LightGrids::new(scene) };
    // The tiles on all cores (the `parallel` feature) or in turn; each is computed alone, so
    // the image is the same either way.
    let tiles: Vec<(u32, u32, Vec<[u8; 3]>, RayCounts)> = (0..n_tiles)
        .into_par_iter()
        .map(|tile| {
            let (pixels, counts) =
                render_tile(scene, &accel, camera, options, tile, aspect, background);
            let (x0, y0) = ((tile as u32 % nx) * ts, (tile as u32 / nx) * ts);
            let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
            if let Some(report) = progress {
                report(finished, n_tiles);
            }
            (x0, y0, pixels, counts)
        })
        .collect();
    let mut image_pixels = vec![[0u8; 3]; w as usize * h as usize];
    let mut counts = RayCounts::default();
    for (x0, y0, pixels, c) in tiles {
        let tw = (x0 + ts).min(w) - x0;
        for (i, px) in pixels.into_iter().enumerate() {
            let (x, y) = (x0 + i as u32 % tw, y0 + i as u32 / tw);
            image_pixels[y as usize * w as usize + x as usize] = px;
        }
        counts.camera += c.camera;
        counts.shadow += c.shadow;
        counts.hits += c.hits;
        counts.shadowed += c.shadowed;
    }
    Ok(Rendering { width: w, height: h, pixels: image_pixels, counts, elapsed: start.elapsed() })
}

/// The binned triangles of a render's meshes (`crate::bins`).
struct Accel {
    screen: ScreenBins,
    lights: LightGrids,
}

/// One tile of [`render`] (tile index `tile`, row-major), on its own: its pixels, row by
/// row, and the rays cast. With a first pass (`options.first_pass`), a pixel whose first
/// samples agree with each other and with its neighbours' is their mean; every other pixel
/// takes all `samples_per_pixel`.
fn render_tile(
    scene: &Scene,
    accel: &Accel,
    camera: &Camera,
    options: &RenderOptions,
    tile: usize,
    aspect: f64,
    background: [f32; 3],
) -> (Vec<[u8; 3]>, RayCounts) {
    let (w, h, ts) = (options.width, options.height, options.tile_size);
    let nx = w.div_ceil(ts);
    let spp = options.samples_per_pixel;
    let (tx, ty) = (tile as u32 % nx, tile as u32 / nx);
    let (x0, y0) = (tx * ts, ty * ts);
    let (x1, y1) = ((x0 + ts).min(w), (y0 + ts).min(h));
    let mut pixels = Vec::with_capacity(((x1 - x0) * (y1 - y0)) as usize);
    let mut counts = RayCounts::default();
    let first = options.first_pass;
    let adaptive = first > 0 && first < spp;
    // The pixels whose samples may be taken: the tile, and with a first pass a one-pixel
    // border around it (a pixel whose few samples all miss a thin edge shows it by differing
    // from a neighbour).
    let (bx0, by0) = if adaptive { (x0.saturating_sub(1), y0.saturating_sub(1)) } else { (x0, y0) };
    let (bx1, by1) = if adaptive { ((x1 + 1).min(w), (y1 + 1).min(h)) } else { (x1, y1) };
    let bw = (bx1 - bx0) as usize;
    // Every sample's camera ray, and its nearest hit on the meshes, found for all of them at
    // once by the bins; a sample not taken in the end costs its ray and its few triangle tests.
    let at: Vec<(f64, f64)> = (by0..by1)
        .flat_map(|y| (bx0..bx1).map(move |x| (x, y)))
        .flat_map(|(x, y)| (0..spp).map(move |s| (x, y, s)))
        .map(|(x, y, s)| {
            let (ox, oy) = sample_offset(x, y, s, spp);
            (f64::from(x) + ox, f64::from(y) + oy)
        })
        .collect();
    let rays: Vec<Ray> =
        at.iter().map(|&(x, y)| camera.ray(x / f64::from(w), y / f64::from(h), aspect)).collect();
    let mesh_hits = if accel.screen.any() {
        accel.screen.nearest(scene, (bx0, by0, bx1, by1), spp, &rays, &at)
    } else {
        vec![None; rays.len()]
    };
    let binned: Vec<bool> = (0..scene.objects().len()).map(|i| accel.screen.binned(i)).collect();
    let all_binned = binned.iter().all(|&b| b);
    // Samples `from..to` of the `spp` of pixel (x, y), added to `sum`; returns the
    // spread of these samples in their widest channel.
    let mut samples = |x: u32, y: u32, from: u32, to: u32, sum: &mut [f64; 3]| {
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        let pixel = ((y - by0) as usize * bw + (x - bx0) as usize) * spp as usize;
        for s in from..to {
            let ray = &rays[pixel + s as usize];
            counts.camera += 1;
            // (The bins hold the hits of meshes only.)
            let on_mesh = mesh_hits[pixel + s as usize].and_then(|(index, tri, h)| {
                match &scene.objects()[index].geometry {
                    Geometry::Mesh(m) => Some(scene.mesh_hit(index, m, tri, &h, ray)),
                    _ => None,
                }
            });
            let hit = if all_binned {
                on_mesh
            } else {
                scene.intersect_after(ray, on_mesh, |i| !binned[i])
            };
            let color = match hit {
                Some(hit) => {
                    counts.hits += 1;
                    // The triangle the shadow rays leave, when the hit is on a mesh.
                    let from = mesh_hits[pixel + s as usize]
                        .map(|(index, tri, _)| (index, tri))
                        .filter(|&(index, _)| index == hit.object);
                    let (c, n_shadow, blocked) = scene.shade(ray, &hit, |light, shadow| {
                        accel.lights.occluded(scene, light, shadow, from)
                    });
                    counts.shadow += n_shadow;
                    counts.shadowed += usize::from(blocked);
                    c
                }
                None => background,
            };
            for k in 0..3 {
                sum[k] += f64::from(color[k]);
                lo[k] = lo[k].min(color[k]);
                hi[k] = hi[k].max(color[k]);
            }
        }
        (0..3).map(|k| hi[k] - lo[k]).fold(0.0f32, f32::max)
    };
    // The first pass over the tile and its border: the sum of each pixel's first samples,
    // their mean and their spread.
    let coarse: Vec<([f64; 3], [f64; 3], f32)> = if adaptive {
        (by0..by1)
            .flat_map(|y| (bx0..bx1).map(move |x| (x, y)))
            .map(|(x, y)| {
                let mut sum = [0.0; 3];
                let spread = samples(x, y, 0, first, &mut sum);
                (sum, sum.map(|c| c / f64::from(first)), spread)
            })
            .collect()
    } else {
        Vec::new()
    };
    let at = |x: u32, y: u32| &coarse[(y - by0) as usize * bw + (x - bx0) as usize];
    for y in y0..y1 {
        for x in x0..x1 {
            let mean = if adaptive {
                let (sum, mean, spread) = *at(x, y);
                let smooth = spread <= ADAPTIVE_SPREAD
                    && (y.saturating_sub(1)..(y + 2).min(h)).all(|ny| {
                        (x.saturating_sub(1)..(x + 2).min(w)).all(|nx| {
                            let other = at(nx, ny).1;
                            (0..3).all(|k| ((other[k] - mean[k]).abs() as f32) <= ADAPTIVE_SPREAD)
                        })
                    });
                if smooth {
                    mean
                } else {
                    // The rest of the samples, after the first pass's.
                    let mut sum = sum;
                    samples(x, y, first, spp, &mut sum);
                    sum.map(|c| c / f64::from(spp))
                }
            } else {
                let mut sum = [0.0; 3];
                samples(x, y, 0, spp, &mut sum);
                sum.map(|c| c / f64::from(spp))
            };
            let px = mean.map(|c| {
                let linear = c.clamp(0.0, 1.0) as f32;
                (linear_to_srgb(linear) * 255.0).round().clamp(0.0, 255.0) as u8
            });
            pixels.push(px);
        }
    }
    (pixels, counts)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first 4 and the first 16 samples of a pixel are (0, k, 2)-nets: one sample in every
    /// elementary box of area 1/4 (resp. 1/16) of the pixel, for every shape of box, so a
    /// refined pixel's 16 samples are as well spread as a fresh set (checked before the
    /// per-pixel shift, which moves every box alike modulo 1).
    #[test]
    fn first_samples_are_nets() {
        for k in [2u32, 4] {
            let n = 1u32 << k;
            let points: Vec<(f64, f64)> =
                (0..n).map(|s| (radical_inverse(s), sobol_second(s))).collect();
            for a in 0..=k {
                let (cols, rows) = (1u32 << a, 1u32 << (k - a));
                let mut seen = vec![0u32; n as usize];
                for &(x, y) in &points {
                    let (i, j) = ((x * f64::from(cols)) as u32, (y * f64::from(rows)) as u32);
                    seen[(j * cols + i) as usize] += 1;
                }
                assert!(seen.iter().all(|&c| c == 1), "{n} samples, boxes {cols}×{rows}: {seen:?}");
            }
        }
    }
}
