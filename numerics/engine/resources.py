"""The machine's resources as the engine's run estimates read them: memory available, and sizes and durations
written for people (:func:`~ringchain.numerics.estimate_run`, the refusals of runs too large)."""

from __future__ import annotations

import os

__all__ = ["format_bytes", "format_duration", "available_memory"]


def format_bytes(n) -> str:
    """``n`` bytes in kB, MB or GB, three significant digits."""
    for unit, size in (("GB", 2**30), ("MB", 2**20), ("kB", 2**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


def format_duration(seconds) -> str:
    """A duration in s, min, h or days, three significant digits."""
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s"


def available_memory() -> int | None:
    """Bytes of memory this process can still take: MemAvailable, capped by ulimit -v and a cgroup limit.

    None if none of them can be read.
    """
    available = None
    try:
        with open("/proc/meminfo") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    available = int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        try:
            available = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (OSError, ValueError, AttributeError):
            pass
    try:  # an address-space limit (ulimit -v) less what the process already maps
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            with open("/proc/self/statm") as handle:
                mapped = int(handle.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
            available = soft - mapped if available is None else min(available, soft - mapped)
    except (ImportError, OSError, ValueError):
        pass
    try:
        with open("/sys/fs/cgroup/memory.max") as handle:
            limit = handle.read().strip()
        with open("/sys/fs/cgroup/memory.current") as handle:
            used = int(handle.read().strip())
        if limit != "max":
            free = int(limit) - used
            available = free if available is None else min(available, free)
    except (OSError, ValueError):
        pass
    return available
