#!/usr/bin/env python3
"""Generate modelDescription.xml, the C variable table and the README variable table from
variables.toml, the single source of the FMU's variables.

    generate.py --toml variables.toml --xml OUT.xml --c-dir DIR     (called by CMake)
    generate.py --toml variables.toml --xml-intenum OUT.xml          (the integer-coded variant)
    generate.py --toml variables.toml --xml3 OUT.xml                 (the FMI 3.0 one)
    generate.py --toml variables.toml --readme README.md [--check]  (README table)
    generate.py --toml variables.toml --python hypoid/fmu/variables.py [--check]  (Python table)

Standard library only (Python >= 3.11 for tomllib), so the FMU builds without the project's venv.
"""

import argparse
import copy
import hashlib
import re
import sys
import tomllib
import uuid
from xml.sax.saxutils import quoteattr

GROUPS = {  # TOML group -> (causality, variability, initial)
    "input": ("input", "continuous", None),
    "output": ("output", "continuous", None),
    "parameter": ("parameter", "fixed", "exact"),
    "calculated": ("calculatedParameter", "fixed", "calculated"),
    "state": ("local", "continuous", "calculated"),       # a continuous state of its own
    "derivative": ("local", "continuous", "calculated"),  # der(state)
}
COMPUTED = ("output", "calculated", "state", "derivative")  # the groups without a start value
STATES_SET = "states"  # the output set of the local states' values: a copy of the state
DERIVATIVES_SET = "derivatives"  # the output set of the derivatives: the right-hand side
BASE_TYPES = ("Real", "Integer", "Boolean", "String")
C_TYPES = {"Real": "double", "Integer": "int", "Boolean": "int", "String": "char *"}
# The communication step hosts are proposed (DefaultExperiment): the half-shaft coupling holds
# with held inputs from 0.1 to 20 ms; at 1 ms its error stays within 1e-3 in every scene of the
# coupling matrix (docs/integration.md).
DEFAULT_STEP = 1e-3

README_BEGIN = "<!-- generated:variables (modelDescription/generate.py from variables.toml) -->"
README_END = "<!-- /generated:variables -->"
README_UNIT_TEXT = {"um": "µm", "degC": "°C"}  # display-unit identifiers as the README prints them


class Spec:
    """variables.toml, expanded: one entry per scalar variable, value reference = list index."""

    def __init__(self, path):
        with open(path, "rb") as f:
            raw = f.read()
        self.digest = hashlib.sha256(raw).hexdigest()
        data = tomllib.loads(raw.decode())
        self.model = data["model"]
        self.enums = data.get("enumerations", {})
        self.units = data.get("units", {})
        self.output_sets = list(data.get("output_sets", {"main": ""}))
        self.start_dependencies = data.get("start_dependencies", {})
        self.fields = []  # (c_type, c_field, array length or 0)
        self.vars = []
        for group in ("input", "output", "parameter", "calculated"):
            for item in data.get(group, []):
                self._add(group, item)
        self.states = []  # (y name, index of the state's variable, index of its derivative)
        self.reports = {}  # index of a local state's variable: index of the output it reports
        self._add_states(data.get("state", []))

    def _add_states(self, items):
        """The continuous states: an output of the same name or a local variable of their own,
        then the derivative of each, value references after every other variable."""
        if not items:
            return
        self.output_sets += [STATES_SET, DERIVATIVES_SET]
        index = {v["name"]: i for i, v in enumerate(self.vars)}
        for item in items:
            if item.get("output"):
                if item["name"] not in index or self.vars[index[item["name"]]]["group"] != "output":
                    sys.exit(f"variables.toml: state {item['name']}: no output of that name")
                self.states.append([item["y"], index[item["name"]], None])
                continue
            local = {k: v for k, v in item.items() if k in ("name", "unit", "description")}
            self._add("state", dict(local, set=STATES_SET))
            self.states.append([item["y"], len(self.vars) - 1, None])
            if "reports" in item:
                if item["reports"] not in index or \
                        self.vars[index[item["reports"]]]["group"] != "output":
                    sys.exit(f"variables.toml: state {item['name']}: reports no output")
                self.reports[len(self.vars) - 1] = index[item["reports"]]
        for state, item in zip(self.states, items):
            v = self.vars[state[1]]
            field = "der_" + v["field"]
            self.fields.append(("double", field, 0))
            self.vars.append(dict(name=f"der({v['name']})", group="derivative", typ="Real",
                                  base="Real", start=None, field=field, set=DERIVATIVES_SET,
                                  unit=item["der_unit"], derivative=state[1] + 1,
                                  description=f"time derivative of {v['name']}"))
            state[2] = len(self.vars) - 1

    def _add(self, group, item):
        typ = item.get("type", "Real")
        if typ not in BASE_TYPES and typ not in self.enums:
            sys.exit(f"variables.toml: {item['name']}: unknown type {typ}")
        base = typ if typ in BASE_TYPES else "Integer"
        n = item.get("array", 0)
        field = c_identifier(item["name"].replace("[k]", ""))
        self.fields.append((C_TYPES[base], field, n))
        if item.get("set", "main") not in self.output_sets or \
                ("set" in item and group not in ("output", "state")):
            sys.exit(f"variables.toml: {item['name']}: set must name an [output_sets] entry "
                     "and is for outputs only")
        start = item.get("start")
        if typ in self.enums and isinstance(start, str):
            start = [e[0] for e in self.enums[typ]].index(start) + 1
        for k in range(1, n + 1) if n else [0]:
            name = item["name"].replace("[k]", f"[{k}]") if n else item["name"]
            self.vars.append(dict(item, name=name, group=group, typ=typ, base=base, start=start,
                                  field=f"{field}[{k - 1}]" if n else field))

    def event_indicators(self):
        """numberOfEventIndicators: the model's, when it has states (Model Exchange)."""
        return self.model.get("numberOfEventIndicators", 0) if self.states else 0

    def guid(self):
        return "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, "hypoidgearpair:" + self.digest)) + "}"


