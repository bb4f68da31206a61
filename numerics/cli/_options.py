"""Options of the ``ringchain`` command line: their types, their checks and the groups subcommands share.

Every value is checked when it is parsed, with ringchain's own validators, and refused in
the user's units under the option's name (``argument --angle: contact angle (deg) must lie
in (0, 90], got 91``); values that depend on each other (R and r, sensors and chain
length, impact speed and material) are checked before any work by the ``check_*``
functions; output paths are checked (by trying to open them) before any work and are
never changed.
"""

from __future__ import annotations

import argparse
import contextlib
import math
import os
from pathlib import Path

import numpy as np
from ringchain.theory import PAPER_TUBE_RADIUS, impact_speed, paper_data
from ringchain.theory import _validate as v

# -- option values: parsed and checked before any work, errors in the user's units ---------------------
#: Most values of one sweep axis and most points of one sweep the command line runs: a guard against a
#: typo such as ``--drop-height 0.01:0.1:1000000000``, which would exhaust the memory before any work
#: (100000 points of static theory alone take a few minutes; :func:`ringchain.numerics.sweep` has no limit).
MAX_GRID_POINTS = 100_000


def one_line(exc) -> str:
    """An exception's message on one line (the command line prints one line per error)."""
    return " ".join(str(exc).split()) or type(exc).__name__


class Checked:
    """argparse type: ``parse`` the text, then ``check`` the value with one of ringchain's validators.

    Text that does not parse gives argparse's own error (``argument --R: invalid float value:
    'abc'``); a value the check refuses gives the check's message, after the option's name
    (``argument --drop-height: drop height must be positive (in m), got -1``).
    """

    def __init__(self, parse, check=None):
        self.parse, self._check = parse, check
        self.__name__ = parse.__name__  # argparse names the type in "invalid float value"

    def check(self, value):
        if self._check is None:
            return value
        try:
            return self._check(value)
        except (ValueError, TypeError) as exc:
            raise argparse.ArgumentTypeError(one_line(exc)) from None

    def __call__(self, text):
        return self.check(self.parse(text))


class Given(argparse.Action):
    """Store an option's value and note its name in ``args.given``: what the user typed, default or not.

    ``--chain`` refuses the ring options it replaces, and a data file that names its rings
    refuses a ring option that differs from them, only when they were given.
    """

    def __call__(self, parser, namespace, values, option_string=None):
        setattr(namespace, self.dest, values)
        namespace.given = {*getattr(namespace, "given", ()), self.dest}


def given(args) -> set:
    """The options ``args`` holds because the user gave them (:class:`Given`), by their dest names."""
    return set(getattr(args, "given", ()))


def positive(what, unit):
    """A finite number > 0, in ``unit``."""
    return Checked(float, lambda x: float(v.positive(what, x, unit)))


def fraction(what):
    """A finite number in (0, 1]."""
    return Checked(float, lambda x: float(v.in_range(what, x, 0.0, 1.0)))


def integer(what, minimum):
    """An integer >= ``minimum``."""
    return Checked(int, lambda n: v.count(what, n, minimum))


def material(name):
    """A material preset key (:data:`ringchain.theory.MATERIALS`)."""
    from ringchain.theory import get_material

    get_material(name)
    return name


#: Most rings of a chain the command line builds (--rings, a chain file, --vary K.rings): a guard against a typo
#: such as --rings 100000000, whose chain alone would fill the memory before any estimate of the run (a chain of
#: 1e6 rings takes about 0.3 GB and minutes to integrate; :func:`ringchain.numerics.simulate` has no limit).
MAX_RINGS = 1_000_000


def check_rings(n: int, what: str) -> int:
    """A ring count within :data:`MAX_RINGS` (``what``: the chain's name in the message)."""
    if n > MAX_RINGS:
        raise ValueError(f"{what} has {n} rings; the command line builds chains of at most {MAX_RINGS} rings (use "
                         "ringchain.numerics.simulate for more)")  # fmt: skip
    return n


def ring_count(n):
    """A number of rings of a chain: an integer from 2 to :data:`MAX_RINGS`."""
    n = v.count("rings", n, 2)
    if n > MAX_RINGS:
        raise ValueError(f"at most {MAX_RINGS} rings from the command line (use ringchain.numerics.simulate for more), "
                         f"got {n}")  # fmt: skip
    return n


def batch_size(n):
    """A positive number of runs per task."""
    if n < 1:
        raise ValueError(f"batch_size must be a positive integer, got {n}")
    return n


