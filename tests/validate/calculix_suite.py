#!/usr/bin/python3
"""CalculiX's own static test decks through ccx and fcs3d: the measurement of issues 16 and 17.

Usage: /usr/bin/python3 tests/validate/calculix_suite.py --fcs3d bin/fcs3d [--work DIR]
           [--decks /usr/share/doc/calculix-ccx-test/examples/test] [--cache DIR] [--jobs 2]
           [--timeout-ccx 300] [--timeout-fcs3d 300] [--tolerance 1e-2] [--only DECK,...]
           [--markdown doc/validation/calculix_suite.md] [--min-agree N]

Decks. Every *.inp (or *.inp.gz) of Debian's calculix-ccx-test (the test decks of ccx 2.11).
A deck is *static* when it has at least one *STEP and *STATIC is its only procedure keyword
(no *FREQUENCY, *BUCKLE, *DYNAMIC, *MODAL DYNAMIC, *STEADY STATE DYNAMICS, *COMPLEX FREQUENCY,
*HEAT TRANSFER, *COUPLED/UNCOUPLED TEMPERATURE-DISPLACEMENT, *VISCO, *ELECTROMAGNETICS,
*GREEN, *SENSITIVITY, *SUBSTRUCTURE GENERATE, *NO ANALYSIS, *CFD ... anywhere in the deck).
Its element kinds are the TYPE= of its *ELEMENT cards; it is *3D solid* when it has elements
and every kind is a C3D* (continuum 3D) element.

Runs. Each static deck is copied into its own scratch directory and run by ccx (`ccx -i deck`)
and by fcs3d (`fcs3d -q deck.inp`), at most --jobs decks at a time, each run under its own
time limit, with OMP_NUM_THREADS=1. ccx's results are cached under --cache by a SHA-256 of the
deck, the files it reads and the ccx version, so a rerun only runs fcs3d again. Three decks
need other files: beamread reads the restart file of beamwrite (ccx runs beamwrite first),
submodelbeamp reads beamp.frd (ccx runs beamp first), submodeltwobeam reads twobeam.frd
(shipped in the package). fcs3d is given the shipped files, not ccx's output files.

Comparison. The .dat files are read with tests/tools/datfile.py (after renaming the few
CalculiX headers its pattern does not take, e.g. "... for all contact elements and time",
"(elem, integ.pnt.,pe)for set"). A reference table is paired with the other file's table of
the same title and set at the same time (the n-th such table with the n-th); rows are paired
by key (node, or element and integration point). The error of a table is, as CalculiX's
datcheck.pl computes it, max |other - reference| / max |reference| over the table (the
largest magnitude of the other table when the reference is all zeros; 0 when both tables are
below 1e-10, datcheck's floor), so near-zero entries do not dominate. A deck *agrees* when
every paired table has the same rows and an error <= --tolerance, and the last table of every
title and set in the reference (the end of the analysis) was paired. Tables at times the other
program did not print (other increments) are counted but not compared. fcs3d is compared with
ccx 2.20 run here; ccx 2.20 is also compared with the shipped 2.11 results (*.dat.ref).

Output: the table (one row per static deck), the counts, and the refusal reasons ranked by
the number of decks; with --markdown, the same between the MEASURED markers of that file.
Exit status: 0 when the measurement ran (and at least --min-agree 3D-solid decks agree), 1
otherwise, 77 when ccx or the decks are missing.
"""

import argparse
import collections
import concurrent.futures
import datetime
import gzip
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "tools"))
import datfile  # noqa: E402  (tests/tools/datfile.py)

DEFAULT_DECKS = "/usr/share/doc/calculix-ccx-test/examples/test"
PROCEDURES = ("STATIC", "FREQUENCY", "BUCKLE", "DYNAMIC", "MODAL DYNAMIC", "STEADY STATE DYNAMICS",
              "COMPLEX FREQUENCY", "HEAT TRANSFER", "COUPLED TEMPERATURE-DISPLACEMENT",
              "UNCOUPLED TEMPERATURE-DISPLACEMENT", "VISCO", "ELECTROMAGNETICS", "GREEN",
              "SENSITIVITY", "SUBSTRUCTURE GENERATE", "NO ANALYSIS", "CFD", "CRACK PROPAGATION",
              "FEASIBLE DIRECTION", "ROBUST DESIGN")
