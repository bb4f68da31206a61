r"""Measurement files: sensor traces, quasi-static tests and (peak force, speed) pairs, read and written.

- :func:`write_traces` writes the sensor traces of a chain's run (``t_s`` and one
  ``sensor_ring<k>_N`` column per sensor ring, and ``support_N`` when the chain hangs from a
  support): the file ``ringchain simulate --out`` writes and :func:`read_traces` reads;
- :func:`read_traces`, :func:`read_static` (``displacement_m``, ``force_N``),
  :func:`read_speed_amplitude` (``peak_force_N``, ``speed_m_s``, or a sweep's
  ``peak_force_near_N``, ``wave_speed_m_s``); a file that cannot be used raises
  :class:`DataError`, which says what is wrong and where;
- :func:`noise_level`, :func:`starting_level`, :func:`pulse_problem` -- what a measured trace
  carries besides its pulse, shared with the trace fits (:mod:`.fit_dynamic`).
"""

from __future__ import annotations

import codecs
import csv
import math
import re
from pathlib import Path

import numpy as np

__all__ = [
    "DataError",
    "read_text",
    "read_table",
    "read_traces",
    "write_traces",
    "read_static",
    "read_speed_amplitude",
    "noise_level",
    "starting_level",
    "pulse_problem",
    "MIN_SAMPLES",
    "PULSE_NOISE_RATIO",
    "TRACE_COLUMN",
]

#: Fewest samples a data file or trace may have.
MIN_SAMPLES = 10
#: A pulse must stand this many noise levels above its baseline (read_traces).
PULSE_NOISE_RATIO = 8.0

#: Name of the column of the sensor in ring k.
TRACE_COLUMN = "sensor_ring{}_N"


class DataError(ValueError):
    """A data file or array that cannot be used; the message says what is wrong and where.

    Attributes
    ----------
    path : str or None
        File.
    line : int or None
        Line of the file (1-based), where known.
    column : str or None
        Column name, where known.
    """

    def __init__(self, message, *, path=None, line=None, column=None, column_number=None):
        parts = [] if path is None else [str(path)]
        if line is not None:
            parts.append(f"line {line}")
        if column is not None:
            parts.append(f"column {column!r}" if column_number is None else f"column {column_number} ({column})")
        where = ", ".join(parts)
        super().__init__(f"{where}: {message}" if where else message)
        self.path, self.line, self.column = path, line, column


# -- reading data ------------------------------------------------------------------------------------
def read_text(path) -> str:
    """The text of a data or chain file, decoded; a file that is not text says where.

    UTF-8, with or without the byte-order mark that Excel's "CSV UTF-8" writes (it is
    dropped), or UTF-16 with its byte-order mark (Excel's "Unicode text").  Anything else
    (Latin-1, Windows-1252...) raises :class:`DataError` naming the file, the line and the
    byte that is not UTF-8.
    """
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise DataError(f"cannot read the file ({exc.strerror or exc})", path=path) from None
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError:
            raise DataError("not text: it starts as UTF-16 (a byte-order mark) but does not decode as UTF-16; "
                            "save it as UTF-8", path=path) from None  # fmt: skip
    if data.startswith(codecs.BOM_UTF8):
        data = data[len(codecs.BOM_UTF8) :]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        column = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        byte = f"byte {column} (0x{data[exc.start]:02x})"
        raise DataError(f"{byte} is not UTF-8 text (a Latin-1 or Windows-1252 file?); save the file as UTF-8 "
                        "(Excel: CSV UTF-8)", path=path, line=line) from None  # fmt: skip


