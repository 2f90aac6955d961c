#!/usr/bin/python3
"""The paper's narrative of the fault-bend model, measured in an fcs3d results file.

Xing, Mora & Makinouchi (2003), section 3, describe the Mises stress maps of their Figs. 2 and 3
in words. This script turns each statement into numbers read from a run of
input/fault_bend/fault_bend.inp and says, for each, whether the run shows it (yes / partly /
no) and by which criterion. Nothing is taken from a previous run: every number comes from the
results file, its *HISTORY CSV, its event catalog and its log.

Usage:
    /usr/bin/python3 post/fault_bend_zones.py --results run/fault_bend/fault_bend.h5
        [--deck DECK] [--geo GEO] [--setnumber NAME VALUE ...] [--band 15] [--far 50]
        [--slip-threshold 1e-4] [--figure doc/figures/fault_bend_mises_change.png]

Zones (all elements through the thickness; element-mean Mises stress `cell/mises`, i.e. the
mean of the Gauss-point values; means weighted by element volume in the reference
configuration):
  CD, DE, EF, FG  elements whose centroid projects onto the segment (0 <= s <= length) and lies
                  within --band mm (default 15) of its line, on either side;
  far             elements whose centroid is more than --far mm (default 50) from the trace.
The fault activity between two times comes from the contact grids of the frames: a slave node
"slipped" in an interval if its accumulated slip grew by more than --slip-threshold mm
(default 1e-4 mm, well below the slip of the smallest catalogued event, about 2e-3 mm in the
default run); nodes of the single D-F pair are assigned to D-E or E-F by their position along
the trace (a node at E to both), as post/make_figures.py does. Events come from
<job>_events.csv, their segment from the hypocentre's position along the trace.

The verdict rules are printed with the verdicts. The paper's times are total times with stage
1 assumed to last 10 s (the paper does not give its length); the end of stage 1 is read from
the results.

Output: a Markdown report on standard output; with --figure, maps of the change of the Mises
stress between consecutive paper times minus the far field's mean change (mid-thickness element
layer; elements whose stress fell outlined) with the nodes that slipped in each interval, and a
map of the zones.
"""

import argparse
import os
import sys

import numpy as np

import fault_profile
import make_figures as mf

#: The paper's Fig. 3 times [s] (total time, stage 1 = 10 s assumed).
PAPER_TIMES = (228.7, 292.75, 296.15, 302.98, 311.08, 329.93, 369.78)
SEGMENTS = ("CD", "DE", "EF", "FG")
ZONES = SEGMENTS + ("far",)
#: A stage-1 map is "smooth" if no element deviates from the far-field mean by more than this.
SMOOTH_RELATIVE = 0.05
#: A rise of an end zone is "clear" if it exceeds the far-field rise by more than this [MPa].
CLEAR_RISE = 1.0
#: Nodes closer than this along the trace to a slipped node are its "neighbours" [mm]
#: (about two slave-node spacings of the default mesh).
NEIGHBOUR_DISTANCE = 20.0
#: 2 x 2 x 2 Gauss points of the reference hexahedron.
GAUSS = np.array([[a, b, c] for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)]) / np.sqrt(3.0)
HEX_CORNERS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                        [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)


def hex_volumes(x, connectivity):
    """Volumes of trilinear hexahedra (gmsh/fcs3d node order), 2x2x2 Gauss quadrature."""
    corners = x[connectivity]                                        # (e, 8, 3)
    volume = np.zeros(len(connectivity))
    for xi in GAUSS:
        dn = np.empty((8, 3))
        for k in range(3):
            others = [j for j in range(3) if j != k]
            dn[:, k] = HEX_CORNERS[:, k] / 8.0 * np.prod(
                1.0 + HEX_CORNERS[:, others] * xi[others], axis=1)
        jacobian = np.einsum("eai,ak->eik", corners, dn)
        volume += np.linalg.det(jacobian)
    return volume


