// SPDX-License-Identifier: MIT
//! The geometry images of a scan's parts by each method (see the module documentation of
//! `fit`): a mesh's parts parameterised, a point set's zero set parameterised and settled onto
//! the points, or the rays of algorithm 2 and §5.8.

use super::*;

/// A part's image, and what is known of the part before its surface.
pub(super) struct Sourced {
    pub(super) name: String,
    pub(super) domain: Domain,
    pub(super) why: String,
    pub(super) area_fraction: f64,
    /// Its share of the scan's points ([`DroppedPart::point_fraction`]).
    pub(super) point_fraction: f64,
    pub(super) genus: usize,
    pub(super) boundary_loops: usize,
    pub(super) repair: Repair,
    pub(super) source: SourceImage,
}

/// The images of a scan's parts, and how they were made.
pub(super) struct Sources {
    pub(super) parts: Vec<Sourced>,
    pub(super) dropped: Vec<DroppedPart>,
    pub(super) method: Method,
    pub(super) reason: String,
    /// The points the images were made from (the scan's, or its summary).
    pub(super) image_points: Vec<DVec3>,
}

/// The texels a part with `area_fraction` of the fitted parts' area gets of `texels`.
fn share(texels: usize, area_fraction: f64, kept: f64) -> usize {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a fraction of a count"
    )]
    let t = (texels as f64 * area_fraction / kept.max(f64::MIN_POSITIVE)).round() as usize;
    t.max(1)
}

/// The user's image size, for the one part of a scan whose one part is a sphere.
fn user_size(options: &FitOptions, planned: &[PlannedPart]) -> Option<(usize, usize)> {
    match planned {
        [only] if matches!(only.domain, Domain::Sphere(_)) => options.resolution,
        _ => None,
    }
}

/// A sentence on what the planned parts are: how many, what was dropped.
fn parts_sentence(planned: &[PlannedPart], dropped: &[DroppedPart]) -> String {
    let mut s = match planned.len() {
        1 => String::new(),
        n => format!("; {n} parts, each fitted on its own"),
    };
    if !dropped.is_empty() {
        s.push_str(&format!(
            "; {} {} left out",
            dropped.len(),
            if dropped.len() == 1 { "part" } else { "parts" }
        ));
    }
    s
}

/// The images of a mesh's parts, each parameterised over its domain; `Ok(Err(why))` when the
/// mesh cannot stand for the scan (its parts above the floor hold too little of its area, or
/// none can be made a surface) and `force` is off.
fn mesh_sources(
    points: &[DVec3],
    triangles: &[[u32; 3]],
    options: &FitOptions,
    texels: usize,
    force: bool,
    clock: &mut Clock<'_>,
) -> Result<Result<Sources, String>, Error> {
    let parts: MeshParts = clock.run(StageKind::Parts, (0, 1), || mesh_parts(points, triangles))?;
    let (planned, dropped) = clock.run(StageKind::Parts, (0, 1), || {
        let floor = (PART_FLOOR, MESH_PART_MIN_VERTICES);
        let points = vertex_counts(&parts);
        plan(&parts, &points, options.boundary, options.layout, floor, MAX_HANDLES, 0.0)
    });
    let kept: f64 = planned.iter().map(|p| p.area_fraction).sum();
    if planned.is_empty() || (!force && kept < MIN_AREA_KEPT) {
        let why = if planned.is_empty() {
            match dropped.first() {
                Some(d) => {
                    format!("the scan's mesh gives no part to fit ({}: {})", d.name, d.reason)
                }
                None => "the scan's mesh gives no part to fit".to_owned(),
            }
        } else {
            format!(
                "the scan's mesh has {} parts and those above the floor hold only {:.1} % of its area",
                parts.parts.len(),
                100.0 * kept
            )
        };
        if force {
            return Err(Error::Topology { what: why });
        }
        return Ok(Err(why));
    }
    let n = planned.len();
    let size = user_size(options, &planned);
    let mut out = Vec::with_capacity(n);
    let mut planned = planned;
    let images = clock.run_each(StageKind::GeometryImage, &mut planned, |part| {
        let texels = share(texels, part.area_fraction, kept);
        // Texels dense where the mesh's vertices are.
        part_image_or_sphere(part, texels, size, options.layout, true, &mesh_density_weights)
    });
    for (part, image) in planned.iter().zip(images) {
        let image = image?;
        let mut repair = part.closed.repair;
        repair.welded_points = parts.welded_points;
        repair.dropped_triangles = parts.dropped_triangles;
        repair.components = parts.parts.len();
        out.push(Sourced {
            name: part.name.clone(),
            domain: part.domain,
            why: part.why.clone(),
            area_fraction: part.area_fraction,
            point_fraction: part.point_fraction,
            genus: part.topology.genus,
            boundary_loops: part.topology.loops.len(),
            repair,
            source: SourceImage::Mesh(MeshSource {
                image: image.image,
                repair,
                area_kept: part.area_fraction,
                quality: image.quality,
                filled: image.filled,
                filled_fraction: image.filled_fraction,
            }),
        });
    }
    let single = &planned[0];
    let mut reason = match (n, single.domain) {
        (1, Domain::Sphere(_)) => format!("the scan's mesh is one part: {}", single.why),
        (1, _) => format!("the scan's mesh is one part, {}", single.why),
        _ => "the scan's mesh is parameterised part by part".to_owned(),
    };
    reason.push_str(&parts_sentence(&planned, &dropped));
    Ok(Ok(Sources {
        parts: out,
        dropped,
        method: Method::Mesh,
        reason,
        image_points: points.to_vec(),
    }))
}

