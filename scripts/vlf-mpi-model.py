#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The cost model of a distributed light field propagation (docs/vlf-mpi-cost-model.md), fitted
to the runs scripts/bench-vlf-mpi.sh measured (vlf-mpi-runs.csv in DIR), and its predictions for
8 to 1024 ranks and scenes of 1x to 1000x the Cornell box's surface area.

    python3 scripts/vlf-mpi-model.py DIR

Writes DIR/vlf-mpi-model-fit.csv (the fitted parameters), DIR/vlf-mpi-model.csv (the
predictions) and DIR/vlf-mpi.svg (measured seconds per run, predicted iteration time per rank
count). Plain Python (no plotting package): the chart is written as SVG by hand.
"""
import csv
import math
import statistics
import sys
from pathlib import Path

# Not measurable on one 2-core machine: a cluster interconnect (InfiniBand HDR class) and a
# parallel file system's bandwidth for one writer. Stated, not fitted; change them here.
LATENCY_S = 2e-6  # alpha: one message
LINK_BYTES_PER_S = 10e9  # beta: one rank's link
REDUCE_BYTES_PER_TEXEL = 12  # 3 floats (Distribution.h), plus 120 bytes per iteration
IMBALANCE_RATIO = 2.0  # costliest direction over the mean (greedy split: the last one placed)
BATCH_BYTES = 8 << 20  # a sender's snapshot batch (Distribution.cxx)
TEXTURE_BYTES_PER_TEXEL = 2 * 12 + 4  # total and unshot diffuse, capacity
BLOCK_BYTES_PER_TEXEL = 12  # one reflected-flux buffer per worker block, every rank
BLOCKS_HERE = 4  # worker blocks: 2 x the hardware threads (LightField.cxx), 2 cores here
BLOCKS_CLUSTER_NODE = 128  # the same on a 64-core cluster node, whatever the ranks per node


def load(directory):
    with open(directory / "vlf-mpi-runs.csv", newline="") as f:
        return list(csv.DictReader(f))


def runs_of(rows, ranks, threads):
    return [r for r in rows if r["ranks"] == str(ranks) and r["threads_per_rank"] == str(threads)]


def fit(rows):
    """Parameters per direction and per byte from the 1 x 1 and 2 x 1 runs. Wall seconds are
    taken as the least of the rounds (the load of a shared machine only adds), CPU seconds of
    own work as the median."""
    one, two = runs_of(rows, 1, 1), runs_of(rows, 2, 1)
    if not one or not two:
        raise SystemExit("vlf-mpi-model.py: need runs of 1 x 1 and 2 x 1 (scripts/bench-vlf-mpi.sh)")
    d = int(one[0]["directions"])
    iterations = int(one[0]["iterations"])
    col = lambda runs, c: [float(r[c]) for r in runs]
    shoot_cpu = statistics.median(col(one, "max_rank_iteration_work_cpu_s"))
    two_work = statistics.median(col(two, "max_rank_iteration_work_cpu_s"))
    maps = statistics.median(col(one, "max_rank_held_bytes"))
    shared = statistics.median(
        [float(r["max_rank_peak_rss_bytes"]) - float(r["max_rank_held_bytes"]) for r in one])
    shared_two = statistics.median(
        [float(r["max_rank_peak_rss_bytes"]) - float(r["max_rank_held_bytes"]) for r in two])
    every = int(one[0].get("snapshot_every") or 1)
    writes = -(-iterations // every)  # after every `every`-th iteration and the last
    write_one = min(col(one, "writes_s")) / writes
    write_two = min(col(two, "writes_s")) / writes
    reduced = statistics.median(col(two, "reduced_bytes_per_iteration"))
    return {
        "directions": d,
        "rays": int(one[0]["rays"]),
        "iterations": iterations,
        # one direction's shooting, one iteration (CPU seconds of one thread)
        "shoot_s_per_direction": shoot_cpu / (iterations * d),
        # the slowest of 2 ranks over half the serial work: split imbalance plus the per-rank
        # serial part (texture update, summing the worker blocks)
        "two_rank_work_ratio": two_work / (shoot_cpu / 2),
        "trace_s_per_direction": min(col(one, "trace_s")) / d,
        "maps_and_textures_bytes": maps,
        # peak RSS less the maps and textures held: the process (VTK, Embree, MPI, the scene)
        "shared_bytes_per_rank": shared,
        # the same at 2 ranks: plus MPI's shared-memory buffers and the snapshot batches
        "shared_bytes_per_rank_two_ranks": shared_two,
        "texels": (reduced - 120) / REDUCE_BYTES_PER_TEXEL,
        "write_bytes_per_s": maps / write_one,
        "distributed_write_s": write_two,
        "allreduce_s_measured": min(col(two, "iterations_in_mpi_s")) / iterations,
    }


def predict(p, ranks, scale, directions):
    """One iteration (and its snapshot) on `ranks` ranks for a scene `scale` times the Cornell
    box's surface area at the same sampling density: crossings, map cells and texels all grow with
    the area; the directions stay."""
    per_dir = p["shoot_s_per_direction"] * scale
    owned = max(1, math.ceil(directions / ranks))
    # Greedy split: the ranks' loads differ by at most one direction's cost.
    compute = per_dir * min(owned, directions / ranks + IMBALANCE_RATIO) if ranks > 1 else per_dir * directions
    texels = p["texels"] * scale
    bytes_reduced = REDUCE_BYTES_PER_TEXEL * texels + 120
    allreduce = 0.0
    if ranks > 1:
        # Rabenseifner: reduce-scatter then all-gather, 2 log2 P messages, 2 (P-1)/P of the bytes.
        allreduce = 2 * math.log2(ranks) * LATENCY_S + 2 * bytes_reduced * (ranks - 1) / ranks / LINK_BYTES_PER_S
    maps = p["maps_and_textures_bytes"] * scale * directions / p["directions"]
    # Rank 0 writes the whole field every iteration, receiving (P-1)/P of it through its link.
    write = maps / p["write_bytes_per_s"] + (maps * (ranks - 1) / ranks / LINK_BYTES_PER_S if ranks > 1 else 0.0)
    # Every rank: the process, the textures and the worker blocks' buffers for every texel (the
    # Cornell box's are inside the measured shared part; a larger scene adds its texels), its
    # share of the maps, a snapshot batch; rank 0 one batch per sender (64 MiB at most).
    extra_texels = texels - p["texels"]
    base = p["shared_bytes_per_rank"] if ranks == 1 else p["shared_bytes_per_rank_two_ranks"]
    per_texel = TEXTURE_BYTES_PER_TEXEL + BLOCKS_HERE * BLOCK_BYTES_PER_TEXEL
    memory = base + extra_texels * per_texel + (maps - p["texels"] * TEXTURE_BYTES_PER_TEXEL * scale) / ranks
    memory_rank0 = memory + (min(64 << 20, (ranks - 1) * BATCH_BYTES) if ranks > 1 else 0)
    memory_node64 = memory + texels * (BLOCKS_CLUSTER_NODE - BLOCKS_HERE) * BLOCK_BYTES_PER_TEXEL
    return {
        "ranks": ranks,
        "area_scale": scale,
        "directions": directions,
        "compute_s": compute,
        "allreduce_s": allreduce,
        "snapshot_write_s": write,
        "iteration_s": compute + allreduce,
        "iteration_with_snapshot_s": compute + allreduce + write,
        "communication_share": allreduce / (compute + allreduce),
        "reduced_bytes_per_rank": bytes_reduced,
        "memory_per_rank_bytes": memory,
        "memory_rank0_bytes": memory_rank0,
        "memory_per_rank_on_64_core_node_bytes": memory_node64,
        "directions_per_rank": directions / ranks,
    }


def crossover(p, scale, directions, what):
    """Smallest power-of-two rank count at which `what` (allreduce or snapshot) costs more than
    the shooting (searched to 2^24 ranks, past one direction per rank: the model then keeps one
    direction's time)."""
    for e in range(0, 25):
        q = predict(p, 2**e, scale, directions)
        other = q["allreduce_s"] if what == "allreduce" else q["snapshot_write_s"]
        if other > q["compute_s"]:
            return 2**e
    return "none below 2^24"


def svg(directory, rows, predictions, p):
    width, height = 1100, 460
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           'font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>']
    # Left: measured seconds per run (median over rounds), stacked: trace, iterations' own work,
    # iterations in MPI, snapshot writes.
    configs = [(1, "1"), (2, "1"), (1, "all")]
    x0, y0, h = 70, 400, 320
    bars = []
    for ranks, threads in configs:
        runs = runs_of(rows, ranks, threads)
        if not runs:
            continue
        med = lambda c: statistics.median(float(r[c]) for r in runs)
        bars.append((f"{ranks} x {threads}", [med("trace_s"), med("iterations_s") - med("iterations_in_mpi_s"),
                                           med("iterations_in_mpi_s"), med("writes_s")], med("wall_s")))
    top = max(b[2] for b in bars) * 1.1
    colours = ["#4e79a7", "#59a14f", "#e15759", "#f28e2b"]
    names = ["trace", "iterations (work)", "iterations (in MPI)", "snapshot writes"]
    out.append(f'<text x="{x0}" y="30" font-size="14">Measured (median of {len(runs_of(rows, 1, "1"))} '
               f'rounds), {p["directions"]} directions, {p["iterations"]} iterations: seconds</text>')
    out.append(f'<line x1="{x0}" y1="{y0}" x2="{x0}" y2="{y0 - h}" stroke="black"/>')
    for i in range(6):
        v = top * i / 5
        y = y0 - h * i / 5
        out.append(f'<text x="{x0 - 8}" y="{y + 4}" text-anchor="end">{v:.1f}</text>')
        out.append(f'<line x1="{x0}" y1="{y}" x2="{x0 + 330}" y2="{y}" stroke="#ddd"/>')
    for i, (label, parts, wall) in enumerate(bars):
        x = x0 + 20 + i * 105
        y = y0
        for part, colour in zip(parts, colours):
            hh = h * part / top
            out.append(f'<rect x="{x}" y="{y - hh}" width="60" height="{hh}" fill="{colour}"/>')
            y -= hh
        yw = y0 - h * wall / top
        out.append(f'<line x1="{x - 5}" y1="{yw}" x2="{x + 65}" y2="{yw}" stroke="black" stroke-dasharray="4"/>')
        out.append(f'<text x="{x + 30}" y="{y0 + 16}" text-anchor="middle">{label}</text>')
    for i, (name, colour) in enumerate(zip(names + ["wall (mpiexec)"], colours + ["black"])):
        out.append(f'<rect x="{x0 + i * 130 - 60}" y="{y0 + 30}" width="10" height="10" fill="{colour}"/>')
        out.append(f'<text x="{x0 + i * 130 - 46}" y="{y0 + 39}">{name}</text>')
    # Right: predicted seconds per iteration against ranks (log-log), per area scale, with and
    # without the per-iteration snapshot.
    x1, w = 560, 480
    out.append(f'<text x="{x1}" y="30" font-size="14">Model: seconds per iteration, {p["directions"]} '
               'directions (solid: no snapshot; dashed: with)</text>')
    ys = [q["iteration_with_snapshot_s"] for q in predictions] + [q["iteration_s"] for q in predictions]
    lo, hi = math.log10(min(ys)), math.log10(max(ys))
    rk = sorted({q["ranks"] for q in predictions})
    rx = lambda r: x1 + w * math.log2(r) / math.log2(rk[-1])
    ry = lambda v: y0 - h * (math.log10(v) - lo) / (hi - lo)
    out.append(f'<line x1="{x1}" y1="{y0}" x2="{x1 + w}" y2="{y0}" stroke="black"/>')
    out.append(f'<line x1="{x1}" y1="{y0}" x2="{x1}" y2="{y0 - h}" stroke="black"/>')
    for r in rk:
        out.append(f'<text x="{rx(r)}" y="{y0 + 16}" text-anchor="middle">{r}</text>')
    for e in range(math.floor(lo), math.ceil(hi) + 1):
        if lo <= e <= hi:
            out.append(f'<text x="{x1 - 6}" y="{ry(10**e) + 4}" text-anchor="end">1e{e}</text>')
            out.append(f'<line x1="{x1}" y1="{ry(10**e)}" x2="{x1 + w}" y2="{ry(10**e)}" stroke="#ddd"/>')
    out.append(f'<text x="{x1 + w / 2}" y="{y0 + 34}" text-anchor="middle">ranks</text>')
    for i, scale in enumerate(sorted({q["area_scale"] for q in predictions})):
        colour = colours[i % len(colours)]
        series = [q for q in predictions if q["area_scale"] == scale and q["directions"] == p["directions"]]
        for key, dash in (("iteration_s", ""), ("iteration_with_snapshot_s", ' stroke-dasharray="5"')):
            pts = " ".join(f"{rx(q['ranks']):.1f},{ry(q[key]):.1f}" for q in series)
            out.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{x1 + w + 5}" y="{ry(series[-1]["iteration_s"]) + 4}" fill="{colour}">{scale:g}x</text>')
    out.append("</svg>")
    (directory / "vlf-mpi.svg").write_text("\n".join(out) + "\n")


