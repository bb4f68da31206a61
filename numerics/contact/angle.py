r"""One contact of two interlocked tori at any angle: the closed form where it holds, the numerical contact elsewhere.

- :func:`contact_at_angle` -- the Hertz-or-numerical choice, made once for the package (``ringchain ring`` and
  the paper's angle table use it): the single-ellipse Hertz contact (paper Eq. (1), App. A) while the contact
  ellipse's long semi-axis at the largest force stays below :data:`~ringchain.numerics.contact.bem.HALF_SPACE_LIMIT`
  of the tube radius, the numerical contact of the exact gap (:func:`~ringchain.numerics.contact_curve`) beyond,
  with K_c continuous across the handover; each in series with the ring's bending (Eqs. (3)-(4)).
- :func:`angle_power_law` -- one angle's row of the paper's Table II from the numerical contact.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from ringchain.theory import DEFAULT_FORCE_WINDOW
from ringchain.theory import _validate as v

from .bem import HALF_SPACE_LIMIT, ContactCurve, HalfSpaceWarning, contact_curve

__all__ = [
    "contact_at_angle",
    "AngleContact",
    "contact_report",
    "ContactReport",
    "angle_power_law",
    "AnglePowerLaw",
    "HERTZ",
    "NUMERICAL",
]


# -- what the angle table needs ------------------------------------------------------------------------
@dataclass(frozen=True)
class AnglePowerLaw:
    """One contact angle's row of the paper's Table II from the numerical contact (:func:`angle_power_law`).

    Attributes: ``angle`` (rad), ``K_c`` (effective Hertz constant of the contact alone,
    N/m^1.5, F = K_c delta^1.5 fitted over the window), ``K`` (N/m^n) and ``n`` of the
    contact in series with bending (Eqs. (3)-(4)), ``n_patches`` (at the window's lower
    end), ``max_extent_over_r`` (largest contact half-length over r), ``curve`` (the
    :class:`ContactCurve` of the contact alone).
    """

    angle: float
    K_c: float
    K: float
    n: float
    n_patches: int
    max_extent_over_r: float
    curve: ContactCurve
    K_b: float

    def _at(self, F, values):
        F = v.positive("F", F, "N")
        series = self.curve.series(self.K_b)
        if np.any(F < series.force[0]) or np.any(F > series.force[-1]):
            raise ValueError(f"F must lie within the computed forces [{series.force[0]:g}, {series.force[-1]:g}] N")
        return np.exp(np.interp(np.log(F), np.log(series.force), np.log(values(series))))

    def extension(self, F):
        """Extension (m) of contact and bending in series at force F (N), interpolated in log-log."""
        return self._at(F, lambda series: series.delta)

    def local_exponent(self, F):
        """Local exponent d ln F/d ln delta of contact and bending in series at force F (N)."""
        return self._at(F, lambda series: series.local_exponent)


def angle_power_law(R, r, E, nu, angle, K_b, window=DEFAULT_FORCE_WINDOW, n_forces=15) -> AnglePowerLaw:
    """Table II's K and n at any contact angle from the numerical contact in series with bending.

    Parameters
    ----------
    R, r, E, nu, angle : float
        As :func:`contact_curve` (m, Pa, rad).
    K_b : float
        Bending stiffness of one ring, N/m (:func:`ringchain.theory.bending_stiffness`).
    window : (float, float), optional
        Force window of the fit, N (default 1 N to 100 N, as :func:`ringchain.theory.fit_power_law`).
    n_forces : int, optional
        Forces of the curve, log-spaced over the window (default 15).

    Returns
    -------
    AnglePowerLaw
        The row; the half-space warning of :func:`contact_curve` is recorded in
        ``max_extent_over_r`` rather than raised.
    """
    F_min, F_max = (float(f) for f in window)
    forces = np.geomspace(F_min, F_max, int(n_forces))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", HalfSpaceWarning)
        curve = contact_curve(R, r, E, nu, angle, forces)
    K_c, _ = curve.fit(window, n=1.5)
    K, n = curve.series(K_b).fit(window)
    return AnglePowerLaw(
        angle=float(angle),
        K_c=K_c,
        K=K,
        n=n,
        n_patches=int(curve.n_patches[0]),
        max_extent_over_r=float(curve.extent.max() / curve.r),
        curve=curve,
        K_b=float(K_b),
    )


# -- one contact at any angle: the closed form where it holds, the numerical contact elsewhere ----------------
HERTZ, NUMERICAL = "hertz", "numerical"


@dataclass(frozen=True)
class AngleContact:
    """The contact of two interlocked tori at one angle, from :func:`contact_at_angle`.

    Attributes
    ----------
    angle : float
        Contact angle, rad.
    method : {"hertz", "numerical"}
        The single-ellipse Hertz contact (paper Eq. (1), App. A) or the numerical contact of the exact
        gap (:func:`contact_curve`).
    K_c : float
        Contact stiffness, N/m^1.5: Hertz's, or F = K_c delta^1.5 fitted over the window (numerical).
    K, n : float
        The power law F = K delta^n (N/m^n) of contact and bending in series, fitted over the window
        (Eqs. (3)-(4)).
    window : (float, float)
        The force window of the fits, N.
    K_b : float
        Bending stiffness of one ring, N/m.
    extent_over_r : float
        Largest half-length of the contact over the tube radius, at the largest force computed: the
        long semi-axis of Hertz's ellipse, or the largest patch of the numerical contact.
    limit_force : float
        Force, N, at which the contact reaches :data:`HALF_SPACE_LIMIT` r (interpolated in log-log
        between computed forces; beyond them, extrapolated as F^(1/3), the Hertz growth).
    handover : float or None
        Angle, rad, above which Hertz's ellipse stays within :data:`HALF_SPACE_LIMIT` r up to the
        largest force, so that the closed form is used; None if it does at no angle.
    n_patches : int
        Contact regions at the smallest force.
    curve : ContactCurve or None
        The numerical contact alone (None for the Hertz contact).
    """

    angle: float
    method: str
    K_c: float
    K: float
    n: float
    window: tuple
    K_b: float
    extent_over_r: float
    limit_force: float
    handover: float | None
    n_patches: int
    curve: ContactCurve | None = None

    @property
    def within_half_space(self) -> bool:
        """Whether the contact stays within :data:`HALF_SPACE_LIMIT` r at every force computed."""
        return self.extent_over_r <= HALF_SPACE_LIMIT

    def _numerical(self, F, values):
        F = v.positive("F", F, "N")
        series = self.curve.series(self.K_b)
        if np.any(F < series.force[0]) or np.any(F > series.force[-1]):
            raise ValueError(f"F must lie within the computed forces [{series.force[0]:g}, {series.force[-1]:g}] N")
        return np.exp(np.interp(np.log(F), np.log(series.force), np.log(values(series))))

    def extension(self, F):
        """Extension (m) of contact and bending in series at force F (N), Eq. (3)."""
        if self.curve is None:
            from ringchain.theory import series_displacement

            return series_displacement(F, K_c=self.K_c, K_b=self.K_b)
        return self._numerical(F, lambda series: series.delta)

    def local_exponent(self, F):
        """Local exponent d ln F/d ln delta of contact and bending in series at force F (N)."""
        if self.curve is None:
            from ringchain.theory import local_exponent

            return local_exponent(F, K_c=self.K_c, K_b=self.K_b)
        return self._numerical(F, lambda series: series.local_exponent)


def _hertz_semi_axis(R, r, E, nu, angle, force):
    from ringchain.theory import contact_semi_axes

    return float(contact_semi_axes(R, r, E, nu, angle, F=force)[0])


def _handover(R, r, E, nu, force):
    """The angle (rad) above which Hertz's long semi-axis at ``force`` stays within the half-space limit, or None."""
    from ringchain.theory import minimum_contact_angle
    from scipy.optimize import brentq

    limit = HALF_SPACE_LIMIT * r

    def excess(angle):
        return _hertz_semi_axis(R, r, E, nu, angle, force) / limit - 1.0

    if excess(np.pi / 2) > 0:
        return None
    lowest = float(minimum_contact_angle(R, r))
    step = 1e-9 * (np.pi / 2 - lowest)
    while lowest + step < np.pi / 2:  # the ellipse is a line at theta_min: a point just above it brackets the root
        try:
            above = excess(lowest + step) > 0
        except ValueError:  # within rounding of theta_min, the ellipse is too long to represent
            step *= 10.0
            continue
        if not above:  # within the limit 1e-9 of the range above theta_min: the handover is closer still
            return lowest + step
        return float(brentq(excess, lowest + step, np.pi / 2, xtol=1e-12))
    return None  # pragma: no cover - excess(pi/2) <= 0 was checked


