// SPDX-License-Identifier: MIT
//! A scan's parts and the surface each becomes: every connected part above a size floor is
//! fitted on its own, over the domain its topology asks for ([`Domain`]):
//!
//! | the part | its surface | its domain |
//! |---|---|---|
//! | an open sheet: genus 0, and a boundary loop whose cap would span at least [`SHEET_SPAN`] of the part's area (or any boundary, with [`Boundary::Open`]) | a disc, the other holes closed (and with [`Boundary::Open`], handles cut) | [`Domain::Sheet`] |
//! | closed (holes closed) of genus 1 | the torus, no cut | [`Domain::Torus`] |
//! | closed (holes closed) of any other genus | a sphere, handles cut | [`Domain::Sphere`] |
//!
//! A handle whose shortest loop is tiny ([`TORUS_MIN_LOOP`], [`TORUS_MIN_EDGES`]) is two sheets that nearly touch,
//! not a ring: it is cut. Should a part not be made the surface its topology asks for, the next
//! one is tried, the sphere last; a part that cannot be made any (one-sided) is left out, and
//! said so.

use glam::DVec3;
use hi_scan::repair::{
    ClosedMesh, Closing, MeshPart, MeshParts, Topology, close_disc_or_sphere, close_part_cutting,
    part_topology, shortest_handle,
};
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use super::source::MapQuality;
use crate::discparam::{
    DiscParamOptions, parameterise_disc, reflect_periodic, reflect_periodic_mask,
};
use crate::domain::Domain;
use crate::sphereparam::{SphereParamOptions, parameterise_weighted};
use crate::spherical::Layout;
use crate::torusparam::{TorusParamOptions, parameterise_torus};
use crate::{Error, GeometryImage};
use hi_par::*;

/// A part whose widest boundary loop would need a cap of at least this share of the part's own
/// area is an open sheet (a terrain, a face mask, a range image: about 1); a closed scan's
/// holes need far less (a head open at the neck: under 0.1).
pub const SHEET_SPAN: f64 = 0.25;

/// A part of genus 1 whose handle's shortest loop is shorter than this share of the square root
/// of its area (or than [`TORUS_MIN_EDGES`] of its edges) is not a ring but two sheets that
/// nearly touch (a tunnel of a zero set, a limb grazing a body): its handle is cut rather than
/// fitted over the torus. A mug's handle or a kitten's tail loop is several times longer.
pub const TORUS_MIN_LOOP: f64 = 0.04;

/// A part of genus 1 whose handle's shortest loop is shorter than this many of its mean edge
/// lengths is taken for a tunnel, as with [`TORUS_MIN_LOOP`].
pub const TORUS_MIN_EDGES: usize = 12;

/// Whether the one handle of the closed genus-1 mesh `closed` (of scan area `area`) is a tunnel
/// between sheets that nearly touch ([`TORUS_MIN_LOOP`], [`TORUS_MIN_EDGES`]).
fn is_tunnel(closed: &ClosedMesh, area: f64) -> bool {
    let edges: f64 = closed
        .triangles
        .iter()
        .map(|t| {
            (0..3)
                .map(|k| {
                    closed.positions[t[k] as usize]
                        .distance(closed.positions[t[(k + 1) % 3] as usize])
                })
                .sum::<f64>()
        })
        .sum::<f64>()
        / (3 * closed.triangles.len()).max(1) as f64;
    let floor = (TORUS_MIN_LOOP * area.sqrt()).max(TORUS_MIN_EDGES as f64 * edges);
    shortest_handle(closed).is_some_and(|l| l < floor)
}

/// Which parts with a boundary are fitted as open sheets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Boundary {
    /// A part of genus 0 whose widest boundary loop spans at least [`SHEET_SPAN`] of its area
    /// is an open sheet; every other part is closed. (A part with handles is closed: on an open
    /// scan, a handle is far more often a tunnel of a point set's zero set, or a cup's handle
    /// whose cut the square's map squeezes, than a sheet's own.)
    #[default]
    Auto,
    /// Every part is closed, its holes capped.
    Closed,
    /// Every part with a boundary is an open sheet.
    Open,
}

