"""Reading the tables people export from spreadsheets: the cell separator (',' or, in locales
with a decimal comma, ';' or a tab) and numbers written with a decimal comma. Used by the TCA
importer and the drive cycle's CSV reader."""


def delimiter(lines):
    """The cell separator of the lines that are neither blank nor comments: whichever of ',', ';'
    and a tab occurs most in the first 50 of them (',' for none)."""
    text = "".join(ln for ln in [ln for ln in lines if ln.strip()
                                 and not ln.lstrip().startswith("#")][:50])
    return max(",;\t", key=text.count) if text else ","


def number(text):
    """float(text), reading one decimal comma (12,5) as a point; ValueError if not a number."""
    return float(text.replace(",", ".") if text.count(",") == 1 and "." not in text else text)
