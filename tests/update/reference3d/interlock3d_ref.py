"""Independent reference implementation of the three-dimensional interface law (SPEC section 9).

Written from the model statement only (SPEC.md sections 1-9 and the decisions), to test the
library's 3D law against: plain Python floats for the law (readable, not fast), numpy only for
the 3-vectors of the macro interface and the central-difference tangent.

Frame and components: s = (s_N, s_T1, s_T2), sigma = (sigma_N, sigma_T1, sigma_T2); units mm,
N, MPa, N/mm. Angles in radians inside; the helpers taking degrees say so in their names.

What is here:
- Material (section 2, derived constants, effect switches) and Plane (gamma_hat, theta_0,
  theta_f, zeta_0, phi) with the mapping of an azimuth outside [0, pi);
- the RIAs `paper`, `azimuthal` (N_a, the plane order of section 9) and general lists;
- PlaneState (D, beta, sf(2), zeta, theta, tauf(2)), virgin and pre-fractured;
- step(): one step of every scheme (explicit, implicit, trapezoidal: the slip direction of a
  plane that slides over the whole step by D14's mean-direction rule, solved as an equation in
  the turn angle), with geometry decay, D7 separation; the implicit and trapezoidal wear equations are solved per plane by a scan
  from zeta_old and a bracketing (bisection / regula falsi) refinement to full precision;
- energies (stored, damage and friction dissipation, work) accumulated along a history;
- tangent_fd(): the tangent by central differences of step();
- solve_normal(): mixed control, sigma_N(s_N) = target at given (s_T1, s_T2);
- run_history(): a preload step then a slip path under constant sigma_N (SPEC D8).
"""

import math
from dataclasses import dataclass, replace

import numpy as np

INF = math.inf
SCHEMES = ("explicit", "implicit", "trapezoidal")


# ----------------------------------------------------------------------------------------------
# Parameters
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Plane:
    """One microplane: area fraction, inclinations [rad], wear scale [N/mm], azimuth [rad]."""
    gamma_hat: float
    theta0: float
    thetaf: float
    zeta0: float = INF
    phi: float = 0.0


def map_azimuth(plane):
    """SPEC 9: an azimuth outside [0, pi) is mapped by (phi, theta_0, theta_f) ->
    (phi - pi, -theta_0, -theta_f). Returns (mapped plane, flipped). phi is first reduced
    modulo 2 pi (a dip direction turned by 2 pi is the same); then phi in [pi, 2 pi) takes the
    rule. A flipped plane's state has sf, tauf and theta of the opposite sign (map_state)."""
    phi = math.fmod(plane.phi, 2.0 * math.pi)
    if phi < 0.0:
        phi += 2.0 * math.pi
    if phi >= math.pi:
        return replace(plane, phi=phi - math.pi, theta0=-plane.theta0,
                       thetaf=-plane.thetaf), True
    return replace(plane, phi=phi), False


class Material:
    """Interface parameters (SPEC 2), derived constants and effect switches (SPEC 7).

    damage=False: D and beta stay at their start values (0, or 1 pre-fractured).
    friction=False: mu = 0. depth=False: H_N = +inf. wear=False: every zeta_0 = +inf."""

    def __init__(self, sigma0_n, sigma0_t, Gc, eta, mu, H_N, planes,
                 damage=True, friction=True, depth=True, wear=True):
        self.sigma0_n, self.sigma0_t, self.Gc, self.eta = sigma0_n, sigma0_t, Gc, eta
        self.mu = mu if friction else 0.0
        self.H_N = H_N if depth else INF
        self.damage = damage
        mapped = []
        for p in planes:
            p, _ = map_azimuth(p)
            if not wear:
                p = replace(p, zeta0=INF)
            mapped.append(p)
        self.planes = mapped
        # derived constants (SPEC 2, D2)
        self.s_cn = 2.0 * Gc / sigma0_n
        self.s_ct = 2.0 * Gc / sigma0_t
        self.s_0n = (1.0 - eta) * self.s_cn
        self.s_0t = (1.0 - eta) * self.s_ct
        self.K_n = sigma0_n / self.s_0n
        self.K_t = sigma0_t / self.s_0t

    def with_planes(self, planes):
        m = Material(self.sigma0_n, self.sigma0_t, self.Gc, self.eta, self.mu, self.H_N, planes,
                     damage=self.damage)
        return m