class Run:
    """Results, trace, zones and fault data of one run."""

    def __init__(self, arguments):
        self.results = mf.Results(arguments.results)
        r = self.results
        stem = os.path.splitext(arguments.results)[0]
        deck = arguments.deck or stem + ".inp"
        self.pairs = mf.deck_pairs(deck) if os.path.exists(deck) else {}
        self.label = mf.run_label(r, deck if os.path.exists(deck) else None,
                                  arguments.setnumber)
        grids = r.grid_names()
        if not self.pairs:
            self.pairs = {seg: (seg,) for seg in SEGMENTS}
            self.pairs.update(mf.COMBINED)
        self.pairs = {p: c for p, c in self.pairs.items() if f"contact_{p}" in grids}
        self.trace, self.trace_source = mf.fault_trace(r, self.pairs, arguments)
        self.views = mf.segment_views(r, self.pairs, self.trace)
        x, conn = r.x_ref, r.connectivity
        centroid = x[conn].mean(axis=1)
        self.volume = hex_volumes(x, conn)
        self.zones = {}
        for seg in SEGMENTS:
            s, n = self.trace.project(centroid[:, :2], seg)
            self.zones[seg] = (s >= 0) & (s <= self.trace.lengths[seg]) & \
                (np.abs(n) <= arguments.band)
        self.distance = self.trace.along(centroid[:, :2])[2]
        self.zones["far"] = self.distance > arguments.far
        self.stage_1_end = r.step_end(1) or mf.STAGE_1_END
        self.times = [self.stage_1_end] + [t for t in PAPER_TIMES if r.frame_at(t) is not None]
        self.missing = [t for t in PAPER_TIMES if r.frame_at(t) is None]
        self.mises = {}
        for t in self.times:
            values = r.field(r.frame_at(t), "cell", "mises")
            if values is None:
                raise ValueError(f"{arguments.results}: the frame at t = {t:g} s has no cell "
                                 f"field 'mises' (*EL FILE S at the paper's time points)")
            self.mises[t] = values
        self.events = mf.read_csv_table(stem + "_events.csv")
        self.history = mf.history_tables(arguments.results)
        self.log = stem + ".log"
        self.threshold = arguments.slip_threshold

    def mean(self, t, zone):
        w = self.volume[self.zones[zone]]
        return float(np.sum(self.mises[t][self.zones[zone]] * w) / np.sum(w))

    def fault_nodes(self):
        """[(segment, grid, indices, along)] of the fault's slave nodes (all four segments)."""
        out = []
        for seg, grid, picked in self.views:
            xy = self.results.grid_coordinates(0, grid)[picked, :2]
            out.append((seg, grid, picked, self.trace.along(xy)[0]))
        return out

    def grid_values(self, t, grid, name):
        return self.results.grid_field(self.results.frame_at(t), grid, name)

    def slipped(self, t0, t1):
        """{segment: (indices into the segment's node list that slipped in (t0, t1], slip
        increments [mm])}."""
        out = {}
        for seg, grid, picked, _ in self.fault_nodes():
            s0 = self.grid_values(t0, grid, "slip")
            s1 = self.grid_values(t1, grid, "slip")
            if s0 is None or s1 is None:
                continue
            d = s1[picked] - s0[picked]
            out[seg] = (np.nonzero(d > self.threshold)[0], d)
        return out

    def events_between(self, t0, t1):
        """[(onset, nodes, segment of the hypocentre, peak rate, stress drop)] with t0 <= onset
        < t1."""
        if self.events is None or not len(self.events.get("onset", [])):
            return []
        e = self.events
        segment = self.trace.along(np.column_stack([e["x"], e["y"]]))[1]
        keep = np.nonzero((e["onset"] >= t0) & (e["onset"] < t1))[0]
        return [(float(e["onset"][k]), int(e["nodes"][k]), str(segment[k]),
                 float(e["peak_slip_rate"][k]), float(e["stress_drop"][k])) for k in keep]

    def first_slip(self):
        """(time of the first increment of stage 2 ending with DF_SLIP > 0 from the *HISTORY
        table, (time, node, segment) of the first stick->slip limit of stage 2 in the log)."""
        history = None
        for table in self.history.values():
            slip_columns = [c for c in table if c.endswith("_SLIP") and not
                            c.endswith("_SLIP_MEAN")]
            for column in slip_columns:
                hit = np.nonzero((table["time"] > self.stage_1_end + 1e-9) &
                                 (table[column] > 0))[0]
                if len(hit) and (history is None or table["time"][hit[0]] < history):
                    history = float(table["time"][hit[0]])
        log = mf.first_slip_event(self.log)
        located = None
        if log is not None and log[1] is not None:
            ids = self.results.file.get("/mesh/node_ids")
            k = np.nonzero(ids[()] == int(log[1]))[0] if ids is not None else []
            segment = str(self.trace.along(self.results.x_ref[k[0], :2])[1][0]) if len(k) \
                else "?"
            located = (log[0], log[1], segment)
        return history, located


