"""``rgbz-fast config``: how the C kernels were built (OpenMP, flags, threads)."""

from __future__ import annotations

from . import _common as c

NAME = "config"


def add_parser(sub):
    return c.command_parser(sub, NAME, "how the C kernels were built",
                            "Print how the C kernels were built: version, compiler, flags, "
                            "whether OpenMP is on, and the thread count.")


def run(args):
    from .._config import show_config

    show_config()
    return 0
