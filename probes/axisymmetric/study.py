"""Manufactured-solution, band and patch studies for the axisymmetric variants.

u_r = r^2 sin(z)/10, u_z = cos(r) z/10 on [1,2]x[0,1] (and [0,1]x[0,1], touching the axis),
E = 1, nu = 0.3, Dirichlet data on the whole boundary, Jmin = h^3 / lambda with lambda = 1.
Errors are relative, weighted L2 (measure 2 pi r dA).
"""
import sys
import numpy as np
import fem

NS = (4, 8, 16, 32, 64)
VARS = ("plain", "grad", "all", "planar", "scalar")
LAMBDA = 1.0


def rates(errs):
    return ["  -  "] + [f"{np.log2(errs[k - 1] / errs[k]):5.2f}" for k in range(1, len(errs))]


def run(variant, band_fn, r0=1.0, r1=2.0, uex=None, load=True):
    out = []
    for N in NS:
        h = 1.0 / N
        delta = None if band_fn is None else band_fn(h)
        pts, tris, bnd, h = fem.mesh(N, r0, r1, 0.0, 1.0, band=delta)
        Jmin = h ** 3 / LAMBDA
        if variant == "plain" and delta == 0.0:
            out.append((np.nan, np.nan, np.nan))
            continue
        try:
            u, ub, Js = fem.solve(pts, tris, bnd, variant, Jmin, uex=uex, load=load)
            if not np.all(np.isfinite(u)):
                raise FloatingPointError("non-finite")
            if load:
                out.append((fem.l2_error(pts, tris, u), Js.min(), Jmin))
            else:
                out.append((np.abs(u - ub).max(), Js.min(), Jmin))
        except Exception as ex:  # singular etc.
            out.append((np.nan, np.nan, Jmin))
            print(f"   [{variant} N={N}: {type(ex).__name__}: {ex}]")
    return out


def table(title, band_fn, r0=1.0, r1=2.0, variants=VARS):
    print(f"\n-- {title}")
    print(f"{'variant':>8} " + " ".join(f"{'h=1/' + str(N):>15}" for N in NS))
    res = {}
    for v in variants:
        o = run(v, band_fn, r0, r1)
        errs = [x[0] for x in o]
        res[v] = errs
        rs = rates(errs)
        print(f"{v:>8} " + " ".join(f"{e:9.3e} ({r})" for e, r in zip(errs, rs)))
    o = run("all", band_fn, r0, r1)
    print(f"{'minJ':>8} " + " ".join(f"{x[1]:15.3e}" for x in o))
    print(f"{'Jmin':>8} " + " ".join(f"{x[2]:15.3e}" for x in o))
    sys.stdout.flush()
    return res


def patch_uex(r, z):
    return 0.1 * r, 0.05 * z + 0.02 + 0 * r


def patch(title, band_fn, variants=VARS):
    print(f"\n-- patch test ({title}): u_r = 0.1 r, u_z = 0.05 z + 0.02, f = 0; max nodal |u_h - u|")
    print(f"{'variant':>8} " + " ".join(f"{'h=1/' + str(N):>10}" for N in NS))
    for v in variants:
        o = run(v, band_fn, uex=patch_uex, load=False)
        print(f"{v:>8} " + " ".join(f"{x[0]:10.2e}" for x in o))
    sys.stdout.flush()


if __name__ == "__main__":
    print("== A. regular meshes (J = h^2 >= Jmin = h^3 on every element) ==")
    table("r in [1,2], regular", None)
    table("r in [0,1] (touching the axis), regular", None, 0.0, 1.0)
    print("\n== B. band of cap-shaped elements at z = 1/2 (J = h*delta), Jmin = h^3 ==")
    table("band delta = h/2 (non-degenerate reference, same topology)", lambda h: h / 2)
    table("band delta = h^2 (J = h^3 = Jmin)", lambda h: h ** 2)
    table("band delta = h^3 (J = h^4 < Jmin)", lambda h: h ** 3)
    table("band delta = h^5 (J = h^6 << Jmin)", lambda h: h ** 5)
    table("band delta = 0 (zero-thickness band, J = 0)", lambda h: 0.0)
    table("band delta = -h^3 (inverted, J = -h^4)", lambda h: -h ** 3)
    table("band delta = -h^2 (inverted, J = -h^3 = -Jmin)", lambda h: -h ** 2)
    table("band delta = 0 on r in [0,1] (band touches the axis)", lambda h: 0.0, 0.0, 1.0)
    table("band delta = h^3 on r in [0,1] (band touches the axis)", lambda h: h ** 3, 0.0, 1.0)
    print("\n== C. patch test (homogeneous stress state, exact for the one-point rule) ==")
    patch("regular mesh", None)
    patch("band delta = 0 (conforming contact: zero-thickness band)", lambda h: 0.0)
    patch("band delta = h^3", lambda h: h ** 3)
    patch("band delta = -h^3", lambda h: -h ** 3)
    patch("band delta = h/2", lambda h: h / 2)