def deg(x):
    return math.radians(x)


def ria_paper(theta0, thetaf=None, zeta0=INF):
    """The paper's RIA (SPEC 2): three planes 1/3 each, -theta_0, flat, +theta_0, phi = 0."""
    if thetaf is None:
        thetaf = theta0
    return [Plane(1.0 / 3.0, -theta0, -thetaf, zeta0, 0.0),
            Plane(1.0 / 3.0, 0.0, 0.0, zeta0, 0.0),
            Plane(1.0 / 3.0, theta0, thetaf, zeta0, 0.0)]


def ria_azimuthal(n_a, theta0, thetaf=None, zeta0=INF):
    """SPEC 9 `azimuthal`: (phi_0, -theta_0), flat, (phi_0, +theta_0), then (phi_j, -theta_0),
    (phi_j, +theta_0) for j = 1..N_a-1, phi_j = pi j / N_a; flat 1/3, inclined 1/(3 N_a)."""
    if thetaf is None:
        thetaf = theta0
    g = 1.0 / (3.0 * n_a)
    planes = [Plane(g, -theta0, -thetaf, zeta0, 0.0),
              Plane(1.0 / 3.0, 0.0, 0.0, zeta0, 0.0),
              Plane(g, theta0, thetaf, zeta0, 0.0)]
    for j in range(1, n_a):
        phi = math.pi * j / n_a
        planes.append(Plane(g, -theta0, -thetaf, zeta0, phi))
        planes.append(Plane(g, theta0, thetaf, zeta0, phi))
    return planes


def granite(ria="paper", n_a=1, **switches):
    """Granite joints (SPEC parameter sets; inputs/fit/granite_staged.nml): Table 2 cohesion,
    eta = 0.99, mu = tan(34.6 deg) (D6), theta_0 = 30, theta_f = 9 deg, H_N = 4 mm,
    zeta_0 = 6.666 N/mm."""
    th0, thf, z0 = deg(30.0), deg(9.0), 6.666
    planes = ria_paper(th0, thf, z0) if ria == "paper" else ria_azimuthal(n_a, th0, thf, z0)
    return Material(0.025, 0.025, 0.0005, 0.99, math.tan(deg(34.6)), 4.0, planes, **switches)


def table1(theta0_deg=25.0, H_N=0.5, ria="paper", n_a=1, **switches):
    """Table 1 (SPEC parameter sets): sigma0 = 3 MPa, Gc = 0.3 N/mm, eta = 0.9, mu = 0.5,
    no wear."""
    th0 = deg(theta0_deg)
    planes = ria_paper(th0) if ria == "paper" else ria_azimuthal(n_a, th0)
    return Material(3.0, 3.0, 0.3, 0.9, 0.5, H_N, planes, **switches)


# ----------------------------------------------------------------------------------------------
# State
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PlaneState:
    D: float = 0.0
    beta: float = 0.0
    sf1: float = 0.0
    sf2: float = 0.0
    zeta: float = 0.0
    theta: float = 0.0
    tauf1: float = 0.0
    tauf2: float = 0.0


def virgin_state(mat):
    return [PlaneState(theta=p.theta0) for p in mat.planes]


def prefractured_state(mat):
    beta = 1.0 / (1.0 - mat.eta)
    return [PlaneState(D=1.0, beta=beta, theta=p.theta0) for p in mat.planes]


def map_state(state):
    """The state of a plane whose azimuth was mapped (map_azimuth): sf, tauf, theta flip."""
    return replace(state, sf1=-state.sf1, sf2=-state.sf2, theta=-state.theta,
                   tauf1=-state.tauf1, tauf2=-state.tauf2)


