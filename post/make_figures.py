#!/usr/bin/python3
"""Figures of a fault-bend run (input/fault_bend/fault_bend.inp) from its fcs3d results file.

Usage:
    /usr/bin/python3 post/make_figures.py --results run/fault_bend/fault_bend.h5 --out doc/figures
        [--deck run/fault_bend/fault_bend.inp] [--geo input/fault_bend/fault_bend.geo]
        [--setnumber NAME VALUE ...] [--z Z] [--vmax MPA] [--prefix fault_bend]
        [--large-event-share 0.5] [--compare-results OTHER.h5 [--compare-deck OTHER.inp]]

Figures written to --out (PNG), each skipped with a message when the data it needs are missing:
  <prefix>_mises_fig2.png       Mises stress [MPa] on the x-y cross-section at z = Z (default
  <prefix>_mises_fig3.png       mid-thickness) at the end of stage 1 (paper Fig. 2) and at the
                                paper's later output times (Fig. 3); one colour scale for all
                                the maps of a figure (0.5th..99.5th percentile of their values,
                                or 0..--vmax), fault trace with C, D, E, F, G (tied segments
                                thick); also one PNG per time (<prefix>_mises_t<time>.png) on
                                its figure's scale.
  <prefix>_fault_histories.png  per fault segment (mean over its slave nodes): contact pressure,
                                shear traction, their ratio and mu, slip, and, between
                                consecutive frames, the mean slip increment and the share of
                                nodes that slipped (increment > SLIP_STEP mm), against time
                                (slip events last less than the spacing of the frames, so the
                                status and slip rate *at* a frame miss them).
  <prefix>_stick_slip.png       space-time diagrams along the trace: contact status at the
                                frames and the slip increment between consecutive frames
                                against distance from C and time.
  <prefix>_loading.png          the force on face B (sum of the x nodal forces of the nodes on
                                x = max x) against B's displacement and against time.
  <prefix>_history.png          from the *HISTORY tables (<job>_<name>.csv, every increment):
                                per pair normal and tangential force, their ratio, mean slip,
                                largest slip rate, share of nodes slipping; event onsets marked.
  <prefix>_events.png           the slip-event catalog (<job>_events.csv): onsets per pair,
                                peak slip rate, largest slip, stress drop.
  <prefix>_model.png, _mises_paper.png, _space_time.png, _stations.png (and _stations.csv),
  _event<k>.png, _compare.png (with --compare-results): drawn by post/fault_figures.py (see
  its docstring): Figure 1 analogue, Mises maps with one scale per map, slip rate along the
  trace against time, fault stations, before/after maps of each large event (at least
  --large-event-share of the frictional slave nodes; maps of earlier runs' events in --out are
  removed), two runs side by side.
Every figure's footer names the run by its deck and job, the gmsh options of mesh_options.txt,
the deck's *HEADING, the fcs3d revision that wrote the results and the results file's date,
never by a path.
and <prefix>_summary.txt: the numbers behind the figures (times of the frames used, first
stick->slip event of stage 2 from the .log, B force at the paper's times).

The results layout (fcs3d src/io/fcs_results.f90) is read from the file: /mesh/coordinates,
/mesh/connectivity, /frames/NNNNNN (attributes time, step) with nodal/<field>, cell/<field>
and surfaces/contact_<pair>/{coordinates, nodal/<field>}. The fault segments are the contact
pairs and ties of the deck (their slave surface CD_UPPER, DE_UPPER, ... names the segment);
a pair on DF_UPPER (D-E and E-F in one pair) is split at E by the nodes' position along the
trace. Without the deck: grids named contact_CD, contact_DE, contact_EF, contact_FG (or
contact_DF). The trace C-D-E-F-G comes from the contact grids when each segment has its own,
else from the .geo parameters: --geo (default: fault_bend.geo next to the results, else
input/fault_bend/fault_bend.geo) and --setnumber, or the options recorded by
tools/run_default.sh in mesh_options.txt next to the results. Frame times are matched to the
wanted times within 1e-6 s.
"""

import argparse
import os
import re
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import ListedColormap, BoundaryNorm, LogNorm  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

import fault_profile  # noqa: E402

#: The paper's output times [s] (Figs. 2 and 3), total time with stage 1 assumed to last 10 s.
STAGE_1_END = 10.0
PAPER_TIMES = (STAGE_1_END, 228.7, 292.75, 296.15, 302.98, 311.08, 329.93, 369.78)
#: Contact status codes written by fcs3d (fcs_contact_element: CONTACT_OPEN ... CONTACT_TIED).
STATUS_NAMES = {0: "open", 1: "stick", 2: "slip", 3: "tied"}
STATUS_COLOURS = ("#ffffff", "#4c72b0", "#dd3c2c", "#9a9a9a")
SEGMENT_COLOURS = {"CD": "#7f7f7f", "DE": "#1f77b4", "EF": "#d62728", "FG": "#2ca02c"}
TIME_TOLERANCE = 1e-6
#: Slip increment [mm] between two frames above which a node counts as having slipped.
SLIP_STEP = 1e-4
#: Faces of a C3D8 hexahedron (0-based local nodes), as in fcs3d and gmsh.
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def message(text):
    print(f"make_figures.py: {text}")


# ------------------------------------------------------------------------------ reading


