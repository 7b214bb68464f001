"""Control: the same staggered cap band in PLANE STRAIN TFEM (K~ = Bhat^T D Bhat / (2 max(J, Jmin))),
patch field u = (0.1 x, 0.05 y + 0.02), f = 0, Dirichlet on the boundary; max nodal |u_h - u|.
Shows whether the O(h^2) patch-test defect of a tempered bulk band (study.py, section C) is
already TFEM's planar behaviour rather than something the axisymmetric variants add."""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
import fem
from element import dmat, parts

D4 = dmat(1.0, 0.3)
D3 = D4[np.ix_([0, 1, 3], [0, 1, 3])]
print(f"{'band':>10} " + " ".join(f"{'h=1/' + str(N):>10}" for N in (4, 8, 16, 32, 64)))
for name, bf in (("none", None), ("h/2", lambda h: h / 2), ("h^3", lambda h: h ** 3),
                 ("0", lambda h: 0.0), ("-h^3", lambda h: -h ** 3)):
    cells = []
    for N in (4, 8, 16, 32, 64):
        h = 1.0 / N
        pts, tris, bnd, h = fem.mesh(N, 0.0, 1.0, band=None if bf is None else bf(h))
        n = 2 * len(pts)
        I, J_, V = [], [], []
        for t in tris:
            J, rbar, Bh, H = parts(pts[t])
            B3 = Bh[[0, 1, 3]]
            Ke = B3.T @ D3 @ B3 / (2 * max(J, h ** 3))
            dofs = np.ravel(np.column_stack([2 * t, 2 * t + 1]))
            I.append(np.repeat(dofs, 6)); J_.append(np.tile(dofs, 6)); V.append(Ke.ravel())
        K = sp.csr_matrix((np.concatenate(V), (np.concatenate(I), np.concatenate(J_))), shape=(n, n))
        ue = np.zeros(n); ue[0::2] = 0.1 * pts[:, 0]; ue[1::2] = 0.05 * pts[:, 1] + 0.02
        fixed = np.repeat(bnd, 2); free = ~fixed
        u = ue.copy()
        u[free] = spla.spsolve(K[free][:, free].tocsc(), -K[free][:, fixed] @ ue[fixed])
        cells.append(f"{np.abs(u - ue).max():10.2e}")
    print(f"{name:>10} " + " ".join(cells))