def c_identifier(name):
    return re.sub(r"[^A-Za-z0-9_]", "_", name)


def fmt_num(x):
    return repr(float(x)) if isinstance(x, float) else str(x)


# ---------------------------------------------------------------- modelDescription.xml


def xml_units(spec):
    out = ["  <UnitDefinitions>"]
    for name, (base, displays) in spec.units.items():
        out.append(f"    <Unit name={quoteattr(name)}>")
        exps = " ".join(f'{k}="{v}"' for k, v in base.items())
        out.append(f"      <BaseUnit {exps}/>")
        for dname, factor, offset in displays:
            out.append(f'      <DisplayUnit name={quoteattr(dname)} factor="{fmt_num(factor)}" '
                       f'offset="{fmt_num(offset)}"/>')
        out.append("    </Unit>")
    out.append("  </UnitDefinitions>")
    return out


def xml_types(spec):
    if not spec.enums:
        return []  # the schema wants at least one SimpleType in TypeDefinitions
    out = ["  <TypeDefinitions>"]
    for name, items in spec.enums.items():
        out.append(f"    <SimpleType name={quoteattr(name)}>")
        out.append("      <Enumeration>")
        for i, (iname, idesc) in enumerate(items, 1):
            out.append(f"        <Item name={quoteattr(iname)} value=\"{i}\" "
                       f"description={quoteattr(idesc)}/>")
        out.append("      </Enumeration>")
        out.append("    </SimpleType>")
    out.append("  </TypeDefinitions>")
    return out


def xml_value_attrs(v):
    """The unit, displayUnit, min and max attributes of a variable (both FMI versions)."""
    out = ""
    if v["base"] == "Real":
        if v.get("unit"):
            out += f' unit={quoteattr(v["unit"])}'
        if v.get("displayUnit"):
            out += f' displayUnit={quoteattr(v["displayUnit"])}'
    for key in ("min", "max"):
        if key in v:
            out += f' {key}="{fmt_num(v[key])}"'
    return out


def xml_variable(vr, v, enums):
    causality, variability, initial = GROUPS[v["group"]]
    if v["group"] == "output" and v["base"] != "Real":
        variability = "discrete"
    attrs = f'name={quoteattr(v["name"])} valueReference="{vr}" causality="{causality}" ' \
            f'variability="{variability}"'
    if initial:
        attrs += f' initial="{initial}"'
    attrs += f' description={quoteattr(v["description"])}'
    tattrs = ""
    if v["typ"] in enums:
        tattrs += f' declaredType={quoteattr(v["typ"])}'
    tattrs += xml_value_attrs(v)
    if "derivative" in v:  # the state's index (FMI 2.0)
        tattrs += f' derivative="{v["derivative"]}"'
    if v["group"] in ("input", "parameter"):
        start = v["start"]
        if v["base"] == "Boolean":
            start = "true" if start else "false"
        tattrs += f' start={quoteattr(str(start) if v["base"] == "String" else fmt_num(start))}'
    elem = "Enumeration" if v["typ"] in enums else v["base"]
    return [f"    <ScalarVariable {attrs}>", f"      <{elem}{tattrs}/>", "    </ScalarVariable>"]



def start_dependencies(spec):
    """{index of an initial unknown: sorted indices of the knowns it depends on}: the inputs that
    [start_dependencies] lists for it ("pair[k].X" for every pair) and every parameter."""
    index = {v["name"]: i + 1 for i, v in enumerate(spec.vars)}
    base = {v["name"]: v["name"].split("[")[0] + "[k]" + v["name"].split("]", 1)[1]
            if v.get("array") else v["name"] for v in spec.vars}
    params = [i + 1 for i, v in enumerate(spec.vars) if v["group"] == "parameter"]
    deps = {}
    for i, v in enumerate(spec.vars):
        if v["group"] not in ("output", "calculated"):
            continue
        inputs = []
        for name, unknowns in spec.start_dependencies.items():
            if name not in index or spec.vars[index[name] - 1]["group"] != "input":
                sys.exit(f"variables.toml: [start_dependencies] {name} is not an input")
            for u in unknowns:
                if u not in base.values():
                    sys.exit(f"variables.toml: [start_dependencies] {name}: unknown {u}")
            if base[v["name"]] in unknowns:
                inputs.append(index[name])
        deps[i + 1] = sorted(inputs + params)
    return deps


