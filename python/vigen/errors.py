"""The exceptions and the warning class of vigen.

Every failure of the library is a :class:`vigen.Error` whose message is the
one line the command line prints for the same failure ("vigen check:
x.lua: ..."), and whose class says what the command line's exit status
says: :class:`InputError` for bad input (exit status 2: an unreadable file,
an invalid entry, a spec that describes no method, an option out of range),
:class:`ResourceError` for a cap reached or a system failure (exit status 3:
the Lua sandbox's memory or instruction cap, the precision cap, a write
error).
"""


class Error(Exception):
    """The base of every error vigen raises.

    Attributes:
        message: the one line the command line prints ("vigen generate: ...").
        status: the name of the library's status code ("syntax error", ...).
        exit_status: the command line's exit status for it (2 or 3).
    """

    def __init__(self, message, status=None, exit_status=None):
        super().__init__(message)
        self.message = message
        self.status = status
        self.exit_status = exit_status


class InputError(Error, ValueError):
    """Bad input: a file that cannot be read or describes no method, an
    invalid entry, an unknown name, an option out of range (the command
    line's exit status 2)."""


class ResourceError(Error, RuntimeError):
    """A cap reached (memory or instructions of the Lua sandbox, working
    precision) or a system failure such as a write error (the command
    line's exit status 3)."""


class VigenWarning(UserWarning):
    """A warning of the library (sum of b not 1, nodes outside [0, 1], ...),
    the line the command line prints as "vigen: warning: ..."."""
