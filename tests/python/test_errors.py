"""Bad arguments, answered: every call refuses what it cannot use with attractor_workbench.Error
(a ValueError), or TypeError / IndexError / KeyError where Python's convention says so, with a
message that names the problem, and never takes the interpreter down. A seeded fuzz session in
a child interpreter feeds a few hundred odd Python values to every call, and Ctrl+C interrupts a
long points()."""

import json
import math
import os
import random
import signal
import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from conftest import FOUR_POINT, FOUR_POINT_FILE, KOCH_FILE, subprocess_env

HERE = Path(__file__).resolve().parent
OMEGA_NAME = "000 Fig. 5: spectra of A_i"


def item_json(curve, **fields):
    obj = curve.to_json()
    obj.pop("children")
    obj.update(fields)
    return obj


# Each case: (id, call(awb, project, curve, tmp_path), exception types, message pattern).
def _cases():
    E = "Error"  # resolved to awb.Error in the test
    nan, inf = math.nan, math.inf
    return [
        # control points
        ("cp NaN", lambda a, p, c, t: c.control_points.__setitem__(0, [nan, 0]), E,
         r"point 0 has a coordinate that is not a finite number \(nan\)"),
        ("cp inf", lambda a, p, c, t: c.control_points.__setitem__(1, [0, inf]), E,
         r"not a finite number \(inf\)"),
        ("cp -inf in a whole array", lambda a, p, c, t: setattr(
            c, "control_points", np.full((7, 2), -inf)), E, "not a finite number"),
        ("cp wrong shape", lambda a, p, c, t: c.control_points.__setitem__(0, [1, 2, 3]), E,
         r"expected an array of shape \(n, 2\), got shape \(3,\)"),
        ("cp whole wrong shape", lambda a, p, c, t: setattr(c, "control_points",
                                                            np.zeros((7, 3))), E,
         r"shape \(n, 2\), got shape \(7, 3\)"),
        ("cp strings", lambda a, p, c, t: c.control_points.__setitem__(0, ["a", "b"]), E,
         r"expected points as a numpy array or a list of \[x, y\]"),
        ("cp None", lambda a, p, c, t: c.control_points.__setitem__(0, None), E, "shape"),
        ("cp index out of range", lambda a, p, c, t: c.control_points[7], IndexError,
         r"point 7 is out of range \(the item has 7\)"),
        ("cp negative index out of range", lambda a, p, c, t: c.control_points[-8], IndexError,
         "out of range"),
        ("cp set out of range", lambda a, p, c, t: c.control_points.__setitem__(9, [0, 0]),
         IndexError, "out of range"),
        ("cp del out of range", lambda a, p, c, t: c.control_points.__delitem__(9), IndexError,
         "out of range"),
        ("cp del by str", lambda a, p, c, t: c.control_points.__delitem__("a"), TypeError, ""),
        ("cp more than 256", lambda a, p, c, t: setattr(c, "control_points",
                                                        np.zeros((300, 2))), E,
         "300 points is more than the 256"),
        ("cp fixed count", lambda a, p, c, t: a.open(
            p.file_name.replace("000-fig05-four-point-from-segment",
                                "003-fig18-refined-junction-g1")).items[0]
         .point_sets[1].__delitem__(0), E, "refused"),
        ("cp of an eigenvalue plot", lambda a, p, c, t: p[OMEGA_NAME].control_points, E,
         "has no attractor"),
        # parameters
        ("parameter unknown key", lambda a, p, c, t: c.parameters["nope"], KeyError,
         r"no parameter 'nope' \(it has: name, scheme.kind, scheme.omega, start_set.kind"),
        ("parameter set unknown key", lambda a, p, c, t: c.parameters.__setitem__("nope", 1),
         KeyError, "nope"),
        ("parameter key not a str", lambda a, p, c, t: c.parameters[3], TypeError,
         "expected a str"),
        ("parameter str for a number", lambda a, p, c, t: c.parameters.__setitem__(
            "scheme.omega", "0.1"), TypeError,
         "parameter 'scheme.omega': expected a number, got str"),
        ("parameter NaN", lambda a, p, c, t: c.parameters.__setitem__("scheme.omega", nan), E,
         "is not a finite number"),
        ("parameter bool for a number", lambda a, p, c, t: c.parameters.__setitem__(
            "scheme.omega", True), TypeError, "expected a number, got bool"),
        ("choice unknown text", lambda a, p, c, t: c.parameters.__setitem__(
            "scheme.kind", "Five-point"), E, "'Five-point' is not one of: Uniform B-spline"),
        ("choice index out of range", lambda a, p, c, t: c.parameters.__setitem__(
            "scheme.kind", 99), E, r"expected a choice index 0\.\.7"),
        ("parameter info unknown", lambda a, p, c, t: c.parameters.info("nope"), KeyError,
         "nope"),
        # items and names
        ("item unknown name", lambda a, p, c, t: p.item("nope"), E, "no item named 'nope'"),
        ("p[unknown]", lambda a, p, c, t: p["nope"], E, "no item named 'nope'"),
        ("item name not a str", lambda a, p, c, t: p.item(3), TypeError, "name: expected a str"),
        ("name empty", lambda a, p, c, t: setattr(c, "name", ""), E, "cannot be empty"),
        ("name taken", lambda a, p, c, t: setattr(c, "name", OMEGA_NAME), E,
         "already called"),
        ("name None", lambda a, p, c, t: setattr(c, "name", None), TypeError, "expected a str"),
        ("remove unknown", lambda a, p, c, t: p.remove("nope"), E, "no item named"),
        ("remove None", lambda a, p, c, t: p.remove(None), E, "which item"),
        ("move into its own child", lambda a, p, c, t: p.move(c, OMEGA_NAME, 0), E,
         "the move is refused"),
        ("move out of range", lambda a, p, c, t: p.move(OMEGA_NAME, None, 99), E,
         "the move is refused"),
        ("move an item of another project", lambda a, p, c, t: p.move(
            a.open(FOUR_POINT_FILE).items[0], None, 0), E, "belongs to another project"),
        ("regularity of a fractal", lambda a, p, c, t: a.open(KOCH_FILE).items[0].regularity(),
         E, "not a subdivision curve"),
        ("maps of an eigenvalue plot", lambda a, p, c, t: p[OMEGA_NAME].maps(), E,
         "has no attractor"),
        # add()
        ("add missing type", lambda a, p, c, t: p.add({"name": "x"}), E,
         'field "type": missing'),
        ("add unknown type", lambda a, p, c, t: p.add(item_json(c, name="x", type="bogus")), E,
         'unknown item type "bogus"'),
        ("add type not a str", lambda a, p, c, t: p.add(item_json(c, name="x", type=5)), E,
         '"type"'),
        ("add control points a str", lambda a, p, c, t: p.add(
            item_json(c, name="x", control_points="abc")), E, 'field "control_points"'),
        ("add control point a str", lambda a, p, c, t: p.add(
            item_json(c, name="x", control_points=[[1, "a"]])), E,
         r'field "control_points\[1\]\[2\]": expected a number'),
        ("add NaN", lambda a, p, c, t: p.add(item_json(c, name="x", control_points=[[1, nan]])),
         E, "not a finite number"),
        ("add name not a str", lambda a, p, c, t: p.add(item_json(c, name=5)), E,
         'field "name": expected a string'),
        ("add bytes", lambda a, p, c, t: p.add(item_json(c, name=b"x")), TypeError,
         "a bytes cannot be written to a project file"),
        ("add non-str key", lambda a, p, c, t: p.add({1: 2}), TypeError,
         "keys of a dict must be str, got int"),
        # A wrong type is a TypeError, as in Python itself (issue 47: add(5) was awb.Error).
        ("add a list", lambda a, p, c, t: p.add([1, 2]), TypeError, "expected a dict, got list"),
        ("add None", lambda a, p, c, t: p.add(None), TypeError, "expected a dict, got NoneType"),
        ("add an int", lambda a, p, c, t: p.add(5), TypeError, "item: expected a dict, got int"),
        ("add index out of range", lambda a, p, c, t: p.add(item_json(c, name="x"), index=99),
         E, r"index 99 is out of range 0\.\.1"),
        ("add under unknown parent", lambda a, p, c, t: p.add(item_json(c, name="x"),
                                                              parent="nope"), E,
         "no item named 'nope'"),
        ("update type", lambda a, p, c, t: c.update({"type": "fractal"}), E,
         "type cannot change"),
        ("update malformed", lambda a, p, c, t: c.update({"scheme": 5}), E,
         'field "scheme": expected an object'),
        ("update not a dict", lambda a, p, c, t: c.update(None), TypeError, "expected a dict"),
        ("update children", lambda a, p, c, t: c.update({"children": []}), E, "children"),
        ("update style field", lambda a, p, c, t: c.update({"style": {"point_size": "x"}}), E,
         r'field "style\.point_size": expected a number'),
        # files
        ("open missing file", lambda a, p, c, t: a.open(t / "missing.awb"), E,
         "missing.awb: cannot open: No such file or directory"),
        ("open malformed file", lambda a, p, c, t: a.open(_write(
            t / "bad.awb", '{"format": "attractor-workbench", "items": [')), E,
         "bad.awb: not valid JSON: unterminated array"),
        ("open another JSON", lambda a, p, c, t: a.open(_write(t / "other.awb", "{}")), E,
         "not an Attractor Workbench project"),
        ("open an empty file", lambda a, p, c, t: a.open(_write(t / "empty.awb", "")), E,
         "the file is empty"),
        ("open a folder", lambda a, p, c, t: a.open(t), E, "is a directory"),
        ("save into a missing folder", lambda a, p, c, t: p.save(t / "no" / "x.awb"), E,
         "cannot save: the folder .* does not exist"),
        ("save with no file", lambda a, p, c, t: a.Project().save(), E, "no file yet"),
        # points()
        ("depth -1", lambda a, p, c, t: c.points(depth=-1), E,
         r"depth: -1 is out of range 0\.\.64"),
        ("depth 1000", lambda a, p, c, t: c.points(depth=1000), E,
         r"depth: 1000 is out of range 0\.\.64"),
        ("depth over the budget", lambda a, p, c, t: c.points(depth=30), E,
         r"depth 30 gives 2\.147e\+09 points, more than"),
        ("max_points negative", lambda a, p, c, t: c.points(depth=3, max_points=-1), E,
         r"max_points: -1 is out of range 1\.\.2e\+09"),
        ("max_points a str", lambda a, p, c, t: c.points(depth=3, max_points="x"), TypeError,
         "max_points"),
        ("start unknown kind", lambda a, p, c, t: c.points(depth=3, start="circle:1"), E,
         "circle"),
        ("start segment short", lambda a, p, c, t: c.points(depth=3, start="segment:0,0"), E,
         r"segment needs 4 coordinates \(2 per point\), got 2"),
        ("start NaN", lambda a, p, c, t: c.points(depth=3, start=[[0, nan]]), E,
         "not a finite number"),
        ("start empty", lambda a, p, c, t: c.points(depth=3, start=np.zeros((0, 2))), E,
         "the start set is empty"),
        ("address map too big", lambda a, p, c, t: c.points(depth=3, address=[5]), E,
         r"map 5, but the IFS has 2 maps \(0\.\.1\)"),
        ("address negative", lambda a, p, c, t: c.points(depth=3, address=[-1]), E,
         r"address: -1 is out of range"),
        ("address empty", lambda a, p, c, t: c.points(depth=3, address=[]), E,
         "the address is empty"),
        ("address too long", lambda a, p, c, t: c.points(depth=3, address=[0] * 100), E,
         "more than 64"),
        ("address an int", lambda a, p, c, t: c.points(depth=3, address=5), E,
         "address: expected a list of map numbers"),
        # render()
        ("render size (0, 0)", lambda a, p, c, t: c.render(t / "x.png", size=(0, 0)), E,
         r"width: 0 is out of range 16\.\.20000"),
        ("render size negative", lambda a, p, c, t: c.render(t / "x.png", size=(-5, 100)), E,
         r"width: -5 is out of range 16\.\.20000"),
        ("render unwritable folder", lambda a, p, c, t: c.render(t / "no" / "x.png",
                                                                 size=(32, 32)), E,
         "cannot write .*x.png: the folder .* does not exist"),
        ("render unknown format", lambda a, p, c, t: c.render(t / "x.txt", size=(32, 32)), E,
         "unknown output format '.txt'"),
        ("render depth 1000", lambda a, p, c, t: c.render(t / "x.png", depth=1000), E,
         r"depth: 1000 is out of range 0\.\.64"),
        ("render samples NaN", lambda a, p, c, t: c.render(t / "x.png", samples=nan), E,
         r"samples: nan is out of range 1\.\.1e\+11"),
        ("render threads -1", lambda a, p, c, t: c.render(t / "x.png", threads=-1), E,
         r"threads: -1 is out of range 0\.\.256"),
        # the rest
        ("undo with nothing", lambda a, p, c, t: a.Project().undo(), E, "nothing to undo"),
        ("redo with nothing", lambda a, p, c, t: a.Project().redo(), E, "nothing to redo"),
        ("edit text not a str", lambda a, p, c, t: p.edit(5), TypeError, "text: expected a str"),
        ("no constructor for Item", lambda a, p, c, t: a.Item(), TypeError, "No constructor"),
        ("removed item", lambda a, p, c, t: _removed(p, c).name, E,
         "is no longer in the project"),
    ]