# ----------------------------------------------------------------------------------------------
# The microplane law (SPEC 9, one step, points 2-5) at a given inclination
# ----------------------------------------------------------------------------------------------
def frame(theta, phi):
    """(m, e, q) of SPEC 9 as tuples in the (n, t1, t2) basis."""
    ct, st = math.cos(theta), math.sin(theta)
    cp, sp = math.cos(phi), math.sin(phi)
    m = (ct, st * cp, st * sp)
    e = (-st, ct * cp, ct * sp)
    q = (0.0, -sp, cp)
    return m, e, q


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@dataclass
class PlaneResult:
    theta: float
    m: tuple
    e: tuple
    q: tuple
    s_kn: float
    s_kt1: float
    s_kt2: float
    D: float
    beta: float
    sf1: float
    sf2: float
    p: float
    tauf1: float
    tauf2: float
    sig_n: float
    sig_t1: float
    sig_t2: float
    # D14 (trapezoidal scheme): the start and end slip directions and the slip of the step when
    # the mean-direction rule gave the slip direction; None under radial return
    mean_dir: tuple = None


def damage_of(beta, eta):
    """SPEC 4.3 (E2): D = (beta - 1) / (eta beta) in [0, 1]; 0 when beta <= 1."""
    if beta <= 1.0:
        return 0.0
    return max(0.0, min(1.0, (beta - 1.0) / (eta * beta)))


def slides_at_start(old, mup_start):
    """D14: the plane slides at the start of the step, |tau_f,old| = mu p_old (to a relative
    1e-10: the stored friction traction against mu p recomputed from the start separation)."""
    return mup_start > 0.0 and math.hypot(old.tauf1, old.tauf2) >= (1.0 - 1e-10) * mup_start


def mean_direction_slip(tr1, tr2, mup, n_o):
    """D14's mean-direction rule on a plane sliding at the start (direction n_o) and at the end
    (|tau_tr| > mu p). Unknown: the turn 2u of the slip direction over the step, n_new = n_o
    turned by 2u; the slip increment is lam m with m = n_o turned by u (the mean of n_o and
    n_new), and tau_f = mu p n_new = tau_tr - K_t lam m. Its component across m vanishes:
    f(u) = (tau_tr - mu p n_new(u)) x m(u) = 0, solved on u in [-pi/4, pi/4] (a turn of at
    most 90 deg) by the bracketing refinement below, split at u = 0 first. Returns (n_new, m, lam K_t) or None where the rule does not
    apply (no root there, or lam <= 0: a reversal) and radial return is taken instead."""
    def rot(v, a):
        c, s = math.cos(a), math.sin(a)
        return (c * v[0] - s * v[1], s * v[0] + c * v[1])

    def f(u):
        nn = rot(n_o, 2.0 * u)
        m = rot(n_o, u)
        d = (tr1 - mup * nn[0], tr2 - mup * nn[1])
        return m[0] * d[1] - m[1] * d[0]

    lo, hi = -0.25 * math.pi, 0.25 * math.pi
    flo, fhi = f(lo), f(hi)
    exact = None
    if flo == 0.0 or fhi == 0.0:
        exact = lo if flo == 0.0 else hi
    elif (flo > 0.0) == (fhi > 0.0):
        return None
    else:
        f0 = f(0.0)
        if f0 == 0.0:
            exact = 0.0
        elif (f0 > 0.0) == (flo > 0.0):
            lo, flo = 0.0, f0
        else:
            hi, fhi = 0.0, f0
        if exact is None:
            lo, flo, hi, fhi, exact, _ = refine_bracket(f, lo, flo, hi, fhi, 1e-16)
    u = exact if exact is not None else (lo if abs(flo) < abs(fhi) else hi)
    nn = rot(n_o, 2.0 * u)
    m = rot(n_o, u)
    lam_kt = m[0] * (tr1 - mup * nn[0]) + m[1] * (tr2 - mup * nn[1])
    if not lam_kt > 0.0:
        return None
    return nn, m, lam_kt


