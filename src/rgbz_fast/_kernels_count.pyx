# cython: language_level=3, embedsignature=True
"""The bridge to the counting build of the C core (-DRGBZ_COUNT_OPS): the kernels whose
operations ``rgbz-fast opcount`` counts (reconstruct, learned, tof_demodulate), the plan
layout and the constants, as in :mod:`rgbz_fast._kernels` (_kernels_common.pxi). Each
wants its ``opcounts`` counters and runs on one thread. Loaded by
:mod:`rgbz_fast._devtools.opcount` only, so that no user's _kernels carries counting code.
"""

include "_kernels_common.pxi"
