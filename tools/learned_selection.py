"""Model selection of the learned filters on CBSD68 alone (the table of docs/reports/results.md).

    python tools/learned_selection.py [PATTERN] [CBSD68_DIR]

Every fourth image of CBSD68 (17) is held out; each variant is fitted on the other 51
(rgbz_fast.reconstruction.train) and scored by the mean CFA PSNR on the Z sites of the
held-out images, noise-free and with the sensor model (the frames of rgbz-fast evaluate,
rgbz_fast.evaluation.image_frames). Kodak is not read. About 30 minutes on 2 cores.
"""

import dataclasses
import sys
from pathlib import Path

import numpy as np

from rgbz_fast.evaluation import EvalConfig, image_frames
from rgbz_fast.io import folder_dataset
from rgbz_fast.metrics import cfa_psnr
from rgbz_fast.reconstruction import reconstruct, train

#: (label, train() options, training frames: "clean", "noisy" or "both")
VARIANTS = (
    ("5x5 window, hash in 5x5", dict(radius=2, hash_radius=2), "clean"),
    ("7x7, hash in 5x5", dict(radius=3, hash_radius=2), "clean"),
    ("7x7, hash in 7x7 (the default)", dict(), "clean"),
    ("9x9, hash in 7x7", dict(radius=4, hash_radius=3), "clean"),
    ("7x7, 2 strengths x 2 coherences", dict(n_strength=2, n_coherence=2), "clean"),
    ("7x7, 4 strengths x 3 coherences", dict(n_strength=4), "clean"),
    ("7x7, prior 200 instead of 50", dict(prior=200.0), "clean"),
    ("7x7, fitted on noisy frames", dict(), "noisy"),
    ("7x7, fitted on noise-free + noisy", dict(), "both"),
)


def frames(sources, pattern, noise):
    out = []
    for i, src in enumerate(sources):
        cfg = EvalConfig(patterns=(pattern,), noise=noise, seed=i, metrics=("cfa_psnr",))
        frame, ref = image_frames(src.load(), pattern, cfg)
        out.append(dataclasses.replace(frame, reference=ref))
    return out


def score(filters, held):
    return float(np.mean([cfa_psnr(f.reference, reconstruct(f, "learned", filters=filters,
                                                            precision="float64"),
                                   f.z_mask, bit_depth=f.bit_depth) for f in held]))


def main():
    pattern = sys.argv[1] if len(sys.argv) > 1 else "mask1"
    folder = Path(sys.argv[2]) if len(sys.argv) > 2 else \
        Path(__file__).resolve().parents[1].parent / "shared" / "data" / "cbsd68"
    sources = folder_dataset(folder)
    held_idx = set(range(0, len(sources), 4))
    fit_src = [s for i, s in enumerate(sources) if i not in held_idx]
    held_src = [s for i, s in enumerate(sources) if i in held_idx]
    fit = {"clean": frames(fit_src, pattern, False), "noisy": frames(fit_src, pattern, True)}
    fit["both"] = fit["clean"] + fit["noisy"]
    held_clean, held_noisy = frames(held_src, pattern, False), frames(held_src, pattern, True)
    print(f"{pattern}: fitted on {len(fit_src)} CBSD68 images, scored on {len(held_src)}\n")
    print("| variant | held-out CFA PSNR, noise-free (dB) | noisy (dB) |\n|---|---|---|")
    for label, options, which in VARIANTS:
        f = train(fit[which], **options)
        print(f"| {label} | {score(f, held_clean):.2f} | {score(f, held_noisy):.2f} |",
              flush=True)


if __name__ == "__main__":
    main()
