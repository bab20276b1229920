"""Attractor Workbench: subdivision schemes and iterated function systems, their attractors,
matrices and spectra, in the projects (.awb) of the application.

The compiled part (_native) holds the model; atlas.py runs the regularity atlas of a family of
schemes, and render.py huge renders, on a Dask cluster (python3 -m attractor_workbench.atlas,
python3 -m attractor_workbench.render).
"""

from ._native import *  # noqa: F401,F403
from ._native import __doc__, __version__  # noqa: F401


def atlas(item, grid, client=None, *, parameters=None, mask=None, smoothness=1, progress=None,
          **options):
    """atlas(item, grid, client=None, *, mask=None, smoothness=1, ...) -> dict

    The certified regularity atlas of the family of `item`'s scheme over `grid`: a dict of
    axes, e.g. {"w": (0, 0.25, 26)} or {"w": (-0.25, 0, 11), "v": (-0.02, 0.02, 11)} (name:
    (from, to, count)). The family is the item's scheme with these parameters moved ("omega",
    "a", "b") or, with `mask`, the names written in it. `client`: a dask.distributed Client;
    None starts a local cluster of this machine's cores; the string "in-process" evaluates
    here, one point after another. Returns {"axes", "smoothness", "rows", "runs", "points",
    "seconds", "workers"}; rows are {"params", "lower", "upper", "exact", ...} sorted by
    parameter, the same wherever they were computed. See attractor_workbench.atlas.
    """
    from ._atlas import run_atlas
    return run_atlas(item, grid, client=client, parameters=parameters, mask=mask,
                     smoothness=smoothness, progress=progress, **options)


def render_density(item, samples, out=None, client=None, **options):
    """render_density(item, samples, out=None, client=None, **options) -> dict

    Options: size=(900, 700), seed=None (the item's), chunks=None. A random-iteration render of `samples` points split into chunks over a Dask cluster
    (`client`: a Client; None starts a local cluster; "in-process" renders here). Each chunk
    is Item.density from its own seed; the sum (float64, in chunk order) is the same wherever
    the chunks ran. Returns {"rgba", "world", "chunks", "samples", "seed", "seconds",
    "workers", "scheduler"}; with `out` (.exr, .png) it is also written as render("F.exr")
    writes. See attractor_workbench.render.
    """
    from ._render import run_render
    return run_render(item, samples, out, client=client, **options)


def animate_frames(item, out_dir, client=None, **options):
    """animate_frames(item, out_dir, client=None, **options) -> dict

    Options: fps=None (the animation's), size=(900, 700), bounds=None (the union). The frames of `item`'s animation drawn on a Dask cluster (`client`: a Client; None starts
    a local cluster; "in-process" draws here), written as frame-0000.png, ... into `out_dir`:
    the frames attractor-cli animate draws, in the one framing of their union. Returns
    {"frames", "bounds", "seconds", "workers", "scheduler"}. See attractor_workbench.animate.
    """
    from ._animate import run_animate
    return run_animate(item, out_dir, client=client, **options)
