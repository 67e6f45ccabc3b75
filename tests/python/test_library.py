"""vigen.methods() and vigen.resolve() against the command line: the same
methods with the same certified orders as the table `vigen list` prints
(read from its text, not its JSON), and names leading to the same files."""
import json
import os

import pytest

import vigen


def parse_list_table(text):
    """{name: (folder, stages, (gen, sep, nys))} from `vigen list`'s table;
    an order is (value, at_least) with "8+" meaning at least 8."""
    rows = {}
    for line in text.splitlines():
        words = line.split()
        if len(words) < 6 or words[1] not in ("published", "generated") or not words[2].isdigit():
            continue

        def order(w):
            if w == "-":   # a method with bracket flows: its orders are in the table of named flows
                return None
            return (int(w.rstrip("+")), w.endswith("+"))

        rows[words[0]] = (words[1], int(words[2]), tuple(order(w) for w in words[3:6]))
    return rows


@pytest.fixture(scope="module")
def methods():
    """vigen.methods() once (each call checks every method of the library)."""
    return vigen.methods()


def test_methods_are_those_of_vigen_list(cli, methods):
    table = parse_list_table(cli("list", check=True).stdout)
    assert len(table) >= 40        # the library ships tens of methods
    listed = {m["name"]: m for m in methods if not m["shadowed"]}
    assert set(listed) == set(table)
    for name, (folder, stages, orders) in table.items():
        m = listed[name]
        assert m["directory"] == folder, name
        assert m["stages"] == stages, name
        if orders == (None, None, None):
            assert m["generalized"]["bracket_flows"] > 0, name
            continue
        got = tuple((m["orders"][f]["order"], m["orders"][f]["at_least"]) for f in ("general", "separable", "nystrom"))
        assert got == orders, name


def test_methods_equal_the_json_of_vigen_list(cli, methods):
    assert methods == json.loads(cli("list", "--json", check=True).stdout)["methods"]


def test_known_orders_of_classical_methods(methods):
    # independent of vigen: Gauss s = 2 has order 4 (Butcher 1964), Yoshida's
    # triple jump order 4, Stormer-Verlet order 2
    orders = {m["name"]: m["orders"]["general"]["order"] for m in methods if not m["shadowed"]}
    assert orders["gauss_2"] == 4
    assert orders["yoshida_4"] == 4
    assert orders["stormer_verlet_velocity"] == 2


def test_shadowed_names_are_listed_with_their_path(methods):
    shadowed = [m for m in methods if m["shadowed"]]
    assert shadowed, "leok_zhang_ex4 is both published and generated"
    for m in shadowed:
        assert os.path.isfile(m["path"])


def test_resolve_leads_where_the_command_line_leads(cli, source_dir):
    assert vigen.resolve("gauss_2") == os.path.join(source_dir, "tableaux", "published", "gauss_2.lua")
    assert vigen.resolve("generated/leok_zhang_ex4") == os.path.join(source_dir, "tableaux", "generated",
                                                                    "leok_zhang_ex4.lua")
    # a path that exists is itself
    path = os.path.join(source_dir, "tableaux", "specs", "gauss_legendre_s2.lua")
    assert vigen.resolve(path) == path


def test_resolve_unknown_name_suggests_like_the_command_line(cli):
    with pytest.raises(vigen.InputError) as e:
        vigen.check("gauss_22")
    err = cli("check", "gauss_22")
    assert err.returncode == 2
    assert str(e.value) == err.stderr.splitlines()[0]
    assert "did you mean" in str(e.value)


def test_vigen_path_adds_a_folder(tmp_path, monkeypatch):
    # a method of one's own, found by name through VIGEN_PATH
    src = vigen.resolve("gauss_2")
    with open(src, encoding="utf-8") as f:
        text = f.read().replace('name = "gauss_2"', 'name = "my_gauss"')
    (tmp_path / "my_gauss.lua").write_text(text, encoding="utf-8")
    monkeypatch.setenv("VIGEN_PATH", str(tmp_path))
    assert vigen.resolve("my_gauss") == str(tmp_path / "my_gauss.lua")
    assert vigen.check("my_gauss")["order"] == 4
