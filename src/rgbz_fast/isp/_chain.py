"""The colour ISP of an RGB-Z sensor (paper §5.1.4, Figs. 18-19), stage by stage.

::

    raw CFA (DN) ─► correct_defects ─► fill_missing (reconstruct the Z sites)
        ─► white_balance (black level, grey-world gains, clip) ─► demosaic
        ─► correct_colour (3x3) ─► srgb_encode (sRGB OETF, 8 or 16 bit)

The defect correction comes first so that a defective pixel never feeds the
reconstruction, and it never reads a Z site; the reconstruction comes before
the white balance, which then sees a complete Bayer CFA, and before the
demosaic (paper §5.1.4). Every stage is a plain function of arrays plus a
small frozen dataclass of parameters; :class:`ColourISP` chains them.

The same chain serves both paths of Fig. 19: ``isp.run(frame)`` reconstructs
only when the frame's pattern has Z sites, and ``isp.run(frame,
reference=True)`` runs the plain Bayer reference CFA (``frame.reference``)
with the reconstruction bypassed. For a fair comparison the white-balance
gains estimated on the reference are reused on the RGB-Z path
(``run(frame, gains=...)``, or :meth:`ColourISP.run_pair`), so that the two
outputs differ by the reconstruction only. :meth:`ColourISP.render` runs the
stages after the reconstruction on a complete Bayer CFA: it is the chain of
every colour metric the library reports (the dataset evaluation, the
trade-off study, ``rgbz-fast reconstruct --output srgb``). The ToF ISP is
:mod:`rgbz_fast.tof`.
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from .._frame import RawFrame, frame_inputs, raw_clip_level
from .._patterns import get_pattern
from .._validate import (FRAME_DTYPES, check_bit_depth, check_choice, check_flag, check_image,
                         check_number, check_workers, merge_params)
from . import _fused
from ._defects import DefectCorrection, _check_known, correct_defects
from ._demosaic import demosaic
from ._stages import (ColourCorrection, Demosaic, Reconstruction, WhiteBalance, _black_white,
                      _check_gains, _encode, _quantise, correct_colour, fill_missing,
                      grey_world_gains, srgb_oetf, stage_params, white_balance)

__all__ = ["ColourISP", "STAGES", "recorded_rendering"]

#: the stages of :meth:`ColourISP.run`, in order (keys of ``return_stages``)
STAGES = ("defect_correction", "reconstruction", "white_balance", "demosaic",
          "colour_correction", "gamma", "output")

_PRECISIONS = {"float32": np.float32, "float64": np.float64}

#: the fields of :class:`ColourISP` that hold a stage's parameters, and their classes
_STAGE_FIELDS = {"defects": DefectCorrection, "reconstruction": Reconstruction,
                 "white_balance": WhiteBalance, "demosaicing": Demosaic,
                 "colour_correction": ColourCorrection}


def recorded_rendering(frame):
    """What a frame records about how to render it, from its ``meta``.

    A dict with ``"black_level"`` (DN of the frame's data: a simulated
    sensor's black level; None for frames whose black level is already
    subtracted, such as those of :func:`rgbz_fast.io.read_raw`),
    ``"white_level"`` (DN from which a pixel may be saturated, when below
    ``2**bit_depth - 1``: a simulated sensor whose well fills first, meta
    ``colour_saturation_level``; a raw file's clip level,
    :func:`rgbz_fast.io.frame_clip_level`; else None), ``"white_gains"``
    (R, G, B: a camera raw file's as-shot white balance, a simulated spectral
    sensor's white) and ``"colour_matrix"`` (3x3 tuple,
    white-balanced camera RGB -> linear sRGB), each None when not recorded.
    :class:`ColourISP` uses them where its own parameters leave the choice
    open; a caller of :meth:`ColourISP.render` passes them.
    """
    if not isinstance(frame, RawFrame):
        raise TypeError(f"frame: expected a RawFrame, got {type(frame).__name__}")
    meta = frame.meta
    black = getattr(meta.get("colour_sensor"), "black_level", None)
    key = "colour_sensor.black_level"
    if black is None:
        black, key = meta.get("colour_black_level"), "colour_black_level"
    gains = meta.get("white_gains")
    matrix = meta.get("colour_matrix")
    white, wkey = meta.get("colour_saturation_level"), "colour_saturation_level"
    try:
        if white is None:
            white, wkey = raw_clip_level(frame), "clip_level"
        if black is not None:             # a file's header may hold anything here
            black = check_number(black, key, lo=0, hi=frame.white_level, hi_open=True)
        if white is not None:
            white = check_number(white, wkey, lo=black or 0.0, lo_open=True)
            white = None if white >= frame.white_level else float(white)
        gains = None if gains is None else tuple(_check_gains(gains, "white_gains"))
        if matrix is not None:
            matrix = tuple(map(tuple, np.reshape(np.asarray(matrix, np.float64), (3, 3))))
            matrix = ColourCorrection(matrix=matrix).matrix
    except (TypeError, ValueError) as exc:
        raise ValueError(f"frame: its meta records an unusable rendering ({exc})") from None
    return {"black_level": None if black is None else float(black), "white_level": white,
            "white_gains": gains, "colour_matrix": matrix}


def _white_of(white_level, bit_depth):
    """A caller's white level (DN, at most full scale), or full scale ``2**bit_depth - 1``."""
    top = (1 << bit_depth) - 1
    if white_level is None:
        return top
    return check_number(white_level, "white_level", lo=0, lo_open=True, hi=top)


