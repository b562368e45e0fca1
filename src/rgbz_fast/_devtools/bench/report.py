"""The text of ``rgbz-fast bench``'s result: the table of every case, the ToF section, the
colour chain and the peak memory."""

from __future__ import annotations

from ..timing import WARMUP_CALLS

__all__ = ["format_table", "format_tof", "format_chain", "format_simulate", "format_tof_isp",
           "QUICK_NOTE"]

#: what a quick run says instead of ratios and verdicts
QUICK_NOTE = "quick run: numbers not comparable, no verdict"


def _f(v, nd=1):
    if v is None:
        return "n/a"
    if v >= 100:
        return f"{v:.0f}"
    return f"{v:.{nd}f}"


def _ratio(r, key):
    """The paired ratio to OpenCV's ``key`` demosaic on all threads: 'median [IQR]' of the
    rounds' ratios (the median alone from a result without the IQR)."""
    med, iqr = r[f"vs_opencv_{key}_all"], r.get(f"vs_opencv_{key}_all_iqr")
    if med is None or iqr is None:
        return _f(med, 2)
    return f"{_f(med, 2)} [{_f(iqr[0], 2)}-{_f(iqr[1], 2)}]"


def format_table(res):
    """The human-readable report of :func:`run_benchmarks`'s result."""
    m = res["machine"]
    quick = res.get("quick", False)
    lines = ([QUICK_NOTE.upper()[:1] + QUICK_NOTE[1:] + " (a smoke test of a small frame)"]
             if quick else [])
    lines += [f"rgbz-fast {m.get('rgbz_fast', '?')} bench: frame {res['frame']['shape'][0]}x"
             f"{res['frame']['shape'][1]} (rows x cols, {res['frame']['pixels'] / 1e6:.1f} Mpix, "
             "uint16 11-bit),"
             f" median [IQR] of {res['repeat']} timed calls after "
             f"{res.get('warmup_calls', WARMUP_CALLS)} warm-up call per case, Mpix/s = frame "
             "pixels / s",
             f"machine: {m['cpu_model']}, {m['logical_cores']} logical cores "
             f"({m.get('usable_cores')} usable), OpenMP {'on' if m.get('openmp') else 'off'}, "
             f"{m.get('compiler', '')}; all threads = {res['workers_all']}; load average "
             f"{_load(m['loadavg_before'])} -> {_load(m['loadavg_after'])}"]
    head = ["kernel", "pattern", "precision", "1 thread", "all threads", "threads", "xNumPy",
            "xCV bil", "xCV EA"]
    if quick:
        head = head[:-3]
    rows = []
    for r in res["results"]:
        t1, ta = r["threads"]["1"], r["threads"]["all"]
        row = [r["name"], r["pattern"], r["precision"],
               f"{_f(t1['mpix_s'])} [{_f(t1['mpix_s_lo'])}-{_f(t1['mpix_s_hi'])}]",
               f"{_f(ta['mpix_s'])} [{_f(ta['mpix_s_lo'])}-{_f(ta['mpix_s_hi'])}]",
               str(ta.get("threads", res["workers_all"]))]
        if not quick:
            row += [_f(r["vs_numpy"]), _ratio(r, "bilinear"), _ratio(r, "ea")]
        rows.append(row)
    ocv = res["opencv"]
    if ocv is not None:
        for key, label in (("bilinear", "OpenCV Bayer bilinear"), ("ea", "OpenCV Bayer EA")):
            t1, ta = ocv[key]["1"], ocv[key]["all"]
            rows.append([label, "bayer", "uint16",
                         f"{_f(t1['mpix_s'])} [{_f(t1['mpix_s_lo'])}-{_f(t1['mpix_s_hi'])}]",
                         f"{_f(ta['mpix_s'])} [{_f(ta['mpix_s_lo'])}-{_f(ta['mpix_s_hi'])}]",
                         str(res["workers_all"])] + ([] if quick else ["", "", ""]))
    if res["results"] or ocv is not None:     # 'tof sites' alone: no kernel table
        w = [max(len(h), *(len(x[i]) for x in rows)) if rows else len(h)
             for i, h in enumerate(head)]
        lines.append("")
        lines.append("  ".join(h.ljust(n) for h, n in zip(head, w)))
        lines.append("  ".join("-" * n for n in w))
        lines += ["  ".join(c.ljust(n) for c, n in zip(x, w)) for x in rows]
        lines.append("")
        lines.append(f"threads: those of the 'all threads' column (at most "
                     f"{res['workers_all']}; a reconstruction or demosaic call takes one per "
                     "262,144 pixels at most).")
        if quick:
            lines.append(f"{QUICK_NOTE}: no speed ratios to NumPy or OpenCV and no target "
                         "verdicts; run without --quick (the 3000x4000 frame, rows x cols) "
                         "for them.")
        else:
            lines.append(
                "xNumPy: our 1-thread speed / the NumPy reference's (timed on a "
                f"{res['numpy_reference']['crop'][0]}x{res['numpy_reference']['crop'][1]} crop"
                + ("" if res["numpy_reference"]["available"] else "; reconstruction: n/a "
                   "without --numpy-reference FILE") + "). xCV: our all-threads speed / OpenCV's "
                "on the same-size Bayer frame, the median [IQR] of the per-round ratios of "
                "calls alternated with ours (so that a change of load hits both; the OpenCV "
                "rows above are timed on their own)" + ("" if ocv else " (cv2 not installed: n/a)")
                + ".")
    t = res["targets"]
    if "sg_mask1_float32_all_threads_mpix_s" in t:
        if t["target_met"] is None:
            verdict = (f"no verdict: the target is defined on the {res['target_frame'][0]}x"
                       f"{res['target_frame'][1]} frame (--shape)")
        else:
            verdict = "met" if t["target_met"] else "NOT met"
        s = (f"target: SG Mask1 float32 all threads {t['sg_mask1_float32_all_threads_mpix_s']:.1f}"
             f" Mpix/s vs >= {t['target_mpix_s']:.0f}: {verdict}")
        if "opencv_ea_all_threads_mpix_s" in t:
            s += (f"; OpenCV EA {t['opencv_ea_all_threads_mpix_s']:.0f} Mpix/s on its own; "
                  f"alternated with it we run at {t['fraction_of_opencv_ea']:.3f} of its "
                  "speed (median of the rounds" + (
                      "" if t.get("fraction_of_opencv_ea_iqr") is None else
                      ", IQR {:.3f}-{:.3f}".format(*t["fraction_of_opencv_ea_iqr"])) + ")")
        lines.append(s)
    tof = res.get("tof_sites")
    if tof:
        lines += ["", format_tof(tof, res.get("verdict", True))]
    if res.get("colour_chain"):
        lines += ["", format_chain(res["colour_chain"])]
    if res.get("simulate"):
        lines += ["", format_simulate(res["simulate"])]
    if res.get("tof_isp"):
        lines += ["", format_tof_isp(res["tof_isp"])]
    mem = res["memory"]
    if mem:
        if "error" in mem:
            lines.append(f"memory: n/a ({mem['error']})")
        else:
            for mode, label in (("array", "a plain array (its values checked)"),
                                ("rawframe", "a frame (checked when it was made)")):
                m = mem[mode]
                lines.append(
                    f"memory: reconstruct {mem['method']} {mem['pattern']} {mem['precision']}, "
                    f"{label}: peak RSS +{m['rss_growth'] / 2**20:.1f} MiB = "
                    f"{m['rss_growth_over_output']:.2f} x output ({m['out_bytes'] / 2**20:.1f} "
                    f"MiB), NumPy allocations peak {m['traced_peak'] / 2**20:.1f} MiB; input + growth ="
                    f" {m['peak_over_in_plus_out']:.3f} x (input + output) [budget 1.10: "
                    f"{'ok' if m['within_budget'] else 'OVER'}]")
    return "\n".join(lines)


