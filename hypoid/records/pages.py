"""What the record pages share: the head that says what wrote the page from which data and what
measured it, Markdown tables, number formats, and the page of a record that is a list of
sections laid out by its measuring script (`tables_page`)."""

import json

SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def head(record, provenance=""):
    """Title and the line every record page starts with."""
    data = ", ".join(f"[{d}]({d})" for d in record.data)
    note = (f"*A record: written by `hypoid records {record.name}` from {data}, measured by "
            f"`{record.measure}`; edit neither by hand.*")
    lines = [f"# {record.title}", "", note]
    if provenance:
        lines += ["", provenance]
    return "\n".join(lines) + "\n"


def load(folder, name):
    return json.loads((folder / name).read_text())


def table(columns, rows):
    """A Markdown table of string cells."""
    out = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out)


def sci(x, digits=2):
    """1.8·10⁻⁵ (`digits` significant digits)."""
    if x == 0.0:
        return "0"
    mantissa, exponent = f"{x:.{digits - 1}e}".split("e")
    return f"{mantissa}·10{str(int(exponent)).translate(SUPERSCRIPT)}"


def minus(text):
    """Typographic minus signs in a formatted figure."""
    return text.replace("-", "−")


def sections(blocks):
    """Markdown of a list of sections: {"heading": text, "level": 2} | {"text": paragraph} |
    {"table": {"columns": [...], "rows": [[...]]}} | {"image": path, "alt": text} |
    {"items": [...]}."""
    out = []
    for b in blocks:
        if "heading" in b:
            out.append("#" * b.get("level", 2) + " " + b["heading"])
        elif "text" in b:
            out.append(b["text"])
        elif "table" in b:
            out.append(table(b["table"]["columns"], b["table"]["rows"]))
        elif "image" in b:
            out.append(f"![{b.get('alt', '')}]({b['image']})")
        elif "items" in b:
            out.append("\n".join(f"- {item}" for item in b["items"]))
        else:
            raise ValueError(f"unknown section {sorted(b)}")
    return "\n\n".join(out) + "\n"


def tables_page(record, folder, _old=None):
    """The page of a record whose data are {"provenance": ..., "sections": [...]}."""
    data = load(folder, record.data[0])
    return head(record, data.get("provenance", "")) + "\n" + sections(data["sections"])
