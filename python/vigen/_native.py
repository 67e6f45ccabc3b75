"""The package's shared library (libvigen_python.so), loaded with cffi in
ABI mode: nothing is compiled against Python, so the library built once
serves every Python 3 interpreter.

``ffi`` and ``lib`` are the cffi objects; the functions are declared from
the library's own header, vigen_python.h (shipped beside it; its '#' lines
are dropped). ``call`` runs one function of the C interface and turns its
result into Python values or exceptions; ``declare`` adds declarations of
more functions of the library (those of its other headers: the module that
uses them declares them).
"""
import os
import re
import threading
import warnings

import cffi

from . import _paths
from .errors import Error, InputError, ResourceError, VigenWarning  # noqa: F401 (InputError for callers)

# The templates (and, relative to them, the method library) of this build or
# install, unless the user points VIGEN_TEMPLATE_DIR elsewhere: the library
# would otherwise look for them relative to the running executable, which is
# the Python interpreter.
os.environ.setdefault("VIGEN_TEMPLATE_DIR", _paths.TEMPLATE_DIR)

_DIR = os.path.dirname(os.path.abspath(__file__))


def _header_declarations(path):
    """The declarations of a C header, for cffi: without preprocessor lines."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("#"))


ffi = cffi.FFI()
ffi.cdef(_header_declarations(os.path.join(_DIR, "vigen_python.h")))
lib = ffi.dlopen(_paths.NATIVE_LIBRARY)
_declare_lock = threading.Lock()

# exit status of the command line -> exception class
_EXCEPTIONS = {2: InputError, 3: ResourceError}


def declare(cdef_text):
    """Declares more functions of libvigen_python.so (C declarations as cffi
    reads them; declaring a function again with the same type is harmless)
    and returns ``lib``, through which they are then called."""
    with _declare_lock:
        ffi.cdef(cdef_text, override=True)
    return lib


def encode(value, what="operand", command=""):
    """A str, bytes or os.PathLike as the bytes the C interface takes.
    A NUL byte, which no command line argument can hold, is an InputError."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if isinstance(value, str):
        data = os.fsencode(value)
    elif isinstance(value, bytes):
        data = value
    else:
        raise TypeError(f"{what} must be a str or a path, not {type(value).__name__}")
    if b"\0" in data:
        prefix = f"vigen {command}: " if command else "vigen: "
        raise InputError(f"{prefix}{what} holds a NUL byte", "usage error", 2)
    return data


def whole(value, what):
    """An integer option as the C interface takes it: its decimal text,
    which the C side checks as the command line checks the option's value
    (None: not given, NULL)."""
    if value is None:
        return ffi.NULL
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{what} must be an int, not {type(value).__name__}")
    return str(value).encode()


def text(ptr):
    """A char * of the result as str (None for NULL)."""
    if ptr == ffi.NULL:
        return None
    return ffi.string(ptr).decode("utf-8", errors="surrogateescape")


def call(function, *args):
    """Calls ``lib.<function>(result, *args)`` and returns the result's
    (text, extra, message, exit_status); raises the Error its status says.
    The library's warnings become VigenWarning."""
    r = ffi.new("vigen_python_result *")
    try:
        status = getattr(lib, function)(r, *args)
        out = (text(r.text), text(r.extra), text(r.message), r.exit_status)
        pending = text(r.warnings)
        status_name = ffi.string(lib.vigen_python_status_name(status)).decode()
    finally:
        lib.vigen_python_result_clear(r)
    for line in (pending or "").splitlines():
        warnings.warn(re.sub(r"^vigen: warning: ", "", line), VigenWarning, stacklevel=3)
    if status != 0:
        message, exit_status = out[2], out[3]
        cls = _EXCEPTIONS.get(exit_status, Error)
        raise cls(message or f"vigen: status {status}", status_name, exit_status)
    return out
