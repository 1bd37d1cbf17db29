#!/usr/bin/python3
"""A second implementation of the imperfect rocking block (issue 41), written from its
statement (dynamics/imperfect_block.hpp's header and docs), not from the C++ code's method:
the geometry by polygon integrals and vectors, the dynamics on the closed-form solution of
expected/spectrum/independent.py (imported, not copied).  Used by this folder's
independent.py.

Geometry.  The perfect block (alpha, p): R = 3 g / (4 p^2) (eq. 4, g = 9.81), half-width
b = R sin alpha, half-height h = R cos alpha, per unit thickness.
- out of plumb phi: the wall is the parallelogram (-b, 0), (b, 0), (b + 2h tan phi, 2h),
  (-b + 2h tan phi, 2h) on a horizontal bed (its top toward +x, the corner theta > 0);
- lean psi: the block and its pivots turned clockwise by psi (its top toward +x): a
  rectangle on a bed inclined by psi;
- setback: the masonry's weight N = rho g A (A the polygon's area) carried at the edge by
  NTC 2018 eq. 7.8.2's rectangular stress block 0.85 fc over a width x_c = N / (0.85 fc);
  the pivot is the block's resultant, x_c / 2 inside each edge; sigma0 = N / (2b).
The area, centroid C and polar moment J about C by Green's theorem over the polygon's
edges (k^2 = J / A); for the corner sigma (+1 at +x, theta > 0) with pivot P_sigma:
  alpha_sigma = the angle of C - P_sigma from the vertical, > 0 when C is inside;
  R_sigma = |C - P_sigma|;  p_sigma^2 = g R_sigma / (k^2 + R_sigma^2) (the moment of the
  weight about the pivot over the moment of inertia about it, per unit mass);
  the restitution onto sigma: the angular momentum about P_sigma just before the impact
  (rotating at omega about P_-sigma: k^2 omega + (C - P_sigma) x v_C, v_C = omega z x
  (C - P_-sigma)) kept through it, over (k^2 + R_sigma^2).

Dynamics, on corner sigma = sgn theta: theta'' = p_sigma^2 (theta + a/g - sigma alpha_sigma)
(linearised eq. 3 with the corner's own alpha and p; independent.Piece solves it exactly
on a sample interval).  At rest the block lifts onto theta > 0 when a/g exceeds alpha_+,
onto theta < 0 when -a/g exceeds alpha_-.  An impact at theta = 0 lands on the other
corner, the angular velocity times the restitution onto it; the block rests when the
rebound is slower than 1e-9 alpha p of the corner landed on, or the impact comes within
1e-6 / max(p_+, p_-) of the previous one (the model's rest rules).  After the record the
free rocking is decided in closed form, with no time limit: on corner sigma it goes over
the top iff sigma theta - alpha_sigma + sigma omega / p_sigma >= 0; otherwise it lands
on the other corner at |omega| = sqrt(omega^2 - p^2 (theta - sigma alpha)^2 + p^2 alpha^2)
times the restitution, and so on, until the speed at theta = 0 is below both corners'
p_sigma alpha_sigma (every rebound is slower: each restitution is below 1).
"""
import importlib.util
import math
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("spectrum_independent",
                                               os.path.join(HERE, "..", "spectrum", "independent.py"))
ind = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ind)

G = 9.81
HALF_PI = ind.HALF_PI
REST_VELOCITY = ind.REST_VELOCITY
MICRO_TIME = ind.MICRO_TIME
DEFAULT_DENSITY = 1800.0


# ---------------------------------------------------------------- geometry