def _write(path, text):
    path.write_text(text)
    return path


def _removed(project, item):
    project.remove(item)
    return item


CASES = _cases()


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_bad_argument(awb, four_point, curve, tmp_path, case):
    _, call, expected, pattern = case
    types = tuple(awb.Error if e == "Error" else e
                  for e in (expected if isinstance(expected, tuple) else (expected,)))
    before = four_point.to_json()
    undo_text = four_point.undo_text
    with pytest.raises(types, match=pattern):
        call(awb, four_point, curve, tmp_path)
    if case[0] != "removed item":
        # a refused edit changes nothing and adds no undo step
        assert four_point.to_json() == before
        assert four_point.undo_text == undo_text


# --- problems the first version of the module had (each fixed, each kept as a test) -----------

CAST = ("pybind11's own cast failure leaks out as RuntimeError('Unable to cast Python instance "
        "to C++ type ...'), naming neither the argument nor the problem")


@pytest.mark.parametrize("call", [
    pytest.param(lambda c: c.points(depth="3"), id="points(depth='3')"),
    pytest.param(lambda c: c.points(depth=3.5), id="points(depth=3.5)"),
    pytest.param(lambda c: c.points(depth=10 ** 30), id="points(depth=10**30)"),
    pytest.param(lambda c: c.points(depth=3, address=["a"]), id="points(address=['a'])"),
    pytest.param(lambda c: c.points(depth=3, address=[10 ** 30]), id="points(address=[1e30])"),
    pytest.param(lambda c: c.render("x.png", size="big"), id="render(size='big')"),
    pytest.param(lambda c: c.render("x.png", size=(10 ** 30, 5)), id="render(size=(1e30, 5))"),
    pytest.param(lambda c: c.render("x.png", size=(1, 2, 3)), id="render(size=(1, 2, 3))"),
    pytest.param(lambda c: c.control_points[10 ** 30], id="cp[10**30]"),
    pytest.param(lambda c: c.parameters.__setitem__("scheme.omega", 10 ** 400),
                 id="parameters[omega]=10**400"),
    pytest.param(lambda c: setattr(c, "name", "\ud800"), id="name=lone surrogate"),
])
def test_wrong_types_name_the_argument(awb, curve, tmp_path, monkeypatch, call):
    monkeypatch.chdir(tmp_path)
    try:
        call(curve)
    except (awb.Error, TypeError, IndexError, KeyError, OverflowError, UnicodeError) as e:
        assert "Unable to cast" not in str(e)
    except RuntimeError as e:
        raise AssertionError(f"RuntimeError: {e}") from e


