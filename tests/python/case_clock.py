"""How long a case has run in a child process, for the runners of test_robustness_inputs.py and
test_extremes.py: in the child's CPU time, not the wall clock. A case is a hang when it has used
more CPU than its budget (it spins), or when it has used none for that long (it is blocked: a
FIFO, a pipe, a lock). On a loaded machine, or under a sanitizer on one, a legal but costly case
takes several times its CPU time in wall time; the wall clock alone called such cases hangs."""

import os
import time

_TICK = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def cpu_seconds(pid):
    """User + system CPU seconds of process pid so far (Linux /proc), None where not readable."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()  # the name in (...) may hold spaces
    except (OSError, IndexError):
        return None
    return (int(fields[11]) + int(fields[12])) / _TICK  # utime, stime: fields 14 and 15


class CaseClock:
    """start() when a case begins; expired() says why it counts as a hang, or None. Where /proc
    is not readable it falls back to the wall clock."""

    def __init__(self, pid, budget):
        self.pid, self.budget = pid, budget
        self.start()

    def start(self):
        self.cpu0 = self.cpu_seen = cpu_seconds(self.pid)
        self.wall0 = self.wall_seen = time.monotonic()

    def expired(self):
        now, cpu = time.monotonic(), cpu_seconds(self.pid)
        if cpu is None or self.cpu0 is None:
            return f"ran {self.budget:g} s (wall clock)" if now - self.wall0 > self.budget else None
        if cpu - self.cpu0 > self.budget:
            return f"used {self.budget:g} s of CPU"
        if cpu > self.cpu_seen:
            self.cpu_seen, self.wall_seen = cpu, now
        elif now - self.wall_seen > self.budget:
            return f"blocked: no CPU used for {self.budget:g} s"
        return None
