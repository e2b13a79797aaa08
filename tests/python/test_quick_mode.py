"""The quick subset (`./test.sh --quick`, conftest.SLOW_FILES, SLOW_TESTS and QUICK_FROM_SLOW):
every file and test it names exists, so that a renamed test changes the subset loudly rather than
silently."""

import ast

from conftest import QUICK_FROM_SLOW, ROOT, SLOW_FILES, SLOW_TESTS

TESTS = ROOT / "tests" / "python"


def functions(path):
    return {node.name for node in ast.walk(ast.parse(path.read_text()))
            if isinstance(node, ast.FunctionDef) and node.name.startswith("test_")}


def test_the_quick_subset_names_existing_tests():
    missing = [f for f in SLOW_FILES if not (TESTS / f).is_file()]
    for entry in SLOW_TESTS | QUICK_FROM_SLOW:
        file, name = entry.split("::")
        if not (TESTS / file).is_file() or name not in functions(TESTS / file):
            missing.append(entry)
    assert missing == []


def test_every_long_file_keeps_a_test_in_the_subset():
    """Each file left out as a whole lends the subset one of its tests but the extremes matrix
    and the paper's studies, whose every case takes seconds (the axle, levels and bad input
    they check are in the subset through other files)."""
    lent = {entry.split("::")[0] for entry in QUICK_FROM_SLOW}
    assert SLOW_FILES - lent == {"test_extremes.py", "test_paper_findings.py",
                                 "test_installed_package.py"}
