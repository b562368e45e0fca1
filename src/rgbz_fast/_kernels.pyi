import numpy as np

NOPS: int
TOF_MAX_WRAPS: int
TOF_MAX_FREQS: int

def plan_layout() -> tuple[int, ...]: ...
def have_openmp() -> bool: ...
def max_threads() -> int: ...
def reconstruct(src: np.ndarray, dst: np.ndarray, precision: int, py: int, px: int,
                phase_map: np.ndarray, plans: np.ndarray, n_plans: int, sigma_floor: float,
                sigma_rel: float, edge_ratio: float, maxval: float, exp_mode: int, workers: int,
                opcounts: np.ndarray | None = ..., mask1_fast: int = ...,
                clip_level: float | None = ...) -> None: ...
def demosaic_malvar(src: np.ndarray, dst: np.ndarray, phase: np.ndarray, mode: int,
                    workers: int) -> bool: ...
def tof_depth(taps: np.ndarray, freqs: np.ndarray, weights: np.ndarray, max_range: float,
              depth: np.ndarray, residual: np.ndarray, wraps: np.ndarray,
              phase: np.ndarray | None = ..., amp: np.ndarray | None = ...,
              offset: np.ndarray | None = ..., workers: int = ...) -> None: ...
def tof_depth_iq(i: np.ndarray, q: np.ndarray, freqs: np.ndarray, weights: np.ndarray,
                 max_range: float, depth: np.ndarray, residual: np.ndarray, wraps: np.ndarray,
                 phase: np.ndarray | None = ..., amp: np.ndarray | None = ...,
                 workers: int = ...) -> bool: ...
def tof_demodulate(taps: np.ndarray, phase: np.ndarray, amp: np.ndarray, offset: np.ndarray,
                   workers: int, opcounts: np.ndarray | None = ...) -> None: ...
def tof_unwrap(phase: np.ndarray, freqs: np.ndarray, weights: np.ndarray, max_range: float,
               depth: np.ndarray, residual: np.ndarray, wraps: np.ndarray,
               workers: int) -> bool: ...
def tof_depth(taps: np.ndarray, freqs: np.ndarray, weights: np.ndarray, max_range: float,
              depth: np.ndarray, residual: np.ndarray, wraps: np.ndarray,
              phase: np.ndarray | None = ..., amp: np.ndarray | None = ...,
              offset: np.ndarray | None = ..., workers: int = ...) -> None: ...
def tof_depth_iq(i: np.ndarray, q: np.ndarray, freqs: np.ndarray, weights: np.ndarray,
                 max_range: float, depth: np.ndarray, residual: np.ndarray, wraps: np.ndarray,
                 phase: np.ndarray | None = ..., amp: np.ndarray | None = ...,
                 workers: int = ...) -> bool: ...
def tof_bilateral(z_re: np.ndarray, z_im: np.ndarray, var: np.ndarray, g_re: np.ndarray,
                  g_im: np.ndarray, g_var: np.ndarray, use: np.ndarray, row_px: np.ndarray,
                  col_px: np.ndarray, reach_rows: int, reach_cols: int, radius_px: int, inv_h2: float,
                  out_re: np.ndarray, out_im: np.ndarray, out_var: np.ndarray,
                  out_neff: np.ndarray, workers: int) -> None: ...
