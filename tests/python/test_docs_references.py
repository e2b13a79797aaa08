"""The repository stands alone: every reference to the physics points into docs/physics.md and
names a section that exists there, and nothing outside the tests' optional tools points to the
team's material outside the repository."""
import pathlib
import re
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PHYSICS = ROOT / "docs" / "physics.md"
THIS = pathlib.Path(__file__).resolve().relative_to(ROOT).as_posix()
BINARY = (".png", ".fmu", ".zip", ".so", ".dll", ".pdf", ".ipynb_checkpoints")

NUM = r"\d+(?:\.\d+)?"
# "§8.5", "§10.4–10.6", "§8.3–§8.5"
SECTION = re.compile(rf"§\s*({NUM})(?:\s*[–-]\s*§?\s*({NUM}))?")
# the old forms that led outside the repository or to no section: "physics 8.5",
# "physics.md 4.1", "physics section 7", "physics §7", "physics.md decision D8"
STALE = re.compile(rf"\bphysics(?:\.md)?\s+(?:section\s+)?{NUM}\b|\bphysics\s+§"
                   r"|\bphysics\.md\s+(?:decision|D\d)")
DECISION = re.compile(r"\bD(\d+) of (?:docs/)?physics\.md\s+§0|physics\.md\s+§0,?\s*\(?D(\d+)")
# the team's reference material lives beside the repository, never in it
OUTSIDE = re.compile(r"\.\./shared\b|/work/" + r"shared\b")


def tracked_text_files():
    """(path, text) of every tracked text file (the working tree when git is unavailable)."""
    try:
        out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                             check=True).stdout.split("\n")
        paths = [ROOT / p for p in out if p]
    except (OSError, subprocess.CalledProcessError):
        skip = {".git", ".venv", "build", "hypoid.egg-info", "__pycache__"}
        paths = [p for p in ROOT.rglob("*") if p.is_file() and not skip & set(p.parts)]
    for p in paths:
        if p.suffix in BINARY or not p.is_file():
            continue
        try:
            yield p.relative_to(ROOT).as_posix(), p.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue


def physics_sections():
    """Section numbers of docs/physics.md ("0", "8", "8.5", "13.14") and its decision ids."""
    text = PHYSICS.read_text(encoding="utf-8")
    sections = set(re.findall(rf"^#{{2,3}} ({NUM})\.? ", text, flags=re.M))
    decisions = set(re.findall(r"^\| D(\d+) \|", text, flags=re.M))
    return sections, decisions


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def test_physics_document_has_the_cited_structure():
    sections, decisions = physics_sections()
    # the sections the paper's equations and the code rely on
    for s in ["0", "1", "2.3", "3", "4.1", "4.5", "5.3", "6.6", "7", "8.1", "8.5", "8.8", "9.1",
              "9.2", "10.7", "11.3", "12", "13.1", "13.14", "14"]:
        assert s in sections, f"docs/physics.md has no section {s}"
    assert {str(i) for i in range(1, 12)} <= decisions
    text = PHYSICS.read_text(encoding="utf-8")
    cited = set()  # "Eq. 10", "Eqs. 20–25", "Eqs. 5, 6, 11"
    for group in re.findall(r"Eqs?\. (\d+(?:\s*(?:[–-]|,|and)\s*\d+)*)", text):
        for a, b in re.findall(r"(\d+)(?:\s*[–-]\s*(\d+))?", group):
            cited.update(range(int(a), int(b or a) + 1))
    assert set(range(1, 26)) <= cited, sorted(set(range(1, 26)) - cited)


def test_every_section_reference_resolves():
    """Each "§n" in the tree (all of them cite docs/physics.md; the paper is cited by
    equation, table and figure numbers, or as "Paouris et al. 2016, §3") names a section of
    docs/physics.md."""
    sections, _ = physics_sections()
    bad = []
    for path, text in tracked_text_files():
        if path == THIS:
            continue
        for m in SECTION.finditer(text):
            for num in filter(None, m.groups()):
                if num not in sections:
                    bad.append(f"{path}:{line_of(text, m.start())}: §{num}")
    assert not bad, "references to sections docs/physics.md does not have:\n" + "\n".join(bad)