class Results:
    """The parts of an fcs3d results file that the figures use."""

    def __init__(self, path):
        self.path = path
        self.file = h5py.File(path, "r")
        try:
            self.x_ref = self.file["/mesh/coordinates"][()]
            self.connectivity = self.file["/mesh/connectivity"][()]
        except KeyError as error:
            raise ValueError(f"{path}: no /mesh/coordinates or /mesh/connectivity") from error
        frames = self.file.get("/frames")
        if frames is None or len(frames) == 0:
            raise ValueError(f"{path}: no frames")
        entries = []
        for name in sorted(frames):
            group = frames[name]
            if int(group.attrs.get("complete", 1)) != 1:
                continue
            entries.append((float(group.attrs["time"]), int(group.attrs.get("step", 0)), name))
        # Several frames at one time (end of a step and a time point): keep the last written.
        by_time = {}
        for time, step, name in entries:
            by_time[round(time / TIME_TOLERANCE)] = (time, step, name)
        self.frames = sorted(by_time.values())
        self.times = np.array([t for t, _, _ in self.frames])

    def close(self):
        self.file.close()

    def step_end(self, step):
        """Time of the last frame of `step` (None if it has none)."""
        times = [t for t, s, _ in self.frames if s == step]
        return max(times) if times else None

    def group(self, index):
        return self.file["/frames"][self.frames[index][2]]

    def frame_at(self, time):
        """Index of the frame at `time` (within TIME_TOLERANCE), or None."""
        hits = np.nonzero(np.abs(self.times - time) <= TIME_TOLERANCE * max(1.0, abs(time)))[0]
        return int(hits[-1]) if len(hits) else None

    def field(self, index, kind, name):
        """A nodal/cell field of a frame, or None if absent."""
        dataset = self.group(index).get(f"{kind}/{name}")
        return None if dataset is None else dataset[()]

    def grid_names(self):
        names = set()
        for _, _, frame in self.frames:
            surfaces = self.file["/frames"][frame].get("surfaces")
            if surfaces is not None:
                names.update(surfaces.keys())
        return sorted(names)

    def grid_field(self, index, grid, name):
        dataset = self.group(index).get(f"surfaces/{grid}/nodal/{name}")
        return None if dataset is None else dataset[()]

    def grid_coordinates(self, index, grid):
        dataset = self.group(index).get(f"surfaces/{grid}/coordinates")
        return None if dataset is None else dataset[()]


#: Slave-surface prefixes that cover several segments (the single D-F pair).
COMBINED = {"DF": ("DE", "EF")}


def deck_pairs(deck):
    """{pair name: segments} from the *CONTACT PAIR and *TIE cards of a deck: the segment is the
    part before '_' of the slave surface's name (CD_UPPER -> CD; DF_UPPER -> DE and EF)."""
    known = {seg for seg, _, _ in fault_profile.SEGMENTS}
    pairs = {}
    with open(deck, encoding="utf-8", errors="replace") as handle:
        lines = [line.rstrip("\n") for line in handle if not line.startswith("**")]
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        upper = line.upper()
        if not (upper.startswith("*CONTACT PAIR") or upper.startswith("*TIE")):
            i += 1
            continue
        params = {}
        for item in line.split(",")[1:]:
            if "=" in item:
                key, value = item.split("=", 1)
                params[key.strip().upper()] = value.strip().upper()
        j = i + 1
        while j < len(lines) and not lines[j].lstrip().startswith("*"):
            prefix = lines[j].split(",")[0].strip().upper().split("_")[0]
            name = params.get("NAME")
            if name and prefix in known:
                pairs[name] = (prefix,)
            elif name and prefix in COMBINED:
                pairs[name] = COMBINED[prefix]
            j += 1
        i = j
    return pairs


def deck_heading(deck):
    """The first line after *HEADING (the run's title), or ''."""
    with open(deck, encoding="utf-8", errors="replace") as handle:
        lines = [line.strip() for line in handle if not line.startswith("**")]
    for i, line in enumerate(lines[:-1]):
        if line.upper().startswith("*HEADING"):
            return lines[i + 1]
    return ""


def deck_ties(deck):
    """Names of the *TIE cards of a deck (upper case)."""
    names = set()
    with open(deck, encoding="utf-8", errors="replace") as handle:
        for line in handle:
            upper = line.strip().upper()
            if upper.startswith("*TIE"):
                for item in upper.split(",")[1:]:
                    if item.strip().startswith("NAME="):
                        names.add(item.split("=", 1)[1].strip())
    return names


def results_creator(results):
    """The program and revision that wrote a results file (its 'creator' attribute), without
    the build variant: 'fcs3d 0.1.0 (git 4273c8936709-dirty)'."""
    creator = results.file.attrs.get("creator", b"fcs3d")
    creator = creator.decode() if isinstance(creator, bytes) else str(creator)
    return re.sub(r",\s*(serial|mpi)[^)]*\)", ")", creator)


def run_label(results, deck, mesh_options=()):
    """The footer that names a run by its deck and job (never by a path of the machine that
    made it): '<deck> (job <job>[, gmsh options]): <heading> | <creator>, run <date>'. The
    date is the results file's modification date (UTC)."""
    import datetime
    job = os.path.splitext(os.path.basename(results.path))[0]
    deck_name = os.path.basename(deck) if deck else "no deck"
    options = " ".join(f"{name}={value}" for name, value in mesh_options)
    date = datetime.datetime.fromtimestamp(os.path.getmtime(results.path),
                                           datetime.timezone.utc).strftime("%Y-%m-%d")
    heading = deck_heading(deck) if deck else ""
    return (f"{deck_name} (job {job}{', mesh ' + options if options else ''})"
            f"{': ' + heading if heading else ''} | {results_creator(results)}, run {date}")


def stamp(fig, arguments):
    """The run's label (deck, job, heading, program revision, date) at the foot of a figure."""
    fig.supxlabel(arguments.label, x=0.005, ha="left", fontsize=5.5, color="0.35", wrap=True)


def deck_time_points(deck, name="PAPER"):
    """The times of *TIME POINTS, NAME=<name> (explicit lists only), or None."""
    with open(deck, encoding="utf-8", errors="replace") as handle:
        lines = [line.strip() for line in handle if not line.startswith("**")]
    for i, line in enumerate(lines):
        upper = line.upper().replace(" ", "")
        if upper.startswith("*TIMEPOINTS") and f"NAME={name}" in upper and "GENERATE" not in upper:
            times = []
            for data in lines[i + 1:]:
                if data.startswith("*"):
                    break
                times += [float(v) for v in data.split(",") if v.strip()]
            return times
    return None


def first_slip_event(log_path, step=2):
    """(time, node) of the first increment of `step` limited by a stick->slip event, from the
    run log, or None."""
    if not os.path.exists(log_path):
        return None
    pattern = re.compile(r"^inc \d+ step (\d+) time (\S+) .* limit stick->slip(?: node (\d+))?")
    with open(log_path, encoding="utf-8", errors="replace") as handle:
        for line in handle:
            match = pattern.match(line)
            if match and int(match.group(1)) == step:
                return float(match.group(2)), match.group(3)
    return None


def recorded_mesh_options(path):
    """[(name, value)] of the -setnumber options in a file written by tools/run_default.sh."""
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as handle:
        words = handle.read().split()
    return [(words[i + 1], words[i + 2]) for i in range(len(words) - 2)
            if words[i] in ("-setnumber", "--setnumber")]


