"""The error the readers raise when a parameter is wrong or missing: it carries the parameter.

A message such as ``"phase: x.png does not record its CFA phase; pass phase=
one of RGGB, ..."`` names the parameter at fault (``param``) and, in its
advice, the settings that fix it. A caller that spells those settings another
way -- the command line's ``--phase`` -- renders the same error with its own
words through :meth:`ParameterError.render`, from the parts of the message
instead of by rewriting its text.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["ParameterError", "Setting", "named"]


@dataclass(frozen=True)
class Setting:
    """A parameter named in an error's advice, as the caller would set it.

    ``name`` is the parameter (``"phase"``); ``python`` how a Python caller
    sets it (default ``"phase="``; ``"grey=True"``, ``"shape=(rows, cols)"``).
    """

    name: str
    python: str = ""

    def __post_init__(self):
        if not self.python:
            object.__setattr__(self, "python", f"{self.name}=")


def _python(setting):
    return setting.python


class ParameterError(ValueError):
    """A ValueError about the parameter ``param``, whose message may name settings that fix it.

    ``ParameterError(param, *parts)``: the message is ``"{param}: "`` followed
    by the parts, each a string or a :class:`Setting`. ``str(error)`` spells
    the settings as Python arguments; :meth:`render` with another spelling.
    ``param`` None: a detail about the content of a file, without a
    parameter yet, which the caller names with :func:`named`.

    Examples
    --------
    >>> from rgbz_fast.io import ParameterError, Setting
    >>> e = ParameterError("shape", "raw.bin needs ", Setting("shape", "shape=(rows, cols)"))
    >>> str(e), e.param, e.settings
    ('shape: raw.bin needs shape=(rows, cols)', 'shape', ('shape',))
    >>> e.render(lambda s: "--" + s.name)
    'shape: raw.bin needs --shape'
    """

    def __init__(self, param, *parts):
        self.param = param
        self.parts = tuple(parts)
        super().__init__(self.render())

    @property
    def settings(self):
        """The names of the parameters the message asks the caller to set, in order."""
        return tuple(p.name for p in self.parts if isinstance(p, Setting))

    def render(self, spell=_python):
        """The message with each :class:`Setting` spelled by ``spell(setting)``."""
        text = "".join(p if isinstance(p, str) else spell(p) for p in self.parts)
        return text if self.param is None else f"{self.param}: {text}"

    def within(self, param, before, after=""):
        """The same error inside a wider one: ``"{param}: {before}{this message}{after}"``."""
        head = () if self.param is None else (f"{self.param}: ",)
        return ParameterError(param, before, *head, *self.parts, after)

    def __reduce__(self):              # pickled by its parts (worker processes return it)
        return (type(self), (self.param, *self.parts))


ParameterError.__module__ = Setting.__module__ = "rgbz_fast.io"      # where users import them


def named(exc, param, before, after=""):
    """``exc`` (a detail of what is wrong) as an error about ``param``, to raise: a
    :class:`ParameterError` keeps its settings, another exception becomes a ValueError of the
    same text, ``"{param}: {before}{exc}{after}"``."""
    if isinstance(exc, ParameterError):
        return exc.within(param, before, after)
    return ValueError(f"{param}: {before}{exc}{after}")