# Files a deck reads besides itself: ("run", deck, produced file, name read) is a file ccx
# writes when it runs that other deck first; ("shipped", file) a file of the package.
PREREQUISITES = {
    "beamread": [("run", "beamwrite", "beamwrite.rout", "beamread.rin")],
    "submodelbeamp": [("run", "beamp", "beamp.frd", "beamp.frd")],
    "submodeltwobeam": [("shipped", "twobeam.frd")],
}
KINDS = ("displacements", "stresses", "forces", "contact", "other")
NOISE_FLOOR = 1.0e-10  # datcheck.pl: tables below this are round-off, not results
TIME_TOLERANCE = 1.0e-6  # times are printed with 7 digits


# ---------------------------------------------------------------------------------- decks

def read_text(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", encoding="latin-1") as handle:
        return handle.read()


def find_decks(directory):
    """{name: path} of every deck (name.inp or name.inp.gz) in the package directory."""
    decks = {}
    for entry in sorted(os.listdir(directory)):
        for suffix in (".inp", ".inp.gz"):
            if entry.endswith(suffix):
                decks[entry[:-len(suffix)]] = os.path.join(directory, entry)
    return decks


def shipped_file(directory, name):
    """The path of a shipped file (name or name.gz), or None."""
    for candidate in (name, name + ".gz"):
        path = os.path.join(directory, candidate)
        if os.path.exists(path):
            return path
    return None


class DeckInfo:
    """What a deck asks for: its procedures (per step), element kinds and keywords."""

    def __init__(self, name, text):
        self.name = name
        self.steps = []          # procedure keywords of each *STEP
        self.procedures = []     # every procedure keyword, in order
        self.element_kinds = set()
        self.keywords = collections.Counter()
        for line in text.splitlines():
            stripped = line.strip().lstrip("\ufeff")
            if not stripped.startswith("*") or stripped.startswith("**"):
                continue
            fields = stripped[1:].split(",")
            keyword = " ".join(fields[0].upper().split())
            self.keywords[keyword] += 1
            if keyword == "STEP":
                self.steps.append([])
            elif keyword in PROCEDURES:
                self.procedures.append(keyword)
                if self.steps:
                    self.steps[-1].append(keyword)
            elif keyword == "ELEMENT":
                for field in fields[1:]:
                    name_value = field.split("=", 1)
                    if len(name_value) == 2 and name_value[0].strip().upper() == "TYPE":
                        self.element_kinds.add(name_value[1].strip().upper())
            elif keyword == "USER ELEMENT":
                self.element_kinds.add("USER")

    @property
    def static(self):
        return bool(self.steps) and set(self.procedures) == {"STATIC"}

    @property
    def solid(self):
        return bool(self.element_kinds) and all(k.startswith("C3D") for k in self.element_kinds)

    def kinds_text(self):
        return "+".join(sorted(self.element_kinds)) or "(none)"


# ----------------------------------------------------------------------------------- runs

def run_command(command, cwd, timeout, log_path):
    """Run command in cwd (its own process group, killed on timeout); (status, seconds).
    status is the exit code, or "timeout"."""
    environment = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    start = time.monotonic()
    with open(log_path, "w") as log:
        process = subprocess.Popen(command, cwd=cwd, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, env=environment,
                                   start_new_session=True)
        try:
            status = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            status = "timeout"
    return status, time.monotonic() - start


def copy_deck(source, target_directory, name):
    os.makedirs(target_directory, exist_ok=True)
    target = os.path.join(target_directory, name)
    if source.endswith(".gz"):
        with gzip.open(source, "rb") as handle, open(target, "wb") as out:
            shutil.copyfileobj(handle, out)
    else:
        shutil.copyfile(source, target)
    return target


def ccx_version():
    try:
        out = subprocess.run(["ccx", "-v"], capture_output=True, text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    match = re.search(r"Version\s+(\S+)", out)
    return match.group(1) if match else out.strip() or "unknown"


def first_ccx_error(log_path):
    with open(log_path, errors="replace") as handle:
        for line in handle:
            if "ERROR" in line.upper():
                return line.strip()
    return None


class Suite:
    def __init__(self, args, decks):
        self.args = args
        self.decks = decks
        self.version = ccx_version()

    def cache_key(self, name):
        digest = hashlib.sha256()
        digest.update(f"ccx {self.version}\n".encode())
        digest.update(read_text(self.decks[name]).encode("latin-1"))
        for item in PREREQUISITES.get(name, []):
            if item[0] == "run":
                digest.update(read_text(self.decks[item[1]]).encode("latin-1"))
            else:
                digest.update(read_text(shipped_file(self.args.decks, item[1])).encode("latin-1"))
        return digest.hexdigest()

    def provide_shipped(self, name, directory):
        for item in PREREQUISITES.get(name, []):
            if item[0] == "shipped":
                copy_deck(shipped_file(self.args.decks, item[1]), directory, item[1])

    def run_ccx(self, name):
        """ccx's .dat for the deck (cached): dict with status, seconds, dat (path), message."""
        key = self.cache_key(name)
        cached = os.path.join(self.args.cache, name + "-" + key[:16])
        record_path = os.path.join(cached, "result.json")
        if os.path.exists(record_path):
            with open(record_path) as handle:
                record = json.load(handle)
            record["cached"] = True
            if record.get("dat"):
                record["dat"] = os.path.join(cached, record["dat"])
            return record
        directory = os.path.join(self.args.work, name, "ccx")
        shutil.rmtree(directory, ignore_errors=True)
        copy_deck(self.decks[name], directory, name + ".inp")
        self.provide_shipped(name, directory)
        seconds = 0.0
        for item in PREREQUISITES.get(name, []):
            if item[0] != "run":
                continue
            copy_deck(self.decks[item[1]], directory, item[1] + ".inp")
            _, used = run_command(["ccx", "-i", item[1]], directory, self.args.timeout_ccx,
                                  os.path.join(directory, item[1] + ".ccx.log"))
            seconds += used
            produced = os.path.join(directory, item[2])
            if os.path.exists(produced) and item[2] != item[3]:
                shutil.copyfile(produced, os.path.join(directory, item[3]))
        log = os.path.join(directory, "ccx.log")
        status, used = run_command(["ccx", "-i", name], directory, self.args.timeout_ccx, log)
        seconds += used
        dat = os.path.join(directory, name + ".dat")
        record = {"status": status, "seconds": round(seconds, 2), "version": self.version,
                  "message": None, "dat": None}
        if status != 0 or not os.path.exists(dat):
            record["message"] = ("timeout" if status == "timeout" else
                                 first_ccx_error(log) or f"exit status {status}, no .dat")
        os.makedirs(cached, exist_ok=True)
        if os.path.exists(dat):
            shutil.copyfile(dat, os.path.join(cached, name + ".dat"))
            record["dat"] = name + ".dat"
        shutil.copyfile(log, os.path.join(cached, "ccx.log"))
        with open(record_path, "w") as handle:
            json.dump(record, handle, indent=1)
        record["cached"] = False
        if record["dat"]:
            record["dat"] = os.path.join(cached, record["dat"])
        return record

    def run_fcs3d(self, name):
        """fcs3d's run of the deck: dict with status (exit code or "timeout"), seconds, dat,
        message (the first error, file:line: text)."""
        directory = os.path.join(self.args.work, name, "fcs3d")
        shutil.rmtree(directory, ignore_errors=True)
        copy_deck(self.decks[name], directory, name + ".inp")
        self.provide_shipped(name, directory)
        log = os.path.join(directory, "fcs3d.log.txt")
        status, seconds = run_command([self.args.fcs3d, "-q", name + ".inp"], directory,
                                      self.args.timeout_fcs3d, log)
        with open(log, errors="replace") as handle:
            lines = [line.rstrip("\n") for line in handle]
        dat = os.path.join(directory, name + ".dat")
        return {"status": status, "seconds": round(seconds, 2),
                "dat": dat if os.path.exists(dat) else None,
                "errors": error_messages(lines), "message": first_message(lines, status)}


def error_messages(lines):
    """fcs3d's input errors: "file:line: text" (the first is prefixed "fcs3d: ")."""
    messages = []
    for line in lines:
        if line.startswith("fcs3d: "):
            line = line[len("fcs3d: "):]
        if re.match(r"^\S+?:\d+: ", line):
            messages.append(line.strip())
    return messages


def short_message(text, width):
    """The first sentence of a message, at most width characters."""
    end = text.find(". ")
    text = text[:end + 1] if end > 0 else text
    return text if len(text) <= width else text[:width - 3] + "..."


def first_message(lines, status):
    if status == 0:
        return None
    if status == "timeout":
        return "timeout"
    for line in lines:
        text = line.strip()
        if text:
            return text[len("fcs3d: "):] if text.startswith("fcs3d: ") else text
    return f"exit status {status}, no message"


# ----------------------------------------------------------------------------- comparison

def is_number(text):
    try:
        datfile.parse_number(text)
    except ValueError:
        return False
    return True


def normalised_copy(path, directory):
    """A copy of a .dat file that datfile.read_blocks takes, with the same numbers:
    - "for all contact elements" becomes "for set ALL-CONTACT"; the blanks ccx 2.11 leaves out
      ("pe)for set", "forset") are put back and its "(elem, integ.pnt.,eneset" is written as
      2.20 writes it, "(elem, integ.pnt.,energy) for set";
    - words ccx 2.20 appends to a row are dropped ("L": the values are in the local system of
      a *TRANSFORM; the name of a shell's expanded element set);
    - a row key repeated within a table (surface-to-surface contact prints one row per
      integration point of a slave face, all keyed element, face) gets its occurrence number as
      one more key, so that the n-th row of a key is paired with the n-th."""
    target = os.path.join(directory, os.path.basename(path) + ".read")
    seen = collections.Counter()
    with open(path, encoding="ascii", errors="replace") as handle, open(target, "w") as out:
        for line in handle:
            if " and time" in line:
                line = line.replace(" for all contact elements and time",
                                    " for set ALL-CONTACT and time")
                line = re.sub(r"\)for set ", ") for set ", line)
                line = re.sub(r"\bforset ", "for set ", line)
                line = line.replace(",eneset ", ",energy) for set ")
                seen.clear()
                out.write(line)
                continue
            fields = line.split()
            keys = []
            while len(keys) < len(fields) and re.fullmatch(r"[+-]?\d+", fields[len(keys)]):
                keys.append(fields[len(keys)])
            values = fields[len(keys):]
            if not values or not is_number(values[0]):
                out.write(line)
                continue
            while not is_number(values[-1]):
                values.pop()
            seen[tuple(keys)] += 1
            if keys and seen[tuple(keys)] > 1:
                keys = keys + [str(seen[tuple(keys)] - 1)]
            out.write(" " + " ".join(keys + values) + "\n")
    return target


def table_kind(title):
    if "contact" in title:
        return "contact"
    first = title.split()[0]
    if first == "displacements":
        return "displacements"
    if first == "stresses":
        return "stresses"
    if first == "forces" or title.startswith("total force"):
        return "forces"
    return "other"


def table_error(reference, other):
    """(error, problem) of one pair of tables: the datcheck.pl error over the common rows, and
    a note when the rows or columns differ."""
    common = [key for key in reference.order if key in other.rows]
    # ccx 2.20 prints a row of exact zeros for every id of a set that names no node (a
    # *NSET, GENERATE range over gaps in the numbering); fcs3d's sets hold nodes only, so it
    # has no such row. A missing row of exact zeros is not counted as missing.
    phantom = [key for key in reference.order if key not in other.rows and
               all(float(v) == 0.0 for v in reference.rows[key])]
    missing = len(reference.rows) - len(common) - len(phantom)
    extra = len(other.rows) - len(common)
    problem = None
    if missing or extra:
        problem = f"rows: {missing} missing, {extra} extra"
    if not common:
        return float("inf"), problem or "no rows"
    try:
        a = np.array([reference.rows[key] for key in common], dtype=float)
        b = np.array([other.rows[key] for key in common], dtype=float)
    except ValueError:
        return float("inf"), "ragged rows"
    if a.shape != b.shape:
        return float("inf"), f"columns {a.shape[1:]} and {b.shape[1:]}"
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        return float("inf"), "NaN or Inf"
    scale_a = np.abs(a).max() if a.size else 0.0
    scale_b = np.abs(b).max() if b.size else 0.0
    if scale_a <= NOISE_FLOOR and scale_b <= NOISE_FLOOR:
        return 0.0, problem
    scale = scale_a if scale_a > NOISE_FLOOR else scale_b
    return float(np.abs(a - b).max() / scale), problem


def compare_dat(reference_path, other_path, scratch, tolerance):
    """Compare two .dat files table by table. Returns a dict: errors {kind: max error},
    problems (list), paired, unpaired (reference tables at times the other did not print),
    agree (bool), tables (number of reference tables)."""
    result = {"errors": {}, "problems": [], "paired": 0, "unpaired": 0, "tables": 0,
              "agree": False}
    try:
        reference = datfile.read_blocks(normalised_copy(reference_path, scratch))
        other = datfile.read_blocks(normalised_copy(other_path, scratch)) if other_path else []
    except ValueError as error:
        result["problems"].append(f"unreadable: {error}")
        return result
    result["tables"] = len(reference)
    if not reference:
        result["problems"].append("no tables in the reference")
        return result
    available = collections.defaultdict(list)
    for block in other:
        available[(block.title, block.set_name)].append(block)
    last = {}
    for index, block in enumerate(reference):
        last[(block.title, block.set_name)] = index
    for index, block in enumerate(reference):
        group = (block.title, block.set_name)
        candidates = available.get(group, [])
        match = None
        for position, candidate in enumerate(candidates):
            if abs(candidate.time - block.time) <= TIME_TOLERANCE * max(1.0, abs(block.time)):
                match = candidates.pop(position)
                break
        if match is None:
            result["unpaired"] += 1
            if last[group] == index:
                result["problems"].append(f"no '{block.title}' for set {block.set_name} at "
                                          f"time {block.time:g} (the reference's last)")
            continue
        result["paired"] += 1
        error, problem = table_error(block, match)
        kind = table_kind(block.title)
        result["errors"][kind] = max(result["errors"].get(kind, 0.0), error)
        if problem:
            result["problems"].append(f"{block.label()}: {problem}")
        elif not error <= tolerance:
            result["problems"].append(f"{block.label()}: error {error:.2e}")
    result["agree"] = result["paired"] > 0 and not result["problems"]
    return result


# ---------------------------------------------------------------------------- refusals

def reason_category(message):
    """A refusal message reduced to what has to be built, without file:line and numbers:
    "*ELEMENT, TYPE=C3D20R", "*EQUATION (not supported)", "*STATIC, DIRECT (unknown
    parameter)", "*PLASTIC (unknown keyword)"..."""
    text = re.sub(r"^\S+?:\d+: ", "", message)
    keyword = r"(\*[A-Z][A-Z0-9 ,=-]*?)"
    patterns = (
        (r"^\*ELEMENT: TYPE=(\S+) is not valid", lambda m: f"*ELEMENT, TYPE={m.group(1)}"),
        (r"^(\*[A-Z][A-Z0-9 -]*?) is not supported", lambda m: f"{m.group(1)} (not supported)"),
        (r"^unknown keyword (\*[A-Z0-9][A-Z0-9 -]*[A-Z0-9])",
         lambda m: f"{m.group(1)} (unknown keyword)"),
        (keyword + r": unknown parameter \"([^\"=]*)",
         lambda m: f"{m.group(1)}, {m.group(2).strip().upper()} (unknown parameter)"),
        (keyword + r": output variable \"([^\"]*)\" is not available",
         lambda m: f"{m.group(1)}: output variable {m.group(2)} (not available)"),
        (keyword + r": ([A-Z-]+=.+?) is not valid",
         lambda m: f"{m.group(1)}, {m.group(2)} (not valid)"),
        (keyword + r": (element|node)( set)? .*is not defined",
         lambda m: "undefined element, node or set (mostly after a refused *ELEMENT)"),
    )
    for pattern, make in patterns:
        match = re.match(pattern, text)
        if match:
            return make(match)
    text = re.sub(r"\"[^\"]*\"", "\"..\"", text)
    text = re.sub(r"\b\d+\b", "N", text)
    text = re.sub(r"\(set at .*", "", text)
    return text.split(";")[0].strip()[:120]


# ------------------------------------------------------------------------------- report

def format_error(value):
    if value is None:
        return "-"
    if value == float("inf"):
        return "inf"
    return f"{value:.1e}"


def deck_row(entry):
    """The cells of one deck's row: the fcs3d status, one error per table kind, agree."""
    fcs, ccx = entry["fcs3d"], entry["ccx"]
    comparison = entry.get("comparison")
    if fcs["status"] == 0:
        state = "run"
    elif fcs["status"] == 2:
        state = "refused"
    elif fcs["status"] == "timeout":
        state = "timeout"
    else:
        state = f"failed ({fcs['status']})"
    errors = {}
    if comparison:
        for kind in KINDS:
            errors[kind] = format_error(comparison["errors"].get(kind))
    if not ccx.get("dat"):
        agree = "no ccx"
    elif entry.get("ccx_tables", 0) == 0:
        agree = "no tables"
    elif fcs["status"] != 0:
        agree = "-"
    else:
        agree = "yes" if comparison["agree"] else "no"
    return state, errors, agree


def versions_cell(entry):
    versions = entry.get("versions")
    if versions is None:
        return "no 2.11 ref" if entry["ccx"].get("dat") else "-"
    if versions["tables"] == 0:
        return "empty"
    worst = max(versions["errors"].values()) if versions["errors"] else None
    return ("" if versions["agree"] else "DIFFERS ") + format_error(worst)


def text_table(entries):
    header = (f"{'deck':<22} {'elements':<13} {'3D':<3} {'fcs3d':<11} {'displ':>8} {'stress':>8} "
              f"{'force':>8} {'contact':>8} {'other':>8} {'agree':<9} ccx2.20-vs-2.11")
    lines = [header, "-" * len(header)]
    for entry in entries:
        info = entry["info"]
        state, errors, agree = deck_row(entry)
        cells = [errors.get(kind, "") for kind in KINDS]
        lines.append(f"{entry['name']:<22} {info.kinds_text()[:13]:<13} "
                     f"{'yes' if info.solid else 'no':<3} {state:<11} "
                     + " ".join(f"{c:>8}" for c in cells) + f" {agree:<9} {versions_cell(entry)}")
        if entry["fcs3d"]["status"] != 0 and entry["fcs3d"]["message"]:
            lines.append(f"{'':<22} {short_message(entry['fcs3d']['message'], 140)}")
        elif entry.get("comparison") and entry["comparison"]["problems"] and agree == "no":
            lines.append(f"{'':<22} {entry['comparison']['problems'][0][:140]}")
    return "\n".join(lines)


def markdown_escape(text):
    return text.replace("|", "\\|").replace("*", "\\*").replace("_", "\\_")


def markdown_table(entries):
    lines = ["| deck | elements | 3D solid | fcs3d | displ. | stress | force | contact | other "
             "| agree | ccx 2.20 vs 2.11 | fcs3d's first reason (refused), or first difference |",
             "|---|---|---|---|---:|---:|---:|---:|---:|---|---|---|"]
    for entry in entries:
        info = entry["info"]
        state, errors, agree = deck_row(entry)
        note = entry["fcs3d"]["message"] or ""
        if not note and entry.get("comparison") and agree == "no":
            note = entry["comparison"]["problems"][0]
        cells = [entry["name"], info.kinds_text(), "yes" if info.solid else "no", state]
        cells += [errors.get(kind, "") for kind in KINDS]
        cells += [agree, versions_cell(entry), markdown_escape(short_message(note, 160))]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def rankings(entries):
    """Refusal reasons ranked by the number of decks: (first reason, any reason) counters over
    the 3D-solid decks and over all static decks."""
    first = {"solid": collections.Counter(), "all": collections.Counter()}
    any_reason = {"solid": collections.Counter(), "all": collections.Counter()}
    for entry in entries:
        fcs = entry["fcs3d"]
        if fcs["status"] == 0:
            continue
        groups = ["all"] + (["solid"] if entry["info"].solid else [])
        if fcs["status"] == 2:
            head = reason_category(fcs["message"])
        else:
            head = f"run failed: {fcs['message']}"
        categories = {reason_category(m) for m in fcs["errors"]} or {head}
        for group in groups:
            first[group][head] += 1
            for category in categories:
                any_reason[group][category] += 1
    return first, any_reason


def ranking_lines(counters, markdown):
    solid, every = counters["solid"], counters["all"]
    keys = sorted(set(solid) | set(every), key=lambda k: (-solid[k], -every[k], k))
    if markdown:
        lines = ["| 3D-solid decks | static decks | reason |", "|---:|---:|---|"]
        lines += [f"| {solid[k]} | {every[k]} | {markdown_escape(k)} |" for k in keys]
    else:
        lines = [f"{'3D solid':>8} {'static':>6}  reason"]
        lines += [f"{solid[k]:>8} {every[k]:>6}  {k}" for k in keys]
    return lines


def counts(entries, all_infos):
    solid = [e for e in entries if e["info"].solid]
    result = {"decks": len(all_infos),
              "static": sum(1 for i in all_infos.values() if i.static),
              "solid": sum(1 for i in all_infos.values() if i.static and i.solid)}
    for label, group in (("static", entries), ("solid", solid)):
        states = collections.Counter(deck_row(e)[0].split(" ")[0] for e in group)
        agrees = collections.Counter(deck_row(e)[2] for e in group)
        result[label + "_states"] = states
        result[label + "_agree"] = agrees
    kinds = collections.Counter()
    for info in all_infos.values():
        if info.static and info.solid:
            for kind in info.element_kinds:
                kinds[kind] += 1
    result["solid_kinds"] = kinds
    procedures = collections.Counter()
    for info in all_infos.values():
        if not info.static:
            for procedure in set(info.procedures) - {"STATIC"}:
                procedures[procedure] += 1
    result["procedures"] = procedures
    result["no_step"] = sorted(n for n, i in all_infos.items() if not i.steps)
    return result


def summary_lines(c, entries, tolerance):
    def state_text(label):
        states, agrees = c[label + "_states"], c[label + "_agree"]
        return (f"fcs3d run {states.get('run', 0)}, refused {states.get('refused', 0)}, "
                f"failed {states.get('failed', 0)}, timeout {states.get('timeout', 0)}; "
                f"agree with ccx 2.20 within {tolerance:g}: {agrees.get('yes', 0)}")
    ccx_failed = [e["name"] for e in entries if not e["ccx"].get("dat") or e["ccx"]["status"] != 0]
    no_tables = [e["name"] for e in entries if e["ccx"].get("dat") and e.get("ccx_tables", 0) == 0]
    comparable = sum(1 for e in entries if e["info"].solid and e.get("ccx_tables", 0) > 0)
    differs = [e["name"] for e in entries if e.get("versions") and e["versions"]["tables"]
               and not e["versions"]["agree"]]
    lines = [
        f"decks in calculix-ccx-test: {c['decks']}; static: {c['static']}; static with 3D solid "
        f"elements only: {c['solid']}",
        "element kinds of the 3D-solid static decks (decks using each): "
        + ", ".join(f"{k} {n}" for k, n in c["solid_kinds"].most_common()),
        "the other decks use (decks per procedure): "
        + ", ".join(f"*{k} {n}" for k, n in c["procedures"].most_common()),
        f"static decks measured ({len(entries)}): " + state_text("static"),
        f"3D-solid static decks measured ({sum(1 for e in entries if e['info'].solid)}): "
        + state_text("solid"),
        f"ccx 2.20 failed ({len(ccx_failed)}): " + (", ".join(ccx_failed) or "none"),
        f"ccx 2.20 printed no .dat table ({len(no_tables)}; the package checks them by .frd): "
        + (", ".join(no_tables) or "none"),
        "3D-solid static decks with .dat tables to compare (the most that can agree): "
        f"{comparable}",
        f"ccx 2.20 differs from the shipped 2.11 .dat.ref by more than {tolerance:g} "
        f"({len(differs)}): " + (", ".join(differs) or "none"),
    ]
    return lines


def write_markdown(path, text):
    begin = "<!-- BEGIN MEASURED (tests/validate/calculix_suite.py) -->"
    end = "<!-- END MEASURED -->"
    old = open(path).read() if os.path.exists(path) else f"# CalculiX's static test decks\n\n{begin}\n{end}\n"
    if begin not in old or end not in old:
        old = old.rstrip("\n") + f"\n\n{begin}\n{end}\n"
    head, rest = old.split(begin, 1)
    tail = rest.split(end, 1)[1]
    with open(path, "w") as handle:
        handle.write(head + begin + "\n" + text.rstrip("\n") + "\n" + end + tail)


def git_revision():
    try:
        out = subprocess.run(["git", "describe", "--always", "--dirty", "--abbrev=12"], cwd=ROOT,
                             capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        out = ""
    return out or "unknown"


def package_version(package):
    try:
        return subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], capture_output=True,
                              text=True, timeout=30).stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


# --------------------------------------------------------------------------------- main

def measure(suite, name, infos, scratch_root):
    """Run one deck through ccx (cached) and fcs3d and compare."""
    args = suite.args
    entry = {"name": name, "info": infos[name]}
    entry["ccx"] = suite.run_ccx(name)
    entry["fcs3d"] = suite.run_fcs3d(name)
    scratch = tempfile.mkdtemp(prefix=name + ".", dir=scratch_root)
    ccx_dat = entry["ccx"].get("dat")
    if ccx_dat:
        try:
            entry["ccx_tables"] = len(datfile.read_blocks(normalised_copy(ccx_dat, scratch)))
        except ValueError as error:
            entry["ccx"]["message"] = f"unreadable .dat: {error}"
            entry["ccx_tables"] = 0
        if entry["fcs3d"]["status"] == 0:
            entry["comparison"] = compare_dat(ccx_dat, entry["fcs3d"]["dat"], scratch, args.tolerance)
        reference = shipped_file(args.decks, name + ".dat.ref")
        if reference:
            local = copy_deck(reference, scratch, name + ".dat.ref")
            entry["versions"] = compare_dat(local, ccx_dat, scratch, args.tolerance)
    shutil.rmtree(scratch, ignore_errors=True)
    return entry


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fcs3d", required=True)
    parser.add_argument("--decks", default=DEFAULT_DECKS)
    parser.add_argument("--work", help="scratch directory (default: a temporary one, removed)")
    parser.add_argument("--cache", default=os.path.join(ROOT, "build", "calculix_suite", "ccx"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout-ccx", type=float, default=300.0)
    parser.add_argument("--timeout-fcs3d", type=float, default=300.0)
    parser.add_argument("--tolerance", type=float, default=1.0e-2)
    parser.add_argument("--only", help="comma-separated deck names (default: every static deck)")
    parser.add_argument("--markdown", help="rewrite the measured part of this file")
    parser.add_argument("--min-agree", type=int, default=0,
                        help="fail when fewer 3D-solid static decks agree")
    args = parser.parse_args()
    command_line = " ".join(["tests/validate/calculix_suite.py"] +
                            [a.replace(ROOT + os.sep, "") for a in sys.argv[1:]])
    if shutil.which("ccx") is None:
        print("ccx (Debian package calculix-ccx) is not installed")
        return 77
    if not os.path.isdir(args.decks):
        print(f"{args.decks}: no such directory (install Debian's calculix-ccx-test)")
        return 77
    args.fcs3d = os.path.abspath(args.fcs3d)
    args.cache = os.path.abspath(args.cache)
    started = time.monotonic()
    decks = find_decks(args.decks)
    infos = {name: DeckInfo(name, read_text(path)) for name, path in decks.items()}
    names = sorted(n for n, i in infos.items() if i.static)
    if args.only:
        wanted = args.only.split(",")
        unknown = [n for n in wanted if n not in decks]
        if unknown:
            print("unknown decks: " + ", ".join(unknown))
            return 1
        names = [n for n in names if n in wanted] + [n for n in wanted if n not in names]
    temporary = None
    if args.work is None:
        temporary = tempfile.mkdtemp(prefix="fcs3d-calculix-suite.")
        args.work = temporary
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    os.makedirs(args.cache, exist_ok=True)
    suite = Suite(args, decks)
    print(f"{len(names)} decks through ccx {suite.version} and {args.fcs3d}, {args.jobs} at a time "
          f"(work {args.work}, ccx cache {args.cache})", flush=True)
    entries = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(measure, suite, name, infos, args.work) for name in names]
        for future in concurrent.futures.as_completed(futures):
            entries.append(future.result())
            if sys.stderr.isatty():
                print(f"\r{len(entries)}/{len(names)}", end="", file=sys.stderr, flush=True)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    entries.sort(key=lambda e: (not e["info"].solid, e["name"]))
    elapsed = time.monotonic() - started
    ccx_run = [e for e in entries if not e["ccx"].get("cached")]
    c = counts(entries, infos)
    first, any_reason = rankings(entries)

    print()
    print(text_table(entries))
    print()
    for line in summary_lines(c, entries, args.tolerance):
        print(line)
    print()
    print("Refusal reasons, first reason of each deck (decks):")
    print("\n".join(ranking_lines(first, False)))
    print()
    print("Refusal reasons, every reason fcs3d reports (decks; fcs3d shows at most 20 per deck):")
    print("\n".join(ranking_lines(any_reason, False)))
    print()
    print(f"{len(entries)} decks in {elapsed:.0f} s (ccx run for {len(ccx_run)}, cached for "
          f"{len(entries) - len(ccx_run)}; fcs3d {sum(e['fcs3d']['seconds'] for e in entries):.0f} s, "
          f"ccx {sum(e['ccx']['seconds'] for e in ccx_run):.0f} s of run time)")

    if args.markdown:
        stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        fcs_version = subprocess.run([args.fcs3d, "--version"], capture_output=True,
                                     text=True).stdout.strip()
        parts = [
            f"Measured {stamp} at commit `{git_revision()}` with `{fcs_version}`, ccx "
            f"{suite.version} (Debian calculix-ccx {package_version('calculix-ccx')}) and the "
            f"decks of calculix-ccx-test {package_version('calculix-ccx-test')}, by `make "
            "ccx-suite` (or `make validate`), which ran",
            "", f"    {command_line}", "",
            f"({len(entries)} decks in {elapsed:.0f} s; ccx run for {len(ccx_run)} decks, "
            f"taken from the cache for {len(entries) - len(ccx_run)}.)", "",
            "### Counts", ""]
        parts += [f"- {line}" for line in summary_lines(c, entries, args.tolerance)]
        parts += ["", "### Refusal reasons, first reason of each deck", ""]
        parts += ranking_lines(first, True)
        parts += ["", "### Refusal reasons, every reason fcs3d reports", "",
                  "fcs3d lists at most 20 errors per deck, and only those of reading the deck.", ""]
        parts += ranking_lines(any_reason, True)
        solid = [e for e in entries if e["info"].solid]
        others = [e for e in entries if not e["info"].solid]
        parts += ["", "### The decks", "",
                  f"Errors are max |fcs3d - ccx| / max |ccx| per table (largest over the tables of "
                  f"a kind); agree: every table within {args.tolerance:g}.", "",
                  f"#### 3D-solid static decks ({len(solid)})", "", markdown_table(solid), "",
                  f"#### Other static decks ({len(others)})", "", markdown_table(others)]
        write_markdown(args.markdown, "\n".join(parts))
        print(f"wrote {args.markdown}")
    if temporary:
        shutil.rmtree(temporary, ignore_errors=True)
    agreeing = c["solid_agree"].get("yes", 0)
    if agreeing < args.min_agree:
        print(f"FAIL: {agreeing} 3D-solid static decks agree with ccx, fewer than {args.min_agree}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
