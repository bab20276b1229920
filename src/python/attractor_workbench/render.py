"""python3 -m attractor_workbench.render PROJECT.awb --item NAME --samples 1e11 --out X.exr|X.png
[--size WxH] [--seed S] [--chunks C] [--scheduler ADDRESS | --workers K | --in-process]

A huge random-iteration render split over a Dask cluster (issue 48); see _render.py. In a
script: attractor_workbench.render_density(item, samples, out=None, client=None, ...).
"""

import sys

from ._render import chunk_plan, main, run_render  # noqa: F401

if __name__ == "__main__":
    sys.exit(main())
