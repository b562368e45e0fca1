"""Reports of an evaluation: CSV, JSON, Markdown tables and figures (matplotlib, lazily)."""

from __future__ import annotations

import io
import os
import re

import numpy as np

from .._patterns import get_pattern
from .._validate import check_flag, check_path
from ..io._files import atomic_write_all
from ..reconstruction import NEEDS_TOF, reconstruct
from ._config import HIGHER_IS_BETTER, METHOD_LABELS, METRIC_LABELS, EvalConfig
from ._results import Results
from ._cache import _safe
from ._run import image_frames

__all__ = ["write_reports", "bar_chart", "paired_chart", "crop_figure", "auto_crop"]


def write_reports(results, out_dir, *, table_image=None, crop_source=None, crop_box=None,
                  plots=True):
    """Write results.csv, results.json, summary.md, a per-image table and the figures.

    The figures, per metric: ``bars_<metric>.png`` (mean ± std per method and
    pattern) and, with several methods and images, ``paired_<metric>.png``
    (each method minus the baseline, image by image; see
    :func:`paired_chart`). Returns the list of files written. The folder's
    ``reports.txt`` lists them; the files a previous run listed there and
    this one does not write are removed, so that a folder never mixes two
    runs (nothing else in it is touched: only a ``reports.txt`` that starts with
    the header this function writes is read, and only the names of the reports
    it makes, plain files in the folder, are removed). The files are written all or none:
    each to a temporary file first and renamed only when every one is written, so a full
    disk leaves the folder as the previous run left it. ``table_image`` defaults to kodim09
    when present, else the first image. ``crop_source`` (an ImageSource)
    adds a Fig. 21-like crop comparison.

    Raises
    ------
    TypeError
        ``results`` is not a :class:`Results`.
    ValueError
        ``results`` holds no row (an empty table has nothing to summarise;
        nothing is written, not even the folder), ``table_image`` is not
        one of its images, ``crop_box`` is not inside the crop source's
        image, or the folder holds a ``reports.txt`` that rgbz-fast did not
        write (it would be replaced; checked before anything is written).
    """
    plots = check_flag(plots, "plots")
    if not isinstance(results, Results):
        raise TypeError(f"results: expected Results, got {type(results).__name__}")
    if not results.rows:
        raise ValueError("results: no rows to report (an evaluation of no image); nothing "
                         "was written")
    images = results.images()
    if table_image is not None and (not isinstance(table_image, str)
                                    or table_image not in images):
        raise ValueError(f"table_image: {table_image!r} is not in the results "
                         f"({', '.join(images)})")
    if crop_box is not None:
        crop_box = _check_box(crop_box, name="crop_box")
    out = check_path(out_dir, "out_dir")
    previous = _previous_reports(out, "out_dir")       # a foreign reports.txt is refused here
    figure = None
    if plots and crop_source is not None:
        # made before anything is written: a crop_box outside its image is refused with the
        # folder as it was
        try:
            figure = crop_figure(crop_source, results.config, box=crop_box)
        except ValueError as exc:                        # the box is this call's crop_box
            if str(exc).startswith("box: "):
                raise ValueError("crop_" + str(exc)) from None
            raise
    # every report is made in memory first (the figures take most of the time), then the
    # previous run's files this one does not write are removed and the new ones written:
    # an interrupt while they were made left the new tables beside the old run's figures
    made = []

    def put(name, data):
        made.append((name, data))

    put("results.csv", results.to_csv())
    put("results.json", results.to_json())
    put("summary.md", "# Evaluation summary\n\n" + results.summary_markdown() + "\n")
    if table_image is None:
        table_image = next((i for i in images if i.lower() == "kodim09"), images[0])
    put(f"table_{_safe(table_image)}.md", results.image_markdown(table_image) + "\n")
    if plots:
        several = len(results.config.methods) > 1 and len(images) > 1
        for k in results.config.metrics:
            put(f"bars_{k}.png", bar_chart(results, k))
            if several:
                put(f"paired_{k}.png", paired_chart(results, k))
        if figure is not None:
            put(f"crops_{_safe(crop_source.name)}.png", figure)
    out.mkdir(parents=True, exist_ok=True)
    names = [name for name, _ in made]

    def remove_stale():
        for name in sorted(previous - set(names)):      # a previous run's, not rewritten
            stale = out / name
            if stale.is_file() and not stale.is_symlink():
                stale.unlink()

    # all or none: every report and the list written to temporary files first, then the
    # previous run's others removed and the new ones renamed into place, the list last. A
    # full disk at the fifth file had left four new reports beside the previous run's others
    # and its list (the set of two runs, H126); now the folder stays the previous run's
    atomic_write_all([(out / name, data) for name, data in made]
                     + [(out / MANIFEST, MANIFEST_HEAD + "".join(n + "\n" for n in names))],
                     before_renames=remove_stale)
    return [out / name for name in names]


