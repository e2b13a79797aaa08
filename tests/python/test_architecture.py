"""The C layers point downwards only (fmi -> model -> mesh / tribo / solver / axle -> io), no two files
include each other, and the include graph that docs/architecture.md prints is the one of
fmu-src/ as it is."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
SRC = ROOT / "fmu-src"
DOC = ROOT / "docs" / "architecture.md"
# each layer and the layers it may include (besides itself and the generated variable table)
ALLOWED = {"fmi": {"model", "io"}, "model": {"mesh", "tribo", "solver", "axle", "io"},
           "mesh": {"io"}, "tribo": {"io"}, "solver": {"io"}, "axle": {"io"}, "io": set()}
INCLUDE = re.compile(r'^#include "([^"]+)"', re.M)


def includes():
    """{"layer/file": [included "layer/file" or special names]} of every file in fmu-src/."""
    graph = {}
    for path in sorted(SRC.glob("*/*.[ch]")):
        layer = path.parent.name
        names = []
        for inc in INCLUDE.findall(path.read_text(encoding="utf-8")):
            if inc == "hg_vars.h":
                names.append("generated")
            elif inc in ("fmi2Functions.h", "fmi3Functions.h"):
                names.append("FMI headers")
            else:
                names.append(inc if "/" in inc else f"{layer}/{inc}")
        graph[f"{layer}/{path.name}"] = names
    return graph


def layer_graph():
    layers = {}
    for name, incs in includes().items():
        layer = name.split("/")[0]
        targets = layers.setdefault(layer, set())
        targets.update(i.split("/")[0] for i in incs if i.split("/")[0] != layer)
    return layers


def test_layers_point_downwards_only():
    for layer, targets in layer_graph().items():
        upward = targets - ALLOWED[layer] - {"generated", "FMI headers"}
        assert not upward, f"fmu-src/{layer}/ includes {sorted(upward)}: layers point down only"
        if layer != "fmi":
            assert "FMI headers" not in targets, f"fmu-src/{layer}/ includes the FMI headers"


def test_no_include_cycles():
    graph = includes()

    def visit(node, stack):
        assert node not in stack, "include cycle: " + " -> ".join(stack + [node])
        for nxt in graph.get(node, []):
            if nxt in graph:
                visit(nxt, stack + [node])

    for node in graph:
        visit(node, [])


def test_every_include_names_its_layer():
    for name, incs in includes().items():
        for inc in incs:
            assert inc in ("generated", "FMI headers") or (SRC / inc).exists(), (name, inc)
        raw = INCLUDE.findall((SRC / name).read_text(encoding="utf-8"))
        bare = [i for i in raw if "/" not in i and i not in ("hg_vars.h", "fmi2Functions.h",
                                                              "fmi3Functions.h")]
        assert not bare, f"{name}: include {bare} as 'layer/file.h'"


def test_architecture_document_prints_the_include_graph():
    text = DOC.read_text(encoding="utf-8")
    printed = {}
    for layer, targets in re.findall(r"^    (\w+)\s+-> (.+)$", text, flags=re.M):
        if layer in ALLOWED:
            printed[layer] = set() if targets.startswith("(") else {
                t.strip() for t in targets.split(",")}
    actual = layer_graph()
    for layer in ALLOWED:
        assert printed.get(layer) == actual.get(layer, set()), (
            f"docs/architecture.md prints {layer} -> {sorted(printed.get(layer, []))}, "
            f"fmu-src/{layer}/ includes {sorted(actual.get(layer, []))}")


def test_architecture_document_names_every_source_file():
    text = DOC.read_text(encoding="utf-8")
    for path in sorted(SRC.glob("*/*.c")):
        rel = f"{path.parent.name}/{path.name}"
        assert rel in text or path.name in text or f"{path.parent.name}/*.c" in text, (
            f"docs/architecture.md does not say what fmu-src/{rel} owns")


def test_errors_are_written_by_hg_errorf():
    """Error buffers are filled by hg_errorf (io/errmsg.c) only, FMI functions name themselves by
    __func__, and the FMI layer has one set of state masks (fmi/instance.h)."""
    for path in sorted(SRC.glob("*/*.c")):
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(SRC).as_posix()
        if rel != "io/errmsg.c":
            assert not re.search(r"\bv?snprintf\(\s*(err|why)\s*,", text), (
                f"fmu-src/{rel}: write error messages with hg_errorf")
        assert not re.search(r'\b(hg_allowed|hg_error|hg_fail)\(\w+,\s*"fmi2', text), (
            f"fmu-src/{rel}: name the FMI function by __func__")
        if path.parent.name == "fmi":
            assert not re.search(r"#define \w+ \(ST_", text), (
                f"fmu-src/{rel}: use the state masks of fmi/instance.h")


def test_pi_is_defined_once():
    """pi and its multiples come from io/constants.h; no file spells them again."""
    spelled = re.compile(r"3\.14159|6\.28318|9\.54929|\bM_PI\b")
    for path in sorted(SRC.glob("*/*.[ch]")):
        rel = path.relative_to(SRC).as_posix()
        if rel != "io/constants.h":
            assert not spelled.search(path.read_text(encoding="utf-8")), (
                f"fmu-src/{rel}: use HG_PI, HG_TWO_PI or HG_RPM_PER_RAD_S of io/constants.h")
