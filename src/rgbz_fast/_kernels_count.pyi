# rgbz_fast._kernels_count is _kernels.pyx built over the counting C library: same interface.
from rgbz_fast._kernels import *  # noqa: F401,F403
