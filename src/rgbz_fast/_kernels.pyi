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
def learned(src: np.ndarray, dst: np.ndarray, precision: int, py: int, px: int,
            phase_map: np.ndarray, n_taps: np.ndarray, tap_dy: np.ndarray, tap_dx: np.ndarray,
            n_pairs: np.ndarray, pair_a: np.ndarray, pair_b: np.ndarray, str_thr: np.ndarray,
            coh_thr2: np.ndarray, w_f32: np.ndarray, w_f64: np.ndarray, radius: int,
            hash_radius: int, maxval: float, workers: int, wd_f32: np.ndarray | None = ...,
            wd_f64: np.ndarray | None = ..., opcounts: np.ndarray | None = ...) -> None: ...
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
