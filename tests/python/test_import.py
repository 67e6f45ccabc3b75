"""The package imports from the build tree and is the same version as the
command line it was built with."""
import vigen


def test_version_is_the_command_line_s(cli):
    out = cli("--version", check=True).stdout
    assert vigen.__version__ in out.split()


def test_public_names_exist():
    for name in vigen.__all__:
        assert hasattr(vigen, name), name