def polygon_moments(vertices):
    """Area, centroid and polar second moment about the centroid of a simple polygon
    (counter-clockwise), by Green's theorem over its edges."""
    A = cx = cy = ixx = iyy = 0.0
    n = len(vertices)
    for i in range(n):
        x0, y0 = vertices[i]
        x1, y1 = vertices[(i + 1) % n]
        c = x0 * y1 - x1 * y0
        A += c / 2
        cx += (x0 + x1) * c / 6
        cy += (y0 + y1) * c / 6
        ixx += (y0 * y0 + y0 * y1 + y1 * y1) * c / 12
        iyy += (x0 * x0 + x0 * x1 + x1 * x1) * c / 12
    cx, cy = cx / A, cy / A
    return A, (cx, cy), ixx + iyy - A * (cx * cx + cy * cy)


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


class Corner:
    __slots__ = ("alpha", "p", "R", "e_onto")

    def __init__(self, alpha, p, R, e_onto):
        self.alpha, self.p, self.R, self.e_onto = alpha, p, R, e_onto


class Geometry:
    """The block (alpha, p) with the imperfections: b, h, sigma0 (Pa), setback (m), k2 and
    the corners plus (theta > 0) and minus."""

    def __init__(self, alpha, p, lean=0.0, out_of_plumb=0.0, fc=0.0, density=DEFAULT_DENSITY):
        R0 = 3 * G / (4 * p * p)
        b, h = R0 * math.sin(alpha), R0 * math.cos(alpha)
        shift = 2 * h * math.tan(out_of_plumb)
        A, C, J = polygon_moments([(-b, 0.0), (b, 0.0), (b + shift, 2 * h), (-b + shift, 2 * h)])
        self.b, self.h, self.k2 = b, h, J / A
        self.sigma0 = self.setback = 0.0
        if fc > 0:
            N = density * G * A
            self.sigma0 = N / (2 * b)
            if not self.sigma0 < 0.85 * fc:
                raise ValueError(f"alpha {alpha} p {p}: the weight crushes the base")
            self.setback = N / (0.85 * fc) / 2
        c, s = math.cos(lean), math.sin(lean)
        turn = lambda v: (v[0] * c + v[1] * s, -v[0] * s + v[1] * c)  # clockwise by the lean
        C = turn(C)
        P = {+1: turn((b - self.setback, 0.0)), -1: turn((-(b - self.setback), 0.0))}
        r = {sg: (C[0] - P[sg][0], C[1] - P[sg][1]) for sg in (1, -1)}
        corners = {}
        for sg in (1, -1):
            R = math.hypot(*r[sg])
            alpha_s = math.atan2(-sg * r[sg][0], r[sg][1])
            p_s = math.sqrt(G * R / (self.k2 + R * R))
            v_c = (-r[-sg][1], r[-sg][0])  # z x (C - P_-sigma), at omega = 1
            e = (self.k2 + cross(r[sg], v_c)) / (self.k2 + R * R)
            corners[sg] = Corner(alpha_s, p_s, R, e)
        self.plus, self.minus = corners[1], corners[-1]


# ---------------------------------------------------------------- one block on a record

