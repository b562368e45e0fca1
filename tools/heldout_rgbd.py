"""Two Middlebury scenes the ToF chain was never tuned on, as ``rgbz-fast evaluate-depth
--data`` folders: Books (2005, full size, like art) and Cloth1 (2006, half size). The section
"Measured: two scenes no default was chosen on" of docs/reports/isp.md.

    python tools/heldout_rgbd.py SOURCE OUT      # SOURCE: a checkout of the source repository
    rgbz-fast evaluate-depth --data OUT --sections scenes,upsample --seed 1

SOURCE is a checkout of ``omkarbhoite25/3D-Sensing-Sensor-Fusion`` at commit
``3e8594838eb99fe5537bff579b0860f9c2433908``, the repository ../shared/data/rgbd/SOURCE.md
names for the six scenes the project ships in its data folder; its Books and Cloth1 folders
hold the same files (Middlebury's ``view1.png``, ground-truth ``disp1.png`` and ``dmin.txt``).
Cloth1's ``disp1.png`` lies in ``Cloth/Cloth`` beside a ``view1.png`` byte for byte equal to
``Cloth/Cloth1/view1.png``, which is checked. Nothing is downloaded and nothing of it is
shipped: the files stay where OUT is (the terms are Middlebury's, see that SOURCE.md).
"""

import sys
from pathlib import Path

#: scene -> (rgb.png, disp1.png, dmin.txt) under SOURCE/Input_Images
SCENES = {"books": ("Books/Books/view1.png", "Books/Books/disp1.png", "Books/Books/dmin.txt"),
          "cloth1": ("Cloth/Cloth1/view1.png", "Cloth/Cloth/disp1.png",
                     "Cloth/Cloth1/dmin.txt")}
SAME = ("Cloth/Cloth/view1.png", "Cloth/Cloth1/view1.png")


def main(source, out):
    root = Path(source) / "Input_Images"
    files = [root / p for paths in SCENES.values() for p in paths] + [root / p for p in SAME]
    missing = [str(p) for p in files if not p.is_file()]
    if missing:
        sys.exit(f"SOURCE: not a checkout of the source repository (missing {missing[0]})")
    if (root / SAME[0]).read_bytes() != (root / SAME[1]).read_bytes():
        sys.exit(f"SOURCE: {SAME[0]} and {SAME[1]} differ: Cloth's disp1.png is not Cloth1's")
    for name, paths in SCENES.items():
        folder = Path(out) / name
        folder.mkdir(parents=True, exist_ok=True)
        for target, rel in zip(("rgb.png", "disp1.png", "dmin.txt"), paths):
            (folder / target).write_bytes((root / rel).read_bytes())
        (folder / "SOURCE.md").write_text(
            f"Middlebury scene {name}: rgb.png = Input_Images/{paths[0]}, disp1.png = "
            f"Input_Images/{paths[1]}, dmin.txt = Input_Images/{paths[2]} of "
            "omkarbhoite25/3D-Sensing-Sensor-Fusion (commit 3e85948); written by "
            "tools/heldout_rgbd.py of rgbz-fast.\n")
        print(f"{folder}: rgb.png, disp1.png, dmin.txt")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