@pytest.mark.parametrize("max_points", [1e300, math.inf, math.nan])
def test_absurd_max_points_is_refused(awb, curve, max_points):
    # depth 3 keeps this cheap; the danger is the same budget at depth 30
    with pytest.raises(awb.Error, match="max_points"):
        curve.points(depth=3, max_points=max_points)


@pytest.mark.subprocess
@pytest.mark.parametrize("value", ["cycle", "deep"])
def test_recursive_values_do_not_crash(child_python, value):
    code = (
        "import sys, attractor_workbench as awb\n"
        "v = []\n"
        "if sys.argv[1] == 'cycle':\n"
        "    v.append(v)\n"
        "else:\n"
        "    for _ in range(100000):\n"
        "        v = [v]\n"
        "try:\n"
        "    awb.Project().add({'type': 'subdivision-curve', 'name': 'x', 'junk': v})\n"
        "except (ValueError, RecursionError) as e:\n"
        "    print('refused:', type(e).__name__, e)\n")
    out = child_python(code, value, timeout=60)
    assert out.returncode == 0, f"the interpreter died: status {out.returncode}"
    assert "refused" in out.stdout


def test_handle_survives_update_undo_and_rename(four_point, curve):
    curve.update({"scheme": {"kind": "four-point", "omega": 0.07}})
    four_point.undo()
    four_point.items[0].name = "renamed"
    assert curve.name == "renamed"