def main():
    directory = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/measurements/vlf-mpi")
    rows = load(directory)
    p = fit(rows)
    with open(directory / "vlf-mpi-model-fit.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["parameter", "value"])
        for k, v in p.items():
            w.writerow([k, f"{v:.6g}"])
        for k, v in (("assumed_latency_s", LATENCY_S), ("assumed_link_bytes_per_s", LINK_BYTES_PER_S),
                     ("assumed_imbalance_ratio", IMBALANCE_RATIO)):
            w.writerow([k, f"{v:.6g}"])
    predictions = [predict(p, r, s, d) for d in (p["directions"], 8193) for s in (1, 10, 100, 1000)
                   for r in (1, 2, 8, 16, 32, 64, 128, 256, 512, 1024)]
    with open(directory / "vlf-mpi-model.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(predictions[0].keys()))
        w.writeheader()
        for q in predictions:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in q.items()})
    svg(directory, rows, predictions, p)
    for k, v in p.items():
        print(f"{k}: {v:.6g}")
    for d in (p["directions"], 8193):
        for s in (1, 10, 100, 1000):
            print(f"{d} directions, {s}x area: the allreduce outweighs the shooting from "
                  f"{crossover(p, s, d, 'allreduce')} ranks, the per-iteration snapshot from "
                  f"{crossover(p, s, d, 'snapshot')} ranks")
    print(f"wrote {directory}/vlf-mpi-model-fit.csv, vlf-mpi-model.csv, vlf-mpi.svg")


if __name__ == "__main__":
    main()
