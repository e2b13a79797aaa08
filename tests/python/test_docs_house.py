"""The documentation's house rules: every page is reachable from the index docs/README.md, which
README.md links."""

import pathlib
import re

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
