"""The results of an evaluation: a tidy table, its summaries and its text renderings."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import asdict, dataclass, field

import numpy as np

from .._validate import as_list, check_int, merge_params, nonfinite_as
from .._patterns import Pattern, get_pattern
from ._config import (ALL_METRICS, HIGHER_IS_BETTER, METHOD_LABELS, METRIC_LABELS, PAPER_TABLE3,
                      EvalConfig, _pattern_name)

__all__ = ["Results"]

#: the keys of one row of the table
_ROW_KEYS = {"image", "pattern", "method", "metric", "value"}
#: the decimals of a metric's values in the Markdown tables
DIGITS = {"cfa_psnr": 2, "cpsnr": 2, "ssim": 4, "ms_ssim": 4, "zipper": 2}

#: Student's t quantile at 0.975 of 1 to 127 degrees of freedom, as
#: ``scipy.special.stdtrit(df, 0.975)`` gives it (scipy 1.17; a test compares them with the
#: installed scipy): the paired intervals of the usual datasets without the import of
#: scipy.special (0.2 s of CPU, as much as the evaluation of an image)
_T975 = (
    12.706204736174694, 4.302652729749462, 3.1824463052837078, 2.7764451051977934,
    2.5705818356363146, 2.4469118511449786, 2.364624251592784, 2.306004135204166,
    2.262157162798205, 2.228138851986274, 2.200985160091639, 2.1788128296672284,
    2.1603686564627913, 2.144786687917804, 2.131449545559776, 2.1199052992212546,
    2.1098155778333156, 2.1009220402410382, 2.0930240544083087, 2.085963447265864,
    2.0796138447276795, 2.0738730679040254, 2.0686576104190486, 2.0638985616280245,
    2.0595385527532972, 2.0555294386428735, 2.0518305164802846, 2.0484071417952454,
    2.045229642132703, 2.0422724563012378, 2.039513446396408, 2.0369333434601016,
    2.0345152974493383, 2.0322445093177186, 2.030107928250343, 2.0280940009804502,
    2.0261924630291093, 2.0243941639119694, 2.022690920036761, 2.021075390306273,
    2.019540970441376, 2.0180817028184443, 2.016692199227824, 2.0153675744437636,
    2.014103388880846, 2.012895598919429, 2.0117405137297655, 2.010634757624232,
    2.0095752371292392, 2.008559112100761, 2.007583770315836, 2.006646805061688,
    2.0057459953178687, 2.0048792881880564, 2.0040447832891455, 2.003240718847872,
    2.002465459291007, 2.0017174841452356, 2.000995378088267, 2.0002978220142604,
    1.999623584994939, 1.9989715170333788, 1.998340542520741, 1.997729654317693,
    1.9971379083920038, 1.9965644189523117, 1.996008354025296, 1.9954689314298435,
    1.9949454151072374, 1.994437111771186, 1.9939433678456255, 1.9934635666618719,
    1.992997125889855, 1.992543495180932, 1.9921021540022417, 1.9916726096446642,
    1.9912543953883846, 1.9908470688116906, 1.9904502102301285, 1.990063421254446,
    1.9896863234569029, 1.989318557136572, 1.9889597801751624, 1.9886096669757083,
    1.9882679074772216, 1.98793420623902, 1.9876082815890708, 1.9872898648311692,
    1.986978699506281, 1.9866745407037683, 1.9863771544186177, 1.98608631695113,
    1.9858018143458227, 1.985523441866604, 1.9852510035054978, 1.984984311522457,
    1.9847231860139845, 1.9844674545084815, 1.9842169515864174, 1.9839715185235518,
    1.983731002955606, 1.9834952585628793, 1.9832641447734565, 1.9830375264837259,
    1.9828152737950475, 1.9825972617655006, 1.9823833701756908, 1.982173483307727,
    1.9819674897364825, 1.981765282132372, 1.9815667570749007, 1.9813718148763053,
    1.981180359414661, 1.9809922979758567, 1.9808075411039094, 1.9806260024590894,
    1.9804475986834025, 1.980272249272974, 1.9800998764569397, 1.9799304050824402,
    1.9797637625053868, 1.9795998784866382, 1.9794386850933035, 1.9792801166048548,
    1.9791241094237977, 1.9789706019906281, 1.9788195347028539,
)


def _t975(df):
    """Student's t quantile at 0.975 of ``df`` >= 1 degrees of freedom."""
    if df <= len(_T975):
        return _T975[df - 1]
    from scipy.special import stdtrit     # scipy.stats.t.ppf's own function

    return float(stdtrit(df, 0.975))