def test_handle_follows_a_name_to_another_item(awb, four_point, curve, examples):
    """By design (src/python/Handles.h) a handle whose item was removed finds an item of the
    same name: this documents that it may then be a different item."""
    four_point.remove(curve)
    koch = awb.open(KOCH_FILE).items[0].to_json()
    koch["name"] = FOUR_POINT
    four_point.add(koch)
    assert curve.kind == koch["type"]


def test_too_few_points_are_an_item_error(awb, curve):
    """As in the window, a point set may be edited below what its scheme needs (the user is
    part-way through an edit); the item then says why it has no attractor, and computing
    refuses with that message."""
    curve.control_points = np.zeros((0, 2))
    assert "needs at least 6 control points, got 0" in curve.error
    with pytest.raises(awb.Error, match="needs at least 6 control points"):
        curve.maps()


@pytest.mark.parametrize("call", [
    pytest.param(lambda awb, p: p.save(123), id="save(123)"),
    pytest.param(lambda awb, p: p.save(["a.awb"]), id="save(['a.awb'])"),
    pytest.param(lambda awb, p: awb.open(None), id="open(None)"),
    pytest.param(lambda awb, p: p.items[0].render(3.5), id="render(3.5)"),
])
def test_paths_must_be_paths(awb, tmp_path, monkeypatch, call):
    monkeypatch.chdir(tmp_path)
    p = awb.open(FOUR_POINT_FILE)
    p.save(tmp_path / "copy.awb")  # save(None) is save() to its file: never the example's
    with pytest.raises(TypeError):
        call(awb, p)


