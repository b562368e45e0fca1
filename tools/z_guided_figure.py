"""The crop figure of docs/guide/z_guided.md: SG, learned, z_guided, the truth and the amplitude.

    python tools/z_guided_figure.py [RGBNIR_DIR] [--pair 0019] [--pattern mask1]
        [--out docs/reports/figures/z_guided_crops.png]

One RGB-NIR pair through the targets' protocol (``Scene.from_rgb(rgb8, depth=np.full(shape,
2.0), ir_reflectance=nir8 / 255)``, ``simulate(scene, pattern, seed=1, noise=False)``), its
Z sites reconstructed by SG, the shipped learned filters and z_guided filters fitted on the
*other* pairs of its fold (5 folds as tools/z_guided_targets.py: the pair is out of the fit),
each CFA rendered by the library's colour chain with the reference's white balance; the
truth is the reference CFA through the same chain, the amplitude the Z pixels' NIR
amplitude (nearest-neighbour on the pixel grid). Crop: the 96 x 96 pixels around the site
where z_guided gains most over learned (mean squared error in a 32 x 32 box).
"""

import argparse
import sys
from pathlib import Path

import numpy as np

import rgbz_fast as rz
from rgbz_fast.evaluation import train_filters
from rgbz_fast.io import atomic_write, folder_dataset
from rgbz_fast.simulation import Scene, simulate

FOLDS = 5
CROP = 96


def main(argv=None):
    root = Path(__file__).resolve().parents[1]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folder", nargs="?", default=str(root.parent / "shared" / "data" / "rgbnir"))
    ap.add_argument("--pair", default="0019")
    ap.add_argument("--pattern", default="mask1")
    ap.add_argument("--out", default=str(root / "docs" / "reports" / "figures"
                                         / "z_guided_crops.png"))
    a = ap.parse_args(argv)
    ds = folder_dataset(a.folder)
    names = [s.name for s in ds]
    if a.pair not in names:
        sys.exit(f"--pair: {a.pair} is not a pair of {a.folder}")
    fold = names.index(a.pair) % FOLDS
    train_set = [s for i, s in enumerate(ds) if i % FOLDS != fold]
    print(f"fitting on {len(train_set)} pairs (fold {fold + 1} held out)", file=sys.stderr)
    zf = train_filters(train_set, a.pattern, z_guided=True, seed=1)
    src = ds[names.index(a.pair)]
    rgb = src.load()
    scene = Scene.from_rgb(rgb, depth=np.full(rgb.shape[:2], 2.0), ir_reflectance=src.load_nir())
    frame = simulate(scene, a.pattern, seed=1, noise=False)
    outs = {"SG": rz.reconstruct(frame, "sg"), "learned": rz.reconstruct(frame, "learned"),
            "z_guided": rz.reconstruct(frame, "z_guided", filters=zf)}
    ref = frame.reference.astype(np.float64)
    z = frame.z_mask
    err = {k: np.where(z, (v.astype(np.float64) - ref) ** 2, 0.0) for k, v in outs.items()}
    gain = err["learned"] - err["z_guided"]
    k = 32
    H, W = gain.shape
    box = gain[:H // k * k, :W // k * k].reshape(H // k, k, W // k, k).sum(axis=(1, 3))
    by, bx = np.unravel_index(np.argmax(box), box.shape)
    y0 = int(np.clip(by * k + k // 2 - CROP // 2, 0, H - CROP)) // 2 * 2
    x0 = int(np.clip(bx * k + k // 2 - CROP // 2, 0, W - CROP)) // 2 * 2
    sl = (slice(y0, y0 + CROP), slice(x0, x0 + CROP))
    isp = rz.ColourISP()
    bayer = frame.pattern.bayer_phase
    black = float(getattr((frame.meta or {}).get("colour_sensor"), "black_level", 0.0))
    truth, st = isp.render(frame.reference, bayer, bit_depth=frame.bit_depth,
                           black_level=black, return_stages=True)
    panels = []
    for name, cfa in outs.items():
        img = isp.render(cfa, bayer, bit_depth=frame.bit_depth, gains=st["gains"],
                         black_level=black)
        psnr = rz.metrics.cfa_psnr(frame.reference, cfa, z, bit_depth=frame.bit_depth)
        panels.append((f"{name} ({psnr:.2f} dB)", img[sl]))
    panels.append(("truth", truth[sl]))
    amp = frame.tof.to_frame(frame.tof.amplitude())
    P, Q = frame.pattern.period
    zr, zc = np.argwhere(frame.pattern.tile == 3).min(axis=0)
    grid = amp[zr::P, zc::Q]
    near = np.kron(grid, np.ones((P, Q)))[:H, :W]
    panels.append(("NIR amplitude (Z pixels)", near[sl]))
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(panels), figsize=(3 * len(panels), 3.4))
    for ax, (title, im) in zip(axes, panels):
        ax.imshow(im, cmap="gray" if im.ndim == 2 else None, interpolation="nearest")
        ax.set_title(title, fontsize=9)
        ax.axis("off")
    fig.suptitle(f"RGB-NIR pair {a.pair}, {a.pattern}, noise-free, rows {y0}-{y0 + CROP}, "
                 f"columns {x0}-{x0 + CROP}; z_guided fitted without this pair's fold",
                 fontsize=9)
    fig.tight_layout()
    import io

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=80)
    atomic_write(a.out, buf.getvalue())
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