def plane_law(mat, plane, old, theta, s, mup_start=0.0):
    """Points 2-5 of SPEC 9 for one plane at inclination theta, end-of-step separation s;
    mup_start > 0: the start state's mu p, for D14's mean-direction rule (trapezoidal)."""
    m, e, q = frame(theta, plane.phi)
    s_kn, s_kt1, s_kt2 = dot(m, s), dot(e, s), dot(q, s)
    K_n, K_t = mat.K_n, mat.K_t
    # damage (isotropic in the microplane)
    if mat.damage:
        beta_now = math.hypot(max(0.0, s_kn) / mat.s_0n, math.hypot(s_kt1, s_kt2) / mat.s_0t)
        beta = max(old.beta, beta_now)
        D = damage_of(beta, mat.eta)
    else:
        beta, D = old.beta, old.D
    # friction: isotropic Coulomb, radial return (D14's mean-direction rule where it applies)
    p = -K_n * min(0.0, s_kn)
    mean_dir = None
    if s_kn >= 0.0:
        sf1, sf2, tf1, tf2 = s_kt1, s_kt2, 0.0, 0.0
    else:
        tr1 = K_t * (s_kt1 - old.sf1)
        tr2 = K_t * (s_kt2 - old.sf2)
        tr = math.hypot(tr1, tr2)
        mup = mat.mu * p
        if mup > 0.0 and tr <= mup:
            sf1, sf2 = old.sf1, old.sf2
            tf1, tf2 = tr1, tr2
        else:
            d14 = None
            if mup > 0.0 and slides_at_start(old, mup_start):
                to = math.hypot(old.tauf1, old.tauf2)
                n_o = (old.tauf1 / to, old.tauf2 / to)
                d14 = mean_direction_slip(tr1, tr2, mup, n_o)
            if d14 is not None:
                n1, n2 = d14[0]
                mean_dir = (n_o, d14[0], d14[2] / K_t)
            elif tr > 0.0:
                n1, n2 = tr1 / tr, tr2 / tr
            else:
                n1, n2 = 0.0, 0.0
            sf1 = s_kt1 - (mup / K_t) * n1
            sf2 = s_kt2 - (mup / K_t) * n2
            tf1, tf2 = mup * n1, mup * n2
    sig_n = (1.0 - D) * K_n * s_kn + D * K_n * min(0.0, s_kn)
    sig_t1 = (1.0 - D) * K_t * s_kt1 + D * tf1
    sig_t2 = (1.0 - D) * K_t * s_kt2 + D * tf2
    return PlaneResult(theta, m, e, q, s_kn, s_kt1, s_kt2, D, beta, sf1, sf2, p, tf1, tf2,
                       sig_n, sig_t1, sig_t2, mean_dir)


def worn_angle(plane, zeta):
    """SPEC 4.7: theta(zeta) = (theta_0 - theta_f) exp(-zeta / zeta_0) + theta_f."""
    if plane.zeta0 == INF or plane.theta0 == plane.thetaf:
        return plane.theta0
    return (plane.theta0 - plane.thetaf) * math.exp(-zeta / plane.zeta0) + plane.thetaf


# ----------------------------------------------------------------------------------------------
# Wear increments of the schemes
# ----------------------------------------------------------------------------------------------
def wear_increment_implicit(r, old):
    """Backward Euler: D |tau_f,1| |d sf_1| at the end of the step."""
    return r.D * abs(r.tauf1) * abs(r.sf1 - old.sf1)


def start_pressure(mat, plane, old, s_old):
    """mu p_o: the contact pressure of the start state at its start angle, times mu."""
    m_o, _, _ = frame(old.theta, plane.phi)
    return mat.mu * (-mat.K_n * min(0.0, dot(m_o, s_old)))