#: the list of the files an evaluation wrote into its folder, so that the next run into
#: that folder removes those it does not write again (and nothing else)
MANIFEST = "reports.txt"
MANIFEST_HEAD = ("# The reports rgbz-fast evaluate wrote here. The next evaluation into this "
                 "folder\n# replaces them and removes those it does not write again.\n")


#: the names of the reports :func:`write_reports` makes: the fixed ones, and the tables,
#: charts and crop figures named after an image or a metric through ``_safe``
REPORT_NAMES = ("results.csv", "results.json", "summary.md")
REPORT_KINDS = (("table_", ".md"), ("bars_", ".png"), ("paired_", ".png"), ("crops_", ".png"))
#: the most of a manifest that is read (a few dozen names; a foreign file may be anything)
MANIFEST_MAX = 1 << 20


def _report_name(name):
    """Whether ``name`` is a name :func:`write_reports` gives a report: a plain file name
    (no separator, not absolute) of one of :data:`REPORT_KINDS`, its field as ``_safe``
    writes it. A field of dots is one too (an image ``...png`` gives ``table_...md``, a plain
    file name, which had been written and then never removed by the next run)."""
    if name in REPORT_NAMES:
        return True
    return any(name.startswith(head) and name.endswith(ext)
               and len(name) > len(head) + len(ext)
               and _safe(name[len(head):-len(ext)]) == name[len(head):-len(ext)]
               for head, ext in REPORT_KINDS)


def _previous_reports(out, name="out_dir"):
    """The report names the manifest of a previous run lists (plain file names in ``out`` of
    the kinds :func:`write_reports` makes; nothing else is ever removed), an empty set when
    there is no manifest; a ValueError naming ``name`` when ``out`` holds a ``reports.txt``
    that is not one (its first line is not :data:`MANIFEST_HEAD`'s): a user's file of that
    name had its lines taken as reports to delete, and would have been replaced."""
    path = out / MANIFEST
    if not os.path.lexists(path):
        return set()
    foreign = (f"{name}: {path} exists and was not written by rgbz-fast (it is not the list "
               f"of reports evaluate writes); move or rename it, or choose another {name}")
    if not path.is_file():                  # a folder, a FIFO, a device, a dangling link
        raise ValueError(foreign)
    head = MANIFEST_HEAD.splitlines(keepends=True)[0].encode("utf-8")
    try:
        with open(path, "rb") as f:
            if f.readline(len(head) + 1) != head:
                raise ValueError(foreign)
            text = f.read(MANIFEST_MAX).decode("utf-8", errors="replace")
    except OSError as exc:
        raise ValueError(f"{name}: {path} cannot be read ({exc.strerror or exc}); it lists "
                         f"the reports a previous run wrote there") from None
    names = {line.strip() for line in text.splitlines()}
    return {n for n in names if n and not n.startswith("#") and _report_name(n)}


def check_reports_folder(out, name="out_dir"):
    """A ValueError naming ``name`` when the folder ``out`` holds a ``reports.txt`` that
    rgbz-fast did not write (:func:`write_reports` would refuse it after the evaluation;
    the command line checks it before)."""
    _previous_reports(check_path(out, name), name)