def dat_totals(dat_path, set_name="B"):
    """[(time, fx, fy, fz)] of the 'total force ... for set <set_name>' tables of a .dat."""
    if not os.path.exists(dat_path):
        return []
    rows = []
    pattern = re.compile(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)")
    with open(dat_path, encoding="utf-8", errors="replace") as handle:
        lines = handle.readlines()
    for i, line in enumerate(lines):
        match = pattern.search(line)
        if not match or match.group(1).upper() != set_name:
            continue
        for data in lines[i + 1:i + 4]:
            values = data.split()
            if len(values) == 3:
                rows.append((float(match.group(2)), *(float(v) for v in values)))
                break
    return rows


# ------------------------------------------------------------------------------ geometry


def fault_trace(results, pairs, arguments):
    """The trace C-D-E-F-G: from the contact grids of the first frame if each of the four
    segments has a grid of its own, else from the .geo parameters."""
    grids = {}
    for pair, covered in pairs.items():
        coordinates = results.grid_coordinates(0, f"contact_{pair}")
        if len(covered) == 1 and coordinates is not None and len(coordinates) >= 2:
            grids[covered[0]] = coordinates
    if len(grids) == 4:
        return fault_profile.FaultTrace.from_contact_grids(grids), "the contact grids"
    p = fault_profile.parameters(arguments.geo, [(n, float(v)) for n, v in arguments.setnumber])
    return fault_profile.FaultTrace.from_parameters(p), \
        f"{os.path.basename(arguments.geo)} with {arguments.setnumber or 'its defaults'}"


def segment_views(results, pairs, trace):
    """[(segment, grid, slave indices)]: the slave nodes of each segment in the grids; a grid
    covering several segments (D-F) is split by the position of its nodes along the trace (a
    node at a segment end belongs to both segments)."""
    views = []
    for pair, covered in sorted(pairs.items()):
        grid = f"contact_{pair}"
        coordinates = results.grid_coordinates(0, grid)
        if coordinates is None:
            continue
        if len(covered) == 1:
            views.append((covered[0], grid, np.arange(len(coordinates))))
            continue
        along = trace.along(coordinates[:, :2])[0]
        tolerance = 1e-6 * trace.total_length
        for segment in covered:
            start = trace.start[segment]
            inside = np.nonzero((along >= start - tolerance) &
                                (along <= start + trace.lengths[segment] + tolerance))[0]
            if len(inside):
                views.append((segment, grid, inside))
    order = {seg: k for k, (seg, _, _) in enumerate(fault_profile.SEGMENTS)}
    return sorted(views, key=lambda view: order[view[0]])


def section_faces(x_ref, connectivity, z0, tolerance):
    """Quadrilateral hexahedron faces lying in the plane z = z0: (faces (k, 4) node indices,
    elements (k)), each face once."""
    on_plane = np.abs(x_ref[:, 2] - z0) <= tolerance
    faces, elements, seen = [], [], set()
    candidates = np.nonzero(on_plane[connectivity].sum(axis=1) == 4)[0]
    for e in candidates:
        for face in HEX_FACES:
            nodes = connectivity[e, list(face)]
            if on_plane[nodes].all():
                key = tuple(sorted(nodes))
                if key not in seen:
                    seen.add(key)
                    faces.append(nodes)
                    elements.append(e)
                break
    return np.array(faces, dtype=int).reshape(-1, 4), np.array(elements, dtype=int)


def layer_elements(x_ref, connectivity, z0):
    """Hexahedra whose z range contains z0 (the element layer cut by the plane)."""
    z = x_ref[connectivity, 2]
    return np.nonzero((z.min(axis=1) <= z0) & (z.max(axis=1) >= z0))[0]


def element_outline_xy(x_ref, connectivity, elements):
    """x-y outlines of extruded hexahedra (mean of the bottom and top faces), (k, 4, 2)."""
    corners = x_ref[connectivity[elements]][:, :, :2]
    return 0.5 * (corners[:, 0:4] + corners[:, 4:8])


# ------------------------------------------------------------------------------ figures


class MisesMaps:
    """Mises stress on the x-y section: nodal values on the faces at z = z0 if there is a node
    level there, else the element values of the layer cut by z = z0."""

    def __init__(self, results, z0):
        self.results = results
        x, conn = results.x_ref, results.connectivity
        size = np.ptp(x, axis=0).max()
        self.tolerance = 1e-6 * size
        self.z0 = z0
        faces, _ = section_faces(x, conn, z0, self.tolerance)
        if len(faces):
            self.mode = "nodal"
            self.triangles = np.vstack([faces[:, [0, 1, 2]], faces[:, [0, 2, 3]]])
            self.description = f"nodal Mises stress (element values extrapolated and averaged " \
                               f"per block) on the plane z = {z0:g} mm"
        else:
            self.mode = "cell"
            self.elements = layer_elements(x, conn, z0)
            self.polygons = element_outline_xy(x, conn, self.elements)
            self.description = f"element mean Mises stress of the element layer cut by " \
                               f"z = {z0:g} mm"

    def values(self, index):
        if self.mode == "nodal":
            return self.results.field(index, "nodal", "mises")
        cell = self.results.field(index, "cell", "mises")
        return None if cell is None else cell[self.elements]

    def draw(self, ax, values, vmin, vmax, cmap):
        if self.mode == "nodal":
            x = self.results.x_ref
            triangulation = Triangulation(x[:, 0], x[:, 1], self.triangles)
            return ax.tripcolor(triangulation, values, shading="gouraud", cmap=cmap,
                                vmin=vmin, vmax=vmax, rasterized=True)
        collection = PolyCollection(self.polygons, array=values, cmap=cmap, edgecolors="face",
                                    linewidths=0.2)
        collection.set_clim(vmin, vmax)
        ax.add_collection(collection)
        return collection


def draw_trace(ax, trace, labels=True):
    line = trace.polyline()
    ax.plot(line[:, 0], line[:, 1], color="black", lw=1.0)
    for seg, a, b in (("CD", "C", "D"), ("FG", "F", "G")):
        pa, pb = trace.points[a], trace.points[b]
        ax.plot([pa[0], pb[0]], [pa[1], pb[1]], color="black", lw=3.0, solid_capstyle="butt")
    if not labels:
        return
    direction = (trace.points["G"] - trace.points["C"]) / np.linalg.norm(
        trace.points["G"] - trace.points["C"])
    normal = np.array([-direction[1], direction[0]])
    for name in "CDEFG":
        p = trace.points[name] + 9.0 * normal
        ax.text(p[0], p[1], name, ha="center", va="center", fontsize=9, fontweight="bold",
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7))