/// The images of a point set's parts: the zero set of its signed distance split into parts,
/// each parameterised over its domain, settled onto the points' patches and refined by moving
/// least squares on the points themselves ([`MovingLeastSquares`]); the radial image wrapped
/// where the zero set gives no part. A cloud larger than the images can hold is summarised
/// first.
fn point_sources(
    points: &[DVec3],
    normals: Option<&[DVec3]>,
    options: &FitOptions,
    (rows, cols): (usize, usize),
    texels: usize,
    clock: &mut Clock<'_>,
) -> Result<Sources, Error> {
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "a count")]
    let target = ((texels as f64 * SUMMARY_POINTS) as usize).max(SUMMARY_MIN);
    let (reps, rep_normals) = if points.len() as f64 > SUMMARY_RATIO * target as f64 {
        clock.run(StageKind::Summary, (0, 1), || -> Result<_, Error> {
            let cell = cell_for_count(points, target)?;
            let summary = summarise(points, normals, cell)?;
            Ok((summary.points, summary.normals))
        })?
    } else {
        (points.to_vec(), normals.map(<[DVec3]>::to_vec))
    };
    let sources = |median: bool, rescue: bool, finer: &mut bool, clock: &mut Clock<'_>| {
        let wanted = (rows, cols, texels, median, rescue);
        point_sources_on(points, (&reps, rep_normals.as_deref()), options, wanted, finer, clock)
    };
    let mut finer = false;
    let mut made = sources(false, false, &mut finer, clock);
    // A grid finer than the median spacing's (for unevenly dense points) resolves thin parts,
    // but its zero set may be too ragged to parameterise: then the median's, as for evenly
    // dense points.
    let median = made.is_err() && finer;
    if median {
        made = sources(true, false, &mut finer, clock);
    }
    // Should a part's sheet or torus map still fail, that part closed as a sphere.
    if made.is_err() {
        made = sources(median, true, &mut finer, clock);
    }
    made.map(|s| Sources { image_points: reps, ..s })
}

