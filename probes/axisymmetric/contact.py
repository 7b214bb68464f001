"""Axisymmetric conforming contact patch test (the analogue of tfem's docs/method.md §6.11.3).

Two blocks r in [r0, r1]: lower z in [-H1, 0], upper z in [0, H2], matching nodes on z = 0,
uniform pressure p on the top (consistent load: int phi_i 2 pi r p ds), rollers (u_z = 0) on the
bottom, u_r = 0 on the axis when r0 = 0, lateral sides free.  Exact: sigma_zz = -p, every other
stress component 0, in both blocks.  B = the conforming strip of flat (J = 0) elements
[L_i, L_i+1, U_i+1] and [L_i, U_i+1, U_i] (tfem's split), all active (the opening of each is
checked to be < 0 afterwards), T = Jmin_B = l_e h_c^2 / lambda, E_c = the smaller E.

B element variants (J = 0 exactly, so only the tempered forms exist):
  d_fric   pi rbar Bhat^T D_c Bhat / T, D_c = E_c e_zz e_zz^T (frictionless, no hoop row)
  c_fric   element.stiffness(.., 'all', D_c, T)   (J -> T everywhere, 4x4 D_c with zero hoop part)
  d_stick  pi rbar Bhat^T D_3 Bhat / T, D_3 = the (rr, zz, rz) rows/cols of the isotropic 4x4 D
  e_stick  element.stiffness(.., 'scalar', D_4, T)  (= d_stick at J = 0)
  c_stick  element.stiffness(.., 'all', D_4, T)     (J -> T everywhere, isotropic 4x4 D with hoop)
  b_stick  element.stiffness(.., 'grad', D_4, T)    (temper the 1/J part only)
Bulk elements: regular meshes (J = h^2 >= Jmin = h^3), so every bulk variant is plain FEM.
"""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from element import dmat, stiffness, parts
import fem

LAMBDA = 1.0


def block(r, zs, offset):
    pts = np.array([(x, z) for z in zs for x in r])
    nr = len(r)
    ids = [np.arange(k * nr, (k + 1) * nr) + offset for k in range(len(zs))]
    tris = []
    for k in range(len(zs) - 1):
        tris += fem.zip_rows(ids[k], r, ids[k + 1], r)
    return pts, tris, ids


def bel(xy, kind, Ec, D4, T):
    J, rbar, Bh, H = parts(xy)
    if kind in ("d_fric", "c_fric"):
        Dc = np.zeros((4, 4))
        Dc[1, 1] = Ec
        if kind == "d_fric":
            return np.pi * rbar * Bh.T @ Dc @ Bh / T
        return stiffness(xy, "all", Dc, T)
    if kind == "d_stick":
        D3 = D4.copy()
        D3[2, :] = 0.0
        D3[:, 2] = 0.0
        return np.pi * rbar * Bh.T @ D3 @ Bh / T
    return stiffness(xy, {"e_stick": "scalar", "c_stick": "all", "b_stick": "grad"}[kind], D4, T)