def figure_mises(results, trace, times, arguments, summary):
    """Paper Fig. 2 (end of stage 1) and Fig. 3 (the later times): one figure each, with one
    colour scale for all the maps of the figure (also used by the single-time PNGs)."""
    z0 = arguments.z if arguments.z is not None else 0.5 * (
        results.x_ref[:, 2].min() + results.x_ref[:, 2].max())
    maps = MisesMaps(results, z0)
    summary.append(f"Mises maps: {maps.description}")
    stage_1_end = results.step_end(1) or STAGE_1_END
    end_of_stage_1 = [t for t in times if abs(t - stage_1_end) <= TIME_TOLERANCE]
    later = [t for t in times if abs(t - stage_1_end) > TIME_TOLERANCE]
    written = []
    for name, group in (("fig2", end_of_stage_1), ("fig3", later)):
        if group:
            written += mises_figure(results, maps, trace, group, name, arguments, summary)
    return written


def mises_figure(results, maps, trace, times, name, arguments, summary):
    panels = []
    for time in times:
        index = results.frame_at(time)
        if index is None:
            message(f"Mises map at t = {time:g} s skipped: no frame at that time")
            continue
        values = maps.values(index)
        if values is None:
            message(f"Mises map at t = {time:g} s skipped: the frame has no "
                    f"{'nodal' if maps.mode == 'nodal' else 'cell'} field 'mises'")
            continue
        panels.append((time, values))
    if not panels:
        message(f"Mises maps ({name}) skipped: none of the times "
                f"{', '.join(f'{t:g}' for t in times)} s has a frame with 'mises'")
        return []
    low = min(float(v.min()) for _, v in panels)
    peak = max(float(v.max()) for _, v in panels)
    vmin = 0.0 if arguments.vmax is not None else \
        min(float(np.percentile(v, 0.5)) for _, v in panels)
    vmax = arguments.vmax if arguments.vmax is not None else \
        max(float(np.percentile(v, 99.5)) for _, v in panels)
    if vmax <= vmin:
        vmax = vmin + max(1e-6, 1e-6 * abs(vmin))
    extend = {(False, False): "neither", (True, False): "min", (False, True): "max",
              (True, True): "both"}[(low < vmin, peak > vmax)]
    cmap = plt.get_cmap("jet")
    n = len(panels)
    columns = min(4, n)
    rows = (n + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.3 * columns + 1.2 if columns > 1 else 5.0,
                                                     3.3 * rows + 0.8 if columns > 1 else 4.6),
                             squeeze=False, constrained_layout=True)
    mappable = None
    for ax, (time, values) in zip(axes.flat, panels):
        mappable = maps.draw(ax, values, vmin, vmax, cmap)
        draw_trace(ax, trace)
        setup_plan_axes(ax, results)
        ax.set_title(f"t = {time:g} s" + (" (end of stage 1)" if name == "fig2" else ""),
                     fontsize=9)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    bar = fig.colorbar(mappable, ax=axes.ravel().tolist(), shrink=0.85, extend=extend)
    bar.set_label("Mises stress [MPa]")
    fig.suptitle(f"Mises stress on the x-y section z = {maps.z0:g} mm "
                 f"(values {low:.2f} .. {peak:.2f} MPa)", fontsize=10)
    path = os.path.join(arguments.out, f"{arguments.prefix}_mises_{name}.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    written = [path]
    for time, values in panels:
        fig, ax = plt.subplots(figsize=(5.6, 4.8), constrained_layout=True)
        mappable = maps.draw(ax, values, vmin, vmax, cmap)
        draw_trace(ax, trace)
        setup_plan_axes(ax, results)
        ax.set_title(f"Mises stress [MPa], t = {time:g} s, z = {maps.z0:g} mm", fontsize=9)
        fig.colorbar(mappable, ax=ax, extend=extend)
        path = os.path.join(arguments.out, f"{arguments.prefix}_mises_t{time:07.2f}.png")
        stamp(fig, arguments)
        fig.savefig(path, dpi=arguments.dpi)
        plt.close(fig)
        written.append(path)
    summary.append(f"  {name}: colour scale {vmin:.3f} .. {vmax:.3f} MPa "
                   f"({'--vmax' if arguments.vmax is not None else '0.5th..99.5th percentile'})")
    for time, values in panels:
        summary.append(f"    t = {time:9.3f} s: Mises min {values.min():8.3f}  mean "
                       f"{values.mean():8.3f}  max {values.max():8.3f} MPa")
    return written


def setup_plan_axes(ax, results):
    x = results.x_ref
    ax.set_xlim(x[:, 0].min(), x[:, 0].max())
    ax.set_ylim(x[:, 1].min(), x[:, 1].max())
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]", fontsize=8)
    ax.set_ylabel("y [mm]", fontsize=8)
    ax.tick_params(labelsize=7)


def segment_histories(results, views):
    """{segment: {field: (frames,) means over the segment's slave nodes}}."""
    fields = ("pressure", "shear_magnitude", "slip", "slip_rate", "mu", "status")
    histories = {}
    for segment, grid, picked in views:
        data = {name: [] for name in fields}
        data["slipping"] = []
        data["ratio"] = []
        data["slip_step"] = []
        data["slipped"] = []
        previous = None
        ok = True
        for index in range(len(results.frames)):
            values = {name: results.grid_field(index, grid, name) for name in fields}
            values = {name: None if v is None else v[picked] for name, v in values.items()}
            if values["status"] is None:
                ok = False
                break
            for name in fields:
                v = values[name]
                data[name].append(np.nan if v is None else float(np.mean(v)))
            status = np.rint(values["status"]).astype(int)
            data["slipping"].append(float(np.mean(status == 2)))
            slip = values["slip"]
            if slip is not None and previous is not None:
                step = slip - previous
                data["slip_step"].append(float(np.mean(step)))
                data["slipped"].append(float(np.mean(step > SLIP_STEP)))
            else:
                data["slip_step"].append(np.nan)
                data["slipped"].append(np.nan)
            previous = slip
            pressure, shear = values["pressure"], values["shear_magnitude"]
            if pressure is not None and shear is not None:
                closed = pressure > 0
                data["ratio"].append(float(np.sum(shear[closed]) / np.sum(pressure[closed]))
                                     if closed.any() else np.nan)
            else:
                data["ratio"].append(np.nan)
        if ok:
            histories[segment] = {k: np.array(v) for k, v in data.items()}
        else:
            message(f"segment {segment}: grid {grid} has no 'status' in some frame; "
                    f"left out of the histories")
    return histories


