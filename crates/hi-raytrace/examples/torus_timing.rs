// SPDX-License-Identifier: MIT
//! Times the torus of Hardy 2005, figure 5.26 (§5.6), by each method and writes the PNGs:
//! `cargo run --release -p hi-raytrace --example torus_timing -- [SIZE] [DIR]`.

use hi_raytrace::testing::{TorusMethod, render_torus};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let size: u32 = args.next().map_or(Ok(512), |s| s.parse())?;
    let dir = args.next();
    for method in TorusMethod::ALL {
        let out = render_torus(method, size, size, 1)?;
        println!(
            "{:>20}: {size}x{size}, {:8.3} s, {} camera rays, {} hits, {} shadow rays, {} shadowed",
            method.name(),
            out.elapsed.as_secs_f64(),
            out.counts.camera,
            out.counts.hits,
            out.counts.shadow,
            out.counts.shadowed,
        );
        if let Some(dir) = &dir {
            let path = std::path::Path::new(dir).join(format!("torus-{}.png", method.name()));
            out.write_png(std::fs::File::create(path)?)?;
        }
    }
    Ok(())
}