def start_dip_friction(mat, plane, old, s_old, r):
    """Trapezoidal start value: |dip component of D_o mu p_o n|, p_o the contact pressure of the
    start state at its start angle, n the direction of the step's frictional slip."""
    d1, d2 = r.sf1 - old.sf1, r.sf2 - old.sf2
    dn = math.hypot(d1, d2)
    if dn == 0.0:
        return 0.0
    return old.D * start_pressure(mat, plane, old, s_old) * abs(d1) / dn


def wear_increment_trapezoidal(mat, plane, old, s_old, r):
    """The trapezoidal rule on the wear rate D |tau_f,1| |d sf_1 / dt|. Under D14 the slip flows
    along the friction traction, whose direction turns from n_o to n_new over the step, so the
    rate is D mu p n_1^2 |d sf| / dt at either end: (D_o mu p_o n_o1^2 + D mu p n_new1^2) lam / 2
    with lam = |d sf|. Otherwise (radial return: one direction for the step) the start value is
    the dip component of D_o mu p_o along the step's slip direction."""
    if r.mean_dir is not None:
        n_o, n_new, lam = r.mean_dir
        mup_o = start_pressure(mat, plane, old, s_old)
        return 0.5 * (old.D * mup_o * n_o[0] ** 2 + r.D * mat.mu * r.p * n_new[0] ** 2) * lam
    return 0.5 * (r.D * abs(r.tauf1) + start_dip_friction(mat, plane, old, s_old, r)) \
        * abs(r.sf1 - old.sf1)


def smallest_root(F, a, width_hint, max_scan=100000):
    """Smallest root z >= a of F (F(a) <= 0 expected): a scan upwards in steps of
    width_hint / 16 (doubling after 64 steps) brackets the first sign change, then a bracketing
    refinement (Illinois regula falsi with bisection every third iteration) to full precision.
    Returns (root, number of F evaluations)."""
    fa = F(a)
    nev = 1
    if fa >= 0.0:
        return a, nev
    h = width_hint / 16.0
    if not h > 0.0:
        h = max(abs(a), 1e-300) * 1e-12
    lo, flo = a, fa
    for i in range(max_scan):
        hi = lo + h
        fhi = F(hi)
        nev += 1
        if fhi >= 0.0:
            break
        lo, flo = hi, fhi
        if i >= 64:
            h *= 2.0
    else:
        raise RuntimeError("no root bracketed")
    if fhi == 0.0:
        return hi, nev
    lo, flo, hi, fhi, exact, n_ref = refine_bracket(F, lo, flo, hi, fhi, 1e-15)
    if exact is not None:
        return exact, nev + n_ref
    nev += n_ref
    # the end of the bracket where F >= 0 (the root to full precision; hi - lo ~ 1 ulp)
    return hi, nev


def refine_bracket(f, lo, flo, hi, fhi, rel_tol):
    """Shrinks a bracket lo < hi (f of opposite signs at the ends) by Illinois regula falsi with
    a bisection every third iteration, until hi - lo <= rel_tol max(|lo|, |hi|) or no double
    lies between them. Returns (lo, flo, hi, fhi, exact root or None, evaluations)."""
    side, nev = 0, 0
    for it in range(400):
        if it % 3 == 2:
            z = 0.5 * (lo + hi)
        else:
            z = hi - fhi * (hi - lo) / (fhi - flo)
            if not (lo < z < hi):
                z = 0.5 * (lo + hi)
        if z <= lo or z >= hi:
            break
        fz = f(z)
        nev += 1
        if fz == 0.0:
            return lo, flo, hi, fhi, z, nev
        if (fz > 0.0) == (fhi > 0.0):
            hi, fhi = z, fz
            if side == 1:
                flo *= 0.5
            side = 1
        else:
            lo, flo = z, fz
            if side == -1:
                fhi *= 0.5
            side = -1
        if hi - lo <= rel_tol * max(abs(hi), abs(lo), 1e-300):
            break
    return lo, flo, hi, fhi, None, nev