def figure_histories(results, views, arguments, summary):
    histories = segment_histories(results, views)
    if not histories:
        message("fault histories skipped: no contact grid with fields in the frames")
        return []
    times = results.times
    panels = (("pressure", "mean contact pressure [MPa]", False),
              ("shear_magnitude", "mean shear traction [MPa]", False),
              ("ratio", "shear / pressure (lines), mu (dashed)", False),
              ("slip", "mean accumulated slip [mm]", False),
              ("slip_step", "mean slip increment since\nthe previous frame [mm]", True),
              ("slipped", f"share of nodes that slipped\n> {SLIP_STEP:g} mm since the "
                          "previous frame", False))
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.5, 12), sharex=True,
                             constrained_layout=True)
    for ax, (field, label, log) in zip(axes, panels):
        for segment in ("CD", "DE", "EF", "FG"):
            if segment not in histories:
                continue
            values = histories[segment][field]
            if np.all(np.isnan(values)):
                continue
            style = dict(color=SEGMENT_COLOURS[segment], lw=1.2, marker=".", ms=3,
                         label=segment)
            if log:
                positive = values > 0
                if positive.any():
                    style.update(ls="none", ms=5)
                    ax.semilogy(times[positive], values[positive], **style)
            elif field == "slipped":
                style.update(ls="none", ms=5)
                shown = values > 0
                ax.plot(times[shown], values[shown], **style)
            else:
                ax.plot(times, values, **style)
            if field == "ratio":
                mu = histories[segment]["mu"]
                if segment in ("DE", "EF") and not np.all(np.isnan(mu)):
                    ax.plot(times, mu, color=SEGMENT_COLOURS[segment], lw=0.8, ls="--")
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, lw=0.3)
        ax.tick_params(labelsize=7)
    for time in PAPER_TIMES[1:]:
        for ax in axes:
            ax.axvline(time, color="0.6", lw=0.5, ls=":")
    axes[0].legend(fontsize=7, ncol=4)
    axes[-1].set_xlabel("time [s] (dotted: the paper's output times)", fontsize=8)
    fig.suptitle("Fault segments: means over the slave nodes of each segment "
                 f"({len(times)} frames)", fontsize=10)
    path = os.path.join(arguments.out, f"{arguments.prefix}_fault_histories.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    for segment, h in histories.items():
        slipping = np.nonzero(h["slipping"] > 0)[0]
        stage_1_end = results.step_end(1) or STAGE_1_END
        after = slipping[times[slipping] > stage_1_end + TIME_TOLERANCE] if len(slipping) \
            else slipping
        first = f"{times[after[0]]:g} s" if len(after) else "never in stage 2"
        moved = np.nonzero(np.nan_to_num(h["slipped"]) > 0)[0]
        moved = f"{times[moved[0]]:g} s" if len(moved) else "never"
        summary.append(f"segment {segment}: first frame with slip > {SLIP_STEP:g} mm since the "
                       f"previous frame: {moved}; first frame of stage 2 with nodes in the "
                       f"slip state at the frame: {first}")
    return [path]


def figure_stick_slip(results, views, trace, arguments, summary):
    """Status at the frames, and slip increment between consecutive frames, of the slave nodes
    of one row (the node level nearest to mid-thickness) against the distance along the trace
    and time; each segment is drawn in its own range, so nodes shared by two pairs (at D, E, F)
    appear in both. The status is a snapshot: an event shorter than the spacing of the frames
    shows only in the slip increments."""
    rows = []
    for segment, grid, picked in views:
        coordinates = results.grid_coordinates(0, grid)
        if coordinates is not None and len(picked):
            rows.append((segment, grid, picked, coordinates[picked]))
    if not rows:
        message("stick-slip diagram skipped: no contact grids")
        return []
    z_all = np.concatenate([c[:, 2] for _, _, _, c in rows])
    levels = np.unique(np.round(z_all, 6))
    z_row = levels[np.argmin(np.abs(levels - 0.5 * (z_all.min() + z_all.max())))]
    times = results.times
    t_edges = cell_edges(times)
    fig, axes = plt.subplots(1, 2, figsize=(11, 6), sharey=True, constrained_layout=True)
    cmap = ListedColormap(STATUS_COLOURS)
    norm = BoundaryNorm([-0.5, 0.5, 1.5, 2.5, 3.5], cmap.N)
    increments = []
    per_segment = []
    n_nodes = 0
    for segment, grid, picked, coordinates in rows:
        row = np.nonzero(np.abs(coordinates[:, 2] - z_row) <= 1e-6 * max(1.0, abs(z_row)))[0]
        if not len(row):
            continue
        along = trace.along(coordinates[row, :2])[0]
        order = np.argsort(along)
        pick, along = picked[row[order]], along[order]
        status = np.full((len(times), len(pick)), np.nan)
        slip = np.full((len(times), len(pick)), np.nan)
        for index in range(len(times)):
            s = results.grid_field(index, grid, "status")
            r = results.grid_field(index, grid, "slip")
            if s is not None:
                status[index] = s[pick]
            if r is not None:
                slip[index] = r[pick]
        increment = np.diff(slip, axis=0)      # slip over (t[k], t[k+1]]
        start = trace.start[segment]
        x_edges = np.clip(cell_edges(along), start, start + trace.lengths[segment])
        per_segment.append((x_edges, status, increment))
        increments.append(increment[np.isfinite(increment) & (increment > 0)])
        n_nodes += len(pick)
    for x_edges, status, _ in per_segment:
        mesh = axes[0].pcolormesh(x_edges, t_edges, np.ma.masked_invalid(status), cmap=cmap,
                                  norm=norm, shading="flat")
    bar = fig.colorbar(mesh, ax=axes[0], ticks=[0, 1, 2, 3])
    bar.ax.set_yticklabels([STATUS_NAMES[k] for k in range(4)])
    positive = np.concatenate(increments) if increments else np.zeros(0)
    if positive.size and positive.max() > SLIP_STEP:
        norm_slip = LogNorm(SLIP_STEP, positive.max())
        for x_edges, _, increment in per_segment:
            mesh = axes[1].pcolormesh(x_edges, times,
                                      np.ma.masked_less_equal(increment, SLIP_STEP),
                                      cmap="viridis", norm=norm_slip, shading="flat")
        fig.colorbar(mesh, ax=axes[1]).set_label("slip increment since the previous frame [mm]")
    else:
        axes[1].text(0.5, 0.5, f"no slip increment > {SLIP_STEP:g} mm",
                     transform=axes[1].transAxes, ha="center")
    for ax in axes:
        for name in "DEF":
            ax.axvline(along_of(trace, name), color="black", lw=0.6)
        ax.set_xlabel("distance along the trace from C [mm]", fontsize=8)
        ax.set_xlim(0.0, trace.total_length)
        ax.tick_params(labelsize=7)
        top = ax.secondary_xaxis("top")
        top.set_xticks([along_of(trace, name) for name in "CDEFG"])
        top.set_xticklabels(list("CDEFG"))
    axes[0].set_ylim(t_edges[0], t_edges[-1])
    axes[0].set_ylabel("time [s]", fontsize=8)
    axes[0].set_title(f"contact status at the frames (slave nodes at z = {z_row:g} mm)",
                      fontsize=9)
    axes[1].set_title(f"slip between consecutive frames (same nodes; blank: < {SLIP_STEP:g} mm)",
                      fontsize=9)
    path = os.path.join(arguments.out, f"{arguments.prefix}_stick_slip.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    summary.append(f"stick-slip diagram: {n_nodes} slave nodes at z = {z_row:g} mm, "
                   f"{len(times)} frames")
    return [path]


def along_of(trace, name):
    position, _, _ = trace.along(trace.points[name][None, :])
    return float(position[0])


def cell_edges(centres):
    """Edges of cells centred on sorted `centres` (midpoints; the ends extended by half a
    spacing)."""
    centres = np.asarray(centres, dtype=float)
    if len(centres) == 1:
        return np.array([centres[0] - 0.5, centres[0] + 0.5])
    middle = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate([[centres[0] - (middle[0] - centres[0])], middle,
                           [centres[-1] + (centres[-1] - middle[-1])]])


def read_csv_table(path):
    """{column: array} of a CSV written by fcs3d (*HISTORY, *EVENT CATALOG), or None."""
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as handle:
        header = handle.readline().strip().split(",")
        rows = [line.split(",") for line in handle if line.strip()]
    if not header or header == [""]:
        return None
    table = {}
    for k, name in enumerate(header):
        values = []
        for row in rows:
            try:
                values.append(float(row[k]))
            except (IndexError, ValueError):
                values.append(np.nan)
        table[name] = np.array(values)
    return table


def history_tables(results_path):
    """{name: table} of the *HISTORY CSV files next to the results (<job>_<name>.csv)."""
    stem = os.path.splitext(results_path)[0]
    directory, job = os.path.split(stem)
    tables = {}
    for entry in sorted(os.listdir(directory or ".")):
        if entry.startswith(job + "_") and entry.endswith(".csv") and \
                entry != job + "_events.csv":
            table = read_csv_table(os.path.join(directory, entry))
            if table is not None and "time" in table:
                tables[entry[len(job) + 1:-4]] = table
    return tables


def figure_history_output(tables, events, pairs, arguments, summary):
    """The *HISTORY tables (every sample, not only the frames): per pair the normal and
    tangential force, their ratio, the mean slip, the largest slip rate and the share of
    slipping nodes; the loading of B; the energies; event onsets marked."""
    columns = {}
    for table in tables.values():
        columns.update(table)
    names = [p for p in pairs if f"{p}_FN" in columns]
    if not names:
        message("history figure skipped: no *HISTORY table with CONTACT items next to the "
                "results")
        return []
    time = None
    for table in tables.values():
        if f"{names[0]}_FN" in table:
            time = table["time"]
    panels = [("normal force [kN]", lambda p: columns[f"{p}_FN"] / 1000.0, False),
              ("tangential force [kN]", lambda p: np.sqrt(sum(columns[f"{p}_FT{k}"] ** 2
                                                              for k in (1, 2, 3))) / 1000.0,
               False),
              ("tangential / normal force", lambda p: np.sqrt(sum(
                  columns[f"{p}_FT{k}"] ** 2 for k in (1, 2, 3))) / np.where(
                      columns[f"{p}_FN"] > 0, columns[f"{p}_FN"], np.nan), False),
              ("mean slip [mm]", lambda p: columns[f"{p}_SLIP_MEAN"], False),
              ("largest slip rate [mm/s]", lambda p: columns[f"{p}_RATE_MAX"], True),
              ("share of nodes slipping", lambda p: columns[f"{p}_SLIP"] / np.maximum(
                  columns[f"{p}_STICK"] + columns[f"{p}_SLIP"] + columns[f"{p}_OPEN"], 1),
               False)]
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.5, 12), sharex=True,
                             constrained_layout=True)
    for ax, (label, value, log) in zip(axes, panels):
        for pair in names:
            colour = SEGMENT_COLOURS.get(pairs[pair][0] if len(pairs[pair]) == 1 else "", None)
            try:
                y = value(pair)
            except KeyError:
                continue
            if len(y) != len(time):
                continue
            if log:
                positive = y > 0
                ax.semilogy(time[positive], y[positive], lw=0.9, color=colour, label=pair)
            else:
                ax.plot(time, y, lw=0.9, color=colour, label=pair)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, lw=0.3)
        ax.tick_params(labelsize=7)
    if events is not None and len(events.get("onset", [])):
        for onset in events["onset"]:
            axes[-2].axvline(onset, color="0.5", lw=0.4, alpha=0.6)
    axes[0].legend(fontsize=7, ncol=4)
    has_events = events is not None and len(events.get("onset", [])) > 0
    axes[-1].set_xlabel("time [s]" + ("  (grey lines: event onsets)" if has_events else ""),
                        fontsize=8)
    fig.suptitle(f"*HISTORY of the contact pairs ({len(time)} samples)", fontsize=10)
    path = os.path.join(arguments.out, f"{arguments.prefix}_history.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    summary.append(f"history: {len(time)} samples of {', '.join(names)} "
                   f"(tables {', '.join(sorted(tables))})")
    return [path]


