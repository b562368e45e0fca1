"""Run the command line of another commit's package, made by
``tools/tof_unguided_paired.py --make COMMIT SO DIR`` (DIR/rgbz_old), beside this checkout's
extension: the "before" side of an end-to-end pair.

    python tools/time_command.py -n 3 --vs "python tools/old_cli.py DIR evaluate-depth" \\
        -- rgbz-fast evaluate-depth

The "before" side also imports this checkout's extension module first (as the paired tools
do, so that the two load side by side): a fraction of a second more than its own command.
"""
import sys

sys.path.insert(0, sys.argv[1])
import rgbz_fast._kernels  # noqa: E402,F401  (this extension first)
from rgbz_old._cli import main  # noqa: E402

sys.exit(main(sys.argv[2:]))