# ----------------------------------------------------------------------------------------------
# One step of the interface
# ----------------------------------------------------------------------------------------------
def geometry_decay(mat, s_N):
    """SPEC 4.1: A_g(x) = max(0, 1 - max(0, x)), x = s_N / H_N; 1 with H_N = +inf."""
    if mat.H_N == INF:
        return 1.0
    return max(0.0, 1.0 - max(0.0, s_N / mat.H_N))


def step(mat, s_old, s_new, old_states, scheme):
    """One step from (s_old, old_states) to s_new. Returns (sigma (3,), new_states, results)
    with results the per-plane PlaneResult at the angle the traction is computed with
    (None for a separated step)."""
    if scheme not in SCHEMES:
        raise ValueError("scheme must be one of %s" % (SCHEMES,))
    s = (float(s_new[0]), float(s_new[1]), float(s_new[2]))
    so = (float(s_old[0]), float(s_old[1]), float(s_old[2]))
    A_g = geometry_decay(mat, s[0])
    if A_g == 0.0:
        # D7: separated, nothing transmitted; damage 1; sf, zeta, theta frozen; tauf = 0
        beta_sep = 1.0 / (1.0 - mat.eta)
        new = [replace(o, D=1.0, beta=max(o.beta, beta_sep), tauf1=0.0, tauf2=0.0)
               for o in old_states]
        return np.zeros(3), new, [None] * len(new)
    sigma = [0.0, 0.0, 0.0]
    new_states, results = [], []
    for plane, old in zip(mat.planes, old_states):
        if scheme == "explicit":
            r = plane_law(mat, plane, old, old.theta, s)
            zeta = old.zeta + old.D * abs(old.tauf1) * abs(r.sf1 - old.sf1)
            theta_next = worn_angle(plane, zeta)
        else:
            mup_o = 0.0
            if scheme == "implicit":
                def G(z):
                    rz = plane_law(mat, plane, old, worn_angle(plane, z), s)
                    return wear_increment_implicit(rz, old)
            else:
                mup_o = start_pressure(mat, plane, old, so)

                def G(z):
                    rz = plane_law(mat, plane, old, worn_angle(plane, z), s, mup_o)
                    return wear_increment_trapezoidal(mat, plane, old, so, rz)
            if plane.zeta0 == INF or plane.theta0 == plane.thetaf:
                zeta = old.zeta + G(old.zeta)     # theta does not depend on zeta
            else:
                g0 = G(old.zeta)
                zeta, _ = smallest_root(lambda z: z - old.zeta - G(z), old.zeta, g0)
            theta_next = worn_angle(plane, zeta)
            r = plane_law(mat, plane, old, theta_next, s, mup_o)
        new_states.append(PlaneState(r.D, r.beta, r.sf1, r.sf2, zeta, theta_next,
                                     r.tauf1, r.tauf2))
        results.append(r)
        g = plane.gamma_hat * A_g
        for i in range(3):
            sigma[i] += g * (r.sig_n * r.m[i] + r.sig_t1 * r.e[i] + r.sig_t2 * r.q[i])
    return np.array(sigma), new_states, results


def tangent_fd(mat, s_old, s_new, old_states, scheme, h=1e-7):
    """K = d sigma / d s_new by central differences of step() (relative step h)."""
    s_new = np.asarray(s_new, dtype=float)
    K = np.zeros((3, 3))
    for j in range(3):
        dh = h * max(1.0, np.max(np.abs(s_new)))
        sp, sm = s_new.copy(), s_new.copy()
        sp[j] += dh
        sm[j] -= dh
        fp = step(mat, s_old, sp, old_states, scheme)[0]
        fm = step(mat, s_old, sm, old_states, scheme)[0]
        K[:, j] = (fp - fm) / (2.0 * dh)
    return K


