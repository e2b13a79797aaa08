"""Generated blocks of the documentation: text between a begin and an end marker that a script
writes from a recorded data file (README's level table, docs/paper-findings.md, physics.md
§10.8's km-effect table), and the check that fails when a page is stale."""

import pathlib
import subprocess
import sys


def replace(text, begin, end, body):
    """`text` with the lines between the markers `begin` and `end` replaced by `body`; None
    when the markers are missing or out of order."""
    i, j = text.find(begin), text.find(end)
    if i < 0 or j < i:
        return None
    return text[:i + len(begin)] + "\n" + body + "\n" + text[j:]


def replace_required(text, begin, end, body, where):
    """`replace`, or exit with a line naming `where` when the markers are missing."""
    new = replace(text, begin, end, body)
    if new is None:
        sys.exit(f"{where} has no generated-block markers ({begin} ... {end})")
    return new


def write_or_check(path, new, check, what, fix):
    """Writes `new` into `path`, or with `check` compares only: 1 (and a line naming `what`
    and the command `fix` that regenerates it) when the file differs, else 0."""
    path = pathlib.Path(path)
    if not check:
        path.write_text(new)
        return 0
    if path.read_text() != new:
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
