"""The results of an evaluation: a tidy table, its summaries and its text renderings."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import asdict, dataclass, field

import numpy as np

from .._validate import as_list, check_int, merge_params
from ._config import (ALL_METRICS, HIGHER_IS_BETTER, METHOD_LABELS, METRIC_LABELS, PAPER_TABLE3,
                      EvalConfig)

__all__ = ["Results"]

#: the keys of one row of the table
_ROW_KEYS = {"image", "pattern", "method", "metric", "value"}


@dataclass
class Results:
    """A tidy table: one row per image, pattern, method and metric.

    ``skipped`` lists the ``(image, reason)`` of the images an evaluation with
    ``skip_bad=True`` left out.
    """

    rows: list
    config: EvalConfig = field(default_factory=EvalConfig)
    skipped: list = field(default_factory=list)

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

    def __len__(self):
        return len(self.rows)

    def _known(self, value, name, known):
        """``value`` when it is one of ``known`` (the names of these results), else a
        ValueError naming ``name``: an unknown name would select nothing, silently."""
        if not isinstance(value, str) or value not in known:
            raise ValueError(f"{name}: {value!r:.40} is not in the results (expected one of "
                             f"{', '.join(known)})")
        return value

    def values(self, pattern, method, metric):
        self._known(pattern, "pattern", self.config.patterns)
        self._known(method, "method", self.config.methods)
        self._known(metric, "metric", self.config.metrics)
        return np.array([r["value"] for r in self.rows if r["pattern"] == pattern
                         and r["method"] == method and r["metric"] == metric], dtype=float)

    def summary(self):
        """{(pattern, method, metric): (mean, std, n)}; infinite values are left out of the mean."""
        out = {}
        for p in self.config.patterns:
            for m in self.config.methods:
                for k in self.config.metrics:
                    v = self.values(p, m, k)
                    v = v[np.isfinite(v)]
                    out[(p, m, k)] = (float(v.mean()) if v.size else math.nan,
                                      float(v.std(ddof=1)) if v.size > 1 else 0.0, int(v.size))
        return out

    def images(self):
        return list(dict.fromkeys(r["image"] for r in self.rows))

    def ir_estimated(self, pattern, method):
        """The images on which ``method`` was guided by a NIR reflectance estimated from the RGB
        (rows marked ``"ir_estimated"``: :func:`~rgbz_fast.evaluation.evaluate_image`). Such
        a result has seen the colour it had to find: it is no evidence for the method."""
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
        self._known(pattern, "pattern", self.config.patterns)
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
        # Student's t quantile from scipy.special (scipy.stats.t.ppf's own function, without
        # the seconds of importing scipy.stats)
        from scipy.special import stdtrit

        half = float(stdtrit(diffs.size - 1, 0.975) * diffs.std(ddof=1)
                     / math.sqrt(diffs.size))
        return diffs, mean, mean - half, mean + half

    def baseline(self):
        """The method the paired differences are taken against: bilinear when it ran, else
        the first method."""
        return "bilinear" if "bilinear" in self.config.methods else self.config.methods[0]

    def to_csv(self):
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
        return json.dumps({"config": asdict(self.config), "rows": self.rows,
                           "skipped": [list(t) for t in self.skipped],
                           "not_applicable": [[p, m, " ".join(str(why).split())] for (p, m), why
                                              in self.config.not_applicable().items()]},
                          indent=1, default=str)

    def summary_markdown(self, digits=None):
        """Per pattern: a table of mean ± std per method and metric, best per column in bold."""
        s = self.summary()
        fmt = {"cfa_psnr": 2, "cpsnr": 2, "ssim": 4, "ms_ssim": 4, "zipper": 2}
        if digits is not None:
            if not isinstance(digits, dict):
                raise TypeError(f"digits: expected a dict of metric -> digits, got "
                                f"{type(digits).__name__}")
            for k, v in digits.items():
                self._known(k, "digits", ALL_METRICS)
                check_int(v, f"digits[{k!r}]", lo=0, hi=17)
            fmt = {**fmt, **digits}
        lines = [f"Mean ± std over {len(self.images())} image(s); {self.config.label()}.", ""]
        if self.skipped:
            lines[-1:] = [f"Skipped {len(self.skipped)} image(s) that could not be evaluated: "
                          + "; ".join(f"{n} ({why})" for n, why in self.skipped) + ".", ""]
        for p in self.config.patterns:
            lines.append(f"**{p}**")
            lines.append("")
            hdr = "| method | " + " | ".join(METRIC_LABELS[k] for k in self.config.metrics) + " |"
            lines += [hdr, "|---" * (len(self.config.metrics) + 1) + "|"]
            best = {}
            for k in self.config.metrics:
                means = [s[(p, m, k)][0] for m in self.config.methods]
                finite = [x for x in means if np.isfinite(x)]
                if finite:
                    best[k] = max(finite) if HIGHER_IS_BETTER[k] else min(finite)
            for m in self.config.methods:
                cells = []
                for k in self.config.metrics:
                    mean, std, _ = s[(p, m, k)]
                    cell = f"{mean:.{fmt[k]}f} ± {std:.{fmt[k]}f}"
                    cells.append("n/a" if not self.config.applies(p, m) else
                                 f"**{cell}**" if best.get(k) == mean else cell)
                lines.append(f"| {self._label(p, m)} | " + " | ".join(cells) + " |")
            lines.append("")
        if self.config.not_applicable():
            lines += [self.notes(), ""]
        base = self.baseline()
        others = [m for m in self.config.methods if m != base]
        if others and len(self.images()) > 1:
            lines += [f"Paired differences to {METHOD_LABELS.get(base, base)}, image by image: "
                      "mean [95 % confidence interval] (the interval of the difference, not the "
                      "spread of the images).", ""]
            for p in self.config.patterns:
                lines += [f"**{p}**", "",
                          "| method | " + " | ".join(f"Δ {METRIC_LABELS[k]}"
                                                     for k in self.config.metrics) + " |",
                          "|---" * (len(self.config.metrics) + 1) + "|"]
                for m in others:
                    if not (self.config.applies(p, m) and self.config.applies(p, base)):
                        continue
                    cells = []
                    for k in self.config.metrics:
                        _, mean, lo, hi = self.paired(p, m, k, base)
                        f = fmt[k]
                        cells.append(f"{mean:+.{f}f} [{lo:+.{f}f}, {hi:+.{f}f}]")
                    lines.append(f"| {self._label(p, m)} | " + " | ".join(cells) + " |")
                lines.append("")
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
                    cell = f"{v[0]:.4g}" if v else "n/a"
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
        w = max(len(METHOD_LABELS.get(m, m)) for m in self.config.methods) + 2
        out = []
        for p in self.config.patterns:
            out.append(f"{p}  ({len(self.images())} images; {self.config.label()})")
            out.append(" " * w + "".join(f"{METRIC_LABELS[k]:>20}" for k in self.config.metrics))
            for m in self.config.methods:
                cells = "".join(f"{s[(p, m, k)][0]:>12.4f} ±{s[(p, m, k)][1]:<7.3f}"
                                if self.config.applies(p, m) else f"{'n/a':>12}{'':8}"
                                for k in self.config.metrics)
                out.append(f"{METHOD_LABELS.get(m, m):<{w}}{cells}")
                if self.ir_estimated(p, m):
                    out.append(" " * w + self._label(p, m)[len(METHOD_LABELS.get(m, m)) + 1:])
            out.append("")
        if self.config.not_applicable():
            out += [self.notes(), ""]
        return "\n".join(out)

    def notes(self):
        """One line per (pattern, method) the evaluation left out, and why ("" when none)."""
        return "\n".join(f"n/a: {METHOD_LABELS.get(m, m)} on {p}: {' '.join(str(why).split())}"
                         for (p, m), why in self.config.not_applicable().items())