def figure_events(events, trace, arguments, summary):
    """The slip-event catalog: the hypocentre's distance along the trace against the onset
    time, sized by the largest slip, coloured by the peak slip rate; and the stress drop
    against the onset time."""
    if events is None or not len(events.get("onset", [])):
        message("event figure skipped: no events in <job>_events.csv (or no *EVENT CATALOG)")
        if events is not None:
            summary.append("events: none catalogued")
        return []
    onset, pair = events["onset"], events["pair"]
    if all(k in events for k in ("x", "y")):
        position = trace.along(np.column_stack([events["x"], events["y"]]))[0]
        position_label = "hypocentre: distance along the trace from C [mm]"
    else:
        position, position_label = pair, "pair (number in the deck order)"
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True, constrained_layout=True)
    size = 10 + 200 * events["max_slip"] / max(np.nanmax(events["max_slip"]), 1e-30)
    rate = events["peak_slip_rate"]
    points = axes[0].scatter(onset, position, s=size, c=rate, cmap="viridis",
                             norm=LogNorm(max(np.nanmin(rate[rate > 0]) if np.any(rate > 0)
                                              else 1e-30, 1e-30),
                                          max(np.nanmax(rate), 1e-30)))
    bar = fig.colorbar(points, ax=axes[0])
    bar.set_label("peak slip rate [mm/s]")
    bar.ax.yaxis.set_minor_formatter(matplotlib.ticker.LogFormatter(labelOnlyBase=False,
                                                                    minor_thresholds=(2, 0.5)))
    bar.ax.tick_params(labelsize=7, which="both")
    axes[0].set_ylabel(position_label, fontsize=8)
    if position is not pair:
        for name in "CDEFG":
            axes[0].axhline(along_of(trace, name), color="black", lw=0.5)
        axes[0].set_ylim(0.0, trace.total_length)
        right = axes[0].secondary_yaxis("right")
        right.set_yticks([along_of(trace, name) for name in "CDEFG"])
        right.set_yticklabels(list("CDEFG"))
    nodes = events.get("nodes", np.ones_like(onset))
    axes[1].scatter(onset, events["stress_drop"], s=10 + 200 * nodes / max(np.nanmax(nodes), 1),
                    color="C0", alpha=0.7)
    for t, drop, n in zip(onset, events["stress_drop"], nodes):
        axes[1].annotate(f"{int(n)}", (t, drop), textcoords="offset points", xytext=(4, 4),
                         fontsize=6)
    axes[1].set_ylabel("mean shear stress drop [MPa]\n(marker size and label: nodes)",
                       fontsize=8)
    axes[1].set_xlabel("onset time [s] (dotted: the paper's output times)", fontsize=8)
    for ax in axes:
        for time in PAPER_TIMES[1:]:
            ax.axvline(time, color="0.6", lw=0.5, ls=":")
        ax.grid(True, lw=0.3)
        ax.tick_params(labelsize=7)
    fig.suptitle(f"Slip-event catalog: {len(onset)} events (marker size: largest slip)",
                 fontsize=10)
    path = os.path.join(arguments.out, f"{arguments.prefix}_events.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    summary.append(f"events: {len(onset)} catalogued; first onsets: " + ", ".join(
        f"{t:.6g} s (pair {int(p)}, {x:.1f} mm from C)"
        for t, p, x in list(zip(onset, pair, position))[:10]))
    return [path]


