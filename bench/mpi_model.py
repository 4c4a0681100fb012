#!/usr/bin/env python3
"""The N-node model of BENCHMARKS.md, "MPI (issue 23)": a model, not a measurement.

    T(N) = T0 + ceil(P / N) t_pass + T_pool(N)
    T_pool(N) = T_copy + 2 F (N - 1) / N / B    (N > 1; 0 for N = 1)

T0: start, scene load and acceleration structures (every node at once); t_pass: one pass (1 spp)
of the film on one node; P: passes to the target relmse, from relmse ~ c / P (c = relmse x spp
measured); T_pool: the reduce-scatter and gather of the film (F bytes of doubles): each rank
sends and receives about two films' worth over its link of B bytes/s, plus the copies in and out
of the film (T_copy, measured on this machine). Efficiency E(N) = T(1) / (N T(N)).
Usage: mpi_model.py T0 t_pass c T_copy F_bytes [B_bytes_per_s ...]
"""
import math
import sys

t0, t_pass, c, t_copy, film = (float(x) for x in sys.argv[1:6])
bandwidths = [float(x) for x in sys.argv[6:]] or [1.25e9, 12.5e9]
target = 1e-3
passes = c / target
print(f"passes to relmse {target:g}: {math.ceil(passes)} (c = {c:g}); one node: {t0 + math.ceil(passes) * t_pass:.0f} s")
for b in bandwidths:
    print(f"link {b / 1e9:g} GB/s:")
    t1 = t0 + math.ceil(passes) * t_pass
    for n in (1, 2, 16, 64, 256):
        pool = 0.0 if n == 1 else t_copy + 2 * film * (n - 1) / n / b
        render = math.ceil(passes / n) * t_pass  # whole passes: a node's share rounded up
        t = t0 + render + pool
        print(f"  {n:4d} nodes: {t:8.1f} s  (render {render:7.1f} s, pooling {pool:5.2f} s, start {t0:.1f} s)"
              f"  efficiency {t1 / (n * t):.2f}")