def format_tof(tof, verdict=True):
    """The ToF section of the report (C vs NumPy, million measurements per second);
    ``verdict`` False: no target verdict (a frame other than the target's)."""
    lines = [f"ToF: demodulation + unwrapping of the {tof['n_sites']:,} Z measurements of a "
             f"{tof['frame_shape'][0]}x{tof['frame_shape'][1]} {tof['pattern']} frame "
             f"({len(tof['frequencies'])} frequencies x 4 taps, uint16), median [IQR] of "
             f"{tof['repeat']} timed runs after {tof.get('warmup_calls', WARMUP_CALLS)} warm-up, "
             "M measurements/s (timed in turn in one loop)"]
    rows = [("C fused, 1 thread", tof["c_1"]), (f"C fused, {tof['workers']} threads",
                                                 tof["c_all"]),
            (f"C demodulate + unwrap, {tof['workers']} threads", tof["c_stages_all"]),
            ("NumPy, the same algorithm vectorised", tof["numpy"])]
    w = max(len(r[0]) for r in rows)
    for label, t in rows:
        lines.append(f"  {label.ljust(w)}  {_f(t['msites_s'])} [{_f(t['msites_s_lo'])}-"
                     f"{_f(t['msites_s_hi'])}]  ({t['median_s']:.3f} s)")
    a = tof["agreement"]
    if tof["x_numpy_all"] is None:
        ratio = f"{QUICK_NOTE}; "
    else:
        ratio = (f"x NumPy: {tof['x_numpy_1']:.1f} (1 thread), {tof['x_numpy_all']:.1f} "
                 f"({tof['workers']} threads) vs >= {tof['target_x_numpy']:g}: "
                 + ((("met" if tof["target_met"] else "NOT met")) if verdict else
                    "no verdict (not the target frame)") + "; ")
    lines.append(f"  {ratio}C and NumPy agree: wrap counts "
                 f"{'identical' if a['wraps_equal'] else 'DIFFER'}, max |depth diff| "
                 f"{a['max_abs_depth_diff_m']:.1e} m, max |phase diff| "
                 f"{a['max_abs_phase_diff_rad']:.1e} rad")
    return "\n".join(lines)