def read_table(path, required, *, optional_pattern=None, optional=(), text=(), near_miss=None, minimum=MIN_SAMPLES):
    """Columns of a CSV file: ({name: array}, [line number of each row], {name: column number}).

    Lines starting with ``#`` and blank lines are skipped; the first other line is the
    header.  Every cell of a required column (and of columns matching ``optional_pattern``,
    and of the ``optional`` columns the header has) must be a finite number; the ``text``
    columns the header has are read as stripped strings.  A column the file gives twice, or
    (``near_miss``, a regular expression searched case-insensitively) one that looks like
    ``optional_pattern`` without matching it, is refused by name: it would be ignored.
    """
    path = Path(path)
    header, rows, lines = None, [], []
    for number, row in enumerate(csv.reader(read_text(path).splitlines()), start=1):
        if not row or not "".join(row).strip() or row[0].lstrip().startswith("#"):
            continue
        if header is None:
            header = [cell.strip() for cell in row]
            header_line = number
            continue
        rows.append(row)
        lines.append(number)
    if header is None:
        raise DataError("no header line (the file is empty or all comments)", path=path)
    alternatives = [required] if isinstance(required[0], str) else list(required)
    for names in alternatives:
        if all(name in header for name in names):
            break
    else:
        wanted = " or ".join(", ".join(names) for names in alternatives)
        raise DataError(f"missing column(s): need {wanted}; the header has {', '.join(header)}",
                        path=path, line=header_line)  # fmt: skip
    wanted = list(names) + [name for name in optional if name in header and name not in names]
    if optional_pattern is not None:
        wanted += [name for name in header if re.fullmatch(optional_pattern, name) and name not in wanted]
        if near_miss is not None:
            for j, name in enumerate(header):
                if re.search(near_miss, name, re.IGNORECASE) and not re.fullmatch(optional_pattern, name):
                    raise DataError(f"looks like a sensor column but is not named {TRACE_COLUMN.format('<k>')} "
                                    "(k >= 0 the ring counted from the impact, the force in N); rename it, or remove "
                                    "it", path=path, line=header_line, column=name, column_number=j + 1)  # fmt: skip
    strings = [name for name in text if name in header]
    for name in wanted + strings:
        where = [j + 1 for j, cell in enumerate(header) if cell == name]
        if len(where) > 1:
            raise DataError(f"column {name!r} appears {len(where)} times (columns {', '.join(map(str, where))}); "
                            "keep one", path=path, line=header_line)  # fmt: skip
    index = {name: header.index(name) for name in wanted + strings}
    columns = {name: np.empty(len(rows)) for name in wanted} | {name: [] for name in strings}
    for i, (row, number) in enumerate(zip(rows, lines, strict=True)):
        for name, j in index.items():
            if j >= len(row):
                raise DataError(f"no value: the row has {len(row)} cells, the header {len(header)}", path=path,
                                line=number, column=name, column_number=j + 1)  # fmt: skip
            cell = row[j].strip()
            if name in strings:
                columns[name].append(cell)
                continue
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise DataError(f"not a finite number: {cell!r}", path=path, line=number, column=name,
                                column_number=j + 1)  # fmt: skip
            columns[name][i] = value
    if len(rows) < minimum:
        raise DataError(f"{len(rows)} samples; at least {minimum} are needed", path=path)
    return columns, lines, {name: j + 1 for name, j in index.items()}


def _check_increasing(t, path, lines, name, number):
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise DataError(f"time does not increase: {t[i]:.9g} s after {t[i - 1]:.9g} s on line {lines[i - 1]}",
                        path=path, line=lines[i], column=name, column_number=number)  # fmt: skip


