#!/usr/bin/python3
"""fcs3d against CalculiX on a frictional block-sliding contact problem (`make bench`, via
tests/bench/run_bench.sh).

Usage: contact_bench.py --fcs3d BIN [--fcs3d-mpi BIN] [--sizes 13,24,35] [--work DIR]
                        [--threads 2] [--ranks 2] [--timeout 3600] [--skyline-limit 30000]
                        [--markdown FILE] [--skip 'ccx@35,...'] [--no-estimate]
                        [--solvers UMFPACK,MUMPS] [--reuse 0,1e-10]
                        [--contact-events ALL,NORMAL] [--deck own|capped]

For each size N, the deck of tests/bench/contact_deck.py (a block of N x N x (N+1)//2 C3D8
pressed on a larger block with a non-matching mesh, then pushed sideways until it slides
with Coulomb friction; NLGEOM; N = 13, 24, 35: 19,257, 102,408 and 301,401 degrees of freedom)
runs, one run at a time, through
  fcs3d SKYLINE            only up to --skyline-limit unknowns (default 30,000): its profile
                           factorisation costs O(n b^2), and every increment refactorises;
  fcs3d UMFPACK, MUMPS     the serial binary, OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = --threads;
  fcs3d MUMPS 2 ranks      with --fcs3d-mpi: mpirun --oversubscribe -np --ranks, --threads
                           divided among the ranks (OMP_NUM_THREADS = threads / ranks);
  ccx                      CalculiX on the same file (CCX_NPROC_* = --threads);
  ccx own increments       CalculiX on the same model with *STATIC left to its own automatic
                           incrementation (no maximum increment in step 2): the cost of
                           CalculiX as one would run it.
fcs3d runs the deck without the cap (--deck own, the default: the file of "ccx own increments",
each step *STATIC 1., 1.; since issue 21's equilibrium iterations fcs3d needs no cap, T/(mu N)
ends within 0.5 %) or the capped one (--deck capped, the file of "ccx": increments at most 0.05
of step 2, as make bench measured before). The ratios of each row are against CalculiX on the
file fcs3d runs: "ccx own increments" with --deck own, "ccx" with --deck capped; that CalculiX
row runs first.

Figures per run:
  increments            fcs3d: "done: N increment(s)" of <job>.log (or the last "inc" line of a
                        stopped run); ccx: converged increments, the rows of <job>.sta.
  factorisations        fcs3d: "linear solver: ... N factorisation(s)" of the log (one per
                        increment, plus one per contact-state switch pass); ccx: "Factoring the
                        system" lines of its output (one per Newton iteration, including those
                        of attempts that were cut back).
  final time            the total time reached (2 = the end of step 2, the final load).
  wall, CPU             /usr/bin/time -v of the whole process (mpirun and its ranks for MPI):
                        wall = time to the final load; CPU = user + system of all threads.
  peak memory           maximum resident set size (/usr/bin/time -v). MPI: the sum over the
                        ranks of their VmHWM (/proc/<pid>/status, sampled every 0.5 s), since
                        /usr/bin/time reports only the largest single process.
  per increment         wall / increments (of a stopped run: wall up to the stop), and
                        factorisations / increments.
  T, T/(mu N) - 1       T = RF_x, N = -RF_z of the pushed top nodes at the end (last *NODE PRINT
                        table of <job>.dat, time 2): in gross slip T = mu N.
  T vs ccx              (T - T_ccx) / T_ccx, against ccx on the same deck.
  ratios                ccx (same deck) divided by the row's figure: above 1, the row is faster
                        (smaller) than CalculiX.
--reuse 0,1e-10 runs every fcs3d row once per factorisation-reuse tolerance (--reuse-tolerance
of fcs3d; 0: factorise every tangent), labelled "reuse off" / "reuse 1e-10", one after the
other in the same script run; without it fcs3d runs with its default. After the table, the
"factorisation reuse" line of each fcs3d log (solves, GMRES iterations, factorisations) is
printed. --contact-events ALL,NORMAL runs every fcs3d row once per value of --contact-events
(*RMIN, CONTACT EVENTS: ALL, every contact change an R-minimum event, fcs3d's default; NORMAL,
onsets of slip and segment hand-overs left to the equilibrium iterations; doc/theory.md 6.9),
labelled "events ALL" / "events NORMAL". --solvers limits the fcs3d solvers (default: SKYLINE
up to --skyline-limit, UMFPACK, MUMPS).
Runs that exceed --timeout are stopped with SIGINT (fcs3d writes a checkpoint and exits; ccx
stops); their row keeps the increments done, the time reached and the time per increment, and
has no time to the final load. Memory guard as in tests/bench/bench.py: every run is limited to
90% of the machine's memory (RLIMIT_AS; an MPI run's ranks to that share each), and a run whose
memory, scaled from the same program at the previous size as (DOF ratio)^(4/3), would not fit
is not started. The load average at the end of each run is printed: figures are only meaningful
on an otherwise idle machine.

Growth with size: for each program, the exponent p of time per increment ~ DOF^p (least
squares on log-log over the sizes that ran, stopped runs included), and of wall to the final
load and peak memory (completed runs only). A benchmark prints figures; it asserts nothing.
"""

