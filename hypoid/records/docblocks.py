"""Generated blocks: where a page mixes written text with text made from recorded data, the
generated part sits between the project's one pair of markers,

    <!-- generated:NAME (SOURCE) -->
    ...
    <!-- /generated:NAME -->

SOURCE says what writes the block from what (e.g. `hypoid records paper-findings` from
paper-findings.json). Pages that are wholly generated (the records) need no markers."""

import pathlib
import re
import subprocess

MARKER = re.compile(r"<!-- (/?)generated:([\w-]+)(?: \(([^)]*)\))? -->")


def begin(name, source):
    return f"<!-- generated:{name} ({source}) -->"


def end(name):
    return f"<!-- /generated:{name} -->"


def replace(text, name, source, body):
    """`text` with the block `name` holding `body` (its begin marker rewritten with `source`);
    None when the page has no such block or its markers are out of order."""
    head = re.search(rf"<!-- generated:{re.escape(name)}(?: \([^)]*\))? -->", text)
    j = text.find(end(name))
    if head is None or j < head.end():
        return None
    return text[:head.start()] + begin(name, source) + "\n" + body + "\n" + text[j:]


def markers(text):
    """(line, closing, name, source) of every marker in `text`, and the list of problems: a
    comment that is not a marker, a block not closed, a closing marker without its opening."""
    found, problems, open_ = [], [], None
    for m in re.finditer(r"<!--.*?-->", text, flags=re.S):
        line = text.count("\n", 0, m.start()) + 1
        k = MARKER.fullmatch(m.group(0))
        if k is None:
            problems.append(f"line {line}: {m.group(0)[:60]!r} is not a generated-block marker")
            continue
        closing, name = bool(k.group(1)), k.group(2)
        found.append((line, closing, name, k.group(3)))
        if not closing and open_ is None and k.group(3):
            open_ = name
        elif closing and open_ == name:
            open_ = None
        else:
            problems.append(f"line {line}: marker {m.group(0)!r} out of order")
    if open_ is not None:
        problems.append(f"block {open_!r} is not closed")
    return found, problems


def write_or_check(path, new, check, what, fix):
    """Writes `new` into `path`, or with `check` compares only: 1 (and a line naming `what`
    and the command `fix` that regenerates it) when the file differs, else 0."""
    path = pathlib.Path(path)
    if not check:
        if not path.exists() or path.read_text() != new:
            path.write_text(new)
        return 0
    if not path.exists() or path.read_text() != new:
        print(f"{path}: {what} is stale: run {fix}")
        return 1
    return 0


def _git(root, *args):
    try:
        return subprocess.run(["git", "-C", str(root), *args], check=True, capture_output=True,
                              text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def commit(root):
    """The checkout's commit at `root`, '+ changes' when the model's sources differ from it
    (for a record's provenance)."""
    dirty = bool(_git(root, "status", "--porcelain", "--", "fmu-src", "hypoid", "resources"))
    return _git(root, "rev-parse", "--short", "HEAD") + (" + changes" if dirty else "")