def test_bytes_path(awb, four_point, tmp_path):
    four_point.save(os.fsencode(tmp_path / "bytes.awb"))
    assert (tmp_path / "bytes.awb").exists()


# --- the fuzz session --------------------------------------------------------------------------

class _Raises:
    """An object whose conversions raise."""

    def __float__(self):
        raise ZeroDivisionError("__float__")

    def __index__(self):
        raise ZeroDivisionError("__index__")

    def __iter__(self):
        raise ZeroDivisionError("__iter__")

    def __len__(self):
        return -1

    def __array__(self, *args, **kwargs):
        raise ZeroDivisionError("__array__")

    def __str__(self):
        raise ZeroDivisionError("__str__")

    def __repr__(self):
        return "<_Raises>"


# Odd values (self-containing and deeply nested ones: test_recursive_values_do_not_crash), no
# absolute paths (save() and render() write where
# they are told: the fuzz session runs in a scratch folder).
ATOMS = [
    None, True, False, 0, 1, -1, 2, 3, 7, 2 ** 31, -2 ** 63, 10 ** 30, -10 ** 400,
    0.0, -0.0, 0.5, 3.5, -2.5, 1e308, math.nan, math.inf, -math.inf, 1j, complex(math.nan),
    Fraction(1, 3), np.float64(math.nan), np.int64(3), np.float32(0.25), "", "a",
    "segment:0,0,1,0", "point:1,1", "lifted:0,0,1;1,1,0", "vertex-limits", "0,1", "0,,1",
    "scheme.omega", "scheme.kind", "Four-point", FOUR_POINT, OMEGA_NAME, "x.png", "x.svg",
    "out.awb", "x.pdf", "\ud800", "a\x00b", "é" * 3, b"bytes", bytearray(b"x"), object(),
    _Raises(), slice(1, 3), slice(None, None, -1), Ellipsis, len, type, {1, 2}, (16, 16),
    (32, 24), (0, 0), (10 ** 30, 5), [0, 1], [[0, 0], [1, 1]], np.zeros((0, 2)),
    np.zeros((2, 2, 2)), np.array(["1", "2"]), {"type": "bogus"}, {1: 2}, [], (), {},
]