/// [`point_sources`] on the points `reps` (a summary of `points`, or the points themselves)
/// with their normals; the zero set taken on the grid of [`PointSurface::zero_set_cell`], or
/// of [`CELL`] median spacings when `median` (of `wanted` = (rows, cols, texels, median,
/// rescue)); with `rescue`, a part whose sheet or torus map fails is closed as a sphere
/// ([`part_image_or_sphere`]) rather than failing the whole. `finer` says whether the grid taken
/// was finer than the median's. The sources' `image_points` are left empty for the caller.
fn point_sources_on(
    points: &[DVec3],
    (reps, rep_normals): (&[DVec3], Option<&[DVec3]>),
    options: &FitOptions,
    (rows, cols, texels, median, rescue): (usize, usize, usize, bool, bool),
    finer: &mut bool,
    clock: &mut Clock<'_>,
) -> Result<Sources, Error> {
    let kept = |planned: &[PlannedPart]| planned.iter().map(|p| p.area_fraction).sum::<f64>();
    let built = clock.run(StageKind::Parts, (0, 1), || -> Result<_, Error> {
        let surface = PointSurface::try_new(reps, rep_normals, NEIGHBOURS)?;
        let cell = if median { CELL * surface.spacing() } else { surface.zero_set_cell() };
        *finer = cell < CELL * surface.spacing();
        // A zero set whose parts cannot be made surfaces (tunnels beyond counting between the
        // walls of a thin part, or a cloud too sparse for its grid) is taken again on a coarser
        // grid; on the coarsest, more handles are cut before the rays are taken instead. The
        // coarsest grid's zero set is taken first, as it costs a fraction of the finer ones':
        // when its handles say that a finer one's would be too many, the finer are not tried
        // (and it is kept for its turn; else it is let go, and taken again should the finer
        // ones fail, which keeps the peak memory that of one zero set).
        let coarsest = ZERO_SET_COARSER[ZERO_SET_COARSER.len() - 1];
        let zero_set_parts =
            |coarser: f64| surface.zero_set(coarser * cell).and_then(|(v, t)| mesh_parts(&v, &t));
        let mut coarse = Some(zero_set_parts(coarsest));
        let finer_too = match &coarse {
            Some(Ok(parts)) => finer_may_keep(parts, (PART_FLOOR, PART_MIN_VERTICES)),
            _ => true,
        };
        if finer_too {
            coarse = None;
        }
        let mut planned = Err(hi_scan::Error::Degenerate { what: "no zero set" });
        let mut fragments = (0, 0);
        for (k, coarser) in ZERO_SET_COARSER.into_iter().enumerate() {
            let last = k + 1 == ZERO_SET_COARSER.len();
            if !last && !finer_too {
                continue;
            }
            let handles = if last { COARSEST_GRID_HANDLES } else { MAX_HANDLES };
            let parts = coarse.take().unwrap_or_else(|| zero_set_parts(coarser));
            planned = parts.map(|mut parts| {
                let nearest;
                (fragments, nearest) = drop_fragments(&mut parts, reps, PART_MIN_VERTICES);
                let (more, nearest) =
                    regrid_sparse_parts(&surface, reps, &mut parts, nearest, coarser * cell);
                fragments = (fragments.0 + more.0, fragments.1 + more.1);
                let nearest: Vec<usize> = nearest.iter().map(Vec::len).collect();
                let floor = (PART_FLOOR, PART_MIN_VERTICES);
                // On a grid with a coarser one to come, a zero set whose parts of few
                // enough handles hold too little of it is given up at once.
                let least = if last { 0.0 } else { MIN_AREA_KEPT };
                let (boundary, layout) = (options.boundary, options.layout);
                plan(&parts, &nearest, boundary, layout, floor, handles, least)
            });
            if planned.as_ref().is_ok_and(|(p, _)| kept(p) >= MIN_AREA_KEPT) {
                break;
            }
        }
        Ok((surface, planned, fragments))
    })?;
    let (mut surface, planned, fragments) = built;
    let (planned, dropped) = match planned {
        Ok((planned, dropped)) if kept(&planned) >= MIN_AREA_KEPT => (planned, dropped),
        outcome => {
            // No part of the zero set to parameterise: the rays, wrapped.
            let why = match outcome {
                Err(e) => format!("their zero set gave no surface ({e})"),
                Ok((_, dropped)) => match dropped.first() {
                    Some(d) => format!(
                        "the parts of their zero set that could be fitted hold too little of it ({}: {})",
                        d.name, d.reason
                    ),
                    None => "their zero set is empty".to_owned(),
                },
            };
            return wrapped_source(reps, rep_normals, options, (rows, cols), &why, clock);
        }
    };
    // Every patch faces out as the parts' surfaces do.
    let (samples, outward) = parts::outward_samples(&planned);
    surface.orient_to(&samples, &outward);
    let kept: f64 = planned.iter().map(|p| p.area_fraction).sum();
    let n = planned.len();
    let size = user_size(options, &planned);
    // The texels settled on the blend of the patches of their nearest points (of a summary,
    // whose cells average the points, for a large cloud) are refined by a quadric fitted about
    // each texel itself, to the points themselves.
    let mls = MovingLeastSquares::try_new(points)?;
    let mut out = Vec::with_capacity(n);
    let mut planned = planned;
    // The parts side by side (each part's own work is parallel too, but a large part's
    // parameterisation is not all of it).
    let images = clock.run_each(StageKind::GeometryImage, &mut planned, |part| {
        let layout = (options.layout, rescue);
        settled_part_image(part, &surface, reps, &mls, (texels, kept, size), layout)
    });
    for (part, image) in planned.iter().zip(images) {
        let image = image?;
        out.push(Sourced {
            name: part.name.clone(),
            domain: part.domain,
            why: part.why.clone(),
            area_fraction: part.area_fraction,
            point_fraction: part.point_fraction,
            genus: part.topology.genus,
            boundary_loops: part.topology.loops.len(),
            repair: part.closed.repair,
            source: SourceImage::ShrinkWrap(image),
        });
    }
    let reason = zero_set_reason(points, reps, &planned, &dropped, fragments);
    Ok(Sources {
        parts: out,
        dropped,
        method: Method::ShrinkWrap,
        reason,
        image_points: Vec::new(),
    })
}

