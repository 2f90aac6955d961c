#!/usr/bin/python3
"""Geometry of the fault-bend model's trace, shared by the post-processing scripts.

The trace C-D-E-F-G is computed exactly as input/fault_bend/fault_bend.geo computes it, from
the same parameters (bend_angle, fault_angle, xE, yE, tied_length, width, height, thickness).
The defaults are read from the .geo file itself (its `If (!Exists(name)) name = value;`
blocks), so there is one place that holds them; `-setnumber`-style overrides are applied on
top. The trace can also be recovered from a results file: the slave nodes of the contact grids
of the pairs/ties named CD, DE, EF, FG (the names the deck gives them).

Used as a module by check_fault_mesh.py and make_figures.py; run on its own it prints the
points of the trace:

    /usr/bin/python3 post/fault_profile.py [--geo input/fault_bend/fault_bend.geo]
                                           [--setnumber NAME VALUE ...]
"""

import argparse
import math
import os
import re
import sys

import numpy as np

#: The .geo file next to this checkout's post/ directory.
DEFAULT_GEO = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "input",
                           "fault_bend", "fault_bend.geo")
#: The fault segments in order along the trace, and their end points.
SEGMENTS = (("CD", "C", "D"), ("DE", "D", "E"), ("EF", "E", "F"), ("FG", "F", "G"))
#: Parameters the trace depends on (all have defaults in the .geo file).
TRACE_PARAMETERS = ("bend_angle", "fault_angle", "xE", "yE", "tied_length", "width", "height",
                    "thickness")

_DEFAULT_PATTERN = re.compile(
    r"If\s*\(\s*!\s*Exists\s*\(\s*(\w+)\s*\)\s*\)\s*\n\s*\1\s*=\s*([-+0-9.eE]+)\s*;")


def geo_defaults(path=DEFAULT_GEO):
    """The parameter defaults of a .geo file: {name: value} from its If (!Exists(..)) blocks."""
    with open(path, encoding="utf-8") as handle:
        text = handle.read()
    return {name: float(value) for name, value in _DEFAULT_PATTERN.findall(text)}


def parameters(geo=DEFAULT_GEO, overrides=None):
    """The .geo defaults updated by `overrides` ({name: value} or [(name, value)])."""
    values = geo_defaults(geo)
    missing = [name for name in TRACE_PARAMETERS if name not in values]
    if missing:
        raise ValueError(f"{geo}: no default for {', '.join(missing)}")
    for name, value in dict(overrides or {}).items():
        values[name] = float(value)
    return values