def fuzz_value(rng, depth=0):
    """One odd Python value: an atom, or a list, tuple, dict or numpy array built of them."""
    r = rng.random()
    if depth >= 3 or r < 0.55:
        return rng.choice(ATOMS)
    if r < 0.65:
        # no "/": a path that a save() or render() gets must stay in the scratch folder
        return "".join(rng.choice("abc019,:;.- é\\") for _ in range(rng.randrange(12)))
    if r < 0.75:
        shape = rng.choice([(0,), (2,), (3,), (1, 2), (3, 2), (7, 2), (2, 3), (2, 2, 2)])
        dtype = rng.choice([float, int, object, complex, str, bool])
        data = rng.choice([np.zeros, np.ones])(shape)
        if dtype is float and data.size and rng.random() < 0.3:
            data.flat[0] = rng.choice([math.nan, math.inf, 1e300])
        return data.astype(dtype)
    if r < 0.85:
        return [fuzz_value(rng, depth + 1) for _ in range(rng.randrange(5))]
    if r < 0.9:
        return tuple(fuzz_value(rng, depth + 1) for _ in range(rng.randrange(4)))
    d = {rng.choice(["type", "name", "scheme", "control_points", "style", "start_set",
                     "algorithm", "children", "kind", "x"]): fuzz_value(rng, depth + 1)
         for _ in range(rng.randrange(5))}
    if rng.random() < 0.5:
        d["type"] = rng.choice(["subdivision-curve", "fractal", "eigenvalue-plot", "bogus"])
    if rng.random() < 0.2:
        d[rng.choice([1, None, (1,)])] = 1
    return d


def known_crash(name, args):
    """Calls the fuzz session leaves out (none now: the first version's crashes have tests of
    their own)."""
    return False


def fuzz_calls(awb, state):
    """Every call of the API: name -> (function of the arguments, the valid arguments)."""
    p = lambda: state["p"]  # noqa: E731
    i = lambda: state["i"]  # noqa: E731
    cp0 = lambda: np.asarray(i().control_points)[0].tolist()  # noqa: E731
    key = lambda: (i().parameters.keys() or ["x"])[0]  # noqa: E731

    def in_edit(text):
        with p().edit(text):
            i().control_points[0] = cp0()

    def new_item():
        obj = i().to_json()
        obj.pop("children", None)
        obj["name"] = "fuzzed"
        return obj

    return {
        "open": (awb.open, lambda: [state["file"]]),
        "Project.item": (lambda n: p().item(n), lambda: [i().name]),
        "Project[]": (lambda n: p()[n], lambda: [i().name]),
        "Project.in": (lambda n: n in p(), lambda: [i().name]),
        "Project.add": (lambda o, parent, index: p().add(o, parent=parent, index=index),
                        lambda: [new_item(), None, -1]),
        "Project.remove": (lambda n: p().remove(n), lambda: ["fuzzed"]),
        "Project.move": (lambda n, parent, index: p().move(n, parent, index),
                         lambda: [i().name, None, 0]),
        "Project.save": (lambda path: p().save(path), lambda: ["saved.awb"]),
        "Project.undo": (lambda: p().undo(), lambda: []),
        "Project.redo": (lambda: p().redo(), lambda: []),
        "Project.edit": (in_edit, lambda: ["Script"]),
        "Project.problems": (lambda: p().problems(), lambda: []),
        "Project.to_json": (lambda: p().to_json(), lambda: []),
        "Item.name=": (lambda n: setattr(i(), "name", n), lambda: ["renamed"]),
        "Item.update": (lambda f: i().update(f), lambda: [{"style": i().to_json()["style"]}]),
        "ControlPoints[]": (lambda k: i().control_points[k], lambda: [0]),
        "ControlPoints[]=": (lambda k, x: i().control_points.__setitem__(k, x),
                             lambda: [0, cp0()]),
        "ControlPoints.insert": (lambda k, x: i().control_points.insert(k, x),
                                 lambda: [0, cp0()]),
        "ControlPoints.append": (lambda x: i().control_points.append(x), lambda: [cp0()]),
        "del ControlPoints[]": (lambda k: i().control_points.__delitem__(k), lambda: [0]),
        "Item.control_points=": (lambda x: setattr(i(), "control_points", x),
                                 lambda: [np.asarray(i().control_points)]),
        "Parameters[]": (lambda k: i().parameters[k], lambda: [key()]),
        "Parameters[]=": (lambda k, x: i().parameters.__setitem__(k, x),
                          lambda: [key(), i().parameters[key()]]),
        "Parameters.info": (lambda k: i().parameters.info(k), lambda: [key()]),
        "Item.points": (lambda d, s, a, m, w: i().points(depth=d, start=s, address=a,
                                                         max_points=m, with_maps=w),
                        lambda: [2, None, None, 1e8, False]),
        "Item.render": (lambda path, size, d, n, t: i().render(path, size=size, depth=d,
                                                              samples=n, threads=t),
                        lambda: ["f.png", (32, 32), 1, None, 1]),
        "Item.maps": (lambda: i().maps(), lambda: []),
        "Item.analyse": (lambda: i().analyse(), lambda: []),
        "Item.regularity": (lambda: i().regularity(), lambda: []),
    }


