"""The reconstruction in silicon: what the fixed-point streaming model costs.

``reconstruct(frame, method, precision="fixed", fixed_point=FixedPointConfig(...))``
runs the bit-exact fixed-point model (csrc/hw_recon.c; csrc/hw_learned.c for
``method="learned"``); :func:`hardware_cost`
counts what it takes in hardware: line buffers and their block RAMs, the
window, the latency, every operator with its width, the tables, the widths of
the registers, the operations per missing pixel. docs/guide/hardware.md
specifies the datapath and gives the numbers.
"""

from ..reconstruction._fixed import (ALL_FIXED_METHODS, FIXED_METHODS, LIMITS, Register,
                                     register_widths)
from ..reconstruction._fixed_config import TABLE_MODES, FixedPointConfig
from ._cost import BRAM18_BITS, FIELDS_USED, HardwareCost, Unit, bram18_blocks, hardware_cost

__all__ = ["hardware_cost", "HardwareCost", "Unit", "FixedPointConfig", "TABLE_MODES",
           "FIXED_METHODS", "ALL_FIXED_METHODS", "LIMITS", "Register", "register_widths",
           "bram18_blocks", "BRAM18_BITS", "FIELDS_USED"]