import argparse
import math
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import time

import bench
import contact_deck

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import datfile  # noqa: E402  (tests/tools/datfile.py)

SKYLINE_LIMIT = 30000
FINAL_TIME = 2.0
GRACE_SECONDS = 120.0
SAMPLE_SECONDS = 0.5


def rank_usage(session, name):
    """{pid: (VmHWM in MiB, CPU seconds)} of every process of the session whose command name
    is `name`."""
    usage = {}
    ticks = os.sysconf("SC_CLK_TCK")
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as handle:
                stat = handle.read()
            command = stat[stat.index("(") + 1:stat.rindex(")")]
            fields = stat[stat.rindex(")") + 2:].split()
            if int(fields[3]) != session or command != name[:15]:
                continue
            cpu = (int(fields[11]) + int(fields[12])) / ticks
            with open(f"/proc/{entry}/status") as handle:
                for line in handle:
                    if line.startswith("VmHWM:"):
                        usage[int(entry)] = (int(line.split()[1]) / 1024.0, cpu)
        except (OSError, ValueError, IndexError):
            continue
    return usage


def stop(session, rank_name):
    """SIGINT to the ranks (fcs3d writes a checkpoint, flushes its log and exits; mpirun
    itself would kill them first), or to the whole session (/usr/bin/time ignores SIGINT)."""
    ranks = rank_usage(session, rank_name) if rank_name else {}
    for pid in ranks:
        try:
            os.kill(pid, signal.SIGINT)
        except ProcessLookupError:
            pass
    if not ranks:
        os.killpg(session, signal.SIGINT)


