"""Small axisymmetric P1 FE code (numpy + scipy.sparse) for the element variants in element.py.

Meshes are built row by row: each row is a z level with sorted r positions; consecutive rows
are joined by a "zip" triangulation (advance whichever row has the nearer next node, ties
advance the bottom row), all triangles ordered so that J > 0 when the top row lies above the
bottom row.  A "band" is one staggered row (r = r0, r0+h/2, ..., r1-h/2, r1) placed at
z_b + delta just above the regular row z_b, so the strip between them is a row of cap-shaped
triangles with J = h*delta (delta = 0: zero-thickness band, delta < 0: inverted band).
"""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
import sympy as sy

from element import dmat, stiffness, parts

E_, NU_ = 1.0, 0.3
D = dmat(E_, NU_)

# ---------------------------------------------------------------- manufactured solution
_r, _z = sy.symbols("r z", real=True)


def manufactured(ur_expr, uz_expr):
    lam = E_ * NU_ / ((1 + NU_) * (1 - 2 * NU_))
    mu = E_ / (2 * (1 + NU_))
    err = sy.diff(ur_expr, _r)
    ezz = sy.diff(uz_expr, _z)
    ett = ur_expr / _r
    grz = sy.diff(ur_expr, _z) + sy.diff(uz_expr, _r)
    tr = err + ezz + ett
    srr = lam * tr + 2 * mu * err
    szz = lam * tr + 2 * mu * ezz
    stt = lam * tr + 2 * mu * ett
    srz = mu * grz
    fr = -(sy.diff(srr, _r) + sy.diff(srz, _z) + (srr - stt) / _r)
    fz = -(sy.diff(srz, _r) + sy.diff(szz, _z) + srz / _r)
    fr, fz = sy.simplify(fr), sy.simplify(fz)
    f = sy.lambdify((_r, _z), [fr, fz], "numpy")
    u = sy.lambdify((_r, _z), [ur_expr, uz_expr], "numpy")
    return u, f, (fr, fz)


U_EX, F_EX, F_SYM = manufactured(_r ** 2 * sy.sin(_z) / 10, sy.cos(_r) * _z / 10)

# ---------------------------------------------------------------- quadrature (Strang-Fix / Dunavant degree 5, 7 points)
_a1, _b1 = 0.059715871789770, 0.470142064105115
_a2, _b2 = 0.797426985353087, 0.101286507323456
QP = np.array([[1 / 3, 1 / 3, 1 / 3],
               [_a1, _b1, _b1], [_b1, _a1, _b1], [_b1, _b1, _a1],
               [_a2, _b2, _b2], [_b2, _a2, _b2], [_b2, _b2, _a2]])
QW = np.array([0.225, 0.132394152788506, 0.132394152788506, 0.132394152788506,
               0.125939180544827, 0.125939180544827, 0.125939180544827])  # sum 1 (x area)


# ---------------------------------------------------------------- meshes
def zip_rows(ib, rb, it, rt):
    tris = []
    i = j = 0
    nb, nt = len(ib), len(it)
    while i < nb - 1 or j < nt - 1:
        adv_b = j == nt - 1 or (i < nb - 1 and rb[i + 1] <= rt[j + 1] + 1e-14)
        if adv_b:
            tris.append((ib[i], ib[i + 1], it[j]))
            i += 1
        else:
            tris.append((ib[i], it[j + 1], it[j]))
            j += 1
    return tris


def mesh(N, r0=1.0, r1=2.0, z0=0.0, z1=1.0, band=None):
    """N cells per side (h = 1/N, square domain assumed r1-r0 = z1-z0).
    band = None, or delta: staggered row at z_b + delta, z_b = middle row (N even)."""
    h = (r1 - r0) / N
    rows = []
    zs = np.linspace(z0, z1, N + 1)
    reg = np.linspace(r0, r1, N + 1)
    for k, zk in enumerate(zs):
        rows.append((zk, reg))
        if band is not None and k == N // 2:
            st = np.concatenate([[r0], r0 + h / 2 + h * np.arange(N), [r1]])
            rows.append((zk + band, st))
    pts, ids = [], []
    for zk, rr in rows:
        ids.append(np.arange(len(pts), len(pts) + len(rr)))
        pts.extend([(x, zk) for x in rr])
    pts = np.array(pts)
    tris = []
    for a in range(len(rows) - 1):
        tris += zip_rows(ids[a], rows[a][1], ids[a + 1], rows[a + 1][1])
    tris = np.array(tris)
    bnd = np.zeros(len(pts), bool)
    bnd |= np.isclose(pts[:, 0], r0) | np.isclose(pts[:, 0], r1)
    bnd[ids[0]] = True
    bnd[ids[-1]] = True
    return pts, tris, bnd, h


# ---------------------------------------------------------------- assembly & solve
def assemble(pts, tris, variant, Jmin):
    n = 2 * len(pts)
    I, Jc, V = [], [], []
    F = np.zeros(n)
    Js = np.empty(len(tris))
    for e, t in enumerate(tris):
        xy = pts[t]
        Ke = stiffness(xy, variant, D, Jmin)
        dofs = np.ravel(np.column_stack([2 * t, 2 * t + 1]))
        I.append(np.repeat(dofs, 6))
        Jc.append(np.tile(dofs, 6))
        V.append(Ke.ravel())
        J = parts(xy)[0]
        Js[e] = J
        # load: int N_i f 2 pi r dA with the true (signed) measure J/2
        q = QP @ xy
        fr, fz = F_EX(q[:, 0], q[:, 1])
        fr = np.broadcast_to(fr, q[:, 0].shape)
        fz = np.broadcast_to(fz, q[:, 0].shape)
        w = QW * (J / 2) * 2 * np.pi * q[:, 0]
        F[dofs[0::2]] += QP.T @ (w * fr)
        F[dofs[1::2]] += QP.T @ (w * fz)
    K = sp.csr_matrix((np.concatenate(V), (np.concatenate(I), np.concatenate(Jc))), shape=(n, n))
    return K, F, Js


def solve(pts, tris, bnd, variant, Jmin, uex=None, load=True):
    K, F, Js = assemble(pts, tris, variant, Jmin)
    if not load:
        F[:] = 0.0
    uex = uex or U_EX
    n = 2 * len(pts)
    ub = np.zeros(n)
    ur, uz = uex(pts[:, 0], pts[:, 1])
    ub[0::2] = ur
    ub[1::2] = uz
    fixed = np.zeros(n, bool)
    fixed[0::2] = bnd
    fixed[1::2] = bnd
    free = ~fixed
    rhs = F[free] - K[free][:, fixed] @ ub[fixed]
    Kff = K[free][:, free].tocsc()
    u = ub.copy()
    u[free] = spla.spsolve(Kff, rhs)
    return u, ub, Js


def l2_error(pts, tris, u, uex=None):
    """Weighted L2 error (2 pi r dA, |J| measure) of the P1 field u vs the exact field."""
    uex = uex or U_EX
    num = den = 0.0
    for t in tris:
        xy = pts[t]
        J = parts(xy)[0]
        q = QP @ xy
        er, ez = uex(q[:, 0], q[:, 1])
        er = np.broadcast_to(er, q[:, 0].shape)
        ez = np.broadcast_to(ez, q[:, 0].shape)
        hr = QP @ u[2 * t]
        hz = QP @ u[2 * t + 1]
        w = QW * abs(J) / 2 * 2 * np.pi * q[:, 0]
        num += w @ ((hr - er) ** 2 + (hz - ez) ** 2)
        den += w @ (er ** 2 + ez ** 2)
    return np.sqrt(num / den)
