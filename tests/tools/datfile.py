"""Read the result tables of a CalculiX-layout .dat file (written by fcs3d and by ccx).

A .dat file is a sequence of blocks, each a header line

     displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

followed by a blank line and one row per node or integration point: the integer keys (node,
or element and integration point) then the values. `read_blocks` returns the blocks in file
order as `Block` objects; `Block.rows` maps the key tuple to a numpy array of the values.
"""

import re

import numpy as np

# CalculiX writes the header of PE/PEEQ blocks without a blank before "for"
# ("equivalent plastic strain (elem, integ.pnt.,pe)for set ...").
HEADER = re.compile(r"^\s*(?P<title>.+?) ?for set (?P<set>\S+) and time\s+(?P<time>\S+)\s*$")
# Fortran drops the "E" of three-digit exponents ("1.234567-100").
FORTRAN_NO_E = re.compile(r"^([+-]?\d*\.?\d+)([+-]\d{3})$")


def parse_number(text):
    """A Fortran real as printed in a .dat file."""
    try:
        return float(text)
    except ValueError:
        match = FORTRAN_NO_E.match(text)
        if match is None:
            raise
        return float(match.group(1) + "e" + match.group(2))


def is_number(text):
    """Whether `text` is a number as a .dat file prints it."""
    try:
        parse_number(text)
    except ValueError:
        return False
    return True


class Block:
    """One table: title ("displacements (vx,vy,vz)"), set name, time, rows {key: values}."""

    def __init__(self, title, set_name, time):
        self.title = title
        self.set_name = set_name
        self.time = time
        self.rows = {}
        self.order = []

    @property
    def kind(self):
        """The first word of the title: displacements, forces, stresses, strains, total..."""
        return self.title.split()[0]

    def values(self):
        """All rows as one 2-D array, in file order."""
        return np.array([self.rows[key] for key in self.order])

    def label(self):
        return f"{self.title} for set {self.set_name} at time {self.time:g}"


def read_blocks(path):
    """All blocks of the .dat file at `path`, in file order."""
    blocks = []
    current = None
    with open(path, encoding="ascii", errors="replace") as handle:
        for line in handle:
            match = HEADER.match(line)
            if match:
                current = Block(match.group("title").strip(), match.group("set"),
                                parse_number(match.group("time")))
                blocks.append(current)
                continue
            fields = line.split()
            if current is None or not fields:
                continue
            keys = []
            while fields and re.fullmatch(r"[+-]?\d+", fields[0]):
                keys.append(int(fields.pop(0)))
            if len(fields) > 1 and not is_number(fields[-1]):
                # *EL PRINT in local axes (GLOBAL=NO): the row ends with the name of the
                # element's *ORIENTATION.
                fields.pop()
            try:
                values = [parse_number(f) for f in fields]
            except ValueError:
                current = None  # some other text (ccx prints notes between blocks)
                continue
            key = tuple(keys)
            if key in current.rows:
                raise ValueError(f"{path}: {current.label()}: row {key} appears twice")
            current.rows[key] = np.array(values)
            current.order.append(key)
    return blocks