def _limit_force(force, extent, limit):
    """Force at which ``extent`` (rising with ``force``) reaches ``limit``: log-log interpolation, F^(1/3) beyond."""
    extent = np.maximum.accumulate(np.asarray(extent, dtype=float))
    if limit <= extent[0]:
        return float(force[0] * (limit / extent[0]) ** 3)
    if limit >= extent[-1]:
        return float(force[-1] * (limit / extent[-1]) ** 3)
    return float(np.exp(np.interp(np.log(limit), np.log(extent), np.log(force))))


def contact_at_angle(R, r, E, nu, angle, *, K_b, window=DEFAULT_FORCE_WINDOW, forces=(), n_forces=15) -> AngleContact:
    """The contact of two interlocked identical tori at any angle: Hertz's ellipse where it holds, else numerical.

    Parameters
    ----------
    R, r, E, nu, angle : float
        As :func:`contact_curve` (m, Pa, rad).
    K_b : float
        Bending stiffness of one ring, N/m (:func:`ringchain.theory.bending_stiffness`), in series
        with the contact (Eq. (3)).
    window : (float, float), optional
        Force window of the fits, N (default 1 N to 100 N).
    forces : sequence of float, optional
        Further forces, N, at which :meth:`AngleContact.extension` and
        :meth:`AngleContact.local_exponent` will be asked (the numerical contact is computed there
        too, and every force counts for the choice and for the half-space limit).
    n_forces : int, optional
        Forces of the numerical contact, log-spaced over the window (default 15).

    Returns
    -------
    AngleContact
        K_c, K and n over the window, the extension and local exponent at any force computed, the
        method used and the contact's size against its half-space limit.

    Notes
    -----
    The single-ellipse Hertz contact (Eq. (1), App. A, elliptical above 90 deg) is a half-space
    solution: it holds while the ellipse is small against the tube.  Its long semi-axis
    (:func:`ringchain.theory.contact_semi_axes`) grows without bound as the angle falls to
    theta_min = arccos(1 - 2r/R), and with it K_c.  So the closed form is used where that semi-axis,
    at the largest force, stays within :data:`HALF_SPACE_LIMIT` r (above :attr:`AngleContact.handover`),
    and the numerical contact of the exact gap (:func:`contact_curve`, two patches below theta_min)
    everywhere else.  At the handover the two agree to the numerical contact's resolution (measured
    2e-4 in K_c for the paper's ring), so K_c is continuous across it.  Below the handover the
    numerical contact may itself exceed the limit: :attr:`AngleContact.within_half_space` says so,
    and :attr:`AngleContact.limit_force` says up to which force it holds.  A contact that reaches
    round the tube is refused (ValueError).  Beyond the paper (which uses Abaqus below 45 deg).

    Examples
    --------
    >>> import math
    >>> contact = contact_at_angle(22.5e-3, 2.5e-3, 193e9, 0.29, np.radians(60), K_b=3.3e6)
    >>> contact.method, round(math.degrees(contact.handover), 2), contact.within_half_space
    ('hertz', 55.84, True)
    """
    from ringchain.theory import fit_power_law, hertz_stiffness, minimum_contact_angle

    F_lo, F_hi = (float(f) for f in v.positive("window", window, "N"))
    if not F_lo < F_hi:
        raise ValueError(f"the force window needs F_min < F_max, got F_min = {F_lo:g} N and F_max = {F_hi:g} N")
    K_b = float(v.positive("K_b", K_b, "N/m"))
    extra = v.positive("forces", forces, "N").ravel()
    angle = float(v.as_float("angle", angle))
    top = max(F_hi, float(extra.max())) if extra.size else F_hi
    handover = _handover(R, r, E, nu, top)
    if handover is not None and angle > handover and angle > float(minimum_contact_angle(R, r)):
        K_c = float(hertz_stiffness(R, r, E, nu, angle))
        K, n = (float(x) for x in fit_power_law(K_c=K_c, K_b=K_b, F_min=F_lo, F_max=F_hi))
        extent = _hertz_semi_axis(R, r, E, nu, angle, top) / r
        return AngleContact(angle, HERTZ, K_c, K, n, (F_lo, F_hi), K_b, extent,
                            top * (HALF_SPACE_LIMIT / extent) ** 3, handover, 1)  # fmt: skip
    computed = np.union1d(np.geomspace(F_lo, F_hi, int(n_forces)), extra)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", HalfSpaceWarning)  # recorded in the result instead
        curve = contact_curve(R, r, E, nu, angle, computed)
    K_c, _ = curve.fit((F_lo, F_hi), n=1.5)
    K, n = curve.series(K_b).fit((F_lo, F_hi))
    return AngleContact(
        angle=angle,
        method=NUMERICAL,
        K_c=float(K_c),
        K=float(K),
        n=float(n),
        window=(F_lo, F_hi),
        K_b=K_b,
        extent_over_r=float(curve.extent.max() / curve.r),
        limit_force=_limit_force(curve.force, curve.extent, HALF_SPACE_LIMIT * curve.r),
        handover=handover,
        n_patches=int(curve.n_patches[0]),
        curve=curve,
    )