def output_dependencies(spec, deps, i):
    """The knowns output i depends on. Co-simulation: none (outputs are computed at the end of a
    step, with the inputs held over it: setting an input moves none before the next step). With
    Model Exchange in the same description the knowns are the inputs and the continuous states
    at any instant, and one ModelStructure serves both interfaces: the inputs [start_dependencies]
    gives the output (a superset of what moves it in continuous time) and every state."""
    if not spec.states:
        return []
    inputs = [k for k in deps[i] if spec.vars[k - 1]["group"] == "input"]
    return sorted(set(inputs) | {s + 1 for _, s, _ in spec.states})


def model_structure(spec):
    """ModelStructure: the outputs' dependencies (output_dependencies), the derivatives (Model
    Exchange: no dependencies attribute, every known), the initial unknowns with the inputs
    [start_dependencies] gives them and every parameter (the states and the derivatives: every
    known)."""
    outputs = [i + 1 for i, v in enumerate(spec.vars) if v["group"] == "output"]
    deps = start_dependencies(spec)
    lines = ["  <ModelStructure>", "    <Outputs>"]
    lines += [f'      <Unknown index="{i}" '
              f'dependencies="{" ".join(map(str, output_dependencies(spec, deps, i)))}"/>'
              for i in outputs]
    lines += ["    </Outputs>"] + xml_derivatives(spec) + ["    <InitialUnknowns>"]
    unknowns = dict(deps)
    unknowns.update({i + 1: None for i, v in enumerate(spec.vars)
                     if v["group"] in ("state", "derivative")})
    lines += [f'      <Unknown index="{i}" dependencies="{" ".join(map(str, d))}"/>'
              if d is not None else f'      <Unknown index="{i}"/>'
              for i, d in sorted(unknowns.items())]
    lines += ["    </InitialUnknowns>", "  </ModelStructure>"]
    return lines


def xml_model_exchange(spec):
    """The ModelExchange element (FMI 2.0), when the model has continuous states."""
    if not spec.states:
        return []
    return [f'  <ModelExchange modelIdentifier={quoteattr(spec.model["modelIdentifier"])} '
            'needsExecutionTool="false" completedIntegratorStepNotNeeded="false" '
            'canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="true" '
            'canGetAndSetFMUstate="true" canSerializeFMUstate="true" '
            'providesDirectionalDerivative="false"/>']


def xml_derivatives(spec):
    """ModelStructure/Derivatives: the derivatives in the order of the state vector."""
    if not spec.states:
        return []
    return (["    <Derivatives>"] +
            [f'      <Unknown index="{der + 1}"/>' for _, _, der in spec.states] +
            ["    </Derivatives>"])


def write_xml(spec, path):
    m = spec.model
    cats = "\n".join(f"    <Category name={quoteattr(n)} description={quoteattr(d)}/>"
                     for n, d in m["logCategories"])
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<fmiModelDescription fmiVersion="2.0" modelName={quoteattr(m["modelName"])} '
        f'guid="{spec.guid()}" description={quoteattr(m["description"])} '
        f'version={quoteattr(m["version"])} author={quoteattr(m["author"])} '
        'generationTool="modelDescription/generate.py" variableNamingConvention="structured" '
        f'numberOfEventIndicators="{spec.event_indicators()}">',
    ] + xml_model_exchange(spec) + [
        f'  <CoSimulation modelIdentifier={quoteattr(m["modelIdentifier"])} '
        'needsExecutionTool="false" canHandleVariableCommunicationStepSize="true" '
        'canInterpolateInputs="true" maxOutputDerivativeOrder="0" canRunAsynchronuously="false" '
        'canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="true" '
        'canGetAndSetFMUstate="true" canSerializeFMUstate="true" '
        'providesDirectionalDerivative="false"/>',
    ]
    lines += xml_units(spec) + xml_types(spec)
    lines += ["  <LogCategories>", cats, "  </LogCategories>",
              '  <DefaultExperiment startTime="0.0" stopTime="0.3" tolerance="1e-06" '
              f'stepSize="{fmt_num(DEFAULT_STEP)}"/>',
              "  <ModelVariables>"]
    for vr, v in enumerate(spec.vars):
        lines.append(f"    <!-- index {vr + 1} -->")
        lines += xml_variable(vr, v, spec.enums)
    lines.append("  </ModelVariables>")
    lines += model_structure(spec)
    lines.append("</fmiModelDescription>")
    write_if_changed(path, "\n".join(lines) + "\n")


# ---------------------------------------------------------------- integer-coded enumerations
# A second modelDescription for hosts that ignore FMI 2.0 Enumeration variables (libcosim 0.11):
# every enumeration is declared as an Integer with min = 1, max = number of items and the coding
# in its description. Same binary, value references and start values; its own GUID, because FMI
# ties a GUID to one modelDescription. The binary accepts both (HG_GUID_INTENUM).


def intenum_guid(spec):
    return "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, "hypoidgearpair-intenum:" + spec.digest)) + "}"


def intenum_spec(spec):
    """A copy of spec with every enumeration variable turned into a coded Integer."""
    out = copy.deepcopy(spec)
    for v in out.vars:
        items = spec.enums.get(v["typ"])
        if items is None:
            continue
        coding = ", ".join(f"{i} = {name}" for i, (name, _) in enumerate(items, 1))
        v.update(typ="Integer", min=1, max=len(items),
                 description=f"{v['description']} (Integer-coded: {coding})")
    out.enums = {}
    out.model = dict(spec.model, description=spec.model["description"]
                     + " (enumerations as Integer-coded variables, for hosts without Enumeration"
                     " support)")
    out.guid = lambda: intenum_guid(spec)
    return out