def patch(N, kind, r0=1.0, r1=2.0, E=(1.0, 1.0), nu=(0.3, 0.3), p=1.0, H1=0.5, H2=0.5, grade=0.0):
    # r nodes, optionally graded (non-uniform spacing)
    s = np.linspace(0.0, 1.0, N + 1)
    r = r0 + (r1 - r0) * (s + grade * s * (1 - s))
    h = (r1 - r0) / N
    nz1 = max(2, int(round(H1 / h)))
    nz2 = max(2, int(round(H2 / h)))
    pl, tl, il = block(r, np.linspace(-H1, 0.0, nz1 + 1), 0)
    pu, tu, iu = block(r, np.linspace(0.0, H2, nz2 + 1), len(pl))
    pts = np.vstack([pl, pu])
    n = 2 * len(pts)
    D = [dmat(E[0], nu[0]), dmat(E[1], nu[1])]
    Ec = min(E)
    I, Jc, V = [], [], []

    def add(t, Ke):
        dofs = np.ravel(np.column_stack([2 * np.asarray(t), 2 * np.asarray(t) + 1]))
        I.append(np.repeat(dofs, 6))
        Jc.append(np.tile(dofs, 6))
        V.append(Ke.ravel())

    bulk = [(t, 0) for t in tl] + [(t, 1) for t in tu]
    for t, b in bulk:
        Jm = h ** 3 / LAMBDA
        add(t, stiffness(pts[list(t)], "plain", D[b], Jm))
    L, U = il[-1], iu[0]
    bels = []
    hc = np.diff(r).min()
    for i in range(N):
        for t in ((L[i], L[i + 1], U[i + 1]), (L[i], U[i + 1], U[i])):
            le = r[i + 1] - r[i]
            T = le * hc ** 2 / LAMBDA
            add(t, bel(pts[list(t)], kind, Ec, D[0] if E[0] <= E[1] else D[1], T))
            bels.append(t)
    K = sp.csr_matrix((np.concatenate(V), (np.concatenate(I), np.concatenate(Jc))), shape=(n, n))
    F = np.zeros(n)
    top = iu[-1]
    for i in range(N):  # consistent load of -p over the top edge, weight 2 pi r
        a, b = r[i], r[i + 1]
        le = b - a
        F[2 * top[i] + 1] += -p * 2 * np.pi * le * (2 * a + b) / 6
        F[2 * top[i + 1] + 1] += -p * 2 * np.pi * le * (a + 2 * b) / 6
    fixed = np.zeros(n, bool)
    fixed[2 * il[0] + 1] = True  # rollers
    if r0 == 0.0:
        ax = np.where(pts[:, 0] == 0.0)[0]
        fixed[2 * ax] = True
    free = ~fixed
    u = np.zeros(n)
    u[free] = spla.spsolve(K[free][:, free].tocsc(), F[free])
    # stresses at the centroids of the bulk elements
    err = 0.0
    for t, b in bulk:
        xy = pts[list(t)]
        J, rbar, Bh, H = parts(xy)
        dofs = np.ravel(np.column_stack([2 * np.asarray(t), 2 * np.asarray(t) + 1]))
        sig = D[b] @ ((Bh / J + H) @ u[dofs])
        err = max(err, np.abs(sig - np.array([0.0, -p, 0.0, 0.0])).max() / p)
    # openings of the B elements (linearised, frictionless reading): m^T Bhat u, m = e_zz
    opn = []
    for t in bels:
        J, rbar, Bh, H = parts(pts[list(t)])
        dofs = np.ravel(np.column_stack([2 * np.asarray(t), 2 * np.asarray(t) + 1]))
        opn.append((Bh @ u[dofs])[1])
    opn = np.array(opn)
    return err, opn.max(), opn.min()


if __name__ == "__main__":
    cases = [
        ("equal blocks E=1, nu=0.3, r in [1,2], uniform", dict(r0=1.0, r1=2.0)),
        ("equal blocks, r in [0,1] (axis)", dict(r0=0.0, r1=1.0)),
        ("equal blocks, r in [1,2], graded spacing", dict(r0=1.0, r1=2.0, grade=0.6)),
        ("upper 10x stiffer, nu 0.3/0.2, r in [0,1] (axis)", dict(r0=0.0, r1=1.0, E=(1.0, 10.0), nu=(0.3, 0.2))),
    ]
    kinds = ("d_fric", "c_fric", "d_stick", "e_stick", "c_stick", "b_stick")
    for title, kw in cases:
        print(f"\n-- {title}: max over bulk elements |sigma_h - sigma|/p  [largest opening, must be < 0]")
        print(f"{'B law':>8} " + " ".join(f"{'h=1/' + str(N):>22}" for N in (4, 8, 16, 32)))
        for k in kinds:
            if "stick" in k and kw.get("E", (1, 1))[0] != kw.get("E", (1, 1))[1]:
                continue
            cells = []
            for N in (4, 8, 16, 32):
                e, omax, omin = patch(N, k, **kw)
                cells.append(f"{e:9.2e} [{omax:+9.2e}]")
            print(f"{k:>8} " + " ".join(f"{c:>22}" for c in cells))