def noise_level(y) -> float:
    """Robust standard deviation of white noise on a smooth trace, from its first differences.

    The smaller of the estimates over the whole trace (the pulse is a small part of it) and
    over its quiet start (its first 5 %, before the wave arrives): ringing of the chain
    after the pulse raises the first, a record that starts late the second.
    """

    def robust(d):
        return float(1.4826 * np.median(np.abs(d - np.median(d))) / math.sqrt(2.0))

    return min(robust(np.diff(y)), robust(np.diff(y[: max(4, y.size // 20)])))


def starting_level(y) -> float:
    """The trace's level before anything happens: median of its first 5 % of samples (at least 3)."""
    return float(np.median(y[: max(3, y.size // 20)]))


def pulse_problem(y) -> str | None:
    """Why ``y`` has no usable pulse (None if it has one): it must rise PULSE_NOISE_RATIO noise levels."""
    excursion = float(np.max(y) - starting_level(y))
    noise = noise_level(y)
    if excursion > PULSE_NOISE_RATIO * noise and excursion > 0:
        return None
    return (f"no pulse: the trace rises at most {excursion:.4g} N above its starting level, within "
            f"{PULSE_NOISE_RATIO:g} noise levels ({noise:.3g} N each); negate an inverted channel")  # fmt: skip


def read_traces(path):
    """Read sensor force traces: the CSV that ``ringchain simulate --out`` writes.

    Parameters
    ----------
    path : str or path
        CSV file with a header line: ``t_s`` (time, s) and one column
        ``sensor_ring<k>_N`` (force, N, tension positive) per sensor ring k, counted from the
        impact as the package counts rings (ring 0 is the one struck).  Lines starting with
        ``#`` are comments; other columns are ignored, except those that look like a sensor's
        (``Sensor_Ring12_N``, ``sensor_ring12_kN``, ``sensor_ring12``...), which are refused by
        name, as is a column given twice.  UTF-8 (with or without Excel's byte-order mark)
        or UTF-16 (:func:`read_text`).  The sampling need not be uniform, the
        time need not start at the impact (a trigger offset is fitted) and a channel may
        carry a DC offset (fitted too).

    Returns
    -------
    t : ndarray
        Times, s, increasing.
    traces : dict
        {k: force (N) of the sensor in ring k}, ring order of the file.

    Raises
    ------
    DataError
        A missing column, a column given twice or almost named as a sensor's, a time that
        does not increase, a cell that is not a finite number (NaN), fewer than
        :data:`MIN_SAMPLES` samples, or a trace without a pulse; the message names the file,
        line and column.

    Examples
    --------
    >>> import tempfile
    >>> t = np.linspace(0.0, 1e-3, 50)
    >>> rows = "".join(f"{x},{np.exp(-((x - 5e-4) / 1e-4) ** 2)}\\n" for x in t)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "run.csv"
    ...     _ = path.write_text("t_s,sensor_ring6_N\\n" + rows)
    ...     t_read, traces = read_traces(path)
    >>> t_read.size, list(traces)
    (50, [6])
    """
    columns, lines, numbers = read_table(path, ["t_s"], optional_pattern=r"sensor_ring\d+_N",
                                         near_miss=_SENSOR_LIKE)  # fmt: skip
    sensors = [name for name in columns if name != "t_s"]
    if not sensors:
        raise DataError("missing column(s): need at least one sensor_ring<k>_N column (force in N of the sensor "
                        "in ring k)", path=path)  # fmt: skip
    t = columns["t_s"]
    _check_increasing(t, path, lines, "t_s", numbers["t_s"])
    traces, names = {}, {}
    for name in sensors:
        problem = pulse_problem(columns[name])
        if problem:
            raise DataError(problem, path=path, column=name, column_number=numbers[name])
        ring = int(re.fullmatch(r"sensor_ring(\d+)_N", name).group(1))
        if ring in traces:
            first = names[ring]
            raise DataError(f"columns {numbers[first]} ({first}) and {numbers[name]} ({name}) are both the sensor "
                            f"of ring {ring}; keep one", path=path)  # fmt: skip
        traces[ring], names[ring] = columns[name], name
    return t, traces


#: Columns that look like a sensor's (searched case-insensitively) but are not named sensor_ring<k>_N.
_SENSOR_LIKE = r"sensor|ring[ _-]?-?\d"


def read_static(path):
    """Read a quasi-static force-displacement test.

    Parameters
    ----------
    path : str or path
        CSV file with the columns ``displacement_m`` (m) and ``force_N`` (N, tension
        positive); ``#`` lines are comments, other columns are ignored.

    Returns
    -------
    displacement, force : ndarray

    Raises
    ------
    DataError
        A missing column, a cell that is not a finite number, fewer than
        :data:`MIN_SAMPLES` rows, or a column that takes one value on every row (no
        law can be read from it) (file, line, column in the message).
    """
    columns, _, numbers = read_table(path, ["displacement_m", "force_N"])
    for name, unit in (("displacement_m", "m"), ("force_N", "N")):
        if np.ptp(columns[name]) == 0:
            raise DataError(f"the same value, {columns[name][0]:g} {unit}, on every row: a static test needs a range "
                            "of loads", path=path, column=name, column_number=numbers[name])  # fmt: skip
    return columns["displacement_m"], columns["force_N"]


def read_speed_amplitude(path, *, geometry=False):
    """Read measured (peak force, wave speed) pairs for :func:`fit_speed_amplitude`.

    Parameters
    ----------
    path : str or path
        CSV file with ``peak_force_N`` and ``speed_m_s``, or the columns of a
        ``ringchain sweep`` file, ``peak_force_near_N`` and ``wave_speed_m_s``; at least 3 rows.
    geometry : bool, optional
        Also return the rings the file names, row by row (a sweep file does): columns
        ``R_m`` and ``r_m`` and optionally ``angle_rad`` or ``angle_deg`` (default 90 deg) and
        ``material`` (default stainless).

    Returns
    -------
    F_m, V_s : ndarray
        N and m/s.
    rings : dict or None
        With ``geometry``: {"R", "r" (m), "angle" (rad): arrays, "material": list of str,
        "line": the file's line of each row}, or None if the file names no rings.
    """
    columns, lines, numbers = read_table(
        path, [("peak_force_N", "speed_m_s"), ("peak_force_near_N", "wave_speed_m_s")], minimum=3,
        optional=("R_m", "r_m", "angle_rad", "angle_deg"), text=("material",),
    )  # fmt: skip
    F_m, V_s = ((columns["peak_force_N"], columns["speed_m_s"]) if "peak_force_N" in columns else
                (columns["peak_force_near_N"], columns["wave_speed_m_s"]))  # fmt: skip
    if not geometry:
        return F_m, V_s
    if "R_m" not in columns and "r_m" not in columns:
        return F_m, V_s, None
    missing = "r_m" if "R_m" in columns else "R_m"
    if missing not in columns:
        present = "R_m" if missing == "r_m" else "r_m"
        raise DataError(f"column {present!r} names the rings' size but {missing!r} is missing; give both or neither",
                        path=path, column=present, column_number=numbers[present])  # fmt: skip
    if "angle_rad" in columns:
        angle = columns["angle_rad"]
    elif "angle_deg" in columns:
        angle = np.radians(columns["angle_deg"])
    else:
        angle = np.full(F_m.size, math.pi / 2)
    material = columns.get("material") or ["stainless"] * F_m.size
    return F_m, V_s, {"R": columns["R_m"], "r": columns["r_m"], "angle": angle, "material": material,
                      "line": np.array(lines)}  # fmt: skip


def write_traces(path, sim, sensors) -> None:
    """Write the sensor traces of a chain's run as CSV: what :func:`read_traces` reads.

    Parameters
    ----------
    path : str or path
    sim : Simulation
        A run of a chain (it may have recorded the sensors' rings only).
    sensors : sequence of int
        Sensor rings, counted from the impact.

    Notes
    -----
    Columns ``t_s`` (s), ``sensor_ring<k>_N`` (N, tension positive) for each sensor ring and,
    when the chain hangs from a support, ``support_N`` (the run must have recorded the top ring); every
    number written with 17 significant digits (it reads back to the same double).
    """
    columns = {"t_s": sim.t, **{TRACE_COLUMN.format(k): sim.sensor(k) for k in sensors}}
    support = sim.support_force
    if support is not None:
        columns["support_N"] = support
    np.savetxt(path, np.column_stack(list(columns.values())), delimiter=",", header=",".join(columns), comments="",
               fmt="%.17g")  # fmt: skip