def write_xml_intenum(spec, path):
    write_xml(intenum_spec(spec), path)


# ---------------------------------------------------------------- FMI 3.0 modelDescription.xml
# The same variables with FMI 3.0's types (Float64, Int32, Enumeration, Boolean, String), each
# per-pair output as one array variable ("pair.W", Dimension 3), the independent variable time
# and, with Model Exchange, the event indicators as variables (FMI 3.0 lists them by value
# reference). Value references: a scalar keeps its FMI 2.0 one, an array takes its first
# element's, time the one after the last (HG_FMI3_VR_TIME), the event indicators the ones after
# it (HG_FMI3_VR_INDICATOR), so the C table serves both versions.

FMI3_TYPES = {"Real": "Float64", "Integer": "Int32", "Boolean": "Boolean", "String": "String"}


def fmi3_guid(spec):
    return "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, "hypoidgearpair-fmi3:" + spec.digest)) + "}"


def fmi3_variables(spec):
    """[(vr, variable, count)]: each FMI 3.0 variable, count its elements (1 for a scalar)."""
    out = []
    for vr, v in enumerate(spec.vars):
        if not v.get("array"):
            out.append((vr, v, 1))
        elif "[1]" in v["name"]:  # an array's first element names the array
            out.append((vr, dict(v, name=v["name"].replace("[1]", "")), v["array"]))
    return out


def xml3_types(spec):
    out = ["  <TypeDefinitions>"]
    for name, items in spec.enums.items():
        out.append(f"    <EnumerationType name={quoteattr(name)}>")
        for i, (iname, idesc) in enumerate(items, 1):
            out.append(f"      <Item name={quoteattr(iname)} value=\"{i}\" "
                       f"description={quoteattr(idesc)}/>")
        out.append("    </EnumerationType>")
    out.append("  </TypeDefinitions>")
    return out if spec.enums else []


def xml3_variable(vr, v, count, enums):
    causality, variability, initial = GROUPS[v["group"]]
    if v["group"] == "output" and v["base"] != "Real":
        variability = "discrete"
    elem = "Enumeration" if v["typ"] in enums else FMI3_TYPES[v["base"]]
    attrs = f'name={quoteattr(v["name"])} valueReference="{vr}" causality="{causality}" ' \
            f'variability="{variability}"'
    if initial:
        attrs += f' initial="{initial}"'
    attrs += f' description={quoteattr(v["description"])}'
    if v["typ"] in enums:
        attrs += f' declaredType={quoteattr(v["typ"])}'
    attrs += xml_value_attrs(v)
    children = [f'      <Dimension start="{count}"/>'] if count > 1 else []
    if "derivative" in v:  # der(x): the state's value reference (FMI 3.0)
        attrs += f' derivative="{v["derivative"] - 1}"'
    if v["group"] in ("input", "parameter"):
        start = v["start"]
        if v["base"] == "String":
            children.append(f"      <Start value={quoteattr(str(start))}/>")
        else:
            if v["base"] == "Boolean":
                start = "true" if start else "false"
            attrs += f' start="{fmt_num(start)}"'
    if not children:
        return [f"    <{elem} {attrs}/>"]
    return [f"    <{elem} {attrs}>"] + children + [f"    </{elem}>"]


def xml3_model_exchange(spec):
    """The ModelExchange element (FMI 3.0), when the model has continuous states."""
    if not spec.states:
        return []
    return [f'  <ModelExchange modelIdentifier={quoteattr(spec.model["modelIdentifier"])} '
            'needsExecutionTool="false" needsCompletedIntegratorStep="true" '
            'canBeInstantiatedOnlyOncePerProcess="false" canGetAndSetFMUState="true" '
            'canSerializeFMUState="true" providesDirectionalDerivative="false" '
            'providesAdjointDerivatives="false" providesEvaluateDiscreteStates="false"/>']


def xml3_indicators(spec):
    """The event indicators as local variables after time: [(vr, variable line)]."""
    return [(len(spec.vars) + k, f'    <Float64 name="event_indicator[{k}]" '
             f'valueReference="{len(spec.vars) + k}" causality="local" variability="continuous" '
             f'description="event indicator {k} of the model (Model Exchange): an event is due '
             'where it changes sign"/>') for k in range(1, spec.event_indicators() + 1)]