class FaultTrace:
    """The polyline C-D-E-F-G in the x-y plane, with distances along it."""

    def __init__(self, points, thickness=None):
        self.points = {name: np.asarray(points[name], dtype=float)[:2] for name in "CDEFG"}
        self.thickness = thickness
        self.lengths = {seg: float(np.linalg.norm(self.points[b] - self.points[a]))
                        for seg, a, b in SEGMENTS}
        self.start = {}
        total = 0.0
        for seg, _, _ in SEGMENTS:
            self.start[seg] = total
            total += self.lengths[seg]
        self.total_length = total

    @classmethod
    def from_parameters(cls, p):
        """Same formulas as fault_bend.geo (see there)."""
        a1 = math.radians(p["fault_angle"] - p["bend_angle"] / 2)
        a2 = math.radians(p["fault_angle"] + p["bend_angle"] / 2)
        xe, ye, width, height = p["xE"], p["yE"], p["width"], p["height"]
        eps = 1e-6 * width
        yc = ye - xe * math.tan(a1)
        xg = xe + (height - ye) / math.tan(a2)
        if yc < -eps or yc > height - eps:
            raise ValueError(f"the trace meets x = 0 at y = {yc:g}, outside the plate")
        if xg < eps or xg > width + eps:
            raise ValueError(f"the trace meets y = {height:g} at x = {xg:g}, outside the plate")
        yc = 0.0 if yc < eps else yc
        xg = width if xg > width - eps else xg
        tied = p["tied_length"]
        c = np.array([0.0, yc])
        g = np.array([xg, height])
        d = c + tied * np.array([math.cos(a1), math.sin(a1)])
        f = g - tied * np.array([math.cos(a2), math.sin(a2)])
        return cls({"C": c, "D": d, "E": np.array([xe, ye]), "F": f, "G": g},
                   thickness=p.get("thickness"))

    @classmethod
    def from_contact_grids(cls, grids):
        """From {segment: (m, 3) slave-node coordinates} of the four segments CD, DE, EF, FG:
        the ends of each segment are its extreme nodes along the segment's direction."""
        ends = {}
        for seg, _, _ in SEGMENTS:
            xy = np.asarray(grids[seg], dtype=float)[:, :2]
            centre = xy.mean(axis=0)
            _, _, vt = np.linalg.svd(xy - centre, full_matrices=False)
            direction = vt[0]
            s = (xy - centre) @ direction
            first, last = xy[np.argmin(s)], xy[np.argmax(s)]
            ends[seg] = (first, last)
        # Orient every segment from C towards G: C is the end of CD farthest from DE, etc.
        points = {}
        cd0, cd1 = ends["CD"]
        de_mid = np.mean(ends["DE"], axis=0)
        c, d = (cd0, cd1) if np.linalg.norm(cd0 - de_mid) > np.linalg.norm(cd1 - de_mid) \
            else (cd1, cd0)
        fg0, fg1 = ends["FG"]
        ef_mid = np.mean(ends["EF"], axis=0)
        g, f = (fg0, fg1) if np.linalg.norm(fg0 - ef_mid) > np.linalg.norm(fg1 - ef_mid) \
            else (fg1, fg0)
        de0, de1 = ends["DE"]
        e_from_de = de1 if np.linalg.norm(de0 - d) < np.linalg.norm(de1 - d) else de0
        ef0, ef1 = ends["EF"]
        e_from_ef = ef1 if np.linalg.norm(ef0 - f) < np.linalg.norm(ef1 - f) else ef0
        points.update(C=c, D=d, E=0.5 * (e_from_de + e_from_ef), F=f, G=g)
        return cls(points)

    def segment_ends(self, seg):
        for name, a, b in SEGMENTS:
            if name == seg:
                return self.points[a], self.points[b]
        raise KeyError(seg)

    def project(self, xy, seg):
        """(distance along the segment from its first point, signed distance from its line
        (positive on the left, i.e. the upper-left block's side)) for points xy (n, 2)."""
        a, b = self.segment_ends(seg)
        t = (b - a) / np.linalg.norm(b - a)
        rel = np.asarray(xy, dtype=float)[..., :2] - a
        along = rel @ t
        normal = rel[..., 1] * t[0] - rel[..., 0] * t[1]
        return along, normal

    def along(self, xy):
        """Distance along the whole trace from C of the nearest point of the trace, and the
        segment that point is on, for points xy (n, 2)."""
        xy = np.atleast_2d(np.asarray(xy, dtype=float))[:, :2]
        best = np.full(len(xy), np.inf)
        position = np.zeros(len(xy))
        segment = np.empty(len(xy), dtype=object)
        for seg, _, _ in SEGMENTS:
            s, n = self.project(xy, seg)
            clipped = np.clip(s, 0.0, self.lengths[seg])
            a, b = self.segment_ends(seg)
            t = (b - a) / self.lengths[seg]
            nearest = a + clipped[:, None] * t
            distance = np.linalg.norm(xy - nearest, axis=1)
            better = distance < best
            best[better] = distance[better]
            position[better] = self.start[seg] + clipped[better]
            segment[better] = seg
        return position, segment, best

    def polyline(self):
        return np.array([self.points[name] for name in "CDEFG"])

    def upper_block_polygon(self, width, height):
        """The upper-left block's outline in the x-y plane (counter-clockwise)."""
        return np.vstack([self.polyline(), [[0.0, height]]])


def main():
    parser = argparse.ArgumentParser(description="Print the fault trace of fault_bend.geo.")
    parser.add_argument("--geo", default=DEFAULT_GEO)
    parser.add_argument("-setnumber", "--setnumber", nargs=2, action="append", default=[],
                        metavar=("NAME", "VALUE"))
    arguments = parser.parse_args()
    try:
        p = parameters(arguments.geo, [(n, float(v)) for n, v in arguments.setnumber])
        trace = FaultTrace.from_parameters(p)
    except (OSError, ValueError) as error:
        print(f"fault_profile.py: {error}", file=sys.stderr)
        return 2
    for name in "CDEFG":
        x, y = trace.points[name]
        print(f"{name}  ({x:.4f}, {y:.4f})")
    for seg, _, _ in SEGMENTS:
        print(f"{seg}: length {trace.lengths[seg]:.4f} mm, from {trace.start[seg]:.4f} mm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
