# rgbz_fast._kernels_count: the counted kernels and the constants of _kernels, over the counting
# C library (_kernels_common.pxi is the source both modules share).
from rgbz_fast._kernels import DEMOSAIC_MODES as DEMOSAIC_MODES
from rgbz_fast._kernels import EXP_MODES as EXP_MODES
from rgbz_fast._kernels import METHODS as METHODS
from rgbz_fast._kernels import NOPS as NOPS
from rgbz_fast._kernels import OP_CATEGORIES as OP_CATEGORIES
from rgbz_fast._kernels import PLAN_LIMITS as PLAN_LIMITS
from rgbz_fast._kernels import PRECISIONS as PRECISIONS
from rgbz_fast._kernels import TOF_MAX_FREQS as TOF_MAX_FREQS
from rgbz_fast._kernels import TOF_MAX_WRAPS as TOF_MAX_WRAPS
from rgbz_fast._kernels import counting_build as counting_build
from rgbz_fast._kernels import have_openmp as have_openmp
from rgbz_fast._kernels import learned as learned
from rgbz_fast._kernels import mask1_plan as mask1_plan
from rgbz_fast._kernels import max_threads as max_threads
from rgbz_fast._kernels import plan_layout as plan_layout
from rgbz_fast._kernels import reconstruct as reconstruct
from rgbz_fast._kernels import rgbz_demosaic_mode as rgbz_demosaic_mode
from rgbz_fast._kernels import rgbz_exp_mode as rgbz_exp_mode
from rgbz_fast._kernels import rgbz_method as rgbz_method
from rgbz_fast._kernels import rgbz_op as rgbz_op
from rgbz_fast._kernels import rgbz_precision as rgbz_precision
from rgbz_fast._kernels import rgbz_status as rgbz_status
from rgbz_fast._kernels import rgbz_type as rgbz_type
from rgbz_fast._kernels import tof_demodulate as tof_demodulate
from rgbz_fast._kernels import z_guided as z_guided
from rgbz_fast._kernels import z_guided_guide as z_guided_guide