/// A part of the scan left out of the fit.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DroppedPart {
    /// Its name (`part k`, numbered with the fitted parts, largest first).
    pub name: String,
    /// Its vertices.
    pub vertices: usize,
    /// Its share of the scan's area.
    pub area_fraction: f64,
    /// Its share of the scan's points: of a mesh's vertices, those on it; of a point set's
    /// points (or of their summary, for a cloud summarised first), those nearer to it than to
    /// any other part of the zero set. A part left out may hold much of the area and few of the
    /// points, or the reverse: this says how many of the points the fit leaves without a
    /// surface through it.
    pub point_fraction: f64,
    /// Why it was left out.
    pub reason: String,
}

/// A part to fit: its repaired surface and the domain it is parameterised over.
#[derive(Clone, Debug)]
pub(crate) struct PlannedPart {
    /// `part k`.
    pub(crate) name: String,
    /// The surface its domain needs.
    pub(crate) closed: ClosedMesh,
    /// Its domain.
    pub(crate) domain: Domain,
    /// Its topology before repair.
    pub(crate) topology: Topology,
    /// Its share of the scan's area.
    pub(crate) area_fraction: f64,
    /// Its share of the scan's points ([`DroppedPart::point_fraction`]).
    pub(crate) point_fraction: f64,
    /// Why the domain, in words.
    pub(crate) why: String,
    /// The part as the scan has it, before repair: closed again as a sphere should its
    /// domain's map fail ([`part_image_or_sphere`]).
    pub(crate) part: MeshPart,
    /// The most handles its closing may cut ([`plan`]'s).
    pub(crate) max_handles: usize,
}

/// The surfaces a part may become, best first, and why.
fn choices(
    topology: &Topology,
    boundary: Boundary,
    layout: Layout,
) -> Vec<(Closing, Domain, String)> {
    let sphere = (Closing::Sphere, Domain::Sphere(layout));
    let widest =
        topology.loops.first().map_or(0.0, |l| l.span / topology.area.max(f64::MIN_POSITIVE));
    let open = match boundary {
        Boundary::Auto => widest >= SHEET_SPAN && topology.genus == 0,
        Boundary::Closed => false,
        Boundary::Open => !topology.loops.is_empty(),
    };
    let loops = |n: usize| {
        if n == 1 { "1 boundary loop".to_owned() } else { format!("{n} boundary loops") }
    };
    let mut out = Vec::new();
    if open {
        out.push((
            Closing::Disc,
            Domain::Sheet,
            format!(
                "an open sheet: {}, the widest spanning {:.0} % of its area",
                loops(topology.loops.len()),
                100.0 * widest
            ),
        ));
    }
    if topology.genus == 1 {
        out.push((
            Closing::Torus,
            Domain::Torus,
            "genus 1: fitted over the torus, with no cut".to_owned(),
        ));
    }
    let why = match (topology.genus, topology.loops.len()) {
        (0, 0) => "closed, genus 0".to_owned(),
        (0, n) => format!("genus 0 once its {} closed", loops(n)),
        (g, 0) => format!("genus {g}: its handles cut"),
        (g, n) => format!("genus {g} once its {} closed: its handles cut", loops(n)),
    };
    out.push((sphere.0, sphere.1, why));
    out
}

