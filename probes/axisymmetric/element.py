"""P1 axisymmetric elasticity element, one-point (centroid) rule, and tempered variants.

Coordinates x = r >= 0, y = z.  Dofs per node: (u_r, u_z); element dof order
[u_r1, u_z1, u_r2, u_z2, u_r3, u_z3].  Strain vector [eps_rr, eps_zz, eps_tt, gamma_rz].

Notation (for nodes i, j, k cyclic):
    b_i = z_j - z_k,  c_i = r_k - r_j,  J = sum_i r_i b_i = 2 * signed area.
    Bhat (4x6): "unnormalised" gradient rows, J * (gradient rows of B); hoop row zero.
        row rr: [b_i, 0], row zz: [0, c_i], row tt: [0, 0], row rz: [c_i, b_i]
    H (4x6): hoop row only, row tt: [1/(3 rbar), 0]   (N_i(centroid) = 1/3)
    Plain B = Bhat / J + H, plain measure 2*pi*rbar*J/2.

    K_plain = 2 pi rbar (J/2) (Bhat/J + H)^T D (Bhat/J + H)
            = pi rbar [ Bhat^T D Bhat / J  +  (Bhat^T D H + H^T D Bhat)  +  J H^T D H ]
              (gradient-gradient ~ rbar/J, gradient-hoop ~ J^0, hoop-hoop ~ J)

Variants (Jt = max(J, Jmin)):
  'plain'  (a)  as above (undefined at J = 0).
  'grad'   (b)  pi rbar [ Bhat^T D Bhat / Jt + cross + J H^T D H ]     (issue's "temper 1/J only")
  'all'    (c)  pi rbar [ Bhat^T D Bhat / Jt + cross + Jt H^T D H ]
                = 2 pi rbar (Jt/2) (Bhat/Jt + H)^T D (Bhat/Jt + H)         (J -> Jt everywhere)
  'planar' (d)  plain for J >= Jmin; for J < Jmin: pi rbar Bhat^T D Bhat / Jt
                (planar tempered element, weighted 2 pi rbar, no hoop row)
  'planar_all' (d') pi rbar Bhat^T D Bhat / Jt for every element (no hoop row anywhere;
                this is NOT a consistent axisymmetric discretisation, reported only as a check)
  'scalar' (e)  (J/Jt) * K_plain  (literal tfem rule K~ = J/max(J,Jmin) K)
                = pi rbar / Jt (Bhat + J H)^T D (Bhat + J H)
                = pi rbar [ Bhat^T D Bhat / Jt + (J/Jt) cross + (J^2/Jt) H^T D H ]
"""
import numpy as np

VARIANTS = ("plain", "grad", "all", "planar", "planar_all", "scalar")


def dmat(E=1.0, nu=0.3):
    """4x4 isotropic D for [eps_rr, eps_zz, eps_tt, gamma_rz]."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    D = np.zeros((4, 4))
    D[:3, :3] = lam
    D[0, 0] = D[1, 1] = D[2, 2] = lam + 2 * mu
    D[3, 3] = mu
    return D


def parts(xy):
    """Return (J, rbar, Bhat, H) for a triangle xy (3x2 array of (r, z))."""
    r = xy[:, 0]
    z = xy[:, 1]
    b = np.array([z[1] - z[2], z[2] - z[0], z[0] - z[1]])
    c = np.array([r[2] - r[1], r[0] - r[2], r[1] - r[0]])
    J = float(r @ b)
    rbar = float(r.mean())
    Bh = np.zeros((4, 6))
    H = np.zeros((4, 6))
    for i in range(3):
        Bh[0, 2 * i] = b[i]
        Bh[1, 2 * i + 1] = c[i]
        Bh[3, 2 * i] = c[i]
        Bh[3, 2 * i + 1] = b[i]
        H[2, 2 * i] = 1.0 / (3.0 * rbar)
    return J, rbar, Bh, H


def stiffness(xy, variant, D, Jmin):
    xy = np.asarray(xy, float)
    J, rbar, Bh, H = parts(xy)
    Jt = max(J, Jmin)
    gg = Bh.T @ D @ Bh
    cross = Bh.T @ D @ H + H.T @ D @ Bh
    hh = H.T @ D @ H
    pr = np.pi * rbar
    if variant == "plain":
        K = pr * (gg / J + cross + J * hh)
    elif variant == "grad":
        K = pr * (gg / Jt + cross + J * hh)
    elif variant == "all":
        K = pr * (gg / Jt + cross + Jt * hh)
    elif variant == "planar":
        K = pr * (gg / J + cross + J * hh) if J >= Jmin else pr * gg / Jt
    elif variant == "planar_all":
        K = pr * gg / Jt
    elif variant == "scalar":
        K = pr * (gg / Jt + (J / Jt) * cross + (J * J / Jt) * hh)
    else:
        raise ValueError(variant)
    return 0.5 * (K + K.T)


def check_formulas():
    """Cross-check the block formulas against the direct B^T D B form."""
    D = dmat()
    rng = np.random.default_rng(0)
    worst = 0.0
    for _ in range(200):
        xy = rng.uniform(0.1, 2.0, (3, 2))
        J, rbar, Bh, H = parts(xy)
        Jmin = 1e-3
        Jt = max(J, Jmin)
        for v, Bm, meas in (("plain", Bh / J + H, J), ("all", Bh / Jt + H, Jt)):
            Kd = 2 * np.pi * rbar * meas / 2 * Bm.T @ D @ Bm
            K = stiffness(xy, v, D, Jmin)
            worst = max(worst, np.abs(K - Kd).max() / np.abs(Kd).max())
        Ks = stiffness(xy, "scalar", D, Jmin)
        Kp = stiffness(xy, "plain", D, Jmin)
        worst = max(worst, np.abs(Ks - J / Jt * Kp).max() / np.abs(Ks).max())
    return worst


if __name__ == "__main__":
    print("max rel. difference block formulas vs direct B^T D B:", check_formulas())
