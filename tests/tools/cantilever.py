#!/usr/bin/python3
"""Slender cantilever under a tip shear load: fcs3d against Timoshenko beam theory.

  cantilever.py [--meshes 10x1x1,20x2x2,40x4x4] [--formulations FULL,BBAR]
                [--solvers UMFPACK] [--work DIR] [--markdown FILE] [--assert-error 0.02]

The beam: length L = 10 along x, square section b = h = 1 (y, z), E = 1000, nu = 0.3. The
root face x = 0 is clamped (u = 0 at every node). A total transverse force P = 1 in y acts
on the tip face x = L as a uniform shear traction, i.e. the consistent nodal forces of the
bilinear face mesh (*CLOAD per node: corner, edge and interior nodes of the face carry 1/4,
1/2 and 1 times P/(ny nz)). The tip deflection is the mean y displacement of the tip-face
nodes.

Theory (Timoshenko beam, shear coefficient of a rectangular section from Cowper 1966,
"The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33(2), 335-340):

    delta = P L^3 / (3 E I) + P L / (k G A),   k = 10 (1 + nu) / (12 + 11 nu),
    I = b h^3 / 12, A = b h, G = E / (2 (1 + nu)).

For each mesh and formulation the script runs fcs3d (once per solver; with several solvers
it also checks that they agree to 1e-10 relative, round-off of the factorisations), prints
the table, optionally writes it as Markdown, and with --assert-error fails if the relative
error of the finest mesh with FORMULATION=BBAR exceeds the given bound, with
--assert-converging if the error of either formulation does not shrink with each refinement.
"""

import argparse
import os
import shlex
import subprocess
import sys
import time

import h5py
import numpy as np

LENGTH, WIDTH, HEIGHT = 10.0, 1.0, 1.0
YOUNGS_MODULUS, POISSON_RATIO = 1000.0, 0.3
LOAD = 1.0
SOLVER_AGREEMENT = 1.0e-10


def timoshenko_deflection():
    inertia = WIDTH * HEIGHT ** 3 / 12.0
    area = WIDTH * HEIGHT
    shear_modulus = YOUNGS_MODULUS / (2.0 * (1.0 + POISSON_RATIO))
    k = 10.0 * (1.0 + POISSON_RATIO) / (12.0 + 11.0 * POISSON_RATIO)
    bending = LOAD * LENGTH ** 3 / (3.0 * YOUNGS_MODULUS * inertia)
    shear = LOAD * LENGTH / (k * shear_modulus * area)
    return bending + shear, bending, shear


