#!/usr/bin/python3
"""fcs3d against CalculiX on cube meshes (`make bench`, via tests/bench/run_bench.sh).

Usage: bench.py --fcs3d BIN [--sizes 20,40,61] [--work DIR] [--threads 2]
                [--timeout 3600] [--markdown FILE]

For each size N, the deck of tests/bench/cube_deck.py (N^3 C3D8 elements, 3 (N+1)^3 degrees
of freedom, one linear static step) runs through fcs3d with each linear solver that can
handle the size (SKYLINE only up to 30,000 unknowns: its profile factorisation costs
O(n b^2)), and through CalculiX (ccx, with whatever solver it chooses; the log says which).

Figures per run:
  assembly, factorisation, solve  fcs3d: the phase summary at the end of its log (printed to
                                  0.1 s). ccx prints no timings of its own: its output lines
                                  are time-stamped as they arrive (line-buffered with stdbuf),
                                  assembly = from "symmetric stiffness/mass contributions" to
                                  "Factoring the system", factorisation + solve = from
                                  "Factoring the system" to the stress calculation after it.
  wall                            elapsed time of the whole process (/usr/bin/time -v),
                                  including reading the deck and writing the results.
  CPU                             user + system time of the whole process (/usr/bin/time -v),
                                  all threads: less sensitive than wall times to other load.
  peak memory                     maximum resident set size (/usr/bin/time -v); fcs3d also
                                  prints its own VmHWM in the log (same figure).
Memory guard: every run is limited to 90% of the machine's memory (RLIMIT_AS), so that a run
that does not fit fails by itself instead of waking the kernel's OOM killer, and a run whose
memory, scaled from the same program at the previous size as (DOF ratio)^(4/3) (the growth of
a nested-dissection factor of a 3-D mesh), would exceed that limit is not started; the table
says so. The load average at the end of each run is printed too: the figures are only
meaningful on an otherwise idle machine.

Ratios are CalculiX's time (memory) divided by fcs3d's: above 1 means fcs3d is faster
(smaller). The displacement of the top corner printed by both programs is compared as a
sanity check. A benchmark prints figures; it asserts nothing about them.
"""

import argparse
import os
import platform
import re
import resource
import shutil
import subprocess
import sys
import time

import cube_deck

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import datfile  # noqa: E402  (tests/tools/datfile.py)

SKYLINE_LIMIT = 30000
MEMORY_FRACTION = 0.9
FILL_EXPONENT = 4.0 / 3.0


def machine_memory_mib():
    with open("/proc/meminfo") as handle:
        for line in handle:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) / 1024.0
    return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2 ** 20


def limit_memory(limit_mib):
    """A preexec_fn: cap the child's address space."""
    def apply():
        size = int(limit_mib * 2 ** 20)
        resource.setrlimit(resource.RLIMIT_AS, (size, size))
    return apply


def gnu_time(path):
    """Wall seconds, peak RSS (MiB) and CPU seconds (user + system) from /usr/bin/time -v."""
    text = open(path).read()
    cpu = sum(float(v) for v in re.findall(r"(?:User|System) time \(seconds\): ([\d.]+)", text))
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
    seconds = None
    if wall:
        seconds = int(wall.group(1) or 0) * 3600 + int(wall.group(2)) * 60 + float(wall.group(3))
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    return seconds, (int(rss.group(1)) / 1024.0 if rss else None), cpu


def duration(text):
    """A duration as fcs3d's log prints it: "4.2 s", "3m 05s", "1h 02m"."""
    text = text.strip()
    match = re.fullmatch(r"([\d.]+) s", text)
    if match:
        return float(match.group(1))
    match = re.fullmatch(r"(\d+)m (\d+)s", text)
    if match:
        return 60 * int(match.group(1)) + int(match.group(2))
    match = re.fullmatch(r"(\d+)h (\d+)m", text)
    if match:
        return 3600 * int(match.group(1)) + 60 * int(match.group(2))
    return None


def fcs3d_phases(log_path):
    phases = {}
    with open(log_path) as handle:
        for line in handle:
            match = re.match(r"\s+(assembly|factorisation|solve|output)\s*: (.*)$", line)
            if match:
                phases[match.group(1)] = duration(match.group(2))
            match = re.search(r"peak memory ([\d.Ee+-]+) MiB", line)
            if match:
                phases["log_peak"] = float(match.group(1))
    return phases


