"""Paths that users give to the tools, made absolute against their working directory.

The FMU reads a relative data-file name (gear_set_file, lubricant_file, efficiency_map_file)
relative to its own resources folder, and a host such as fmpy unzips the FMU into a temporary
folder: `lubricant_file=my.txt` given to the FMU directly names <temporary folder>/resources/my.txt.
The tools therefore hand the FMU an absolute path whenever the name is a file relative to where
the user stands, and pass any other relative name through unchanged, so that names of the FMU's
own resources (`lubricants/OS265962.txt`) still work. docs/integration.md, "Relative paths"."""

import os


def user_path(path):
    """An absolute path for a path given by the user (relative to the working directory, `~`
    expanded); the empty string stays empty."""
    text = os.fspath(path)
    return os.path.abspath(os.path.expanduser(text)) if text else text


def data_file(value):
    """The value of a data-file variable as the FMU should get it: absolute when it names a file
    relative to the working directory, otherwise unchanged (a name inside the FMU's resources)."""
    text = os.fspath(value)
    if not text or os.path.isabs(text):
        return text
    candidate = user_path(text)
    return candidate if os.path.isfile(candidate) else text

