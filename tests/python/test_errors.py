"""Bad input gives the exception the command line's exit status says
(2: InputError, 3: ResourceError) with the line the command line prints,
nothing written, and no crash: missing files, malformed and hostile specs
and tableaux, files that loop or allocate without end (the sandbox's caps),
the precision and instruction caps lowered, options out of range, files
that cannot be written.  Warnings are the command line's warning lines."""
import glob
import os
import subprocess
import sys
import warnings

import pytest

import vigen

SPEC = "tableaux/specs/gauss_legendre_s2.lua"
EXCEPTION = {2: vigen.InputError, 3: vigen.ResourceError}


def same_failure(cli, call, *cli_args):
    """call() raises what `vigen cli_args...` reports; returns the exception."""
    proc = cli(*cli_args)
    assert proc.returncode in EXCEPTION, (cli_args, proc.returncode, proc.stderr)
    with pytest.raises(vigen.Error) as e:
        call()
    assert type(e.value) is EXCEPTION[proc.returncode], (cli_args, str(e.value))
    assert str(e.value) == proc.stderr.splitlines()[0]
    assert e.value.message == str(e.value)
    assert e.value.exit_status == proc.returncode
    assert e.value.status        # the status code's words
    return e.value


@pytest.fixture
def scratch(tmp_path, monkeypatch):
    """A current directory that must stay empty."""
    monkeypatch.chdir(tmp_path)
    yield tmp_path
    assert os.listdir(tmp_path) == []


@pytest.fixture
def default_caps():
    """Puts the caps back to the command line's defaults after a test."""
    yield
    vigen.set_caps(max_memory=256, max_instructions=50000000, max_prec=524288)


DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")
# every bad spec but the two that take tens of seconds to succeed
BAD_SPECS = sorted(os.path.basename(p) for p in glob.glob(os.path.join(DATA, "bad_specs", "*.lua"))
                   if os.path.basename(p) not in ("slow_basis.lua", "hostile_num_quadrature.lua"))
BAD_TABLEAUX = sorted(os.path.basename(p) for p in glob.glob(os.path.join(DATA, "bad_tableaux", "*.lua")))


@pytest.mark.parametrize("name", BAD_SPECS)
def test_bad_specs_fail_as_on_the_command_line(cli, source_dir, name):
    assert len(BAD_SPECS) > 40
    path = os.path.join(source_dir, "tests", "data", "bad_specs", name)
    proc = cli("generate", "-q", path)
    if proc.returncode == 0:          # a spec that only warns
        with warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            assert vigen.generate(path).text == proc.stdout
        return
    same_failure(cli, lambda: vigen.generate(path), "generate", "-q", path)


@pytest.mark.parametrize("name", BAD_TABLEAUX)
def test_bad_tableaux_fail_as_on_the_command_line(cli, source_dir, name):
    path = os.path.join(source_dir, "tests", "data", "bad_tableaux", name)
    proc = cli("check", "--json", path)
    if proc.returncode in (0, 1):
        with warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            assert vigen.check(path)["exit"] == proc.returncode
        return
    same_failure(cli, lambda: vigen.check(path), "check", "--json", path)
    same_failure(cli, lambda: vigen.Tableau.from_file(path), "show", "--format", "lua", path)


def test_missing_file(cli, scratch):
    same_failure(cli, lambda: vigen.generate("no/such/spec.lua"), "generate", "no/such/spec.lua")
    same_failure(cli, lambda: vigen.check("no/such/file.lua"), "check", "no/such/file.lua")
    same_failure(cli, lambda: vigen.Tableau.from_file("no_such_method"), "show", "no_such_method")


def test_endless_loop_and_memory_bomb_are_stopped_by_the_caps(cli, source_dir, scratch):
    # (memory_bomb.lua is among the bad specs above)
    for name in ("endless_loop.lua", "hostile_lua_pcall_memory.lua"):
        path = os.path.join(source_dir, "tests", "data", "bad_specs", name)
        e = same_failure(cli, lambda: vigen.generate(path), "generate", path)
        assert isinstance(e, vigen.ResourceError)
        same_failure(cli, lambda: vigen.check(path), "check", path)


def test_a_tableau_file_is_not_a_spec(cli):
    path = vigen.resolve("gauss_2")
    e = same_failure(cli, lambda: vigen.generate(path), "generate", path)
    assert "not a spec" in str(e)


@pytest.mark.parametrize("digits", [0, -3, 100001])
def test_digits_out_of_range(cli, digits):
    same_failure(cli, lambda: vigen.generate(SPEC, digits=digits), "generate", SPEC, "--digits", str(digits))
    same_failure(cli, lambda: vigen.Tableau.from_file("gauss_2", digits=digits),
                 "show", "gauss_2", "--digits", str(digits))


