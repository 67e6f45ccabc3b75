#!/usr/bin/env python3
"""bench/blanes_moan_criterion.py — is the printed Blanes-Moan S6 (and S10)
point a minimum of a 2-norm of its principal error?  (docs/published.md)

A minimiser of f (a norm of the principal error) on the family {g = 0} is
a stationary point: grad f lies in the span of the gradients of the order
conditions g.  For each norm tried this prints the relative residual
|grad f - J^T lambda| / |grad f| at the library's point (the exact member
nearest the printed coefficients, 40 certified digits): about 1e-7 at a
stationary point (the finite differences' noise), of order 1e-2 to 1 at a
point that is not one.  The log of the method is computed from scratch in
the free associative algebra on A (drift, T) and B (kick, V), truncated at
the degree of the principal error, in double; its part of that degree is
written in a basis of the free Lie algebra by least squares.

Norms: the Lie coordinates in the right-nested basis [X1,[X2,[...,[A,B]]]]
of Blanes and Moan's papers (degree 5), in the basis of standard bracketings
of Lyndon words, and the coefficients of the associative words.

Usage: python3 bench/blanes_moan_criterion.py   (numpy; a few seconds)
"""
import itertools
import numpy as np


def words(n):
    return ["".join(w) for w in itertools.product("AB", repeat=n)]


class Algebra:
    """Truncated free associative algebra: dense vectors over the words of
    length 0..D."""

    def __init__(self, D):
        self.D = D
        self.words = [w for n in range(D + 1) for w in words(n)]
        self.index = {w: i for i, w in enumerate(self.words)}
        n = len(self.words)
        self.pairs = [(i, j, self.index[u + v]) for i, u in enumerate(self.words)
                      for j, v in enumerate(self.words) if len(u) + len(v) <= D]
        self.pi = np.array([p[0] for p in self.pairs])
        self.pj = np.array([p[1] for p in self.pairs])
        self.pk = np.array([p[2] for p in self.pairs])
        self.n = n

    def mul(self, x, y):
        r = np.zeros(self.n)
        np.add.at(r, self.pk, x[self.pi] * y[self.pj])
        return r

    def exp_letter(self, letter, c):
        r = np.zeros(self.n)
        t = 1.0
        r[0] = 1.0
        for k in range(1, self.D + 1):
            t = t * c / k
            r[self.index[letter * k]] = t
        return r

    def log(self, g):
        y = g.copy()
        y[0] = 0.0
        r = np.zeros(self.n)
        p = np.zeros(self.n)
        p[0] = 1.0
        for k in range(1, self.D + 1):
            p = self.mul(p, y)
            r += (-1) ** (k + 1) * p / k
        return r

    def method_log(self, steps):
        g = np.zeros(self.n)
        g[0] = 1.0
        for letter, c in steps:
            g = self.mul(g, self.exp_letter(letter, c))
        return self.log(g)

    def degree(self, x, d):
        return np.array([x[self.index[w]] for w in words(d)])


def bracket(x, y):
    r = {}
    for u, a in x.items():
        for v, b in y.items():
            r[u + v] = r.get(u + v, 0) + a * b
            r[v + u] = r.get(v + u, 0) - a * b
    return r


def letter(c):
    return {c: 1.0}


def right_nested(w):
    x = bracket(letter(w[-2]), letter(w[-1]))
    for c in reversed(w[:-2]):
        x = bracket(letter(c), x)
    return x


def is_lyndon(w):
    return all(w < w[i:] + w[:i] for i in range(1, len(w)))


def standard(w):
    if len(w) == 1:
        return letter(w)
    for i in range(1, len(w)):
        if is_lyndon(w[i:]):
            return bracket(standard(w[:i]), standard(w[i:]))


def basis_matrix(basis, d):
    return np.array([[b.get(w, 0.0) for b in basis] for w in words(d)])


def coordinates(M, v):
    c, *_ = np.linalg.lstsq(M, v, rcond=None)
    return c


def s6_steps(x):
    a1, a2, a3, b1, b2 = x
    a = [a1, a2, a3, 1 - 2 * (a1 + a2 + a3), a3, a2, a1]
    b = [b1, b2, 0.5 - (b1 + b2)]
    b = b + b[::-1]
    steps = []
    for i in range(6):
        steps += [("A", a[i]), ("B", b[i])]
    return steps + [("A", a[6])]


def s10_steps(x):
    a, b = list(x[:5]), list(x[5:9])
    a6 = 1 - 2 * sum(a)
    b5 = 0.5 - sum(b)
    a_all = a + [a6] + a[::-1]
    b_all = b + [b5, b5] + b[::-1]
    steps = []
    for i in range(10):
        steps += [("A", a_all[i]), ("B", b_all[i])]
    return steps + [("A", a_all[10])]


