#!/usr/bin/python3
"""The scaling model of doc/performance.md, from the logs of a contact benchmark run.

Usage: scaling_model.py WORK [--solver MUMPS] [--sizes 1e6,1e7] [--cores 64,512]
                        [--efficiency 0.5,0.25] [--markdown FILE]

WORK is the work directory of tests/bench/contact_bench.py (make bench: BENCH_WORK); every
<WORK>/contact<N>/<solver>/contact<N>.log of a serial fcs3d run is read (completed runs and
runs stopped at the timeout alike: both end with the run summary). Per run, from the log:

  DOF                     "model: ... N degrees of freedom"
  increments              "done:" / "stopped:" N increment(s)
  factorisations          "linear solver: ... N factorisation(s)"
  factor entries, flops   the last factorisation, as the solver reports it (MUMPS: INFOG(29),
                          RINFOG(3))
  working memory          MUMPS INFOG(22): memory effectively used by the factorisation
  peak memory             the run's VmHWM ("peak memory")
  seconds/factorisation   the factorisation phase / factorisations
  assembly/factorisation  the assembly phase / factorisations (one assembly per solve)
  threads                 OMP_NUM_THREADS of the run (contact_bench.py --threads), --threads

Fits, by least squares on log-log over the sizes: factor entries, flops, working memory and
the rest of the peak memory (peak - working: the model, its state and the assembled matrix,
held whole by every rank of a parallel run) against DOF, and the achieved factorisation rate
(flops / seconds per factorisation / threads) of the largest run.

Model, for each target size n and core count P (assumptions, not measurements; they are
printed with the table):
  factor memory           working memory(n), spread over the P ranks (MUMPS distributes the
                          factors) -> per core working(n) / P;
  replicated memory       (peak - working)(n) on every rank, as fcs3d holds the whole model on
                          each (doc/performance.md, section 6);
  time per factorisation  flops(n) / (rate per core x P x efficiency), efficiency given;
  time per increment      factorisations per increment (of the run with the most increments:
                          a run's first increments re-solve more often) x (that + the
                          assembly per factorisation, linear in n / P).
A benchmark prints figures; it asserts nothing.
"""

import argparse
import glob
import math
import os
import re
import sys

import bench  # tests/bench/bench.py: duration() reads the log's durations


def read_log(path):
    """The figures of one run's log, or None when it has no run summary."""
    text = open(path).read()
    dofs = re.search(r"(\d+) degrees of freedom", text)
    head = re.search(r"^(?:done|stopped): (\d+) increment\(s\), time (\S+), wall (.+?), "
                     r"peak memory ([\d.]+) MiB", text, re.M)
    solver = re.search(r"linear solver: (\d+) analysis\(es\), (\d+) factorisation\(s\).*?; "
                       r"last factor (\S+) entries, (\S+) flops, ([\d.]+) MiB working memory",
                       text)
    phase = dict(re.findall(r"^  (assembly|factorisation|solve)\s*: (.+)$", text, re.M))
    if not (dofs and head and solver and 'assembly' in phase):
        return None
    return {"dofs": int(dofs.group(1)), "increments": int(head.group(1)),
            "time": float(head.group(2)), "peak": float(head.group(4)),
            "factorisations": int(solver.group(2)), "entries": float(solver.group(3)),
            "flops": float(solver.group(4)), "working": float(solver.group(5)),
            "factor_s": bench.duration(phase["factorisation"]),
            "assembly_s": bench.duration(phase["assembly"])}