/// The parts of `parts` to fit, each made the surface its topology asks for, and those left
/// out: parts with less than `floor` of the area or fewer than `min_vertices` vertices, and
/// parts that cannot be made any surface with up to `max_handles` handles cut. A part of higher
/// genus (but a torus) is refused by every closing before anything is done to it, so this is
/// known from the parts' topology alone: when the others hold less than `least_kept` of the
/// area, nothing is planned (both lists empty) rather than every other part closed for nothing.
/// `points` holds the scan's points on (or nearest to) each part, in the order of `parts`: the
/// parts' shares of the points ([`DroppedPart::point_fraction`]).
pub(crate) fn plan(
    parts: &MeshParts,
    points: &[usize],
    boundary: Boundary,
    layout: Layout,
    (floor, min_vertices): (f64, usize),
    max_handles: usize,
    least_kept: f64,
) -> (Vec<PlannedPart>, Vec<DroppedPart>) {
    let total: f64 = parts.parts.iter().map(|p| p.area).sum::<f64>().max(f64::MIN_POSITIVE);
    #[expect(clippy::cast_precision_loss, reason = "a point count")]
    let every = points.iter().sum::<usize>().max(1) as f64;
    #[expect(clippy::cast_precision_loss, reason = "a point count")]
    let point_fraction = |k: usize| points.get(k).map_or(0.0, |&n| n as f64) / every;
    let topologies: Vec<Option<Topology>> = parts
        .parts
        .par_iter()
        .map(|part| {
            let above = part.area / total >= floor && part.positions.len() >= min_vertices;
            above.then(|| part_topology(part))
        })
        .collect();
    let keepable: f64 = parts
        .parts
        .iter()
        .zip(&topologies)
        .filter(|(_, t)| t.as_ref().is_some_and(|t| t.genus <= max_handles.max(1)))
        .map(|(part, _)| part.area / total)
        .sum();
    if keepable < least_kept {
        return (Vec::new(), Vec::new());
    }
    let outcomes: Vec<Result<PlannedPart, DroppedPart>> = parts
        .parts
        .par_iter()
        .zip(topologies.into_par_iter())
        .enumerate()
        .map(|(k, (part, topology))| {
            let name = format!("part {}", k + 1);
            let area_fraction = part.area / total;
            let point_fraction = point_fraction(k);
            let dropped = |reason: String| DroppedPart {
                name: name.clone(),
                vertices: part.positions.len(),
                area_fraction,
                point_fraction,
                reason,
            };
            let Some(topology) = topology else {
                return Err(dropped(format!(
                    "below the floor ({:.2} % of the area, {} vertices; a part needs {:.2} % and {min_vertices})",
                    100.0 * area_fraction,
                    part.positions.len(),
                    100.0 * floor
                )));
            };
            let mut last = String::new();
            let choices = choices(&topology, boundary, layout);
            let sphere = choices.last().map(|c| (c.1, c.2.clone()));
            for (closing, domain, why) in choices {
                // A disc that keeps a handle goes on as a sphere from its cuts (but for genus
                // 1, whose torus comes first).
                let closed = if closing == Closing::Disc && topology.genus != 1 {
                    close_disc_or_sphere(part, max_handles).map(|(closed, failed)| match failed {
                        None => (closed, domain, why),
                        Some(e) => {
                            let (domain, why) = sphere.clone().unwrap_or((domain, why));
                            (closed, domain, format!("{why} (not a {}: {e})", Domain::Sheet.name()))
                        }
                    })
                } else {
                    close_part_cutting(part, closing, max_handles).map(|c| (c, domain, why))
                };
                match closed {
                    Ok((closed, ..)) if closing == Closing::Torus && is_tunnel(&closed, part.area) => {
                        last = format!(
                            "its handle's shortest loop is under {TORUS_MIN_EDGES} edges or {:.0} % of the square root of its area: two sheets that nearly touch, not a ring",
                            100.0 * TORUS_MIN_LOOP
                        );
                    }
                    Ok((closed, domain, why)) => {
                        let why = if last.is_empty() { why } else { format!("{why} ({last})") };
                        return Ok(PlannedPart {
                            name,
                            closed,
                            domain,
                            topology,
                            area_fraction,
                            point_fraction,
                            why,
                            part: part.clone(),
                            max_handles,
                        });
                    }
                    Err(e) => last = format!("not a {}: {e}", domain.name()),
                }
            }
            Err(dropped(last))
        })
        .collect();
    let mut planned = Vec::new();
    let mut dropped = Vec::new();
    for o in outcomes {
        match o {
            Ok(p) => planned.push(p),
            Err(d) => dropped.push(d),
        }
    }
    (planned, dropped)
}

/// The number of each part's vertices, in order: a mesh's points on each of its parts, for
/// [`plan`].
pub(crate) fn vertex_counts(parts: &MeshParts) -> Vec<usize> {
    parts.parts.iter().map(|p| p.positions.len()).collect()
}