def residual(alg, steps_of, x0, cond_degrees, cond_bases, err_degree, norms, eps=1e-6):
    """relative stationarity residual of each norm at x0"""
    def conditions(X):
        return np.concatenate([coordinates(cond_bases[d], alg.degree(X, d)) for d in cond_degrees])

    def values(x):
        X = alg.method_log(steps_of(x))
        e = alg.degree(X, err_degree)
        return conditions(X), {k: f(e) for k, f in norms.items()}

    g0, _ = values(x0)
    n = len(x0)
    J = np.zeros((len(g0), n))
    G = {k: np.zeros(n) for k in norms}
    for i in range(n):
        xp, xm = x0.copy(), x0.copy()
        xp[i] += eps
        xm[i] -= eps
        gp, fp = values(xp)
        gm, fm = values(xm)
        J[:, i] = (gp - gm) / (2 * eps)
        for k in norms:
            G[k][i] = (fp[k] - fm[k]) / (2 * eps)
    out = {}
    for k, grad in G.items():
        lam, *_ = np.linalg.lstsq(J.T, grad, rcond=None)
        out[k] = np.linalg.norm(J.T @ lam - grad) / np.linalg.norm(grad)
    return np.max(np.abs(g0)), out


def ma2_steps(x):
    b1, a1 = x
    return [("B", b1), ("A", a1), ("B", 1 - b1), ("A", 1 - a1)]


def main():
    # the control: McLachlan and Atela's optimal second-order method, a
    # stationary point of the Lyndon norm of its principal error (degree 3)
    alg3 = Algebra(3)
    cond2 = {2: basis_matrix([standard("AB")], 2)}
    ly3 = basis_matrix([standard(w) for w in words(3) if is_lyndon(w)], 3)
    r2 = np.sqrt(2.0)
    worst, res = residual(alg3, ma2_steps, np.array([1 - r2 / 2, r2 / 2]), [2], cond2, 3,
                          {"Lyndon basis, standard bracketing": lambda e: np.sum(coordinates(ly3, e) ** 2)})
    print("control, McLachlan-Atela 2 (a known stationary point): order conditions at the point %.1e" % worst)
    for k, v in res.items():
        print("  %-45s relative residual %.3g" % (k, v))
    # S6: a1, a2, a3, b1, b2 (the library's 40 digits, read as doubles)
    s6 = np.array([0.07920369643119567419764962376313816651194, 0.3531729060497740368186655573031425943496,
                   -0.04206508035771952921517158087661579516925, 0.2095151066133620529724499860936093178064,
                   -0.1438517731798180379640962992327095997669])
    alg5 = Algebra(5)
    cond3 = {3: basis_matrix([standard(w) for w in words(3) if is_lyndon(w)], 3)}
    rn5 = basis_matrix([right_nested(w) for w in ["AAAAB", "BAAAB", "ABAAB", "BBAAB", "ABBAB", "BBBAB"]], 5)
    ly5 = basis_matrix([standard(w) for w in words(5) if is_lyndon(w)], 5)
    norms5 = {
        "right-nested basis (Blanes-Moan's E_5,j)": lambda e: np.sum(coordinates(rn5, e) ** 2),
        "Lyndon basis, standard bracketing": lambda e: np.sum(coordinates(ly5, e) ** 2),
        "coefficients of the associative words": lambda e: np.sum(e ** 2),
    }
    worst, res = residual(alg5, s6_steps, s6, [3], cond3, 5, norms5)
    print("S6 (order 4, 3 free parameters): order conditions at the point %.1e" % worst)
    for k, v in res.items():
        print("  %-45s relative residual %.3g" % (k, v))
    # S10: a1..a5, b1..b4
    s10 = np.array([0.05026276440039272276463501706551157802999, 0.4135143004283434774541367150491272930119,
                    0.04507988979439811148986108449994759793866, -0.1880548538195686184904252832565255703991,
                    0.5419606784507800123668921918616562122025,
                    0.1488164479010432804573382503624305490099, -0.1323858657677837561493469658764191817796,
                    0.06730760469218439924077148588987427738938, 0.4326664025781737116335833140130967131357])
    alg7 = Algebra(7)
    cond = {d: basis_matrix([standard(w) for w in words(d) if is_lyndon(w)], d) for d in (3, 5)}
    ly7 = basis_matrix([standard(w) for w in words(7) if is_lyndon(w)], 7)
    norms7 = {
        "Lyndon basis, standard bracketing": lambda e: np.sum(coordinates(ly7, e) ** 2),
        "coefficients of the associative words": lambda e: np.sum(e ** 2),
    }
    worst, res = residual(alg7, s10_steps, s10, [3, 5], cond, 7, norms7)
    print("S10 (order 6, 1 free parameter): order conditions at the point %.1e" % worst)
    for k, v in res.items():
        print("  %-45s relative residual %.3g" % (k, v))


if __name__ == "__main__":
    main()
