"""The method library: the methods known by name (``vigen list``)."""
import json

from . import _native


def methods():
    """The methods of the library, as ``vigen list --json`` lists them.

    Returns a list of dicts, one per method file in the order of ``vigen
    list`` (names shadowed by an earlier folder are listed too, with
    ``"shadowed": True``), each with ``"name"``, ``"directory"``,
    ``"path"``, ``"stages"``, ``"orders"`` (the certified orders for
    ``"general"``, ``"separable"`` and ``"nystrom"`` Hamiltonians, each a dict
    with ``"order"``, ``"at_least"`` and ``"undecided_above"``),
    ``"symplectic"``, ``"explicit"``, ``"evaluations_per_step"``,
    ``"source"``...

    >>> [m["name"] for m in vigen.methods()][:1]      # doctest: +SKIP
    ['blanes_moan_s10_6']
    """
    out, _, _, _ = _native.call("vigen_python_list")
    return json.loads(out)["methods"]


def resolve(name_or_path):
    """The file a method name leads to, as the command line resolves its
    operands: a path that exists is itself; a name (``"gauss_2"``,
    ``"published/yoshida_4"``) is looked up in the current directory,
    ``VIGEN_PATH`` and the installed library. Raises InputError (with
    "did you mean") when nothing matches."""
    out, _, _, _ = _native.call("vigen_python_resolve", b"", _native.encode(name_or_path, "method"))
    return out
