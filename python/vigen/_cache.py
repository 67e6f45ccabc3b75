"""The per-user cache of compiled stepper modules.

A stepper module is a shared library built by the system C compiler from C
text (the emitted stepper and its force) against the runtime and the problem
collection.  It is stored under ``$XDG_CACHE_HOME/vigen/steppers`` (default
``~/.cache/vigen/steppers``; ``VIGEN_CACHE_DIR`` overrides the whole path), in
a folder named by a hash of everything the module depends on: the caller's
key material (the method file's contents, the options, the force's source),
the compiler command, the compiler's identity (its ``--version`` text and
the file it runs) and the runtime (its version, headers and libraries).  A
second request for the same key finds the folder and compiles nothing.

Builds are atomic: a module is compiled in a private temporary folder beside
the final one and renamed into place; the rename either succeeds or finds
the folder made by another process meanwhile (then that one is used and the
private copy removed).  So processes compiling the same key at once each
get a complete module, and no reader ever sees a half-written one.
"""
import hashlib
import json
import os
import shlex
import shutil
import subprocess
import tempfile

from . import _paths

#: The module's file name inside its folder.
MODULE_FILE = "stepper.so"
_compiler_ids = {}


def cache_dir():
    """The folder holding the compiled steppers (created when missing)."""
    root = os.environ.get("VIGEN_CACHE_DIR")
    if not root:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        root = os.path.join(base, "vigen", "steppers")
    os.makedirs(root, exist_ok=True)
    return root


def compiler():
    """The C compiler command as a list: ``$CC`` (which may carry flags), else ``cc``."""
    words = shlex.split(os.environ.get("CC", "") or "cc")
    return words or ["cc"]


def _file_digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def compiler_identity(cc):
    """What identifies the compiler cc (a list): its resolved path and its
    ``--version`` text.  Asked once per process and command."""
    key = tuple(cc)
    if key not in _compiler_ids:
        exe = shutil.which(cc[0])
        if exe is None:
            from . import ResourceError
            raise ResourceError("cannot run the C compiler '%s' (install one, or set CC to a C compiler, "
                                "e.g. CC=gcc)" % " ".join(cc))
        out = subprocess.run(cc + ["--version"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             check=False).stdout.decode("utf-8", "replace")
        _compiler_ids[key] = [os.path.realpath(exe), out.strip()]
    return _compiler_ids[key]


_runtime_id = None


def runtime_identity():
    """What identifies the runtime the modules link: vigen's version and the
    contents of the runtime's headers and libraries."""
    global _runtime_id
    if _runtime_id is None:
        ident = [_paths.VERSION]
        for lib in (_paths.RUNTIME_LIBRARY, _paths.PROBLEMS_LIBRARY):
            ident.append(_file_digest(lib))
        for inc in _paths.INCLUDE_DIRS:
            d = os.path.join(inc, "vigen")
            if os.path.isdir(d):
                for name in sorted(os.listdir(d)):
                    ident.append(name + ":" + _file_digest(os.path.join(d, name)))
        _runtime_id = ident
    return _runtime_id


def link_flags():
    """The libraries a module links after its sources: the problem
    collection, the runtime and what they need (GSL, libm, OpenMP's flag,
    the sanitizers in a sanitized build: _paths.LINK_FLAGS)."""
    extra = getattr(_paths, "LINK_FLAGS", None) or ["-lgsl", "-lgslcblas", "-lm"]
    return [_paths.PROBLEMS_LIBRARY, _paths.RUNTIME_LIBRARY] + list(extra)


def compile_command(cc, source, output):
    """The command compiling one C file into a module."""
    cmd = list(cc) + ["-std=c11", "-O2", "-fPIC", "-shared", "-I."]
    cmd += ["-I" + d for d in _paths.INCLUDE_DIRS]
    return cmd + [source] + link_flags() + ["-o", output]


def key_of(material):
    """The cache key (hex) of a JSON-serialisable description of a module."""
    text = json.dumps(material, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:40]


def module_path(material, make_sources):
    """The path of the module described by material, compiled on a miss.

    material: a JSON-serialisable description of everything the sources
    depend on besides the compiler and runtime (added here).
    make_sources(): called only on a miss; returns (main file name, {file
    name: text}), the main file being the one compiled.
    A compiler error in the sources raises vigen.InputError with the
    compiler's first error lines; a missing compiler vigen.ResourceError."""
    cc = compiler()
    full = {"module": material, "cc": cc, "compiler": compiler_identity(cc), "runtime": runtime_identity(),
            "command": compile_command(["CC"], "MAIN", "OUT")}  # the flags and libraries, LINK_FLAGS included
    key = key_of(full)
    root = cache_dir()
    final = os.path.join(root, key)
    target = os.path.join(final, MODULE_FILE)
    if os.path.isfile(target):
        return target
    main, files = make_sources()
    tmp = tempfile.mkdtemp(prefix=".build-", dir=root)
    try:
        for name, text in files.items():
            with open(os.path.join(tmp, name), "w", encoding="utf-8") as f:
                f.write(text)
        with open(os.path.join(tmp, "key.json"), "w", encoding="utf-8") as f:
            json.dump(full, f, sort_keys=True, indent=1)
        cmd = compile_command(cc, main, MODULE_FILE)
        run = subprocess.run(cmd, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=False)
        if run.returncode != 0:
            from . import InputError
            log = run.stdout.decode("utf-8", "replace")
            errors = [line for line in log.splitlines() if "error" in line] or log.splitlines()[-5:]
            raise InputError("vigen: the C compiler '%s' failed (status %d): %s"
                             % (" ".join(cc), run.returncode, "\n".join(errors[:5])))
        try:
            os.rename(tmp, final)
        except OSError:
            # another process renamed its build into place first: use that one
            if not os.path.isfile(target):
                raise
        else:
            tmp = None
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
    return target