def test_lowered_precision_cap(cli, default_caps):
    vigen.set_caps(max_prec=64)
    same_failure(cli, lambda: vigen.generate(SPEC, digits=100), "--max-prec", "64", "generate", SPEC,
                 "--digits", "100")
    vigen.set_caps(max_prec=524288)
    assert vigen.generate(SPEC, digits=100).digits == 100


def test_lowered_instruction_and_memory_caps(cli, source_dir, default_caps):
    path = os.path.join(source_dir, "tests", "data", "bad_specs", "slow_basis.lua")
    vigen.set_caps(max_instructions=1000)
    same_failure(cli, lambda: vigen.generate(path), "--max-instructions", "1000", "generate", path)
    vigen.set_caps(max_instructions=50000000, max_memory=1)
    bomb = os.path.join(source_dir, "tests", "data", "bad_specs", "memory_bomb.lua")
    same_failure(cli, lambda: vigen.generate(bomb), "--max-memory", "1", "generate", bomb)


def test_caps_out_of_range_change_nothing(cli, default_caps):
    # the command line names the command it parsed the global option for;
    # set_caps belongs to none
    for kw, args in (({"max_prec": 10}, ("--max-prec", "10")), ({"max_memory": 0}, ("--max-memory", "0")),
                     ({"max_instructions": 0}, ("--max-instructions", "0"))):
        proc = cli(*args, "list")
        assert proc.returncode == 2
        with pytest.raises(vigen.InputError) as e:
            vigen.set_caps(**kw)
        assert str(e.value) == proc.stderr.splitlines()[0].replace("vigen list: ", "vigen: ")
    assert vigen.generate(SPEC, digits=50).digits == 50


def test_unwritable_file_is_a_resource_error_and_writes_nothing(cli, tmp_path):
    t = vigen.generate(SPEC, digits=10)
    target = tmp_path / "missing" / "t.lua"
    same_failure(cli, lambda: t.to_file(target), "generate", SPEC, "--digits", "10", "-q", "-o", str(target))
    assert not (tmp_path / "missing").exists()
    # a read-only folder: nothing appears in it (root writes anywhere, so only as another user)
    if os.geteuid() != 0:
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o500)
        with pytest.raises(vigen.ResourceError):
            t.to_file(ro / "t.lua")
        assert os.listdir(ro) == []


def test_an_existing_file_is_kept_when_writing_fails(tmp_path):
    t = vigen.generate(SPEC, digits=10)
    target = tmp_path / "t.lua"
    target.mkdir()                    # a folder where the file should go: the rename fails
    with pytest.raises(vigen.ResourceError):
        t.to_file(target)
    assert target.is_dir() and os.listdir(tmp_path) == ["t.lua"]


def test_nul_bytes_and_wrong_types():
    with pytest.raises(vigen.InputError):
        vigen.generate("tableaux/specs/gauss\0legendre_s2.lua")
    with pytest.raises(vigen.InputError):
        vigen.check("gauss_2\0")
    with pytest.raises(TypeError):
        vigen.generate(None)
    with pytest.raises(TypeError):
        vigen.generate(SPEC, digits=3.5)
    with pytest.raises(TypeError):
        vigen.generate(SPEC, digits=True)


def test_warnings_are_the_command_line_s(cli, source_dir):
    path = os.path.join(source_dir, "tests", "data", "bad_specs", "node_outside.lua")
    proc = cli("generate", "-q", path, check=True)
    expected = [line[len("vigen: warning: "):] for line in proc.stderr.splitlines()
                if line.startswith("vigen: warning: ")]
    assert expected
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        vigen.generate(path)
    assert [str(w.message) for w in caught if w.category is vigen.VigenWarning] == expected


def test_no_crash_in_a_fresh_process(source_dir):
    # the hostile bytes and numbers of the test data and every bad tableau
    # through every call, one after the other in one process that must end
    # normally (the Lua bombs, slower, are run above one by one)
    code = """
import glob, warnings, vigen
warnings.simplefilter("ignore")
n = 0
for path in sorted(glob.glob("tests/data/bad_specs/hostile_bytes_*.lua") + glob.glob("tests/data/bad_tableaux/*.lua")
                   + ["tests/data/bad_specs/hostile_num_exponent.lua", "tests/data/bad_specs/hostile_num_many_nodes.lua"]):
    for call in (vigen.generate, vigen.check, vigen.Tableau.from_file, lambda p: vigen.compare(p, "gauss_2")):
        try:
            call(path)
        except vigen.Error:
            n += 1
print("errors", n)
"""
    proc = subprocess.run([sys.executable, "-c", code], cwd=source_dir, capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert int(proc.stdout.split()[-1]) > 20