def write_xml3(spec, path):
    m = spec.model
    cats = "\n".join(f"    <Category name={quoteattr(n)} description={quoteattr(d)}/>"
                     for n, d in m["logCategories"])
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<fmiModelDescription fmiVersion="3.0" modelName={quoteattr(m["modelName"])} '
        f'instantiationToken="{fmi3_guid(spec)}" description={quoteattr(m["description"])} '
        f'version={quoteattr(m["version"])} author={quoteattr(m["author"])} '
        'generationTool="modelDescription/generate.py" variableNamingConvention="structured">',
    ] + xml3_model_exchange(spec) + [
        f'  <CoSimulation modelIdentifier={quoteattr(m["modelIdentifier"])} '
        'needsExecutionTool="false" canBeInstantiatedOnlyOncePerProcess="false" '
        'canGetAndSetFMUState="true" canSerializeFMUState="true" '
        'providesDirectionalDerivative="false" providesAdjointDerivatives="false" '
        'canHandleVariableCommunicationStepSize="true" '
        f'maxOutputDerivativeOrder="{1 if spec.states else 0}" '
        'providesIntermediateUpdate="false" mightReturnEarlyFromDoStep="false" '
        'canReturnEarlyAfterIntermediateUpdate="false" hasEventMode="false" '
        'providesEvaluateDiscreteStates="false"/>',
    ]
    lines += xml_units(spec) + xml3_types(spec)
    lines += ["  <LogCategories>", cats, "  </LogCategories>",
              '  <DefaultExperiment startTime="0.0" stopTime="0.3" tolerance="1e-06" '
              f'stepSize="{fmt_num(DEFAULT_STEP)}"/>',
              "  <ModelVariables>",
              f'    <Float64 name="time" valueReference="{len(spec.vars)}" causality="independent" '
              'variability="continuous" unit="s" description="simulation time"/>']
    lines += [line for _, line in xml3_indicators(spec)]
    variables = fmi3_variables(spec)
    for vr, v, count in variables:
        lines += xml3_variable(vr, v, count, spec.enums)
    lines.append("  </ModelVariables>")
    lines.append("  <ModelStructure>")
    outputs = [vr for vr, v, _ in variables if v["group"] == "output"]
    unknowns = [vr for vr, v, _ in variables if v["group"] in ("calculated", "state", "derivative")]
    deps = start_dependencies(spec)  # by FMI 2.0 index (value reference + 1): the same data

    def vrs(indices):
        return " ".join(str(k - 1) for k in indices)

    lines += [f'    <Output valueReference="{vr}" '
              f'dependencies="{vrs(output_dependencies(spec, deps, vr + 1))}"/>' for vr in outputs]
    lines += [f'    <ContinuousStateDerivative valueReference="{der}"/>' for _, _, der in spec.states]
    lines += [f'    <InitialUnknown valueReference="{vr}" dependencies="{vrs(deps[vr + 1])}"/>'
              if vr + 1 in deps else f'    <InitialUnknown valueReference="{vr}"/>'
              for vr in sorted(outputs + unknowns)]
    lines += [f'    <EventIndicator valueReference="{vr}"/>' for vr, _ in xml3_indicators(spec)]
    lines.append("  </ModelStructure>")
    lines.append("</fmiModelDescription>")
    write_if_changed(path, "\n".join(lines) + "\n")


def c_fmi3_table(spec):
    """hg_fmi3_vars: for each FMI 2.0 value reference its FMI 3.0 element count (0: an array
    element after the first) and whether it is an Enumeration (fmi3Get/SetInt64)."""
    count = {vr: n for vr, _, n in fmi3_variables(spec)}
    c = ["const hg_fmi3_var hg_fmi3_vars[HG_NUM_VARS] = {"]
    c += [f"    {{{count.get(vr, 0)}, {int(v['typ'] in spec.enums)}}}, /* {v['name']} */"
          for vr, v in enumerate(spec.vars)]
    return c + ["};", ""]


# ---------------------------------------------------------------- C table


def c_inputs_header(inputs):
    """The continuous inputs (all Real), their indices, value references and accessors."""
    h = ["/* The continuous inputs, k = 0 .. HG_NUM_INPUTS - 1 in table order. */",
         f"#define HG_NUM_INPUTS {len(inputs)}",
         "enum { " + ", ".join(f"HG_IN_{v['field'].upper()} = {k}" for k, (_, v) in
                               enumerate(inputs)) + " };",
         "extern const unsigned hg_input_vr[HG_NUM_INPUTS]; /* value reference of input k */", "",
         "/* The inputs at one instant, by name; hg_input(u, k) reaches them by index. */",
         "typedef struct {"]
    h += [f"    double {v['field']};" for _, v in inputs]
    h += ["} hg_inputs;", "",
          "double *hg_input(hg_inputs *u, int k);",
          "double hg_input_value(const hg_inputs *u, int k);",
          "/* u = u0 + du dt input by input (field by field: the right-hand side's inputs). */",
          "void hg_inputs_at(const hg_inputs *u0, const hg_inputs *du, double dt, hg_inputs *u);",
          "/* The inputs held in v. */",
          "void hg_vars_inputs(const hg_vars *v, hg_inputs *u);", ""]
    return h


