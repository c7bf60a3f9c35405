"""General scenes: objects, obstacles and the snake's own links, every contact found from
geometry, solved exactly at rest (see docs/how-to/scenes.md)."""

from .description import GROUND_MODELS, GeneralScene, Ground, Obstacle, SceneObject

__all__ = ["GROUND_MODELS", "GeneralScene", "Ground", "Obstacle", "SceneObject", "load_scene",
           "simulate_scene_batch"]


def load_scene(scene, **kwargs):
    """The loaded model of a :class:`GeneralScene` (a :class:`snakecg.Scene` is converted
    first, :meth:`GeneralScene.from_scene`)."""
    from ..robot import Scene
    from .model import GeneralSceneModel

    if isinstance(scene, Scene):
        scene = GeneralScene.from_scene(scene)
    return GeneralSceneModel(scene, **kwargs)


def simulate_scene_batch(model, q0, duration, **kwargs):
    """Many runs of one general scene in one call:
    :func:`snakecg.scenes.run_batch.simulate_scene_batch`."""
    from .run_batch import simulate_scene_batch as batch

    return batch(model, q0, duration, **kwargs)