# -- everything about one contact (ringchain ring) --------------------------------------------------------------
@dataclass(frozen=True)
class ContactReport:
    """One ring contact at one angle and one force: statics (Eqs. 1-4) and the solitary wave (Eq. (8)).

    Attributes
    ----------
    ring : Ring
    angle : float
        rad.
    force : float
        N.
    m_eff_ratio : float
    contact : AngleContact
    crossover_force, crossover_exponent : float
        F* = K_b^3/K_c^2 (N) and the local exponent there.
    extension, local_exponent : float
        Extension (m) and local exponent of the series law at ``force`` (Eq. 3).
    wave_speed, wave_width : float
        V_s (m/s, Eq. (8) with m = m_eff_ratio m0) and the support of the compact wave (m) at ``force``.
    warning : str or None
        Why the numbers extrapolate the contact models, if they do (beyond the half-space limit).
    """

    ring: object
    angle: float
    force: float
    m_eff_ratio: float
    contact: AngleContact
    crossover_force: float
    crossover_exponent: float
    extension: float
    local_exponent: float
    wave_speed: float
    wave_width: float
    warning: str | None

    def rows(self) -> list[tuple[str, str]]:
        """(what, value) lines, as ``ringchain ring`` prints them."""
        from ringchain.theory import MIN_CHAIN_ASPECT_RATIO, minimum_contact_angle, si_to_n_per_mm

        ring, contact, F = self.ring, self.contact, self.force
        mat, (F_lo, F_hi) = ring.material, contact.window
        top = max(F_hi, F)
        K, n, K_c = contact.K, contact.n, contact.K_c
        lowest = math.degrees(float(minimum_contact_angle(ring.R, ring.r)))
        aspect = v.distinct(ring.aspect_ratio, MIN_CHAIN_ASPECT_RATIO)
        chain_note = "yes" if ring.can_form_chain else (
            f"no: R/r < {MIN_CHAIN_ASPECT_RATIO:g}, two rings interlock but a chain cannot form")  # fmt: skip
        if contact.method == NUMERICAL:
            patches = "two patches" if contact.n_patches == 2 else "one patch"
            contact_line = (f"K_c, {patches} (BEM, tilt {math.degrees(contact.curve.tilt):.1f} deg)",
                            f"{K_c:.4e} N/m^1.5 (F = K_c delta^1.5 fitted over {F_lo:g}-{F_hi:g} N; contact up to "
                            f"{contact.extent_over_r:.2f} r at {top:g} N)")  # fmt: skip
        else:
            extent = f"ellipse up to {contact.extent_over_r:.3f} r at {top:g} N"
            contact_line = ("K_c, Hertz contact (Eq. 1)", f"{K_c:.4e} N/m^1.5 ({extent})")
        if contact.handover is None:
            hertz_range = f"none within the half-space limit at {top:g} N"
        else:
            hertz_range = f"within the half-space limit up to {top:g} N above {math.degrees(contact.handover):.2f} deg"
        m = self.m_eff_ratio * ring.mass
        return [
            ("geometry", f"R = {ring.R * 1e3:g} mm, r = {ring.r * 1e3:g} mm, R/r = {aspect}"),
            ("material", f"{mat.name}: E = {mat.E / 1e9:g} GPa, nu = {mat.nu:g}, rho = {mat.rho:g} kg/m^3"),
            ("contact angle", f"{math.degrees(self.angle):g} deg (single Hertz contact above {lowest:.2f} deg; "
                              f"{hertz_range})"),
            ("forms a chain", chain_note),
            ("ring mass m0", f"{ring.mass * 1e3:.4g} g"),
            ("spacing a = 2(R - r)", f"{ring.spacing * 1e3:.4g} mm"),
            contact_line,
            ("K_b, ring bending (Eq. 2)", f"{ring.K_b:.4e} N/m" + (" (thin ring)" if ring.thin else "")),
            ("crossover F* = K_b^3/K_c^2", f"{self.crossover_force:.4g} N (local exponent there "
                                           f"{self.crossover_exponent:.4f})"),
            (f"power law over {F_lo:g}-{F_hi:g} N (Eq. 4)",
             f"K = {float(si_to_n_per_mm(K, n=n)):.5g} N/mm^n = {K:.5g} N/m^n, n = {n:.4f}"),
            (f"at F = {F:g} N (Eq. 3)", f"extension {self.extension * 1e6:.4g} um, local exponent "
                                        f"{self.local_exponent:.4f}"),
            (f"solitary wave at F_m = {F:g} N", f"V_s = {self.wave_speed:.4g} m/s (Eq. (8), m = {self.m_eff_ratio:g} "
             f"m0 = {m * 1e3:.4g} g), width {self.wave_width * 1e3:.4g} mm = {self.wave_width / ring.spacing:.3g} a"),
        ]  # fmt: skip


