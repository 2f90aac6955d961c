#!/usr/bin/python3
"""The figures of a fault-bend run that a reader of Xing, Mora & Makinouchi (2003) expects
(issue 19, item 8); called by post/make_figures.py, which documents the command line.

Figures (PNG, <prefix>_*.png in --out):
  model.png            Figure 1 analogue: plan view of the top face with the mesh, the fault
                       trace C-D-E-F-G (tied and frictional segments distinguished), the loaded
                       faces (*DSLOAD surfaces, *BOUNDARY, TYPE=VELOCITY sets) and the supports
                       (*BOUNDARY sets), with dimensions; and an oblique 3D view of the plate.
                       Sets and surfaces are the deck's, their nodes the physical groups of the
                       .msh named by *MESH, FILE= (ASCII MSH 4.1).
  mises_paper.png      Mises maps at the paper's times in the paper's manner: banded colours,
                       one colour scale per panel (the common-scale version is mises_fig2/3).
  space_time.png       slip rate along the trace C-G against time (log colour): the mean rate
                       between consecutive frames (slip increment / time between the frames;
                       every slave node of the frames' contact grids, averaged through the
                       thickness), the slip rate held in the frames (a snapshot), and each
                       pair's largest slip rate from *HISTORY (every increment).
  stations.png         shear and normal traction and accumulated slip at five fault stations
                       (mid C-D, mid D-E, E, mid E-F, mid F-G; the slave node nearest to each,
                       at the node level nearest to mid-thickness) at every frame; the values
                       are also written to <prefix>_stations.csv.
  event<k>.png         each large event of <job>_events.csv (at least --large-event-share of
                       the frictional fault's slave nodes): Mises on the section and shear
                       traction on the unrolled fault at the last frame at or before its onset
                       and the first frame at or after its end, and their difference; the time
                       gaps are in the titles and the summary.
  compare.png          with --compare-results: the two runs side by side (space-time slip rate
                       on one colour scale, force on the moving face against time).
"""

import os
import re

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import BoundaryNorm, LogNorm, TwoSlopeNorm  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

import fault_profile  # noqa: E402
import make_figures as mf  # noqa: E402

#: Fault stations: (name, trace point or segment whose midpoint is taken).
STATIONS = (("mid C-D", "CD"), ("mid D-E", "DE"), ("E", "E"), ("mid E-F", "EF"),
            ("mid F-G", "FG"))
STATION_COLOURS = ("#7f7f7f", "#1f77b4", "#9467bd", "#d62728", "#2ca02c")
#: Number of colour bands of a paper-style map.
BANDS = 12
#: Slip rates below this share of the largest one are left blank in the space-time plots.
RATE_RANGE = 1e-5
#: Resolution cap of the figures made of maps (their PNGs are the largest).
MAP_DPI = 100
SET_COLOURS = {"load": "#1f5fbf", "velocity": "#e07b00", "support": "#2e8b57"}


# ------------------------------------------------------------------------------ deck and mesh


def deck_model(deck):
    """What Figure 1 shows, from the deck: {'mesh': file, 'supports': [(set, first, last)],
    'displacements': [(set, first, last, value, step)], 'velocities': [(set, dof, value,
    step)], 'pressures': [(surface, value, step)]}; steps are named by *STEP, NAME= (or
    their number)."""
    model = {"mesh": None, "supports": [], "displacements": [], "velocities": [],
             "pressures": []}
    if deck is None:
        return model
    with open(deck, encoding="utf-8", errors="replace") as handle:
        lines = [line.strip() for line in handle if not line.startswith("**")]
    keyword, params, step, n_steps = "", {}, "model", 0
    for line in lines:
        if not line:
            continue
        if line.startswith("*"):
            items = [item.strip() for item in line.split(",")]
            keyword = items[0].upper()
            params = {}
            for item in items[1:]:
                key, _, value = item.partition("=")
                params[key.strip().upper()] = value.strip()
            if keyword == "*STEP":
                n_steps += 1
                step = params.get("NAME", f"step {n_steps}")
            elif keyword == "*MESH" and "FILE" in params:
                model["mesh"] = params["FILE"]
            continue
        data = [item.strip() for item in line.split(",")]
        if keyword == "*BOUNDARY" and len(data) >= 2:
            first = int(data[1])
            last = int(data[2]) if len(data) > 2 and data[2] else first
            value = float(data[3]) if len(data) > 3 and data[3] else 0.0
            if params.get("TYPE", "").upper() == "VELOCITY":
                model["velocities"].append((data[0].upper(), first, value, step))
            elif value == 0.0:
                if (data[0].upper(), first, last) not in model["supports"]:
                    model["supports"].append((data[0].upper(), first, last))
            else:
                model["displacements"].append((data[0].upper(), first, last, value, step))
        elif keyword == "*DSLOAD" and len(data) >= 3 and data[1].upper().startswith("P"):
            model["pressures"].append((data[0].upper(), float(data[2]), step))
    return model


def mesh_sets(mesh_path, names):
    """{name: (k, 4, 3) corner coordinates of the quadrilaterals of the surface physical group}
    of an ASCII MSH 4.1 file, for the groups in `names` that it has."""
    import check_fault_mesh as cfm
    nodes, blocks, groups, entity_groups = cfm.read_msh41(mesh_path)
    out = {}
    for name in names:
        if name not in groups or groups[name][0] != 2:
            continue
        table = cfm.group_elements(blocks, entity_groups, groups[name], cfm.GMSH_QUAD)
        if len(table):
            out[name] = np.array([[nodes[tag] for tag in row[1:5]] for row in table])
    return out


def plane_of(quads, size):
    """(axis, coordinate) of the box plane a set of faces lies in, or None."""
    points = quads.reshape(-1, 3)
    for axis in range(3):
        if np.ptp(points[:, axis]) <= 1e-6 * size:
            return axis, float(points[0, axis])
    return None


# ------------------------------------------------------------------------------ fault nodes