def test_references_use_the_section_form():
    """No "physics 8.5" or "physics section 7" style references: they pointed outside."""
    bad = [f"{path}:{line_of(text, m.start())}: {m.group(0)!r}"
           for path, text in tracked_text_files() if path != THIS
           for m in STALE.finditer(text)]
    assert not bad, "write these as docs/physics.md §n:\n" + "\n".join(bad)


def test_decision_references_resolve():
    _, decisions = physics_sections()
    bad, seen = [], 0
    for path, text in tracked_text_files():
        if path == THIS:
            continue
        for m in DECISION.finditer(text):
            seen += 1
            d = m.group(1) or m.group(2)
            if d not in decisions:
                bad.append(f"{path}:{line_of(text, m.start())}: D{d}")
    assert seen > 5 and not bad, bad


def test_decision_ids_say_where_they_are_defined():
    """A decision id (D1-D11) is always cited next to docs/physics.md (same line or the two
    lines around it), so a reader finds the table of §0."""
    bad = []
    for path, text in tracked_text_files():
        if path in (THIS, "docs/physics.md"):
            continue
        lines = text.split("\n")
        for i, line in enumerate(lines):
            if re.search(r"\bD(?:1[01]|[1-9])\b", line) and \
                    "physics.md" not in "\n".join(lines[max(0, i - 2):i + 3]):
                bad.append(f"{path}:{i + 1}: {line.strip()[:80]}")
    assert not bad, "decision ids without docs/physics.md nearby:\n" + "\n".join(bad)


def optional_test_tool(path, text):
    """Test tooling (tests/, scripts/) that only looks for the team's tools/ and skips with a
    message when they are absent (e.g. scripts/fmucheck.sh)."""
    return path.startswith(("tests/", "scripts/")) and "tools/" in text and \
        re.search(r"skip", text, flags=re.I) is not None


def test_nothing_points_outside_the_repository():
    """Only the tests' optional tools may come from the team's shared folder (and must skip
    when it is absent)."""
    bad = []
    for path, text in tracked_text_files():
        if path == THIS or optional_test_tool(path, text):
            continue
        bad += [f"{path}:{line_of(text, m.start())}: {m.group(0)}" for m in OUTSIDE.finditer(text)]
    assert not bad, "references outside the repository:\n" + "\n".join(bad)


def test_physics_document_names_files_that_exist():
    text = PHYSICS.read_text(encoding="utf-8")
    named = set(re.findall(r"`((?:fmu-src|hypoid|tests|tools|docs|resources|bench|scripts|"
                           r"modelDescription)/[^`\s]+)`", text))
    assert len(named) > 10
    missing = sorted(p for p in named if not (ROOT / p).exists())
    assert not missing, missing


def test_named_documents_exist():
    """Every docs/NAME.md the tree names (code comments, CLI help, variable descriptions, docs)
    and every relative [link](NAME.md) between the docs is there."""
    bad = []
    for path, text in tracked_text_files():
        if path == THIS:
            continue
        for m in re.finditer(r"\bdocs/([\w.-]+\.md)\b", text):
            if not (ROOT / "docs" / m.group(1)).is_file():
                bad.append(f"{path}:{line_of(text, m.start())}: docs/{m.group(1)}")
        if path.startswith("docs/"):
            for m in re.finditer(r"\]\(([\w./-]+\.md)(?:#[^)]*)?\)", text):
                if not ((ROOT / path).parent / m.group(1)).is_file():
                    bad.append(f"{path}:{line_of(text, m.start())}: ({m.group(1)})")
    assert not bad, "documents that do not exist:\n" + "\n".join(bad)


def test_readme_points_to_the_physics_document():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "docs/physics.md" in readme


@pytest.mark.parametrize("doc", ["README.md", "tests/regression/README.md"] + sorted(
    p.relative_to(ROOT).as_posix() for p in (ROOT / "docs").glob("*.md")))
def test_docs_write_micrometres(doc):
    """Prose says µm; "um" survives only as the FMI displayUnit identifier in code spans."""
    text = (ROOT / doc).read_text(encoding="utf-8")
    prose = re.sub(r"`[^`]*`", "", text)
    hits = [f"{doc}:{line_of(prose, m.start())}" for m in
            re.finditer(r"(?<![\w/])\d*\s?um\b", prose)]
    assert not hits, hits
