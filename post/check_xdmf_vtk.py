#!/usr/bin/python3
"""Read an fcs3d XDMF file with VTK's vtkXdmfReader (the reader ParaView's "Xdmf Reader" uses)
and compare what it returns with the HDF5 data.

Usage: /usr/bin/python3 post/check_xdmf_vtk.py [--frames N] FILE.xdmf [FILE.xdmf ...]

For every time step: the reader's times equal the <Time> values; each grid of the frame comes
out with its number of points and cells; the points equal the Geometry dataset; every attribute
is present with its values (Tensor6 expanded by VTK to a 3x3 tensor, whose entries must be
xx xy xz / xy yy yz / xz yz zz taken from the stored order xx xy xz yy yz zz); every solid cell
(tetrahedra, wedges, hexahedra, linear or quadratic) is of a 3D solid type and has a positive
volume on its corners (the sum of the signed volumes of tetrahedra the corners split into, each
of which must be positive), i.e. the node order is VTK's.

Exit status: 0 if all agree, 1 on any difference or reader error, 2 for bad usage, 77 when no
VTK with the Xdmf2 reader is installed (Debian: python3-paraview provides vtkIOXdmf2;
python3-vtk9 alone does not) -- the convention for a skipped test.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import h5py
    from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import (VTK_TETRA, VTK_WEDGE, VTK_HEXAHEDRON,
                                               VTK_QUADRATIC_TETRA, VTK_QUADRATIC_WEDGE,
                                               VTK_QUADRATIC_HEXAHEDRON)
except ImportError as error:
    print(f"check_xdmf_vtk.py: skipped, VTK's Xdmf2 reader is not available ({error})")
    sys.exit(77)

#: VTK's expansion of Tensor6 (xx xy xz yy yz zz) into the 9 entries of a 3x3 tensor.
TENSOR6_TO_9 = [0, 1, 2, 1, 3, 4, 2, 4, 5]
#: Values are copied, not computed: they must be identical.
TOLERANCE = 0.0


def expected_frames(path):
    """[(time, [grid, ...])] from the XDMF text; a grid is a dict of its references."""
    root = ET.parse(path).getroot()
    series = root.find("Domain").find("Grid")
    frames = []
    for frame in series.findall("Grid"):
        time = float(frame.find("Time").get("Value"))
        grids = frame.findall("Grid") if frame.get("GridType") == "Collection" else [frame]
        frames.append((time, [describe_grid(grid) for grid in grids]))
    return frames


def describe_grid(grid):
    topology = grid.find("Topology")
    return {
        "name": grid.get("Name"),
        "cells": int(topology.get("NumberOfElements")),
        "geometry": grid.find("Geometry").find("DataItem").text.strip(),
        "attributes": [(a.get("Name"), a.get("Center", "Node"), a.get("AttributeType", "Scalar"),
                        a.find("DataItem").text.strip()) for a in grid.findall("Attribute")],
    }


class Heavy:
    """Reads "file.h5:/path" references relative to the XDMF file."""

    def __init__(self, xdmf_path):
        self.directory = os.path.dirname(os.path.abspath(xdmf_path))
        self.files = {}

    def read(self, reference):
        file_name, path = reference.rsplit(":", 1)
        full = os.path.join(self.directory, file_name)
        if full not in self.files:
            self.files[full] = h5py.File(full, "r")
        return self.files[full][path][()]

    def close(self):
        for handle in self.files.values():
            handle.close()


def output_blocks(output):
    """The unstructured grids of the reader's output, in order."""
    if output.IsA("vtkMultiBlockDataSet"):
        return [output.GetBlock(i) for i in range(output.GetNumberOfBlocks())]
    return [output]


def compare_grid(block, grid, heavy, where, problems):
    """Compare one VTK block with its XDMF grid; return the number of arrays compared."""
    points = heavy.read(grid["geometry"])
    if block.GetNumberOfPoints() != points.shape[0]:
        problems.append(f"{where}: {block.GetNumberOfPoints()} points, expected {points.shape[0]}")
        return 0
    if block.GetNumberOfCells() != grid["cells"]:
        problems.append(f"{where}: {block.GetNumberOfCells()} cells, expected {grid['cells']}")
    vtk_points = vtk_to_numpy(block.GetPoints().GetData())
    if not np.allclose(vtk_points, points, rtol=TOLERANCE, atol=TOLERANCE):
        problems.append(f"{where}: points differ from {grid['geometry']}")
    check_solids(block, where, problems)
    compared = 0
    for name, centre, kind, reference in grid["attributes"]:
        data = block.GetPointData() if centre == "Node" else block.GetCellData()
        array = data.GetArray(name)
        if array is None:
            problems.append(f"{where}: no {centre} array {name}")
            continue
        stored = heavy.read(reference)
        stored = stored.reshape(stored.shape[0], -1)
        if kind == "Tensor6":
            stored = stored[:, TENSOR6_TO_9]
        values = vtk_to_numpy(array).reshape(stored.shape[0], -1)
        if values.shape != stored.shape or not np.allclose(values, stored, rtol=TOLERANCE,
                                                           atol=TOLERANCE):
            problems.append(f"{where}: array {name} {values.shape} differs from {reference}")
        compared += 1
    return compared


