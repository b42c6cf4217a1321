//! scratch
use glam::DVec3;
use hi_raytrace::*;
fn main() {
    let camera = Camera::try_new(DVec3::new(1.0, -3.0, 2.0), DVec3::ZERO, DVec3::Z, 0.9).unwrap();
    let k = HarmonicObject::try_new(hi_surface::sphere(1.0), &HarmonicSettings::default()).unwrap();
    let n = 40;
    for i in 0..n * n {
        let r =
            camera.ray(((i % n) as f64 + 0.5) / n as f64, ((i / n) as f64 + 0.5) / n as f64, 1.0);
        let (o, d) = (r.origin, r.dir);
        let b = o.dot(d);
        let c = o.dot(o) - 1.0;
        let disc = b * b - c;
        if disc < 0.0 {
            continue;
        }
        let t = -b - disc.sqrt();
        if let Some(h) = k.intersect(&r) {
            if (h.t - t).abs() > 1e-9 {
                println!("pixel {i}: {h:?} exact {t}");
            }
        }
    }
}