# =========================================================================== the chain

def _check_cfa_levels(data, white, bit_depth):
    """A complete CFA's values against its levels (H81): a negative DN is refused (one had
    zeroed grey world's green mean: unit gains for the image, without a word); values above
    the white level are saturated pixels, but a CFA mostly above it is warned about (an 11-bit
    CFA rendered with ``bit_depth=8`` came out nearly white)."""
    if data.dtype.kind == "f" and data.size and float(data.min()) < 0:
        raise ValueError(f"cfa: a value of {float(data.min()):g} DN; a CFA's values are >= 0 "
                         "(subtract no black level that the chain subtracts itself)")
    if data.size and float(data.max()) > white:
        share = float(np.count_nonzero(data > white)) / data.size
        if share > 0.5:
            warnings.warn(f"cfa: {100 * share:.0f} % of the pixels are above the white level "
                          f"{white:g} DN (bit_depth={bit_depth}): is bit_depth the CFA's?",
                          UserWarning, stacklevel=3)


@dataclass(frozen=True)
class ColourISP:
    """The colour ISP chain (paper Fig. 18): a frozen set of stage parameters.

    Every field is checked when the chain is made, by the class of its
    stage. A stage field takes the stage's parameters or a dict of their
    fields, applied over the stage's defaults
    (``ColourISP(demosaicing={"method": "menon2007"})``);
    :meth:`build` and :meth:`replace` apply keyword overrides to a chain,
    and a dict given for a stage there overrides fields of that chain's
    stage.

    Attributes
    ----------
    defects : DefectCorrection or dict
    reconstruction : Reconstruction or dict
        Used only when the frame's pattern has Z sites.
    white_balance : WhiteBalance or dict
    demosaicing : Demosaic or dict
    colour_correction : ColourCorrection or dict
    output_bits : {8, 16}
        Bits of the sRGB output.
    black_level : float or None
        DN. None: ``frame.meta["colour_sensor"].black_level`` when the frame
        comes from :func:`rgbz_fast.simulate`, else 0.
    precision : {"float32", "float64"}
        Float type from the white balance on.

    Examples
    --------
    >>> import numpy as np
    >>> import rgbz_fast as rz
    >>> from rgbz_fast.isp import ColourISP
    >>> frame = rz.mosaic(np.full((8, 8, 3), 0.5), "mask1")
    >>> out, stages = ColourISP().run(frame, return_stages=True)
    >>> out.shape, out.dtype, int(out[4, 4, 1])
    ((8, 8, 3), dtype('uint8'), 188)
    >>> [k for k in stages if k in rz.isp.STAGES] == list(rz.isp.STAGES)
    True
    >>> chain = ColourISP(precision="float64").replace(white_balance={"clip": False})
    >>> chain.precision, chain.white_balance
    ('float64', WhiteBalance(method='as_shot', gains=None, clip=False))
    """

    defects: DefectCorrection = DefectCorrection()
    reconstruction: Reconstruction = Reconstruction()
    white_balance: WhiteBalance = WhiteBalance()
    demosaicing: Demosaic = Demosaic()
    colour_correction: ColourCorrection = ColourCorrection()
    output_bits: int = 8
    black_level: float | None = None
    precision: str = "float32"

    if TYPE_CHECKING:
        # the __init__ type checkers see (py.typed is shipped): a stage field also takes a
        # dict of the stage's fields, which __post_init__ makes the stage the field holds
        def __init__(self, defects: DefectCorrection | Mapping[str, Any] = ...,
                     reconstruction: Reconstruction | Mapping[str, Any] = ...,
                     white_balance: WhiteBalance | Mapping[str, Any] = ...,
                     demosaicing: Demosaic | Mapping[str, Any] = ...,
                     colour_correction: ColourCorrection | Mapping[str, Any] = ...,
                     output_bits: int = 8, black_level: float | None = None,
                     precision: str = "float32") -> None: ...

    def __post_init__(self):
        for name, cls in _STAGE_FIELDS.items():
            object.__setattr__(self, name, stage_params(cls, getattr(self, name),
                                                        name=f"ColourISP.{name}",
                                                        allow_none=False))
        if isinstance(self.output_bits, bool) or not isinstance(
                self.output_bits, (int, np.integer)) or self.output_bits not in (8, 16):
            raise ValueError(f"ColourISP.output_bits: expected 8 or 16, got "
                             f"{self.output_bits!r}")
        if self.black_level is not None:
            check_number(self.black_level, "ColourISP.black_level", lo=0)
        object.__setattr__(self, "precision", check_choice(self.precision, tuple(_PRECISIONS),
                                                           "ColourISP.precision"))

    @classmethod
    def build(cls, params=None, overrides=None, *, name="params", caller="ColourISP.build()"):
        """``params`` (a ColourISP, a dict of its fields or None) with ``overrides`` applied.

        :func:`~rgbz_fast._validate.merge_params`, the library's one parameter
        rule; a dict given for a stage field overrides fields of the stage of
        ``params`` (of the stage's defaults when ``params`` is not a ColourISP).
        """
        if isinstance(params, cls) and overrides:
            overrides = dict(overrides)
            for field, stage in _STAGE_FIELDS.items():
                if isinstance(overrides.get(field), Mapping):
                    overrides[field] = merge_params(stage, getattr(params, field),
                                                    overrides[field], name=f"ColourISP.{field}",
                                                    caller=f"ColourISP.{field}")
        return merge_params(cls, params, overrides, name=name, caller=caller)

    def replace(self, **changes):
        """A copy with some fields changed (and checked); a dict for a stage field changes
        some fields of that stage (see :meth:`build`)."""
        return self.build(self, changes, caller="ColourISP.replace()")

    # ------------------------------------------------------------------ helpers
    def _bayer_input(self, cfa, phase, bit_depth, black_level, white_level):
        """A complete Bayer CFA's checked arguments (render, white_balance_gains): data,
        pattern, bit depth, black and white levels."""
        data = check_image(cfa, "cfa", ndim=2, dtypes=FRAME_DTYPES)
        pattern = get_pattern(phase)
        if pattern.has_z or pattern.bayer_phase is None:
            raise ValueError(f"phase: expected a plain Bayer phase, got pattern "
                             f"{pattern.name!r} (reconstruct the Z sites first)")
        bd = check_bit_depth(bit_depth)
        if black_level is None:
            black_level = self.black_level if self.black_level is not None else 0.0
        black, white = _black_white(black_level, _white_of(white_level, bd))
        _check_cfa_levels(data, white, bd)
        return data, pattern, bd, black, white

    def _inputs(self, frame, pattern, bit_depth, black_level, reference):
        if reference and not isinstance(frame, RawFrame):
            raise ValueError("reference: needs a RawFrame with a reference CFA")
        data, pat, bd = frame_inputs(frame, pattern, bit_depth)
        recorded = recorded_rendering(frame) if isinstance(frame, RawFrame) else {}
        if isinstance(frame, RawFrame) and reference:
            if frame.reference is None:
                raise ValueError("reference: the frame holds no reference Bayer CFA "
                                 "(frame.reference is None)")
            data, pat = frame.reference, frame.pattern.bayer_pattern()
        if pat.bayer_phase is None:
            raise ValueError(f"pattern: {pat.name!r} fits no Bayer phase; the chain needs "
                             "a Bayer-derived pattern")
        if black_level is None:
            black_level = self.black_level
        if black_level is None:
            black_level = recorded.get("black_level") or 0.0
        # a frame that saturates below full scale renders its saturation white, and grey
        # world leaves its saturated pixels out (they had been counted, tinting the gains)
        black, white = _black_white(black_level, _white_of(recorded.get("white_level"), bd))
        return data, pat, bd, black, white, recorded

    def _recorded(self, recorded, gains, matrix):
        """The gains and the matrix of a run: the caller's, else the chain's, else what the
        frame records (``as_shot`` gains; a matrix when the chain has none)."""
        if gains is None and self.white_balance.gains is None \
                and self.white_balance.method == "as_shot":
            gains = recorded.get("white_gains")
        if matrix is None and self.colour_correction.matrix is None:
            matrix = recorded.get("colour_matrix")
        return gains, matrix

    # ------------------------------------------------------------------ run
    def run(self, frame, *, pattern=None, bit_depth=None, black_level=None, gains=None,
            reference=False, defects=None, workers=None, return_stages=False, nir=None):
        """Run the chain: raw frame -> 8- or 16-bit sRGB image.

        Parameters
        ----------
        frame : RawFrame or ndarray, shape (rows, cols)
            The raw frame. A plain array needs ``pattern`` (and ``bit_depth``
            if not 11).
        pattern : Pattern or str, optional
            The pattern of a plain-array frame. The reconstruction runs only
            when it has Z sites, so a Bayer frame takes the reference path.
        bit_depth : int, optional
            Bits of a plain-array frame (11).
        black_level : float, optional
            DN; overrides :attr:`black_level`.
        gains : array_like (3,), optional
            White-balance gains (R, G, B) to use instead of estimating them:
            pass the reference path's gains (``stages["gains"]``) to the RGB-Z
            path for the paper's comparison (Fig. 19).
        reference : bool
            Run ``frame.reference`` (the plain Bayer CFA of the same
            exposure) on the frame's underlying Bayer pattern: the reference
            path, no reconstruction.
        defects : ndarray of bool, optional
            Known defects, corrected in addition to the detected ones.
        workers : int, optional
            Threads of the C kernels (None or -1: all cores).
        return_stages : bool
            Also return a dict of every intermediate result.
        nir : ndarray, optional
            The guide of a reconstruction method of :data:`rgbz_fast.NEEDS_TOF`
            (``"z_guided"``) for a frame without ToF taps
            (:func:`rgbz_fast.reconstruct`); a :class:`~rgbz_fast.RawFrame`'s
            taps (``frame.tof``) are passed through by default.

        Returns
        -------
        image : ndarray of uint8 or uint16, shape (rows, cols, 3)
            sRGB. Without ``return_stages``, on memory of the library's pool
            (:func:`rgbz_fast.memory_pool`): an ordinary array over the pool's
            block, whose memory the next call of the same size takes back when
            it is freed.
        stages : dict
            Only with ``return_stages``. In order: ``"raw"`` (input CFA, DN),
            ``"defect_mask"`` (bool), ``"defect_correction"`` (CFA, DN),
            ``"reconstruction"`` (full Bayer CFA, DN; the same array as the
            previous stage when the pattern has no Z), ``"gains"`` (R, G, B),
            ``"white_balance"`` (normalised CFA in [0, 1]), ``"demosaic"``
            (linear RGB, not clipped), ``"colour_correction"`` (linear RGB in
            [0, 1]), ``"gamma"`` (sRGB-encoded floats in [0, 1]),
            ``"output"`` (the returned image), ``"seconds"`` (time per
            stage), ``"pattern"``, ``"black_level"``, ``"white_level"``.
        """
        return_stages = check_flag(return_stages, "return_stages")
        data, pat, bd, black, white, recorded = self._inputs(frame, pattern, bit_depth,
                                                             black_level,
                                                             check_flag(reference, "reference"))
        gains, matrix = self._recorded(recorded, gains, None)
        # the frame's own taps guide a method of NEEDS_TOF, on either path
        tof = frame.tof if isinstance(frame, RawFrame) and not reference else None
        if not return_stages and self._fused(data):
            threads = check_workers(workers)
            fixed = _fused.defect_fixes(data, pat, self.defects, white,
                                        _check_known(defects, data.shape), threads)
            full = fill_missing(fixed, pat, self.reconstruction, bit_depth=bd, workers=workers,
                                tof=tof, nir=nir) if pat.has_z else fixed
            return _fused.render(full, pat.bayer_pattern(), self, black, white, gains,
                                 threads, matrix)[0]
        seconds = {}
        t0 = time.perf_counter()
        fixed, mask = correct_defects(data, pat, self.defects, white_level=white,
                                      known=defects, return_mask=True)
        t1 = time.perf_counter()
        seconds["defect_correction"] = t1 - t0
        full = fill_missing(fixed, pat, self.reconstruction, bit_depth=bd, workers=workers,
                            tof=tof, nir=nir) if pat.has_z else fixed
        seconds["reconstruction"] = time.perf_counter() - t1
        out, stages = self._render(full, pat.bayer_pattern(), black, white, gains, workers,
                                   return_stages, matrix)
        if not return_stages:
            return out
        stages["seconds"] = {**seconds, **stages["seconds"]}
        stages = {"raw": data, "defect_mask": mask, "defect_correction": fixed,
                  "reconstruction": full, **stages, "pattern": pat}
        return out, stages

    def render(self, cfa, phase="GRBG", *, bit_depth=11, black_level=None, white_level=None,
               gains=None, colour_matrix=None, workers=None, return_stages=False):
        """The stages after the reconstruction: complete Bayer CFA -> 8- or 16-bit sRGB.

        White balance, demosaic, colour correction, sRGB gamma and quantisation,
        with this chain's parameters: what :meth:`run` does once the Z sites are
        filled in, and the one colour chain behind every colour metric of the
        library (dataset evaluation, trade-off study, the command line).

        Parameters
        ----------
        cfa : ndarray, shape (rows, cols)
            A complete Bayer CFA in DN (reconstruct an RGB-Z frame first).
        phase : str or Pattern
            Its Bayer phase.
        bit_depth : int
            Bits of the CFA (white level ``2**bit_depth - 1``).
        black_level : float, optional
            DN; default :attr:`black_level`, else 0.
        white_level : float, optional
            DN rendered white, above which a pixel is saturated (grey world
            leaves it out); default ``2**bit_depth - 1``. A frame that
            saturates below full scale records its level
            (:func:`recorded_rendering`).
        gains : array_like (3,), optional
            White-balance gains to use instead of estimating them (the
            reference path's, for the comparison of Fig. 19, or the ones a
            frame records: :func:`recorded_rendering`).
        colour_matrix : 3x3 array_like, optional
            The colour matrix when the chain has none (a frame's recorded
            one); the chain's own :class:`ColourCorrection` matrix wins.
        workers : int, optional
            Threads of the C kernels.
        return_stages : bool
            Also return the intermediate results (``"gains"``,
            ``"white_balance"``, ``"demosaic"``, ``"colour_correction"``,
            ``"gamma"``, ``"output"``, ``"seconds"``, ``"black_level"``,
            ``"white_level"``).

        Examples
        --------
        >>> import numpy as np
        >>> from rgbz_fast import ColourISP
        >>> cfa = np.full((8, 8), 1023, np.uint16)
        >>> img, st = ColourISP().render(cfa, "GRBG", bit_depth=11, return_stages=True)
        >>> img.shape, img.dtype, int(img[4, 4, 0]), st["gains"].tolist()
        ((8, 8, 3), dtype('uint8'), 187, [1.0, 1.0, 1.0])
        """
        data, pattern, bd, black, white = self._bayer_input(cfa, phase, bit_depth, black_level,
                                                            white_level)
        return_stages = check_flag(return_stages, "return_stages")
        if colour_matrix is not None:
            colour_matrix = ColourCorrection(matrix=colour_matrix).matrix    # checked
        if not return_stages and self._fused(data):
            return _fused.render(data, pattern, self, black, white, gains,
                                 check_workers(workers), colour_matrix)[0]
        out, stages = self._render(data, pattern, black, white, gains, workers, return_stages,
                                   colour_matrix)
        return (out, stages) if return_stages else out

    def _fused(self, data):
        """Whether the stages after the input checks run as the C passes of
        :mod:`._fused` (the same image): every demosaic (:data:`._fused.DEMOSAICS`; Malvar
        and bilinear in the row pass, Menon 2007 through its own kernel between the C white
        balance and the C encoding) on a frame the passes take. A float
        frame without the white balance's clip stays on the stages, which refuse balanced
        values that overflow the working precision (the C passes would carry them on)."""
        return (self.demosaicing.method in _fused.DEMOSAICS
                and data.dtype in FRAME_DTYPES
                and data.ndim == 2 and data.shape[0] >= 2 and data.shape[1] >= 2
                and (self.white_balance.clip or data.dtype.kind != "f"))

    def white_balance_gains(self, cfa, phase="GRBG", *, bit_depth=11, black_level=None,
                            white_level=None):
        """The white-balance gains (R, G, B) :meth:`render` applies to a complete Bayer CFA:
        this chain's fixed gains, the grey-world estimate (``"as_shot"`` too: an array
        records no gains) or unit gains (its :class:`WhiteBalance`). Pass them to :meth:`render` (``gains=``) to render other
        CFAs of the scene with the same white balance (the RGB-Z path of Fig. 19).
        ``black_level`` and ``white_level`` as :meth:`render` takes them (grey world leaves
        the pixels at or above the white level out).

        Examples
        --------
        >>> import numpy as np
        >>> from rgbz_fast import ColourISP
        >>> cfa = np.tile(np.array([[800, 400], [300, 800]], np.uint16), (4, 4))
        >>> ColourISP().white_balance_gains(cfa, "GRBG").tolist()
        [2.0, 1.0, 2.6666666666666665]
        """
        data, pattern, bd, black, white = self._bayer_input(cfa, phase, bit_depth, black_level,
                                                            white_level)        # as render()
        wb = self.white_balance
        if wb.gains is not None:
            return np.asarray(wb.gains, np.float64)
        if wb.method in ("grey_world", "as_shot"):      # an array records no gains
            return grey_world_gains(data, pattern, black_level=black, white_level=white)
        return np.ones(3)

    def _render(self, full, bayer, black, white, gains, workers, keep_stages=True,
                matrix=None):
        """White balance .. output of a validated complete CFA; (image, stages).

        Without ``keep_stages`` the stages are None, and the colour correction's clip,
        the sRGB gamma and the quantisation run fused (:func:`._stages._encode`, the
        same codes bit for bit) instead of keeping their float images."""
        dt = _PRECISIONS[self.precision]
        seconds = {}
        t0 = time.perf_counter()

        def tick(name):
            nonlocal t0
            t1 = time.perf_counter()
            seconds[name] = t1 - t0
            t0 = t1

        balanced, used = white_balance(full, bayer, self.white_balance, black_level=black,
                                       white_level=white, gains=gains, dtype=dt)
        tick("white_balance")
        rgb = demosaic(balanced, bayer.bayer_phase, self.demosaicing.method,
                       mode=self.demosaicing.mode, dtype=dt, workers=workers)
        tick("demosaic")
        cc = self.colour_correction
        if cc.matrix is None and matrix is not None:
            cc = ColourCorrection(matrix=matrix)
        if not keep_stages:
            # the identity matrix: correct_colour would only clip, which _encode does
            linear = rgb if cc.matrix is None else correct_colour(rgb, cc)
            return _encode(linear, self.output_bits), None
        corrected = correct_colour(rgb, cc)
        tick("colour_correction")
        encoded = srgb_oetf(corrected)
        tick("gamma")
        out = _quantise(encoded, self.output_bits)
        tick("output")
        stages = {"gains": used, "white_balance": balanced, "demosaic": rgb,
                  "colour_correction": corrected, "gamma": encoded, "output": out,
                  "seconds": seconds, "black_level": black, "white_level": white}
        return out, stages

    def run_pair(self, frame, *, workers=None, return_stages=False):
        """Both paths of Fig. 19 with the same white balance: (reference, RGB-Z) images.

        The gains are estimated on the reference CFA (or taken from
        ``white_balance``) and reused on the RGB-Z frame, so the two images
        differ by the missing-colour reconstruction only.

        Returns
        -------
        reference_image, rgbz_image : ndarray
        reference_stages, rgbz_stages : dict
            Only with ``return_stages``.
        """
        if not isinstance(frame, RawFrame):
            raise TypeError(f"frame: expected a RawFrame with a reference CFA, got "
                            f"{type(frame).__name__}")
        return_stages = check_flag(return_stages, "return_stages")
        ref, ref_st = self.run(frame, reference=True, workers=workers, return_stages=True)
        test, test_st = self.run(frame, gains=ref_st["gains"], workers=workers,
                                 return_stages=True)
        if return_stages:
            return ref, test, ref_st, test_st
        return ref, test
