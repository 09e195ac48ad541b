#!/usr/bin/python3
"""First period of a clamped-free Timoshenko beam (shear deformation and
rotary inertia), the reference of the cantilever benchmark until the FE
reference solver exists. Finite elements with linear w and theta and
one-point (reduced) shear integration, refined until converged.
Usage: timoshenko_period.py [L H E nu rho [shear_coefficient]]
Prints T_Timoshenko, T_EB and their ratio. Plane stress: G = E/(2(1+nu));
the shear coefficient defaults to Cowper's 10(1+nu)/(12+11nu)."""
import math
import sys

import numpy as np


def period(L, H, E, nu, rho, k, n):
    A, I, G = H, H**3 / 12, E / (2 * (1 + nu))
    le = L / n
    ndof = 2 * (n + 1)  # (w, theta) per node
    K = np.zeros((ndof, ndof))
    M = np.zeros((ndof, ndof))
    # bending: EI theta'^2 (exact for linear theta)
    kb = E * I / le * np.array([[0, 0, 0, 0], [0, 1, 0, -1],
                                [0, 0, 0, 0], [0, -1, 0, 1]])
    # shear: kGA (w' - theta)^2 at the element midpoint
    b = np.array([-1 / le, -0.5, 1 / le, -0.5])
    ks = k * G * A * le * np.outer(b, b)
    # consistent mass: rho A w^2 + rho I theta^2
    mm = le / 6 * np.array([[2, 1], [1, 2]])
    me = np.zeros((4, 4))
    me[np.ix_([0, 2], [0, 2])] = rho * A * mm
    me[np.ix_([1, 3], [1, 3])] = rho * I * mm
    for e in range(n):
        idx = slice(2 * e, 2 * e + 4)
        K[idx, idx] += kb + ks
        M[idx, idx] += me
    free = slice(2, ndof)  # clamped at x = 0
    Kf, Mf = K[free, free], M[free, free]
    lam = np.linalg.eigvals(np.linalg.solve(Mf, Kf)).real
    return 2 * math.pi / math.sqrt(lam[lam > 0].min())


def main():
    a = [float(v) for v in sys.argv[1:]]
    L, H, E, nu, rho = a[:5] if len(a) >= 5 else (1, 0.1, 1e7, 0.3, 1000)
    k = a[5] if len(a) > 5 else 10 * (1 + nu) / (12 + 11 * nu)
    T = [period(L, H, E, nu, rho, k, n) for n in (200, 400)]
    T_EB = 2 * math.pi / (3.51602 * math.sqrt(E * H**3 / 12 / (rho * H * L**4)))
    print(f"T_Timoshenko = {T[1]:.6f} s  T_EB = {T_EB:.6f} s  "
          f"T_Timoshenko/T_EB = {T[1] / T_EB:.5f}  "
          f"(change over the last refinement {abs(T[1] / T[0] - 1):.1e})")


if __name__ == "__main__":
    main()