#: the strings a non-finite float is written as in results.json (JSON has no such numbers)
_NONFINITE = {"inf": math.inf, "-inf": -math.inf, "nan": math.nan}


def _json_safe(obj):
    """``obj`` with every non-finite float written "inf", "-inf" or "nan", for
    ``json.dumps(..., allow_nan=False)``."""
    return nonfinite_as(obj, lambda x: "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf"))


def _json_float(obj):
    """The inverse of :func:`_json_safe` for a row's value: "inf", "-inf", "nan" (and the
    older files' Infinity/NaN, already floats) as floats; anything else unchanged."""
    return _NONFINITE[obj] if isinstance(obj, str) and obj in _NONFINITE else obj


def _names(items):
    """"a", "a and b", "a, b and c"."""
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _cells(groups):
    """(key, words) of ``groups`` ({key: {pattern: [methods]}}, the key's first item a metric):
    the patterns on which the same methods are alike together, as "METRIC of METHODS on
    PATTERNS"."""
    for key, per_pattern in groups.items():
        by_methods = {}
        for p, ms in per_pattern.items():
            by_methods.setdefault(tuple(ms), []).append(p)
        for ms, ps in by_methods.items():
            yield key, (f"{METRIC_LABELS[key[0]].split(' (')[0]} of "
                        f"{_names(METHOD_LABELS.get(m, m) for m in ms)} on {_names(ps)}")


