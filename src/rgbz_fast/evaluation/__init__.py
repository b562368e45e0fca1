"""Dataset evaluation: the paper's Fig. 19 chain on every image x pattern x method.

:func:`evaluate` runs an :class:`EvalConfig` over a dataset
(:func:`rgbz_fast.io.folder_dataset`, :func:`rgbz_fast.io.sample_dataset`) in a
process pool or on Dask distributed, with a per-image cache; it returns
:class:`Results`, a tidy table that :func:`write_reports` turns into CSV, JSON,
Markdown tables and figures. :func:`train_filters` fits the ``"learned"``
method's filters to a dataset with the same protocol.
:func:`evaluate_depth` measures the ToF chain
(the RGB-D scenes, ranges, noise, sunlight, calibration) and
:func:`depth_report` prints its tables.
"""

from ._config import (ALL_METRICS, HIGHER_IS_BETTER, IMAGE_METRICS, METHOD_LABELS,
                      METRIC_LABELS, PAPER_TABLE3, EvalConfig)
from ._reports import bar_chart, crop_figure, paired_chart, write_reports
from ._results import Results
from ._run import evaluate, evaluate_image, image_frames
from ._train import train_filters

__all__ = ["EvalConfig", "evaluate", "evaluate_image", "image_frames", "Results",
           "write_reports", "bar_chart", "paired_chart", "crop_figure", "PAPER_TABLE3",
           "IMAGE_METRICS", "ALL_METRICS", "METRIC_LABELS", "METHOD_LABELS", "HIGHER_IS_BETTER",
           "train_filters",
           "evaluate_depth", "depth_report", "DEPTH_SECTIONS"]


_LAZY = ("DEPTH_SECTIONS", "depth_report", "evaluate_depth")


def __getattr__(name):
    """The depth evaluation (and with it the ToF chain) is imported at its first use: the
    colour evaluation never loads it."""
    if name in _LAZY:
        from . import _depth

        value = getattr(_depth, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_LAZY))
