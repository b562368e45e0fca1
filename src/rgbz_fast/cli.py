"""Command line interface: ``rgbz-fast``."""
import sys


def main(argv=None):
    print("rgbz-fast: CLI under construction", file=sys.stderr)
    return 0
