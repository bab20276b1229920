"""The recording of edits as Python (model/ScriptRecorder, the console's Tools > Save
Recording), through Project.record(): on every example project, a seeded series of edits of
every kind (control points of every set, every parameter the Properties dock has, renames,
added and removed items, style updates, edit blocks, undo and redo) is recorded, and the
recorded script, replayed on the original file, saves the same bytes as the edited project."""
import random
import sys

import numpy as np
import pytest

from conftest import EXAMPLES


def edit_at_random(awb, project, rng):
    """One random edit (or an attempt the model refuses, which must leave no step)."""
    items = project.items
    if not items:
        return
    item = rng.choice(items)
    kind = rng.random()
    try:
        if kind < 0.35 and item.dimension:
            sets = item.point_sets
            if not sets:
                return
            s = rng.randrange(len(sets))
            points = np.asarray(sets[s])
            if len(points) == 0:
                return
            i = rng.randrange(len(points))
            moved = points[i] + rng.uniform(-0.3, 0.3)
            sets[s][i] = moved
        elif kind < 0.7:
            keys = [k for k in item.parameters.keys()
                    if not item.parameters.info(k)["read_only"]]
            if not keys:
                return
            key = rng.choice(keys)
            info = item.parameters.info(key)
            value = item.parameters[key]
            if info["type"] == "real":
                value = value + rng.uniform(-0.05, 0.05) if value else rng.uniform(0.1, 0.9)
            elif info["type"] == "integer":
                value = value + rng.choice([-1, 1])
            elif info["type"] == "choice":
                value = rng.randrange(len(info["choices"]))
            elif info["type"] == "bool":
                value = not value
            elif info["type"] == "complex":
                value = value + complex(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05))
            else:
                return  # text (a mask): its own tests
            item.parameters[key] = value
        elif kind < 0.75:
            item.name = item.name + " *"
        elif kind < 0.8 and item.parent is None:
            copy = item.to_json()
            copy["name"] = item.name + " (copy)"
            project.add(copy, index=rng.randrange(len(project.items) + 1)
                        if rng.random() < 0.5 else -1)
        elif kind < 0.84 and len(items) > 1:
            project.remove(item)
        elif kind < 0.88:
            style = item.to_json()["style"]
            style["point_size"] = rng.choice([1, 2, 3, 4])
            item.update({"style": style})
        elif kind < 0.92 and item.dimension and item.point_sets:
            with project.edit("Two edits"):
                cp = item.point_sets[0]
                if len(cp):
                    cp[0] = np.asarray(cp)[0] + 0.125
                item.name = item.name + " +"
        elif kind < 0.97 and project.can_undo:
            project.undo()
        elif project.can_redo:
            project.redo()
    except (awb.Error, TypeError, KeyError, IndexError):
        pass


@pytest.mark.parametrize("seed", [1, 2])
@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.awb")))
def test_recorded_edits_replay_to_the_same_file(awb, example, seed, tmp_path, monkeypatch):
    original = EXAMPLES / example
    project = awb.open(original)
    recording = project.record()
    assert recording.base_file == str(original)
    rng = random.Random(f"{example} {seed}")
    for _ in range(16):
        edit_at_random(awb, project, rng)
    assert recording.steps, "no edit was made"
    edited = tmp_path / "edited.awb"
    project.save(edited)
    script = tmp_path / "session.py"
    script.write_text(recording.script(), encoding="utf-8")
    replayed = tmp_path / "replayed.awb"
    monkeypatch.setattr(sys, "argv", [str(script), str(original), str(replayed)])
    code = compile(script.read_text(encoding="utf-8"), str(script), "exec")
    exec(code, {"__name__": "__main__"})
    assert replayed.read_bytes() == edited.read_bytes(), "\n".join(recording.steps)


def test_a_refused_edit_is_not_recorded(awb, four_point, curve):
    recording = four_point.record()
    with pytest.raises(awb.Error):
        curve.control_points[0] = [float("nan"), 0]
    curve.control_points[0] = [0.5, 0.25]
    assert recording.steps == [
        'project.item("000 Fig. 5: four-point scheme from a segment")'
        '.control_points[0] = [0.5, 0.25]']
