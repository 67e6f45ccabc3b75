#!/usr/bin/env python3
"""stability_direct.py TABLEAU.lua [XMAX] — the linear stability interval of a
PRK tableau on q'' = -omega^2 q, computed directly and independently of vigen:
for each x = h omega the 2s stage equations Q = q0 + x A P, P = p0 - x At Q are
solved by Gaussian elimination (floats), the step matrix R(x) is formed from
its two columns, and the method is stable when both eigenvalues of R lie in
the closed unit disk (|tr| <= 1 + det, det <= 1).  The first x where that
fails is found by a scan (step 1e-3) and bisection; prints it, or "unbounded"
when no failure is found up to XMAX (default 40).

The tableau is read from the file's entry strings (decimals and arithmetic
with ^ and sqrt), not through vigen."""
import math
import re
import sys


def table(text, name):
    m = re.search(r'\n  ' + name + r' = \{', text)
    if not m:
        return None
    i, depth = m.end(), 1
    while depth:
        depth += {'{': 1, '}': -1}.get(text[i], 0)
        i += 1
    body = re.sub(r'--[^\n]*', '', text[m.end():i - 1])
    return [evaluate(e) for e in re.findall(r'"([^"]*)"', body)]


def evaluate(e):
    return float(eval(e.replace('^', '**'), {'__builtins__': {}}, {'sqrt': math.sqrt}))


def solve(M, r):
    n = len(r)
    M = [row[:] + [r[i]] for i, row in enumerate(M)]
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(M[i][k]))
        M[k], M[p] = M[p], M[k]
        for i in range(k + 1, n):
            f = M[i][k] / M[k][k]
            for j in range(k, n + 1):
                M[i][j] -= f * M[k][j]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (M[i][n] - sum(M[i][j] * x[j] for j in range(i + 1, n))) / M[i][i]
    return x


def step(x, s, A, At, b, bt):
    R = [[0.0, 0.0], [0.0, 0.0]]
    for col, (q0, p0) in enumerate(((1.0, 0.0), (0.0, 1.0))):
        M = [[0.0] * (2 * s) for _ in range(2 * s)]
        r = [q0] * s + [p0] * s
        for i in range(s):
            M[i][i] = 1.0
            M[s + i][s + i] = 1.0
            for j in range(s):
                M[i][s + j] = -x * A[i * s + j]
                M[s + i][j] = x * At[i * s + j]
        z = solve(M, r)
        R[0][col] = q0 + x * sum(b[i] * z[s + i] for i in range(s))
        R[1][col] = p0 - x * sum(bt[i] * z[i] for i in range(s))
    return R


def stable(x, tab):
    R = step(x, *tab)
    tr, det = R[0][0] + R[1][1], R[0][0] * R[1][1] - R[0][1] * R[1][0]
    return abs(tr) <= 1 + det + 1e-12 and det <= 1 + 1e-12


def main():
    text = open(sys.argv[1]).read()
    xmax = float(sys.argv[2]) if len(sys.argv) > 2 else 40.0
    A, b = table(text, 'A'), table(text, 'b')
    s = len(b)
    At = table(text, 'At') or A
    bt = table(text, 'bt') or b
    tab = (s, A, At, b, bt)
    x = 1e-3
    while x < xmax and stable(x, tab):
        x += 1e-3
    if x >= xmax:
        print('unbounded')
        return
    lo, hi = x - 1e-3, x
    for _ in range(60):
        mid = (lo + hi) / 2
        if stable(mid, tab):
            lo = mid
        else:
            hi = mid
    print('%.12f' % lo)


main()
