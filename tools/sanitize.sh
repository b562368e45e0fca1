#!/usr/bin/env bash
# Build the C kernels with AddressSanitizer + UndefinedBehaviorSanitizer and run the
# kernel tests on small frames (docs/reports/robustness.md, "Sanitizers").
#
# Everything lives outside the checkout's own environment: a separate virtual
# environment ($ASAN_VENV) and a separate meson build directory ($ASAN_BUILD_DIR);
# the development venv and ./build are never touched.
#
#   tools/sanitize.sh                  # build (if needed) and run the default selection
#   tools/sanitize.sh -k mask2         # extra pytest arguments are passed through
#   ASAN_REBUILD=1 tools/sanitize.sh   # force a rebuild of the package
#   RGBZ_SKIP_KNOWN_UB=1 tools/sanitize.sh   # leave out the inputs of known bug B10
#
# Any ASan/UBSan report aborts the run (halt_on_error) and is a real bug.
set -euo pipefail

REPO=$(cd "$(dirname "$0")/.." && pwd)
VENV=${ASAN_VENV:-/tmp/rgbz-asan-venv}
BUILD=${ASAN_BUILD_DIR:-/tmp/rgbz-asan-build}
PY=${PYTHON:-python3}

if [ ! -x "$VENV/bin/python" ]; then
    "$PY" -m venv "$VENV"
    "$VENV/bin/pip" install -q meson-python meson ninja cython numpy scipy scikit-image \
        colour-science colour-demosaicing imageio tifffile matplotlib tqdm pytest hypothesis
fi

if [ -n "${ASAN_REBUILD:-}" ] || ! "$VENV/bin/python" -c "import rgbz_fast" 2>/dev/null; then
    rm -rf "$BUILD"
    # b_lundef=false: a Python extension leaves the Python C API undefined at link time,
    # which meson's default -Wl,--no-undefined rejects once sanitizers are on.
    # float-cast-overflow is not part of -fsanitize=undefined: add it explicitly.
    "$VENV/bin/pip" install -q --no-build-isolation --no-deps --force-reinstall "$REPO" \
        -Cbuild-dir="$BUILD" \
        -Csetup-args=-Db_sanitize=address,undefined \
        -Csetup-args=-Db_lundef=false \
        -Csetup-args=-Dc_args=-fsanitize=float-cast-overflow \
        -Csetup-args=-Dbuildtype=debugoptimized
fi

ASAN_LIB=$(gcc -print-file-name=libasan.so)
# libstdc++ preloaded too: colour-science imports matplotlib, whose C++ extension throws
# exceptions; ASan's __cxa_throw interceptor needs the real one loaded before it is called
# (without it: "CHECK failed: asan_interceptors.cpp ... real___cxa_throw").
STDCXX_LIB=$(gcc -print-file-name=libstdc++.so.6)
LOGDIR=$(mktemp -d /tmp/rgbz-sanitize-logs.XXXXXX)
cd "$REPO"
# The tests of every C kernel on small frames (the Kodak crops are left out: they only add run
# time), and the robustness tests that drive the kernels with extreme values.
# --capture=sys: a sanitizer report is written to fd 2 by the runtime and would be lost
# in pytest's fd capture when the process aborts; it is also kept in $LOGDIR.
# `-p no:cacheprovider` keeps .pytest_cache out of the checkout.
status=0
env LD_PRELOAD="$ASAN_LIB $STDCXX_LIB" \
    ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:exitcode=99:log_path=$LOGDIR/asan" \
    UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=98:log_path=$LOGDIR/ubsan" \
    CI=1 \
    "$VENV/bin/python" -m pytest -p no:cacheprovider -q -x --capture=sys \
        tests/reconstruction/test_reconstruct.py -k "not kodak" \
        tests/reconstruction/test_learned.py tests/reconstruction/test_clip.py \
        tests/metrics/test_metric_kernels.py tests/isp/test_encode.py \
        tests/isp/test_demosaic.py tests/tof/test_filters.py tests/test_kernels.py \
        tests/test_extremes.py tests/test_properties.py tests/test_concurrency.py \
        "$@" || status=$?
if compgen -G "$LOGDIR/*" > /dev/null; then
    echo "=== sanitizer reports (exit status $status; 99 ASan, 98 UBSan) ===" >&2
    cat "$LOGDIR"/* >&2
    [ "$status" -eq 0 ] && status=1
fi
rm -rf "$LOGDIR"
exit "$status"