@dataclass(repr=False)
class Results:
    """A tidy table: one row per image, pattern, method and metric.

    ``dataset`` names the images' source (the folder they come from, "scikit-image samples";
    "" when they come from several), which the figures' titles carry.
    ``skipped`` lists the ``(image, reason)`` of the images an evaluation with
    ``skip_bad=True`` left out; ``raw_images`` the names of the images read from camera raw
    or bare Bayer files, measured at their own bit depth, noise and lens rather than through
    the configuration's mosaic (the reports' header says so).
    """

    rows: list
    config: EvalConfig = field(default_factory=EvalConfig)
    skipped: list = field(default_factory=list)
    raw_images: list = field(default_factory=list)
    dataset: str = ""

    def __post_init__(self):
        self.config = merge_params(EvalConfig, self.config, name="config")
        self.rows = as_list(self.rows, "rows", "a list of row dicts")
        for r in self.rows:
            # "ir_estimated": an optional mark of the rows of a method guided by the Z pixels
            if not isinstance(r, dict) or set(r) - {"ir_estimated"} != _ROW_KEYS or \
                    not isinstance(r["value"], (int, float)) or isinstance(r["value"], bool):
                raise TypeError(f"rows: expected dicts of {', '.join(sorted(_ROW_KEYS))} "
                                f"(value a number), got {r!r:.80}")
        self.skipped = as_list(self.skipped, "skipped", "a list of (image, reason)")
        self.raw_images = as_list(self.raw_images, "raw_images", "a list of image names")
        if not all(isinstance(n, str) for n in self.raw_images):
            raise TypeError("raw_images: expected a list of image names (strings)")
        if not isinstance(self.dataset, str):
            raise TypeError(f"dataset: expected the dataset's name (a string), got "
                            f"{type(self.dataset).__name__}")

    def label(self):
        """:meth:`EvalConfig.label`, with what the images were: the mosaic's settings describe
        the RGB images alone, a raw file is measured as it is."""
        images = set(self.images())
        raw = set(self.raw_images) & images
        if not raw:
            return self.config.label()
        return self.config.label(raw_files=len(raw), rgb_images=len(images - raw))

    def __len__(self):
        return len(self.rows)

    def __repr__(self):
        # the dataclass's repr printed every row (3 MB for 500 images): a notebook or a log
        # line took it all (H102); the rows are in .rows, the tables in the *_markdown methods
        c = self.config
        extra = "".join(f", {len(v)} {what}" for v, what in ((self.skipped, "skipped"),
                                                             (self.raw_images, "raw"))
                        if v)
        return (f"Results({len(self.rows)} rows: {len(self.images())} images x patterns "
                f"{list(c.patterns)} x methods {list(c.methods)} x metrics "
                f"{list(c.metrics)}{extra})")

    def _known(self, value, name, known):
        """``value`` when it is one of ``known`` (the names of these results), else a
        ValueError naming ``name``: an unknown name would select nothing, silently. A Pattern
        is taken as the name :class:`EvalConfig` gives it (it had been refused, although the
        config takes Pattern objects)."""
        if name == "pattern" and isinstance(value, Pattern):
            # the config's name of an equal pattern, however either was written
            for k in known:
                try:
                    if get_pattern(k) == value:
                        return k
                except ValueError:
                    continue
            try:
                value = _pattern_name(value)
            except ValueError:
                pass
        if not isinstance(value, str) or value not in known:
            shown = repr(value)
            shown = shown if len(shown) <= 60 else shown[:57] + "..."
            raise ValueError(f"{name}: {shown} is not in the results (expected one of "
                             f"{', '.join(known)})")
        return value

    def values(self, pattern, method, metric):
        """The values of one cell, one per image (in the rows' order), as float64."""
        pattern = self._known(pattern, "pattern", self.config.patterns)
        self._known(method, "method", self.config.methods)
        self._known(metric, "metric", self.config.metrics)
        return np.array([r["value"] for r in self.rows if r["pattern"] == pattern
                         and r["method"] == method and r["metric"] == metric], dtype=float)

    def summary(self):
        """{(pattern, method, metric): (mean, std, n)}; infinite values are left out of the mean;
        the std (ddof=1) is NaN with fewer than two values (one image has no spread)."""
        out = {}
        for p in self.config.patterns:
            for m in self.config.methods:
                for k in self.config.metrics:
                    v = self.values(p, m, k)
                    v = v[np.isfinite(v)]
                    out[(p, m, k)] = (float(v.mean()) if v.size else math.nan,
                                      float(v.std(ddof=1)) if v.size > 1 else math.nan,
                                      int(v.size))
        return out

    def left_out(self):
        """{(pattern, method, metric): (n, total, kinds)} of the cells whose mean leaves out
        values: ``n`` finite values of the cell's ``total``, ``kinds`` the sorted set of the
        left-out values ("+inf", "-inf", "nan"). A PSNR is +inf where the test image equals
        its reference; :meth:`summary` averages the finite values only."""
        out = {}
        for p in self.config.patterns:
            for m in self.config.methods:
                if not self.config.applies(p, m):
                    continue
                for k in self.config.metrics:
                    v = self.values(p, m, k)
                    bad = v[~np.isfinite(v)]
                    if bad.size:
                        kinds = {"nan" if np.isnan(x) else ("+inf" if x > 0 else "-inf")
                                 for x in bad}
                        out[(p, m, k)] = (int(v.size - bad.size), int(v.size),
                                          tuple(sorted(kinds)))
        return out

    def _finite_images(self, pattern, method, metric):
        """The images whose value of the cell is finite (those its mean covers)."""
        return frozenset(r["image"] for r in self.rows if r["pattern"] == pattern
                         and r["method"] == method and r["metric"] == metric
                         and math.isfinite(r["value"]))

    def summary_dict(self):
        """:meth:`summary` as ``{"pattern/method/metric": {"mean", "std", "n"}}`` for JSON
        (non-finite numbers as "inf", "-inf", "nan"), with what the tables say too: a cell
        whose values are +inf on every image has the mean "inf" (a perfect reconstruction,
        not one that did not run); a cell whose mean leaves out values has ``"left_out":
        {"n": count, "kinds": [...]}`` (:meth:`left_out`); a method that does not apply to
        the pattern has ``"applies": false``. (The mean of a cell alone had been "nan" with
        n 0 for both a perfect method and one that never ran.)"""
        left = self.left_out()
        out = {}
        for (p, m, k), (mean, std, n) in self.summary().items():
            entry = {"mean": mean, "std": std, "n": n}
            if (p, m, k) in left:
                finite, total, kinds = left[(p, m, k)]
                entry["left_out"] = {"n": total - finite, "kinds": list(kinds)}
                if finite == 0 and kinds == ("+inf",):
                    entry["mean"] = math.inf
            if not self.config.applies(p, m):
                entry["applies"] = False
            out[f"{p}/{m}/{k}"] = entry
        return _json_safe(out)

    def nonfinite_note(self, metrics=None):
        """One line saying which means leave out non-finite values, and why ("" when none).

        Cells alike (the same metric, counts and kind of values) are grouped: their
        methods, then the patterns on which those methods are alike. ``metrics`` restricts
        the line to those metrics.
        """
        cells = {c: v for c, v in self.left_out().items() if metrics is None or c[2] in metrics}
        if not cells:
            return ""
        only_inf = all(v[2] == ("+inf",) for v in cells.values())
        head = ("Means leave out infinite values (a test image equal to its reference: "
                "PSNR +inf): " if only_inf else
                "Means leave out non-finite values (+inf: a test image equal to its reference; "
                "-inf or NaN: a metric that could not be computed): ")
        groups = {}                  # (metric, n, total, kinds) -> {pattern: [methods]}
        for k in self.config.metrics:
            for p in self.config.patterns:
                for m in self.config.methods:
                    if (p, m, k) in cells:
                        n, total, kinds = cells[(p, m, k)]
                        groups.setdefault((k, n, total, kinds), {}).setdefault(p, []).append(m)
        parts = []
        for (k, n, total, kinds), what in _cells(groups):
            if n == 0 and kinds == ("+inf",):
                parts.append(f"{what}: all {total} images are +inf")
            elif n == 0:
                parts.append(f"{what}: no finite value in {total} images ({', '.join(kinds)})")
            else:
                parts.append(f"{what} over {n} of {total} images"
                             + ("" if only_inf else f" ({', '.join(kinds)} left out)"))
        return head + "; ".join(parts) + "."

    def _paired_note(self, base, others):
        """The line under the paired differences: the cells whose difference leaves out
        images on which either method is not finite ("" when none)."""
        groups = {}                  # (metric, n, total) -> {pattern: [methods]}
        for k in self.config.metrics:
            for p in self.config.patterns:
                for m in others:
                    if not (self.config.applies(p, m) and self.config.applies(p, base)):
                        continue
                    a = {r["image"] for r in self.rows if r["pattern"] == p
                         and r["method"] == m and r["metric"] == k}
                    b = {r["image"] for r in self.rows if r["pattern"] == p
                         and r["method"] == base and r["metric"] == k}
                    total = len(a & b)
                    n = self.paired(p, m, k, base)[0].size
                    if n < total:
                        groups.setdefault((k, n, total), {}).setdefault(p, []).append(m)
        parts = [f"Δ {what}: none of {total} images" if n == 0 else
                 f"Δ {what} over {n} of {total} images"
                 for (k, n, total), what in _cells(groups)]
        if not parts:
            return ""
        return ("Differences leave out the images on which either method is not finite (a "
                "PSNR is +inf where a test image equals its reference): " + "; ".join(parts)
                + ".")

    def images(self):
        """The images of the rows, in their order, each once."""
        return list(dict.fromkeys(r["image"] for r in self.rows))

    def ir_estimated(self, pattern, method):
        """The images on which ``method`` was guided by a NIR reflectance estimated from the RGB
        (rows marked ``"ir_estimated"``: :func:`~rgbz_fast.evaluation.evaluate_image`). Such
        a result has seen the colour it had to find: it is no evidence for the method. A
        pattern or method not in the results is a ValueError (it had read as "none")."""
        pattern = self._known(pattern, "pattern", self.config.patterns)
        self._known(method, "method", self.config.methods)
        return list(dict.fromkeys(r["image"] for r in self.rows if r.get("ir_estimated")
                                  and r["pattern"] == pattern and r["method"] == method))

    def _label(self, pattern, method):
        """The method's label; a guide estimated from the RGB is said in it."""
        label = METHOD_LABELS.get(method, method)
        est = self.ir_estimated(pattern, method)
        if est:
            label += (f" (NIR estimated from the RGB on {len(est)} of {len(self.images())} "
                      "images: leaks the answer, not evidence)")
        return label

    def paired(self, pattern, method, metric, baseline="bilinear"):
        """Per-image differences ``method - baseline`` and their mean with a 95 % interval.

        Both methods see the same images, so the difference of each image
        removes what the images themselves contribute (a detailed image is
        hard for every method): the interval of the mean difference is much
        narrower than the spread of either method's values. Images with a
        non-finite value in either method are left out.

        Returns
        -------
        diffs : ndarray, shape (n,)
            One difference per image, in the order of :meth:`images`.
        mean, lo, hi : float
            The mean difference and its 95 % confidence interval (Student's
            t with n - 1 degrees of freedom; the mean itself when n = 1).

        Examples
        --------
        >>> from rgbz_fast.evaluation import EvalConfig, Results
        >>> rows = [{"image": i, "pattern": "mask1", "method": m, "metric": "cfa_psnr",
        ...          "value": v} for i, m, v in (("a", "bilinear", 30.0), ("a", "sg", 31.0),
        ...                                      ("b", "bilinear", 20.0), ("b", "sg", 21.5))]
        >>> res = Results(rows, EvalConfig(methods=("bilinear", "sg"), metrics=("cfa_psnr",)))
        >>> diffs, mean, lo, hi = res.paired("mask1", "sg", "cfa_psnr")
        >>> diffs.tolist(), mean, round(lo, 3), round(hi, 3)
        ([1.0, 1.5], 1.25, -1.927, 4.427)
        """
        pattern = self._known(pattern, "pattern", self.config.patterns)
        self._known(method, "method", self.config.methods)
        self._known(baseline, "baseline", self.config.methods)
        self._known(metric, "metric", self.config.metrics)

        def per_image(m):
            return {r["image"]: r["value"] for r in self.rows if r["pattern"] == pattern
                    and r["method"] == m and r["metric"] == metric}

        a, b = per_image(method), per_image(baseline)
        diffs = np.array([a[i] - b[i] for i in self.images() if i in a and i in b
                          and np.isfinite(a[i]) and np.isfinite(b[i])], dtype=float)
        if diffs.size == 0:
            return diffs, math.nan, math.nan, math.nan
        mean = float(diffs.mean())
        if diffs.size == 1:
            return diffs, mean, mean, mean
        half = float(_t975(diffs.size - 1) * diffs.std(ddof=1) / math.sqrt(diffs.size))
        return diffs, mean, mean - half, mean + half

    def baseline(self):
        """The method the paired differences are taken against: bilinear when it ran, else
        the first method."""
        return "bilinear" if "bilinear" in self.config.methods else self.config.methods[0]

    def to_csv(self):
        """The rows as CSV text: image, pattern, method, metric, value (its repr: ``inf`` for
        +inf), and an ``ir_estimated`` column when a row has it."""
        buf = io.StringIO()
        fields = ["image", "pattern", "method", "metric", "value"]
        if any("ir_estimated" in r for r in self.rows):
            fields.append("ir_estimated")
        w = csv.DictWriter(buf, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        for r in self.rows:
            w.writerow({**r, "value": repr(r["value"])})
        return buf.getvalue()

    def to_json(self):
        """The results as strict JSON: a non-finite value (a PSNR of +inf) is written as the
        string "inf", "-inf" or "nan" (:meth:`from_json` reads both these and the
        ``Infinity``/``NaN`` of older files)."""
        return json.dumps(_json_safe(
            {"config": asdict(self.config), "rows": self.rows,
             "skipped": [list(t) for t in self.skipped], "raw_images": list(self.raw_images),
             "dataset": self.dataset,
             "not_applicable": [[p, m, " ".join(str(why).split())] for (p, m), why
                                in self.config.not_applicable().items()]}),
            indent=1, default=str, allow_nan=False)

    @classmethod
    def from_json(cls, text):
        """The :class:`Results` of :meth:`to_json`'s text (results.json).

        A row's value may be a number, the string "inf", "-inf" or "nan", or the
        ``Infinity``/``NaN`` of the files older versions wrote.

        Examples
        --------
        >>> from rgbz_fast.evaluation import EvalConfig, Results
        >>> rows = [{"image": "a", "pattern": "mask1", "method": "bilinear",
        ...          "metric": "cpsnr", "value": float("inf")}]
        >>> res = Results(rows, EvalConfig(methods=("bilinear",), metrics=("cpsnr",)))
        >>> '"value": "inf"' in res.to_json()
        True
        >>> Results.from_json(res.to_json()).rows[0]["value"]
        inf
        """
        from ..simulation import Optics
        from ._config import EvalConfig

        if isinstance(text, (bytes, bytearray)):
            text = text.decode("utf-8")
        data = json.loads(text)
        if not isinstance(data, dict) or not isinstance(data.get("rows"), list):
            raise ValueError("results.json: expected an object with a list of rows")
        rows = [{**r, "value": _json_float(r["value"])} if isinstance(r, dict) and "value" in r
                else r for r in data["rows"]]
        config = dict(data.get("config") or {})
        if isinstance(config.get("params"), dict):
            config["params"] = {k: _json_float(v) for k, v in config["params"].items()}
            given = config["params"].get("filters")
            if given is not None:
                from pathlib import Path

                names = [given] if isinstance(given, str) else list(given)
                if not all(isinstance(n, str) and Path(n).is_file() for n in names):
                    # to_json describes the filters (their repr: pattern, training set and
                    # digest); their weights are not in the file, so the configuration is
                    # read without them, and the rows as they are
                    import warnings

                    warnings.warn("results.json: the configuration's filters are described, "
                                  "not stored (" + "; ".join(map(str, names)) + "); they are "
                                  "left out of Results.config", UserWarning, stacklevel=2)
                    config["params"]["filters"] = None
        if isinstance(config.get("optics"), dict):
            config["optics"] = Optics(**{k: _json_float(v) for k, v in config["optics"].items()})
        skipped = [tuple(t) for t in data.get("skipped", [])]
        return cls(rows, EvalConfig(**config), skipped=skipped,
                   raw_images=list(data.get("raw_images", [])),
                   dataset=str(data.get("dataset") or ""))

    def summary_markdown(self, digits=None):
        """Per pattern: a table of mean ± std per method and metric, best per column in bold."""
        s = self.summary()
        all_inf = {c for c, (n, _, kinds) in self.left_out().items() if n == 0
                   and kinds == ("+inf",)}
        fmt = dict(DIGITS)
        if digits is not None:
            if not isinstance(digits, dict):
                raise TypeError(f"digits: expected a dict of metric -> digits, got "
                                f"{type(digits).__name__}")
            for k, v in digits.items():
                self._known(k, "digits", ALL_METRICS)
                check_int(v, f"digits[{k!r}]", lo=0, hi=17)
            fmt = {**fmt, **digits}
        n_images = len(self.images())
        lines = [f"Mean ± std over {n_images} image(s); {self.label()}." if n_images != 1 else
                 f"The values of 1 image (no spread to show); {self.label()}.", ""]
        if self.skipped:
            lines[-1:] = [f"Skipped {len(self.skipped)} image(s) that could not be evaluated: "
                          + "; ".join(f"{n} ({why})" for n, why in self.skipped) + ".", ""]
        unranked = set()
        for p in self.config.patterns:
            lines.append(f"**{p}**")
            lines.append("")
            hdr = "| method | " + " | ".join(METRIC_LABELS[k] for k in self.config.metrics) + " |"
            lines += [hdr, "|---" * (len(self.config.metrics) + 1) + "|"]
            best = {}
            for k in self.config.metrics:
                means = [s[(p, m, k)][0] for m in self.config.methods]
                finite = [x for x in means if np.isfinite(x)]
                covered = {self._finite_images(p, m, k) for m in self.config.methods
                           if self.config.applies(p, m) and (p, m, k) not in all_inf}
                if finite and len(covered) == 1:
                    best[k] = max(finite) if HIGHER_IS_BETTER[k] else min(finite)
                elif finite:
                    # means over different images (a +inf left out of one cell) do not rank:
                    # a method worse on every image had been marked best
                    unranked.add(k)
                if HIGHER_IS_BETTER[k] and any((p, m, k) in all_inf for m in self.config.methods):
                    best[k] = math.inf            # a +inf PSNR on every image is the best
            for m in self.config.methods:
                cells = []
                for k in self.config.metrics:
                    mean, std, _ = s[(p, m, k)]
                    cell = f"{mean:.{fmt[k]}f}" + (f" ± {std:.{fmt[k]}f}" if np.isfinite(std)
                                                   else "")
                    if (p, m, k) in all_inf:      # a perfect image everywhere: no mean to show
                        cell, mean = "inf", math.inf
                    cells.append("n/a" if not self.config.applies(p, m) else
                                 f"**{cell}**" if best.get(k) == mean else cell)
                lines.append(f"| {self._label(p, m)} | " + " | ".join(cells) + " |")
            lines.append("")
        note = self.nonfinite_note()
        if note:
            if unranked:
                note += (" No best is marked for " + _names([METRIC_LABELS[k] for k in
                                                              self.config.metrics
                                                              if k in unranked])
                         + " where the means cover different images.")
            lines += [note, ""]
        if self.config.not_applicable():
            lines += [self.notes(), ""]
        base = self.baseline()
        others = [m for m in self.config.methods if m != base]
        if others and len(self.images()) > 1:
            lines += [f"Paired differences to {METHOD_LABELS.get(base, base)}, image by image: "
                      "mean [95 % confidence interval] (the interval of the difference, not the "
                      "spread of the images).", ""]
            for p in self.config.patterns:
                paired = [m for m in others
                          if self.config.applies(p, m) and self.config.applies(p, base)]
                if not paired:              # a table of no row had been printed (n/a: notes)
                    continue
                lines += [f"**{p}**", "",
                          "| method | " + " | ".join(f"Δ {METRIC_LABELS[k]}"
                                                     for k in self.config.metrics) + " |",
                          "|---" * (len(self.config.metrics) + 1) + "|"]
                for m in paired:
                    cells = []
                    for k in self.config.metrics:
                        diffs, mean, lo, hi = self.paired(p, m, k, base)
                        f = fmt[k]
                        # no image on which both are finite: no difference to show; one:
                        # no interval (lo = hi = the mean had read as an exact difference)
                        cells.append("—" if diffs.size == 0 else
                                     f"{mean:+.{f}f} (1 image, no interval)"
                                     if diffs.size == 1 else
                                     f"{mean:+.{f}f} [{lo:+.{f}f}, {hi:+.{f}f}]")
                    lines.append(f"| {self._label(p, m)} | " + " | ".join(cells) + " |")
                lines.append("")
            note = self._paired_note(base, others)
            if note:
                lines += [note, ""]
        return "\n".join(lines)

    def image_markdown(self, image):
        """The paper's Table 3 layout for one image, with the paper's kodim09 values beside ours."""
        if not isinstance(image, str) or image not in self.images():
            raise ValueError(f"image: {image!r} is not in the results ({', '.join(self.images())})")
        lines = []
        for p in self.config.patterns:
            paper = PAPER_TABLE3.get(p, {}) if image.lower().startswith("kodim09") else {}
            lines += [f"**{p}** — {image}" + (" (paper's Table 3 in brackets)" if paper else ""),
                      "", "| metric | " + " | ".join(METHOD_LABELS.get(m, m)
                                                      for m in self.config.methods) + " |",
                      "|---" * (len(self.config.methods) + 1) + "|"]
            for i, k in enumerate(self.config.metrics):
                cells = []
                for m in self.config.methods:
                    v = [r["value"] for r in self.rows if r["image"] == image and r["pattern"] == p
                         and r["method"] == m and r["metric"] == k]
                    # the summary's decimals per metric (".4g" had mixed 35.6 with 38.78 and
                    # printed a perfect SSIM as 1); the paper's values as it prints them
                    cell = f"{v[0]:.{DIGITS[k]}f}" if v else "n/a"
                    if m in paper:
                        j = list(ALL_METRICS).index(k)
                        cell += f" ({paper[m][j]:.4g})"
                    cells.append(cell)
                lines.append(f"| {METRIC_LABELS[k]} | " + " | ".join(cells) + " |")
            lines.append("")
        return "\n".join(lines)

    def plain_table(self):
        """The summary as aligned plain text for the terminal."""
        s = self.summary()
        all_inf = {c for c, (n, _, kinds) in self.left_out().items() if n == 0
                   and kinds == ("+inf",)}
        w = max(len(METHOD_LABELS.get(m, m)) for m in self.config.methods) + 2
        out = []
        for p in self.config.patterns:
            n_images = len(self.images())
            out.append(f"{p}  ({n_images} image{'s' if n_images != 1 else ''}; {self.label()})")
            # a cell: the mean in 12, a space, the spread in 8 (its header right-aligned on it)
            out.append(" " * w + "".join(f"{METRIC_LABELS[k]:>21}" for k in self.config.metrics))
            for m in self.config.methods:
                cells = "".join(f"{'inf':>12}{'':9}" if (p, m, k) in all_inf else
                                f"{s[(p, m, k)][0]:>12.4f} " + (f"±{s[(p, m, k)][1]:<7.3f}"
                                                               if np.isfinite(s[(p, m, k)][1])
                                                               else " " * 8)
                                if self.config.applies(p, m) else f"{'n/a':>12}{'':9}"
                                for k in self.config.metrics)
                out.append(f"{METHOD_LABELS.get(m, m):<{w}}{cells}")
                if self.ir_estimated(p, m):
                    out.append(" " * w + self._label(p, m)[len(METHOD_LABELS.get(m, m)) + 1:])
            out.append("")
        note = self.nonfinite_note()
        if note:
            out += [note, ""]
        if self.config.not_applicable():
            out += [self.notes(), ""]
        return "\n".join(out)

    def notes(self):
        """One line per (pattern, method) the evaluation left out, and why ("" when none)."""
        return "\n".join(f"n/a: {METHOD_LABELS.get(m, m)} on {p}: {' '.join(str(why).split())}"
                         for (p, m), why in self.config.not_applicable().items())