def fuzz_session(seed, rounds, source, systematic=False):
    """Runs in a child interpreter (cwd: a scratch folder, where it works on copies of four
    examples). With `systematic`, each argument of each call gets each value of ATOMS (the
    others valid); then `rounds` calls with random arguments (each valid or odd by chance).
    Every outcome is counted; the counts are printed as JSON on the last line. Only Exception
    subclasses may come out; anything else (or a crash) ends the child."""
    import faulthandler
    import resource
    faulthandler.enable()  # a crash prints the Python stack: the call that crashed
    if "asan" not in os.environ.get("LD_PRELOAD", ""):  # AddressSanitizer maps terabytes
        resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))  # not the machine's memory
    import attractor_workbench as awb
    rng = random.Random(seed)
    examples = Path(source) / "examples"
    files = []  # copies in the scratch folder: save(None) writes a project back to its file
    for name in ["000-fig05-four-point-from-segment.awb", "001-fig06-koch-curve.awb",
                 "000-fig06-bicubic-patch.awb", "003-fig18-refined-junction-g1.awb"]:
        files.append(Path(name).resolve())
        files[-1].write_bytes((examples / name).read_bytes())
    state = {}

    def fresh():
        state["file"] = str(rng.choice(files))
        state["p"] = awb.open(state["file"])
        state["i"] = state["p"].items[0]

    calls = fuzz_calls(awb, state)
    names = sorted(calls)
    counts = {name: {} for name in names}

    def attempt(name, args):
        if known_crash(name, args):
            outcome = "skipped: known crash"
        else:
            try:
                calls[name][0](*args)
                outcome = "ok"
            except Exception as e:  # noqa: BLE001 - any Exception is an answer
                outcome = type(e).__name__
                if outcome == "RuntimeError" and "Unable to cast" in str(e):
                    outcome = "RuntimeError(Unable to cast)"
        counts[name][outcome] = counts[name].get(outcome, 0) + 1
        try:  # the item may be gone (removed, replaced, its point set emptied): start again
            state["i"].name
            np.asarray(state["i"].control_points)[0]
        except Exception:  # noqa: BLE001
            fresh()

    fresh()
    if systematic:
        for name in names:
            if not calls[name][1]():  # no arguments: once on each example
                for file in files:
                    state["file"] = str(file)
                    state["p"] = awb.open(state["file"])
                    state["i"] = state["p"].items[0]
                    attempt(name, [])
            for position in range(len(calls[name][1]())):
                for atom in ATOMS:
                    fresh()
                    args = calls[name][1]()
                    args[position] = atom
                    attempt(name, args)
    for n in range(rounds):
        if n % 40 == 0:
            fresh()
        name = rng.choice(names)
        args = [x if rng.random() < 0.4 else fuzz_value(rng) for x in calls[name][1]()]
        attempt(name, args)
    print(json.dumps(counts))


def run_fuzz(tmp_path, seed, rounds, systematic=False):
    code = ("import sys; sys.path.insert(0, %r)\n"
            "from test_errors import fuzz_session\n"
            "fuzz_session(%d, %d, %r, %r)\n" % (str(HERE), seed, rounds, os.environ.get(
                "AWB_SOURCE", str(HERE.parents[1])), systematic))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=subprocess_env(), timeout=600, cwd=tmp_path)
    assert out.returncode == 0, (f"the fuzz session (seed {seed}) died with status "
                                 f"{out.returncode}: {out.stderr[-3000:]}")
    counts = json.loads(out.stdout.strip().splitlines()[-1])
    leaks = {k: c["RuntimeError(Unable to cast)"] for k, c in counts.items()
             if "RuntimeError(Unable to cast)" in c}
    ok = sum(c.get("ok", 0) for c in counts.values())
    total = sum(sum(c.values()) for c in counts.values())
    return counts, f"{total} calls, {ok} succeeded; pybind11 cast RuntimeErrors: {leaks}"


