#!/usr/bin/env python3
"""bch_direct.py CHECK.json SUBSTEPS — checks the principal error in the Lyndon
basis that `vigen check --json` reports for a splitting (key lie_error),
independently of vigen's algorithm: for two random 5 x 5 matrices A and B,
log(exp(c1 h X1) exp(c2 h X2) ...) is expanded as a power series in h with
matrix coefficients (products of truncated exponential series, then the log
series), and its coefficient of h^n is compared with
sum_w coef_w P_w(A, B), each bracket of the report ("[A,[A,B]]") evaluated
as matrix commutators.  Generic matrices make the brackets of one degree
linearly independent, so agreement means the coefficients are right.

SUBSTEPS: "d:0.5,k:1,d:0.5" (d drift = A, k kick = B, coefficients as
Python expressions).  Prints the largest difference relative to the size
of the coefficient matrix; exit 1 above 1e-9."""
import json
import random
import sys

M = 5


def zeros():
    return [[0.0] * M for _ in range(M)]


def eye():
    z = zeros()
    for i in range(M):
        z[i][i] = 1.0
    return z


def add(x, y, a=1.0):
    return [[x[i][j] + a * y[i][j] for j in range(M)] for i in range(M)]


def mul(x, y):
    return [[sum(x[i][k] * y[k][j] for k in range(M)) for j in range(M)] for i in range(M)]


def scale(x, a):
    return [[a * x[i][j] for j in range(M)] for i in range(M)]


def series_mul(p, q, n):
    """power series in h with matrix coefficients, truncated at degree n"""
    r = [zeros() for _ in range(n + 1)]
    for a in range(n + 1):
        for b in range(n + 1 - a):
            r[a + b] = add(r[a + b], mul(p[a], q[b]))
    return r


def bracket(text, gens):
    """evaluates "[X,Y]" recursively"""
    def parse(i):
        if text[i] in gens:
            return gens[text[i]], i + 1
        assert text[i] == '['
        x, i = parse(i + 1)
        assert text[i] == ','
        y, i = parse(i + 1)
        assert text[i] == ']'
        return add(mul(x, y), mul(y, x), -1.0), i + 1
    v, i = parse(0)
    assert i == len(text)
    return v


def main():
    report = json.load(open(sys.argv[1]))
    le = report["lie_error"]
    n = le["degree"]
    random.seed(7)
    gens = {"A": [[random.uniform(-1, 1) for _ in range(M)] for _ in range(M)],
            "B": [[random.uniform(-1, 1) for _ in range(M)] for _ in range(M)]}
    prod = [eye()] + [zeros() for _ in range(n)]
    for item in sys.argv[2].split(","):
        kind, coef = item.split(":")
        c = float(eval(coef, {"__builtins__": {}}, {}))
        X = gens["A" if kind == "d" else "B"]
        e = [eye()]
        for k in range(1, n + 1):
            e.append(scale(mul(e[-1], X), c / k))
        prod = series_mul(prod, e, n)
    z = [zeros()] + prod[1:]
    log = [zeros() for _ in range(n + 1)]
    power = z
    for k in range(1, n + 1):
        log = [add(log[d], power[d], (1.0 if k % 2 else -1.0) / k) for d in range(n + 1)]
        power = series_mul(power, z, n)
    want = log[n]
    got = zeros()
    for t in le["terms"]:
        got = add(got, bracket(t["bracket"], gens), t["coefficient"])
    size = max(abs(v) for row in want for v in row)
    diff = max(abs(want[i][j] - got[i][j]) for i in range(M) for j in range(M))
    # the orders below n vanish (the method has the order the report says)
    low = max(abs(v) for d in range(2, n) for row in log[d] for v in row) if n > 2 else 0.0
    print("%.3e %.3e" % (diff / size, low))
    sys.exit(0 if diff <= 1e-9 * size and low <= 1e-9 else 1)


main()