def run_fcs3d(fcs3d, deck, solver, workdir, env, timeout, limit_mib):
    outdir = os.path.join(workdir, solver.lower())
    os.makedirs(outdir, exist_ok=True)
    time_file = os.path.join(outdir, "time.txt")
    job = os.path.splitext(os.path.basename(deck))[0]
    command = ["/usr/bin/time", "-v", "-o", time_file, fcs3d, "-q", "--solver", solver,
               "-o", outdir, deck]
    with open(os.path.join(outdir, "stdout.txt"), "w") as out:
        try:
            status = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=env,
                                    timeout=timeout, preexec_fn=limit_memory(limit_mib)).returncode
        except subprocess.TimeoutExpired:
            return {"program": f"fcs3d {solver}", "failed": f"timed out after {timeout} s"}
    row = {"program": f"fcs3d {solver}", "load": os.getloadavg()[0]}
    if status != 0:
        tail = open(os.path.join(outdir, "stdout.txt")).read().strip().splitlines()[-3:]
        row["failed"] = f"exit status {status}: " + " / ".join(tail)
        return row
    row["wall"], row["peak"], row["cpu"] = gnu_time(time_file)
    phases = fcs3d_phases(os.path.join(outdir, job + ".log"))
    row.update(assembly=phases.get("assembly"), factor=phases.get("factorisation"),
               solve=phases.get("solve"), log_peak=phases.get("log_peak"))
    if row["factor"] is not None and row["solve"] is not None:
        row["factor_solve"] = row["factor"] + row["solve"]
    row["dat"] = os.path.join(outdir, job + ".dat")
    return row


