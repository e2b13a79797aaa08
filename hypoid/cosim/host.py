"""What the drivers of outside co-simulation hosts share (libcosim.py, ecos.py): whether the
host's library loads here, and the error that says how to get it."""

from hypoid.errors import UsageError


def why_not(probe):
    """None when probe() (which loads the host's library) runs, else why not (one line)."""
    try:
        probe()
    except Exception as e:  # noqa: BLE001 - any failure means: not usable here
        return f"{type(e).__name__}: {e}"
    return None


def require(host, why, install):
    """Raises UsageError naming the host, why it does not load (why: its why_unavailable) and
    how to install it."""
    reason = why()
    if reason:
        raise UsageError(f"{host} is not usable here ({reason}): {install}")