def figure_loading(results, tables, arguments, summary):
    x = results.x_ref
    size = np.ptp(x, axis=0).max()
    on_b = np.nonzero(x[:, 0] >= x[:, 0].max() - 1e-6 * size)[0]
    force, shortening, times = [], [], []
    for index in range(len(results.frames)):
        f = results.field(index, "nodal", "force")
        u = results.field(index, "nodal", "displacement")
        if f is None or u is None:
            continue
        force.append(-f[on_b, 0].sum())
        shortening.append(-u[on_b, 0].mean())
        times.append(results.times[index])
    if not force:
        message("loading curve skipped: no frame has nodal 'force' and 'displacement'")
        return []
    force = np.array(force) / 1000.0
    shortening = np.array(shortening)
    times = np.array(times)
    dat = dat_totals(os.path.splitext(results.path)[0] + ".dat", "B")
    history = next((t for t in tables.values() if "B_RF1" in t and "B_U1" in t), None)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    axes[0].plot(shortening, force, color="C0", marker=".", ms=3, lw=1.0,
                 label="sum of nodal forces on B (frames)")
    axes[0].set_xlabel("displacement of B, -u_x [mm] (mean over its nodes)", fontsize=8)
    axes[0].set_ylabel("force on B, -F_x [kN]", fontsize=8)
    axes[1].plot(times, force, color="C0", marker=".", ms=3, lw=1.0, label="frames")
    if history is not None:
        axes[0].plot(-history["B_U1"], -history["B_RF1"] / 1000.0, color="C1", lw=0.7,
                     label="*HISTORY (every sample)")
        axes[1].plot(history["time"], -history["B_RF1"] / 1000.0, color="C1", lw=0.7,
                     label="*HISTORY (every sample)")
    if dat:
        dat = np.array(dat)
        axes[1].plot(dat[:, 0], -dat[:, 1] / 1000.0, "x", color="C3", ms=4,
                     label=".dat totals of set B (RF)")
    for time in PAPER_TIMES[1:]:
        axes[1].axvline(time, color="0.6", lw=0.5, ls=":")
    axes[1].set_xlabel("time [s] (dotted: the paper's output times)", fontsize=8)
    axes[1].set_ylabel("force on B, -F_x [kN]", fontsize=8)
    for ax in axes:
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
        ax.tick_params(labelsize=7)
    fig.suptitle(f"Loading of face B (x = {x[:, 0].max():g} mm, {len(on_b)} nodes)", fontsize=10)
    path = os.path.join(arguments.out, f"{arguments.prefix}_loading.png")
    stamp(fig, arguments)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    summary.append(f"loading: B = {len(on_b)} nodes on x = {x[:, 0].max():g} mm")
    for time in PAPER_TIMES:
        hit = np.nonzero(np.abs(times - time) <= TIME_TOLERANCE * max(1.0, time))[0]
        if len(hit):
            k = hit[-1]
            summary.append(f"  t = {time:9.3f} s: force on B {force[k]:10.3f} kN, "
                           f"displacement of B {shortening[k]:.5f} mm")
    return [path]


