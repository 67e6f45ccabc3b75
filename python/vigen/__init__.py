"""vigen: certified symplectic integrators from Python.

The method library, the checker and the generator of the vigen command
line, called in-process (libvigen through cffi), with the command line's
caps and messages:

    >>> import vigen
    >>> [m["name"] for m in vigen.methods()]          # `vigen list`
    >>> report = vigen.check("gauss_2")                 # `vigen check --json`
    >>> t = vigen.generate("tableaux/specs/gauss_legendre_s2.lua", digits=20)
    >>> t.to_numpy()["A"], t.latex(), t.to_file("gauss2.lua")

Errors are :class:`vigen.Error` (:class:`InputError`, :class:`ResourceError`)
carrying the command line's one-line message. docs/python.md is the guide.
"""
from . import _native
from .checker import check, compare
from .errors import Error, InputError, ResourceError, VigenWarning
from .library import methods, resolve
from .tableau import Tableau, generate

__version__ = _native.text(_native.lib.vigen_python_version())


def set_caps(*, max_memory=None, max_instructions=None, max_prec=None):
    """Sets the caps every later call runs under, the global options of the
    command line: ``max_memory`` (MiB of each Lua state, --max-memory,
    default 256), ``max_instructions`` (Lua instructions per call,
    --max-instructions, default 50 million), ``max_prec`` (bits of working
    precision, --max-prec, default 524288). None leaves a cap as it is. A
    value out of range raises InputError and changes nothing."""
    _native.call("vigen_python_set_caps", _native.whole(max_memory, "max_memory"),
                 _native.whole(max_instructions, "max_instructions"), _native.whole(max_prec, "max_prec"))


__all__ = ["Error", "InputError", "ResourceError", "VigenWarning", "Tableau", "check", "compare", "generate",
           "methods", "resolve", "set_caps", "Stepper", "StepperState", "StepError", "__version__"]

# Steppers on NumPy arrays (stepper.py); plots are the submodule vigen.plot
# (matplotlib is imported only when a figure is drawn).
from .stepper import Stepper, StepperState, StepError  # noqa: E402