class ImperfectBlock:
    """One run of the imperfect block: its state and its rules."""

    __slots__ = ("c", "p_max", "th", "om", "sg", "resting", "fallen", "t_last", "impacts")

    def __init__(self, geometry):
        self.c = {1: geometry.plus, -1: geometry.minus}
        self.p_max = max(geometry.plus.p, geometry.minus.p)
        self.th = self.om = 0.0
        self.sg = 1.0
        self.resting, self.fallen = True, False
        self.t_last = None
        self.impacts = 0

    def corner(self):
        return self.c[1 if self.sg > 0 else -1]

    def impact(self, t, om_i):
        self.impacts += 1
        micro = self.t_last is not None and t - self.t_last < MICRO_TIME / self.p_max
        self.t_last = t
        self.th = 0.0
        self.sg = -self.sg
        k = self.corner()
        self.om = k.e_onto * om_i
        if micro or abs(self.om) < REST_VELOCITY * k.alpha * k.p:
            self.om = 0.0
            self.resting = True

    def interval(self, k, dt, ak, ak1):
        """Sample interval k from the state at its start, with all its events."""
        c1 = (ak1 - ak) / dt
        t0, te = k * dt, (k + 1) * dt
        t = t0
        up, down = self.c[1].alpha, self.c[-1].alpha
        for _ in range(10 ** 7):
            if not (t < te and not self.fallen):
                return
            if self.resting:
                a_here = ak + c1 * (t - t0)
                # Beyond a threshold by rounding alone and falling back, the block would rise by
                # (a - alpha)^2 / c1 ~ 1e-40 and land at once (the rest rule): it stays at rest.
                # Lifting it there would land it within rounding at the same t, for ever.
                if (a_here > up and (c1 >= 0 or a_here - up > 1e-14 * up)) or \
                        (a_here < -down and (c1 <= 0 or -down - a_here > 1e-14 * down)):
                    a0 = a_here
                elif c1 > 0 and ak1 > up:
                    t, a0 = max(t, t0 + (up - ak) / c1), up
                elif c1 < 0 and ak1 < -down:
                    t, a0 = max(t, t0 + (-down - ak) / c1), -down
                else:
                    return
                if not t < te:
                    return
                self.resting = False
                self.sg = 1.0 if a0 > 0 else -1.0
                self.th = self.om = 0.0
            else:
                a0 = ak + c1 * (t - t0)
            t = self.stretch(t, te - t, a0, c1)
        raise RuntimeError(f"no end to interval {k}")

    def stretch(self, t, h, a0, c1):
        """Rocking from t for h at most: to the first impact or fall, or to t + h."""
        sg, k = self.sg, self.corner()
        pc = ind.Piece(k.p, self.th, self.om, sg, k.alpha, a0, c1)
        cuts = [0.0] + pc.critical(h) + [h]
        va = sg * pc.th0
        for ua, ub in zip(cuts, cuts[1:]):
            vb = sg * pc.theta(ub)
            if vb >= HALF_PI:
                self.fallen = True
                return t + ub
            if vb <= 0.0 and va > 0.0:
                u = ind.find_level(lambda s: sg * pc.theta(s), lambda s: sg * pc.omega(s), ua, ub, va, vb)
                self.impact(t + u, pc.omega(u))
                return t + u
            if vb < 0.0 and va <= 0.0:  # pressed back onto the ground within rounding: at rest
                self.th = self.om = 0.0
                self.resting = True
                return t
            va = vb
        self.th, self.om = pc.theta(h), pc.omega(h)
        return t + h

    def free_rocking_overturns(self):
        if self.fallen:
            return True
        if self.resting:
            return False
        th, om, sg = self.th, self.om, (1 if self.sg > 0 else -1)
        lowest = min(k.p * k.alpha for k in self.c.values())
        while True:
            k = self.c[sg]
            if sg * th - k.alpha + sg * om / k.p >= 0.0:
                return True
            d = th - sg * k.alpha
            w = math.sqrt(max(om * om - k.p * k.p * d * d + k.p * k.p * k.alpha * k.alpha, 0.0))
            if w < lowest:
                return False  # below both corners' barriers, and every rebound slower
            sg = -sg
            th, om = 0.0, sg * self.c[sg].e_onto * w