class FaultNodes:
    """The slave nodes of every contact grid of the fault, each position once (a node at D or F
    that a tie and the frictional pair share is taken from the tie), with their distance along
    the trace, and each grid field at every frame (read once)."""

    def __init__(self, run):
        self.run = run
        results = run.results
        size = np.ptp(results.x_ref, axis=0).max()
        grids, index, tied, xyz = [], [], [], []
        for pair in sorted(run.pairs, key=lambda p: (p not in run.ties, p)):
            grid = f"contact_{pair}"
            coordinates = results.grid_coordinates(0, grid)
            if coordinates is None:
                continue
            for k, point in enumerate(coordinates):
                grids.append(grid)
                index.append(k)
                tied.append(pair in run.ties)
                xyz.append(point)
        xyz = np.array(xyz, dtype=float).reshape(-1, 3)
        keys = np.round(xyz / (1e-6 * size)).astype(np.int64)
        _, first = np.unique(keys, axis=0, return_index=True)
        keep = np.sort(first)
        self.grid = np.array(grids, dtype=object)[keep]
        self.index = np.array(index, dtype=int)[keep]
        self.tied = np.array(tied, dtype=bool)[keep]
        self.xyz = xyz[keep]
        self.along = run.trace.along(self.xyz[:, :2])[0] if len(keep) else np.zeros(0)
        self.z = self.xyz[:, 2]
        self._cache = {}

    def __len__(self):
        return len(self.index)

    def series(self, name):
        """(frames, nodes) values of grid field `name` (NaN where a frame lacks it); a vector
        field gives (frames, nodes, 3)."""
        if name in self._cache:
            return self._cache[name]
        results = self.run.results
        out = None
        for k in range(len(results.frames)):
            for grid in np.unique(self.grid):
                values = results.grid_field(k, grid, name)
                if values is None:
                    continue
                if out is None:
                    out = np.full((len(results.frames), len(self)) + values.shape[1:], np.nan)
                picked = self.grid == grid
                out[k, picked] = values[self.index[picked]]
        self._cache[name] = out
        return out

    def columns(self):
        """(positions along the trace (m,), column of each node (n,)): nodes at one position
        (one column through the thickness) share a column."""
        size = max(self.run.trace.total_length, 1.0)
        keys = np.round(self.along / (1e-6 * size)).astype(np.int64)
        unique, column = np.unique(keys, return_inverse=True)
        positions = np.array([self.along[column == c].mean() for c in range(len(unique))])
        return positions, column

    def mid_level(self):
        """The node level (z) nearest to the fault's mid-thickness."""
        levels = np.unique(np.round(self.z, 6))
        return float(levels[np.argmin(np.abs(levels - 0.5 * (self.z.min() + self.z.max())))])


def frictional_node_count(run):
    """Slave nodes of the fault's frictional (non-tie) pairs."""
    total = 0
    for pair in run.pairs:
        if pair not in run.ties:
            coordinates = run.results.grid_coordinates(0, f"contact_{pair}")
            total += 0 if coordinates is None else len(coordinates)
    return total


def save(fig, run, arguments, name, dpi=None):
    """Write a figure with the run's footer; `dpi` caps --dpi (for the map-heavy figures)."""
    path = os.path.join(arguments.out, f"{arguments.prefix}_{name}.png")
    fig.supxlabel(run.label, x=0.005, ha="left", fontsize=5.5, color="0.35", wrap=True)
    fig.savefig(path, dpi=min(arguments.dpi, dpi) if dpi else arguments.dpi)
    plt.close(fig)
    return path


def mark_trace_points(ax, trace, vertical=True):
    """Lines at C ... G on an axis of distance along the trace, named on the opposite side."""
    positions = [mf.along_of(trace, name) for name in "CDEFG"]
    for position in positions[1:-1]:
        (ax.axvline if vertical else ax.axhline)(position, color="black", lw=0.5)
    if vertical:
        top = ax.secondary_xaxis("top")
        top.set_xticks(positions)
        top.set_xticklabels(list("CDEFG"), fontsize=7)
    else:
        right = ax.secondary_yaxis("right")
        right.set_yticks(positions)
        right.set_yticklabels(list("CDEFG"), fontsize=7)


# ------------------------------------------------------------------------------ Figure 1


def segment_kinds(run):
    """{segment: 'tied' | 'frictional' | None} from the pairs that cover each segment."""
    kinds = {seg: None for seg, _, _ in fault_profile.SEGMENTS}
    for pair, covered in run.pairs.items():
        for seg in covered:
            kinds[seg] = "tied" if pair in run.ties else "frictional"
    return kinds


def draw_fault(ax, run, z=None, labels=True):
    """The trace, frictional segments red, tied ones thick black; C ... G named."""
    trace = run.trace
    kinds = segment_kinds(run)
    for seg, a, b in fault_profile.SEGMENTS:
        pa, pb = trace.points[a], trace.points[b]
        style = dict(color="black", lw=4.0, solid_capstyle="butt") if kinds[seg] == "tied" \
            else dict(color="#d62728", lw=2.2) if kinds[seg] == "frictional" \
            else dict(color="0.4", lw=1.0, ls="--")
        if z is None:
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], **style)
        else:
            ax.plot([pa[0], pb[0]], [pa[1], pb[1]], [z, z], zorder=5, **style)
    if not labels or z is not None:
        return
    direction = trace.points["G"] - trace.points["C"]
    direction /= np.linalg.norm(direction)
    normal = np.array([-direction[1], direction[0]])
    for name in "CDEFG":
        p = trace.points[name] + 11.0 * normal
        ax.text(p[0], p[1], name, ha="center", va="center", fontsize=9, fontweight="bold",
                bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8))


def plan_mesh(ax, run):
    """Element edges of the top face, blocks shaded by their side of the trace."""
    results = run.results
    x, conn = results.x_ref, results.connectivity
    size = np.ptp(x, axis=0).max()
    faces, _ = mf.section_faces(x, conn, x[:, 2].max(), 1e-6 * size)
    if not len(faces):
        return
    polygons = x[faces][:, :, :2]
    centre = polygons.mean(axis=1)
    _, segment, _ = run.trace.along(centre)
    side = np.array([run.trace.project(c[None, :], s)[1][0] for c, s in zip(centre, segment)])
    colours = np.where(side > 0, "#f3e7cf", "#dfe7f1")
    ax.add_collection(PolyCollection(polygons, facecolors=colours, edgecolors="0.55",
                                     linewidths=0.3))


