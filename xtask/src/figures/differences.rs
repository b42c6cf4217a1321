// SPDX-License-Identifier: MIT
//! Where a figure's result differs from the thesis's, and why: one line per figure, shown in
//! the gallery's "differs from the thesis" column and under each figure (`docs/figures/`).
//!
//! A difference here is one of result or method: the thesis is wrong (Theorem 5.1 for even n,
//! the final non-uniform formula; `docs/math.md` §2 and §5), a convention differs (mean
//! curvature), or the figure shows something else or more for a stated reason. Stand-in data is
//! not listed here: each figure's data line names it.

/// The notes, by figure number.
const DIFFERENCES: &[((u32, u32), &str)] = &[
    (
        (3, 20),
        "The thesis's final formula (§3.10) does not pass through xₖ at its chord-length tₖ: the tₖ act as \
         frequencies, and the curve passes through xₖ at t = k/(n−1) and is open (docs/math.md §5). Drawn as \
         printed, beside true interpolation at the nodes tₖ.",
    ),
    (
        (3, 21),
        "As 3.20: the thesis's formula as printed is open and passes through xₖ at t = k/(n−1), not at \
         tₖ; the node-interpolating reading is drawn beside it.",
    ),
    (
        (3, 22),
        "As 3.20: the thesis's formula as printed is open and passes through xₖ at t = k/(n−1), not at \
         tₖ; the node-interpolating reading is drawn beside it.",
    ),
    (
        (3, 23),
        "As 3.20: the thesis's formula as printed is open and passes through xₖ at t = k/(n−1), not at \
         tₖ; the node-interpolating reading is drawn beside it.",
    ),
    ((4, 35), "Adds panel (e), interpolating √3 (Labsik–Greiner), which the thesis does not show."),
    (
        (5, 3),
        "Shows level 4 (64×64) where the thesis shows level 7 (512×512, about 11 MB): every level lies \
         on the same surface, which the generator checks for level 7.",
    ),
    (
        (5, 4),
        "Shows level 4 (64×64) where the thesis shows level 7 (512×512, about 11 MB): every level lies \
         on the same surface, which the generator checks for level 7.",
    ),
    (
        (5, 5),
        "Shows level 4 (64×64) where the thesis shows level 7 (512×512, about 11 MB): every level lies \
         on the same surface, which the generator checks for level 7.",
    ),
    (
        (5, 6),
        "Theorem 5.1 is exact only for odd n. For even n the thesis's rotation misses by \
         c·sin(πno)·sin(πnt) with c = (1/n)Σ(−1)ᵏxₖ (docs/math.md §2): panel (c), not in the thesis, shows \
         the defect beside the exact rotation.",
    ),
    (
        (5, 25),
        "Rendered by ray tracing the tessellated mesh in a BVH, the renderer's equivalent of the \
         thesis's scanline rendering: the same triangles, with shadows.",
    ),
    (
        (5, 26),
        "The thesis's interval ray tracing took \"several hours\"; the same method here takes \
         seconds (`cargo xtask bench render`). The thesis's \"few other objects\" are not given: a \
         harmonic sphere and a floor stand in.",
    ),
    (
        (5, 27),
        "The thesis's cubic patches are C0 only: the derivative jumps by about 12% of max|σ′| at the \
         patch edges and the deviation does not shrink with n (docs/math.md §4), so the normals visibly \
         jump; 5.28(b) adds C1 patches.",
    ),
    (
        (5, 28),
        "Adds panel (b): C1 Hermite patches with a guaranteed error bound, beside the thesis's C0 \
         patches of (a).",
    ),
];

/// The notes on the §5.9 surfaces (5.31–5.43), which share one.
const CURVATURE: &str = "The thesis colours |K| and |κ₁ + κ₂| from blue to purple; these maps \
     colour K and H = (κ₁ + κ₂)/2 with their signs on a diverging map (blue negative, grey zero, \
     red positive), so that elliptic and hyperbolic points, and the side a surface bends to, can \
     be told apart. Each map's scale is set per quantity, so the picture of H is that of \
     κ₁ + κ₂; the values of |H| in the table are half of κ₁ + κ₂.";

/// Why figure `number`'s result differs from the thesis's, if it does.
pub(crate) fn differs(number: (u32, u32)) -> Option<&'static str> {
    if number.0 == 5 && (31..=43).contains(&number.1) {
        return Some(CURVATURE);
    }
    DIFFERENCES.iter().find(|(n, _)| *n == number).map(|(_, note)| *note)
}

/// Every figure number with a note (for the registry's check that each is a real figure).
#[cfg(test)]
pub(crate) fn numbers() -> impl Iterator<Item = (u32, u32)> {
    DIFFERENCES.iter().map(|(n, _)| *n).chain((31..=43).map(|k| (5, k)))
}
