// SPDX-License-Identifier: MIT
//! `hi surface eval`: a harmonic surface, its derivatives, normal and curvature at (u, v)
//! pairs (Hardy 2005, §5.1, §4.6).

use glam::DVec3;

use crate::cli::SurfaceEvalArgs;
use crate::error::Failure;
use crate::input::read_surface;
use crate::output::{Json, Object};

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
    let vectors = |f: &dyn Fn(usize) -> DVec3| {
        Json::Array((0..derivs.len()).map(|i| Json::point(&f(i))).collect())
    };
    Ok(Object::new()
        .field("p", vectors(&|i| derivs[i].p))
        .field("pu", vectors(&|i| derivs[i].pu))
        .field("pv", vectors(&|i| derivs[i].pv))
        .field("puu", vectors(&|i| derivs[i].puu))
        .field("puv", vectors(&|i| derivs[i].puv))
        .field("pvv", vectors(&|i| derivs[i].pvv))
        .field(
            "normal",
            Json::Array(
                curvature
                    .iter()
                    .map(|c| c.map_or(Json::Null, |c| Json::point(&c.normal)))
                    .collect(),
            ),
        )
        .field("gaussian", Json::optional_numbers(curvature.iter().map(|c| c.map(|c| c.gaussian))))
        .field("mean", Json::optional_numbers(curvature.iter().map(|c| c.map(|c| c.mean))))
        .build())
}
