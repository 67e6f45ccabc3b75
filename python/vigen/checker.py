"""The checker: what a method is, certified in ball arithmetic
(``vigen check``), and several methods side by side (``vigen compare``)."""
import json

from . import _native


def _operand(method, command):
    """A method for the C interface: a name, a path, or a Tableau (its file)."""
    path = getattr(method, "path", None)
    if path is not None and hasattr(method, "to_file"):
        method = path
    return _native.encode(method, "method", command)


def check(method, *, against=None, max_order=None, prec=None):
    """Certifies what a method is, as ``vigen check --json`` does.

    Args:
        method: a method name of the library (``"gauss_2"``), the path of a
            tableau or spec file, or a Tableau read from a file.
        against: the path of a second tableau file whose entries every entry
            is compared with (``--against``).
        max_order: orders 1..max_order are checked (``--max-order``; default 8).
        prec: the starting working precision in bits (``--prec``).

    Returns:
        The dict ``vigen check --json`` prints: ``"order"``,
        ``"symplectic"``, ``"consistent"``, the error constants, the
        stability interval, ``"claims"``, ``"problems"`` (the failing or
        undecided conditions), ... A claim of the file that fails is reported
        there (as the command line's exit status 1 reports it), not raised.

    Raises:
        InputError: the file cannot be read or describes no method, an
            unknown name, an option out of range.
        ResourceError: a cap of the sandbox or of the precision was reached.
    """
    against_arg = _native.ffi.NULL if against is None else _native.encode(against, "against", "check")
    out, _, _, _ = _native.call("vigen_python_check", _operand(method, "check"), against_arg,
                                _native.whole(max_order, "max_order"), _native.whole(prec, "prec"))
    return json.loads(out)


def compare(*methods, format="json", max_order=None):
    """The checker's figures of several methods side by side, as ``vigen
    compare`` prints them: stages, design order, principal error constant,
    linear stability interval, cost and the efficiency measure.

    Args:
        *methods: method names or paths (at most 64).
        format: ``"json"`` (the default: the parsed object is returned),
            ``"text"`` or ``"latex"`` (the table is returned as a str).
        max_order: orders 1..max_order are checked (``--max-order``).

    Raises:
        InputError, ResourceError: as :func:`check`, naming the method.
    """
    if len(methods) == 1 and isinstance(methods[0], (list, tuple)):
        methods = tuple(methods[0])
    files = b"\n".join(_operand(m, "compare") for m in methods)
    out, _, _, _ = _native.call("vigen_python_compare", files, _native.encode(format, "format", "compare"),
                                _native.whole(max_order, "max_order"))
    return json.loads(out) if format == "json" else out