# ----------------------------------------------------------------------------------------------
# Energies (SPEC 8, D9): per plane psi_k = (1-D) [K_n s_kn^2 + K_t |s_kt|^2] / 2
#   + D [K_n min(0, s_kn)^2 + K_t |s_kt - sf|^2] / 2, so that sigma_k = d psi_k / d s_k;
#   damage driving force Y_k = -d psi_k / d D; friction dissipation rate D tau_f . d sf.
# Increments over a step, all by the trapezoidal rule: work (sigma_o + sigma) . ds / 2, damage
# dissipation (Y_o + Y) dD / 2, friction dissipation (D_o tauf_o + D tau_f) . d sf / 2. With
# depth and wear off, psi is a cubic of (s, D, sf) and these are its exact increment up to the
# rule's error: the balance work = stored + damage + friction holds to O(h^2) on any path,
# which checks that the traction, Y and tau_f are the derivatives of one psi (not a tautology).
# The scheme's own friction dissipation of a step, D tau_f . d sf = D mu p |d sf|, is never
# negative.
# ----------------------------------------------------------------------------------------------
def plane_energy(mat, s_kn, s_kt1, s_kt2, D, sf1, sf2):
    """(psi_k, Y_k) of a plane at its local separation and state."""
    K_n, K_t = mat.K_n, mat.K_t
    bond = 0.5 * (K_n * s_kn ** 2 + K_t * (s_kt1 ** 2 + s_kt2 ** 2))
    cn = min(0.0, s_kn)
    fric = 0.5 * (K_n * cn ** 2 + K_t * ((s_kt1 - sf1) ** 2 + (s_kt2 - sf2) ** 2))
    return (1.0 - D) * bond + D * fric, bond - fric


@dataclass
class Energies:
    work: float = 0.0
    stored: float = 0.0
    damage: float = 0.0
    friction: float = 0.0


def energy_update(mat, en, sig_old, sig_new, s_old, s_new, old_states, new_states):
    """Energies after a step (wear off: theta is each plane's constant angle)."""
    so, sn = np.asarray(s_old, dtype=float), np.asarray(s_new, dtype=float)
    A_o, A_n = geometry_decay(mat, so[0]), geometry_decay(mat, sn[0])
    w = en.work + 0.5 * float(np.dot(np.asarray(sig_old) + np.asarray(sig_new), sn - so))
    stored, dmg, fr = 0.0, en.damage, en.friction
    for plane, o, nw in zip(mat.planes, old_states, new_states):
        m, e, q = frame(nw.theta, plane.phi)
        psi_n, Y_n = plane_energy(mat, dot(m, sn), dot(e, sn), dot(q, sn), nw.D, nw.sf1, nw.sf2)
        m, e, q = frame(o.theta, plane.phi)
        _, Y_o = plane_energy(mat, dot(m, so), dot(e, so), dot(q, so), o.D, o.sf1, o.sf2)
        stored += plane.gamma_hat * A_n * psi_n
        dmg += plane.gamma_hat * 0.5 * (A_o * Y_o + A_n * Y_n) * (nw.D - o.D)
        d1, d2 = nw.sf1 - o.sf1, nw.sf2 - o.sf2
        fr += plane.gamma_hat * 0.5 * (A_o * o.D * (o.tauf1 * d1 + o.tauf2 * d2)
                                       + A_n * nw.D * (nw.tauf1 * d1 + nw.tauf2 * d2))
    return Energies(w, stored, dmg, fr)


