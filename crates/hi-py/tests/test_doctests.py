# SPDX-License-Identifier: MIT
"""The examples in the docstrings (``help(harmonic.X)``) run and print what they show."""

import doctest

import numpy as np
import pytest

import harmonic
import harmonic.batch

OBJECTS = [harmonic, harmonic.batch] + [getattr(harmonic, name) for name in harmonic.__all__
                                        if name != "__version__"]


@pytest.mark.parametrize("obj", OBJECTS, ids=lambda o: getattr(o, "__name__", repr(o)))
def test_docstring_examples_run(obj):
    finder = doctest.DocTestFinder(exclude_empty=True)
    tests = finder.find(obj, getattr(obj, "__name__", "obj"),
                        globs={"harmonic": harmonic, "np": np})
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0


def test_every_public_object_has_a_docstring_with_an_example_or_a_description():
    for name in harmonic.__all__:
        if name == "__version__":
            continue
        doc = getattr(harmonic, name).__doc__
        assert doc and len(doc) > 40, name
    examples = [t for o in OBJECTS for t in doctest.DocTestFinder().find(o) if t.examples]
    assert len(examples) >= 10, "the docs show how to call the package"