/// Each part of the zero set `parts` (taken on a grid of `cell`) whose nearest points (`nearest`,
/// indices into `reps`, one list per part) are sparse enough for a grid [`REGRID_RATIO`] times
/// as coarse or more ([`PointSurface::zero_set_cell_of`], scaled as `cell` is from
/// [`PointSurface::zero_set_cell`]) taken again on a coarser grid about its points alone
/// ([`retaken`]): a cell that follows the points' density part by part, fine on the finely
/// sampled parts and coarse on the rest, where the one grid of the densest parts would put
/// many vertices per point (and as many handles to cut and vertices to parameterise) for no
/// detail (parts of at least [`REGRID_MIN_POINTS`] points only). Returns the fragments left out
/// of the parts taken again (count, points) and the points nearest to each part, the parts
/// again largest first.
fn regrid_sparse_parts(
    surface: &PointSurface,
    reps: &[DVec3],
    parts: &mut MeshParts,
    nearest: Vec<Vec<u32>>,
    cell: f64,
) -> ((usize, usize), Vec<Vec<u32>>) {
    // A lone part's points are all of them, whose grid `cell` is.
    if parts.parts.len() < 2 {
        return ((0, 0), nearest);
    }
    let scale = cell / surface.zero_set_cell();
    let again: Vec<Option<Retaken>> = parts
        .parts
        .par_iter()
        .zip(&nearest)
        .map(|(part, about)| {
            if about.len() < REGRID_MIN_POINTS {
                return None;
            }
            let own = scale * surface.zero_set_cell_of(about)?;
            if own < REGRID_RATIO * cell {
                return None;
            }
            retaken(surface, reps, part.area, about, (own, REGRID_RATIO * cell))
        })
        .collect();
    if again.iter().all(Option::is_none) {
        return ((0, 0), nearest);
    }
    let mut fragments = (0, 0);
    let mut both: Vec<(MeshPart, Vec<u32>)> = Vec::new();
    for ((part, about), again) in
        std::mem::take(&mut parts.parts).into_iter().zip(nearest).zip(again)
    {
        match again {
            Some(Retaken { parts: taken, nearest: within, fragments: dropped }) => {
                fragments = (fragments.0 + dropped.0, fragments.1 + dropped.1);
                let within =
                    within.into_iter().map(|w| w.into_iter().map(|k| about[k as usize]).collect());
                both.extend(taken.parts.into_iter().zip(within));
            }
            None => both.push((part, about)),
        }
    }
    // Largest first again.
    both.sort_by(|a, b| b.0.area.total_cmp(&a.0.area));
    let nearest;
    (parts.parts, nearest) = both.into_iter().unzip();
    (fragments, nearest)
}

/// A part of a zero set taken again ([`retaken`]).
struct Retaken {
    /// What it became: one part or more, largest first.
    parts: MeshParts,
    /// The points nearest to each (indices into the points it was taken about).
    nearest: Vec<Vec<u32>>,
    /// The fragments of the grid left out: how many, and the points nearest to them.
    fragments: (usize, usize),
}