def timed_run(command, cwd, env, timeout, limit_mib, time_file, output, rank_name=None):
    """Run `command` under /usr/bin/time -v in its own session; stop it with SIGINT after
    `timeout` seconds (`stop`; SIGKILL GRACE_SECONDS later). Returns a dict: status, stopped (the
    elapsed seconds when SIGINT was sent, or None) and, with rank_name, rank_peak and rank_cpu
    (sums over the processes of that name of their VmHWM in MiB and CPU seconds)."""
    with open(output, "w") as out:
        process = subprocess.Popen(["/usr/bin/time", "-v", "-o", time_file] + command, cwd=cwd,
                                   stdout=out, stderr=subprocess.STDOUT, env=env,
                                   start_new_session=True,
                                   preexec_fn=bench.limit_memory(limit_mib))
        started = time.monotonic()
        stopped = None
        usage = {}
        while process.poll() is None:
            if rank_name:
                usage.update(rank_usage(process.pid, rank_name))
            elapsed = time.monotonic() - started
            if stopped is None and elapsed > timeout:
                stopped = elapsed
                stop(process.pid, rank_name)
            elif stopped is not None and elapsed > timeout + GRACE_SECONDS:
                try:
                    os.killpg(process.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            time.sleep(SAMPLE_SECONDS)
    result = {"status": process.returncode, "stopped": stopped}
    if usage:
        result["rank_peak"] = sum(peak for peak, _ in usage.values())
        result["rank_cpu"] = sum(cpu for _, cpu in usage.values())
    return result


def final_forces(dat_path):
    """(time, T = RF_x, N = -RF_z) of the last total-force table of set TOP, or None."""
    if not os.path.exists(dat_path):
        return None
    try:
        blocks = [b for b in datfile.read_blocks(dat_path)
                  if b.kind == "total" and b.set_name == "TOP"]
    except (ValueError, OSError):
        return None
    if not blocks:
        return None
    last = blocks[-1]
    values = last.values()[0]
    return last.time, float(values[0]), float(-values[2])


def fill_common(row, result, time_file, outdir, job):
    status, stopped = result["status"], result["stopped"]
    row["load"] = os.getloadavg()[0]
    if stopped is not None:
        row["stopped"] = stopped
    elif status != 0:
        text = open(os.path.join(outdir, "stdout.txt")).read().strip().splitlines()
        row["failed"] = f"exit status {status}: " + " / ".join(text[-3:])
    row["wall"], row["peak"], row["cpu"] = bench.gnu_time(time_file)
    forces = final_forces(os.path.join(outdir, job + ".dat"))
    if forces and abs(forces[0] - FINAL_TIME) < 1e-9 and stopped is None and status == 0:
        row["force"], row["normal"] = forces[1], forces[2]


def reuse_label(tolerance):
    """', reuse off' / ', reuse 1e-10' for a --reuse-tolerance, '' for fcs3d's default."""
    if tolerance is None:
        return ""
    return ", reuse off" if float(tolerance) == 0.0 else f", reuse {tolerance}"


def events_label(events):
    """', events NORMAL' for a --contact-events value, '' for fcs3d's default."""
    return "" if events is None else f", events {events.upper()}"


def run_fcs3d(binary, deck, solver, workdir, env, timeout, limit_mib, ranks=None, reuse=None,
              events=None):
    label = (f"fcs3d {solver}" + (f" {ranks} ranks" if ranks else "") + reuse_label(reuse) +
             events_label(events))
    outdir = os.path.join(workdir, re.sub(r"[^a-z0-9.-]+", "_", label.split(" ", 1)[1].lower()))
    os.makedirs(outdir, exist_ok=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    time_file = os.path.join(outdir, "time.txt")
    command = [binary, "-q", "--solver", solver, "-o", outdir, deck]
    if reuse is not None:
        command[2:2] = ["--reuse-tolerance", str(reuse)]
    if events is not None:
        command[2:2] = ["--contact-events", events.upper()]
    rank_name = None
    if ranks:
        command = ["mpirun", "--oversubscribe", "-np", str(ranks)] + command
        env = dict(env, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        limit_mib = limit_mib / ranks
        rank_name = os.path.basename(binary)
    result = timed_run(command, outdir, env, timeout, limit_mib, time_file,
                       os.path.join(outdir, "stdout.txt"), rank_name)
    row = {"program": label}
    fill_common(row, result, time_file, outdir, job)
    if "rank_peak" in result:
        row["peak"] = result["rank_peak"]
        row["cpu"] = max(row.get("cpu") or 0.0, result["rank_cpu"])
    log = os.path.join(outdir, job + ".log")
    text = open(log).read() if os.path.exists(log) else ""
    done = re.search(r"^done: (\d+) increment\(s\), time (\S+),", text, re.M)
    factorisations = re.search(r"linear solver: .*?(\d+) factorisation\(s\)", text)
    increments = re.findall(r"^inc (\d+) step \d+ time (\S+)", text, re.M)
    if done:
        row["increments"], row["time"] = int(done.group(1)), float(done.group(2))
    elif increments:
        row["increments"], row["time"] = int(increments[-1][0]), float(increments[-1][1])
    if factorisations:
        row["factorisations"] = int(factorisations.group(1))
    reuse_line = re.search(r"^\s*(factorisation reuse.*)$", text, re.M)
    if reuse_line:
        row["reuse"] = reuse_line.group(1)
    return row


def run_ccx(deck, workdir, name, env, timeout, limit_mib):
    outdir = os.path.join(workdir, name.replace(" ", "_"))
    os.makedirs(outdir, exist_ok=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    shutil.copy(deck, outdir)
    time_file = os.path.join(outdir, "time.txt")
    result = timed_run(["ccx", job], outdir, env, timeout, limit_mib, time_file,
                       os.path.join(outdir, "stdout.txt"))
    row = {"program": name}
    fill_common(row, result, time_file, outdir, job)
    text = open(os.path.join(outdir, "stdout.txt")).read()
    if "failed" not in row and "stopped" not in row and "Job finished" not in text:
        row["failed"] = "no 'Job finished' in the output"
    solver = re.search(r"Factoring the system of equations using the (.*) solver", text)
    if solver:
        row["program"] = f"{name} ({solver.group(1)})"
    row["factorisations"] = len(re.findall(r"Factoring the system of equations", text))
    sta = os.path.join(outdir, job + ".sta")
    rows = []
    if os.path.exists(sta):
        for line in open(sta):
            fields = line.split()
            if len(fields) == 7 and fields[0].isdigit():
                rows.append(fields)
    if rows:
        row["increments"], row["time"] = len(rows), float(rows[-1][4])
    return row


def per_increment(row):
    """Wall seconds per increment (of a stopped run: up to the stop)."""
    wall = row.get("stopped", row.get("wall"))
    if wall is None or not row.get("increments"):
        return None
    return wall / row["increments"]


def to_final_load(row):
    return None if "stopped" in row or "failed" in row else row.get("wall")


def table_row(dofs, row, reference):
    if "failed" in row and row.get("wall") is None:
        return f"| {dofs:,} | {row['program']} | {row['failed']} |" + " |" * 14
    fmt = bench.fmt
    increments = row.get("increments")
    factor_ratio = None
    if increments and row.get("factorisations") is not None:
        factor_ratio = row["factorisations"] / increments
    final = fmt(row.get("time"), 3)
    if "stopped" in row:
        final += f" (stopped at {row['stopped']:.0f} s)"
    elif "failed" in row:
        final += f" ({row['failed']})"
    force, normal = row.get("force"), row.get("normal")
    slip = "-" if force is None or not normal else f"{force / (contact_deck.MU * normal) - 1:+.2%}"
    versus = "-"
    if force is not None and reference.get("force") and row is not reference:
        versus = f"{force / reference['force'] - 1:+.1e}"
    return (f"| {dofs:,} | {row['program']} | {increments if increments else '-'} | "
            f"{row.get('factorisations', '-')} | {final} | {fmt(to_final_load(row), 1)} | "
            f"{fmt(row.get('cpu'), 1)} | {fmt(row.get('peak'), 0)} | "
            f"{fmt(per_increment(row), 3)} | {fmt(factor_ratio, 2)} | "
            f"{'-' if force is None else f'{force:.6f}'} | {slip} | {versus} | "
            f"{bench.ratio(per_increment(reference), per_increment(row))} | "
            f"{bench.ratio(to_final_load(reference), to_final_load(row))} | "
            f"{bench.ratio(reference.get('peak'), row.get('peak'))} | {fmt(row.get('load'))} |")


def fit_exponent(points):
    """Least-squares slope of log(y) against log(x), or None with fewer than 2 points."""
    points = [(math.log(x), math.log(y)) for x, y in points if y]
    if len(points) < 2 or len({x for x, _ in points}) < 2:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    return (sum((x - mx) * (y - my) for x, y in points)
            / sum((x - mx) ** 2 for x, _ in points))


def growth_table(results):
    """results: {program: [(dofs, row)]} -> Markdown lines of the fitted exponents."""
    lines = ["| program | sizes (DOF) | p: time per increment | p: wall to final load | "
             "p: peak memory | p: increments |", "|---|---|---|---|---|---|"]
    for program, runs in results.items():
        steps = [(d, per_increment(r)) for d, r in runs if per_increment(r)]
        walls = [(d, to_final_load(r)) for d, r in runs if to_final_load(r)]
        peaks = [(d, r.get("peak")) for d, r in runs if to_final_load(r) and r.get("peak")]
        counts = [(d, r.get("increments")) for d, r in runs if to_final_load(r)]

        def show(points):
            p = fit_exponent(points)
            return "-" if p is None else f"{p:.2f} ({len(points)})"

        sizes = ", ".join(f"{d:,}" for d, _ in steps) or "-"
        lines.append(f"| {program} | {sizes} | {show(steps)} | {show(walls)} | "
                     f"{show(peaks)} | {show(counts)} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fcs3d", required=True)
    parser.add_argument("--fcs3d-mpi", help="the MPI build (bin/fcs3d-mpi): adds MUMPS on "
                        "--ranks ranks")
    parser.add_argument("--sizes", default="13,24,35",
                        help="upper-block element counts N (contact_deck.py)")
    parser.add_argument("--work", default="bench_work")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=3600.0,
                        help="seconds per run; longer runs are stopped and reported as such")
    parser.add_argument("--skyline-limit", type=int, default=SKYLINE_LIMIT)
    parser.add_argument("--markdown")
    parser.add_argument("--skip", default="",
                        help="runs not to start, e.g. 'ccx@35,fcs3d UMFPACK@35,"
                             "fcs3d MUMPS 2 ranks@35,ccx own increments@13'; separated by ';' "
                             "when a label holds a comma, e.g. 'ccx@24;fcs3d MUMPS, events ALL@24'")
    parser.add_argument("--no-estimate", action="store_true",
                        help="start every run, even when the scaled memory would not fit "
                             "(the memory limit still applies)")
    parser.add_argument("--solvers", help="fcs3d solvers to run, e.g. 'UMFPACK,MUMPS' "
                        "(default: SKYLINE up to --skyline-limit, UMFPACK, MUMPS)")
    parser.add_argument("--reuse", help="factorisation-reuse tolerances: each fcs3d run once "
                        "per value, e.g. '0,1e-10' (0: off); default: fcs3d's own default")
    parser.add_argument("--contact-events", help="fcs3d's --contact-events: each fcs3d run once "
                        "per value, e.g. 'ALL,NORMAL'; default: fcs3d's own default (ALL)")
    parser.add_argument("--deck", choices=("own", "capped"), default="own",
                        help="the deck fcs3d runs: without the increment cap (own, the file "
                        "of 'ccx own increments') or with it (capped, the file of 'ccx')")
    args = parser.parse_args()
    tolerances = [t.strip() for t in args.reuse.split(",")] if args.reuse else [None]
    event_modes = ([e.strip() for e in args.contact_events.split(",")]
                   if args.contact_events else [None])
    # Labels may hold commas ("fcs3d MUMPS, events CLOSING"): with a ";" in it, --skip is a
    # ";"-separated list.
    skip = {item.strip() for item in args.skip.split(";" if ";" in args.skip else ",")
            if item.strip()}
    threads = str(args.threads)
    env = dict(os.environ, OMP_NUM_THREADS=threads, OPENBLAS_NUM_THREADS=threads,
               MKL_NUM_THREADS=threads, CCX_NPROC_EQUATION_SOLVER=threads,
               CCX_NPROC_STIFFNESS=threads, CCX_NPROC_RESULTS=threads)
    rank_threads = str(max(1, args.threads // args.ranks))
    mpi_env = dict(env, OMP_NUM_THREADS=rank_threads, OPENBLAS_NUM_THREADS=rank_threads,
                   MKL_NUM_THREADS=rank_threads)
    memory_mib = bench.machine_memory_mib()
    limit_mib = bench.MEMORY_FRACTION * memory_mib
    cpu = platform.machine()
    if os.path.exists("/proc/cpuinfo"):
        names = re.findall(r"model name\s*: (.*)", open("/proc/cpuinfo").read())
        cpu = names[0] if names else cpu
    notes = [f"machine: {cpu}, nproc {os.cpu_count()}, {memory_mib / 1024:.1f} GiB memory, "
             f"{platform.system()} {platform.release()}",
             f"threads: OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = CCX_NPROC_* = {threads}; "
             f"MPI: {args.ranks} ranks x {rank_threads} thread(s)",
             f"memory limit per run: {limit_mib / 1024:.1f} GiB; timeout per run: "
             f"{args.timeout:.0f} s",
             f"model: tests/bench/contact_deck.py, mu = {contact_deck.MU}, final load at "
             f"time {FINAL_TIME:g} (push {contact_deck.PUSH:g}); fcs3d runs the "
             f"{'uncapped' if args.deck == 'own' else 'capped'} deck, ratios against "
             f"{'ccx own increments' if args.deck == 'own' else 'ccx'}"]
    header = ("| DOF | program, solver | increments | factorisations | final time | "
              "wall to final load [s] | CPU [s] | peak memory [MiB] | per increment [s] | "
              "factorisations per increment | T = RF_x | T/(mu N) - 1 | T vs ccx | "
              "ccx/this per increment | ccx/this to final load | ccx/this memory | load |")
    lines = [header, "|" + "---|" * 17]
    print("\n".join(notes + [""] + lines), flush=True)
    previous = {}
    results = {}

    def attempt(program, n, dofs, run):
        if f"{program}@{n}" in skip:
            return {"program": program, "failed": "not run (--skip)"}
        if args.no_estimate:
            previous.pop(program, None)
        row = bench.guarded(program, dofs, previous, limit_mib, run)
        if row.get("wall") is not None:
            results.setdefault(program, []).append((dofs, row))
        return row

    reuse_notes = []

    def emit(dofs, row, reference):
        lines.append(table_row(dofs, row, reference))
        print(lines[-1], flush=True)
        if row.get("reuse"):
            reuse_notes.append(f"- {dofs:,} DOF, {row['program']}: {row['reuse']}")

    for n in (int(s) for s in args.sizes.split(",")):
        dofs = contact_deck.dofs(n)
        workdir = os.path.abspath(os.path.join(args.work, f"contact{n}"))
        os.makedirs(workdir, exist_ok=True)
        deck = os.path.join(workdir, f"contact{n}.inp")
        contact_deck.write_deck(n, deck)
        own = os.path.join(workdir, "own", f"contact{n}.inp")
        os.makedirs(os.path.dirname(own), exist_ok=True)
        contact_deck.write_deck(n, own, cap=False)
        ccx_runs = [("ccx", lambda: run_ccx(deck, workdir, "ccx", env, args.timeout,
                                            limit_mib)),
                    ("ccx own increments",
                     lambda: run_ccx(own, workdir, "ccx own increments", env, args.timeout,
                                     limit_mib))]
        if args.deck == "own":
            ccx_runs.reverse()
        fcs_deck = own if args.deck == "own" else deck
        reference = attempt(ccx_runs[0][0], n, dofs, ccx_runs[0][1])
        emit(dofs, reference, reference)
        runs = ccx_runs[1:]
        solvers = (["SKYLINE"] if dofs <= args.skyline_limit else []) + ["UMFPACK", "MUMPS"]
        if args.solvers:
            solvers = [s.strip().upper() for s in args.solvers.split(",")]
        runs += [(f"fcs3d {s}{reuse_label(t)}{events_label(e)}",
                  lambda s=s, t=t, e=e: run_fcs3d(args.fcs3d, fcs_deck, s, workdir, env,
                                                  args.timeout, limit_mib, reuse=t, events=e))
                 for s in solvers for e in event_modes for t in tolerances]
        if args.fcs3d_mpi:
            runs += [(f"fcs3d MUMPS {args.ranks} ranks{reuse_label(t)}{events_label(e)}",
                      lambda t=t, e=e: run_fcs3d(args.fcs3d_mpi, fcs_deck, "MUMPS", workdir,
                                                 mpi_env, args.timeout, limit_mib,
                                                 ranks=args.ranks, reuse=t, events=e))
                     for e in event_modes for t in tolerances]
        for program, run in runs:
            emit(dofs, attempt(program, n, dofs, run), reference)
    if reuse_notes:
        reuse_notes = ["", "Factorisation reuse (the summary line of each fcs3d log):", ""] + \
            reuse_notes
        print("\n".join(reuse_notes), flush=True)
    growth = ["", "Growth with size, cost ~ DOF^p (least squares on log-log; in brackets the "
              "number of sizes fitted):", ""] + growth_table(results)
    print("\n".join(growth), flush=True)
    if args.markdown:
        with open(args.markdown, "w") as handle:
            handle.write("\n".join(notes + [""] + lines + reuse_notes + growth) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
