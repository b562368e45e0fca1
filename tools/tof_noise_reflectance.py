"""The spread of the ToF depths against the ISP's predicted sigma on bright and dark flat walls,
near the sensor: where the taps' PRNU dominates the noise. The paragraph "Bright near walls"
of docs/reports/isp.md ("Measured: depth noise against the predicted sigma").

    python tools/tof_noise_reflectance.py        # under a minute

As ``rgbz-fast evaluate-depth --sections noise`` measures it (the standard deviation of the
valid depths away from the frame's border against the RMS of ``sigma``; the guided rows pool 4
frames, seeds 1000 apart), at NIR reflectance 0.9 and 0.2 instead of 0.5, default ToFSensor
and ToFISP, ``simulate(scene, pattern, seed=7 + 1000 j)``.
"""

import warnings

import numpy as np

from rgbz_fast.isp import ColourISP
from rgbz_fast.simulation import Scene, simulate
from rgbz_fast.tof import ToFISP

WALLS = (("mask1", (256, 256), (0.3, 0.5, 1.0)), ("mask2", (384, 384), (0.3, 0.5, 1.0, 2.0)))


def _ratio(isp, pattern, shape, d, rho, guided):
    errs, sig, valid = [], [], []
    for j in range(4 if guided else 1):
        scene = Scene(np.full(shape + (3,), 0.5), depth=np.full(shape, d),
                      ir_reflectance=np.full(shape, rho))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")              # a saturated near wall warns
            frame = simulate(scene, pattern, seed=7 + 1000 * j)
        res = isp.run(frame.tof, guide=ColourISP().run(frame) if guided else None)
        r, c = frame.tof.sites
        m = 6 * frame.tof.block * 2
        inner = (r >= m) & (r < shape[0] - m) & (c >= m) & (c < shape[1] - m) & res.valid
        errs.append(res.depth[inner] - d)
        sig.append(res.sigma[inner])
        valid.append(res.valid.mean())
    e, s = np.concatenate(errs), np.concatenate(sig)
    ratio = e.std() / np.sqrt(np.mean(s ** 2)) if e.size > 1 else np.nan
    return 100 * float(np.mean(valid)), ratio


def main():
    isp = ToFISP()
    print("| pattern | reflectance | distance m | valid % (none / colour) | ratio, no guide "
          "| ratio, guided |")
    print("|---|---|---|---|---|---|")
    for pattern, shape, distances in WALLS:
        for rho in (0.9, 0.2):
            for d in distances:
                v0, r0 = _ratio(isp, pattern, shape, d, rho, False)
                v1, r1 = _ratio(isp, pattern, shape, d, rho, True)
                print(f"| {pattern} | {rho} | {d} | {v0:.0f} / {v1:.0f} | {r0:.3f} | {r1:.3f} |")


if __name__ == "__main__":
    main()
