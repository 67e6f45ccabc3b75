#!/usr/bin/env python3
"""gauss6_misrounded.py -- makes and verifies gauss6_misrounded75.lua.

make FILE95 OUT: from the 6-stage Gauss tableau printed with 95 digits
(`vigen generate` of gauss_legendre(6), monomials(6)), choose the RK tree t of
order <= 8 whose condition r(t) = b . Phi(t) - 1/gamma(t) has the most
cancellation in its gradient (the ratio sum_u dP/du rad_u / sum_u |dr/du|
rad_u, P the condition on |entries|), and print every entry of A with 75
significant digits on the side of the sign of dr/du, at least 0.6 units of the
last digit from the true value (so the ball of the printed decimal, +-0.5
units, excludes it: misrounded); b correctly rounded to 75 digits, c the
correctly rounded row sums of the printed A.

verify FILE: independently of vigen, in exact rationals, over the box of the
balls of A and b (c does not occur in tree conditions):
  r(x) in r(d) +- (sum_u |dr/du(d)| rad_u + R2),
  R2 = P(|d| + rad) - P(|d|) - sum_u rad_u dP/du(|d|),
and prints "fails ORDER TREE" when that interval excludes 0 (no tableau in
the balls satisfies the condition), exit 0; exit 1 otherwise.
"""
import random
import re
import sys
from fractions import Fraction as F
from decimal import Decimal, getcontext

getcontext().prec = 200


def read(path):
    text = open(path).read()
    def strings(s):
        return re.findall(r'"([-+0-9.eE]+)"', s)
    A_block = re.search(r'\bA\s*=\s*\{(.*?)\n\s*\},', text, re.S).group(1)
    rows = [strings(r) for r in re.findall(r'\{([^{}]*)\}', A_block)]
    b = strings(re.search(r'\bb\s*=\s*\{([^{}]*)\}', text).group(1))
    return rows, b


def ball(t):
    """The decimal t as an exact midpoint and half a unit of its last digit."""
    d = Decimal(t)
    return F(d), F(1, 2) * F(10) ** d.as_tuple().exponent


def trees(n):
    """RK trees of order n as sorted tuples of children."""
    if n == 1:
        return [()]
    out = set()
    def forests(m, maxt):
        if m == 0:
            yield ()
            return
        for k in range(m, 0, -1):
            for t in trees(k):
                key = (k, t)
                if maxt is not None and key > maxt:
                    continue
                for rest in forests(m - k, key):
                    yield ((k, t),) + rest
    for f in forests(n - 1, None):
        out.add(tuple(sorted(f, reverse=True)))
    return sorted(out)


def gamma(t):
    n = 1 + sum(k for k, _ in t)
    g = n
    for _, c in t:
        g *= gamma(c)
    return g


def order(t):
    return 1 + sum(k for k, _ in t)


def bracket(t):
    return "b" if not t else "b[" + ",".join(bracket(c) for _, c in t) + "]"


class D:
    """A value and its gradient with respect to the N entries."""
    def __init__(self, v, g):
        self.v, self.g = v, g

    def __add__(self, o):
        return D(self.v + o.v, [x + y for x, y in zip(self.g, o.g)])

    def __mul__(self, o):
        return D(self.v * o.v, [self.v * y + o.v * x for x, y in zip(self.g, o.g)])


def condition(t, A, b, one, zero):
    """b . Phi(t) over dual numbers A[i][j], b[i]."""
    s = len(b)
    N = len(b[0].g)
    def const(x):
        return D(x, [zero] * N)
    def phi(t):
        out = [const(one) for _ in range(s)]
        for _, c in t:
            p = phi(c)
            for i in range(s):
                w = const(zero)
                for j in range(s):
                    w = w + A[i][j] * p[j]
                out[i] = out[i] * w
        return out
    p = phi(t)
    r = const(zero)
    for i in range(s):
        r = r + b[i] * p[i]
    return r


def duals(A, b, one, zero):
    s = len(b)
    N = s * s + s
    def e(k, x):
        g = [zero] * N
        g[k] = one
        return D(x, g)
    DA = [[e(i * s + j, A[i][j]) for j in range(s)] for i in range(s)]
    Db = [e(s * s + i, b[i]) for i in range(s)]
    return DA, Db