/// Leaves out of a point set's zero set the parts fewer than `min_points` of the points are
/// nearest to (a few cells where the points' signed distance crosses zero off their surface,
/// between two sheets or over a stray point): not parts of the point set, which its own gaps
/// split, but of the grid. Returns how many were left out and the points nearest to them, and
/// the points (indices) nearest to each part kept, in order (their counts are [`plan`]'s
/// `points`); the parts kept keep their order. With one part nothing is left out, and every
/// point is nearest to it.
pub(crate) fn drop_fragments(
    parts: &mut MeshParts,
    points: &[DVec3],
    min_points: usize,
) -> ((usize, usize), Vec<Vec<u32>>) {
    #[expect(clippy::cast_possible_truncation, reason = "point indices fit in u32")]
    let all = || (0..points.len() as u32).collect::<Vec<u32>>();
    if parts.parts.len() < 2 {
        return ((0, 0), parts.parts.iter().map(|_| all()).collect());
    }
    let (mut vertices, mut owner) = (Vec::new(), Vec::new());
    for (k, part) in parts.parts.iter().enumerate() {
        vertices.extend(part.positions.iter().map(|p| p.to_array()));
        owner.extend(std::iter::repeat_n(k, part.positions.len()));
    }
    let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> = ImmutableKdTree::new_from_slice(&vertices)
    else {
        return ((0, 0), vec![Vec::new(); parts.parts.len()]);
    };
    let nearest: Vec<usize> = points
        .par_iter()
        .map(|p| {
            let n = tree.query(&p.to_array()).nearest_one::<SquaredEuclidean<f64>>().execute();
            owner[n.item as usize]
        })
        .collect();
    let mut owned = vec![Vec::new(); parts.parts.len()];
    for (i, k) in nearest.into_iter().enumerate() {
        #[expect(clippy::cast_possible_truncation, reason = "point indices fit in u32")]
        owned[k].push(i as u32);
    }
    let mut k = 0;
    let (mut fragments, mut stray) = (0, 0);
    parts.parts.retain(|_| {
        let n = owned[k].len();
        k += 1;
        if n >= min_points {
            return true;
        }
        fragments += 1;
        stray += n;
        false
    });
    owned.retain(|o| o.len() >= min_points);
    ((fragments, stray), owned)
}

/// A part's geometry image sampled from its parameterisation.
#[derive(Clone, Debug)]
pub(crate) struct PartImage {
    /// The image (for a sheet, mirrored: doubly periodic).
    pub(crate) image: GeometryImage,
    /// Texels on triangles that close holes or cuts.
    pub(crate) filled: Vec<bool>,
    /// The fraction of the distinct texels filled.
    pub(crate) filled_fraction: f64,
    /// The quality of the map.
    pub(crate) quality: MapQuality,
}

/// The smallest side of a part's image (rows and columns of the square or the sphere's
/// layout; the torus's shorter side).
const MIN_SIDE: usize = 16;

/// A sheet's map onto the square with a stretch efficiency ([`FlatQuality`]) below this gives
/// some part of the surface a billionth of its share of the texels or less: none, in any
/// image (a handle of a cup-shaped part, cut and squeezed against a side of the square). Such
/// a part is closed as a sphere instead ([`part_image_or_sphere`]). The maps of terrains and
/// of ragged scans lie far above (10⁻⁶ to 1).
///
/// [`FlatQuality`]: crate::flat::FlatQuality
const MIN_SHEET_EFFICIENCY: f64 = 1e-9;

/// The image of `part` over its domain, with about `texels` distinct texels (`resolution`, if
/// given, for the sphere's layouts: rows × columns as the user asked); a sphere's map weighs
/// its stretch by `weigh` of the surface it maps (the maps of a torus and of a sheet do not
/// weigh theirs).
pub(crate) fn part_image(
    part: &PlannedPart,
    texels: usize,
    resolution: Option<(usize, usize)>,
    weigh: &Weigh<'_>,
) -> Result<PartImage, Error> {
    let c = &part.closed;
    match part.domain {
        Domain::Sphere(layout) => {
            let (rows, cols) = resolution.unwrap_or_else(|| sphere_side(layout, texels));
            let param = parameterise_weighted(c, &weigh(c), &SphereParamOptions::default())?;
            let image = param.image(layout, rows, cols)?;
            Ok(PartImage {
                image: image.image,
                filled: image.filled,
                filled_fraction: image.filled_fraction,
                quality: MapQuality::Sphere(param.quality()),
            })
        }
        Domain::Torus => {
            let param = parameterise_torus(
                &c.positions,
                &c.triangles,
                &c.filled,
                &TorusParamOptions::default(),
            )?;
            let (rows, cols) = param.resolution(texels.max(MIN_SIDE * MIN_SIDE));
            let image = param.image(rows.max(MIN_SIDE), cols.max(MIN_SIDE))?;
            Ok(PartImage {
                image: image.image,
                filled: image.filled,
                filled_fraction: image.filled_fraction,
                quality: MapQuality::Flat(param.quality()),
            })
        }
        Domain::Sheet => {
            let param = parameterise_disc(
                &c.positions,
                &c.triangles,
                &c.filled,
                &DiscParamOptions::default(),
            )?;
            let (rows, cols) = param.resolution(texels.max(MIN_SIDE * MIN_SIDE));
            let (rows, cols) = (rows.max(MIN_SIDE), cols.max(MIN_SIDE));
            let square = param.image(rows, cols)?;
            Ok(PartImage {
                image: reflect_periodic(&square.image)?,
                filled: reflect_periodic_mask(&square.filled, rows, cols)?,
                filled_fraction: square.filled_fraction,
                quality: MapQuality::Flat(param.quality()),
            })
        }
    }
}