def write_deck(path, nx, ny, nz, formulation):
    def node_id(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)

    lines = ["*HEADING", f"Cantilever {nx}x{ny}x{nz}, tip shear, {formulation}", "*NODE, NSET=NALL"]
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                lines.append(f"{node_id(i, j, k)}, {LENGTH * i / nx!r}, {WIDTH * j / ny!r}, "
                             f"{HEIGHT * k / nz!r}")
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=BEAM")
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                n = [node_id(i, j, k), node_id(i + 1, j, k), node_id(i + 1, j + 1, k),
                     node_id(i, j + 1, k), node_id(i, j, k + 1), node_id(i + 1, j, k + 1),
                     node_id(i + 1, j + 1, k + 1), node_id(i, j + 1, k + 1)]
                lines.append(", ".join(str(v) for v in [e] + n))
    root = [node_id(0, j, k) for k in range(nz + 1) for j in range(ny + 1)]
    tip = [node_id(nx, j, k) for k in range(nz + 1) for j in range(ny + 1)]
    lines.append("*NSET, NSET=ROOT")
    lines += [", ".join(str(v) for v in root[i:i + 16]) for i in range(0, len(root), 16)]
    lines.append("*NSET, NSET=TIP")
    lines += [", ".join(str(v) for v in tip[i:i + 16]) for i in range(0, len(tip), 16)]
    lines += ["*MATERIAL, NAME=MAT", "*ELASTIC", f"{YOUNGS_MODULUS!r}, {POISSON_RATIO!r}",
              f"*SOLID SECTION, ELSET=BEAM, MATERIAL=MAT, FORMULATION={formulation}",
              "*STEP", "*STATIC", "*BOUNDARY", "ROOT, 1, 3", "*CLOAD"]
    cell_force = LOAD / (ny * nz)
    for k in range(nz + 1):
        for j in range(ny + 1):
            weight = (0.5 if j in (0, ny) else 1.0) * (0.5 if k in (0, nz) else 1.0)
            lines.append(f"{node_id(nx, j, k)}, 2, {weight * cell_force!r}")
    lines += ["*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    with open(path, "w") as handle:
        handle.write("\n".join(lines) + "\n")
    return tip


def tip_deflection(h5_path, tip):
    with h5py.File(h5_path, "r") as results:
        ids = results["mesh/node_ids"][...]
        frames = results["frames"]
        u = frames[sorted(frames.keys())[-1]]["nodal/displacement"][...]
    index = {node: i for i, node in enumerate(ids)}
    return float(np.mean([u[index[n], 1] for n in tip])), u


def run(fcs3d, deck, solver, outdir):
    os.makedirs(outdir, exist_ok=True)
    started = time.perf_counter()
    subprocess.run([fcs3d, "-q", "--solver", solver, "-o", outdir, deck], check=True)
    return time.perf_counter() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--meshes", default="10x1x1,20x2x2,40x4x4")
    parser.add_argument("--formulations", default="FULL,BBAR")
    parser.add_argument("--solvers", default="UMFPACK")
    parser.add_argument("--work", default=".")
    parser.add_argument("--markdown")
    parser.add_argument("--assert-error", type=float)
    parser.add_argument("--assert-converging", action="store_true")
    parser.add_argument("--fcs3d", default=os.environ.get("FCS3D", "fcs3d"))
    args = parser.parse_args()
    meshes = [tuple(int(v) for v in m.split("x")) for m in args.meshes.split(",")]
    formulations = args.formulations.split(",")
    solvers = args.solvers.split(",")
    theory, bending, shear = timoshenko_deflection()
    print(f"Timoshenko: delta = {theory:.6f} (bending {bending:.6f} + shear {shear:.6f})")
    rows, problems = [], []
    for nx, ny, nz in meshes:
        for formulation in formulations:
            name = f"cantilever_{nx}x{ny}x{nz}_{formulation}"
            deck = os.path.join(args.work, name + ".inp")
            tip = write_deck(deck, nx, ny, nz, formulation)
            results = {}
            for solver in solvers:
                outdir = os.path.join(args.work, solver)
                seconds = run(args.fcs3d, deck, solver, outdir)
                results[solver] = tip_deflection(os.path.join(outdir, name + ".h5"), tip) + (seconds,)
            delta, u, seconds = results[solvers[0]]
            for solver in solvers[1:]:
                other = results[solver][1]
                difference = np.abs(other - u).max() / np.abs(u).max()
                print(f"  {name}: {solver} vs {solvers[0]}: displacements differ by {difference:.2e} relative")
                if not difference <= SOLVER_AGREEMENT:
                    problems.append(f"{name}: {solver} and {solvers[0]} differ by {difference:.2e}")
            error = delta / theory - 1.0
            dofs = 3 * (nx + 1) * (ny + 1) * (nz + 1)
            rows.append((f"{nx}x{ny}x{nz}", dofs, formulation, delta, theory, error, seconds))
            print(f"{nx}x{ny}x{nz:<3d} {dofs:7d} {formulation:4s} {delta:.6f} {theory:.6f} "
                  f"{100 * error:+7.2f}%  {seconds:.2f} s")
    if args.markdown:
        write_markdown(args, rows, theory, bending, shear)
    if args.assert_converging:
        for formulation in formulations:
            errors = [abs(row[5]) for row in rows if row[2] == formulation]
            if any(later >= earlier for earlier, later in zip(errors, errors[1:])):
                problems.append(f"{formulation}: the error does not decrease with every "
                                f"refinement: {', '.join(f'{100 * e:.2f}%' for e in errors)}")
    if args.assert_error is not None:
        nx, ny, nz = meshes[-1]
        for row in rows:
            if row[0] == f"{nx}x{ny}x{nz}" and row[2] == "BBAR" and not abs(row[5]) <= args.assert_error:
                problems.append(f"finest mesh {row[0]}, BBAR: error {100 * row[5]:+.2f}% exceeds "
                                f"{100 * args.assert_error:g}%")
    for problem in problems:
        print("FAIL: " + problem)
    return 1 if problems else 0


def write_markdown(args, rows, theory, bending, shear):
    path = args.markdown
    command = (f"FCS3D=bin/fcs3d /usr/bin/python3 tests/tools/cantilever.py --meshes {args.meshes} "
               f"--formulations {args.formulations} --solvers {args.solvers} --work <scratch dir> "
               f"--markdown {shlex.quote(path)}")
    lines = [
        "# Validation: slender cantilever under a tip shear load",
        "",
        "Generated by `make validate` (tests/validate/cantilever.sh), which ran:",
        "",
        "    " + command,
        "",
        "Beam L = 10, square section 1 x 1, E = 1000, nu = 0.3; root face clamped (u = 0),",
        "tip shear force P = 1 in y as a uniform traction (consistent nodal forces); tip",
        "deflection = mean y displacement of the tip-face nodes; small strain (no NLGEOM).",
        "",
        "Theory: Timoshenko beam, delta = P L^3/(3 E I) + P L/(k G A) with the shear coefficient",
        "of a rectangular section k = 10 (1 + nu)/(12 + 11 nu) (Cowper 1966, \"The shear coefficient",
        "in Timoshenko's beam theory\", J. Appl. Mech. 33(2), 335-340):",
        f"delta = {bending:.6f} (bending) + {shear:.6f} (shear) = {theory:.6f}.",
        "",
    ]
    formulations = list(dict.fromkeys(row[2] for row in rows))
    header = "| mesh | DOF | theory |"
    rule = "|---|---:|---:|"
    for formulation in formulations:
        header += f" {formulation} deflection | {formulation} error |"
        rule += "---:|---:|"
    lines += [header, rule]
    for mesh in dict.fromkeys(row[0] for row in rows):
        cells = {row[2]: row for row in rows if row[0] == mesh}
        first = next(iter(cells.values()))
        line = f"| {mesh} | {first[1]} | {first[4]:.6f} |"
        for formulation in formulations:
            row = cells[formulation]
            line += f" {row[3]:.6f} | {100 * row[5]:+.2f}% |"
        lines.append(line)
    lines += ["", "Error = fcs3d / theory - 1. FULL is CalculiX's C3D8 (2x2x2 Gauss points); BBAR is",
              "*SOLID SECTION, FORMULATION=BBAR. `make test` runs the three coarsest meshes",
              "(tests/integration/cantilever.sh) and requires |error| <= 2% with BBAR on 40x4x4 and an",
              "error that shrinks with every refinement; `make validate` runs all of them and requires",
              "the same of the finest.",
              "",
              "Reading the table: the hexahedra converge from below (too stiff). FULL integration",
              "locks in bending (parasitic shear strains of the 8-node brick, and a volumetric part",
              "for nu > 0); B-bar removes the volumetric part only, hence its smaller error; on the single",
              "element through the thickness (10x1x1) B-bar over-softens instead: an element-mean",
              "dilatation cannot vary through the thickness, so the bending stress loses its",
              "volumetric part (sigma = 2/3 E kappa z for nu = 0.3 instead of E kappa z). The limit of",
              "refinement lies a fraction of a percent below the beam formula: the 3D body with a",
              "fully clamped root face is stiffer than a Timoshenko beam, whose root section may",
              "contract (Poisson) and warp freely, and the shear term the theory adds is itself only",
              "0.76% of the deflection at this slenderness (L/h = 10)."]
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w") as handle:
        handle.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
