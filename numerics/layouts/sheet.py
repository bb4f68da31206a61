r"""A sheet of interlinked rings as a two-dimensional network: a layout of the engine (beyond the paper).

The paper closes by naming two-dimensional interlinked lattices as the next step (Sec. V).  A
:class:`Sheet` lays rings out in a plane, one site per ring moving in the sheet's plane (two
components, x along the rows and y up the sheet), and joins linked rings by a contact: a
:class:`~ringchain.numerics.laws.PowerLaw` acting along the line between the two ring centres,
tension only (interlocked rings slide freely until pulled).  :func:`ringchain.numerics.simulate`
integrates it like a chain; the linear waves of the pretensioned sheet are
:func:`ringchain.theory.sheet_dispersion`.

Layouts
-------
``Sheet.square(rows, cols, ring)`` -- 4-in-1 chain mail: site (row, col) at (col a_x, row a_y), linked to
its neighbours along x and y (families "x", "y").  ``Sheet.triangular(rows, cols, ring)`` -- 6-in-1: rows
a sqrt(3)/2 apart, odd rows shifted by a/2, each site linked at 0, 60 and 120 degrees (families "0 deg",
"60 deg", "120 deg").  Row 0 is the bottom edge; site (row, col) is ``row * cols + col``
(:meth:`Sheet.site`).  ``Sheet.from_links(positions, links, rings)`` takes any layout.

The contact of two rings
------------------------
Each link is the power law F = K delta^n (paper Eq. (4)) of its ring pair at the angle between the two
rings' planes (:func:`contact_law`): the Hertz contact of the pair (Eq. (1), elliptical at an oblique
angle, :func:`~ringchain.theory.hertz_stiffness_pair`) in series with the bending of the ring body
(Eq. (2)), fitted over the force window (Eq. (4)), as :meth:`Chain.from_ring` does for a chain; below the
angle theta_min where one Hertz contact no longer exists, the numerical contact of
:mod:`~ringchain.numerics.contact.bem`.  The angle is a parameter (4-in-1 mail links its rings
diagonally), one for every link or one per family, defaulting to the ring's own ``angle``.

Why the power law only.  The dual-spring chain (Eqs. (5)-(6)) gives each ring two half-masses joined by
its bending spring, because in a chain a ring is squeezed between two contacts, on one line.  A ring of a
sheet is pulled at 4 or 6 contacts in different directions: its body answers with a 4 x 4 or 6 x 6
compliance (the ring's in-plane bending couples every pair of contacts), not with one spring per link,
and two half-masses have no place to sit.  The sheet is therefore the power-law model (one site per
ring, Eq. (7)), each link's law the series law of Eq. (3) through its fitted power law: exact for a ring
pulled along one line (a row of the sheet taut, its neighbours slack), an approximation where a ring is
pulled along several lines at once (theory/sheet.py's notes).  The series law itself (a contact in series
with a massless ring body per link) is well defined link by link, but it gives the extension from the force
(Eq. (3)), not the force from the extension the engine needs at every step; over the force window its fitted
power law stands in for it, as in the paper's power-law chain (Eq. (4)).

Loads
-----
- ``hanging=True``: the sheet hangs in a vertical plane under gravity (along -y), clamped along its top
  edge: the top row hangs from the fixed support through one more link per site (the chain's support),
  vertical links at the chain's angle, the sides free (slack) or periodic.  Gravity acts on the ring mass
  m0 and the inertia is m_eff (``m_eff_ratio``), as in the chain.  Each column of the square sheet then
  hangs as a chain: the link above row r carries the weight of the column below it, the horizontal links
  stay at their unloaded length (no force).  The triangular sheet hangs row by row from its inclined links
  and needs periodic sides (a free edge site would hang from a single inclined link, whose sideways pull
  nothing balances).
- ``pretension``: the sheet lies in a horizontal plane (gravity normal to it, not acting on the in-plane
  motion), each link of a family carrying the static tension T of that family (a biaxial pretension:
  (T_x, T_y), or one per family of the triangular sheet).  Its rest positions are this static state:
  every link at its static extension, held by a frame of fixed points where the missing neighbours of the
  edge sites would be (``boundary="clamped"``) or by periodic images (``boundary="periodic"``).  Every set
  of family tensions is an equilibrium (:func:`ringchain.theory.sheet.equilibrium_force`).
- ``gamma``: a dashpot inside each contact's bracket (Eq. (7)).

Displacements are measured from :attr:`Sheet.positions`: for a hanging sheet the lattice with every link
just taut and unloaded (the chain's convention; the hanging state sags below it), for a pretensioned sheet
the pretensioned lattice itself (its static state is x = 0).

The impact (``struck``)
-----------------------
An edge (``"bottom"``, ``"top"``, ``"left"``, ``"right"``: every site of that edge moves away from the
sheet, along the edge's outward normal), a list of sites (moving along ``impact_direction``, by default
the outward normal of the edge they lie on), or a velocity field, shape (n_sites, 2), per unit impact speed.
``simulate(sheet, t_end, impact_velocity=v)`` starts the struck sites at v.  ``drop_height`` follows the
chain's drop protocol on a hanging sheet: the struck sites (of the bottom row) were lifted and fall
freely; the run starts when their links are just taut again, the struck sites unstretched and moving down
at sqrt(2 g h), the rows above hanging at rest without their weight.  Struck along its whole bottom row, a
hanging square sheet is a row of identical chains (:class:`~ringchain.numerics.Chain`), column by column.

Records: ``simulate(..., rings=sites)`` keeps the states of those sites only (one ring per site;
:meth:`Sheet.link_sites` gives the sites whose states the forces of some links need).  A run is a
:class:`~ringchain.numerics.SheetSimulation` (:mod:`.sheet_runs`): ``link_force`` (time x links),
``displacement`` and ``velocity`` (time x sites x 2), ``energy()`` (the forces and energies compiled in one
pass over the samples, :mod:`ringchain.numerics.engine.fields`), its fields written to NetCDF.
"""

from __future__ import annotations

import copy
import dataclasses
import functools

