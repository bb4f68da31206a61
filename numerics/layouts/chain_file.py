r"""Chain descriptions in TOML: the rings of a chain that changes along its length, segment by segment.

A file lists segments from the impact end (ring 0) up to the support::

    support = "fixed"          # optional: "fixed" (default) or "free" (no gravity: --no-gravity)

    [[segment]]
    rings = 10                 # ring count
    R = 22.5e-3                # major radius, m
    r = 2.5e-3                 # tube radius, m
    material = "stainless"     # optional (a preset of ringchain.theory.MATERIALS; default stainless)
    angle = 90                 # optional: contact angle to the ring above, degrees (default 90)

    [[segment]]
    rings = 10
    R = [22.5e-3, 12.5e-3]     # graded: first and last ring of the segment
    r = 2.5e-3
    profile = "geometric"      # optional: how graded values are spaced, "linear" (default) or "geometric"

R, r and angle are one number, or a pair [first, last] graded over the segment's rings.
Each ring's angle is the contact angle to the ring above it (the last ring's, to the
support); see :meth:`ringchain.numerics.Chain.from_rings`.  Angles are in degrees, as on
the command line; lengths in m.  A malformed file is refused with a message naming the
segment (counted from 1) and the field.  The file is UTF-8, with or without a byte-order mark, or
UTF-16 (:func:`~ringchain.numerics.engine.traces.read_text`).

A sweep varies one field of one segment (:func:`vary`): ``"2.R"`` replaces segment 2's R,
``"2.R.last"`` only the last end of its grading (the grading parameter), ``"2.R.first"`` the first.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from ringchain.theory import Ring, get_material
from ringchain.theory import _validate as v

from ..engine.traces import read_text
from .chain import GRADING_PROFILES, SUPPORTS, Chain

try:  # Python 3.11+
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["Segment", "ChainFile", "read_chain_file", "parse_chain", "vary"]

_FIELDS = ("rings", "R", "r", "material", "angle", "profile")
_GRADED = ("R", "r", "angle")


@dataclass(frozen=True)
class Segment:
    """Rings of one kind, or graded from one kind to another.

    Attributes
    ----------
    rings : int
        Ring count, >= 1.
    R, r : float or (float, float)
        Major and tube radius, m; a pair grades from the first ring to the last.
    material : str
        Material preset key.
    angle : float or (float, float)
        Contact angle to the ring above, degrees, in (0, 90].
    profile : {"linear", "geometric"}
        Spacing of graded values.
    """

    rings: int
    R: float | tuple
    r: float | tuple
    material: str = "stainless"
    angle: float | tuple = 90.0
    profile: str = "linear"

    def values(self, name: str) -> np.ndarray:
        """The field ``name`` (R, r or angle) of each ring of the segment."""
        value = getattr(self, name)
        if np.ndim(value) == 0:
            return np.full(self.rings, float(value))
        spaced = np.linspace if self.profile == "linear" else np.geomspace
        return spaced(value[0], value[1], self.rings)

    def ring_list(self) -> list[Ring]:
        if all(np.ndim(getattr(self, name)) == 0 for name in _GRADED):  # rings of one kind: one (immutable) Ring
            return [Ring(R=self.R, r=self.r, material=self.material, angle=math.radians(self.angle))] * self.rings
        R, r, angle = (self.values(name) for name in _GRADED)
        return [Ring(R=R[i], r=r[i], material=self.material, angle=math.radians(angle[i])) for i in range(self.rings)]


@dataclass(frozen=True)
class ChainFile:
    """A parsed chain description: its segments, impact end first, and the far end's support; ``path``: the file
    it was read from (None for text)."""

    segments: tuple
    support: str = "fixed"
    source: str = "chain description"
    path: str | None = dataclasses.field(default=None, compare=False)

    @property
    def n_rings(self) -> int:
        return sum(segment.rings for segment in self.segments)

    def rings(self) -> list[Ring]:
        """Every ring, ring 0 (the impact end) first; an error names the segment."""
        rings = []
        for k, segment in enumerate(self.segments, start=1):
            try:
                rings += segment.ring_list()
            except ValueError as error:
                raise ValueError(f"{self.source}: segment {k}: {error}") from None
        return rings

    def chain(self, model: str = "dual-spring", m_eff_ratio: float = 1.0, *, striker_mass=None) -> Chain:
        """The :class:`~ringchain.numerics.Chain` of these rings (:meth:`Chain.from_rings`).

        ``model``, ``m_eff_ratio`` and ``striker_mass`` (``"m_eff"``, the default, ``"m0"``: ring 0's
        own mass, or kg) are the model's choices, not the rings': they are arguments, not fields of
        the file.

        Examples
        --------
        >>> text = '''
        ... [[segment]]
        ... rings = 3
        ... R = 22.5e-3
        ... r = 2.5e-3
        ... [[segment]]
        ... rings = 2
        ... R = [15e-3, 12.5e-3]
        ... r = 2.5e-3
        ... '''
        >>> chain = parse_chain(text).chain()
        >>> chain.n_rings, (chain.a * 1e3).round(2).tolist()  # centre distances, mm
        (5, [40.0, 40.0, 32.5, 22.5])
        """
        rings = self.rings()
        if len(rings) < 2:
            raise ValueError(f"{self.source}: a chain needs at least two rings, the segments hold {len(rings)}")
        for i, ring in enumerate(rings):
            if not ring.can_form_chain:
                k = self._segment_of(i)
                raise ValueError(f"{self.source}: segment {k}, field 'R': R/r = {ring.aspect_ratio:.4g} (ring {i}) is "
                                 "below 3: the rings cannot form a chain")  # fmt: skip
        try:
            return Chain.from_rings(rings, model=model, m_eff_ratio=m_eff_ratio, support=self.support,
                                    striker_mass=striker_mass)  # fmt: skip
        except ValueError as error:
            raise ValueError(f"{self.source}: {error}") from None

    def _segment_of(self, ring: int) -> int:
        ends = np.cumsum([segment.rings for segment in self.segments])
        return int(np.searchsorted(ends, ring, side="right")) + 1


def _field(where: str, name: str, value, check):
    try:
        return check(value)
    except (ValueError, TypeError) as error:
        raise ValueError(f"{where}, field {name!r}: {error}") from None


def _graded(name: str, unit: str, low: float, high: float):
    def check(value):
        if isinstance(value, bool) or isinstance(value, str):
            raise ValueError(f"must be a number (in {unit}) or a pair [first, last], got {value!r}")
        if isinstance(value, list):
            if len(value) != 2 or any(isinstance(x, bool | str) for x in value):
                raise ValueError(f"must be a number (in {unit}) or a pair [first, last], got {value!r}")
            return tuple(float(v.in_range(name, x, low, high)) for x in value)
        return float(v.in_range(name, value, low, high))

    return check


def _segment(where: str, table) -> Segment:
    if not isinstance(table, dict):
        raise ValueError(f"{where}: must be a table of fields {', '.join(_FIELDS)}, got {table!r}")
    unknown = sorted(set(table) - set(_FIELDS))
    if unknown:
        raise ValueError(f"{where}: unknown field {unknown[0]!r} (fields: {', '.join(_FIELDS)})")
    for name in ("rings", "R", "r"):
        if name not in table:
            raise ValueError(f"{where}: field {name!r} is missing")
    fields = {
        "rings": _field(where, "rings", table["rings"], lambda x: v.count("rings", x, 1)),
        "R": _field(where, "R", table["R"], _graded("R", "m", 0.0, np.inf)),
        "r": _field(where, "r", table["r"], _graded("r", "m", 0.0, np.inf)),
        "angle": _field(where, "angle", table.get("angle", 90.0), _graded("angle", "degrees", 0.0, 90.0)),
    }
    material = table.get("material", "stainless")
    fields["material"] = _field(where, "material", material, lambda x: get_material(x) and x)
    profile = table.get("profile", "linear")
    if profile not in GRADING_PROFILES:
        raise ValueError(f"{where}, field 'profile': must be one of {GRADING_PROFILES}, got {profile!r}")
    fields["profile"] = profile
    return Segment(**fields)


def parse_chain(text: str, source: str = "chain description") -> ChainFile:
    """A :class:`ChainFile` from TOML text (see the module); errors name ``source``, the segment and the field."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{source}: not valid TOML: {error}") from None
    unknown = sorted(set(data) - {"segment", "support"})
    if unknown:
        raise ValueError(f"{source}: unknown key {unknown[0]!r} (a chain description has [[segment]] tables and "
                         "an optional support)")  # fmt: skip
    support = data.get("support", "fixed")
    if support not in SUPPORTS:
        raise ValueError(f"{source}: support must be one of {SUPPORTS}, got {support!r}")
    segments = data.get("segment")
    if not isinstance(segments, list) or not segments:
        raise ValueError(f"{source}: no [[segment]] tables: list the chain's segments from the impact end")
    parsed = tuple(_segment(f"{source}: segment {k}", table) for k, table in enumerate(segments, start=1))
    return ChainFile(parsed, support, source)


