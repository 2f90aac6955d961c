#!/usr/bin/env python3
"""The fault-bend default run as a benchmark (`make bench`, issue 20 item 4): time to the final
load of the `make run` deck, with and without factorisation reuse, and optionally the same
deck run by another build, in one script run on one machine. Prints figures and asserts
nothing about time.

Runs (each fcs3d alone, one BLAS thread as `make run`, timed by GNU time):
  reference   input/fault_bend/fault_bend.inp (the `make run` deck: Ruina's slip law,
              radiation damping) on the default mesh, once per --options entry (default: the
              default options, and --reuse-tolerance 1e-10);
  paper law   with --before OLD: input/fault_bend/fault_bend_paper_law.inp (the `make run`
              deck before issue 19) on the mesh of those runs (lower_fault_factor 1.25), run
              by this build, and by OLD as builds before issues 19-21 read it (`*ELASTIC`,
              their name for the hypoelastic law, for `*HYPOELASTIC`, and without the card
              `*RMIN, NO EQUILIBRIUM=CARRY`, which was their only behaviour): the speed-up of
              the code on the deck that was `make run` when issue 20 was written.

For every run: increments, factorisations, solves and Krylov iterations, the phase times of
fcs3d's own summary, wall and CPU time, and its event catalogue (number of events; the first
event's onset, mean slip and stress drop), with the ratio of times and the change of the
catalogue against the first run of the same deck.

Usage: fault_bend_bench.py --fcs3d BIN [--before OLD_BIN] [--work DIR]
                           [--options "LABEL=opts;LABEL=opts"] [--markdown FILE]
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DECKS = os.path.join(ROOT, "input", "fault_bend")
DEFAULT_OPTIONS = "default=;reuse 1e-10=--reuse-tolerance 1e-10"
# The mesh option of the runs before issue 19 (fault_bend_paper_law.inp's header).
PAPER_LAW_GMSH = ["-setnumber", "lower_fault_factor", "1.25"]


def parse_options(text):
    """'LABEL=opts;LABEL=opts' -> [(label, [opts...])]."""
    runs = []
    for item in filter(None, (part.strip() for part in text.split(";"))):
        label, _, opts = item.partition("=")
        runs.append((label.strip(), opts.split()))
    return runs


def mesh(work, name, gmsh_options):
    """The fault-bend mesh into work/name/fault_bend.msh (once)."""
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    shutil.copy(os.path.join(DECKS, "fault_bend.geo"), directory)
    with open(os.path.join(directory, "gmsh.log"), "w") as log:
        subprocess.run(["gmsh", "-3", "-format", "msh41", *gmsh_options, "fault_bend.geo",
                        "-o", "fault_bend.msh"], cwd=directory, stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    return os.path.join(directory, "fault_bend.msh")


def seconds(text):
    """'1m 15s', '22.9 s', '2h 3m 4s' -> seconds."""
    total = 0.0
    for value, unit in re.findall(r"([0-9.]+)\s*([hms])", text):
        total += float(value) * {"h": 3600.0, "m": 60.0, "s": 1.0}[unit]
    return total


def summary(log_path):
    """What fcs3d's log says at the end of the run (the `done:` block)."""
    found = {}
    with open(log_path, errors="replace") as log:
        lines = log.read().splitlines()
    done = [k for k, line in enumerate(lines) if line.startswith("done:")]
    if not done:
        return found
    for line in lines[done[-1]:]:
        m = re.match(r"done: (\d+) increment", line)
        if m:
            found["increments"] = int(m.group(1))
        m = re.match(r"\s+(assembly|factorisation|solve|update|r-minimum|output)\s*:\s*(.*)$", line)
        if m:
            found[m.group(1)] = seconds(m.group(2))
        m = re.search(r"linear solver: .*?(\d+) factorisation\(s\)", line)
        if m:
            found["factorisations"] = int(m.group(1))
        m = re.search(r"factorisation reuse.*?: (?:off; )?(\d+) solve\(s\)", line)
        if m:
            found["solves"] = int(m.group(1))
        m = re.search(r"with (\d+) iteration\(s\)", line)
        if m:
            found["krylov"] = int(m.group(1))
    return found


def catalogue(csv_path):
    """Events of the run: their number and the first one's onset, mean slip, stress drop."""
    if not os.path.exists(csv_path):
        return {}
    with open(csv_path) as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        return {"events": 0}
    first = rows[0]
    return {"events": len(rows), "onset": float(first["onset"]),
            "mean_slip": float(first["mean_slip"]), "stress_drop": float(first["stress_drop"])}


def as_before_issue_19(text):
    """The paper-law deck in the words of builds before issues 19-21 (see the module)."""
    lines = [line for line in text.splitlines(keepends=True)
             if not re.match(r"\*RMIN,\s*NO EQUILIBRIUM\s*=\s*CARRY\s*$", line.strip(), re.I)]
    return "".join("*ELASTIC\n" if re.match(r"\*HYPOELASTIC\s*$", line, re.I) else line
                   for line in lines)


