"""Lazy imports of the heavy optional-at-runtime dependencies, without side effects.

colour-science takes about a second to import and, on import, switches NumPy's
print options to the 1.13 legacy mode for the whole process (``np.set_printoptions(
legacy="1.13")``); colour-demosaicing 0.2 imports from a SciPy namespace SciPy
deprecates; colour-science imports matplotlib, whose older releases call names
that pyparsing deprecates. These helpers import them when a function first needs
them and undo or silence what the import does to the user's process.
"""

from __future__ import annotations

import threading
import warnings

import numpy as np

__all__ = ["import_colour", "import_colour_demosaicing"]

#: the import-time warnings silenced (messages, as warnings.filterwarnings matches them):
#: pyparsing 3.3's deprecated names, which an older matplotlib (3.8, the floor) calls when
#: colour-science imports it; SciPy's deprecated namespace, which colour-demosaicing 0.2
#: imports from (SciPy 1.10, the floor, says "use", later releases "import")
PYPARSING_NAMES = r"'[A-Za-z]+' (argument is )?deprecated[-, ]+use '[a-z_]+'"
SCIPY_NDIMAGE_NAMESPACE = r"Please (import|use) `\w+` from the `scipy\.ndimage` namespace"

#: held while an import changes the warning filters and the print options, which belong to
#: the process: two threads importing at once would each restore the other's changed state
_PROCESS_STATE = threading.RLock()


def import_colour():
    """``colour`` (colour-science), leaving NumPy's print options and the warning filters as
    they were."""
    with _PROCESS_STATE:
        return _import_colour()


def _import_colour():
    opts = np.get_printoptions()
    try:
        with warnings.catch_warnings():
            # colour-science may warn about optional dependencies when loaded
            warnings.filterwarnings("ignore", module=r"colour(\.|$)")
            # and matplotlib's pyparsing names when it imports it: under -W error the import
            # failed half-way, and every later use of colour-science with it
            warnings.filterwarnings("ignore", category=DeprecationWarning,
                                    message=PYPARSING_NAMES)
            import colour
    finally:
        np.set_printoptions(**opts)
    return colour


def import_colour_demosaicing():
    """``colour_demosaicing``, hiding its import-time SciPy deprecation warnings.

    colour-demosaicing 0.2.x imports ``convolve`` from ``scipy.ndimage.filters``,
    a namespace SciPy deprecates; only that warning is silenced. It imports
    colour-science, whose print-option change is undone as in :func:`import_colour`.
    """
    with _PROCESS_STATE:
        return _import_colour_demosaicing()


def _import_colour_demosaicing():
    _import_colour()
    opts = np.get_printoptions()
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings(
                "ignore", category=DeprecationWarning, message=SCIPY_NDIMAGE_NAMESPACE)
            import colour_demosaicing
    except ImportError as exc:  # pragma: no cover - a declared dependency
        raise ImportError("the reference demosaics (tests, rgbz-fast bench) need the "
                          "colour-demosaicing package (pip install colour-demosaicing)") from exc
    finally:
        np.set_printoptions(**opts)
    return colour_demosaicing
