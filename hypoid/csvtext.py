"""Reading the files people write for the tools: tables exported from spreadsheets (the cell
separator ',' or, in locales with a decimal comma, ';' or a tab, and numbers with a decimal
comma; the TCA importer, the drive cycle's CSV reader) and TOML files (the vehicle file, the
design file), each failure one message naming the file."""

import pathlib
import tomllib


def read_toml(path, where, error):
    """The TOML file's tables; a file that cannot be read or is not TOML raises error(one line
    starting with `where`)."""
    try:
        return tomllib.loads(pathlib.Path(path).read_text())
    except (OSError, UnicodeDecodeError) as e:
        raise error(f"{where}: cannot read it ({e})") from None
    except tomllib.TOMLDecodeError as e:
        raise error(f"{where}: not TOML ({e})") from None


def delimiter(lines):
    """The cell separator of the lines that are neither blank nor comments: whichever of ',', ';'
    and a tab occurs most in the first 50 of them (',' for none)."""
    text = "".join(ln for ln in [ln for ln in lines if ln.strip()
                                 and not ln.lstrip().startswith("#")][:50])
    return max(",;\t", key=text.count) if text else ","


def number(text):
    """float(text), reading one decimal comma (12,5) as a point; ValueError if not a number."""
    return float(text.replace(",", ".") if text.count(",") == 1 and "." not in text else text)