/// [`part_image`], and should a sheet's map squeeze part of it to nothing
/// ([`MIN_SHEET_EFFICIENCY`]), or, with `any_failure`, a sheet's or a torus's map fail (a fold
/// its solve cannot undo, on a ragged zero set), the part closed as a sphere instead (its
/// boundary capped, its handles cut) and mapped over the sphere in `layout`: `part`'s
/// surface, domain and reason are changed to say so. The sphere's own failure is returned as
/// it is.
pub(crate) fn part_image_or_sphere(
    part: &mut PlannedPart,
    texels: usize,
    resolution: Option<(usize, usize)>,
    layout: Layout,
    any_failure: bool,
    weigh: &Weigh<'_>,
) -> Result<PartImage, Error> {
    let failed = match part_image(part, texels, resolution, weigh) {
        Ok(image)
            if part.domain == Domain::Sheet
                && image.quality.stretch_efficiency() < MIN_SHEET_EFFICIENCY =>
        {
            Error::Topology {
                what: format!(
                    "its map onto the square leaves part of it next to no texels (a stretch \
                     efficiency of {:.0e}: a handle or a long limb squeezed against a side)",
                    image.quality.stretch_efficiency()
                ),
            }
        }
        Err(e) if any_failure && !matches!(part.domain, Domain::Sphere(_)) => e,
        done => return done,
    };
    let Ok(closed) = close_part_cutting(&part.part, Closing::Sphere, part.max_handles) else {
        return Err(failed);
    };
    part.why = format!(
        "closed as a sphere, its handles cut and its boundary capped (not {}: {failed})",
        match part.domain {
            Domain::Sheet => "an open sheet",
            _ => "a torus",
        }
    );
    part.closed = closed;
    part.domain = Domain::Sphere(layout);
    part_image(part, texels, resolution, weigh)
}

/// The weights of the stretch of a part's spherical map ([`parameterise_weighted`]), one per
/// vertex of the surface it maps.
pub(crate) type Weigh<'a> = dyn Fn(&ClosedMesh) -> Vec<f64> + Sync + 'a;

/// The side of a square image of the sphere in `layout` with about `texels` distinct texels:
/// a multiple of 8 (the doubled layouts mirror rows and columns), at least [`MIN_SIDE`] · 2.
pub(crate) fn sphere_side(layout: Layout, texels: usize) -> (usize, usize) {
    let per_side = if layout == Layout::Octahedron { 1.0 } else { 2.0 };
    let side = (per_side * texels as f64).sqrt();
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "clamped")]
    let side = ((side / 8.0).ceil() as usize * 8).clamp(2 * MIN_SIDE, 4096);
    (side, side)
}