def run_ccx(deck, workdir, env, timeout, limit_mib):
    ccxdir = os.path.join(workdir, "ccx")
    os.makedirs(ccxdir, exist_ok=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    shutil.copy(deck, ccxdir)
    time_file = os.path.join(ccxdir, "time.txt")
    env = dict(env, GFORTRAN_UNBUFFERED_PRECONNECTED="y")
    command = ["/usr/bin/time", "-v", "-o", time_file, "stdbuf", "-oL", "-eL", "ccx", job]
    stamps = []
    started = time.perf_counter()
    with subprocess.Popen(command, cwd=ccxdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, env=env, preexec_fn=limit_memory(limit_mib)) as process, \
            open(os.path.join(ccxdir, "ccx.log"), "w") as log:
        for line in process.stdout:
            stamp = time.perf_counter() - started
            stamps.append((stamp, line.rstrip()))
            log.write(f"{stamp:10.3f} {line}")
            if stamp > timeout:
                process.kill()
        status = process.wait()
    row = {"program": "ccx", "load": os.getloadavg()[0]}
    if status != 0 or not any("Job finished" in text for _, text in stamps):
        row["failed"] = f"exit status {status}"
        return row
    row["wall"], row["peak"], row["cpu"] = gnu_time(time_file)

    def first(pattern, after=0.0):
        for stamp, text in stamps:
            if stamp >= after and re.search(pattern, text):
                return stamp, text
        return None, None

    t_stiffness, _ = first(r"symmetric stiffness/mass contributions")
    t_factor, text = first(r"Factoring the system of equations")
    if text:
        row["program"] = "ccx " + re.search(r"using the (.*) solver", text).group(1)
    t_stress, _ = first(r"for the stress calculation", after=t_factor or 0.0)
    if t_stiffness is not None and t_factor is not None:
        row["assembly"] = t_factor - t_stiffness
    if t_factor is not None and t_stress is not None:
        row["factor_solve"] = t_stress - t_factor
    threads = re.findall(r"Using up to (\d+) cpu\(s\) for (spooles|pardiso|pastix)",
                         "\n".join(text for _, text in stamps))
    row["threads"] = threads[0][0] if threads else "?"
    row["dat"] = os.path.join(ccxdir, job + ".dat")
    return row


def monitor_difference(row, reference):
    """Largest relative difference of the printed corner displacement."""
    if "dat" not in row or "dat" not in reference:
        return None
    a = datfile.read_blocks(row["dat"])[0].values()
    b = datfile.read_blocks(reference["dat"])[0].values()
    return float(abs(a - b).max() / abs(b).max())


def fmt(value, digits=1):
    return "-" if value is None else f"{value:.{digits}f}"


def ratio(reference, value):
    if reference is None or value is None or value <= 0:
        return "-"
    return f"{reference / value:.2f}"


def table_row(dofs, row, reference):
    if "failed" in row:
        return f"| {dofs:,} | {row['program']} | {row['failed']} |" + " |" * 12
    difference = monitor_difference(row, reference) if row is not reference else None
    return (f"| {dofs:,} | {row['program']} | {fmt(row.get('assembly'), 2)} | "
            f"{fmt(row.get('factor'))} | {fmt(row.get('solve'))} | "
            f"{fmt(row.get('factor_solve'), 2)} | {fmt(row.get('wall'), 2)} | {fmt(row.get('cpu'), 1)} | "
            f"{fmt(row.get('peak'), 0)} | "
            f"{ratio(reference.get('factor_solve'), row.get('factor_solve'))} | "
            f"{ratio(reference.get('wall'), row.get('wall'))} | "
            f"{ratio(reference.get('cpu'), row.get('cpu'))} | "
            f"{ratio(reference.get('peak'), row.get('peak'))} | "
            f"{'-' if difference is None else f'{difference:.1e}'} | {fmt(row.get('load'))} |")


def guarded(program, dofs, previous, limit_mib, run):
    """Run `run()` unless the memory scaled from the previous size would not fit."""
    if program in previous:
        last_dofs, last_peak = previous[program]
        estimate = last_peak * (dofs / last_dofs) ** FILL_EXPONENT
        if estimate > limit_mib:
            return {"program": program, "failed": (
                f"not run: needs about {estimate / 1024:.0f} GiB (scaled from "
                f"{last_peak / 1024:.1f} GiB at {last_dofs:,} DOF), limit {limit_mib / 1024:.0f} GiB")}
    row = run()
    if row.get("peak"):
        previous[program] = (dofs, row["peak"])
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fcs3d", required=True)
    parser.add_argument("--sizes", default="20,40,61")
    parser.add_argument("--work", default="bench_work")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=3600.0)
    parser.add_argument("--markdown")
    parser.add_argument("--skip", default="",
                        help="runs not to start, e.g. 'ccx@61,fcs3d UMFPACK@61'")
    parser.add_argument("--no-estimate", action="store_true",
                        help="start every run, even when the scaled memory would not fit "
                             "(the memory limit still applies)")
    args = parser.parse_args()
    skip = {item.strip() for item in args.skip.split(",") if item.strip()}
    threads = str(args.threads)
    env = dict(os.environ, OMP_NUM_THREADS=threads, OPENBLAS_NUM_THREADS=threads,
               MKL_NUM_THREADS=threads, CCX_NPROC_EQUATION_SOLVER=threads,
               CCX_NPROC_STIFFNESS=threads, CCX_NPROC_RESULTS=threads)
    memory_mib = machine_memory_mib()
    limit_mib = MEMORY_FRACTION * memory_mib
    cpu = ""
    if os.path.exists("/proc/cpuinfo"):
        names = re.findall(r"model name\s*: (.*)", open("/proc/cpuinfo").read())
        cpu = names[0] if names else platform.machine()
    machine = (f"{cpu}, nproc {os.cpu_count()}, {memory_mib / 1024:.1f} GiB memory, "
               f"{platform.system()} {platform.release()}")
    notes = [f"machine: {machine}",
             f"threads: OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = CCX_NPROC_* = {threads}",
             f"memory limit per run: {limit_mib / 1024:.1f} GiB"]
    header = ("| DOF | program, solver | assembly [s] | factorisation [s] | solve [s] | "
              "factor+solve [s] | wall [s] | CPU [s] | peak memory [MiB] | "
              "ccx/fcs3d factor+solve | ccx/fcs3d wall | ccx/fcs3d CPU | ccx/fcs3d memory | "
              "corner u vs ccx | load |")
    lines = [header, "|" + "---|" * 15]
    print("\n".join(notes + [""] + lines), flush=True)
    previous = {}

    def attempt(program, n, dofs, run):
        if f"{program}@{n}" in skip:
            return {"program": program, "failed": "not run (--skip)"}
        if args.no_estimate:
            previous.pop(program, None)
        return guarded(program, dofs, previous, limit_mib, run)

    for n in (int(s) for s in args.sizes.split(",")):
        dofs = 3 * (n + 1) ** 3
        workdir = os.path.abspath(os.path.join(args.work, f"cube{n}"))
        os.makedirs(workdir, exist_ok=True)
        deck = os.path.join(workdir, f"cube{n}.inp")
        cube_deck.write_deck(n, deck)
        solvers = (["SKYLINE"] if dofs <= SKYLINE_LIMIT else []) + ["UMFPACK", "MUMPS"]
        reference = attempt("ccx", n, dofs,
                            lambda: run_ccx(deck, workdir, env, args.timeout, limit_mib))
        rows = [attempt(f"fcs3d {s}", n, dofs,
                        lambda s=s: run_fcs3d(args.fcs3d, deck, s, workdir, env, args.timeout,
                                              limit_mib))
                for s in solvers]
        for row in rows + [reference]:
            lines.append(table_row(dofs, row, reference))
            print(lines[-1], flush=True)
    if args.markdown:
        with open(args.markdown, "w") as handle:
            handle.write("\n".join(notes + [""] + lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