/// A part of a zero set, of area `area`, taken again about its points `about` (indices into
/// `reps`) on the coarsest grid of cell `own`, `own` · [`REGRID_STEP`], `own` ·
/// [`REGRID_STEP`]², … (down to `least`) whose largest part ([`drop_fragments`] leaving out the
/// grid's fragments) keeps at least [`REGRID_AREA`] of that area: a coarser grid must not cut it in two where it is
/// thinner than the cell (a fin joined by a narrow root) nor lose a thin part of it; a speck it
/// parts from the rest is a part of its own. `None` when no grid keeps it.
fn retaken(
    surface: &PointSurface,
    reps: &[DVec3],
    area: f64,
    about: &[u32],
    (own, least): (f64, f64),
) -> Option<Retaken> {
    let points: Vec<DVec3> = about.iter().map(|&k| reps[k as usize]).collect();
    let mut cell = own;
    while cell >= least {
        let taken = surface.zero_set_about(cell, about).and_then(|(v, t)| mesh_parts(&v, &t));
        if let Ok(mut taken) = taken {
            let (dropped, within) = drop_fragments(&mut taken, &points, PART_MIN_VERTICES);
            if taken.parts.first().is_some_and(|one| one.area >= REGRID_AREA * area) {
                return Some(Retaken { parts: taken, nearest: within, fragments: dropped });
            }
        }
        cell *= REGRID_STEP;
    }
    None
}

/// Whether a zero set on a grid finer than that of the zero set `parts` (split into parts)
/// may give parts above `floor` (a share of the area and a number of vertices) holding
/// [`MIN_AREA_KEPT`] of its area, each with at most [`MAX_HANDLES`] handles, as
/// [`point_sources_on`] asks of a grid with a coarser one to come: not when the parts of
/// `parts` that would hold them have more than [`MAX_HANDLES`] / [`FINER_GENUS_GROWTH`]
/// handles.
fn finer_may_keep(parts: &MeshParts, (floor, min_vertices): (f64, usize)) -> bool {
    let total: f64 = parts.parts.iter().map(|p| p.area).sum::<f64>().max(f64::MIN_POSITIVE);
    #[expect(clippy::cast_precision_loss, reason = "a handle count")]
    let keepable: f64 = parts
        .parts
        .par_iter()
        .filter(|p| p.area / total >= floor && p.positions.len() >= min_vertices)
        .filter(|p| {
            let genus = hi_scan::repair::part_topology(p).genus as f64;
            genus * FINER_GENUS_GROWTH <= MAX_HANDLES as f64
        })
        .map(|p| p.area / total)
        .sum();
    keepable >= MIN_AREA_KEPT
}

/// [`point_sources_on`] where the zero set gives no part to parameterise: the rays from the
/// centre shrink-wrapped onto the points, for the reason `why`.
fn wrapped_source(
    reps: &[DVec3],
    rep_normals: Option<&[DVec3]>,
    options: &FitOptions,
    (rows, cols): (usize, usize),
    why: &str,
    clock: &mut Clock<'_>,
) -> Result<Sources, Error> {
    let wrap = ShrinkWrapOptions {
        layout: options.layout,
        rows,
        cols,
        centre: options.centre,
        ..ShrinkWrapOptions::default()
    };
    let image =
        clock.run(StageKind::GeometryImage, (0, 1), || shrink_wrap(reps, rep_normals, &wrap))?;
    let reason = format!("the points shrink-wrapped from the rays: {why}");
    Ok(Sources {
        parts: vec![Sourced {
            name: "part 1".to_owned(),
            domain: Domain::Sphere(options.layout),
            why: "rays from the centre, wrapped onto the points".to_owned(),
            area_fraction: 1.0,
            point_fraction: 1.0,
            genus: 0,
            boundary_loops: 0,
            repair: Repair::default(),
            source: SourceImage::ShrinkWrap(image),
        }],
        dropped: Vec::new(),
        method: Method::ShrinkWrap,
        reason,
        image_points: Vec::new(),
    })
}