def c_inputs_source(inputs):
    c = ["const unsigned hg_input_vr[HG_NUM_INPUTS] = {"
         + ", ".join(str(vr) for vr, _ in inputs) + "};", "",
         "static const size_t input_offset[HG_NUM_INPUTS] = {"]
    c += [f"    offsetof(hg_inputs, {v['field']})," for _, v in inputs]
    c += ["};", "",
          "void *hg_var_ptr(hg_vars *v, const hg_var_info *info)",
          "{", "    return (char *)v + info->offset;", "}", "",
          "const void *hg_var_cptr(const hg_vars *v, const hg_var_info *info)",
          "{", "    return (const char *)v + info->offset;", "}", "",
          "double *hg_input(hg_inputs *u, int k)",
          "{", "    return (double *)((char *)u + input_offset[k]);", "}", "",
          "double hg_input_value(const hg_inputs *u, int k)",
          "{", "    return *(const double *)((const char *)u + input_offset[k]);", "}", "",
          "void hg_inputs_at(const hg_inputs *u0, const hg_inputs *du, double dt, hg_inputs *u)",
          "{"]
    c += [f"    u->{v['field']} = u0->{v['field']} + du->{v['field']} * dt;" for _, v in inputs]
    c += ["}", "",
          "void hg_vars_inputs(const hg_vars *v, hg_inputs *u)",
          "{", "    int k;",
          "    for (k = 0; k < HG_NUM_INPUTS; k++)",
          "        *hg_input(u, k) = *(const double *)hg_var_cptr(v, &hg_var_table[hg_input_vr[k]]);",
          "}", ""]
    return c


def c_states_header(spec):
    """The continuous states (Model Exchange) and the check of their order against the model's."""
    order = " && ".join(f"HG_Y_{y} == {k}" for k, (y, _, _) in enumerate(spec.states))
    return ["/* The continuous states k = 0 .. HG_NUM_STATES - 1, in the model's order: the value",
            " * references of each state and of its derivative. HG_STATE_ORDER_OK is true where the",
            " * model's state enum (HG_Y_*) has this order; the model layer checks it when built. */",
            f"#define HG_NUM_STATES {len(spec.states)}",
            f"#define HG_NUM_EVENT_INDICATORS {spec.event_indicators()}",
            f"#define HG_STATE_ORDER_OK ({order or 1})",
            "extern const unsigned hg_state_vr[HG_NUM_STATES];",
            "extern const unsigned hg_derivative_vr[HG_NUM_STATES];",
            "/* The output each state gives (its own variable, or the output a local state",
            " * reports), HG_NUM_VARS for none: the outputs whose derivative is the state's. */",
            "extern const unsigned hg_state_output_vr[HG_NUM_STATES];", ""]


def c_states_source(spec):
    return ["const unsigned hg_state_vr[HG_NUM_STATES] = {"
            + ", ".join(str(s) for _, s, _ in spec.states) + "};",
            "const unsigned hg_derivative_vr[HG_NUM_STATES] = {"
            + ", ".join(str(d) for _, _, d in spec.states) + "};",
            "const unsigned hg_state_output_vr[HG_NUM_STATES] = {"
            + ", ".join(str(s if spec.vars[s]["group"] == "output"
                            else spec.reports.get(s, len(spec.vars))) for _, s, _ in spec.states)
            + "};", ""]


