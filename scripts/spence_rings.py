#!/usr/bin/env python3
"""Spence's frictional indentation (J. Elasticity 5:297, 1975), solved
numerically: the stick radius c/a of a rigid sphere pressed into an elastic
half-space with Coulomb friction, for prm/spence_sphere_axisymmetric.prm.

The half-space's surface is cut into rings of constant pressure p and radial
shear q (collocation at their mid-radii); the sphere is pressed in step by
step, each step solved exactly by an active set (open, stick: no radial
motion since the step's start, slip: q = mu p against the slip). With rings
in geometric progression (--lam) and steps growing a by lam^k, the discrete
problem is itself self-similar: c/a is the same at every step after the
first two. Results (nu = 0.3, mu = 0.3): 0.873, 0.875, 0.888, 0.894 at
--lam 1.04, 1.02, 1.01, 1.005 (k = 1); the frictionless force is Hertz's
to 1e-4 at mu -> 0.
  /usr/bin/python3 scripts/spence_rings.py --lam 1.02 --rmin 0.002 --a0 0.3 --mu 0.3 0.2 0.1
(numpy; about 10 s at --lam 1.02, 15 min at 1.005).

Kernels (z into the solid, q outward on the half-space):
  u_z <- p : (1-nu^2)/(pi E) * s * 4 K(m)/(r+s),  m = 4rs/(r+s)^2
  u_r <- q : (1-nu^2)/(pi E) * s * 2/(r s) [(r^2+s^2) K/(r+s) - (r+s) E(m)]
             (Cerruti over a ring: its nu term integrates to zero)
  u_r <- p : -(1-2nu)(1+nu)/(E r) int_0^r s p ds      (Boussinesq)
  u_z <- q : -(1-2nu)(1+nu)/E int_r^inf q ds          (by reciprocity)
"""
import numpy as np, sys, argparse

def ellip(m):
    # K and E by the AGM (Abramowitz & Stegun 17.6)
    m = np.asarray(m, float)
    a = np.ones_like(m); b = np.sqrt(np.maximum(1 - m, 0)); c = np.sqrt(m)
    ssum = 0.5 * c**2
    pw = 1.0
    for _ in range(30):
        c = 0.5 * (a - b)
        a, b = 0.5 * (a + b), np.sqrt(a * b)
        pw *= 2
        ssum = ssum + 0.5 * pw * c**2
    K = np.pi / (2 * a)
    E = K * (1 - ssum)
    return K, E

GX, GW = np.polynomial.legendre.leggauss(24)

def kern(r, s):
    m = 4 * r * s / (r + s)**2
    m = np.minimum(m, 1 - 1e-16)
    K, E = ellip(m)
    kz = s * 4 * K / (r + s)
    kr = 2 / r * ((r * r + s * s) * K / (r + s) - (r + s) * E)
    return kz, kr

def integrate(r, s0, s1):
    """int_{s0}^{s1} kernel ds at r; near r, graded (s - r ~ u^2) toward the log singularity."""
    L = s1 - s0
    if s0 < r < s1:
        pieces = [(r, s0), (r, s1)]
    elif r <= s0 and s0 - r < 2 * L:
        pieces = [(s0, s1)]
    elif r >= s1 and r - s1 < 2 * L:
        pieces = [(s1, s0)]
    else:
        pieces = None
    u = 0.5 * (GX + 1); w = 0.5 * GW
    if pieces:
        tz = tr = 0.0
        for (x0, x1) in pieces:
            s = x0 + (x1 - x0) * u**2
            jac = 2 * u * abs(x1 - x0)
            kz, kr = kern(r, s)
            tz += np.sum(w * jac * kz); tr += np.sum(w * jac * kr)
        return tz, tr
    s = s0 + L * u
    kz, kr = kern(r, s)
    return np.sum(w * kz) * L, np.sum(w * kr) * L