/// The image of one part of a point set's zero set in [`point_sources_on`]: sampled from its
/// parameterisation with its `share` of the texels (`texels`, the parts' area `kept`, the
/// user's `size`), settled onto the patches of `surface` and refined by moving least squares;
/// in `layout`, closed as a sphere should its sheet map squeeze part of it to nothing, or, with
/// `rescue`, should its sheet or torus map fail.
fn settled_part_image(
    part: &mut PlannedPart,
    surface: &PointSurface,
    reps: &[DVec3],
    mls: &MovingLeastSquares,
    (texels, kept, size): (usize, f64, Option<(usize, usize)>),
    (layout, rescue): (Layout, bool),
) -> Result<ShrinkWrapImage, Error> {
    let texels = share(texels, part.area_fraction, kept);
    // Texels dense where the points are.
    let weigh = |c: &ClosedMesh| {
        crate::shrinkwrap::with_empty_caps(crate::shrinkwrap::point_density_weights(surface, c), c)
    };
    let image = part_image_or_sphere(part, texels, size, layout, rescue, &weigh)?;
    let (r, c) = (image.image.rows(), image.image.cols());
    let mut settled = settle(
        surface,
        reps,
        image.image.texels().to_vec(),
        Some(&image.filled),
        part.domain,
        (r, c),
        0,
    );
    crate::shrinkwrap::refine(
        mls,
        &mut settled.texels,
        &settled.filled,
        part.domain,
        (r, c),
        REFINE_BAND * surface.spacing(),
    );
    // The caps smoothed between the texels on the points.
    crate::shrinkwrap::smooth_fills(
        surface,
        &mut settled.texels,
        &settled.filled,
        part.domain,
        (r, c),
    );
    Ok(ShrinkWrapImage {
        image: GeometryImage::try_new(r, c, settled.texels)?,
        filled: settled.filled,
        filled_fraction: settled.filled_fraction,
        non_star_fraction: 0.0,
        implicit_start: true,
        reparameterised: true,
        rms_move: settled.rms_move,
        pulled: settled.pulled,
    })
}

/// The report's sentence on how [`point_sources_on`] made the images: the zero set, its
/// parts, a summary, what was left out, and the fragments (count, points) dropped.
fn zero_set_reason(
    points: &[DVec3],
    reps: &[DVec3],
    planned: &[PlannedPart],
    dropped: &[DroppedPart],
    fragments: (usize, usize),
) -> String {
    let n = planned.len();
    let mut reason = format!(
        "the points shrink-wrapped: the zero set of their signed distance{}",
        if n == 1 { format!(", {}", planned[0].why) } else { " split into parts".to_owned() }
    );
    if reps.len() < points.len() {
        reason.push_str(&format!(" (from a summary of {} points)", reps.len()));
    }
    reason.push_str(&parts_sentence(planned, dropped));
    if fragments.0 > 0 {
        reason.push_str(&format!(
            "; {} {} of the zero set with fewer than {PART_MIN_VERTICES} points nearest to {} left out ({} points in all, measured against the nearest part)",
            fragments.0,
            if fragments.0 == 1 { "fragment" } else { "fragments" },
            if fragments.0 == 1 { "it" } else { "each" },
            fragments.1,
        ));
    }
    reason
}

/// The one image of the ray methods (algorithm 2, §5.8) over the whole scan, its sparse mesh
/// densified first.
fn ray_sources(
    points: &[DVec3],
    triangles: &[[u32; 3]],
    options: &FitOptions,
    (rows, cols): (usize, usize),
    clock: &mut Clock<'_>,
) -> Result<Sources, Error> {
    let dense = if triangles.is_empty() {
        points.to_vec()
    } else {
        hi_scan::sampling::densify(
            &Scan { points: points.to_vec(), triangles: triangles.to_vec(), ..Scan::default() },
            options.densify,
        )
    };
    let rays = SphericalOptions {
        layout: options.layout,
        rows,
        cols,
        centre: options.centre,
        ..SphericalOptions::default()
    };
    let source = clock.run(StageKind::GeometryImage, (0, 1), || -> Result<_, Error> {
        Ok(match options.method {
            Method::Contours => SourceImage::Contours(contour_image(&dense, &rays)?),
            _ => SourceImage::Radial(spherical_image(&dense, &rays)?),
        })
    })?;
    Ok(Sources {
        parts: vec![Sourced {
            name: "part 1".to_owned(),
            domain: Domain::Sphere(options.layout),
            why: "rays from the centre".to_owned(),
            area_fraction: 1.0,
            point_fraction: 1.0,
            genus: 0,
            boundary_loops: 0,
            repair: Repair::default(),
            source,
        }],
        dropped: Vec::new(),
        method: options.method,
        reason: format!("{} asked for", options.method.name()),
        image_points: dense,
    })
}

