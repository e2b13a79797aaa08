"""The read-only tables the FMU ships in resources/tables/ (io/tablefile.h, tools/table_files.c):
written at build time by the FMU's own code, read at the first lookup of their content key
instead of solved. Outputs are bit-identical with and without them; a file that fails a check is
ignored (the table solved as before); a well-formed file is really used; the shipped files are
what the code computes, whether it solves the tables or reads them."""

import filecmp
import pathlib
import shutil
import struct
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TABLE_FILES = ROOT / "build" / "table_files"
HEADER = 64
NODE_TABLE = 4176  # sizeof(hg_ft_column): a node table's load column
C_OFFSET = 48  # offsetof(hg_ft_column, c): the key (5 doubles), usable

# the full level at its start values for 20 ms at 1 ms steps, every Real output after each step,
# in a process of its own (the table store is the process's): the outputs' bytes, hashed
RUN = """
import hashlib, sys
from hypoid.fmu.instance import Instance
inst = Instance(sys.argv[1]).start()
names = [v.name for v in inst.md.modelVariables if v.type == "Real" and v.causality == "output"]
print(hashlib.sha256(inst.record(0.02, 1e-3, names).tobytes()).hexdigest())
"""


def outputs(fmu_dir):
    return subprocess.run([sys.executable, "-c", RUN, str(fmu_dir)], check=True,
                          capture_output=True, text=True, cwd=ROOT).stdout.strip()


def checksum(data):
    """FNV-1a 64 over little-endian 64-bit words, the tail bytewise (io/tablefile.c)."""
    h, n = 0xCBF29CE484222325, len(data) // 8 * 8
    for (w,) in struct.iter_unpack("<Q", data[:n]):
        h = ((h ^ w) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    for b in data[n:]:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


@pytest.fixture(scope="module")
def copies(unzipped, tmp_path_factory):
    """make(name): a copy of the unzipped FMU; shipped(dir): its tables' folder."""
    root = tmp_path_factory.mktemp("tables")

    def make(name):
        target = root / name
        shutil.copytree(unzipped, target)
        return target

    return make


@pytest.fixture(scope="module")
def without(copies):
    d = copies("without")
    shutil.rmtree(d / "resources" / "tables")
    return outputs(d)


def node_tables(fmu_dir):
    files = sorted((fmu_dir / "resources" / "tables").glob("*.tbl"))
    return [f for f in files if f.stat().st_size == HEADER + NODE_TABLE]


def test_the_fmu_ships_the_start_values_tables(unzipped):
    files = list((unzipped / "resources" / "tables").glob("*.tbl"))
    assert len(files) >= 3 and len(node_tables(unzipped)) >= 1
    for f in files:
        head = f.read_bytes()[:HEADER]
        magic, version, size_h, order, double, _, _, size, _ = struct.unpack("<8sIIQd4Q", head)
        assert (magic, version, size_h, order, double) == (b"HGTABLE\0", 1, 64,
                                                           0x0102030405060708, -1.5)
        assert f.stat().st_size == HEADER + size


def test_outputs_with_and_without_the_tables_are_bit_identical(copies, without):
    assert outputs(copies("with")) == without


@pytest.mark.parametrize("damage", ["truncated", "content byte", "checksum", "version", "key"])
def test_a_file_failing_a_check_is_ignored_and_the_table_solved(copies, without, damage):
    d = copies(damage.replace(" ", "_"))
    for f in node_tables(d):
        b = bytearray(f.read_bytes())
        if damage == "truncated":
            b = b[:len(b) // 2]
        else:
            b[{"content byte": HEADER + C_OFFSET + 17, "checksum": 56, "version": 8,
               "key": 32}[damage]] ^= 0x01
        f.write_bytes(bytes(b))
    assert outputs(d) == without


def test_a_well_formed_file_is_what_the_fmu_uses(copies, without):
    """The node tables' friction coefficients scaled by 1.5 in files that pass every check: the
    outputs change, so the FMU read them (the check above cannot pass by never reading)."""
    import numpy as np

    d = copies("altered")
    for f in node_tables(d):
        b = bytearray(f.read_bytes())
        c = np.frombuffer(bytes(b[HEADER + C_OFFSET:]), dtype="<f8").copy()
        c[0::4] += np.log(1.5)  # ln mu, the first of each node's four channels
        b[HEADER + C_OFFSET:] = c.tobytes()
        b[56:64] = struct.pack("<Q", checksum(bytes(b[HEADER:])))
        f.write_bytes(bytes(b))
    assert outputs(d) != without


@pytest.mark.skipif(not TABLE_FILES.exists(), reason="build/table_files is built with the FMU")
def test_read_tables_are_the_solved_tables_bit_for_bit(unzipped, tmp_path):
    """The generator writes what its process's store holds: solved from the data files alone,
    and read from the shipped files (every table then comes from a file): the same bytes, the
    shipped ones."""
    shipped = unzipped / "resources" / "tables"
    for name, resources in [("solved", ROOT / "resources"), ("read", unzipped / "resources")]:
        out = tmp_path / name
        out.mkdir()
        subprocess.run([str(TABLE_FILES), str(resources), str(out)], check=True,
                       capture_output=True)
        names = sorted(p.name for p in shipped.iterdir())
        assert sorted(p.name for p in out.iterdir()) == names
        match, mismatch, errors = filecmp.cmpfiles(shipped, out, names, shallow=False)
        assert not mismatch and not errors
