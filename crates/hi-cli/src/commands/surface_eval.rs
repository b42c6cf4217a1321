// SPDX-License-Identifier: MIT
//! `hi surface eval`: a harmonic surface, its derivatives, normal and curvature at (u, v)
//! pairs (Hardy 2005, §5.1, §4.6).

use glam::DVec3;
use hi_surface::SurfaceDerivs;

use crate::cli::SurfaceEvalArgs;
use crate::error::Failure;
use crate::input::read_surface;
use serde::Serialize;

use crate::output::{Json, json};

/// `{"p", "pu", "pv", "puu", "puv", "pvv", "normal", "gaussian", "mean"}`, one entry per
/// (u, v) pair; `normal`, `gaussian` and `mean` are null where pᵤ × pᵥ = 0.
///
/// # Errors
///
/// [`Failure::Input`] for a bad grid file, or `--u` and `--v` of different lengths.
pub(crate) fn run(args: &SurfaceEvalArgs) -> Result<Json, Failure> {
    let (us, vs) = (&args.u.0, &args.v.0);
    if us.len() != vs.len() {
        return Err(Failure::input(format!(
            "--u has {} values and --v has {}: give one v for each u (the pairs (u, v))",
            us.len(),
            vs.len()
        )));
    }
    let surface = read_surface(&args.input.input)?;
    let derivs: Vec<_> = us.iter().zip(vs).map(|(&u, &v)| surface.derivs(u, v)).collect();
    let curvature: Vec<_> = derivs.iter().map(|d| d.curvature(surface.radius())).collect();
    let vectors = |f: &dyn Fn(&SurfaceDerivs) -> DVec3| derivs.iter().map(f).collect();
    /// One array per quantity, one entry per (u, v); `null` where the surface is singular.
    #[derive(Serialize)]
    struct Values {
        p: Vec<DVec3>,
        pu: Vec<DVec3>,
        pv: Vec<DVec3>,
        puu: Vec<DVec3>,
        puv: Vec<DVec3>,
        pvv: Vec<DVec3>,
        normal: Vec<Option<DVec3>>,
        gaussian: Vec<Option<f64>>,
        mean: Vec<Option<f64>>,
    }
    json(&Values {
        p: vectors(&|d| d.p),
        pu: vectors(&|d| d.pu),
        pv: vectors(&|d| d.pv),
        puu: vectors(&|d| d.puu),
        puv: vectors(&|d| d.puv),
        pvv: vectors(&|d| d.pvv),
        normal: curvature.iter().map(|c| c.map(|c| c.normal)).collect(),
        gaussian: curvature.iter().map(|c| c.map(|c| c.gaussian)).collect(),
        mean: curvature.iter().map(|c| c.map(|c| c.mean)).collect(),
    })
}
