"""The documentation's house rules: every page is reachable from the index docs/README.md, which
README.md links; measured figures live in the records (docs/records/), not in the pages that
explain; one marker convention for generated text; the project's history (work sessions, issue
numbers, commit ids) only in docs/decisions.md and CHANGELOG.md."""

import pathlib
import re
import subprocess

from hypoid.records import docblocks

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
LINK = re.compile(r"\]\(([^)#\s]+\.md)(?:#[^)]*)?\)")


def links(page):
    """The Markdown pages `page` links to, as resolved paths (external links left out)."""
    return {(page.parent / m.group(1)).resolve() for m in LINK.finditer(page.read_text())
            if "://" not in m.group(1)}


def reachable(start):
    seen, todo = set(), [start.resolve()]
    while todo:
        page = todo.pop()
        if page in seen or not page.is_file():
            continue
        seen.add(page)
        todo += [p for p in links(page) if p.is_relative_to(DOCS)]
    return seen


def test_readme_links_the_index():
    assert (DOCS / "README.md").resolve() in links(ROOT / "README.md")


def test_every_page_is_reachable_from_the_index():
    found = reachable(DOCS / "README.md")
    missing = sorted(p.relative_to(ROOT).as_posix() for p in DOCS.rglob("*.md")
                     if p.resolve() not in found)
    assert not missing, f"pages no link from docs/README.md leads to: {missing}"


def test_index_links_resolve():
    bad = sorted(p.as_posix() for p in links(DOCS / "README.md") if not p.is_file())
    assert not bad, bad


# ---------------------------------------------------------------- measured figures by hand
# A measured figure: what a run of the model on some machine gives and the next run changes
# (real-time factors, timings, step counts, errors in %-points, energies of a drive cycle).
# Reference pages link to the record that holds it instead of copying it.
FIGURE = re.compile("|".join([
    r"\d[\d.,]*\s?[×x](?=\s*(?:real|faster|slower|cheaper|dearer|more|less)\b|\s*$|\s*[|,.;:)(])",
    r"\d[\d.]*\s?(?:µs|ms|s|min)\s+(?:of\s+)?(?:CPU|wall)\b",
    r"\d[\d.]*\s?(?:µs|ms|s)\s+(?:CPU\s+)?(?:per|a|an)\s+(?:mesh|point|step|run|window|task|"
    r"fmi2DoStep|cycle|simulated)",
    r"\d[\d.]*\s+solver\s+steps|\d+\.\d+\s+steps\b|\d[\d.]*\s+right-hand\s+sides",
    r"\d[\d.·⁻⁰¹²³⁴⁵⁶⁷⁸⁹e-]*\s?%-points?",
    r"\d\s?kJ\b(?!/)",
    r"real[- ]time\s+factors?\s+(?:of\s+)?\d",
]), re.M)
GENERATED = re.compile(r"<!-- generated:([\w-]+)[^>]*-->.*?<!-- /generated:\1 -->", re.S)


def reference_pages():
    """The pages that explain (everything but the records, the decisions and the changelog)."""
    pages = [ROOT / "README.md", ROOT / "CONTRIBUTING.md"] + sorted(DOCS.glob("*.md"))
    return [p for p in pages if p.name != "decisions.md" and p.is_file()]


def figures(text):
    """(line, match) of every measured figure outside the generated blocks of `text`."""
    prose = GENERATED.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    return [(prose.count("\n", 0, m.start()) + 1, m.group(0)) for m in FIGURE.finditer(prose)]


# Facts that the FIGURE pattern takes for measured figures: published values and settings
# (page, the matched text, why it stays).
ALLOWED = {
}


def test_no_measured_figure_outside_the_records():
    found = [f"{page.relative_to(ROOT)}:{line}: {text!r}" for page in reference_pages()
             for line, text in figures(page.read_text())
             if (page.relative_to(ROOT).as_posix(), text) not in ALLOWED]
    assert not found, ("measured figures in pages that explain (link the record instead):\n"
                       + "\n".join(found))


# ---------------------------------------------------------------- one marker convention

def tracked(*suffixes):
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout.split()
    return [ROOT / f for f in out if f.endswith(suffixes) and (ROOT / f).is_file()]


def test_one_marker_convention():
    """Every HTML comment of the Markdown pages is a generated-block marker of the one
    convention, in pairs; no code writes another kind."""
    bad = []
    for page in tracked(".md"):
        bad += [f"{page.relative_to(ROOT)}: {p}" for p in docblocks.markers(page.read_text())[1]]
    other = re.compile(r"<!-- [\w-]+:(?:begin|end)\b|<!-- /?(?!generated:)[\w-]+:[\w-]+")
    for code in tracked(".py", ".sh"):
        if code.name != pathlib.Path(__file__).name:
            bad += [f"{code.relative_to(ROOT)}: {m.group(0)}"
                    for m in other.finditer(code.read_text())]
    assert not bad, "\n".join(bad)


# ---------------------------------------------------------------- the diary

# "session 4", "issue 10", "round 3", and a commit id: 7 to 12 hex digits with a letter and a
# digit, standing alone (not inside a number, a hash of data or an identifier).
DIARY = re.compile(r"\b(?:[Ss]essions?|[Ii]ssues?|[Rr]ounds?) #?\d+\b"
                   r"|(?<![\w.+-])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*\d)[0-9a-f]{7,12}(?![\w.+-])")
HISTORY = {"docs/decisions.md", "CHANGELOG.md"}  # where the history lives
DIARY_SOURCES = (".md", ".py", ".c", ".h", ".sh", ".toml", ".txt", "CMakeLists.txt")


def diary(path, text):
    """Diary entries of a file; the records may name the commit they were measured on, and the
    data files (CSV, JSON) are not prose."""
    rel = path.relative_to(ROOT).as_posix()
    hits = []
    for m in DIARY.finditer(text):
        commit_id = not m.group(0)[0].isalpha() or re.fullmatch(r"[0-9a-f]+", m.group(0))
        if rel.startswith("docs/records/") and commit_id:
            continue
        hits.append((text.count("\n", 0, m.start()) + 1, m.group(0)))
    return hits


def test_no_diary_outside_the_history():
    bad = [f"{p.relative_to(ROOT)}:{line}: {text}" for p in tracked(*DIARY_SOURCES)
           if p.relative_to(ROOT).as_posix() not in HISTORY and p.name != pathlib.Path(__file__).name
           for line, text in diary(p, p.read_text())]
    assert not bad, ("history (sessions, issue numbers, commit ids) belongs in docs/decisions.md "
                     "or CHANGELOG.md:\n" + "\n".join(bad))


if __name__ == "__main__":  # count them: python tests/python/test_docs_house.py [ROOT]
    import sys
    if len(sys.argv) > 1:
        ROOT, DOCS = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[1]) / "docs"
    total = 0
    for page in reference_pages():
        found = figures(page.read_text())
        total += len(found)
        print(f"{len(found):4d} {page.relative_to(ROOT)}")
    print(f"{total:4d} measured figures written by hand outside records")