/// The images of the scan's parts by the method asked for (`Auto`: a mesh's parts if they can
/// stand for it, else the points'); see the module documentation.
pub(super) fn sources(
    (points, normals, triangles): (&[DVec3], Option<&[DVec3]>, &[[u32; 3]]),
    options: &FitOptions,
    (rows, cols): (usize, usize),
    clock: &mut Clock<'_>,
) -> Result<Sources, Error> {
    let texels = Domain::Sphere(options.layout).distinct_texels(rows, cols);
    Ok(match options.method {
        Method::Radial | Method::Contours => {
            ray_sources(points, triangles, options, (rows, cols), clock)?
        }
        Method::Auto | Method::Mesh if !triangles.is_empty() => {
            let force = options.method == Method::Mesh;
            match mesh_sources(points, triangles, options, texels, force, clock)? {
                Ok(sources) => sources,
                Err(why) => {
                    let mut s =
                        point_sources(points, normals, options, (rows, cols), texels, clock)?;
                    s.reason = format!("{why}; {}", s.reason);
                    s
                }
            }
        }
        Method::Mesh => {
            return Err(Error::Topology {
                what: "the scan has no triangles to parameterise".to_owned(),
            });
        }
        Method::Auto | Method::ShrinkWrap => {
            let mut s = point_sources(points, normals, options, (rows, cols), texels, clock)?;
            if triangles.is_empty() && options.method == Method::Auto {
                s.reason = format!("the scan has no triangles; {}", s.reason);
            }
            s
        }
    })
}

