"""python3 -m attractor_workbench.animate PROJECT.awb [--item NAME] --out DIR [--fps N]
[--size WxH] [--scheduler ADDRESS | --workers K | --in-process]

An animation's frames drawn on a Dask cluster (issue 48); see _animate.py.
"""

import sys

from ._animate import main, run_animate  # noqa: F401

if __name__ == "__main__":
    sys.exit(main())
