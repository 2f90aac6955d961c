#!/usr/bin/python3
"""Check an XDMF 2 file written by fcs3d (or any XDMF 2 time series with HDF5 heavy data).

Usage: /usr/bin/python3 post/check_xdmf.py [--frames N] FILE.xdmf [FILE.xdmf ...]

Checks that the file is well-formed XML, an <Xdmf Version="2..."> document with a <Domain>
holding a Temporal collection whose frames each carry a <Time> (non-decreasing); that every
Uniform grid has a known topology and an XYZ geometry; and that every DataItem refers to an
existing dataset ("file.h5:/path", file relative to the XDMF) whose shape equals its Dimensions
and whose type matches NumberType/Precision. Sizes are cross-checked: the connectivity holds
NumberOfElements x NodesPerElement entries within 0..points-1, node-centred attributes have one
row per point, cell-centred ones one per cell, and Scalar/Vector/Tensor6/Tensor have 1/3/6/9
components. With --frames N the number of frames must be N.

Prints "FILE: N frames, M datasets checked (D distinct)" and exits 0, or lists every problem
found and exits 1 (2 for bad usage).
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

NODES_PER_CELL = {"Hexahedron": 8, "Quadrilateral": 4, "Triangle": 3, "Tetrahedron": 4,
                  "Wedge": 6, "Pyramid": 5}
VARIABLE_TOPOLOGIES = {"Polyvertex", "Polyline", "Polygon"}
COMPONENTS = {"Scalar": 1, "Vector": 3, "Tensor6": 6, "Tensor": 9}
MAX_PROBLEMS = 50


class Checker:
    """Walks one XDMF document and collects problems."""

    def __init__(self, path):
        self.path = path
        self.directory = os.path.dirname(os.path.abspath(path))
        self.problems = []
        self.files = {}
        self.connectivity_ranges = {}
        self.references = 0
        self.distinct = set()
        self.frames = 0

    def problem(self, where, text):
        self.problems.append(f"{where}: {text}")

    def close(self):
        for handle in self.files.values():
            if handle is not None:
                handle.close()

    # ---------------------------------------------------------------- document structure

    def run(self):
        try:
            root = ET.parse(self.path).getroot()
        except ET.ParseError as error:
            self.problem(self.path, f"not well-formed XML: {error}")
            return
        except OSError as error:
            self.problem(self.path, f"cannot read: {error.strerror}")
            return
        if root.tag != "Xdmf":
            self.problem(self.path, f"root element is <{root.tag}>, expected <Xdmf>")
            return
        version = root.get("Version", "")
        if not version.startswith("2"):
            self.problem(self.path, f'<Xdmf Version="{version}">, expected version 2')
        domains = root.findall("Domain")
        if len(domains) != 1:
            self.problem(self.path, f"{len(domains)} <Domain> elements, expected 1")
            return
        temporal = [g for g in domains[0].findall("Grid")
                    if g.get("GridType") == "Collection" and g.get("CollectionType") == "Temporal"]
        if len(temporal) != 1:
            self.problem(self.path, "the <Domain> holds no Temporal collection "
                         "(Grid GridType=\"Collection\" CollectionType=\"Temporal\")")
            return
        self.check_series(temporal[0])

    def check_series(self, series):
        previous = None
        for index, frame in enumerate(series.findall("Grid"), start=1):
            where = f"frame {index} ({frame.get('Name', 'unnamed')})"
            self.frames += 1
            time = self.frame_time(frame, where)
            if time is not None and previous is not None and time < previous:
                self.problem(where, f"time {time} is earlier than the previous frame's {previous}")
            if time is not None:
                previous = time
            grid_type = frame.get("GridType", "Uniform")
            if grid_type == "Uniform":
                self.check_grid(frame, where)
            elif grid_type == "Collection" and frame.get("CollectionType") == "Spatial":
                grids = frame.findall("Grid")
                if not grids:
                    self.problem(where, "empty Spatial collection")
                for grid in grids:
                    if grid.get("GridType", "Uniform") != "Uniform":
                        self.problem(where, f"grid {grid.get('Name')} is not Uniform")
                        continue
                    self.check_grid(grid, f"{where}, grid {grid.get('Name', 'unnamed')}")
            else:
                self.problem(where, f"unexpected GridType {grid_type} in a Temporal collection")

    def frame_time(self, frame, where):
        times = frame.findall("Time")
        if len(times) != 1:
            self.problem(where, f"{len(times)} <Time> elements, expected 1")
            return None
        try:
            return float(times[0].get("Value"))
        except (TypeError, ValueError):
            self.problem(where, f"bad <Time Value=\"{times[0].get('Value')}\">")
            return None

    # ---------------------------------------------------------------- one grid

    def check_grid(self, grid, where):
        topology = self.single(grid, "Topology", where)
        geometry = self.single(grid, "Geometry", where)
        if topology is None or geometry is None:
            return
        n_points = self.check_geometry(geometry, where)
        n_cells = self.check_topology(topology, n_points, where)
        for attribute in grid.findall("Attribute"):
            self.check_attribute(attribute, n_points, n_cells,
                                 f"{where}, attribute {attribute.get('Name', 'unnamed')}")

    def single(self, element, tag, where):
        found = element.findall(tag)
        if len(found) != 1:
            self.problem(where, f"{len(found)} <{tag}> elements, expected 1")
            return None
        return found[0]

    def check_geometry(self, geometry, where):
        where = f"{where}, geometry"
        if geometry.get("GeometryType", "XYZ") != "XYZ":
            self.problem(where, f"GeometryType {geometry.get('GeometryType')}, expected XYZ")
            return None
        item = self.single(geometry, "DataItem", where)
        shape = self.check_data_item(item, where) if item is not None else None
        if shape is None:
            return None
        if len(shape) != 2 or shape[1] != 3:
            self.problem(where, f"shape {shape}, expected (points, 3)")
            return None
        return shape[0]

    def check_topology(self, topology, n_points, where):
        where = f"{where}, topology"
        kind = topology.get("TopologyType", "")
        try:
            n_cells = int(topology.get("NumberOfElements", ""))
        except ValueError:
            self.problem(where, "missing or bad NumberOfElements")
            return None
        if kind in NODES_PER_CELL:
            per_cell = NODES_PER_CELL[kind]
            given = topology.get("NodesPerElement")
            if given is not None and int(given) != per_cell:
                self.problem(where, f"{kind} with NodesPerElement={given}, expected {per_cell}")
        elif kind in VARIABLE_TOPOLOGIES:
            try:
                per_cell = int(topology.get("NodesPerElement", ""))
            except ValueError:
                self.problem(where, f"{kind} needs NodesPerElement")
                return None
        else:
            self.problem(where, f"unsupported TopologyType \"{kind}\"")
            return None
        item = self.single(topology, "DataItem", where)
        shape = self.check_data_item(item, where) if item is not None else None
        if shape is None:
            return n_cells
        if int(np.prod(shape)) != n_cells * per_cell:
            self.problem(where, f"connectivity {shape} holds {int(np.prod(shape))} entries, "
                         f"expected {n_cells} x {per_cell}")
        low, high = self.connectivity_range(item)
        if n_points is not None and low is not None and (low < 0 or high >= n_points):
            self.problem(where, f"connectivity values {low}..{high} outside 0..{n_points - 1}")
        return n_cells

    def connectivity_range(self, item):
        reference = (item.text or "").strip()
        if reference not in self.connectivity_ranges:
            dataset = self.dataset(reference)
            if dataset is None or dataset.size == 0:
                self.connectivity_ranges[reference] = (None, None)
            else:
                values = dataset[()]
                self.connectivity_ranges[reference] = (int(values.min()), int(values.max()))
        return self.connectivity_ranges[reference]

    def check_attribute(self, attribute, n_points, n_cells, where):
        centre = attribute.get("Center", "Node")
        kind = attribute.get("AttributeType", "Scalar")
        item = self.single(attribute, "DataItem", where)
        shape = self.check_data_item(item, where) if item is not None else None
        if shape is None:
            return
        rows = {"Node": n_points, "Cell": n_cells}.get(centre)
        if centre not in ("Node", "Cell"):
            self.problem(where, f"Center=\"{centre}\", expected Node or Cell")
        elif rows is not None and shape[0] != rows:
            self.problem(where, f"{shape[0]} rows, expected {rows} "
                         f"({'points' if centre == 'Node' else 'cells'})")
        components = 1 if len(shape) == 1 else int(np.prod(shape[1:]))
        if kind == "Matrix":
            return
        if kind not in COMPONENTS:
            self.problem(where, f"unknown AttributeType \"{kind}\"")
        elif components != COMPONENTS[kind]:
            self.problem(where, f"{kind} with {components} components, "
                         f"expected {COMPONENTS[kind]}")

    # ---------------------------------------------------------------- heavy data

    def check_data_item(self, item, where):
        """Check one DataItem; return the dataset's shape, or None after a problem."""
        where = f"{where}, DataItem"
        if item.get("Format", "XML") != "HDF":
            self.problem(where, f"Format {item.get('Format', 'XML')}, expected HDF")
            return None
        try:
            dims = tuple(int(d) for d in item.get("Dimensions", "").split())
        except ValueError:
            dims = ()
        if not dims:
            self.problem(where, f"bad Dimensions \"{item.get('Dimensions')}\"")
            return None
        reference = (item.text or "").strip()
        self.references += 1
        dataset = self.dataset(reference, where)
        if dataset is None:
            return None
        self.distinct.add(reference)
        if tuple(dataset.shape) != dims:
            self.problem(where, f"{reference} has shape {tuple(dataset.shape)}, "
                         f"but Dimensions=\"{item.get('Dimensions')}\"")
            return None
        self.check_number_type(item, dataset, reference, where)
        return dims

    def check_number_type(self, item, dataset, reference, where):
        number_type = item.get("NumberType", item.get("DataType", "Float"))
        precision = int(item.get("Precision", "4"))
        kind = dataset.dtype.kind
        expected = {"Float": "f", "Int": "i", "UInt": "u", "Char": "i", "UChar": "u"}.get(number_type)
        if expected is None:
            self.problem(where, f"unknown NumberType {number_type}")
        elif kind != expected or dataset.dtype.itemsize != precision:
            self.problem(where, f"{reference} holds {dataset.dtype}, but NumberType="
                         f"{number_type} Precision={precision}")

    def dataset(self, reference, where=None):
        """The h5py dataset for "file.h5:/path", or None (reporting why when `where`)."""
        if ":" not in reference:
            if where:
                self.problem(where, f"\"{reference}\" is not of the form file.h5:/path")
            return None
        file_name, path = reference.rsplit(":", 1)
        if os.path.isabs(file_name) and where:
            self.problem(where, f"absolute file name {file_name}: the pair of files cannot move")
        full = os.path.join(self.directory, file_name)
        if full not in self.files:
            try:
                self.files[full] = h5py.File(full, "r")
            except OSError as error:
                self.files[full] = None
                if where:
                    self.problem(where, f"cannot open {full}: {error}")
                return None
        handle = self.files[full]
        if handle is None:
            return None
        if path not in handle or not isinstance(handle[path], h5py.Dataset):
            if where:
                self.problem(where, f"{reference}: no such dataset")
            return None
        return handle[path]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", metavar="FILE.xdmf")
    parser.add_argument("--frames", type=int, help="required number of frames")
    arguments = parser.parse_args()
    failed = False
    for path in arguments.files:
        checker = Checker(path)
        try:
            checker.run()
        finally:
            checker.close()
        if arguments.frames is not None and not checker.problems and \
                checker.frames != arguments.frames:
            checker.problem(path, f"{checker.frames} frames, expected {arguments.frames}")
        if checker.problems:
            failed = True
            print(f"{path}: {len(checker.problems)} problem(s):", file=sys.stderr)
            for text in checker.problems[:MAX_PROBLEMS]:
                print(f"  {text}", file=sys.stderr)
            if len(checker.problems) > MAX_PROBLEMS:
                print(f"  ... and {len(checker.problems) - MAX_PROBLEMS} more", file=sys.stderr)
        else:
            print(f"{path}: {checker.frames} frames, {checker.references} datasets checked "
                  f"({len(checker.distinct)} distinct)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