def contact_report(ring, angle, force, *, window=DEFAULT_FORCE_WINDOW, m_eff_ratio=1.0) -> ContactReport:
    """Everything about one contact of ``ring`` s at ``angle`` (rad) and ``force`` (N): ``ringchain ring``.

    The contact at any angle (:func:`contact_at_angle`, its K and n fitted over ``window``), in series with
    the ring's bending (Eqs. 3-4), the crossover force, and the compact wave at ``force`` (Eq. (8)) with the
    inertial mass ``m_eff_ratio`` times the ring's.
    """
    from ringchain.theory import crossover_force, local_exponent, solitary_wave_speed, solitary_wave_width

    force = float(v.positive("force", force, "N"))
    ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
    mat = ring.material
    contact = contact_at_angle(ring.R, ring.r, mat.E, mat.nu, angle, K_b=ring.K_b, window=window, forces=[force])
    K_c, K, n = contact.K_c, contact.K, contact.n
    F_star = float(crossover_force(K_c=K_c, K_b=ring.K_b))
    warning = None
    if not contact.within_half_space:
        top = max(contact.window[1], force)
        warning = (f"the contact reaches {contact.extent_over_r:.2f} r from its centre at {top:g}"
                   f" N, beyond the half-space limit {HALF_SPACE_LIMIT:g} r of both contact models, so K_c, K, n and "
                   "V_s above extrapolate them")  # fmt: skip
    return ContactReport(
        ring=ring, angle=float(angle), force=force, m_eff_ratio=ratio, contact=contact, crossover_force=F_star,
        crossover_exponent=float(local_exponent(F_star, K_c=K_c, K_b=ring.K_b)),
        extension=float(contact.extension(force)), local_exponent=float(contact.local_exponent(force)),
        wave_speed=float(solitary_wave_speed(force, K=K, n=n, m=ratio * ring.mass, a=ring.spacing)),
        wave_width=float(solitary_wave_width(n=n, a=ring.spacing)), warning=warning,
    )  # fmt: skip