# ------------------------------------------------------------------------------ tables


def fmt(value, digits=2, sign=False):
    if value is None or (isinstance(value, float) and not np.isfinite(value)):
        return "-"
    return f"{value:+.{digits}f}" if sign else f"{value:.{digits}f}"


def table_levels(run):
    lines = ["| time [s] | " + " | ".join(ZONES) + " | " +
             " | ".join(f"{z} - far" for z in SEGMENTS) + " |",
             "|---:|" + "---:|" * (2 * len(ZONES) - 1)]
    for t in run.times:
        far = run.mean(t, "far")
        lines.append(f"| {t:g} | " + " | ".join(fmt(run.mean(t, z)) for z in ZONES) + " | " +
                     " | ".join(fmt(run.mean(t, z) - far, sign=True) for z in SEGMENTS) + " |")
    return lines


def table_changes(run):
    lines = ["| interval [s] | " + " | ".join(f"d {z}" for z in ZONES) + " | " +
             " | ".join(f"d {z} - d far" for z in SEGMENTS) +
             " | elements falling: all / CD / DE / EF / FG |",
             "|---|" + "---:|" * (2 * len(ZONES) - 1) + "---|"]
    for t0, t1 in zip(run.times[:-1], run.times[1:]):
        d = {z: run.mean(t1, z) - run.mean(t0, z) for z in ZONES}
        falling = run.mises[t1] < run.mises[t0]
        shares = [np.mean(falling)] + [np.mean(falling[run.zones[z]]) for z in SEGMENTS]
        lines.append(f"| {t0:g} - {t1:g} | " + " | ".join(fmt(d[z], sign=True) for z in ZONES) +
                     " | " + " | ".join(fmt(d[z] - d["far"], sign=True) for z in SEGMENTS) +
                     " | " + " / ".join(f"{100 * s:.0f} %" for s in shares) + " |")
    return lines


def table_fault(run):
    lines = ["| interval [s] | nodes that slipped (CD / DE / EF / FG, of " +
             " / ".join(str(len(p)) for _, _, p, _ in run.fault_nodes()) +
             ") | largest slip increment [mm] | events: onset [s] (nodes, hypocentre segment) |",
             "|---|---|---:|---|"]
    for t0, t1 in zip(run.times[:-1], run.times[1:]):
        slipped = run.slipped(t0, t1)
        counts = " / ".join(str(len(slipped[s][0])) if s in slipped else "-" for s in SEGMENTS)
        largest = max((float(d.max()) for _, d in slipped.values() if len(d)), default=0.0)
        events = run.events_between(t0, t1)
        text = ", ".join(f"{o:.2f} ({n}, {s})" for o, n, s, _, _ in events) or "none"
        lines.append(f"| {t0:g} - {t1:g} | {counts} | {largest:.2e} | {text} |")
    return lines


def frame_means(run, index):
    """{zone: volume-weighted mean Mises} of frame `index`, or None without 'mises'."""
    values = run.results.field(index, "cell", "mises")
    if values is None:
        return None
    return {z: float(np.sum(values[run.zones[z]] * run.volume[run.zones[z]]) /
                     np.sum(run.volume[run.zones[z]])) for z in ZONES}


def table_big_events(run, slaves):
    """For each event on at least half of the D-E + E-F slave nodes: the zone means minus the
    far field at the last frame before its onset and the first frame after its end."""
    e = run.events
    if e is None or not len(e.get("onset", [])) or not slaves:
        return []
    times = run.results.times
    lines = ["| event | onset [s] | frames used [s] | " +
             " | ".join(f"{z} - far before -> after" for z in SEGMENTS) + " |",
             "|---:|---:|---|" + "---|" * len(SEGMENTS)]
    for k in np.nonzero(e["nodes"] >= 0.5 * slaves)[0]:
        before = np.nonzero(times < e["onset"][k] - 1e-9)[0]
        after = np.nonzero(times > e["end"][k] + 1e-9)[0]
        if not len(before) or not len(after):
            continue
        a, b = frame_means(run, before[-1]), frame_means(run, after[0])
        if a is None or b is None:
            continue
        cells = [f"{a[z] - a['far']:+.2f} -> {b[z] - b['far']:+.2f} "
                 f"({(b[z] - b['far']) - (a[z] - a['far']):+.2f})" for z in SEGMENTS]
        lines.append(f"| {int(e['event'][k])} | {e['onset'][k]:.2f} | {times[before[-1]]:g}, "
                     f"{times[after[0]]:g} | " + " | ".join(cells) + " |")
    if len(lines) == 2:
        return []
    return ["", "Zone mean minus far field [MPa] across each of these events (last frame "
            "before the onset -> first frame after the end; change in brackets):", ""] + lines