def run(fcs3d, deck, msh, directory, options, timeout, old_words=False):
    """One timed fcs3d run in its own directory."""
    os.makedirs(directory, exist_ok=True)
    with open(deck) as source:
        text = source.read()
    with open(os.path.join(directory, "fault_bend.inp"), "w") as target:
        target.write(as_before_issue_19(text) if old_words else text)
    shutil.copy(msh, directory)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    command = ["/usr/bin/time", "-f", "%e %U %S %M", "-o", "times.txt", fcs3d, "-q", *options,
               "fault_bend.inp"]
    with open(os.path.join(directory, "stdout.txt"), "w") as out:
        try:
            status = subprocess.run(command, cwd=directory, stdout=out, stderr=subprocess.STDOUT,
                                    env=env, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            status = "timeout"
    result = {"status": status}
    times = os.path.join(directory, "times.txt")
    if os.path.exists(times):
        fields = open(times).read().split()[-4:]
        if len(fields) == 4:
            result.update(wall=float(fields[0]), cpu=float(fields[1]) + float(fields[2]),
                          rss_mib=float(fields[3]) / 1024.0)
    result.update(summary(os.path.join(directory, "fault_bend.log")))
    result.update(catalogue(os.path.join(directory, "fault_bend_events.csv")))
    return result


def cell(value, form):
    return "-" if value is None else format(value, form)


def table(rows):
    """Text and Markdown tables; times and catalogue against the first row of each deck."""
    head = ["deck", "build", "options", "increments", "factorisations", "solves",
            "Krylov its", "assembly [s]", "factorisation [s]", "solve [s]", "wall [s]",
            "CPU [s]", "speed-up (CPU)", "events", "first onset [s]", "d onset [s]",
            "mean slip rel.", "stress drop rel."]
    lines = []
    first = {}
    for row in rows:
        r = row["result"]
        base = first.setdefault(row["deck"], r)
        speed = (base["cpu"] / r["cpu"]) if r.get("cpu") and base.get("cpu") else None
        d_onset = (r["onset"] - base["onset"]) if "onset" in r and "onset" in base else None
        rel = {}
        for key in ("mean_slip", "stress_drop"):
            rel[key] = (r[key] / base[key] - 1.0) if key in r and key in base and base[key] else None
        lines.append([row["deck"], row["build"], row["label"] + (" [" + str(r["status"]) + "]"
                                                                 if r["status"] != 0 else ""),
                      cell(r.get("increments"), "d"), cell(r.get("factorisations"), "d"),
                      cell(r.get("solves"), "d"), cell(r.get("krylov"), "d"),
                      cell(r.get("assembly"), ".1f"), cell(r.get("factorisation"), ".1f"),
                      cell(r.get("solve"), ".1f"), cell(r.get("wall"), ".1f"),
                      cell(r.get("cpu"), ".1f"), cell(speed, ".2f"), cell(r.get("events"), "d"),
                      cell(r.get("onset"), ".6f"), cell(d_onset, "+.2e"),
                      cell(rel["mean_slip"], "+.1e"), cell(rel["stress_drop"], "+.1e")])
    widths = [max(len(head[k]), *(len(line[k]) for line in lines)) for k in range(len(head))]
    text = ["  ".join(h.rjust(w) for h, w in zip(head, widths))]
    text += ["  ".join(c.rjust(w) for c, w in zip(line, widths)) for line in lines]
    markdown = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
    markdown += ["| " + " | ".join(line) + " |" for line in lines]
    return "\n".join(text), "\n".join(markdown)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fcs3d", required=True)
    parser.add_argument("--before", help="another build: the paper-law deck run by both")
    parser.add_argument("--work")
    parser.add_argument("--options", default=DEFAULT_OPTIONS,
                        help="runs of the reference deck, 'LABEL=options;...' (default: %(default)s)")
    parser.add_argument("--markdown")
    parser.add_argument("--timeout", type=float, default=3600.0)
    args = parser.parse_args()
    if shutil.which("gmsh") is None:
        sys.exit("fault_bend_bench.py: gmsh is not installed")
    work = args.work or tempfile.mkdtemp(prefix="fcs3d-fault-bench.")
    os.makedirs(work, exist_ok=True)
    fcs3d = os.path.abspath(args.fcs3d)
    print(f"fault-bend bench in {work}; fcs3d {fcs3d}"
          + (f", before {os.path.abspath(args.before)}" if args.before else ""), flush=True)
    rows = []
    reference_mesh = mesh(work, "mesh_reference", [])
    for k, (label, options) in enumerate(parse_options(args.options)):
        print(f"  reference deck, {label} ...", flush=True)
        result = run(fcs3d, os.path.join(DECKS, "fault_bend.inp"), reference_mesh,
                     os.path.join(work, f"reference.{k}"), options, args.timeout)
        rows.append({"deck": "reference", "build": "this", "label": label, "result": result})
    if args.before:
        paper_mesh = mesh(work, "mesh_paper_law", PAPER_LAW_GMSH)
        for build, binary in (("before", os.path.abspath(args.before)), ("this", fcs3d)):
            print(f"  paper-law deck, {build} ...", flush=True)
            result = run(binary, os.path.join(DECKS, "fault_bend_paper_law.inp"), paper_mesh,
                         os.path.join(work, f"paper_law.{build}"), [], args.timeout,
                         old_words=build == "before")
            rows.append({"deck": "paper law", "build": build, "label": "default",
                         "result": result})
    text, markdown = table(rows)
    print()
    print(text)
    print("(speed-up: CPU time of the deck's first run over this one's; d onset, rel.: the "
          "first event against the deck's first run)")
    if args.markdown:
        with open(args.markdown, "w") as handle:
            handle.write(markdown + "\n")
    return 0 if all(row["result"]["status"] == 0 for row in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
