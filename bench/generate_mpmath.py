#!/usr/bin/env python3
"""generate_mpmath.py S DIGITS [trig] — the peer of `vigen generate`: the
same tableau (Lagrange at Gauss-Legendre nodes, or trig(S) at Gauss-Legendre
nodes) computed the way one does it by hand with mpmath, at mp.dps = DIGITS + 10,
with NO certification.  Prints "<median seconds> <runs>"."""
import sys
import time
from mpmath import mp, mpf, matrix, lu_solve, cos, sin, pi

def legendre_pair(n, x):
    """P_n(x) and P_{n-1}(x) by the three-term recurrence."""
    p0, p1 = mpf(1), x
    for k in range(2, n + 1):
        p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
    return (p1, p0) if n >= 1 else (p0, mpf(0))

def gauss_nodes(s):
    # Gauss-Legendre nodes on [0,1]: Newton from the classical initial guesses
    xs = []
    eps = mpf(10) ** (-mp.dps + 3)
    for k in range(1, s + 1):
        x = cos(pi * (k - mpf(1) / 4) / (s + mpf(1) / 2))
        for _ in range(200):
            p, q = legendre_pair(s, x)
            dp = s * (x * p - q) / (x * x - 1)
            dx = p / dp
            x -= dx
            if abs(dx) < eps:
                break
        xs.append((1 + x) / 2)
    return sorted(xs)

def lagrange_tableau(c):
    s = len(c)
    # coefficients of l_j by products of linear factors, then exact antiderivatives
    A = matrix(s, s)
    b = [mpf(0)] * s
    for j in range(s):
        poly = [mpf(1)]
        den = mpf(1)
        for k in range(s):
            if k == j:
                continue
            poly = [mpf(0)] + poly
            for m in range(len(poly) - 1):
                poly[m] -= c[k] * poly[m + 1]
            den *= c[j] - c[k]
        poly = [p / den for p in poly]
        anti = lambda x: sum(p * x ** (m + 1) / (m + 1) for m, p in enumerate(poly))
        b[j] = anti(mpf(1))
        for i in range(s):
            A[i, j] = anti(c[i])
    return A, b

def trig_tableau(c):
    s = len(c)
    def psi(i, t):
        k = (i + 1) // 2
        return mpf(1) if i == 0 else (cos(k * pi * t) if i % 2 == 1 else sin(k * pi * t))
    def ipsi(i, x):
        k = (i + 1) // 2
        if i == 0:
            return x
        return sin(k * pi * x) / (k * pi) if i % 2 == 1 else (1 - cos(k * pi * x)) / (k * pi)
    M = matrix(s, s)
    for i in range(s):
        for j in range(s):
            M[i, j] = psi(i, c[j])
    B = matrix([ipsi(i, mpf(1)) for i in range(s)])
    b = lu_solve(M, B)
    A = matrix(s, s)
    for i in range(s):
        col = lu_solve(M, matrix([ipsi(k, c[i]) for k in range(s)]))
        for j in range(s):
            A[i, j] = col[j]
    return A, [b[i] for i in range(s)]

def run(s, digits, trig):
    mp.dps = digits + 10
    c = gauss_nodes(s)
    A, b = trig_tableau(c) if trig else lagrange_tableau(c)
    At = matrix(s, s)
    for i in range(s):
        for j in range(s):
            At[i, j] = (b[i] * b[j] - b[j] * A[j, i]) / b[i]
    return A, At

def main():
    s, digits = int(sys.argv[1]), int(sys.argv[2])
    trig = len(sys.argv) > 3 and sys.argv[3] == "trig"
    times = []
    while len(times) < 3 or (sum(times) < 1.0 and len(times) < 51):
        t0 = time.perf_counter()
        run(s, digits, trig)
        times.append(time.perf_counter() - t0)
    times.sort()
    print("%.6f %d" % (times[len(times) // 2], len(times)))

if __name__ == "__main__":
    main()
