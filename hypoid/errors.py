"""The error every layer may raise for a mistake in what the user gave: a command-line option, a
file, a setting. The `hypoid` command (hypoid.cli) prints it, like hypoid.fmu.values.BadValue and
hypoid.fmu.instance.FmuError, as one line `hypoid <tool>: ...` with exit status 2."""


class UsageError(Exception):
    """A mistake in what the user gave; the message is one line saying what is allowed."""
