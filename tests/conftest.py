"""Shared fixtures; puts tests/ on sys.path so that every test module, in any sub-folder, can
import the helpers (``_support``) and the NumPy references (``_reference``)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np
import pytest

try:
    from hypothesis import settings

    settings.register_profile("deterministic", derandomize=True, database=None,
                              deadline=None, print_blob=True)
    settings.register_profile("dev", deadline=None)
    settings.load_profile("deterministic" if os.environ.get("CI") else "dev")
except ImportError:  # pragma: no cover
    pass

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _support import shared_path  # noqa: E402


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


@pytest.fixture(scope="session")
def kodak_dir():
    return shared_path("kodak")


@pytest.fixture
def terminal(monkeypatch):
    """The command line's stderr taken for a terminal, so that it draws its progress bars
    into the captured stream (it draws none into a log or a pipe)."""
    import rgbz_fast._cli._common as common

    monkeypatch.setattr(common, "_terminal", lambda: True)