def _figure_png(fig, metadata=None):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight", metadata=metadata)
    return buf.getvalue()


class _Figures:
    """pyplot's ``subplots`` and ``figure`` for the library's figures, without pyplot: each a :class:`matplotlib.figure.Figure` on its own Agg canvas, which pyplot
    does not manage (nothing to close: it goes with its last reference). The figures had
    been pyplot's after ``matplotlib.use("Agg")``, which switched the backend of the
    caller's process: a notebook's or a Tk/Qt session's ``plt.show()`` then showed nothing."""

    @staticmethod
    def figure(figsize=None, **kwargs):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fig = Figure(figsize=figsize, **kwargs)
        FigureCanvasAgg(fig)
        return fig

    @classmethod
    def subplots(cls, nrows=1, ncols=1, *, figsize=None, **kwargs):
        fig = cls.figure(figsize=figsize)
        return fig, fig.subplots(nrows, ncols, **kwargs)



def _colours(methods):
    import matplotlib
    cycle = matplotlib.colormaps["tab10"]
    return {m: cycle(i % 10) for i, m in enumerate(methods)}


def _direction(metric):
    return "higher is better" if HIGHER_IS_BETTER[metric] else "lower is better"


def _limits(lo, hi):
    """Axis limits around [lo, hi] (the whiskers included), with a margin."""
    lo, hi = float(np.nanmin(lo)), float(np.nanmax(hi))
    pad = max(hi - lo, 1e-9) * 0.08
    return lo - pad, hi + pad


#: the mark of a method whose guide, the NIR, was estimated from the very RGB it had to
#: reconstruct (z_guided without a registered NIR image): the tables say it in the method's
#: label; a figure has no room for that sentence, so it marks the label and says it below
LEAK_MARK = "*"
#: the font size of the notes under a figure
NOTE_SIZE = 7.5


def _estimated_images(results, method):
    """The images on which ``method`` was guided by a NIR estimated from the RGB, on any
    pattern (:meth:`Results.ir_estimated`)."""
    return list(dict.fromkeys(i for p in results.config.patterns
                              for i in results.ir_estimated(p, method)))


def _chart_labels(results, methods):
    """({method: label}, notes) of a chart: a method guided by a NIR estimated from the RGB is
    marked :data:`LEAK_MARK` and a note says what the mark means, as the tables' label does
    (the figures had shown z_guided's leaked result as the best method, unmarked)."""
    labels, notes = {}, []
    n = len(results.images())
    for m in methods:
        label = METHOD_LABELS.get(m, m)
        est = _estimated_images(results, m)
        if est:
            notes.append(f"{LEAK_MARK} {label}: NIR estimated from the RGB on {len(est)} of {n} "
                         "images: its guide leaks the answer, not evidence (measure it on "
                         "registered RGB + NIR pairs)")
            label += LEAK_MARK
        labels[m] = label
    return labels, notes


def _chars(inches, fontsize, em=0.6):
    """About how many characters of ``fontsize`` points fit in ``inches`` (DejaVu Sans: 0.6 em
    a character of text, 0.72 of a tile's capitals)."""
    return max(8, int(inches * 72 / (em * fontsize)))


def _wrap(text, chars):
    """``text`` broken into lines of at most ``chars`` characters (its own line breaks kept)."""
    import textwrap

    return "\n".join(textwrap.fill(line, chars, break_on_hyphens=False) or line
                     for line in text.split("\n"))


def _pattern_label(name, chars):
    """A pattern's name as a figure shows it: a custom tile (rows joined by '/', as long as
    ``ZRGRGRGR/BGBGBGBG/GRGRZRGR/BGBGBGBG``) broken after a '/' into lines of at most
    ``chars`` characters, so that it does not run into its neighbours' labels."""
    name = _shown_name(name)
    if len(name) <= chars or "/" not in name:
        return name
    lines = [""]
    for part in re.findall(r"[^/]+/?|/", name):
        if lines[-1] and len(lines[-1]) + len(part) > chars:
            lines.append("")
        lines[-1] += part
    return "\n".join(lines)