def read_chain_file(path) -> ChainFile:
    """A :class:`ChainFile` read from a TOML file (see the module): UTF-8, with or without a byte-order mark, or
    UTF-16 with one (:func:`~ringchain.numerics.engine.traces.read_text`);
    another encoding is refused naming the file."""
    return dataclasses.replace(parse_chain(read_text(path), source=f"chain file {path}"), path=str(path))


def vary(description: ChainFile, spec: str, value: float) -> ChainFile:
    """``description`` with one field of one segment set to ``value``.

    Parameters
    ----------
    description : ChainFile
    spec : str
        ``"K.FIELD"`` (segment K counted from 1; FIELD one of rings, R, r, angle) sets the
        field; ``"K.FIELD.first"`` or ``"K.FIELD.last"`` sets one end of a graded field (a
        field given as one number becomes a pair with the other end at that number).
    value : float
        In the field's units (m, degrees, or a ring count).

    Examples
    --------
    >>> base = parse_chain("[[segment]]\\nrings = 4\\nR = 22.5e-3\\nr = 2.5e-3\\n")
    >>> vary(base, "1.R.last", 15e-3).segments[0].R
    (0.0225, 0.015)
    """
    parts = spec.split(".") if isinstance(spec, str) else []
    if len(parts) not in (2, 3) or not parts[0].isdigit() or (len(parts) == 3 and parts[2] not in ("first", "last")):
        raise ValueError(f"a varied field is SEGMENT.FIELD or SEGMENT.FIELD.first/last, e.g. 2.R.last; got {spec!r}")
    k, name = int(parts[0]), parts[1]
    if not 1 <= k <= len(description.segments):
        raise ValueError(f"{description.source}: there is no segment {k} (segments 1 to {len(description.segments)})")
    if name not in ("rings", *_GRADED):
        raise ValueError(f"a varied field must be one of rings, R, r, angle, got {name!r}")
    segment = description.segments[k - 1]
    where = f"{description.source}: segment {k}"
    if name == "rings":
        if len(parts) == 3:
            raise ValueError("the ring count is one number: vary K.rings, not its first or last")
        new = _field(where, "rings", value, lambda x: v.count("rings", x, 1))
    else:
        unit, high = ("degrees", 90.0) if name == "angle" else ("m", np.inf)
        one = _field(where, name, value, _graded(name, unit, 0.0, high))
        if len(parts) == 2:
            new = one
        else:
            current = getattr(segment, name)
            first, last = (current, current) if np.ndim(current) == 0 else current
            new = (one, last) if parts[2] == "first" else (first, one)
    segments = list(description.segments)
    segments[k - 1] = dataclasses.replace(segment, **{name: new})
    return dataclasses.replace(description, segments=tuple(segments))