# ------------------------------------------------------------------------------ main


class Run:
    """One run's results, deck, contact pairs, fault trace and tables, found from its results
    file alone (deck, .geo and mesh options next to it unless given)."""

    def __init__(self, results_path, deck=None, geo=None, setnumber=None, label=None):
        self.path = results_path
        self.results = Results(results_path)
        here = os.path.dirname(os.path.abspath(results_path))
        stem = os.path.splitext(results_path)[0]
        self.job = os.path.basename(stem)
        if geo is None:
            local = os.path.join(here, "fault_bend.geo")
            geo = local if os.path.exists(local) else fault_profile.DEFAULT_GEO
        self.mesh_options = list(setnumber) if setnumber else \
            recorded_mesh_options(os.path.join(here, "mesh_options.txt"))
        deck = deck or stem + ".inp"
        self.deck = deck if os.path.exists(deck) else None
        self.pairs = deck_pairs(self.deck) if self.deck else {}
        self.ties = deck_ties(self.deck) if self.deck else set()
        grids = self.results.grid_names()
        if not self.pairs:
            self.pairs = {seg: (seg,) for seg, _, _ in fault_profile.SEGMENTS}
            self.pairs.update(COMBINED)
            self.ties = {"CD", "FG"}
        self.pairs = {p: covered for p, covered in self.pairs.items()
                      if f"contact_{p}" in grids}
        self.label = label or run_label(self.results, self.deck, self.mesh_options)
        self.heading = deck_heading(self.deck) if self.deck else ""
        geometry = argparse.Namespace(geo=geo, setnumber=self.mesh_options)
        self.trace, self.trace_source = fault_trace(self.results, self.pairs, geometry)
        self.geo = geo
        self.views = segment_views(self.results, self.pairs, self.trace)
        self.tables = history_tables(results_path)
        self.events = read_csv_table(stem + "_events.csv")
        self.log = stem + ".log"

    def close(self):
        self.results.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--results", required=True, help="fcs3d results file (.h5)")
    parser.add_argument("--out", required=True, help="directory for the figures")
    parser.add_argument("--deck", help="the deck of the run (default: <results>.inp if any)")
    parser.add_argument("--geo",
                        help="the .geo file (fault trace if the results lack contact grids)")
    parser.add_argument("-setnumber", "--setnumber", nargs=2, action="append", default=[],
                        metavar=("NAME", "VALUE"), help="as given to gmsh")
    parser.add_argument("--z", type=float, help="z of the section [mm] (default: mid-thickness)")
    parser.add_argument("--vmax", type=float, help="top of the Mises colour scale [MPa]")
    parser.add_argument("--prefix", default="fault_bend")
    parser.add_argument("--label", help="text at the foot of every figure (default: deck, job, "
                        "*HEADING, fcs3d revision and date of the run)")
    parser.add_argument("--dpi", type=int, default=130)
    parser.add_argument("--large-event-share", type=float, default=0.5,
                        help="an event is large if it covers at least this share of the "
                        "frictional fault's slave nodes (before/after maps); default 0.5")
    parser.add_argument("--compare-results", help="a second run (e.g. the flat fault) for the "
                        "side-by-side figure <prefix>_compare.png")
    parser.add_argument("--compare-deck", help="its deck (default: next to its results)")
    arguments = parser.parse_args()

    for path in [arguments.results] + ([arguments.compare_results]
                                       if arguments.compare_results else []):
        if not os.path.exists(path):
            print(f"make_figures.py: {path}: no such file (run `make run` first)",
                  file=sys.stderr)
            return 2
    try:
        run = Run(arguments.results, arguments.deck, arguments.geo, arguments.setnumber,
                  arguments.label)
        other = Run(arguments.compare_results, arguments.compare_deck) \
            if arguments.compare_results else None
    except (OSError, ValueError) as error:
        print(f"make_figures.py: {error}", file=sys.stderr)
        return 2
    os.makedirs(arguments.out, exist_ok=True)
    results, pairs, trace, views = run.results, run.pairs, run.trace, run.views
    arguments.label = run.label
    times = sorted(set([results.step_end(1) or STAGE_1_END] + list(PAPER_TIMES[1:])))
    listed = deck_time_points(run.deck, "PAPER") if run.deck else None
    if listed:
        times = sorted(set([results.step_end(1) or STAGE_1_END] + listed))
    summary = [f"run: {run.label}",
               f"results: {os.path.basename(run.path)}, deck: "
               f"{os.path.basename(run.deck) if run.deck else 'none'}",
               f"frames: {len(results.frames)}, times {results.times.min():g} .. "
               f"{results.times.max():g} s"]
    summary.append(f"trace (from {run.trace_source}): " + "  ".join(
        f"{k} ({v[0]:.3f}, {v[1]:.3f})" for k, v in trace.points.items()))
    summary.append("segments: " + (", ".join(f"{seg} = {len(picked)} nodes of {grid}"
                                             for seg, grid, picked in views) or "none"))
    event = first_slip_event(run.log)
    summary.append("first stick->slip event of stage 2 (log): " +
                   (f"t = {event[0]:.6g} s, node {event[1]}" if event else "none found"))

    import fault_figures
    written = []
    written += fault_figures.figure_model(run, arguments, summary)
    written += figure_mises(results, trace, times, arguments, summary)
    written += fault_figures.figure_mises_own_scales(run, times, arguments, summary)
    written += figure_histories(results, views, arguments, summary)
    written += figure_stick_slip(results, views, trace, arguments, summary)
    written += fault_figures.figure_space_time(run, arguments, summary)
    written += fault_figures.figure_stations(run, arguments, summary)
    written += fault_figures.figure_event_maps(run, arguments, summary)
    written += figure_loading(results, run.tables, arguments, summary)
    written += figure_history_output(run.tables, run.events, pairs, arguments, summary)
    written += figure_events(run.events, trace, arguments, summary)
    if other is not None:
        written += fault_figures.figure_compare(run, other, arguments, summary)
        other.close()
    run.close()
    path = os.path.join(arguments.out, f"{arguments.prefix}_summary.txt")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write("\n".join(summary) + "\n")
    written.append(path)
    for item in written:
        print(f"wrote {item}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
