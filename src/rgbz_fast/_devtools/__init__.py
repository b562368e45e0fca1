"""The tooling layer: the engines of ``rgbz-fast bench``, ``opcount`` and ``tradeoff``, and
the figures of the commands.

Not imported by ``import rgbz_fast`` and not a public API. The engines measure
the library (speed beside OpenCV and NumPy: :mod:`.bench`; operations per
missing pixel beside the paper's Table 1: :mod:`.opcount`; the speed/accuracy
trade: :mod:`.tradeoff`) and return JSON-able results and their text; they
hold no command-line code (the commands in :mod:`rgbz_fast._cli` parse, write
and print). Every speed goes through the one timing loop of :mod:`.timing`;
:mod:`.plots` draws the figures (the only place that imports matplotlib). This
layer alone may load the counting build of the kernels (``_kernels_count``).
"""