def write_c(spec, directory):
    inputs = [(vr, v) for vr, v in enumerate(spec.vars) if v["group"] == "input"]
    for _, v in inputs:
        if v["base"] != "Real" or v.get("array"):
            sys.exit(f"variables.toml: input {v['name']}: inputs must be scalar Reals")
    input_index = {vr: k for k, (vr, _) in enumerate(inputs)}
    h = ["/* Generated by modelDescription/generate.py from variables.toml: do not edit. */",
         "#ifndef HG_VARS_H", "#define HG_VARS_H", "", "#include <stddef.h>", "",
         f'#define HG_GUID "{spec.guid()}"',
         f'#define HG_GUID_INTENUM "{intenum_guid(spec)}" /* the integer-coded variant */',
         f'#define HG_TOKEN_FMI3 "{fmi3_guid(spec)}" /* the FMI 3.0 instantiationToken */',
         f"#define HG_NUM_VARS {len(spec.vars)}",
         "#define HG_FMI3_VR_TIME HG_NUM_VARS /* FMI 3.0: the independent variable */",
         "/* FMI 3.0: event indicator k (0-based) is a variable of value reference",
         " * HG_FMI3_VR_INDICATOR + k (Model Exchange, HG_NUM_EVENT_INDICATORS of them) */",
         "#define HG_FMI3_VR_INDICATOR (HG_NUM_VARS + 1)", "",
         "typedef enum { HG_REAL, HG_INTEGER, HG_BOOLEAN, HG_STRING } hg_base_type;",
         "typedef enum { HG_INPUT, HG_OUTPUT, HG_PARAMETER, HG_CALCULATED, HG_LOCAL } hg_causality;",
         ""]
    for ename, items in spec.enums.items():
        consts = ", ".join(f"HG_{ename.upper()}_{iname.upper()} = {i}"
                           for i, (iname, _) in enumerate(items, 1))
        h.append(f"enum {{ {consts} }};")
    sets = ", ".join(f"HG_OUTSET_{name.upper()} = {i}" for i, name in enumerate(spec.output_sets))
    h += ["", "/* The sets the outputs are computed in, each when one of its outputs is read. */",
          f"enum {{ {sets}, HG_NUM_OUTSETS = {len(spec.output_sets)} }};"]
    h += ["", "/* Every variable of the FMU; value reference r lives at hg_var_table[r].offset. */",
          "typedef struct {"]
    for ctype, field, n in spec.fields:
        h.append(f"    {ctype} {field}{f'[{n}]' if n else ''};")
    h += ["} hg_vars;", "", "typedef struct {",
          "    const char *name;",
          "    hg_base_type type;",
          "    hg_causality causality;",
          "    size_t offset;        /* offsetof(hg_vars, field) */",
          "    double start;         /* Real, Integer, Boolean, enumeration */",
          "    const char *start_string;",
          "    int has_min, has_max;",
          "    double min, max;",
          "    int input;            /* index k among the inputs (hg_input_vr), -1 if no input */",
          "    int outset;           /* outputs: the set it is computed with (HG_OUTSET_*), else 0 */",
          "    const char *unit;     /* \"\" when it has none */",
          "    const char *display_unit; /* NULL when it has none */",
          "    double display_factor, display_offset; /* display = factor * value + offset */",
          "} hg_var_info;", "",
          "extern const hg_var_info hg_var_table[HG_NUM_VARS];", "",
          "/* FMI 3.0: value reference r names a variable of count elements (r .. r + count - 1",
          " * in hg_var_table; 0: an array element after the first, no FMI 3.0 variable), an",
          " * Enumeration when enumeration is 1 (fmi3Get/SetInt64). */",
          "typedef struct {", "    unsigned char count, enumeration;", "} hg_fmi3_var;",
          "extern const hg_fmi3_var hg_fmi3_vars[HG_NUM_VARS];", "",
          "/* The storage of a variable in v: the one way from the table to a field. */",
          "void *hg_var_ptr(hg_vars *v, const hg_var_info *info);",
          "const void *hg_var_cptr(const hg_vars *v, const hg_var_info *info);", ""]
    h += c_inputs_header(inputs)
    h += c_states_header(spec)
    h += ["#endif", ""]
    kinds = {"Real": "HG_REAL", "Integer": "HG_INTEGER", "Boolean": "HG_BOOLEAN",
             "String": "HG_STRING"}
    causal = {"input": "HG_INPUT", "output": "HG_OUTPUT", "parameter": "HG_PARAMETER",
              "calculated": "HG_CALCULATED", "state": "HG_LOCAL", "derivative": "HG_LOCAL"}
    c = ["/* Generated by modelDescription/generate.py from variables.toml: do not edit. */",
         '#include "hg_vars.h"', "", "const hg_var_info hg_var_table[HG_NUM_VARS] = {"]
    for vr, v in enumerate(spec.vars):
        lo, hi = v.get("min"), v.get("max")
        if v["typ"] in spec.enums:
            lo, hi = 1, len(spec.enums[v["typ"]])
        start = v.get("start", 0)
        start_num = "0.0" if v["base"] == "String" or start is None else fmt_num(float(start))
        start_str = '"' + str(start).replace('"', '\\"') + '"' if v["base"] == "String" else "NULL"
        c.append(f'    {{"{v["name"]}", {kinds[v["base"]]}, {causal[v["group"]]}, '
                 f'offsetof(hg_vars, {v["field"]}), {start_num}, {start_str}, '
                 f'{int(lo is not None)}, {int(hi is not None)}, '
                 f'{fmt_num(float(lo or 0))}, {fmt_num(float(hi or 0))}, '
                 f'{input_index.get(vr, -1)}, '
                 f'{spec.output_sets.index(v.get("set", spec.output_sets[0]))}, '
                 f'{c_units(spec, v)}}},')
    c += ["};", ""] + c_fmi3_table(spec) + c_inputs_source(inputs) + c_states_source(spec)
    write_if_changed(f"{directory}/hg_vars.h", "\n".join(h))
    write_if_changed(f"{directory}/hg_vars.c", "\n".join(c))


def c_units(spec, v):
    """The unit fields of a variable's C table entry (messages quote values with their units)."""
    unit = v.get("unit", "") if v["base"] == "Real" else ""
    display = v.get("displayUnit") if unit else None
    factor, offset = 1.0, 0.0
    if display:
        factor, offset = next((f, o) for d, f, o in spec.units[unit][1] if d == display)
    name = f'"{display}"' if display else "NULL"
    return f'"{unit}", {name}, {fmt_num(float(factor))}, {fmt_num(float(offset))}'


# ---------------------------------------------------------------- README table


def readme_table(spec):
    rows = ["| name | causality | type | unit | start | description |",
            "|---|---|---|---|---|---|"]
    for v in spec.vars:
        if v.get("array") and not v["name"].endswith("[1]") and "[1]." not in v["name"]:
            continue
        if v["group"] == "derivative":  # one row for them all, after the states
            if v is next(d for d in spec.vars if d["group"] == "derivative"):
                rows.append("| `der(<state>)` | local | Real | the state's per s |  | the time "
                            "derivative of each continuous state (Model Exchange) |")
            continue
        name = v["name"].replace("[1]", "[k]") if v.get("array") else v["name"]
        typ = v["typ"]
        start = f"`{v.get('start', '')}`"
        if typ in spec.enums:  # items with the integer codes hosts set (fmpy needs the codes)
            typ = "enum: " + ", ".join(f"{i} = {e[0]}" for i, e in enumerate(spec.enums[typ], 1))
            start = f"`{v['start']}` ({spec.enums[v['typ']][v['start'] - 1][0]})"
        unit = v.get("unit", "") if v["base"] == "Real" else ""
        if v.get("displayUnit"):
            unit += f" ({README_UNIT_TEXT.get(v['displayUnit'], v['displayUnit'])})"
        start = "" if v["group"] in COMPUTED else start
        rows.append(f"| `{name}` | {GROUPS[v['group']][0]} | {typ} | {unit} | {start} | "
                    f"{v['description']} |")
    return "\n".join(rows)