/// Area-weighted unit vertex normals of all the planned parts' surfaces, with their positions:
/// the outward side of every part, for the point set's patches to face.
pub(crate) fn outward_samples(parts: &[PlannedPart]) -> (Vec<DVec3>, Vec<DVec3>) {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    for p in parts {
        positions.extend_from_slice(&p.closed.positions);
        normals.extend(hi_scan::implicit::vertex_normals(&p.closed.positions, &p.closed.triangles));
    }
    (positions, normals)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sphereparam::mesh_density_weights;
    use hi_scan::repair::{MAX_HANDLES, mesh_parts};

    /// An octahedron of radius 1 about the origin and a tetrahedron of size 0.1 about (5, 0, 0):
    /// two parts, the octahedron first (larger).
    fn two_parts() -> MeshParts {
        let mut p: Vec<DVec3> =
            [DVec3::X, -DVec3::X, DVec3::Y, -DVec3::Y, DVec3::Z, -DVec3::Z].to_vec();
        let mut t: Vec<[u32; 3]> = vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ];
        let c = DVec3::new(5.0, 0.0, 0.0);
        p.extend([c, c + 0.1 * DVec3::X, c + 0.1 * DVec3::Y, c + 0.1 * DVec3::Z]);
        t.extend([[6, 8, 7], [6, 7, 9], [6, 9, 8], [7, 8, 9]]);
        let parts = mesh_parts(&p, &t).unwrap();
        assert_eq!(parts.parts.len(), 2);
        assert_eq!(parts.parts[0].positions.len(), 6, "the octahedron first");
        parts
    }

    /// Points on the octahedron's faces (barycentric grid on each): `per_face` each.
    fn octahedron_points(per_face: usize) -> Vec<DVec3> {
        let corners = [DVec3::X, DVec3::Y, DVec3::Z];
        let mut out = Vec::new();
        for sx in [-1.0, 1.0] {
            for sy in [-1.0, 1.0] {
                for sz in [-1.0, 1.0] {
                    let s = DVec3::new(sx, sy, sz);
                    for k in 0..per_face {
                        let a = (k as f64 + 0.5) / per_face as f64;
                        let b = 0.5 * (1.0 - a);
                        out.push(
                            s * (a * corners[k % 3]
                                + b * corners[(k + 1) % 3]
                                + b * corners[(k + 2) % 3]),
                        );
                    }
                }
            }
        }
        out
    }

    /// A part fewer than `min_points` points are nearest to is a fragment of the grid, left
    /// out and counted with its points; one with as many is a part of the point set, kept.
    #[test]
    fn fragments_are_parts_few_points_are_nearest_to() {
        let mut points = octahedron_points(10);
        points.push(DVec3::new(5.05, 0.02, 0.02));
        let mut parts = two_parts();
        // 80 points on the octahedron, one by the tetrahedron.
        let (dropped, nearest) = drop_fragments(&mut parts, &points, 12);
        assert_eq!(dropped, (1, 1));
        assert_eq!(nearest, vec![(0..80).collect::<Vec<u32>>()]);
        assert_eq!(parts.parts.len(), 1);
        assert_eq!(parts.parts[0].positions.len(), 6, "the octahedron kept");
        // Twelve points about the tetrahedron: a part of the point set.
        points.extend((1..12).map(|k| DVec3::new(5.0 + 0.005 * k as f64, 0.03, 0.03)));
        let mut parts = two_parts();
        let (dropped, nearest) = drop_fragments(&mut parts, &points, 12);
        assert_eq!(dropped, (0, 0));
        assert_eq!(nearest, vec![(0..80).collect::<Vec<u32>>(), (80..92).collect()]);
        assert_eq!(parts.parts.len(), 2);
        // One part: nothing to do, whatever the points.
        let mut one = two_parts();
        one.parts.truncate(1);
        assert_eq!(drop_fragments(&mut one, &[DVec3::ZERO], 12), ((0, 0), vec![vec![0]]));
    }

    /// [`plan`] with every part above the floor, each one's points its vertices.
    fn plan_every_part(parts: &MeshParts) -> (Vec<PlannedPart>, Vec<DroppedPart>) {
        let points = vertex_counts(parts);
        plan(parts, &points, Boundary::Auto, Layout::FlatOctahedron, (0.0, 4), MAX_HANDLES, 0.0)
    }

    /// A part whose sheet map fails (here a closed octahedron taken for a sheet: a disc map
    /// needs a boundary) is closed as a sphere and mapped over it, and says so; its image is
    /// the sphere's, every texel on the octahedron.
    #[test]
    fn a_part_whose_sheet_map_fails_is_fitted_as_a_sphere() {
        let parts = two_parts();
        let (mut planned, dropped) = plan_every_part(&parts);
        assert!(dropped.is_empty());
        let mut part = planned.swap_remove(0);
        assert_eq!(part.domain, Domain::Sphere(Layout::FlatOctahedron));
        part.domain = Domain::Sheet;
        let sheet_error =
            part_image(&part, 32 * 32, None, &mesh_density_weights).unwrap_err().to_string();
        let image = part_image_or_sphere(
            &mut part,
            32 * 32,
            None,
            Layout::FlatOctahedron,
            true,
            &mesh_density_weights,
        )
        .expect("the sphere's map");
        assert_eq!(part.domain, Domain::Sphere(Layout::FlatOctahedron));
        assert!(part.why.contains("not an open sheet"), "{}", part.why);
        assert!(part.why.contains(&sheet_error), "{} lacks {sheet_error}", part.why);
        // Every texel lies on the octahedron |x| + |y| + |z| = 1 (its faces).
        for p in image.image.texels() {
            assert!((p.x.abs() + p.y.abs() + p.z.abs() - 1.0).abs() < 1e-9, "{p}");
        }
    }

    /// A sheet with a long limb (a dome of 20 × 20 cells, and from a hole of 2 × 2 cells in its
    /// middle a square tube 40 cells long, capped): the disc map squeezes the limb until it
    /// has no texels, so the part is closed as a sphere at once, and says why.
    #[test]
    fn a_sheet_whose_map_squeezes_a_limb_is_fitted_as_a_sphere() {
        let h = 1.0 / 20.0;
        let dome = |i: i32, j: i32| {
            let (x, y) = (f64::from(i) * h, f64::from(j) * h);
            DVec3::new(x, y, 0.3 * x * (1.0 - x) * y * (1.0 - y))
        };
        let mut p: Vec<DVec3> = Vec::new();
        let mut at = std::collections::HashMap::new();
        let mut t: Vec<[u32; 3]> = Vec::new();
        let hole = |i: i32, j: i32| (9..11).contains(&i) && (9..11).contains(&j);
        for i in 0..20 {
            for j in 0..20 {
                if hole(i, j) {
                    continue;
                }
                let mut v = |a: i32, b: i32| {
                    *at.entry((a, b)).or_insert_with(|| {
                        p.push(dome(a, b));
                        (p.len() - 1) as u32
                    })
                };
                let [a, b, c, d] = [v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)];
                t.extend([[a, b, c], [a, c, d]]);
            }
        }
        // The hole's rim, counter-clockwise seen from above, and the tube's rings above it.
        let rim = [(9, 9), (10, 9), (11, 9), (11, 10), (11, 11), (10, 11), (9, 11), (9, 10)];
        let mut below: Vec<u32> = rim.iter().map(|k| at[k]).collect();
        for level in 1..=40 {
            let ring: Vec<u32> = rim
                .iter()
                .map(|&(i, j)| {
                    p.push(dome(i, j) + DVec3::Z * (f64::from(level) * h));
                    (p.len() - 1) as u32
                })
                .collect();
            for k in 0..8 {
                let (a, b) = (below[k], below[(k + 1) % 8]);
                let (c, d) = (ring[(k + 1) % 8], ring[k]);
                // The tube's outside faces away from its axis; the dome's top is +z.
                t.extend([[a, c, b], [a, d, c]]);
            }
            below = ring;
        }
        let top = p.len() as u32;
        p.push(dome(10, 10) + DVec3::Z * (41.0 * h));
        for k in 0..8 {
            t.push([below[k], top, below[(k + 1) % 8]]);
        }
        let parts = mesh_parts(&p, &t).unwrap();
        assert_eq!(parts.parts.len(), 1);
        let (mut planned, _) = plan_every_part(&parts);
        let mut part = planned.swap_remove(0);
        assert_eq!(part.domain, Domain::Sheet, "{}", part.why);
        let sheet =
            part_image(&part, 64 * 64, None, &mesh_density_weights).expect("a map, squeezed");
        let efficiency = sheet.quality.stretch_efficiency();
        assert!(efficiency < MIN_SHEET_EFFICIENCY, "{efficiency:e}");
        part_image_or_sphere(
            &mut part,
            64 * 64,
            None,
            Layout::FlatOctahedron,
            false,
            &mesh_density_weights,
        )
        .expect("the sphere's map");
        assert_eq!(part.domain, Domain::Sphere(Layout::FlatOctahedron));
        assert!(part.why.contains("next to no texels"), "{}", part.why);
    }
}