def figure_model(run, arguments, summary):
    """Figure 1 analogue: plan view and oblique view with supports, loads, trace, dimensions."""
    results = run.results
    x = results.x_ref
    low, high = x.min(axis=0), x.max(axis=0)
    size = np.ptp(x, axis=0).max()
    model = deck_model(run.deck)
    names = {s for s, _, _ in model["supports"]} | {s for s, _, _, _ in model["velocities"]} | \
        {s for s, _, _ in model["pressures"]} | {s for s, *_ in model["displacements"]}
    sets = {}
    if model["mesh"] and run.deck:
        mesh = os.path.join(os.path.dirname(os.path.abspath(run.deck)), model["mesh"])
        try:
            sets = mesh_sets(mesh, names)
        except Exception as error:  # noqa: BLE001 - any unreadable mesh only loses the sets
            mf.message(f"Figure 1: sets of {os.path.basename(mesh)} not read ({error}); "
                       "supports and loads drawn without their faces")
    fig = plt.figure(figsize=(13.0, 6.2), constrained_layout=True)
    ax = fig.add_subplot(1, 2, 1)
    plan_mesh(ax, run)
    draw_fault(ax, run)
    notes = []
    arrows = 5
    span = np.ptp(x[:, :2], axis=0)
    dof_name = {1: "x", 2: "y", 3: "z"}
    for surface, value, step in model["pressures"]:
        plane = plane_of(sets[surface], size) if surface in sets else None
        notes.append(f"{surface}: pressure {value:g} MPa ({step})")
        if plane is None or plane[0] == 2:
            continue
        axis, coordinate = plane
        other = 1 - axis
        inward = 1.0 if coordinate <= low[axis] + 1e-6 * size else -1.0
        quads = sets[surface].reshape(-1, 3)
        lo, hi = quads[:, other].min(), quads[:, other].max()
        for t in np.linspace(lo, hi, arrows + 2)[1:-1]:
            tail = np.zeros(2)
            tail[axis] = coordinate - inward * 0.12 * span[axis]
            tail[other] = t
            delta = np.zeros(2)
            delta[axis] = inward * 0.09 * span[axis]
            ax.annotate("", xy=tail + delta, xytext=tail,
                        arrowprops=dict(arrowstyle="-|>", color=SET_COLOURS["load"], lw=1.2))
        edge = np.zeros((2, 2))
        edge[:, axis] = coordinate
        edge[:, other] = (lo, hi)
        ax.plot(edge[:, 0], edge[:, 1], color=SET_COLOURS["load"], lw=3.0)
        label = np.zeros(2)
        label[axis] = coordinate - inward * 0.17 * span[axis]
        label[other] = 0.5 * (lo + hi)
        ax.text(label[0], label[1], surface, color=SET_COLOURS["load"], fontsize=12,
                fontweight="bold", ha="center", va="center")
    for name, dof, value, step in model["velocities"]:
        notes.append(f"{name}: velocity v_{dof_name.get(dof, dof)} = {value:g} mm/s ({step})")
        plane = plane_of(sets[name], size) if name in sets else None
        if plane is None or dof not in (1, 2) or plane[0] == 2:
            continue
        axis, coordinate = plane
        quads = sets[name].reshape(-1, 3)
        other = 1 - axis
        middle = np.zeros(2)
        middle[axis] = coordinate
        middle[other] = 0.5 * (quads[:, other].min() + quads[:, other].max()) + \
            0.22 * span[other]
        delta = np.zeros(2)
        delta[dof - 1] = np.sign(value) * 0.1 * span[dof - 1]
        start = middle - delta + (0.05 * span[axis] if dof - 1 == axis else 0) * \
            np.eye(2)[axis] * (1 if coordinate >= high[axis] - 1e-6 * size else -1)
        ax.annotate("", xy=start + delta, xytext=start,
                    arrowprops=dict(arrowstyle="-|>", color=SET_COLOURS["velocity"], lw=2.5))
        ax.text(*(start + np.array([0.0, 0.04 * span[1]])), f"v{dof_name[dof]}",
                color=SET_COLOURS["velocity"], fontsize=8, ha="center")
    for name, first, last in model["supports"]:
        dofs = ", ".join(f"u_{dof_name.get(d, d)}" for d in range(first, last + 1))
        plane = plane_of(sets[name], size) if name in sets else None
        where = "" if plane is None else f" on {'xyz'[plane[0]]} = {plane[1]:g} mm"
        notes.append(f"{name}{where}: {dofs} = 0")
        if plane is None or plane[0] == 2:
            continue
        axis, coordinate = plane
        other = 1 - axis
        quads = sets[name].reshape(-1, 3)
        outward = -1.0 if coordinate <= low[axis] + 1e-6 * size else 1.0
        for t in np.linspace(quads[:, other].min(), quads[:, other].max(), 9)[1:-1]:
            p = np.zeros(2)
            p[axis] = coordinate + outward * 0.025 * span[axis]
            p[other] = t
            ax.plot(*p, marker="o", ms=4, mfc="white", mec=SET_COLOURS["support"], mew=1.2)
        edge = np.zeros((2, 2))
        edge[:, axis] = coordinate + outward * 0.045 * span[axis]
        edge[:, other] = (quads[:, other].min(), quads[:, other].max())
        ax.plot(edge[:, 0], edge[:, 1], color=SET_COLOURS["support"], lw=2.0)
        label = np.zeros(2)
        label[axis] = coordinate + outward * 0.08 * span[axis]
        label[other] = quads[:, other].min() + 0.12 * span[other]
        ax.text(label[0], label[1], name, color=SET_COLOURS["support"], fontsize=9,
                fontweight="bold", ha="center", va="center")
    # dimensions
    for axis in (0, 1):
        other = 1 - axis
        a, b = np.zeros(2), np.zeros(2)
        a[axis], b[axis] = low[axis], high[axis]
        a[other] = b[other] = low[other] - 0.2 * span[other]
        ax.annotate("", xy=b, xytext=a, arrowprops=dict(arrowstyle="<->", color="black",
                                                        lw=0.8))
        middle = 0.5 * (a + b)
        middle[other] -= 0.03 * span[other]
        ax.text(middle[0], middle[1], f"{span[axis]:g} mm", ha="center", va="center",
                fontsize=8, rotation=0 if axis == 0 else 90,
                bbox=dict(fc="white", ec="none", pad=0.5))
    ax.set_xlim(low[0] - 0.27 * span[0], high[0] + 0.27 * span[0])
    ax.set_ylim(low[1] - 0.27 * span[1], high[1] + 0.27 * span[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]", fontsize=8)
    ax.set_ylabel("y [mm]", fontsize=8)
    ax.tick_params(labelsize=7)
    kinds = segment_kinds(run)
    lengths = ", ".join(f"{seg} {run.trace.lengths[seg]:.1f} mm ({kinds[seg] or 'no pair'})"
                        for seg, _, _ in fault_profile.SEGMENTS)
    ax.set_title(f"plan view of the top face z = {high[2]:g} mm: {len(results.connectivity)} "
                 f"hexahedra, {len(x)} nodes", fontsize=9)
    handles = [plt.Line2D([], [], color="#d62728", lw=2.2, label="frictional (contact pair)"),
               plt.Line2D([], [], color="black", lw=4.0, label="tied (*TIE)"),
               plt.Line2D([], [], color=SET_COLOURS["load"], lw=3, label="pressure (*DSLOAD)"),
               plt.Line2D([], [], color=SET_COLOURS["velocity"], lw=2.5,
                          label="velocity (*BOUNDARY, TYPE=VELOCITY)"),
               plt.Line2D([], [], color=SET_COLOURS["support"], lw=2, marker="o", mfc="white",
                          label="roller (*BOUNDARY)")]
    ax.legend(handles=handles, fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.09),
              ncol=3, framealpha=0.9)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d", computed_zorder=False)
    draw_box(ax3, run, sets, model, size)
    ax3.text2D(0.02, -0.02, "\n".join(merge_notes(notes)), transform=ax3.transAxes,
               fontsize=7.5, va="top", family="monospace")
    fig.suptitle("The fault-bend model (Figure 1 analogue): mesh, supports, loaded faces, "
                 "fault trace", fontsize=10)
    path = save(fig, run, arguments, "model", dpi=MAP_DPI)
    summary.append("Figure 1: " + "; ".join(merge_notes(notes)) + f"; segments {lengths}")
    return [path]