def striker_mass(text: str):
    """argparse type of --striker-mass: "m_eff", "m0" or a positive mass in kg (:func:`.chain.striker_convention`)."""
    from ..layouts.chain import STRIKERS, striker_convention

    if text not in STRIKERS:
        try:
            text = float(text)
        except ValueError:
            expected = ", ".join(STRIKERS)
            raise argparse.ArgumentTypeError(f"expected {expected} or a mass in kg, got {text!r}") from None
    try:
        return striker_convention(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(one_line(exc).replace("striker_mass", "striker mass")) from None


LENGTH_R = positive("R", "m")
LENGTH_r = positive("r", "m")
ASPECT = positive("R/r", "")
ANGLE = Checked(float, lambda x: float(v.in_range("contact angle (deg)", x, 0.0, 90.0)))
M_EFF_RATIO = fraction("m_eff/m0")
DROP_HEIGHT = positive("drop height", "m")
IMPACT_VELOCITY = positive("impact velocity", "m/s")
FORCE = positive("force", "N")
DURATION = positive("duration", "s")


class Values:
    """argparse type of a sweep axis: one value, or ``start:stop:count`` for ``count`` evenly spaced ones.

    Each value is checked as one value of the option would be; start > stop counts down.
    """

    def __init__(self, one: Checked):
        self.one = one
        self.__name__ = one.__name__

    def __call__(self, text: str) -> list:
        floats = self.one.parse is float
        parts = text.split(":")
        try:
            if len(parts) == 1:
                return [self.one(text)]
            if len(parts) != 3 or not floats:
                raise ValueError
            start, stop = float(parts[0]), float(parts[1])
        except ValueError:
            form = "a number or start:stop:count" if floats else "an integer"
            raise argparse.ArgumentTypeError(f"expected {form}, got {text!r}") from None
        try:
            count = int(parts[2])
        except ValueError:
            count = 0
        if not 1 <= count <= MAX_GRID_POINTS:
            raise argparse.ArgumentTypeError(
                f"the count of start:stop:count must be an integer from 1 to {MAX_GRID_POINTS}, got {parts[2]!r} "
                f"in {text!r}"
            )
        self.one.check(start), self.one.check(stop)
        if start == stop and count > 1:
            raise argparse.ArgumentTypeError(f"{text!r} gives {count} equal values; give the value once")
        # 12 significant digits: 0.08, not linspace's 0.07999999999999999.
        return [self.one.check(float(f"{x:.12g}")) for x in np.linspace(start, stop, count)]


def flat(lists):
    """The values of a sweep axis given as several ``Values`` (a list per argument), or None."""
    return None if lists is None else [x for values in lists for x in values]


# -- output paths: checked before any work, never changed --------------------------------------------
def output_file(text: str) -> str:
    """argparse type of an output file: refused at once if it cannot be written (it is not written yet)."""
    path = Path(text)
    if not text:
        raise argparse.ArgumentTypeError("the file name is empty")
    if path.is_dir():
        raise argparse.ArgumentTypeError(f"{text} is a folder; give the name of a file (in it, say)")
    folder = path.parent
    if not folder.is_dir():
        reason = "is not a folder" if folder.exists() else "does not exist"
        raise argparse.ArgumentTypeError(f"cannot write {text}: the folder {folder} {reason}")
    existed = path.exists()
    try:
        with open(path, "a"):  # appends nothing: the one sure test (read-only file systems, ACLs, root)
            pass
    except OSError as exc:
        raise argparse.ArgumentTypeError(f"cannot write {text}: {exc.strerror or exc}") from None
    if not existed:
        path.unlink(missing_ok=True)
    return text


def output_csv(text: str) -> str:
    """An output file, or ``-`` for the standard output."""
    return text if text == "-" else output_file(text)


def _plot_formats() -> dict:
    from matplotlib.backend_bases import FigureCanvasBase

    return FigureCanvasBase.get_supported_filetypes()


def plot_file(text: str) -> str:
    """An output file whose extension names an image format matplotlib writes (never added by us)."""
    path = Path(text)
    if path.is_dir():
        raise argparse.ArgumentTypeError(f"{text} is a folder; give an image file in it, e.g. {path / 'plot.png'}")
    formats = _plot_formats()
    extension = path.suffix.lower().lstrip(".")
    if extension not in formats:
        known = ", ".join(f".{f}" for f in sorted(formats))
        what = f"its extension .{extension} is not an image format" if extension else "it has no extension"
        raise argparse.ArgumentTypeError(f"{text}: {what}; name the file with one of {known}")
    return output_file(text)


def output_folder(text: str) -> str:
    """argparse type of an output folder: an existing folder, or one that can be created."""
    path = Path(text)
    if not text:
        raise argparse.ArgumentTypeError("the folder name is empty")
    if path.exists() and not path.is_dir():
        raise argparse.ArgumentTypeError(f"{text} exists and is not a folder")
    parent = path
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    if not parent.is_dir():
        raise argparse.ArgumentTypeError(f"cannot create the folder {text}: {parent} is not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise argparse.ArgumentTypeError(f"cannot write in the folder {parent}: permission denied")
    return text


# -- checks across options, before any work ------------------------------------------------------------
def aspect_ratio(R: float, r: float) -> float:
    """R/r to 12 significant digits: 3, not 2.9999999999999996 for R = 0.3, r = 0.1."""
    return float(f"{R / r:.12g}")


def check_geometry(aspect: float, angles, *, chain: bool, given: str, two_patches: bool = False) -> None:
    """R/r and the contact angles (deg) admit one Hertz contact and, for a chain, rings that hold two neighbours.

    ``two_patches``: angles below arccos(1 - 2r/R), where the numerical contact takes over with
    two patches, are admitted down to 2 arcsin(r/R), where the patches reach the sides of the tubes.
    """
    from ringchain.theory import MIN_CHAIN_ASPECT_RATIO, minimum_contact_angle, smallest_patch_angle

    if not aspect > 2:
        raise ValueError(f"{given}: R must exceed 2 r for the Hertz contact of two tori, got R/r = "
                         f"{v.distinct(aspect, 2)}")  # fmt: skip
    if chain and aspect < MIN_CHAIN_ASPECT_RATIO:
        raise ValueError(
            f"{given}: R/r = {v.distinct(aspect, MIN_CHAIN_ASPECT_RATIO)} < {MIN_CHAIN_ASPECT_RATIO:g}, so the hole of "
            "a ring, 2(R - r) across, cannot pass the wires of its two neighbours (4 r): rings this thick cannot "
            "form a chain"
        )
    lowest = math.degrees(float(minimum_contact_angle(aspect, 1.0)))
    angle = min(angles)
    if two_patches:
        floor = math.degrees(float(smallest_patch_angle(aspect, 1.0)))
        if angle <= floor:
            raise ValueError(
                f"argument --angle: a contact angle of {v.distinct(angle, floor)} deg is at or below "
                f"2 arcsin(r/R) = {v.distinct(floor, angle)} deg for R/r = {aspect:.6g}: the contact points reach the "
                "sides of the tubes there and the rings no longer pull each other along the chain"
            )
        return
    if angle <= lowest:
        raise ValueError(
            f"argument --angle: a contact angle of {v.distinct(angle, lowest)} deg is at or below "
            f"arccos(1 - 2r/R) = {v.distinct(lowest, angle)} deg for R/r = {aspect:.6g}: the tori touch along a line "
            "or at two patches there, and a single elliptical Hertz contact does not apply"
        )


def check_sensors(sensors, chain_lengths, source=None) -> None:
    """Near sensor before the far one, both in the shortest chain (of the chain file ``source``, if given)."""
    near, far = sensors
    if not near < far:
        raise ValueError(f"argument --sensors: the near ring comes first, then the far one; got {near} {far}")
    shortest = min(chain_lengths)
    if far >= shortest:
        example = f"--sensors {shortest // 3} {2 * shortest // 3}"
        remedy = (f"give --rings {far + 1} or more" if source is None else
                  f"give sensors below {shortest} ({example}, say), or a chain file of {far + 1} rings or "
                  "more")  # fmt: skip
        where = f"a chain of {shortest} rings" if source is None else f"the {shortest} rings of {source}"
        raise ValueError(f"argument --sensors: sensor ring {far} is not in {where} (0..{shortest - 1}); {remedy}")


def check_outputs(inputs, outputs) -> None:
    """Refuse an output (--out, --plot) that names an input (a chain file, a data file): it would be overwritten."""
    read = {Path(path).resolve(): path for path in inputs if path is not None}
    for flag, path in outputs:
        if path is not None and path != "-" and Path(path).resolve() in read:
            raise ValueError(f"argument {flag}: {path} is an input of this command and would be overwritten; give "
                             "another file")  # fmt: skip


def check_impact(material: str, *, drop_heights=None, impact_velocities=None) -> None:
    """Impacts slower than the bar-wave speed sqrt(E/rho) of the material, where the contact model can hold.

    Hertz contact is quasi-static: it holds for impact speeds far below the elastic wave
    speed of the bodies (Johnson, Contact Mechanics, Sec. 11.4); at or above sqrt(E/rho) no
    lattice of point masses describes the impact (and the integrators fail).
    """
    from ringchain.theory import get_material

    mat = get_material(material)
    c0 = math.sqrt(mat.E / mat.rho)
    speeds = [(f"argument --impact-velocity: {u:g} m/s", u) for u in impact_velocities or ()]
    for h in drop_heights or ():
        speeds.append((f"argument --drop-height: a drop of {h:g} m gives an impact at {{:.3g}} m/s, which",
                       float(impact_speed(h))))  # fmt: skip
    for text, speed in speeds:
        if speed >= c0:
            raise ValueError(
                f"{text.format(speed)} is not below the bar-wave speed sqrt(E/rho) = {c0:.4g} m/s of {mat.name}; "
                "Hertz contact and the lattice models hold only far below it"
            )


@contextlib.contextmanager
def computing(what: str):
    """Report a failure of the theory or the solver as one about the options the user gave."""
    try:
        yield
    except (ValueError, ArithmeticError, RuntimeWarning) as exc:
        raise ValueError(f"cannot compute {what}: {one_line(exc)}") from None


def ring_of(R, r, material, angle_deg, what, *, thin=False, window=None):
    """The Ring (R, r in m, angle in degrees) and its statics, computed here so that a failure names ``what``."""
    from ringchain.theory import Ring

    with computing(what):
        ring = Ring(R, r, material=material, angle=math.radians(angle_deg), thin=thin)
        ring.K_c, ring.K_b, ring.power_law(*(window or ()))
    return ring


@contextlib.contextmanager
def naming_size(args):
    """A run the engine refuses as too large: add the command line's remedies."""
    from ..engine.integrate import RunTooLargeError

    try:
        yield
    except RunTooLargeError as exc:
        chain = "fewer rings in --chain's file" if getattr(args, "chain", None) is not None else "fewer --rings"
        raise ValueError(f"{one_line(exc)}. From the command line: {chain}, fewer --samples or a shorter "
                         "--t-end") from None  # fmt: skip


@contextlib.contextmanager
def naming_t_end(args):
    """A duration the sweep finds too short is the user's --t-end: say so."""
    try:
        yield
    except ValueError as exc:
        if args.t_end is None or "t_end" not in str(exc):
            raise
        raise ValueError(f"argument --t-end: {one_line(exc).replace('t_end', '--t-end')}") from None


# -- option groups: defined once, shared by the subcommands -----------------------------------------
def option(p, many, name, one, default, **kwargs):
    """One option of one value, or of several values and ranges for a sweep (``many``); noted in ``args.given``."""
    if many:
        p.add_argument(name, type=Values(one), nargs="+", default=[[default]], action=Given, **kwargs)
    else:
        p.add_argument(name, type=one, default=default, action=Given, **kwargs)


def geometry_options(p, *, many=False, R_required=False):
    """Chain geometry: --R (--R-over-r in a sweep), --r, --angle, --material, --m-eff-ratio."""
    if many:
        option(p, True, "--R-over-r", ASPECT, 9.0, metavar="X", help="aspect ratios R/r (default 9)")
    elif R_required:
        p.add_argument("--R", type=LENGTH_R, required=True, metavar="M", help="major (centroidal) radius, m")
    else:
        p.add_argument("--R", type=LENGTH_R, default=22.5e-3, metavar="M", action=Given,
                       help="major (centroidal) radius of the rings, m (default 22.5e-3)")  # fmt: skip
    p.add_argument("--r", type=LENGTH_r, default=PAPER_TUBE_RADIUS, metavar="M", action=Given,
                   help="tube radius, m (default 2.5e-3, the paper's)")  # fmt: skip
    option(p, many, "--angle", ANGLE, 90.0, metavar="DEG",
           help="contact angle between ring planes, degrees, in (0, 90] (default 90)")  # fmt: skip
    p.add_argument("--material", type=Checked(str, material), default="stainless", action=Given,
                   help="material preset (default stainless: AISI 304)")  # fmt: skip
    option(p, many, "--m-eff-ratio", M_EFF_RATIO, 1.0, metavar="X",
           help="inertial over ring mass m_eff/m0 in (0, 1] (default 1; the paper fits 0.33-0.37)")  # fmt: skip


def impact_options(p, *, many=False, required=False):
    """The impact on ring 0: --drop-height or --impact-velocity."""
    impact = p.add_mutually_exclusive_group(required=required)
    if many:
        impact.add_argument("--drop-height", type=Values(DROP_HEIGHT), nargs="+", metavar="M", help="drop heights, m")
        impact.add_argument("--impact-velocity", type=Values(IMPACT_VELOCITY), nargs="+", metavar="M/S",
                            help="impact speeds, m/s")  # fmt: skip
    else:
        impact.add_argument("--drop-height", type=DROP_HEIGHT, metavar="M", help="free-fall height of ring 0, m")
        impact.add_argument("--impact-velocity", type=IMPACT_VELOCITY, metavar="M/S",
                            help="impact speed of ring 0, m/s")  # fmt: skip


def executor_options(p, *, default_batch: int, what: str = "runs of one chain"):
    """Where the work runs: --batch-size, --workers, --dask ADDRESS, --dask-timeout (a sweep, an ensemble)."""
    p.add_argument("--batch-size", type=Checked(int, batch_size), default=default_batch,
                   help=f"{what} integrated together (default {default_batch})")  # fmt: skip
    p.add_argument("--workers", type=integer("workers", 0), default=None,
                   help="local worker processes (default: CPUs; 0: run in this process)")  # fmt: skip
    p.add_argument("--dask", metavar="ADDRESS", help="run on a Dask cluster, e.g. tcp://scheduler:8786")
    p.add_argument("--dask-timeout", type=DURATION, default=5.0, metavar="S",
                   help="seconds to wait for the Dask scheduler to answer (default 5)")  # fmt: skip


@contextlib.contextmanager
def executor_of(args):
    """The executor of --dask (a client's, closed at the end), or None for local processes (--workers)."""
    if not args.dask:
        yield None
        return
    from ..engine.executors import dask_client

    try:
        client = dask_client(args.dask, args.dask_timeout)
    except ImportError:
        raise ValueError("--dask needs the dask extra: pip install 'ringchain[dask]'") from None
    except (ConnectionError, ValueError) as exc:
        raise ValueError(f"argument --dask: {one_line(exc)}") from None
    with client:
        yield client.get_executor()


def chain_options(p, *, many=False):
    """The lattice run: --rings, --model, --sensors, --t-end, --samples."""
    from ..engine.integrate import check_samples
    from ..layouts.chain import MODELS

    rings = Checked(int, ring_count)
    if many:
        p.add_argument("--rings", type=Values(rings), nargs="+", default=[[paper_data.CHAIN_RINGS]], metavar="N",
                       action=Given, help="chain lengths (default 20)")  # fmt: skip
    else:
        p.add_argument("--rings", type=rings, default=paper_data.CHAIN_RINGS, action=Given,
                       help="rings in the chain (default 20)")  # fmt: skip
    p.add_argument("--model", choices=MODELS, default=None if many else "dual-spring", nargs="+" if many else None,
                   help="lattice model (paper Sec. III.B; default dual-spring)")  # fmt: skip
    p.add_argument("--sensors", type=integer("sensor ring", 0), nargs=2, default=list(paper_data.SENSOR_RINGS),
                   metavar=("NEAR", "FAR"), help="sensor rings counted from the impact (default 6 12)")  # fmt: skip
    p.add_argument("--t-end", type=DURATION, default=None, metavar="S",
                   help="duration, s (default: long enough for the pulse to pass the far sensor)")  # fmt: skip
    p.add_argument("--samples", type=Checked(int, check_samples), default=None,
                   help="samples of each force record (default: simulate's 2001, sweep's 1001)")  # fmt: skip
    p.add_argument("--no-gravity", dest="gravity", action="store_false",
                   help="no gravity: the chain starts unstretched (a chain file's free support needs it)")  # fmt: skip


def striker_option(p, *, many=False):
    """--striker-mass: the inertia of the struck ring 0 (several, for a sweep)."""
    what = ("inertia of the struck ring 0: m_eff (the lattice's, the paper's convention; default), m0 (the ring's "
            "own mass, a rigid ring in free fall) or a mass in kg")  # fmt: skip
    if many:
        p.add_argument("--striker-mass", type=striker_mass, nargs="+", default=["m_eff"], metavar="MASS",
                       help=what + "; several give one row each")  # fmt: skip
    else:
        p.add_argument("--striker-mass", type=striker_mass, default="m_eff", metavar="MASS", help=what)


def striker_words(striker, m0: float | None = None) -> str:
    """The striker of a run in words, for what ``ringchain simulate`` prints."""
    if striker == "m_eff":
        return "striker of the lattice's inertia m_eff (the paper's convention)"  # m_eff is the chain's m
    if striker == "m0":
        mass = "" if m0 is None else f", {m0 * 1e3:.4g} g"
        return f"rigid striker of the ring's mass m0{mass}"
    return f"striker of {striker * 1e3:.4g} g"


def chain_file(text: str):
    """argparse type of --chain: a TOML chain description, read and checked now (:mod:`.chain_file`)."""
    from ..layouts.chain_file import read_chain_file

    try:
        description = read_chain_file(text)
        check_rings(description.n_rings, description.source)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(one_line(exc)) from None
    return description


def chain_file_options(p, *, sweep=False):
    """--chain FILE (a chain that changes along its length) and, for a sweep, --vary SPEC VALUES."""
    p.add_argument("--chain", type=chain_file, metavar="FILE",
                   help="TOML chain description (segments of ring count, R, r, material, angle; see "
                        "ringchain.numerics.layouts.chain_file); "
                        "replaces --R, --r, --angle, --material, --rings")  # fmt: skip
    if sweep:
        p.add_argument("--vary", nargs="+", metavar=("FIELD", "VALUES"),
                       help="with --chain: a field of one segment and its values, e.g. --vary 2.R.last 0.01:0.02:5 "
                            "(SEGMENT.FIELD or SEGMENT.FIELD.first/last; FIELD rings, R, r or angle)")  # fmt: skip


def check_chain_file_alone(args, names=("R", "R_over_r", "r", "angle", "material", "rings")) -> None:
    """--chain replaces the single-ring geometry: refuse those options when given, whatever their values."""
    for name in names:
        if name in given(args):
            flag = "--" + name.replace("_", "-")
            raise ValueError(f"argument {flag}: not allowed with --chain (the chain file gives every ring's geometry)")


def vary_values(spec: list) -> tuple[str, list]:
    """The field and the values of --vary FIELD VALUES... (numbers or start:stop:count)."""
    if len(spec) < 2:
        raise ValueError("argument --vary: give a field and at least one value, e.g. --vary 2.R.last 0.01:0.02:5")
    parse = Values(Checked(float))
    try:
        values = flat([parse(text) for text in spec[1:]])
    except argparse.ArgumentTypeError as exc:
        raise ValueError(f"argument --vary: {exc}") from None
    if len(values) > MAX_GRID_POINTS:
        raise ValueError(f"argument --vary: at most {MAX_GRID_POINTS} values, got {len(values)}")
    return spec[0], values


# -- the chain of ringchain simulate, the points of ringchain sweep: every input checked first ----------
def check_support(description, args) -> None:
    """A chain file whose far end is free cannot hang under gravity: it needs --no-gravity."""
    if description.support == "free" and args.gravity:
        raise ValueError(f'{description.source} has support = "free": a chain with a free far end cannot hang under '
                         "gravity; give --no-gravity")  # fmt: skip


def simulated_chain(args):
    """The chain of ``ringchain simulate`` (of --chain FILE, or of the ring options) and how to name it."""
    from ..jobs.sweep import Point

    impacts = {"drop_heights": [args.drop_height] if args.drop_height is not None else None,
               "impact_velocities": [args.impact_velocity] if args.impact_velocity is not None else None}  # fmt: skip
    if args.chain is not None:
        description = args.chain
        check_chain_file_alone(args)
        check_support(description, args)
        check_sensors(args.sensors, [description.n_rings], description.source)
        for material in {segment.material for segment in description.segments}:
            check_impact(material, **impacts)
        with computing(f"the chain of {description.source}"):
            chain = description.chain(args.model, args.m_eff_ratio, striker_mass=args.striker_mass)
        striker = striker_words(args.striker_mass, chain.striker_inertia)
        return chain, f" from {description.source} ({len(description.segments)} segments), {striker}"
    aspect = aspect_ratio(args.R, args.r)
    check_geometry(aspect, [args.angle], chain=True, given="arguments --R and --r")
    check_sensors(args.sensors, [args.rings])
    check_impact(args.material, **impacts)
    ring_of(aspect * args.r, args.r, args.material, args.angle, f"the ring of --R {args.R:g} m and --r {args.r:g} m")
    point = Point(R_over_r=aspect, r=args.r, angle=math.radians(args.angle), material=args.material, model=args.model,
                  n_rings=args.rings, m_eff_ratio=args.m_eff_ratio, sensors=tuple(args.sensors),
                  striker_mass=args.striker_mass)  # fmt: skip
    with computing(f"the chain of {args.rings} rings"):
        chain = point.chain()
    return chain, f", R/r = {aspect:g}, {striker_words(args.striker_mass, chain.striker_inertia)}"


def sweep_points(args) -> list:
    """The points of ``ringchain sweep``: a grid of ring options, or the values of --vary on --chain FILE."""
    from ..jobs.sweep import FilePoint, expand

    if args.chain is None:
        if args.vary:
            raise ValueError("argument --vary: varies a field of a chain file; give --chain FILE")
        return expand(_sweep_grid(args))
    check_chain_file_alone(args)
    check_support(args.chain, args)
    if args.drop_height is None and args.impact_velocity is None:
        raise ValueError("a sweep of a chain file needs impacts: give --drop-height or --impact-velocity")
    field, values = vary_values(args.vary) if args.vary else (None, [None])
    lengths = [args.chain.n_rings]
    if field is not None:
        from ..layouts.chain_file import vary

        try:
            lengths = [vary(args.chain, field, value).n_rings for value in values]
        except ValueError as exc:
            raise ValueError(f"argument --vary: {one_line(exc)}") from None
        for n, value in zip(lengths, values, strict=True):
            check_rings(n, f"argument --vary: the chain of {field} = {value:g}")
    check_sensors(args.sensors, lengths, args.chain.source)
    ratios, models = flat(args.m_eff_ratio), args.model or ["dual-spring"]
    heights, velocities = flat(args.drop_height), flat(args.impact_velocity)
    for material in {segment.material for segment in args.chain.segments}:
        check_impact(material, drop_heights=heights, impact_velocities=velocities)
    impacts = [{"drop_height": h} for h in heights] if heights else [{"impact_velocity": u} for u in velocities]
    return [FilePoint(args.chain, field, value, model, ratio, sensors=tuple(args.sensors), striker_mass=striker,
                      **impact)
            for model in models for ratio in ratios for striker in args.striker_mass for value in values
            for impact in impacts]  # fmt: skip


def _sweep_grid(args) -> dict:
    """The grid of ``ringchain sweep``, every value checked against the others before any work."""
    aspects, angles, rings = flat(args.R_over_r), flat(args.angle), flat(args.rings)
    impacts = {"drop_height": flat(args.drop_height)} if args.drop_height is not None else (
        {"impact_velocity": flat(args.impact_velocity)} if args.impact_velocity is not None else {})  # fmt: skip
    for aspect in aspects:
        check_geometry(aspect, angles, chain=bool(impacts), given="argument --R-over-r")
    if impacts:
        check_sensors(args.sensors, rings)
        check_impact(args.material, drop_heights=impacts.get("drop_height"),
                     impact_velocities=impacts.get("impact_velocity"))  # fmt: skip
    # Axis order fixes the row order: the impact varies fastest, so runs of one chain are adjacent.
    grid = {
        "model": args.model or ["dual-spring"],
        "n_rings": rings,
        "R_over_r": aspects,
        "angle": [math.radians(a) for a in angles],
        "m_eff_ratio": flat(args.m_eff_ratio),
        "striker_mass": args.striker_mass,
        "r": [args.r],
        "material": [args.material],
        "sensors": [tuple(args.sensors)],
        **impacts,
    }
    size = math.prod(len(values) for values in grid.values())
    if size > MAX_GRID_POINTS:
        shape = " x ".join(str(len(values)) for values in grid.values() if len(values) > 1)
        raise ValueError(f"the grid has {size} points ({shape}); the command line runs at most {MAX_GRID_POINTS} "
                         "(split it, or call ringchain.numerics.sweep)")  # fmt: skip
    # The rings at the corners of the grid, where the theory's numbers are most extreme.
    for aspect in {min(aspects), max(aspects)}:
        for angle in {min(angles), max(angles)}:
            ring_of(aspect * args.r, args.r, args.material, angle,
                    f"the ring of --R-over-r {aspect:g}, --r {args.r:g} m, --angle {angle:g} deg")  # fmt: skip
    return grid


# -- the rings of ringchain fit speed, the chain of ringchain fit traces -----------------------------------
def speed_rings(args, rows):
    """The rings of ``ringchain fit speed``: the file's, row by row (``rows`` of
    :func:`~ringchain.numerics.read_speed_amplitude`, a sweep file names them), or the ring options' (``rows``
    None).  A ring option given that differs from the file's value on a row is refused, naming the line."""
    if (args.K is None) != (args.n is None):
        raise ValueError("give both --K and --n, or neither (then the ring's power law, Eq. 4, is used)")
    if rows is None:
        return ring_of(args.R, args.r, args.material, args.angle, f"the ring of --R {args.R:g} m and --r {args.r:g} m")
    columns = {"R": (rows["R"], "m"), "r": (rows["r"], "m"), "angle": (np.degrees(rows["angle"]), "deg"),
               "material": (rows["material"], "")}  # fmt: skip
    for name in sorted(given(args) & set(columns)):
        values, unit = columns[name]
        ours = getattr(args, name)
        for value, line in zip(values, rows["line"], strict=True):
            differs = value != ours if name == "material" else not math.isclose(value, ours, rel_tol=1e-9)
            if differs:
                shown = value if name == "material" else f"{value:.6g} {unit}"
                raise ValueError(f"argument --{name}: {args.file} names its rings, and line {line} gives {name} = "
                                 f"{shown}, not the {ours:g}{' ' + unit if unit else ''} given; leave --{name} out to "
                                 "use the file's rings")  # fmt: skip
    if args.K is not None:
        distinct = {(R, r, a, m) for R, r, a, m in zip(rows["R"], rows["r"], rows["angle"], rows["material"],
                                                         strict=True)}  # fmt: skip
        if len(distinct) > 1:
            raise ValueError(f"arguments --K and --n give one power law, but {args.file} holds pairs from "
                             f"{len(distinct)} different rings; leave them out (each ring's own, Eq. 4)")  # fmt: skip
    rings = {}
    for R, r, angle, name, line in zip(rows["R"], rows["r"], rows["angle"], rows["material"], rows["line"],
                                       strict=True):  # fmt: skip
        if (R, r, angle, name) not in rings:
            where = f"the ring of {args.file}, line {line} (R = {R:g} m, r = {r:g} m)"
            rings[R, r, angle, name] = ring_of(R, r, name or "stainless", math.degrees(angle), where)
    return [rings[key] for key in zip(rows["R"], rows["r"], rows["angle"], rows["material"], strict=True)]


def trace_chain(args):
    """The starting chain of ``ringchain fit traces`` (of --chain FILE, or of the ring options, with --K and --n
    for a power law) and its ring 0's mass m0 (kg)."""
    import dataclasses

    from ..layouts.chain import Chain

    dashpots = {"gamma": args.gamma} if args.model == "power-law" else {"gamma_c": args.gamma,
                                                                           "gamma_b": args.gamma_b}  # fmt: skip
    if args.model != "power-law" and (args.K is not None or args.n is not None):
        raise ValueError("--K and --n give a power law: use them with --model power-law")
    if (args.K is None) != (args.n is None):
        raise ValueError("give both --K and --n, or neither (then the ring's power law, Eq. 4, is used)")
    if args.chain is not None:
        check_chain_file_alone(args, names=("R", "r", "angle", "material", "rings"))
        if args.K is not None:
            raise ValueError("arguments --K and --n: not allowed with --chain (the chain file gives every contact)")
        description = args.chain
        with computing(f"the chain of {description.source}"):
            chain = description.chain(args.model, args.m_eff_ratio)
        chain = dataclasses.replace(chain, gamma=args.gamma, striker_mass=args.striker_mass,
                                    **({} if args.model == "power-law" else {"gamma_b": args.gamma_b}))  # fmt: skip
        return chain, float(np.ravel(chain.m_gravity)[0])
    ring = ring_of(args.R, args.r, args.material, args.angle, f"the ring of --R {args.R:g} m and --r {args.r:g} m")
    ring.check_chain()
    law = {} if args.K is None else {"K": args.K, "n": args.n}
    with computing(f"the chain of {args.rings} rings"):
        chain = Chain.from_ring(ring, args.rings, args.model, m_eff_ratio=args.m_eff_ratio, **law, **dashpots,
                                striker_mass=args.striker_mass)  # fmt: skip
    return chain, ring.mass