def matrices(edges, nu, E=1.0, near=3):
    n = len(edges) - 1
    rc = 0.5 * (edges[1:] + edges[:-1])
    # far pairs: plain Gauss, vectorised
    u = 0.5 * (GX + 1); w = 0.5 * GW
    L = edges[1:] - edges[:-1]
    S = edges[:-1, None] + L[:, None] * u[None, :]          # (n, g)
    Gzz = np.zeros((n, n)); Grr = np.zeros((n, n))
    for i in range(n):
        kz, kr = kern(rc[i], S)
        Gzz[i] = (kz * w).sum(1) * L; Grr[i] = (kr * w).sum(1) * L
        for j in range(max(0, i - near), min(n, i + near + 1)):
            Gzz[i, j], Grr[i, j] = integrate(rc[i], edges[j], edges[j + 1])
    f = (1 - nu**2) / (np.pi * E)
    Gzz *= f; Grr *= f
    g = (1 - 2 * nu) * (1 + nu) / E
    lo = edges[:-1]; hi = edges[1:]
    R = rc[:, None]
    inside_hi = np.minimum(hi[None, :], R)
    Grz = -g / R * np.where(inside_hi > lo[None, :], 0.5 * (inside_hi**2 - lo[None, :]**2), 0)
    Gzr = -g * np.maximum(hi[None, :] - np.maximum(lo[None, :], R), 0)
    return rc, Gzz, Grr, Grz, Gzr

def solve_history(edges, nu, mu, deltas, R=1.0, coupled=True, verbose=False):
    rc, Gzz, Grr, Grz, Gzr = matrices(edges, nu)
    if not coupled:
        Grz[:] = 0; Gzr[:] = 0
    n = len(rc)
    A = np.block([[Gzz, Gzr], [Grz, Grr]])
    p = np.zeros(n); q = np.zeros(n); ur = np.zeros(n)
    state = np.zeros(n, int)  # 0 open, 1 stick, 2 slip
    sgn = np.zeros(n)         # slip direction of u_r (q = -mu p sgn)
    out = []
    for d in deltas:
        ur0 = ur.copy()
        m = min(n, int(np.searchsorted(rc, 1.25 * np.sqrt(d * R))) + 8)
        rhs_z = d - rc[:m]**2 / (2 * R)
        idx = np.r_[0:m, n:n + m]
        Am = A[np.ix_(idx, idx)]
        st_, sg_ = state[:m].copy(), sgn[:m].copy()
        for it in range(200):
            M = Am.copy(); b = np.concatenate([rhs_z, ur0[:m]])
            op = np.where(st_ == 0)[0]; ns = np.where(st_ != 1)[0]; sl = np.where(st_ == 2)[0]
            M[op] = 0; M[op, op] = 1; b[op] = 0
            M[m + ns] = 0; M[m + ns, m + ns] = 1; b[m + ns] = 0
            M[m + sl, sl] = mu * sg_[sl]
            x = np.linalg.solve(M, b)
            pn, qn = x[:m], x[m:]
            uz = Am[:m] @ x
            urn = Am[m:] @ x
            new = st_.copy(); newsgn = sg_.copy()
            openn = st_ == 0
            ent = openn & (uz < rhs_z - 1e-13 * d)
            new[ent] = 2; newsgn[ent] = np.where(urn[ent] - ur0[:m][ent] > 0, 1.0, -1.0)
            c_ = ~openn
            neg = c_ & (pn < 0); new[neg] = 0
            stk = (st_ == 1) & ~neg & (np.abs(qn) > mu * pn * (1 + 1e-12))
            new[stk] = 2; newsgn[stk] = -np.sign(qn[stk])
            slp = (st_ == 2) & ~neg & ((urn - ur0[:m]) * sg_ < 0)
            new[slp] = 1
            changed = np.where((new != st_) | ((st_ == 2) & (newsgn != sg_)))[0]
            if len(changed) == 0:
                break
            if it >= 20:
                # cycling: change only the node furthest out of its law (the largest violation)
                viol = np.zeros(m)
                viol[openn] = np.maximum(rhs_z - uz, 0)[openn]
                viol[neg] = -pn[neg]
                viol[stk] = (np.abs(qn) - mu * pn)[stk]
                viol[slp] = np.abs(urn - ur0[:m])[slp] * mu
                j = changed[np.argmax(viol[changed] * (1 + 0 * changed))] if it % 2 == 0 else changed[-1]
                keep = new.copy(); new = st_.copy(); new[j] = keep[j]
                ns_ = sg_.copy(); ns_[j] = newsgn[j]; newsgn = ns_
            st_, sg_ = new, newsgn
        else:
            print("no convergence at delta", d, file=sys.stderr)
        state[:] = 0; state[:m] = st_; sgn[:m] = sg_
        p = np.zeros(n); q = np.zeros(n); p[:m] = pn; q[:m] = qn
        ur = Grz @ p + Grr @ q
        assert state[m - 1] == 0, "contact reached the reduced system's edge"
        cont = np.where(state > 0)[0]
        a = c = 0.0
        if len(cont):
            j = cont.max()
            a = edges[j + 1]
            if j >= 1 and p[j - 1] > p[j] > 0:   # p^2 linear through the last two ring centres
                y1, y0 = p[j]**2, p[j - 1]**2
                a = rc[j] + (rc[j] - rc[j - 1]) * y1 / (y0 - y1)
                a = min(max(a, rc[j]), rc[j] + (rc[j] - rc[j - 1]) * 1.5)
        stk = np.where(state == 1)[0]
        if len(stk):
            j = stk.max()
            c = edges[j + 1]
            if j >= 1 and state[j - 1] == 1 and j + 1 < n and state[j + 1] == 2:
                # (1 - q/(mu p))^2 linear through the last two stick rings: where it vanishes
                y1 = (1 - abs(q[j]) / (mu * p[j]))**2; y0 = (1 - abs(q[j - 1]) / (mu * p[j - 1]))**2
                if y0 > y1:
                    c = rc[j] + (rc[j] - rc[j - 1]) * y1 / (y0 - y1)
                    c = min(max(c, rc[j]), rc[j + 1])
        F = np.sum(p * np.pi * (edges[1:]**2 - edges[:-1]**2))
        craw = edges[1:][state == 1].max() if (state == 1).any() else 0
        araw = edges[1:][state > 0].max() if (state > 0).any() else 0
        out.append((d, a, c, F, it, araw, craw))
        if verbose:
            print(f"delta={d:.4e} a={a:.4f} c={c:.4f} c/a={c/a if a else 0:.4f} F={F:.4e} it={it}")
    return np.array(out), rc, p, q, state