def merge_notes(notes):
    """The Figure 1 notes with the steps of identical loads merged ('A: pressure 10 MPa (STAGE
    1, STAGE 2)')."""
    merged = {}
    for note in notes:
        text, _, step = note.rpartition(" (")
        if text and step.endswith(")"):
            merged.setdefault(text, []).append(step[:-1])
        else:
            merged.setdefault(note, [])
    return [f"{text} ({', '.join(steps)})" if steps else text for text, steps in merged.items()]


def draw_box(ax, run, sets, model, size):
    """Oblique view: the outer faces of the mesh, faces of loaded and supported sets coloured,
    the trace on the top and bottom faces, vertical lines at C ... G, dimensions."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    results = run.results
    x, conn = results.x_ref, results.connectivity
    low, high = x.min(axis=0), x.max(axis=0)
    tolerance = 1e-6 * size
    polygons, colours = [], []
    kind_of = {}
    for surface, _, _ in model["pressures"]:
        kind_of[surface] = "load"
    for name, *_ in model["velocities"]:
        kind_of[name] = "velocity"
    for name, _, _ in model["supports"]:
        kind_of.setdefault(name, "support")
    planes = {name: plane_of(quads, size) for name, quads in sets.items()}
    for face in mf.HEX_FACES:
        corners = x[conn[:, list(face)]]                              # (e, 4, 3)
        for axis in range(3):
            for bound in (low[axis], high[axis]):
                on = np.all(np.abs(corners[:, :, axis] - bound) <= tolerance, axis=1)
                for quad in corners[on]:
                    colour = "#e8e8e8"
                    for name, plane in planes.items():
                        if plane == (axis, bound) or (plane and plane[0] == axis and
                                                      abs(plane[1] - bound) <= tolerance):
                            colour = SET_COLOURS.get(kind_of.get(name), colour)
                    polygons.append(quad)
                    colours.append(colour)
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=colours, edgecolors="0.45",
                                         linewidths=0.2))
    draw_fault(ax, run, z=high[2])
    for name in "CDEFG":
        p = run.trace.points[name]
        ax.plot([p[0], p[0]], [p[1], p[1]], [low[2], high[2]], color="black", lw=0.8, zorder=5)
        ax.text(p[0], p[1], high[2] + 0.06 * size, name, fontsize=9, fontweight="bold",
                ha="center")
    for name, plane in planes.items():
        if plane is None or name not in kind_of:
            continue
        centre = sets[name].reshape(-1, 3).mean(axis=0)
        hidden = plane[1] <= low[plane[0]] + tolerance
        ax.text(*centre, name + (" (hidden side)" if hidden else ""), color="black",
                fontsize=9 if not hidden else 7, fontweight="bold", zorder=10)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    span = high - low
    ax.set_box_aspect(span / span.max())
    ax.view_init(elev=30, azim=40)
    ax.set_xlabel(f"x [mm] ({span[0]:g})", fontsize=7)
    ax.set_ylabel(f"y [mm] ({span[1]:g})", fontsize=7)
    ax.set_zlabel(f"z [mm] ({span[2]:g})", fontsize=7)
    ax.tick_params(labelsize=6)
    ax.set_title(f"{span[0]:g} x {span[1]:g} x {span[2]:g} mm; coloured: loaded (blue, "
                 "orange) and supported (green) faces", fontsize=8)


# ------------------------------------------------------------------------------ Mises maps


def draw_map(maps, ax, values, norm, cmap):
    """A MisesMaps section with a given norm (banded colours)."""
    if maps.mode == "nodal":
        x = maps.results.x_ref
        triangulation = Triangulation(x[:, 0], x[:, 1], maps.triangles)
        return ax.tripcolor(triangulation, values, shading="flat" if isinstance(
            norm, BoundaryNorm) else "gouraud", cmap=cmap, norm=norm, rasterized=True)
    collection = PolyCollection(maps.polygons, array=values, cmap=cmap, norm=norm,
                                edgecolors="face", linewidths=0.2)
    ax.add_collection(collection)
    return collection


def figure_mises_own_scales(run, times, arguments, summary):
    """The Mises maps at the paper's times, each on its own banded colour scale; and, in the
    summary, how far consecutive maps differ on the common scale of mises_fig3."""
    results = run.results
    z0 = arguments.z if arguments.z is not None else 0.5 * (
        results.x_ref[:, 2].min() + results.x_ref[:, 2].max())
    maps = mf.MisesMaps(results, z0)
    panels = []
    for time in times:
        index = results.frame_at(time)
        values = None if index is None else maps.values(index)
        if values is None:
            mf.message(f"own-scale Mises map at t = {time:g} s skipped: no frame with 'mises'")
            continue
        panels.append((time, index, values))
    if not panels:
        return []
    n = len(panels)
    columns = min(4, n)
    rows = (n + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.3 * rows + 0.6),
                             squeeze=False, constrained_layout=True)
    cmap = plt.get_cmap("jet")
    stage_1_end = results.step_end(1) or mf.STAGE_1_END
    for ax, (time, index, values) in zip(axes.flat, panels):
        levels = MaxNLocator(BANDS).tick_values(float(values.min()), float(values.max()))
        norm = BoundaryNorm(levels, cmap.N)
        mappable = draw_map(maps, ax, values, norm, cmap)
        mf.draw_trace(ax, run.trace)
        mf.setup_plan_axes(ax, results)
        ax.set_title(f"t = {time:g} s" + (" (end of stage 1)" if abs(time - stage_1_end) <=
                                          mf.TIME_TOLERANCE else ""), fontsize=9)
        bar = fig.colorbar(mappable, ax=ax, shrink=0.9, ticks=levels[::2])
        bar.ax.tick_params(labelsize=6)
        bar.set_label("Mises [MPa]", fontsize=7)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    fig.suptitle(f"Mises stress on the x-y section z = {maps.z0:g} mm at the paper's times, "
                 f"each map on its own scale ({BANDS} bands at most)", fontsize=10)
    path = save(fig, run, arguments, "mises_paper", dpi=MAP_DPI)
    summary.append(f"Mises maps, own scales: {n} maps ({maps.description})")
    later = [(t, v) for t, _, v in panels if abs(t - stage_1_end) > mf.TIME_TOLERANCE]
    if len(later) > 1:
        vmin = min(float(np.percentile(v, 0.5)) for _, v in later)
        vmax = max(float(np.percentile(v, 99.5)) for _, v in later)
        width = max(vmax - vmin, 1e-30)
        summary.append(f"  consecutive later maps on the common scale {vmin:.2f} .. "
                       f"{vmax:.2f} MPa (mises_fig3): range of each map; between consecutive "
                       "maps (frame indices), the largest |change| and the 95th percentile of "
                       "|change| as shares of the scale")
        for t0, v0 in later:
            summary.append(f"    t = {t0:g} s: values {v0.min():.2f} .. {v0.max():.2f} MPa span "
                           f"{100 * (v0.max() - v0.min()) / width:.1f} % of the common scale, "
                           f"from {100 * (v0.min() - vmin) / width:.1f} % of it")
        for (t0, v0), (t1, v1) in zip(later[:-1], later[1:]):
            change = np.abs(v1 - v0)
            p95 = float(np.percentile(change, 95))
            verdict = "looks the same on the common scale" if p95 < 0.05 * width else "differs"
            summary.append(f"    {t0:g} -> {t1:g} s (frames {results.frame_at(t0)}, "
                           f"{results.frame_at(t1)}): largest {change.max():.3f} MPa "
                           f"({100 * change.max() / width:.1f} %), 95th percentile {p95:.3f} "
                           f"MPa ({100 * p95 / width:.1f} %): {verdict}")
    return [path]


# ------------------------------------------------------------------------------ space-time


def space_time(run, nodes=None):
    """Slip rate along the trace against time: (position edges (m+1,), frame times (f,),
    mean rate between consecutive frames (f-1, m), slip rate at the frames (f, m)), each the
    mean through the thickness of a column of slave nodes. None without slip fields."""
    nodes = nodes or FaultNodes(run)
    if not len(nodes):
        return None
    slip = nodes.series("slip")
    if slip is None:
        return None
    rate = nodes.series("slip_rate")
    times = run.results.times
    positions, column = nodes.columns()
    order = np.argsort(positions)
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    positions = positions[order]
    dt = np.diff(times)
    step = np.diff(slip, axis=0) / np.where(dt > 0, dt, np.nan)[:, None]
    mean_step = np.full((len(times) - 1, len(positions)), np.nan)
    mean_rate = np.full((len(times), len(positions)), np.nan)
    for c in range(len(positions)):
        members = rank[column] == c
        mean_step[:, c] = np.nanmean(step[:, members], axis=1) if members.any() else np.nan
        if rate is not None:
            mean_rate[:, c] = np.nanmean(rate[:, members], axis=1)
    edges = np.clip(mf.cell_edges(positions), 0.0, run.trace.total_length)
    return edges, times, mean_step, mean_rate


def first_slip_time(data, norm):
    """The start of the first frame interval with a mean slip rate above the colour floor, less
    a tenth of the time after it (the lower time limit of the plots)."""
    _, times, mean_step, _ = data
    active = np.nonzero(np.nan_to_num(mean_step).max(axis=1) > norm.vmin)[0]
    if not len(active):
        return float(times[0])
    start = float(times[active[0]])
    return max(float(times[0]), start - 0.1 * (float(times[-1]) - start))


def rate_norm(*arrays):
    finite = np.concatenate([a[np.isfinite(a) & (a > 0)].ravel() for a in arrays if a is not None]
                            or [np.zeros(0)])
    if not finite.size:
        return None
    top = float(finite.max())
    return LogNorm(top * RATE_RANGE, top)


def draw_space_time(ax, run, data, norm, title, events=True):
    edges, times, mean_step, _ = data
    masked = np.ma.masked_where(~np.isfinite(mean_step) | (mean_step <= norm.vmin), mean_step)
    mesh = ax.pcolormesh(edges, times, masked, cmap="viridis", norm=norm, shading="flat")
    mark_events(ax, run, events)
    finish_space_time(ax, run, title)
    return mesh


def mark_events(ax, run, show=True):
    events = run.events
    if not show or events is None or not len(events.get("onset", [])):
        return
    if all(k in events for k in ("x", "y")):
        position = run.trace.along(np.column_stack([events["x"], events["y"]]))[0]
        ax.plot(position, events["onset"], "*", color="white", mec="black", mew=0.5, ms=8,
                label="event onset at its hypocentre")


def finish_space_time(ax, run, title):
    mark_trace_points(ax, run.trace)
    ax.set_xlim(0.0, run.trace.total_length)
    ax.set_xlabel("distance along the trace from C [mm]", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.set_title(title, fontsize=8.5)


def figure_space_time(run, arguments, summary):
    nodes = FaultNodes(run)
    data = space_time(run, nodes)
    if data is None:
        mf.message("space-time slip rate skipped: the frames have no contact grids with 'slip'")
        return []
    edges, times, mean_step, mean_rate = data
    norm = rate_norm(mean_step, mean_rate)
    if norm is None:
        mf.message("space-time slip rate skipped: no slip between frames")
        return []
    fig, axes = plt.subplots(1, 3, figsize=(13, 6.5), sharey=True, constrained_layout=True,
                             gridspec_kw=dict(width_ratios=(1, 1, 0.55)))
    mesh = draw_space_time(axes[0], run, data, norm,
                           "mean slip rate between consecutive frames")
    masked = np.ma.masked_where(~np.isfinite(mean_rate) | (mean_rate <= norm.vmin), mean_rate)
    axes[1].pcolormesh(edges, mf.cell_edges(times), masked, cmap="viridis", norm=norm,
                       shading="flat")
    mark_events(axes[1], run)
    finish_space_time(axes[1], run, "slip rate at the frames (snapshot)")
    bar = fig.colorbar(mesh, ax=axes[:2].tolist(), location="bottom", shrink=0.6, aspect=40)
    bar.set_label("slip rate [mm/s] (mean through the thickness; blank: below "
                  f"{norm.vmin:.1e})", fontsize=8)
    axes[0].set_ylabel("time [s]", fontsize=8)
    quiet_until = first_slip_time(data, norm)
    axes[0].set_ylim(quiet_until, times[-1])
    handles, labels = axes[0].get_legend_handles_labels()
    if handles:
        axes[0].legend(fontsize=7, loc="lower right")
    columns = [p for p in run.pairs if any(f"{p}_RATE_MAX" in t for t in run.tables.values())]
    for pair in columns:
        table = next(t for t in run.tables.values() if f"{pair}_RATE_MAX" in t)
        y = table[f"{pair}_RATE_MAX"]
        if np.any(y > norm.vmin):
            covered = run.pairs[pair]
            colour = mf.SEGMENT_COLOURS.get(covered[0] if len(covered) == 1 else "", None)
            axes[2].semilogx(np.maximum(y, norm.vmin), table["time"], lw=0.8, color=colour,
                             label=pair + (" (tie)" if pair in run.ties else ""))
    axes[2].set_xlim(left=norm.vmin)
    axes[2].set_xlabel("largest slip rate of the pair [mm/s]", fontsize=8)
    axes[2].set_title("*HISTORY, every increment", fontsize=8.5)
    axes[2].grid(True, lw=0.3)
    axes[2].tick_params(labelsize=7)
    if columns:
        axes[2].legend(fontsize=7)
    dt = np.diff(times)
    spacing = np.diff(mf.cell_edges(np.sort(0.5 * (edges[1:] + edges[:-1]))))
    samples = sum(len(t["time"]) for t in run.tables.values()
                  if any(f"{p}_RATE_MAX" in t for p in run.pairs)) if columns else 0
    resolution = (f"{len(times)} frames (spacing {np.median(dt):g} s median, {dt.min():g} .. "
                  f"{dt.max():g} s), {len(edges) - 1} node columns along the trace "
                  f"(spacing {np.median(spacing):.2f} mm median), {len(nodes)} slave nodes")
    fig.suptitle(f"Slip rate along C-G against time: {resolution}\n(no slip rate above "
                 f"{norm.vmin:.1e} mm/s before {quiet_until:g} s)", fontsize=9.5)
    path = save(fig, run, arguments, "space_time")
    summary.append(f"space-time slip rate: {resolution}; *HISTORY: {samples} samples per pair "
                   "(largest rate of the pair only: the CSV holds no per-node data)")
    return [path]


# ------------------------------------------------------------------------------ stations


def station_nodes(run, nodes):
    """[(name, node number in `nodes`)] of the stations, at the node level nearest to
    mid-thickness."""
    level = nodes.mid_level()
    on_level = np.nonzero(np.abs(nodes.z - level) <= 1e-6 * max(1.0, abs(level)))[0]
    out = []
    for name, where in STATIONS:
        if len(where) == 1:
            target = mf.along_of(run.trace, where)
        else:
            target = run.trace.start[where] + 0.5 * run.trace.lengths[where]
        out.append((name, int(on_level[np.argmin(np.abs(nodes.along[on_level] - target))])))
    return out


def figure_stations(run, arguments, summary):
    nodes = FaultNodes(run)
    if not len(nodes):
        mf.message("station histories skipped: no contact grids")
        return []
    fields = {name: nodes.series(name) for name in ("pressure", "shear_magnitude", "slip")}
    if any(v is None for v in fields.values()):
        mf.message("station histories skipped: the contact grids lack pressure, "
                   "shear_magnitude or slip")
        return []
    times = run.results.times
    stations = station_nodes(run, nodes)
    rows = ["station,grid,node,x,y,z,along,time,pressure,shear,slip"]
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True, constrained_layout=True)
    panels = (("pressure", "normal traction (contact pressure) [MPa]"),
              ("shear_magnitude", "shear traction [MPa]"), ("slip", "accumulated slip [mm]"))
    for (name, k), colour in zip(stations, STATION_COLOURS):
        kind = "tied" if nodes.tied[k] else "frictional"
        for ax, (field, label) in zip(axes, panels):
            ax.plot(times, fields[field][:, k], color=colour, lw=1.0, marker=".", ms=2.5,
                    label=f"{name} ({kind}, {nodes.along[k]:.1f} mm from C)")
            ax.set_ylabel(label, fontsize=8)
        x, y, z = nodes.xyz[k]
        for f, t in enumerate(times):
            rows.append(f"{name},{nodes.grid[k]},{nodes.index[k]},{x:.6g},{y:.6g},{z:.6g},"
                        f"{nodes.along[k]:.6g},{t:.17g},{fields['pressure'][f, k]:.17g},"
                        f"{fields['shear_magnitude'][f, k]:.17g},{fields['slip'][f, k]:.17g}")
        summary.append(f"station {name}: {nodes.grid[k]} slave node {nodes.index[k]} at "
                       f"({x:.2f}, {y:.2f}, {z:.2f}) mm, {nodes.along[k]:.2f} mm from C ({kind})")
    events = run.events
    for ax in axes:
        ax.grid(True, lw=0.3)
        ax.tick_params(labelsize=7)
        if events is not None:
            for onset in events.get("onset", []):
                ax.axvline(onset, color="0.6", lw=0.5, ls=":")
    axes[0].legend(fontsize=7)
    axes[-1].set_xlabel(f"time [s] ({len(times)} frames"
                        + ("; dotted: event onsets" if events is not None and
                           len(events.get("onset", [])) else "") + ")", fontsize=8)
    fig.suptitle(f"Tractions and slip at fault stations (slave nodes at z = "
                 f"{nodes.mid_level():g} mm)", fontsize=10)
    path = save(fig, run, arguments, "stations")
    table = os.path.join(arguments.out, f"{arguments.prefix}_stations.csv")
    with open(table, "w", encoding="utf-8") as handle:
        handle.write("\n".join(rows) + "\n")
    return [path, table]


# ------------------------------------------------------------------------------ events


def large_events(run, share):
    """[(number, row)] of the catalogued events over at least `share` of the frictional
    fault's slave nodes."""
    events = run.events
    if events is None or not len(events.get("onset", [])):
        return [], 0
    total = frictional_node_count(run)
    picked = [k for k in range(len(events["onset"]))
              if total and events["nodes"][k] >= share * total]
    return picked, total


