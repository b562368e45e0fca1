"""The library's parameter rule for the ToF ISP until ``rgbz_fast._validate.merge_params``
reaches this branch: the same signature and messages. Replace the import of this module in
:mod:`._chain` by ``from .._validate import merge_params`` and delete it."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

__all__ = ["merge_params"]


def merge_params(cls, params=None, overrides=None, *, name="params", caller=None, what=None):
    """``params`` (a ``cls``, a mapping of its fields or None) with keyword ``overrides`` of its
    fields, made by ``cls`` (whose ``__post_init__`` checks every field once)."""
    names = tuple(f.name for f in dataclasses.fields(cls))
    what = what or f"fields of {cls.__name__}"

    def known(mapping, label):
        unknown = [k for k in mapping if k not in names]
        if unknown:
            raise TypeError(f"{label} got an unexpected keyword argument {unknown[0]!r} "
                            f"({what}: {', '.join(names)})")
        return mapping

    overrides = known(dict(overrides or {}), caller or name)
    if isinstance(params, cls):
        return dataclasses.replace(params, **overrides) if overrides else params
    if params is None:
        base = {}
    elif isinstance(params, Mapping):
        base = known(dict(params), name)
    else:
        raise TypeError(f"{name}: expected a {cls.__name__}, a dict of its fields or None, "
                        f"got {type(params).__name__}")
    return cls(**{**base, **overrides})
