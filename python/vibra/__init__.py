"""vibra from Python: the vibration ODEs of Linge & Langtangen, *Finite
Difference Computing with PDEs*, chapter 1, solved in C++ with the results as
numpy arrays, and scenes rendered to videos that play in a notebook.

    import vibra
    run = vibra.solve("pendulum", Theta=40, alpha=0.8)
    run.t, run.theta              # numpy arrays viewing the C++ buffer
    vibra.render(Theta=40)        # a Video that plays in a notebook cell
    vibra.lecture("story.toml")   # a storyboard's shots in one Video
    vibra.explore(Theta=40)       # a live page, re-solved in the cell as its controls move
    vibra.convergence("undamped", scheme="rk4")   # a Table

Bad input raises ValueError with the command line's message; a solution
that blows up raises vibra.SolutionError (with .step and .t).
"""

from ._vibra import SolutionError
from ._solution import Solution, models, solve, stream
from ._media import Image, Video, lecture, plot, render
from ._explore import LivePage, explore
from ._ascii import ascii_lines
from ._analyses import Table, amplitude, convergence, empirical, energy, frequency, orbit

__all__ = [
    "Image", "LivePage", "Solution", "SolutionError", "Table", "Video",
    "amplitude", "ascii_lines", "convergence", "empirical", "energy", "explore", "frequency",
    "lecture", "models", "orbit", "plot", "render", "solve", "stream",
]
