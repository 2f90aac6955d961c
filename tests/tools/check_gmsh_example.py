#!/usr/bin/python3
"""Check the results of the gmsh example (input/examples/block.inp, mesh size h = 0.5).

Usage: check_gmsh_example.py block.h5 block.dat

The block is 10 x 4 x 2 with h = 0.5: 20 x 8 x 4 = 640 hexahedra and 21 x 9 x 5 = 945 nodes,
clamped at x = 0, pressure p = 100 on x = 10, E = 210000. Checks:
  - the file's format attributes, /mesh datasets with these shapes, connectivity in range;
  - frames: the initial one at time 0 and the last one at time 1, marked complete, holding
    nodal displacement (945, 3), force (945, 3), stress (945, 6) and integration-point
    stress and strain (640, 8, 6), all finite;
  - physics, exactly: the clamped nodes do not move; the mean of sxx over the (equal-volume)
    integration points is -p to 1e-10 relative, an identity of the discrete equilibrium (virtual
    work with the linear test field u* = x e_x, which the mesh represents exactly); the total
    force on LOADED in block.dat is -p x 8 = -800 to print precision (1e-6);
  - physics, roughly: the mean x displacement of the loaded face is within 3% of the uniaxial
    -p L / E (the clamped end stiffens the block by about 1%).
"""

import sys

import h5py
import numpy as np

import datfile

N_NODES, N_ELEMENTS, PRESSURE, LENGTH, MODULUS, AREA = 945, 640, 100.0, 10.0, 210000.0, 8.0


def main(h5_path, dat_path):
    problems = []

    def expect(condition, text):
        if not condition:
            problems.append(text)

    def shape(dataset, wanted):
        expect(dataset.shape == wanted, f"{dataset.name}: shape {dataset.shape}, expected {wanted}")

    with h5py.File(h5_path, "r") as f:
        expect(f.attrs.get("format") in (b"fcs3d results", "fcs3d results"), "format attribute")
        shape(f["mesh/node_ids"], (N_NODES,))
        shape(f["mesh/coordinates"], (N_NODES, 3))
        shape(f["mesh/element_ids"], (N_ELEMENTS,))
        shape(f["mesh/connectivity"], (N_ELEMENTS, 8))
        connectivity = f["mesh/connectivity"][...]
        expect(connectivity.min() >= 0 and connectivity.max() < N_NODES, "connectivity out of range")
        x = f["mesh/coordinates"][...]
        names = sorted(f["frames"].keys())
        expect(len(names) == 2, f"{len(names)} frames, expected 2 (time 0 and 1)")
        first, last = f["frames"][names[0]], f["frames"][names[-1]]
        expect(first.attrs["time"] == 0.0 and last.attrs["time"] == 1.0, "frame times")
        expect(last.attrs["complete"] == 1, "last frame not complete")
        fields = {"nodal/displacement": (N_NODES, 3), "nodal/force": (N_NODES, 3),
                  "nodal/stress": (N_NODES, 6), "integration_points/stress": (N_ELEMENTS, 8, 6),
                  "integration_points/strain": (N_ELEMENTS, 8, 6)}
        for name, wanted in fields.items():
            if name not in last:
                problems.append(f"last frame lacks {name}")
                continue
            shape(last[name], wanted)
            expect(np.isfinite(last[name][...]).all(), f"{name}: not finite")
        if problems:
            return problems
        u = last["nodal/displacement"][...]
        stress = last["integration_points/stress"][...]
        xx = list(last["integration_points/stress"].attrs["components"].decode().split()).index("xx")
    clamped = np.isclose(x[:, 0], 0.0)
    loaded = np.isclose(x[:, 0], LENGTH)
    expect(clamped.sum() == 45 and loaded.sum() == 45, "node counts on the end faces")
    expect(np.abs(u[clamped]).max() == 0.0, "clamped nodes moved")
    mean_sxx = stress[:, :, xx].mean()
    print(f"mean sxx {mean_sxx:.12g} (exact -{PRESSURE:g})")
    expect(abs(mean_sxx + PRESSURE) <= 1e-10 * PRESSURE, f"mean sxx {mean_sxx!r} is not -{PRESSURE}")
    end = u[loaded, 0].mean()
    uniaxial = -PRESSURE * LENGTH / MODULUS
    print(f"mean u_x on LOADED {end:.6g}, uniaxial {uniaxial:.6g} ({100 * (end / uniaxial - 1):+.2f}%)")
    expect(abs(end / uniaxial - 1.0) <= 0.03, "loaded-face displacement far from -p L / E")
    totals = [b for b in datfile.read_blocks(dat_path) if b.kind == "total" and b.set_name == "LOADED"]
    expect(len(totals) == 1, "block.dat: no total force for LOADED")
    if totals:
        fx = totals[0].values()[0, 0]
        print(f"total force on LOADED {fx:g} (exact {-PRESSURE * AREA:g})")
        expect(abs(fx + PRESSURE * AREA) <= 1e-6 * PRESSURE * AREA, "total force on LOADED")
    return problems


if __name__ == "__main__":
    found = main(sys.argv[1], sys.argv[2])
    for problem in found:
        print("FAIL: " + problem)
    sys.exit(1 if found else 0)
