# SPDX-License-Identifier: MIT
"""Curves: the harmonic curve against scipy's Fourier resampling (the trigonometric
interpolant, for odd n), against the ``hi`` command, and against algebra (a circle's
curvature and derivative, a rotation's shift); the comparison curves by kind."""

import numpy as np
import pytest
import scipy.signal

import harmonic
from conftest import hi_json


def polygon(n, seed=1, dim=2):
    return np.random.default_rng(seed).normal(size=(n, dim))


@pytest.mark.parametrize("n", [5, 7, 15])
def test_uniform_samples_are_scipys_fourier_resampling_for_odd_n(n):
    # For odd n the harmonic curve is the trigonometric interpolant of degree (n - 1) / 2
    # (thesis §3.2), which scipy.signal.resample evaluates on the finer grid.
    x = polygon(n)
    dense = harmonic.HarmonicCurve(x).sample_uniform(8 * n)
    expected = scipy.signal.resample(x, 8 * n, axis=0)
    np.testing.assert_allclose(dense, expected, atol=1e-12)


def test_the_curve_interpolates_its_points():
    for dim in (2, 3):
        x = polygon(8, dim=dim)
        c = harmonic.HarmonicCurve(x)
        np.testing.assert_allclose(c.eval(np.arange(8) / 8), x, atol=1e-13)
    values = np.array([0.0, 2.0, -1.0, 3.0])
    np.testing.assert_allclose(harmonic.HarmonicCurve(values).eval(np.arange(4) / 4), values,
                               atol=1e-13)


def test_values_derivatives_and_curvature_are_those_of_hi_curve_eval():
    x = polygon(6, dim=3)
    ts = [0.0, 0.1, 0.37, 0.9]
    out = hi_json("curve", "eval", "--input", "-", "--t", ",".join(map(repr, ts)),
                  "--derivatives", "2", input=str(x.tolist()))
    c = harmonic.HarmonicCurve(x)
    np.testing.assert_allclose(c.eval(ts), out["X"], rtol=0, atol=1e-15)
    np.testing.assert_allclose(c.derivative(ts, 1), out["d1"], rtol=1e-15, atol=1e-13)
    np.testing.assert_allclose(c.derivative(ts, 2), out["d2"], rtol=1e-15, atol=1e-12)
    np.testing.assert_allclose(c.curvature(ts), out["curvature"], rtol=1e-14)


def test_a_circle_has_curvature_one_over_its_radius_and_speed_two_pi_r():
    r = 2.5
    k = np.arange(4)
    c = harmonic.HarmonicCurve(r * np.column_stack([np.cos(k * np.pi / 2), np.sin(k * np.pi / 2)]))
    t = np.linspace(0, 1, 17)
    np.testing.assert_allclose(c.curvature(t), 1 / r, rtol=1e-12)
    speed = np.linalg.norm(c.derivative(t), axis=1)
    np.testing.assert_allclose(speed, 2 * np.pi * r, rtol=1e-12)
    assert c.curvature(0.3) == pytest.approx(1 / r, rel=1e-12)


def test_rotation_shifts_the_parameter_and_resampling_keeps_the_curve():
    x = polygon(9)
    c = harmonic.HarmonicCurve(x)
    t = np.linspace(0, 1, 31)
    np.testing.assert_allclose(c.rotate(0.13).eval(t), c.eval(t + 0.13), atol=1e-12)
    more = c.resample(27)
    assert len(more) == 27 and more.dim == 2
    np.testing.assert_allclose(more.eval(t), c.eval(t), atol=1e-12)
    fewer, error = c.resample(5, with_error=True)
    deviation = np.abs(fewer.sample_uniform(512) - c.sample_uniform(512)).max()
    assert deviation <= error["error_bound"] + 1e-12


def de_casteljau(control, s):
    """A Bézier segment's point at s in [0, 1], by repeated linear interpolation."""
    p = np.array(control, dtype=float)
    while len(p) > 1:
        p = (1 - s) * p[:-1] + s * p[1:]
    return p[0]


def test_bezier_pieces_follow_the_curve_within_their_bound():
    c = harmonic.HarmonicCurve(polygon(7))
    b = c.to_bezier(tolerance=1e-6)
    breaks = b["breaks"]
    assert len(b["segments"]) == len(breaks) - 1
    worst = 0.0
    for seg, (t0, t1) in zip(b["segments"], zip(breaks[:-1], breaks[1:])):
        for s in np.linspace(0, 1, 9):
            worst = max(worst, np.linalg.norm(de_casteljau(seg, s) - c.eval(t0 + s * (t1 - t0))))
    assert worst <= 1e-6


def test_every_comparison_kind_builds_and_the_interpolating_ones_pass_through_the_points():
    x = polygon(8, seed=3)
    kinds = harmonic.curve_kinds()
    assert "catmull-rom" in kinds and "hobby-closed" in kinds and len(kinds) == 12
    for kind in kinds:
        c = harmonic.Curve(x, kind)
        assert c.kind == kind
        assert c.sample(16).shape == (16, 2)
    for kind in ["harmonic", "trig", "catmull-rom", "bspline-periodic", "four-point"]:
        c = harmonic.Curve(x, kind)
        np.testing.assert_allclose(c.eval(np.arange(8) / 8), x, atol=1e-9, err_msg=kind)


def test_catmull_rom_is_a_chain_of_cubics():
    x = polygon(6, seed=4)
    segments = harmonic.Curve(x, "catmull-rom").to_bezier()
    assert len(segments) == 6 and all(s.shape == (4, 2) for s in segments)
    # Each segment runs from one point to the next.
    for k, s in enumerate(segments):
        np.testing.assert_allclose(s[0], x[k], atol=1e-12)
        np.testing.assert_allclose(s[-1], x[(k + 1) % 6], atol=1e-12)
