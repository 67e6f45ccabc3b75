"""The checker: what a method is, certified in ball arithmetic
(``vigen check``), and several methods side by side (``vigen compare``)."""
import contextlib
import json
import os
import tempfile

from . import _native
from .tableau import Tableau


@contextlib.contextmanager
def _operands(methods, command):
    """The methods as the C interface takes them: names and paths as they
    are; a Tableau read from a file as that file; a generated Tableau as its
    tableau file, written to a temporary folder for the call."""
    with tempfile.TemporaryDirectory(prefix="vigen-") as tmp:
        out = []
        for k, m in enumerate(methods):
            if isinstance(m, Tableau) and m.path is not None:
                m = m.path
            elif isinstance(m, Tableau):
                folder = os.path.join(tmp, str(k))
                os.mkdir(folder)
                m.to_file(os.path.join(folder, os.path.basename(m.name) + ".lua"))
                m = os.path.join(folder, os.path.basename(m.name) + ".lua")
            out.append(_native.encode(m, "method", command))
        yield out


def check(method, *, against=None, max_order=None, prec=None):
    """Certifies what a method is, as ``vigen check --json`` does.

    Args:
        method: a method name of the library (``"gauss_2"``), the path of a
            tableau or spec file, or a Tableau (read from a file: that file;
            generated: its tableau file, written to a temporary folder, whose
            path the report's ``"file"`` then names).
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
    with _operands([method], "check") as (operand,):
        out, _, _, _ = _native.call("vigen_python_check", operand, against_arg,
                                    _native.whole(max_order, "max_order"), _native.whole(prec, "prec"))
    return json.loads(out)


def compare(*methods, format="json", max_order=None):
    """The checker's figures of several methods side by side, as ``vigen
    compare`` prints them: stages, design order, principal error constant,
    linear stability interval, cost and the efficiency measure.

    Args:
        *methods: method names, paths or Tableaux, as :func:`check` takes
            them (at most 64; a single list or tuple of them also does).
        format: ``"json"`` (the default: the parsed object is returned),
            ``"text"`` or ``"latex"`` (the table is returned as a str).
        max_order: orders 1..max_order are checked (``--max-order``).

    Raises:
        InputError, ResourceError: as :func:`check`, naming the method.
    """
    if len(methods) == 1 and isinstance(methods[0], (list, tuple)):
        methods = tuple(methods[0])
    with _operands(methods, "compare") as operands:
        for op in operands:
            if b"\n" in op:     # the C interface takes the files one a line
                raise _native.InputError(f"vigen compare: {op!r} holds a newline", "usage error", 2)
        out, _, _, _ = _native.call("vigen_python_compare", b"\n".join(operands),
                                    _native.encode(format, "format", "compare"), _native.whole(max_order, "max_order"))
    return json.loads(out) if format == "json" else out
