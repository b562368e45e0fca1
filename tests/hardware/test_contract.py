"""The bad-input contract of rgbz_fast.hardware: rows of docs/reports/robustness.md
(``hardware.*``), run by the shared runner of ``tests/_contract.py``. The refusals of
``precision="fixed"`` and of FixedPointConfig are rows of the reconstruction contract, where
they live."""

from __future__ import annotations

from _contract import Row, api_tests, files  # noqa: F401
from rgbz_fast.hardware import hardware_cost

R = Row

ROWS = [
    R("hardware.hardware_cost-width", "hardware_cost(width=0)",
      lambda f: hardware_cost("mask1", "sg", width=0), ValueError,
      "width: expected an integer >= 1 and <= 16384, got 0"),
    R("hardware.hardware_cost-method", "hardware_cost('z_guided')",
      lambda f: hardware_cost("mask1", "z_guided"), ValueError,
      "method: expected one of 'bilinear', 'bi', 'edi_central', 'edi_line', 'sg', 'learned'"),
    R("hardware.hardware_cost-bit_depth", "hardware_cost(bit_depth=17)",
      lambda f: hardware_cost("mask1", "sg", bit_depth=17), ValueError,
      "bit_depth: expected 1..16 bits, got 17"),
    R("hardware.hardware_cost-no-z", "hardware_cost('bayer', 'sg')",
      lambda f: hardware_cost("bayer", "sg"), ValueError,
      "pattern: 'bayer_grbg' has no Z site; the model reconstructs the Z sites"),
    R("hardware.hardware_cost-register", "hardware_cost(mask2, register_bits=24)",
      lambda f: hardware_cost("mask2", "sg", fixed_point={"register_bits": 24}), ValueError,
      "register_bits: the register mean_product"),
]

test_api_contract = api_tests(ROWS)