def _footnote(fig, lines, fontsize=NOTE_SIZE):
    """Notes under everything the figure's axes draw (their tick labels included), left-aligned
    with them and wrapped to the figure's width; the figures are saved with a tight box,
    which takes the notes in. Returns the Text (None without lines)."""
    lines = [line for line in lines if line]
    if not lines:
        return None
    renderer = fig.canvas.get_renderer()
    boxes = [ax.get_tightbbox(renderer) for ax in fig.axes]
    inv = fig.transFigure.inverted()
    x0 = min(inv.transform((b.x0, b.y0))[0] for b in boxes)
    y0 = min(inv.transform((b.x0, b.y0))[1] for b in boxes)
    chars = max(_chars(fig.get_figwidth() * (1 - max(x0, 0.0)), fontsize), 64)
    return fig.text(max(x0, 0.0), y0 - 0.02, "\n".join(_wrap(line, chars) for line in lines),
                    ha="left", va="top", fontsize=fontsize, color="0.25")


def _run_line(results):
    """What the run was, for a chart's title: the dataset's name (when known) and the tables'
    header (:meth:`Results.label`: noise, bit depth, demosaic...)."""
    name = _shown_name(results.dataset)
    return f"{name}: {results.label()}" if name else results.label()


def _not_applicable_note(results, pairs):
    """The note of the (pattern, method) slots a chart marks n/a ("" when none)."""
    if not pairs:
        return ""
    return ("n/a: " + "; ".join(f"{METHOD_LABELS.get(m, m)} on {p}" for p, m in pairs)
            + " (the method does not apply to the pattern: the reason is in summary.md)")


def bar_chart(results, metric):
    """Fig. 20-like chart: mean per method and pattern, ±1 std over the images (PNG bytes).

    Points with whiskers rather than bars, since a bar's length from an
    arbitrary axis floor means nothing for a PSNR; the axis spans the
    whiskers, so none is cut, and the legend sits beside the plot. The
    spread is that of the images (it shows how hard they are, not how sure
    the ranking is): :func:`paired_chart` shows the latter. The title says the
    run's settings (:meth:`Results.label`); a slot without a point says why
    ("n/a", "all +inf"), and notes under the plot say what the tables say
    beside the numbers (n/a, z_guided's guide estimated from the RGB, marked
    ``*``).
    """
    return _figure_png(_bar_figure(*_chart_inputs(results, metric)))


def _chart_inputs(results, metric):
    """(results, metric) of a chart, checked: a metric the results do not hold drew an
    empty chart or failed inside matplotlib."""
    if not isinstance(results, Results):
        raise TypeError(f"results: expected Results, got {type(results).__name__}")
    results._known(metric, "metric", results.config.metrics)
    return results, metric


