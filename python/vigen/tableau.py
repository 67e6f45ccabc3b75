"""Tableaux: the coefficients of a partitioned Runge-Kutta method as exact
decimal texts, generated from a spec (``vigen generate``) or read from a
file, with NumPy and mpmath views, LaTeX, and the tableau file."""
import json
import os
import tempfile

from . import _native

_DEFAULT_DIGITS = 34


class Tableau:
    """The tableau (c, A, b; ct, At, bt) of a partitioned Runge-Kutta method.

    The entries are decimal texts exactly as vigen writes them (certified to
    ``digits`` significant digits for a generated tableau; as the file
    states them for a tableau file, exact entries printed as certified
    decimals): ``c``, ``b`` lists of str, ``A`` a list of rows. ``ct``,
    ``At``, ``bt`` are those of the second part (the momenta), or None when
    the file gives one Runge-Kutta method for both parts.

    Build one with :func:`vigen.generate` or :meth:`Tableau.from_file`; do
    not construct it directly.

    Attributes:
        name: the method's name.
        s: the number of stages.
        digits: the significant digits of the decimal texts.
        text: the tableau file (what ``vigen generate -o`` writes).
        path: the file it was read from (None for a generated tableau).
        summary: for a generated tableau, the line ``vigen generate`` prints
            on standard error (stages, digits, symplecticity residual).
    """

    def __init__(self, entries, text, digits, path=None, summary=None):
        self.name = entries["name"]
        self.s = entries["s"]
        self.c = entries["c"]
        self.A = entries["A"]
        self.b = entries["b"]
        self.ct = entries.get("ct")
        self.At = entries.get("At")
        self.bt = entries.get("bt")
        self.text = text
        self.digits = digits
        self.path = path
        self.summary = summary

    def __repr__(self):
        return f"<vigen.Tableau {self.name!r}: {self.s} stages, {self.digits} digits>"

    def __eq__(self, other):
        return isinstance(other, Tableau) and self.text == other.text

    __hash__ = None

    def _parts(self):
        """The six arrays of entries, the second part filled from the first."""
        return {
            "c": self.c, "A": self.A, "b": self.b,
            "ct": self.ct if self.ct is not None else self.c,
            "At": self.At if self.At is not None else self.A,
            "bt": self.bt if self.bt is not None else self.b,
        }

    def to_numpy(self, dtype=None):
        """The entries as NumPy arrays: a dict with the keys ``"c"``,
        ``"A"``, ``"b"``, ``"ct"``, ``"At"``, ``"bt"`` (the second part equal
        to the first when the file gives one method). dtype: float64 by
        default; ``numpy.longdouble`` reads the texts at long double
        precision."""
        import numpy as np

        dtype = np.float64 if dtype is None else dtype
        return {k: np.array(v, dtype=dtype) for k, v in self._parts().items()}

    def to_mpmath(self):
        """The entries as mpmath numbers (``mpmath.mpf``, read from the
        decimal texts at the working precision of ``mpmath.mp`` in force): a
        dict of ``mpmath.matrix`` for ``"A"``, ``"At"`` and lists for the
        vectors. Raises ImportError when mpmath is not installed."""
        import mpmath

        def conv(v):
            if v and isinstance(v[0], list):
                return mpmath.matrix([[mpmath.mpf(x) for x in row] for row in v])
            return [mpmath.mpf(x) for x in v]

        return {k: conv(v) for k, v in self._parts().items()}

    def to_file(self, path):
        """Writes the tableau file (the bytes ``vigen generate -o`` writes) to
        path, atomically: the file is the old one or the new one, never a
        part, and nothing is written when it fails. Raises ResourceError when
        the file cannot be written."""
        data = _native.encode(path, "path", "generate")
        if data == b"-":          # a file named "-", not standard output
            data = b"./-"
        _native.call("vigen_python_write_file", b"generate", data, self.text.encode("utf-8", "surrogateescape"))

    @classmethod
    def from_file(cls, path, digits=_DEFAULT_DIGITS):
        """Reads a method file: a tableau file (its entries as written) or a
        spec (generated at ``digits`` digits), or a method name of the
        library. Its ``text`` is the tableau file ``vigen show --format lua``
        prints, which is the file itself for a file vigen wrote."""
        operand = _native.encode(path, "path", "show")
        lua, _, _, _ = _native.call("vigen_python_show", operand, b"lua", _native.whole(digits, "digits"))
        entries, _, _, _ = _native.call("vigen_python_show", operand, b"json", _native.whole(digits, "digits"))
        return cls(json.loads(entries), lua, digits, path=os.fspath(path))

    def latex(self, digits=None):
        """The tableau as LaTeX (``vigen show --format latex``): a Butcher
        array per part."""
        return self._show("latex", digits)

    def show(self, digits=None):
        """The tableau as ``vigen show`` prints it (text)."""
        return self._show("text", digits)

    def _show(self, fmt, digits):
        digits = _native.whole(self.digits if digits is None else digits, "digits")
        fmt = fmt.encode()
        with tempfile.TemporaryDirectory(prefix="vigen-") as tmp:
            name = os.path.join(tmp, "tableau.lua")
            with open(name, "w", encoding="utf-8", errors="surrogateescape") as f:
                f.write(self.text)
            out, _, _, _ = _native.call("vigen_python_show", _native.encode(name), fmt, digits)
        return out


def generate(spec, digits=_DEFAULT_DIGITS):
    """The tableau of a spec file (nodes and basis), certified to ``digits``
    significant digits, as ``vigen generate SPEC --digits N`` computes it;
    the order and symplecticity the checker certifies become the file's
    claims.

    Args:
        spec: the path of a spec file, or a name of the library.
        digits: significant digits of every entry (1 to 100000).

    Returns:
        A :class:`Tableau`; ``.to_file(path)`` writes the file ``vigen
        generate -o path`` writes.

    Raises:
        InputError: an unreadable or invalid spec, a tableau file instead of
            a spec, digits out of range.
        ResourceError: a cap of the sandbox or of the precision reached.
    """
    lua, entries, summary, _ = _native.call("vigen_python_generate", _native.encode(spec, "spec", "generate"),
                                            _native.whole(digits, "digits"))
    return Tableau(json.loads(entries), lua, digits, summary=summary)
