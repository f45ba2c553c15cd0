"""Shared fixtures: running a test on the NumPy path and on the list path."""

import pytest

from hdt import _arrays

HAVE_NUMPY = _arrays.numpy is not None


@pytest.fixture(params=["numpy", "lists"])
def arrays(request, monkeypatch):
    """The array path under test: "numpy" (skipped without NumPy) or "lists"
    (NumPy switched off in hdt._arrays for the test, installed or not)."""
    if request.param == "numpy":
        if not HAVE_NUMPY:
            pytest.skip("NumPy is not installed")
    else:
        monkeypatch.setattr(_arrays, "numpy", None)
    return request.param