def bracketing_frames(times, onset, end):
    """(last frame at or before onset, first frame at or after end), None where absent."""
    before = np.nonzero(times <= onset + mf.TIME_TOLERANCE * max(1.0, onset))[0]
    after = np.nonzero(times >= end - mf.TIME_TOLERANCE * max(1.0, end))[0]
    return (int(before[-1]) if len(before) else None, int(after[0]) if len(after) else None)


def figure_event_maps(run, arguments, summary):
    stale = re.compile(re.escape(arguments.prefix) + r"_event\d+\.png$")
    for name in os.listdir(arguments.out):
        if stale.match(name):               # maps of an earlier run's events
            os.remove(os.path.join(arguments.out, name))
    picked, total = large_events(run, arguments.large_event_share)
    if not picked:
        mf.message(f"event maps skipped: no event over {100 * arguments.large_event_share:g} % "
                   f"of the {total} frictional slave nodes")
        summary.append(f"event maps: no event over {100 * arguments.large_event_share:g} % of "
                       f"the {total} frictional slave nodes")
        return []
    results = run.results
    events = run.events
    nodes = FaultNodes(run)
    shear = nodes.series("shear_magnitude")
    z0 = arguments.z if arguments.z is not None else 0.5 * (
        results.x_ref[:, 2].min() + results.x_ref[:, 2].max())
    maps = mf.MisesMaps(results, z0)
    times = results.times
    written = []
    summary.append(f"event maps: events over {100 * arguments.large_event_share:g} % of the "
                   f"{total} frictional slave nodes; frames at or before the onset and at or "
                   "after the end")
    gaps = []
    for k in picked:
        number = int(events["event"][k]) if "event" in events else k + 1
        onset, end = float(events["onset"][k]), float(events["end"][k])
        before, after = bracketing_frames(times, onset, end)
        if before is None or after is None or before == after:
            mf.message(f"event {number}: no frames around {onset:g} .. {end:g} s; skipped")
            continue
        between = [int(events["event"][j]) if "event" in events else j + 1
                   for j in range(len(events["onset"]))
                   if j != k and times[before] < events["onset"][j] < times[after]]
        gap_before, gap_after = onset - times[before], times[after] - end
        gaps.append((gap_before, gap_after))
        fig, axes = plt.subplots(2, 3, figsize=(13, 7.4), constrained_layout=True,
                                 gridspec_kw=dict(height_ratios=(1.6, 1)))
        m0, m1 = maps.values(before), maps.values(after)
        if m0 is not None and m1 is not None:
            low = float(min(np.percentile(m0, 0.5), np.percentile(m1, 0.5)))
            high = float(max(np.percentile(m0, 99.5), np.percentile(m1, 99.5)))
            for ax, values, title in ((axes[0, 0], m0, f"before: t = {times[before]:g} s"),
                                      (axes[0, 1], m1, f"after: t = {times[after]:g} s")):
                mappable = maps.draw(ax, values, low, high, plt.get_cmap("jet"))
                mf.draw_trace(ax, run.trace)
                mf.setup_plan_axes(ax, results)
                ax.set_title(f"Mises, {title}", fontsize=9)
            fig.colorbar(mappable, ax=axes[0, :2].tolist(), shrink=0.8,
                         extend="both").set_label("Mises [MPa]", fontsize=8)
            change = m1 - m0
            bound = max(float(np.abs(change).max()), 1e-12)
            mappable = maps.draw(axes[0, 2], change, -bound, bound, plt.get_cmap("RdBu_r"))
            mf.draw_trace(axes[0, 2], run.trace)
            mf.setup_plan_axes(axes[0, 2], results)
            axes[0, 2].set_title("Mises after - before", fontsize=9)
            fig.colorbar(mappable, ax=axes[0, 2], shrink=0.8).set_label("change [MPa]",
                                                                        fontsize=8)
        if shear is not None:
            triangulation = Triangulation(nodes.along, nodes.z)
            s0, s1 = shear[before], shear[after]
            free = ~nodes.tied if (~nodes.tied).any() else np.ones(len(nodes), bool)
            low = float(min(np.nanmin(s0[free]), np.nanmin(s1[free])))
            high = float(max(np.nanmax(s0[free]), np.nanmax(s1[free])))
            for ax, values, title in ((axes[1, 0], s0, "before"), (axes[1, 1], s1, "after")):
                mappable = ax.tripcolor(triangulation, values, shading="gouraud", cmap="jet",
                                        vmin=low, vmax=high, rasterized=True)
                ax.set_title(f"shear traction on the fault, {title}", fontsize=9)
            fig.colorbar(mappable, ax=axes[1, :2].tolist(), shrink=0.8, extend="both").set_label(
                "shear [MPa] (scale of the frictional nodes)", fontsize=8)
            change = s1 - s0
            bound = max(float(np.nanmax(np.abs(change[free]))), 1e-12)
            mappable = axes[1, 2].tripcolor(triangulation, change, shading="gouraud",
                                            cmap="RdBu_r", norm=TwoSlopeNorm(0.0, -bound, bound),
                                            rasterized=True)
            axes[1, 2].set_title("shear after - before", fontsize=9)
            fig.colorbar(mappable, ax=axes[1, 2], shrink=0.8, extend="both").set_label(
                "change [MPa]", fontsize=8)
            for ax in axes[1]:
                mark_trace_points(ax, run.trace)
                ax.set_xlim(0.0, run.trace.total_length)
                ax.set_xlabel("distance along the trace from C [mm]", fontsize=8)
                ax.set_ylabel("z [mm]", fontsize=8)
                ax.tick_params(labelsize=7)
                if "x" in events and "y" in events:
                    hypocentre = run.trace.along(np.array([[events["x"][k], events["y"][k]]]))[0]
                    ax.plot(hypocentre, [events["z"][k]] if "z" in events else [0.0], "*",
                            color="white", mec="black", ms=10)
        note = f"; other events in between: {', '.join(map(str, between))}" if between else ""
        fig.suptitle(f"Event {number}: onset {onset:g} s, end {end:g} s, "
                     f"{int(events['nodes'][k])} of {total} nodes, stress drop "
                     f"{events['stress_drop'][k]:.3g} MPa. Frames {gap_before:.3g} s before the "
                     f"onset and {gap_after:.3g} s after the end{note}", fontsize=9.5)
        written.append(save(fig, run, arguments, f"event{number}", dpi=MAP_DPI))
        summary.append(f"  event {number} ({onset:g} .. {end:g} s, {int(events['nodes'][k])} "
                       f"nodes): frames at {times[before]:g} s ({gap_before:.3g} s before the "
                       f"onset) and {times[after]:g} s ({gap_after:.3g} s after the end){note}")
    if gaps and max(max(g) for g in gaps) > 0:
        summary.append("  exact before/after frames: *CONTACT FILE, FREQUENCY=1 (with *EL FILE, "
                       "FREQUENCY=1 for the Mises maps) writes a frame at every increment, and "
                       "event onsets and ends are increment boundaries; a *TIME POINTS list "
                       "cannot, since the event times are not known before the run")
    return written


