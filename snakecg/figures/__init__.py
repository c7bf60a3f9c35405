"""All of snakecg's drawing (matplotlib), in one package.

* :mod:`snakecg.figures.configuration`: ``snakecg.plot(scene, q, tau=None, ax=None)``, one
  configuration with its object, contact normal, wheels, and with a torque its constraint
  forces and accelerations;
* :mod:`snakecg.figures.paper`: the paper's Figures 4-6 from computed data (what
  ``snakecg reproduce`` writes);
* :mod:`snakecg.figures.simulation`: the figures and the animation of a simulated run (what
  ``snakecg simulate`` writes; also ``snakecg.simulate.save_figures``).
"""

from .configuration import configuration_geometry, plot
from .paper import (
                    Drawer,
                    Fig4Panel,
                    Shape,
                    figure4,
                    figure5,
                    figure6,
                    make_figure4,
                    make_figure5,
                    make_figure6,
                    write_figure,
)
from .simulation import save_animation, save_figures

__all__ = ["plot", "configuration_geometry", "Drawer", "Fig4Panel", "Shape", "figure4",
           "figure5", "figure6", "make_figure4", "make_figure5", "make_figure6", "write_figure",
           "save_figures", "save_animation"]