@pytest.mark.subprocess
def test_fuzz_each_argument_with_each_odd_value(tmp_path, capsys):
    counts, summary = run_fuzz(tmp_path, 1, 0, systematic=True)
    assert all(counts.values()), "every call was made"
    with capsys.disabled():
        print(f"\n[fuzz, systematic] {summary}")


@pytest.mark.subprocess
@pytest.mark.parametrize("seed", [20240601, 7, 99])
def test_fuzz_every_call_answers(tmp_path, capsys, seed):
    counts, summary = run_fuzz(tmp_path, seed, 800)
    assert sum(sum(c.values()) for c in counts.values()) == 800
    with capsys.disabled():
        print(f"\n[fuzz seed {seed}] {summary}")


@pytest.mark.subprocess
@pytest.mark.parametrize("call", ["p.item(None)", "p[None]"])
def test_item_none_does_not_crash(child_python, call):
    code = ("import attractor_workbench as awb\n"
            "p = awb.Project()\n"
            "try:\n"
            "    %s\n"
            "except (ValueError, TypeError, KeyError) as e:\n"
            "    print('refused:', e)\n" % call)
    out = child_python(code, timeout=60)
    assert out.returncode == 0, f"the interpreter died: status {out.returncode}"
    assert "refused" in out.stdout


# --- Ctrl+C ----------------------------------------------------------------------------------

@pytest.mark.subprocess
@pytest.mark.parametrize("file", [FOUR_POINT_FILE, "000-fig10-koch-with-control-points.awb"])
def test_ctrl_c_interrupts_points(examples, file):
    """points(depth=29, max_points=2e9) runs for minutes; SIGINT after 1 s must end it with
    KeyboardInterrupt within a few seconds. The child restores Python's SIGINT handler: a shell
    that runs its jobs in the background (CI, this test's own runner) starts them with SIGINT
    ignored, and Python then never installs the handler that raises KeyboardInterrupt. The
    child caps its address space (not under AddressSanitizer, whose shadow memory needs more)
    so that a failed interrupt cannot take the machine's memory."""
    path = examples / file
    code = (
        "import os, resource, signal, sys, time\n"
        "if 'asan' not in os.environ.get('LD_PRELOAD', ''):\n"
        "    resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))\n"
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "import attractor_workbench as awb\n"
        "item = awb.open(sys.argv[1]).items[0]\n"
        "depth = 29 if len(item.maps()) == 2 else 15\n"
        "print('ready', depth, flush=True)\n"
        "t = time.monotonic()\n"
        "try:\n"
        "    item.points(depth=depth, max_points=2e9)\n"
        "    print('finished', flush=True)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after %.2f s' % (time.monotonic() - t), flush=True)\n"
        "    sys.exit(42)\n")
    child = subprocess.Popen([sys.executable, "-c", code, str(path)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=subprocess_env())
    try:
        assert child.stdout.readline().startswith("ready")
        time.sleep(1.0)
        assert child.poll() is None, "points() ended before the signal"
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=10)
        waited = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert child.returncode == 42, f"status {child.returncode}: {out} {err}"
    assert "interrupted" in out and waited < 5


@pytest.mark.subprocess
@pytest.mark.parametrize("file, amount", [
    ("002-fig03-union-p1.awb", "samples=1e9"),
    # A surface (its own raster, render/SurfaceFigure): 6^11 triangles, a minute.
    ("000-fig07-box-spline-hexagon.awb", "depth=11")])
def test_ctrl_c_interrupts_render(examples, tmp_path, file, amount):
    code = (
        "import signal, sys, time\n"
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "import attractor_workbench as awb\n"
        "item = awb.open(sys.argv[1]).items[0]\n"
        "print('ready', flush=True)\n"
        "t = time.monotonic()\n"
        "try:\n"
        "    item.render(sys.argv[2], size=(64, 64), %s, threads=1)\n" % amount +
        "    print('finished after %.2f s' % (time.monotonic() - t), flush=True)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after %.2f s' % (time.monotonic() - t), flush=True)\n")
    child = subprocess.Popen([sys.executable, "-c", code,
                              str(examples / file), str(tmp_path / "f.png")],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=subprocess_env())
    try:
        assert child.stdout.readline().startswith("ready")
        time.sleep(0.5)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=120)
        waited = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert "interrupted" in out and waited < 1.5, f"{out.strip()}, {waited:.2f} s after SIGINT"