# ------------------------------------------------------------------------------ comparison


def load_curve(run):
    """(time, force [kN], what) on the face moved by *BOUNDARY, TYPE=VELOCITY (else face B, the
    nodes on x = max x): its *HISTORY reaction if the tables hold it, else the frames' nodal
    forces."""
    model = deck_model(run.deck)
    for name, dof, _, _ in model["velocities"]:
        for table in run.tables.values():
            column = f"{name}_RF{dof}"
            if column in table:
                return table["time"], -table[column] / 1000.0, f"-{column} (*HISTORY)"
    results = run.results
    x = results.x_ref
    on_b = np.nonzero(x[:, 0] >= x[:, 0].max() - 1e-6 * np.ptp(x, axis=0).max())[0]
    times, force = [], []
    for index in range(len(results.frames)):
        f = results.field(index, "nodal", "force")
        if f is not None:
            times.append(results.times[index])
            force.append(-f[on_b, 0].sum() / 1000.0)
    return np.array(times), np.array(force), "-sum of F_x on x = max x (frames)"


def figure_compare(run, other, arguments, summary):
    """The two runs side by side: space-time slip rate on one colour scale, force on the moved
    face against time (the other run thin grey for reference)."""
    data = [space_time(r) for r in (run, other)]
    if any(d is None for d in data):
        mf.message("comparison skipped: a run lacks contact grids with 'slip'")
        return []
    norm = rate_norm(*(d[2] for d in data))
    if norm is None:
        mf.message("comparison skipped: no slip between frames in either run")
        return []
    fig, axes = plt.subplots(2, 2, figsize=(12, 9.5), constrained_layout=True,
                             gridspec_kw=dict(height_ratios=(1.7, 1)))
    curves = [load_curve(r) for r in (run, other)]
    end = max(float(d[1][-1]) for d in data)
    start = min(first_slip_time(d, norm) for d in data)
    shown = [c[1][(c[0] >= start) & (c[0] <= end)] for c in curves]
    top = max(float(np.nanmax(v)) for v in shown if len(v))
    bottom = min(float(np.nanmin(v)) for v in shown if len(v))
    for column, (r, d, curve, reference) in enumerate(zip((run, other), data, curves,
                                                          curves[::-1])):
        title = run_title(r)
        mesh = draw_space_time(axes[0, column], r, d, norm, title)
        axes[0, column].set_ylim(start, end)
        axes[0, column].set_ylabel("time [s]", fontsize=8)
        ax = axes[1, column]
        ax.plot(reference[0], reference[1], color="0.7", lw=0.8, label="the other run")
        ax.plot(curve[0], curve[1], color="C0", lw=1.0, label=curve[2])
        if r.events is not None:
            for onset in r.events.get("onset", []):
                ax.axvline(onset, color="C3", lw=0.5, ls=":")
        ax.set_xlim(start, end)
        ax.set_ylim(bottom - 0.05 * (top - bottom), top + 0.05 * (top - bottom))
        ax.set_xlabel("time [s] (dotted: event onsets)", fontsize=8)
        ax.set_ylabel("force on the moved face [kN]", fontsize=8)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
        ax.tick_params(labelsize=7)
        first = r.events["onset"][0] if r.events is not None and len(
            r.events.get("onset", [])) else None
        summary.append(f"compare: {title}: {len(r.events['onset']) if first else 0} events"
                       + (f", first onset {first:g} s" if first else "") +
                       f", peak force {np.nanmax(curve[1]):.1f} kN")
    fig.colorbar(mesh, ax=axes[0, :].tolist(), location="bottom", shrink=0.6,
                 aspect=40).set_label("mean slip rate between frames [mm/s] (one scale)",
                                      fontsize=8)
    fig.supxlabel(f"left: {run.label}\nright: {other.label}", x=0.005, ha="left",
                  fontsize=5.5, color="0.35")
    path = os.path.join(arguments.out, f"{arguments.prefix}_compare.png")
    fig.suptitle(f"Two runs side by side from {start:g} s (no slip before in either run)",
                 fontsize=10)
    fig.savefig(path, dpi=arguments.dpi)
    plt.close(fig)
    return [path]


def run_title(run):
    """A short name for a run: its job and the gmsh options it was meshed with."""
    options = ", ".join(f"{n} {v}" for n, v in run.mesh_options)
    return f"job {run.job}" + (f" ({options})" if options else " (default mesh)")
