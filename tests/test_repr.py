"""Readable reprs: Robot and Scene show what differs from the defaults and evaluate back to an
equal object; models say what they are a model of."""

from __future__ import annotations

import snakecg
from snakecg import Robot, Scene


def test_reprs_are_short_and_evaluate_back():
    table1 = Robot(joints=9)
    assert repr(table1) == "Robot(joints=9)"
    custom = Robot(joints=2, mass=[1, 2, 3], length=0.2, com=0.05, name="arm")
    assert repr(custom) == ("Robot(joints=2, mass=(1.0, 2.0, 3.0), length=0.2, com=0.05, "
                            "name='arm')")
    assert repr(Scene(table1)) == "Scene(Robot(joints=9))"
    scene = Scene(custom, scenario="wheels", kappa=30, contact_link=2, side="right",
                  wheel_links=[1], object_inertia=2.0)
    assert repr(scene) == ("Scene(Robot(joints=2, mass=(1.0, 2.0, 3.0), length=0.2, com=0.05,"
                           " name='arm'), scenario='wheels', kappa=30.0, contact_link=2, "
                           "side='right', object_inertia=2.0, wheel_links=(1,))")
    for obj in (table1, custom, Scene(table1), scene, Scene(custom, contact_offset=0.01)):
        back = eval(repr(obj), {"Robot": Robot, "Scene": Scene})  # noqa: S307 - our own text
        assert back == obj
        assert getattr(back, "name", None) == getattr(obj, "name", None)


def test_model_repr_names_its_robot_or_scene():
    model = snakecg.load(Scene(Robot(joints=1), scenario="ideal_wheels"))
    assert repr(model) == ("<SceneModel of Scene(Robot(joints=1), scenario='ideal_wheels'),"
                           f" backend {model.backend_kind!r}>")
    assert repr(snakecg.load(Robot(joints=1))).startswith("<RobotModel of Robot(joints=1),")