# ----------------------------------------------------------------------------------------------
# Mixed control and histories
# ----------------------------------------------------------------------------------------------
def solve_normal(mat, s_old, sT, old_states, scheme, target, sN_guess):
    """s_N with sigma_N(s_N, sT1, sT2) = target (the step from s_old, old_states): bracket by
    expanding steps from the guess, then Illinois / bisection to full precision."""
    def f(sN):
        return step(mat, s_old, (sN, sT[0], sT[1]), old_states, scheme)[0][0] - target
    a = sN_guess
    fa = f(a)
    if fa == 0.0:
        return a
    # sigma_N increases with s_N under compression: step towards the target
    h = max(abs(fa) / mat.K_n, 1e-12 * max(1.0, abs(a)))
    direction = -1.0 if fa > 0.0 else 1.0
    b, fb = a, fa
    for _ in range(200):
        b = a + direction * h
        fb = f(b)
        if fb == 0.0:
            return b
        if (fb > 0.0) != (fa > 0.0):
            break
        a, fa = b, fb
        h *= 2.0
    else:
        raise RuntimeError("solve_normal: no bracket for sigma_N = %g" % target)
    lo, flo, hi, fhi = (a, fa, b, fb) if a < b else (b, fb, a, fa)
    lo, flo, hi, fhi, exact, _ = refine_bracket(f, lo, flo, hi, fhi, 4e-16)
    if exact is not None:
        return exact
    return lo if abs(flo) <= abs(fhi) else hi


@dataclass
class HistoryRow:
    time: float
    s: np.ndarray
    sigma: np.ndarray
    states: list
    energies: Energies


def run_history(mat, path, scheme, sigma_N=None, state0=None, store_every=1,
                with_energies=False):
    """A history: path is a list of in-plane points (s_T1, s_T2), path[0] the start point.
    Under mixed control (sigma_N given) the first step is the preload from the virgin state at
    path[0] (SPEC D8), then one step per further point, each solving sigma_N = target; without
    sigma_N, path holds full separations (s_N, s_T1, s_T2) and the first point is reached in
    one step from zero. time = accumulated in-plane slip length. Returns rows (the preload
    row first, then every store_every-th step and the last)."""
    states = state0 if state0 is not None else virgin_state(mat)
    s_prev = np.zeros(3)
    sig_prev = np.zeros(3)
    en = Energies()
    rows = []
    time = 0.0
    n = len(path)
    for i, pt in enumerate(path):
        if sigma_N is not None:
            sT = (float(pt[0]), float(pt[1]))
            sN = solve_normal(mat, s_prev, sT, states, scheme, sigma_N, s_prev[0])
            s_new = np.array([sN, sT[0], sT[1]])
        else:
            s_new = np.asarray(pt, dtype=float)
        sig, new_states, _ = step(mat, s_prev, s_new, states, scheme)
        if with_energies:
            en = energy_update(mat, en, sig_prev, sig, s_prev, s_new, states, new_states)
        if i > 0:
            time += math.hypot(s_new[1] - s_prev[1], s_new[2] - s_prev[2])
        if i == 0 or i % store_every == 0 or i == n - 1:
            rows.append(HistoryRow(time, s_new, sig, new_states, en))
        s_prev, sig_prev, states = s_new, sig, new_states
    return rows


def straight_path(length, angle, n_steps, start=(0.0, 0.0)):
    """Points (s_T1, s_T2): start, then n_steps uniform steps of total length along angle."""
    c, s = math.cos(angle), math.sin(angle)
    return [(start[0] + length * c * i / n_steps, start[1] + length * s * i / n_steps)
            for i in range(n_steps + 1)]


def square_path(side, n_per_side):
    """0 -> (a, 0) -> (a, a) -> (0, a) -> 0, n_per_side uniform steps per side."""
    corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side), (0.0, 0.0)]
    pts = [corners[0]]
    for (x0, y0), (x1, y1) in zip(corners[:-1], corners[1:]):
        for i in range(1, n_per_side + 1):
            t = i / n_per_side
            pts.append((x0 + (x1 - x0) * t, y0 + (y1 - y0) * t))
    return pts


def circle_path(radius, n_radial, n_around, turns=1.0):
    """0 -> (r, 0) in n_radial steps, then around the circle of radius r centred at the origin
    (counter-clockwise, `turns` revolutions) in n_around steps."""
    pts = [(radius * i / n_radial, 0.0) for i in range(n_radial + 1)]
    for i in range(1, n_around + 1):
        a = 2.0 * math.pi * turns * i / n_around
        pts.append((radius * math.cos(a), radius * math.sin(a)))
    return pts