def run_many(a, dt, geometries, scales):
    """Each imperfect block (a Geometry) on the record a (in g) times its scale: whether it
    overturns (bool array) and its impacts.  The blocks are stepped together (numpy)
    through the sample intervals on which a bound on the chord's error keeps sigma theta
    inside (0, pi/2) on the corner they rock on; any other interval is solved alone."""
    n = len(geometries)
    blocks = [ImperfectBlock(g) for g in geometries]
    s = np.asarray(scales, dtype=float)
    PP = np.array([g.plus.p for g in geometries])
    PM = np.array([g.minus.p for g in geometries])
    AP = np.array([g.plus.alpha for g in geometries])
    AM = np.array([g.minus.alpha for g in geometries])
    lowest = np.minimum(AP, AM)

    def pieces(p):
        x = p * dt
        if np.any(x > 1.0):
            raise ValueError("p dt > 1: the series are for short intervals")
        return np.sinh(x), 2 * np.sinh(0.5 * x) ** 2, ind.series_shx(x), x * x / 8.0

    SHp, CHp, SXp, Bp = pieces(PP)
    SHm, CHm, SXm, Bm = pieces(PM)
    th = np.zeros(n)
    om = np.zeros(n)
    sg = np.ones(n)
    rocking = np.zeros(n, dtype=bool)
    active = np.ones(n, dtype=bool)

    def pull(js):
        for j in js:
            blk = blocks[j]
            blk.th, blk.om, blk.sg = float(th[j]), float(om[j]), float(sg[j])

    def push(js):
        for j in js:
            blk = blocks[j]
            th[j], om[j], sg[j] = blk.th, blk.om, blk.sg
            rocking[j] = not blk.resting and not blk.fallen
            active[j] = not blk.fallen

    amax = np.abs(np.asarray(a))
    for k in range(len(a) - 1):
        ak, ak1 = s * a[k], s * a[k + 1]
        c1 = (ak1 - ak) / dt
        on_plus = sg > 0
        p = np.where(on_plus, PP, PM)
        al = np.where(on_plus, AP, AM)
        SH, CH1, SHX, bound = (np.where(on_plus, u, v) for u, v in ((SHp, SHm), (CHp, CHm), (SXp, SXm), (Bp, Bm)))
        A = th + ak - sg * al
        th1 = th + A * CH1 + om * SH / p + c1 * SHX / p
        om1 = om + p * A * SH + (om + c1) * CH1
        e1 = th1 + ak1 - sg * al
        b = bound * np.maximum(np.abs(A), np.abs(e1))
        s0, s1 = sg * th, sg * th1
        quiet = rocking & (np.minimum(s0, s1) - b > 0.0) & (np.maximum(s0, s1) + b < HALF_PI)
        th = np.where(quiet, th1, th)
        om = np.where(quiet, om1, om)
        lifts = s * max(amax[k], amax[k + 1]) > lowest
        js = np.flatnonzero(active & ~quiet & (rocking | lifts))
        if len(js):
            pull(js)
            for j in js:
                try:
                    blocks[j].interval(k, dt, float(ak[j]), float(ak1[j]))
                except RuntimeError as e:
                    g = geometries[j]
                    raise RuntimeError(f"{e}: block {j} (alpha+ {g.plus.alpha!r}, p+ {g.plus.p!r}, alpha- "
                                       f"{g.minus.alpha!r}, p- {g.minus.p!r}), scale {s[j]!r}") from None
            push(js)
    pull(range(n))
    return np.array([blk.free_rocking_overturns() for blk in blocks]), np.array([blk.impacts for blk in blocks])


def run_pulses(geometry, sigma, pulses, pga_g, to):
    """The block under a train of constant pulses [(amplitude, duration in to)] at PGA pga_g
    (in g), mirrored toward theta < 0 when sigma = -1, from rest on corner sigma, no impact
    expected: theta(t_fin) / alpha_sigma and the lowest sigma theta / alpha_sigma over
    (end of the first pulse, t_fin]."""
    k = geometry.plus if sigma > 0 else geometry.minus
    th = om = 0.0
    lowest = math.inf
    for i, (amp, dur) in enumerate(pulses):
        h = dur * to
        pc = ind.Piece(k.p, th, om, sigma, k.alpha, sigma * amp * pga_g, 0.0)
        for u in (pc.critical(h) if i > 0 else []) + [h]:
            lowest = min(lowest, sigma * pc.theta(u) / k.alpha)
        th, om = pc.theta(h), pc.omega(h)
    return sigma * th / k.alpha, lowest