def table_events(run):
    """The whole event catalog, with the hypocentre's segment and position along the trace."""
    e = run.events
    if e is None or not len(e.get("onset", [])):
        return ["no events catalogued"]
    xy = np.column_stack([e["x"], e["y"]])
    position, segment, _ = run.trace.along(xy)
    grids = {}
    for seg, grid, picked, _ in run.fault_nodes():
        if seg in ("DE", "EF"):
            grids.setdefault(grid, set()).update(int(k) for k in picked)
    slaves = sum(len(v) for v in grids.values())
    lines = ["| # | onset [s] | duration [s] | nodes | peak slip rate [mm/s] | largest slip "
             "[mm] | mean slip [mm] | mean stress drop [MPa] | hypocentre: segment, mm from C |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for k in range(len(e["onset"])):
        lines.append(f"| {int(e['event'][k])} | {e['onset'][k]:.2f} | {e['duration'][k]:.3f} | "
                     f"{int(e['nodes'][k])} | {e['peak_slip_rate'][k]:.3f} | "
                     f"{e['max_slip'][k]:.2e} | {e['mean_slip'][k]:.2e} | "
                     f"{e['stress_drop'][k]:.2f} | {segment[k]}, {position[k]:.1f} |")
    big = e["nodes"] >= 0.5 * slaves if slaves else np.zeros(len(e["onset"]), bool)
    lines += ["", f"{len(e['onset'])} events; {int(big.sum())} involve at least half of the "
              f"{slaves} slave nodes of D-E and E-F (onsets " +
              ", ".join(f"{t:.2f}" for t in e["onset"][big]) + " s); hypocentres on " +
              ", ".join(f"{s} {int(np.sum(segment == s))}" for s in SEGMENTS) + "."]
    return lines + table_big_events(run, slaves)


# ------------------------------------------------------------------------------ statements


def slip_segments(run, t0, t1):
    return {s: len(v[0]) for s, v in run.slipped(t0, t1).items()}


def statement_stage_1(run):
    t = run.stage_1_end
    m = run.mises[t]
    far = run.mean(t, "far")
    deviation = np.abs(m - far) / far
    worst = float(deviation.max())
    anomaly = {z: run.mean(t, z) - far for z in SEGMENTS}
    peak = {z: float(np.max(np.abs(m[run.zones[z]] - far))) for z in SEGMENTS}
    far_peak = float(np.max(np.abs(m[run.zones["far"]] - far)))
    smooth = worst <= SMOOTH_RELATIVE
    ends_mean = min(abs(anomaly["CD"]), abs(anomaly["FG"])) > max(abs(anomaly["DE"]),
                                                                   abs(anomaly["EF"]))
    ends_peak = min(peak["CD"], peak["FG"]) > max(peak["DE"], peak["EF"])
    verdict = "yes" if smooth and ends_mean and ends_peak else \
        "partly" if smooth and (ends_mean or ends_peak or
                                max(abs(anomaly["CD"]), abs(anomaly["FG"])) >
                                max(abs(anomaly["DE"]), abs(anomaly["EF"]))) else "no"
    text = (f"t = {t:g} s: far-field mean {far:.3f} MPa; the largest deviation of any element "
            f"from it is {100 * worst:.1f} % (smooth if <= {100 * SMOOTH_RELATIVE:.0f} %). "
            "Zone mean minus far field [MPa]: " +
            ", ".join(f"{z} {anomaly[z]:+.3f}" for z in SEGMENTS) +
            "; largest element deviation in each zone [MPa]: " +
            ", ".join(f"{z} {peak[z]:.3f}" for z in SEGMENTS) + f", far {far_peak:.3f}. "
            "Rule: yes if smooth and both end zones (CD, FG) stand out from D-E and E-F in mean "
            "and in largest deviation; partly if smooth and one end zone stands out")
    return verdict, text


def statement_until_first_slip(run):
    t = PAPER_TIMES[0]
    if t not in run.mises:
        return "-", f"no frame at {t:g} s"
    far = run.mean(t, "far")
    worst = float(np.max(np.abs(run.mises[t] - far)) / far)
    history, log = run.first_slip()
    first = history if history is not None else (log[0] if log else None)
    slipped_before = sum(slip_segments(run, run.stage_1_end, t).values())
    where = f"node {log[1]} on {log[2]}; log: {log[0]:.4f} s" if log else \
        "no stick->slip limit in the log"
    if first is None:
        return "no", "no stick->slip in stage 2"
    relative = first / t - 1
    verdict = "yes" if abs(relative) <= 0.05 and worst <= SMOOTH_RELATIVE else \
        "partly" if abs(relative) <= 0.25 else "no"
    text = (f"first stick->slip of stage 2 at {first:.2f} s ({where}) vs the paper's "
            f"{t:g} s: {100 * relative:+.1f} %. At {t:g} s "
            f"{slipped_before} fault nodes have slipped since the end of stage 1 and the largest "
            f"element deviation from the far-field mean ({far:.2f} MPa) is {100 * worst:.1f} %. "
            "Rule: yes if within 5 % of 228.7 s with a smooth map, partly if within 25 %")
    return verdict, text


def statement_de_release(run):
    t0, t1 = 292.75, 296.15
    if t0 not in run.mises or t1 not in run.mises:
        return "-", "no frames at 292.75 and 296.15 s"
    lines = []
    d = {z: run.mean(t1, z) - run.mean(t0, z) for z in ZONES}
    rel = {z: d[z] - d["far"] for z in SEGMENTS}
    falling = run.mises[t1] < run.mises[t0]
    share_de = float(np.mean(falling[run.zones["DE"]]))
    slipped = slip_segments(run, t0, t1)
    events = run.events_between(t0, t1)
    prior = run.times[run.times.index(t0) - 1]
    d_prior = {z: run.mean(t0, z) - run.mean(prior, z) for z in ZONES}
    de_slip = slipped.get("DE", 0) > 0
    de_down = d["DE"] < 0
    de_relative_down = rel["DE"] < 0 and share_de > 0
    neighbours_up = rel["CD"] > 0 and rel["EF"] > 0
    one_neighbour_up = rel["CD"] > 0 or rel["EF"] > 0
    verdict = "yes" if de_slip and de_down and neighbours_up else \
        "partly" if de_slip and (de_down or de_relative_down) and one_neighbour_up else "no"
    lines.append(f"{t0:g} -> {t1:g} s: slipped nodes CD/DE/EF/FG "
                 f"{'/'.join(str(slipped.get(s, 0)) for s in SEGMENTS)}; events " +
                 (", ".join(f"{o:.2f} s ({n} nodes, {s})" for o, n, s, _, _ in events) or "none") +
                 f". Mean change [MPa]: DE {d['DE']:+.3f}, CD {d['CD']:+.3f}, EF {d['EF']:+.3f},"
                 f" FG {d['FG']:+.3f}, far {d['far']:+.3f}; relative to the far field: DE "
                 f"{rel['DE']:+.3f}, CD {rel['CD']:+.3f}, EF {rel['EF']:+.3f}; "
                 f"{100 * share_de:.0f} % of the D-E zone's elements fall. Over {prior:g} -> "
                 f"{t0:g} s (first slips) D-E rises by {d_prior['DE']:+.2f} MPa against "
                 f"{d_prior['far']:+.2f} MPa in the far field. Rule: yes if D-E slips, its "
                 "mean falls and C-D and E-F both rise more than the far field; partly if D-E "
                 "slips, its mean falls or lags the far field (with some elements falling) and "
                 "C-D or E-F rises more than the far field")
    return verdict, " ".join(lines)


def statement_rise_except_de(run):
    t0, t1 = 296.15, 302.98
    if t0 not in run.mises or t1 not in run.mises:
        return "-", "no frames at 296.15 and 302.98 s"
    d = {z: run.mean(t1, z) - run.mean(t0, z) for z in ZONES}
    rising = float(np.mean(run.mises[t1] > run.mises[t0]))
    level = {z: run.mean(t1, z) - run.mean(t1, "far") for z in SEGMENTS}
    smallest_change = min(SEGMENTS, key=lambda z: d[z])
    lowest_level = min(SEGMENTS, key=lambda z: level[z])
    slipped = slip_segments(run, t0, t1)
    events = run.events_between(t0, t1)
    most = rising > 0.5
    verdict = "yes" if most and smallest_change == "DE" else \
        "partly" if most and lowest_level == "DE" else "no"
    text = (f"{t0:g} -> {t1:g} s: {100 * rising:.0f} % of all elements rise; mean change "
            f"[MPa]: " + ", ".join(f"{z} {d[z]:+.3f}" for z in ZONES) +
            f" (smallest: {smallest_change}); slipped nodes CD/DE/EF/FG "
            f"{'/'.join(str(slipped.get(s, 0)) for s in SEGMENTS)}; events " +
            (", ".join(f"{o:.2f} s ({n} nodes, {s})" for o, n, s, _, _ in events) or "none") +
            f". At {t1:g} s, zone mean minus far field [MPa]: " +
            ", ".join(f"{z} {level[z]:+.2f}" for z in SEGMENTS) +
            f" (lowest: {lowest_level}). Rule: yes if most elements rise and D-E rises least; "
            "partly if most rise and D-E is the least stressed zone (an earlier release) but "
            "another zone rises least")
    return verdict, text


def statement_ef_stick_slip(run):
    t0, t1 = 311.08, 369.78
    if t0 not in run.mises or t1 not in run.mises:
        return "-", "no frames at 311.08 and 369.78 s"
    frames = [t for t in run.results.times if t0 - 1e-9 <= t <= t1 + 1e-9]
    intervals = {"DE": 0, "EF": 0}
    drops = {"slipped": [], "neighbours": []}
    pattern = 0
    slipping_intervals = 0
    nodes = {seg: (grid, picked, along) for seg, grid, picked, along in run.fault_nodes()}
    for a, b in zip(frames[:-1], frames[1:]):
        slipped = run.slipped(a, b)
        for seg in ("DE", "EF"):
            if seg in slipped and len(slipped[seg][0]):
                intervals[seg] += 1
        if "EF" not in slipped or not len(slipped["EF"][0]):
            continue
        grid, picked, along = nodes["EF"]
        shear0 = run.grid_values(a, grid, "shear_magnitude")[picked]
        shear1 = run.grid_values(b, grid, "shear_magnitude")[picked]
        moved = slipped["EF"][0]
        still = np.setdiff1d(np.arange(len(picked)), moved)
        near = still[np.min(np.abs(along[still][:, None] - along[moved][None, :]), axis=1)
                     <= NEIGHBOUR_DISTANCE] if len(still) else still
        d_moved = float(np.mean(shear1[moved] - shear0[moved]))
        d_near = float(np.mean(shear1[near] - shear0[near])) if len(near) else np.nan
        drops["slipped"].append(d_moved)
        drops["neighbours"].append(d_near)
        slipping_intervals += 1
        if d_moved < 0 and d_near > 0:
            pattern += 1
    events = run.events_between(t0, t1)
    on = {s: [e for e in events if e[2] == s] for s in SEGMENTS}
    ef_events = len(on["EF"])
    verdict = "yes" if ef_events >= 2 and pattern == slipping_intervals and \
        ef_events >= len(on["DE"]) else \
        "partly" if intervals["EF"] > 0 and pattern > 0 else "no"
    text = (f"{t0:g} -> {t1:g} s, {len(frames) - 1} intervals between frames: E-F nodes slip in "
            f"{intervals['EF']}, D-E nodes in {intervals['DE']}; catalogued events with the "
            f"hypocentre on E-F: {ef_events} (" +
            ", ".join(f"{o:.2f} s, {n} nodes" for o, n, _, _, _ in on["EF"]) +
            f"), on D-E: {len(on['DE'])}. In the intervals with E-F slip the mean change of "
            f"shear traction of the slipped E-F nodes is " +
            ", ".join(fmt(v, 2, True) for v in drops["slipped"]) +
            f" MPa and of their stuck neighbours (within {NEIGHBOUR_DISTANCE:g} mm along the "
            "trace) " + ", ".join(fmt(v, 2, True) for v in drops["neighbours"]) +
            f" MPa (drop at the slipped, rise at the neighbours in {pattern} of "
            f"{slipping_intervals}). Rule: yes if at least two events nucleate on E-F, at least "
            "as many as on D-E, and every E-F slip drops the slipped nodes' shear and raises the "
            "neighbours'; partly if E-F slips with that pattern at least once")
    return verdict, text


def statement_ends_rise(run):
    t0, t1 = 329.93, 369.78
    if t0 not in run.mises or t1 not in run.mises:
        return "-", "no frames at 329.93 and 369.78 s"
    d = {z: run.mean(t1, z) - run.mean(t0, z) for z in ZONES}
    rel = {z: d[z] - d["far"] for z in SEGMENTS}
    earlier = 311.08 if 311.08 in run.mises else t0
    d_e = {z: run.mean(t0, z) - run.mean(earlier, z) for z in ZONES}
    rel_e = {z: d_e[z] - d_e["far"] for z in SEGMENTS}
    level = {z: run.mean(t1, z) - run.mean(t1, "far") for z in SEGMENTS}
    highest = sorted(SEGMENTS, key=lambda z: -level[z])[:2]
    clear = rel["CD"] > CLEAR_RISE and rel["FG"] > CLEAR_RISE
    clear_before = rel_e["CD"] > CLEAR_RISE and rel_e["FG"] > CLEAR_RISE
    verdict = "yes" if clear else \
        "partly" if (clear_before or sorted(highest) == ["CD", "FG"]) else "no"
    text = (f"{t0:g} -> {t1:g} s: mean change [MPa] CD {d['CD']:+.2f}, FG {d['FG']:+.2f}, "
            f"far {d['far']:+.2f}, i.e. {rel['CD']:+.2f} and {rel['FG']:+.2f} above the far "
            f"field; {earlier:g} -> {t0:g} s: {rel_e['CD']:+.2f} and {rel_e['FG']:+.2f} above "
            f"the far field ({d_e['far']:+.2f}). At {t1:g} s the zone means stand "
            + ", ".join(f"{z} {level[z]:+.2f}" for z in SEGMENTS) +
            f" MPa above the far field. Rule: yes if both C-D and F-G rise more than "
            f"{CLEAR_RISE:g} MPa above the far-field rise over {t0:g} -> {t1:g} s; partly if they "
            f"do so over {earlier:g} -> {t0:g} s or are the two most stressed zones")
    return verdict, text


STATEMENTS = (
    ("1", "End of stage 1 (Fig. 2): Mises stress rather smooth except at both ends",
     statement_stage_1),
    ("2", "The same until nodes change from stick to slip, t = 228.7 s",
     statement_until_first_slip),
    ("3", "292.75-296.15 s: stress on D-E decreases and redistributes (slip on D-E); it rises "
     "around C-D and E-F", statement_de_release),
    ("4", "302.98 s: stress rises for most nodes except the released zone around D-E",
     statement_rise_except_de),
    ("5", "311.08-369.78 s: stick-slip on E-F; stress drops at the nodes that slip and rises at "
          "their stuck neighbours", statement_ef_stick_slip),
    ("6", "329.93-369.78 s: clear stress rise at both ends C-D and F-G", statement_ends_rise),
)


# ------------------------------------------------------------------------------ figure


def figure_changes(run, path, z0):
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import Normalize
    r = run.results
    x, conn = r.x_ref, r.connectivity
    layer = mf.layer_elements(x, conn, z0)
    polygons = mf.element_outline_xy(x, conn, layer)
    pairs = list(zip(run.times[:-1], run.times[1:]))
    columns = 4
    rows = (len(pairs) + 1 + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.4 * rows),
                             squeeze=False, constrained_layout=True)
    nodes = run.fault_nodes()
    for ax, (t0, t1) in zip(axes.flat, pairs):
        far = run.mean(t1, "far") - run.mean(t0, "far")
        absolute = (run.mises[t1] - run.mises[t0])[layer]
        change = absolute - far
        top = max(float(np.abs(change).max()), 1e-6)
        collection = PolyCollection(polygons, array=change, cmap="RdBu_r",
                                    norm=Normalize(-top, top), edgecolors="face",
                                    linewidths=0.2)
        ax.add_collection(collection)
        falling = absolute < 0
        if falling.any():
            ax.add_collection(PolyCollection(polygons[falling], facecolors="none",
                                             edgecolors="black", linewidths=0.6))
        mf.draw_trace(ax, run.trace)
        slipped = run.slipped(t0, t1)
        for seg, grid, picked, _ in nodes:
            if seg in slipped and len(slipped[seg][0]):
                xy = r.grid_coordinates(0, grid)[picked[slipped[seg][0]], :2]
                ax.plot(xy[:, 0], xy[:, 1], "o", ms=3.5, mfc="none", mec="#00a000", mew=0.9)
        mf.setup_plan_axes(ax, r)
        ax.set_title(f"{t0:g} -> {t1:g} s (far field {far:+.2f} MPa)", fontsize=8, pad=11)
        fig.colorbar(collection, ax=ax, shrink=0.8).ax.tick_params(labelsize=6)
    ax = list(axes.flat)[len(pairs)]
    colours = dict(mf.SEGMENT_COLOURS, far="#ffbf00")
    for zone in ZONES:
        picked = run.zones[zone][layer]
        ax.add_collection(PolyCollection(polygons[picked], facecolors=colours[zone],
                                         edgecolors="white", linewidths=0.2, alpha=0.8,
                                         label=f"{zone} ({int(run.zones[zone].sum())} elements)"))
    mf.draw_trace(ax, run.trace)
    mf.setup_plan_axes(ax, r)
    ax.legend(fontsize=6, loc="lower right")
    ax.set_title("zones (mid-thickness layer shown)", fontsize=8, pad=11)
    for ax in list(axes.flat)[len(pairs) + 1:]:
        ax.set_visible(False)
    fig.suptitle(f"Change of the element Mises stress [MPa] between the paper's times minus the "
                 f"far field's mean change (in brackets); element layer at z = {z0:g} mm\n"
                 f"black outline: the element's Mises stress fell; green circles: fault nodes "
                 f"that slipped more than {run.threshold:g} mm in the interval", fontsize=9)
    fig.supxlabel(run.label, x=0.005, ha="left", fontsize=5.5, color="0.35")
    fig.savefig(path, dpi=130)
    plt.close(fig)