import numpy as np
from ringchain.theory import (
    DEFAULT_FORCE_WINDOW,
    MATERIALS,
    STANDARD_GRAVITY,
    Ring,
    fit_power_law,
    hertz_stiffness_pair,
    minimum_contact_angle,
)
from ringchain.theory import _validate as v
from ringchain.theory.sheet import FAMILY_NAMES, PATTERNS

from ..engine.integrate import check_model_size
from ..engine.laws import PowerLaw
from ..engine.network import ANCHOR, Links, Network
from .sheet_runs import SheetBatch

__all__ = ["Sheet", "PATTERNS", "EDGES", "SHEET_MODELS", "contact_law"]

#: The edges of a sheet, by the names ``struck`` and :meth:`Sheet.edge` take, with their outward normals.
EDGES = {"bottom": (0.0, -1.0), "top": (0.0, 1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}

#: The lattice models of a sheet: the power law only (see the module notes for the dual-spring model).
SHEET_MODELS = ("power-law",)


def contact_law(ring_a: Ring, ring_b: Ring | None = None, angle=None, window=DEFAULT_FORCE_WINDOW):
    """(K, n) of the contact of two interlocked rings at an angle between their planes (Eqs. (1)-(4)).

    The one place a sheet takes its contact law from (module notes): above the smallest angle of one Hertz
    contact, theta_min (:func:`~ringchain.theory.minimum_contact_angle`), the Hertz contact of the pair
    (:func:`~ringchain.theory.hertz_stiffness_pair`; for two equal rings :meth:`Ring.power_law` at that angle,
    the chain's own numbers) in series with the bending of the ring body, the power law fitted over
    ``window`` (Eq. (4)); at or below theta_min, the numerical contact of two equal rings
    (:func:`~ringchain.numerics.angle_power_law`).

    Parameters
    ----------
    ring_a, ring_b : Ring
        The two rings (``ring_b`` default ``ring_a``).  Unequal rings take the harmonic mean of their two
        bending stiffnesses (each link stretches half of each ring's body).
    angle : float, optional
        Angle between the two rings' planes, rad, in (0, pi/2]; default ``ring_a.angle``.
    window : (float, float), optional
        Force window of the fit, N.

    Returns
    -------
    (float, float)
        K (N/m^n) and n.

    Examples
    --------
    >>> ring = Ring.from_aspect_ratio(9.0)
    >>> contact_law(ring) == ring.power_law()
    True
    """
    ring_b = ring_a if ring_b is None else ring_b
    for name, ring in (("ring_a", ring_a), ("ring_b", ring_b)):
        if not isinstance(ring, Ring):
            raise TypeError(f"{name} must be a ringchain.theory.Ring, got {type(ring).__name__}")
    angle = ring_a.angle if angle is None else float(v.in_range("angle", angle, 0.0, np.pi / 2))
    same = dataclasses.replace(ring_b, angle=ring_a.angle) == ring_a
    if same and angle <= float(minimum_contact_angle(ring_a.R, ring_a.r)):
        from ..contact.angle import angle_power_law

        mat = ring_a.material
        law = angle_power_law(ring_a.R, ring_a.r, mat.E, mat.nu, angle, ring_a.K_b, tuple(window))
        return float(law.K), float(law.n)
    if same:
        return dataclasses.replace(ring_a, angle=angle).power_law(*window)
    a, b = ring_a.material, ring_b.material
    K_c = hertz_stiffness_pair(ring_a.R, ring_a.r, a.E, a.nu, ring_b.R, ring_b.r, b.E, b.nu, angle)
    K_b = 2.0 / (1.0 / ring_a.K_b + 1.0 / ring_b.K_b)
    K, n = fit_power_law(K_c=K_c, K_b=K_b, F_min=window[0], F_max=window[1])
    return float(K), float(n)


def _per_family(name, value, families, check, unit):
    """One value per family: a sequence (tuple, list, array) gives them in the family order, a number is shared."""
    if not isinstance(value, str) and np.ndim(value) == 1:
        value = tuple(np.asarray(value, dtype=object).tolist())
    elif np.ndim(value) > 1:
        raise ValueError(f"{name} is one value or one per link family ({', '.join(families)}), got shape "
                         f"{np.shape(value)}")  # fmt: skip
    if isinstance(value, tuple):
        if len(value) != len(families):
            raise ValueError(f"{name} is one value or a tuple of {len(families)} (one per link family: "
                             f"{', '.join(families)}), got a tuple of {len(value)}")  # fmt: skip
        return tuple(float(check(f"{name}[{k}]", item, unit)) for k, item in enumerate(value))
    return (float(check(name, value, unit)),) * len(families)


def _angle(name, value, unit):
    return v.in_range(name, value, 0.0, np.pi / 2)


#: Bytes per ring at the peak of building a sheet's network (positions, links, laws, rest geometry; measured with
#: tracemalloc: 510 for a square and 700 for a triangular sheet of 100x100, tests/numerics/test_sheet_estimate.py):
#: a sheet that cannot fit is refused before it is built.
_BYTES_PER_SITE = 1000

#: Largest relative difference between a link's length and the spacing 2(R - r) of its rings (plus its static
#: extension) that :meth:`Sheet.from_links` accepts: positions in millimetres are 1000 times too far apart.
LINK_LENGTH_TOLERANCE = 0.5


def _check_link_lengths(positions, pairs, anchor_points, per_site):
    """Refuse links whose length is far from 2(R - r) (positions in mm, not m), or of zero length."""
    far = np.where((pairs[:, 1] == ANCHOR)[:, None], anchor_points, positions[np.where(pairs[:, 1] == ANCHOR, 0,
                                                                                         pairs[:, 1])])  # fmt: skip
    length = np.hypot(*(far - positions[pairs[:, 0]]).T)
    spacing = np.array([per_site[i].spacing for i in pairs[:, 0]])
    ratio = length / spacing
    worst = int(np.argmax(np.abs(np.log(np.maximum(ratio, 1e-300)))))
    if not abs(ratio[worst] - 1.0) <= LINK_LENGTH_TOLERANCE:
        raise ValueError(f"links[{worst}] is {length[worst]:.4g} m long, {ratio[worst]:.3g} times the spacing "
                         f"2(R - r) = {spacing[worst]:.4g} m of its rings: positions are in m (not mm), and "
                         "linked rings lie about 2(R - r) apart")  # fmt: skip


class _Lattice:
    """Positions and forward bonds of a square or triangular lattice of stretched bond lengths ``lengths``."""

    def __init__(self, pattern, rows, cols, lengths):
        self.pattern, self.rows, self.cols = pattern, rows, cols
        if pattern == "square":
            self.bonds = np.array([[lengths[0], 0.0], [0.0, lengths[1]]])
        else:  # b_120 = b_60 - b_0: three lengths make an (oblique, if unequal) triangular lattice
            L0, L60, L120 = lengths
            p = (L0**2 + L60**2 - L120**2) / (2.0 * L0)
            h = np.sqrt(L60**2 - p**2)
            self.bonds = np.array([[L0, 0.0], [p, h], [p - L0, h]])

    def position(self, r, c):
        """Position of site (r, c), rows and columns extended beyond the sheet (its periodic images)."""
        r, c = np.asarray(r), np.asarray(c)
        if self.pattern == "square":
            return c[..., None] * self.bonds[0] + r[..., None] * self.bonds[1]
        return c[..., None] * self.bonds[0] + ((r + 1) // 2)[..., None] * self.bonds[1] + (r // 2)[..., None] * \
            self.bonds[2]  # fmt: skip

    def forward(self, f, r, c):
        """The neighbour of (r, c) along +bond f."""
        if self.pattern == "square":
            return (r, c + 1) if f == 0 else (r + 1, c)
        return [(r, c + 1), (r + 1, c + r % 2), (r + 1, c - 1 + r % 2)][f]

    def backward(self, f, r, c):
        """The site whose forward neighbour along bond f is (r, c)."""
        if self.pattern == "square":
            return (r, c - 1) if f == 0 else (r - 1, c)
        return [(r, c - 1), (r - 1, c - (r - 1) % 2), (r - 1, c + 1 - (r - 1) % 2)][f]


class Sheet:
    """A sheet of interlinked rings: a two-dimensional network and how it is loaded (see the module notes).

    Build it with :meth:`square`, :meth:`triangular` or :meth:`from_links`.  It implements the model
    contract of :mod:`ringchain.numerics.engine.integrate`, so ``simulate(sheet, t_end, impact_velocity=v)`` runs it.

    Attributes
    ----------
    pattern : {"square", "triangular"} or None
        None for a sheet of :meth:`from_links`.
    shape : (int, int) or None
        Rows and columns.
    family_names : tuple of str
        The link families ("x", "y"; "0 deg", "60 deg", "120 deg"; "link" for :meth:`from_links`).
    link_family : ndarray of int, shape (n_links,)
        The family of each link (an index into ``family_names``).
    K, n : ndarray, shape (n_links,)
        Each link's power law, N/m^n and exponent (Eq. (4)).
    m, m_gravity : float or ndarray
        Inertial mass of a ring (m_eff) and the mass gravity acts on (m0 for a hanging sheet, 0 for a
        sheet lying flat), kg.
    hanging : bool
    boundary : str
        "free" or "periodic" sides of a hanging sheet; "clamped" or "periodic" edges of a pretensioned one.
    pretension : tuple of float or None
        Static tension of each family, N (None for a hanging sheet).
    static_tension_links : ndarray or None
        Static tension of each link of a pretensioned sheet, N.
    struck_sites : ndarray of int
        Sites the impact sets moving.
    """

    def __init__(self, network, *, family, family_names, K, n, m, m_gravity, pattern=None, shape=None,
                 hanging=False, boundary="clamped", pretension=None, tensions=None, support_links=None,
                 edges=None, ring=None, m_eff_ratio=1.0, gamma=0.0, link_angle=None):  # fmt: skip
        self._network = network
        self.pattern, self.shape = pattern, shape
        self.link_family, self.family_names = family, tuple(family_names)
        self.K, self.n, self.m, self.m_gravity = K, n, m, m_gravity
        self.hanging, self.boundary, self.pretension = hanging, boundary, pretension
        self.static_tension_links = tensions
        self._support = support_links
        self._edges = edges
        self.ring, self.m_eff_ratio, self.gamma, self.link_angle = ring, m_eff_ratio, gamma, link_angle
        self.struck_sites, self._field = np.zeros(0, dtype=np.intp), np.zeros((network.n_sites, 2))

    # -- constructors --------------------------------------------------------------------------------
    @classmethod
    def square(cls, rows, cols, ring, **options) -> Sheet:
        """A square sheet (4-in-1 chain mail) of ``rows`` x ``cols`` identical rings.

        Parameters
        ----------
        rows, cols : int
            Rows (along y, row 0 at the bottom) and columns (along x), at least 2 each (3 along a
            periodic direction).
        ring : Ring
            Geometry and material of every ring; the links are ``ring.spacing`` = 2(R - r) long, just taut.
        model : {"power-law"}, optional
            The lattice model (module notes: why not the dual-spring model).
        angle : float or (float, float), optional
            Angle between the planes of two linked rings, rad: one for every link or (x, y) per family;
            default ``ring.angle``.  The vertical links of a hanging sheet default to the ring's angle, as
            the chain's contacts do.
        m_eff_ratio : float, optional
            Inertial mass over ring mass, m_eff/m0 in (0, 1] (paper Table I); gravity acts on m0.
        hanging : bool, optional
            Hang the sheet from its top edge under gravity (module notes).
        pretension : float or tuple, optional
            Static tension of every link, N, or (T_x, T_y) per family (a sheet lying flat; default 0: every
            link just taut and unloaded).  Not with ``hanging``.
        boundary : str, optional
            A hanging sheet's sides, "free" (default) or "periodic"; a pretensioned sheet's edges, "clamped"
            (default) or "periodic".
        gamma : float, optional
            Contact dashpot, N s/m, inside each contact's bracket (Eq. (7)).
        struck : str, sequence of int or array_like, optional
            What the impact sets moving (module notes); default "bottom" (nothing, for a sheet periodic along
            y, which has no bottom edge: strike sites with ``impact_direction`` or give a velocity field).
        impact_direction : float or (float, float), optional
            Direction of the struck sites' velocity, rad from x or a vector; default the outward normal of
            their edge.
        window : (float, float), optional
            Force window of the power-law fit, N (Eq. (4)).

        Examples
        --------
        >>> ring = Ring.from_aspect_ratio(9.0)
        >>> sheet = Sheet.square(3, 4, ring, hanging=True)
        >>> sheet.n_sites, sheet.n_links  # 3 x 3 horizontal, 2 x 4 vertical and 4 to the support
        (12, 21)
        >>> sheet.site(2, 1), sheet.edge("bottom").tolist()
        (9, [0, 1, 2, 3])
        """
        return cls._grid("square", rows, cols, ring, **options)

    @classmethod
    def triangular(cls, rows, cols, ring, **options) -> Sheet:
        """A triangular sheet (6-in-1 chain mail) of ``rows`` x ``cols`` identical rings.

        Rows are a sqrt(3)/2 apart, odd rows shifted by a/2 along x; each site is linked along 0, 60 and
        120 degrees.  Options as :meth:`square`, with ``angle`` and ``pretension`` per family given as
        (0 deg, 60 deg, 120 deg) tuples.  A hanging triangular sheet needs ``boundary="periodic"`` sides; a
        periodic pretensioned one an even number of rows.

        Examples
        --------
        >>> sheet = Sheet.triangular(4, 5, Ring.from_aspect_ratio(9.0), pretension=2.0, boundary="periodic")
        >>> sheet.n_links == 3 * sheet.n_sites  # every site three links forward, wrapping around
        True
        """
        return cls._grid("triangular", rows, cols, ring, **options)

    @classmethod
    def _grid(cls, pattern, rows, cols, ring, *, model="power-law", angle=None, m_eff_ratio=1.0, hanging=False,
              pretension=None, boundary=None, gamma=0.0, struck=None, impact_direction=None,
              window=DEFAULT_FORCE_WINDOW):  # fmt: skip
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        ring.check_chain()
        _model(model)
        rows, cols = v.count("rows", rows, 2), v.count("cols", cols, 2)
        check_model_size(rows * cols, _BYTES_PER_SITE, f"the {rows}x{cols} sheet's network")
        hanging = v.flag("hanging", hanging)
        names = FAMILY_NAMES[pattern]
        ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
        gamma = float(v.nonnegative("gamma", gamma, "N s/m"))
        if hanging:
            boundary = v.choice("boundary", "free" if boundary is None else boundary, ("free", "periodic"))
            if pretension is not None and np.any(np.asarray(pretension, dtype=object) != 0):
                raise ValueError("a hanging sheet is loaded by its weight: give hanging=True or a pretension, not both")
            if pattern == "triangular" and boundary == "free":
                raise ValueError(
                    "a hanging triangular sheet needs boundary='periodic' sides: a free edge site hangs from a single "
                    "inclined link, whose sideways pull nothing balances (there is no small-displacement equilibrium)"
                )
        else:
            boundary = v.choice("boundary", "clamped" if boundary is None else boundary, ("clamped", "periodic"))
        angles = _per_family("angle", ring.angle if angle is None else angle, names, _angle, "rad")
        laws = [contact_law(ring, ring, a_f, window) for a_f in angles]
        K_f, n_f = np.array([k for k, _ in laws]), np.array([n for _, n in laws])
        tensions = None if hanging else _per_family("pretension", 0.0 if pretension is None else pretension, names,
                                                    v.nonnegative, "N")  # fmt: skip
        stretch = np.zeros(len(names)) if hanging else np.array(
            [PowerLaw(k, n).static_extension(t) for k, n, t in zip(K_f, n_f, tensions, strict=True)])  # fmt: skip
        a0 = ring.spacing
        wrap_x = boundary == "periodic"
        wrap_y = boundary == "periodic" and not hanging
        for name, count, wraps in (("cols", cols, wrap_x), ("rows", rows, wrap_y)):
            if wraps and count < 3:
                raise ValueError(f"a periodic direction needs at least 3 sites along it, got {name} = {count}")
        if pattern == "triangular" and wrap_y and rows % 2:
            raise ValueError(f"a triangular sheet periodic along y needs an even number of rows, got {rows}")
        lattice = _Lattice(pattern, rows, cols, a0 + stretch)
        r, c = np.divmod(np.arange(rows * cols), cols)
        positions = lattice.position(r, c)
        i, j, fam, anchors, shifts, support = [], [], [], [], [], []

        def add(sites, far, f, anchor, shift, to_support=False):
            i.append(sites), j.append(far), fam.append(np.full(sites.size, f))
            anchors.append(anchor), shifts.append(shift), support.append(np.full(sites.size, to_support))

        for f in range(len(names)):
            for forward in (True, False):
                r2, c2 = (lattice.forward if forward else lattice.backward)(f, r, c)
                inside = (r2 >= 0) & (r2 < rows) & (c2 >= 0) & (c2 < cols)
                wrapped = ~inside & ((r2 >= 0) & (r2 < rows) | wrap_y) & ((c2 >= 0) & (c2 < cols) | wrap_x)
                image = lattice.position(r2, c2)
                if forward:
                    keep = inside | wrapped
                    home = lattice.position(r2 % rows, c2 % cols)
                    add(np.flatnonzero(keep), ((r2 % rows) * cols + c2 % cols)[keep], f, np.zeros((keep.sum(), 2)),
                        (image - home)[keep])  # fmt: skip
                # The frame of a clamped sheet, the support of a hanging one: fixed points where the missing
                # neighbours would be (forward and backward for the frame, forward off the top for the support).
                missing = ~inside & ~wrapped
                top = (r2 >= rows) if forward else np.zeros_like(missing)
                fixed = missing & ((not hanging and boundary == "clamped") | (hanging & top))
                add(np.flatnonzero(fixed), np.full(fixed.sum(), ANCHOR), f, image[fixed], np.zeros((fixed.sum(), 2)),
                    hanging)  # fmt: skip
        i, j, fam = np.concatenate(i), np.concatenate(j), np.concatenate(fam)
        anchors, shifts, support = np.concatenate(anchors), np.concatenate(shifts), np.concatenate(support)
        m0 = ring.mass
        law = PowerLaw(K_f[fam], n_f[fam], gamma)
        links = Links(i, j, law, anchor=anchors, shift=shifts, prestretch=stretch[fam])
        S = rows * cols
        network = Network(np.full(S, ratio * m0), [links], weight_mass=np.full(S, m0 if hanging else 0.0), dim=2,
                          positions=positions)  # fmt: skip
        edges = {"bottom": np.flatnonzero(r == 0), "top": np.flatnonzero(r == rows - 1),
                 "left": np.flatnonzero(c == 0), "right": np.flatnonzero(c == cols - 1)}  # fmt: skip
        if struck is None:
            struck = () if wrap_y else "bottom"
        sheet = cls(network, family=fam, family_names=names, K=K_f[fam], n=n_f[fam], m=ratio * m0,
                    m_gravity=m0 if hanging else 0.0, pattern=pattern, shape=(rows, cols), hanging=hanging,
                    boundary=boundary, pretension=tensions, support_links=np.flatnonzero(support),
                    tensions=None if hanging else np.asarray(tensions)[fam], edges=edges, ring=ring,
                    m_eff_ratio=ratio, gamma=gamma, link_angle=np.asarray(angles)[fam])  # fmt: skip
        return sheet.struck_at(struck, impact_direction)

    @classmethod
    def from_links(cls, positions, links, rings, *, tension=0.0, anchors=None, angle=None, m_eff_ratio=1.0,
                   gamma=0.0, struck=(), impact_direction=None, window=DEFAULT_FORCE_WINDOW) -> Sheet:  # fmt: skip
        """A sheet of any layout: rings at ``positions``, linked as ``links`` say, lying flat and pretensioned.

        Parameters
        ----------
        positions : array_like, shape (n_sites, 2)
            Ring centres in the static state, m.
        links : array_like of int, shape (n_links, 2)
            The two sites of each link; a second site -1 (``ANCHOR``) ties the first to a fixed point
            (``anchors``).
        rings : Ring or sequence of Ring
            One ring for every site, or one per site.
        tension : float or array_like, optional
            Static tension of each link, N (default 0: every link just taut); the tensions must balance at
            every site (checked: a ValueError names the first site where they do not).
        anchors : array_like, shape (n_links, 2), optional
            Fixed points of the anchored links, m (rows of the other links are ignored).
        angle : float or array_like, optional
            Angle between the planes of the two rings of each link, rad; default the first ring's angle.
        m_eff_ratio, gamma, struck, impact_direction, window
            As in :meth:`square` (``struck`` default: no site).

        Examples
        --------
        >>> ring = Ring.from_aspect_ratio(9.0)
        >>> a = ring.spacing
        >>> triangle = Sheet.from_links([[0, 0], [a, 0], [a / 2, a * 3**0.5 / 2]], [[0, 1], [1, 2], [2, 0]], ring)
        >>> triangle.n_links, triangle.family_names
        (3, ('link',))
        """
        positions = v.as_float("positions", positions)
        if positions.ndim != 2 or positions.shape[1] != 2 or positions.shape[0] < 2:
            raise ValueError(f"positions must have shape (n_sites, 2) with at least 2 sites, got {positions.shape}")
        S = positions.shape[0]
        pairs = np.asarray(links)
        if pairs.ndim != 2 or pairs.shape[1] != 2 or pairs.dtype.kind not in "iu" or pairs.shape[0] < 1:
            raise ValueError(f"links must be an integer array of site pairs, shape (n_links, 2), got {pairs.shape}")
        L = pairs.shape[0]
        bad = np.flatnonzero((pairs[:, 0] < 0) | (pairs[:, 0] >= S) | (pairs[:, 1] < ANCHOR) | (pairs[:, 1] >= S))
        if bad.size:
            raise ValueError(f"links[{bad[0]}] = {pairs[bad[0]].tolist()} names a site outside 0..{S - 1} (-1: a fixed "
                             "point)")  # fmt: skip
        same = np.flatnonzero(pairs[:, 0] == pairs[:, 1])
        if same.size:
            raise ValueError(f"links[{same[0]}] = {pairs[same[0]].tolist()} joins a site to itself")
        per_site = [rings] * S if isinstance(rings, Ring) else list(rings)
        if len(per_site) != S or not all(isinstance(ring, Ring) for ring in per_site):
            raise ValueError(f"rings must be one Ring or {S} Rings (one per site)")
        anchored = pairs[:, 1] == ANCHOR
        if np.any(anchored) and anchors is None:
            raise ValueError("anchored links (second site -1) need their fixed points: give anchors")
        anchor_points = np.zeros((L, 2)) if anchors is None else np.broadcast_to(v.as_float("anchors", anchors),
                                                                                 (L, 2))  # fmt: skip
        _check_link_lengths(positions, pairs, anchor_points, per_site)
        angles = np.broadcast_to(v.in_range("angle", per_site[0].angle if angle is None else angle, 0.0, np.pi / 2),
                                 (L,))  # fmt: skip
        laws = {}
        for k, (a_, b_) in enumerate(pairs):
            key = (per_site[a_], per_site[a_ if b_ == ANCHOR else b_], float(angles[k]))
            if key not in laws:
                laws[key] = contact_law(*key, window)
        K = np.array([laws[(per_site[a_], per_site[a_ if b_ == ANCHOR else b_], float(angles[k]))][0]
                      for k, (a_, b_) in enumerate(pairs)])  # fmt: skip
        n = np.array([laws[(per_site[a_], per_site[a_ if b_ == ANCHOR else b_], float(angles[k]))][1]
                      for k, (a_, b_) in enumerate(pairs)])  # fmt: skip
        T = np.broadcast_to(v.nonnegative("tension", tension, "N"), (L,)).astype(float)
        law = PowerLaw(K, n, float(v.nonnegative("gamma", gamma, "N s/m")))
        stretch = PowerLaw(K, n).static_extension(T)
        ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
        m0 = np.array([ring.mass for ring in per_site])
        network = Network(ratio * m0, [Links(pairs[:, 0], pairs[:, 1], law, anchor=anchor_points, prestretch=stretch)],
                          weight_mass=np.zeros(S), dim=2, positions=positions)  # fmt: skip
        residual = np.abs(network.accelerations(np.zeros(2 * S), g=0.0).reshape(S, 2)) * network.mass[:, None]
        worst = int(np.argmax(residual.max(axis=1)))
        if residual[worst].max() > 1e-9 * max(float(T.max()), 1e-300):  # rounding of sums of tensions
            raise ValueError(f"the link tensions do not balance at site {worst} (net force {residual[worst].max():.3g} "
                             "N): give tensions in equilibrium (a pretensioned sheet's static state)")  # fmt: skip
        lo, hi = positions.min(axis=0), positions.max(axis=0)
        tol = 1e-9 * float(np.max(hi - lo))
        edges = {"bottom": np.flatnonzero(positions[:, 1] <= lo[1] + tol),
                 "top": np.flatnonzero(positions[:, 1] >= hi[1] - tol),
                 "left": np.flatnonzero(positions[:, 0] <= lo[0] + tol),
                 "right": np.flatnonzero(positions[:, 0] >= hi[0] - tol)}  # fmt: skip
        uniform = float(ratio * m0[0]) if np.ptp(m0) == 0 else ratio * m0
        sheet = cls(network, family=np.zeros(L, dtype=np.intp), family_names=("link",), K=K, n=n, m=uniform,
                    m_gravity=0.0, boundary="clamped", pretension=None, tensions=T, edges=edges,
                    ring=per_site[0] if all(ring == per_site[0] for ring in per_site) else None, m_eff_ratio=ratio,
                    gamma=law.gamma, link_angle=np.array(angles, dtype=float))  # fmt: skip
        return sheet.struck_at(struck, impact_direction)

    @classmethod
    def from_run(cls, run) -> Sheet:
        """The sheet that made a run, rebuilt from its file (:meth:`SheetSimulation.to_netcdf`).

        Parameters
        ----------
        run : xarray.Dataset or str or path
            What :func:`~ringchain.numerics.read_sheet_run` returns, or the file.

        Returns
        -------
        Sheet
            The same network (masses, links, laws, rest geometry), loads and impact field:
            ``simulate(Sheet.from_run(run), **sheet_run_options(run))`` gives the run's numbers again.
        """
        from .sheet_runs import EDGE_NAMES, read_sheet_run

        ds = run if hasattr(run, "attrs") else read_sheet_run(run)
        attrs = ds.attrs

        def values(name):
            return np.asarray(ds[name].values)

        K, n, gamma = values("link_K").astype(float), values("link_n").astype(float), float(attrs["gamma_N_s_m"])
        links = Links(values("network_link_i").astype(np.intp), values("network_link_j").astype(np.intp),
                      PowerLaw(K, n, gamma), anchor=values("link_anchor"), shift=values("link_shift"),
                      prestretch=values("link_prestretch"))  # fmt: skip
        mass, weight = values("site_mass").astype(float), values("site_weight_mass").astype(float)
        network = Network(mass, [links], weight_mass=weight, dim=2, positions=values("site_position"))
        pattern = None if attrs["pattern"] == "links" else str(attrs["pattern"])
        hanging = bool(attrs["hanging"])
        tension = values("link_static_tension").astype(float)
        ring = None  # descriptive only: the network above carries every number the run used
        if "R_m" in attrs:
            mat = MATERIALS.get(str(attrs["material"]))
            if mat is not None and (mat.E, mat.nu, mat.rho) == (attrs["E_Pa"], attrs["nu"], attrs["rho_kg_m3"]):
                ring = Ring(float(attrs["R_m"]), float(attrs["r_m"]), material=mat,
                            angle=float(attrs["ring_angle_rad"]), thin=bool(attrs["thin"]))  # fmt: skip
        pretension = None if hanging or pattern is None else tuple(np.atleast_1d(attrs.get("pretension_N", 0.0)))
        sheet = cls(network, family=values("network_link_family").astype(np.intp),
                    family_names=tuple(str(attrs["families"]).split(", ")), K=K, n=n,
                    m=float(mass[0]) if np.ptp(mass) == 0 else mass, m_gravity=float(np.max(weight)), pattern=pattern,
                    shape=(int(attrs["rows"]), int(attrs["cols"])) if "rows" in attrs else None, hanging=hanging,
                    boundary=str(attrs["boundary"]), pretension=pretension, tensions=None if hanging else tension,
                    support_links=np.atleast_1d(attrs["support_links"]).astype(np.intp),
                    edges={name: np.atleast_1d(attrs[f"edge_{name}"]).astype(np.intp) for name in EDGE_NAMES},
                    ring=ring, m_eff_ratio=float(attrs["m_eff_ratio"]), gamma=gamma,
                    link_angle=values("link_angle").astype(float))  # fmt: skip
        return sheet.struck_at(values("impact_field").astype(float))

    # -- the layout ----------------------------------------------------------------------------------
    def network(self) -> Network:
        """The two-dimensional network the engine integrates (one site per ring, 2 components)."""
        return self._network

    @property
    def n_sites(self) -> int:
        return self._network.n_sites

    @property
    def n_links(self) -> int:
        return self._network.n_links

    @property
    def positions(self) -> np.ndarray:
        """Rest positions of the ring centres, m, shape (n_sites, 2) (module notes: what they are)."""
        return self._network.positions

    @property
    def links(self) -> np.ndarray:
        """The two sites of every link, shape (n_links, 2); ``-1`` (``ANCHOR``) where the far end is fixed."""
        return np.stack([self._network.i, self._network.j], axis=-1)

    @property
    def support_links(self) -> np.ndarray:
        """Links from the top row of a hanging sheet to its support (empty for a sheet lying flat)."""
        return np.zeros(0, dtype=np.intp) if self._support is None else self._support

    @functools.cached_property
    def link_midpoints(self) -> np.ndarray:
        """Midpoint of every link at rest, m, shape (n_links, 2) (for maps of link forces)."""
        net = self._network
        return net.positions[net.i] + 0.5 * net.rest_vectors

    def site(self, row, col) -> int:
        """Index of the site at (row, col) of a square or triangular sheet (row 0 at the bottom)."""
        if self.shape is None:
            raise ValueError("a sheet of from_links has no rows and columns; its sites are numbered as given")
        rows, cols = self.shape
        row, col = v.integer("row", row), v.integer("col", col)
        if not (0 <= row < rows and 0 <= col < cols):
            raise ValueError(f"site ({row}, {col}) is not in a sheet of {rows} rows and {cols} columns")
        return row * cols + col

    def edge(self, name: str) -> np.ndarray:
        """Sites of an edge, ``"bottom"``, ``"top"``, ``"left"`` or ``"right"`` (sorted)."""
        return self._edges[v.choice("edge", name, tuple(EDGES))].copy()

    def link_sites(self, links) -> np.ndarray:
        """The sites (sorted) whose states the forces of ``links`` need: record them to read those forces."""
        links = np.atleast_1d(np.asarray(links))
        if links.dtype.kind not in "iu" or np.any((links < 0) | (links >= self.n_links)):
            raise ValueError(f"links must be link indices in 0..{self.n_links - 1}")
        ends = np.concatenate([self._network.i[links], self._network.j[links]])
        return np.unique(ends[ends != ANCHOR])

    def struck_at(self, struck, impact_direction=None) -> Sheet:
        """The same sheet struck elsewhere (``struck`` and ``impact_direction`` as in :meth:`square`)."""
        S = self.n_sites
        field = np.zeros((S, 2))
        if isinstance(struck, str):
            self._check_edge(struck)
            sites = self.edge(struck)
            if impact_direction is None:
                impact_direction = EDGES[struck]
        else:
            array = np.asarray(struck)
            if array.ndim == 2:
                field = np.array(v.as_float("struck (a velocity field)", array), dtype=float)
                if field.shape != (S, 2):
                    raise ValueError(f"a velocity field must have shape (n_sites, 2) = ({S}, 2), got {field.shape}")
                out = copy.copy(self)
                out.struck_sites, out._field = np.flatnonzero(np.any(field != 0, axis=1)), field
                return out
            sites = np.unique(np.atleast_1d(array).astype(np.intp)) if array.size else np.zeros(0, dtype=np.intp)
            if array.size and (array.dtype.kind not in "iu" or np.any((sites < 0) | (sites >= S))):
                raise ValueError(f"struck sites must be site indices in 0..{S - 1} (sheet.site(row, col)), got "
                                 f"{struck!r}")  # fmt: skip
            if impact_direction is None and sites.size:
                on = [name for name in EDGES if np.all(np.isin(sites, self._edges[name]))]
                if not on:
                    raise ValueError("the struck sites lie on no single edge: give impact_direction (rad, or a vector)")
                if len(on) > 1:
                    raise ValueError(f"the struck sites lie on the {' and '.join(on)} edges (a corner): give "
                                     "impact_direction (rad, or a vector)")  # fmt: skip
                self._check_edge(on[0])
                impact_direction = EDGES[on[0]]
        if sites.size:
            direction = np.asarray(v.as_float("impact_direction", impact_direction), dtype=float)
            if direction.ndim == 0:
                if not abs(float(direction)) <= 2 * np.pi:
                    raise ValueError(f"impact_direction is an angle in rad, at most 2 pi in size, got "
                                     f"{float(direction):g} (degrees? give np.radians of them)")  # fmt: skip
                direction = np.array([np.cos(direction), np.sin(direction)])
            if direction.shape != (2,) or not np.any(direction):
                raise ValueError(f"impact_direction must be an angle (rad) or a non-zero 2-vector, got {direction!r}")
            field[sites] = direction / np.hypot(*direction)
        out = copy.copy(self)
        out.struck_sites, out._field = sites, field
        return out

    def _check_edge(self, name):
        """Refuse an edge a periodic direction joins to the opposite one (it has no outward normal)."""
        wraps = self.boundary == "periodic" and (name in ("left", "right") or not self.hanging)
        if wraps:
            lines = "columns" if name in ("left", "right") else "rows"
            raise ValueError(f"a periodic sheet has no {name} edge (its {lines} "
                             "wrap around, linking it to the opposite one): strike sites with impact_direction (rad), "
                             "or give a velocity field")  # fmt: skip

    @property
    def impact_field(self) -> np.ndarray:
        """Velocity of every site per unit impact speed, shape (n_sites, 2)."""
        return self._field.copy()

    # -- statics -----------------------------------------------------------------------------------
    def static_tension(self, g=STANDARD_GRAVITY, *, lifted=None) -> np.ndarray:
        """Static tension of every link, N: the pretension, or the weight a link of a hanging sheet carries.

        ``lifted`` (sites, hanging sheets): sites held up (the drop protocol), their weight off the sheet.
        """
        if not self.hanging:
            return self.static_tension_links.copy()
        rows, cols = self.shape
        net = self._network
        weights = (g * net.weight_mass).reshape(rows, cols).copy()
        if lifted is not None and np.size(lifted):
            weights.reshape(-1)[np.asarray(lifted)] = 0.0
        tension = np.zeros(self.n_links)
        carried = np.cumsum(weights, axis=0)  # the weight of each column (square) or per site of a row, up to row r
        r_i = net.i // cols
        if self.pattern == "square":
            vertical = self.link_family == 1
            tension[vertical] = carried[r_i[vertical], net.i[vertical] % cols]
            return tension
        if not np.all(np.ptp(carried, axis=1) == 0):
            raise ValueError("a hanging triangular sheet hangs row by row: lift whole rows (struck='bottom')")
        inclined = self.link_family > 0
        # Each site hangs from two inclined links: their vertical pulls T h/l carry half of the row's load each.
        tension[inclined] = self._inclined_tension(carried[:, 0] / 2.0)[r_i[inclined]]
        return tension

    def _inclined_tension(self, half_loads) -> np.ndarray:
        """Tension T of an inclined link (60 or 120 deg) whose vertical pull T h(T)/l(T) is ``half_loads`` (N)."""
        from scipy.optimize import brentq

        inclined = self.link_family == 1
        a0 = float(self._network.spans[self.link_family == 0][0])
        K, n = float(self.K[inclined][0]), float(self.n[inclined][0])
        law = PowerLaw(K, n)

        def pull(T, load):
            length = a0 + law.static_extension(T)
            return T * np.sqrt(length**2 - a0**2 / 4) / length - load

        return np.array([0.0 if load == 0 else brentq(pull, load, 2.0 * load / np.sqrt(3.0) * 1.01, args=(load,),
                                                      xtol=1e-300, rtol=4 * np.finfo(float).eps)
                         for load in half_loads])  # fmt: skip

    def static_state(self, g=STANDARD_GRAVITY, *, lifted=None) -> np.ndarray:
        """Site displacements of the static state, m, shape (n_sites * 2,) (x, y per site).

        Zero for a pretensioned sheet (its rest positions are its static state).  A hanging sheet sags from
        its support: every link at the extension of its :meth:`static_tension`, the horizontal links at
        their unloaded length; the displacement of a site is the sum of the stretches above it (the chain's
        :meth:`~ringchain.numerics.Chain.displacement_from_extension`, column by column).
        """
        x = np.zeros((self.n_sites, 2))
        if not self.hanging or g == 0:
            return x.ravel()
        rows, cols = self.shape
        e = self._network.extension_at(self.static_tension(g, lifted=lifted))
        net = self._network
        if self.pattern == "square":
            vertical = np.flatnonzero(self.link_family == 1)
            column = np.empty((rows, cols))
            column[net.i[vertical] // cols, net.i[vertical] % cols] = e[vertical]
            x[:, 1] = (0.0 - np.cumsum(column[::-1], axis=0)[::-1]).ravel()  # as Chain.displacement_from_extension
            return x.ravel()
        # Triangular: inclined links of row gap r at length a0 + e_r with the horizontal spacing a0/2 unchanged;
        # the gap's height grows by ((a0 + e)^2 - a0^2)/(h + h0) (no cancellation).
        a0 = float(net.spans[self.link_family == 0][0])
        h0 = float(net.spans[self.link_family == 1][0]) * np.sqrt(3.0) / 2.0
        gap = np.zeros(rows)
        inclined = np.flatnonzero(self.link_family == 1)
        gap[net.i[inclined] // cols] = e[inclined]
        rise = (2.0 * a0 + gap) * gap / (np.sqrt((a0 + gap) ** 2 - a0**2 / 4) + h0)
        x[:, 1] = np.repeat(0.0 - np.cumsum(rise[::-1])[::-1], cols)
        return x.ravel()

    # -- the model contract (ringchain.numerics.engine.integrate) ------------------------------------------------
    def dynamics(self) -> Network:
        """What the engine integrates: :meth:`network`."""
        return self._network

    def impact_state(self, speeds, dropped, gravity, g):
        """Displacements and velocities of B runs at t = 0 (module notes); ``speeds`` validated (m/s)."""
        if not np.any(self._field) or not np.any(speeds):
            raise ValueError("nothing sets the sheet moving: give struck sites (struck=...; none are struck) and an "
                             "impact_velocity (m/s) or a drop_height (m) above 0, or an initial state"
                             if not np.any(self._field) else
                             "nothing sets the sheet moving: give an impact_velocity (m/s) or a drop_height (m) above "
                             "0, or an initial state")  # fmt: skip
        if dropped:
            if not self.hanging:
                raise ValueError("a drop (drop_height) needs a hanging sheet: give impact_velocity to a sheet lying "
                                 "flat")  # fmt: skip
            if not np.all(np.isin(self.struck_sites, self._edges["bottom"])):
                raise ValueError("a drop lifts sites of the bottom row of a hanging sheet: strike those")
        if self.hanging and not gravity:
            x = np.zeros(2 * self.n_sites)  # without gravity the sheet starts just taut
        else:
            x = self.static_state(g, lifted=self.struck_sites if dropped else None)
        B = speeds.size
        return np.broadcast_to(x, (B, x.size)).copy(), speeds[:, None] * self._field.ravel()[None, :]

    def recorded(self, rings):
        """The sites to record (one ring per site; validated, sorted) and their coordinates; (None, None) for all."""
        if rings is None:
            return None, None
        values = np.unique(np.atleast_1d(np.asarray(rings)))
        if values.size == 0 or values.dtype.kind not in "iu" or values[0] < 0 or values[-1] >= self.n_sites:
            raise ValueError(f"rings must name sites of the sheet (0..{self.n_sites - 1}; one ring per site), got "
                             f"{rings!r}")  # fmt: skip
        return tuple(int(s) for s in values), (values[:, None] * 2 + np.arange(2)).ravel()

    def result(self, *, rings=None, impact_velocity=None, drop_height=None, **record) -> SheetBatch:
        """The record of a batch of runs of this sheet (:class:`~ringchain.numerics.SheetBatch`)."""
        sites = None if rings is None else np.asarray(rings, dtype=np.intp)
        return SheetBatch(network=self._network, sites=sites, sheet=self, impact_velocity=impact_velocity,
                          drop_height=drop_height, **record)  # fmt: skip


def _model(model):
    if model == "dual-spring":
        raise ValueError("a sheet is the power-law model: the dual-spring ring (two half-masses joined by one "
                         "bending spring) has no counterpart where a ring is pulled at 4 or 6 contacts "
                         "(ringchain.numerics.layouts.sheet)")  # fmt: skip
    return v.choice("model", model, SHEET_MODELS)