def ratio(t, A, b):
    """Plain ball arithmetic's first-order radius over the mean-value one."""
    s = len(b)
    rad = [abs(x) * 1e-75 for row in A for x in row] + [abs(x) * 1e-75 for x in b]
    G = condition(t, *duals(A, b, 1.0, 0.0), 1.0, 0.0).g
    H = condition(t, *duals([[abs(x) for x in r] for r in A], [abs(x) for x in b], 1.0, 0.0), 1.0, 0.0).g
    mv = sum(abs(g) * r for g, r in zip(G, rad))
    pl = sum(h * r for h, r in zip(H, rad))
    return pl / mv if mv > 0 else 0, G


def decimal_at(x, sig, side, dist):
    """The decimal with sig significant digits on the given side of x (+1
    above, -1 below) at least dist units of its last digit away."""
    xd = Decimal(x.numerator) / Decimal(x.denominator)
    e = xd.adjusted() - (sig - 1)
    unit = F(10) ** e
    k = x / unit
    q = int(k.numerator // k.denominator)   # floor
    m = q
    if side > 0:
        m = q + 1
        while F(m) - k < dist:
            m += 1
    else:
        while k - F(m) < dist:
            m -= 1
    v = F(m) * unit
    return fmt(v, e), v


def fmt(v, e):
    """v = m 10^e exactly, as plain decimal text with every digit."""
    m = v / F(10) ** e
    assert m.denominator == 1
    m = m.numerator
    sign = "-" if m < 0 else ""
    digs = str(abs(m))
    if e >= 0:
        return sign + digs + "0" * e
    if len(digs) <= -e:
        digs = "0" * (-e - len(digs) + 1) + digs
    return sign + digs[:e] + "." + digs[e:]


def nearest(x, sig):
    xd = Decimal(x.numerator) / Decimal(x.denominator)
    e = xd.adjusted() - (sig - 1)
    unit = F(10) ** e
    k = x / unit
    m = round(k)
    return fmt(F(m) * unit, e)


def make(src, out):
    rows, bt = read(src)
    A = [[ball(x)[0] for x in r] for r in rows]
    b = [ball(x)[0] for x in bt]
    s = len(b)
    Af = [[float(x) for x in r] for r in A]
    bf = [float(x) for x in b]
    absA = [[abs(x) for x in r] for r in Af]
    absb = [abs(x) for x in bf]
    xs = [x for r in A for x in r]
    # in units of 1e-75: the last digit of each entry, its fractional position
    unit, frac = [], []
    for x in xs + b:
        e = (Decimal(x.numerator) / Decimal(x.denominator)).adjusted() - 74
        unit.append(10.0 ** (e + 75))
        k = x / F(10) ** e
        frac.append(float(k - k.numerator // k.denominator))
    rad = [0.5 * u for u in unit]
    info = []
    for n in range(1, 9):
        for t in trees(n):
            q, G = ratio(t, Af, bf)
            H = condition(t, *duals(absA, absb, 1.0, 0.0), 1.0, 0.0).g
            mv = sum(abs(g) * r for g, r in zip(G, rad))
            pl = sum(h * r for h, r in zip(H, rad))
            info.append((t, q, G, mv, pl))
    # the offset of entry k on side sg, at least 0.6 units away (first order:
    # r(d) - r(x) = G . offsets)
    def offset(k, sg):
        d = (1 - frac[k]) if sg > 0 else frac[k]
        while d < 0.6:
            d += 1
        return sg * d * unit[k]
    opts = [(offset(k, 1), offset(k, -1)) for k in range(s * s)]
    def score(sig, ti):
        delta = [opts[k][0 if sig[k] > 0 else 1] for k in range(s * s)]
        slack, target = 1e9, 0
        for i, (t, q, G, mv, pl) in enumerate(info):
            v = abs(sum(g * d for g, d in zip(G, delta)))
            slack = min(slack, 1 - v / pl)           # plain ball arithmetic: holds
            if i == ti:
                target = v / mv - 1                  # the mean-value form: fails
        return min(slack, target)
    # hill climbing over the sides, from the signs of the gradient of each of
    # the trees with the most cancellation
    random.seed(1)
    best = None
    for ti in sorted(range(len(info)), key=lambda i: -info[i][1])[:12]:
        sig = [1 if g > 0 else -1 for g in info[ti][2][:s * s]]
        cur = score(sig, ti)
        for _ in range(400):
            k = random.randrange(s * s)
            sig[k] = -sig[k]
            sc = score(sig, ti)
            if sc >= cur:
                cur = sc
            else:
                sig[k] = -sig[k]
        if best is None or cur > best[0]:
            best = (cur, ti, list(sig))
    cur, ti, sig = best
    assert cur > 0.2, cur
    t = info[ti][0]
    Atxt, Ad = [], []
    for i in range(s):
        row, rowd = [], []
        for j in range(s):
            txt, v = decimal_at(A[i][j], 75, sig[i * s + j], F(3, 5))
            row.append(txt)
            rowd.append(v)
        Atxt.append(row)
        Ad.append(rowd)
    btxt = [nearest(x, 75) for x in b]
    ctxt = [nearest(sum(r), 75) for r in Ad]
    q = lambda xs: ", ".join('"%s"' % x for x in xs)
    with open(out, "w") as f:
        f.write("-- The 6-stage Gauss method (order 12) printed with 75 digits, every entry\n"
                "-- of A MISROUNDED: at least 0.6 units of the last digit from the true value\n"
                "-- (no ball of A holds its true entry), on sides chosen so that the\n"
                "-- condition of the tree %s (order %d) fails for every\n"
                "-- tableau inside the balls while plain ball arithmetic, which adds the\n"
                "-- |terms| of its gradient that cancel, gives every condition up to order\n"
                "-- 8 a ball containing 0; b correctly rounded, c the correctly rounded row\n"
                "-- sums of this A.  Made by `gauss6_misrounded.py make` from `vigen\n"
                "-- generate` of gauss_legendre(6), monomials(6) at 95 digits;\n"
                "-- `gauss6_misrounded.py verify` proves the failure in exact rationals.\n"
                % (bracket(t), order(t)))
        f.write('return {\n  name = "gauss6_misrounded75",\n  s = %d,\n' % s)
        f.write("  c = { %s },\n" % q(ctxt))
        f.write("  A = {\n")
        for r in Atxt:
            f.write("    { %s },\n" % q(r))
        f.write("  },\n  b = { %s },\n}\n" % q(btxt))


def verify(path):
    rows, bt = read(path)
    A = [[ball(x) for x in r] for r in rows]
    b = [ball(x) for x in bt]
    s = len(b)
    mid_A = [[m for m, _ in r] for r in A]
    mid_b = [m for m, _ in b]
    rad = [r for row in A for _, r in row] + [r for _, r in b]
    absA = [[abs(m) for m in r] for r in mid_A]
    absb = [abs(m) for m in mid_b]
    hiA = [[abs(m) + r for m, r in row] for row in A]
    hib = [abs(m) + r for m, r in b]
    found = None
    for n in range(1, 9):
        for t in trees(n):
            r = condition(t, *duals(mid_A, mid_b, F(1), F(0)), F(1), F(0))
            val = r.v - F(1, gamma(t))
            first = sum(abs(g) * w for g, w in zip(r.g, rad))
            P = condition(t, *duals(absA, absb, F(1), F(0)), F(1), F(0))
            Phi = condition(t, *duals(hiA, hib, F(1), F(0)), F(1), F(0)).v
            R2 = Phi - P.v - sum(h * w for h, w in zip(P.g, rad))
            assert R2 >= 0
            if abs(val) > first + R2:
                found = (n, t, val, first + R2)
                break
        if found:
            break
    if not found:
        print("no condition of order <= 8 fails over the whole box")
        return 1
    n, t, val, bound = found
    print("fails %d %s value %.3e bound %.3e" % (n, bracket(t), float(val), float(bound)))
    return 0


if __name__ == "__main__":
    if sys.argv[1] == "make":
        make(sys.argv[2], sys.argv[3])
    else:
        sys.exit(verify(sys.argv[2]))
