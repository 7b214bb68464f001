"""Element eigenvalue checks for the axisymmetric P1 variants (see element.py).

Prints:
  1. reproduction of the issue's numbers (nodes (1,0),(2,0),(1.5,t); J = t),
     both with the full-revolution measure 2*pi*rbar*J/2 and per radian (rbar*J/2);
  2. a sweep over t (regular, flat, inverted) and over axis-touching elements:
     min/max eigenvalue, the three smallest eigenvalues (relative to max) and the
     numerical null-space dimension (|lambda| <= 1e-10 * max|lambda|);
  3. energies of the modes u_z = 1 (rigid), u_r = 1 (not rigid: hoop strain 1/r),
     and the rotation about the centroid (zero-energy in the one-point rule).
"""
import numpy as np
from element import dmat, stiffness, parts

D = dmat(1.0, 0.3)
JMIN = 1e-3
TOL = 1e-10
SHOW = ("plain", "grad", "all", "planar", "scalar")


def eig(xy, v):
    return np.linalg.eigvalsh(stiffness(xy, v, D, JMIN))


def nulldim(e):
    return int(np.sum(np.abs(e) <= TOL * np.abs(e).max()))


def modes(xy):
    xy = np.asarray(xy, float)
    uz = np.tile([0.0, 1.0], 3)
    ur = np.tile([1.0, 0.0], 3)
    c = xy.mean(axis=0)
    rot = np.ravel(np.column_stack([-(xy[:, 1] - c[1]), xy[:, 0] - c[0]]))
    return {"u_z=1": uz, "u_r=1": ur, "rot@centroid": rot}


def part1():
    print("== 1. issue reproduction: nodes (1,0),(2,0),(1.5,t), E=1, nu=0.3, Jmin=1e-3 ==")
    for scale, name in ((1.0, "2*pi*rbar*J/2 (full revolution)"), (1 / (2 * np.pi), "rbar*J/2 (per radian)")):
        print(f"-- measure {name}")
        print(f"{'J':>8} {'variant':>8} {'min eig':>12} {'max eig':>12}")
        for t in (1e-5, -0.1, -1.0):
            xy = np.array([[1, 0], [2, 0], [1.5, t]], float)
            for v in ("grad", "all", "scalar"):
                e = scale * eig(xy, v)
                print(f"{t:8.0e} {v:>8} {e.min():12.4e} {e.max():12.4e}")


def part2():
    print()
    print("== 2. sweep (full-revolution measure), Jmin=1e-3; nd = numerical null dim (|l|<=1e-10 max) ==")
    ts = [1.0, 0.5, 0.1, 1e-2, 2e-3, 1e-3, 5e-4, 1e-4, 1e-5, 0.0, -1e-5, -1e-3, -1e-2, -0.1, -0.5, -1.0]
    geoms = []
    for t in ts:
        geoms.append((f"(1,0),(2,0),(1.5,{t:g})", np.array([[1, 0], [2, 0], [1.5, t]], float)))
    for t in (1.0, 1e-2, 1e-5, 0.0, -1e-2, -1.0):
        geoms.append((f"axis: (0,0),(1,0),(0.5,{t:g})", np.array([[0, 0], [1, 0], [0.5, t]], float)))
    for t in (1.0, 1e-5, 0.0, -1.0):
        geoms.append((f"axis2: (0,0),(1,0),(0,{t:g})", np.array([[0, 0], [1, 0], [0, t]], float)))
    # flat along z (collinear nodes parallel to the axis), touching the axis
    for s in (1.0, 1e-5, -1e-5, -1.0):  # s = 0 would put all nodes on the axis (rbar = 0): excluded
        geoms.append((f"axisz: (0,0),({s:g},0.5),(0,1)", np.array([[0, 0], [s, 0.5], [0, 1]], float)))
    hdr = f"{'element':>32} {'J':>9} " + " ".join(f"{v:>24}" for v in SHOW)
    print(hdr)
    print(f"{'':>32} {'':>9} " + " ".join(f"{'min eig    max eig  nd':>24}" for v in SHOW))
    for name, xy in geoms:
        J = parts(xy)[0]
        cells = []
        for v in SHOW:
            if v == "plain" and J == 0.0:
                cells.append(f"{'undefined (J=0)':>24}")
                continue
            e = eig(xy, v)
            cells.append(f"{e.min():+10.2e} {e.max():+10.2e} {nulldim(e):2d}".rjust(24))
        print(f"{name:>32} {J:9.2e} " + " ".join(cells))


def part3():
    print()
    print("== 3. mode energies u^T K u (full revolution), element (1,0),(2,0),(1.5,t) ==")
    print(f"{'t':>8} {'mode':>14} " + " ".join(f"{v:>11}" for v in SHOW))
    for t in (1.0, 1e-5, 0.0, -0.1, -1.0):
        xy = np.array([[1, 0], [2, 0], [1.5, t]], float)
        for mname, u in modes(xy).items():
            vals = []
            for v in SHOW:
                if v in ("plain",) and t == 0.0:
                    vals.append(f"{'undef':>11}")
                    continue
                K = stiffness(xy, v, D, JMIN)
                vals.append(f"{u @ K @ u:11.3e}")
            print(f"{t:8g} {mname:>14} " + " ".join(vals))
    print()
    print("-- smallest 4 eigenvalues (full revolution) at selected t --")
    for t in (1.0, 1e-5, 0.0, -0.1, -1.0):
        xy = np.array([[1, 0], [2, 0], [1.5, t]], float)
        for v in SHOW:
            if v in ("plain", "planar") and t == 0.0 and v == "plain":
                continue
            e = eig(xy, v)
            print(f"t={t:<6g} {v:>7}: " + " ".join(f"{x:+.3e}" for x in e[:4]) + f"   max {e.max():.3e}")


if __name__ == "__main__":
    part1()
    part2()
    part3()


def part4():
    print()
    print("== 4. continuity in J at J = Jmin and J = 0: ||K(J+) - K(J-)|| / ||K(J+)|| (Frobenius), element (1,0),(2,0),(1.5,t) ==")
    for J0 in (JMIN, 0.0):
        for v in ("grad", "all", "planar", "scalar"):
            d = 1e-12
            Kp = stiffness(np.array([[1, 0], [2, 0], [1.5, J0 + d]]), v, D, JMIN)
            Km = stiffness(np.array([[1, 0], [2, 0], [1.5, J0 - d]]), v, D, JMIN)
            print(f"J = {J0:g}: {v:>7}: {np.linalg.norm(Kp - Km) / np.linalg.norm(Kp):.3e}")


if __name__ == "__main__":
    part4()