/// Leaves out the parts whose images are mostly guesswork, naming them; an error if every
/// part's is. (The texels a parameterisation puts on the caps of holes are the surface's
/// choice, said so in the report, not missing data: only the rays' images are judged.)
pub(super) fn leave_out_guesswork(
    sources: &mut Sources,
    max_hole_fraction: f64,
) -> Result<(), Error> {
    let guesswork = |p: &Sourced| {
        let h = p.source.hole_fraction();
        h >= 1.0 || (p.source.follows_outer_shell() && h > max_hole_fraction)
    };
    if sources.parts.iter().all(guesswork) {
        let worst = sources.parts.iter().map(|p| p.source.hole_fraction()).fold(0.0, f64::max);
        return Err(Error::MostlyHoles { fraction: worst });
    }
    let dropped = &mut sources.dropped;
    sources.parts.retain(|p| {
        let bad = guesswork(p);
        if bad {
            dropped.push(DroppedPart {
                name: p.name.clone(),
                vertices: 0,
                area_fraction: p.area_fraction,
                point_fraction: p.point_fraction,
                reason: format!(
                    "{:.0} % of its image found no scan data",
                    100.0 * p.source.hole_fraction()
                ),
            });
        }
        !bad
    });
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed surface of a slab of `2 g + 1` × 3 × 1 unit cubes with a square hole
    /// through every second cube of its middle row: a surface of genus `g`, as triangles.
    fn slab_with_holes(g: i32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let n = [2 * g + 1, 3, 1];
        let inside = |c: [i32; 3]| {
            (0..3).all(|k| (0..n[k]).contains(&c[k])) && !(c[1] == 1 && c[0] % 2 == 1)
        };
        let mut index = std::collections::HashMap::new();
        let mut p: Vec<DVec3> = Vec::new();
        let mut t = Vec::new();
        for c in
            (0..n[0]).flat_map(|x| (0..n[1]).flat_map(move |y| (0..n[2]).map(move |z| [x, y, z])))
        {
            if !inside(c) {
                continue;
            }
            for (axis, dir) in (0..3).flat_map(|a| [(a, -1), (a, 1)]) {
                let mut o = c;
                o[axis] += dir;
                if inside(o) {
                    continue;
                }
                // The face's corners, counter-clockwise seen from outside.
                let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                let mut base = c;
                base[axis] += i32::from(dir > 0);
                let mut quad = [(0, 0), (1, 0), (1, 1), (0, 1)].map(|(du, dv)| {
                    let mut q = base;
                    q[u] += du;
                    q[v] += dv;
                    q
                });
                if dir < 0 {
                    quad.reverse();
                }
                let q = quad.map(|q| {
                    *index.entry(q).or_insert_with(|| {
                        p.push(DVec3::new(f64::from(q[0]), f64::from(q[1]), f64::from(q[2])));
                        u32::try_from(p.len() - 1).unwrap()
                    })
                });
                t.extend([[q[0], q[1], q[2]], [q[0], q[2], q[3]]]);
            }
        }
        (p, t)
    }

    /// A finer grid is tried while twice the coarse zero set's handles are at most
    /// [`MAX_HANDLES`] (16 holes through a slab), and not beyond (17).
    #[test]
    fn a_finer_grid_is_tried_while_twice_the_handles_are_few_enough() {
        let floor = (PART_FLOOR, PART_MIN_VERTICES);
        let half = i32::try_from(MAX_HANDLES).unwrap() / 2;
        for (g, tried) in [(0, true), (half, true), (half + 1, false)] {
            let (p, t) = slab_with_holes(g);
            let parts = mesh_parts(&p, &t).unwrap();
            assert_eq!(parts.parts.len(), 1);
            assert_eq!(hi_scan::repair::part_topology(&parts.parts[0]).genus, g as usize);
            assert_eq!(finer_may_keep(&parts, floor), tried, "genus {g}");
        }
    }

    /// Two unit spheres 5 apart, one sampled by 4000 points and one by 500: the zero set's
    /// grid follows the dense one's spacing, which puts about 8 times as many vertices on the
    /// sparse one as its own points need (the spacings' ratio √8, squared); taken again, the
    /// sparse sphere's part has a quarter of its vertices or fewer, still on the sphere and
    /// closed, while the dense sphere's part is left as it was.
    #[test]
    fn a_part_sampled_more_sparsely_than_the_rest_is_taken_again_on_a_coarser_grid() {
        let centre = DVec3::new(5.0, 0.0, 0.0);
        let points: Vec<DVec3> = hi_testkit::fibonacci_sphere(4000)
            .map(DVec3::from_array)
            .chain(hi_testkit::fibonacci_sphere(500).map(|p| DVec3::from_array(p) + centre))
            .collect();
        let surface = PointSurface::try_new(&points, None, NEIGHBOURS).unwrap();
        let cell = surface.zero_set_cell();
        let (v, t) = surface.zero_set(cell).unwrap();
        let mut parts = mesh_parts(&v, &t).unwrap();
        let (_, nearest) = drop_fragments(&mut parts, &points, PART_MIN_VERTICES);
        assert_eq!(parts.parts.len(), 2);
        let sparse = |parts: &MeshParts| {
            parts.parts.iter().position(|p| p.positions[0].x > 2.5).expect("the sparse sphere")
        };
        let before = parts.clone();
        let k = sparse(&before);
        let (_, nearest) = regrid_sparse_parts(&surface, &points, &mut parts, nearest, cell);
        assert_eq!(parts.parts.len(), 2);
        let j = sparse(&parts);
        let (old, new) = (&before.parts[k], &parts.parts[j]);
        assert!(
            4 * new.positions.len() <= old.positions.len(),
            "{} vertices, {} before",
            new.positions.len(),
            old.positions.len()
        );
        // Each vertex the mean of crossings at most a cell's diagonal h√3 apart on a sphere of
        // radius 1: within 3h²/8 inside it (the sag of a chord that long), and a little for
        // the points' patches.
        let h = surface.zero_set_cell_of(&nearest[j]).unwrap();
        assert!(h > 2.0 * cell, "{h} against {cell}");
        for p in &new.positions {
            let off = (*p - centre).length() - 1.0;
            assert!((-3.0 * h * h / 8.0 - 0.005..0.005).contains(&off), "{p}: {off}, h {h}");
        }
        // Closed, genus 0: V − E + F = 2 with E = 3F/2.
        assert_eq!(new.positions.len() as i64 - new.triangles.len() as i64 / 2, 2);
        assert_eq!(parts.parts[1 - j], before.parts[1 - k], "the dense sphere's part");
        // The points nearest to each part: the sparse sphere's are its own 500.
        assert_eq!(nearest[j], (4000..4500).collect::<Vec<u32>>());
        assert_eq!(nearest[1 - j], (0..4000).collect::<Vec<u32>>());
    }
}