def fit(xs, ys):
    """Least squares y = c x^p on log-log: (c, p); p is None with one point."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    if len(xs) < 2:
        return ys[0] / xs[0], None
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    p = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
    return math.exp(my - p * mx), p


def human_bytes(mib):
    return f"{mib / 1024:.1f} GiB" if mib >= 1024 else f"{mib:.0f} MiB"


def human_seconds(s):
    if s >= 3600:
        return f"{s / 3600:.1f} h"
    if s >= 60:
        return f"{s / 60:.1f} min"
    return f"{s:.2g} s" if s < 10 else f"{s:.0f} s"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("work")
    parser.add_argument("--solver", default="MUMPS")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--sizes", default="1e6,1e7")
    parser.add_argument("--cores", default="64,512")
    parser.add_argument("--efficiency", default="0.5,0.25")
    parser.add_argument("--markdown")
    args = parser.parse_args()
    runs = []
    for path in sorted(glob.glob(os.path.join(args.work, "contact*", args.solver.lower(),
                                              "contact*.log"))):
        figures = read_log(path)
        if figures:
            runs.append(figures)
    if not runs:
        sys.exit(f"no {args.solver} run with a run summary under {args.work}")
    runs.sort(key=lambda r: r["dofs"])
    out = [f"Measured ({args.solver}, {args.threads} thread(s); logs under {args.work}):", "",
           "| DOF | increments | factorisations | factor entries | flops per factorisation | "
           "working memory [MiB] | peak memory [MiB] | peak - working [MiB] | s per "
           "factorisation | GFlop/s per core | assembly per factorisation [s] |",
           "|" + "---:|" * 11]
    for r in runs:
        per = r["factor_s"] / r["factorisations"]
        r["rate"] = r["flops"] / per / args.threads
        r["other"] = max(r["peak"] - r["working"], 1.0)
        out.append(f"| {r['dofs']:,} | {r['increments']} | {r['factorisations']} | "
                   f"{r['entries']:.3g} | {r['flops']:.3g} | {r['working']:.0f} | "
                   f"{r['peak']:.0f} | {r['other']:.0f} | {per:.3g} | {r['rate'] / 1e9:.1f} | "
                   f"{r['assembly_s'] / r['factorisations']:.3g} |")
    dofs = [r["dofs"] for r in runs]
    fits = {key: fit(dofs, [r[key] for r in runs])
            for key in ("entries", "flops", "working", "other")}
    names = {"entries": "factor entries", "flops": "flops per factorisation",
             "working": "factorisation working memory", "other": "peak - working memory"}
    out += ["", f"Fitted growth, quantity ~ DOF^p over {len(runs)} size(s) "
            "(theory for nested dissection on 3-D meshes: entries p = 4/3, flops p = 2):", "",
            "| quantity | p |", "|---|---:|"]
    for key, (_, p) in fits.items():
        out.append(f"| {names[key]} | {'-' if p is None else f'{p:.2f}'} |")
    if len(runs) < 2:
        print("\n".join(out + ["", "The model needs runs at two sizes at least."]))
        return 1
    largest = runs[-1]
    longest = max(runs, key=lambda r: r["increments"])
    per_inc = longest["factorisations"] / longest["increments"]
    assembly_per_dof = min(r["assembly_s"] / r["factorisations"] / r["dofs"] for r in runs)
    rate = largest["rate"]
    out += ["", f"Model: rate {rate / 1e9:.1f} GFlop/s per core (the {largest['dofs']:,}-DOF "
            f"run); {per_inc:.2f} factorisations per increment (the run with the most "
            f"increments, {longest['dofs']:,} DOF: the first increments of a run re-solve "
            f"more often); assembly {assembly_per_dof * 1e6:.2f} us per DOF and factorisation "
            "on one core (the smallest of the runs), divided over the cores; MUMPS's parallel "
            "efficiency is an assumption (columns).", ""]
    efficiencies = [float(e) for e in args.efficiency.split(",")]
    header = ("| DOF | factor entries | flops per factorisation | factor memory, total | "
              "cores | factor memory per core | replicated per rank | " +
              " | ".join(f"per increment at efficiency {e:g}" for e in efficiencies) + " |")
    out += [header, "|" + "---:|" * (7 + len(efficiencies))]
    for n in (float(s) for s in args.sizes.split(",")):
        values = {key: c * n ** p if p is not None else c * n for key, (c, p) in fits.items()}
        for cores in (int(c) for c in args.cores.split(",")):
            times = []
            for e in efficiencies:
                factor = values["flops"] / (rate * cores * e)
                times.append(human_seconds(per_inc * (factor + assembly_per_dof * n / cores)))
            out.append(f"| {n:.0e} | {values['entries']:.2g} | {values['flops']:.2g} | "
                       f"{human_bytes(values['working'])} | {cores} | "
                       f"{human_bytes(values['working'] / cores)} | "
                       f"{human_bytes(values['other'])} | " + " | ".join(times) + " |")
    print("\n".join(out))
    if args.markdown:
        with open(args.markdown, "w") as handle:
            handle.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