#: Corner tetrahedra of each solid cell type (VTK corner order; the corners come first in the
#: quadratic types too): a tetrahedron is itself; a wedge three; a hexahedron the six of
#: Kuhn's subdivision along the diagonal 0-6.
CORNER_TETRAHEDRA = {}
#: VTK cell types of surface grids (not checked): vertex, poly-vertex, line, triangle, polygon,
#: quadrilateral, quadratic triangle and quadrilateral.
SURFACE_CELL_TYPES = [1, 2, 3, 5, 7, 9, 22, 23]


def _corner_tetrahedra():
    tet = [(0, 1, 2, 3)]
    wedge = [(0, 1, 2, 3), (1, 2, 3, 4), (2, 3, 4, 5)]
    hexahedron = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6),
                  (0, 5, 1, 6)]
    for kind, table in ((VTK_TETRA, tet), (VTK_QUADRATIC_TETRA, tet), (VTK_WEDGE, wedge),
                        (VTK_QUADRATIC_WEDGE, wedge), (VTK_HEXAHEDRON, hexahedron),
                        (VTK_QUADRATIC_HEXAHEDRON, hexahedron)):
        CORNER_TETRAHEDRA[kind] = np.array(table)


def check_solids(block, where, problems):
    """Every cell a 3D solid type with positive corner tetrahedra: an inverted cell (negative
    volume) means a node order VTK does not expect."""
    if not CORNER_TETRAHEDRA:
        _corner_tetrahedra()
    points = vtk_to_numpy(block.GetPoints().GetData())
    cells = block.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    types = vtk_to_numpy(block.GetCellTypesArray())
    if np.isin(types, SURFACE_CELL_TYPES).all():
        return  # a surface grid (points, lines, triangles, quadrilaterals)
    inverted = 0
    for kind in np.unique(types):
        if kind not in CORNER_TETRAHEDRA:
            problems.append(f"{where}: cells of VTK type {kind}, not a 3D solid")
            continue
        for cell in np.flatnonzero(types == kind):
            ids = connectivity[offsets[cell]:offsets[cell + 1]]
            x = points[ids[CORNER_TETRAHEDRA[kind]]]
            volumes = np.einsum("ij,ij->i", np.cross(x[:, 1] - x[:, 0], x[:, 2] - x[:, 0]),
                                x[:, 3] - x[:, 0])
            if (volumes <= 0.0).any():
                inverted += 1
    if inverted:
        problems.append(f"{where}: {inverted} cells with a corner tetrahedron of volume <= 0 "
                        f"(node order is not VTK's)")


def check_file(path, n_frames):
    problems = []
    frames = expected_frames(path)
    if n_frames is not None and len(frames) != n_frames:
        problems.append(f"{len(frames)} frames, expected {n_frames}")
    reader = vtkXdmfReader()
    reader.AddObserver("ErrorEvent", lambda caller, event: problems.append("vtkXdmfReader error"))
    reader.SetFileName(path)
    reader.UpdateInformation()
    info = reader.GetOutputInformation(0)
    times = list(info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS()) or [])
    if len(times) != len(frames) or not np.allclose(times, [t for t, _ in frames]):
        problems.append(f"reader times {times}, XDMF times {[t for t, _ in frames]}")
        return problems, 0
    heavy = Heavy(path)
    compared = 0
    try:
        for index, (time, grids) in enumerate(frames, start=1):
            reader.UpdateTimeStep(time)
            blocks = output_blocks(reader.GetOutputDataObject(0))
            if len(blocks) != len(grids):
                problems.append(f"frame {index}: {len(blocks)} blocks, expected {len(grids)}")
                continue
            for block, grid in zip(blocks, grids):
                compared += compare_grid(block, grid, heavy, f"frame {index}, grid {grid['name']}",
                                         problems)
    finally:
        heavy.close()
    return problems, compared


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="+", metavar="FILE.xdmf")
    parser.add_argument("--frames", type=int, help="required number of frames")
    arguments = parser.parse_args()
    failed = False
    for path in arguments.files:
        try:
            problems, compared = check_file(path, arguments.frames)
        except (OSError, KeyError, AttributeError, ET.ParseError) as error:
            problems, compared = [f"cannot check: {error!r}"], 0
        if problems:
            failed = True
            print(f"{path}: {len(problems)} problem(s) reading with vtkXdmfReader:",
                  file=sys.stderr)
            for text in problems[:50]:
                print(f"  {text}", file=sys.stderr)
        else:
            print(f"{path}: vtkXdmfReader read {len(expected_frames(path))} frames, "
                  f"{compared} arrays identical to the HDF5 data")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