# ------------------------------------------------------------------------------ main


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--results", required=True, help="fcs3d results file (.h5)")
    parser.add_argument("--deck", help="the run's deck (default: <results>.inp)")
    parser.add_argument("--geo", help="the .geo file (default: next to the results, else "
                        "input/fault_bend/fault_bend.geo)")
    parser.add_argument("-setnumber", "--setnumber", nargs=2, action="append", default=[],
                        metavar=("NAME", "VALUE"))
    parser.add_argument("--band", type=float, default=15.0,
                        help="half-width of the zone around each segment [mm]")
    parser.add_argument("--far", type=float, default=50.0,
                        help="far field: farther than this from the trace [mm]")
    parser.add_argument("--slip-threshold", type=float, default=1e-4,
                        help="slip increment that counts as slip in an interval [mm]")
    parser.add_argument("--figure", help="write the change maps to this PNG")
    arguments = parser.parse_args()
    if not os.path.exists(arguments.results):
        print(f"fault_bend_zones.py: {arguments.results}: no such file", file=sys.stderr)
        return 2
    here = os.path.dirname(os.path.abspath(arguments.results))
    if arguments.geo is None:
        local = os.path.join(here, "fault_bend.geo")
        arguments.geo = local if os.path.exists(local) else fault_profile.DEFAULT_GEO
    if not arguments.setnumber:
        arguments.setnumber = mf.recorded_mesh_options(os.path.join(here, "mesh_options.txt"))
    try:
        run = Run(arguments)
    except (OSError, ValueError, KeyError) as error:
        print(f"fault_bend_zones.py: {error}", file=sys.stderr)
        return 2
    out = [f"Run: {run.label}; trace from {run.trace_source}.",
           f"Zones: within {arguments.band:g} mm of each segment (projection onto it), far "
           f"field farther than {arguments.far:g} mm from the trace; element counts " +
           ", ".join(f"{z} {int(run.zones[z].sum())}" for z in ZONES) +
           f" of {len(run.volume)}. Means weighted by element volume. Slip in an interval: "
           f"slip increment > {arguments.slip_threshold:g} mm.", ""]
    if run.missing:
        out.append("No frame at " + ", ".join(f"{t:g}" for t in run.missing) +
                   " s: left out.\n")
    out += ["Mean element Mises stress [MPa] per zone:", ""] + table_levels(run) + [""]
    out += ["Changes between the times [MPa]:", ""] + table_changes(run) + [""]
    out += ["Fault activity between the times:", ""] + table_fault(run) + [""]
    out += ["Slip events (<job>_events.csv):", ""] + table_events(run) + [""]
    out += ["The paper's statements:", "", "| # | paper (section 3) | this run | numbers |",
            "|---|---|---|---|"]
    for number, text, check in STATEMENTS:
        verdict, numbers = check(run)
        out.append(f"| {number} | {text} | **{verdict}** | {numbers} |")
    print("\n".join(out))
    if arguments.figure:
        x = run.results.x_ref
        figure_changes(run, arguments.figure, 0.5 * (x[:, 2].min() + x[:, 2].max()))
        print(f"\nwrote {arguments.figure}")
    run.results.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