def format_chain(ch):
    """The colour-chain section: the fused total, the reference's seconds per stage, the
    speed ratios over OpenCV's edge-aware demosaic."""
    h, w = ch["frame_shape"]

    def vs(key):
        v = ch.get(key)
        return "n/a (no cv2)" if v is None else f"{v:.3f}"
    lines = [f"colour chain: ColourISP.run on a {h}x{w} {ch['pattern']} frame "
             f"({ch['reconstruction']} {ch['precision']}, {ch['demosaic']}, "
             f"{ch['workers']} threads), median of {ch['repeat']} rounds",
             f"  fused (C passes)   {ch['fused_s']:.3f} s  x OpenCV EA {vs('vs_opencv_ea_fused')}"
             f"  (image {'identical to' if ch['identical'] else 'DIFFERS from'} the stages')",
             f"  stages (NumPy ref) {ch['total_s']:.3f} s  x OpenCV EA "
             f"{vs('vs_opencv_ea_stages')}, per stage:"]
    for k, v in ch["stages_s"].items():
        lines.append(f"    {k:<18} {v:.3f} s  {100 * v / ch['total_s']:5.1f} %")
    return "\n".join(lines)


def format_simulate(sim):
    """The simulate section: seconds per pattern, noise-free and noisy, and the targets."""
    h, w = sim["frame_shape"]
    lines = [f"simulate: the benchmark image with a depth plane, {h}x{w}, ToF 3 frequencies, "
             f"no optics, {sim['workers']} threads, median of {sim['repeat']} runs "
             f"(Scene from the 8-bit image: {sim['scene_s']:.3f} s, not included)"]
    for pattern, r in sim["patterns"].items():
        lines.append(f"  {pattern:<6} noise-free {r['noise_free']['median_s']:.3f} s (best "
                     f"{r['noise_free']['min_s']:.3f}), noisy {r['noisy']['median_s']:.3f} s "
                     f"(best {r['noisy']['min_s']:.3f})")
    for k, t in sim["targets"].items():
        verdict = ("no verdict (not the target frame)" if t["met"] is None
                   else "met" if t["met"] else "NOT met")
        lines.append(f"  target mask1 {k.replace('_', '-')} <= {t['target_s']:g} s: "
                     f"{t['seconds']:.3f} s, {verdict}")
    return "\n".join(lines)


def format_tof_isp(t):
    """The ToF ISP section: the guided and unguided ISP and upsample_depth, and the targets."""
    h, w = t["frame_shape"]
    lines = [f"ToF ISP: the simulate case's {t['pattern']} frame, {h}x{w}, {t['n_sites']} "
             f"measurements, {t['workers']} threads, median of {t['repeat']} rounds of the "
             f"guided ISP then upsample_depth of its result, then of {t['repeat']} unguided "
             f"calls (memory pool {t['memory_pool_limit'] / 2**20:.0f} MiB; "
             f"{100 * t['valid_share']:.1f} % valid, guided)"]
    for key, label in (("guided", "ToFISP().run(tof, guide=image)"),
                       ("unguided", "ToFISP().run(tof)")):
        r = t[key]
        lines.append(f"  {label:<32} {r['median_s']:.3f} s (best {r['min_s']:.3f})  "
                     f"{r['msites_s']:.1f} M measurements/s")
    r = t["upsample"]
    lines.append(f"  {'upsample_depth(result, image)':<32} {r['median_s']:.3f} s (best "
                 f"{r['min_s']:.3f})  {r['mpix_s']:.1f} Mpix/s")
    for k, g in t["targets"].items():
        verdict = ("no verdict (not the target frame)" if g["met"] is None
                   else "met" if g["met"] else "NOT met")
        unit = "Mpix/s" if k == "upsample" else "M measurements/s"
        lines.append(f"  target {k} >= {g['target']:g} {unit}: {g['rate']:.1f}, {verdict}")
    return "\n".join(lines)


def _load(v):
    return "n/a" if v is None else "/".join(f"{x:.2f}" for x in v)