def _bar_figure(results, metric):
    from matplotlib.transforms import blended_transform_factory

    plt = _Figures
    s = results.summary()
    cfg = results.config
    colours = _colours(cfg.methods)
    labels, notes = _chart_labels(results, cfg.methods)
    nm = len(cfg.methods)
    fig, ax = plt.subplots(figsize=(2.2 + 0.55 * nm * len(cfg.patterns), 3.6))
    lows, highs, empty = [], [], []
    for j, m in enumerate(cfg.methods):
        x = np.arange(len(cfg.patterns)) + (j - (nm - 1) / 2) * 0.8 / nm
        mean = np.array([s[(p, m, metric)][0] for p in cfg.patterns])
        std = np.array([s[(p, m, metric)][1] for p in cfg.patterns])
        ax.errorbar(x, mean, yerr=std, fmt="o", ms=6, capsize=4, lw=1.4, color=colours[m],
                    label=labels[m])
        lows.append(mean - std)
        highs.append(mean + std)
        empty += [(xi, p, m) for xi, p, v in zip(x, cfg.patterns, mean) if not np.isfinite(v)]
    if np.isfinite(np.concatenate(lows)).any():
        ax.set_ylim(*_limits(np.concatenate(lows), np.concatenate(highs)))
    # a slot with no point says why: the method does not apply to the pattern (the tables'
    # n/a), or every value is +inf (a perfect reconstruction: no finite mean); an empty slot
    # had read as a method that was forgotten
    left = results.left_out()
    slot = blended_transform_factory(ax.transData, ax.transAxes)
    na = []
    for xi, p, m in empty:
        if not cfg.applies(p, m):
            text = "n/a"
            na.append((p, m))
        elif left.get((p, m, metric), (1, 0, ()))[2] == ("+inf",):
            text = "all +inf"
        else:
            text = "no value"
        ax.text(xi, 0.03, text, transform=slot, rotation=90, ha="center", va="bottom",
                fontsize=7, color=colours[m])
    chars = _chars(0.55 * nm, 10, em=0.72)              # a pattern's slot, at the ticks' size
    ax.set_xticks(np.arange(len(cfg.patterns)), [_pattern_label(p, chars) for p in cfg.patterns])
    ax.set_xlim(-0.6, len(cfg.patterns) - 0.4)
    ax.set_ylabel(METRIC_LABELS[metric])
    # a mean over fewer images than the results hold (a PSNR of +inf left out) is said
    n_left = sum(1 for (_, _, k) in left if k == metric)
    n_images = len(results.images())
    head = (f"mean ± 1 std over {n_images} image(s)" if n_images != 1 else
            "1 image, no spread")
    # the second line: what the tables' header says the numbers are (noise, bit depth,
    # demosaic...): two runs differing in those had given charts of the same text
    head = f"{METRIC_LABELS[metric]}: {head} ({_direction(metric)})"
    ax.set_title(head + "\n" + _wrap(_run_line(results), max(_chars(fig.get_figwidth(), 9),
                                                            len(head)))
                 + (f"\n{n_left} mean(s) leave out infinite values: see summary.md" if n_left
                    else ""), fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    ax.grid(axis="y", alpha=0.3)
    _footnote(fig, notes + [_not_applicable_note(results, na)])
    return fig


def paired_chart(results, metric, baseline=None):
    """Each method minus the baseline, image by image, with the 95 % interval of the mean (PNG).

    One panel per pattern; a grey dot per image, the mean difference with
    its confidence interval in the method's colour, and the zero line (no
    difference). Paired differences remove what the images contribute, so a
    method that is better on every image shows it even when the images'
    spread dwarfs the gain. The dots are counted as drawn: an image on which
    either method is not finite (a PSNR of +inf) has none, and a note says so;
    n/a and z_guided's estimated guide are said as in :func:`bar_chart`.
    """
    results, metric = _chart_inputs(results, metric)
    if baseline is not None:
        results._known(baseline, "baseline", results.config.methods)
    return _figure_png(_paired_figure(results, metric, baseline))


def _paired_figure(results, metric, baseline=None):
    plt = _Figures
    cfg = results.config
    base = baseline or results.baseline()
    others = [m for m in cfg.methods if m != base]
    if not others:
        raise ValueError(f"baseline: {base!r} is the only method; nothing to compare")
    colours = _colours(cfg.methods)
    labels, notes = _chart_labels(results, cfg.methods)
    fig, axes = plt.subplots(1, len(cfg.patterns), sharey=True, squeeze=False,
                             figsize=(1.2 + 0.75 * len(others) * len(cfg.patterns) + 0.8, 3.8))
    lo_all, hi_all = [0.0], [0.0]
    rng = np.random.default_rng(0)                    # the jitter of the dots, reproducible
    n_images = len(results.images())
    drawn, short, na = set(), [], []          # dots per panel slot; slots with images left out

    def images_of(p, m):
        return {r["image"] for r in results.rows if r["pattern"] == p and r["method"] == m
                and r["metric"] == metric}

    for ax, p in zip(axes[0], cfg.patterns):
        for i, m in enumerate(others):
            if not (cfg.applies(p, m) and cfg.applies(p, base)):
                # the tables' n/a: a tick with nothing above it had read as a method forgotten
                ax.text(i, 0.03, "n/a", transform=ax.get_xaxis_transform(), rotation=90,
                        ha="center", va="bottom", fontsize=7, color=colours[m])
                na.append((p, m if cfg.applies(p, base) else base))
                continue
            diffs, mean, lo, hi = results.paired(p, m, metric, base)
            total = len(images_of(p, m) & images_of(p, base))
            drawn.add(diffs.size)
            if diffs.size < total:
                short.append((p, m, diffs.size, total))
            if diffs.size:
                ax.plot(i + rng.uniform(-0.18, 0.18, diffs.size), diffs, ".", ms=4,
                        color="0.55", alpha=0.7, zorder=1)
                ax.errorbar([i], [mean], yerr=[[mean - lo], [hi - mean]], fmt="D", ms=6,
                            capsize=5, lw=1.8, color=colours[m], zorder=3)
                lo_all += [diffs.min(), lo]
                hi_all += [diffs.max(), hi]
            else:
                ax.text(i, 0.03, "no finite Δ", transform=ax.get_xaxis_transform(),
                        rotation=90, ha="center", va="bottom", fontsize=7, color=colours[m])
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xticks(range(len(others)), [labels[m] for m in others],
                      rotation=30, ha="right", fontsize=8)
        ax.set_xlim(-0.6, len(others) - 0.4)
        # a custom tile's long name broken at its '/': the panels' titles had run together
        ax.set_title(_pattern_label(p, _chars(0.75 * len(others), 9, em=0.72)), fontsize=9)
        ax.grid(axis="y", alpha=0.3)
    axes[0][0].set_ylim(*_limits(lo_all, hi_all))
    unit = METRIC_LABELS[metric].split("(")[-1].rstrip(")") if "(" in METRIC_LABELS[metric] \
        else ""
    name = METRIC_LABELS[metric].split(" (")[0]
    base_label = labels[base]
    axes[0][0].set_ylabel(f"Δ {name} vs {base_label}" + (f" ({unit})" if unit else ""))
    # the count of the dots is the dots drawn: an image on which either method is not finite
    # (a PSNR of +inf) has no difference, and the title had counted it all the same
    if not short:
        dots = f"dots = images ({n_images})"
    elif len(drawn) == 1:
        dots = f"dots = images ({min(drawn)} of {n_images}: see the note)"
    else:
        dots = f"dots = images (of {n_images}: see the note)"
    # two lines: one line of this length ran off a two-mask figure; the third what the
    # tables' header says the numbers are (noise, bit depth, demosaic...)
    head = (f"{name}, each method minus {base_label} on the same image "
            f"({_direction(metric)})\n{dots}, diamond = mean with 95 % confidence interval")
    width = max(_chars(fig.get_figwidth(), 9), *(len(line) for line in head.split("\n")))
    fig.suptitle(head + "\n" + _wrap(_run_line(results), width), fontsize=9)
    fig.tight_layout()
    if short:
        notes.append("Left out: " + "; ".join(
            f"{labels[m]} on {_shown_name(p)}: {total - n} of {total} images" for p, m, n, total
            in short) + " (either method is not finite there: a PSNR is +inf where the test "
            "image equals its reference; see summary.md)")
    _footnote(fig, notes + [_not_applicable_note(results, list(dict.fromkeys(na)))])
    return fig


def _shown_name(name):
    """An image name as a figure (or any text) can show it: a lone surrogate -- the byte of a
    file name that is not UTF-8, b"caf\\xe9.png" being "caf\\udce9" -- escaped as the text
    reports escape it (:func:`rgbz_fast.io.atomic_write`: ``caf\\udce9``). matplotlib's
    text layout refused the surrogate, and with it every report after the evaluation."""
    return name.encode("utf-8", "backslashreplace").decode("utf-8")


#: the PNG text key of the crop figure's region
CROP_KEY = "rgbz-fast crop"


def auto_crop(reference, tests, size):
    """(row, col, size, size): the crop of the figure, where the methods' errors show.

    Among the ``size`` x ``size`` windows that show structure -- the detail
    of the reference, its gradient after a blur of 1.5 pixels that keeps
    edges and drops pixel noise, at least the median window's -- and are not
    dark (mean above a quarter of the brightest window's), the one where the
    methods differ most from the reference. Dark, flat areas are left out:
    there the error is the sensor's noise, amplified by the sRGB gamma, and
    the crop would show nothing. A flat image falls back to its most
    detailed window.
    """
    from scipy.ndimage import gaussian_filter, sobel, uniform_filter

    ref = np.asarray(reference, np.float64)
    luma = ref.mean(axis=2)
    err = sum(np.abs(np.asarray(t, np.float64) - ref).sum(axis=2) for t in tests)
    smooth = gaussian_filter(luma, 1.5)
    detail = np.hypot(sobel(smooth, 0), sobel(smooth, 1))
    # window means, indexed by the window's top-left pixel
    h = ref.shape[0] - size + 1
    w = ref.shape[1] - size + 1
    c = size // 2

    def means(a):
        return uniform_filter(a, size, mode="nearest")[c:c + h, c:c + w]

    e, d, lum = means(err), means(detail), means(luma)
    ok = (d >= np.median(d)) & (lum >= 0.25 * lum.max())
    score = np.where(ok, e, -np.inf) if ok.any() else d
    y0, x0 = np.unravel_index(np.argmax(score), score.shape)
    return int(y0), int(x0), size, size


def _check_box(box, shape=None, name="box"):
    """A crop box: four integers (row, col, rows, cols), the sizes >= 1, inside an image of
    ``shape`` when given; a TypeError or ValueError naming ``name`` otherwise."""
    from .._validate import as_list, check_int

    box = as_list(box, name, "(row, col, rows, cols)")
    if len(box) != 4:
        raise TypeError(f"{name}: expected (row, col, rows, cols), got {box!r:.40}")
    y0, x0, h, w = (check_int(v, f"{name}[{i}]", lo=0 if i < 2 else 1)
                    for i, v in enumerate(box))
    if shape is not None and (y0 + h > shape[0] or x0 + w > shape[1]):
        raise ValueError(f"{name}: ({y0}, {x0}, {h}, {w}) is not inside the "
                         f"{shape[0]}x{shape[1]} image")
    return y0, x0, h, w


def crop_figure(source, config, box=None, size=64):
    """Fig. 21-like comparison: where the crop is, then the reference and each method (PNG).

    The left column shows the whole reference image with the crop outlined;
    each row then shows the crop, enlarged with no smoothing, for one
    pattern: the reference and every method. ``box`` (row, col, rows, cols)
    places the crop; by default :func:`auto_crop` chooses a ``size`` x
    ``size`` one on the first pattern, where the methods' errors show.
    """
    from .._validate import check_int, merge_params
    from ..io import ImageSource

    if not isinstance(source, ImageSource):
        raise TypeError(f"source: expected an ImageSource, got {type(source).__name__}")
    config = merge_params(EvalConfig, config, name="config")
    size = check_int(size, "size", lo=1)
    if box is not None:
        box = _check_box(box)
    plt = _Figures
    from matplotlib.patches import Rectangle

    img = source.load()
    # the registered NIR image when there is one, as the evaluation takes it (the crops had
    # shown z_guided on a NIR estimated from the RGB whatever the source held)
    nir = source.load_nir() if config.needs_tof else None
    chain = config.colour_isp()
    tiles = []
    leaked = []                                 # methods whose guide was estimated from the RGB
    for pname in config.patterns:
        frame, ref_cfa = image_frames(img, get_pattern(pname), config, nir=nir)
        estimated = frame.tof is not None and bool(frame.tof.meta.get("ir_estimated"))
        bayer, bd = frame.pattern.bayer_phase, frame.bit_depth
        ref, st = chain.render(ref_cfa, bayer, bit_depth=bd, return_stages=True)
        row = [("reference", ref)]
        for m in config.methods:
            label = METHOD_LABELS.get(m, m)
            if not config.applies(pname, m):     # a grey tile where the method does not apply
                row.append((f"{label} (n/a)", np.full_like(ref, 128)))
                continue
            if estimated and m in NEEDS_TOF:     # marked, and said under the figure
                leaked.append(label)
                label += LEAK_MARK
            out = reconstruct(frame, m, params=config.params_for(m))
            row.append((label, chain.render(out, bayer, bit_depth=bd, gains=st["gains"])))
        tiles.append((pname, row))
    full = tiles[0][1][0][1]
    size = int(min(size, *full.shape[:2]))
    box = auto_crop(full, [t for _, t in tiles[0][1][1:]], size) if box is None else \
        _check_box(box, full.shape)
    y0, x0, h, w = box
    ncol = len(tiles[0][1])
    # a custom tile's long name broken at its '/' (a panel is 2 inches wide): the titles had
    # run into each other; the rows' titles take the room of their longest
    names = {pname: _pattern_label(pname, _chars(1.9, 8, em=0.72)) for pname, _ in tiles}
    titles = [[(names[pname] + (":\n" if "\n" in names[pname] else ": ") + label) if j
               else "reference" for j, (label, _) in enumerate(row)] for pname, row in tiles]
    lines = max(t.count("\n") + 1 for row in titles for t in row)
    # the overview column: the image's aspect, but never so narrow that it shows nothing
    wide = max(1.25 * full.shape[1] / full.shape[0], 1.4)
    extra = 0.16 * (lines - 1)                  # inches of each row's further title lines
    fig = plt.figure(figsize=(2.0 * (ncol + wide), (2.15 + extra) * len(tiles) + 0.4))
    # the panels' titles below the figure's title: 0.55 inch kept above the grid
    grid = fig.add_gridspec(len(tiles), ncol + 1, width_ratios=[wide] + [1] * ncol,
                            wspace=0.08, hspace=0.25 + extra / 1.9,
                            top=1 - (0.55 + extra) / fig.get_figheight())
    ax = fig.add_subplot(grid[:, 0])
    ax.imshow(full, interpolation="antialiased")
    ax.add_patch(Rectangle((x0 - 0.5, y0 - 0.5), w, h, fill=False, ec="red", lw=1.6))
    ax.set_title("reference, the crop in red", fontsize=8)
    ax.set_xticks([])
    ax.set_yticks([])
    for i, (pname, row) in enumerate(tiles):
        for j, (label, im) in enumerate(row):
            ax = fig.add_subplot(grid[i, j + 1])
            ax.imshow(im[y0:y0 + h, x0:x0 + w], interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            for sp in ax.spines.values():
                sp.set_edgecolor("red" if j == 0 else "0.6")
            ax.set_title(titles[i][j], fontsize=8)
    fig.suptitle(f"{_shown_name(source.name)}: crop rows {y0}:{y0 + h}, cols {x0}:{x0 + w}, "
                 "enlarged without smoothing", fontsize=9, y=1 - 0.1 / fig.get_figheight())
    if leaked:
        # the tables' caveat of z_guided without a registered NIR image, as the charts say it
        _footnote(fig, [f"{LEAK_MARK} {leaked[0]}: NIR estimated from this RGB image: its "
                        "guide leaks the answer, not evidence (measure it on registered RGB + "
                        "NIR pairs)"])
    # the region, readable by programs (a PNG text chunk): ROW,COL,ROWS,COLS
    return _figure_png(fig, {CROP_KEY: f"{y0},{x0},{h},{w}"})