def update_readme(spec, path, check):
    text = open(path).read()
    if README_BEGIN not in text or README_END not in text:
        sys.exit(f"{path}: markers {README_BEGIN!r} / {README_END!r} not found")
    head, rest = text.split(README_BEGIN, 1)
    _, tail = rest.split(README_END, 1)
    new = head + README_BEGIN + "\n" + readme_table(spec) + "\n" + README_END + tail
    if check:
        if new != text:
            sys.exit(f"{path}: the variable table is out of date; run "
                     "python3 modelDescription/generate.py --readme README.md")
        return
    write_if_changed(path, new)


# ---------------------------------------------------------------- Python table


def python_entry(vr, v, spec):
    """One variable as the source text of a hypoid.fmu.variables.Variable."""
    enum = v["typ"] if v["typ"] in spec.enums else None
    fields = dict(name=v["name"], vr=vr, causality=GROUPS[v["group"]][0],
                  variability=("discrete" if v["group"] == "output" and v["base"] != "Real"
                               else GROUPS[v["group"]][1]),
                  type="Enumeration" if enum else v["base"], enumeration=enum,
                  unit=v.get("unit") if v["base"] == "Real" else None,
                  display_unit=v.get("displayUnit"),
                  start=None if v["group"] in COMPUTED else v.get("start"),
                  min=v.get("min", 1 if enum else None),
                  max=v.get("max", len(spec.enums[enum]) if enum else None),
                  description=v["description"])
    return "    Variable(" + ", ".join(f"{k}={val!r}" for k, val in fields.items()) + "),"


def python_module(spec):
    """The source of hypoid/fmu/variables.py: the variable table for the Python tools."""
    m = spec.model
    enums = {name: {iname: i for i, (iname, _) in enumerate(items, 1)}
             for name, items in spec.enums.items()}
    units = {name: {d: (f, o) for d, f, o in displays} for name, (_, displays) in spec.units.items()}
    lines = ['"""The FMU\'s variables (generated by modelDescription/generate.py from',
             'modelDescription/variables.toml: do not edit; regenerate with',
             '`python3 modelDescription/generate.py --python hypoid/fmu/variables.py`).',
             "",
             "VARIABLES maps each scalar name to its Variable (value reference vr, causality, type",
             "'Real' | 'Integer' | 'Boolean' | 'String' | 'Enumeration', unit, start, min, max);",
             "ENUMERATIONS maps each enumeration to {item name: code}; DISPLAY_UNITS maps a unit to",
             '{display unit: (factor, offset)} with display = factor * value + offset."""',
             "",
             "from typing import NamedTuple",
             "",
             f"MODEL_NAME = {m['modelName']!r}",
             f"MODEL_VERSION = {m['version']!r}",
             f"GUID = {spec.guid()!r}",
             "",
             "",
             "class Variable(NamedTuple):",
             "    name: str",
             "    vr: int",
             "    causality: str",
             "    variability: str",
             "    type: str",
             "    enumeration: str | None",
             "    unit: str | None",
             "    display_unit: str | None",
             "    start: object",
             "    min: float | None",
             "    max: float | None",
             "    description: str",
             "",
             "",
             f"ENUMERATIONS = {enums!r}",
             "",
             f"DISPLAY_UNITS = {units!r}",
             "",
             "_TABLE = ("]
    lines += [python_entry(vr, v, spec) for vr, v in enumerate(spec.vars)]
    lines += [")", "", "VARIABLES = {v.name: v for v in _TABLE}", ""]
    return "\n".join(lines)


def update_python(spec, path, check):
    text = python_module(spec)
    if check:
        try:
            old = open(path).read()
        except FileNotFoundError:
            old = None
        if old != text:
            sys.exit(f"{path}: the Python variable table is out of date; run "
                     "python3 modelDescription/generate.py --python hypoid/fmu/variables.py")
        return
    write_if_changed(path, text)


def write_if_changed(path, text):
    try:
        if open(path).read() == text:
            return
    except FileNotFoundError:
        pass
    with open(path, "w") as f:
        f.write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--toml", default=__file__.rsplit("/", 1)[0] + "/variables.toml")
    ap.add_argument("--xml")
    ap.add_argument("--xml-intenum", help="the modelDescription with Integer-coded enumerations")
    ap.add_argument("--xml3", help="the FMI 3.0 modelDescription")
    ap.add_argument("--c-dir")
    ap.add_argument("--readme")
    ap.add_argument("--python", help="the Python variable table (hypoid/fmu/variables.py)")
    ap.add_argument("--check", action="store_true",
                    help="with --readme / --python: fail if stale instead of writing")
    args = ap.parse_args()
    spec = Spec(args.toml)
    if args.xml:
        write_xml(spec, args.xml)
    if args.xml_intenum:
        write_xml_intenum(spec, args.xml_intenum)
    if args.xml3:
        write_xml3(spec, args.xml3)
    if args.c_dir:
        write_c(spec, args.c_dir)
    if args.readme:
        update_readme(spec, args.readme, args.check)
    if args.python:
        update_python(spec, args.python, args.check)
    return 0


if __name__ == "__main__":
    sys.exit(main())