if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--mu", type=float, nargs="+", default=[0.3])
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--rmax", type=float, default=1.3)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--a0", type=float, default=0.05)
    ap.add_argument("--uncoupled", action="store_true")
    ap.add_argument("-v", action="store_true")
    ap.add_argument("--linear", action="store_true")
    ap.add_argument("--lam", type=float, default=0)
    ap.add_argument("--k", type=int, default=1)
    ap.add_argument("--rmin", type=float, default=1e-3)
    o = ap.parse_args()
    if o.lam:
        ne = int(np.ceil(np.log(o.rmax / o.rmin) / np.log(o.lam)))
        edges = np.r_[0.0, o.rmin * o.lam**np.arange(ne + 1)]
        o.n = len(edges) - 1
    else:
        edges = np.linspace(0, o.rmax, o.n + 1)
    R = 1.0
    # a^2 = R delta (Hertz); final a = 1
    if o.lam:
        ks = int(round(np.log(1 / o.a0) / np.log(o.lam) / o.k))
        a_s = o.lam**(-o.k * np.arange(ks, -1, -1))
        o.steps = len(a_s)
    else:
        a_s = np.geomspace(o.a0, 1.0, o.steps) if not o.linear else np.linspace(o.a0, 1.0, o.steps)
    deltas = a_s**2 / R
    beta = (1 - 2 * o.nu) / (2 * (1 - o.nu))
    for mu in o.mu:
        out, rc, p, q, st = solve_history(edges, o.nu, mu, deltas, R, not o.uncoupled, o.v)
        a, c = out[:, 1], out[:, 2]
        sel = a > 0.3
        last = a > 0.5
        print("  raw ring edges c/a final %.4f" % (out[-1,6]/out[-1,5]))
        print("  mean c/a over a in (0.5,1]: %.4f (min %.4f max %.4f)  a_final=%.4f" % (np.mean(c[last]/a[last]), np.min(c[last]/a[last]), np.max(c[last]/a[last]), a[-1]))
        print(f"nu={o.nu} beta={beta:.4f} mu={mu} beta/mu={beta/mu:.4f} n={o.n} steps={o.steps}: "
              f"c/a final={c[-1]/a[-1]:.4f}  (a>0.3: min {np.min(c[sel]/a[sel]):.4f} max {np.max(c[sel]/a[sel]):.4f})  "
              f"F/F_hertz={out[-1,3]/(4/3/(1-o.nu**2)*1.0):.4f}")
